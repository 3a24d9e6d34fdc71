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
use crate::report::catalogue::{Case, Regime, IMPACTS};
use crate::solvers::indentation::Prescribed;
use crate::solvers::mdr;
use crate::solvers::theory;
use crate::solvers::{SolveOptions, SolverKind};

// the report's building blocks, re-exported where the validation tables have always been
pub use crate::report::external::{
    external_glassy_rows, external_rows, ExternalRow, EXTERNAL_CORNER_TABLE, EXTERNAL_GLASSY_TABLE,
    EXTERNAL_TABLE,
};
pub use crate::report::markdown::{fmt_err, fmt_val, Table};
use crate::report::sections::FILLED;

mod check;
pub mod dem_example;
pub mod dma;
mod impact;
mod limits;
pub mod liquid;
pub mod oblique;
pub mod oblique_dem;
mod prescribed;
pub mod shapes;
mod tables;

pub use check::{check, per_regime, regenerate, staleness, Checked, Staleness, FIGURE_DIR};
pub use impact::*;
pub use limits::*;
pub use prescribed::*;
pub use tables::*;

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

const SHAPES_TEXT: &str = "Every indenter shape of docs/theory.md §11 (`[indenter]` and \
`[sphere] profile`), elastic and viscoelastic, by `reference` (rtol 1e-10), `auto` (rtol 1e-8: \
`fast`, the flat punch by the modes of its linear ODE and elastic power laws in closed form; the \
exact sphere on the elastic half-space, which `fast` refuses, by `reference`) and \
`mdr` (rtol 1e-4). Each cell is the \
largest relative difference of the CoR, contact time, maximum indentation and maximum force \
against the truth: on the elastic half-space (G = 1 MPa, incompressible, 4.11 g at 0.8 m/s) the \
closed forms written in `report::validate::shapes` independently of the solvers' geometry \
(Sneddon's power law and cone with the Beta function, the flat punch as a harmonic oscillator, \
Segedin's exact sphere by Gauss–Legendre quadrature); for the viscoelastic flat punch on the \
standard solid the linear ODE solved by the matrix exponential (no Ting phase; its maximum force \
is taken from `reference`); otherwise `reference` at 1e-10. Materials: the standard solid \
G_inf = 1 MPa, G_1 = 10 MPa, eta = 500 Pa s, nu = 0.3 at 0.99 m/s; three shear terms on an \
elastic bulk at 1.5 m/s; the 30-term polyisobutylene of `scenes/polyisobutylene.toml` at 1 m/s. \
Asserted in `tests/shapes.rs` (`reference` within 1e-8, `auto` within 1e-6, `mdr` within \
2e-4); `tests/shapes_fast.rs` asserts `fast` itself against `reference` on every shape and \
material (within 1e-6 at rtol 1e-8, 1e-8 at rtol 1e-10), the exact sphere on polyisobutylene up \
to a/R = 0.73. Re-run: `mdr-impact validate`; one case: `mdr-impact run scenes/cone_indenter.toml`.\n\n";

const DMA_TEXT: &str = "The `prony` command (docs/dma.md) on synthetic DMA data of a known \
material: shear moduli G', G'' of a 20-term spectrum (`g_inf` = 1 MPa, times 1e-6 to 1e2 s, \
`g_i` falling as `tau_i^-0.4`) on 12 isotherms from -30 to 80 °C (21 frequencies each, 0.01 to \
100 Hz), shifted by WLF (c1 = 8, c2 = 150 K at 20 °C), each modulus times `1 + noise n` with a \
standard normal `n` (`report::validate::dma::synthetic`). The recovered shift factors are \
compared with the true law, and the CoR of a 10 mm steel ball (4.11 g) at 1 m/s on the fitted \
material with the fitted law (incompressible) with the CoR on the true material, at -20, 0, 20, \
40, 60 and 80 °C. A second truth is a real polymer's spectrum with a terminal zone: the 30 \
terms of polyisobutylene (`scenes/polyisobutylene_prony.csv`, `g_inf` = 1 kPa, times taken at \
-20 °C) under the steep WLF law c1 = 17.44, c2 = 51.6 K at -20 °C, on 23 isotherms from -30 to \
80 °C every 5 °C (the same 21 frequencies), fitted with `--t-ref -20`, the CoR compared at -20, \
0, 25, 50 and 80 °C (`report::validate::dma::polymer_round_trip`). The noise-free rows are the \
fit's own error (its relaxation times, 3 per decade, and window); with 2 per decade the \
polymer's rows read 1.1 % rms and 4.1 % in the CoR without noise, 3.6 % to 4.4 % in the CoR at \
1 % noise (the terminal zone, which the contacts near 25 °C probe, missed by the coarser \
times). Asserted in `tests/dma.rs` (shifts within 0.05 decades, fit \
within 1.5 % rms, CoR within 1 %; the polymer without noise within 0.2 %). \
Re-run: `mdr-impact validate`; by hand: `mdr-impact prony scenes/dma_example.csv`.\n\n";

