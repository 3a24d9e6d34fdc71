//! Scenes: a strict TOML description of one impact, its solver and its requested outputs.
//!
//! ```toml
//! # SI units throughout
//! [sphere]
//! mass = 4.11e-3        # kg
//! radius = 5.0e-3       # m
//!
//! [impact]
//! velocity = 1.0        # m/s, normal approach speed
//!
//! [material]
//! g_inf = 1.0e6         # Pa, relaxed shear modulus G_inf
//! g_1 = 1.0e7           # Pa, relaxing shear modulus G_1
//! eta = 500.0           # Pa s, shear viscosity
//! poisson = 0.49        # static Poisson ratio, -1 < nu <= 0.5 (0.5 = incompressible)
//! # k_0 = 5.0e7         # Pa, bulk modulus: give either poisson or k_0, not both
//!
//! [solver]              # optional
//! name = "auto"         # auto | fast | reference | mdr | mdr-euler
//! rtol = 1e-6           # requested relative accuracy of the CoR
//! # elements = 200      # explicit MDR resolution (both or neither; mdr, mdr-euler, auto only):
//! # steps = 2000        #   2..=10^6 elements per contact radius, 4..=10^9 steps per contact time
//!
//! [output]              # optional; nothing here means: summary only, no histories computed
//! history = "out/history.csv"   # CSV t,d,v,force,a in SI
//! plot = "out/force.svg"        # force-time plot
//! ```
//!
//! A general material replaces the `[material]` keys by two tables (all forms in README's
//! scene-format section):
//!
//! ```toml
//! [material.shear]
//! g_inf = 1.0e3                        # Pa, relaxed shear modulus
//! terms = [[1.0e7, 1.0e-6]]            # [g_i (Pa), tau_i (s)]; or file = "prony.csv"
//! # instantaneous = 1.0e7              #   or the normalised FE form G0 (1 - sum g_i (1 - e^(-t/tau_i)))
//! # ratios = [[0.9, 1.0e-6]]
//! [material.bulk]                      # exactly one of:
//! incompressible = true                # or k_0 = ..., poisson = ..., k_inf + terms/file,
//!                                      # instantaneous + ratios
//! ```
//!
//! An oblique impact adds `[impact] tangential_velocity` (m/s) and `spin` (rad/s), a
//! `[friction]` table with `coefficient` (Coulomb) and `inertia_factor` in `[sphere]` or each
//! `[[body]]` (`I = factor m R^2`, default 0.4); all default to a frictionless normal impact
//! (docs/theory.md §14, [`crate::model::oblique`]).
//!
//! Unknown keys are errors. Every path in a scene (the `[output]` files, a Prony table `file`)
//! is relative to the folder of the scene file ([`Scene::load`]; to the working directory for
//! text without a file, [`Scene::parse`]); an absolute path stays as it is.

use serde::Deserialize;
use std::path::{Path, PathBuf};

use crate::error::{escape_text, Error, Result};
use crate::model::bodies::{Body, BodyMaterial, Side, TwoBodies};
use crate::model::geometry::{Cap, Shape, ShapeKeys};
use crate::model::impact::{Impact, Sphere};
use crate::model::material::shift::ShiftTable;
use crate::model::material::Material;
use crate::model::oblique::{inertia_factor, Oblique, SOLID_SPHERE};
use crate::solvers::{Resolution, SolveOptions, SolverKind};

mod series;
use series::general_material;
mod temperature;
use temperature::Temperature;
pub use temperature::{
    shift_warning, shifted_material, temperature_without_shift, MAX_LOG10_SHIFT,
};

/// The embedded default scene: a 10 mm steel ball (4.11 g) dropped from 5 cm on a thick,
/// nearly incompressible elastomer block.
pub const DEFAULT_SCENE: &str = include_str!("../../../scenes/default.toml");

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScene {
    sphere: Option<RawSphere>,
    indenter: Option<RawIndenter>,
    impact: RawImpact,
    material: Option<RawMaterial>,
    body: Option<Vec<RawBody>>,
    friction: Option<RawFriction>,
    #[serde(default)]
    solver: RawSolver,
    #[serde(default)]
    output: RawOutput,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSphere {
    mass: f64,
    radius: f64,
    /// `paraboloid` (Hertz, the default) or `sphere` (the exact cap).
    profile: Option<String>,
    /// `I = inertia_factor m R^2` (default 0.4, a solid sphere).
    inertia_factor: Option<f64>,
}

/// `[friction]`: the Coulomb coefficient of the contact (default 0: frictionless).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFriction {
    coefficient: f64,
}

