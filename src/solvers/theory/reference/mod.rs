//! Reference impact solver: the impact of a rigid sphere solved from the Lee–Radok/Ting
//! formulation (docs/theory.md §4), not from an element foundation.
//!
//! Canonical units `m = R = v0 = 1`, the relaxation function `G_eq(t) = c_inf + sum_k c_k
//! exp(-t/tau_k)` in units of `G_inf`. With `phi = d^(3/2)`:
//!
//! ```text
//! compression (d' >= 0):   q_k' = -q_k/tau_k + phi',   S_k' = -S_k/tau_k + d',
//!                          d'' = -F,   F = (16/3) (c_inf phi + sum_k c_k q_k)
//! restitution (t > t_m):   t_1(t) root of  c_inf (d(t) - d(t_1)) + sum_k c_k [S_k(t) - e^{-(t-t_1)/tau_k} S_k(t_1)] = 0
//!                          F = (16/3) [c_inf phi(t_1) + sum_k c_k e^{-(t-t_1)/tau_k} q_k(t_1)]
//! end of contact:          t_1 = 0, i.e. c_inf d + sum_k c_k S_k = 0;   e = -d'(t_end).
//! ```
//!
//! # Method
//! *Exponential collocation.* On a step `[t_n, t_n + h]` the depth is the polynomial of degree
//! `s + 1` (`s = 5`) with `d(t_n) = d_n`, `d'(t_n) = v_n`, collocating `d'' = -F` at the Radau IIA
//! nodes `c_i` (`c_s = 1`). The internal variables are integrated *exactly* for the polynomial
//! driving terms (`d'` exactly, `phi'` through the interpolant of `phi` at `{0, c_1..c_s}`):
//!
//! ```text
//! int_0^{c h} e^{-(c h - s)/tau} p'(s) ds = sum_m p_m m c^m e_{m-1}(c h / tau),
//! e_m(z) = int_0^1 e^{-z(1-u)} u^m du        (super::special::exp_moments)
//! ```
//!
//! which is stable for any `h / tau` (stiff terms with `tau / t_contact` down to `1e-9` cost
//! nothing extra). The `s` node depths are found by Newton's method with the analytic Jacobian
//! (compression: `dF_i/dD_j = 8 sqrt(D_j) (c_inf delta_ij + sum_k c_k W_kij)`; restitution:
//! `dF_i/dD_j = 8 sqrt(d(t_1,i)) (c_inf delta_ij + sum_k c_k dS_k(t_i)/dD_j)`, since
//! `dF/dt_1 = phi'(t_1) G(t - t_1)` and `dPhi/dt_1 = -d'(t_1) G(t - t_1)`).
//!
//! *Dense record.* Each compression step keeps its polynomials and initial `q_k, S_k`; `d, q_k,
//! S_k` at any `t_1 <= t_m` are evaluated exactly from them, so Ting's root is solved with the
//! same accuracy as the steps (safeguarded Newton, [`crate::math::roots::newton_bracketed`]).
//!
//! *Error control.* Step doubling (one step of `h` against two of `h/2`) on `(d, v)`, local
//! tolerance `REF_LOCAL_FACTOR * rtol`; the singular start (`d ~ t`, `phi ~ t^(3/2)`) and end
//! (`F ~ (t_end - t)^(3/2)`) are resolved by the resulting geometric grading from `h_0 = 1e-6`.
//! The time of maximum indentation (`v = 0`) and the end of contact are landed on exactly
//! (secant on the step length). The whole solve is repeated with a 30 times smaller tolerance;
//! the difference of the two CoRs is the reported `cor_error_estimate` (of the coarser run, hence
//! conservative for the returned finer one), and the driver refines until it is below `rtol`.
//! The local tolerance has a floor (`2e-15`, absolute in canonical velocity); once a refinement
//! would stay at the floor the driver refuses (`AccuracyNotReached`) instead of comparing two
//! identical runs. Errors are then about `1e-12 / e` relative: for the smallest CoR of the
//! external corner table (`e = 6.3e-4`) rtol 1e-10 is refused (estimate 1.0e-9).
//! In the glassy corner (`G_eq(0) / G_eq(inf) >` [`super::REF_GLASSY_RATIO`]) successive runs
//! were measured to agree within rtol while both were off by up to 18x rtol (against the
//! external SciPy solution): there the difference is accepted only below
//! [`super::REF_GLASSY_SAFETY`]` rtol`, and a request with `rtol e <`
//! [`super::REF_GLASSY_ABS_FLOOR`] is refused, with `REF_GLASSY_ABS_FLOOR / e` as the estimate.

