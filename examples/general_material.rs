//! A general material: a three-term Prony series in shear with a viscoelastic bulk (one term),
//! the equivalent relaxation function G_eq(t) it implies, and the CoR of a ball on it from the
//! fast solver and the independent reference solver.
//!
//! Run: `cargo run --release --example general_material`

use mdr_impact::model::material::{BulkInput, BulkProny, ShearProny};
use mdr_impact::{solve, Impact, Material, SolveOptions, SolverKind, Sphere};

fn main() -> mdr_impact::Result<()> {
    // shear: G_inf = 1 MPa plus three Maxwell branches (modulus Pa, time s)
    let shear = ShearProny::new(1.0e6, &[(5.0e6, 1.0e-6), (2.0e6, 1.0e-4), (1.0e6, 1.0e-2)])?;
    // bulk: K_inf = 50 MPa plus one branch of 20 MPa relaxing in 10 us
    let bulk = BulkInput::Prony(BulkProny::new(5.0e7, &[(2.0e7, 1.0e-5)])?);
    let material = Material::general(shear, bulk)?;
    let g_eq = material.equivalent_relaxation()?;
    println!(
        "G_eq(t) = {:.6e} Pa relaxed, {} terms:",
        g_eq.relaxed,
        g_eq.terms.len()
    );
    for t in &g_eq.terms {
        println!("  {:.6e} Pa  exp(-t / {:.6e} s)", t.coefficient, t.tau);
    }
    let impact = Impact::new(Sphere::new(4.1e-3, 5.0e-3)?, 1.0, material)?;
    for solver in [SolverKind::Fast, SolverKind::Reference] {
        let o = solve(&impact, &SolveOptions::with(solver, 1e-8))?;
        println!(
            "{:>9}: CoR {:.10}, contact time {:.6e} s",
            o.solver, o.cor, o.contact_time
        );
    }
    Ok(())
}
