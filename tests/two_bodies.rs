//! Two-body collisions (docs/theory.md §8) as an insta snapshot (`snapshots/two_bodies.snap`) and
//! tests. The checks, each a relative deviation (two significant digits) also asserted against
//! a stated bound:
//! - body B rigid (a rigid sphere of infinite mass and radius, i.e. a rigid wall) is today's
//!   one-sphere impact, bit for bit, for every solver;
//! - B almost rigid (every modulus x 1e8) approaches it at the rate of the compliance ratio;
//! - two identical bodies are the one-body impact of the effective mass `m/2`, radius `R/2` on
//!   half the moduli (`G_tot = G_eq / 2`);
//! - swapping A and B changes nothing;
//! - `mdr` on the two stacked element networks (never forming `G_tot`) against `fast` and
//!   `reference` on the combined `G_tot`.
use std::process::Command;

use mdr_impact::io::scene::Scene;
use mdr_impact::model::material::{BulkInput, BulkProny, Material, ShearProny};
use mdr_impact::report::validate::fmt_err;
use mdr_impact::{
    solve, Body, BodyMaterial, Error, Impact, Outcome, Side, SolverKind, Sphere, TwoBodies,
};

use crate::common;
use common::{opts, rel_err};

fn run(imp: &Impact, solver: SolverKind, rtol: f64) -> Outcome {
    solve(imp, &opts(solver, rtol)).unwrap()
}

fn elastomer() -> Material {
    Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.49).unwrap()
}

fn polymer() -> Material {
    let shear =
        ShearProny::new(5.0e6, &[(2.0e7, 1.0e-6), (3.0e7, 1.0e-5), (1.0e7, 1.0e-4)]).unwrap();
    let bulk = BulkProny::new(2.0e8, &[(1.0e8, 1.0e-5)]).unwrap();
    Material::general(shear, BulkInput::Prony(bulk)).unwrap()
}

fn body(side: Side, mass: f64, radius: f64, m: BodyMaterial) -> Body {
    Body::new(side, mass, radius, m).unwrap()
}

fn collision(a: Body, b: Body, v0: f64) -> Impact {
    Impact::with_bodies(TwoBodies::new(a, b).unwrap(), v0).unwrap()
}

fn wall(side: Side) -> Body {
    body(side, f64::INFINITY, f64::INFINITY, BodyMaterial::Rigid)
}

