//! Prony series from storage and loss moduli: non-negative least squares (Lawson–Hanson) on the
//! relative errors of `G'` and `G''` with relaxation times spread over the reduced-frequency
//! window.
//!
//! ```text
//! G'(omega)  = g_inf + sum_i g_i (omega tau_i)^2 / (1 + (omega tau_i)^2)
//! G''(omega) =         sum_i g_i  omega tau_i    / (1 + (omega tau_i)^2)
//! ```
//!
//! (Ferry, *Viscoelastic Properties of Polymers*, 3rd ed., 1980, Eq. 3-33/3-34 with a discrete
//! spectrum.) The times are `tau_i = 1 / omega` log-spaced over the window extended by
//! [`WINDOW_EXTENSION`] decades each side; the moduli `g_inf, g_i >= 0` minimise
//! `sum ((G'_fit - G')/G')^2 + ((G''_fit - G'')/G'')^2`, a linear problem with sign
//! constraints, solved exactly by [`nnls`].

use nalgebra::{DMatrix, DVector};

use crate::error::{Error, Result};

/// Decades by which the window of relaxation times extends beyond `1 / omega` of the data on
/// each side.
pub const WINDOW_EXTENSION: f64 = 0.5;

/// Relaxation times per decade of the default (`--terms auto`) fit.
pub const TERMS_PER_DECADE: f64 = 3.0;

/// Terms whose modulus is below this fraction of the glassy modulus are dropped (they carry
/// nothing the data can see) and the rest refitted.
pub const NEGLIGIBLE_TERM: f64 = 1e-9;

/// Non-negative least squares, `min ||A x - b||_2` subject to `x >= 0`, by the active-set
/// method of Lawson & Hanson (*Solving Least Squares Problems*, 1974, ch. 23, algorithm NNLS).
///
/// Columns are scaled to unit norm internally. The result satisfies the Karush–Kuhn–Tucker
/// conditions to rounding: `x >= 0`, `w = A^T (b - A x) <= tol` and `w_j = 0` where `x_j > 0`.
/// Fails with [`Error::NoConvergence`] after `3 n` outer iterations (never seen in practice)
/// and [`Error::NonFinite`] on non-finite input.
///
/// ```
/// # use mdr_impact::apps::dma::prony_fit::nnls;
/// # use nalgebra::{DMatrix, DVector};
/// // unconstrained least squares gives x = (2, -1); with x >= 0 the answer is (1.5, 0)
/// let a = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, 1.0, 1.0, 0.0, 1.0]);
/// let b = DVector::from_vec(vec![2.0, 1.0, -1.0]);
/// let x = nnls(&a, &b).unwrap();
/// assert!((x[0] - 1.5).abs() < 1e-12 && x[1] == 0.0);
/// ```
pub fn nnls(a: &DMatrix<f64>, b: &DVector<f64>) -> Result<DVector<f64>> {
    let (m, n) = a.shape();
    if a.iter().chain(b.iter()).any(|v| !v.is_finite()) {
        return Err(Error::NonFinite {
            what: "nnls input",
            value: f64::NAN,
        });
    }
    let norms: Vec<f64> = (0..n)
        .map(|j| {
            let s = a.column(j).norm();
            if s > 0.0 {
                s
            } else {
                1.0
            }
        })
        .collect();
    let mut s = a.clone();
    for (j, &nj) in norms.iter().enumerate() {
        s.column_mut(j).scale_mut(1.0 / nj);
    }
    let tol = 10.0 * f64::EPSILON * (m.max(n) as f64) * b.norm().max(1e-300);
    let mut x = DVector::<f64>::zeros(n);
    let mut passive = vec![false; n];
    let solve_passive = |passive: &[bool]| -> DVector<f64> {
        let idx: Vec<usize> = (0..n).filter(|&j| passive[j]).collect();
        let mut z = DVector::<f64>::zeros(n);
        if idx.is_empty() {
            return z;
        }
        let sub = s.select_columns(idx.iter());
        let sol = sub
            .svd(true, true)
            .solve(b, 1e-14)
            .unwrap_or_else(|_| DVector::zeros(idx.len()));
        for (k, &j) in idx.iter().enumerate() {
            z[j] = sol[k];
        }
        z
    };
    let max_outer = 3 * n.max(1) + 10;
    let mut outer = 0;
    loop {
        let w = s.tr_mul(&(b - &s * &x));
        let next = (0..n)
            .filter(|&j| !passive[j] && w[j] > tol)
            .max_by(|&i, &j| w[i].total_cmp(&w[j]));
        let Some(j) = next else { break };
        outer += 1;
        if outer > max_outer {
            return Err(Error::NoConvergence {
                what: "nnls (Lawson-Hanson)",
                iterations: max_outer as u64,
            });
        }
        passive[j] = true;
        let mut z = solve_passive(&passive);
        if z[j] <= 0.0 {
            // the new variable does not improve (rounding): stop rather than cycle
            passive[j] = false;
            break;
        }
        let mut inner = 0;
        while (0..n).any(|k| passive[k] && z[k] <= 0.0) {
            inner += 1;
            if inner > n + 1 {
                break;
            }
            let alpha = (0..n)
                .filter(|&k| passive[k] && z[k] <= 0.0)
                .map(|k| x[k] / (x[k] - z[k]))
                .fold(f64::INFINITY, f64::min);
            x += (&z - &x) * alpha;
            for k in 0..n {
                if passive[k] && x[k] <= 1e-300 {
                    passive[k] = false;
                    x[k] = 0.0;
                }
            }
            z = solve_passive(&passive);
        }
        x = z;
        for k in 0..n {
            if !passive[k] || x[k] < 0.0 {
                x[k] = 0.0;
            }
        }
    }
    for (j, &nj) in norms.iter().enumerate() {
        x[j] /= nj;
    }
    Ok(x)
}

