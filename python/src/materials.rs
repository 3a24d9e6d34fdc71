//! Materials: `Prony`, the standard solid `Material` and the general `GeneralMaterial`.

use super::*;

/// A Prony series `f(t) = relaxed + sum_i c_i exp(-t / tau_i)`: moduli in Pa, times in s.
///
/// `Prony(relaxed, terms=())` with `terms` a sequence of pairs `(c_i, tau_i)` (an `(n, 2)` array
/// works). It only holds the numbers; they are checked where the series is used (a
/// `GeneralMaterial` names `g_i[k]`, `tau_i[k]`, `k_j[k]`, `theta_j[k]` in its errors). Calling
/// it evaluates `f(t)` (Pa) elementwise at the times `t` (s, `t >= 0`): a float for a scalar,
/// else an array of the shape of `t`.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Prony {
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
    pub(crate) fn of(p: &mdr_impact::Prony) -> Self {
        Self {
            relaxed: p.relaxed,
            terms: p.terms.iter().map(|t| (t.coefficient, t.tau)).collect(),
        }
    }
}

/// The paper's standard solid: shear `G(t) = g_inf + g_1 exp(-t g_1 / eta)` (Pa, Pa s) with an
/// elastic bulk given by the static Poisson ratio `poisson` (`-1 < nu <= 0.5`, 0.5:
/// incompressible) or the bulk modulus `k_0` (Pa), exactly one of them. `g_inf = 0` (with
/// `g_1 > 0`, `eta > 0`) is a Maxwell fluid, which has no groups (its `poisson` must be 0.5 or a
/// `k_0` given). `shift` (a `Shift`) is applied by a `Scene` at its temperature.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Material {
    inner: RsMaterial,
    /// The standard solid's view of `inner` (built by a standard-solid constructor).
    solid: StandardSolid,
    /// The time–temperature shift law (`[material.shift]`), applied by a `Scene`.
    shift: Option<ShiftTable>,
}

impl Material {
    /// The Python `Material` of a material of the standard solid's shape.
    pub(crate) fn of(inner: RsMaterial) -> Option<Self> {
        // a Maxwell fluid (g_inf = 0) keeps its parameters, though it has no groups
        let solid = inner
            .as_standard_solid()
            .or_else(|| inner.written_standard_solid())?;
        Some(Self {
            inner,
            solid,
            shift: None,
        })
    }
}

