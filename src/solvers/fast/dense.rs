//! A step's polynomial (`Seg`), dense values at one instant (`Pt`), and the dense output of the
//! compression history that every Ting root evaluates (`KernelPoly`, `Solver::comp_at`).

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

use super::*;

/// One step's polynomial representation (compression or restitution).
#[derive(Clone, Copy, Debug)]
pub(super) struct Seg<const K: usize> {
    pub(super) t0: f64,
    pub(super) h: f64,
    pub(super) kind: Kind,
    /// `d = dn + vh θ + Σ α_j θ^{dexp_j}` (`dn = 0` for the first step).
    pub(super) dn: f64,
    pub(super) vh: f64,
    pub(super) alpha: [f64; S],
    /// Regular: `w_n` (constant term); first step: coefficient of `θ^{3/2}`.
    pub(super) wfix: f64,
    pub(super) beta: [f64; S],
    pub(super) q0: [f64; K],
    pub(super) s0: [f64; K],
}

/// Dense values at one instant.
#[derive(Clone, Copy, Debug)]
pub(super) struct Pt<const K: usize> {
    pub(super) d: f64,
    pub(super) v: f64,
    pub(super) dd: f64,
    pub(super) w: f64,
    pub(super) q: [f64; K],
    pub(super) s: [f64; K],
}

/// Largest number of coefficients of a dense kernel polynomial.
pub(super) const NT: usize = 64;

/// `h / tau` above which the dense output uses the polynomial particular solution.
/// The particular form loses about `log10(Σ_m m! λ^-m |α_m| / |y|)` digits: a few at `λ = 1/2`
/// for the small high-order coefficients; the Taylor form needs ~`15` terms there.
pub(super) const PARTICULAR_LAMBDA: f64 = 0.5;

/// `h / tau` up to which the first step's kernels have a dense series in `sqrt(θ)`.
pub(super) const SIGMA_LAMBDA: f64 = 2.0;

/// Dense output of one hereditary integral on a regular step, for fast evaluation at any `θ`:
/// `y(θ) = poly(θ) + amp exp(-λ θ)` with `λ = h / tau`. For `λ <= 1/2` `poly` is the Taylor
/// series of the exact solution (`amp = 0`, terms decay like `λ^n / n!`); for `λ > 1/2` it is
/// the polynomial particular solution `Y = Σ_j (-1/λ)^j (1/λ) P^(j+1)` of
/// `y' = -λ y + P'` and `amp = y(0) - Y(0)`. Both are exact for the step's polynomial `P`.
/// The `n` coefficients (of powers of `θ`, or of `sqrt(θ)` on the first step) are
/// `coef[off..off + n]` of the solver's coefficient store.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct KernelPoly {
    pub(super) lam: f64,
    pub(super) amp: f64,
    pub(super) off: usize,
    pub(super) n: usize,
}

impl KernelPoly {
    /// First step, `λ <= 2`: `y = Σ_n y_n σ^n`, `σ = sqrt(θ)`, `y_n = p_n - (2λ/n) y_(n-2)`,
    /// `y_0 = 0`; `p` holds the forcing's coefficients of `σ^n`. `None` for `λ > 2`.
    pub(super) fn new_sigma(p: &[f64], lam: f64, coef: &mut Vec<f64>) -> Option<Self> {
        if lam > SIGMA_LAMBDA {
            return None;
        }
        let off = coef.len();
        coef.push(0.0);
        let mut big: f64 = 0.0;
        let mut n = 1;
        while n < NT {
            let pn = if n < p.len() { p[n] } else { 0.0 };
            let prev = if n >= 2 { coef[off + n - 2] } else { 0.0 };
            let cn = pn - 2.0 * lam / n as f64 * prev;
            coef.push(cn);
            big = big.max(cn.abs());
            n += 1;
            if n > p.len()
                && coef[off + n - 1].abs() <= 1e-18 * big
                && coef[off + n - 2].abs() <= 1e-18 * big
            {
                break;
            }
        }
        Some(KernelPoly {
            lam,
            amp: 0.0,
            off,
            n,
        })
    }

