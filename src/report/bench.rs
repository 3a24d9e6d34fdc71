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
use std::time::Instant;

use crate::error::{Error, Result};
use crate::io::output::write_atomic;
use crate::model::impact::Outcome;
use crate::report::catalogue::{impact_case, Case};
use crate::solvers::theory;
use crate::solvers::{solve, SolveOptions, SolverKind};

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

/// Median wall time of `f` over repeats: at least 3 (1 when a single run exceeds `budget`),
/// at most 101, stopping once `budget` seconds have been spent.
pub fn median_time(budget: f64, mut f: impl FnMut() -> Result<()>) -> Result<(f64, usize)> {
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < 101 {
        let t0 = Instant::now();
        f()?;
        times.push(t0.elapsed().as_secs_f64());
        let spent = start.elapsed().as_secs_f64();
        if spent > budget && (times.len() >= 3 || times.len() == 1) {
            break;
        }
    }
    times.sort_by(|a, b| a.total_cmp(b));
    Ok((times[times.len() / 2], times.len()))
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
                });
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
    let mut s =
        String::from("solver,rtol,case,regime,median_seconds,repeats,cor_error,force_error\n");
    for p in points {
        let _ = writeln!(
            s,
            "{},{:e},{},{},{:e},{},{:e},{:e}",
            p.solver,
            p.rtol,
            p.case,
            p.regime,
            p.median_seconds,
            p.repeats,
            p.cor_error,
            p.force_error
        );
    }
    write_atomic(path, |w| {
        w.write_all(s.as_bytes()).map_err(|e| Error::io(path, e))
    })
}

/// Aggregate of one (solver, rtol) over the cases: geometric-mean median time, worst CoR error,
/// worst force error; `None` when the setting was refused on every case.
fn aggregate(points: &[BenchPoint], solver: SolverKind, rtol: f64) -> Option<(f64, f64, f64)> {
    let sel: Vec<&BenchPoint> = points
        .iter()
        .filter(|p| p.solver == solver && p.rtol == rtol)
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
    }
    crate::io::plot::line_chart_svg(
        path,
        "Work-precision: worst CoR error over the cases vs time per impact",
        "log10 median time per impact (s)",
        "log10 max relative CoR error",
        &series,
    )
}

/// The performance section of VALIDATION.md (between the markers).
pub fn summary(
    points: &[BenchPoint],
    machine: &str,
    batch: Option<(usize, f64)>,
    timed: &[(TimedRows, Vec<RowTiming>)],
    general: &[GeneralTiming],
) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Measured by `mdr-impact bench` in one run on {machine}; times are medians over repeats \
         of a CoR-only solve (no histories), errors are against the reference solver at rtol 1e-11 \
         (outside the timed region). Data: [`validation/bench.csv`](validation/bench.csv); \
         plot: `validation/work-precision.svg`. Machine-dependent, so not part of the staleness check. \
         Re-run: `cargo run --release -- bench --batch-rows 100000` (under two minutes on this machine).\n"
    );
    let _ = writeln!(s, "![work-precision](validation/work-precision.svg)\n");
    let _ = writeln!(
        s,
        "| solver | rtol | median time per impact (geometric mean over cases) | max CoR error | max force error / F_peak |\n| --- | --- | --- | --- | --- |"
    );
    for (solver, rtols) in sweep(false) {
        for rtol in rtols {
            match aggregate(points, solver, rtol) {
                Some((t, e, f)) => {
                    let _ = writeln!(
                        s,
                        "| {solver} | {rtol:.0e} | {} | {e:.1e} | {f:.1e} |",
                        fmt_time(t)
                    );
                }
                None => {
                    let _ = writeln!(
                        s,
                        "| {solver} | {rtol:.0e} | refused (work limit) | - | - |"
                    );
                }
            }
        }
    }
    if let Some((euler, fast)) = cheapest_pair(points) {
        let _ = writeln!(
            s,
            "\nAt equal accuracy (worst CoR error over the cases at most 1e-4, cheapest setting of each): \
             `mdr-euler` {} against `fast` {}, a ratio of {:.0}.",
            fmt_time(euler),
            fmt_time(fast),
            euler / fast
        );
    }
    for (kind, rows) in timed {
        let _ = writeln!(s, "\n{}\n", kind.intro(rows.len()));
        s.push_str(&timing_table(rows, *kind));
    }
    if !general.is_empty() {
        let random = random_rows_of(timed);
        let _ = writeln!(
            s,
            "\n`fast` at rtol 1e-6 on the general materials of VALIDATION.md section 1c (one core, \
             CoR only), each beside the standard solid of the random sample in the same CoR group; \
             the ratio is of the median times:\n"
        );
        s.push_str(&general_timing_table(general, random));
    }
    if let Some((rows, secs)) = batch {
        let _ = writeln!(
            s,
            "\n`mdr-impact cor --input` path (`batch::solve_rows`, default solver and rtol 1e-6, all cores): \
             {rows} random rows of the paper's range in {secs:.2} s."
        );
    }
    if !timed.is_empty() {
        let random = random_rows_of(timed);
        s.push('\n');
        s.push_str(&targets(
            timed,
            speedup(points),
            batch,
            &general_targets(general, random),
        ));
    }
    s
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

