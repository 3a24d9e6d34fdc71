//! One function per subcommand: it calls one library entry point and prints.

use std::io::Write;
use std::path::Path;

use mdr_impact::apps::{batch, curve, dem, dma, fit, indent, sweep};
use mdr_impact::error::escape_text;
use mdr_impact::io::run_files::RunFiles;
use mdr_impact::io::{oblique as oblique_out, output, scene::Scene};
use mdr_impact::model::geometry::{Shape, ShapeKeys};
use mdr_impact::report::{bench, figures, sections, stress, validate};
use mdr_impact::solvers::oblique::solve_oblique;
use mdr_impact::{solve, Error, Groups, Impact, Material, SolveOptions};

use super::args::*;
use super::{progress_bar, with_progress, with_spinner, Failure, Outcome};

/// `println!` through [`stdout`]: a write error (a full disk, a closed file) is the command's
/// error instead of a panic.
macro_rules! outln {
    () => {
        stdout("\n")?
    };
    ($($t:tt)*) => {
        stdout(&(format!($($t)*) + "\n"))?
    };
}

/// `print!` through [`stdout`], as [`outln`].
macro_rules! out {
    ($($t:tt)*) => {
        stdout(&format!($($t)*))?
    };
}

/// Run one parsed command (none: `run` on the default scene); what it printed is flushed, and a
/// failed write is its error.
pub fn run(command: Option<Command>) -> Outcome {
    run_command(command)?;
    std::io::stdout()
        .flush()
        .map_err(|e| Error::io("<stdout>", e).into())
}

fn run_command(command: Option<Command>) -> Outcome {
    let default = RunArgs {
        scene: None,
        json: false,
        out: None,
    };
    match command.unwrap_or(Command::Run(default)) {
        Command::Run(a) => cmd_run(a),
        Command::Curve(a) => cmd_curve(a),
        Command::Dem(a) => cmd_dem(a),
        Command::Cor(a) => cmd_cor(a),
        Command::Indent(a) => cmd_indent(a),
        Command::Validate(a) => cmd_validate(a),
        Command::Bench(a) => cmd_bench(a),
        Command::Stress(a) => cmd_stress(a),
        Command::Reference(a) => cmd_reference(a),
        Command::Sweep(a) => cmd_sweep(a),
        Command::Fit(a) => cmd_fit(a),
        Command::FitStudy(a) => cmd_fit_study(a),
        Command::Prony(a) => cmd_prony(a),
        Command::Figures(a) => cmd_figures(a),
    }
}

/// Write `text` to stdout in one piece.
fn stdout(text: &str) -> Outcome {
    std::io::stdout()
        .write_all(text.as_bytes())
        .map_err(|e| Error::io("<stdout>", e).into())
}

/// The scene at `path`, or the embedded default.
fn scene_or_default(path: Option<&Path>) -> Result<Scene, Error> {
    path.map_or_else(|| Ok(Scene::default_scene()), Scene::load)
}

fn cmd_run(RunArgs { scene, json, out }: RunArgs) -> Outcome {
    let name = scene_name(scene.as_deref());
    let mut scene = scene_or_default(scene.as_deref())?;
    let files = match &out {
        Some(dir) => RunFiles::in_folder(dir),
        None => RunFiles::of_scene(&scene),
    };
    scene.options.history = files.any();
    let what = format!("solving ({})", scene.options.solver.name());
    let (ob, opts) = (&scene.oblique, &scene.options);
    let oo = with_spinner(&what, || solve_oblique(&scene.impact, ob, opts))?;
    let outcome = &oo.normal;
    // rendered first and written together: a failure leaves none of them
    let mut rendered = files.render(&name, &scene.impact, outcome)?;
    if oblique_out::reports_tangential(ob) {
        let path = files.history.as_ref().map(|(_, p)| p.as_path());
        oblique_out::with_tangential_history(&mut rendered, path, &oo);
    }
    output::write_outputs(&rendered)?;
    if json {
        outln!(
            "{}",
            oblique_out::oblique_json(&scene.impact, opts, ob, &oo, &scene.warnings)
        );
    } else {
        for (table, log10_a) in &scene.shifts {
            let log10_a = log10_a + 0.0; // no "-0.0000" at the reference temperature
            let at = match scene.temperature {
                Some(t) => format!("{} °C", mdr_impact::model::material::shift::celsius_text(t)),
                None => "its reference temperature".to_string(),
            };
            outln!(
                "{:<28}a_T = {:.6e} (log10 a_T = {log10_a:.4}) at {at}, {table}",
                "time-temperature shift",
                10f64.powf(log10_a)
            );
        }
        out!(
            "{}",
            oblique_out::oblique_summary(&scene.impact, opts, ob, &oo)
        );
        for w in &scene.warnings {
            outln!("{:<28}{w}", "warning");
        }
    }
    // with --json, stdout holds the JSON object alone; notes go to stderr
    for (what, path) in files.described() {
        match json {
            true => eprintln!("{what:<28}{}", path.display()),
            false => outln!("{what:<28}{}", path.display()),
        }
    }
    if !json && !files.any() {
        outln!(
            "{:<28}none (ask with --out DIR or the scene's [output])",
            "files written"
        );
    }
    Ok(())
}

