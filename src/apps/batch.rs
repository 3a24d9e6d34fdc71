//! Many impacts at once from dimensionless groups: the `cor --input FILE.csv` job.
//!
//! Input: CSV with a header and exactly the columns `nu,p2,p3` (`nu = 0.5`: incompressible);
//! see [`parse_rows`] for line endings, blank lines and quoting.
//! Output: the input columns, then `cor,contact_time_canonical,max_indentation_canonical` in
//! canonical units (`m = R = v0 = G_inf = 1`), rows in input order, computed in parallel.

use rayon::prelude::*;
use std::io::Write;
use std::path::Path;

use crate::error::{Error, Result};
use crate::io::lines::parse_numeric;
use crate::io::output::fmt;
use crate::model::impact::{Groups, Impact, Outcome};
use crate::rng::SplitMix64;
use crate::solvers::{solve, SolveOptions};

/// One input row: its 1-based line number, the original text of its fields and the groups.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// 1-based physical line number in the file (see [`parse_rows`]).
    pub line: u64,
    /// The three fields as written (trimmed, quotes removed).
    pub text: [String; 3],
    /// The parsed, validated groups.
    pub groups: Groups,
}

/// What an input file holds: its data rows in order, and the empty lines that were skipped.
///
/// Every data line of the file is in `rows` (a bad one is an error, never dropped), so
/// `rows.len()` plus the header plus `skipped_blank_lines.len()` is the file's number of lines.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Rows {
    /// The data rows, in file order.
    pub rows: Vec<Row>,
    /// 1-based physical line numbers of the empty lines skipped, ascending.
    pub skipped_blank_lines: Vec<u64>,
}

/// The header of the output: the input columns, the CoR, and the contact time and maximum
/// indentation in canonical units (`m = R = v0 = G_inf = 1`), which their names say.
pub const OUTPUT_HEADER: [&str; 6] = [
    "nu",
    "p2",
    "p3",
    "cor",
    "contact_time_canonical",
    "max_indentation_canonical",
];

/// The header every input file starts with.
pub const HEADER: [&str; 3] = ["nu", "p2", "p3"];

/// Read `nu,p2,p3` rows from a file; see [`parse_rows`].
pub fn read_rows(path: &Path) -> Result<Rows> {
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    parse_rows(&path.display().to_string(), &bytes)
}

/// Parse the bytes of an input file named `file` (the name is only used in messages): the
/// line rules of [`crate::io::lines`] (byte-order mark, `\n`/`\r\n`/`\r` line ends, physical line
/// numbers in messages and in [`Row::line`], empty lines skipped and reported in
/// [`Rows::skipped_blank_lines`], trimmed and optionally quoted fields, finite numbers) with the
/// header `nu,p2,p3`, and every row valid [`Groups`]; any bad line is an [`Error::Csv`] naming
/// its line.
pub fn parse_rows(file: &str, bytes: &[u8]) -> Result<Rows> {
    let table = parse_numeric(file, bytes, &HEADER)?;
    let mut out = Rows {
        rows: Vec::with_capacity(table.rows.len()),
        skipped_blank_lines: table.skipped_blank_lines,
    };
    for r in table.rows {
        let groups =
            Groups::new(r.values[0], r.values[1], r.values[2]).map_err(|e| Error::Csv {
                file: file.to_string(),
                line: r.line,
                message: e.to_string(),
            })?;
        let [a, b, c]: [String; 3] = r.fields.try_into().unwrap_or_default();
        out.rows.push(Row {
            line: r.line,
            text: [a, b, c],
            groups,
        });
    }
    Ok(out)
}

/// Line numbers as a short list: `3`, `3, 4`, `3-5, 9`.
pub fn format_line_list(lines: &[u64]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let mut j = i;
        while j + 1 < lines.len() && lines[j + 1] == lines[j] + 1 {
            j += 1;
        }
        match j - i {
            0 => parts.push(lines[i].to_string()),
            1 => parts.push(format!("{}, {}", lines[i], lines[j])),
            _ => parts.push(format!("{}-{}", lines[i], lines[j])),
        }
        i = j + 1;
    }
    parts.join(", ")
}

/// Solve every row in parallel (rayon); the first failing row (in input order) is the error.
pub fn solve_rows(file: &str, rows: &[Row], opts: &SolveOptions) -> Result<Vec<Outcome>> {
    let groups: Vec<Groups> = rows.iter().map(|r| r.groups).collect();
    solve_groups(&groups, opts).map_err(|(i, e)| Error::Csv {
        file: file.to_string(),
        line: rows[i].line,
        message: e.to_string(),
    })
}

/// Solve the impact of every set of groups in canonical units (`m = R = v0 = G_inf = 1`) in
/// parallel (rayon), results in input order; the error is that of the first failing entry (in
/// input order) with its index. The computation of `cor --input` (and of the Python package's
/// `cor`), without the file. Their outputs hold no force, so the maximum force is not located
/// after each solve ([`SolveOptions::peak_force`] false: `max_force` is the largest sampled
/// force with its parabola).
pub fn solve_groups(
    groups: &[Groups],
    opts: &SolveOptions,
) -> std::result::Result<Vec<Outcome>, (usize, Error)> {
    let opts = &SolveOptions {
        peak_force: false,
        ..*opts
    };
    let results: Vec<Result<Outcome>> = groups
        .par_iter()
        .map(|&g| Impact::from_groups(g).and_then(|imp| solve(&imp, opts)))
        .collect();
    results
        .into_iter()
        .enumerate()
        .map(|(i, r)| r.map_err(|e| (i, e)))
        .collect()
}

/// Rows formatted per task of [`write_results`].
pub const WRITE_CHUNK: usize = 4096;

/// Write the result table as CSV. The rows are formatted in parallel (rayon), a chunk of
/// [`WRITE_CHUNK`] rows per task, each by its own CSV writer without a header, and written in
/// input order: the same bytes as one writer over all rows (formatting the numbers costs about
/// as much as solving 100 000 elastic rows).
pub fn write_results(w: &mut dyn Write, rows: &[Row], outcomes: &[Outcome]) -> Result<()> {
    let io = |e: csv::Error| Error::io("<stdout>", e);
    let chunks: Vec<Vec<u8>> = rows
        .par_chunks(WRITE_CHUNK)
        .zip(outcomes.par_chunks(WRITE_CHUNK))
        .map(|(rows, outcomes)| {
            let mut c = csv::Writer::from_writer(Vec::with_capacity(rows.len() * 96));
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
            c.into_inner()
                .map_err(|e| Error::io("<stdout>", e.into_error()))
        })
        .collect::<Result<_>>()?;
    let mut c = csv::Writer::from_writer(&mut *w);
    c.write_record(OUTPUT_HEADER).map_err(io)?;
    c.flush().map_err(|e| Error::io("<stdout>", e))?;
    drop(c);
    for chunk in &chunks {
        w.write_all(chunk).map_err(|e| Error::io("<stdout>", e))?;
    }
    w.flush().map_err(|e| Error::io("<stdout>", e))?;
    Ok(())
}

/// `n` pseudo-random rows over the paper's range (nu in (-1, 0.5], log10 p2 in [-4, 2],
/// log10 p3 in [-3, 4]), reproducible from `seed` (for benchmarks).
pub fn random_rows(n: usize, seed: u64) -> Result<Vec<Row>> {
    let mut rng = SplitMix64::new(seed);
    let mut uniform = move || rng.uniform();
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
