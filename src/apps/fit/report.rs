//! What `fit` prints and writes: the summary, the TOML material block, the JSON object and the
//! plot of the data against the fitted `e(v0)` (and `t_c(v0)`) with its 95 % band.

use std::path::{Path, PathBuf};

use plotters::prelude::*;
use rayon::prelude::*;

use super::{Estimate, FitResult, ModelKind, Prediction};
use crate::error::{Error, Result};

/// Points of each fitted curve in the plot.
pub const PLOT_POINTS: usize = 41;

fn json_number(x: f64) -> serde_json::Value {
    serde_json::Number::from_f64(x).map_or(serde_json::Value::Null, serde_json::Value::Number)
}

fn estimate_json(e: &Estimate, conditional_on_nu: Option<f64>) -> serde_json::Value {
    serde_json::json!({
        "value": e.value.map(json_number),
        "ci95": e.ci95.map(|(a, b)| vec![json_number(a), json_number(b)]),
        "identifiable": e.identifiable,
        "fixed": e.fixed,
        "unit": e.unit,
        "note": e.note,
        "conditional_on": conditional_on_nu.map(|nu| serde_json::json!({"nu": json_number(nu)})),
    })
}

/// The `nu` a parameter estimate is conditional on ([`FitResult::conditional_on_nu`]): fitted
/// moduli and viscosities only.
fn condition(r: &FitResult, e: &Estimate) -> Option<f64> {
    r.conditional_on_nu.filter(|_| {
        !e.fixed
            && e.value.is_some()
            && e.unit != "1"
            && r.parameters.iter().any(|p| p.name == e.name)
    })
}

/// The JSON object of `fit --json`: `parameters` and `groups` (each `{"value", "ci95",
/// "identifiable", "fixed", "unit", "note"}`; not determined: `ci95` null unless closed on a
/// flat shoulder, `value` the minimum's location or null along a null direction),
/// `rms_residual`, plus `model`, `taus` (s, Prony), `k_0` (Pa, when fixed), `dof`,
/// `noise_scale`, `singular_values`, `verdict`, `conditional_on_nu` (the `nu` every fitted
/// modulus holds for when the data do not determine `nu`, else null; each such parameter also
/// has `conditional_on: {"nu": ...}`), `goodness` (`chi2`, `dof`, `p_value` with standard
/// deviations given, else null), `warnings` and `residuals` (`observation`, `quantity`,
/// `measured`, `model`, `weighted`). SI units.
pub fn json(r: &FitResult) -> serde_json::Value {
    let mut parameters = serde_json::Map::new();
    for e in &r.parameters {
        parameters.insert(e.name.clone(), estimate_json(e, condition(r, e)));
    }
    let mut groups = serde_json::Map::new();
    for e in &r.groups {
        groups.insert(e.name.clone(), estimate_json(e, None));
    }
    let residuals: Vec<serde_json::Value> = r
        .residuals
        .iter()
        .map(|x| {
            serde_json::json!({
                "observation": x.observation,
                "quantity": x.quantity,
                "measured": json_number(x.measured),
                "model": json_number(x.model),
                "weighted": json_number(x.weighted),
            })
        })
        .collect();
    serde_json::json!({
        "model": model_name(r),
        "parameters": parameters,
        "groups": groups,
        "rms_residual": json_number(r.rms_residual),
        "dof": r.dof,
        "noise_scale": r.noise_scale.map(json_number),
        "taus": r.model.taus.iter().map(|t| json_number(*t)).collect::<Vec<_>>(),
        "k_0": r.model.k_0.map(json_number),
        "singular_values": r.singular_values.iter().map(|s| json_number(*s)).collect::<Vec<_>>(),
        "verdict": r.verdict,
        "conditional_on_nu": r.conditional_on_nu.map(json_number),
        "goodness": r.goodness.map(|g| serde_json::json!({
            "chi2": json_number(g.chi2),
            "dof": g.dof,
            "p_value": json_number(g.p_value),
        })),
        "warnings": r.warnings,
        "residuals": residuals,
    })
}

fn model_name(r: &FitResult) -> String {
    match r.model.kind {
        ModelKind::StandardSolid => "standard-solid".into(),
        ModelKind::Prony { n } => format!("prony:{n}"),
    }
}

fn value_text(e: &Estimate) -> String {
    match (e.value, e.ci95) {
        (None, _) => "not determined".into(),
        (Some(v), _) if e.fixed => format!("{v:.6e} (fixed)"),
        (Some(v), Some((a, b))) => format!("{v:.6e}  95 % [{a:.4e}, {b:.4e}]"),
        (Some(v), None) => format!("{v:.6e}  (no interval)"),
    }
}

