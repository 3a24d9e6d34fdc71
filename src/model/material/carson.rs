//! The equivalent incompressible relaxation function of a general linear-viscoelastic solid as an
//! exact Prony series, from the Carson-domain formula (docs/theory.md §2 and §8).
//!
//! In Carson transforms (`s` times Laplace) a term `g exp(-t/tau)` becomes `g s tau / (1 + s tau)`
//! and a constant stays a constant, so `G(s)` and `K(s)` are sums of such terms, and
//!
//! ```text
//! G_eq(s) = G (3K + G) / (3K + 4G) = G / 4 + (9/4) H(s),    H = G K / D,    D = 3K + 4G
//! ```
//!
//! (`1 / G_eq = 1 / G + 1 / (K + G/3)`: the element of Fig. 2 with generalised Maxwell
//! branches). The poles of `G_eq`, all on the negative real axis `s = -1/T`:
//!
//! - a pole `tau` of `G` alone keeps a quarter of its term: `H -> K / 4` stays finite there, so
//!   the term is `g / 4` (the standard solid's `c_a = G_1 / 4`);
//! - a pole of `K` alone cancels: `H -> G / 3` stays finite;
//! - a pole shared by `G` (modulus `g`) and `K` (modulus `k`) is a simple pole of `H` too
//!   (`H ~ ab / ((3b + 4a)(s - p))` with the residues `a`, `b` of `G`, `K`): the term is
//!   `g / 4 + (9/4) g k / (3k + 4g) = g (3k + g) / (3k + 4g)`, the elastic formula on the term;
//! - the zeros of `D` are the new poles. On the real axis `D` is a sum of increasing terms, so
//!   between two consecutive distinct poles of `D` it rises from `-inf` to `+inf`, and between the
//!   slowest pole and `s = 0` from `-inf` to `D(0) = 3 k_inf + 4 g_inf >= 0` (no zero there when
//!   `D(0) = 0`: both moduli relax to zero and `H` vanishes at `s = 0`); left of the fastest
//!   pole it stays above the glassy `3 K_0 + 4 G_0 > 0`. Exactly one zero per distinct pole of
//!   `D`, each bracketed. At a zero `z = -1/T`, `3K = -4G`, so the residue of `H` is
//!   `G K / D'(z) = -(4/3) G^2 / D'(z) <= 0` and the time-domain coefficient is
//!   `c = (9/4) (-G K) / (lambda D'(z)) >= 0` with `lambda = 1/T`.
//!
//! Every coefficient is therefore non-negative: `G_eq(t)` is completely monotone, as a relaxation
//! function must be. (In the degenerate case where `G` and `K` vanish at the same zero of `D` the
//! pole cancels and the coefficient is zero.)
//!
//! The zeros are found one bracket at a time by a safeguarded Newton iteration in `log(-s)`, never
//! through polynomial coefficients or a companion matrix (30 terms over 20 decades would lose
//! every digit there). A zero can sit extremely close to a pole (relative distance
//! `~ 4 g / (3 K_0)` as `K_0 -> inf`), closer than `lambda` itself can resolve; so each zero is
//! written as an offset `y` from the nearer pole of its bracket, `lambda = lambda_a exp(y)`, and
//! every `1 - lambda tau_i` is formed from `y` and `(tau_i - tau_a) / tau_a` without cancellation.
//!
//! The code works on the general composition `H = P Q / (alpha P + beta Q)` of two Carson sums:
//! `P = G`, `Q = K`, `(alpha, beta) = (4, 3)` for [`equivalent_relaxation`], and `P = G_A`,
//! `Q = G_B`, `(1, 1)` for the two-body combination [`combine`] (`1/G_tot = 1/G_A + 1/G_B`).
//!
//! Accuracy (`tests/rheology.rs`): the series reproduces the Carson formula on `s > 0` to
//! `1.3e-15` relative on the test materials (30 terms over 20 decades with a 12-term bulk
//! included) and to `1e-12` on random series (1 to 40 terms, times over 20 decades, moduli over 8);
//! it agrees with the independent Talbot inversion `theory::bromwich` in the time domain to that
//! route's own accuracy (`1e-11` worst, `1e-13` mean).

use super::prony::{Prony, PronyTerm};
use super::rheology::BulkRheology;
use super::Material;
use crate::error::{Error, Result};

