//! The profile misfit of a linear combination of the coordinates (a parameter, or a group such
//! as `ln p2 = ln g_inf - ln g_1`), and the check of a Wald interval's ends against it
//! (docs/theory.md §16.1): the Wald interval is the profile's quadratic approximation at the
//! estimate, so where the misfit is flat, curved or has another basin it can end where the
//! profile is still below the threshold. Each end, and a point beyond it, is therefore
//! re-minimised with the combination held; where the profile lies below the threshold there,
//! the end is moved outward by stepping along the profile until it crosses, or the quantity is
//! reported not determined when it does not cross within a factor 10. [`profile_misfit`] gives
//! the profile of a named parameter or group at a value, for checks outside the fit (the box
//! study's misses).

use super::{
    check_fixed_slots, Ctx, Data, Model, ModelKind, Parameter, FIT_MAX_HALF_WIDTH,
    FIT_PROFILE_BEYOND,
};
use crate::error::Result;

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
            // a coordinate outside the constraint (a zero coefficient) can be infinite: nu
            // fixed at 0.5 has the coordinate +inf, and 0 * inf would poison the sum
            .filter(|(i, (a, _))| *i != self.pivot && **a != 0.0)
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

/// Bisections of the bracket in which the profile crosses the threshold.
const CROSSING_BISECTIONS: usize = 3;

/// The starts of a profile minimisation at `a . c = target`: `others`, then the first
/// [`FIT_PROFILE_BEYOND`] points of `pool` whose `a . c` lies at or beyond `target` on the
/// side `sign`.
fn others_and_pool(
    others: &[Vec<f64>],
    pool: &[(f64, Vec<f64>)],
    a: &[f64],
    target: f64,
    sign: f64,
) -> Vec<Vec<f64>> {
    let mut starts = others.to_vec();
    starts.extend(
        pool.iter()
            .filter(|(_, c)| {
                let ac: f64 = a.iter().zip(c).map(|(ai, ci)| ai * ci).sum();
                sign * (ac - target) >= 0.0
            })
            .take(FIT_PROFILE_BEYOND)
            .map(|(_, c)| c.clone()),
    );
    starts
}

impl Ctx<'_> {
    /// The profile misfit at `a . c = t`: the smallest misfit over the other coordinates of
    /// `moving`, re-minimised from each of `starts` (coordinates; the constraint is applied
    /// first), and the coordinates there. `None` when no coordinate of `moving` enters `a`, or
    /// every minimisation fails.
    pub(super) fn profile_at(
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
    /// point, from `others` (coordinates of other minima met by the fit) and from the
    /// [`FIT_PROFILE_BEYOND`] points of `pool` (coordinates with their misfit, best first: the
    /// points the fit screened or evaluated) of smallest misfit whose `a . c` lies at or beyond
    /// the profile point, so that a basin on the far side is reached. Where either lies
    /// below the level, the profile is followed outward in growing steps until it crosses
    /// (the crossing bracketed by bisection, [`Ctx::bisect_crossing`]) or reaches [`FIT_MAX_HALF_WIDTH`].
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
        pool: &[(f64, Vec<f64>)],
    ) -> End {
        let level = best_ssr + threshold;
        let mut warm = at.to_vec();
        let mut prev_off = 0.0;
        let mut off = h;
        let mut step = h * (BEYOND - 1.0);
        let mut below_seen = false;
        loop {
            let mut starts = vec![warm.clone()];
            starts.extend(others_and_pool(others, pool, a, x + sign * off, sign));
            let Some((s, c)) = self.profile_at(a, x + sign * off, moving, &starts) else {
                return End::Open;
            };
            if s >= level {
                if below_seen {
                    let crossing = self.bisect_crossing(
                        a,
                        (x, sign),
                        (prev_off, off),
                        level,
                        moving,
                        (
                            &warm,
                            &others_and_pool(others, pool, a, x + sign * prev_off, sign),
                        ),
                    );
                    // a crossing bracketed only by the reach itself (every bisection below the
                    // level) is no end found within the reach: the rise there can be the box's
                    // (a profile flat up to a factor 10, then clamped)
                    return if crossing >= FIT_MAX_HALF_WIDTH {
                        End::Open
                    } else {
                        End::Moved(crossing)
                    };
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
            prev_off = off;
            off = (off + step).min(FIT_MAX_HALF_WIDTH.max(BEYOND * h));
            if below_seen {
                step *= 2.0;
            }
        }
    }

    /// The flat shoulder test of one end of a 95 % interval of `a . c` (estimate `x` at the
    /// coordinates `at`, misfit `best_ssr`; the end at `x + sign off`): the profile at twice the
    /// end's distance, `x + sign 2 off`, re-minimised from `at`, `others` and the points of
    /// `pool` beyond it. Its rise above `best_ssr` when that lies below `level` (a quadratic
    /// profile would have risen to four times the threshold there; docs/theory.md §16.1), else
    /// `None` (also when the minimisation fails: nothing is shown then).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn shoulder(
        &self,
        a: &[f64],
        (x, off, sign): (f64, f64, f64),
        at: &[f64],
        best_ssr: f64,
        level: f64,
        moving: &[usize],
        others: &[Vec<f64>],
        pool: &[(f64, Vec<f64>)],
    ) -> Option<f64> {
        let t = x + sign * 2.0 * off;
        let mut starts = vec![at.to_vec()];
        starts.extend(others_and_pool(others, pool, a, t, sign));
        let (s, _) = self.profile_at(a, t, moving, &starts)?;
        (s - best_ssr < level).then_some(s - best_ssr)
    }

    /// The offset at which the profile of `a . c` crosses `level` between `lo` (below it) and
    /// `hi` (at or above it) from the estimate `x` on the side `sign`: [`CROSSING_BISECTIONS`]
    /// bisections, each profile point re-minimised from the last point below the level and
    /// from `starts`; the outer end of the last bracket (where the profile was seen at or
    /// above the level), so that no value below the level is left out by the linear
    /// interpolation of a curved profile.
    fn bisect_crossing(
        &self,
        a: &[f64],
        (x, sign): (f64, f64),
        (mut lo, mut hi): (f64, f64),
        level: f64,
        moving: &[usize],
        (warm, starts): (&[f64], &[Vec<f64>]),
    ) -> f64 {
        let mut warm = warm.to_vec();
        for _ in 0..CROSSING_BISECTIONS {
            let mid = 0.5 * (lo + hi);
            let mut from = vec![warm.clone()];
            from.extend(starts.iter().cloned());
            match self.profile_at(a, x + sign * mid, moving, &from) {
                Some((s, c)) if s < level => {
                    lo = mid;
                    warm = c;
                }
                Some(_) => hi = mid,
                // a failed re-minimisation proves nothing: keep the verified outer end
                None => lo = mid,
            }
        }
        hi
    }
}

