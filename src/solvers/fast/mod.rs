//! The `fast` impact solver: Lee–Radok in compression, Ting/Graham in restitution, on the
//! indentation `d(t)` alone (docs/theory.md §4–§5), with exact exponential kernels.
//!
//! Written for the paraboloid (`w = d^(3/2)` below); any other indenter but the flat punch runs
//! through [`impact_on`] with its `w(d)` and `a(d)` (module `shape`, docs/theory.md §11; its cost
//! against the paraboloid is in VALIDATION.md §9), and the flat punch, whose contact radius
//! never changes, by the modes of its linear ODE (module `flat`).
//!
//! # Why no elements
//! All MDR elements in contact share one rate `u_i' = d'` and leave last-in-first-out
//! (docs/theory.md §5), so the force is a functional of `d(t)` alone. With a Prony series
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
//! arrays `[f64; K]` of a capacity class `K ∈ {2, 8, 16, 32, 128}` chosen once per solve
//! (`Solver<K>`, the smallest class that holds the terms; at most [`FAST_MAX_TERMS`]), so the
//! one- and two-term materials keep small stack copies of the state (the dense evaluations of
//! the Ting roots return it by value) while 30 shear terms with a viscoelastic bulk fit. The
//! padding of a class costs its zero initialisation and copies, at most 4x the live terms (the
//! class 16 holds the 9 to 16 terms a reduced real polymer keeps, module `reduce`: 5.5 % fewer
//! instructions than the class 32 for `polyisobutylene`, 5 % for `epoxy`, callgrind). Terms
//! with the same time are merged into one before the solve (a series given in parts is solved
//! as the same series), terms with `tau = inf` join `c_inf`, and terms with `tau = 0` or
//! `c_k = 0` are dropped.
//! Measured on the 765 external rows at rtol 1e-6 (`XRTOL=1e-6 XREPS=3`, `tests/fast_xcheck.rs`,
//! eight alternating runs, 2026-11-23): median 34.9 to 35.2 us per impact with the single
//! class `[f64; 8]` used before, 33.9 to 34.6 us with the classes (the two-term class), 57 us
//! with one class of 128 for every input (the zeroing and copying of `Pt`, `Seg` and the
//! restitution's per-term tables); 250 evaluations on average and the same results in all.
//!
//! # Verified answers
//! [`impact`] returns a solve at `rtol` only with an estimate of its CoR error at or below
//! `rtol`, by one of two paths (docs/theory.md §10.1):
//!
//! - **One solve.** The sum of the local defects that chooses the steps, over `e`, exceeds the
//!   CoR error by far (the defect is measured between the nodes, the CoR is taken at the
//!   superconvergent step ends). Divided by the calibration [`FAST_LOCAL_CALIBRATION`]`
//!   rtol^(-`[`FAST_LOCAL_EXPONENT`]`)` (about 16 at 1e-6, 160 at 1e-10) it is the estimate;
//!   the solve is returned when that is at most `rtol`, for `rtol >=`
//!   [`FAST_ONE_SOLVE_MIN_RTOL`] and `e rtol >=` [`FAST_ROUNDOFF_FLOOR`]. Calibrated on 1500
//!   rows of the stress distribution (`nu` in (-1, 0.5], `p2`, `p3` log-uniform over 1e-8 to
//!   1e8, seed 11) and checked on 1500 others (seed 12), against `reference` at least 10x
//!   tighter than the rtol, at every rtol from 1e-2 to 1e-10: the smallest ratio of the defect
//!   sum to the error was 2.3 at 1e-2, 25 at 1e-4, 65 at 1e-6, 175 at 1e-8, 445 at 1e-10;
//!   with the calibration, accepted errors were at most 0.75 of the estimate and 0.46 `rtol`
//!   (0.23 `rtol` from 1e-3 to 1e-10), and 91-96% of the rows took this path. The unverified
//!   solve alone was up to 7x outside `rtol` on those rows (CoR about 1e-5, or few steps at a
//!   loose rtol); each of those had a defect sum far above the others and took the tight check.
//!   `mdr-impact stress` counts this path and the largest error of its answers.
//! - **Tight check**, otherwise: solves at `rtol / `[`FAST_CHECK_RATIO`]`, ...` (at most
//!   [`FAST_CHECK_LEVELS`] solves with the first) until two successive CoRs agree to `rtol`,
//!   and returns the tighter one with their relative difference as `cor_error_estimate`, or
//!   refuses with [`Error::AccuracyNotReached`] and that difference. The difference estimates
//!   the error of the looser solve, about [`FAST_CHECK_RATIO`] times the error of the returned
//!   one.
//!
//! A second solve that reuses nothing but is 1000x looser was tried as the cheap check and
//! rejected: the loose solves are more accurate than their tolerance (fixed work per solve), so
//! the difference says little about the solve at `rtol` (it accepted answers 4.8x outside
//! `rtol`). A CoR below the step tolerance's energy floor [`FAST_MIN_TOL_SCALE`] lowers that
//! floor to `e / 2` and is solved again before any estimate (the floor made CoRs about 1e-5
//! wrong by 25x `rtol`). [`impact_unverified`] is one solve, for the work-precision diagram.
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
//! The figures of this section are of one solve at `rtol`, before the verification (see
//! above); `mdr-impact bench` and VALIDATION.md report the verified solver next to it.
//!
//! Independent of [`crate::solvers::mdr`] and [`crate::solvers::theory`]; shares only [`Prony`] with them.

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

