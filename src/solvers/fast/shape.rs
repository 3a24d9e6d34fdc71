//! The indenter's functions as the steps of `fast` use them ([`ShapeFns`]): `w(d)`, its
//! increments and slope, the contact radius `a(d)` and `a'(d)`, in closed form for the
//! paraboloid, the cone and the power laws, and by the safeguarded Halley inverse of
//! [`Geometry::contact_radius`] for exact caps (docs/theory.md §11).
//!
//! A power law `g = k x^n` has `a = (d/k)^(1/n)`, `w = (3/2) n/(n+1) a d`, `a' = a / (n d)`:
//! one `powf` gives `a`, `w`, `w'` and `a'` at a point. The cone (`n = 1`) needs none:
//! `a = d/k`, `w = (3/4) d^2 / k`, `w(d + δ) - w(d) = (3/4) δ (2 d + δ) / k`.

use super::dense::{pow15, pow15_increment};
use std::sync::OnceLock;

use crate::model::contact::Geometry;
use crate::model::geometry::{cap_atanh_tail, cap_psi_at, Cap, CAP_SERIES_U};

/// Below this ratio `|δ| / d` an increment `w(d + δ) - w(d)` of a power law is formed without
/// the difference (which loses `d / |δ|` units in the last place of the increment, at most 20
/// above it); exact caps, whose increment without the difference costs four inverses of the
/// profile, take the difference down to [`DIRECT_INCREMENT_CAPS`] (at most 1000 units in the
/// last place of the increment: an absolute error of `2e-13 w`, that of `w` itself).
const DIRECT_INCREMENT: f64 = 0.05;
/// [`DIRECT_INCREMENT`] of exact caps.
const DIRECT_INCREMENT_CAPS: f64 = 1e-3;

/// 4-point Gauss–Legendre nodes and weights on `[0, 1]`.
const GL_X: [f64; 4] = [
    0.069_431_844_202_973_71,
    0.330_009_478_207_571_9,
    0.669_990_521_792_428_1,
    0.930_568_155_797_026_3,
];
const GL_W: [f64; 4] = [
    0.173_927_422_568_726_93,
    0.326_072_577_431_273_07,
    0.326_072_577_431_273_07,
    0.173_927_422_568_726_93,
];

/// `w`, `a` and `a'` at one indentation `d` ([`ShapeFns::point`]).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct ShapePoint {
    /// `d`.
    pub(super) d: f64,
    /// `w(d)`.
    pub(super) w: f64,
    /// `a(d)`.
    pub(super) a: f64,
    /// `a'(d)`.
    pub(super) a_slope: f64,
}

/// The indenter's functions (a copy, free of the solver's borrows).
#[derive(Debug, Clone, Copy)]
pub(super) struct ShapeFns {
    /// The indenter (canonical, [`crate::model::geometry`]); `None` for the unit paraboloid,
    /// whose `w = d^(3/2)` has the closed forms of `dense` (bit for bit the solver it was).
    pub(super) geom: Option<Geometry>,
    form: Form,
}

#[derive(Debug, Clone, Copy)]
enum Form {
    /// `w = d^(3/2)`, `a = sqrt(d)`.
    Paraboloid,
    /// `g = k x`: `inv_k = 1 / k`.
    Cone { inv_k: f64 },
    /// `g = k x^n`: `w = cw a d`, `cw = (3/2) n / (n + 1)`, `p = 1 + 1/n`.
    Power { inv_n: f64, k: f64, cw: f64, p: f64 },
    /// One exact cap `g = scale x atanh(x / r)` (the other surface a plane): by the table
    /// inverse of [`cap_table`].
    Cap { r: f64, scale: f64, inv_sr: f64 },
    /// Any other geometry (two caps): through [`Geometry`].
    Other(Geometry),
}

