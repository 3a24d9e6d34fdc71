//! `mdr_impact._core`: the Python binding of the `mdr-impact` library (PyO3, rust-numpy).
//!
//! This layer only converts types: every number comes from the library ([`mdr_impact::solve`],
//! [`mdr_impact::apps::batch::solve_groups`], [`mdr_impact::apps::curve::run_velocities`], the scene
//! parser), every error is the library's [`mdr_impact::Error`] with the message the command line
//! prints (after `error: `), raised as `mdr_impact.Error`, a subclass of `ValueError`. Solves run
//! with the GIL released, many at once in parallel (rayon). The public Python API, with its
//! docstrings, is `mdr_impact/__init__.py`; the docstrings here describe the classes.

use std::path::PathBuf;

use numpy::{PyArray1, PyArrayDyn, PyArrayLikeDyn, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use mdr_impact::error::escape_text;
use mdr_impact::io::scene::Scene as RsScene;
use mdr_impact::model::bodies::Side;
use mdr_impact::model::geometry::{Cap, Shape, ShapeKeys};
use mdr_impact::model::material::{BulkInput, BulkProny, BulkRheology, ShearProny};
use mdr_impact::{
    apps::batch, apps::curve, apps::dem, io::output, model::tolerances, report::catalogue,
    Body as RsBody, BodyMaterial, Bulk, Groups, History, Impact, Material as RsMaterial, Outcome,
    Resolution, SolveOptions, SolverKind, Sphere as RsSphere, StandardSolid, Target, TwoBodies,
};

pyo3::create_exception!(
    mdr_impact,
    Error,
    PyValueError,
    "Bad input or a refused solve: the message is the one `mdr-impact` prints after `error: `."
);

/// The library's error as `mdr_impact.Error` (a `ValueError`), message as on the command line.
fn py_err(e: mdr_impact::Error) -> PyErr {
    Error::new_err(escape_text(&e.to_string()))
}

/// A library result as a Python result.
fn ok<T>(r: mdr_impact::Result<T>) -> PyResult<T> {
    r.map_err(py_err)
}

/// A message of this layer (argument combinations) as `mdr_impact.Error`.
fn usage(message: String) -> PyErr {
    Error::new_err(message)
}

/// `(i, j, ...)` of the flat (C-order) index `flat` in an array of `shape`.
fn unravel(mut flat: usize, shape: &[usize]) -> String {
    let mut idx = vec![0usize; shape.len()];
    for (k, &n) in shape.iter().enumerate().rev() {
        if n > 0 {
            idx[k] = flat % n;
            flat /= n;
        }
    }
    let parts: Vec<String> = idx.iter().map(usize::to_string).collect();
    if parts.len() == 1 {
        format!("({},)", parts[0])
    } else {
        format!("({})", parts.join(", "))
    }
}

/// The error of element `flat` of an array of `shape`: the command line's message, prefixed by
/// the element's index unless the input was a scalar (`shape = ()`).
fn element_err(flat: usize, shape: &[usize], e: mdr_impact::Error) -> PyErr {
    let msg = escape_text(&e.to_string());
    if shape.is_empty() {
        Error::new_err(msg)
    } else {
        Error::new_err(format!("index {}: {msg}", unravel(flat, shape)))
    }
}

/// Solve options from the Python arguments, validated as the command line does.
fn options(solver: &str, rtol: f64) -> PyResult<SolveOptions> {
    let opts = SolveOptions {
        solver: ok(solver.parse::<SolverKind>())?,
        rtol,
        ..Default::default()
    };
    ok(opts.validate())?;
    Ok(opts)
}

fn array<'py>(py: Python<'py>, v: Vec<f64>, shape: &[usize]) -> PyResult<Bound<'py, PyAny>> {
    let a = PyArray1::from_vec(py, v);
    Ok(a.reshape(shape.to_vec())?.into_any())
}

/// Elements solved per release of the GIL: between two chunks a pending signal is handled, so
/// Ctrl-C (`KeyboardInterrupt`) ends a long call after the chunk in progress.
const CHUNK: usize = 4096;

/// `solve` over `items` in chunks of [`CHUNK`], in order, each with the GIL released; a pending
/// signal between chunks ends the call with its exception. The error of a failing chunk carries
/// the index in `items` of its first failing element (so the first in input order, as
/// `cor --input` reports it).
fn in_chunks<T, R, F>(
    py: Python<'_>,
    items: &[T],
    solve: F,
) -> PyResult<Result<Vec<R>, (usize, mdr_impact::Error)>>
where
    T: Sync,
    R: Send,
    F: Fn(&[T]) -> Result<Vec<R>, (usize, mdr_impact::Error)> + Sync,
{
    let mut out = Vec::with_capacity(items.len());
    for (k, chunk) in items.chunks(CHUNK).enumerate() {
        match py.detach(|| solve(chunk)) {
            Ok(rows) => out.extend(rows),
            Err((i, e)) => return Ok(Err((k * CHUNK + i, e))),
        }
        py.check_signals()?;
    }
    Ok(Ok(out))
}

