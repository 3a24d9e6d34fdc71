//! Axisymmetric indenters (docs/theory.md §11, VALIDATION.md §14): the elastic closed forms of
//! every shape (power laws and cones by the Beta function, the flat punch as a harmonic
//! oscillator, Segedin's exact sphere by quadrature written here), the viscoelastic flat punch
//! as a linear ODE solved by the matrix exponential, the agreement of `reference` and `mdr` for
//! every shape on a standard solid, a three-term material and a real polymer spectrum, and the
//! limit exact sphere -> paraboloid as `a/R -> 0`.

mod common;

use common::{abs_rel_err, opts};
use mdr_impact::model::geometry::{power_law_stretch, Shape};
use mdr_impact::model::material::ShearProny;
use mdr_impact::{solve, BulkInput, Impact, Material, Outcome, SolverKind, Sphere};
use nalgebra::DMatrix;

const MASS: f64 = 4.11e-3;
const G: f64 = 1.0e6;

/// An elastic, incompressible half-space of shear modulus `G` (`E* = 4 G`).
fn elastic() -> Material {
    Material::general(ShearProny::new(G, &[]).unwrap(), BulkInput::Incompressible).unwrap()
}

fn shapes() -> Vec<(&'static str, Shape)> {
    vec![
        (
            "cone",
            Shape::Cone {
                half_angle_deg: 70.3,
            },
        ),
        (
            "power-law n=3",
            Shape::PowerLaw {
                exponent: 3.0,
                coefficient: 2.0e4,
            },
        ),
        (
            "power-law n=1.5",
            Shape::PowerLaw {
                exponent: 1.5,
                coefficient: 10.0,
            },
        ),
        ("flat", Shape::Flat { radius: 1.0e-3 }),
        ("sphere", Shape::sphere(5.0e-3)),
    ]
}

fn impact(shape: Shape, v0: f64, material: Material) -> Impact {
    let sphere = match shape.tip_radius() {
        Some(r) => Sphere::new(MASS, r).unwrap(),
        None => Sphere::without_radius(MASS).unwrap(),
    };
    Impact::shaped(sphere, shape, v0, material).unwrap()
}

fn run(imp: &Impact, solver: SolverKind, rtol: f64) -> Outcome {
    solve(imp, &opts(solver, rtol)).unwrap()
}

/// `(d_max, t_c, F_max)` of the elastic impact on `F = K d^alpha` (mass `MASS`, speed `v0`):
/// `d_max` from the energy, `t_c = 2 (d_max / v0) B(1/(alpha+1), 1/2) / (alpha + 1)`.
fn power_force_impact(k: f64, alpha: f64, v0: f64) -> (f64, f64, f64) {
    use statrs::function::beta::beta;
    let p = alpha + 1.0;
    let d_max = (p * MASS * v0 * v0 / (2.0 * k)).powf(1.0 / p);
    let t_c = 2.0 * d_max / v0 * beta(1.0 / p, 0.5) / p;
    (d_max, t_c, k * d_max.powf(alpha))
}

fn check_elastic(name: &str, o: &Outcome, truth: (f64, f64, f64), tol: f64) {
    let (d, t, f) = truth;
    for (what, got, want) in [
        ("max_indentation", o.max_indentation, d),
        ("contact_time", o.contact_time, t),
        ("max_force", o.max_force, f),
        ("cor", o.cor, 1.0),
    ] {
        assert!(
            abs_rel_err(got, want) < tol,
            "{name} {what} ({}): {got} vs {want}",
            o.solver
        );
    }
}

