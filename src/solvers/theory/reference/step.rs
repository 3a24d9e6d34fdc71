//! One step of the exponential Radau IIA collocation (compression: Lee–Radok; restitution:
//! Ting's root for the contact radius), the dense record, and the force at any time from it.

use super::*;

impl<'a> Solver<'a> {
    pub(super) fn new(prony: &'a Prony, geom: Geometry) -> Result<Self> {
        Ok(Self {
            prony,
            geom,
            coll: Coll::new()?,
            records: Vec::new(),
            t_m: 0.0,
            evals: 0,
        })
    }

    /// `U[k][i][m] = m c_i^m e_{m-1}(c_i h / tau_k)` for `m = 1..=s+1` (index `m-1`), and
    /// `E[k][i] = exp(-c_i h / tau_k)`.
    pub(super) fn weights(&self, h: f64) -> (Vec<[[f64; S + 1]; S]>, Vec<[f64; S]>) {
        let kk = self.prony.terms.len();
        let mut u = vec![[[0.0; S + 1]; S]; kk];
        let mut e = vec![[0.0; S]; kk];
        for (k, p) in self.prony.terms.iter().enumerate() {
            for i in 0..S {
                let z = NODES[i] * h / p.tau;
                let mut mo = [0.0; S + 1];
                exp_moments(z, &mut mo);
                for m in 1..=S + 1 {
                    u[k][i][m - 1] = m as f64 * NODES[i].powi(m as i32) * mo[m - 1];
                }
                e[k][i] = (-z).exp();
            }
        }
        (u, e)
    }

    /// Evaluate the compression record at `t1` in `[0, t_m]`.
    pub(super) fn dense(&self, t1: f64) -> Dense {
        let j = match self.records.binary_search_by(|r| r.t0.total_cmp(&t1)) {
            Ok(j) => j,
            Err(0) => 0,
            Err(j) => j - 1,
        };
        self.eval_record(&self.records[j], t1)
    }

    /// `d, d', q_k, S_k` at `t1` inside the step of record `r` (`q_k` meaningful for compression
    /// records only).
    pub(super) fn eval_record(&self, r: &Record, t1: f64) -> Dense {
        let th = ((t1 - r.t0) / r.h).clamp(0.0, 1.0);
        let mut d = 0.0;
        let mut dv = 0.0;
        let mut p = 1.0;
        for m in 0..NB {
            d += r.b[m] * p;
            if m + 1 < NB {
                dv += (m + 1) as f64 * r.b[m + 1] * p;
            }
            p *= th;
        }
        dv /= r.h;
        let kk = self.prony.terms.len();
        let mut q = vec![0.0; kk];
        let mut s = vec![0.0; kk];
        for (k, pt) in self.prony.terms.iter().enumerate() {
            let z = th * r.h / pt.tau;
            let mut mo = [0.0; S + 1];
            exp_moments(z, &mut mo);
            let ez = (-z).exp();
            let mut qs = ez * r.q0[k];
            let mut ss = ez * r.s0[k];
            let mut thm = 1.0;
            for m in 1..=S + 1 {
                thm *= th;
                let w = m as f64 * thm * mo[m - 1];
                ss += r.b[m] * w;
                if m <= S {
                    qs += r.a[m] * w;
                }
            }
            q[k] = qs;
            s[k] = ss;
        }
        Dense { d, dv, q, s }
    }

    /// Ting's root `t_1` at time `t` with current `d(t)`, `S_k(t)`; returns `(t1, d(t1), F)`.
    pub(super) fn ting(&self, t: f64, d: f64, s: &[f64], guess: f64) -> Result<(f64, f64, f64)> {
        let pr = self.prony;
        let psi = pr.relaxed * d
            + pr.terms
                .iter()
                .zip(s)
                .map(|(p, sk)| p.coefficient * sk)
                .sum::<f64>();
        if psi <= 0.0 {
            return Ok((0.0, 0.0, 0.0));
        }
        let tm = self.t_m;
        let phi_at = |t1: f64| -> (f64, f64) {
            let de = self.dense(t1);
            let mut val = pr.relaxed * (d - de.d);
            let mut g = pr.relaxed;
            for (k, p) in pr.terms.iter().enumerate() {
                let ex = (-(t - t1) / p.tau).exp();
                val += p.coefficient * (s[k] - ex * de.s[k]);
                g += p.coefficient * ex;
            }
            (val, -de.dv * g)
        };
        let (fm, _) = phi_at(tm);
        let t1 = if fm >= 0.0 {
            tm
        } else {
            // Phi(0) = psi > 0 and Phi(t_m) = fm < 0 are known: no need to re-evaluate them.
            newton_bracketed_with(
                "Ting t1 (reference impact)",
                |x| Ok(phi_at(x)),
                (0.0, psi),
                (tm, fm),
                Some(guess.clamp(0.0, tm)),
                1e-16 * tm,
            )?
        };
        let de = self.dense(t1);
        let mut f = pr.relaxed * self.geom.force_function(de.d);
        for (k, p) in pr.terms.iter().enumerate() {
            f += p.coefficient * (-(t - t1) / p.tau).exp() * de.q[k];
        }
        Ok((t1, de.d, 16.0 / 3.0 * f))
    }

