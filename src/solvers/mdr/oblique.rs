//! The MDR's tangential foundation (docs/theory.md §14): oblique impacts with Coulomb friction,
//! partial slip and spin, on top of the normal foundation and never changing it.
//!
//! Every element of the normal foundation in contact also carries a tangential spring of the
//! tangential relaxation function `G_t / 4` (Prony, canonical) with its own displacement `w_i`
//! and hereditary variables. The impactor's contact point moves tangentially by `u`; over a
//! step an element sticks (`dw_i = du`) while its end-of-step force `|q_i|` stays within
//! `mu f_i`, with `f_i` its own end-of-step normal force from the normal foundation (the
//! viscoelastic one included), and otherwise slides with `q_i = +-mu f_i` (the return map: the
//! element's increment follows from its affine force law). Elements enter with no tangential
//! history and leave with the normal foundation (their normal force returns to zero, so their
//! tangential force has already gone). The slip velocity obeys `v_c' = -lambda Q` (canonical,
//! `lambda` the tangential compliance of [`crate::model::oblique`]) by the trapezoidal rule,
//! `Q = 8 dx sum_i w_i q_i`; the end-of-step `Q` is a continuous, non-decreasing, piecewise
//! linear function of the step's `du`, and its root is found exactly by a safeguarded Newton
//! iteration on the pieces.
//!
//! The normal problem does not see the tangential one (Goodman's uncoupling), so the normal
//! outcome of an oblique run equals that of the normal run on the same grid, bit for bit.

use super::*;
use crate::model::oblique::Tangential;

/// The tangential state over the elements in contact (canonical units).
#[derive(Debug, Clone)]
pub(crate) struct TangentialFoundation {
    c_inf: f64,
    coef: Vec<f64>,
    tau: Vec<f64>,
    decay: Vec<f64>,
    beta: Vec<f64>,
    dt: f64,
    mu: f64,
    lambda: f64,
    /// Per element: tangential displacement `w`, force `q` (per `8 dx` and relative width),
    /// hereditary variables (stride `K`).
    w: Vec<f64>,
    q: Vec<f64>,
    h: Vec<f64>,
    /// Scratch: normal forces, start-of-step affine parts.
    f_n: Vec<f64>,
    a: Vec<f64>,
    /// Slip velocity, total tangential force, impulse and friction work.
    pub(crate) v: f64,
    pub(crate) force: f64,
    pub(crate) impulse: f64,
    pub(crate) friction_work: f64,
    /// Elapsed time and the inner radius of the slip zone at the end of the last step.
    pub(crate) t: f64,
    pub(crate) slip_radius: f64,
    pub(crate) history: Option<Vec<[f64; 4]>>,
}

impl TangentialFoundation {
    pub(crate) fn new(tangential: &Tangential, history: bool) -> Self {
        let g = &tangential.g_t;
        let k = g.terms.len();
        Self {
            c_inf: g.relaxed,
            coef: g.terms.iter().map(|p| p.coefficient).collect(),
            tau: g.terms.iter().map(|p| p.tau).collect(),
            decay: vec![1.0; k],
            beta: vec![0.0; k],
            dt: 0.0,
            mu: tangential.friction,
            lambda: tangential.compliance,
            w: Vec::new(),
            q: Vec::new(),
            h: Vec::new(),
            f_n: Vec::new(),
            a: Vec::new(),
            v: tangential.slip_velocity,
            force: 0.0,
            impulse: 0.0,
            friction_work: 0.0,
            t: 0.0,
            slip_radius: 0.0,
            history: history.then(|| vec![[0.0, 0.0, 0.0, tangential.slip_velocity]]),
        }
    }

    fn set_step(&mut self, dt: f64) {
        if dt != self.dt {
            self.dt = dt;
            for k in 0..self.tau.len() {
                let x = dt / self.tau[k];
                self.decay[k] = (-x).exp();
                self.beta[k] = -self.tau[k] * (-x).exp_m1();
            }
        }
    }

    /// End-of-step total force (per `8 dx`) and its slope for the increment `du`.
    fn total(&self, du: f64, b: f64, geom: &Foundation) -> (f64, f64) {
        let (mut q, mut dq) = (0.0, 0.0);
        for i in 0..self.w.len() {
            let lim = self.mu * self.f_n[i];
            let trial = self.a[i] + b * du;
            let om = geom.rel_weight(i);
            if trial > lim {
                q += om * lim;
            } else if trial < -lim {
                q -= om * lim;
            } else {
                q += om * trial;
                dq += om * b;
            }
        }
        (q, dq)
    }

