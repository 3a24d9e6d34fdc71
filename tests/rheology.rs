//! General rheology (docs/theory.md §8): validated Prony series in shear and bulk, the equivalent
//! relaxation `G_eq(t)` as an exact Prony series (`material::carson`), and its independent
//! Talbot inversion (`theory::bromwich`).
//!
//! Checks: the series against the Carson formula evaluated directly on `s > 0`, the glassy and
//! relaxed closed forms, the standard solid's closed form (docs/theory.md §2), the limits
//! `K -> inf` and split terms, the two routes against each other, bad input, and random series.

use approx::assert_relative_eq;
use mdr_impact::model::material::carson;
use mdr_impact::model::material::rheology::{
    equivalent_elastic, BulkInput, BulkProny, BulkRheology, ShearProny,
};
use mdr_impact::model::material::{Material, Prony};
use mdr_impact::solvers::theory::bromwich;
use mdr_impact::Error;
use proptest::prelude::*;

/// Tolerance of the Prony series of `G_eq` against the Carson formula and the closed forms.
const SERIES_RTOL: f64 = 1e-12;
/// Tolerance of the Talbot inversion against the Prony series: measured at most 1.2e-11 over the
/// catalogue (30 terms over 20 decades, `G_0 / G_inf ~ 1e5`; see `talbot_error_against_nodes`).
const TALBOT_RTOL: f64 = 2e-11;

/// Tiny deterministic generator (xorshift64*), uniform in [0, 1). Kept instead of
/// `mdr_impact::rng::SplitMix64` on purpose: the Talbot tolerances below were measured on the
/// materials this stream draws (other draws reach 7e-11, still the Talbot route's own accuracy).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }
    /// `10^(lo + (hi - lo) u)`.
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(lo + (hi - lo) * self.next())
    }
}

/// `n` terms with log-uniform moduli in `[1e-3, 1e3]` and times spread over `[1e-10, 1e10]`
/// (one per slot of 20/n decades, jittered).
fn spread_terms(rng: &mut Rng, n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let slot = 20.0 / n as f64;
            let e = -10.0 + slot * (i as f64 + 0.2 + 0.6 * rng.next());
            (rng.log_uniform(-3.0, 3.0), 10f64.powf(e))
        })
        .collect()
}

/// A Carson transform `relaxed + sum m s tau / (1 + s tau)` at real `s > 0`.
fn carson_sum(relaxed: f64, terms: &[(f64, f64)], s: f64) -> f64 {
    relaxed
        + terms
            .iter()
            .map(|&(m, tau)| m * s * tau / (1.0 + s * tau))
            .sum::<f64>()
}

/// `G_eq(s)` directly from the formula `G (3K + G) / (3K + 4G)` at real `s > 0`.
fn carson_formula(m: &Material, s: f64) -> f64 {
    let g = carson_sum(m.shear().g_inf(), m.shear().terms(), s);
    let k = match m.bulk() {
        BulkRheology::Incompressible => f64::INFINITY,
        BulkRheology::Elastic(k) => *k,
        BulkRheology::Prony(p) => carson_sum(p.k_inf(), p.terms(), s),
    };
    equivalent_elastic(g, k)
}

/// `G_eq(s)` of a Prony series (Carson transform).
fn carson_of_series(p: &Prony, s: f64) -> f64 {
    let terms: Vec<(f64, f64)> = p.terms.iter().map(|t| (t.coefficient, t.tau)).collect();
    carson_sum(p.relaxed, &terms, s)
}

/// Time constants of the material (shear and bulk), increasing.
fn times(m: &Material) -> Vec<f64> {
    let mut t: Vec<f64> = m.shear().terms().iter().map(|p| p.1).collect();
    if let BulkRheology::Prony(p) = m.bulk() {
        t.extend(p.terms().iter().map(|p| p.1));
    }
    t.sort_by(f64::total_cmp);
    t
}

/// `n` log-spaced points from `lo` to `hi`.
fn log_space(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64))
        .collect()
}

fn material(shear: ShearProny, bulk: BulkInput) -> Material {
    Material::general(shear, bulk).unwrap()
}

