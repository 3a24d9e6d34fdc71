//! `mdr-impact indent`: the force curve of a prescribed indentation (AFM / nanoindentation), with
//! the command's history kinds, its default output times and its CSV.

use std::fmt::Write as _;

use crate::error::{escape_text, Error, Result};
use crate::io::output::fmt;
use crate::model::geometry::Shape;
use crate::model::material::Material;
use crate::solvers::indentation::Prescribed;
use crate::solvers::{force_curve, ForceCurveRow, IndentMethod};

/// The shape of a prescribed indentation `d(t)` with rate `V` and peak time `T`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum HistoryKind {
    /// `d = V t` up to `T`, then `V (2T - t)`.
    Triangle,
    /// `d = V T sin(pi t / 2T)`.
    HalfSine,
}

impl HistoryKind {
    /// Every kind, in the order of [`HistoryKind::NAMES`].
    pub const ALL: [HistoryKind; 2] = [HistoryKind::Triangle, HistoryKind::HalfSine];
    /// The names accepted by `--history`.
    pub const NAMES: [&'static str; 2] = ["triangle", "half-sine"];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            HistoryKind::Triangle => Self::NAMES[0],
            HistoryKind::HalfSine => Self::NAMES[1],
        }
    }

    /// The history with rate `rate` (m/s) and peak time `peak_time` (s).
    pub fn prescribed(self, rate: f64, peak_time: f64) -> Result<Prescribed> {
        match self {
            HistoryKind::Triangle => Prescribed::triangle(rate, peak_time),
            HistoryKind::HalfSine => Prescribed::half_sine(rate, peak_time),
        }
    }
}

impl std::str::FromStr for HistoryKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| Error::Parse {
                what: "--history",
                input: escape_text(s),
                expected: Self::NAMES.join(" or "),
            })
    }
}

/// Output times of the default grid of [`default_times`].
pub const DEFAULT_TIMES: usize = 101;

/// The default output times: [`DEFAULT_TIMES`] uniform points over `[0, 2 peak_time]`.
pub fn default_times(peak_time: f64) -> Vec<f64> {
    let n = DEFAULT_TIMES - 1;
    (0..=n)
        .map(|i| 2.0 * peak_time * i as f64 / n as f64)
        .collect()
}

/// The force curve of a rigid indenter of `shape` pressed into `material` along the history
/// `kind` (rate `rate`, peak time `peak_time`) at `times` (default: [`default_times`]).
pub fn run(
    material: &Material,
    shape: &Shape,
    kind: HistoryKind,
    rate: f64,
    peak_time: f64,
    times: Option<&[f64]>,
    method: IndentMethod,
) -> Result<Vec<ForceCurveRow>> {
    let history = kind.prescribed(rate, peak_time)?;
    let default;
    let times = match times {
        Some(t) => t,
        None => {
            default = default_times(peak_time);
            &default
        }
    };
    // a failure deep in a solver (a tolerance or a force that under- or overflows) is placed
    // at the flags that set the history's scale
    force_curve(material, shape, &history, times, method).map_err(|e| {
        e.at(format!(
            "indent --rate {rate:e} m/s --peak-time {peak_time:e} s (depth scale {:e} m)",
            rate * peak_time
        ))
    })
}

/// The validity warnings of a force curve: those of its shape at the largest contact radius
/// and depth of `rows` ([`crate::model::validity::shape_warnings`]; a sphere's contact measured
/// against its radius).
pub fn warnings(shape: &Shape, rows: &[ForceCurveRow]) -> Vec<String> {
    let a = rows.iter().map(|r| r.a).fold(0.0, f64::max);
    let d = rows.iter().map(|r| r.d).fold(0.0, f64::max);
    let radius = match shape {
        Shape::Paraboloid { .. } | Shape::Spheres { .. } => shape.tip_radius(),
        _ => None,
    };
    crate::model::validity::shape_warnings(shape, radius.unwrap_or(f64::INFINITY), a, d)
}

/// The header of [`csv()`]: time (s), depth (m), contact radius (m), force (N).
pub const CSV_HEADER: &str = "t_s,d_m,a_m,force_N";

/// The rows as CSV with the header [`CSV_HEADER`] (SI, the crate's number format).
pub fn csv(rows: &[ForceCurveRow]) -> String {
    let mut out = format!("{CSV_HEADER}\n");
    for r in rows {
        let _ = writeln!(
            out,
            "{},{},{},{}",
            fmt(r.t),
            fmt(r.d),
            fmt(r.a),
            fmt(r.force)
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_a_typo_is_a_parse_error() {
        for k in HistoryKind::ALL {
            assert_eq!(k.name().parse::<HistoryKind>().unwrap(), k);
        }
        assert!(matches!(
            "sine".parse::<HistoryKind>(),
            Err(Error::Parse {
                what: "--history",
                ..
            })
        ));
    }

    #[test]
    fn default_grid_is_101_points_over_twice_the_peak_time() {
        let t = default_times(0.5);
        assert_eq!(t.len(), DEFAULT_TIMES);
        assert_eq!((t[0], t[50], t[100]), (0.0, 0.5, 1.0));
    }
}
