//! A CoR curve: the coefficient of restitution of one ball and material over impact velocities
//! from 1 mm/s to 100 m/s (log-spaced), solved in parallel; prints velocity, CoR and contact time
//! and the velocity of the smallest CoR.
//!
//! Run: `cargo run --release --example cor_curve`

use mdr_impact::apps::curve::run_velocities;
use mdr_impact::{Impact, Material, SolveOptions, SolverKind, Sphere};

fn main() -> mdr_impact::Result<()> {
    let material = Material::with_poisson(1.0e6, 1.0e7, 1.0e3, 0.45)?;
    let impact = Impact::new(Sphere::new(4.1e-3, 5.0e-3)?, 1.0, material)?;
    let velocities: Vec<f64> = (0..=25)
        .map(|i| 10f64.powf(-3.0 + 5.0 * i as f64 / 25.0))
        .collect();
    let opts = SolveOptions::with(SolverKind::Auto, 1e-6);
    let rows = run_velocities(&impact, &opts, &velocities, &|| {}).map_err(|(_, e)| e)?;
    println!("{:>12} {:>12} {:>14}", "v0 (m/s)", "CoR", "t_c (s)");
    for r in &rows {
        println!("{:>12.4e} {:>12.6} {:>14.6e}", r.v0, r.cor, r.contact_time);
    }
    if let Some(min) = rows.iter().min_by(|a, b| a.cor.total_cmp(&b.cor)) {
        println!("smallest CoR {:.6} at v0 = {:.3e} m/s", min.cor, min.v0);
    }
    Ok(())
}
