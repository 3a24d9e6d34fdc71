//! The compression phase (`0 <= t <= t_m`, Lee–Radok): one collocation step and the phase's
//! step loop up to the time of maximum indentation.

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

use super::*;

/// [`remainder_correction`] of a compression step after the correction `delta` to `z`: the
/// second-order remainder of the forces `(16/3) (c_inf I + M) W'' delta^2 / 2` with `W''` at
/// the nodes `D = dfix + z` given by `w2 = W''(D)` (`(3/4) D^(-1/2)` for the paraboloid,
/// `(3/2) a'(D)` for any shape).
#[allow(clippy::too_many_arguments)]
pub(super) fn compression_remainder(
    a_inv: &Mat<S>,
    jf: &Mat<S>,
    h2: f64,
    m: &Mat<S>,
    c_inf: f64,
    nodes: (&[f64; S], &[f64; S]),
    curvature: Option<&[f64; S]>,
    delta: &[f64; S],
) -> f64 {
    let (dfix, z) = nodes;
    let w2: [f64; S] = std::array::from_fn(|j| match curvature {
        None => 0.375 * delta[j] * delta[j] / (dfix[j] + z[j]).max(f64::MIN_POSITIVE).sqrt(),
        Some(w2) => 0.5 * w2[j] * delta[j] * delta[j],
    });
    let rem_f = std::array::from_fn(|i| {
        let mut acc = c_inf * w2[i];
        for j in 0..S {
            acc += m[i][j] * w2[j];
        }
        K16 * acc
    });
    remainder_correction(a_inv, jf, h2, &rem_f)
}

/// The compression phase of one pass: the state at the time of maximum indentation `t_m`.
pub(super) struct Turn<const K: usize> {
    pub(super) t_m: f64,
    pub(super) d_m: f64,
    pub(super) v_m: f64,
    pub(super) s_m: [f64; K],
    pub(super) f_m: f64,
    /// Length of the first restitution step.
    pub(super) h: f64,
    pub(super) steps: u64,
    pub(super) err_sum: f64,
    pub(super) hist: Option<History>,
    pub(super) peak: PeakTracker,
}

