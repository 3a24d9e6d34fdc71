//! The Prony series of a scene's `[material.shear]` and `[material.bulk]` tables (inline
//! `terms`, the normalised `instantaneous` + `ratios` form, or a `file`), and the general
//! material they make.

use std::path::Path;

use super::*;
use crate::model::material::{BulkInput, BulkProny, ShearProny};

/// Which table a Prony series comes from, with the names its errors use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Table {
    Shear,
    Bulk,
}

impl Table {
    fn name(self) -> &'static str {
        match self {
            Table::Shear => "[material.shear]",
            Table::Bulk => "[material.bulk]",
        }
    }
    /// The relaxed-modulus key (`g_inf`, `k_inf`).
    fn relaxed(self) -> &'static str {
        match self {
            Table::Shear => "g_inf",
            Table::Bulk => "k_inf",
        }
    }
    /// `e` with the table it came from as its place ([`Error::In`]): an error about the terms
    /// of a series is placed in the table's `section` (`terms` or `ratios`), anything else in
    /// the table itself.
    fn place(self, section: &str, e: Error) -> Error {
        let (modulus, time) = self.term_fields();
        match e {
            Error::PronyTerm { .. } => e.at(format!("{} {section}", self.name())),
            Error::OutOfRange { field, .. } if field == modulus || field == time => {
                e.at(format!("{} {section}", self.name()))
            }
            e => e.at(self.name()),
        }
    }
    /// The names of a term's modulus and time in this table (`g_i`, `tau_i` or `k_j`, `theta_j`).
    fn term_fields(self) -> (&'static str, &'static str) {
        match self {
            Table::Shear => ("g_i", "tau_i"),
            Table::Bulk => ("k_j", "theta_j"),
        }
    }
}

/// The keys of a Prony-series form (shared by `[material.shear]` and `[material.bulk]`).
struct SeriesKeys<'a> {
    relaxed: Option<f64>,
    terms: &'a Option<Vec<Vec<f64>>>,
    file: &'a Option<PathBuf>,
    instantaneous: Option<f64>,
    ratios: &'a Option<Vec<Vec<f64>>>,
}

/// The relaxed modulus (Pa) and the `(modulus` (Pa), `time` (s)`)` pairs of a series form:
/// `relaxed` with `terms` or `file`, or `instantaneous` with `ratios`
/// (`G(t) = G0 (1 - sum g_i (1 - exp(-t / tau_i)))`: relaxed `G0 (1 - sum g_i)`, moduli
/// `g_i G0`). Only checks what the forms need; the moduli and times themselves are checked by
/// the series constructors.
fn series_of(table: Table, k: &SeriesKeys<'_>, base: &Path) -> Result<(f64, Vec<(f64, f64)>)> {
    let t = table.name();
    let r = table.relaxed();
    if k.instantaneous.is_some() || k.ratios.is_some() {
        if k.relaxed.is_some() || k.terms.is_some() || k.file.is_some() {
            return Err(scene_error(format!(
                "{t}: instantaneous/ratios (normalised form) cannot be mixed with {r}, terms or \
                 file"
            )));
        }
        let (Some(g0), Some(ratios)) = (k.instantaneous, k.ratios) else {
            let missing = if k.instantaneous.is_none() {
                "instantaneous (Pa)"
            } else {
                "ratios = [[ratio, time], ...]"
            };
            return Err(scene_error(format!(
                "{t}: missing {missing} (the normalised form needs instantaneous and ratios)"
            )));
        };
        let g0 = crate::error::check(
            "instantaneous",
            g0,
            g0 > 0.0,
            "0 < instantaneous < inf (Pa)",
        )
        .map_err(|e| table.place("ratios", e))?;
        let pairs = pairs_of(t, "ratios", ratios)?;
        let mut sum = 0.0;
        for (index, &(g, tau)) in pairs.iter().enumerate() {
            if !(g.is_finite() && (0.0..1.0).contains(&g)) {
                return Err(table.place(
                    "ratios",
                    Error::PronyTerm {
                        field: table.term_fields().0,
                        index,
                        value: g,
                        allowed: "0 <= ratio < 1",
                    },
                ));
            }
            if !(tau.is_finite() && tau > 0.0) {
                return Err(table.place(
                    "ratios",
                    Error::PronyTerm {
                        field: table.term_fields().1,
                        index,
                        value: tau,
                        allowed: "0 < time < inf (s)",
                    },
                ));
            }
            sum += g;
        }
        if sum >= 1.0 {
            return Err(table.place(
                "ratios",
                Error::OutOfRange {
                    field: "ratios",
                    value: sum,
                    allowed: "a sum of the ratios below 1 (relaxed modulus = instantaneous \
                              (1 - sum) > 0)",
                },
            ));
        }
        let relaxed = g0 * (1.0 - sum);
        let moduli = pairs.iter().map(|&(g, tau)| (g * g0, tau)).collect();
        return Ok((relaxed, moduli));
    }
    let Some(relaxed) = k.relaxed else {
        return Err(scene_error(format!(
            "{t}: missing {r} (Pa, the relaxed modulus) with terms = [[modulus, time], ...] or \
             file = \"table.csv\"; or instantaneous with ratios"
        )));
    };
    let pairs = match (k.terms, k.file) {
        (Some(terms), None) => pairs_of(t, "terms", terms)?,
        (None, Some(file)) => {
            if file.as_os_str().is_empty() {
                return Err(scene_error(format!(
                    "{t} file is an empty path: give a file name"
                )));
            }
            crate::io::prony_table::read_prony_table(&base.join(file))?
        }
        (Some(_), Some(_)) => {
            return Err(scene_error(format!(
                "{t}: give either terms or file, not both"
            )))
        }
        (None, None) => {
            return Err(scene_error(format!(
                "{t}: missing terms = [[modulus, time], ...] (terms = [] for none) or \
                 file = \"table.csv\" beside {r}"
            )))
        }
    };
    Ok((relaxed, pairs))
}

