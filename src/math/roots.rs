//! A safeguarded Newton iteration on a bracket (Newton steps that leave the bracket or shrink it
//! too slowly are replaced by bisection), as in `rtsafe` of Numerical Recipes.

use crate::error::{Error, Result};

/// Root of `f` in `[lo, hi]` where `f(lo)` and `f(hi)` have opposite signs (or one is zero).
///
/// `f` returns `(value, derivative)`; the derivative may be `0` or inexact (only the step is
/// affected). Stops when the bracket or the Newton step is below `xtol`, or `f = 0`.
/// Bounded by [`super::ROOT_MAX_ITER`] iterations ([`Error::NoConvergence`] beyond);
/// [`Error::OutOfRange`] when the bracket does not bracket.
pub fn newton_bracketed<F>(
    what: &'static str,
    mut f: F,
    lo: f64,
    hi: f64,
    x0: Option<f64>,
    xtol: f64,
) -> Result<f64>
where
    F: FnMut(f64) -> Result<(f64, f64)>,
{
    let (flo, _) = f(lo)?;
    let (fhi, _) = f(hi)?;
    newton_bracketed_with(what, f, (lo, flo), (hi, fhi), x0, xtol)
}

/// As [`newton_bracketed`] with the values at the bracket ends already known:
/// `(lo, f(lo))`, `(hi, f(hi))`.
pub fn newton_bracketed_with<F>(
    what: &'static str,
    mut f: F,
    (lo, flo): (f64, f64),
    (hi, fhi): (f64, f64),
    x0: Option<f64>,
    xtol: f64,
) -> Result<f64>
where
    F: FnMut(f64) -> Result<(f64, f64)>,
{
    if flo == 0.0 {
        return Ok(lo);
    }
    if fhi == 0.0 {
        return Ok(hi);
    }
    if flo.signum() == fhi.signum() {
        return Err(Error::OutOfRange {
            field: what,
            value: flo,
            allowed: "a bracket with a sign change (root finder)",
        });
    }
    // orient so that f(a) < 0 < f(b)
    let (mut a, mut b) = if flo < 0.0 { (lo, hi) } else { (hi, lo) };
    let mut x = match x0 {
        Some(x) if x > lo.min(hi) && x < lo.max(hi) => x,
        _ => 0.5 * (lo + hi),
    };
    let mut dx_old = (hi - lo).abs();
    let mut dx = dx_old;
    let (mut fx, mut dfx) = f(x)?;
    for _ in 0..super::ROOT_MAX_ITER {
        if fx == 0.0 {
            return Ok(x);
        }
        if fx < 0.0 {
            a = x;
        } else {
            b = x;
        }
        let newton_ok = dfx != 0.0 && dfx.is_finite() && {
            let xn = x - fx / dfx;
            (xn - a) * (xn - b) < 0.0 && (2.0 * fx).abs() <= (dx_old * dfx).abs()
        };
        dx_old = dx;
        if newton_ok {
            dx = fx / dfx;
            x -= dx;
        } else {
            dx = 0.5 * (b - a);
            x = a + dx;
        }
        let floor = xtol.max(4.0 * f64::EPSILON * a.abs().max(b.abs()));
        if dx.abs() <= floor || (b - a).abs() <= floor {
            return Ok(x);
        }
        let r = f(x)?;
        fx = r.0;
        dfx = r.1;
        if !fx.is_finite() {
            return Err(Error::NonFinite { what, value: fx });
        }
    }
    Err(Error::NoConvergence {
        what,
        iterations: super::ROOT_MAX_ITER,
    })
}
