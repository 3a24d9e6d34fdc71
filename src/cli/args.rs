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
    Run(RunArgs),
    /// CoR against impact velocity: the scene's impact (the embedded default when none is
    /// given) at N velocities; writes DIR/curve.csv and DIR/curve.svg. With --angle and
    /// --speed: the oblique impact at N incidence angles (DIR/curve.csv,
    /// DIR/tangential_cor.svg, DIR/rebound_angle.svg).
    Curve(CurveArgs),
    /// Parameters for DEM codes: the scene's e(v0) (the embedded default when none is given),
    /// the constant-CoR and viscoelastic damping laws fitted to it with their errors, and the
    /// Hertz stiffness; writes DIR/dem.csv, DIR/dem.svg and DIR/dem_lammps.in or
    /// DIR/dem_liggghts.in.
    Dem(DemArgs),
    /// Coefficient of restitution from the dimensionless groups (Eq. 11).
    Cor(CorArgs),
    /// Force curve of a prescribed indentation (AFM / nanoindentation) for any indenter shape:
    /// CSV t_s,d_m,a_m,force_N on stdout.
    Indent(IndentArgs),
    /// Run the validation catalogue and write VALIDATION.md with its figures.
    Validate(ValidateArgs),
    /// Work-precision benchmark of every solver; writes CSV, plot and the performance section.
    Bench(BenchArgs),
    /// Stress test: random groups over the whole input range, `auto` and `fast` at every rtol
    /// from 1e-2 to 1e-11 against the reference; writes the stress section of the report and the
    /// rows that break the contract.
    Stress(StressArgs),
    /// Regenerate the reference force histories and their manifest.
    Reference(ReferenceArgs),
    /// CoR over a grid or random sample of (nu, p2, p3); rows appended to a CSV, resumable.
    Sweep(SweepArgs),
    /// Regenerate the paper's figures (SVG), the data behind them (CSV) and the result tables.
    Figures(FigureArgs),
    /// Identify material parameters from drop tests (CSV v0,cor[,cor_sd,contact_time,
    /// contact_time_sd,setup]); writes DIR/fit.toml and DIR/fit.svg.
    Fit(FitArgs),
    /// Round trip of fit: synthetic drop tests from a known material with noise, fitted again;
    /// prints the coverage of the 95 % intervals (with --report, fills its section of the report).
    FitStudy(FitStudyArgs),
    /// Prony series and shift law from DMA data (CSV frequency|omega,storage,loss[,temperature]);
    /// writes DIR/material.toml, prony.csv, master.csv and dma.svg (docs/dma.md).
    Prony(PronyArgs),
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

// `run` (its help text is the doc comment of Command::Run)
#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    /// Scene file (TOML); see README for the format.
    pub scene: Option<PathBuf>,
    /// Print the outcome as one JSON object (SI units) and nothing else on stdout.
    #[arg(long)]
    pub json: bool,
    /// Write DIR/history.csv, DIR/force.svg and DIR/force_indentation.svg (instead of the
    /// scene's [output] files). Without it and without [output], no file is written.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

// `curve` (its help text is the doc comment of Command::Curve)
#[derive(Debug, Clone, Args)]
pub struct CurveArgs {
    /// Scene file (TOML); its sphere, material and solver are used, its velocity and
    /// [output] are not.
    pub scene: Option<PathBuf>,
    /// Velocities MIN:MAX[:N] in m/s (0 < MIN < MAX, 2 <= N <= 100000; N defaults to 50).
    #[arg(
        long,
        allow_hyphen_values = true,
        required_unless_present_any = ["temperature", "angle"]
    )]
    pub v0: Option<String>,
    /// Incidence angles MIN:MAX:N in degrees from the normal (0 <= MIN < MAX < 90,
    /// 2 <= N <= 10000) at the speed --speed; the scene's [friction], spin and inertia
    /// factors are kept. Not together with --v0 or --temperature.
    #[arg(long, conflicts_with_all = ["v0", "temperature", "log"], requires = "speed")]
    pub angle: Option<String>,
    /// Impact speed (m/s) of an --angle curve.
    #[arg(long, requires = "angle", allow_hyphen_values = true)]
    pub speed: Option<f64>,
    /// Temperatures MIN:MAX:N in °C at the scene's velocity instead of velocities (the
    /// scene's materials need a [material.shift] law); not together with --v0.
    #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["v0", "log"])]
    pub temperature: Option<String>,
    /// Log-spaced velocities (and a log velocity axis) instead of linear.
    #[arg(long)]
    pub log: bool,
    /// Output folder.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
}

