//! `mdr-impact`: the command line. Parses, calls the library, prints; nothing else.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use mdr_impact::error::escape_text;
use mdr_impact::report::{figures, sections};
use mdr_impact::solvers::indentation::Prescribed;
use mdr_impact::solvers::{force_curve, IndentMethod};
use mdr_impact::{
    apps::batch, io::output, io::plot, io::scene::Scene, report::validate, solve, Error, Groups,
    Impact, Material, SolveOptions, SolverKind,
};

#[derive(Parser)]
#[command(
    name = "mdr-impact",
    version,
    about = "Normal impact of a rigid sphere on a compressible viscoelastic half-space (MDR)"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene (the embedded default when none is given) and print the outcome with units.
    Run {
        /// Scene file (TOML); see README for the format.
        scene: Option<PathBuf>,
        /// Print the outcome as one JSON object (SI units) and nothing else on stdout.
        #[arg(long)]
        json: bool,
    },
    /// CoR against impact velocity: the scene's impact (the embedded default when none is
    /// given) at N velocities; writes DIR/curve.csv and DIR/curve.svg.
    Curve {
        /// Scene file (TOML); its sphere, material and solver are used, its velocity and
        /// [output] are not.
        scene: Option<PathBuf>,
        /// Velocities MIN:MAX:N in m/s (0 < MIN < MAX, 2 <= N <= 100000).
        #[arg(long, allow_hyphen_values = true)]
        v0: String,
        /// Log-spaced velocities (and a log velocity axis) instead of linear.
        #[arg(long)]
        log: bool,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
    /// Parameters for DEM codes: the scene's e(v0) (the embedded default when none is given),
    /// the constant-CoR and viscoelastic damping laws fitted to it with their errors, and the
    /// Hertz stiffness; writes DIR/dem.csv, DIR/dem.svg and DIR/dem_lammps.in or
    /// DIR/dem_liggghts.in.
    Dem {
        /// Scene file (TOML); its sphere(s), material(s) and solver are used, its velocity and
        /// [output] are not.
        scene: Option<PathBuf>,
        /// Velocities MIN:MAX[:N] in m/s (0 < MIN < MAX, 2 <= N <= 100000; N defaults to 50).
        #[arg(long, allow_hyphen_values = true)]
        v0: String,
        /// Output: lammps or liggghts (input lines on stdout and in DIR), or json (one object
        /// on stdout).
        #[arg(long)]
        format: String,
        /// Log-spaced velocities (and a log velocity axis) instead of linear.
        #[arg(long)]
        log: bool,
        /// Hertz stiffness from the relaxed (E* = 4 G_eq(inf)) or glassy (E* = 4 G_eq(0))
        /// modulus.
        #[arg(long, default_value = "relaxed")]
        modulus: String,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
    /// Coefficient of restitution from the dimensionless groups (Eq. 11).
    Cor {
        /// Static Poisson ratio, -1 < nu <= 0.5 (0.5 = incompressible).
        #[arg(
            long,
            allow_hyphen_values = true,
            required_unless_present = "input",
            conflicts_with = "input"
        )]
        nu: Option<f64>,
        /// p2 = G_inf / G_1, 0 < p2 < inf (finite).
        #[arg(
            long,
            allow_hyphen_values = true,
            required_unless_present = "input",
            conflicts_with = "input"
        )]
        p2: Option<f64>,
        /// p3 = eta (v0 R / (m^2 G_inf^3))^(1/5), 0 <= p3 < inf (0: elastic, Hertz).
        #[arg(
            long,
            allow_hyphen_values = true,
            required_unless_present = "input",
            conflicts_with = "input"
        )]
        p3: Option<f64>,
        /// CSV with header nu,p2,p3: writes nu,p2,p3,cor,contact_time,max_indentation to stdout.
        #[arg(long)]
        input: Option<PathBuf>,
        /// Solver: auto, fast, reference, mdr, mdr-euler.
        #[arg(long, default_value = "auto")]
        solver: String,
        /// Requested relative accuracy of the CoR.
        #[arg(long, default_value_t = mdr_impact::model::tolerances::DEFAULT_RTOL)]
        rtol: f64,
    },
    /// Force curve of a prescribed indentation (AFM / nanoindentation): CSV t,d,a,force on stdout.
    Indent {
        /// triangle (d = V t up to T, then V (2T - t)) or half-sine (d = V T sin(pi t / 2T)).
        #[arg(long)]
        history: String,
        /// Rate V (m/s).
        #[arg(long)]
        rate: f64,
        /// Time of the peak T (s).
        #[arg(long = "peak-time")]
        peak_time: f64,
        /// Sphere radius R (m).
        #[arg(long)]
        radius: f64,
        /// Relaxed shear modulus G_inf (Pa).
        #[arg(long = "g-inf")]
        g_inf: f64,
        /// Relaxing shear modulus G_1 (Pa).
        #[arg(long)]
        g1: f64,
        /// Shear viscosity eta (Pa s).
        #[arg(long)]
        eta: f64,
        /// Static Poisson ratio, -1 < nu <= 0.5 (0.5 = incompressible).
        #[arg(long, allow_hyphen_values = true)]
        nu: f64,
        /// theory (Lee-Radok/Ting) or mdr.
        #[arg(long, default_value = "theory")]
        solver: String,
        /// Output times (s), comma separated; default: 101 uniform points over [0, 2T].
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        times: Option<Vec<f64>>,
    },
    /// Run the validation catalogue and write VALIDATION.md with its figures.
    Validate {
        /// The report to write.
        #[arg(long, default_value = "VALIDATION.md")]
        out: PathBuf,
        /// Folder of the figures.
        #[arg(long, default_value = "validation")]
        figures: PathBuf,
        /// Do not write: fail when the committed report differs from a fresh run.
        #[arg(long)]
        check: bool,
    },
    /// Work-precision benchmark of every solver; writes CSV, plot and the performance section.
    Bench {
        /// One case, one setting per solver, no report update (CI smoke test).
        #[arg(long)]
        quick: bool,
        /// Folder for bench.csv and work-precision.svg.
        #[arg(long, default_value = "validation")]
        out: PathBuf,
        /// Report whose performance section is replaced (not with --quick).
        #[arg(long, default_value = "VALIDATION.md")]
        report: PathBuf,
        /// Seconds of repeats per timed point.
        #[arg(long, default_value_t = 0.3)]
        budget: f64,
        /// Also time `cor --input` on this many random rows (0: skip).
        #[arg(long, default_value_t = 0)]
        batch_rows: usize,
    },
    /// Stress test: random groups over the whole input range, `auto` and `fast` at every rtol
    /// from 1e-2 to 1e-11 against the reference; writes the stress section of the report and the
    /// rows that break the contract.
    Stress {
        /// Number of random rows.
        #[arg(long, default_value_t = mdr_impact::report::stress::DEFAULT_ROWS)]
        rows: usize,
        /// Seed of the rows.
        #[arg(long, default_value_t = mdr_impact::report::stress::DEFAULT_SEED)]
        seed: u64,
        /// Folder for stress_outside.csv.
        #[arg(long, default_value = "validation")]
        out: PathBuf,
        /// Report whose stress section is replaced.
        #[arg(long, default_value = "VALIDATION.md")]
        report: PathBuf,
    },
    /// Regenerate the reference force histories and their manifest.
    Reference {
        /// Output folder.
        #[arg(long, default_value = "reference")]
        out: PathBuf,
    },
    /// CoR over a grid or random sample of (nu, p2, p3); rows appended to a CSV, resumable.
    Sweep {
        /// Static Poisson ratios, comma-separated, in (-1, 0.5]; 'inc' = 0.5 (incompressible).
        #[arg(long, default_value = "0.45", allow_hyphen_values = true)]
        nu: String,
        /// log10 p2 grid as MIN:MAX:N (MIN:MAX is enough with --random).
        #[arg(long, default_value = "-3:1:41", allow_hyphen_values = true)]
        log_p2: String,
        /// log10 p3 grid as MIN:MAX:N (MIN:MAX is enough with --random).
        #[arg(long, default_value = "-2:3:51", allow_hyphen_values = true)]
        log_p3: String,
        /// Random sample of N points instead of the grid.
        #[arg(long, value_name = "N")]
        random: Option<usize>,
        /// Seed of the random sample and of the dimensional inputs.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Solver: auto, fast, reference, mdr, mdr-euler.
        #[arg(long, default_value = "auto")]
        solver: String,
        /// Requested relative accuracy of each CoR.
        #[arg(long, default_value_t = mdr_impact::apps::sweep::DEFAULT_SWEEP_RTOL)]
        rtol: f64,
        /// Output CSV; rows already there are kept and their points skipped (resume).
        #[arg(long)]
        out: PathBuf,
        /// Random dimensional inputs (m, R, v0, G_inf drawn) instead of canonical units.
        #[arg(long)]
        dimensional: bool,
        /// With --dimensional, also solve every K-th point in canonical units (0: never).
        #[arg(long, value_name = "K", default_value_t = mdr_impact::apps::sweep::DEFAULT_CHECK_EVERY)]
        check_every: u64,
        /// Discard the rows already in the output file instead of resuming.
        #[arg(long)]
        fresh: bool,
    },
    /// Regenerate the paper's figures (SVG), the data behind them (CSV) and the result tables.
    Figures(FigureArgs),
    /// Identify material parameters from drop tests (CSV v0,cor[,cor_sd,contact_time,
    /// contact_time_sd,setup]); writes DIR/fit.toml and DIR/fit.svg.
    Fit {
        /// The data file.
        data: PathBuf,
        /// Scene whose sphere was dropped (rows without a setup column); default scene if absent.
        #[arg(long)]
        scene: Option<PathBuf>,
        /// standard-solid or prony:N (N fixed log-spaced times, fitted moduli).
        #[arg(long, default_value = "standard-solid")]
        model: String,
        /// Fix a parameter, name=value in SI (g_inf, g_1, eta, nu, k_0; prony: g_inf, g_1..g_N,
        /// nu, k_0); repeatable.
        #[arg(long = "fix", value_name = "NAME=VALUE")]
        fix: Vec<String>,
        /// Prony times MIN:MAX (s), log-spaced; default: the measured contact times / 100 to x 100.
        #[arg(long = "tau-range")]
        tau_range: Option<String>,
        /// Output folder for fit.toml and fit.svg.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Print one JSON object (SI) and nothing else on stdout.
        #[arg(long)]
        json: bool,
    },
    /// Round trip of fit: synthetic drop tests from a known material with noise, fitted again;
    /// prints the coverage of the 95 % intervals (with --report, fills its section of the report).
    FitStudy {
        /// Repetitions.
        #[arg(long, default_value_t = 200)]
        reps: usize,
        /// Seed of the noise.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Drops (velocities) per repetition.
        #[arg(long, default_value_t = 10)]
        velocities: usize,
        /// Relative noise of every measured value.
        #[arg(long, default_value_t = 0.01)]
        noise: f64,
        /// Only the CoR-only study (default: both, with and without contact times).
        #[arg(long)]
        cor_only: bool,
        /// Report whose fit section is replaced.
        #[arg(long)]
        report: Option<PathBuf>,
    },
}

