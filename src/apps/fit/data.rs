//! Drop-test data for `fit`: the CSV reader and the validated observations.
//!
//! Columns (header required, SI units): `v0` (m/s, `0 < v0 < inf`) and `cor`
//! (`0 < cor <= 1`, or up to `1 + 5 cor_sd` when `cor_sd` is given: a measured CoR above 1 is
//! read as noise around a CoR at most 1, [`cor_allowed`]), optionally `cor_sd` (`> 0`),
//! `contact_time` (s, `> 0`),
//! `contact_time_sd` (s, `> 0`, only beside `contact_time`) and `setup`: the scene file (TOML,
//! relative to the data file's folder) whose sphere was dropped in that row; rows without a
//! setup use the `--scene` given to `fit` (or the embedded default scene). An optional column
//! may be empty in a row. Unknown columns, a missing `v0` or `cor`, non-finite or out-of-range
//! values are refused with the file and line named.

use std::path::Path;

use crate::error::{escape_text, Error, Result};
use crate::io::scene::Scene;
use crate::model::geometry::Shape;
use crate::model::impact::Sphere;

/// How many standard deviations a measured CoR may lie above 1 ([`cor_allowed`]).
pub const COR_ABOVE_ONE_SDS: f64 = 5.0;

/// The allowed range of a measured CoR, in words.
pub const COR_ALLOWED: &str = "0 < cor <= 1, or cor <= 1 + 5 cor_sd when cor_sd is given";

/// Whether a measured CoR is admissible: `0 < cor <= 1`, or, with its standard deviation
/// known, up to [`COR_ABOVE_ONE_SDS`] standard deviations above 1. A CoR is at most 1, but a
/// measurement of it is not: clipping or dropping the values that noise pushes above 1 biases
/// a fit towards dissipation (docs/theory.md §16.2), so they are kept as measured. Without a
/// standard deviation noise cannot be told from an error, and values above 1 are refused.
pub fn cor_allowed(cor: f64, cor_sd: Option<f64>) -> bool {
    cor.is_finite()
        && cor > 0.0
        && (cor <= 1.0 || cor_sd.is_some_and(|sd| cor <= 1.0 + COR_ABOVE_ONE_SDS * sd))
}

/// The columns a data file may have.
pub const COLUMNS: [&str; 6] = [
    "v0",
    "cor",
    "cor_sd",
    "contact_time",
    "contact_time_sd",
    "setup",
];

/// One drop: impact velocity, measured CoR and optionally contact time, with standard
/// deviations when known.
#[derive(Debug, Clone, PartialEq)]
pub struct Observation {
    /// Index of the setup (sphere) in [`Data::setups`].
    pub setup: usize,
    /// Impact velocity (m/s).
    pub v0: f64,
    /// Coefficient of restitution.
    pub cor: f64,
    /// Standard deviation of `cor`, if known.
    pub cor_sd: Option<f64>,
    /// Contact time (s), if measured.
    pub contact_time: Option<f64>,
    /// Standard deviation of the contact time (s), if known.
    pub contact_time_sd: Option<f64>,
}

/// What was dropped: a sphere (its mass and nominal radius) and its shape (Hertz's paraboloid of
/// that radius unless the scene says otherwise, docs/theory.md §11).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impactor {
    /// Mass (kg) and nominal radius (m, `inf` for a cone, a power law or a flat punch).
    pub sphere: Sphere,
    /// The shape.
    pub shape: Shape,
}

impl From<Sphere> for Impactor {
    fn from(sphere: Sphere) -> Self {
        Self {
            sphere,
            shape: Shape::Paraboloid {
                radius: sphere.radius(),
            },
        }
    }
}

impl Impactor {
    /// The radius of curvature the fit's starting values use: the shape's tip radius, or for a
    /// shape without one the paraboloid through the contact edge at the canonical indentation
    /// of an impact at `v0` on 1 MPa (`A^2 / L`, [`Shape::canonical`]): starting values only.
    pub fn start_radius(&self, v0: f64) -> f64 {
        match self.shape.tip_radius() {
            Some(r) => r,
            None => {
                let (l, a, _) = self.shape.canonical(self.sphere.mass(), v0, 1.0e6);
                a * a / l
            }
        }
    }
}

