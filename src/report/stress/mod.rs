//! Stress test of the accuracy contract: every answer within its rtol, or a refusal.
//!
//! Random rows of the whole input range (`nu` uniform in `(-1, 0.5]`, every tenth row exactly
//! incompressible; `log10 p2` and `log10 p3` uniform in `[-8, 8]`) are solved with `auto` and
//! with `fast` at every rtol from 1e-2 to 1e-11. Each solve runs under
//! [`std::panic::catch_unwind`], so that a panic is counted rather than fatal. A success must
//! carry a finite CoR in `(0, 1]` with an error estimate at or below its rtol, and agree with an
//! independent truth within `rtol + truth_rtol`; a refusal is an error, counted by its kind.
//!
//! The truth of a row is the `reference` solver (a different integrator from `fast`) at the
//! tightest rtol it accepts among 1e-11 down to 1e-6 (in the glassy corner it refuses requests
//! below its measured accuracy, see [`crate::solvers::theory::REF_GLASSY_ABS_FLOOR`]); only where it
//! refuses all of them is `fast` at 1e-12 used, and such rows are counted apart (their
//! comparison of `fast` is not independent). A success is compared within `rtol + truth_rtol`,
//! so where the truth is looser than the rtol tested the check is only as strict as the truth. Rows are drawn from the seed and their index alone and reduced in index order,
//! so the report does not depend on the number of threads. Re-run:
//! `mdr-impact stress --rows N --seed S`, or
//! `cargo test --release --test suite stress:: -- --ignored`.

use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};

use rayon::prelude::*;

mod markdown;

use crate::error::Result;
use crate::model::impact::{Groups, Impact, Method, Outcome};
use crate::rng::SplitMix64;
use crate::solvers::{solve, SolveOptions, SolverKind};

/// The requested tolerances of the stress test, 1e-2 down to 1e-11.
pub const RTOLS: [f64; 10] = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11];

/// The solvers under test.
pub const SOLVERS: [SolverKind; 2] = [SolverKind::Auto, SolverKind::Fast];

/// The rtols at which the `reference` solver is asked for the truth, tightest first.
pub const TRUTH_REFERENCE_RTOLS: [f64; 6] = [1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6];

/// The rtol of the `fast` truth used where `reference` refuses all of [`TRUTH_REFERENCE_RTOLS`].
pub const TRUTH_FAST_RTOL: f64 = 1e-12;

/// Range of `log10 p2` and `log10 p3`.
pub const LOG_RANGE: (f64, f64) = (-8.0, 8.0);

/// Every how many rows `nu = 0.5` exactly (row indices `9, 19, 29, ...`).
pub const INCOMPRESSIBLE_EVERY: usize = 10;

/// Default number of rows of the command (the ignored test runs the first 2000 of them).
pub const DEFAULT_ROWS: usize = 5000;

/// Default seed.
pub const DEFAULT_SEED: u64 = 1;

/// One sampled row of groups.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// Index of the row (0-based).
    pub index: usize,
    /// Static Poisson ratio.
    pub nu: f64,
    /// `p2`.
    pub p2: f64,
    /// `p3`.
    pub p3: f64,
}

/// The rows of a stress run: deterministic in `seed` and the row's index alone.
pub fn sample(rows: usize, seed: u64) -> Vec<Row> {
    (0..rows)
        .map(|index| {
            let mut rng =
                SplitMix64::new(seed ^ (index as u64).wrapping_mul(0xA076_1D64_78BD_642F));
            // 0.5 - 1.5 u with u in [0, 1): nu in (-1, 0.5]
            let u = rng.uniform();
            let nu = if index % INCOMPRESSIBLE_EVERY == INCOMPRESSIBLE_EVERY - 1 {
                0.5
            } else {
                0.5 - 1.5 * u
            };
            let (lo, hi) = LOG_RANGE;
            let p2 = 10f64.powf(lo + (hi - lo) * rng.uniform());
            let p3 = 10f64.powf(lo + (hi - lo) * rng.uniform());
            Row { index, nu, p2, p3 }
        })
        .collect()
}

