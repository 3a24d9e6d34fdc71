//! The command line as a user meets it: exit codes, one-line errors, outputs.

use std::path::Path;
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_mdr-impact"))
}

fn run(args: &[&str], dir: &Path) -> Output {
    bin().args(args).current_dir(dir).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).to_string()
}

fn assert_one_line_error(o: &Output, needle: &str) {
    let code = o.status.code().unwrap();
    assert!(code == 1 || code == 2, "exit {code}");
    let e = stderr(o);
    assert_eq!(e.trim_end().lines().count(), 1, "not one line: {e}");
    assert!(e.contains(needle), "'{needle}' not in: {e}");
    assert!(!e.contains("panicked"));
}

#[test]
fn default_scene_runs_and_writes_nothing_unless_asked() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(&[], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("coefficient of restitution"));
    assert!(out.contains("contact time") && out.contains(" s\n"));
    assert!(out.contains("max force") && out.contains(" N\n"));
    assert!(out.contains("files written               none"), "{out}");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    // --out DIR: the history, the force-time and the force-indentation plots
    let o = run(&["run", "--out", "res"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains("history written to          res/history.csv"),
        "{out}"
    );
    let csv = std::fs::read_to_string(dir.path().join("res/history.csv")).unwrap();
    assert!(csv.starts_with("t,d,v,force,a\n"));
    assert!(csv.lines().count() > 100);
    for svg in ["force.svg", "force_indentation.svg"] {
        let text = std::fs::read_to_string(dir.path().join("res").join(svg)).unwrap();
        assert!(
            text.contains("<svg") && text.contains("default scene"),
            "{svg}"
        );
    }
}

#[test]
fn cor_prints_the_cor_alone_on_the_last_line() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        &[
            "cor", "--nu", "0.45", "--p2", "0.01", "--p3", "1", "--solver", "mdr", "--rtol", "1e-4",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let e: f64 = out.lines().last().unwrap().trim().parse().unwrap();
    assert!((e - 0.2350313).abs() < 1e-4 * 0.235, "{e}");
}

#[test]
fn cor_input_csv_in_order_and_bad_rows_named() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("in.csv");
    std::fs::write(&p, "nu,p2,p3\n0.5,0.001,10\n0.45,0.01,1\n-0.5,1,0.1\n").unwrap();
    let o = run(
        &[
            "cor", "--input", "in.csv", "--solver", "mdr", "--rtol", "1e-4",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines[0],
        "nu,p2,p3,cor,contact_time_canonical,max_indentation_canonical"
    );
    assert_eq!(lines.len(), 4);
    assert!(lines[1].starts_with("0.5,0.001,10,"));
    assert!(lines[2].starts_with("0.45,0.01,1,"));
    assert!(lines[3].starts_with("-0.5,1,0.1,"));
    for l in &lines[1..] {
        for f in l.split(',') {
            let x: f64 = f.parse().unwrap();
            assert!(x.is_finite());
        }
    }
    std::fs::write(&p, "nu,p2,p3\n0.3,1,1\n0.7,1,1\n").unwrap();
    let o = run(&["cor", "--input", "in.csv"], dir.path());
    assert_one_line_error(&o, "in.csv:3:");
    assert!(o.stdout.is_empty());
    std::fs::write(&p, "nu,p2,p3\n0.3,abc,1\n").unwrap();
    assert_one_line_error(
        &run(&["cor", "--input", "in.csv"], dir.path()),
        "in.csv:2: p2 = 'abc'",
    );
    std::fs::write(&p, "nu,p3\n0.3,1\n").unwrap();
    assert_one_line_error(
        &run(&["cor", "--input", "in.csv"], dir.path()),
        "in.csv:1: header",
    );
}

