//! Outputs of `prony`: the scene fragment `material.toml`, the tables `prony.csv` and
//! `master.csv`, the chart `dma.svg` (all written together, atomically), the printed summary
//! and the JSON object.

use std::fmt::Write as _;
use std::path::Path;

use plotters::prelude::*;

use super::{BulkChoice, PronyReport};
use crate::error::{Error, Result};
use crate::io::output::{fmt, write_all_atomic};

/// The files `prony` writes into its output folder.
pub const OUTPUT_FILES: [&str; 4] = ["material.toml", "prony.csv", "master.csv", "dma.svg"];

/// Write `material.toml`, `prony.csv`, `master.csv` and `dma.svg` into `dir`, all or none.
pub fn write_outputs(dir: &Path, r: &PronyReport) -> Result<()> {
    let svg = dma_svg(&dir.join("dma.svg"), r)?;
    let files = [material_toml(r), prony_csv(r), master_csv(r), svg];
    let paths: Vec<std::path::PathBuf> = OUTPUT_FILES.iter().map(|f| dir.join(f)).collect();
    let list: Vec<(&Path, &[u8])> = paths
        .iter()
        .zip(&files)
        .map(|(p, b)| (p.as_path(), b.as_bytes()))
        .collect();
    write_all_atomic(&list)
}

/// The scene fragment: `[material.shear]` (`g_inf`, `terms`), `[material.bulk]` and, with a
/// fitted law, `[material.shift]`.
pub fn material_toml(r: &PronyReport) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# Fitted by `mdr-impact prony` from {} ({} points, {} isotherm{}); rms relative error \
         of G', G'': {:.3e}.",
        r.file,
        r.isotherms.iter().map(|i| i.points.len()).sum::<usize>(),
        r.isotherms.len(),
        if r.isotherms.len() == 1 { "" } else { "s" },
        r.rms_rel_error
    );
    if let Some(t) = r.t_ref {
        let _ = writeln!(s, "# Relaxation times at the reference temperature {t} °C.");
    }
    let _ = writeln!(s, "\n[material.shear]");
    let _ = writeln!(
        s,
        "g_inf = {:?}    # Pa, relaxed shear modulus",
        r.series.g_inf
    );
    let _ = writeln!(s, "terms = [    # [g_i (Pa), tau_i (s)]");
    for &(g, t) in &r.series.terms {
        let _ = writeln!(s, "    [{g:?}, {t:?}],");
    }
    let _ = writeln!(s, "]\n\n[material.bulk]");
    match r.bulk {
        BulkChoice::Incompressible => {
            let _ = writeln!(s, "incompressible = true");
        }
        BulkChoice::Poisson(nu) => {
            let _ = writeln!(
                s,
                "poisson = {nu:?}    # static Poisson ratio (elastic bulk from g_inf)"
            );
        }
        BulkChoice::Proportional(nu) => {
            let f = 2.0 * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu));
            let _ = writeln!(
                s,
                "# constant Poisson ratio {nu:?} in time: K(t) = G(t) * {f:?}"
            );
            let _ = writeln!(s, "k_inf = {:?}    # Pa", r.series.g_inf * f);
            let _ = writeln!(s, "terms = [    # [k_j (Pa), theta_j (s)]");
            for &(g, t) in &r.series.terms {
                let _ = writeln!(s, "    [{:?}, {t:?}],", g * f);
            }
            let _ = writeln!(s, "]");
        }
    }
    if let Some(f) = &r.law {
        let _ = writeln!(s, "\n[material.shift]    # temperatures in °C");
        let _ = writeln!(s, "{}", f.law.toml_line());
        // the measured range: a scene at a temperature outside it is warned
        if let Some((lo, hi)) = calibrated(r) {
            let _ = writeln!(
                s,
                "calibrated = [{lo:?}, {hi:?}]    # the data's temperatures"
            );
        }
    }
    s
}

/// The lowest and highest measured temperature of the data's rows (°C), `None` without a
/// temperature column: the range the fitted shift law is calibrated on.
pub fn calibrated(r: &PronyReport) -> Option<(f64, f64)> {
    let ranges = r.isotherms.iter().filter_map(|i| i.measured);
    let lo = ranges.clone().map(|m| m.0).fold(f64::INFINITY, f64::min);
    let hi = ranges.map(|m| m.1).fold(f64::NEG_INFINITY, f64::max);
    (lo <= hi).then_some((lo, hi))
}

/// `prony.csv`: the terms as `tau,modulus` (s, Pa), the table format of a scene's `file`.
pub fn prony_csv(r: &PronyReport) -> String {
    let mut s = String::from("tau,modulus\n");
    for &(g, t) in &r.series.terms {
        let _ = writeln!(s, "{},{}", fmt(t), fmt(g));
    }
    s
}

