//! `fit` never reports a worse minimum than the data admit, and its intervals keep their
//! promise: regression tests on two drop tests (tests/data/fit/, the default scene's sphere, a
//! standard solid with 1 % noise and the standard deviations given) where an earlier fit stopped
//! in the Kelvin corner (`g_1 -> inf`) or gave 95 % intervals that all excluded a truth within
//! the threshold of the misfit.

use std::path::Path;

use mdr_impact::apps::fit::{self, data, FitResult, Fix, ModelKind};
use mdr_impact::Sphere;

const TRUTH_049: [f64; 4] = [1.0e6, 1.0e7, 500.0, 0.49];
const TRUTH_045: [f64; 4] = [1.0e6, 1.0e7, 500.0, 0.45];

fn run(file: &str, fixes: &[Fix]) -> (FitResult, f64, [f64; 4]) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/fit")
        .join(file);
    let sphere = Sphere::new(4.11e-3, 5.0e-3).unwrap();
    let d = data::read(&path, sphere, "default").unwrap();
    let (model, fixed) = fit::setup_model(ModelKind::StandardSolid, fixes, vec![]).unwrap();
    let truth = if file.contains("049") {
        TRUTH_049
    } else {
        TRUTH_045
    };
    let truth_ssr = fit::misfit(&model, &d, &truth).unwrap();
    (fit::fit(&model, &d, &fixed).unwrap(), truth_ssr, truth)
}

/// `--fix name=value`.
fn fix(name: &str, value: f64) -> Fix {
    Fix {
        name: name.into(),
        value,
    }
}

/// `--fix nu=value`.
fn nu_at(value: f64) -> Fix {
    fix("nu", value)
}

fn ssr(r: &FitResult) -> f64 {
    r.residuals.iter().map(|x| x.weighted * x.weighted).sum()
}

/// Every reported interval of a parameter or group holds its true value; a quantity without
/// an interval is reported not determined.
fn intervals_hold_the_truth(r: &FitResult, truth: &[f64; 4]) {
    let [g_inf, g_1, eta, _] = *truth;
    let groups = [
        ("p2", g_inf / g_1),
        ("eta_over_g_inf_3_5", eta / g_inf.powf(0.6)),
    ];
    let named = r.parameters.iter().zip(truth.iter().copied()).chain(
        groups
            .iter()
            .filter_map(|(n, t)| r.groups.iter().find(|e| e.name == *n).map(|e| (e, *t))),
    );
    for (e, t) in named {
        if e.fixed {
            continue;
        }
        let Some((a, b)) = e.ci95 else {
            assert!(
                !e.identifiable,
                "{}: determined without an interval",
                e.name
            );
            continue;
        };
        // the interval ends are rounded to the printed digits nowhere: a closed check, with a
        // relative slack of 1e-9 for an end that lands on a grid level of nu
        assert!(
            a <= t + 1e-9 * t.abs() && t <= b + 1e-9 * t.abs(),
            "{}: truth {t} outside [{a}, {b}]",
            e.name
        );
    }
}

#[test]
fn nu_fixed_finds_the_basin_of_the_truth() {
    let nu = nu_at(0.49);
    let (r, truth_ssr, truth) = run("drops_nu049.csv", &[nu]);
    assert!(
        ssr(&r) <= truth_ssr * (1.0 + 1e-6),
        "{} > {truth_ssr}",
        ssr(&r)
    );
    assert!(
        r.parameters.iter().all(|e| e.identifiable || e.fixed),
        "{}",
        r.verdict
    );
    intervals_hold_the_truth(&r, &truth);
    assert!(r.conditional_on_nu.is_none());
    let g = r.goodness.unwrap();
    assert!(g.p_value > 0.01 && g.dof == 17, "{g:?}");
    // the model fits; the faster drops (a_max/R up to 0.48 at 3 m/s) lie outside its validity
    assert_eq!(r.warnings.len(), 1, "{:?}", r.warnings);
    assert!(r.warnings[0].contains("4 of 10 drops lie outside the model's validity"));
}