/// The scene's own warnings ([`Scene::warnings`]) on stderr, for the commands whose stdout is
/// a summary of many solves.
fn warn_scene(scene: &Scene) {
    for w in &scene.warnings {
        eprintln!("warning: {w}");
    }
}

/// How plots name a scene: its file stem, or "default scene".
fn scene_name(path: Option<&Path>) -> String {
    path.and_then(|p| p.file_stem())
        .map_or("default scene".into(), |s| s.to_string_lossy().into_owned())
}

fn cmd_curve(
    CurveArgs {
        scene,
        v0,
        temperature,
        angle,
        speed,
        log,
        out,
    }: CurveArgs,
) -> Outcome {
    if let (Some(a), Some(v)) = (angle, speed) {
        return cmd_curve_angle(scene.as_deref(), &a, v, &out);
    }
    if let Some(t) = temperature {
        return cmd_curve_temperature(scene.as_deref(), &t, &out);
    }
    // clap requires --v0 without --temperature
    let v0 = v0.unwrap_or_default();
    // the input is checked before the scene is read or anything solved
    let range = curve::VelocityRange::parse(&v0, log)?;
    let name = scene_name(scene.as_deref());
    let scene = scene_or_default(scene.as_deref())?;
    let c = with_progress(range.n as u64, "curve", |tick| {
        curve::run(&scene.impact, &scene.options, &range, tick)
    })?;
    let written = curve::write_outputs(&out, &c, log, &name)?;
    out!("{}", curve::summary(&c, Some(&written)));
    warn_scene(&scene);
    Ok(())
}

/// `curve --angle --speed`: the scene's oblique impact over incidence angles.
fn cmd_curve_angle(scene: Option<&Path>, spec: &str, speed: f64, out: &Path) -> Outcome {
    use mdr_impact::apps::curve_angle as ca;
    let range = ca::AngleRange::parse(spec)?;
    ca::check_speed(speed)?;
    let name = scene_name(scene);
    let scene = scene_or_default(scene)?;
    let rows = with_progress(range.n as u64, "curve", |tick| {
        ca::run(
            &scene.impact,
            &scene.oblique,
            &scene.options,
            &range,
            speed,
            tick,
        )
    })?;
    for path in ca::write_outputs(out, &rows, &name)? {
        outln!("{:<28}{}", "written", path.display());
    }
    warn_scene(&scene);
    Ok(())
}

/// `curve --temperature`: the scene at its velocity over temperatures.
fn cmd_curve_temperature(scene: Option<&Path>, spec: &str, out: &Path) -> Outcome {
    use mdr_impact::apps::curve_temperature as ct;
    let range = ct::TemperatureRange::parse(spec)?;
    let (text, base, name) = match scene {
        Some(p) => (
            std::fs::read_to_string(p).map_err(|e| Error::io(p, e))?,
            p.parent().unwrap_or(Path::new("")).to_path_buf(),
            p.file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy().into_owned()),
        ),
        None => (
            mdr_impact::io::scene::DEFAULT_SCENE.to_string(),
            Default::default(),
            "default scene".into(),
        ),
    };
    let (rows, warnings) = with_progress(range.n as u64, "curve", |tick| {
        ct::run(&text, &base, &range.values(), tick)
    })?;
    let title = format!("Coefficient of restitution against temperature: {name}");
    let written = ct::write_outputs(out, &rows, &title)?;
    out!("{}", ct::summary(&rows, Some(&written)));
    for w in &warnings {
        eprintln!("warning: {w}");
    }
    Ok(())
}