/// `[indenter]`: a rigid impactor of any axisymmetric shape (docs/theory.md §11).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawIndenter {
    mass: f64,
    shape: String,
    radius: Option<f64>,
    half_angle_deg: Option<f64>,
    exponent: Option<f64>,
    coefficient: Option<f64>,
}

/// `[[body]]`: `mass` (kg, `inf` allowed) or `density` (kg/m^3), `radius` (m, `inf`: a wall),
/// and `rigid = true` or a `[body.material]` in the keys of `[material]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBody {
    mass: Option<f64>,
    density: Option<f64>,
    radius: f64,
    /// `paraboloid` (the default) or `sphere` (the exact cap; the gap adds the two profiles).
    profile: Option<String>,
    rigid: Option<bool>,
    material: Option<RawMaterial>,
    /// `I = inertia_factor m R^2` (default 0.4, a solid sphere).
    inertia_factor: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawImpact {
    velocity: f64,
    /// Tangential velocity of the centre before contact (m/s, default 0).
    tangential_velocity: Option<f64>,
    /// Spin before contact (rad/s, default 0; docs/theory.md §14 for the sign).
    spin: Option<f64>,
    /// Temperature (°C) at which the materials' `[material.shift]` laws are evaluated.
    temperature: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMaterial {
    rigid: Option<bool>,
    g_inf: Option<f64>,
    g_1: Option<f64>,
    eta: Option<f64>,
    poisson: Option<f64>,
    k_0: Option<f64>,
    shear: Option<RawShear>,
    bulk: Option<RawBulk>,
    /// Mass density (kg/m^3): enables the quasi-static check of the answers.
    density: Option<f64>,
    /// Time–temperature shift law (`wlf = {...}` or `arrhenius = {...}`, optionally
    /// `calibrated = [t_min, t_max]`).
    shift: Option<ShiftTable>,
}

/// `[material.shear]`: `g_inf` with `terms` or `file`, or `instantaneous` with `ratios`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawShear {
    g_inf: Option<f64>,
    terms: Option<Vec<Vec<f64>>>,
    file: Option<PathBuf>,
    instantaneous: Option<f64>,
    ratios: Option<Vec<Vec<f64>>>,
}

/// `[material.bulk]`: one of `incompressible = true`, `k_0`, `poisson`, `k_inf` with `terms`
/// or `file`, `instantaneous` with `ratios`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBulk {
    incompressible: Option<bool>,
    k_0: Option<f64>,
    poisson: Option<f64>,
    k_inf: Option<f64>,
    terms: Option<Vec<Vec<f64>>>,
    file: Option<PathBuf>,
    instantaneous: Option<f64>,
    ratios: Option<Vec<Vec<f64>>>,
}

#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawSolver {
    name: Option<String>,
    rtol: Option<f64>,
    elements: Option<usize>,
    steps: Option<usize>,
}

#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawOutput {
    history: Option<PathBuf>,
    plot: Option<PathBuf>,
}

/// A validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The impact.
    pub impact: Impact,
    /// How to solve it.
    pub options: SolveOptions,
    /// Where to write the history CSV, if requested (relative to the scene file's folder
    /// already joined in).
    pub history_csv: Option<PathBuf>,
    /// Where to write the force-time plot (SVG), if requested (likewise); the force-indentation
    /// plot `force_indentation.svg` goes beside it.
    pub plot: Option<PathBuf>,
    /// `[impact] temperature` (°C), when given.
    pub temperature: Option<f64>,
    /// The shift factor `log10 a_T` applied to each material with a `[material.shift]` law at
    /// the scene's temperature (its `t_ref` when none is given), with the table it belongs to.
    pub shifts: Vec<(String, f64)>,
    /// Warnings about the scene's inputs that no solve sees: a temperature outside the range a
    /// shift law was calibrated on (`calibrated`), one sentence each with its table.
    pub warnings: Vec<String>,
    /// The tangential inputs (`[friction]`, `[impact] tangential_velocity` and `spin`, the
    /// inertia factors); the default is a frictionless, normal impact.
    pub oblique: Oblique,
}

