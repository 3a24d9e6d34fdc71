//! CoR against impact velocity: one scene's impact solved at many velocities (`mdr-impact curve`).
//!
//! The sphere, the material and the solver options of the scene are kept; only the impact
//! velocity `v0` changes, and no histories are computed. The velocities are solved in parallel
//! (rayon); the rows come back in velocity order, each bit-identical to [`solve`] at that
//! velocity.
//!
//! # Limits (docs/theory.md §6, §7)
//! A viscoelastic half-space is elastic at both ends of the velocity range: for `v0 -> 0` the
//! contact lasts much longer than every relaxation time and the material answers with its relaxed
//! modulus (Hertz with `G_eq(inf)`, for the standard solid `G_inf`), for `v0 -> inf` the contact
//! is much shorter and it answers with its glassy modulus (Hertz with `G_eq(0)`, `G_0`). Both give
//! `e = 1`, so the elastic limits do not move the CoR; they mark where it returns to 1. In between
//! the relaxation time is of the order of the contact time and the dissipation peaks:
//!
//! - standard solid: `p3 = eta (v0 R / (m^2 G_inf^3))^(1/5)` grows as `v0^(1/5)`, so `p3 = 1` at
//!   `v0 = m^2 G_inf^3 / (R eta^5)` ([`Limits::p3_unit_velocity`]);
//! - general material (no `p3`): the Hertz contact time
//!   `t_c = 2 I (5 m / (4 k))^(2/5) v0^(-1/5)`, `k = (4/3) E* sqrt(R)`, `E* = 4 G_eq`, equals the
//!   slowest relaxation time of `G_eq` with the relaxed modulus at
//!   [`Limits::relaxed_crossover`] and the fastest one with the glassy modulus at
//!   [`Limits::glassy_crossover`]. These mark orders of magnitude only: the dissipation peak
//!   lies where `t_c` is several relaxation times, and since `t_c ~ v0^(-1/5)` a factor 10 in time
//!   is a factor 10^5 in velocity. The default scene's material given as a general material has
//!   its crossovers at 4.3e7 and 1.6e6 m/s (the glassy one below the relaxed one), while its CoR
//!   is smallest near 100 m/s (`p3 = 1` at 108 m/s). They are therefore not computed for the
//!   standard solid, whose `p3 = 1` velocity says it better.
//!
//! Both ends approach `e = 1` slowly: the dissipation goes as `tau / t_c ~ v0^(1/5)` on the
//! relaxed side and as `t_c / tau ~ v0^(-1/5)` on the glassy side, so `1 - e` falls by only about
//! 0.63 per decade of velocity (the default scene: `e = 0.97` at `1e-8` m/s, `0.99` at `1e14` m/s).

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::io::output::fmt;
use crate::io::plot::{cor_chart_svg, velocity_span, CorLine, Shaded, COR_AXIS_TOP};
use crate::model::hertz::HERTZ_I;
use crate::model::impact::Impact;
use crate::model::validity::Validity;
use crate::solvers::{solve, SolveOptions};
use plotters::style::RGBColor;

/// The CSV header of `curve.csv`.
pub const CSV_HEADER: &str =
    "v0,cor,contact_time,max_force,max_compression,contact_radius_ratio,indentation_ratio";

/// Largest number of velocities of one curve.
pub const MAX_VELOCITIES: usize = 100_000;

/// The option name used in error messages.
const FIELD: &str = "--v0";

/// Velocities of a curve when `--v0 MIN:MAX` leaves out `N` (`curve`, `dem` and the Python
/// package alike).
pub const DEFAULT_VELOCITIES: usize = 50;

/// Impact velocities `MIN:MAX:N` (m/s): `N` values from `MIN` to `MAX`, both included, evenly
/// spaced in `v0` or, with `log`, in `ln v0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VelocityRange {
    /// Smallest velocity (m/s), `0 < min < max`.
    pub min: f64,
    /// Largest velocity (m/s), finite.
    pub max: f64,
    /// Number of velocities, `2 <= n <= 100000`.
    pub n: usize,
    /// Log spacing (else linear).
    pub log: bool,
}

