//! The fit study across the parameter box (`mdr-impact fit-study --box`): synthetic drop tests
//! of standard solids drawn over the whole box, fitted again, and two promises checked in every
//! set: the reported minimum's misfit is at most the truth's (no worse basin), and the reported
//! 95 % intervals hold the truth about 95 % of the time.
//!
//! Set `k` belongs to the cell `k mod 16`: `nu` free or fixed at its true value, CoR only or CoR
//! and contact times, 1 % or 5 % noise, `nu` drawn from `[0, 0.45]` or near 0.5
//! (`[0.45, 0.499]`). Its truth and noise come from a SplitMix64 stream seeded by the study
//! seed and `k` alone, so a set is reproducible on its own and the result does not depend on the
//! number of threads. The two checks and the Wilson interval: docs/theory.md §16.

use rayon::prelude::*;

use super::data::{Data, Observation, Setup};
use super::starts::p3_scale;
use super::{fit, misfit, Model, ModelKind, ParamKind};
use crate::error::Result;
use crate::model::impact::Sphere;
use crate::rng::SplitMix64;
use crate::solvers::{solve, SolveOptions};

use super::study::{SPHERE, TRUTH_RTOL};

/// Velocity range of the drops (m/s), log-spaced.
pub const BOX_VELOCITIES: (f64, f64) = (0.1, 10.0);
/// `log10` range of the relaxed modulus `g_inf` (Pa) the truths are drawn from.
pub const BOX_LOG_G_INF: (f64, f64) = (6.0, 9.0);
/// `log10` range of the stiffness ratio `p2 = g_inf / g_1`.
pub const BOX_LOG_P2: (f64, f64) = (-3.0, -0.5);
/// `log10` range of `p3` (paper Eq. 11) at the data's geometric-mean velocity; `eta` follows.
pub const BOX_LOG_P3: (f64, f64) = (-1.0, 1.0);
/// Range of `nu` away from the incompressible limit, and near it.
pub const BOX_NU: [(f64, f64); 2] = [(0.0, 0.45), (0.45, 0.499)];
/// The two noise levels (relative standard deviation of every measured value).
pub const BOX_NOISE: [f64; 2] = [0.01, 0.05];
/// Excess of the reported minimum's misfit over the truth's that counts as numerical noise:
/// relative to the truth's misfit (forward solves at `FIT_RTOL = 1e-8` move a weighted residual
/// by about `1e-8 / noise`).
pub const BOX_SSR_SLACK: f64 = 1e-6;

/// An across-the-box study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoxConfig {
    /// Number of synthetic data sets (16 cells, assigned in turn).
    pub sets: usize,
    /// Seed.
    pub seed: u64,
    /// Drops per set (velocities).
    pub velocities: usize,
}

impl BoxConfig {
    /// The inputs in range: at least one set, at least four velocities (four parameters).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `sets` or `velocities`.
    pub fn check(&self) -> Result<()> {
        crate::error::check("sets", self.sets as f64, self.sets >= 1, "1 <= sets")?;
        crate::error::check(
            "velocities",
            self.velocities as f64,
            self.velocities >= 4,
            "4 <= velocities",
        )
        .map(|_| ())
    }
}

/// The design cell of a set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    /// Whether `nu` is fitted (else fixed at its true value).
    pub nu_free: bool,
    /// Whether contact times are measured.
    pub contact_times: bool,
    /// Relative noise.
    pub noise: f64,
    /// Whether `nu` is drawn near 0.5.
    pub near_half: bool,
}

impl Cell {
    /// The cell of set `k`.
    pub fn of(k: u64) -> Self {
        Cell {
            nu_free: k & 1 == 0,
            contact_times: k & 2 == 0,
            noise: BOX_NOISE[((k >> 2) & 1) as usize],
            near_half: k & 8 != 0,
        }
    }
}

/// A set of design cells, named as in the report's tables.
pub type Pick = fn(&Cell) -> bool;

