//! Axisymmetric indenters (docs/theory.md §11, VALIDATION.md §14): the elastic closed forms of
//! every shape (power laws and cones by the Beta function, the flat punch as a harmonic
//! oscillator, Segedin's exact sphere by quadrature written here), the viscoelastic flat punch
//! as a linear ODE solved by the matrix exponential, the agreement of `reference` and `mdr` for
//! every shape on a standard solid, a three-term material and a real polymer spectrum, and the
//! limit exact sphere -> paraboloid as `a/R -> 0`.

use crate::common;

use common::{abs_rel_err, opts};
use mdr_impact::model::geometry::{power_law_stretch, Shape};
use mdr_impact::model::material::ShearProny;
use mdr_impact::report::validate::shapes::{
    elastic_truth, flat_punch_ode, max_difference, shaped_impact, shapes, sneddon_constant,
    sphere_limit, MASS,
};
use mdr_impact::{solve, BulkInput, Impact, Material, Outcome, SolverKind};

fn elastic() -> Material {
    mdr_impact::report::validate::shapes::elastic().unwrap()
}

fn impact(shape: Shape, v0: f64, material: Material) -> Impact {
    shaped_impact(shape, v0, material).unwrap()
}

fn run(imp: &Impact, solver: SolverKind, rtol: f64) -> Outcome {
    solve(imp, &opts(solver, rtol)).unwrap()
}

fn check_elastic(name: &str, o: &Outcome, truth: (f64, f64, f64), tol: f64) {
    let (d, t, f) = truth;
    for (what, got, want) in [
        ("max_indentation", o.max_indentation, d),
        ("contact_time", o.contact_time, t),
        ("max_force", o.max_force, f),
        ("cor", o.cor, 1.0),
    ] {
        assert!(
            abs_rel_err(got, want) < tol,
            "{name} {what} ({}): {got} vs {want}",
            o.solver
        );
    }
}

#[test]
fn power_laws_and_cones_meet_sneddon_and_the_beta_function() {
    // the report's constant against the MDR stretch k_n of the solvers' geometry (Sneddon's
    // cone: F = (2/pi) E* tan(theta) d^2)
    let (g, theta) = (
        mdr_impact::report::validate::shapes::G,
        70.3f64.to_radians(),
    );
    let sneddon = 2.0 / std::f64::consts::PI * 4.0 * g * theta.tan();
    assert!(abs_rel_err(sneddon_constant(g, 1.0, 1.0 / theta.tan()), sneddon) < 1e-14);
    for n in [1.0, 1.5, 2.0, 3.0] {
        let via_stretch = 8.0 * g * n / (n + 1.0) * (power_law_stretch(n) * 7.0).powf(-1.0 / n);
        assert!(abs_rel_err(sneddon_constant(g, n, 7.0), via_stretch) < 1e-13);
    }
    let v0 = 0.8;
    for (name, shape) in shapes() {
        if !matches!(shape, Shape::Cone { .. } | Shape::PowerLaw { .. }) {
            continue;
        }
        let truth = elastic_truth(shape, v0).unwrap();
        let imp = impact(shape, v0, elastic());
        check_elastic(name, &run(&imp, SolverKind::Reference, 1e-10), truth, 1e-8);
        check_elastic(name, &run(&imp, SolverKind::Auto, 1e-8), truth, 1e-6);
        check_elastic(name, &run(&imp, SolverKind::Mdr, 1e-4), truth, 2e-4);
    }
}

#[test]
fn flat_punch_is_a_harmonic_oscillator() {
    // F = 8 G a0 d = 2 E* a0 d: t_c = pi sqrt(m/k), d_max = v0 sqrt(m/k)
    let (a0, v0) = (1.0e-3, 1.3);
    let truth = elastic_truth(Shape::Flat { radius: a0 }, v0).unwrap();
    let imp = impact(Shape::Flat { radius: a0 }, v0, elastic());
    for (solver, rtol, tol) in [
        (SolverKind::Reference, 1e-10, 1e-8),
        (SolverKind::Auto, 1e-8, 1e-6),
        (SolverKind::Mdr, 1e-4, 2e-4),
    ] {
        let o = run(&imp, solver, rtol);
        check_elastic("flat", &o, truth, tol);
        assert_eq!(o.max_contact_radius, a0, "{solver:?}");
    }
}