/// The human-readable summary.
pub fn summary(r: &FitResult, written: Option<&Written>) -> String {
    let mut out = String::new();
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<34}{v}\n"));
    line("model", model_name(r));
    if let Some(k) = r.model.k_0 {
        line("k_0 (fixed)", format!("{k:.6e} Pa"));
    }
    if !r.model.taus.is_empty() {
        let t: Vec<String> = r.model.taus.iter().map(|t| format!("{t:.3e}")).collect();
        line("tau_i (fixed, s)", t.join(", "));
    }
    line(
        "data",
        format!(
            "{} drops, {} measured values, {} setup(s)",
            r.data.observations.len(),
            r.residuals.len(),
            r.data
                .setups
                .iter()
                .enumerate()
                .filter(|(i, _)| r.data.observations.iter().any(|o| o.setup == *i))
                .count()
        ),
    );
    for e in r.parameters.iter().chain(&r.groups) {
        let flag = if e.identifiable {
            ""
        } else {
            "  [not identifiable]"
        };
        let cond = match condition(r, e) {
            Some(nu) => format!("  (conditional on nu = {nu:.4})"),
            None => String::new(),
        };
        line(
            &format!("{} ({})", e.name, e.unit),
            format!("{}{cond}{flag}", value_text(e)),
        );
        if !e.identifiable && !e.note.is_empty() {
            line("", format!("  {}", e.note));
        }
    }
    line("rms residual", format!("{:.4e} (weighted)", r.rms_residual));
    line(
        "noise scale",
        match r.noise_scale {
            Some(s) if r.data.noise_known() => format!("{s} (standard deviations given)"),
            Some(s) => format!("{s:.4e} (estimated, {} degrees of freedom)", r.dof),
            None => "unknown (no degrees of freedom)".into(),
        },
    );
    let sv: Vec<String> = r
        .singular_values
        .iter()
        .map(|s| format!("{s:.3e}"))
        .collect();
    line("singular values", sv.join(", "));
    line("identifiability", r.verdict.clone());
    if let Some(g) = r.goodness {
        line(
            "goodness of fit",
            format!(
                "chi^2 = {:.4} on {} degrees of freedom, p = {:.3e}",
                g.chi2, g.dof, g.p_value
            ),
        );
    }
    for w in &r.warnings {
        line("warning", w.clone());
    }
    out.push_str("residuals (drop, quantity, measured, model, weighted):\n");
    for x in &r.residuals {
        out.push_str(&format!(
            "  {:>3}  {:<12} {:.6e}  {:.6e}  {:+.3e}\n",
            x.observation + 1,
            x.quantity,
            x.measured,
            x.model,
            x.weighted
        ));
    }
    out.push_str("\nmaterial block:\n");
    out.push_str(&toml_block(r));
    if let Some(w) = written {
        out.push('\n');
        let mut line = |k: &str, v: String| out.push_str(&format!("{k:<34}{v}\n"));
        line("material written to", w.toml.display().to_string());
        line("plot written to", w.svg.display().to_string());
    }
    out
}

