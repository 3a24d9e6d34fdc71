//! Material parameters from drop tests (`mdr-impact fit`): weighted nonlinear least squares of
//! measured coefficients of restitution (and contact times) against the impact solver.
//!
//! # Method
//! - Residuals: `(e_model - e) / sd_e` per drop and `(t_model - t_c) / sd_t` per measured contact
//!   time; without a `cor_sd` column `sd_e = 1` (absolute CoR residuals), without
//!   `contact_time_sd` `sd_t = t_c` (relative contact-time residuals). Forward model: [`solve`]
//!   with `auto` at [`FIT_RTOL`] (1e-8, far below any drop test's
//!   noise).
//! - Coordinates: `ln` of every modulus and viscosity (positivity) and the logistic coordinate
//!   of `nu` in `(-1, 0.5)` ([`model::ParamKind`]); fixed parameters (`--fix`) are left out.
//! - Multi-start: a grid over the sensible box (`p2 = g_inf / g_1` from 1e-4 to 1, `p3` at the
//!   data's mean velocity from 0.03 to 300, `nu` at -0.5, 0, 0.3, 0.4, 0.45, 0.47, 0.48, 0.49,
//!   denser near 0.5 where the misfit has narrow valleys along `nu`, and with contact times
//!   `g_inf` from 1e-3 to 1 times their Hertz modulus) is screened at a loose rtol;
//!   Levenberg–Marquardt (the `levenberg-marquardt` crate, MINPACK's algorithm, central-difference
//!   Jacobians) runs from the best [`FIT_LM_STARTS`], the best of every `nu` level, and the basins
//!   scouted (`global.rs`) from the best point of every decade of `p2` and the best
//!   [`FIT_SCOUT_TOP`] within [`FIT_SCOUT_KEEP`] thresholds of the best scout; least misfit wins.
//! - CoR alone depends on the material only through the groups of paper Eq. (11): `nu`,
//!   `p2 = g_inf / g_1` and `p3 = eta (v0 R / (m^2 g_inf^3))^(1/5)`, i.e. `eta / g_inf^(3/5)`
//!   for given spheres and velocities. Scaling `(g_inf, g_1, eta)` by `(s, s, s^(3/5))` leaves
//!   every CoR unchanged, so without contact times (and with none of `g_inf`, `g_1`, `eta`
//!   fixed) `g_inf` is held at an arbitrary reference and only `g_1`, `eta` and `nu` move: the
//!   fit then runs in coordinates equivalent to the identifiable ones.
//!
//! # Uncertainty and identifiability
//! At the estimate, the weighted Jacobian `J` over every parameter that is not fixed (`g_inf`
//! included even when it was held) is decomposed, `J = U S V^T`. Singular values at or below
//! [`FIT_NULL_RATIO`] times the largest span the *null space*: directions the data do not
//! determine. A parameter or group (a linear combination `a` of the coordinates) is
//! **identifiable** when
//! 1. its direction has no component above [`FIT_NULL_COMPONENT`] in the null space (else its
//!    value is not reported: `null`),
//! 2. the noise scale is known (every `*_sd` given) or there are residual degrees of freedom to
//!    estimate it (`s^2 = SSR / (n - rank)`),
//! 3. its 95 % interval is bounded: the Wald interval when it reaches at most
//!    [`FIT_MAX_HALF_WIDTH`] (a factor of 10 for a modulus) from the estimate in its coordinate
//!    and the profile misfit at each end and 1.5 half-widths out lies at or above the threshold
//!    (else the end moves out to where the profile crosses, and the quantity is not determined
//!    when that lies beyond [`FIT_MAX_HALF_WIDTH`]; docs/theory.md §16.1, `profile.rs`);
//!    otherwise, for a parameter, the profile-likelihood interval, which must close on both
//!    sides within [`FIT_PROFILE_STEPS`] steps of [`FIT_PROFILE_STEP`] (four decades; else the
//!    value is reported with `identifiable: false` and no interval). A group whose Wald interval
//!    is too wide is reported `identifiable: false` with that interval; a group whose Wald
//!    interval is narrow enough has its ends checked against its profile like a parameter.
//! 4. neither end of its interval lies on a flat shoulder of the profile: at twice an end's
//!    distance from the estimate the profile lies at least [`FIT_SHOULDER_LEVEL`] (scaled like
//!    the threshold when the noise is estimated) above the minimum (else the interval is kept
//!    and the quantity reported `identifiable: false`; docs/theory.md §16.1).
//!
//! The Wald interval is `a x ± q sqrt(s^2 a^T V S^-2 V^T a)` (range of `V` only), mapped back
//! to the parameter (`exp`, logistic), with `q` the normal quantile when the noise is known and
//! Student's `t` with `n - rank` degrees of freedom otherwise. The profile interval is where the
//! misfit, re-minimised over the other parameters, rises by `q^2 s^2` above its minimum. When
//! another start of the multi-start ends in a different minimum whose misfit is within that
//! same threshold of the best, every interval is widened to contain it (the data do not exclude
//! it; the note says so). The same holds for the minima found with `nu` held at the grid levels
//! of the multi-start: any point within the threshold lies inside every profile interval.
//!
//! [`solve`]: crate::solve
//! [`FIT_LM_STARTS`]: crate::model::tolerances::FIT_LM_STARTS
//! [`FIT_NULL_RATIO`]: crate::model::tolerances::FIT_NULL_RATIO
//! [`FIT_NULL_COMPONENT`]: crate::model::tolerances::FIT_NULL_COMPONENT
//! [`FIT_MAX_HALF_WIDTH`]: crate::model::tolerances::FIT_MAX_HALF_WIDTH
//! [`FIT_PROFILE_STEP`]: crate::model::tolerances::FIT_PROFILE_STEP
//! [`FIT_PROFILE_STEPS`]: crate::model::tolerances::FIT_PROFILE_STEPS
//! [`FIT_SHOULDER_LEVEL`]: crate::model::tolerances::FIT_SHOULDER_LEVEL

