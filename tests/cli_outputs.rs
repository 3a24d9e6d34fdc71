//! The files a run writes: only when asked, where the scene says (relative to the scene file),
//! with the usual permissions, all or none, never replacing what is not a regular file; and
//! which solver answered and why.

use crate::common;

use std::path::Path;

use common::{run, stderr};

/// The default scene's sphere and material, without `[solver]` or `[output]`.
const BASE: &str = "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n[impact]\nvelocity = 0.99\n\
                    [material]\ng_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\npoisson = 0.49\n";

/// `BASE` with an `[output]` table of `history` and `plot`.
fn scene_with_output(history: &str, plot: &str) -> String {
    format!("{BASE}[output]\nhistory = \"{history}\"\nplot = \"{plot}\"\n")
}

fn assert_refused(o: &std::process::Output, needles: &[&str]) {
    assert_eq!(o.status.code(), Some(1), "{}", stderr(o));
    let e = stderr(o);
    assert_eq!(e.trim_end().lines().count(), 1, "not one line: {e}");
    for n in needles {
        assert!(e.contains(n), "'{n}' not in: {e}");
    }
}

/// Every file and folder below `dir`, relative, sorted.
fn listing(dir: &Path) -> Vec<String> {
    fn walk(root: &Path, dir: &Path, out: &mut Vec<String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            out.push(p.strip_prefix(root).unwrap().display().to_string());
            if p.is_dir() && !p.is_symlink() {
                walk(root, &p, out);
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, dir, &mut out);
    out.sort();
    out
}

/// `auto` says why its solver answered, the same in the text and in JSON `fallback`.
#[test]
fn auto_says_which_solver_answered_and_why() {
    let dir = tempfile::tempdir().unwrap();
    // no history: fast, no fallback
    let o = run(&["run"], dir.path());
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("solver                      fast\n"), "{out}");
    assert!(
        out.contains("  chosen by auto            no force history"),
        "{out}"
    );
    // a history: reference, and JSON `fallback` says why auto did not answer with fast
    let o = run(&["run", "--json", "--out", "res"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["solver"], "reference");
    let why = v["fallback"].as_str().unwrap();
    assert!(why.contains("force history was requested"), "{why}");
    assert_eq!(v["solver_reason"], v["fallback"]);
    let o = run(&["run", "--out", "res"], dir.path());
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains(&format!("  chosen by auto            {why}\n")),
        "{out}"
    );
    // an elastic material: the Hertz closed form, whatever was asked
    let elastic = BASE.replace("eta = 500.0", "eta = 0.0");
    std::fs::write(
        dir.path().join("e.toml"),
        elastic + "[solver]\nname = \"mdr\"\n",
    )
    .unwrap();
    let o = run(&["run", "e.toml", "--json"], dir.path());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["solver"], "hertz");
    assert_eq!(v["requested_solver"], "mdr");
    assert!(v["fallback"].is_null(), "not auto: {v}");
    assert!(v["solver_reason"].as_str().unwrap().contains("elastic"));
    let o = run(&["run", "e.toml"], dir.path());
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains("work                        none (closed form)"),
        "{out}"
    );
}

/// The work line names only the counters of the solver that answered.
#[test]
fn work_line_shows_the_solvers_own_counters() {
    let dir = tempfile::tempdir().unwrap();
    for (solver, has, lacks) in [
        (
            "fast",
            &["steps", "evaluations"][..],
            &["element", "level"][..],
        ),
        (
            "reference",
            &["steps", "evaluations", "level"][..],
            &["element"][..],
        ),
        (
            "mdr",
            &["steps", "elements", "element updates", "level"][..],
            &["evaluation"][..],
        ),
    ] {
        let text = format!("{BASE}[solver]\nname = \"{solver}\"\nrtol = 1e-4\n");
        std::fs::write(dir.path().join("s.toml"), text).unwrap();
        let o = run(&["run", "s.toml"], dir.path());
        assert!(o.status.success(), "{solver}: {}", stderr(&o));
        let out = String::from_utf8(o.stdout).unwrap();
        let work = out.lines().find(|l| l.starts_with("work ")).unwrap();
        for h in has {
            assert!(work.contains(h), "{solver}: '{h}' not in {work}");
        }
        for l in lacks {
            assert!(!work.contains(l), "{solver}: '{l}' in {work}");
        }
    }
}

/// `[output]` paths are relative to the scene file, like a Prony table `file`.
#[test]
fn output_paths_are_relative_to_the_scene_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("scenes")).unwrap();
    std::fs::write(
        dir.path().join("scenes/s.toml"),
        scene_with_output("out/h.csv", "out/f.svg"),
    )
    .unwrap();
    let o = run(&["run", "scenes/s.toml"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("scenes/out/h.csv"), "{out}");
    assert_eq!(
        listing(dir.path()),
        [
            "scenes",
            "scenes/out",
            "scenes/out/f.svg",
            "scenes/out/force_indentation.svg",
            "scenes/out/h.csv",
            "scenes/s.toml"
        ]
    );
}