// ------------------------------------------------------------------------------------------
// Dimensionless groups
// ------------------------------------------------------------------------------------------

/// CoR, contact time and maximum indentation (canonical units `m = R = v0 = G_inf = 1`) of the
/// flat arrays `nu`, `p2`, `p3` (equal lengths) that were broadcast to `shape`: the computation
/// of `mdr-impact cor --input`, in parallel, GIL released ([`in_chunks`]). Errors name the
/// element's index.
#[pyfunction]
#[pyo3(signature = (nu, p2, p3, shape, rtol, solver))]
fn cor_groups<'py>(
    py: Python<'py>,
    nu: PyReadonlyArray1<'py, f64>,
    p2: PyReadonlyArray1<'py, f64>,
    p3: PyReadonlyArray1<'py, f64>,
    shape: Vec<usize>,
    rtol: f64,
    solver: &str,
) -> PyResult<Bound<'py, PyTuple>> {
    let opts = options(solver, rtol)?;
    let (nu, p2, p3) = (nu.to_vec()?, p2.to_vec()?, p3.to_vec()?);
    if nu.len() != p2.len() || nu.len() != p3.len() {
        return Err(usage(format!(
            "nu, p2 and p3 have {}, {} and {} elements: broadcast them first",
            nu.len(),
            p2.len(),
            p3.len()
        )));
    }
    if nu.len() != shape.iter().product::<usize>() {
        return Err(usage(format!(
            "{} elements do not fill the shape {shape:?}",
            nu.len()
        )));
    }
    // every input checked before anything is solved, as `cor --input` reads its file first
    let mut groups = Vec::with_capacity(nu.len());
    for i in 0..nu.len() {
        groups.push(Groups::new(nu[i], p2[i], p3[i]).map_err(|e| element_err(i, &shape, e))?);
    }
    let outcomes = in_chunks(py, &groups, |g| batch::solve_groups(g, &opts))?
        .map_err(|(i, e)| element_err(i, &shape, e))?;
    let pick = |f: fn(&Outcome) -> f64| outcomes.iter().map(f).collect::<Vec<f64>>();
    let cor = array(py, pick(|o| o.cor), &shape)?;
    let time = array(py, pick(|o| o.contact_time), &shape)?;
    let depth = array(py, pick(|o| o.max_indentation), &shape)?;
    PyTuple::new(py, [cor, time, depth])
}

/// The catalogue of validation cases (`src/report/catalogue.rs`): a list of dicts with the keys `id`,
/// `regime`, `nu`, `p2`, `p3`.
#[pyfunction]
fn catalogue_impacts(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    catalogue::IMPACTS
        .iter()
        .map(|c| {
            let d = PyDict::new(py);
            d.set_item("id", c.id)?;
            d.set_item("regime", c.regime.name())?;
            d.set_item("nu", c.nu)?;
            d.set_item("p2", c.p2)?;
            d.set_item("p3", c.p3)?;
            Ok(d)
        })
        .collect()
}

// ------------------------------------------------------------------------------------------
// Materials
// ------------------------------------------------------------------------------------------

/// A Prony series `f(t) = relaxed + sum_i c_i exp(-t / tau_i)`: moduli in Pa, times in s.
///
/// `Prony(relaxed, terms=())` with `terms` a sequence of pairs `(c_i, tau_i)` (an `(n, 2)` array
/// works). It only holds the numbers; they are checked where the series is used (a
/// `GeneralMaterial` names `g_i[k]`, `tau_i[k]`, `k_j[k]`, `theta_j[k]` in its errors). Calling
/// it evaluates `f(t)` (Pa) elementwise at the times `t` (s, `t >= 0`): a float for a scalar,
/// else an array of the shape of `t`.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
struct Prony {
    relaxed: f64,
    terms: Vec<(f64, f64)>,
}

#[pymethods]
impl Prony {
    #[new]
    #[pyo3(signature = (relaxed, terms = Vec::new()))]
    fn new(relaxed: f64, terms: Vec<[f64; 2]>) -> Self {
        Self {
            relaxed,
            terms: terms.into_iter().map(|[c, t]| (c, t)).collect(),
        }
    }

    /// The relaxed value `f(inf)` (Pa).
    #[getter]
    fn relaxed(&self) -> f64 {
        self.relaxed
    }