#[test]
fn two_body_checks() {
    let mut out = String::from("check | quantity | relative deviation | bound\n");
    let mut line = |what: &str, quantity: &str, dev: f64, bound: f64| {
        assert!(dev.abs() <= bound, "{what} {quantity}: {dev:e} > {bound:e}");
        let bound = if bound == 0.0 {
            "exact".to_string()
        } else {
            format!("{bound:.0e}")
        };
        out.push_str(&format!(
            "{what} | {quantity} | {} | {bound}\n",
            fmt_err(dev)
        ));
    };
    let (mass, radius, v0) = (4.11e-3, 5.0e-3, 0.99);
    let sphere = Sphere::new(mass, radius).unwrap();
    let solvers = [
        (SolverKind::Fast, 1e-10),
        (SolverKind::Reference, 1e-10),
        (SolverKind::Mdr, 1e-4),
    ];

    // B a rigid wall: the one-sphere impact, bit for bit
    for (name, one, a_mat) in [
        (
            "standard solid",
            Impact::new(sphere, v0, elastomer()).unwrap(),
            BodyMaterial::Viscoelastic(elastomer()),
        ),
        (
            "general",
            Impact::with_general(sphere, v0, polymer()).unwrap(),
            BodyMaterial::Viscoelastic(polymer()),
        ),
    ] {
        let two = collision(body(Side::A, mass, radius, a_mat), wall(Side::B), v0);
        assert_eq!(two.sphere(), one.sphere());
        assert_eq!(two.scales(), one.scales());
        for (solver, rtol) in solvers {
            let (o1, o2) = (run(&one, solver, rtol), run(&two, solver, rtol));
            assert_eq!(o1.cor, o2.cor, "{name} {}", solver.name());
            assert_eq!(o1.contact_time, o2.contact_time);
            assert_eq!(o1.max_force, o2.max_force);
            assert_eq!(o1.max_indentation, o2.max_indentation);
        }
        line(
            &format!("B rigid wall, A {name}"),
            "CoR, t_c, F_max, d_max (fast, reference, mdr)",
            0.0,
            0.0,
        );
    }

    // B almost rigid: a stiff copy of the polymer (every modulus x 1e8), mass and radius infinite
    let stiff = {
        let shear = ShearProny::new(
            5.0e14,
            &[(2.0e15, 1.0e-6), (3.0e15, 1.0e-5), (1.0e15, 1.0e-4)],
        )
        .unwrap();
        let bulk = BulkProny::new(2.0e16, &[(1.0e16, 1.0e-5)]).unwrap();
        Material::general(shear, BulkInput::Prony(bulk)).unwrap()
    };
    let one = Impact::new(sphere, v0, elastomer()).unwrap();
    let near = collision(
        body(
            Side::A,
            mass,
            radius,
            BodyMaterial::Viscoelastic(elastomer()),
        ),
        body(
            Side::B,
            f64::INFINITY,
            f64::INFINITY,
            BodyMaterial::Viscoelastic(stiff),
        ),
        v0,
    );
    for (solver, rtol) in [(SolverKind::Fast, 1e-10), (SolverKind::Reference, 1e-10)] {
        let (o1, o2) = (run(&one, solver, rtol), run(&near, solver, rtol));
        line(
            &format!("B x 1e8 stiffer ({})", solver.name()),
            "CoR",
            rel_err(o2.cor, o1.cor),
            1e-7,
        );
    }

    // identical bodies = one body of mass m/2, radius R/2 on half the moduli
    for (name, mat, half) in [
        (
            "standard solid",
            BodyMaterial::Viscoelastic(elastomer()),
            Impact::new(
                Sphere::new(mass / 2.0, radius / 2.0).unwrap(),
                v0,
                Material::with_poisson(0.5e6, 0.5e7, 250.0, 0.49).unwrap(),
            )
            .unwrap(),
        ),
        (
            "general",
            BodyMaterial::Viscoelastic(polymer()),
            Impact::with_general(Sphere::new(mass / 2.0, radius / 2.0).unwrap(), v0, {
                let shear =
                    ShearProny::new(2.5e6, &[(1.0e7, 1.0e-6), (1.5e7, 1.0e-5), (0.5e7, 1.0e-4)])
                        .unwrap();
                let bulk = BulkProny::new(1.0e8, &[(0.5e8, 1.0e-5)]).unwrap();
                Material::general(shear, BulkInput::Prony(bulk)).unwrap()
            })
            .unwrap(),
        ),
    ] {
        let two = collision(
            body(Side::A, mass, radius, mat.clone()),
            body(Side::B, mass, radius, mat),
            v0,
        );
        for (solver, rtol) in solvers {
            let (o1, o2) = (run(&half, solver, rtol), run(&two, solver, rtol));
            let bound = if solver == SolverKind::Mdr {
                1e-4
            } else {
                1e-9
            };
            line(
                &format!("identical bodies, {name} ({})", solver.name()),
                "CoR",
                rel_err(o2.cor, o1.cor),
                bound,
            );
            line(
                &format!("identical bodies, {name} ({})", solver.name()),
                "contact time",
                rel_err(o2.contact_time, o1.contact_time),
                bound,
            );
        }
    }

    // swap A and B: elastomer ball against a smaller polymer ball
    let a = body(
        Side::A,
        4.6e-3,
        1.0e-2,
        BodyMaterial::Viscoelastic(elastomer()),
    );
    let b = body(
        Side::B,
        6.3e-4,
        5.0e-3,
        BodyMaterial::Viscoelastic(polymer()),
    );
    let ab = collision(a.clone(), b.clone(), 2.0);
    let ba = collision(
        body(Side::A, b.mass(), b.radius(), b.material().clone()),
        body(Side::B, a.mass(), a.radius(), a.material().clone()),
        2.0,
    );
    let mut mixed = Vec::new();
    for (solver, rtol) in solvers {
        let (o1, o2) = (run(&ab, solver, rtol), run(&ba, solver, rtol));
        line(
            &format!("swap A and B ({})", solver.name()),
            "CoR",
            rel_err(o2.cor, o1.cor),
            1e-12,
        );
        mixed.push((solver, o1));
    }

    // stacked networks (mdr) against G_tot (fast, reference) on the mixed pair
    let cor = |k: SolverKind| mixed.iter().find(|(s, _)| *s == k).unwrap().1.cor;
    let reference = cor(SolverKind::Reference);
    line(
        "mixed pair: fast against reference",
        "CoR",
        rel_err(cor(SolverKind::Fast), reference),
        2e-10,
    );
    line(
        "mixed pair: mdr (stacked networks) against reference",
        "CoR",
        rel_err(cor(SolverKind::Mdr), reference),
        1e-4,
    );
    let tight = run(&ab, SolverKind::Mdr, 1e-6);
    line(
        "mixed pair: mdr rtol 1e-6 against reference",
        "CoR",
        rel_err(tight.cor, reference),
        1e-6,
    );

    insta::with_settings!({
        snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"),
        prepend_module_to_snapshot => false,
        omit_expression => true,
    }, {
        insta::assert_snapshot!("two_bodies", out);
    });
}

