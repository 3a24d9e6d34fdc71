use mdr_impact::*;
fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let imp = Impact::from_groups(Groups::new(a[0], a[1], a[2]).unwrap()).unwrap();
    let reference = solve(
        &imp,
        &SolveOptions {
            solver: SolverKind::Reference,
            rtol: 1e-10,
            ..Default::default()
        },
    )
    .unwrap()
    .cor;
    let mat = solver::canonical_material(&imp);
    let lay = mdr::pilot(&mat.prony).unwrap();
    println!("ref {reference:.12} {lay:?}");
    let (mut n, mut m) = (16usize, 32usize);
    let nmul = a.get(3).copied().unwrap_or(2.0) as usize;
    let mmul = a.get(4).copied().unwrap_or(2.0) as usize;
    for _ in 0..8 {
        let o = mdr::run_resolution(mdr::Scheme::Exponential, &mat, &lay, n, m, false).unwrap();
        println!(
            "N={n:6} M={m:6} e={:.12} relerr={:+.3e} steps={}",
            o.cor,
            (o.cor - reference) / reference,
            o.work.steps
        );
        n *= nmul;
        m *= mmul;
    }
}