mod basis;
mod compression;
mod control;
mod dense;
mod driver;
mod flat;
mod kernel;
mod linalg;
mod newton;
mod reduce;
mod restitution;
mod shape;
mod ting;

use std::sync::OnceLock;

use crate::error::{Error, Result};
use crate::model::contact::{CanonicalOutcome, Contact, Geometry};
use crate::model::impact::{History, Method, Outcome, Work};
use crate::model::material::Prony;
use crate::model::tolerances;
use crate::solvers::api::{ImpactSolver, SolveOptions, SolverKind};
use basis::*;
use compression::*;
use control::*;
use dense::*;
use driver::*;
use linalg::Mat;
use newton::*;
use restitution::*;
use shape::{ShapeFns, ShapePoint};
use ting::*;

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
/// Smallest `rtol` answered by one solve when its calibrated local estimate allows (module
/// docs, "Verified answers"); below it every answer is checked by a tighter solve.
pub const FAST_ONE_SOLVE_MIN_RTOL: f64 = 1e-10;
/// Calibration of the local estimate: the sum of the local defects of a solve at `rtol` over
/// `e` is taken to exceed its CoR error by `FAST_LOCAL_CALIBRATION rtol^(-FAST_LOCAL_EXPONENT)`.
pub const FAST_LOCAL_CALIBRATION: f64 = 0.5;
/// Exponent of [`FAST_LOCAL_CALIBRATION`]'s law.
pub const FAST_LOCAL_EXPONENT: f64 = 0.25;
/// One solve is accepted only where `e rtol` is at least this (the round-off of the velocity,
/// integrated from 1 down to `e`, does not scale with the tolerance).
pub const FAST_ROUNDOFF_FLOOR: f64 = 1e-12;
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
/// `2 I`, `I = (2/5) B(2/5, 1/2) = 1.4716375921623523` (docs/theory.md §6).
pub const HERTZ_CONTACT_FACTOR: f64 = 2.943_275_184_324_704_7;
/// Name of the solver in an [`Outcome`].
pub const SOLVER_NAME: &str = "fast";

const S: usize = FAST_NODES;
/// Order in `h` assumed for the first retry of a rejected first step (`(S + 2) / 2`).
const FIRST_STEP_ORDER: f64 = (S as f64 + 2.0) / 2.0;
const K16: f64 = 16.0 / 3.0;

struct Solver<const K: usize> {
    rtol: f64,
    /// The indenter's functions ([`ShapeFns`]; the unit paraboloid's closed forms when its
    /// geometry is `None`).
    shape: ShapeFns,
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
    /// Time and value of the largest node force of the last solve, when it lies in compression.
    peak_node: Option<(f64, f64)>,
    /// Locate the maximum force on the dense output after the solve ([`driver`]'s `finish`).
    refine_peak: bool,
    /// The shape's values at the indentation of the last dense compression output (a shape
    /// other than the paraboloid: the Ting root that asked for it uses `a` and `a'` there too).
    last_point: ShapePoint,
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
}

