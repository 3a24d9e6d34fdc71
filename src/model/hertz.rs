//! Hertz: closed forms of the elastic impact of a rigid sphere (docs/theory.md §6).
//!
//! With the effective modulus `E*` ([`crate::StandardSolid::effective_modulus`]):
//!
//! ```text
//! k = (4/3) E* sqrt(R),   F = k d^(3/2),   d_max = (5 m v0^2 / (4 k))^(2/5)
//! t_contact = 2 I d_max / v0,   I = (2/5) B(2/5, 1/2) = 1.4716375921623523...
//! ```
//!
//! Energy conservation gives `d'^2 = v0^2 (1 - x)`, `x = (d/d_max)^(5/2)`, hence the exact
//! loading trajectory
//!
//! ```text
//! t(d) = (d / v0) 2F1(2/5, 1/2; 7/5; x)                                  (x <= 1/2)
//!      = t_m - (4/5)(d_max/v0) x^(2/5) sqrt(1-x) 2F1(1, 9/10; 3/2; 1-x)  (x >= 1/2)
//! ```
//!
//! (the second line is the `x -> 1 - x` connection formula, with `Gamma` ratios `I` and
//! `-4/5`), symmetric about `t_m = I d_max / v0` on unloading. It is inverted with a safeguarded
//! Newton iteration ([`crate::math::roots::newton_bracketed`]): in `u = d/d_max` on the early branch,
//! in `s = |d'|/v0` near the peak (where `dt/ds` is bounded).

use crate::error::{check, Result};
use crate::math::roots::newton_bracketed;
use crate::math::special::hyp2f1_series;
use crate::model::impact::{History, Impact, Method, Outcome, Work};

/// `I = int_0^1 (1 - x^(5/2))^(-1/2) dx = (2/5) B(2/5, 1/2)`: Hertz contact time is
/// `2 I d_max / v0` (docs/theory.md §6). Value from mpmath at 30 digits.
pub const HERTZ_I: f64 = 1.471_637_592_162_352_3;

/// An elastic (Hertz) impact with mass `m`, sphere radius `R`, velocity `v0` and effective
/// modulus `E*`, in any consistent units (SI or canonical `m = R = v0 = 1`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzImpact {
    mass: f64,
    radius: f64,
    velocity: f64,
    e_star: f64,
}

/// Value of `u = d/d_max` where the early branch `x = u^(5/2) <= 1/2` ends: `0.5^(2/5)`.
const U_SWITCH: f64 = 0.757_858_283_255_198_9;
/// Brackets extend into the overlap `0.45 <= x <= 0.55` where both branches are valid, so that
/// rounding at the switch never loses the sign change: `0.55^(2/5)`.
const U_OVERLAP: f64 = 0.787_308_745_762_333_7;

impl HertzImpact {
    /// Validated Hertz impact (all arguments finite and `> 0`).
    pub fn new(mass: f64, radius: f64, velocity: f64, e_star: f64) -> Result<Self> {
        Ok(Self {
            mass: check("mass", mass, mass > 0.0, "0 < mass < inf")?,
            radius: check("radius", radius, radius > 0.0, "0 < radius < inf")?,
            velocity: check("velocity", velocity, velocity > 0.0, "0 < velocity < inf")?,
            e_star: check("e_star", e_star, e_star > 0.0, "0 < e_star < inf")?,
        })
    }

    /// Canonical units `m = R = v0 = 1` with effective modulus `e_star` (in units of `G_inf`).
    pub fn canonical(e_star: f64) -> Result<Self> {
        Self::new(1.0, 1.0, 1.0, e_star)
    }

    /// The elastic impact of `impact` with the *relaxed* modulus `G_inf` (SI), i.e. the limit
    /// `p3 -> 0` (or an elastic material).
    pub fn relaxed(impact: &Impact) -> Result<Self> {
        Self::new(
            impact.sphere().mass(),
            impact
                .shape()
                .tip_radius()
                .unwrap_or(impact.sphere().radius()),
            impact.velocity(),
            impact.relaxed_effective_modulus(),
        )
    }

    /// Stiffness `k = (4/3) E* sqrt(R)`.
    pub fn stiffness(&self) -> f64 {
        4.0 / 3.0 * self.e_star * self.radius.sqrt()
    }
    /// Maximum indentation `d_max = (5 m v0^2 / (4 k))^(2/5)`.
    pub fn max_indentation(&self) -> f64 {
        (5.0 * self.mass * self.velocity * self.velocity / (4.0 * self.stiffness())).powf(0.4)
    }
    /// Time of maximum indentation `t_m = I d_max / v0`.
    pub fn peak_time(&self) -> f64 {
        HERTZ_I * self.max_indentation() / self.velocity
    }
    /// Contact time `2 I d_max / v0 = 2.9432751843247047 d_max / v0`.
    pub fn contact_time(&self) -> f64 {
        2.0 * self.peak_time()
    }
    /// Maximum force `k d_max^(3/2)`.
    pub fn max_force(&self) -> f64 {
        self.stiffness() * self.max_indentation().powf(1.5)
    }
    /// Maximum contact radius `sqrt(R d_max)`.
    pub fn max_contact_radius(&self) -> f64 {
        (self.radius * self.max_indentation()).sqrt()
    }
    /// Force `k d^(3/2)` at depth `d >= 0`.
    pub fn force_at_depth(&self, d: f64) -> f64 {
        self.stiffness() * d.max(0.0).powf(1.5)
    }

