//! The impactor, bodies and scenes: `Sphere`, `Indenter`, `Body`, `Scene`.

use super::*;

/// A rigid sphere: `mass` (kg) and `radius` (m), both `0 < x < inf`; `profile` is
/// `"paraboloid"` (Hertz, the default) or `"sphere"` (the exact cap, docs/theory.md §11).
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Sphere {
    inner: RsSphere,
    exact: bool,
}

/// `true` for `profile="sphere"`, `false` for `"paraboloid"`.
pub(crate) fn exact_profile(profile: &str) -> PyResult<bool> {
    match profile {
        "paraboloid" => Ok(false),
        "sphere" => Ok(true),
        other => Err(usage(format!(
            "profile='{}': expected 'paraboloid' (Hertz, the default) or 'sphere' (the exact cap)",
            escape_text(other)
        ))),
    }
}

/// The profile's name: `"sphere"` for the exact cap, else `"paraboloid"`.
pub(crate) fn profile_name(exact: bool) -> &'static str {
    if exact {
        "sphere"
    } else {
        "paraboloid"
    }
}

#[pymethods]
impl Sphere {
    #[new]
    #[pyo3(signature = (mass, radius, profile = "paraboloid"))]
    fn new(mass: f64, radius: f64, profile: &str) -> PyResult<Self> {
        Ok(Self {
            inner: ok(RsSphere::new(mass, radius))?,
            exact: exact_profile(profile)?,
        })
    }
    /// `"paraboloid"` or `"sphere"` (the exact cap).
    #[getter]
    fn profile(&self) -> &'static str {
        profile_name(self.exact)
    }
    /// Mass (kg).
    #[getter]
    fn mass(&self) -> f64 {
        self.inner.mass()
    }
    /// Radius (m).
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }
    fn __repr__(&self) -> String {
        format!(
            "Sphere(mass={:?}, radius={:?}, profile={:?})",
            self.inner.mass(),
            self.inner.radius(),
            self.profile()
        )
    }
}

/// A rigid impactor of any axisymmetric shape (docs/theory.md §11, the scene's `[indenter]`):
/// `mass` (kg) and `shape` (`"paraboloid"`, `"sphere"`, `"cone"`, `"power-law"`, `"flat"`) with
/// exactly the keys the shape takes: `radius` (m; paraboloid, sphere, flat punch),
/// `half_angle_deg` (cone: degrees between the axis and the face), `exponent` and
/// `coefficient` (power law `f = coefficient r^exponent`, coefficient in m^(1 - exponent)).
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Indenter {
    mass: f64,
    shape: Shape,
}

#[pymethods]
impl Indenter {
    #[new]
    #[pyo3(signature = (mass, shape, *, radius = None, half_angle_deg = None, exponent = None,
        coefficient = None))]
    fn new(
        mass: f64,
        shape: &str,
        radius: Option<f64>,
        half_angle_deg: Option<f64>,
        exponent: Option<f64>,
        coefficient: Option<f64>,
    ) -> PyResult<Self> {
        let keys = ShapeKeys {
            radius,
            half_angle_deg,
            exponent,
            coefficient,
        };
        let shape = Shape::from_keys(
            shape,
            &keys,
            ["radius", "half_angle_deg", "exponent", "coefficient"],
        )
        .map_err(usage)?;
        ok(RsSphere::without_radius(mass))?;
        Ok(Self {
            mass,
            shape: ok(shape.validated())?,
        })
    }
    /// Mass (kg).
    #[getter]
    fn mass(&self) -> f64 {
        self.mass
    }
    /// The shape's name.
    #[getter]
    fn shape(&self) -> &'static str {
        self.shape.name()
    }
    fn __repr__(&self) -> String {
        format!("Indenter(mass={:?}, {})", self.mass, self.shape.describe())
    }
}

/// One body of a two-body collision: `radius` (m, `inf` for a flat wall), `mass` (kg, `inf`
/// allowed) or `density` (kg/m^3, with a finite radius), and a `material` (`Material` or
/// `GeneralMaterial`) or `rigid=True`.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Body {
    inner: RsBody,
    /// `profile="sphere"`: the exact cap.
    exact: bool,
    /// The material's shift law, applied by a `Scene` at its temperature.
    shift: Option<ShiftTable>,
}

