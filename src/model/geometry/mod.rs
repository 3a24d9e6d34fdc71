//! Axisymmetric indenters (docs/theory.md §11): the rigid body's shape in SI ([`Shape`]) and, in
//! canonical units, the MDR's view of it ([`Geometry`]): the equivalent profile `g(x)`, the
//! contact radius `a(d)` and the force function `w(d)` every solver integrates.
//!
//! # The one function a solver needs
//! For any axisymmetric profile the MDR foundation of elements `4 G dx` pressed to `d - g(x)`
//! for `|x| < a(d)` (with `g(a) = d`) gives, with a constant modulus `G`, the force
//! `F = 8 G int_0^a (d - g(x)) dx = (16/3) G w(d)`, and `w'(d) = (3/2) a(d)`. Lee–Radok
//! (loading) and Ting (unloading) then hold with `w` in place of the paraboloid's `d^(3/2)`
//! (docs/theory.md §11): the Ting condition does not involve the shape, only its force and
//! contact radius do. The flat punch has `g = 0` inside its radius: its contact radius never
//! shrinks, and contact ends when the force returns to zero.
//!
//! # Canonical units
//! Each shape has its own length scale `L` (of `d`) and radius scale `A` (of `a`), chosen so
//! that `G_inf A L^2 = m v0^2` (force scale `m v0^2 / L = G_inf A L`) and that the canonical
//! shape is a fixed member of its family ([`Shape::canonical`]):
//!
//! | shape | `A`, `L` | canonical `g(x)` |
//! |---|---|---|
//! | paraboloid `R` | `L = (m v0^2 / (G sqrt R))^(2/5)`, `A = sqrt(R L)` | `x^2` |
//! | power law `c r^n` (cone: `n = 1`, `c = 1/tan θ`) | `A^(2n+1) = m v0^2 / (G k_n^2 c^2)`, `L = k_n c A^n` | `x^n` |
//! | flat punch `a_0` | `A = a_0`, `L = sqrt(m v0^2 / (G a_0))` | `0` for `x < 1` |
//! | exact sphere(s) `R_i` | as the paraboloid of `1/R = Σ 1/R_i` | `(A/L) x Σ atanh(x A / R_i)` |
//!
//! with `k_n = sqrt(pi) Γ(n/2 + 1) / Γ(n/2 + 1/2)` (`g = k_n c x^n`, Popov & Heß's MDR rule).

use crate::error::{Error, Result};

/// The rigid indenter's shape in SI, `f(r)` its height above the tip at distance `r` from the
/// axis (m).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Shape {
    /// Hertz's paraboloid `f(r) = r^2 / (2 R)`, radius of curvature `R` (m).
    Paraboloid {
        /// `R` (m).
        radius: f64,
    },
    /// The exact spherical cap `f(r) = R - sqrt(R^2 - r^2)`, or the gap of two colliding bodies
    /// with a cap each (the profiles add): `caps` are the two bodies' radii (m, `inf` for a
    /// flat wall) and whether each is exact (`true`) or Hertz's paraboloid.
    Spheres {
        /// The two surfaces of the gap.
        caps: [Cap; 2],
    },
    /// The cone `f(r) = r / tan(θ)`, `θ` the angle between the axis and the face (degrees).
    Cone {
        /// `θ` (degrees, `0 < θ < 90`).
        half_angle_deg: f64,
    },
    /// The power law `f(r) = c r^n` (SI: `c` in m^(1 - n)).
    PowerLaw {
        /// `n` (`0.25 <= n <= 20`).
        exponent: f64,
        /// `c` (m^(1 - n)).
        coefficient: f64,
    },
    /// The flat-ended cylinder of radius `a_0` (m): its contact radius is `a_0` from the first
    /// touch to the separation.
    Flat {
        /// `a_0` (m).
        radius: f64,
    },
}

