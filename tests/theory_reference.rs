//! Reference impact solver (Lee–Radok/Ting, exponential collocation): elastic limit, convergence
//! in rtol, agreement with the prescribed-history theory on its own trajectory, slow-relaxation
//! asymptote, input errors.

use mdr_impact::model::hertz::HertzImpact;
use mdr_impact::solvers::theory::reference::impact;
use mdr_impact::solvers::theory::viscoelastic::{response, OneMaximum};
use mdr_impact::{Error, History};

use crate::common;
use common::canonical;

/// Elastic series: e = 1 to 1e-12, contact time, maximum indentation and force equal Hertz with
/// `E* = 4 c_inf` to 1e-10 (relative).
#[test]
fn elastic_limit_is_hertz() {
    for nu in [0.5, 0.3, 0.0, -0.5] {
        let pr = canonical(nu, 1.0, 0.0);
        let o = impact(&pr, 1e-10, false).unwrap();
        let h = HertzImpact::canonical(4.0 * pr.relaxed).unwrap();
        assert!((o.cor - 1.0).abs() < 1e-12, "nu={nu}: {}", o.cor);
        let rel = |a: f64, b: f64| ((a - b) / b).abs();
        assert!(rel(o.contact_time, h.contact_time()) < 1e-10, "nu={nu}");
        assert!(
            rel(o.max_indentation, h.max_indentation()) < 1e-10,
            "nu={nu}"
        );
        assert!(
            rel(o.time_of_max_indentation, h.peak_time()) < 1e-10,
            "nu={nu}"
        );
        assert!(rel(o.max_force, h.max_force()) < 1e-9, "nu={nu}");
        assert!(o.dissipated_energy.abs() < 1e-12);
        assert_eq!(o.solver, "reference");
    }
}

/// Convergence in rtol and honesty of the estimate: the answers at rtol = 1e-6 and 1e-9 are within
/// their rtol of the answer at 1e-11, and each reported estimate is below its rtol.
#[test]
fn converges_in_rtol() {
    for (nu, p2, p3) in [(0.3, 0.1, 1.0), (0.49, 1e-4, 1.0), (0.0, 0.1, 1e-3)] {
        let pr = canonical(nu, p2, p3);
        let fine = impact(&pr, 1e-11, false).unwrap();
        for rtol in [1e-6, 1e-9] {
            let o = impact(&pr, rtol, false).unwrap();
            assert!(o.cor_error_estimate.unwrap() <= rtol);
            let err = ((o.cor - fine.cor) / fine.cor).abs();
            assert!(err <= rtol, "({nu},{p2},{p3}) rtol={rtol}: {err:e}");
        }
        assert!(fine.cor > 0.0 && fine.cor < 1.0);
        let de = 0.5 * (1.0 - fine.cor * fine.cor);
        assert!((fine.dissipated_energy - de).abs() < 1e-15);
    }
}

/// Stiff relaxation (tau / t_contact ~ 1e-7): solved to rtol 1e-10 with a bounded amount of work.
#[test]
fn stiff_cases_are_cheap() {
    for (nu, p2, p3) in [(0.49, 1e-4, 1e-3), (-0.9, 1e-4, 1e-3), (0.3, 1e-3, 1e-4)] {
        let pr = canonical(nu, p2, p3);
        assert!(pr.min_tau() < 1e-6);
        let o = impact(&pr, 1e-10, false).unwrap();
        assert!(o.cor > 0.9 && o.cor < 1.0, "{}", o.cor);
        assert!(o.work.steps < 2_000, "steps {}", o.work.steps);
    }
}

/// The impact's trajectory as a prescribed history: quintic Hermite interpolation of
/// `(d, d', d'' = -F)` between the recorded step ends (error O(h^6)).
struct Trajectory {
    h: History,
    t_m: f64,
    t_end: f64,
}

