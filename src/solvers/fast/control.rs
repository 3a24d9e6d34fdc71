//! Error and step-size control: the energy scale of the step tolerance, the step factor after
//! an accepted or rejected step, the steps near the end of contact and after the turn.

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

use super::*;

/// Length of the next restitution step near the end of contact, where the force vanishes
/// like `(t_end - t)^(3/2)`: the defect of a step of length `H` ending at distance `δ_e` from the
/// end grows like `H^(S+1) (δ_e + κ H)^(-7/2)` (the `S`-th derivative of the force there). The
/// model is calibrated on the step just accepted (`ratio`, length `h`, ending at distance
/// `delta`); returns the largest `H <= delta` predicted at half the tolerance, and whether it
/// reaches the end (the last step).
pub(super) fn end_approach(ratio: f64, h: f64, delta: f64) -> (f64, bool) {
    const TARGET: f64 = 0.5;
    let kappa = FAST_END_KAPPA;
    let p = (S + 1) as f64;
    let base = (delta + kappa * h).ln();
    // log of the predicted ratio of a step of length H
    let log_r =
        |hh: f64| ratio.ln() + p * (hh / h).ln() - 3.5 * ((delta - (1.0 - kappa) * hh).ln() - base);
    let goal = TARGET.ln();
    if log_r(delta) <= goal {
        return (delta, true);
    }
    // log_r increases with H: Newton from the right on the convex function
    let mut hh = delta;
    for _ in 0..8 {
        let f = log_r(hh) - goal;
        let df = p / hh + 3.5 * (1.0 - kappa) / (delta - (1.0 - kappa) * hh);
        let next = hh - f / df;
        if !(next > 0.0) {
            hh *= 0.5;
            continue;
        }
        if (next - hh).abs() <= 1e-3 * hh {
            hh = next;
            break;
        }
        hh = next;
    }
    (hh.min(delta), false)
}

/// Model of the layer after the turn in [`turn_layer_step`]: a first restitution step of
/// `x tau_k` misses about `TURN_LAYER_MISS x^10` of the layer's impulse, at most
/// `TURN_LAYER_SATURATION` of it (fitted to the first restitution steps of the external rows at
/// rtol 1e-6: the observed misses rise from about 1e-7 at `x = 1` to 3e-3 at `x = 2.6` and stay
/// near 0.003 to 0.01 beyond; the coefficient is about 8x the fit, to the safe side); the step
/// aims at `TURN_LAYER_TARGET` of its tolerance.
pub(super) const TURN_LAYER_MISS: f64 = 1e-6;

pub(super) const TURN_LAYER_SATURATION: f64 = 0.008;

pub(super) const TURN_LAYER_TARGET: f64 = 0.3;

/// Length of the first restitution step: `h` (the last full compression step), shortened for
/// the layer of width `tau_k / 2` that the Ting factor `exp(-(t - t_1)/tau_k)` leaves after the
/// turn (`t - t_1 ≈ 2 (t - t_m)` there). Its impulse is about `(16/3) |c_k q_k(t_m)| tau_k / 2`,
/// `λ_k` times the velocity tolerance `tol` (the compression's, which the model was fitted
/// with: a third of the restitution's, to the safe side); a term whose layer can fail the step
/// (`λ_k TURN_LAYER_SATURATION > TURN_LAYER_TARGET`) limits the step to `x tau_k` with
/// `λ_k TURN_LAYER_MISS x^10 = TURN_LAYER_TARGET`. Before, the step was found by rejections,
/// about 35 evaluations each: 1.6 per impact with CoR below 0.01 and 1.2 for CoR in
/// `[0.01, 0.1)`, now 0.5 and 0.3 (rtol 1e-6, external rows; 0.2 and 0.04 together with
/// [`FAST_REST_TOL_FACTOR`]).
pub(super) fn turn_layer_step<const K: usize>(
    s: &Solver<K>,
    h: f64,
    q_m: &[f64; K],
    tol: f64,
) -> f64 {
    let mut h = h;
    for k in 0..s.k {
        let lam = K16 * (s.c[k] * q_m[k]).abs() * 0.5 * s.tau[k] / tol;
        if lam * TURN_LAYER_SATURATION > TURN_LAYER_TARGET {
            let x = (TURN_LAYER_TARGET / (TURN_LAYER_MISS * lam)).powf(0.1);
            h = h.min(x * s.tau[k]);
        }
    }
    h
}