/// Impact of the unit sphere (`m = R = v0 = 1`) on a half-space with the equivalent
/// relaxation function `prony` (moduli in units of `G_inf`, times in units of `L / v0`),
/// solved by Lee–Radok / Ting–Graham on `d(t)` (see the module docs).
///
/// `rtol` is the requested relative accuracy of the CoR (`MIN_RTOL <= rtol <= MAX_RTOL` of
/// [`crate::model::tolerances`]); `history` asks for `(t, d, v, F, a)` at the step ends. The outcome
/// is canonical: `rebound_velocity = cor`, `dissipated_energy = (1 - e^2)/2`,
/// `max_contact_radius = sqrt(d_max)`, solver `"fast"`. The CoR is verified (module docs,
/// "Verified answers"): `cor_error_estimate` is the calibrated local estimate of a solve at
/// `rtol` or the relative difference from the solve at a [`FAST_CHECK_RATIO`] times looser
/// tolerance, always `<= rtol`; `max_force` is the largest
/// node force, refined by a parabola through its neighbours; `work.steps` counts attempted
/// steps and `work.evaluations` force and history evaluations of all solves, `work.levels`
/// the solves.
///
/// Elastic input (no Prony terms) is answered in closed form (Hertz, docs/theory.md §6):
/// `k = (16/3) c_inf`, `d_max = (5/(4k))^(2/5)`, `t_c = 2.9432751843247047 d_max`, `e = 1`.
///
/// ```
/// # use mdr_impact::{Prony, solvers::fast};
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
    impact_on(None, prony, rtol, history)
}

/// [`impact`] for the indenter `geometry` (canonical, [`crate::model::geometry`]; `None` or the
/// unit sphere: the paraboloid): the shape's `w(d)` and `a(d)` in place of `d^(3/2)` and
/// `sqrt(d)` (docs/theory.md §11), in closed form for the power laws and by a tabulated
/// inverse for an exact cap (module `shape`). The first step's basis is the paraboloid's
/// (powers of `sqrt(t)` after `t^(3/2)`): for another shape its step control shrinks the first
/// step until the mismatch, of the size of `w` over the step, is within the tolerance. The flat
/// punch, a linear ODE, is solved by its modes (module `flat`); an elastic material on a power
/// law in closed form (Sneddon's force and the Beta function); an elastic material on exact
/// spheres is refused ([`Error::NotSupported`]: `reference` solves it).
pub fn impact_on(
    geometry: Option<Geometry>,
    prony: &Prony,
    rtol: f64,
    history: bool,
) -> Result<Outcome> {
    impact_with(geometry, prony, rtol, history, true)
}

/// [`impact_on`]; with `peak_force` false the maximum force is not located to `rtol` after
/// the solve ([`SolveOptions::peak_force`]: the largest sampled force with its parabola).
pub fn impact_with(
    geometry: Option<Geometry>,
    prony: &Prony,
    rtol: f64,
    history: bool,
    peak_force: bool,
) -> Result<Outcome> {
    let mode = if peak_force {
        Mode::Verified
    } else {
        Mode::VerifiedNoPeak
    };
    let geom = geometry.filter(|g| *g != Geometry::UNIT_SPHERE);
    let (c_inf, live) = prepare(prony, rtol)?;
    if geom.is_some_and(|g| g.is_flat()) {
        // a linear ODE: its modes, every term kept (module `flat`)
        return flat::flat_impact(c_inf, &live, rtol, history);
    }
    if let (Some(g), true) = (geom, live.is_empty()) {
        return elastic_power_law(g, c_inf, history).ok_or_else(|| Error::NotSupported {
            solver: SOLVER_NAME,
            what: "an elastic material on exact spheres (no closed form here); reference \
                   solves it"
                .into(),
        });
    }
    // terms far outside the contact window are merged into their limit forms when the bound
    // of the merge stays within a share of rtol (module `reduce`)
    if live.len() > 2 {
        return reduce::solve(c_inf, &live, rtol, |c, l, r| {
            dispatch(geom, c, l, r, history, mode)
        });
    }
    dispatch(geom, c_inf, &live, rtol, history, mode)
}

