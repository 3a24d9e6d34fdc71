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
//! The target ([`Target`]) is a half-space of any [`Material`] or two colliding bodies; `G_inf` is
//! the relaxed shear modulus `g_inf`, and the dimensionless groups of Eq. (11) exist for a
//! half-space of the standard solid's shape only ([`Impact::groups`]). A viscoelastic liquid
//! (`g_inf = 0`) has no relaxed modulus: its scale `G_inf` is the glassy shear modulus `G(0)`
//! instead ([`Target::modulus_scale`], docs/theory.md §15), and its relaxed limits do not exist
//! ([`Target::relaxes_to_zero`]).

use crate::error::{check, Error, Result};
use crate::model::bodies::TwoBodies;
use crate::model::geometry::Shape;
pub use crate::model::material::Groups;
use crate::model::material::{poles, Material, Prony, StandardSolid};

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
    /// An impactor of `mass` (kg) without a radius (a cone or a power-law indenter): its
    /// radius reads `inf`, and the validity checks that compare with it do not apply.
    pub fn without_radius(mass: f64) -> Result<Self> {
        Ok(Self {
            mass: check("mass", mass, mass > 0.0, "0 < mass < inf (kg)")?,
            radius: f64::INFINITY,
        })
    }
    /// Mass (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Radius (m; `inf` for an impactor without one, [`Sphere::without_radius`]).
    pub fn radius(&self) -> f64 {
        self.radius
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
    /// Modulus scale `G_inf` (Pa): the relaxed shear modulus, or the glassy one of a liquid.
    pub modulus: f64,
}

/// What the sphere hits: a half-space of a [`Material`], or two colliding bodies whose contact is
/// that of the effective sphere on a half-space of their combined compliance (docs/theory.md §8).
#[derive(Debug, Clone, PartialEq)]
pub enum Target {
    /// A half-space of a linear-viscoelastic material (the standard solid among them).
    HalfSpace(Material),
    /// Two colliding bodies (docs/theory.md §8): the half-space has their combined compliance
    /// and the sphere their effective mass and radius.
    TwoBodies(Box<TwoBodies>),
}

impl Target {
    /// The modulus scale `G_inf` of the canonical units (Pa): the relaxed shear modulus
    /// `G(inf)`, or for a viscoelastic liquid (`g_inf = 0`) the glassy `G(0)`
    /// ([`Material::modulus_scale`], docs/theory.md §15); for two bodies their scales combined
    /// like compliances ([`TwoBodies::modulus_scale`]).
    pub fn modulus_scale(&self) -> f64 {
        match self {
            Target::HalfSpace(m) => m.modulus_scale(),
            Target::TwoBodies(b) => b.modulus_scale(),
        }
    }

    /// True when the relaxed equivalent modulus `G_eq(inf)` is zero: a half-space of a
    /// viscoelastic liquid, or two bodies of which one is a liquid. The relaxed limits (Hertz
    /// with the relaxed modulus, the groups of Eq. 11, the DEM relaxed law) do not apply.
    pub fn relaxes_to_zero(&self) -> bool {
        match self {
            Target::HalfSpace(m) => m.is_liquid(),
            Target::TwoBodies(b) => [b.a(), b.b()]
                .iter()
                .any(|body| body.material().material().is_some_and(Material::is_liquid)),
        }
    }
}

/// A validated impact: sphere, impact velocity `v0` (m/s) and half-space material.
///
/// The equivalent relaxation function `G_eq(t)` (SI) is computed once, at construction, by
/// [`Material::equivalent_relaxation`] (chosen by the material's shape).
#[derive(Debug, Clone, PartialEq)]
pub struct Impact {
    sphere: Sphere,
    /// The indenter's shape (the paraboloid of the sphere's radius unless set otherwise).
    shape: Shape,
    velocity: f64,
    target: Target,
    /// `G_eq(t)` in SI (Pa, s).
    equivalent: Prony,
}

/// Smallest `p2 = G_inf / G_1` that [`Impact::from_groups`] answers: squares of the glassy
/// modulus `1 / p2` (canonical units) overflow beyond about `1e-280`, and `1e-250` answered
/// (with `tau = p2 p3 = 1`).
pub const MIN_P2: f64 = 1e-250;