/// A sphere a data set was measured with, and the name it was given.
#[derive(Debug, Clone, PartialEq)]
pub struct Setup {
    /// The scene's path as written in the data (or `--scene`, or `default`).
    pub name: String,
    /// The impactor.
    pub sphere: Impactor,
}

/// Validated drop-test data.
#[derive(Debug, Clone, PartialEq)]
pub struct Data {
    /// The spheres.
    pub setups: Vec<Setup>,
    /// The drops, in file order.
    pub observations: Vec<Observation>,
}

impl Data {
    /// Whether any drop has a contact time.
    pub fn has_contact_times(&self) -> bool {
        self.observations.iter().any(|o| o.contact_time.is_some())
    }
    /// Number of residuals (one per CoR and one per contact time).
    pub fn residual_count(&self) -> usize {
        self.observations.len()
            + self
                .observations
                .iter()
                .filter(|o| o.contact_time.is_some())
                .count()
    }
    /// Check data built in code the way [`parse`] checks a file: at least one drop, every setup
    /// index valid, `0 < v0 < inf`, `cor` as [`cor_allowed`], contact times and standard deviations
    /// finite and positive ([`Error::OutOfRange`] naming the field).
    pub fn validate(&self) -> Result<()> {
        use crate::error::check;
        if self.observations.is_empty() {
            return Err(Error::TooFewObservations {
                observations: 0,
                parameters: 1,
            });
        }
        for o in &self.observations {
            if o.setup >= self.setups.len() {
                return Err(Error::OutOfRange {
                    field: "setup",
                    value: o.setup as f64,
                    allowed: "an index into the setups",
                });
            }
            check("v0", o.v0, o.v0 > 0.0, "0 < v0 < inf (m/s)")?;
            for (field, x, allowed) in [
                ("cor_sd", o.cor_sd, "0 < cor_sd < inf"),
                ("contact_time", o.contact_time, "0 < contact_time < inf (s)"),
                (
                    "contact_time_sd",
                    o.contact_time_sd,
                    "0 < contact_time_sd < inf (s)",
                ),
            ] {
                if let Some(x) = x {
                    check(field, x, x > 0.0, allowed)?;
                }
            }
            check("cor", o.cor, cor_allowed(o.cor, o.cor_sd), COR_ALLOWED)?;
        }
        Ok(())
    }

    /// Whether every standard deviation is given (then the noise scale is known).
    /// Standard deviations are given for every measured value or for none (of both kinds):
    /// with some missing, one noise scale would have to cover weighted and unweighted residuals
    /// of different scales.
    ///
    /// # Errors
    /// [`Error::PartialNoise`] naming the column that is given only in part (or missing where
    /// the other is given).
    pub fn check_noise(&self) -> Result<()> {
        let obs = &self.observations;
        let cor_given = obs.iter().filter(|o| o.cor_sd.is_some()).count();
        let times: Vec<_> = obs.iter().filter(|o| o.contact_time.is_some()).collect();
        let time_given = times.iter().filter(|o| o.contact_time_sd.is_some()).count();
        let any = cor_given > 0 || time_given > 0;
        if any && cor_given < obs.len() {
            return Err(Error::PartialNoise {
                column: "cor_sd",
                given: cor_given,
                values: obs.len(),
            });
        }
        if any && time_given < times.len() {
            return Err(Error::PartialNoise {
                column: "contact_time_sd",
                given: time_given,
                values: times.len(),
            });
        }
        Ok(())
    }

    /// Whether the standard deviation of every measured value is given.
    pub fn noise_known(&self) -> bool {
        self.observations.iter().all(|o| {
            o.cor_sd.is_some() && (o.contact_time.is_none() || o.contact_time_sd.is_some())
        })
    }
}

/// The impactor of a scene; two-body scenes are refused (`fit` identifies one half-space).
pub fn scene_sphere(scene: &Scene, name: &str) -> Result<Impactor> {
    if scene.impact.bodies().is_some() {
        return Err(Error::NotSupported {
            solver: "fit",
            what: "it needs a one-sphere scene ([sphere]), not [[body]] tables".into(),
        }
        .at(escape_text(name)));
    }
    Ok(Impactor {
        sphere: scene.impact.sphere(),
        shape: *scene.impact.shape(),
    })
}