// `dem` (its help text is the doc comment of Command::Dem)
#[derive(Debug, Clone, Args)]
pub struct DemArgs {
    /// Scene file (TOML); its sphere(s), material(s) and solver are used, its velocity and
    /// [output] are not.
    pub scene: Option<PathBuf>,
    /// Velocities MIN:MAX[:N] in m/s (0 < MIN < MAX, 2 <= N <= 100000; N defaults to 50).
    #[arg(long, allow_hyphen_values = true)]
    pub v0: String,
    /// Output: lammps or liggghts (input lines on stdout and in DIR), or json (one object
    /// on stdout).
    #[arg(long, value_enum)]
    pub format: values::Format,
    /// Log-spaced velocities (and a log velocity axis) instead of linear.
    #[arg(long)]
    pub log: bool,
    /// Hertz stiffness from the relaxed (E* = 4 G_eq(inf)) or glassy (E* = 4 G_eq(0))
    /// modulus.
    #[arg(long, value_enum, default_value_t = values::Modulus::Relaxed)]
    pub modulus: values::Modulus,
    /// LAMMPS version YYYYMMDD (the date `lmp -h` prints) the lammps lines are for;
    /// default: current LAMMPS.
    #[arg(long)]
    pub lammps_version: Option<String>,
    /// Output folder.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
}

// `cor` (its help text is the doc comment of Command::Cor)
#[derive(Debug, Clone, Args)]
pub struct CorArgs {
    #[command(flatten)]
    pub groups: GroupArgs,
    /// CSV with header nu,p2,p3: writes
    /// nu,p2,p3,cor,contact_time_canonical,max_indentation_canonical to stdout (units
    /// m = R = v0 = G_inf = 1).
    #[arg(long)]
    pub input: Option<PathBuf>,
    /// Print one JSON object (the groups, the CoR, contact time and indentation in canonical
    /// units, the solver and why) and nothing else on stdout; not with --input (CSV).
    #[arg(long, conflicts_with = "input")]
    pub json: bool,
    /// Solver.
    #[arg(long, default_value = "auto", value_parser = values::solver())]
    pub solver: SolverKind,
    /// Requested relative accuracy of the CoR.
    #[arg(long, allow_hyphen_values = true, default_value_t = mdr_impact::model::tolerances::DEFAULT_RTOL)]
    pub rtol: f64,
}

// `indent` (its help text is the doc comment of Command::Indent)
#[derive(Debug, Clone, Args)]
pub struct IndentArgs {
    /// triangle (d = V t up to T, then V (2T - t)) or half-sine (d = V T sin(pi t / 2T)).
    #[arg(long, value_enum)]
    pub history: HistoryKind,
    /// Rate V (m/s).
    #[arg(long, allow_hyphen_values = true)]
    pub rate: f64,
    /// Time of the peak T (s).
    #[arg(long = "peak-time", allow_hyphen_values = true)]
    pub peak_time: f64,
    /// The indenter: paraboloid (Hertz, the default), sphere (the exact cap), cone, power-law or
    /// flat (a flat-ended cylinder); with --scene and no --shape, the scene's indenter.
    #[arg(long)]
    pub shape: Option<String>,
    /// Radius R (m) of a paraboloid or sphere, the punch radius of a flat punch.
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<f64>,
    /// Cone half angle (degrees between the axis and the face), e.g. 70.3 (Berkovich-equivalent).
    #[arg(long = "half-angle", allow_hyphen_values = true)]
    pub half_angle: Option<f64>,
    /// Power-law exponent n of f = c r^n.
    #[arg(long, allow_hyphen_values = true)]
    pub exponent: Option<f64>,
    /// Power-law coefficient c of f = c r^n (m^(1 - n)).
    #[arg(long, allow_hyphen_values = true)]
    pub coefficient: Option<f64>,
    /// A scene whose half-space material (any Prony series) replaces the standard-solid flags.
    #[arg(long, conflicts_with_all = ["g_inf", "g1", "eta", "nu"])]
    pub scene: Option<PathBuf>,
    /// Relaxed shear modulus G_inf (Pa).
    #[arg(long = "g-inf", allow_hyphen_values = true)]
    pub g_inf: Option<f64>,
    /// Relaxing shear modulus G_1 (Pa).
    #[arg(long, allow_hyphen_values = true)]
    pub g1: Option<f64>,
    /// Shear viscosity eta (Pa s).
    #[arg(long, allow_hyphen_values = true)]
    pub eta: Option<f64>,
    /// Static Poisson ratio, -1 < nu <= 0.5 (0.5 = incompressible).
    #[arg(long, allow_hyphen_values = true)]
    pub nu: Option<f64>,
    /// theory (Lee-Radok/Ting) or mdr.
    #[arg(long, value_enum, default_value_t = values::Indent::Theory)]
    pub solver: values::Indent,
    /// Output times (s), comma separated; default: 101 uniform points over [0, 2T].
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub times: Option<Vec<f64>>,
}