fn cmd_dem(a: DemArgs) -> Outcome {
    let format = a.format.with_lammps_version(a.lammps_version.as_deref())?;
    let modulus = a.modulus.into();
    // the input is checked before the scene is read or anything solved
    let range = curve::VelocityRange::parse(&a.v0, a.log)?;
    let scene = scene_or_default(a.scene.as_deref())?;
    let mut report = with_progress(range.n as u64, "dem", |tick| {
        dem::run(&scene.impact, &scene.options, &range, modulus, tick)
    })?;
    report.warnings.splice(0..0, scene.warnings.iter().cloned());
    let written = dem::write_outputs(&a.out, &report, format)?;
    out!("{}", report.text(format));
    if format == dem::Format::Json {
        outln!();
    }
    for w in &report.warnings {
        eprintln!("warning: {w}");
    }
    for f in &written.files {
        eprintln!("{:<28}{}", "written", f.display());
    }
    Ok(())
}

fn cmd_cor(a: CorArgs) -> Outcome {
    let opts = SolveOptions {
        solver: a.solver,
        rtol: a.rtol,
        ..Default::default()
    };
    opts.validate()?;
    if let Some(path) = &a.input {
        let input = batch::read_rows(path)?;
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
            let s = if skipped.len() == 1 { "" } else { "s" };
            let lines = batch::format_line_list(skipped);
            eprintln!(
                "note: {}: skipped blank line{s} {lines}",
                escape_text(&file)
            );
        }
        return Ok(());
    }
    // clap guarantees all three are present without --input
    let g = |x: Option<f64>| x.unwrap_or(f64::NAN);
    let (nu, p2, p3) = (g(a.groups.nu), g(a.groups.p2), g(a.groups.p3));
    let groups = Groups::new(nu, p2, p3)?;
    let impact = Impact::from_groups(groups)?;
    let o = solve(&impact, &opts)?;
    if a.json {
        outln!("{}", output::groups_json(&groups, &impact, &opts, &o));
        return Ok(());
    }
    if let Some(why) = o.fallback_reason() {
        eprintln!("note: answered by {} ({})", o.solver, escape_text(&why));
    }
    outln!("{}", o.cor);
    Ok(())
}

fn cmd_indent(a: IndentArgs) -> Outcome {
    let scene = a.scene.as_deref().map(Scene::load).transpose()?;
    let material = match &scene {
        Some(s) => s
            .impact
            .half_space()
            .cloned()
            .ok_or_else(|| Error::Unsupported("indent --scene: a two-body scene has no half-space material; give a scene with [sphere] or [indenter] and [material]".into()))?,
        None => {
            let need = |flag: &str, v: Option<f64>| {
                v.ok_or_else(|| {
                    Error::Unsupported(format!(
                        "indent: missing {flag}: give --g-inf, --g1, --eta and --nu (a standard \
                         solid) or --scene SCENE.toml (any material)"
                    ))
                })
            };
            Material::with_poisson(
                need("--g-inf", a.g_inf)?,
                need("--g1", a.g1)?,
                need("--eta", a.eta)?,
                need("--nu", a.nu)?,
            )?
        }
    };
    let keys = ShapeKeys {
        radius: a.radius,
        half_angle_deg: a.half_angle,
        exponent: a.exponent,
        coefficient: a.coefficient,
    };
    let shape = match (&a.shape, &scene) {
        (None, Some(s)) if keys.radius.is_none() => *s.impact.shape(),
        (name, _) => Shape::from_keys(
            name.as_deref().unwrap_or("paraboloid"),
            &keys,
            ["--radius", "--half-angle", "--exponent", "--coefficient"],
        )
        .map_err(|m| Error::Unsupported(format!("indent --shape: {m}")))?,
    };
    let (kind, rate, peak, times) = (a.history, a.rate, a.peak_time, a.times.as_deref());
    let rows = indent::run(&material, &shape, kind, rate, peak, times, a.solver.into())?;
    // stdout holds the CSV alone
    if let Some(scene) = &scene {
        warn_scene(scene);
    }
    for w in indent::warnings(&shape, &rows) {
        eprintln!("warning: {w}");
    }
    stdout(&indent::csv(&rows))
}

