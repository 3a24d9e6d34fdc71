//! The one catalogue of validation and benchmark cases, shared by the tests, the benches, the
//! `validate` and `bench` commands and VALIDATION.md. Every case is a point of the paper's
//! dimensionless space (Eq. 11) with its regime; reference values come from the independent
//! theory ([`crate::solvers::theory`]) at run time, from the committed files in `reference/` and,
//! for each impact case, from its expected values ([`Case::expected`], `report::expected`).

use crate::error::Result;
use crate::model::bodies::{Body, BodyMaterial, Side, TwoBodies};
use crate::model::impact::{Groups, Impact, Sphere};
use crate::model::material::{BulkInput, BulkProny, BulkRheology, Material, ShearProny};

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
    pub fn material(&self) -> Result<Material> {
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
            None => BulkInput::Incompressible,
            Some((k_inf, kt)) => {
                let kt: Vec<(f64, f64)> = kt.iter().copied().filter(|&(k, _)| k > 0.0).collect();
                if kt.is_empty() {
                    BulkInput::Elastic(k_inf)
                } else {
                    BulkInput::Prony(BulkProny::new(k_inf, &kt)?)
                }
            }
        };
        Material::general(shear, bulk)
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

/// A real polymer given as a published Prony series: a scene of `scenes/` (its header line
/// cites the source), with the default scene's steel ball at 0.99 m/s.
#[derive(Debug, Clone, Copy)]
pub struct PolymerCase {
    /// Short identifier.
    pub id: &'static str,
    /// What it stands for.
    pub what: &'static str,
    /// File name of the scene in `scenes/`.
    pub scene: &'static str,
}

impl PolymerCase {
    /// Path of the scene in the source tree.
    pub fn path(&self) -> std::path::PathBuf {
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(self.scene)
    }
    /// The impact of the scene.
    pub fn impact(&self) -> Result<Impact> {
        Ok(crate::io::scene::Scene::load(&self.path())?.impact)
    }
}

/// The real polymers: a rubber (30 shear terms over 18 decades) and a glassy polymer (24
/// terms over 12 decades), both shipped as scenes.
pub const POLYMERS: &[PolymerCase] = &[
    PolymerCase {
        id: "polyisobutylene",
        what: "rubber: polyisobutylene, 30 shear terms (Brinson & Brinson), incompressible",
        scene: "polyisobutylene.toml",
    },
    PolymerCase {
        id: "epoxy",
        what: "glassy polymer: cured epoxy, 24 shear terms (Simon, McKenna & Sindt 2000), incompressible",
        scene: "epoxy.toml",
    },
];

/// One general-material entry of the validation and the bench: a synthetic case of
/// [`GENERAL`] (unit sphere at unit speed) or a real polymer of [`POLYMERS`] (SI scene).
#[derive(Debug, Clone)]
pub struct GeneralEntry {
    /// Short identifier.
    pub id: &'static str,
    /// What it stands for.
    pub what: &'static str,
    /// The material.
    pub material: Material,
    /// The impact.
    pub impact: Impact,
}

impl GeneralEntry {
    /// Shortest and longest relaxation time of shear and bulk (s).
    pub fn time_range(&self) -> (f64, f64) {
        let shear = self.material.shear().terms().iter().map(|t| t.1);
        let bulk: Vec<f64> = match self.material.bulk() {
            BulkRheology::Prony(b) => b.terms().iter().map(|t| t.1).collect(),
            _ => Vec::new(),
        };
        shear
            .chain(bulk)
            .fold((f64::INFINITY, 0.0_f64), |(lo, hi), t| {
                (lo.min(t), hi.max(t))
            })
    }
}

/// Every general-material entry: [`GENERAL`], then [`POLYMERS`].
pub fn general_entries() -> Result<Vec<GeneralEntry>> {
    let mut out = Vec::new();
    for case in GENERAL {
        out.push(GeneralEntry {
            id: case.id,
            what: case.what,
            material: case.material()?,
            impact: case.impact()?,
        });
    }
    for case in POLYMERS {
        let impact = case.impact()?;
        let material = impact
            .general_material()
            .cloned()
            .ok_or(crate::Error::Internal(
                "catalogue: a polymer that is not a general material",
            ))?;
        out.push(GeneralEntry {
            id: case.id,
            what: case.what,
            material,
            impact,
        });
    }
    Ok(out)
}

/// A two-body collision case (docs/theory.md §8), SI units: body A, body B, relative velocity.
#[derive(Debug, Clone, Copy)]
pub struct TwoBodyCase {
    /// Short identifier.
    pub id: &'static str,
    /// What it stands for.
    pub what: &'static str,
    /// Builds the impact.
    pub build: fn() -> Result<Impact>,
}

