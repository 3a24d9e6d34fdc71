//! The `mdr` time scheme: MDR foundation with the exact exponential update of each element's
//! internal variables for an indentation that is linear over the step, and the trapezoidal rule
//! (A-stable, second order) for the sphere.
//!
//! Each element in contact carries `u_i = d - g_i` and, per Prony term `k` of `G_eq`, the
//! hereditary variable `h_ki(t) = int exp(-(t-t')/tau_k) u_i'(t') dt'` since its entry; its force
//! (both sides of the symmetric foundation, `8 dx`) is
//! `f_i = 8 dx (c_inf u_i + sum_k c_k h_ki)`. For `d` linear over `[t_n, t_n + dt]` with rate
//! `r`, `h_ki <- E_k h_ki + beta_k r`, `E_k = exp(-dt/tau_k)`, `beta_k = tau_k (1 - E_k)`,
//! exactly, whatever `dt / tau_k`: no stiffness limit.

use super::Foundation;
use crate::model::material::Prony;

/// Element states of the exponential scheme.
#[derive(Debug, Clone)]
pub(crate) struct ExpFoundation {
    geom: Foundation,
    c_inf: f64,
    coef: Vec<f64>,
    tau: Vec<f64>,
    /// `E_k` and `beta_k` for the current step size.
    decay: Vec<f64>,
    beta: Vec<f64>,
    dt: f64,
    /// Hereditary variables, element-major with stride `K`.
    h: Vec<f64>,
    /// Elements in contact: `0..n`.
    n: usize,
    /// `sum_i h_ki` over the contact set, per term.
    sum_h: Vec<f64>,
    /// `sum_i w_i g_i` over the contact set (`w_i` the cells' relative widths,
    /// [`Foundation::rel_weight`]; `sum_h` is weighted the same way).
    sum_g: f64,
    /// `sum_i w_i` over the contact set (the element count on a uniform grid).
    wsum: f64,
    /// Counters.
    pub(crate) element_updates: u64,
    pub(crate) max_elements: usize,
}

/// Affine model of the end-of-step force over the fixed contact set: `F(r) = a + b r`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Affine {
    pub a: f64,
    pub b: f64,
}

impl ExpFoundation {
    pub(crate) fn new(geom: Foundation, prony: &Prony) -> Self {
        let k = prony.terms.len();
        Self {
            geom,
            c_inf: prony.relaxed,
            coef: prony.terms.iter().map(|p| p.coefficient).collect(),
            tau: prony.terms.iter().map(|p| p.tau).collect(),
            decay: vec![1.0; k],
            beta: vec![0.0; k],
            dt: 0.0,
            h: Vec::new(),
            n: 0,
            sum_h: vec![0.0; k],
            sum_g: 0.0,
            wsum: 0.0,
            element_updates: 0,
            max_elements: 0,
        }
    }

    pub(crate) fn in_contact(&self) -> usize {
        self.n
    }

    pub(crate) fn geometry(&self) -> &Foundation {
        &self.geom
    }

    /// Set the step size (recomputes the exponential factors when it changes).
    pub(crate) fn set_step(&mut self, dt: f64) {
        if dt != self.dt {
            self.dt = dt;
            for k in 0..self.tau.len() {
                let x = dt / self.tau[k];
                self.decay[k] = (-x).exp();
                self.beta[k] = -self.tau[k] * (-x).exp_m1();
            }
        }
    }

    /// Force over the current contact set at depth `d` with the current states (start of step).
    pub(crate) fn force_now(&self, d: f64) -> f64 {
        let w = self.geom.weight();
        let hs: f64 = self.coef.iter().zip(&self.sum_h).map(|(c, s)| c * s).sum();
        w * (self.c_inf * (self.wsum * d - self.sum_g) + hs)
    }

    /// End-of-step force over the *current* contact set as an affine function of the rate `r`
    /// (depth at the start `d`).
    pub(crate) fn affine(&self, d: f64) -> Affine {
        let w = self.geom.weight();
        let n = self.wsum;
        let mut a = self.c_inf * (n * d - self.sum_g);
        let mut b = self.c_inf * self.dt * n;
        for k in 0..self.coef.len() {
            a += self.coef[k] * self.decay[k] * self.sum_h[k];
            b += self.coef[k] * self.beta[k] * n;
        }
        Affine { a: w * a, b: w * b }
    }

    /// End-of-step force `f` and `df/dr` of the elements that enter during a step from depth
    /// `d` at rate `r > 0` (those not in contact with `g_i < d + r dt`).
    pub(crate) fn entering(&self, d: f64, r: f64) -> (f64, f64) {
        if !(r > 0.0) {
            return (0.0, 0.0);
        }
        let d1 = d + r * self.dt;
        let w = self.geom.weight();
        let (mut f, mut df) = (0.0, 0.0);
        let mut i = self.n;
        while i < self.geom.capacity() {
            let g = self.geom.g(i);
            if g >= d1 {
                break;
            }
            let u = d1 - g;
            let om = self.geom.rel_weight(i);
            // time since entry s = u / r; h_k = tau_k (1 - exp(-s/tau_k)) r
            f += om * (self.c_inf * u);
            df += om * (self.c_inf * self.dt);
            for k in 0..self.coef.len() {
                let x = u / (r * self.tau[k]);
                let em = (-x).exp();
                let h = -self.tau[k] * (-x).exp_m1() * r;
                f += om * (self.coef[k] * h);
                // dh/dr with u = d1 - g, d1 = d + r dt: x = u/(r tau)
                // dh/dr = tau(1-e^-x) + r tau e^-x dx/dr, dx/dr = (dt r - u)/(r^2 tau)
                df += om
                    * (self.coef[k] * (-self.tau[k] * (-x).exp_m1() + em * (self.dt * r - u) / r));
            }
            i += 1;
        }
        (w * f, w * df)
    }