    /// The terms as an `(n, 2)` array of `(c_i` (Pa), `tau_i` (s)`)`.
    #[getter]
    fn terms<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let flat: Vec<f64> = self.terms.iter().flat_map(|&(c, t)| [c, t]).collect();
        array(py, flat, &[self.terms.len(), 2])
    }

    /// The glassy value `f(0) = relaxed + sum_i c_i` (Pa).
    #[getter]
    fn glassy(&self) -> f64 {
        self.relaxed + self.terms.iter().map(|&(c, _)| c).sum::<f64>()
    }

    fn __call__<'py>(
        &self,
        py: Python<'py>,
        t: PyArrayLikeDyn<'py, f64, numpy::AllowTypeChange>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let p = self.library();
        let values = t.as_array().mapv(|t| p.eval(t));
        if values.ndim() == 0 {
            let v = values.iter().next().copied().unwrap_or(f64::NAN);
            return Ok(v.into_pyobject(py)?.into_any());
        }
        Ok(PyArrayDyn::from_owned_array(py, values).into_any())
    }

    fn __len__(&self) -> usize {
        self.terms.len()
    }

    fn __repr__(&self) -> String {
        format!("Prony(relaxed={:?}, terms={:?})", self.relaxed, self.terms)
    }
}

impl Prony {
    fn library(&self) -> mdr_impact::Prony {
        mdr_impact::Prony {
            relaxed: self.relaxed,
            terms: self
                .terms
                .iter()
                .map(|&(coefficient, tau)| mdr_impact::PronyTerm { coefficient, tau })
                .collect(),
        }
    }
    fn of(p: &mdr_impact::Prony) -> Self {
        Self {
            relaxed: p.relaxed,
            terms: p.terms.iter().map(|t| (t.coefficient, t.tau)).collect(),
        }
    }
}

/// The paper's standard solid: shear `G(t) = g_inf + g_1 exp(-t g_1 / eta)` (Pa, Pa s) with an
/// elastic bulk given by the static Poisson ratio `poisson` (`-1 < nu <= 0.5`, 0.5:
/// incompressible) or the bulk modulus `k_0` (Pa), exactly one of them.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
struct Material {
    inner: RsMaterial,
    /// The standard solid's view of `inner` (built by a standard-solid constructor).
    solid: StandardSolid,
}

impl Material {
    /// The Python `Material` of a material of the standard solid's shape.
    fn of(inner: RsMaterial) -> Option<Self> {
        let solid = inner.as_standard_solid()?;
        Some(Self { inner, solid })
    }
}

#[pymethods]
impl Material {
    #[new]
    #[pyo3(signature = (g_inf, g_1, eta, *, poisson = None, k_0 = None))]
    fn new(
        g_inf: f64,
        g_1: f64,
        eta: f64,
        poisson: Option<f64>,
        k_0: Option<f64>,
    ) -> PyResult<Self> {
        let inner = match (poisson, k_0) {
            (Some(nu), None) => ok(RsMaterial::with_poisson(g_inf, g_1, eta, nu))?,
            (None, Some(k)) => ok(RsMaterial::new(g_inf, g_1, eta, k))?,
            (Some(_), Some(_)) => return Err(usage("give either poisson or k_0, not both".into())),
            (None, None) => {
                return Err(usage("missing poisson (-1 < nu <= 0.5) or k_0 (Pa)".into()))
            }
        };
        Self::of(inner).ok_or_else(|| {
            usage("internal: a standard solid without the standard solid's shape".into())
        })
    }
    /// Relaxed shear modulus `G_inf` (Pa).
    #[getter]
    fn g_inf(&self) -> f64 {
        self.inner.g_inf()
    }
    /// Relaxing shear modulus `G_1` (Pa).
    #[getter]
    fn g_1(&self) -> f64 {
        self.solid.g_1()
    }
    /// Shear viscosity `eta` (Pa s).
    #[getter]
    fn eta(&self) -> f64 {
        self.solid.eta()
    }
    /// Bulk modulus `K_0` (Pa), `inf` when incompressible.
    #[getter]
    fn k_0(&self) -> f64 {
        self.solid.k_0()
    }
    /// Static Poisson ratio (dimensionless; 0.5 when incompressible).
    #[getter]
    fn poisson(&self) -> f64 {
        match self.solid.bulk() {
            Bulk::Incompressible => 0.5,
            Bulk::Modulus(_) => self.solid.poisson(),
        }
    }
    /// Relaxation time `tau = eta / g_1` (s).
    #[getter]
    fn tau(&self) -> f64 {
        self.solid.tau()
    }
    /// True when `g_1 = 0` or `eta = 0` (Hertz with `g_inf`).
    #[getter]
    fn is_elastic(&self) -> bool {
        self.solid.is_elastic()
    }
    /// The equivalent incompressible relaxation function `G_eq(t)` (docs/theory.md §2) as a
    /// `Prony` (Pa, s).
    fn equivalent_relaxation(&self) -> Prony {
        Prony::of(&self.solid.equivalent_relaxation())
    }
    /// This standard solid as a `GeneralMaterial` (one shear term).
    fn general(&self) -> GeneralMaterial {
        let bulk = match self.inner.written_poisson() {
            Some(nu) => BulkInput::Poisson(nu),
            None => BulkInput::from(self.inner.bulk().clone()),
        };
        GeneralMaterial {
            inner: RsMaterial::general(self.inner.shear().clone(), bulk)
                .expect("a validated shear series and resolved bulk"),
        }
    }
    fn __repr__(&self) -> String {
        let bulk = match self.solid.bulk() {
            Bulk::Incompressible => "poisson=0.5".to_string(),
            Bulk::Modulus(k) => format!("k_0={k:?}"),
        };
        format!(
            "Material(g_inf={:?}, g_1={:?}, eta={:?}, {bulk})",
            self.inner.g_inf(),
            self.solid.g_1(),
            self.solid.eta()
        )
    }
}

