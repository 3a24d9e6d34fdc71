//! SVG rendering of the figures with plotters (SVG backend only, no font files): filled contour
//! maps with labelled isolines and a colour bar, and line charts.

use std::path::Path;

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::contour::{isolines, length, midpoint, Field};
use crate::error::{Error, Result};
use crate::io::output::write_atomic;

/// Colour bands of a filled contour map: `colors[k]` fills values between `levels[k - 1]` and
/// `levels[k]` (`colors[0]` below the first level, the last colour above the last level).
#[derive(Debug, Clone, PartialEq)]
pub struct Bands {
    /// Increasing band boundaries.
    pub levels: Vec<f64>,
    /// One colour more than levels.
    pub colors: Vec<RGBColor>,
}

impl Bands {
    /// Band index of a value (`None` when not finite).
    pub fn band(&self, v: f64) -> Option<usize> {
        if !v.is_finite() {
            return None;
        }
        Some(self.levels.iter().take_while(|&&l| v >= l).count())
    }
}

/// Linear interpolation in a list of anchor colours, `t` in `[0, 1]`.
fn ramp(anchors: &[(u8, u8, u8)], t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0) * (anchors.len() - 1) as f64;
    let i = (t.floor() as usize).min(anchors.len() - 2);
    let f = t - i as f64;
    let mix = |a: u8, b: u8| (a as f64 + f * (b as f64 - a as f64)).round() as u8;
    let (a, b) = (anchors[i], anchors[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Viridis-like sequential colour (dark blue at 0, yellow at 1).
pub fn sequential(t: f64) -> RGBColor {
    ramp(
        &[
            (68, 1, 84),
            (65, 68, 135),
            (42, 120, 142),
            (34, 168, 132),
            (122, 209, 81),
            (253, 231, 37),
        ],
        t,
    )
}

/// Diverging colour: blue at -1, white at 0, red at +1.
pub fn diverging(t: f64) -> RGBColor {
    if t < 0.0 {
        ramp(
            &[
                (255, 255, 255),
                (146, 197, 222),
                (33, 102, 172),
                (5, 48, 97),
            ],
            -t,
        )
    } else {
        ramp(
            &[
                (255, 255, 255),
                (244, 165, 130),
                (178, 24, 43),
                (103, 0, 31),
            ],
            t,
        )
    }
}

/// One isoline level: value, label, drawn thick.
#[derive(Debug, Clone, PartialEq)]
pub struct Iso {
    /// The level.
    pub level: f64,
    /// Its label on the map.
    pub label: String,
    /// Draw it thicker (a threshold worth seeing).
    pub bold: bool,
}

/// What a contour map shows.
#[derive(Debug, Clone, PartialEq)]
pub struct MapStyle {
    /// Title.
    pub title: String,
    /// x-axis description.
    pub x_label: String,
    /// y-axis description.
    pub y_label: String,
    /// Filled bands.
    pub bands: Bands,
    /// Labelled isolines.
    pub isolines: Vec<Iso>,
    /// Title of the colour bar.
    pub bar_label: String,
}

/// Drawing scale: plotters rounds coordinates to whole pixels, which makes smooth curves jagged;
/// the figures are drawn `S` times larger and the SVG's displayed size is set back by
/// [`shrink`], so the coordinates keep `1/S` pixel resolution.
const S: u32 = 4;

/// Scale a size in display pixels to drawing pixels.
fn px(v: u32) -> u32 {
    v * S
}

/// Set the displayed size of a plotters SVG (drawn `S` times larger) back to `w x h`.
fn shrink(svg: &str, w: u32, h: u32) -> String {
    svg.replacen(
        &format!("width=\"{}\" height=\"{}\"", px(w), px(h)),
        &format!("width=\"{w}\" height=\"{h}\""),
        1,
    )
}

fn perr(path: &Path) -> impl Fn(&dyn std::fmt::Display) -> Error + '_ {
    move |e| Error::io(path, format!("plotting: {e}"))
}

/// Filled contour map of `f` (bands from node-centred cells), isolines with labels, colour bar;
/// written atomically as SVG.
pub fn map_svg(path: &Path, f: &Field, style: &MapStyle) -> Result<()> {
    let e = perr(path);
    let (nx, ny) = (f.x.len(), f.y.len());
    let (x0, x1, y0, y1) = (f.x[0], f.x[nx - 1], f.y[0], f.y[ny - 1]);
    // cell boundaries half-way between nodes
    let edges = |c: &[f64]| -> Vec<f64> {
        let n = c.len();
        let mut b = Vec::with_capacity(n + 1);
        b.push(c[0]);
        for i in 1..n {
            b.push(0.5 * (c[i - 1] + c[i]));
        }
        b.push(c[n - 1]);
        b
    };
    let (bx, by) = (edges(&f.x), edges(&f.y));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (px(980), px(680))).into_drawing_area();
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let (main, bar) = root.split_horizontally(px(850));
        let mut chart = ChartBuilder::on(&main)
            .caption(&style.title, ("sans-serif", px(20)))
            .margin(px(14))
            .x_label_area_size(px(50))
            .y_label_area_size(px(64))
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|x| e(&x))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(style.x_label.as_str())
            .y_desc(style.y_label.as_str())
            .label_style(("sans-serif", px(15)))
            .axis_desc_style(("sans-serif", px(17)))
            .draw()
            .map_err(|x| e(&x))?;
        // bands: runs of equal band along x merged into one rectangle
        let mut rects = Vec::new();
        for iy in 0..ny {
            let mut ix = 0;
            while ix < nx {
                let b = style.bands.band(f.at(ix, iy));
                let mut jx = ix + 1;
                while jx < nx && style.bands.band(f.at(jx, iy)) == b {
                    jx += 1;
                }
                let color = match b {
                    Some(k) => style.bands.colors[k.min(style.bands.colors.len() - 1)],
                    None => RGBColor(200, 200, 200),
                };
                rects.push(Rectangle::new(
                    [(bx[ix], by[iy]), (bx[jx], by[iy + 1])],
                    color.filled(),
                ));
                ix = jx;
            }
        }
        chart.draw_series(rects).map_err(|x| e(&x))?;
        // isolines and one label per level, on the longest line of the level
        let (rx, ry) = chart.plotting_area().get_pixel_range();
        let sx = (x1 - x0) / (rx.end - rx.start).max(1) as f64;
        let sy = (y1 - y0) / (ry.end - ry.start).max(1) as f64;
        let mut labels = Vec::new();
        for iso in &style.isolines {
            let lines = isolines(f, iso.level);
            let width = px(if iso.bold { 3 } else { 1 });
            for l in &lines {
                chart
                    .draw_series(std::iter::once(PathElement::new(
                        l.clone(),
                        BLACK.stroke_width(width),
                    )))
                    .map_err(|x| e(&x))?;
            }
            if let Some(longest) = lines.iter().max_by(|a, b| length(a).total_cmp(&length(b)))
                && let Some(m) = midpoint(longest)
            {
                labels.push((iso.label.clone(), m));
            }
        }
        for (text, (x, y)) in labels {
            let hw = (3.6 * text.chars().count() as f64 + 3.0) * S as f64;
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [
                        (x - hw * sx, y - 8.0 * S as f64 * sy),
                        (x + hw * sx, y + 8.0 * S as f64 * sy),
                    ],
                    WHITE.mix(0.85).filled(),
                )))
                .map_err(|x| e(&x))?;
            let ts = TextStyle::from(("sans-serif", px(13)).into_font())
                .pos(Pos::new(HPos::Center, VPos::Center));
            chart
                .draw_series(std::iter::once(Text::new(text, (x, y), ts)))
                .map_err(|x| e(&x))?;
        }
        // colour bar: equal-height bands, boundaries labelled with the levels
        let nb = style.bands.colors.len();
        let mut cb = ChartBuilder::on(&bar)
            .margin_top(px(64))
            .margin_bottom(px(64))
            .margin_left(px(4))
            .margin_right(px(4))
            .caption(&style.bar_label, ("sans-serif", px(14)))
            .build_cartesian_2d(0f64..3f64, 0f64..nb as f64)
            .map_err(|x| e(&x))?;
        cb.draw_series((0..nb).map(|k| {
            Rectangle::new(
                [(0.0, k as f64), (1.0, k as f64 + 1.0)],
                style.bands.colors[k].filled(),
            )
        }))
        .map_err(|x| e(&x))?;
        cb.draw_series(std::iter::once(Rectangle::new(
            [(0.0, 0.0), (1.0, nb as f64)],
            BLACK.stroke_width(px(1)),
        )))
        .map_err(|x| e(&x))?;
        let ts = TextStyle::from(("sans-serif", px(13)).into_font())
            .pos(Pos::new(HPos::Left, VPos::Center));
        cb.draw_series(
            style
                .bands
                .levels
                .iter()
                .enumerate()
                .map(|(k, l)| Text::new(format_level(*l), (1.15, k as f64 + 1.0), ts.clone())),
        )
        .map_err(|x| e(&x))?;
        root.present().map_err(|x| e(&x))?;
    }
    let svg = shrink(&svg, 980, 680);
    write_atomic(path, |w| {
        w.write_all(svg.as_bytes()).map_err(|e| Error::io(path, e))
    })
}