/// One surface of a gap of spheres: its radius (m, or canonical) and whether the exact cap
/// (`true`) or Hertz's paraboloid of the same radius (`false`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cap {
    /// Radius (`inf`: a plane, contributing nothing).
    pub radius: f64,
    /// The exact spherical cap rather than its paraboloid.
    pub exact: bool,
}

/// Largest contact radius, relative to the smallest exact cap's radius, that the canonical
/// [`Geometry::contact_radius`] returns (`g` grows without bound as `a -> R`).
const CAP_EDGE: f64 = 1.0 - 1e-15;

impl Shape {
    /// One exact sphere of radius `radius` (m).
    pub fn sphere(radius: f64) -> Self {
        Shape::Spheres {
            caps: [
                Cap {
                    radius,
                    exact: true,
                },
                Cap {
                    radius: f64::INFINITY,
                    exact: false,
                },
            ],
        }
    }

    /// The shape if every parameter is in range, else the first that is not (named as in a
    /// scene: `radius`, `half_angle_deg`, `exponent`, `coefficient`).
    pub fn validated(self) -> Result<Self> {
        let bad = |field, value, allowed| Error::OutOfRange {
            field,
            value,
            allowed,
        };
        match self {
            Shape::Paraboloid { radius } | Shape::Flat { radius } => {
                if !(radius.is_finite() && radius > 0.0) {
                    return Err(bad("radius", radius, "0 < radius < inf (m)"));
                }
            }
            Shape::Spheres { caps } => {
                for c in caps {
                    if !(c.radius > 0.0) || c.radius.is_nan() {
                        return Err(bad("radius", c.radius, "0 < radius <= inf (m)"));
                    }
                }
                if caps.iter().all(|c| c.radius.is_infinite()) {
                    return Err(bad(
                        "radius",
                        f64::INFINITY,
                        "at least one finite radius (two planes do not make a contact)",
                    ));
                }
            }
            Shape::Cone { half_angle_deg } => {
                if !(half_angle_deg > 0.0 && half_angle_deg < 90.0) {
                    return Err(bad(
                        "half_angle_deg",
                        half_angle_deg,
                        "0 < half_angle_deg < 90 (degrees between axis and face)",
                    ));
                }
            }
            Shape::PowerLaw {
                exponent,
                coefficient,
            } => {
                if !(0.25..=20.0).contains(&exponent) {
                    return Err(bad("exponent", exponent, "0.25 <= exponent <= 20"));
                }
                if !(coefficient.is_finite() && coefficient > 0.0) {
                    return Err(bad(
                        "coefficient",
                        coefficient,
                        "0 < coefficient < inf (m^(1 - exponent))",
                    ));
                }
            }
        }
        Ok(self)
    }

