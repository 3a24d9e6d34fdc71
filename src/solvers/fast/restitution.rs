//! The restitution phase (`t > t_m`, Ting/Graham): one collocation step with a Ting root at
//! every node, and the phase's step loop up to the end of contact.

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

use super::*;

/// Restitution phase (`t_m < t <= t_end`) after `turn`, with the per-step velocity tolerance
/// `prec` times [`FAST_TOL_FACTOR`] and [`FAST_REST_TOL_FACTOR`], on the dense compression
/// output left in `s` by [`compress`].
pub(super) fn restitute<const K: usize>(
    s: &mut Solver<K>,
    turn: Turn<K>,
    prec: f64,
) -> Result<Outcome> {
    let tol = prec * FAST_TOL_FACTOR * FAST_REST_TOL_FACTOR;
    s.rtol = prec;
    let Turn {
        t_m,
        d_m,
        v_m,
        s_m,
        f_m,
        mut h,
        mut steps,
        mut err_sum,
        mut hist,
        mut peak,
    } = turn;
    s.accept_step = (FAST_ROOT_LEVEL * prec).sqrt().min(1e-4) * t_m;
    let mut retry = Retry::default();
    let (mut t, mut d, mut v, mut f_n) = (t_m, d_m, v_m, f_m);
    let mut sk = s_m;
    // t_1 at the nodes of the last step, with its start and length (None: mirror image of the
    // elastic case, t_1 = 2 t_m - t); the polynomial through them gives the next step's guesses
    // (the quadratic through the last three nodes used before was off by up to 4e-2 t_m on a
    // dissipative row, a degree-4 fit by about 1e-4: 13% fewer evaluations at rtol 1e-10)
    let mut t1_hist: Option<(f64, f64, [f64; S])> = None;
    let mut prev_rest: Option<Seg<K>> = None;
    let mut ending = false;
    let mut end_iter = 0usize;
    let mut last_miss = f64::INFINITY;
    // lengths of steps from the current start that ended inside the contact (`g > 0`) and
    // after it: the end of contact lies between them
    let (mut end_lo, mut end_hi) = (0.0_f64, f64::INFINITY);
    // after a last step too long for the accuracy: (estimated end of contact, length of the
    // last step); the steps before it stop short of that last step instead of trying again
    let mut end_plan: Option<(f64, f64)> = None;
    let (v_end, t_end);
    // the end of contact predicted after the last accepted step (see FAST_END_RECEDE)
    let mut end_predicted = f64::INFINITY;
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
        let mut guess = [0.0; S];
        let mut omega = [0.0; S];
        for i in 0..S {
            let tt = t + s.tab.c[i] * h;
            guess[i] = match &t1_hist {
                // the polynomial through the node values of t_1(t) on the last step
                Some((tp, hp, ys)) => {
                    let th = (tt - tp) / hp;
                    omega[i] = s.tab.c.iter().map(|&cj| th - cj).product();
                    interp_nodes(s.tab, ys, th)
                }
                None => t_m - (tt - t_m),
            }
            .clamp(0.0, t_m);
        }
        let omega = t1_hist.is_some().then_some(&omega);
        // predictor: the last restitution step's polynomial, or for the first one the
        // compression step of the turn (the force is C^1 there: F' = -(16/3) Σ c_k q_k / tau_k
        // on both sides, so its polynomial extrapolates to third order)
        let turn_seg = if prev_rest.is_none() {
            s.comp.last().copied()
        } else {
            None
        };
        let pred = prev_rest.as_ref().or(turn_seg.as_ref());
        let first = prev_rest.is_none();
        let out = match s.rest_step(t, d, v, &sk, h, f_n, &guess, omega, pred, first) {
            Ok(o) => o,
            Err(Error::NoConvergence { .. }) => {
                h *= 0.25;
                ending = false;
                continue;
            }
            Err(e) => return Err(e),
        };
        let ratio = out.err / (tol * rest_tol_scale(v, f_n, d, s.min_tol_scale));
        let seg = out.seg;
        let end = out.end;
        let mut g1 = s.c_inf * end.d;
        for k in 0..s.k {
            g1 += s.c[k] * end.s[k];
        }
        // the end of contact first: a step across it sees a kink (F = 0 beyond) and would be
        // rejected for the wrong reason
        if g1 <= 0.0 || ending {
            end_iter += 1;
            if end_iter > FAST_END_MAX_ITER {
                return Err(Error::NoConvergence {
                    what: "fast end of contact (last step fit)",
                    iterations: end_iter as u64,
                });
            }
            let th = if g1 <= 0.0 {
                s.end_root(&seg, 1.0, g1)?
            } else {
                // the step ends just before the contact: extrapolate its polynomial
                let mut hi = 1.0;
                let mut ghi = g1;
                let mut found = false;
                for _ in 0..8 {
                    hi *= 1.25;
                    ghi = s.contact_measure(&seg, hi).0;
                    if ghi <= 0.0 {
                        found = true;
                        break;
                    }
                }
                if !found {
                    ending = false;
                    f64::NAN
                } else {
                    s.end_root(&seg, hi, ghi)?
                }
            };
            if th.is_finite() {
                if g1 <= 0.0 {
                    end_hi = end_hi.min(h);
                } else {
                    end_lo = end_lo.max(h);
                }
                let miss = (th - 1.0).abs();
                // converged, or stalled at rounding level (the end is located to far better
                // than the step's accuracy needs: F vanishes there like (t_end - t)^(3/2))
                // F ~ K (t_end - t)^(3/2) near the end (K from the force at the step start,
                // a distance th h before the end): a step end off by miss h changes v by about
                // K (miss h)^(5/2) / (5/2); the CoR is |v| there (at the end, from the step's
                // polynomial: the step may start at the turn, v = 0, and end the contact),
                // hence the relative bound
                let kink = f_n * (miss / th.max(1e-3)).powf(1.5) * miss * h * 0.4;
                let v_scale = (seg_poly_at(&seg, th).1 / h).abs().max(v.abs());
                let done = miss <= 1e-9
                    || (miss <= 1e-6 && miss >= 0.5 * last_miss)
                    || (miss <= 0.1 && kink <= 0.01 * tol * v_scale);
                last_miss = miss;
                if done {
                    if !(ratio <= 1.0) {
                        // the last step is too long for the accuracy: approach in smaller
                        // steps, the last one short enough (its error grows like h^(5/2),
                        // F ~ (t_end - t)^(3/2))
                        let last = h * th * (0.5 * ratio.powf(-0.4)).clamp(0.05, 0.5);
                        end_plan = Some((t + th * h, last));
                        h = (th * h - last).min(h * step_factor(ratio).min(0.7));
                        ending = false;
                        last_miss = f64::INFINITY;
                        continue;
                    }
                    err_sum += out.err;
                    for i in 0..S {
                        peak.push(t + s.tab.c[i] * h, out.f[i]);
                    }
                    let pt = s.eval_seg(&seg, th, false);
                    v_end = pt.v;
                    t_end = t + th * h;
                    if let Some(hh) = hist.as_mut() {
                        hh.push(t_end, pt.d, pt.v, 0.0, 0.0);
                    }
                    break;
                }
                ending = true;
                // the step to the end located on this step's polynomial; bisection of the
                // bracket when that leaves it (the polynomials of a step that stops short and
                // of one that crosses the end can disagree on where it is, and the fit then
                // 2-cycles: seen with CoR near 1e-4, p2 below 1e-5, rtol 1e-2)
                let next = h * th;
                h = if end_hi.is_finite()
                    && !(next > end_lo + 1e-3 * (end_hi - end_lo)
                        && next < end_hi - 1e-3 * (end_hi - end_lo))
                {
                    0.5 * (end_lo + end_hi)
                } else {
                    next
                };
                continue;
            }
        }
        if !(ratio <= 1.0) {
            h = retry.next(h, ratio);
            ending = false;
            continue;
        }
        retry = Retry::default();
        // accept
        end_iter = 0;
        (end_lo, end_hi) = (0.0, f64::INFINITY);
        err_sum += out.err;
        for i in 0..S {
            peak.push(t + s.tab.c[i] * h, out.f[i]);
        }
        t1_hist = Some((t, h, out.t1));
        prev_rest = Some(seg);
        t += h;
        d = end.d;
        v = end.v;
        sk = end.s;
        f_n = out.f[S - 1];
        if let Some(hh) = hist.as_mut() {
            hh.push(t, d, v, f_n, out.a[S - 1]);
        }
        if !(d.is_finite() && v.is_finite()) {
            return Err(Error::NonFinite {
                what: "fast restitution state",
                value: d + v,
            });
        }
        let h_done = h;
        h *= step_factor(ratio);
        if end_plan.is_none() {
            // distance to the end of contact from g and dg/dt at the step end
            let mut dg = s.c_inf * v;
            for k in 0..s.k {
                dg += s.c[k] * (v - sk[k] / s.tau[k]);
            }
            if dg < 0.0 && g1 > 0.0 {
                let delta = -g1 / dg;
                // a prediction that moved later by more than the step just taken is not
                // a distance to the end: in the slow tail of a strongly dissipative rebound
                // the tangent of g meets zero far before the end, and that point moves on
                // with every step
                let receded = t + delta - end_predicted;
                end_predicted = t + delta;
                if delta < FAST_END_NEAR * h && receded <= FAST_END_RECEDE * h_done {
                    let (next, last) = end_approach(ratio.max(1e-3), h_done, delta);
                    h = next.min(h);
                    if last {
                        ending = true;
                    }
                }
            }
        }
        if let Some((te, last)) = end_plan {
            let rest = te - t;
            if rest <= 0.5 * last {
                end_plan = None; // the estimate was off: find the end anew
            } else if rest <= 1.2 * last {
                h = rest;
                ending = true;
            } else {
                h = h.min(rest - last);
            }
        }
    }
    let cor = -v_end;
    if !cor.is_finite() {
        return Err(Error::NonFinite {
            what: "fast coefficient of restitution",
            value: cor,
        });
    }
    // the verified driver refines the returned solve's maximum from here (Solver::refine_peak)
    s.peak_node = (peak.t_max <= s.t_m).then_some((peak.t_max, peak.f_max));
    let max_force = peak.max;
    Ok(Outcome {
        cor,
        rebound_velocity: cor,
        contact_time: t_end,
        max_indentation: d_m,
        time_of_max_indentation: t_m,
        max_force,
        max_contact_radius: s.shape.radius_at(d_m),
        dissipated_energy: 0.5 * (1.0 - cor * cor),
        cor_error_estimate: Some(err_sum / cor.abs().max(f64::MIN_POSITIVE)),
        history: hist,
        work: Work {
            steps,
            elements: 0,
            element_updates: 0,
            evaluations: s.evaluations,
            levels: 1,
            tight_checks: 0,
        },
        solver: Method::Fast,
        fallback: None,
    })
}