/// Iteration cap of the pole finder (one zero of `D`); [`Error::NoConvergence`] beyond.
/// A bracket of positive doubles is halved in bit space by each bisection, so 64 bisections
/// (interleaved with at most as many Newton steps) always suffice.
pub const POLE_MAX_ITER: u64 = 200;

/// Offset `|y|` below which `1 - lambda tau_i` is formed relative to the anchor (see
/// `Context::sample`).
const SPLIT_OFFSET: f64 = 0.5;

/// A distinct pole `s = -1/tau` of `D = alpha P + beta Q`, with the moduli of its terms in `P`
/// and in `Q` (either may be zero, not both). For `G_eq`: `P = G`, `Q = K`, `alpha = 4`,
/// `beta = 3`; for two bodies: `P = G_eq,A`, `Q = G_eq,B`, `alpha = beta = 1`.
#[derive(Debug, Clone, Copy)]
struct Pole {
    tau: f64,
    g: f64,
    k: f64,
}

/// The equivalent incompressible relaxation `G_eq(t) = relaxed + sum_m c_m exp(-t / T_m)` of
/// `material` (docs/theory.md §8; module docs for the derivation), moduli in Pa and times in s.
///
/// - relaxed: `g_inf (3 k_inf + g_inf) / (3 k_inf + 4 g_inf)`;
/// - incompressible bulk: `G_eq = G` (the shear series itself);
/// - elastic shear and bulk: no terms;
/// - otherwise one term per shear term and one per distinct time of `G` and `K` together.
///
/// Terms are sorted by `T`, equal `T` (a zero of `D` closer to a pole than one ulp) merged.
/// Errors: [`Error::NoConvergence`] if a zero of `D` is not found within [`POLE_MAX_ITER`].
pub fn equivalent_relaxation(material: &Material) -> Result<Prony> {
    let shear = material.shear();
    let g_inf = shear.g_inf();
    let (k_inf, bulk_terms): (f64, &[(f64, f64)]) = match material.bulk() {
        BulkRheology::Incompressible => {
            return Ok(Prony {
                relaxed: g_inf,
                terms: shear
                    .terms()
                    .iter()
                    .map(|&(g, tau)| PronyTerm {
                        coefficient: g,
                        tau,
                    })
                    .collect(),
            });
        }
        BulkRheology::Elastic(k) => (*k, &[]),
        BulkRheology::Prony(p) => (p.k_inf(), p.terms()),
    };
    let d0 = 3.0 * k_inf + 4.0 * g_inf;
    // both moduli relax to zero (a liquid with a relaxing bulk): G_eq relaxes to zero too
    let relaxed = if d0 == 0.0 {
        0.0
    } else {
        g_inf * (3.0 * k_inf + g_inf) / (3.0 * k_inf + 4.0 * g_inf)
    };
    let poles = merge(shear.terms(), bulk_terms);
    let mut terms: Vec<(f64, f64)> = Vec::with_capacity(2 * poles.len());
    for p in &poles {
        if p.g > 0.0 {
            let c = if p.k > 0.0 {
                p.g * (3.0 * p.k + p.g) / (3.0 * p.k + 4.0 * p.g)
            } else {
                0.25 * p.g
            };
            terms.push((p.tau, c));
        }
    }
    let ctx = Context {
        poles: &poles,
        g_inf,
        k_inf,
        alpha: 4.0,
        beta: 3.0,
        d0,
    };
    // G_eq = G / 4 + (9/4) H, H = G K / (4G + 3K)
    for m in 0..ctx.brackets() {
        let zero = ctx.zero_after(m)?;
        terms.push((zero.tau, 2.25 * zero.coefficient));
    }
    Ok(Prony {
        relaxed,
        terms: collect_terms(terms),
    })
}

