//! Stability stress tests: over the paper's range and far beyond, every run ends with a finite
//! CoR in (0, 1] or a clear error, never NaN and never a hang (work limits turn into errors).
//! Property tests for scaling invariance, energy balance and refinement.

use mdr_impact::solvers::mdr;
use mdr_impact::*;
use proptest::prelude::*;

fn ok_or_clear(r: &Result<Outcome>) -> std::result::Result<(), String> {
    match r {
        Ok(o) => {
            let fields = [
                o.cor,
                o.contact_time,
                o.max_indentation,
                o.max_force,
                o.dissipated_energy,
            ];
            if fields.iter().all(|x| x.is_finite())
                && o.cor > 0.0
                && o.cor <= 1.0
                && o.dissipated_energy >= 0.0
            {
                Ok(())
            } else {
                Err(format!("bad outcome {o:?}"))
            }
        }
        Err(Error::AccuracyNotReached { estimate, .. })
            if estimate.is_finite() || estimate.is_infinite() =>
        {
            Ok(())
        }
        Err(Error::WorkLimit { .. }) => Ok(()),
        Err(e) => Err(format!("unexpected error {e}")),
    }
}

/// nu from -0.99 to 0.5, p2 and p3 over 1e-6..1e6, with a work limit that keeps each run short.
#[test]
fn wide_range_never_nan_never_hangs() {
    let mut failures = Vec::new();
    for nu in [-0.99, -0.5, 0.0, 0.45, 0.499, 0.5] {
        for lp2 in [-6, -3, 0, 3, 6] {
            for lp3 in [-6, -3, 0, 3, 6] {
                let (p2, p3) = (10f64.powi(lp2), 10f64.powi(lp3));
                let imp = Impact::from_groups(Groups::new(nu, p2, p3).unwrap()).unwrap();
                for solver in [SolverKind::Mdr, SolverKind::Auto] {
                    let opts = SolveOptions {
                        solver,
                        rtol: 1e-3,
                        work_limit: 20_000_000,
                        ..Default::default()
                    };
                    if let Err(m) = ok_or_clear(&solve(&imp, &opts)) {
                        failures.push(format!("{solver} nu={nu} p2={p2:e} p3={p3:e}: {m}"));
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Dimensional inputs over many decades: valid results or a clear error, never NaN.
#[test]
fn dimensional_extremes() {
    for lm in [-9, -3, 3] {
        for lr in [-7, -2, 2] {
            for lv in [-4, 0, 3] {
                for lg in [2, 6, 11] {
                    let r = (|| {
                        let s = Sphere::new(10f64.powi(lm), 10f64.powi(lr))?;
                        let g = 10f64.powi(lg);
                        let mat = Material::with_poisson(g, 10.0 * g, g * 1e-4, 0.45)?;
                        let imp = Impact::new(s, 10f64.powi(lv), mat)?;
                        solve(
                            &imp,
                            &SolveOptions {
                                rtol: 1e-3,
                                work_limit: 20_000_000,
                                ..Default::default()
                            },
                        )
                    })();
                    match &r {
                        Err(Error::NonFinite { .. } | Error::OutOfScale { .. }) => {}
                        other => ok_or_clear(other).unwrap(),
                    }
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    /// Same groups from random dimensional inputs: same CoR.
    #[test]
    fn scaling_invariance(nu in -0.95f64..0.5, lp2 in -3.0f64..1.0, lp3 in -2.0f64..2.0,
                          lm in -6.0f64..2.0, lr in -5.0f64..0.0, lv in -2.0f64..1.0, lg in 3.0f64..10.0) {
        let (p2, p3) = (10f64.powf(lp2), 10f64.powf(lp3));
        let (m, r, v0, g) = (10f64.powf(lm), 10f64.powf(lr), 10f64.powf(lv), 10f64.powf(lg));
        let eta = p3 / (v0 * r / (m * m * g.powi(3))).powf(0.2);
        let imp = Impact::new(Sphere::new(m, r).unwrap(), v0, Material::with_poisson(g, g / p2, eta, nu).unwrap()).unwrap();
        let canonical = Impact::from_groups(Groups::new(nu, p2, p3).unwrap()).unwrap();
        let opts = SolveOptions { solver: SolverKind::Mdr, rtol: 1e-4, ..Default::default() };
        let (a, b) = (solve(&imp, &opts).unwrap(), solve(&canonical, &opts).unwrap());
        prop_assert!((a.cor - b.cor).abs() <= 1e-8 * b.cor, "{} vs {}", a.cor, b.cor);
    }

    /// Dissipated energy is non-negative and equals (1 - e^2) m v0^2 / 2.
    #[test]
    fn energy_balance(nu in -0.95f64..0.5, lp2 in -3.0f64..1.0, lp3 in -2.0f64..2.0) {
        let imp = Impact::from_groups(Groups::new(nu, 10f64.powf(lp2), 10f64.powf(lp3)).unwrap()).unwrap();
        let o = solve(&imp, &SolveOptions { solver: SolverKind::Mdr, rtol: 1e-4, ..Default::default() }).unwrap();
        prop_assert!(o.dissipated_energy >= 0.0);
        prop_assert!((o.dissipated_energy - 0.5 * (1.0 - o.cor * o.cor)).abs() <= 1e-14);
    }

    /// Refining the MDR reduces the CoR error against the reference solver, in the asymptotic
    /// range. Coarse levels are pre-asymptotic: there the error can be small by cancellation
    /// and grow on refinement (random inputs found 16 x 32 -> 64 x 128 going from 8e-5 to 5e-4),
    /// which is why the adaptive driver demands three consistent differences. Even past 128 x 256
    /// a single 4x refinement can leave the error unchanged (found: 2.6e-6 -> 2.7e-6 -> 4.2e-7),
    /// so the property is on the 16x refinement from the coarser two levels to 2048 x 4096:
    /// the error must drop by at least 4.
    #[test]
    fn refinement_reduces_error(nu in -0.9f64..0.5, lp2 in -3.0f64..0.0, lp3 in -1.0f64..1.0) {
        let imp = Impact::from_groups(Groups::new(nu, 10f64.powf(lp2), 10f64.powf(lp3)).unwrap()).unwrap();
        let mat = solvers::canonical_material(&imp).unwrap();
        let layout = mdr::pilot(&mat.prony).unwrap();
        let run = |n, m| mdr::run_resolution(mdr::Scheme::Exponential, &mat, &layout, n, m, false).unwrap().cor;
        let exact = solve(&imp, &SolveOptions { solver: SolverKind::Reference, rtol: 1e-10, ..Default::default() }).unwrap().cor;
        let err = |n, m| (run(n, m) - exact).abs();
        let e: Vec<f64> = [(128, 256), (512, 1024), (2048, 4096)].iter().map(|&(n, m)| err(n, m)).collect();
        prop_assert!(e[2] < 0.25 * e[0].max(e[1]), "errors {e:?}");
    }
}
