//! `mdr-impact`: the command line. Parses, calls the library, prints; nothing else.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use mdr_impact::{
    batch, output, plot, scene::Scene, solve, Error, Groups, Impact, SolveOptions, SolverKind,
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
        /// p2 = G_inf / G_1 (> 0).
        #[arg(long, required_unless_present = "input", conflicts_with = "input")]
        p2: Option<f64>,
        /// p3 = eta (v0 R / (m^2 G_inf^3))^(1/5) (>= 0).
        #[arg(long, required_unless_present = "input", conflicts_with = "input")]
        p3: Option<f64>,
        /// CSV with header nu,p2,p3: writes nu,p2,p3,cor,contact_time,max_indentation to stdout.
        #[arg(long)]
        input: Option<PathBuf>,
        /// Solver: auto, mdr, mdr-euler, reference.
        #[arg(long, default_value = "auto")]
        solver: String,
        /// Requested relative accuracy of the CoR.
        #[arg(long, default_value_t = mdr_impact::tolerances::DEFAULT_RTOL)]
        rtol: f64,
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
        /// Solver name (auto, mdr, mdr-euler, ...).
        #[arg(long, default_value = "auto")]
        solver: String,
        /// Requested relative accuracy of each CoR.
        #[arg(long, default_value_t = mdr_impact::sweep::DEFAULT_SWEEP_RTOL)]
        rtol: f64,
        /// Output CSV; rows already there are kept and their points skipped (resume).
        #[arg(long)]
        out: PathBuf,
        /// Random dimensional inputs (m, R, v0, G_inf drawn) instead of canonical units.
        #[arg(long)]
        dimensional: bool,
        /// With --dimensional, also solve every K-th point in canonical units (0: never).
        #[arg(long, value_name = "K", default_value_t = mdr_impact::sweep::DEFAULT_CHECK_EVERY)]
        check_every: u64,
        /// Discard the rows already in the output file instead of resuming.
        #[arg(long)]
        fresh: bool,
    },
    /// Regenerate the paper's figures (SVG), the data behind them (CSV) and the result tables.
    Figures(mdr_impact::figures::FigureArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
    }
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command.unwrap_or(Command::Run { scene: None }) {
        Command::Run { scene } => {
            let scene = match scene {
                Some(p) => Scene::load(&p)?,
                None => Scene::default_scene(),
            };
            let outcome = solve(&scene.impact, &scene.options)?;
            print!("{}", output::summary(&scene.impact, &outcome));
            if let Some(h) = &outcome.history {
                if let Some(p) = &scene.history_csv {
                    output::write_history_csv(p, h)?;
                    println!("{:<28}{}", "history written to", p.display());
                }
                if let Some(p) = &scene.plot {
                    plot::force_history_svg(p, h, "Contact force")?;
                    println!("{:<28}{}", "force plot written to", p.display());
                }
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
                let rows = batch::read_rows(&path)?;
                let outcomes = batch::solve_rows(&path.display().to_string(), &rows, &opts)?;
                let mut buf = Vec::new();
                batch::write_results(&mut buf, &rows, &outcomes)?;
                std::io::stdout()
                    .write_all(&buf)
                    .map_err(|e| Error::io("<stdout>", e))?;
            } else {
                // clap guarantees all three are present without --input
                let (nu, p2, p3) = (
                    nu.unwrap_or(f64::NAN),
                    p2.unwrap_or(f64::NAN),
                    p3.unwrap_or(f64::NAN),
                );
                let impact = Impact::from_groups(Groups::new(nu, p2, p3)?)?;
                let o = solve(&impact, &opts)?;
                println!("{}", o.cor);
            }
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
            use mdr_impact::sweep;
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
                progress: true,
                resume: !fresh,
            };
            let summary = sweep::run(&plan.points()?, &out, &opts)?;
            println!("{summary}");
            println!("rows in {}", out.display());
            Ok(())
        }
        Command::Figures(args) => {
            let report = mdr_impact::figures::run(&args)?;
            print!("{report}");
            Ok(())
        }
    }
}