/// `[[a, b], ...]` as pairs; a row that is not a pair is an error naming `table key[index]`,
/// more than [`crate::io::prony_table::MAX_PRONY_TERMS`] rows one naming `table key`.
fn pairs_of(table: &str, key: &str, rows: &[Vec<f64>]) -> Result<Vec<(f64, f64)>> {
    crate::io::prony_table::check_term_count(&format!("{table} {key}"), rows.len())?;
    rows.iter()
        .enumerate()
        .map(|(i, row)| match row.as_slice() {
            &[a, b] => Ok((a, b)),
            _ => Err(scene_error(format!(
                "{table} {key}[{i}]: expected a pair [modulus, time], found {} numbers",
                row.len()
            ))),
        })
        .collect()
}

/// The general material of `[material.shear]` and `[material.bulk]`.
pub(super) fn general_material(shear: &RawShear, bulk: &RawBulk, base: &Path) -> Result<Material> {
    let (g_inf, terms) = series_of(
        Table::Shear,
        &SeriesKeys {
            relaxed: shear.g_inf,
            terms: &shear.terms,
            file: &shear.file,
            instantaneous: shear.instantaneous,
            ratios: &shear.ratios,
        },
        base,
    )?;
    let shear = ShearProny::new(g_inf, &terms).map_err(|e| Table::Shear.place("terms", e))?;
    let series_given = bulk.k_inf.is_some()
        || bulk.terms.is_some()
        || bulk.file.is_some()
        || bulk.instantaneous.is_some()
        || bulk.ratios.is_some();
    let forms: Vec<&str> = [
        ("incompressible", bulk.incompressible.is_some()),
        ("k_0", bulk.k_0.is_some()),
        ("poisson", bulk.poisson.is_some()),
        (
            "a relaxing bulk (k_inf/terms/file/instantaneous/ratios)",
            series_given,
        ),
    ]
    .iter()
    .filter(|(_, given)| *given)
    .map(|(name, _)| *name)
    .collect();
    if forms.len() != 1 {
        let found = if forms.is_empty() {
            "none".to_string()
        } else {
            forms.join(" and ")
        };
        return Err(scene_error(format!(
            "[material.bulk]: give exactly one of incompressible = true, k_0, poisson, k_inf with \
             terms or file, instantaneous with ratios; found {found}"
        )));
    }
    let rheology = if let Some(flag) = bulk.incompressible {
        if !flag {
            return Err(scene_error(
                "[material.bulk] incompressible = false: give k_0, poisson, or a relaxing bulk \
                 instead"
                    .into(),
            ));
        }
        BulkInput::Incompressible
    } else if let Some(k) = bulk.k_0 {
        BulkInput::Elastic(k)
    } else if let Some(nu) = bulk.poisson {
        // the key is `poisson`: check it under its name before the material checks `nu`
        let nu = crate::error::check("poisson", nu, nu > -1.0 && nu <= 0.5, "-1 < poisson <= 0.5")
            .map_err(|e| Table::Bulk.place("", e))?;
        BulkInput::Poisson(nu)
    } else {
        let (k_inf, terms) = series_of(
            Table::Bulk,
            &SeriesKeys {
                relaxed: bulk.k_inf,
                terms: &bulk.terms,
                file: &bulk.file,
                instantaneous: bulk.instantaneous,
                ratios: &bulk.ratios,
            },
            base,
        )?;
        if terms.is_empty() {
            // a relaxing bulk without a relaxing term is an elastic one
            return Err(scene_error(format!(
                "[material.bulk]: no relaxing term (terms = [] or ratios = []): an elastic bulk \
                 is k_0 = {k_inf:e} (Pa) instead of k_inf; or give at least one [k_j, theta_j]"
            )));
        }
        BulkInput::Prony(BulkProny::new(k_inf, &terms).map_err(|e| Table::Bulk.place("terms", e))?)
    };
    Material::general(shear, rheology).map_err(|e| Table::Bulk.place("terms", e))
}
