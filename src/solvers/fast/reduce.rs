//! Skip what the impact does not need: Prony terms far outside the contact window, replaced by
//! fewer terms with an error bound kept within a share of `rtol` (a general material's `G_eq`
//! can have dozens of terms over 20 decades; the work per step of `fast` grows linearly with the
//! terms: every kernel, dense output and Ting root runs over them).
//!
//! # Replacements: Gauss rules of the spectrum (docs/theory.md §9.7)
//! A group of terms is a discrete measure, and its replacement by `n` terms is the `n`-point
//! Gauss rule of that measure, which matches its first `2n` moments; the error of a Gauss rule
//! for `f` is `f^(2n)(ξ) / (2n)! · ‖π_n‖²`, with `π_n` the measure's monic orthogonal
//! polynomial of degree `n` (computed with the rule by Stieltjes' procedure, [`stieltjes`]).
//!
//! A group much **slower** than the contact acts almost elastically. In the rates `s = 1/tau`
//! with weights `c_k`, `G(t) = Σ c_k exp(-t s_k)` and `|d^(2n)/ds^(2n) exp(-t s)| <= t^(2n)`, so
//! the relaxation function changes by at most `T^(2n) / (2n)! · ‖π_n‖²` over `[0, T]`; with
//! `n = 1` the rule keeps value and slope at `t = 0` (`c_S = Σ c_k`, `c_S / tau_S = Σ c_k / tau_k`).
//!
//! A group much **faster** than the contact acts as a dashpot and its higher moments: the force
//! of a term is `c tau φ(tau)` with `φ(tau) = ∫_0^(t/tau) exp(-x) w'(t - tau x) dx`, so in the
//! times with weights `c_k tau_k` the rule matches `Σ c_k tau_k^j`, `j = 1 ..= 2n` (for
//! `n = 1` the viscous limit `Σ c_k tau_k` and `Σ c_k tau_k²`), and since
//! `|φ^(2n)| <= (2n)! max |w^(2n+1)|` the force changes by at most `(16/3) max |w^(2n+1)| ‖π_n‖²`.
//! The model takes `|w^(j)| <= j! w_max / T_f^j` with `T_f = T / 4` (a function analytic in a
//! disc of radius `T_f` around the motion), so the relative force change is at most
//! `(2n+1)! ‖π_n‖² / (T_f^(2n+1) G_eq(T))`. Within a few `tau` of the start `w = t^(3/2)` is
//! not smooth on that scale (the initial layers). What matters there is what the rule changes,
//! not what the group does: to first order the CoR changes by `Σ c Q(tau)` over the group minus
//! the rule, one function `Q` for every term, and by `∫_0^t q = tau (w - q)` (from
//! `tau q' + q = tau w'`, `q(0) = 0`) the matched moments cancel in the velocity and the
//! indentation at every time, the start included. What is left of the start is the part of `Q`
//! that is not a polynomial in `tau`, modelled per term as `LAYER_FACTOR (16/3) c tau^(7/2) / T`
//! (the indentation of a spring-like layer of duration `tau`, acting over the contact); the
//! bound charges its change, the Gauss rule's error for `tau^(5/2)` in the measure `c tau`,
//! computed directly from both term lists ([`fast_layer`]).
//!
//! A relative change `ε` of the contact force changes the rebound energy `e²` by about `2 ε`
//! and the CoR by `ε / e²` relative. The estimate of the CoR error of a reduction is therefore
//!
//! ```text
//! bound = [ T^(2n_S)/(2n_S)! ‖π_(n_S)‖²_slow + (2n_F+1)! ‖π_(n_F)‖²_fast / T_f^(2n_F+1) ] / (G_eq(T) e²)
//!         + LAYER_FACTOR (16/3) |Σ_fast c_k tau_k^(7/2) - Σ_rule c_j tau_j^(7/2)| / (T e²)
//! ```
//!
//! with `G_eq(T)`, the modulus left at the end of contact, as the force scale. Each side takes
//! the rule of 1 to [`REDUCE_MAX_POINTS`] points that removes the most terms within half the
//! budget (the moment part grows with the group, so the largest group of each `n` is a
//! bisection; the layer part needs the rule, so it is checked on the group found, which
//! shrinks until the whole bound fits).
//! The bound and its model were checked against unreduced solves 100x tighter on the general
//! validation cases, the real polymers at several velocities, random series and groups of
//! spread fast terms (`tests/fast_reduce.rs`), and rule by rule against the replaced group
//! (`fast_replacements_are_within_their_bound`).
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
//! finally solved unreduced. A group is replaced only by fewer terms than it has, so the
//! standard solid (two terms) is never reduced.

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

