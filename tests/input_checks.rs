//! Inputs are answered or refused, never silently bent: the dimensionless groups, the explicit
//! MDR resolution, output paths and user text quoted in scene messages.

use mdr_impact::io::scene::{Scene, DEFAULT_SCENE};
use mdr_impact::{solve, Error, Groups, Impact, Resolution, SolveOptions, SolverKind};

fn refused(r: mdr_impact::Result<Groups>, f: &str) {
    match r {
        Err(Error::OutOfRange { field, .. }) => assert_eq!(field, f),
        other => panic!("expected OutOfRange({f}), got {other:?}"),
    }
}

/// `p3 = 0` is the elastic limit (Hertz, e = 1); non-finite groups and values outside the ranges
/// are refused with the group named.
#[test]
fn groups_elastic_limit_and_refusals() {
    let g = Groups::new(0.3, 1.0, 0.0).unwrap();
    let o = solve(&Impact::from_groups(g).unwrap(), &SolveOptions::default()).unwrap();
    assert_eq!(o.cor, 1.0);
    assert_eq!(o.solver, "hertz");
    refused(Groups::new(0.3, f64::INFINITY, 1.0), "p2");
    refused(Groups::new(0.3, "1e999".parse().unwrap(), 1.0), "p2");
    refused(Groups::new(0.3, 1e-310, 1.0), "p2");
    refused(Groups::new(0.3, 0.0, 1.0), "p2");
    refused(Groups::new(0.3, 1.0, -1.0), "p3");
    refused(Groups::new(0.3, 1.0, f64::INFINITY), "p3");
    refused(Groups::new(0.5000001, 1.0, 1.0), "nu");
    refused(Groups::new(f64::NAN, 1.0, 1.0), "nu");
    refused(Groups::new(0.3, f64::NAN, 1.0), "p2");
    refused(Groups::new(0.3, 1.0, f64::NAN), "p3");
    let e = Groups::new(0.3, f64::INFINITY, 1.0)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("p2 = inf is out of range") && e.contains("p3 = 0"),
        "{e}"
    );
}

fn with_resolution(solver: SolverKind, elements: usize, steps: usize) -> SolveOptions {
    SolveOptions {
        solver,
        resolution: Some(Resolution { elements, steps }),
        ..Default::default()
    }
}

/// `elements` and `steps` outside their ranges are refused as written (no saturated product), and
/// an explicit resolution is refused by the solvers that would ignore it.
#[test]
fn resolution_ranges_and_solvers() {
    for (elements, steps, field) in [
        (usize::MAX, 100, "elements"),
        (1_000_001, 100, "elements"),
        (1, 100, "elements"),
        (100, usize::MAX, "steps"),
        (100, 1_000_000_001, "steps"),
        (100, 3, "steps"),
    ] {
        match with_resolution(SolverKind::Mdr, elements, steps).validate() {
            Err(Error::OutOfRange { field: f, .. }) => assert_eq!(f, field),
            other => panic!("{elements} {steps}: {other:?}"),
        }
    }
    for kind in [SolverKind::Mdr, SolverKind::MdrEuler, SolverKind::Auto] {
        with_resolution(kind, 1_000_000, 1_000_000_000)
            .validate()
            .unwrap();
    }
    for kind in [SolverKind::Fast, SolverKind::Reference] {
        match with_resolution(kind, 100, 1000).validate() {
            Err(Error::NotSupported { solver, what }) => {
                assert_eq!(solver, kind.name());
                assert!(what.contains("elements/steps"), "{what}")
            }
            other => panic!("{kind}: {other:?}"),
        }
    }
}

/// The default scene with `extra` lines added to `[solver]`, without the `[output]` table.
fn scene_with(solver_lines: &str, output_lines: &str) -> String {
    let head = DEFAULT_SCENE.split("[output]").next().unwrap();
    let head = head.replace("rtol = 1e-6", &format!("rtol = 1e-6\n{solver_lines}"));
    format!("{head}[output]\n{output_lines}\n")
}

fn scene_error(text: &str) -> Error {
    match Scene::parse(text) {
        Err(e) => e,
        Ok(_) => panic!("accepted:\n{text}"),
    }
}

#[test]
fn scene_resolution_refused_as_written() {
    let e = scene_error(&scene_with(
        "elements = 18446744073709551615\nsteps = 2000",
        "",
    ));
    assert!(matches!(
        e,
        Error::OutOfRange {
            field: "elements",
            ..
        }
    ));
    assert!(e.to_string().contains("2 <= elements <= 10^6"), "{e}");
    let e = scene_error(&scene_with("elements = 200\nsteps = 2000000000", ""));
    assert!(matches!(e, Error::OutOfRange { field: "steps", .. }));
    for name in ["fast", "reference"] {
        let text = scene_with("elements = 200\nsteps = 2000", "")
            .replace("name = \"auto\"", &format!("name = \"{name}\""));
        let e = scene_error(&text).to_string();
        assert!(
            e.contains(&format!("{name}: [solver] elements/steps")),
            "{e}"
        );
    }
    for name in ["auto", "mdr", "mdr-euler"] {
        let text = scene_with("elements = 200\nsteps = 2000", "")
            .replace("name = \"auto\"", &format!("name = \"{name}\""));
        Scene::parse(&text).unwrap();
    }
}

#[test]
fn scene_empty_output_paths_refused() {
    for (key, field) in [("history", "[output] history"), ("plot", "[output] plot")] {
        let e = scene_error(&scene_with("", &format!("{key} = \"\"")));
        assert_eq!(e, Error::EmptyPath { field });
        assert_eq!(
            e.to_string(),
            format!("{field} is an empty path: give a file name")
        );
    }
}

/// User text quoted in a scene message never carries a raw control character.
#[test]
fn scene_messages_escape_control_characters() {
    let text = DEFAULT_SCENE.replace("name = \"auto\"", "name = \"fa\\u0007st\"");
    let e = scene_error(&text).to_string();
    assert!(e.contains("name = 'fa\\u{7}st'"), "{e}");
    assert!(!e.chars().any(char::is_control), "{e:?}");
    let text = DEFAULT_SCENE.replace("[impact]", "[impact]\n\"spe\\u0000ed\" = 3.0");
    let e = scene_error(&text).to_string();
    assert!(e.contains("spe\\0ed"), "{e}");
    assert!(!e.chars().any(char::is_control), "{e:?}");
}
