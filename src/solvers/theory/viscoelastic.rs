//! Lee–Radok (compression) and Ting/Graham (restitution) for a prescribed indentation history
//! `d(t)` with one maximum, rigid sphere of radius `R`, any Prony relaxation function `G_eq`
//! (docs/theory.md §4).
//!
//! ```text
//! 0 <= t <= t_m:  a^2 = R d(t),  F(t) = (16 sqrt(R)/3) int_0^t G_eq(t-s) d/ds[d(s)^(3/2)] ds
//! t > t_m:        t_1(t) in [0, t_m] root of  Phi(t_1) = int_{t_1}^t G_eq(t-s) d'(s) ds = 0,
//!                 a^2 = R d(t_1),  F(t) = (16 sqrt(R)/3) int_0^{t_1} G_eq(t-s) d/ds[d^(3/2)] ds
//! separation:     t_s root of psi(t) = int_0^t G_eq(t-s) d'(s) ds = 0 (t_1 = 0); F = a = 0 after.
//! ```
//!
//! [`response`] and [`separation_time`] evaluate the integrals with the checked quadrature of
//! [`crate::math::quad`] (pieces split at the kinks of `d'` and at `t - 4^j tau_k` to isolate the kernel
//! layers; absolute tolerance [`super::QUAD_RTOL`] times the natural scale of each integral) and
//! find the roots with [`crate::math::roots::newton_bracketed`] (`dPhi/dt_1 = -d'(t_1) G_eq(t-t_1)`).
//!
//! [`triangle_closed_form`] is the independent closed form for the triangle history
//! `d = V t` (`t <= T`), `d = V(2T - t)`: with Dawson's integral `D` and
//! `J(x) = x - D(x)` ([`crate::math::special::x_minus_dawson`]),
//!
//! ```text
//! int_0^t exp(-(t-s)/tau) d/ds[(V s)^(3/2)] ds = (3/2) V^(3/2) tau^(3/2) J(sqrt(t/tau))
//! ```
//!
//! (substitute `s = tau y^2`: `int_0^X y^2 e^(y^2) dy = e^(X^2) (X - D(X)) / 2`), and with
//! `A(a, b) = int_a^b G_eq(t-s) ds = c_inf (b-a) - sum_k c_k tau_k e^(-(t-b)/tau_k) expm1(-(b-a)/tau_k)`
//! the restitution condition is `A(t_1, T) = A(T, t)` and separation `A(0, T) = A(T, t_s)`.

use super::{QUAD_MAX_PIECES, QUAD_RTOL, ROOT_RTOL};
use crate::error::{check, Error, Result};
use crate::math::quad::{integrate, layer_splits};
use crate::math::roots::newton_bracketed;
use crate::math::special::x_minus_dawson;
use crate::model::geometry::Geometry;
use crate::model::material::Prony;
use crate::solvers::indentation::Prescribed;

/// An indentation history `d(t) >= 0` with a single maximum at [`OneMaximum::peak_time`],
/// increasing before and decreasing after it.
pub trait OneMaximum {
    /// Depth `d(t)`.
    fn depth(&self, t: f64) -> f64;
    /// Rate `d'(t)`.
    fn rate(&self, t: f64) -> f64;
    /// Time of the maximum `t_m`.
    fn peak_time(&self) -> f64;
    /// End of the prescribed history (the contact has separated by then).
    fn end_time(&self) -> f64;
    /// Interior points where `d'` is not smooth.
    fn kinks(&self) -> Vec<f64>;
}

impl OneMaximum for Prescribed {
    fn depth(&self, t: f64) -> f64 {
        Prescribed::depth(self, t)
    }
    fn rate(&self, t: f64) -> f64 {
        Prescribed::rate(self, t)
    }
    fn peak_time(&self) -> f64 {
        Prescribed::peak_time(self)
    }
    fn end_time(&self) -> f64 {
        Prescribed::end_time(self)
    }
    fn kinks(&self) -> Vec<f64> {
        Prescribed::kinks(self)
    }
}

