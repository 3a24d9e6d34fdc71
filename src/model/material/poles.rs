//! `G_eq(t)` of a general material and `G_tot(t)` of two bodies as exact Prony series, by a
//! route that shares no code with [`crate::model::material::carson`] (which `fast` and `mdr`'s pilot
//! use): the reference solver takes its relaxation function from here.
//!
//! # Formulation: relaxation times as roots in the time domain
//! A Prony-type modulus `P(t) = p_inf + sum_k p_k exp(-t/tau_k)` has the Carson transform
//! `P(s) = p_inf + sum_k p_k s tau_k / (1 + s tau_k)`. On the negative real axis, written with
//! the time `T = -1/s > 0`,
//!
//! ```text
//! P~(T) = p_inf + sum_k p_k tau_k / (tau_k - T),    dP~/dT = sum_k p_k tau_k / (tau_k - T)^2 > 0,
//! ```
//!
//! so a positive combination `W~ = alpha P~ + beta Q~` of two such functions increases
//! strictly in `T` between consecutive times `tau_k < tau_(k+1)` of either, from `-inf` to
//! `+inf`, and from `-inf` to `w_inf > 0` beyond the longest one: exactly one root `T` per
//! interval, and no root below the shortest time (where `W~ > w_inf + sum_k w_k > 0`). When
//! `w_inf = 0` (both inputs relax to zero) `W~` only tends to zero beyond the longest time and
//! that interval has no root.
//!
//! - `G_eq = G (3K + G) / (3K + 4G)` (docs/theory.md §8): `W = 3K + 4G`, `N = G (3K + G)`.
//! - `G_tot = G_A G_B / (G_A + G_B)` (two bodies): `W = G_A + G_B`, `N = G_A G_B`.
//!
//! Each root `T_z` of `W~` is a relaxation time of the result, with the modulus
//! `c_z = -N~(T_z) / (T_z dW~/dT(T_z))` (the residue of `N/W` in `s`, times `-1/s`). A time
//! `tau` of the inputs stays a relaxation time with the limit of `N/W` of the two inputs'
//! moduli there: `g (3k + g) / (3k + 4g)` (so `g/4` where the bulk has no term, and nothing
//! where only the bulk has one), `a b / (a + b)` for two bodies.
//!
//! # Accuracy
//! The root in `(tau_k, tau_(k+1))` is sought as an offset `delta` from the nearer end (the
//! end is chosen by the sign of `W~` at the midpoint), with every `tau_j - anchor` formed once:
//! then `tau_j / ((tau_j - anchor) - delta)` keeps full relative accuracy even where the root
//! lies within `1e-20 tau_k` of a pole. The offset is found by Brent's method
//! ([`roots::find_root_brent`], a maintained crate) in `x = ln(delta / half-width)`, then
//! polished by one Newton step in `delta`. Measured in `tests/rheology.rs` against
//! `material::carson` and the Talbot inversion of `theory::bromwich`.

use roots::{find_root_brent, Convergency};

use crate::error::{Error, Result};
use crate::model::material::{BulkRheology, Material, Prony, PronyTerm};

/// Iteration cap of one root search (Brent's method on a bracket of at most 1500 e-folds
/// converges in far fewer); [`Error::NoConvergence`] beyond.
pub const ROOT_MAX_ITER: usize = 300;

/// Widening steps (factor `e^40` each) when bracketing a root from its anchor.
const BRACKET_STEPS: usize = 40;

/// One time of the combined pole list with the two inputs' moduli there (either may be 0).
#[derive(Debug, Clone, Copy)]
struct Time {
    tau: f64,
    p: f64,
    q: f64,
}

/// Two Prony-type inputs on one sorted list of distinct times.
struct Pair {
    p_inf: f64,
    q_inf: f64,
    times: Vec<Time>,
}

impl Pair {
    fn new(p_inf: f64, p: &[(f64, f64)], q_inf: f64, q: &[(f64, f64)]) -> Self {
        // (modulus, time) pairs; zero moduli carry no pole
        let mut all: Vec<Time> = p
            .iter()
            .filter(|t| t.0 > 0.0)
            .map(|&(m, tau)| Time { tau, p: m, q: 0.0 })
            .chain(
                q.iter()
                    .filter(|t| t.0 > 0.0)
                    .map(|&(m, tau)| Time { tau, p: 0.0, q: m }),
            )
            .collect();
        all.sort_by(|a, b| a.tau.total_cmp(&b.tau));
        let mut times: Vec<Time> = Vec::with_capacity(all.len());
        for t in all {
            match times.last_mut() {
                Some(last) if last.tau == t.tau => {
                    last.p += t.p;
                    last.q += t.q;
                }
                _ => times.push(t),
            }
        }
        Self {
            p_inf,
            q_inf,
            times,
        }
    }

