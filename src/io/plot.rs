//! Charts (SVG, plotters): force histories.

use std::path::Path;

use plotters::coord::combinators::BindKeyPoints;
use plotters::prelude::*;

use crate::error::{Error, Result};
use crate::io::output::write_atomic;
use crate::model::impact::History;

/// The title of a chart and a subtitle with what it is about (the scene and its key inputs).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Caption {
    /// What is plotted (e.g. `"Contact force against time"`).
    pub title: String,
    /// The scene's name and key inputs (e.g. `"default scene: m = 4.11 g, R = 5 mm, ..."`).
    pub subtitle: String,
}

/// `x` with four significant digits, trailing zeros dropped (`4.11e-3`, `9.9e-1`, `2e0`).
pub fn short(x: f64) -> String {
    let s = format!("{x:.3e}");
    match s.split_once('e') {
        Some((m, e)) if m.contains('.') => {
            format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.'))
        }
        _ => s,
    }
}

/// A unit with an SI prefix for values up to `max` in `unit` (`max` in the base unit): the
/// factor the values are multiplied by and the prefixed unit, so that `max` reads between 1
/// and 1000 (`(1e3, "ms")` for `max = 2e-3` s).
pub fn si_scale(max: f64, unit: &str) -> (f64, String) {
    // prefixes from nano (10^-9) to giga (10^9), in steps of 10^3
    const PREFIXES: [&str; 7] = ["n", "µ", "m", "", "k", "M", "G"];
    let max = max.abs();
    if !(max.is_finite() && max > 0.0) {
        return (1.0, unit.to_string());
    }
    let k = ((max.log10() / 3.0).floor() as i32).clamp(-3, 3);
    let prefix = PREFIXES[(k + 3) as usize];
    (10f64.powi(-3 * k), format!("{prefix}{unit}"))
}

/// The force-time plot of an impact history as SVG text (time and force with SI prefixes),
/// its one curve named `label` in the legend. Rendered in memory only; `path` names the file in
/// errors.
pub fn force_time_svg(path: &Path, h: &History, caption: &Caption, label: &str) -> Result<String> {
    let t_max = h.t.iter().copied().fold(0.0, f64::max);
    let f_max = h.force.iter().copied().fold(0.0, f64::max);
    let (tk, tu) = si_scale(t_max, "s");
    let (fk, fu) = si_scale(f_max, "N");
    let pts =
        h.t.iter()
            .zip(&h.force)
            .map(|(t, f)| (t * tk, f * fk))
            .collect();
    chart_text(
        path,
        caption,
        &format!("time t ({tu})"),
        &format!("contact force F ({fu})"),
        &[(label.to_string(), pts, RGBColor(30, 80, 200))],
        SeriesLabelPosition::UpperRight,
    )
}

/// The force-indentation plot of an impact history as SVG text: the loading branch (up to the
/// largest indentation) and the unloading branch (after it) in two colours, so that the area
/// between them, the energy dissipated in the material, shows. Rendered in memory only; `path`
/// names the file in errors.
pub fn force_indentation_svg(path: &Path, h: &History, caption: &Caption) -> Result<String> {
    let peak =
        h.d.iter()
            .enumerate()
            .fold(0, |k, (i, &d)| if d > h.d[k] { i } else { k });
    let d_max = h.d.get(peak).copied().unwrap_or(0.0);
    let f_max = h.force.iter().copied().fold(0.0, f64::max);
    let (dk, du) = si_scale(d_max, "m");
    let (fk, fu) = si_scale(f_max, "N");
    let point = |i: usize| (h.d[i] * dk, h.force[i] * fk);
    let loading = (0..=peak.min(h.len().saturating_sub(1)))
        .map(point)
        .collect();
    let unloading = (peak..h.len()).map(point).collect();
    chart_text(
        path,
        caption,
        &format!("indentation d ({du})"),
        &format!("contact force F ({fu})"),
        &[
            (
                "loading (d increasing)".to_string(),
                loading,
                RGBColor(200, 50, 40),
            ),
            (
                "unloading (d decreasing)".to_string(),
                unloading,
                RGBColor(30, 80, 200),
            ),
        ],
        // the loop fills the right of the chart; its upper left is empty
        SeriesLabelPosition::UpperLeft,
    )
}

/// One named, coloured line of [`chart_text`]: legend text, points, colour.
pub type Series = (String, Vec<(f64, f64)>, RGBColor);

