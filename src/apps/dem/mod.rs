//! Parameters for DEM codes (`mdr-impact dem`): the damping laws of LAMMPS and LIGGGHTS that best
//! reproduce a scene's `e(v0)` over a velocity range, with the Hertz stiffness they need.
//!
//! # The DEM force laws
//! A DEM code models the normal contact of two spheres (or a sphere and a wall) by a Hertz
//! spring and a damper acting on the overlap `delta` (m) and its rate `delta'` (m/s):
//!
//! ```text
//! m delta'' = -F,   F = max(0, k delta^(3/2) + F_d),   k = (4/3) E* sqrt(R)   (N/m^(3/2))
//! ```
//!
//! with the effective mass `m` (kg), radius `R` (m) and plane-strain modulus `E*` (Pa). Two
//! damping laws are fitted:
//!
//! - **constant CoR** (LAMMPS `damping coeff_restitution`, LIGGGHTS `model hertz` with
//!   `coefficientRestitution`): `F_d = gamma sqrt(m k) delta^(1/4) delta'` with
//!   `gamma = sqrt(5) (-ln e_in) / sqrt(pi^2 + ln^2 e_in)` for the input CoR `e_in`. LAMMPS
//!   computes `eta_n = sqrt(3/2) 2 sqrt(5/6) (-ln e) / sqrt(pi^2 + ln^2 e) sqrt(m F_ne / delta)`
//!   with `F_ne / delta = k sqrt(delta)`
//!   (<https://docs.lammps.org/pair_granular.html>, section on `damping coeff_restitution`);
//!   LIGGGHTS computes `gamma_n = -2 sqrt(5/6) beta sqrt(S_n m)`, `S_n = 2 Y* sqrt(R delta)`,
//!   `beta = ln e / sqrt(ln^2 e + pi^2)`
//!   (<https://www.cfdem.com/media/DEM/docu/gran_model_hertz.html>): the same force. Its CoR
//!   does not depend on `v0` (the force law has no scale), but it is not exactly `e_in` either,
//!   so the input value is found by root finding on our own integration of the law.
//! - **viscoelastic** (Brilliantov, Spahn, Hertzsch, Pöschel, Phys. Rev. E 53, 5382 (1996);
//!   Kuwabara–Kono): `F = k (delta^(3/2) + (3/2) A sqrt(delta) delta')` with the dissipative
//!   constant `A` (s). In LAMMPS this is `damping viscoelastic`, `eta_n = eta_n0 a m` with the
//!   contact radius `a = sqrt(R delta)` (<https://docs.lammps.org/pair_granular.html>), so
//!   `eta_n0 = 2 E* A / m` (1/(m s)). Its CoR falls with `v0^(1/5)`
//!   (`1 - e ~ 1.15344 (3/2) A (k/m)^(2/5) v0^(1/5)` for small `A`, Schwager and Pöschel,
//!   Phys. Rev. E 57, 650 (1998)). LIGGGHTS-PUBLIC's `model hertz` has no such law.
//!
//! **The tensile force.** Near the end of a damped contact the damping term outgrows the
//! elastic one (`delta'` stays finite while `delta -> 0`) and the sum turns attractive. We
//! clip the force at zero, as LAMMPS does with the `limit_damping` keyword ("zero out the normal
//! component of the force if there is an effective attractive force", same page) and LIGGGHTS
//! with `limitForce on`; the emitted input lines carry that keyword. Physically the surfaces
//! separate when the force vanishes, before the overlap returns to zero (Schwager and Pöschel,
//! Phys. Rev. E 78, 051304 (2008)); from then on the spheres fly apart at constant velocity, so
//! the CoR is the rebound velocity at the instant the force reaches zero.
//!
//! **The integration.** In units of the Hertz length `(m v0^2 / k)^(2/5)` and time
//! `length / v0` every law becomes `x'' = -(x^(3/2) + c x^p x')`, `x(0) = 0`, `x'(0) = 1`, with
//! `p = 1/4`, `c = gamma` (constant CoR) and `p = 1/2`, `c = (3/2) A v0^(1/5) (k/m)^(2/5)`
//! (viscoelastic). [`integrate`] solves it by the adaptive Dormand–Prince 5(4) pair and locates
//! the end of contact (`x^(3/2 - p) + c x' = 0`, the zero of `F / x^p`) by bisection on the last
//! step.
//!
//! # The Hertz stiffness
//! `E*` comes from the equivalent incompressible relaxation function (docs/theory.md §2, §8):
//! `E* = 4 G_eq(inf)` with `--modulus relaxed` (the default) and `E* = 4 G_eq(0)` with
//! `--modulus glassy`, `G_eq` the combined `G_tot` for two bodies. LAMMPS `hertz/material` and
//! LIGGGHTS take a Young's modulus and a Poisson ratio per type and mix them as
//! `E* = (2 (1 - nu^2) / E)^-1` for equal types (and walls); we give both types
//! `E = 2 (1 - nu^2) E* = 1.5 E*` with `nu = 0.5`, the equivalent incompressible solid, so that
//! the codes' mixing returns our `E*` exactly. `nu` enters their tangential stiffness only,
//! which a normal impact does not determine.
//!
//! # LAMMPS versions
//! LAMMPS before [`LAMMPS_WALL_MIX_SINCE`] mixes a `fix wall/gran` wall as `E / (2 (1 - nu))`:
//! the wall line then gets `E = 2 (1 - nu) E* = E*`. LAMMPS before
//! [`LAMMPS_COEFF_RESTITUTION_SINCE`] has no `damping coeff_restitution`; its `damping tsuji`
//! multiplies the same `sqrt(m F_ne / delta) delta'` by Marshall's polynomial of its input, so
//! the constant-CoR law is written as `damping tsuji` with [`tsuji_input`]. Both were checked by
//! running LAMMPS [`LAMMPS_PROVEN`] and LIGGGHTS 3.8.0 (`validation/dem_clients/verify.py`).

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::apps::curve::{self, CurveRow, VelocityRange};
use crate::error::{Error, Result};
use crate::io::output::{fmt, write_atomic};
use crate::io::plot::{panels_svg, velocity_span, CorLine, Panel, COR_AXIS_TOP};
use crate::model::impact::Impact;
use crate::solvers::SolveOptions;
use plotters::style::RGBColor;