/// Most points of one merged group.
pub const REDUCE_MAX_POINTS: usize = 4;

/// A reduced series: the kept terms and the two merged groups, each `(c, tau)`, with the
/// number of terms that replaced each group.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Reduction {
    /// The series the solver gets (kept terms and the replacements), sorted by time.
    pub terms: Vec<(f64, f64)>,
    slow: Vec<(f64, f64)>,
    fast: Vec<(f64, f64)>,
    /// The terms that replaced the fast group (empty for an empty group).
    fast_rule: Vec<(f64, f64)>,
    /// Terms replacing the slow and the fast group (0 for an empty group).
    points: (usize, usize),
}

impl Reduction {
    /// The bound of the module docs for the contact time `t` and the CoR `e`, with `g_t`
    /// the modulus at `t`.
    fn bound(&self, t: f64, e: f64, g_t: f64) -> f64 {
        slow_bound(&self.slow, self.points.0, t, e, g_t)
            + fast_bound(&self.fast, self.points.1, t, e, g_t)
            + fast_layer(&self.fast, &self.fast_rule, t, e)
    }
}

/// Largest discrete measure of a bound or rule: every group is part of the live terms, at
/// most [`super::FAST_MAX_TERMS`] (checked by `prepare`).
const MAX_MEASURE: usize = super::FAST_MAX_TERMS;

/// Recurrence coefficients of [`stieltjes`] (at most [`REDUCE_MAX_POINTS`] of each).
type Recurrence = ([f64; REDUCE_MAX_POINTS], [f64; REDUCE_MAX_POINTS]);