/// The materials of the agreement tests, with names.
fn catalogue() -> Vec<(&'static str, Material)> {
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    let standard = Material::with_poisson(1.0, 1000.0, 1.0, 0.49).unwrap();
    let wide = spread_terms(&mut rng, 30);
    let wide_bulk = spread_terms(&mut rng, 12);
    let ten = spread_terms(&mut rng, 10);
    // shared times: every other bulk time equals a shear time
    let shared_shear = [(5.0, 1e-3), (2.0, 1e-1), (7.0, 1e1), (1.0, 1e3)];
    let shared_bulk = [(40.0, 1e-3), (3.0, 1e0), (11.0, 1e1), (0.5, 1e4)];
    vec![
        ("standard solid, nu 0.49", standard),
        (
            "standard solid, nu -0.9",
            Material::with_poisson(1.0, 30.0, 0.3, -0.9).unwrap(),
        ),
        (
            "30 terms over 20 decades, Prony bulk (12 terms)",
            material(
                ShearProny::new(1e-2, &wide).unwrap(),
                BulkInput::Prony(BulkProny::new(50.0, &wide_bulk).unwrap()),
            ),
        ),
        (
            "30 terms over 20 decades, nu 0.3",
            material(
                ShearProny::new(1e-2, &wide).unwrap(),
                BulkInput::Poisson(0.3),
            ),
        ),
        (
            "10 terms, K_0 = 1e4 g_inf",
            material(ShearProny::new(1.0, &ten).unwrap(), BulkInput::Elastic(1e4)),
        ),
        (
            "elastic shear, Prony bulk",
            material(
                ShearProny::elastic(1.0).unwrap(),
                BulkInput::Prony(BulkProny::new(0.1, &[(10.0, 1e-2), (100.0, 1e2)]).unwrap()),
            ),
        ),
        (
            "shared shear and bulk times",
            material(
                ShearProny::new(0.1, &shared_shear).unwrap(),
                BulkInput::Prony(BulkProny::new(1.0, &shared_bulk).unwrap()),
            ),
        ),
        (
            "incompressible, 30 terms",
            material(
                ShearProny::new(1e-2, &wide).unwrap(),
                BulkInput::Incompressible,
            ),
        ),
    ]
}

#[test]
fn series_matches_carson_formula() {
    for (name, m) in catalogue() {
        let g = carson::equivalent_relaxation(&m).unwrap();
        let mut worst: f64 = 0.0;
        for s in log_space(1e-14, 1e14, 561) {
            let direct = carson_formula(&m, s);
            let series = carson_of_series(&g, s);
            worst = worst.max(((series - direct) / direct).abs());
        }
        println!("{name}: max relative error of G_eq(s) on s > 0: {worst:.2e}");
        assert!(worst < SERIES_RTOL, "{name}: {worst:e}");
    }
}

#[test]
fn glassy_and_relaxed_closed_forms() {
    for (name, m) in catalogue() {
        let g = carson::equivalent_relaxation(&m).unwrap();
        let g0 = m.shear().glassy();
        let k0 = m.bulk_glassy();
        let (gi, ki) = (m.shear().g_inf(), m.bulk_relaxed());
        let glassy = if k0.is_infinite() {
            g0
        } else {
            g0 * (3.0 * k0 + g0) / (3.0 * k0 + 4.0 * g0)
        };
        let relaxed = if ki.is_infinite() {
            gi
        } else {
            gi * (3.0 * ki + gi) / (3.0 * ki + 4.0 * gi)
        };
        assert_relative_eq!(g.glassy(), glassy, max_relative = SERIES_RTOL);
        assert_relative_eq!(g.eval(0.0), glassy, max_relative = SERIES_RTOL);
        assert_relative_eq!(g.relaxed, relaxed, max_relative = SERIES_RTOL);
        assert_relative_eq!(m.equivalent_glassy(), glassy, max_relative = 1e-15);
        assert_relative_eq!(m.equivalent_relaxed(), relaxed, max_relative = 1e-15);
        println!("{name}: {} terms", g.terms.len());
    }
}