    /// `(P~, Q~, dP~/dT, dQ~/dT)` at `T = anchor + delta`, with `gaps[j] = tau_j - anchor`.
    fn at(&self, gaps: &[f64], delta: f64) -> [f64; 4] {
        let (mut p, mut q, mut dp, mut dq) = (self.p_inf, self.q_inf, 0.0, 0.0);
        for (t, gap) in self.times.iter().zip(gaps) {
            let r = 1.0 / (gap - delta);
            let x = t.tau * r;
            p += t.p * x;
            q += t.q * x;
            dp += t.p * x * r;
            dq += t.q * x * r;
        }
        [p, q, dp, dq]
    }

    fn gaps(&self, anchor: f64) -> Vec<f64> {
        self.times.iter().map(|t| t.tau - anchor).collect()
    }
}

/// What is combined: `W = alpha P + beta Q`, `N(P, Q)`, the modulus at a shared time.
#[derive(Debug, Clone, Copy)]
enum Combination {
    /// `G_eq` from `P = G`, `Q = K`.
    Equivalent,
    /// `G_tot` from `P = G_A`, `Q = G_B`.
    Series,
}

impl Combination {
    fn w(self, p: f64, q: f64) -> f64 {
        match self {
            Combination::Equivalent => 3.0 * q + 4.0 * p,
            Combination::Series => p + q,
        }
    }
    fn n(self, p: f64, q: f64) -> f64 {
        match self {
            Combination::Equivalent => p * (3.0 * q + p),
            Combination::Series => p * q,
        }
    }
    /// The result's modulus at a time where the inputs have the moduli `p` and `q`.
    fn at_pole(self, p: f64, q: f64) -> f64 {
        match self {
            Combination::Equivalent if p > 0.0 => p * (3.0 * q + p) / (3.0 * q + 4.0 * p),
            Combination::Series if p > 0.0 && q > 0.0 => p * q / (p + q),
            _ => 0.0,
        }
    }
}

/// Brent's stopping rule on `x = ln(delta / h)`: an absolute width of `4 eps` in `x`
/// (relative `4 eps` in `delta`), a cap on iterations.
struct Stop;

impl Convergency<f64> for Stop {
    fn is_root_found(&mut self, y: f64) -> bool {
        y == 0.0
    }
    fn is_converged(&mut self, a: f64, b: f64) -> bool {
        (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs()).max(1.0)
    }
    fn is_iteration_limit_reached(&mut self, iter: usize) -> bool {
        iter > ROOT_MAX_ITER
    }
}

fn no_convergence(what: &'static str) -> Error {
    Error::NoConvergence {
        what,
        iterations: ROOT_MAX_ITER as u64,
    }
}

/// The root of `W~` as `(T, N~(T), dW~/dT(T))`, searched as `T = anchor + sign delta` with
/// `delta` in `(0, h)`; `h = inf` for the open interval beyond the longest time (then
/// `sign = +1`). `W~(anchor + sign 0+) = -sign inf`.
fn root(pair: &Pair, c: Combination, anchor: f64, sign: f64, h: f64) -> Result<(f64, f64, f64)> {
    let gaps = pair.gaps(anchor);
    let w_at = |delta: f64| {
        let [p, q, ..] = pair.at(&gaps, sign * delta);
        c.w(p, q)
    };
    // bracket in x = ln(delta / scale): W~ has the sign of `sign` at x_hi, the opposite at x_lo
    let scale = if h.is_finite() { h } else { anchor };
    let f = |x: f64| sign * w_at(scale * x.exp());
    let mut x_hi = 0.0;
    if !h.is_finite() {
        let mut steps = 0;
        while !(f(x_hi) > 0.0) {
            steps += 1;
            if steps > BRACKET_STEPS {
                return Err(no_convergence(
                    "relaxation time beyond the longest (bracket)",
                ));
            }
            x_hi += 5.0;
        }
    }
    let mut x_lo = x_hi - 40.0;
    let mut steps = 0;
    while !(f(x_lo) < 0.0) {
        steps += 1;
        if steps > BRACKET_STEPS || scale * (x_lo - 40.0).exp() == 0.0 {
            return Err(no_convergence("relaxation time near a pole (bracket)"));
        }
        x_lo -= 40.0;
    }
    let x = find_root_brent(x_lo, x_hi, f, &mut Stop)
        .map_err(|_| no_convergence("relaxation time (Brent)"))?;
    let mut delta = scale * x.exp();
    // one Newton step in delta, kept when it stays inside the bracket and lowers |W~|
    let [p, q, dp, dq] = pair.at(&gaps, sign * delta);
    let (w, dw) = (c.w(p, q), c.w(dp, dq));
    let next = delta - sign * w / dw;
    if next > scale * x_lo.exp() && next < scale * x_hi.exp() && w_at(next).abs() < w.abs() {
        delta = next;
    }
    let [p, q, dp, dq] = pair.at(&gaps, sign * delta);
    Ok((anchor + sign * delta, c.n(p, q), c.w(dp, dq)))
}

