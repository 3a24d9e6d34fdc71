//! Material: the standard solid in shear with an elastic bulk (paper §2, Eqs. 1–3), and its
//! equivalent incompressible relaxation function `G_eq(t)` (docs/theory.md §2).
//!
//! Shear relaxation, Eq. (1): `G(t) = G_inf + G_1 exp(-t/tau)`, `tau = eta / G_1`,
//! glassy modulus `G_0 = G_inf + G_1`. Bulk, Eq. (2): `K(t) = K_0`. Static Poisson ratio, Eq. (3):
//! `nu = (3 K_0 - 2 G_inf) / (6 K_0 + 2 G_inf)`, `nu = 0.5` being the incompressible limit.
//!
//! All moduli are in pascal (Pa), `eta` in pascal-seconds (Pa s), times in seconds (s).
//!
//! Compressibility is carried internally as the bulk compliance `kappa = 1 / (3 K_0)` (1/Pa),
//! which is `0` for an incompressible solid, so that every formula stays well conditioned as
//! `nu -> 0.5`.
//!
//! General linear viscoelasticity (Prony series in shear and bulk, docs/theory.md §8) lives in
//! [`rheology`]; its equivalent relaxation function `G_eq(t)`, an exact Prony series from the
//! Carson-domain formula, in [`carson`]. The standard solid above is their one-term case
//! ([`Material::general`]).

use crate::error::{check, Error, Result};

pub mod carson;
pub mod network;
pub mod rheology;

pub use network::{ElementModel, GeneralNetwork, StackedNetwork};
pub use rheology::{BulkProny, BulkRheology, GeneralMaterial, ShearProny};

/// Bulk behaviour: an elastic modulus `K_0` (Pa) or incompressible.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bulk {
    /// Elastic bulk modulus `K_0` in Pa, `0 < K_0 < inf`.
    Modulus(f64),
    /// `K_0 = inf`, static Poisson ratio 0.5.
    Incompressible,
}

/// A validated standard solid in shear with elastic bulk.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    g_inf: f64,
    g_1: f64,
    eta: f64,
    bulk: Bulk,
}

impl Material {
    /// Material from its shear parameters and the bulk modulus `k_0` (all Pa, `eta` in Pa s).
    ///
    /// Ranges: `0 < g_inf < inf`, `0 <= g_1 < inf`, `0 <= eta < inf`, `0 < k_0 < inf`.
    pub fn new(g_inf: f64, g_1: f64, eta: f64, k_0: f64) -> Result<Self> {
        let k_0 = check("k_0", k_0, k_0 > 0.0, "0 < k_0 < inf (Pa)")?;
        Self::with_bulk(g_inf, g_1, eta, Bulk::Modulus(k_0))
    }