/// Design targets of `fast` (checked by [`targets`]): median CoR-only time per impact in every
/// group of [`timing_groups`] at rtol 1e-6 and 1e-10 (s).
pub const TARGET_MEDIAN_SECONDS: [f64; 2] = [20e-6, 200e-6];
/// Design target: `mdr-euler` time over `fast` time at equal CoR error (at most 1e-4).
pub const TARGET_SPEEDUP: f64 = 1000.0;
/// Design target: `cor --input` rows at rtol 1e-6 and the wall time allowed for them (s).
pub const TARGET_BATCH: (usize, f64) = (100_000, 2.0);

/// A list stating which design targets this run met and which it did not (with the measured
/// values): [`TARGET_MEDIAN_SECONDS`] per group of rows, [`TARGET_SPEEDUP`] and
/// [`TARGET_BATCH`] (when measured).
pub fn targets(
    timed: &[(TimedRows, Vec<RowTiming>)],
    speedup: Option<f64>,
    batch: Option<(usize, f64)>,
    general: &[String],
) -> String {
    let mut parts = Vec::new();
    for (kind, rows) in timed {
        let stats = group_stats(rows);
        for (k, (&rtol, &limit)) in TIMING_RTOLS.iter().zip(&TARGET_MEDIAN_SECONDS).enumerate() {
            let missed: Vec<String> = stats
                .iter()
                .filter(|g| g.median[k] > limit)
                .map(|g| format!("{} ({})", g.name, fmt_time(g.median[k])))
                .collect();
            let verdict = if missed.is_empty() {
                format!("met in all {} groups", stats.len())
            } else {
                format!(
                    "met in {} of {} groups, **not met** in {}",
                    stats.len() - missed.len(),
                    stats.len(),
                    missed.join(", ")
                )
            };
            parts.push(format!(
                "median at most {} at rtol {rtol:.0e} on the {}: {verdict}",
                fmt_time(limit),
                kind.title()
            ));
        }
    }
    if let Some(x) = speedup {
        let verdict = if x >= TARGET_SPEEDUP {
            "met"
        } else {
            "**not met**"
        };
        parts.push(format!(
            "at least {TARGET_SPEEDUP:.0}x less time than `mdr-euler` at equal CoR error: {verdict} ({x:.0}x)"
        ));
    }
    if let Some((n, secs)) = batch {
        let (want, limit) = TARGET_BATCH;
        if n >= want {
            let verdict = if secs <= limit { "met" } else { "**not met**" };
            parts.push(format!(
                "{want} rows through `cor --input` in at most {limit} s: {verdict} ({n} rows in {secs:.2} s)"
            ));
        }
    }
    parts.extend(general.iter().cloned());
    let mut s = String::from("Design targets of `fast`, checked in this run:\n\n");
    for p in parts {
        let _ = writeln!(s, "- {p}.");
    }
    s
}

/// Which rows a timing table describes ([`external_timing`] or [`random_timing`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TimedRows {
    /// The rows of the external reference tables, errors against their reference CoR.
    External,
    /// A random sample of the paper's range, differences from the rtol 1e-10 solve.
    Random,
}

impl TimedRows {
    /// Both sets, in the order the benchmark times them.
    pub const ALL: [TimedRows; 2] = [TimedRows::External, TimedRows::Random];

    /// Number of rows of the set.
    pub fn rows(self) -> Result<usize> {
        Ok(match self {
            TimedRows::External => crate::report::validate::external_rows()?.len(),
            TimedRows::Random => RANDOM_ROWS,
        })
    }

    /// Time `fast` on the set ([`external_timing`] or [`random_timing`]); `tick` after every
    /// row of every pass.
    pub fn time(self, tick: &dyn Fn()) -> Result<Vec<RowTiming>> {
        match self {
            TimedRows::External => external_timing(tick),
            TimedRows::Random => random_timing(RANDOM_ROWS, RANDOM_SEED, tick),
        }
    }

    /// File name of the per-row CSV (in the benchmark's output directory).
    pub fn csv_name(self) -> &'static str {
        match self {
            TimedRows::External => "bench_external.csv",
            TimedRows::Random => "bench_random.csv",
        }
    }

    /// The paragraph before the set's table in VALIDATION.md, for `n` rows.
    fn intro(self, n: usize) -> String {
        let data = format!("[`validation/{0}`](validation/{0})", self.csv_name());
        match self {
            TimedRows::External => format!(
                "`fast` on every row of the external tables (the paper's range and its most \
                 dissipative corner; one core, CoR only, median of {TIMING_REPEATS} solves per \
                 row, one per pass over all rows; steps / evaluations: the mean attempted steps \
                 and force and history evaluations of one solve, which do not depend on the \
                 machine; data: {data}):"
            ),
            TimedRows::Random => format!(
                "The same on {n} random groups of the paper's range (`nu` uniform in \
                 `(-0.99, 0.5]`, `p2` and `p3` log-uniform; seed {RANDOM_SEED}), where each \
                 regime has its share of the range; grouped by the CoR at rtol 1e-10, no \
                 reference (data: {data}):"
            ),
        }
    }

    /// First column of the Markdown table.
    fn title(self) -> &'static str {
        match self {
            TimedRows::External => "rows of the external tables",
            TimedRows::Random => "random rows of the paper's range",
        }
    }

    /// Header of the error columns.
    fn error_header(self) -> &'static str {
        match self {
            TimedRows::External => "max CoR error",
            TimedRows::Random => "max CoR difference from rtol 1e-10",
        }
    }

    /// CSV column of the CoR the errors are taken against.
    fn cor_column(self) -> &'static str {
        match self {
            TimedRows::External => "cor_reference",
            TimedRows::Random => "cor_rtol_1e-10",
        }
    }
}

