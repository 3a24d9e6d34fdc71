//! The performance section of VALIDATION.md.

use std::fmt::Write as _;
use std::path::PathBuf;

use super::*;

/// The performance section of VALIDATION.md (between the markers).
pub fn summary(
    points: &[BenchPoint],
    machine: &str,
    batch: Option<BatchTiming>,
    timed: &[(TimedRows, Vec<RowTiming>)],
    general: &[GeneralTiming],
    general_lines: &[String],
) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Measured by `mdr-impact bench` in one run on {machine}; times are medians over repeats \
         of a CoR-only solve (no histories), errors are against the reference solver at rtol 1e-11 \
         (outside the timed region). Data: [`validation/bench.csv`](validation/bench.csv); \
         plot: `validation/work-precision.svg`. Machine-dependent, so not part of the staleness check. \
         Re-run: `cargo run --release -- bench --batch-rows 100000` (the run's own wall time is \
         at the end of this section).\n"
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
    let one: Vec<String> = sweep(false)
        .into_iter()
        .filter(|(k, _)| *k == SolverKind::Fast)
        .flat_map(|(_, r)| r)
        .filter_map(|rtol| {
            let (t1, e1, _) = aggregate_of(points, SolverKind::Fast, rtol, false)?;
            let (tv, ev, _) = aggregate(points, SolverKind::Fast, rtol)?;
            Some(format!(
                "| {rtol:.0e} | {} | {e1:.1e} | {} | {ev:.1e} | {:.2} |",
                fmt_time(t1),
                fmt_time(tv),
                tv / t1
            ))
        })
        .collect();
    if !one.is_empty() {
        let _ = writeln!(
            s,
            "\n`fast` verified (as called) against one unverified solve at the same rtol \
             (`fast::impact_unverified`, the solver before the verification; the diagram's \
             \"fast, one solve\" series), same cases:\n\n| rtol | one solve: time | max CoR error \
             | verified: time | max CoR error | time ratio |\n| --- | --- | --- | --- | --- | --- |"
        );
        for l in one {
            let _ = writeln!(s, "{l}");
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
        let _ = writeln!(
            s,
            "\n`fast` at rtol 1e-6 on the general materials of VALIDATION.md section 1c (one core, \
             CoR only), each beside the standard solids of the random sample in the same CoR group \
             and beside those within {COR_BAND} of its CoR (a group spans CoRs whose cost differs \
             more than the terms': its median sits near the group's cheap end). For the ratios the \
             case is timed in alternation with those standard solids (at most {PAIRED_MAX_ROWS} of \
             them; {PAIRED_PASSES} passes, each solving the case and one standard solid in turn, \
             so both see the same load of the machine), and each ratio is of the two medians; \
             steps / evaluations: the mean work of one solve of those standard solids:\n"
        );
        s.push_str(&general_timing_table(general));
    }
    if let Some(b) = batch {
        let _ = writeln!(
            s,
            "\n`mdr-impact cor --input` path (the file's bytes parsed by `batch::parse_rows`, solved by \
             `batch::solve_rows`, formatted by `batch::write_results` into memory; default solver and \
             rtol 1e-6, all cores; median of {BATCH_PASSES} passes, each also timing the solves \
             alone): {} random rows of the paper's range in {:.2} s.{}",
            b.rows,
            b.seconds,
            b.solves_text()
        );
    }
    if !timed.is_empty() {
        s.push('\n');
        s.push_str(&targets(timed, speedup(points), batch, general_lines));
    }
    s
}

/// Passes of [`batch_timing`], each timing the three paths in turn.
pub const BATCH_PASSES: usize = 3;

/// The `cor --input` path timed by [`batch_timing`] on random rows of the paper's range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatchTiming {
    /// Rows.
    pub rows: usize,
    /// Median wall time of the whole path: parse, solve, format (s).
    pub seconds: f64,
    /// Median wall times of the solves alone on the same rows: verified `fast` as `cor --input`
    /// calls it, and one unverified solve per row (s).
    pub solves: (f64, f64),
}