/// The design factors by which the report pools cells: each level of each factor.
pub const FACTORS: [(&str, Pick); 8] = [
    ("nu free", |c| c.nu_free),
    ("nu fixed", |c| !c.nu_free),
    ("CoR + contact time", |c| c.contact_times),
    ("CoR only", |c| !c.contact_times),
    ("1 % noise", |c| c.noise == BOX_NOISE[0]),
    ("5 % noise", |c| c.noise == BOX_NOISE[1]),
    ("nu in [0, 0.45]", |c| !c.near_half),
    ("nu in [0.45, 0.499]", |c| c.near_half),
];

/// How one quantity of one set came out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Reported determined; whether its 95 % interval holds the truth.
    Determined(bool),
    /// Reported conditional on a `nu` the data do not determine; whether its interval holds the
    /// truth anyway.
    Conditional(bool),
    /// Reported not determined (no value, or no bounded interval).
    NotDetermined,
}

/// A reported estimate and its 95 % interval (SI; `None` when not given).
pub type Reported = (Option<f64>, Option<(f64, f64)>);

/// One set's outcome.
#[derive(Debug, Clone, PartialEq)]
pub struct SetOutcome {
    /// Index of the set.
    pub set: u64,
    /// Its cell.
    pub cell: Cell,
    /// The truth `g_inf, g_1, eta, nu` (Pa, Pa, Pa s, 1).
    pub truth: [f64; 4],
    /// Weighted SSR at the reported minimum and at the truth.
    pub ssr: (f64, f64),
    /// Per quantity (in [`QUANTITIES`] order; `None` when fixed).
    pub status: Vec<Option<Status>>,
    /// Per quantity: the reported estimate and 95 % interval (SI; `None` when not given).
    pub reported: Vec<Reported>,
    /// Per quantity that was fitted: the profile misfit at the truth's value less the misfit at
    /// the estimate, the likelihood-ratio statistic `W` of the truth ([`super::profile_misfit`],
    /// from the truth and from the estimate). `None` when fixed, for the moduli without contact
    /// times (the CoR leaves their common scale free), or when the profile could not be
    /// evaluated.
    pub profile_excess: Vec<Option<f64>>,
}

/// The quantities checked: the parameters and the CoR-determined groups.
pub const QUANTITIES: [&str; 6] = ["g_inf", "g_1", "eta", "nu", "p2", "eta_over_g_inf_3_5"];

fn truth_of(name: &str, t: &[f64; 4]) -> f64 {
    let [g_inf, g_1, eta, nu] = *t;
    match name {
        "g_inf" => g_inf,
        "g_1" => g_1,
        "eta" => eta,
        "nu" => nu,
        "p2" => g_inf / g_1,
        _ => eta / g_inf.powf(super::model::ETA_GROUP_EXPONENT),
    }
}

/// The drops of set `k` (velocities only, no values yet).
fn skeleton(cfg: &BoxConfig, contact_times: bool, noise: f64) -> Result<Data> {
    let sphere = Sphere::new(SPHERE.0, SPHERE.1)?;
    let n = cfg.velocities;
    let (lo, hi) = BOX_VELOCITIES;
    let observations = crate::math::logspace(lo, hi, n)
        .into_iter()
        .map(|v0| Observation {
            setup: 0,
            v0,
            cor: 0.5,
            cor_sd: Some(noise),
            contact_time: contact_times.then_some(1.0),
            contact_time_sd: contact_times.then_some(noise),
        })
        .collect();
    Ok(Data {
        setups: vec![Setup {
            name: "box".into(),
            sphere: sphere.into(),
        }],
        observations,
    })
}