/// Compression phase (`0 <= t <= t_m`) with the per-step velocity tolerance `prec * factor`
/// (`prec` also sets the Newton stops); the first step at [`FAST_FIRST_STEP_FACTOR`] of it.
/// Leaves the dense compression output in `s`.
pub(super) fn compress<const K: usize>(
    s: &mut Solver<K>,
    prec: f64,
    history: bool,
) -> Result<Turn<K>> {
    let tol = prec * FAST_TOL_FACTOR;
    s.rtol = prec;
    s.comp.clear();
    s.last_seg = 0;
    let mut hist = history.then(History::default);
    if let Some(hh) = hist.as_mut() {
        hh.push(0.0, 0.0, 1.0, 0.0, 0.0);
    }
    let mut peak = PeakTracker::default();
    peak.push(0.0, 0.0);
    let mut steps = 0u64;
    let mut err_sum = 0.0;
    // glassy Hertz time of maximum indentation as the first length scale
    let d0 = s.shape.elastic_scale(s.glassy);
    let tm0 = 0.5 * HERTZ_CONTACT_FACTOR * d0;
    let mut h = 0.1 * tm0 * (prec / 1e-6).powf(1.0 / (S as f64 + 2.0)).min(1.0);

    // ---- compression
    let (mut t, mut d, mut v, mut f_n) = (0.0_f64, 0.0_f64, 1.0_f64, 0.0_f64);
    let mut q = [0.0; K];
    let mut sk = [0.0; K];
    let mut kind = Kind::First;
    let (t_m, d_m, v_m, s_m, f_m);
    let mut retry = Retry::default();
    let mut h_full = 0.0;
    loop {
        steps += 1;
        if steps > FAST_MAX_STEPS {
            return Err(Error::WorkLimit {
                solver: SOLVER_NAME,
                what: "steps",
                needed: steps,
                limit: FAST_MAX_STEPS,
            });
        }
        let pred = s.comp.last().copied();
        let out = match s.comp_step(kind, t, d, v, &q, &sk, h, f_n, pred.as_ref()) {
            Ok(o) => o,
            Err(Error::NoConvergence { .. }) => {
                h *= 0.25;
                continue;
            }
            Err(e) => return Err(e),
        };
        // the first step is one step: a tighter tolerance there costs little and covers the
        // initial relaxation layers, where the error estimate is least conservative
        let step_tol = match kind {
            Kind::First => tol * FAST_FIRST_STEP_FACTOR,
            Kind::Regular => tol,
        } * tol_scale(v, f_n, d, s.min_tol_scale);
        let ratio = out.err / step_tol;
        if !(ratio <= 1.0) {
            h = match kind {
                // the first step's basis is in powers of sqrt(θ): its error grows with about
                // half the order in h (observed 3.4 between two attempts on one row; 0.57 -> 0.48
                // first-step retries per impact at rtol 1e-6, 1.61 -> 1.35 at 1e-10)
                Kind::First => retry.next_order(h, ratio, FIRST_STEP_ORDER),
                Kind::Regular => retry.next(h, ratio),
            };
            continue;
        }
        retry = Retry::default();
        err_sum += out.err;
        let seg = out.seg;
        let end = out.end;
        if end.v > 0.0 {
            for i in 0..S {
                peak.push(t + s.tab.c[i] * h, out.f[i]);
            }
            s.comp.push(seg);
            t += h;
            d = end.d;
            v = end.v;
            q = end.q;
            sk = end.s;
            f_n = out.f[S - 1];
            if let Some(hh) = hist.as_mut() {
                hh.push(t, d, v, f_n, s.shape.radius_at(d));
            }
            kind = Kind::Regular;
            h_full = h;
            h *= step_factor(ratio);
            continue;
        }
        // v = 0 inside this step: Newton–bisection on v(θ)
        // (the polynomial alone: the hereditary integrals once, at the root)
        let (mut lo, mut hi) = (0.0, 1.0);
        let mut th = 0.5;
        let (_, mut vt, mut at) = seg_poly_at(&seg, th);
        for it in 0..=tolerances::ROOT_MAX_ITER {
            if it == tolerances::ROOT_MAX_ITER {
                return Err(Error::NoConvergence {
                    what: "fast time of maximum indentation",
                    iterations: it as u64,
                });
            }
            if vt > 0.0 {
                lo = th;
            } else {
                hi = th;
            }
            let newton = th - vt / at;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let done = (next - th).abs() <= 1e-15 || hi - lo <= 1e-15;
            th = next;
            (_, vt, at) = seg_poly_at(&seg, th);
            if done {
                break;
            }
        }
        let pt = s.eval_seg(&seg, th, true);
        for i in 0..S {
            if s.tab.c[i] < th {
                peak.push(t + s.tab.c[i] * h, out.f[i]);
            }
        }
        s.comp.push(seg);
        t_m = t + th * h;
        d_m = pt.d;
        v_m = pt.v;
        s_m = pt.s;
        f_m = s.force_comp(&pt);
        peak.push(t_m, f_m);
        if let Some(hh) = hist.as_mut() {
            hh.push(t_m, d_m, v_m, f_m, s.shape.radius_at(d_m));
        }
        // restitution starts with the length of the last full compression step, shortened
        // for the relaxation layers after the turn
        h = turn_layer_step(
            s,
            (th * h).max(h_full),
            &pt.q,
            tol * rest_tol_scale(v_m, f_m, d_m, s.min_tol_scale),
        );
        break;
    }
    s.t_m = t_m;
    s.build_dense();
    Ok(Turn {
        t_m,
        d_m,
        v_m,
        s_m,
        f_m,
        h,
        steps,
        err_sum,
        hist,
        peak,
    })
}

impl<const K: usize> Solver<K> {
    /// Modulus by which a mismatch `δw` of `w` between the nodes of a step of length `h` acts on
    /// the force: `c_inf + Σ_k c_k min(1, 2 (S+1)^2 tau_k / h)`. Through a term it acts as
    /// `∫ exp(-(t-s)/tau_k) δw'(s) ds`: at most `c_k |δw|`, and for `tau_k << h` about
    /// `c_k tau_k |δw'| <= c_k tau_k 2 (S+1)^2 |δw| / h` (Markov's inequality for the step
    /// polynomial; the glassy modulus overstates stiff terms by `h / tau_k`).
    pub(super) fn effective_modulus(&self, h: f64) -> f64 {
        let markov = 2.0 * ((S + 1) * (S + 1)) as f64;
        let mut g = self.c_inf;
        for k in 0..self.k {
            g += self.c[k] * (markov * self.tau[k] / h).min(1.0);
        }
        g
    }

    /// Defect of a compression step's polynomial at `θ`: `|d'' + F|` plus the mismatch between
    /// `w` and `d^(3/2)` times `geff` ([`Solver::effective_modulus`]).
    pub(super) fn comp_defect(&self, seg: &Seg<K>, th: f64, geff: f64) -> f64 {
        let pt = self.eval_seg(seg, th, true);
        (pt.dd + self.force_comp(&pt)).abs() + K16 * geff * (self.shape.w(pt.d) - pt.w).abs()
    }

    pub(super) fn force_comp(&self, pt: &Pt<K>) -> f64 {
        let mut f = self.c_inf * pt.w;
        for k in 0..self.k {
            f += self.c[k] * pt.q[k];
        }
        K16 * f
    }

