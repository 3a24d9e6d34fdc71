//! Messages a user meets, one test per fix: each names the key, the file and the table (or
//! the flag and the parameter) it is about, in words rather than Rust type names.

use crate::common;

use common::{run, stderr};

/// A one-sphere scene with `radius` and the `[material]` lines `material`.
fn scene(radius: &str, material: &str) -> String {
    format!("[sphere]\nmass = 4.11e-3\nradius = {radius}\n[impact]\nvelocity = 0.99\n{material}")
}

const STANDARD: &str = "[material]\ng_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\npoisson = 0.49\n";

fn assert_one_line_error(o: &std::process::Output, needle: &str) {
    assert_eq!(o.status.code(), Some(1), "{}", stderr(o));
    let e = stderr(o);
    assert_eq!(e.trim_end().lines().count(), 1, "not one line: {e}");
    assert!(e.contains(needle), "'{needle}' not in: {e}");
}

/// `radius = "abc"` names the line, the table and the key, and the type in words.
#[test]
fn type_errors_name_the_key() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), scene("\"abc\"", STANDARD)).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert_one_line_error(
        &o,
        "s.toml: line 3: key [sphere] radius: invalid type: string \"abc\", expected a number",
    );
    let text = format!(
        "{}[solver]\nelements = -3\nsteps = 10\n",
        scene("5e-3", STANDARD)
    );
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert_one_line_error(&o, "key [solver] elements: invalid value: integer `-3`");
}

/// A value out of range names the file and the table.
#[test]
fn bad_values_name_file_and_table() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), scene("-5e-3", STANDARD)).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert_one_line_error(&o, "s.toml [sphere]: radius = -5e-3 is out of range");
    let material = STANDARD.replace("g_1 = 1.0e7", "g_1 = -1.0");
    std::fs::write(dir.path().join("s.toml"), scene("5e-3", &material)).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert_one_line_error(&o, "s.toml [material]: g_1 = -1e0 is out of range");
}

/// `--fix g_inf=-1` names the parameter.
#[test]
fn fix_out_of_range_names_the_parameter() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("d.csv"), "v0,cor\n0.5,0.5\n1,0.45\n2,0.4\n").unwrap();
    for (fix, needle) in [
        ("g_inf=-1", "--fix g_inf: value = -1e0 is out of range"),
        ("eta=0", "--fix eta: value = 0e0 is out of range"),
        ("k_0=-1", "--fix k_0: k_0 = -1e0 is out of range"),
    ] {
        let o = run(&["fit", "d.csv", "--fix", fix, "--out", "res"], dir.path());
        assert_one_line_error(&o, needle);
        assert!(!dir.path().join("res").exists());
    }
}

