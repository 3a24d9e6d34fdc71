//! The material: one type, [`Material`], for every linear-viscoelastic solid of the crate: shear
//! as a Prony series [`ShearProny`], bulk incompressible, elastic or a Prony series
//! ([`BulkRheology`]; docs/theory.md §8). All moduli in pascal (Pa), times in seconds (s),
//! viscosities in pascal-seconds (Pa s).
//!
//! The paper's standard solid (§2, Eqs. 1–3: one Maxwell term in shear, elastic bulk) is a set of
//! constructors ([`Material::new`], [`Material::with_poisson`], ...) and a shape query,
//! [`Material::as_standard_solid`], which recognises any material of at most one shear term and
//! an elastic or incompressible bulk however it was written, and returns a [`StandardSolid`] that
//! carries the closed forms and the groups of Eq. (11). What depends on the shape is decided here,
//! once: the equivalent relaxation function `G_eq(t)` ([`Material::equivalent_relaxation`]: the
//! closed form of docs/theory.md §2 for the standard solid's shape, the exact Carson-domain
//! composition of [`carson`] otherwise).

use crate::error::{check, Result};

pub mod carson;
pub mod network;
pub mod poles;
pub mod prony;
pub mod rheology;
pub mod shift;
pub mod standard;

pub use network::{ElementModel, GeneralNetwork, StackedNetwork};
pub use prony::{Prony, PronyTerm};
pub use rheology::{BulkInput, BulkProny, BulkRheology, ShearProny};
pub use standard::{Bulk, ElementNetwork, Groups, StandardSolid};

/// A validated linear-viscoelastic solid: shear [`ShearProny`] and resolved bulk
/// [`BulkRheology`] (docs/theory.md §8), of which the paper's standard solid is a shape
/// ([`Material::as_standard_solid`]).
///
/// Two materials are equal when their shear and bulk are, and, for the standard solid's shape,
/// their [`StandardSolid`] views (which keep `G_1` and `eta` of an elastic standard solid).
#[derive(Debug, Clone)]
pub struct Material {
    shear: ShearProny,
    bulk: BulkRheology,
    /// `(G_1, eta)` as given to a standard-solid constructor: exact (`eta` is not recomputed
    /// from `G_1 tau`) and kept when the shear has no term (`G_1 = 0` or `eta = 0`).
    written: Option<(f64, f64)>,
    /// The static Poisson ratio the elastic bulk was computed from, when it was given as one
    /// ([`Material::with_poisson`], [`BulkInput::Poisson`]): how it was written, so that a scene
    /// writes it back as `poisson` ([`Material::written_poisson`]). Not part of `==`.
    poisson: Option<f64>,
    /// Mass density (kg/m³), when known: only the quasi-static check of an answer uses it
    /// ([`crate::model::validity`]).
    density: Option<f64>,
}

impl PartialEq for Material {
    fn eq(&self, other: &Self) -> bool {
        self.shear == other.shear
            && self.bulk == other.bulk
            && self.as_standard_solid() == other.as_standard_solid()
    }
}

impl Material {
    /// This material with the mass density `rho` (kg/m³, `0 < rho < inf`), which enables the
    /// quasi-static check of answers on it ([`crate::model::validity`]).
    pub fn with_density(mut self, rho: f64) -> Result<Self> {
        self.density = Some(crate::error::check(
            "density",
            rho,
            rho > 0.0,
            "0 < density < inf (kg/m^3)",
        )?);
        Ok(self)
    }

    /// The mass density (kg/m³), when given.
    pub fn density(&self) -> Option<f64> {
        self.density
    }

    /// Standard solid from its shear parameters and the bulk modulus `k_0` (all Pa, `eta` in
    /// Pa s).
    ///
    /// Ranges: `0 <= g_inf < inf`, `0 <= g_1 < inf`, `0 <= eta < inf`, `0 < k_0 < inf`;
    /// `g_inf = 0` (a Maxwell fluid) needs `g_1 > 0` and `eta > 0`.
    pub fn new(g_inf: f64, g_1: f64, eta: f64, k_0: f64) -> Result<Self> {
        let k_0 = check("k_0", k_0, k_0 > 0.0, "0 < k_0 < inf (Pa)")?;
        Self::with_bulk(g_inf, g_1, eta, Bulk::Modulus(k_0))
    }

