//! Skip what the impact does not need: Prony terms far outside the contact window, replaced by
//! their limit forms with an estimated error kept within a share of `rtol` (a general material's `G_eq` can have dozens of terms
//! over 20 decades; the work per step of `fast` grows with the terms).
//!
//! # Limit forms
//! Over a contact of duration `T`, a group of terms much **slower** than the contact acts almost
//! elastically: it is replaced by one term with the same value and slope at `t = 0`,
//! `c_S = Σ c_k`, `c_S / tau_S = Σ c_k / tau_k`. With `R(x) = e^(-x) - 1 + x ∈ [0, x²/2]`, the
//! relaxation function changes by `Σ c_k R(t/tau_k) - c_S R(t/tau_S)`, at most
//! `(T²/2) Σ c_k / tau_k²` over `[0, T]` (Cauchy–Schwarz: `c_S / tau_S² <= Σ c_k / tau_k²`).
//!
//! A group much **faster** than the contact acts as a dashpot (its integral viscous limit
//! `Σ c_k tau_k`): it is replaced by one term with the same zeroth and first moments,
//! `c_F tau_F = Σ c_k tau_k`, `c_F tau_F² = Σ c_k tau_k²`. Against a force history that is
//! smooth on the scale `tau`, the force changes by the second moments,
//! `(1/2) |h'''| Σ (2 c_k tau_k³ + 2 c_F tau_F³)`, of relative size about `2 Σ c_k tau_k² / T_f²`
//! for the motion's time scale `T_f` (the compression time); the model takes `T_f = T / 4`.
//!
//! A relative change `ε` of the contact force changes the rebound energy `e²` by about `2 ε`
//! and the CoR by `ε / e²` relative. The estimate of the CoR error of a reduction is therefore
//!
//! ```text
//! bound = [ (T²/2) Σ_slow c_k / tau_k² + 2 Σ_fast c_k tau_k² / (T/4)² ] / (G_eq(T) e²)
//! ```
//!
//! with `G_eq(T)`, the modulus left at the end of contact, as the force scale.
//!
//! # Use
//! [`solve`] first estimates the contact time as the smallest fixed point of
//! `T = T_H(G_eq(T))`, the elastic Hertz contact time on the modulus left at the end of the
//! contact ([`contact_time_estimate`]; from the glassy Hertz time upwards, so it never jumps to
//! the relaxed modulus of a material that is far stiffer during the contact), and reduces with
//! `2 T` on the slow side, `T / 2` on the fast side (each the conservative side) and `e = 1/2`.
//! It solves the reduced series at `(1 - REDUCE_SHARE) rtol` and checks the bound
//! **a posteriori** with the solve's own contact time and CoR: accepted when it is at most
//! `REDUCE_SHARE rtol` (the reported estimate is the solve's plus the bound, so at most
//! `rtol`), otherwise reduced again from those values (at most [`REDUCE_ATTEMPTS`] times) and
//! finally solved unreduced. Only groups of at least two terms are merged, so a series is never
//! reduced to as many terms as it had (the standard solid, two terms, never is).

use crate::error::Result;
use crate::model::impact::Outcome;

/// Share of `rtol` a reduction may spend.
pub const REDUCE_SHARE: f64 = 0.1;

/// Reduced solves tried before the unreduced one.
pub const REDUCE_ATTEMPTS: usize = 3;

/// Hertz contact time over the maximum indentation (docs/theory.md §6).
const HERTZ_TC: f64 = 2.943_275_184_324_704_7;

/// Canonical Hertz contact time on the modulus `g` (`k = (16/3) g`).
fn hertz_time(g: f64) -> f64 {
    HERTZ_TC * (1.25 / (16.0 / 3.0 * g)).powf(0.4)
}

/// A reduced series: the kept terms and the two merged groups, each `(c, tau)`.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Reduction {
    /// The series the solver gets (kept terms and the aggregates), sorted by time.
    pub terms: Vec<(f64, f64)>,
    slow: Vec<(f64, f64)>,
    fast: Vec<(f64, f64)>,
}

impl Reduction {
    /// The bound of the module docs for the contact time `t` and the CoR `e`, with `g_t`
    /// the modulus at `t`.
    fn bound(&self, t: f64, e: f64, g_t: f64) -> f64 {
        group_bound(&self.slow, &self.fast, t, e, g_t)
    }
}

