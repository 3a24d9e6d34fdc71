//! The outcome of one impact: `ImpactResult`.

use super::*;

/// The outcome of one impact (SI units): `cor` (dimensionless), `rebound_velocity` (m/s), `contact_time` (s),
/// `max_indentation` (m), `time_of_max_indentation` (s), `max_force` (N), `max_contact_radius`
/// (m), `dissipated_energy` (J), `solver`, `estimated_rel_error` (of the CoR, relative; `None`
/// when the solver gives none), `fallback` (why `auto` did not answer with `fast`, else `None`), `work` (dict),
/// `history` (dict of arrays `t`, `d`, `v`, `force`, `a` when asked, else `None`) and, for two
/// bodies, `bodies` (`{"a": v_A, "b": v_B}`, m/s, velocities after the impact in the frame where B
/// was at rest).
#[pyclass(frozen, module = "mdr_impact")]
pub(crate) struct ImpactResult {
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
    pub(crate) fallback: Option<String>,
    /// Why the model may not apply to this answer (one sentence each; empty when it does):
    /// the same lines as `run`'s `warning` lines and `run --json`'s `warnings`.
    #[pyo3(get)]
    pub(crate) warnings: Vec<String>,
    validity: mdr_impact::model::validity::Validity,
    work: mdr_impact::Work,
    histories: Option<History>,
    velocities: Option<(f64, f64)>,
}

impl ImpactResult {
    pub(crate) fn new(
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
