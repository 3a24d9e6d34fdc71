//! Lee–Radok/Ting for prescribed histories: quadrature path against the independent closed form
//! (Dawson) for the triangle; elastic limits; Hertz trajectory.

use mdr_impact::model::material::{Prony, PronyTerm};
use mdr_impact::solvers::indentation::Prescribed;
use mdr_impact::solvers::theory::viscoelastic::{response, separation_time, triangle_closed_form};
use mdr_impact::{Groups, Material};

fn cases() -> Vec<(&'static str, Prony)> {
    let canon = |nu, p2, p3| {
        Groups::new(nu, p2, p3)
            .unwrap()
            .canonical_material()
            .unwrap()
            .equivalent_relaxation()
            .unwrap()
    };
    vec![
        ("dissipative nu=0.3", canon(0.3, 0.1, 1.0)),
        ("strong nu=0.49", canon(0.49, 1e-2, 0.2)),
        ("compressible nu=0", canon(0.0, 0.1, 3.0)),
        ("stiff tau=1e-6 nu=0.3", canon(0.3, 1e-3, 1e-3)),
        (
            "stiff tau=1e-4",
            Prony {
                relaxed: 1.0,
                terms: vec![PronyTerm {
                    coefficient: 50.0,
                    tau: 1e-4,
                }],
            },
        ),
    ]
}

/// Force (relative to the peak force), t1 and separation time agree to 1e-12 (measured: 4e-14;
/// the brief asks 1e-10) between the
/// quadrature path and the closed form for the triangle.
#[test]
fn triangle_quadrature_matches_closed_form() {
    let (v, tp, r) = (1.3, 0.8, 0.7);
    let h = Prescribed::triangle(v, tp).unwrap();
    let times: Vec<f64> = (0..=80).map(|i| 2.0 * tp * i as f64 / 80.0).collect();
    for (name, prony) in cases() {
        let (exact, ts_exact) = triangle_closed_form(&prony, r, v, tp, &times).unwrap();
        let num = response(&prony, r, &h, &times).unwrap();
        let ts = separation_time(&prony, r, &h).unwrap();
        assert!(
            (ts - ts_exact).abs() < 1e-12 * tp,
            "{name}: ts {ts} vs {ts_exact}"
        );
        assert!(ts_exact > tp && ts_exact < 2.0 * tp, "{name}: {ts_exact}");
        let fmax = exact.iter().map(|s| s.force).fold(0.0, f64::max);
        assert!(fmax > 0.0);
        for (a, b) in num.iter().zip(&exact) {
            assert!(
                (a.force - b.force).abs() < 1e-12 * fmax,
                "{name} t={}: {} vs {}",
                a.t,
                a.force,
                b.force
            );
            assert!((a.t1 - b.t1).abs() < 1e-12 * tp, "{name} t={}: t1", a.t);
            assert!(
                (a.a - b.a).abs() < 1e-9 * (r * v * tp).sqrt(),
                "{name} t={}",
                a.t
            );
        }
    }
}

/// Elastic series: F = (16/3) G sqrt(R) d^(3/2) on loading and unloading, t1 mirrors t,
/// separation at the end of the history (half sine, Hertz trajectory).
#[test]
fn elastic_is_hertzian_force_law() {
    let prony = Material::with_poisson(1.0, 0.0, 0.0, 0.25)
        .unwrap()
        .equivalent_relaxation()
        .unwrap();
    let r = 2.0;
    for h in [
        Prescribed::half_sine(1.0, 1.0).unwrap(),
        Prescribed::hertz_impact(1.0, 1.0).unwrap(),
    ] {
        let times: Vec<f64> = (1..40).map(|i| 2.0 * i as f64 / 40.0).collect();
        let out = response(&prony, r, &h, &times).unwrap();
        let k = 16.0 / 3.0 * prony.relaxed * r.sqrt();
        for s in &out {
            let f = k * s.d.powf(1.5);
            assert!(
                (s.force - f).abs() < 1e-11 * k,
                "t={} {} {}",
                s.t,
                s.force,
                f
            );
        }
        assert_eq!(separation_time(&prony, r, &h).unwrap(), 2.0);
    }
}

/// Half sine and Hertz trajectory: force positive until separation, zero after; t1 decreasing;
/// separation before the end of the history for a dissipative material.
#[test]
fn viscoelastic_half_sine_and_hertz_trajectory() {
    let (_, prony) = cases().remove(0);
    for h in [
        Prescribed::half_sine(1.0, 1.0).unwrap(),
        Prescribed::hertz_impact(1.0, 1.0).unwrap(),
    ] {
        let ts = separation_time(&prony, 1.0, &h).unwrap();
        assert!(ts > 1.0 && ts < 2.0, "{ts}");
        let times: Vec<f64> = (1..60).map(|i| 2.0 * i as f64 / 60.0).collect();
        let out = response(&prony, 1.0, &h, &times).unwrap();
        let mut last_t1 = f64::INFINITY;
        for s in &out {
            if s.t < ts {
                assert!(s.force > 0.0, "t={}", s.t);
                if s.t > 1.0 {
                    assert!(s.t1 < last_t1);
                    last_t1 = s.t1;
                }
            } else {
                assert_eq!((s.force, s.a), (0.0, 0.0));
            }
        }
    }
}
