//! DMA data for `prony`: the CSV reader, the tensile-to-shear conversion and the isotherms.
//!
//! Columns (header required, any order): `frequency` (Hz) or `omega` (rad/s), `storage` and
//! `loss` (Pa; `G'`, `G''`, or `E'`, `E''` with `--modulus tensile`), optionally
//! `temperature` (°C). Lines starting with `#` are comments. Every value must be a finite
//! number; frequencies and moduli must be positive. A bad line is an [`Error::Csv`] naming the
//! file and the physical line. Rows whose temperatures lie within [`ISOTHERM_TOLERANCE`] of the
//! coldest row of a group form one isotherm (a controller's temperature wanders by a few tenths
//! of a degree during a sweep); its temperature is their mean.
//!
//! Tensile moduli become shear moduli by `G = E / (2 (1 + nu))` with one constant Poisson ratio
//! for storage and loss, which assumes that `nu` does not depend on frequency (for rubbers far
//! above the glass transition `nu ~ 0.5` holds; through the transition `nu` falls towards
//! ~0.35 and the converted `G''` is then a few per cent off).

use std::path::Path;

use crate::error::{escape_text, Error, Result};

/// Rows within this many °C of the coldest row of a group belong to one isotherm.
pub const ISOTHERM_TOLERANCE: f64 = 0.5;

/// Loss tangents below this are flagged: they are at the phase resolution of a typical DMA
/// (tan delta ~ 1e-3), so the loss modulus there is mostly noise.
pub const TAN_DELTA_FLOOR: f64 = 1e-3;

/// Which moduli the data hold (`--modulus`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModulusKind {
    /// Shear `G'`, `G''`.
    Shear,
    /// Tensile (Young's) `E'`, `E''`, converted with a constant Poisson ratio.
    Tensile,
}

impl std::str::FromStr for ModulusKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "shear" => Ok(ModulusKind::Shear),
            "tensile" => Ok(ModulusKind::Tensile),
            _ => Err(Error::Parse {
                what: "--modulus",
                input: escape_text(s),
                expected: "shear or tensile".into(),
            }),
        }
    }
}

/// One isotherm: its temperature (°C; `None` without a temperature column) and its points
/// `(omega` (rad/s), `G'` (Pa), `G''` (Pa)`)` in shear, by strictly increasing `omega`.
#[derive(Debug, Clone, PartialEq)]
pub struct Isotherm {
    /// Temperature (°C), the mean of its rows.
    pub temperature: Option<f64>,
    /// The lowest and highest temperature of its rows (°C), as measured.
    pub measured: Option<(f64, f64)>,
    /// `(omega, G', G'')`, by increasing `omega`.
    pub points: Vec<(f64, f64, f64)>,
}

/// Validated DMA data in shear.
#[derive(Debug, Clone, PartialEq)]
pub struct DmaData {
    /// The isotherms, by increasing temperature.
    pub isotherms: Vec<Isotherm>,
    /// Data rows read.
    pub rows: usize,
    /// Problems that do not stop the fit, one line each.
    pub warnings: Vec<String>,
}

