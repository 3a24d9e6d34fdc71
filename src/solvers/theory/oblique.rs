//! The reference route of oblique impacts (docs/theory.md §14.4), sharing no code with the MDR's
//! tangential foundation ([`crate::solvers::mdr::oblique`]).
//!
//! - the normal history `d(t)` and the contact radius `a(t)` come from the Lee–Radok/Ting
//!   reference solver ([`super::reference::impact_at_on`]) on the independently derived
//!   `G_eq` ([`Contact::independent_g_eq`]), sampled on a uniform grid of `steps` intervals over
//!   the contact time;
//! - the contact line is sampled at two-point Gauss–Legendre nodes on `panels` panels over
//!   `[0, a_max]` (not the MDR's cell midpoints); a node enters when `d` passes `g(x)` (its
//!   entry time interpolated inside the interval) and leaves when Ting's `a(t)` passes it, so the
//!   MDR's rule (an element leaves when its own force returns to zero) is checked against Ting's
//!   contact radius rather than assumed;
//! - each node's normal line load is the hereditary integral of `G_eq` over `d - g(x)` since its
//!   entry and its tangential line load that of `G_t / 4` over its own displacement, both with
//!   `d` and the displacement linear between samples; the node sticks or slides under the
//!   Coulomb limit of its own normal load;
//! - the impactor's slip velocity is advanced by Heun's explicit predictor–corrector
//!   (`v_c' = -lambda Q`), not by the MDR's implicit trapezoidal root.
//!
//! The exact limits it meets: gross slip (the impulse `mu (1 + e) m v0`), and for an elastic
//! material whose nodes never slip, the closed form of the no-slip hereditary integral
//! (docs/theory.md §14.3) that the tests evaluate separately.

use crate::error::{Error, Result};
use crate::model::contact::Contact;
use crate::model::impact::Outcome;
use crate::model::oblique::Tangential;

/// Default samples of the normal history over the contact time.
pub const OBLIQUE_REF_STEPS: usize = 4000;
/// Default Gauss–Legendre panels over the largest contact radius.
pub const OBLIQUE_REF_PANELS: usize = 400;

/// The reference route's result (canonical units).
#[derive(Debug, Clone)]
pub struct ReferenceOblique {
    /// The normal outcome of the reference solver (with its history at the sample times).
    pub normal: Outcome,
    /// Tangential impulse (units `m v0`).
    pub impulse: f64,
    /// Friction work (units `m v0^2`).
    pub friction_work: f64,
    /// Slip velocity after the impact (units `v0`).
    pub slip_velocity: f64,
    /// Rows `[t, Q, slip radius, v_c]`.
    pub rows: Vec<[f64; 4]>,
}

/// The reference route with its default discretisation ([`OBLIQUE_REF_STEPS`],
/// [`OBLIQUE_REF_PANELS`]); `rtol` is the normal reference solver's.
pub fn solve(contact: &Contact, tangential: &Tangential, rtol: f64) -> Result<ReferenceOblique> {
    solve_with(
        contact,
        tangential,
        rtol,
        OBLIQUE_REF_STEPS,
        OBLIQUE_REF_PANELS,
    )
}

/// One node of the contact line.
#[derive(Debug, Clone)]
struct Node {
    x: f64,
    weight: f64,
    g: f64,
    /// 0: not yet entered, 1: in contact, 2: left.
    phase: u8,
    hn: Vec<f64>,
    ht: Vec<f64>,
    w: f64,
    q: f64,
}

