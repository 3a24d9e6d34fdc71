use mdr_impact::*;
fn main() {
    let rtol: f64 = std::env::args().nth(1).unwrap().parse().unwrap();
    let solver: SolverKind = std::env::args().nth(2).unwrap().parse().unwrap();
    for c in catalogue::IMPACTS {
        let imp = c.impact().unwrap();
        let r = solve(
            &imp,
            &SolveOptions {
                solver: SolverKind::Reference,
                rtol: 1e-11,
                ..Default::default()
            },
        )
        .unwrap();
        let t0 = std::time::Instant::now();
        let o = solve(
            &imp,
            &SolveOptions {
                solver,
                rtol,
                ..Default::default()
            },
        );
        match o {
            Ok(o) => println!(
                "{:40} e={:.10} err={:+.2e} tc={:+.2e} fm={:+.2e} {:?} {:?}",
                c.id,
                o.cor,
                (o.cor - r.cor) / r.cor,
                (o.contact_time - r.contact_time) / r.contact_time,
                (o.max_force - r.max_force) / r.max_force,
                t0.elapsed(),
                o.work
            ),
            Err(e) => println!("{:40} {e}", c.id),
        }
    }
}