/// The truth of set `k` and its noisy data (standard deviations `noise` times the exact values;
/// CoRs above 1 kept as measured).
pub fn draw(cfg: &BoxConfig, k: u64) -> Result<([f64; 4], Data)> {
    let cell = Cell::of(k);
    let mut rng = SplitMix64::new(cfg.seed ^ (k + 1).wrapping_mul(0xD1B5_4A32_D192_ED03));
    let mut between = |(a, b): (f64, f64)| a + (b - a) * rng.uniform();
    let g_inf = 10f64.powf(between(BOX_LOG_G_INF));
    let g_1 = g_inf / 10f64.powf(between(BOX_LOG_P2));
    let p3 = 10f64.powf(between(BOX_LOG_P3));
    let nu = between(BOX_NU[usize::from(cell.near_half)]);
    let mut data = skeleton(cfg, cell.contact_times, cell.noise)?;
    let eta = p3 * g_inf.powf(super::model::ETA_GROUP_EXPONENT) / p3_scale(&data);
    let truth = [g_inf, g_1, eta, nu];
    let model = Model::new(ModelKind::StandardSolid, None, vec![])?;
    let opts = SolveOptions {
        rtol: TRUTH_RTOL,
        ..Default::default()
    };
    let sphere = data.setups[0].sphere;
    for o in &mut data.observations {
        let out = solve(&model.impact(sphere, o.v0, &truth)?, &opts)?;
        o.cor_sd = Some(cell.noise * out.cor);
        o.cor = out.cor * (1.0 + cell.noise * rng.normal());
        if cell.contact_times {
            o.contact_time_sd = Some(cell.noise * out.contact_time);
            o.contact_time = Some(out.contact_time * (1.0 + cell.noise * rng.normal()));
        }
    }
    Ok((truth, data))
}

/// Fit set `k` (with `nu` fixed at its truth in the cells that fix it) and compare with the
/// truth.
pub fn set_outcome(cfg: &BoxConfig, k: u64) -> Result<SetOutcome> {
    let cell = Cell::of(k);
    let (truth, data) = draw(cfg, k)?;
    let model = Model::new(ModelKind::StandardSolid, None, vec![])?;
    let mut fixed = vec![None; model.params.len()];
    if !cell.nu_free {
        fixed[model.index("nu").unwrap_or(3)] = Some(truth[3]);
    }
    let r = fit(&model, &data, &fixed)?;
    let ssr_fit: f64 = r.residuals.iter().map(|x| x.weighted * x.weighted).sum();
    let ssr_truth = misfit(&model, &data, &truth)?;
    let (status, reported): (Vec<Option<Status>>, Vec<Reported>) = QUANTITIES
        .iter()
        .map(|&name| {
            let Some(e) = r.get(name) else {
                return (None, (None, None));
            };
            let reported = (e.value, e.ci95);
            if e.fixed {
                return (None, reported);
            }
            let t = truth_of(name, &truth);
            let covered = e.ci95.is_some_and(|(a, b)| a <= t && t <= b);
            let kind = r
                .model
                .index(name)
                .map_or(ParamKind::Positive, |i| r.model.params[i].kind);
            let conditional = r.conditional_on_nu.is_some()
                && kind == ParamKind::Positive
                && r.model.index(name).is_some()
                && e.value.is_some();
            let status = if e.identifiable {
                Status::Determined(covered)
            } else if conditional {
                Status::Conditional(covered)
            } else {
                Status::NotDetermined
            };
            (Some(status), reported)
        })
        .unzip();
    // the likelihood-ratio statistic of the truth: the profile at the truth above the misfit at
    // the estimate (the CoR alone leaves the moduli's common scale free: no statistic for them)
    let starts = [truth.to_vec(), r.values.clone()];
    let profile_excess =
        QUANTITIES
            .iter()
            .zip(&status)
            .map(|(&name, st)| {
                let scale_free = !cell.contact_times && matches!(name, "g_inf" | "g_1" | "eta");
                if st.is_none() || scale_free {
                    return Ok(None);
                }
                Ok(super::profile_misfit(
                    &model,
                    &data,
                    &fixed,
                    name,
                    truth_of(name, &truth),
                    &starts,
                )?
                .map(|s| s - ssr_fit))
            })
            .collect::<Result<Vec<_>>>()?;
    Ok(SetOutcome {
        set: k,
        cell,
        truth,
        ssr: (ssr_fit, ssr_truth),
        status,
        reported,
        profile_excess,
    })
}

