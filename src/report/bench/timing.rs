//! Timing of `fast` row by row (the external tables and a random sample), of the general
//! materials, of the Euler baseline against `fast` on them, and of one `fit`.

use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use crate::error::{Error, Result};
use crate::io::output::write_atomic;
use crate::solvers::{solve, SolveOptions, SolverKind};

use super::*;

/// The median of `v` (the upper one of an even count), sorting `v` in place; `v` must not be
/// empty. Every median of the bench.
pub(super) fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
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
    Ok((median(&mut times), times.len()))
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
    pub(super) fn intro(self, n: usize) -> String {
        let data = format!("[`validation/{0}`](validation/{0})", self.csv_name());
        match self {
            TimedRows::External => format!(
                "`fast` on every row of the external tables (the paper's range and its most \
                 dissipative corner; one core, CoR only, median of {TIMING_REPEATS} solves per \
                 row, one per pass over all rows; steps / evaluations: the mean attempted steps \
                 and force and history evaluations of one solve, which do not depend on the \
                 machine; tight check: the share of rows whose answer needed a second, tighter \
                 solve because the one-solve estimate was above rtol (docs/theory.md §9.8); \
                 data: {data}):"
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
    pub(super) fn title(self) -> &'static str {
        match self {
            TimedRows::External => "rows of the external tables",
            TimedRows::Random => "random rows of the paper's range",
        }
    }

    /// Header of the error columns.
    pub(super) fn error_header(self) -> &'static str {
        match self {
            TimedRows::External => "max CoR error",
            TimedRows::Random => "max CoR difference from rtol 1e-10",
        }
    }

    /// CSV column of the CoR the errors are taken against.
    pub(super) fn cor_column(self) -> &'static str {
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
    /// Whether the answer at rtol 1e-6 and 1e-10 came from the tight check (a second, tighter
    /// solve: `Work::tight_checks > 0`) rather than from one solve.
    pub tight: [bool; 2],
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
    tight: [bool; 2],
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
            tight: self.tight,
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
            tight: [false; 2],
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
                out[i].tight[k] = o.work.tight_checks > 0;
            }
            tick();
        }
    }
    for (t, o) in times.iter_mut().zip(&mut out) {
        o.seconds = [median(&mut t[0]), median(&mut t[1])];
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
            "tight_check_rtol_1e-6",
            "tight_check_rtol_1e-10",
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
                )
                .chain(t.tight.map(|b| u8::from(b).to_string())),
            )
            .map_err(io)?;
        }
        c.flush().map_err(|e| Error::io(path, e))
    })
}

/// One group of [`timing_groups`]: its rows' median time, worst CoR error and mean work at
/// each accuracy of [`TIMING_RTOLS`].
pub(super) struct GroupStats {
    pub(super) name: &'static str,
    pub(super) n: usize,
    pub(super) median: [f64; 2],
    pub(super) max_error: [f64; 2],
    pub(super) steps: [f64; 2],
    pub(super) evaluations: [f64; 2],
    /// Share of the rows answered by the tight check.
    pub(super) tight: [f64; 2],
}

