//! Contour lines of a field sampled on a rectangular grid: marching squares with linear
//! interpolation along cell edges, saddles resolved by the cell-centre average, segments joined
//! into polylines. (plotters has no contour helper.)

use std::collections::HashMap;

use crate::error::{Error, Result};

/// A scalar field on a rectangular grid: `z[iy * x.len() + ix]` is the value at `(x[ix], y[iy])`.
/// Non-finite values mark missing samples; cells touching one are skipped.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// Strictly increasing x coordinates (`>= 2`).
    pub x: Vec<f64>,
    /// Strictly increasing y coordinates (`>= 2`).
    pub y: Vec<f64>,
    /// Values, row by row (`y` outer, `x` inner).
    pub z: Vec<f64>,
}

impl Field {
    /// Validated field: at least 2 x 2 strictly increasing finite coordinates, `z` of matching size.
    pub fn new(x: Vec<f64>, y: Vec<f64>, z: Vec<f64>) -> Result<Self> {
        for (field, c) in [("x", &x), ("y", &y)] {
            if c.len() < 2 {
                return Err(Error::OutOfRange {
                    field,
                    value: c.len() as f64,
                    allowed: ">= 2 grid coordinates",
                });
            }
            if c.iter().any(|v| !v.is_finite()) || c.windows(2).any(|w| !(w[1] > w[0])) {
                return Err(Error::NotSupported {
                    solver: "field",
                    what: format!("{field} coordinates must be finite and strictly increasing"),
                });
            }
        }
        if z.len() != x.len() * y.len() {
            return Err(Error::OutOfRange {
                field: "z",
                value: z.len() as f64,
                allowed: "x.len() * y.len() values",
            });
        }
        Ok(Self { x, y, z })
    }

    /// The value at grid node `(ix, iy)`.
    pub fn at(&self, ix: usize, iy: usize) -> f64 {
        self.z[iy * self.x.len() + ix]
    }
}

/// A cell edge: horizontal (`(ix, iy)`–`(ix + 1, iy)`) or vertical (`(ix, iy)`–`(ix, iy + 1)`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct Edge {
    vertical: bool,
    ix: usize,
    iy: usize,
}

/// Isolines `z = level` as polylines of `(x, y)` points; a closed line repeats its first point
/// at the end. Values equal to `level` count as above it.
pub fn isolines(f: &Field, level: f64) -> Vec<Vec<(f64, f64)>> {
    let (nx, ny) = (f.x.len(), f.y.len());
    let above = |v: f64| v >= level;
    let point = |e: Edge| -> (f64, f64) {
        let (ax, ay) = (e.ix, e.iy);
        let (bx, by) = if e.vertical {
            (ax, ay + 1)
        } else {
            (ax + 1, ay)
        };
        let (za, zb) = (f.at(ax, ay), f.at(bx, by));
        let t = if zb == za {
            0.5
        } else {
            ((level - za) / (zb - za)).clamp(0.0, 1.0)
        };
        (
            f.x[ax] + t * (f.x[bx] - f.x[ax]),
            f.y[ay] + t * (f.y[by] - f.y[ay]),
        )
    };
    let mut segs: Vec<(Edge, Edge)> = Vec::new();
    for iy in 0..ny.saturating_sub(1) {
        for ix in 0..nx.saturating_sub(1) {
            let v = [
                f.at(ix, iy),
                f.at(ix + 1, iy),
                f.at(ix + 1, iy + 1),
                f.at(ix, iy + 1),
            ];
            if v.iter().any(|z| !z.is_finite()) {
                continue;
            }
            let s = v.map(above);
            // edges: 0 bottom (v0-v1), 1 right (v1-v2), 2 top (v3-v2), 3 left (v0-v3)
            let edges = [
                Edge {
                    vertical: false,
                    ix,
                    iy,
                },
                Edge {
                    vertical: true,
                    ix: ix + 1,
                    iy,
                },
                Edge {
                    vertical: false,
                    ix,
                    iy: iy + 1,
                },
                Edge {
                    vertical: true,
                    ix,
                    iy,
                },
            ];
            let cut = [s[0] != s[1], s[1] != s[2], s[3] != s[2], s[0] != s[3]];
            let crossed: Vec<usize> = (0..4).filter(|&k| cut[k]).collect();
            match crossed.len() {
                2 => segs.push((edges[crossed[0]], edges[crossed[1]])),
                4 => {
                    // saddle: the centre value decides which diagonal pair is connected
                    let centre = above(0.25 * (v[0] + v[1] + v[2] + v[3]));
                    if centre == s[0] {
                        segs.push((edges[0], edges[1]));
                        segs.push((edges[2], edges[3]));
                    } else {
                        segs.push((edges[3], edges[0]));
                        segs.push((edges[1], edges[2]));
                    }
                }
                _ => {}
            }
        }
    }
    // join segments that share an edge into polylines
    let mut at_edge: HashMap<Edge, Vec<usize>> = HashMap::new();
    for (i, (a, b)) in segs.iter().enumerate() {
        at_edge.entry(*a).or_default().push(i);
        at_edge.entry(*b).or_default().push(i);
    }
    let mut used = vec![false; segs.len()];
    let mut lines = Vec::new();
    for start in 0..segs.len() {
        if used[start] {
            continue;
        }
        used[start] = true;
        let (a, b) = segs[start];
        let mut chain = std::collections::VecDeque::from([a, b]);
        // extend forwards from the back, then backwards from the front
        for forward in [true, false] {
            loop {
                let end = if forward {
                    chain[chain.len() - 1]
                } else {
                    chain[0]
                };
                let next = at_edge
                    .get(&end)
                    .and_then(|v| v.iter().copied().find(|&j| !used[j]));
                let Some(j) = next else { break };
                used[j] = true;
                let (c, d) = segs[j];
                let other = if c == end { d } else { c };
                if forward {
                    chain.push_back(other);
                } else {
                    chain.push_front(other);
                }
            }
        }
        lines.push(chain.into_iter().map(point).collect());
    }
    lines
}

/// Length of a polyline.
pub fn length(line: &[(f64, f64)]) -> f64 {
    line.windows(2)
        .map(|w| ((w[1].0 - w[0].0).powi(2) + (w[1].1 - w[0].1).powi(2)).sqrt())
        .sum()
}

/// The point half-way along a polyline (by arc length); `None` when empty.
pub fn midpoint(line: &[(f64, f64)]) -> Option<(f64, f64)> {
    let half = 0.5 * length(line);
    let mut acc = 0.0;
    for w in line.windows(2) {
        let l = ((w[1].0 - w[0].0).powi(2) + (w[1].1 - w[0].1).powi(2)).sqrt();
        if acc + l >= half && l > 0.0 {
            let t = (half - acc) / l;
            return Some((
                w[0].0 + t * (w[1].0 - w[0].0),
                w[0].1 + t * (w[1].1 - w[0].1),
            ));
        }
        acc += l;
    }
    line.first().copied()
}
