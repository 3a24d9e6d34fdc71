//! Work-precision benchmark: time per impact against CoR error and force-history error, for
//! every solver over a sweep of requested accuracies, on one catalogue case per regime.
//!
//! Timing runs solve CoR-only (no histories), as a user asking for the CoR would, and report
//! the median over repeats; the errors are computed afterwards, outside the timed region,
//! against the reference solver at rtol 1e-11: the CoR, and the force at each of the solver's
//! history times (the reference's dense record evaluated there; the peak force for the scale
//! from its history on 40001 uniform times).

use std::fmt::Write as _;
use std::path::Path;

use crate::error::{Error, Result};
use crate::io::output::write_atomic;
use crate::model::impact::Outcome;
use crate::report::catalogue::{impact_case, Case};
use crate::solvers::{fast, theory};
use crate::solvers::{solve, SolveOptions, SolverKind};

mod baseline;
mod paired;
mod report;
mod scipy;
mod targets;
#[cfg(test)]
mod tests;
mod timing;

pub use baseline::*;
pub use paired::*;
pub use report::*;
pub use scipy::*;
pub use targets::*;
pub use timing::*;
/// One measured point of the work-precision diagram.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchPoint {
    /// Solver.
    pub solver: SolverKind,
    /// Requested rtol.
    pub rtol: f64,
    /// Catalogue case id.
    pub case: &'static str,
    /// Regime name.
    pub regime: &'static str,
    /// Median wall time per impact (s).
    pub median_seconds: f64,
    /// Repeats timed.
    pub repeats: usize,
    /// Relative CoR error against the reference.
    pub cor_error: f64,
    /// Max |F - F_ref| / max F_ref over the solver's history samples.
    pub force_error: f64,
    /// `false` for `fast`'s single unverified solve ([`crate::solvers::fast::impact_unverified`],
    /// the solver before the verification), `true` for every solver as the user calls it.
    pub verified: bool,
}

/// The accuracy sweep of each solver.
pub fn sweep(quick: bool) -> Vec<(SolverKind, Vec<f64>)> {
    if quick {
        return vec![
            (SolverKind::MdrEuler, vec![1e-2]),
            (SolverKind::Mdr, vec![1e-3]),
            (SolverKind::Reference, vec![1e-6]),
            (SolverKind::Fast, vec![1e-6]),
        ];
    }
    vec![
        (SolverKind::MdrEuler, vec![1e-2, 3e-3, 1e-3, 3e-4, 1e-4]),
        (SolverKind::Mdr, vec![1e-3, 1e-4, 1e-5, 1e-6, 1e-7]),
        (SolverKind::Reference, vec![1e-4, 1e-6, 1e-8, 1e-10]),
        (SolverKind::Fast, vec![1e-4, 1e-6, 1e-8, 1e-10]),
    ]
}

/// One case per regime.
pub fn cases(quick: bool) -> Vec<&'static Case> {
    let ids: &[&str] = if quick {
        &["dissipative-nu045"]
    } else {
        &[
            "elastic-slow-relaxation",
            "dissipative-nu045",
            "near-incompressible-nu049",
            "compressible-nu-09",
            "stiff-dissipative",
        ]
    };
    ids.iter().filter_map(|id| impact_case(id)).collect()
}

/// Max `|F - F_ref| / F_peak` over the solver's history samples, the reference evaluated at
/// exactly those times (its dense record: no interpolation, so stiff layers narrower than any
/// fixed sample grid are compared correctly); `F_peak` from the reference's uniform history.
fn force_error(
    o: &Outcome,
    prony: &crate::model::material::Prony,
    reference: &Outcome,
) -> Result<f64> {
    let (Some(h), Some(r)) = (o.history.as_ref(), reference.history.as_ref()) else {
        return Ok(f64::NAN);
    };
    let f_peak = r.force.iter().cloned().fold(0.0, f64::max);
    let at = theory::reference::impact_at(prony, REFERENCE_RTOL, &h.t)?;
    let Some(ra) = at.history.as_ref() else {
        return Ok(f64::NAN);
    };
    Ok(h.force
        .iter()
        .zip(&ra.force)
        .map(|(&f, &fr)| (f - fr).abs() / f_peak)
        .fold(0.0, f64::max))
}

/// Accuracy of the reference solves of the benchmark.
const REFERENCE_RTOL: f64 = 1e-11;

/// Run the benchmark. `tick` after every point.
pub fn run(quick: bool, budget: f64, tick: &dyn Fn()) -> Result<Vec<BenchPoint>> {
    let mut out = Vec::new();
    for case in cases(quick) {
        let imp = case.impact()?;
        let prony = imp.canonical_relaxation();
        let reference = theory::reference::impact_sampled(&prony, REFERENCE_RTOL, 40001)?;
        for (solver, rtols) in sweep(quick) {
            for rtol in rtols {
                let opts = SolveOptions {
                    solver,
                    rtol,
                    ..Default::default()
                };
                let mut cor = f64::NAN;
                let timed = median_time(budget, || {
                    cor = solve(&imp, &opts)?.cor;
                    Ok(())
                });
                let (median_seconds, repeats) = match timed {
                    Ok(x) => x,
                    Err(
                        Error::AccuracyNotReached { .. }
                        | Error::NotAsymptotic { .. }
                        | Error::WorkLimit { .. },
                    ) => {
                        tick();
                        continue;
                    }
                    Err(e) => return Err(e),
                };
                let with_history = solve(
                    &imp,
                    &SolveOptions {
                        history: true,
                        ..opts
                    },
                )?;
                out.push(BenchPoint {
                    solver,
                    rtol,
                    case: case.id,
                    regime: case.regime.name(),
                    median_seconds,
                    repeats,
                    cor_error: ((cor - reference.cor) / reference.cor).abs(),
                    force_error: force_error(&with_history, &prony, &reference)?,
                    verified: true,
                });
                if solver == SolverKind::Fast {
                    // the same solver without the verification, for the diagram
                    let mut one = f64::NAN;
                    let (median_seconds, repeats) = median_time(budget, || {
                        one = fast::impact_unverified(&prony, rtol, false)?.cor;
                        Ok(())
                    })?;
                    out.push(BenchPoint {
                        solver,
                        rtol,
                        case: case.id,
                        regime: case.regime.name(),
                        median_seconds,
                        repeats,
                        cor_error: ((one - reference.cor) / reference.cor).abs(),
                        force_error: f64::NAN,
                        verified: false,
                    });
                }
                tick();
            }
        }
    }
    Ok(out)
}