impl ShapeFns {
    /// The functions of `geom` (`None`: the unit paraboloid).
    pub(super) fn new(geom: Option<Geometry>) -> Self {
        let form = match geom {
            None => Form::Paraboloid,
            Some(Geometry::PowerLaw {
                exponent: 1.0,
                coefficient,
            }) => Form::Cone {
                inv_k: 1.0 / coefficient,
            },
            Some(Geometry::PowerLaw {
                exponent,
                coefficient,
            }) => Form::Power {
                inv_n: 1.0 / exponent,
                k: coefficient,
                cw: 1.5 * exponent / (exponent + 1.0),
                p: 1.0 + 1.0 / exponent,
            },
            Some(Geometry::Caps { scale, caps }) if single_cap(&caps).is_some() => {
                let r = single_cap(&caps).unwrap_or(1.0);
                Form::Cap {
                    r,
                    scale,
                    inv_sr: 1.0 / (scale * r),
                }
            }
            Some(g) => Form::Other(g),
        };
        ShapeFns { geom, form }
    }

    /// The contact radius `a(d)` (0 for `d <= 0`).
    #[inline]
    pub(super) fn radius_at(&self, d: f64) -> f64 {
        let d = d.max(0.0);
        match self.form {
            Form::Paraboloid => d.sqrt(),
            Form::Cone { inv_k } => d * inv_k,
            Form::Power { inv_n, k, .. } => (d / k).powf(inv_n),
            Form::Cap { .. } => self.point(d).a,
            Form::Other(g) => g.contact_radius(d),
        }
    }

    /// `w(d)` given `a = a(d)` (`d >= 0`).
    #[inline]
    pub(super) fn w_at(&self, d: f64, a: f64) -> f64 {
        match self.form {
            Form::Paraboloid => d * a,
            Form::Cone { .. } => 0.75 * a * d,
            Form::Power { cw, .. } => cw * a * d,
            Form::Cap { .. } => self.point(d).w,
            Form::Other(g) => g.force_function(d),
        }
    }

    /// `w`, `a` and `a'` at `d` (`d` at least the smallest positive number) from one inverse of
    /// the profile.
    #[inline]
    pub(super) fn point(&self, d: f64) -> ShapePoint {
        let d = d.max(f64::MIN_POSITIVE);
        let (w, a, a_slope) = match self.form {
            Form::Cap { r, scale, inv_sr } => match cap_point(d * inv_sr) {
                Some((u, w, slope)) => (0.75 * scale * r * r * w, r * u, 1.0 / (scale * slope)),
                None => Geometry::Caps {
                    scale,
                    caps: [
                        Cap {
                            radius: r,
                            exact: true,
                        },
                        Cap {
                            radius: f64::INFINITY,
                            exact: false,
                        },
                    ],
                }
                .force_radius_slope(d),
            },
            Form::Other(g) => g.force_radius_slope(d),
            _ => {
                let a = self.radius_at(d);
                (self.w_at(d, a), a, self.radius_slope_at(d, a))
            }
        };
        ShapePoint { d, w, a, a_slope }
    }

    /// `(w(d), a(d))` at `d >= 0` from one inverse of the profile.
    #[inline]
    pub(super) fn w_and_radius(&self, d: f64) -> (f64, f64) {
        match self.form {
            Form::Cap { .. } if d > 0.0 => {
                let p = self.point(d);
                (p.w, p.a)
            }
            Form::Other(g) => g.force_and_radius(d),
            _ => {
                let a = self.radius_at(d);
                (self.w_at(d, a), a)
            }
        }
    }

    /// The force function `w(d)` (`d^(3/2)` for the paraboloid; 0 for `d <= 0`).
    #[inline]
    pub(super) fn w(&self, d: f64) -> f64 {
        match self.form {
            Form::Paraboloid => pow15(d),
            Form::Cap { .. } if d > 0.0 => self.point(d).w,
            Form::Cap { .. } => 0.0,
            Form::Other(g) => g.force_function(d.max(0.0)),
            _ => {
                let d = d.max(0.0);
                self.w_at(d, self.radius_at(d))
            }
        }
    }