/// A general linear-viscoelastic solid (docs/theory.md §8): the shear series `shear` (a `Prony`
/// with `relaxed = g_inf`, terms `(g_i, tau_i)`) and exactly one bulk: `bulk` (a `Prony`,
/// `relaxed = k_inf`, terms `(k_j, theta_j)`), `k_0` (Pa), `poisson` or `incompressible=True`.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
struct GeneralMaterial {
    inner: RsMaterial,
}

#[pymethods]
impl GeneralMaterial {
    #[new]
    #[pyo3(signature = (shear, *, bulk = None, k_0 = None, poisson = None, incompressible = false))]
    fn new(
        shear: PyRef<'_, Prony>,
        bulk: Option<PyRef<'_, Prony>>,
        k_0: Option<f64>,
        poisson: Option<f64>,
        incompressible: bool,
    ) -> PyResult<Self> {
        let given = [
            bulk.is_some(),
            k_0.is_some(),
            poisson.is_some(),
            incompressible,
        ];
        if given.iter().filter(|g| **g).count() != 1 {
            return Err(usage(
                "give exactly one bulk: bulk=Prony(k_inf, terms), k_0, poisson or \
                 incompressible=True"
                    .into(),
            ));
        }
        let s = ok(ShearProny::new(shear.relaxed, &shear.terms))?;
        let rheology = match (bulk, k_0, poisson) {
            (Some(b), _, _) => BulkInput::Prony(ok(BulkProny::new(b.relaxed, &b.terms))?),
            (_, Some(k), _) => BulkInput::Elastic(k),
            (_, _, Some(nu)) => BulkInput::Poisson(nu),
            _ => BulkInput::Incompressible,
        };
        Ok(Self {
            inner: ok(RsMaterial::general(s, rheology))?,
        })
    }
    /// The shear series `G(t)` as validated (terms sorted by time, equal times merged, zero
    /// moduli dropped).
    #[getter]
    fn shear(&self) -> Prony {
        let s = self.inner.shear();
        Prony {
            relaxed: s.g_inf(),
            terms: s.terms().to_vec(),
        }
    }
    /// The bulk series `K(t)` when viscoelastic, else `None`.
    #[getter]
    fn bulk(&self) -> Option<Prony> {
        match self.inner.bulk() {
            BulkRheology::Prony(p) => Some(Prony {
                relaxed: p.k_inf(),
                terms: p.terms().to_vec(),
            }),
            _ => None,
        }
    }
    /// `"incompressible"`, `"elastic"` or `"prony"`.
    #[getter]
    fn bulk_kind(&self) -> &'static str {
        match self.inner.bulk() {
            BulkRheology::Incompressible => "incompressible",
            BulkRheology::Prony(_) => "prony",
            BulkRheology::Elastic(_) => "elastic",
        }
    }
    /// Relaxed bulk modulus `K(inf)` (Pa), `inf` when incompressible.
    #[getter]
    fn k_0(&self) -> f64 {
        self.inner.bulk_relaxed()
    }
    /// `G_eq(t)` (docs/theory.md §8) as an exact `Prony` series (Pa, s).
    fn equivalent_relaxation(&self) -> PyResult<Prony> {
        Ok(Prony::of(&ok(self.inner.equivalent_relaxation())?))
    }
    fn __repr__(&self) -> String {
        let bulk = match self.inner.bulk() {
            BulkRheology::Incompressible => "incompressible=True".to_string(),
            BulkRheology::Elastic(k) => format!("k_0={k:?}"),
            BulkRheology::Prony(_) => format!(
                "bulk={}",
                self.bulk().map(|b| b.__repr__()).unwrap_or_default()
            ),
        };
        format!("GeneralMaterial(shear={}, {bulk})", self.shear().__repr__())
    }
}