#[test]
fn exact_sphere_meets_segedin() {
    // a/R about 0.37, 0.7 and 0.85 (the outside checks go to 0.7)
    for v0 in [1.0, 6.0, 12.0] {
        let shape = Shape::sphere(5.0e-3);
        let truth = elastic_truth(shape, v0).unwrap();
        let imp = impact(shape, v0, elastic());
        check_elastic(
            "sphere",
            &run(&imp, SolverKind::Reference, 1e-10),
            truth,
            1e-8,
        );
        check_elastic("sphere", &run(&imp, SolverKind::Auto, 1e-8), truth, 1e-6);
        check_elastic("sphere", &run(&imp, SolverKind::Mdr, 1e-4), truth, 2e-4);
    }
    // the 30-digit value quoted in report::validate::shapes::segedin_impact
    let (_, t_c, _) = elastic_truth(Shape::sphere(5.0e-3), 12.0).unwrap();
    assert!(
        abs_rel_err(t_c, 1.331_425_935_729_616_2e-3) < 5e-13,
        "{t_c}"
    );
}

#[test]
fn exact_sphere_approaches_the_paraboloid_as_the_square_of_a_over_r() {
    // the maximum force of the exact sphere falls below Hertz's by c (a/R)^2, c settling
    let rows = sphere_limit().unwrap();
    let c: Vec<f64> = rows.iter().map(|r| r.2).collect();
    assert!(abs_rel_err(c[0], c[1]) < 0.05, "diff / (a/R)^2 = {c:?}");
    assert!(rows[0].0 < 0.15 && rows[3].0 > 0.5, "{rows:?}");
    assert!(c.iter().all(|c| *c > 0.05 && *c < 1.0), "{c:?}");
}

#[test]
fn viscoelastic_flat_punch_meets_the_matrix_exponential() {
    let (a0, v0) = (1.0e-3, 0.99);
    let mat = Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.49).unwrap();
    let imp = impact(Shape::Flat { radius: a0 }, v0, mat);
    let (cor, t_c, d_max) = flat_punch_ode(imp.equivalent_relaxation(), a0, MASS, v0);
    for (solver, rtol, tol) in [
        (SolverKind::Reference, 1e-10, 1e-8),
        (SolverKind::Auto, 1e-8, 1e-6),
        (SolverKind::Mdr, 1e-4, 2e-4),
    ] {
        let o = run(&imp, solver, rtol);
        assert!(
            abs_rel_err(o.cor, cor) < tol,
            "{solver:?} cor {} vs {cor}",
            o.cor
        );
        assert!(abs_rel_err(o.contact_time, t_c) < tol, "{solver:?} t_c");
        assert!(
            abs_rel_err(o.max_indentation, d_max) < tol,
            "{solver:?} d_max"
        );
    }
}

/// The shapes' viscoelastic impacts by `reference` (rtol 1e-10) and `mdr` (rtol 1e-4): the four
/// reported values within 2e-4; and `auto` at 1e-8 within 1e-6 of `reference`.
fn solvers_agree(material: Material, v0: f64) {
    for (name, shape) in shapes() {
        let imp = impact(shape, v0, material.clone());
        let r = run(&imp, SolverKind::Reference, 1e-10);
        let checks = [
            (SolverKind::Mdr, 1e-4, 2e-4),
            (SolverKind::Auto, 1e-8, 1e-6),
        ];
        for (solver, rtol, tol) in checks {
            let o = run(&imp, solver, rtol);
            let diff = max_difference(&o, &r);
            assert!(
                diff < tol,
                "{name}: {solver:?} differs by {diff:.2e} from reference"
            );
        }
    }
}

#[test]
fn solvers_agree_on_every_shape_for_the_standard_solid() {
    solvers_agree(
        Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.3).unwrap(),
        0.99,
    );
}

#[test]
fn solvers_agree_on_every_shape_for_a_three_term_material() {
    let shear = ShearProny::new(1.0e6, &[(4.0e6, 1e-5), (3.0e6, 2e-4), (2.0e6, 3e-3)]).unwrap();
    let m = Material::general(shear, BulkInput::Elastic(2.0e7)).unwrap();
    solvers_agree(m, 1.5);
}