impl Scene {
    /// Parse and validate a scene from TOML text; its paths (a Prony table `file`, the `[output]`
    /// files) are relative to the working directory (see [`Scene::parse_in`]).
    pub fn parse(text: &str) -> Result<Self> {
        Self::parse_in(text, Path::new(""))
    }

    /// Parse and validate a scene from TOML text, with every path in it relative to the folder
    /// `base`: Prony table files (`file = ...` in `[material.shear]` or `[material.bulk]`) and
    /// the `[output]` files.
    pub fn parse_in(text: &str, base: &Path) -> Result<Self> {
        Self::parse_at(text, base, None)
    }

    /// [`Scene::parse_in`] with `[impact] temperature` replaced by `temperature` (°C) when it is
    /// `Some`: the scene at another temperature (its materials need a `[material.shift]` law).
    pub fn parse_at(text: &str, base: &Path, temperature: Option<f64>) -> Result<Self> {
        let raw: RawScene = toml::from_str(text).map_err(|e| {
            // one line: toml's message spans several lines with a source excerpt
            let msg = escape_text(&plain_types(e.message().trim_end()));
            match e.span() {
                Some(span) => {
                    let line = text[..span.start.min(text.len())].lines().count().max(1);
                    match key_at(text, span.start) {
                        Some(key) => Error::Scene(format!("line {line}: key {key}: {msg}")),
                        None => Error::Scene(format!("line {line}: {msg}")),
                    }
                }
                None => Error::Scene(msg),
            }
        })?;
        let temperature = temperature.or(raw.impact.temperature);
        let mut shifts: Vec<(String, f64)> = Vec::new();
        let mut warnings: Vec<String> = Vec::new();
        let mut at = Temperature {
            celsius: temperature,
            shifts: &mut shifts,
            warnings: &mut warnings,
        };
        let impact = match (&raw.body, &raw.sphere, &raw.indenter, &raw.material) {
            (Some(bodies), None, None, None) => {
                collision(bodies, raw.impact.velocity, base, &mut at)?
            }
            (Some(_), _, _, _) => {
                return Err(scene_error(
                    "[[body]] cannot be mixed with [sphere], [indenter] or [material]: a \
                     collision gives each body its own material ([body.material])"
                        .into(),
                ))
            }
            (None, Some(_), Some(_), _) => {
                return Err(scene_error(
                    "give [sphere] or [indenter], not both ([indenter] with shape = \"sphere\" \
                     or \"paraboloid\" is a sphere)"
                        .into(),
                ))
            }
            (None, Some(sphere), None, Some(material)) => {
                let shape = sphere_profile("[sphere]", sphere.profile.as_deref(), sphere.radius)?;
                let sphere = Sphere::new(sphere.mass, sphere.radius)?;
                impact_of(sphere, shape, raw.impact.velocity, material, base, &mut at)?
            }
            (None, None, Some(ind), Some(material)) => {
                let (sphere, shape) = indenter_of(ind)?;
                impact_of(sphere, shape, raw.impact.velocity, material, base, &mut at)?
            }
            (None, sphere, indenter, _) => {
                let missing = if sphere.is_none() && indenter.is_none() {
                    "[sphere] (or [indenter])"
                } else {
                    "[material]"
                };
                return Err(scene_error(format!(
                    "missing {missing}: give [sphere] (or [indenter]) and [material] (one \
                     impactor on a half-space) or two [[body]] tables (a collision)"
                )));
            }
        };
        if let Some(t) = temperature
            && shifts.is_empty()
        {
            return Err(temperature_without_shift(t));
        }
        let oblique = oblique_of(&raw)?;
        let mut options = SolveOptions::default();
        if let Some(name) = &raw.solver.name {
            options.solver = name.parse::<SolverKind>().map_err(|_| {
                Error::Scene(format!(
                    "[solver] name = '{}': expected one of {}",
                    escape_text(name),
                    SolverKind::NAMES.join(", ")
                ))
            })?;
        }
        if let Some(rtol) = raw.solver.rtol {
            options.rtol = rtol;
        }
        options.resolution = match (raw.solver.elements, raw.solver.steps) {
            (Some(elements), Some(steps)) => Some(Resolution { elements, steps }),
            (None, None) => None,
            _ => {
                return Err(Error::Scene(
                    "[solver]: give both elements and steps, or neither".into(),
                ))
            }
        };
        for (field, path) in [
            ("[output] history", &raw.output.history),
            ("[output] plot", &raw.output.plot),
        ] {
            if path.as_ref().is_some_and(|p| p.as_os_str().is_empty()) {
                return Err(Error::EmptyPath { field });
            }
        }
        // one rule for every path in a scene: relative to the scene file's folder
        let history_csv = raw.output.history.map(|p| base.join(p));
        let plot = raw.output.plot.map(|p| base.join(p));
        options.history = history_csv.is_some() || plot.is_some();
        options.validate()?;
        Ok(Scene {
            impact,
            options,
            history_csv,
            plot,
            temperature,
            shifts,
            warnings,
            oblique,
        })
    }