/// `master.csv`: one row per point, with its temperature (°C, empty without), `log10 a_T`,
/// measured and reduced angular frequency (rad/s), measured `G'`, `G''` and the fitted ones
/// at the reduced frequency (Pa, shear).
pub fn master_csv(r: &PronyReport) -> String {
    let mut s = String::from(
        "temperature,log10_shift,omega,reduced_omega,storage,loss,storage_fit,loss_fit\n",
    );
    for (k, iso) in r.isotherms.iter().enumerate() {
        let a = 10f64.powf(r.log10_shift[k]);
        let t = iso.temperature.map(fmt).unwrap_or_default();
        for &(w, g1, g2) in &iso.points {
            let wr = w * a;
            let _ = writeln!(
                s,
                "{t},{},{},{},{},{},{},{}",
                fmt(r.log10_shift[k]),
                fmt(w),
                fmt(wr),
                fmt(g1),
                fmt(g2),
                fmt(r.series.storage(wr)),
                fmt(r.series.loss(wr))
            );
        }
    }
    s
}

/// The printed summary: data, reference temperature, shift factors and law, the series.
pub fn summary(r: &PronyReport) -> String {
    let mut s = String::new();
    let mut line = |k: &str, v: String| {
        let _ = writeln!(s, "{k:<28}{v}");
    };
    let points: usize = r.isotherms.iter().map(|i| i.points.len()).sum();
    line(
        "data",
        format!(
            "{}: {points} points, {} isotherm{}",
            r.file,
            r.isotherms.len(),
            if r.isotherms.len() == 1 { "" } else { "s" }
        ),
    );
    if let Some(t) = r.t_ref {
        line("reference temperature", format!("{t} °C"));
    }
    if r.isotherms.len() > 1 {
        for (k, iso) in r.isotherms.iter().enumerate() {
            let t = iso.temperature.unwrap_or(f64::NAN);
            let fitted = r
                .law
                .as_ref()
                .and_then(|f| f.law.log10_a(t).ok())
                .map(|v| format!(" (law {v:+.3})"))
                .unwrap_or_default();
            line(
                if k == 0 { "log10 a_T" } else { "" },
                format!("{t:>8.2} °C  {:+.3}{fitted}", r.log10_shift[k]),
            );
        }
    }
    match r.law.as_ref().map(|f| (f.law, f.rms)) {
        Some((super::shift::ShiftLaw::Wlf { c1, c2, t_ref }, rms)) => line(
            "shift law",
            format!("WLF c1 = {c1:.4}, c2 = {c2:.4} K, t_ref = {t_ref} °C (rms {rms:.3} decades)"),
        ),
        Some((
            super::shift::ShiftLaw::Arrhenius {
                activation_energy,
                t_ref,
            },
            rms,
        )) => line(
            "shift law",
            format!(
                "Arrhenius E_a = {activation_energy:.4e} J/mol, t_ref = {t_ref} °C (rms {rms:.3} \
                 decades)"
            ),
        ),
        None => {}
    }
    line("g_inf", format!("{:.4e} Pa", r.series.g_inf));
    let (t0, t1) = (
        r.series.terms.first().map_or(0.0, |t| t.1),
        r.series.terms.last().map_or(0.0, |t| t.1),
    );
    line(
        "prony terms",
        format!(
            "{} (tau {t0:.3e} s to {t1:.3e} s), glassy G = {:.4e} Pa",
            r.series.terms.len(),
            r.series.glassy()
        ),
    );
    line("rms relative error", format!("{:.3e}", r.rms_rel_error));
    for w in &r.warnings {
        let _ = writeln!(s, "warning: {w}");
    }
    s
}

/// The JSON object of `prony --json`: `g_inf` (Pa), `terms` (`[[g_i, tau_i], ...]`, Pa, s),
/// `shift` (the law's object, see [`super::shift::ShiftLaw::json`], or null), `log10_shift`
/// (`[{"temperature": °C, "log10_shift": ..}, ...]`; one entry with temperature null without
/// a temperature column), `calibrated` (`[t_min, t_max]`, °C, the data's temperatures, as in
/// `material.toml`; null without a shift law), `rms_rel_error`, `warnings`.
pub fn json(r: &PronyReport) -> serde_json::Value {
    serde_json::json!({
        "calibrated": r.law.as_ref().and(calibrated(r)).map(|(lo, hi)| [lo, hi]),
        "g_inf": r.series.g_inf,
        "terms": r.series.terms.iter().map(|&(g, t)| [g, t]).collect::<Vec<_>>(),
        "shift": r.law.as_ref().map(|f| f.law.json()),
        "t_ref": r.t_ref,
        "log10_shift": r.isotherms.iter().zip(&r.log10_shift).map(|(i, s)| serde_json::json!({
            "temperature": i.temperature,
            "log10_shift": s,
        })).collect::<Vec<_>>(),
        "rms_rel_error": r.rms_rel_error,
        "warnings": r.warnings,
    })
}