/// `--fix nu=0.5` (the incompressible limit, whose fit coordinate is infinite): an earlier fit
/// panicked in the interval checks, where the profile constraint multiplied that coordinate by
/// its zero coefficient (NaN). Now a fit with finite values and intervals.
#[test]
fn nu_fixed_at_one_half_fits() {
    let nu = nu_at(0.5);
    let (r, ..) = run("drops_nu049.csv", &[nu]);
    assert!(ssr(&r).is_finite());
    for e in r.parameters.iter().chain(&r.groups) {
        assert!(e.value.is_none_or(f64::is_finite), "{e:?}");
        if let Some((a, b)) = e.ci95 {
            assert!(a.is_finite() && b.is_finite() && a <= b, "{e:?}");
        }
    }
    assert_eq!(r.get("nu").and_then(|e| e.value), Some(0.5));
}

/// Six drops at one velocity (1 m/s) with CoR and contact time, `nu` fixed: two numbers cannot
/// pin three moduli, so `g_inf` and `g_1` are not determined. The profile of `eta` is flat
/// (misfit 5.60) from 500 to about 4700 Pa s and rises beyond, where `g_inf` reaches 0 (the
/// Maxwell limit; `--fix eta=4849` gives 19.2): an earlier fit reported `eta` determined in
/// [491, 5001] only because its profile clamped at the reach of a factor 10, so that its end
/// proved nothing. Now `eta` is either not determined or its interval holds every value of an
/// independent scan (21 values log-spaced over 300..10000 Pa s, each a fit with `eta` fixed
/// there and its own multi-start) whose profile misfit lies within the threshold, the whole
/// flat stretch included.
#[test]
fn one_velocity_with_contact_times_determines_no_modulus() {
    let nu = nu_at(0.49);
    let (r, ..) = run(
        "one_velocity_with_contact_times.csv",
        std::slice::from_ref(&nu),
    );
    for name in ["g_inf", "g_1"] {
        let e = r.get(name).unwrap();
        assert!(!e.identifiable, "{name}: {e:?}\n{}", r.verdict);
    }
    let e = r.get("eta").unwrap();
    if !e.identifiable {
        return;
    }
    let (lo, hi) = e.ci95.unwrap();
    let best = ssr(&r);
    let (q, s) = (r.quantile.unwrap(), r.noise_scale.unwrap());
    let threshold = q * q * s * s;
    let mut within = Vec::new();
    for i in 0..=20 {
        let eta = 300.0 * (10000.0f64 / 300.0).powf(f64::from(i) / 20.0);
        let fixes = [nu.clone(), fix("eta", eta)];
        let (model, fixed) = fit::setup_model(ModelKind::StandardSolid, &fixes, vec![]).unwrap();
        let p = ssr(&fit::fit(&model, &r.data, &fixed).unwrap());
        if p - best < threshold {
            within.push(eta);
            assert!(
                lo <= eta && eta <= hi,
                "eta = {eta}: profile {} above the minimum (threshold {threshold}) outside \
                 [{lo}, {hi}]",
                p - best
            );
        }
    }
    assert!(
        within.iter().any(|&x| x > 4000.0),
        "the flat stretch reaches 4000 Pa s: {within:?}"
    );
}

#[test]
fn nu_free_reports_the_moduli_conditional_on_nu() {
    let (r, truth_ssr, _) = run("drops_nu049.csv", &[]);
    assert!(
        ssr(&r) <= truth_ssr * (1.0 + 1e-6),
        "{} > {truth_ssr}",
        ssr(&r)
    );
    let nu = r
        .conditional_on_nu
        .expect("nu is not determined by these data");
    for name in ["g_inf", "g_1", "eta"] {
        let e = r.parameters.iter().find(|e| e.name == name).unwrap();
        assert!(!e.identifiable, "{name} reported as determined");
        assert!(e.note.contains("conditional on nu"), "{name}: {}", e.note);
    }
    let json = fit::report::json(&r);
    assert_eq!(json["conditional_on_nu"].as_f64(), Some(nu));
    assert_eq!(
        json["parameters"]["g_inf"]["conditional_on"]["nu"].as_f64(),
        Some(nu)
    );
    assert!(fit::report::toml_block(&r).contains("the moduli above hold for this value only"));
}