    pub(super) fn new(y0: f64, p: &[f64], lam: f64, trunc: f64, coef: &mut Vec<f64>) -> Self {
        let off = coef.len();
        if lam <= PARTICULAR_LAMBDA {
            coef.push(y0);
            let mut big = y0.abs();
            let mut n = 1;
            while n < NT {
                let pn = if n < p.len() { p[n] } else { 0.0 };
                let cn = (-lam * coef[off + n - 1] + n as f64 * pn) / n as f64;
                coef.push(cn);
                big = big.max(cn.abs());
                n += 1;
                if n >= p.len() && cn.abs() <= trunc * big {
                    break;
                }
            }
            KernelPoly {
                lam,
                amp: 0.0,
                off,
                n,
            }
        } else {
            let eps = 1.0 / lam;
            // derivative coefficients, repeatedly
            let mut c = [0.0; S + 2];
            let mut der = [0.0; S + 2];
            let deg = p.len() - 1;
            for i in 0..deg {
                der[i] = (i + 1) as f64 * p[i + 1];
            }
            let mut len = deg;
            let mut fac = eps;
            while len > 0 {
                for i in 0..len {
                    c[i] += fac * der[i];
                }
                for i in 0..len - 1 {
                    der[i] = (i + 1) as f64 * der[i + 1];
                }
                len -= 1;
                fac *= -eps;
            }
            let n = deg.max(1);
            coef.extend_from_slice(&c[..n]);
            KernelPoly {
                lam,
                amp: y0 - c[0],
                off,
                n,
            }
        }
    }

    /// Value at `θ`; `ex = exp(-λ θ)` (only used when `amp != 0`), `x = θ` or `sqrt(θ)`.
    #[inline]
    pub(super) fn eval(&self, coef: &[f64], x: f64, ex: f64) -> f64 {
        let mut acc = 0.0;
        for &c in coef[self.off..self.off + self.n].iter().rev() {
            acc = acc * x + c;
        }
        if self.amp != 0.0 {
            acc += self.amp * ex;
        }
        acc
    }
}

/// `(d, dd/dθ, d²d/dθ²)` of a step's polynomial at `θ` from its powers (any `θ >= 0`, also
/// beyond the step for prediction; derivatives per unit `θ`, not per unit time).
pub(super) fn seg_poly<const K: usize>(seg: &Seg<K>, p: &Powers) -> (f64, f64, f64) {
    let mut d = seg.dn + seg.vh * p.th;
    let mut v = seg.vh;
    let mut a = 0.0;
    for j in 0..S {
        let e = dexp(seg.kind, j);
        d += seg.alpha[j] * p.d0[j];
        v += seg.alpha[j] * e * p.d1[j];
        a += seg.alpha[j] * e * (e - 1.0) * p.d2[j];
    }
    (d, v, a)
}

/// [`seg_poly`] at `θ`; on a regular step by Horner's rule (`d = dn + vh θ + Σ α_j θ^(j+2)`),
/// without the table of powers.
pub(super) fn seg_poly_at<const K: usize>(seg: &Seg<K>, th: f64) -> (f64, f64, f64) {
    if seg.kind == Kind::First {
        return seg_poly(seg, &powers(Kind::First, th));
    }
    let (mut d, mut v, mut a) = (0.0, 0.0, 0.0);
    for j in (0..S).rev() {
        let e = (j + 2) as f64;
        d = d * th + seg.alpha[j];
        v = v * th + e * seg.alpha[j];
        a = a * th + e * (e - 1.0) * seg.alpha[j];
    }
    (seg.dn + th * (seg.vh + th * d), seg.vh + th * v, a)
}

/// Newton start of a step: the unknowns `z_i = D_i - dfix_i` at the nodes `t0 + c_i h`,
/// extrapolated from the previous step's polynomial `pred`, or without one from the force `f_n`
/// at the step start (`D = dfix - h^2 A F` with `F` constant).
pub(super) fn predict_nodes<const K: usize>(
    b: &Basis,
    c: &[f64; S],
    t0: f64,
    h: f64,
    dfix: &[f64; S],
    f_n: f64,
    pred: Option<&Seg<K>>,
) -> [f64; S] {
    let h2 = h * h;
    let mut z = [0.0; S];
    for i in 0..S {
        let mut a1 = 0.0;
        for j in 0..S {
            a1 += b.a[i][j];
        }
        z[i] = match pred {
            // extrapolate the previous step's polynomial to the new nodes
            Some(p) => seg_d(p, (t0 + c[i] * h - p.t0) / p.h) - dfix[i],
            None => -h2 * a1 * f_n,
        };
    }
    z
}

/// `d` of a step's polynomial at `θ` (see [`seg_poly`]).
pub(super) fn seg_d<const K: usize>(seg: &Seg<K>, th: f64) -> f64 {
    seg_poly_at(seg, th).0
}

/// `max(x, 0)^(3/2)`.
#[inline]
pub(super) fn pow15(x: f64) -> f64 {
    let x = x.max(0.0);
    x * x.sqrt()
}