/// The two routes to `G_eq(t)`: the Prony series of `material::carson` and the Talbot inversion
/// of `theory::bromwich`, over `t` from `1e-3 min(tau)` to `1e3 max(tau)`.
#[test]
fn talbot_agrees_with_series() {
    for (name, m) in catalogue() {
        let g = carson::equivalent_relaxation(&m).unwrap();
        let t = times(&m);
        let (lo, hi) = (1e-3 * t[0], 1e3 * t[t.len() - 1]);
        let mut worst: f64 = 0.0;
        let mut mean = 0.0;
        let points = log_space(lo, hi, 400);
        for &t in &points {
            let talbot = bromwich::equivalent_relaxation_at(&m, t).unwrap();
            let series = g.eval(t);
            let e = ((talbot - series) / series).abs();
            worst = worst.max(e);
            mean += e / points.len() as f64;
        }
        println!("{name}: Talbot vs series over [{lo:.0e}, {hi:.0e}] s: max {worst:.2e}, mean {mean:.2e}");
        assert!(worst < TALBOT_RTOL, "{name}: {worst:e}");
        assert_eq!(
            bromwich::equivalent_relaxation_at(&m, 0.0).unwrap(),
            m.equivalent_glassy()
        );
    }
}

/// Error of the Talbot rule against the node count, printed per material (the numbers quoted in
/// `theory::bromwich`): it falls like `3.89^-N` down to a rounding floor that grows with `N`.
#[test]
fn talbot_error_against_nodes() {
    for (name, m) in catalogue() {
        let g = carson::equivalent_relaxation(&m).unwrap();
        let t = times(&m);
        let points = log_space(1e-3 * t[0], 1e3 * t[t.len() - 1], 400);
        let mut errors = Vec::new();
        for nodes in [8, 12, 16, 20, 22, 24, 26, 28, 30, 32, 36, 40, 48] {
            let worst = points
                .iter()
                .map(|&t| {
                    let e = bromwich::equivalent_relaxation_with(&m, t, nodes).unwrap();
                    ((e - g.eval(t)) / g.eval(t)).abs()
                })
                .fold(0.0, f64::max);
            println!("{name}: N = {nodes}: max relative error {worst:.2e}");
            errors.push(worst);
        }
        // geometric convergence at first: N = 8 -> 16 gains at least 3.89^8 / 10 ~ 5e3, and the
        // default N = 28 is within the tolerance
        assert!(errors[0] / errors[2] > 5e3, "{name}: {errors:?}");
        assert!(errors[7] < TALBOT_RTOL, "{name}: {errors:?}");
    }
}

/// One shear term with an elastic (or incompressible) bulk is the standard solid: the closed
/// form of docs/theory.md §2 (`Material::equivalent_relaxation`), term by term.
#[test]
fn one_term_is_the_standard_solid() {
    for (nu, g1, eta) in [
        (0.45, 100.0, 1.0),
        (0.0, 10.0, 2.5),
        (-0.9, 30.0, 0.3),
        (0.499, 3.0, 7.0),
        (0.49999, 1e3, 1e-3),
        (0.5, 50.0, 1.0),
        (0.3, 0.0, 1.0),
        (0.3, 5.0, 0.0),
    ] {
        let m = Material::with_poisson(1.0, g1, eta, nu).unwrap();
        let closed = m.as_standard_solid().unwrap().equivalent_relaxation();
        let general = carson::equivalent_relaxation(&m).unwrap();
        assert_eq!(general.terms.len(), closed.terms.len(), "nu {nu}");
        assert_relative_eq!(general.relaxed, closed.relaxed, max_relative = 1e-15);
        for (a, b) in general.terms.iter().zip(&closed.terms) {
            assert_relative_eq!(a.tau, b.tau, max_relative = SERIES_RTOL);
            assert_relative_eq!(a.coefficient, b.coefficient, max_relative = SERIES_RTOL);
        }
        for t in [0.0, 1e-4, 0.01, 0.3, 1.0, 10.0, 1e3] {
            assert_relative_eq!(general.eval(t), closed.eval(t), max_relative = SERIES_RTOL);
        }
    }
}

