//! Section 1e of VALIDATION.md: axisymmetric indenters (docs/theory.md §11). Closed forms
//! written here from the literature, independent of `model::geometry` (which the solvers use):
//! Sneddon's power law with the Beta function, the flat punch as a harmonic oscillator,
//! Segedin's exact sphere by quadrature, and the viscoelastic flat punch as a linear ODE solved by
//! the matrix exponential. `tests/shapes.rs` asserts what the table shows.

use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;

use crate::error::Result;
use crate::math::quad::gauss_legendre;
use crate::model::geometry::Shape;
use crate::model::material::{Prony, ShearProny};
use crate::model::{impact::Outcome, impact::Sphere};
use crate::report::markdown::{fmt_err, Table};
use crate::solvers::{solve, SolveOptions, SolverKind};
use crate::{BulkInput, Impact, Material};

/// `(d_max, t_c, F_max)` of an elastic impact of `mass` at `v0` on the force law `F = k d^alpha`:
/// `d_max` from the energy, `t_c = 2 (d_max / v0) B(1/(alpha+1), 1/2) / (alpha + 1)`.
pub fn power_force_impact(k: f64, alpha: f64, mass: f64, v0: f64) -> (f64, f64, f64) {
    use statrs::function::beta::beta;
    let p = alpha + 1.0;
    let d_max = (p * mass * v0 * v0 / (2.0 * k)).powf(1.0 / p);
    let t_c = 2.0 * d_max / v0 * beta(1.0 / p, 0.5) / p;
    (d_max, t_c, k * d_max.powf(alpha))
}

/// Sneddon's force constant of the power law `f = c r^n` with `E* = 4 G`:
/// `F = 2 E* n/(n+1) (k_n c)^(-1/n) d^(1+1/n)`, `k_n = sqrt(pi) Γ(n/2+1) / Γ(n/2+1/2)`.
pub fn sneddon_constant(g: f64, n: f64, c: f64) -> f64 {
    use statrs::function::gamma::gamma;
    let k_n = std::f64::consts::PI.sqrt() * gamma(0.5 * n + 1.0) / gamma(0.5 * n + 0.5);
    8.0 * g * n / (n + 1.0) * (k_n * c).powf(-1.0 / n)
}

