// cross-check against an external table: nu,p2,p3,cor,contact_time,max_indentation,...
use mdr_impact::*;
use rayon::prelude::*;
fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let solver: SolverKind = a[1].parse().unwrap();
    let rtol: f64 = a[2].parse().unwrap();
    let mut rdr = csv::Reader::from_path(&a[0]).unwrap();
    let rows: Vec<[f64; 6]> = rdr
        .records()
        .map(|r| {
            let r = r.unwrap();
            [0, 1, 2, 3, 4, 5].map(|i| r[i].parse().unwrap())
        })
        .collect();
    let res: Vec<_> = rows
        .par_iter()
        .map(|r| {
            let imp = Impact::from_groups(Groups::new(r[0], r[1], r[2]).unwrap()).unwrap();
            let t0 = std::time::Instant::now();
            let o = solve(
                &imp,
                &SolveOptions {
                    solver,
                    rtol,
                    ..Default::default()
                },
            );
            (r, o, t0.elapsed().as_secs_f64())
        })
        .collect();
    let (mut max_e, mut max_t, mut max_d, mut n_bad, mut worst, mut tot) =
        (0f64, 0f64, 0f64, 0, String::new(), 0.0);
    let mut times: Vec<f64> = vec![];
    for (r, o, s) in &res {
        tot += s;
        times.push(*s);
        match o {
            Ok(o) => {
                let e = ((o.cor - r[3]) / r[3]).abs();
                if e > max_e {
                    max_e = e;
                    worst = format!("{:?} e={} ref={}", &r[..3], o.cor, r[3]);
                }
                max_t = max_t.max(((o.contact_time - r[4]) / r[4]).abs());
                max_d = max_d.max(((o.max_indentation - r[5]) / r[5]).abs());
                if e > rtol {
                    n_bad += 1;
                }
            }
            Err(e) => {
                println!("ERR {:?} {e}", &r[..3]);
                n_bad += 1;
            }
        }
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!("{} rows: max rel cor err {max_e:.2e} (worst {worst}); contact time {max_t:.2e}; d_max {max_d:.2e}; over rtol {n_bad}; cpu {tot:.1}s median {:.2e}s max {:.2e}s", res.len(), times[times.len()/2], times[times.len()-1]);
}