/// Options of the `figures` command.
#[derive(Debug, Clone, clap::Args)]
struct FigureArgs {
    /// Output folder for the SVGs, CSVs and tables.md.
    #[arg(long, default_value = figures::DEFAULT_OUT)]
    out: PathBuf,
    /// Solver name (auto, mdr, ...).
    #[arg(long, default_value = "auto")]
    solver: String,
    /// Requested relative accuracy of each CoR.
    #[arg(long, default_value_t = mdr_impact::apps::sweep::DEFAULT_SWEEP_RTOL)]
    rtol: f64,
    /// Grid values of log10 p2 over [-3, 1] in the maps (>= 3).
    #[arg(long, default_value_t = figures::DEFAULT_N_P2)]
    n_p2: usize,
    /// Grid values of log10 p3 over [-2, 3] in the maps (>= 3).
    #[arg(long, default_value_t = figures::DEFAULT_N_P3)]
    n_p3: usize,
    /// Values of log10 p3 over [-2, 3] on the curves of Figs. 5 and 6 (>= 3).
    #[arg(long, default_value_t = figures::DEFAULT_N_LINE)]
    n_line: usize,
    /// Canonical units instead of random dimensional inputs (the paper drew them at random).
    #[arg(long)]
    canonical: bool,
    /// Seed of the random dimensional inputs.
    #[arg(long, default_value_t = figures::DEFAULT_SEED)]
    seed: u64,
    /// Scaling check on every K-th point (dimensional inputs only; 0: never).
    #[arg(long, value_name = "K", default_value_t = mdr_impact::apps::sweep::DEFAULT_CHECK_EVERY)]
    check_every: u64,
    /// Keep rows already in the data files (continue an interrupted run) instead of recomputing.
    #[arg(long)]
    resume: bool,
    /// Also replace the generated block of this Markdown file (e.g. RESULTS.md) by the tables.
    #[arg(long)]
    results: Option<PathBuf>,
    /// Show progress bars (on a terminal only).
    #[arg(long)]
    progress: bool,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // escaped: one line, no raw control bytes from a user's text
            eprintln!("error: {}", escape_text(&e.to_string()));
            ExitCode::from(1)
        }
    }
}