const LIQUID_TEXT: &str =
    "A material whose shear modulus relaxes to zero (`g_inf = 0`, docs/theory.md \
§15) is scaled by its glassy modulus; its groups and relaxed limits do not exist. A 4.11 g, 5 mm \
ball on Maxwell fluids (G_1 = 10 MPa, incompressible, 0.99 m/s), on three shear terms with no \
plateau and a bulk proportional to them (k_inf = 0, 1 m/s), and two equal balls of which one or \
both are the Maxwell fluid of eta = 5000 Pa s (the other: the default solid). Each cell is the \
relative CoR difference from `fast`; the three solvers share nothing but the material (`reference` \
takes `G_eq` from `material::poles`, `fast` and `mdr` from `material::carson`). Asserted in \
`tests/liquid.rs`. Re-run: `mdr-impact validate`.\n\n";

const LIQUID_LIMIT_TEXT: &str = "\nContinuity at `g_inf = 0`: solids of relaxed modulus \
`g_inf = eps G_1` (scaled by `g_inf`) against the Maxwell fluid of eta = 5000 Pa s (scaled by \
`G(0)`), `fast` at rtol 1e-10. The gap shrinks in proportion to `eps` down to the solver's \
tolerance.\n\n";

const SPHERE_LIMIT_TEXT: &str = "\nThe limit exact sphere -> paraboloid (R = 5 mm, elastic, \
`reference` at 1e-10, impact speeds 0.05 to 3 m/s): the maximum forces differ by a multiple of \
`(a/R)^2` that settles as `a/R -> 0` (the exact sphere is softer: it reaches a wider contact at \
the same indentation).\n\n";

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

    // 1e. indenter shapes
    w(&mut md, "\n## 1e. Indenter shapes\n\n");
    w(&mut md, SHAPES_TEXT);
    w(&mut md, &shapes::shapes_table()?.markdown());
    let mut t = Table::new(&[
        "a_max / R",
        "max force, abs(sphere / paraboloid - 1)",
        "difference / (a/R)^2",
    ]);
    for (ar, diff, c) in shapes::sphere_limit()? {
        t.rows
            .push(vec![format!("{ar:.3}"), fmt_err(diff), format!("{c:.4}")]);
    }
    w(&mut md, SPHERE_LIMIT_TEXT);
    w(&mut md, &t.markdown());
    tick();

    // 1f. DMA round trip
    w(
        &mut md,
        "\n## 1f. From DMA data to a Prony series and back\n\n",
    );
    w(&mut md, DMA_TEXT);
    w(&mut md, &dma::round_trip_table()?.markdown());
    tick();

    // 1g. oblique impacts
    w(
        &mut md,
        "\n## 1g. Oblique impacts: friction, partial slip and spin\n\n",
    );
    w(&mut md, oblique::OBLIQUE_TEXT);
    w(&mut md, &oblique::oblique_table()?.markdown());
    w(&mut md, oblique::MBF_TEXT);
    w(&mut md, &oblique::mbf_table()?.markdown());
    let dem_rows = oblique_dem::dem_rows()?;
    w(&mut md, oblique_dem::DEM_TEXT);
    w(&mut md, &oblique_dem::real_table(&dem_rows)?.markdown());
    w(&mut md, oblique_dem::SUMMARY_TEXT);
    w(&mut md, &oblique_dem::summary_table(&dem_rows)?.markdown());
    w(&mut md, oblique_dem::EMULATION_TEXT);
    w(&mut md, "<!-- dem-emulation -->\n");
    w(
        &mut md,
        &oblique_dem::emulation_table(&dem_rows)?.markdown(),
    );
    w(&mut md, "<!-- /dem-emulation -->\n");
    tick();

    // 1h. viscoelastic liquids
    w(&mut md, "\n## 1h. Viscoelastic liquids (g_inf = 0)\n\n");
    w(&mut md, LIQUID_TEXT);
    w(&mut md, &liquid::solver_table()?.markdown());
    w(&mut md, LIQUID_LIMIT_TEXT);
    w(&mut md, &liquid::limit_table()?.markdown());
    tick();

    // 1i. DEM laws with the three Hertz stiffnesses
    w(
        &mut md,
        "\n## 1i. DEM laws on a rubber: `dem --modulus fit`\n\n",
    );
    w(&mut md, dem_example::DEM_TEXT);
    w(
        &mut md,
        &dem_example::table(&dem_example::reports()?).markdown(),
    );
    tick();

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
        .ok_or(Error::Internal("catalogue: no case dissipative-nu045"))?;
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
    (IMPACTS.len() * settings().len() + 1 + external + IMPACTS.len() * hist + 10) as u64
}

fn rel(file: &Path, base: &Path) -> String {
    file.strip_prefix(base)
        .unwrap_or(file)
        .display()
        .to_string()
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
`mdr-impact validate`, or `cargo test --release --test suite external_reference:: -- --ignored`.\n\n";

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
