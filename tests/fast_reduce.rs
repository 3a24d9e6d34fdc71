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
}