/// Stieltjes' procedure on the discrete measure `Σ w_k δ(x - x_k)` (`len` points given by
/// `x(k)`, `w(k)`; positive weights): the recurrence coefficients `α_j`, `β_j` (`j < n`, `β_0`
/// the total weight) of its monic orthogonal polynomials and `‖π_n‖² = ∫ π_n² dμ`, the
/// constant of the `n`-point Gauss rule's error (docs/theory.md §9.7). The measure is scaled to
/// total weight 1 and largest point 1 for the recurrence. No allocation: the bisections of
/// [`best_group`] call it for every trial group. Each pass evaluates `π_j(x_k)` again by the
/// recurrence from the coefficients found so far (`n <= 4`: at most 10 recurrence steps per
/// point) instead of keeping `π_j` and `π_(j-1)` in two more buffers of the largest measure's
/// size, whose zeroing cost more (the same operations in the same order, so the same bits).
fn stieltjes(
    len: usize,
    x: impl Fn(usize) -> f64,
    w: impl Fn(usize) -> f64,
    n: usize,
) -> (Recurrence, f64) {
    debug_assert!(len <= MAX_MEASURE && n <= REDUCE_MAX_POINTS);
    let mut xs = [0.0; MAX_MEASURE];
    let mut ws = [0.0; MAX_MEASURE];
    let mut xscale = 0.0f64;
    let mut wscale = 0.0;
    for k in 0..len {
        xs[k] = x(k);
        ws[k] = w(k);
        xscale = xscale.max(xs[k]);
        wscale += ws[k];
    }
    for k in 0..len {
        xs[k] /= xscale;
        ws[k] /= wscale;
    }
    // the scaled recurrence coefficients (the returned ones are unscaled)
    let (mut a_s, mut b_s) = ([0.0; REDUCE_MAX_POINTS], [0.0; REDUCE_MAX_POINTS]);
    // `π_j` of the scaled measure at the scaled point `xk` (the same operations, in the same
    // order, as a recurrence run once over stored values)
    let pi = |xk: f64, j: usize, a_s: &[f64; REDUCE_MAX_POINTS], b_s: &[f64; REDUCE_MAX_POINTS]| {
        let (mut p_prev, mut p) = (0.0, 1.0);
        for i in 0..j {
            let next = (xk - a_s[i]) * p - if i == 0 { 0.0 } else { b_s[i] * p_prev };
            p_prev = p;
            p = next;
        }
        p
    };
    let (mut alpha, mut beta) = ([0.0; REDUCE_MAX_POINTS], [0.0; REDUCE_MAX_POINTS]);
    let mut norm_prev = 1.0;
    for j in 0..=n {
        let (mut norm, mut first) = (0.0, 0.0);
        for (&xk, &wk) in xs[..len].iter().zip(&ws[..len]) {
            let p = pi(xk, j, &a_s, &b_s);
            norm += wk * p * p;
            first += wk * xk * p * p;
        }
        if j == n {
            return ((alpha, beta), norm * wscale * xscale.powi(2 * n as i32));
        }
        let a = first / norm;
        let b = if j == 0 { 1.0 } else { norm / norm_prev };
        a_s[j] = a;
        b_s[j] = b;
        alpha[j] = a * xscale;
        beta[j] = b * if j == 0 { wscale } else { xscale * xscale };
        norm_prev = norm;
    }
    unreachable!("the loop returns at j = n")
}

/// `‖π_n‖²` of [`stieltjes`] for the points `x` with weights `w`.
#[cfg(test)]
fn gauss_norm(x: &[f64], w: &[f64], n: usize) -> f64 {
    stieltjes(x.len(), |k| x[k], |k| w[k], n).1
}

/// The `n`-point Gauss rule of the discrete measure `Σ w_k δ(x - x_k)` (Golub–Welsch: the
/// eigenvalues of the Jacobi matrix and `β_0` times the squared first components of its
/// eigenvectors): `(node, weight)` pairs, `None` unless every node lies within the points'
/// range and every weight is positive (round-off).
fn gauss_rule(x: &[f64], w: &[f64], n: usize) -> Option<Vec<(f64, f64)>> {
    let ((alpha, beta), _) = stieltjes(x.len(), |k| x[k], |k| w[k], n);
    let jac = nalgebra::DMatrix::from_fn(n, n, |i, j| {
        if i == j {
            alpha[i]
        } else if i.abs_diff(j) == 1 {
            beta[i.max(j)].sqrt()
        } else {
            0.0
        }
    });
    let eig = nalgebra::SymmetricEigen::new(jac);
    let (lo, hi) = x
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), &v| (l.min(v), h.max(v)));
    let rule: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            (
                eig.eigenvalues[i],
                beta[0] * eig.eigenvectors[(0, i)].powi(2),
            )
        })
        .collect();
    let ok = rule.iter().all(|&(node, weight)| {
        node >= lo * (1.0 - 1e-9) && node <= hi * (1.0 + 1e-9) && weight > 0.0 && node > 0.0
    });
    ok.then_some(rule)
}

fn factorial(n: usize) -> f64 {
    (1..=n).map(|k| k as f64).product()
}

/// Relative CoR error bound of replacing the slow group by its `n`-point Gauss rule in the
/// rates `s = 1 / tau` (weights `c`), over a contact of duration `t` (module docs).
fn slow_bound(slow: &[(f64, f64)], n: usize, t: f64, e: f64, g_t: f64) -> f64 {
    if slow.is_empty() {
        return 0.0;
    }
    let (_, norm) = stieltjes(slow.len(), |k| 1.0 / slow[k].1, |k| slow[k].0, n);
    t.powi(2 * n as i32) / factorial(2 * n) * norm / (g_t * e * e)
}

