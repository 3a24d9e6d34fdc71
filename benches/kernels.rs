//! Criterion benches of the solver kernels on catalogue cases (one per regime): each solver at
//! a representative accuracy, and the MDR foundation at a fixed resolution (no adaptivity), so a
//! change in the cost of a kernel is seen apart from a change in the step-size control.
//! The work-precision study across accuracies is `mdr-impact bench`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use mdr_impact::report::catalogue::impact_case;
use mdr_impact::{solve, solvers, solvers::mdr, SolveOptions, SolverKind};

const CASES: &[&str] = &[
    "dissipative-nu045",
    "near-incompressible-nu049",
    "stiff-tau-1e-6",
];

fn solvers(c: &mut Criterion) {
    let mut g = c.benchmark_group("impact");
    g.sample_size(20);
    for id in CASES {
        let imp = impact_case(id).unwrap().impact().unwrap();
        for (solver, rtol) in [
            (SolverKind::Fast, 1e-6),
            (SolverKind::Fast, 1e-10),
            (SolverKind::Reference, 1e-10),
            (SolverKind::Mdr, 1e-4),
        ] {
            let opts = SolveOptions {
                solver,
                rtol,
                ..Default::default()
            };
            g.bench_with_input(
                BenchmarkId::new(format!("{solver} rtol={rtol:e}"), id),
                &opts,
                |b, o| b.iter(|| solve(&imp, o).unwrap()),
            );
        }
    }
    g.finish();
}

fn foundation(c: &mut Criterion) {
    let mut g = c.benchmark_group("mdr-foundation");
    g.sample_size(20);
    let imp = impact_case("dissipative-nu045").unwrap().impact().unwrap();
    let mat = solvers::canonical_material(&imp).unwrap();
    let layout = mdr::pilot(&mat.prony).unwrap();
    for scheme in [mdr::Scheme::Exponential, mdr::Scheme::Euler] {
        g.bench_function(
            format!("{} 256 elements x 2048 steps", scheme.name()),
            |b| b.iter(|| mdr::run_resolution(scheme, &mat, &layout, 256, 2048, false).unwrap()),
        );
    }
    g.finish();
}

criterion_group!(benches, solvers, foundation);
criterion_main!(benches);