/// A line chart of named, coloured series as SVG text, with a title, a subtitle and a legend
/// naming every series at `legend`. Rendered in memory only; `path` names the file in
/// errors.
pub fn chart_text(
    path: &Path,
    caption: &Caption,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    legend: SeriesLabelPosition,
) -> Result<String> {
    let finite = series
        .iter()
        .flat_map(|(_, pts, _)| pts.iter())
        .filter(|(x, y)| x.is_finite() && y.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in finite {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
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
    let e = |e: &dyn std::fmt::Display| Error::io(path, e);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let area = root
            .titled(&caption.title, ("sans-serif", 22))
            .map_err(|x| e(&x))?;
        let area = area
            .titled(
                &caption.subtitle,
                ("sans-serif", 15).into_font().color(&RGBColor(60, 60, 60)),
            )
            .map_err(|x| e(&x))?;
        let mut chart = ChartBuilder::on(&area)
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
        for (name, pts, color) in series {
            let style = color.stroke_width(2);
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), style))
                .map_err(|x| e(&x))?
                .label(name.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
        }
        chart
            .configure_series_labels()
            .position(legend)
            .border_style(BLACK)
            .background_style(WHITE.mix(0.85))
            .draw()
            .map_err(|x| e(&x))?;
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}

/// Radius (px) of the marker that stands for a series of one point in [`line_chart_svg`].
const SINGLE_POINT_RADIUS: i32 = 5;

/// A line chart of one or more named series as SVG, written atomically. A series of a single
/// point (a line through it would draw nothing) is drawn as a filled circle.
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
        if !(x0 <= x1) {
            return Err(Error::NotSupported {
                solver: "plot",
                what: "nothing to plot (no finite point)".into(),
            }
            .at(path.display().to_string()));
        }
        if x0 == x1 {
            // every point at one x: a range around it
            let w = if x0 == 0.0 { 1.0 } else { 0.05 * x0.abs() };
            (x0, x1) = (x0 - w, x1 + w);
        }
        if !(y0 < y1) {
            y1 = y0 + 1.0;
        }
        let pad = 0.05 * (y1 - y0);
        // room for the whole of a marker at the ends of the x range
        let x_pad = if series.iter().any(|(_, p)| p.len() == 1) {
            0.03 * (x1 - x0)
        } else {
            0.0
        };
        let (x0, x1) = (x0 - x_pad, x1 + x_pad);
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
            // a line through one point draws nothing: such a series is a marker
            let single = pts.len() == 1;
            let ann = if single {
                chart.draw_series(
                    pts.iter()
                        .map(|&p| Circle::new(p, SINGLE_POINT_RADIUS, color.filled())),
                )
            } else {
                chart.draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
            };
            ann.map_err(|x| e(&x))?.label(name.as_str()).legend(
                move |(x, y)| -> DynElement<'static, SVGBackend<'_>, (i32, i32)> {
                    if single {
                        Circle::new((x + 9, y), SINGLE_POINT_RADIUS, color.filled()).into_dyn()
                    } else {
                        PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                            .into_dyn()
                    }
                },
            );
        }
        if series.len() > 1 {
            let corner = legend_corner(series, (x0, x1), (y0 - pad, y1 + pad));
            chart
                .configure_series_labels()
                .position(corner)
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

/// The corner of a [`line_chart_svg`] for its legend: the one whose box (about the legend's
/// size in the 900 x 560 chart: 6 px per character of the longest name and 60 px more across,
/// 16 px per line and 16 px more down, over a plot area of about 800 x 460 px) covers the
/// fewest points of the lines (each segment sampled at 17 points, a series of one point, drawn
/// as a marker, weighing as much as a segment), the upper right on a tie.
fn legend_corner(
    series: &[(String, Vec<(f64, f64)>)],
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> SeriesLabelPosition {
    let longest = series
        .iter()
        .map(|(n, _)| n.chars().count())
        .max()
        .unwrap_or(0);
    let w = ((6 * longest + 60) as f64 / 800.0).min(0.9);
    let h = ((16 * (series.len() + 1)) as f64 / 460.0).min(0.9);
    // corners as the fractions of the axes where their boxes start
    let corners = [
        (SeriesLabelPosition::UpperRight, 1.0 - w, 1.0 - h),
        (SeriesLabelPosition::UpperLeft, 0.0, 1.0 - h),
        (SeriesLabelPosition::LowerRight, 1.0 - w, 0.0),
        (SeriesLabelPosition::LowerLeft, 0.0, 0.0),
    ];
    let mut covered = [0usize; 4];
    for (_, pts) in series {
        // a lone point is the segment from itself to itself
        let lone;
        let segments = if let [p] = pts.as_slice() {
            lone = [*p; 2];
            lone.windows(2)
        } else {
            pts.windows(2)
        };
        for seg in segments {
            for k in 0..=16 {
                let f = k as f64 / 16.0;
                let x = (seg[0].0 + f * (seg[1].0 - seg[0].0) - x0) / (x1 - x0);
                let y = (seg[0].1 + f * (seg[1].1 - seg[0].1) - y0) / (y1 - y0);
                for (n, &(_, cx, cy)) in covered.iter_mut().zip(&corners) {
                    if x >= cx && x <= cx + w && y >= cy && y <= cy + h {
                        *n += 1;
                    }
                }
            }
        }
    }
    let best = (0..4).min_by_key(|&i| covered[i]).unwrap_or(0);
    corners[best].0.clone()
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
                        .x_label_formatter(&|x| tick_label(*x))
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
                let (bold, light) = log_ticks(x0, x1);
                let x = (x0..x1)
                    .log_scale()
                    .with_key_points(bold)
                    .with_light_points(light);
                // room for the label of the range's upper end
                builder.margin_right(40);
                draw!(builder.build_cartesian_2d(x, y0..y1));
            } else {
                draw!(builder.build_cartesian_2d(x0..x1, y0..y1));
            }
        }
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}

