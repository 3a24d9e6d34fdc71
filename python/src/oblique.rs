//! Oblique impacts (docs/theory.md §14): one scene's tangential outputs and the curve over
//! incidence angles, from [`mdr_impact::solvers::oblique::solve_oblique`] and
//! [`mdr_impact::apps::curve_angle::run_angles`].

use super::*;
use mdr_impact::apps::curve_angle;
use mdr_impact::model::oblique::Oblique;
use mdr_impact::solvers::oblique::solve_oblique;

/// The scene's tangential inputs with the given ones in their place, validated.
fn inputs(
    scene: &RsScene,
    friction: Option<f64>,
    tangential_velocity: Option<f64>,
    spin: Option<f64>,
    inertia_factor: Option<f64>,
) -> PyResult<Oblique> {
    let o = scene.oblique;
    ok(Oblique::new(
        friction.unwrap_or(o.friction),
        tangential_velocity.unwrap_or(o.tangential_velocity),
        spin.unwrap_or(o.spin),
        inertia_factor.unwrap_or(o.inertia),
        o.inertia_b,
    ))
}

/// The scene's impact with its `[friction]`, tangential velocity, spin and inertia factors, GIL
/// released: a dict with `cor` and the tangential outputs of `run --json` (`tangential_cor`,
/// `tangential_cor_centre`, `spin_after` (rad/s), `rebound_angle_deg`,
/// `contact_patch_rebound_angle_deg`, `friction_dissipated_energy` (J), `tangential_impulse`
/// (N s), `tangential_error_estimate`), a ratio whose initial velocity is zero as NaN, and
/// `solver`. Each of `friction`, `tangential_velocity` (m/s), `spin` (rad/s) and
/// `inertia_factor` (body A's) given replaces the scene's.
#[pyfunction]
#[pyo3(signature = (scene, friction = None, tangential_velocity = None, spin = None, inertia_factor = None))]
pub(crate) fn oblique_values<'py>(
    py: Python<'py>,
    scene: PyRef<'py, Scene>,
    friction: Option<f64>,
    tangential_velocity: Option<f64>,
    spin: Option<f64>,
    inertia_factor: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let s = &scene.inner;
    let ob = inputs(s, friction, tangential_velocity, spin, inertia_factor)?;
    let mut opts = s.options;
    opts.history = false;
    let o = ok(py.detach(|| solve_oblique(&s.impact, &ob, &opts)))?;
    let d = PyDict::new(py);
    let t = o.tangential;
    d.set_item("cor", o.normal.cor)?;
    d.set_item("solver", o.normal.solver.name())?;
    d.set_item("tangential_cor", t.tangential_cor)?;
    d.set_item("tangential_cor_centre", t.tangential_cor_centre)?;
    d.set_item("spin_after", t.spin_after)?;
    d.set_item("rebound_angle_deg", t.rebound_angle_deg)?;
    d.set_item(
        "contact_patch_rebound_angle_deg",
        t.contact_patch_rebound_angle_deg,
    )?;
    d.set_item("friction_dissipated_energy", t.friction_dissipated_energy)?;
    d.set_item("tangential_impulse", t.impulse)?;
    d.set_item("tangential_error_estimate", o.tangential_error_estimate)?;
    Ok(d)
}

/// `mdr-impact curve --angle` on `scene` at the incidence angles `angles` (degrees from the
/// normal) and the speed `speed` (m/s), GIL released: a dict of arrays with the columns of
/// `curve.csv`. `friction`, `spin` and `inertia_factor` given replace the scene's.
#[pyfunction]
#[pyo3(signature = (scene, angles, speed, friction = None, spin = None, inertia_factor = None))]
pub(crate) fn angle_curve_values<'py>(
    py: Python<'py>,
    scene: PyRef<'py, Scene>,
    angles: Vec<f64>,
    speed: f64,
    friction: Option<f64>,
    spin: Option<f64>,
    inertia_factor: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let s = &scene.inner;
    let ob = inputs(s, friction, None, spin, inertia_factor)?;
    let rows =
        ok(py.detach(|| {
            curve_angle::run_angles(&s.impact, &ob, &s.options, &angles, speed, &|| {})
        }))?;
    let d = PyDict::new(py);
    let col = |f: fn(&curve_angle::AngleRow) -> f64| {
        PyArray1::from_vec(py, rows.iter().map(f).collect::<Vec<f64>>())
    };
    d.set_item("angle_deg", col(|r| r.angle_deg))?;
    d.set_item("cor", col(|r| r.cor))?;
    d.set_item("tangential_cor", col(|r| r.tangential_cor))?;
    d.set_item("tangential_cor_centre", col(|r| r.tangential_cor_centre))?;
    d.set_item("rebound_angle_deg", col(|r| r.rebound_angle_deg))?;
    d.set_item(
        "contact_patch_rebound_angle_deg",
        col(|r| r.contact_patch_rebound_angle_deg),
    )?;
    d.set_item("spin_after", col(|r| r.spin_after))?;
    Ok(d)
}
