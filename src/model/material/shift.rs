//! Temperature: the shift laws of a thermorheologically simple material (docs/theory.md §13).
//! At temperature `T` every relaxation time of shear and bulk is `a_T` times its value at the
//! reference temperature; `log10 a_T > 0` below it (slower, stiffer). A scene gives the law as
//! `[material.shift]`, `mdr-impact prony` fits it to DMA isotherms (`crate::apps::dma`).

use serde::{Deserialize, Serialize};

use crate::error::{check, Error, Result};
use crate::model::material::{BulkInput, BulkProny, BulkRheology, Material, ShearProny};

/// Molar gas constant `R` (J/(mol K)), CODATA 2018 (exact).
pub const GAS_CONSTANT: f64 = 8.314_462_618;

/// Absolute zero in °C: `T_K = T_C + 273.15`.
pub const ZERO_CELSIUS_K: f64 = 273.15;

/// A shift law `log10 a_T(T)`: temperatures in °C, `a_T` multiplies every relaxation time.
///
/// Serialised (TOML, serde) in exactly the shape of a scene's `[material.shift]` table:
///
/// ```toml
/// [material.shift]
/// wlf = { c1 = 8.86, c2 = 101.6, t_ref = 25.0 }           # °C
/// # arrhenius = { activation_energy = 2.0e5, t_ref = 25.0 }  # J/mol, °C
/// ```
///
/// Deserialising validates (unknown keys, non-finite or out-of-range constants are refused).
///
/// ```
/// # use mdr_impact::model::material::shift::ShiftLaw;
/// let law: ShiftLaw = toml::from_str("wlf = { c1 = 8.86, c2 = 101.6, t_ref = 25.0 }").unwrap();
/// // WLF at T = t_ref + 10: -8.86 * 10 / (101.6 + 10)
/// assert!((law.log10_a(35.0).unwrap() + 0.793_907).abs() < 1e-6);
/// assert!(law.log10_a(25.0 - 101.6).is_err()); // at or below t_ref - c2: refused
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase", try_from = "RawShiftLaw")]
pub enum ShiftLaw {
    /// Williams–Landel–Ferry (1955): `log10 a_T = -c1 (T - t_ref) / (c2 + T - t_ref)`, valid
    /// for `T > t_ref - c2`; `c1 > 0` (dimensionless), `c2 > 0` (K), `t_ref` (°C).
    Wlf {
        /// `C1` (dimensionless), `0 < c1 < inf`.
        c1: f64,
        /// `C2` (K), `0 < c2 < inf`.
        c2: f64,
        /// Reference temperature (°C).
        t_ref: f64,
    },
    /// Arrhenius: `log10 a_T = E_a / (R ln 10) (1/T_K - 1/T_ref,K)` with absolute temperatures.
    Arrhenius {
        /// Activation energy `E_a` (J/mol), `0 < E_a < inf`.
        activation_energy: f64,
        /// Reference temperature (°C).
        t_ref: f64,
    },
}