#[test]
fn intervals_hold_a_truth_within_the_threshold() {
    let (r, truth_ssr, truth) = run("drops_nu045_seed3.csv", &[]);
    assert!(
        ssr(&r) <= truth_ssr * (1.0 + 1e-6),
        "{} > {truth_ssr}",
        ssr(&r)
    );
    // the truth lies within chi^2 = 3.84 of the estimate: every interval must hold it (nu may
    // be reported not determined: its profile stays within the threshold towards the
    // incompressible limit), and the CoR groups are determined
    assert!(truth_ssr - ssr(&r) < 3.84);
    intervals_hold_the_truth(&r, &truth);
    for name in ["p2", "eta_over_g_inf_3_5"] {
        let g = r.groups.iter().find(|e| e.name == name).unwrap();
        assert!(g.identifiable, "{name}: {}", g.note);
    }
}

/// Six drops at one velocity (a CoR and a contact time each) hold two numbers: with
/// `prony:2` they cannot pin two moduli while `g_inf` and `nu` are free, so no parameter may be
/// reported as determined (an earlier fit called `g_1` and `g_2` determined).
#[test]
fn one_velocity_determines_no_prony_modulus() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/fit/six_drops_one_velocity.csv");
    let sphere = Sphere::new(4.11e-3, 5.0e-3).unwrap();
    let d = data::read(&path, sphere, "default").unwrap();
    let kind = ModelKind::Prony { n: 2 };
    let taus = fit::prony_times(&kind, None, &d).unwrap();
    let (model, fixed) = fit::setup_model(kind, &[], taus).unwrap();
    let r = fit::fit(&model, &d, &fixed).unwrap();
    for e in r.parameters.iter().chain(&r.groups) {
        assert!(
            !e.identifiable,
            "{} reported as determined: {}",
            e.name, r.verdict
        );
    }
    assert!(
        r.verdict.contains("determined by the data: none"),
        "{}",
        r.verdict
    );
}

/// The study across the box: two of its sets (`nu` free with contact times; `nu` fixed near 0.5
/// from CoRs alone) end no higher than their truth's misfit, are drawn reproducibly inside the
/// box, and count every fitted quantity once.
#[test]
fn box_study_sets_end_no_higher_than_the_truth() {
    use mdr_impact::apps::fit::study_box::{self, BoxConfig, Cell, QUANTITIES};
    let cfg = BoxConfig {
        sets: 16,
        seed: 1,
        velocities: 10,
    };
    for k in [0, 11] {
        let o = study_box::set_outcome(&cfg, k).unwrap();
        assert_eq!(o.cell, Cell::of(k));
        let (fit_ssr, truth_ssr) = o.ssr;
        assert!(
            study_box::relative_excess(&o) <= study_box::BOX_SSR_SLACK,
            "set {k}: {fit_ssr} > {truth_ssr}"
        );
        let (truth, _) = study_box::draw(&cfg, k).unwrap();
        assert_eq!(truth, o.truth);
        let [g_inf, g_1, _, nu] = truth;
        let (lo, hi) = study_box::BOX_LOG_G_INF;
        assert!((lo..=hi).contains(&g_inf.log10()));
        let (lo, hi) = study_box::BOX_LOG_P2;
        assert!((lo..=hi).contains(&(g_inf / g_1).log10()));
        let (lo, hi) = study_box::BOX_NU[usize::from(o.cell.near_half)];
        assert!((lo..=hi).contains(&nu));
        assert_eq!(o.status.len(), QUANTITIES.len());
        // nu is fixed in odd sets and counted nowhere there
        assert_eq!(o.status[3].is_none(), !o.cell.nu_free);
    }
}