mod fitting;
mod laws;
mod output;
pub mod tangential;
mod versions;

pub use fitting::*;
pub use laws::*;
pub use output::*;
pub use versions::*;

/// Velocities of `--v0 MIN:MAX` when `N` is left out: the one default of every `--v0`.
pub const DEFAULT_VELOCITIES: usize = crate::apps::curve::DEFAULT_VELOCITIES;

/// A law whose worst relative CoR error over the range exceeds this is reported with a warning.
pub const WARN_REL_ERROR: f64 = 0.05;

/// A law whose contact time misses ours by more than this (relative) at some velocity is
/// warned about: the contact time sets the DEM time step and the duration of collisions in
/// dense flows.
pub const WARN_CONTACT_TIME_REL_ERROR: f64 = 0.10;

/// Poisson ratio given to both types in the emitted input lines (the equivalent incompressible
/// solid, see the module docs).
pub const DEM_POISSON: f64 = 0.5;

/// LIGGGHTS refuses Young's moduli at or below this in SI units (Pa; restriction on
/// <https://www.cfdem.com/media/DEM/docu/gran_model_hertz.html>).
pub const LIGGGHTS_MIN_YOUNG: f64 = 5e6;

/// Relative tolerance of the DEM ODE integration (per step, mixed with [`ODE_ATOL`]).
pub const ODE_RTOL: f64 = 1e-11;
/// Absolute tolerance of the DEM ODE integration (dimensionless overlap and rate).
pub const ODE_ATOL: f64 = 1e-13;
/// Step cap of one DEM ODE integration.
pub const ODE_MAX_STEPS: u64 = 200_000;

/// Smallest input CoR of the constant-CoR law the fit writes. The law's CoR has a floor as the
/// input goes to zero (`gamma -> sqrt(5)`), so a curve below it is answered with this input and
/// a warning.
pub const MIN_COR_INPUT: f64 = 1e-6;