fn cmd_validate(
    ValidateArgs {
        out,
        figures,
        check,
    }: ValidateArgs,
) -> Outcome {
    let (out, figures) = (out.as_path(), figures.as_path());
    let units = validate::units();
    if check {
        let c = with_progress(units, "validate", |tick| validate::check(out, tick))?;
        if let Some(t) = validate::per_regime(&c.fresh) {
            outln!("{t}");
        }
        if let validate::Staleness::Stale { line, .. } = c.staleness {
            let report = out.to_path_buf();
            return Err(Failure::Stale { report, line });
        }
        outln!("{} is current", out.display());
    } else {
        let fresh = with_progress(units, "validate", |tick| {
            validate::regenerate(out, figures, tick)
        })?;
        if let Some(t) = validate::per_regime(&fresh) {
            outln!("{t}");
        }
        outln!("wrote {}", out.display());
    }
    Ok(())
}

fn cmd_bench(a: BenchArgs) -> Outcome {
    let (out, report) = (a.out.as_path(), a.report.as_path());
    let opts = &bench::BenchOptions {
        quick: a.quick,
        budget: a.budget,
        batch_rows: a.batch_rows,
        baseline: a.baseline_bin.clone(),
    };
    if !opts.quick {
        // a missing report or markers fail before minutes of work
        sections::require_section(report, &sections::PERFORMANCE)?;
    }
    let units = bench::full_units(opts)?;
    let r = with_progress(units, "bench", |tick| bench::run_full(opts, tick))?;
    r.write_files(out)?;
    out!("{}", r.text());
    if !opts.quick {
        sections::update_section(report, &sections::PERFORMANCE, &r.section())?;
        outln!("performance section of {} updated", report.display());
    }
    Ok(())
}

fn cmd_stress(a: StressArgs) -> Outcome {
    let (rows, seed, out) = (a.rows, a.seed, a.out.as_path());
    // outside the repository there is no VALIDATION.md: the section is printed, not filed
    let default = Path::new(DEFAULT_REPORT);
    let report = a
        .report
        .as_deref()
        .or_else(|| default.exists().then_some(default));
    if let Some(report) = report {
        // a missing report or markers fail before minutes of work
        sections::require_section(report, &sections::STRESS)?;
    }
    let r = with_progress(rows as u64, "stress", |tick| stress::run(rows, seed, tick));
    let section = r.markdown();
    out!("{section}");
    let csv = out.join("stress_outside.csv");
    r.write_problems_csv(&csv)?;
    let (n, path) = (r.problems.len(), csv.display());
    match report {
        Some(report) => {
            sections::update_section(report, &sections::STRESS, &section)?;
            outln!(
                "stress section of {} updated; {n} solves that broke the contract in {path}",
                report.display()
            );
        }
        None => outln!(
            "no report updated (no {DEFAULT_REPORT} here; --report FILE names one); {n} solves \
             that broke the contract in {path}"
        ),
    }
    match r.clean() {
        true => Ok(()),
        false => Err(Failure::ContractBroken { problems: n, csv }),
    }
}

/// The report `stress` updates by default, when the working directory has it.
const DEFAULT_REPORT: &str = "VALIDATION.md";

fn cmd_reference(a: ReferenceArgs) -> Outcome {
    let written = mdr_impact::solvers::theory::generate_reference(&a.out)?;
    let (n, manifest) = (written.files.len(), written.manifest.display());
    outln!("wrote {n} files and {manifest}");
    Ok(())
}

fn cmd_sweep(a: SweepArgs) -> Outcome {
    let plan = sweep::Plan {
        nu: sweep::parse_nu_list(&a.nu)?,
        log_p2: sweep::LogRange::parse("log-p2", &a.log_p2)?,
        log_p3: sweep::LogRange::parse("log-p3", &a.log_p3)?,
        sampling: match a.random {
            Some(n) => sweep::Sampling::Random { n, seed: a.seed },
            None => sweep::Sampling::Grid,
        },
    };
    let opts = &sweep::SweepOptions {
        solve: SolveOptions {
            solver: a.solver,
            rtol: a.rtol,
            ..Default::default()
        },
        dimensional: a.dimensional.then_some(a.seed),
        check_every: a.check_every,
        resume: !a.fresh,
    };
    let out = a.out.as_path();
    let points = plan.points()?;
    let summary = with_progress(points.len() as u64, &out.display().to_string(), |tick| {
        sweep::run(&points, out, opts, tick)
    })?;
    outln!("{summary}");
    outln!("{:<28}{}", "rows written to", out.display());
    Ok(())
}

