//! Unit tests of the bench tables and targets.

use super::*;
use crate::report::validate::ExternalRow;

fn timing(cor: f64, steps: [u64; 2], evaluations: [u64; 2]) -> RowTiming {
    RowTiming {
        row: ExternalRow {
            nu: 0.3,
            p2: 1.0,
            p3: 1.0,
            cor,
            contact_time: 1.0,
            max_indentation: 0.5,
            est_rel_err: 1e-12,
        },
        seconds: [1e-5, 5e-5],
        cor_error: [1e-7, 1e-11],
        steps,
        evaluations,
        tight: [cor < 0.1, false],
    }
}

#[test]
fn timing_table_reports_mean_work_per_group() {
    let rows = [
        timing(0.95, [10, 40], [60, 300]),
        timing(0.05, [30, 90], [200, 700]),
        timing(0.04, [20, 70], [100, 500]),
    ];
    let table = timing_table(&rows, TimedRows::External);
    // means over the group's rows: (10+30+20)/3 = 20 steps, (60+200+100)/3 = 120 evaluations
    for (row, cell) in [
        ("| all rows | 3 |", "| 20.0 / 120 |"),
        ("| all rows | 3 |", "| 66.7 / 500 |"),
        ("| strongly dissipative", "| 25.0 / 150 | 100.0 % |"),
        ("| nearly elastic", "| 10.0 / 60 | 0.0 % |"),
        ("| all rows | 3 |", "| 20.0 / 120 | 66.7 % |"),
    ] {
        assert!(line_of(&table, row).contains(cell), "{cell} in\n{table}");
    }
    assert!(table.starts_with("| rows of the external tables | n |"));
    // without a reference (the random sample at rtol 1e-10): a dash, not NaN
    let mut random = rows.clone();
    for t in &mut random {
        t.cor_error[1] = f64::NAN;
    }
    let table = timing_table(&random, TimedRows::Random);
    assert!(table.starts_with("| random rows of the paper's range | n |"));
    let all = line_of(&table, "| all rows | 3 |");
    assert!(all.contains("| 1.0e-7 | 20.0 / 120 | 66.7 % |"), "{table}");
    assert!(all.contains("| - | 66.7 / 500 | 0.0 % |"), "{table}");
    assert!(!table.contains("NaN"), "{table}");
}

/// A paired timing of `rows` standard solids of mean work 20 steps / 150 evaluations.
fn paired(rows: usize, case: f64, standard: f64) -> Option<Paired> {
    Some(Paired {
        rows,
        case,
        standard,
        work: (20.0, 150.0),
    })
}

#[test]
fn general_timing_table_compares_within_the_cor_group() {
    let general = [
        GeneralTiming {
            id: "g-elastic",
            terms: 30,
            cor: 0.97,
            seconds: 3e-5,
            steps: 40,
            evaluations: 250,
            unreduced_seconds: 6e-5,
            group: paired(1, 3.3e-5, 1.1e-5),
            band: paired(1, 3.2e-5, 0.8e-5),
        },
        GeneralTiming {
            id: "g-dissipative",
            terms: 62,
            cor: 0.6,
            seconds: 2e-5,
            steps: 35,
            evaluations: 200,
            unreduced_seconds: 4e-5,
            group: paired(2, 2e-5, 1e-5),
            band: None,
        },
    ];
    let table = general_timing_table(&general);
    // the ratios and the work are the paired timings' (3.3 / 1.1 and 3.2 / 0.8), the group
    // named by the case's CoR; the dissipative case has no band rows
    let e = line_of(&table, "| g-elastic | 30 |");
    assert!(
        e.contains("| nearly elastic (e >= 0.9): 1, 11.0 µs / 33.0 µs, 20.0 / 150 | 3.0 |")
            && e.ends_with("| 1, 8.0 µs / 32.0 µs, 20.0 / 150 | 4.0 |"),
        "{table}"
    );
    let d = line_of(&table, "| g-dissipative | 62 |");
    assert!(
        d.contains("| dissipative (0.1 <= e < 0.9): 2, 10.0 µs / 20.0 µs, 20.0 / 150 | 2.0 |")
            && d.ends_with("| - | - |"),
        "{table}"
    );
    // not timed in alternation (no random sample): dashes
    let mut unpaired = general.clone();
    for g in &mut unpaired {
        (g.group, g.band) = (None, None);
    }
    let table = general_timing_table(&unpaired);
    assert!(
        line_of(&table, "| g-elastic").ends_with("| - | - | - | - |"),
        "{table}"
    );
}

