//! A checked wrapper around `quadrature::integrate` (v0.1.2, double-exponential rule).
//!
//! The raw routine has no convergence flag, silently replaces non-finite integrand values by `0`,
//! takes an absolute tolerance only, and is odd for `a > b` (style notes, habit 8). This wrapper:
//!
//! - rejects any non-finite integrand value ([`Error::NonFinite`]), detected through a flag set
//!   inside the closure;
//! - checks the returned error estimate against the tolerance ([`Error::Quadrature`]);
//! - returns `0` for `a == b` and integrates `-int_b^a` for `a > b`;
//! - splits `[a, b]` at given interior points (kinks, boundary layers), distributing the tolerance
//!   over the pieces;
//! - counts integrand evaluations.

use crate::error::{Error, Result};
use std::cell::Cell;

/// Result of a checked quadrature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quad {
    /// The integral.
    pub value: f64,
    /// Sum of the error estimates of the pieces (absolute).
    pub error_estimate: f64,
    /// Integrand evaluations.
    pub evaluations: u64,
}

/// `int_a^b f(x) dx` to absolute tolerance `tol`, split at the points of `splits` that lie
/// strictly inside `(min(a,b), max(a,b))` (others are ignored).
///
/// Errors: [`Error::OutOfRange`] for non-finite limits or `tol <= 0`, [`Error::NonFinite`] when
/// `f` returns a non-finite value at any node, [`Error::Quadrature`] when a piece's error estimate
/// exceeds its share of `tol`.
///
/// ```
/// # use mdr_impact::math::quad::integrate;
/// // int_0^1 sqrt(x) dx = 2/3 (endpoint singularity: the double-exponential rule copes)
/// let q = integrate("sqrt", |x: f64| x.sqrt(), 0.0, 1.0, &[], 1e-13).unwrap();
/// assert!((q.value - 2.0 / 3.0).abs() < 1e-13);
/// ```
pub fn integrate<F>(
    what: &'static str,
    f: F,
    a: f64,
    b: f64,
    splits: &[f64],
    tol: f64,
) -> Result<Quad>
where
    F: Fn(f64) -> f64,
{
    for (field, v) in [("a", a), ("b", b)] {
        if !v.is_finite() {
            return Err(Error::OutOfRange {
                field,
                value: v,
                allowed: "finite integration limits",
            });
        }
    }
    if !(tol > 0.0 && tol.is_finite()) {
        return Err(Error::OutOfRange {
            field: "tol",
            value: tol,
            allowed: "0 < tol < inf",
        });
    }
    if a == b {
        return Ok(Quad {
            value: 0.0,
            error_estimate: 0.0,
            evaluations: 0,
        });
    }
    if a > b {
        let q = integrate(what, f, b, a, splits, tol)?;
        return Ok(Quad {
            value: -q.value,
            ..q
        });
    }
    let mut pts: Vec<f64> = Vec::with_capacity(splits.len() + 2);
    pts.push(a);
    let mut inner: Vec<f64> = splits
        .iter()
        .copied()
        .filter(|&s| s.is_finite() && s > a && s < b)
        .collect();
    inner.sort_by(|x, y| x.total_cmp(y));
    inner.dedup();
    pts.extend(inner);
    pts.push(b);
    let pieces = pts.len() - 1;
    let share = tol / pieces as f64;
    let bad = Cell::new(None::<(f64, f64)>);
    let count = Cell::new(0u64);
    let mut out = Quad {
        value: 0.0,
        error_estimate: 0.0,
        evaluations: 0,
    };
    for w in pts.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        let g = |x: f64| {
            count.set(count.get() + 1);
            let y = f(x);
            if !y.is_finite() && bad.get().is_none() {
                bad.set(Some((x, y)));
            }
            y
        };
        let o = quadrature::integrate(g, lo, hi, share);
        if let Some((_, y)) = bad.get() {
            return Err(Error::NonFinite { what, value: y });
        }
        if o.error_estimate.is_nan() || o.error_estimate > share || !o.integral.is_finite() {
            return Err(Error::Quadrature {
                what,
                a: lo,
                b: hi,
                estimate: o.error_estimate,
                tolerance: share,
            });
        }
        out.value += o.integral;
        out.error_estimate += o.error_estimate;
    }
    out.evaluations = count.get();
    Ok(out)
}

/// Split points for a kernel `exp(-(t - s)/tau)` integrated over `s` in `[a, t]`: the layer of
/// width `tau` at `s = t` is isolated by points at `t - tau * 4^j` (`j = 0, 1, ...`) inside
/// `(a, t)`. Returns at most `max` points.
pub fn layer_splits(a: f64, t: f64, tau: f64, max: usize) -> Vec<f64> {
    let mut v = Vec::new();
    if tau.is_nan() || tau <= 0.0 || !tau.is_finite() {
        return v;
    }
    let mut w = tau;
    while t - w > a && v.len() < max {
        v.push(t - w);
        w *= 4.0;
    }
    v
}

/// `int_a^b f` by composite 16-point Gauss–Legendre on `panels` equal panels (nodes by Newton
/// on `P_16`, weights `2 / ((1 - x^2) P_16'(x)^2)`): for smooth (analytic) integrands, where it
/// converges to rounding with a handful of panels and needs no error estimate.
///
/// ```
/// # use mdr_impact::math::quad::gauss_legendre;
/// let q = gauss_legendre(|x: f64| x.exp(), 0.0, 1.0, 2);
/// assert!((q - (1f64.exp() - 1.0)).abs() < 1e-15);
/// ```
pub fn gauss_legendre(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    const N: usize = 16;
    let mut nodes = [(0.0, 0.0); N];
    for (i, node) in nodes.iter_mut().enumerate() {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (N as f64 + 0.5)).cos();
        for _ in 0..100 {
            // P_N(x) and P_N'(x) by the three-term recurrence
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=N {
                let kf = k as f64;
                (p0, p1) = (p1, ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf);
            }
            let dp = N as f64 * (x * p1 - p0) / (x * x - 1.0);
            let step = p1 / dp;
            x -= step;
            if step.abs() < 1e-16 {
                *node = (x, 2.0 / ((1.0 - x * x) * dp * dp));
                break;
            }
        }
    }
    let h = (b - a) / panels.max(1) as f64;
    (0..panels.max(1))
        .map(|p| {
            let mid = a + (p as f64 + 0.5) * h;
            nodes
                .iter()
                .map(|&(x, w)| w * f(mid + 0.5 * h * x))
                .sum::<f64>()
                * 0.5
                * h
        })
        .sum()
}
