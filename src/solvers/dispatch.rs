//! The top-level [`solve`]: a validated [`Impact`] becomes its [`Contact`] in canonical units,
//! the solver of the table answers ([`solver_for`]), and the outcome maps back to SI. `auto`
//! is a solver too ([`Auto`]).

use crate::error::{Error, Result};
use crate::model::contact::{CanonicalOutcome, Contact, Geometry};
use crate::model::impact::{Impact, Outcome};
use crate::model::tolerances;
use crate::solvers::api::{ImpactSolver, SolveOptions, SolverKind};
use crate::solvers::fast;
use crate::solvers::mdr;
use crate::solvers::theory;

pub use crate::solvers::mdr::canonical_material;

/// Solve an impact. Elastic materials use the Hertz closed form whatever the solver.
///
/// A general material (Prony series in shear and bulk) is solved by `fast` (and `auto`) from its
/// canonical `G_eq` series of `material::carson`, by `reference` from the same function derived
/// independently (`material::poles`), and by `mdr` on its element network built from `G` and `K`
/// ([`crate::model::material::GeneralNetwork`], a third path); two bodies likewise, `mdr` on the
/// two networks in series ([`crate::model::material::StackedNetwork`]). `mdr-euler` runs the
/// paper's explicit Euler on one body's network (the standard solid's of Eq. 8 or a general
/// material's) and refuses two viscoelastic bodies ([`Error::NotSupported`],
/// [`MDR_EULER_GENERAL_UNSUPPORTED`]).
///
/// In nearly elastic cases a solver's discretisation error can push the CoR above 1; since
/// `e <= 1` holds exactly (a passive material dissipates a non-negative energy), such a value is
/// projected onto `(0, 1]` (`e = 1`, no dissipated energy); the error estimate is kept as
/// computed, and the projection only ever reduces the error.
pub fn solve(impact: &Impact, opts: &SolveOptions) -> Result<Outcome> {
    opts.validate()?;
    if impact.is_elastic()
        && opts.resolution.is_none()
        && impact.canonical_geometry() == Geometry::UNIT_SPHERE
    {
        // nothing to integrate: the Hertz closed form is exact (for the paraboloid; other
        // shapes' elastic impacts are solved, and checked against their closed forms in
        // tests/shapes.rs)
        let o = theory::hertz_outcome(
            impact,
            opts.history.then_some(tolerances::HERTZ_HISTORY_SAMPLES),
        )?;
        check_outcome(&o)?;
        return Ok(o);
    }
    let contact = impact.contact()?;
    let mut canonical = solver_for(opts.solver).solve(&contact, opts).map_err(|e| {
        if impact.target().relaxes_to_zero() {
            // the solvers fail where a liquid relaxes fast against the contact: the sphere
            // then comes to rest in it (e -> 0, contact time -> inf as g_inf -> 0+)
            e.at(LIQUID_PLACE)
        } else if let Some(x) = relaxed_sinks(impact) {
            // a solid whose relaxed modulus could not hold the sphere fails like a liquid
            e.at(format!(
                "a nearly liquid material: on its relaxed modulus alone the sphere would sink \
                 to a_max/R = {} (the relaxed Hertz estimate), so it may hold the sphere when \
                 it relaxes fast against the contact (the CoR tends to 0 and the contact time \
                 to inf as g_inf -> 0+)",
                crate::model::validity::ratio_text(x)
            ))
        } else if let Some(x) = exact_sphere_reach(impact) {
            // the exact cap's contact radius cannot pass its radius: the solvers fail as the
            // contact approaches it
            e.at(format!(
                "an exact sphere whose contact may reach its radius (the relaxed Hertz estimate \
                 gives a_max/R = {}; the exact cap ends at a = R, and the half-space model \
                 long before): a larger radius, a lower velocity, or the paraboloid (shape or \
                 profile \"paraboloid\") for its formal answer",
                crate::model::validity::ratio_text(x)
            ))
        } else {
            e
        }
    })?;
    check_outcome(&canonical)?;
    if canonical.cor > 1.0 {
        let o = canonical.get_mut();
        o.cor = 1.0;
        o.rebound_velocity = 1.0;
        o.dissipated_energy = 0.0;
    }
    Ok(canonical.to_si(&impact.scales()))
}

/// Where a failed solve of a viscoelastic liquid (`g_inf = 0`) is placed ([`Error::at`]): what
/// usually makes it fail (docs/theory.md §15).
pub const LIQUID_PLACE: &str = "g_inf = 0, a viscoelastic liquid that may hold the sphere (the \
    CoR tends to 0 and the contact time to inf when it relaxes fast against the contact)";

/// The relaxed Hertz estimate of `a_max / R` of an impactor with a radius, when it exceeds 1
/// while the glassy one stays below 1: a material whose relaxed modulus alone cannot hold the
/// sphere within the half-space model, though its glassy modulus could (`g_inf` far below the
/// glassy modulus; the solvers fail on it as on a liquid, `g_inf = 0`). The Hertz contact
/// radius scales as `E*^(-1/5)`, so the glassy estimate is the relaxed one times
/// `(G_eq(inf) / G_eq(0))^(1/5)`.
fn relaxed_sinks(impact: &Impact) -> Option<f64> {
    let r = impact
        .shape()
        .tip_radius()
        .unwrap_or(impact.sphere().radius());
    let x = crate::model::hertz::HertzImpact::relaxed(impact)
        .ok()?
        .max_contact_radius()
        / r;
    let g = impact.equivalent_relaxation();
    let glassy = x * (g.relaxed / g.glassy()).powf(0.2);
    (r.is_finite() && x > 1.0 && glassy < 1.0).then_some(x)
}

