//! Where the one-solve estimate of `fast` sends rows to the tight check (docs/theory.md §10.1):
//! on the bench's random rows (`batch::random_rows`, the rows of `cor --input` in
//! `mdr-impact bench`), one unverified solve per row at `rtol`, and per class of its CoR the
//! calibrated estimate (the sum of the local defects over `e`, divided by the calibration
//! `0.5 rtol^(-1/4)`) in units of `rtol`: its quantiles, and how many rows it would answer with
//! one solve if the calibration were looser by a factor 1 (today), 2, 3 or 4; and the steps that
//! looser calibration would save (those of the tight check on the rows it lets pass, from the
//! verified solve's work) against all steps of the verified solves.
//!
//! ```text
//! cargo run --release --example fast_estimate_by_cor -- ROWS SEED RTOL
//! ```
use mdr_impact::apps::batch;
use mdr_impact::model::impact::Impact;
use mdr_impact::solvers::fast;
use rayon::prelude::*;

/// Classes of the CoR: `[lo, hi)`.
const COR_CLASSES: [(f64, f64); 5] = [
    (0.0, 0.01),
    (0.01, 0.1),
    (0.1, 0.5),
    (0.5, 0.9),
    (0.9, 1.01),
];

/// Loosenings of the calibration tried.
const LOOSER: [f64; 4] = [1.0, 2.0, 3.0, 4.0];

fn main() {
    let arg = |i: usize| std::env::args().nth(i);
    let n: usize = arg(1).and_then(|s| s.parse().ok()).unwrap_or(4000);
    let seed: u64 = arg(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    let rtol: f64 = arg(3).and_then(|s| s.parse().ok()).unwrap_or(1e-6);
    let kappa = fast::FAST_LOCAL_CALIBRATION * rtol.powf(-fast::FAST_LOCAL_EXPONENT);
    let rows = batch::random_rows(n, seed).expect("random rows are valid groups");
    // (CoR, calibrated estimate / rtol) of one unverified solve per row, and the steps of the
    // verified solve beyond that one solve
    let cells: Vec<(f64, f64, u64, u64)> = rows
        .par_iter()
        .filter_map(|r| {
            let p = Impact::from_groups(r.groups).ok()?.canonical_relaxation();
            let one = fast::impact_unverified(&p, rtol, false).ok()?;
            let verified = fast::impact(&p, rtol, false).ok()?;
            let extra = verified.work.steps.saturating_sub(one.work.steps);
            let est = one.cor_error_estimate? / kappa / rtol;
            Some((one.cor, est, extra, verified.work.steps))
        })
        .collect();
    let all: u64 = cells.iter().map(|c| c.3).sum();
    println!(
        "{} of {n} rows solved, seed {seed}, rtol {rtol:e}",
        cells.len()
    );
    let head: Vec<String> = LOOSER.iter().map(|f| format!("{f}x")).collect();
    println!(
        "CoR class | rows | estimate / rtol: p10 | p50 | p90 | max | one solve with the calibration looser by {}",
        head.join(" | ")
    );
    for (lo, hi) in COR_CLASSES {
        let mut x: Vec<f64> = cells
            .iter()
            .filter(|c| c.0 >= lo && c.0 < hi)
            .map(|c| c.1)
            .collect();
        if x.is_empty() {
            continue;
        }
        x.sort_by(f64::total_cmp);
        let q = |p: f64| x[((x.len() - 1) as f64 * p).round() as usize];
        let pass: Vec<String> = LOOSER
            .iter()
            .map(|f| x.iter().filter(|&&est| est <= *f).count().to_string())
            .collect();
        println!(
            "[{lo}, {hi}) | {} | {:.2} | {:.2} | {:.2} | {:.2} | {}",
            x.len(),
            q(0.1),
            q(0.5),
            q(0.9),
            x[x.len() - 1],
            pass.join(" | ")
        );
    }
    let saved: Vec<String> = LOOSER
        .iter()
        .map(|f| {
            let s: u64 = cells
                .iter()
                .filter(|c| c.1 > 1.0 && c.1 <= *f)
                .map(|c| c.2)
                .sum();
            format!("{f}x: {s} ({:.1} %)", 100.0 * s as f64 / all as f64)
        })
        .collect();
    println!(
        "steps of the verified solves: {all}; saved by the looser calibration {}",
        saved.join(", ")
    );
}
