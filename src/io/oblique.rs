//! The outputs of oblique impacts (docs/theory.md §14): the summary lines, the JSON keys and
//! the history CSV with the tangential columns.
//!
//! JSON keys (SI; added when the scene has a tangential velocity, a spin or friction):
//! `tangential_cor`, `tangential_cor_centre` (null when the velocity they divide by is zero),
//! `spin_after` (rad/s), `rebound_angle_deg`, `contact_patch_rebound_angle_deg`,
//! `friction_dissipated_energy` (J), `tangential_impulse` (N s), `friction_coefficient`,
//! `tangential_error_estimate` (absolute, of `tangential_cor`; null when not estimated).

use crate::io::output::{fmt, impact_value_of, summary, OutputFile};
use crate::model::impact::{History, Impact};
use crate::model::oblique::{Oblique, TangentialHistory};
use crate::solvers::oblique::ObliqueOutcome;
use crate::solvers::SolveOptions;

/// True when a scene's outputs include the tangential ones.
pub fn reports_tangential(oblique: &Oblique) -> bool {
    oblique.is_oblique() || oblique.friction > 0.0
}

fn finite(x: f64) -> serde_json::Value {
    if x.is_finite() {
        serde_json::json!(x)
    } else {
        serde_json::Value::Null
    }
}

/// The JSON object of `run --json` for an oblique scene: [`crate::io::output::impact_json`]'s
/// keys with the tangential ones of the module docs (and `solver_reason` saying why `auto`
/// chose `mdr`); `scene_warnings` (the scene's own, [`crate::io::scene::Scene::warnings`])
/// come first in `warnings`.
pub fn oblique_json(
    impact: &Impact,
    opts: &SolveOptions,
    oblique: &Oblique,
    o: &ObliqueOutcome,
    scene_warnings: &[String],
) -> String {
    let mut v = impact_value_of(impact, opts, &o.normal);
    if let Some(map) = v.as_object_mut() {
        if let Some(list) = map.get_mut("warnings").and_then(|w| w.as_array_mut()) {
            list.splice(0..0, scene_warnings.iter().map(|w| w.as_str().into()));
        }
        if let Some(why) = o.reason {
            map.insert("solver_reason".into(), why.into());
            map.insert("fallback".into(), why.into());
        }
        if reports_tangential(oblique) {
            let t = &o.tangential;
            map.insert("tangential_cor".into(), finite(t.tangential_cor));
            map.insert(
                "tangential_cor_centre".into(),
                finite(t.tangential_cor_centre),
            );
            map.insert("spin_after".into(), finite(t.spin_after));
            map.insert("rebound_angle_deg".into(), finite(t.rebound_angle_deg));
            map.insert(
                "contact_patch_rebound_angle_deg".into(),
                finite(t.contact_patch_rebound_angle_deg),
            );
            map.insert(
                "friction_dissipated_energy".into(),
                finite(t.friction_dissipated_energy),
            );
            map.insert("tangential_impulse".into(), finite(t.impulse));
            map.insert("friction_coefficient".into(), oblique.friction.into());
            map.insert(
                "tangential_error_estimate".into(),
                serde_json::json!(o.tangential_error_estimate),
            );
        }
    }
    v.to_string()
}

/// The summary of `run` for an oblique scene: the normal summary (its solver line saying why
/// `auto` chose `mdr`) and the tangential lines.
pub fn oblique_summary(
    impact: &Impact,
    opts: &SolveOptions,
    oblique: &Oblique,
    o: &ObliqueOutcome,
) -> String {
    let mut out = summary(impact, opts, &o.normal);
    if let Some(why) = o.reason {
        out = out
            .replace("auto answered with mdr", why)
            .replace("auto answered with reference", why);
    }
    if !reports_tangential(oblique) {
        return out;
    }
    let t = &o.tangential;
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<28}{v}\n"));
    let num = |x: f64, unit: &str| {
        if x.is_finite() {
            format!("{x:.6e}{unit}")
        } else {
            "undefined (zero before)".into()
        }
    };
    line(
        "oblique inputs",
        format!(
            "mu = {}, v_t = {:.6e} m/s, spin = {:.6e} rad/s",
            oblique.friction, oblique.tangential_velocity, oblique.spin
        ),
    );
    line("tangential CoR (contact)", num(t.tangential_cor, ""));
    if let Some(e) = o.tangential_error_estimate {
        line("  estimated abs. error", format!("{e:.1e}"));
    }
    line("tangential CoR (centre)", num(t.tangential_cor_centre, ""));
    line("spin after", num(t.spin_after, " rad/s"));
    line("rebound angle (centre)", num(t.rebound_angle_deg, " deg"));
    line(
        "rebound angle (contact)",
        num(t.contact_patch_rebound_angle_deg, " deg"),
    );
    line(
        "friction dissipated energy",
        num(t.friction_dissipated_energy, " J"),
    );
    out
}

/// A history with the tangential columns:
/// `t,d,v,force,a,tangential_force,slip_radius,slip_velocity` (SI: s, m, m/s, N, m, N, m,
/// m/s); the rows of the two histories are the same solver steps.
pub fn oblique_history_csv_text(h: &History, t: &TangentialHistory) -> String {
    let mut out = String::from("t,d,v,force,a,tangential_force,slip_radius,slip_velocity\n");
    let n = h.len().min(t.t.len());
    for i in 0..n {
        out.push_str(&format!(
            "{},{},{},{},{},{},{},{}\n",
            fmt(h.t[i]),
            fmt(h.d[i]),
            fmt(h.v[i]),
            fmt(h.force[i]),
            fmt(h.a[i]),
            fmt(t.force[i]),
            fmt(t.slip_radius[i]),
            fmt(t.slip_velocity[i])
        ));
    }
    out
}

/// Replace the history file among a run's `files` (the one at `history_path`) by the CSV with
/// the tangential columns.
pub fn with_tangential_history(
    files: &mut [OutputFile],
    history_path: Option<&std::path::Path>,
    o: &ObliqueOutcome,
) {
    let (Some(path), Some(h), Some(t)) = (history_path, &o.normal.history, &o.history) else {
        return;
    };
    for f in files.iter_mut().filter(|f| f.path == path) {
        f.bytes = oblique_history_csv_text(h, t).into_bytes();
    }
}