impl Impact {
    /// Impact of `sphere` at speed `velocity` (m/s, `0 < v0 < inf`) on a half-space of
    /// `material`. Its `G_eq(t)` must stay a valid Prony series in canonical units (finite,
    /// positive times and relaxed modulus), otherwise [`Error::NonFinite`] or
    /// [`Error::OutOfRange`].
    ///
    /// ```
    /// # use mdr_impact::{Impact, Material, Sphere};
    /// # use mdr_impact::model::material::{BulkInput, ShearProny};
    /// let m = Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.49).unwrap();
    /// let s = Sphere::new(4.11e-3, 5.0e-3).unwrap();
    /// let standard = Impact::new(s, 0.99, m).unwrap();
    /// assert!(standard.groups().is_some());
    /// // the same shape written as a one-term Prony series: the same groups
    /// let shear = ShearProny::new(1.0e6, &[(1.0e7, 500.0 / 1.0e7)]).unwrap();
    /// let series = Material::general(shear, BulkInput::Poisson(0.49)).unwrap();
    /// let general = Impact::new(s, 0.99, series).unwrap();
    /// let (a, b) = (general.groups().unwrap(), standard.groups().unwrap());
    /// assert!((a.p3 - b.p3).abs() < 1e-15 * b.p3);
    /// ```
    pub fn new(sphere: Sphere, velocity: f64, material: Material) -> Result<Self> {
        let shape = Shape::Paraboloid {
            radius: sphere.radius,
        };
        Self::shaped(sphere, shape, velocity, material)
    }

    /// An impactor of `sphere`'s mass with the shape `shape` (docs/theory.md §11) at `velocity`
    /// (m/s) on a half-space of `material`; `sphere`'s radius is the nominal size the validity
    /// checks compare with (`inf`: none, [`Sphere::without_radius`]).
    pub fn shaped(sphere: Sphere, shape: Shape, velocity: f64, material: Material) -> Result<Self> {
        let equivalent = material.equivalent_relaxation()?;
        Self::build(
            sphere,
            shape.validated()?,
            velocity,
            Target::HalfSpace(material),
            equivalent,
        )
    }

