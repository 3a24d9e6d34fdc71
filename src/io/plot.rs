//! Charts (SVG, plotters): force histories.

use std::path::Path;

use plotters::prelude::*;

use crate::error::{Error, Result};
use crate::io::output::write_atomic;
use crate::model::impact::History;

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
            return Err(Error::NotSupported {
                solver: "plot",
                what: "nothing to plot (no finite x range)".into(),
            }
            .at(path.display().to_string()));
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
pub const COR_AXIS_TOP: f64 = 1.05;

/// One line of a CoR chart: legend name, points `(v0, e)`, colour and stroke width (px).
pub type CorLine = (String, Vec<(f64, f64)>, RGBColor, u32);

/// The SVG text of a chart of `e` (0 to [`COR_AXIS_TOP`]) against `v0` from `x0` to `x1` (m/s,
/// logarithmic axis with `log`), the `lines` drawn in order and named in a legend at the lower
/// left, over the `shaded` velocity spans. Rendered in memory only; `path` names the file in
/// errors. One panel of [`panels_svg`].
pub fn cor_chart_svg(
    path: &Path,
    title: &str,
    span: (f64, f64),
    log: bool,
    lines: &[CorLine],
    shaded: &Shaded,
) -> Result<String> {
    let panel = Panel {
        caption: title.to_string(),
        y_label: "coefficient of restitution e".into(),
        y_range: (0.0, COR_AXIS_TOP),
        lines: lines.to_vec(),
        shaded: shaded.clone(),
    };
    panels_svg(path, span, log, "impact velocity v0 (m/s)", &[panel])
}

/// Velocity spans shaded on a CoR chart, with their legend entry (no entry without spans).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Shaded {
    /// `(from, to)` in m/s.
    pub spans: Vec<(f64, f64)>,
    /// Legend text.
    pub label: String,
}

/// The velocity range `(first, last)` of a curve's velocities (m/s); an error unless there are
/// two of them.
pub fn velocity_span(path: &Path, velocities: &[f64]) -> Result<(f64, f64)> {
    match (velocities.first(), velocities.last()) {
        (Some(a), Some(b)) if velocities.len() >= 2 => Ok((*a, *b)),
        _ => Err(Error::NotSupported {
            solver: "plot",
            what: "a curve needs at least two velocities".into(),
        }
        .at(path.display().to_string())),
    }
}

/// One panel of [`panels_svg`]: its caption, y-axis label and range, and its lines.
#[derive(Debug, Clone)]
pub struct Panel {
    /// Caption above the panel.
    pub caption: String,
    /// Label of the y axis (with its unit).
    pub y_label: String,
    /// The y range `(low, high)`.
    pub y_range: (f64, f64),
    /// The lines, drawn in order and named in a legend.
    pub lines: Vec<CorLine>,
    /// x spans shaded under the lines (none by default).
    pub shaded: Shaded,
}

/// The SVG text of panels stacked vertically over one x axis from `x0` to `x1` (logarithmic
/// with `log`) labelled `x_label`, each panel 900 x 480 px with its own legend at the lower
/// left. Rendered in memory only; `path` names the file in errors.
pub fn panels_svg(
    path: &Path,
    (x0, x1): (f64, f64),
    log: bool,
    x_label: &str,
    panels: &[Panel],
) -> Result<String> {
    let e = |e: &dyn std::fmt::Display| Error::io(path, e);
    if !(x0 < x1) || panels.is_empty() {
        return Err(Error::Internal(
            "panels_svg needs a non-empty x range and a panel",
        ));
    }
    let mut svg = String::new();
    {
        let height = 480 * panels.len() as u32;
        let root = SVGBackend::with_string(&mut svg, (900, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let areas = root.split_evenly((panels.len(), 1));
        for (area, panel) in areas.iter().zip(panels) {
            let (y0, y1) = panel.y_range;
            let mut builder = ChartBuilder::on(area);
            builder
                .caption(&panel.caption, ("sans-serif", 20))
                .margin(12)
                .x_label_area_size(44)
                .y_label_area_size(80);
            macro_rules! draw {
                ($chart:expr) => {{
                    let mut chart = $chart.map_err(|x| e(&x))?;
                    chart
                        .configure_mesh()
                        .x_desc(x_label)
                        .y_desc(panel.y_label.as_str())
                        .draw()
                        .map_err(|x| e(&x))?;
                    if !panel.shaded.spans.is_empty() {
                        let fill = RGBColor(230, 80, 60).mix(0.15).filled();
                        chart
                            .draw_series(
                                panel
                                    .shaded
                                    .spans
                                    .iter()
                                    .map(|&(a, b)| Rectangle::new([(a, y0), (b, y1)], fill)),
                            )
                            .map_err(|x| e(&x))?
                            .label(panel.shaded.label.as_str())
                            .legend(move |(x, y)| {
                                Rectangle::new([(x, y - 5), (x + 18, y + 5)], fill)
                            });
                    }
                    for (name, pts, color, width) in &panel.lines {
                        let style = color.stroke_width(*width);
                        chart
                            .draw_series(LineSeries::new(pts.iter().copied(), style))
                            .map_err(|x| e(&x))?
                            .label(name.as_str())
                            .legend(move |(x, y)| {
                                PathElement::new(vec![(x, y), (x + 18, y)], style)
                            });
                    }
                    chart
                        .configure_series_labels()
                        .position(SeriesLabelPosition::LowerLeft)
                        .border_style(BLACK)
                        .background_style(WHITE.mix(0.85))
                        .draw()
                        .map_err(|x| e(&x))?;
                }};
            }
            if log {
                draw!(builder.build_cartesian_2d((x0..x1).log_scale(), y0..y1));
            } else {
                draw!(builder.build_cartesian_2d(x0..x1, y0..y1));
            }
        }
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}