#[test]
fn rebound_velocities_conserve_momentum() {
    let a = body(
        Side::A,
        4.6e-3,
        1.0e-2,
        BodyMaterial::Viscoelastic(elastomer()),
    );
    let b = body(
        Side::B,
        6.3e-4,
        5.0e-3,
        BodyMaterial::Viscoelastic(polymer()),
    );
    let imp = collision(a, b, 2.0);
    let o = run(&imp, SolverKind::Fast, 1e-8);
    let two = imp.bodies().unwrap();
    let (va, vb) = two.rebound_velocities(2.0, o.cor);
    // momentum before: m_A v0; relative velocity after: e v0
    assert!((4.6e-3 * va + 6.3e-4 * vb - 4.6e-3 * 2.0).abs() < 1e-15);
    assert!((vb - va - o.cor * 2.0).abs() < 1e-14);
    // energy lost = (1 - e^2) m v0^2 / 2 with the effective mass
    let m = imp.sphere().mass();
    let lost = 0.5 * 4.6e-3 * 4.0 - 0.5 * (4.6e-3 * va * va + 6.3e-4 * vb * vb);
    assert!((lost - 0.5 * m * 4.0 * (1.0 - o.cor * o.cor)).abs() < 1e-12 * lost);
    assert!((o.dissipated_energy - lost).abs() < 1e-9 * lost);
}

#[test]
fn bad_bodies_are_refused() {
    let m = || BodyMaterial::Viscoelastic(elastomer());
    for (mass, radius) in [
        (0.0, 1.0),
        (-1.0, 1.0),
        (f64::NAN, 1.0),
        (1.0, 0.0),
        (1.0, f64::NAN),
    ] {
        assert!(matches!(
            Body::new(Side::B, mass, radius, m()),
            Err(Error::In { place, source }) if place == "body B"
                && matches!(*source, Error::OutOfRange { .. })
        ));
    }
    let sphere = |mat| body(Side::A, 1.0, 1.0, mat);
    assert!(TwoBodies::new(sphere(BodyMaterial::Rigid), wall(Side::B)).is_err());
    assert!(TwoBodies::new(
        body(Side::A, f64::INFINITY, 1.0, m()),
        body(Side::B, f64::INFINITY, 1.0, m())
    )
    .is_err());
    assert!(TwoBodies::new(
        body(Side::A, 1.0, f64::INFINITY, m()),
        body(Side::B, 1.0, f64::INFINITY, m())
    )
    .is_err());
}

const TWO: &str = r#"
[impact]
velocity = 2.0
[[body]]
mass = 4.6e-3
radius = 1.0e-2
[body.material]
g_inf = 1.0e6
g_1 = 1.0e7
eta = 500.0
poisson = 0.49
[[body]]
mass = inf
radius = inf
rigid = true
"#;