// The collocation algebra indexes several arrays with the same node/term/monomial indices;
// explicit index loops mirror the formulas. The Radau nodes keep their mpmath digits.
#![allow(clippy::needless_range_loop, clippy::excessive_precision)]

use super::{REF_EVENT_TOL, REF_LOCAL_FACTOR, REF_MAX_NEWTON, REF_MAX_STEPS, REF_NEWTON_TOL};
use crate::error::{check, Error, Result};
use crate::math::roots::newton_bracketed_with;
use crate::math::special::exp_moments;
use crate::model::contact::Geometry;
use crate::model::impact::{History, Method, Outcome, Work};
use crate::model::material::Prony;
use nalgebra::{SMatrix, SVector};

mod step;

/// Number of collocation nodes.
const S: usize = 5;
/// Polynomial degree of `d` on a step plus one.
const NB: usize = S + 2;
/// Radau IIA nodes for `s = 5` (zeros of `P_5(2c-1) - P_4(2c-1)`, mpmath, 20 digits).
const NODES: [f64; S] = [
    0.057_104_196_114_517_682,
    0.276_843_013_638_123_83,
    0.583_590_432_368_916_82,
    0.860_240_135_656_219_45,
    1.0,
];
/// First step length (canonical time), grown by the controller.
const H0: f64 = 1e-6;
/// Smallest step length (canonical time); below it the local tolerance is deemed unreachable.
const MIN_STEP: f64 = 1e-13;
/// Smallest local tolerance (roundoff floor of `d` and `v`, which are of order one).
const MIN_LOCAL_TOL: f64 = 2e-15;
/// Refinement levels of the driver (each divides the local tolerance by 30).
const MAX_LEVELS: u32 = 6;
/// Ratio of local tolerances between the two runs whose difference estimates the error.
const LEVEL_RATIO: f64 = 30.0;

type Mat = SMatrix<f64, S, S>;
type Vs = SVector<f64, S>;

/// Constant collocation matrices.
struct Coll {
    /// `a = linv * [phi_0, phi_1..phi_s]`: monomial coefficients of the `phi` interpolant.
    linv: SMatrix<f64, { S + 1 }, { S + 1 }>,
    /// `b_{2..s+1} = minv * (D - d_n - h v_n c)`.
    minv: Mat,
    /// `h^2 d''(c_i) = a2 * (D - d_n - h v_n c)`.
    a2: Mat,
}

impl Coll {
    fn new() -> Result<Self> {
        let mut vand = SMatrix::<f64, { S + 1 }, { S + 1 }>::zeros();
        for r in 0..=S {
            let x = if r == 0 { 0.0 } else { NODES[r - 1] };
            for m in 0..=S {
                vand[(r, m)] = x.powi(m as i32);
            }
        }
        let linv = vand.try_inverse().ok_or(Error::NonFinite {
            what: "collocation Vandermonde inverse",
            value: f64::NAN,
        })?;
        let mut mm = Mat::zeros();
        let mut c2 = Mat::zeros();
        for i in 0..S {
            for m in 0..S {
                let p = (m + 2) as i32;
                mm[(i, m)] = NODES[i].powi(p);
                c2[(i, m)] = (p * (p - 1)) as f64 * NODES[i].powi(p - 2);
            }
        }
        let minv = mm.try_inverse().ok_or(Error::NonFinite {
            what: "collocation matrix inverse",
            value: f64::NAN,
        })?;
        Ok(Self {
            linv,
            a2: c2 * minv,
            minv,
        })
    }
}

