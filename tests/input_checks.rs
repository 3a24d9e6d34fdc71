//! Inputs are answered or refused, never silently bent: the dimensionless groups.

use mdr_impact::{solve, Error, Groups, Impact, SolveOptions};

fn refused(r: mdr_impact::Result<Groups>, f: &str) {
    match r {
        Err(Error::OutOfRange { field, .. }) => assert_eq!(field, f),
        other => panic!("expected OutOfRange({f}), got {other:?}"),
    }
}

/// `p3 = 0` is the elastic limit (Hertz, e = 1); non-finite groups and values outside the ranges
/// are refused with the group named.
#[test]
fn groups_elastic_limit_and_refusals() {
    let g = Groups::new(0.3, 1.0, 0.0).unwrap();
    let o = solve(&Impact::from_groups(g).unwrap(), &SolveOptions::default()).unwrap();
    assert_eq!(o.cor, 1.0);
    assert_eq!(o.solver, "hertz");
    refused(Groups::new(0.3, f64::INFINITY, 1.0), "p2");
    refused(Groups::new(0.3, "1e999".parse().unwrap(), 1.0), "p2");
    refused(Groups::new(0.3, 1e-310, 1.0), "p2");
    refused(Groups::new(0.3, 0.0, 1.0), "p2");
    refused(Groups::new(0.3, 1.0, -1.0), "p3");
    refused(Groups::new(0.3, 1.0, f64::INFINITY), "p3");
    refused(Groups::new(0.5000001, 1.0, 1.0), "nu");
    refused(Groups::new(f64::NAN, 1.0, 1.0), "nu");
    refused(Groups::new(0.3, f64::NAN, 1.0), "p2");
    refused(Groups::new(0.3, 1.0, f64::NAN), "p3");
    let e = Groups::new(0.3, f64::INFINITY, 1.0)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("p2 = inf is out of range") && e.contains("p3 = 0"),
        "{e}"
    );
}