/// `K -> inf` (`K = 1e30 g`, elastic or Prony bulk) gives the shear series back: the new poles sit
/// within `~1e-30` of the shear poles (same double) and carry the missing three quarters.
#[test]
fn stiff_bulk_gives_the_shear_series() {
    let mut rng = Rng(7);
    let terms = spread_terms(&mut rng, 30);
    let shear = ShearProny::new(1.0, &terms).unwrap();
    let stiff = 1e30 * shear.glassy();
    let bulk_terms = [(stiff, 1e-5), (stiff, 1e5)];
    for bulk in [
        BulkInput::Elastic(stiff),
        BulkInput::Prony(BulkProny::new(stiff, &bulk_terms).unwrap()),
    ] {
        let m = material(shear.clone(), bulk);
        let g = carson::equivalent_relaxation(&m).unwrap();
        for t in log_space(1e-13, 1e13, 300) {
            assert_relative_eq!(g.eval(t), shear.relaxation(t), max_relative = SERIES_RTOL);
        }
        // Each shear term comes back whole (a quarter from the shear pole, three quarters from
        // the zero of 3K + 4G within ~1e-30 of it: the same double); the bulk poles cancel.
        for &(c, tau) in shear.terms() {
            let back: f64 = g
                .terms
                .iter()
                .filter(|p| p.tau == tau)
                .map(|p| p.coefficient)
                .sum();
            assert_relative_eq!(back, c, max_relative = SERIES_RTOL);
        }
        // What is left: the zeros of 3K + 4G near the zeros of K, negligible coefficients.
        let rest: Vec<_> = g
            .terms
            .iter()
            .filter(|p| !shear.terms().iter().any(|&(_, tau)| tau == p.tau))
            .collect();
        println!(
            "{} terms, {} off the shear times: {rest:?}",
            g.terms.len(),
            rest.len()
        );
        assert!(rest.len() <= bulk_terms.len());
        assert!(rest.iter().all(|p| p.coefficient < 1e-25 * shear.glassy()));
        assert!(g.terms.iter().all(|p| p.coefficient >= 0.0));
    }
}

/// A term split into two equal halves (same time) is merged by the constructors: the same series
/// to the last bit. Split at two times `1e-10` apart, the result moves by `O(1e-10)` only: nearly
/// coincident poles cost no accuracy.
#[test]
fn split_term_changes_nothing() {
    let bulk = || BulkInput::Prony(BulkProny::new(2.0, &[(8.0, 0.5), (1.0, 3.0)]).unwrap());
    let whole = material(
        ShearProny::new(1.0, &[(10.0, 1.0), (4.0, 0.01)]).unwrap(),
        bulk(),
    );
    let halves = material(
        ShearProny::new(1.0, &[(5.0, 1.0), (4.0, 0.01), (5.0, 1.0)]).unwrap(),
        BulkInput::Prony(BulkProny::new(2.0, &[(4.0, 0.5), (1.0, 3.0), (4.0, 0.5)]).unwrap()),
    );
    let near = material(
        ShearProny::new(1.0, &[(5.0, 1.0), (4.0, 0.01), (5.0, 1.0 + 1e-10)]).unwrap(),
        bulk(),
    );
    let g = carson::equivalent_relaxation(&whole).unwrap();
    assert_eq!(carson::equivalent_relaxation(&halves).unwrap(), g);
    let gn = carson::equivalent_relaxation(&near).unwrap();
    for t in log_space(1e-4, 1e3, 100) {
        assert_relative_eq!(gn.eval(t), g.eval(t), max_relative = 1e-9);
    }
    assert_relative_eq!(gn.glassy(), g.glassy(), max_relative = SERIES_RTOL);
}

