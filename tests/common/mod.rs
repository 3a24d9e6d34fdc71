//! Helpers of the integration tests that run the command line.

use std::path::Path;
use std::process::{Command, Output};

/// Run `mdr-impact` with `args` in `dir`, with `CI` set (no progress bars).
pub fn run(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mdr-impact"))
        .args(args)
        .current_dir(dir)
        .env("CI", "1")
        .output()
        .unwrap()
}

/// The standard error of a run, as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).to_string()
}
