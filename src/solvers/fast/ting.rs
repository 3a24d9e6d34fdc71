//! Ting/Graham roots: `t_1(t)` from `Φ(t_1) = 0` on the dense compression output, and the end
//! of contact (`t_1 = 0`, `c_inf d + Σ_k c_k S_k = 0`).

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

use super::*;

/// A Ting root and what the Newton stop of a restitution step needs at it.
#[derive(Clone, Copy, Default)]
pub(super) struct Root {
    /// `t_1`.
    pub(super) t1: f64,
    /// Force at the node.
    pub(super) f: f64,
    /// `d(t_1)`.
    pub(super) d1: f64,
    /// `d'(t_1)`.
    pub(super) v1: f64,
    /// `G_eq(t - t_1)`.
    pub(super) g: f64,
    /// `a` and `a'` at `d(t_1)` before the first-order move (a shape other than the
    /// paraboloid; 0 otherwise).
    pub(super) a1: f64,
    pub(super) a1_slope: f64,
}

impl<const K: usize> Solver<K> {
    /// Ting/Graham root `t_1` at time `t` with indentation `d` and `S_k(t) = s_k`, with the force
    /// and local derivatives ([`Root`]). `t_1 = 0` (and `F = 0`) once `c_inf d + Σ c_k s_k <= 0`.
    pub(super) fn t1_root(&mut self, t: f64, d: f64, s: &[f64; K], guess: f64) -> Result<Root> {
        let mut phi0 = self.c_inf * d;
        for k in 0..self.k {
            phi0 += self.c[k] * s[k];
        }
        if phi0 <= 0.0 {
            return Ok(Root::default());
        }
        let tm = self.t_m;
        let (mut lo, mut hi) = (0.0, tm);
        let mut x = if guess > 0.0 && guess < tm {
            guess
        } else {
            0.5 * tm
        };
        let mut hi_checked = false;
        for _ in 0..tolerances::ROOT_MAX_ITER {
            let mut decay = [0.0; K];
            for k in 0..self.k {
                decay[k] = kernel::exp_neg((t - x) * self.inv_tau[k]);
            }
            let pt = self.comp_at_decayed(x, Some(&decay));
            let mut phi = self.c_inf * (d - pt.d);
            let mut g = self.c_inf;
            let mut f = self.c_inf * pt.w;
            for k in 0..self.k {
                let ek = decay[k];
                phi += self.c[k] * (s[k] - ek * pt.s[k]);
                g += self.c[k] * ek;
                f += self.c[k] * ek * pt.q[k];
            }
            let dphi = -pt.v * g;
            let root = |t1: f64, f: f64, d1: f64| Root {
                t1,
                f,
                d1,
                v1: pt.v,
                g,
                a1: 0.0,
                a1_slope: 0.0,
            };
            if phi > 0.0 {
                lo = x;
                if x == tm || (!hi_checked && hi - x < 1e-15 * tm) {
                    return Ok(root(x, K16 * f, pt.d));
                }
            } else {
                hi = x;
                hi_checked = true;
            }
            let newton = x - phi / dphi;
            let step = (newton - x).abs();
            if step <= 1e-14 * tm || hi - lo <= 1e-14 * tm {
                return Ok(root(x, K16 * f, pt.d));
            }
            // d²F/dφ² = 8 a'(d(t_1)) / G_eq: 4 / (sqrt(d) G_eq) for the paraboloid
            let sp = self.shape.geom.map(|_| self.point_at(pt.d));
            let sd = match sp {
                None => pt.d.max(0.0).sqrt(),
                Some(p) => 0.5 / p.a_slope,
            };
            // Accept the Newton point when it is close (`accept_step`), or when the force
            // there, moved to first order, is exact to FAST_ROOT_LEVEL rtol relative or to
            // the step's absolute `root_force_tol`: as a function of the residual Φ = φ the
            // force has d²F/dφ² = 4 / (sqrt(d(t_1)) G_eq) (see rest_step), so the first-order
            // move leaves 2 φ² / (sqrt(d(t_1)) G_eq)
            let f_tol = (FAST_ROOT_LEVEL * self.rtol * K16 * f.abs()).max(self.root_force_tol);
            if newton >= lo
                && newton <= hi
                && (step <= self.accept_step || 2.0 * phi * phi <= f_tol * sd * g)
            {
                // quadratic convergence: the Newton point is exact to ~step^2; move F and d
                // there to first order (dF/dt_1 = (16/3) G_eq(t - t_1) w'(t_1))
                let dx = newton - x;
                let df =
                    K16 * sp.map_or_else(|| self.shape.w_slope(pt.d), |p| 1.5 * p.a) * pt.v * g;
                let mut r = root(newton, K16 * f + df * dx, pt.d + pt.v * dx);
                if let Some(p) = sp {
                    (r.a1, r.a1_slope) = (p.a, p.a_slope);
                }
                return Ok(r);
            }
            x = if newton > lo && newton < hi {
                newton
            } else if !hi_checked && lo > 0.0 {
                // root may sit at t_m itself (right after the turn)
                if lo < tm {
                    0.5 * (lo + hi)
                } else {
                    tm
                }
            } else {
                0.5 * (lo + hi)
            };
        }
        Err(Error::NoConvergence {
            what: "fast Ting root t_1",
            iterations: tolerances::ROOT_MAX_ITER as u64,
        })
    }

    /// `g(θ) = c_inf d + Σ c_k S_k` on a restitution step (contact while `g > 0`).
    pub(super) fn contact_measure(&self, seg: &Seg<K>, th: f64) -> (f64, Pt<K>) {
        let pt = self.eval_seg(seg, th, false);
        let mut g = self.c_inf * pt.d;
        for k in 0..self.k {
            g += self.c[k] * pt.s[k];
        }
        (g, pt)
    }

    /// Root of `g` in `(0, hi]` by safeguarded Newton, `g(0) > 0 >= g(hi)`;
    /// `dg/dθ = h [c_inf v + Σ_k c_k (v - S_k / tau_k)]` (`S_k' = d' - S_k / tau_k`).
    pub(super) fn end_root(&self, seg: &Seg<K>, hi: f64, g_hi: f64) -> Result<f64> {
        let g0 = self.contact_measure(seg, 0.0).0;
        let (mut a, mut b) = (0.0, hi);
        // first iterate: the secant through the bracket
        let mut x = (hi * g0) / (g0 - g_hi);
        if !(x > a && x < b) {
            x = 0.5 * (a + b);
        }
        for _ in 0..tolerances::ROOT_MAX_ITER {
            let (gx, pt) = self.contact_measure(seg, x);
            if gx == 0.0 {
                return Ok(x);
            }
            if gx > 0.0 {
                a = x;
            } else {
                b = x;
            }
            let mut dg = self.c_inf * pt.v;
            for k in 0..self.k {
                dg += self.c[k] * (pt.v - pt.s[k] / self.tau[k]);
            }
            dg *= seg.h;
            let newton = x - gx / dg;
            let dx = (newton - x).abs();
            if newton > a && newton < b {
                // quadratic convergence: the Newton point is exact to ~dx^2
                if dx <= 1e-10 * hi {
                    return Ok(newton);
                }
                x = newton;
            } else {
                x = 0.5 * (a + b);
            }
            if b - a <= 1e-15 * hi {
                return Ok(x);
            }
        }
        Err(Error::NoConvergence {
            what: "fast end of contact",
            iterations: tolerances::ROOT_MAX_ITER as u64,
        })
    }
}