/// One sample of a Lee–Radok/Ting response.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IndentSample {
    /// Time.
    pub t: f64,
    /// Prescribed depth `d(t)`.
    pub d: f64,
    /// Contact radius `a = sqrt(R d(t_1))` (`0` after separation).
    pub a: f64,
    /// Contact force (`0` after separation).
    pub force: f64,
    /// Ting's `t_1(t)`: `= t` while loading, the root of `Phi` after the peak, `0` after separation.
    pub t1: f64,
}

fn check_inputs(prony: &Prony, radius: f64) -> Result<()> {
    check("radius", radius, radius > 0.0, "0 < radius < inf")?;
    prony.validate()?;
    Ok(())
}

/// Split points for integrals over `s` in `[a, b]` with kernel `G_eq(t - s)`.
fn splits<H: OneMaximum + ?Sized>(prony: &Prony, h: &H, a: f64, b: f64, t: f64) -> Vec<f64> {
    let mut v: Vec<f64> = h.kinks();
    v.push(h.peak_time());
    let per = (QUAD_MAX_PIECES / (prony.terms.len() + 1)).max(2);
    for p in &prony.terms {
        v.extend(layer_splits(a, t, p.tau, per));
    }
    v.retain(|&s| s > a && s < b);
    v
}

/// `int_0^upper G_eq(t-s) d/ds[w(d(s))] ds` by quadrature (no `16/3` factor; the paraboloid's
/// `w = sqrt(R) d^(3/2)`).
fn hereditary_phi<H: OneMaximum + ?Sized>(
    geometry: &Geometry,
    prony: &Prony,
    h: &H,
    upper: f64,
    t: f64,
) -> Result<(f64, u64)> {
    if upper <= 0.0 {
        return Ok((0.0, 0));
    }
    let scale = prony.glassy() * geometry.force_function(h.depth(h.peak_time()));
    let sp = splits(prony, h, 0.0, upper, t);
    let q = integrate(
        "Lee-Radok force integrand",
        |s| geometry.force_slope(h.depth(s)) * h.rate(s) * prony.eval(t - s),
        0.0,
        upper,
        &sp,
        QUAD_RTOL * scale,
    )?;
    Ok((q.value, q.evaluations))
}

/// `int_lo^t G_eq(t-s) d'(s) ds` and (when `deriv`) its `t` derivative at fixed `lo`,
/// `G_eq(0) d'(t) + int_lo^t G_eq'(t-s) d'(s) ds`.
fn hereditary_d<H: OneMaximum + ?Sized>(
    prony: &Prony,
    h: &H,
    lo: f64,
    t: f64,
    deriv: bool,
) -> Result<(f64, f64)> {
    let scale = prony.glassy() * h.depth(h.peak_time());
    let sp = splits(prony, h, lo, t, t);
    let q = integrate(
        "Ting restitution integrand",
        |s| prony.eval(t - s) * h.rate(s),
        lo,
        t,
        &sp,
        QUAD_RTOL * scale,
    )?;
    let mut dq = 0.0;
    if deriv {
        let slope = |u: f64| -> f64 {
            -prony
                .terms
                .iter()
                .map(|p| p.coefficient / p.tau * (-u / p.tau).exp())
                .sum::<f64>()
        };
        let dscale = (-prony.initial_slope()).max(1e-300) * h.depth(h.peak_time());
        let r = integrate(
            "Ting restitution derivative",
            |s| slope(t - s) * h.rate(s),
            lo,
            t,
            &sp,
            QUAD_RTOL * dscale,
        )?;
        dq = prony.glassy() * h.rate(t) + r.value;
    }
    Ok((q.value, dq))
}

/// Separation time `t_s`: root of `psi(t) = int_0^t G_eq(t-s) d'(s) ds` in `(t_m, end]`.
/// Elastic series (no terms) give `t_s = end` exactly when the history returns to zero there.
pub fn separation_time<H: OneMaximum + ?Sized>(prony: &Prony, radius: f64, h: &H) -> Result<f64> {
    check_inputs(prony, radius)?;
    separation_time_of(prony, h)
}