    /// The scene name of the shape: `paraboloid`, `sphere`, `cone`, `power-law`, `flat`.
    pub fn name(&self) -> &'static str {
        match self {
            Shape::Paraboloid { .. } => "paraboloid",
            Shape::Spheres { .. } => "sphere",
            Shape::Cone { .. } => "cone",
            Shape::PowerLaw { .. } => "power-law",
            Shape::Flat { .. } => "flat",
        }
    }

    /// The radius of curvature at the tip (m) of a shape that has one (paraboloid, spheres:
    /// `1/R = Σ 1/R_i`); `None` for cones, power laws other than `n = 2` and flat punches.
    pub fn tip_radius(&self) -> Option<f64> {
        match *self {
            Shape::Paraboloid { radius } => Some(radius),
            Shape::Spheres { caps } => Some(1.0 / caps.iter().map(|c| 1.0 / c.radius).sum::<f64>()),
            Shape::PowerLaw {
                exponent: 2.0,
                coefficient,
            } => Some(0.5 / coefficient),
            _ => None,
        }
    }

    /// The radius (m) the contact radius cannot reach: the smallest exact cap's; `None` for
    /// shapes without such a limit.
    pub fn cap_limit(&self) -> Option<f64> {
        match self {
            Shape::Spheres { caps } => caps
                .iter()
                .filter(|c| c.exact)
                .map(|c| c.radius)
                .min_by(f64::total_cmp)
                .filter(|r| r.is_finite()),
            _ => None,
        }
    }

    /// True for the flat punch (no Ting phase: the contact radius is constant).
    pub fn is_flat(&self) -> bool {
        matches!(self, Shape::Flat { .. })
    }

    /// A one-line description with the parameters in SI, for reports.
    pub fn describe(&self) -> String {
        match *self {
            Shape::Paraboloid { radius } => format!("paraboloid, R = {radius:.6e} m"),
            Shape::Spheres { caps } => {
                let parts: Vec<String> = caps
                    .iter()
                    .filter(|c| c.radius.is_finite())
                    .map(|c| {
                        format!(
                            "{} R = {:.6e} m",
                            if c.exact {
                                "exact sphere"
                            } else {
                                "paraboloid"
                            },
                            c.radius
                        )
                    })
                    .collect();
                parts.join(" + ")
            }
            Shape::Cone { half_angle_deg } => format!("cone, half angle {half_angle_deg} deg"),
            Shape::PowerLaw {
                exponent,
                coefficient,
            } => format!("power law f = {coefficient:.6e} r^{exponent}"),
            Shape::Flat { radius } => format!("flat punch, radius {radius:.6e} m"),
        }
    }

    /// The scales `(L, A)` of the canonical units of an impact of mass `mass` (kg) at `velocity`
    /// (m/s) on the modulus scale `modulus` (Pa), and the canonical geometry (module docs).
    /// Computed in logarithms to survive extreme magnitudes.
    pub fn canonical(&self, mass: f64, velocity: f64, modulus: f64) -> (f64, f64, Geometry) {
        // ln(m v0^2 / G)
        let ln_e = mass.ln() + 2.0 * velocity.ln() - modulus.ln();
        let paraboloid = |r: f64| {
            let ln_l = 0.4 * (ln_e - 0.5 * r.ln());
            let ln_a = 0.5 * (r.ln() + ln_l);
            (ln_l.exp(), ln_a.exp())
        };
        match *self {
            Shape::Paraboloid { radius } => {
                let (l, a) = paraboloid(radius);
                (l, a, Geometry::UNIT_SPHERE)
            }
            Shape::Spheres { caps } => {
                let r = self.tip_radius().unwrap_or(f64::INFINITY);
                let (l, a) = paraboloid(r);
                let scale = a / l;
                let caps = caps.map(|c| Cap {
                    radius: c.radius / a,
                    exact: c.exact,
                });
                (l, a, Geometry::Caps { scale, caps })
            }
            Shape::Cone { half_angle_deg } => {
                let c = 1.0 / half_angle_deg.to_radians().tan();
                power_law_scales(ln_e, 1.0, c)
            }
            Shape::PowerLaw {
                exponent,
                coefficient,
            } => {
                if exponent == 2.0 {
                    let (l, a) = paraboloid(0.5 / coefficient);
                    return (l, a, Geometry::UNIT_SPHERE);
                }
                power_law_scales(ln_e, exponent, coefficient)
            }
            Shape::Flat { radius } => {
                let ln_l = 0.5 * (ln_e - radius.ln());
                (ln_l.exp(), radius, Geometry::Flat { radius: 1.0 })
            }
        }
    }
}

/// The parameters a shape may be given with (a scene's `[indenter]` keys, the `indent` flags),
/// and the names the caller gives them in messages (in the order radius, half angle, exponent,
/// coefficient).
#[derive(Debug, Clone, Copy, Default)]
pub struct ShapeKeys {
    /// Radius (m) of a paraboloid, a sphere or a flat punch.
    pub radius: Option<f64>,
    /// Half angle of a cone (degrees).
    pub half_angle_deg: Option<f64>,
    /// Exponent of a power law.
    pub exponent: Option<f64>,
    /// Coefficient of a power law (m^(1 - exponent)).
    pub coefficient: Option<f64>,
}

