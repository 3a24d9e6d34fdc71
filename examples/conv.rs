use mdr_impact::*;
fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let g = Groups::new(
        a[0].parse().unwrap(),
        a[1].parse().unwrap(),
        a[2].parse().unwrap(),
    )
    .unwrap();
    let imp = Impact::from_groups(g).unwrap();
    for rtol in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7] {
        let t0 = std::time::Instant::now();
        let opts = SolveOptions {
            solver: a[3].parse().unwrap(),
            rtol,
            ..Default::default()
        };
        match solve(&imp, &opts) {
            Ok(o) => println!(
                "rtol={rtol:e} e={:.12} est={:?} {:?} {:?}",
                o.cor,
                o.cor_error_estimate,
                o.work,
                t0.elapsed()
            ),
            Err(e) => println!("rtol={rtol:e} err {e}"),
        }
    }
}