    /// Standard solid from its shear parameters and the static Poisson ratio `nu` of Eq. (3).
    ///
    /// `-1 < nu <= 0.5`; `nu = 0.5` gives an incompressible material, otherwise
    /// `K_0 = 2 G_inf (1 + nu) / (3 (1 - 2 nu))` (so `nu = 0.5` only when `g_inf = 0`).
    pub fn with_poisson(g_inf: f64, g_1: f64, eta: f64, nu: f64) -> Result<Self> {
        let nu = check("nu", nu, nu > -1.0 && nu <= 0.5, "-1 < nu <= 0.5")?;
        let g_inf = check_g_inf(g_inf)?;
        if nu == 0.5 {
            return Self::with_bulk(g_inf, g_1, eta, Bulk::Incompressible);
        }
        if g_inf == 0.0 {
            // the message of the general form
            BulkInput::Poisson(nu).resolve(g_inf)?;
        }
        let k_0 = 2.0 * g_inf * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu));
        // For nu just above -1 or just below 0.5 the bulk modulus can leave the f64 range.
        if !(k_0.is_finite() && k_0 > 0.0) {
            return Err(crate::Error::OutOfRange {
                field: "nu",
                value: nu,
                allowed:
                    "-1 < nu <= 0.5 with K_0 = 2 G_inf (1 + nu) / (3 (1 - 2 nu)) finite and > 0",
            });
        }
        let mut m = Self::with_bulk(g_inf, g_1, eta, Bulk::Modulus(k_0))?;
        m.poisson = Some(nu);
        Ok(m)
    }

    /// Incompressible standard solid (`K_0 = inf`, `nu = 0.5`).
    pub fn incompressible(g_inf: f64, g_1: f64, eta: f64) -> Result<Self> {
        Self::with_bulk(g_inf, g_1, eta, Bulk::Incompressible)
    }

    /// Standard solid with an explicit [`Bulk`]: one shear term `(G_1, tau = eta / G_1)`, none
    /// when elastic (`G_1 = 0` or `eta = 0`).
    pub fn with_bulk(g_inf: f64, g_1: f64, eta: f64, bulk: Bulk) -> Result<Self> {
        let g_inf = check_g_inf(g_inf)?;
        let g_1 = check("g_1", g_1, g_1 >= 0.0, "0 <= g_1 < inf (Pa)")?;
        let eta = check("eta", eta, eta >= 0.0, "0 <= eta < inf (Pa s)")?;
        if g_inf == 0.0 && !(g_1 > 0.0 && eta > 0.0) {
            return Err(crate::Error::OutOfRange {
                field: "g_inf",
                value: g_inf,
                allowed: "g_inf > 0 unless g_1 > 0 and eta > 0 (g_inf = 0 with a Maxwell term: \
                          a viscoelastic liquid)",
            });
        }
        let bulk = match bulk {
            Bulk::Modulus(k) => {
                BulkRheology::Elastic(check("k_0", k, k > 0.0, "0 < k_0 < inf (Pa)")?)
            }
            Bulk::Incompressible => BulkRheology::Incompressible,
        };
        let term = (g_1 != 0.0 && eta != 0.0).then(|| (g_1, standard_tau(g_1, eta)));
        Ok(Self {
            shear: ShearProny::standard(g_inf, term),
            bulk,
            written: Some((g_1, eta)),
            poisson: None,
            density: None,
        })
    }

    /// Any material from its shear series and its bulk as written; checks `K_0`
    /// (`0 < K_0 < inf`, field `"k_0"`) and the Poisson ratio (`-1 < nu <= 0.5` with a finite
    /// positive `K_0`, field `"nu"`), and refuses `k_inf = 0` beside `g_inf > 0` (field `"k_inf"`).
    ///
    /// ```
    /// # use mdr_impact::model::material::{BulkInput, BulkRheology, Material, ShearProny};
    /// let shear = ShearProny::new(1.0, &[(99.0, 1.0)]).unwrap();
    /// let m = Material::general(shear, BulkInput::Poisson(0.3)).unwrap();
    /// // K_0 = 2 (1 + nu) / (3 (1 - 2 nu)) = 2.6 / 1.2 with g_inf = 1 (paper Eq. 3)
    /// let BulkRheology::Elastic(k) = m.bulk() else { panic!() };
    /// assert!((k - 2.6 / 1.2).abs() < 1e-15 * k);
    /// // one shear term and an elastic bulk: the standard solid's shape
    /// assert_eq!(m.as_standard_solid().unwrap().g_1(), 99.0);
    /// ```
    pub fn general(shear: ShearProny, bulk: BulkInput) -> Result<Self> {
        let given = match bulk {
            BulkInput::Poisson(nu) => Some(nu),
            _ => None,
        };
        let bulk = bulk.resolve(shear.g_inf())?;
        if let BulkRheology::Prony(p) = &bulk
            && p.k_inf() == 0.0
            && !shear.is_liquid()
        {
            // a solid's relaxed Poisson ratio would be -1, outside -1 < nu <= 0.5
            return Err(crate::Error::OutOfRange {
                field: "k_inf",
                value: 0.0,
                allowed: "0 < k_inf < inf (Pa) when g_inf > 0 (k_inf = 0 only for a liquid, \
                          g_inf = 0)",
            });
        }
        // an incompressible bulk is written as such whatever it was given as
        let poisson = given.filter(|_| matches!(bulk, BulkRheology::Elastic(_)));
        Ok(Self {
            shear,
            bulk,
            written: None,
            poisson,
            density: None,
        })
    }

    /// The standard solid's view of this material, if it has that shape: at most one shear term
    /// and an elastic or incompressible bulk, however it was written (with a standard-solid
    /// constructor, or as a Prony series of one term or none). `None` otherwise, and for a
    /// one-term series whose viscosity `g_1 tau_1` leaves the `f64` range.
    ///
    /// ```
    /// # use mdr_impact::model::material::{BulkInput, Material, ShearProny};
    /// let a = Material::with_poisson(1.0, 4.0, 2.0, 0.3).unwrap();
    /// let shear = ShearProny::new(1.0, &[(4.0, 0.5)]).unwrap();
    /// let b = Material::general(shear, BulkInput::Poisson(0.3)).unwrap();
    /// assert_eq!(a.as_standard_solid(), b.as_standard_solid());
    /// ```
    pub fn as_standard_solid(&self) -> Option<StandardSolid> {
        // a viscoelastic liquid has no relaxed modulus, so none of the standard solid's groups
        if self.shear.is_liquid() {
            return None;
        }
        self.standard_view()
    }

    /// The parameters `(g_inf, G_1, eta, bulk)` of a material built by a standard-solid
    /// constructor, as a [`StandardSolid`], also for a Maxwell fluid (`g_inf = 0`), which
    /// [`Material::as_standard_solid`] does not treat as one (its groups do not exist): for
    /// display and bindings only. `None` when not written as a standard solid.
    pub fn written_standard_solid(&self) -> Option<StandardSolid> {
        self.written.and_then(|_| self.standard_view())
    }

    /// The standard solid's view of the shape, liquid or not (see [`Material::as_standard_solid`]).
    fn standard_view(&self) -> Option<StandardSolid> {
        let bulk = match self.bulk {
            BulkRheology::Incompressible => Bulk::Incompressible,
            BulkRheology::Elastic(k) => Bulk::Modulus(k),
            BulkRheology::Prony(_) => return None,
        };
        let (g_1, eta, tau) = match (self.written, self.shear.terms()) {
            (Some((g_1, eta)), _) => (g_1, eta, standard_tau(g_1, eta)),
            (None, []) => (0.0, 0.0, f64::INFINITY),
            (None, &[(g, tau)]) => {
                let eta = g * tau;
                if !(eta.is_finite() && eta > 0.0) {
                    return None;
                }
                (g, eta, tau)
            }
            (None, _) => return None,
        };
        Some(StandardSolid {
            g_inf: self.shear.g_inf(),
            g_1,
            eta,
            tau,
            bulk,
        })
    }

    /// True when a standard-solid constructor built this material (with `G_1` and `eta`): how
    /// it was written, for display and export (a scene writes it back with the same keys). What
    /// is computed goes by shape ([`Material::as_standard_solid`]), never by this.
    pub fn is_written_as_standard_solid(&self) -> bool {
        self.written.is_some()
    }

    /// The static Poisson ratio the elastic bulk was computed from, when the material was given
    /// one ([`Material::with_poisson`] with `nu < 0.5`, [`BulkInput::Poisson`]): how it was
    /// written, for export (a scene writes `poisson = 0.49` back, not the `k_0` it gave). `None`
    /// for a bulk given as a modulus, a series or incompressible.
    ///
    /// ```
    /// # use mdr_impact::model::material::Material;
    /// assert_eq!(Material::with_poisson(1.0, 4.0, 2.0, 0.49).unwrap().written_poisson(), Some(0.49));
    /// assert_eq!(Material::new(1.0, 4.0, 2.0, 50.0).unwrap().written_poisson(), None);
    /// ```
    pub fn written_poisson(&self) -> Option<f64> {
        self.poisson
    }

    /// The shear relaxation.
    pub fn shear(&self) -> &ShearProny {
        &self.shear
    }

    /// The resolved bulk.
    pub fn bulk(&self) -> &BulkRheology {
        &self.bulk
    }

    /// Relaxed (static) shear modulus `G(inf) = g_inf` (Pa); 0 for a viscoelastic liquid.
    pub fn g_inf(&self) -> f64 {
        self.shear.g_inf()
    }

    /// True when the shear modulus relaxes to zero (`g_inf = 0`, [`ShearProny::is_liquid`]).
    pub fn is_liquid(&self) -> bool {
        self.shear.is_liquid()
    }

    /// The modulus scale of the canonical units (Pa; docs/theory.md §15): the relaxed shear
    /// modulus `g_inf` when positive, the glassy `G(0)` of a viscoelastic liquid (`g_inf = 0`).
    pub fn modulus_scale(&self) -> f64 {
        if self.shear.is_liquid() {
            self.shear.glassy()
        } else {
            self.shear.g_inf()
        }
    }

    /// Relaxed bulk modulus `K(inf)` (Pa), `inf` when incompressible.
    pub fn bulk_relaxed(&self) -> f64 {
        match &self.bulk {
            BulkRheology::Incompressible => f64::INFINITY,
            BulkRheology::Elastic(k) => *k,
            BulkRheology::Prony(p) => p.k_inf(),
        }
    }

    /// Glassy bulk modulus `K(0)` (Pa), `inf` when incompressible.
    pub fn bulk_glassy(&self) -> f64 {
        match &self.bulk {
            BulkRheology::Prony(p) => p.glassy(),
            _ => self.bulk_relaxed(),
        }
    }

    /// `K(t)` (Pa) at `t >= 0` (s), `inf` when incompressible.
    pub fn bulk_relaxation(&self, t: f64) -> f64 {
        match &self.bulk {
            BulkRheology::Prony(p) => p.relaxation(t),
            _ => self.bulk_relaxed(),
        }
    }

    /// Relaxed equivalent modulus `G_eq(t -> inf) = G (3K + G) / (3K + 4G)` with the relaxed
    /// `G = g_inf`, `K = k_inf` (Pa; docs/theory.md §2 and §8). Equals `g_inf` when incompressible.
    pub fn equivalent_relaxed(&self) -> f64 {
        rheology::equivalent_elastic(self.shear.g_inf(), self.bulk_relaxed())
    }

    /// Glassy equivalent modulus `G_eq(0) = G_0 (3K_0 + G_0) / (3K_0 + 4G_0)` with the glassy
    /// moduli `G_0 = G(0)`, `K_0 = K(0)` (Pa; docs/theory.md §2 and §8).
    pub fn equivalent_glassy(&self) -> f64 {
        rheology::equivalent_elastic(self.shear.glassy(), self.bulk_glassy())
    }

    /// The equivalent incompressible relaxation function `G_eq(t)` (Pa, s), chosen by shape in
    /// this one place: the closed form of docs/theory.md §2
    /// ([`StandardSolid::equivalent_relaxation`]) for the standard solid's shape, otherwise the
    /// exact Carson-domain composition ([`carson::equivalent_relaxation`], docs/theory.md §8),
    /// which errors only if a pole cannot be located ([`crate::Error::NoConvergence`]).
    ///
    /// ```
    /// # use mdr_impact::model::material::{carson, Material};
    /// let m = Material::with_poisson(1.0, 100.0, 1.0, 0.45).unwrap();
    /// let closed = m.equivalent_relaxation().unwrap(); // docs/theory.md §2
    /// let composed = carson::equivalent_relaxation(&m).unwrap(); // docs/theory.md §8
    /// for t in [0.0, 0.1, 1.0, 10.0] {
    ///     assert!((composed.eval(t) - closed.eval(t)).abs() < 1e-13 * closed.eval(t));
    /// }
    /// ```
    pub fn equivalent_relaxation(&self) -> Result<Prony> {
        match self.as_standard_solid() {
            Some(s) => Ok(s.equivalent_relaxation()),
            None => carson::equivalent_relaxation(self),
        }
    }
}