/// Whether the fit holds `g_inf` (CoR only, with the scale free in `g_inf`, `g_1` and `eta`:
/// module docs; a fixed `k_0` breaks that symmetry, since scaling the moduli then changes `nu`),
/// and the coordinates it moves.
pub(super) fn moving_coordinates(
    model: &Model,
    data: &Data,
    fixed: &[Option<f64>],
) -> (bool, Vec<usize>) {
    let hold = model.kind == ModelKind::StandardSolid
        && model.k_0.is_none()
        && !data.has_contact_times()
        && [Parameter::GInf, Parameter::G1, Parameter::Eta]
            .iter()
            .all(|&p| model.slot(p).is_some_and(|i| fixed[i].is_none()));
    let moving = (0..model.params.len())
        .filter(|&i| fixed[i].is_none() && !(hold && i == 0))
        .collect();
    (hold, moving)
}

/// The profile misfit of the parameter or group `name` at the value `target` (SI): the smallest
/// weighted SSR of `data` over the coordinates the fit moves with `name` held at `target` and the
/// `fixed` values kept, minimised by Levenberg–Marquardt from each of `starts` (parameter
/// values) as the fit's interval checks do (docs/theory.md §16.1). A constrained local minimum
/// is an upper bound of the profile. `None` when `name` is unknown or fixed, no moving
/// coordinate enters it, or every minimisation fails.
///
/// # Errors
/// [`crate::Error::OutOfRange`] when `fixed` has the wrong length or `target` is not positive (moduli,
/// groups) or not a Poisson's ratio.
pub fn profile_misfit(
    model: &Model,
    data: &Data,
    fixed: &[Option<f64>],
    name: &str,
    target: f64,
    starts: &[Vec<f64>],
) -> Result<Option<f64>> {
    let np = model.params.len();
    check_fixed_slots(model, fixed)?;
    let Some(first) = starts.first() else {
        return Ok(None);
    };
    let ctx = Ctx::new(model, data, fixed);
    let (_, moving) = moving_coordinates(model, data, fixed);
    let (a, t) = match model.index(name) {
        Some(i) => {
            if fixed[i].is_some() {
                return Ok(None);
            }
            model.check_value(i, target)?;
            let mut a = vec![0.0; np];
            a[i] = 1.0;
            (a, model.params[i].kind.to_coord(target))
        }
        None => {
            let Some((_, _, mut grad)) = model.groups(first).into_iter().find(|g| g.0 == name)
            else {
                return Ok(None);
            };
            crate::error::check("target", target, target > 0.0, "0 < target < inf")?;
            for (g, f) in grad.iter_mut().zip(fixed) {
                if f.is_some() {
                    *g = 0.0;
                }
            }
            (grad, target.ln())
        }
    };
    let coords: Vec<Vec<f64>> = starts
        .iter()
        .map(|v| {
            let mut v = v.clone();
            for (x, f) in v.iter_mut().zip(fixed) {
                if let Some(f) = f {
                    *x = *f;
                }
            }
            ctx.coords(&v)
        })
        .collect();
    Ok(ctx.profile_at(&a, t, &moving, &coords).map(|(s, _)| s))
}
