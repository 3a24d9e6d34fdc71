//! Limits and asymptotes: Hertz (relaxed and glassy), the incompressible limit, slow relaxation
//! and Kelvin–Voigt.

use rayon::prelude::*;

use crate::error::Result;
use crate::model::impact::{Groups, Impact};
use crate::report::catalogue::{Case, Regime};
use crate::solvers::theory;
use crate::solvers::{solve, SolveOptions, SolverKind};

// the report's building blocks, re-exported where the validation tables have always been
use crate::report::markdown::{fmt_err, fmt_val, Table};

use super::*;

/// A row of the limit tables: parameter, e, relative contact-time and max-force deviation
/// from the Hertz limit.
pub fn hertz_limit_table() -> Result<Table> {
    let mut t = Table::new(&[
        "limit",
        "nu, p2, p3",
        "e (reference)",
        "1 - e",
        "t_c / t_Hertz - 1",
        "F_max / F_Hertz - 1",
        "Hertz modulus",
    ]);
    let cases: Vec<(&str, f64, f64, f64, bool)> = vec![
        ("G_1 -> 0", 0.3, 1e2, 1.0, false),
        ("G_1 -> 0", 0.3, 1e4, 1.0, false),
        ("G_1 -> 0", 0.3, 1e6, 1.0, false),
        ("eta -> 0", 0.3, 0.1, 1e-2, false),
        ("eta -> 0", 0.3, 0.1, 1e-4, false),
        ("eta -> 0", 0.3, 0.1, 1e-6, false),
        ("eta -> inf", 0.3, 0.1, 1e2, true),
        ("eta -> inf", 0.3, 0.1, 1e4, true),
        ("eta -> inf", 0.3, 0.1, 1e6, true),
    ];
    let rows: Vec<Vec<String>> = cases
        .par_iter()
        .map(|&(name, nu, p2, p3, glassy)| -> Result<Vec<String>> {
            let imp = Impact::from_groups(Groups::new(nu, p2, p3)?)?;
            let o = solve(
                &imp,
                &SolveOptions {
                    solver: SolverKind::Reference,
                    rtol: REFERENCE_RTOL,
                    ..Default::default()
                },
            )?;
            let prony = imp.canonical_relaxation();
            let g = if glassy {
                prony.glassy()
            } else {
                prony.relaxed
            };
            let h = theory::HertzImpact::canonical(4.0 * g)?;
            Ok(vec![
                name.into(),
                format!("{nu}, {p2:e}, {p3:e}"),
                fmt_val(o.cor),
                fmt_err(1.0 - o.cor),
                fmt_err(o.contact_time / h.contact_time() - 1.0),
                fmt_err(o.max_force / h.max_force() - 1.0),
                if glassy {
                    "glassy G_eq(0)".into()
                } else {
                    "relaxed G_eq(inf)".into()
                },
            ])
        })
        .collect::<Result<_>>()?;
    t.rows = rows;
    Ok(t)
}

/// Incompressible limit: `|e(nu) - e(0.5)| / e(0.5)` as `nu -> 0.5`, with the observed rate in
/// `0.5 - nu` per decade.
pub fn incompressible_limit_table(p2: f64, p3: f64) -> Result<(Table, Vec<f64>)> {
    let e_inc = reference_outcome(&Case {
        id: "inc",
        regime: Regime::Dissipative,
        nu: 0.5,
        p2,
        p3,
    })?
    .cor;
    let ks = [1, 2, 3, 4, 5, 6];
    let diffs: Vec<f64> = ks
        .par_iter()
        .map(|&k| {
            let nu = 0.5 - 10f64.powi(-k);
            let c = Case {
                id: "nu",
                regime: Regime::NearIncompressible,
                nu,
                p2,
                p3,
            };
            reference_outcome(&c).map(|o| (o.cor - e_inc) / e_inc)
        })
        .collect::<Result<_>>()?;
    let mut t = Table::new(&["0.5 - nu", "(e(nu) - e_inc) / e_inc", "observed rate"]);
    let mut rates = Vec::new();
    for (i, (&k, d)) in ks.iter().zip(&diffs).enumerate() {
        let rate = if i > 0 {
            let r = (diffs[i - 1] / d).log10();
            rates.push(r);
            format!("{r:.3}")
        } else {
            "-".into()
        };
        t.rows.push(vec![format!("1e-{k}"), fmt_err(*d), rate]);
    }
    t.rows.insert(
        0,
        vec![
            "0 (incompressible)".into(),
            format!("e_inc = {}", fmt_val(e_inc)),
            "-".into(),
        ],
    );
    Ok((t, rates))
}

/// Asymptote tables: slow relaxation and Kelvin–Voigt; ratio (1 - e) / prediction -> 1.
pub fn asymptote_table() -> Result<(Table, Vec<(String, f64)>)> {
    let mut rows: Vec<(&str, f64, f64, f64)> = Vec::new();
    for p3 in [1e2, 1e3, 1e4, 1e5] {
        rows.push(("slow relaxation", 0.45, 1.0, p3));
    }
    for p3 in [1e-2, 1e-3, 1e-4] {
        rows.push(("Kelvin-Voigt", 0.5, 1e-6, p3));
    }
    for p3 in [1e-2, 1e-3, 1e-4] {
        rows.push(("Kelvin-Voigt", 0.3, 1e-6, p3));
    }
    let out: Vec<(Vec<String>, (String, f64))> = rows
        .par_iter()
        .map(|&(name, nu, p2, p3)| -> Result<_> {
            let imp = Impact::from_groups(Groups::new(nu, p2, p3)?)?;
            let prony = imp.canonical_relaxation();
            let o = theory::impact(&prony, REFERENCE_RTOL, false)?;
            let pred = if name == "slow relaxation" {
                theory::asymptotes::slow_relaxation_loss(&prony)
            } else {
                theory::asymptotes::kelvin_voigt_loss(&prony)?
            };
            let ratio = (1.0 - o.cor) / pred;
            Ok((
                vec![
                    name.into(),
                    format!("{nu}, {p2:e}, {p3:e}"),
                    fmt_err(1.0 - o.cor),
                    fmt_err(pred),
                    format!("{ratio:.6}"),
                ],
                (format!("{name} nu={nu} p3={p3:e}"), ratio),
            ))
        })
        .collect::<Result<_>>()?;
    let mut t = Table::new(&[
        "asymptote",
        "nu, p2, p3",
        "1 - e (reference)",
        "prediction",
        "ratio",
    ]);
    let mut ratios = Vec::new();
    for (r, x) in out {
        t.rows.push(r);
        ratios.push(x);
    }
    Ok((t, ratios))
}