mod analysis;
pub mod checks;
pub mod data;
mod forward;
mod global;
pub mod model;
mod profile;
pub mod report;
mod starts;
pub mod study;
pub mod study_box;
mod study_statistic;

use std::cell::{Cell, RefCell};

use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt, TerminationReason};
use nalgebra_lm::{storage::Owned, DMatrix as LmMatrix, DVector as LmVector, Dyn};

use crate::error::{Error, Result};
use crate::model::tolerances::{
    FIT_FD_STEP, FIT_LM_PATIENCE, FIT_LM_STARTS, FIT_LM_TOL, FIT_MAX_HALF_WIDTH,
    FIT_NULL_COMPONENT, FIT_NULL_RATIO, FIT_PROFILE_BEYOND, FIT_PROFILE_OTHERS,
    FIT_PROFILE_OTHERS_SSR, FIT_PROFILE_STEP, FIT_PROFILE_STEPS, FIT_RTOL, FIT_SCOUT_KEEP,
    FIT_SCOUT_TOP, FIT_SCREEN_RTOL,
};
use crate::solvers::{solve, SolveOptions};
use analysis::analyse;
pub use analysis::{normal_quantile, t_quantile};
pub use data::{Data, Observation, Setup};
pub use model::{prony_times, Model, ModelKind, ParamKind, Parameter};
use profile::moving_coordinates;
pub use profile::profile_misfit;
pub use starts::hertz_modulus;
use starts::{candidates, p3_scale};

/// The modulus (Pa) at which `g_inf` is held when the data (CoR only) cannot determine it; any
/// value gives the same CoRs, and it is never reported as an estimate.
pub const COR_ONLY_REFERENCE_MODULUS: f64 = 1.0e6;

/// A `--fix name=value`: the parameter's name (a JSON parameter key, or `k_0`) and its value (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct Fix {
    /// Parameter name.
    pub name: String,
    /// Value (Pa, Pa s, or 1 for `nu`).
    pub value: f64,
}

impl std::str::FromStr for Fix {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        let bad = || Error::Parse {
            what: "--fix",
            input: crate::error::escape_text(s),
            expected: "name=value (SI), e.g. nu=0.45".into(),
        };
        let (name, value) = s.split_once('=').ok_or_else(bad)?;
        let value: f64 = value.trim().parse().map_err(|_| bad())?;
        Ok(Fix {
            name: name.trim().to_string(),
            value,
        })
    }
}

