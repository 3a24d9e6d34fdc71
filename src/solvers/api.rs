//! The solver interface: the names of the solvers ([`SolverKind`], one table), the options of
//! a solve ([`SolveOptions`]) and the trait every solver implements ([`ImpactSolver`]) on one
//! [`Contact`] in canonical units. A new solver is one `impl ImpactSolver`, one row of
//! [`SolverKind::ALL`] and one arm of `solvers::solver_for`.

use crate::error::{Error, Result};
use crate::model::contact::{CanonicalOutcome, Contact};
use crate::model::tolerances;

/// A solver of the contact problem.
pub trait ImpactSolver {
    /// Which solver this is.
    fn kind(&self) -> SolverKind;
    /// Solve `contact` (canonical units) as `opts` asks; the outcome is canonical.
    ///
    /// # Errors
    /// The solver's refusals (accuracy, work, capability: [`Error::NotSupported`]) and the
    /// errors of its numerics.
    fn solve(&self, contact: &Contact, opts: &SolveOptions) -> Result<CanonicalOutcome>;
}

/// The available impact solvers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum SolverKind {
    /// Cheapest solver that meets the requested rtol.
    Auto,
    /// The paper's explicit Euler on the element network of Eq. (8).
    MdrEuler,
    /// MDR foundation with exact exponential update of the internal variables and a
    /// trapezoidal (A-stable, second-order) time scheme for the sphere.
    Mdr,
    /// Lee–Radok/Ting reference solution (independent of the MDR foundation).
    Reference,
    /// Reduced solver: O(1) state per Prony term (all elements share one rate and leave last in,
    /// first out), stiff terms integrated exactly.
    Fast,
}

impl SolverKind {
    /// The one table of solvers and their names (command line, scenes, the `solver` column):
    /// [`SolverKind::name`], [`SolverKind::NAMES`] and `FromStr` derive from it.
    pub const ALL: [(SolverKind, &'static str); 5] = [
        (SolverKind::Auto, "auto"),
        (SolverKind::MdrEuler, "mdr-euler"),
        (SolverKind::Mdr, "mdr"),
        (SolverKind::Reference, "reference"),
        (SolverKind::Fast, "fast"),
    ];

    /// Every name accepted on the command line and in scenes.
    pub const NAMES: &'static [&'static str] = &{
        let mut names = [""; 5];
        let mut i = 0;
        while i < names.len() {
            names[i] = SolverKind::ALL[i].1;
            i += 1;
        }
        names
    };

    /// The command-line / scene name.
    pub fn name(self) -> &'static str {
        SolverKind::ALL
            .iter()
            .find(|(k, _)| *k == self)
            .map_or("", |(_, n)| n)
    }
}

impl std::str::FromStr for SolverKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        SolverKind::ALL
            .iter()
            .find(|(_, n)| *n == s)
            .map(|(k, _)| *k)
            .ok_or_else(|| Error::Parse {
                what: "solver",
                input: crate::error::escape_text(s),
                expected: format!("one of {}", SolverKind::NAMES.join(", ")),
            })
    }
}

impl std::fmt::Display for SolverKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Explicit discretisation of an MDR solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// Number of elements across the (estimated) maximum contact radius, `>= 2`.
    pub elements: usize,
    /// Number of time steps per (estimated) contact time, `>= 4`.
    pub steps: usize,
}

/// How to solve: which solver, how accurately, what to record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// The solver.
    pub solver: SolverKind,
    /// Requested relative accuracy of the CoR (ignored when `resolution` is given).
    pub rtol: f64,
    /// Explicit discretisation for the MDR solvers (overrides `rtol`).
    pub resolution: Option<Resolution>,
    /// Record the histories `(t, d, v, F, a)`.
    pub history: bool,
    /// Locate the maximum force to `rtol` (`fast`: a search on the dense output after the
    /// solve, about 8 % of its evaluations). With `false`, `Outcome::max_force` of `fast` is the
    /// largest sampled force refined by a parabola through its neighbours (good to about 1e-5
    /// relative); the CoR, contact time and maximum indentation are the same. Default `true`.
    pub peak_force: bool,
    /// Cap on the work of the MDR solvers, in element updates (element-steps) summed over the
    /// refinement levels; beyond it the solve fails with [`Error::AccuracyNotReached`].
    pub work_limit: u64,
}

impl Default for SolveOptions {
    fn default() -> Self {
        Self {
            solver: SolverKind::Auto,
            rtol: tolerances::DEFAULT_RTOL,
            resolution: None,
            history: false,
            peak_force: true,
            work_limit: tolerances::MDR_MAX_ELEMENT_UPDATES,
        }
    }
}

impl SolveOptions {
    /// `solver` at `rtol`, everything else at its default (CoR only, no explicit resolution).
    pub fn with(solver: SolverKind, rtol: f64) -> Self {
        Self {
            solver,
            rtol,
            ..Default::default()
        }
    }

    /// Validate the options: `1e-12 <= rtol <= 0.1`; an explicit resolution needs
    /// `2 <= elements <= 10^6` and `4 <= steps <= 10^9` ([`Error::OutOfRange`] naming the field),
    /// and applies to the MDR schemes only (`mdr`, `mdr-euler`, and `auto`, which then uses
    /// `mdr`): with `fast` or `reference` it is [`Error::NotSupported`] rather than ignored.
    pub fn validate(&self) -> Result<()> {
        crate::error::check(
            "rtol",
            self.rtol,
            self.rtol >= tolerances::MIN_RTOL && self.rtol <= tolerances::MAX_RTOL,
            "1e-12 <= rtol <= 0.1",
        )?;
        if let Some(r) = self.resolution {
            if !(2..=1_000_000).contains(&r.elements) {
                return Err(Error::OutOfRange {
                    field: "elements",
                    value: r.elements as f64,
                    allowed: "2 <= elements <= 10^6",
                });
            }
            if !(4..=1_000_000_000).contains(&r.steps) {
                return Err(Error::OutOfRange {
                    field: "steps",
                    value: r.steps as f64,
                    allowed: "4 <= steps <= 10^9",
                });
            }
            if matches!(self.solver, SolverKind::Fast | SolverKind::Reference) {
                return Err(Error::NotSupported {
                    solver: self.solver.name(),
                    what: "[solver] elements/steps apply to the mdr and mdr-euler solvers (and \
                           auto, which then uses mdr) only"
                        .into(),
                });
            }
        }
        Ok(())
    }
}