/// A Prony series in shear: `g_inf` (Pa, may be 0) and the terms `(g_i` (Pa), `tau_i` (s)`)`,
/// sorted by `tau_i`, all moduli positive.
#[derive(Debug, Clone, PartialEq)]
pub struct PronySeries {
    /// Relaxed modulus (Pa), `>= 0`.
    pub g_inf: f64,
    /// `(g_i, tau_i)`, by increasing `tau_i`.
    pub terms: Vec<(f64, f64)>,
}

impl PronySeries {
    /// `G'(omega)` (Pa) at `omega` (rad/s).
    pub fn storage(&self, omega: f64) -> f64 {
        self.g_inf
            + self
                .terms
                .iter()
                .map(|&(g, t)| g * maxwell(omega * t).0)
                .sum::<f64>()
    }

    /// `G''(omega)` (Pa) at `omega` (rad/s).
    pub fn loss(&self, omega: f64) -> f64 {
        self.terms
            .iter()
            .map(|&(g, t)| g * maxwell(omega * t).1)
            .sum()
    }

    /// Glassy modulus `g_inf + sum g_i` (Pa).
    pub fn glassy(&self) -> f64 {
        self.g_inf + self.terms.iter().map(|&(g, _)| g).sum::<f64>()
    }

    /// The series with every time multiplied by `a` (the material at a temperature with shift
    /// factor `a_T = a`).
    pub fn shifted(&self, a: f64) -> PronySeries {
        PronySeries {
            g_inf: self.g_inf,
            terms: self.terms.iter().map(|&(g, t)| (g, t * a)).collect(),
        }
    }

    /// Root-mean-square relative error of `G'` and `G''` against the data `(omega, G', G'')`.
    pub fn rms_rel_error(&self, data: &[(f64, f64, f64)]) -> f64 {
        let ss: f64 = data
            .iter()
            .map(|&(w, s, l)| {
                (self.storage(w) / s - 1.0).powi(2) + (self.loss(w) / l - 1.0).powi(2)
            })
            .sum();
        (ss / (2 * data.len()).max(1) as f64).sqrt()
    }
}

/// `count` log-spaced times from `t0` to `t1` (s).
pub fn log_times(t0: f64, t1: f64, count: usize) -> Vec<f64> {
    if count <= 1 {
        return vec![(t0 * t1).sqrt()];
    }
    let (l0, l1) = (t0.ln(), t1.ln());
    (0..count)
        .map(|k| (l0 + (l1 - l0) * k as f64 / (count - 1) as f64).exp())
        .collect()
}