impl BatchTiming {
    /// The sentence on [`BatchTiming::solves`].
    pub fn solves_text(&self) -> String {
        let (verified, one) = self.solves;
        format!(
            " The solves alone (`fast` at rtol 1e-6, all cores): {verified:.2} s verified \
             (`fast` as `cor --input` calls it), {one:.2} s as one unverified solve per row at \
             the same rtol (`fast::impact_unverified`, no check at all: {:.2} of the verified \
             time).",
            one / verified
        )
    }
}

/// The `cor --input` path on `n` random rows of the paper's range (seed 1), all cores, rtol
/// 1e-6, CoR only, in [`BATCH_PASSES`] passes that each time in turn: the whole path on the
/// file's bytes (parse, solve with the default options, format into memory), the verified
/// `fast` solves alone (as `cor --input` calls it) and one unverified solve per row
/// (`fast::impact_unverified`); the median of each, so that all three see the same load.
pub fn batch_timing(n: usize) -> Result<BatchTiming> {
    use crate::apps::batch;
    use rayon::prelude::*;
    use std::time::Instant;
    let rows = batch::random_rows(n, 1)?;
    let mut file = batch::HEADER.join(",");
    for r in &rows {
        file.push('\n');
        file.push_str(&r.text.join(","));
    }
    let rtol = TIMING_RTOLS[0];
    let relax = |r: &batch::Row| -> Result<crate::model::material::Prony> {
        Ok(crate::model::impact::Impact::from_groups(r.groups)?.canonical_relaxation())
    };
    let mut times = [Vec::new(), Vec::new(), Vec::new()];
    for _ in 0..BATCH_PASSES {
        let t0 = Instant::now();
        let parsed = batch::parse_rows("random", file.as_bytes())?;
        let outcomes = batch::solve_rows("random", &parsed.rows, &SolveOptions::default())?;
        let mut table = Vec::new();
        batch::write_results(&mut table, &parsed.rows, &outcomes)?;
        times[0].push(t0.elapsed().as_secs_f64());
        let t0 = Instant::now();
        rows.par_iter()
            .map(|r| fast::impact_with(None, &relax(r)?, rtol, false, false))
            .collect::<Result<Vec<_>>>()?;
        times[1].push(t0.elapsed().as_secs_f64());
        let t0 = Instant::now();
        rows.par_iter()
            .map(|r| fast::impact_unverified(&relax(r)?, rtol, false))
            .collect::<Result<Vec<_>>>()?;
        times[2].push(t0.elapsed().as_secs_f64());
    }
    let [whole, verified, one] = times.map(|mut t| median(&mut t));
    Ok(BatchTiming {
        rows: n,
        seconds: whole,
        solves: (verified, one),
    })
}

/// What `mdr-impact bench` runs: the work-precision points and (without `quick`) the row
/// timings, the general materials and the Euler baseline on them; always one fit, and, when
/// `batch_rows > 0`, the `cor --input` path on that many random rows ([`batch_timing`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BenchOptions {
    /// One case, one setting per solver, no row timings (CI smoke test).
    pub quick: bool,
    /// Seconds of repeats per timed point.
    pub budget: f64,
    /// Random rows for the `cor --input` timing (0: skip).
    pub batch_rows: usize,
    /// An earlier build of this program to time against ([`baseline_ratio`]; none: skip).
    pub baseline: Option<PathBuf>,
}

/// Velocities of the `curve` timing (`--v0`, log-spaced) on the default scene.
pub const CURVE_VELOCITIES: &str = "0.01:10:200";