/// Where the truth of a row comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TruthSource {
    /// `reference` at this rtol.
    Reference(f64),
    /// `fast` at [`TRUTH_FAST_RTOL`] (reference refused every rtol).
    Fast,
    /// No solver produced a truth.
    None,
}

impl TruthSource {
    /// Label for tables and CSV.
    pub fn label(&self) -> String {
        match self {
            TruthSource::Reference(r) => format!("reference rtol={r:.0e}"),
            TruthSource::Fast => format!("fast rtol={TRUTH_FAST_RTOL:.0e}"),
            TruthSource::None => "none".into(),
        }
    }
    /// The accuracy of the truth (its rtol), if any.
    pub fn rtol(&self) -> Option<f64> {
        match self {
            TruthSource::Reference(r) => Some(*r),
            TruthSource::Fast => Some(TRUTH_FAST_RTOL),
            TruthSource::None => None,
        }
    }
}

/// What one solve gave.
#[derive(Debug, Clone, PartialEq)]
pub enum SolveResult {
    /// A finite outcome.
    Ok {
        /// The CoR.
        cor: f64,
        /// Its error estimate (`None` when the solver gave none).
        estimate: Option<f64>,
        /// `auto` answered with `reference` because `fast` refused.
        fell_back: bool,
        /// `fast` answered from one solve, without a tighter check (`Work::tight_checks`).
        one_solve: bool,
    },
    /// An outcome with a non-finite CoR or error estimate.
    NonFinite {
        /// The CoR.
        cor: f64,
        /// Its error estimate.
        estimate: Option<f64>,
    },
    /// A refusal: the kind of error (its variant name) and its message.
    Refused {
        /// Variant name of the error.
        kind: &'static str,
        /// The message.
        message: String,
    },
    /// The solve panicked, with the panic message.
    Panicked(String),
}

fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "(non-string panic payload)".into()
    }
}

/// Solve one row with one solver and rtol, catching panics.
pub fn solve_one(row: &Row, solver: SolverKind, rtol: f64) -> SolveResult {
    let run = || -> Result<Outcome> {
        let imp = Impact::from_groups(Groups::new(row.nu, row.p2, row.p3)?)?;
        solve(
            &imp,
            &SolveOptions {
                solver,
                rtol,
                ..Default::default()
            },
        )
    };
    match catch_unwind(AssertUnwindSafe(run)) {
        Err(payload) => SolveResult::Panicked(panic_message(payload.as_ref())),
        Ok(Err(e)) => SolveResult::Refused {
            kind: e.variant_name(),
            message: e.to_string(),
        },
        Ok(Ok(o)) => {
            let finite = o.cor.is_finite() && o.cor_error_estimate.is_none_or(f64::is_finite);
            if finite {
                SolveResult::Ok {
                    cor: o.cor,
                    estimate: o.cor_error_estimate,
                    fell_back: o.fallback.is_some(),
                    one_solve: o.solver == Method::Fast && o.work.tight_checks == 0,
                }
            } else {
                SolveResult::NonFinite {
                    cor: o.cor,
                    estimate: o.cor_error_estimate,
                }
            }
        }
    }
}

/// The truth of a row: `reference` at the tightest rtol it accepts, else `fast` at 1e-12.
/// Panics of the truth solves are returned as messages.
pub fn truth(row: &Row) -> (TruthSource, Option<f64>, Vec<String>) {
    let mut panics = Vec::new();
    for r in TRUTH_REFERENCE_RTOLS {
        match solve_one(row, SolverKind::Reference, r) {
            SolveResult::Ok { cor, .. } if cor > 0.0 => {
                return (TruthSource::Reference(r), Some(cor), panics)
            }
            SolveResult::Panicked(m) => panics.push(m),
            _ => {}
        }
    }
    match solve_one(row, SolverKind::Fast, TRUTH_FAST_RTOL) {
        SolveResult::Ok { cor, .. } if cor > 0.0 => (TruthSource::Fast, Some(cor), panics),
        SolveResult::Panicked(m) => {
            panics.push(m);
            (TruthSource::None, None, panics)
        }
        _ => (TruthSource::None, None, panics),
    }
}