fn line_of(table: &str, prefix: &str) -> String {
    table
        .lines()
        .find(|l| l.starts_with(prefix))
        .unwrap_or_else(|| panic!("no row {prefix} in\n{table}"))
        .to_string()
}

/// The 2x target applies to the real polymers of at least 30 terms only, each against the
/// standard solids of its own CoR group timed in alternation with it, and lands in the target
/// list with the ratio against the standard solids of about its CoR.
#[test]
fn general_targets_compare_polymers_with_their_group() {
    let g = |id: &'static str, terms, cor, case: f64| GeneralTiming {
        id,
        terms,
        cor,
        seconds: 2.0 * case,
        steps: 40,
        evaluations: 300,
        unreduced_seconds: 4.0 * case,
        group: paired(2, case, 10e-6),
        band: paired(1, case, 12e-6),
    };
    let rows = [
        g("polyisobutylene", 30, 0.28, 18e-6),
        g("epoxy", 24, 0.94, 90e-6),
        g("prony-30-incompressible", 30, 0.87, 90e-6),
    ];
    let t = general_targets(&rows);
    assert_eq!(t.len(), 1, "{t:?}");
    assert!(t[0].contains("`polyisobutylene`"), "{}", t[0]);
    assert!(
        t[0].contains(
            ": met (1.8x: 18.0 µs against 10.0 µs, timed in alternation with 2 of the group's \
             rows; 1.5x the 1 standard solids within 0.05 of its CoR (18.0 µs against 12.0 µs))"
        ),
        "{}",
        t[0]
    );
    let slow = [g("polyisobutylene", 30, 0.28, 35e-6)];
    let t = general_targets(&slow);
    assert!(t[0].contains("**not met** (3.5x"), "{}", t[0]);
    // not timed in alternation: no verdict
    let mut unpaired = slow.clone();
    unpaired[0].group = None;
    assert!(general_targets(&unpaired).is_empty());
    let text = targets(&[], None, None, &t);
    assert!(text.contains("- the 30-term real polymer"), "{text}");
}

fn batch_of(rows: usize, seconds: f64, solves: (f64, f64)) -> BatchTiming {
    BatchTiming {
        rows,
        seconds,
        solves,
    }
}

/// The batch target says whether the solves alone, and one unverified solve per row, could
/// meet it.
#[test]
fn batch_target_names_the_floor_of_the_verification() {
    let cases = [
        (
            batch_of(100_000, 1.9, (1.8, 1.5)),
            "**not met** (100000 rows in 1.90 s; the solves alone took 1.80 s, and one \
             unverified solve per row 1.50 s: above the target even without any verification)",
        ),
        (
            batch_of(100_000, 1.2, (1.1, 0.9)),
            "**not met** (100000 rows in 1.20 s; the solves alone took 1.10 s, one unverified \
             solve per row 0.90 s)",
        ),
    ];
    for (batch, want) in cases {
        let text = targets(&[], None, Some(batch), &[]);
        assert!(text.contains(want), "{text}");
    }
}

/// [`batch_timing`] on a few rows: the three paths run without error, each timed.
#[test]
fn batch_timing_times_the_three_paths() {
    let b = batch_timing(8).unwrap();
    assert_eq!(b.rows, 8);
    let (verified, one) = b.solves;
    assert!(b.seconds > 0.0 && verified > 0.0 && one > 0.0, "{b:?}");
}