/// Every bad input gives the exact variant with the field, the input index and the value.
#[test]
fn bad_input_names_field_and_index() {
    let term = |r: Result<ShearProny, Error>| match r {
        Err(Error::PronyTerm {
            field,
            index,
            value,
            ..
        }) => (field, index, value),
        other => panic!("expected Error::PronyTerm, got {other:?}"),
    };
    let (f, i, v) = term(ShearProny::new(1.0, &[(1.0, 1.0), (-2.0, 3.0)]));
    assert_eq!((f, i, v), ("g_i", 1, -2.0));
    let (f, i, v) = term(ShearProny::new(
        1.0,
        &[(1.0, 1.0), (1.0, 2.0), (f64::NAN, 3.0)],
    ));
    assert_eq!((f, i), ("g_i", 2));
    assert!(v.is_nan());
    let (f, i, v) = term(ShearProny::new(1.0, &[(1.0, 0.0)]));
    assert_eq!((f, i, v), ("tau_i", 0, 0.0));
    let (f, i, v) = term(ShearProny::new(1.0, &[(1.0, 1.0), (1.0, -1.0)]));
    assert_eq!((f, i, v), ("tau_i", 1, -1.0));
    let (f, i, v) = term(ShearProny::new(1.0, &[(f64::INFINITY, 1.0)]));
    assert_eq!((f, i, v), ("g_i", 0, f64::INFINITY));
    let (f, i, v) = term(ShearProny::new(1.0, &[(1.0, f64::INFINITY)]));
    assert_eq!((f, i, v), ("tau_i", 0, f64::INFINITY));
    let msg = ShearProny::new(1.0, &[(1.0, 1.0), (-2.0, 3.0)])
        .unwrap_err()
        .to_string();
    assert!(msg.contains("g_i[1] = -2e0"), "{msg}");

    match BulkProny::new(1.0, &[(1.0, 1.0), (2.0, f64::NAN)]) {
        Err(Error::PronyTerm { field, index, .. }) => assert_eq!((field, index), ("theta_j", 1)),
        other => panic!("{other:?}"),
    }
    match BulkProny::new(1.0, &[(-1.0, 1.0)]) {
        Err(Error::PronyTerm {
            field,
            index,
            value,
            ..
        }) => assert_eq!((field, index, value), ("k_j", 0, -1.0)),
        other => panic!("{other:?}"),
    }
    let out_of_range = |r: Result<(), Error>| match r {
        Err(Error::OutOfRange { field, value, .. }) => (field, value),
        other => panic!("expected Error::OutOfRange, got {other:?}"),
    };
    for (g_inf, value) in [(0.0, 0.0), (-1.0, -1.0), (f64::INFINITY, f64::INFINITY)] {
        assert_eq!(
            out_of_range(ShearProny::new(g_inf, &[]).map(|_| ())),
            ("g_inf", value)
        );
    }
    assert!(out_of_range(ShearProny::elastic(f64::NAN).map(|_| ()))
        .1
        .is_nan());
    for k_inf in [-3.0, f64::INFINITY] {
        assert_eq!(
            out_of_range(BulkProny::new(k_inf, &[(1.0, 1.0)]).map(|_| ())),
            ("k_inf", k_inf)
        );
    }
    // a bulk that relaxes to zero is allowed, as a shear series that does (a liquid)
    assert!(BulkProny::new(0.0, &[(1.0, 1.0)]).is_ok());
    assert!(ShearProny::new(0.0, &[(1.0, 1.0)]).is_ok());
    // empty, or nothing left after dropping zero moduli
    assert_eq!(
        out_of_range(BulkProny::new(1.0, &[]).map(|_| ())),
        ("k_j", 0.0)
    );
    assert_eq!(
        out_of_range(BulkProny::new(1.0, &[(0.0, 1.0), (0.0, 2.0)]).map(|_| ())),
        ("k_j", 0.0)
    );
    let shear = || ShearProny::new(1.0, &[(1.0, 1.0)]).unwrap();
    assert_eq!(
        out_of_range(Material::general(shear(), BulkInput::Elastic(-1.0)).map(|_| ())),
        ("k_0", -1.0)
    );
    for nu in [0.6, -1.0] {
        assert_eq!(
            out_of_range(Material::general(shear(), BulkInput::Poisson(nu)).map(|_| ())),
            ("nu", nu)
        );
    }
    // nu = 0.5 is incompressible; the overflow of two finite moduli with one time is refused
    assert_eq!(
        Material::general(shear(), BulkInput::Poisson(0.5))
            .unwrap()
            .bulk(),
        &BulkRheology::Incompressible
    );
    assert_eq!(
        out_of_range(ShearProny::new(1.0, &[(f64::MAX, 1.0), (f64::MAX, 1.0)]).map(|_| ())),
        ("g_i", f64::INFINITY)
    );
}