/// `(d_max, t_c, F_max)` of the elastic impact of `mass` at `v0` on Segedin's exact sphere of
/// `radius` with `E* = e_star`: `d(a) = (a/2) ln((R+a)/(R-a))`,
/// `F(a) = (E*/2) [(a^2+R^2) ln((R+a)/(R-a)) - 2 a R]`; `a_max` from the energy
/// `int_0^a F d'(a) da = m v0^2 / 2` (bisection), `t_c = 2 int_0^{a_max} d'(a) / v(a) da` with
/// `a = a_max (1 - s^2)` (smooth in `s`) and `v^2 = (2/m) int_a^{a_max} F d' da`. An mpmath
/// evaluation at 30 digits (R = 5 mm, G = 1 MPa, m = 4.11 g, v0 = 12 m/s: t_c =
/// 1.3314259357296162e-3 s) agrees to 3e-13.
pub fn segedin_impact(radius: f64, e_star: f64, mass: f64, v0: f64) -> (f64, f64, f64) {
    let ln = |a: f64| ((radius + a) / (radius - a)).ln();
    let d_of = |a: f64| 0.5 * a * ln(a);
    let dd = |a: f64| 0.5 * ln(a) + a * radius / (radius * radius - a * a);
    let f_of = |a: f64| 0.5 * e_star * ((a * a + radius * radius) * ln(a) - 2.0 * a * radius);
    let work = |a: f64, b: f64| gauss_legendre(|x| f_of(x) * dd(x), a, b, 8);
    let half = 0.5 * mass * v0 * v0;
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
        * gauss_legendre(
            |s| {
                let a = a_max * (1.0 - s * s);
                let v2 = 2.0 * work(a, a_max) / mass;
                if v2 <= 0.0 {
                    // s = 0: the integrand's limit
                    let k = 2.0 * f_of(a_max) * dd(a_max) * 2.0 * a_max / mass;
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

/// `(cor, t_c, d_max)` of a rigid flat punch of radius `a0` and `mass` at `v0` on `G_eq = prony`:
/// `m d'' = -F`, `F = 8 a0 (c_inf d + Σ c_k q_k)`, `q_k' = -q_k / tau_k + d'` is linear (the
/// contact radius never changes), solved by the matrix exponential and bisection on `F = 0`.
pub fn flat_punch_ode(prony: &Prony, a0: f64, mass: f64, v0: f64) -> (f64, f64, f64) {
    let k = prony.terms.len();
    let n = 2 + k;
    let mut m = DMatrix::<f64>::zeros(n, n);
    m[(0, 1)] = 1.0;
    m[(1, 0)] = -8.0 * a0 * prony.relaxed / mass;
    for (j, t) in prony.terms.iter().enumerate() {
        m[(1, 2 + j)] = -8.0 * a0 * t.coefficient / mass;
        m[(2 + j, 1)] = 1.0;
        m[(2 + j, 2 + j)] = -1.0 / t.tau;
    }
    let mut x0 = DVector::<f64>::zeros(n);
    x0[1] = v0;
    let state = |t: f64| (&m * t).exp() * &x0;
    let force = |x: &DVector<f64>| {
        prony.relaxed * x[0]
            + prony
                .terms
                .iter()
                .enumerate()
                .map(|(j, p)| p.coefficient * x[2 + j])
                .sum::<f64>()
    };
    let period = std::f64::consts::PI * (mass / (8.0 * a0 * prony.glassy())).sqrt();
    let mut hi = period;
    while force(&state(hi)) > 0.0 {
        hi *= 1.5;
    }
    let mut lo = 0.5 * hi.min(period);
    while force(&state(lo)) <= 0.0 {
        lo *= 0.5;
    }
    let bisect = |mut lo: f64, mut hi: f64, above: &dyn Fn(f64) -> bool| {
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if above(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let t_end = bisect(lo, hi, &|t| force(&state(t)) > 0.0);
    let t_m = bisect(0.0, t_end, &|t| state(t)[1] > 0.0);
    (-state(t_end)[1] / v0, t_end, state(t_m)[0])
}

/// Mass (kg) of the impactor of the section's cases.
pub const MASS: f64 = 4.11e-3;
/// Shear modulus (Pa) of the section's elastic half-space (incompressible, `E* = 4 G`).
pub const G: f64 = 1.0e6;

/// The shapes of the section (and of `tests/shapes.rs`).
pub fn shapes() -> Vec<(&'static str, Shape)> {
    vec![
        (
            "cone 70.3°",
            Shape::Cone {
                half_angle_deg: 70.3,
            },
        ),
        (
            "power law n = 3",
            Shape::PowerLaw {
                exponent: 3.0,
                coefficient: 2.0e4,
            },
        ),
        (
            "power law n = 1.5",
            Shape::PowerLaw {
                exponent: 1.5,
                coefficient: 10.0,
            },
        ),
        ("flat punch", Shape::Flat { radius: 1.0e-3 }),
        ("exact sphere", Shape::sphere(5.0e-3)),
    ]
}

/// The elastic, incompressible half-space of shear modulus [`G`].
pub fn elastic() -> Result<Material> {
    Material::general(ShearProny::new(G, &[])?, BulkInput::Incompressible)
}

/// The impact of an impactor of [`MASS`] with `shape` at `v0` on `material` (its nominal radius:
/// the shape's tip radius, or none).
pub fn shaped_impact(shape: Shape, v0: f64, material: Material) -> Result<Impact> {
    let sphere = match shape.tip_radius() {
        Some(r) => Sphere::new(MASS, r)?,
        None => Sphere::without_radius(MASS)?,
    };
    Impact::shaped(sphere, shape, v0, material)
}

/// The elastic closed form `(d_max, t_c, F_max)` of a shape at `v0` on [`elastic`].
pub fn elastic_truth(shape: Shape, v0: f64) -> Option<(f64, f64, f64)> {
    match shape {
        Shape::Cone { half_angle_deg } => {
            let k = sneddon_constant(G, 1.0, 1.0 / half_angle_deg.to_radians().tan());
            Some(power_force_impact(k, 2.0, MASS, v0))
        }
        Shape::PowerLaw {
            exponent,
            coefficient,
        } => {
            let k = sneddon_constant(G, exponent, coefficient);
            Some(power_force_impact(k, 1.0 + 1.0 / exponent, MASS, v0))
        }
        Shape::Flat { radius } => {
            let w = (8.0 * G * radius / MASS).sqrt();
            Some((v0 / w, std::f64::consts::PI / w, 8.0 * G * radius * v0 / w))
        }
        Shape::Spheres { .. } => shape
            .cap_limit()
            .map(|r| segedin_impact(r, 4.0 * G, MASS, v0)),
        _ => None,
    }
}

/// The largest relative difference of `(cor, t_c, d_max, F_max)` between two outcomes.
pub fn max_difference(o: &Outcome, truth: &Outcome) -> f64 {
    [
        (o.cor, truth.cor),
        (o.contact_time, truth.contact_time),
        (o.max_indentation, truth.max_indentation),
        (o.max_force, truth.max_force),
    ]
    .iter()
    .map(|(a, b)| ((a - b) / b).abs())
    .fold(0.0, f64::max)
}

/// The section's materials: the elastic half-space, a standard solid, a three-term material and
/// the polyisobutylene spectrum of `scenes/polyisobutylene.toml` (30 terms).
fn materials() -> Result<Vec<(&'static str, Material, f64)>> {
    let pib = crate::report::catalogue::general_entries()?
        .into_iter()
        .find(|e| e.id == "polyisobutylene")
        .ok_or(crate::Error::Internal("catalogue: no polyisobutylene"))?
        .material;
    let three = ShearProny::new(1.0e6, &[(4.0e6, 1e-5), (3.0e6, 2e-4), (2.0e6, 3e-3)])?;
    Ok(vec![
        ("elastic (closed form)", elastic()?, 0.8),
        (
            "standard solid",
            Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.3)?,
            0.99,
        ),
        (
            "three terms",
            Material::general(three, BulkInput::Elastic(2.0e7))?,
            1.5,
        ),
        ("polyisobutylene (30 terms)", pib, 1.0),
    ])
}

/// The section's table: for each shape and material, the largest relative difference of the CoR,
/// contact time, maximum indentation and maximum force of `reference` (rtol 1e-10), `auto`
/// (1e-8) and `mdr` (1e-4) against the truth: the closed form for the elastic half-space (and the
/// matrix exponential for the viscoelastic flat punch of the standard solid), `reference` at
/// 1e-10 otherwise.
pub fn shapes_table() -> Result<Table> {
    let mut t = Table::new(&[
        "shape",
        "material",
        "truth",
        "CoR",
        "reference 1e-10",
        "auto 1e-8",
        "mdr 1e-4",
    ]);
    let mats = materials()?;
    let jobs: Vec<_> = shapes()
        .into_iter()
        .flat_map(|s| mats.iter().map(move |m| (s, m)))
        .collect();
    let rows: Vec<Result<Vec<String>>> = jobs
        .par_iter()
        .map(|((name, shape), (mname, material, v0))| {
            let imp = shaped_impact(*shape, *v0, material.clone())?;
            let run = |solver, rtol| solve(&imp, &SolveOptions::with(solver, rtol));
            let reference = run(SolverKind::Reference, 1e-10)?;
            let mut truth = reference.clone();
            let mut source = "reference 1e-10";
            if imp.is_elastic() {
                if let Some((d, tc, f)) = elastic_truth(*shape, *v0) {
                    (
                        truth.cor,
                        truth.contact_time,
                        truth.max_indentation,
                        truth.max_force,
                    ) = (1.0, tc, d, f);
                    source = "closed form";
                }
            } else if let (Shape::Flat { radius }, Some(_)) = (shape, imp.standard_solid()) {
                let (cor, tc, d) = flat_punch_ode(imp.equivalent_relaxation(), *radius, MASS, *v0);
                (truth.cor, truth.contact_time, truth.max_indentation) = (cor, tc, d);
                truth.max_force = reference.max_force;
                source = "matrix exponential";
            }
            let diff = |o: Result<Outcome>| match o {
                Ok(o) => fmt_err(max_difference(&o, &truth)),
                Err(e) => format!("refused: {e}"),
            };
            Ok(vec![
                name.to_string(),
                mname.to_string(),
                source.to_string(),
                format!("{:.9}", truth.cor),
                diff(Ok(reference.clone())),
                diff(run(SolverKind::Auto, 1e-8)),
                diff(run(SolverKind::Mdr, 1e-4)),
            ])
        })
        .collect();
    for r in rows {
        t.rows.push(r?);
    }
    Ok(t)
}

/// The limit exact sphere -> paraboloid: `(a_max / R, relative force difference, difference /
/// (a/R)^2)` of elastic impacts at increasing speeds (both by `reference` at 1e-10).
pub fn sphere_limit() -> Result<Vec<(f64, f64, f64)>> {
    let r = 5.0e-3;
    [0.05, 0.2, 0.8, 3.0]
        .par_iter()
        .map(|&v0| {
            let opts = SolveOptions::with(SolverKind::Reference, 1e-10);
            let exact = solve(&shaped_impact(Shape::sphere(r), v0, elastic()?)?, &opts)?;
            let hertz = solve(
                &shaped_impact(Shape::Paraboloid { radius: r }, v0, elastic()?)?,
                &opts,
            )?;
            let ar = exact.max_contact_radius / r;
            let diff = ((exact.max_force - hertz.max_force) / hertz.max_force).abs();
            Ok((ar, diff, diff / (ar * ar)))
        })
        .collect()
}
