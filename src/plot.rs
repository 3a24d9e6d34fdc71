//! Charts (SVG, plotters): force histories.

use std::path::Path;

use plotters::prelude::*;

use crate::error::{Error, Result};
use crate::impact::History;
use crate::output::write_atomic;

/// Force-time plot of an impact history (time in ms, force in N) as SVG.
pub fn force_history_svg(path: &Path, h: &History, title: &str) -> Result<()> {
    let series = vec![(
        "MDR".to_string(),
        h.t.iter()
            .zip(&h.force)
            .map(|(t, f)| (t * 1e3, *f))
            .collect::<Vec<_>>(),
    )];
    line_chart_svg(path, title, "time t (ms)", "contact force F (N)", &series)
}

/// A line chart of one or more named series as SVG, written atomically.
pub fn line_chart_svg(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[(String, Vec<(f64, f64)>)],
) -> Result<()> {
    let mut svg = String::new();
    {
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for (_, pts) in series {
            for &(x, y) in pts {
                if x.is_finite() && y.is_finite() {
                    x0 = x0.min(x);
                    x1 = x1.max(x);
                    y0 = y0.min(y);
                    y1 = y1.max(y);
                }
            }
        }
        if !(x0 < x1) {
            return Err(Error::Unsupported(format!(
                "{}: nothing to plot",
                path.display()
            )));
        }
        if !(y0 < y1) {
            y1 = y0 + 1.0;
        }
        let pad = 0.05 * (y1 - y0);
        let root = SVGBackend::with_string(&mut svg, (900, 560)).into_drawing_area();
        let e = |e: &dyn std::fmt::Display| Error::io(path, e);
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, (y0 - pad)..(y1 + pad))
            .map_err(|x| e(&x))?;
        chart
            .configure_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .draw()
            .map_err(|x| e(&x))?;
        for (i, (name, pts)) in series.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
                .map_err(|x| e(&x))?
                .label(name.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                });
        }
        if series.len() > 1 {
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .border_style(BLACK)
                .background_style(WHITE.mix(0.8))
                .draw()
                .map_err(|x| e(&x))?;
        }
        root.present().map_err(|x| e(&x))?;
    }
    write_atomic(path, |w| {
        w.write_all(svg.as_bytes()).map_err(|e| Error::io(path, e))
    })
}

/// Top of the CoR axis: `e` runs from 0 to a little above 1, so that the line `e = 1` stays
/// visible.
const COR_AXIS_TOP: f64 = 1.05;

/// One line of a CoR chart: legend name, points `(v0, e)`, colour and stroke width (px).
type CorLine = (String, Vec<(f64, f64)>, RGBColor, u32);

/// The SVG text of a chart of `e` (0 to [`COR_AXIS_TOP`]) against `v0` from `x0` to `x1` (m/s,
/// logarithmic axis with `log`), the `lines` drawn in order and named in a legend at the lower
/// left. Rendered in memory only; `path` names the file in errors.
fn cor_chart_svg(
    path: &Path,
    title: &str,
    (x0, x1): (f64, f64),
    log: bool,
    lines: &[CorLine],
) -> Result<String> {
    type Chart<'a, 'b, X> =
        ChartContext<'a, SVGBackend<'b>, Cartesian2d<X, plotters::coord::types::RangedCoordf64>>;
    fn draw<'a, 'b: 'a, X>(
        path: &Path,
        chart: &mut Chart<'a, 'b, X>,
        lines: &[CorLine],
    ) -> Result<()>
    where
        X: Ranged<ValueType = f64> + plotters::coord::ranged1d::ValueFormatter<f64>,
    {
        let e = |e: &dyn std::fmt::Display| Error::io(path, e);
        chart
            .configure_mesh()
            .x_desc("impact velocity v0 (m/s)")
            .y_desc("coefficient of restitution e")
            .draw()
            .map_err(|x| e(&x))?;
        for (name, pts, color, width) in lines {
            let style = color.stroke_width(*width);
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), style))
                .map_err(|x| e(&x))?
                .label(name.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .border_style(BLACK)
            .background_style(WHITE.mix(0.85))
            .draw()
            .map_err(|x| e(&x))?;
        Ok(())
    }

    if !(x0 < x1) {
        return Err(Error::Unsupported(format!(
            "{}: a curve needs at least two velocities",
            path.display()
        )));
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 560)).into_drawing_area();
        let e = |e: &dyn std::fmt::Display| Error::io(path, e);
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let mut builder = ChartBuilder::on(&root);
        builder
            .caption(title, ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(70);
        if log {
            let mut chart = builder
                .build_cartesian_2d((x0..x1).log_scale(), 0.0..COR_AXIS_TOP)
                .map_err(|x| e(&x))?;
            draw(path, &mut chart, lines)?;
        } else {
            let mut chart = builder
                .build_cartesian_2d(x0..x1, 0.0..COR_AXIS_TOP)
                .map_err(|x| e(&x))?;
            draw(path, &mut chart, lines)?;
        }
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}

