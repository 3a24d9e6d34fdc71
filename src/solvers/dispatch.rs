//! Solver choice, accuracy request and the top-level [`solve`] that dispatches a validated
//! [`Impact`] to a solver in canonical units and maps the outcome back to SI.

use crate::error::{Error, Result};
use crate::model::impact::{Impact, Outcome, Target};
use crate::model::material::{ElementNetwork, GeneralNetwork, Material, StackedNetwork};
use crate::model::tolerances;
use crate::solvers::fast;
use crate::solvers::mdr;
use crate::solvers::theory;

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
    /// Every name accepted on the command line and in scenes.
    pub const NAMES: &'static [&'static str] = &["auto", "mdr-euler", "mdr", "reference", "fast"];

    /// The command-line / scene name.
    pub fn name(self) -> &'static str {
        match self {
            SolverKind::Auto => "auto",
            SolverKind::MdrEuler => "mdr-euler",
            SolverKind::Mdr => "mdr",
            SolverKind::Reference => "reference",
            SolverKind::Fast => "fast",
        }
    }
}

impl std::str::FromStr for SolverKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Ok(match s {
            "auto" => SolverKind::Auto,
            "mdr-euler" => SolverKind::MdrEuler,
            "mdr" => SolverKind::Mdr,
            "reference" => SolverKind::Reference,
            "fast" => SolverKind::Fast,
            _ => {
                return Err(Error::Unsupported(format!(
                    "unknown solver '{s}': expected one of {}",
                    SolverKind::NAMES.join(", ")
                )))
            }
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
    /// `mdr`): with `fast` or `reference` it is [`Error::Unsupported`] rather than ignored.
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
                return Err(Error::Unsupported(format!(
                    "[solver] elements/steps apply to the mdr and mdr-euler solvers (and auto, \
                     which then uses mdr) only, not '{}'",
                    self.solver
                )));
            }
        }
        Ok(())
    }
}

/// Solve an impact. Elastic materials use the Hertz closed form whatever the solver.
///
/// A general material (Prony series in shear and bulk) is solved by `fast` (and `auto`) from its
/// canonical `G_eq` series of `material::carson`, by `reference` from the same function derived
/// independently (`theory::poles`), and by `mdr` on its element network built from `G` and `K`
/// ([`GeneralNetwork`], a third path); two bodies likewise, `mdr` on the two networks in series
/// ([`StackedNetwork`]). `mdr-euler` runs the paper's explicit Euler on one body's network
/// (the standard solid's of Eq. 8 or a general material's) and refuses two viscoelastic bodies
/// ([`Error::Unsupported`], [`MDR_EULER_GENERAL_UNSUPPORTED`]).
///
/// In nearly elastic cases a solver's discretisation error can push the CoR above 1; since
/// `e <= 1` holds exactly (a passive material dissipates a non-negative energy), such a value is
/// projected onto `(0, 1]` (`e = 1`, no dissipated energy); the error estimate is kept as
/// computed, and the projection only ever reduces the error.
pub fn solve(impact: &Impact, opts: &SolveOptions) -> Result<Outcome> {
    opts.validate()?;
    if impact.is_elastic() && opts.resolution.is_none() {
        // nothing to integrate: the Hertz closed form is exact
        let o = theory::hertz_outcome(
            impact,
            opts.history.then_some(tolerances::HERTZ_HISTORY_SAMPLES),
        )?;
        check_outcome(&o)?;
        return Ok(o);
    }
    let mut canonical = solve_canonical(impact, opts)?;
    check_outcome(&canonical)?;
    if canonical.cor > 1.0 {
        canonical.cor = 1.0;
        canonical.rebound_velocity = 1.0;
        canonical.dissipated_energy = 0.0;
    }
    Ok(canonical.to_si(impact))
}

/// The one-line refusal of `mdr-euler` for two viscoelastic bodies.
pub const MDR_EULER_GENERAL_UNSUPPORTED: &str = mdr::EULER_GENERAL_UNSUPPORTED;