/// The tangential relaxation function of the MDR's tangential foundation (docs/theory.md §14),
/// `G_t(t) / 4` as an exact Prony series (Pa, s), where in Carson transforms
///
/// ```text
/// G_t(s) = (8/3) G (3K + G) / (3K + 2G),      G_t / 4 = G / 3 + G K / (3K + 2G)
/// ```
///
/// is the tangential stiffness per unit length of the 1D foundation (`G* = 4G / (2 - nu)` of
/// an elastic solid; `8G/3` when incompressible). The quarter matches [`equivalent_relaxation`]
/// (`G_eq = E* / 4`), so that an element's tangential force is `8 dx` times the hereditary
/// response of `G_t / 4`, as its normal force is of `G_eq`.
///
/// The composition is `H = P Q / (alpha P + beta Q)` of the module docs with `P = G`, `Q = K`,
/// `(alpha, beta) = (2, 3)`: a time of `G` alone keeps `g / 3`, a time of `K` alone cancels, a
/// shared time keeps the elastic formula on its term, and every zero of `2G + 3K` is a new
/// time with a non-negative coefficient (the argument of the module docs with `(2, 3)`).
///
/// ```
/// # use mdr_impact::model::material::{carson, Material};
/// let m = Material::with_poisson(1.0, 100.0, 1.0, 0.3).unwrap();
/// let gt = carson::tangential_relaxation(&m).unwrap();
/// // relaxed: G* / 4 = G / (2 - nu)
/// assert!((gt.relaxed - 1.0 / 1.7).abs() < 1e-12);
/// ```
pub fn tangential_relaxation(material: &Material) -> Result<Prony> {
    let shear = material.shear();
    let g_inf = shear.g_inf();
    let (k_inf, bulk_terms): (f64, &[(f64, f64)]) = match material.bulk() {
        BulkRheology::Incompressible => {
            return Ok(Prony {
                relaxed: 2.0 / 3.0 * g_inf,
                terms: shear
                    .terms()
                    .iter()
                    .map(|&(g, tau)| PronyTerm {
                        coefficient: 2.0 / 3.0 * g,
                        tau,
                    })
                    .collect(),
            });
        }
        BulkRheology::Elastic(k) => (*k, &[]),
        BulkRheology::Prony(p) => (p.k_inf(), p.terms()),
    };
    let elastic = |g: f64, k: f64| 2.0 / 3.0 * g * (3.0 * k + g) / (3.0 * k + 2.0 * g);
    let relaxed = elastic(g_inf, k_inf);
    let poles = merge(shear.terms(), bulk_terms);
    let mut terms: Vec<(f64, f64)> = Vec::with_capacity(2 * poles.len());
    for p in &poles {
        if p.g > 0.0 {
            let c = if p.k > 0.0 {
                elastic(p.g, p.k)
            } else {
                p.g / 3.0
            };
            terms.push((p.tau, c));
        }
    }
    let ctx = Context {
        poles: &poles,
        g_inf,
        k_inf,
        alpha: 2.0,
        beta: 3.0,
        d0: 2.0 * g_inf + 3.0 * k_inf,
    };
    for m in 0..poles.len() {
        let zero = ctx.zero_after(m)?;
        terms.push((zero.tau, zero.coefficient));
    }
    Ok(Prony {
        relaxed,
        terms: collect_terms(terms),
    })
}

