//! `mdr` on general linear-viscoelastic materials: the element network built from `G(t)` and
//! `K(t)` (a shear branch in series with a `K + G/3` branch, each a generalised Maxwell element),
//! an MDR path independent of the Carson composition of `G_eq` that `fast` and `reference`
//! integrate. Checked against `fast` at 1e-10; the one-term case against the standard solid;
//! `mdr-euler` refuses general materials with one line.

use mdr_impact::model::material::{BulkInput, BulkProny, BulkRheology, ShearProny};
use mdr_impact::{solve, Error, Impact, Material, Resolution, SolverKind, Sphere};
use std::time::Instant;

use crate::common;
use common::opts;

fn sphere() -> Sphere {
    Sphere::new(4.11e-3, 5.0e-3).unwrap()
}

/// `n` shear terms log-spaced over `[lo, hi]` s with moduli `g_i = 3e6 (tau_i / 1e-3)^(-0.2)`
/// Pa, `g_inf = 1e6` Pa, and a viscoelastic bulk of three terms (the contact time is ~4 ms).
fn general(n: usize, lo: f64, hi: f64) -> Impact {
    let bulk = BulkProny::new(2.0e7, &[(4.0e7, 2.0e-5), (1.0e7, 1.0e-3), (3.0e7, 3.0e-2)]).unwrap();
    with_bulk(n, lo, hi, BulkInput::Prony(bulk))
}

/// The shear series of [`general`] with another bulk.
fn with_bulk(n: usize, lo: f64, hi: f64, bulk: BulkInput) -> Impact {
    let terms: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            let tau = lo * (hi / lo).powf(i as f64 / (n - 1) as f64);
            (3.0e6 * (tau / 1e-3).powf(-0.2), tau)
        })
        .collect();
    let m = Material::general(ShearProny::new(1.0e6, &terms).unwrap(), bulk).unwrap();
    Impact::with_general(sphere(), 0.99, m).unwrap()
}

/// `mdr` at rtol 1e-4 and 1e-6 against `fast` at 1e-10 for 3, 10 and 30 shear terms with a viscoelastic
/// bulk (and 10 terms with an elastic and an incompressible bulk, and an elastic shear with the
/// viscoelastic bulk): within rtol, and within a few times its own error estimate.
#[test]
fn mdr_agrees_with_fast() {
    let cases = [
        (3, 1e-4, 1e-2, None),
        (10, 1e-7, 1e2, None),
        (30, 1e-10, 1e10, None),
        (10, 1e-7, 1e2, Some(BulkInput::Poisson(0.3))),
        (10, 1e-7, 1e2, Some(BulkInput::Incompressible)),
        // elastic shear, viscoelastic bulk: G_eq relaxes through the bulk alone
        (0, 1.0, 1.0, None),
    ];
    for (n, lo, hi, bulk) in cases {
        let imp = match bulk {
            None => general(n, lo, hi),
            Some(b) => with_bulk(n, lo, hi, b),
        };
        let fast = solve(&imp, &opts(SolverKind::Fast, 1e-10)).unwrap();
        for rtol in [1e-4, 1e-6] {
            let start = Instant::now();
            let o = solve(&imp, &opts(SolverKind::Mdr, rtol)).unwrap();
            let secs = start.elapsed().as_secs_f64();
            assert_eq!(o.solver, "mdr");
            let err = (o.cor / fast.cor - 1.0).abs();
            let est = o.cor_error_estimate.unwrap();
            eprintln!(
            "{n} shear terms, {} ({} G_eq terms), rtol {rtol:.0e}: mdr e = {:.10} vs fast {:.10}: error \
             {err:.2e}, estimate {est:.2e}, {} levels, {} element updates, {:.1} ms",
            match imp.general_material().unwrap().bulk() {
                BulkRheology::Prony(_) => "viscoelastic bulk",
                BulkRheology::Incompressible => "incompressible",
                _ => "elastic bulk",
            },
            imp.canonical_relaxation().terms.len(),
            o.cor,
            fast.cor,
            o.work.levels,
            o.work.element_updates,
            1e3 * secs
        );
            assert!(err < rtol, "{n} terms: error {err:e}");
            assert!(
                err < 4.0 * est.max(0.01 * rtol),
                "{n} terms: error {err:e}, estimate {est:e}"
            );
            // the contact time and the maximum force agree too (to the discretisation)
            assert!((o.contact_time / fast.contact_time - 1.0).abs() < 1e-2);
            assert!((o.max_force / fast.max_force - 1.0).abs() < 1e-2);
        }
    }
}

/// An explicit resolution runs the network (also through `auto`), and refining it converges to
/// `fast`.
#[test]
fn explicit_resolution_converges() {
    let imp = general(3, 1e-4, 1e-2);
    let fast = solve(&imp, &opts(SolverKind::Fast, 1e-10)).unwrap().cor;
    let mut errs = Vec::new();
    for (elements, steps) in [(25, 100), (50, 200), (100, 400)] {
        let mut o = opts(SolverKind::Auto, 1e-4);
        o.resolution = Some(Resolution { elements, steps });
        let r = solve(&imp, &o).unwrap();
        assert_eq!(r.solver, "mdr");
        errs.push((r.cor - fast).abs() / fast);
    }
    eprintln!("explicit resolutions: errors {errs:?}");
    assert!(errs[2] < errs[0] / 4.0, "{errs:?}");
    assert!(errs[2] < 1e-3, "{errs:?}");
}