fn group_bound(slow: &[(f64, f64)], fast: &[(f64, f64)], t: f64, e: f64, g_t: f64) -> f64 {
    let tf = 0.25 * t;
    let s: f64 = slow.iter().map(|(c, tau)| c / (tau * tau)).sum::<f64>() * 0.5 * t * t;
    let f: f64 = fast.iter().map(|(c, tau)| c * tau * tau).sum::<f64>() * 2.0 / (tf * tf);
    (s + f) / (g_t * e * e)
}

/// `G_eq(t)` of `c_inf` and `terms`.
fn modulus_at(c_inf: f64, terms: &[(f64, f64)], t: f64) -> f64 {
    c_inf
        + terms
            .iter()
            .map(|(c, tau)| c * (-t / tau).exp())
            .sum::<f64>()
}

/// Iterations of [`contact_time_estimate`].
const ESTIMATE_ITERATIONS: usize = 60;

/// The smallest fixed point of `T = T_H(G_eq(T))` (canonical Hertz contact time on the modulus
/// at the end of the contact), iterated from the glassy Hertz time: the map is increasing in
/// `T`, so the iterates increase towards it. At most [`ESTIMATE_ITERATIONS`] steps (the last
/// iterate is returned: it is only a first guess, checked a posteriori).
pub(super) fn contact_time_estimate(c_inf: f64, live: &[(f64, f64)]) -> f64 {
    let glassy = c_inf + live.iter().map(|t| t.0).sum::<f64>();
    let mut t = hertz_time(glassy);
    for _ in 0..ESTIMATE_ITERATIONS {
        let next = hertz_time(modulus_at(c_inf, live, t));
        if (next - t).abs() <= 1e-3 * t {
            return next;
        }
        t = next;
    }
    t
}

/// The largest reduction of `live` (any order) whose bound is at most `budget`, half for each
/// side: the slow side for the contact time `t_slow`, the fast side for `t_fast` (an upper and
/// a lower estimate of the contact time; the force scale is `G_eq(t_slow)`) and the CoR `e`;
/// `None` when nothing can be merged.
pub(super) fn reduce(
    c_inf: f64,
    live: &[(f64, f64)],
    (t_slow, t_fast): (f64, f64),
    e: f64,
    budget: f64,
) -> Option<Reduction> {
    let mut sorted = live.to_vec();
    sorted.sort_by(|a, b| a.1.total_cmp(&b.1));
    let g_t = modulus_at(c_inf, live, t_slow);
    let n = sorted.len();
    // slow group: from the slowest term down while its share stays within budget / 2
    let mut n_slow = 0;
    while n_slow < n && group_bound(&sorted[n - n_slow - 1..], &[], t_slow, e, g_t) <= 0.5 * budget
    {
        n_slow += 1;
    }
    // fast group: from the fastest up, never overlapping the slow one
    let mut n_fast = 0;
    while n_fast < n - n_slow
        && group_bound(&[], &sorted[..n_fast + 1], t_fast, e, g_t) <= 0.5 * budget
    {
        n_fast += 1;
    }
    let (n_slow, n_fast) = (
        if n_slow >= 2 { n_slow } else { 0 },
        if n_fast >= 2 { n_fast } else { 0 },
    );
    if n_slow == 0 && n_fast == 0 {
        return None;
    }
    let fast = sorted[..n_fast].to_vec();
    let slow = sorted[n - n_slow..].to_vec();
    let mut terms: Vec<(f64, f64)> = sorted[n_fast..n - n_slow].to_vec();
    if !fast.is_empty() {
        let a: f64 = fast.iter().map(|(c, tau)| c * tau).sum();
        let b: f64 = fast.iter().map(|(c, tau)| c * tau * tau).sum();
        let tau = b / a;
        terms.push((a / tau, tau));
    }
    if !slow.is_empty() {
        let c: f64 = slow.iter().map(|(c, _)| c).sum();
        let r: f64 = slow.iter().map(|(c, tau)| c / tau).sum();
        terms.push((c, c / r));
    }
    terms.sort_by(|a, b| a.1.total_cmp(&b.1));
    Some(Reduction { terms, slow, fast })
}