/// The relaxation times of the default fit for reduced frequencies in `[w0, w1]` (rad/s):
/// `1 / omega` over the window extended by [`WINDOW_EXTENSION`] decades each side,
/// [`TERMS_PER_DECADE`] per decade (both ends included).
pub fn default_times(w0: f64, w1: f64) -> Vec<f64> {
    let ext = 10f64.powf(WINDOW_EXTENSION);
    let (t0, t1) = (1.0 / (w1 * ext), ext / w0);
    let decades = (t1 / t0).log10();
    let count = (decades * TERMS_PER_DECADE).ceil() as usize + 1;
    log_times(t0, t1, count)
}

/// NNLS fit of `g_inf` and the moduli of the given `times` to data `(omega, G', G'')` (rad/s,
/// Pa, Pa), on relative errors; terms with a zero or negligible modulus
/// ([`NEGLIGIBLE_TERM`]) are dropped and the rest refitted.
pub fn fit_times(data: &[(f64, f64, f64)], times: &[f64]) -> Result<PronySeries> {
    let mut times = times.to_vec();
    loop {
        let series = fit_once(data, &times)?;
        let glassy = series.glassy();
        let keep: Vec<f64> = series
            .terms
            .iter()
            .filter(|&&(g, _)| g > NEGLIGIBLE_TERM * glassy)
            .map(|&(_, t)| t)
            .collect();
        if keep.len() == series.terms.len() {
            return Ok(series);
        }
        times = keep;
    }
}

/// `(u^2 / (1 + u^2), u / (1 + u^2))` for `u = omega tau >= 0`, in forms that neither overflow
/// nor lose the small end (any `u` from 0 to `inf`).
fn maxwell(u: f64) -> (f64, f64) {
    if u <= 1.0 {
        let d = 1.0 + u * u;
        (u * u / d, u / d)
    } else {
        let v = 1.0 / u;
        (1.0 / (1.0 + v * v), v / (1.0 + v * v))
    }
}

/// The fit in units of the data's scale (the geometric mean of every `G'` and `G''`), so that
/// it is the same for moduli in Pa, GPa or any other unit: the matrix entries are `O(1)`
/// whatever the magnitude of the moduli (no squares under- or overflow in [`nnls`]).
fn fit_once(data: &[(f64, f64, f64)], times: &[f64]) -> Result<PronySeries> {
    let m = 2 * data.len();
    let n = times.len() + 1;
    let log_scale = data.iter().map(|&(_, s, l)| s.ln() + l.ln()).sum::<f64>() / m.max(1) as f64;
    let scale = log_scale.exp();
    let mut a = DMatrix::<f64>::zeros(m, n);
    let b = DVector::<f64>::from_element(m, 1.0);
    for (r, &(w, s, l)) in data.iter().enumerate() {
        let (s, l) = (s / scale, l / scale);
        a[(2 * r, 0)] = 1.0 / s;
        for (i, &t) in times.iter().enumerate() {
            let (fs, fl) = maxwell(w * t);
            a[(2 * r, i + 1)] = fs / s;
            a[(2 * r + 1, i + 1)] = fl / l;
        }
    }
    let x = nnls(&a, &b)?;
    let mut terms: Vec<(f64, f64)> = times
        .iter()
        .enumerate()
        .filter(|&(i, _)| x[i + 1] > 0.0)
        .map(|(i, &t)| (x[i + 1] * scale, t))
        .collect();
    terms.sort_by(|p, q| p.1.total_cmp(&q.1));
    Ok(PronySeries {
        g_inf: x[0] * scale,
        terms,
    })
}