/// A fixed value outside the box every fit stays in is refused at once, naming the value and
/// the box's rule it breaks (`--fix g_inf=1e-300` spent a minute on solves that could not
/// succeed, `--fix g_inf=1e300` said "0 tried").
#[test]
fn fix_outside_the_fit_box_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("d.csv"), "v0,cor\n0.5,0.5\n1,0.45\n2,0.4\n").unwrap();
    let rule = "leaves no material in the box the fit searches";
    for (fix, needle) in [
        (&["g_inf=1e-300"][..], "--fix g_inf = 1e-300 Pa leaves"),
        (&["g_inf=1e300"], "--fix g_inf = 1e300 Pa leaves"),
        (&["g_1=1e-300"], "g_inf/g_1 from 1e-7 to 1e4"),
        (&["eta=1e300"], "p3 from 1e-4 to 1e5 at these drops"),
        (
            &["g_inf=1e6", "g_1=1e20"],
            "--fix g_inf = 1e6 Pa with g_1 = 1e20 Pa leaves",
        ),
    ] {
        let mut args = vec!["fit", "d.csv", "--out", "res"];
        for f in fix {
            args.extend(["--fix", f]);
        }
        let o = run(&args, dir.path());
        assert_one_line_error(&o, rule);
        assert!(stderr(&o).contains(needle), "{}", stderr(&o));
        assert!(!dir.path().join("res").exists());
    }
    // fixed values are reported as given, not after a round trip through the fit's coordinates
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let drops = root.join("examples/data/drops.csv");
    let o = run(
        &[
            "fit",
            drops.to_str().unwrap(),
            "--fix",
            "g_inf=1e6",
            "--fix",
            "nu=0.45",
            "--out",
            "fixed",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let toml = std::fs::read_to_string(dir.path().join("fixed/fit.toml")).unwrap();
    assert!(toml.contains("g_inf = 1e6    # fixed"), "{toml}");
    assert!(toml.contains("poisson = 4.5e-1    # fixed"), "{toml}");
    // the box's own edge is inside it
    let o = run(
        &[
            "fit",
            "d.csv",
            "--fix",
            "g_inf=1e13",
            "--fix",
            "g_1=1e20",
            "--out",
            "res",
        ],
        dir.path(),
    );
    assert!(!stderr(&o).contains(rule), "{}", stderr(&o));
}

/// An empty relaxing bulk says what to write instead, without a Rust type name.
#[test]
fn empty_bulk_terms_get_a_plain_message() {
    let dir = tempfile::tempdir().unwrap();
    for form in [
        "k_inf = 1.0e9\nterms = []",
        "instantaneous = 1.0e9\nratios = []",
    ] {
        let material = format!(
            "[material.shear]\ng_inf = 1.0e6\nterms = [[1.0e7, 1.0e-4]]\n[material.bulk]\n{form}\n"
        );
        std::fs::write(dir.path().join("s.toml"), scene("5e-3", &material)).unwrap();
        let o = run(&["run", "s.toml"], dir.path());
        assert_one_line_error(&o, "[material.bulk]: no relaxing term");
        assert!(stderr(&o).contains("k_0 = 1e9"), "{}", stderr(&o));
        assert!(!stderr(&o).contains("::"), "{}", stderr(&o));
    }
}

/// A series longer than the documented limit is refused in one line naming where it was given
/// and the limit, inline and from a table file.
#[test]
fn prony_terms_have_a_limit() {
    use mdr_impact::io::prony_table::MAX_PRONY_TERMS;
    let dir = tempfile::tempdir().unwrap();
    let n = MAX_PRONY_TERMS + 1;
    let tau = |i: usize| 1e-6 * 1.01f64.powi(i as i32);
    let terms: Vec<String> = (0..n).map(|i| format!("[1.0e5, {:e}]", tau(i))).collect();
    let material = format!(
        "[material.shear]\ng_inf = 1.0e6\nterms = [{}]\n[material.bulk]\nincompressible = true\n",
        terms.join(", ")
    );
    std::fs::write(dir.path().join("s.toml"), scene("5e-3", &material)).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert_one_line_error(
        &o,
        &format!(
            "[material.shear] terms: {n} Prony terms exceed the limit of {MAX_PRONY_TERMS} terms"
        ),
    );
    let rows: String = (0..n).map(|i| format!("{:e},1e5\n", tau(i))).collect();
    std::fs::write(dir.path().join("t.csv"), format!("tau,modulus\n{rows}")).unwrap();
    let material = "[material.shear]\ng_inf = 1.0e6\nfile = \"t.csv\"\n[material.bulk]\n\
                    incompressible = true\n";
    std::fs::write(dir.path().join("s.toml"), scene("5e-3", material)).unwrap();
    let o = run(&["run", "s.toml"], dir.path());
    assert_one_line_error(&o, &format!("t.csv: {n} Prony terms exceed the limit"));
}

/// A file of blank lines is not called empty.
#[test]
fn blank_lines_only_are_not_an_empty_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("b.csv"), "\n\n").unwrap();
    let o = run(&["cor", "--input", "b.csv"], dir.path());
    assert_one_line_error(&o, "the file holds only 2 blank line(s)");
}

