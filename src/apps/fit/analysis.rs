//! The analysis of a fit at its estimate: covariance from the Jacobian's singular values,
//! confidence intervals (normal or Student's `t`), identifiability of parameters and groups, and
//! the verdict.

use super::profile::End;
use super::*;
use crate::model::tolerances::FIT_SHOULDER_LEVEL;

/// Uncertainty and identifiability at the estimate (module docs).
pub(super) fn analyse(
    ctx: &Ctx,
    (best_ssr, mut values): (f64, Vec<f64>),
    others: &[(f64, Vec<f64>)],
    fixed: &[Option<f64>],
    free: &[usize],
    moving: &[usize],
) -> Result<FitResult> {
    // the fixed values as given, not their round trip through the fit coordinates
    // (`--fix g_inf=1e6` was reported as 9.999999999999995e5)
    for (v, f) in values.iter_mut().zip(fixed) {
        if let Some(f) = f {
            *v = *f;
        }
    }
    let model = ctx.model;
    let np = model.params.len();
    let coords = ctx.coords(&values);
    let residuals = ctx.residual_list(&values, FIT_RTOL)?;
    let n = residuals.len();
    let ss: f64 = residuals.iter().map(|r| r.weighted * r.weighted).sum();
    let rms_residual = (ss / n as f64).sqrt();

    // SVD of the weighted Jacobian over every free coordinate
    let cols = if free.is_empty() {
        Vec::new()
    } else {
        ctx.jacobian(&coords, free, None)?
    };
    let j = nalgebra::DMatrix::from_fn(n, free.len(), |i, k| cols[k][i]);
    let (sv, v_t) = if free.is_empty() {
        (Vec::new(), nalgebra::DMatrix::zeros(0, 0))
    } else {
        let svd = j.svd(false, true);
        let v_t = svd.v_t.ok_or(Error::NonFinite {
            what: "fit Jacobian SVD",
            value: f64::NAN,
        })?;
        (svd.singular_values.iter().copied().collect::<Vec<_>>(), v_t)
    };
    for &s in &sv {
        if !s.is_finite() {
            return Err(Error::NonFinite {
                what: "fit Jacobian singular value",
                value: s,
            });
        }
    }
    let s_max = sv.iter().copied().fold(0.0, f64::max);
    let in_range = |k: usize| sv[k] > FIT_NULL_RATIO * s_max && s_max > 0.0;
    let rank = (0..sv.len()).filter(|&k| in_range(k)).count();
    let dof = n.saturating_sub(rank);
    let scale_and_quantile = noise_and_quantile(ctx.data, ss, dof);
    let noise_scale = scale_and_quantile.map(|x| x.0);
    let quantile = scale_and_quantile.map(|x| x.1);
    // covariance on the identified subspace, in the full coordinate numbering
    let covariance = noise_scale.map(|s| {
        let mut c = vec![vec![0.0; np]; np];
        for k in (0..sv.len()).filter(|&k| in_range(k)) {
            for (a, &ia) in free.iter().enumerate() {
                for (b, &ib) in free.iter().enumerate() {
                    c[ia][ib] += s * s * v_t[(k, a)] * v_t[(k, b)] / (sv[k] * sv[k]);
                }
            }
        }
        c
    });
    // the null-space component of a direction a (full numbering) over the free coordinates:
    // the norm of what is left after projecting it onto the identified right singular vectors,
    // relative to its free part (independent of the basis the SVD picks for the null space, and
    // right when the SVD has fewer rows than free coordinates: n < p leaves p - n null
    // directions without a row of v_t)
    let null_component = |a: &[f64]| -> f64 {
        let norm2 = free.iter().map(|&i| a[i] * a[i]).sum::<f64>();
        if norm2 == 0.0 {
            return 0.0;
        }
        let in_span: f64 = (0..sv.len())
            .filter(|&k| in_range(k))
            .map(|k| {
                let p = free
                    .iter()
                    .enumerate()
                    .map(|(b, &ib)| v_t[(k, b)] * a[ib])
                    .sum::<f64>();
                p * p
            })
            .sum();
        (1.0 - in_span / norm2).max(0.0).sqrt()
    };
    let estimate = |name: String,
                    unit: &'static str,
                    a: &[f64],
                    coord: f64,
                    back: &dyn Fn(f64) -> f64,
                    fixed_value: Option<f64>|
     -> Estimate {
        let value = back(coord);
        if let Some(value) = fixed_value {
            return Estimate {
                name,
                unit,
                value: Some(value),
                ci95: Some((value, value)),
                se: Some(0.0),
                identifiable: true,
                fixed: true,
                note: "fixed".into(),
            };
        }
        if null_component(a) > FIT_NULL_COMPONENT {
            return Estimate {
                name,
                unit,
                value: None,
                ci95: None,
                se: None,
                identifiable: false,
                fixed: false,
                note: "not determined by the data (a null direction of the Jacobian)".into(),
            };
        }
        let (Some(c), Some(q)) = (&covariance, quantile) else {
            return Estimate {
                name,
                unit,
                value: Some(value),
                ci95: None,
                se: None,
                identifiable: false,
                fixed: false,
                note: "no residual degrees of freedom to estimate the noise (give cor_sd)".into(),
            };
        };
        let var: f64 = (0..np)
            .map(|i| (0..np).map(|k| a[i] * c[i][k] * a[k]).sum::<f64>())
            .sum();
        let se = var.max(0.0).sqrt();
        let half = q * se;
        let lo = back(coord - half);
        let hi = back(coord + half);
        let wide = !(half <= FIT_MAX_HALF_WIDTH);
        Estimate {
            name,
            unit,
            value: Some(value),
            ci95: Some((lo.min(hi), lo.max(hi))),
            se: Some(se),
            identifiable: !wide,
            fixed: false,
            note: if wide {
                "poorly determined: the 95 % interval spans more than a factor 10 either way \
                 (in the parameter's coordinate)"
                    .into()
            } else {
                String::new()
            },
        }
    };
    // the direction of parameter `i` in the coordinates
    let unit_direction = |i: usize| {
        let mut a = vec![0.0; np];
        a[i] = 1.0;
        a
    };
    let parameters: Vec<Estimate> = model
        .params
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let a = unit_direction(i);
            estimate(
                p.name.clone(),
                p.unit,
                &a,
                coords[i],
                &|c| p.kind.from_coord(c),
                fixed[i],
            )
        })
        .collect();
    // every group with its value and its direction in the coordinates: the Poisson coordinate
    // does not enter; fixed coordinates do not vary
    let group_dirs: Vec<(&'static str, f64, Vec<f64>)> = model
        .groups(&values)
        .into_iter()
        .map(|(name, value, mut grad)| {
            for (g, f) in grad.iter_mut().zip(fixed) {
                if f.is_some() {
                    *g = 0.0;
                }
            }
            (name, value, grad)
        })
        .collect();
    let groups: Vec<Estimate> = group_dirs
        .iter()
        .map(|&(name, value, ref grad)| {
            let all_fixed = grad.iter().all(|g| *g == 0.0);
            let unit = if name == "p2" { "1" } else { "Pa^(2/5) s" };
            estimate(
                name.to_string(),
                unit,
                grad,
                value.ln(),
                &f64::exp,
                all_fixed.then_some(value),
            )
        })
        .collect();
    let mut parameters = parameters;
    let mut groups = groups;
    if let (Some(s), Some(q)) = (noise_scale, quantile) {
        let threshold = q * q * s * s;
        // the ends of every Wald interval against the profile misfit (profile.rs)
        let starts = profile_starts(ctx, &coords, best_ssr, others, moving);
        let pool = profile_pool(ctx, best_ssr, threshold);
        let check = |e: &mut Estimate, a: &[f64], x: f64, back: &dyn Fn(f64) -> f64| {
            let (Some(se), Some(_), true, false) = (e.se, e.ci95, e.identifiable, e.fixed) else {
                return;
            };
            let h = q * se;
            let end = |sign: f64| {
                ctx.check_end(
                    a,
                    (x, h, sign),
                    &coords,
                    best_ssr,
                    threshold,
                    moving,
                    &starts,
                    &pool,
                )
            };
            let offset = |end: End| match end {
                End::Moved(o) => Some(o),
                End::Kept => Some(h),
                End::Open => None,
            };
            let (lo, hi) = (end(-1.0), end(1.0));
            if (lo, hi) == (End::Kept, End::Kept) {
                return;
            }
            match (offset(lo), offset(hi)) {
                (Some(l), Some(u)) => {
                    let (a, b) = (back(x - l), back(x + u));
                    e.ci95 = Some((a.min(b), a.max(b)));
                    e.note = "interval extended along the profile misfit (it lay within the 95 % \
                              threshold at an end of the Wald interval)"
                        .into();
                }
                _ => {
                    e.ci95 = None;
                    e.identifiable = false;
                    e.note = "not determined: the profile misfit stays within the 95 % threshold \
                              beyond a factor 10 (in the coordinate) from the estimate, flat or \
                              with another basin"
                        .into();
                }
            }
        };
        for &i in moving {
            let a = unit_direction(i);
            let kind = model.params[i].kind;
            check(&mut parameters[i], &a, coords[i], &|c| kind.from_coord(c));
        }
        for (e, (_, value, grad)) in groups.iter_mut().zip(&group_dirs) {
            check(e, grad, value.ln(), &f64::exp);
        }
        // the profile likelihood where the Wald interval is too wide to trust
        for &i in moving {
            let e = &mut parameters[i];
            if e.identifiable || e.value.is_none() || e.ci95.is_none() {
                continue;
            }
            let kind = model.params[i].kind;
            let (lo, hi) = ctx.profile(&coords, best_ssr, i, moving, threshold);
            let back = |c: Option<f64>| c.map(|c| kind.from_coord(c));
            match (back(lo), back(hi)) {
                (Some(a), Some(b)) => {
                    e.ci95 = Some((a.min(b), a.max(b)));
                    e.identifiable = true;
                    e.note = "profile-likelihood interval (the Wald interval was too wide)".into();
                }
                (a, b) => {
                    e.ci95 = None;
                    e.note = format!(
                        "not determined: the profile likelihood stays within the 95 % threshold \
                         {} (bounds found: {}, {})",
                        "up to four decades (or the nu range) from the estimate",
                        a.map_or("none".to_string(), |x| format!("{x:.4e}")),
                        b.map_or("none".to_string(), |x| format!("{x:.4e}"))
                    );
                }
            }
        }
        // Another point met by the fit (any point evaluated at the fit's rtol: the minimum of
        // another start or of a nu level with nu held, whose last evaluation is recorded too, a
        // step of a minimisation, a Jacobian, a profile) whose misfit is within the
        // likelihood-ratio threshold: the profile of every parameter and group lies at or below
        // it there, so every interval is widened to contain it (and judged again by its reach).
        let within: Vec<(f64, Vec<f64>)> = ctx
            .visited
            .borrow()
            .iter()
            .filter(|o| o.0 - best_ssr <= threshold)
            .cloned()
            .collect();
        // The profile goes on beyond such a point (it lies in another basin, which the checks
        // of the Wald ends did not reach): each end moved to a point is followed outward along
        // the profile from there like a Wald end ([`Ctx::check_end`]).
        let widen = |e: &mut Estimate,
                     a: &[f64],
                     x: f64,
                     points: &[(f64, f64, usize)],
                     to_coord: &dyn Fn(f64) -> f64,
                     back: &dyn Fn(f64) -> f64| {
            let (Some((lo, hi)), Some(_), false) = (e.ci95, e.value, e.fixed) else {
                return;
            };
            let Some(&p_lo) = points.iter().min_by(|a, b| a.0.total_cmp(&b.0)) else {
                return;
            };
            let Some(&p_hi) = points.iter().max_by(|a, b| a.0.total_cmp(&b.0)) else {
                return;
            };
            if lo <= p_lo.0 && p_hi.0 <= hi {
                return;
            }
            let mut ends = [to_coord(lo), to_coord(hi)];
            let mut open = false;
            let mut other_ssr = f64::NEG_INFINITY;
            for (k, (p, outside)) in [(p_lo, p_lo.0 < lo), (p_hi, p_hi.0 > hi)]
                .into_iter()
                .enumerate()
            {
                if !outside {
                    continue;
                }
                other_ssr = other_ssr.max(p.1);
                let c = to_coord(p.0);
                let (sign, h) = ((c - x).signum(), (c - x).abs());
                if !e.identifiable || h == 0.0 {
                    ends[k] = c;
                    continue;
                }
                let at = ctx.coords(&within[p.2].1);
                match ctx.check_end(
                    a,
                    (x, h, sign),
                    &at,
                    best_ssr,
                    threshold,
                    moving,
                    &starts,
                    &pool,
                ) {
                    End::Kept => ends[k] = c,
                    End::Moved(o) => ends[k] = x + sign * o,
                    End::Open => open = true,
                }
            }
            if open {
                e.ci95 = None;
                e.identifiable = false;
                e.note = format!(
                    "not determined: another point lies within the 95 % threshold of the misfit \
                     (SSR {other_ssr:.4e} against {best_ssr:.4e}) and the profile beyond it \
                     stays within the threshold past a factor 10 (in the coordinate)"
                );
                return;
            }
            let (u, v) = (back(ends[0]), back(ends[1]));
            let (lo, hi) = (u.min(v).min(lo), u.max(v).max(hi));
            e.ci95 = Some((lo, hi));
            e.note = format!(
                "interval widened to another point within the 95 % threshold of the misfit (SSR \
                 {other_ssr:.4e} against {best_ssr:.4e}) and along the profile beyond it"
            );
            let reach = (to_coord(lo) - x).abs().max((to_coord(hi) - x).abs());
            if !(reach <= FIT_MAX_HALF_WIDTH) {
                e.identifiable = false;
                e.note
                    .push_str(", which spans more than a factor 10 either way");
            }
        };
        for (i, (e, p)) in parameters.iter_mut().zip(&model.params).enumerate() {
            if fixed[i].is_some() {
                continue;
            }
            let points: Vec<(f64, f64, usize)> = within
                .iter()
                .enumerate()
                .map(|(k, (s, v))| (v[i], *s, k))
                .collect();
            let a = unit_direction(i);
            let kind = p.kind;
            widen(e, &a, coords[i], &points, &|x| kind.to_coord(x), &|c| {
                kind.from_coord(c)
            });
        }
        let group_values: Vec<Vec<f64>> = within
            .iter()
            .map(|(_, v)| model.groups(v).into_iter().map(|(_, g, _)| g).collect())
            .collect();
        for (k, (e, (_, value, grad))) in groups.iter_mut().zip(&group_dirs).enumerate() {
            let points: Vec<(f64, f64, usize)> = within
                .iter()
                .zip(&group_values)
                .enumerate()
                .map(|(j, ((s, _), g))| (g[k], *s, j))
                .collect();
            widen(e, grad, value.ln(), &points, &f64::ln, &f64::exp);
        }
        // Flat shoulders (docs/theory.md §16.1): where the profile at twice an end's distance
        // from the estimate still lies below the two-degree-of-freedom level, the profile is
        // far flatter than the quadratic the threshold assumes (which would rise to four times
        // the threshold there), and the likelihood-ratio statistic of a truth out on the
        // shoulder is no longer chi-square with one degree of freedom: the interval is kept
        // but not reported determined.
        let level = threshold * FIT_SHOULDER_LEVEL / normal_quantile().powi(2);
        let shoulder = |e: &mut Estimate, a: &[f64], x: f64, to_coord: &dyn Fn(f64) -> f64| {
            let (Some((lo, hi)), true, false) = (e.ci95, e.identifiable, e.fixed) else {
                return;
            };
            for (end, sign, side) in [(lo, -1.0, "lower"), (hi, 1.0, "upper")] {
                let off = (to_coord(end) - x).abs();
                if !(off > 0.0) {
                    continue;
                }
                let at = (x, off, sign);
                if let Some(rise) =
                    ctx.shoulder(a, at, &coords, best_ssr, level, moving, &starts, &pool)
                {
                    e.identifiable = false;
                    e.note = format!(
                        "not determined: the profile misfit is flat beyond the interval's {side} \
                         end (twice as far from the estimate, in the coordinate, it lies only \
                         {rise:.2} above the minimum, below the two-degree-of-freedom level \
                         {level:.2}): the data hardly exclude values out there"
                    );
                    return;
                }
            }
        };
        for &i in moving {
            let a = unit_direction(i);
            let kind = model.params[i].kind;
            shoulder(&mut parameters[i], &a, coords[i], &|v| kind.to_coord(v));
        }
        for (e, (_, value, grad)) in groups.iter_mut().zip(&group_dirs) {
            shoulder(e, grad, value.ln(), &f64::ln);
        }
    }
    let verdict = verdict(&parameters, &groups);
    Ok(FitResult {
        model: model.clone(),
        data: ctx.data.clone(),
        values,
        fixed: fixed.to_vec(),
        parameters,
        groups,
        residuals,
        rms_residual,
        dof,
        noise_scale,
        quantile,
        singular_values: sv,
        covariance,
        solves: ctx.solves.get(),
        verdict,
        conditional_on_nu: None,
        goodness: None,
        warnings: Vec::new(),
    })
}

