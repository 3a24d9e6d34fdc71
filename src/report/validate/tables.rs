//! The tables against the external SciPy reference and of the general-material and two-body
//! cases.

use rayon::prelude::*;

use crate::error::Result;
use crate::model::impact::{Groups, Impact};
use crate::solvers::theory;
use crate::solvers::{solve, SolveOptions, SolverKind};

// the report's building blocks, re-exported where the validation tables have always been
use crate::report::external::ExternalRow;
use crate::report::markdown::{fmt_err, fmt_val, Table};

use super::*;

/// The settings compared on the glassy corner table.
pub fn glassy_settings() -> Vec<SolverSetting> {
    [
        (SolverKind::Fast, 1e-6),
        (SolverKind::Fast, 1e-8),
        (SolverKind::Fast, 1e-10),
        (SolverKind::Reference, 1e-6),
        (SolverKind::Reference, 1e-8),
        (SolverKind::Reference, 1e-10),
    ]
    .into_iter()
    .map(|(solver, rtol)| SolverSetting {
        solver,
        rtol,
        work_limit: 0,
    })
    .collect()
}

/// Relative CoR, contact-time and maximum-indentation errors of a setting on every row of the
/// external table: (max, mean) per quantity, rows within rtol, rows refused.
pub fn external_comparison(
    setting: &SolverSetting,
    rows: &[ExternalRow],
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<String>> {
    let errs: Vec<Option<[f64; 3]>> = rows
        .par_iter()
        .map(|r| {
            let o = Groups::new(r.nu, r.p2, r.p3)
                .and_then(Impact::from_groups)
                .and_then(|imp| solve(&imp, &setting.options()));
            tick();
            o.ok().map(|o| {
                [
                    ((o.cor - r.cor) / r.cor).abs(),
                    ((o.contact_time - r.contact_time) / r.contact_time).abs(),
                    ((o.max_indentation - r.max_indentation) / r.max_indentation).abs(),
                ]
            })
        })
        .collect();
    let ok: Vec<[f64; 3]> = errs.iter().flatten().copied().collect();
    let stat = |k: usize| {
        let max = ok.iter().map(|e| e[k]).fold(0.0, f64::max);
        let mean = ok.iter().map(|e| e[k]).sum::<f64>() / ok.len().max(1) as f64;
        format!("{} / {}", fmt_err(max), fmt_err(mean))
    };
    Ok(vec![
        setting.label(),
        rows.len().to_string(),
        stat(0),
        stat(1),
        stat(2),
        format!(
            "{}/{}",
            ok.iter().filter(|e| e[0] <= setting.rtol).count(),
            ok.len()
        ),
        (errs.len() - ok.len()).to_string(),
    ])
}

/// Per general-material case: `G_eq` terms, the `G_eq` check against the Carson inversion, the
/// reference CoR and the errors of `fast` (rtol 1e-6, 1e-10) and `mdr` (rtol 1e-4).
pub fn general_table() -> Result<Table> {
    let mut t = Table::new(&[
        "case",
        "material",
        "G_eq terms",
        "G_eq check",
        "reference e (rtol 1e-10)",
        "fast rtol=1e-6",
        "fast rtol=1e-10",
        "mdr rtol=1e-4",
        "reduced vs unreduced",
    ]);
    let rows: Vec<Result<Vec<String>>> = crate::report::catalogue::general_entries()?
        .par_iter()
        .map(|case| {
            let material = &case.material;
            let imp = &case.impact;
            let g_eq = material.equivalent_relaxation()?;
            let (tau_min, tau_max) = case.time_range();
            let mut check: f64 = 0.0;
            for i in 0..=60 {
                let x = i as f64 / 60.0;
                let lo = 1e-3 * tau_min;
                let tt = lo * (1e6 * tau_max / tau_min).powf(x);
                let inv = theory::bromwich::equivalent_relaxation_at(material, tt)?;
                check = check.max(((g_eq.eval(tt) - inv) / inv).abs());
            }
            let opts = SolveOptions::with;
            let truth = solve(imp, &opts(SolverKind::Reference, 1e-10))?.cor;
            let err = |solver, rtol| match solve(imp, &opts(solver, rtol)) {
                Ok(o) => fmt_err((o.cor - truth) / truth),
                Err(e) => format!("refused: {}", short_error(&e.to_string())),
            };
            Ok(vec![
                case.id.to_string(),
                case.what.to_string(),
                g_eq.terms.len().to_string(),
                fmt_err(check),
                fmt_val(truth),
                err(SolverKind::Fast, 1e-6),
                err(SolverKind::Fast, 1e-10),
                err(SolverKind::Mdr, 1e-4),
                {
                    let p = imp.canonical_relaxation();
                    let reduced = crate::solvers::fast::impact(&p, 1e-6, false)?.cor;
                    let full = crate::solvers::fast::impact_unreduced(&p, 1e-6, false)?.cor;
                    fmt_err((reduced - full) / full)
                },
            ])
        })
        .collect();
    for r in rows {
        t.rows.push(r?);
    }
    Ok(t)
}

/// Per two-body case: `G_tot` terms, the reference CoR and the errors of `fast` (rtol 1e-6,
/// 1e-10) and `mdr` on the stacked networks (rtol 1e-4, 1e-6).
pub fn two_body_table() -> Result<Table> {
    let mut t = Table::new(&[
        "case",
        "collision",
        "G_tot terms",
        "reference e (rtol 1e-10)",
        "fast rtol=1e-6",
        "fast rtol=1e-10",
        "mdr rtol=1e-4",
        "mdr rtol=1e-6",
    ]);
    let rows: Vec<Result<Vec<String>>> = crate::report::catalogue::TWO_BODIES
        .par_iter()
        .map(|case| {
            let imp = case.impact()?;
            let opts = SolveOptions::with;
            let truth = solve(&imp, &opts(SolverKind::Reference, 1e-10))?.cor;
            let err = |solver, rtol| match solve(&imp, &opts(solver, rtol)) {
                Ok(o) => fmt_err((o.cor - truth) / truth),
                Err(e) => format!("refused: {}", short_error(&e.to_string())),
            };
            Ok(vec![
                case.id.to_string(),
                case.what.to_string(),
                imp.equivalent_relaxation().terms.len().to_string(),
                fmt_val(truth),
                err(SolverKind::Fast, 1e-6),
                err(SolverKind::Fast, 1e-10),
                err(SolverKind::Mdr, 1e-4),
                err(SolverKind::Mdr, 1e-6),
            ])
        })
        .collect();
    for r in rows {
        t.rows.push(r?);
    }
    Ok(t)
}

/// The empty table of [`external_comparison`] rows.
pub(super) fn external_table() -> Table {
    Table::new(&[
        "solver",
        "rows",
        "CoR error max / mean",
        "contact time error max / mean",
        "max indentation error max / mean",
        "CoR within rtol",
        "refused",
    ])
}