#[test]
fn power_laws_and_cones_meet_sneddon_and_the_beta_function() {
    // f = c r^n: g = k_n c x^n, F = 8 G n/(n+1) (k_n c)^(-1/n) d^(1+1/n) (E* = 4G)
    let v0 = 0.8;
    for (name, shape) in shapes() {
        let (n, c) = match shape {
            Shape::Cone { half_angle_deg } => (1.0, 1.0 / half_angle_deg.to_radians().tan()),
            Shape::PowerLaw {
                exponent,
                coefficient,
            } => (exponent, coefficient),
            _ => continue,
        };
        let k = 8.0 * G * n / (n + 1.0) * (power_law_stretch(n) * c).powf(-1.0 / n);
        if n == 1.0 {
            // Sneddon's cone: F = (2/pi) E* tan(theta) d^2
            let sneddon = 2.0 / std::f64::consts::PI * 4.0 * G / c;
            assert!(abs_rel_err(k, sneddon) < 1e-14);
        }
        let truth = power_force_impact(k, 1.0 + 1.0 / n, v0);
        let imp = impact(shape, v0, elastic());
        check_elastic(name, &run(&imp, SolverKind::Reference, 1e-10), truth, 1e-8);
        check_elastic(name, &run(&imp, SolverKind::Auto, 1e-8), truth, 1e-6);
        check_elastic(name, &run(&imp, SolverKind::Mdr, 1e-4), truth, 2e-4);
    }
}

#[test]
fn flat_punch_is_a_harmonic_oscillator() {
    // F = 8 G a0 d = 2 E* a0 d: t_c = pi sqrt(m/k), d_max = v0 sqrt(m/k)
    let (a0, v0) = (1.0e-3, 1.3);
    let k = 8.0 * G * a0;
    let w = (k / MASS).sqrt();
    let truth = (v0 / w, std::f64::consts::PI / w, k * v0 / w);
    let imp = impact(Shape::Flat { radius: a0 }, v0, elastic());
    for (solver, rtol, tol) in [
        (SolverKind::Reference, 1e-10, 1e-8),
        (SolverKind::Auto, 1e-8, 1e-6),
        (SolverKind::Mdr, 1e-4, 2e-4),
    ] {
        let o = run(&imp, solver, rtol);
        check_elastic("flat", &o, truth, tol);
        assert_eq!(o.max_contact_radius, a0, "{solver:?}");
    }
}

/// `int_a^b f` by composite 16-point Gauss–Legendre on `panels` equal panels (nodes by Newton
/// on `P_16`): for the smooth integrands below, converged to rounding.
fn gauss(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    const N: usize = 16;
    let mut nodes = [(0.0, 0.0); N];
    for (i, node) in nodes.iter_mut().enumerate() {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (N as f64 + 0.5)).cos();
        for _ in 0..100 {
            // P_N(x) and P_N'(x) by the three-term recurrence
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=N {
                let kf = k as f64;
                (p0, p1) = (p1, ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf);
            }
            let dp = N as f64 * (x * p1 - p0) / (x * x - 1.0);
            let step = p1 / dp;
            x -= step;
            if step.abs() < 1e-16 {
                *node = (x, 2.0 / ((1.0 - x * x) * dp * dp));
                break;
            }
        }
    }
    let h = (b - a) / panels as f64;
    (0..panels)
        .map(|p| {
            let mid = a + (p as f64 + 0.5) * h;
            nodes
                .iter()
                .map(|&(x, w)| w * f(mid + 0.5 * h * x))
                .sum::<f64>()
                * 0.5
                * h
        })
        .sum()
}