    /// One collocation step of length `h` from `st`.
    pub(super) fn step(&mut self, phase: Phase, st: &State, h: f64) -> Result<StepOut> {
        let pr = self.prony;
        let kk = pr.terms.len();
        let (u, e) = self.weights(h);
        let c = NODES;
        // predictor: Taylor with the last force
        // Unknowns: y_i = d(t_n + c_i h) - d_n - h v_n c_i = O(h^2 F), so that short steps keep
        // their precision (the node depths themselves would lose the h^2 part to rounding).
        let mut y = Vs::zeros();
        for i in 0..S {
            let x = c[i] * h;
            y[i] = -0.5 * st.force * x * x;
        }
        let mut dn = [0.0; S];
        let phi0 = self.geom.force_function(st.d);
        // W[k][i][j], j = 0..=S: weights of phi_j in q_k(t_i)
        let mut w = vec![[[0.0; S + 1]; S]; kk];
        // V[k][i][j], j = 0..S: dS_k(t_i)/dD_j
        let mut vw = vec![[[0.0; S]; S]; kk];
        for k in 0..kk {
            for i in 0..S {
                for j in 0..=S {
                    let mut acc = 0.0;
                    for m in 1..=S {
                        acc += u[k][i][m - 1] * self.coll.linv[(m, j)];
                    }
                    w[k][i][j] = acc;
                }
                for j in 0..S {
                    let mut acc = 0.0;
                    for m in 2..=S + 1 {
                        acc += u[k][i][m - 1] * self.coll.minv[(m - 2, j)];
                    }
                    vw[k][i][j] = acc;
                }
            }
        }
        let mut t1_guess = [st.t1; S];
        let mut force = [0.0; S];
        let mut t1s = [0.0; S];
        let mut bcoef = [0.0; NB];
        let mut prev_dx = f64::INFINITY;
        let mut converged = false;
        let mut sk_nodes = vec![[0.0; S]; kk];
        for _ in 0..REF_MAX_NEWTON {
            // polynomial coefficients
            for i in 0..S {
                dn[i] = st.d + h * st.v * c[i] + y[i];
            }
            let rhs = y;
            let bm = self.coll.minv * rhs;
            bcoef[0] = st.d;
            bcoef[1] = h * st.v;
            for m in 0..S {
                bcoef[m + 2] = bm[m];
            }
            let acc = self.coll.a2 * rhs / (h * h);
            // S_k at the nodes
            for k in 0..kk {
                for i in 0..S {
                    let mut sv = e[k][i] * st.s[k] + u[k][i][0] * bcoef[1];
                    for m in 2..=S + 1 {
                        sv += u[k][i][m - 1] * bcoef[m];
                    }
                    sk_nodes[k][i] = sv;
                }
            }
            let mut jac = Mat::zeros();
            let mut res = Vs::zeros();
            match phase {
                Phase::Compression | Phase::FlatRelease => {
                    let mut phi = [0.0; S + 1];
                    phi[0] = phi0;
                    for j in 0..S {
                        phi[j + 1] = self.geom.force_function(dn[j]);
                    }
                    for i in 0..S {
                        let mut f = pr.relaxed * phi[i + 1];
                        for k in 0..kk {
                            let mut qv = e[k][i] * st.q[k];
                            for j in 0..=S {
                                qv += w[k][i][j] * phi[j];
                            }
                            f += pr.terms[k].coefficient * qv;
                        }
                        force[i] = 16.0 / 3.0 * f;
                        t1s[i] = st.t + c[i] * h;
                        for j in 0..S {
                            let mut g = if i == j { pr.relaxed } else { 0.0 };
                            for k in 0..kk {
                                g += pr.terms[k].coefficient * w[k][i][j + 1];
                            }
                            jac[(i, j)] = 8.0 * self.geom.contact_radius(dn[j]) * g;
                        }
                    }
                }
                Phase::Restitution => {
                    for i in 0..S {
                        let ti = st.t + c[i] * h;
                        let sk: Vec<f64> = (0..kk).map(|k| sk_nodes[k][i]).collect();
                        let (t1, d1, f) = self.ting(ti, dn[i], &sk, t1_guess[i])?;
                        t1_guess[i] = t1;
                        t1s[i] = t1;
                        force[i] = f;
                        if t1 > 0.0 {
                            let sq = 8.0 * self.geom.contact_radius(d1);
                            for j in 0..S {
                                let mut g = if i == j { pr.relaxed } else { 0.0 };
                                for k in 0..kk {
                                    g += pr.terms[k].coefficient * vw[k][i][j];
                                }
                                jac[(i, j)] = sq * g;
                            }
                        }
                    }
                }
            }
            self.evals += S as u64;
            for i in 0..S {
                res[i] = acc[i] + force[i];
            }
            let jfull = self.coll.a2 / (h * h) + jac;
            let dx = jfull.lu().solve(&res).ok_or(Error::NonFinite {
                what: "collocation Jacobian (singular)",
                value: f64::NAN,
            })?;
            y -= dx;
            let n = dx.amax();
            let scale = st.d.abs().max(h * st.v.abs()).max(1e-300);
            if !n.is_finite() {
                return Err(Error::NonFinite {
                    what: "collocation Newton update",
                    value: n,
                });
            }
            if n <= REF_NEWTON_TOL * scale || (n <= 1e-14 * scale && n > 0.5 * prev_dx) {
                converged = true;
                break;
            }
            prev_dx = n;
        }
        if !converged {
            return Err(Error::NoConvergence {
                what: "collocation Newton (reference impact)",
                iterations: REF_MAX_NEWTON,
            });
        }
        // final polynomial and end state from the converged node values
        for i in 0..S {
            dn[i] = st.d + h * st.v * c[i] + y[i];
        }
        let bm = self.coll.minv * y;
        for m in 0..S {
            bcoef[m + 2] = bm[m];
        }
        let mut vend = 0.0;
        for m in 1..NB {
            vend += m as f64 * bcoef[m];
        }
        vend /= h;
        let mut phi = [0.0; S + 1];
        phi[0] = phi0;
        for j in 0..S {
            phi[j + 1] = self.geom.force_function(dn[j]);
        }
        let av = self.coll.linv * SVector::<f64, { S + 1 }>::from_column_slice(&phi);
        let mut a = [0.0; S + 1];
        a.copy_from_slice(av.as_slice());
        let mut qe = vec![0.0; kk];
        let mut se = vec![0.0; kk];
        for k in 0..kk {
            let mut qv = e[k][S - 1] * st.q[k];
            for j in 0..=S {
                qv += w[k][S - 1][j] * phi[j];
            }
            qe[k] = qv;
            let mut sv = e[k][S - 1] * st.s[k] + u[k][S - 1][0] * bcoef[1];
            for m in 2..=S + 1 {
                sv += u[k][S - 1][m - 1] * bcoef[m];
            }
            se[k] = sv;
        }
        let mut nodes = [(0.0, 0.0); S];
        for i in 0..S {
            nodes[i] = (st.t + c[i] * h, force[i]);
        }
        Ok(StepOut {
            end: State {
                t: st.t + h,
                d: st.d + h * st.v + y[S - 1],
                v: vend,
                q: qe,
                s: se,
                force: force[S - 1],
                t1: t1s[S - 1],
            },
            rec: Record {
                t0: st.t,
                h,
                b: bcoef,
                a,
                q0: st.q.clone(),
                s0: st.s.clone(),
            },
            nodes,
        })
    }