    /// `w(d + delta) - w(d)` given `w_d = w(d)` and `w_b = w(d + delta)`: their difference when
    /// `|delta| >= 0.05 d` or an end is not positive; otherwise without it (the paraboloid's
    /// closed form; the cone's `(3/4) δ (2 d + δ) / k`; a power law's
    /// `w(d) expm1(p ln1p(δ/d))`; else `δ` times the mean of `w' = (3/2) a` by 4-point
    /// Gauss–Legendre, exact to `O(δ^8)` where `a` is smooth).
    #[inline]
    pub(super) fn w_increment_known(&self, d: f64, delta: f64, w_d: f64, w_b: f64) -> f64 {
        let b = d + delta;
        match self.form {
            Form::Paraboloid => pow15_increment(d, delta),
            Form::Cone { inv_k } if d >= 0.0 && b >= 0.0 => {
                0.75 * delta * (2.0 * d + delta) * inv_k
            }
            _ if d <= 0.0 || b <= 0.0 => w_b - w_d,
            Form::Power { .. } | Form::Cap { .. } | Form::Other(_)
                if delta.abs() >= self.direct_increment() * d =>
            {
                w_b - w_d
            }
            Form::Power { p, .. } => w_d * (p * (delta / d).ln_1p()).exp_m1(),
            _ => {
                let mean: f64 = GL_X
                    .iter()
                    .zip(GL_W)
                    .map(|(x, w)| w * self.radius_at(d + x * delta))
                    .sum();
                1.5 * delta * mean
            }
        }
    }

    /// The ratio `|δ| / d` from which an increment is the difference of the two values.
    fn direct_increment(&self) -> f64 {
        match self.form {
            Form::Cap { .. } | Form::Other(_) => DIRECT_INCREMENT_CAPS,
            _ => DIRECT_INCREMENT,
        }
    }

    /// `w'(d) = (3/2) a(d)`.
    #[inline]
    pub(super) fn w_slope(&self, d: f64) -> f64 {
        1.5 * self.radius_at(d)
    }

    /// `a'(d)` (bounds of the Newton remainders; `1 / (2 sqrt(d))` for the paraboloid), at `d`
    /// at least the smallest positive number.
    #[inline]
    pub(super) fn radius_slope(&self, d: f64) -> f64 {
        let d = d.max(f64::MIN_POSITIVE);
        match self.form {
            Form::Paraboloid => 0.5 / d.sqrt(),
            Form::Cap { .. } => self.point(d).a_slope,
            Form::Other(g) => g.contact_radius_slope(d),
            _ => self.radius_slope_at(d, self.radius_at(d)),
        }
    }

    /// `a'(d)` given `a = a(d)` (closed form for the paraboloid and the power laws).
    #[inline]
    pub(super) fn radius_slope_at(&self, d: f64, a: f64) -> f64 {
        let d = d.max(f64::MIN_POSITIVE);
        match self.form {
            Form::Paraboloid => 0.5 / d.sqrt(),
            Form::Cone { inv_k } => inv_k,
            Form::Power { inv_n, .. } => inv_n * a / d,
            Form::Cap { .. } => self.point(d).a_slope,
            Form::Other(g) if a > 0.0 => 1.0 / g.profile_slope(a),
            Form::Other(g) => g.contact_radius_slope(d),
        }
    }

    /// The maximum indentation of the elastic impact on the constant modulus `g` (canonical:
    /// `(16/3) g int_0^d w = 1/2`), the first step's length scale: in closed form for the
    /// paraboloid and the power laws (`w = cw k^(-1/n) d^p`), the paraboloid's (an upper bound:
    /// `g` lies above `x^2`) for exact caps, [`Geometry::elastic_max_indentation`] otherwise.
    pub(super) fn elastic_scale(&self, g: f64) -> f64 {
        let k16 = 16.0 / 3.0;
        match self.form {
            Form::Paraboloid => (1.25 / (k16 * g)).powf(0.4),
            Form::Cone { inv_k } => (1.5 / (k16 * g * 0.75 * inv_k)).powf(1.0 / 3.0),
            Form::Power {
                k, cw, p, inv_n, ..
            } => {
                let c = cw * k.powf(-inv_n);
                ((p + 1.0) / (2.0 * k16 * g * c)).powf(1.0 / (p + 1.0))
            }
            Form::Cap { .. } | Form::Other(Geometry::Caps { .. }) => (1.25 / (k16 * g)).powf(0.4),
            Form::Other(geom) => geom.elastic_max_indentation(g),
        }
    }
}

/// The radius of the one exact cap of a gap whose other surface is a plane.
fn single_cap(caps: &[Cap; 2]) -> Option<f64> {
    match caps {
        [c, p] | [p, c] if c.exact && c.radius.is_finite() && p.radius.is_infinite() => {
            Some(c.radius)
        }
        _ => None,
    }
}