/// Two bodies in contact (docs/theory.md §8): the combined relaxation function `G_tot(t)` with
/// `1 / G_tot(s) = 1 / G_A(s) + 1 / G_B(s)` in Carson transforms (compliances add, as for `E*`),
/// as an exact Prony series; `a` and `b` are the equivalent relaxation functions `G_eq` of the two
/// bodies (Pa, s).
///
/// `G_tot = A B / (A + B)` is the composition `H` of the module docs with `alpha = beta = 1`:
/// a time of `A` alone (or `B` alone) cancels (`G_tot -> B` there); a time shared by a term `a` of
/// `A` and `b` of `B` keeps `a b / (a + b)`; and `A + B`, a sum of terms increasing in `s`, has one
/// zero between consecutive distinct times and one between the slowest and `s = 0`, each a pole of
/// `G_tot` with the coefficient `-A B / (lambda (A + B)') = A^2 / (lambda (A + B)') >= 0`.
/// Relaxed value `a_inf b_inf / (a_inf + b_inf)`; identical bodies give `G / 2`.
///
/// The terms of `a` and `b` may come in any order (sorted, equal times merged). Errors: as
/// [`Prony::validate`] for either input, [`Error::NoConvergence`] as for
/// [`equivalent_relaxation`].
///
/// ```
/// # use mdr_impact::model::material::{carson, Prony, PronyTerm};
/// let g = Prony { relaxed: 1.0, terms: vec![PronyTerm { coefficient: 9.0, tau: 2.0 }] };
/// let two = carson::combine(&g, &g).unwrap();
/// assert!((two.eval(1.0) - 0.5 * g.eval(1.0)).abs() < 1e-14);
/// ```
pub fn combine(a: &Prony, b: &Prony) -> Result<Prony> {
    a.validate()?;
    b.validate()?;
    let normalised = |p: &Prony| -> Vec<(f64, f64)> {
        collect_terms(p.terms.iter().map(|t| (t.tau, t.coefficient)).collect())
            .into_iter()
            .map(|t| (t.coefficient, t.tau))
            .collect()
    };
    let (ta, tb) = (normalised(a), normalised(b));
    let (a0, b0) = (a.relaxed, b.relaxed);
    let relaxed = if a0 + b0 == 0.0 {
        0.0 // two liquids
    } else {
        a0 * b0 / (a0 + b0)
    };
    let poles = merge(&ta, &tb);
    let mut terms: Vec<(f64, f64)> = Vec::with_capacity(2 * poles.len());
    for p in &poles {
        if p.g > 0.0 && p.k > 0.0 {
            terms.push((p.tau, p.g * p.k / (p.g + p.k)));
        }
    }
    let ctx = Context {
        poles: &poles,
        g_inf: a0,
        k_inf: b0,
        alpha: 1.0,
        beta: 1.0,
        d0: a0 + b0,
    };
    for m in 0..ctx.brackets() {
        let zero = ctx.zero_after(m)?;
        terms.push((zero.tau, zero.coefficient));
    }
    Ok(Prony {
        relaxed,
        terms: collect_terms(terms),
    })
}

/// Sort by time, merge equal times, drop zero coefficients.
fn collect_terms(mut terms: Vec<(f64, f64)>) -> Vec<PronyTerm> {
    terms.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out: Vec<PronyTerm> = Vec::with_capacity(terms.len());
    for (tau, c) in terms {
        match out.last_mut() {
            Some(last) if last.tau == tau => last.coefficient += c,
            _ => out.push(PronyTerm {
                coefficient: c,
                tau,
            }),
        }
    }
    out.retain(|p| p.coefficient > 0.0);
    out
}

/// Union of the shear and bulk times (both sorted, distinct), increasing.
fn merge(shear: &[(f64, f64)], bulk: &[(f64, f64)]) -> Vec<Pole> {
    let mut out = Vec::with_capacity(shear.len() + bulk.len());
    let (mut i, mut j) = (0, 0);
    while i < shear.len() || j < bulk.len() {
        let ts = shear.get(i).map_or(f64::INFINITY, |p| p.1);
        let tb = bulk.get(j).map_or(f64::INFINITY, |p| p.1);
        if ts < tb {
            out.push(Pole {
                tau: ts,
                g: shear[i].0,
                k: 0.0,
            });
            i += 1;
        } else if tb < ts {
            out.push(Pole {
                tau: tb,
                g: 0.0,
                k: bulk[j].0,
            });
            j += 1;
        } else {
            out.push(Pole {
                tau: ts,
                g: shear[i].0,
                k: bulk[j].0,
            });
            i += 1;
            j += 1;
        }
    }
    out
}

/// A zero `s = -1/tau` of `D` and the coefficient of its term in `H(t)`,
/// `H = P Q / (alpha P + beta Q)`.
struct Zero {
    tau: f64,
    coefficient: f64,
}

/// `G`, `K`, `D` and `lambda D'(s)` at `lambda = lambda_a exp(y)` (`lambda_a = 1/tau_a`), each
/// multiplied by `scale = lambda tau_a - 1 = expm1(y)` squared or not as noted, so that nothing
/// overflows as `y -> 0`.
struct Sample {
    /// `D` (Pa).
    d: f64,
    /// `dD/dy = -lambda dD/ds` is `-slope`; `slope = sum w_i q_i / d_i^2 > 0` (Pa).
    slope: f64,
    /// `G * d_a` (Pa).
    g_scaled: f64,
    /// `K * d_a` (Pa).
    k_scaled: f64,
    /// `sum |terms of G * d_a|` and `sum |terms of K * d_a|` (Pa): the rounding scale of the two.
    g_abs: f64,
    k_abs: f64,
    /// `slope * d_a^2` (Pa).
    slope_scaled: f64,
}