    /// Read and parse a scene file. Its errors name the file; an out-of-range value of the
    /// one-sphere tables also names its table (`s.toml [sphere]: radius = -5e-3 is out of
    /// range: ...`).
    pub fn load(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let base = path.parent().unwrap_or(Path::new(""));
        Self::parse_in(&text, base).map_err(|e| match e {
            Error::Scene(m) => Error::Scene(format!("{}: {m}", path.display())),
            Error::Io { .. } | Error::Csv { .. } => e,
            other => {
                let place = match table_of_value(&other) {
                    Some(table) => format!("{} {table}", path.display()),
                    None => path.display().to_string(),
                };
                other.at(place)
            }
        })
    }

    /// The embedded default scene.
    pub fn default_scene() -> Self {
        Self::parse(DEFAULT_SCENE).expect("the embedded default scene is valid")
    }
}

/// The tangential inputs of a scene (docs/theory.md §14); errors name the table.
fn oblique_of(raw: &RawScene) -> Result<Oblique> {
    let inertia = |table: &str, k: Option<f64>| -> Result<f64> {
        inertia_factor("inertia_factor", k.unwrap_or(SOLID_SPHERE))
            .map_err(|e| Error::Scene(format!("{table}: {e}")))
    };
    let (ka, kb) = match (&raw.body, &raw.sphere) {
        (Some(b), _) if b.len() == 2 => (
            inertia(body_name(Side::A), b[0].inertia_factor)?,
            inertia(body_name(Side::B), b[1].inertia_factor)?,
        ),
        (_, Some(s)) => (inertia("[sphere]", s.inertia_factor)?, SOLID_SPHERE),
        _ => (SOLID_SPHERE, SOLID_SPHERE),
    };
    let mu = raw.friction.as_ref().map_or(0.0, |f| f.coefficient);
    Oblique::new(
        mu,
        raw.impact.tangential_velocity.unwrap_or(0.0),
        raw.impact.spin.unwrap_or(0.0),
        ka,
        kb,
    )
    .map_err(|e| match &e {
        Error::OutOfRange { field, .. } if *field == "coefficient" => {
            Error::Scene(format!("[friction]: {e}"))
        }
        Error::OutOfRange { .. } => Error::Scene(format!("[impact]: {e}")),
        _ => e,
    })
}

/// The impact of a one-sphere scene: the standard solid of `[material]` (`g_inf`, `g_1`,
/// `eta`, `poisson` or `k_0`), or the general material of `[material.shear]` and
/// `[material.bulk]`.
fn impact_of(
    sphere: Sphere,
    shape: Shape,
    velocity: f64,
    m: &RawMaterial,
    base: &Path,
    at: &mut Temperature,
) -> Result<Impact> {
    match material_of(m, base, "[material]", at)? {
        BodyMaterial::Viscoelastic(m) => Impact::shaped(sphere, shape, velocity, m),
        BodyMaterial::Rigid => Err(scene_error(
            "[material] rigid = true: a rigid half-space under a rigid sphere has no \
             compliance; only a [[body]] of a collision can be rigid"
                .into(),
        )),
    }
}