/// The standard solid written as a one-term Prony series has the standard solid's shape: the
/// same groups, and every solver takes the same path and gives the same outcome to the bit (the
/// relaxation time is the one `eta / G_1` the standard-solid constructor stores). The general
/// network of the same solid (the route of a multi-term material) agrees with the closed-form
/// route to its discretisation error, within its rtol of `fast`.
#[test]
fn one_term_series_is_the_standard_solid() {
    use mdr_impact::model::material::GeneralNetwork;
    use mdr_impact::{solvers::canonical_material, solvers::mdr};
    for nu in [0.5, 0.49, 0.3] {
        let m = Material::with_poisson(1.0e6, 1.0e7, 500.0, nu).unwrap();
        let shear = ShearProny::new(1.0e6, &[(1.0e7, 500.0 / 1.0e7)]).unwrap();
        let series = Material::general(shear, BulkInput::Poisson(nu)).unwrap();
        assert!(series.as_standard_solid().is_some());
        let standard = Impact::new(sphere(), 0.99, m).unwrap();
        let general = Impact::new(sphere(), 0.99, series).unwrap();
        assert!(general.general_material().is_none());
        let (ga, gb) = (standard.groups().unwrap(), general.groups().unwrap());
        assert_eq!((ga.nu, ga.p2), (gb.nu, gb.p2));
        assert!((ga.p3 / gb.p3 - 1.0).abs() < 1e-15);
        assert_eq!(
            standard.equivalent_relaxation(),
            general.equivalent_relaxation()
        );
        for (solver, rtol) in [
            (SolverKind::Auto, 1e-6),
            (SolverKind::Fast, 1e-6),
            (SolverKind::Reference, 1e-6),
            (SolverKind::Mdr, 1e-4),
        ] {
            let a = solve(&standard, &opts(solver, rtol)).unwrap();
            let b = solve(&general, &opts(solver, rtol)).unwrap();
            assert_eq!(a.cor.to_bits(), b.cor.to_bits(), "{solver}");
            assert_eq!(a.contact_time.to_bits(), b.contact_time.to_bits());
            assert_eq!(a.work, b.work, "{solver}");
        }
        let rtol = 1e-6;
        let f = solve(&standard, &opts(SolverKind::Fast, 1e-11)).unwrap();
        let mut c = canonical_material(&standard).unwrap();
        let s = standard.scales();
        let net = GeneralNetwork::new(standard.half_space().unwrap(), s.modulus, s.time);
        c.network = mdr::Network::General(net);
        let b = mdr::solve_rtol(mdr::Scheme::Exponential, &c, rtol, false, u64::MAX).unwrap();
        let eb = (b.cor / f.cor - 1.0).abs();
        eprintln!("nu {nu}: general-network mdr error {eb:.2e}");
        assert!(eb < rtol, "{eb:e}");
    }
}

/// `mdr-euler` (the paper's explicit Euler, on the dashpot positions of the general network)
/// converges at first order to `reference` on a 3-term material with a viscoelastic bulk: on
/// fixed grids the error halves (ratio 1.7 to 2.3) with each doubling of the steps, and its
/// adaptive driver answers within rtol 1e-3; a one-term series equals the standard solid's Euler
/// network.
#[test]
fn mdr_euler_takes_general_material() {
    let imp = general(3, 1e-4, 1e-2);
    let truth = solve(&imp, &opts(SolverKind::Reference, 1e-10))
        .unwrap()
        .cor;
    let err = |steps: usize| {
        let mut o = opts(SolverKind::MdrEuler, 1e-4);
        o.resolution = Some(Resolution {
            elements: 400,
            steps,
        });
        (solve(&imp, &o).unwrap().cor - truth).abs() / truth
    };
    let (e1, e2, e3) = (err(1000), err(2000), err(4000));
    for ratio in [e1 / e2, e2 / e3] {
        assert!((1.7..2.3).contains(&ratio), "{e1:e} {e2:e} {e3:e}");
    }
    let adaptive = solve(&imp, &opts(SolverKind::MdrEuler, 1e-3)).unwrap();
    assert_eq!(adaptive.solver, "mdr-euler");
    assert!((adaptive.cor - truth).abs() <= 1e-3 * truth);
    // two viscoelastic bodies stay refused, with one line
    let two = mdr_impact::report::catalogue::TWO_BODIES[0]
        .impact()
        .unwrap();
    let e = solve(&two, &opts(SolverKind::MdrEuler, 1e-3)).unwrap_err();
    assert!(matches!(
        e,
        Error::NotSupported {
            solver: "mdr-euler",
            ..
        }
    ));
    assert_eq!(
        e.to_string(),
        mdr_impact::solvers::MDR_EULER_GENERAL_UNSUPPORTED
    );
    // the standard solid's Euler network of Eq. (8) and the general network of the same solid
    // (one shear term, elastic bulk), on one grid
    use mdr_impact::model::material::GeneralNetwork;
    use mdr_impact::{solvers::canonical_material, solvers::mdr};
    let m = mdr_impact::Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.45).unwrap();
    let imp = Impact::new(sphere(), 0.99, m).unwrap();
    let a = canonical_material(&imp).unwrap();
    assert!(matches!(a.network, mdr::Network::StandardSolid(_)));
    let mut b = a.clone();
    let s = imp.scales();
    let net = GeneralNetwork::new(imp.half_space().unwrap(), s.modulus, s.time);
    b.network = mdr::Network::General(net);
    let layout = mdr::pilot(&a.prony).unwrap();
    let grid = mdr::Grid::from_layout(&layout, 200, 2000);
    let (oa, ob) = (
        mdr::run_euler(&a, &grid, 4000, false).unwrap(),
        mdr::run_euler(&b, &grid, 4000, false).unwrap(),
    );
    assert!(
        (oa.cor / ob.cor - 1.0).abs() < 1e-12,
        "{} vs {}",
        oa.cor,
        ob.cor
    );
}