/// The Prony fit of `prony`: the default times over the window of `data`, then, with a cap of
/// `max_terms`, the best (lowest rms relative error) of the capped fits: `1, 2, ...,
/// max_terms` log-spaced times over the same extended window, and the uncapped fit with its
/// smallest term dropped and the rest refitted until at most `max_terms` remain.
pub fn fit_prony(data: &[(f64, f64, f64)], max_terms: Option<usize>) -> Result<PronySeries> {
    let (w0, w1) = data
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &(w, _, _)| {
            (a.min(w), b.max(w))
        });
    let times = default_times(w0, w1);
    let full = fit_times(data, &times)?;
    let Some(cap) = max_terms else {
        return Ok(full);
    };
    if full.terms.len() <= cap {
        return Ok(full);
    }
    let (t0, t1) = (times[0], times[times.len() - 1]);
    // every count up to the cap, so that a larger cap never fits worse than a smaller one
    let mut candidates = (1..=cap)
        .map(|k| fit_times(data, &log_times(t0, t1, k)))
        .collect::<Result<Vec<_>>>()?;
    let mut dropped = full;
    while dropped.terms.len() > cap {
        let k = dropped
            .terms
            .iter()
            .enumerate()
            .min_by(|p, q| p.1 .0.total_cmp(&q.1 .0))
            .map(|(k, _)| k)
            .unwrap_or(0);
        let mut ts: Vec<f64> = dropped.terms.iter().map(|&(_, t)| t).collect();
        ts.remove(k);
        dropped = fit_times(data, &ts)?;
    }
    candidates.push(dropped);
    // the first of the lowest rms (fewer log-spaced times, then those, before the dropped fit)
    let rms: Vec<f64> = candidates.iter().map(|c| c.rms_rel_error(data)).collect();
    let best = (0..rms.len())
        .min_by(|&i, &j| rms[i].total_cmp(&rms[j]))
        .unwrap_or(0);
    Ok(candidates.swap_remove(best))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::SplitMix64;

    fn kkt(a: &DMatrix<f64>, b: &DVector<f64>, x: &DVector<f64>) {
        let w = a.tr_mul(&(b - a * x));
        let scale = a.norm() * b.norm();
        for j in 0..x.len() {
            assert!(x[j] >= 0.0);
            assert!(w[j] <= 1e-9 * scale, "w[{j}] = {}", w[j]);
            if x[j] > 0.0 {
                assert!(w[j].abs() <= 1e-9 * scale, "w[{j}] = {} at x > 0", w[j]);
            }
        }
    }

    #[test]
    fn nnls_satisfies_kkt_on_random_problems() {
        let mut rng = SplitMix64::new(7);
        for case in 0..200 {
            let m = 3 + (rng.next_u64() % 12) as usize;
            let n = 1 + (rng.next_u64() % 10) as usize;
            let a = DMatrix::from_fn(m, n, |_, _| rng.normal());
            let b = DVector::from_fn(m, |_, _| rng.normal());
            let x = nnls(&a, &b).unwrap();
            kkt(&a, &b, &x);
            let _ = case;
        }
    }

    #[test]
    fn nnls_recovers_a_nonnegative_exact_solution() {
        let mut rng = SplitMix64::new(3);
        let a = DMatrix::from_fn(20, 6, |_, _| rng.uniform());
        let truth = DVector::from_vec(vec![1.0, 0.0, 2.5, 0.0, 0.3, 4.0]);
        let b = &a * &truth;
        let x = nnls(&a, &b).unwrap();
        assert!((x - truth).norm() < 1e-10);
    }

    #[test]
    fn prony_fit_recovers_a_spectrum_on_its_grid() {
        // seven times of the default grid of the data's window, one per decade (3.2e-5 s to
        // 3.2e1 s), so that the capped fit can find them exactly
        let per_decade = TERMS_PER_DECADE as usize;
        let times: Vec<f64> = default_times(1e-3, 1e5)
            .into_iter()
            .skip(per_decade)
            .step_by(per_decade)
            .take(7)
            .collect();
        let truth = PronySeries {
            g_inf: 1e6,
            terms: times.iter().map(|&t| (3e7, t)).collect(),
        };
        let data: Vec<(f64, f64, f64)> = log_times(1e-3, 1e5, 41)
            .into_iter()
            .map(|w| (w, truth.storage(w), truth.loss(w)))
            .collect();
        let fit = fit_times(&data, &times).unwrap();
        assert!((fit.g_inf / 1e6 - 1.0).abs() < 1e-8);
        assert!(fit.rms_rel_error(&data) < 1e-10);
        // capped at 5 of the 7 terms: within the cap, worse but sane; at 7, exact again
        let capped = fit_prony(&data, Some(5)).unwrap();
        assert!(capped.terms.len() <= 5);
        assert!(
            capped.rms_rel_error(&data) < 0.3,
            "{}",
            capped.rms_rel_error(&data)
        );
        let seven = fit_prony(&data, Some(7)).unwrap();
        assert!(seven.terms.len() <= 7);
        assert!(
            seven.rms_rel_error(&data) < 1e-6,
            "{}",
            seven.rms_rel_error(&data)
        );
    }
}
