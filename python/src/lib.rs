//! `mdr_impact._core`: the Python binding of the `mdr-impact` library (PyO3, rust-numpy).
//!
//! This layer only converts types: every number comes from the library ([`mdr_impact::solve`],
//! [`mdr_impact::apps::batch::solve_groups`], [`mdr_impact::apps::curve::run_velocities`], the scene
//! parser), every error is the library's [`mdr_impact::Error`] with the message the command line
//! prints (after `error: `), raised as `mdr_impact.Error`, a subclass of `ValueError`. Solves run
//! with the GIL released, many at once in parallel (rayon). The public Python API, with its
//! docstrings, is `mdr_impact/__init__.py`; the docstrings here describe the classes.

mod materials;
mod oblique;
mod reports;
mod result;
mod scene;
mod solve;

use std::path::PathBuf;

use numpy::{PyArray1, PyArrayDyn, PyArrayLikeDyn, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use mdr_impact::error::escape_text;
use mdr_impact::io::scene::Scene as RsScene;
use mdr_impact::io::scene::{shift_warning, shifted_material, temperature_without_shift};
use mdr_impact::model::bodies::Side;
use mdr_impact::model::geometry::{Cap, Shape, ShapeKeys};
use mdr_impact::model::material::shift::{ShiftLaw, ShiftTable};
use mdr_impact::model::material::{BulkInput, BulkProny, BulkRheology, ShearProny};
use mdr_impact::{
    apps::batch, apps::curve, apps::dem, io::output, model::tolerances, report::catalogue,
    Body as RsBody, BodyMaterial, Bulk, Groups, History, Impact, Material as RsMaterial, Outcome,
    Resolution, SolveOptions, SolverKind, Sphere as RsSphere, StandardSolid, Target, TwoBodies,
};

use materials::{
    body_material, material_object, material_shift, GeneralMaterial, Material, Prony, Shift,
};
use oblique::{angle_curve_values, oblique_values};
use reports::{curve_values, dem_report, fit_report, prony_report};
use result::ImpactResult;
use scene::{Body, Indenter, Scene, Sphere};
use solve::{catalogue_impacts, cor_groups};

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
    m.add_function(wrap_pyfunction!(oblique_values, m)?)?;
    m.add_function(wrap_pyfunction!(angle_curve_values, m)?)?;
    m.add_function(wrap_pyfunction!(catalogue_impacts, m)?)?;
    m.add_function(wrap_pyfunction!(dem_report, m)?)?;
    m.add_function(wrap_pyfunction!(prony_report, m)?)?;
    m.add_function(wrap_pyfunction!(fit_report, m)?)?;
    m.add_class::<Prony>()?;
    m.add_class::<Material>()?;
    m.add_class::<Shift>()?;
    m.add_class::<GeneralMaterial>()?;
    m.add_class::<Sphere>()?;
    m.add_class::<Indenter>()?;
    m.add_class::<Body>()?;
    m.add_class::<Scene>()?;
    m.add_class::<ImpactResult>()?;
    Ok(())
}
