//! Temperature in scenes: `[material.shift]` (WLF or Arrhenius) and `[impact] temperature`
//! multiply every relaxation time by `a_T` (thermorheological simplicity); the shift in a scene
//! equals the hand-shifted Prony series to the last bit.

use crate::common;

use common::run;
use mdr_impact::io::scene::Scene;
use mdr_impact::model::material::shift::ShiftLaw;
use mdr_impact::solve;

const TAUS: [f64; 2] = [1.0e-5, 1.0e-3];

fn scene(taus: [f64; 2], temperature: Option<f64>, shift: bool) -> String {
    let mut s = format!(
        "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n\n[impact]\nvelocity = 1.0\n{}\n\
         [material.shear]\ng_inf = 1.0e6\nterms = [[5.0e6, {:?}], [2.0e6, {:?}]]\n\n\
         [material.bulk]\nk_inf = 1.0e9\nterms = [[5.0e8, {:?}]]\n",
        temperature.map_or(String::new(), |t| format!("temperature = {t:?}\n")),
        taus[0],
        taus[1],
        3.0 * taus[0],
    );
    if shift {
        s.push_str("\n[material.shift]\nwlf = { c1 = 8.86, c2 = 101.6, t_ref = 25.0 }\n");
    }
    s
}

fn cor(text: &str) -> f64 {
    let sc = Scene::parse(text).unwrap();
    solve(&sc.impact, &sc.options).unwrap().cor
}

#[test]
fn the_shift_in_a_scene_equals_the_hand_shifted_series_to_the_bit() {
    let law = ShiftLaw::wlf(8.86, 101.6, 25.0).unwrap();
    for t in [-20.0, 0.0, 25.0, 60.0] {
        let a = 10f64.powf(law.log10_a(t).unwrap());
        let shifted = cor(&scene(TAUS, Some(t), true));
        let hand = cor(&scene([TAUS[0] * a, TAUS[1] * a], None, false));
        assert_eq!(
            shifted.to_bits(),
            hand.to_bits(),
            "T = {t}: {shifted} vs {hand}"
        );
        let sc = Scene::parse(&scene(TAUS, Some(t), true)).unwrap();
        assert_eq!(sc.shifts.len(), 1);
        assert_eq!(sc.shifts[0].1, law.log10_a(t).unwrap());
    }
    // colder is slower: the material is glassier at 1 m/s, so the CoR rises
    assert!(cor(&scene(TAUS, Some(-20.0), true)) > cor(&scene(TAUS, Some(25.0), true)));
    // without a temperature the law's t_ref: a_T = 1, the unshifted material
    assert_eq!(
        cor(&scene(TAUS, None, true)).to_bits(),
        cor(&scene(TAUS, None, false)).to_bits()
    );
}

#[test]
fn bad_temperatures_are_refused_naming_the_key() {
    // no law to shift with
    let e = Scene::parse(&scene(TAUS, Some(0.0), false))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("[impact] temperature") && e.contains("[material.shift]"),
        "{e}"
    );
    // at or below t_ref - c2, the WLF singularity
    let e = Scene::parse(&scene(TAUS, Some(25.0 - 101.6), true))
        .unwrap_err()
        .to_string();
    assert!(e.contains("temperature"), "{e}");
    // an unknown law
    let bad = scene(TAUS, Some(0.0), false) + "\n[material.shift]\nvft = { a = 1.0 }\n";
    assert!(Scene::parse(&bad).is_err());
    // both laws, or neither: the keys named, not serde's count of enum elements
    let arr = "arrhenius = { activation_energy = 1.0e5, t_ref = 25.0 }\n";
    let both = scene(TAUS, Some(0.0), true) + arr;
    let e = Scene::parse(&both).unwrap_err().to_string();
    assert!(
        e.contains("shift table: cannot read 'wlf and arrhenius'"),
        "{e}"
    );
    let neither = scene(TAUS, Some(0.0), false) + "\n[material.shift]\n";
    let e = Scene::parse(&neither).unwrap_err().to_string();
    assert!(e.contains("neither wlf nor arrhenius"), "{e}");
    // hot enough that a_T leaves a double's range: the temperature refused with its bound
    let hot = scene(TAUS, Some(26.0), false)
        + "\n[material.shift]\narrhenius = { activation_energy = 1.0e9, t_ref = 25.0 }\n";
    let e = Scene::parse(&hot).unwrap_err().to_string();
    assert!(
        e.contains("[impact] temperature = 26 °C") && e.contains("allowed: temperature < 25.5"),
        "{e}"
    );
}

#[test]
fn run_prints_the_shift_factor() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), scene(TAUS, Some(0.0), true)).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert!(o.status.success(), "{}", common::stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.starts_with(
            "time-temperature shift      a_T = 7.791928e2 (log10 a_T = 2.8916) at 0 °C"
        ),
        "{text}"
    );
}

