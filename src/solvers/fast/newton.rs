//! The Newton solve of a collocation step: corrections, and the stops from the last correction
//! or from an estimate of the next one.

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

use super::*;

/// Newton correction of a collocation step: solve `(I + h^2 A J) delta = r`, with `A` the
/// collocation matrix and `J` the force Jacobian at the nodes, in the equivalent form
/// `(A^-1 + h^2 J) delta = A^-1 r` (no matrix product).
pub(super) fn newton_correction(
    a_inv: &[[f64; S]; S],
    jf: &[[f64; S]; S],
    h2: f64,
    r: [f64; S],
    what: &'static str,
) -> Result<[f64; S]> {
    linalg::solve(newton_matrix(a_inv, jf, h2), linalg::mul_vec(a_inv, &r)).ok_or(
        Error::NoConvergence {
            what,
            iterations: 0,
        },
    )
}

/// The matrix `A^-1 + h^2 J` of a step's Newton system.
pub(super) fn newton_matrix(a_inv: &Mat<S>, jf: &Mat<S>, h2: f64) -> Mat<S> {
    let mut jac = *a_inv;
    for (row, jrow) in jac.iter_mut().zip(jf) {
        for (x, j) in row.iter_mut().zip(jrow) {
            *x += h2 * j;
        }
    }
    jac
}

/// Size of the Newton correction that a force remainder `rem_f` (at the nodes) causes:
/// `max |δ|` with `(A^-1 + h^2 J) δ = h^2 rem_f`, the system of [`newton_correction`].
///
/// The bound `h^2 |A| |rem_f|` ignores `(I + h^2 A J)^-1`, which damps the remainder wherever
/// the force is stiff in `d` over the step (`h^2 A J` large). Measured in instrumented solves
/// of the restitution of a strongly dissipative row (CoR 1.6e-3, rtol 1e-6), over steps whose
/// second Newton correction ranged from 0.1 to 30 times the stop level: the bound was 40x to
/// 75x that correction, this estimate within 5% of it. On a compression step of a row with
/// `c_1 = 2500`, `tau_1 = 1e-3`, the glassy-modulus bound used before was about 250x the
/// correction that followed. Infinite if the matrix is singular (no stop).
pub(super) fn remainder_correction(a_inv: &Mat<S>, jf: &Mat<S>, h2: f64, rem_f: &[f64; S]) -> f64 {
    let rhs = std::array::from_fn(|i| h2 * rem_f[i]);
    match linalg::solve(newton_matrix(a_inv, jf, h2), rhs) {
        Some(d) => d.iter().fold(0.0, |acc: f64, x| acc.max(x.abs())),
        None => f64::INFINITY,
    }
}

/// Add a Newton correction; returns `(max |delta|, max |z|)`.
pub(super) fn update(z: &mut [f64; S], delta: &[f64; S]) -> (f64, f64) {
    let mut dmax: f64 = 0.0;
    let mut scale: f64 = 0.0;
    for i in 0..S {
        z[i] += delta[i];
        dmax = dmax.max(delta[i].abs());
        scale = scale.max(z[i].abs());
    }
    (dmax, scale)
}

/// Newton stop after one small correction: the next one is at most about `curv dmax^2`
/// (`curv` from a bound of the second derivative of the forces); stop when
/// [`FAST_QUADRATIC_SAFETY`] times that is below the stop level of [`newton_done`]
/// (saves the confirming iteration).
pub(super) fn quadratic_done(dmax: f64, scale: f64, curv: f64, rtol: f64) -> bool {
    let tol = (FAST_NEWTON_LEVEL * rtol).max(1e-14);
    curv.is_finite() && curv * dmax * dmax * FAST_QUADRATIC_SAFETY <= tol * scale
}

/// Newton stop from an estimate `next` of the next correction (the second-order remainder
/// propagated through one collocation solve): [`FAST_QUADRATIC_SAFETY`] times it below the stop
/// level of [`newton_done`].
pub(super) fn next_correction_done(next: f64, scale: f64, rtol: f64) -> bool {
    let tol = (FAST_NEWTON_LEVEL * rtol).max(1e-14);
    next.is_finite() && next * FAST_QUADRATIC_SAFETY <= tol * scale
}

/// Newton stop: a correction below the stop level ([`FAST_NEWTON_LEVEL`]), or stagnation near
/// rounding level.
pub(super) fn newton_done(dmax: f64, scale: f64, prev: f64, rtol: f64) -> bool {
    let tol = (FAST_NEWTON_LEVEL * rtol).max(1e-14);
    dmax <= tol * scale || (dmax <= 1e-10 * scale && dmax > 0.3 * prev) || scale == 0.0
}
