//! CoR against temperature (`mdr-impact curve SCENE --temperature MIN:MAX:N`): the scene's
//! impact at its own velocity, its materials shifted to each temperature by their
//! `[material.shift]` laws (`docs/theory.md` §13), solved in parallel.

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::error::{escape_text, Error, Result, ResultExt};
use crate::io::output::{fmt, write_all_atomic};
use crate::io::plot::{panels_svg, CorLine, Panel, COR_AXIS_TOP};
use crate::io::scene::Scene;
use crate::model::material::shift::celsius_text;
use crate::model::validity::Validity;
use crate::solvers::{solve, SolveOptions};
use plotters::style::RGBColor;

/// Header of `curve.csv` for a temperature curve.
pub const CSV_HEADER: &str = "temperature,cor,contact_time,max_force,max_compression";

/// Largest number of temperatures of one curve.
pub const MAX_TEMPERATURES: usize = 10_000;

/// Temperatures `MIN:MAX:N` (°C): `N` values from `MIN` to `MAX`, both included, evenly spaced.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TemperatureRange {
    /// Lowest temperature (°C).
    pub min: f64,
    /// Highest temperature (°C), `min < max`.
    pub max: f64,
    /// Number of temperatures, `2 <= n <= MAX_TEMPERATURES`.
    pub n: usize,
}

impl TemperatureRange {
    /// Parse `MIN:MAX:N` (finite `MIN < MAX` in °C, above absolute zero; `2 <= N <= 10000`).
    pub fn parse(s: &str) -> Result<Self> {
        let bad = || Error::Parse {
            what: "--temperature",
            input: escape_text(s),
            expected: format!(
                "MIN:MAX:N in °C with -273.15 < MIN < MAX < inf and 2 <= N <= {MAX_TEMPERATURES}"
            ),
        };
        let parts: Vec<&str> = s.split(':').collect();
        let [min, max, n] = parts.as_slice() else {
            return Err(bad());
        };
        let (min, max): (f64, f64) = (
            min.trim().parse().map_err(|_| bad())?,
            max.trim().parse().map_err(|_| bad())?,
        );
        let n: usize = n.trim().parse().map_err(|_| bad())?;
        let ordered = min > -273.15 && min < max && max.is_finite();
        if !ordered || !(2..=MAX_TEMPERATURES).contains(&n) {
            return Err(bad());
        }
        Ok(Self { min, max, n })
    }

    /// The temperatures (°C), `min` and `max` included.
    pub fn values(&self) -> Vec<f64> {
        crate::math::linspace(self.min, self.max, self.n)
    }
}

/// One temperature of the curve (SI, °C).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TemperatureRow {
    /// Temperature (°C).
    pub temperature: f64,
    /// Coefficient of restitution.
    pub cor: f64,
    /// Contact time (s).
    pub contact_time: f64,
    /// Maximum contact force (N).
    pub max_force: f64,
    /// Maximum compression = maximum indentation depth (m).
    pub max_compression: f64,
}

/// Solve the scene of `text` (Prony files relative to `base`) at each of `temperatures` (°C)
/// with its own velocity and solver (histories off), in parallel, rows in input order;
/// `progress` is called once per temperature. The scene needs a `[material.shift]` law; an
/// error names the temperature. Also returns the warnings of the scene at those temperatures
/// ([`Scene::warnings`]: temperatures outside the range a shift law was calibrated on) and of
/// the answers outside the model's validity ([`Validity`], as `run` warns at one temperature),
/// one sentence per kind, naming how many temperatures it concerns.
pub fn run(
    text: &str,
    base: &Path,
    temperatures: &[f64],
    progress: &(dyn Fn() + Sync),
) -> Result<(Vec<TemperatureRow>, Vec<String>)> {
    // the scene as written first: its own errors are reported as they are
    Scene::parse_in(text, base)?;
    type Solved = (TemperatureRow, Vec<String>, Option<(f64, Option<f64>)>);
    let solved: Vec<Solved> = temperatures
        .par_iter()
        .map(|&t| {
            let row = Scene::parse_at(text, base, Some(t)).and_then(|scene| {
                let opts = SolveOptions {
                    history: false,
                    ..scene.options
                };
                let o = solve(&scene.impact, &opts)?;
                // the validity measures of a row outside the model's validity
                let v = Validity::of(&scene.impact, &o);
                let invalid = (!v.warnings.is_empty())
                    .then_some((v.contact_radius_ratio, v.wave_transit_ratio));
                let row = TemperatureRow {
                    temperature: t,
                    cor: o.cor,
                    contact_time: o.contact_time,
                    max_force: o.max_force,
                    max_compression: o.max_indentation,
                };
                Ok((row, scene.warnings, invalid))
            });
            progress();
            row.at(|| format!("--temperature: at {t} °C"))
        })
        .collect::<Result<_>>()?;
    let outside: Vec<(f64, &String)> = solved
        .iter()
        .filter_map(|(r, w, _)| w.first().map(|w| (r.temperature, w)))
        .collect();
    let invalid: Vec<(f64, (f64, Option<f64>))> = solved
        .iter()
        .filter_map(|(r, _, m)| m.map(|m| (r.temperature, m)))
        .collect();
    let mut warnings = match (outside.first(), outside.last()) {
        (Some((lo, first)), Some((hi, _))) => vec![format!(
            "{} of {} temperatures (the lowest {} °C, the highest {} °C) lie outside a \
             shift law's calibrated range; the first: {first}",
            outside.len(),
            solved.len(),
            celsius_text(*lo),
            celsius_text(*hi)
        )],
        _ => Vec::new(),
    };
    if let Some((first, _)) = invalid.first() {
        let worst = crate::model::validity::worst_measures(invalid.iter().map(|s| s.1));
        warnings.push(format!(
            "{} of {} temperatures lie outside the model's validity (from {} °C; {worst}; \
             `run --json` at one of them says why)",
            invalid.len(),
            solved.len(),
            celsius_text(*first)
        ));
    }
    Ok((solved.into_iter().map(|(r, _, _)| r).collect(), warnings))
}

