//! The material models `fit` identifies and their parameter coordinates.
//!
//! Every parameter is fitted in an unbounded coordinate: moduli and viscosities (`g_inf`, `g_1`,
//! `eta`, `g_i`) in their natural logarithm (positivity), the static Poisson ratio through the
//! logistic transform `nu = -1 + 1.5 / (1 + exp(-z))`, which keeps it in `(-1, 0.5)` (the
//! incompressible limit `nu = 0.5` is approached as `z -> inf`; fix `nu=0.5` to impose it).

use crate::error::{Error, Result};
use crate::model::impact::{Impact, Sphere};
use crate::model::material::{BulkInput, Material, ShearProny};

/// Largest number of Prony terms of `prony:N`.
pub const MAX_PRONY_TERMS: usize = 12;

/// The exponent of `G_inf` in the CoR-determined viscosity group `eta / G_inf^(3/5)` (paper
/// Eq. 11: `p3 = eta (v0 R / (m^2 G_inf^3))^(1/5)`).
pub const ETA_GROUP_EXPONENT: f64 = 0.6;

/// The box every fit stays in (values outside are clamped onto it, so the misfit is flat
/// beyond it and the solver never meets absurd materials): `g_inf` in Pa.
pub const BOX_G_INF: (f64, f64) = (1.0, 1.0e13);
/// The box of `p2 = g_inf / g_1` (for Prony each `g_inf / g_i`).
pub const BOX_P2: (f64, f64) = (1.0e-7, 1.0e4);
/// The box of `p3` at the data's mean velocity (standard solid).
pub const BOX_P3: (f64, f64) = (1.0e-4, 1.0e5);
/// The box of `nu`.
pub const BOX_NU: (f64, f64) = (-0.999, 0.4999);

/// Which material model is fitted.
#[derive(Debug, Clone, PartialEq)]
pub enum ModelKind {
    /// The standard solid: `g_inf`, `g_1`, `eta` (Pa, Pa, Pa s) and `nu` (or a fixed `k_0`).
    StandardSolid,
    /// A Prony series in shear `g_inf + sum_i g_i exp(-t / tau_i)` with `n` fixed log-spaced
    /// times `tau_i` and fitted moduli `g_1 .. g_n` (Pa), with `nu` (or a fixed `k_0`).
    Prony {
        /// Number of terms, `1 <= n <= 12`.
        n: usize,
    },
}

impl std::str::FromStr for ModelKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        if s == "standard-solid" {
            return Ok(ModelKind::StandardSolid);
        }
        let bad = || {
            Error::Unsupported(format!(
                "--model '{}': expected standard-solid or prony:N with 1 <= N <= \
                 {MAX_PRONY_TERMS}",
                crate::error::escape_text(s)
            ))
        };
        let n: usize = s
            .strip_prefix("prony:")
            .ok_or_else(bad)?
            .trim()
            .parse()
            .map_err(|_| bad())?;
        if !(1..=MAX_PRONY_TERMS).contains(&n) {
            return Err(bad());
        }
        Ok(ModelKind::Prony { n })
    }
}

/// What kind of quantity a parameter is, which decides its fit coordinate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamKind {
    /// A modulus (Pa) or viscosity (Pa s), `0 < x < inf`: coordinate `ln x`.
    Positive,
    /// The static Poisson ratio, `-1 < nu < 0.5`: coordinate `z`, `nu = -1 + 1.5 / (1 + e^-z)`.
    Poisson,
}

impl ParamKind {
    /// The fit coordinate of `value`.
    pub fn to_coord(self, value: f64) -> f64 {
        match self {
            ParamKind::Positive => value.ln(),
            ParamKind::Poisson => {
                let s = (value + 1.0) / 1.5;
                (s / (1.0 - s)).ln()
            }
        }
    }
    /// The value of the coordinate `c`.
    pub fn from_coord(self, c: f64) -> f64 {
        match self {
            ParamKind::Positive => c.exp(),
            ParamKind::Poisson => -1.0 + 1.5 / (1.0 + (-c).exp()),
        }
    }
}

