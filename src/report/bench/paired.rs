//! A general material timed in alternation with the standard solids it is compared with: the
//! ratio of two medians taken at different times of a run follows the load of a shared machine
//! (two runs three minutes apart gave 2.3x and 4.1x for the same polymer against the same
//! group); solving the material and a standard solid one after the other, over the same passes,
//! exposes both to the same load.

use std::time::Instant;

use super::*;
use crate::model::material::Prony;

/// Passes over the compared rows; each pass solves, for every row, the material once and the
/// row once.
pub const PAIRED_PASSES: usize = 5;

/// Most standard solids a material is timed against (evenly strided over the selection).
pub const PAIRED_MAX_ROWS: usize = 400;

/// A material against standard solids, timed in alternation ([`alternate`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Paired {
    /// Standard solids timed.
    pub rows: usize,
    /// Median time of the material's solves (s).
    pub case: f64,
    /// Median over the rows of each row's median time (s).
    pub standard: f64,
    /// Mean attempted steps and mean evaluations of one solve of the rows.
    pub work: (f64, f64),
}

impl Paired {
    /// The material's time over the standard solids'.
    pub fn ratio(&self) -> f64 {
        self.case / self.standard
    }
}

/// `fast` at rtol 1e-6 (CoR only, one core) on `case` and on each of `rows`, alternating: in
/// each of [`PAIRED_PASSES`] passes, for every row, one solve of the material and one of the
/// row. `None` for no rows.
pub fn alternate(case: &Prony, rows: &[Prony]) -> Result<Option<Paired>> {
    if rows.is_empty() {
        return Ok(None);
    }
    let rtol = TIMING_RTOLS[0];
    let mut case_times = Vec::with_capacity(rows.len() * PAIRED_PASSES);
    let mut row_times = vec![Vec::with_capacity(PAIRED_PASSES); rows.len()];
    let (mut steps, mut evaluations) = (0u64, 0u64);
    for pass in 0..PAIRED_PASSES {
        for (p, times) in rows.iter().zip(&mut row_times) {
            let t0 = Instant::now();
            fast::impact(case, rtol, false)?;
            case_times.push(t0.elapsed().as_secs_f64());
            let t0 = Instant::now();
            let o = fast::impact(p, rtol, false)?;
            times.push(t0.elapsed().as_secs_f64());
            if pass == 0 {
                steps += o.work.steps;
                evaluations += o.work.evaluations;
            }
        }
    }
    let mut per_row: Vec<f64> = row_times.iter_mut().map(|t| median(t)).collect();
    let n = rows.len() as f64;
    Ok(Some(Paired {
        rows: rows.len(),
        case: median(&mut case_times),
        standard: median(&mut per_row),
        work: (steps as f64 / n, evaluations as f64 / n),
    }))
}

/// At most [`PAIRED_MAX_ROWS`] of `rows`, evenly strided.
fn strided<T: Clone>(rows: &[T]) -> Vec<T> {
    let step = rows.len().div_ceil(PAIRED_MAX_ROWS).max(1);
    rows.iter().step_by(step).cloned().collect()
}

/// Time every general material of `general` in alternation with the standard solids of the
/// random sample `random` in its CoR group and within [`COR_BAND`] of its CoR, filling
/// [`GeneralTiming::group`] and [`GeneralTiming::band`].
pub fn pair_with_standard_solids(
    general: &mut [GeneralTiming],
    random: &[RowTiming],
) -> Result<()> {
    let cases = crate::report::catalogue::general_entries()?;
    let relaxation = |r: &RowTiming| -> Result<Prony> {
        Ok(
            crate::model::impact::Impact::from_groups(crate::model::impact::Groups::new(
                r.row.nu, r.row.p2, r.row.p3,
            )?)?
            .canonical_relaxation(),
        )
    };
    for g in general.iter_mut() {
        let Some(case) = cases.iter().find(|c| c.id == g.id) else {
            continue;
        };
        let p = case.impact.canonical_relaxation();
        let group: Vec<&RowTiming> = match cor_groups().into_iter().find(|(_, m)| m(g.cor)) {
            Some((_, member)) => random.iter().filter(|t| member(t.row.cor)).collect(),
            None => Vec::new(),
        };
        let band: Vec<&RowTiming> = random
            .iter()
            .filter(|t| (t.row.cor - g.cor).abs() <= COR_BAND)
            .collect();
        let group = strided(&group)
            .into_iter()
            .map(relaxation)
            .collect::<Result<Vec<_>>>()?;
        let band = strided(&band)
            .into_iter()
            .map(relaxation)
            .collect::<Result<Vec<_>>>()?;
        g.group = alternate(&p, &group)?;
        g.band = alternate(&p, &band)?;
    }
    Ok(())
}