/// The model with the fixes applied: `k_0` becomes the bulk, the rest fixed parameter values.
pub fn setup_model(
    kind: ModelKind,
    fixes: &[Fix],
    taus: Vec<f64>,
) -> Result<(Model, Vec<Option<f64>>)> {
    let k_0 = fixes.iter().find(|f| f.name == "k_0").map(|f| f.value);
    let model = Model::new(kind, k_0, taus).map_err(|e| match e {
        Error::OutOfRange { field: "k_0", .. } => e.at("--fix k_0"),
        e => e,
    })?;
    let mut fixed = vec![None; model.params.len()];
    for f in fixes.iter().filter(|f| f.name != "k_0") {
        let i = model.index(&f.name).ok_or_else(|| Error::Parse {
            what: "--fix",
            input: crate::error::escape_text(&f.name),
            expected: format!(
                "a parameter of the model{}: one of {}",
                if f.name == "nu" {
                    " (not nu: k_0 is fixed)"
                } else {
                    ""
                },
                model.names()
            ),
        })?;
        if fixed[i].is_some() {
            return Err(Error::Parse {
                what: "--fix",
                input: crate::error::escape_text(&f.name),
                expected: "each parameter fixed once (it is given twice)".into(),
            });
        }
        fixed[i] = Some(model.check_value(i, f.value)?);
    }
    Ok((model, fixed))
}

/// The estimate of one parameter or group.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// Name (the JSON key).
    pub name: String,
    /// SI unit.
    pub unit: &'static str,
    /// The estimate; `None` when the data do not determine it.
    pub value: Option<f64>,
    /// The 95 % interval; `None` when there is none.
    pub ci95: Option<(f64, f64)>,
    /// Standard error in the fit coordinate (`ln x` for moduli and groups, logistic for `nu`).
    pub se: Option<f64>,
    /// Whether the data determine it (see the module docs for the rule).
    pub identifiable: bool,
    /// Whether it was fixed by `--fix`.
    pub fixed: bool,
    /// Why it is not identifiable (empty when it is).
    pub note: String,
}

/// One residual of the fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Residual {
    /// Index of the drop in [`Data::observations`].
    pub observation: usize,
    /// `"cor"` or `"contact_time"`.
    pub quantity: &'static str,
    /// Measured value.
    pub measured: f64,
    /// Fitted model value.
    pub model: f64,
    /// Weighted residual `(model - measured) / sd`.
    pub weighted: f64,
}

/// The result of a fit.
#[derive(Debug, Clone)]
pub struct FitResult {
    /// The model.
    pub model: Model,
    /// The data.
    pub data: Data,
    /// The parameter values at the estimate (a held `g_inf` included; see [`Estimate::value`]
    /// for what is reported).
    pub values: Vec<f64>,
    /// Fixed values (`None`: fitted).
    pub fixed: Vec<Option<f64>>,
    /// Parameter estimates, in model order.
    pub parameters: Vec<Estimate>,
    /// The CoR-determined groups `p2` and `eta_over_g_inf_3_5`.
    pub groups: Vec<Estimate>,
    /// The residuals.
    pub residuals: Vec<Residual>,
    /// `sqrt(SSR / n)` of the weighted residuals.
    pub rms_residual: f64,
    /// Residual degrees of freedom `n - rank`.
    pub dof: usize,
    /// The noise scale `s` (1 when every standard deviation is given).
    pub noise_scale: Option<f64>,
    /// The quantile `q` of the 95 % intervals.
    pub quantile: Option<f64>,
    /// Singular values of the weighted Jacobian, largest first.
    pub singular_values: Vec<f64>,
    /// Covariance of the parameter coordinates (pseudo-inverse on the identified subspace,
    /// scaled by `s^2`; zero rows for fixed parameters), when an interval exists.
    pub covariance: Option<Vec<Vec<f64>>>,
    /// Forward solves done.
    pub solves: usize,
    /// One-line identifiability verdict.
    pub verdict: String,
    /// The `nu` of the estimate when it was fitted but the data do not determine it: every
    /// fitted modulus holds only for it ([`checks::condition_on_nu`]).
    pub conditional_on_nu: Option<f64>,
    /// Chi-square goodness of fit, when every standard deviation was given.
    pub goodness: Option<checks::Goodness>,
    /// Warnings about the fit as a whole (the model does not fit; the CoR rises with `v0`).
    pub warnings: Vec<String>,
}