// `validate` (its help text is the doc comment of Command::Validate)
#[derive(Debug, Clone, Args)]
pub struct ValidateArgs {
    /// The report to write.
    #[arg(long, default_value = "VALIDATION.md")]
    pub out: PathBuf,
    /// Folder of the figures.
    #[arg(long, default_value = "validation")]
    pub figures: PathBuf,
    /// Do not write: fail when the committed report differs from a fresh run.
    #[arg(long)]
    pub check: bool,
}

// `bench` (its help text is the doc comment of Command::Bench)
#[derive(Debug, Clone, Args)]
pub struct BenchArgs {
    /// One case, one setting per solver, no report update (CI smoke test).
    #[arg(long)]
    pub quick: bool,
    /// Folder for bench.csv and work-precision.svg.
    #[arg(long, default_value = "validation")]
    pub out: PathBuf,
    /// Report whose performance section is replaced (not with --quick).
    #[arg(long, default_value = "VALIDATION.md")]
    pub report: PathBuf,
    /// Seconds of repeats per timed point.
    #[arg(long, allow_hyphen_values = true, default_value_t = 0.3)]
    pub budget: f64,
    /// Also time `cor --input` on this many random rows, and its solves alone, verified and
    /// unverified (0: skip).
    #[arg(long, default_value_t = 0)]
    pub batch_rows: usize,
    /// An earlier build of mdr-impact (scripts/build-baseline.sh prints its path): times its
    /// `cor --input --solver fast` against this build's on the same rows, one thread each.
    #[arg(long)]
    pub baseline_bin: Option<PathBuf>,
}

// `stress` (its help text is the doc comment of Command::Stress)
#[derive(Debug, Clone, Args)]
pub struct StressArgs {
    /// Number of random rows.
    #[arg(long, default_value_t = mdr_impact::report::stress::DEFAULT_ROWS)]
    pub rows: usize,
    /// Seed of the rows.
    #[arg(long, default_value_t = mdr_impact::report::stress::DEFAULT_SEED)]
    pub seed: u64,
    /// Folder for stress_outside.csv.
    #[arg(long, default_value = "validation")]
    pub out: PathBuf,
    /// Report whose stress section is replaced; default: VALIDATION.md when there is one in
    /// the working directory (the repository's), else no report is updated.
    #[arg(long)]
    pub report: Option<PathBuf>,
}

// `reference` (its help text is the doc comment of Command::Reference)
#[derive(Debug, Clone, Args)]
pub struct ReferenceArgs {
    /// Output folder.
    #[arg(long, default_value = "reference")]
    pub out: PathBuf,
}

// `sweep` (its help text is the doc comment of Command::Sweep)
#[derive(Debug, Clone, Args)]
pub struct SweepArgs {
    /// Static Poisson ratios, comma-separated, in (-1, 0.5]; 'inc' = 0.5 (incompressible).
    #[arg(long, default_value = "0.45", allow_hyphen_values = true)]
    pub nu: String,
    /// log10 p2 grid as MIN:MAX:N (MIN:MAX is enough with --random).
    #[arg(long, default_value = "-3:1:41", allow_hyphen_values = true)]
    pub log_p2: String,
    /// log10 p3 grid as MIN:MAX:N (MIN:MAX is enough with --random).
    #[arg(long, default_value = "-2:3:51", allow_hyphen_values = true)]
    pub log_p3: String,
    /// Random sample of N points instead of the grid.
    #[arg(long, value_name = "N")]
    pub random: Option<usize>,
    /// Seed of the random sample and of the dimensional inputs.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Solver.
    #[arg(long, default_value = "auto", value_parser = values::solver())]
    pub solver: SolverKind,
    /// Requested relative accuracy of each CoR.
    #[arg(long, allow_hyphen_values = true, default_value_t = mdr_impact::apps::sweep::DEFAULT_SWEEP_RTOL)]
    pub rtol: f64,
    /// Output CSV; rows already there are kept and their points skipped (resume).
    #[arg(long)]
    pub out: PathBuf,
    /// Random dimensional inputs (m, R, v0, G_inf drawn) instead of canonical units.
    #[arg(long)]
    pub dimensional: bool,
    /// With --dimensional, also solve every K-th point in canonical units (0: never).
    #[arg(long, value_name = "K", default_value_t = mdr_impact::apps::sweep::DEFAULT_CHECK_EVERY)]
    pub check_every: u64,
    /// Discard the rows already in the output file instead of resuming.
    #[arg(long)]
    pub fresh: bool,
}