/// The shape names [`Shape::from_keys`] accepts.
pub const SHAPE_NAMES: [&str; 5] = ["paraboloid", "sphere", "cone", "power-law", "flat"];

impl Shape {
    /// The shape `name` (one of [`SHAPE_NAMES`]) from exactly the keys it takes: a missing key,
    /// a key that does not apply or an unknown name is a message naming it as `names` does
    /// (the caller's spelling of radius, half angle, exponent, coefficient); the values are
    /// range-checked ([`Shape::validated`]) by the caller.
    pub fn from_keys(
        name: &str,
        keys: &ShapeKeys,
        names: [&str; 4],
    ) -> std::result::Result<Shape, String> {
        let given = [
            keys.radius,
            keys.half_angle_deg,
            keys.exponent,
            keys.coefficient,
        ];
        let need = |i: usize| given[i].ok_or_else(|| format!("shape {name} needs {}", names[i]));
        let (shape, takes): (Shape, &[usize]) = match name {
            "paraboloid" => (Shape::Paraboloid { radius: need(0)? }, &[0]),
            "sphere" => (Shape::sphere(need(0)?), &[0]),
            "flat" => (Shape::Flat { radius: need(0)? }, &[0]),
            "cone" => (
                Shape::Cone {
                    half_angle_deg: need(1)?,
                },
                &[1],
            ),
            "power-law" => (
                Shape::PowerLaw {
                    exponent: need(2)?,
                    coefficient: need(3)?,
                },
                &[2, 3],
            ),
            other => {
                return Err(format!(
                    "unknown shape '{}': expected one of {}",
                    crate::error::escape_text(other),
                    SHAPE_NAMES.join(", ")
                ))
            }
        };
        if let Some(i) = (0..4).find(|i| given[*i].is_some() && !takes.contains(i)) {
            let list: Vec<&str> = takes.iter().map(|i| names[*i]).collect();
            return Err(format!(
                "{} does not apply to shape {name} (it takes {})",
                names[i],
                list.join(", ")
            ));
        }
        Ok(shape)
    }

    /// The shape's geometry in SI (lengths in m: the canonical form with `L = A = 1 m`), for a
    /// prescribed indentation ([`crate::solvers::force_curve`]).
    pub fn geometry_si(&self) -> Geometry {
        match *self {
            Shape::Paraboloid { radius } => Geometry::Paraboloid { radius },
            Shape::Spheres { caps } => Geometry::Caps { scale: 1.0, caps },
            Shape::Cone { half_angle_deg } => Geometry::PowerLaw {
                exponent: 1.0,
                coefficient: power_law_stretch(1.0) / half_angle_deg.to_radians().tan(),
            },
            Shape::PowerLaw {
                exponent,
                coefficient,
            } => Geometry::PowerLaw {
                exponent,
                coefficient: power_law_stretch(exponent) * coefficient,
            },
            Shape::Flat { radius } => Geometry::Flat { radius },
        }
    }
}

/// `k_n = sqrt(pi) Γ(n/2 + 1) / Γ(n/2 + 1/2)`: the MDR profile of `f = c r^n` is `k_n c x^n`.
pub fn power_law_stretch(n: f64) -> f64 {
    use statrs::function::gamma::ln_gamma;
    (0.5 * std::f64::consts::PI.ln() + ln_gamma(0.5 * n + 1.0) - ln_gamma(0.5 * n + 0.5)).exp()
}

fn power_law_scales(ln_e: f64, n: f64, c: f64) -> (f64, f64, Geometry) {
    let ln_kc = power_law_stretch(n).ln() + c.ln();
    let ln_a = (ln_e - 2.0 * ln_kc) / (2.0 * n + 1.0);
    let ln_l = ln_kc + n * ln_a;
    (
        ln_l.exp(),
        ln_a.exp(),
        Geometry::PowerLaw {
            exponent: n,
            coefficient: 1.0,
        },
    )
}