/// A box study's result.
#[derive(Debug, Clone, PartialEq)]
pub struct BoxReport {
    /// The configuration.
    pub config: BoxConfig,
    /// Every set that was fitted.
    pub outcomes: Vec<SetOutcome>,
    /// Sets whose data or fit failed, with the message.
    pub failures: Vec<(u64, String)>,
}

/// Run the study (sets in parallel); `tick` after each set.
pub fn run(cfg: &BoxConfig, tick: &(dyn Fn() + Sync)) -> Result<BoxReport> {
    cfg.check()?;
    let all: Vec<u64> = (0..cfg.sets as u64).collect();
    run_sets(cfg, &all, tick)
}

/// Run the sets `sets` of the study (each reproducible on its own: its truth and noise depend
/// only on the seed and its index); `tick` after each set.
///
/// # Errors
/// [`crate::Error::OutOfRange`] naming `only` when a set is not below `cfg.sets`.
pub fn run_sets(cfg: &BoxConfig, sets: &[u64], tick: &(dyn Fn() + Sync)) -> Result<BoxReport> {
    cfg.check()?;
    for &k in sets {
        crate::error::check("only", k as f64, k < cfg.sets as u64, "0 <= set < sets")?;
    }
    let results: Vec<(u64, Result<SetOutcome>)> = sets
        .par_iter()
        .map(|&k| {
            let r = set_outcome(cfg, k);
            tick();
            (k, r)
        })
        .collect();
    let mut outcomes = Vec::new();
    let mut failures = Vec::new();
    for (k, r) in results {
        match r {
            Ok(o) => outcomes.push(o),
            Err(e) => failures.push((k, e.to_string())),
        }
    }
    Ok(BoxReport {
        config: *cfg,
        outcomes,
        failures,
    })
}

/// One row per set and quantity (`fit-study --box --csv`): `set, nu_free, contact_times,
/// noise, near_half, quantity, truth, estimate, ci_low, ci_high, status, ssr_fit, ssr_truth,
/// profile_excess_at_truth` (SI; `status` is `determined`, `conditional`, `not_determined` or
/// `fixed`; empty fields where `fit` gave no value; the last column is the likelihood-ratio
/// statistic of the truth, [`SetOutcome::profile_excess`]).
///
/// # Errors
/// [`crate::Error::Io`] when the file cannot be written.
pub fn write_csv(r: &BoxReport, path: &std::path::Path) -> Result<()> {
    let io = |e: ::csv::Error| crate::Error::io(path, e);
    let mut w = ::csv::Writer::from_path(path).map_err(io)?;
    w.write_record([
        "set",
        "nu_free",
        "contact_times",
        "noise",
        "near_half",
        "quantity",
        "truth",
        "estimate",
        "ci_low",
        "ci_high",
        "status",
        "ssr_fit",
        "ssr_truth",
        "profile_excess_at_truth",
    ])
    .map_err(io)?;
    let opt = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v:e}"));
    for o in &r.outcomes {
        for (q, name) in QUANTITIES.iter().enumerate() {
            let (value, ci) = o.reported.get(q).copied().unwrap_or((None, None));
            let status = match o.status.get(q).copied().flatten() {
                Some(Status::Determined(_)) => "determined",
                Some(Status::Conditional(_)) => "conditional",
                Some(Status::NotDetermined) => "not_determined",
                None => "fixed",
            };
            w.write_record([
                o.set.to_string(),
                o.cell.nu_free.to_string(),
                o.cell.contact_times.to_string(),
                o.cell.noise.to_string(),
                o.cell.near_half.to_string(),
                (*name).to_string(),
                format!("{:e}", truth_of(name, &o.truth)),
                opt(value),
                opt(ci.map(|c| c.0)),
                opt(ci.map(|c| c.1)),
                status.to_string(),
                format!("{:e}", o.ssr.0),
                format!("{:e}", o.ssr.1),
                opt(o.profile_excess.get(q).copied().flatten()),
            ])
            .map_err(io)?;
        }
    }
    w.flush().map_err(|e| crate::Error::io(path, e))
}

