//! Dawson's integral against mpmath (`sqrt(pi)/2 exp(-x^2) erfi(x)`, 30 digits).
// Reference values are kept with all the digits mpmath printed (provenance), beyond f64 precision.
#![allow(clippy::excessive_precision)]

use approx::assert_relative_eq;
use mdr_impact::math::special::{dawson, x_minus_dawson};

const MPMATH: &[(f64, f64)] = &[
    (1e-3, 0.000_999_999_333_333_600_020_7),
    (0.1, 0.099_335_992_397_852_866_51),
    (0.5, 0.424_436_383_502_022_295_93),
    (1.0, 0.538_079_506_912_768_419_14),
    (2.0, 0.301_340_388_923_791_966_03),
    (3.0, 0.178_271_030_610_558_287_34),
    (5.5, 0.092_493_232_310_754_759_967),
    (6.5, 0.077_867_818_986_069_871_389),
    (10.0, 0.050_253_847_187_598_528_033),
    (30.0, 0.016_675_941_401_059_175_798),
];

/// Relative error below 1e-15 at every tabulated point (both branches), odd symmetry.
#[test]
fn dawson_matches_mpmath() {
    for &(x, d) in MPMATH {
        assert_relative_eq!(dawson(x), d, max_relative = 1e-15);
        assert_eq!(dawson(-x), -dawson(x));
    }
}

/// `x - D(x)` is accurate for small x (series `2x^3/3 - 4x^5/15 + ...`) and continuous at the switch.
#[test]
fn x_minus_dawson_small_and_switch() {
    let x: f64 = 1e-3;
    let series = 2.0 * x.powi(3) / 3.0 - 4.0 * x.powi(5) / 15.0 + 8.0 * x.powi(7) / 105.0;
    assert_relative_eq!(x_minus_dawson(x), series, max_relative = 1e-15);
    let below = x_minus_dawson(1.0 - 1e-15);
    let above = x_minus_dawson(1.0);
    assert_relative_eq!(below, above, max_relative = 1e-14);
    assert_relative_eq!(
        above,
        1.0 - 0.538_079_506_912_768_419_14,
        max_relative = 1e-15
    );
}