#[test]
fn targets_name_the_groups_that_miss_them() {
    let mut slow = timing(0.05, [30, 90], [200, 700]);
    slow.seconds = [40e-6, 150e-6];
    let rows = [timing(0.95, [10, 40], [60, 300]), slow];
    let text = targets(
        &[(TimedRows::External, rows.to_vec())],
        Some(3250.0),
        Some(batch_of(100_000, 0.99, (0.9, 0.8))),
        &[],
    );
    // all rows: median of 10 µs and 40 µs is the upper one (40 µs)
    assert!(
        text.contains(
            "median at most 20.0 µs at rtol 1e-6 on the rows of the external tables: met in 1 \
             of 3 groups, **not met** in all rows (40.0 µs), strongly dissipative (e < 0.1) \
             (40.0 µs)"
        ),
        "{text}"
    );
    assert!(
        text.contains("at rtol 1e-10 on the rows of the external tables: met in all 3 groups"),
        "{text}"
    );
    assert!(text.contains(": met (3250x)"), "{text}");
    assert!(
        text.contains(
            ": met (100000 rows in 0.99 s; the solves alone took 0.90 s, one unverified solve \
             per row 0.80 s)"
        ),
        "{text}"
    );
    let late = targets(&[], None, Some(batch_of(100_000, 1.01, (0.95, 0.9))), &[]);
    assert!(
        late.contains(
            "in at most 1 s: **not met** (100000 rows in 1.01 s; the solves alone took 0.95 s, \
             one unverified solve per row 0.90 s)"
        ),
        "{late}"
    );
    let fast = [timing(0.95, [10, 40], [60, 300])];
    let text = targets(
        &[
            (TimedRows::External, rows.to_vec()),
            (TimedRows::Random, fast.to_vec()),
        ],
        Some(900.0),
        Some(batch_of(1000, 0.1, (0.08, 0.07))),
        &[],
    );
    assert!(
        text.contains("at rtol 1e-6 on the random rows of the paper's range: met in all 2 groups"),
        "{text}"
    );
    assert!(text.contains("**not met** (900x)"), "{text}");
    assert!(
        !text.contains("cor --input"),
        "a smaller batch is not the target: {text}"
    );
}

#[test]
fn random_timing_measures_every_row_against_its_tight_solve() {
    let t = random_timing(20, RANDOM_SEED, &|| {}).unwrap();
    assert_eq!(t.len(), 20);
    for r in &t {
        let row = &r.row;
        assert!((-0.99..=0.5).contains(&row.nu), "{row:?}");
        assert!((1e-4..=1e2).contains(&row.p2) && (1e-3..=1e4).contains(&row.p3));
        assert!(row.cor > 0.0 && row.cor <= 1.0, "{row:?}");
        // the rtol 1e-6 CoR is within its request of the rtol 1e-10 one
        assert!(r.cor_error[0] <= 1e-6, "{r:?}");
        assert!(r.cor_error[1].is_nan());
        assert!(r.seconds.iter().all(|&s| s > 0.0 && s.is_finite()));
        assert!(r.steps[1] > r.steps[0] && r.evaluations[1] > r.evaluations[0]);
    }
    // the same sample as `cor --input` draws for this seed
    let rows = crate::apps::batch::random_rows(20, RANDOM_SEED).unwrap();
    assert_eq!(rows[3].groups.p3, t[3].row.p3);
}