/// `prony`'s material.toml with a sphere and a temperature is a scene.
#[test]
fn the_material_of_prony_runs_at_a_temperature() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = tempfile::tempdir().unwrap();
    let data = root.join("scenes/dma_example.csv");
    let o = run(
        &["prony", data.to_str().unwrap(), "--out", "dma"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", common::stderr(&o));
    let material = std::fs::read_to_string(dir.path().join("dma/material.toml")).unwrap();
    assert!(material.contains("[material.shift]"), "{material}");
    // the isotherms' range (scenes/dma_example.csv: -20 to 80 °C)
    assert!(
        material.contains("\ncalibrated = [-20.0, 80.0]"),
        "{material}"
    );
    let mut cors = Vec::new();
    for t in [0.0, 25.0, 60.0] {
        let text = format!(
            "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n\n[impact]\nvelocity = 1.0\n\
             temperature = {t:?}\n\n{material}"
        );
        std::fs::write(dir.path().join("s.toml"), text).unwrap();
        let o = run(&["run", "s.toml", "--json"], dir.path());
        assert!(o.status.success(), "{}", common::stderr(&o));
        let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        cors.push(j["cor"].as_f64().unwrap());
    }
    assert!(cors.iter().all(|c| *c > 0.0 && *c < 1.0), "{cors:?}");
    assert!(cors[0] != cors[1] && cors[1] != cors[2], "{cors:?}");
}

/// `curve --temperature`: one row per temperature, each the CoR `run` gives at that
/// temperature, the header of the issue, a plot; with `--v0` a usage error (exit 2); on a scene
/// without a shift law a one-line error and no files.
#[test]
fn curve_over_temperature() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), scene(TAUS, Some(0.0), true)).unwrap();
    let o = run(
        &["curve", "s.toml", "--temperature", "-10:50:4"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", common::stderr(&o));
    let csv = std::fs::read_to_string(dir.path().join("out/curve.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("temperature,cor,contact_time,max_force,max_compression")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 4);
    for (r, t) in rows.iter().zip([-10.0, 10.0, 30.0, 50.0]) {
        assert_eq!(r[0], t);
        assert_eq!(r[1].to_bits(), cor(&scene(TAUS, Some(t), true)).to_bits());
    }
    assert!(std::fs::read_to_string(dir.path().join("out/curve.svg"))
        .unwrap()
        .contains("<svg"));
    let both = run(
        &[
            "curve",
            "s.toml",
            "--temperature",
            "0:50:4",
            "--v0",
            "1:2:3",
        ],
        dir.path(),
    );
    assert_eq!(both.status.code(), Some(2));
    std::fs::write(dir.path().join("plain.toml"), scene(TAUS, None, false)).unwrap();
    let o = run(
        &[
            "curve",
            "plain.toml",
            "--temperature",
            "0:50:4",
            "--out",
            "none",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(common::stderr(&o).contains("[material.shift]"));
    assert!(!dir.path().join("none").exists());
    for bad in ["0:50", "50:0:4", "0:50:1", "-300:0:4", "a:b:c"] {
        let o = run(&["curve", "s.toml", "--temperature", bad], dir.path());
        assert_eq!(o.status.code(), Some(1), "{bad}");
        assert!(common::stderr(&o).contains("--temperature"), "{bad}");
    }
}

/// A temperature outside the range a shift law was calibrated on (`calibrated`, which `prony`
/// writes from its isotherms) is answered with a warning, in `run`'s text and JSON and once in
/// `curve --temperature`; inside it, or without a range, none. A bad range is refused naming
/// `calibrated`.
#[test]
fn temperatures_outside_the_calibrated_range_are_warned() {
    let dir = tempfile::tempdir().unwrap();
    let with_range = |t: f64| scene(TAUS, Some(t), true) + "calibrated = [-20.0, 80.0]\n";
    let needle = "[material] shift: temperature 100 °C lies outside the -20 to 80 °C the WLF \
                  shift law was calibrated on";
    std::fs::write(dir.path().join("s.toml"), with_range(100.0)).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert!(o.status.success(), "{}", common::stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains(&format!("warning                     {needle}")),
        "{text}"
    );
    let o = run(&["run", "s.toml", "--json"], dir.path());
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(
        j["warnings"][0].as_str().unwrap().starts_with(needle),
        "{j}"
    );
    // the answer is the same as without the range
    assert_eq!(
        j["cor"].as_f64().unwrap().to_bits(),
        cor(&scene(TAUS, Some(100.0), true)).to_bits()
    );
    for inside in [
        with_range(-20.0),
        with_range(80.0),
        scene(TAUS, Some(100.0), true),
    ] {
        std::fs::write(dir.path().join("s.toml"), inside).unwrap();
        let o = run(&["run", "s.toml", "--json"], dir.path());
        let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert!(!j["warnings"].to_string().contains("calibrated"), "{j}");
    }
    // at t_ref (no temperature given): 25 °C is inside
    assert!(
        Scene::parse(&(scene(TAUS, None, true) + "calibrated = [-20.0, 80.0]\n"))
            .unwrap()
            .warnings
            .is_empty()
    );
    std::fs::write(dir.path().join("s.toml"), with_range(0.0)).unwrap();
    let o = run(
        &["curve", "s.toml", "--temperature", "-40:100:8"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", common::stderr(&o));
    let err = common::stderr(&o);
    assert!(
        err.contains(
            "warning: 2 of 8 temperatures (the lowest -40 °C, the highest 100 °C) lie outside"
        ),
        "{err}"
    );
    let o = run(
        &["curve", "s.toml", "--temperature", "-20:80:6"],
        dir.path(),
    );
    // (inside the range: no calibration warning; the warm rows' a_max/R of 0.378 is warned)
    assert!(
        !common::stderr(&o).contains("calibrated"),
        "{}",
        common::stderr(&o)
    );
    // rows outside the model's validity are warned as curve --v0 warns (20 m/s: a_max/R > 1)
    let fast = scene(TAUS, Some(20.0), true).replace("velocity = 1.0", "velocity = 20.0");
    std::fs::write(dir.path().join("fast.toml"), fast).unwrap();
    let o = run(
        &["curve", "fast.toml", "--temperature", "0:40:3"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", common::stderr(&o));
    let err = common::stderr(&o);
    assert!(
        err.contains("warning: 3 of 3 temperatures lie outside the model's validity (from 0 °C; a_max/R up to"),
        "{err}"
    );
    // the scene's warning reaches the other commands that read it: curve --v0 and dem
    std::fs::write(dir.path().join("s.toml"), with_range(100.0)).unwrap();
    let o = run(&["curve", "s.toml", "--v0", "0.5:2:3"], dir.path());
    let err = common::stderr(&o);
    assert!(err.contains(&format!("warning: {needle}")), "{err}");
    let o = run(
        &["dem", "s.toml", "--v0", "0.5:2:3", "--format", "json"],
        dir.path(),
    );
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(
        j["warnings"][0].as_str().unwrap().starts_with(needle),
        "{j}"
    );
    for (range, field) in [
        ("[80.0, -20.0]", "calibrated[0]"),
        ("[-200.0, 80.0]", "calibrated[0]"),
        ("[-20.0, inf]", "calibrated[1]"),
        ("[-20.0]", "calibrated: number of temperatures"),
    ] {
        let text = scene(TAUS, Some(0.0), true) + &format!("calibrated = {range}\n");
        let e = Scene::parse(&text).unwrap_err().to_string();
        assert!(e.contains(field) && !e.contains('\n'), "{range}: {e}");
    }
}

/// `calibrated` spans the measured rows (an isotherm's rows at 80.0 and 80.4 °C end it at
/// 80.4, not at their mean), in material.toml and in `prony --json`; `indent --scene` warns as
/// `run` does; far temperatures print in e-notation, and WLF stays finite there.
#[test]
fn calibrated_spans_the_measured_rows_and_reaches_indent() {
    let dir = tempfile::tempdir().unwrap();
    let mut data = String::from("frequency,storage,loss,temperature\n");
    for (t, shift) in [(20.0, 1.0), (40.0, 0.1)] {
        for k in 0..9 {
            let f = 10f64.powf(-1.0 + 0.5 * k as f64);
            let w = f * shift;
            let (g1, g2) = (1e6 + 1e7 * w * w / (1.0 + w * w), 1e7 * w / (1.0 + w * w));
            let t = if t == 40.0 && k % 2 == 1 { 40.4 } else { t };
            data.push_str(&format!("{f},{g1},{g2},{t}\n"));
        }
    }
    std::fs::write(dir.path().join("d.csv"), data).unwrap();
    let o = run(
        &[
            "prony",
            "d.csv",
            "--shift",
            "arrhenius",
            "--out",
            "p",
            "--json",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", common::stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(j["calibrated"], serde_json::json!([20.0, 40.4]), "{j}");
    let material = std::fs::read_to_string(dir.path().join("p/material.toml")).unwrap();
    assert!(material.contains("calibrated = [20.0, 40.4]"), "{material}");
    // indent --scene at a temperature outside the range
    let text = format!(
        "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n\n[impact]\nvelocity = 1.0\n\
         temperature = 60.0\n\n{material}"
    );
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let o = run(
        &[
            "indent",
            "--history",
            "triangle",
            "--rate",
            "1e-3",
            "--peak-time",
            "1e-3",
            "--scene",
            "s.toml",
            "--times",
            "1e-3",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", common::stderr(&o));
    assert!(
        common::stderr(&o).contains("temperature 60 °C lies outside the 20 to 40.4 °C"),
        "{}",
        common::stderr(&o)
    );
    // 1e308 °C: WLF tends to -c1 (no -inf from c1 (T - t_ref)), and the text is short
    let law = ShiftLaw::wlf(8.86, 101.6, 25.0).unwrap();
    assert!((law.log10_a(1e308).unwrap() + 8.86).abs() < 1e-12);
    let hot = scene(TAUS, Some(1e308), true) + "calibrated = [-20.0, 80.0]\n";
    let w = Scene::parse(&hot).unwrap().warnings.join(" ");
    assert!(w.contains("temperature 1e308 °C lies outside"), "{w}");
}