/// Segedin's exact sphere, written here from the closed forms (no library geometry):
/// `d(a) = (a/2) ln((R+a)/(R-a))`, `F(a) = (E*/2) [(a^2+R^2) ln((R+a)/(R-a)) - 2 a R]`.
/// Returns `(d_max, t_c, F_max)` of the elastic impact at `v0`: `a_max` from the energy
/// `int_0^a F d'(a) da = m v0^2 / 2` (bisection), `t_c = 2 int_0^{a_max} d'(a) / v(a) da` with
/// `a = a_max (1 - s^2)` (smooth in `s`) and `v^2 = (2/m) int_a^{a_max} F d' da`. An mpmath
/// evaluation of the same integrals at 30 digits (R = 5 mm, G = 1 MPa, m = 4.11 g, v0 = 12 m/s:
/// t_c = 1.33142593572962e-3 s) agrees with this to 1e-14.
fn segedin_impact(radius: f64, v0: f64) -> (f64, f64, f64) {
    let e_star = 4.0 * G;
    let ln = |a: f64| ((radius + a) / (radius - a)).ln();
    let d_of = |a: f64| 0.5 * a * ln(a);
    let dd = |a: f64| 0.5 * ln(a) + a * radius / (radius * radius - a * a);
    let f_of = |a: f64| 0.5 * e_star * ((a * a + radius * radius) * ln(a) - 2.0 * a * radius);
    let work = |a: f64, b: f64| gauss(|x| f_of(x) * dd(x), a, b, 8);
    let half = 0.5 * MASS * v0 * v0;
    let (mut lo, mut hi) = (0.0, 0.999 * radius);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if work(0.0, mid) < half {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let a_max = 0.5 * (lo + hi);
    let t_c = 2.0
        * gauss(
            |s| {
                let a = a_max * (1.0 - s * s);
                let v2 = 2.0 * work(a, a_max) / MASS;
                if v2 <= 0.0 {
                    // s = 0: the limit of the integrand, d'(a_max) 2 a_max / sqrt(2 F d' 2 a_max / m)
                    let k = 2.0 * f_of(a_max) * dd(a_max) * 2.0 * a_max / MASS;
                    return dd(a_max) * 2.0 * a_max / k.sqrt();
                }
                dd(a) * 2.0 * a_max * s / v2.sqrt()
            },
            0.0,
            1.0,
            16,
        );
    (d_of(a_max), t_c, f_of(a_max))
}

#[test]
fn exact_sphere_meets_segedin() {
    let r = 5.0e-3;
    // a/R about 0.3 and 0.7 (the largest radii the outside checks use)
    for v0 in [1.0, 6.0, 12.0] {
        let truth = segedin_impact(r, v0);
        let imp = impact(Shape::sphere(r), v0, elastic());
        let o = run(&imp, SolverKind::Reference, 1e-10);
        check_elastic("sphere", &o, truth, 1e-8);
        check_elastic("sphere", &run(&imp, SolverKind::Auto, 1e-8), truth, 1e-6);
        check_elastic("sphere", &run(&imp, SolverKind::Mdr, 1e-4), truth, 2e-4);
    }
}

#[test]
fn exact_sphere_approaches_the_paraboloid_as_the_square_of_a_over_r() {
    // elastic: the maximum force of the exact sphere falls below Hertz's by c (a/R)^2
    let r = 5.0e-3;
    let mut ratios = Vec::new();
    for v0 in [0.05, 0.2, 0.8] {
        let exact = run(
            &impact(Shape::sphere(r), v0, elastic()),
            SolverKind::Reference,
            1e-10,
        );
        let hertz = run(
            &impact(Shape::Paraboloid { radius: r }, v0, elastic()),
            SolverKind::Reference,
            1e-10,
        );
        let ar = exact.max_contact_radius / r;
        let diff = abs_rel_err(exact.max_force, hertz.max_force);
        ratios.push(diff / (ar * ar));
    }
    // the coefficient settles: within 5 % between the two smallest radii
    assert!(
        abs_rel_err(ratios[0], ratios[1]) < 0.05,
        "diff / (a/R)^2 = {ratios:?}"
    );
    assert!(ratios.iter().all(|c| *c > 0.05 && *c < 1.0), "{ratios:?}");
}

/// The viscoelastic flat punch of a standard solid is a linear ODE: `m d'' = -F`,
/// `F = 8 a0 (c_inf d + sum_k c_k q_k)`, `q_k' = -q_k / tau_k + d'`, solved here by the matrix
/// exponential (nalgebra) and bisection on `F = 0`; no Ting phase.
fn flat_linear_ode(prony: &mdr_impact::Prony, a0: f64, v0: f64) -> (f64, f64, f64) {
    let k = prony.terms.len();
    let n = 2 + k;
    let mut m = DMatrix::<f64>::zeros(n, n);
    m[(0, 1)] = 1.0;
    m[(1, 0)] = -8.0 * a0 * prony.relaxed / MASS;
    for (j, t) in prony.terms.iter().enumerate() {
        m[(1, 2 + j)] = -8.0 * a0 * t.coefficient / MASS;
        m[(2 + j, 1)] = 1.0;
        m[(2 + j, 2 + j)] = -1.0 / t.tau;
    }
    let mut x0 = nalgebra::DVector::<f64>::zeros(n);
    x0[1] = v0;
    let state = |t: f64| (&m * t).exp() * &x0;
    let force = |x: &nalgebra::DVector<f64>| {
        8.0 * a0
            * (prony.relaxed * x[0]
                + prony
                    .terms
                    .iter()
                    .enumerate()
                    .map(|(j, p)| p.coefficient * x[2 + j])
                    .sum::<f64>())
    };
    // bracket the end of contact by the undamped period, then bisect
    let period = std::f64::consts::PI * (MASS / (8.0 * a0 * prony.glassy())).sqrt();
    let mut hi = period;
    while force(&state(hi)) > 0.0 {
        hi *= 1.5;
    }
    let mut lo = 0.5 * hi.min(period);
    while force(&state(lo)) <= 0.0 {
        lo *= 0.5;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if force(&state(mid)) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let t_end = 0.5 * (lo + hi);
    let cor = -state(t_end)[1] / v0;
    // the maximum indentation where d' = 0
    let (mut a, mut b) = (0.0, t_end);
    for _ in 0..200 {
        let mid = 0.5 * (a + b);
        if state(mid)[1] > 0.0 {
            a = mid;
        } else {
            b = mid;
        }
    }
    (cor, t_end, state(0.5 * (a + b))[0])
}

#[test]
fn viscoelastic_flat_punch_meets_the_matrix_exponential() {
    let (a0, v0) = (1.0e-3, 0.99);
    let mat = Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.49).unwrap();
    let imp = impact(Shape::Flat { radius: a0 }, v0, mat);
    let (cor, t_c, d_max) = flat_linear_ode(imp.equivalent_relaxation(), a0, v0);
    for (solver, rtol, tol) in [
        (SolverKind::Reference, 1e-10, 1e-8),
        (SolverKind::Auto, 1e-8, 1e-6),
        (SolverKind::Mdr, 1e-4, 2e-4),
    ] {
        let o = run(&imp, solver, rtol);
        assert!(
            abs_rel_err(o.cor, cor) < tol,
            "{solver:?} cor {} vs {cor}",
            o.cor
        );
        assert!(abs_rel_err(o.contact_time, t_c) < tol, "{solver:?} t_c");
        assert!(
            abs_rel_err(o.max_indentation, d_max) < tol,
            "{solver:?} d_max"
        );
    }
}

/// The shapes' viscoelastic impacts by `reference` (rtol 1e-10) and `mdr` (rtol 1e-4): the four
/// reported values within 2e-4; and `auto` at 1e-8 within 1e-6 of `reference`.
fn solvers_agree(material: Material, v0: f64) {
    for (name, shape) in shapes() {
        let imp = impact(shape, v0, material.clone());
        let r = run(&imp, SolverKind::Reference, 1e-10);
        let checks = [
            (SolverKind::Mdr, 1e-4, 2e-4),
            (SolverKind::Auto, 1e-8, 1e-6),
        ];
        for (solver, rtol, tol) in checks {
            let o = run(&imp, solver, rtol);
            for (what, got, want) in [
                ("cor", o.cor, r.cor),
                ("contact_time", o.contact_time, r.contact_time),
                ("max_indentation", o.max_indentation, r.max_indentation),
                ("max_force", o.max_force, r.max_force),
            ] {
                assert!(
                    abs_rel_err(got, want) < tol,
                    "{name} {what}: {solver:?} {got} vs reference {want}"
                );
            }
        }
    }
}

#[test]
fn solvers_agree_on_every_shape_for_the_standard_solid() {
    solvers_agree(
        Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.3).unwrap(),
        0.99,
    );
}