/// Intervals of [`cap_table`] over `sqrt(y)` in `[0, CAP_V_MAX]`.
const CAP_CELLS: usize = 512;
/// The end of the table, `sqrt(y)` at `u = 0.95` (`0.95 atanh(0.95) = 1.7402…`): beyond it
/// [`cap_point`] leaves the inverse to [`Geometry`]'s Halley iteration.
const CAP_V_MAX: f64 = 1.319;

/// The inverse `u(y)` of `y = u atanh(u)` (the exact cap `g = scale x atanh(x/r)` in the units
/// `u = a / r`, `y = d / (scale r)`), tabulated once with its derivative in `v = sqrt(y)` (where
/// `u(v)` is an odd analytic function, `u ≈ v` at the tip) on [`CAP_CELLS`] uniform cells up to
/// `sqrt(y) = `[`CAP_V_MAX`]: `(cell width, [(u, du/dv)])`, each node by [`Geometry`]'s safeguarded
/// Halley iteration.
fn cap_table() -> &'static (f64, Vec<(f64, f64)>) {
    static TABLE: OnceLock<(f64, Vec<(f64, f64)>)> = OnceLock::new();
    TABLE.get_or_init(|| {
        let unit = Geometry::Caps {
            scale: 1.0,
            caps: [
                Cap {
                    radius: 1.0,
                    exact: true,
                },
                Cap {
                    radius: f64::INFINITY,
                    exact: false,
                },
            ],
        };
        let hv = CAP_V_MAX / CAP_CELLS as f64;
        let nodes = (0..=CAP_CELLS)
            .map(|i| {
                let v = i as f64 * hv;
                if i == 0 {
                    return (0.0, 1.0);
                }
                let u = unit.contact_radius(v * v);
                // dy/du = atanh(u) + u / (1 - u^2), dv/du = (dy/du) / (2 v)
                (u, 2.0 * v / (u.atanh() + u / (1.0 - u * u)))
            })
            .collect();
        (hv, nodes)
    })
}