/// A Python material object (`Material`, `GeneralMaterial`) as the library's body material.
fn body_material(m: &Bound<'_, PyAny>) -> PyResult<BodyMaterial> {
    if let Ok(m) = m.cast::<Material>() {
        return Ok(BodyMaterial::Viscoelastic(m.get().inner.clone()));
    }
    if let Ok(m) = m.cast::<GeneralMaterial>() {
        return Ok(BodyMaterial::Viscoelastic(m.get().inner.clone()));
    }
    Err(pyo3::exceptions::PyTypeError::new_err(format!(
        "material must be a Material or a GeneralMaterial, not {}",
        m.get_type().name()?
    )))
}

/// A body material as a Python object (`None` when rigid): a `Material` when it was written as
/// a standard solid, else a `GeneralMaterial`.
fn material_object(py: Python<'_>, m: &BodyMaterial) -> PyResult<Option<Py<PyAny>>> {
    let Some(m) = m.material() else {
        return Ok(None);
    };
    Ok(Some(match Material::of(m.clone()) {
        Some(s) if m.is_written_as_standard_solid() => Py::new(py, s)?.into_any(),
        _ => Py::new(py, GeneralMaterial { inner: m.clone() })?.into_any(),
    }))
}

// ------------------------------------------------------------------------------------------
// Sphere, bodies, scenes
// ------------------------------------------------------------------------------------------

/// A rigid sphere: `mass` (kg) and `radius` (m), both `0 < x < inf`; `profile` is
/// `"paraboloid"` (Hertz, the default) or `"sphere"` (the exact cap, docs/theory.md §11).
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
struct Sphere {
    inner: RsSphere,
    exact: bool,
}

