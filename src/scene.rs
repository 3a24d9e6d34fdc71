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
//! Unknown keys are errors. Paths are relative to the working directory.

use serde::Deserialize;
use std::path::{Path, PathBuf};

use crate::error::{escape_text, Error, Result};
use crate::impact::{Impact, Sphere};
use crate::material::Material;
use crate::solver::{Resolution, SolveOptions, SolverKind};

/// The embedded default scene: a 10 mm steel ball (4.11 g) dropped from 5 cm on a thick,
/// nearly incompressible elastomer block.
pub const DEFAULT_SCENE: &str = include_str!("../scenes/default.toml");

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScene {
    sphere: RawSphere,
    impact: RawImpact,
    material: RawMaterial,
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
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawImpact {
    velocity: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMaterial {
    g_inf: f64,
    g_1: f64,
    eta: f64,
    poisson: Option<f64>,
    k_0: Option<f64>,
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
    /// Where to write the history CSV, if requested.
    pub history_csv: Option<PathBuf>,
    /// Where to write the force-time plot (SVG), if requested.
    pub plot: Option<PathBuf>,
}

impl Scene {
    /// Parse and validate a scene from TOML text.
    pub fn parse(text: &str) -> Result<Self> {
        let raw: RawScene = toml::from_str(text).map_err(|e| {
            // one line: toml's message spans several lines with a source excerpt
            let msg = escape_text(e.message().trim_end());
            match e.span() {
                Some(span) => {
                    let line = text[..span.start.min(text.len())].lines().count().max(1);
                    Error::Scene(format!("line {line}: {msg}"))
                }
                None => Error::Scene(msg),
            }
        })?;
        let sphere = Sphere::new(raw.sphere.mass, raw.sphere.radius)?;
        let m = &raw.material;
        let material = match (m.poisson, m.k_0) {
            (Some(nu), None) => Material::with_poisson(m.g_inf, m.g_1, m.eta, nu)?,
            (None, Some(k)) => Material::new(m.g_inf, m.g_1, m.eta, k)?,
            (Some(_), Some(_)) => {
                return Err(Error::Scene(
                    "[material]: give either poisson or k_0, not both".into(),
                ))
            }
            (None, None) => {
                return Err(Error::Scene(
                    "[material]: missing poisson (-1 < nu <= 0.5) or k_0 (Pa)".into(),
                ))
            }
        };
        let impact = Impact::new(sphere, raw.impact.velocity, material)?;
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
        let history_csv = raw.output.history;
        let plot = raw.output.plot;
        for (field, path) in [("[output] history", &history_csv), ("[output] plot", &plot)] {
            if path.as_ref().is_some_and(|p| p.as_os_str().is_empty()) {
                return Err(Error::EmptyPath { field });
            }
        }
        options.history = history_csv.is_some() || plot.is_some();
        options.validate()?;
        Ok(Scene {
            impact,
            options,
            history_csv,
            plot,
        })
    }

    /// Read and parse a scene file.
    pub fn load(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        Self::parse(&text).map_err(|e| match e {
            Error::Scene(m) => Error::Scene(format!("{}: {m}", path.display())),
            other => other,
        })
    }

    /// The embedded default scene.
    pub fn default_scene() -> Self {
        Self::parse(DEFAULT_SCENE).expect("the embedded default scene is valid")
    }
}