    /// Loading time at which depth `d` in `[0, d_max]` is reached (exact trajectory).
    pub fn time_at_depth(&self, d: f64) -> Result<f64> {
        let dm = self.max_indentation();
        let d = check("d", d, (0.0..=dm).contains(&d), "0 <= d <= d_max")?;
        let u = d / dm;
        let scale = dm / self.velocity;
        if u <= U_SWITCH {
            Ok(scale * early_branch(u)?)
        } else {
            let s = (1.0 - u.powf(2.5)).max(0.0).sqrt();
            Ok(self.peak_time() - scale * late_branch(s)?)
        }
    }

    /// Depth and rate `(d, d')` at time `t` (zero outside `[0, t_contact]`).
    pub fn state(&self, t: f64) -> Result<(f64, f64)> {
        let tc = self.contact_time();
        if t.is_nan() || t <= 0.0 || t >= tc {
            return Ok((0.0, 0.0));
        }
        let tm = self.peak_time();
        let (tl, sign) = if t <= tm { (t, 1.0) } else { (tc - t, -1.0) };
        let dm = self.max_indentation();
        let scale = dm / self.velocity;
        let tau = tl / scale; // normalised loading time in [0, I]
        let t_switch = early_branch(U_SWITCH)?;
        if tau <= t_switch {
            let u = newton_bracketed(
                "Hertz trajectory (early branch)",
                |u| {
                    let x = u.powf(2.5);
                    Ok((early_branch(u)? - tau, 1.0 / (1.0 - x).sqrt()))
                },
                0.0,
                U_OVERLAP,
                Some(tau.min(U_SWITCH)),
                1e-17,
            )?;
            let v = (1.0 - u.powf(2.5)).sqrt();
            Ok((dm * u, sign * self.velocity * v))
        } else {
            let rem = (HERTZ_I - tau).max(0.0);
            if rem == 0.0 {
                return Ok((dm, 0.0));
            }
            let s_overlap = 0.55f64.sqrt();
            let s = newton_bracketed(
                "Hertz trajectory (late branch)",
                |s| Ok((late_branch(s)? - rem, 0.8 * (1.0 - s * s).powf(-0.6))),
                0.0,
                s_overlap,
                Some(1.25 * rem),
                1e-17,
            )?;
            Ok((dm * (1.0 - s * s).powf(0.4), sign * self.velocity * s))
        }
    }

    /// Depth `d(t)` (exact trajectory).
    pub fn depth(&self, t: f64) -> Result<f64> {
        Ok(self.state(t)?.0)
    }

    /// Force `k d(t)^(3/2)` at time `t`.
    pub fn force(&self, t: f64) -> Result<f64> {
        Ok(self.force_at_depth(self.depth(t)?))
    }

    /// The outcome in the units of the inputs: `cor = 1`, no dissipation, solver `"hertz"`.
    /// With `history = Some(n)`, `n >= 2` equally spaced samples over `[0, t_contact]`.
    pub fn outcome(&self, history: Option<usize>) -> Result<Outcome> {
        let hist = match history {
            None => None,
            Some(n) => {
                let n = n.max(2);
                let tc = self.contact_time();
                let mut h = History::default();
                for i in 0..n {
                    let t = tc * i as f64 / (n - 1) as f64;
                    let (d, v) = if i == n - 1 {
                        (0.0, -self.velocity)
                    } else if i == 0 {
                        (0.0, self.velocity)
                    } else {
                        self.state(t)?
                    };
                    h.push(t, d, v, self.force_at_depth(d), (self.radius * d).sqrt());
                }
                Some(h)
            }
        };
        Ok(Outcome {
            cor: 1.0,
            rebound_velocity: self.velocity,
            contact_time: self.contact_time(),
            max_indentation: self.max_indentation(),
            time_of_max_indentation: self.peak_time(),
            max_force: self.max_force(),
            max_contact_radius: self.max_contact_radius(),
            dissipated_energy: 0.0,
            cor_error_estimate: Some(0.0),
            history: hist,
            work: Work::default(),
            solver: Method::Hertz,
            fallback: None,
        })
    }
}

/// Hertz outcome (SI) of a validated impact with the relaxed modulus (exact for elastic
/// materials, the `p3 -> 0` limit otherwise).
pub fn hertz_outcome(impact: &Impact, history: Option<usize>) -> Result<Outcome> {
    HertzImpact::relaxed(impact)?.outcome(history)
}

/// `t v0 / d_max = u 2F1(2/5, 1/2; 7/5; u^(5/2))`, `u = d/d_max <= 0.55^(2/5)`.
fn early_branch(u: f64) -> Result<f64> {
    Ok(u * hyp2f1_series(0.4, 0.5, 1.4, u.powf(2.5).min(0.55))?)
}

/// `(t_m - t) v0 / d_max = (4/5) (1 - s^2)^(2/5) s 2F1(1, 9/10; 3/2; s^2)`, `s = |d'|/v0`,
/// `s^2 <= 0.55`.
fn late_branch(s: f64) -> Result<f64> {
    let y = (s * s).min(0.55);
    Ok(0.8 * (1.0 - y).powf(0.4) * s * hyp2f1_series(1.0, 0.9, 1.5, y)?)
}
