//! The material models `fit` identifies and their parameter coordinates.
//!
//! Every parameter is fitted in an unbounded coordinate: moduli and viscosities (`g_inf`, `g_1`,
//! `eta`, `g_i`) in their natural logarithm (positivity), the static Poisson ratio through the
//! logistic transform `nu = -1 + 1.5 / (1 + exp(-z))`, which keeps it in `(-1, 0.5)` (the
//! incompressible limit `nu = 0.5` is approached as `z -> inf`; fix `nu=0.5` to impose it).

use crate::error::{Error, Result};
use crate::model::impact::Impact;
use crate::model::material::{BulkInput, Material, ShearProny};

use super::data::Data;

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
        let bad = || Error::Parse {
            what: "--model",
            input: crate::error::escape_text(s),
            expected: format!("standard-solid or prony:N with 1 <= N <= {MAX_PRONY_TERMS}"),
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

/// A parameter of a model, by name: the code reads values through [`Model::slot`] and
/// [`Model::get`], never by position; the positions exist only in the value vector that the
/// Levenberg–Marquardt solver moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parameter {
    /// The relaxed shear modulus `g_inf` (Pa), in every model.
    GInf,
    /// The standard solid's relaxing modulus `g_1` (Pa).
    G1,
    /// The standard solid's viscosity `eta` (Pa s).
    Eta,
    /// The modulus `g_i` (Pa) of the Prony term `i` (1-based).
    Term(usize),
    /// The static Poisson ratio `nu` (absent when `k_0` is fixed).
    Nu,
}

impl Parameter {
    /// The name (the `--fix` and JSON key).
    pub fn name(self) -> String {
        match self {
            Parameter::GInf => "g_inf".into(),
            Parameter::G1 => "g_1".into(),
            Parameter::Eta => "eta".into(),
            Parameter::Term(i) => format!("g_{i}"),
            Parameter::Nu => "nu".into(),
        }
    }
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
                    return Err(Error::OutOfRange {
                        field: "prony: relaxation times",
                        value: taus.len() as f64,
                        allowed: "one relaxation time per term of prony:N",
                    });
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

    /// The slot of `p` in a value vector, `None` when the model does not have it.
    pub fn slot(&self, p: Parameter) -> Option<usize> {
        match (&self.kind, p) {
            (_, Parameter::GInf) => Some(0),
            (ModelKind::StandardSolid, Parameter::G1) => Some(1),
            (ModelKind::StandardSolid, Parameter::Eta) => Some(2),
            (ModelKind::Prony { n }, Parameter::Term(i)) if (1..=*n).contains(&i) => Some(i),
            (_, Parameter::Nu) => self.index("nu"),
            _ => None,
        }
    }

    /// The parameters that are shear moduli besides `g_inf`: `g_1`, or the Prony `g_1 .. g_N`.
    pub fn moduli(&self) -> Vec<Parameter> {
        match self.kind {
            ModelKind::StandardSolid => vec![Parameter::G1],
            ModelKind::Prony { n } => (1..=n).map(Parameter::Term).collect(),
        }
    }

    /// The value of `p` in `values` (aligned with [`Model::params`]); `p` must be one of the
    /// model's parameters (`g_inf` always is; `g_1` and `eta` in the standard solid).
    pub fn get(&self, values: &[f64], p: Parameter) -> f64 {
        self.slot(p).map_or(f64::NAN, |i| values[i])
    }

    /// Set `p` in `values` (a parameter the model does not have is ignored).
    pub fn set(&self, values: &mut [f64], p: Parameter, value: f64) {
        if let Some(i) = self.slot(p) {
            values[i] = value;
        }
    }

    /// The names a `--fix` accepts, for messages.
    pub fn names(&self) -> String {
        let mut n: Vec<&str> = self.params.iter().map(|p| p.name.as_str()).collect();
        if self.k_0.is_none() {
            n.push("k_0");
        }
        n.join(", ")
    }

    /// Whether a parameter value is allowed: moduli `0 < x < inf`, `-1 < nu <= 0.5`; an error
    /// names the parameter (`--fix g_inf: value = -1e0 is out of range: ...`).
    pub fn check_value(&self, i: usize, value: f64) -> Result<f64> {
        match self.params[i].kind {
            ParamKind::Positive => crate::error::check(
                "value",
                value,
                value > 0.0,
                "0 < value < inf (a modulus in Pa or a viscosity in Pa s)",
            )
            .map_err(|e| e.at(format!("--fix {}", self.params[i].name))),
            ParamKind::Poisson => crate::error::check(
                "--fix nu",
                value,
                value > -1.0 && value <= 0.5,
                "-1 < nu <= 0.5",
            ),
        }
    }

