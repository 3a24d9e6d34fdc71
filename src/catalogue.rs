//! The one catalogue of validation and benchmark cases, shared by the tests, the benches, the
//! `validate` and `bench` commands and VALIDATION.md. Every case is a point of the paper's
//! dimensionless space (Eq. 11) with its regime; reference values come from the independent
//! theory ([`crate::theory`]) at run time and from the committed files in `reference/`.

use crate::error::Result;
use crate::impact::{Groups, Impact, Sphere};
use crate::material::{BulkProny, BulkRheology, GeneralMaterial, ShearProny};

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

/// A general-material case: Prony series in shear and bulk, in canonical units (`m = R = v0 = 1`,
/// moduli in units of the relaxed shear modulus `g_inf = 1`, times in units of `L / v0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GeneralCase {
    /// Short identifier.
    pub id: &'static str,
    /// What it stands for.
    pub what: &'static str,
    /// Number of shear terms, log-spaced in time over `[tau_min, tau_max]`.
    pub shear_terms: usize,
    /// Shortest shear relaxation time.
    pub tau_min: f64,
    /// Longest shear relaxation time.
    pub tau_max: f64,
    /// Sum of the shear moduli `Σ g_i` (the glassy modulus is `1 + Σ g_i`); `g_i ∝ tau_i^-0.3`.
    pub shear_sum: f64,
    /// Bulk: `None` incompressible, else `(k_inf, [(k_j, theta_j)])` with at most two terms.
    pub bulk: Option<(f64, [(f64, f64); 2])>,
}

impl GeneralCase {
    /// The material.
    pub fn material(&self) -> Result<GeneralMaterial> {
        let n = self.shear_terms;
        let taus: Vec<f64> = (0..n)
            .map(|i| {
                let x = if n > 1 {
                    i as f64 / (n - 1) as f64
                } else {
                    0.0
                };
                self.tau_min * (self.tau_max / self.tau_min).powf(x)
            })
            .collect();
        let w: Vec<f64> = taus.iter().map(|t| t.powf(-0.3)).collect();
        let total: f64 = w.iter().sum();
        let terms: Vec<(f64, f64)> = w
            .iter()
            .zip(&taus)
            .map(|(wi, &t)| (self.shear_sum * wi / total, t))
            .collect();
        let shear = ShearProny::new(1.0, &terms)?;
        let bulk = match self.bulk {
            None => BulkRheology::Incompressible,
            Some((k_inf, kt)) => {
                let kt: Vec<(f64, f64)> = kt.iter().copied().filter(|&(k, _)| k > 0.0).collect();
                if kt.is_empty() {
                    BulkRheology::Elastic(k_inf)
                } else {
                    BulkRheology::Prony(BulkProny::new(k_inf, &kt)?)
                }
            }
        };
        GeneralMaterial::new(shear, bulk)
    }
    /// The impact of the unit sphere at unit speed.
    pub fn impact(&self) -> Result<Impact> {
        Impact::with_general(Sphere::new(1.0, 1.0)?, 1.0, self.material()?)
    }
}

/// The general-material cases: multi-term shear series over many decades, elastic and
/// viscoelastic bulk (VALIDATION.md section 1c).
pub const GENERAL: &[GeneralCase] = &[
    GeneralCase {
        id: "prony-3-elastic-bulk",
        what: "3 shear terms over 2 decades, elastic bulk (static nu about 0.45)",
        shear_terms: 3,
        tau_min: 1e-2,
        tau_max: 1.0,
        shear_sum: 100.0,
        bulk: Some((9.7, [(0.0, 1.0), (0.0, 1.0)])),
    },
    GeneralCase {
        id: "prony-10-viscoelastic-bulk",
        what: "10 shear terms over 9 decades, bulk with 2 terms",
        shear_terms: 10,
        tau_min: 1e-6,
        tau_max: 1e3,
        shear_sum: 300.0,
        bulk: Some((5.0, [(20.0, 1e-3), (5.0, 1e-1)])),
    },
    GeneralCase {
        id: "prony-30-incompressible",
        what: "30 shear terms over 20 decades, incompressible (a glassy polymer's span)",
        shear_terms: 30,
        tau_min: 1e-12,
        tau_max: 1e8,
        shear_sum: 1000.0,
        bulk: None,
    },
    GeneralCase {
        id: "prony-30-viscoelastic-bulk",
        what: "30 shear terms over 20 decades, bulk with 2 terms",
        shear_terms: 30,
        tau_min: 1e-12,
        tau_max: 1e8,
        shear_sum: 1000.0,
        bulk: Some((50.0, [(500.0, 1e-6), (100.0, 1e-2)])),
    },
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
        let mut general: Vec<_> = GENERAL.iter().map(|c| c.id).collect();
        general.sort();
        general.dedup();
        assert_eq!(general.len(), GENERAL.len());
        for c in GENERAL {
            let imp = c.impact().unwrap();
            assert!(imp.canonical_relaxation().terms.len() >= c.shear_terms);
        }
        for r in Regime::ALL {
            assert!(
                IMPACTS.iter().filter(|c| c.regime == r).count() >= 3,
                "{r:?}"
            );
        }
    }
}