/// The weighted problem: model, data, which coordinates move.
struct Ctx<'a> {
    model: &'a Model,
    data: &'a Data,
    solves: Cell<usize>,
    /// `p3 / (eta / g_inf^(3/5))` at the data's mean velocity and first sphere.
    p3_scale: f64,
    /// Fixed values (never clamped).
    fixed: Vec<Option<f64>>,
    /// rtol of the forward solves inside Levenberg–Marquardt ([`FIT_RTOL`]; looser while
    /// scouting, [`Ctx::scout`]).
    lm_rtol: Cell<f64>,
    /// Every point whose misfit was evaluated at [`FIT_RTOL`] (by a minimisation, a Jacobian or
    /// a profile), with that misfit: the points met within the 95 % threshold of the best one
    /// must lie inside every interval ([`analysis`]).
    visited: RefCell<Vec<(f64, Vec<f64>)>>,
    /// The starting points screened at a loose rtol, with their misfit (parameter values).
    screened: RefCell<Vec<(f64, Vec<f64>)>>,
}

impl<'a> Ctx<'a> {
    fn new(model: &'a Model, data: &'a Data, fixed: &[Option<f64>]) -> Self {
        Ctx {
            model,
            data,
            solves: Cell::new(0),
            p3_scale: p3_scale(data),
            fixed: fixed.to_vec(),
            lm_rtol: Cell::new(FIT_RTOL),
            visited: RefCell::new(Vec::new()),
            screened: RefCell::new(Vec::new()),
        }
    }

    /// Levenberg–Marquardt from `coords` over the coordinates `moving` (the others held):
    /// the misfit (SSR) and parameter values at the end.
    fn minimise(&self, coords: Vec<f64>, moving: &[usize]) -> Result<(f64, Vec<f64>)> {
        self.minimise_with(coords, moving, None)
    }

    /// [`Ctx::minimise`] with the constraint `tie` kept (when given).
    fn minimise_with(
        &self,
        coords: Vec<f64>,
        moving: &[usize],
        tie: Option<&profile::Tie>,
    ) -> Result<(f64, Vec<f64>)> {
        if moving.is_empty() {
            let values = self.values(&coords);
            return Ok((ssr(&self.residuals(&values, FIT_RTOL)?), values));
        }
        let lm = LevenbergMarquardt::new()
            .with_ftol(FIT_LM_TOL)
            .with_xtol(FIT_LM_TOL)
            .with_gtol(FIT_LM_TOL)
            .with_patience(FIT_LM_PATIENCE);
        let problem = LmProblem {
            ctx: self,
            coords,
            moving: moving.to_vec(),
            failure: RefCell::new(None),
            tie: tie.cloned(),
        };
        let (p, report) = lm.minimize(problem);
        let values = self.values(&p.coords);
        if let Some(e) = p.failure.into_inner()
            && !report.termination.was_successful()
        {
            return Err(e);
        }
        if matches!(
            report.termination,
            TerminationReason::NoResiduals | TerminationReason::WrongDimensions(_)
        ) {
            return Err(Error::Internal(
                "fit: Levenberg-Marquardt stopped on wrong dimensions or no residuals",
            ));
        }
        let s = ssr(&self.residuals(&values, FIT_RTOL)?);
        if !s.is_finite() {
            return Err(Error::NonFinite {
                what: "fit misfit",
                value: s,
            });
        }
        Ok((s, values))
    }

    /// The profile-likelihood interval of coordinate `i` (moving in `moving`) at the level
    /// `best_ssr + threshold`: steps of [`FIT_PROFILE_STEP`] away from the estimate `coords` on
    /// each side, the other coordinates re-minimised at each step, up to [`FIT_PROFILE_STEPS`]
    /// steps; the crossing is interpolated linearly. `None` for a side that does not cross
    /// within the reach (or where a solve fails).
    fn profile(
        &self,
        coords: &[f64],
        best_ssr: f64,
        i: usize,
        moving: &[usize],
        threshold: f64,
    ) -> (Option<f64>, Option<f64>) {
        let rest: Vec<usize> = moving.iter().copied().filter(|&k| k != i).collect();
        let side = |sign: f64| {
            let mut c = coords.to_vec();
            let (mut prev_off, mut prev_ssr) = (0.0, best_ssr);
            for k in 1..=FIT_PROFILE_STEPS {
                let off = sign * k as f64 * FIT_PROFILE_STEP;
                c[i] = coords[i] + off;
                let Ok((s, values)) = self.minimise(c.clone(), &rest) else {
                    return None;
                };
                if s - best_ssr >= threshold {
                    let f = (best_ssr + threshold - prev_ssr) / (s - prev_ssr);
                    return Some(coords[i] + prev_off + f.clamp(0.0, 1.0) * (off - prev_off));
                }
                c = self.coords(&values);
                (prev_off, prev_ssr) = (off, s.max(prev_ssr));
            }
            None
        };
        (side(-1.0), side(1.0))
    }

