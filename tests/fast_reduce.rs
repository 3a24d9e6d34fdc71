//! The reduction of terms outside the contact window (`fast`, module `reduce`: Gauss rules of
//! the spectrum's far ends): the reduced solve agrees to rtol with an unreduced solve 100x
//! tighter (and with the unreduced solve at rtol) on every general validation case (the real
//! polymers too) and on random series, and the reduced solve's estimate (which includes the
//! reduction's bound) stays within rtol.
use mdr_impact::report::catalogue::general_entries;
use mdr_impact::{solvers::fast, Prony, PronyTerm};
use proptest::prelude::*;

fn check(name: &str, p: &Prony, rtol: f64) -> Result<(usize, f64), TestCaseError> {
    let full = fast::impact_unreduced(p, rtol, false).unwrap();
    let tight = fast::impact_unreduced(p, (rtol / 100.0).max(1e-12), false).unwrap();
    let red = fast::impact(p, rtol, false).unwrap();
    let err = ((red.cor - tight.cor) / tight.cor).abs();
    prop_assert!(
        err <= rtol,
        "{name} rtol {rtol:e}: reduced {} vs unreduced at rtol/100 {} ({err:e})",
        red.cor,
        tight.cor
    );
    let diff = ((red.cor - full.cor) / full.cor).abs();
    prop_assert!(
        diff <= rtol,
        "{name} rtol {rtol:e}: reduced {} vs unreduced {} ({diff:e})",
        red.cor,
        full.cor
    );
    prop_assert!(red.cor_error_estimate.unwrap() <= rtol);
    Ok((red.work.evaluations as usize, err))
}

#[test]
fn reduced_agrees_with_unreduced_on_general_cases() {
    // the synthetic cases and the real polymers (scenes/polyisobutylene.toml, scenes/epoxy.toml)
    for case in general_entries().unwrap() {
        let p = case.impact.canonical_relaxation();
        for rtol in [1e-4, 1e-6, 1e-8, 1e-10] {
            let (evals, err) = check(case.id, &p, rtol).unwrap();
            println!(
                "{} rtol {rtol:e}: {} terms, {evals} evaluations, reduced vs unreduced {err:.1e}",
                case.id,
                p.terms.len()
            );
        }
    }
}

#[test]
fn reduced_agrees_with_unreduced_on_real_polymers_at_several_velocities() {
    // a velocity changes the canonical times (over L/v0) and moduli, so the contact window
    // moves over the spectrum: other groups of fast terms are merged at each velocity
    for case in general_entries().unwrap() {
        if !matches!(case.id, "polyisobutylene" | "epoxy") {
            continue;
        }
        for factor in [0.03, 0.3, 3.0, 30.0] {
            let v0 = case.impact.velocity() * factor;
            let p = case.impact.at_velocity(v0).unwrap().canonical_relaxation();
            for rtol in [1e-4, 1e-7, 1e-10] {
                let (evals, err) = check(case.id, &p, rtol).unwrap();
                println!(
                    "{} v0 {v0:.3} m/s rtol {rtol:e}: {evals} evaluations, reduced vs unreduced \
                     {err:.1e}",
                    case.id
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Random series of 3 to 40 terms over 24 decades around the contact time.
    #[test]
    fn reduced_agrees_with_unreduced_on_random_series(
        terms in prop::collection::vec((-3.0f64..3.0, -12.0f64..12.0), 3..=40),
        lrtol in -10.0f64..-3.0,
    ) {
        let p = Prony {
            relaxed: 1.0,
            terms: terms
                .iter()
                .map(|&(lc, lt)| PronyTerm { coefficient: 10f64.powf(lc), tau: 10f64.powf(lt) })
                .collect(),
        };
        check("random", &p, 10f64.powf(lrtol))?;
    }

    /// A group of 3 to 12 fast terms spread over 1 to 6 decades, its slowest between 3e-4 and
    /// 0.3 in canonical time (the contact lasts about 1 to 3), beside a term inside the contact
    /// window and a slow one, glassy modulus 1 to 1e4 times the relaxed one: the groups the
    /// fast side merges with rules of several points, where the initial layers' part of the
    /// bound decides.
    #[test]
    fn reduced_agrees_with_unreduced_on_spread_fast_groups(
        fast in prop::collection::vec((0.1f64..1.0, 0.0f64..1.0), 3..=12),
        (ltop, span, lglassy) in (-3.5f64..-0.5, 1.0f64..6.0, 0.0f64..4.0),
        (mid, ltau_mid, slow) in (0.0f64..0.5, -0.5f64..0.5, 0.0f64..0.5),
        lrtol in -10.0f64..-4.0,
    ) {
        let glassy = 10f64.powf(lglassy);
        let total: f64 = fast.iter().map(|t| t.0).sum();
        let mut terms: Vec<PronyTerm> = fast
            .iter()
            .map(|&(w, x)| PronyTerm {
                coefficient: glassy * w / total,
                tau: 10f64.powf(ltop - span * x),
            })
            .collect();
        terms.push(PronyTerm { coefficient: glassy * mid, tau: 10f64.powf(ltau_mid) });
        terms.push(PronyTerm { coefficient: glassy * slow, tau: 1e4 });
        let p = Prony { relaxed: 1.0, terms };
        check("spread fast group", &p, 10f64.powf(lrtol))?;
    }
}
