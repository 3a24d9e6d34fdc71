//! Exact exponential kernels: the normalised incomplete-gamma function `Ĵ_ν(x)`.
//!
//! For a Prony term with relaxation time `tau` and a step of length `h`, the hereditary
//! integral of a power forcing is
//!
//! ```text
//! ∫_0^t exp(-(t-s)/tau) d/ds[(s/h)^ν] ds = ν (t/h)^ν Ĵ_ν(t/tau),
//! Ĵ_ν(x) = x^(-ν) e^(-x) ∫_0^x e^u u^(ν-1) du = e^(-x) Σ_{j>=0} x^j / (ν (ν+1) ... (ν+j)),
//! ```
//!
//! Series (positive terms, no cancellation): `Ĵ_ν(x) = e^(-x) Σ_{j>=0} x^j / (j! (ν + j))`
//! (expand `e^u`); asymptotic (`x -> inf`, from `J' + J = x^(ν-1)`):
//! `Ĵ_ν(x) ~ (1/x) Σ_m (-1)^m (ν-1)(ν-2)...(ν-m) / x^m`, exact (terminating) for integer `ν`
//! up to `e^(-x)`; recurrence `Ĵ_(ν+1) = (1 - ν Ĵ_ν) / x` (integration by parts).
//! `Ĵ_ν(0) = 1/ν` (no relaxation), `Ĵ_ν(x) ~ 1/x` for `x -> inf` (a dashpot). This is what makes
//! the solver exact in the kernel for any `h / tau` (an exponential integrator).

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

/// `1/n` for `n < RECIP_LEN` (the series divide by small integers and half-integers).
const RECIP_LEN: usize = 512;
static RECIP: [f64; RECIP_LEN] = {
    let mut r = [0.0; RECIP_LEN];
    let mut n = 1;
    while n < RECIP_LEN {
        r[n] = 1.0 / n as f64;
        n += 1;
    }
    r
};

/// Below this `x` the families use the positive series; above, forward recurrence, whose
/// error grows by at most `Π_m (ν0 + m)/x` (about 10 at `x = 2` for six terms from `ν0 = 3/2`).
const FORWARD_X: f64 = 2.0;

/// Largest `x` for which the positive series is used for non-integer `ν`; beyond it the
/// asymptotic series has error below `e^(-x)`.
const ASYMPTOTIC_X: f64 = 40.0;

/// The `x` from which [`jhat_tol_ex`] uses the asymptotic series at relative tolerance `tol`:
/// its smallest term and the part it omits are about `e^(-x)` relative, so `ln(1/tol) + 4`
/// (measured against 40-digit quadrature for `ν` = 3/2 to 11/2: at most 0.94 `tol` for `tol`
/// from 1e-7 to 1e-15), at most [`ASYMPTOTIC_X`].
fn asymptotic_x(tol: f64) -> f64 {
    (4.0 - tol.ln()).min(ASYMPTOTIC_X)
}

/// `exp(-x)`, flushed to 0 beyond `x = 708` (where `exp(-x)` is below the smallest normal
/// number): multiplies bounded states only, and libm's underflow path is slow.
#[inline]
pub(crate) fn exp_neg(x: f64) -> f64 {
    if x > 708.0 {
        0.0
    } else {
        (-x).exp()
    }
}

/// `Ĵ_ν(x)` for any `ν > 0`, `x >= 0` to double precision ([`jhat_tol_ex`] at 1e-17).
#[cfg(test)]
pub(crate) fn jhat(nu: f64, x: f64) -> f64 {
    jhat_tol(nu, x, 1e-17)
}

/// [`jhat_tol_ex`] with its own `exp(-x)`.
#[cfg(test)]
pub(crate) fn jhat_tol(nu: f64, x: f64, tol: f64) -> f64 {
    jhat_tol_ex(nu, x, tol, exp_neg(x))
}