/// Extra starting points of the profile minimisations: the other minima met by the fit within
/// [`FIT_PROFILE_OTHERS_SSR`] times the misfit of the estimate that lie away from it (some moving
/// coordinate differs by more than [`FIT_PROFILE_STEP`]), best first, at most
/// [`FIT_PROFILE_OTHERS`] of them (coordinates).
fn profile_starts(
    ctx: &Ctx,
    coords: &[f64],
    best_ssr: f64,
    others: &[(f64, Vec<f64>)],
    moving: &[usize],
) -> Vec<Vec<f64>> {
    let mut near: Vec<&(f64, Vec<f64>)> = others
        .iter()
        .filter(|(s, _)| *s <= FIT_PROFILE_OTHERS_SSR * best_ssr.max(1.0))
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    near.into_iter()
        .map(|(_, v)| ctx.coords(v))
        .filter(|c| {
            moving
                .iter()
                .any(|&i| (c[i] - coords[i]).abs() > FIT_PROFILE_STEP)
        })
        .take(FIT_PROFILE_OTHERS)
        .collect()
}

/// The points screened or evaluated by the fit whose misfit lies within four thresholds of the
/// best (coordinates, best first): starts of the profile minimisations on the far side of an
/// interval's end ([`Ctx::check_end`]). Screened misfits come from loose solves; they only
/// rank the starts.
fn profile_pool(ctx: &Ctx, best_ssr: f64, threshold: f64) -> Vec<(f64, Vec<f64>)> {
    let mut pool: Vec<(f64, Vec<f64>)> = ctx
        .screened
        .borrow()
        .iter()
        .chain(ctx.visited.borrow().iter())
        .filter(|(s, _)| *s <= best_ssr + 4.0 * threshold)
        .map(|(s, v)| (*s, ctx.coords(v)))
        .collect();
    pool.sort_by(|a, b| a.0.total_cmp(&b.0));
    pool
}

