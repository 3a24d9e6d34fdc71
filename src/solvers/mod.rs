//! The three independent solvers and their one dispatch.
//!
//! - [`theory`]: Hertz, Lee–Radok and Ting/Graham by quadrature (the reference);
//! - [`mdr`]: the MDR element foundation with two time schemes (the paper's method);
//! - [`fast`]: the reduced collocation solver with O(1) state per Prony term;
//! - [`indentation`]: prescribed indentation histories shared by `theory` and `mdr`.
//!
//! `theory` and `mdr` never import each other: they meet only in the model, in tests and in
//! the reports. Every solver implements [`ImpactSolver`] on one
//! [`crate::model::contact::Contact`] in canonical units; [`SolverKind::ALL`] is the one table of
//! their names and [`solver_for`] the one map to implementations. [`solve`] is the one entry
//! point that converts SI to canonical units, chooses a solver and converts back.

mod api;
mod dispatch;
pub mod fast;
pub mod indentation;
pub mod mdr;
pub mod oblique;
pub mod theory;

pub use api::{ImpactSolver, Resolution, SolveOptions, SolverKind};
pub use dispatch::*;