/// `Ĵ_ν(x)` for any `ν > 0`, `x >= 0` (series or asymptotic expansion), truncated at `tol`
/// relative (`tol >= 1e-17`; the series terms decay factorially, so the first omitted one
/// bounds the error), with `exp(-x)` given (`ex`, as from [`exp_neg`]).
fn jhat_tol_ex(nu: f64, x: f64, tol: f64, ex: f64) -> f64 {
    let tol = tol.max(1e-17);
    // (the logarithm of `asymptotic_x` only where it can matter)
    let x_asym = if x >= ASYMPTOTIC_X {
        ASYMPTOTIC_X
    } else {
        asymptotic_x(tol)
    };
    let two_nu = 2.0 * nu;
    if x < x_asym && two_nu.fract() == 0.0 && two_nu < 64.0 {
        // the same series with 1/j and 1/(ν + j) = 2/(2ν + 2j) from the table (no divisions)
        let two_nu = two_nu as usize;
        let mut t = 1.0; // x^j / j!
        let mut sum = 2.0 * RECIP[two_nu];
        let mut j = 0;
        loop {
            j += 1;
            t *= x * RECIP[j];
            let term = 2.0 * t * RECIP[two_nu + 2 * j];
            sum += term;
            if (term <= tol * sum && j as f64 > x) || j > 200 {
                break;
            }
        }
        ex * sum
    } else if x < x_asym {
        let mut t = 1.0; // x^j / j!
        let mut sum = 1.0 / nu;
        let mut j = 0.0;
        loop {
            j += 1.0;
            t *= x / j;
            let term = t / (nu + j);
            sum += term;
            if (term <= tol * sum && j > x) || j > 400.0 {
                break;
            }
        }
        ex * sum
    } else {
        // divergent: stop at `tol`, or at the smallest term
        let mut term: f64 = 1.0;
        let mut sum = 1.0;
        let inv_x = 1.0 / x;
        for m in 1..80 {
            let next = term * -(nu - m as f64) * inv_x;
            if next.abs() > term.abs() {
                break;
            }
            term = next;
            sum += term;
            if term.abs() <= tol * sum.abs() {
                break;
            }
        }
        sum * inv_x
    }
}

/// `Ĵ_m(x)` for the integers `m = 1..=N-1` into `out[m]` (`out[0]` is unused).
///
/// For `x >= 2` as [`jhat_family_ex`] (`ν0 = 1`); for `x < 2` one series for the highest order, `Ĵ_ν(x) = e^(-x) Σ_j x^j / (j! (ν + j))`,
/// then the backward recurrence `Ĵ_ν = (1 - x Ĵ_(ν+1)) / ν` (stable: errors shrink by `x/ν`).
/// The one-argument form of [`jhat_int_lanes`], which the solver uses; kept as its reference
/// in the tests.
#[cfg(test)]
pub(crate) fn jhat_int<const N: usize>(x: f64, out: &mut [f64; N]) {
    if x >= FORWARD_X || N < 3 {
        let mut tmp = [0.0; N];
        jhat_family(1.0, x, 1e-17, &mut tmp);
        out[0] = 0.0;
        out[1..N].copy_from_slice(&tmp[..N - 1]);
        return;
    }
    let top = N - 1;
    let mut t = 1.0; // x^j / j!
    let mut sum = RECIP[top];
    let mut j = 0;
    loop {
        j += 1;
        t *= x * RECIP[j];
        let term = t * RECIP[top + j];
        sum += term;
        if term <= 1e-17 * sum || j > 60 {
            break;
        }
    }
    let mut v = (-x).exp() * sum;
    out[top] = v;
    for m in (1..top).rev() {
        v = (1.0 - x * v) * RECIP[m];
        out[m] = v;
    }
    out[0] = 0.0;
}

