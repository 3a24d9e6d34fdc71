//! Sweeps and figures: grid parsing, CSV columns, resume after an interrupt, marching squares,
//! scaling check, the figures command end to end on a coarse grid.

use std::path::Path;

use mdr_impact::apps::sweep::{self, LogRange, Plan, Sampling, SweepOptions, COLUMNS};
use mdr_impact::report::figures::contour::{isolines, Field};
use mdr_impact::report::figures::{self, stats, FigureOptions};
use mdr_impact::{Error, SolveOptions, SolverKind};

fn opts(dimensional: Option<u64>) -> SweepOptions {
    SweepOptions {
        solve: SolveOptions::with(SolverKind::Mdr, 1e-3),
        dimensional,
        check_every: 2,
        resume: true,
    }
}

fn small_plan() -> Plan {
    Plan {
        nu: vec![0.3, 0.5],
        log_p2: LogRange::parse("log-p2", "-2:0:3").unwrap(),
        log_p3: LogRange::parse("log-p3", "-1:1:3").unwrap(),
        sampling: Sampling::Grid,
    }
}

#[test]
fn grid_parsing() {
    let r = LogRange::parse("log-p2", "-3:1:5").unwrap();
    assert_eq!(
        r.values("log-p2").unwrap(),
        vec![-3.0, -2.0, -1.0, 0.0, 1.0]
    );
    assert_eq!(
        LogRange::parse("log-p3", " 2 ")
            .unwrap()
            .values("log-p3")
            .unwrap(),
        vec![2.0]
    );
    // MIN:MAX is enough for random samples but not for a grid
    let r = LogRange::parse("log-p3", "-2:3").unwrap();
    assert_eq!(r.n, None);
    assert!(matches!(
        r.values("log-p3"),
        Err(Error::NotSupported {
            solver: "log-p3",
            ..
        })
    ));
    // errors name the option
    for (s, needle) in [
        ("1:-1:3", "log-p2"),
        ("a:1:3", "log-p2"),
        ("0:1:x", "log-p2"),
        ("0:1:2:3", "log-p2"),
        ("0:1:1", "log-p2"),
    ] {
        let e = LogRange::parse("log-p2", s).unwrap_err();
        assert!(e.to_string().contains(needle), "{s}: {e}");
    }
    assert!(matches!(
        LogRange::parse("log-p2", "0:1:0"),
        Err(Error::OutOfRange {
            field: "log-p2",
            ..
        })
    ));
    assert!(matches!(
        LogRange::parse("log-p2", "0:inf:3"),
        Err(Error::OutOfRange {
            field: "log-p2",
            ..
        })
    ));
    assert_eq!(
        sweep::parse_nu_list("0, 0.3,0.49,inc").unwrap(),
        vec![0.0, 0.3, 0.49, 0.5]
    );
    assert!(matches!(
        sweep::parse_nu_list("0.6"),
        Err(Error::OutOfRange { field: "nu", .. })
    ));
    assert!(sweep::parse_nu_list("0.3,0.3").is_err());
    assert!(sweep::parse_nu_list("x").is_err());
    // plan order: nu outermost, p3 innermost; random plans are reproducible
    let pts = small_plan().points().unwrap();
    assert_eq!(pts.len(), 18);
    assert_eq!(
        (pts[1].nu, pts[1].log10_p2, pts[1].log10_p3),
        (0.3, -2.0, 0.0)
    );
    assert_eq!(pts[9].nu, 0.5);
    let mut rp = small_plan();
    rp.sampling = Sampling::Random { n: 7, seed: 3 };
    let a = rp.points().unwrap();
    assert_eq!(a, rp.points().unwrap());
    assert!(a
        .iter()
        .all(|p| (-2.0..=0.0).contains(&p.log10_p2) && (-1.0..=1.0).contains(&p.log10_p3)));
}

#[test]
fn csv_columns() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.csv");
    let pts = small_plan().points().unwrap();
    let s = sweep::run(&pts, &out, &opts(None), &|| {}).unwrap();
    assert_eq!((s.planned, s.computed, s.resumed, s.failed), (18, 18, 0, 0));
    let text = std::fs::read_to_string(&out).unwrap();
    let header = text.lines().next().unwrap();
    assert_eq!(header, COLUMNS.join(","));
    assert_eq!(
        header,
        "index,nu,p2,p3,log10_p2,log10_p3,cor,cor_error_estimate,contact_time,max_indentation,\
         mass,radius,velocity,g_inf,g_1,eta,k_0,cor_canonical,scaling_dev,solver,rtol,\
         dimensional,seconds,error"
    );
    let recs = sweep::read_records(&out).unwrap();
    // complete run: rows rewritten in index order
    assert!(recs
        .iter()
        .enumerate()
        .all(|(i, r)| r.point.index == i as u64));
    for r in &recs {
        let e = r.cor.unwrap();
        assert!(e > 0.0 && e <= 1.0, "{e}");
        assert_eq!(r.solver, "mdr");
        assert!(r.error.is_empty());
        assert_eq!(r.k_0.is_none(), r.point.nu == 0.5);
        assert_eq!(r.inputs[..3], [1.0, 1.0, 1.0]); // canonical units
    }
    // a foreign CSV is refused with the file named
    let other = dir.path().join("other.csv");
    std::fs::write(&other, "nu,p2,p3\n0.3,1,1\n").unwrap();
    let e = sweep::run(&pts, &other, &opts(None), &|| {}).unwrap_err();
    assert!(matches!(&e, Error::Csv { line: 1, .. }), "{e}");
}