fn cmd_fit(a: FitArgs) -> Outcome {
    let (scene, kind, tau_range) = (a.scene.as_deref(), a.model, a.tau_range.as_deref());
    let fixes = a
        .fix
        .iter()
        .map(|f| f.parse::<fit::Fix>())
        .collect::<Result<Vec<_>, _>>()?;
    let name = scene.map_or("default scene".to_string(), |p| p.display().to_string());
    let scene = scene_or_default(scene)?;
    let sphere = fit::data::scene_sphere(&scene, &name)?;
    let data = fit::data::read(&a.data, sphere, &name)?;
    let taus = fit::prony_times(&kind, tau_range, &data)?;
    let (model, fixed) = fit::setup_model(kind, &fixes, taus)?;
    let result = fit::fit(&model, &data, &fixed)?;
    let written = fit::report::write_outputs(&a.out, &result)?;
    if a.json {
        outln!("{}", fit::report::json(&result));
        eprintln!("material written to {}", written.toml.display());
        eprintln!("plot written to {}", written.svg.display());
    } else {
        out!("{}", fit::report::summary(&result, Some(&written)));
    }
    Ok(())
}

fn cmd_fit_study(a: FitStudyArgs) -> Outcome {
    let report = a.report.as_deref();
    if a.across_box {
        let cfg = fit::study_box::BoxConfig {
            sets: a.sets,
            seed: a.seed,
            velocities: a.velocities,
        };
        if let Some(p) = report {
            sections::require_section(p, &sections::FIT_BOX)?;
        }
        let sets: Vec<u64> = if a.only.is_empty() {
            (0..cfg.sets as u64).collect()
        } else {
            a.only.clone()
        };
        let r = with_progress(sets.len() as u64, "fit-study --box", |tick| {
            fit::study_box::run_sets(&cfg, &sets, tick)
        })?;
        if let Some(p) = &a.csv {
            fit::study_box::write_csv(&r, p)?;
            eprintln!("per-set outcomes written to {}", p.display());
        }
        let section = fit::study_box::markdown(&r);
        out!("{section}");
        if let Some(p) = report {
            sections::update_section(p, &sections::FIT_BOX, &section)?;
            outln!("fit-box section of {} updated", p.display());
        }
        return Ok(());
    }
    let config = |contact_times| fit::study::StudyConfig {
        reps: a.reps,
        seed: a.seed,
        noise: a.noise,
        velocities: a.velocities,
        contact_times,
    };
    if let Some(p) = report {
        sections::require_section(p, &sections::FIT_STUDY)?;
    }
    let mut reports = Vec::new();
    let studies: &[bool] = if a.cor_only { &[false] } else { &[true, false] };
    for &contact_times in studies {
        let cfg = config(contact_times);
        let r = with_progress(cfg.reps as u64, "fit-study", |tick| {
            fit::study::run(&cfg, tick)
        });
        reports.push(r?);
    }
    let section = fit::study::markdown(&reports);
    out!("{section}");
    if let Some(p) = report {
        sections::update_section(p, &sections::FIT_STUDY, &section)?;
        outln!("fit section of {} updated", p.display());
    }
    Ok(())
}

fn cmd_figures(args: FigureArgs) -> Outcome {
    let opts = figures::FigureOptions {
        out: args.out,
        solver: args.solver,
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
    let bar = match args.progress {
        true => progress_bar(opts.units(), "figures"),
        false => indicatif::ProgressBar::hidden(),
    };
    let report = figures::run(&opts, &|| bar.inc(1));
    bar.finish_and_clear();
    out!("{}", report?);
    Ok(())
}

fn cmd_prony(a: PronyArgs) -> Outcome {
    let options = dma::PronyOptions {
        data: a.data.clone(),
        max_terms: dma::parse_terms(&a.terms)?,
        modulus: a.modulus.into(),
        nu: a.nu,
        t_ref: a.t_ref,
        shift: a.shift.into(),
    };
    let report = dma::run(&options)?;
    dma::write_outputs(&a.out, &report)?;
    if a.json {
        outln!("{}", dma::json(&report));
    } else {
        out!("{}", dma::summary(&report));
        outln!("{:<28}{}", "written", a.out.display());
    }
    Ok(())
}