/// One parameter of a model: its name (the `--fix` and JSON key), kind and unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    /// Name: `g_inf`, `g_1`, `eta`, `nu`, or for Prony `g_inf`, `g_1 .. g_N`, `nu`.
    pub name: String,
    /// Coordinate kind.
    pub kind: ParamKind,
    /// SI unit (`"Pa"`, `"Pa s"`, `"1"`).
    pub unit: &'static str,
}

/// A model with its parameters, fixed bulk and (for Prony) fixed relaxation times.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    /// The kind.
    pub kind: ModelKind,
    /// The parameters, in order (values are vectors aligned with this list).
    pub params: Vec<Param>,
    /// A fixed elastic bulk modulus `k_0` (Pa) instead of the parameter `nu`.
    pub k_0: Option<f64>,
    /// The fixed relaxation times `tau_1 .. tau_N` (s) of a Prony model (empty otherwise).
    pub taus: Vec<f64>,
}

impl Model {
    /// The model of `kind`; `k_0` replaces the parameter `nu` by a fixed bulk modulus (Pa,
    /// `0 < k_0 < inf`); `taus` are the Prony times (s), `N` of them for `prony:N`.
    pub fn new(kind: ModelKind, k_0: Option<f64>, taus: Vec<f64>) -> Result<Self> {
        let pos = |name: &str, unit| Param {
            name: name.to_string(),
            kind: ParamKind::Positive,
            unit,
        };
        let mut params = vec![pos("g_inf", "Pa")];
        match kind {
            ModelKind::StandardSolid => {
                params.push(pos("g_1", "Pa"));
                params.push(pos("eta", "Pa s"));
            }
            ModelKind::Prony { n } => {
                if taus.len() != n {
                    return Err(Error::Unsupported(format!(
                        "prony:{n} needs {n} relaxation times, got {}",
                        taus.len()
                    )));
                }
                for i in 1..=n {
                    params.push(pos(&format!("g_{i}"), "Pa"));
                }
            }
        }
        if let Some(k) = k_0 {
            crate::error::check("k_0", k, k > 0.0, "0 < k_0 < inf (Pa)")?;
        } else {
            params.push(Param {
                name: "nu".into(),
                kind: ParamKind::Poisson,
                unit: "1",
            });
        }
        Ok(Self {
            kind,
            params,
            k_0,
            taus,
        })
    }