/// The impact's material in canonical units, in the forms the MDR schemes need. The network is
/// chosen by shape in this one place: a deformable material of the standard solid's shape
/// (half-space, or the one deformable body beside a rigid one) gets the network of Eq. (8), which
/// [`mdr::Scheme::Exponential`] integrates through the closed-form `G_eq`; any other material its
/// network built from `G` and `K`; two deformable bodies their two networks in series.
pub fn canonical_material(impact: &Impact) -> Result<mdr::CanonicalMaterial> {
    let s = impact.scales();
    let one = |m: &Material| match m.as_standard_solid() {
        Some(ss) => mdr::Network::StandardSolid(ElementNetwork::new(&ss).scaled(s.modulus, s.time)),
        None => mdr::Network::General(GeneralNetwork::new(m, s.modulus, s.time)),
    };
    let network = match impact.target() {
        Target::HalfSpace(m) => one(m),
        Target::TwoBodies(b) => match (b.a().material().material(), b.b().material().material()) {
            (Some(ma), Some(mb)) => mdr::Network::Stacked(StackedNetwork::new(
                GeneralNetwork::new(ma, s.modulus, s.time),
                GeneralNetwork::new(mb, s.modulus, s.time),
            )),
            (Some(m), None) | (None, Some(m)) => one(m),
            (None, None) => return Err(Error::Internal("TwoBodies refuses two rigid bodies")),
        },
    };
    Ok(mdr::CanonicalMaterial {
        prony: impact.canonical_relaxation(),
        network,
    })
}

/// Refusals of `fast` after which `auto` asks `reference`: accuracy or work it could not reach,
/// and a series with more terms than it accepts ([`fast::FAST_MAX_TERMS`]; a general material's
/// `G_eq` can have many).
fn fast_refusal_falls_back(e: &Error) -> bool {
    matches!(
        e,
        Error::AccuracyNotReached { .. }
            | Error::NoConvergence { .. }
            | Error::WorkLimit { .. }
            | Error::StepSizeTooSmall { .. }
            | Error::TooManyTerms { .. }
    )
}

/// The canonical relaxation function of the reference solver: derived by `theory::poles`, not
/// by the `material::carson` composition that `fast` integrates (the standard solid's closed
/// form is the same for both).
fn reference_prony(impact: &Impact) -> Result<crate::model::material::Prony> {
    let s = impact.scales();
    Ok(theory::poles::reference_relaxation(impact)?.scaled(s.modulus, s.time))
}

fn solve_canonical(impact: &Impact, opts: &SolveOptions) -> Result<Outcome> {
    let prony = impact.canonical_relaxation();
    let scheme = match (opts.solver, opts.resolution) {
        (SolverKind::MdrEuler, _) => mdr::Scheme::Euler,
        (SolverKind::Mdr, _) | (SolverKind::Auto, Some(_)) => mdr::Scheme::Exponential,
        (SolverKind::Reference, _) | (SolverKind::Auto, None) if opts.history => {
            // histories on a uniform grid, forces evaluated from the dense solution
            return theory::reference::impact_sampled(
                &reference_prony(impact)?,
                opts.rtol.max(1e-13),
                tolerances::HISTORY_SAMPLES,
            );
        }
        (SolverKind::Reference, _) => {
            return theory::impact(&reference_prony(impact)?, opts.rtol, false);
        }
        (SolverKind::Fast, _) => return fast::impact(&prony, opts.rtol, opts.history),
        (SolverKind::Auto, None) => {
            // The cheapest solver for any rtol is the reduced one, which verifies itself by
            // successively tighter solves; should it refuse, the reference solver (a different
            // integrator, verified the same way) answers instead, and the outcome says why.
            return match fast::impact(&prony, opts.rtol, opts.history) {
                Ok(o) => Ok(o),
                Err(first) if fast_refusal_falls_back(&first) => {
                    let reference = reference_prony(impact)
                        .and_then(|p| theory::impact(&p, opts.rtol, opts.history));
                    match reference {
                        Ok(mut o) => {
                            o.fallback = Some(Box::new(first));
                            Ok(o)
                        }
                        Err(second) => Err(Error::NoSolver {
                            first: Box::new(first),
                            second: Box::new(second),
                        }),
                    }
                }
                Err(e) => Err(e),
            };
        }
    };
    let material = canonical_material(impact)?;
    match opts.resolution {
        Some(r) => {
            let needed = (r.elements as u64).saturating_mul(r.steps as u64);
            if needed > opts.work_limit {
                return Err(Error::WorkLimit {
                    solver: scheme.name(),
                    what: "elements x steps",
                    needed,
                    limit: opts.work_limit,
                });
            }
            let layout = mdr::pilot_material(&material)?;
            mdr::run_resolution(
                scheme,
                &material,
                &layout,
                r.elements,
                r.steps,
                opts.history,
            )
        }
        None => mdr::solve_rtol(scheme, &material, opts.rtol, opts.history, opts.work_limit),
    }
}