    /// The same as [`Impact::new`] (kept for callers that name a general material so).
    pub fn with_general(sphere: Sphere, velocity: f64, material: Material) -> Result<Self> {
        Self::new(sphere, velocity, material)
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
            Shape::Paraboloid {
                radius: sphere.radius,
            },
            velocity,
            Target::TwoBodies(Box::new(bodies)),
            equivalent,
        )
    }

    /// The same impact at another velocity `v0` (m/s): sphere(s) and material(s) unchanged.
    pub fn at_velocity(&self, velocity: f64) -> Result<Self> {
        Self::build(
            self.sphere,
            self.shape,
            velocity,
            self.target.clone(),
            self.equivalent.clone(),
        )
    }

    /// The same impact with the indenter's shape `shape` (docs/theory.md §11; mass, velocity and
    /// material unchanged). The sphere's radius stays the nominal size the validity checks use.
    pub fn with_shape(mut self, shape: Shape) -> Result<Self> {
        self.shape = shape.validated()?;
        self.check_scales()?;
        Ok(self)
    }

    fn build(
        sphere: Sphere,
        shape: Shape,
        velocity: f64,
        target: Target,
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
            shape,
            velocity,
            target,
            equivalent,
        };
        imp.check_scales()?;
        Ok(imp)
    }

    /// Refuse magnitudes whose canonical form leaves the f64 range (module docs), naming the
    /// inputs that made them ([`Error::OutOfScale`]).
    fn check_scales(&self) -> Result<()> {
        let imp = self;
        let inputs = || {
            format!(
                "mass {:e} kg, {}, velocity {:e} m/s, {} {:e} Pa",
                imp.sphere.mass,
                imp.shape.describe(),
                imp.velocity,
                if imp.target.relaxes_to_zero() {
                    "modulus scale (glassy shear modulus of the liquid)"
                } else {
                    "relaxed shear modulus"
                },
                imp.target.modulus_scale()
            )
        };
        let out = |what, value| Error::OutOfScale {
            what,
            value,
            inputs: inputs(),
        };
        let s = imp.scales();
        for (what, v) in [
            ("the indentation scale (m)", s.length),
            ("the contact time scale (s)", s.time),
            ("the force scale (N)", s.force),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(out(what, v));
            }
        }
        if let Some(g) = imp.groups()
            && !g.p3.is_finite()
        {
            return Err(out("the group p3", g.p3));
        }
        // the series the solvers get: every modulus and time finite and positive in canonical
        // units (extreme times or moduli can underflow or overflow when scaled)
        let c = imp.canonical_relaxation();
        // a liquid relaxes to exactly zero; anything else must stay positive when scaled
        let liquid = imp.equivalent.relaxed == 0.0;
        if !(c.relaxed.is_finite() && (c.relaxed > 0.0 || liquid)) {
            return Err(out("G_eq(inf) over the relaxed modulus", c.relaxed));
        }
        for t in &c.terms {
            if !(t.tau.is_finite() && t.tau > 0.0) {
                return Err(Error::OutOfScale {
                    what: "a relaxation time of G_eq over the contact time scale",
                    value: t.tau,
                    inputs: format!(
                        "{} (the material's relaxation times: shortest {:e} s, longest {:e} s; \
                         contact time scale {:e} s)",
                        inputs(),
                        imp.equivalent.min_tau(),
                        imp.equivalent
                            .terms
                            .iter()
                            .map(|t| t.tau)
                            .fold(0.0, f64::max),
                        s.time
                    ),
                });
            }
            if !(t.coefficient.is_finite() && t.coefficient > 0.0) {
                return Err(out(
                    "a modulus of G_eq over the relaxed modulus",
                    t.coefficient,
                ));
            }
        }
        Ok(())
    }

    /// The impact in canonical units `m = R = v0 = G_inf = 1` with the given groups.
    pub fn from_groups(groups: Groups) -> Result<Self> {
        if groups.p2 < MIN_P2 && groups.p3 > 0.0 {
            return Err(Error::NotSupported {
                solver: "groups",
                what: format!(
                    "p2 = {:e}: a glassy modulus 1/p2 times the relaxed one overflows the \
                     solvers' arithmetic in canonical units (answered for p2 >= {MIN_P2:e})",
                    groups.p2
                ),
            });
        }
        Self::new(Sphere::new(1.0, 1.0)?, 1.0, groups.canonical_material()?).map_err(|e| match e {
            // in canonical units the inputs are the groups, not a mass, a radius and moduli
            Error::OutOfScale { what, value, .. } => Error::NotSupported {
                solver: "groups",
                what: format!(
                    "nu = {}, p2 = {:e}, p3 = {:e} give {what} = {value:e} (canonical units \
                     m = R = v0 = G_inf = 1: G_1 = 1/p2, eta = p3, tau = p2 p3), beyond the \
                     range of double precision",
                    groups.nu, groups.p2, groups.p3
                ),
            },
            e => e,
        })
    }

    /// The sphere: the indenter's mass and its nominal radius (the radius of its shape for a
    /// paraboloid or an exact sphere).
    pub fn sphere(&self) -> Sphere {
        self.sphere
    }
    /// The indenter's shape.
    pub fn shape(&self) -> &Shape {
        &self.shape
    }
    /// Impact velocity `v0` (m/s).
    pub fn velocity(&self) -> f64 {
        self.velocity
    }
    /// What the sphere hits.
    pub fn target(&self) -> &Target {
        &self.target
    }

    /// The half-space material, `None` for two bodies.
    pub fn half_space(&self) -> Option<&Material> {
        match &self.target {
            Target::HalfSpace(m) => Some(m),
            Target::TwoBodies(_) => None,
        }
    }

    /// The half-space as a standard solid, if it has that shape
    /// ([`Material::as_standard_solid`]); `None` for two bodies.
    pub fn standard_solid(&self) -> Option<StandardSolid> {
        self.half_space().and_then(Material::as_standard_solid)
    }

    /// The half-space material when it is not of the standard solid's shape (a general
    /// material: more shear terms or a relaxing bulk); `None` otherwise and for two bodies.
    pub fn general_material(&self) -> Option<&Material> {
        self.half_space()
            .filter(|m| m.as_standard_solid().is_none())
    }

    /// The two bodies, if the impact is a two-body collision.
    pub fn bodies(&self) -> Option<&TwoBodies> {
        match &self.target {
            Target::TwoBodies(b) => Some(b),
            Target::HalfSpace(_) => None,
        }
    }

    /// The equivalent relaxation function `G_eq(t)` in SI (Pa, s).
    pub fn equivalent_relaxation(&self) -> &Prony {
        &self.equivalent
    }

    /// `G_eq(t)` in SI (Pa, s) derived without `material::carson`, for the reference solver: the
    /// closed form of docs/theory.md §2 for a material of the standard solid's shape
    /// ([`Material::as_standard_solid`]), [`poles::equivalent_relaxation`] otherwise, and for two
    /// bodies each body's by the same rule combined by [`poles::series`] (a rigid body drops
    /// out). Two derivations of one function that verify each other.
    pub fn independent_relaxation(&self) -> Result<Prony> {
        let one = |m: &Material| -> Result<Prony> {
            match m.as_standard_solid() {
                Some(s) => Ok(s.equivalent_relaxation()),
                None => poles::equivalent_relaxation(m),
            }
        };
        match &self.target {
            Target::HalfSpace(m) => one(m),
            Target::TwoBodies(b) => {
                match (b.a().material().material(), b.b().material().material()) {
                    (Some(a), Some(b)) => poles::series(&one(a)?, &one(b)?),
                    (Some(m), None) | (None, Some(m)) => one(m),
                    (None, None) => Err(Error::Internal(
                        "two rigid bodies have no relaxation function",
                    )),
                }
            }
        }
    }

    /// True when `G_eq(t)` is constant for `t > 0` (no decaying term): the Hertz closed form
    /// with the relaxed modulus is exact.
    pub fn is_elastic(&self) -> bool {
        match self.standard_solid() {
            Some(m) => m.is_elastic(),
            None => self.equivalent.is_elastic(),
        }
    }

    /// Plane-strain modulus `E* = 4 G_eq(inf)` (Pa) of the relaxed material (the Hertz limit).
    pub fn relaxed_effective_modulus(&self) -> f64 {
        match self.standard_solid() {
            Some(m) => m.effective_modulus(m.g_inf()),
            None => 4.0 * self.equivalent.relaxed,
        }
    }

    /// Dimensionless groups, Eq. (11), of a half-space of the standard solid's shape
    /// ([`StandardSolid::groups`]) hit by a paraboloid; `None` otherwise (a general material,
    /// two bodies or another indenter shape have no such three groups).
    pub fn groups(&self) -> Option<Groups> {
        if !matches!(self.shape, Shape::Paraboloid { .. }) {
            return None;
        }
        Some(self.standard_solid()?.groups(self.scales().time))
    }

    /// Scales from canonical units to SI ([`Shape::canonical`]; for the paraboloid
    /// `L = (m v^2 / (G sqrt(R)))^(2/5)` and contact radius `sqrt(R L)`).
    pub fn scales(&self) -> Scales {
        let (m, v) = (self.sphere.mass, self.velocity);
        let g = self.target.modulus_scale();
        let (length, radius, _) = self.shape.canonical(m, v, g);
        let ln_l = length.ln();
        Scales {
            length,
            time: (ln_l - v.ln()).exp(),
            force: (m.ln() + 2.0 * v.ln() - ln_l).exp(),
            energy: m * v * v,
            velocity: v,
            radius,
            modulus: g,
        }
    }

    /// The indenter's shape in canonical units ([`Shape::canonical`]).
    pub fn canonical_geometry(&self) -> crate::model::geometry::Geometry {
        self.shape
            .canonical(self.sphere.mass, self.velocity, self.target.modulus_scale())
            .2
    }

    /// Equivalent relaxation function in canonical units (moduli / `G_inf`, times / `L/v0`),
    /// `G_inf` the modulus scale ([`Target::modulus_scale`]: `g_inf`, or the glassy shear
    /// modulus of a liquid).
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
    pub(crate) fn scale(&mut self, s: &Scales) {
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
    /// Refinement levels of the adaptive driver (`fast`: its solves).
    pub levels: u32,
    /// Solves tighter than the requested rtol made only to verify the answer (`fast`: 0 where
    /// the loose check sufficed).
    pub tight_checks: u32,
}