/// Everything computed for one row.
#[derive(Debug, Clone, PartialEq)]
pub struct RowResult {
    /// The row.
    pub row: Row,
    /// Where its truth came from.
    pub truth_source: TruthSource,
    /// The truth's CoR.
    pub truth: Option<f64>,
    /// Panic messages of the truth solves.
    pub truth_panics: Vec<String>,
    /// One result per (rtol, solver), in the order of [`RTOLS`] x [`SOLVERS`].
    pub results: Vec<SolveResult>,
}

/// Solve every rtol and solver on one row, and its truth.
pub fn run_row(row: &Row) -> RowResult {
    let (truth_source, truth, truth_panics) = truth(row);
    let results = RTOLS
        .iter()
        .flat_map(|&r| SOLVERS.iter().map(move |&s| (s, r)))
        .map(|(s, r)| solve_one(row, s, r))
        .collect();
    RowResult {
        row: *row,
        truth_source,
        truth,
        truth_panics,
        results,
    }
}

/// Counts of one (rtol, solver) cell of the report.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Cell {
    /// Rows solved.
    pub rows: usize,
    /// Successes (finite outcomes).
    pub successes: usize,
    /// Successes of `auto` answered by `reference` after `fast` refused.
    pub fallbacks: usize,
    /// Refusals by error kind.
    pub refusals: BTreeMap<&'static str, usize>,
    /// Successes with `|cor - truth| / truth > rtol + truth_rtol` (must be 0).
    pub outside: usize,
    /// Successes whose error estimate is above rtol or missing (must be 0).
    pub estimate_above: usize,
    /// Successes with a CoR outside `(0, 1]` (must be 0).
    pub cor_out_of_range: usize,
    /// Panics (must be 0).
    pub panics: usize,
    /// Non-finite outcomes (must be 0).
    pub non_finite: usize,
    /// Successes compared against a truth.
    pub compared: usize,
    /// Max `|cor - truth| / truth / (rtol + truth_rtol)` over the compared successes (at most 1
    /// unless `outside > 0`).
    pub max_error_over_bound: f64,
    /// Successes compared against a truth at least as tight as their rtol.
    pub strict: usize,
    /// Max `|cor - truth| / truth / rtol` over those.
    pub max_strict_over_rtol: f64,
    /// Successes of `fast` from one solve (no tighter check).
    pub one_solve: usize,
    /// Max `|cor - truth| / truth / rtol` over those compared against a truth at least as
    /// tight as their rtol.
    pub max_one_solve_over_rtol: f64,
}

impl Cell {
    /// Refusals of every kind.
    pub fn refused(&self) -> usize {
        self.refusals.values().sum()
    }
    fn add(&mut self, o: &Cell) {
        self.rows += o.rows;
        self.successes += o.successes;
        self.fallbacks += o.fallbacks;
        for (k, v) in &o.refusals {
            *self.refusals.entry(k).or_default() += v;
        }
        self.outside += o.outside;
        self.estimate_above += o.estimate_above;
        self.cor_out_of_range += o.cor_out_of_range;
        self.panics += o.panics;
        self.non_finite += o.non_finite;
        self.compared += o.compared;
        self.max_error_over_bound = self.max_error_over_bound.max(o.max_error_over_bound);
        self.strict += o.strict;
        self.max_strict_over_rtol = self.max_strict_over_rtol.max(o.max_strict_over_rtol);
        self.one_solve += o.one_solve;
        self.max_one_solve_over_rtol = self.max_one_solve_over_rtol.max(o.max_one_solve_over_rtol);
    }
}