/// Velocities the viscoelastic fit uses at most (an even subsample of a longer curve; its
/// errors are still evaluated at every velocity).
pub const FIT_MAX_VELOCITIES: usize = 200;

/// Largest damping coefficient `c` of the viscoelastic law searched by the fit (dimensionless;
/// `e` is about 0.1 there).
const MAX_VISCO_C: f64 = 100.0;

/// Everything `mdr-impact dem` reports.
#[derive(Debug, Clone, PartialEq)]
pub struct DemReport {
    /// Our `e(v0)`.
    pub rows: Vec<CurveRow>,
    /// Log-spaced velocities.
    pub log: bool,
    /// The modulus limit of the Hertz stiffness.
    pub modulus: ModulusChoice,
    /// The Hertz contact.
    pub contact: HertzContact,
    /// Pair or wall.
    pub geometry: Geometry,
    /// The constant-CoR law.
    pub constant: ConstantLaw,
    /// The viscoelastic law.
    pub viscoelastic: ViscoelasticLaw,
    /// Contact times of the constant-CoR law.
    pub constant_times: ContactTimes,
    /// Contact times of the viscoelastic law.
    pub viscoelastic_times: ContactTimes,
    /// Warnings, one line each (without the `warning: ` prefix).
    pub warnings: Vec<String>,
}

/// How the DEM code sees `impact`'s contact, and a warning when a wall of finite mass moves or
/// a fixed body is not flat.
fn geometry(impact: &Impact) -> (Geometry, Option<String>) {
    let Some(b) = impact.bodies() else {
        return (Geometry::Wall, None);
    };
    let (a, bb) = (b.a(), b.b());
    let wall = a.radius().is_infinite() || bb.radius().is_infinite();
    let heavy = a.mass().is_infinite() || bb.mass().is_infinite();
    match (wall, heavy) {
        (false, false) => (Geometry::Pair, None),
        (true, true) => (Geometry::Wall, None),
        (false, true) => (
            Geometry::Wall,
            Some(
                "a body of infinite mass has a finite radius: DEM walls are flat, so the DEM \
                 code uses the particle's radius where these parameters assume the effective \
                 radius"
                    .into(),
            ),
        ),
        (true, false) => (
            Geometry::Wall,
            Some(
                "a body of infinite radius has finite mass: DEM walls do not move, so the DEM \
                 code uses the particle's mass where these parameters assume the effective mass"
                    .into(),
            ),
        ),
    }
}

/// Solve `impact` over `range` (our `e(v0)`, [`curve::run`]) and fit both laws with the Hertz
/// stiffness of `modulus` ([`ModulusChoice::Fit`]: the stiffness that matches our contact
/// times, [`fit_stiffness`]).
pub fn run(
    impact: &Impact,
    opts: &SolveOptions,
    range: &VelocityRange,
    modulus: ModulusChoice,
    progress: &(dyn Fn() + Sync),
) -> Result<DemReport> {
    let liquid = impact.target().relaxes_to_zero();
    if liquid && modulus == ModulusChoice::Relaxed {
        return Err(Error::NotSupported {
            solver: "dem",
            what: "--modulus relaxed does not apply: g_inf = 0 (a viscoelastic liquid has no \
                   relaxed modulus); use --modulus glassy or fit"
                .into(),
        });
    }
    let c = curve::run(impact, opts, range, progress)?;
    let e_star = match modulus {
        // a liquid's fit starts from the glassy stiffness (it has no relaxed one)
        ModulusChoice::Fit if liquid => c.limits.glassy_modulus,
        ModulusChoice::Relaxed | ModulusChoice::Fit => c.limits.relaxed_modulus,
        ModulusChoice::Glassy => c.limits.glassy_modulus,
    };
    let sphere = impact.sphere();
    let (radius, shape_note) = hertz_radius(impact, opts, range)?;
    let contact = HertzContact::new(sphere.mass(), radius, e_star)?;
    let (geometry, note) = geometry(impact);
    let mut report = fit(c.rows, range.log, modulus, contact, geometry, note)?;
    report.warnings.extend(shape_note);
    Ok(report)
}