/// Units of progress of [`run`].
pub fn units(quick: bool) -> u64 {
    (cases(quick).len() * sweep(quick).iter().map(|s| s.1.len()).sum::<usize>()) as u64
}

/// Write the points as CSV.
pub fn write_csv(path: &Path, points: &[BenchPoint]) -> Result<()> {
    let mut s = String::from(
        "solver,rtol,case,regime,median_seconds,repeats,cor_error,force_error,verified\n",
    );
    for p in points {
        let _ = writeln!(
            s,
            "{},{:e},{},{},{:e},{},{:e},{:e},{}",
            p.solver,
            p.rtol,
            p.case,
            p.regime,
            p.median_seconds,
            p.repeats,
            p.cor_error,
            p.force_error,
            p.verified
        );
    }
    write_atomic(path, |w| {
        w.write_all(s.as_bytes()).map_err(|e| Error::io(path, e))
    })
}

/// Aggregate of one (solver, rtol) over the cases: geometric-mean median time, worst CoR error,
/// worst force error; `None` when the setting was refused on every case.
fn aggregate(points: &[BenchPoint], solver: SolverKind, rtol: f64) -> Option<(f64, f64, f64)> {
    aggregate_of(points, solver, rtol, true)
}

/// [`aggregate`] of the verified (`true`) or the unverified points.
fn aggregate_of(
    points: &[BenchPoint],
    solver: SolverKind,
    rtol: f64,
    verified: bool,
) -> Option<(f64, f64, f64)> {
    let sel: Vec<&BenchPoint> = points
        .iter()
        .filter(|p| p.solver == solver && p.rtol == rtol && p.verified == verified)
        .collect();
    if sel.is_empty() {
        return None;
    }
    let t = (sel.iter().map(|p| p.median_seconds.ln()).sum::<f64>() / sel.len() as f64).exp();
    let e = sel.iter().map(|p| p.cor_error).fold(0.0, f64::max);
    let f = sel.iter().map(|p| p.force_error).fold(0.0, f64::max);
    Some((t, e, f))
}

/// Log-log work-precision plot: per solver, the worst CoR error over the cases against the
/// median time per impact (geometric mean over the cases), one point per rtol.
pub fn plot(path: &Path, points: &[BenchPoint]) -> Result<()> {
    let mut series = Vec::new();
    for (solver, rtols) in sweep(false) {
        let mut pts = Vec::new();
        for rtol in rtols {
            if let Some((t, e, _)) = aggregate(points, solver, rtol) {
                pts.push((t.log10(), e.max(1e-16).log10()));
            }
        }
        if !pts.is_empty() {
            series.push((solver.name().to_string(), pts));
        }
        if solver == SolverKind::Fast {
            let one: Vec<(f64, f64)> = rtols_of(solver)
                .into_iter()
                .filter_map(|rtol| aggregate_of(points, solver, rtol, false))
                .map(|(t, e, _)| (t.log10(), e.max(1e-16).log10()))
                .collect();
            if !one.is_empty() {
                series.push(("fast, one solve (unverified)".to_string(), one));
            }
        }
    }
    crate::io::plot::line_chart_svg(
        path,
        "Work-precision: worst CoR error over the cases vs time per impact",
        "log10 median time per impact (s)",
        "log10 max relative CoR error",
        &series,
    )
}

/// The rtols of `solver`'s full sweep.
fn rtols_of(solver: SolverKind) -> Vec<f64> {
    sweep(false)
        .into_iter()
        .filter(|(k, _)| *k == solver)
        .flat_map(|(_, r)| r)
        .collect()
}

/// The cheapest `mdr-euler` and `fast` settings (geometric-mean median time, s) whose worst CoR
/// error over the cases is at most 1e-4: the comparison at equal accuracy.
fn cheapest_pair(points: &[BenchPoint]) -> Option<(f64, f64)> {
    let cheapest = |solver: SolverKind| {
        sweep(false)
            .into_iter()
            .filter(|(k, _)| *k == solver)
            .flat_map(|(_, rtols)| rtols)
            .filter_map(|rtol| aggregate(points, solver, rtol))
            .filter(|&(_, e, _)| e <= 1e-4)
            .map(|(t, _, _)| t)
            .fold(f64::INFINITY, f64::min)
    };
    let (euler, fast) = (cheapest(SolverKind::MdrEuler), cheapest(SolverKind::Fast));
    (euler.is_finite() && fast.is_finite()).then_some((euler, fast))
}

/// `mdr-euler` time over `fast` time at equal accuracy (the cheapest setting of each whose worst
/// CoR error over the cases is at most 1e-4), if both reached it.
pub fn speedup(points: &[BenchPoint]) -> Option<f64> {
    cheapest_pair(points).map(|(euler, fast)| euler / fast)
}
