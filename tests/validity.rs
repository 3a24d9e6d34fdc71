//! Answers say when the model does not apply: `run --json` carries `validity` and `warnings`,
//! `run` prints them, `curve` adds the ratio columns and warns, and a density enables the
//! quasi-static check (docs/theory.md §12, `model::validity`).

use crate::common;

use common::run;

/// The default scene at `velocity` (m/s), without outputs, with `extra` lines in `[material]`.
fn scene(velocity: f64, extra: &str) -> String {
    mdr_impact::io::scene::DEFAULT_SCENE
        .replace("velocity = 0.99", &format!("velocity = {velocity}"))
        .replace("poisson = 0.49", &format!("poisson = 0.49\n{extra}"))
        .lines()
        .filter(|l| !l.starts_with("history") && !l.starts_with("plot"))
        .collect::<Vec<_>>()
        .join("\n")
}

fn run_json(text: &str) -> serde_json::Value {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let o = run(&["run", "s.toml", "--json"], dir.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn default_scene_at_one_metre_per_second_is_inside_and_at_100_outside() {
    let inside = run_json(&scene(1.0, ""));
    let v = &inside["validity"];
    let ratio = v["contact_radius_ratio"].as_f64().unwrap();
    assert!((0.31..0.32).contains(&ratio), "{ratio}");
    let expected = inside["max_contact_radius"].as_f64().unwrap() / 5.0e-3;
    assert!((ratio / expected - 1.0).abs() < 1e-12);
    assert!(v["indentation_ratio"].as_f64().unwrap() > 0.0);
    assert!(v["wave_transit_ratio"].is_null(), "no density given");
    assert_eq!(inside["warnings"].as_array().unwrap().len(), 0, "{inside}");

    let outside = run_json(&scene(100.0, ""));
    let w = outside["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1, "{outside}");
    assert!(w[0].as_str().unwrap().contains("a_max/R = 1.7"), "{w:?}");
    assert!(outside["validity"]["sphere_force_excess"].is_null());
}

#[test]
fn a_density_enables_the_quasi_static_check() {
    // an elastomer of 1100 kg/m^3: shear waves at sqrt(1 MPa / 1100) = 30 m/s take 5.6 % of the
    // contact time to cross the 3.2 mm contact at 1 m/s
    let j = run_json(&scene(1.0, "density = 1100.0"));
    let w = j["validity"]["wave_transit_ratio"].as_f64().unwrap();
    assert!((0.05..0.06).contains(&w), "{w}");
    let warnings = j["warnings"].as_array().unwrap();
    assert_eq!(warnings.len(), 1);
    assert!(warnings[0].as_str().unwrap().contains("shear waves"));
    // a tenth of the velocity: the ratio falls as v0^(3/5)
    let slow = run_json(&scene(0.1, "density = 1100.0"));
    let w_slow = slow["validity"]["wave_transit_ratio"].as_f64().unwrap();
    assert!((w_slow / w - 0.1f64.powf(0.6)).abs() < 0.02, "{w_slow} {w}");
    // a bad density is refused naming the key
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), scene(1.0, "density = -1.0")).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("density"));
}

#[test]
fn run_prints_and_curve_tabulates_the_validity() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), scene(100.0, "")).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("validity                    a_max/R = 1.7"),
        "{text}"
    );
    assert!(
        text.contains("\nwarning                     contact radius a_max/R"),
        "{text}"
    );
    let o = run(
        &["curve", "s.toml", "--v0", "0.1:100:4", "--log"],
        dir.path(),
    );
    assert!(o.status.success());
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("velocities lie outside the model's validity"),
        "{text}"
    );
    let csv = std::fs::read_to_string(dir.path().join("out/curve.csv")).unwrap();
    let mut lines = csv.lines();
    assert!(lines
        .next()
        .unwrap()
        .ends_with(",contact_radius_ratio,indentation_ratio"));
    let ratios: Vec<f64> = lines
        .map(|l| l.split(',').nth(5).unwrap().parse().unwrap())
        .collect();
    assert!(ratios.windows(2).all(|w| w[0] < w[1]), "{ratios:?}");
    assert!(ratios[0] < 0.35 && ratios[3] > 0.35);
    let svg = std::fs::read_to_string(dir.path().join("out/curve.svg")).unwrap();
    assert!(
        svg.contains("outside the model&apos;s validity")
            || svg.contains("outside the model's validity")
    );
}

/// With a density `curve` tabulates the wave transit ratio (the `run --json` value of every
/// velocity) and its warning names the measure that fails: slow waves at contacts far below the
/// paraboloid's limit, not `a_max/R`.
#[test]
fn curve_with_a_density_names_the_wave_transit() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), scene(1.0, "density = 1100.0")).unwrap();
    let o = run(
        &["curve", "s.toml", "--v0", "0.01:1:5", "--log"],
        dir.path(),
    );
    assert!(o.status.success());
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("shear waves take up to"), "{text}");
    assert!(!text.contains("a_max/R up to"), "{text}");
    let csv = std::fs::read_to_string(dir.path().join("out/curve.csv")).unwrap();
    let mut lines = csv.lines();
    assert!(lines
        .next()
        .unwrap()
        .ends_with(",contact_radius_ratio,indentation_ratio,wave_transit_ratio"));
    for l in lines {
        let f: Vec<&str> = l.split(',').collect();
        let v = run_json(&scene(f[0].parse().unwrap(), "density = 1100.0"));
        let w: f64 = f[7].parse().unwrap();
        assert_eq!(
            w,
            v["validity"]["wave_transit_ratio"].as_f64().unwrap(),
            "{l}"
        );
    }
}
