//! `fast` on every indenter shape (docs/theory.md §11) against `reference`, which shares no
//! code with it but the geometry's definition: on the elastic half-space (the power laws and
//! the flat punch in closed form or by modes; exact spheres are refused and left to
//! `reference`), a standard solid, a three-term material and the polyisobutylene spectrum of
//! `scenes/polyisobutylene.toml`, the last also on the exact sphere at contact radii up to
//! 0.73 R. The outside checks' tolerances: `fast` at rtol 1e-8 within 1e-6 of `reference` at
//! 1e-10 in `cor`, `contact_time`, `max_indentation` and `max_force`.

use crate::common;

use common::opts;
use mdr_impact::model::geometry::Shape;
use mdr_impact::model::material::ShearProny;
use mdr_impact::report::validate::shapes::{max_difference, shaped_impact, shapes};
use mdr_impact::{solve, BulkInput, Error, Material, Method, Outcome, SolverKind};

fn polyisobutylene() -> Material {
    let scene =
        mdr_impact::io::scene::Scene::load(std::path::Path::new("scenes/polyisobutylene.toml"))
            .unwrap();
    scene.impact.half_space().unwrap().clone()
}

fn run(shape: Shape, v0: f64, material: &Material, solver: SolverKind, rtol: f64) -> Outcome {
    let imp = shaped_impact(shape, v0, material.clone()).unwrap();
    solve(&imp, &opts(solver, rtol)).unwrap()
}

/// `fast` at 1e-8 within 1e-6 of `reference` at 1e-10, and at 1e-10 within 1e-8, on every shape.
fn fast_meets_reference(material: &Material, v0: f64) {
    for (name, shape) in shapes() {
        let r = run(shape, v0, material, SolverKind::Reference, 1e-10);
        for (rtol, tol) in [(1e-8, 1e-6), (1e-10, 1e-8)] {
            let o = run(shape, v0, material, SolverKind::Fast, rtol);
            assert_eq!(o.solver, Method::Fast);
            let diff = max_difference(&o, &r);
            assert!(
                diff < tol,
                "{name} at rtol {rtol:e}: {diff:.2e} from reference"
            );
        }
    }
}

#[test]
fn fast_meets_reference_on_every_shape_for_the_standard_solid() {
    let m = Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.3).unwrap();
    fast_meets_reference(&m, 0.99);
}

#[test]
fn fast_meets_reference_on_every_shape_for_a_three_term_material() {
    let shear = ShearProny::new(1.0e6, &[(4.0e6, 1e-5), (3.0e6, 2e-4), (2.0e6, 3e-3)]).unwrap();
    let m = Material::general(shear, BulkInput::Elastic(2.0e7)).unwrap();
    fast_meets_reference(&m, 1.5);
}

#[test]
fn fast_meets_reference_on_every_shape_for_a_real_polymer() {
    fast_meets_reference(&polyisobutylene(), 1.0);
}

#[test]
fn fast_meets_reference_on_the_exact_sphere_up_to_a_over_r_0_7() {
    let (pib, shape) = (polyisobutylene(), Shape::sphere(5.0e-3));
    let mut largest: f64 = 0.0;
    for v0 in [3.0, 10.0, 20.0] {
        let r = run(shape, v0, &pib, SolverKind::Reference, 1e-10);
        let o = run(shape, v0, &pib, SolverKind::Fast, 1e-8);
        let diff = max_difference(&o, &r);
        assert!(diff < 1e-6, "v0 {v0}: {diff:.2e} from reference");
        assert!((o.max_contact_radius / r.max_contact_radius - 1.0).abs() < 1e-6);
        largest = largest.max(r.max_contact_radius / 5.0e-3);
    }
    assert!(largest > 0.7, "largest a/R {largest}");
}

#[test]
fn fast_solves_elastic_power_laws_and_flat_punches_and_refuses_elastic_spheres() {
    let elastic = mdr_impact::report::validate::shapes::elastic().unwrap();
    for (name, shape) in shapes() {
        let imp = shaped_impact(shape, 0.8, elastic.clone()).unwrap();
        match solve(&imp, &opts(SolverKind::Fast, 1e-8)) {
            Ok(o) => {
                assert!(!matches!(shape, Shape::Spheres { .. }), "{name}");
                let r = run(shape, 0.8, &elastic, SolverKind::Reference, 1e-10);
                let diff = max_difference(&o, &r);
                assert!(diff < 1e-8, "{name}: {diff:.2e} from reference");
                assert_eq!(o.cor, 1.0, "{name}");
            }
            Err(e) => {
                assert!(matches!(shape, Shape::Spheres { .. }), "{name}: {e}");
                assert!(matches!(e, Error::NotSupported { .. }), "{name}: {e}");
                // auto hands it to reference
                let o = run(shape, 0.8, &elastic, SolverKind::Auto, 1e-8);
                assert_eq!(o.solver, Method::Reference);
            }
        }
    }
}

#[test]
fn fast_flat_punch_history_ends_where_the_force_returns_to_zero() {
    let m = Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.3).unwrap();
    let imp = shaped_impact(Shape::Flat { radius: 1.0e-3 }, 0.99, m).unwrap();
    let mut o = opts(SolverKind::Fast, 1e-8);
    o.history = true;
    let out = solve(&imp, &o).unwrap();
    let h = out.history.as_ref().unwrap();
    let n = h.t.len();
    assert!(n > 10);
    assert!((h.t[n - 1] - out.contact_time).abs() <= 1e-12 * out.contact_time);
    assert_eq!(h.force[n - 1], 0.0);
    // the force is positive before the end, and the contact radius is the punch's throughout
    assert!(h.force[1..n - 1].iter().all(|f| *f > 0.0));
    assert!(h.a.iter().all(|a| (*a - 1.0e-3).abs() <= 1e-15));
    assert!(out.max_force >= h.force.iter().cloned().fold(0.0, f64::max));
}
