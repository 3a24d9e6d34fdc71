//! Two bodies colliding (docs/theory.md §8): two spheres, a sphere and a wall, each viscoelastic,
//! elastic or rigid.
//!
//! The contact of bodies A and B (masses `m_A`, `m_B`, radii `R_A`, `R_B`, relative normal
//! velocity `v0`) is that of a rigid sphere with the effective mass and radius
//!
//! ```text
//! m = m_A m_B / (m_A + m_B),   R = R_A R_B / (R_A + R_B)      (an infinite one drops out)
//! ```
//!
//! on a half-space whose compliances add, `1/G_tot(s) = 1/G_eq,A(s) + 1/G_eq,B(s)` in Carson form
//! (a rigid body adds nothing). [`TwoBodies::new`] forms `G_tot` as an exact Prony series
//! ([`carson::combine`]) for `fast` and `reference`; `mdr` never forms it and stacks the two
//! bodies' element networks instead ([`crate::model::material::StackedNetwork`]), the independent path.
//!
//! A wall is a body with `radius = inf` (and usually `mass = inf`); a rigid body has no
//! compliance. Velocities after the impact are reported in the frame where B is at rest before
//! it ([`TwoBodies::rebound_velocities`]).

use crate::error::{Error, Result};
use crate::model::material::{carson, Material, Prony};

/// What a body is made of.
#[derive(Debug, Clone, PartialEq)]
pub enum BodyMaterial {
    /// No compliance (`1/G_eq = 0`).
    Rigid,
    /// A linear-viscoelastic (or elastic) [`Material`], the standard solid among them.
    Viscoelastic(Material),
}

impl BodyMaterial {
    /// The body's equivalent relaxation function `G_eq(t)` (SI), `None` when rigid.
    pub fn equivalent_relaxation(&self) -> Result<Option<Prony>> {
        self.material()
            .map(Material::equivalent_relaxation)
            .transpose()
    }

    /// The material, `None` when rigid.
    pub fn material(&self) -> Option<&Material> {
        match self {
            BodyMaterial::Rigid => None,
            BodyMaterial::Viscoelastic(m) => Some(m),
        }
    }

    /// Relaxed shear modulus (Pa), `inf` when rigid.
    pub fn g_inf(&self) -> f64 {
        self.material().map_or(f64::INFINITY, Material::g_inf)
    }

    /// The material's modulus scale ([`Material::modulus_scale`]: `g_inf`, or the glassy shear
    /// modulus of a liquid) (Pa), `inf` when rigid.
    pub fn modulus_scale(&self) -> f64 {
        self.material()
            .map_or(f64::INFINITY, Material::modulus_scale)
    }

    /// True for a rigid body.
    pub fn is_rigid(&self) -> bool {
        matches!(self, BodyMaterial::Rigid)
    }
}

/// One body: mass (kg), radius (m) and material. Mass and radius may be infinite (a wall).
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    mass: f64,
    radius: f64,
    material: BodyMaterial,
}

impl Body {
    /// A body of `mass` (kg, `0 < mass <= inf`) and `radius` (m, `0 < radius <= inf`; `inf`
    /// for a flat wall). Errors name the field and are placed at the body ([`Error::In`],
    /// `"body A"`).
    pub fn new(name: Side, mass: f64, radius: f64, material: BodyMaterial) -> Result<Self> {
        Self::unplaced(mass, radius, material).map_err(|e| e.at(name.place()))
    }

    fn unplaced(mass: f64, radius: f64, material: BodyMaterial) -> Result<Self> {
        let check = |field, v: f64, allowed| {
            if v > 0.0 {
                Ok(v)
            } else {
                Err(Error::OutOfRange {
                    field,
                    value: v,
                    allowed,
                })
            }
        };
        Ok(Self {
            mass: check("mass", mass, "0 < mass <= inf (kg)")?,
            radius: check("radius", radius, "0 < radius <= inf (m; inf: a wall)")?,
            material,
        })
    }

    /// A body of the given `density` (kg/m^3, finite and positive) and finite `radius` (m):
    /// `mass = 4/3 pi R^3 density`.
    pub fn with_density(
        name: Side,
        density: f64,
        radius: f64,
        material: BodyMaterial,
    ) -> Result<Self> {
        let place = |e: Error| e.at(name.place());
        crate::error::check(
            "density",
            density,
            density > 0.0,
            "0 < density < inf (kg/m^3)",
        )
        .map_err(place)?;
        crate::error::check(
            "radius",
            radius,
            radius > 0.0,
            "0 < radius < inf (m) with a density (a wall needs mass = inf)",
        )
        .map_err(place)?;
        let mass = 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3) * density;
        Self::new(name, mass, radius, material)
    }

    /// Mass (kg), possibly `inf`.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Radius (m), possibly `inf` (a wall).
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// The body's material.
    pub fn material(&self) -> &BodyMaterial {
        &self.material
    }
}

/// Which body: the first (`A`) or the second (`B`) of a collision.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The first body.
    A,
    /// The second body.
    B,
}

impl Side {
    /// Where an error about this body arose, for [`Error::In`]: `"body A"`, `"body B"`.
    pub fn place(self) -> &'static str {
        match self {
            Side::A => "body A",
            Side::B => "body B",
        }
    }
}

