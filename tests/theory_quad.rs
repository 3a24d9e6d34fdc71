//! The checked quadrature wrapper (style notes, habit 8).

use mdr_impact::math::quad::integrate;
use mdr_impact::math::special::dawson;
use mdr_impact::Error;

/// Known integrals to 1e-13; reversed limits flip the sign; a == b gives 0 with no evaluations.
#[test]
fn values_limits_and_counts() {
    let q = integrate("exp", f64::exp, 0.0, 1.0, &[], 1e-13).unwrap();
    assert!((q.value - (std::f64::consts::E - 1.0)).abs() <= 1e-13);
    assert!(q.evaluations > 0 && q.error_estimate <= 1e-13);
    let r = integrate("exp", f64::exp, 1.0, 0.0, &[], 1e-13).unwrap();
    assert_eq!(r.value, -q.value);
    let z = integrate("exp", f64::exp, 0.5, 0.5, &[], 1e-14).unwrap();
    assert_eq!((z.value, z.evaluations), (0.0, 0));
    // |x - 1/3| with the kink given: exact 5/18
    let k = integrate(
        "abs",
        |x: f64| (x - 1.0 / 3.0).abs(),
        0.0,
        1.0,
        &[1.0 / 3.0],
        1e-13,
    )
    .unwrap();
    assert!((k.value - 5.0 / 18.0).abs() <= 1e-13);
    // the raw rule would have needed far more work without the split
    // Dawson by quadrature: exp(-x^2) int_0^x exp(y^2) dy at x = 2
    let d = integrate("dawson", |y: f64| (y * y - 4.0).exp(), 0.0, 2.0, &[], 1e-14).unwrap();
    assert!((d.value - dawson(2.0)).abs() <= 1e-14);
}

/// Non-finite integrand values are errors (the raw rule would silently use 0).
#[test]
fn rejects_non_finite() {
    let e = integrate("1/x", |x: f64| 1.0 / x, -1.0, 1.0, &[], 1e-10).unwrap_err();
    assert!(matches!(e, Error::NonFinite { what: "1/x", .. }), "{e:?}");
    let e = integrate("nan", |_| f64::NAN, 0.0, 1.0, &[], 1e-10).unwrap_err();
    assert!(matches!(e, Error::NonFinite { .. }));
}

/// An unreachable tolerance is reported with the estimate, never returned silently.
#[test]
fn reports_unconverged() {
    let e = integrate(
        "oscillatory",
        |x: f64| (1000.0 * x).sin() * x.sqrt().sin(),
        0.0,
        50.0,
        &[],
        1e-15,
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            Error::Quadrature {
                what: "oscillatory",
                ..
            }
        ),
        "{e:?}"
    );
    let e = integrate("bad tol", f64::exp, 0.0, 1.0, &[], 0.0).unwrap_err();
    assert!(matches!(e, Error::OutOfRange { field: "tol", .. }));
    let e = integrate("bad limit", f64::exp, 0.0, f64::INFINITY, &[], 1e-6).unwrap_err();
    assert!(matches!(e, Error::OutOfRange { field: "b", .. }));
}