/// The unvalidated serde form of [`ShiftLaw`]: both keys optional, so that a table with
/// neither or both gets a message that names them (not serde's count of enum elements).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawShiftLaw {
    wlf: Option<RawWlf>,
    arrhenius: Option<RawArrhenius>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawWlf {
    c1: f64,
    c2: f64,
    t_ref: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawArrhenius {
    activation_energy: f64,
    t_ref: f64,
}

/// A scene's `[material.shift]` table: the law and, optionally, the temperatures it was
/// calibrated on, `calibrated = [t_min, t_max]` (°C; `mdr-impact prony` writes the lowest and
/// highest temperature of its data's rows). A temperature outside that range is still answered, with a warning that the law
/// is extrapolated there ([`ShiftTable::warning`]).
///
/// ```
/// # use mdr_impact::model::material::shift::ShiftTable;
/// let t: ShiftTable = toml::from_str(
///     "wlf = { c1 = 8.86, c2 = 101.6, t_ref = 25.0 }\ncalibrated = [-30.0, 80.0]",
/// )
/// .unwrap();
/// assert!(t.warning(20.0).is_none());
/// assert!(t.warning(120.0).unwrap().contains("-30 to 80 °C"));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(try_from = "RawShiftTable")]
pub struct ShiftTable {
    /// The shift law.
    pub law: ShiftLaw,
    /// The lowest and highest temperature the law was calibrated on (°C), when known.
    pub calibrated: Option<(f64, f64)>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawShiftTable {
    wlf: Option<RawWlf>,
    arrhenius: Option<RawArrhenius>,
    calibrated: Option<Vec<f64>>,
}

impl TryFrom<RawShiftTable> for ShiftTable {
    type Error = Error;
    fn try_from(raw: RawShiftTable) -> Result<Self> {
        let law = ShiftLaw::try_from(RawShiftLaw {
            wlf: raw.wlf,
            arrhenius: raw.arrhenius,
        })?;
        let calibrated = match raw.calibrated.as_deref() {
            None => None,
            Some(&[lo, hi]) => Some(ShiftTable::check_range(&law, lo, hi)?),
            Some(v) => {
                return Err(Error::OutOfRange {
                    field: "calibrated: number of temperatures",
                    value: v.len() as f64,
                    allowed: "two, [t_min, t_max] (°C)",
                })
            }
        };
        Ok(ShiftTable { law, calibrated })
    }
}

impl ShiftTable {
    /// `law` calibrated on `lo ..= hi` (°C): both finite, `lo <= hi`, and the law defined at
    /// `lo` (above absolute zero; WLF above `t_ref - c2`).
    pub fn new(law: ShiftLaw, calibrated: Option<(f64, f64)>) -> Result<Self> {
        let calibrated = match calibrated {
            Some((lo, hi)) => Some(Self::check_range(&law, lo, hi)?),
            None => None,
        };
        Ok(ShiftTable { law, calibrated })
    }

    fn check_range(law: &ShiftLaw, lo: f64, hi: f64) -> Result<(f64, f64)> {
        check(
            "calibrated[1]",
            hi,
            hi.is_finite(),
            "a finite temperature (°C)",
        )?;
        let allowed = "t_min <= t_max, where the law is defined (above -273.15 °C; WLF above \
                       t_ref - c2)";
        check(
            "calibrated[0]",
            lo,
            lo <= hi && law.log10_a(lo).is_ok(),
            allowed,
        )?;
        Ok((lo, hi))
    }

    /// The warning of a temperature `t` (°C) outside the calibrated range, `None` inside it or
    /// without a range.
    pub fn warning(&self, t: f64) -> Option<String> {
        let (lo, hi) = self.calibrated?;
        (t < lo || t > hi).then(|| {
            format!(
                "temperature {} °C lies outside the {} to {} °C the {} shift law was \
                 calibrated on (calibrated = [{lo:?}, {hi:?}]): a_T is extrapolated there, and \
                 with it every relaxation time",
                celsius_text(t),
                celsius_text(lo),
                celsius_text(hi),
                match self.law {
                    ShiftLaw::Wlf { .. } => "WLF",
                    ShiftLaw::Arrhenius { .. } => "Arrhenius",
                }
            )
        })
    }
}

impl TryFrom<RawShiftLaw> for ShiftLaw {
    type Error = Error;
    fn try_from(raw: RawShiftLaw) -> Result<Self> {
        match (raw.wlf, raw.arrhenius) {
            (Some(RawWlf { c1, c2, t_ref }), None) => ShiftLaw::wlf(c1, c2, t_ref),
            (
                None,
                Some(RawArrhenius {
                    activation_energy,
                    t_ref,
                }),
            ) => ShiftLaw::arrhenius(activation_energy, t_ref),
            (w, _) => Err(Error::Parse {
                what: "shift table",
                input: if w.is_some() {
                    "wlf and arrhenius"
                } else {
                    "neither wlf nor arrhenius"
                }
                .into(),
                expected: "exactly one of wlf = { c1, c2, t_ref } or arrhenius = { \
                           activation_energy, t_ref }"
                    .into(),
            }),
        }
    }
}

impl ShiftLaw {
    /// Validated WLF law: `0 < c1 < inf`, `0 < c2 < inf` (K), `t_ref` finite and above
    /// absolute zero (°C).
    pub fn wlf(c1: f64, c2: f64, t_ref: f64) -> Result<Self> {
        check("c1", c1, c1 > 0.0, "0 < c1 < inf")?;
        check("c2", c2, c2 > 0.0, "0 < c2 < inf (K)")?;
        check_t_ref(t_ref)?;
        Ok(ShiftLaw::Wlf { c1, c2, t_ref })
    }

    /// Validated Arrhenius law: `0 < activation_energy < inf` (J/mol), `t_ref` finite and above
    /// absolute zero (°C).
    pub fn arrhenius(activation_energy: f64, t_ref: f64) -> Result<Self> {
        check(
            "activation_energy",
            activation_energy,
            activation_energy > 0.0,
            "0 < activation_energy < inf (J/mol)",
        )?;
        check_t_ref(t_ref)?;
        Ok(ShiftLaw::Arrhenius {
            activation_energy,
            t_ref,
        })
    }

    /// The reference temperature (°C), where `a_T = 1`.
    pub fn t_ref(&self) -> f64 {
        match *self {
            ShiftLaw::Wlf { t_ref, .. } | ShiftLaw::Arrhenius { t_ref, .. } => t_ref,
        }
    }

    /// `log10 a_T` at `t` (°C). WLF refuses `t <= t_ref - c2` (its singularity and beyond),
    /// Arrhenius `t <= -273.15 °C`, both with [`Error::OutOfRange`] on the field `temperature`.
    pub fn log10_a(&self, t: f64) -> Result<f64> {
        match *self {
            ShiftLaw::Wlf { c1, c2, t_ref } => {
                let d = check(
                    "temperature",
                    t,
                    t - t_ref + c2 > 0.0,
                    "T > t_ref - c2 (°C; WLF is singular at t_ref - c2)",
                )? - t_ref;
                // -c1 d / (c2 + d), with the quotient first: c1 d overflows for d near 1e308
                Ok(-c1 * (d / (c2 + d)))
            }
            ShiftLaw::Arrhenius {
                activation_energy,
                t_ref,
            } => {
                let tk = check("temperature", t, t > -ZERO_CELSIUS_K, "T > -273.15 °C")?
                    + ZERO_CELSIUS_K;
                let rk = t_ref + ZERO_CELSIUS_K;
                Ok(activation_energy / (GAS_CONSTANT * std::f64::consts::LN_10)
                    * (1.0 / tk - 1.0 / rk))
            }
        }
    }

    /// The lowest temperature (°C) at which `log10 a_T <= max_log10` (`max_log10 > 0`): both
    /// laws grow without bound only towards low temperatures (WLF towards `t_ref - c2`,
    /// Arrhenius towards absolute zero), and stay finite above.
    pub fn min_temperature(&self, max_log10: f64) -> f64 {
        match *self {
            // -c1 d / (c2 + d) = m  <=>  d = -m c2 / (c1 + m)
            ShiftLaw::Wlf { c1, c2, t_ref } => t_ref - max_log10 * c2 / (c1 + max_log10),
            ShiftLaw::Arrhenius {
                activation_energy,
                t_ref,
            } => {
                let rk = t_ref + ZERO_CELSIUS_K;
                let inv = 1.0 / rk
                    + max_log10 * GAS_CONSTANT * std::f64::consts::LN_10 / activation_energy;
                1.0 / inv - ZERO_CELSIUS_K
            }
        }
    }

    /// The highest temperature (°C) at which `log10 a_T >= -min_log10` (`min_log10 > 0`), or
    /// `None` when the law never falls that low (WLF tends to `-c1` and Arrhenius to
    /// `-E / (R ln 10 T_ref)` at high temperature).
    pub fn max_temperature(&self, min_log10: f64) -> Option<f64> {
        match *self {
            // -c1 d / (c2 + d) = -m  <=>  d = m c2 / (c1 - m)
            ShiftLaw::Wlf { c1, c2, t_ref } => {
                (c1 > min_log10).then(|| t_ref + min_log10 * c2 / (c1 - min_log10))
            }
            ShiftLaw::Arrhenius {
                activation_energy,
                t_ref,
            } => {
                let rk = t_ref + ZERO_CELSIUS_K;
                let inv = 1.0 / rk
                    - min_log10 * GAS_CONSTANT * std::f64::consts::LN_10 / activation_energy;
                (inv > 0.0).then(|| 1.0 / inv - ZERO_CELSIUS_K)
            }
        }
    }

    /// The law's name in the scene table and the JSON output: `wlf` or `arrhenius`.
    pub fn kind(&self) -> &'static str {
        match self {
            ShiftLaw::Wlf { .. } => "wlf",
            ShiftLaw::Arrhenius { .. } => "arrhenius",
        }
    }

    /// The law as the JSON object of `prony --json`: `{"kind": "wlf", "c1", "c2", "t_ref"}` or
    /// `{"kind": "arrhenius", "activation_energy", "t_ref"}`.
    pub fn json(&self) -> serde_json::Value {
        match *self {
            ShiftLaw::Wlf { c1, c2, t_ref } => {
                serde_json::json!({"kind": "wlf", "c1": c1, "c2": c2, "t_ref": t_ref})
            }
            ShiftLaw::Arrhenius {
                activation_energy,
                t_ref,
            } => serde_json::json!({
                "kind": "arrhenius",
                "activation_energy": activation_energy,
                "t_ref": t_ref,
            }),
        }
    }

    /// The body of a `[material.shift]` table: one line, `wlf = { ... }` or
    /// `arrhenius = { ... }`, numbers in shortest round-trip form.
    pub fn toml_line(&self) -> String {
        match *self {
            ShiftLaw::Wlf { c1, c2, t_ref } => {
                format!("wlf = {{ c1 = {c1:?}, c2 = {c2:?}, t_ref = {t_ref:?} }}")
            }
            ShiftLaw::Arrhenius {
                activation_energy,
                t_ref,
            } => format!(
                "arrhenius = {{ activation_energy = {activation_energy:?}, t_ref = {t_ref:?} }}"
            ),
        }
    }
}

/// A temperature (°C) as messages write it: as given in the usual range (`100`, `-20.5`),
/// in e-notation far outside it (`1e308`, not 309 digits).
pub fn celsius_text(t: f64) -> String {
    if t == 0.0 || (1e-4..1e6).contains(&t.abs()) {
        format!("{t}")
    } else {
        format!("{t:e}")
    }
}

fn check_t_ref(t_ref: f64) -> Result<f64> {
    check(
        "t_ref",
        t_ref,
        t_ref > -ZERO_CELSIUS_K,
        "-273.15 < t_ref < inf (°C)",
    )
}

impl Material {
    /// This material at the shift factor `a_t` (`0 < a_t < inf`): every relaxation time of
    /// shear and bulk multiplied by `a_t`, every modulus unchanged (thermorheological
    /// simplicity). `a_t = 1` gives the material back unchanged.
    pub fn time_shifted(&self, a_t: f64) -> Result<Material> {
        check("a_T", a_t, a_t > 0.0, "0 < a_T < inf")?;
        if a_t == 1.0 {
            return Ok(self.clone());
        }
        let scale = |terms: &[(f64, f64)]| -> Vec<(f64, f64)> {
            terms.iter().map(|&(g, tau)| (g, tau * a_t)).collect()
        };
        let shear = ShearProny::new(self.shear().g_inf(), &scale(self.shear().terms()))?;
        let bulk = match self.bulk() {
            BulkRheology::Incompressible => BulkInput::Incompressible,
            BulkRheology::Elastic(k) => BulkInput::Elastic(*k),
            BulkRheology::Prony(p) => {
                BulkInput::Prony(BulkProny::new(p.k_inf(), &scale(p.terms()))?)
            }
        };
        let shifted = Material::general(shear, bulk)?;
        match self.density() {
            Some(rho) => shifted.with_density(rho),
            None => Ok(shifted),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `min_temperature` inverts `log10_a` for both laws.
    #[test]
    fn min_temperature_is_where_the_shift_reaches_its_bound() {
        for law in [
            ShiftLaw::wlf(8.86, 101.6, 20.0).unwrap(),
            ShiftLaw::arrhenius(2.0e5, 20.0).unwrap(),
        ] {
            for m in [1.0, 30.0, 300.0] {
                let t = law.min_temperature(m);
                let back = law.log10_a(t).unwrap();
                assert!((back - m).abs() < 1e-9 * m, "{law:?} {m} {t} {back}");
                assert!(law.log10_a(t + 1e-6).unwrap() < m);
            }
        }
    }

    /// `max_temperature` inverts `log10_a` on the hot side, and is `None` where the law never
    /// falls that low.
    #[test]
    fn max_temperature_is_where_the_shift_reaches_its_lower_bound() {
        for law in [
            ShiftLaw::wlf(400.0, 101.6, 20.0).unwrap(),
            ShiftLaw::arrhenius(2.0e6, 20.0).unwrap(),
        ] {
            for m in [1.0, 30.0, 300.0] {
                let t = law.max_temperature(m).unwrap();
                let back = law.log10_a(t).unwrap();
                assert!((back + m).abs() < 1e-9 * m, "{law:?} {m} {t} {back}");
                assert!(law.log10_a(t - 1e-6).unwrap() > -m);
            }
        }
        assert_eq!(
            ShiftLaw::wlf(8.86, 101.6, 20.0)
                .unwrap()
                .max_temperature(8.86),
            None
        );
        assert_eq!(
            ShiftLaw::arrhenius(2.0e5, 20.0)
                .unwrap()
                .max_temperature(300.0),
            None
        );
    }

    #[test]
    fn time_shift_scales_every_time_and_no_modulus() {
        let shear = ShearProny::new(1.0e6, &[(5.0e6, 1.0e-5), (2.0e6, 1.0e-3)]).unwrap();
        let bulk = BulkInput::Prony(BulkProny::new(1.0e9, &[(5.0e8, 1.0e-4)]).unwrap());
        let m = Material::general(shear, bulk).unwrap();
        let a = 10f64.powf(1.7);
        let shifted = m.time_shifted(a).unwrap();
        // the hand-shifted series, to the last bit
        let hand = Material::general(
            ShearProny::new(1.0e6, &[(5.0e6, 1.0e-5 * a), (2.0e6, 1.0e-3 * a)]).unwrap(),
            BulkInput::Prony(BulkProny::new(1.0e9, &[(5.0e8, 1.0e-4 * a)]).unwrap()),
        )
        .unwrap();
        assert_eq!(shifted.shear().terms(), hand.shear().terms());
        let g0 = m.equivalent_relaxation().unwrap();
        let g1 = shifted.equivalent_relaxation().unwrap();
        for t in [0.0, 1e-6, 1e-4, 1e-2] {
            let (x, y) = (g0.eval(t), g1.eval(a * t));
            assert!((x - y).abs() <= 1e-12 * x, "t = {t}: {x} vs {y}");
        }
        assert_eq!(
            m.time_shifted(1.0).unwrap().shear().terms(),
            m.shear().terms()
        );
        assert!(m.time_shifted(0.0).is_err());
        assert!(m.time_shifted(f64::NAN).is_err());
    }
}