/// [`GroupStats`] of every group of [`timing_groups`] that has rows.
pub(super) fn group_stats(rows: &[RowTiming]) -> Vec<GroupStats> {
    let mut out = Vec::new();
    for (name, member) in timing_groups() {
        let sel: Vec<&RowTiming> = rows.iter().filter(|t| member(&t.row)).collect();
        if sel.is_empty() {
            continue;
        }
        let n = sel.len() as f64;
        let median_of =
            |k: usize| median(&mut sel.iter().map(|t| t.seconds[k]).collect::<Vec<_>>());
        // NaN (no reference) when no row has one
        let max_err = |k: usize| sel.iter().map(|t| t.cor_error[k]).fold(f64::NAN, f64::max);
        let steps = |k: usize| sel.iter().map(|t| t.steps[k] as f64).sum::<f64>() / n;
        let evals = |k: usize| sel.iter().map(|t| t.evaluations[k] as f64).sum::<f64>() / n;
        let tight = |k: usize| sel.iter().filter(|t| t.tight[k]).count() as f64 / n;
        out.push(GroupStats {
            name,
            n: sel.len(),
            median: [median_of(0), median_of(1)],
            max_error: [max_err(0), max_err(1)],
            steps: [steps(0), steps(1)],
            evaluations: [evals(0), evals(1)],
            tight: [tight(0), tight(1)],
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
        "| {} | n | rtol 1e-6: median time | {err} | steps / evaluations | tight check | rtol 1e-10: median time | {err} | steps / evaluations | tight check |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n",
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
                    "{} | {e} | {:.1} / {:.0} | {:.1} %",
                    fmt_time(g.median[k]),
                    g.steps[k],
                    g.evaluations[k],
                    100.0 * g.tight[k]
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
    /// Timed in alternation with the standard solids of its CoR group in the random sample
    /// ([`pair_with_standard_solids`]; `None` before that or without rows).
    pub group: Option<Paired>,
    /// Timed in alternation with the standard solids within [`COR_BAND`] of its CoR.
    pub band: Option<Paired>,
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
                group: None,
                band: None,
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

/// The time of one `fit` of 10 drops (CoR and contact time, 1 % noise, the round-trip study's
/// material and sphere, repetition 0 of seed 1), its forward solves on all cores (`fit` solves the
/// drops of every misfit and Jacobian in parallel).
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
         study's data; all cores, the drops of every misfit and Jacobian solved in parallel): \
         {:.2} s, {} forward solves.\n",
        t.drops, t.seconds, t.solves
    )
}

/// The time of `fast` per impact for one indenter shape, and its ratio to the paraboloid's.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeTiming {
    /// The shape, as `report::validate::shapes` names it.
    pub shape: &'static str,
    /// Median time per impact (s), summed over the velocities.
    pub seconds: f64,
    /// `seconds` over the paraboloid's.
    pub ratio: f64,
}

/// Largest ratio of a shape's time per impact to the paraboloid's that [`shape_timing_table`]
/// reports as met (the design target of the indenter shapes).
pub const SHAPE_TARGET_RATIO: f64 = 1.5;

/// Velocities (m/s) of [`shape_timing`].
pub const SHAPE_VELOCITIES: [f64; 4] = [0.3, 0.7, 1.5, 3.0];

/// `fast` at rtol 1e-6 on every indenter shape (docs/theory.md §11; the flat punch by its
/// modes) and on the paraboloid of the same radius, one thread, the default scene's material and 4.11 g at
/// [`SHAPE_VELOCITIES`]: the median time per impact of each and the ratio to the paraboloid's
/// (target: at most [`SHAPE_TARGET_RATIO`]). The shapes are timed in alternation: each
/// pass solves every shape's impacts in turn, so all of them see the same load of the machine
/// (timed one after the other, the exact sphere's ratio was 1.64 in one run and 1.13 in the
/// next); passes go on until `budget` seconds per shape are spent (at least 5, at most 101).
pub fn shape_timing(budget: f64) -> Result<Vec<ShapeTiming>> {
    use crate::model::geometry::Shape;
    use crate::report::validate::shapes::{shaped_impact, shapes};
    let material = crate::io::scene::Scene::default_scene()
        .impact
        .half_space()
        .cloned()
        .ok_or(Error::Internal("the default scene is a half-space"))?;
    let opts = SolveOptions::with(SolverKind::Fast, 1e-6);
    let mut list: Vec<(&'static str, Shape)> =
        vec![("paraboloid", Shape::Paraboloid { radius: 5.0e-3 })];
    list.extend(shapes());
    let sets = list
        .iter()
        .map(|&(name, shape)| {
            let impacts = SHAPE_VELOCITIES
                .iter()
                .map(|&v| shaped_impact(shape, v, material.clone()))
                .collect::<Result<Vec<_>>>()?;
            Ok((name, impacts))
        })
        .collect::<Result<Vec<_>>>()?;
    let mut times = vec![Vec::new(); sets.len()];
    let start = Instant::now();
    for pass in 0..101 {
        for ((_, impacts), t) in sets.iter().zip(&mut times) {
            let t0 = Instant::now();
            for imp in impacts {
                solve(imp, &opts)?;
            }
            t.push(t0.elapsed().as_secs_f64() / impacts.len() as f64);
        }
        if pass + 1 >= 5 && start.elapsed().as_secs_f64() > budget * sets.len() as f64 {
            break;
        }
    }
    let medians: Vec<f64> = times.iter_mut().map(|t| median(t)).collect();
    Ok(sets
        .iter()
        .zip(&medians)
        .map(|(&(shape, _), &seconds)| ShapeTiming {
            shape,
            seconds,
            ratio: seconds / medians[0],
        })
        .collect())
}

/// The table of [`shape_timing`], and which shapes miss [`SHAPE_TARGET_RATIO`].
pub fn shape_timing_table(rows: &[ShapeTiming]) -> String {
    let mut s = format!(
        "Indenter shapes (`fast` at rtol 1e-6, one thread, the default scene's material, 4.11 g \
         at {SHAPE_VELOCITIES:?} m/s; the flat punch by the modes of its linear ODE): median \
         time per impact and its ratio to the paraboloid's, the shapes timed in alternation \
         (each pass solves every shape in turn; target: at most {SHAPE_TARGET_RATIO}).\n\n| shape | time per impact | ratio to the paraboloid |\n| --- | --- | --- |\n"
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {:.2} |",
            r.shape,
            fmt_time(r.seconds),
            r.ratio
        );
    }
    let shapes = rows.len().saturating_sub(1);
    if shapes == 0 {
        return s;
    }
    // judged on the printed ratio, so that the verdict never contradicts the table
    let missed: Vec<String> = rows
        .iter()
        .filter(|r| {
            format!("{:.2}", r.ratio).parse::<f64>().unwrap_or(r.ratio) > SHAPE_TARGET_RATIO
        })
        .map(|r| format!("{} ({:.2})", r.shape, r.ratio))
        .collect();
    let _ = writeln!(
        s,
        "\nAt most {SHAPE_TARGET_RATIO}x the paraboloid: {}.",
        if missed.is_empty() {
            format!("met by all {shapes} shapes")
        } else {
            format!(
                "met by {} of {shapes} shapes, **not met** by {}",
                shapes.saturating_sub(missed.len()),
                missed.join(", ")
            )
        }
    );
    s
}