/// The radius of the Hertz contact the DEM laws assume: the impactor's radius of curvature
/// (paraboloid, exact sphere), or, for a cone, a power law or a flat punch, the radius of the
/// paraboloid through the contact edge at the maximum compression of the middle velocity of
/// `range`, `R = a_max^2 / d_max`, with a warning that says what the Hertzian laws miss.
fn hertz_radius(
    impact: &Impact,
    opts: &SolveOptions,
    range: &VelocityRange,
) -> Result<(f64, Option<String>)> {
    if let Some(r) = impact.shape().tip_radius() {
        let note = matches!(
            impact.shape(),
            crate::model::geometry::Shape::Spheres { .. }
        )
        .then(|| {
            "the DEM codes' Hertz laws are the paraboloid's: with a contact radius near the \
             sphere's they overestimate the force at a given overlap (docs/theory.md §12)"
                .to_string()
        });
        return Ok((r, note));
    }
    let v_mid = if range.log {
        (range.min * range.max).sqrt()
    } else {
        0.5 * (range.min + range.max)
    };
    let o = crate::solvers::solve(&impact.at_velocity(v_mid)?, opts)?;
    let r = o.max_contact_radius * o.max_contact_radius / o.max_indentation;
    Ok((
        r,
        Some(format!(
            "the impactor is a {} and the DEM codes' laws are Hertzian (force ~ overlap^(3/2)): \
             they stand in with the paraboloid through the contact edge at {v_mid:.3e} m/s, \
             R = {r:.4e} m; the force-overlap curve differs in shape (use --modulus fit to \
             match the contact times)",
            match impact.shape().name() {
                "flat" => "flat punch",
                "power-law" => "power-law indenter",
                other => other,
            }
        )),
    ))
}

/// The effective modulus `E*` (Pa) at which the two laws' contact times best match ours in
/// least squares of `ln(t_law / t)` over both laws and every velocity of `report` (fitted with
/// any stiffness): each law's contact time scales as `E*^(-2/5)` at a fixed CoR, so the optimum
/// is `E* = E*_report exp((5/2) mean(ln(t_law / t)))`.
pub fn fit_stiffness(report: &DemReport) -> f64 {
    let mut sum = 0.0;
    let mut n = 0usize;
    for law in [&report.constant_times.law, &report.viscoelastic_times.law] {
        for (t, r) in law.iter().zip(&report.rows) {
            sum += (t / r.contact_time).ln();
            n += 1;
        }
    }
    report.contact.effective_modulus * (2.5 * sum / n as f64).exp()
}

/// Fit both laws to `rows` (our `e(v0)`) with the Hertz `contact`; with [`ModulusChoice::Fit`]
/// `contact`'s modulus is only the start: the laws are fitted again at [`fit_stiffness`].
pub fn fit(
    rows: Vec<CurveRow>,
    log: bool,
    modulus: ModulusChoice,
    contact: HertzContact,
    geometry: Geometry,
    note: Option<String>,
) -> Result<DemReport> {
    if modulus != ModulusChoice::Fit {
        return fit_at(rows, log, modulus, contact, geometry, note);
    }
    let first = fit_at(rows, log, modulus, contact, geometry, None)?;
    let fitted = HertzContact::new(contact.mass, contact.radius, fit_stiffness(&first))?;
    fit_at(first.rows, log, modulus, fitted, geometry, note)
}