#[pymethods]
impl Material {
    #[new]
    #[pyo3(signature = (g_inf, g_1, eta, *, poisson = None, k_0 = None, shift = None))]
    fn new(
        g_inf: f64,
        g_1: f64,
        eta: f64,
        poisson: Option<f64>,
        k_0: Option<f64>,
        shift: Option<PyRef<'_, Shift>>,
    ) -> PyResult<Self> {
        let inner = match (poisson, k_0) {
            (Some(nu), None) => ok(RsMaterial::with_poisson(g_inf, g_1, eta, nu))?,
            (None, Some(k)) => ok(RsMaterial::new(g_inf, g_1, eta, k))?,
            (Some(_), Some(_)) => return Err(usage("give either poisson or k_0, not both".into())),
            (None, None) => {
                return Err(usage("missing poisson (-1 < nu <= 0.5) or k_0 (Pa)".into()))
            }
        };
        let mut m = Self::of(inner).ok_or_else(|| {
            usage("internal: a standard solid without the standard solid's shape".into())
        })?;
        m.shift = shift.map(|s| s.table);
        Ok(m)
    }
    /// The time–temperature shift law (a `Shift`), or `None`.
    #[getter]
    fn shift(&self) -> Option<Shift> {
        self.shift.map(|table| Shift { table })
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
    fn equivalent_relaxation(&self) -> PyResult<Prony> {
        Ok(Prony::of(&ok(self.inner.equivalent_relaxation())?))
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
            shift: self.shift,
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
/// `relaxed = k_inf`, terms `(k_j, theta_j)`), `k_0` (Pa), `poisson` or `incompressible=True`;
/// `g_inf = 0` with a term is a viscoelastic liquid. `shift` (a `Shift`) is applied by a `Scene`
/// at its temperature.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct GeneralMaterial {
    inner: RsMaterial,
    /// The time–temperature shift law (`[material.shift]`), applied by a `Scene`.
    shift: Option<ShiftTable>,
}

#[pymethods]
impl GeneralMaterial {
    #[new]
    #[pyo3(signature = (shear, *, bulk = None, k_0 = None, poisson = None, incompressible = false,
        shift = None))]
    fn new(
        shear: PyRef<'_, Prony>,
        bulk: Option<PyRef<'_, Prony>>,
        k_0: Option<f64>,
        poisson: Option<f64>,
        incompressible: bool,
        shift: Option<PyRef<'_, Shift>>,
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
            shift: shift.map(|s| s.table),
        })
    }
    /// The time–temperature shift law (a `Shift`), or `None`.
    #[getter]
    fn shift(&self) -> Option<Shift> {
        self.shift.map(|table| Shift { table })
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

/// The shift law of a Python material object (`Material`, `GeneralMaterial`), if any.
pub(crate) fn material_shift(m: &Bound<'_, PyAny>) -> Option<ShiftTable> {
    if let Ok(m) = m.cast::<Material>() {
        return m.get().shift;
    }
    m.cast::<GeneralMaterial>().ok().and_then(|m| m.get().shift)
}

/// A time–temperature shift law of a thermorheologically simple material (docs/theory.md §13,
/// a scene's `[material.shift]`): `Shift.wlf(c1, c2, t_ref)` (`c1` dimensionless, `c2` in K,
/// `t_ref` in °C) or `Shift.arrhenius(activation_energy, t_ref)` (J/mol, °C). At temperature
/// `T` every relaxation time of shear and bulk is multiplied by `a_T`. `calibrated=(t_min,
/// t_max)` (°C), the temperatures the law was fitted on (`calibrated` in a scene): a `Scene` at a
/// temperature outside them warns that the law is extrapolated there.
#[pyclass(frozen, eq, module = "mdr_impact")]
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Shift {
    pub(crate) table: ShiftTable,
}

#[pymethods]
impl Shift {
    /// WLF: `log10 a_T = -c1 (T - t_ref) / (c2 + T - t_ref)`, valid above `t_ref - c2`.
    #[staticmethod]
    #[pyo3(signature = (c1, c2, t_ref, *, calibrated = None))]
    fn wlf(c1: f64, c2: f64, t_ref: f64, calibrated: Option<(f64, f64)>) -> PyResult<Self> {
        let law = ok(ShiftLaw::wlf(c1, c2, t_ref))?;
        Ok(Self {
            table: ok(ShiftTable::new(law, calibrated))?,
        })
    }
    /// Arrhenius: `log10 a_T = E_a / (R ln 10) (1/T_K - 1/T_ref,K)`.
    #[staticmethod]
    #[pyo3(signature = (activation_energy, t_ref, *, calibrated = None))]
    fn arrhenius(
        activation_energy: f64,
        t_ref: f64,
        calibrated: Option<(f64, f64)>,
    ) -> PyResult<Self> {
        let law = ok(ShiftLaw::arrhenius(activation_energy, t_ref))?;
        Ok(Self {
            table: ok(ShiftTable::new(law, calibrated))?,
        })
    }
    /// The temperatures `(t_min, t_max)` (°C) the law was calibrated on, or `None`.
    #[getter]
    fn calibrated(&self) -> Option<(f64, f64)> {
        self.table.calibrated
    }
    /// `"wlf"` or `"arrhenius"`.
    #[getter]
    fn kind(&self) -> &'static str {
        self.table.law.kind()
    }
    /// Reference temperature (°C).
    #[getter]
    fn t_ref(&self) -> f64 {
        self.table.law.t_ref()
    }
    /// `log10 a_T` at `temperature` (°C); an error at or below a WLF law's singularity.
    fn log10_a(&self, temperature: f64) -> PyResult<f64> {
        ok(self.table.law.log10_a(temperature))
    }
    fn __repr__(&self) -> String {
        let calibrated = match self.table.calibrated {
            Some((lo, hi)) => format!(", calibrated=({lo:?}, {hi:?})"),
            None => String::new(),
        };
        match self.table.law {
            ShiftLaw::Wlf { c1, c2, t_ref } => {
                format!("Shift.wlf(c1={c1:?}, c2={c2:?}, t_ref={t_ref:?}{calibrated})")
            }
            ShiftLaw::Arrhenius {
                activation_energy,
                t_ref,
            } => format!(
                "Shift.arrhenius(activation_energy={activation_energy:?}, \
                 t_ref={t_ref:?}{calibrated})"
            ),
        }
    }
}

/// A Python material object (`Material`, `GeneralMaterial`) as the library's body material.
pub(crate) fn body_material(m: &Bound<'_, PyAny>) -> PyResult<BodyMaterial> {
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
pub(crate) fn material_object(py: Python<'_>, m: &BodyMaterial) -> PyResult<Option<Py<PyAny>>> {
    let Some(m) = m.material() else {
        return Ok(None);
    };
    Ok(Some(match Material::of(m.clone()) {
        Some(s) if m.is_written_as_standard_solid() => Py::new(py, s)?.into_any(),
        _ => Py::new(
            py,
            GeneralMaterial {
                inner: m.clone(),
                shift: None,
            },
        )?
        .into_any(),
    }))
}