/// The Wilson interval's ends solve `|p_hat - p| = z sqrt(p (1 - p) / n)` (its definition).
#[test]
fn wilson_interval_solves_its_equation() {
    use mdr_impact::apps::fit::study_box::wilson;
    let z = 1.959_963_984_540_054;
    for (k, n) in [(95, 100), (180, 190), (1, 7), (50, 50)] {
        let p_hat = k as f64 / n as f64;
        let (a, b) = wilson(k, n);
        assert!(a <= p_hat && p_hat <= b);
        for p in [a, b] {
            if p == 0.0 || p == 1.0 {
                continue;
            }
            let lhs = (p_hat - p).abs();
            let rhs = z * (p * (1.0 - p) / n as f64).sqrt();
            assert!((lhs - rhs).abs() < 1e-12, "{k}/{n}: {lhs} vs {rhs}");
        }
    }
}

/// `fit-study --box` refuses the single-point study's flags, `--sets` needs `--box`, and zero
/// sets is a one-line error naming `sets`.
#[test]
fn box_study_flags_are_checked() {
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_mdr-impact"))
            .args(args)
            .output()
            .unwrap()
    };
    for args in [
        &["fit-study", "--box", "--reps", "3"][..],
        &["fit-study", "--box", "--noise", "0.05"],
        &["fit-study", "--box", "--cor-only"],
        &["fit-study", "--sets", "3"],
    ] {
        assert_eq!(run(args).status.code(), Some(2), "{args:?}");
    }
    let o = run(&["fit-study", "--box", "--sets", "0"]);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("sets") && err.trim().lines().count() == 1,
        "{err}"
    );
}

/// A set of the box study: the fit as the study runs it, the truth, its misfit and the fixed
/// values.
type BoxSet = (FitResult, [f64; 4], f64, Vec<Option<f64>>);

/// Set `k` of the box study with seed 1 (the draw depends on the seed and `k` only).
fn box_set(k: u64) -> BoxSet {
    box_set_of_seed(1, k)
}

/// [`box_set`] of the study with seed `seed`.
fn box_set_of_seed(seed: u64, k: u64) -> BoxSet {
    use mdr_impact::apps::fit::study_box::{self, BoxConfig, Cell};
    let cfg = BoxConfig {
        sets: 320,
        seed,
        velocities: 10,
    };
    let (truth, d) = study_box::draw(&cfg, k).unwrap();
    let fixes: Vec<Fix> = if Cell::of(k).nu_free {
        vec![]
    } else {
        vec![nu_at(truth[3])]
    };
    let (model, fixed) = fit::setup_model(ModelKind::StandardSolid, &fixes, vec![]).unwrap();
    let truth_ssr = fit::misfit(&model, &d, &truth).unwrap();
    (
        fit::fit(&model, &d, &fixed).unwrap(),
        truth,
        truth_ssr,
        fixed,
    )
}

/// The reported minimum is no worse than the truth's misfit, and every quantity reported
/// determined either holds its truth in its 95 % interval or provably may exclude it: for a
/// parameter, the profile misfit at the true value (a fit with the parameter fixed there,
/// with its own multi-start) lies above the threshold; for a group, the profile misfit at the
/// group's true value (`fit::profile_misfit`, from the truth and from the estimate) does.
fn box_set_keeps_its_promises(k: u64) {
    keeps_its_promises(k, &box_set(k));
}

