//! Core properties: the element network relaxes like G_eq, scaling invariance, energy balance,
//! the elastic (Hertz) case, convergence of both MDR schemes to one CoR, and every error variant.

use approx::assert_relative_eq;
use mdr_impact::model::material::ElementNetwork;
use mdr_impact::solvers::mdr;
use mdr_impact::*;
use nalgebra::{Matrix2, Vector2};

use crate::common;
use common::{case_groups, case_impact, opts};

/// The network of Eq. (8) under a unit step of u relaxes exactly like the closed-form G_eq(t).
/// The linear ODE w' = A w + b is solved exactly with the matrix exponential of the 2x2 state
/// matrix (Sylvester's formula from its eigenvalues, which come from its trace and determinant:
/// nothing of the closed form of G_eq is used). The f64 evaluation of the network loses digits
/// as G_0 / G_eq(t) times the condition of the state matrix grows (the G_1 spring elongation is
/// the small difference u2 - w3): at nu = -0.9 with G_1 / G_inf = 1000 the agreement is 2.5e-11
/// in f64 while a 40-digit evaluation agrees to 1e-37, so the cases below stay where f64 can
/// show 1e-12.
#[test]
fn element_network_relaxes_like_equivalent_relaxation() {
    for (nu, g1, eta) in [
        (0.45, 100.0, 1.0),
        (0.0, 10.0, 2.5),
        (-0.9, 30.0, 0.3),
        (0.499, 3.0, 7.0),
        (0.5, 50.0, 1.0),
    ] {
        let m = Material::with_poisson(1.0, g1, eta, nu)
            .unwrap()
            .as_standard_solid()
            .unwrap();
        let net = ElementNetwork::new(&m);
        let g = m.equivalent_relaxation();
        let col = |w1, w3| {
            let (a, b) = net.rates(0.0, w1, w3);
            Vector2::new(a, b)
        };
        let a = Matrix2::from_columns(&[col(1.0, 0.0), col(0.0, 1.0)]);
        let (b1, b3) = net.rates(1.0, 0.0, 0.0);
        let b = Vector2::new(b1, b3);
        let a_inv = a.try_inverse().unwrap();
        for t in [0.0, 1e-3, 0.01, 0.1, 0.5, 1.0, 3.0, 10.0, 100.0] {
            let e = expm2(&a, t);
            let w = a_inv * (e - Matrix2::identity()) * b;
            let f = net.force(1.0, w[0], w[1]);
            assert_relative_eq!(f, g.eval(t), max_relative = 1e-12);
        }
    }
}

/// `exp(A t)` of a 2x2 matrix with real distinct eigenvalues (Sylvester's formula).
fn expm2(a: &Matrix2<f64>, t: f64) -> Matrix2<f64> {
    let tr = a.trace();
    let det = a.determinant();
    let disc = (tr * tr - 4.0 * det).sqrt();
    // larger-magnitude root first, the other from the product (no cancellation)
    let l1 = 0.5 * (tr - tr.signum() * disc);
    let l2 = det / l1;
    let i = Matrix2::identity();
    if (l1 - l2).abs() <= 1e-12 * l1.abs() {
        // repeated eigenvalue (incompressible: both branches relax with 1/tau)
        let l = 0.5 * (l1 + l2);
        return (i + (a - i * l) * t) * (l * t).exp();
    }
    ((a - i * l2) * (l1 * t).exp() - (a - i * l1) * (l2 * t).exp()) / (l1 - l2)
}

fn impact(nu: f64, p2: f64, p3: f64) -> Impact {
    Impact::from_groups(Groups::new(nu, p2, p3).unwrap()).unwrap()
}

/// Random dimensional inputs with the same (nu, p2, p3) give the same CoR (the paper's check).
#[test]
fn scaling_invariance() {
    let g = case_groups("dissipative-nu045");
    let (nu, p2, p3) = (g.nu, g.p2, g.p3);
    let base = solve(&impact(nu, p2, p3), &opts(SolverKind::Mdr, 1e-6)).unwrap();
    // deterministic pseudo-random dimensional inputs over many decades
    let mut rng = mdr_impact::rng::SplitMix64::new(12345);
    let mut rnd = || rng.uniform();
    for _ in 0..6 {
        let m = 10f64.powf(-4.0 + 6.0 * rnd());
        let r = 10f64.powf(-4.0 + 4.0 * rnd());
        let v0 = 10f64.powf(-2.0 + 3.0 * rnd());
        let g_inf = 10f64.powf(4.0 + 6.0 * rnd());
        let g_1 = g_inf / p2;
        let eta = p3 / (v0 * r / (m * m * g_inf.powi(3))).powf(0.2);
        let mat = Material::with_poisson(g_inf, g_1, eta, nu).unwrap();
        let imp = Impact::new(Sphere::new(m, r).unwrap(), v0, mat).unwrap();
        let g = imp.groups().unwrap();
        assert_relative_eq!(g.p3, p3, max_relative = 1e-12);
        let o = solve(&imp, &opts(SolverKind::Mdr, 1e-6)).unwrap();
        assert_relative_eq!(o.cor, base.cor, max_relative = 1e-9);
        // SI outcome scales like the Hertz scales
        let s = imp.scales();
        assert_relative_eq!(
            o.max_indentation / s.length,
            base.max_indentation,
            max_relative = 1e-9
        );
        assert_relative_eq!(
            o.contact_time / s.time,
            base.contact_time,
            max_relative = 1e-9
        );
    }
}

