use mdr_impact::*;
use rayon::prelude::*;
fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let solver: SolverKind = a[0].parse().unwrap();
    let rtol: f64 = a[1].parse().unwrap();
    let mut cases = vec![];
    for nu in [-0.9, -0.5, 0.0, 0.3, 0.45, 0.49, 0.499, 0.5] {
        for lp2 in [-4, -3, -2, -1, 0, 1, 2] {
            for lp3 in [-3.0, -2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0] {
                cases.push((nu, 10f64.powi(lp2), 10f64.powf(lp3)));
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
                    ..Default::default()
                },
            );
            (nu, p2, p3, r, t0.elapsed().as_secs_f64())
        })
        .collect();
    println!("nu,p2,p3,cor,est,secs,err");
    for (nu, p2, p3, r, s) in res {
        match r {
            Ok(o) => println!(
                "{nu},{p2:e},{p3:e},{:.15e},{:.2e},{s:.4},",
                o.cor,
                o.cor_error_estimate.unwrap_or(0.0)
            ),
            Err(e) => println!("{nu},{p2:e},{p3:e},nan,nan,{s:.4},{e}"),
        }
    }
}