/// The ticks of a logarithmic axis from `x0` to `x1` (`0 < x0 < x1`): labelled ones at both
/// ends of the range and at every decade between them (a decade too close to an end to carry
/// its own label, within a fifth of a decade, gives way to the end), and minor ones at 2..9
/// times every decade that reaches into the range, the first and last partial decades
/// included.
pub fn log_ticks(x0: f64, x1: f64) -> (Vec<f64>, Vec<f64>) {
    if !(x0 > 0.0 && x0 < x1 && x1.is_finite()) {
        return (vec![x0, x1], Vec::new());
    }
    let (l0, l1) = (x0.log10(), x1.log10());
    let mut bold = vec![x0];
    let mut light = Vec::new();
    for k in (l0.floor() as i32)..=(l1.ceil() as i32) {
        let decade = 10f64.powi(k);
        let lk = f64::from(k);
        if lk - l0 > 0.2 && l1 - lk > 0.2 {
            bold.push(decade);
        }
        for m in 1..10 {
            let x = f64::from(m) * decade;
            if x >= x0 && x <= x1 {
                light.push(x);
            }
        }
    }
    bold.push(x1);
    (bold, light)
}

/// The label of a tick: the value with at most four significant digits and no trailing zeros
/// (`0.1`, `1`, `1000`, `0.25`), in exponent form outside 1e-3..1e5 (`1e-5`, `2.5e6`).
pub fn tick_label(x: f64) -> String {
    if x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e5) {
        return short(x);
    }
    // round to four significant digits, then print the shortest form of that number
    let rounded: f64 = format!("{x:.3e}").parse().unwrap_or(x);
    format!("{rounded}")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn corner(series: &[(String, Vec<(f64, f64)>)]) -> String {
        format!("{:?}", legend_corner(series, (0.0, 1.0), (0.0, 1.0)))
    }

    #[test]
    fn the_legend_goes_to_the_emptiest_corner() {
        // a line falling from the upper left to the lower right leaves the upper right free
        let two = [
            ("a".to_string(), vec![(0.0, 1.0), (1.0, 0.0)]),
            ("b".to_string(), vec![(0.0, 0.9), (1.0, 0.1)]),
        ];
        assert_eq!(corner(&two), "UpperRight");
        // a line rising into the upper right (the work-precision plot's slow solver) moves it
        let rising = [
            ("a".to_string(), vec![(0.5, 0.6), (1.0, 0.95)]),
            ("b".to_string(), vec![(0.0, 0.0), (0.2, 0.3)]),
            ("c".to_string(), vec![(0.0, 0.95), (0.3, 0.9)]),
        ];
        assert_eq!(corner(&rising), "LowerRight");
        // markers (series of one point) count too: one in the upper right moves it
        let markers = [
            ("a".to_string(), vec![(0.95, 0.95)]),
            ("b".to_string(), vec![(0.0, 0.0)]),
            ("c".to_string(), vec![(0.05, 0.95)]),
        ];
        assert_eq!(corner(&markers), "LowerRight");
    }

    #[test]
    fn a_series_of_one_point_is_a_marker() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("chart.svg");
        let count = |series: &[(String, Vec<(f64, f64)>)]| {
            line_chart_svg(&path, "t", "x", "y", series).unwrap();
            let svg = std::fs::read_to_string(&path).unwrap();
            (
                svg.matches("<circle").count(),
                svg.matches("<polyline").count(),
            )
        };
        // one point each (a `bench --quick` run): a marker in the plot and one in the legend
        let single = [
            ("a".to_string(), vec![(0.0, 1.0)]),
            ("b".to_string(), vec![(1.0, 0.0)]),
        ];
        let (circles, axes) = count(&single);
        assert_eq!(circles, 4);
        // lines stay lines: four polylines (two lines, two legend keys) beside the frame's
        let lines = [
            ("a".to_string(), vec![(0.0, 1.0), (1.0, 0.5)]),
            ("b".to_string(), vec![(0.0, 0.0), (1.0, 0.2)]),
        ];
        assert_eq!(count(&lines), (0, axes + 4));
    }
}