/// `(u, ψ(u), dy/du)` at `y = u atanh(u)` (`y > 0`, `ψ(u) = (1 + u^2) atanh(u) - u`), or `None`
/// beyond the table. The cubic Hermite interpolant of [`cap_table`] (error below about 1e-10
/// on 512 cells, checked in the tests) and one Newton step on `u atanh(u) = y`, which squares
/// that error; `atanh` at the corrected point by its Taylor series from the first (the step
/// is below 1e-9, so the cubic term is below the round-off): one logarithm per call for
/// `u >= 0.2`, none below, where `atanh` and `ψ` come from the series of [`cap_atanh_tail`].
fn cap_point(y: f64) -> Option<(f64, f64, f64)> {
    let (hv, nodes) = cap_table();
    let x = y.sqrt() * (CAP_CELLS as f64 / CAP_V_MAX);
    let i = x as usize;
    if i >= CAP_CELLS {
        return None;
    }
    let t = x - i as f64;
    let ((u0, m0), (u1, m1)) = (nodes[i], nodes[i + 1]);
    let (t2, t3) = (t * t, t * t * t);
    let u = (2.0 * t3 - 3.0 * t2 + 1.0) * u0
        + (t3 - 2.0 * t2 + t) * hv * m0
        + (-2.0 * t3 + 3.0 * t2) * u1
        + (t3 - t2) * hv * m1;
    let at = if u < CAP_SERIES_U {
        u + u * cap_atanh_tail(u * u)
    } else {
        // (libm's log1p behind atanh costs about twice its log; the quotient's rounding
        // moves the result by at most 0.8e-16 / atanh(u) relative, 2 units in the last place)
        0.5 * ((1.0 + u) / (1.0 - u)).ln()
    };
    let inv_m = 1.0 / (1.0 - u * u);
    let step = (y - u * at) / (at + u * inv_m);
    let at = at + step * inv_m * (1.0 + step * u * inv_m);
    // 1 / (1 - u^2) at the corrected point to first order in the step (its square, below
    // (1e-9 inv_m)^2, is under the round-off)
    let inv_m = inv_m * (1.0 + 2.0 * u * step * inv_m);
    let u = u + step;
    Some((u, cap_psi_at(u, at), at + u * inv_m))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::geometry::Shape;

    /// The table inverse of the exact cap against [`Geometry`]'s Halley iteration, and `g(a) = d`,
    /// over the table's range and beyond it; and the interpolant's own error before the Newton
    /// step (the bound the step squares).
    #[test]
    fn cap_table_inverse_meets_the_profile() {
        let geom = Shape::sphere(2e-3).canonical(1e-3, 2.0, 1e6).2;
        let fns = ShapeFns::new(Some(geom));
        assert!(matches!(fns.form, Form::Cap { .. }));
        let Geometry::Caps { scale, caps } = geom else {
            unreachable!()
        };
        let r = caps[0].radius;
        let mut worst_interp = 0.0f64;
        let (hv0, nodes0) = cap_table();
        for (i, (u, _)) in nodes0.iter().enumerate().skip(1) {
            let y = (i as f64 * hv0).powi(2);
            assert!((u * u.atanh() - y).abs() <= 1e-15 * y, "node {i}");
        }
        for i in 1..4000 {
            let u = 0.99 * i as f64 / 4000.0;
            let d = geom.profile(u * r);
            let p = fns.point(d);
            let a = geom.contact_radius(d);

            // a few units in the last place apart (either rounds)
            assert!((p.a - a).abs() <= 1e-15 * a, "u {u}: {} vs {a}", p.a);
            assert!((geom.profile(p.a) - d).abs() <= 1e-14 * d, "u {u}");
            let w = geom.force_function(d);
            // both lose up to 19 units in the last place just above u = 0.2 (cap_psi)
            assert!((p.w - w).abs() <= 1e-14 * w, "u {u}: w {} vs {w}", p.w);
            let slope = 1.0 / geom.profile_slope(a);
            assert!((p.a_slope - slope).abs() <= 1e-14 * slope, "u {u}");
            // the interpolant alone (u below the table's end)
            let y = d / (scale * r);
            let (hv, nodes) = cap_table();
            let x = y.sqrt() / hv;
            let j = x as usize;
            if j < CAP_CELLS {
                let t = x - j as f64;
                let ((u0, m0), (u1, m1)) = (nodes[j], nodes[j + 1]);
                let (t2, t3) = (t * t, t * t * t);
                let ui = (2.0 * t3 - 3.0 * t2 + 1.0) * u0
                    + (t3 - 2.0 * t2 + t) * hv * m0
                    + (-2.0 * t3 + 3.0 * t2) * u1
                    + (t3 - t2) * hv * m1;
                worst_interp = worst_interp.max((ui - u).abs() / u);
            }
        }
        assert!(worst_interp < 1e-9, "interpolation error {worst_interp:e}");
    }

    /// The closed forms of the power laws and the cone against [`Geometry`].
    #[test]
    fn power_law_closed_forms_meet_the_geometry() {
        for n in [1.0, 1.5, 3.0] {
            let geom = Geometry::PowerLaw {
                exponent: n,
                coefficient: 1.7,
            };
            let fns = ShapeFns::new(Some(geom));
            for d in [1e-6, 0.01, 0.3, 1.0, 2.5] {
                let p = fns.point(d);
                let (w, a) = (geom.force_function(d), geom.contact_radius(d));
                assert!((p.w - w).abs() <= 4e-16 * w && (p.a - a).abs() <= 4e-16 * a);
                let slope = geom.contact_radius_slope(d);
                assert!((p.a_slope - slope).abs() <= 1e-15 * slope);
                for delta in [1e-9 * d, 1e-3 * d, 0.2 * d] {
                    let inc = fns.w_increment_known(d, delta, w, geom.force_function(d + delta));
                    // 1.5 int a by the midpoint rule, refined
                    let n_int = 4000;
                    let h = delta / n_int as f64;
                    let num: f64 = (0..n_int)
                        .map(|i| 1.5 * geom.contact_radius(d + (i as f64 + 0.5) * h) * h)
                        .sum();
                    assert!((inc - num).abs() <= 1e-8 * num, "n {n} d {d} delta {delta}");
                }
            }
        }
    }
}