/// [`separation_time`] of any indenter: the separation does not depend on the shape.
fn separation_time_of<H: OneMaximum + ?Sized>(prony: &Prony, h: &H) -> Result<f64> {
    prony.validate()?;
    let (tm, end) = (h.peak_time(), h.end_time());
    if prony.is_elastic() {
        return Ok(end);
    }
    let (psi_end, _) = hereditary_d(prony, h, 0.0, end, false)?;
    let tol = 10.0 * QUAD_RTOL * prony.glassy() * h.depth(tm);
    if psi_end >= -tol {
        return Ok(end);
    }
    newton_bracketed(
        "separation time",
        |t| hereditary_d(prony, h, 0.0, t, true),
        tm,
        end,
        None,
        ROOT_RTOL * end,
    )
}

/// Ting's `t_1(t)` for `t_m < t < t_s` (root of `Phi`, bracketed by `[0, t_m]`).
pub fn ting_t1<H: OneMaximum + ?Sized>(
    prony: &Prony,
    h: &H,
    t: f64,
    guess: Option<f64>,
) -> Result<f64> {
    let tm = h.peak_time();
    newton_bracketed(
        "Ting t1",
        |t1| {
            let (phi, _) = hereditary_d(prony, h, t1, t, false)?;
            Ok((phi, -h.rate(t1) * prony.eval(t - t1)))
        },
        0.0,
        tm,
        guess,
        ROOT_RTOL * tm,
    )
}

/// Lee–Radok/Ting response of a rigid sphere of radius `radius` pressed along `history` into
/// the half-space with equivalent relaxation `prony`, at the given `times` (any order).
///
/// Accuracy: integrals to [`QUAD_RTOL`] of their natural scale (error estimates checked), roots
/// to [`ROOT_RTOL`] of the peak time; against the closed form for the triangle the force agrees to
/// better than `1e-10` of the peak force (test `theory_viscoelastic`).
pub fn response<H: OneMaximum + ?Sized>(
    prony: &Prony,
    radius: f64,
    history: &H,
    times: &[f64],
) -> Result<Vec<IndentSample>> {
    check_inputs(prony, radius)?;
    response_on(&Geometry::Paraboloid { radius }, prony, history, times)
}

/// [`response`] for any axisymmetric indenter `geometry` (SI, [`Shape::geometry_si`]): the
/// force integrand `w'(d) d'(s) G_eq(t - s)` with `w' = (3/2) a(d)` (docs/theory.md §11), the
/// contact radius `a(d(t_1))`; a flat punch has no Ting phase (its force is the compression
/// integral up to `t` until the separation).
///
/// [`Shape::geometry_si`]: crate::model::geometry::Shape::geometry_si
pub fn response_on<H: OneMaximum + ?Sized>(
    geometry: &Geometry,
    prony: &Prony,
    history: &H,
    times: &[f64],
) -> Result<Vec<IndentSample>> {
    prony.validate()?;
    let tm = history.peak_time();
    let ts = separation_time_of(prony, history)?;
    let pref = 16.0 / 3.0;
    let flat = geometry.is_flat();
    let mut out = Vec::with_capacity(times.len());
    let mut guess: Option<f64> = None;
    for &t in times {
        if !t.is_finite() {
            return Err(Error::NonFinite {
                what: "sample time",
                value: t,
            });
        }
        let d = history.depth(t);
        if t <= 0.0 || t >= ts {
            out.push(IndentSample {
                t,
                d,
                a: 0.0,
                force: 0.0,
                t1: 0.0,
            });
            continue;
        }
        if t <= tm || flat {
            let (f, _) = hereditary_phi(geometry, prony, history, t, t)?;
            out.push(IndentSample {
                t,
                d,
                a: geometry.contact_radius(d),
                force: pref * f,
                t1: t,
            });
            continue;
        }
        let t1 = ting_t1(prony, history, t, guess)?;
        guess = Some(t1);
        let (f, _) = hereditary_phi(geometry, prony, history, t1, t)?;
        out.push(IndentSample {
            t,
            d,
            a: geometry.contact_radius(history.depth(t1)),
            force: pref * f,
            t1,
        });
    }
    Ok(out)
}