/// Dissipated energy m (v0^2 - v^2)/2 equals the work of the contact force, int F v dt, >= 0.
#[test]
fn energy_balance() {
    for (nu, p2, p3) in [(0.45, 0.01, 1.0), (0.0, 0.1, 0.3), (0.5, 1.0, 3.0)] {
        let mut o = opts(SolverKind::Mdr, 1e-6);
        o.history = true;
        let out = solve(&impact(nu, p2, p3), &o).unwrap();
        let h = out.history.as_ref().unwrap();
        let mut work = 0.0;
        for i in 1..h.len() {
            // trapezoidal rule is exactly the scheme's impulse; d increments are exact
            work += 0.5 * (h.force[i] + h.force[i - 1]) * (h.d[i] - h.d[i - 1]);
        }
        assert!(out.dissipated_energy > 0.0);
        assert_relative_eq!(work, out.dissipated_energy, max_relative = 1e-9);
        assert_relative_eq!(
            out.dissipated_energy,
            0.5 * (1.0 - out.cor * out.cor),
            max_relative = 1e-12
        );
    }
}

/// The elastic case through the MDR foundation: e = 1 to 1e-6 and the Hertz contact time.
#[test]
fn elastic_mdr_is_hertz() {
    for nu in [0.5, 0.3, -0.5] {
        // G_1 = 0 (p2 = inf, which Groups::new refuses as user input)
        let imp = Impact::from_groups(Groups {
            nu,
            p2: f64::INFINITY,
            p3: 1.0,
        })
        .unwrap();
        let mat = solvers::canonical_material(&imp).unwrap();
        let o = mdr::solve_rtol(mdr::Scheme::Exponential, &mat, 1e-7, false, u64::MAX).unwrap();
        assert_relative_eq!(o.cor, 1.0, max_relative = 1e-6);
        let k = 4.0 / 3.0 * imp.standard_solid().unwrap().effective_modulus(1.0);
        let d_max = (1.25 / k).powf(0.4);
        assert_relative_eq!(o.max_indentation, d_max, max_relative = 1e-5);
        assert_relative_eq!(
            o.contact_time,
            2.9432751843247047 * d_max,
            max_relative = 1e-4
        );
    }
}

/// Both MDR schemes converge to the same CoR; mdr-euler at first order.
#[test]
fn euler_converges_to_mdr() {
    let imp = case_impact("dissipative-nu045");
    let fine = solve(&imp, &opts(SolverKind::Mdr, 1e-7)).unwrap().cor;
    let mat = solvers::canonical_material(&imp).unwrap();
    let layout = mdr::pilot(&mat.prony).unwrap();
    let mut errs = Vec::new();
    for (n, m) in [(64, 512), (90, 1024), (128, 2048)] {
        let o = mdr::run_resolution(mdr::Scheme::Euler, &mat, &layout, n, m, false).unwrap();
        errs.push((o.cor - fine).abs());
    }
    let p1 = (errs[0] / errs[1]).log2();
    let p2 = (errs[1] / errs[2]).log2();
    assert!(
        (p1 - 1.0).abs() < 0.3 && (p2 - 1.0).abs() < 0.3,
        "orders {p1} {p2}, errors {errs:?}"
    );
}

