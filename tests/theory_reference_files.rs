//! The committed reference files (`reference/`) equal what the code produces now.
//!
//! Regenerate with `cargo test --test suite theory_reference_files:: -- --ignored` (or, once wired,
//! `mdr-impact reference --out reference`).

use mdr_impact::solvers::theory::generate_reference;
use std::path::{Path, PathBuf};

/// Relative tolerance per column (scaled by the column's largest magnitude): the generators are
/// deterministic; this only absorbs last-bit differences across platforms and compilers.
const FILE_RTOL: f64 = 1e-9;

fn committed() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("reference")
}

fn parse(path: &Path) -> (String, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header = lines.next().unwrap().to_string();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse::<f64>().unwrap()).collect())
        .collect();
    (header, rows)
}

/// Every file named in the committed manifest matches a fresh generation (same header, same
/// number of rows, every number within FILE_RTOL of its column scale); the manifest lists every
/// generated file.
#[test]
fn committed_files_are_current() {
    let tmp = tempfile::tempdir().unwrap();
    let written = generate_reference(tmp.path()).unwrap();
    let manifest: toml::Table =
        toml::from_str(&std::fs::read_to_string(committed().join("manifest.toml")).unwrap())
            .unwrap();
    let listed: Vec<String> = manifest["file"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["name"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(listed.len(), written.files.len());
    for f in &written.files {
        let name = f.file_name().unwrap().to_str().unwrap();
        assert!(
            listed.iter().any(|l| l == name),
            "{name} missing from manifest"
        );
        let (h_new, new) = parse(f);
        let (h_old, old) = parse(&committed().join(name));
        assert_eq!(h_new, h_old, "{name}");
        assert_eq!(new.len(), old.len(), "{name}: row count");
        let ncol = new[0].len();
        for c in 0..ncol {
            let scale = old
                .iter()
                .map(|r| r[c].abs())
                .fold(0.0, f64::max)
                .max(1e-300);
            for (i, (a, b)) in new.iter().zip(&old).enumerate() {
                assert!(
                    (a[c] - b[c]).abs() <= FILE_RTOL * scale,
                    "{name} row {i} col {c}: {} vs {}",
                    a[c],
                    b[c]
                );
            }
        }
    }
}

/// Rewrites `reference/` from the current code.
#[test]
#[ignore = "regenerates the committed reference files"]
fn regenerate() {
    let w = generate_reference(&committed()).unwrap();
    assert!(w.manifest.exists());
    assert!(!w.files.is_empty());
}
