//! Plots a referee accepts: log axes labelled at every decade and at both ends of the range,
//! titles that name the scene, and the force-indentation loop beside the force-time plot.

use crate::common;

use common::{run, stderr};
use mdr_impact::io::plot::{log_ticks, tick_label};

#[test]
fn log_ticks_label_every_decade_and_both_ends() {
    let (bold, light) = log_ticks(0.1, 1000.0);
    assert_eq!(bold, [0.1, 1.0, 10.0, 100.0, 1000.0]);
    // minor ticks in the first decade too
    assert!(light.contains(&0.2) && light.contains(&0.9), "{light:?}");
    let (bold, _) = log_ticks(0.5, 5.0);
    assert_eq!(bold, [0.5, 1.0, 5.0]);
    // a decade within a fifth of a decade of an end gives way to the end's label
    let (bold, _) = log_ticks(0.011, 95.0);
    assert_eq!(bold, [0.011, 0.1, 1.0, 10.0, 95.0]);
    let labels: Vec<String> = [0.1, 1.0, 1000.0, 0.25, 1e-5, 2.5e6]
        .map(tick_label)
        .to_vec();
    assert_eq!(labels, ["0.1", "1", "1000", "0.25", "1e-5", "2.5e6"]);
}

#[test]
fn curve_plot_names_the_scene_and_labels_its_range_ends() {
    let dir = tempfile::tempdir().unwrap();
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/polymer_ball_on_steel.toml"
    );
    let o = run(
        &["curve", scene, "--v0", "0.1:1000:8", "--log", "--out", "c"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(dir.path().join("c/curve.svg")).unwrap();
    assert!(
        svg.contains("Coefficient of restitution against impact velocity: polymer_ball_on_steel"),
        "title"
    );
    // plotters writes each text on a line of its own
    let texts: Vec<&str> = svg.lines().map(str::trim).collect();
    for label in ["0.1", "1", "10", "100", "1000"] {
        assert!(texts.contains(&label), "{label} not labelled");
    }
    assert!(!texts.contains(&"1000.0"));
}

#[test]
fn run_plots_name_the_scene_and_show_both_branches() {
    let dir = tempfile::tempdir().unwrap();
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/two_spheres.toml");
    let o = run(&["run", scene, "--out", "r"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let loop_svg = std::fs::read_to_string(dir.path().join("r/force_indentation.svg")).unwrap();
    for text in [
        "Contact force against indentation (hysteresis)",
        "two_spheres: effective sphere m = ",
        "loading (d increasing)",
        "unloading (d decreasing)",
    ] {
        assert!(loop_svg.contains(text), "{text}");
    }
    let force = std::fs::read_to_string(dir.path().join("r/force.svg")).unwrap();
    assert!(force.contains("contact force (reference solver)"));
}