/// State at a step boundary.
#[derive(Debug, Clone)]
struct State {
    t: f64,
    d: f64,
    v: f64,
    q: Vec<f64>,
    s: Vec<f64>,
    force: f64,
    t1: f64,
}

/// Dense record of one compression step.
#[derive(Debug, Clone)]
struct Record {
    t0: f64,
    h: f64,
    b: [f64; NB],
    a: [f64; S + 1],
    q0: Vec<f64>,
    s0: Vec<f64>,
}

/// Result of one collocation step.
struct StepOut {
    end: State,
    rec: Record,
    /// node forces and times (for the history and the maximum force)
    nodes: [(f64, f64); S],
}

/// Values of the compression record at `t1`: `d, d', q_k, S_k`.
struct Dense {
    d: f64,
    dv: f64,
    q: Vec<f64>,
    s: Vec<f64>,
}

struct Solver<'a> {
    prony: &'a Prony,
    /// The indenter's shape: `w(d)` (`phi` of the module docs) and `a(d)`.
    geom: Geometry,
    coll: Coll,
    records: Vec<Record>,
    t_m: f64,
    evals: u64,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Phase {
    Compression,
    Restitution,
    /// After the turn of a flat punch: the contact radius stays, so the compression equations
    /// hold until the force returns to zero (no Ting root).
    FlatRelease,
}

/// Raw result of one run at a fixed local tolerance.
struct Run {
    cor: f64,
    t_end: f64,
    t_m: f64,
    d_max: f64,
    f_max: f64,
    steps: u64,
    evals: u64,
    history: Option<History>,
}

fn grow(err: f64) -> f64 {
    if err == 0.0 {
        4.0
    } else {
        (0.9 * err.powf(-1.0 / 6.0)).clamp(0.2, 4.0)
    }
}

/// Which samples of the history a run records.
#[derive(Debug, Clone, PartialEq)]
enum Sampling {
    None,
    StepEnds,
    Times(Vec<f64>),
}

/// Record the requested output times inside the step of `rec` (dense evaluation).
fn emit(
    sv: &Solver,
    hist: &mut Option<History>,
    rec: &Record,
    phase: Phase,
    times: &[f64],
    next: &mut usize,
) -> Result<()> {
    let Some(hh) = hist.as_mut() else {
        return Ok(());
    };
    let mut guess = sv.t_m;
    while *next < times.len() && times[*next] <= rec.t0 + rec.h {
        let t = times[*next];
        let de = sv.eval_record(rec, t);
        match phase {
            Phase::Compression | Phase::FlatRelease => {
                let mut f = sv.prony.relaxed * sv.geom.force_function(de.d);
                for (k, p) in sv.prony.terms.iter().enumerate() {
                    f += p.coefficient * de.q[k];
                }
                hh.push(t, de.d, de.dv, 16.0 / 3.0 * f, sv.geom.contact_radius(de.d));
            }
            Phase::Restitution => {
                let (t1, d1, f) = sv.ting(t, de.d, &de.s, guess)?;
                guess = t1;
                // At the end of contact t1 -> 0 and sqrt(d(t1)) magnifies the root's round-off
                // (t1 ~ 1e-15 gives a ~ 3e-8): below END_T1 t_m the sample is the end of contact.
                let a = if t1 > END_T1 * sv.t_m {
                    sv.geom.contact_radius(d1)
                } else {
                    0.0
                };
                hh.push(t, de.d, de.dv, f, a);
            }
        }
        *next += 1;
    }
    Ok(())
}

/// `t1 / t_m` below which a restitution sample is taken as the end of contact (`a = 0`).
const END_T1: f64 = 1e-9;