/// A solve that broke the contract (outside rtol, estimate above rtol, CoR out of range,
/// non-finite, panic), with its exact inputs.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// `outside`, `estimate`, `cor-range`, `non-finite`, `panic` or `truth-panic`.
    pub what: &'static str,
    /// The row.
    pub row: Row,
    /// Requested rtol.
    pub rtol: f64,
    /// The solver (`reference`/`fast` for a truth panic).
    pub solver: &'static str,
    /// The CoR (NaN when none).
    pub cor: f64,
    /// The truth (NaN when none).
    pub truth: f64,
    /// Where the truth came from.
    pub truth_source: String,
    /// `|cor - truth| / truth` (NaN when not compared).
    pub rel_error: f64,
    /// The error estimate, panic message or other detail.
    pub detail: String,
}

/// The stress report.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Rows sampled.
    pub rows: usize,
    /// Seed.
    pub seed: u64,
    /// Rows with `nu = 0.5` exactly.
    pub incompressible_rows: usize,
    /// Smallest and largest CoR of the truths.
    pub truth_cor_range: (f64, f64),
    /// Rows per truth source label, in a fixed order.
    pub truth_sources: Vec<(String, usize)>,
    /// Panics of the truth solves.
    pub truth_panics: usize,
    /// One cell per (rtol, solver), in the order of [`RTOLS`] x [`SOLVERS`].
    pub cells: Vec<(f64, SolverKind, Cell)>,
    /// Every broken contract, in row order.
    pub problems: Vec<Problem>,
}

impl Report {
    /// Totals per solver over every rtol.
    pub fn totals(&self) -> Vec<(SolverKind, Cell)> {
        SOLVERS
            .iter()
            .map(|&s| {
                let mut t = Cell::default();
                for (_, k, c) in &self.cells {
                    if *k == s {
                        t.add(c);
                    }
                }
                (s, t)
            })
            .collect()
    }

    /// Totals over every solver and rtol.
    pub fn total(&self) -> Cell {
        let mut t = Cell::default();
        for (_, _, c) in &self.cells {
            t.add(c);
        }
        t
    }

    /// True when every must-be-zero count is zero (and no truth solve panicked).
    pub fn clean(&self) -> bool {
        let t = self.total();
        t.outside == 0
            && t.estimate_above == 0
            && t.cor_out_of_range == 0
            && t.panics == 0
            && t.non_finite == 0
            && self.truth_panics == 0
    }
}

