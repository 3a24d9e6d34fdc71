//! Readers of Prony tables as material-testing software exports them.
//!
//! A DMA or relaxation fit is commonly exported as a two-column CSV of the discrete spectrum,
//! one Maxwell branch per row, relaxation time first:
//!
//! ```text
//! tau,modulus
//! 1.0e-6,2.5e8
//! 1.0e-4,4.0e7
//! ```
//!
//! SI units (s, Pa). The relaxed modulus is not part of the table; a scene gives it beside the
//! file (`g_inf` or `k_inf`). Lines and fields follow the rules of the `cor --input` reader
//! ([`crate::io::lines`]): UTF-8 with an optional byte-order mark, `\n`, `\r\n` or `\r`
//! line ends, trimmed and optionally quoted fields; empty lines are skipped here.

use std::path::Path;

use crate::error::{Error, Result};
use crate::io::lines::parse_numeric;

/// The most terms one Prony series of a scene may have (`terms`, `ratios` or a table `file`, in
/// shear and in bulk each). The cost of a solve grows faster than linearly with the terms of
/// `G_eq` (5000 terms took nearly 5 minutes), and published series of real polymers have a few
/// dozen (30 for polyisobutylene, 24 for the epoxy of `scenes/`); a longer series is refused
/// with [`Error::TooManyPronyTerms`] rather than left to run without a word.
pub const MAX_PRONY_TERMS: usize = 1000;

/// [`Error::TooManyPronyTerms`] when a series named `field` has more than [`MAX_PRONY_TERMS`]
/// terms.
pub fn check_term_count(field: &str, terms: usize) -> Result<()> {
    match terms > MAX_PRONY_TERMS {
        true => Err(Error::TooManyPronyTerms {
            field: field.to_string(),
            terms,
            max: MAX_PRONY_TERMS,
        }),
        false => Ok(()),
    }
}

/// The header of a Prony table file.
pub const PRONY_HEADER: [&str; 2] = ["tau", "modulus"];

/// Read a `tau,modulus` table from a file; see [`parse_prony_table`].
pub fn read_prony_table(path: &Path) -> Result<Vec<(f64, f64)>> {
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    parse_prony_table(&path.display().to_string(), &bytes)
}

/// Parse the bytes of a `tau,modulus` table named `file` (the name is used in messages) into
/// `(modulus` (Pa), `tau` (s)`)` pairs in file order, the order of
/// [`crate::model::material::rheology::ShearProny::new`] and [`crate::model::material::rheology::BulkProny::new`].
///
/// Every row needs exactly two finite numbers, `tau > 0` and `modulus >= 0`; a bad row is an
/// [`Error::Csv`] naming its physical line. At least one row is required, at most
/// [`MAX_PRONY_TERMS`].
///
/// ```
/// # use mdr_impact::io::prony_table::parse_prony_table;
/// let t = parse_prony_table("t.csv", b"tau,modulus\r\n1e-3,2e6\n\n0.1,5e5\n").unwrap();
/// assert_eq!(t, vec![(2e6, 1e-3), (5e5, 0.1)]);
/// assert!(parse_prony_table("t.csv", b"tau,modulus\n1e-3,-2e6\n").is_err());
/// ```
pub fn parse_prony_table(file: &str, bytes: &[u8]) -> Result<Vec<(f64, f64)>> {
    let bad = |line: u64, message: String| Error::Csv {
        file: file.to_string(),
        line,
        message,
    };
    let table = parse_numeric(file, bytes, &PRONY_HEADER)?;
    check_term_count(file, table.rows.len())?;
    let mut out = Vec::with_capacity(table.rows.len());
    for r in &table.rows {
        let (tau, modulus) = (r.values[0], r.values[1]);
        if !(tau > 0.0) {
            return Err(bad(
                r.line,
                format!("tau = {tau:e} is out of range: allowed 0 < tau < inf (s)"),
            ));
        }
        if !(modulus >= 0.0) {
            return Err(bad(
                r.line,
                format!("modulus = {modulus:e} is out of range: allowed 0 <= modulus < inf (Pa)"),
            ));
        }
        out.push((modulus, tau));
    }
    if out.is_empty() {
        return Err(bad(1, "no rows after the header 'tau,modulus'".into()));
    }
    Ok(out)
}