/// The reference route on `steps` sample intervals and `panels` Gauss–Legendre panels.
pub fn solve_with(
    contact: &Contact,
    tangential: &Tangential,
    rtol: f64,
    steps: usize,
    panels: usize,
) -> Result<ReferenceOblique> {
    if steps < 16 || panels < 4 {
        return Err(Error::OutOfRange {
            field: "steps or panels",
            value: steps.min(panels) as f64,
            allowed: "steps >= 16, panels >= 4",
        });
    }
    let geometry = contact.geometry;
    let gn = contact.independent_g_eq()?;
    let first = super::reference::impact_on(geometry, gn, rtol, false)?;
    let t_end = 1.02 * first.contact_time;
    let times: Vec<f64> = (0..=steps)
        .map(|i| t_end * i as f64 / steps as f64)
        .collect();
    let normal = super::reference::impact_at_on(geometry, gn, rtol, &times)?;
    let h = normal
        .history
        .as_ref()
        .ok_or(Error::Internal("the sampled reference run has no history"))?;
    let a_max = h.a.iter().copied().fold(0.0, f64::max) * 1.0001;
    let i_peak = (0..h.len())
        .max_by(|&i, &j| h.d[i].total_cmp(&h.d[j]))
        .unwrap_or(0);
    // nodes: two-point Gauss–Legendre per panel
    let off = 0.5 / 3f64.sqrt();
    let width = a_max / panels as f64;
    let (kn, kt) = (gn.terms.len(), tangential.g_t.terms.len());
    let mut nodes: Vec<Node> = Vec::with_capacity(2 * panels);
    for p in 0..panels {
        for s in [-off, off] {
            let x = (p as f64 + 0.5 + s) * width;
            nodes.push(Node {
                x,
                weight: 0.5 * width,
                g: geometry.profile(x),
                phase: 0,
                hn: vec![0.0; kn],
                ht: vec![0.0; kt],
                w: 0.0,
                q: 0.0,
            });
        }
    }
    let gt = &tangential.g_t;
    let (mu, lambda) = (tangential.friction, tangential.compliance);
    let (mut v, mut force, mut impulse, mut work) = (tangential.slip_velocity, 0.0, 0.0, 0.0);
    let mut rows = vec![[0.0, 0.0, 0.0, v]];
    for i in 0..steps {
        let dt = h.t[i + 1] - h.t[i];
        let (d0, d1) = (h.d[i], h.d[i + 1]);
        let rate = (d1 - d0) / dt;
        let restitution = i + 1 > i_peak;
        let a1 = h.a[i + 1];
        // tangential predictor
        let v_pred = v - lambda * dt * force;
        let du = 0.5 * dt * (v + v_pred);
        let mut total = 0.0;
        let mut slip_radius: Option<f64> = None;
        for node in nodes.iter_mut() {
            // normal state at the end of the interval; the part of the interval in contact
            let span = match node.phase {
                0 if !restitution && d1 > node.g && rate > 0.0 => {
                    let since = ((d1 - node.g) / rate).min(dt);
                    for (k, t) in gn.terms.iter().enumerate() {
                        node.hn[k] = -t.tau * (-since / t.tau).exp_m1() * rate;
                    }
                    node.phase = 1;
                    since
                }
                1 if restitution && node.x >= a1 => {
                    node.phase = 2;
                    node.q = 0.0;
                    0.0
                }
                1 => {
                    for (k, t) in gn.terms.iter().enumerate() {
                        let e = (-dt / t.tau).exp();
                        node.hn[k] = e * node.hn[k] - t.tau * (-dt / t.tau).exp_m1() * rate;
                    }
                    dt
                }
                _ => 0.0,
            };
            if node.phase != 1 || !(span > 0.0) {
                continue;
            }
            let limit = mu * normal_load(node, gn, d1).max(0.0);
            let slid = tangential_update(node, gt, span, du * span / dt, limit, &mut work);
            if slid && slip_radius.is_none_or(|r| node.x - 0.5 * width < r) {
                slip_radius = Some((node.x - 0.5 * width).max(0.0));
            }
            total += node.weight * node.q;
        }
        let q1 = 8.0 * total;
        impulse += 0.5 * dt * (force + q1);
        v -= lambda * 0.5 * dt * (force + q1);
        force = q1;
        let slip_radius = slip_radius.unwrap_or(a1).min(a1);
        rows.push([h.t[i + 1], force, slip_radius, v]);
        if !(v.is_finite() && force.is_finite()) {
            return Err(Error::NonFinite {
                what: "reference tangential state",
                value: v + force,
            });
        }
    }
    Ok(ReferenceOblique {
        normal,
        impulse,
        friction_work: work,
        slip_velocity: v,
        rows,
    })
}

/// Normal line load (per `4`, the hereditary response of `G_eq`) of a node in contact at `d`.
fn normal_load(node: &Node, gn: &crate::model::material::Prony, d: f64) -> f64 {
    let mut f = gn.relaxed * (d - node.g);
    for (k, t) in gn.terms.iter().enumerate() {
        f += t.coefficient * node.hn[k];
    }
    f
}