/// The method that produced an [`Outcome`]: one of the solvers, or the Hertz closed form that
/// answers an elastic impact whatever the solver. It prints as its name (`hertz`, `fast`,
/// `reference`, `mdr`, `mdr-euler`), the text of the `solver` column and key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Method {
    /// The Hertz closed form (an elastic impact).
    Hertz,
    /// The reduced collocation solver.
    Fast,
    /// The Lee–Radok/Ting reference solver.
    Reference,
    /// MDR with the exponential scheme.
    Mdr,
    /// MDR with the paper's explicit Euler.
    MdrEuler,
}

impl Method {
    /// The printed name.
    pub fn name(self) -> &'static str {
        match self {
            Method::Hertz => "hertz",
            Method::Fast => "fast",
            Method::Reference => "reference",
            Method::Mdr => "mdr",
            Method::MdrEuler => "mdr-euler",
        }
    }
}

impl std::fmt::Display for Method {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl PartialEq<&str> for Method {
    fn eq(&self, other: &&str) -> bool {
        self.name() == *other
    }
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
    /// The method that produced it (prints as the solver's name, or `hertz` for the closed form).
    pub solver: Method,
    /// Why `auto` did not answer with its first choice: the refusal of `fast` when `reference`
    /// answered instead (`None` otherwise), as the typed error.
    pub fallback: Option<Box<Error>>,
}

impl Outcome {
    /// The refusal of `fast` that made `auto` fall back ([`Outcome::fallback`]) as one line that
    /// names `fast`: the message itself when its variant starts with the solver's name (every
    /// accuracy, work and capability refusal does), else the message after `fast: `.
    pub fn fallback_reason(&self) -> Option<String> {
        let e = self.fallback.as_deref()?;
        let named = matches!(
            e.root(),
            Error::AccuracyNotReached { .. }
                | Error::NotAsymptotic { .. }
                | Error::StepSizeTooSmall { .. }
                | Error::WorkLimit { .. }
                | Error::TooManyTerms { .. }
                | Error::NotSupported { .. }
        ) && !matches!(e, Error::In { .. });
        Some(if named {
            e.to_string()
        } else {
            format!("fast: {e}")
        })
    }
}