/// Refuse to hand out a non-finite or unphysical outcome.
fn check_outcome(o: &Outcome) -> Result<()> {
    for (what, v) in [
        ("cor", o.cor),
        ("contact_time", o.contact_time),
        ("max_indentation", o.max_indentation),
        ("time_of_max_indentation", o.time_of_max_indentation),
        ("max_contact_radius", o.max_contact_radius),
        ("max_force", o.max_force),
        ("dissipated_energy", o.dissipated_energy),
    ] {
        if !v.is_finite() {
            return Err(Error::NonFinite { what, value: v });
        }
    }
    Ok(())
}

/// Which method computes a prescribed-indentation force curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IndentMethod {
    /// Lee–Radok/Ting by quadrature ([`theory::response`]).
    Theory,
    /// The MDR foundation driven by the prescribed indentation ([`mdr::indent::response`]).
    Mdr,
}

impl std::str::FromStr for IndentMethod {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "theory" => Ok(IndentMethod::Theory),
            "mdr" => Ok(IndentMethod::Mdr),
            _ => Err(Error::Unsupported(format!(
                "unknown indentation solver '{s}': expected theory or mdr"
            ))),
        }
    }
}

/// One row of a force curve: time (s), depth (m), contact radius (m), force (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceCurveRow {
    /// Time (s).
    pub t: f64,
    /// Prescribed depth (m).
    pub d: f64,
    /// Contact radius (m), 0 after separation.
    pub a: f64,
    /// Contact force (N), 0 after separation.
    pub force: f64,
}

/// Force curve of a rigid sphere of radius `radius` (m) pressed into `material` along `history`
/// (SI), at `times` (s, sorted), by Lee–Radok/Ting theory or by the displacement-driven MDR.
pub fn force_curve(
    material: &crate::model::material::Material,
    radius: f64,
    history: &crate::solvers::indentation::Prescribed,
    times: &[f64],
    method: IndentMethod,
) -> Result<Vec<ForceCurveRow>> {
    let prony = material.equivalent_relaxation()?;
    let row = |t, d, a, force| ForceCurveRow { t, d, a, force };
    let rows: Vec<ForceCurveRow> = match method {
        IndentMethod::Theory => theory::response(&prony, radius, history, times)?
            .into_iter()
            .map(|s| row(s.t, s.d, s.a, s.force))
            .collect(),
        IndentMethod::Mdr => {
            mdr::indent::response(&prony, radius, history, times, Default::default())?
                .into_iter()
                .map(|s| row(s.t, s.d, s.a, s.force))
                .collect()
        }
    };
    for r in &rows {
        if !(r.force.is_finite() && r.a.is_finite()) {
            return Err(Error::NonFinite {
                what: "force curve",
                value: r.force,
            });
        }
    }
    Ok(rows)
}