/// `10` with a superscript exponent for integer `v`, else nothing (decade labels).
fn decade(v: &f64) -> String {
    let k = v.round();
    if (v - k).abs() > 1e-6 {
        return String::new();
    }
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    let k = k as i64;
    if k < 0 {
        s.push('⁻');
    }
    for c in k.abs().to_string().chars() {
        s.push(SUP[c.to_digit(10).unwrap_or(0) as usize]);
    }
    s
}

/// Colour of isotherm `k` of `n`: blue (cold) to red (hot).
fn colour(k: usize, n: usize) -> RGBColor {
    let f = if n > 1 {
        k as f64 / (n - 1) as f64
    } else {
        0.0
    };
    let c = |a: f64, b: f64| (a + (b - a) * f).round() as u8;
    RGBColor(c(30.0, 215.0), c(80.0, 40.0), c(200.0, 40.0))
}

/// The chart: master curve (G', G'' per isotherm, the fit, tan delta) and the shift factors
/// with the fitted law. `path` names the file in errors.
pub fn dma_svg(path: &Path, r: &PronyReport) -> Result<String> {
    let e = |x: &dyn std::fmt::Display| Error::io(path, x);
    let pts = r.master_points();
    let lx: Vec<f64> = pts.iter().map(|p| p.1.log10()).collect();
    let (x0, x1) = lx
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let ly: Vec<f64> = pts
        .iter()
        .flat_map(|p| [p.2.log10(), p.3.log10()])
        .collect();
    let (y0, y1) = ly
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let (y0, y1) = ((y0 - 0.2).floor(), (y1 + 0.2).ceil());
    // the fit over the data's window only: beyond it the series is an extrapolation
    let (w0, w1) = (x0, x1);
    let (x0, x1) = ((x0 - 0.3).floor(), (x1 + 0.3).ceil());
    let curve: Vec<(f64, f64, f64)> = (0..=400)
        .map(|k| {
            let lw = w0 + (w1 - w0) * k as f64 / 400.0;
            let w = 10f64.powf(lw);
            (lw, r.series.storage(w), r.series.loss(w))
        })
        .collect();
    let tans: Vec<f64> = pts.iter().map(|p| (p.3 / p.2).log10()).collect();
    let (d0, d1) = tans
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let (d0, d1) = ((d0 - 0.2).floor(), (d1 + 0.2).ceil().max(d0.floor() + 1.0));
    let n = r.isotherms.len();
    let tref = r
        .t_ref
        .map(|t| format!(" at T_ref = {t} °C"))
        .unwrap_or_default();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1280, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let (left, right) = root.split_horizontally(820);
        let mut chart = ChartBuilder::on(&left)
            .caption(format!("Master curve{tref}"), ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(46)
            .y_label_area_size(64)
            .right_y_label_area_size(58)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|x| e(&x))?
            .set_secondary_coord(x0..x1, d0..d1);
        chart
            .configure_mesh()
            .x_labels((x1 - x0) as usize + 1)
            .y_labels((y1 - y0) as usize + 1)
            .x_label_formatter(&decade)
            .y_label_formatter(&decade)
            .x_desc("reduced angular frequency ω a_T (rad/s)")
            .y_desc("shear modulus G′, G″ (Pa)")
            .light_line_style(WHITE)
            .draw()
            .map_err(|x| e(&x))?;
        chart
            .configure_secondary_axes()
            .y_labels((d1 - d0) as usize + 1)
            .y_label_formatter(&decade)
            .y_desc("loss tangent tan δ")
            .draw()
            .map_err(|x| e(&x))?;
        for (k, _) in r.isotherms.iter().enumerate() {
            let c = colour(k, n);
            let mine = pts.iter().filter(|p| p.0 == k);
            chart
                .draw_series(
                    mine.clone()
                        .map(|p| Circle::new((p.1.log10(), p.2.log10()), 3, c.filled())),
                )
                .map_err(|x| e(&x))?;
            chart
                .draw_series(
                    mine.map(|p| {
                        TriangleMarker::new((p.1.log10(), p.3.log10()), 4, c.stroke_width(1))
                    }),
                )
                .map_err(|x| e(&x))?;
        }
        chart
            .draw_secondary_series(pts.iter().map(|p| {
                Cross::new(
                    (p.1.log10(), (p.3 / p.2).log10()),
                    2,
                    RGBColor(0, 140, 60).mix(0.5),
                )
            }))
            .map_err(|x| e(&x))?;
        let black = BLACK.stroke_width(2);
        chart
            .draw_series(LineSeries::new(
                curve.iter().map(|c| (c.0, c.1.log10())),
                black,
            ))
            .map_err(|x| e(&x))?
            .label("G′ fit")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], black));
        chart
            .draw_series(DashedLineSeries::new(
                curve.iter().map(|c| (c.0, c.2.log10())),
                8,
                5,
                black,
            ))
            .map_err(|x| e(&x))?
            .label("G″ fit")
            .legend(move |(x, y)| {
                EmptyElement::at((x, y))
                    + PathElement::new(vec![(0, 0), (7, 0)], black)
                    + PathElement::new(vec![(11, 0), (18, 0)], black)
            });
        let green = RGBColor(0, 140, 60).stroke_width(2);
        chart
            .draw_secondary_series(LineSeries::new(
                curve.iter().map(|c| (c.0, (c.2 / c.1).log10())),
                green,
            ))
            .map_err(|x| e(&x))?
            .label("tan δ fit (right axis; × data)")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], green));
        let grey = RGBColor(90, 90, 90);
        chart
            .draw_series(Vec::<Circle<(f64, f64), i32>>::new())
            .map_err(|x| e(&x))?
            .label("G′ data (colour: temperature, blue cold to red hot)")
            .legend(move |(x, y)| Circle::new((x + 9, y), 3, grey.filled()));
        chart
            .draw_series(Vec::<TriangleMarker<(f64, f64), i32>>::new())
            .map_err(|x| e(&x))?
            .label("G″ data")
            .legend(move |(x, y)| TriangleMarker::new((x + 9, y), 4, grey));
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .border_style(BLACK)
            .background_style(WHITE.mix(0.85))
            .draw()
            .map_err(|x| e(&x))?;

        // shift factors against temperature
        let temps: Vec<f64> = r.isotherms.iter().filter_map(|i| i.temperature).collect();
        if temps.len() == n && n > 1 {
            let (t0, t1) = temps
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                    (a.min(x), b.max(x))
                });
            let pad = 0.05 * (t1 - t0);
            let (t0, t1) = (t0 - pad, t1 + pad);
            let law: Vec<(f64, f64)> = r
                .law
                .as_ref()
                .map(|f| {
                    (0..=200)
                        .filter_map(|k| {
                            let t = t0 + (t1 - t0) * k as f64 / 200.0;
                            f.law.log10_a(t).ok().map(|v| (t, v))
                        })
                        .collect()
                })
                .unwrap_or_default();
            let (s0, s1) = r
                .log10_shift
                .iter()
                .chain(law.iter().map(|p| &p.1))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                    (a.min(x), b.max(x))
                });
            let spad = 0.08 * (s1 - s0).max(0.5);
            let mut c2 = ChartBuilder::on(&right)
                .caption("Shift factors", ("sans-serif", 22))
                .margin(12)
                .x_label_area_size(46)
                .y_label_area_size(56)
                .build_cartesian_2d(t0..t1, (s0 - spad)..(s1 + spad))
                .map_err(|x| e(&x))?;
            c2.configure_mesh()
                .x_label_formatter(&|t| format!("{t:.0}"))
                .x_desc("temperature T (°C)")
                .y_desc("log₁₀ a_T")
                .light_line_style(WHITE)
                .draw()
                .map_err(|x| e(&x))?;
            if let Some(f) = &r.law {
                let name = match f.law {
                    super::shift::ShiftLaw::Wlf { c1, c2, .. } => {
                        format!("WLF: c1 = {c1:.3}, c2 = {c2:.1} K")
                    }
                    super::shift::ShiftLaw::Arrhenius {
                        activation_energy, ..
                    } => format!("Arrhenius: E_a = {:.1} kJ/mol", activation_energy / 1e3),
                };
                c2.draw_series(LineSeries::new(law.iter().copied(), BLACK.stroke_width(2)))
                    .map_err(|x| e(&x))?
                    .label(name)
                    .legend(|(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], BLACK.stroke_width(2))
                    });
            }
            c2.draw_series(
                temps
                    .iter()
                    .zip(&r.log10_shift)
                    .enumerate()
                    .map(|(k, (&t, &s))| Circle::new((t, s), 5, colour(k, n).filled())),
            )
            .map_err(|x| e(&x))?
            .label("from the data (colour key)")
            .legend(|(x, y)| Circle::new((x + 9, y), 5, colour(0, 2).filled()));
            c2.configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .border_style(BLACK)
                .background_style(WHITE.mix(0.85))
                .draw()
                .map_err(|x| e(&x))?;
        } else {
            right
                .draw(&Text::new(
                    "one isotherm: no shift factors",
                    (40, 280),
                    ("sans-serif", 18),
                ))
                .map_err(|x| e(&x))?;
        }
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}