impl<const K: usize> Solver<K> {
    /// `w'` at a Ting root's `d(t_1)` (for a shape other than the paraboloid from the root's
    /// `a`, taken before its first-order move, when it has one).
    fn root_w_slope(&self, r: &Root) -> f64 {
        match self.shape.geom {
            Some(_) if r.a1 > 0.0 => 1.5 * r.a1,
            _ => self.shape.w_slope(r.d1),
        }
    }

    /// `a'` at a Ting root's `d(t_1)` (as [`Solver::root_w_slope`]).
    fn root_radius_slope(&self, r: &Root) -> f64 {
        if r.a1 > 0.0 {
            r.a1_slope
        } else {
            self.shape.radius_slope(r.d1)
        }
    }

    /// One restitution step of length `h`. `t1_guess`: guesses of `t_1` at the nodes;
    /// `omega`: when they come from the polynomial through the last step's nodes, its node
    /// polynomial `Π_j (θ - c_j)` at each node (`θ` in units of that step), to correct the
    /// guesses of the first pass node by node with the error found at the node before.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn rest_step(
        &mut self,
        t0: f64,
        dn: f64,
        vn: f64,
        s0: &[f64; K],
        h: f64,
        f_n: f64,
        t1_guess: &[f64; S],
        omega: Option<&[f64; S]>,
        pred: Option<&Seg<K>>,
        first: bool,
    ) -> Result<StepOut<K>> {
        let b = &self.tab.reg;
        let c = self.tab.c;
        let vh = vn * h;
        // the velocity scale of the step's tolerance (`rest_velocity_scale`, as in
        // `restitute` but without the energy floor) sets two absolute floors: the force error
        // of a Ting root taken from one Newton step (FAST_ROOT_STEP_LEVEL), and the scale of
        // the Newton stop, at least that velocity times the step length. Relative to the
        // curvature of d alone, as before, the stop asked far more than the step's tolerance
        // where the force is small (the slow tail of a strongly dissipative rebound):
        // measured 9% to 13% fewer evaluations at rtol 1e-6 on the external rows with CoR
        // below 0.1, the same maximum errors at every rtol
        let vel_scale = rest_velocity_scale(vn, f_n, dn);
        self.root_force_tol = FAST_ROOT_STEP_LEVEL * FAST_TOL_FACTOR * self.rtol * vel_scale / h;
        let newton_floor = vel_scale * h;
        let mut dfix = [0.0; S];
        for i in 0..S {
            dfix[i] = dn + vh * c[i];
        }
        // S_{k,i} = sfix_{k,i} + Σ_j L^k_{ij} α_j with the step's coefficients α = V_d^-1 (D - dfix)
        // (N^k = L^k V_d^-1 is never formed); keep C = Σ_k c_k N^k for the Jacobian
        let mut sfix = [[0.0; S]; K];
        let mut lc = [[0.0; S]; S];
        // built term by term (each entry written once: zeroing the whole table first cost
        // about 2 % of the instructions of a solve with 11 terms in the class of 16)
        let lk: [[[f64; S]; S]; K] = std::array::from_fn(|k| {
            let mut lk_k = [[0.0; S]; S];
            if k >= self.k {
                return lk_k;
            }
            let (jn, exn) = jt_lanes::<S>(
                Kind::Regular,
                &std::array::from_fn(|i| c[i] * h / self.tau[k]),
                self.series_tol(),
            );
            for i in 0..S {
                let jj = jn[i];
                sfix[k][i] = exn[i] * s0[k] + vh * c[i] * jj.one;
                for j in 0..S {
                    let l = dexp(Kind::Regular, j) * b.pd[i][j] * jj.d[j];
                    lk_k[i][j] = l;
                    lc[i][j] += self.c[k] * l;
                }
            }
            lk_k
        });
        let cn = linalg::mul(&lc, &b.vd_inv);
        let kk = self.k;
        // S_k at node i from the coefficients α of the step's polynomial
        let s_node = |alpha: &[f64; S], i: usize| {
            let mut si = [0.0; K];
            for k in 0..kk {
                let mut acc = sfix[k][i];
                for j in 0..S {
                    acc += lk[k][i][j] * alpha[j];
                }
                si[k] = acc;
            }
            si
        };
        let h2 = h * h;
        let mut z = predict_nodes(b, &c, t0, h, &dfix, f_n, pred);
        let mut t1 = *t1_guess;
        let mut f = [0.0; S];
        let mut d1 = [0.0; S];
        let mut roots = [Root::default(); S];
        let mut prev = f64::INFINITY;
        let mut converged = false;
        for it in 0..=FAST_NEWTON_MAX_ITER {
            let alpha = linalg::mul_vec(&b.vd_inv, &z);
            for i in 0..S {
                if let (0, Some(om)) = (it, omega) {
                    // the extrapolation error of the guesses grows like the node polynomial:
                    // move this guess by the error found at the node before, scaled by it
                    // (measured: 8% to 10% fewer evaluations at rtol 1e-6 for CoR below 0.1)
                    if i > 0 && om[i - 1] != 0.0 {
                        let miss = t1[i - 1] - t1_guess[i - 1];
                        t1[i] = (t1_guess[i] + miss * om[i] / om[i - 1]).clamp(0.0, self.t_m);
                    }
                }
                let si = s_node(&alpha, i);
                roots[i] = self.t1_root(t0 + c[i] * h, dfix[i] + z[i], &si, t1[i])?;
                t1[i] = roots[i].t1;
                f[i] = roots[i].f;
                d1[i] = roots[i].d1;
            }
            if converged || it == FAST_NEWTON_MAX_ITER {
                break;
            }
            let af = linalg::mul_vec(&b.a, &f);
            let mut r = [0.0; S];
            for i in 0..S {
                r[i] = -(z[i] + h2 * af[i]);
            }
            let mut jf = [[0.0; S]; S];
            for i in 0..S {
                if t1[i] > 0.0 {
                    let g = K16 * self.root_w_slope(&roots[i]);
                    for j in 0..S {
                        jf[i][j] = g * (cn[i][j] + if i == j { self.c_inf } else { 0.0 });
                    }
                }
            }
            let delta = newton_correction(
                &b.a_inv,
                &jf,
                h2,
                r,
                "fast restitution step (singular Newton matrix)",
            )?;
            let (dmax, scale) = update(&mut z, &delta);
            let scale = scale.max(newton_floor);
            if !dmax.is_finite() {
                break;
            }
            // move the guesses of t_1 with the correction to first order:
            // dΦ_i = ψ_i = Σ_j (c_inf δ_ij + Σ_k c_k N^k_ij) δ_j and dΦ/dt_1 = -d'(t_1) G_eq;
            // and the second-order remainder of the forces after this correction, node by
            // node. As a function of the shift ψ of Φ, the force at a node has
            // d²F/dψ² = (3/4) (16/3) / (sqrt(d(t_1)) G_eq(t - t_1)): in
            // F_ψψ = F_t1t1 / Φ_t1² - F_t1 Φ_t1t1 / Φ_t1³ (F_t1 = (16/3) w'(t_1) G_eq,
            // Φ_t1 = -d'(t_1) G_eq, w = d^(3/2)) the terms in d''(t_1) and dG_eq/dt_1 cancel,
            // and with them the 1/d'(t_1)² of a remainder taken in t_1 (which overstated it
            // 4x to several hundred x after the turn, where d'(t_1) -> 0). The next correction
            // is about h^2 |A| F_ψψ ψ^2 / 2.
            let df = linalg::mul_vec(&jf, &delta);
            let mut rem_f = [0.0; S];
            for i in 0..S {
                let r = &roots[i];
                if r.t1 <= 0.0 || r.v1 <= 0.0 || r.g <= 0.0 || r.d1 <= 0.0 {
                    continue; // past the end of contact, or t_1 held at t_m
                }
                let mut psi = self.c_inf * delta[i];
                for j in 0..S {
                    psi += cn[i][j] * delta[j];
                }
                t1[i] = r.t1 + psi / (r.v1 * r.g);
                rem_f[i] = match self.shape.geom {
                    None => 2.0 * psi * psi / (r.d1.sqrt() * r.g),
                    // d²F/dψ² = 8 a'(d(t_1)) / G_eq (the paraboloid's 4 / (sqrt(d) G_eq))
                    Some(_) => 4.0 * self.root_radius_slope(r) * psi * psi / r.g,
                };
            }
            let rem = rem_f.iter().fold(0.0, |acc: f64, &x| acc.max(x));
            converged = newton_done(dmax, scale, prev, self.rtol)
                || next_correction_done(h2 * b.a_norm * rem, scale, self.rtol)
                || next_correction_done(
                    remainder_correction(&b.a_inv, &jf, h2, &rem_f),
                    scale,
                    self.rtol,
                );
            prev = dmax;
            if converged {
                // the last correction is at the accuracy floor: move the forces to first order
                // instead of solving the Ting roots again (t_1, d(t_1) keep an O(delta) lag,
                // used only for guesses and the contact radius of the history)
                for i in 0..S {
                    f[i] += df[i];
                }
                break;
            }
        }
        if !converged {
            return Err(Error::NoConvergence {
                what: "fast restitution step (Newton)",
                iterations: FAST_NEWTON_MAX_ITER as u64,
            });
        }
        let rd = z;
        let seg = Seg {
            t0,
            h,
            kind: Kind::Regular,
            dn,
            vh,
            alpha: linalg::mul_vec(&b.vd_inv, &rd),
            wfix: 0.0,
            beta: [0.0; S],
            q0: [0.0; K],
            s0: *s0,
        };
        let ts = self.tab.theta_star;
        // guess for t_1 at the probe: the polynomial through the node values
        let g = interp_nodes(self.tab, &t1, ts).clamp(0.0, self.t_m);
        let mut err = h * self.rest_defect(&seg, ts, g)?;
        if first {
            // first restitution step: the Ting factor exp(-(t - t_1)/tau_k) with
            // t - t_1 ~ 2 (t - t_m) leaves a layer of width tau_k / 2 after t_m, which the probe
            // does not see when it lies before the second node (without this probe three of
            // 5000 random groups missed rtol 1e-8 / 1e-9 by up to 2x, all from this step)
            for k in 0..self.k {
                let th = 0.5 * self.tau[k] / h;
                if th < c[1] {
                    err += FAST_LAYER_WIDTH
                        * 0.5
                        * self.tau[k]
                        * self.rest_defect(&seg, th, t0 - th * h)?;
                }
            }
        }
        let mut a = [0.0; S];
        for i in 0..S {
            a[i] = self.shape.radius_at(d1[i]);
        }
        // step end from the last node (θ = 1)
        let mut end = Pt {
            d: dfix[S - 1] + z[S - 1],
            v: seg_poly_at(&seg, 1.0).1 / h,
            dd: 0.0,
            w: 0.0,
            q: [0.0; K],
            s: [0.0; K],
        };
        end.s = s_node(&seg.alpha, S - 1);
        Ok(StepOut {
            seg,
            f,
            t1,
            a,
            err,
            end,
        })
    }

    /// Defect `|d'' + F|` of a restitution step's polynomial at `θ` (`guess`: of `t_1` there).
    pub(super) fn rest_defect(&mut self, seg: &Seg<K>, th: f64, guess: f64) -> Result<f64> {
        let pt = self.eval_seg(seg, th, false);
        let f = self.t1_root(seg.t0 + th * seg.h, pt.d, &pt.s, guess)?.f;
        Ok((pt.dd + f).abs())
    }
}