#[test]
fn external_csv_has_work_columns() {
    let dir = std::env::temp_dir().join(format!("mdr-impact-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bench_external.csv");
    write_timing_csv(
        &path,
        &[timing(0.5, [12, 45], [70, 310])],
        TimedRows::External,
    )
    .unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let values: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| values[header.iter().position(|h| *h == name).unwrap()];
    assert_eq!(col("steps_rtol_1e-6"), "12");
    assert_eq!(col("evaluations_rtol_1e-6"), "70");
    assert_eq!(col("steps_rtol_1e-10"), "45");
    assert_eq!(col("evaluations_rtol_1e-10"), "310");
    assert_eq!(col("tight_check_rtol_1e-6"), "0");
    assert_eq!(col("tight_check_rtol_1e-10"), "0");
    assert_eq!(col("cor_reference").parse::<f64>().unwrap(), 0.5);
}

fn report(quick: bool) -> BenchReport {
    let point = |solver, rtol, seconds, cor_error| BenchPoint {
        solver,
        rtol,
        case: "dissipative-nu045",
        regime: "dissipative",
        median_seconds: seconds,
        repeats: 3,
        cor_error,
        force_error: 1e-5,
        verified: true,
    };
    BenchReport {
        options: BenchOptions {
            quick,
            budget: 0.1,
            batch_rows: 0,
            baseline: None,
        },
        points: vec![
            point(SolverKind::MdrEuler, 1e-4, 2e-2, 5e-5),
            point(SolverKind::Fast, 1e-4, 2e-5, 1e-6),
            BenchPoint {
                verified: false,
                ..point(SolverKind::Fast, 1e-4, 1e-5, 3e-6)
            },
        ],
        timed: if quick {
            vec![]
        } else {
            vec![(TimedRows::Random, vec![timing(0.5, [10, 20], [60, 120])])]
        },
        general: vec![],
        euler_general: None,
        fit: FitTiming {
            seconds: 1.5,
            solves: 100,
            drops: 10,
        },
        batch: Some(batch_of(1000, 0.25, (0.2, 0.17))),
        curve_seconds: 0.0125,
        shapes: vec![],
        machine: "a test machine".into(),
        baseline: None,
        scipy: ScipyComparison::NotMeasured("no python here".into()),
        seconds: 150.0,
    }
}

#[test]
fn full_report_text_section_and_files() {
    let r = report(false);
    let text = r.text();
    let first = text.lines().next().unwrap();
    assert!(first.starts_with("mdr-euler  rtol=1e-4"), "{first}");
    assert!(
        text.contains(
            "cor --input path: 1000 rows in 0.25 s. The solves alone (`fast` at rtol 1e-6, all \
             cores): 0.20 s verified (`fast` as `cor --input` calls it), 0.17 s as one \
             unverified solve per row at the same rtol (`fast::impact_unverified`, no check at \
             all: 0.85 of the verified time).\n"
        ),
        "{text}"
    );
    assert!(text.contains("curve --v0 0.01:10:200 --log (default scene): 0.013 s\n"));
    assert!(text.contains("Design targets of `fast`"), "{text}");
    let section = r.section();
    assert!(section.starts_with("Measured by `mdr-impact bench` in one run on a test machine"));
    assert!(section.contains("`mdr-impact fit` of 10 drops"));
    // the verified fast beside one unverified solve: times 20 us and 10 us, ratio 2
    assert!(
        section.contains("| 1e-4 | 10.0 µs | 3.0e-6 | 20.0 µs | 1.0e-6 | 2.00 |"),
        "{section}"
    );
    assert!(section.contains(
        "\n`mdr-impact curve --v0 0.01:10:200 --log` on the default scene (200 velocities, all \
         cores): 0.013 s.\n"
    ));
    // the SciPy comparison follows the shapes' table (empty rows here); the run's own wall
    // time closes the section
    assert!(
        section.ends_with(
            "| --- | --- | --- |\n\n`fast` against the SciPy script (`python/scipy_cor.py`): \
             not measured (no python here).\n\nThis run of `mdr-impact bench` took 2.5 min.\n"
        ),
        "{section}"
    );
    assert!(
        text.contains("- `fast` against the SciPy script: not measured (see above)."),
        "{text}"
    );
    let dir = tempfile::tempdir().unwrap();
    r.write_files(dir.path()).unwrap();
    for f in ["bench.csv", "work-precision.svg", "bench_random.csv"] {
        assert!(dir.path().join(f).exists(), "{f}");
    }
    // quick: no row timings, no targets
    let q = report(true);
    assert!(!q.text().contains("Design targets"));
    assert_eq!(full_units(&q.options).unwrap(), units(true));
}

#[test]
fn run_full_refuses_a_budget_that_is_not_positive() {
    for budget in [0.0, -1.0, f64::NAN] {
        let opts = BenchOptions {
            quick: true,
            budget,
            batch_rows: 0,
            baseline: None,
        };
        assert!(matches!(
            run_full(&opts, &|| {}),
            Err(Error::OutOfRange {
                field: "--budget",
                ..
            })
        ));
    }
}

#[test]
fn baseline_rows_and_text() {
    let csv = baseline_rows_csv(200, 28);
    assert_eq!(csv, baseline_rows_csv(200, 28));
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 200);
    for r in &rows {
        assert!((-0.5..=0.5).contains(&r[0]), "{r:?}");
        assert!(
            (1e-3..=1e2).contains(&r[1]) && (1e-2..=1e3).contains(&r[2]),
            "{r:?}"
        );
    }
    let b = BaselineRatio {
        baseline: "old/mdr-impact".into(),
        rows: 200,
        baseline_seconds: 2.0,
        today_seconds: 2.5,
        max_cor_difference: 3e-7,
    };
    assert_eq!(b.ratio(), 1.25);
    let t = b.text();
    assert!(
        t.contains("2.500 s against 2.000 s, a ratio of **1.25**"),
        "{t}"
    );
    assert!(
        t.contains("`old/mdr-impact`") && t.contains("3.0e-7"),
        "{t}"
    );
}