    /// Material from its shear parameters and the static Poisson ratio `nu` of Eq. (3).
    ///
    /// `-1 < nu <= 0.5`; `nu = 0.5` gives an incompressible material, otherwise
    /// `K_0 = 2 G_inf (1 + nu) / (3 (1 - 2 nu))`.
    pub fn with_poisson(g_inf: f64, g_1: f64, eta: f64, nu: f64) -> Result<Self> {
        let nu = check("nu", nu, nu > -1.0 && nu <= 0.5, "-1 < nu <= 0.5")?;
        let g_inf = check_g_inf(g_inf)?;
        if nu == 0.5 {
            return Self::with_bulk(g_inf, g_1, eta, Bulk::Incompressible);
        }
        let k_0 = 2.0 * g_inf * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu));
        // For nu just above -1 or just below 0.5 the bulk modulus can leave the f64 range.
        let k_0 = check(
            "nu",
            k_0,
            k_0 > 0.0,
            "-1 < nu <= 0.5 with a finite positive K_0",
        )
        .map_err(|_| Error::OutOfRange {
            field: "nu",
            value: nu,
            allowed: "-1 < nu <= 0.5 with K_0 = 2 G_inf (1 + nu) / (3 (1 - 2 nu)) finite and > 0",
        })?;
        Self::with_bulk(g_inf, g_1, eta, Bulk::Modulus(k_0))
    }

    /// Incompressible material (`K_0 = inf`, `nu = 0.5`).
    pub fn incompressible(g_inf: f64, g_1: f64, eta: f64) -> Result<Self> {
        Self::with_bulk(g_inf, g_1, eta, Bulk::Incompressible)
    }

    /// Material with an explicit [`Bulk`].
    pub fn with_bulk(g_inf: f64, g_1: f64, eta: f64, bulk: Bulk) -> Result<Self> {
        let g_inf = check_g_inf(g_inf)?;
        let g_1 = check("g_1", g_1, g_1 >= 0.0, "0 <= g_1 < inf (Pa)")?;
        let eta = check("eta", eta, eta >= 0.0, "0 <= eta < inf (Pa s)")?;
        if let Bulk::Modulus(k) = bulk {
            check("k_0", k, k > 0.0, "0 < k_0 < inf (Pa)")?;
        }
        Ok(Self {
            g_inf,
            g_1,
            eta,
            bulk,
        })
    }

    /// Relaxed (static) shear modulus `G_inf` (Pa).
    pub fn g_inf(&self) -> f64 {
        self.g_inf
    }
    /// Relaxing shear modulus `G_1` (Pa).
    pub fn g_1(&self) -> f64 {
        self.g_1
    }
    /// Shear viscosity `eta` (Pa s).
    pub fn eta(&self) -> f64 {
        self.eta
    }
    /// Glassy (instantaneous) shear modulus `G_0 = G_inf + G_1` (Pa).
    pub fn g_0(&self) -> f64 {
        self.g_inf + self.g_1
    }
    /// The bulk behaviour.
    pub fn bulk(&self) -> Bulk {
        self.bulk
    }
    /// Bulk modulus `K_0` (Pa), `f64::INFINITY` when incompressible.
    pub fn k_0(&self) -> f64 {
        match self.bulk {
            Bulk::Modulus(k) => k,
            Bulk::Incompressible => f64::INFINITY,
        }
    }
    /// Bulk compliance `kappa = 1 / (3 K_0)` (1/Pa); `0` when incompressible.
    pub fn kappa(&self) -> f64 {
        match self.bulk {
            Bulk::Modulus(k) => 1.0 / (3.0 * k),
            Bulk::Incompressible => 0.0,
        }
    }
    /// Shear relaxation time `tau = eta / G_1` (s); `0` when `eta = 0`, `inf` when `G_1 = 0`.
    pub fn tau(&self) -> f64 {
        if self.g_1 == 0.0 {
            f64::INFINITY
        } else {
            self.eta / self.g_1
        }
    }
    /// True when the material is purely elastic over any time scale (`G_1 = 0` or `eta = 0`):
    /// then `G(t) = G_inf` for every `t > 0`.
    pub fn is_elastic(&self) -> bool {
        self.g_1 == 0.0 || self.eta == 0.0
    }

    /// Static Poisson ratio, Eq. (3) (`0.5` when incompressible).
    pub fn poisson(&self) -> f64 {
        poisson_of(self.g_inf, self.kappa())
    }
    /// Glassy Poisson ratio `(3 K_0 - 2 G_0) / (6 K_0 + 2 G_0)`; can be far below the static one.
    pub fn glassy_poisson(&self) -> f64 {
        poisson_of(self.g_0(), self.kappa())
    }

    /// Shear relaxation function `G(t)` of Eq. (1) (Pa), `t` in s, `t >= 0`.
    pub fn shear_relaxation(&self, t: f64) -> f64 {
        if self.is_elastic() {
            if self.eta == 0.0 && t == 0.0 {
                return self.g_0();
            }
            return self.g_inf;
        }
        self.g_inf + self.g_1 * (-t / self.tau()).exp()
    }

    /// Equivalent incompressible shear relaxation function `G_eq(t)` (docs/theory.md §2), the
    /// inverse Carson transform of `G (3K + G) / (3K + 4G)`:
    ///
    /// ```text
    /// G_eq(t) = c_inf + c_a exp(-t/tau) + c_b exp(-t/tau_b)
    /// c_inf = G_inf (1 + kappa G_inf) / (1 + 4 kappa G_inf)          (relaxed)
    /// c_a   = G_1 / 4
    /// c_b   = (3/4) G_1 / ((1 + 4 kappa G_0)(1 + 4 kappa G_inf))
    /// tau_b = tau (1 + 4 kappa G_0) / (1 + 4 kappa G_inf)
    /// ```
    ///
    /// with `kappa = 1/(3 K_0)`. For an incompressible solid the two terms share `tau` and are
    /// merged into one (`c = G_1`). For an elastic material the series has no terms.
    ///
    /// ```
    /// # use mdr_impact::model::material::Material;
    /// let m = Material::with_poisson(1.0, 100.0, 1.0, 0.45).unwrap();
    /// let g = m.equivalent_relaxation();
    /// // glassy value: G_0 (3K + G_0)/(3K + 4 G_0) with G_0 = 101, K_0 = 2*1.45/(3*0.1)
    /// let k = 2.0 * 1.45 / 0.3;
    /// let glassy = 101.0 * (3.0 * k + 101.0) / (3.0 * k + 404.0);
    /// assert!((g.glassy() - glassy).abs() < 1e-12 * glassy);
    /// ```
    pub fn equivalent_relaxation(&self) -> Prony {
        let kappa = self.kappa();
        let (gi, g1, g0) = (self.g_inf, self.g_1, self.g_0());
        let relaxed = gi * (1.0 + kappa * gi) / (1.0 + 4.0 * kappa * gi);
        if self.is_elastic() {
            return Prony {
                relaxed,
                terms: Vec::new(),
            };
        }
        let tau = self.tau();
        if kappa == 0.0 {
            return Prony {
                relaxed,
                terms: vec![PronyTerm {
                    coefficient: g1,
                    tau,
                }],
            };
        }
        let c_a = 0.25 * g1;
        let c_b = 0.75 * g1 / ((1.0 + 4.0 * kappa * g0) * (1.0 + 4.0 * kappa * gi));
        let tau_b = tau * (1.0 + 4.0 * kappa * g0) / (1.0 + 4.0 * kappa * gi);
        Prony {
            relaxed,
            terms: vec![
                PronyTerm {
                    coefficient: c_a,
                    tau,
                },
                PronyTerm {
                    coefficient: c_b,
                    tau: tau_b,
                },
            ],
        }
    }

    /// Plane-strain (effective) modulus `E* = 4 G (1 + kappa G) / (1 + 4 kappa G)` of the
    /// elastic solid with shear modulus `g` and this material's bulk (Pa).
    pub fn effective_modulus(&self, g: f64) -> f64 {
        let kappa = self.kappa();
        4.0 * g * (1.0 + kappa * g) / (1.0 + 4.0 * kappa * g)
    }
}