/// Advance a node's tangential state over `dt` by the contact-point motion `du` (its
/// displacement linear over the interval) under the Coulomb `limit` of its end-of-interval normal
/// load; adds the slip work (8 times the node weight times the mean force times the slip) to
/// `work` and returns whether the node slid.
fn tangential_update(
    node: &mut Node,
    gt: &crate::model::material::Prony,
    dt: f64,
    du: f64,
    limit: f64,
    work: &mut f64,
) -> bool {
    let mut a = gt.relaxed * node.w;
    let mut b = gt.relaxed;
    let mut decay = Vec::with_capacity(gt.terms.len());
    for (k, t) in gt.terms.iter().enumerate() {
        let e = (-dt / t.tau).exp();
        let beta = -t.tau * (-dt / t.tau).exp_m1() / dt;
        a += t.coefficient * e * node.ht[k];
        b += t.coefficient * beta;
        decay.push((e, beta));
    }
    let trial = a + b * du;
    let (q, dw, slid) = if trial.abs() <= limit {
        (trial, du, false)
    } else {
        let q = limit.copysign(trial);
        (q, (q - a) / b, true)
    };
    if slid {
        *work += 8.0 * node.weight * 0.5 * (q + node.q) * (du - dw);
    }
    for (k, (e, beta)) in decay.into_iter().enumerate() {
        node.ht[k] = e * node.ht[k] + beta * dw;
    }
    node.w += dw;
    node.q = q;
    slid
}

/// The no-slip limit (`mu -> inf`, docs/theory.md §14.3): the slip velocity after the impact
/// (units `v0`) from the tangential hereditary integral
///
/// ```text
/// Q(t) = 8 int_0^t (G_t/4)(t - t') min(a*(t'), a(t)) u'(t') dt',   a*(t') = max_{s <= t'} a(s)
/// ```
///
/// (every point of the contact line sticks from its entry, when `a` first reaches it, until
/// Ting's `a(t)` passes it again), with `v_c' = -lambda Q` and `u' = v_c`, on `steps` uniform
/// intervals of the Lee–Radok/Ting normal history: midpoint rule in the hereditary integral,
/// trapezoidal rule for the impactor. `O(steps^2)` work.
pub fn no_slip(contact: &Contact, tangential: &Tangential, rtol: f64, steps: usize) -> Result<f64> {
    if steps < 16 {
        return Err(Error::OutOfRange {
            field: "steps",
            value: steps as f64,
            allowed: "steps >= 16",
        });
    }
    let gn = contact.independent_g_eq()?;
    let first = super::reference::impact_on(contact.geometry, gn, rtol, false)?;
    let t_end = 1.02 * first.contact_time;
    let times: Vec<f64> = (0..=steps)
        .map(|i| t_end * i as f64 / steps as f64)
        .collect();
    let normal = super::reference::impact_at_on(contact.geometry, gn, rtol, &times)?;
    let h = normal
        .history
        .as_ref()
        .ok_or(Error::Internal("the sampled reference run has no history"))?;
    let dt = t_end / steps as f64;
    let gt = &tangential.g_t;
    let lambda = tangential.compliance;
    // a*(t) at the sample times
    let mut a_star = Vec::with_capacity(h.len());
    let mut m = 0.0f64;
    for &a in &h.a {
        m = m.max(a);
        a_star.push(m);
    }
    let (mut v, mut q) = (tangential.slip_velocity, 0.0);
    let mut du: Vec<f64> = Vec::with_capacity(steps);
    let k_self = 8.0 * gt.eval(0.5 * dt);
    for n in 0..steps {
        let a1 = h.a[n + 1];
        // the known part of Q_{n+1}
        let t1 = h.t[n + 1];
        let mut s = 0.0;
        for (j, d) in du.iter().enumerate() {
            let tm = 0.5 * (h.t[j] + h.t[j + 1]);
            s += gt.eval(t1 - tm) * a_star[j + 1].min(a1) * d;
        }
        s *= 8.0;
        let c = lambda * dt * dt / 4.0;
        let step = (dt * v - c * (q + s)) / (1.0 + c * k_self * a1);
        let q1 = s + k_self * a1 * step;
        v -= lambda * 0.5 * dt * (q + q1);
        q = q1;
        du.push(step);
    }
    if !v.is_finite() {
        return Err(Error::NonFinite {
            what: "no-slip tangential integral",
            value: v,
        });
    }
    Ok(v)
}
