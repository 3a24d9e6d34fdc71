//! Oblique impacts against the incidence angle (`mdr-impact curve SCENE --angle MIN:MAX:N
//! --speed V`, docs/theory.md §14): the scene's impact at the speed `V` (m/s) arriving at the
//! angle `theta` from the normal, `v_n = V cos theta` and `v_t = V sin theta`, its friction,
//! spin, inertia factors, material(s) and solver kept; solved in parallel, rows in angle order.
//!
//! At `theta = 0` without spin the tangential ratios divide by zero and are `NaN` in the CSV.

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::error::{check, escape_text, Error, Result};
use crate::io::output::{fmt, write_atomic};
use crate::io::plot::line_chart_svg;
use crate::model::impact::Impact;
use crate::model::oblique::Oblique;
use crate::solvers::oblique::solve_oblique;
use crate::solvers::SolveOptions;

/// Header of `curve.csv` for an angle curve (the fixed interface).
pub const CSV_HEADER: &str = "angle_deg,cor,tangential_cor,tangential_cor_centre,\
rebound_angle_deg,contact_patch_rebound_angle_deg,spin_after";

/// Largest number of angles of one curve.
pub const MAX_ANGLES: usize = 10_000;

/// File names of the two plots beside `curve.csv`.
pub const TANGENTIAL_COR_SVG: &str = "tangential_cor.svg";
/// The contact-patch rebound angle against the incidence angle.
pub const REBOUND_ANGLE_SVG: &str = "rebound_angle.svg";

/// Incidence angles `MIN:MAX:N` (degrees from the normal): `0 <= MIN < MAX < 90`,
/// `2 <= N <= MAX_ANGLES`, evenly spaced, both ends included.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleRange {
    /// Smallest angle (degrees).
    pub min: f64,
    /// Largest angle (degrees).
    pub max: f64,
    /// Number of angles.
    pub n: usize,
}

impl AngleRange {
    /// Parse `MIN:MAX:N` (module docs for the ranges); errors name `--angle`.
    pub fn parse(s: &str) -> Result<Self> {
        let bad = || Error::Parse {
            what: "--angle",
            input: escape_text(s),
            expected: format!(
                "MIN:MAX:N in degrees from the normal with 0 <= MIN < MAX < 90 and \
                 2 <= N <= {MAX_ANGLES}"
            ),
        };
        let parts: Vec<&str> = s.split(':').map(str::trim).collect();
        let [min, max, n] = parts.as_slice() else {
            return Err(bad());
        };
        let min: f64 = min.parse().map_err(|_| bad())?;
        let max: f64 = max.parse().map_err(|_| bad())?;
        let n: usize = n.parse().map_err(|_| bad())?;
        if !(min >= 0.0 && min < max && max < 90.0 && (2..=MAX_ANGLES).contains(&n)) {
            return Err(bad());
        }
        Ok(Self { min, max, n })
    }

    /// The angles (degrees), both ends included.
    pub fn values(&self) -> Vec<f64> {
        crate::math::linspace(self.min, self.max, self.n)
    }
}

/// Check the speed of `--speed` (m/s, finite and positive).
pub fn check_speed(speed: f64) -> Result<f64> {
    crate::error::check("--speed", speed, speed > 0.0, "0 < speed < inf (m/s)")
}

/// One angle of the curve (SI; angles in degrees).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleRow {
    /// Incidence angle from the normal (degrees).
    pub angle_deg: f64,
    /// Normal coefficient of restitution.
    pub cor: f64,
    /// Contact-point tangential velocity after over before.
    pub tangential_cor: f64,
    /// Centre tangential velocity after over before.
    pub tangential_cor_centre: f64,
    /// Rebound angle of the centre (degrees).
    pub rebound_angle_deg: f64,
    /// Rebound angle of the contact point (degrees).
    pub contact_patch_rebound_angle_deg: f64,
    /// Spin after (rad/s).
    pub spin_after: f64,
}

/// The impact of `impact`'s impactor(s) and material(s) at `speed` (m/s) and `angle_deg`, with
/// `oblique`'s friction, spin and inertia factors.
pub fn at_angle(
    impact: &Impact,
    oblique: &Oblique,
    speed: f64,
    angle_deg: f64,
) -> Result<(Impact, Oblique)> {
    let th = angle_deg.to_radians();
    let imp = impact.at_velocity(speed * th.cos())?;
    let ob = Oblique {
        tangential_velocity: speed * th.sin(),
        ..*oblique
    };
    Ok((imp, ob))
}