/// Sorting, merging and dropping in the constructors.
#[test]
fn constructors_normalise() {
    let g = ShearProny::new(2.0, &[(1.0, 5.0), (0.0, 1.0), (2.0, 0.5), (3.0, 5.0)]).unwrap();
    assert_eq!(g.terms(), &[(2.0, 0.5), (4.0, 5.0)]);
    assert_eq!(g.glassy(), 8.0);
    assert_relative_eq!(
        g.relaxation(1.0),
        2.0 + 2.0 * (-2.0f64).exp() + 4.0 * (-0.2f64).exp()
    );
    let k = BulkProny::new(1.0, &[(3.0, 2.0), (1.0, 1.0)]).unwrap();
    assert_eq!(k.terms(), &[(1.0, 1.0), (3.0, 2.0)]);
    assert_eq!(k.glassy(), 5.0);
    let m = material(g, BulkInput::Prony(k));
    assert_eq!(m.bulk_relaxation(0.0), 5.0);
    assert_eq!(m.bulk_relaxed(), 1.0);
}

/// A random bulk of one of the four kinds from `(kind, scale, terms)`.
fn random_bulk(kind: u8, scale: f64, nu: f64, terms: &[(f64, f64)]) -> BulkInput {
    match kind {
        0 => BulkInput::Incompressible,
        1 => BulkInput::Elastic(scale),
        2 => BulkInput::Poisson(nu),
        _ => BulkInput::Prony(BulkProny::new(scale, terms).unwrap()),
    }
}

