//! The `mdr` time scheme on the element network of a general material
//! ([`GeneralNetwork`](crate::model::material::GeneralNetwork): a `G(t)` branch in series with a `K(t) + G(t)/3` branch, each a
//! generalised Maxwell element), built from `G` and `K` directly rather than from the poles of
//! `G_eq`: an MDR path independent of the Carson composition.
//!
//! Same step as [`super::exponential`]: the indentation is linear over the step, every internal
//! variable updates exactly, the series condition gives each element's inner-node increment in
//! closed form, and the end-of-step force over a fixed contact set is affine in the rate `r`
//! (all maps are linear in the element states, so the foundation keeps their sums).

use super::exponential::Affine;
use super::{Foundation, Stepper};
use crate::model::material::ElementModel;

/// Element states of the general network.
#[derive(Debug, Clone)]
pub(crate) struct NetFoundation<N: ElementModel> {
    geom: Foundation,
    net: N,
    /// Factors for the current step size.
    factors: N::Factors,
    /// States `[u2, q.., s.., p..]`, element-major with stride `len`.
    state: Vec<f64>,
    len: usize,
    /// Elements in contact: `0..n`.
    n: usize,
    /// Sum of the states over the contact set.
    sum: Vec<f64>,
    /// `sum_i w_i g_i` over the contact set (`w_i` the cells' relative widths,
    /// [`Foundation::rel_weight`]; `sum` is weighted the same way).
    sum_g: f64,
    /// `sum_i w_i` (the element count on a uniform grid).
    wsum: f64,
    element_updates: u64,
    max_elements: usize,
}

impl<N: ElementModel> NetFoundation<N> {
    pub(crate) fn new(geom: Foundation, net: N) -> Self {
        let len = net.state_len();
        Self {
            geom,
            factors: net.factors(0.0),
            net,
            state: Vec::new(),
            len,
            n: 0,
            sum: vec![0.0; len],
            sum_g: 0.0,
            wsum: 0.0,
            element_updates: 0,
            max_elements: 0,
        }
    }

    fn outer(&self) -> &[f64] {
        let i = self.n - 1;
        &self.state[i * self.len..(i + 1) * self.len]
    }
}

impl<N: ElementModel> Stepper for NetFoundation<N> {
    fn set_step(&mut self, dt: f64) {
        if dt != N::step(&self.factors) {
            self.factors = self.net.factors(dt);
        }
    }

    fn force_now(&self, _d: f64) -> f64 {
        self.geom.weight() * self.net.force(&self.sum)
    }

    fn affine(&self, d: f64) -> Affine {
        let w = self.geom.weight();
        let n = self.wsum;
        let (a, b) = self
            .net
            .end_force(&self.factors, n * d - self.sum_g, &self.sum);
        Affine {
            a: w * a,
            b: w * b * N::step(&self.factors) * n,
        }
    }

    fn entering(&self, d: f64, r: f64) -> (f64, f64) {
        if !(r > 0.0) {
            return (0.0, 0.0);
        }
        let dt = N::step(&self.factors);
        let d1 = d + r * dt;
        let (mut f, mut df) = (0.0, 0.0);
        let mut i = self.n;
        while i < self.geom.capacity() {
            let g = self.geom.g(i);
            if g >= d1 {
                break;
            }
            // loaded linearly from rest over s = u / r: force Q(s) u, u = d + r dt - g
            let u = d1 - g;
            let s = u / r;
            let (q, dq) = self.net.entry_stiffness(s);
            let om = self.geom.rel_weight(i);
            f += om * (q * u);
            df += om * (q * dt + u * dq * (dt - s) / r);
            i += 1;
        }
        let w = self.geom.weight();
        (w * f, w * df)
    }

    fn outer_force(&self, d: f64, r: f64) -> Option<f64> {
        if self.n == 0 {
            return None;
        }
        let g = self.geom.g(self.n - 1);
        let (a, b) = self.net.end_force(&self.factors, d - g, self.outer());
        Some(a + b * r * N::step(&self.factors))
    }

    fn outer_force_start(&self, _d: f64) -> f64 {
        self.net.force(self.outer())
    }

    fn outer_affine(&self, d: f64) -> Affine {
        let g = self.geom.g(self.n - 1);
        let (a, b) = self.net.end_force(&self.factors, d - g, self.outer());
        let w = self.geom.weight() * self.geom.rel_weight(self.n - 1);
        Affine {
            a: w * a,
            b: w * b * N::step(&self.factors),
        }
    }

    fn pop(&mut self) {
        self.n -= 1;
        self.state.truncate(self.n * self.len);
        let om = self.geom.rel_weight(self.n);
        self.sum_g -= om * self.geom.g(self.n);
        self.wsum -= om;
        if self.n == 0 {
            self.sum_g = 0.0;
            self.wsum = 0.0;
        }
    }

    fn commit(&mut self, d: f64, r: f64, admit: bool) {
        let len = self.len;
        let du = r * N::step(&self.factors);
        for s in self.sum.iter_mut() {
            *s = 0.0;
        }
        for i in 0..self.n {
            let st = &mut self.state[i * len..(i + 1) * len];
            self.net.advance(&self.factors, d - self.geom.g(i), du, st);
            let om = self.geom.rel_weight(i);
            for (s, x) in self.sum.iter_mut().zip(st.iter()) {
                *s += om * x;
            }
        }
        self.element_updates += self.n as u64;
        if admit && r > 0.0 {
            let d1 = d + du;
            while self.n < self.geom.capacity() {
                let g = self.geom.g(self.n);
                if g >= d1 {
                    break;
                }
                let u = d1 - g;
                let f = self.net.factors(u / r);
                let mut st = vec![0.0; len];
                self.net.advance(&f, 0.0, u, &mut st);
                let om = self.geom.rel_weight(self.n);
                for (s, x) in self.sum.iter_mut().zip(&st) {
                    *s += om * x;
                }
                self.state.extend_from_slice(&st);
                self.sum_g += om * g;
                self.wsum += om;
                self.n += 1;
            }
            self.max_elements = self.max_elements.max(self.n);
        }
    }

    fn in_contact(&self) -> usize {
        self.n
    }

    fn geometry(&self) -> &Foundation {
        &self.geom
    }

    fn counters(&self) -> (usize, u64) {
        (self.max_elements, self.element_updates)
    }

    fn element_force(&self, i: usize, _d: f64) -> f64 {
        self.net
            .force(&self.state[i * self.len..(i + 1) * self.len])
    }
}