#[test]
fn bad_input_is_one_line_and_nonzero() {
    let dir = tempfile::tempdir().unwrap();
    assert_one_line_error(
        &run(
            &["cor", "--nu", "0.6", "--p2", "1", "--p3", "1"],
            dir.path(),
        ),
        "nu = 6e-1",
    );
    // a value outside a closed set is a usage error (exit 2) listing the values
    let o = run(
        &[
            "cor", "--nu", "0.3", "--p2", "1", "--p3", "1", "--solver", "x",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert_one_line_error(&o, "invalid value 'x' for '--solver <SOLVER>'");
    assert!(stderr(&o).contains("auto, mdr-euler, mdr, reference, fast"));
    assert_one_line_error(
        &run(
            &[
                "cor", "--nu", "0.3", "--p2", "1", "--p3", "1", "--rtol", "0",
            ],
            dir.path(),
        ),
        "rtol",
    );
    assert_one_line_error(&run(&["run", "missing.toml"], dir.path()), "missing.toml");
    let scene = mdr_impact::io::scene::DEFAULT_SCENE.replace("[impact]", "[impact]\nspeed = 3.0");
    std::fs::write(dir.path().join("s.toml"), scene).unwrap();
    assert_one_line_error(
        &run(&["run", "s.toml"], dir.path()),
        "unknown field `speed`",
    );
    let scene = mdr_impact::io::scene::DEFAULT_SCENE.replace("g_1 = 1.0e7", "g_1 = -1.0");
    std::fs::write(dir.path().join("s.toml"), scene).unwrap();
    assert_one_line_error(
        &run(&["run", "s.toml"], dir.path()),
        "g_1 = -1e0 is out of range",
    );
    // explicit Euler step above the stability bound
    let scene = mdr_impact::io::scene::DEFAULT_SCENE
        .replace(
            "name = \"auto\"",
            "name = \"mdr-euler\"\nelements = 20\nsteps = 10",
        )
        .replace("[output]", "[unused]");
    let scene: String = scene
        .lines()
        .filter(|l| {
            !l.starts_with("history") && !l.starts_with("plot") && !l.starts_with("[unused]")
        })
        .collect::<Vec<_>>()
        .join("\n");
    std::fs::write(dir.path().join("s.toml"), scene).unwrap();
    assert_one_line_error(&run(&["run", "s.toml"], dir.path()), "stability bound");
}

/// Blank lines are skipped and named on stderr; every data row has its row out.
#[test]
fn cor_input_blank_lines_reported_and_no_row_lost() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("in.csv");
    std::fs::write(
        &p,
        "nu,p2,p3\r\n0.45,0.01,1\r\n\r\n\r\n0.3,1,0.1\r\n\r\n0.5,0.001,10",
    )
    .unwrap();
    let o = run(&["cor", "--input", "in.csv"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout.clone()).unwrap();
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 4, "{out}");
    assert!(lines[1].starts_with("0.45,0.01,1,"));
    assert!(lines[2].starts_with("0.3,1,0.1,"));
    assert!(lines[3].starts_with("0.5,0.001,10,"));
    assert_eq!(
        stderr(&o).trim_end(),
        "note: in.csv: skipped blank lines 3, 4, 6"
    );
    // no blank line: nothing on stderr
    std::fs::write(&p, "nu,p2,p3\n0.45,0.01,1\n").unwrap();
    let o = run(&["cor", "--input", "in.csv"], dir.path());
    assert!(o.status.success() && o.stderr.is_empty(), "{}", stderr(&o));
}

/// Errors name the physical line whatever the line endings, and quote no raw control byte.
#[test]
fn cor_input_errors_name_the_physical_line() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("in.csv");
    for (bytes, needle) in [
        (
            &b"nu,p2,p3\r\n0.45,0.01,1\r\n0.3,1,0.1\r\n0.5,x,10\r\n"[..],
            "in.csv:4: p2 = 'x'",
        ),
        (
            &b"nu,p2,p3\r0.45,0.01,1\r0.3,1,0.1\r0.5,x,10\r"[..],
            "in.csv:4:",
        ),
        (&b"nu,p2,p3\n\n\n0.5,x,10\n"[..], "in.csv:4:"),
        (
            &b"nu,p2,p3\n0.45,0.0\x001,1\n"[..],
            "in.csv:2: p2 = '0.0\\01'",
        ),
        (&b"nu,p2,p3\n0.45,\x07,1\n"[..], "in.csv:2: p2 = '\\u{7}'"),
        (&b"nu,p2,p3\n0.45,\xff,1\n"[..], "in.csv:2: not valid UTF-8"),
        (&b"nu,p2,p3\n0.45,0.01,1\n,,\n"[..], "in.csv:3: nu is empty"),
        (&b"nu,p2,p3\n0.45,0.01\n"[..], "in.csv:2: expected 3 fields"),
    ] {
        std::fs::write(&p, bytes).unwrap();
        let o = run(&["cor", "--input", "in.csv"], dir.path());
        assert_one_line_error(&o, needle);
        assert!(o.stdout.is_empty());
        let e = stderr(&o);
        assert!(
            !e.trim_end().chars().any(char::is_control),
            "raw control byte in {e:?}"
        );
    }
}

