//! The command line's flags: one variant of [`Command`] per subcommand.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};
use mdr_impact::apps::fit;
use mdr_impact::apps::indent::HistoryKind;
use mdr_impact::report::figures;
use mdr_impact::SolverKind;

use super::values;

#[derive(Parser)]
#[command(
    name = "mdr-impact",
    version,
    about = "Normal impact of a rigid sphere on a compressible viscoelastic half-space (MDR)"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand)]
pub enum Command {
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
        #[arg(long, value_enum)]
        format: values::Format,
        /// Log-spaced velocities (and a log velocity axis) instead of linear.
        #[arg(long)]
        log: bool,
        /// Hertz stiffness from the relaxed (E* = 4 G_eq(inf)) or glassy (E* = 4 G_eq(0))
        /// modulus.
        #[arg(long, value_enum, default_value_t = values::Modulus::Relaxed)]
        modulus: values::Modulus,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
    /// Coefficient of restitution from the dimensionless groups (Eq. 11).
    Cor {
        #[command(flatten)]
        groups: GroupArgs,
        /// CSV with header nu,p2,p3: writes nu,p2,p3,cor,contact_time,max_indentation to stdout.
        #[arg(long)]
        input: Option<PathBuf>,
        /// Solver.
        #[arg(long, default_value = "auto", value_parser = values::solver())]
        solver: SolverKind,
        /// Requested relative accuracy of the CoR.
        #[arg(long, allow_hyphen_values = true, default_value_t = mdr_impact::model::tolerances::DEFAULT_RTOL)]
        rtol: f64,
    },
    /// Force curve of a prescribed indentation (AFM / nanoindentation): CSV t,d,a,force on stdout.
    Indent {
        /// triangle (d = V t up to T, then V (2T - t)) or half-sine (d = V T sin(pi t / 2T)).
        #[arg(long, value_enum)]
        history: HistoryKind,
        /// Rate V (m/s).
        #[arg(long, allow_hyphen_values = true)]
        rate: f64,
        /// Time of the peak T (s).
        #[arg(long = "peak-time", allow_hyphen_values = true)]
        peak_time: f64,
        /// Sphere radius R (m).
        #[arg(long, allow_hyphen_values = true)]
        radius: f64,
        /// Relaxed shear modulus G_inf (Pa).
        #[arg(long = "g-inf", allow_hyphen_values = true)]
        g_inf: f64,
        /// Relaxing shear modulus G_1 (Pa).
        #[arg(long, allow_hyphen_values = true)]
        g1: f64,
        /// Shear viscosity eta (Pa s).
        #[arg(long, allow_hyphen_values = true)]
        eta: f64,
        /// Static Poisson ratio, -1 < nu <= 0.5 (0.5 = incompressible).
        #[arg(long, allow_hyphen_values = true)]
        nu: f64,
        /// theory (Lee-Radok/Ting) or mdr.
        #[arg(long, value_enum, default_value_t = values::Indent::Theory)]
        solver: values::Indent,
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
        #[arg(long, allow_hyphen_values = true, default_value_t = 0.3)]
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
        /// Solver.
        #[arg(long, default_value = "auto", value_parser = values::solver())]
        solver: SolverKind,
        /// Requested relative accuracy of each CoR.
        #[arg(long, allow_hyphen_values = true, default_value_t = mdr_impact::apps::sweep::DEFAULT_SWEEP_RTOL)]
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
        #[arg(long, default_value = "standard-solid", value_parser = values::model)]
        model: fit::ModelKind,
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
        #[arg(long, allow_hyphen_values = true, default_value_t = 0.01)]
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
pub struct FigureArgs {
    /// Output folder for the SVGs, CSVs and tables.md.
    #[arg(long, default_value = figures::DEFAULT_OUT)]
    pub out: PathBuf,
    /// Solver of every CoR.
    #[arg(long, default_value = "auto", value_parser = values::solver())]
    pub solver: SolverKind,
    /// Requested relative accuracy of each CoR.
    #[arg(long, allow_hyphen_values = true, default_value_t = mdr_impact::apps::sweep::DEFAULT_SWEEP_RTOL)]
    pub rtol: f64,
    /// Grid values of log10 p2 over [-3, 1] in the maps (>= 3).
    #[arg(long, default_value_t = figures::DEFAULT_N_P2)]
    pub n_p2: usize,
    /// Grid values of log10 p3 over [-2, 3] in the maps (>= 3).
    #[arg(long, default_value_t = figures::DEFAULT_N_P3)]
    pub n_p3: usize,
    /// Values of log10 p3 over [-2, 3] on the curves of Figs. 5 and 6 (>= 3).
    #[arg(long, default_value_t = figures::DEFAULT_N_LINE)]
    pub n_line: usize,
    /// Canonical units instead of random dimensional inputs (the paper drew them at random).
    #[arg(long)]
    pub canonical: bool,
    /// Seed of the random dimensional inputs.
    #[arg(long, default_value_t = figures::DEFAULT_SEED)]
    pub seed: u64,
    /// Scaling check on every K-th point (dimensional inputs only; 0: never).
    #[arg(long, value_name = "K", default_value_t = mdr_impact::apps::sweep::DEFAULT_CHECK_EVERY)]
    pub check_every: u64,
    /// Keep rows already in the data files (continue an interrupted run) instead of recomputing.
    #[arg(long)]
    pub resume: bool,
    /// Also replace the generated block of this Markdown file (e.g. RESULTS.md) by the tables.
    #[arg(long)]
    pub results: Option<PathBuf>,
    /// Show progress bars (on a terminal only).
    #[arg(long)]
    pub progress: bool,
}

/// The dimensionless groups of `cor` (all three, unless `--input` gives a file of them).
#[derive(Debug, Clone, Args)]
#[group(id = "groups", multiple = true, conflicts_with = "input")]
pub struct GroupArgs {
    /// Static Poisson ratio, -1 < nu <= 0.5 (0.5 = incompressible).
    #[arg(long, allow_hyphen_values = true, required_unless_present = "input")]
    pub nu: Option<f64>,
    /// p2 = G_inf / G_1, 0 < p2 < inf (finite).
    #[arg(long, allow_hyphen_values = true, required_unless_present = "input")]
    pub p2: Option<f64>,
    /// p3 = eta (v0 R / (m^2 G_inf^3))^(1/5), 0 <= p3 < inf (0: elastic, Hertz).
    #[arg(long, allow_hyphen_values = true, required_unless_present = "input")]
    pub p3: Option<f64>,
}
