//! The sections of VALIDATION.md that commands other than `validate` fill (stress, bench,
//! the Python timing, fit-study): their markers, and how a report keeps, strips and replaces them.

use std::path::Path;

use crate::error::{Error, Result};
use crate::io::output::write_atomic;

/// Put the body of the section `begin` ... `end` of `existing` into `fresh` (unchanged when
/// either lacks the markers).
pub fn keep_section(fresh: &str, existing: &str, begin: &str, end: &str) -> String {
    match (
        existing.find(begin),
        existing.find(end),
        fresh.find(begin),
        fresh.find(end),
    ) {
        (Some(eb), Some(ee), Some(fb), Some(fe)) if eb < ee && fb < fe => {
            format!("{}{}{}", &fresh[..fb], &existing[eb..ee], &fresh[fe..])
        }
        _ => fresh.to_string(),
    }
}

/// Replace the body of the section `begin` ... `end` (called `name` in the error) of `existing`
/// with `section`.
pub fn replace_section(
    existing: &str,
    begin: &str,
    end: &str,
    name: &str,
    section: &str,
) -> Result<String> {
    match (existing.find(begin), existing.find(end)) {
        (Some(b), Some(e)) if b < e => Ok(format!(
            "{}{begin}\n{section}{}",
            &existing[..b],
            &existing[e..]
        )),
        _ => Err(Error::NotSupported {
            solver: "report",
            what: format!("no {name} markers ({begin} ... {end}); run `mdr-impact validate` first"),
        }),
    }
}

/// Strip the body of the section `begin` ... `end` (the markers' positions are kept).
pub fn without_section(s: &str, begin: &str, end: &str) -> String {
    match (s.find(begin), s.find(end)) {
        (Some(b), Some(e)) if b < e => format!("{}{}", &s[..b], &s[e..]),
        _ => s.to_string(),
    }
}

/// A section of VALIDATION.md that a command other than `validate` fills (its numbers are
/// machine dependent or take minutes): `validate` writes a placeholder for it, keeps the existing
/// body when it regenerates the file, and leaves it out of the staleness check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FilledSection {
    /// Marker key: the body sits between `<!-- KEY:begin -->` and `<!-- KEY:end -->`.
    pub key: &'static str,
    /// The section's heading (without `## `).
    pub heading: &'static str,
    /// The command that fills it.
    pub command: &'static str,
}

impl FilledSection {
    /// Marker opening the section.
    pub fn begin(&self) -> String {
        format!("<!-- {}:begin -->", self.key)
    }
    /// Marker closing the section.
    pub fn end(&self) -> String {
        format!("<!-- {}:end -->", self.key)
    }
    /// The section as `validate` writes it before its command has run.
    pub fn placeholder(&self) -> String {
        format!(
            "\n## {}\n\n{}\nRun `{}` to fill this section.\n{}\n",
            self.heading,
            self.begin(),
            self.command,
            self.end()
        )
    }
}

/// The stress section, filled by `mdr-impact stress`.
pub const STRESS: FilledSection = FilledSection {
    key: "stress",
    heading: "8. Stress test: every answer within rtol or refused",
    command: "mdr-impact stress",
};

/// The performance section, filled by `mdr-impact bench`.
pub const PERFORMANCE: FilledSection = FilledSection {
    key: "performance",
    heading: "9. Performance",
    command: "mdr-impact bench",
};

/// The Python package's timing against the command line, filled by `python/bench_cor.py`.
pub const PYTHON: FilledSection = FilledSection {
    key: "python",
    heading: "10. Python package: `cor` against `cor --input`",
    command: "python python/bench_cor.py --report VALIDATION.md",
};

/// The round trip of `fit`, filled by `mdr-impact fit-study`.
pub const FIT_STUDY: FilledSection = FilledSection {
    key: "fit-study",
    heading: "11. Fitting drop tests: round trip",
    command: "mdr-impact fit-study --reps 200 --report VALIDATION.md",
};

/// The fit study across the parameter box, filled by `mdr-impact fit-study --box`.
pub const FIT_BOX: FilledSection = FilledSection {
    key: "fit-box",
    heading: "11b. Fitting drop tests across the parameter box",
    command: "mdr-impact fit-study --box --report VALIDATION.md",
};