/// Step size after a rejected step. The first retry assumes the nominal order (`h^(S+1)`);
/// a second one at the same time uses the order observed between the two failed attempts
/// (boundary layers and the end of contact reduce it), clamped to `[1, S + 1]`.
#[derive(Default)]
pub(super) struct Retry {
    pub(super) last: Option<(f64, f64)>,
}

impl Retry {
    pub(super) fn next(&mut self, h: f64, ratio: f64) -> f64 {
        self.next_order(h, ratio, S as f64 + 1.0)
    }

    pub(super) fn next_order(&mut self, h: f64, ratio: f64, order: f64) -> f64 {
        let nominal = h * step_factor_order(ratio, order);
        let next = match self.last {
            Some((h0, r0)) if h0 > h && r0 > ratio && ratio.is_finite() => {
                let p = ((r0 / ratio).ln() / (h0 / h).ln()).clamp(1.0, S as f64 + 1.0);
                (h * (0.5 / ratio).powf(1.0 / p)).clamp(0.2 * h, nominal)
            }
            _ => nominal,
        };
        self.last = Some((h, ratio));
        next
    }
}

pub(super) fn step_factor(ratio: f64) -> f64 {
    step_factor_order(ratio, S as f64 + 1.0)
}

/// Step-size factor for an error ratio (estimate over tolerance) that grows like `h^order`:
/// `0.9 ratio^(-1/order)` within `[0.2, 2]`.
pub(super) fn step_factor_order(ratio: f64, order: f64) -> f64 {
    if ratio <= 0.0 || !ratio.is_finite() {
        return if ratio <= 0.0 { 3.0 } else { 0.2 };
    }
    (0.9 * ratio.powf(-1.0 / order)).clamp(0.2, 2.0)
}

/// Scale of the step tolerance at a step start: the mechanical energy left, relative to the
/// impact energy, `E = v^2 + (4/5) F d` (kinetic, plus the Hertz energy `(2/5) F d` of the
/// current force and indentation; canonical units `m = v0 = 1`), at least
/// [`FAST_MIN_TOL_SCALE`]. `E = 1` at the start and `e^2` at the end of contact.
/// `tol_scale` in restitution, at least `|v|`: an error of the velocity near the end of
/// contact passes to the rebound velocity unchanged, so it needs to be small relative to `e`
/// (about `|v|` there), not to `e^2` (5000 random groups at rtol 1e-6: 35.9 instead of 37.7
/// steps for `e < 0.01`, 29.8 instead of 32.1 for `0.01 <= e < 0.05`, same maximum error).
pub(super) fn rest_tol_scale(v: f64, f: f64, d: f64, floor: f64) -> f64 {
    tol_scale(v, f, d, floor).max(v.abs().min(1.0))
}

/// The velocity scale of [`rest_tol_scale`] without its floor [`FAST_MIN_TOL_SCALE`]
/// (`max(E, |v|)`, at most 1): the Newton and Ting-root floors of a restitution step follow the
/// velocity itself, also where the CoR lies below that floor.
pub(super) fn rest_velocity_scale(v: f64, f: f64, d: f64) -> f64 {
    let e = (v * v + 0.8 * f * d).max(v.abs());
    if e.is_nan() {
        return 1.0;
    }
    e.min(1.0)
}

pub(super) fn tol_scale(v: f64, f: f64, d: f64, floor: f64) -> f64 {
    let e = v * v + 0.8 * f * d;
    if e.is_nan() {
        return 1.0; // a non-finite state is reported by the caller
    }
    e.clamp(floor, 1.0)
}