impl VelocityRange {
    /// Parse `MIN:MAX[:N]`, `N` = [`DEFAULT_VELOCITIES`] when left out (the grammar of every
    /// `--v0`). Requires finite `0 < MIN < MAX` and `2 <= N <= 100000`: a curve needs two
    /// distinct ends, so `N = 1` is refused (solve one velocity with `run`). Every error names
    /// `--v0` and the part of it that is wrong.
    pub fn parse(s: &str, log: bool) -> Result<Self> {
        Self::parse_optional_n(s, log, DEFAULT_VELOCITIES)
    }

    /// Parse `MIN:MAX[:N]`: as [`VelocityRange::parse`], with `N = default_n` when it is left
    /// out.
    pub fn parse_optional_n(s: &str, log: bool, default_n: usize) -> Result<Self> {
        let bad = |what: &str| Error::Parse {
            what: FIELD,
            input: crate::error::escape_text(s),
            expected: format!(
                "MIN:MAX[:N] (m/s, 0 < MIN < MAX, 2 <= N <= {MAX_VELOCITIES}, N = {default_n} \
                 when left out); {}",
                crate::error::escape_text(what)
            ),
        };
        let parts: Vec<&str> = s.split(':').map(str::trim).collect();
        let default_text = default_n.to_string();
        let (a, b, n) = match parts.as_slice() {
            [a, b, n] => (*a, *b, *n),
            [a, b] => (*a, *b, default_text.as_str()),
            _ => return Err(bad("wrong number of ':'-separated parts")),
        };
        let num = |t: &str| -> Result<f64> {
            let v: f64 = t
                .parse()
                .map_err(|_| bad(&format!("'{t}' is not a number")))?;
            if v.is_finite() && v > 0.0 {
                Ok(v)
            } else {
                Err(Error::OutOfRange {
                    field: FIELD,
                    value: v,
                    allowed: "0 < velocity < inf (m/s)",
                })
            }
        };
        let (min, max) = (num(a)?, num(b)?);
        let n: i64 = n
            .parse()
            .map_err(|_| bad(&format!("N = '{n}' is not a whole number")))?;
        Self::checked(min, max, n, log, "run").map_err(|why| bad(&why))
    }

    /// The range `(MIN, MAX[, N])` given as numbers (the Python package's
    /// `dem(v0=(min, max, n))`), `N = default_n` when `None`: the checks of
    /// [`VelocityRange::parse`], but every error names `field` (e.g. `"v0"`) and the range as the
    /// tuple it was given as, never the command line's `--v0`.
    pub fn from_parts(
        field: &'static str,
        min: f64,
        max: f64,
        n: Option<i64>,
        default_n: usize,
        log: bool,
    ) -> Result<Self> {
        let given = match n {
            Some(n) => format!("({min:?}, {max:?}, {n})"),
            None => format!("({min:?}, {max:?})"),
        };
        let n = n.unwrap_or(default_n as i64);
        Self::checked(min, max, n, log, "impact").map_err(|why| Error::Parse {
            what: field,
            input: given,
            expected: format!(
                "(MIN, MAX) or (MIN, MAX, N) (m/s, 0 < MIN < MAX, 2 <= N <= {MAX_VELOCITIES}, \
                 N = {default_n} when left out); {why}"
            ),
        })
    }

    /// The range of the numbers `min`, `max`, `n`, or what is wrong with them, in words
    /// (`MIN = 2e0 is not below MAX = 1e0`); `one` is what to use for one velocity.
    fn checked(
        min: f64,
        max: f64,
        n: i64,
        log: bool,
        one: &str,
    ) -> std::result::Result<Self, String> {
        for (name, v) in [("MIN", min), ("MAX", max)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(format!(
                    "{name} = {v:e} is out of range: allowed 0 < velocity < inf (m/s)"
                ));
            }
        }
        if !(min < max) {
            return Err(format!("MIN = {min:e} is not below MAX = {max:e}"));
        }
        let n = match usize::try_from(n) {
            Ok(n) if (2..=MAX_VELOCITIES).contains(&n) => n,
            _ => {
                let hint = if n == 1 {
                    format!(" (one velocity: use {one})")
                } else {
                    String::new()
                };
                return Err(format!(
                    "N = {n} is out of range: allowed 2 <= N <= {MAX_VELOCITIES}{hint}"
                ));
            }
        };
        let r = Self { min, max, n, log };
        // log spacing of extreme ends must not round to equal or non-finite values
        let v = r.values();
        if v.iter().any(|x| !(x.is_finite() && *x > 0.0)) {
            return Err("the velocities are not all finite and positive".into());
        }
        Ok(r)
    }

    /// The velocities in increasing order, exact at both ends.
    pub fn values(&self) -> Vec<f64> {
        let last = self.n - 1;
        (0..self.n)
            .map(|i| {
                let f = i as f64 / last as f64;
                if i == 0 {
                    self.min
                } else if i == last {
                    self.max
                } else if self.log {
                    (self.min.ln() + (self.max.ln() - self.min.ln()) * f).exp()
                } else {
                    self.min + (self.max - self.min) * f
                }
            })
            .collect()
    }
}