    /// Index of the parameter called `name`.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.params.iter().position(|p| p.name == name)
    }

    /// The names a `--fix` accepts, for messages.
    pub fn names(&self) -> String {
        let mut n: Vec<&str> = self.params.iter().map(|p| p.name.as_str()).collect();
        if self.k_0.is_none() {
            n.push("k_0");
        }
        n.join(", ")
    }

    /// Whether a parameter value is allowed: moduli `0 < x < inf`, `-1 < nu <= 0.5`.
    pub fn check_value(&self, i: usize, value: f64) -> Result<f64> {
        match self.params[i].kind {
            ParamKind::Positive => crate::error::check(
                "--fix",
                value,
                value > 0.0,
                "0 < value < inf for a modulus (Pa) or viscosity (Pa s)",
            ),
            ParamKind::Poisson => crate::error::check(
                "--fix nu",
                value,
                value > -1.0 && value <= 0.5,
                "-1 < nu <= 0.5",
            ),
        }
    }

    /// `values` clamped into the box ([`BOX_G_INF`], [`BOX_P2`], [`BOX_P3`] with
    /// `p3 = p3_scale eta / g_inf^(3/5)`, [`BOX_NU`]).
    pub fn clamp(&self, values: &[f64], p3_scale: f64) -> Vec<f64> {
        let mut v = values.to_vec();
        let g_inf = v[0].clamp(BOX_G_INF.0, BOX_G_INF.1);
        v[0] = g_inf;
        let moduli = match self.kind {
            ModelKind::StandardSolid => 1..2,
            ModelKind::Prony { n } => 1..n + 1,
        };
        for x in &mut v[moduli] {
            *x = x.clamp(g_inf / BOX_P2.1, g_inf / BOX_P2.0);
        }
        if self.kind == ModelKind::StandardSolid {
            let c = g_inf.powf(ETA_GROUP_EXPONENT) / p3_scale;
            v[2] = v[2].clamp(BOX_P3.0 * c, BOX_P3.1 * c);
        }
        if let Some(i) = self.index("nu") {
            v[i] = v[i].clamp(BOX_NU.0, BOX_NU.1);
        }
        v
    }

    /// The impact of `sphere` at `v0` (m/s) on the material with parameter `values`.
    pub fn impact(&self, sphere: Sphere, v0: f64, values: &[f64]) -> Result<Impact> {
        let nu = self.index("nu").map(|i| values[i]);
        match self.kind {
            ModelKind::StandardSolid => {
                let (g_inf, g_1, eta) = (values[0], values[1], values[2]);
                let m = match (self.k_0, nu) {
                    (Some(k), _) => Material::new(g_inf, g_1, eta, k)?,
                    (None, Some(nu)) => Material::with_poisson(g_inf, g_1, eta, nu)?,
                    (None, None) => unreachable!("a model without k_0 has nu"),
                };
                Impact::new(sphere, v0, m)
            }
            ModelKind::Prony { n } => {
                let terms: Vec<(f64, f64)> =
                    (0..n).map(|i| (values[1 + i], self.taus[i])).collect();
                let shear = ShearProny::new(values[0], &terms)?;
                let bulk = match (self.k_0, nu) {
                    (Some(k), _) => BulkInput::Elastic(k),
                    (None, Some(nu)) => BulkInput::Poisson(nu),
                    (None, None) => unreachable!("a model without k_0 has nu"),
                };
                Impact::new(sphere, v0, Material::general(shear, bulk)?)
            }
        }
    }

    /// The CoR-determined groups (paper Eq. 11) as `(name, value, gradient of ln(group) with
    /// respect to the parameter coordinates)`: `p2 = g_inf / G_1` and
    /// `eta_over_g_inf_3_5 = eta / g_inf^(3/5)`. For a Prony model `G_1 = sum g_i` and
    /// `eta = sum g_i tau_i` (the total relaxing modulus and the viscosity of the series).
    pub fn groups(&self, values: &[f64]) -> Vec<(&'static str, f64, Vec<f64>)> {
        let np = self.params.len();
        let mut grad_p2 = vec![0.0; np];
        let mut grad_c = vec![0.0; np];
        grad_p2[0] = 1.0;
        grad_c[0] = -ETA_GROUP_EXPONENT;
        let (g_1, eta) = match self.kind {
            ModelKind::StandardSolid => {
                grad_p2[1] = -1.0;
                grad_c[2] = 1.0;
                (values[1], values[2])
            }
            ModelKind::Prony { n } => {
                let g1: f64 = values[1..=n].iter().sum();
                let eta: f64 = (0..n).map(|i| values[1 + i] * self.taus[i]).sum();
                for i in 0..n {
                    grad_p2[1 + i] = -values[1 + i] / g1;
                    grad_c[1 + i] = values[1 + i] * self.taus[i] / eta;
                }
                (g1, eta)
            }
        };
        vec![
            ("p2", values[0] / g_1, grad_p2),
            (
                "eta_over_g_inf_3_5",
                eta / values[0].powf(ETA_GROUP_EXPONENT),
                grad_c,
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_round_trip() {
        for v in [-0.9, 0.0, 0.3, 0.49, 0.4999] {
            let k = ParamKind::Poisson;
            assert!((k.from_coord(k.to_coord(v)) - v).abs() < 1e-12);
        }
        let k = ParamKind::Positive;
        assert!((k.from_coord(k.to_coord(3.5e6)) / 3.5e6 - 1.0).abs() < 1e-14);
    }

    #[test]
    fn model_names() {
        assert_eq!(
            "prony:3".parse::<ModelKind>().unwrap(),
            ModelKind::Prony { n: 3 }
        );
        assert!("prony:0".parse::<ModelKind>().is_err());
        assert!("prony:x".parse::<ModelKind>().is_err());
        assert!("maxwell".parse::<ModelKind>().is_err());
        let m = Model::new(ModelKind::StandardSolid, None, vec![]).unwrap();
        assert_eq!(m.names(), "g_inf, g_1, eta, nu, k_0");
    }
}
