//! The `fast` solver against checks that share no code with it: a slow brute-force integration
//! of the same hereditary equations written out in this file (RK4 in `sqrt(t)` for compression,
//! RK4 in `t` with a bisected Ting root on a Hermite-interpolated history for restitution), and
//! the slow-relaxation asymptote of the CoR.

use mdr_impact::{solvers::fast, Prony, PronyTerm};

use crate::common;
use common::canonical;

const K16: f64 = 16.0 / 3.0;

/// Brute-force CoR, contact time and maximum indentation with `n` steps per phase.
///
/// Compression (docs/theory.md §4), with `σ = sqrt(t)` so that the start `d ≈ t` is regular:
/// `dd/dσ = 2σ v`, `dv/dσ = -2σ F`, `dq_k/dσ = 2σ (-q_k/τ_k + (3/2) sqrt(d) v)`,
/// `dS_k/dσ = 2σ (-S_k/τ_k + v)`, `F = (16/3)(c_inf d^(3/2) + Σ c_k q_k)`.
/// Restitution: RK4 in `t` on `(d, v, S_k)`, `F` from the root `t_1` of
/// `c_inf (d - d(t_1)) + Σ c_k (S_k - exp(-(t-t_1)/τ_k) S_k(t_1)) = 0` by bisection.
fn brute(prony: &Prony, n: usize) -> (f64, f64, f64) {
    let c_inf = prony.relaxed;
    let c: Vec<f64> = prony.terms.iter().map(|p| p.coefficient).collect();
    let tau: Vec<f64> = prony.terms.iter().map(|p| p.tau).collect();
    let k = c.len();
    let glassy = c_inf + c.iter().sum::<f64>();
    let relaxed_tm = 0.5 * 2.943 * (1.25 / (K16 * c_inf)).powf(0.4);
    // ---- compression: y = [d, v, q.., S..]
    let force = |y: &[f64]| {
        K16 * (c_inf * y[0].max(0.0).powf(1.5) + (0..k).map(|i| c[i] * y[2 + i]).sum::<f64>())
    };
    let rhs = |s: f64, y: &[f64]| -> Vec<f64> {
        let mut f = vec![0.0; y.len()];
        let fo = force(y);
        f[0] = 2.0 * s * y[1];
        f[1] = -2.0 * s * fo;
        for i in 0..k {
            f[2 + i] = 2.0 * s * (-y[2 + i] / tau[i] + 1.5 * y[0].max(0.0).sqrt() * y[1]);
            f[2 + k + i] = 2.0 * s * (-y[2 + k + i] / tau[i] + y[1]);
        }
        f
    };
    let rk4 = |f: &dyn Fn(f64, &[f64]) -> Vec<f64>, s: f64, y: &[f64], h: f64| -> Vec<f64> {
        let add = |a: &[f64], b: &[f64], w: f64| {
            a.iter().zip(b).map(|(x, y)| x + w * y).collect::<Vec<_>>()
        };
        let k1 = f(s, y);
        let k2 = f(s + 0.5 * h, &add(y, &k1, 0.5 * h));
        let k3 = f(s + 0.5 * h, &add(y, &k2, 0.5 * h));
        let k4 = f(s + h, &add(y, &k3, h));
        (0..y.len())
            .map(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
            .collect()
    };
    let ds = (2.0 * relaxed_tm).sqrt() / n as f64;
    let mut s = 0.0;
    let mut y = vec![0.0; 2 + 2 * k];
    y[1] = 1.0;
    // history in t: (t, state)
    let mut hist: Vec<(f64, Vec<f64>)> = vec![(0.0, y.clone())];
    loop {
        let y1 = rk4(&rhs, s, &y, ds);
        if y1[1] <= 0.0 {
            // v = 0 inside: bisect the partial step
            let (mut lo, mut hi) = (0.0, ds);
            for _ in 0..60 {
                let m = 0.5 * (lo + hi);
                if rk4(&rhs, s, &y, m)[1] > 0.0 {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            let ym = rk4(&rhs, s, &y, lo);
            s += lo;
            y = ym;
            hist.push((s * s, y.clone()));
            break;
        }
        s += ds;
        y = y1;
        hist.push((s * s, y.clone()));
        assert!(hist.len() < 100 * n, "compression did not end");
    }
    let t_m = s * s;
    let d_max = y[0];
    let deriv = |y: &[f64]| -> Vec<f64> {
        let mut f = vec![0.0; y.len()];
        f[0] = y[1];
        f[1] = -force(y);
        for i in 0..k {
            f[2 + i] = -y[2 + i] / tau[i] + 1.5 * y[0].max(0.0).sqrt() * y[1];
            f[2 + k + i] = -y[2 + k + i] / tau[i] + y[1];
        }
        f
    };
    let dhist: Vec<Vec<f64>> = hist.iter().map(|(_, y)| deriv(y)).collect();
    // cubic Hermite interpolation of the compression history at t1
    let at = |t1: f64| -> Vec<f64> {
        let j = hist
            .partition_point(|(t, _)| *t <= t1)
            .clamp(1, hist.len() - 1);
        let (ta, ya) = (&hist[j - 1].0, &hist[j - 1].1);
        let (tb, yb) = (&hist[j].0, &hist[j].1);
        let h = tb - ta;
        let x = ((t1 - ta) / h).clamp(0.0, 1.0);
        let (h00, h10, h01, h11) = (
            (1.0 + 2.0 * x) * (1.0 - x) * (1.0 - x),
            x * (1.0 - x) * (1.0 - x),
            x * x * (3.0 - 2.0 * x),
            x * x * (x - 1.0),
        );
        (0..ya.len())
            .map(|i| h00 * ya[i] + h10 * h * dhist[j - 1][i] + h01 * yb[i] + h11 * h * dhist[j][i])
            .collect()
    };
    // ---- restitution: z = [d, v, S..]
    let rforce = |t: f64, z: &[f64]| -> f64 {
        let phi = |t1: f64| {
            let p = at(t1);
            c_inf * (z[0] - p[0])
                + (0..k)
                    .map(|i| c[i] * (z[2 + i] - (-(t - t1) / tau[i]).exp() * p[2 + k + i]))
                    .sum::<f64>()
        };
        if phi(0.0) <= 0.0 {
            return 0.0;
        }
        let (mut lo, mut hi) = (0.0, t_m);
        for _ in 0..60 {
            let m = 0.5 * (lo + hi);
            if phi(m) > 0.0 {
                lo = m;
            } else {
                hi = m;
            }
        }
        let t1 = 0.5 * (lo + hi);
        let p = at(t1);
        K16 * (c_inf * p[0].max(0.0).powf(1.5)
            + (0..k)
                .map(|i| c[i] * (-(t - t1) / tau[i]).exp() * p[2 + i])
                .sum::<f64>())
    };
    let rrhs = |t: f64, z: &[f64]| -> Vec<f64> {
        let mut f = vec![0.0; z.len()];
        f[0] = z[1];
        f[1] = -rforce(t, z);
        for i in 0..k {
            f[2 + i] = -z[2 + i] / tau[i] + z[1];
        }
        f
    };
    let gap = |z: &[f64]| c_inf * z[0] + (0..k).map(|i| c[i] * z[2 + i]).sum::<f64>();
    let mut z = vec![y[0], y[1]];
    z.extend_from_slice(&y[2 + k..]);
    let mut t = t_m;
    let dt = 2.0 * relaxed_tm.max(t_m) / n as f64;
    let _ = glassy;
    loop {
        let z1 = rk4(&rrhs, t, &z, dt);
        if gap(&z1) <= 0.0 {
            let (mut lo, mut hi) = (0.0, dt);
            for _ in 0..60 {
                let m = 0.5 * (lo + hi);
                if gap(&rk4(&rrhs, t, &z, m)) > 0.0 {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            let ze = rk4(&rrhs, t, &z, hi);
            return (-ze[1], t + hi, d_max);
        }
        t += dt;
        z = z1;
        assert!(t < 1e3 * t_m, "restitution did not end");
    }
}

/// Moderate relaxation times (RK4 stays stable and accurate with a few thousand steps):
/// incompressible (one term) and compressible (two terms).
#[test]
fn fast_agrees_with_brute_force_integration() {
    for (nu, p2, p3) in [(0.5, 1.0, 1.0), (0.3, 0.1, 3.0), (-0.5, 1.0, 0.5)] {
        let prony = canonical(nu, p2, p3);
        let (e1, tc1, dm1) = brute(&prony, 2000);
        let (e2, tc2, dm2) = brute(&prony, 4000);
        // the brute force itself converges (RK4, weakened to ~2.5 by the end of contact)
        assert!(
            (e1 - e2).abs() < 1e-6,
            "brute force not converged: {e1} {e2}"
        );
        let out = fast::impact(&prony, 1e-8, false).unwrap();
        let tol = 4.0 * (e1 - e2).abs() + 1e-8;
        eprintln!(
            "({nu}, {p2}, {p3}): fast {:.12} brute {e2:.12} (brute n/2 {e1:.12})",
            out.cor
        );
        assert!(
            (out.cor - e2).abs() < tol,
            "({nu}, {p2}, {p3}): fast {} brute {e2} (brute change {:.1e})",
            out.cor,
            (e1 - e2).abs()
        );
        assert!((out.contact_time - tc2).abs() < 1e-5 * tc2 + 4.0 * (tc1 - tc2).abs());
        assert!((out.max_indentation - dm2).abs() < 1e-6 * dm2 + 4.0 * (dm1 - dm2).abs());
    }
}

/// Slow relaxation (`tau >> t_c`): the material is nearly elastic with the glassy modulus and
/// the dissipation is first order in `1/tau`: `1 - e ≈ (4/9) t_c0 (Σ c_k / tau_k) / G_eq(0)`,
/// `t_c0` the Hertz contact time with `G_eq(0)`. The relative correction is `O(t_c / tau)`.
#[test]
fn slow_relaxation_asymptote() {
    for (c_inf, terms) in [
        (1.0, vec![(1.0, 1e4)]),
        (0.7, vec![(0.25, 3e4), (0.2, 5e4)]),
        (1.0, vec![(100.0, 1e5)]),
    ] {
        let prony = Prony {
            relaxed: c_inf,
            terms: terms
                .iter()
                .map(|&(coefficient, tau)| PronyTerm { coefficient, tau })
                .collect(),
        };
        let g0 = prony.glassy();
        let tc0 = 2.9432751843247047 * (1.25 / (K16 * g0)).powf(0.4);
        let rate: f64 = terms.iter().map(|&(c, tau)| c / tau).sum();
        let predicted = 4.0 / 9.0 * tc0 * rate / g0;
        let out = fast::impact(&prony, 1e-10, false).unwrap();
        let min_tau = terms.iter().map(|t| t.1).fold(f64::INFINITY, f64::min);
        let rel = ((1.0 - out.cor) - predicted).abs() / predicted;
        eprintln!(
            "1 - e = {:.6e}, asymptote {predicted:.6e}, t_c0/tau {:.1e}",
            1.0 - out.cor,
            tc0 / min_tau
        );
        assert!(
            rel < 3.0 * tc0 / min_tau,
            "1 - e = {:.6e}, asymptote {predicted:.6e}, rel {rel:.1e}",
            1.0 - out.cor
        );
    }
}