    /// Whether the fixed values (aligned with [`Model::params`]) leave room in the box of
    /// [`Model::clamp`]: every fit stays in it and holds its fixed values, so a fixed value
    /// outside it would meet free values clamped to a box of other materials (a fixed
    /// `g_inf = 1e-300` Pa put `g_1` at 1e4 Pa or more, `p2` near 1e-304, and the fit spent a
    /// minute on solves that could not succeed). The `g_inf` the fixed values allow: the box
    /// [`BOX_G_INF`], a fixed `g_inf` itself, `g_i BOX_P2` for a fixed modulus `g_i`, and
    /// `(eta p3_scale / BOX_P3)^(5/3)` for a fixed `eta`. An empty intersection is refused,
    /// naming the first fixed value that excludes the box or the pair that exclude each other.
    pub fn check_fixed_in_box(&self, fixed: &[Option<f64>], p3_scale: f64) -> Result<()> {
        use Parameter::*;
        let fixed_of = |p: Parameter| self.slot(p).and_then(|i| fixed.get(i).copied().flatten());
        // (what fixed it, its g_inf interval)
        // (the fixed value, the box's rule on it, the g_inf it allows)
        let mut limits: Vec<(String, String, (f64, f64))> = Vec::new();
        if let Some(g) = fixed_of(GInf) {
            limits.push((format!("g_inf = {g:e} Pa"), String::new(), (g, g)));
        }
        for p in self.moduli() {
            if let (Some(g), Some(i)) = (fixed_of(p), self.slot(p)) {
                let name = &self.params[i].name;
                let rule = format!("g_inf/{name} from {:e} to {:e}", BOX_P2.0, BOX_P2.1);
                limits.push((
                    format!("{name} = {g:e} Pa"),
                    rule,
                    (g * BOX_P2.0, g * BOX_P2.1),
                ));
            }
        }
        if let (ModelKind::StandardSolid, Some(eta)) = (&self.kind, fixed_of(Eta)) {
            let g = |p3: f64| (eta * p3_scale / p3).powf(1.0 / ETA_GROUP_EXPONENT);
            let rule = format!("p3 from {:e} to {:e} at these drops", BOX_P3.0, BOX_P3.1);
            limits.push((
                format!("eta = {eta:e} Pa s"),
                rule,
                (g(BOX_P3.1), g(BOX_P3.0)),
            ));
        }
        let outside = |which: &[&(String, String, (f64, f64))]| {
            let values: Vec<&str> = which.iter().map(|l| l.0.as_str()).collect();
            let mut rules = vec![format!(
                "g_inf from {:e} to {:e} Pa",
                BOX_G_INF.0, BOX_G_INF.1
            )];
            rules.extend(
                which
                    .iter()
                    .filter(|l| !l.1.is_empty())
                    .map(|l| l.1.clone()),
            );
            Error::NotSupported {
                solver: "fit",
                what: format!(
                    "--fix {} leaves no material in the box the fit searches ({}): fix values \
                     inside it, or solve such a material with `run`",
                    values.join(" with "),
                    rules.join(", ")
                ),
            }
        };
        // ends compared with a relative slack: a value on the box's edge is in it
        let meets = |(lo, hi): (f64, f64), (l, h): (f64, f64)| {
            lo <= h * (1.0 + 1e-12) && l <= hi * (1.0 + 1e-12)
        };
        if let Some(l) = limits.iter().find(|l| !meets(l.2, BOX_G_INF)) {
            return Err(outside(&[l]));
        }
        let joint = limits
            .iter()
            .fold(BOX_G_INF, |(lo, hi), l| (lo.max(l.2 .0), hi.min(l.2 .1)));
        if !meets(joint, joint) {
            return Err(outside(&limits.iter().collect::<Vec<_>>()));
        }
        Ok(())
    }

    /// `values` clamped into the box ([`BOX_G_INF`], [`BOX_P2`], [`BOX_P3`] with
    /// `p3 = p3_scale eta / g_inf^(3/5)`, [`BOX_NU`]).
    pub fn clamp(&self, values: &[f64], p3_scale: f64) -> Vec<f64> {
        use Parameter::*;
        let mut v = values.to_vec();
        let g_inf = self.get(&v, GInf).clamp(BOX_G_INF.0, BOX_G_INF.1);
        self.set(&mut v, GInf, g_inf);
        for p in self.moduli() {
            let x = self.get(&v, p).clamp(g_inf / BOX_P2.1, g_inf / BOX_P2.0);
            self.set(&mut v, p, x);
        }
        if self.kind == ModelKind::StandardSolid {
            let c = g_inf.powf(ETA_GROUP_EXPONENT) / p3_scale;
            let eta = self.get(&v, Eta).clamp(BOX_P3.0 * c, BOX_P3.1 * c);
            self.set(&mut v, Eta, eta);
        }
        if self.slot(Nu).is_some() {
            let nu = self.get(&v, Nu).clamp(BOX_NU.0, BOX_NU.1);
            self.set(&mut v, Nu, nu);
        }
        v
    }