#[test]
fn scipy_rows_and_text() {
    let rows = scipy_rows(28);
    assert_eq!(rows, scipy_rows(28));
    assert_eq!(rows.len(), SCIPY_ROWS);
    for &(nu, p2, p3) in &rows {
        assert!((-0.5..=0.5).contains(&nu) && (1e-3..=1e2).contains(&p2));
        assert!((1e-2..=1e3).contains(&p3) && p2 * p3 >= SCIPY_MIN_TAU);
    }
    let m = ScipyComparison::Measured {
        rows: 20,
        scipy_seconds: 1.5,
        fast_seconds: 1.5e-3,
        max_cor_difference: 4e-9,
    };
    assert_eq!(m.ratio(), Some(1000.0));
    let t = m.text();
    assert!(
        t.contains("1.500 s against 1.50 ms, a ratio of **1000**") && t.contains("4.0e-9"),
        "{t}"
    );
    assert_eq!(ScipyComparison::NotMeasured("x".into()).ratio(), None);
}

/// The alternation solves the case once per row and pass: positive medians, one per side; no
/// rows, no timing.
#[test]
fn alternate_times_case_and_rows() {
    let p = |p2, p3| {
        crate::model::impact::Impact::from_groups(
            crate::model::impact::Groups::new(0.3, p2, p3).unwrap(),
        )
        .unwrap()
        .canonical_relaxation()
    };
    let case = p(0.1, 1.0);
    let got = alternate(&case, &[p(1.0, 0.1), p(0.01, 3.0)])
        .unwrap()
        .unwrap();
    assert_eq!(got.rows, 2);
    assert!(got.case > 0.0 && got.standard > 0.0 && got.ratio().is_finite());
    assert!(got.work.0 >= 1.0 && got.work.1 >= got.work.0, "{got:?}");
    assert_eq!(alternate(&case, &[]).unwrap(), None);
}

#[test]
fn shape_table_names_the_shapes_over_the_target() {
    let row = |shape: &'static str, ratio: f64| ShapeTiming {
        shape,
        seconds: 2e-5 * ratio,
        ratio,
    };
    let all = [
        row("paraboloid", 1.0),
        row("cone", 1.18),
        row("flat punch", 0.27),
    ];
    let t = shape_timing_table(&all);
    assert!(
        t.contains("At most 1.5x the paraboloid: met by all 2 shapes."),
        "{t}"
    );
    // 1.504 prints as 1.50: met, as the table shows it
    let some = [
        row("paraboloid", 1.0),
        row("power law n = 3", 1.504),
        row("exact sphere", 1.74),
    ];
    let t = shape_timing_table(&some);
    assert!(
        t.contains("met by 1 of 2 shapes, **not met** by exact sphere (1.74)."),
        "{t}"
    );
}