#[test]
fn scene_forms() {
    // a body on a rigid wall is the one-sphere scene
    let two = Scene::parse(TWO).unwrap();
    let one = Scene::parse(
        "[sphere]\nmass = 4.6e-3\nradius = 1.0e-2\n[impact]\nvelocity = 2.0\n[material]\n\
         g_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\npoisson = 0.49\n",
    )
    .unwrap();
    let o = |s: &Scene| solve(&s.impact, &s.options).unwrap();
    assert_eq!(o(&two).cor, o(&one).cor);
    // rigid = true inside [body.material] is the same body
    let inside = TWO.replace("rigid = true", "[body.material]\nrigid = true");
    assert_eq!(o(&Scene::parse(&inside).unwrap()).cor, o(&one).cor);
    // density instead of mass
    let dense = Scene::parse(&TWO.replace("mass = 4.6e-3", "density = 1100.0")).unwrap();
    let m = 4.0 / 3.0 * std::f64::consts::PI * 1e-6 * 1100.0;
    assert!((dense.impact.sphere().mass() - m).abs() < 1e-15 * m);
    // the shipped scene parses and its bodies are as stated
    let shipped = Scene::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/two_spheres.toml"
    )))
    .unwrap();
    let b = shipped.impact.bodies().unwrap();
    assert!((b.effective_radius() - 1.0e-2 / 3.0).abs() < 1e-17);
}

#[test]
fn bad_scenes_are_one_line_errors() {
    let cases: Vec<(String, &str)> = vec![
        (
            TWO.split("[[body]]\nmass = inf")
                .next()
                .unwrap()
                .to_string(),
            "exactly two",
        ),
        (TWO.replace("mass = 4.6e-3", "mass = 0.0"), "body A: mass"),
        (TWO.replace("mass = 4.6e-3", "mass = -1.0"), "body A: mass"),
        (
            TWO.replace("mass = 4.6e-3", "mass = 1.0\ndensity = 1.0"),
            "not both",
        ),
        (TWO.replace("mass = 4.6e-3\n", ""), "missing mass"),
        (
            TWO.replace("poisson = 0.49", "poisson = 0.49\nrigid = true"),
            "rigid",
        ),
        (
            format!("{TWO}[[body]]\nmass = 1.0\nradius = 1.0\nrigid = true\n"),
            "exactly two",
        ),
        (
            TWO.replace(
                "[[body]]\nmass = inf\nradius = inf\nrigid = true",
                "[[body]]\nmass = 1.0\nradius = 1.0\nrigid = true",
            )
            .replace(
                "g_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\npoisson = 0.49",
                "rigid = true",
            ),
            "both bodies are rigid",
        ),
        (
            format!("[sphere]\nmass = 1.0\nradius = 1.0\n{TWO}"),
            "cannot be mixed",
        ),
        (
            TWO.replace("radius = inf", "radius = inf\ncolour = 1"),
            "colour",
        ),
        (TWO.replace("g_1 = 1.0e7", "g_1 = -1.0e7"), "g_1"),
    ];
    for (text, want) in cases {
        let e = Scene::parse(&text).unwrap_err().to_string();
        assert!(e.contains(want), "{e:?} should mention {want:?}");
        assert!(!e.contains('\n'), "one line: {e:?}");
    }
}

#[test]
fn run_json_reports_both_bodies() {
    let out = Command::new(env!("CARGO_BIN_EXE_mdr-impact"))
        .args(["run", "--json"])
        .arg(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/scenes/two_spheres.toml"
        ))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "cor",
        "contact_time",
        "max_indentation",
        "max_force",
        "solver",
        "estimated_rel_error",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    let (va, vb) = (
        v["bodies"]["a"]["rebound_velocity"].as_f64().unwrap(),
        v["bodies"]["b"]["rebound_velocity"].as_f64().unwrap(),
    );
    let e = v["cor"].as_f64().unwrap();
    assert!((vb - va - 2.0 * e).abs() < 1e-12);
}

/// Every catalogue collision: `fast` (rtol 1e-6 and 1e-10) and `mdr` on the stacked networks
/// (rtol 1e-4) agree with `reference` (rtol 1e-10) within their tolerances.
#[test]
fn catalogue_collisions_agree() {
    for case in mdr_impact::report::catalogue::TWO_BODIES {
        let imp = case.impact().unwrap();
        let truth = run(&imp, SolverKind::Reference, 1e-10).cor;
        for (solver, rtol) in [
            (SolverKind::Fast, 1e-6),
            (SolverKind::Fast, 1e-10),
            (SolverKind::Mdr, 1e-4),
        ] {
            let e = run(&imp, solver, rtol).cor;
            let err = rel_err(e, truth).abs();
            assert!(
                err <= rtol + 1e-10,
                "{} {} rtol {rtol:e}: {err:e}",
                case.id,
                solver.name()
            );
        }
    }
}
