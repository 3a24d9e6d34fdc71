//! Accuracy of `fast` against the external tables (`reference/external/cor_python*.csv`, all 765
//! rows) at rtol 1e-6 (bound 1e-6) and 1e-10 (bound 1e-9), median time per impact (best of
//! `XREPS` runs, default 9), and consistency of histories. Env: `XRTOL` (that rtol only, bound `max(rtol, 1e-9)`),
//! `XDUMP` (append `rtol,row,cor,cor_ref,steps,time_us,nu,p2,p3,levels,error_estimate` to a
//! file),
//! `XROWS` (a CSV `nu,p2,p3,cor,...` to check instead of the external table),
//! `XCOR_BELOW` (only the rows whose reference CoR is below this value).
//! `cargo test --release --test suite fast_xcheck:: -- --ignored --nocapture`
use mdr_impact::report::validate::external_rows;
use mdr_impact::{solvers::fast, Groups, Impact};
use std::time::Instant;

struct Row {
    nu: f64,
    p2: f64,
    p3: f64,
    cor: f64,
}

#[test]
#[ignore = "throwaway accuracy + timing"]
fn xcheck() {
    // XROWS: another table with the columns nu,p2,p3,cor first (e.g. `cor --input` output)
    let rows: Vec<Row> = match std::env::var("XROWS") {
        Ok(path) => std::fs::read_to_string(path)
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| {
                let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
                Row {
                    nu: v[0],
                    p2: v[1],
                    p3: v[2],
                    cor: v[3],
                }
            })
            .collect(),
        Err(_) => external_rows()
            .unwrap()
            .iter()
            .map(|r| Row {
                nu: r.nu,
                p2: r.p2,
                p3: r.p3,
                cor: r.cor,
            })
            .collect(),
    };
    let rows: Vec<Row> = match std::env::var("XCOR_BELOW") {
        Ok(v) => {
            let below: f64 = v.parse().unwrap();
            rows.into_iter().filter(|r| r.cor < below).collect()
        }
        Err(_) => rows,
    };
    let pr: Vec<_> = rows
        .iter()
        .map(|r| {
            Impact::from_groups(Groups::new(r.nu, r.p2, r.p3).unwrap())
                .unwrap()
                .canonical_relaxation()
        })
        .collect();
    let only: Option<f64> = std::env::var("XRTOL").ok().map(|v| v.parse().unwrap());
    // XRTOL: that rtol alone, bound max(rtol, 1e-9)
    let list = match only {
        Some(o) => vec![(o, o.max(1e-9))],
        None => vec![(1e-6, 1e-6), (1e-10, 1e-9)],
    };
    for &(rtol, bound) in &list {
        let mut times = Vec::new();
        let mut maxerr: f64 = 0.0;
        let mut worst = 0;
        let mut bad = 0;
        let mut steps = 0u64;
        let mut evals = 0u64;
        for (i, (r, p)) in rows.iter().zip(&pr).enumerate() {
            let mut best = f64::INFINITY;
            let mut o = None;
            for _ in 0..std::env::var("XREPS").map_or(9, |v| v.parse().unwrap()) {
                let t0 = Instant::now();
                let out = fast::impact(p, rtol, false);
                best = best.min(t0.elapsed().as_secs_f64() * 1e6);
                o = Some(out);
            }
            times.push(best);
            let o = o.unwrap().unwrap();
            if let Ok(f) = std::env::var("XDUMP") {
                use std::io::Write;
                let mut w = std::fs::OpenOptions::new()
                    .create(true)
                    .append(true)
                    .open(f)
                    .unwrap();
                writeln!(
                    w,
                    "{rtol:e},{i},{:.17e},{},{},{},{},{},{},{},{}",
                    o.cor,
                    r.cor,
                    o.work.steps,
                    best,
                    r.nu,
                    r.p2,
                    r.p3,
                    o.work.levels,
                    o.cor_error_estimate.unwrap_or(f64::NAN)
                )
                .unwrap();
            }
            steps += o.work.steps;
            evals += o.work.evaluations;
            let err = ((o.cor - r.cor) / r.cor).abs();
            if err.is_nan() || err > bound {
                bad += 1;
            }
            if err.is_nan() || err > maxerr {
                maxerr = err;
                worst = i;
            }
        }
        times.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let n = times.len();
        println!(
            "rtol {rtol:e}: median {:.1} us, p90 {:.1}, max {:.1}; max err {maxerr:.2e} (row {worst}: nu={} p2={} p3={} cor={}), bad {bad}, mean steps {:.1}, evals {:.0}",
            times[n / 2], times[n * 9 / 10], times[n - 1], rows[worst].nu, rows[worst].p2, rows[worst].p3, rows[worst].cor,
            steps as f64 / n as f64, evals as f64 / n as f64
        );
        assert_eq!(bad, 0);
    }
    // histories
    for p in pr.iter().step_by(37) {
        let o = fast::impact(p, 1e-8, true).unwrap();
        let h = o.history.unwrap();
        assert!(h.len() > 3);
        assert!(h.t.windows(2).all(|w| w[1] > w[0]));
        assert!((h.v[h.len() - 1] + o.cor).abs() < 1e-12);
        assert!((h.t[h.len() - 1] - o.contact_time).abs() < 1e-12);
    }
}