/// `true` for `profile="sphere"`, `false` for `"paraboloid"`.
fn exact_profile(profile: &str) -> PyResult<bool> {
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
fn profile_name(exact: bool) -> &'static str {
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
struct Indenter {
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
struct Body {
    inner: RsBody,
    /// `profile="sphere"`: the exact cap.
    exact: bool,
}

/// `e` without the body it is placed at (`Error::In`): a body is named only once it is placed in
/// a scene.
fn unsided(e: mdr_impact::Error) -> mdr_impact::Error {
    match e {
        mdr_impact::Error::In { source, .. } => *source,
        other => other,
    }
}

impl Body {
    /// The same body as body `side` of a collision.
    fn as_side(&self, side: Side) -> PyResult<RsBody> {
        let b = &self.inner;
        ok(RsBody::new(
            side,
            b.mass(),
            b.radius(),
            b.material().clone(),
        ))
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
        Ok(Self { inner, exact })
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
/// `Scene.run`).
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
struct Scene {
    inner: RsScene,
}

#[pymethods]
impl Scene {
    #[new]
    #[pyo3(signature = (*, velocity, sphere = None, material = None, bodies = None,
        indenter = None, solver = "auto", rtol = tolerances::DEFAULT_RTOL, elements = None, steps = None,
        history_csv = None, plot = None))]
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
    ) -> PyResult<Self> {
        let half_space = |m: &Bound<'_, PyAny>| match body_material(m)? {
            BodyMaterial::Viscoelastic(m) => Ok(m),
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
                let pair = ok(TwoBodies::new(a.as_side(Side::A)?, b.as_side(Side::B)?))?;
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
                temperature: None,
                shifts: Vec::new(),
            },
        })
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
        let outcome = ok(py.detach(|| mdr_impact::solve(impact, &opts)))?;
        let bodies = impact
            .bodies()
            .map(|b| b.rebound_velocities(impact.velocity(), outcome.cor));
        let validity = mdr_impact::model::validity::Validity::of(impact, &outcome);
        // as `run --json`: `fallback` says why auto did not answer with fast, and the
        // plausibility warnings of the inputs come first
        let fallback = output::fallback(&opts, &outcome);
        let mut warnings = mdr_impact::model::plausibility::warnings(impact);
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
                },
                Body {
                    inner: b.b().clone(),
                    exact: exact[1],
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

// ------------------------------------------------------------------------------------------
// Results
// ------------------------------------------------------------------------------------------

/// The outcome of one impact (SI units): `cor` (dimensionless), `rebound_velocity` (m/s), `contact_time` (s),
/// `max_indentation` (m), `time_of_max_indentation` (s), `max_force` (N), `max_contact_radius`
/// (m), `dissipated_energy` (J), `solver`, `estimated_rel_error` (of the CoR, relative; `None`
/// when the solver gives none), `fallback` (why `auto` did not answer with `fast`, else `None`), `work` (dict),
/// `history` (dict of arrays `t`, `d`, `v`, `force`, `a` when asked, else `None`) and, for two
/// bodies, `bodies` (`{"a": v_A, "b": v_B}`, m/s, velocities after the impact in the frame where B
/// was at rest).
#[pyclass(frozen, module = "mdr_impact")]
struct ImpactResult {
    /// Coefficient of restitution `e = -v_end / v0` (Eq. 10; dimensionless).
    #[pyo3(get)]
    cor: f64,
    /// Rebound velocity at separation (m/s).
    #[pyo3(get)]
    rebound_velocity: f64,
    /// Contact duration (s).
    #[pyo3(get)]
    contact_time: f64,
    /// Maximum indentation (m; the total compression of both bodies for two).
    #[pyo3(get)]
    max_indentation: f64,
    /// Time of maximum indentation (s).
    #[pyo3(get)]
    time_of_max_indentation: f64,
    /// Maximum contact force (N).
    #[pyo3(get)]
    max_force: f64,
    /// Maximum contact radius (m).
    #[pyo3(get)]
    max_contact_radius: f64,
    /// Dissipated energy `m (v0^2 - v^2) / 2` (J).
    #[pyo3(get)]
    dissipated_energy: f64,
    /// Estimated relative error of the CoR (dimensionless), `None` when the solver gives none.
    #[pyo3(get)]
    estimated_rel_error: Option<f64>,
    /// The solver that answered.
    #[pyo3(get)]
    solver: &'static str,
    /// Why `auto` answered with `reference` instead of `fast`, else `None`.
    #[pyo3(get)]
    fallback: Option<String>,
    /// Why the model may not apply to this answer (one sentence each; empty when it does):
    /// the same lines as `run`'s `warning` lines and `run --json`'s `warnings`.
    #[pyo3(get)]
    warnings: Vec<String>,
    validity: mdr_impact::model::validity::Validity,
    work: mdr_impact::Work,
    histories: Option<History>,
    velocities: Option<(f64, f64)>,
}

impl ImpactResult {
    fn new(
        o: Outcome,
        velocities: Option<(f64, f64)>,
        validity: mdr_impact::model::validity::Validity,
    ) -> Self {
        Self {
            warnings: validity.warnings.clone(),
            validity,
            cor: o.cor,
            rebound_velocity: o.rebound_velocity,
            contact_time: o.contact_time,
            max_indentation: o.max_indentation,
            time_of_max_indentation: o.time_of_max_indentation,
            max_force: o.max_force,
            max_contact_radius: o.max_contact_radius,
            dissipated_energy: o.dissipated_energy,
            estimated_rel_error: o.cor_error_estimate,
            solver: o.solver.name(),
            fallback: o.fallback.map(|e| e.to_string()),
            work: o.work,
            histories: o.history,
            velocities,
        }
    }
}

#[pymethods]
impl ImpactResult {
    /// Validity measures (`run --json`'s `validity`), all dimensionless: `contact_radius_ratio`
    /// (a_max/R), `indentation_ratio` (d_max/R), `sphere_force_excess` (the exact sphere's extra
    /// force at a_max, relative; `None` beyond the sphere), `wave_transit_ratio`
    /// (`2 a_max / (c_s t_c)`, shear wave transit over contact time; `None` without a density).
    #[getter]
    fn validity<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let v = &self.validity;
        let d = PyDict::new(py);
        d.set_item("contact_radius_ratio", v.contact_radius_ratio)?;
        d.set_item("indentation_ratio", v.indentation_ratio)?;
        d.set_item("sphere_force_excess", v.sphere_force_excess)?;
        d.set_item("wave_transit_ratio", v.wave_transit_ratio)?;
        Ok(d)
    }
    /// Work counters (counts): `steps`, `elements`, `element_updates`, `evaluations`,
    /// `levels`; 0 where a counter does not apply to the solver.
    #[getter]
    fn work<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let w = self.work;
        let d = PyDict::new(py);
        d.set_item("steps", w.steps)?;
        d.set_item("elements", w.elements)?;
        d.set_item("element_updates", w.element_updates)?;
        d.set_item("evaluations", w.evaluations)?;
        d.set_item("levels", w.levels)?;
        Ok(d)
    }
    /// Histories (SI): dict of arrays `t` (s), `d` (m), `v` (m/s), `force` (N), `a` (m), when
    /// asked (`run(history=True)`), else `None`.
    #[getter]
    fn history<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(h) = &self.histories else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        let History {
            t,
            d: depth,
            v,
            force,
            a,
        } = h;
        for (k, x) in [("t", t), ("d", depth), ("v", v), ("force", force), ("a", a)] {
            d.set_item(k, PyArray1::from_slice(py, x))?;
        }
        Ok(Some(d))
    }
    /// Two bodies: `{"a": v_A, "b": v_B}` (m/s) after the impact, else `None`.
    #[getter]
    fn bodies<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some((va, vb)) = self.velocities else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        d.set_item("a", va)?;
        d.set_item("b", vb)?;
        Ok(Some(d))
    }
    fn __repr__(&self) -> String {
        format!(
            "ImpactResult(cor={:?}, contact_time={:?} s, max_force={:?} N, solver={:?})",
            self.cor, self.contact_time, self.max_force, self.solver
        )
    }
}