fn run(geom: Geometry, prony: &Prony, tol: f64, sampling: &Sampling) -> Result<Run> {
    let want_history = *sampling == Sampling::StepEnds;
    let out_times: &[f64] = match sampling {
        Sampling::Times(t) => t,
        _ => &[],
    };
    let mut next_out = 0usize;
    let mut sv = Solver::new(prony, geom)?;
    let mut d_max = 0.0f64;
    let kk = prony.terms.len();
    let mut st = State {
        t: 0.0,
        d: 0.0,
        v: 1.0,
        q: vec![0.0; kk],
        s: vec![0.0; kk],
        force: 0.0,
        t1: 0.0,
    };
    let mut hist = want_history.then(History::default);
    if let Some(hh) = hist.as_mut() {
        hh.push(0.0, 0.0, 1.0, 0.0, 0.0);
    }
    let mut samples = (!out_times.is_empty()).then(History::default);
    while next_out < out_times.len() && out_times[next_out] <= 0.0 {
        if let Some(hh) = samples.as_mut() {
            hh.push(out_times[next_out], 0.0, 1.0, 0.0, 0.0);
        }
        next_out += 1;
    }
    let mut f_max = 0.0f64;
    let mut f_max_t = 0.0f64;
    let mut h = H0;
    let mut steps = 0u64;
    let mut phase = Phase::Compression;
    let push = |hist: &mut Option<History>, s: &State, phase: Phase, sv: &mut Solver| {
        if !want_history {
            return;
        }
        if let Some(hh) = hist.as_mut() {
            let a = match phase {
                Phase::Compression | Phase::FlatRelease => sv.geom.contact_radius(s.d),
                Phase::Restitution => {
                    if s.t1 > 0.0 {
                        sv.geom.contact_radius(sv.dense(s.t1).d)
                    } else {
                        0.0
                    }
                }
            };
            hh.push(s.t, s.d, s.v, s.force, a);
        }
    };
    loop {
        steps += 1;
        if steps > REF_MAX_STEPS {
            return Err(Error::WorkLimit {
                solver: "reference",
                what: "time steps",
                needed: steps,
                limit: REF_MAX_STEPS,
            });
        }
        if h < MIN_STEP {
            return Err(Error::StepSizeTooSmall {
                solver: "reference",
                time: st.t,
                step: h,
                rtol: tol,
            });
        }
        let (first, second, err) = sv.doubled(phase, &st, h, tol)?;
        let event = match phase {
            Phase::Compression => second.end.v < 0.0 || first.end.v < 0.0,
            Phase::Restitution | Phase::FlatRelease => {
                sv.psi(&second.end) <= 0.0 || sv.psi(&first.end) <= 0.0
            }
        };
        if !event {
            if err > 1.0 {
                h *= grow(err).min(0.9);
                continue;
            }
            for o in [&first, &second] {
                for &(t, f) in &o.nodes {
                    if f > f_max {
                        (f_max, f_max_t) = (f, t);
                    }
                }
                if phase == Phase::Compression {
                    sv.records.push(o.rec.clone());
                }
                emit(&sv, &mut samples, &o.rec, phase, out_times, &mut next_out)?;
            }
            push(&mut hist, &first.end, phase, &mut sv);
            push(&mut hist, &second.end, phase, &mut sv);
            st = second.end;
            h *= grow(err);
            continue;
        }
        // Event inside (0, h]: land on it with a secant/bisection on the step length.
        let g = |sv: &mut Solver, o: &(StepOut, StepOut, f64)| -> f64 {
            match phase {
                Phase::Compression => o.1.end.v,
                Phase::Restitution | Phase::FlatRelease => sv.psi(&o.1.end),
            }
        };
        let (mut lo, mut hi) = (0.0f64, h);
        let g_lo = match phase {
            Phase::Compression => st.v,
            Phase::Restitution | Phase::FlatRelease => sv.psi(&st),
        };
        let mut g_hi = {
            let full = (first, second, err);
            g(&mut sv, &full)
        };
        let mut g_lo_v = g_lo;
        let mut best: Option<(StepOut, StepOut, f64)> = None;
        let mut hl = hi;
        for it in 0..100u32 {
            // regula falsi with Illinois safeguard; bisection every fourth iteration
            let mut x = if it % 4 == 3 || g_hi == g_lo_v {
                0.5 * (lo + hi)
            } else {
                lo - g_lo_v * (hi - lo) / (g_hi - g_lo_v)
            };
            if !(x > lo && x < hi) {
                x = 0.5 * (lo + hi);
            }
            let o = sv.doubled(phase, &st, x, tol)?;
            let gx = g(&mut sv, &o);
            let scale = match phase {
                Phase::Compression => 1.0,
                Phase::Restitution | Phase::FlatRelease => {
                    sv.prony.glassy() * st.d.abs().max(1e-300)
                }
            };
            if gx.abs() <= REF_EVENT_TOL * scale || (hi - lo) <= 1e-15 * st.t.max(x) {
                hl = x;
                best = Some(o);
                break;
            }
            if gx > 0.0 {
                lo = x;
                g_lo_v = gx;
            } else {
                hi = x;
                g_hi = gx;
            }
        }
        let Some(o) = best else {
            return Err(Error::NoConvergence {
                what: "event location (reference impact)",
                iterations: 100,
            });
        };
        if o.2 > 1.0 {
            // the landing step is not accurate enough: shorten and keep stepping
            h = hl * grow(o.2).min(0.9);
            continue;
        }
        let (first, mut second, _) = o;
        for oo in [&first, &second] {
            for &(t, f) in &oo.nodes {
                if f > f_max {
                    (f_max, f_max_t) = (f, t);
                }
            }
        }
        // samples inside the two half steps (compression samples read the step's own record;
        // restitution samples need the compression records, complete by then)
        for rec in [&first.rec, &second.rec] {
            emit(&sv, &mut samples, rec, phase, out_times, &mut next_out)?;
        }
        match phase {
            Phase::Compression => {
                sv.records.push(first.rec.clone());
                sv.records.push(second.rec.clone());
                push(&mut hist, &first.end, phase, &mut sv);
                second.end.v = 0.0;
                push(&mut hist, &second.end, phase, &mut sv);
                st = second.end;
                sv.t_m = st.t;
                d_max = st.d;
                st.t1 = st.t;
                phase = if sv.geom.is_flat() {
                    Phase::FlatRelease
                } else {
                    Phase::Restitution
                };
                h = hl.max(H0);
            }
            Phase::Restitution | Phase::FlatRelease => {
                // free flight after separation: d = d_end + v_end (t - t_end), no force
                if let Some(hh) = samples.as_mut() {
                    for &t in &out_times[next_out..] {
                        let d = second.end.d + second.end.v * (t - second.end.t);
                        hh.push(t, d, second.end.v, 0.0, 0.0);
                    }
                }
                if samples.is_some() {
                    hist = samples.take();
                }
                push(&mut hist, &first.end, phase, &mut sv);
                second.end.force = 0.0;
                second.end.t1 = 0.0;
                push(&mut hist, &second.end, phase, &mut sv);
                let cor = -second.end.v;
                if f_max_t < sv.t_m {
                    f_max = f_max.max(sv.refine_max_force(f_max_t));
                }
                return Ok(Run {
                    cor,
                    t_end: second.end.t,
                    t_m: sv.t_m,
                    d_max,
                    f_max,
                    steps,
                    evals: sv.evals,
                    history: hist,
                });
            }
        }
    }
}