/// One velocity of the curve (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveRow {
    /// Impact velocity (m/s).
    pub v0: f64,
    /// Coefficient of restitution.
    pub cor: f64,
    /// Contact time (s).
    pub contact_time: f64,
    /// Maximum contact force (N).
    pub max_force: f64,
    /// Maximum compression = maximum indentation depth (m).
    pub max_compression: f64,
    /// `a_max / R` ([`Validity::contact_radius_ratio`]).
    pub contact_radius_ratio: f64,
    /// `d_max / R` ([`Validity::indentation_ratio`]).
    pub indentation_ratio: f64,
    /// Transit time of shear waves over the contact against the contact time
    /// ([`Validity::wave_transit_ratio`]; `None` without a density).
    pub wave_transit_ratio: Option<f64>,
    /// Whether the answer at this velocity carries a validity warning ([`Validity`]).
    pub outside_validity: bool,
}

impl CurveRow {
    /// The row of `outcome` (SI) of `impact` at `v0`, with its validity measures.
    pub fn new(impact: &Impact, v0: f64, o: &crate::model::impact::Outcome) -> Self {
        let v = Validity::of(impact, o);
        CurveRow {
            v0,
            cor: o.cor,
            contact_time: o.contact_time,
            max_force: o.max_force,
            max_compression: o.max_indentation,
            contact_radius_ratio: v.contact_radius_ratio,
            indentation_ratio: v.indentation_ratio,
            wave_transit_ratio: v.wave_transit_ratio,
            outside_validity: !v.warnings.is_empty(),
        }
    }
}

/// The elastic limits of the curve and where the material leaves them (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Plane-strain modulus of the relaxed limit `v0 -> 0`, `E* = 4 G_eq(inf)` (Pa); 0 for a
    /// viscoelastic liquid (`g_inf = 0`), which has no relaxed limit.
    pub relaxed_modulus: f64,
    /// Plane-strain modulus of the glassy limit `v0 -> inf`, `E* = 4 G_eq(0)` (Pa).
    pub glassy_modulus: f64,
    /// Velocity (m/s) where `p3 = 1`: standard solid with `eta > 0` only.
    pub p3_unit_velocity: Option<f64>,
    /// Slowest relaxation time of `G_eq` (s); `None` for an elastic material.
    pub slowest_tau: Option<f64>,
    /// Fastest relaxation time of `G_eq` (s); `None` for an elastic material.
    pub fastest_tau: Option<f64>,
    /// General material only: velocity (m/s) where the Hertz contact time with the relaxed
    /// modulus equals the slowest relaxation time of `G_eq`.
    pub relaxed_crossover: Option<f64>,
    /// General material only: velocity (m/s) where the Hertz contact time with the glassy
    /// modulus equals the fastest relaxation time of `G_eq`.
    pub glassy_crossover: Option<f64>,
}

/// A computed curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Rows in velocity order.
    pub rows: Vec<CurveRow>,
    /// The limits.
    pub limits: Limits,
}

impl Curve {
    /// The row of smallest CoR (the first one on ties).
    pub fn min_cor(&self) -> Option<&CurveRow> {
        self.rows
            .iter()
            .reduce(|best, r| if r.cor < best.cor { r } else { best })
    }
}