/// Short label of a level (`0.1`, `-0.05`, `1`).
pub fn format_level(l: f64) -> String {
    let s = format!("{l:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// One curve of a line chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Legend entry.
    pub name: String,
    /// Points.
    pub points: Vec<(f64, f64)>,
    /// Colour.
    pub color: RGBColor,
    /// Stroke width (px).
    pub width: u32,
}

/// Line chart with fixed axis ranges and an optional vertical marker line at `marker`;
/// written atomically as SVG.
#[allow(clippy::too_many_arguments)]
pub fn curves_svg(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    x_range: (f64, f64),
    y_range: (f64, f64),
    curves: &[Curve],
    marker: Option<(f64, String)>,
) -> Result<()> {
    let e = perr(path);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (px(900), px(600))).into_drawing_area();
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", px(20)))
            .margin(px(14))
            .x_label_area_size(px(50))
            .y_label_area_size(px(64))
            .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)
            .map_err(|x| e(&x))?;
        chart
            .configure_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .label_style(("sans-serif", px(15)))
            .axis_desc_style(("sans-serif", px(17)))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(|x| e(&x))?;
        if let Some((x, text)) = marker {
            let grey = RGBColor(130, 130, 130);
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(x, y_range.0), (x, y_range.1)],
                    grey.stroke_width(px(1)),
                )))
                .map_err(|x| e(&x))?;
            chart
                .draw_series(std::iter::once(Text::new(
                    text,
                    (x, y_range.1 - 0.02 * (y_range.1 - y_range.0)),
                    ("sans-serif", px(13)).into_font().color(&grey),
                )))
                .map_err(|x| e(&x))?;
        }
        for c in curves {
            let style = c.color.stroke_width(px(c.width));
            chart
                .draw_series(LineSeries::new(c.points.iter().copied(), style))
                .map_err(|x| e(&x))?
                .label(c.name.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + px(22) as i32, y)], style)
                });
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .legend_area_size(px(30))
            .margin(px(8))
            .label_font(("sans-serif", px(14)))
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .draw()
            .map_err(|x| e(&x))?;
        root.present().map_err(|x| e(&x))?;
    }
    let svg = shrink(&svg, 900, 600);
    write_atomic(path, |w| {
        w.write_all(svg.as_bytes()).map_err(|e| Error::io(path, e))
    })
}