/// Relative CoR error bound of replacing the fast group by its `n`-point Gauss rule in the
/// times (weights `c tau`), for a contact of duration `t` (module docs): the moment remainder
/// (the initial layers are [`fast_layer`]).
fn fast_bound(fast: &[(f64, f64)], n: usize, t: f64, e: f64, g_t: f64) -> f64 {
    if fast.is_empty() {
        return 0.0;
    }
    let tf = 0.25 * t;
    let (_, norm) = stieltjes(fast.len(), |k| fast[k].1, |k| fast[k].0 * fast[k].1, n);
    factorial(2 * n + 1) * norm / (tf.powi(2 * n as i32 + 1) * g_t * e * e)
}

/// `Σ c_k tau_k^(7/2)` of `terms`: the initial layers' moment (module docs).
fn layer_moment(terms: &[(f64, f64)]) -> f64 {
    terms
        .iter()
        .map(|(c, tau)| c * tau.powi(3) * tau.sqrt())
        .sum()
}

/// The initial layers' part of the fast bound (module docs): what the replacement `rule`
/// changes of the group's layer moment `Σ c_k tau_k^(7/2)`, computed directly from both.
fn fast_layer(fast: &[(f64, f64)], rule: &[(f64, f64)], t: f64, e: f64) -> f64 {
    LAYER_FACTOR * K16 * (layer_moment(fast) - layer_moment(rule)).abs() / (t * e * e)
}

/// The fast group's rule: `(c, tau)` terms of the `n`-point Gauss rule in the times (weights
/// `c tau`), `None` as for [`gauss_rule`].
fn fast_rule(fast: &[(f64, f64)], n: usize) -> Option<Vec<(f64, f64)>> {
    let x: Vec<f64> = fast.iter().map(|(_, tau)| *tau).collect();
    let w: Vec<f64> = fast.iter().map(|(c, tau)| c * tau).collect();
    let rule = gauss_rule(&x, &w, n)?;
    Some(rule.iter().map(|&(tau, ct)| (ct / tau, tau)).collect())
}

/// Factor of the initial layers' share of the fast bound (module docs).
const LAYER_FACTOR: f64 = 8.0;

/// `16/3` of the force law.
const K16: f64 = 16.0 / 3.0;

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