/// Everything one bench run measured.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchReport {
    /// The options it ran with.
    pub options: BenchOptions,
    /// The work-precision points.
    pub points: Vec<BenchPoint>,
    /// The row timings of `fast` (empty with `quick`).
    pub timed: Vec<(TimedRows, Vec<RowTiming>)>,
    /// `fast` on the general materials (empty with `quick`).
    pub general: Vec<GeneralTiming>,
    /// The Euler baseline against `fast` on a general material (not with `quick`).
    pub euler_general: Option<EulerSpeedup>,
    /// One 10-drop fit.
    pub fit: FitTiming,
    /// `cor --input` rows and their wall time (s), when asked for.
    pub batch: Option<BatchTiming>,
    /// Wall time (s) of `curve --v0 0.01:10:200 --log` on the default scene.
    pub curve_seconds: f64,
    /// `fast` on the indenter shapes against the paraboloid ([`shape_timing`]).
    pub shapes: Vec<ShapeTiming>,
    /// The machine it ran on ([`machine`]).
    pub machine: String,
    /// This build against an earlier one, when asked for.
    pub baseline: Option<BaselineRatio>,
    /// `fast` against the SciPy script ([`scipy_comparison`]).
    pub scipy: ScipyComparison,
    /// Wall time of the whole run (s).
    pub seconds: f64,
}

/// Units of progress [`run_full`] reports: the work-precision points and, without `quick`,
/// every row of every pass of the row timings.
pub fn full_units(opts: &BenchOptions) -> Result<u64> {
    let mut n = units(opts.quick);
    if !opts.quick {
        for kind in TimedRows::ALL {
            n += (kind.rows()? * TIMING_REPEATS) as u64;
        }
    }
    Ok(n)
}

/// Run the whole benchmark ([`BenchOptions`]); `tick` as [`full_units`] counts. A budget that
/// is not positive and finite is refused ([`Error::OutOfRange`]).
pub fn run_full(opts: &BenchOptions, tick: &dyn Fn()) -> Result<BenchReport> {
    use crate::apps::curve;
    use std::time::Instant;
    crate::error::check(
        "--budget",
        opts.budget,
        opts.budget > 0.0,
        "0 < budget < inf",
    )?;
    let start = Instant::now();
    let points = run(opts.quick, opts.budget, tick)?;
    let mut timed = Vec::new();
    let mut general = Vec::new();
    let mut euler_general = None;
    if !opts.quick {
        for kind in TimedRows::ALL {
            timed.push((kind, kind.time(tick)?));
        }
        general = general_timing(opts.budget)?;
        if let Some(random) = random_rows_of(&timed) {
            pair_with_standard_solids(&mut general, random)?;
        }
        euler_general = Some(general_euler_speedup(opts.budget)?);
    }
    let fit = fit_timing()?;
    let batch = if opts.batch_rows > 0 {
        Some(batch_timing(opts.batch_rows)?)
    } else {
        None
    };
    let scene = crate::io::scene::Scene::default_scene();
    let range = curve::VelocityRange::parse(CURVE_VELOCITIES, true)?;
    let t0 = Instant::now();
    curve::run(&scene.impact, &scene.options, &range, &|| {})?;
    let curve_seconds = t0.elapsed().as_secs_f64();
    let shapes = shape_timing(opts.budget)?;
    let scipy = scipy_comparison(opts.budget, if opts.quick { 1 } else { 3 })?;
    let baseline = match &opts.baseline {
        Some(b) => {
            let exe = std::env::current_exe().map_err(|e| Error::io("current_exe", e))?;
            Some(baseline_ratio(b, &exe)?)
        }
        None => None,
    };
    Ok(BenchReport {
        options: opts.clone(),
        baseline,
        points,
        timed,
        general,
        euler_general,
        fit,
        batch,
        curve_seconds,
        shapes,
        scipy,
        machine: machine(),
        seconds: start.elapsed().as_secs_f64(),
    })
}