/// The excess `ssr_fit - ssr_truth` of a set, relative to `max(1, ssr_truth)`.
pub fn relative_excess(o: &SetOutcome) -> f64 {
    (o.ssr.0 - o.ssr.1) / o.ssr.1.max(1.0)
}

/// Tallies of the statuses of one quantity over some sets.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counts {
    /// Reported determined.
    pub determined: usize,
    /// Of those, intervals holding the truth.
    pub covered: usize,
    /// Reported conditional on `nu`.
    pub conditional: usize,
    /// Of those, intervals holding the truth.
    pub conditional_covered: usize,
    /// Reported not determined.
    pub not_determined: usize,
}

impl Counts {
    /// Tally quantity `q` (index into [`QUANTITIES`]) over `sets`.
    pub fn of<'a>(q: usize, sets: impl IntoIterator<Item = &'a SetOutcome>) -> Self {
        let mut c = Counts::default();
        for s in sets {
            match s.status.get(q).copied().flatten() {
                Some(Status::Determined(h)) => {
                    c.determined += 1;
                    c.covered += usize::from(h);
                }
                Some(Status::Conditional(h)) => {
                    c.conditional += 1;
                    c.conditional_covered += usize::from(h);
                }
                Some(Status::NotDetermined) => c.not_determined += 1,
                None => {}
            }
        }
        c
    }
}

/// The Wilson score interval (95 %) of `k` successes in `n` trials.
pub fn wilson(k: usize, n: usize) -> (f64, f64) {
    if n == 0 {
        return (0.0, 1.0);
    }
    let (z, n_f) = (1.959_963_984_540_054, n as f64);
    let p = k as f64 / n_f;
    let d = 1.0 + z * z / n_f;
    let c = (p + z * z / (2.0 * n_f)) / d;
    let h = z * (p * (1.0 - p) / n_f + z * z / (4.0 * n_f * n_f)).sqrt() / d;
    ((c - h).max(0.0), (c + h).min(1.0))
}

fn cell_label(c: &Cell) -> [String; 4] {
    [
        if c.nu_free { "free" } else { "fixed (truth)" }.into(),
        if c.contact_times {
            "CoR + contact time"
        } else {
            "CoR only"
        }
        .into(),
        format!("{} %", c.noise * 100.0),
        format!(
            "[{}, {}]",
            BOX_NU[usize::from(c.near_half)].0,
            BOX_NU[usize::from(c.near_half)].1
        ),
    ]
}

fn coverage_cell(c: &Counts) -> String {
    if c.determined == 0 {
        return "-".into();
    }
    let (a, b) = wilson(c.covered, c.determined);
    format!(
        "{}/{} = {:.1} % [{:.1}, {:.1}]",
        c.covered,
        c.determined,
        100.0 * c.covered as f64 / c.determined as f64,
        100.0 * a,
        100.0 * b
    )
}