/// Time and error of `fast` on one timed row (of the external tables or the random sample, see
/// [`TimedRows`]), at rtol 1e-6 and 1e-10.
#[derive(Debug, Clone, PartialEq)]
pub struct RowTiming {
    /// The row: groups, and the CoR the errors are taken against (the reference, or for the
    /// random sample the CoR at rtol 1e-10).
    pub row: crate::report::validate::ExternalRow,
    /// Median wall time per impact (s) at rtol 1e-6 and 1e-10.
    pub seconds: [f64; 2],
    /// Relative CoR error against `row.cor` at rtol 1e-6 and 1e-10 (NaN without a reference).
    pub cor_error: [f64; 2],
    /// Attempted steps of one solve at rtol 1e-6 and 1e-10 (`Work::steps`; the same on every
    /// repeat: the solver is deterministic).
    pub steps: [u64; 2],
    /// Force and history evaluations of one solve at rtol 1e-6 and 1e-10 (`Work::evaluations`).
    pub evaluations: [u64; 2],
}

/// The two accuracies of [`RowTiming`].
pub const TIMING_RTOLS: [f64; 2] = [1e-6, 1e-10];

/// Repeats per row and accuracy in [`external_timing`] and [`random_timing`] (the median is kept),
/// one per pass over all rows.
pub const TIMING_REPEATS: usize = 5;

/// Time `fast` (CoR only, one core) on every row of the external tables (`validate::external_rows`):
/// the median of [`TIMING_REPEATS`] solves per row and accuracy, taken in as many passes over
/// all rows. On a shared machine a slow period then spreads over every group of rows instead of
/// slowing the rows timed during it (with the repeats of a row back to back, two runs of
/// nearly the same code minutes apart gave 23.7 and 17.2 µs for the rows with `nu < 0`).
/// `tick` after every row of every pass.
pub fn external_timing(tick: &dyn Fn()) -> Result<Vec<RowTiming>> {
    let rows = crate::report::validate::external_rows()?;
    let timed = time_rows(&rows, tick)?;
    Ok(rows
        .into_iter()
        .zip(timed)
        .map(|(row, t)| {
            let cor_error = t.cor.map(|c| ((c - row.cor) / row.cor).abs());
            t.timing(row, cor_error)
        })
        .collect())
}

/// Rows of the random sample of the paper's range timed by [`random_timing`].
pub const RANDOM_ROWS: usize = 5000;

/// Seed of that sample (`batch::random_rows`).
pub const RANDOM_SEED: u64 = 7;

/// Time `fast` as [`external_timing`] does on `n` random groups of the paper's range
/// (`batch::random_rows`: `nu` uniform in `(-0.99, 0.5]`, `p2` and `p3` log-uniform in
/// `[1e-4, 1e2]` and `[1e-3, 1e4]`), a sample in which each regime has its share of the range
/// (the external tables hold many rows of the most dissipative corner). No reference: `row.cor`
/// is the CoR at rtol 1e-10 (within 5.0e-10 of the reference solver on 5000 random groups, see
/// [`crate::solvers::fast`]), `cor_error[0]` the difference of the rtol 1e-6 CoR from it, `cor_error[1]`
/// NaN.
pub fn random_timing(n: usize, seed: u64, tick: &dyn Fn()) -> Result<Vec<RowTiming>> {
    let rows: Vec<crate::report::validate::ExternalRow> = crate::apps::batch::random_rows(n, seed)?
        .iter()
        .map(|r| crate::report::validate::ExternalRow {
            nu: r.groups.nu,
            p2: r.groups.p2,
            p3: r.groups.p3,
            cor: f64::NAN,
            contact_time: f64::NAN,
            max_indentation: f64::NAN,
            est_rel_err: f64::NAN,
        })
        .collect();
    let timed = time_rows(&rows, tick)?;
    Ok(rows
        .into_iter()
        .zip(timed)
        .map(|(row, t)| {
            let cor = t.cor[1];
            let cor_error = [((t.cor[0] - cor) / cor).abs(), f64::NAN];
            t.timing(
                crate::report::validate::ExternalRow { cor, ..row },
                cor_error,
            )
        })
        .collect())
}

/// What [`time_rows`] measured on one row at each accuracy of [`TIMING_RTOLS`].
struct Timed {
    seconds: [f64; 2],
    cor: [f64; 2],
    steps: [u64; 2],
    evaluations: [u64; 2],
}

impl Timed {
    /// The [`RowTiming`] of `row` with the given CoR errors.
    fn timing(self, row: crate::report::validate::ExternalRow, cor_error: [f64; 2]) -> RowTiming {
        RowTiming {
            row,
            seconds: self.seconds,
            cor_error,
            steps: self.steps,
            evaluations: self.evaluations,
        }
    }
}

