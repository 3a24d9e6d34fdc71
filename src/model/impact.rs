//! The impact problem (paper §2 and §4): sphere, impact velocity, material; the dimensionless
//! groups of Eq. (11); the outcome with the coefficient of restitution of Eq. (10).
//!
//! # Scaling
//! In the quasi-static problem the radius enters only through `G sqrt(R)` and `eta sqrt(R)`, so
//! every solver works in *canonical units* `m = R = v0 = G_inf = 1`, in which
//! `G_1 = 1/p2`, `eta = p3`, `tau = p2 p3` and `K_0` follows from `nu`. The canonical solution
//! maps back to SI with the scales of [`Scales`]:
//! length `L = (m v0^2 / (G_inf sqrt(R)))^(2/5)`, time `L / v0`, force `m v0^2 / L`,
//! energy `m v0^2`, contact radius `sqrt(R L)`.
//!
//! The half-space is the standard solid of the paper or a general linear-viscoelastic solid
//! ([`ImpactMaterial`]); for the latter `G_inf` is its relaxed shear modulus `g_inf`, and the
//! dimensionless groups of Eq. (11) do not exist ([`Impact::groups`] is `None`).

use crate::error::{check, Error, Result};
use crate::model::bodies::TwoBodies;
use crate::model::material::{Bulk, GeneralMaterial, Material, Prony};

/// A rigid sphere: mass `m` (kg) and radius `R` (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    mass: f64,
    radius: f64,
}

impl Sphere {
    /// Sphere with mass (kg) and radius (m), both `0 < x < inf`.
    pub fn new(mass: f64, radius: f64) -> Result<Self> {
        Ok(Self {
            mass: check("mass", mass, mass > 0.0, "0 < mass < inf (kg)")?,
            radius: check("radius", radius, radius > 0.0, "0 < radius < inf (m)")?,
        })
    }
    /// Mass (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Radius (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

/// The dimensionless groups of Eq. (11): `p1 = nu`, `p2 = G_inf / G_1`,
/// `p3 = eta (v0 R / (m^2 G_inf^3))^(1/5)`.
///
/// [`Groups::new`] takes user input and refuses every non-finite value (`inf`, `NaN`, `1e999`).
/// The elastic limit is `p3 = 0` (`eta = 0`: Hertz with `G_inf`, `e = 1`). [`Impact::groups`]
/// of an elastic material with `G_1 = 0` reports `p2 = inf`, which
/// [`Groups::canonical_material`] maps back to `G_1 = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Groups {
    /// Static Poisson ratio, `-1 < nu <= 0.5` (`0.5`: incompressible).
    pub nu: f64,
    /// `G_inf / G_1`, `0 < p2 < inf` with `1/p2` finite (`inf` only from [`Impact::groups`]).
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

/// Scales that map canonical results to SI (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scales {
    /// Length scale of the indentation, `L` (m).
    pub length: f64,
    /// Time scale `L / v0` (s).
    pub time: f64,
    /// Force scale `m v0^2 / L` (N).
    pub force: f64,
    /// Energy scale `m v0^2` (J).
    pub energy: f64,
    /// Velocity scale `v0` (m/s).
    pub velocity: f64,
    /// Contact-radius scale `sqrt(R L)` (m).
    pub radius: f64,
    /// Modulus scale `G_inf` (Pa).
    pub modulus: f64,
}

/// The half-space material of an [`Impact`]: the paper's standard solid, or a general
/// linear-viscoelastic solid (Prony series in shear and bulk, docs/theory.md §8) of which the
/// standard solid is the one-term case.
#[derive(Debug, Clone, PartialEq)]
pub enum ImpactMaterial {
    /// Standard solid in shear with elastic bulk (paper Eqs. 1–3).
    StandardSolid(Material),
    /// General linear viscoelasticity in shear and bulk.
    General(GeneralMaterial),
    /// Two colliding bodies (docs/theory.md §8): the half-space has their combined compliance
    /// and the sphere their effective mass and radius.
    TwoBodies(Box<TwoBodies>),
}

impl ImpactMaterial {
    /// The modulus scale `G_inf` of the canonical units (Pa): the relaxed shear modulus
    /// `G(inf)`; for two bodies their relaxed shear moduli combined like compliances
    /// ([`TwoBodies::modulus_scale`]).
    pub fn g_inf(&self) -> f64 {
        match self {
            ImpactMaterial::StandardSolid(m) => m.g_inf(),
            ImpactMaterial::General(m) => m.shear().g_inf(),
            ImpactMaterial::TwoBodies(b) => b.modulus_scale(),
        }
    }
}

