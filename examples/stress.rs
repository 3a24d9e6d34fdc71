use mdr_impact::*;
use rayon::prelude::*;
fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let solver: SolverKind = a[0].parse().unwrap();
    let rtol: f64 = a[1].parse().unwrap();
    let mut cases = vec![];
    for nu in [-0.99, -0.5, 0.0, 0.45, 0.499, 0.5] {
        for lp2 in [-6, -4, -2, 0, 2, 4, 6] {
            for lp3 in [-6, -4, -2, 0, 2, 4, 6] {
                cases.push((nu, 10f64.powi(lp2), 10f64.powi(lp3)));
            }
        }
    }
    let res: Vec<_> = cases
        .par_iter()
        .map(|&(nu, p2, p3)| {
            let imp = Impact::from_groups(Groups::new(nu, p2, p3).unwrap()).unwrap();
            let t0 = std::time::Instant::now();
            let r = solve(
                &imp,
                &SolveOptions {
                    solver,
                    rtol,
                    work_limit: 200_000_000,
                    ..Default::default()
                },
            );
            (nu, p2, p3, r, t0.elapsed().as_secs_f64())
        })
        .collect();
    for (nu, p2, p3, r, s) in res {
        match r {
            Ok(o) => {
                if !(o.cor > 0.0 && o.cor <= 1.0) || s > 1.0 {
                    println!(
                        "{nu},{p2:e},{p3:e},{:.15e},{:.2e},{s:.4},",
                        o.cor,
                        o.cor_error_estimate.unwrap_or(0.0)
                    )
                }
            }
            Err(e) => println!("{nu},{p2:e},{p3:e},nan,nan,{s:.4},{e}"),
        }
    }
}