    /// The impact of `sphere` (a [`crate::model::impact::Sphere`]: Hertz's paraboloid, or an impactor of any
    /// shape) at `v0` (m/s) on the material with parameter `values`.
    pub fn impact(
        &self,
        sphere: impl Into<super::data::Impactor>,
        v0: f64,
        values: &[f64],
    ) -> Result<Impact> {
        let super::data::Impactor { sphere, shape } = sphere.into();
        use Parameter::*;
        let nu = self.slot(Nu).map(|_| self.get(values, Nu));
        let g_inf = self.get(values, GInf);
        match self.kind {
            ModelKind::StandardSolid => {
                let (g_1, eta) = (self.get(values, G1), self.get(values, Eta));
                let m = match (self.k_0, nu) {
                    (Some(k), _) => Material::new(g_inf, g_1, eta, k)?,
                    (None, Some(nu)) => Material::with_poisson(g_inf, g_1, eta, nu)?,
                    (None, None) => unreachable!("a model without k_0 has nu"),
                };
                Impact::shaped(sphere, shape, v0, m)
            }
            ModelKind::Prony { n } => {
                let terms: Vec<(f64, f64)> = (0..n)
                    .map(|i| (self.get(values, Term(i + 1)), self.taus[i]))
                    .collect();
                let shear = ShearProny::new(g_inf, &terms)?;
                let bulk = match (self.k_0, nu) {
                    (Some(k), _) => BulkInput::Elastic(k),
                    (None, Some(nu)) => BulkInput::Poisson(nu),
                    (None, None) => unreachable!("a model without k_0 has nu"),
                };
                Impact::shaped(sphere, shape, v0, Material::general(shear, bulk)?)
            }
        }
    }

    /// The CoR-determined groups (paper Eq. 11) as `(name, value, gradient of ln(group) with
    /// respect to the parameter coordinates)`: `p2 = g_inf / G_1` and
    /// `eta_over_g_inf_3_5 = eta / g_inf^(3/5)`. For a Prony model `G_1 = sum g_i` and
    /// `eta = sum g_i tau_i` (the total relaxing modulus and the viscosity of the series).
    pub fn groups(&self, values: &[f64]) -> Vec<(&'static str, f64, Vec<f64>)> {
        use Parameter::*;
        let np = self.params.len();
        let mut grad_p2 = vec![0.0; np];
        let mut grad_c = vec![0.0; np];
        self.set(&mut grad_p2, GInf, 1.0);
        self.set(&mut grad_c, GInf, -ETA_GROUP_EXPONENT);
        let (g_1, eta) = match self.kind {
            ModelKind::StandardSolid => {
                self.set(&mut grad_p2, G1, -1.0);
                self.set(&mut grad_c, Eta, 1.0);
                (self.get(values, G1), self.get(values, Eta))
            }
            ModelKind::Prony { n } => {
                let g = |i: usize| self.get(values, Term(i + 1));
                let g1: f64 = (0..n).map(g).sum();
                let eta: f64 = (0..n).map(|i| g(i) * self.taus[i]).sum();
                for i in 0..n {
                    self.set(&mut grad_p2, Term(i + 1), -g(i) / g1);
                    self.set(&mut grad_c, Term(i + 1), g(i) * self.taus[i] / eta);
                }
                (g1, eta)
            }
        };
        let g_inf = self.get(values, GInf);
        vec![
            ("p2", g_inf / g_1, grad_p2),
            (
                "eta_over_g_inf_3_5",
                eta / g_inf.powf(ETA_GROUP_EXPONENT),
                grad_c,
            ),
        ]
    }
}

/// The fixed relaxation times of `prony:N` (s): `N` log-spaced times over `MIN:MAX` (`range`),
/// or by default from the measured contact times (the shortest / 100 to the longest x 100; one
/// time: their geometric mean). Without contact times `range` is required. Empty for the
/// standard solid.
pub fn prony_times(kind: &ModelKind, range: Option<&str>, data: &Data) -> Result<Vec<f64>> {
    let ModelKind::Prony { n } = *kind else {
        return match range {
            Some(_) => Err(Error::NotSupported {
                solver: "fit",
                what: "--tau-range applies to --model prony:N only".into(),
            }),
            None => Ok(Vec::new()),
        };
    };
    let (lo, hi) = match range {
        Some(s) => {
            let bad = || Error::Parse {
                what: "--tau-range",
                input: crate::error::escape_text(s),
                expected: "MIN:MAX (s) with 0 < MIN < MAX < inf".into(),
            };
            let (a, b) = s.split_once(':').ok_or_else(bad)?;
            let a: f64 = a.trim().parse().map_err(|_| bad())?;
            let b: f64 = b.trim().parse().map_err(|_| bad())?;
            if !(a > 0.0 && a < b && b.is_finite()) {
                return Err(bad());
            }
            (a, b)
        }
        None => {
            let t: Vec<f64> = data
                .observations
                .iter()
                .filter_map(|o| o.contact_time)
                .collect();
            if t.is_empty() {
                return Err(Error::NotSupported {
                    solver: "fit",
                    what: "--model prony:N without contact times needs --tau-range MIN:MAX (s)"
                        .into(),
                });
            }
            let a = t.iter().copied().fold(f64::INFINITY, f64::min) / 100.0;
            let b = t.iter().copied().fold(0.0, f64::max) * 100.0;
            (a, b)
        }
    };
    Ok(crate::math::logspace(lo, hi, n))
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