/// Read a DMA file; see [`parse`].
pub fn read(path: &Path, modulus: ModulusKind, nu: f64) -> Result<DmaData> {
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    let file = path.display().to_string();
    let text = std::str::from_utf8(&bytes).map_err(|e| Error::Csv {
        file: file.clone(),
        line: 1 + bytes[..e.valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count() as u64,
        message: "not valid UTF-8".into(),
    })?;
    parse(text, &file, modulus, nu)
}

/// One data row: temperature (°C), omega (rad/s), G', G'' (Pa, shear) and its line.
type Row = (Option<f64>, f64, f64, f64, u64);

const COLUMNS: [&str; 5] = ["frequency", "omega", "storage", "loss", "temperature"];

/// Parse CSV `text` (named `file` in messages) into isotherms in shear (see the module docs).
pub fn parse(text: &str, file: &str, modulus: ModulusKind, nu: f64) -> Result<DmaData> {
    crate::error::check("--nu", nu, nu > -1.0 && nu <= 0.5, "-1 < nu <= 0.5")?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let err = |line: u64, message: String| Error::Csv {
        file: file.to_string(),
        line,
        message,
    };
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .flexible(false)
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let header_line = line_of(text, 0);
    let header: Vec<String> = reader
        .headers()
        .map_err(|e| err(header_line, escape_text(&e.to_string())))?
        .iter()
        .map(str::to_string)
        .collect();
    let mut col = [None; 5];
    for (j, h) in header.iter().enumerate() {
        match COLUMNS.iter().position(|c| c == h) {
            Some(k) if col[k].is_none() => col[k] = Some(j),
            Some(_) => {
                return Err(err(
                    header_line,
                    format!("column '{}' appears twice", escape_text(h)),
                ))
            }
            None => {
                return Err(err(
                    header_line,
                    format!(
                        "unknown column '{}': expected frequency (Hz) or omega (rad/s), \
                         storage, loss (Pa) and optionally temperature (°C)",
                        escape_text(h)
                    ),
                ))
            }
        }
    }
    let freq_col = match (col[0], col[1]) {
        (Some(j), None) => (j, std::f64::consts::TAU),
        (None, Some(j)) => (j, 1.0),
        (Some(_), Some(_)) => {
            return Err(err(
                header_line,
                "give frequency (Hz) or omega (rad/s), not both".into(),
            ))
        }
        (None, None) => {
            return Err(err(
                header_line,
                "missing column frequency (Hz) or omega (rad/s)".into(),
            ))
        }
    };
    for k in [2, 3] {
        if col[k].is_none() {
            return Err(err(
                header_line,
                format!("missing column '{}' (Pa)", COLUMNS[k]),
            ));
        }
    }
    let factor = match modulus {
        ModulusKind::Shear => 1.0,
        ModulusKind::Tensile => 1.0 / (2.0 * (1.0 + nu)),
    };
    // (temperature, omega, G', G'', line)
    let mut rows: Vec<Row> = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| {
            let line = e.position().map_or(0, |p| line_of(text, p.byte()));
            err(line, escape_text(&e.to_string()))
        })?;
        let line = record.position().map_or(0, |p| line_of(text, p.byte()));
        let number = |j: usize, name: &str, positive: bool| -> Result<f64> {
            let s = record.get(j).unwrap_or("");
            if s.is_empty() {
                return Err(err(line, format!("{name} is empty")));
            }
            let v: f64 = s.parse().map_err(|_| {
                err(
                    line,
                    format!("{name} = '{}' is not a number", escape_text(s)),
                )
            })?;
            if !v.is_finite() {
                return Err(err(
                    line,
                    format!("{name} = '{}' is not finite", escape_text(s)),
                ));
            }
            if positive && !(v > 0.0) {
                return Err(err(
                    line,
                    format!("{name} = {v:e} is out of range: allowed {name} > 0"),
                ));
            }
            Ok(v)
        };
        let w = number(
            freq_col.0,
            COLUMNS[if col[0].is_some() { 0 } else { 1 }],
            true,
        )?;
        let s = number(col[2].unwrap_or(0), "storage", true)?;
        let l = number(col[3].unwrap_or(0), "loss", true)?;
        let t = match col[4] {
            Some(j) => {
                let t = number(j, "temperature", false)?;
                if t <= -273.15 {
                    return Err(err(
                        line,
                        format!("temperature = {t:e} °C is below absolute zero"),
                    ));
                }
                Some(t)
            }
            None => None,
        };
        rows.push((t, w * freq_col.1, s * factor, l * factor, line));
    }
    if rows.len() < 2 {
        return Err(err(
            header_line,
            format!(
                "{} data row{}: a Prony fit needs at least two frequencies",
                rows.len(),
                if rows.len() == 1 { "" } else { "s" }
            ),
        ));
    }
    let mut warnings = Vec::new();
    let low: Vec<u64> = rows
        .iter()
        .filter(|r| r.3 < TAN_DELTA_FLOOR * r.2)
        .map(|r| r.4)
        .collect();
    if !low.is_empty() {
        warnings.push(format!(
            "loss modulus below {TAN_DELTA_FLOOR:e} of the storage modulus at {} point{} \
             (first at line {}): tan delta there is at the phase resolution of a typical DMA, so \
             the loss is mostly noise",
            low.len(),
            if low.len() == 1 { "" } else { "s" },
            low[0]
        ));
    }
    // group into isotherms
    rows.sort_by(|a, b| {
        a.0.unwrap_or(0.0)
            .total_cmp(&b.0.unwrap_or(0.0))
            .then(a.4.cmp(&b.4))
    });
    let mut groups: Vec<Vec<Row>> = Vec::new();
    for r in rows.iter().copied() {
        match groups.last_mut() {
            Some(g) if r.0.unwrap_or(0.0) - g[0].0.unwrap_or(0.0) <= ISOTHERM_TOLERANCE => {
                g.push(r)
            }
            _ => groups.push(vec![r]),
        }
    }
    let mut isotherms = Vec::with_capacity(groups.len());
    for mut g in groups {
        let temperature = g[0]
            .0
            .map(|_| g.iter().map(|r| r.0.unwrap_or(0.0)).sum::<f64>() / g.len() as f64);
        let measured = g[0].0.map(|_| {
            let t = g.iter().map(|r| r.0.unwrap_or(0.0));
            (
                t.clone().fold(f64::INFINITY, f64::min),
                t.fold(f64::NEG_INFINITY, f64::max),
            )
        });
        g.sort_by(|a, b| a.1.total_cmp(&b.1));
        let mut points: Vec<(f64, f64, f64)> = Vec::new();
        let mut counts: Vec<usize> = Vec::new();
        let mut merged = 0;
        for r in &g {
            match points.last_mut() {
                // a repeated frequency: geometric means of the moduli
                Some(p) if (r.1 / p.0 - 1.0).abs() < 1e-9 => {
                    let n = counts.last_mut().expect("counts follow points");
                    let k = *n as f64;
                    p.1 = ((p.1.ln() * k + r.2.ln()) / (k + 1.0)).exp();
                    p.2 = ((p.2.ln() * k + r.3.ln()) / (k + 1.0)).exp();
                    *n += 1;
                    merged += 1;
                }
                _ => {
                    points.push((r.1, r.2, r.3));
                    counts.push(1);
                }
            }
        }
        let name = temperature.map_or("the data".to_string(), |t| {
            format!("the isotherm at {t} °C")
        });
        if merged > 0 {
            warnings.push(format!(
                "{name}: {merged} repeated frequenc{} merged (geometric mean of the moduli)",
                if merged == 1 { "y" } else { "ies" }
            ));
        }
        if points.len() < 2 {
            return Err(err(
                g[0].4,
                format!(
                    "{name} has a single frequency: an isotherm needs at least two to be \
                     shifted and fitted"
                ),
            ));
        }
        isotherms.push(Isotherm {
            temperature,
            measured,
            points,
        });
    }
    Ok(DmaData {
        isotherms,
        rows: rows.len(),
        warnings,
    })
}