/// The group at one end of `sorted` (the `m` last terms for the slow side, the `m` first for
/// the fast side) that saves the most terms among the rules of 1 to [`REDUCE_MAX_POINTS`]
/// points whose `bound(group, n)` is at most `limit`, at most `avail` terms: `(m, n)`, or
/// `(0, 0)` when no group of more than `n` terms fits. The bound grows with the group (the
/// norm of a Gauss rule's error grows with the measure), so each `n` is a binary search, and
/// no `n` that could not save more terms than the best so far is tried.
fn best_group(
    sorted: &[(f64, f64)],
    avail: usize,
    slow: bool,
    limit: f64,
    bound: impl Fn(&[(f64, f64)], usize) -> f64,
) -> (usize, usize) {
    let nn = sorted.len();
    let group = |m: usize| {
        if slow {
            &sorted[nn - m..]
        } else {
            &sorted[..m]
        }
    };
    let mut best: (usize, usize) = (0, 0);
    for n in 1..=REDUCE_MAX_POINTS {
        // a rule of n points saves at most avail - n terms (fewer for larger n)
        if avail <= n || avail - n <= best.0.saturating_sub(best.1) {
            break;
        }
        // only a group of at least `first` terms saves more than the best so far; the bound
        // grows with the group, so if that one is over the limit every larger one is too
        let first = (n + 1).max(best.0.saturating_sub(best.1) + n + 1);
        if first > avail || bound(group(first), n) > limit {
            continue;
        }
        // largest m in [first, avail] within the limit
        let (mut lo, mut hi) = (first, avail);
        while lo < hi {
            let mid = (lo + hi).div_ceil(2);
            if bound(group(mid), n) <= limit {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        if lo - n > best.0.saturating_sub(best.1) {
            best = (lo, n);
        }
    }
    best
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
    let (mut n_slow, mut p_slow) = best_group(&sorted, n, true, 0.5 * budget, |g, p| {
        slow_bound(g, p, t_slow, e, g_t)
    });
    let (mut n_fast, mut p_fast) = best_group(&sorted, n - n_slow, false, 0.5 * budget, |g, p| {
        fast_bound(g, p, t_fast, e, g_t)
    });
    // the layer part needs the rule itself: checked on the group found, which shrinks until
    // the whole fast bound fits (no rule: the group is kept)
    let mut rule = Vec::new();
    while n_fast > p_fast {
        let g = &sorted[..n_fast];
        match fast_rule(g, p_fast) {
            Some(r)
                if fast_bound(g, p_fast, t_fast, e, g_t) + fast_layer(g, &r, t_fast, e)
                    <= 0.5 * budget =>
            {
                rule = r;
                break;
            }
            Some(_) => n_fast -= 1,
            None => break,
        }
    }
    if rule.is_empty() {
        (n_fast, p_fast) = (0, 0);
    }
    let fast = sorted[..n_fast].to_vec();
    let slow = sorted[n - n_slow..].to_vec();
    let mut terms: Vec<(f64, f64)> = sorted[n_fast..n - n_slow].to_vec();
    terms.extend_from_slice(&rule);
    if n_slow > 0 {
        let x: Vec<f64> = slow.iter().map(|(_, tau)| 1.0 / tau).collect();
        let w: Vec<f64> = slow.iter().map(|(c, _)| *c).collect();
        match gauss_rule(&x, &w, p_slow) {
            Some(rule) => terms.extend(rule.iter().map(|&(s, c)| (c, 1.0 / s))),
            None => {
                terms.extend_from_slice(&slow);
                (n_slow, p_slow) = (0, 0);
            }
        }
    }
    if n_slow == 0 && n_fast == 0 {
        return None;
    }
    terms.sort_by(|a, b| a.1.total_cmp(&b.1));
    Some(Reduction {
        terms,
        slow: if n_slow > 0 { slow } else { Vec::new() },
        fast,
        fast_rule: rule,
        points: (p_slow, p_fast),
    })
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

    /// A rule of `n` points matches the first `2n` moments of its measure; `‖π_n‖²` equals
    /// `∫ p² dμ` for the monic orthogonal `p`, which is below `∫ x^(2n) dμ`.
    #[test]
    fn gauss_rules_match_the_moments() {
        let x: Vec<f64> = (0..12).map(|i| 10f64.powf(-3.0 + 0.4 * i as f64)).collect();
        let w: Vec<f64> = (0..12).map(|i| 1.0 + (i % 5) as f64).collect();
        for n in 1..=REDUCE_MAX_POINTS {
            let rule = gauss_rule(&x, &w, n).unwrap();
            assert_eq!(rule.len(), n);
            for j in 0..2 * n {
                let exact: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(j as i32)).sum();
                let q: f64 = rule.iter().map(|(x, w)| w * x.powi(j as i32)).sum();
                assert!(
                    (q - exact).abs() <= 1e-9 * exact,
                    "n {n} moment {j}: {q} vs {exact}"
                );
            }
            let norm = gauss_norm(&x, &w, n);
            let top: f64 = x
                .iter()
                .zip(&w)
                .map(|(x, w)| w * x.powi(2 * n as i32))
                .sum();
            assert!(
                norm > 0.0 && norm <= top * (1.0 + 1e-12),
                "n {n}: {norm} vs {top}"
            );
        }
    }

    /// The slow group's bound holds for the relaxation function itself: the largest change of
    /// `G` over `[0, T]` by the replacement is below `T^(2n)/(2n)! ‖π_n‖²`.
    #[test]
    fn slow_replacement_is_within_its_bound() {
        let live: Vec<(f64, f64)> = (0..30)
            .map(|i| (1.0 + i as f64, 10f64.powf(-12.0 + 20.0 * i as f64 / 29.0)))
            .collect();
        let (t, e) = (3.0, 0.5);
        let g_t = modulus_at(1.0, &live, t);
        let r = reduce(1.0, &live, (t, t), e, 1e-7).unwrap();
        assert!(r.terms.len() < live.len());
        assert!(r.bound(t, e, g_t) <= 1e-7);
        let rule: Vec<(f64, f64)> = r
            .terms
            .iter()
            .copied()
            .filter(|&(_, tau)| tau > r.slow[0].1 * (1.0 - 1e-12))
            .collect();
        assert_eq!(rule.len(), r.points.0);
        let bound = slow_bound(&r.slow, r.points.0, t, e, g_t) * g_t * e * e;
        let worst = (0..=200)
            .map(|i| {
                let tt = t * i as f64 / 200.0;
                (modulus_at(0.0, &r.slow, tt) - modulus_at(0.0, &rule, tt)).abs()
            })
            .fold(0.0f64, f64::max);
        assert!(worst <= bound * (1.0 + 1e-9) + 1e-12 * modulus_at(0.0, &r.slow, 0.0));
        // the fast rule keeps the viscous limit and the next moment
        let fast_rule: Vec<(f64, f64)> = r
            .terms
            .iter()
            .copied()
            .filter(|&(_, tau)| tau < r.fast[r.fast.len() - 1].1 * (1.0 + 1e-12))
            .collect();
        assert_eq!(fast_rule.len(), r.points.1);
        for j in 1..=2 {
            let m = |g: &[(f64, f64)]| g.iter().map(|(c, tau)| c * tau.powi(j)).sum::<f64>();
            assert!((m(&fast_rule) - m(&r.fast)).abs() <= 1e-9 * m(&r.fast));
        }
    }

    /// A bound of a group and a number of points, as [`best_group`] takes it.
    type GroupBound<'a> = &'a dyn Fn(&[(f64, f64)], usize) -> f64;

    /// The search of [`reduce`] (bisection per `n` on the moment part, the stop once no `n`
    /// can save more) finds the groups an exhaustive search of every group size and every `n`
    /// finds, on random series spread over 24 decades around the contact.
    #[test]
    fn group_search_matches_exhaustive_search() {
        // the largest saving over every n and every group size within the limit (ties: the
        // smallest n, as in best_group)
        let exhaustive =
            |sorted: &[(f64, f64)], avail: usize, slow: bool, limit: f64, bound: GroupBound| {
                let nn = sorted.len();
                let mut best: (usize, usize) = (0, 0);
                for n in 1..=REDUCE_MAX_POINTS {
                    for m in n + 1..=avail {
                        let g = if slow {
                            &sorted[nn - m..]
                        } else {
                            &sorted[..m]
                        };
                        if bound(g, n) <= limit && m - n > best.0.saturating_sub(best.1) {
                            best = (m, n);
                        }
                    }
                }
                best
            };
        let mut rng = crate::rng::SplitMix64::new(3);
        let mut merged = 0;
        for case in 0..200 {
            let n = 3 + case % 40;
            let mut live: Vec<(f64, f64)> = (0..n)
                .map(|_| {
                    let c = 10f64.powf(-1.0 + 7.0 * rng.uniform());
                    (c, 10f64.powf(-12.0 + 24.0 * rng.uniform()))
                })
                .collect();
            live.sort_by(|a, b| a.1.total_cmp(&b.1));
            let t = contact_time_estimate(1.0, &live);
            let (t_slow, t_fast, e) = (2.0 * t, 0.5 * t, 0.5);
            let g_t = modulus_at(1.0, &live, t_slow);
            for budget in [1e-3, 1e-7, 1e-11] {
                let limit = 0.5 * budget;
                let slow = |g: &[(f64, f64)], p: usize| slow_bound(g, p, t_slow, e, g_t);
                let fast = |g: &[(f64, f64)], p: usize| fast_bound(g, p, t_fast, e, g_t);
                let s = best_group(&live, n, true, limit, slow);
                assert_eq!(s, exhaustive(&live, n, true, limit, &slow), "case {case}");
                let f = best_group(&live, n - s.0, false, limit, fast);
                assert_eq!(
                    f,
                    exhaustive(&live, n - s.0, false, limit, &fast),
                    "case {case}"
                );
                merged += usize::from(s.0 > 0) + usize::from(f.0 > 0);
            }
        }
        // the cases exercise both sides
        assert!(merged > 100, "{merged}");
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

    /// The fast side's bound holds where the initial layers' part decides: groups of 3 to 12
    /// fast terms spread over 1 to 6 decades, each replaced by its rules of 1 to 4 points, and
    /// the CoR of the replaced series against the full one, both solved unreduced at 1e-12
    /// (their own estimates added to the bound). Without the layer part the rule of several
    /// points has a moment part far below the whole group's layer moment, so these cases test
    /// the difference of the layer moments, not the moment remainder.
    #[test]
    fn fast_replacements_are_within_their_bound() {
        let solve_tight = |c_inf: f64, terms: &[(f64, f64)]| {
            let p = crate::Prony {
                relaxed: c_inf,
                terms: terms
                    .iter()
                    .map(|&(coefficient, tau)| crate::PronyTerm { coefficient, tau })
                    .collect(),
            };
            crate::solvers::fast::impact_unreduced(&p, 1e-12, false).unwrap()
        };
        let mut rng = crate::rng::SplitMix64::new(7);
        let (mut worst, mut layer_decides) = (0.0f64, 0);
        for case in 0..24 {
            let m = 3 + case % 10;
            let glassy = 10f64.powf(4.0 * rng.uniform());
            let top = 10f64.powf(-3.0 + 2.5 * rng.uniform());
            let span = 1.0 + 5.0 * rng.uniform();
            let mut live: Vec<(f64, f64)> = (0..m)
                .map(|_| (0.1 + rng.uniform(), top * 10f64.powf(-span * rng.uniform())))
                .collect();
            let total: f64 = live.iter().map(|t| t.0).sum();
            live.iter_mut().for_each(|t| t.0 *= glassy / total);
            // a term inside the contact window beside the group
            live.push((glassy * 0.5 * rng.uniform(), 0.3 + rng.uniform()));
            live.sort_by(|a, b| a.1.total_cmp(&b.1));
            let c_inf = 0.5 + rng.uniform();
            let full = solve_tight(c_inf, &live);
            let (t, e) = (full.contact_time, full.cor);
            let g_t = modulus_at(c_inf, &live, t);
            let group = &live[..m];
            for n in 1..=REDUCE_MAX_POINTS.min(m - 1) {
                let Some(rule) = fast_rule(group, n) else {
                    continue;
                };
                let mut reduced = rule.clone();
                reduced.extend_from_slice(&live[m..]);
                let red = solve_tight(c_inf, &reduced);
                let err = ((red.cor - full.cor) / full.cor).abs();
                let (moments, layer) = (
                    fast_bound(group, n, t, e, g_t),
                    fast_layer(group, &rule, t, e),
                );
                let noise = full.cor_error_estimate.unwrap() + red.cor_error_estimate.unwrap();
                assert!(
                    err <= moments + layer + noise,
                    "case {case} n {n}: {err:e} > {moments:e} + {layer:e} + {noise:e}"
                );
                if moments + layer > 1e-10 {
                    worst = worst.max(err / (moments + layer));
                }
                // the whole group's layer moment would have decided here
                let whole = LAYER_FACTOR * K16 * layer_moment(group) / (t * e * e);
                layer_decides += usize::from(whole > moments && whole > 1e-8);
            }
        }
        println!("largest error over bound {worst:.2e}; {layer_decides} rules");
        assert!(layer_decides >= 10, "{layer_decides}");
    }
}
