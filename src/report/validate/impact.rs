//! Every solver setting on every catalogue impact against the reference solver: per case, per
//! regime, and refinement studies of the MDR schemes.

use rayon::prelude::*;

use crate::error::Result;
use crate::model::impact::Outcome;
use crate::report::catalogue::{Case, Regime};
use crate::solvers::mdr;
use crate::solvers::{canonical_material, solve, SolveOptions, SolverKind};

// the report's building blocks, re-exported where the validation tables have always been
use crate::report::markdown::{fmt_err, fmt_val, Table};

use super::*;

/// Comparison of one solver on one impact case against the reference.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactComparison {
    /// The case.
    pub case: Case,
    /// Solver setting.
    pub setting: SolverSetting,
    /// Reference outcome (canonical units).
    pub reference: Outcome,
    /// The solver's outcome, or its error message.
    pub outcome: std::result::Result<Outcome, String>,
}

impl ImpactComparison {
    /// Relative CoR error.
    pub fn cor_error(&self) -> Option<f64> {
        self.outcome
            .as_ref()
            .ok()
            .map(|o| (o.cor - self.reference.cor) / self.reference.cor)
    }
    /// Relative contact-time error.
    pub fn contact_time_error(&self) -> Option<f64> {
        self.outcome
            .as_ref()
            .ok()
            .map(|o| (o.contact_time - self.reference.contact_time) / self.reference.contact_time)
    }
    /// Relative maximum-force error.
    pub fn max_force_error(&self) -> Option<f64> {
        self.outcome
            .as_ref()
            .ok()
            .map(|o| (o.max_force - self.reference.max_force) / self.reference.max_force)
    }
}

/// Reference outcome of a case (canonical units).
pub fn reference_outcome(case: &Case) -> Result<Outcome> {
    let imp = case.impact()?;
    solve(
        &imp,
        &SolveOptions {
            solver: SolverKind::Reference,
            rtol: REFERENCE_RTOL,
            ..Default::default()
        },
    )
}

/// Run every setting on every catalogue impact case (in parallel).
pub fn impact_comparisons(
    cases: &[Case],
    settings: &[SolverSetting],
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<ImpactComparison>> {
    let refs: Vec<Outcome> = cases
        .par_iter()
        .map(reference_outcome)
        .collect::<Result<_>>()?;
    let jobs: Vec<(usize, usize)> = (0..cases.len())
        .flat_map(|i| (0..settings.len()).map(move |j| (i, j)))
        .collect();
    let out: Vec<ImpactComparison> = jobs
        .par_iter()
        .map(|&(i, j)| {
            let case = cases[i];
            let setting = settings[j];
            let outcome = case
                .impact()
                .and_then(|imp| solve(&imp, &setting.options()))
                .map_err(|e| e.to_string());
            tick();
            ImpactComparison {
                case,
                setting,
                reference: refs[i].clone(),
                outcome,
            }
        })
        .collect();
    Ok(out)
}

/// Per-case table: CoR, and for each setting its CoR / contact-time / max-force errors.
pub fn impact_case_table(cmp: &[ImpactComparison], settings: &[SolverSetting]) -> Table {
    let mut headers = vec![
        "case".to_string(),
        "regime".into(),
        "nu, p2, p3".into(),
        "reference e".into(),
    ];
    for s in settings {
        headers.push(format!("{}: e / t_c / F_max rel. error", s.label()));
    }
    let mut t = Table {
        headers,
        rows: Vec::new(),
    };
    let mut ids: Vec<&str> = cmp.iter().map(|c| c.case.id).collect();
    ids.dedup();
    for id in ids {
        let row_cmp: Vec<&ImpactComparison> = cmp.iter().filter(|c| c.case.id == id).collect();
        let c0 = row_cmp[0];
        let mut row = vec![
            id.to_string(),
            c0.case.regime.name().to_string(),
            format!("{}, {:e}, {:e}", c0.case.nu, c0.case.p2, c0.case.p3),
            fmt_val(c0.reference.cor),
        ];
        for s in settings {
            let c = row_cmp.iter().find(|c| c.setting == *s);
            row.push(match c {
                Some(c) => match (
                    &c.outcome,
                    c.cor_error(),
                    c.contact_time_error(),
                    c.max_force_error(),
                ) {
                    (Ok(_), Some(a), Some(b), Some(f)) => {
                        format!("{} / {} / {}", fmt_err(a), fmt_err(b), fmt_err(f))
                    }
                    (Err(e), ..) => format!("refused: {}", short_error(e)),
                    _ => "-".into(),
                },
                None => "-".into(),
            });
        }
        t.rows.push(row);
    }
    t
}

pub(super) fn short_error(e: &str) -> String {
    if e.contains("did not converge asymptotically") {
        "refinement not asymptotic".into()
    } else if e.contains("not supported") {
        "not supported".into()
    } else if e.contains("not reached") {
        "accuracy not reached within the work limit".into()
    } else if e.contains("work limit") {
        "work limit".into()
    } else {
        e.chars().take(60).collect()
    }
}

/// Per-regime summary: max and mean |relative CoR error| per setting, and how many met rtol.
pub fn impact_regime_table(cmp: &[ImpactComparison], settings: &[SolverSetting]) -> Table {
    let mut t = Table::new(&[
        "solver",
        "regime",
        "cases",
        "max rel. CoR error",
        "mean rel. CoR error",
        "within rtol",
        "refused",
    ]);
    for s in settings {
        for r in Regime::ALL {
            let sel: Vec<&ImpactComparison> = cmp
                .iter()
                .filter(|c| c.setting == *s && c.case.regime == r)
                .collect();
            if sel.is_empty() {
                continue;
            }
            let errs: Vec<f64> = sel
                .iter()
                .filter_map(|c| c.cor_error())
                .map(f64::abs)
                .collect();
            let refused = sel.len() - errs.len();
            let (max, mean) = if errs.is_empty() {
                ("-".to_string(), "-".to_string())
            } else {
                (
                    fmt_err(errs.iter().cloned().fold(0.0, f64::max)),
                    fmt_err(errs.iter().sum::<f64>() / errs.len() as f64),
                )
            };
            let within = errs.iter().filter(|&&e| e <= s.rtol).count();
            t.rows.push(vec![
                s.label(),
                r.name().into(),
                sel.len().to_string(),
                max,
                mean,
                format!("{within}/{}", errs.len()),
                refused.to_string(),
            ]);
        }
    }
    t
}

/// What a refinement study doubles per level.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refine {
    /// Time steps only (time order).
    Steps,
    /// Elements only (spacing order).
    Elements,
    /// Both.
    Both,
}

/// Impact refinement of an MDR scheme from the resolution `base` = (elements, steps), doubling
/// per level what `refine` says: relative CoR errors against the reference per level.
pub fn impact_refinement(
    case: &Case,
    scheme: mdr::Scheme,
    refine: Refine,
    base: (usize, usize),
    levels: usize,
) -> Result<Refinement> {
    let imp = case.impact()?;
    let mat = canonical_material(&imp)?;
    let layout = mdr::pilot(&mat.prony)?;
    let reference = reference_outcome(case)?.cor;
    (0..levels)
        .map(|l| {
            let (n, m) = match refine {
                Refine::Steps => (base.0, base.1 << l),
                Refine::Elements => (base.0 << l, base.1),
                Refine::Both => (base.0 << l, base.1 << l),
            };
            let o = mdr::run_resolution(scheme, &mat, &layout, n, m, false)?;
            Ok((n, m, (o.cor - reference) / reference))
        })
        .collect()
}
