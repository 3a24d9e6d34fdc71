//! The binary's modules: flags ([`args`]), closed sets of values ([`values`]), one function per
//! subcommand ([`commands`]), and the outcomes that are the command line's own (a stale report,
//! a broken stress contract), with their exit code.

pub mod args;
pub mod commands;
pub mod values;

use std::path::PathBuf;

use mdr_impact::Error;

/// Why a command failed: a library error, or an outcome only the command line reports as a
/// failure. Every one is printed as one line and exits with code 1.
#[derive(Debug)]
pub enum Failure {
    /// An error of the library.
    Lib(Error),
    /// `validate --check`: the committed report differs from a fresh run.
    Stale {
        /// The report.
        report: PathBuf,
        /// First line that differs.
        line: usize,
    },
    /// `stress`: solves that broke the accuracy contract.
    ContractBroken {
        /// How many.
        problems: usize,
        /// The CSV that lists them.
        csv: PathBuf,
    },
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure::Lib(e)
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Lib(e) => write!(f, "{e}"),
            Failure::Stale { report, line } => write!(
                f,
                "{} is stale (first difference at line {line}): run `mdr-impact validate` and \
                 commit the result",
                report.display()
            ),
            Failure::ContractBroken { problems, csv } => write!(
                f,
                "stress: {problems} solves broke the contract (see {})",
                csv.display()
            ),
        }
    }
}

/// A command's result.
pub type Outcome = std::result::Result<(), Failure>;

/// Whether progress bars are drawn: stderr is a terminal and `CI` is not set.
fn show_progress() -> bool {
    use std::io::IsTerminal;
    std::io::stderr().is_terminal() && std::env::var_os("CI").is_none()
}

/// A progress bar of `len` units named `what`; hidden when [`show_progress`] says no.
pub fn progress_bar(len: u64, what: &str) -> indicatif::ProgressBar {
    if !show_progress() {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(len);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} {elapsed}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(what.to_string());
    bar
}

/// Run `work` with a progress bar of `len` units named `what`, ticked by the callback it gets.
pub fn with_progress<T>(len: u64, what: &str, work: impl FnOnce(&(dyn Fn() + Sync)) -> T) -> T {
    let bar = progress_bar(len, what);
    let out = work(&|| bar.inc(1));
    bar.finish_and_clear();
    out
}

/// Run `work` (one solve, which has no unit count) under a spinner with the elapsed time, named
/// `what`, drawn only where [`show_progress`] says so: a long `mdr` solve
/// shows that it is alive.
pub fn with_spinner<T>(what: &str, work: impl FnOnce() -> T) -> T {
    if !show_progress() {
        return work();
    }
    let spinner = indicatif::ProgressBar::new_spinner();
    if let Ok(style) = indicatif::ProgressStyle::with_template("{spinner} {msg} {elapsed}") {
        spinner.set_style(style);
    }
    spinner.set_message(what.to_string());
    spinner.enable_steady_tick(std::time::Duration::from_millis(250));
    let out = work();
    spinner.finish_and_clear();
    out
}

/// A clap error as one line (README: errors are one line on stderr): its lines joined, without
/// the "For more information" trailer.
pub fn one_line(e: &clap::Error) -> String {
    e.render()
        .to_string()
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("For more information"))
        .collect::<Vec<_>>()
        .join(" ")
}