/// The shape of the indenter, as the MDR sees it, in canonical units (module docs): the
/// equivalent profile `g(x)` of the one-dimensional foundation, the contact radius `a(d)` and
/// the force function `w(d)` (`F = (16/3) G w(d)` for a constant modulus, `w' = (3/2) a`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Geometry {
    /// The paraboloid `g(x) = x^2 / R`, `a = sqrt(R d)`, `w = sqrt(R) d^(3/2)`.
    Paraboloid {
        /// Radius of curvature `R` (1 in canonical units).
        radius: f64,
    },
    /// The power law `g(x) = k x^n`, `a = (d/k)^(1/n)`, `w = (3/2) n/(n+1) a d` (the cone:
    /// `n = 1`; `k = 1` in canonical units, `k_n c` in SI).
    PowerLaw {
        /// `n`.
        exponent: f64,
        /// `k`.
        coefficient: f64,
    },
    /// The flat punch: `g = 0` for `x < radius`, `a = radius`, `w = (3/2) radius d`.
    Flat {
        /// The punch radius (1 in canonical units).
        radius: f64,
    },
    /// Exact spherical caps (and paraboloids) adding to one gap:
    /// `g(x) = scale x Σ_i φ_i(x)`, `φ_i = atanh(x / R_i)` for an exact cap, `x / R_i` for a
    /// paraboloid.
    Caps {
        /// The factor `A / L` of the profile.
        scale: f64,
        /// The two surfaces (canonical radii, `inf` for a plane).
        caps: [Cap; 2],
    },
}

/// Below this `u` the cap's functions of `u = a / R` use the series of [`cap_atanh_tail`]
/// instead of `atanh` (where `ψ`'s closed form cancels).
pub const CAP_SERIES_U: f64 = 0.2;

/// `(1 + u^2) atanh(u) - u` for `0 <= u < 1`, by the series of [`cap_atanh_tail`] where the
/// closed form cancels (`u <` [`CAP_SERIES_U`]: the closed form loses at most `0.75 / u^2` units
/// in the last place, 19 at `u = 0.2`).
fn cap_psi(u: f64) -> f64 {
    cap_psi_at(u, if u >= CAP_SERIES_U { u.atanh() } else { 0.0 })
}

/// `ψ(u) = (1 + u^2) atanh(u) - u` given `atanh_u = atanh(u)` (not read for `u <`
/// [`CAP_SERIES_U`], where `ψ = u (u^2 + (1 + u^2) T(u^2))` with `T` = [`cap_atanh_tail`], a sum
/// of positive terms, replaces the cancelling closed form).
pub fn cap_psi_at(u: f64, atanh_u: f64) -> f64 {
    if u >= CAP_SERIES_U {
        return (1.0 + u * u) * atanh_u - u;
    }
    let x = u * u;
    u * (x + (1.0 + x) * cap_atanh_tail(x))
}

/// `T(x) = Σ_{k>=1} x^k / (2k + 1)` for `0 <= x < CAP_SERIES_U^2 = 0.04`, so that
/// `atanh(u) = u (1 + T(u^2))` for `u < 0.2` without a logarithm. Thirteen terms: the first
/// omitted one, `x^14 / 29`, is below `2e-18 T(x)` there (`T >= x / 3`). By Estrin's scheme
/// (independent pairs, then powers `x^2`, `x^4`, `x^8`: a chain of 5 products instead of
/// Horner's 13; plain products and sums, no fused multiply-add, so every build rounds alike).
pub fn cap_atanh_tail(x: f64) -> f64 {
    // a_k = 1 / (2k + 3), k = 0..=12: T = x Σ a_k x^k
    const A: [f64; 13] = {
        let mut a = [0.0; 13];
        let mut k = 0;
        while k < 13 {
            a[k] = 1.0 / (2 * k + 3) as f64;
            k += 1;
        }
        a
    };
    let x2 = x * x;
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    let q0 = (A[0] + A[1] * x) + (A[2] + A[3] * x) * x2;
    let q1 = (A[4] + A[5] * x) + (A[6] + A[7] * x) * x2;
    let q2 = (A[8] + A[9] * x) + (A[10] + A[11] * x) * x2;
    let r0 = q0 + q1 * x4;
    let r1 = q2 + A[12] * x4;
    x * (r0 + r1 * x8)
}

