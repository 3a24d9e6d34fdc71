//! The `fast` impact solver: Lee–Radok in compression, Ting/Graham in restitution, on the
//! indentation `d(t)` alone (theory notes §4–§5), with exact exponential kernels.
//!
//! # Why no elements
//! All MDR elements in contact share one rate `u_i' = d'` and leave last-in-first-out
//! (theory notes §5), so the force is a functional of `d(t)` alone. With a Prony series
//! `G_eq(t) = c_inf + Σ_k c_k exp(-t/tau_k)` and canonical units `m = R = v0 = G_inf = 1`:
//!
//! **Compression** (`0 <= t <= t_m`, `d' >= 0`):
//!
//! ```text
//! d' = v,   v' = -F,   F = (16/3) (c_inf w + Σ_k c_k q_k),   w = d^(3/2),
//! q_k(t) = ∫_0^t exp(-(t-s)/tau_k) w'(s) ds,      S_k(t) = ∫_0^t exp(-(t-s)/tau_k) d'(s) ds.
//! ```
//!
//! **Restitution** (`t > t_m`): `t_1(t) ∈ [0, t_m]` is the root of
//! `Φ(t_1) = c_inf (d(t) - d(t_1)) + Σ_k c_k [S_k(t) - exp(-(t-t_1)/tau_k) S_k(t_1)] = 0`
//! (the edge carries no force; `Φ` decreases in `t_1`, `dΦ/dt_1 = -d'(t_1) G_eq(t - t_1)`), and
//! `F = (16/3) [c_inf d(t_1)^(3/2) + Σ_k c_k exp(-(t-t_1)/tau_k) q_k(t_1)]`, the contact radius
//! `a = sqrt(d(t_1))`. Contact ends when `t_1` reaches 0, i.e. `c_inf d + Σ_k c_k S_k = 0`,
//! and `e = -d'(t_end)` (paper Eq. 10). References: Lee & Radok (1960), Ting (1966),
//! Graham (1965); the paper's Eqs. (1)–(3) and (10).
//!
//! # Method
//! Implicit collocation with [`FAST_NODES`] Radau IIA points per step for `d'' = -F`, with the
//! hereditary integrals evaluated **exactly** for the step's polynomial `w` and `d'`
//! (`∫ exp(-(t-s)/tau) d/ds[(s/h)^ν] ds = ν (t/h)^ν Ĵ_ν(t/tau)`, an incomplete gamma
//! function), so that the step follows the dynamics, not `tau` (any `h/tau`, `tau/t_c` down
//! to 1e-12 and below). The first step uses powers of `sqrt(t)`
//! (`d = t + Σ α_j t^(j/2)`, `j >= 5`; `w = t^(3/2) + Σ β_j t^(j/2)`, `j >= 6`), which
//! represents the singular start exactly, including the dashpot limit `F ~ sqrt(t)`.
//! Each step is a small Newton solve on the node values of `d`; in restitution each node
//! also solves for `t_1` on the dense, exact-in-the-kernel output of the compression phase.
//! Step sizes are chosen from the defect of the collocation polynomial at a point between the
//! nodes. The velocity error allowed per step is [`FAST_TOL_FACTOR`]` rtol E`, with `E` the
//! mechanical energy left relative to the impact energy (`E = v^2 + (4/5) F d` in canonical
//! units, `tol_scale`): 1 at the start, `e^2` at the end of contact; in restitution at least
//! `|v|` (`rest_tol_scale`), since an error there passes to the rebound velocity, and
//! [`FAST_REST_TOL_FACTOR`] times larger (only the compression's dense output between the
//! nodes is used again). A fixed absolute
//! tolerance would ask the same of every row while the request is relative to `e`, and errors
//! made while little energy is left weigh most in the final velocity; with the energy scale
//! every CoR down to 5.5e-4 is within `rtol` in one solve (the version before solved a CoR below
//! 0.05 twice). The first step, which holds the initial relaxation layer of every term with
//! `tau_k` below the second node (where the probe point cannot see: its estimate also probes
//! the layer), runs at [`FAST_FIRST_STEP_FACTOR`] of that. In compression, the mismatch between
//! `w` and `d^(3/2)` enters the estimate through `Solver::effective_modulus`, not the glassy
//! modulus (a stiff term responds to it through `tau_k w'` only). The first step's estimate
//! is the largest defect at the middle of every gap between its nodes, and the first
//! restitution step also probes the layer of width `tau_k / 2` after `t_m` that the Ting factor
//! `exp(-(t - t_1)/tau_k)` leaves there (`t - t_1 ≈ 2 (t - t_m)`): a single probe point was
//! measured to sit near a zero of the defect on both steps, with actual errors 5x to 8x rtol. A retry after a rejection
//! uses the order observed between the failed attempts. The end of compression (`v = 0`) is
//! found on the step polynomial. Near the end of contact the force vanishes like `(t_end - t)^(3/2)`, so the
//! defect of a step grows like `h^(S+1) (δ + κ h)^(-7/2)` with the distance `δ` of its end from
//! `t_end` (predicted from `g = c_inf d + Σ c_k S_k` and `dg/dt`): within
//! [`FAST_END_NEAR`] steps of the end the step lengths follow that model, calibrated on the
//! step just accepted, and the last one is planned to reach `t_1 = 0` (then fitted to end
//! there, by the end located on each attempt's polynomial, or by bisection between the longest
//! attempt that stopped short and the shortest that crossed when that leaves them).
//! Newton stops after one correction when an estimate of the next one (compression: a
//! bound from the second derivative of `d^(3/2)`; restitution: the second-order remainder of
//! the force at each node as a function of the shift of `Φ`, `d²F/dΦ² = 4 / (sqrt(d(t_1)) G_eq)`)
//! is below its stop level, first as a bound `h² |A| |remainder|`, then, if that fails, as the
//! correction the remainder causes through the step's Newton system (`remainder_correction`:
//! the bound ignores the damping by `(I + h² A J)^-1`, which is strong where the force is
//! stiff in `d` over the step); a Ting root is taken from one Newton step by the same remainder.
//! In restitution both stops also have absolute floors from the step's velocity tolerance
//! ([`FAST_ROOT_STEP_LEVEL`]; the Newton scale is at least that velocity times the step
//! length), so that the slow tail of a strongly dissipative rebound, where the force is tiny,
//! is not solved far beyond the step's accuracy.
//! The Ting roots start from the polynomial through the last step's node values of `t_1(t)`,
//! in the first Newton pass corrected node by node with the extrapolation error found at the
//! node before; a step's predictor is the last step's polynomial, for the first restitution
//! step the compression step of the turn (the force is `C^1` at `t_m`). That step's length
//! comes from a model of the layer the Ting factor leaves after the turn (`turn_layer_step`)
//! instead of from rejections.
//! The kernel series are truncated at [`FAST_SERIES_LEVEL`]` rtol`, and the kernels of a step's
//! nodes are evaluated together (their series in one loop).
//!
//! # Term state
//! The solver carries O(1) state per Prony term of `G_eq` (`q_k`, `S_k` at a step start, and
//! per compression step their start values for the dense output), and a step costs
//! O(terms): every loop runs over the live terms only. The per-term values live in fixed
//! arrays `[f64; K]` of a capacity class `K ∈ {2, 8, 32, 128}` chosen once per solve
//! (`Solver<K>`, the smallest class that holds the terms; at most [`FAST_MAX_TERMS`]), so the
//! one- and two-term materials keep small stack copies of the state (the dense evaluations of
//! the Ting roots return it by value) while 30 shear terms with a viscoelastic bulk fit. The
//! padding of a class costs only its zero initialisation, at most 4x the live terms.
//! Measured on the 765 external rows at rtol 1e-6 (`XRTOL=1e-6 XREPS=3`, `tests/fast_xcheck.rs`,
//! eight alternating runs, 2026-11-23): median 34.9 to 35.2 us per impact with the single
//! class `[f64; 8]` used before, 33.9 to 34.6 us with the classes (the two-term class), 57 us
//! with one class of 128 for every input (the zeroing and copying of `Pt`, `Seg` and the
//! restitution's per-term tables); 250 evaluations on average and the same results in all.
//!
//! # Verified answers
//! [`impact`] never returns a single solve: it solves at `rtol`, then at `rtol /`
//! [`FAST_CHECK_RATIO`], ... (at most [`FAST_CHECK_LEVELS`] solves) until two successive CoRs
//! agree to `rtol`, and returns the tighter one with their relative difference as
//! `cor_error_estimate`; otherwise it refuses with [`Error::AccuracyNotReached`] and that
//! difference. The difference estimates the error of the looser solve, about
//! [`FAST_CHECK_RATIO`] times the error of the returned one. The sum of the local defects that
//! chooses the steps is no global estimate (66x to thousands of times the error on the
//! external tables, and below the error where the step tolerance's energy floor
//! [`FAST_MIN_TOL_SCALE`] is above the CoR); a CoR below that floor lowers it to `e / 2` and is
//! solved again before any comparison (the floor made CoRs about 1e-5 wrong by 25x `rtol`).
//!
//! # Accuracy and cost (measured 2026-11-22, release build, one core, shared machine)
//! Against the independent Python reference tables (765 groups: the 660-row grid and random
//! set, `nu ∈ [-0.9, 0.5]`, `p2 ∈ [1e-4, 1e2]`, `p3 ∈ [1e-3, 1e4]`, and 105 rows in the most
//! dissipative corner, CoR down to 5.5e-4; reference error <= 1.1e-12): max relative CoR error
//! 8.1e-7 at `rtol = 1e-6` and 6.1e-11 at `rtol = 1e-10`, within `rtol` on every row for every
//! `rtol` from 1e-2 to 1e-11 (`tests/external_reference.rs` checks 1e-4, 1e-6, 1e-8 and 1e-10
//! on every row). On 5000 random groups over the range against the reference solver: within
//! `rtol` from 1e-2 to 1e-9 (5.8e-7 at 1e-6, 5.3e-9 at 1e-8, 7.1e-10 at 1e-9), 5.0e-10 at
//! 1e-10 (that reference is good to about 1e-10 for the smallest CoRs). Against the
//! brute-force integration in `tests/fast_independent.rs`: within 8.3e-10 at `rtol = 1e-8`.
//! `rtol` governs the CoR; the contact time, located where the force vanishes like
//! `(t_end - t)^(3/2)`, is less accurate (at most 1.7e-5 at `rtol = 1e-6` and 2.8e-10 at 1e-10
//! on the external tables, `mdr-impact validate`). No error and no NaN in 330 000 solves of
//! random groups with `p2`, `p3` in `[1e-6, 1e6]` and `nu` in `(-0.99, 0.5]` at every rtol from
//! 1e-2 to 1e-12 (`wide_random_stress` in `tests/fast_core.rs`, ignored).
//! Cost on the 765 external rows (`tests/fast_xcheck.rs`, ignored): 15.7 and 64 steps on
//! average at `rtol = 1e-6` and `1e-10` (26.9 and about 100 with an absolute tolerance and
//! second solves), 104 and 379 history and force evaluations (145 and 452 without the
//! absolute Newton and root floors of the restitution, the node-by-node guesses, the turn
//! layer step and [`FAST_REST_TOL_FACTOR`]; 114 and 382 without `remainder_correction` and
//! [`FAST_END_RECEDE`]), 129 M instructions for the 660 rows of `cor_python.csv` at 1e-6
//! (203 M and 369 M without those restitution changes and the energy-scaled tolerance, all
//! instruction counts by callgrind on that test); on the 114 rows with CoR below 0.1
//! (`XCOR_BELOW=0.1`), 209 evaluations and 46 M instructions (233 and 49 M without
//! `remainder_correction` and [`FAST_END_RECEDE`]).
//! The largest shares are the Ting roots of the restitution (dense evaluations of the
//! compression history), the exact kernels (`exp`, `Ĵ`) and the 5x5 Newton solves.
//! The figures of this section are of one solve at `rtol`, before the verification by a
//! second, tighter solve (see above); `mdr-impact bench` and VALIDATION.md report the
//! verified solver (about 2.4x the work of one solve at 1e-6, errors about 10x below `rtol`).
//!
//! Independent of [`crate::mdr`] and [`crate::theory`]; shares only [`Prony`] with them.

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

mod kernel;
mod linalg;

use std::sync::OnceLock;

use crate::error::{Error, Result};
use crate::impact::{History, Outcome, Work};
use crate::material::Prony;
use crate::tolerances;
use linalg::Mat;