#[test]
fn solvers_agree_on_every_shape_for_a_real_polymer() {
    let scene =
        mdr_impact::io::scene::Scene::load(std::path::Path::new("scenes/polyisobutylene.toml"))
            .unwrap();
    let m = scene.impact.half_space().unwrap().clone();
    solvers_agree(m, 1.0);
}

#[test]
fn validity_warnings_follow_the_shape() {
    use mdr_impact::model::validity::Validity;
    let warnings = |shape: Shape, v0: f64| {
        let imp = impact(shape, v0, elastic());
        let o = run(&imp, SolverKind::Auto, 1e-6);
        (o.max_contact_radius, Validity::of(&imp, &o).warnings)
    };
    let r = 5.0e-3;
    // a/R about 0.5: the paraboloid is warned about, the exact sphere is not
    let (a, w) = warnings(Shape::Paraboloid { radius: r }, 3.0);
    assert!(a / r > 0.4 && a / r < 0.8, "{a}");
    assert!(w.iter().any(|m| m.contains("paraboloid of Hertz")), "{w:?}");
    let (_, w) = warnings(Shape::sphere(r), 3.0);
    assert!(w.is_empty(), "{w:?}");
    // a/R = 0.85: the exact sphere warns that the contact is no longer small
    let (a, w) = warnings(Shape::sphere(r), 12.0);
    assert!(a / r > 0.8, "{a}");
    assert!(w.iter().any(|m| m.contains("exceeds 0.8")), "{w:?}");
    // a sharp cone warns about its slope, the Berkovich-equivalent one does not
    let (_, w) = warnings(
        Shape::Cone {
            half_angle_deg: 45.0,
        },
        1.0,
    );
    assert!(w.iter().any(|m| m.contains("slope")), "{w:?}");
    let (_, w) = warnings(
        Shape::Cone {
            half_angle_deg: 70.3,
        },
        1.0,
    );
    assert!(w.is_empty(), "{w:?}");
}

#[test]
fn scene_keys_name_every_shape_and_refuse_what_does_not_apply() {
    use mdr_impact::io::scene::Scene;
    let material = "[impact]\nvelocity = 1.0\n[material]\ng_inf = 1e6\ng_1 = 1e7\neta = 500.0\n\
                    poisson = 0.49\n";
    let parse = |head: &str| Scene::parse(&format!("{head}\n{material}"));
    let shape = |head: &str| *parse(head).unwrap().impact.shape();
    assert_eq!(
        shape("[indenter]\nmass = 1e-3\nshape = \"cone\"\nhalf_angle_deg = 70.3"),
        Shape::Cone {
            half_angle_deg: 70.3
        }
    );
    assert_eq!(
        shape("[indenter]\nmass = 1e-3\nshape = \"power-law\"\nexponent = 3.0\ncoefficient = 2e4"),
        Shape::PowerLaw {
            exponent: 3.0,
            coefficient: 2e4
        }
    );
    assert_eq!(
        shape("[indenter]\nmass = 1e-3\nshape = \"flat\"\nradius = 1e-3"),
        Shape::Flat { radius: 1e-3 }
    );
    assert_eq!(
        shape("[indenter]\nmass = 1e-3\nshape = \"sphere\"\nradius = 5e-3"),
        Shape::sphere(5e-3)
    );
    assert_eq!(
        shape("[sphere]\nmass = 1e-3\nradius = 5e-3\nprofile = \"sphere\""),
        Shape::sphere(5e-3)
    );
    assert_eq!(
        shape("[sphere]\nmass = 1e-3\nradius = 5e-3"),
        Shape::Paraboloid { radius: 5e-3 }
    );
    for (head, says) in [
        (
            "[indenter]\nmass = 1e-3\nshape = \"cone\"\nradius = 1e-3",
            "needs half_angle_deg",
        ),
        (
            "[indenter]\nmass = 1e-3\nshape = \"cone\"\nhalf_angle_deg = 70.0\nradius = 1e-3",
            "does not apply",
        ),
        (
            "[indenter]\nmass = 1e-3\nshape = \"cone\"\nhalf_angle_deg = 95.0",
            "half_angle_deg",
        ),
        (
            "[indenter]\nmass = 1e-3\nshape = \"pyramid\"",
            "expected one of",
        ),
        (
            "[sphere]\nmass = 1e-3\nradius = 5e-3\nprofile = \"cap\"",
            "profile = 'cap'",
        ),
        (
            "[indenter]\nmass = 1e-3\nshape = \"power-law\"\nexponent = 50.0\ncoefficient = 1.0",
            "exponent",
        ),
    ] {
        let e = parse(head).unwrap_err().to_string();
        assert!(e.contains(says), "{head}: {e}");
    }
}