#[test]
fn resume_after_interrupt_does_not_recompute() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.csv");
    let pts = small_plan().points().unwrap();
    sweep::run(&pts, &out, &opts(None), &|| {}).unwrap();
    let full = std::fs::read_to_string(&out).unwrap();
    let lines: Vec<&str> = full.lines().collect();
    // simulate a run killed after 5 rows, in the middle of writing the 6th, with rows out of
    // order; mark one finished row so that a recomputation would show
    let mut marked: Vec<String> = lines[1..6].iter().map(|s| s.to_string()).collect();
    marked.reverse();
    let f: Vec<&str> = marked[0].split(',').collect();
    let marked_index: u64 = f[0].parse().unwrap();
    let mut g: Vec<String> = f.iter().map(|s| s.to_string()).collect();
    g[6] = "1.234e-1".into(); // cor
    marked[0] = g.join(",");
    let torn = &lines[6][..lines[6].len() / 2];
    let text = format!("{}\n{}\n{}", lines[0], marked.join("\n"), torn);
    std::fs::write(&out, text).unwrap();
    // a partial file reads back without the torn line
    assert_eq!(sweep::read_records(&out).unwrap().len(), 5);

    let s = sweep::run(&pts, &out, &opts(None), &|| {}).unwrap();
    assert_eq!((s.resumed, s.computed), (5, 13));
    let recs = sweep::read_records(&out).unwrap();
    assert_eq!(recs.len(), 18);
    assert!(recs
        .iter()
        .enumerate()
        .all(|(i, r)| r.point.index == i as u64));
    assert_eq!(recs[marked_index as usize].cor, Some(0.1234)); // kept, not recomputed

    // nothing left to do
    let s = sweep::run(&pts, &out, &opts(None), &|| {}).unwrap();
    assert_eq!((s.resumed, s.computed), (18, 0));
    // a different sweep on the same file is refused
    let mut o = opts(None);
    o.solve.rtol = 1e-4;
    let e = sweep::run(&pts, &out, &o, &|| {}).unwrap_err();
    assert!(e.to_string().contains("different sweep"), "{e}");
    // ... unless asked to start afresh
    o.resume = false;
    let s = sweep::run(&pts, &out, &o, &|| {}).unwrap();
    assert_eq!((s.resumed, s.computed), (0, 18));
}

#[test]
fn scaling_check_with_dimensional_inputs() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("d.csv");
    let pts = small_plan().points().unwrap();
    let s = sweep::run(&pts, &out, &opts(Some(7)), &|| {}).unwrap();
    assert_eq!(s.checks, 9); // every 2nd of 18
    assert!(s.max_scaling_dev.unwrap() < 1e-9, "{s}");
    let recs = sweep::read_records(&out).unwrap();
    for r in &recs {
        assert!(r.dimensional);
        let [m, rad, v0, g_inf, g_1, eta] = r.inputs;
        assert!(m != 1.0 && rad != 1.0 && v0 != 1.0 && g_inf != 1.0);
        // the drawn inputs reproduce the planned groups (Eq. 11)
        assert!((g_inf / g_1 / r.p2 - 1.0).abs() < 1e-12);
        let p3 = eta * (v0 * rad / (m * m * g_inf.powi(3))).powf(0.2);
        assert!((p3 / r.p3 - 1.0).abs() < 1e-12, "{p3} vs {}", r.p3);
    }
    // the same seed draws the same inputs
    let again = sweep::dimensional_impact(pts[3].groups().unwrap(), 7, 3).unwrap();
    assert_eq!(again.sphere().mass(), recs[3].inputs[0]);
}