/// Collocation (Radau IIA) nodes per step.
pub const FAST_NODES: usize = 5;
/// Largest number of Prony terms the fast solver accepts (a compressible standard solid has 2;
/// a general material with `n` shear and `m` bulk terms has up to `2n + m`).
pub const FAST_MAX_TERMS: usize = 128;
/// Hard cap on steps (accepted and rejected) of one solve.
pub const FAST_MAX_STEPS: u64 = 20_000;
/// Iteration cap of the Newton solve of one step.
pub const FAST_NEWTON_MAX_ITER: usize = 40;
/// Newton stop level, relative to `rtol` and to the largest increment of `d` over the step:
/// the last correction below it, or an estimate of the next one below it over
/// [`FAST_QUADRATIC_SAFETY`]. The remaining Newton error of a step is then at most about
/// `0.01 rtol` of its velocity change, at most `0.02 rtol` over the impact (impulse `1 + e <= 2`).
/// Measured: the same maximum errors on the external tables (1e-2 to 1e-11) and on 5000 random
/// groups as with the level 1e-4 used before, 24% fewer history evaluations at rtol 1e-6.
pub const FAST_NEWTON_LEVEL: f64 = 0.1;
/// A Ting root is taken from one Newton step once that step is below `sqrt(FAST_ROOT_LEVEL rtol)`
/// of `t_m`, or once the force there, moved to first order, is exact to `FAST_ROOT_LEVEL rtol`
/// relative by its second derivative in the residual of `Φ` (see `Solver::t1_root`): the
/// Newton point is then exact to about `FAST_ROOT_LEVEL rtol` relative in the force, at most
/// about `0.002 rtol` over an impact. Measured: the same maximum errors on the external tables
/// and 5000 random groups as with 1e-4, 4% fewer evaluations at rtol 1e-6 (the step rule), 3%
/// fewer again (the force rule).
pub const FAST_ROOT_LEVEL: f64 = 1e-3;
/// The kernel series (`Ĵ` at the nodes, the dense Taylor polynomials of the compression
/// history) are truncated at this fraction of `rtol`, relative (at least at 1e-17): their
/// terms decay factorially, so the first omitted one bounds the error.
pub const FAST_SERIES_LEVEL: f64 = 1e-5;
/// A Ting root is also taken from one Newton step once the force there, moved to first order,
/// is exact to this fraction of [`FAST_TOL_FACTOR`]` rtol` times the step's velocity scale
/// (`rest_velocity_scale`), divided by the step length (a force error `δF` over a step of
/// length `h` moves the velocity by about `h δF`).
/// The relative rule of [`FAST_ROOT_LEVEL`] alone asked far more where the force is small (the
/// slow tail of a strongly dissipative rebound). Measured: 6% fewer evaluations at rtol 1e-6
/// on the external rows with CoR below 0.1, the same maximum errors.
pub const FAST_ROOT_STEP_LEVEL: f64 = 1e-2;
/// Safety factor of the one-correction Newton stop (`quadratic_done`).
pub const FAST_QUADRATIC_SAFETY: f64 = 10.0;
/// Local error tolerance per step (velocity, in units of `v0`), as a multiple of `rtol` times
/// the energy scale of `tol_scale`.
pub const FAST_TOL_FACTOR: f64 = 2.0;
/// Restitution steps run at this multiple of the tolerance of [`FAST_TOL_FACTOR`]. The
/// estimate is the defect between the nodes, and the compression's dense output between the
/// nodes is used again by every Ting root; the restitution's is not, and at its step ends the
/// collocation is far more accurate than between the nodes. Measured on the external rows and
/// 5000 random groups: the same maximum errors within rtol at every rtol from 1e-2 to 1e-11
/// (8.1e-7 at 1e-6 on the external rows), 7% fewer evaluations at 1e-6 (14% for CoR >= 0.9);
/// at 10 the rows with CoR below 0.05 missed rtol 1e-6 (1.1e-6), while a compression loosened
/// by 3 already missed it (1.9e-6).
pub const FAST_REST_TOL_FACTOR: f64 = 3.0;
/// The first step's tolerance, as a fraction of the others'.
pub const FAST_FIRST_STEP_FACTOR: f64 = 0.1;
/// Tolerance ratio between the successive solves of [`impact`]: each solve's step tolerance is
/// this many times tighter than the one before, and the CoR is returned once two successive
/// solves agree to `rtol`.
pub const FAST_CHECK_RATIO: f64 = 10.0;
/// Largest number of solves of one [`impact`] (the first at `rtol`).
pub const FAST_CHECK_LEVELS: u32 = 4;
/// Tightest step tolerance of a solve (relative, as `rtol`): below it the velocity, integrated
/// from 1 down to `e`, is at the round-off of `f64`.
pub const FAST_MIN_PREC: f64 = 1e-14;
/// Smallest energy scale of the step tolerance (lowered for a CoR below it, see [`impact`]).
pub const FAST_MIN_TOL_SCALE: f64 = 1e-3;
/// Width of the initial relaxation layer of a stiff term, in units of its `tau`, in the
/// first step's error estimate.
pub const FAST_LAYER_WIDTH: f64 = 3.0;
/// The end-of-contact step control takes over within this many step lengths of the end.
pub const FAST_END_NEAR: f64 = 6.0;
/// The end-of-contact step control is skipped after a step at whose end the predicted end of
/// contact moved later by more than this multiple of the step (the linear prediction from `g`
/// and `dg/dt` is then not tracking the end). On strongly dissipative rows it receded by 1.1 to
/// 1.7 steps per step over most of the restitution (e.g. predicted 0.05 to 0.26 ahead for a
/// rebound ending 1.08 after the turn), and the step control shortened every step for it.
/// Measured on the 114 external rows with CoR below 0.1 at rtol 1e-6 (`XCOR_BELOW=0.1` of
/// `tests/fast_xcheck.rs`), together with `remainder_correction`: 29.0 -> 27.9 steps (all
/// attempts of both phases) and 233 -> 209 evaluations on average, the same maximum errors.
pub const FAST_END_RECEDE: f64 = 1.0;
/// `κ` of the end-of-contact error model (see `end_approach`), fitted on the external table.
pub const FAST_END_KAPPA: f64 = 0.3;
/// Iteration cap of the fit of the last step to the end of contact.
pub const FAST_END_MAX_ITER: usize = 60;
/// Hertz contact time in units of the maximum indentation over `v0`:
/// `2 I`, `I = (2/5) B(2/5, 1/2) = 1.4716375921623523` (theory notes §6).
pub const HERTZ_CONTACT_FACTOR: f64 = 2.943_275_184_324_704_7;
/// Name of the solver in an [`Outcome`].
pub const SOLVER_NAME: &str = "fast";

const S: usize = FAST_NODES;
/// Order in `h` assumed for the first retry of a rejected first step (`(S + 2) / 2`).
const FIRST_STEP_ORDER: f64 = (S as f64 + 2.0) / 2.0;
const K16: f64 = 16.0 / 3.0;

// ---------------------------------------------------------------------------------------------
// Collocation tables

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// First step: powers of `sqrt(theta)`.
    First,
    /// Any later step: powers of `theta`.
    Regular,
}

/// Exponents of the free coefficients: `d = dfix + Σ α_j θ^{dexp_j}`, `w = wfix + Σ β_j θ^{wexp_j}`.
fn dexp(kind: Kind, j: usize) -> f64 {
    match kind {
        Kind::First => 2.5 + 0.5 * j as f64,
        Kind::Regular => (j + 2) as f64,
    }
}
fn wexp(kind: Kind, j: usize) -> f64 {
    match kind {
        Kind::First => 3.0 + 0.5 * j as f64,
        Kind::Regular => (j + 1) as f64,
    }
}

/// Powers of `theta`: `θ^{dexp_j}`, `θ^{dexp_j - 1}`, `θ^{dexp_j - 2}`, `θ^{wexp_j}`.
struct Powers {
    d0: [f64; S],
    d1: [f64; S],
    d2: [f64; S],
    w: [f64; S],
    /// `θ^{3/2}` (first step's fixed `w` term).
    w15: f64,
    /// `θ`.
    th: f64,
}

fn powers(kind: Kind, th: f64) -> Powers {
    let mut p = Powers {
        d0: [0.0; S],
        d1: [0.0; S],
        d2: [0.0; S],
        w: [0.0; S],
        w15: 0.0,
        th,
    };
    match kind {
        Kind::Regular => {
            let mut x = 1.0;
            for j in 0..S {
                p.d2[j] = x; // θ^j
                p.d1[j] = x * th; // θ^{j+1}
                p.d0[j] = x * th * th; // θ^{j+2}
                p.w[j] = x * th; // θ^{j+1}
                x *= th;
            }
        }
        Kind::First => {
            let s = th.sqrt();
            p.w15 = th * s;
            let mut x = th * th * s; // θ^{2.5}
            let mut y = th * th * th; // θ^3
            for j in 0..S {
                p.d0[j] = x;
                p.w[j] = y;
                x *= s;
                y *= s;
            }
            // θ^{e-1} = θ^{1.5 + j/2}, θ^{e-2} = θ^{0.5 + j/2}, computed directly (θ may be 0)
            let mut a = th * s;
            let mut b = s;
            for j in 0..S {
                p.d1[j] = a;
                p.d2[j] = b;
                a *= s;
                b *= s;
            }
        }
    }
    p
}

struct Basis {
    /// `c_i^{dexp_j}` and `c_i^{wexp_j}`.
    pd: Mat<S>,
    pw: Mat<S>,
    /// `α = vd_inv (D - dfix)`, `β = vw_inv (W - wfix)`.
    vd_inv: Mat<S>,
    vw_inv: Mat<S>,
    /// Collocation: `D = dfix - h^2 A F`.
    a: Mat<S>,
    /// `A^-1` (the Newton matrix is formed as `A^-1 + h^2 J`).
    a_inv: Mat<S>,
    /// `|A|_inf`.
    a_norm: f64,
}

struct Tables {
    c: [f64; S],
    /// Barycentric weights of the nodes, `1 / Π_(m != j) (c_j - c_m)`.
    bary: [f64; S],
    theta_star: f64,
    reg: Basis,
    first: Basis,
}

fn legendre(n: usize, y: f64) -> f64 {
    let (mut p0, mut p1) = (1.0, y);
    if n == 0 {
        return 1.0;
    }
    for k in 1..n {
        let kf = k as f64;
        let p2 = ((2.0 * kf + 1.0) * y * p1 - kf * p0) / (kf + 1.0);
        p0 = p1;
        p1 = p2;
    }
    p1
}

/// Radau IIA nodes: zeros of `P_S(2x-1) - P_{S-1}(2x-1)` in `(0, 1]`.
fn radau_nodes() -> [f64; S] {
    let f = |x: f64| legendre(S, 2.0 * x - 1.0) - legendre(S - 1, 2.0 * x - 1.0);
    let mut c = [1.0; S];
    let mut n = 0;
    let grid = 4000;
    for g in 0..grid - 1 {
        let (mut a, mut b) = (g as f64 / grid as f64, (g + 1) as f64 / grid as f64);
        let (fa, fb) = (f(a), f(b));
        if fa == 0.0 || fa * fb < 0.0 {
            for _ in 0..200 {
                let m = 0.5 * (a + b);
                if f(a) * f(m) <= 0.0 {
                    b = m;
                } else {
                    a = m;
                }
            }
            if n < S - 1 {
                c[n] = 0.5 * (a + b);
                n += 1;
            }
        }
    }
    c
}

fn build_basis(kind: Kind, c: &[f64; S]) -> Basis {
    let mut pd = [[0.0; S]; S];
    let mut pw = [[0.0; S]; S];
    let mut p2 = [[0.0; S]; S];
    for i in 0..S {
        let p = powers(kind, c[i]);
        for j in 0..S {
            let e = dexp(kind, j);
            pd[i][j] = p.d0[j];
            pw[i][j] = p.w[j];
            p2[i][j] = e * (e - 1.0) * p.d2[j];
        }
    }
    // The tables are fixed and well conditioned; failure here is a programming error.
    let vd_inv = linalg::inverse(&pd).expect("collocation Vandermonde (d) is regular");
    let vw_inv = linalg::inverse(&pw).expect("collocation Vandermonde (w) is regular");
    let a_inv = linalg::mul(&p2, &vd_inv);
    let a = linalg::inverse(&a_inv).expect("collocation matrix is regular");
    Basis {
        pd,
        pw,
        vd_inv,
        vw_inv,
        a_norm: linalg::norm_inf(&a),
        a,
        a_inv,
    }
}

fn tables() -> &'static Tables {
    static T: OnceLock<Tables> = OnceLock::new();
    T.get_or_init(|| {
        let c = radau_nodes();
        // defect probe: the midpoint of the widest gap between 0, c_1, ..., c_S
        let mut theta_star = 0.5 * c[0];
        let mut gap = c[0];
        for i in 1..S {
            if c[i] - c[i - 1] > gap {
                gap = c[i] - c[i - 1];
                theta_star = 0.5 * (c[i] + c[i - 1]);
            }
        }
        let bary = std::array::from_fn(|j| {
            (0..S)
                .filter(|&m| m != j)
                .fold(1.0, |acc, m| acc / (c[j] - c[m]))
        });
        Tables {
            c,
            bary,
            theta_star,
            reg: build_basis(Kind::Regular, &c),
            first: build_basis(Kind::First, &c),
        }
    })
}

// ---------------------------------------------------------------------------------------------
// Kernel values for one (theta, h / tau)

/// `Ĵ` at the exponents of a step: `one` (`ν = 1`, the `v_n h θ` term), `wfix` (`ν = 3/2`,
/// first step), `d[j]` (`ν = dexp_j`), `w[j]` (`ν = wexp_j`).
#[derive(Clone, Copy)]
struct Jt {
    one: f64,
    wfix: f64,
    d: [f64; S],
    w: [f64; S],
}

impl Jt {
    const ZERO: Jt = Jt {
        one: 0.0,
        wfix: 0.0,
        d: [0.0; S],
        w: [0.0; S],
    };
}

/// Kernels of a regular step from `Ĵ_1 ..= Ĵ_(S+1)` (`t[m] = Ĵ_m`, `t[0]` unused).
fn jt_regular(t: &[f64; S + 2]) -> Jt {
    let mut j = Jt::ZERO;
    j.one = t[1];
    j.d.copy_from_slice(&t[2..S + 2]);
    j.w.copy_from_slice(&t[1..S + 1]);
    j
}

/// Kernels of the first step (powers of `sqrt(θ)`) at `x`, the series truncated at `tol`.
fn jt_first(x: f64, tol: f64) -> Jt {
    let kind = Kind::First;
    // integer family 1, 2, ..., S+1 and half-integer family 3/2, 5/2, ..., S+1/2
    let mut fi = [0.0; S + 1];
    let mut fh = [0.0; S + 1];
    kernel::jhat_family(1.0, x, tol, &mut fi);
    kernel::jhat_family(1.5, x, tol, &mut fh);
    let pick = |nu: f64| -> f64 {
        if nu.fract() == 0.0 {
            fi[nu as usize - 1]
        } else {
            fh[(nu - 1.5) as usize]
        }
    };
    let mut j = Jt {
        one: fi[0],
        wfix: fh[0],
        d: [0.0; S],
        w: [0.0; S],
    };
    for k in 0..S {
        j.d[k] = pick(dexp(kind, k));
        j.w[k] = pick(wexp(kind, k));
    }
    j
}

/// The kernels of a step at `x` and `exp(-x)` (from the same evaluation on regular steps); the
/// integer series truncated at `tol` relative.
fn jt_ex(kind: Kind, x: f64, tol: f64) -> (Jt, f64) {
    let (jj, ex) = jt_lanes(kind, &[x], tol);
    (jj[0], ex[0])
}