impl Trajectory {
    fn locate(&self, t: f64) -> Option<(usize, f64, f64)> {
        let ts = &self.h.t;
        if t <= 0.0 || t >= self.t_end {
            return None;
        }
        let j = ts.partition_point(|&x| x <= t).clamp(1, ts.len() - 1) - 1;
        let dt = ts[j + 1] - ts[j];
        Some((j, (t - ts[j]) / dt, dt))
    }
    fn eval(&self, t: f64) -> (f64, f64) {
        let Some((j, s, dt)) = self.locate(t) else {
            return (0.0, 0.0);
        };
        let h = &self.h;
        let (p0, m0, a0) = (h.d[j], h.v[j] * dt, -h.force[j] * dt * dt);
        let (p1, m1, a1) = (h.d[j + 1], h.v[j + 1] * dt, -h.force[j + 1] * dt * dt);
        let (s2, s3, s4, s5) = (s * s, s * s * s, s.powi(4), s.powi(5));
        let h00 = 1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5;
        let h10 = s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5;
        let h20 = 0.5 * (s2 - 3.0 * s3 + 3.0 * s4 - s5);
        let h01 = 10.0 * s3 - 15.0 * s4 + 6.0 * s5;
        let h11 = -4.0 * s3 + 7.0 * s4 - 3.0 * s5;
        let h21 = 0.5 * (s3 - 2.0 * s4 + s5);
        let d = h00 * p0 + h10 * m0 + h20 * a0 + h01 * p1 + h11 * m1 + h21 * a1;
        let dh00 = -30.0 * s2 + 60.0 * s3 - 30.0 * s4;
        let dh10 = 1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4;
        let dh20 = 0.5 * (2.0 * s - 9.0 * s2 + 12.0 * s3 - 5.0 * s4);
        let dh01 = 30.0 * s2 - 60.0 * s3 + 30.0 * s4;
        let dh11 = -12.0 * s2 + 28.0 * s3 - 15.0 * s4;
        let dh21 = 0.5 * (3.0 * s2 - 8.0 * s3 + 5.0 * s4);
        let v = (dh00 * p0 + dh10 * m0 + dh20 * a0 + dh01 * p1 + dh11 * m1 + dh21 * a1) / dt;
        (d, v)
    }
}

impl OneMaximum for Trajectory {
    fn depth(&self, t: f64) -> f64 {
        self.eval(t).0.max(0.0)
    }
    fn rate(&self, t: f64) -> f64 {
        self.eval(t).1
    }
    fn peak_time(&self) -> f64 {
        self.t_m
    }
    fn end_time(&self) -> f64 {
        self.t_end
    }
    /// The interpolant is piecewise: every recorded time is a breakpoint.
    fn kinks(&self) -> Vec<f64> {
        self.h.t.clone()
    }
}

/// The reference solver's force equals the Lee–Radok/Ting force (quadrature, independent code
/// path) of its own trajectory to 1e-6 of the peak force (limited by the O(h^6) interpolation of
/// the recorded trajectory, not by either solver).
#[test]
fn force_agrees_with_prescribed_history_theory() {
    for (nu, p2, p3) in [(0.3, 0.1, 1.0), (0.0, 0.1, 0.3)] {
        let pr = canonical(nu, p2, p3);
        let o = impact(&pr, 1e-11, true).unwrap();
        let h = o.history.clone().unwrap();
        let traj = Trajectory {
            h: h.clone(),
            t_m: o.time_of_max_indentation,
            t_end: o.contact_time,
        };
        let idx: Vec<usize> = (1..h.len() - 1).step_by((h.len() / 25).max(1)).collect();
        let times: Vec<f64> = idx.iter().map(|&i| h.t[i]).collect();
        let lr = response(&pr, 1.0, &traj, &times).unwrap();
        for (k, &i) in idx.iter().enumerate() {
            let diff = (lr[k].force - h.force[i]).abs();
            assert!(
                diff < 1e-6 * o.max_force,
                "({nu},{p2},{p3}) t={}: {} vs {}",
                h.t[i],
                lr[k].force,
                h.force[i]
            );
            assert!((lr[k].a - h.a[i]).abs() < 1e-6, "t={}: a", h.t[i]);
        }
    }
}

/// Slow relaxation (tau >> t_contact): 1 - e ~ (4/9) t_c0 (sum c_k / tau_k) / G_eq(0), t_c0 the
/// Hertz contact time with the glassy modulus; relative agreement better than 5 t_c0 / tau.
#[test]
fn slow_relaxation_asymptote() {
    for (nu, p2, p3) in [(0.3, 1.0, 1e4), (0.5, 0.1, 3e4)] {
        let pr = canonical(nu, p2, p3);
        let o = impact(&pr, 1e-11, false).unwrap();
        let tc0 = HertzImpact::canonical(4.0 * pr.glassy())
            .unwrap()
            .contact_time();
        let pred = 4.0 / 9.0 * tc0 * (-pr.initial_slope()) / pr.glassy();
        let rel = ((1.0 - o.cor) - pred).abs() / pred;
        assert!(
            rel < 5.0 * tc0 / pr.min_tau(),
            "({nu},{p2},{p3}): {} vs {pred} ({rel:e})",
            1.0 - o.cor
        );
    }
}