/// A progress bar on a terminal; hidden when stderr is not a terminal or under CI.
fn progress_bar(len: u64, what: &str) -> indicatif::ProgressBar {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() || std::env::var_os("CI").is_some() {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(len);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} {elapsed}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(what.to_string());
    bar
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command.unwrap_or(Command::Run {
        scene: None,
        json: false,
    }) {
        Command::Run { scene, json } => {
            let scene = match scene {
                Some(p) => Scene::load(&p)?,
                None => Scene::default_scene(),
            };
            let outcome = solve(&scene.impact, &scene.options)?;
            // with --json, stdout holds the JSON object alone; notes go to stderr
            let note = |k: &str, v: String| {
                if json {
                    eprintln!("{k:<28}{v}");
                } else {
                    println!("{k:<28}{v}");
                }
            };
            if let Some(h) = &outcome.history {
                if let Some(p) = &scene.history_csv {
                    output::write_history_csv(p, h)?;
                }
                if let Some(p) = &scene.plot {
                    plot::force_history_svg(p, h, "Contact force")?;
                }
            }
            if json {
                println!("{}", output::impact_json(&scene.impact, &outcome));
            } else {
                print!("{}", output::summary(&scene.impact, &outcome));
            }
            if outcome.history.is_some() {
                if let Some(p) = &scene.history_csv {
                    note("history written to", p.display().to_string());
                }
                if let Some(p) = &scene.plot {
                    note("force plot written to", p.display().to_string());
                }
            }
            Ok(())
        }
        Command::Curve {
            scene,
            v0,
            log,
            out,
        } => {
            use mdr_impact::apps::curve;
            // the input is checked before the scene is read or anything solved
            let range = curve::VelocityRange::parse(&v0, log)?;
            if out.as_os_str().is_empty() {
                return Err(Error::EmptyPath { field: "--out" });
            }
            let scene = match scene {
                Some(p) => Scene::load(&p)?,
                None => Scene::default_scene(),
            };
            let bar = progress_bar(range.n as u64, "curve");
            let c = curve::run(&scene.impact, &scene.options, &range, &|| bar.inc(1));
            bar.finish_and_clear();
            let c = c?;
            let written = curve::write_outputs(&out, &c, log)?;
            print!("{}", curve::summary(&c, Some(&written)));
            Ok(())
        }
        Command::Dem {
            scene,
            v0,
            format,
            log,
            modulus,
            out,
        } => {
            use mdr_impact::apps::dem;
            // the input is checked before the scene is read or anything solved
            let range = mdr_impact::apps::curve::VelocityRange::parse_optional_n(
                &v0,
                log,
                dem::DEFAULT_VELOCITIES,
            )?;
            let format = format.parse::<dem::Format>()?;
            let modulus = modulus.parse::<dem::ModulusChoice>()?;
            if out.as_os_str().is_empty() {
                return Err(Error::EmptyPath { field: "--out" });
            }
            let scene = match scene {
                Some(p) => Scene::load(&p)?,
                None => Scene::default_scene(),
            };
            let bar = progress_bar(range.n as u64, "dem");
            let report = dem::run(&scene.impact, &scene.options, &range, modulus, &|| {
                bar.inc(1)
            });
            bar.finish_and_clear();
            let report = report?;
            let written = dem::write_outputs(&out, &report, format)?;
            print!("{}", report.text(format));
            if format == dem::Format::Json {
                println!();
            }
            for w in &report.warnings {
                eprintln!("warning: {w}");
            }
            for f in &written.files {
                eprintln!("{:<28}{}", "written", f.display());
            }
            Ok(())
        }
        Command::Cor {
            nu,
            p2,
            p3,
            input,
            solver,
            rtol,
        } => {
            let opts = SolveOptions {
                solver: solver.parse::<SolverKind>()?,
                rtol,
                ..Default::default()
            };
            opts.validate()?;
            if let Some(path) = input {
                let input = batch::read_rows(&path)?;
                let file = path.display().to_string();
                let outcomes = batch::solve_rows(&file, &input.rows, &opts)?;
                let mut buf = Vec::new();
                batch::write_results(&mut buf, &input.rows, &outcomes)?;
                std::io::stdout()
                    .write_all(&buf)
                    .map_err(|e| Error::io("<stdout>", e))?;
                // after success only, so that an error stays the one line on stderr
                let skipped = &input.skipped_blank_lines;
                if !skipped.is_empty() {
                    eprintln!(
                        "note: {}: skipped blank line{} {}",
                        escape_text(&file),
                        if skipped.len() == 1 { "" } else { "s" },
                        batch::format_line_list(skipped)
                    );
                }
            } else {
                // clap guarantees all three are present without --input
                let (nu, p2, p3) = (
                    nu.unwrap_or(f64::NAN),
                    p2.unwrap_or(f64::NAN),
                    p3.unwrap_or(f64::NAN),
                );
                let impact = Impact::from_groups(Groups::new(nu, p2, p3)?)?;
                let o = solve(&impact, &opts)?;
                if let Some(why) = &o.fallback {
                    // `why` is the refusal of fast, which names it ("fast: requested rtol ...")
                    let fast = SolverKind::Fast.name();
                    let why = if why.starts_with(&format!("{fast}:")) {
                        why.clone()
                    } else {
                        format!("{fast}: {why}")
                    };
                    eprintln!("note: answered by {} ({})", o.solver, escape_text(&why));
                }
                println!("{}", o.cor);
            }
            Ok(())
        }
        Command::Indent {
            history,
            rate,
            peak_time,
            radius,
            g_inf,
            g1,
            eta,
            nu,
            solver,
            times,
        } => {
            let method = solver.parse::<IndentMethod>()?;
            let material = Material::with_poisson(g_inf, g1, eta, nu)?;
            let history = match history.as_str() {
                "triangle" => Prescribed::triangle(rate, peak_time)?,
                "half-sine" => Prescribed::half_sine(rate, peak_time)?,
                other => {
                    return Err(Error::Unsupported(format!(
                        "unknown history '{other}': expected triangle or half-sine"
                    )))
                }
            };
            let times = match times {
                Some(t) => t,
                None => (0..=100)
                    .map(|i| 2.0 * peak_time * i as f64 / 100.0)
                    .collect(),
            };
            let rows = force_curve(&material, radius, &history, &times, method)?;
            let mut out = String::from("t,d,a,force\n");
            for r in rows {
                out.push_str(&format!(
                    "{},{},{},{}\n",
                    output::fmt(r.t),
                    output::fmt(r.d),
                    output::fmt(r.a),
                    output::fmt(r.force)
                ));
            }
            std::io::stdout()
                .write_all(out.as_bytes())
                .map_err(|e| Error::io("<stdout>", e))
        }
        Command::Validate {
            out,
            figures,
            check,
        } => {
            let bar = progress_bar(validate::units(), "validate");
            if check {
                let c = validate::check(&out, &|| bar.inc(1));
                bar.finish_and_clear();
                let c = c?;
                if let Some(t) = validate::per_regime(&c.fresh) {
                    println!("{t}");
                }
                if let validate::Staleness::Stale { line, .. } = c.staleness {
                    return Err(Error::Unsupported(format!(
                        "{} is stale (first difference at line {line}): run `mdr-impact validate` and commit the result",
                        out.display()
                    )));
                }
                println!("{} is current", out.display());
            } else {
                let fresh = validate::regenerate(&out, &figures, &|| bar.inc(1));
                bar.finish_and_clear();
                if let Some(t) = validate::per_regime(&fresh?) {
                    println!("{t}");
                }
                println!("wrote {}", out.display());
            }
            Ok(())
        }
        Command::Bench {
            quick,
            out,
            report,
            budget,
            batch_rows,
        } => {
            use mdr_impact::report::bench;
            let bar = progress_bar(bench::units(quick), "bench");
            let points = bench::run(quick, budget, &|| bar.inc(1))?;
            bar.finish_and_clear();
            for p in &points {
                println!(
                    "{:<10} rtol={:<6.0e} {:<28} {:>12}  cor err {:.1e}  force err {:.1e}",
                    p.solver.name(),
                    p.rtol,
                    p.case,
                    bench::fmt_time(p.median_seconds),
                    p.cor_error,
                    p.force_error
                );
            }
            bench::write_csv(&out.join("bench.csv"), &points)?;
            bench::plot(&out.join("work-precision.svg"), &points)?;
            let mut timed = Vec::new();
            let kinds: &[bench::TimedRows] = if quick { &[] } else { &bench::TimedRows::ALL };
            for &kind in kinds {
                let bar = progress_bar(
                    (kind.rows()? * bench::TIMING_REPEATS) as u64,
                    &format!("bench fast: {}", kind.csv_name()),
                );
                let t = kind.time(&|| bar.inc(1))?;
                bar.finish_and_clear();
                bench::write_timing_csv(&out.join(kind.csv_name()), &t, kind)?;
                println!("{}", bench::timing_table(&t, kind));
                timed.push((kind, t));
            }
            let general = if quick {
                Vec::new()
            } else {
                let g = bench::general_timing(budget)?;
                let random = bench::random_rows_of(&timed);
                println!("{}", bench::general_timing_table(&g, random));
                g
            };
            let euler_general = if quick {
                None
            } else {
                let r = bench::general_euler_speedup(budget)?;
                print!("{}", bench::general_euler_text(&r));
                Some(r)
            };
            // one 10-drop fit (mdr-impact fit)
            let fit_time = bench::fit_timing()?;
            print!("{}", bench::fit_timing_text(&fit_time));
            let batch = if batch_rows > 0 {
                let rows = batch::random_rows(batch_rows, 1)?;
                let t0 = std::time::Instant::now();
                batch::solve_rows("random", &rows, &SolveOptions::default())?;
                let secs = t0.elapsed().as_secs_f64();
                println!("cor --input path: {batch_rows} rows in {secs:.2} s");
                Some((batch_rows, secs))
            } else {
                None
            };
            let curve_secs = {
                // curve over 200 velocities of the default scene
                use mdr_impact::apps::curve;
                let scene = Scene::default_scene();
                let range = curve::VelocityRange::parse("0.01:10:200", true)?;
                let t0 = std::time::Instant::now();
                curve::run(&scene.impact, &scene.options, &range, &|| {})?;
                let secs = t0.elapsed().as_secs_f64();
                println!("curve --v0 0.01:10:200 --log (default scene): {secs:.3} s");
                secs
            };
            if !timed.is_empty() {
                let random = bench::random_rows_of(&timed);
                print!(
                    "{}",
                    bench::targets(
                        &timed,
                        bench::speedup(&points),
                        batch,
                        &bench::general_targets(&general, random)
                    )
                );
            }
            if !quick {
                let mut section =
                    bench::summary(&points, &bench::machine(), batch, &timed, &general);
                section.push('\n');
                section.push_str(&bench::fit_timing_text(&fit_time));
                if let Some(r) = euler_general {
                    section.push('\n');
                    section.push_str(&bench::general_euler_text(&r));
                }
                section.push_str(&format!(
                    "\n`mdr-impact curve --v0 0.01:10:200 --log` on the default scene (200 \
                     velocities, all cores): {curve_secs:.3} s.\n"
                ));
                sections::update_section(&report, &sections::PERFORMANCE, &section)?;
                println!("performance section of {} updated", report.display());
            }
            Ok(())
        }
        Command::Stress {
            rows,
            seed,
            out,
            report,
        } => {
            use mdr_impact::report::stress;
            // read first: a missing report or markers fail before minutes of work
            sections::require_section(&report, &sections::STRESS)?;
            let bar = progress_bar(rows as u64, "stress");
            let r = stress::run(rows, seed, &|| bar.inc(1));
            bar.finish_and_clear();
            let section = r.markdown();
            print!("{section}");
            std::fs::create_dir_all(&out).map_err(|e| Error::io(&out, e))?;
            let csv = out.join("stress_outside.csv");
            r.write_problems_csv(&csv)?;
            sections::update_section(&report, &sections::STRESS, &section)?;
            println!(
                "stress section of {} updated; {} solves that broke the contract in {}",
                report.display(),
                r.problems.len(),
                csv.display()
            );
            if r.clean() {
                Ok(())
            } else {
                Err(Error::Unsupported(format!(
                    "stress: {} solves broke the contract (see {})",
                    r.problems.len(),
                    csv.display()
                )))
            }
        }
        Command::Reference { out } => {
            let written = mdr_impact::solvers::theory::generate_reference(&out)?;
            println!(
                "wrote {} files and {}",
                written.files.len(),
                written.manifest.display()
            );
            Ok(())
        }
        Command::Sweep {
            nu,
            log_p2,
            log_p3,
            random,
            seed,
            solver,
            rtol,
            out,
            dimensional,
            check_every,
            fresh,
        } => {
            use mdr_impact::apps::sweep;
            let plan = sweep::Plan {
                nu: sweep::parse_nu_list(&nu)?,
                log_p2: sweep::LogRange::parse("log-p2", &log_p2)?,
                log_p3: sweep::LogRange::parse("log-p3", &log_p3)?,
                sampling: match random {
                    Some(n) => sweep::Sampling::Random { n, seed },
                    None => sweep::Sampling::Grid,
                },
            };
            let opts = sweep::SweepOptions {
                solve: SolveOptions {
                    solver: solver.parse::<SolverKind>()?,
                    rtol,
                    ..Default::default()
                },
                dimensional: dimensional.then_some(seed),
                check_every,
                resume: !fresh,
            };
            let points = plan.points()?;
            let bar = progress_bar(points.len() as u64, &out.display().to_string());
            let summary = sweep::run(&points, &out, &opts, &|| bar.inc(1));
            bar.finish_and_clear();
            let summary = summary?;
            println!("{summary}");
            println!("rows in {}", out.display());
            Ok(())
        }
        Command::Fit {
            data,
            scene,
            model,
            fix,
            tau_range,
            out,
            json,
        } => {
            use mdr_impact::apps::fit;
            if out.as_os_str().is_empty() {
                return Err(Error::EmptyPath { field: "--out" });
            }
            let kind = model.parse::<fit::ModelKind>()?;
            let fixes = fix
                .iter()
                .map(|f| f.parse::<fit::Fix>())
                .collect::<Result<Vec<_>, _>>()?;
            let (scene, name) = match &scene {
                Some(p) => (Scene::load(p)?, p.display().to_string()),
                None => (Scene::default_scene(), "default scene".to_string()),
            };
            let sphere = fit::data::scene_sphere(&scene, &name)?;
            let data = fit::data::read(&data, sphere, &name)?;
            let taus = fit::prony_times(&kind, tau_range.as_deref(), &data)?;
            let (model, fixed) = fit::setup_model(kind, &fixes, taus)?;
            let result = fit::fit(&model, &data, &fixed)?;
            let written = fit::report::write_outputs(&out, &result)?;
            if json {
                println!("{}", fit::report::json(&result));
                eprintln!("material written to {}", written.toml.display());
                eprintln!("plot written to {}", written.svg.display());
            } else {
                print!("{}", fit::report::summary(&result, Some(&written)));
            }
            Ok(())
        }
        Command::FitStudy {
            reps,
            seed,
            velocities,
            noise,
            cor_only,
            report,
        } => {
            use mdr_impact::apps::fit::study;
            if let Some(p) = &report {
                sections::require_section(p, &sections::FIT_STUDY)?;
            }
            let mut reports = Vec::new();
            for contact_times in [true, false] {
                if cor_only && contact_times {
                    continue;
                }
                let cfg = study::StudyConfig {
                    reps,
                    seed,
                    noise,
                    velocities,
                    contact_times,
                };
                let bar = progress_bar(reps as u64, "fit-study");
                let r = study::run(&cfg, &|| bar.inc(1));
                bar.finish_and_clear();
                reports.push(r?);
            }
            let section = study::markdown(&reports);
            print!("{section}");
            if let Some(p) = &report {
                sections::update_section(p, &sections::FIT_STUDY, &section)?;
                println!("fit section of {} updated", p.display());
            }
            Ok(())
        }
        Command::Figures(args) => {
            let opts = figures::FigureOptions {
                out: args.out,
                solver: args.solver.parse::<SolverKind>()?,
                rtol: args.rtol,
                n_p2: args.n_p2,
                n_p3: args.n_p3,
                n_line: args.n_line,
                canonical: args.canonical,
                seed: args.seed,
                check_every: args.check_every,
                resume: args.resume,
                results: args.results,
            };
            let bar = if args.progress {
                progress_bar(opts.units(), "figures")
            } else {
                indicatif::ProgressBar::hidden()
            };
            let report = figures::run(&opts, &|| bar.inc(1));
            bar.finish_and_clear();
            let report = report?;
            print!("{report}");
            Ok(())
        }
    }
}