/// Reduce the per-row results (in row order) to the report.
pub fn report(results: &[RowResult], seed: u64) -> Report {
    let mut cells: Vec<(f64, SolverKind, Cell)> = RTOLS
        .iter()
        .flat_map(|&r| SOLVERS.iter().map(move |&s| (r, s, Cell::default())))
        .collect();
    let mut problems = Vec::new();
    let mut truth_panics = 0;
    let mut sources: BTreeMap<String, usize> = BTreeMap::new();
    let mut cor_range = (f64::INFINITY, f64::NEG_INFINITY);
    for rr in results {
        let label = rr.truth_source.label();
        *sources.entry(label.clone()).or_default() += 1;
        if let Some(t) = rr.truth {
            cor_range = (cor_range.0.min(t), cor_range.1.max(t));
        }
        for m in &rr.truth_panics {
            truth_panics += 1;
            problems.push(Problem {
                what: "truth-panic",
                row: rr.row,
                rtol: f64::NAN,
                solver: "reference/fast",
                cor: f64::NAN,
                truth: f64::NAN,
                truth_source: label.clone(),
                rel_error: f64::NAN,
                detail: m.clone(),
            });
        }
        for ((rtol, solver, cell), res) in cells.iter_mut().zip(&rr.results) {
            let (rtol, solver) = (*rtol, *solver);
            cell.rows += 1;
            let problem = |what, cor: f64, rel_error, detail: String| Problem {
                what,
                row: rr.row,
                rtol,
                solver: solver.name(),
                cor,
                truth: rr.truth.unwrap_or(f64::NAN),
                truth_source: label.clone(),
                rel_error,
                detail,
            };
            match res {
                SolveResult::Panicked(m) => {
                    cell.panics += 1;
                    problems.push(problem("panic", f64::NAN, f64::NAN, m.clone()));
                }
                SolveResult::NonFinite { cor, estimate } => {
                    cell.non_finite += 1;
                    problems.push(problem(
                        "non-finite",
                        *cor,
                        f64::NAN,
                        format!("estimate {estimate:?}"),
                    ));
                }
                SolveResult::Refused { kind, .. } => {
                    *cell.refusals.entry(kind).or_default() += 1;
                }
                SolveResult::Ok {
                    cor,
                    estimate,
                    fell_back,
                    one_solve,
                } => {
                    cell.successes += 1;
                    cell.one_solve += usize::from(*one_solve);
                    if *fell_back {
                        cell.fallbacks += 1;
                    }
                    let detail = format!(
                        "estimate {}{}",
                        estimate.map_or("none".into(), |e| format!("{e:e}")),
                        if *fell_back { ", by reference" } else { "" }
                    );
                    let rel = rr.truth.map(|t| ((cor - t) / t).abs());
                    if !(*cor > 0.0 && *cor <= 1.0) {
                        cell.cor_out_of_range += 1;
                        problems.push(problem(
                            "cor-range",
                            *cor,
                            rel.unwrap_or(f64::NAN),
                            detail.clone(),
                        ));
                    }
                    if !estimate.is_some_and(|e| e <= rtol) {
                        cell.estimate_above += 1;
                        problems.push(problem(
                            "estimate",
                            *cor,
                            rel.unwrap_or(f64::NAN),
                            detail.clone(),
                        ));
                    }
                    if let (Some(rel), Some(tr)) = (rel, rr.truth_source.rtol()) {
                        cell.compared += 1;
                        cell.max_error_over_bound =
                            cell.max_error_over_bound.max(rel / (rtol + tr));
                        if tr <= rtol {
                            cell.strict += 1;
                            cell.max_strict_over_rtol = cell.max_strict_over_rtol.max(rel / rtol);
                            if *one_solve {
                                cell.max_one_solve_over_rtol =
                                    cell.max_one_solve_over_rtol.max(rel / rtol);
                            }
                        }
                        if rel > rtol + tr {
                            cell.outside += 1;
                            problems.push(problem("outside", *cor, rel, detail));
                        }
                    }
                }
            }
        }
    }
    let order = TRUTH_REFERENCE_RTOLS
        .iter()
        .map(|&r| TruthSource::Reference(r))
        .chain([TruthSource::Fast, TruthSource::None]);
    let truth_sources = order
        .map(|s| {
            let l = s.label();
            let n = sources.get(&l).copied().unwrap_or(0);
            (l, n)
        })
        .collect();
    Report {
        rows: results.len(),
        seed,
        incompressible_rows: results.iter().filter(|r| r.row.nu == 0.5).count(),
        truth_cor_range: if cor_range.0 <= cor_range.1 {
            cor_range
        } else {
            (f64::NAN, f64::NAN)
        },
        truth_sources,
        truth_panics,
        cells,
        problems,
    }
}

/// Run the stress test on `rows` rows drawn from `seed`, in parallel over rows; `tick` after
/// every row.
pub fn run(rows: usize, seed: u64, tick: &(dyn Fn() + Sync)) -> Report {
    let sampled = sample(rows, seed);
    let results: Vec<RowResult> = sampled
        .par_iter()
        .map(|r| {
            let out = run_row(r);
            tick();
            out
        })
        .collect();
    report(&results, seed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sample_is_deterministic_and_in_range() {
        let a = sample(50, 3);
        assert_eq!(a, sample(50, 3));
        assert_ne!(a, sample(50, 4));
        for r in &a {
            assert!(r.nu > -1.0 && r.nu <= 0.5);
            assert!((1e-8..=1e8).contains(&r.p2) && (1e-8..=1e8).contains(&r.p3));
        }
        assert_eq!(a.iter().filter(|r| r.nu == 0.5).count(), 5);
        // a prefix of a longer run is the shorter run
        assert_eq!(&sample(80, 3)[..50], &a[..]);
    }
}