#[test]
fn error_variants() {
    use Error::*;
    let bad = |r: Result<Material>, f: &str| match r {
        Err(OutOfRange { field, .. }) => assert_eq!(field, f),
        other => panic!("expected OutOfRange({f}), got {other:?}"),
    };
    // g_inf = 0 is a Maxwell fluid: a static Poisson ratio below 0.5 would give K_0 = 0, and
    // without a Maxwell term no modulus is left
    bad(Material::with_poisson(0.0, 1.0, 1.0, 0.3), "nu");
    bad(Material::with_poisson(0.0, 0.0, 1.0, 0.5), "g_inf");
    bad(Material::with_poisson(0.0, 1.0, 0.0, 0.5), "g_inf");
    bad(Material::with_poisson(-1.0, 1.0, 1.0, 0.3), "g_inf");
    bad(Material::with_poisson(f64::NAN, 1.0, 1.0, 0.3), "g_inf");
    bad(Material::with_poisson(1.0, -1.0, 1.0, 0.3), "g_1");
    bad(Material::with_poisson(1.0, 1.0, -1.0, 0.3), "eta");
    bad(Material::with_poisson(1.0, 1.0, f64::INFINITY, 0.3), "eta");
    bad(Material::with_poisson(1.0, 1.0, 1.0, -1.0), "nu");
    bad(Material::with_poisson(1.0, 1.0, 1.0, 0.51), "nu");
    bad(Material::new(1.0, 1.0, 1.0, 0.0), "k_0");
    assert!(matches!(
        Sphere::new(-1.0, 1.0),
        Err(OutOfRange { field: "mass", .. })
    ));
    assert!(matches!(
        Sphere::new(1.0, 0.0),
        Err(OutOfRange {
            field: "radius",
            ..
        })
    ));
    let mat = Material::with_poisson(1.0, 1.0, 1.0, 0.3).unwrap();
    let s = Sphere::new(1.0, 1.0).unwrap();
    assert!(matches!(
        Impact::new(s, 0.0, mat.clone()),
        Err(OutOfRange {
            field: "velocity",
            ..
        })
    ));
    assert!(matches!(
        Groups::new(0.3, 0.0, 1.0),
        Err(OutOfRange { field: "p2", .. })
    ));
    assert!(matches!(
        Groups::new(0.3, 1.0, -1.0),
        Err(OutOfRange { field: "p3", .. })
    ));
    // scales out of the f64 range
    let huge = Sphere::new(1e300, 1e-300).unwrap();
    assert!(matches!(
        Impact::new(huge, 1e300, mat),
        Err(OutOfScale { .. })
    ));
    // rtol range
    let imp = case_impact("dissipative-nu045");
    assert!(matches!(
        solve(&imp, &opts(SolverKind::Mdr, 0.0)),
        Err(OutOfRange { field: "rtol", .. })
    ));
    // explicit Euler above its stability bound
    let mut o = opts(SolverKind::MdrEuler, 1e-6);
    o.resolution = Some(Resolution {
        elements: 16,
        steps: 8,
    });
    assert!(matches!(
        solve(&imp, &o),
        Err(UnstableStep {
            scheme: "mdr-euler",
            ..
        })
    ));
    // explicit resolution beyond the work limit
    o.resolution = Some(Resolution {
        elements: 1_000_000,
        steps: 1_000_000_000,
    });
    assert!(matches!(solve(&imp, &o), Err(WorkLimit { .. })));
    o.resolution = Some(Resolution {
        elements: 1,
        steps: 100,
    });
    assert!(matches!(
        solve(&imp, &o),
        Err(OutOfRange {
            field: "elements",
            ..
        })
    ));
    // adaptive driver out of budget: refused as soon as the asymptotic rate predicts it (or
    // before its sequence is asymptotic, with the last change), never with an estimate that
    // would have been accepted
    let mut o = opts(SolverKind::MdrEuler, 1e-9);
    o.work_limit = 1_000_000;
    match solve(&imp, &o) {
        Err(WorkLimit {
            solver: "mdr-euler",
            needed,
            limit,
            ..
        }) => assert!(needed > limit),
        Err(AccuracyNotReached {
            solver: "mdr-euler",
            estimate,
            required,
            ..
        }) => assert!(estimate > required),
        Err(NotAsymptotic {
            solver: "mdr-euler",
            ..
        }) => {}
        other => panic!("unexpected {other:?}"),
    }
    assert!(matches!(
        "euler".parse::<SolverKind>(),
        Err(Error::Parse { what: "solver", .. })
    ));
    // a time loop that is not allowed enough steps to finish the contact
    let mat = solvers::canonical_material(&imp).unwrap();
    let layout = mdr::pilot(&mat.prony).unwrap();
    let mut grid = mdr::Grid::from_layout(&layout, 16, 32);
    grid.max_steps = 5;
    assert!(matches!(
        mdr::run_exponential(&mat.prony, &grid, 1000, false),
        Err(NoConvergence { .. })
    ));
    // a quadrature that cannot meet its tolerance
    let q = mdr_impact::math::quad::integrate(
        "oscillatory",
        |x: f64| (1e6 * x).sin() / x.sqrt().max(1e-300),
        0.0,
        1.0,
        &[],
        1e-15,
    );
    assert!(
        matches!(q, Err(Quadrature { .. }) | Err(NonFinite { .. })),
        "{q:?}"
    );
}
