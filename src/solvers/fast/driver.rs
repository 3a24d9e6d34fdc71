//! The verified driver: one solve (compression, then restitution), the successive solves of
//! [`super::impact`] until two agree to `rtol`, and the running force maximum both phases feed.

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

use super::*;

/// Running maximum of the force with a parabola through the three samples around the peak.
#[derive(Default)]
pub(super) struct PeakTracker {
    pub(super) prev: [(f64, f64); 2],
    pub(super) n: usize,
    pub(super) max: f64,
    /// Time of the largest node force.
    pub(super) t_max: f64,
    /// The largest node force.
    pub(super) f_max: f64,
}

impl PeakTracker {
    pub(super) fn push(&mut self, t: f64, f: f64) {
        if self.n >= 2 {
            let (t0, f0) = self.prev[0];
            let (t1, f1) = self.prev[1];
            if f1 >= f0 && f1 >= f && f1 >= self.max && t1 > t0 && t > t1 {
                let d01 = (f1 - f0) / (t1 - t0);
                let d12 = (f - f1) / (t - t1);
                let cc = (d12 - d01) / (t - t0);
                if cc < 0.0 {
                    let bb = d01 + cc * (t1 - t0);
                    self.max = self.max.max(f1 - bb * bb / (4.0 * cc));
                }
            }
        }
        self.max = self.max.max(f);
        if f > self.f_max {
            (self.t_max, self.f_max) = (t, f);
        }
        self.prev = [self.prev[1], (t, f)];
        self.n += 1;
    }
}

/// One solve at the step tolerance `prec` (see the module docs); its `cor_error_estimate` is the
/// sum of the accepted local defect estimates over `e`.
pub(super) fn solve_once<const K: usize>(
    s: &mut Solver<K>,
    prec: f64,
    history: bool,
) -> Result<Outcome> {
    let turn = compress(s, prec, history)?;
    restitute(s, turn, prec)
}

/// One solve at `prec` whose CoR lies above the step tolerance's energy floor: a CoR below
/// [`FAST_MIN_TOL_SCALE`] lowers the floor to `e / 2` and solves again (at most
/// `floor_solves_left` times, counted down). The work of every solve is in the solver's
/// counters; the outcome's `work.steps` counts the steps of all of them.
fn floored<const K: usize>(
    s: &mut Solver<K>,
    prec: f64,
    history: bool,
    floor_solves_left: &mut u32,
) -> Result<Outcome> {
    let mut steps = 0;
    loop {
        let mut out = solve_once(s, prec, history)?;
        steps += out.work.steps;
        if out.cor < s.min_tol_scale && *floor_solves_left > 0 {
            s.min_tol_scale = (0.5 * out.cor).max(f64::MIN_POSITIVE);
            *floor_solves_left -= 1;
            continue;
        }
        out.work.steps = steps;
        return Ok(out);
    }
}

/// The returned solve's finishing: the maximum force from its dense output, the estimate and
/// the work of every solve.
fn finish<const K: usize>(
    s: &mut Solver<K>,
    mut out: Outcome,
    estimate: f64,
    steps: u64,
    levels: u32,
    tight_checks: u32,
) -> Outcome {
    if let (true, Some((t_max, f_max))) = (s.refine_peak, s.peak_node) {
        out.max_force = s.refine_peak(t_max).max(f_max);
    }
    out.cor_error_estimate = Some(estimate);
    out.work.steps = steps;
    out.work.evaluations = s.evaluations;
    out.work.levels = levels;
    out.work.tight_checks = tight_checks;
    out
}

/// One solve at `rtol`, not verified (the energy floor handled as in [`verified`]): the
/// solver's `cor_error_estimate` is the sum of the local defects over `e`, no global estimate.
pub(super) fn unverified<const K: usize>(
    s: &mut Solver<K>,
    rtol: f64,
    history: bool,
) -> Result<Outcome> {
    let mut left = 2;
    let out = floored(s, rtol, history, &mut left)?;
    let (steps, est) = (
        out.work.steps,
        out.cor_error_estimate.unwrap_or(f64::INFINITY),
    );
    Ok(finish(s, out, est, steps, 3 - left, 0))
}

