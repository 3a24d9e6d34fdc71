//! Many impacts at once from dimensionless groups: the `cor --input FILE.csv` job.
//!
//! Input: CSV with a header and exactly the columns `nu,p2,p3` (`nu = 0.5`: incompressible).
//! Output: the input columns, then `cor,contact_time,max_indentation` in canonical units
//! (`m = R = v0 = G_inf = 1`), rows in input order, computed in parallel.

use rayon::prelude::*;
use std::io::Write;
use std::path::Path;

use crate::error::{Error, Result};
use crate::impact::{Groups, Impact, Outcome};
use crate::output::fmt;
use crate::solver::{solve, SolveOptions};

/// One input row: its 1-based line number, the original text of its fields and the groups.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// 1-based line number in the file (the header is line 1).
    pub line: u64,
    /// The three fields as written.
    pub text: [String; 3],
    /// The parsed, validated groups.
    pub groups: Groups,
}

/// Read `nu,p2,p3` rows; any bad row is an error naming its line.
pub fn read_rows(path: &Path) -> Result<Vec<Row>> {
    let file = path.display().to_string();
    let bad = |line: u64, message: String| Error::Csv {
        file: file.clone(),
        line,
        message,
    };
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_path(path)
        .map_err(|e| Error::io(path, e))?;
    let header = rdr.headers().map_err(|e| bad(1, e.to_string()))?.clone();
    let names: Vec<&str> = header.iter().collect();
    if names != ["nu", "p2", "p3"] {
        return Err(bad(
            1,
            format!("header must be 'nu,p2,p3', found '{}'", names.join(",")),
        ));
    }
    let mut rows = Vec::new();
    for rec in rdr.records() {
        let rec = rec.map_err(|e| {
            let line = e.position().map_or(0, |p| p.line());
            bad(line, e.to_string())
        })?;
        let line = rec.position().map_or(0, |p| p.line());
        let mut v = [0.0; 3];
        for (j, name) in ["nu", "p2", "p3"].iter().enumerate() {
            let s = rec.get(j).unwrap_or("");
            v[j] = s
                .parse::<f64>()
                .map_err(|_| bad(line, format!("{name} = '{s}' is not a number")))?;
        }
        let groups = Groups::new(v[0], v[1], v[2]).map_err(|e| bad(line, e.to_string()))?;
        rows.push(Row {
            line,
            text: [rec[0].to_string(), rec[1].to_string(), rec[2].to_string()],
            groups,
        });
    }
    Ok(rows)
}

/// Solve every row in parallel (rayon); the first failing row (in input order) is the error.
pub fn solve_rows(file: &str, rows: &[Row], opts: &SolveOptions) -> Result<Vec<Outcome>> {
    let results: Vec<Result<Outcome>> = rows
        .par_iter()
        .map(|row| {
            Impact::from_groups(row.groups)
                .and_then(|imp| solve(&imp, opts))
                .map_err(|e| Error::Csv {
                    file: file.to_string(),
                    line: row.line,
                    message: e.to_string(),
                })
        })
        .collect();
    results.into_iter().collect()
}

/// Write the result table as CSV.
pub fn write_results(w: &mut dyn Write, rows: &[Row], outcomes: &[Outcome]) -> Result<()> {
    let mut c = csv::Writer::from_writer(w);
    let io = |e: csv::Error| Error::io("<stdout>", e);
    c.write_record(["nu", "p2", "p3", "cor", "contact_time", "max_indentation"])
        .map_err(io)?;
    for (r, o) in rows.iter().zip(outcomes) {
        c.write_record([
            r.text[0].as_str(),
            r.text[1].as_str(),
            r.text[2].as_str(),
            &fmt(o.cor),
            &fmt(o.contact_time),
            &fmt(o.max_indentation),
        ])
        .map_err(io)?;
    }
    c.flush().map_err(|e| Error::io("<stdout>", e))?;
    Ok(())
}

/// `n` pseudo-random rows over the paper's range (nu in (-1, 0.5], log10 p2 in [-4, 2],
/// log10 p3 in [-3, 4]), reproducible from `seed` (for benchmarks).
pub fn random_rows(n: usize, seed: u64) -> Result<Vec<Row>> {
    let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    let mut uniform = move || {
        // xorshift64*
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n)
        .map(|i| {
            let nu = 0.5 - 1.49 * uniform();
            let p2 = 10f64.powf(-4.0 + 6.0 * uniform());
            let p3 = 10f64.powf(-3.0 + 7.0 * uniform());
            Ok(Row {
                line: i as u64 + 2,
                text: [nu.to_string(), p2.to_string(), p3.to_string()],
                groups: Groups::new(nu, p2, p3)?,
            })
        })
        .collect()
}
