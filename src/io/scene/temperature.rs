//! Temperature in scenes: the shift of a material to `[impact] temperature` by its
//! `[material.shift]` law, its bounds and warnings (docs/theory.md §13). Shared by the scene file
//! and the Python binding.

use super::scene_error;
use crate::error::{Error, Result};
use crate::model::material::shift::{ShiftLaw, ShiftTable};
use crate::model::material::Material;

/// The scene's temperature and the shift factors applied so far.
pub(super) struct Temperature<'a> {
    pub(super) celsius: Option<f64>,
    pub(super) shifts: &'a mut Vec<(String, f64)>,
    pub(super) warnings: &'a mut Vec<String>,
}

/// Largest `log10 a_T` a temperature may give: relaxation times of a material stretched by more
/// leave the range of a double (a shift of 1e300 is far past any glass transition anyway).
pub const MAX_LOG10_SHIFT: f64 = 300.0;

/// `material` at `temperature` (°C; the law's `t_ref` when `None`) by its shift `law`: every
/// relaxation time times `a_T`, with `log10 a_T`; errors placed at `table`. The one path of the
/// scene file and the Python binding.
pub fn shifted_material(
    material: &Material,
    law: &ShiftLaw,
    temperature: Option<f64>,
    table: &str,
) -> Result<(Material, f64)> {
    let t = temperature.unwrap_or(law.t_ref());
    let tt = crate::model::material::shift::celsius_text(t);
    let log10_a = law
        .log10_a(t)
        .map_err(|e| e.at(format!("{table} shift at [impact] temperature")))?;
    if log10_a > MAX_LOG10_SHIFT {
        return Err(scene_error(format!(
            "{table} shift: [impact] temperature = {tt} °C gives log10 a_T = {log10_a:.4e}, \
             relaxation times beyond a double's range; allowed: temperature > {:.4} °C for this \
             law (log10 a_T < {MAX_LOG10_SHIFT})",
            law.min_temperature(MAX_LOG10_SHIFT)
        )));
    }
    if log10_a < -MAX_LOG10_SHIFT {
        let bound = law
            .max_temperature(MAX_LOG10_SHIFT)
            .map_or_else(|| "none".to_string(), |t| format!("{t:.4}"));
        return Err(scene_error(format!(
            "{table} shift: [impact] temperature = {tt} °C gives log10 a_T = {log10_a:.4e}, \
             relaxation times below a double's range; allowed: temperature < {bound} °C for \
             this law (log10 a_T > -{MAX_LOG10_SHIFT})"
        )));
    }
    let shifted = material
        .time_shifted(10f64.powf(log10_a))
        .map_err(|e| e.at(format!("{table} shift")))?;
    Ok((shifted, log10_a))
}

/// The warning of a material at `temperature` (°C; the law's `t_ref` when `None`) outside the
/// range its shift law was calibrated on ([`ShiftTable::warning`]), placed at `table`. The one
/// path of the scene file and the Python binding.
pub fn shift_warning(shift: &ShiftTable, temperature: Option<f64>, table: &str) -> Option<String> {
    let t = temperature.unwrap_or(shift.law.t_ref());
    shift.warning(t).map(|w| format!("{table} shift: {w}"))
}

/// The error of a temperature given without any shift law (scene and Python binding).
pub fn temperature_without_shift(t: f64) -> Error {
    scene_error(format!(
        "[impact] temperature = {t}: no material has a [material.shift] law \
         (wlf = {{ c1, c2, t_ref }} or arrhenius = {{ activation_energy, t_ref }}), \
         so its relaxation times at another temperature are unknown"
    ))
}