/// The verified solve behind [`impact`] (module docs, "Verified answers").
///
/// **One solve** (for `rtol >= FAST_ONE_SOLVE_MIN_RTOL`): the solve `A` at `rtol` is returned
/// when its calibrated local estimate, the sum of its accepted local defects over `e` divided by
/// [`local_calibration`]`(rtol)`, is at most `rtol` and `e rtol >= FAST_ROUNDOFF_FLOOR`, with
/// that estimate. Otherwise the tight check goes on from `A`.
///
/// **Tight check**: solves at `rtol`, `rtol / FAST_CHECK_RATIO`, ... (at most
/// [`FAST_CHECK_LEVELS`] solves) until two successive CoRs agree to `rtol` relative, and
/// returns the last (tighter) one with that relative difference as its error estimate.
///
/// The difference estimates the error of the looser of the two solves; with the tolerance
/// proportionality measured on the external tables (maximum error 0.81 `rtol` at every `rtol`
/// from 1e-2 to 1e-11) the returned value is about `FAST_CHECK_RATIO` times more accurate than
/// that.
///
/// A CoR below [`FAST_MIN_TOL_SCALE`] (the step tolerance's energy floor, relative to the
/// impact energy) lowers that floor to `e / 2` for the next solves: the error allowed per step
/// then scales with the velocity left instead of staying at the floor, which gave relative CoR
/// errors of `rtol` times `FAST_MIN_TOL_SCALE / e` (25x `rtol` at `e = 6e-6`).
pub(super) fn verified<const K: usize>(
    s: &mut Solver<K>,
    rtol: f64,
    history: bool,
) -> Result<Outcome> {
    // solves at one tolerance repeated after the energy floor was lowered (at most 2)
    let mut floor_left = 2u32;
    if rtol < FAST_ONE_SOLVE_MIN_RTOL {
        return tight(s, rtol, history, None, rtol, 0, floor_left);
    }
    match floored(s, rtol, history, &mut floor_left) {
        Ok(a) => {
            let steps = a.work.steps;
            let est = a.cor_error_estimate.unwrap_or(f64::INFINITY) / local_calibration(rtol);
            if est <= rtol && a.cor * rtol >= FAST_ROUNDOFF_FLOOR {
                let levels = 1 + (2 - floor_left);
                return Ok(finish(s, a, est, steps, levels, 0));
            }
            tight(
                s,
                rtol,
                history,
                Some(a),
                rtol / FAST_CHECK_RATIO,
                1,
                floor_left,
            )
        }
        // long steps of a loose solve can fail to settle: the tighter solves go on
        Err(Error::NoConvergence { .. } | Error::WorkLimit { .. }) => tight(
            s,
            rtol,
            history,
            None,
            rtol / FAST_CHECK_RATIO,
            1,
            floor_left,
        ),
        Err(e) => Err(e),
    }
}

/// The factor by which the sum of the local defects of a solve at `rtol` (over `e`) exceeds
/// its CoR error: `FAST_LOCAL_CALIBRATION rtol^(-FAST_LOCAL_EXPONENT)` (module docs,
/// "Verified answers": the measured ratios and their margin).
pub(super) fn local_calibration(rtol: f64) -> f64 {
    FAST_LOCAL_CALIBRATION * rtol.powf(-FAST_LOCAL_EXPONENT)
}

/// The tight check of [`verified`], from the step tolerance `prec` after `tried` solves,
/// comparing first with the solve `first` (at `rtol`) if there is one; `floor_left` carries the
/// floor solves left.
fn tight<const K: usize>(
    s: &mut Solver<K>,
    rtol: f64,
    history: bool,
    first: Option<Outcome>,
    mut prec: f64,
    mut tried: u32,
    mut floor_left: u32,
) -> Result<Outcome> {
    let mut steps = first.as_ref().map_or(0, |a| a.work.steps);
    let mut levels = tried;
    let mut tight_checks = 0u32;
    let mut prev: Option<f64> = first.as_ref().map(|a| a.cor);
    let mut estimate = f64::INFINITY;
    // the last solve's sum of local defects: the refusal's estimate when no two solves compare
    let mut local = first
        .as_ref()
        .and_then(|a| a.cor_error_estimate)
        .unwrap_or(f64::INFINITY);
    let mut last_err: Option<Error> = None;
    while tried < FAST_CHECK_LEVELS && prec >= FAST_MIN_PREC {
        tried += 1;
        levels += 1;
        if prec < rtol {
            tight_checks += 1;
        }
        let floor_before = floor_left;
        match floored(s, prec, history, &mut floor_left) {
            Ok(out) => {
                steps += out.work.steps;
                local = out.cor_error_estimate.unwrap_or(f64::INFINITY);
                if floor_left < floor_before {
                    // the floor was lowered in this solve: the solve before does not compare
                    prev = None;
                }
                if let Some(p) = prev {
                    estimate = ((out.cor - p) / out.cor).abs();
                    if estimate <= rtol {
                        let floors = 2 - floor_left;
                        return Ok(finish(
                            s,
                            out,
                            estimate,
                            steps,
                            levels + floors,
                            tight_checks,
                        ));
                    }
                }
                prev = Some(out.cor);
            }
            // long steps of a loose solve can fail to settle (seen with CoR about 1e-5, p2
            // below 1e-5): the next, tighter solve goes on
            Err(e @ (Error::NoConvergence { .. } | Error::WorkLimit { .. })) => {
                prev = None;
                last_err = Some(e);
            }
            Err(e) => return Err(e),
        }
        prec /= FAST_CHECK_RATIO;
    }
    let levels = levels + (2 - floor_left);
    match (estimate.is_finite(), local.is_finite(), last_err) {
        (false, false, Some(e)) => Err(e),
        (true, ..) | (false, true, _) => Err(Error::AccuracyNotReached {
            solver: SOLVER_NAME,
            rtol,
            estimate: if estimate.is_finite() {
                estimate
            } else {
                local
            },
            required: rtol,
            levels,
        }),
        (false, false, None) => Err(Error::NoConvergence {
            what: "fast: successive solves",
            iterations: u64::from(levels),
        }),
    }
}
