use mdr_impact::theory::reference::impact;
use mdr_impact::Groups;
use std::time::Instant;

#[test]
#[ignore = "scratch"]
fn scratch() {
    for (nu, p2, p3) in [
        (0.5, f64::INFINITY, 0.0),
        (0.3, 0.1, 1.0),
        (0.49, 1e-4, 1.0),
        (0.0, 0.1, 1e-3),
        (0.45, 1e-2, 1e4),
        (-0.9, 1e-4, 1e-3),
        (0.5, 100.0, 0.001),
    ] {
        let g = Groups::new(nu, p2, p3).unwrap();
        let pr = g.canonical_material().unwrap().equivalent_relaxation();
        for rtol in [1e-6, 1e-9, 1e-11] {
            let t0 = Instant::now();
            let o = impact(&pr, rtol, false);
            let dt = t0.elapsed().as_secs_f64() * 1e3;
            match o {
                Ok(o) => println!("{nu} {p2} {p3} rtol={rtol:e}: e={:.15} tc={:.12} dm={:.12} est={:.2e} steps={} evals={} {dt:.2}ms", o.cor, o.contact_time, o.max_indentation, o.cor_error_estimate.unwrap(), o.work.steps, o.work.evaluations),
                Err(e) => println!("{nu} {p2} {p3} rtol={rtol:e}: ERR {e} {dt:.2}ms"),
            }
        }
    }
}