/// A validated impact: sphere, impact velocity `v0` (m/s) and half-space material.
///
/// The equivalent relaxation function `G_eq(t)` (SI) is computed once, at construction: the
/// closed form of docs/theory.md §2 for the standard solid, the Carson-domain composition of
/// [`GeneralMaterial::equivalent_relaxation`] for a general material.
#[derive(Debug, Clone, PartialEq)]
pub struct Impact {
    sphere: Sphere,
    velocity: f64,
    material: ImpactMaterial,
    /// `G_eq(t)` in SI (Pa, s).
    equivalent: Prony,
}

impl Impact {
    /// Impact of `sphere` at speed `velocity` (m/s, `0 < v0 < inf`) on the standard solid
    /// `material`.
    pub fn new(sphere: Sphere, velocity: f64, material: Material) -> Result<Self> {
        let equivalent = material.equivalent_relaxation();
        Self::build(
            sphere,
            velocity,
            ImpactMaterial::StandardSolid(material),
            equivalent,
        )
    }

    /// Impact of `sphere` at speed `velocity` (m/s, `0 < v0 < inf`) on a general
    /// linear-viscoelastic `material`. Its `G_eq(t)` must stay a valid Prony series in canonical
    /// units (finite, positive times and relaxed modulus), otherwise [`Error::NonFinite`] or
    /// [`Error::OutOfRange`].
    ///
    /// ```
    /// # use mdr_impact::{Impact, Material, Sphere};
    /// let m = Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.49).unwrap();
    /// let s = Sphere::new(4.11e-3, 5.0e-3).unwrap();
    /// let general = Impact::with_general(s, 0.99, m.general()).unwrap();
    /// assert!(general.groups().is_none()); // groups belong to the standard solid
    /// let standard = Impact::new(s, 0.99, m).unwrap();
    /// let (a, b) = (general.canonical_relaxation(), standard.canonical_relaxation());
    /// assert!((a.glassy() - b.glassy()).abs() < 1e-13 * b.glassy());
    /// ```
    pub fn with_general(sphere: Sphere, velocity: f64, material: GeneralMaterial) -> Result<Self> {
        let equivalent = material.equivalent_relaxation()?;
        Self::build(
            sphere,
            velocity,
            ImpactMaterial::General(material),
            equivalent,
        )
    }

    /// Collision of two bodies at the relative normal velocity `velocity` (m/s): a rigid sphere
    /// of the effective mass and radius on a half-space with the combined `G_tot`
    /// ([`TwoBodies`]). [`Impact::sphere`] is then the effective sphere and
    /// [`Impact::equivalent_relaxation`] is `G_tot`.
    pub fn with_bodies(bodies: TwoBodies, velocity: f64) -> Result<Self> {
        let sphere = Sphere::new(bodies.effective_mass(), bodies.effective_radius())?;
        let equivalent = bodies.combined_relaxation().clone();
        Self::build(
            sphere,
            velocity,
            ImpactMaterial::TwoBodies(Box::new(bodies)),
            equivalent,
        )
    }

    /// The same impact at another velocity `v0` (m/s): sphere(s) and material(s) unchanged.
    pub fn at_velocity(&self, velocity: f64) -> Result<Self> {
        Self::build(
            self.sphere,
            velocity,
            self.material.clone(),
            self.equivalent.clone(),
        )
    }

