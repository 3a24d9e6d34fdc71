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
use crate::model::material::{ElementNetwork, GeneralNetwork};

/// An element network as the explicit Euler scheme sees it: dashpot positions as the state,
/// the force and the dashpot rates from the current state (the algebraic line solved for the
/// inner node).
pub(crate) trait Dashpots {
    /// Dashpot positions per element.
    fn len(&self) -> usize;
    /// Force (per unit `4 dx`) at the outer displacement `u`, and the rates of `w`.
    fn force_rates(&self, u: f64, w: &[f64], rates: &mut [f64]) -> f64;
}

impl Dashpots for ElementNetwork {
    fn len(&self) -> usize {
        2
    }
    fn force_rates(&self, u: f64, w: &[f64], rates: &mut [f64]) -> f64 {
        let (r1, r3) = self.rates(u, w[0], w[1]);
        rates[0] = r1;
        rates[1] = r3;
        self.force(u, w[0], w[1])
    }
}

impl Dashpots for GeneralNetwork {
    fn len(&self) -> usize {
        self.dashpot_len()
    }
    fn force_rates(&self, u: f64, w: &[f64], rates: &mut [f64]) -> f64 {
        self.dashpots(u, w, rates)
    }
}

#[derive(Debug, Clone)]
pub(crate) struct EulerFoundation<N: Dashpots> {
    geom: Foundation,
    net: N,
    /// Dashpot positions of the elements in contact, element-major with stride `len`.
    w: Vec<f64>,
    len: usize,
    n: usize,
    rates: Vec<f64>,
    pub(crate) element_updates: u64,
    pub(crate) max_elements: usize,
}

impl<N: Dashpots> EulerFoundation<N> {
    pub(crate) fn new(geom: Foundation, net: N) -> Self {
        let len = net.len();
        Self {
            geom,
            net,
            w: Vec::new(),
            len,
            n: 0,
            rates: vec![0.0; len],
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

    /// Total force at depth `d` with the current states, and the explicit Euler update of the
    /// states over `dt` (uses the states *before* the update, as explicit Euler does).
    pub(crate) fn force_and_advance(&mut self, d: f64, dt: f64) -> f64 {
        let mut f = 0.0;
        let len = self.len;
        for i in 0..self.n {
            let u = d - self.geom.g(i);
            let w = &mut self.w[i * len..(i + 1) * len];
            f += self.net.force_rates(u, w, &mut self.rates);
            for (x, r) in w.iter_mut().zip(&self.rates) {
                *x += dt * r;
            }
        }
        self.element_updates += self.n as u64;
        f * self.geom.weight()
    }

    /// Total force at depth `d` without advancing.
    pub(crate) fn force(&mut self, d: f64) -> f64 {
        let len = self.len;
        let mut f = 0.0;
        for i in 0..self.n {
            let w = &self.w[i * len..(i + 1) * len];
            f += self.net.force_rates(d - self.geom.g(i), w, &mut self.rates);
        }
        f * self.geom.weight()
    }

    /// Admit the elements with `g_i < d` (they enter at rest: `w = 0`).
    pub(crate) fn admit(&mut self, d: f64) {
        while self.n < self.geom.capacity() && self.geom.g(self.n) < d {
            self.w.resize(self.w.len() + self.len, 0.0);
            self.n += 1;
        }
        self.max_elements = self.max_elements.max(self.n);
    }

    /// Force (per `4 dx`) of the outermost element at depth `d`.
    pub(crate) fn outer_force(&mut self, d: f64) -> Option<f64> {
        let i = self.n.checked_sub(1)?;
        let len = self.len;
        let w = &self.w[i * len..(i + 1) * len];
        Some(self.net.force_rates(d - self.geom.g(i), w, &mut self.rates))
    }

    /// Drop the outermost element.
    pub(crate) fn pop(&mut self) {
        self.n -= 1;
        self.w.truncate(self.n * self.len);
    }
}