/// New files get `0666` less the umask, like any other program's (not a temporary file's 0600).
#[cfg(unix)]
#[test]
fn files_honour_the_umask() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    for (umask, mode) in [("022", 0o644), ("002", 0o664), ("077", 0o600)] {
        let out = format!("res{umask}");
        let o = std::process::Command::new("sh")
            .arg("-c")
            .arg(format!("umask {umask} && exec \"$0\" run --out {out}",))
            .arg(env!("CARGO_BIN_EXE_mdr-impact"))
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
        for f in ["history.csv", "force.svg", "force_indentation.svg"] {
            let m = std::fs::metadata(dir.path().join(&out).join(f)).unwrap();
            assert_eq!(m.permissions().mode() & 0o777, mode, "umask {umask}: {f}");
        }
    }
}

/// An existing output path that is not a regular file is refused, not replaced; the message
/// names the key and the path, and no file of the run is written.
#[cfg(unix)]
#[test]
fn non_regular_output_paths_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::os::unix::fs::symlink("target.csv", d.join("link.csv")).unwrap();
    std::fs::create_dir(d.join("folder.csv")).unwrap();
    let fifo = std::process::Command::new("mkfifo")
        .arg(d.join("fifo.csv"))
        .status()
        .is_ok_and(|s| s.success());
    let mut cases = vec![("link.csv", "a symbolic link"), ("folder.csv", "a folder")];
    if fifo {
        cases.push(("fifo.csv", "not a regular file"));
    }
    for (path, what) in cases {
        std::fs::write(d.join("s.toml"), scene_with_output(path, "new/f.svg")).unwrap();
        let before = listing(d);
        let o = run(&["run", "s.toml"], d);
        assert_refused(
            &o,
            &[&format!("[output] history = {path}: exists and is {what}")],
        );
        assert_eq!(listing(d), before, "{path}");
        assert!(!d.join("target.csv").exists());
    }
}

/// Two outputs at one path, and a file used as a folder, are refused before anything is
/// written, naming the key and the path.
#[test]
fn clashing_output_paths_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (history, plot, needle) in [
        (
            "same.svg",
            "./same.svg",
            "[output] plot = ./same.svg: the same file as [output] history = same.svg",
        ),
        (
            "h.csv",
            "s.toml/f.svg",
            "[output] plot = s.toml/f.svg: s.toml is a file, not a folder",
        ),
        (
            "new/h.csv",
            "new/force_indentation.svg",
            "[output] plot = new/force_indentation.svg: the same file as [output] plot",
        ),
    ] {
        std::fs::write(d.join("s.toml"), scene_with_output(history, plot)).unwrap();
        let o = run(&["run", "s.toml"], d);
        assert_refused(&o, &[needle]);
        assert_eq!(listing(d), ["s.toml"], "{history} {plot}");
    }
}

/// A run whose second file cannot be written leaves neither its first file nor the folders it
/// created.
#[test]
fn a_failed_run_leaves_none_of_its_files() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("blocker"), "a file").unwrap();
    std::fs::write(
        d.join("s.toml"),
        scene_with_output("a/b/h.csv", "blocker/x/f.svg"),
    )
    .unwrap();
    let o = run(&["run", "s.toml"], d);
    assert_refused(&o, &["[output] plot = blocker/x/f.svg: blocker is a file"]);
    assert_eq!(listing(d), ["blocker", "s.toml"]);
    // a folder that cannot be created is found only while writing: the history staged (and
    // its folders created) before is removed again
    if Path::new("/proc/self").exists() {
        std::fs::write(
            d.join("s.toml"),
            scene_with_output("a/b/h.csv", "/proc/self/none/f.svg"),
        )
        .unwrap();
        let o = run(&["run", "s.toml"], d);
        assert_refused(
            &o,
            &["[output] plot = /proc/self/none/f.svg: cannot create"],
        );
        assert_eq!(listing(d), ["blocker", "s.toml"]);
    }
}

#[test]
fn a_closed_pipe_ends_the_output_quietly() {
    // `mdr-impact cor --input big.csv | head -1`: the reader leaves after one line; no panic
    // message ("failed printing to stdout") and no error line, whatever the exit status
    use std::io::{BufRead, BufReader, Write};
    use std::process::{Command, Stdio};
    let dir = std::env::temp_dir().join(format!("mdr-pipe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let input = dir.join("groups.csv");
    let mut f = std::fs::File::create(&input).unwrap();
    writeln!(f, "nu,p2,p3").unwrap();
    for i in 0..4000 {
        writeln!(f, "0.3,{},{}", 0.01 + 1e-5 * i as f64, 0.5).unwrap();
    }
    drop(f);
    let mut child = Command::new(env!("CARGO_BIN_EXE_mdr-impact"))
        .args(["cor", "--input", input.to_str().unwrap()])
        .env("CI", "1")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(first.starts_with("nu,p2,p3,cor"), "{first}");
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked") && !err.contains("error"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}
