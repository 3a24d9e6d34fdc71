//! The one catalogue of validation and benchmark cases, shared by the tests, the benches, the
//! `validate` and `bench` commands and VALIDATION.md. Every case is a point of the paper's
//! dimensionless space (Eq. 11) with its regime; reference values come from the independent
//! theory ([`crate::theory`]) at run time and from the committed files in `reference/`.

use crate::error::Result;
use crate::impact::{Groups, Impact};

/// The regimes in which accuracy is reported.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Regime {
    /// Little dissipation: relaxation much faster or much slower than the impact.
    Elastic,
    /// Strong dissipation (CoR well below 1), moderate compressibility.
    Dissipative,
    /// Static Poisson ratio 0.49 and above.
    NearIncompressible,
    /// Static Poisson ratio 0 and below (negative glassy Poisson ratio).
    StronglyCompressible,
    /// Relaxation time `tau` below 1e-3 of the contact time.
    Stiff,
}

impl Regime {
    /// All regimes, in report order.
    pub const ALL: [Regime; 5] = [
        Regime::Elastic,
        Regime::Dissipative,
        Regime::NearIncompressible,
        Regime::StronglyCompressible,
        Regime::Stiff,
    ];
    /// Name used in tables and snapshots.
    pub fn name(self) -> &'static str {
        match self {
            Regime::Elastic => "elastic",
            Regime::Dissipative => "dissipative",
            Regime::NearIncompressible => "near-incompressible",
            Regime::StronglyCompressible => "strongly-compressible",
            Regime::Stiff => "stiff",
        }
    }
}

/// One catalogue case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Case {
    /// Short identifier (file names, snapshot keys).
    pub id: &'static str,
    /// Regime of the case.
    pub regime: Regime,
    /// Static Poisson ratio (0.5: incompressible).
    pub nu: f64,
    /// `p2 = G_inf / G_1`.
    pub p2: f64,
    /// `p3`, the dimensionless viscosity of Eq. (11).
    pub p3: f64,
}

impl Case {
    /// Dimensionless groups of the case.
    pub fn groups(&self) -> Result<Groups> {
        Groups::new(self.nu, self.p2, self.p3)
    }
    /// The impact in canonical units.
    pub fn impact(&self) -> Result<Impact> {
        Impact::from_groups(self.groups()?)
    }
}

macro_rules! case {
    ($id:literal, $regime:ident, $nu:expr, $p2:expr, $p3:expr) => {
        Case {
            id: $id,
            regime: Regime::$regime,
            nu: $nu,
            p2: $p2,
            p3: $p3,
        }
    };
}

/// The impact cases.
pub const IMPACTS: &[Case] = &[
    case!("elastic-fast-relaxation", Elastic, 0.3, 1.0, 1e-3),
    case!("elastic-slow-relaxation", Elastic, 0.45, 1.0, 1e3),
    case!("elastic-weak-relaxing-branch", Elastic, 0.5, 100.0, 1.0),
    case!("dissipative-nu045", Dissipative, 0.45, 0.01, 1.0),
    case!("dissipative-incompressible", Dissipative, 0.5, 0.01, 1.0),
    case!("dissipative-nu03", Dissipative, 0.3, 0.1, 0.5),
    // the glassy corner, G_0 / G_inf = 1e6, p3 = 1e4 (where fast once missed its rtol)
    case!(
        "dissipative-nu045-p2-1e-6-p3-1e4",
        Dissipative,
        0.45,
        1e-6,
        1e4
    ),
    case!(
        "near-incompressible-nu049",
        NearIncompressible,
        0.49,
        0.001,
        10.0
    ),
    case!(
        "near-incompressible-nu0499",
        NearIncompressible,
        0.499,
        0.01,
        1.0
    ),
    case!(
        "near-incompressible-nu0499-p2-1e-3",
        NearIncompressible,
        0.499,
        0.001,
        10.0
    ),
    case!(
        "compressible-nu0-p2-0.1",
        StronglyCompressible,
        0.0,
        0.1,
        1.0
    ),
    case!("compressible-nu-05", StronglyCompressible, -0.5, 0.01, 1.0),
    case!("compressible-nu-09", StronglyCompressible, -0.9, 0.001, 3.0),
    case!("stiff-tau-1e-5", Stiff, 0.45, 1e-3, 1e-2),
    case!("stiff-tau-1e-6", Stiff, 0.3, 1e-4, 1e-2),
    case!("stiff-tau-1e-7", Stiff, 0.5, 1e-4, 1e-3),
    case!("stiff-dissipative", Stiff, 0.45, 1e-4, 0.3),
    // G_0 / G_inf = 1e7 and tau = p2 p3 = 1e-3
    case!("stiff-glassy-p2-1e-7-p3-1e4", Stiff, 0.5, 1e-7, 1e4),
];

/// Look up an impact case by id.
pub fn impact_case(id: &str) -> Option<&'static Case> {
    IMPACTS.iter().find(|c| c.id == id)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_unique_and_cases_valid() {
        let mut ids: Vec<_> = IMPACTS.iter().map(|c| c.id).collect();
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), IMPACTS.len());
        for c in IMPACTS {
            c.impact().unwrap();
        }
        for r in Regime::ALL {
            assert!(
                IMPACTS.iter().filter(|c| c.regime == r).count() >= 3,
                "{r:?}"
            );
        }
    }
}
