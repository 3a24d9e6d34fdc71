//! General rheology (theory notes §8): validated Prony series in shear and bulk, the equivalent
//! relaxation `G_eq(t)` as an exact Prony series (`material::carson`), and its independent
//! Talbot inversion (`theory::bromwich`).
//!
//! Checks: the series against the Carson formula evaluated directly on `s > 0`, the glassy and
//! relaxed closed forms, the standard solid's closed form (theory notes §2), the limits
//! `K -> inf` and split terms, the two routes against each other, bad input, and random series.

use approx::assert_relative_eq;
use mdr_impact::material::carson;
use mdr_impact::material::rheology::{
    equivalent_elastic, BulkProny, BulkRheology, GeneralMaterial, ShearProny,
};
use mdr_impact::material::{Material, Prony};
use mdr_impact::theory::bromwich;
use mdr_impact::Error;
use proptest::prelude::*;

/// Tolerance of the Prony series of `G_eq` against the Carson formula and the closed forms.
const SERIES_RTOL: f64 = 1e-12;
/// Tolerance of the Talbot inversion against the Prony series (measured: see
/// `talbot_agrees_with_series`).
const TALBOT_RTOL: f64 = 1e-12;

/// Tiny deterministic generator (xorshift64*), uniform in [0, 1).
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
    relaxed + terms.iter().map(|&(m, tau)| m * s * tau / (1.0 + s * tau)).sum::<f64>()
}

/// `G_eq(s)` directly from the formula `G (3K + G) / (3K + 4G)` at real `s > 0`.
fn carson_formula(m: &GeneralMaterial, s: f64) -> f64 {
    let g = carson_sum(m.shear().g_inf(), m.shear().terms(), s);
    let k = match m.bulk() {
        BulkRheology::Incompressible => f64::INFINITY,
        BulkRheology::Elastic(k) => *k,
        BulkRheology::Prony(p) => carson_sum(p.k_inf(), p.terms(), s),
        BulkRheology::Poisson(_) => unreachable!("resolved by GeneralMaterial::new"),
    };
    equivalent_elastic(g, k)
}

/// `G_eq(s)` of a Prony series (Carson transform).
fn carson_of_series(p: &Prony, s: f64) -> f64 {
    let terms: Vec<(f64, f64)> = p.terms.iter().map(|t| (t.coefficient, t.tau)).collect();
    carson_sum(p.relaxed, &terms, s)
}

/// Time constants of the material (shear and bulk), increasing.
fn times(m: &GeneralMaterial) -> Vec<f64> {
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

fn material(shear: ShearProny, bulk: BulkRheology) -> GeneralMaterial {
    GeneralMaterial::new(shear, bulk).unwrap()
}

/// The materials of the agreement tests, with names.
fn catalogue() -> Vec<(&'static str, GeneralMaterial)> {
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    let standard = Material::with_poisson(1.0, 1000.0, 1.0, 0.49).unwrap();
    let wide = spread_terms(&mut rng, 30);
    let wide_bulk = spread_terms(&mut rng, 12);
    let ten = spread_terms(&mut rng, 10);
    // shared times: every other bulk time equals a shear time
    let shared_shear = [(5.0, 1e-3), (2.0, 1e-1), (7.0, 1e1), (1.0, 1e3)];
    let shared_bulk = [(40.0, 1e-3), (3.0, 1e0), (11.0, 1e1), (0.5, 1e4)];
    vec![
        ("standard solid, nu 0.49", standard.general()),
        (
            "standard solid, nu -0.9",
            Material::with_poisson(1.0, 30.0, 0.3, -0.9)
                .unwrap()
                .general(),
        ),
        (
            "30 terms over 20 decades, Prony bulk (12 terms)",
            material(
                ShearProny::new(1e-2, &wide).unwrap(),
                BulkRheology::Prony(BulkProny::new(50.0, &wide_bulk).unwrap()),
            ),
        ),
        (
            "30 terms over 20 decades, nu 0.3",
            material(
                ShearProny::new(1e-2, &wide).unwrap(),
                BulkRheology::Poisson(0.3),
            ),
        ),
        (
            "10 terms, K_0 = 1e4 g_inf",
            material(
                ShearProny::new(1.0, &ten).unwrap(),
                BulkRheology::Elastic(1e4),
            ),
        ),
        (
            "elastic shear, Prony bulk",
            material(
                ShearProny::elastic(1.0).unwrap(),
                BulkRheology::Prony(BulkProny::new(0.1, &[(10.0, 1e-2), (100.0, 1e2)]).unwrap()),
            ),
        ),
        (
            "shared shear and bulk times",
            material(
                ShearProny::new(0.1, &shared_shear).unwrap(),
                BulkRheology::Prony(BulkProny::new(1.0, &shared_bulk).unwrap()),
            ),
        ),
        (
            "incompressible, 30 terms",
            material(
                ShearProny::new(1e-2, &wide).unwrap(),
                BulkRheology::Incompressible,
            ),
        ),
    ]
}

#[test]
fn series_matches_carson_formula() {
    for (name, m) in catalogue() {
        let g = m.equivalent_relaxation().unwrap();
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
        let g = m.equivalent_relaxation().unwrap();
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