/// `A(a, b) = int_a^b G_eq(t - s) ds` (closed form for a Prony series), `a <= b <= t`.
fn prony_area(prony: &Prony, t: f64, a: f64, b: f64) -> f64 {
    prony.relaxed * (b - a)
        - prony
            .terms
            .iter()
            .map(|p| p.coefficient * p.tau * (-(t - b) / p.tau).exp() * (-(b - a) / p.tau).exp_m1())
            .sum::<f64>()
}

/// `int_0^{t1} G_eq(t - s) d/ds[(V s)^(3/2)] ds` in closed form (Dawson), `t1 <= t`.
fn triangle_force_integral(prony: &Prony, v: f64, t1: f64, t: f64) -> f64 {
    if t1 <= 0.0 {
        return 0.0;
    }
    let v32 = v.powf(1.5);
    prony.relaxed * v32 * t1.powf(1.5)
        + prony
            .terms
            .iter()
            .map(|p| {
                1.5 * p.coefficient
                    * v32
                    * p.tau.powf(1.5)
                    * x_minus_dawson((t1 / p.tau).sqrt())
                    * (-(t - t1) / p.tau).exp()
            })
            .sum::<f64>()
}

/// Closed-form Lee–Radok/Ting response for the triangle history `d = V t` (`t <= T`),
/// `d = V (2T - t)` (module docs), and its separation time. Independent of the quadrature path.
pub fn triangle_closed_form(
    prony: &Prony,
    radius: f64,
    rate: f64,
    peak_time: f64,
    times: &[f64],
) -> Result<(Vec<IndentSample>, f64)> {
    check_inputs(prony, radius)?;
    let h = Prescribed::triangle(rate, peak_time)?;
    let (v, tp) = (rate, peak_time);
    let end = 2.0 * tp;
    let g = |u: f64| prony.eval(u);
    // psi(t) = V [A(0,T) - A(T,t)], psi' = V [G(t) - 2 G(t-T)] < 0
    let ts = if prony.is_elastic() {
        end
    } else {
        let psi = |t: f64| v * (prony_area(prony, t, 0.0, tp) - prony_area(prony, t, tp, t));
        if psi(end) >= 0.0 {
            end
        } else {
            newton_bracketed(
                "triangle separation time",
                |t| Ok((psi(t), v * (g(t) - 2.0 * g(t - tp)))),
                tp,
                end,
                None,
                ROOT_RTOL * end,
            )?
        }
    };
    let pref = 16.0 * radius.sqrt() / 3.0;
    let mut out = Vec::with_capacity(times.len());
    for &t in times {
        let d = h.depth(t);
        if t.is_nan() || t <= 0.0 || t >= ts {
            out.push(IndentSample {
                t,
                d,
                a: 0.0,
                force: 0.0,
                t1: 0.0,
            });
            continue;
        }
        let t1 = if t <= tp {
            t
        } else {
            // Phi(t1) = V [A(t1, T) - A(T, t)], dPhi/dt1 = -V G(t - t1)
            let rhs = prony_area(prony, t, tp, t);
            newton_bracketed(
                "triangle t1",
                |t1| Ok((v * (prony_area(prony, t, t1, tp) - rhs), -v * g(t - t1))),
                0.0,
                tp,
                Some((2.0 * tp - t).max(0.0)),
                ROOT_RTOL * tp,
            )?
        };
        out.push(IndentSample {
            t,
            d,
            a: (radius * v * t1).sqrt(),
            force: pref * triangle_force_integral(prony, v, t1, t),
            t1,
        });
    }
    Ok((out, ts))
}
