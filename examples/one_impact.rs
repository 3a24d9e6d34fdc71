//! One impact: a 5 mm steel ball (4.1 g) at 1 m/s on the paper's standard solid, solved
//! with the default solver; prints the CoR, its error estimate and the contact time, force and
//! indentation (SI units).
//!
//! Run: `cargo run --release --example one_impact`

use mdr_impact::{solve, Impact, Material, SolveOptions, SolverKind, Sphere};

fn main() -> mdr_impact::Result<()> {
    // G_inf = 1 MPa, G_1 = 10 MPa, eta = 1 kPa s (relaxation time eta / G_1 = 0.1 ms), nu = 0.45
    let material = Material::with_poisson(1.0e6, 1.0e7, 1.0e3, 0.45)?;
    let sphere = Sphere::new(4.1e-3, 5.0e-3)?; // mass (kg), radius (m)
    let impact = Impact::new(sphere, 1.0, material)?; // velocity (m/s)
    let outcome = solve(&impact, &SolveOptions::with(SolverKind::Auto, 1e-6))?;
    println!(
        "CoR {:.9} (estimated error {:.1e}, solver {})",
        outcome.cor,
        outcome.cor_error_estimate.unwrap_or(f64::NAN),
        outcome.solver
    );
    println!(
        "contact time {:.6e} s, max force {:.6e} N, max indentation {:.6e} m",
        outcome.contact_time, outcome.max_force, outcome.max_indentation
    );
    Ok(())
}