/// [`impact`] without merging the terms outside the contact window (module `reduce`): every
/// term is integrated. For checks of the reduction and for benchmarks.
pub fn impact_unreduced(prony: &Prony, rtol: f64, history: bool) -> Result<Outcome> {
    let (c_inf, live) = prepare(prony, rtol)?;
    dispatch(None, c_inf, &live, rtol, history, Mode::Verified)
}

/// One solve at the step tolerance `rtol`, **not verified** (every term integrated; a CoR
/// below the energy floor solved again, as in [`impact`]): the solver before the verification,
/// for the work-precision diagram and the checks of the verification. Its
/// `cor_error_estimate` is the sum of the local defects over `e`, no global estimate.
///
/// # Errors
/// As [`impact`], but never [`Error::AccuracyNotReached`].
pub fn impact_unverified(prony: &Prony, rtol: f64, history: bool) -> Result<Outcome> {
    let (c_inf, live) = prepare(prony, rtol)?;
    dispatch(None, c_inf, &live, rtol, history, Mode::Unverified)
}

/// Verified ([`impact`]) or one solve ([`impact_unverified`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Verified,
    /// [`Mode::Verified`] without locating the maximum force after the solve.
    VerifiedNoPeak,
    Unverified,
}

/// Validate `rtol` and `prony`; the relaxed modulus and the live terms `(c_k, tau_k)` (zero
/// terms dropped, infinite times added to the relaxed modulus, equal times merged).
fn prepare(prony: &Prony, rtol: f64) -> Result<(f64, Vec<(f64, f64)>)> {
    if !(tolerances::MIN_RTOL..=tolerances::MAX_RTOL).contains(&rtol) {
        return Err(Error::OutOfRange {
            field: "rtol",
            value: rtol,
            allowed: "MIN_RTOL <= rtol <= MAX_RTOL (1e-12 ..= 0.1)",
        });
    }
    // c_inf = 0: a viscoelastic liquid (checked below to have a decaying term)
    if !(prony.relaxed >= 0.0 && prony.relaxed.is_finite()) {
        return Err(Error::OutOfRange {
            field: "relaxed modulus",
            value: prony.relaxed,
            allowed: "0 <= c_inf < inf",
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
        // terms with the same time are one term (a series split into parts gives the same
        // solve, not one with other rounding and hence other step decisions)
        match live.iter_mut().find(|(_, t)| *t == term.tau) {
            Some((c, _)) => *c += term.coefficient,
            None => live.push((term.coefficient, term.tau)),
        }
    }
    // the limit counts the decaying terms as given, before the merge of equal times
    let decaying = prony
        .terms
        .iter()
        .filter(|t| t.coefficient > 0.0 && t.tau > 0.0 && t.tau.is_finite())
        .count();
    if !(c_inf > 0.0 || live.iter().any(|&(c, _)| c > 0.0)) {
        return Err(Error::OutOfRange {
            field: "relaxed modulus",
            value: c_inf,
            allowed: "0 < c_inf < inf, or c_inf = 0 with a decaying term (a liquid)",
        });
    }
    if decaying > FAST_MAX_TERMS {
        return Err(Error::TooManyTerms {
            solver: "fast",
            terms: decaying,
            max: FAST_MAX_TERMS,
        });
    }
    Ok((c_inf, live))
}

/// [`impact`] on the validated, merged terms `live`.
fn dispatch(
    geom: Option<Geometry>,
    c_inf: f64,
    live: &[(f64, f64)],
    rtol: f64,
    history: bool,
    mode: Mode,
) -> Result<Outcome> {
    // the per-term state lives in arrays of the smallest capacity class that holds the live
    // terms (module docs, "Term state"): every loop runs over the live terms only
    match live.len() {
        0 => Ok(hertz(c_inf, history)),
        1..=2 => solve_terms::<2>(geom, c_inf, live, rtol, history, mode),
        3..=8 => solve_terms::<8>(geom, c_inf, live, rtol, history, mode),
        9..=16 => solve_terms::<16>(geom, c_inf, live, rtol, history, mode),
        17..=32 => solve_terms::<32>(geom, c_inf, live, rtol, history, mode),
        _ => solve_terms::<FAST_MAX_TERMS>(geom, c_inf, live, rtol, history, mode),
    }
}

/// [`impact`] for `1 <= live.len() <= K` terms `(c_k, tau_k)` (positive, finite) and the
/// relaxed modulus `c_inf`, with the per-term state in arrays of capacity `K`.
fn solve_terms<const K: usize>(
    geom: Option<Geometry>,
    c_inf: f64,
    live: &[(f64, f64)],
    rtol: f64,
    history: bool,
    mode: Mode,
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
        shape: ShapeFns::new(geom),
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
        t_m: 0.0,
        evaluations: 0,
        last_seg: 0,
        peak_node: None,
        refine_peak: mode != Mode::VerifiedNoPeak,
        last_point: ShapePoint::default(),
    };
    match mode {
        Mode::Verified | Mode::VerifiedNoPeak => verified(&mut s, rtol, history),
        Mode::Unverified => unverified(&mut s, rtol, history),
    }
}

/// Elastic closed form (docs/theory.md §6) in canonical units.
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
        solver: Method::Fast,
        fallback: None,
    }
}