fn check_g_inf(g_inf: f64) -> Result<f64> {
    check("g_inf", g_inf, g_inf > 0.0, "0 < g_inf < inf (Pa)")
}

/// Poisson ratio `(3K - 2G)/(6K + 2G)` written with `kappa = 1/(3K)`.
fn poisson_of(g: f64, kappa: f64) -> f64 {
    (1.0 - 2.0 * kappa * g) / (2.0 + 2.0 * kappa * g)
}

/// One term `c exp(-t / tau)` of a Prony series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PronyTerm {
    /// Coefficient `c` (Pa).
    pub coefficient: f64,
    /// Relaxation time `tau` (s), `> 0`.
    pub tau: f64,
}

/// A Prony series `G(t) = relaxed + sum_k c_k exp(-t / tau_k)` with non-negative coefficients.
#[derive(Debug, Clone, PartialEq)]
pub struct Prony {
    /// Relaxed value `G(inf)` (Pa).
    pub relaxed: f64,
    /// The decaying terms.
    pub terms: Vec<PronyTerm>,
}

impl Prony {
    /// Check that the series is a valid relaxation function: `0 < relaxed < inf`, every
    /// `0 < tau_k < inf` and `0 <= c_k < inf` (errors name the field).
    pub fn validate(&self) -> Result<()> {
        check(
            "relaxed",
            self.relaxed,
            self.relaxed > 0.0,
            "0 < G_eq(inf) < inf",
        )?;
        for p in &self.terms {
            check("tau", p.tau, p.tau > 0.0, "0 < tau < inf")?;
            check(
                "coefficient",
                p.coefficient,
                p.coefficient >= 0.0,
                "0 <= c_k < inf",
            )?;
        }
        Ok(())
    }

    /// `G(t)` (Pa) for `t >= 0`.
    pub fn eval(&self, t: f64) -> f64 {
        self.relaxed
            + self
                .terms
                .iter()
                .map(|p| p.coefficient * (-t / p.tau).exp())
                .sum::<f64>()
    }
    /// Glassy value `G(0)` (Pa).
    pub fn glassy(&self) -> f64 {
        self.relaxed + self.terms.iter().map(|p| p.coefficient).sum::<f64>()
    }
    /// Initial slope `G'(0)` (Pa/s), `<= 0`.
    pub fn initial_slope(&self) -> f64 {
        -self
            .terms
            .iter()
            .map(|p| p.coefficient / p.tau)
            .sum::<f64>()
    }
    /// Shortest relaxation time (s), `inf` without terms.
    pub fn min_tau(&self) -> f64 {
        self.terms
            .iter()
            .map(|p| p.tau)
            .fold(f64::INFINITY, f64::min)
    }
    /// True without decaying terms.
    pub fn is_elastic(&self) -> bool {
        self.terms.is_empty()
    }
    /// The same series with moduli divided by `modulus` and times by `time` (non-dimensionalise).
    pub fn scaled(&self, modulus: f64, time: f64) -> Prony {
        Prony {
            relaxed: self.relaxed / modulus,
            terms: self
                .terms
                .iter()
                .map(|p| PronyTerm {
                    coefficient: p.coefficient / modulus,
                    tau: p.tau / time,
                })
                .collect(),
        }
    }
}