#[test]
fn marching_squares_circle() {
    let n = 41;
    let c: Vec<f64> = (0..n)
        .map(|i| -1.0 + 2.0 * i as f64 / (n - 1) as f64)
        .collect();
    let mut z = Vec::new();
    for &y in &c {
        for &x in &c {
            z.push(x * x + y * y);
        }
    }
    let f = Field::new(c.clone(), c.clone(), z).unwrap();
    let lines = isolines(&f, 0.25);
    assert_eq!(lines.len(), 1);
    let l = &lines[0];
    assert_eq!(l.first(), l.last(), "closed");
    for &(x, y) in l {
        let r = (x * x + y * y).sqrt();
        assert!((r - 0.5).abs() < 2e-3, "r = {r}");
    }
    let len = figures::contour::length(l);
    assert!((len - std::f64::consts::PI).abs() < 0.01, "{len}");
    // a level outside the field gives nothing; an open line crosses the border
    assert!(isolines(&f, 5.0).is_empty());
    let open = isolines(&f, 1.5);
    assert_eq!(open.len(), 4); // four arcs cut by the corners of the square
    assert!(open.iter().all(|l| l.first() != l.last()));
    // saddle: z = x y has the level-0 lines along the axes
    let mut z = Vec::new();
    for &y in &c {
        for &x in &c {
            z.push((x - 0.013) * (y - 0.017));
        }
    }
    let f = Field::new(c.clone(), c, z).unwrap();
    let total: f64 = isolines(&f, 0.0)
        .iter()
        .map(|l| figures::contour::length(l))
        .sum();
    assert!((total - 4.0).abs() < 0.05, "{total}");
    assert!(Field::new(vec![0.0], vec![0.0, 1.0], vec![0.0, 0.0]).is_err());
}

#[test]
fn spearman_and_splice() {
    let a = [1.0, 2.0, 3.0, 4.0];
    assert_eq!(stats::spearman(&a, &[10.0, 20.0, 30.0, 40.0]), Some(1.0));
    assert_eq!(stats::spearman(&a, &[4.0, 3.0, 2.0, 1.0]), Some(-1.0));
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("R.md");
    std::fs::write(
        &p,
        format!(
            "head\n{}\nold\n{}\ntail\n",
            figures::BEGIN_MARK,
            figures::END_MARK
        ),
    )
    .unwrap();
    figures::splice_results(&p, "new table\n").unwrap();
    let t = std::fs::read_to_string(&p).unwrap();
    assert!(t.contains("new table") && !t.contains("old") && t.ends_with("tail\n"));
    std::fs::write(&p, "no markers").unwrap();
    assert!(figures::splice_results(&p, "x").is_err());
}

fn exists_nonempty(p: &Path) -> bool {
    std::fs::metadata(p).map(|m| m.len() > 0).unwrap_or(false)
}

#[test]
fn figures_command_on_a_coarse_grid() {
    let dir = tempfile::tempdir().unwrap();
    let args = FigureOptions {
        out: dir.path().join("fig"),
        solver: SolverKind::Mdr,
        rtol: 1e-3,
        n_p2: 9,
        n_p3: 11,
        n_line: 11,
        ..Default::default()
    };
    let report = figures::run(&args, &|| {}).unwrap();
    assert!(report.contains("computed in"));
    for f in [
        "fig3_cor_nu0.45.svg",
        "fig4_cor_incompressible.svg",
        "fig5_cor_vs_p3_log_p2_-2.svg",
        "fig6_cor_vs_p3_log_p2_-3.svg",
        "relerr_nu0.45.svg",
        "relerr_nu0.49.svg",
        "fig3_cor_nu0.45.csv",
        "fig6_cor_vs_p3_log_p2_-3.csv",
        "relerr_nu0.49.csv",
        "maps.csv",
        "tables.md",
    ] {
        assert!(exists_nonempty(&args.out.join(f)), "{f}");
    }
    let svg = std::fs::read_to_string(args.out.join("fig3_cor_nu0.45.svg")).unwrap();
    assert!(svg.starts_with("<svg width=\"980\" height=\"680\""));
    let t = std::fs::read_to_string(args.out.join("tables.md")).unwrap();
    assert!(t.contains("### T3."));
    // bad grid sizes are refused with the option named
    let bad = FigureOptions {
        n_p2: 2,
        ..args.clone()
    };
    assert!(matches!(
        figures::run(&bad, &|| {}),
        Err(Error::OutOfRange { field: "n-p2", .. })
    ));
}

/// A point refused before its impact exists (p2 = 1e-300) has empty input cells, never `NaN`,
/// and a resume reads the file back without recomputing it.
#[test]
fn refused_points_write_no_nan_and_resume() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "sweep",
        "--nu",
        "0.45",
        "--log-p2",
        "-300:300:3",
        "--log-p3",
        "-2:3:3",
        "--out",
        "sw.csv",
    ];
    let o = crate::common::run(&args, dir.path());
    assert!(o.status.success(), "{}", crate::common::stderr(&o));
    let csv = std::fs::read_to_string(dir.path().join("sw.csv")).unwrap();
    assert!(!csv.contains("NaN") && !csv.contains(",inf"), "{csv}");
    let failed: Vec<&str> = csv
        .lines()
        .filter(|l| l.split(',').nth(2) == Some("1e-300"))
        .collect();
    assert_eq!(failed.len(), 3, "{csv}");
    let o = crate::common::run(&args, dir.path());
    assert!(o.status.success(), "{}", crate::common::stderr(&o));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("sw.csv")).unwrap(),
        csv
    );
}