    /// The parameter values of `coords`, clamped into the model's box ([`Model::clamp`]).
    fn values(&self, coords: &[f64]) -> Vec<f64> {
        let v: Vec<f64> = self
            .model
            .params
            .iter()
            .zip(coords)
            .map(|(p, c)| p.kind.from_coord(*c))
            .collect();
        let mut v = self.model.clamp(&v, self.p3_scale);
        for (x, f) in v.iter_mut().zip(&self.fixed) {
            if let Some(f) = f {
                *x = *f;
            }
        }
        v
    }

    fn coords(&self, values: &[f64]) -> Vec<f64> {
        self.model
            .params
            .iter()
            .zip(values)
            .map(|(p, v)| p.kind.to_coord(*v))
            .collect()
    }
}

/// The least-squares problem handed to the `levenberg-marquardt` crate (its nalgebra 0.34
/// vectors stay inside this type).
struct LmProblem<'a, 'b> {
    ctx: &'b Ctx<'a>,
    coords: Vec<f64>,
    moving: Vec<usize>,
    failure: RefCell<Option<Error>>,
    /// A constraint kept while the coordinates move (a profile point, [`profile`]).
    tie: Option<profile::Tie>,
}

impl LmProblem<'_, '_> {
    fn note<T>(&self, r: Result<T>) -> Option<T> {
        r.map_err(|e| *self.failure.borrow_mut() = Some(e)).ok()
    }
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for LmProblem<'_, '_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &LmVector<f64>) {
        for (k, &j) in self.moving.iter().enumerate() {
            self.coords[j] = x[k];
        }
        if let Some(t) = &self.tie {
            t.apply(&mut self.coords);
        }
    }
    fn params(&self) -> LmVector<f64> {
        LmVector::from_iterator(
            self.moving.len(),
            self.moving.iter().map(|&j| self.coords[j]),
        )
    }
    fn residuals(&self) -> Option<LmVector<f64>> {
        let r = self.note(
            self.ctx
                .residuals(&self.ctx.values(&self.coords), self.ctx.lm_rtol.get()),
        )?;
        Some(LmVector::from_vec(r))
    }
    fn jacobian(&self) -> Option<LmMatrix<f64>> {
        let cols = self.note(
            self.ctx
                .jacobian(&self.coords, &self.moving, self.tie.as_ref()),
        )?;
        let m = cols.first().map_or(0, Vec::len);
        Some(LmMatrix::from_fn(m, cols.len(), |i, j| cols[j][i]))
    }
}

fn ssr(r: &[f64]) -> f64 {
    r.iter().map(|x| x * x).sum()
}

