//! The forward problem of the fit: the model's CoR and contact time of every drop at trial
//! parameter values, their weighted residuals, and the central-difference Jacobian. The drops
//! of every misfit, Jacobian and screening are solved in parallel (rayon); each result, down to
//! the count of forward solves, is that of solving them one by one.

use rayon::prelude::*;

use super::{profile, ssr, Ctx, Residual};
use crate::error::{Error, Result};
use crate::model::impact::Impact;
use crate::model::tolerances::{FIT_FD_STEP, FIT_RTOL};
use crate::solvers::{solve, SolveOptions, SolverKind};

/// Model CoR and contact time (s) of one drop.
type Forward = (f64, f64);

impl Ctx<'_> {
    /// Model CoR and contact time of every drop at each of `points` (parameter values). All the
    /// drops of all the points are solved in parallel (rayon): a misfit evaluation is one solve
    /// per drop, a Jacobian one per drop and perturbed point, and a fit makes tens of thousands
    /// of them. Each point's entry is what solving its drops in order gives (the first error in
    /// drop order), with the number of solves that takes (up to and including a failing one);
    /// [`Ctx::solves`] is left to the caller.
    fn forward_points(&self, points: &[Vec<f64>], rtol: f64) -> Vec<(Result<Vec<Forward>>, usize)> {
        let opts = SolveOptions {
            solver: SolverKind::Auto,
            rtol,
            ..Default::default()
        };
        let drops = self.data.observations.len();
        let mut impacts = Vec::with_capacity(points.len() * drops);
        // per point: the impacts built (from `impacts`, in order) and why the next one was not
        let mut built: Vec<(usize, Option<Error>)> = Vec::with_capacity(points.len());
        for values in points {
            let mut base: Vec<Option<Impact>> = vec![None; self.data.setups.len()];
            let start = impacts.len();
            let mut error = None;
            for o in &self.data.observations {
                let imp = match &base[o.setup] {
                    Some(b) => b.at_velocity(o.v0),
                    None => self
                        .model
                        .impact(self.data.setups[o.setup].sphere, o.v0, values)
                        .inspect(|b| base[o.setup] = Some(b.clone())),
                };
                match imp {
                    Ok(imp) => impacts.push(imp),
                    Err(e) => {
                        error = Some(e);
                        break;
                    }
                }
            }
            built.push((impacts.len() - start, error));
        }
        let solved: Vec<Result<Forward>> = impacts
            .par_iter()
            .map(|imp| solve(imp, &opts).map(|out| (out.cor, out.contact_time)))
            .collect();
        let mut solved = solved.into_iter();
        built
            .into_iter()
            .map(|(n, error)| {
                let mut out = Vec::with_capacity(n);
                let (mut count, mut first_error) = (0, None);
                // every one of the point's results is taken, so the next point starts at its own
                for r in solved.by_ref().take(n) {
                    if first_error.is_some() {
                        continue;
                    }
                    count += 1;
                    match r {
                        Ok(x) => out.push(x),
                        Err(e) => first_error = Some(e),
                    }
                }
                match first_error.or(error) {
                    Some(e) => (Err(e), count),
                    None => (Ok(out), count),
                }
            })
            .collect()
    }

    /// Model CoR and contact time of every drop ([`Ctx::forward_points`] at one point).
    fn forward(&self, values: &[f64], rtol: f64) -> Result<Vec<Forward>> {
        let points = [values.to_vec()];
        let (r, count) = self
            .forward_points(&points, rtol)
            .pop()
            .unwrap_or((Ok(Vec::new()), 0));
        self.solves.set(self.solves.get() + count);
        r
    }

    pub(super) fn residuals(&self, values: &[f64], rtol: f64) -> Result<Vec<f64>> {
        let f = self.forward(values, rtol)?;
        Ok(self.weighted(values, rtol, f))
    }

    /// [`Ctx::residuals`] at each of `points`, in order, their drops solved together
    /// ([`Ctx::forward_points`]); every point is evaluated whatever the others give.
    pub(super) fn residuals_points(&self, points: &[Vec<f64>], rtol: f64) -> Vec<Result<Vec<f64>>> {
        self.forward_points(points, rtol)
            .into_iter()
            .zip(points)
            .map(|((r, count), values)| {
                self.solves.set(self.solves.get() + count);
                r.map(|f| self.weighted(values, rtol, f))
            })
            .collect()
    }

    /// [`Ctx::residuals`] at every one of `points`, their drops solved together, or the first
    /// error in the order of `points`: the points after the failing one are neither counted
    /// nor recorded, as if they were evaluated one by one.
    fn residuals_all(&self, points: &[Vec<f64>], rtol: f64) -> Result<Vec<Vec<f64>>> {
        let mut out = Vec::with_capacity(points.len());
        for ((r, count), values) in self.forward_points(points, rtol).into_iter().zip(points) {
            self.solves.set(self.solves.get() + count);
            out.push(self.weighted(values, rtol, r?));
        }
        Ok(out)
    }

    /// The weighted residuals of the model values `f` at `values`; the point is recorded in
    /// [`Ctx::visited`] when `rtol` is [`FIT_RTOL`] and its misfit is finite.
    fn weighted(&self, values: &[f64], rtol: f64, f: Vec<Forward>) -> Vec<f64> {
        let r: Vec<f64> = self
            .residual_list_of(f)
            .into_iter()
            .map(|r| r.weighted)
            .collect();
        let s = ssr(&r);
        if rtol == FIT_RTOL && s.is_finite() {
            self.visited.borrow_mut().push((s, values.to_vec()));
        }
        r
    }

    pub(super) fn residual_list(&self, values: &[f64], rtol: f64) -> Result<Vec<Residual>> {
        Ok(self.residual_list_of(self.forward(values, rtol)?))
    }

    /// The residuals of the model values `f` (CoR and contact time of every drop).
    fn residual_list_of(&self, f: Vec<Forward>) -> Vec<Residual> {
        let mut out = Vec::with_capacity(self.data.residual_count());
        for (i, (o, (e, t))) in self.data.observations.iter().zip(f).enumerate() {
            out.push(Residual {
                observation: i,
                quantity: "cor",
                measured: o.cor,
                model: e,
                weighted: (e - o.cor) / o.cor_sd.unwrap_or(1.0),
            });
            if let Some(tc) = o.contact_time {
                out.push(Residual {
                    observation: i,
                    quantity: "contact_time",
                    measured: tc,
                    model: t,
                    weighted: (t - tc) / o.contact_time_sd.unwrap_or(tc),
                });
            }
        }
        out
    }

    /// Central-difference Jacobian of the weighted residuals with respect to the coordinates
    /// `moving` at `coords` (with the constraint `tie` kept, when given).
    pub(super) fn jacobian(
        &self,
        coords: &[f64],
        moving: &[usize],
        tie: Option<&profile::Tie>,
    ) -> Result<Vec<Vec<f64>>> {
        // the perturbed points in the order of the one-by-one evaluation: + then - per column
        let mut points = Vec::with_capacity(2 * moving.len());
        for &j in moving {
            for off in [FIT_FD_STEP, -FIT_FD_STEP] {
                let mut c = coords.to_vec();
                c[j] = coords[j] + off;
                if let Some(t) = tie {
                    t.apply(&mut c);
                }
                points.push(self.values(&c));
            }
        }
        let r = self.residuals_all(&points, self.lm_rtol.get())?;
        let cols = r
            .chunks_exact(2)
            .map(|pm| {
                pm[0]
                    .iter()
                    .zip(&pm[1])
                    .map(|(p, m)| (p - m) / (2.0 * FIT_FD_STEP))
                    .collect()
            })
            .collect();
        Ok(cols)
    }
}
