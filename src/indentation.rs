//! Prescribed indentation histories `d(t)` with one maximum, shared by the displacement-controlled
//! MDR and the Lee–Radok/Ting theory (which must agree force for force on them).
//!
//! Units: `d` in m, `t` in s, rates in m/s (or any consistent set, e.g. canonical units).

use crate::error::{check, Result};

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
}

impl Prescribed {
    /// Validated triangle history.
    pub fn triangle(rate: f64, peak_time: f64) -> Result<Self> {
        let rate = check("rate", rate, rate > 0.0, "0 < rate < inf (m/s)")?;
        let peak_time = check(
            "peak_time",
            peak_time,
            peak_time > 0.0,
            "0 < peak_time < inf (s)",
        )?;
        Ok(Prescribed::Triangle { rate, peak_time })
    }
    /// Validated half-sine history.
    pub fn half_sine(rate: f64, peak_time: f64) -> Result<Self> {
        let rate = check("rate", rate, rate > 0.0, "0 < rate < inf (m/s)")?;
        let peak_time = check(
            "peak_time",
            peak_time,
            peak_time > 0.0,
            "0 < peak_time < inf (s)",
        )?;
        Ok(Prescribed::HalfSine { rate, peak_time })
    }
    /// Indentation depth `d(t)`; `0` outside `[0, end_time]`.
    pub fn depth(&self, t: f64) -> f64 {
        if !(t > 0.0) || t >= self.end_time() {
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
        }
    }
    /// Time of the maximum indentation (s).
    pub fn peak_time(&self) -> f64 {
        match *self {
            Prescribed::Triangle { peak_time, .. } | Prescribed::HalfSine { peak_time, .. } => {
                peak_time
            }
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
            Prescribed::HalfSine { .. } => Vec::new(),
        }
    }
}