/// The elastic impact on a power law `g = k x^n` (the cone: `n = 1`) in closed form
/// (docs/theory.md §11): `F = K d^p`, `p = 1 + 1/n`, `K = (16/3) c_inf (3/2) n/(n+1) k^(-1/n)`;
/// `d_max = ((p+1) / (2K))^(1/(p+1))`, `t_c = 2 d_max B(1/(p+1), 1/2) / (p+1)`,
/// `F_max = K d_max^p`, `e = 1`. `None` for other geometries.
fn elastic_power_law(geom: Geometry, c_inf: f64, history: bool) -> Option<Outcome> {
    let Geometry::PowerLaw {
        exponent: n,
        coefficient: k,
    } = geom
    else {
        return None;
    };
    use statrs::function::gamma::ln_gamma;
    let p = 1.0 + 1.0 / n;
    let q = p + 1.0;
    let kf = K16 * c_inf * 1.5 * n / (n + 1.0) * k.powf(-1.0 / n);
    let d_max = (q / (2.0 * kf)).powf(1.0 / q);
    let beta = (ln_gamma(1.0 / q) + ln_gamma(0.5) - ln_gamma(1.0 / q + 0.5)).exp();
    let tc = 2.0 * d_max * beta / q;
    let f_max = kf * d_max.powf(p);
    let a_max = (d_max / k).powf(1.0 / n);
    Some(Outcome {
        cor: 1.0,
        rebound_velocity: 1.0,
        contact_time: tc,
        max_indentation: d_max,
        time_of_max_indentation: 0.5 * tc,
        max_force: f_max,
        max_contact_radius: a_max,
        dissipated_energy: 0.0,
        cor_error_estimate: Some(0.0),
        history: history.then(|| {
            let mut h = History::default();
            h.push(0.0, 0.0, 1.0, 0.0, 0.0);
            h.push(0.5 * tc, d_max, 0.0, f_max, a_max);
            h.push(tc, 0.0, -1.0, 0.0, 0.0);
            h
        }),
        work: Work::default(),
        solver: Method::Fast,
        fallback: None,
    })
}

/// The `fast` solver behind the solver interface: [`impact`] on the contact's `G_eq`.
#[derive(Debug, Clone, Copy, Default)]
pub struct Fast;

impl ImpactSolver for Fast {
    fn kind(&self) -> SolverKind {
        SolverKind::Fast
    }
    fn solve(&self, contact: &Contact, opts: &SolveOptions) -> Result<CanonicalOutcome> {
        impact_with(
            Some(contact.geometry),
            &contact.g_eq,
            opts.rtol,
            opts.history,
            opts.peak_force,
        )
        .map(CanonicalOutcome::new)
    }
}