/// `impact` with its velocity replaced by `v0` (m/s): same sphere(s) and material(s)
/// ([`Impact::at_velocity`]).
pub fn impact_at(impact: &Impact, v0: f64) -> Result<Impact> {
    impact.at_velocity(v0)
}

/// Velocity (m/s) where the Hertz contact time with plane-strain modulus `e_star` (Pa) equals
/// `tau` (s): `v0 = (2 I)^5 (5 m / (4 k))^2 / tau^5`, computed in logs; `None` when not finite.
pub fn hertz_crossover(mass: f64, radius: f64, e_star: f64, tau: f64) -> Option<f64> {
    let k = 4.0 / 3.0 * e_star * radius.sqrt();
    let ln_v = 5.0 * (2.0 * HERTZ_I).ln() + 2.0 * (5.0 * mass / (4.0 * k)).ln() - 5.0 * tau.ln();
    let v = ln_v.exp();
    (v.is_finite() && v > 0.0).then_some(v)
}

/// The limits of `impact`'s material (its velocity only enters through `p3`, see
/// [`Limits::p3_unit_velocity`], and the result does not depend on it).
pub fn limits(impact: &Impact) -> Limits {
    let g = impact.equivalent_relaxation();
    let (m, r) = (impact.sphere().mass(), impact.sphere().radius());
    let relaxed_modulus = impact.relaxed_effective_modulus();
    let glassy_modulus = 4.0 * g.glassy();
    let taus = g
        .terms
        .iter()
        .filter(|t| t.coefficient > 0.0)
        .map(|t| t.tau);
    let slowest_tau = taus.clone().reduce(f64::max);
    let fastest_tau = taus.reduce(f64::min);
    let general = impact.general_material().is_some();
    let p3_unit_velocity = impact.groups().and_then(|gr| {
        // p3 ~ v0^(1/5): p3(v) = 1 at v = v0 / p3(v0)^5
        let v = (impact.velocity().ln() - 5.0 * gr.p3.ln()).exp();
        (gr.p3 > 0.0 && v.is_finite() && v > 0.0).then_some(v)
    });
    Limits {
        relaxed_modulus,
        glassy_modulus,
        p3_unit_velocity,
        slowest_tau,
        fastest_tau,
        relaxed_crossover: slowest_tau
            .filter(|_| general)
            .and_then(|t| hertz_crossover(m, r, relaxed_modulus, t)),
        glassy_crossover: fastest_tau
            .filter(|_| general)
            .and_then(|t| hertz_crossover(m, r, glassy_modulus, t)),
    }
}

/// Solve `impact` (its velocity replaced) at every velocity of `range` with `opts` (histories
/// off), in parallel; `progress` is called once per solved velocity. A velocity whose solve fails
/// fails the curve with that velocity named (the first failing one in velocity order).
pub fn run(
    impact: &Impact,
    opts: &SolveOptions,
    range: &VelocityRange,
    progress: &(dyn Fn() + Sync),
) -> Result<Curve> {
    let rows = run_velocities(impact, opts, &range.values(), progress).map_err(|(_, e)| e)?;
    Ok(Curve {
        rows,
        limits: limits(impact),
    })
}

/// Solve `impact` (its velocity replaced) at each of `velocities` (m/s, any order) with `opts`
/// (histories off), in parallel; rows in the order of `velocities`, each bit-identical to
/// [`solve`] at that velocity. `progress` is called once per solved velocity. The error is that
/// of the first failing velocity in input order, with its index; its message names the velocity
/// (`at v0 = ... m/s: ...`), not the flag: the range was valid, the solve at it failed. [`run`] is this on a [`VelocityRange`].
pub fn run_velocities(
    impact: &Impact,
    opts: &SolveOptions,
    velocities: &[f64],
    progress: &(dyn Fn() + Sync),
) -> std::result::Result<Vec<CurveRow>, (usize, Error)> {
    let opts = SolveOptions {
        history: false,
        ..*opts
    };
    opts.validate().map_err(|e| (0, e))?;
    let results: Vec<Result<CurveRow>> = velocities
        .par_iter()
        .map(|&v0| {
            let row = impact_at(impact, v0)
                .and_then(|i| solve(&i, &opts).map(|o| CurveRow::new(&i, v0, &o)))
                .map_err(|e| e.at(format!("at v0 = {v0:e} m/s")));
            progress();
            row
        })
        .collect();
    results
        .into_iter()
        .enumerate()
        .map(|(i, r)| r.map_err(|e| (i, e)))
        .collect()
}