/// A full disk on stdout is the command's one-line error (exit 1), not a panic.
#[cfg(target_os = "linux")]
#[test]
fn a_full_stdout_is_an_error_not_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["run"][..],
        &["cor", "--nu", "0.45", "--p2", "0.01", "--p3", "1"][..],
    ] {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_mdr-impact"))
            .args(args)
            .current_dir(dir.path())
            .env("CI", "true")
            .stdout(std::fs::File::create("/dev/full").unwrap())
            .output()
            .unwrap();
        assert_one_line_error(&o, "<stdout>: No space left on device");
    }
}

/// An elastic standard solid (`g_1 = 0`) and a radius far below any ball: the summary holds
/// words where a ratio has no finite value, never `inf` or `NaN`.
#[test]
fn summaries_print_no_inf() {
    let dir = tempfile::tempdir().unwrap();
    let elastic = "[material]\ng_inf = 1.0e6\ng_1 = 0.0\neta = 500.0\npoisson = 0.49\n";
    for (radius, material, want) in [
        (
            "5e-3",
            elastic,
            "p2 unbounded (no relaxing branch: elastic)",
        ),
        ("1e-300", STANDARD, "d_max/R = above 1e308"),
    ] {
        std::fs::write(dir.path().join("s.toml"), scene(radius, material)).unwrap();
        let o = run(&["run", "s.toml"], dir.path());
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(out.contains(want), "{want}: {out}");
        let all = format!("{out}{}", stderr(&o));
        let words = all.split(|c: char| c.is_whitespace() || ",()=".contains(c));
        assert!(
            !words.into_iter().any(|w| w == "inf" || w == "NaN"),
            "{all}"
        );
    }
}

/// The validity of prescribed indentations and steep shapes: `indent` warns on stderr (its
/// stdout is the CSV), and a power law as steep as a sharp cone warns as the cone does.
#[test]
fn steep_shapes_and_deep_indentations_are_warned() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        &[
            "indent",
            "--history",
            "triangle",
            "--peak-time",
            "1",
            "--g-inf",
            "1e6",
            "--g1",
            "1e7",
            "--eta",
            "1e6",
            "--nu",
            "0.45",
            "--rate",
            "1e-4",
            "--radius",
            "1e-5",
            "--times",
            "0.5,1,1.5",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("warning: contact radius a_max/R = 3.162 exceeds 0.35"),
        "{}",
        stderr(&o)
    );
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("t_s,d_m,a_m,force_N\n"));
    let steep = "[indenter]\nmass = 4.11e-3\nshape = \"power-law\"\nexponent = 1\n\
                 coefficient = 2.0e4\n[impact]\nvelocity = 0.99\n";
    std::fs::write(dir.path().join("p.toml"), format!("{steep}{STANDARD}")).unwrap();
    let o = run(&["run", "p.toml"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("the power law's face has the slope"), "{out}");
}

/// An exact sphere far too small for its impact: the solvers' failure says why.
#[test]
fn an_exact_sphere_indented_past_its_radius_is_explained() {
    let dir = tempfile::tempdir().unwrap();
    let text = format!(
        "[indenter]\nmass = 4.11e-3\nshape = \"sphere\"\nradius = 1e-6\n[impact]\n\
         velocity = 0.99\n{STANDARD}"
    );
    std::fs::write(dir.path().join("e.toml"), text).unwrap();
    let o = run(&["run", "e.toml"], dir.path());
    assert_one_line_error(&o, "an exact sphere whose contact may reach its radius");
}

/// Groups whose canonical material leaves double precision are refused naming the groups (not
/// the canonical mass, radius and modulus of 1 that stand behind them).
#[test]
fn groups_beyond_double_precision_name_the_groups() {
    let dir = tempfile::tempdir().unwrap();
    for (p2, p3, want) in [
        (
            "1e200",
            "1e200",
            "groups: nu = 0.45, p2 = 1e200, p3 = 1e200 give a relaxation time",
        ),
        (
            "1e-300",
            "1e300",
            "groups: p2 = 1e-300: a glassy modulus 1/p2",
        ),
    ] {
        let o = run(&["cor", "--nu", "0.45", "--p2", p2, "--p3", p3], dir.path());
        assert_one_line_error(&o, want);
    }
}