impl<const K: usize> Solver<K> {
    /// The largest compression force near the node time `t0` (the largest node force): the
    /// dense compression force (`q_k` from the exact kernels, `w` at the dense depth) maximised
    /// over the neighbouring steps by successive parabolic interpolation in a bracket (a golden
    /// section where the parabola leaves it), to a time within 1e-6 of the bracket (the force is
    /// smooth there and its error quadratic in the time: below 1e-11 relative). About eight
    /// dense evaluations; the parabola through three node forces that it replaces was off by up
    /// to 7e-6 relative at rtol 1e-8.
    pub(super) fn refine_peak(&mut self, t0: f64) -> f64 {
        let n = self.comp.len();
        let j = self.comp.partition_point(|g| g.t0 <= t0).max(1) - 1;
        let lo = if j > 0 { self.comp[j - 1].t0 } else { 0.0 };
        let hi = if j + 1 < n {
            self.comp[j + 1].t0 + self.comp[j + 1].h
        } else {
            self.t_m
        }
        .min(self.t_m);
        let mut force = |t: f64| {
            let pt = self.comp_at(t);
            self.force_comp(&pt)
        };
        let width = hi - lo;
        let golden = 0.5 * (3.0 - 5f64.sqrt());
        let (mut a, mut b, mut m) = (lo, hi, t0.clamp(lo, hi));
        let (mut fa, mut fb, mut fm) = (force(a), force(b), force(m));
        if !(m > a && m < b) {
            // the node sits at an end of the window (the turn): start from its interior
            m = if m >= b {
                b - golden * (b - a)
            } else {
                a + golden * (b - a)
            };
            fm = force(m);
        }
        if !(fm >= fa && fm >= fb) {
            // no interior point above both ends: a golden section over the window (the maximum
            // may still be interior, or sit at an end)
            let (mut x1, mut x2) = (b - (1.0 - golden) * (b - a), a + (1.0 - golden) * (b - a));
            let (mut f1, mut f2) = (force(x1), force(x2));
            for _ in 0..60 {
                if b - a <= 1e-7 * width {
                    break;
                }
                if f1 < f2 {
                    (a, x1, f1) = (x1, x2, f2);
                    x2 = a + (1.0 - golden) * (b - a);
                    f2 = force(x2);
                } else {
                    (b, x2, f2) = (x2, x1, f1);
                    x1 = b - (1.0 - golden) * (b - a);
                    f1 = force(x1);
                }
            }
            return f1.max(f2).max(fa).max(fb).max(fm);
        }
        for _ in 0..40 {
            let (p, q) = ((m - a) * (fm - fb), (m - b) * (fm - fa));
            let den = p - q;
            let mut x = if den != 0.0 {
                m - 0.5 * ((m - a) * p - (m - b) * q) / den
            } else {
                f64::NAN
            };
            if !(x > a && x < b) || (x - m).abs() < 1e-9 * width {
                // a golden step into the larger side
                x = if m - a > b - m {
                    m - golden * (m - a)
                } else {
                    m + golden * (b - m)
                };
            }
            let fx = force(x);
            let step = (x - m).abs();
            if fx > fm {
                if x < m {
                    (b, fb) = (m, fm);
                } else {
                    (a, fa) = (m, fm);
                }
                (m, fm) = (x, fx);
            } else if x < m {
                (a, fa) = (x, fx);
            } else {
                (b, fb) = (x, fx);
            }
            if step <= 1e-6 * width || b - a <= 1e-6 * width {
                break;
            }
        }
        fm
    }
}