/// The CSV text of the rows: header [`CSV_HEADER`], full-precision SI numbers.
pub fn csv_text(rows: &[TemperatureRow]) -> String {
    let mut s = String::from(CSV_HEADER);
    s.push('\n');
    for r in rows {
        s.push_str(&format!(
            "{},{},{},{},{}\n",
            fmt(r.temperature),
            fmt(r.cor),
            fmt(r.contact_time),
            fmt(r.max_force),
            fmt(r.max_compression)
        ));
    }
    s
}

/// The SVG text of the CoR against temperature; `title` names the scene.
pub fn svg(path: &Path, rows: &[TemperatureRow], title: &str) -> Result<String> {
    let (Some(a), Some(b)) = (rows.first(), rows.last()) else {
        return Err(Error::Internal("a temperature curve has at least two rows"));
    };
    let lines: Vec<CorLine> = vec![(
        "e(T), this model".to_string(),
        rows.iter().map(|r| (r.temperature, r.cor)).collect(),
        RGBColor(30, 80, 200),
        2,
    )];
    let panel = Panel {
        caption: title.to_string(),
        y_label: "coefficient of restitution e".into(),
        y_range: (0.0, COR_AXIS_TOP),
        lines,
        shaded: Default::default(),
    };
    panels_svg(
        path,
        (a.temperature, b.temperature),
        false,
        "temperature (°C)",
        &[panel],
    )
}

/// Files written by [`write_outputs`]: `DIR/curve.csv` and `DIR/curve.svg`.
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    /// `DIR/curve.csv`.
    pub csv: PathBuf,
    /// `DIR/curve.svg`.
    pub svg: PathBuf,
}

/// Write `dir/curve.csv` and `dir/curve.svg`, all or none.
pub fn write_outputs(dir: &Path, rows: &[TemperatureRow], title: &str) -> Result<Written> {
    let csv = dir.join("curve.csv");
    let svg_path = dir.join("curve.svg");
    let body = svg(&svg_path, rows, title)?;
    let text = csv_text(rows);
    write_all_atomic(&[(&csv, text.as_bytes()), (&svg_path, body.as_bytes())])?;
    Ok(Written { csv, svg: svg_path })
}

/// The printed summary: the number of temperatures, the smallest and largest CoR, the ends.
pub fn summary(rows: &[TemperatureRow], written: Option<&Written>) -> String {
    let mut out = String::new();
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<28}{v}\n"));
    line("temperatures", rows.len().to_string());
    let by = |a: &&TemperatureRow, b: &&TemperatureRow| a.cor.total_cmp(&b.cor);
    if let (Some(lo), Some(hi)) = (rows.iter().min_by(by), rows.iter().max_by(by)) {
        line(
            "minimum CoR",
            format!("{:.6} at {} °C", lo.cor, lo.temperature),
        );
        line(
            "maximum CoR",
            format!("{:.6} at {} °C", hi.cor, hi.temperature),
        );
    }
    if let Some(w) = written {
        line("curve written to", w.csv.display().to_string());
        line("plot written to", w.svg.display().to_string());
    }
    out
}