/// Input errors name the field.
#[test]
fn input_errors() {
    let pr = canonical(0.3, 0.1, 1.0);
    let e = impact(&pr, 0.0, false).unwrap_err();
    assert!(
        matches!(e, Error::OutOfRange { field: "rtol", .. }),
        "{e:?}"
    );
    let mut bad = pr.clone();
    bad.terms[0].tau = -1.0;
    let e = impact(&bad, 1e-6, false).unwrap_err();
    assert!(matches!(e, Error::OutOfRange { field: "tau", .. }), "{e:?}");
}

/// The maximum force is the maximum of the continuous Lee–Radok force (not a node value): it
/// is reached before the maximum indentation, and the recorded history never exceeds it; it
/// agrees between rtol = 1e-10 and 1e-11 to 1e-9 (node values alone are off by ~5e-4 here).
#[test]
fn max_force_is_refined() {
    let pr = canonical(0.3, 0.1, 1.0);
    let o = impact(&pr, 1e-11, true).unwrap();
    let h = o.history.unwrap();
    let hmax = h.force.iter().copied().fold(0.0, f64::max);
    assert!(hmax <= o.max_force * (1.0 + 1e-12));
    let coarse = impact(&pr, 1e-10, false).unwrap();
    let rel = ((coarse.max_force - o.max_force) / o.max_force).abs();
    assert!(
        rel < 1e-9,
        "{} vs {} ({rel:e}), node max {hmax}",
        coarse.max_force,
        o.max_force
    );
    let i = h.force.iter().position(|&f| f == hmax).unwrap();
    assert!(h.t[i] < o.time_of_max_indentation);
}

/// Sampled histories (dense output): in the elastic case every sample equals the exact Hertz
/// trajectory (d to 1e-10, F to 1e-9 of the peak); in a dissipative case the last sample is free
/// flight with velocity -e and no force, and no sample exceeds the maximum force.
#[test]
fn sampled_history() {
    use mdr_impact::solvers::theory::reference::impact_sampled;
    let pr = canonical(0.3, 1.0, 0.0);
    let o = impact_sampled(&pr, 1e-11, 41).unwrap();
    let hz = HertzImpact::canonical(4.0 * pr.relaxed).unwrap();
    let h = o.history.unwrap();
    assert_eq!(h.len(), 41);
    for i in 0..h.len() {
        let (d, v) = hz.state(h.t[i]).unwrap();
        assert!(
            (h.d[i] - d).abs() < 1e-10,
            "t={}: {} vs {d}",
            h.t[i],
            h.d[i]
        );
        assert!(
            (h.v[i] - v).abs() < 1e-9 || i == 0 || i == h.len() - 1,
            "t={}",
            h.t[i]
        );
        let f = hz.force_at_depth(d);
        assert!(
            (h.force[i] - f).abs() < 1e-9 * hz.max_force(),
            "t={}",
            h.t[i]
        );
    }
    let pr = canonical(0.3, 0.1, 1.0);
    let o = impact_sampled(&pr, 1e-10, 64).unwrap();
    let h = o.history.unwrap();
    let n = h.len() - 1;
    assert!((h.v[n] + o.cor).abs() < 1e-12 && h.force[n].abs() < 1e-12);
    assert!(h
        .force
        .iter()
        .all(|&f| f <= o.max_force * (1.0 + 1e-12) && f >= 0.0));
    assert!(impact_sampled(&pr, 1e-10, 1).is_err());
}

/// Histories at given times (`impact_at`): the same forces as the uniform sampling at the same
/// times, any ascending times accepted (also past the separation: free flight, no force), and
/// bad time lists refused.
#[test]
fn history_at_given_times() {
    use mdr_impact::solvers::theory::reference::{impact_at, impact_sampled};
    let pr = canonical(0.3, 0.1, 1.0);
    let uniform = impact_sampled(&pr, 1e-10, 33).unwrap();
    let hu = uniform.history.unwrap();
    let at = impact_at(&pr, 1e-10, &hu.t).unwrap();
    let ha = at.history.unwrap();
    assert_eq!(ha.len(), hu.len());
    let peak = uniform.max_force;
    for i in 0..hu.len() {
        assert!(
            (ha.force[i] - hu.force[i]).abs() <= 1e-9 * peak,
            "t={}",
            hu.t[i]
        );
        assert!((ha.d[i] - hu.d[i]).abs() <= 1e-10, "t={}", hu.t[i]);
    }
    let late = [0.0, 1e-6, 0.5, 2.0 * uniform.contact_time];
    let h = impact_at(&pr, 1e-10, &late).unwrap().history.unwrap();
    assert_eq!(h.len(), late.len());
    assert_eq!(h.force[3], 0.0);
    assert!(impact_at(&pr, 1e-10, &[]).is_err());
    assert!(impact_at(&pr, 1e-10, &[0.5, 0.1]).is_err());
    assert!(impact_at(&pr, 1e-10, &[-1.0]).is_err());
}