    /// One compression step of length `h` from `(t0, dn, vn, q0, s0)`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn comp_step(
        &mut self,
        kind: Kind,
        t0: f64,
        dn: f64,
        vn: f64,
        q0: &[f64; K],
        s0: &[f64; K],
        h: f64,
        f_n: f64,
        pred: Option<&Seg<K>>,
    ) -> Result<StepOut<K>> {
        let b = self.basis(kind);
        let c = self.tab.c;
        let vh = vn * h;
        let wfix = match kind {
            Kind::Regular => self.shape.w(dn),
            Kind::First => self.shape.w(vh),
        };
        let mut dfix = [0.0; S];
        let mut wfix_n = [0.0; S];
        for i in 0..S {
            dfix[i] = dn + vh * c[i];
            wfix_n[i] = match kind {
                Kind::Regular => wfix,
                Kind::First => wfix * c[i] * c[i].sqrt(),
            };
        }
        // q_i = f0_i / c-weights + M (W - wfix): linear in W
        let mut m = [[0.0; S]; S];
        // Σ_k c_k Ĵ_w at the nodes
        let mut lw = [[0.0; S]; S];
        let mut f0 = [0.0; S];
        // per term at the step end (θ = c_S = 1): kernels, the decayed start values of q and S
        let mut jend = [Jt::ZERO; K];
        let mut qend = [0.0; K];
        let mut send = [0.0; K];
        for k in 0..self.k {
            let ck = self.c[k];
            let (jn, exn) = jt_lanes::<S>(
                kind,
                &std::array::from_fn(|i| c[i] * h / self.tau[k]),
                self.series_tol(),
            );
            for i in 0..S {
                let jj = jn[i];
                let ex = exn[i];
                let mut fi = ex * q0[k];
                if kind == Kind::First {
                    fi += wfix * 1.5 * c[i] * c[i].sqrt() * jj.wfix;
                }
                if i == S - 1 {
                    qend[k] = fi;
                    send[k] = ex * s0[k] + vh * jj.one;
                    jend[k] = jj;
                }
                f0[i] += ck * fi;
                for j in 0..S {
                    lw[i][j] += ck * jj.w[j];
                }
            }
        }
        // M = (L ∘ wexp ∘ P_w) V_w^-1, summed over the terms before the product
        for i in 0..S {
            let mut l = [0.0; S];
            for j in 0..S {
                l[j] = lw[i][j] * wexp(kind, j) * b.pw[i][j];
            }
            for j in 0..S {
                let mut acc = 0.0;
                for (lj, vrow) in l.iter().zip(b.vw_inv.iter()) {
                    acc += lj * vrow[j];
                }
                m[i][j] = acc;
            }
        }
        // unknowns: the increments z_i = d(t_n + c_i h) - dfix_i (no cancellation for small h)
        let regular = kind == Kind::Regular;
        let shape = self.shape;
        // the forces at the nodes, and the contact radii there (one inverse of the profile per
        // node: `w`, its increment from the step start and `w' = (3/2) a` share it)
        let forces = |z: &[f64; S]| {
            let mut dw = [0.0; S]; // W_i - wfix_i
            let mut w = [0.0; S];
            let mut a = [0.0; S];
            for i in 0..S {
                let di = (dfix[i] + z[i]).max(0.0);
                (w[i], a[i]) = shape.w_and_radius(di);
                dw[i] = if regular {
                    shape.w_increment_known(dn, vh * c[i] + z[i], wfix, w[i])
                } else {
                    w[i] - wfix_n[i]
                };
            }
            let mut f = [0.0; S];
            for i in 0..S {
                let mut acc = self.c_inf * w[i] + f0[i];
                for j in 0..S {
                    acc += m[i][j] * dw[j];
                }
                f[i] = K16 * acc;
            }
            (dw, f, a)
        };
        let h2 = h * h;
        let mut z = predict_nodes(b, &c, t0, h, &dfix, f_n, pred);
        // modulus of the Newton stop's curvature bound: the largest row sum of c_inf I + |M|
        // (the glassy modulus used before overstated a term relaxing within the step by about
        // h / tau_k)
        let g_step = self.c_inf + linalg::norm_inf(&m);
        let mut prev = f64::INFINITY;
        let mut converged = false;
        for _ in 0..FAST_NEWTON_MAX_ITER {
            self.evaluations += S as u64;
            let (_, f, a_nodes) = forces(&z);
            let af = linalg::mul_vec(&b.a, &f);
            let mut r = [0.0; S];
            for i in 0..S {
                r[i] = -(z[i] + h2 * af[i]);
            }
            // dW_j/dD_j = (3/2) a(D_j) (sqrt(D_j) for the paraboloid)
            let dw: [f64; S] = std::array::from_fn(|j| 1.5 * a_nodes[j]);
            // a'(D) at the nodes before the correction (the bounds below need its size only)
            let a_slope: [f64; S] = std::array::from_fn(|j| {
                self.shape
                    .radius_slope_at((dfix[j] + z[j]).max(0.0), a_nodes[j])
            });
            let mut jf = [[0.0; S]; S];
            for i in 0..S {
                for j in 0..S {
                    jf[i][j] = K16 * (m[i][j] + if i == j { self.c_inf } else { 0.0 }) * dw[j];
                }
            }
            let delta = newton_correction(
                &b.a_inv,
                &jf,
                h2,
                r,
                "fast compression step (singular Newton matrix)",
            )?;
            let (dmax, scale) = update(&mut z, &delta);
            if !dmax.is_finite() {
                break;
            }
            // F'' = (3/4) (16/3) G d^(-1/2) at most, G = g_step: the next correction is
            // h^2 A F'' dmax^2 / 2
            let mut dmin = f64::INFINITY;
            for i in 0..S {
                dmin = dmin.min(dfix[i] + z[i]);
            }
            let curv = match self.shape.geom {
                None => 0.5 * h2 * 0.75 * K16 * g_step / dmin.max(0.0).sqrt(),
                Some(_) => {
                    let slope = a_slope.iter().fold(0.0, |m: f64, &x| m.max(x));
                    0.5 * h2 * 1.5 * slope * K16 * g_step
                }
            };
            if newton_done(dmax, scale, prev, self.rtol)
                || quadratic_done(dmax, scale, curv, self.rtol)
                || next_correction_done(
                    compression_remainder(
                        &b.a_inv,
                        &jf,
                        h2,
                        &m,
                        self.c_inf,
                        (&dfix, &z),
                        self.shape
                            .geom
                            .is_some()
                            .then(|| std::array::from_fn(|j| 1.5 * a_slope[j]))
                            .as_ref(),
                        &delta,
                    ),
                    scale,
                    self.rtol,
                )
            {
                converged = true;
                break;
            }
            prev = dmax;
        }
        if !converged {
            return Err(Error::NoConvergence {
                what: "fast compression step (Newton)",
                iterations: FAST_NEWTON_MAX_ITER as u64,
            });
        }
        let (rw, f, a_nodes) = forces(&z);
        let rd = z;
        let seg = Seg {
            t0,
            h,
            kind,
            dn,
            vh,
            alpha: linalg::mul_vec(&b.vd_inv, &rd),
            wfix,
            beta: linalg::mul_vec(&b.vw_inv, &rw),
            q0: *q0,
            s0: *s0,
        };
        // defect of the collocation polynomial between the nodes
        let geff = self.effective_modulus(h);
        let mut err = h * self.comp_defect(&seg, self.tab.theta_star, geff);
        if kind == Kind::First && self.tau[..self.k].iter().any(|&tk| tk < h) {
            // a term relaxing inside the first step: the defect at the middle of every gap
            // between the nodes, not only at the probe, which can sit near a zero of the defect
            // (one row's first step, tau / h = 0.41, was accepted at 0.9 of the tolerance with
            // an actual error of 7e-10 at rtol 1e-10; 6% longer or shorter, its estimate was
            // about 100)
            for i in 1..S {
                err = err.max(h * self.comp_defect(&seg, 0.5 * (c[i - 1] + c[i]), geff));
            }
        }
        if kind == Kind::First {
            // a term relaxing much faster than the step leaves a layer of width tau_k at the
            // start, before the second node, where the probe does not look: its velocity error
            // is about the defect there times the width of the layer (below the first node only,
            // one row at tau / h = 0.075 was accepted at 0.84 of the tolerance with an actual
            // error of about 5x it, 3.6e-8 at rtol 1e-8; the estimate at h 3% longer or shorter
            // was 10-15)
            for k in 0..self.k {
                let th = self.tau[k] / h;
                if th < c[1] {
                    err += FAST_LAYER_WIDTH * self.tau[k] * self.comp_defect(&seg, th, geff);
                }
            }
        }
        let a = a_nodes;
        // step end from the last node (θ = 1: every power of θ is 1)
        let mut end = Pt {
            d: dfix[S - 1] + z[S - 1],
            v: vh,
            dd: 0.0,
            w: 0.0,
            q: qend,
            s: send,
        };
        let mut wend = seg.wfix;
        for j in 0..S {
            let (ed, ew) = (dexp(kind, j), wexp(kind, j));
            end.v += seg.alpha[j] * ed;
            wend += seg.beta[j];
            for k in 0..self.k {
                end.s[k] += seg.alpha[j] * ed * jend[k].d[j];
                end.q[k] += seg.beta[j] * ew * jend[k].w[j];
            }
        }
        end.v /= h;
        end.w = wend;
        Ok(StepOut {
            seg,
            f,
            t1: [0.0; S],
            a,
            err,
            end,
        })
    }
}