/// Fit `model` to `data` with the parameters `fixed` (`Some(value)`, aligned with
/// `model.params`) held.
///
/// Errors: [`Error::ElasticData`] when every CoR is 1, [`Error::TooFewObservations`] when
/// there are fewer measured values than moving parameters, [`Error::FitFailed`] when no start
/// gives a finite misfit; solver errors otherwise.
pub fn fit(model: &Model, data: &Data, fixed: &[Option<f64>]) -> Result<FitResult> {
    let np = model.params.len();
    check_fixed_slots(model, fixed)?;
    data.validate()?;
    for (i, f) in fixed.iter().enumerate() {
        if let Some(v) = f {
            model.check_value(i, *v)?;
        }
    }
    model.check_fixed_in_box(fixed, p3_scale(data))?;
    data.check_noise()?;
    if data.observations.iter().all(|o| o.cor == 1.0) {
        return Err(Error::ElasticData {
            observations: data.observations.len(),
        });
    }
    let ctx = Ctx::new(model, data, fixed);
    let free: Vec<usize> = (0..np).filter(|&i| fixed[i].is_none()).collect();
    let (hold, moving) = moving_coordinates(model, data, fixed);
    let n = data.residual_count();
    if n < moving.len() {
        return Err(Error::TooFewObservations {
            observations: n,
            parameters: moving.len(),
        });
    }

    // screen the starting points at a loose rtol, keep the best few
    let points = candidates(model, data, fixed, hold);
    let mut screened: Vec<(f64, Vec<f64>)> = ctx
        .residuals_points(&points, FIT_SCREEN_RTOL)
        .into_iter()
        .zip(points)
        .filter_map(|(r, v)| {
            let s = ssr(&r.ok()?);
            s.is_finite().then_some((s, v))
        })
        .collect();
    screened.sort_by(|a, b| a.0.total_cmp(&b.0));
    ctx.screened.borrow_mut().clone_from(&screened);
    // The misfit can have several basins, mostly along nu. With nu free, the best screened
    // points of every nu level are first minimised with nu held at the level (the profile of
    // the misfit along nu at the grid levels), and the full fit starts from the best levels.
    let mut last_error = String::from("no starting point gave a finite misfit");
    let mut starts_from: Vec<Vec<f64>> = Vec::new();
    // every minimum met on the way (with nu held or not): all may widen the intervals
    let mut probes: Vec<(f64, Vec<f64>)> = Vec::new();
    match model.slot(Parameter::Nu).filter(|i| moving.contains(i)) {
        Some(inu) => {
            let held: Vec<usize> = moving.iter().copied().filter(|&k| k != inu).collect();
            let mut levels: Vec<(f64, Vec<f64>)> = Vec::new();
            let mut nus: Vec<f64> = screened.iter().map(|(_, v)| v[inu]).collect();
            nus.sort_by(f64::total_cmp);
            nus.dedup();
            for nu in nus {
                // the best points of the level, and the best scouted basin of the stiffness
                // ratio p2 in it (the Kelvin corner p2 -> 0 attracts the best screened points
                // when nu is near 0.5)
                let level: Vec<&Vec<f64>> = screened
                    .iter()
                    .filter(|(_, v)| v[inu] == nu)
                    .map(|(_, v)| v)
                    .collect();
                let mut from: Vec<Vec<f64>> = level
                    .iter()
                    .take(FIT_LM_STARTS)
                    .map(|v| (*v).clone())
                    .collect();
                from.extend(
                    ctx.scout_basins(&level, &held, 0)
                        .into_iter()
                        .next()
                        .map(|(_, v)| v),
                );
                let best_of_level = from
                    .iter()
                    .filter_map(|v| match ctx.minimise(ctx.coords(v), &held) {
                        Ok(m) => Some(m),
                        Err(e) => {
                            last_error = e.to_string();
                            None
                        }
                    })
                    .min_by(|a, b| a.0.total_cmp(&b.0));
                levels.extend(best_of_level);
            }
            levels.sort_by(|a, b| a.0.total_cmp(&b.0));
            probes.extend(levels.iter().cloned());
            starts_from.extend(levels.into_iter().take(FIT_LM_STARTS + 1).map(|(_, v)| v));
        }
        None => starts_from.extend(screened.iter().take(FIT_LM_STARTS).map(|(_, v)| v.clone())),
    }
    // Global stage: the best basin scouted from every decade of the stiffness ratio `p2` and
    // from the best FIT_SCOUT_TOP screened points starts a full minimisation too, so that a
    // basin away from the best screened points is not missed; so does every other scouted
    // basin within FIT_SCOUT_KEEP thresholds of it, whose minimum may lie within the threshold
    // of the best and then widens the intervals.
    let all: Vec<&Vec<f64>> = screened.iter().map(|(_, v)| v).collect();
    let scouted = ctx.scout_basins(&all, &moving, FIT_SCOUT_TOP);
    if let Some(&(best_scout, _)) = scouted.first() {
        let margin =
            FIT_SCOUT_KEEP * global::provisional_threshold(data, best_scout, n, moving.len());
        starts_from.extend(
            scouted
                .into_iter()
                .filter(|(s, _)| *s - best_scout <= margin)
                .map(|(_, v)| v),
        );
    }
    let mut minima: Vec<(f64, Vec<f64>)> = Vec::new();
    let starts = starts_from.len();
    for v in starts_from {
        match ctx.minimise(ctx.coords(&v), &moving) {
            Ok(m) => minima.push(m),
            Err(e) => last_error = e.to_string(),
        }
    }
    minima.sort_by(|a, b| a.0.total_cmp(&b.0));
    if minima.is_empty() {
        return Err(Error::FitFailed {
            starts,
            last: last_error,
        });
    }
    let best = minima.remove(0);
    probes.extend(minima);
    let mut result = analyse(&ctx, best, &probes, fixed, &free, &moving)?;
    checks::apply(&mut result);
    Ok(result)
}