/// The element network of the paper's Fig. 2 / Eq. (8), one MDR element per unit `4 dx`.
///
/// States are the two dashpot positions `w1 = u - u1` (outer Maxwell branch, `eta/3`, `G_1/3`)
/// and `w3 = u2 - u3` (inner Maxwell branch, `eta`, `G_1`); the inner node `u2` is the solution
/// of the algebraic third line of Eq. (8). With these states the DAE is semi-explicit of index 1:
///
/// ```text
/// w1' = (u - w1 - u2) / tau,     w3' = (u2 - w3) / tau,
/// u2  = [G_1 w3 + (G_inf/3 + K_0 + G_1/3) u - (G_1/3) w1] / (4 G_inf/3 + K_0 + 4 G_1/3)
/// force per 4 dx:  G_inf u2 + G_1 (u2 - w3)
/// ```
///
/// Used by the explicit Euler MDR scheme and by the test that the network relaxes like
/// [`Material::equivalent_relaxation`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementNetwork {
    g_inf: f64,
    g_1: f64,
    inv_tau: f64,
    kappa: f64,
}

impl ElementNetwork {
    /// The network of a (non-elastic) material.
    pub fn new(material: &Material) -> Self {
        Self {
            g_inf: material.g_inf,
            g_1: material.g_1,
            inv_tau: if material.eta == 0.0 {
                f64::INFINITY
            } else {
                material.g_1 / material.eta
            },
            kappa: material.kappa(),
        }
    }
    /// Same network in units where moduli are divided by `modulus` and times by `time`.
    pub fn scaled(&self, modulus: f64, time: f64) -> Self {
        Self {
            g_inf: self.g_inf / modulus,
            g_1: self.g_1 / modulus,
            inv_tau: self.inv_tau * time,
            kappa: self.kappa * modulus,
        }
    }
    /// Inner node displacement `u2` from the algebraic line of Eq. (8), written with
    /// `kappa = 1/(3 K_0)` (divide the line by `K_0`) so that `kappa = 0` is incompressible.
    #[inline]
    pub fn inner_node(&self, u: f64, w1: f64, w3: f64) -> f64 {
        let k = self.kappa;
        let num =
            3.0 * k * self.g_1 * w3 + (1.0 + k * (self.g_inf + self.g_1)) * u - k * self.g_1 * w1;
        num / (1.0 + 4.0 * k * (self.g_inf + self.g_1))
    }
    /// Force per unit `4 dx` for outer displacement `u` and states `(w1, w3)`.
    #[inline]
    pub fn force(&self, u: f64, w1: f64, w3: f64) -> f64 {
        let u2 = self.inner_node(u, w1, w3);
        self.g_inf * u2 + self.g_1 * (u2 - w3)
    }
    /// Time derivatives `(w1', w3')` of the dashpot positions.
    #[inline]
    pub fn rates(&self, u: f64, w1: f64, w3: f64) -> (f64, f64) {
        let u2 = self.inner_node(u, w1, w3);
        ((u - w1 - u2) * self.inv_tau, (u2 - w3) * self.inv_tau)
    }
    /// `1/tau` of the shear Maxwell branch.
    pub fn inv_tau(&self) -> f64 {
        self.inv_tau
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn poisson_roundtrip() {
        for nu in [-0.99, -0.5, 0.0, 0.3, 0.45, 0.49, 0.499] {
            let m = Material::with_poisson(2.0, 3.0, 4.0, nu).unwrap();
            assert_relative_eq!(m.poisson(), nu, epsilon = 1e-13);
        }
        let m = Material::with_poisson(2.0, 3.0, 4.0, 0.5).unwrap();
        assert_eq!(m.bulk(), Bulk::Incompressible);
        assert_eq!(m.poisson(), 0.5);
    }

    #[test]
    fn equivalent_relaxation_limits() {
        let m = Material::with_poisson(1.0, 99.0, 1.0, 0.3).unwrap();
        let g = m.equivalent_relaxation();
        assert_relative_eq!(
            4.0 * g.relaxed,
            m.effective_modulus(1.0),
            max_relative = 1e-14
        );
        assert_relative_eq!(
            4.0 * g.glassy(),
            m.effective_modulus(100.0),
            max_relative = 1e-14
        );
        // E* = E / (1 - nu^2) for the relaxed state
        let nu = 0.3;
        let e = 2.0 * (1.0 + nu);
        assert_relative_eq!(4.0 * g.relaxed, e / (1.0 - nu * nu), max_relative = 1e-14);
    }
}
