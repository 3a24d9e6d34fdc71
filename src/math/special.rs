//! Special functions for the closed forms: Dawson's integral, `x - D(x)`, the Gauss
//! hypergeometric series for `|x| <= 1/2`, and `exp(-z(1-u))`-moment integrals used by the
//! exponential collocation of [`crate::solvers::theory::reference`].

use crate::error::{Error, Result};

/// Dawson's integral `D(x) = exp(-x^2) int_0^x exp(y^2) dy` (odd in `x`).
///
/// For `|x| < 6` the positive-term series `D(x) = exp(-x^2) sum_n x^(2n+1) / (n! (2n+1))` (no
/// cancellation; relative error a few ulps); for `|x| >= 6` the asymptotic series
/// `D(x) ~ (1/(2x)) sum_n (2n-1)!! / (2x^2)^n`, truncated at its smallest term (`< 1e-16`
/// relative at `x = 6`).
///
/// ```
/// # use mdr_impact::math::special::dawson;
/// // mpmath: sqrt(pi)/2 exp(-1) erfi(1) = 0.53807950691276841914
/// assert!((dawson(1.0) - 0.538_079_506_912_768_4).abs() < 2e-16);
/// ```
pub fn dawson(x: f64) -> f64 {
    if x < 0.0 {
        return -dawson(-x);
    }
    if x.is_nan() {
        return f64::NAN;
    }
    let x2 = x * x;
    if x < 6.0 {
        // term_n = x^(2n+1)/n!; sum term_n / (2n+1)
        let mut term = x;
        let mut sum = x;
        let mut n = 0.0;
        loop {
            n += 1.0;
            term *= x2 / n;
            let add = term / (2.0 * n + 1.0);
            sum += add;
            if add < 1e-17 * sum || n > 400.0 {
                break;
            }
        }
        sum * (-x2).exp()
    } else {
        let inv = 1.0 / (2.0 * x2);
        let mut term = 1.0;
        let mut sum = 1.0;
        let mut n = 0.0;
        loop {
            n += 1.0;
            let next = term * (2.0 * n - 1.0) * inv;
            if next >= term || next < 1e-18 || n > 200.0 {
                break;
            }
            term = next;
            sum += term;
        }
        sum / (2.0 * x)
    }
}

/// `J(x) = x - D(x)` for `x >= 0`, without cancellation for small `x`:
/// `J(x) = sum_{n>=1} (-1)^(n+1) 2^n x^(2n+1) / (2n+1)!!  ~ 2 x^3 / 3`.
///
/// It gives `int_0^t exp(-(t-s)/tau) sqrt(s) ds = tau^(3/2) J(sqrt(t/tau))`
/// (see [`crate::solvers::theory::viscoelastic::triangle_closed_form`]).
pub fn x_minus_dawson(x: f64) -> f64 {
    if x < 1.0 {
        let x2 = x * x;
        let mut term = x; // 2^n x^(2n+1) / (2n+1)!! at n = 0
        let mut sum = 0.0;
        let mut n = 0.0;
        loop {
            n += 1.0;
            term *= -2.0 * x2 / (2.0 * n + 1.0);
            sum -= term;
            if term.abs() < 1e-18 * sum.abs() || n > 100.0 {
                break;
            }
        }
        sum
    } else {
        x - dawson(x)
    }
}

/// Gauss hypergeometric series `2F1(a, b; c; x)` for `|x| <= 0.6` (terms decrease at least like
/// `0.6^n` eventually). Errors for `|x| > 0.6` or when 400 terms do not converge.
pub fn hyp2f1_series(a: f64, b: f64, c: f64, x: f64) -> Result<f64> {
    if x.is_nan() || x.abs() > 0.6 {
        return Err(Error::OutOfRange {
            field: "x",
            value: x,
            allowed: "|x| <= 0.6 for the 2F1 series",
        });
    }
    let mut term = 1.0;
    let mut sum = 1.0;
    for n in 0..400 {
        let n = n as f64;
        term *= (a + n) * (b + n) / ((c + n) * (n + 1.0)) * x;
        sum += term;
        if term.abs() <= 1e-17 * sum.abs() {
            return Ok(sum);
        }
    }
    Err(Error::NoConvergence {
        what: "2F1 series",
        iterations: 400,
    })
}

/// Moments `e_m(z) = int_0^1 exp(-z (1-u)) u^m du`, `m = 0..out.len()`, for `z >= 0`.
///
/// For `z <= max(8, len)`: positive series `e_m = exp(-z) sum_n z^n / (n! (m+n+1))` (no
/// cancellation). Beyond: forward recurrence `e_0 = (1 - exp(-z))/z`, `e_m = (1 - m e_(m-1))/z`,
/// whose error amplification `m/z` is then below 1.
pub fn exp_moments(z: f64, out: &mut [f64]) {
    if out.is_empty() {
        return;
    }
    if z <= (out.len() as f64).max(8.0) {
        let mut t = 1.0; // z^n / n!
        for o in out.iter_mut() {
            *o = 0.0;
        }
        let mut n = 0usize;
        loop {
            let mut maxadd = 0.0f64;
            for (m, o) in out.iter_mut().enumerate() {
                let add = t / (m + n + 1) as f64;
                *o += add;
                maxadd = maxadd.max(add / *o);
            }
            n += 1;
            t *= z / n as f64;
            let last = out[out.len() - 1];
            if (maxadd < 1e-17 && n as f64 > z && t < 1e-17 * last) || t == 0.0 || n > 400 {
                break;
            }
        }
        let e = (-z).exp();
        for o in out.iter_mut() {
            *o *= e;
        }
    } else {
        out[0] = -(-z).exp_m1() / z;
        for m in 1..out.len() {
            out[m] = (1.0 - m as f64 * out[m - 1]) / z;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[allow(clippy::needless_range_loop)]
    fn moments_agree_across_the_switch() {
        let mut a = [0.0; 8];
        let mut b = [0.0; 8];
        exp_moments(8.0, &mut a);
        // forward recurrence at the same z
        b[0] = -(-8.0f64).exp_m1() / 8.0;
        for m in 1..8 {
            b[m] = (1.0 - m as f64 * b[m - 1]) / 8.0;
        }
        for m in 0..8 {
            assert!(
                (a[m] - b[m]).abs() < 1e-15 * a[m],
                "m={m} {} {}",
                a[m],
                b[m]
            );
        }
        // z = 0: e_m = 1/(m+1)
        exp_moments(0.0, &mut a);
        for m in 0..8 {
            assert!((a[m] - 1.0 / (m + 1) as f64).abs() < 1e-16);
        }
    }
}
