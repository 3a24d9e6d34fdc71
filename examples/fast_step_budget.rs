//! Where `fast` spends its steps (docs/theory.md §10.1): on the bench's random rows, one
//! unverified solve per row with its step ends, counted by part of the contact.
//!
//! ```text
//! cargo run --release --example fast_step_budget -- ROWS SEED RTOL
//! ```
//!
//! Per impact, for all rows and for the nearly elastic ones (`e >= 0.9`):
//! - the steps tried (accepted and rejected), and the rejected ones;
//! - the accepted compression steps (up to the time of maximum indentation `t_m`; the step in
//!   which `t_m` falls counts as one), of which those ending before `0.15 T` (the start, where
//!   `d = t` and `w = t^(3/2)` make the steps grow from the first one by at most the distance from
//!   `t = 0`);
//! - the accepted restitution steps, of which those ending after `0.85 T` (the end, where the
//!   force vanishes like `(T - t)^(3/2)`).
//!
//! `T` is the contact time. The figures of docs/theory.md §10.1 come from `-- 3000 7 1e-6`.
use mdr_impact::apps::batch;
use mdr_impact::model::impact::Impact;
use mdr_impact::solvers::fast;
use rayon::prelude::*;

/// Fraction of the contact time that bounds the start and the end of the contact.
const EDGE: f64 = 0.15;

/// Per row: the CoR and `[tried, accepted, compression, start, restitution, end]`.
type Counts = (f64, [f64; 6]);

fn counts(row: &batch::Row, rtol: f64) -> Option<Counts> {
    let p = Impact::from_groups(row.groups).ok()?.canonical_relaxation();
    let o = fast::impact_unverified(&p, rtol, true).ok()?;
    let h = o.history?;
    let (tm, te) = (o.time_of_max_indentation, o.contact_time);
    let mut c = [o.work.steps as f64, 0.0, 0.0, 0.0, 0.0, 0.0];
    // the history has the start, every accepted step's end, t_m, and the end of contact
    for &t in &h.t[1..] {
        c[1] += 1.0;
        if t <= tm {
            c[2] += 1.0;
            if t <= EDGE * te {
                c[3] += 1.0;
            }
        } else {
            c[4] += 1.0;
            if t >= (1.0 - EDGE) * te {
                c[5] += 1.0;
            }
        }
    }
    Some((o.cor, c))
}

fn main() {
    let arg = |i: usize| std::env::args().nth(i);
    let n: usize = arg(1).and_then(|s| s.parse().ok()).unwrap_or(3000);
    let seed: u64 = arg(2).and_then(|s| s.parse().ok()).unwrap_or(7);
    let rtol: f64 = arg(3).and_then(|s| s.parse().ok()).unwrap_or(1e-6);
    let rows = batch::random_rows(n, seed).expect("random rows are valid groups");
    let all: Vec<Counts> = rows.par_iter().filter_map(|r| counts(r, rtol)).collect();
    println!(
        "rows {n}, seed {seed}, rtol {rtol:e}; per impact (one unverified solve)\n\
         class | rows | steps tried | rejected | compression | of it before {EDGE} T | \
         restitution | of it after {} T",
        1.0 - EDGE
    );
    for (name, lo) in [("all", f64::NEG_INFINITY), ("e >= 0.9", 0.9)] {
        let sel: Vec<&[f64; 6]> = all.iter().filter(|c| c.0 >= lo).map(|c| &c.1).collect();
        let m = sel.len().max(1) as f64;
        let mean = |i: usize| sel.iter().map(|c| c[i]).sum::<f64>() / m;
        println!(
            "{name} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2}",
            sel.len(),
            mean(0),
            mean(0) - mean(1),
            mean(2),
            mean(3),
            mean(4),
            mean(5)
        );
    }
}