impl BenchReport {
    /// Write `bench.csv`, `work-precision.svg` and the per-row CSVs of the row timings into
    /// `dir`.
    pub fn write_files(&self, dir: &Path) -> Result<()> {
        write_csv(&dir.join("bench.csv"), &self.points)?;
        plot(&dir.join("work-precision.svg"), &self.points)?;
        for (kind, rows) in &self.timed {
            write_timing_csv(&dir.join(kind.csv_name()), rows, *kind)?;
        }
        Ok(())
    }

    /// The line on the `curve` timing.
    fn curve_line(&self) -> String {
        format!(
            "`mdr-impact curve --v0 {CURVE_VELOCITIES} --log` on the default scene (200 \
             velocities, all cores): {:.3} s.\n",
            self.curve_seconds
        )
    }

    /// The terminal report: one line per work-precision point, the timing tables, the fit,
    /// batch and curve times and the design targets.
    pub fn text(&self) -> String {
        let mut s = String::new();
        for p in &self.points {
            let _ = writeln!(
                s,
                "{:<10} rtol={:<6.0e} {:<28} {:>12}  cor err {:.1e}  force err {:.1e}",
                p.solver.name(),
                p.rtol,
                p.case,
                fmt_time(p.median_seconds),
                p.cor_error,
                p.force_error
            );
        }
        for (kind, rows) in &self.timed {
            let _ = writeln!(s, "{}", timing_table(rows, *kind));
        }
        if !self.options.quick {
            let _ = writeln!(s, "{}", general_timing_table(&self.general));
        }
        if let Some(r) = &self.euler_general {
            s.push_str(&general_euler_text(r));
        }
        s.push_str(&fit_timing_text(&self.fit));
        if let Some(b) = self.batch {
            let _ = writeln!(
                s,
                "cor --input path: {} rows in {:.2} s.{}",
                b.rows,
                b.seconds,
                b.solves_text()
            );
        }
        let _ = writeln!(
            s,
            "curve --v0 {CURVE_VELOCITIES} --log (default scene): {:.3} s",
            self.curve_seconds
        );
        s.push_str(&shape_timing_table(&self.shapes));
        if let Some(b) = &self.baseline {
            s.push_str(&b.text());
        }
        s.push_str(&self.scipy.text());
        if !self.timed.is_empty() {
            s.push_str(&targets(
                &self.timed,
                speedup(&self.points),
                self.batch,
                &self.general_lines(),
            ));
        }
        s
    }

    /// The entries of the design targets beyond the row timings: the polymers against the
    /// standard solid and `fast` against the SciPy script.
    fn general_lines(&self) -> Vec<String> {
        let mut v = general_targets(&self.general);
        v.push(match self.scipy.ratio() {
            Some(x) => format!(
                "`fast` against the SciPy script a user would write (DOP853, rtol {SCIPY_RTOL:.0e}, \
                 {SCIPY_ROWS} rows): {x:.0}x less time (reported, no target number)"
            ),
            None => "`fast` against the SciPy script: not measured (see above)".to_string(),
        });
        v
    }

    /// The body of the performance section of VALIDATION.md.
    pub fn section(&self) -> String {
        let mut s = summary(
            &self.points,
            &self.machine,
            self.batch,
            &self.timed,
            &self.general,
            &self.general_lines(),
        );
        s.push('\n');
        s.push_str(&fit_timing_text(&self.fit));
        if let Some(r) = &self.euler_general {
            s.push('\n');
            s.push_str(&general_euler_text(r));
        }
        s.push('\n');
        s.push_str(&self.curve_line());
        s.push('\n');
        s.push_str(&shape_timing_table(&self.shapes));
        if let Some(b) = &self.baseline {
            s.push('\n');
            s.push_str(&b.text());
        }
        s.push('\n');
        s.push_str(&self.scipy.text());
        let _ = writeln!(
            s,
            "\nThis run of `mdr-impact bench` took {:.1} min.",
            self.seconds / 60.0
        );
        s
    }
}
