//! Property test of the accuracy contract of `auto` over the whole input range (the quick
//! counterpart of the ignored stress test in `tests/stress.rs`): `nu` in (-1, 0.5] (0.5 exactly
//! for a share of the cases), `p2` and `p3` log-uniform over 1e-8..1e8, rtol from 1e-2 to 1e-11.
//! Never a panic (proptest fails on one), never NaN; on success the CoR is in (0, 1] with an error
//! estimate at or below rtol, and for rtol >= 1e-8 it agrees with `fast` at rtol 1e-12 (or
//! `reference` at 1e-11 where `fast` refuses) within `rtol + 1e-11`.

use mdr_impact::*;
use proptest::prelude::*;

fn solve_groups(g: Groups, solver: SolverKind, rtol: f64) -> Result<Outcome> {
    solve(
        &Impact::from_groups(g)?,
        &SolveOptions {
            solver,
            rtol,
            ..Default::default()
        },
    )
}

/// The truth of the comparison: `fast` at 1e-12, else `reference` at 1e-11, else none.
fn truth(g: Groups) -> Option<f64> {
    solve_groups(g, SolverKind::Fast, 1e-12)
        .or_else(|_| solve_groups(g, SolverKind::Reference, 1e-11))
        .ok()
        .map(|o| o.cor)
}

fn nu_strategy() -> impl Strategy<Value = f64> {
    // 0.5 - 1.5 u with u in [0, 1): (-1, 0.5]; one case in five exactly incompressible
    prop_oneof![4 => (0.0f64..1.0).prop_map(|u| 0.5 - 1.5 * u), 1 => Just(0.5)]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn auto_within_rtol_or_refused(
        nu in nu_strategy(),
        lp2 in -8.0f64..=8.0,
        lp3 in -8.0f64..=8.0,
        k in 2i32..=11,
    ) {
        let rtol = 10f64.powi(-k);
        let g = Groups::new(nu, 10f64.powf(lp2), 10f64.powf(lp3)).unwrap();
        match solve_groups(g, SolverKind::Auto, rtol) {
            Ok(o) => {
                prop_assert!(o.cor.is_finite() && o.cor > 0.0 && o.cor <= 1.0, "cor {}", o.cor);
                let est = o.cor_error_estimate;
                prop_assert!(
                    est.is_some_and(|e| e.is_finite() && e <= rtol),
                    "estimate {est:?} above rtol {rtol:e}"
                );
                if rtol >= 1e-8 {
                    if let Some(t) = truth(g) {
                        let rel = ((o.cor - t) / t).abs();
                        prop_assert!(
                            rel <= rtol + 1e-11,
                            "cor {} truth {t} rel. error {rel:e} > rtol {rtol:e} (solver {}, fallback {:?})",
                            o.cor, o.solver, o.fallback
                        );
                    }
                }
            }
            // a refusal is an error that says so; a non-finite value would have been refused
            // as NonFinite, which the contract forbids as much as a NaN
            Err(Error::NonFinite { what, value }) => {
                prop_assert!(false, "non-finite {what} = {value}");
            }
            Err(_) => {}
        }
    }
}
