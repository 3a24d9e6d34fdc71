//! Small numeric CSV tables read line by line, for the input files of the CLI (`cor --input`,
//! Prony tables): every physical line is accounted for, so that a message names the line a user
//! sees in an editor and no data line is lost.
//!
//! - A UTF-8 byte-order mark at the start is ignored.
//! - Lines end at `\r\n`, `\n` or a lone `\r`; line numbers count physical lines from 1, blank
//!   lines included. A final line terminator is optional.
//! - An empty line is skipped and its number reported; a line of only spaces or commas is not
//!   blank but an error.
//! - The first non-empty line is the header; every other line holds exactly one field per header
//!   name. Fields are trimmed and may be quoted (`"0.45"`, `""` for a quote inside); a quoted
//!   field cannot span lines.
//! - Every value must be a finite number.
//! - Any bad line (invalid UTF-8 included) is an [`Error::Csv`] naming its line; text quoted in a
//!   message is escaped with [`escape_text`].

use crate::error::{escape_text, Error, Result};

/// One data line: its physical line number, its fields as written (trimmed, unquoted) and their
/// values.
#[derive(Debug, Clone, PartialEq)]
pub struct NumericRow {
    /// 1-based physical line number.
    pub line: u64,
    /// The fields as written.
    pub fields: Vec<String>,
    /// The finite values of the fields, in header order.
    pub values: Vec<f64>,
}

/// A parsed table: its data rows in file order and the empty lines skipped.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct NumericTable {
    /// The data rows, in file order.
    pub rows: Vec<NumericRow>,
    /// 1-based physical line numbers of the empty lines skipped, ascending.
    pub skipped_blank_lines: Vec<u64>,
}

/// Parse the bytes of a table named `file` (the name is only used in messages) whose header is
/// exactly `header` (see the module docs for the rules).
pub fn parse_numeric<'a>(file: &str, bytes: &'a [u8], header: &[&str]) -> Result<NumericTable> {
    use rayon::prelude::*;
    let bad = |line: u64, message: String| Error::Csv {
        file: file.to_string(),
        line,
        message,
    };
    let names = header.join(",");
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let utf8 = |line: u64, raw: &'a [u8]| -> Result<&'a str> {
        std::str::from_utf8(raw).map_err(|e| {
            bad(
                line,
                format!("not valid UTF-8 (byte {} of the line)", e.valid_up_to() + 1),
            )
        })
    };
    let mut out = NumericTable::default();
    let lines = physical_lines(bytes);
    let mut data = Vec::with_capacity(lines.len());
    let mut header_seen = false;
    for (line, raw) in lines {
        if raw.is_empty() {
            out.skipped_blank_lines.push(line);
        } else if header_seen {
            data.push((line, raw));
        } else {
            let fields = split_fields(utf8(line, raw)?).map_err(|m| bad(line, m))?;
            if fields != header {
                return Err(bad(
                    line,
                    format!(
                        "header must be '{names}', found '{}'",
                        escape_text(&fields.join(","))
                    ),
                ));
            }
            header_seen = true;
        }
    }
    if !header_seen {
        return Err(bad(
            1,
            if out.skipped_blank_lines.is_empty() {
                format!("no header: expected '{names}' (the file is empty)")
            } else {
                format!(
                    "no header: expected '{names}' (the file holds only {} blank line(s))",
                    out.skipped_blank_lines.len()
                )
            },
        ));
    }
    // the data lines in parallel; the first bad line in file order is the error
    let row = |&(line, raw): &(u64, &'a [u8])| -> Result<NumericRow> {
        let text = utf8(line, raw)?;
        let fields = split_fields(text).map_err(|m| bad(line, m))?;
        if text.trim().is_empty() {
            return Err(bad(
                line,
                "line holds only whitespace; a blank line must be empty to be skipped".into(),
            ));
        }
        if fields.len() != header.len() {
            return Err(bad(
                line,
                format!(
                    "expected {} fields ({names}), found {}: '{}'",
                    header.len(),
                    fields.len(),
                    escape_text(text)
                ),
            ));
        }
        let mut values = Vec::with_capacity(header.len());
        for (s, name) in fields.iter().zip(header) {
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
            values.push(x);
        }
        Ok(NumericRow {
            line,
            fields,
            values,
        })
    };
    let rows: Vec<Result<NumericRow>> = data.par_iter().map(row).collect();
    out.rows = rows.into_iter().collect::<Result<_>>()?;
    Ok(out)
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