/// Read `path`; rows without a `setup` use `default` (named `default_name`).
pub fn read(path: &Path, default: impl Into<Impactor>, default_name: &str) -> Result<Data> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    let base = path.parent().unwrap_or(Path::new(""));
    parse(
        &text,
        &path.display().to_string(),
        default.into(),
        default_name,
        &|name| {
            let p = base.join(name);
            let scene = Scene::load(&p)?;
            scene_sphere(&scene, name)
        },
    )
}

/// Parse CSV `text` (named `file` in messages); `load` gives the sphere of a named setup.
pub fn parse(
    text: &str,
    file: &str,
    default: impl Into<Impactor>,
    default_name: &str,
    load: &dyn Fn(&str) -> Result<Impactor>,
) -> Result<Data> {
    let default = default.into();
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .flexible(false)
        .from_reader(text.as_bytes());
    let err = |line: u64, message: String| Error::Csv {
        file: file.to_string(),
        line,
        message,
    };
    let header: Vec<String> = reader
        .headers()
        .map_err(|e| err(1, escape_text(&e.to_string())))?
        .iter()
        .map(str::to_string)
        .collect();
    let mut col = [None; 6];
    for (j, h) in header.iter().enumerate() {
        match COLUMNS.iter().position(|c| c == h) {
            Some(k) if col[k].is_none() => col[k] = Some(j),
            Some(_) => return Err(err(1, format!("column '{}' appears twice", escape_text(h)))),
            None => {
                return Err(err(
                    1,
                    format!(
                        "unknown column '{}': expected {}",
                        escape_text(h),
                        COLUMNS.join(", ")
                    ),
                ))
            }
        }
    }
    for k in 0..2 {
        if col[k].is_none() {
            return Err(err(1, format!("missing column '{}'", COLUMNS[k])));
        }
    }
    if col[4].is_some() && col[3].is_none() {
        return Err(err(1, "contact_time_sd without contact_time".into()));
    }
    let mut setups = vec![Setup {
        name: default_name.to_string(),
        sphere: default,
    }];
    let mut observations = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| {
            let line = e.position().map_or(0, |p| p.line());
            err(line, escape_text(&e.to_string()))
        })?;
        let line = record.position().map_or(0, |p| p.line());
        let field = |k: usize| col[k].and_then(|j| record.get(j)).filter(|s| !s.is_empty());
        let number = |k: usize, ok: fn(f64) -> bool, allowed: &str| -> Result<Option<f64>> {
            let Some(s) = field(k) else { return Ok(None) };
            let v: f64 = s.parse().map_err(|_| {
                err(
                    line,
                    format!("{} = '{}' is not a number", COLUMNS[k], escape_text(s)),
                )
            })?;
            if v.is_finite() && ok(v) {
                Ok(Some(v))
            } else {
                Err(err(
                    line,
                    format!("{} = {v:e} is out of range: allowed {allowed}", COLUMNS[k]),
                ))
            }
        };
        let v0 = number(0, |v| v > 0.0, "0 < v0 < inf (m/s)")?
            .ok_or_else(|| err(line, "v0 is empty".into()))?;
        let cor =
            number(1, |v| v > 0.0, "0 < cor")?.ok_or_else(|| err(line, "cor is empty".into()))?;
        let cor_sd = number(2, |v| v > 0.0, "0 < cor_sd < inf")?;
        if !cor_allowed(cor, cor_sd) {
            return Err(err(
                line,
                format!("cor = {cor:e} is out of range: allowed {COR_ALLOWED}"),
            ));
        }
        let contact_time = number(3, |v| v > 0.0, "0 < contact_time < inf (s)")?;
        let contact_time_sd = number(4, |v| v > 0.0, "0 < contact_time_sd < inf (s)")?;
        if contact_time_sd.is_some() && contact_time.is_none() {
            return Err(err(line, "contact_time_sd without contact_time".into()));
        }
        let setup = match field(5) {
            None => 0,
            Some(name) => match setups.iter().position(|s| s.name == name) {
                Some(i) => i,
                None => {
                    let sphere = load(name)
                        .map_err(|e| err(line, format!("setup '{}': {e}", escape_text(name))))?;
                    setups.push(Setup {
                        name: name.to_string(),
                        sphere,
                    });
                    setups.len() - 1
                }
            },
        };
        observations.push(Observation {
            setup,
            v0,
            cor,
            cor_sd,
            contact_time,
            contact_time_sd,
        });
    }
    if observations.is_empty() {
        return Err(err(1, "no data rows".into()));
    }
    Ok(Data {
        setups,
        observations,
    })
}
