//! One grammar across commands, and the messages of issue 27 that were about the wrong thing:
//! `--v0 MIN:MAX[:N]` everywhere, `cor --json`, headers that say their units, a work count not
//! printed as an rtol, a solver failure not blamed on `--v0`, `sweep`'s lines, `stress` outside
//! the repository, the effective sphere of two bodies.

use crate::common;

use common::{run, stderr};
use mdr_impact::apps::curve::DEFAULT_VELOCITIES;

fn assert_one_line_error(o: &std::process::Output, needle: &str) {
    assert_eq!(o.status.code(), Some(1), "{}", stderr(o));
    let e = stderr(o);
    assert_eq!(e.trim_end().lines().count(), 1, "not one line: {e}");
    assert!(e.contains(needle), "'{needle}' not in: {e}");
}

/// `curve --v0 MIN:MAX` and `dem --v0 MIN:MAX` both take the one default N.
#[test]
fn v0_without_n_means_the_same_default_everywhere() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(&["curve", "--v0", "0.5:2", "--out", "c"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = std::fs::read_to_string(dir.path().join("c/curve.csv")).unwrap();
    assert_eq!(csv.lines().count(), DEFAULT_VELOCITIES + 1);
    let o = run(
        &["dem", "--v0", "0.5:2", "--format", "json", "--out", "d"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = std::fs::read_to_string(dir.path().join("d/dem.csv")).unwrap();
    assert_eq!(csv.lines().count(), DEFAULT_VELOCITIES + 1);
}

/// `--v0 1:2:1` names N, `--v0 2:1` the two ends.
#[test]
fn v0_errors_name_the_part_that_is_wrong() {
    let dir = tempfile::tempdir().unwrap();
    for (v0, needle) in [
        (
            "1:2:1",
            "N = 1 is out of range: allowed 2 <= N <= 100000 (one velocity: use run)",
        ),
        ("2:1", "MIN = 2e0 is not below MAX = 1e0"),
    ] {
        for cmd in ["curve", "dem"] {
            let mut args = vec![cmd, "--v0", v0];
            if cmd == "dem" {
                args.extend(["--format", "json"]);
            }
            let o = run(&args, dir.path());
            assert_one_line_error(&o, needle);
            assert!(!stderr(&o).contains("2 <= N <= 100000 is out of range"));
        }
    }
}

/// A solve that fails inside `curve` names the velocity, not the flag, and a work limit is
/// printed as a count of work, not as an rtol.
#[test]
fn curve_solver_failure_is_not_blamed_on_v0() {
    let dir = tempfile::tempdir().unwrap();
    let scene =
        mdr_impact::io::scene::DEFAULT_SCENE.replace("name = \"auto\"", "name = \"mdr-euler\"");
    std::fs::write(dir.path().join("euler.toml"), scene).unwrap();
    let o = run(&["curve", "euler.toml", "--v0", "0.5:1:3"], dir.path());
    assert_one_line_error(&o, "error: at v0 = 5e-1 m/s: mdr-euler: element updates");
    let e = stderr(&o);
    assert!(!e.contains("--v0"), "{e}");
    assert!(e.contains("needed, above the work limit of"), "{e}");
    assert!(!e.contains("rtol ="), "{e}");
}

/// `cor --json`: one object with the groups as given, the units named, the solver and why;
/// refused with `--input` (CSV) as a usage error.
#[test]
fn cor_json_and_canonical_headers() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        &["cor", "--nu", "0.45", "--p2", "0.01", "--p3", "1", "--json"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(out.trim_end().lines().count(), 1);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["groups"]["nu"], 0.45);
    assert_eq!(v["groups"]["p2"], 0.01);
    assert_eq!(v["units"], "canonical: m = R = v0 = G_inf = 1");
    assert_eq!(v["requested_solver"], "auto");
    // the groups do not fix a_max/R (canonical units set m v0^2 / (G_inf R^3) = 1): no
    // validity judged here, even where the canonical contact is wide (a_max/R = 0.63 at these
    // groups, 0.32 in the default scene that has them)
    let wide = run(
        &[
            "cor",
            "--nu",
            "0.49",
            "--p2",
            "0.1",
            "--p3",
            "0.3911599",
            "--json",
        ],
        dir.path(),
    );
    let w: serde_json::Value = serde_json::from_slice(&wide.stdout).unwrap();
    assert!(w["validity"].is_null(), "{w}");
    assert_eq!(w["warnings"], serde_json::json!([]));
    // the same digits as the plain command's (serde_json's own parsing may round the last bit)
    let plain = run(
        &["cor", "--nu", "0.45", "--p2", "0.01", "--p3", "1"],
        dir.path(),
    );
    let e = String::from_utf8(plain.stdout).unwrap();
    assert!(out.contains(&format!("\"cor\":{},", e.trim())), "{out} {e}");
    std::fs::write(dir.path().join("g.csv"), "nu,p2,p3\n0.45,0.01,1\n").unwrap();
    let o = run(&["cor", "--input", "g.csv", "--json"], dir.path());
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let o = run(&["cor", "--input", "g.csv"], dir.path());
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.starts_with("nu,p2,p3,cor,contact_time_canonical,max_indentation_canonical\n"));
}

/// `sweep` says where its rows are in a labelled line; a file of another sweep names `--fresh`.
#[test]
fn sweep_lines_and_mismatch_message() {
    let dir = tempfile::tempdir().unwrap();
    let grid = [
        "sweep", "--log-p2", "-1:0:2", "--log-p3", "0:1:2", "--out", "s.csv",
    ];
    let o = run(&grid, dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("rows written to             s.csv\n"), "{out}");
    assert!(!out.lines().any(|l| l.starts_with("rows in")), "{out}");
    let other = [
        "sweep", "--log-p2", "-1:0:3", "--log-p3", "0:1:2", "--out", "s.csv",
    ];
    let o = run(&other, dir.path());
    assert_one_line_error(&o, "or --fresh to discard its rows and start afresh");
    let mut fresh = other.to_vec();
    fresh.push("--fresh");
    assert!(run(&fresh, dir.path()).status.success());
}

/// `stress` runs outside the repository: no VALIDATION.md there, the section is printed and
/// no report updated; a named report without markers is still refused.
#[test]
fn stress_runs_outside_the_repository() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(&["stress", "--rows", "2"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains("no report updated (no VALIDATION.md here"),
        "{out}"
    );
    assert!(dir.path().join("validation/stress_outside.csv").exists());
    assert!(!dir.path().join("VALIDATION.md").exists());
}

/// Two bodies: the summary calls the reduced sphere what it is.
#[test]
fn two_bodies_label_the_effective_sphere() {
    let dir = tempfile::tempdir().unwrap();
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/two_spheres.toml");
    let o = run(&["run", scene], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.starts_with("effective sphere            m = "), "{out}");
    assert!(!out.lines().any(|l| l.starts_with("sphere ")), "{out}");
}
