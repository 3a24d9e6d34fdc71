//! What a perfect error estimate could save `fast` (docs/theory.md §10.1): on the bench's random
//! rows, the verified solve at `rtol` against an oracle that knows every row's true CoR and solves
//! it once, unverified, at the loosest step tolerance that still lands within `rtol`.
//!
//! ```text
//! cargo run --release --example fast_tolerance_oracle -- ROWS SEED RTOL
//! ```
//!
//! Per row: the truth is the verified `fast` at [`TRUTH_RTOL`] (within 1e-10 of the external
//! tables, VALIDATION.md); the oracle tries the step tolerances `rtol`, `2 rtol`, `4 rtol`, ...
//! (at most [`LOOSEST`] `rtol` and 1e-2) and stops at the first whose answer is outside `rtol`
//! or fails; its cost is that of the last one inside. No estimate, however sharp, can do better
//! than this oracle with the same solver: it is the most that the goal-oriented estimates of the
//! issue's first item could buy. Work counters (steps, evaluations) are exact; the times are
//! means of [`REPEAT`] solves per row with all cores busy, so only their ratios mean anything.
//! The figures of docs/theory.md §10.1 come from `-- 4000 1 1e-6` and `-- 4000 1 1e-8`.
use mdr_impact::apps::batch;
use mdr_impact::model::impact::Impact;
use mdr_impact::model::material::Prony;
use mdr_impact::solvers::fast;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::time::Instant;

/// Tolerance of the truth.
const TRUTH_RTOL: f64 = 1e-11;
/// Loosest step tolerance the oracle tries, in units of `rtol`.
const LOOSEST: f64 = 4096.0;
/// Solves per row and path in the timing.
const REPEAT: u32 = 5;

/// Work of one path on one row: seconds (mean of [`REPEAT`]), steps and evaluations.
#[derive(Clone, Copy, Default)]
struct Cost {
    seconds: f64,
    steps: f64,
    evaluations: f64,
}

impl std::ops::AddAssign for Cost {
    fn add_assign(&mut self, o: Cost) {
        self.seconds += o.seconds;
        self.steps += o.steps;
        self.evaluations += o.evaluations;
    }
}

/// Cost of `solve` on one row (`None` when it fails).
fn cost(solve: impl Fn() -> mdr_impact::Result<mdr_impact::Outcome>) -> Option<Cost> {
    let out = solve().ok()?;
    let t0 = Instant::now();
    for _ in 0..REPEAT {
        let _ = solve();
    }
    Some(Cost {
        seconds: t0.elapsed().as_secs_f64() / f64::from(REPEAT),
        steps: out.work.steps as f64,
        evaluations: out.work.evaluations as f64,
    })
}

/// Per row: the verified solve, one unverified solve at `rtol`, the oracle and its factor.
fn row_costs(p: &Prony, rtol: f64) -> Option<(Cost, Cost, Cost, f64)> {
    let truth = fast::impact(p, TRUTH_RTOL, false).ok()?.cor;
    let verified = cost(|| fast::impact(p, rtol, false))?;
    let one = cost(|| fast::impact_unverified(p, rtol, false))?;
    let within = |prec: f64| {
        fast::impact_unverified(p, prec, false)
            .ok()
            .is_some_and(|o| ((o.cor - truth) / truth).abs() <= rtol)
    };
    let mut factor = 0.0;
    let mut f = 1.0;
    while f <= LOOSEST && rtol * f <= 1e-2 && within(rtol * f) {
        factor = f;
        f *= 2.0;
    }
    // a row whose single solve at rtol is already outside: the oracle pays the verified solve
    let oracle = if factor == 0.0 {
        verified
    } else {
        cost(|| fast::impact_unverified(p, rtol * factor, false))?
    };
    Some((verified, one, oracle, factor))
}

fn main() {
    let arg = |i: usize| std::env::args().nth(i);
    let n: usize = arg(1).and_then(|s| s.parse().ok()).unwrap_or(4000);
    let seed: u64 = arg(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    let rtol: f64 = arg(3).and_then(|s| s.parse().ok()).unwrap_or(1e-6);
    let rows = batch::random_rows(n, seed).expect("random rows are valid groups");
    let per_row: Vec<_> = rows
        .par_iter()
        .filter_map(|r| {
            let p = Impact::from_groups(r.groups).ok()?.canonical_relaxation();
            row_costs(&p, rtol)
        })
        .collect();
    let mut sums = [Cost::default(); 3];
    let mut factors: BTreeMap<u64, usize> = BTreeMap::new();
    for (v, o, x, f) in &per_row {
        sums[0] += *v;
        sums[1] += *o;
        sums[2] += *x;
        *factors.entry(*f as u64).or_default() += 1;
    }
    let m = per_row.len().max(1) as f64;
    println!(
        "rows {} of {n}, seed {seed}, rtol {rtol:e}; truth: verified fast at {TRUTH_RTOL:e}\n\
         path | steps per row | evaluations per row | time / verified",
        per_row.len()
    );
    for (name, c) in [
        ("verified at rtol", sums[0]),
        ("one unverified solve at rtol", sums[1]),
        (
            "oracle: one solve at the loosest tolerance within rtol",
            sums[2],
        ),
    ] {
        println!(
            "{name} | {:.2} | {:.1} | {:.3}",
            c.steps / m,
            c.evaluations / m,
            c.seconds / sums[0].seconds
        );
    }
    let hist: Vec<String> = factors.iter().map(|(f, k)| format!("{f}: {k}")).collect();
    println!(
        "oracle's step tolerance / rtol (0: the solve at rtol is outside): {}",
        hist.join(", ")
    );
}
