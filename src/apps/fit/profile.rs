//! The profile misfit of a linear combination of the coordinates (a parameter, or a group such
//! as `ln p2 = ln g_inf - ln g_1`), and the check of a Wald interval's ends against it
//! (docs/theory.md §16.1): the Wald interval is the profile's quadratic approximation at the
//! estimate, so where the misfit is flat, curved or has another basin it can end where the
//! profile is still below the threshold. Each end, and a point beyond it, is therefore
//! re-minimised with the combination held; where the profile lies below the threshold there,
//! the end is moved outward by stepping along the profile until it crosses, or the quantity is
//! reported not determined when it does not cross within a factor 10.

use super::{Ctx, FIT_MAX_HALF_WIDTH};

/// A linear constraint `a . c = target` on the coordinates `c`, kept by solving it for the
/// coordinate `pivot` (whose coefficient is not zero).
#[derive(Debug, Clone)]
pub(super) struct Tie {
    pivot: usize,
    a: Vec<f64>,
    target: f64,
}

impl Tie {
    /// Set `c[pivot]` so that `a . c = target`.
    pub(super) fn apply(&self, c: &mut [f64]) {
        let rest: f64 = self
            .a
            .iter()
            .zip(c.iter())
            .enumerate()
            .filter(|(i, _)| *i != self.pivot)
            .map(|(_, (a, x))| a * x)
            .sum();
        c[self.pivot] = (self.target - rest) / self.a[self.pivot];
    }
}

/// How one end of a Wald interval came out against the profile misfit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum End {
    /// The profile lies at or above the threshold at the end and at the point beyond it.
    Kept,
    /// The profile lies below the threshold there: it crosses at this offset from the
    /// estimate (in the combination's coordinate, larger than the Wald half-width).
    Moved(f64),
    /// The profile stays below the threshold up to [`FIT_MAX_HALF_WIDTH`] (or a re-minimisation
    /// failed): no bounded end.
    Open,
}

/// Ratio of the offset of the point checked beyond a Wald end to the Wald half-width.
const BEYOND: f64 = 1.5;

impl Ctx<'_> {
    /// The profile misfit at `a . c = t`: the smallest misfit over the other coordinates of
    /// `moving`, re-minimised from each of `starts` (coordinates; the constraint is applied
    /// first), and the coordinates there. `None` when no coordinate of `moving` enters `a`, or
    /// every minimisation fails.
    fn profile_at(
        &self,
        a: &[f64],
        t: f64,
        moving: &[usize],
        starts: &[Vec<f64>],
    ) -> Option<(f64, Vec<f64>)> {
        let pivot = moving
            .iter()
            .copied()
            .filter(|&i| a[i] != 0.0)
            .max_by(|&i, &j| a[i].abs().total_cmp(&a[j].abs()))?;
        let rest: Vec<usize> = moving.iter().copied().filter(|&k| k != pivot).collect();
        let tie = Tie {
            pivot,
            a: a.to_vec(),
            target: t,
        };
        starts
            .iter()
            .filter_map(|s| {
                let mut c = s.clone();
                tie.apply(&mut c);
                let (ssr, values) = self.minimise_with(c, &rest, Some(&tie)).ok()?;
                Some((ssr, self.coords(&values)))
            })
            .min_by(|x, y| x.0.total_cmp(&y.0))
    }

    /// Check the end `x + sign h` of the Wald interval of `a . c` (estimate `x` at the
    /// coordinates `at`, misfit `best_ssr`) against the level `best_ssr + threshold`: the
    /// profile at the end and at `x + sign 1.5 h`, each re-minimised from the previous profile
    /// point and from `others` (coordinates of other minima met by the fit). Where either lies
    /// below the level, the profile is followed outward in growing steps until it crosses
    /// (the crossing interpolated linearly) or reaches [`FIT_MAX_HALF_WIDTH`].
    #[allow(clippy::too_many_arguments)]
    pub(super) fn check_end(
        &self,
        a: &[f64],
        (x, h, sign): (f64, f64, f64),
        at: &[f64],
        best_ssr: f64,
        threshold: f64,
        moving: &[usize],
        others: &[Vec<f64>],
    ) -> End {
        let level = best_ssr + threshold;
        let mut warm = at.to_vec();
        let (mut prev_off, mut prev_ssr) = (0.0, best_ssr);
        let mut off = h;
        let mut step = h * (BEYOND - 1.0);
        let mut below_seen = false;
        loop {
            let mut starts = vec![warm.clone()];
            starts.extend(others.iter().cloned());
            let Some((s, c)) = self.profile_at(a, x + sign * off, moving, &starts) else {
                return End::Open;
            };
            if s >= level {
                if below_seen {
                    let f = ((level - prev_ssr) / (s - prev_ssr)).clamp(0.0, 1.0);
                    return End::Moved(prev_off + f * (off - prev_off));
                }
                if off >= BEYOND * h {
                    return End::Kept;
                }
            } else {
                below_seen = true;
                if off >= FIT_MAX_HALF_WIDTH {
                    return End::Open;
                }
            }
            warm = c;
            (prev_off, prev_ssr) = (off, s);
            off = (off + step).min(FIT_MAX_HALF_WIDTH.max(BEYOND * h));
            if below_seen {
                step *= 2.0;
            }
        }
    }
}
