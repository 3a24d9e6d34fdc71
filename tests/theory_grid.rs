//! Work-precision sweep of the reference impact solver over the paper's parameter box
//! (slow: run with `cargo test --release --test theory_grid -- --ignored --nocapture`).
//! Prints the median / max time per impact and, when `/work/xcheck/cor_ref.csv` exists (an
//! independent table, not part of the repository), the largest relative CoR difference to it.

use mdr_impact::theory::reference::impact;
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
                    .equivalent_relaxation();
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

/// Cross-check against the independent Python table when present (does nothing otherwise, and
/// says so).
#[test]
#[ignore = "needs /work/xcheck/cor_ref.csv (external)"]
fn cross_check_python_table() {
    let Ok(text) = std::fs::read_to_string("/work/xcheck/cor_ref.csv") else {
        println!("no /work/xcheck/cor_ref.csv: skipped");
        return;
    };
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| header.iter().position(|h| h.trim() == n).unwrap();
    let (cn, c2, c3, ce, ct, cd) = (
        col("nu"),
        col("p2"),
        col("p3"),
        col("cor"),
        col("contact_time"),
        col("max_indentation"),
    );
    let (mut max_e, mut max_t, mut max_d, mut n) = (0.0f64, 0.0f64, 0.0f64, 0);
    let mut worst = (0.0, 0.0, 0.0);
    for l in lines {
        let v: Vec<f64> = l
            .split(',')
            .map(|x| x.trim().parse().unwrap_or(f64::NAN))
            .collect();
        let pr = Groups::new(v[cn], v[c2], v[c3])
            .unwrap()
            .canonical_material()
            .unwrap()
            .equivalent_relaxation();
        let o = impact(&pr, 1e-11, false).unwrap();
        let de = ((o.cor - v[ce]) / v[ce]).abs();
        if de > max_e {
            max_e = de;
            worst = (v[cn], v[c2], v[c3]);
        }
        max_t = max_t.max(((o.contact_time - v[ct]) / v[ct]).abs());
        max_d = max_d.max(((o.max_indentation - v[cd]) / v[cd]).abs());
        n += 1;
    }
    println!(
        "{n} rows: max rel diff cor {max_e:.2e} (at {worst:?}), contact time {max_t:.2e}, max indentation {max_d:.2e}"
    );
}
