//! `G_eq(t)` of a general linear-viscoelastic material by numerical inversion of the Carson
//! formula (docs/theory.md §2 and §8), independent of the pole computation of
//! [`crate::model::material::carson`].
//!
//! The Carson transform `G_eq(s) = G (3K + G) / (3K + 4G)` is evaluated in complex arithmetic from
//! the shear and bulk terms (`g exp(-t/tau) -> g s tau / (1 + s tau)`), and the Bromwich integral
//!
//! ```text
//! G_eq(t) = (1 / 2 pi i) int e^{s t} G_eq(s) / s ds
//! ```
//!
//! is taken along Weideman's optimised Talbot contour (J. A. C. Weideman, *Optimizing Talbot's
//! contours for the inversion of the Laplace transform*, SIAM J. Numer. Anal. 44 (2006);
//! L. N. Trefethen, J. A. C. Weideman, T. Schmelzer, *Talbot quadratures and rational
//! approximations*, BIT 46 (2006), Eq. (2.5)):
//!
//! ```text
//! s(theta) = (N / t) (sigma + mu theta cot(alpha theta) + i nu theta),  -pi < theta < pi,
//! sigma = -0.6122, mu = 0.5017, alpha = 0.6407, nu = 0.2645
//! ```
//!
//! with the `N`-point midpoint rule in `theta`; the discretisation error falls like `3.89^-N`.
//! Every singularity of `G_eq(s) / s` lies on `(-inf, 0]` (poles of `G`, zeros of `3K + 4G`, and
//! `s = 0`), inside the contour; `3K + 4G` has no zero off the real axis (its imaginary part is
//! `sum w tau Im(s) / |1 + s tau|^2`). The largest factor `|e^{s t}|` on the contour is
//! `e^{0.171 N}`, which sets the rounding floor: a term `c exp(-t/tau)` with `tau` between about
//! `t / N` and `t` contributes node values of order `c e^{0.171 N}` but only `c e^{-t/tau}` to the
//! result, so the relative rounding error grows with `N` and with the share of `G_eq` that has
//! relaxed by `t`.
//!
//! Measured against the exact Prony series of `material::carson` (`tests/rheology.rs`,
//! `talbot_error_against_nodes`, 400 log-spaced `t` from `1e-3 min(tau)` to `1e3 max(tau)`): the
//! error falls from `4e-3` at `N = 8` to `3e-10` at `N = 20`; at [`TALBOT_NODES`] `= 28` it is at
//! most `2e-13` for the standard solid, `5e-13` for 10 terms, `2e-12` to `1.2e-11` for 30 terms
//! over 20 decades with `G_0 / G_inf ~ 1e5` (mean `1e-13`), and grows again beyond `N = 30`.
//!
//! Nothing here shares code with the MDR solvers or with `material::carson`; only the material
//! definition ([`Material`]) is common.

use crate::error::{check, Error, Result};
use crate::model::material::{BulkRheology, Material};
use nalgebra::Complex;

/// Nodes of the Talbot rule (the full contour; half of them are evaluated thanks to conjugate
/// symmetry). Chosen where the `3.89^-N` discretisation error meets the rounding floor, which
/// grows with `N` (measured, module docs): `N = 28` gave the smallest maximum error over the test
/// materials among `N = 20 ... 48`.
pub const TALBOT_NODES: usize = 28;

const SIGMA: f64 = -0.6122;
const MU: f64 = 0.5017;
const ALPHA: f64 = 0.6407;
const NU: f64 = 0.2645;

/// `G_eq(t)` (Pa) of `material` at `t >= 0` (s) by Talbot inversion with [`TALBOT_NODES`] nodes.
///
/// `t = 0` returns the glassy value `G_0 (3K_0 + G_0) / (3K_0 + 4G_0)` (the limit `s -> inf`).
///
/// ```
/// # use mdr_impact::model::material::Material;
/// # use mdr_impact::solvers::theory::bromwich::equivalent_relaxation_at;
/// let m = Material::with_poisson(1.0, 100.0, 1.0, 0.45).unwrap();
/// let closed = m.equivalent_relaxation().unwrap(); // docs/theory.md §2
/// let g = equivalent_relaxation_at(&m, 0.3).unwrap();
/// assert!((g - closed.eval(0.3)).abs() < 1e-12 * closed.eval(0.3));
/// ```
pub fn equivalent_relaxation_at(material: &Material, t: f64) -> Result<f64> {
    equivalent_relaxation_with(material, t, TALBOT_NODES)
}

