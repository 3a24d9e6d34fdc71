//! Hertz closed forms (docs/theory.md §6) and the exact trajectory.

use approx::assert_relative_eq;
use mdr_impact::math::special::hyp2f1_series;
use mdr_impact::model::hertz::HertzImpact;
use mdr_impact::model::hertz::HERTZ_I;
use mdr_impact::solvers::indentation::Prescribed;

/// `2 I = 2.9432751843247047` (mpmath, 30 digits: 2.94327518432470465738178730008).
#[test]
fn contact_time_coefficient() {
    assert_relative_eq!(2.0 * HERTZ_I, 2.943_275_184_324_704_7, max_relative = 1e-12);
    let h = HertzImpact::canonical(4.0).unwrap();
    assert_relative_eq!(
        h.contact_time() / h.max_indentation(),
        2.943_275_184_324_704_7,
        max_relative = 1e-12
    );
}

/// Closed forms against their definitions, canonical incompressible (E* = 4):
/// k = 16/3, d_max = (15/64)^(2/5), F_max = k d_max^(3/2).
#[test]
fn closed_forms() {
    let h = HertzImpact::canonical(4.0).unwrap();
    assert_relative_eq!(h.stiffness(), 16.0 / 3.0, max_relative = 1e-15);
    let dm = (15.0f64 / 64.0).powf(0.4);
    assert_relative_eq!(h.max_indentation(), dm, max_relative = 1e-15);
    assert_relative_eq!(
        h.max_force(),
        16.0 / 3.0 * dm.powf(1.5),
        max_relative = 1e-15
    );
    assert_relative_eq!(h.max_contact_radius(), dm.sqrt(), max_relative = 1e-15);
    let o = h.outcome(Some(11)).unwrap();
    assert_eq!(o.solver, "hertz");
    assert_eq!(o.cor, 1.0);
    assert_eq!(o.dissipated_energy, 0.0);
    assert_eq!(o.history.as_ref().unwrap().len(), 11);
}

/// The 2F1 series against mpmath values (hyp2f1(0.4,0.5,1.4,0.3) = 1.04973401392694042839...).
#[test]
fn hypergeometric_series() {
    assert_relative_eq!(
        hyp2f1_series(0.4, 0.5, 1.4, 0.3).unwrap(),
        1.049_734_013_926_940_4,
        max_relative = 1e-15
    );
    assert!(hyp2f1_series(0.4, 0.5, 1.4, 0.9).is_err());
}

/// The trajectory satisfies energy conservation `v^2 = v0^2 (1 - (d/d_max)^(5/2))`, inverts
/// `time_at_depth` to 1e-13, and `d'' = -F/m` (central differences, 1e-6).
#[test]
fn trajectory_is_exact() {
    let h = HertzImpact::new(2.0, 0.5, 3.0, 7.0).unwrap();
    let (dm, tc, v0) = (h.max_indentation(), h.contact_time(), 3.0);
    for i in 1..200 {
        let t = tc * i as f64 / 200.0;
        let (d, v) = h.state(t).unwrap();
        let x = (d / dm).powf(2.5);
        assert!(
            (v * v - v0 * v0 * (1.0 - x)).abs() < 1e-13 * v0 * v0,
            "t={t}"
        );
        if t < 0.5 * tc {
            assert_relative_eq!(h.time_at_depth(d).unwrap(), t, max_relative = 1e-13);
        }
        let dt = 1e-4 * tc;
        if t > dt && t < tc - dt {
            let acc = (h.depth(t + dt).unwrap() - 2.0 * d + h.depth(t - dt).unwrap()) / (dt * dt);
            assert!(
                (acc + h.force_at_depth(d) / 2.0).abs() < 1e-6 * h.max_force(),
                "t={t}"
            );
        }
    }
    // symmetric, peak at t_m
    assert_relative_eq!(h.depth(h.peak_time()).unwrap(), dm, max_relative = 1e-15);
    assert_relative_eq!(
        h.depth(0.3 * tc).unwrap(),
        h.depth(0.7 * tc).unwrap(),
        max_relative = 1e-14
    );
}

/// The Prescribed::HertzImpact variant reproduces the trajectory: peak depth V T / I.
#[test]
fn prescribed_variant() {
    let p = Prescribed::hertz_impact(2.0, 1.5).unwrap();
    assert_relative_eq!(p.peak_depth(), 2.0 * 1.5 / HERTZ_I, max_relative = 1e-14);
    assert_relative_eq!(p.rate(1e-9), 2.0, max_relative = 1e-9);
    assert_relative_eq!(p.rate(1.5), 0.0, epsilon = 1e-12);
    assert_eq!(p.end_time(), 3.0);
    assert!(p.kinks().is_empty());
    assert!(Prescribed::hertz_impact(-1.0, 1.0).is_err());
}

/// SI Hertz outcome of a dimensional impact equals the canonical one mapped with the impact's
/// scales (`Outcome::to_si`), to 1e-12: the closed forms respect the scaling of Eq. (11).
#[test]
fn si_outcome_matches_canonical_scaled() {
    use mdr_impact::model::hertz::hertz_outcome;
    use mdr_impact::{Impact, Material, Sphere};
    let m = Material::with_poisson(3e6, 0.0, 0.0, 0.3).unwrap();
    let imp = Impact::new(Sphere::new(0.012, 0.004).unwrap(), 1.7, m.clone()).unwrap();
    let si = hertz_outcome(&imp, None).unwrap();
    let m = m.as_standard_solid().unwrap();
    let e_star = m.effective_modulus(m.g_inf()) / m.g_inf();
    let can = HertzImpact::canonical(e_star)
        .unwrap()
        .outcome(None)
        .unwrap()
        .to_si(&imp);
    for (a, b) in [
        (si.contact_time, can.contact_time),
        (si.max_indentation, can.max_indentation),
        (si.max_force, can.max_force),
        (si.max_contact_radius, can.max_contact_radius),
        (si.rebound_velocity, can.rebound_velocity),
    ] {
        assert_relative_eq!(a, b, max_relative = 1e-12);
    }
}
