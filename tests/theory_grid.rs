//! Work-precision sweep of the reference impact solver over the paper's parameter box
//! (slow: run with `cargo test --release --test suite theory_grid:: -- --ignored --nocapture`).
//! Prints the median / max time per impact. The cross-check against the independent tables is
//! `tests/external_reference.rs` (committed tables, every row asserted).

use mdr_impact::solvers::theory::reference::impact;
use mdr_impact::Groups;
use std::time::Instant;

/// Every grid point solves at rtol = 1e-10 with a reported estimate below it.
#[test]
#[ignore = "slow sweep (about 100 impacts); prints timing"]
fn grid_timing_and_estimates() {
    let mut times = Vec::new();
    let mut worst_est = 0.0f64;
    for nu in [-0.9, 0.0, 0.3, 0.49, 0.5] {
        for p2 in [1e-4, 1e-2, 1.0, 1e2] {
            for p3 in [1e-3, 1e-1, 10.0, 1e3, 1e4] {
                let pr = Groups::new(nu, p2, p3)
                    .unwrap()
                    .canonical_material()
                    .unwrap()
                    .equivalent_relaxation()
                    .unwrap();
                let t0 = Instant::now();
                let o = impact(&pr, 1e-10, false).unwrap();
                times.push(t0.elapsed().as_secs_f64() * 1e3);
                let est = o.cor_error_estimate.unwrap();
                assert!(est <= 1e-10, "({nu},{p2},{p3}): {est:e}");
                worst_est = worst_est.max(est);
            }
        }
    }
    times.sort_by(f64::total_cmp);
    println!(
        "impacts: {}, median {:.2} ms, max {:.2} ms, worst estimate {worst_est:.2e}",
        times.len(),
        times[times.len() / 2],
        times[times.len() - 1]
    );
}