/// `x y / (x + y)` with an infinite argument dropping out (`inf` only when both are).
pub fn harmonic(x: f64, y: f64) -> f64 {
    match (x.is_infinite(), y.is_infinite()) {
        (true, _) => y,
        (_, true) => x,
        // x / (1 + x/y): no overflow of x y for large magnitudes
        _ => x / (1.0 + x / y),
    }
}

/// Two bodies in contact, validated, with their combined `G_tot(t)`.
#[derive(Debug, Clone, PartialEq)]
pub struct TwoBodies {
    a: Body,
    b: Body,
    combined: Prony,
}

impl TwoBodies {
    /// Bodies A and B. Refused ([`Error::InvalidBodies`]): both rigid (no compliance: the impact is instantaneous), both of
    /// infinite mass (nothing moves), both of infinite radius (two walls: no Hertz contact).
    pub fn new(a: Body, b: Body) -> Result<Self> {
        if a.material.is_rigid() && b.material.is_rigid() {
            return Err(Error::InvalidBodies {
                reason: "both bodies are rigid; at least one must deform",
            });
        }
        if a.mass.is_infinite() && b.mass.is_infinite() {
            return Err(Error::InvalidBodies {
                reason: "both masses are infinite; at least one body must be free to move",
            });
        }
        if a.radius.is_infinite() && b.radius.is_infinite() {
            return Err(Error::InvalidBodies {
                reason: "both radii are infinite (two walls); at least one body must be a sphere",
            });
        }
        let combined = match (
            a.material.equivalent_relaxation()?,
            b.material.equivalent_relaxation()?,
        ) {
            (Some(ga), Some(gb)) => carson::combine(&ga, &gb)?,
            (Some(g), None) | (None, Some(g)) => g,
            (None, None) => return Err(Error::Internal("two rigid bodies passed the check")),
        };
        Ok(Self { a, b, combined })
    }

    /// Body A.
    pub fn a(&self) -> &Body {
        &self.a
    }
    /// Body B.
    pub fn b(&self) -> &Body {
        &self.b
    }

    /// Effective mass `m_A m_B / (m_A + m_B)` (kg).
    pub fn effective_mass(&self) -> f64 {
        harmonic(self.a.mass, self.b.mass)
    }

    /// Effective radius `R_A R_B / (R_A + R_B)` (m).
    pub fn effective_radius(&self) -> f64 {
        harmonic(self.a.radius, self.b.radius)
    }

    /// The combined relaxation `G_tot(t)` (SI), `1/G_tot = 1/G_eq,A + 1/G_eq,B` in Carson form.
    pub fn combined_relaxation(&self) -> &Prony {
        &self.combined
    }

    /// The modulus scale of the canonical units (Pa): the bodies' modulus scales
    /// ([`BodyMaterial::modulus_scale`]: the relaxed shear moduli, or the glassy one of a
    /// liquid) combined like compliances (a rigid body drops out, so a rigid B gives A's scale
    /// exactly).
    pub fn modulus_scale(&self) -> f64 {
        harmonic(
            self.a.material.modulus_scale(),
            self.b.material.modulus_scale(),
        )
    }

    /// Velocities of A and B after the impact (m/s, along the line of approach, positive in
    /// A's approach direction), in the frame where B was at rest and A approached at `v0`:
    /// momentum is conserved and the relative velocity reverses to `e v0`:
    /// `v_A = v0 (m_A - e m_B) / (m_A + m_B)`, `v_B = v0 m_A (1 + e) / (m_A + m_B)`
    /// (a body of infinite mass keeps its velocity).
    pub fn rebound_velocities(&self, v0: f64, cor: f64) -> (f64, f64) {
        let (ma, mb) = (self.a.mass, self.b.mass);
        if mb.is_infinite() {
            (-cor * v0, 0.0)
        } else if ma.is_infinite() {
            (v0, v0 * (1.0 + cor))
        } else {
            // shares of the total mass, without forming m_A + m_B of huge values
            let (sa, sb) = (1.0 / (1.0 + mb / ma), 1.0 / (1.0 + ma / mb));
            (v0 * (sa - cor * sb), v0 * sa * (1.0 + cor))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn harmonic_drops_infinities() {
        assert_eq!(harmonic(2.0, f64::INFINITY), 2.0);
        assert_eq!(harmonic(f64::INFINITY, 3.0), 3.0);
        assert_eq!(harmonic(2.0, 2.0), 1.0);
        assert!((harmonic(1e300, 1e300) - 5e299).abs() < 1e285);
    }

    #[test]
    fn momentum_is_conserved_and_relative_velocity_reverses() {
        let m = Material::with_poisson(1e6, 1e7, 500.0, 0.45).unwrap();
        for (ma, mb) in [
            (1.0, 1.0),
            (2.0, 0.5),
            (1.0, f64::INFINITY),
            (f64::INFINITY, 3.0),
        ] {
            let a = Body::new(Side::A, ma, 1.0, BodyMaterial::Viscoelastic(m.clone())).unwrap();
            let b = Body::new(Side::B, mb, 1.0, BodyMaterial::Rigid).unwrap();
            let two = TwoBodies::new(a, b).unwrap();
            let (va, vb) = two.rebound_velocities(2.0, 0.6);
            assert!((vb - va - 1.2).abs() < 1e-14, "{ma} {mb}: {va} {vb}");
            if ma.is_finite() && mb.is_finite() {
                assert!((ma * va + mb * vb - ma * 2.0).abs() < 1e-14);
            }
        }
    }
}