/// One fixed-value slot per parameter of `model`.
///
/// # Errors
/// [`Error::OutOfRange`] naming the slots otherwise.
fn check_fixed_slots(model: &Model, fixed: &[Option<f64>]) -> Result<()> {
    if fixed.len() != model.params.len() {
        return Err(Error::OutOfRange {
            field: "fit: fixed-value slots",
            value: fixed.len() as f64,
            allowed: "one slot per parameter of the model",
        });
    }
    Ok(())
}

/// The weighted sum of squared residuals of `data` for the parameter `values` (forward solves at
/// [`FIT_RTOL`]).
pub fn misfit(model: &Model, data: &Data, values: &[f64]) -> Result<f64> {
    let ctx = Ctx::new(model, data, &[]);
    Ok(ssr(&ctx.residuals(values, FIT_RTOL)?))
}

impl FitResult {
    /// The estimate called `name` among the parameters and groups.
    pub fn get(&self, name: &str) -> Option<&Estimate> {
        self.parameters
            .iter()
            .chain(&self.groups)
            .find(|e| e.name == name)
    }

    /// Fitted CoR and contact time of `sphere` at `v0` with their standard deviations from the
    /// covariance (delta method; `None` without one). `solves` counts the forward solves.
    pub fn predict(&self, sphere: impl Into<data::Impactor>, v0: f64) -> Result<Prediction> {
        let sphere = sphere.into();
        let opts = SolveOptions {
            rtol: FIT_RTOL,
            ..Default::default()
        };
        let at = |values: &[f64]| -> Result<(f64, f64)> {
            let o = solve(&self.model.impact(sphere, v0, values)?, &opts)?;
            Ok((o.cor, o.contact_time))
        };
        let (cor, contact_time) = at(&self.values)?;
        let mut sd = None;
        if let Some(c) = &self.covariance {
            let coords: Vec<f64> = self
                .model
                .params
                .iter()
                .zip(&self.values)
                .map(|(p, v)| p.kind.to_coord(*v))
                .collect();
            let np = coords.len();
            let mut grad = vec![(0.0, 0.0); np];
            for (i, g) in grad.iter_mut().enumerate() {
                if self.fixed[i].is_some() {
                    continue;
                }
                let vals = |d: f64| {
                    let mut x = coords.clone();
                    x[i] += d;
                    let v: Vec<f64> = self
                        .model
                        .params
                        .iter()
                        .zip(&x)
                        .map(|(p, c)| p.kind.from_coord(*c))
                        .collect();
                    at(&v)
                };
                let (p, m) = (vals(FIT_FD_STEP)?, vals(-FIT_FD_STEP)?);
                *g = (
                    (p.0 - m.0) / (2.0 * FIT_FD_STEP),
                    (p.1 - m.1) / (2.0 * FIT_FD_STEP),
                );
            }
            let quad = |f: &dyn Fn(usize) -> f64| -> f64 {
                (0..np)
                    .map(|i| (0..np).map(|k| f(i) * c[i][k] * f(k)).sum::<f64>())
                    .sum::<f64>()
                    .max(0.0)
                    .sqrt()
            };
            sd = Some((quad(&|i| grad[i].0), quad(&|i| grad[i].1)));
        }
        Ok(Prediction {
            v0,
            cor,
            contact_time,
            sd,
        })
    }
}

/// The fitted model at one velocity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prediction {
    /// Impact velocity (m/s).
    pub v0: f64,
    /// CoR.
    pub cor: f64,
    /// Contact time (s).
    pub contact_time: f64,
    /// Standard deviations of CoR and contact time (s) from the parameter covariance.
    pub sd: Option<(f64, f64)>,
}
