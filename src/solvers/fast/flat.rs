//! The flat punch in `fast`: its contact radius never changes, so the force is linear in the
//! indentation history and the impact is a linear ODE, solved here by its modes
//! (docs/theory.md §11).
//!
//! In canonical units (`m = v0 = 1`, punch radius 1, `w = (3/2) d`) the force is
//! `F = 8 (c_inf d + Σ_k c_k S_k)`, `S_k' = d' - λ_k S_k` (`λ_k = 1/tau_k`), and `d'' = -F` from
//! `d(0) = 0`, `d'(0) = 1`. Its Laplace transform is `D(s) = 1 / H(s)` with
//!
//! ```text
//! H(s) = s^2 + 8 (c_inf + Σ_k c_k s / (s + λ_k)),
//! ```
//!
//! so `d(t) = Σ_p e^(p t) / H'(p)` over the `K + 2` roots `p` of `H` (`H'(s) = 2 s + 8 Σ_k c_k
//! λ_k / (s + λ_k)^2`), and `v = Σ p e^(p t) / H'(p)`, `F = -d'' = -Σ p^2 e^(p t) / H'(p)`.
//! With the `λ_k` in increasing order, `H` runs from `-inf` to `+inf` between two successive
//! poles `-λ_(k+1)` and `-λ_k` and from `-inf` to `H(0) = 8 c_inf > 0` on `(-λ_1, 0)`: these `K`
//! real roots are found by safeguarded Newton in their brackets. The two others (the damped
//! oscillation, or two more real roots) are the roots of the quadratic
//! `q(s) = H(s) Π_k (s + λ_k) / (s - p_k)`, read from `q` at `s = 0, ω, 2ω`, and polished by
//! Newton on `H` in complex arithmetic. The initial conditions `Σ 1/H'(p) = 0`,
//! `Σ p / H'(p) = 1` and `Σ p^2 / H'(p) = 0` are then checked: their residual is the error
//! estimate (the solve is refused above `rtol`).
//!
//! Contact ends where the force returns to zero (`F(t_c) = 0`, the first sign change after
//! `t = 0`); the maximum indentation is where `v = 0`, the maximum force where `F' = 0`. Each is
//! bracketed on a grid of 32 points per half period of the oscillating pair (or of its faster
//! real root) and refined by safeguarded Newton on the exact sums.

use nalgebra::Complex;

use super::*;

/// Grid points per half period (`π / |p|` of the slowest-decaying pair) of the brackets.
const FLAT_GRID: f64 = 32.0;
/// Largest number of grid steps before the force returns to zero.
const FLAT_MAX_STEPS: u64 = 1_000_000;
/// Newton iterations of one root.
const FLAT_ROOT_ITER: usize = 200;

/// One mode: the root `p` and `1 / H'(p)`, and its weight (2 for one of a complex pair, which
/// stands for both).
#[derive(Clone, Copy, Debug)]
struct Mode {
    p: Complex<f64>,
    res: Complex<f64>,
    weight: f64,
}

struct Modes {
    c_inf: f64,
    c: Vec<f64>,
    lam: Vec<f64>,
    modes: Vec<Mode>,
    evaluations: u64,
}

impl Modes {
    /// `H(s)` and `H'(s)`.
    fn h(&self, s: Complex<f64>) -> (Complex<f64>, Complex<f64>) {
        let mut g = Complex::new(self.c_inf, 0.0);
        let mut g1 = Complex::new(0.0, 0.0);
        for (c, l) in self.c.iter().zip(&self.lam) {
            let inv = (s + l).inv();
            g += c * s * inv;
            g1 += c * l * inv * inv;
        }
        (s * s + g * 8.0, s * 2.0 + g1 * 8.0)
    }

    fn h_real(&self, s: f64) -> (f64, f64) {
        let (h, h1) = self.h(Complex::new(s, 0.0));
        (h.re, h1.re)
    }