/// The groups from flags and from CSV rows: p3 = 0 is the elastic limit (e = 1); non-finite
/// values and values outside the ranges are refused naming the group.
#[test]
fn cor_groups_elastic_limit_and_refusals() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        &["cor", "--nu", "0.3", "--p2", "1", "--p3", "0"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(String::from_utf8(o.stdout).unwrap().trim(), "1");
    for (args, needle) in [
        (["0.3", "inf", "1"], "p2 = inf is out of range"),
        (["0.3", "1e999", "1"], "p2 = inf is out of range"),
        (["0.3", "1", "-1"], "p3 = -1e0 is out of range"),
        (["0.5000001", "1", "1"], "nu = 5.000001e-1 is out of range"),
        (["NaN", "1", "1"], "nu = NaN is out of range"),
        (["0.3", "NaN", "1"], "p2 = NaN is out of range"),
        (["0.3", "1", "NaN"], "p3 = NaN is out of range"),
    ] {
        let o = run(
            &["cor", "--nu", args[0], "--p2", args[1], "--p3", args[2]],
            dir.path(),
        );
        assert_one_line_error(&o, needle);
    }
    let p = dir.path().join("in.csv");
    std::fs::write(&p, "nu,p2,p3\n0.3,1,0\n").unwrap();
    let o = run(&["cor", "--input", "in.csv"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.lines().nth(1).unwrap().starts_with("0.3,1,0,1e0,"),
        "{out}"
    );
    for (row, needle) in [
        ("0.3,inf,1", "in.csv:2: p2 = 'inf' is not a finite number"),
        (
            "0.3,1e999,1",
            "in.csv:2: p2 = '1e999' is not a finite number",
        ),
        ("0.3,1,-1", "in.csv:2: p3 = -1e0 is out of range"),
        (
            "0.5000001,1,1",
            "in.csv:2: nu = 5.000001e-1 is out of range",
        ),
        ("NaN,1,1", "in.csv:2: nu = 'NaN' is not a finite number"),
    ] {
        std::fs::write(&p, format!("nu,p2,p3\n{row}\n")).unwrap();
        assert_one_line_error(&run(&["cor", "--input", "in.csv"], dir.path()), needle);
    }
}

/// The default scene without outputs, `solver_lines` added to `[solver]`.
fn scene_without_outputs(solver_lines: &str) -> String {
    let head = mdr_impact::io::scene::DEFAULT_SCENE
        .split("[output]")
        .next()
        .unwrap()
        .to_string();
    head.replace("rtol = 1e-6", &format!("rtol = 1e-6\n{solver_lines}"))
}

/// Scene `[solver]` resolution and `[output]` paths are refused up front, naming the key.
#[test]
fn scene_resolution_and_empty_paths_refused() {
    let dir = tempfile::tempdir().unwrap();
    let s = dir.path().join("s.toml");
    for (text, needle) in [
        (
            scene_without_outputs("elements = 18446744073709551615\nsteps = 2000"),
            "allowed 2 <= elements <= 10^6",
        ),
        (
            scene_without_outputs("elements = 200\nsteps = 1000000001"),
            "allowed 4 <= steps <= 10^9",
        ),
        (
            scene_without_outputs("elements = 200\nsteps = 2000")
                .replace("name = \"auto\"", "name = \"fast\""),
            "fast: [solver] elements/steps",
        ),
        (
            scene_without_outputs("elements = 200\nsteps = 2000")
                .replace("name = \"auto\"", "name = \"reference\""),
            "reference: [solver] elements/steps",
        ),
        (
            format!("{}[output]\nhistory = \"\"\n", scene_without_outputs("")),
            "[output] history is an empty path",
        ),
        (
            format!("{}[output]\nplot = \"\"\n", scene_without_outputs("")),
            "[output] plot is an empty path",
        ),
        (
            scene_without_outputs("").replace("name = \"auto\"", "name = \"fa\\u0000st\""),
            "name = 'fa\\0st'",
        ),
    ] {
        std::fs::write(&s, text).unwrap();
        let o = run(&["run", "s.toml"], dir.path());
        assert_one_line_error(&o, needle);
        assert!(!stderr(&o).trim_end().chars().any(char::is_control));
        assert!(o.stdout.is_empty());
    }
}

/// An empty path on the command line is a usage error naming the flag, never an OS error.
#[test]
fn empty_path_flags_refused() {
    let dir = tempfile::tempdir().unwrap();
    for (args, flag) in [
        (&["cor", "--input", ""][..], "--input"),
        (&["sweep", "--out", ""][..], "--out"),
        (&["validate", "--out", ""][..], "--out"),
        (&["bench", "--quick", "--out", ""][..], "--out"),
        (&["reference", "--out", ""][..], "--out"),
        (&["figures", "--out", ""][..], "--out"),
        (&["run", ""][..], "SCENE"),
    ] {
        let o = run(args, dir.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let e = stderr(&o);
        assert!(e.contains(flag), "{args:?}: {e}");
        assert!(!e.contains("No such file"), "{args:?}: {e}");
    }
    // nothing was written
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn stress_smoke_fills_its_section_and_keeps_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let report = "# R\n\nbefore\n<!-- stress:begin -->\nold\n<!-- stress:end -->\nafter\n";
    std::fs::write(dir.path().join("R.md"), report).unwrap();
    let o = run(
        &[
            "stress", "--rows", "4", "--seed", "3", "--out", "v", "--report", "R.md",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.path().join("R.md")).unwrap();
    assert!(text.starts_with("# R\n\nbefore\n<!-- stress:begin -->\nGenerated by `mdr-impact stress --rows 4 --seed 3`"), "{text}");
    assert!(text.ends_with("<!-- stress:end -->\nafter\n"), "{text}");
    assert!(!text.contains("old"));
    assert!(text.contains("| all | fast | 40 |"), "{text}");
    let csv = std::fs::read_to_string(dir.path().join("v/stress_outside.csv")).unwrap();
    assert_eq!(
        csv,
        "problem,index,nu,p2,p3,rtol,solver,cor,truth,truth_source,rel_error,detail\n"
    );
    // a report without the markers is refused before any work, in one line
    std::fs::write(dir.path().join("N.md"), "# no markers\n").unwrap();
    let o = run(&["stress", "--rows", "4", "--report", "N.md"], dir.path());
    assert_one_line_error(&o, "no stress markers");
}

/// `run --json`: one JSON object on stdout with the outcome's keys (SI), for the standard solid
/// and for a general material; the notes about written files go to stderr.
#[test]
fn run_json_prints_one_object() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(&["run", "--json"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout.clone()).unwrap();
    assert_eq!(out.trim_end().lines().count(), 1, "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    for key in [
        "cor",
        "contact_time",
        "max_indentation",
        "max_force",
        "estimated_rel_error",
        "rebound_velocity",
        "time_of_max_indentation",
        "max_contact_radius",
        "dissipated_energy",
    ] {
        assert!(v[key].is_number(), "{key}: {v}");
    }
    // the default scene asks for auto and no history: fast answers, no fallback
    assert_eq!(v["solver"], "fast");
    assert_eq!(v["requested_solver"], "auto");
    assert!(v["fallback"].is_null());
    assert!(v["solver_reason"].is_string());
    for key in ["steps", "evaluations", "levels"] {
        assert!(v["work"][key].is_u64(), "work.{key}: {v}");
    }
    let cor = v["cor"].as_f64().unwrap();
    assert!(cor > 0.0 && cor < 1.0);

    // a general material with 10 G_eq terms (answered by fast; with more than FAST_MAX_TERMS
    // auto would fall back to reference and say why)
    let terms: Vec<String> = (0..10)
        .map(|i| {
            format!(
                "[{:e}, {:e}]",
                2.0e6 / (1.0 + i as f64),
                1.0e-7 * 10f64.powi(i)
            )
        })
        .collect();
    std::fs::write(
        dir.path().join("general.toml"),
        format!(
            "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n[impact]\nvelocity = 0.99\n\
             [material.shear]\ng_inf = 1.0e6\nterms = [{}]\n[material.bulk]\nincompressible = true\n\
             [solver]\nrtol = 1e-5\n",
            terms.join(", ")
        ),
    )
    .unwrap();
    let o = run(&["run", "general.toml", "--json"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["estimated_rel_error"].as_f64().unwrap() <= 1e-5);
    if v["solver"] == "reference" {
        assert!(v["fallback"].as_str().unwrap().contains("prony terms"));
    }
    // the summary names the general material
    let o = run(&["run", "general.toml"], dir.path());
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("general: 10 shear terms"), "{out}");
    assert!(
        out.contains("G_eq") && !out.contains("groups (Eq. 11)"),
        "{out}"
    );
}

/// The shipped real polymers (published Prony series, `scenes/polyisobutylene.toml` with its
/// `tau,modulus` table, `scenes/epoxy.toml` inline) run from any folder, and their `--json` CoR
/// agrees with `reference` at rtol 1e-10 within the scene's rtol 1e-6.
#[test]
fn polymer_scenes_run() {
    use mdr_impact::{solve, SolveOptions, SolverKind};
    let dir = tempfile::tempdir().unwrap();
    for case in mdr_impact::report::catalogue::POLYMERS {
        let path = case.path();
        let o = run(&["run", path.to_str().unwrap(), "--json"], dir.path());
        assert!(o.status.success(), "{}: {}", case.id, stderr(&o));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let cor = v["cor"].as_f64().unwrap();
        let truth = solve(
            &case.impact().unwrap(),
            &SolveOptions::with(SolverKind::Reference, 1e-10),
        )
        .unwrap()
        .cor;
        assert!(
            ((cor - truth) / truth).abs() <= 1e-6,
            "{}: {cor} vs {truth}",
            case.id
        );
        assert!(v["estimated_rel_error"].as_f64().unwrap() <= 1e-6);
        let text = run(&["run", path.to_str().unwrap()], dir.path());
        assert!(text.status.success());
        assert!(String::from_utf8_lossy(&text.stdout).contains("coefficient of restitution"));
    }
}

/// Closed sets of values are clap's: a typo exits with 2 on one line naming the flag and the
/// accepted values.
#[test]
fn closed_sets_are_usage_errors_listing_the_values() {
    let dir = tempfile::tempdir().unwrap();
    let indent = [
        "indent",
        "--rate",
        "0.3",
        "--peak-time",
        "1",
        "--radius",
        "1",
        "--g-inf",
        "1",
        "--g1",
        "100",
        "--eta",
        "1",
        "--nu",
        "0.45",
    ];
    for (args, needle, values) in [
        (
            &["--history", "sine"][..],
            "'--history <HISTORY>'",
            "triangle, half-sine",
        ),
        (
            &["--history", "triangle", "--solver", "fem"][..],
            "'--solver <SOLVER>'",
            "theory, mdr",
        ),
    ] {
        let all: Vec<&str> = indent.iter().chain(args).copied().collect();
        let o = run(&all, dir.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_one_line_error(&o, needle);
        assert!(stderr(&o).contains(values), "{}", stderr(&o));
    }
    let o = run(&["fit", "d.csv", "--model", "maxwell"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert_one_line_error(&o, "'--model <MODEL>'");
    let o = run(&["figures", "--solver", "fastest"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert_one_line_error(&o, "'--solver <SOLVER>'");
    // nothing was written
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

/// Signed-number flags take a negative value and refuse it with a range message (exit 1).
#[test]
fn negative_numbers_get_a_range_message() {
    let dir = tempfile::tempdir().unwrap();
    for (args, needle) in [
        (
            &["bench", "--quick", "--budget", "-1", "--out", "b"][..],
            "--budget = -1e0",
        ),
        (
            &["fit-study", "--reps", "1", "--noise", "-1"][..],
            "noise = -1e0",
        ),
    ] {
        let o = run(args, dir.path());
        assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
        assert_one_line_error(&o, needle);
    }
}

/// The indent defaults (history kinds, 101 times over [0, 2T]) come from the library.
#[test]
fn indent_default_times_grid() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        &[
            "indent",
            "--history",
            "half-sine",
            "--rate",
            "0.3",
            "--peak-time",
            "1",
            "--radius",
            "1",
            "--g-inf",
            "1",
            "--g1",
            "100",
            "--eta",
            "1",
            "--nu",
            "0.45",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "t_s,d_m,a_m,force_N");
    assert_eq!(lines.len(), 1 + mdr_impact::apps::indent::DEFAULT_TIMES);
    assert!(lines[101].starts_with("2"), "{}", lines[101]);
}