/// The velocity range `(first, last)` of curve rows (m/s); an error unless there are two rows.
fn velocity_span(path: &Path, rows: &[crate::curve::CurveRow]) -> Result<(f64, f64)> {
    match (rows.first(), rows.last()) {
        (Some(a), Some(b)) if rows.len() >= 2 => Ok((a.v0, b.v0)),
        _ => Err(Error::Unsupported(format!(
            "{}: a curve needs at least two velocities",
            path.display()
        ))),
    }
}

/// The SVG text of a CoR-against-velocity curve ([`crate::curve`]): `e(v0)` on a linear or (with
/// `log`) logarithmic velocity axis, `e` from 0 to 1 (with a little headroom so that the line
/// `e = 1` stays visible), the elastic limits `e = 1` as a horizontal line and, where they fall
/// inside the velocity range, vertical markers at the `p3 = 1` velocity and at the velocities
/// where the Hertz contact time meets the slowest / fastest relaxation time. Rendered in memory
/// only; `path` names the file in errors (the caller writes it, atomically).
pub fn cor_curve_svg(path: &Path, curve: &crate::curve::Curve, log: bool) -> Result<String> {
    let (x0, x1) = velocity_span(path, &curve.rows)?;
    let mut lines: Vec<CorLine> = vec![(
        "elastic limits (relaxed v0 -> 0, glassy v0 -> inf)".to_string(),
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
    cor_chart_svg(
        path,
        "Coefficient of restitution against impact velocity",
        (x0, x1),
        log,
        &lines,
    )
}

/// The SVG text of `mdr-impact dem`'s plot: our `e(v0)` and the `e(v0)` of each fitted DEM law
/// (our integration of its force law), on a linear or (with the report's `log`) logarithmic
/// velocity axis. Rendered in memory only; `path` names the file in errors.
pub fn dem_svg(path: &Path, report: &crate::dem::DemReport) -> Result<String> {
    let rows = &report.rows;
    let span = velocity_span(path, rows)?;
    let pct = |x: f64| format!("{:.1} %", 100.0 * x);
    let along = |cor: &[f64]| -> Vec<(f64, f64)> {
        rows.iter().zip(cor).map(|(r, e)| (r.v0, *e)).collect()
    };
    let (c, v) = (&report.constant, &report.viscoelastic);
    let lines: Vec<CorLine> = vec![
        (
            "e(v0), this model".to_string(),
            rows.iter().map(|r| (r.v0, r.cor)).collect(),
            RGBColor(30, 80, 200),
            2,
        ),
        (
            format!(
                "constant CoR e = {:.4}, input e = {:.4} (worst {}, rms {})",
                c.cor,
                c.cor_input,
                pct(c.fit.worst_rel_error),
                pct(c.fit.rms_rel_error)
            ),
            along(&c.fit.cor),
            RGBColor(200, 30, 30),
            2,
        ),
        (
            format!(
                "viscoelastic, A = {:.3e} s (worst {}, rms {})",
                v.a,
                pct(v.fit.worst_rel_error),
                pct(v.fit.rms_rel_error)
            ),
            along(&v.fit.cor),
            RGBColor(30, 140, 60),
            2,
        ),
    ];
    let title = format!(
        "DEM damping laws fitted to e(v0), Hertz with the {} modulus",
        report.modulus.name()
    );
    cor_chart_svg(path, &title, span, report.log, &lines)
}