/// The timing loop of [`external_timing`] and [`random_timing`]: [`TIMING_REPEATS`] passes
/// over all rows, each solving every row at each accuracy; the median time per row and accuracy.
fn time_rows(rows: &[crate::report::validate::ExternalRow], tick: &dyn Fn()) -> Result<Vec<Timed>> {
    let pronys = rows
        .iter()
        .map(|row| {
            Ok(
                crate::model::impact::Impact::from_groups(crate::model::impact::Groups::new(
                    row.nu, row.p2, row.p3,
                )?)?
                .canonical_relaxation(),
            )
        })
        .collect::<Result<Vec<_>>>()?;
    let mut times = vec![[Vec::new(), Vec::new()]; rows.len()];
    let mut out: Vec<Timed> = (0..rows.len())
        .map(|_| Timed {
            seconds: [f64::NAN; 2],
            cor: [f64::NAN; 2],
            steps: [0; 2],
            evaluations: [0; 2],
        })
        .collect();
    for _ in 0..TIMING_REPEATS {
        for (i, prony) in pronys.iter().enumerate() {
            for (k, &rtol) in TIMING_RTOLS.iter().enumerate() {
                let t0 = Instant::now();
                let o = crate::solvers::fast::impact(prony, rtol, false)?;
                times[i][k].push(t0.elapsed().as_secs_f64());
                out[i].cor[k] = o.cor;
                out[i].steps[k] = o.work.steps;
                out[i].evaluations[k] = o.work.evaluations;
            }
            tick();
        }
    }
    for (t, o) in times.iter_mut().zip(&mut out) {
        for k in 0..2 {
            t[k].sort_by(|a, b| a.total_cmp(b));
            o.seconds[k] = t[k][t[k].len() / 2];
        }
    }
    Ok(out)
}

/// Groups of rows reported by [`timing_table`]: name and membership.
#[allow(clippy::type_complexity)]
pub fn timing_groups() -> Vec<(
    &'static str,
    fn(&crate::report::validate::ExternalRow) -> bool,
)> {
    let [(elastic, _), (dissipative, _), (strongly, _)] = cor_groups();
    vec![
        ("all rows", |_| true),
        (elastic, |r| cor_groups()[0].1(r.cor)),
        (dissipative, |r| cor_groups()[1].1(r.cor)),
        (strongly, |r| cor_groups()[2].1(r.cor)),
        ("strongly compressible (nu < 0)", |r| r.nu < 0.0),
        ("near-incompressible (nu >= 0.45)", |r| r.nu >= 0.45),
        ("stiff (tau = p2 p3 <= 1e-3)", |r| r.p2 * r.p3 <= 1e-3),
    ]
}