/// The shape named by a `profile` key: the paraboloid (default) or the exact sphere of `radius`.
fn sphere_profile(table: &str, profile: Option<&str>, radius: f64) -> Result<Shape> {
    match profile.unwrap_or("paraboloid") {
        "paraboloid" => Ok(Shape::Paraboloid { radius }),
        "sphere" => Ok(Shape::sphere(radius)),
        other => Err(scene_error(format!(
            "{table} profile = '{}': expected \"paraboloid\" (Hertz, the default) or \"sphere\" \
             (the exact cap)",
            escape_text(other)
        ))),
    }
}

/// The `[indenter]` table: its mass, a nominal sphere (the radius of a paraboloid or sphere;
/// none, `inf`, for a cone, a power law or a flat punch) and its shape, with exactly the keys its
/// shape needs.
fn indenter_of(raw: &RawIndenter) -> Result<(Sphere, Shape)> {
    let keys = ShapeKeys {
        radius: raw.radius,
        half_angle_deg: raw.half_angle_deg,
        exponent: raw.exponent,
        coefficient: raw.coefficient,
    };
    let shape = Shape::from_keys(
        &raw.shape,
        &keys,
        [
            "radius (m)",
            "half_angle_deg (degrees between the axis and the face)",
            "exponent",
            "coefficient (m^(1 - exponent))",
        ],
    )
    .map_err(|m| scene_error(format!("[indenter] {m}")))?;
    let shape = shape
        .validated()
        .map_err(|e| scene_error(format!("[indenter] {e}")))?;
    // the nominal radius the validity checks compare with: a sphere's; a flat punch's radius
    // is its shape, not a curvature
    let sphere = match (shape, raw.radius) {
        (Shape::Flat { .. }, _) | (_, None) => Sphere::without_radius(raw.mass)?,
        (_, Some(r)) => Sphere::new(raw.mass, r)?,
    };
    Ok((sphere, shape))
}

/// The collision of exactly two `[[body]]` tables at the relative normal velocity `velocity`.
fn collision(
    bodies: &[RawBody],
    velocity: f64,
    base: &Path,
    at: &mut Temperature,
) -> Result<Impact> {
    let [a, b] = bodies else {
        return Err(scene_error(format!(
            "[[body]]: found {} bod{}; a collision needs exactly two [[body]] tables",
            bodies.len(),
            if bodies.len() == 1 { "y" } else { "ies" }
        )));
    };
    let cap = |side: Side, raw: &RawBody| {
        sphere_profile(body_name(side), raw.profile.as_deref(), raw.radius).map(|s| Cap {
            radius: raw.radius,
            exact: matches!(s, Shape::Spheres { .. }),
        })
    };
    let caps = [cap(Side::A, a)?, cap(Side::B, b)?];
    let a = body_of(Side::A, a, base, at)?;
    let b = body_of(Side::B, b, base, at)?;
    // the domain names what is wrong; the scene adds where (the text of earlier versions)
    let bodies = TwoBodies::new(a, b).map_err(|e| match e {
        Error::InvalidBodies { reason } => scene_error(format!("[[body]]: {reason}")),
        e => e,
    })?;
    let impact = Impact::with_bodies(bodies, velocity)?;
    if caps.iter().any(|c| c.exact) {
        impact.with_shape(Shape::Spheres { caps })
    } else {
        Ok(impact)
    }
}

/// One `[[body]]`; its errors name the body (`A` is the first table, `B` the second).
/// How a body's errors name it (`A` is the first `[[body]]` table, `B` the second).
fn body_name(side: Side) -> &'static str {
    match side {
        Side::A => "[[body]] A (the first)",
        Side::B => "[[body]] B (the second)",
    }
}