/// `(d + delta)^(3/2) - d^(3/2)` without cancellation for small `delta`.
pub(super) fn pow15_increment(d: f64, delta: f64) -> f64 {
    let a = (d + delta).max(0.0);
    let b = d.max(0.0);
    let den = a * a.sqrt() + b * b.sqrt();
    let diff = if d >= 0.0 && d + delta >= 0.0 {
        delta
    } else {
        a - b
    };
    if den > 0.0 {
        diff * (a * a + a * b + b * b) / den
    } else {
        0.0
    }
}

impl<const K: usize> Solver<K> {
    /// Dense output of a step at `theta` (`with_w`: also `w` and `q_k`).
    pub(super) fn eval_seg(&self, seg: &Seg<K>, th: f64, with_w: bool) -> Pt<K> {
        let kind = seg.kind;
        let p = powers(kind, th);
        let h = seg.h;
        let (d, v, dd) = seg_poly(seg, &p);
        let (v, dd) = (v / h, dd / (h * h));
        let mut w = 0.0;
        if with_w {
            w = match kind {
                Kind::Regular => seg.wfix,
                Kind::First => seg.wfix * p.w15,
            };
            for j in 0..S {
                w += seg.beta[j] * p.w[j];
            }
        }
        let mut q = [0.0; K];
        let mut s = [0.0; K];
        for k in 0..self.k {
            let x = th * h / self.tau[k];
            let (jj, ex) = jt_ex(kind, x, self.series_tol());
            let mut sk = ex * seg.s0[k] + seg.vh * th * jj.one;
            for j in 0..S {
                sk += seg.alpha[j] * dexp(kind, j) * p.d0[j] * jj.d[j];
            }
            s[k] = sk;
            if with_w {
                let mut qk = ex * seg.q0[k];
                if kind == Kind::First {
                    qk += seg.wfix * 1.5 * p.w15 * jj.wfix;
                }
                for j in 0..S {
                    qk += seg.beta[j] * wexp(kind, j) * p.w[j] * jj.w[j];
                }
                q[k] = qk;
            }
        }
        Pt { d, v, dd, w, q, s }
    }

    /// `w(d)` of a dense compression output; for a shape other than the paraboloid its `a` and
    /// `a'` are kept in `last_point` for the Ting root that asked.
    fn dense_w(&mut self, d: f64) -> f64 {
        if self.shape.geom.is_none() {
            return self.shape.w(d);
        }
        self.last_point = self.shape.point(d);
        if d > 0.0 {
            self.last_point.w
        } else {
            0.0
        }
    }

    /// The shape's values at `d` (from the last dense output when it was at `d`).
    pub(super) fn point_at(&self, d: f64) -> ShapePoint {
        if self.last_point.d == d.max(f64::MIN_POSITIVE) {
            self.last_point
        } else {
            self.shape.point(d)
        }
    }

    /// Dense compression output at `t1 ∈ [0, t_m]`.
    pub(super) fn comp_at(&mut self, t1: f64) -> Pt<K> {
        self.comp_at_decayed(t1, None)
    }