/// Reference impact in canonical units (`m = R = v0 = 1`, `prony` = `G_eq` in units of `G_inf`),
/// solved from the Lee–Radok/Ting formulation (module docs) to relative accuracy `rtol` in the CoR.
///
/// The outcome is in canonical units: `max_contact_radius = sqrt(d_max)`, `dissipated_energy =
/// (1 - e^2)/2`, `cor_error_estimate` the difference to a run with a 30 times coarser local
/// tolerance, solver `"reference"`. With `history`, samples `(t, d, v, F, a)` at the step ends.
///
/// Errors: [`Error::OutOfRange`] for `rtol` outside `[1e-13, 0.1]` or an invalid series,
/// [`Error::AccuracyNotReached`] when the estimate stays above `rtol` after the refinement levels,
/// and the step / iteration limits of the module.
///
/// ```
/// # use mdr_impact::model::material::Prony;
/// # use mdr_impact::solvers::theory::reference::impact;
/// // Elastic, incompressible (G_eq = 1): Hertz with E* = 4, contact time 2 I (15/64)^(2/5).
/// let o = impact(&Prony { relaxed: 1.0, terms: vec![] }, 1e-10, false).unwrap();
/// assert!((o.cor - 1.0).abs() < 1e-12);
/// let tc = 2.943_275_184_324_704_7 * (15.0f64 / 64.0).powf(0.4);
/// assert!((o.contact_time - tc).abs() < 1e-10 * tc);
/// ```
pub fn impact(prony: &Prony, rtol: f64, history: bool) -> Result<Outcome> {
    impact_on(Geometry::UNIT_SPHERE, prony, rtol, history)
}