fn body_of(side: Side, raw: &RawBody, base: &Path, at: &mut Temperature) -> Result<Body> {
    let name = body_name(side);
    let named = |e: Error| match e {
        Error::Scene(m) => Error::Scene(format!("{name}: {m}")),
        e @ (Error::OutOfRange { .. } | Error::PronyTerm { .. }) => {
            Error::Scene(format!("{name}: {e}"))
        }
        other => other,
    };
    let rigid_flag = raw.rigid.or(raw.material.as_ref().and_then(|m| m.rigid));
    let material = match (rigid_flag, &raw.material) {
        (Some(false), _) => {
            return Err(named(scene_error(
                "rigid = false: leave it out and give [body.material]".into(),
            )))
        }
        (Some(true), Some(m)) if raw.rigid.is_some() || has_material_keys(m) => {
            return Err(named(scene_error(
                "rigid = true cannot be combined with material keys (or given twice)".into(),
            )))
        }
        (Some(true), _) => BodyMaterial::Rigid,
        (None, Some(m)) => {
            let table = match side {
                Side::A => "[[body]] A [body.material]",
                Side::B => "[[body]] B [body.material]",
            };
            material_of(m, base, table, at).map_err(named)?
        }
        (None, None) => {
            return Err(named(scene_error(
                "missing [body.material] (the keys of [material]) or rigid = true".into(),
            )))
        }
    };
    match (raw.mass, raw.density) {
        (Some(mass), None) => Body::new(side, mass, raw.radius, material),
        (None, Some(rho)) => Body::with_density(side, rho, raw.radius, material),
        (Some(_), Some(_)) => Err(named(scene_error(
            "give either mass (kg) or density (kg/m^3), not both".into(),
        ))),
        (None, None) => Err(named(scene_error(
            "missing mass (kg, inf for a wall) or density (kg/m^3)".into(),
        ))),
    }
}

/// True when `m` has any key besides `rigid`.
fn has_material_keys(m: &RawMaterial) -> bool {
    m.g_inf.is_some()
        || m.g_1.is_some()
        || m.eta.is_some()
        || m.poisson.is_some()
        || m.k_0.is_some()
        || m.shear.is_some()
        || m.bulk.is_some()
        || m.density.is_some()
}

/// The material of a `[material]` table (named `table` in messages): rigid, standard solid or
/// general, with its `density` when given, and shifted to the scene's temperature by its
/// `[material.shift]` law (every relaxation time times `a_T`; at its `t_ref` when the scene
/// gives no temperature).
fn material_of(
    m: &RawMaterial,
    base: &Path,
    table: &str,
    at: &mut Temperature,
) -> Result<BodyMaterial> {
    let BodyMaterial::Viscoelastic(mut v) = material_kind(m, base)? else {
        if m.shift.is_some() || m.density.is_some() {
            return Err(scene_error(format!(
                "{table}: a rigid material has no shift or density"
            )));
        }
        return Ok(BodyMaterial::Rigid);
    };
    if let Some(rho) = m.density {
        v = v.with_density(rho).map_err(|e| e.at(table.to_string()))?;
    }
    if let Some(shift) = m.shift {
        let (shifted, log10_a) = shifted_material(&v, &shift.law, at.celsius, table)?;
        v = shifted;
        at.shifts.push((table.to_string(), log10_a));
        at.warnings.extend(shift_warning(&shift, at.celsius, table));
    }
    Ok(BodyMaterial::Viscoelastic(v))
}