    /// [`Solver::comp_at`] for a Ting root, with the factors `decay[k] = exp(-(t - t1)/tau_k)`
    /// that multiply `q_k` and `S_k` there: a term whose factor is exactly 0 (flushed by
    /// `exp_neg`) is not evaluated and its `q_k`, `S_k` are left 0, since they enter only
    /// through that product (the fast terms of a real polymer, for most of the restitution).
    pub(super) fn comp_at_decayed(&mut self, t1: f64, decay: Option<&[f64; K]>) -> Pt<K> {
        let skip = |k: usize| decay.is_some_and(|e| e[k] == 0.0);
        self.evaluations += 1;
        // the roots move slowly: try the last segment and its neighbour first
        let n = self.comp.len();
        let inside =
            |i: usize| i < n && self.comp[i].t0 <= t1 && (i + 1 == n || self.comp[i + 1].t0 > t1);
        let hint = self.last_seg;
        let i = if inside(hint) {
            hint
        } else if hint > 0 && inside(hint - 1) {
            hint - 1
        } else {
            self.comp.partition_point(|s| s.t0 <= t1).max(1) - 1
        };
        self.last_seg = i;
        let seg = &self.comp[i];
        let inv_h = 1.0 / seg.h;
        let th = ((t1 - seg.t0) * inv_h).max(0.0);
        if self.dense.len() <= i * self.k {
            return self.eval_seg(seg, th, true);
        }
        if seg.kind == Kind::First {
            let p = powers(Kind::First, th);
            let mut d = seg.vh * th;
            let mut v = seg.vh;
            for j in 0..S {
                let e = dexp(Kind::First, j);
                d += seg.alpha[j] * p.d0[j];
                v += seg.alpha[j] * e * p.d1[j];
            }
            let mut q = [0.0; K];
            let mut s = [0.0; K];
            let sig = th.sqrt();
            for k in 0..self.k {
                if skip(k) {
                    continue;
                }
                let kp = &self.dense[i * self.k + k];
                if kp[0].n > 0 {
                    s[k] = kp[0].eval(&self.coef, sig, 0.0);
                    q[k] = kp[1].eval(&self.coef, sig, 0.0);
                    continue;
                }
                // a term relaxing within the step (no series in sqrt(θ)): its exact kernels
                // at θ, as in `eval_seg`
                let x = th * seg.h / self.tau[k];
                let ex = kernel::exp_neg(x);
                let jj = jt_first(x, self.series_tol(), ex);
                let mut sk = ex * seg.s0[k] + seg.vh * th * jj.one;
                let mut qk = ex * seg.q0[k] + seg.wfix * 1.5 * p.w15 * jj.wfix;
                for j in 0..S {
                    sk += seg.alpha[j] * dexp(Kind::First, j) * p.d0[j] * jj.d[j];
                    qk += seg.beta[j] * wexp(Kind::First, j) * p.w[j] * jj.w[j];
                }
                s[k] = sk;
                q[k] = qk;
            }
            return Pt {
                d,
                v: v * inv_h,
                dd: 0.0,
                w: self.dense_w(d),
                q,
                s,
            };
        }
        // regular step: d = dn + vh θ + Σ α_j θ^(j+2), kernels from the precomputed polynomials
        let mut d = 0.0;
        let mut dv = 0.0;
        for j in (0..S).rev() {
            d = d * th + seg.alpha[j];
            dv = dv * th + (j + 2) as f64 * seg.alpha[j];
        }
        let d = seg.dn + th * (seg.vh + th * d);
        let v = (seg.vh + th * dv) * inv_h;
        let mut q = [0.0; K];
        let mut s = [0.0; K];
        for k in 0..self.k {
            if skip(k) {
                continue;
            }
            let kp = &self.dense[i * self.k + k];
            let ex = if kp[0].amp != 0.0 || kp[1].amp != 0.0 {
                kernel::exp_neg(kp[0].lam * th)
            } else {
                0.0
            };
            s[k] = kp[0].eval(&self.coef, th, ex);
            q[k] = kp[1].eval(&self.coef, th, ex);
        }
        Pt {
            d,
            v,
            dd: 0.0,
            w: self.dense_w(d),
            q,
            s,
        }
    }

    /// Precompute the dense kernel polynomials of the regular compression steps.
    pub(super) fn build_dense(&mut self) {
        let trunc = self.series_tol();
        let mut dense = Vec::with_capacity(self.comp.len() * self.k);
        let mut coef = Vec::with_capacity(self.comp.len() * self.k * 24);
        for seg in &self.comp {
            if seg.kind == Kind::First {
                // forcing coefficients of σ^n: d = vh σ^2 + Σ α_j σ^(5+j), w = wfix σ^3 + Σ β_j σ^(6+j)
                let mut ps = [0.0; S + 6];
                ps[2] = seg.vh;
                ps[5..5 + S].copy_from_slice(&seg.alpha);
                let mut pq = [0.0; S + 6];
                pq[3] = seg.wfix;
                pq[6..6 + S].copy_from_slice(&seg.beta);
                for k in 0..self.k {
                    let lam = seg.h / self.tau[k];
                    // both or neither: the same λ; neither (`n = 0`) for a term relaxing within
                    // the step, which `comp_at` evaluates by its exact kernels
                    match KernelPoly::new_sigma(&ps, lam, &mut coef) {
                        Some(a) => {
                            let b = KernelPoly::new_sigma(&pq, lam, &mut coef)
                                .expect("same λ as the first series");
                            dense.push([a, b]);
                        }
                        None => dense.push([KernelPoly::default(); 2]),
                    }
                }
                continue;
            }
            let mut ps = [0.0; S + 2];
            ps[0] = seg.dn;
            ps[1] = seg.vh;
            ps[2..].copy_from_slice(&seg.alpha);
            let mut pq = [0.0; S + 1];
            pq[0] = seg.wfix;
            pq[1..].copy_from_slice(&seg.beta);
            for k in 0..self.k {
                let lam = seg.h / self.tau[k];
                dense.push([
                    KernelPoly::new(seg.s0[k], &ps, lam, trunc, &mut coef),
                    KernelPoly::new(seg.q0[k], &pq, lam, trunc, &mut coef),
                ]);
            }
        }
        self.dense = dense;
        self.coef = coef;
    }
}
