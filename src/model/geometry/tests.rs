//! Tests of the geometry: `w` against the integral of the profile, the cap series, the
//! canonical scales.

use super::*;

fn num_w(g: &Geometry, d: f64) -> f64 {
    let a = g.contact_radius(d);
    let n = 20_000;
    let h = a / n as f64;
    // midpoint rule of 1.5 int_0^a (d - g)
    (0..n)
        .map(|i| d - g.profile((i as f64 + 0.5) * h))
        .sum::<f64>()
        * h
        * 1.5
}

#[test]
fn force_function_is_the_integral_of_the_profile() {
    let shapes = [
        Geometry::UNIT_SPHERE,
        Geometry::PowerLaw {
            exponent: 1.0,
            coefficient: 1.0,
        },
        Geometry::PowerLaw {
            exponent: 3.5,
            coefficient: 2.5,
        },
        Shape::sphere(1e-3).canonical(1e-3, 1.0, 1e6).2,
        Shape::Spheres {
            caps: [
                Cap {
                    radius: 2e-3,
                    exact: true,
                },
                Cap {
                    radius: 3e-3,
                    exact: false,
                },
            ],
        }
        .canonical(1e-3, 3.0, 1e6)
        .2,
    ];
    for g in shapes {
        for d in [1e-3, 0.1, 0.7, 1.3] {
            let (w, n) = (g.force_function(d), num_w(&g, d));
            assert!((w - n).abs() < 1e-6 * n, "{g:?} d {d}: {w} vs {n}");
            assert!((g.profile(g.contact_radius(d)) - d).abs() < 1e-13 * d);
            // w' = 1.5 a by a central difference
            let h = 1e-6 * d;
            let fd = (g.force_function(d + h) - g.force_function(d - h)) / (2.0 * h);
            assert!((fd - g.force_slope(d)).abs() < 1e-6 * fd, "{g:?} d {d}");
        }
    }
}

#[test]
fn cap_series_meets_the_closed_form() {
    for u in [0.19, 0.1999999, 0.2, 0.35, 0.5] {
        let closed = (1.0 + u * u) * f64::atanh(u) - u;
        assert!((cap_psi(u) - closed).abs() < 5e-15 * closed, "{u}");
    }
    // the leading term 4/3 u^3 for small u
    assert!((cap_psi(1e-5) / (4.0 / 3.0 * 1e-15) - 1.0).abs() < 1e-9);
}

#[test]
fn cap_atanh_tail_is_atanh_without_a_logarithm() {
    // u (1 + T(u^2)) against libm's atanh below the series' bound: a few units in the last place
    for i in 1..=2000 {
        let u = CAP_SERIES_U * f64::from(i) / 2000.0;
        let series = u + u * cap_atanh_tail(u * u);
        assert!(
            (series - u.atanh()).abs() <= 4.0 * f64::EPSILON * u.atanh(),
            "{u}"
        );
    }
    // T itself against its terms summed from the smallest, far beyond the 13 kept (tiny and
    // largest x of its range)
    for x in [1e-12_f64, 1e-6, 1e-3, 0.01, 0.039_999] {
        let direct: f64 = (1..=40)
            .rev()
            .map(|k| x.powi(k) / f64::from(2 * k + 1))
            .sum();
        assert!(
            (cap_atanh_tail(x) - direct).abs() <= 2.0 * f64::EPSILON * direct,
            "{x}"
        );
    }
}

#[test]
fn canonical_scales_balance_the_energy() {
    // G A L^2 = m v^2 for every shape, and the paraboloid of the power law n = 2
    let (m, v, g) = (2e-3, 1.7, 3e6);
    for s in [
        Shape::Paraboloid { radius: 4e-3 },
        Shape::sphere(4e-3),
        Shape::Cone {
            half_angle_deg: 70.3,
        },
        Shape::PowerLaw {
            exponent: 3.0,
            coefficient: 50.0,
        },
        Shape::Flat { radius: 1e-3 },
    ] {
        let (l, a, _) = s.canonical(m, v, g);
        assert!((g * a * l * l / (m * v * v) - 1.0).abs() < 1e-13, "{s:?}");
    }
    let p = Shape::PowerLaw {
        exponent: 2.0,
        coefficient: 0.5 / 4e-3,
    }
    .canonical(m, v, g);
    let q = Shape::Paraboloid { radius: 4e-3 }.canonical(m, v, g);
    assert!((p.0 / q.0 - 1.0).abs() < 1e-14 && p.2 == q.2);
    assert!((power_law_stretch(2.0) - 2.0).abs() < 1e-14);
    assert!((power_law_stretch(1.0) - std::f64::consts::FRAC_PI_2).abs() < 1e-14);
}