/// [`material_of`] without the density.
fn material_kind(m: &RawMaterial, base: &Path) -> Result<BodyMaterial> {
    if let Some(rigid) = m.rigid {
        if has_material_keys(m) || !rigid {
            return Err(scene_error(
                "[material] rigid: give rigid = true alone, or the material keys without it".into(),
            ));
        }
        return Ok(BodyMaterial::Rigid);
    }
    let standard = [
        ("g_inf", m.g_inf),
        ("g_1", m.g_1),
        ("eta", m.eta),
        ("poisson", m.poisson),
        ("k_0", m.k_0),
    ];
    let given: Vec<&str> = standard
        .iter()
        .filter(|(_, v)| v.is_some())
        .map(|(k, _)| *k)
        .collect();
    if m.shear.is_some() || m.bulk.is_some() {
        if !given.is_empty() {
            return Err(scene_error(format!(
                "[material]: {} cannot be mixed with [material.shear]/[material.bulk]: give the \
                 standard solid (g_inf, g_1, eta, poisson or k_0 in [material]) or the two tables",
                given.join(", ")
            )));
        }
        let (Some(shear), Some(bulk)) = (&m.shear, &m.bulk) else {
            let missing = if m.shear.is_none() {
                "[material.shear]"
            } else {
                "[material.bulk]"
            };
            return Err(scene_error(format!(
                "[material]: missing {missing}: a general material needs both [material.shear] \
                 and [material.bulk]"
            )));
        };
        return Ok(BodyMaterial::Viscoelastic(general_material(
            shear, bulk, base,
        )?));
    }
    for (key, value) in [("g_inf", m.g_inf), ("g_1", m.g_1), ("eta", m.eta)] {
        if value.is_none() {
            return Err(scene_error(format!(
                "[material]: missing {key} (standard solid: g_inf, g_1, eta and poisson or k_0; \
                 or the tables [material.shear] and [material.bulk])"
            )));
        }
    }
    let (g_inf, g_1, eta) = (
        m.g_inf.unwrap_or_default(),
        m.g_1.unwrap_or_default(),
        m.eta.unwrap_or_default(),
    );
    let material = match (m.poisson, m.k_0) {
        (Some(nu), None) => Material::with_poisson(g_inf, g_1, eta, nu)?,
        (None, Some(k)) => Material::new(g_inf, g_1, eta, k)?,
        (Some(_), Some(_)) => {
            return Err(scene_error(
                "[material]: give either poisson or k_0, not both".into(),
            ))
        }
        (None, None) => {
            return Err(scene_error(
                "[material]: missing poisson (-1 < nu <= 0.5) or k_0 (Pa)".into(),
            ))
        }
    };
    Ok(BodyMaterial::Viscoelastic(material))
}

/// A TOML message with Rust's type names in words (`expected f64` -> `expected a number`).
fn plain_types(message: &str) -> String {
    message
        .replace("expected f64", "expected a number")
        .replace("expected usize", "expected a whole number >= 0")
        .replace("expected a boolean", "expected true or false")
}

/// The table of a scene whose value an unplaced [`Error::OutOfRange`] is about, by its field:
/// the sphere's `mass` and `radius`, the impact's `velocity` and `temperature`, a standard
/// solid's keys in `[material]` (errors of `[[body]]` tables and of general-material tables
/// already carry their place).
fn table_of_value(e: &Error) -> Option<&'static str> {
    match e {
        Error::OutOfRange { field, .. } => match *field {
            "mass" | "radius" => Some("[sphere]"),
            "velocity" | "v0" | "temperature" => Some("[impact]"),
            "g_inf" | "g_1" | "eta" | "nu" | "poisson" | "k_0" | "density" => Some("[material]"),
            _ => None,
        },
        _ => None,
    }
}

/// The key whose value starts at byte `at` of a TOML `text`, as the user wrote it (`radius`,
/// `sphere.radius`), with the table it is in (`[sphere] radius`), when the line reads
/// `key = value`; `None` otherwise (the position is a key or a header itself).
fn key_at(text: &str, at: usize) -> Option<String> {
    let at = at.min(text.len());
    let line_start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let before = &text[line_start..at];
    let (key, rest) = before.split_once('=')?;
    let key = key.trim();
    let bare = |c: char| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | '"' | ' ');
    if key.is_empty() || !key.chars().all(bare) || !rest.trim().is_empty() {
        return None;
    }
    // the last table header above the line
    let table = text[..line_start]
        .lines()
        .rev()
        .map(str::trim)
        .find(|l| l.starts_with('['))
        .map(|l| l.split('#').next().unwrap_or(l).trim());
    Some(match table {
        Some(t) => format!("{t} {key}"),
        None => key.to_string(),
    })
}

fn scene_error(message: String) -> Error {
    Error::Scene(message)
}