/// The TOML `[material]` block of the estimate, ready to paste into a scene. A parameter the
/// data do not determine is not given a number: its line is a comment that says how to complete
/// it from the determined groups.
pub fn toml_block(r: &FitResult) -> String {
    let mut s = String::from("# fitted by mdr-impact fit (SI units)\n");
    let get = |name: &str| r.parameters.iter().find(|e| e.name == name);
    let known =
        |name: &str| get(name).and_then(|e| e.value.filter(|_| e.ci95.is_some() || e.fixed));
    let line = |s: &mut String, key: &str, name: &str, unit: &str| match get(name) {
        Some(e) if e.value.is_some() => {
            s.push_str(&format!("{key} = {:e}", e.value.unwrap_or(f64::NAN)));
            let tag = if e.fixed {
                "fixed".to_string()
            } else if let Some(nu) = condition(r, e) {
                format!("{unit}, conditional on poisson = {nu:.4}, which the data do not determine")
            } else if e.identifiable {
                unit.to_string()
            } else {
                format!("{unit}, poorly determined")
            };
            s.push_str(&format!("    # {tag}\n"));
        }
        _ => s.push_str(&format!(
            "# {key} = ?    # {unit}: not determined by the data\n"
        )),
    };
    let bulk = |s: &mut String| match (r.model.k_0, r.conditional_on_nu) {
        (Some(k), _) => s.push_str(&format!("k_0 = {k:e}    # Pa, fixed\n")),
        (None, Some(nu)) => s.push_str(&format!(
            "poisson = {nu:e}    # not determined by the data: the moduli above hold for this \
             value only\n"
        )),
        (None, None) => line(s, "poisson", "nu", "static Poisson ratio"),
    };
    match r.model.kind {
        ModelKind::StandardSolid => {
            s.push_str("[material]\n");
            line(&mut s, "g_inf", "g_inf", "Pa");
            line(&mut s, "g_1", "g_1", "Pa");
            line(&mut s, "eta", "eta", "Pa s");
            bulk(&mut s);
            if known("g_inf").is_none() {
                let g = |n: &str| r.get(n).and_then(|e| e.value);
                if let (Some(p2), Some(c)) = (g("p2"), g("eta_over_g_inf_3_5")) {
                    s.push_str(&format!(
                        "# CoR data fix only the groups: choose g_inf, then g_1 = g_inf / {p2:e} \
                         and eta = {c:e} * g_inf^(3/5)\n"
                    ));
                }
            }
        }
        ModelKind::Prony { n } => {
            s.push_str("[material.shear]\n");
            line(&mut s, "g_inf", "g_inf", "Pa");
            let all = (1..=n).all(|i| known(&format!("g_{i}")).is_some());
            if all {
                let terms: Vec<String> = (0..n)
                    .map(|i| format!("[{:e}, {:e}]", r.values[1 + i], r.model.taus[i]))
                    .collect();
                s.push_str(&format!(
                    "terms = [{}]    # [g_i (Pa), tau_i (s)]\n",
                    terms.join(", ")
                ));
            } else {
                s.push_str("# terms: not all moduli g_i are determined by the data\n");
                for i in 1..=n {
                    line(
                        &mut s,
                        &format!("# g_{i} (tau = {:e} s)", r.model.taus[i - 1]),
                        &format!("g_{i}"),
                        "Pa",
                    );
                }
            }
            s.push_str("[material.bulk]\n");
            bulk(&mut s);
        }
    }
    s
}

/// Files written by [`write_outputs`].
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    /// `DIR/fit.toml`.
    pub toml: PathBuf,
    /// `DIR/fit.svg`.
    pub svg: PathBuf,
}

/// A fitted curve of the plot: the setup's index in [`crate::apps::fit::Data::setups`], its name and
/// the predictions.
pub type Curve = (usize, String, Vec<Prediction>);

/// The fitted curves for the plot: per setup used, `PLOT_POINTS` log-spaced velocities over the
/// data's range (predicted in parallel, rayon; in order, and the error of a failed prediction is
/// the first in that order).
pub fn curves(r: &FitResult) -> Result<Vec<Curve>> {
    let mut out = Vec::new();
    for (i, s) in r.data.setups.iter().enumerate() {
        let v: Vec<f64> = r
            .data
            .observations
            .iter()
            .filter(|o| o.setup == i)
            .map(|o| o.v0)
            .collect();
        if v.is_empty() {
            continue;
        }
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(0.0, f64::max);
        let (lo, hi) = if lo < hi {
            (lo, hi)
        } else {
            (lo / 2.0, hi * 2.0)
        };
        let pts = (0..PLOT_POINTS)
            .into_par_iter()
            .map(|k| {
                let x = (lo.ln() + (hi / lo).ln() * k as f64 / (PLOT_POINTS - 1) as f64).exp();
                r.predict(s.sphere, x)
            })
            .collect::<Vec<Result<_>>>()
            .into_iter()
            .collect::<Result<Vec<_>>>()?;
        out.push((i, s.name.clone(), pts));
    }
    Ok(out)
}