impl Geometry {
    /// The canonical sphere, `R = 1`.
    pub const UNIT_SPHERE: Geometry = Geometry::Paraboloid { radius: 1.0 };

    /// The MDR equivalent profile `g(x)` at distance `x` from the axis (docs/theory.md, paper
    /// Eq. 6; `inf` outside a flat punch and at or beyond an exact cap's radius).
    pub fn profile(&self, x: f64) -> f64 {
        match *self {
            Geometry::Paraboloid { radius } => x * x / radius,
            Geometry::PowerLaw {
                exponent,
                coefficient,
            } => coefficient * x.powf(exponent),
            Geometry::Flat { radius } => {
                if x < radius {
                    0.0
                } else {
                    f64::INFINITY
                }
            }
            Geometry::Caps { scale, caps } => {
                let mut s = 0.0;
                for c in caps {
                    if c.radius.is_infinite() {
                        continue;
                    }
                    let u = x / c.radius;
                    s += if !c.exact {
                        u
                    } else if u < 1.0 {
                        u.atanh()
                    } else {
                        return f64::INFINITY;
                    };
                }
                scale * x * s
            }
        }
    }

    /// `g'(x)`.
    pub fn profile_slope(&self, x: f64) -> f64 {
        match *self {
            Geometry::Paraboloid { radius } => 2.0 * x / radius,
            Geometry::PowerLaw {
                exponent,
                coefficient,
            } => coefficient * exponent * x.powf(exponent - 1.0),
            Geometry::Flat { .. } => 0.0,
            Geometry::Caps { scale, caps } => {
                let mut s = 0.0;
                for c in caps {
                    if c.radius.is_infinite() {
                        continue;
                    }
                    let u = x / c.radius;
                    s += if c.exact {
                        u.atanh() + u / (1.0 - u * u)
                    } else {
                        2.0 * u
                    };
                }
                scale * s
            }
        }
    }

    /// Contact radius `a(d)` at indentation `d > 0` (the inverse of `g`; the punch radius for a
    /// flat punch; `0` for `d <= 0` otherwise).
    pub fn contact_radius(&self, d: f64) -> f64 {
        if let Geometry::Flat { radius } = *self {
            return radius;
        }
        if !(d > 0.0) {
            return 0.0;
        }
        match *self {
            Geometry::Paraboloid { radius } => (radius * d).sqrt(),
            Geometry::PowerLaw {
                exponent,
                coefficient,
            } => (d / coefficient).powf(1.0 / exponent),
            Geometry::Flat { radius } => radius,
            Geometry::Caps { .. } => self.cap_radius(d),
        }
    }