/// The relaxed Hertz estimate of `a_max` (an upper bound: the viscoelastic material is stiffer)
/// over the radius the exact cap's contact cannot reach ([`Shape::cap_limit`]), when it exceeds
/// [`crate::model::validity::EXACT_SPHERE_MAX_CONTACT_RADIUS_RATIO`].
///
/// [`Shape::cap_limit`]: crate::model::geometry::Shape::cap_limit
fn exact_sphere_reach(impact: &Impact) -> Option<f64> {
    let r = impact.shape().cap_limit()?;
    let x = crate::model::hertz::HertzImpact::relaxed(impact)
        .ok()?
        .max_contact_radius()
        / r;
    (x > crate::model::validity::EXACT_SPHERE_MAX_CONTACT_RADIUS_RATIO).then_some(x)
}

/// The solver of a kind: the one place that maps the table's names to implementations.
pub fn solver_for(kind: SolverKind) -> &'static dyn ImpactSolver {
    match kind {
        SolverKind::Auto => &Auto,
        SolverKind::MdrEuler => &mdr::Mdr(mdr::Scheme::Euler),
        SolverKind::Mdr => &mdr::Mdr(mdr::Scheme::Exponential),
        SolverKind::Reference => &theory::Reference,
        SolverKind::Fast => &fast::Fast,
    }
}

/// The one-line refusal of `mdr-euler` for two viscoelastic bodies.
pub const MDR_EULER_GENERAL_UNSUPPORTED: &str = mdr::EULER_GENERAL_UNSUPPORTED;

/// `auto`: the cheapest solver for the request. With an explicit resolution, `mdr`; with
/// histories, `reference` (uniform samples from its dense solution); otherwise `fast`, and when
/// `fast` refuses for accuracy, work or the number of terms, `reference`, the outcome saying why
/// ([`Outcome::fallback`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Auto;

impl ImpactSolver for Auto {
    fn kind(&self) -> SolverKind {
        SolverKind::Auto
    }
    fn solve(&self, contact: &Contact, opts: &SolveOptions) -> Result<CanonicalOutcome> {
        if opts.resolution.is_some() {
            return mdr::Mdr(mdr::Scheme::Exponential).solve(contact, opts);
        }
        if opts.history {
            return theory::Reference.solve(contact, opts);
        }
        // The cheapest solver for any rtol is the reduced one, which verifies itself by
        // successively tighter solves; should it refuse, the reference solver (a different
        // integrator, verified the same way) answers instead, and the outcome says why.
        match fast::Fast.solve(contact, opts) {
            Ok(o) => Ok(o),
            Err(first) if fast_refusal_falls_back(&first) => {
                match theory::Reference.solve(contact, opts) {
                    Ok(mut o) => {
                        o.get_mut().fallback = Some(Box::new(first));
                        Ok(o)
                    }
                    Err(second) => Err(Error::NoSolver {
                        first: Box::new(first),
                        second: Box::new(second),
                    }),
                }
            }
            Err(e) => Err(e),
        }
    }
}

/// Refusals of `fast` after which `auto` asks `reference`: accuracy or work it could not reach,
/// a series with more terms than it accepts ([`fast::FAST_MAX_TERMS`]; a general material's
/// `G_eq` can have many), and an indenter shape it does not solve.
fn fast_refusal_falls_back(e: &Error) -> bool {
    matches!(
        e,
        Error::AccuracyNotReached { .. }
            | Error::NoConvergence { .. }
            | Error::WorkLimit { .. }
            | Error::StepSizeTooSmall { .. }
            | Error::TooManyTerms { .. }
            | Error::NotSupported { .. }
    )
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
            _ => Err(Error::Parse {
                what: "indentation solver",
                input: crate::error::escape_text(s),
                expected: "theory or mdr".into(),
            }),
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

/// Force curve of a rigid indenter of `shape` (SI) pressed into `material` along `history` (SI),
/// at `times` (s, sorted), by Lee–Radok/Ting theory or by the displacement-driven MDR.
pub fn force_curve(
    material: &crate::model::material::Material,
    shape: &crate::model::geometry::Shape,
    history: &crate::solvers::indentation::Prescribed,
    times: &[f64],
    method: IndentMethod,
) -> Result<Vec<ForceCurveRow>> {
    let prony = material.equivalent_relaxation()?;
    let geometry = shape.validated()?.geometry_si();
    let row = |t, d, a, force| ForceCurveRow { t, d, a, force };
    let rows: Vec<ForceCurveRow> = match method {
        IndentMethod::Theory => {
            theory::viscoelastic::response_on(&geometry, &prony, history, times)?
                .into_iter()
                .map(|s| row(s.t, s.d, s.a, s.force))
                .collect()
        }
        IndentMethod::Mdr => {
            mdr::indent::response_on(&geometry, &prony, history, times, Default::default())?
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
