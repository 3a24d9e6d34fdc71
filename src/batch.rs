//! Many impacts at once from dimensionless groups: the `cor --input FILE.csv` job.
//!
//! Input: CSV with a header and exactly the columns `nu,p2,p3` (`nu = 0.5`: incompressible);
//! see [`parse_rows`] for line endings, blank lines and quoting.
//! Output: the input columns, then `cor,contact_time,max_indentation` in canonical units
//! (`m = R = v0 = G_inf = 1`), rows in input order, computed in parallel.

use rayon::prelude::*;
use std::io::Write;
use std::path::Path;

use crate::error::{escape_text, Error, Result};
use crate::impact::{Groups, Impact, Outcome};
use crate::output::fmt;
use crate::solver::{solve, SolveOptions};

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

/// The header every input file starts with.
pub const HEADER: [&str; 3] = ["nu", "p2", "p3"];

/// Read `nu,p2,p3` rows from a file; see [`parse_rows`].
pub fn read_rows(path: &Path) -> Result<Rows> {
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    parse_rows(&path.display().to_string(), &bytes)
}

/// Parse the bytes of an input file named `file` (the name is only used in messages).
///
/// - A UTF-8 byte-order mark at the start is ignored.
/// - Lines end at `\r\n`, `\n` or a lone `\r`; line numbers in messages and in [`Row::line`]
///   count physical lines from 1, blank lines included. A final line terminator is optional.
/// - An empty line is skipped and its number reported in [`Rows::skipped_blank_lines`]; a line
///   of only spaces or commas is not blank but an error.
/// - The first non-empty line is the header `nu,p2,p3`; every other line holds exactly three
///   comma-separated fields. Fields are trimmed and may be quoted (`"0.45"`, `""` for a quote
///   inside); a quoted field cannot span lines.
/// - Every value must be a finite number, and the three must be valid [`Groups`].
/// - Any bad line (invalid UTF-8 included) is an [`Error::Csv`] naming its line; text quoted in a
///   message is escaped with [`escape_text`].
pub fn parse_rows(file: &str, bytes: &[u8]) -> Result<Rows> {
    let bad = |line: u64, message: String| Error::Csv {
        file: file.to_string(),
        line,
        message,
    };
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let mut out = Rows::default();
    let mut header_seen = false;
    for (line, raw) in physical_lines(bytes) {
        if raw.is_empty() {
            out.skipped_blank_lines.push(line);
            continue;
        }
        let text = std::str::from_utf8(raw).map_err(|e| {
            bad(
                line,
                format!("not valid UTF-8 (byte {} of the line)", e.valid_up_to() + 1),
            )
        })?;
        let fields = split_fields(text).map_err(|m| bad(line, m))?;
        if !header_seen {
            if fields != HEADER {
                return Err(bad(
                    line,
                    format!(
                        "header must be 'nu,p2,p3', found '{}'",
                        escape_text(&fields.join(","))
                    ),
                ));
            }
            header_seen = true;
            continue;
        }
        if text.trim().is_empty() {
            return Err(bad(
                line,
                "line holds only whitespace; a blank line must be empty to be skipped".into(),
            ));
        }
        if fields.len() != 3 {
            return Err(bad(
                line,
                format!(
                    "expected 3 fields (nu,p2,p3), found {}: '{}'",
                    fields.len(),
                    escape_text(text)
                ),
            ));
        }
        let mut v = [0.0; 3];
        for (j, name) in HEADER.iter().enumerate() {
            let s = fields[j].as_str();
            if s.is_empty() {
                return Err(bad(line, format!("{name} is empty")));
            }
            let x = s.parse::<f64>().map_err(|_| {
                bad(
                    line,
                    format!("{name} = '{}' is not a number", escape_text(s)),
                )
            })?;
            if !x.is_finite() {
                return Err(bad(
                    line,
                    format!("{name} = '{}' is not a finite number", escape_text(s)),
                ));
            }
            v[j] = x;
        }
        let groups = Groups::new(v[0], v[1], v[2]).map_err(|e| bad(line, e.to_string()))?;
        let [a, b, c]: [String; 3] = fields.try_into().unwrap_or_default();
        out.rows.push(Row {
            line,
            text: [a, b, c],
            groups,
        });
    }
    if !header_seen {
        return Err(bad(
            1,
            "no header: expected 'nu,p2,p3' (the file is empty)".into(),
        ));
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

/// The physical lines of `bytes` with their 1-based numbers, terminators removed. A line ends at
/// `\r\n`, `\n` or a lone `\r`; text after the last terminator, if any, is the last line.
pub(crate) fn physical_lines(bytes: &[u8]) -> Vec<(u64, &[u8])> {
    let mut lines = Vec::new();
    let mut start = 0;
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'\n' => {
                lines.push(&bytes[start..i]);
                start = i + 1;
            }
            b'\r' => {
                lines.push(&bytes[start..i]);
                if bytes.get(i + 1) == Some(&b'\n') {
                    i += 1;
                }
                start = i + 1;
            }
            _ => {}
        }
        i += 1;
    }
    if start < bytes.len() {
        lines.push(&bytes[start..]);
    }
    (1..).zip(lines).collect()
}

/// Split one line into comma-separated fields, each trimmed; a field may be quoted (`"..."`,
/// with `""` for a quote inside) and then may hold commas. An unterminated quote is an error:
/// a quoted field cannot span lines.
pub(crate) fn split_fields(line: &str) -> std::result::Result<Vec<String>, String> {
    let mut fields = Vec::new();
    let mut rest = line;
    loop {
        let t = rest.trim_start();
        if let Some(q) = t.strip_prefix('"') {
            let mut value = String::new();
            let mut end = None;
            let mut chars = q.char_indices().peekable();
            while let Some((i, c)) = chars.next() {
                if c != '"' {
                    value.push(c);
                } else if chars.peek().map(|&(_, n)| n) == Some('"') {
                    value.push('"');
                    chars.next();
                } else {
                    end = Some(i + 1);
                    break;
                }
            }
            let Some(end) = end else {
                return Err(
                    "unterminated quoted field (a quoted field cannot span lines)".to_string(),
                );
            };
            fields.push(value.trim().to_string());
            let after = q[end..].trim_start();
            if after.is_empty() {
                break;
            }
            match after.strip_prefix(',') {
                Some(r) => rest = r,
                None => {
                    return Err(format!(
                        "unexpected text '{}' after a quoted field",
                        escape_text(after)
                    ))
                }
            }
        } else {
            match t.find(',') {
                Some(i) => {
                    fields.push(t[..i].trim().to_string());
                    rest = &t[i + 1..];
                }
                None => {
                    fields.push(t.trim().to_string());
                    break;
                }
            }
        }
    }
    Ok(fields)
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