/// The SVG of the data (with one standard deviation where given) against the fitted curves with
/// the 95 % band (a second panel for the
/// contact time when the data have contact times). Rendered in memory; `path` names errors.
pub fn svg(path: &Path, r: &FitResult, curves: &[Curve]) -> Result<String> {
    let e = |x: &dyn std::fmt::Display| Error::io(path, x);
    let q = r.quantile.unwrap_or(0.0);
    let with_t = r.data.has_contact_times();
    let obs = &r.data.observations;
    let (mut x0, mut x1) = (f64::INFINITY, 0.0f64);
    for (_, _, c) in curves {
        for p in c {
            x0 = x0.min(p.v0);
            x1 = x1.max(p.v0);
        }
    }
    if !(x0 < x1) {
        return Err(Error::NotSupported {
            solver: "fit plot",
            what: "nothing to plot (one velocity)".into(),
        }
        .at(path.display().to_string()));
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, if with_t { 900 } else { 560 }))
            .into_drawing_area();
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let panels = if with_t {
            root.split_evenly((2, 1))
        } else {
            vec![root.clone()]
        };
        for (k, area) in panels.iter().enumerate() {
            let time = k == 1;
            let ms = |t: f64| t * 1e3;
            let pick = |p: &Prediction, s: f64| {
                if time {
                    ms(p.contact_time + s * p.sd.map_or(0.0, |d| d.1))
                } else {
                    p.cor + s * p.sd.map_or(0.0, |d| d.0)
                }
            };
            let (mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY);
            for (_, _, c) in curves {
                for p in c {
                    y0 = y0.min(pick(p, -q));
                    y1 = y1.max(pick(p, q));
                }
            }
            for o in obs {
                let (y, sd) = if time {
                    match o.contact_time {
                        Some(t) => (ms(t), ms(o.contact_time_sd.unwrap_or(0.0))),
                        None => continue,
                    }
                } else {
                    (o.cor, o.cor_sd.unwrap_or(0.0))
                };
                y0 = y0.min(y - 2.0 * sd);
                y1 = y1.max(y + 2.0 * sd);
            }
            if !(y0 < y1) {
                y1 = y0 + 1.0;
            }
            let pad = 0.05 * (y1 - y0);
            let mut chart = ChartBuilder::on(area)
                .caption(
                    if time {
                        "Contact time: data and fit (95 % band)"
                    } else {
                        "Coefficient of restitution: data and fit (95 % band)"
                    },
                    ("sans-serif", 20),
                )
                .margin(12)
                .x_label_area_size(44)
                .y_label_area_size(70)
                .build_cartesian_2d((x0..x1).log_scale(), (y0 - pad)..(y1 + pad))
                .map_err(|x| e(&x))?;
            chart
                .configure_mesh()
                .x_desc("impact velocity v0 (m/s)")
                .y_desc(if time { "contact time (ms)" } else { "CoR e" })
                .draw()
                .map_err(|x| e(&x))?;
            for (i, (setup, name, c)) in curves.iter().enumerate() {
                let color = Palette99::pick(i).to_rgba();
                if q > 0.0 {
                    let band: Vec<(f64, f64)> = c
                        .iter()
                        .map(|p| (p.v0, pick(p, q)))
                        .chain(c.iter().rev().map(|p| (p.v0, pick(p, -q))))
                        .collect();
                    chart
                        .draw_series(std::iter::once(Polygon::new(band, color.mix(0.2).filled())))
                        .map_err(|x| e(&x))?;
                }
                chart
                    .draw_series(LineSeries::new(
                        c.iter().map(|p| (p.v0, pick(p, 0.0))),
                        color.stroke_width(2),
                    ))
                    .map_err(|x| e(&x))?
                    .label(format!("fit, {name}"))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                    });
                // the drops of this setup, with one standard deviation where it is known
                let pts: Vec<(f64, f64, f64)> = obs
                    .iter()
                    .filter(|o| o.setup == *setup)
                    .filter_map(|o| {
                        if time {
                            o.contact_time
                                .map(|t| (o.v0, ms(t), ms(o.contact_time_sd.unwrap_or(0.0))))
                        } else {
                            Some((o.v0, o.cor, o.cor_sd.unwrap_or(0.0)))
                        }
                    })
                    .collect();
                chart
                    .draw_series(pts.iter().filter(|p| p.2 > 0.0).map(|&(x, y, sd)| {
                        PathElement::new(vec![(x, y - sd), (x, y + sd)], BLACK.stroke_width(1))
                    }))
                    .map_err(|x| e(&x))?;
                chart
                    .draw_series(
                        pts.iter()
                            .map(|&(x, y, _)| Circle::new((x, y), 4, BLACK.filled())),
                    )
                    .map_err(|x| e(&x))?;
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::LowerLeft)
                .border_style(BLACK)
                .background_style(WHITE.mix(0.85))
                .draw()
                .map_err(|x| e(&x))?;
        }
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}

/// Write `dir/fit.toml` (the material block) and `dir/fit.svg` (the plot), both rendered in
/// memory first and written atomically; on an error neither is left behind.
pub fn write_outputs(dir: &Path, r: &FitResult) -> Result<Written> {
    let toml = dir.join("fit.toml");
    let svg_path = dir.join("fit.svg");
    let c = curves(r)?;
    let svg_body = svg(&svg_path, r, &c)?;
    let toml_body = toml_block(r);
    crate::io::output::write_all_atomic(&[
        (toml.as_path(), toml_body.as_bytes()),
        (svg_path.as_path(), svg_body.as_bytes()),
    ])?;
    Ok(Written {
        toml,
        svg: svg_path,
    })
}