/// The markdown of a box study (section 11b of VALIDATION.md).
pub fn markdown(r: &BoxReport) -> String {
    let c = &r.config;
    let mut s = format!(
        "Fit study across the parameter box (`src/apps/fit/study_box.rs`, \
         `mdr-impact fit-study --box --sets {} --seed {} --velocities {}`): {} synthetic drop \
         tests of standard solids, each with its own truth drawn log-uniformly over \
         `g_inf` in 1e{}..1e{} Pa, `p2 = g_inf / g_1` in 1e{}..1e{} and `p3` (paper Eq. 11, at \
         the data's geometric-mean velocity; `eta` follows) in 1e{}..1e{}, `nu` uniform in \
         {:?} or near 0.5 in {:?}; the default scene's sphere (`m = {:e} kg`, `R = {:e} m`) at \
         {} log-spaced velocities from {} to {} m/s, CoR (and contact times) from `auto` at \
         rtol {TRUTH_RTOL:e}, each value multiplied by `1 + noise * N(0, 1)` with its standard \
         deviation given. Set `k` is in cell `k mod 16`: `nu` free or fixed at its truth \
         (`--fix nu=...`), CoR only or with contact times, 1 % or 5 % noise, `nu` away from or \
         near 0.5. Every set is fitted by `fit` as a user would run it.\n\n",
        c.sets,
        c.seed,
        c.velocities,
        c.sets,
        BOX_LOG_G_INF.0,
        BOX_LOG_G_INF.1,
        BOX_LOG_P2.0,
        BOX_LOG_P2.1,
        BOX_LOG_P3.0,
        BOX_LOG_P3.1,
        BOX_NU[0],
        BOX_NU[1],
        SPHERE.0,
        SPHERE.1,
        c.velocities,
        BOX_VELOCITIES.0,
        BOX_VELOCITIES.1,
    );
    let worse: Vec<&SetOutcome> = r
        .outcomes
        .iter()
        .filter(|o| relative_excess(o) > BOX_SSR_SLACK)
        .collect();
    let worst = r
        .outcomes
        .iter()
        .max_by(|a, b| relative_excess(a).total_cmp(&relative_excess(b)));
    s.push_str(&format!(
        "### No worse minimum than the truth\n\nIn {} of {} fitted sets the reported minimum's \
         weighted SSR exceeds the truth's by more than {BOX_SSR_SLACK:e} relative (numerical \
         noise of the forward solves).",
        worse.len(),
        r.outcomes.len()
    ));
    if let Some(w) = worst {
        s.push_str(&format!(
            " The largest excess `(SSR_fit - SSR_truth) / max(1, SSR_truth)` is {:.2e} (set {}, \
             SSR {:.6} against {:.6}); a negative number means the fit is below the truth.",
            relative_excess(w),
            w.set,
            w.ssr.0,
            w.ssr.1
        ));
    }
    s.push_str("\n\n| nu | data | noise | true nu in | sets | SSR_fit <= SSR_truth | largest relative excess |\n");
    s.push_str("| --- | --- | --- | --- | --- | --- | --- |\n");
    for cell in 0..16u64 {
        let cl = Cell::of(cell);
        let sets: Vec<&SetOutcome> = r.outcomes.iter().filter(|o| o.cell == cl).collect();
        if sets.is_empty() {
            continue;
        }
        let ok = sets
            .iter()
            .filter(|o| relative_excess(o) <= BOX_SSR_SLACK)
            .count();
        let ex = sets
            .iter()
            .map(|o| relative_excess(o))
            .fold(f64::NEG_INFINITY, f64::max);
        let [a, b, n, nu] = cell_label(&cl);
        s.push_str(&format!(
            "| {a} | {b} | {n} | {nu} | {} | {ok}/{} | {ex:.2e} |\n",
            sets.len(),
            sets.len()
        ));
    }
    s.push_str(
        "\n### Coverage of the 95 % intervals\n\nPer quantity over every set where it was \
         fitted: `determined` counts the sets in which `fit` reported it determined, with the \
         share whose 95 % interval holds the truth and that share's 95 % Wilson interval \
         (binomial uncertainty; target 93–97 %). `conditional` counts the sets in which `nu` was \
         free but not determined, so that `fit` reported the moduli conditional on the fitted \
         `nu` (not determined); how many of those intervals hold the truth anyway is given in \
         brackets. `not determined` counts the sets in which `fit` gave no value or no bounded \
         interval. Without contact times `g_inf`, `g_1` and `eta` are never determined (only \
         the groups are).\n\n",
    );
    s.push_str("| quantity | determined: coverage [95 % Wilson] | conditional on nu (interval holds truth) | not determined |\n");
    s.push_str("| --- | --- | --- | --- |\n");
    for (q, name) in QUANTITIES.iter().enumerate() {
        let ct = Counts::of(q, &r.outcomes);
        s.push_str(&format!(
            "| {name} | {} | {} ({}) | {} |\n",
            coverage_cell(&ct),
            ct.conditional,
            ct.conditional_covered,
            ct.not_determined
        ));
    }
    s.push_str(
        "\nCoverage of the determined intervals by design factor (each row pools the sets of \
         the cells it names):\n\n| sets | ",
    );
    s.push_str(&QUANTITIES.join(" | "));
    s.push_str(" |\n| --- |");
    s.push_str(&" --- |".repeat(QUANTITIES.len()));
    s.push('\n');
    for (label, pick) in FACTORS {
        s.push_str(&format!("| {label} |"));
        for q in 0..QUANTITIES.len() {
            let ct = Counts::of(q, r.outcomes.iter().filter(|o| pick(&o.cell)));
            if ct.determined == 0 {
                s.push_str(" - |");
            } else {
                s.push_str(&format!(
                    " {}/{} = {:.1} % |",
                    ct.covered,
                    ct.determined,
                    100.0 * ct.covered as f64 / ct.determined as f64
                ));
            }
        }
        s.push('\n');
    }
    // the intervals' promise: no truth within the threshold of the misfit is left out (every
    // set gives its standard deviations: the threshold is the normal quantile squared)
    let threshold = super::analysis::normal_quantile().powi(2);
    s.push_str(&super::study_statistic::markdown(r, threshold));
    let misses: Vec<(u64, &str, f64, Option<f64>)> = r
        .outcomes
        .iter()
        .flat_map(|o| {
            o.status
                .iter()
                .zip(QUANTITIES)
                .zip(&o.profile_excess)
                .filter(|((st, _), _)| matches!(st, Some(Status::Determined(false))))
                .map(move |((_, name), p)| (o.set, name, o.ssr.1 - o.ssr.0, *p))
        })
        .collect();
    // the profile at the truth's value where it was evaluated, else its upper bound SSR_truth
    let excess = |m: &(u64, &str, f64, Option<f64>)| m.3.unwrap_or(m.2).min(m.2);
    let broken: Vec<String> = misses
        .iter()
        .filter(|m| excess(m) < threshold)
        .map(|m| format!("set {} {} ({:.2})", m.0, m.1, excess(m)))
        .collect();
    let unevaluated = misses.iter().filter(|m| m.3.is_none()).count();
    let beyond: Vec<f64> = misses
        .iter()
        .map(excess)
        .filter(|d| *d >= threshold)
        .collect();
    let fmt_min = |v: &[f64]| {
        let m = v.iter().copied().fold(f64::INFINITY, f64::min);
        if m.is_finite() {
            format!("{m:.2}")
        } else {
            "-".into()
        }
    };
    s.push_str(&format!(
        "\nOf the {} determined intervals that leave out the truth, {} do so although the profile \
         misfit at the truth's value lies within the 95 % threshold of the estimate's \
         (`S_p(truth) - SSR_fit < {:.2}`, so that the promise of the interval is broken){}. The \
         profile at the truth's value is minimised over the other moving coordinates from the \
         truth and from the estimate (`profile_misfit`, an upper bound of the profile; in {} \
         misses it could not be evaluated and `SSR_truth - SSR_fit` bounds it instead). In the \
         others the truth lies beyond the threshold (smallest `S_p(truth) - SSR_fit`: {}; \
         median {}), so that each is one of the misses a 95 % likelihood-ratio interval allows \
         by its construction; the table of the statistic above tells whether their share among \
         the determined intervals comes from the statistic's law (then it is also high over all \
         sets) or from selecting the sets whose profile closes (docs/theory.md §16.1).\n",
        misses.len(),
        broken.len(),
        threshold,
        if broken.is_empty() {
            String::new()
        } else {
            format!(": {}", broken.join(", "))
        },
        unevaluated,
        fmt_min(&beyond),
        {
            let mut b = beyond.clone();
            b.sort_by(f64::total_cmp);
            b.get(b.len() / 2)
                .map_or("-".to_string(), |m| format!("{m:.2}"))
        }
    ));
    s.push_str(&format!("\nFailed sets: {}", r.failures.len()));
    for (k, e) in r.failures.iter().take(5) {
        s.push_str(&format!("; set {k}: {e}"));
    }
    s.push_str(".\n\n");
    s
}
