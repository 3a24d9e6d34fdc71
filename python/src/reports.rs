//! The commands' reports: `curve`, `dem`, `prony` and `fit`.

use super::*;

/// CoR and contact time, maximum force and maximum compression (SI) of `scene` at the flat
/// velocities `v0` (m/s) broadcast from `shape`, in parallel with the GIL released: the rows of
/// `mdr-impact curve`. Returns a dict of arrays of `shape` (keys `v0`, `cor`, `contact_time`,
/// `max_force`, `max_compression`) and the curve's limits.
#[pyfunction]
pub(crate) fn curve_values<'py>(
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
    d.set_item(
        "wave_transit_ratio",
        array(
            py,
            rows.iter()
                .map(|r| r.wave_transit_ratio.unwrap_or(f64::NAN))
                .collect(),
            &shape,
        )?,
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
pub(crate) fn dem_report(
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
pub(crate) enum DemVelocities {
    Text(String),
    Parts(f64, f64, Option<i64>),
}

/// `mdr-impact prony` on the DMA file `data` (the command's JSON report as text); with `out`,
/// the command's files are written there too.
#[pyfunction]
#[pyo3(signature = (data, terms, modulus, nu, t_ref, shift, out))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn prony_report(
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
pub(crate) fn fit_report(
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
