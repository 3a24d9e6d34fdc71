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

/// The verified solve behind [`impact`]: solves at `rtol`, `rtol / FAST_CHECK_RATIO`, ... (at
/// most [`FAST_CHECK_LEVELS`] solves) until two successive CoRs agree to `rtol` relative, and
/// returns the last (tighter) one with that relative difference as its error estimate.
///
/// The difference estimates the error of the looser of the two solves; with the tolerance
/// proportionality measured on the external tables (maximum error 0.81 `rtol` at every `rtol`
/// from 1e-2 to 1e-11) the returned value is about `FAST_CHECK_RATIO` times more accurate than
/// that. The sum of the local defects (the per-step estimates that choose the steps) is no
/// global estimate: it over-estimates the error 66x to several thousand times, and where the
/// step tolerance cannot follow the CoR (below its energy floor) it was seen below the error.
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
    let mut steps = 0u64;
    let mut levels = 0u32;
    let mut prev: Option<f64> = None;
    let mut estimate = f64::INFINITY;
    // the last solve's sum of local defects: the refusal's estimate when no two solves compare
    let mut local = f64::INFINITY;
    let mut last_err: Option<Error> = None;
    let mut prec = rtol;
    // solves at one tolerance repeated after the energy floor was lowered (at most 2)
    let mut floor_solves = 0u32;
    while levels < FAST_CHECK_LEVELS && prec >= FAST_MIN_PREC {
        levels += 1;
        match solve_once(s, prec, history) {
            Ok(mut out) => {
                steps += out.work.steps;
                local = out.cor_error_estimate.unwrap_or(f64::INFINITY);
                if out.cor < s.min_tol_scale && floor_solves < 2 {
                    // the floor was active in this solve: it does not count as a check, nor
                    // as one of the FAST_CHECK_LEVELS tolerances
                    s.min_tol_scale = (0.5 * out.cor).max(f64::MIN_POSITIVE);
                    floor_solves += 1;
                    levels -= 1;
                    prev = None;
                    continue;
                }
                if let Some(p) = prev {
                    estimate = ((out.cor - p) / out.cor).abs();
                    if estimate <= rtol {
                        // the maximum force of the returned solve from its dense output
                        if let Some((t_max, f_max)) = s.peak_node {
                            out.max_force = s.refine_peak(t_max).max(f_max);
                        }
                        out.cor_error_estimate = Some(estimate);
                        out.work.steps = steps;
                        out.work.evaluations = s.evaluations;
                        out.work.levels = levels + floor_solves;
                        return Ok(out);
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
            levels: levels + floor_solves,
        }),
        (false, false, None) => Err(Error::NoConvergence {
            what: "fast: successive solves",
            iterations: u64::from(levels + floor_solves),
        }),
    }
}
