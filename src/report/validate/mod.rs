//! The validation catalogue run: every solver against the independent theory, per regime, plus
//! limits, asymptotes and convergence orders. Produces the tables of VALIDATION.md (and the
//! insta snapshots reuse the same computations).
//!
//! Every number is formatted with a fixed number of significant digits, so the report is
//! reproducible on any machine running the same build: CI regenerates it and fails when the
//! committed file differs (`mdr-impact validate --check`).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::model::impact::{Groups, Impact, Outcome};
use crate::model::material::Prony;
use crate::report::catalogue::{Case, Regime, IMPACTS};
use crate::solvers::indentation::Prescribed;
use crate::solvers::mdr;
use crate::solvers::theory;
use crate::solvers::{canonical_material, solve, SolveOptions, SolverKind};

/// A refinement study: (elements, steps, relative error) per level.
pub type Refinement = Vec<(usize, usize, f64)>;

/// A solver setting under test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverSetting {
    /// The solver.
    pub solver: SolverKind,
    /// Requested rtol.
    pub rtol: f64,
    /// Work limit (element updates) for the MDR solvers.
    pub work_limit: u64,
}

impl SolverSetting {
    /// Label for tables, e.g. `mdr rtol=1e-4`.
    pub fn label(&self) -> String {
        format!("{} rtol={:.0e}", self.solver, self.rtol)
    }
    fn options(&self) -> SolveOptions {
        SolveOptions {
            solver: self.solver,
            rtol: self.rtol,
            work_limit: self.work_limit,
            ..Default::default()
        }
    }
}

/// The solver settings VALIDATION.md reports on.
pub fn settings() -> Vec<SolverSetting> {
    let s = |solver, rtol, work_limit| SolverSetting {
        solver,
        rtol,
        work_limit,
    };
    vec![
        s(SolverKind::MdrEuler, 1e-3, 400_000_000),
        s(SolverKind::Mdr, 1e-4, 4_000_000_000),
        s(SolverKind::Mdr, 1e-6, 4_000_000_000),
        s(SolverKind::Fast, 1e-6, 0),
        s(SolverKind::Fast, 1e-10, 0),
        s(SolverKind::Reference, 1e-8, 0),
    ]
}

/// Settings compared against the external tables (every row of both).
pub fn external_settings() -> Vec<SolverSetting> {
    vec![
        SolverSetting {
            solver: SolverKind::Mdr,
            rtol: 1e-4,
            work_limit: 4_000_000_000,
        },
        SolverSetting {
            solver: SolverKind::Fast,
            rtol: 1e-6,
            work_limit: 0,
        },
        SolverSetting {
            solver: SolverKind::Fast,
            rtol: 1e-10,
            work_limit: 0,
        },
        SolverSetting {
            solver: SolverKind::Reference,
            rtol: 1e-10,
            work_limit: 0,
        },
    ]
}

/// Requested rtol of the reference values all comparisons are made against.
pub const REFERENCE_RTOL: f64 = 1e-11;

/// Format a relative error with 2 significant digits (sign kept), or the error's name.
pub fn fmt_err(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.1e}")
    }
}

/// Format a value with 10 significant digits.
pub fn fmt_val(x: f64) -> String {
    format!("{x:.9e}")
}

/// A markdown table.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Table {
    /// Column headers.
    pub headers: Vec<String>,
    /// Rows of cells.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    fn new(headers: &[&str]) -> Self {
        Self {
            headers: headers.iter().map(|s| s.to_string()).collect(),
            rows: Vec::new(),
        }
    }
    /// Render as GitHub markdown.
    pub fn markdown(&self) -> String {
        let mut s = format!("| {} |\n", self.headers.join(" | "));
        s.push_str(&format!("|{}\n", " --- |".repeat(self.headers.len())));
        for r in &self.rows {
            s.push_str(&format!("| {} |\n", r.join(" | ")));
        }
        s
    }
}

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