/// CoR and contact time, maximum force and maximum compression (SI) of `scene` at the flat
/// velocities `v0` (m/s) broadcast from `shape`, in parallel with the GIL released: the rows of
/// `mdr-impact curve`. Returns a dict of arrays of `shape` (keys `v0`, `cor`, `contact_time`,
/// `max_force`, `max_compression`) and the curve's limits.
#[pyfunction]
fn curve_values<'py>(
    py: Python<'py>,
    scene: PyRef<'py, Scene>,
    v0: PyReadonlyArray1<'py, f64>,
    shape: Vec<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let v0 = v0.to_vec()?;
    if v0.len() != shape.iter().product::<usize>() {
        return Err(usage(format!(
            "{} velocities do not fill the shape {shape:?}",
            v0.len()
        )));
    }
    let s = &scene.inner;
    let rows = in_chunks(py, &v0, |v| {
        curve::run_velocities(&s.impact, &s.options, v, &|| {})
    })?
    .map_err(|(i, e)| element_err(i, &shape, e))?;
    let d = PyDict::new(py);
    let col = |f: fn(&curve::CurveRow) -> f64| rows.iter().map(f).collect::<Vec<f64>>();
    d.set_item("v0", array(py, v0.clone(), &shape)?)?;
    d.set_item("cor", array(py, col(|r| r.cor), &shape)?)?;
    d.set_item("contact_time", array(py, col(|r| r.contact_time), &shape)?)?;
    d.set_item("max_force", array(py, col(|r| r.max_force), &shape)?)?;
    d.set_item(
        "max_compression",
        array(py, col(|r| r.max_compression), &shape)?,
    )?;
    d.set_item(
        "contact_radius_ratio",
        array(py, col(|r| r.contact_radius_ratio), &shape)?,
    )?;
    d.set_item(
        "indentation_ratio",
        array(py, col(|r| r.indentation_ratio), &shape)?,
    )?;
    let outside: Vec<bool> = rows.iter().map(|r| r.outside_validity).collect();
    d.set_item(
        "outside_validity",
        numpy::PyArray1::from_vec(py, outside).reshape(shape.clone())?,
    )?;
    let l = curve::limits(&s.impact);
    let limits = PyDict::new(py);
    limits.set_item("relaxed_modulus", l.relaxed_modulus)?;
    limits.set_item("glassy_modulus", l.glassy_modulus)?;
    limits.set_item("p3_unit_velocity", l.p3_unit_velocity)?;
    limits.set_item("slowest_tau", l.slowest_tau)?;
    limits.set_item("fastest_tau", l.fastest_tau)?;
    limits.set_item("relaxed_crossover", l.relaxed_crossover)?;
    limits.set_item("glassy_crossover", l.glassy_crossover)?;
    d.set_item("limits", limits)?;
    Ok(d)
}

/// `mdr-impact dem` on `scene`: our `e(v0)` at the velocities `v0` and both DEM damping laws
/// fitted with the Hertz stiffness of `modulus` (`relaxed` or `glassy`), GIL released. `v0` is
/// the command's text `MIN:MAX[:N]` (errors name `--v0`) or the numbers `(MIN, MAX, N or None)`
/// (m/s; errors name `v0`); log spaced with `log`. Returns the report as the command's JSON text
/// and its LAMMPS and LIGGGHTS input lines.
#[pyfunction]
fn dem_report(
    py: Python<'_>,
    scene: PyRef<'_, Scene>,
    v0: DemVelocities,
    log: bool,
    modulus: &str,
) -> PyResult<(String, String, String)> {
    let range = ok(match v0 {
        DemVelocities::Text(text) => {
            curve::VelocityRange::parse_optional_n(&text, log, dem::DEFAULT_VELOCITIES)
        }
        DemVelocities::Parts(min, max, n) => {
            curve::VelocityRange::from_parts("v0", min, max, n, dem::DEFAULT_VELOCITIES, log)
        }
    })?;
    let modulus = ok(modulus.parse::<dem::ModulusChoice>())?;
    let s = &scene.inner;
    let report = ok(py.detach(|| dem::run(&s.impact, &s.options, &range, modulus, &|| {})))?;
    Ok((report.json(), report.lammps_text(), report.liggghts_text()))
}