/// The CSV text of the rows: header [`CSV_HEADER`], full-precision SI numbers; with a density
/// in the scene (every row has a [`CurveRow::wave_transit_ratio`]) one more column,
/// `wave_transit_ratio`.
pub fn csv_text(rows: &[CurveRow]) -> String {
    let waves = !rows.is_empty() && rows.iter().all(|r| r.wave_transit_ratio.is_some());
    let mut s = String::with_capacity(64 * (rows.len() + 1));
    s.push_str(CSV_HEADER);
    if waves {
        s.push_str(",wave_transit_ratio");
    }
    s.push('\n');
    for r in rows {
        s.push_str(&format!(
            "{},{},{},{},{},{},{}",
            fmt(r.v0),
            fmt(r.cor),
            fmt(r.contact_time),
            fmt(r.max_force),
            fmt(r.max_compression),
            fmt(r.contact_radius_ratio),
            fmt(r.indentation_ratio)
        ));
        if let (true, Some(w)) = (waves, r.wave_transit_ratio) {
            s.push(',');
            s.push_str(&fmt(w));
        }
        s.push('\n');
    }
    s
}

/// Files written by [`write_outputs`].
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    /// `DIR/curve.csv`.
    pub csv: PathBuf,
    /// `DIR/curve.svg`.
    pub svg: PathBuf,
}

/// Write `dir/curve.csv` and `dir/curve.svg` (log velocity axis with `log`). Both are rendered
/// in memory first and written atomically, so an error leaves no partial file.
/// The plot's title names the scene, `name` (its file stem, or `"default scene"`).
pub fn write_outputs(dir: &Path, curve: &Curve, log: bool, name: &str) -> Result<Written> {
    let csv = dir.join("curve.csv");
    let svg = dir.join("curve.svg");
    let csv_body = csv_text(&curve.rows);
    let svg_body = cor_curve_svg(&svg, curve, log, name)?;
    crate::io::output::write_all_atomic(&[
        (csv.as_path(), csv_body.as_bytes()),
        (svg.as_path(), svg_body.as_bytes()),
    ])?;
    Ok(Written { csv, svg })
}

/// A few lines describing the curve for the terminal.
pub fn summary(curve: &Curve, written: Option<&Written>) -> String {
    let mut out = String::new();
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<28}{v}\n"));
    line("velocities", format!("{}", curve.rows.len()));
    if let Some(r) = curve.min_cor() {
        line(
            "minimum CoR",
            format!("{:.6} at v0 = {:.4e} m/s", r.cor, r.v0),
        );
    }
    if let (Some(a), Some(b)) = (curve.rows.first(), curve.rows.last()) {
        line(
            "CoR at the ends",
            format!(
                "{:.6} (v0 = {:.4e} m/s), {:.6} (v0 = {:.4e} m/s)",
                a.cor, a.v0, b.cor, b.v0
            ),
        );
    }
    let l = &curve.limits;
    if let Some(v) = l.p3_unit_velocity {
        line("p3 = 1 at", format!("{v:.4e} m/s"));
    }
    let at = |what: &str, x: Option<f64>| {
        x.map_or(String::new(), |x| {
            format!("; Hertz t_c = {what} tau at {x:.4e} m/s")
        })
    };
    line(
        "relaxed limit (v0 -> 0)",
        if l.relaxed_modulus == 0.0 {
            "does not apply: g_inf = 0, a viscoelastic liquid has no relaxed modulus".to_string()
        } else {
            format!(
                "E* = {:.4e} Pa, e -> 1{}",
                l.relaxed_modulus,
                at("slowest", l.relaxed_crossover)
            )
        },
    );
    line(
        "glassy limit (v0 -> inf)",
        format!(
            "E* = {:.4e} Pa, e -> 1{}",
            l.glassy_modulus,
            at("fastest", l.glassy_crossover)
        ),
    );
    if let Some(w) = validity_warning(&curve.rows) {
        line("warning", format!("{w}: shaded on the plot"));
    }
    if let Some(w) = written {
        line("curve written to", w.csv.display().to_string());
        line("plot written to", w.svg.display().to_string());
    }
    out
}