// `fit` (its help text is the doc comment of Command::Fit)
#[derive(Debug, Clone, Args)]
pub struct FitArgs {
    /// The data file.
    pub data: PathBuf,
    /// Scene whose sphere was dropped (rows without a setup column); default scene if absent.
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// standard-solid or prony:N (N fixed log-spaced times, fitted moduli).
    #[arg(long, default_value = "standard-solid", value_parser = values::model)]
    pub model: fit::ModelKind,
    /// Fix a parameter, name=value in SI (g_inf, g_1, eta, nu, k_0; prony: g_inf, g_1..g_N,
    /// nu, k_0); repeatable.
    #[arg(long = "fix", value_name = "NAME=VALUE")]
    pub fix: Vec<String>,
    /// Prony times MIN:MAX (s), log-spaced; default: the measured contact times / 100 to x 100.
    #[arg(long = "tau-range")]
    pub tau_range: Option<String>,
    /// Output folder for fit.toml and fit.svg.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// Print one JSON object (SI) and nothing else on stdout.
    #[arg(long)]
    pub json: bool,
}

// `fitstudy` (its help text is the doc comment of Command::FitStudy)
#[derive(Debug, Clone, Args)]
pub struct FitStudyArgs {
    /// Repetitions.
    #[arg(long, default_value_t = 200)]
    pub reps: usize,
    /// Seed of the noise.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Drops (velocities) per repetition.
    #[arg(long, default_value_t = 10)]
    pub velocities: usize,
    /// Relative noise of every measured value.
    #[arg(long, allow_hyphen_values = true, default_value_t = 0.01)]
    pub noise: f64,
    /// Only the CoR-only study (default: both, with and without contact times).
    #[arg(long, conflicts_with = "across_box")]
    pub cor_only: bool,
    /// The study across the parameter box instead: `--sets` data sets, each with its own truth
    /// (nu free and fixed, nu near 0.5, CoR only and with contact times, 1 % and 5 % noise).
    #[arg(long = "box", conflicts_with_all = ["reps", "noise"])]
    pub across_box: bool,
    /// Data sets of the study across the box.
    #[arg(long, default_value_t = 640, requires = "across_box")]
    pub sets: usize,
    /// Only these sets of the box study (comma-separated indices below --sets; each set's
    /// truth and noise depend only on the seed and its index).
    #[arg(
        long,
        value_delimiter = ',',
        requires = "across_box",
        conflicts_with = "report"
    )]
    pub only: Vec<u64>,
    /// Per-set outcomes of the box study as CSV (truth, estimate, 95 % interval and status of
    /// every quantity, misfits at the estimate and the truth).
    #[arg(long, requires = "across_box")]
    pub csv: Option<PathBuf>,
    /// Report whose fit section (or, with `--box`, fit-box section) is replaced.
    #[arg(long)]
    pub report: Option<PathBuf>,
}

// `prony` (its help text is the doc comment of Command::Prony)
#[derive(Debug, Args)]
pub struct PronyArgs {
    /// The DMA data file.
    pub data: PathBuf,
    /// auto, or at most N terms.
    #[arg(long, default_value = "auto", allow_hyphen_values = true)]
    pub terms: String,
    /// shear (G', G'') or tensile (E', E'', converted with --nu).
    #[arg(long, value_enum, default_value_t = values::DmaModulus::Shear)]
    pub modulus: values::DmaModulus,
    /// Poisson ratio (tensile conversion, default 0.5; bulk of material.toml).
    #[arg(long, allow_hyphen_values = true)]
    pub nu: Option<f64>,
    /// Reference temperature (°C); default: the isotherm nearest 25 °C.
    #[arg(long = "t-ref", allow_hyphen_values = true)]
    pub t_ref: Option<f64>,
    /// Shift law fitted to the isotherms' shift factors.
    #[arg(long, value_enum, default_value_t = values::Shift::Wlf)]
    pub shift: values::Shift,
    /// Output folder.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// Print one JSON object and nothing else on stdout.
    #[arg(long)]
    pub json: bool,
}