fn term_strategy(max: usize) -> impl Strategy<Value = Vec<(f64, f64)>> {
    prop::collection::vec((-4.0f64..4.0, -10.0f64..10.0), 1..=max).prop_map(|v| {
        v.into_iter()
            .map(|(m, t)| (10f64.powf(m), 10f64.powf(t)))
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Random series (1 to 40 shear terms, times over 20 decades, moduli over 8, any bulk kind):
    /// no panic, every time positive and finite, every coefficient non-negative (theory: the
    /// coefficients are g/4, g (3k + g)/(3k + 4g) and (9/4)(-G K)/(lambda D') with G K < 0 at a
    /// zero of D), G_eq(t) non-increasing, and the series equals the Carson formula on s > 0;
    /// the same for the two-body combination with a second body.
    #[test]
    fn random_series_are_relaxation_functions(
        g_inf in -4.0f64..2.0,
        shear in term_strategy(40),
        kind in 0u8..4,
        scale in -3.0f64..8.0,
        nu in -0.99f64..0.5,
        bulk in term_strategy(10),
    ) {
        let shear = ShearProny::new(10f64.powf(g_inf), &shear).unwrap();
        let m = material(shear, random_bulk(kind, 10f64.powf(scale), nu, &bulk));
        let g = carson::equivalent_relaxation(&m).unwrap();
        prop_assert!(g.relaxed > 0.0 && g.relaxed.is_finite());
        for p in &g.terms {
            prop_assert!(p.tau > 0.0 && p.tau.is_finite(), "{:?}", p);
            prop_assert!(p.coefficient >= 0.0 && p.coefficient.is_finite(), "{:?}", p);
        }
        let mut last = f64::INFINITY;
        for t in log_space(1e-12, 1e12, 97) {
            let v = g.eval(t);
            prop_assert!(v <= last, "G_eq({t}) = {v} > {last}");
            last = v;
        }
        for s in log_space(1e-12, 1e12, 49) {
            let direct = carson_formula(&m, s);
            let series = carson_of_series(&g, s);
            prop_assert!(((series - direct) / direct).abs() < SERIES_RTOL, "s {s}: {series} vs {direct}");
        }
        prop_assert_eq!(g.relaxed, m.equivalent_relaxed());
        // two bodies: this one against a body whose G_eq is the shear series itself
        let other = Prony {
            relaxed: m.shear().g_inf(),
            terms: m
                .shear()
                .terms()
                .iter()
                .map(|&(c, tau)| mdr_impact::PronyTerm { coefficient: c, tau })
                .collect(),
        };
        let both = carson::combine(&g, &other).unwrap();
        for p in &both.terms {
            prop_assert!(p.tau > 0.0 && p.tau.is_finite(), "{:?}", p);
            prop_assert!(p.coefficient >= 0.0 && p.coefficient.is_finite(), "{:?}", p);
        }
        for s in log_space(1e-12, 1e12, 49) {
            let direct = combined_formula(&g, &other, s);
            let series = carson_of_series(&both, s);
            prop_assert!(((series - direct) / direct).abs() < SERIES_RTOL, "two bodies, s {s}: {series} vs {direct}");
        }
    }
}

/// `1 / G_tot(s) = 1 / G_A(s) + 1 / G_B(s)` directly at real `s > 0`.
fn combined_formula(a: &Prony, b: &Prony, s: f64) -> f64 {
    1.0 / (1.0 / carson_of_series(a, s) + 1.0 / carson_of_series(b, s))
}

/// Two bodies (docs/theory.md §8): the combined series against the compliance sum on `s > 0`,
/// identical bodies give `G / 2`, a much stiffer partner gives the softer body back, and the
/// glassy and relaxed values are the elastic combinations.
#[test]
fn two_bodies_combine_compliances() {
    let cat = catalogue();
    let series: Vec<(&str, Prony)> = cat
        .iter()
        .map(|(name, m)| (*name, carson::equivalent_relaxation(m).unwrap()))
        .collect();
    for (na, a) in &series {
        for (nb, b) in &series {
            let g = carson::combine(a, b).unwrap();
            let mut worst: f64 = 0.0;
            for s in log_space(1e-14, 1e14, 281) {
                let direct = combined_formula(a, b, s);
                worst = worst.max(((carson_of_series(&g, s) - direct) / direct).abs());
            }
            assert!(worst < SERIES_RTOL, "{na} + {nb}: {worst:e}");
            let harmonic = |x: f64, y: f64| x * y / (x + y);
            assert_relative_eq!(
                g.relaxed,
                harmonic(a.relaxed, b.relaxed),
                max_relative = 1e-15
            );
            assert_relative_eq!(
                g.glassy(),
                harmonic(a.glassy(), b.glassy()),
                max_relative = SERIES_RTOL
            );
            assert!(g.terms.iter().all(|p| p.coefficient >= 0.0 && p.tau > 0.0));
        }
        // identical bodies: half the relaxation function
        let twin = carson::combine(a, a).unwrap();
        let stiff = Prony {
            relaxed: 1e30 * a.glassy(),
            terms: vec![mdr_impact::PronyTerm {
                coefficient: 1e30 * a.glassy(),
                tau: 1.0,
            }],
        };
        let soft = carson::combine(a, &stiff).unwrap();
        for t in log_space(1e-13, 1e13, 200) {
            assert_relative_eq!(twin.eval(t), 0.5 * a.eval(t), max_relative = SERIES_RTOL);
            assert_relative_eq!(soft.eval(t), a.eval(t), max_relative = SERIES_RTOL);
        }
    }
    let bad = Prony {
        relaxed: -1.0,
        terms: vec![],
    };
    assert!(matches!(
        carson::combine(&series[0].1, &bad),
        Err(Error::OutOfRange {
            field: "relaxed",
            ..
        })
    ));
    // relaxing to zero is a liquid, but with no term nothing is left
    let empty = Prony {
        relaxed: 0.0,
        terms: vec![],
    };
    assert!(matches!(
        carson::combine(&series[0].1, &empty),
        Err(Error::OutOfRange {
            field: "glassy",
            ..
        })
    ));
}

/// Largest relative difference of two relaxation functions over `t` in `[lo, hi]` (and at 0).
fn time_domain_difference(a: &Prony, b: &Prony, lo: f64, hi: f64) -> f64 {
    std::iter::once(0.0)
        .chain(log_space(lo, hi, 301))
        .map(|t| ((a.eval(t) - b.eval(t)) / b.eval(t)).abs())
        .fold(0.0, f64::max)
}

/// The reference solver's route to `G_eq(t)` (`theory::poles`: relaxation times as roots in
/// the time domain, Brent's method from a crate, no code shared with `material::carson`) agrees
/// with the Carson composition of `fast` and with the Talbot inversion on every catalogue
/// material, at any `t`, to 1e-12; and the two-body series of both routes agree too.
#[test]
fn time_domain_route_agrees_with_carson_and_talbot() {
    let mut series = Vec::new();
    for (name, m) in catalogue() {
        let carson_route = carson::equivalent_relaxation(&m).unwrap();
        let poles_route = mdr_impact::solvers::theory::poles::equivalent_relaxation(&m).unwrap();
        let t = times(&m);
        let (lo, hi) = (1e-3 * t[0], 1e3 * t[t.len() - 1]);
        let d = time_domain_difference(&poles_route, &carson_route, lo, hi);
        println!(
            "{name}: poles vs carson {d:.1e} ({} / {} terms)",
            poles_route.terms.len(),
            carson_route.terms.len()
        );
        assert!(d < 1e-12, "{name}: {d:e}");
        for &t in &log_space(lo, hi, 60) {
            let talbot = bromwich::equivalent_relaxation_at(&m, t).unwrap();
            let e = ((poles_route.eval(t) - talbot) / talbot).abs();
            assert!(e < TALBOT_RTOL, "{name} t {t:e}: {e:e}");
        }
        series.push((name, lo, hi, carson_route, poles_route));
    }
    for (na, lo_a, hi_a, ca, pa) in &series {
        for (nb, lo_b, hi_b, cb, pb) in &series {
            let c = carson::combine(ca, cb).unwrap();
            let p = mdr_impact::solvers::theory::poles::series(pa, pb).unwrap();
            let d = time_domain_difference(&p, &c, lo_a.min(*lo_b), hi_a.max(*hi_b));
            assert!(d < 1e-12, "{na} + {nb}: {d:e}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// Random materials (1 to 40 shear terms over 20 decades, moduli over 8 decades, any bulk):
    /// the time-domain route and the Carson composition agree to 1e-11 at every `t`, and so do
    /// their two-body series against the shear series as the second body.
    #[test]
    fn time_domain_route_random(
        g_inf in -4.0f64..2.0,
        shear in term_strategy(40),
        kind in 0u8..4,
        scale in -3.0f64..8.0,
        nu in -0.99f64..0.5,
        bulk in term_strategy(10),
    ) {
        let shear = ShearProny::new(10f64.powf(g_inf), &shear).unwrap();
        let m = material(shear, random_bulk(kind, 10f64.powf(scale), nu, &bulk));
        let c = carson::equivalent_relaxation(&m).unwrap();
        let p = mdr_impact::solvers::theory::poles::equivalent_relaxation(&m).unwrap();
        let d = time_domain_difference(&p, &c, 1e-13, 1e13);
        prop_assert!(d < 1e-11, "{d:e}");
        let other = Prony {
            relaxed: m.shear().g_inf(),
            terms: m
                .shear()
                .terms()
                .iter()
                .map(|&(c, tau)| mdr_impact::PronyTerm { coefficient: c, tau })
                .collect(),
        };
        let cc = carson::combine(&c, &other).unwrap();
        let pp = mdr_impact::solvers::theory::poles::series(&p, &other).unwrap();
        let d = time_domain_difference(&pp, &cc, 1e-13, 1e13);
        prop_assert!(d < 1e-11, "two bodies: {d:e}");
    }
}