    fn build(
        sphere: Sphere,
        velocity: f64,
        material: ImpactMaterial,
        equivalent: Prony,
    ) -> Result<Self> {
        let velocity = check(
            "velocity",
            velocity,
            velocity > 0.0,
            "0 < velocity < inf (m/s)",
        )?;
        let imp = Self {
            sphere,
            velocity,
            material,
            equivalent,
        };
        // Extreme magnitudes can leave the f64 range when scaled; refuse them here, loudly.
        let s = imp.scales();
        for (what, v) in [
            ("length scale", s.length),
            ("time scale", s.time),
            ("force scale", s.force),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(crate::Error::NonFinite { what, value: v });
            }
        }
        if let Some(g) = imp.groups() {
            if !g.p3.is_finite() {
                return Err(crate::Error::NonFinite {
                    what: "p3",
                    value: g.p3,
                });
            }
        }
        // the series the solvers get: every modulus and time finite and positive in canonical
        // units (extreme times or moduli can underflow or overflow when scaled)
        let c = imp.canonical_relaxation();
        for (what, v) in std::iter::once(("canonical G_eq(inf)", c.relaxed)).chain(
            c.terms.iter().flat_map(|t| {
                [
                    ("canonical G_eq time", t.tau),
                    ("canonical G_eq term", t.coefficient),
                ]
            }),
        ) {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::NonFinite { what, value: v });
            }
        }
        Ok(imp)
    }

    /// The impact in canonical units `m = R = v0 = G_inf = 1` with the given groups.
    pub fn from_groups(groups: Groups) -> Result<Self> {
        Self::new(Sphere::new(1.0, 1.0)?, 1.0, groups.canonical_material()?)
    }

    /// The sphere.
    pub fn sphere(&self) -> Sphere {
        self.sphere
    }
    /// Impact velocity `v0` (m/s).
    pub fn velocity(&self) -> f64 {
        self.velocity
    }
    /// The half-space material.
    pub fn material(&self) -> &ImpactMaterial {
        &self.material
    }

    /// The standard solid, if the material is one (`None` for a general material, even a
    /// one-term one: its `G_eq` comes from a different route, see [`Impact::with_general`]).
    pub fn standard_solid(&self) -> Option<&Material> {
        match &self.material {
            ImpactMaterial::StandardSolid(m) => Some(m),
            ImpactMaterial::General(_) | ImpactMaterial::TwoBodies(_) => None,
        }
    }

    /// The general material, if the impact has one.
    pub fn general_material(&self) -> Option<&GeneralMaterial> {
        match &self.material {
            ImpactMaterial::General(m) => Some(m),
            ImpactMaterial::StandardSolid(_) | ImpactMaterial::TwoBodies(_) => None,
        }
    }

    /// The two bodies, if the impact is a two-body collision.
    pub fn bodies(&self) -> Option<&TwoBodies> {
        match &self.material {
            ImpactMaterial::TwoBodies(b) => Some(b),
            _ => None,
        }
    }

    /// The equivalent relaxation function `G_eq(t)` in SI (Pa, s).
    pub fn equivalent_relaxation(&self) -> &Prony {
        &self.equivalent
    }

    /// True when `G_eq(t)` is constant for `t > 0` (no decaying term): the Hertz closed form
    /// with the relaxed modulus is exact.
    pub fn is_elastic(&self) -> bool {
        match &self.material {
            ImpactMaterial::StandardSolid(m) => m.is_elastic(),
            ImpactMaterial::General(_) | ImpactMaterial::TwoBodies(_) => {
                self.equivalent.is_elastic()
            }
        }
    }

    /// Plane-strain modulus `E* = 4 G_eq(inf)` (Pa) of the relaxed material (the Hertz limit).
    pub fn relaxed_effective_modulus(&self) -> f64 {
        match &self.material {
            ImpactMaterial::StandardSolid(m) => m.effective_modulus(m.g_inf()),
            ImpactMaterial::General(_) | ImpactMaterial::TwoBodies(_) => {
                4.0 * self.equivalent.relaxed
            }
        }
    }

    /// Dimensionless groups, Eq. (11), of a standard solid; `None` for a general material,
    /// which has no such three groups.
    pub fn groups(&self) -> Option<Groups> {
        let ImpactMaterial::StandardSolid(m) = &self.material else {
            return None;
        };
        let p2 = if m.g_1() == 0.0 {
            f64::INFINITY
        } else {
            m.g_inf() / m.g_1()
        };
        // p3 = eta / (G_inf T) with T the time scale: algebraically Eq. (11), better conditioned.
        let p3 = m.eta() / (m.g_inf() * self.scales().time);
        let nu = match m.bulk() {
            Bulk::Incompressible => 0.5,
            Bulk::Modulus(_) => m.poisson(),
        };
        Some(Groups { nu, p2, p3 })
    }

    /// Scales from canonical units to SI.
    pub fn scales(&self) -> Scales {
        let (m, r, v) = (self.sphere.mass, self.sphere.radius, self.velocity);
        let g = self.material.g_inf();
        // L = (m v^2 / (G sqrt(R)))^(2/5), computed in logs to survive extreme magnitudes.
        let ln_l = 0.4 * (m.ln() + 2.0 * v.ln() - g.ln() - 0.5 * r.ln());
        let length = ln_l.exp();
        Scales {
            length,
            time: (ln_l - v.ln()).exp(),
            force: (m.ln() + 2.0 * v.ln() - ln_l).exp(),
            energy: m * v * v,
            velocity: v,
            radius: (0.5 * (r.ln() + ln_l)).exp(),
            modulus: g,
        }
    }

    /// Equivalent relaxation function in canonical units (moduli / `G_inf`, times / `L/v0`),
    /// `G_inf` the relaxed shear modulus (`g_inf` of a general material).
    pub fn canonical_relaxation(&self) -> Prony {
        let s = self.scales();
        self.equivalent.scaled(s.modulus, s.time)
    }
}

