//! The rows of a sweep's CSV: writing them and reading them back (a resumed sweep).

use super::*;

/// One row of a sweep's CSV (see [`COLUMNS`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// Planned point.
    pub point: Point,
    /// `p2 = 10^log10_p2`.
    pub p2: f64,
    /// `p3 = 10^log10_p3`.
    pub p3: f64,
    /// The CoR; `None` when the solve failed.
    pub cor: Option<f64>,
    /// The solver's relative error estimate of the CoR.
    pub cor_error_estimate: Option<f64>,
    /// Contact time in units of `L / v0`.
    pub contact_time: Option<f64>,
    /// Maximum indentation in units of `L`.
    pub max_indentation: Option<f64>,
    /// SI inputs `[mass, radius, velocity, g_inf, g_1, eta]` actually solved.
    pub inputs: [f64; 6],
    /// Bulk modulus (Pa), `None` when incompressible.
    pub k_0: Option<f64>,
    /// Canonical CoR on the checked subsample.
    pub cor_canonical: Option<f64>,
    /// `|cor - cor_canonical| / cor_canonical` on the checked subsample.
    pub scaling_dev: Option<f64>,
    /// Requested solver name.
    pub solver: String,
    /// Requested rtol.
    pub rtol: f64,
    /// Random dimensional inputs were used.
    pub dimensional: bool,
    /// Wall time of the point (s).
    pub seconds: f64,
    /// Failure message; empty on success.
    pub error: String,
}

pub(super) fn opt(x: Option<f64>) -> String {
    x.map(fmt).unwrap_or_default()
}

impl Record {
    pub(super) fn fields(&self) -> Vec<String> {
        let p = &self.point;
        let mut f = vec![
            p.index.to_string(),
            fmt(p.nu),
            fmt(self.p2),
            fmt(self.p3),
            fmt(p.log10_p2),
            fmt(p.log10_p3),
            opt(self.cor),
            opt(self.cor_error_estimate),
            opt(self.contact_time),
            opt(self.max_indentation),
        ];
        // a point refused before its impact was built has no inputs: empty cells, never NaN
        f.extend(self.inputs.iter().map(|&x| opt(x.is_finite().then_some(x))));
        f.extend([
            opt(self.k_0),
            opt(self.cor_canonical),
            opt(self.scaling_dev),
            self.solver.clone(),
            fmt(self.rtol),
            u8::from(self.dimensional).to_string(),
            format!("{:.3e}", self.seconds),
            self.error.replace(['\n', '\r'], " "),
        ]);
        f
    }

    pub(super) fn parse(file: &str, line: u64, rec: &csv::StringRecord) -> Result<Self> {
        let bad = |message: String| Error::Csv {
            file: file.to_string(),
            line,
            message,
        };
        if rec.len() != COLUMNS.len() {
            return Err(bad(format!(
                "{} fields, expected {}",
                rec.len(),
                COLUMNS.len()
            )));
        }
        let get = |j: usize| rec.get(j).unwrap_or("");
        let num = |j: usize| -> Result<f64> {
            get(j)
                .parse::<f64>()
                .map_err(|_| bad(format!("{} = '{}' is not a number", header()[j], get(j))))
        };
        let onum = |j: usize| -> Result<Option<f64>> {
            if get(j).is_empty() {
                Ok(None)
            } else {
                num(j).map(Some)
            }
        };
        let index = get(0)
            .parse::<u64>()
            .map_err(|_| bad(format!("index = '{}' is not a whole number", get(0))))?;
        Ok(Record {
            point: Point {
                index,
                nu: num(1)?,
                log10_p2: num(4)?,
                log10_p3: num(5)?,
            },
            p2: num(2)?,
            p3: num(3)?,
            cor: onum(6)?,
            cor_error_estimate: onum(7)?,
            contact_time: onum(8)?,
            max_indentation: onum(9)?,
            inputs: [
                onum(10)?.unwrap_or(f64::NAN),
                onum(11)?.unwrap_or(f64::NAN),
                onum(12)?.unwrap_or(f64::NAN),
                onum(13)?.unwrap_or(f64::NAN),
                onum(14)?.unwrap_or(f64::NAN),
                onum(15)?.unwrap_or(f64::NAN),
            ],
            k_0: onum(16)?,
            cor_canonical: onum(17)?,
            scaling_dev: onum(18)?,
            solver: get(19).to_string(),
            rtol: num(20)?,
            dimensional: get(21) == "1",
            seconds: num(22)?,
            error: get(23).to_string(),
        })
    }
}

/// Read every complete row of a sweep CSV. A torn last line (no newline at the end) is ignored.
pub fn read_records(path: &Path) -> Result<Vec<Record>> {
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    parse_records(path, &bytes[..complete_len(&bytes)])
}

/// Length of the prefix of `bytes` made of complete lines.
pub(super) fn complete_len(bytes: &[u8]) -> usize {
    match bytes.iter().rposition(|&b| b == b'\n') {
        Some(i) => i + 1,
        None => 0,
    }
}

pub(super) fn parse_records(path: &Path, bytes: &[u8]) -> Result<Vec<Record>> {
    let file = path.display().to_string();
    if bytes.is_empty() {
        return Ok(Vec::new());
    }
    let mut rdr = csv::ReaderBuilder::new()
        .has_headers(true)
        .flexible(true)
        .from_reader(bytes);
    let h = rdr
        .headers()
        .map_err(|e| Error::Csv {
            file: file.clone(),
            line: 1,
            message: e.to_string(),
        })?
        .clone();
    let want = header();
    if h.iter().collect::<Vec<_>>() != want {
        return Err(Error::Csv {
            file,
            line: 1,
            message: format!(
                "not a sweep file: header must be '{}'; use another --out, or --fresh to discard \
                 its rows and start afresh",
                want.join(",")
            ),
        });
    }
    let mut out = Vec::new();
    for rec in rdr.records() {
        let rec = rec.map_err(|e| Error::Csv {
            file: file.clone(),
            line: e.position().map_or(0, |p| p.line()),
            message: e.to_string(),
        })?;
        let line = rec.position().map_or(0, |p| p.line());
        out.push(Record::parse(&file, line, &rec)?);
    }
    Ok(out)
}