/// A warning when some velocities of `rows` lie outside the model's validity ([`Validity`]):
/// how many, from which velocity, and the worst measures there that fail
/// ([`crate::model::validity::worst_measures`]).
pub fn validity_warning(rows: &[CurveRow]) -> Option<String> {
    let out: Vec<&CurveRow> = rows.iter().filter(|r| r.outside_validity).collect();
    let first = out.first()?;
    let worst = crate::model::validity::worst_measures(
        out.iter()
            .map(|r| (r.contact_radius_ratio, r.wave_transit_ratio)),
    );
    Some(format!(
        "{} of {} velocities lie outside the model's validity (from v0 = {:.4e} m/s; {worst}; \
         `run --json` at one of them says why)",
        out.len(),
        rows.len(),
        first.v0
    ))
}

/// The SVG text of a CoR-against-velocity curve : `e(v0)` on a linear or (with
/// `log`) logarithmic velocity axis, `e` from 0 to 1 (with a little headroom so that the line
/// `e = 1` stays visible), the elastic limits `e = 1` as a horizontal line and, where they fall
/// inside the velocity range, vertical markers at the `p3 = 1` velocity and at the velocities
/// where the Hertz contact time meets the slowest / fastest relaxation time. Rendered in memory
/// only; `path` names the file in errors (the caller writes it, atomically).
pub fn cor_curve_svg(path: &Path, curve: &Curve, log: bool, name: &str) -> Result<String> {
    let (x0, x1) = velocity_span(path, &curve.rows.iter().map(|r| r.v0).collect::<Vec<_>>())?;
    let label = if curve.limits.relaxed_modulus == 0.0 {
        "elastic limit (glassy v0 -> inf; a liquid has no relaxed limit)"
    } else {
        "elastic limits (relaxed v0 -> 0, glassy v0 -> inf)"
    };
    let mut lines: Vec<CorLine> = vec![(
        label.to_string(),
        vec![(x0, 1.0), (x1, 1.0)],
        RGBColor(120, 120, 120),
        2,
    )];
    let l = &curve.limits;
    let markers = [
        (l.p3_unit_velocity, "p3 = 1", RGBColor(200, 30, 30)),
        (
            l.relaxed_crossover,
            "Hertz contact time (relaxed) = slowest tau",
            RGBColor(30, 140, 60),
        ),
        (
            l.glassy_crossover,
            "Hertz contact time (glassy) = fastest tau",
            RGBColor(150, 60, 170),
        ),
    ];
    for (v, name, color) in markers {
        if let Some(v) = v.filter(|v| *v >= x0 && *v <= x1) {
            lines.push((
                format!("{name} (v0 = {v:.3e} m/s)"),
                vec![(v, 0.0), (v, COR_AXIS_TOP)],
                color,
                1,
            ));
        }
    }
    lines.push((
        "e(v0)".to_string(),
        curve.rows.iter().map(|r| (r.v0, r.cor)).collect(),
        RGBColor(30, 80, 200),
        2,
    ));
    // velocities outside the model's validity, shaded half way to their neighbours
    let rows = &curve.rows;
    let mut spans: Vec<(f64, f64)> = Vec::new();
    for (k, r) in rows.iter().enumerate().filter(|(_, r)| r.outside_validity) {
        let mid = |a: f64, b: f64| if log { (a * b).sqrt() } else { 0.5 * (a + b) };
        let lo = if k == 0 {
            r.v0
        } else {
            mid(rows[k - 1].v0, r.v0)
        };
        let hi = rows.get(k + 1).map_or(r.v0, |n| mid(r.v0, n.v0));
        match spans.last_mut() {
            Some(last) if last.1 >= lo => last.1 = hi,
            _ => spans.push((lo, hi)),
        }
    }
    let shaded = Shaded {
        spans,
        label: "outside the model's validity (warnings: contact too large or waves too slow)"
            .into(),
    };
    cor_chart_svg(
        path,
        &format!("Coefficient of restitution against impact velocity: {name}"),
        (x0, x1),
        log,
        &lines,
        &shaded,
    )
}