    /// One step of size `dt` after the normal foundation `f` reached depth `d`.
    pub(crate) fn step<F: Stepper>(&mut self, f: &F, dt: f64, d: f64) -> Result<()> {
        let geom = *f.geometry();
        let n = f.in_contact();
        let k_n = self.coef.len();
        self.w.resize(n, 0.0);
        self.q.resize(n, 0.0);
        self.h.resize(n * k_n, 0.0);
        self.f_n.clear();
        self.a.clear();
        self.set_step(dt);
        let mut b = self.c_inf;
        for k in 0..k_n {
            b += self.coef[k] * self.beta[k] / dt;
        }
        for i in 0..n {
            self.f_n.push(f.element_force(i, d).max(0.0));
            let mut a = self.c_inf * self.w[i];
            for k in 0..k_n {
                a += self.coef[k] * self.decay[k] * self.h[i * k_n + k];
            }
            self.a.push(a);
        }
        // du + c Q(du) = rhs, c = lambda dt^2 / 4, Q = W total(du)
        let w8 = geom.weight();
        let c = self.lambda * dt * dt / 4.0;
        let rhs = dt * self.v - c * self.force;
        let cap: f64 = (0..n)
            .map(|i| geom.rel_weight(i) * self.mu * self.f_n[i])
            .sum::<f64>()
            * w8;
        let (mut lo, mut hi) = (rhs - c * cap, rhs + c * cap);
        let phi = |du: f64| {
            let (q, dq) = self.total(du, b, &geom);
            (du + c * w8 * q - rhs, 1.0 + c * w8 * dq)
        };
        let mut du = rhs.clamp(lo, hi);
        let mut converged = false;
        for _ in 0..tolerances::ROOT_MAX_ITER {
            let (p, dp) = phi(du);
            if p == 0.0 {
                converged = true;
                break;
            }
            if p > 0.0 {
                hi = du;
            } else {
                lo = du;
            }
            let mut next = du - p / dp;
            if !(next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
            if (next - du).abs() <= 4.0 * f64::EPSILON * du.abs().max(rhs.abs()).max(1e-300)
                || hi - lo <= 4.0 * f64::EPSILON * hi.abs().max(lo.abs())
            {
                du = next;
                converged = true;
                break;
            }
            du = next;
        }
        if !converged {
            return Err(Error::NoConvergence {
                what: "mdr tangential step (stick/slip of the elements)",
                iterations: tolerances::ROOT_MAX_ITER as u64,
            });
        }
        // commit: return map per element
        let mut total = 0.0;
        let mut work = 0.0;
        let mut first_slip = None;
        for i in 0..n {
            let lim = self.mu * self.f_n[i];
            let trial = self.a[i] + b * du;
            let (q, dw) = if trial.abs() <= lim {
                (trial, du)
            } else {
                let q = lim.copysign(trial);
                (q, (q - self.a[i]) / b)
            };
            let om = geom.rel_weight(i);
            if dw != du {
                first_slip.get_or_insert(i);
                work += om * 0.5 * (q + self.q[i]) * (du - dw);
            }
            for k in 0..k_n {
                let h = &mut self.h[i * k_n + k];
                *h = self.decay[k] * *h + self.beta[k] * dw / dt;
            }
            self.w[i] += dw;
            self.q[i] = q;
            total += om * q;
        }
        let q1 = w8 * total;
        self.friction_work += w8 * work;
        self.impulse += 0.5 * dt * (self.force + q1);
        self.v -= self.lambda * 0.5 * dt * (self.force + q1);
        self.force = q1;
        self.t += dt;
        self.slip_radius = geom.radius_of(first_slip.unwrap_or(n));
        if let Some(h) = self.history.as_mut() {
            h.push([self.t, self.force, self.slip_radius, self.v]);
        }
        if !(self.v.is_finite() && self.force.is_finite()) {
            return Err(Error::NonFinite {
                what: "mdr tangential state",
                value: self.v + self.force,
            });
        }
        Ok(())
    }
}

/// The canonical result of an oblique MDR run: the normal outcome and the tangential state at
/// separation.
#[derive(Debug, Clone)]
pub struct ObliqueRun {
    /// The normal outcome (canonical), identical to the normal run on the same grid.
    pub normal: Outcome,
    /// Tangential impulse `J` (units `m v0`).
    pub impulse: f64,
    /// Friction work (units `m v0^2`).
    pub friction_work: f64,
    /// Slip velocity after the impact (units `v0`).
    pub slip_velocity: f64,
    /// Rows `[t, Q, slip radius, v_c]` (canonical) when a history was requested.
    pub history: Option<Vec<[f64; 4]>>,
    /// Elements per contact radius and steps per contact time of the run.
    pub resolution: (usize, usize),
    /// Estimated absolute error of `v_c' / v_c` (adaptive runs).
    pub error_estimate: Option<f64>,
}

/// One oblique run of the exponential scheme on a fixed resolution from `layout`.
pub fn run_oblique(
    material: &CanonicalMaterial,
    tangential: &Tangential,
    layout: &Layout,
    elements: usize,
    steps: usize,
    history: bool,
) -> Result<ObliqueRun> {
    let grid = Grid::from_layout(layout, elements, steps);
    let capacity = capacity_for(grid.dx, layout.contact_radius);
    let g = &material.geometry;
    let geom = Foundation::new(grid.dx, g, capacity);
    let mut tf = TangentialFoundation::new(tangential, history);
    let normal = match &material.network {
        Network::General(net) => run_stepper(
            NetFoundation::new(geom, net.clone()),
            &grid,
            capacity,
            history,
            &mut |f, dt, d| tf.step(f, dt, d),
        )?,
        Network::Stacked(net) => run_stepper(
            NetFoundation::new(geom, net.clone()),
            &grid,
            capacity,
            history,
            &mut |f, dt, d| tf.step(f, dt, d),
        )?,
        Network::StandardSolid(_) => run_stepper(
            ExpFoundation::new(geom, &material.prony),
            &grid,
            capacity,
            history,
            &mut |f, dt, d| tf.step(f, dt, d),
        )?,
    };
    Ok(ObliqueRun {
        normal,
        impulse: tf.impulse,
        friction_work: tf.friction_work,
        slip_velocity: tf.v,
        history: tf.history,
        resolution: (elements, steps),
        error_estimate: None,
    })
}

/// Solve an oblique impact with `mdr` to `rtol`: levels doubling the elements and the steps
/// from the normal driver's start, accepted when the normal CoR passes the normal driver's
/// test (relative, `rtol`) and `v_c' / v_c` passes the same test in absolute terms (it crosses
/// zero) at `max(rtol, OBLIQUE_TANGENTIAL_ATOL)` with first order assumed.
/// With an explicit resolution, one run on it.
pub fn solve_oblique(
    material: &CanonicalMaterial,
    tangential: &Tangential,
    rtol: f64,
    resolution: Option<(usize, usize)>,
    history: bool,
    work_limit: u64,
) -> Result<ObliqueRun> {
    let layout = pilot_material(material)?;
    if let Some((n, m)) = resolution {
        return run_oblique(material, tangential, &layout, n, m, history);
    }
    let (mut n, mut m) = (tolerances::MDR_START_ELEMENTS, tolerances::MDR_START_STEPS);
    let vc0 = tangential.slip_velocity;
    let scale_t = if vc0 == 0.0 { 1.0 } else { vc0.abs() };
    let (mut prev, mut dn, mut dt) = (None::<(f64, f64)>, Vec::new(), Vec::new());
    let mut work = Work::default();
    let mut last_estimate = f64::INFINITY;
    for level in 0..tolerances::MDR_MAX_LEVELS {
        let predicted =
            (capacity_for(layout.contact_radius / n as f64, layout.contact_radius) as u64 / 4)
                .saturating_mul(2 * m as u64 + 16);
        if work.element_updates.saturating_add(predicted) > work_limit {
            return Err(Error::AccuracyNotReached {
                solver: "mdr",
                rtol,
                estimate: last_estimate,
                required: tolerances::MDR_SAFETY * rtol,
                levels: level,
            });
        }
        let mut o = run_oblique(material, tangential, &layout, n, m, history)?;
        work.steps += o.normal.work.steps;
        work.element_updates += 2 * o.normal.work.element_updates;
        work.elements = work.elements.max(o.normal.work.elements);
        work.levels = level + 1;
        let tcor = o.slip_velocity / scale_t;
        if let Some((pn, pt)) = prev {
            dn.push(o.normal.cor - pn);
            dt.push(tcor - pt);
            let sn = o.normal.cor.abs().max(1e-300);
            let en = accept(&dn, 2.0, rtol * sn).map(|e| e / sn);
            let atol = rtol.max(tolerances::OBLIQUE_TANGENTIAL_ATOL);
            let et = accept(&dt, 1.0, atol);
            if let (Some(en), Some(et)) = (en, et) {
                last_estimate = (en / rtol).max(et / atol) * rtol;
                if en <= tolerances::MDR_SAFETY * rtol && et <= tolerances::MDR_SAFETY * atol {
                    o.normal.work = work;
                    o.normal.cor_error_estimate = Some(en);
                    o.error_estimate = Some(et);
                    return Ok(o);
                }
            }
        }
        prev = Some((o.normal.cor, tcor));
        (n, m) = (2 * n, 2 * m);
    }
    Err(Error::AccuracyNotReached {
        solver: "mdr",
        rtol,
        estimate: last_estimate,
        required: tolerances::MDR_SAFETY * rtol,
        levels: tolerances::MDR_MAX_LEVELS,
    })
}