/// The velocities of `dem_report`: the command line's text, or `(MIN, MAX, N or None)`.
#[derive(FromPyObject)]
enum DemVelocities {
    Text(String),
    Parts(f64, f64, Option<i64>),
}

/// `mdr-impact prony` on the DMA file `data` (the command's JSON report as text); with `out`,
/// the command's files are written there too.
#[pyfunction]
#[pyo3(signature = (data, terms, modulus, nu, t_ref, shift, out))]
#[allow(clippy::too_many_arguments)]
fn prony_report(
    py: Python<'_>,
    data: std::path::PathBuf,
    terms: &str,
    modulus: &str,
    nu: Option<f64>,
    t_ref: Option<f64>,
    shift: &str,
    out: Option<std::path::PathBuf>,
) -> PyResult<String> {
    use mdr_impact::apps::dma;
    let options = dma::PronyOptions {
        data,
        max_terms: ok(dma::parse_terms(terms))?,
        modulus: ok(modulus.parse())?,
        nu,
        t_ref,
        shift: ok(shift.parse())?,
    };
    let report = ok(py.detach(|| dma::run(&options)))?;
    if let Some(dir) = out {
        ok(dma::write_outputs(&dir, &report))?;
    }
    Ok(dma::json(&report).to_string())
}

/// `mdr-impact fit` on the drop-test file `data` with the impactor of `scene` (the embedded
/// default when `None`): the command's JSON report as text; with `out`, `fit.toml` and
/// `fit.svg` are written there too. `fix` pairs `(name, value)` as `--fix name=value`;
/// `tau_range` `(min, max)` (s) as `--tau-range`.
#[pyfunction]
#[pyo3(signature = (data, scene, model, fix, tau_range, out))]
fn fit_report(
    py: Python<'_>,
    data: PathBuf,
    scene: Option<PyRef<'_, Scene>>,
    model: &str,
    fix: Vec<(String, f64)>,
    tau_range: Option<(f64, f64)>,
    out: Option<PathBuf>,
) -> PyResult<String> {
    use mdr_impact::apps::fit;
    let kind = ok(model.parse::<fit::ModelKind>())?;
    let fixes = fix
        .iter()
        .map(|(name, value)| ok(format!("{name}={value:e}").parse::<fit::Fix>()))
        .collect::<PyResult<Vec<_>>>()?;
    let (scene, name) = match &scene {
        Some(s) => (s.inner.clone(), "the scene".to_string()),
        None => (RsScene::default_scene(), "default scene".to_string()),
    };
    let impactor = ok(fit::data::scene_sphere(&scene, &name))?;
    let range = tau_range.map(|(lo, hi)| format!("{lo:e}:{hi:e}"));
    let result = py.detach(|| -> mdr_impact::Result<_> {
        let data = fit::data::read(&data, impactor, &name)?;
        let taus = fit::prony_times(&kind, range.as_deref(), &data)?;
        let (model, fixed) = fit::setup_model(kind, &fixes, taus)?;
        fit::fit(&model, &data, &fixed)
    });
    let result = ok(result)?;
    if let Some(dir) = out {
        ok(fit::report::write_outputs(&dir, &result))?;
    }
    Ok(fit::report::json(&result).to_string())
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("Error", m.py().get_type::<Error>())?;
    // the package version: python/Cargo.toml's, which maturin also writes into the metadata
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("DEFAULT_RTOL", tolerances::DEFAULT_RTOL)?;
    m.add("MIN_RTOL", tolerances::MIN_RTOL)?;
    m.add("MAX_RTOL", tolerances::MAX_RTOL)?;
    m.add("SOLVERS", SolverKind::NAMES.to_vec())?;
    m.add("DEFAULT_SCENE", mdr_impact::io::scene::DEFAULT_SCENE)?;
    m.add_function(wrap_pyfunction!(cor_groups, m)?)?;
    m.add_function(wrap_pyfunction!(curve_values, m)?)?;
    m.add_function(wrap_pyfunction!(catalogue_impacts, m)?)?;
    m.add_function(wrap_pyfunction!(dem_report, m)?)?;
    m.add_function(wrap_pyfunction!(prony_report, m)?)?;
    m.add_function(wrap_pyfunction!(fit_report, m)?)?;
    m.add_class::<Prony>()?;
    m.add_class::<Material>()?;
    m.add_class::<GeneralMaterial>()?;
    m.add_class::<Sphere>()?;
    m.add_class::<Indenter>()?;
    m.add_class::<Body>()?;
    m.add_class::<Scene>()?;
    m.add_class::<ImpactResult>()?;
    Ok(())
}