/// Histories of an impact (or an indentation), sampled at the solver's steps.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct History {
    /// Time (s).
    pub t: Vec<f64>,
    /// Indentation depth `d` (m).
    pub d: Vec<f64>,
    /// Indentation rate `d'` (m/s); the sphere's velocity into the half-space.
    pub v: Vec<f64>,
    /// Contact force (N).
    pub force: Vec<f64>,
    /// Contact radius (m).
    pub a: Vec<f64>,
}

impl History {
    /// Append one sample.
    pub fn push(&mut self, t: f64, d: f64, v: f64, force: f64, a: f64) {
        self.t.push(t);
        self.d.push(d);
        self.v.push(v);
        self.force.push(force);
        self.a.push(a);
    }
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.t.len()
    }
    /// True when empty.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }
    fn scale(&mut self, s: &Scales) {
        self.t.iter_mut().for_each(|x| *x *= s.time);
        self.d.iter_mut().for_each(|x| *x *= s.length);
        self.v.iter_mut().for_each(|x| *x *= s.velocity);
        self.force.iter_mut().for_each(|x| *x *= s.force);
        self.a.iter_mut().for_each(|x| *x *= s.radius);
    }
}

/// Work counters of a solve, so that a change in work is noticed as surely as a change in result.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Work {
    /// Time steps taken (summed over refinement levels).
    pub steps: u64,
    /// Largest number of MDR elements used.
    pub elements: u64,
    /// Element updates (element-steps), summed over levels.
    pub element_updates: u64,
    /// Integrand / right-hand-side evaluations (reference and fast solvers).
    pub evaluations: u64,
    /// Refinement levels of the adaptive driver.
    pub levels: u32,
}

/// What an impact produced. All quantities SI unless stated.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// Coefficient of restitution `e = -v_end / v0`, Eq. (10) (dimensionless).
    pub cor: f64,
    /// Rebound velocity `|d'|` at separation (m/s).
    pub rebound_velocity: f64,
    /// Contact duration (s).
    pub contact_time: f64,
    /// Maximum indentation depth (m).
    pub max_indentation: f64,
    /// Time of maximum indentation (s).
    pub time_of_max_indentation: f64,
    /// Maximum contact force (N).
    pub max_force: f64,
    /// Maximum contact radius (m).
    pub max_contact_radius: f64,
    /// Energy dissipated in the half-space, `m (v0^2 - v^2) / 2` (J).
    pub dissipated_energy: f64,
    /// Estimated relative error of the CoR (from the adaptive driver), if known.
    pub cor_error_estimate: Option<f64>,
    /// Histories when requested.
    pub history: Option<History>,
    /// Work counters.
    pub work: Work,
    /// Name of the solver that produced it.
    pub solver: &'static str,
    /// Why `auto` did not answer with its first choice: the refusal of `fast` when `reference`
    /// answered instead (`None` otherwise).
    pub fallback: Option<String>,
}

impl Outcome {
    /// Map a canonical outcome (`m = R = v0 = G_inf = 1`) to SI with the impact's scales.
    pub fn to_si(mut self, impact: &Impact) -> Outcome {
        let s = impact.scales();
        self.rebound_velocity *= s.velocity;
        self.contact_time *= s.time;
        self.max_indentation *= s.length;
        self.time_of_max_indentation *= s.time;
        self.max_force *= s.force;
        self.max_contact_radius *= s.radius;
        // canonical energy is in units of m v0^2
        self.dissipated_energy *= s.energy;
        if let Some(h) = self.history.as_mut() {
            h.scale(&s);
        }
        self
    }
}