    /// The real root of `H` in `(lo, hi)` where `H(lo+) < 0 < H(hi-)`.
    fn real_root(&self, mut lo: f64, mut hi: f64) -> f64 {
        let mid = |lo: f64, hi: f64| {
            if lo < 0.0 && hi < 0.0 && lo / hi > 4.0 {
                -(lo * hi).sqrt()
            } else {
                0.5 * (lo + hi)
            }
        };
        let mut x = mid(lo, hi);
        for _ in 0..FLAT_ROOT_ITER {
            let (h, h1) = self.h_real(x);
            if h == 0.0 {
                return x;
            }
            if h < 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            let newton = x - h / h1;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                mid(lo, hi)
            };
            if (next - x).abs() <= 1e-16 * x.abs() || hi - lo <= 4.0 * f64::EPSILON * hi.abs() {
                return next;
            }
            x = next;
        }
        x
    }

    /// Newton on `H` from `s` (complex).
    fn polish(&self, mut s: Complex<f64>) -> Complex<f64> {
        for _ in 0..FLAT_ROOT_ITER {
            let (h, h1) = self.h(s);
            let step = h / h1;
            if !step.re.is_finite() || !step.im.is_finite() {
                break;
            }
            s -= step;
            if step.norm() <= 1e-16 * s.norm() {
                break;
            }
        }
        s
    }

    /// `Σ_p w Re(p^j e^(p t) / H'(p))` for `j = 0..=4`: `d`, `v`, `-F`, `-F'`, `-F''`.
    fn sums(&mut self, t: f64) -> [f64; 5] {
        self.evaluations += 1;
        let mut out = [0.0; 5];
        for m in &self.modes {
            let e = (m.p * t).exp() * m.res;
            let mut x = e;
            for o in out.iter_mut() {
                *o += m.weight * x.re;
                x *= m.p;
            }
        }
        out
    }

    /// The root in `[lo, hi]` of `f(t) = sign sums(t)[j]`, which falls through zero there
    /// (`f(lo) > 0 >= f(hi)`), by Newton with `f' = sign sums(t)[j + 1]`, safeguarded by
    /// bisection.
    fn falling_root(&mut self, j: usize, sign: f64, mut lo: f64, mut hi: f64) -> f64 {
        let mut x = 0.5 * (lo + hi);
        for _ in 0..FLAT_ROOT_ITER {
            let s = self.sums(x);
            let (f, f1) = (sign * s[j], sign * s[j + 1]);
            if f > 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            let newton = x - f / f1;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (next - x).abs() <= 1e-15 * x || hi - lo <= 1e-15 * hi {
                return next;
            }
            x = next;
        }
        x
    }
}