/// One line: which parameters and groups the data determine.
pub(super) fn verdict(parameters: &[Estimate], groups: &[Estimate]) -> String {
    let names = |list: &[&Estimate]| {
        if list.is_empty() {
            "none".to_string()
        } else {
            list.iter()
                .map(|e| e.name.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        }
    };
    let det: Vec<&Estimate> = parameters
        .iter()
        .chain(groups)
        .filter(|e| e.identifiable && !e.fixed)
        .collect();
    let not: Vec<&Estimate> = parameters
        .iter()
        .chain(groups)
        .filter(|e| !e.identifiable)
        .collect();
    format!(
        "determined by the data: {}; not determined: {}",
        names(&det),
        names(&not)
    )
}

/// The noise scale and the 97.5 % quantile of the intervals for a weighted misfit `ss` with
/// `dof` degrees of freedom: `(1, z)` when the data carry standard deviations, else
/// `(sqrt(ss / dof), t_dof)` (Student's `t`), `None` without degrees of freedom. The threshold of
/// the profile intervals is `q² s²`.
pub(super) fn noise_and_quantile(data: &Data, ss: f64, dof: usize) -> Option<(f64, f64)> {
    if data.noise_known() {
        Some((1.0, normal_quantile()))
    } else if dof > 0 {
        Some(((ss / dof as f64).sqrt(), t_quantile(dof)))
    } else {
        None
    }
}

/// The 97.5 % quantile of the standard normal distribution.
pub fn normal_quantile() -> f64 {
    use statrs::distribution::{ContinuousCDF, Normal};
    Normal::standard().inverse_cdf(0.975)
}

/// The 97.5 % quantile of Student's `t` with `dof >= 1` degrees of freedom.
pub fn t_quantile(dof: usize) -> f64 {
    use statrs::distribution::{ContinuousCDF, StudentsT};
    match StudentsT::new(0.0, 1.0, dof.max(1) as f64) {
        Ok(t) => t.inverse_cdf(0.975),
        Err(_) => f64::NAN,
    }
}
