//! `validate --check` and `validate`: compare the committed report with a fresh run, or write
//! it keeping the sections other commands fill.

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

use crate::io::output::write_atomic;
// the report's building blocks, re-exported where the validation tables have always been
use crate::report::sections::{keep_generated, without_generated};

use super::*;

/// Folder of the committed figures, as the committed report links them.
pub const FIGURE_DIR: &str = "validation";

/// Whether a committed report matches a fresh run (outside the sections other commands fill).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Staleness {
    /// Identical.
    Current,
    /// Different: the first line that differs (1-based, in the text without the filled
    /// sections) and that line in each version (empty past the end).
    Stale {
        /// 1-based line number.
        line: usize,
        /// The committed line.
        committed: String,
        /// The fresh line.
        fresh: String,
    },
}

/// Compare a fresh rendering with the committed report, ignoring the bodies of the sections that
/// other commands fill ([`FILLED`]).
pub fn staleness(fresh: &str, committed: &str) -> Staleness {
    let (f, c) = (without_generated(fresh), without_generated(committed));
    if f == c {
        return Staleness::Current;
    }
    let (mut fl, mut cl) = (f.lines(), c.lines());
    let mut line = 1;
    loop {
        match (fl.next(), cl.next()) {
            (Some(a), Some(b)) if a == b => line += 1,
            (a, b) => {
                return Staleness::Stale {
                    line,
                    committed: b.unwrap_or_default().to_string(),
                    fresh: a.unwrap_or_default().to_string(),
                }
            }
        }
    }
}

/// The per-regime accuracy table of a rendered report (what `validate` prints).
pub fn per_regime(markdown: &str) -> Option<&str> {
    let b = markdown.find("### Per regime")?;
    let e = markdown.find("### Per case")?;
    (b < e).then(|| markdown[b..e].trim_end())
}

/// What [`check()`] found: the fresh rendering (figure links as committed) and how the report
/// compares with it.
#[derive(Debug, Clone, PartialEq)]
pub struct Checked {
    /// The fresh report.
    pub fresh: String,
    /// The comparison with the committed one.
    pub staleness: Staleness,
}

/// `validate --check`: run the validation with its figures in a scratch folder and compare the
/// report at `report` (missing: empty) with it. `tick` as for [`run`].
pub fn check(report: &Path, tick: &(dyn Fn() + Sync)) -> Result<Checked> {
    let scratch = tempfile::tempdir().map_err(|e| Error::io(std::env::temp_dir(), e))?;
    let opts = ValidateOptions {
        figure_dir: scratch.path().to_path_buf(),
        markdown_dir: report.parent().map(PathBuf::from).unwrap_or_default(),
    };
    let fresh = run(&opts, tick)?.replace(&opts.figure_dir.display().to_string(), FIGURE_DIR);
    let committed = std::fs::read_to_string(report).unwrap_or_default();
    let staleness = staleness(&fresh, &committed);
    Ok(Checked { fresh, staleness })
}

/// `validate`: run the validation, write its figures into `figure_dir` and the report to
/// `report`, keeping the bodies of the sections other commands fill. Returns the fresh report.
pub fn regenerate(report: &Path, figure_dir: &Path, tick: &(dyn Fn() + Sync)) -> Result<String> {
    let opts = ValidateOptions {
        figure_dir: figure_dir.to_path_buf(),
        markdown_dir: report.parent().map(PathBuf::from).unwrap_or_default(),
    };
    let fresh = run(&opts, tick)?;
    let existing = std::fs::read_to_string(report).unwrap_or_default();
    let text = keep_generated(&fresh, &existing);
    write_atomic(report, |w| {
        w.write_all(text.as_bytes())
            .map_err(|e| Error::io(report, e))
    })?;
    Ok(fresh)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::sections::{replace_filled, STRESS};

    const COMMITTED: &str = include_str!("../../../VALIDATION.md");

    #[test]
    fn a_tampered_number_makes_the_report_stale_at_its_line() {
        assert_eq!(staleness(COMMITTED, COMMITTED), Staleness::Current);
        // change the first table cell of the accuracy tables
        let at = COMMITTED.find("| ").expect("a table");
        let line = COMMITTED[..at].lines().count() + 1;
        let mut tampered = COMMITTED.to_string();
        tampered.insert(at + 2, '9');
        match staleness(&tampered, COMMITTED) {
            Staleness::Stale {
                line: l,
                committed,
                fresh,
            } => {
                assert_eq!(l, line);
                assert_eq!(fresh.replacen("| 9", "| ", 1), committed);
            }
            Staleness::Current => panic!("tampering not seen"),
        }
        // a missing report is stale at line 1
        assert!(matches!(
            staleness(COMMITTED, ""),
            Staleness::Stale { line: 1, .. }
        ));
    }

    #[test]
    fn the_filled_sections_do_not_count() {
        let other = replace_filled(COMMITTED, &STRESS, "another machine's run\n").unwrap();
        assert_ne!(other, COMMITTED);
        assert_eq!(staleness(&other, COMMITTED), Staleness::Current);
        assert!(per_regime(COMMITTED).is_some_and(|t| t.starts_with("### Per regime")));
    }
}