    /// Two half steps and one full step; returns the half-step results and the error ratio.
    pub(super) fn doubled(
        &mut self,
        phase: Phase,
        st: &State,
        h: f64,
        tol: f64,
    ) -> Result<(StepOut, StepOut, f64)> {
        let full = self.step(phase, st, h)?;
        let first = self.step(phase, st, 0.5 * h)?;
        let second = self.step(phase, &first.end, 0.5 * h)?;
        let err = (full.end.d - second.end.d)
            .abs()
            .max((full.end.v - second.end.v).abs())
            / tol;
        Ok((first, second, err))
    }

    /// Compression force `(16/3)(c_inf w(d) + sum_k c_k q_k)` at `t <= t_m` from the record.
    pub(super) fn compression_force(&self, t: f64) -> f64 {
        let de = self.dense(t);
        let mut f = self.prony.relaxed * self.geom.force_function(de.d);
        for (k, p) in self.prony.terms.iter().enumerate() {
            f += p.coefficient * de.q[k];
        }
        16.0 / 3.0 * f
    }

    /// Maximum of the compression force near the node time `t0` (golden-section search on the
    /// dense record over the neighbouring steps; the force is smooth and unimodal there).
    pub(super) fn refine_max_force(&self, t0: f64) -> f64 {
        let j = self.records.partition_point(|r| r.t0 <= t0).max(1) - 1;
        let lo = if j > 0 { self.records[j - 1].t0 } else { 0.0 };
        let hi = self
            .records
            .get(j + 1)
            .map_or(self.t_m, |r| r.t0 + r.h)
            .min(self.t_m);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let (mut a, mut b) = (lo, hi);
        let mut x1 = b - g * (b - a);
        let mut x2 = a + g * (b - a);
        let (mut f1, mut f2) = (self.compression_force(x1), self.compression_force(x2));
        for _ in 0..80 {
            if f1 < f2 {
                a = x1;
                x1 = x2;
                f1 = f2;
                x2 = a + g * (b - a);
                f2 = self.compression_force(x2);
            } else {
                b = x2;
                x2 = x1;
                f2 = f1;
                x1 = b - g * (b - a);
                f1 = self.compression_force(x1);
            }
            if b - a <= 1e-12 * hi {
                break;
            }
        }
        f1.max(f2)
    }

    pub(super) fn psi(&self, st: &State) -> f64 {
        self.prony.relaxed * st.d
            + self
                .prony
                .terms
                .iter()
                .zip(&st.s)
                .map(|(p, s)| p.coefficient * s)
                .sum::<f64>()
    }
}