/// Solve `(c_inf, live)` at `rtol` through `dispatch`, reduced where the bound allows (module
/// docs); the outcome's estimate includes the reduction's bound and its work counts every
/// solve.
pub(super) fn solve(
    c_inf: f64,
    live: &[(f64, f64)],
    rtol: f64,
    dispatch: impl Fn(f64, &[(f64, f64)], f64) -> Result<Outcome>,
) -> Result<Outcome> {
    // first guesses: twice / half the estimated contact time for the slow / fast side, e = 1/2
    let t0 = contact_time_estimate(c_inf, live);
    let (mut times, mut e) = ((2.0 * t0, 0.5 * t0), 0.5);
    let mut spent = crate::model::impact::Work::default();
    let mut tried: Option<Vec<(f64, f64)>> = None;
    for _ in 0..REDUCE_ATTEMPTS {
        let Some(red) = reduce(c_inf, live, times, e, REDUCE_SHARE * rtol) else {
            break;
        };
        if tried.as_ref() == Some(&red.terms) {
            break; // the same reduction again would fail again
        }
        let Ok(mut out) = dispatch(c_inf, &red.terms, (1.0 - REDUCE_SHARE) * rtol) else {
            break; // the unreduced solve decides (and reports its own refusal)
        };
        add(&mut spent, &out.work);
        let g_t = modulus_at(c_inf, live, out.contact_time);
        let b = red.bound(out.contact_time, out.cor, g_t);
        if b <= REDUCE_SHARE * rtol && b.is_finite() {
            out.cor_error_estimate = out.cor_error_estimate.map(|x| x + b);
            out.work = spent;
            return Ok(out);
        }
        tried = Some(red.terms);
        // reduce again from what the solve found (its contact time on both sides)
        times = (times.0.max(out.contact_time), times.1.min(out.contact_time));
        e = e.min(out.cor);
    }
    let mut out = dispatch(c_inf, live, rtol)?;
    add(&mut spent, &out.work);
    out.work = spent;
    Ok(out)
}

fn add(total: &mut crate::model::impact::Work, w: &crate::model::impact::Work) {
    total.steps += w.steps;
    total.evaluations += w.evaluations;
    total.element_updates += w.element_updates;
    total.elements = total.elements.max(w.elements);
    total.levels += w.levels;
    total.tight_checks += w.tight_checks;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aggregates_keep_their_moments() {
        let live: Vec<(f64, f64)> = (0..30)
            .map(|i| (1.0 + i as f64, 10f64.powf(-12.0 + 20.0 * i as f64 / 29.0)))
            .collect();
        let r = reduce(1.0, &live, (3.0, 3.0), 0.5, 1e-7).unwrap();
        assert!(r.terms.len() < live.len());
        let (a, b): (f64, f64) = (
            r.fast.iter().map(|(c, t)| c * t).sum(),
            r.fast.iter().map(|(c, t)| c * t * t).sum(),
        );
        let agg = r.terms[0];
        assert!((agg.0 * agg.1 - a).abs() <= 1e-14 * a);
        assert!((agg.0 * agg.1 * agg.1 - b).abs() <= 1e-14 * b);
        let last = r.terms[r.terms.len() - 1];
        let c: f64 = r.slow.iter().map(|(c, _)| c).sum();
        let slope: f64 = r.slow.iter().map(|(c, t)| c / t).sum();
        assert!((last.0 - c).abs() <= 1e-14 * c);
        assert!((last.0 / last.1 - slope).abs() <= 1e-14 * slope);
        assert!(r.bound(3.0, 0.5, modulus_at(1.0, &live, 3.0)) <= 1e-7);
    }

    #[test]
    fn two_terms_are_never_reduced() {
        assert!(reduce(1.0, &[(1.0, 1e-12), (2.0, 1e12)], (3.0, 3.0), 0.5, 1e-2).is_none());
    }

    /// The estimate lies between the glassy and the relaxed Hertz contact times, is a fixed
    /// point of `T = T_H(G_eq(T))`, and is the Hertz time itself without terms.
    #[test]
    fn contact_time_estimate_is_the_smallest_fixed_point() {
        assert_eq!(contact_time_estimate(1.0, &[]), hertz_time(1.0));
        // a rubber: glassy 1e6 times the relaxed modulus, spread over 20 decades
        let live: Vec<(f64, f64)> = (0..30)
            .map(|i| (1e6 / 30.0, 10f64.powf(-12.0 + 20.0 * i as f64 / 29.0)))
            .collect();
        let t = contact_time_estimate(1.0, &live);
        assert!(t > hertz_time(1e6 + 1.0) && t < hertz_time(1.0), "{t}");
        let g = modulus_at(1.0, &live, t);
        assert!((hertz_time(g) / t - 1.0).abs() < 2e-3, "{t}");
    }
}
