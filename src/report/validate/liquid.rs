//! Section 1h of VALIDATION.md: viscoelastic liquids, `g_inf = 0` (docs/theory.md §15). Their
//! canonical units take the glassy modulus as scale; the CoR of `fast` is compared with
//! `reference` and `mdr` (no shared code beyond the material), and with solids of a vanishing
//! relaxed modulus `g_inf = eps G_1`, whose scale is still `g_inf`. `tests/liquid.rs` asserts
//! what the tables show.

use crate::error::Result;
use crate::model::bodies::{Body, BodyMaterial, Side, TwoBodies};
use crate::model::material::{BulkInput, BulkProny, ShearProny};
use crate::report::markdown::{fmt_err, Table};
use crate::{solve, Impact, Material, SolveOptions, SolverKind, Sphere};

/// The ball of the section: 4.11 g, 5 mm.
fn ball() -> Result<Sphere> {
    Sphere::new(4.11e-3, 5.0e-3)
}

/// A Maxwell fluid (`g_inf`, `G_1 = 10 MPa`, `eta`, incompressible) under the ball at 0.99 m/s.
pub fn maxwell(g_inf: f64, eta: f64) -> Result<Impact> {
    Impact::new(ball()?, 0.99, Material::incompressible(g_inf, 1.0e7, eta)?)
}

/// Three shear terms with no plateau and a bulk proportional to the shear (constant Poisson
/// ratio 0.45 in time, as `prony --nu` writes for a liquid), under the ball at 1 m/s.
pub fn proportional() -> Result<Impact> {
    let shear = [(4.0e6, 1.0e-4), (3.0e6, 1.0e-3), (1.0e6, 1.0e-2)];
    let f = 2.0 * 1.45 / (3.0 * 0.1);
    let bulk: Vec<(f64, f64)> = shear.iter().map(|&(g, t)| (g * f, t)).collect();
    let m = Material::general(
        ShearProny::new(0.0, &shear)?,
        BulkInput::Prony(BulkProny::new(0.0, &bulk)?),
    )?;
    Impact::new(ball()?, 1.0, m)
}

/// Two equal balls at 0.99 m/s: A a Maxwell fluid (`eta = 5000 Pa s`), B the liquid too or the
/// default solid (`g_inf = 1 MPa`, `G_1 = 10 MPa`, `eta = 500 Pa s`, `nu = 0.49`).
pub fn two_bodies(both_liquid: bool) -> Result<Impact> {
    let a = Material::incompressible(0.0, 1.0e7, 5.0e3)?;
    let b = if both_liquid {
        a.clone()
    } else {
        Material::with_poisson(1.0e6, 1.0e7, 500.0, 0.49)?
    };
    let body = |side, m| Body::new(side, 4.11e-3, 5.0e-3, BodyMaterial::Viscoelastic(m));
    Impact::with_bodies(TwoBodies::new(body(Side::A, a)?, body(Side::B, b)?)?, 0.99)
}

fn cor(imp: &Impact, solver: SolverKind, rtol: f64) -> Result<f64> {
    Ok(solve(imp, &SolveOptions::with(solver, rtol))?.cor)
}

/// The liquids: CoR of `fast` at rtol 1e-10, and the relative differences of `reference`
/// (1e-10) and `mdr` (1e-5) from it.
pub fn solver_table() -> Result<Table> {
    let mut t = Table::new(&[
        "liquid",
        "CoR (fast, rtol 1e-10)",
        "reference (1e-10)",
        "mdr (1e-5)",
    ]);
    let cases: Vec<(String, Impact)> = vec![
        ("Maxwell, eta = 5e3 Pa s".into(), maxwell(0.0, 5.0e3)?),
        ("Maxwell, eta = 2e4 Pa s".into(), maxwell(0.0, 2.0e4)?),
        ("Maxwell, eta = 5e4 Pa s".into(), maxwell(0.0, 5.0e4)?),
        ("3 terms, bulk relaxing to 0".into(), proportional()?),
        ("two bodies, liquid on solid".into(), two_bodies(false)?),
        ("two bodies, both liquid".into(), two_bodies(true)?),
    ];
    for (name, imp) in cases {
        let fast = cor(&imp, SolverKind::Fast, 1e-10)?;
        let diff = |x: f64| fmt_err((x - fast).abs() / fast);
        t.rows.push(vec![
            name,
            format!("{fast:.9}"),
            diff(cor(&imp, SolverKind::Reference, 1e-10)?),
            diff(cor(&imp, SolverKind::Mdr, 1e-5)?),
        ]);
    }
    Ok(t)
}

/// The relative CoR gaps `|e(eps) - e(0)| / e(0)` of solids `g_inf = eps G_1` from the
/// Maxwell fluid `eta = 5000 Pa s` (`fast` at rtol 1e-10), with `eps`.
pub fn limit_gaps() -> Result<Vec<(f64, f64)>> {
    let liquid = cor(&maxwell(0.0, 5.0e3)?, SolverKind::Fast, 1e-10)?;
    [1e-2, 1e-3, 1e-4, 1e-5, 1e-6]
        .into_iter()
        .map(|eps| {
            let solid = cor(&maxwell(eps * 1.0e7, 5.0e3)?, SolverKind::Fast, 1e-10)?;
            Ok((eps, (solid - liquid).abs() / liquid))
        })
        .collect()
}

/// [`limit_gaps`] as a table, with `gap / eps`.
pub fn limit_table() -> Result<Table> {
    let mut t = Table::new(&["eps = g_inf / G_1", "abs(e(eps) / e(0) - 1)", "gap / eps"]);
    for (eps, gap) in limit_gaps()? {
        t.rows.push(vec![
            format!("{eps:.0e}"),
            fmt_err(gap),
            format!("{:.3}", gap / eps),
        ]);
    }
    Ok(t)
}