/// [`jt_ex`] at `L` arguments, e.g. the nodes `x_i = c_i h / tau` of a step: on regular steps
/// in one pass ([`kernel::jhat_int_lanes`]).
fn jt_lanes<const L: usize>(kind: Kind, xs: &[f64; L], tol: f64) -> ([Jt; L], [f64; L]) {
    let mut ex = [0.0; L];
    match kind {
        Kind::Regular => {
            let mut t = [[0.0; S + 2]; L];
            kernel::jhat_int_lanes(xs, tol, &mut t, &mut ex);
            (std::array::from_fn(|i| jt_regular(&t[i])), ex)
        }
        Kind::First => {
            for i in 0..L {
                ex[i] = kernel::exp_neg(xs[i]);
            }
            (std::array::from_fn(|i| jt_first(xs[i], tol)), ex)
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Steps and dense output

/// One step's polynomial representation (compression or restitution).
#[derive(Clone, Copy, Debug)]
struct Seg<const K: usize> {
    t0: f64,
    h: f64,
    kind: Kind,
    /// `d = dn + vh θ + Σ α_j θ^{dexp_j}` (`dn = 0` for the first step).
    dn: f64,
    vh: f64,
    alpha: [f64; S],
    /// Regular: `w_n` (constant term); first step: coefficient of `θ^{3/2}`.
    wfix: f64,
    beta: [f64; S],
    q0: [f64; K],
    s0: [f64; K],
}

/// Dense values at one instant.
#[derive(Clone, Copy, Debug)]
struct Pt<const K: usize> {
    d: f64,
    v: f64,
    dd: f64,
    w: f64,
    q: [f64; K],
    s: [f64; K],
}

/// Largest number of coefficients of a dense kernel polynomial.
const NT: usize = 64;
/// `h / tau` above which the dense output uses the polynomial particular solution.
/// The particular form loses about `log10(Σ_m m! λ^-m |α_m| / |y|)` digits: a few at `λ = 1/2`
/// for the small high-order coefficients; the Taylor form needs ~`15` terms there.
const PARTICULAR_LAMBDA: f64 = 0.5;
/// `h / tau` up to which the first step's kernels have a dense series in `sqrt(θ)`.
const SIGMA_LAMBDA: f64 = 2.0;

/// Dense output of one hereditary integral on a regular step, for fast evaluation at any `θ`:
/// `y(θ) = poly(θ) + amp exp(-λ θ)` with `λ = h / tau`. For `λ <= 1/2` `poly` is the Taylor
/// series of the exact solution (`amp = 0`, terms decay like `λ^n / n!`); for `λ > 1/2` it is
/// the polynomial particular solution `Y = Σ_j (-1/λ)^j (1/λ) P^(j+1)` of
/// `y' = -λ y + P'` and `amp = y(0) - Y(0)`. Both are exact for the step's polynomial `P`.
/// The `n` coefficients (of powers of `θ`, or of `sqrt(θ)` on the first step) are
/// `coef[off..off + n]` of the solver's coefficient store.
#[derive(Clone, Copy, Debug, Default)]
struct KernelPoly {
    lam: f64,
    amp: f64,
    off: usize,
    n: usize,
}

impl KernelPoly {
    /// First step, `λ <= 2`: `y = Σ_n y_n σ^n`, `σ = sqrt(θ)`, `y_n = p_n - (2λ/n) y_(n-2)`,
    /// `y_0 = 0`; `p` holds the forcing's coefficients of `σ^n`. `None` for `λ > 2`.
    fn new_sigma(p: &[f64], lam: f64, coef: &mut Vec<f64>) -> Option<Self> {
        if lam > SIGMA_LAMBDA {
            return None;
        }
        let off = coef.len();
        coef.push(0.0);
        let mut big: f64 = 0.0;
        let mut n = 1;
        while n < NT {
            let pn = if n < p.len() { p[n] } else { 0.0 };
            let prev = if n >= 2 { coef[off + n - 2] } else { 0.0 };
            let cn = pn - 2.0 * lam / n as f64 * prev;
            coef.push(cn);
            big = big.max(cn.abs());
            n += 1;
            if n > p.len()
                && coef[off + n - 1].abs() <= 1e-18 * big
                && coef[off + n - 2].abs() <= 1e-18 * big
            {
                break;
            }
        }
        Some(KernelPoly {
            lam,
            amp: 0.0,
            off,
            n,
        })
    }

    fn new(y0: f64, p: &[f64], lam: f64, trunc: f64, coef: &mut Vec<f64>) -> Self {
        let off = coef.len();
        if lam <= PARTICULAR_LAMBDA {
            coef.push(y0);
            let mut big = y0.abs();
            let mut n = 1;
            while n < NT {
                let pn = if n < p.len() { p[n] } else { 0.0 };
                let cn = (-lam * coef[off + n - 1] + n as f64 * pn) / n as f64;
                coef.push(cn);
                big = big.max(cn.abs());
                n += 1;
                if n >= p.len() && cn.abs() <= trunc * big {
                    break;
                }
            }
            KernelPoly {
                lam,
                amp: 0.0,
                off,
                n,
            }
        } else {
            let eps = 1.0 / lam;
            // derivative coefficients, repeatedly
            let mut c = [0.0; S + 2];
            let mut der = [0.0; S + 2];
            let deg = p.len() - 1;
            for i in 0..deg {
                der[i] = (i + 1) as f64 * p[i + 1];
            }
            let mut len = deg;
            let mut fac = eps;
            while len > 0 {
                for i in 0..len {
                    c[i] += fac * der[i];
                }
                for i in 0..len - 1 {
                    der[i] = (i + 1) as f64 * der[i + 1];
                }
                len -= 1;
                fac *= -eps;
            }
            let n = deg.max(1);
            coef.extend_from_slice(&c[..n]);
            KernelPoly {
                lam,
                amp: y0 - c[0],
                off,
                n,
            }
        }
    }

    /// Value at `θ`; `ex = exp(-λ θ)` (only used when `amp != 0`), `x = θ` or `sqrt(θ)`.
    #[inline]
    fn eval(&self, coef: &[f64], x: f64, ex: f64) -> f64 {
        let mut acc = 0.0;
        for &c in coef[self.off..self.off + self.n].iter().rev() {
            acc = acc * x + c;
        }
        if self.amp != 0.0 {
            acc += self.amp * ex;
        }
        acc
    }
}

struct Solver<const K: usize> {
    rtol: f64,
    /// Smallest energy scale of the step tolerance ([`FAST_MIN_TOL_SCALE`], lowered for a
    /// CoR below it: see [`impact`]).
    min_tol_scale: f64,
    /// Newton step of `t_1` below which the Newton point is taken with first-order updates.
    accept_step: f64,
    /// Absolute force error allowed for a Ting root taken from one Newton step in the current
    /// restitution step ([`FAST_ROOT_STEP_LEVEL`]); 0 outside restitution.
    root_force_tol: f64,
    dense: Vec<[KernelPoly; 2]>,
    /// Coefficient store of the dense kernel polynomials.
    coef: Vec<f64>,
    dense_ok: Vec<bool>,
    c_inf: f64,
    c: [f64; K],
    tau: [f64; K],
    /// `1 / tau_k` (the Ting roots multiply by it).
    inv_tau: [f64; K],
    k: usize,
    glassy: f64,
    tab: &'static Tables,
    comp: Vec<Seg<K>>,
    t_m: f64,
    evaluations: u64,
    /// Compression segment of the last dense evaluation.
    last_seg: usize,
}

/// A Ting root and what the Newton stop of a restitution step needs at it.
#[derive(Clone, Copy, Default)]
struct Root {
    /// `t_1`.
    t1: f64,
    /// Force at the node.
    f: f64,
    /// `d(t_1)`.
    d1: f64,
    /// `d'(t_1)`.
    v1: f64,
    /// `G_eq(t - t_1)`.
    g: f64,
}

/// One converged compression or restitution step.
struct StepOut<const K: usize> {
    seg: Seg<K>,
    f: [f64; S],
    t1: [f64; S],
    a: [f64; S],
    err: f64,
    /// Values at the step end (`θ = 1`, the last Radau node), from the node data.
    end: Pt<K>,
}

impl<const K: usize> Solver<K> {
    /// Relative truncation of the kernel series ([`FAST_SERIES_LEVEL`] of `rtol`).
    fn series_tol(&self) -> f64 {
        (FAST_SERIES_LEVEL * self.rtol).max(1e-17)
    }

    fn basis(&self, kind: Kind) -> &'static Basis {
        match kind {
            Kind::First => &self.tab.first,
            Kind::Regular => &self.tab.reg,
        }
    }

    /// Dense output of a step at `theta` (`with_w`: also `w` and `q_k`).
    fn eval_seg(&self, seg: &Seg<K>, th: f64, with_w: bool) -> Pt<K> {
        let kind = seg.kind;
        let p = powers(kind, th);
        let h = seg.h;
        let (d, v, dd) = seg_poly(seg, &p);
        let (v, dd) = (v / h, dd / (h * h));
        let mut w = 0.0;
        if with_w {
            w = match kind {
                Kind::Regular => seg.wfix,
                Kind::First => seg.wfix * p.w15,
            };
            for j in 0..S {
                w += seg.beta[j] * p.w[j];
            }
        }
        let mut q = [0.0; K];
        let mut s = [0.0; K];
        for k in 0..self.k {
            let x = th * h / self.tau[k];
            let (jj, ex) = jt_ex(kind, x, self.series_tol());
            let mut sk = ex * seg.s0[k] + seg.vh * th * jj.one;
            for j in 0..S {
                sk += seg.alpha[j] * dexp(kind, j) * p.d0[j] * jj.d[j];
            }
            s[k] = sk;
            if with_w {
                let mut qk = ex * seg.q0[k];
                if kind == Kind::First {
                    qk += seg.wfix * 1.5 * p.w15 * jj.wfix;
                }
                for j in 0..S {
                    qk += seg.beta[j] * wexp(kind, j) * p.w[j] * jj.w[j];
                }
                q[k] = qk;
            }
        }
        Pt { d, v, dd, w, q, s }
    }

    /// Dense compression output at `t1 ∈ [0, t_m]`.
    fn comp_at(&mut self, t1: f64) -> Pt<K> {
        self.evaluations += 1;
        // the roots move slowly: try the last segment and its neighbour first
        let n = self.comp.len();
        let inside =
            |i: usize| i < n && self.comp[i].t0 <= t1 && (i + 1 == n || self.comp[i + 1].t0 > t1);
        let hint = self.last_seg;
        let i = if inside(hint) {
            hint
        } else if hint > 0 && inside(hint - 1) {
            hint - 1
        } else {
            self.comp.partition_point(|s| s.t0 <= t1).max(1) - 1
        };
        self.last_seg = i;
        let seg = &self.comp[i];
        let inv_h = 1.0 / seg.h;
        let th = ((t1 - seg.t0) * inv_h).max(0.0);
        if self.dense.len() <= i * self.k || !self.dense_ok[i] {
            return self.eval_seg(seg, th, true);
        }
        if seg.kind == Kind::First {
            let p = powers(Kind::First, th);
            let mut d = seg.vh * th;
            let mut v = seg.vh;
            for j in 0..S {
                let e = dexp(Kind::First, j);
                d += seg.alpha[j] * p.d0[j];
                v += seg.alpha[j] * e * p.d1[j];
            }
            let mut q = [0.0; K];
            let mut s = [0.0; K];
            let sig = th.sqrt();
            for k in 0..self.k {
                let kp = &self.dense[i * self.k + k];
                s[k] = kp[0].eval(&self.coef, sig, 0.0);
                q[k] = kp[1].eval(&self.coef, sig, 0.0);
            }
            return Pt {
                d,
                v: v * inv_h,
                dd: 0.0,
                w: pow15(d),
                q,
                s,
            };
        }
        // regular step: d = dn + vh θ + Σ α_j θ^(j+2), kernels from the precomputed polynomials
        let mut d = 0.0;
        let mut dv = 0.0;
        for j in (0..S).rev() {
            d = d * th + seg.alpha[j];
            dv = dv * th + (j + 2) as f64 * seg.alpha[j];
        }
        let d = seg.dn + th * (seg.vh + th * d);
        let v = (seg.vh + th * dv) * inv_h;
        let mut q = [0.0; K];
        let mut s = [0.0; K];
        for k in 0..self.k {
            let kp = &self.dense[i * self.k + k];
            let ex = if kp[0].amp != 0.0 || kp[1].amp != 0.0 {
                kernel::exp_neg(kp[0].lam * th)
            } else {
                0.0
            };
            s[k] = kp[0].eval(&self.coef, th, ex);
            q[k] = kp[1].eval(&self.coef, th, ex);
        }
        Pt {
            d,
            v,
            dd: 0.0,
            w: pow15(d),
            q,
            s,
        }
    }

    /// Precompute the dense kernel polynomials of the regular compression steps.
    fn build_dense(&mut self) {
        let trunc = self.series_tol();
        let mut dense = Vec::with_capacity(self.comp.len() * self.k);
        let mut ok = Vec::with_capacity(self.comp.len());
        let mut coef = Vec::with_capacity(self.comp.len() * self.k * 24);
        for seg in &self.comp {
            if seg.kind == Kind::First {
                // forcing coefficients of σ^n: d = vh σ^2 + Σ α_j σ^(5+j), w = wfix σ^3 + Σ β_j σ^(6+j)
                let mut ps = [0.0; S + 6];
                ps[2] = seg.vh;
                ps[5..5 + S].copy_from_slice(&seg.alpha);
                let mut pq = [0.0; S + 6];
                pq[3] = seg.wfix;
                pq[6..6 + S].copy_from_slice(&seg.beta);
                let mut good = true;
                for k in 0..self.k {
                    let lam = seg.h / self.tau[k];
                    // both or neither: the same λ
                    match KernelPoly::new_sigma(&ps, lam, &mut coef) {
                        Some(a) => {
                            let b = KernelPoly::new_sigma(&pq, lam, &mut coef)
                                .expect("same λ as the first series");
                            dense.push([a, b]);
                        }
                        None => {
                            good = false;
                            dense.push([KernelPoly::default(); 2]);
                        }
                    }
                }
                ok.push(good);
                continue;
            }
            ok.push(true);
            let mut ps = [0.0; S + 2];
            ps[0] = seg.dn;
            ps[1] = seg.vh;
            ps[2..].copy_from_slice(&seg.alpha);
            let mut pq = [0.0; S + 1];
            pq[0] = seg.wfix;
            pq[1..].copy_from_slice(&seg.beta);
            for k in 0..self.k {
                let lam = seg.h / self.tau[k];
                dense.push([
                    KernelPoly::new(seg.s0[k], &ps, lam, trunc, &mut coef),
                    KernelPoly::new(seg.q0[k], &pq, lam, trunc, &mut coef),
                ]);
            }
        }
        self.dense = dense;
        self.coef = coef;
        self.dense_ok = ok;
    }

    /// Modulus by which a mismatch `δw` of `w` between the nodes of a step of length `h` acts on
    /// the force: `c_inf + Σ_k c_k min(1, 2 (S+1)^2 tau_k / h)`. Through a term it acts as
    /// `∫ exp(-(t-s)/tau_k) δw'(s) ds`: at most `c_k |δw|`, and for `tau_k << h` about
    /// `c_k tau_k |δw'| <= c_k tau_k 2 (S+1)^2 |δw| / h` (Markov's inequality for the step
    /// polynomial; the glassy modulus overstates stiff terms by `h / tau_k`).
    fn effective_modulus(&self, h: f64) -> f64 {
        let markov = 2.0 * ((S + 1) * (S + 1)) as f64;
        let mut g = self.c_inf;
        for k in 0..self.k {
            g += self.c[k] * (markov * self.tau[k] / h).min(1.0);
        }
        g
    }

    /// Defect of a compression step's polynomial at `θ`: `|d'' + F|` plus the mismatch between
    /// `w` and `d^(3/2)` times `geff` ([`Solver::effective_modulus`]).
    fn comp_defect(&self, seg: &Seg<K>, th: f64, geff: f64) -> f64 {
        let pt = self.eval_seg(seg, th, true);
        (pt.dd + self.force_comp(&pt)).abs() + K16 * geff * (pow15(pt.d) - pt.w).abs()
    }

    fn force_comp(&self, pt: &Pt<K>) -> f64 {
        let mut f = self.c_inf * pt.w;
        for k in 0..self.k {
            f += self.c[k] * pt.q[k];
        }
        K16 * f
    }

    /// One compression step of length `h` from `(t0, dn, vn, q0, s0)`.
    #[allow(clippy::too_many_arguments)]
    fn comp_step(
        &mut self,
        kind: Kind,
        t0: f64,
        dn: f64,
        vn: f64,
        q0: &[f64; K],
        s0: &[f64; K],
        h: f64,
        f_n: f64,
        pred: Option<&Seg<K>>,
    ) -> Result<StepOut<K>> {
        let b = self.basis(kind);
        let c = self.tab.c;
        let vh = vn * h;
        let wfix = match kind {
            Kind::Regular => pow15(dn),
            Kind::First => pow15(vh),
        };
        let mut dfix = [0.0; S];
        let mut wfix_n = [0.0; S];
        for i in 0..S {
            dfix[i] = dn + vh * c[i];
            wfix_n[i] = match kind {
                Kind::Regular => wfix,
                Kind::First => wfix * c[i] * c[i].sqrt(),
            };
        }
        // q_i = f0_i / c-weights + M (W - wfix): linear in W
        let mut m = [[0.0; S]; S];
        // Σ_k c_k Ĵ_w at the nodes
        let mut lw = [[0.0; S]; S];
        let mut f0 = [0.0; S];
        // per term at the step end (θ = c_S = 1): kernels, the decayed start values of q and S
        let mut jend = [Jt::ZERO; K];
        let mut qend = [0.0; K];
        let mut send = [0.0; K];
        for k in 0..self.k {
            let ck = self.c[k];
            let (jn, exn) = jt_lanes::<S>(
                kind,
                &std::array::from_fn(|i| c[i] * h / self.tau[k]),
                self.series_tol(),
            );
            for i in 0..S {
                let jj = jn[i];
                let ex = exn[i];
                let mut fi = ex * q0[k];
                if kind == Kind::First {
                    fi += wfix * 1.5 * c[i] * c[i].sqrt() * jj.wfix;
                }
                if i == S - 1 {
                    qend[k] = fi;
                    send[k] = ex * s0[k] + vh * jj.one;
                    jend[k] = jj;
                }
                f0[i] += ck * fi;
                for j in 0..S {
                    lw[i][j] += ck * jj.w[j];
                }
            }
        }
        // M = (L ∘ wexp ∘ P_w) V_w^-1, summed over the terms before the product
        for i in 0..S {
            let mut l = [0.0; S];
            for j in 0..S {
                l[j] = lw[i][j] * wexp(kind, j) * b.pw[i][j];
            }
            for j in 0..S {
                let mut acc = 0.0;
                for (lj, vrow) in l.iter().zip(b.vw_inv.iter()) {
                    acc += lj * vrow[j];
                }
                m[i][j] = acc;
            }
        }
        // unknowns: the increments z_i = d(t_n + c_i h) - dfix_i (no cancellation for small h)
        let regular = kind == Kind::Regular;
        let forces = |z: &[f64; S]| {
            let mut dw = [0.0; S]; // W_i - wfix_i
            let mut w = [0.0; S];
            for i in 0..S {
                let di = (dfix[i] + z[i]).max(0.0);
                w[i] = pow15(di);
                dw[i] = if regular {
                    pow15_increment(dn, vh * c[i] + z[i])
                } else {
                    w[i] - wfix_n[i]
                };
            }
            let mut f = [0.0; S];
            for i in 0..S {
                let mut acc = self.c_inf * w[i] + f0[i];
                for j in 0..S {
                    acc += m[i][j] * dw[j];
                }
                f[i] = K16 * acc;
            }
            (dw, f)
        };
        let h2 = h * h;
        let mut z = [0.0; S];
        for i in 0..S {
            let mut a1 = 0.0;
            for j in 0..S {
                a1 += b.a[i][j];
            }
            z[i] = match pred {
                // extrapolate the previous step's polynomial to the new nodes
                Some(p) => seg_d(p, (t0 + c[i] * h - p.t0) / p.h) - dfix[i],
                None => -h2 * a1 * f_n,
            };
        }
        // modulus of the Newton stop's curvature bound: the largest row sum of c_inf I + |M|
        // (the glassy modulus used before overstated a term relaxing within the step by about
        // h / tau_k)
        let g_step = self.c_inf + linalg::norm_inf(&m);
        let mut prev = f64::INFINITY;
        let mut converged = false;
        for _ in 0..FAST_NEWTON_MAX_ITER {
            self.evaluations += S as u64;
            let (_, f) = forces(&z);
            let af = linalg::mul_vec(&b.a, &f);
            let mut r = [0.0; S];
            for i in 0..S {
                r[i] = -(z[i] + h2 * af[i]);
            }
            // dW_j/dD_j = (3/2) sqrt(D_j)
            let dw: [f64; S] = std::array::from_fn(|j| 1.5 * (dfix[j] + z[j]).max(0.0).sqrt());
            let mut jf = [[0.0; S]; S];
            for i in 0..S {
                for j in 0..S {
                    jf[i][j] = K16 * (m[i][j] + if i == j { self.c_inf } else { 0.0 }) * dw[j];
                }
            }
            let delta = newton_correction(
                &b.a_inv,
                &jf,
                h2,
                r,
                "fast compression step (singular Newton matrix)",
            )?;
            let (dmax, scale) = update(&mut z, &delta);
            if !dmax.is_finite() {
                break;
            }
            // F'' = (3/4) (16/3) G d^(-1/2) at most, G = g_step: the next correction is
            // h^2 A F'' dmax^2 / 2
            let mut dmin = f64::INFINITY;
            for i in 0..S {
                dmin = dmin.min(dfix[i] + z[i]);
            }
            let curv = 0.5 * h2 * 0.75 * K16 * g_step / dmin.max(0.0).sqrt();
            if newton_done(dmax, scale, prev, self.rtol)
                || quadratic_done(dmax, scale, curv, self.rtol)
                || next_correction_done(
                    compression_remainder(&b.a_inv, &jf, h2, &m, self.c_inf, &dfix, &z, &delta),
                    scale,
                    self.rtol,
                )
            {
                converged = true;
                break;
            }
            prev = dmax;
        }
        if !converged {
            return Err(Error::NoConvergence {
                what: "fast compression step (Newton)",
                iterations: FAST_NEWTON_MAX_ITER as u64,
            });
        }
        let (rw, f) = forces(&z);
        let rd = z;
        let seg = Seg {
            t0,
            h,
            kind,
            dn,
            vh,
            alpha: linalg::mul_vec(&b.vd_inv, &rd),
            wfix,
            beta: linalg::mul_vec(&b.vw_inv, &rw),
            q0: *q0,
            s0: *s0,
        };
        // defect of the collocation polynomial between the nodes
        let geff = self.effective_modulus(h);
        let mut err = h * self.comp_defect(&seg, self.tab.theta_star, geff);
        if kind == Kind::First && self.tau[..self.k].iter().any(|&tk| tk < h) {
            // a term relaxing inside the first step: the defect at the middle of every gap
            // between the nodes, not only at the probe, which can sit near a zero of the defect
            // (one row's first step, tau / h = 0.41, was accepted at 0.9 of the tolerance with
            // an actual error of 7e-10 at rtol 1e-10; 6% longer or shorter, its estimate was
            // about 100)
            for i in 1..S {
                err = err.max(h * self.comp_defect(&seg, 0.5 * (c[i - 1] + c[i]), geff));
            }
        }
        if kind == Kind::First {
            // a term relaxing much faster than the step leaves a layer of width tau_k at the
            // start, before the second node, where the probe does not look: its velocity error
            // is about the defect there times the width of the layer (below the first node only,
            // one row at tau / h = 0.075 was accepted at 0.84 of the tolerance with an actual
            // error of about 5x it, 3.6e-8 at rtol 1e-8; the estimate at h 3% longer or shorter
            // was 10-15)
            for k in 0..self.k {
                let th = self.tau[k] / h;
                if th < c[1] {
                    err += FAST_LAYER_WIDTH * self.tau[k] * self.comp_defect(&seg, th, geff);
                }
            }
        }
        let mut a = [0.0; S];
        for i in 0..S {
            a[i] = (dfix[i] + z[i]).max(0.0).sqrt();
        }
        // step end from the last node (θ = 1: every power of θ is 1)
        let mut end = Pt {
            d: dfix[S - 1] + z[S - 1],
            v: vh,
            dd: 0.0,
            w: 0.0,
            q: qend,
            s: send,
        };
        let mut wend = seg.wfix;
        for j in 0..S {
            let (ed, ew) = (dexp(kind, j), wexp(kind, j));
            end.v += seg.alpha[j] * ed;
            wend += seg.beta[j];
            for k in 0..self.k {
                end.s[k] += seg.alpha[j] * ed * jend[k].d[j];
                end.q[k] += seg.beta[j] * ew * jend[k].w[j];
            }
        }
        end.v /= h;
        end.w = wend;
        Ok(StepOut {
            seg,
            f,
            t1: [0.0; S],
            a,
            err,
            end,
        })
    }

    /// Ting/Graham root `t_1` at time `t` with indentation `d` and `S_k(t) = s_k`, with the force
    /// and local derivatives ([`Root`]). `t_1 = 0` (and `F = 0`) once `c_inf d + Σ c_k s_k <= 0`.
    fn t1_root(&mut self, t: f64, d: f64, s: &[f64; K], guess: f64) -> Result<Root> {
        let mut phi0 = self.c_inf * d;
        for k in 0..self.k {
            phi0 += self.c[k] * s[k];
        }
        if phi0 <= 0.0 {
            return Ok(Root::default());
        }
        let tm = self.t_m;
        let (mut lo, mut hi) = (0.0, tm);
        let mut x = if guess > 0.0 && guess < tm {
            guess
        } else {
            0.5 * tm
        };
        let mut hi_checked = false;
        for _ in 0..tolerances::ROOT_MAX_ITER {
            let pt = self.comp_at(x);
            let mut phi = self.c_inf * (d - pt.d);
            let mut g = self.c_inf;
            let mut f = self.c_inf * pt.w;
            for k in 0..self.k {
                let ek = kernel::exp_neg((t - x) * self.inv_tau[k]);
                phi += self.c[k] * (s[k] - ek * pt.s[k]);
                g += self.c[k] * ek;
                f += self.c[k] * ek * pt.q[k];
            }
            let dphi = -pt.v * g;
            let root = |t1: f64, f: f64, d1: f64| Root {
                t1,
                f,
                d1,
                v1: pt.v,
                g,
            };
            if phi > 0.0 {
                lo = x;
                if x == tm || (!hi_checked && hi - x < 1e-15 * tm) {
                    return Ok(root(x, K16 * f, pt.d));
                }
            } else {
                hi = x;
                hi_checked = true;
            }
            let newton = x - phi / dphi;
            let step = (newton - x).abs();
            if step <= 1e-14 * tm || hi - lo <= 1e-14 * tm {
                return Ok(root(x, K16 * f, pt.d));
            }
            let sd = pt.d.max(0.0).sqrt();
            // Accept the Newton point when it is close (`accept_step`), or when the force
            // there, moved to first order, is exact to FAST_ROOT_LEVEL rtol relative or to
            // the step's absolute `root_force_tol`: as a function of the residual Φ = φ the
            // force has d²F/dφ² = 4 / (sqrt(d(t_1)) G_eq) (see rest_step), so the first-order
            // move leaves 2 φ² / (sqrt(d(t_1)) G_eq)
            let f_tol = (FAST_ROOT_LEVEL * self.rtol * K16 * f.abs()).max(self.root_force_tol);
            if newton >= lo
                && newton <= hi
                && (step <= self.accept_step || 2.0 * phi * phi <= f_tol * sd * g)
            {
                // quadratic convergence: the Newton point is exact to ~step^2; move F and d
                // there to first order (dF/dt_1 = (16/3) G_eq(t - t_1) w'(t_1))
                let dx = newton - x;
                let df = K16 * 1.5 * pt.d.max(0.0).sqrt() * pt.v * g;
                return Ok(root(newton, K16 * f + df * dx, pt.d + pt.v * dx));
            }
            x = if newton > lo && newton < hi {
                newton
            } else if !hi_checked && lo > 0.0 {
                // root may sit at t_m itself (right after the turn)
                if lo < tm {
                    0.5 * (lo + hi)
                } else {
                    tm
                }
            } else {
                0.5 * (lo + hi)
            };
        }
        Err(Error::NoConvergence {
            what: "fast Ting root t_1",
            iterations: tolerances::ROOT_MAX_ITER as u64,
        })
    }

    /// One restitution step of length `h`. `t1_guess`: guesses of `t_1` at the nodes;
    /// `omega`: when they come from the polynomial through the last step's nodes, its node
    /// polynomial `Π_j (θ - c_j)` at each node (`θ` in units of that step), to correct the
    /// guesses of the first pass node by node with the error found at the node before.
    #[allow(clippy::too_many_arguments)]
    fn rest_step(
        &mut self,
        t0: f64,
        dn: f64,
        vn: f64,
        s0: &[f64; K],
        h: f64,
        f_n: f64,
        t1_guess: &[f64; S],
        omega: Option<&[f64; S]>,
        pred: Option<&Seg<K>>,
        first: bool,
    ) -> Result<StepOut<K>> {
        let b = &self.tab.reg;
        let c = self.tab.c;
        let vh = vn * h;
        // the velocity scale of the step's tolerance (`rest_velocity_scale`, as in
        // `restitute` but without the energy floor) sets two absolute floors: the force error
        // of a Ting root taken from one Newton step (FAST_ROOT_STEP_LEVEL), and the scale of
        // the Newton stop, at least that velocity times the step length. Relative to the
        // curvature of d alone, as before, the stop asked far more than the step's tolerance
        // where the force is small (the slow tail of a strongly dissipative rebound):
        // measured 9% to 13% fewer evaluations at rtol 1e-6 on the external rows with CoR
        // below 0.1, the same maximum errors at every rtol
        let vel_scale = rest_velocity_scale(vn, f_n, dn);
        self.root_force_tol = FAST_ROOT_STEP_LEVEL * FAST_TOL_FACTOR * self.rtol * vel_scale / h;
        let newton_floor = vel_scale * h;
        let mut dfix = [0.0; S];
        for i in 0..S {
            dfix[i] = dn + vh * c[i];
        }
        // S_{k,i} = sfix_{k,i} + Σ_j L^k_{ij} α_j with the step's coefficients α = V_d^-1 (D - dfix)
        // (N^k = L^k V_d^-1 is never formed); keep C = Σ_k c_k N^k for the Jacobian
        let mut sfix = [[0.0; S]; K];
        let mut lk = [[[0.0; S]; S]; K];
        let mut lc = [[0.0; S]; S];
        for k in 0..self.k {
            let (jn, exn) = jt_lanes::<S>(
                Kind::Regular,
                &std::array::from_fn(|i| c[i] * h / self.tau[k]),
                self.series_tol(),
            );
            for i in 0..S {
                let jj = jn[i];
                sfix[k][i] = exn[i] * s0[k] + vh * c[i] * jj.one;
                for j in 0..S {
                    let l = dexp(Kind::Regular, j) * b.pd[i][j] * jj.d[j];
                    lk[k][i][j] = l;
                    lc[i][j] += self.c[k] * l;
                }
            }
        }
        let cn = linalg::mul(&lc, &b.vd_inv);
        let kk = self.k;
        // S_k at node i from the coefficients α of the step's polynomial
        let s_node = |alpha: &[f64; S], i: usize| {
            let mut si = [0.0; K];
            for k in 0..kk {
                let mut acc = sfix[k][i];
                for j in 0..S {
                    acc += lk[k][i][j] * alpha[j];
                }
                si[k] = acc;
            }
            si
        };
        let h2 = h * h;
        let mut z = [0.0; S];
        for i in 0..S {
            let mut a1 = 0.0;
            for j in 0..S {
                a1 += b.a[i][j];
            }
            z[i] = match pred {
                // extrapolate the previous step's polynomial to the new nodes
                Some(p) => seg_d(p, (t0 + c[i] * h - p.t0) / p.h) - dfix[i],
                None => -h2 * a1 * f_n,
            };
        }
        let mut t1 = *t1_guess;
        let mut f = [0.0; S];
        let mut d1 = [0.0; S];
        let mut roots = [Root::default(); S];
        let mut prev = f64::INFINITY;
        let mut converged = false;
        for it in 0..=FAST_NEWTON_MAX_ITER {
            let alpha = linalg::mul_vec(&b.vd_inv, &z);
            for i in 0..S {
                if let (0, Some(om)) = (it, omega) {
                    // the extrapolation error of the guesses grows like the node polynomial:
                    // move this guess by the error found at the node before, scaled by it
                    // (measured: 8% to 10% fewer evaluations at rtol 1e-6 for CoR below 0.1)
                    if i > 0 && om[i - 1] != 0.0 {
                        let miss = t1[i - 1] - t1_guess[i - 1];
                        t1[i] = (t1_guess[i] + miss * om[i] / om[i - 1]).clamp(0.0, self.t_m);
                    }
                }
                let si = s_node(&alpha, i);
                roots[i] = self.t1_root(t0 + c[i] * h, dfix[i] + z[i], &si, t1[i])?;
                t1[i] = roots[i].t1;
                f[i] = roots[i].f;
                d1[i] = roots[i].d1;
            }
            if converged || it == FAST_NEWTON_MAX_ITER {
                break;
            }
            let af = linalg::mul_vec(&b.a, &f);
            let mut r = [0.0; S];
            for i in 0..S {
                r[i] = -(z[i] + h2 * af[i]);
            }
            let mut jf = [[0.0; S]; S];
            for i in 0..S {
                if t1[i] > 0.0 {
                    let g = 8.0 * d1[i].max(0.0).sqrt();
                    for j in 0..S {
                        jf[i][j] = g * (cn[i][j] + if i == j { self.c_inf } else { 0.0 });
                    }
                }
            }
            let delta = newton_correction(
                &b.a_inv,
                &jf,
                h2,
                r,
                "fast restitution step (singular Newton matrix)",
            )?;
            let (dmax, scale) = update(&mut z, &delta);
            let scale = scale.max(newton_floor);
            if !dmax.is_finite() {
                break;
            }
            // move the guesses of t_1 with the correction to first order:
            // dΦ_i = ψ_i = Σ_j (c_inf δ_ij + Σ_k c_k N^k_ij) δ_j and dΦ/dt_1 = -d'(t_1) G_eq;
            // and the second-order remainder of the forces after this correction, node by
            // node. As a function of the shift ψ of Φ, the force at a node has
            // d²F/dψ² = (3/4) (16/3) / (sqrt(d(t_1)) G_eq(t - t_1)): in
            // F_ψψ = F_t1t1 / Φ_t1² - F_t1 Φ_t1t1 / Φ_t1³ (F_t1 = (16/3) w'(t_1) G_eq,
            // Φ_t1 = -d'(t_1) G_eq, w = d^(3/2)) the terms in d''(t_1) and dG_eq/dt_1 cancel,
            // and with them the 1/d'(t_1)² of a remainder taken in t_1 (which overstated it
            // 4x to several hundred x after the turn, where d'(t_1) -> 0). The next correction
            // is about h^2 |A| F_ψψ ψ^2 / 2.
            let df = linalg::mul_vec(&jf, &delta);
            let mut rem_f = [0.0; S];
            for i in 0..S {
                let r = &roots[i];
                if r.t1 <= 0.0 || r.v1 <= 0.0 || r.g <= 0.0 || r.d1 <= 0.0 {
                    continue; // past the end of contact, or t_1 held at t_m
                }
                let mut psi = self.c_inf * delta[i];
                for j in 0..S {
                    psi += cn[i][j] * delta[j];
                }
                t1[i] = r.t1 + psi / (r.v1 * r.g);
                rem_f[i] = 2.0 * psi * psi / (r.d1.sqrt() * r.g);
            }
            let rem = rem_f.iter().fold(0.0, |acc: f64, &x| acc.max(x));
            converged = newton_done(dmax, scale, prev, self.rtol)
                || next_correction_done(h2 * b.a_norm * rem, scale, self.rtol)
                || next_correction_done(
                    remainder_correction(&b.a_inv, &jf, h2, &rem_f),
                    scale,
                    self.rtol,
                );
            prev = dmax;
            if converged {
                // the last correction is at the accuracy floor: move the forces to first order
                // instead of solving the Ting roots again (t_1, d(t_1) keep an O(delta) lag,
                // used only for guesses and the contact radius of the history)
                for i in 0..S {
                    f[i] += df[i];
                }
                break;
            }
        }
        if !converged {
            return Err(Error::NoConvergence {
                what: "fast restitution step (Newton)",
                iterations: FAST_NEWTON_MAX_ITER as u64,
            });
        }
        let rd = z;
        let seg = Seg {
            t0,
            h,
            kind: Kind::Regular,
            dn,
            vh,
            alpha: linalg::mul_vec(&b.vd_inv, &rd),
            wfix: 0.0,
            beta: [0.0; S],
            q0: [0.0; K],
            s0: *s0,
        };
        let ts = self.tab.theta_star;
        // guess for t_1 at the probe: the polynomial through the node values
        let g = interp_nodes(self.tab, &t1, ts).clamp(0.0, self.t_m);
        let mut err = h * self.rest_defect(&seg, ts, g)?;
        if first {
            // first restitution step: the Ting factor exp(-(t - t_1)/tau_k) with
            // t - t_1 ~ 2 (t - t_m) leaves a layer of width tau_k / 2 after t_m, which the probe
            // does not see when it lies before the second node (without this probe three of
            // 5000 random groups missed rtol 1e-8 / 1e-9 by up to 2x, all from this step)
            for k in 0..self.k {
                let th = 0.5 * self.tau[k] / h;
                if th < c[1] {
                    err += FAST_LAYER_WIDTH
                        * 0.5
                        * self.tau[k]
                        * self.rest_defect(&seg, th, t0 - th * h)?;
                }
            }
        }
        let mut a = [0.0; S];
        for i in 0..S {
            a[i] = d1[i].max(0.0).sqrt();
        }
        // step end from the last node (θ = 1)
        let mut end = Pt {
            d: dfix[S - 1] + z[S - 1],
            v: seg_poly_at(&seg, 1.0).1 / h,
            dd: 0.0,
            w: 0.0,
            q: [0.0; K],
            s: [0.0; K],
        };
        end.s = s_node(&seg.alpha, S - 1);
        Ok(StepOut {
            seg,
            f,
            t1,
            a,
            err,
            end,
        })
    }

    /// Defect `|d'' + F|` of a restitution step's polynomial at `θ` (`guess`: of `t_1` there).
    fn rest_defect(&mut self, seg: &Seg<K>, th: f64, guess: f64) -> Result<f64> {
        let pt = self.eval_seg(seg, th, false);
        let f = self.t1_root(seg.t0 + th * seg.h, pt.d, &pt.s, guess)?.f;
        Ok((pt.dd + f).abs())
    }

    /// `g(θ) = c_inf d + Σ c_k S_k` on a restitution step (contact while `g > 0`).
    fn contact_measure(&self, seg: &Seg<K>, th: f64) -> (f64, Pt<K>) {
        let pt = self.eval_seg(seg, th, false);
        let mut g = self.c_inf * pt.d;
        for k in 0..self.k {
            g += self.c[k] * pt.s[k];
        }
        (g, pt)
    }

    /// Root of `g` in `(0, hi]` by safeguarded Newton, `g(0) > 0 >= g(hi)`;
    /// `dg/dθ = h [c_inf v + Σ_k c_k (v - S_k / tau_k)]` (`S_k' = d' - S_k / tau_k`).
    fn end_root(&self, seg: &Seg<K>, hi: f64, g_hi: f64) -> Result<f64> {
        let g0 = self.contact_measure(seg, 0.0).0;
        let (mut a, mut b) = (0.0, hi);
        // first iterate: the secant through the bracket
        let mut x = (hi * g0) / (g0 - g_hi);
        if !(x > a && x < b) {
            x = 0.5 * (a + b);
        }
        for _ in 0..tolerances::ROOT_MAX_ITER {
            let (gx, pt) = self.contact_measure(seg, x);
            if gx == 0.0 {
                return Ok(x);
            }
            if gx > 0.0 {
                a = x;
            } else {
                b = x;
            }
            let mut dg = self.c_inf * pt.v;
            for k in 0..self.k {
                dg += self.c[k] * (pt.v - pt.s[k] / self.tau[k]);
            }
            dg *= seg.h;
            let newton = x - gx / dg;
            let dx = (newton - x).abs();
            if newton > a && newton < b {
                // quadratic convergence: the Newton point is exact to ~dx^2
                if dx <= 1e-10 * hi {
                    return Ok(newton);
                }
                x = newton;
            } else {
                x = 0.5 * (a + b);
            }
            if b - a <= 1e-15 * hi {
                return Ok(x);
            }
        }
        Err(Error::NoConvergence {
            what: "fast end of contact",
            iterations: tolerances::ROOT_MAX_ITER as u64,
        })
    }
}

/// The polynomial through the node values `ys` of a step at `θ` (any `θ`, also beyond the
/// step): Lagrange form with the tables' barycentric weights and prefix/suffix products of
/// `θ - c_m` (no divisions).
fn interp_nodes(tab: &Tables, ys: &[f64; S], th: f64) -> f64 {
    let mut pre = [1.0; S];
    for j in 1..S {
        pre[j] = pre[j - 1] * (th - tab.c[j - 1]);
    }
    let mut acc = 0.0;
    let mut suf = 1.0;
    for j in (0..S).rev() {
        acc += ys[j] * tab.bary[j] * pre[j] * suf;
        suf *= th - tab.c[j];
    }
    acc
}

/// `(d, dd/dθ, d²d/dθ²)` of a step's polynomial at `θ` from its powers (any `θ >= 0`, also
/// beyond the step for prediction; derivatives per unit `θ`, not per unit time).
fn seg_poly<const K: usize>(seg: &Seg<K>, p: &Powers) -> (f64, f64, f64) {
    let mut d = seg.dn + seg.vh * p.th;
    let mut v = seg.vh;
    let mut a = 0.0;
    for j in 0..S {
        let e = dexp(seg.kind, j);
        d += seg.alpha[j] * p.d0[j];
        v += seg.alpha[j] * e * p.d1[j];
        a += seg.alpha[j] * e * (e - 1.0) * p.d2[j];
    }
    (d, v, a)
}

/// [`seg_poly`] at `θ`; on a regular step by Horner's rule (`d = dn + vh θ + Σ α_j θ^(j+2)`),
/// without the table of powers.
fn seg_poly_at<const K: usize>(seg: &Seg<K>, th: f64) -> (f64, f64, f64) {
    if seg.kind == Kind::First {
        return seg_poly(seg, &powers(Kind::First, th));
    }
    let (mut d, mut v, mut a) = (0.0, 0.0, 0.0);
    for j in (0..S).rev() {
        let e = (j + 2) as f64;
        d = d * th + seg.alpha[j];
        v = v * th + e * seg.alpha[j];
        a = a * th + e * (e - 1.0) * seg.alpha[j];
    }
    (seg.dn + th * (seg.vh + th * d), seg.vh + th * v, a)
}

/// `d` of a step's polynomial at `θ` (see [`seg_poly`]).
fn seg_d<const K: usize>(seg: &Seg<K>, th: f64) -> f64 {
    seg_poly_at(seg, th).0
}

/// `max(x, 0)^(3/2)`.
#[inline]
fn pow15(x: f64) -> f64 {
    let x = x.max(0.0);
    x * x.sqrt()
}

/// `(d + delta)^(3/2) - d^(3/2)` without cancellation for small `delta`.
fn pow15_increment(d: f64, delta: f64) -> f64 {
    let a = (d + delta).max(0.0);
    let b = d.max(0.0);
    let den = a * a.sqrt() + b * b.sqrt();
    let diff = if d >= 0.0 && d + delta >= 0.0 {
        delta
    } else {
        a - b
    };
    if den > 0.0 {
        diff * (a * a + a * b + b * b) / den
    } else {
        0.0
    }
}

/// Newton correction of a collocation step: solve `(I + h^2 A J) delta = r`, with `A` the
/// collocation matrix and `J` the force Jacobian at the nodes, in the equivalent form
/// `(A^-1 + h^2 J) delta = A^-1 r` (no matrix product).
fn newton_correction(
    a_inv: &[[f64; S]; S],
    jf: &[[f64; S]; S],
    h2: f64,
    r: [f64; S],
    what: &'static str,
) -> Result<[f64; S]> {
    linalg::solve(newton_matrix(a_inv, jf, h2), linalg::mul_vec(a_inv, &r)).ok_or(
        Error::NoConvergence {
            what,
            iterations: 0,
        },
    )
}

/// The matrix `A^-1 + h^2 J` of a step's Newton system.
fn newton_matrix(a_inv: &Mat<S>, jf: &Mat<S>, h2: f64) -> Mat<S> {
    let mut jac = *a_inv;
    for (row, jrow) in jac.iter_mut().zip(jf) {
        for (x, j) in row.iter_mut().zip(jrow) {
            *x += h2 * j;
        }
    }
    jac
}

/// Size of the Newton correction that a force remainder `rem_f` (at the nodes) causes:
/// `max |δ|` with `(A^-1 + h^2 J) δ = h^2 rem_f`, the system of [`newton_correction`].
///
/// The bound `h^2 |A| |rem_f|` ignores `(I + h^2 A J)^-1`, which damps the remainder wherever
/// the force is stiff in `d` over the step (`h^2 A J` large). Measured in instrumented solves
/// of the restitution of a strongly dissipative row (CoR 1.6e-3, rtol 1e-6), over steps whose
/// second Newton correction ranged from 0.1 to 30 times the stop level: the bound was 40x to
/// 75x that correction, this estimate within 5% of it. On a compression step of a row with
/// `c_1 = 2500`, `tau_1 = 1e-3`, the glassy-modulus bound used before was about 250x the
/// correction that followed. Infinite if the matrix is singular (no stop).
fn remainder_correction(a_inv: &Mat<S>, jf: &Mat<S>, h2: f64, rem_f: &[f64; S]) -> f64 {
    let rhs = std::array::from_fn(|i| h2 * rem_f[i]);
    match linalg::solve(newton_matrix(a_inv, jf, h2), rhs) {
        Some(d) => d.iter().fold(0.0, |acc: f64, x| acc.max(x.abs())),
        None => f64::INFINITY,
    }
}

/// [`remainder_correction`] of a compression step after the correction `delta` to `z`: the
/// second-order remainder of the forces `(16/3) (c_inf I + M) W'' delta^2 / 2` with
/// `W'' = (3/4) D^(-1/2)` at the nodes `D = dfix + z`.
#[allow(clippy::too_many_arguments)]
fn compression_remainder(
    a_inv: &Mat<S>,
    jf: &Mat<S>,
    h2: f64,
    m: &Mat<S>,
    c_inf: f64,
    dfix: &[f64; S],
    z: &[f64; S],
    delta: &[f64; S],
) -> f64 {
    let w2: [f64; S] = std::array::from_fn(|j| {
        0.375 * delta[j] * delta[j] / (dfix[j] + z[j]).max(f64::MIN_POSITIVE).sqrt()
    });
    let rem_f = std::array::from_fn(|i| {
        let mut acc = c_inf * w2[i];
        for j in 0..S {
            acc += m[i][j] * w2[j];
        }
        K16 * acc
    });
    remainder_correction(a_inv, jf, h2, &rem_f)
}

/// Add a Newton correction; returns `(max |delta|, max |z|)`.
fn update(z: &mut [f64; S], delta: &[f64; S]) -> (f64, f64) {
    let mut dmax: f64 = 0.0;
    let mut scale: f64 = 0.0;
    for i in 0..S {
        z[i] += delta[i];
        dmax = dmax.max(delta[i].abs());
        scale = scale.max(z[i].abs());
    }
    (dmax, scale)
}

/// Newton stop after one small correction: the next one is at most about `curv dmax^2`
/// (`curv` from a bound of the second derivative of the forces); stop when
/// [`FAST_QUADRATIC_SAFETY`] times that is below the stop level of [`newton_done`]
/// (saves the confirming iteration).
fn quadratic_done(dmax: f64, scale: f64, curv: f64, rtol: f64) -> bool {
    let tol = (FAST_NEWTON_LEVEL * rtol).max(1e-14);
    curv.is_finite() && curv * dmax * dmax * FAST_QUADRATIC_SAFETY <= tol * scale
}

/// Newton stop from an estimate `next` of the next correction (the second-order remainder
/// propagated through one collocation solve): [`FAST_QUADRATIC_SAFETY`] times it below the stop
/// level of [`newton_done`].
fn next_correction_done(next: f64, scale: f64, rtol: f64) -> bool {
    let tol = (FAST_NEWTON_LEVEL * rtol).max(1e-14);
    next.is_finite() && next * FAST_QUADRATIC_SAFETY <= tol * scale
}

/// Newton stop: a correction below the stop level ([`FAST_NEWTON_LEVEL`]), or stagnation near
/// rounding level.
fn newton_done(dmax: f64, scale: f64, prev: f64, rtol: f64) -> bool {
    let tol = (FAST_NEWTON_LEVEL * rtol).max(1e-14);
    dmax <= tol * scale || (dmax <= 1e-10 * scale && dmax > 0.3 * prev) || scale == 0.0
}

/// Running maximum of the force with a parabola through the three samples around the peak.
#[derive(Default)]
struct PeakTracker {
    prev: [(f64, f64); 2],
    n: usize,
    max: f64,
}

impl PeakTracker {
    fn push(&mut self, t: f64, f: f64) {
        if self.n >= 2 {
            let (t0, f0) = self.prev[0];
            let (t1, f1) = self.prev[1];
            if f1 >= f0 && f1 >= f && f1 >= self.max && t1 > t0 && t > t1 {
                let d01 = (f1 - f0) / (t1 - t0);
                let d12 = (f - f1) / (t - t1);
                let cc = (d12 - d01) / (t - t0);
                if cc < 0.0 {
                    let bb = d01 + cc * (t1 - t0);
                    self.max = self.max.max(f1 - bb * bb / (4.0 * cc));
                }
            }
        }
        self.max = self.max.max(f);
        self.prev = [self.prev[1], (t, f)];
        self.n += 1;
    }
}

/// Length of the next restitution step near the end of contact, where the force vanishes
/// like `(t_end - t)^(3/2)`: the defect of a step of length `H` ending at distance `δ_e` from the
/// end grows like `H^(S+1) (δ_e + κ H)^(-7/2)` (the `S`-th derivative of the force there). The
/// model is calibrated on the step just accepted (`ratio`, length `h`, ending at distance
/// `delta`); returns the largest `H <= delta` predicted at half the tolerance, and whether it
/// reaches the end (the last step).
fn end_approach(ratio: f64, h: f64, delta: f64) -> (f64, bool) {
    const TARGET: f64 = 0.5;
    let kappa = FAST_END_KAPPA;
    let p = (S + 1) as f64;
    let base = (delta + kappa * h).ln();
    // log of the predicted ratio of a step of length H
    let log_r =
        |hh: f64| ratio.ln() + p * (hh / h).ln() - 3.5 * ((delta - (1.0 - kappa) * hh).ln() - base);
    let goal = TARGET.ln();
    if log_r(delta) <= goal {
        return (delta, true);
    }
    // log_r increases with H: Newton from the right on the convex function
    let mut hh = delta;
    for _ in 0..8 {
        let f = log_r(hh) - goal;
        let df = p / hh + 3.5 * (1.0 - kappa) / (delta - (1.0 - kappa) * hh);
        let next = hh - f / df;
        if !(next > 0.0) {
            hh *= 0.5;
            continue;
        }
        if (next - hh).abs() <= 1e-3 * hh {
            hh = next;
            break;
        }
        hh = next;
    }
    (hh.min(delta), false)
}

/// Model of the layer after the turn in [`turn_layer_step`]: a first restitution step of
/// `x tau_k` misses about `TURN_LAYER_MISS x^10` of the layer's impulse, at most
/// `TURN_LAYER_SATURATION` of it (fitted to the first restitution steps of the external rows at
/// rtol 1e-6: the observed misses rise from about 1e-7 at `x = 1` to 3e-3 at `x = 2.6` and stay
/// near 0.003 to 0.01 beyond; the coefficient is about 8x the fit, to the safe side); the step
/// aims at `TURN_LAYER_TARGET` of its tolerance.
const TURN_LAYER_MISS: f64 = 1e-6;
const TURN_LAYER_SATURATION: f64 = 0.008;
const TURN_LAYER_TARGET: f64 = 0.3;

/// Length of the first restitution step: `h` (the last full compression step), shortened for
/// the layer of width `tau_k / 2` that the Ting factor `exp(-(t - t_1)/tau_k)` leaves after the
/// turn (`t - t_1 ≈ 2 (t - t_m)` there). Its impulse is about `(16/3) |c_k q_k(t_m)| tau_k / 2`,
/// `λ_k` times the velocity tolerance `tol` (the compression's, which the model was fitted
/// with: a third of the restitution's, to the safe side); a term whose layer can fail the step
/// (`λ_k TURN_LAYER_SATURATION > TURN_LAYER_TARGET`) limits the step to `x tau_k` with
/// `λ_k TURN_LAYER_MISS x^10 = TURN_LAYER_TARGET`. Before, the step was found by rejections,
/// about 35 evaluations each: 1.6 per impact with CoR below 0.01 and 1.2 for CoR in
/// `[0.01, 0.1)`, now 0.5 and 0.3 (rtol 1e-6, external rows; 0.2 and 0.04 together with
/// [`FAST_REST_TOL_FACTOR`]).
fn turn_layer_step<const K: usize>(s: &Solver<K>, h: f64, q_m: &[f64; K], tol: f64) -> f64 {
    let mut h = h;
    for k in 0..s.k {
        let lam = K16 * (s.c[k] * q_m[k]).abs() * 0.5 * s.tau[k] / tol;
        if lam * TURN_LAYER_SATURATION > TURN_LAYER_TARGET {
            let x = (TURN_LAYER_TARGET / (TURN_LAYER_MISS * lam)).powf(0.1);
            h = h.min(x * s.tau[k]);
        }
    }
    h
}

/// Step size after a rejected step. The first retry assumes the nominal order (`h^(S+1)`);
/// a second one at the same time uses the order observed between the two failed attempts
/// (boundary layers and the end of contact reduce it), clamped to `[1, S + 1]`.
#[derive(Default)]
struct Retry {
    last: Option<(f64, f64)>,
}

impl Retry {
    fn next(&mut self, h: f64, ratio: f64) -> f64 {
        self.next_order(h, ratio, S as f64 + 1.0)
    }

    fn next_order(&mut self, h: f64, ratio: f64, order: f64) -> f64 {
        let nominal = h * step_factor_order(ratio, order);
        let next = match self.last {
            Some((h0, r0)) if h0 > h && r0 > ratio && ratio.is_finite() => {
                let p = ((r0 / ratio).ln() / (h0 / h).ln()).clamp(1.0, S as f64 + 1.0);
                (h * (0.5 / ratio).powf(1.0 / p)).clamp(0.2 * h, nominal)
            }
            _ => nominal,
        };
        self.last = Some((h, ratio));
        next
    }
}

fn step_factor(ratio: f64) -> f64 {
    step_factor_order(ratio, S as f64 + 1.0)
}

/// Step-size factor for an error ratio (estimate over tolerance) that grows like `h^order`:
/// `0.9 ratio^(-1/order)` within `[0.2, 2]`.
fn step_factor_order(ratio: f64, order: f64) -> f64 {
    if ratio <= 0.0 || !ratio.is_finite() {
        return if ratio <= 0.0 { 3.0 } else { 0.2 };
    }
    (0.9 * ratio.powf(-1.0 / order)).clamp(0.2, 2.0)
}

/// Impact of the unit sphere (`m = R = v0 = 1`) on a half-space with the equivalent
/// relaxation function `prony` (moduli in units of `G_inf`, times in units of `L / v0`),
/// solved by Lee–Radok / Ting–Graham on `d(t)` (see the module docs).
///
/// `rtol` is the requested relative accuracy of the CoR (`MIN_RTOL <= rtol <= MAX_RTOL` of
/// [`crate::tolerances`]); `history` asks for `(t, d, v, F, a)` at the step ends. The outcome
/// is canonical: `rebound_velocity = cor`, `dissipated_energy = (1 - e^2)/2`,
/// `max_contact_radius = sqrt(d_max)`, solver `"fast"`. The CoR is verified (module docs,
/// "Verified answers"): `cor_error_estimate` is the relative difference from the solve at a
/// [`FAST_CHECK_RATIO`] times looser tolerance, always `<= rtol`; `max_force` is the largest
/// node force, refined by a parabola through its neighbours; `work.steps` counts attempted
/// steps and `work.evaluations` force and history evaluations of all solves, `work.levels`
/// the solves.
///
/// Elastic input (no Prony terms) is answered in closed form (Hertz, theory notes §6):
/// `k = (16/3) c_inf`, `d_max = (5/(4k))^(2/5)`, `t_c = 2.9432751843247047 d_max`, `e = 1`.
///
/// ```
/// # use mdr_impact::{Prony, fast};
/// let hertz = Prony { relaxed: 1.0, terms: vec![] };
/// let out = fast::impact(&hertz, 1e-6, false).unwrap();
/// assert_eq!(out.cor, 1.0);
/// // d_max = (15/64)^(2/5) for c_inf = 1
/// assert!((out.max_indentation - (15.0f64 / 64.0).powf(0.4)).abs() < 1e-15);
/// ```
///
/// # Errors
/// [`Error::OutOfRange`] for a bad `rtol` or series (non-finite, `c_inf <= 0`, negative
/// coefficient or time, more than [`FAST_MAX_TERMS`] terms); [`Error::AccuracyNotReached`]
/// when no two successive solves agree to `rtol` (with the last difference);
/// [`Error::NoConvergence`] / [`Error::WorkLimit`] when every solve stopped on a bounded
/// iteration.
pub fn impact(prony: &Prony, rtol: f64, history: bool) -> Result<Outcome> {
    if !(tolerances::MIN_RTOL..=tolerances::MAX_RTOL).contains(&rtol) {
        return Err(Error::OutOfRange {
            field: "rtol",
            value: rtol,
            allowed: "MIN_RTOL <= rtol <= MAX_RTOL (1e-12 ..= 0.1)",
        });
    }
    if !(prony.relaxed > 0.0 && prony.relaxed.is_finite()) {
        return Err(Error::OutOfRange {
            field: "relaxed modulus",
            value: prony.relaxed,
            allowed: "0 < c_inf < inf",
        });
    }
    let mut c_inf = prony.relaxed;
    let mut live: Vec<(f64, f64)> = Vec::with_capacity(prony.terms.len());
    for term in &prony.terms {
        if !(term.coefficient >= 0.0 && term.coefficient.is_finite()) {
            return Err(Error::OutOfRange {
                field: "prony coefficient",
                value: term.coefficient,
                allowed: "0 <= c_k < inf",
            });
        }
        if !(term.tau >= 0.0) {
            return Err(Error::OutOfRange {
                field: "prony tau",
                value: term.tau,
                allowed: "0 <= tau_k <= inf",
            });
        }
        if term.coefficient == 0.0 || term.tau == 0.0 {
            continue; // relaxes instantly or carries nothing
        }
        if term.tau.is_infinite() {
            c_inf += term.coefficient; // never relaxes: part of the elastic modulus
            continue;
        }
        live.push((term.coefficient, term.tau));
    }
    if live.len() > FAST_MAX_TERMS {
        return Err(Error::OutOfRange {
            field: "prony terms",
            value: live.len() as f64,
            allowed: "at most FAST_MAX_TERMS = 128 terms",
        });
    }
    // the per-term state lives in arrays of the smallest capacity class that holds the live
    // terms (module docs, "Term state"): every loop runs over the live terms only
    match live.len() {
        0 => Ok(hertz(c_inf, history)),
        1..=2 => solve_terms::<2>(c_inf, &live, rtol, history),
        3..=8 => solve_terms::<8>(c_inf, &live, rtol, history),
        9..=32 => solve_terms::<32>(c_inf, &live, rtol, history),
        _ => solve_terms::<FAST_MAX_TERMS>(c_inf, &live, rtol, history),
    }
}

/// [`impact`] for `1 <= live.len() <= K` terms `(c_k, tau_k)` (positive, finite) and the
/// relaxed modulus `c_inf`, with the per-term state in arrays of capacity `K`.
fn solve_terms<const K: usize>(
    c_inf: f64,
    live: &[(f64, f64)],
    rtol: f64,
    history: bool,
) -> Result<Outcome> {
    let k = live.len();
    let mut c = [0.0; K];
    let mut tau = [0.0; K];
    for (j, &(cj, tj)) in live.iter().enumerate() {
        c[j] = cj;
        tau[j] = tj;
    }
    let glassy = c_inf + c[..k].iter().sum::<f64>();
    let mut s = Solver {
        rtol,
        min_tol_scale: FAST_MIN_TOL_SCALE,
        accept_step: 0.0,
        root_force_tol: 0.0,
        c_inf,
        c,
        tau,
        inv_tau: std::array::from_fn(|j| if j < k { 1.0 / tau[j] } else { 0.0 }),
        k,
        glassy,
        tab: tables(),
        comp: Vec::with_capacity(64),
        dense: Vec::new(),
        coef: Vec::new(),
        dense_ok: Vec::new(),
        t_m: 0.0,
        evaluations: 0,
        last_seg: 0,
    };
    verified(&mut s, rtol, history)
}

/// One solve at the step tolerance `prec` (see the module docs); its `cor_error_estimate` is the
/// sum of the accepted local defect estimates over `e`.
fn solve_once<const K: usize>(s: &mut Solver<K>, prec: f64, history: bool) -> Result<Outcome> {
    let turn = compress(s, prec, history)?;
    restitute(s, turn, prec)
}

/// The verified solve behind [`impact`]: solves at `rtol`, `rtol / FAST_CHECK_RATIO`, ... (at
/// most [`FAST_CHECK_LEVELS`] solves) until two successive CoRs agree to `rtol` relative, and
/// returns the last (tighter) one with that relative difference as its error estimate.
///
/// The difference estimates the error of the looser of the two solves; with the tolerance
/// proportionality measured on the external tables (maximum error 0.81 `rtol` at every `rtol`
/// from 1e-2 to 1e-11) the returned value is about `FAST_CHECK_RATIO` times more accurate than
/// that. The sum of the local defects (the per-step estimates that choose the steps) is no
/// global estimate: it over-estimates the error 66x to several thousand times, and where the
/// step tolerance cannot follow the CoR (below its energy floor) it was seen below the error.
///
/// A CoR below [`FAST_MIN_TOL_SCALE`] (the step tolerance's energy floor, relative to the
/// impact energy) lowers that floor to `e / 2` for the next solves: the error allowed per step
/// then scales with the velocity left instead of staying at the floor, which gave relative CoR
/// errors of `rtol` times `FAST_MIN_TOL_SCALE / e` (25x `rtol` at `e = 6e-6`).
fn verified<const K: usize>(s: &mut Solver<K>, rtol: f64, history: bool) -> Result<Outcome> {
    let mut steps = 0u64;
    let mut levels = 0u32;
    let mut prev: Option<f64> = None;
    let mut estimate = f64::INFINITY;
    // the last solve's sum of local defects: the refusal's estimate when no two solves compare
    let mut local = f64::INFINITY;
    let mut last_err: Option<Error> = None;
    let mut prec = rtol;
    // solves at one tolerance repeated after the energy floor was lowered (at most 2)
    let mut floor_solves = 0u32;
    while levels < FAST_CHECK_LEVELS && prec >= FAST_MIN_PREC {
        levels += 1;
        match solve_once(s, prec, history) {
            Ok(mut out) => {
                steps += out.work.steps;
                local = out.cor_error_estimate.unwrap_or(f64::INFINITY);
                if out.cor < s.min_tol_scale && floor_solves < 2 {
                    // the floor was active in this solve: it does not count as a check, nor
                    // as one of the FAST_CHECK_LEVELS tolerances
                    s.min_tol_scale = (0.5 * out.cor).max(f64::MIN_POSITIVE);
                    floor_solves += 1;
                    levels -= 1;
                    prev = None;
                    continue;
                }
                if let Some(p) = prev {
                    estimate = ((out.cor - p) / out.cor).abs();
                    if estimate <= rtol {
                        out.cor_error_estimate = Some(estimate);
                        out.work.steps = steps;
                        out.work.evaluations = s.evaluations;
                        out.work.levels = levels + floor_solves;
                        return Ok(out);
                    }
                }
                prev = Some(out.cor);
            }
            // long steps of a loose solve can fail to settle (seen with CoR about 1e-5, p2
            // below 1e-5): the next, tighter solve goes on
            Err(e @ (Error::NoConvergence { .. } | Error::WorkLimit { .. })) => {
                prev = None;
                last_err = Some(e);
            }
            Err(e) => return Err(e),
        }
        prec /= FAST_CHECK_RATIO;
    }
    match (estimate.is_finite(), local.is_finite(), last_err) {
        (false, false, Some(e)) => Err(e),
        (true, ..) | (false, true, _) => Err(Error::AccuracyNotReached {
            solver: SOLVER_NAME,
            rtol,
            estimate: if estimate.is_finite() {
                estimate
            } else {
                local
            },
            required: rtol,
            levels,
        }),
        (false, false, None) => Err(Error::NoConvergence {
            what: "fast: successive solves",
            iterations: u64::from(levels + floor_solves),
        }),
    }
}

/// Scale of the step tolerance at a step start: the mechanical energy left, relative to the
/// impact energy, `E = v^2 + (4/5) F d` (kinetic, plus the Hertz energy `(2/5) F d` of the
/// current force and indentation; canonical units `m = v0 = 1`), at least
/// [`FAST_MIN_TOL_SCALE`]. `E = 1` at the start and `e^2` at the end of contact.
/// `tol_scale` in restitution, at least `|v|`: an error of the velocity near the end of
/// contact passes to the rebound velocity unchanged, so it needs to be small relative to `e`
/// (about `|v|` there), not to `e^2` (5000 random groups at rtol 1e-6: 35.9 instead of 37.7
/// steps for `e < 0.01`, 29.8 instead of 32.1 for `0.01 <= e < 0.05`, same maximum error).
fn rest_tol_scale(v: f64, f: f64, d: f64, floor: f64) -> f64 {
    tol_scale(v, f, d, floor).max(v.abs().min(1.0))
}

/// The velocity scale of [`rest_tol_scale`] without its floor [`FAST_MIN_TOL_SCALE`]
/// (`max(E, |v|)`, at most 1): the Newton and Ting-root floors of a restitution step follow the
/// velocity itself, also where the CoR lies below that floor.
fn rest_velocity_scale(v: f64, f: f64, d: f64) -> f64 {
    let e = (v * v + 0.8 * f * d).max(v.abs());
    if e.is_nan() {
        return 1.0;
    }
    e.min(1.0)
}

fn tol_scale(v: f64, f: f64, d: f64, floor: f64) -> f64 {
    let e = v * v + 0.8 * f * d;
    if e.is_nan() {
        return 1.0; // a non-finite state is reported by the caller
    }
    e.clamp(floor, 1.0)
}

/// Elastic closed form (theory notes §6) in canonical units.
fn hertz(c_inf: f64, history: bool) -> Outcome {
    let k = K16 * c_inf;
    let d_max = (1.25 / k).powf(0.4);
    let tc = HERTZ_CONTACT_FACTOR * d_max;
    Outcome {
        cor: 1.0,
        rebound_velocity: 1.0,
        contact_time: tc,
        max_indentation: d_max,
        time_of_max_indentation: 0.5 * tc,
        max_force: k * d_max.powf(1.5),
        max_contact_radius: d_max.sqrt(),
        dissipated_energy: 0.0,
        cor_error_estimate: Some(0.0),
        history: history.then(|| {
            let mut h = History::default();
            h.push(0.0, 0.0, 1.0, 0.0, 0.0);
            h.push(0.5 * tc, d_max, 0.0, k * d_max.powf(1.5), d_max.sqrt());
            h.push(tc, 0.0, -1.0, 0.0, 0.0);
            h
        }),
        work: Work::default(),
        solver: SOLVER_NAME,
        fallback: None,
    }
}

/// The compression phase of one pass: the state at the time of maximum indentation `t_m`.
struct Turn<const K: usize> {
    t_m: f64,
    d_m: f64,
    v_m: f64,
    s_m: [f64; K],
    f_m: f64,
    /// Length of the first restitution step.
    h: f64,
    steps: u64,
    err_sum: f64,
    hist: Option<History>,
    peak: PeakTracker,
}

/// Compression phase (`0 <= t <= t_m`) with the per-step velocity tolerance `prec * factor`
/// (`prec` also sets the Newton stops); the first step at [`FAST_FIRST_STEP_FACTOR`] of it.
/// Leaves the dense compression output in `s`.
fn compress<const K: usize>(s: &mut Solver<K>, prec: f64, history: bool) -> Result<Turn<K>> {
    let tol = prec * FAST_TOL_FACTOR;
    s.rtol = prec;
    s.comp.clear();
    s.last_seg = 0;
    let mut hist = history.then(History::default);
    if let Some(hh) = hist.as_mut() {
        hh.push(0.0, 0.0, 1.0, 0.0, 0.0);
    }
    let mut peak = PeakTracker::default();
    peak.push(0.0, 0.0);
    let mut steps = 0u64;
    let mut err_sum = 0.0;
    // glassy Hertz time of maximum indentation as the first length scale
    let d0 = (1.25 / (K16 * s.glassy)).powf(0.4);
    let tm0 = 0.5 * HERTZ_CONTACT_FACTOR * d0;
    let mut h = 0.1 * tm0 * (prec / 1e-6).powf(1.0 / (S as f64 + 2.0)).min(1.0);

    // ---- compression
    let (mut t, mut d, mut v, mut f_n) = (0.0_f64, 0.0_f64, 1.0_f64, 0.0_f64);
    let mut q = [0.0; K];
    let mut sk = [0.0; K];
    let mut kind = Kind::First;
    let (t_m, d_m, v_m, s_m, f_m);
    let mut retry = Retry::default();
    let mut h_full = 0.0;
    loop {
        steps += 1;
        if steps > FAST_MAX_STEPS {
            return Err(Error::WorkLimit {
                solver: SOLVER_NAME,
                what: "steps",
                needed: steps,
                limit: FAST_MAX_STEPS,
            });
        }
        let pred = s.comp.last().copied();
        let out = match s.comp_step(kind, t, d, v, &q, &sk, h, f_n, pred.as_ref()) {
            Ok(o) => o,
            Err(Error::NoConvergence { .. }) => {
                h *= 0.25;
                continue;
            }
            Err(e) => return Err(e),
        };
        // the first step is one step: a tighter tolerance there costs little and covers the
        // initial relaxation layers, where the error estimate is least conservative
        let step_tol = match kind {
            Kind::First => tol * FAST_FIRST_STEP_FACTOR,
            Kind::Regular => tol,
        } * tol_scale(v, f_n, d, s.min_tol_scale);
        let ratio = out.err / step_tol;
        if !(ratio <= 1.0) {
            h = match kind {
                // the first step's basis is in powers of sqrt(θ): its error grows with about
                // half the order in h (observed 3.4 between two attempts on one row; 0.57 -> 0.48
                // first-step retries per impact at rtol 1e-6, 1.61 -> 1.35 at 1e-10)
                Kind::First => retry.next_order(h, ratio, FIRST_STEP_ORDER),
                Kind::Regular => retry.next(h, ratio),
            };
            continue;
        }
        retry = Retry::default();
        err_sum += out.err;
        let seg = out.seg;
        let end = out.end;
        if end.v > 0.0 {
            for i in 0..S {
                peak.push(t + s.tab.c[i] * h, out.f[i]);
            }
            s.comp.push(seg);
            t += h;
            d = end.d;
            v = end.v;
            q = end.q;
            sk = end.s;
            f_n = out.f[S - 1];
            if let Some(hh) = hist.as_mut() {
                hh.push(t, d, v, f_n, d.max(0.0).sqrt());
            }
            kind = Kind::Regular;
            h_full = h;
            h *= step_factor(ratio);
            continue;
        }
        // v = 0 inside this step: Newton–bisection on v(θ)
        // (the polynomial alone: the hereditary integrals once, at the root)
        let (mut lo, mut hi) = (0.0, 1.0);
        let mut th = 0.5;
        let (_, mut vt, mut at) = seg_poly_at(&seg, th);
        for it in 0..=tolerances::ROOT_MAX_ITER {
            if it == tolerances::ROOT_MAX_ITER {
                return Err(Error::NoConvergence {
                    what: "fast time of maximum indentation",
                    iterations: it as u64,
                });
            }
            if vt > 0.0 {
                lo = th;
            } else {
                hi = th;
            }
            let newton = th - vt / at;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let done = (next - th).abs() <= 1e-15 || hi - lo <= 1e-15;
            th = next;
            (_, vt, at) = seg_poly_at(&seg, th);
            if done {
                break;
            }
        }
        let pt = s.eval_seg(&seg, th, true);
        for i in 0..S {
            if s.tab.c[i] < th {
                peak.push(t + s.tab.c[i] * h, out.f[i]);
            }
        }
        s.comp.push(seg);
        t_m = t + th * h;
        d_m = pt.d;
        v_m = pt.v;
        s_m = pt.s;
        f_m = s.force_comp(&pt);
        peak.push(t_m, f_m);
        if let Some(hh) = hist.as_mut() {
            hh.push(t_m, d_m, v_m, f_m, d_m.max(0.0).sqrt());
        }
        // restitution starts with the length of the last full compression step, shortened
        // for the relaxation layers after the turn
        h = turn_layer_step(
            s,
            (th * h).max(h_full),
            &pt.q,
            tol * rest_tol_scale(v_m, f_m, d_m, s.min_tol_scale),
        );
        break;
    }
    s.t_m = t_m;
    s.build_dense();
    Ok(Turn {
        t_m,
        d_m,
        v_m,
        s_m,
        f_m,
        h,
        steps,
        err_sum,
        hist,
        peak,
    })
}

/// Restitution phase (`t_m < t <= t_end`) after `turn`, with the per-step velocity tolerance
/// `prec` times [`FAST_TOL_FACTOR`] and [`FAST_REST_TOL_FACTOR`], on the dense compression
/// output left in `s` by [`compress`].
fn restitute<const K: usize>(s: &mut Solver<K>, turn: Turn<K>, prec: f64) -> Result<Outcome> {
    let tol = prec * FAST_TOL_FACTOR * FAST_REST_TOL_FACTOR;
    s.rtol = prec;
    let Turn {
        t_m,
        d_m,
        v_m,
        s_m,
        f_m,
        mut h,
        mut steps,
        mut err_sum,
        mut hist,
        mut peak,
    } = turn;
    s.accept_step = (FAST_ROOT_LEVEL * prec).sqrt().min(1e-4) * t_m;
    let mut retry = Retry::default();
    let (mut t, mut d, mut v, mut f_n) = (t_m, d_m, v_m, f_m);
    let mut sk = s_m;
    // t_1 at the nodes of the last step, with its start and length (None: mirror image of the
    // elastic case, t_1 = 2 t_m - t); the polynomial through them gives the next step's guesses
    // (the quadratic through the last three nodes used before was off by up to 4e-2 t_m on a
    // dissipative row, a degree-4 fit by about 1e-4: 13% fewer evaluations at rtol 1e-10)
    let mut t1_hist: Option<(f64, f64, [f64; S])> = None;
    let mut prev_rest: Option<Seg<K>> = None;
    let mut ending = false;
    let mut end_iter = 0usize;
    let mut last_miss = f64::INFINITY;
    // lengths of steps from the current start that ended inside the contact (`g > 0`) and
    // after it: the end of contact lies between them
    let (mut end_lo, mut end_hi) = (0.0_f64, f64::INFINITY);
    // after a last step too long for the accuracy: (estimated end of contact, length of the
    // last step); the steps before it stop short of that last step instead of trying again
    let mut end_plan: Option<(f64, f64)> = None;
    let (v_end, t_end);
    // the end of contact predicted after the last accepted step (see FAST_END_RECEDE)
    let mut end_predicted = f64::INFINITY;
    loop {
        steps += 1;
        if steps > FAST_MAX_STEPS {
            return Err(Error::WorkLimit {
                solver: SOLVER_NAME,
                what: "steps",
                needed: steps,
                limit: FAST_MAX_STEPS,
            });
        }
        let mut guess = [0.0; S];
        let mut omega = [0.0; S];
        for i in 0..S {
            let tt = t + s.tab.c[i] * h;
            guess[i] = match &t1_hist {
                // the polynomial through the node values of t_1(t) on the last step
                Some((tp, hp, ys)) => {
                    let th = (tt - tp) / hp;
                    omega[i] = s.tab.c.iter().map(|&cj| th - cj).product();
                    interp_nodes(s.tab, ys, th)
                }
                None => t_m - (tt - t_m),
            }
            .clamp(0.0, t_m);
        }
        let omega = t1_hist.is_some().then_some(&omega);
        // predictor: the last restitution step's polynomial, or for the first one the
        // compression step of the turn (the force is C^1 there: F' = -(16/3) Σ c_k q_k / tau_k
        // on both sides, so its polynomial extrapolates to third order)
        let turn_seg = if prev_rest.is_none() {
            s.comp.last().copied()
        } else {
            None
        };
        let pred = prev_rest.as_ref().or(turn_seg.as_ref());
        let first = prev_rest.is_none();
        let out = match s.rest_step(t, d, v, &sk, h, f_n, &guess, omega, pred, first) {
            Ok(o) => o,
            Err(Error::NoConvergence { .. }) => {
                h *= 0.25;
                ending = false;
                continue;
            }
            Err(e) => return Err(e),
        };
        let ratio = out.err / (tol * rest_tol_scale(v, f_n, d, s.min_tol_scale));
        let seg = out.seg;
        let end = out.end;
        let mut g1 = s.c_inf * end.d;
        for k in 0..s.k {
            g1 += s.c[k] * end.s[k];
        }
        // the end of contact first: a step across it sees a kink (F = 0 beyond) and would be
        // rejected for the wrong reason
        if g1 <= 0.0 || ending {
            end_iter += 1;
            if end_iter > FAST_END_MAX_ITER {
                return Err(Error::NoConvergence {
                    what: "fast end of contact (last step fit)",
                    iterations: end_iter as u64,
                });
            }
            let th = if g1 <= 0.0 {
                s.end_root(&seg, 1.0, g1)?
            } else {
                // the step ends just before the contact: extrapolate its polynomial
                let mut hi = 1.0;
                let mut ghi = g1;
                let mut found = false;
                for _ in 0..8 {
                    hi *= 1.25;
                    ghi = s.contact_measure(&seg, hi).0;
                    if ghi <= 0.0 {
                        found = true;
                        break;
                    }
                }
                if !found {
                    ending = false;
                    f64::NAN
                } else {
                    s.end_root(&seg, hi, ghi)?
                }
            };
            if th.is_finite() {
                if g1 <= 0.0 {
                    end_hi = end_hi.min(h);
                } else {
                    end_lo = end_lo.max(h);
                }
                let miss = (th - 1.0).abs();
                // converged, or stalled at rounding level (the end is located to far better
                // than the step's accuracy needs: F vanishes there like (t_end - t)^(3/2))
                // F ~ K (t_end - t)^(3/2) near the end (K from the force at the step start,
                // a distance th h before the end): a step end off by miss h changes v by about
                // K (miss h)^(5/2) / (5/2); the CoR is |v| there (at the end, from the step's
                // polynomial: the step may start at the turn, v = 0, and end the contact),
                // hence the relative bound
                let kink = f_n * (miss / th.max(1e-3)).powf(1.5) * miss * h * 0.4;
                let v_scale = (seg_poly_at(&seg, th).1 / h).abs().max(v.abs());
                let done = miss <= 1e-9
                    || (miss <= 1e-6 && miss >= 0.5 * last_miss)
                    || (miss <= 0.1 && kink <= 0.01 * tol * v_scale);
                last_miss = miss;
                if done {
                    if !(ratio <= 1.0) {
                        // the last step is too long for the accuracy: approach in smaller
                        // steps, the last one short enough (its error grows like h^(5/2),
                        // F ~ (t_end - t)^(3/2))
                        let last = h * th * (0.5 * ratio.powf(-0.4)).clamp(0.05, 0.5);
                        end_plan = Some((t + th * h, last));
                        h = (th * h - last).min(h * step_factor(ratio).min(0.7));
                        ending = false;
                        last_miss = f64::INFINITY;
                        continue;
                    }
                    err_sum += out.err;
                    for i in 0..S {
                        peak.push(t + s.tab.c[i] * h, out.f[i]);
                    }
                    let pt = s.eval_seg(&seg, th, false);
                    v_end = pt.v;
                    t_end = t + th * h;
                    if let Some(hh) = hist.as_mut() {
                        hh.push(t_end, pt.d, pt.v, 0.0, 0.0);
                    }
                    break;
                }
                ending = true;
                // the step to the end located on this step's polynomial; bisection of the
                // bracket when that leaves it (the polynomials of a step that stops short and
                // of one that crosses the end can disagree on where it is, and the fit then
                // 2-cycles: seen with CoR near 1e-4, p2 below 1e-5, rtol 1e-2)
                let next = h * th;
                h = if end_hi.is_finite()
                    && !(next > end_lo + 1e-3 * (end_hi - end_lo)
                        && next < end_hi - 1e-3 * (end_hi - end_lo))
                {
                    0.5 * (end_lo + end_hi)
                } else {
                    next
                };
                continue;
            }
        }
        if !(ratio <= 1.0) {
            h = retry.next(h, ratio);
            ending = false;
            continue;
        }
        retry = Retry::default();
        // accept
        end_iter = 0;
        (end_lo, end_hi) = (0.0, f64::INFINITY);
        err_sum += out.err;
        for i in 0..S {
            peak.push(t + s.tab.c[i] * h, out.f[i]);
        }
        t1_hist = Some((t, h, out.t1));
        prev_rest = Some(seg);
        t += h;
        d = end.d;
        v = end.v;
        sk = end.s;
        f_n = out.f[S - 1];
        if let Some(hh) = hist.as_mut() {
            hh.push(t, d, v, f_n, out.a[S - 1]);
        }
        if !(d.is_finite() && v.is_finite()) {
            return Err(Error::NonFinite {
                what: "fast restitution state",
                value: d + v,
            });
        }
        let h_done = h;
        h *= step_factor(ratio);
        if end_plan.is_none() {
            // distance to the end of contact from g and dg/dt at the step end
            let mut dg = s.c_inf * v;
            for k in 0..s.k {
                dg += s.c[k] * (v - sk[k] / s.tau[k]);
            }
            if dg < 0.0 && g1 > 0.0 {
                let delta = -g1 / dg;
                // a prediction that moved later by more than the step just taken is not
                // a distance to the end: in the slow tail of a strongly dissipative rebound
                // the tangent of g meets zero far before the end, and that point moves on
                // with every step
                let receded = t + delta - end_predicted;
                end_predicted = t + delta;
                if delta < FAST_END_NEAR * h && receded <= FAST_END_RECEDE * h_done {
                    let (next, last) = end_approach(ratio.max(1e-3), h_done, delta);
                    h = next.min(h);
                    if last {
                        ending = true;
                    }
                }
            }
        }
        if let Some((te, last)) = end_plan {
            let rest = te - t;
            if rest <= 0.5 * last {
                end_plan = None; // the estimate was off: find the end anew
            } else if rest <= 1.2 * last {
                h = rest;
                ending = true;
            } else {
                h = h.min(rest - last);
            }
        }
    }
    let cor = -v_end;
    if !cor.is_finite() {
        return Err(Error::NonFinite {
            what: "fast coefficient of restitution",
            value: cor,
        });
    }
    Ok(Outcome {
        cor,
        rebound_velocity: cor,
        contact_time: t_end,
        max_indentation: d_m,
        time_of_max_indentation: t_m,
        max_force: peak.max,
        max_contact_radius: d_m.max(0.0).sqrt(),
        dissipated_energy: 0.5 * (1.0 - cor * cor),
        cor_error_estimate: Some(err_sum / cor.abs().max(f64::MIN_POSITIVE)),
        history: hist,
        work: Work {
            steps,
            elements: 0,
            element_updates: 0,
            evaluations: s.evaluations,
            levels: 1,
        },
        solver: SOLVER_NAME,
        fallback: None,
    })
}