/// As [`impact`], for the indenter `geometry` (canonical units of its shape,
/// [`crate::model::geometry`]): Lee–Radok and Ting with the shape's `w(d)` and `a(d)` in place
/// of `d^(3/2)` and `sqrt(d)`; a flat punch keeps its contact radius and separates where the
/// force returns to zero.
pub fn impact_on(geometry: Geometry, prony: &Prony, rtol: f64, history: bool) -> Result<Outcome> {
    let sampling = if history {
        Sampling::StepEnds
    } else {
        Sampling::None
    };
    solve(geometry, prony, rtol, sampling, 0)
}

/// As [`impact`], with the history sampled at `samples >= 2` equally spaced times over
/// `[0, t_c]`, `t_c` the contact time of the first (coarser) run; samples after the final
/// separation are free flight (`F = a = 0`, `d = d_end + v_end (t - t_end)`). Forces at the
/// samples are evaluated from the dense record (compression: `q_k` exactly integrated over the
/// partial step; restitution: Ting's root at that time), so the sample grid does not depend on the
/// adaptive steps.
pub fn impact_sampled(prony: &Prony, rtol: f64, samples: usize) -> Result<Outcome> {
    impact_sampled_on(Geometry::UNIT_SPHERE, prony, rtol, samples)
}

/// As [`impact_sampled`], for the indenter `geometry` ([`impact_on`]).
pub fn impact_sampled_on(
    geometry: Geometry,
    prony: &Prony,
    rtol: f64,
    samples: usize,
) -> Result<Outcome> {
    if samples < 2 {
        return Err(Error::OutOfRange {
            field: "samples",
            value: samples as f64,
            allowed: "samples >= 2",
        });
    }
    solve(geometry, prony, rtol, Sampling::None, samples)
}

/// As [`impact`], with the history sampled at the given ascending `times` (forces from the dense
/// record, as in [`impact_sampled`]; times after the separation are free flight). For comparing
/// another solver's history point by point, without interpolating the reference.
pub fn impact_at(prony: &Prony, rtol: f64, times: &[f64]) -> Result<Outcome> {
    if times.is_empty() || times.windows(2).any(|w| !(w[1] >= w[0])) || !(times[0] >= 0.0) {
        return Err(Error::OutOfRange {
            field: "sample times",
            value: times.first().copied().unwrap_or(f64::NAN),
            allowed: "a non-empty ascending list of times >= 0",
        });
    }
    solve(
        Geometry::UNIT_SPHERE,
        prony,
        rtol,
        Sampling::Times(times.to_vec()),
        0,
    )
}