/// Solve the curve (module docs); `tick` is called once per angle.
pub fn run(
    impact: &Impact,
    oblique: &Oblique,
    opts: &SolveOptions,
    range: &AngleRange,
    speed: f64,
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<AngleRow>> {
    run_angles(impact, oblique, opts, &range.values(), speed, tick)
}

/// [`run`] at the given angles (degrees, each in `[0, 90)`), in their order.
pub fn run_angles(
    impact: &Impact,
    oblique: &Oblique,
    opts: &SolveOptions,
    angles: &[f64],
    speed: f64,
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<AngleRow>> {
    let speed = check_speed(speed)?;
    for &a in angles {
        check(
            "angle",
            a,
            (0.0..90.0).contains(&a),
            "0 <= angle < 90 (degrees)",
        )?;
    }
    let mut opts = *opts;
    opts.history = false;
    angles
        .to_vec()
        .into_par_iter()
        .map(|angle| {
            let (imp, ob) = at_angle(impact, oblique, speed, angle)?;
            let o =
                solve_oblique(&imp, &ob, &opts).map_err(|e| e.at(format!("angle {angle} deg")))?;
            tick();
            let t = o.tangential;
            Ok(AngleRow {
                angle_deg: angle,
                cor: o.normal.cor,
                tangential_cor: t.tangential_cor,
                tangential_cor_centre: t.tangential_cor_centre,
                rebound_angle_deg: t.rebound_angle_deg,
                contact_patch_rebound_angle_deg: t.contact_patch_rebound_angle_deg,
                spin_after: t.spin_after,
            })
        })
        .collect()
}

/// The CSV text of a curve ([`CSV_HEADER`]); a ratio without a value (the tangential CoRs at
/// 0°, where the velocity they divide by is zero) is an empty cell, as it is `null` in JSON.
pub fn csv_text(rows: &[AngleRow]) -> String {
    let fmt = |x: f64| if x.is_finite() { fmt(x) } else { String::new() };
    let mut out = format!("{CSV_HEADER}\n");
    for r in rows {
        out.push_str(&format!(
            "{},{},{},{},{},{},{}\n",
            fmt(r.angle_deg),
            fmt(r.cor),
            fmt(r.tangential_cor),
            fmt(r.tangential_cor_centre),
            fmt(r.rebound_angle_deg),
            fmt(r.contact_patch_rebound_angle_deg),
            fmt(r.spin_after)
        ));
    }
    out
}

/// Write `dir/curve.csv`, `dir/tangential_cor.svg` and `dir/rebound_angle.svg`; returns the
/// paths written.
pub fn write_outputs(dir: &Path, rows: &[AngleRow], name: &str) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let csv = dir.join("curve.csv");
    let text = csv_text(rows);
    write_atomic(&csv, |w| {
        w.write_all(text.as_bytes()).map_err(|e| Error::io(&csv, e))
    })?;
    let pts = |f: fn(&AngleRow) -> f64| -> Vec<(f64, f64)> {
        rows.iter()
            .map(|r| (r.angle_deg, f(r)))
            .filter(|p| p.1.is_finite())
            .collect()
    };
    let tc = dir.join(TANGENTIAL_COR_SVG);
    line_chart_svg(
        &tc,
        &format!("Tangential CoR against incidence angle ({name})"),
        "incidence angle from the normal (deg)",
        "tangential CoR",
        &[
            ("contact point".into(), pts(|r| r.tangential_cor)),
            ("centre".into(), pts(|r| r.tangential_cor_centre)),
        ],
    )?;
    let ra = dir.join(REBOUND_ANGLE_SVG);
    line_chart_svg(
        &ra,
        &format!("Rebound angle against incidence angle ({name})"),
        "incidence angle from the normal (deg)",
        "rebound angle (deg)",
        &[
            (
                "contact patch".into(),
                pts(|r| r.contact_patch_rebound_angle_deg),
            ),
            ("centre".into(), pts(|r| r.rebound_angle_deg)),
        ],
    )?;
    Ok(vec![csv, tc, ra])
}