/// As [`equivalent_relaxation_at`] with `nodes` Talbot nodes (even, `>= 2`).
pub fn equivalent_relaxation_with(material: &Material, t: f64, nodes: usize) -> Result<f64> {
    let t = check("t", t, t >= 0.0, "0 <= t < inf (s)")?;
    if nodes < 2 || !nodes.is_multiple_of(2) {
        return Err(Error::OutOfRange {
            field: "nodes",
            value: nodes as f64,
            allowed: "an even number of Talbot nodes >= 2",
        });
    }
    if t == 0.0 {
        return Ok(glassy(material));
    }
    let n = nodes as f64;
    let h = 2.0 * std::f64::consts::PI / n;
    let scale = n / t;
    let mut sum = 0.0;
    for k in 0..nodes / 2 {
        let theta = (k as f64 + 0.5) * h;
        let (sin, cos) = (ALPHA * theta).sin_cos();
        let cot = cos / sin;
        let s = Complex::new(SIGMA + MU * theta * cot, NU * theta) * scale;
        let ds = Complex::new(MU * (cot - ALPHA * theta / (sin * sin)), NU) * scale;
        let integrand = (s * t).exp() * carson(material, s) / s * ds;
        sum += integrand.im;
    }
    let g = sum * h / std::f64::consts::PI;
    if !g.is_finite() {
        return Err(Error::NonFinite {
            what: "G_eq(t) by Talbot inversion",
            value: g,
        });
    }
    Ok(g)
}

/// The Carson transform `G_eq(s) = G (3K + G) / (3K + 4G)` at complex `s` (Pa).
pub fn carson(material: &Material, s: Complex<f64>) -> Complex<f64> {
    let shear = material.shear();
    let g = term_sum(shear.g_inf(), shear.terms(), s);
    let k = match material.bulk() {
        BulkRheology::Incompressible => return g,
        BulkRheology::Elastic(k) => Complex::new(*k, 0.0),
        BulkRheology::Prony(p) => term_sum(p.k_inf(), p.terms(), s),
    };
    g * (k * 3.0 + g) / (k * 3.0 + g * 4.0)
}

/// `relaxed + sum m s tau / (1 + s tau)` over `(m, tau)`.
fn term_sum(relaxed: f64, terms: &[(f64, f64)], s: Complex<f64>) -> Complex<f64> {
    terms
        .iter()
        .fold(Complex::new(relaxed, 0.0), |acc, &(m, tau)| {
            let st = s * tau;
            acc + st * m / (st + 1.0)
        })
}

/// Glassy `G_eq(0)` from the glassy moduli (`s -> inf`).
fn glassy(material: &Material) -> f64 {
    let shear = material.shear();
    let g0 = shear.g_inf() + shear.terms().iter().map(|&(g, _)| g).sum::<f64>();
    let k0 = match material.bulk() {
        BulkRheology::Incompressible => return g0,
        BulkRheology::Elastic(k) => *k,
        BulkRheology::Prony(p) => p.k_inf() + p.terms().iter().map(|&(k, _)| k).sum::<f64>(),
    };
    g0 * (3.0 * k0 + g0) / (3.0 * k0 + 4.0 * g0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::material::rheology::ShearProny;

    /// One Maxwell term, incompressible: G_eq(t) = 1 + exp(-t) exactly.
    #[test]
    fn single_exponential() {
        let m = Material::general(
            ShearProny::new(1.0, &[(1.0, 1.0)]).unwrap(),
            crate::model::material::BulkInput::Incompressible,
        )
        .unwrap();
        for t in [1e-3f64, 0.1, 1.0, 5.0, 30.0, 1e3] {
            let g = equivalent_relaxation_at(&m, t).unwrap();
            let exact = 1.0 + (-t).exp();
            assert!((g - exact).abs() < 1e-13 * exact, "t {t}: {g} vs {exact}");
        }
    }
}