/// `Ĵ_m(x_l)` for the integers `m = 1..=N-1` into `out[l][m]` (`out[l][0]` is unused) for `L`
/// arguments at once, with `exp(-x_l)` in `ex[l]`; the series truncated at `tol` relative.
/// For `x >= 2` the forward recurrence from `Ĵ_1 = (1 - e^(-x)) / x`; below, one series for
/// the highest order, `Ĵ_ν(x) = e^(-x) Σ_j x^j / (j! (ν + j))`, and the backward recurrence
/// `Ĵ_ν = (1 - x Ĵ_(ν+1)) / ν` (stable: errors shrink by `x/ν`). The series of all arguments
/// below 2 run in one loop (until every one has converged), so that their independent
/// dependency chains overlap instead of running one after another: the kernels of a step's
/// nodes are needed together. `N >= 3`.
// (inlined into the callers' loops over the terms: as a call, with its arrays passed through
// memory, it cost 7% more instructions in a solve of the 30-term polymer scene)
#[inline(always)]
pub(crate) fn jhat_int_lanes<const N: usize, const L: usize>(
    xs: &[f64; L],
    tol: f64,
    out: &mut [[f64; N]; L],
    ex: &mut [f64; L],
) {
    debug_assert!(N >= 3);
    let top = N - 1;
    let mut t = [1.0; L]; // x^j / j!
    let mut sum = [RECIP[top]; L];
    let mut xl = [0.0; L];
    let mut any = false;
    for l in 0..L {
        if xs[l] < FORWARD_X {
            xl[l] = xs[l];
            any = true;
        }
    }
    if any {
        let mut j = 0;
        loop {
            j += 1;
            let mut done = true;
            for l in 0..L {
                t[l] *= xl[l] * RECIP[j];
                let term = t[l] * RECIP[top + j];
                sum[l] += term;
                done &= term <= tol * sum[l];
            }
            if done || j > 60 {
                break;
            }
        }
    }
    for l in 0..L {
        let x = xs[l];
        ex[l] = exp_neg(x);
        if x >= FORWARD_X {
            // forward recurrence from Ĵ_1 = (1 - e^(-x)) / x (no cancellation for x >= 2)
            let inv_x = 1.0 / x;
            let mut v = (1.0 - ex[l]) * inv_x;
            out[l][0] = 0.0;
            out[l][1] = v;
            for m in 1..top {
                v = (1.0 - m as f64 * v) * inv_x;
                out[l][m + 1] = v;
            }
            continue;
        }
        let mut v = ex[l] * sum[l];
        out[l][top] = v;
        for m in (1..top).rev() {
            v = (1.0 - x * v) * RECIP[m];
            out[l][m] = v;
        }
        out[l][0] = 0.0;
    }
}

/// [`jhat_family_ex`] with its own `exp(-x)`.
#[cfg(test)]
pub(crate) fn jhat_family<const N: usize>(nu0: f64, x: f64, tol: f64, out: &mut [f64; N]) {
    jhat_family_ex(nu0, x, tol, exp_neg(x), out);
}

