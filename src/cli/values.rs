//! Closed sets of flag values, parsed by clap so that a typo exits with code 2 and lists the
//! accepted values. The library keeps its own enums and `FromStr`; these map onto them.

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::ValueEnum;
use mdr_impact::apps::{dem, dma, fit};
use mdr_impact::solvers::IndentMethod;
use mdr_impact::SolverKind;

/// `--solver` of the impact commands: the names of [`SolverKind::NAMES`].
pub fn solver() -> impl TypedValueParser<Value = SolverKind> {
    PossibleValuesParser::new(SolverKind::NAMES).try_map(|s| s.parse::<SolverKind>())
}

/// `--model` of `fit`: `standard-solid` or `prony:N` (not a closed set: N is a number).
pub fn model(s: &str) -> Result<fit::ModelKind, String> {
    s.parse::<fit::ModelKind>().map_err(|e| e.to_string())
}

/// `dem --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// LAMMPS input lines.
    Lammps,
    /// LIGGGHTS input lines.
    Liggghts,
    /// One JSON object on stdout.
    Json,
}

impl Format {
    /// The library's format of this name, with `--lammps-version` applied.
    pub fn with_lammps_version(self, version: Option<&str>) -> mdr_impact::Result<dem::Format> {
        let name = self.to_possible_value().map(|v| v.get_name().to_string());
        name.unwrap_or_default()
            .parse::<dem::Format>()?
            .with_lammps_version(version)
    }
}

/// `dem --modulus`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Modulus {
    /// E* = 4 G_eq(inf).
    Relaxed,
    /// E* = 4 G_eq(0).
    Glassy,
    /// E* fitted to the contact times.
    Fit,
}

impl From<Modulus> for dem::ModulusChoice {
    fn from(m: Modulus) -> Self {
        match m {
            Modulus::Relaxed => dem::ModulusChoice::Relaxed,
            Modulus::Glassy => dem::ModulusChoice::Glassy,
            Modulus::Fit => dem::ModulusChoice::Fit,
        }
    }
}

/// `indent --solver`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Indent {
    /// Lee-Radok/Ting by quadrature.
    Theory,
    /// The MDR foundation driven by the indentation.
    Mdr,
}

impl From<Indent> for IndentMethod {
    fn from(m: Indent) -> Self {
        match m {
            Indent::Theory => IndentMethod::Theory,
            Indent::Mdr => IndentMethod::Mdr,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every mirror value has the library's name for the library's value.
    #[test]
    fn mirrors_use_the_library_names() {
        let name = |v: &dyn Fn() -> Option<clap::builder::PossibleValue>| {
            v().map(|p| p.get_name().to_string()).unwrap()
        };
        for f in Format::value_variants() {
            let n = name(&|| f.to_possible_value());
            assert_eq!(
                n.parse::<dem::Format>().unwrap(),
                f.with_lammps_version(None).unwrap()
            );
        }
        for m in Modulus::value_variants() {
            let n = name(&|| m.to_possible_value());
            assert_eq!(n.parse::<dem::ModulusChoice>().unwrap(), (*m).into());
        }
        for m in Indent::value_variants() {
            let n = name(&|| m.to_possible_value());
            assert_eq!(n.parse::<IndentMethod>().unwrap(), (*m).into());
        }
    }
}

/// `prony --modulus`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DmaModulus {
    /// Shear moduli G', G''.
    Shear,
    /// Tensile moduli E', E'' (converted with --nu).
    Tensile,
}

impl From<DmaModulus> for dma::data::ModulusKind {
    fn from(m: DmaModulus) -> Self {
        match m {
            DmaModulus::Shear => dma::data::ModulusKind::Shear,
            DmaModulus::Tensile => dma::data::ModulusKind::Tensile,
        }
    }
}

/// `prony --shift`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Shift {
    /// Williams–Landel–Ferry.
    Wlf,
    /// Arrhenius.
    Arrhenius,
    /// No law: only the per-isotherm factors.
    None,
}

impl From<Shift> for dma::shift::LawKind {
    fn from(s: Shift) -> Self {
        match s {
            Shift::Wlf => dma::shift::LawKind::Wlf,
            Shift::Arrhenius => dma::shift::LawKind::Arrhenius,
            Shift::None => dma::shift::LawKind::None,
        }
    }
}