/// [`box_set_keeps_its_promises`] for set `k` (named in the messages), already fitted.
fn keeps_its_promises(k: u64, set: &BoxSet) {
    let (r, truth, truth_ssr, fixed) = set;
    let (truth, truth_ssr) = (*truth, *truth_ssr);
    let best = ssr(r);
    assert!(
        best <= truth_ssr * (1.0 + 1e-6),
        "set {k}: {best} > {truth_ssr}"
    );
    let (q, s) = (r.quantile.unwrap(), r.noise_scale.unwrap());
    let threshold = q * q * s * s;
    let [g_inf, g_1, eta, _] = truth;
    let group_truth = |name: &str| match name {
        "p2" => g_inf / g_1,
        _ => eta / g_inf.powf(0.6),
    };
    for (i, e) in r.parameters.iter().enumerate() {
        let Some((a, b)) = e.ci95.filter(|_| e.identifiable && !e.fixed) else {
            continue;
        };
        let t = truth[i];
        if a <= t && t <= b {
            continue;
        }
        let mut held = fixed.clone();
        held[i] = Some(t);
        let p = fit::fit(&r.model, &r.data, &held).unwrap();
        assert!(
            ssr(&p) - best >= threshold * (1.0 - 1e-3),
            "set {k}: {} = {t} outside [{a}, {b}] while its profile misfit there is {} above \
             the minimum (threshold {threshold})",
            e.name,
            ssr(&p) - best
        );
    }
    for e in &r.groups {
        let Some((a, b)) = e.ci95.filter(|_| e.identifiable) else {
            continue;
        };
        let t = group_truth(&e.name);
        if a <= t && t <= b {
            continue;
        }
        let starts = [truth.to_vec(), r.values.clone()];
        let p = fit::profile_misfit(&r.model, &r.data, fixed, &e.name, t, &starts)
            .unwrap()
            .unwrap();
        assert!(
            p <= truth_ssr * (1.0 + 1e-9) && p - best >= threshold * (1.0 - 1e-3),
            "set {k}: {} = {t} outside [{a}, {b}] with the profile {} above the minimum \
             (threshold {threshold}, truth's misfit {})",
            e.name,
            p - best,
            truth_ssr - best
        );
    }
}

/// Set 69 (`nu` fixed, contact times, 5 % noise): an earlier fit called `g_1` and `p2`
/// determined with Wald intervals a factor 30 from the truth while its misfit was below the
/// truth's; the profile misfit stays within the threshold down to the truth.
#[test]
fn box_set_69_flat_profile_is_not_determined() {
    let set = box_set(69);
    keeps_its_promises(69, &set);
    let r = &set.0;
    for name in ["g_1", "p2"] {
        assert!(!r.get(name).unwrap().identifiable, "{name}: {}", r.verdict);
    }
}

/// Set 85 (`nu` fixed, contact times, 5 % noise, `g_inf` in its null direction): an earlier
/// fit gave `g_1` a Wald interval [6.55e9, 7.64e9] excluding the truth 3.2e9 that lies within
/// the threshold.
#[test]
fn box_set_85_interval_follows_the_profile() {
    box_set_keeps_its_promises(85);
}

/// Set 144 (`nu` free, contact times, 1 % noise): an earlier fit ended in a basin at SSR 72.4
/// against 9.18 at the truth.
#[test]
fn box_set_144_finds_the_basin_of_the_truth() {
    box_set_keeps_its_promises(144);
}

/// Set 42 (`nu` free near 0.5, CoR only, 1 % noise): an earlier fit ended at nu = 0.414 with
/// SSR 43.3 against 17.2 at the truth (nu = 0.477).
#[test]
fn box_set_42_finds_the_basin_near_half() {
    box_set_keeps_its_promises(42);
}

/// Set 22 (`nu` free, CoR only, 5 % noise): the estimate lies in the Kelvin corner
/// (`g_1 -> inf`, `nu` = 0.39) and another basin near `nu` = 0 fits about as well; an earlier fit
/// widened the interval of `eta / g_inf^(3/5)` to a point of that basin but stopped there,
/// excluding the truth 0.298 (misfit 0.6 above the estimate's) at 0.294.
#[test]
fn box_set_22_interval_follows_the_profile_past_another_basin() {
    box_set_keeps_its_promises(22);
}

