//! Criterion benches of the solver kernels on representative cases.
use criterion::{criterion_group, criterion_main, Criterion};
use mdr_impact::{solve, Groups, Impact, SolveOptions, SolverKind};

fn bench(c: &mut Criterion) {
    let cases = [
        ("dissipative nu=0.45", 0.45, 0.01, 1.0),
        ("incompressible", 0.5, 0.001, 10.0),
    ];
    for (name, nu, p2, p3) in cases {
        let imp = Impact::from_groups(Groups::new(nu, p2, p3).unwrap()).unwrap();
        for rtol in [1e-4, 1e-6] {
            let opts = SolveOptions {
                solver: SolverKind::Mdr,
                rtol,
                ..Default::default()
            };
            c.bench_function(&format!("mdr {name} rtol={rtol:e}"), |b| {
                b.iter(|| solve(&imp, &opts).unwrap())
            });
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