    /// The contact radius `a(d) > 0` of exact caps, by Halley's iteration on
    /// `g(a) = d` (`g'' = scale Σ 2 / (R_i (1 - u_i^2)^2)` for an exact cap, `2 scale / R_i` for
    /// a paraboloid, with no further logarithm) from the inverse of the profile's first two
    /// terms, `g ≈ κ x^2 + μ x^4` (`κ = scale Σ 1/R_i`, `μ = scale Σ_exact 1/(3 R_i^3)`),
    /// safeguarded by bisection in `[0, min(sqrt(d/κ), edge)]` (`g >= κ x^2` bounds `a` from
    /// above). The start is within `O((a/R)^4)`, so two or three iterations (one logarithm per
    /// exact cap each) reach the round-off; stopped once the cube of the last relative step,
    /// amplified by `1/(1 - u^2)^2`, is below `1e-17`.
    fn cap_radius(&self, d: f64) -> f64 {
        let Geometry::Caps { scale, caps } = *self else {
            return self.contact_radius(d);
        };
        let mut edge = f64::INFINITY;
        let (mut kappa, mut mu) = (0.0, 0.0);
        for c in caps {
            if c.radius.is_infinite() {
                continue;
            }
            kappa += scale / c.radius;
            if c.exact {
                edge = edge.min(c.radius);
                mu += scale / (3.0 * c.radius * c.radius * c.radius);
            }
        }
        let edge = edge * CAP_EDGE;
        let hi0 = (d / kappa).sqrt().min(edge);
        // v = x^2 from κ v + μ v^2 = d, without cancellation
        let v = 2.0 * d / (kappa + (kappa * kappa + 4.0 * mu * d).sqrt());
        let (mut lo, mut hi) = (0.0, hi0);
        let mut a = v.sqrt().min(hi0);
        for _ in 0..100 {
            // g, g', g'' at a
            let (mut g, mut g1, mut g2, mut near) = (0.0, 0.0, 0.0, 1.0f64);
            for c in caps {
                if c.radius.is_infinite() {
                    continue;
                }
                let u = a / c.radius;
                if c.exact {
                    if u >= 1.0 {
                        g = f64::INFINITY;
                        break;
                    }
                    let at = u.atanh();
                    let m = 1.0 - u * u;
                    g += a * at;
                    g1 += at + u / m;
                    g2 += 2.0 / (c.radius * m * m);
                    near = near.min(m);
                } else {
                    g += a * u;
                    g1 += 2.0 * u;
                    g2 += 2.0 / c.radius;
                }
            }
            let (f, f1, f2) = (scale * g - d, scale * g1, scale * g2);
            if f == 0.0 {
                break;
            }
            if f > 0.0 {
                hi = a;
            } else {
                lo = a;
            }
            // Halley: a - 2 f f' / (2 f'^2 - f f'')
            let den = 2.0 * f1 * f1 - f * f2;
            let next = if f.is_finite() && den > 0.0 {
                a - 2.0 * f * f1 / den
            } else {
                f64::NAN
            };
            if next >= lo && next <= hi {
                // a Halley step: the error after it is about the cube of its length
                let rel = (next - a).abs() / next;
                a = next;
                if rel * rel * rel <= 1e-17 * near * near {
                    break;
                }
            } else {
                a = 0.5 * (lo + hi);
                if hi - lo <= 1e-16 * hi {
                    break;
                }
            }
        }
        a.max(0.0)
    }

    /// `a'(d) = 1 / g'(a(d))` (`0` for a flat punch and for `d <= 0`).
    pub fn contact_radius_slope(&self, d: f64) -> f64 {
        if !(d > 0.0) || self.is_flat() {
            return 0.0;
        }
        match *self {
            Geometry::Caps { .. } => 1.0 / self.profile_slope(self.cap_radius(d)),
            _ => 1.0 / self.profile_slope(self.contact_radius(d)),
        }
    }

    /// Indentation `d(a)` at which the contact radius is `a` (`g(a)`).
    pub fn indentation(&self, a: f64) -> f64 {
        self.profile(a)
    }

    /// The force function `w(d)` (`F = (16/3) G w(d)` for a constant modulus `G`;
    /// `w(d) = (3/2) int_0^a (d - g(x)) dx`), `0` for `d <= 0` but for the flat punch, whose
    /// `w = (3/2) radius d` is linear.
    pub fn force_function(&self, d: f64) -> f64 {
        if let Geometry::Flat { radius } = *self {
            return 1.5 * radius * d;
        }
        if !(d > 0.0) {
            return 0.0;
        }
        match *self {
            Geometry::Paraboloid { radius } => radius.sqrt() * d.powf(1.5),
            Geometry::PowerLaw {
                exponent,
                coefficient,
            } => 1.5 * exponent / (exponent + 1.0) * (d / coefficient).powf(1.0 / exponent) * d,
            Geometry::Flat { radius } => 1.5 * radius * d,
            Geometry::Caps { .. } => self.caps_force(self.cap_radius(d)),
        }
    }