/// `e` without the body it is placed at (`Error::In`): a body is named only once it is placed in
/// a scene.
pub(crate) fn unsided(e: mdr_impact::Error) -> mdr_impact::Error {
    match e {
        mdr_impact::Error::In { source, .. } => *source,
        other => other,
    }
}

impl Body {
    /// The same body as body `side` of a collision, its material shifted to `temperature`
    /// (°C; the law's `t_ref` when `None`) when it has a shift law (`log10 a_T` then pushed to
    /// `shifts` with the scene's table name).
    fn as_side(
        &self,
        side: Side,
        temperature: Option<f64>,
        shifts: &mut Vec<(String, f64)>,
        warnings: &mut Vec<String>,
    ) -> PyResult<RsBody> {
        let b = &self.inner;
        let table = match side {
            Side::A => "[[body]] A [body.material]",
            Side::B => "[[body]] B [body.material]",
        };
        let material = match (b.material(), &self.shift) {
            (BodyMaterial::Viscoelastic(m), Some(shift)) => {
                let (m, log10_a) = ok(shifted_material(m, &shift.law, temperature, table))?;
                shifts.push((table.to_string(), log10_a));
                warnings.extend(shift_warning(shift, temperature, table));
                BodyMaterial::Viscoelastic(m)
            }
            (m, _) => m.clone(),
        };
        ok(RsBody::new(side, b.mass(), b.radius(), material))
    }
}

#[pymethods]
impl Body {
    #[new]
    #[pyo3(signature = (*, radius, material = None, mass = None, density = None, rigid = false,
        profile = "paraboloid"))]
    fn new(
        radius: f64,
        material: Option<&Bound<'_, PyAny>>,
        mass: Option<f64>,
        density: Option<f64>,
        rigid: bool,
        profile: &str,
    ) -> PyResult<Self> {
        let exact = exact_profile(profile)?;
        let shift = material.and_then(material_shift);
        let material = match (material, rigid) {
            (Some(m), false) => body_material(m)?,
            (None, true) => BodyMaterial::Rigid,
            (Some(_), true) => {
                return Err(usage(
                    "give either a material or rigid=True, not both".into(),
                ))
            }
            (None, false) => return Err(usage("missing material (or rigid=True)".into())),
        };
        let inner = match (mass, density) {
            (Some(m), None) => RsBody::new(Side::A, m, radius, material),
            (None, Some(rho)) => RsBody::with_density(Side::A, rho, radius, material),
            (Some(_), Some(_)) => {
                return Err(usage(
                    "give either mass (kg) or density (kg/m^3), not both".into(),
                ))
            }
            (None, None) => {
                return Err(usage(
                    "missing mass (kg, inf for a wall) or density (kg/m^3)".into(),
                ))
            }
        }
        .map_err(|e| py_err(unsided(e)))?;
        Ok(Self {
            inner,
            exact,
            shift,
        })
    }
    /// Mass (kg), possibly `inf`.
    #[getter]
    fn mass(&self) -> f64 {
        self.inner.mass()
    }
    /// Radius (m), `inf` for a wall.
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }
    /// `"paraboloid"` or `"sphere"` (the exact cap).
    #[getter]
    fn profile(&self) -> &'static str {
        profile_name(self.exact)
    }
    /// True for a rigid body.
    #[getter]
    fn rigid(&self) -> bool {
        self.inner.material().is_rigid()
    }
    /// The material (`Material` or `GeneralMaterial`), `None` when rigid.
    #[getter]
    fn material(&self, py: Python<'_>) -> PyResult<Option<Py<PyAny>>> {
        material_object(py, self.inner.material())
    }
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let m = match self.material(py)? {
            Some(m) => format!("material={}", m.bind(py).repr()?),
            None => "rigid=True".into(),
        };
        Ok(format!(
            "Body(mass={:?}, radius={:?}, {m})",
            self.inner.mass(),
            self.inner.radius()
        ))
    }
}