/// Membership of a CoR group: the CoR alone decides.
pub type CorGroup = (&'static str, fn(f64) -> bool);

/// The groups of [`timing_groups`] that split the rows by their CoR alone.
pub fn cor_groups() -> [CorGroup; 3] {
    [
        ("nearly elastic (e >= 0.9)", |e| e >= 0.9),
        ("dissipative (0.1 <= e < 0.9)", |e| (0.1..0.9).contains(&e)),
        ("strongly dissipative (e < 0.1)", |e| e < 0.1),
    ]
}

/// Write the per-row timings as CSV.
pub fn write_timing_csv(path: &Path, rows: &[RowTiming], kind: TimedRows) -> Result<()> {
    write_atomic(path, |w| {
        let mut c = csv::Writer::from_writer(w);
        let io = |e: csv::Error| Error::io(path, e);
        c.write_record([
            "nu",
            "p2",
            "p3",
            kind.cor_column(),
            "seconds_rtol_1e-6",
            "cor_error_rtol_1e-6",
            "seconds_rtol_1e-10",
            "cor_error_rtol_1e-10",
            "steps_rtol_1e-6",
            "evaluations_rtol_1e-6",
            "steps_rtol_1e-10",
            "evaluations_rtol_1e-10",
        ])
        .map_err(io)?;
        for t in rows {
            c.write_record(
                [
                    t.row.nu,
                    t.row.p2,
                    t.row.p3,
                    t.row.cor,
                    t.seconds[0],
                    t.cor_error[0],
                    t.seconds[1],
                    t.cor_error[1],
                ]
                .map(|x| format!("{x:e}"))
                .into_iter()
                .chain(
                    [t.steps[0], t.evaluations[0], t.steps[1], t.evaluations[1]]
                        .map(|n| n.to_string()),
                ),
            )
            .map_err(io)?;
        }
        c.flush().map_err(|e| Error::io(path, e))
    })
}

/// One group of [`timing_groups`]: its rows' median time, worst CoR error and mean work at
/// each accuracy of [`TIMING_RTOLS`].
struct GroupStats {
    name: &'static str,
    n: usize,
    median: [f64; 2],
    max_error: [f64; 2],
    steps: [f64; 2],
    evaluations: [f64; 2],
}

/// [`GroupStats`] of every group of [`timing_groups`] that has rows.
fn group_stats(rows: &[RowTiming]) -> Vec<GroupStats> {
    let mut out = Vec::new();
    for (name, member) in timing_groups() {
        let sel: Vec<&RowTiming> = rows.iter().filter(|t| member(&t.row)).collect();
        if sel.is_empty() {
            continue;
        }
        let n = sel.len() as f64;
        let median = |k: usize| {
            let mut v: Vec<f64> = sel.iter().map(|t| t.seconds[k]).collect();
            v.sort_by(|a, b| a.total_cmp(b));
            v[v.len() / 2]
        };
        // NaN (no reference) when no row has one
        let max_err = |k: usize| sel.iter().map(|t| t.cor_error[k]).fold(f64::NAN, f64::max);
        let steps = |k: usize| sel.iter().map(|t| t.steps[k] as f64).sum::<f64>() / n;
        let evals = |k: usize| sel.iter().map(|t| t.evaluations[k] as f64).sum::<f64>() / n;
        out.push(GroupStats {
            name,
            n: sel.len(),
            median: [median(0), median(1)],
            max_error: [max_err(0), max_err(1)],
            steps: [steps(0), steps(1)],
            evaluations: [evals(0), evals(1)],
        });
    }
    out
}

/// Markdown table: per group, rows, and at each accuracy the median time, the max CoR error and
/// the mean work of a solve (attempted steps / force and history evaluations; machine
/// independent, unlike the times).
pub fn timing_table(rows: &[RowTiming], kind: TimedRows) -> String {
    let err = kind.error_header();
    let mut s = format!(
        "| {} | n | rtol 1e-6: median time | {err} | steps / evaluations | rtol 1e-10: median time | {err} | steps / evaluations |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n",
        kind.title()
    );
    for g in group_stats(rows) {
        let cols: Vec<String> = (0..2)
            .map(|k| {
                let e = g.max_error[k];
                let e = if e.is_nan() {
                    "-".to_string()
                } else {
                    format!("{e:.1e}")
                };
                format!(
                    "{} | {e} | {:.1} / {:.0}",
                    fmt_time(g.median[k]),
                    g.steps[k],
                    g.evaluations[k]
                )
            })
            .collect();
        let _ = writeln!(s, "| {} | {} | {} | {} |", g.name, g.n, cols[0], cols[1]);
    }
    s
}

/// Human time.
pub fn fmt_time(t: f64) -> String {
    if t < 1e-3 {
        format!("{:.1} µs", t * 1e6)
    } else if t < 1.0 {
        format!("{:.2} ms", t * 1e3)
    } else {
        format!("{t:.2} s")
    }
}

/// Machine description (CPU model and core count) for the report.
pub fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|x| x.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!("{cpu}, {cores} cores")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::validate::ExternalRow;

    fn timing(cor: f64, steps: [u64; 2], evaluations: [u64; 2]) -> RowTiming {
        RowTiming {
            row: ExternalRow {
                nu: 0.3,
                p2: 1.0,
                p3: 1.0,
                cor,
                contact_time: 1.0,
                max_indentation: 0.5,
                est_rel_err: 1e-12,
            },
            seconds: [1e-5, 5e-5],
            cor_error: [1e-7, 1e-11],
            steps,
            evaluations,
        }
    }

    #[test]
    fn timing_table_reports_mean_work_per_group() {
        let rows = [
            timing(0.95, [10, 40], [60, 300]),
            timing(0.05, [30, 90], [200, 700]),
            timing(0.04, [20, 70], [100, 500]),
        ];
        let table = timing_table(&rows, TimedRows::External);
        // means over the group's rows: (10+30+20)/3 = 20 steps, (60+200+100)/3 = 120 evaluations
        for (row, cell) in [
            ("| all rows | 3 |", "| 20.0 / 120 |"),
            ("| all rows | 3 |", "| 66.7 / 500 |"),
            ("| strongly dissipative", "| 25.0 / 150 |"),
            ("| nearly elastic", "| 10.0 / 60 |"),
        ] {
            assert!(line_of(&table, row).contains(cell), "{cell} in\n{table}");
        }
        assert!(table.starts_with("| rows of the external tables | n |"));
        // without a reference (the random sample at rtol 1e-10): a dash, not NaN
        let mut random = rows.clone();
        for t in &mut random {
            t.cor_error[1] = f64::NAN;
        }
        let table = timing_table(&random, TimedRows::Random);
        assert!(table.starts_with("| random rows of the paper's range | n |"));
        let all = line_of(&table, "| all rows | 3 |");
        assert!(all.contains("| 1.0e-7 | 20.0 / 120 |"), "{table}");
        assert!(all.contains("| - | 66.7 / 500 |"), "{table}");
        assert!(!table.contains("NaN"), "{table}");
    }

    #[test]
    fn general_timing_table_compares_within_the_cor_group() {
        let random = [
            timing(0.95, [10, 40], [60, 300]),
            timing(0.5, [30, 90], [200, 700]),
            timing(0.4, [20, 70], [100, 500]),
        ];
        let general = [
            GeneralTiming {
                id: "g-elastic",
                terms: 30,
                cor: 0.97,
                seconds: 3e-5,
                steps: 40,
                evaluations: 250,
                unreduced_seconds: 6e-5,
            },
            GeneralTiming {
                id: "g-dissipative",
                terms: 62,
                cor: 0.6,
                seconds: 2e-5,
                steps: 35,
                evaluations: 200,
                unreduced_seconds: 4e-5,
            },
        ];
        let table = general_timing_table(&general, Some(&random));
        // the nearly elastic group has one row (1e-5 s): ratio 3; the dissipative one two rows,
        // median the upper one (1e-5 s), mean work 25.0 / 150: ratio 2
        let e = line_of(&table, "| g-elastic | 30 |");
        assert!(
            e.contains("nearly elastic (e >= 0.9)") && e.ends_with("| 3.0 |"),
            "{table}"
        );
        let d = line_of(&table, "| g-dissipative | 62 |");
        assert!(
            d.contains("25.0 / 150") && d.ends_with("| 2.0 |"),
            "{table}"
        );
        // without the random sample: dashes
        let table = general_timing_table(&general, None);
        assert!(
            line_of(&table, "| g-elastic").ends_with("| - | - |"),
            "{table}"
        );
    }

    fn line_of(table: &str, prefix: &str) -> String {
        table
            .lines()
            .find(|l| l.starts_with(prefix))
            .unwrap_or_else(|| panic!("no row {prefix} in\n{table}"))
            .to_string()
    }

    /// The 3x target applies to the real polymers of at least 30 terms only, each against the
    /// standard solid of its own CoR group, and lands in the target list.
    #[test]
    fn general_targets_compare_polymers_with_their_group() {
        let g = |id: &'static str, terms, cor, seconds| GeneralTiming {
            id,
            terms,
            cor,
            seconds,
            steps: 40,
            evaluations: 300,
            unreduced_seconds: 2.0 * seconds,
        };
        let rows = [
            g("polyisobutylene", 30, 0.28, 25e-6),
            g("epoxy", 24, 0.94, 90e-6),
            g("prony-30-incompressible", 30, 0.87, 90e-6),
        ];
        let random = [
            timing(0.5, [10, 40], [60, 300]),
            timing(0.95, [10, 40], [60, 300]),
        ];
        let t = general_targets(&rows, Some(&random));
        assert_eq!(t.len(), 1, "{t:?}");
        assert!(t[0].contains("`polyisobutylene`"), "{}", t[0]);
        assert!(
            t[0].contains(": met (2.5x: 25.0 µs against 10.0 µs)"),
            "{}",
            t[0]
        );
        let slow = [g("polyisobutylene", 30, 0.28, 35e-6)];
        let t = general_targets(&slow, Some(&random));
        assert!(t[0].contains("**not met** (3.5x"), "{}", t[0]);
        assert!(general_targets(&rows, None).is_empty());
        let text = targets(&[], None, None, &t);
        assert!(text.contains("- the 30-term real polymer"), "{text}");
    }

    #[test]
    fn targets_name_the_groups_that_miss_them() {
        let mut slow = timing(0.05, [30, 90], [200, 700]);
        slow.seconds = [40e-6, 150e-6];
        let rows = [timing(0.95, [10, 40], [60, 300]), slow];
        let text = targets(
            &[(TimedRows::External, rows.to_vec())],
            Some(3250.0),
            Some((100_000, 1.01)),
            &[],
        );
        // all rows: median of 10 µs and 40 µs is the upper one (40 µs)
        assert!(
            text.contains(
                "median at most 20.0 µs at rtol 1e-6 on the rows of the external tables: met in 1 \
                 of 3 groups, **not met** in all rows (40.0 µs), strongly dissipative (e < 0.1) \
                 (40.0 µs)"
            ),
            "{text}"
        );
        assert!(
            text.contains("at rtol 1e-10 on the rows of the external tables: met in all 3 groups"),
            "{text}"
        );
        assert!(text.contains(": met (3250x)"), "{text}");
        assert!(text.contains(": met (100000 rows in 1.01 s)"), "{text}");
        let fast = [timing(0.95, [10, 40], [60, 300])];
        let text = targets(
            &[
                (TimedRows::External, rows.to_vec()),
                (TimedRows::Random, fast.to_vec()),
            ],
            Some(900.0),
            Some((1000, 0.1)),
            &[],
        );
        assert!(
            text.contains(
                "at rtol 1e-6 on the random rows of the paper's range: met in all 2 groups"
            ),
            "{text}"
        );
        assert!(text.contains("**not met** (900x)"), "{text}");
        assert!(
            !text.contains("cor --input"),
            "a smaller batch is not the target: {text}"
        );
    }

    #[test]
    fn random_timing_measures_every_row_against_its_tight_solve() {
        let t = random_timing(20, RANDOM_SEED, &|| {}).unwrap();
        assert_eq!(t.len(), 20);
        for r in &t {
            let row = &r.row;
            assert!((-0.99..=0.5).contains(&row.nu), "{row:?}");
            assert!((1e-4..=1e2).contains(&row.p2) && (1e-3..=1e4).contains(&row.p3));
            assert!(row.cor > 0.0 && row.cor <= 1.0, "{row:?}");
            // the rtol 1e-6 CoR is within its request of the rtol 1e-10 one
            assert!(r.cor_error[0] <= 1e-6, "{r:?}");
            assert!(r.cor_error[1].is_nan());
            assert!(r.seconds.iter().all(|&s| s > 0.0 && s.is_finite()));
            assert!(r.steps[1] > r.steps[0] && r.evaluations[1] > r.evaluations[0]);
        }
        // the same sample as `cor --input` draws for this seed
        let rows = crate::apps::batch::random_rows(20, RANDOM_SEED).unwrap();
        assert_eq!(rows[3].groups.p3, t[3].row.p3);
    }

    #[test]
    fn external_csv_has_work_columns() {
        let dir = std::env::temp_dir().join(format!("mdr-impact-bench-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("bench_external.csv");
        write_timing_csv(
            &path,
            &[timing(0.5, [12, 45], [70, 310])],
            TimedRows::External,
        )
        .unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let values: Vec<&str> = lines.next().unwrap().split(',').collect();
        let col = |name: &str| values[header.iter().position(|h| *h == name).unwrap()];
        assert_eq!(col("steps_rtol_1e-6"), "12");
        assert_eq!(col("evaluations_rtol_1e-6"), "70");
        assert_eq!(col("steps_rtol_1e-10"), "45");
        assert_eq!(col("evaluations_rtol_1e-10"), "310");
        assert_eq!(col("cor_reference").parse::<f64>().unwrap(), 0.5);
    }
}

/// Time of `fast` at rtol 1e-6 on one general-material case ([`crate::report::catalogue::GENERAL`]).
#[derive(Debug, Clone, PartialEq)]
pub struct GeneralTiming {
    /// Case id.
    pub id: &'static str,
    /// Terms of its `G_eq`.
    pub terms: usize,
    /// Its CoR.
    pub cor: f64,
    /// Median wall time per impact (s).
    pub seconds: f64,
    /// Attempted steps of one solve.
    pub steps: u64,
    /// Force and history evaluations of one solve.
    pub evaluations: u64,
    /// Median wall time per impact without the merge of terms outside the contact window
    /// (`fast::impact_unreduced`), same run (s).
    pub unreduced_seconds: f64,
}

/// Time `fast` (CoR only, one core, rtol 1e-6) on every general-material case: the median over
/// repeats within `budget` seconds per case.
pub fn general_timing(budget: f64) -> Result<Vec<GeneralTiming>> {
    crate::report::catalogue::general_entries()?
        .iter()
        .map(|case| {
            let imp = &case.impact;
            let opts = SolveOptions {
                solver: SolverKind::Fast,
                rtol: TIMING_RTOLS[0],
                ..Default::default()
            };
            let out = solve(imp, &opts)?;
            let (seconds, _) = median_time(budget, || solve(imp, &opts).map(|_| ()))?;
            let p = imp.canonical_relaxation();
            let (unreduced_seconds, _) = median_time(budget, || {
                crate::solvers::fast::impact_unreduced(&p, opts.rtol, false).map(|_| ())
            })?;
            Ok(GeneralTiming {
                unreduced_seconds,
                id: case.id,
                terms: imp.canonical_relaxation().terms.len(),
                cor: out.cor,
                seconds,
                steps: out.work.steps,
                evaluations: out.work.evaluations,
            })
        })
        .collect()
}

/// `mdr-euler` against `fast` on one general material at equal requested accuracy.
#[derive(Debug, Clone, PartialEq)]
pub struct EulerSpeedup {
    /// Case id ([`crate::report::catalogue::GENERAL`]).
    pub id: &'static str,
    /// Shear terms of the material and terms of its `G_eq`.
    pub terms: (usize, usize),
    /// `mdr-euler`: median time (s) and relative CoR error.
    pub euler: (f64, f64),
    /// `fast`: median time (s) and relative CoR error.
    pub fast: (f64, f64),
}

/// `mdr-euler` against `fast` on the first general material of the catalogue (3 shear terms),
/// both asked for rtol 1e-4 (one core, CoR only, medians within `budget` seconds each), errors
/// relative to `reference` at rtol 1e-10.
pub fn general_euler_speedup(budget: f64) -> Result<EulerSpeedup> {
    let case = &crate::report::catalogue::GENERAL[0];
    let imp = case.impact()?;
    let opts = SolveOptions::with;
    let truth = solve(&imp, &opts(SolverKind::Reference, 1e-10))?.cor;
    let run = |solver| -> Result<(f64, f64)> {
        let o = opts(solver, 1e-4);
        let e = ((solve(&imp, &o)?.cor - truth) / truth).abs();
        let (t, _) = median_time(budget, || solve(&imp, &o).map(|_| ()))?;
        Ok((t, e))
    };
    Ok(EulerSpeedup {
        id: case.id,
        terms: (
            case.material()?.shear().terms().len(),
            imp.canonical_relaxation().terms.len(),
        ),
        euler: run(SolverKind::MdrEuler)?,
        fast: run(SolverKind::Fast)?,
    })
}

/// One markdown paragraph of [`general_euler_speedup`].
pub fn general_euler_text(r: &EulerSpeedup) -> String {
    let ((te, ee), (tf, ef)) = (r.euler, r.fast);
    format!(
        "`mdr-euler` (the paper's explicit Euler, on the general element network) against `fast` on the \
         {}-term material `{}` ({} `G_eq` terms), both at rtol 1e-4: `mdr-euler` {} \
         (CoR error {:.1e}), `fast` {} (CoR error {:.1e}): ratio {:.0}x (target at least {:.0}x: {}).\n",
        r.terms.0,
        r.id,
        r.terms.1,
        fmt_time(te),
        ee,
        fmt_time(tf),
        ef,
        te / tf,
        TARGET_SPEEDUP,
        if te / tf >= TARGET_SPEEDUP { "met" } else { "**not met**" }
    )
}

/// The timed rows of the random sample ([`TimedRows::Random`]) among `timed`, if timed.
pub fn random_rows_of(timed: &[(TimedRows, Vec<RowTiming>)]) -> Option<&[RowTiming]> {
    timed
        .iter()
        .find(|(k, _)| *k == TimedRows::Random)
        .map(|(_, r)| r.as_slice())
}

/// The standard solid of the random sample (`random`) in the CoR group of `r`: the group's
/// name, median time (s), mean steps and evaluations at rtol 1e-6.
fn same_group(
    r: &GeneralTiming,
    random: Option<&[RowTiming]>,
) -> Option<(&'static str, f64, f64, f64)> {
    let (name, member) = cor_groups().into_iter().find(|(_, member)| member(r.cor))?;
    let sel: Vec<&RowTiming> = random?.iter().filter(|t| member(t.row.cor)).collect();
    if sel.is_empty() {
        return None;
    }
    let mut v: Vec<f64> = sel.iter().map(|t| t.seconds[0]).collect();
    v.sort_by(|a, b| a.total_cmp(b));
    let n = sel.len() as f64;
    let steps = sel.iter().map(|t| t.steps[0] as f64).sum::<f64>() / n;
    let evals = sel.iter().map(|t| t.evaluations[0] as f64).sum::<f64>() / n;
    Some((name, v[v.len() / 2], steps, evals))
}

/// Design target: `fast` at rtol 1e-6 on a real polymer of at least 30 terms
/// ([`crate::report::catalogue::POLYMERS`]) takes at most this multiple of the median time of the
/// standard solid in the same CoR group.
pub const TARGET_GENERAL_RATIO: f64 = 3.0;

/// The target [`TARGET_GENERAL_RATIO`] for the real polymers of at least 30 `G_eq` terms among
/// `rows`, each beside the standard solid of its CoR group in `random` (one list entry per
/// polymer; none without the random sample).
pub fn general_targets(rows: &[GeneralTiming], random: Option<&[RowTiming]>) -> Vec<String> {
    rows.iter()
        .filter(|r| r.terms >= 30 && crate::report::catalogue::POLYMERS.iter().any(|p| p.id == r.id))
        .filter_map(|r| {
            let (name, t, _, _) = same_group(r, random)?;
            let x = r.seconds / t;
            let verdict = if x <= TARGET_GENERAL_RATIO {
                "met"
            } else {
                "**not met**"
            };
            Some(format!(
                "the {}-term real polymer `{}` at rtol 1e-6 in at most {TARGET_GENERAL_RATIO:.0}x the \
                 median time of the standard solid in its CoR group ({name}): {verdict} ({x:.1}x: {} \
                 against {})",
                r.terms,
                r.id,
                fmt_time(r.seconds),
                fmt_time(t)
            ))
        })
        .collect()
}

/// Markdown table of [`general_timing`], each case beside the standard solid of the random
/// sample in the same CoR group (`random`: the rows of [`TimedRows::Random`], if timed), with
/// the ratio of the median times.
pub fn general_timing_table(rows: &[GeneralTiming], random: Option<&[RowTiming]>) -> String {
    let mut s = String::from(
        "| case | G_eq terms | CoR | median time | steps / evaluations | without the merge of far terms (`fast::reduce`) | standard solid, same CoR group (random rows): median time, steps / evaluations | ratio |\n\
         | --- | --- | --- | --- | --- | --- | --- | --- |\n",
    );
    for r in rows {
        let (std_text, ratio) = match same_group(r, random) {
            Some((name, t, steps, evals)) => (
                format!("{name}: {}, {steps:.1} / {evals:.0}", fmt_time(t)),
                format!("{:.1}", r.seconds / t),
            ),
            None => ("-".to_string(), "-".to_string()),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {:.4} | {} | {} / {} | {} | {std_text} | {ratio} |",
            r.id,
            r.terms,
            r.cor,
            fmt_time(r.seconds),
            r.steps,
            r.evaluations,
            fmt_time(r.unreduced_seconds)
        );
    }
    s
}

/// The time of one `fit` of 10 drops (CoR and contact time, 1 % noise, the round-trip study's
/// material and sphere, repetition 0 of seed 1), on the calling thread.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitTiming {
    /// Wall time of the fit (s).
    pub seconds: f64,
    /// Forward solves it made.
    pub solves: usize,
    /// Drops fitted.
    pub drops: usize,
}

/// Time one 10-drop fit ([`FitTiming`]).
pub fn fit_timing() -> Result<FitTiming> {
    use crate::apps::fit::{self, study};
    let cfg = study::StudyConfig {
        reps: 1,
        seed: 1,
        noise: 0.01,
        velocities: 10,
        contact_times: true,
    };
    let data = study::noisy(&study::exact_data(&cfg)?, cfg.noise, cfg.seed, 0);
    let model = fit::Model::new(fit::ModelKind::StandardSolid, None, vec![])?;
    let t0 = Instant::now();
    let r = fit::fit(&model, &data, &[None; 4])?;
    Ok(FitTiming {
        seconds: t0.elapsed().as_secs_f64(),
        solves: r.solves,
        drops: data.observations.len(),
    })
}

/// One line on the fit's time for the bench output and the performance section.
pub fn fit_timing_text(t: &FitTiming) -> String {
    format!(
        "`mdr-impact fit` of {} drops (standard solid, CoR and contact time, the round-trip \
         study's data; one core): {:.2} s, {} forward solves.\n",
        t.drops, t.seconds, t.solves
    )
}