/// `H = P Q / D`, `D = alpha P + beta Q`, with `P = g_inf + sum g s tau / (1 + s tau)` and
/// `Q = k_inf + sum k s tau / (1 + s tau)` over the poles (names from the `G_eq` case).
struct Context<'a> {
    poles: &'a [Pole],
    g_inf: f64,
    k_inf: f64,
    alpha: f64,
    beta: f64,
    /// `D(0) = alpha g_inf + beta k_inf > 0`.
    d0: f64,
}

impl Context<'_> {
    fn w(&self, p: &Pole) -> f64 {
        self.alpha * p.g + self.beta * p.k
    }

    /// Evaluate at `lambda = exp(y) / tau_a`, anchor `a`.
    ///
    /// With `q_i = lambda tau_i` the Carson term `w s tau_i / (1 + s tau_i)` at `s = -lambda` is
    /// `w q_i / d_i` with `d_i = q_i - 1`, and `d/dy (w q_i / d_i) = -w q_i / d_i^2`
    /// (`lambda dD/ds = sum w q_i / d_i^2`). For the anchor `d_a = expm1(y)` exactly. For the
    /// other poles, all at least as far from `lambda` in `log` as the anchor, `d_i` is formed as
    /// `((tau_i - tau_a) / tau_a) e^y + expm1(y)` while `|y| <= SPLIT_OFFSET` (no cancellation
    /// when `y` is tiny) and as `q_i - 1` beyond (then `|log q_i| >= |y|` bounds the cancellation
    /// by a factor `1 / (1 - exp(-SPLIT_OFFSET))`).
    fn sample(&self, a: usize, y: f64) -> Sample {
        let tau_a = self.poles[a].tau;
        let ey = y.exp();
        let da = y.exp_m1();
        let (mut d, mut slope) = (self.d0, 0.0);
        let (mut gs, mut ks, mut ss) = (self.g_inf * da, self.k_inf * da, 0.0);
        let (mut g_abs, mut k_abs) = (gs.abs(), ks.abs());
        for (i, p) in self.poles.iter().enumerate() {
            let (q, di) = if i == a {
                (ey, da)
            } else if y.abs() <= SPLIT_OFFSET {
                let r = p.tau / tau_a;
                (r * ey, ((p.tau - tau_a) / tau_a) * ey + da)
            } else {
                let q = p.tau / tau_a * ey;
                (q, q - 1.0)
            };
            let w = self.w(p);
            d += w * q / di;
            slope += w * q / (di * di);
            // ratio = d_a / d_i (1 for the anchor)
            let ratio = if i == a { 1.0 } else { da / di };
            gs += p.g * q * ratio;
            ks += p.k * q * ratio;
            g_abs += (p.g * q * ratio).abs();
            k_abs += (p.k * q * ratio).abs();
            ss += w * q * ratio * ratio;
        }
        Sample {
            d,
            slope,
            g_scaled: gs,
            k_scaled: ks,
            g_abs,
            k_abs,
            slope_scaled: ss,
        }
    }

    /// The number of zeros of `D`: one per distinct pole, but none between the slowest pole
    /// and `s = 0` when `D(0) = 0` (both inputs relax to zero): there `D` reaches zero only at
    /// `s = 0`, where `H = P Q / D` vanishes with `P` and `Q` and has no pole.
    fn brackets(&self) -> usize {
        if self.d0 == 0.0 {
            self.poles.len().saturating_sub(1)
        } else {
            self.poles.len()
        }
    }

    /// The zero of `D` between pole `m` and pole `m + 1` (in `lambda`: between `1/tau_{m+1}` and
    /// `1/tau_m`), or between the slowest pole and `lambda = 0` when `m` is the last.
    fn zero_after(&self, m: usize) -> Result<Zero> {
        // Choose the anchor (the nearer pole) and the half-bracket of the offset u = |y|:
        // y = dir * u, dir = +1 when anchored at the slower pole (lambda above it),
        // -1 at the faster one (lambda below it). F(u) = -dir * D rises from -inf at u = 0+.
        let (a, dir, u_max) = if m + 1 < self.poles.len() {
            let half = 0.5 * (self.poles[m + 1].tau / self.poles[m].tau).ln();
            // D at the log-midpoint, anchored at the slower pole m + 1 (y = +half).
            let mid = self.sample(m + 1, half).d;
            if mid < 0.0 {
                (m + 1, 1.0, half) // zero between lambda_{m+1} and the midpoint
            } else {
                (m, -1.0, half) // zero between the midpoint and lambda_m
            }
        } else {
            // Slowest bracket (0, lambda_m): D(lambda) lies between D0 - 2 lambda S and
            // D0 - lambda S (S = sum w tau) for lambda <= lambda_m / 2, so the zero is above
            // min(lambda_m / 2, D0 / (2 S)).
            let s: f64 = self.poles.iter().map(|p| self.w(p) * p.tau).sum();
            let tau_m = self.poles[m].tau;
            let mut u = -(0.5f64.min(self.d0 / (2.0 * s) * tau_m)).ln();
            // Rounding safety: move down until D > 0 there (bounded).
            let mut tries = 0;
            while self.sample(m, -u).d <= 0.0 && tries < 64 {
                u *= 2.0;
                tries += 1;
            }
            (m, -1.0, u)
        };
        let f = |u: f64| {
            let s = self.sample(a, dir * u);
            (-dir * s.d, s.slope)
        };
        let u = solve_offset(f, u_max)?;
        let y = dir * u;
        let s = self.sample(a, y);
        let tau = self.poles[a].tau * (-y).exp();
        // h = -P Q / (lambda D'(s)) with lambda D'(s) = slope; the d_a^2 cancels.
        // At the zero alpha P = -beta Q, so -P Q = (alpha/beta) P^2 = (beta/alpha) Q^2: take the
        // one of P and Q computed with the smaller relative rounding error (when K is huge, K at a
        // zero near a zero of K is a difference of huge terms and -G K would be rounding noise).
        let (gs, ks) = (s.g_scaled, s.k_scaled);
        let minus_pq = if s.g_abs * ks.abs() <= s.k_abs * gs.abs() {
            self.alpha / self.beta * gs * gs
        } else {
            self.beta / self.alpha * ks * ks
        };
        let c = minus_pq / s.slope_scaled;
        Ok(Zero {
            tau,
            coefficient: if c.is_finite() { c } else { 0.0 },
        })
    }
}

