//! The one entry point of oblique impacts ([`solve_oblique`], docs/theory.md §14): the normal
//! impact as [`crate::solvers::solve`] answers it, and the tangential problem on top.
//!
//! - no friction, or neither tangential velocity nor spin: the normal impact of [`solve`] (bit
//!   for bit the same outcome) and the trivial tangential answer (nothing changes tangentially);
//! - otherwise `mdr` (and `auto`, which says so: [`AUTO_OBLIQUE`]) on the tangential foundation
//!   ([`crate::solvers::mdr::oblique`]), or `reference`, the independent route of
//!   [`crate::solvers::theory::oblique`] (Lee–Radok/Ting normal history, its own discretisation
//!   of the Coulomb foundation); `fast` and `mdr-euler` refuse in one line.

use crate::error::{Error, Result};
use crate::model::contact::CanonicalOutcome;
use crate::model::impact::{Impact, Outcome};
use crate::model::oblique::{Oblique, TangentialHistory, TangentialOutcome};
use crate::solvers::api::{SolveOptions, SolverKind};
use crate::solvers::dispatch::solve;
use crate::solvers::{mdr, theory};

/// Why `auto` answers an oblique impact with `mdr`.
pub const AUTO_OBLIQUE: &str = "an oblique impact with friction: mdr, the solver with the \
     tangential foundation (fast has no tangential reduction)";

/// Why `auto` answers an oblique impact with `reference`: `mdr` failed on it.
pub const AUTO_OBLIQUE_FALLBACK: &str = "an oblique impact with friction on which mdr's \
     stick/slip iteration did not converge: the independent reference route answered";

/// An oblique impact's outcome (SI): the normal outcome and the tangential one.
#[derive(Debug, Clone)]
pub struct ObliqueOutcome {
    /// The normal impact.
    pub normal: Outcome,
    /// The tangential results.
    pub tangential: TangentialOutcome,
    /// Tangential histories when histories were requested.
    pub history: Option<TangentialHistory>,
    /// Estimated absolute error of `tangential_cor` (adaptive `mdr`, `reference`), if known.
    pub tangential_error_estimate: Option<f64>,
    /// Why `auto` chose the solver it did (oblique scenes only).
    pub reason: Option<&'static str>,
}

/// Canonical tangential results of a solver: impulse (`m v0`), friction work (`m v0^2`),
/// history rows `[t, Q, slip radius, v_c]` and an error estimate of `v_c' / v_c`.
pub(crate) struct CanonicalTangential {
    pub impulse: f64,
    pub friction_work: f64,
    pub rows: Option<Vec<[f64; 4]>>,
    pub error: Option<f64>,
}

/// Solve an oblique impact (module docs). The normal outcome of `mdr` is its normal run on the
/// accepted grid; its CoR is projected onto `(0, 1]` as in [`solve`].
pub fn solve_oblique(
    impact: &Impact,
    oblique: &Oblique,
    opts: &SolveOptions,
) -> Result<ObliqueOutcome> {
    opts.validate()?;
    if oblique.is_trivial() {
        let normal = solve(impact, opts)?;
        let tangential = oblique.outputs(impact, normal.cor, 0.0, 0.0);
        let history = normal.history.as_ref().map(|h| TangentialHistory {
            t: h.t.clone(),
            force: vec![0.0; h.len()],
            slip_radius: vec![0.0; h.len()],
            slip_velocity: vec![tangential.slip_velocity_after; h.len()],
        });
        return Ok(ObliqueOutcome {
            normal,
            tangential,
            history,
            tangential_error_estimate: None,
            reason: None,
        });
    }
    let tangential = oblique.tangential(impact)?;
    let contact = impact.contact()?;
    let s = impact.scales();
    let reference = || -> Result<_> {
        let run = theory::oblique::solve(&contact, &tangential, opts.rtol)?;
        let t = CanonicalTangential {
            impulse: run.impulse,
            friction_work: run.friction_work,
            rows: opts.history.then_some(run.rows),
            error: None,
        };
        Ok((run.normal, t))
    };
    let (canonical, t, reason) = match opts.solver {
        SolverKind::Auto | SolverKind::Mdr => {
            let material = mdr::CanonicalMaterial::of(&contact);
            let run = mdr::oblique::solve_oblique(
                &material,
                &tangential,
                opts.rtol,
                opts.resolution.map(|r| (r.elements, r.steps)),
                opts.history,
                opts.work_limit,
            );
            match run {
                Ok(run) => {
                    let reason = (opts.solver == SolverKind::Auto).then_some(AUTO_OBLIQUE);
                    let t = CanonicalTangential {
                        impulse: run.impulse,
                        friction_work: run.friction_work,
                        rows: run.history,
                        error: run.error_estimate,
                    };
                    (run.normal, t, reason)
                }
                // `auto` answers by the independent route where mdr's stick/slip iteration
                // fails (an extreme friction coefficient: every element sticks), as the normal
                // `auto` falls back. Not where mdr's estimate misses the accuracy: there (an
                // inertia factor below about 1e-6, a tangential period a thousandth of the
                // contact) the reference's grid does not resolve the motion either, and its
                // answer drifts without a warning
                Err(e @ Error::NoConvergence { .. }) if opts.solver == SolverKind::Auto => {
                    match reference() {
                        Ok((normal, t)) => (normal, t, Some(AUTO_OBLIQUE_FALLBACK)),
                        Err(r) => {
                            return Err(Error::NotSupported {
                                solver: "auto",
                                what: format!("mdr: {e}; fallback reference: {r}"),
                            })
                        }
                    }
                }
                Err(e) => return Err(e),
            }
        }
        SolverKind::Reference => {
            let (normal, t) = reference()?;
            (normal, t, None)
        }
        SolverKind::Fast | SolverKind::MdrEuler => {
            return Err(Error::NotSupported {
                solver: opts.solver.name(),
                what: "oblique impacts with friction have no tangential model here; use mdr, \
                       reference or auto"
                    .into(),
            })
        }
    };
    let mut normal = CanonicalOutcome::new(canonical).to_si(&s);
    if !(normal.cor.is_finite() && t.impulse.is_finite()) {
        return Err(Error::NonFinite {
            what: "oblique outcome",
            value: normal.cor + t.impulse,
        });
    }
    if normal.cor > 1.0 {
        normal.cor = 1.0;
        normal.rebound_velocity = s.velocity;
        normal.dissipated_energy = 0.0;
    }
    let out = oblique.outputs(impact, normal.cor, t.impulse, t.friction_work);
    let history = t.rows.map(|rows| TangentialHistory {
        t: rows.iter().map(|r| r[0] * s.time).collect(),
        force: rows.iter().map(|r| r[1] * s.force).collect(),
        slip_radius: rows.iter().map(|r| r[2] * s.radius).collect(),
        slip_velocity: rows.iter().map(|r| r[3] * s.velocity).collect(),
    });
    Ok(ObliqueOutcome {
        normal,
        tangential: out,
        history,
        tangential_error_estimate: t.error,
        reason,
    })
}
