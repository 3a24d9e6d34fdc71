//! The `mdr-euler` time scheme: the paper's explicit Euler on the element network of Eq. (8),
//! kept faithful as the baseline the paper used.
//!
//! Every element carries the two dashpot positions of [`ElementNetwork`] (the algebraic third
//! line of Eq. (8) is solved for the inner node at every evaluation). One step from `t_n`:
//! forces from the current states, explicit Euler for the dashpots, and the explicit (symplectic)
//! Euler for the sphere: `v_{n+1} = v_n - dt F_n / m`, `d_{n+1} = d_n + dt v_{n+1}`.
//!
//! Stability: the dashpot modes relax with rates `1/tau` and `1/tau_b <= 1/tau`, so explicit
//! Euler needs `dt < 2 tau`; the sphere on the glassy contact stiffness `8 G_eq(0) a` needs
//! `dt < 2 / sqrt(8 G_eq(0) a_max / m)`.

use super::Foundation;
use crate::material::ElementNetwork;

#[derive(Debug, Clone)]
pub(crate) struct EulerFoundation {
    geom: Foundation,
    net: ElementNetwork,
    /// Dashpot positions `(w1, w3)` of the elements in contact.
    w: Vec<(f64, f64)>,
    pub(crate) element_updates: u64,
    pub(crate) max_elements: usize,
}

impl EulerFoundation {
    pub(crate) fn new(geom: Foundation, net: ElementNetwork) -> Self {
        Self {
            geom,
            net,
            w: Vec::new(),
            element_updates: 0,
            max_elements: 0,
        }
    }

    pub(crate) fn in_contact(&self) -> usize {
        self.w.len()
    }

    pub(crate) fn geometry(&self) -> &Foundation {
        &self.geom
    }

    /// Total force at depth `d` with the current states, and the explicit Euler update of the
    /// states over `dt` (uses the states *before* the update, as explicit Euler does).
    pub(crate) fn force_and_advance(&mut self, d: f64, dt: f64) -> f64 {
        let mut f = 0.0;
        for (i, w) in self.w.iter_mut().enumerate() {
            let u = d - self.geom.g(i);
            let (w1, w3) = *w;
            f += self.net.force(u, w1, w3);
            let (r1, r3) = self.net.rates(u, w1, w3);
            *w = (w1 + dt * r1, w3 + dt * r3);
        }
        self.element_updates += self.w.len() as u64;
        f * self.geom.weight()
    }

    /// Total force at depth `d` without advancing.
    pub(crate) fn force(&self, d: f64) -> f64 {
        let f: f64 = self
            .w
            .iter()
            .enumerate()
            .map(|(i, &(w1, w3))| self.net.force(d - self.geom.g(i), w1, w3))
            .sum();
        f * self.geom.weight()
    }

    /// Admit the elements with `g_i < d` (they enter at rest: `w = 0`).
    pub(crate) fn admit(&mut self, d: f64) {
        while self.w.len() < self.geom.capacity() && self.geom.g(self.w.len()) < d {
            self.w.push((0.0, 0.0));
        }
        self.max_elements = self.max_elements.max(self.w.len());
    }

    /// Force (per `8 dx`) of the outermost element at depth `d`.
    pub(crate) fn outer_force(&self, d: f64) -> Option<f64> {
        let i = self.w.len().checked_sub(1)?;
        let (w1, w3) = self.w[i];
        Some(self.net.force(d - self.geom.g(i), w1, w3))
    }

    /// Drop the outermost element.
    pub(crate) fn pop(&mut self) {
        self.w.pop();
    }
}