/// An impact with its solver settings, as in a scene file (SI units): one `sphere` (a `Sphere`:
/// kg, m) or `indenter` (an `Indenter`) on a half-space of `material` (`Material` or
/// `GeneralMaterial`: Pa, Pa s, s), or two `bodies` (`Body`, `Body`); `velocity` (m/s) the
/// (relative) normal impact velocity; the solver's name `solver` (`auto`, `fast`, `reference`,
/// `mdr`, `mdr-euler`), `rtol` (requested relative accuracy of the CoR, dimensionless,
/// `1e-12 <= rtol <= 0.1`, default `1e-6`), and optionally an explicit MDR resolution
/// `elements`, `steps` (counts); the `[output]` paths `history_csv` (TOML key `history`) and
/// `plot` are kept for `to_toml` (the files are written by `mdr-impact run`, not by
/// `Scene.run`); `temperature` (°C) shifts every material given with a `shift` law (default:
/// each law's `t_ref`), as `[impact] temperature` does.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Scene {
    pub(crate) inner: RsScene,
}

#[pymethods]
impl Scene {
    #[new]
    #[pyo3(signature = (*, velocity, sphere = None, material = None, bodies = None,
        indenter = None, solver = "auto", rtol = tolerances::DEFAULT_RTOL, elements = None, steps = None,
        history_csv = None, plot = None, temperature = None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        velocity: f64,
        sphere: Option<PyRef<'_, Sphere>>,
        material: Option<&Bound<'_, PyAny>>,
        bodies: Option<(PyRef<'_, Body>, PyRef<'_, Body>)>,
        indenter: Option<PyRef<'_, Indenter>>,
        solver: &str,
        rtol: f64,
        elements: Option<usize>,
        steps: Option<usize>,
        history_csv: Option<PathBuf>,
        plot: Option<PathBuf>,
        temperature: Option<f64>,
    ) -> PyResult<Self> {
        let mut shifts: Vec<(String, f64)> = Vec::new();
        let mut warnings: Vec<String> = Vec::new();
        let mut half_space = |m: &Bound<'_, PyAny>| match body_material(m)? {
            BodyMaterial::Viscoelastic(v) => match material_shift(m) {
                Some(shift) => {
                    let table = "[material]";
                    let (v, log10_a) = ok(shifted_material(&v, &shift.law, temperature, table))?;
                    shifts.push((table.to_string(), log10_a));
                    warnings.extend(shift_warning(&shift, temperature, table));
                    Ok(v)
                }
                None => Ok(v),
            },
            BodyMaterial::Rigid => Err(usage("a rigid half-space has no compliance".into())),
        };
        let impact = match (sphere, indenter, material, bodies) {
            (Some(s), None, Some(m), None) => {
                let shape = if s.exact {
                    Shape::sphere(s.inner.radius())
                } else {
                    Shape::Paraboloid {
                        radius: s.inner.radius(),
                    }
                };
                ok(Impact::shaped(s.inner, shape, velocity, half_space(m)?))?
            }
            (None, Some(ind), Some(m), None) => {
                // the nominal radius of the validity checks: a paraboloid's or sphere's
                let nominal = match (ind.shape, ind.shape.tip_radius()) {
                    (Shape::Paraboloid { .. } | Shape::Spheres { .. }, Some(r)) => {
                        ok(RsSphere::new(ind.mass, r))?
                    }
                    _ => ok(RsSphere::without_radius(ind.mass))?,
                };
                ok(Impact::shaped(nominal, ind.shape, velocity, half_space(m)?))?
            }
            (None, None, None, Some((a, b))) => {
                let pair = ok(TwoBodies::new(
                    a.as_side(Side::A, temperature, &mut shifts, &mut warnings)?,
                    b.as_side(Side::B, temperature, &mut shifts, &mut warnings)?,
                ))?;
                let impact = ok(Impact::with_bodies(pair, velocity))?;
                if a.exact || b.exact {
                    let cap = |body: &Body| Cap {
                        radius: body.inner.radius(),
                        exact: body.exact,
                    };
                    ok(impact.with_shape(Shape::Spheres {
                        caps: [cap(&a), cap(&b)],
                    }))?
                } else {
                    impact
                }
            }
            _ => {
                return Err(usage(
                    "give sphere and material (one sphere on a half-space), indenter and \
                     material (any other impactor) or bodies=(a, b) (a collision)"
                        .into(),
                ))
            }
        };
        if let (Some(t), true) = (temperature, shifts.is_empty()) {
            return Err(py_err(temperature_without_shift(t)));
        }
        let mut options = options(solver, rtol)?;
        options.resolution = match (elements, steps) {
            (Some(elements), Some(steps)) => Some(Resolution { elements, steps }),
            (None, None) => None,
            _ => return Err(usage("give both elements and steps, or neither".into())),
        };
        for (field, path) in [("history_csv", &history_csv), ("plot", &plot)] {
            if path.as_ref().is_some_and(|p| p.as_os_str().is_empty()) {
                return Err(usage(format!("{field} is an empty path: give a file name")));
            }
        }
        options.history = history_csv.is_some() || plot.is_some();
        ok(options.validate())?;
        Ok(Self {
            inner: RsScene {
                impact,
                options,
                history_csv,
                plot,
                temperature,
                shifts,
                warnings,
                oblique: Default::default(),
            },
        })
    }

    /// `[impact] temperature` (°C), or `None`.
    #[getter]
    fn temperature(&self) -> Option<f64> {
        self.inner.temperature
    }
    /// The shift factors applied to the materials with a shift law: a list of pairs
    /// `(table, log10 a_T)` (`"[material]"`, `"[[body]] A [body.material]"`, ...), as `run`
    /// prints them.
    #[getter]
    fn shifts(&self) -> Vec<(String, f64)> {
        self.inner.shifts.clone()
    }
    /// Read a scene file (TOML); a Prony table `file` is relative to the scene's folder.
    #[staticmethod]
    fn load(path: PathBuf) -> PyResult<Self> {
        Ok(Self {
            inner: ok(RsScene::load(&path))?,
        })
    }

    /// Parse scene TOML text; Prony table files are read relative to `base` (default: the
    /// working directory).
    #[staticmethod]
    #[pyo3(signature = (text, base = None))]
    fn from_toml(text: &str, base: Option<PathBuf>) -> PyResult<Self> {
        let base = base.unwrap_or_default();
        Ok(Self {
            inner: ok(RsScene::parse_in(text, &base))?,
        })
    }

    /// The embedded default scene (`scenes/default.toml`: a 10 mm steel ball on an elastomer).
    #[staticmethod]
    fn default() -> Self {
        Self {
            inner: RsScene::default_scene(),
        }
    }

    /// The scene as TOML text (validated form; `Scene.from_toml(s.to_toml()) == s`).
    fn to_toml(&self) -> String {
        self.inner.to_toml()
    }

    /// Write `to_toml()` to `path` (atomically: no partial file).
    fn save(&self, path: PathBuf) -> PyResult<()> {
        let text = self.inner.to_toml();
        ok(output::write_atomic(&path, |w| {
            w.write_all(text.as_bytes())
                .map_err(|e| mdr_impact::Error::io(&path, e))
        }))
    }

    /// The same scene at another impact velocity (m/s).
    fn with_velocity(&self, velocity: f64) -> PyResult<Self> {
        let mut inner = self.inner.clone();
        inner.impact = ok(self.inner.impact.at_velocity(velocity))?;
        Ok(Self { inner })
    }

    /// The same scene with another solver (`solver`: auto, fast, reference, mdr, mdr-euler)
    /// and/or requested `rtol` (relative accuracy of the CoR, dimensionless,
    /// `1e-12 <= rtol <= 0.1`); `None` keeps the scene's.
    #[pyo3(signature = (solver = None, rtol = None))]
    fn with_solver(&self, solver: Option<&str>, rtol: Option<f64>) -> PyResult<Self> {
        let mut inner = self.inner.clone();
        if let Some(name) = solver {
            inner.options.solver = ok(name.parse::<SolverKind>())?;
        }
        if let Some(rtol) = rtol {
            inner.options.rtol = rtol;
        }
        ok(inner.options.validate())?;
        Ok(Self { inner })
    }

    /// Solve the impact (GIL released), as `mdr-impact run` does: an `ImpactResult` (SI
    /// units: m/s, s, m, N, J); the result carries the
    /// histories with `history=True`, or with `history=None` (default) when the scene has
    /// `[output]` paths (which is what makes `run` compute them too; the embedded default
    /// scene has none).
    #[pyo3(signature = (history = None))]
    fn run(&self, py: Python<'_>, history: Option<bool>) -> PyResult<ImpactResult> {
        let opts = SolveOptions {
            history: history.unwrap_or(self.inner.options.history),
            ..self.inner.options
        };
        let impact = &self.inner.impact;
        // the normal outcome of `run`: an oblique scene's is that of its oblique solve
        let oblique = &self.inner.oblique;
        let oo =
            ok(py.detach(|| mdr_impact::solvers::oblique::solve_oblique(impact, oblique, &opts)))?;
        let outcome = oo.normal;
        let bodies = impact
            .bodies()
            .map(|b| b.rebound_velocities(impact.velocity(), outcome.cor));
        let validity = mdr_impact::model::validity::Validity::of(impact, &outcome);
        // as `run --json`: `fallback` says why auto did not answer with fast, and the
        // plausibility warnings of the inputs come first
        let fallback = match oo.reason {
            Some(why) => Some(why.to_string()),
            None => output::fallback(&opts, &outcome),
        };
        let mut warnings = mdr_impact::model::plausibility::warnings(impact);
        warnings.extend(self.inner.warnings.iter().cloned());
        let mut r = ImpactResult::new(outcome, bodies, validity);
        r.fallback = fallback;
        warnings.append(&mut r.warnings);
        r.warnings = warnings;
        Ok(r)
    }

    /// Impact velocity (m/s; relative normal velocity for two bodies).
    #[getter]
    fn velocity(&self) -> f64 {
        self.inner.impact.velocity()
    }
    /// The sphere (for two bodies: the effective sphere, `m_A m_B / (m_A + m_B)`,
    /// `R_A R_B / (R_A + R_B)`).
    #[getter]
    fn sphere(&self) -> Sphere {
        Sphere {
            inner: self.inner.impact.sphere(),
            exact: matches!(self.inner.impact.shape(), Shape::Spheres { .. }),
        }
    }
    /// The impactor's shape: `"paraboloid"`, `"sphere"`, `"cone"`, `"power-law"` or `"flat"`.
    #[getter]
    fn shape(&self) -> &'static str {
        self.inner.impact.shape().name()
    }
    /// The half-space material (`Material` or `GeneralMaterial`), `None` for two bodies.
    #[getter]
    fn material(&self, py: Python<'_>) -> PyResult<Option<Py<PyAny>>> {
        match self.inner.impact.target() {
            Target::HalfSpace(m) => material_object(py, &BodyMaterial::Viscoelastic(m.clone())),
            Target::TwoBodies(_) => Ok(None),
        }
    }
    /// The two bodies `(a, b)` of a collision, else `None`.
    #[getter]
    fn bodies(&self) -> Option<(Body, Body)> {
        let exact = match self.inner.impact.shape() {
            Shape::Spheres { caps } => [caps[0].exact, caps[1].exact],
            _ => [false, false],
        };
        self.inner.impact.bodies().map(|b| {
            (
                Body {
                    inner: b.a().clone(),
                    exact: exact[0],
                    shift: None, // the material as solved: already at the temperature
                },
                Body {
                    inner: b.b().clone(),
                    exact: exact[1],
                    shift: None,
                },
            )
        })
    }
    /// The solver's name.
    #[getter]
    fn solver(&self) -> &'static str {
        self.inner.options.solver.name()
    }
    /// Requested relative accuracy of the CoR (dimensionless).
    #[getter]
    fn rtol(&self) -> f64 {
        self.inner.options.rtol
    }
    /// Explicit MDR resolution `(elements, steps)`, else `None`.
    #[getter]
    fn resolution(&self) -> Option<(usize, usize)> {
        self.inner.options.resolution.map(|r| (r.elements, r.steps))
    }
    /// The `[output] history` path (CSV), else `None`.
    #[getter]
    fn history_csv(&self) -> Option<PathBuf> {
        self.inner.history_csv.clone()
    }
    /// The `[output] plot` path, else `None`.
    #[getter]
    fn plot(&self) -> Option<PathBuf> {
        self.inner.plot.clone()
    }
    /// The dimensionless groups `(nu, p2, p3)` of Eq. (11) (standard solid only), else `None`.
    #[getter]
    fn groups(&self) -> Option<(f64, f64, f64)> {
        self.inner.impact.groups().map(|g| (g.nu, g.p2, g.p3))
    }
    /// `G_eq(t)` of the half-space (`G_tot` for two bodies) as a `Prony` (Pa, s).
    fn equivalent_relaxation(&self) -> Prony {
        Prony::of(self.inner.impact.equivalent_relaxation())
    }
    fn __repr__(&self) -> String {
        format!("Scene.from_toml({:?})", self.inner.to_toml())
    }
}
