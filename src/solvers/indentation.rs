//! Prescribed indentation histories `d(t)` with one maximum, shared by the displacement-controlled
//! MDR and the Lee–Radok/Ting theory (which must agree force for force on them).
//!
//! Units: `d` in m, `t` in s, rates in m/s (or any consistent set, e.g. canonical units).

use crate::error::{check, Result};
use crate::model::hertz::HertzImpact;

/// An indentation history with a single maximum at [`Prescribed::peak_time`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Prescribed {
    /// Constant-rate load and unload: `d = V t` for `t <= T`, then `d = V (2T - t)`; ends at `2T`.
    Triangle {
        /// Rate `V` (m/s), `> 0`.
        rate: f64,
        /// Time of the peak `T` (s), `> 0`.
        peak_time: f64,
    },
    /// Half sine: `d = V T sin(pi t / (2T))` for `0 <= t <= 2T` (initial rate `V pi / 2`).
    HalfSine {
        /// Rate scale `V` (m/s), `> 0`.
        rate: f64,
        /// Time of the peak `T` (s), `> 0`.
        peak_time: f64,
    },
    /// The exact elastic (Hertz) impact trajectory with impact velocity `V` and peak time `T`
    /// (maximum depth `V T / I`, `I = 1.4716...`; see [`crate::model::hertz`]); ends at `2T`.
    /// Smooth inside `(0, 2T)` with `d ~ V t` at the start.
    HertzImpact {
        /// Impact velocity `V` (m/s), `> 0`.
        rate: f64,
        /// Time of the peak `T` (s), `> 0`.
        peak_time: f64,
    },
}

/// Validate the rate (m/s) and the peak time (s) shared by every history.
fn check_rate_and_peak(rate: f64, peak_time: f64) -> Result<(f64, f64)> {
    Ok((
        check("rate", rate, rate > 0.0, "0 < rate < inf (m/s)")?,
        check(
            "peak_time",
            peak_time,
            peak_time > 0.0,
            "0 < peak_time < inf (s)",
        )?,
    ))
}

impl Prescribed {
    /// Validated triangle history.
    pub fn triangle(rate: f64, peak_time: f64) -> Result<Self> {
        let (rate, peak_time) = check_rate_and_peak(rate, peak_time)?;
        Ok(Prescribed::Triangle { rate, peak_time })
    }
    /// Validated half-sine history.
    pub fn half_sine(rate: f64, peak_time: f64) -> Result<Self> {
        let (rate, peak_time) = check_rate_and_peak(rate, peak_time)?;
        Ok(Prescribed::HalfSine { rate, peak_time })
    }
    /// Validated Hertz impact trajectory with impact velocity `rate` and peak time `peak_time`.
    pub fn hertz_impact(rate: f64, peak_time: f64) -> Result<Self> {
        let (rate, peak_time) = check_rate_and_peak(rate, peak_time)?;
        hertz_trajectory(rate, peak_time)?;
        Ok(Prescribed::HertzImpact { rate, peak_time })
    }
    /// Indentation depth `d(t)`; `0` outside `[0, end_time]`.
    pub fn depth(&self, t: f64) -> f64 {
        if t.is_nan() || t <= 0.0 || t >= self.end_time() {
            return 0.0;
        }
        match *self {
            Prescribed::Triangle { rate, peak_time } => {
                if t <= peak_time {
                    rate * t
                } else {
                    rate * (2.0 * peak_time - t)
                }
            }
            Prescribed::HalfSine { rate, peak_time } => {
                rate * peak_time * (std::f64::consts::FRAC_PI_2 * t / peak_time).sin()
            }
            // The trajectory's bracketed Newton cannot fail for a validated variant; a NaN here
            // would be caught by the checked quadrature of the theory module.
            Prescribed::HertzImpact { rate, peak_time } => hertz_trajectory(rate, peak_time)
                .and_then(|h| h.state(t))
                .map_or(f64::NAN, |s| s.0),
        }
    }
    /// Indentation rate `d'(t)` (right derivative at kinks); `0` outside `[0, end_time)`.
    pub fn rate(&self, t: f64) -> f64 {
        if t < 0.0 || t >= self.end_time() {
            return 0.0;
        }
        match *self {
            Prescribed::Triangle { rate, peak_time } => {
                if t < peak_time {
                    rate
                } else {
                    -rate
                }
            }
            Prescribed::HalfSine { rate, peak_time } => {
                rate * std::f64::consts::FRAC_PI_2
                    * (std::f64::consts::FRAC_PI_2 * t / peak_time).cos()
            }
            Prescribed::HertzImpact { rate, peak_time } => {
                if t == 0.0 {
                    return rate;
                }
                hertz_trajectory(rate, peak_time)
                    .and_then(|h| h.state(t))
                    .map_or(f64::NAN, |s| s.1)
            }
        }
    }
    /// Time of the maximum indentation (s).
    pub fn peak_time(&self) -> f64 {
        match *self {
            Prescribed::Triangle { peak_time, .. }
            | Prescribed::HalfSine { peak_time, .. }
            | Prescribed::HertzImpact { peak_time, .. } => peak_time,
        }
    }
    /// Maximum indentation (m).
    pub fn peak_depth(&self) -> f64 {
        self.depth(self.peak_time())
    }
    /// Time at which the prescribed `d` returns to zero (s).
    pub fn end_time(&self) -> f64 {
        2.0 * self.peak_time()
    }
    /// Times in `(0, end_time)` where `d'` is not smooth (quadrature splits there).
    pub fn kinks(&self) -> Vec<f64> {
        match *self {
            Prescribed::Triangle { peak_time, .. } => vec![peak_time],
            Prescribed::HalfSine { .. } | Prescribed::HertzImpact { .. } => Vec::new(),
        }
    }
}

/// The Hertz impact (unit mass and radius) whose trajectory has impact velocity `rate` and peak
/// time `peak_time`: `d_max = V T / I`, `k = 5 V^2 / (4 d_max^(5/2))`, `E* = 3 k / 4`.
fn hertz_trajectory(rate: f64, peak_time: f64) -> Result<HertzImpact> {
    let d_max = rate * peak_time / crate::model::hertz::HERTZ_I;
    let k = 5.0 * rate * rate / (4.0 * d_max.powf(2.5));
    HertzImpact::new(1.0, 1.0, rate, 0.75 * k)
}
