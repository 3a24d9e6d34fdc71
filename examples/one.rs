use mdr_impact::*;
fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let imp = Impact::from_groups(Groups::new(a[0], a[1], a[2]).unwrap()).unwrap();
    let r = solve(
        &imp,
        &SolveOptions {
            solver: SolverKind::Mdr,
            rtol: a[3],
            ..Default::default()
        },
    );
    println!(
        "{:?}",
        r.map(|o| (
            o.cor,
            o.contact_time,
            o.max_indentation,
            o.cor_error_estimate,
            o.work
        ))
    );
}