/// `tau = eta / G_1` of the standard solid (s): `inf` when `G_1 = 0`.
fn standard_tau(g_1: f64, eta: f64) -> f64 {
    if g_1 == 0.0 {
        f64::INFINITY
    } else {
        eta / g_1
    }
}

fn check_g_inf(g_inf: f64) -> Result<f64> {
    check("g_inf", g_inf, g_inf >= 0.0, "0 <= g_inf < inf (Pa)")
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn poisson_roundtrip() {
        for nu in [-0.99, -0.5, 0.0, 0.3, 0.45, 0.49, 0.499] {
            let m = Material::with_poisson(2.0, 3.0, 4.0, nu).unwrap();
            let s = m.as_standard_solid().unwrap();
            assert_relative_eq!(s.poisson(), nu, epsilon = 1e-13);
        }
        let m = Material::with_poisson(2.0, 3.0, 4.0, 0.5).unwrap();
        let s = m.as_standard_solid().unwrap();
        assert_eq!(s.bulk(), Bulk::Incompressible);
        assert_eq!(s.poisson(), 0.5);
    }

    #[test]
    fn equivalent_relaxation_limits() {
        let m = Material::with_poisson(1.0, 99.0, 1.0, 0.3)
            .unwrap()
            .as_standard_solid()
            .unwrap();
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

    /// The shape query recognises a standard solid however it was written, and keeps `G_1` and
    /// `eta` of an elastic one.
    #[test]
    fn shape_query() {
        let written = Material::with_poisson(3.0, 8.0, 4.0, 0.25).unwrap();
        let shear = ShearProny::new(3.0, &[(8.0, 0.5)]).unwrap();
        let series = Material::general(shear, BulkInput::Poisson(0.25)).unwrap();
        assert_eq!(written.as_standard_solid(), series.as_standard_solid());
        assert_eq!(written, series);
        let elastic = Material::with_poisson(3.0, 8.0, 0.0, 0.25).unwrap();
        let s = elastic.as_standard_solid().unwrap();
        assert_eq!((s.g_1(), s.eta(), s.tau()), (8.0, 0.0, 0.0));
        assert!(s.is_elastic() && elastic.shear().is_elastic());
        let none = Material::general(ShearProny::elastic(3.0).unwrap(), BulkInput::Elastic(5.0));
        let s = none.unwrap().as_standard_solid().unwrap();
        assert_eq!((s.g_1(), s.eta(), s.k_0()), (0.0, 0.0, 5.0));
        let two = ShearProny::new(3.0, &[(8.0, 0.5), (1.0, 5.0)]).unwrap();
        let two = Material::general(two, BulkInput::Incompressible).unwrap();
        assert!(two.as_standard_solid().is_none());
        let bulk = BulkProny::new(5.0, &[(1.0, 1.0)]).unwrap();
        let shear = ShearProny::new(3.0, &[(8.0, 0.5)]).unwrap();
        let relaxing = Material::general(shear, BulkInput::Prony(bulk)).unwrap();
        assert!(relaxing.as_standard_solid().is_none());
    }
}