/// Set 125 (`nu` fixed near 0.5, contact times, 5 % noise): an earlier fit placed the lower
/// end of `g_1` at 5.66e9 by interpolating a curved profile linearly, excluding the truth
/// 5.55e9 (misfit 1.75 above the estimate's).
#[test]
fn box_set_125_crossing_is_bracketed() {
    box_set_keeps_its_promises(125);
}

/// Set 315 (`nu` fixed, CoR only, 1 % noise): the interval of `p2` leaves out the truth 0.189 by
/// a hair (lower end 0.190). The profile misfit of `p2` (`fit::profile_misfit`) is the
/// estimate's misfit at the estimate, reaches the threshold at the interval's ends (each the
/// outer end of a bracket where the profile was seen at or above it) and lies above it at the
/// truth, so this miss is one a 95 % likelihood-ratio interval allows.
#[test]
fn box_set_315_p2_interval_ends_where_the_profile_crosses() {
    let (r, truth, truth_ssr, fixed) = box_set(315);
    let best = ssr(&r);
    let (q, s) = (r.quantile.unwrap(), r.noise_scale.unwrap());
    let threshold = q * q * s * s;
    let e = r.get("p2").unwrap();
    assert!(e.identifiable, "{}", r.verdict);
    let (value, (a, b)) = (e.value.unwrap(), e.ci95.unwrap());
    let profile = |t: f64| {
        fit::profile_misfit(
            &r.model,
            &r.data,
            &fixed,
            "p2",
            t,
            std::slice::from_ref(&r.values),
        )
        .unwrap()
        .unwrap()
            - best
    };
    assert!(profile(value).abs() <= 1e-6 * best, "{}", profile(value));
    for end in [a, b] {
        assert!(
            profile(end) >= threshold * (1.0 - 1e-3),
            "p2 = {end}: {} below the threshold {threshold}",
            profile(end)
        );
    }
    let p2_truth = truth[0] / truth[1];
    assert!(!(a <= p2_truth && p2_truth <= b));
    let at_truth = fit::profile_misfit(
        &r.model,
        &r.data,
        &fixed,
        "p2",
        p2_truth,
        &[truth.to_vec(), r.values.clone()],
    )
    .unwrap()
    .unwrap();
    assert!(at_truth - best >= threshold && at_truth <= truth_ssr * (1.0 + 1e-9));
    // unknown or fixed quantities have no profile
    assert_eq!(
        fit::profile_misfit(
            &r.model,
            &r.data,
            &fixed,
            "nu",
            0.3,
            std::slice::from_ref(&r.values)
        )
        .unwrap(),
        None
    );
    assert!(fit::profile_misfit(
        &r.model,
        &r.data,
        &fixed,
        "p2",
        -1.0,
        std::slice::from_ref(&r.values)
    )
    .is_err());
}

/// Set 87 (`nu` fixed, CoR only, 5 % noise): the profile of `p2` crosses the threshold below the
/// estimate (0.69) and then levels off towards the Kelvin limit `p2 -> 0`, about 5.3 above the
/// minimum, where the truth 0.026 lies. An earlier fit called `p2` determined with the interval
/// [0.22, 1.0]; the interval is kept, but the flat shoulder makes it not determined, and the
/// profile at twice the lower end's distance indeed lies below the two-degree-of-freedom level.
#[test]
fn box_set_87_flat_shoulder_is_not_determined() {
    let (r, _, _, fixed) = box_set(87);
    let best = ssr(&r);
    let e = r.get("p2").unwrap();
    assert!(!e.identifiable, "{}", r.verdict);
    assert!(
        e.note.contains("flat beyond the interval's lower end"),
        "{}",
        e.note
    );
    let (value, (lo, _)) = (e.value.unwrap(), e.ci95.unwrap());
    let twice = lo * (lo / value);
    let p = fit::profile_misfit(
        &r.model,
        &r.data,
        &fixed,
        "p2",
        twice,
        std::slice::from_ref(&r.values),
    )
    .unwrap()
    .unwrap();
    let level = -2.0 * 0.05f64.ln();
    assert!(
        p - best < level && p - best > 3.84,
        "profile at p2 = {twice}: {} above the minimum",
        p - best
    );
}