#[test]
fn solvers_agree_on_every_shape_for_a_three_term_material() {
    let shear = ShearProny::new(1.0e6, &[(4.0e6, 1e-5), (3.0e6, 2e-4), (2.0e6, 3e-3)]).unwrap();
    let m = Material::general(shear, BulkInput::Elastic(2.0e7)).unwrap();
    solvers_agree(m, 1.5);
}

#[test]
fn solvers_agree_on_every_shape_for_a_real_polymer() {
    let scene =
        mdr_impact::io::scene::Scene::load(std::path::Path::new("scenes/polyisobutylene.toml"))
            .unwrap();
    let m = scene.impact.half_space().unwrap().clone();
    solvers_agree(m, 1.0);
}

#[test]
fn validity_warnings_follow_the_shape() {
    use mdr_impact::model::validity::Validity;
    let warnings = |shape: Shape, v0: f64| {
        let imp = impact(shape, v0, elastic());
        let o = run(&imp, SolverKind::Auto, 1e-6);
        (o.max_contact_radius, Validity::of(&imp, &o).warnings)
    };
    let r = 5.0e-3;
    // a/R about 0.5: the paraboloid is warned about, the exact sphere is not
    let (a, w) = warnings(Shape::Paraboloid { radius: r }, 3.0);
    assert!(a / r > 0.4 && a / r < 0.8, "{a}");
    assert!(w.iter().any(|m| m.contains("paraboloid of Hertz")), "{w:?}");
    let (_, w) = warnings(Shape::sphere(r), 3.0);
    assert!(w.is_empty(), "{w:?}");
    // a/R = 0.85: the exact sphere warns that the contact is no longer small
    let (a, w) = warnings(Shape::sphere(r), 12.0);
    assert!(a / r > 0.8, "{a}");
    assert!(w.iter().any(|m| m.contains("exceeds 0.8")), "{w:?}");
    // a sharp cone warns about its slope, the Berkovich-equivalent one does not
    let (_, w) = warnings(
        Shape::Cone {
            half_angle_deg: 45.0,
        },
        1.0,
    );
    assert!(w.iter().any(|m| m.contains("slope")), "{w:?}");
    let (_, w) = warnings(
        Shape::Cone {
            half_angle_deg: 70.3,
        },
        1.0,
    );
    assert!(w.is_empty(), "{w:?}");
}

