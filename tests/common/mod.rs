//! Helpers shared by the integration tests: the command-line runner, the one relative-error
//! helper (signed and absolute, named so), shared solve options and named tolerances.
//!
//! Each test file that uses them declares `mod common;`; not every file uses every helper.
#![allow(dead_code)]

use std::path::Path;
use std::process::{Command, Output};

use mdr_impact::report::catalogue;
use mdr_impact::{Groups, Impact, Prony, SolveOptions, SolverKind};

/// Run `mdr-impact` with `args` in `dir`, with `CI` set (no progress bars).
pub fn run(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mdr-impact"))
        .args(args)
        .current_dir(dir)
        .env("CI", "1")
        .output()
        .unwrap()
}

/// The standard error of a run, as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).to_string()
}

/// Signed relative error `(value - truth) / truth`: positive when `value` is above the truth.
pub fn rel_err(value: f64, truth: f64) -> f64 {
    (value - truth) / truth
}

/// Absolute relative error `|value - truth| / |truth|`, for two-sided bounds.
pub fn abs_rel_err(value: f64, truth: f64) -> f64 {
    (value - truth).abs() / truth.abs()
}

/// Options of one solver at one rtol, every other option at its default.
pub fn opts(solver: SolverKind, rtol: f64) -> SolveOptions {
    SolveOptions::with(solver, rtol)
}

/// The canonical `G_eq(t)` of the standard solid with the groups `(nu, p2, p3)`.
pub fn canonical(nu: f64, p2: f64, p3: f64) -> Prony {
    Impact::from_groups(Groups::new(nu, p2, p3).unwrap())
        .unwrap()
        .canonical_relaxation()
}

/// The groups of a catalogue case, by its id (panics on an unknown id: a typo in a test).
pub fn case_groups(id: &str) -> Groups {
    catalogue::impact_case(id)
        .unwrap_or_else(|| panic!("no catalogue case {id}"))
        .groups()
        .unwrap()
}

/// The standard-solid impact of a catalogue case in canonical units, by its id.
pub fn case_impact(id: &str) -> Impact {
    Impact::from_groups(case_groups(id)).unwrap()
}

/// Named tolerances of the tests: each says what it bounds and why it has this value.
pub mod tol {
    /// Two routes of one formula in floating point (a closed form against the same quantity
    /// assembled term by term): a few ulps of the result, with room for cancellation.
    pub const ROUNDING: f64 = 1e-12;
    /// Identities that hold to the last bits (the same arithmetic in another order).
    pub const BITS: f64 = 1e-15;
    /// Two independent solvers, each asked for rtol 1e-10: their CoRs agree within the sum.
    pub const SOLVERS_AT_1E10: f64 = 2e-10;
}