    /// `w` of exact caps at the contact radius `a`:
    /// `(3/4) scale Σ_i R_i^2 ψ(a / R_i)` (`ψ(u) = (1 + u^2) atanh(u) - u` for an exact cap,
    /// `(4/3) u^3` for a paraboloid).
    fn caps_force(&self, a: f64) -> f64 {
        match *self {
            Geometry::Caps { scale, caps } => {
                let mut s = 0.0;
                for c in caps {
                    if c.radius.is_infinite() {
                        continue;
                    }
                    let u = a / c.radius;
                    let psi = if c.exact {
                        cap_psi(u)
                    } else {
                        4.0 / 3.0 * u * u * u
                    };
                    s += c.radius * c.radius * psi;
                }
                0.75 * scale * s
            }
            _ => f64::NAN,
        }
    }

    /// `(w(d), a(d), a'(d))` at `d > 0`, sharing the inverse of the profile (exact caps).
    pub fn force_radius_slope(&self, d: f64) -> (f64, f64, f64) {
        match *self {
            Geometry::Caps { .. } if d > 0.0 => {
                let a = self.cap_radius(d);
                (self.caps_force(a), a, 1.0 / self.profile_slope(a))
            }
            _ => (
                self.force_function(d),
                self.contact_radius(d),
                self.contact_radius_slope(d),
            ),
        }
    }

    /// `(w(d), a(d))`, sharing the inverse of the profile (exact caps) between them.
    pub fn force_and_radius(&self, d: f64) -> (f64, f64) {
        match *self {
            Geometry::Caps { .. } if d > 0.0 => {
                let a = self.cap_radius(d);
                (self.caps_force(a), a)
            }
            _ => (self.force_function(d), self.contact_radius(d)),
        }
    }

    /// `w'(d) = (3/2) a(d)`.
    pub fn force_slope(&self, d: f64) -> f64 {
        1.5 * self.contact_radius(d)
    }

    /// `1 / R` of a paraboloid: the factor of `x^2` in `g(x)` (`None` for other shapes).
    pub fn inverse_radius(&self) -> Option<f64> {
        match *self {
            Geometry::Paraboloid { radius } => Some(1.0 / radius),
            _ => None,
        }
    }

    /// True for the flat punch.
    pub fn is_flat(&self) -> bool {
        matches!(self, Geometry::Flat { .. })
    }

    /// The elastic impact in this geometry with the constant modulus `g` (canonical: unit mass
    /// and impact velocity): the maximum indentation, from `(16/3) g int_0^d w = 1/2`.
    pub fn elastic_max_indentation(&self, g: f64) -> f64 {
        let energy = |d: f64| 16.0 / 3.0 * g * integral_of(|x| self.force_function(x), d);
        // bracket then bisect in log space (the energy grows monotonically)
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        while energy(hi) < 0.5 {
            lo = hi;
            hi *= 2.0;
            if hi > 1e300 {
                break;
            }
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if energy(mid) < 0.5 {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo <= 1e-15 * hi {
                break;
            }
        }
        0.5 * (lo + hi)
    }
}

/// `int_0^d f` by 64-point Gauss–Legendre after the substitution `x = d s^2` (smooth for the
/// `sqrt`-type start of every force function).
fn integral_of(f: impl Fn(f64) -> f64, d: f64) -> f64 {
    crate::math::quad::integrate(
        "force function",
        |s| 2.0 * d * s * f(d * s * s),
        0.0,
        1.0,
        &[],
        1e-13,
    )
    .map_or(f64::NAN, |q| q.value)
}

#[cfg(test)]
mod tests;
