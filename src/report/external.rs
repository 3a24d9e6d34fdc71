//! The external reference: CoR tables computed by an independent SciPy solution of the
//! Lee–Radok/Ting impact (`reference/external/`, provenance in its README), embedded at build time,
//! and their parser.

use crate::error::{Error, Result};

/// One row of the external reference table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExternalRow {
    /// Static Poisson ratio.
    pub nu: f64,
    /// `p2`.
    pub p2: f64,
    /// `p3`.
    pub p3: f64,
    /// CoR.
    pub cor: f64,
    /// Contact time (canonical).
    pub contact_time: f64,
    /// Maximum indentation (canonical).
    pub max_indentation: f64,
    /// The generator's own error estimate of the CoR (relative).
    pub est_rel_err: f64,
}

/// The external reference table, embedded at build time (`reference/external/cor_python.csv`):
/// a grid over the paper's range and beyond, and 100 random points.
pub const EXTERNAL_TABLE: &str = include_str!("../../reference/external/cor_python.csv");

/// Its second part (`reference/external/cor_python_corner.csv`): the most dissipative corner of
/// the range (CoR down to 5.5e-4), random points, its edge and the points where an earlier
/// `fast` missed its tolerance.
pub const EXTERNAL_CORNER_TABLE: &str =
    include_str!("../../reference/external/cor_python_corner.csv");

/// Its third part (`reference/external/cor_python_glassy.csv`), kept apart from the rows of
/// [`external_rows`]: the glassy corner, `p2` from 1.3e-8 to 1e-6 (`G_0 / G_inf` up to 8e7),
/// where a stress run found `fast` and `reference` disagreeing beyond rtol 1e-10.
pub const EXTERNAL_GLASSY_TABLE: &str =
    include_str!("../../reference/external/cor_python_glassy.csv");

/// The rows of [`EXTERNAL_GLASSY_TABLE`].
pub fn external_glassy_rows() -> Result<Vec<ExternalRow>> {
    parse_external(
        EXTERNAL_GLASSY_TABLE,
        "reference/external/cor_python_glassy.csv",
    )
}

/// Parse the external reference tables: the rows of [`EXTERNAL_TABLE`], then those of
/// [`EXTERNAL_CORNER_TABLE`].
pub fn external_rows() -> Result<Vec<ExternalRow>> {
    let mut out = parse_external(EXTERNAL_TABLE, "reference/external/cor_python.csv")?;
    out.extend(parse_external(
        EXTERNAL_CORNER_TABLE,
        "reference/external/cor_python_corner.csv",
    )?);
    Ok(out)
}

fn parse_external(table: &str, file: &str) -> Result<Vec<ExternalRow>> {
    let mut rdr = csv::Reader::from_reader(table.as_bytes());
    let mut out = Vec::new();
    for (i, rec) in rdr.records().enumerate() {
        let bad = |m: String| Error::Csv {
            file: file.into(),
            line: i as u64 + 2,
            message: m,
        };
        let rec = rec.map_err(|e| bad(e.to_string()))?;
        let mut v = [0.0; 7];
        for (j, x) in v.iter_mut().enumerate() {
            *x = rec
                .get(j)
                .and_then(|s| s.parse().ok())
                .ok_or_else(|| bad(format!("column {} is not a number", j + 1)))?;
        }
        out.push(ExternalRow {
            nu: v[0],
            p2: v[1],
            p3: v[2],
            cor: v[3],
            contact_time: v[4],
            max_indentation: v[5],
            est_rel_err: v[6],
        });
    }
    Ok(out)
}