/// As [`impact_at`], for the indenter `geometry` ([`impact_on`]).
pub fn impact_at_on(
    geometry: Geometry,
    prony: &Prony,
    rtol: f64,
    times: &[f64],
) -> Result<Outcome> {
    if times.is_empty() || times.windows(2).any(|w| !(w[1] >= w[0])) || !(times[0] >= 0.0) {
        return Err(Error::OutOfRange {
            field: "sample times",
            value: times.first().copied().unwrap_or(f64::NAN),
            allowed: "a non-empty ascending list of times >= 0",
        });
    }
    solve(geometry, prony, rtol, Sampling::Times(times.to_vec()), 0)
}

fn solve(
    geom: Geometry,
    prony: &Prony,
    rtol: f64,
    sampling: Sampling,
    samples: usize,
) -> Result<Outcome> {
    check(
        "rtol",
        rtol,
        (1e-13..=0.1).contains(&rtol),
        "1e-13 <= rtol <= 0.1",
    )?;
    prony.validate()?;
    let mut tol = (REF_LOCAL_FACTOR * rtol).max(MIN_LOCAL_TOL);
    let mut coarse = run(geom, prony, tol, &Sampling::None)?;
    let sampling = if samples >= 2 {
        let tc = coarse.t_end;
        Sampling::Times(
            (0..samples)
                .map(|i| tc * i as f64 / (samples - 1) as f64)
                .collect(),
        )
    } else {
        sampling
    };
    let mut work = Work {
        steps: coarse.steps,
        evaluations: coarse.evals,
        ..Work::default()
    };
    let mut est = f64::INFINITY;
    // in the glassy corner the difference of two runs is accepted only well below rtol
    let glassy = prony.glassy() > super::REF_GLASSY_RATIO * prony.relaxed;
    let required = if glassy {
        super::REF_GLASSY_SAFETY * rtol
    } else {
        rtol
    };
    // in the glassy corner the runs share an error the difference does not see: a request
    // below REF_GLASSY_ABS_FLOOR / e is refused as soon as a run shows it
    let glassy_floor = |cor: f64, levels: u32| {
        let floor = super::REF_GLASSY_ABS_FLOOR / cor.abs();
        if glassy && floor > rtol {
            Err(Error::AccuracyNotReached {
                solver: "reference",
                rtol,
                estimate: floor,
                required,
                levels,
            })
        } else {
            Ok(())
        }
    };
    glassy_floor(coarse.cor, 0)?;
    for level in 1..=MAX_LEVELS {
        let next = (tol / LEVEL_RATIO).max(MIN_LOCAL_TOL);
        if next >= tol {
            // at the floor: two runs at the same tolerance would agree and prove nothing
            return Err(Error::AccuracyNotReached {
                solver: "reference",
                rtol,
                estimate: est,
                required,
                levels: level - 1,
            });
        }
        tol = next;
        let fine = run(geom, prony, tol, &sampling)?;
        work.steps += fine.steps;
        work.evaluations += fine.evals;
        work.levels = level;
        est = ((fine.cor - coarse.cor) / fine.cor).abs();
        glassy_floor(fine.cor, level)?;
        if est <= required {
            let e = fine.cor;
            return Ok(Outcome {
                cor: e,
                rebound_velocity: e,
                contact_time: fine.t_end,
                max_indentation: fine.d_max,
                time_of_max_indentation: fine.t_m,
                max_force: fine.f_max,
                max_contact_radius: geom.contact_radius(fine.d_max),
                dissipated_energy: 0.5 * (1.0 - e * e),
                cor_error_estimate: Some(est),
                history: fine.history,
                work,
                solver: Method::Reference,
                fallback: None,
            });
        }
        coarse = fine;
    }
    Err(Error::AccuracyNotReached {
        solver: "reference",
        rtol,
        estimate: est,
        required,
        levels: MAX_LEVELS,
    })
}
