//! Warnings where a scene is almost certainly a unit mistake: the answer is still given, the
//! warning says what looks wrong and what to check.

use crate::common;

use common::{run, stderr};
use mdr_impact::io::scene::Scene;
use mdr_impact::model::plausibility::{self, sphere_density, DENSITY_RANGE, MODULUS_RANGE};

/// The default scene, with `edit` applied to its text.
fn default_with(edit: &[(&str, &str)]) -> Scene {
    let mut text = mdr_impact::io::scene::DEFAULT_SCENE.to_string();
    for (from, to) in edit {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    Scene::parse(&text).unwrap()
}

#[test]
fn the_shipped_scenes_are_plausible() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "toml") {
            let s = Scene::load(&p).unwrap();
            assert_eq!(
                plausibility::warnings(&s.impact),
                Vec::<String>::new(),
                "{p:?}"
            );
        }
    }
    // the default ball is steel
    let s = Scene::default_scene().impact.sphere();
    let rho = sphere_density(s.mass(), s.radius());
    assert!((rho - 7850.0).abs() < 10.0, "{rho}");
}

/// A Poisson ratio a hair below 0.5 gives a huge bulk modulus on purpose (K = 5e15 Pa at
/// nu = 0.4999999999): no unit warning, since the bulk carries the shear modulus's units; a
/// bulk modulus written in MPa still warns.
#[test]
fn a_bulk_from_a_poisson_ratio_near_one_half_is_not_a_unit_mistake() {
    let s = default_with(&[("poisson = 0.49", "poisson = 0.4999999999")]);
    assert_eq!(plausibility::warnings(&s.impact), Vec::<String>::new());
    let k = default_with(&[("poisson = 0.49", "k_0 = 5.0e13")]);
    let w = plausibility::warnings(&k.impact);
    assert!(w.iter().any(|w| w.contains("bulk modulus")), "{w:?}");
}

/// The scene written in mm, g and MPa: a CoR of 0.99, and warnings on the density and
/// every modulus, in the text and in JSON `warnings`.
#[test]
fn a_scene_in_mm_g_and_mpa_is_warned_about() {
    let s = default_with(&[
        ("mass = 4.11e-3", "mass = 4.11"),
        ("radius = 5.0e-3", "radius = 5.0"),
        ("g_inf = 1.0e6", "g_inf = 1.0"),
        ("g_1 = 1.0e7", "g_1 = 10.0"),
    ]);
    let w = plausibility::warnings(&s.impact);
    assert!(w[0].starts_with("the sphere: mass 4.1100e0 kg and radius 5.0000e0 m imply a density"));
    assert!(w[0].contains("check the units (kg and m, not g and mm)"));
    assert_eq!(
        w.iter().filter(|x| x.contains("shear modulus")).count(),
        2,
        "{w:?}"
    );
    // the same in the command's output
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("s.toml"),
        mdr_impact::io::scene::DEFAULT_SCENE
            .replace("mass = 4.11e-3", "mass = 4.11")
            .replace("radius = 5.0e-3", "radius = 5.0"),
    )
    .unwrap();
    let o = run(&["run", "s.toml", "--json"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let first = v["warnings"][0].as_str().unwrap();
    assert!(
        first.contains("imply a density of 7.850e-3 kg/m^3"),
        "{first}"
    );
    let o = run(&["run", "s.toml"], dir.path());
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains("warning                     the sphere: mass"),
        "{out}"
    );
}

/// Just inside the ranges: no warning; just outside: one.
#[test]
fn density_and_modulus_ranges() {
    let r: f64 = 5.0e-3;
    let volume = 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
    for (rho, warned) in [
        (DENSITY_RANGE.0 * 1.01, false),
        (DENSITY_RANGE.1 * 0.99, false),
        (DENSITY_RANGE.0 * 0.99, true),
        (DENSITY_RANGE.1 * 1.01, true),
    ] {
        let mass = format!("mass = {:e}", rho * volume);
        let s = default_with(&[("mass = 4.11e-3", &mass)]);
        assert_eq!(
            !plausibility::warnings(&s.impact).is_empty(),
            warned,
            "{rho}"
        );
    }
    for (g_inf, warned) in [
        (MODULUS_RANGE.0 * 1.01, false),
        (MODULUS_RANGE.0 * 0.99, true),
    ] {
        let key = format!("g_inf = {g_inf:e}");
        let s = default_with(&[("g_inf = 1.0e6", &key)]);
        let w = plausibility::warnings(&s.impact);
        assert_eq!(
            w.iter().any(|x| x.contains("relaxed shear modulus")),
            warned,
            "{w:?}"
        );
    }
}

/// With a density, a velocity above the glassy shear wave speed is warned about.
#[test]
fn velocity_above_the_wave_speed() {
    // G(0) = 11 MPa, rho = 1100: c = 100 m/s
    for (v, warned) in [("99.0", false), ("101.0", true)] {
        let s = default_with(&[
            ("velocity = 0.99", &format!("velocity = {v}")),
            ("poisson = 0.49", "poisson = 0.49\ndensity = 1100.0"),
        ]);
        let w = plausibility::warnings(&s.impact);
        assert_eq!(
            w.iter().any(|x| x.contains("fastest shear wave speed")),
            warned,
            "{v}: {w:?}"
        );
    }
}

/// `cor --json` is in canonical units: no density or modulus warning there.
#[test]
fn canonical_units_are_not_checked() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        &[
            "cor", "--nu", "0.45", "--p2", "0.5", "--p3", "0.01", "--json",
        ],
        dir.path(),
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for w in v["warnings"].as_array().unwrap() {
        assert!(!w.as_str().unwrap().contains("check the units"), "{w}");
    }
}