/// The 1-based physical line (ends: `\n`, `\r\n`, lone `\r`) of the record that the csv
/// reader places at `byte`: its position points before the empty and comment lines it skipped.
fn line_of(text: &str, byte: u64) -> u64 {
    let b = text.as_bytes();
    let mut i = (byte as usize).min(b.len());
    loop {
        let at_line_start = i == 0 || matches!(b[i - 1], b'\n' | b'\r');
        match b.get(i) {
            Some(b'\n' | b'\r') => i += 1,
            Some(b'#') if at_line_start => {
                while i < b.len() && !matches!(b[i], b'\n' | b'\r') {
                    i += 1;
                }
            }
            _ => break,
        }
    }
    let mut line = 1;
    let mut k = 0;
    while k < i {
        match b[k] {
            b'\n' => line += 1,
            b'\r' if b.get(k + 1) != Some(&b'\n') => line += 1,
            _ => {}
        }
        k += 1;
    }
    line
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_comments_hz_and_tensile() {
        let text =
            "# synthetic\nfrequency,storage,loss,temperature\n1,3e6,3e5,20\n10,6e6,6e5,20.2\n\
                    1,1e6,1e5,40\n10,2e6,2e5,40\n";
        let d = parse(text, "d.csv", ModulusKind::Tensile, 0.5).unwrap();
        assert_eq!(d.isotherms.len(), 2);
        let p = d.isotherms[0].points[0];
        assert!((p.0 - std::f64::consts::TAU).abs() < 1e-12 && (p.1 - 1e6).abs() < 1e-6);
        assert!((d.isotherms[0].temperature.unwrap() - 20.1).abs() < 1e-12);
    }

    #[test]
    fn line_numbers_count_comments_blank_lines_and_every_line_end() {
        let e = parse(
            "# c\r\n\nomega,storage,loss\r1,1e6,1e5\n\n# d\n2,x,1e5\n",
            "d.csv",
            ModulusKind::Shear,
            0.5,
        )
        .unwrap_err();
        assert!(e.to_string().starts_with("d.csv:7: storage = 'x'"), "{e}");
        let e = parse("# c\nomega,storage\n", "d.csv", ModulusKind::Shear, 0.5).unwrap_err();
        assert!(
            e.to_string().starts_with("d.csv:2: missing column 'loss'"),
            "{e}"
        );
    }

    #[test]
    fn bad_rows_name_their_line() {
        let e = parse(
            "omega,storage,loss\n1,1e6,1e5\n2,-1e6,1e5\n",
            "d.csv",
            ModulusKind::Shear,
            0.5,
        )
        .unwrap_err();
        assert_eq!(
            e,
            Error::Csv {
                file: "d.csv".into(),
                line: 3,
                message: "storage = -1e6 is out of range: allowed storage > 0".into()
            }
        );
        let e = parse(
            "omega,storage,loss\n1,1e6,1e5\n",
            "d.csv",
            ModulusKind::Shear,
            0.5,
        )
        .unwrap_err();
        assert!(e.to_string().contains("1 data row"), "{e}");
    }
}