/// Root `u > 0` of an increasing `f` with `f(0+) = -inf`, `f(u_max) >= 0` (or taken as the root
/// if rounding says otherwise). `f` returns `(value, derivative)`. Safeguarded Newton: a Newton
/// step that leaves the bracket or shrinks it too slowly is replaced by bisection of the bracket
/// in the bit pattern of the doubles (a geometric bisection across magnitudes, exact in at most 64
/// steps), so the iteration reaches adjacent doubles whatever the scale of the root.
fn solve_offset<F>(mut f: F, u_max: f64) -> Result<f64>
where
    F: FnMut(f64) -> (f64, f64),
{
    let (fhi, _) = f(u_max);
    if !(fhi > 0.0) {
        return Ok(u_max);
    }
    let mut lo = f64::MIN_POSITIVE;
    let (flo, _) = f(lo);
    if !(flo < 0.0) {
        return Ok(lo);
    }
    let mut hi = u_max;
    let mut x = bit_mid(lo, hi);
    let (mut fx, mut dfx) = f(x);
    let mut dx_old = hi - lo;
    for _ in 0..POLE_MAX_ITER {
        if fx == 0.0 {
            return Ok(x);
        }
        if fx < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        if hi.to_bits() - lo.to_bits() <= 1 {
            return Ok(x);
        }
        let newton = x - fx / dfx;
        let slow = (2.0 * fx).abs() > (dx_old * dfx).abs();
        let next = if newton > lo && newton < hi && !slow {
            newton
        } else {
            bit_mid(lo, hi)
        };
        let step = (next - x).abs();
        dx_old = step;
        x = next;
        if step <= 2.0 * f64::EPSILON * x {
            return Ok(x);
        }
        (fx, dfx) = f(x);
    }
    Err(Error::NoConvergence {
        what: "pole of a composed relaxation function (zero of 3K + 4G or of G_A + G_B)",
        iterations: POLE_MAX_ITER,
    })
}

/// Midpoint of two positive doubles in their bit patterns (geometric-like across magnitudes).
fn bit_mid(a: f64, b: f64) -> f64 {
    let (ia, ib) = (a.to_bits(), b.to_bits());
    f64::from_bits(ia + (ib - ia) / 2)
}