/// The Prony series of `N/W` for the inputs `pair` (module docs).
fn combine(pair: &Pair, c: Combination, relaxed: f64) -> Result<Prony> {
    let mut terms: Vec<PronyTerm> = Vec::with_capacity(2 * pair.times.len());
    for t in &pair.times {
        let m = c.at_pole(t.p, t.q);
        if m > 0.0 {
            terms.push(PronyTerm {
                coefficient: m,
                tau: t.tau,
            });
        }
    }
    let n = pair.times.len();
    // both inputs relax to zero: W~ tends to 0 beyond the longest time and has no root there
    let roots = if c.w(pair.p_inf, pair.q_inf) == 0.0 {
        n.saturating_sub(1)
    } else {
        n
    };
    for k in 0..roots {
        let lo = pair.times[k].tau;
        let (t, num, dw) = if k + 1 < n {
            let hi = pair.times[k + 1].tau;
            let h = 0.5 * (hi - lo);
            let gaps = pair.gaps(lo);
            let [p, q, ..] = pair.at(&gaps, h);
            if c.w(p, q) > 0.0 {
                root(pair, c, lo, 1.0, h)?
            } else {
                root(pair, c, hi, -1.0, h)?
            }
        } else {
            root(pair, c, lo, 1.0, f64::INFINITY)?
        };
        let m = -num / (t * dw);
        if !(m.is_finite() && t.is_finite() && t > 0.0) {
            return Err(Error::NonFinite {
                what: "relaxation modulus at a root (theory::poles)",
                value: m,
            });
        }
        if m > 0.0 {
            terms.push(PronyTerm {
                coefficient: m,
                tau: t,
            });
        }
    }
    terms.sort_by(|a, b| a.tau.total_cmp(&b.tau));
    let mut merged: Vec<PronyTerm> = Vec::with_capacity(terms.len());
    for t in terms {
        match merged.last_mut() {
            Some(last) if last.tau == t.tau => last.coefficient += t.coefficient,
            _ => merged.push(t),
        }
    }
    let out = Prony {
        relaxed,
        terms: merged,
    };
    out.validate()?;
    Ok(out)
}

/// `G_eq(t)` of a general material (Pa, s), by roots in the time domain (module docs).
pub fn equivalent_relaxation(material: &Material) -> Result<Prony> {
    let shear = material.shear();
    let g_inf = shear.g_inf();
    let (k_inf, k_terms): (f64, &[(f64, f64)]) = match material.bulk() {
        BulkRheology::Incompressible => {
            // G_eq = G
            let terms = shear
                .terms()
                .iter()
                .filter(|t| t.0 > 0.0)
                .map(|&(g, tau)| PronyTerm {
                    coefficient: g,
                    tau,
                })
                .collect();
            return Ok(Prony {
                relaxed: g_inf,
                terms,
            });
        }
        BulkRheology::Elastic(k) => (*k, &[]),
        BulkRheology::Prony(p) => (p.k_inf(), p.terms()),
    };
    let relaxed = if g_inf == 0.0 {
        0.0 // a liquid: G_eq relaxes to zero whatever the bulk
    } else {
        g_inf * (3.0 * k_inf + g_inf) / (3.0 * k_inf + 4.0 * g_inf)
    };
    let pair = Pair::new(g_inf, shear.terms(), k_inf, k_terms);
    combine(&pair, Combination::Equivalent, relaxed)
}

/// `G_tot(t)` of two bodies in contact, `1/G_tot = 1/G_A + 1/G_B` in Carson form (Pa, s).
pub fn series(a: &Prony, b: &Prony) -> Result<Prony> {
    a.validate()?;
    b.validate()?;
    let pairs =
        |p: &Prony| -> Vec<(f64, f64)> { p.terms.iter().map(|t| (t.coefficient, t.tau)).collect() };
    let relaxed = if a.relaxed == 0.0 || b.relaxed == 0.0 {
        0.0 // a liquid in series relaxes to zero
    } else {
        a.relaxed * b.relaxed / (a.relaxed + b.relaxed)
    };
    let pair = Pair::new(a.relaxed, &pairs(a), b.relaxed, &pairs(b));
    combine(&pair, Combination::Series, relaxed)
}
