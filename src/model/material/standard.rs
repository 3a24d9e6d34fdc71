//! The standard solid of the paper (§2, Eqs. 1–3): one Maxwell term in shear and an elastic (or
//! incompressible) bulk, seen as a shape of the one [`Material`] through
//! [`Material::as_standard_solid`](super::Material::as_standard_solid), with its closed forms.
//!
//! Shear relaxation, Eq. (1): `G(t) = G_inf + G_1 exp(-t/tau)`, `tau = eta / G_1`,
//! glassy modulus `G_0 = G_inf + G_1`. Bulk, Eq. (2): `K(t) = K_0`. Static Poisson ratio, Eq. (3):
//! `nu = (3 K_0 - 2 G_inf) / (6 K_0 + 2 G_inf)`, `nu = 0.5` being the incompressible limit.
//!
//! All moduli are in pascal (Pa), `eta` in pascal-seconds (Pa s), times in seconds (s).
//! Compressibility is carried as the bulk compliance `kappa = 1 / (3 K_0)` (1/Pa), which is `0`
//! for an incompressible solid, so that every formula stays well conditioned as `nu -> 0.5`.

use super::prony::{Prony, PronyTerm};
use super::Material;
use crate::error::{check, Result};

/// Bulk behaviour of a standard solid: an elastic modulus `K_0` (Pa) or incompressible.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bulk {
    /// Elastic bulk modulus `K_0` in Pa, `0 < K_0 < inf`.
    Modulus(f64),
    /// `K_0 = inf`, static Poisson ratio 0.5.
    Incompressible,
}

/// A material of the standard solid's shape (at most one shear term, elastic or incompressible
/// bulk), however it was written: a small copy of its parameters that carries the closed forms
/// (paper Eq. 3, docs/theory.md §2) and the groups of Eq. (11).
///
/// `G_1 = 0` or `eta = 0` is the elastic case (`G(t) = G_inf` for `t > 0`). The relaxation time
/// is kept as stored (`eta / G_1` for a material written with `eta`, the series' time for one
/// written as a one-term Prony series), so that both writings give the same `G_eq` to the bit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StandardSolid {
    pub(super) g_inf: f64,
    pub(super) g_1: f64,
    pub(super) eta: f64,
    pub(super) tau: f64,
    pub(super) bulk: Bulk,
}

impl StandardSolid {
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
        self.tau
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
        self.g_inf + self.g_1 * (-t / self.tau).exp()
    }

    /// Equivalent incompressible shear relaxation function `G_eq(t)` (docs/theory.md §2), the
    /// inverse Carson transform of `G (3K + G) / (3K + 4G)`, in closed form:
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
    /// let g = m.as_standard_solid().unwrap().equivalent_relaxation();
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
        let tau = self.tau;
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

    /// The dimensionless groups of Eq. (11) of an impact with time scale `time_scale` (s):
    /// `nu`, `p2 = G_inf / G_1` (`inf` when `G_1 = 0`) and `p3 = eta / (G_inf T)` (algebraically
    /// Eq. (11), better conditioned).
    pub fn groups(&self, time_scale: f64) -> Groups {
        let p2 = if self.g_1 == 0.0 {
            f64::INFINITY
        } else {
            self.g_inf / self.g_1
        };
        let p3 = self.eta / (self.g_inf * time_scale);
        let nu = match self.bulk {
            Bulk::Incompressible => 0.5,
            Bulk::Modulus(_) => self.poisson(),
        };
        Groups { nu, p2, p3 }
    }
}

/// The dimensionless groups of Eq. (11): `p1 = nu`, `p2 = G_inf / G_1`,
/// `p3 = eta (v0 R / (m^2 G_inf^3))^(1/5)`.
///
/// [`Groups::new`] takes user input and refuses every non-finite value (`inf`, `NaN`, `1e999`).
/// The elastic limit is `p3 = 0` (`eta = 0`: Hertz with `G_inf`, `e = 1`). [`crate::Impact::groups`]
/// of an elastic material with `G_1 = 0` reports `p2 = inf`, which
/// [`Groups::canonical_material`] maps back to `G_1 = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Groups {
    /// Static Poisson ratio, `-1 < nu <= 0.5` (`0.5`: incompressible).
    pub nu: f64,
    /// `G_inf / G_1`, `0 < p2 < inf` with `1/p2` finite (`inf` only from [`crate::Impact::groups`]).
    pub p2: f64,
    /// Dimensionless viscosity, `0 <= p3 < inf` (`0`: elastic with `G_inf`, Hertz).
    pub p3: f64,
}

impl Groups {
    /// Validated groups: `-1 < nu <= 0.5`, `0 < p2 < inf` with `1/p2` finite, `0 <= p3 < inf`,
    /// all finite; otherwise [`crate::Error::OutOfRange`] naming the group.
    ///
    /// ```
    /// # use mdr_impact::{Error, Groups};
    /// assert!(Groups::new(0.3, 1.0, 0.0).is_ok()); // elastic limit
    /// assert!(matches!(
    ///     Groups::new(0.3, f64::INFINITY, 1.0),
    ///     Err(Error::OutOfRange { field: "p2", .. })
    /// ));
    /// ```
    pub fn new(nu: f64, p2: f64, p3: f64) -> Result<Self> {
        check("nu", nu, nu > -1.0 && nu <= 0.5, "-1 < nu <= 0.5")?;
        check(
            "p2",
            p2,
            p2 > 0.0 && (1.0 / p2).is_finite(),
            "0 < p2 < inf with 1/p2 finite (elastic limit: p3 = 0)",
        )?;
        check("p3", p3, p3 >= 0.0, "0 <= p3 < inf (0: elastic)")?;
        Ok(Self { nu, p2, p3 })
    }

    /// The material in canonical units (`G_inf = 1`, `G_1 = 1/p2`, `eta = p3`).
    pub fn canonical_material(&self) -> Result<Material> {
        let g_1 = if self.p2.is_infinite() {
            0.0
        } else {
            1.0 / self.p2
        };
        Material::with_poisson(1.0, g_1, self.p3, self.nu)
    }
}

/// Poisson ratio `(3K - 2G)/(6K + 2G)` written with `kappa = 1/(3K)`.
fn poisson_of(g: f64, kappa: f64) -> f64 {
    (1.0 - 2.0 * kappa * g) / (2.0 + 2.0 * kappa * g)
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
/// [`StandardSolid::equivalent_relaxation`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementNetwork {
    g_inf: f64,
    g_1: f64,
    inv_tau: f64,
    kappa: f64,
}

impl ElementNetwork {
    /// The network of a (non-elastic) standard solid.
    pub fn new(material: &StandardSolid) -> Self {
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
