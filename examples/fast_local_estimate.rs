//! The calibration of `fast`'s one-solve estimate (docs/theory.md §10.1): on rows of the stress
//! distribution, one unverified solve at each rtol against the truth of the stress run
//! (`reference` at least 10x tighter than the rtol), the ratio of its sum of local defects to its
//! error, and what the verified solve accepts from one solve.
//!
//! ```text
//! cargo run --release --example fast_local_estimate -- ROWS SEED
//! ```
//!
//! The figures of docs/theory.md §10.1 come from `-- 1500 11` (fit) and `-- 1500 12` (check);
//! the second table gives the smallest ratio per class of the CoR (where the calibration binds).
use mdr_impact::model::impact::{Groups, Impact};
use mdr_impact::report::stress;
use mdr_impact::solvers::fast;
use rayon::prelude::*;

/// Per row and rtol: the error of one solve, its defect sum over `e`, the verified answer's
/// error, its estimate, whether it came from one solve, and the true CoR.
type Cell = (f64, f64, f64, f64, bool, f64);

/// Classes of the CoR for the second table: `[lo, hi)`.
const COR_CLASSES: [(f64, f64); 5] = [
    (0.0, 0.01),
    (0.01, 0.1),
    (0.1, 0.5),
    (0.5, 0.9),
    (0.9, 1.01),
];

fn main() {
    let arg = |i: usize, d: u64| {
        std::env::args()
            .nth(i)
            .and_then(|s| s.parse().ok())
            .unwrap_or(d)
    };
    let (n, seed) = (arg(1, 300) as usize, arg(2, 11));
    let rtols = &stress::RTOLS[..9]; // 1e-2 ..= 1e-10: the truth reaches 1e-11
                                     // per row and rtol: (error of one solve, its defect sum over e, the verified answer's error,
                                     // its estimate, answered by one solve)
    let rows: Vec<Vec<Option<Cell>>> = stress::sample(n, seed)
        .par_iter()
        .map(|row| {
            let imp = Groups::new(row.nu, row.p2, row.p3).and_then(Impact::from_groups);
            let (src, truth, _) = stress::truth(row);
            let (Ok(imp), Some(truth), Some(tr)) = (imp, truth, src.rtol()) else {
                return vec![None; rtols.len()];
            };
            let p = imp.canonical_relaxation();
            rtols
                .iter()
                .map(|&rtol| {
                    if tr > rtol / 10.0 {
                        return None;
                    }
                    let one = fast::impact_unverified(&p, rtol, false).ok()?;
                    let v = fast::impact(&p, rtol, false).ok()?;
                    Some((
                        ((one.cor - truth) / truth).abs(),
                        one.cor_error_estimate?,
                        ((v.cor - truth) / truth).abs(),
                        v.cor_error_estimate?,
                        v.work.tight_checks == 0,
                        truth,
                    ))
                })
                .collect()
        })
        .collect();
    println!(
        "rows {n}, seed {seed}; truth at least 10x tighter than rtol\n\
         rtol   | rows | one solve: max err/rtol | min defect sum/err | verified: by one solve | max err/rtol there | max err/estimate there | max err/rtol (all)"
    );
    for (j, rtol) in rtols.iter().enumerate() {
        let cells: Vec<_> = rows.iter().filter_map(|r| r[j]).collect();
        let max = |f: &dyn Fn(&Cell) -> Option<f64>| cells.iter().filter_map(f).fold(0.0, f64::max);
        let min_ratio = cells
            .iter()
            .filter(|c| c.0 > 0.0)
            .map(|c| c.1 / c.0)
            .fold(f64::INFINITY, f64::min);
        println!(
            "{rtol:.0e} | {} | {:.2} | {:.3} | {} | {:.2} | {:.2} | {:.2}",
            cells.len(),
            max(&|c| Some(c.0 / rtol)),
            min_ratio,
            cells.iter().filter(|c| c.4).count(),
            max(&|c| c.4.then_some(c.2 / rtol)),
            max(&|c| c.4.then_some(c.2 / c.3)),
            max(&|c| Some(c.2 / rtol)),
        );
    }
    let classes: Vec<String> = COR_CLASSES
        .iter()
        .map(|(lo, hi)| format!("e in [{lo}, {hi})"))
        .collect();
    println!(
        "\nsmallest defect sum/err by CoR class\nrtol   | {}",
        classes.join(" | ")
    );
    for (j, rtol) in rtols.iter().enumerate() {
        let cells: Vec<_> = rows.iter().filter_map(|r| r[j]).collect();
        let mins: Vec<String> = COR_CLASSES
            .iter()
            .map(|&(lo, hi)| {
                let m = cells
                    .iter()
                    .filter(|c| c.0 > 0.0 && c.5 >= lo && c.5 < hi)
                    .map(|c| c.1 / c.0)
                    .fold(f64::INFINITY, f64::min);
                format!("{m:.1}")
            })
            .collect();
        println!("{rtol:.0e} | {}", mins.join(" | "));
    }
}