#[test]
fn scene_keys_name_every_shape_and_refuse_what_does_not_apply() {
    use mdr_impact::io::scene::Scene;
    let material = "[impact]\nvelocity = 1.0\n[material]\ng_inf = 1e6\ng_1 = 1e7\neta = 500.0\n\
                    poisson = 0.49\n";
    let parse = |head: &str| Scene::parse(&format!("{head}\n{material}"));
    let shape = |head: &str| *parse(head).unwrap().impact.shape();
    assert_eq!(
        shape("[indenter]\nmass = 1e-3\nshape = \"cone\"\nhalf_angle_deg = 70.3"),
        Shape::Cone {
            half_angle_deg: 70.3
        }
    );
    assert_eq!(
        shape("[indenter]\nmass = 1e-3\nshape = \"power-law\"\nexponent = 3.0\ncoefficient = 2e4"),
        Shape::PowerLaw {
            exponent: 3.0,
            coefficient: 2e4
        }
    );
    assert_eq!(
        shape("[indenter]\nmass = 1e-3\nshape = \"flat\"\nradius = 1e-3"),
        Shape::Flat { radius: 1e-3 }
    );
    assert_eq!(
        shape("[indenter]\nmass = 1e-3\nshape = \"sphere\"\nradius = 5e-3"),
        Shape::sphere(5e-3)
    );
    assert_eq!(
        shape("[sphere]\nmass = 1e-3\nradius = 5e-3\nprofile = \"sphere\""),
        Shape::sphere(5e-3)
    );
    assert_eq!(
        shape("[sphere]\nmass = 1e-3\nradius = 5e-3"),
        Shape::Paraboloid { radius: 5e-3 }
    );
    for (head, says) in [
        (
            "[indenter]\nmass = 1e-3\nshape = \"cone\"\nradius = 1e-3",
            "needs half_angle_deg",
        ),
        (
            "[indenter]\nmass = 1e-3\nshape = \"cone\"\nhalf_angle_deg = 70.0\nradius = 1e-3",
            "radius does not apply",
        ),
        (
            "[indenter]\nmass = 1e-3\nshape = \"cone\"\nhalf_angle_deg = 95.0",
            "half_angle_deg",
        ),
        (
            "[indenter]\nmass = 1e-3\nshape = \"pyramid\"",
            "expected one of",
        ),
        (
            "[sphere]\nmass = 1e-3\nradius = 5e-3\nprofile = \"cap\"",
            "profile = 'cap'",
        ),
        (
            "[indenter]\nmass = 1e-3\nshape = \"power-law\"\nexponent = 50.0\ncoefficient = 1.0",
            "exponent",
        ),
    ] {
        let e = parse(head).unwrap_err().to_string();
        assert!(e.contains(says), "{head}: {e}");
    }
}