/// Set 319 of the study with seed 2 (`nu` fixed near 0.5, CoR only, 5 % noise): the profile of
/// `p2` has two basins, the best at 0.17 and another at 0.019 whose minimum lies 2.8 above the
/// best (within the threshold 3.84), which holds the truth 0.021. The scout of that decade of
/// `p2` found it, but only the best scouted basin was minimised fully, so an earlier fit reported
/// `p2` determined in [0.121, 0.220] around the best basin alone. Every point of an independent
/// scan of the profile (41 values log-spaced over 1e-3..1, each minimised from the truth and
/// from the estimate) that lies within the threshold must lie inside the interval.
#[test]
fn box_seed_2_set_319_interval_holds_the_second_basin() {
    let set = box_set_of_seed(2, 319);
    let (r, truth, _, fixed) = &set;
    let best = ssr(r);
    let (q, s) = (r.quantile.unwrap(), r.noise_scale.unwrap());
    let threshold = q * q * s * s;
    let e = r.get("p2").unwrap();
    let starts = [truth.to_vec(), r.values.clone()];
    let mut within: Vec<f64> = Vec::new();
    for i in 0..=40 {
        let p2 = 10f64.powf(-3.0 + 3.0 * f64::from(i) / 40.0);
        let p = fit::profile_misfit(&r.model, &r.data, fixed, "p2", p2, &starts)
            .unwrap()
            .unwrap();
        if p - best < threshold {
            within.push(p2);
            let held = e.ci95.is_some_and(|(a, b)| a <= p2 && p2 <= b);
            assert!(
                held || !e.identifiable,
                "p2 = {p2}: profile {} above the minimum (threshold {threshold}) outside {:?} ({})",
                p - best,
                e.ci95,
                e.note
            );
        }
    }
    // the scan sees both basins within the threshold
    assert!(
        within.iter().any(|&p2| p2 < 0.05) && within.iter().any(|&p2| p2 > 0.1),
        "scan points within the threshold: {within:?}"
    );
    keeps_its_promises(319, &set);
}

/// Set 313 of the study with seed 2 (`nu` fixed at 0.4597, CoR and contact times, 1 % noise;
/// truth `g_inf` 9.10e7 Pa, `g_1` 2.35e10 Pa, `eta` 1.77e5 Pa s, misfit 14.0): the best
/// screened point of every decade of `p2` led to a minimum of misfit 611 at `g_inf` 4.96e8 Pa,
/// reported determined with intervals excluding the truth. The fourth best screened point lies
/// in the truth's basin; the global stage now scouts the best few screened points too
/// (`FIT_SCOUT_TOP`). The truth's value must lie in every interval (1 % noise, misfit within
/// the threshold of the minimum).
#[test]
fn box_seed_2_set_313_finds_the_truths_basin() {
    let set = box_set_of_seed(2, 313);
    let (r, truth, truth_ssr, _) = &set;
    let best = ssr(r);
    assert!(best < 20.0, "minimum {best} (truth {truth_ssr})");
    for (name, t) in [("g_inf", truth[0]), ("g_1", truth[1]), ("eta", truth[2])] {
        let e = r.get(name).unwrap();
        let (a, b) = e.ci95.unwrap();
        assert!(
            e.identifiable && a <= t && t <= b,
            "{name}: truth {t} outside [{a}, {b}] ({})",
            e.note
        );
    }
    keeps_its_promises(313, &set);
}