impl TwoBodyCase {
    /// The impact.
    pub fn impact(&self) -> Result<Impact> {
        (self.build)()
    }
}

/// The default scene's elastomer as a body material.
fn elastomer() -> Result<BodyMaterial> {
    Ok(BodyMaterial::Viscoelastic(Material::with_poisson(
        1.0e6, 1.0e7, 500.0, 0.49,
    )?))
}

/// The polymer of `scenes/two_spheres.toml`: three shear terms and a relaxing bulk.
fn polymer() -> Result<BodyMaterial> {
    let shear = ShearProny::new(5.0e6, &[(2.0e7, 1.0e-6), (3.0e7, 1.0e-5), (1.0e7, 1.0e-4)])?;
    let bulk = BulkProny::new(2.0e8, &[(1.0e8, 1.0e-5)])?;
    Ok(BodyMaterial::Viscoelastic(Material::general(
        shear,
        BulkInput::Prony(bulk),
    )?))
}

/// Elastic steel (E = 210 GPa, nu = 0.3) as a general material without terms.
fn steel() -> Result<BodyMaterial> {
    let g = 210.0e9 / (2.0 * 1.3);
    Ok(BodyMaterial::Viscoelastic(Material::general(
        ShearProny::new(g, &[])?,
        BulkInput::Poisson(0.3),
    )?))
}

fn pair(a: Body, b: Body, v0: f64) -> Result<Impact> {
    Impact::with_bodies(TwoBodies::new(a, b)?, v0)
}

/// Two-body collisions: every combination the two-body model adds (two viscoelastic spheres,
/// identical spheres, a viscoelastic sphere on an elastic or viscoelastic wall, a rigid sphere on
/// a viscoelastic wall, compressible standard solids with far-apart relaxation times).
pub const TWO_BODIES: &[TwoBodyCase] = &[
    TwoBodyCase {
        id: "elastomer-polymer-spheres",
        what: "20 mm elastomer ball against a 10 mm 3-term polymer ball (scenes/two_spheres.toml)",
        build: || {
            pair(
                Body::with_density(Side::A, 1100.0, 1.0e-2, elastomer()?)?,
                Body::with_density(Side::B, 1200.0, 5.0e-3, polymer()?)?,
                2.0,
            )
        },
    },
    TwoBodyCase {
        id: "identical-elastomer-spheres",
        what: "two identical 10 mm elastomer balls",
        build: || {
            pair(
                Body::new(Side::A, 4.11e-3, 5.0e-3, elastomer()?)?,
                Body::new(Side::B, 4.11e-3, 5.0e-3, elastomer()?)?,
                0.99,
            )
        },
    },
    TwoBodyCase {
        id: "polymer-on-steel-plate",
        what: "10 mm polymer ball on an elastic steel plate (wall)",
        build: || {
            pair(
                Body::with_density(Side::A, 1200.0, 5.0e-3, polymer()?)?,
                Body::new(Side::B, f64::INFINITY, f64::INFINITY, steel()?)?,
                1.0,
            )
        },
    },
    TwoBodyCase {
        id: "steel-ball-on-polymer-block",
        what: "10 mm elastic steel ball on a polymer block (wall)",
        build: || {
            pair(
                Body::with_density(Side::A, 7850.0, 5.0e-3, steel()?)?,
                Body::new(Side::B, f64::INFINITY, f64::INFINITY, polymer()?)?,
                1.0,
            )
        },
    },
    TwoBodyCase {
        id: "compressible-standard-solids",
        what: "standard solids nu = 0.3 (tau 10 us) and nu = -0.5 (tau 1 ms), masses 1:10",
        build: || {
            let a = Material::with_poisson(2.0e6, 2.0e7, 200.0, 0.3)?;
            let b = Material::with_poisson(1.0e6, 5.0e6, 5000.0, -0.5)?;
            pair(
                Body::new(Side::A, 1.0e-3, 5.0e-3, BodyMaterial::Viscoelastic(a))?,
                Body::new(Side::B, 1.0e-2, 1.0e-2, BodyMaterial::Viscoelastic(b))?,
                3.0,
            )
        },
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
        for c in TWO_BODIES {
            assert!(c.impact().unwrap().bodies().is_some(), "{}", c.id);
        }
        for r in Regime::ALL {
            assert!(
                IMPACTS.iter().filter(|c| c.regime == r).count() >= 3,
                "{r:?}"
            );
        }
    }
}
