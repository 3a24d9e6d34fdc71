//! Displacement-controlled MDR: the foundation driven by a prescribed indentation history, so
//! that the MDR and the Lee–Radok/Ting theory can be compared force for force.
//!
//! The exponential scheme (`mdr::exponential`) is exact for an indentation that is linear
//! over each step, so the only time error is the piecewise-linear interpolation of `d(t)`
//! (second order); the element spacing gives a second-order error as in the impact.
//! The step grid contains every requested time and the history's kinks, so outputs are
//! sampled, not interpolated.

use super::exponential::ExpFoundation;
use super::Foundation;
use crate::error::{Error, Result};
use crate::model::contact::Geometry;
use crate::model::material::Prony;
use crate::model::tolerances;
use crate::solvers::indentation::Prescribed;

/// One sample of a displacement-controlled run (units of the inputs, e.g. SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IndentSample {
    /// Time.
    pub t: f64,
    /// Prescribed indentation depth.
    pub d: f64,
    /// Contact radius (0 after separation).
    pub a: f64,
    /// Contact force (0 after separation).
    pub force: f64,
}

/// Resolution of a displacement-controlled run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IndentResolution {
    /// Elements across the maximum contact radius `sqrt(R d_max)`.
    pub elements: usize,
    /// Time steps over the prescribed history `[0, end_time]`.
    pub steps: usize,
}

impl Default for IndentResolution {
    fn default() -> Self {
        Self {
            elements: tolerances::INDENT_ELEMENTS,
            steps: tolerances::INDENT_STEPS,
        }
    }
}

/// Force history of the MDR foundation under a prescribed indentation `history` for a sphere of
/// radius `radius` and the equivalent relaxation `prony` (consistent units), at `times`
/// (sorted, non-negative).
pub fn response(
    prony: &Prony,
    radius: f64,
    history: &Prescribed,
    times: &[f64],
    res: IndentResolution,
) -> Result<Vec<IndentSample>> {
    crate::error::check("radius", radius, radius > 0.0, "0 < radius < inf (m)")?;
    response_on(&Geometry::Paraboloid { radius }, prony, history, times, res)
}

/// [`response`] for any axisymmetric indenter `geometry` (SI): the elements sit on its `g(x)`
/// (graded or fitted to a flat punch as in the impact, [`Foundation`]); a flat punch's contact
/// radius is its radius until the separation.
pub fn response_on(
    geometry: &Geometry,
    prony: &Prony,
    history: &Prescribed,
    times: &[f64],
    res: IndentResolution,
) -> Result<Vec<IndentSample>> {
    if res.elements < 2 || res.elements > tolerances::MDR_MAX_ELEMENTS {
        return Err(Error::OutOfRange {
            field: "elements",
            value: res.elements as f64,
            allowed: "2 <= elements <= 4194304",
        });
    }
    if res.steps < 4 || res.steps > 1_000_000_000 {
        return Err(Error::OutOfRange {
            field: "steps",
            value: res.steps as f64,
            allowed: "4 <= steps <= 10^9",
        });
    }
    for w in times.windows(2) {
        if !(w[1] >= w[0]) {
            return Err(Error::OutOfRange {
                field: "times",
                value: w[1],
                allowed: "sorted non-decreasing times >= 0",
            });
        }
    }
    if let Some(&t0) = times.first() {
        crate::error::check("times", t0, t0 >= 0.0, "sorted non-decreasing times >= 0")?;
    }
    let a_max = geometry.contact_radius(history.peak_depth());
    let dx = a_max / res.elements as f64;
    // the paraboloid's elements end at a_max; a graded grid maps over four times that
    // (Foundation), and a flat punch's never exceed its radius
    let capacity = match geometry {
        Geometry::Paraboloid { .. } => res.elements + 2,
        _ => 4 * res.elements + 16,
    };
    let geom = Foundation::new(dx, geometry, capacity);
    let mut f = ExpFoundation::new(geom, prony);
    let end = history.end_time();
    let dt_target = end / res.steps as f64;

    // grid nodes: kinks and requested times inside the contact history
    let mut nodes: Vec<f64> = history.kinks();
    nodes.push(history.peak_time());
    nodes.extend(times.iter().copied().filter(|&t| t > 0.0 && t < end));
    nodes.push(end);
    nodes.sort_by(|a, b| a.total_cmp(b));
    nodes.dedup();

    let mut out = Vec::with_capacity(times.len());
    let mut next_out = 0usize;
    let emit =
        |t: f64, d: f64, a: f64, force: f64, out: &mut Vec<IndentSample>, next: &mut usize| {
            while *next < times.len() && times[*next] <= t {
                if times[*next] == t {
                    out.push(IndentSample { t, d, a, force });
                }
                *next += 1;
            }
        };
    emit(0.0, 0.0, 0.0, 0.0, &mut out, &mut next_out);
    let (mut t, mut d) = (0.0_f64, 0.0_f64);
    let mut compression = true;
    let mut separated = false;
    for &node in &nodes {
        let span = node - t;
        if span <= 0.0 {
            continue;
        }
        let n_sub = (span / dt_target).ceil().max(1.0) as usize;
        let t_start = t;
        for j in 1..=n_sub {
            let t1 = if j == n_sub {
                node
            } else {
                t_start + span * j as f64 / n_sub as f64
            };
            let d1 = history.depth(t1);
            let dt = t1 - t;
            let r = (d1 - d) / dt;
            f.set_step(dt);
            if compression && t >= history.peak_time() {
                compression = false;
            }
            if !separated && !compression {
                while let Some(fo) = f.outer_force(d, r) {
                    if fo >= 0.0 {
                        break;
                    }
                    f.pop();
                }
                if f.in_contact() == 0 {
                    separated = true;
                }
            }
            f.commit(d, r, compression && !separated);
            t = t1;
            d = d1;
            let (force, a) = if separated {
                (0.0, 0.0)
            } else if compression || geometry.is_flat() {
                (f.force_now(d).max(0.0), geometry.contact_radius(d))
            } else {
                (f.force_now(d).max(0.0), f.edge_radius(d))
            };
            emit(t, d, a, force, &mut out, &mut next_out);
        }
    }
    // requested times at or after the end of the history: no contact
    while next_out < times.len() {
        let t = times[next_out];
        out.push(IndentSample {
            t,
            d: history.depth(t),
            a: 0.0,
            force: 0.0,
        });
        next_out += 1;
    }
    Ok(out)
}