#[test]
fn every_shape_scene_round_trips_through_to_toml() {
    use mdr_impact::io::scene::Scene;
    for file in [
        "scenes/cone_indenter.toml",
        "scenes/power_law_indenter.toml",
        "scenes/flat_punch.toml",
        "scenes/exact_sphere.toml",
        "scenes/two_exact_spheres.toml",
    ] {
        let scene = Scene::load(std::path::Path::new(file)).unwrap();
        assert_ne!(
            *scene.impact.shape(),
            Shape::Paraboloid {
                radius: scene.impact.sphere().radius()
            },
            "{file}"
        );
        assert_eq!(Scene::parse(&scene.to_toml()).unwrap(), scene, "{file}");
    }
}

/// The prescribed history of the `indent` checks: a triangle at 1 mm/s up to 1 ms.
const INDENT: [&str; 7] = [
    "indent",
    "--history",
    "triangle",
    "--rate",
    "1e-3",
    "--peak-time",
    "1e-3",
];

#[test]
fn indent_takes_every_shape_and_a_scene_material() {
    // theory (Lee-Radok/Ting by quadrature) and the displacement-driven MDR agree on the force
    // curve of each shape; --scene replaces the standard-solid flags
    let dir = std::env::temp_dir();
    let here = std::env::current_dir().unwrap();
    let pib = here.join("scenes/polyisobutylene.toml");
    let standard = [
        "--g-inf", "1e6", "--g1", "1e7", "--eta", "500", "--nu", "0.5",
    ];
    let scene = ["--scene", pib.to_str().unwrap()];
    for (shape, material) in [
        (
            vec!["--shape", "cone", "--half-angle", "70.3"],
            &standard[..],
        ),
        (vec!["--shape", "flat", "--radius", "1e-4"], &standard[..]),
        (vec!["--shape", "sphere", "--radius", "2e-6"], &standard[..]),
        (
            vec![
                "--shape",
                "power-law",
                "--exponent",
                "3",
                "--coefficient",
                "1e9",
            ],
            &scene[..],
        ),
    ] {
        let curve = |solver: &str| {
            let mut args = INDENT.to_vec();
            args.extend(["--solver", solver]);
            args.extend(&shape);
            args.extend(material);
            let o = common::run(&args, &dir);
            assert!(o.status.success(), "{args:?}: {}", common::stderr(&o));
            let text = String::from_utf8(o.stdout).unwrap();
            assert_eq!(text.lines().next(), Some("t_s,d_m,a_m,force_N"));
            text.lines()
                .skip(1)
                .map(|l| {
                    let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
                    v[3]
                })
                .collect::<Vec<f64>>()
        };
        let (theory, mdr) = (curve("theory"), curve("mdr"));
        let peak = theory.iter().cloned().fold(0.0, f64::max);
        assert!(peak > 0.0, "{shape:?}");
        let worst = theory
            .iter()
            .zip(&mdr)
            .map(|(a, b)| (a - b).abs() / peak)
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-3,
            "{shape:?}: theory and mdr differ by {worst:.2e} of the peak"
        );
    }
    // a flag that does not apply, and the missing material
    let run_with = |extra: &[&str]| common::run(&[&INDENT[..], extra].concat(), &dir);
    let o = run_with(&[&["--shape", "cone", "--radius", "1e-3"][..], &standard[..]].concat());
    assert!(!o.status.success());
    assert!(
        common::stderr(&o).contains("needs --half-angle"),
        "{}",
        common::stderr(&o)
    );
    let o = run_with(&["--radius", "1e-3"]);
    assert!(
        common::stderr(&o).contains("missing --g-inf"),
        "{}",
        common::stderr(&o)
    );
}
