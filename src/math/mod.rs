//! Numerical building blocks below the physics: bracketed root finding, special functions and a
//! checked adaptive quadrature. Nothing here knows a material or a solver.

pub mod quad;
pub mod roots;
pub mod special;

/// Iteration cap of every root finder of [`roots`].
pub const ROOT_MAX_ITER: u64 = 200;

/// `n` evenly spaced values from `min` to `max`, both ends included exactly (`[min]` when
/// `n == 1`).
pub fn linspace(min: f64, max: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            if i + 1 == n && n > 1 {
                max
            } else if n == 1 {
                min
            } else {
                min + (max - min) * i as f64 / (n - 1) as f64
            }
        })
        .collect()
}

/// `n` log-spaced values from `lo` to `hi` (both positive), `exp(ln lo + ln(hi/lo) i/(n-1))`;
/// the ends to rounding (not pinned); the geometric mean `sqrt(lo hi)` when `n == 1`.
pub fn logspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            if n == 1 {
                (lo * hi).sqrt()
            } else {
                (lo.ln() + (hi / lo).ln() * i as f64 / (n - 1) as f64).exp()
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{linspace, logspace};

    #[test]
    fn spaced_values_reach_their_ends() {
        let v = linspace(-20.0, 80.0, 21);
        assert_eq!((v.len(), v[0], v[10], v[20]), (21, -20.0, 30.0, 80.0));
        let w = logspace(0.1, 10.0, 3);
        // the logarithmic grid reaches its ends to rounding, not exactly
        for (got, want) in w.iter().zip([0.1, 1.0, 10.0]) {
            assert!(
                (got / want - 1.0).abs() < 4.0 * f64::EPSILON,
                "{got} vs {want}"
            );
        }
        assert_eq!(linspace(2.0, 3.0, 1), vec![2.0]);
        assert_eq!(logspace(1.0, 4.0, 1), vec![2.0]);
    }
}