/// The impact of the canonical flat punch on `G_eq = c_inf + Σ c_k exp(-t / tau_k)` (`live`:
/// the validated terms `(c_k, tau_k)`), by its modes (module docs). `rtol` bounds the residual
/// of the initial conditions (the error estimate); `history`: the grid points.
///
/// # Errors
/// [`Error::AccuracyNotReached`] when the modes miss the initial conditions by more than
/// `rtol` (a double root, or roots closer than the round-off resolves);
/// [`Error::NoConvergence`] when the force does not return to zero within
/// [`FLAT_MAX_STEPS`] grid steps.
pub(super) fn flat_impact(
    c_inf: f64,
    live: &[(f64, f64)],
    rtol: f64,
    history: bool,
) -> Result<Outcome> {
    let mut terms: Vec<(f64, f64)> = live.iter().map(|&(c, tau)| (c, 1.0 / tau)).collect();
    terms.sort_by(|a, b| a.1.total_cmp(&b.1));
    let mut m = Modes {
        c_inf,
        c: terms.iter().map(|t| t.0).collect(),
        lam: terms.iter().map(|t| t.1).collect(),
        modes: Vec::with_capacity(terms.len() + 2),
        evaluations: 0,
    };
    // the K real roots between the poles and on (-λ_1, 0)
    let k = m.lam.len();
    let real: Vec<f64> = (0..k)
        .map(|i| {
            let hi = if i == 0 { 0.0 } else { -m.lam[i - 1] };
            m.real_root(-m.lam[i], hi)
        })
        .collect();
    // the quadratic q(s) = H(s) Π (s + λ_k) / (s - p_k) = s^2 + b s + c
    let q = |s: f64| {
        let mut v = m.h_real(s).0;
        for (l, p) in m.lam.iter().zip(&real) {
            v *= (s + l) / (s - p);
        }
        v
    };
    let glassy = c_inf + m.c.iter().sum::<f64>();
    let omega = (8.0 * glassy).sqrt();
    let c0 = q(0.0);
    let b = (q(omega) - omega * omega - c0) / omega;
    let disc = b * b - 4.0 * c0;
    let pair: [Complex<f64>; 2] = if disc < 0.0 {
        let z = Complex::new(-0.5 * b, 0.5 * (-disc).sqrt());
        [z, z.conj()]
    } else {
        let r = -0.5 * (b + b.signum() * disc.sqrt());
        [Complex::new(r, 0.0), Complex::new(c0 / r, 0.0)]
    };
    let mut roots: Vec<(Complex<f64>, f64)> =
        real.iter().map(|&p| (Complex::new(p, 0.0), 1.0)).collect();
    if disc < 0.0 {
        let p = m.polish(pair[0]);
        roots.push((p, 2.0));
    } else {
        for z in pair {
            roots.push((m.polish(z), 1.0));
        }
    }
    m.modes = roots
        .iter()
        .map(|&(p, weight)| Mode {
            p,
            res: m.h(p).1.inv(),
            weight,
        })
        .collect();
    // the initial conditions d = 0, v = 1, F = 0 as the error estimate
    let s0 = m.sums(0.0);
    let scale_d: f64 = m.modes.iter().map(|x| x.weight * x.res.norm()).sum();
    let scale_f: f64 = m
        .modes
        .iter()
        .map(|x| x.weight * (x.res * x.p * x.p).norm())
        .sum::<f64>()
        .max(8.0 * glassy);
    let estimate = (s0[0].abs() / scale_d.max(f64::MIN_POSITIVE))
        .max((s0[1] - 1.0).abs())
        .max(s0[2].abs() / scale_f);
    if !(estimate <= rtol) {
        return Err(Error::AccuracyNotReached {
            solver: SOLVER_NAME,
            rtol,
            estimate,
            required: rtol,
            levels: 1,
        });
    }
    // the grid: 32 points per half period of the oscillating pair (or its faster real root)
    let rate = pair
        .iter()
        .map(|p| p.norm())
        .fold(0.0, f64::max)
        .max(1e-300);
    let h = std::f64::consts::PI / (FLAT_GRID * rate);
    let mut hist = history.then(History::default);
    if let Some(hh) = hist.as_mut() {
        hh.push(0.0, 0.0, 1.0, 0.0, 1.0);
    }
    let mut t_prev = 0.0;
    let (mut t_m, mut best) = (None, (0.0, 0.0, 0.0));
    let mut steps = 0u64;
    let t_c = loop {
        steps += 1;
        if steps > FLAT_MAX_STEPS {
            return Err(Error::NoConvergence {
                what: "fast flat punch (the force does not return to zero)",
                iterations: steps,
            });
        }
        let t = t_prev + h;
        let s = m.sums(t);
        if t_m.is_none() && s[1] <= 0.0 {
            t_m = Some(m.falling_root(1, 1.0, t_prev, t));
        }
        // F = -s[2]: the force returns to zero
        if -s[2] <= 0.0 {
            break m.falling_root(2, -1.0, t_prev, t);
        }
        if -s[2] > best.1 {
            best = (t, -s[2], t_prev);
        }
        if let Some(hh) = hist.as_mut() {
            hh.push(t, s[0], s[1], -s[2], 1.0);
        }
        t_prev = t;
    };
    let t_m = t_m.unwrap_or(t_c);
    // the maximum force: F' = -s[3] changes sign around the largest grid force
    let (tb, _, ta) = best;
    let t_f = {
        let lo = ta;
        let hi = (tb + h).min(t_c);
        let (f_lo, f_hi) = (-m.sums(lo)[3], -m.sums(hi)[3]);
        if f_lo > 0.0 && f_hi <= 0.0 {
            m.falling_root(3, -1.0, lo, hi)
        } else {
            tb
        }
    };
    let f_max = -m.sums(t_f)[2];
    let end = m.sums(t_c);
    let d_max = m.sums(t_m)[0];
    let cor = -end[1];
    if let Some(hh) = hist.as_mut() {
        hh.push(t_c, end[0], end[1], 0.0, 1.0);
    }
    Ok(Outcome {
        cor,
        rebound_velocity: cor,
        contact_time: t_c,
        max_indentation: d_max,
        time_of_max_indentation: t_m,
        max_force: f_max,
        max_contact_radius: 1.0,
        dissipated_energy: 0.5 * (1.0 - cor * cor),
        cor_error_estimate: Some(estimate),
        history: hist,
        work: Work {
            steps,
            elements: 0,
            element_updates: 0,
            evaluations: m.evaluations,
            levels: 1,
            tight_checks: 0,
        },
        solver: Method::Fast,
        fallback: None,
    })
}