    /// End-of-step force of the outermost element in contact (per `8 dx` and relative width)
    /// for rate `r` from `d`.
    pub(crate) fn outer_force(&self, d: f64, r: f64) -> Option<f64> {
        if self.n == 0 {
            return None;
        }
        let i = self.n - 1;
        let k_n = self.coef.len();
        let mut f = self.c_inf * (d + r * self.dt - self.geom.g(i));
        for k in 0..k_n {
            f += self.coef[k] * (self.decay[k] * self.h[i * k_n + k] + self.beta[k] * r);
        }
        Some(f)
    }

    /// Force of element `i` (per `8 dx` and relative width) at depth `d` with the current states.
    pub(crate) fn element_force(&self, i: usize, d: f64) -> f64 {
        let k_n = self.coef.len();
        let mut f = self.c_inf * (d - self.geom.g(i));
        for k in 0..k_n {
            f += self.coef[k] * self.h[i * k_n + k];
        }
        f
    }

    /// Force of the outermost element (per `8 dx`) at depth `d` with the current states.
    pub(crate) fn outer_force_start(&self, d: f64) -> f64 {
        let i = self.n - 1;
        let k_n = self.coef.len();
        let mut f = self.c_inf * (d - self.geom.g(i));
        for k in 0..k_n {
            f += self.coef[k] * self.h[i * k_n + k];
        }
        f
    }

    /// Contact radius where the force density of the foundation vanishes: linear extrapolation
    /// of the two outermost elements' forces at depth `d` (current states), kept within the
    /// outermost element's cell.
    pub(crate) fn edge_radius(&self, d: f64) -> f64 {
        match self.n {
            0 => 0.0,
            1 => self.geom.radius_of(1),
            n => {
                let k_n = self.coef.len();
                let force = |i: usize| {
                    let mut f = self.c_inf * (d - self.geom.g(i));
                    for k in 0..k_n {
                        f += self.coef[k] * self.h[i * k_n + k];
                    }
                    f
                };
                let (fo, fi) = (force(n - 1), force(n - 2));
                let (x_o, x_i) = (self.geom.x(n - 1), self.geom.x(n - 2));
                let s = if fi > fo { fo / (fi - fo) } else { 0.5 };
                x_o + (x_o - x_i) * s.clamp(0.0, 0.5)
            }
        }
    }

    /// Affine contribution of the outermost element (to subtract when it leaves).
    pub(crate) fn outer_affine(&self, d: f64) -> Affine {
        let i = self.n - 1;
        let k_n = self.coef.len();
        let mut a = self.c_inf * (d - self.geom.g(i));
        let mut b = self.c_inf * self.dt;
        for k in 0..k_n {
            a += self.coef[k] * self.decay[k] * self.h[i * k_n + k];
            b += self.coef[k] * self.beta[k];
        }
        let w = self.geom.weight() * self.geom.rel_weight(i);
        Affine { a: w * a, b: w * b }
    }

    /// Remove the outermost element (it left contact; it is never traced again).
    pub(crate) fn pop(&mut self) {
        let k_n = self.coef.len();
        self.n -= 1;
        self.h.truncate(self.n * k_n);
        let om = self.geom.rel_weight(self.n);
        self.sum_g -= om * self.geom.g(self.n);
        self.wsum -= om;
        if self.n == 0 {
            self.sum_g = 0.0;
            self.wsum = 0.0;
        }
    }

    /// Advance all elements in contact by one step at rate `r` from depth `d`, admitting the
    /// elements that enter during the step when `admit` is set.
    pub(crate) fn commit(&mut self, d: f64, r: f64, admit: bool) {
        let k_n = self.coef.len();
        for s in self.sum_h.iter_mut() {
            *s = 0.0;
        }
        for i in 0..self.n {
            let om = self.geom.rel_weight(i);
            for k in 0..k_n {
                let h = &mut self.h[i * k_n + k];
                *h = self.decay[k] * *h + self.beta[k] * r;
                self.sum_h[k] += om * *h;
            }
        }
        self.element_updates += self.n as u64;
        if admit && r > 0.0 {
            let d1 = d + r * self.dt;
            while self.n < self.geom.capacity() {
                let g = self.geom.g(self.n);
                if g >= d1 {
                    break;
                }
                let u = d1 - g;
                let om = self.geom.rel_weight(self.n);
                for k in 0..k_n {
                    let h = -self.tau[k] * (-(u / (r * self.tau[k]))).exp_m1() * r;
                    self.h.push(h);
                    self.sum_h[k] += om * h;
                }
                self.sum_g += om * g;
                self.wsum += om;
                self.n += 1;
            }
            self.max_elements = self.max_elements.max(self.n);
        }
    }
}