/// `Ĵ_(ν0 + m)(x)` for `m = 0..N` into `out[m]` (`ν0` a positive multiple of 1/2, `N` small),
/// the series truncated at `tol` relative (at least 1e-17): forward recurrence from `Ĵ_ν0` for
/// `x >= 2`, otherwise the positive series of the highest order and the backward recurrence.
/// `exp(-x)` is given (`ex`, as from [`exp_neg`]): the kernels of one argument share one
/// exponential (the first step needs two families and `exp(-x)` itself). For `ν0 = 1` and
/// `x >= 2` the base is `Ĵ_1 = (1 - e^(-x)) / x` (no cancellation there).
pub(crate) fn jhat_family_ex<const N: usize>(
    nu0: f64,
    x: f64,
    tol: f64,
    ex: f64,
    out: &mut [f64; N],
) {
    let tol = tol.max(1e-17);
    if x >= FORWARD_X {
        let inv_x = 1.0 / x;
        let mut j = if nu0 == 1.0 {
            (1.0 - ex) * inv_x
        } else {
            // the recurrence multiplies the base's error by up to Π_m (ν0 + m) / x
            let mut amp: f64 = 1.0;
            for m in 0..N.saturating_sub(1) {
                amp = amp.max(amp * (nu0 + m as f64) * inv_x);
            }
            jhat_tol_ex(nu0, x, tol / amp, ex)
        };
        out[0] = j;
        for m in 1..N {
            j = (1.0 - (nu0 + (m - 1) as f64) * j) * inv_x;
            out[m] = j;
        }
        return;
    }
    // the positive series Σ_j x^j/j! / (ν_top + j) for the highest order only (with 2 ν0
    // integer, 1/(ν + j) = 2/(2ν + 2j)), then the backward recurrence Ĵ_ν = (1 - x Ĵ_(ν+1)) / ν
    // (stable: errors shrink by x/ν), as in jhat_int
    let two_nu0 = (2.0 * nu0) as usize;
    let two_top = two_nu0 + 2 * (N - 1);
    let mut t = 1.0;
    let mut sum = 2.0 * RECIP[two_top];
    let mut j = 0;
    loop {
        j += 1;
        t *= x * RECIP[j];
        let term = 2.0 * t * RECIP[two_top + 2 * j];
        sum += term;
        if term <= tol * sum || j > 60 {
            break;
        }
    }
    let mut v = ex * sum;
    out[N - 1] = v;
    for m in (0..N - 1).rev() {
        v = (1.0 - x * v) * 2.0 * RECIP[two_nu0 + 2 * m];
        out[m] = v;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Independent reference: Simpson quadrature of `Ĵ_ν(x) = 2 ∫_0^1 exp(-x (1 - z^2)) z^(2ν-1) dz`
    /// (substitute `u = x z^2` in the definition); smooth for `2ν >= 1`.
    fn reference(nu: f64, x: f64) -> f64 {
        let n = 20_000;
        let f = |z: f64| 2.0 * (-x * (1.0 - z * z)).exp() * z.powf(2.0 * nu - 1.0);
        let h = 1.0 / n as f64;
        let mut s = f(0.0) + f(1.0);
        for i in 1..n {
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * h);
        }
        s * h / 3.0
    }

    #[test]
    fn jhat_matches_quadrature() {
        for &nu in &[0.5, 1.0, 1.5, 2.5, 3.0, 4.5, 6.0] {
            for &x in &[0.0, 1e-3, 0.7, 3.0, 12.0, 39.0, 41.0, 100.0] {
                let r = reference(nu, x);
                let j = jhat(nu, x);
                assert!((j - r).abs() <= 1e-9 * r, "nu={nu} x={x}: {j} vs {r}");
            }
        }
    }

    #[test]
    fn jhat_family_matches_general() {
        for &nu0 in &[1.0, 1.5] {
            for &x in &[
                0.0, 1e-8, 0.05, 0.3, 1.0, 1.9, 2.5, 9.0, 11.5, 13.0, 39.0, 41.0, 1e3, 1e9,
            ] {
                let mut out = [0.0; 6];
                jhat_family(nu0, x, 1e-17, &mut out);
                for (m, &o) in out.iter().enumerate() {
                    let g = jhat(nu0 + m as f64, x);
                    assert!(
                        (o - g).abs() <= 1e-13 * g,
                        "nu={} x={x}: {o} vs {g}",
                        nu0 + m as f64
                    );
                }
            }
        }
    }

    #[test]
    fn truncated_families_within_their_tolerance() {
        // the solver asks for 1e-5 rtol: the series stop earlier and the asymptotic series
        // takes over from ln(1/tol) + 4
        for &tol in &[1e-7, 1e-11, 1e-15] {
            for &nu0 in &[1.0, 1.5] {
                for i in 0..=90 {
                    let x = 0.5 * i as f64;
                    let mut full = [0.0; 6];
                    let mut cut = [0.0; 6];
                    jhat_family(nu0, x, 1e-17, &mut full);
                    jhat_family(nu0, x, tol, &mut cut);
                    for m in 0..6 {
                        let err = (cut[m] - full[m]).abs() / full[m];
                        assert!(
                            err <= 2.0 * tol,
                            "tol={tol} nu={} x={x}: {err:.1e}",
                            nu0 + m as f64
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn jhat_int_lanes_match_single() {
        let xs = [0.0, 1e-9, 0.3, 1.999, 2.0, 7.5, 1e3];
        let mut out = [[0.0; 7]; 7];
        let mut ex = [0.0; 7];
        jhat_int_lanes(&xs, 1e-17, &mut out, &mut ex);
        for (l, &x) in xs.iter().enumerate() {
            let mut one = [0.0; 7];
            jhat_int(x, &mut one);
            assert_eq!(ex[l], exp_neg(x));
            for m in 1..7 {
                // the lanes may add terms below 1e-17 of the sum that the single series skips,
                // and start the forward recurrence from 1 - e^(-x) instead of expm1
                assert!((out[l][m] - one[m]).abs() <= 1e-15 * one[m], "x={x} m={m}");
            }
        }
        // a truncated series (the solver truncates at 1e-5 rtol) is within its truncation
        let mut loose = [[0.0; 7]; 7];
        jhat_int_lanes(&xs, 1e-11, &mut loose, &mut ex);
        for l in 0..xs.len() {
            for m in 1..7 {
                assert!((loose[l][m] - out[l][m]).abs() <= 3e-11 * out[l][m]);
            }
        }
    }

    #[test]
    fn jhat_int_matches_general() {
        for &x in &[0.0, 1e-8, 0.3, 1.0, 2.5, 5.9, 6.1, 20.0, 50.0, 1e6, 1e12] {
            let mut out = [0.0; 8];
            jhat_int(x, &mut out);
            for (m, &o) in out.iter().enumerate().skip(1) {
                let g = jhat(m as f64, x);
                assert!((o - g).abs() <= 1e-13 * g, "m={m} x={x}: {o} vs {g}");
            }
        }
    }
}