/// [`fit`] at the stiffness of `contact`.
fn fit_at(
    rows: Vec<CurveRow>,
    log: bool,
    modulus: ModulusChoice,
    contact: HertzContact,
    geometry: Geometry,
    note: Option<String>,
) -> Result<DemReport> {
    let v0: Vec<f64> = rows.iter().map(|r| r.v0).collect();
    let target: Vec<f64> = rows.iter().map(|r| r.cor).collect();
    if let Some(bad) = target.iter().find(|e| !(**e > 0.0 && **e <= 1.0)) {
        return Err(Error::NonFinite {
            what: "CoR of the curve (outside (0, 1])",
            value: *bad,
        });
    }
    if let Some(bad) = rows.iter().find(|r| !(r.contact_time > 0.0)) {
        return Err(Error::NonFinite {
            what: "contact time of the curve (not positive)",
            value: bad.contact_time,
        });
    }
    let constant = fit_constant(&target)?;
    // long curves: the parameter from an even subsample, the errors from every velocity
    let viscoelastic = if v0.len() > FIT_MAX_VELOCITIES {
        let pick: Vec<usize> = (0..FIT_MAX_VELOCITIES)
            .map(|i| i * (v0.len() - 1) / (FIT_MAX_VELOCITIES - 1))
            .collect();
        let sub = |x: &[f64]| -> Vec<f64> { pick.iter().map(|&i| x[i]).collect() };
        let a = fit_viscoelastic(&contact, &sub(&v0), &sub(&target))?.a;
        let cor = visco_cors(contact.viscoelastic_c(a, 1.0), &v0)?;
        ViscoelasticLaw {
            a,
            eta_n0: contact.lammps_eta_n0(a),
            fit: Fit::new(cor, &target),
        }
    } else {
        fit_viscoelastic(&contact, &v0, &target)?
    };
    let times = |law: DemLaw| -> Result<ContactTimes> {
        let law: Vec<f64> = v0
            .par_iter()
            .map(|v| contact.impact(law, *v).map(|d| d.contact_time))
            .collect::<Result<_>>()?;
        let worst_rel_error = law
            .iter()
            .zip(&rows)
            .map(|(t, r)| ((t - r.contact_time) / r.contact_time).abs())
            .fold(0.0, f64::max);
        Ok(ContactTimes {
            law,
            worst_rel_error,
        })
    };
    let constant_times = times(DemLaw::CoeffRestitution {
        cor_input: constant.cor_input,
    })?;
    let viscoelastic_times = times(DemLaw::Viscoelastic { a: viscoelastic.a })?;
    let mut warnings: Vec<String> = note.into_iter().collect();
    if constant.at_floor {
        warnings.push(format!(
            "the constant CoR law cannot produce less than e = {:.4} (input e = \
             {MIN_COR_INPUT:e}); our e(v0) lies lower",
            constant.cor
        ));
    }
    let pct = |x: f64| format!("{:.1} %", 100.0 * x);
    let laws = [
        ("constant CoR", &constant.fit),
        ("viscoelastic", &viscoelastic.fit),
    ];
    for (name, f) in laws {
        if f.worst_rel_error > WARN_REL_ERROR {
            warnings.push(format!(
                "the {name} law misses our e(v0) by up to {} (rms {}) over this range, more \
                 than {}",
                pct(f.worst_rel_error),
                pct(f.rms_rel_error),
                pct(WARN_REL_ERROR)
            ));
        }
    }
    for (name, t) in [
        ("constant CoR", &constant_times),
        ("viscoelastic", &viscoelastic_times),
    ] {
        if t.worst_rel_error > WARN_CONTACT_TIME_REL_ERROR {
            warnings.push(format!(
                "the {name} law's contact time misses ours by up to {} over this range with the \
                 {} Hertz stiffness, more than {}{}",
                pct(t.worst_rel_error),
                modulus.name(),
                pct(WARN_CONTACT_TIME_REL_ERROR),
                if modulus == ModulusChoice::Fit {
                    ""
                } else {
                    " (--modulus fit matches the contact times)"
                }
            ));
        }
    }
    if laws.iter().all(|(_, f)| f.worst_rel_error > WARN_REL_ERROR) {
        warnings.push(format!(
            "no damping law fits our e(v0) within {} over this range: narrow the range",
            pct(WARN_REL_ERROR)
        ));
    }
    if let Some(w) = curve::validity_warning(&rows) {
        warnings.push(format!(
            "our e(v0): {w}; the laws are fitted to those CoRs all the same"
        ));
    }
    if contact.dem_young() <= LIGGGHTS_MIN_YOUNG {
        warnings.push(format!(
            "Young's modulus {:.4e} Pa is at or below LIGGGHTS's lower limit {LIGGGHTS_MIN_YOUNG:e} \
             Pa (SI units)",
            contact.dem_young()
        ));
    }
    Ok(DemReport {
        rows,
        log,
        modulus,
        contact,
        geometry,
        constant,
        viscoelastic,
        constant_times,
        viscoelastic_times,
        warnings,
    })
}