fn short_error(e: &str) -> String {
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

/// One MDR-vs-theory comparison of a prescribed indentation.
#[derive(Debug, Clone, PartialEq)]
pub struct PrescribedComparison {
    /// Case id of the material.
    pub case: &'static str,
    /// History name.
    pub history: &'static str,
    /// Max |F_mdr - F_theory| / max F_theory over the samples.
    pub force_error: f64,
    /// Max |a_mdr - a_theory| / max a_theory.
    pub radius_error: f64,
    /// Separation time from theory (canonical units).
    pub separation_time: f64,
    /// Samples (t, F_theory, F_mdr) for plots.
    pub samples: Vec<(f64, f64, f64)>,
}

/// Canonical prescribed histories used for the force-for-force comparison: peak at `t = 1`,
/// peak depth 0.3 (R = 1).
pub fn prescribed_histories() -> Result<Vec<(&'static str, Prescribed)>> {
    Ok(vec![
        ("triangle", Prescribed::triangle(0.3, 1.0)?),
        ("half-sine", Prescribed::half_sine(0.3, 1.0)?),
    ])
}

/// MDR (displacement-driven, given resolution) against Lee–Radok/Ting on one material.
pub fn prescribed_comparison(
    case: &Case,
    history_name: &'static str,
    history: &Prescribed,
    res: mdr::indent::IndentResolution,
) -> Result<PrescribedComparison> {
    let prony = canonical_prony(case)?;
    let times: Vec<f64> = (0..=200)
        .map(|i| history.end_time() * i as f64 / 200.0)
        .collect();
    let th = theory::response(&prony, 1.0, history, &times)?;
    let md = mdr::indent::response(&prony, 1.0, history, &times, res)?;
    let f_peak = th.iter().map(|s| s.force).fold(0.0, f64::max);
    let a_peak = th.iter().map(|s| s.a).fold(0.0, f64::max);
    let mut fe: f64 = 0.0;
    let mut ae: f64 = 0.0;
    let mut samples = Vec::with_capacity(times.len());
    for (a, b) in th.iter().zip(&md) {
        fe = fe.max((a.force - b.force).abs() / f_peak);
        ae = ae.max((a.a - b.a).abs() / a_peak);
        samples.push((a.t, a.force, b.force));
    }
    Ok(PrescribedComparison {
        case: case.id,
        history: history_name,
        force_error: fe,
        radius_error: ae,
        separation_time: theory::separation_time(&prony, 1.0, history)?,
        samples,
    })
}

fn canonical_prony(case: &Case) -> Result<Prony> {
    Ok(case.impact()?.canonical_relaxation())
}

/// Observed orders from errors at successively doubled resolutions: `log2(e_i / e_{i+1})`.
pub fn observed_orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

/// Refinement study of the displacement-driven MDR against theory for one case: (elements,
/// steps, force error) with both doubled per level.
pub fn prescribed_refinement(
    case: &Case,
    history: &Prescribed,
    levels: usize,
) -> Result<Vec<(usize, usize, f64)>> {
    (0..levels)
        .map(|l| {
            let res = mdr::indent::IndentResolution {
                elements: 25 << l,
                steps: 50 << l,
            };
            let c = prescribed_comparison(case, "h", history, res)?;
            Ok((res.elements, res.steps, c.force_error))
        })
        .collect()
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

/// One row of the external reference table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExternalRow {
    /// Static Poisson ratio.
    pub nu: f64,
    /// `p2`.
    pub p2: f64,
    /// `p3`.
    pub p3: f64,
    /// CoR.
    pub cor: f64,
    /// Contact time (canonical).
    pub contact_time: f64,
    /// Maximum indentation (canonical).
    pub max_indentation: f64,
    /// The generator's own error estimate of the CoR (relative).
    pub est_rel_err: f64,
}

/// The external reference table, embedded at build time (`reference/external/cor_python.csv`):
/// a grid over the paper's range and beyond, and 100 random points.
pub const EXTERNAL_TABLE: &str = include_str!("../../reference/external/cor_python.csv");

/// Its second part (`reference/external/cor_python_corner.csv`): the most dissipative corner of
/// the range (CoR down to 5.5e-4), random points, its edge and the points where an earlier
/// `fast` missed its tolerance.
pub const EXTERNAL_CORNER_TABLE: &str =
    include_str!("../../reference/external/cor_python_corner.csv");

/// Its third part (`reference/external/cor_python_glassy.csv`), kept apart from the rows of
/// [`external_rows`]: the glassy corner, `p2` from 1.3e-8 to 1e-6 (`G_0 / G_inf` up to 8e7),
/// where a stress run found `fast` and `reference` disagreeing beyond rtol 1e-10.
pub const EXTERNAL_GLASSY_TABLE: &str =
    include_str!("../../reference/external/cor_python_glassy.csv");

/// The rows of [`EXTERNAL_GLASSY_TABLE`].
pub fn external_glassy_rows() -> Result<Vec<ExternalRow>> {
    parse_external(
        EXTERNAL_GLASSY_TABLE,
        "reference/external/cor_python_glassy.csv",
    )
}

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

const GLASSY_TEXT: &str = "\n### The glassy corner (external)\n\n\
`reference/external/cor_python_glassy.csv`: 26 rows with `p2` from 1.3e-8 to 1e-6 and `p3` from 98 to \
1e4 (CoR 3.2e-6 to 0.61), computed by the same SciPy generator (`cor_ref.py --glassy`, estimated accuracy \
1.0e-11 or better): the 19 rows where `mdr-impact stress` found `fast` and `reference` apart by more than \
rtol 1e-10 or 1e-11, the three rows where an earlier `fast` missed rtol 1e-6, the two glassy catalogue \
cases, and two rows where a second stress run found `reference` outside rtol 1e-8. The SciPy solution \
sides with `fast` on every row; the two runs of `reference` agreed there while both were off, so where \
`G_eq(0) / G_eq(inf) > 1e5` it accepts the difference of its runs only below `0.1 rtol` \
(`theory::REF_GLASSY_SAFETY`) and refuses requests with `rtol e` below 1e-12 \
(`theory::REF_GLASSY_ABS_FLOOR`). Errors at rtol 1e-10 include the table's own (up to 1.0e-11).\n\n";

/// Parse the external reference tables: the rows of [`EXTERNAL_TABLE`], then those of
/// [`EXTERNAL_CORNER_TABLE`].
pub fn external_rows() -> Result<Vec<ExternalRow>> {
    let mut out = parse_external(EXTERNAL_TABLE, "reference/external/cor_python.csv")?;
    out.extend(parse_external(
        EXTERNAL_CORNER_TABLE,
        "reference/external/cor_python_corner.csv",
    )?);
    Ok(out)
}

fn parse_external(table: &str, file: &str) -> Result<Vec<ExternalRow>> {
    let mut rdr = csv::Reader::from_reader(table.as_bytes());
    let mut out = Vec::new();
    for (i, rec) in rdr.records().enumerate() {
        let bad = |m: String| Error::Csv {
            file: file.into(),
            line: i as u64 + 2,
            message: m,
        };
        let rec = rec.map_err(|e| bad(e.to_string()))?;
        let mut v = [0.0; 7];
        for (j, x) in v.iter_mut().enumerate() {
            *x = rec
                .get(j)
                .and_then(|s| s.parse().ok())
                .ok_or_else(|| bad(format!("column {} is not a number", j + 1)))?;
        }
        out.push(ExternalRow {
            nu: v[0],
            p2: v[1],
            p3: v[2],
            cor: v[3],
            contact_time: v[4],
            max_indentation: v[5],
            est_rel_err: v[6],
        });
    }
    Ok(out)
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

const GENERAL_TEXT: &str = "Cases: `catalogue::GENERAL`, in canonical units (`m = R = v0 = 1`, \
relaxed shear modulus 1), shear terms log-spaced in time with `g_i ∝ tau_i^-0.3`; then the real polymers \
of `catalogue::POLYMERS`, published Prony series shipped as scenes (`scenes/polyisobutylene.toml`, \
`scenes/epoxy.toml`; each file cites its source), hit by the default scene's steel ball at 0.99 m/s. `fast` integrates `G_eq` \
as the exact Prony series of the Carson-domain composition (`material::carson`, poles by bracketing in \
`log(-s)`); the column *G_eq check* is its largest relative difference from the independent numerical \
inversion of the Carson formula (`theory::bromwich`, Talbot contour) at 61 times from `1e-3 tau_min` to \
`1e3 tau_max` (shortest and longest time of shear and bulk). Errors are relative CoR errors against `reference` at rtol 1e-10, a different integrator \
on `G_eq` derived by a third route that shares no code with `material::carson` (`theory::poles`: \
relaxation times as roots in the time domain by Brent's method; it agrees with `material::carson` to \
1e-15 on these materials and to 1e-11 on 128 random ones, `tests/rheology.rs`); `mdr` solves on an \
element network built from G and K themselves (a G branch in series with a K + G/3 branch, never from \
the `G_eq` poles). `fast` merges terms far outside the contact window into their limit forms when the \
bound of the merge is within a tenth of rtol (`fast::reduce`); the column *reduced vs unreduced* is \
the relative CoR difference of `fast` with and without that merge at rtol 1e-6. Re-run: \
`mdr-impact validate`.\n\n";

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

const TWO_BODY_TEXT: &str = "Cases: `catalogue::TWO_BODIES`, SI inputs. `fast` and `reference` solve \
the effective sphere (mass `m_A m_B / (m_A + m_B)`, radius `R_A R_B / (R_A + R_B)`) on the combined \
`G_tot` (`1/G_tot = 1/G_eq,A + 1/G_eq,B` in Carson form, an exact Prony series: `fast` from \
`material::carson::combine`, `reference` from the independent `theory::poles::series`); `mdr` never forms `G_tot`: each MDR element is body A's element \
network (built from its G and K) in series with body B's (`material::StackedNetwork`). Errors are \
relative CoR errors against `reference` at rtol 1e-10. The exact limits are pinned in \
`snapshots/two_bodies.snap` (`tests/two_bodies.rs`): a rigid wall as body B reproduces the one-sphere \
impact bit for bit with every solver, B 1e8 times stiffer moves the CoR by 1.4e-9, two identical \
bodies equal the one-body impact of mass `m/2`, radius `R/2` on half the moduli (to 2e-14 for `fast` \
and `reference`), swapping A and B changes the CoR by at most 1.3e-14. Re-run: `mdr-impact validate`; \
one case: `mdr-impact run scenes/two_spheres.toml`.\n\n";

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
fn external_table() -> Table {
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

/// Options of a validation run.
#[derive(Debug, Clone)]
pub struct ValidateOptions {
    /// Where figures go (relative paths in the markdown are taken from `markdown_dir`).
    pub figure_dir: PathBuf,
    /// Folder of the markdown file (for relative figure links).
    pub markdown_dir: PathBuf,
}

/// Run the whole validation and render VALIDATION.md. `tick` is called after every unit of
/// work (for a progress bar); `units()` says how many there are.
pub fn run(opts: &ValidateOptions, tick: &(dyn Fn() + Sync)) -> Result<String> {
    let settings = settings();
    let mut md = String::new();
    let w = |md: &mut String, s: &str| md.push_str(s);
    w(&mut md, HEADER);

    // 1. impacts
    let cmp = impact_comparisons(IMPACTS, &settings, tick)?;
    w(
        &mut md,
        "\n## 1. Coefficient of restitution, contact time and maximum force of the impact\n\n",
    );
    w(&mut md, IMPACT_TEXT);
    w(
        &mut md,
        "\n### Per regime (relative CoR error against the reference)\n\n",
    );
    w(&mut md, &impact_regime_table(&cmp, &settings).markdown());
    w(&mut md, "\n### Per case\n\n");
    w(&mut md, &impact_case_table(&cmp, &settings).markdown());
    tick();

    // 1b. external reference
    w(
        &mut md,
        "\n## 1b. Against the external reference table (computed outside the project)\n\n",
    );
    w(&mut md, EXTERNAL_TEXT);
    let mut t = external_table();
    let rows = external_rows()?;
    for s in external_settings() {
        t.rows.push(external_comparison(&s, &rows, tick)?);
    }
    w(&mut md, &t.markdown());
    w(&mut md, GLASSY_TEXT);
    let glassy = external_glassy_rows()?;
    let mut t = external_table();
    for s in glassy_settings() {
        t.rows.push(external_comparison(&s, &glassy, &|| {})?);
    }
    w(&mut md, &t.markdown());

    // 1c. general materials
    w(
        &mut md,
        "\n## 1c. General materials (Prony series in shear and bulk)\n\n",
    );
    w(&mut md, GENERAL_TEXT);
    w(&mut md, &general_table()?.markdown());

    // 1d. two bodies
    w(&mut md, "\n## 1d. Two bodies colliding\n\n");
    w(&mut md, TWO_BODY_TEXT);
    w(&mut md, &two_body_table()?.markdown());

    // 2. prescribed histories
    w(
        &mut md,
        "\n## 2. Force for force: MDR against Lee–Radok/Ting on prescribed indentations\n\n",
    );
    w(&mut md, PRESCRIBED_TEXT);
    let hist = prescribed_histories()?;
    let jobs: Vec<(&Case, &(&'static str, Prescribed))> = IMPACTS
        .iter()
        .flat_map(|c| hist.iter().map(move |h| (c, h)))
        .collect();
    let pcs: Vec<PrescribedComparison> = jobs
        .par_iter()
        .map(|(c, (name, h))| {
            let r = prescribed_comparison(c, name, h, Default::default());
            tick();
            r
        })
        .collect::<Result<_>>()?;
    let mut t = Table::new(&[
        "case",
        "regime",
        "history",
        "max abs(F_mdr - F_theory) / F_peak",
        "max abs(a_mdr - a_theory) / a_peak",
        "separation time (theory)",
    ]);
    for (p, (c, _)) in pcs.iter().zip(&jobs) {
        t.rows.push(vec![
            p.case.into(),
            c.regime.name().into(),
            p.history.into(),
            fmt_err(p.force_error),
            fmt_err(p.radius_error),
            fmt_val(p.separation_time),
        ]);
    }
    w(&mut md, &t.markdown());
    let mut per_regime = Table::new(&["regime", "max force error", "mean force error"]);
    for r in Regime::ALL {
        let e: Vec<f64> = pcs
            .iter()
            .zip(&jobs)
            .filter(|(_, (c, _))| c.regime == r)
            .map(|(p, _)| p.force_error)
            .collect();
        per_regime.rows.push(vec![
            r.name().into(),
            fmt_err(e.iter().cloned().fold(0.0, f64::max)),
            fmt_err(e.iter().sum::<f64>() / e.len().max(1) as f64),
        ]);
    }
    w(&mut md, "\nPer regime:\n\n");
    w(&mut md, &per_regime.markdown());
    // plots of a few force histories
    std::fs::create_dir_all(&opts.figure_dir).map_err(|e| Error::io(&opts.figure_dir, e))?;
    w(&mut md, "\n");
    for id in [
        "dissipative-nu045",
        "compressible-nu-09",
        "stiff-dissipative",
    ] {
        for p in pcs
            .iter()
            .filter(|p| p.case == id && p.history == "triangle")
        {
            let file = opts
                .figure_dir
                .join(format!("force-{}-{}.svg", p.case, p.history));
            crate::io::plot::line_chart_svg(
                &file,
                &format!("{} ({}): MDR vs Lee–Radok/Ting", p.case, p.history),
                "time t (canonical)",
                "force F (canonical)",
                &[
                    (
                        "Lee–Radok/Ting".into(),
                        p.samples.iter().map(|s| (s.0, s.1)).collect(),
                    ),
                    ("MDR".into(), p.samples.iter().map(|s| (s.0, s.2)).collect()),
                ],
            )?;
            let _ = writeln!(md, "![{id}]({})\n", rel(&file, &opts.markdown_dir));
        }
    }

    // 3. convergence
    w(&mut md, "\n## 3. Convergence orders of the MDR schemes\n\n");
    w(&mut md, CONVERGENCE_TEXT);
    let case = crate::report::catalogue::impact_case("dissipative-nu045")
        .ok_or(Error::Unsupported("catalogue".into()))?;
    let tri = Prescribed::triangle(0.3, 1.0)?;
    let studies: Vec<(&str, f64, Refinement)> = vec![
        (
            "prescribed triangle, mdr: elements and steps doubled",
            2.0,
            prescribed_refinement(case, &tri, 6)?,
        ),
        (
            "impact, mdr: steps doubled (4096 elements)",
            2.0,
            impact_refinement(case, mdr::Scheme::Exponential, Refine::Steps, (4096, 32), 5)?,
        ),
        (
            "impact, mdr: elements doubled (16384 steps)",
            2.0,
            impact_refinement(
                case,
                mdr::Scheme::Exponential,
                Refine::Elements,
                (16, 16384),
                5,
            )?,
        ),
        (
            "impact, mdr-euler: steps and elements doubled",
            1.0,
            impact_refinement(case, mdr::Scheme::Euler, Refine::Both, (64, 512), 5)?,
        ),
    ];
    tick();
    let mut t = Table::new(&[
        "study",
        "resolutions (elements x steps)",
        "errors",
        "observed orders",
        "theoretical",
    ]);
    let mut series = Vec::new();
    for (name, p, s) in &studies {
        let errs: Vec<f64> = s.iter().map(|x| x.2.abs()).collect();
        let orders = observed_orders(&errs);
        t.rows.push(vec![
            name.to_string(),
            s.iter()
                .map(|x| format!("{}x{}", x.0, x.1))
                .collect::<Vec<_>>()
                .join(", "),
            errs.iter()
                .map(|e| fmt_err(*e))
                .collect::<Vec<_>>()
                .join(", "),
            orders
                .iter()
                .map(|o| format!("{o:.2}"))
                .collect::<Vec<_>>()
                .join(", "),
            format!("{p}"),
        ]);
        series.push((
            name.to_string(),
            s.iter()
                .enumerate()
                .map(|(i, x)| (i as f64, x.2.abs().log10()))
                .collect::<Vec<_>>(),
        ));
    }
    w(&mut md, &t.markdown());
    w(&mut md, "\nPrescribed indentations on every catalogue material (elements x steps from 25x50 to 800x1600): \
average observed order of the force error over the last two doublings. Expected: 2 where the force density \
vanishes continuously at the contact edge; in the stiff regime relaxation is fast against the edge's motion \
across one element, the viscous part of the density jumps at the edge and the order tends to 1 (between 1 and \
2 at these resolutions).\n\n");
    let jobs: Vec<(&Case, &(&'static str, Prescribed))> = IMPACTS
        .iter()
        .flat_map(|c| hist.iter().map(move |h| (c, h)))
        .collect();
    let orders: Vec<(f64, f64)> = jobs
        .par_iter()
        .map(|(c, (_, h))| {
            let s = prescribed_refinement(c, h, 6)?;
            Ok(((s[3].2 / s[5].2).log2() / 2.0, s[5].2))
        })
        .collect::<Result<_>>()?;
    let mut t = Table::new(&[
        "case",
        "regime",
        "history",
        "observed order",
        "error at 800x1600",
    ]);
    for ((c, (name, _)), (p, e)) in jobs.iter().zip(&orders) {
        t.rows.push(vec![
            c.id.into(),
            c.regime.name().into(),
            name.to_string(),
            format!("{p:.2}"),
            fmt_err(*e),
        ]);
    }
    w(&mut md, &t.markdown());
    tick();
    let file = opts.figure_dir.join("convergence.svg");
    crate::io::plot::line_chart_svg(
        &file,
        "MDR refinement studies (dissipative-nu045)",
        "refinement level (resolution x 2 per level)",
        "log10 |relative error|",
        &series,
    )?;
    let _ = writeln!(md, "\n![convergence]({})\n", rel(&file, &opts.markdown_dir));

    // 4. limits
    w(&mut md, "\n## 4. Hertz limits\n\n");
    w(&mut md, HERTZ_TEXT);
    w(&mut md, &hertz_limit_table()?.markdown());
    tick();
    w(&mut md, "\n## 5. Incompressible limit\n\n");
    w(&mut md, INCOMPRESSIBLE_TEXT);
    let (t, _) = incompressible_limit_table(0.01, 1.0)?;
    w(&mut md, &t.markdown());
    tick();
    w(&mut md, "\n## 6. First-order asymptotes\n\n");
    w(&mut md, &asymptote_text()?);
    let (t, _) = asymptote_table()?;
    w(&mut md, &t.markdown());
    tick();
    w(&mut md, "\n## 7. Committed reference files\n\n");
    w(&mut md, REFERENCE_FILES_TEXT);
    for f in FILLED {
        w(&mut md, &f.placeholder());
    }
    Ok(md)
}

/// Units of progress `run` reports.
pub fn units() -> u64 {
    let hist = 2;
    let external = EXTERNAL_TABLE.lines().count().saturating_sub(1) * external_settings().len();
    (IMPACTS.len() * settings().len() + 1 + external + IMPACTS.len() * hist + 5) as u64
}

fn rel(file: &Path, base: &Path) -> String {
    file.strip_prefix(base)
        .unwrap_or(file)
        .display()
        .to_string()
}

/// Put the body of the section `begin` ... `end` of `existing` into `fresh` (unchanged when
/// either lacks the markers).
pub fn keep_section(fresh: &str, existing: &str, begin: &str, end: &str) -> String {
    match (
        existing.find(begin),
        existing.find(end),
        fresh.find(begin),
        fresh.find(end),
    ) {
        (Some(eb), Some(ee), Some(fb), Some(fe)) if eb < ee && fb < fe => {
            format!("{}{}{}", &fresh[..fb], &existing[eb..ee], &fresh[fe..])
        }
        _ => fresh.to_string(),
    }
}

/// Replace the body of the section `begin` ... `end` (called `name` in the error) of `existing`
/// with `section`.
pub fn replace_section(
    existing: &str,
    begin: &str,
    end: &str,
    name: &str,
    section: &str,
) -> Result<String> {
    match (existing.find(begin), existing.find(end)) {
        (Some(b), Some(e)) if b < e => Ok(format!(
            "{}{begin}\n{section}{}",
            &existing[..b],
            &existing[e..]
        )),
        _ => Err(Error::Unsupported(format!(
            "the report has no {name} markers ({begin} ... {end}); run `mdr-impact validate` first"
        ))),
    }
}

/// Strip the body of the section `begin` ... `end` (the markers' positions are kept).
pub fn without_section(s: &str, begin: &str, end: &str) -> String {
    match (s.find(begin), s.find(end)) {
        (Some(b), Some(e)) if b < e => format!("{}{}", &s[..b], &s[e..]),
        _ => s.to_string(),
    }
}

/// A section of VALIDATION.md that a command other than `validate` fills (its numbers are
/// machine dependent or take minutes): `validate` writes a placeholder for it, keeps the existing
/// body when it regenerates the file, and leaves it out of the staleness check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FilledSection {
    /// Marker key: the body sits between `<!-- KEY:begin -->` and `<!-- KEY:end -->`.
    pub key: &'static str,
    /// The section's heading (without `## `).
    pub heading: &'static str,
    /// The command that fills it.
    pub command: &'static str,
}

impl FilledSection {
    /// Marker opening the section.
    pub fn begin(&self) -> String {
        format!("<!-- {}:begin -->", self.key)
    }
    /// Marker closing the section.
    pub fn end(&self) -> String {
        format!("<!-- {}:end -->", self.key)
    }
    fn placeholder(&self) -> String {
        format!(
            "\n## {}\n\n{}\nRun `{}` to fill this section.\n{}\n",
            self.heading,
            self.begin(),
            self.command,
            self.end()
        )
    }
}

/// The stress section, filled by `mdr-impact stress`.
pub const STRESS: FilledSection = FilledSection {
    key: "stress",
    heading: "8. Stress test: every answer within rtol or refused",
    command: "mdr-impact stress",
};

/// The performance section, filled by `mdr-impact bench`.
pub const PERFORMANCE: FilledSection = FilledSection {
    key: "performance",
    heading: "9. Performance",
    command: "mdr-impact bench",
};

/// The Python package's timing against the command line, filled by `python/bench_cor.py`.
pub const PYTHON: FilledSection = FilledSection {
    key: "python",
    heading: "10. Python package: `cor` against `cor --input`",
    command: "python python/bench_cor.py --report VALIDATION.md",
};

/// The round trip of `fit`, filled by `mdr-impact fit-study`.
pub const FIT_STUDY: FilledSection = FilledSection {
    key: "fit-study",
    heading: "11. Fitting drop tests: round trip",
    command: "mdr-impact fit-study --reps 200 --report VALIDATION.md",
};

/// Every section filled by another command, in the order of the report.
pub const FILLED: &[FilledSection] = &[STRESS, PERFORMANCE, PYTHON, FIT_STUDY];

/// Keep the bodies of the sections that other commands fill ([`FILLED`]) when `fresh` replaces
/// `existing`.
pub fn keep_generated(fresh: &str, existing: &str) -> String {
    FILLED.iter().fold(fresh.to_string(), |acc, f| {
        keep_section(&acc, existing, &f.begin(), &f.end())
    })
}

/// Strip the bodies of the sections that other commands fill (for the staleness check).
pub fn without_generated(s: &str) -> String {
    FILLED.iter().fold(s.to_string(), |acc, f| {
        without_section(&acc, &f.begin(), &f.end())
    })
}

/// Replace the body of the filled section `f` of `existing` with `section`.
pub fn replace_filled(existing: &str, f: &FilledSection, section: &str) -> Result<String> {
    replace_section(existing, &f.begin(), &f.end(), f.key, section)
}

/// Replace the body of the performance section of `existing` with `section`.
pub fn replace_performance(existing: &str, section: &str) -> Result<String> {
    replace_filled(existing, &PERFORMANCE, section)
}

/// Replace the body of the stress section of `existing` with `section`.
pub fn replace_stress(existing: &str, section: &str) -> Result<String> {
    replace_filled(existing, &STRESS, section)
}

const HEADER: &str = "# Validation\n\n\
Generated by `mdr-impact validate` (this file and the figures in `validation/`); CI regenerates it with \
`mdr-impact validate --check` and fails when the committed file is stale. All quantities are in canonical \
units `m = R = v0 = G_inf = 1` (paper Eq. 11); errors are relative and rounded to two significant digits, \
so the file is identical on any machine that runs the same build.\n\n\
The references are independent of the MDR: the Lee–Radok/Ting theory (`src/solvers/theory/`), evaluated either by \
checked quadrature (prescribed indentations) or by the reference impact solver (exponential Radau \
collocation of the hereditary integrals, requested rtol 1e-11, its own error estimate below 1e-12 on the \
catalogue), closed forms (Hertz, Dawson's function for the triangle) and asymptotes derived in \
`src/solvers/theory/asymptotes.rs`. The catalogue (`src/report/catalogue.rs`) spans five regimes: elastic, dissipative, \
near-incompressible (nu >= 0.49), strongly compressible (nu <= 0) and stiff (relaxation time below 1e-3 of the \
contact time).\n";

const IMPACT_TEXT: &str = "Inputs: every catalogue case (table below), every solver setting. Reference: \
`--solver reference` at rtol 1e-11. Result: the relative error of the CoR `e`, the contact time `t_c` and the \
maximum force. `mdr-euler` is the paper's explicit Euler; where its stability bound `dt < 2 tau` makes the \
requested accuracy unaffordable within the work limit (4e8 element updates) it refuses with an error \
instead of returning an inaccurate number. Re-run: `mdr-impact validate`; single values: \
`mdr-impact cor --nu NU --p2 P2 --p3 P3 --solver S --rtol R`.\n";

const EXTERNAL_TEXT: &str = "Inputs: the 660 rows of `reference/external/cor_python.csv` (the full grid \
nu in {-0.9, -0.5, 0, 0.3, 0.45, 0.49, 0.499, 0.5} x log10 p2 in {-4..2} x log10 p3 in {-3..4}: 560 rows, the \
paper's range and beyond; and 100 random points), then the 105 rows of \
`reference/external/cor_python_corner.csv` (the most dissipative corner, log10 p2 in [-4, -2.5] x log10 p3 in \
[0.5, 2.3]: 60 random points, 16 on its edge nu -> -1, p2 = 1e-4, and 29 points with CoR < 0.002 where an earlier \
`fast` missed rtol 1e-6; CoR down to 5.5e-4). Reference: an independent SciPy solution of the Lee–Radok/Ting \
impact (implicit Radau and explicit DOP853 cross-checked, estimated accuracy 1.1e-12 or better; provenance and \
regeneration in `reference/external/README.md`). Relative errors, max / mean over all rows. Re-run: \
`mdr-impact validate`, or `cargo test --release --test external_reference -- --ignored`.\n\n";

const PRESCRIBED_TEXT: &str = "Inputs: the material of every catalogue case, a sphere of radius 1 pressed along a \
triangle (`d = 0.3 t` up to `t = 1`, then back) and a half-sine (`d = 0.3 sin(pi t / 2)`), 201 sample times \
over `[0, 2]`. Reference: Lee–Radok force in compression and Ting's `t_1` root in restitution by checked \
quadrature (`theory::response`, integrals to 1e-12 of their scale; the triangle agrees with its Dawson closed \
form to 1e-12). MDR: the foundation driven by the same `d(t)` (`mdr::indent`, 2000 elements across the \
maximum contact radius, 4000 steps). Re-run one curve: `mdr-impact indent --history triangle --rate 0.3 \
--peak-time 1 --radius 1 --g-inf 1 --g1 100 --eta 1 --nu 0.45 --solver mdr` (and `--solver theory`).\n\n";

const CONVERGENCE_TEXT: &str = "Errors against the reference (theory) as the MDR is refined; observed order \
`log2(err_i / err_(i+1))`. The tests (`tests/verification.rs`) assert the orders within 0.3 of the theory in \
the asymptotic range.\n\n";

const HERTZ_TEXT: &str = "Reference solver against the Hertz closed forms (`theory::hertz`, contact time \
`2.9432751843247047 d_max / v0`) with the effective modulus `E* = 4 G_eq` of the relaxed (`G_1 -> 0`, \
`eta -> 0`) or glassy (`eta -> inf`) state. The deviations shrink like the small parameter.\n\n";

const INCOMPRESSIBLE_TEXT: &str = "`p2 = 0.01`, `p3 = 1`: the CoR for `nu -> 0.5` against the incompressible \
solution (`nu = 0.5`, `K_0 = inf`), reference solver. The difference is first order in `0.5 - nu` (the \
equivalent relaxation function depends on `1/K_0` smoothly), so the rate per decade is 1.\n\n";

fn asymptote_text() -> Result<String> {
    Ok(format!(
        "Slow relaxation (`tau` much longer than the impact): `1 - e ≈ (4/9) t_c0 (-G_eq'(0)/G_eq(0))`, \
with `t_c0` the Hertz contact time of the glassy modulus. Kelvin–Voigt (`p2 -> 0` with `tau = p2 p3 -> 0`): \
`1 - e ≈ C k^(2/5) A`, `k = (16/3) c_inf`, `A = sum_k c_k tau_k / c_inf`, `C = 3 J (5/4)^(3/5) = {:.6}` with \
`J = (2/5) B(3/5, 3/2)` (derivation in `src/solvers/theory/asymptotes.rs`; for the incompressible case this is Ting's \
law `F = k (d + A d')^(3/2)` to first order, and `C / 1.5` is Brilliantov's 1.15344). The ratio tends to 1 \
as the small parameter goes to 0.\n\n",
        theory::asymptotes::kelvin_voigt_constant()?
    ))
}

const REFERENCE_FILES_TEXT: &str = "`reference/` holds nondimensional reference force histories (triangle: \
closed form; half-sine: quadrature; impacts: reference solver at rtol 1e-11) with `reference/manifest.toml` \
giving each file's case, parameters, generating command (`mdr-impact reference --out reference`), method \
and accuracy. `tests/theory_reference_files.rs` regenerates them and requires equality to 1e-9 of each \
column's scale.\n";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_sections_are_kept_and_ignored_by_the_check() {
        let (sb, se, pb, pe) = (
            STRESS.begin(),
            STRESS.end(),
            PERFORMANCE.begin(),
            PERFORMANCE.end(),
        );
        let fresh = format!("a\n{sb}\nrun stress\n{se}\nb\n{pb}\nrun bench\n{pe}\nc\n");
        let existing = format!("old a\n{sb}\nstress table\n{se}\nb\n{pb}\ntimes\n{pe}\nc\n");
        let kept = keep_generated(&fresh, &existing);
        assert_eq!(
            kept,
            format!("a\n{sb}\nstress table\n{se}\nb\n{pb}\ntimes\n{pe}\nc\n")
        );
        assert_eq!(without_generated(&kept), without_generated(&fresh));
        assert_ne!(without_generated(&existing), without_generated(&fresh));
        let replaced = replace_stress(&kept, "new\n").unwrap();
        assert!(replaced.contains(&format!("{sb}\nnew\n{se}")));
        assert_eq!(without_generated(&replaced), without_generated(&fresh));
        assert!(matches!(
            replace_stress("no markers", "x"),
            Err(Error::Unsupported(_))
        ));
    }
}