/// Every section filled by another command, in the order of the report.
pub const FILLED: &[FilledSection] = &[STRESS, PERFORMANCE, PYTHON, FIT_STUDY, FIT_BOX];

/// Keep the bodies of the sections that other commands fill ([`FILLED`]) when `fresh` replaces
/// `existing`.
pub fn keep_generated(fresh: &str, existing: &str) -> String {
    FILLED.iter().fold(fresh.to_string(), |acc, f| {
        keep_section(&acc, existing, &f.begin(), &f.end())
    })
}

/// Strip the bodies of the sections that other commands fill (for the staleness check).
pub fn without_generated(s: &str) -> String {
    FILLED.iter().fold(s.to_string(), |acc, f| {
        without_section(&acc, &f.begin(), &f.end())
    })
}

/// Replace the body of the filled section `f` of `existing` with `section`.
pub fn replace_filled(existing: &str, f: &FilledSection, section: &str) -> Result<String> {
    replace_section(existing, &f.begin(), &f.end(), f.key, section)
}

/// Check that the report at `path` has the markers of `section`, and return its text (so that a
/// long command fails on a missing report before its work, not after).
pub fn require_section(path: &Path, section: &FilledSection) -> Result<String> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    replace_filled(&text, section, "").map_err(|e| e.at(path.display().to_string()))?;
    Ok(text)
}

/// Replace the body of `section` of the report at `path` with `text` and write the report
/// atomically (read, replace, write): the one way every command updates its section.
pub fn update_section(path: &Path, section: &FilledSection, text: &str) -> Result<()> {
    let existing = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    let updated =
        replace_filled(&existing, section, text).map_err(|e| e.at(path.display().to_string()))?;
    write_atomic(path, |w| {
        w.write_all(updated.as_bytes())
            .map_err(|e| Error::io(path, e))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_sections_are_kept_and_ignored_by_the_check() {
        let (sb, se, pb, pe) = (
            STRESS.begin(),
            STRESS.end(),
            PERFORMANCE.begin(),
            PERFORMANCE.end(),
        );
        let fresh = format!("a\n{sb}\nrun stress\n{se}\nb\n{pb}\nrun bench\n{pe}\nc\n");
        let existing = format!("old a\n{sb}\nstress table\n{se}\nb\n{pb}\ntimes\n{pe}\nc\n");
        let kept = keep_generated(&fresh, &existing);
        assert_eq!(
            kept,
            format!("a\n{sb}\nstress table\n{se}\nb\n{pb}\ntimes\n{pe}\nc\n")
        );
        assert_eq!(without_generated(&kept), without_generated(&fresh));
        assert_ne!(without_generated(&existing), without_generated(&fresh));
        let replaced = replace_filled(&kept, &STRESS, "new\n").unwrap();
        assert!(replaced.contains(&format!("{sb}\nnew\n{se}")));
        assert_eq!(without_generated(&replaced), without_generated(&fresh));
        assert!(matches!(
            replace_filled("no markers", &STRESS, "x"),
            Err(Error::NotSupported {
                solver: "report",
                ..
            })
        ));
    }

    #[test]
    fn update_section_replaces_one_body_and_keeps_the_rest() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("R.md");
        let (b, e) = (PERFORMANCE.begin(), PERFORMANCE.end());
        std::fs::write(&path, format!("# R\n{b}\nold\n{e}\ntail\n")).unwrap();
        assert!(require_section(&path, &PERFORMANCE).is_ok());
        update_section(&path, &PERFORMANCE, "new\n").unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(text, format!("# R\n{b}\nnew\n{e}\ntail\n"));
        // a section the file does not have: typed refusal, file untouched
        let e = update_section(&path, &STRESS, "x").unwrap_err();
        assert!(e.to_string().contains("no stress markers"), "{e}");
        assert!(require_section(&path, &STRESS).is_err());
        assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
        // a missing file: an I/O error naming it
        let missing = dir.path().join("none.md");
        assert!(matches!(
            update_section(&missing, &STRESS, "x"),
            Err(Error::Io { .. })
        ));
    }
}
