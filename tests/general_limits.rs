//! Limits of a general material as an insta snapshot (`snapshots/general_limits.snap`): a
//! one-term Prony series is the standard solid; all relaxation times to infinity give Hertz with
//! the glassy `G_eq`, all to zero Hertz with the relaxed one; `K -> infinity` gives the
//! incompressible result; splitting every term into two equal halves changes nothing. Each line
//! holds the relative deviation from its limit (two significant digits) and is also asserted
//! against a stated bound. Unit sphere at unit speed, relaxed shear modulus 1: canonical units.
use mdr_impact::model::material::{BulkInput, Material, ShearProny};
use mdr_impact::report::validate::fmt_err;
use mdr_impact::{solve, Impact, Outcome, SolveOptions, SolverKind, Sphere};

use crate::common;
use common::rel_err;

const RTOL: f64 = 1e-10;
/// Hertz contact time over the maximum indentation (docs/theory.md §6).
const HERTZ_TC: f64 = 2.943_275_184_324_704_7;

fn fast(imp: &Impact) -> Outcome {
    solve(imp, &SolveOptions::with(SolverKind::Fast, RTOL)).unwrap()
}

fn general(terms: &[(f64, f64)], bulk: BulkInput) -> Impact {
    let m = Material::general(ShearProny::new(1.0, terms).unwrap(), bulk).unwrap();
    Impact::with_general(Sphere::new(1.0, 1.0).unwrap(), 1.0, m).unwrap()
}

/// Hertz contact time of the unit impact on `G_eq = g` (canonical units).
fn hertz_contact_time(g: f64) -> f64 {
    let k = 16.0 / 3.0 * g;
    HERTZ_TC * (1.25 / k).powf(0.4)
}

#[test]
fn general_limits() {
    let terms = [(100.0, 0.01), (30.0, 0.3), (10.0, 3.0)];
    let bulk = BulkInput::Poisson(0.45);
    let mut out = String::from("limit | quantity | relative deviation | bound\n");
    let mut line = |what: &str, quantity: &str, dev: f64, bound: f64| {
        assert!(dev.abs() <= bound, "{what} {quantity}: {dev:e} > {bound:e}");
        out.push_str(&format!(
            "{what} | {quantity} | {} | {bound:.0e}\n",
            fmt_err(dev)
        ));
    };

    // one term = the standard solid (G_1 = 100, eta = 1, nu = 0.45): the same shape, the same
    // path, the same outcome to the bit
    let standard = Material::with_poisson(1.0, 100.0, 1.0, 0.45).unwrap();
    let s = fast(&Impact::new(Sphere::new(1.0, 1.0).unwrap(), 1.0, standard).unwrap());
    let g = fast(&general(&[(100.0, 0.01)], BulkInput::Poisson(0.45)));
    line(
        "one term = standard solid",
        "CoR",
        rel_err(g.cor, s.cor),
        1e-12,
    );
    line(
        "one term = standard solid",
        "contact time",
        rel_err(g.contact_time, s.contact_time),
        1e-9,
    );

    // all relaxation times to infinity / to zero: Hertz with the glassy / relaxed G_eq
    let m = Material::general(ShearProny::new(1.0, &terms).unwrap(), bulk.clone()).unwrap();
    for (what, scale, modulus) in [
        ("times x 1e12", 1e12, m.equivalent_glassy()),
        ("times x 1e-12", 1e-12, m.equivalent_relaxed()),
    ] {
        let scaled: Vec<(f64, f64)> = terms.iter().map(|&(g, t)| (g, t * scale)).collect();
        let o = fast(&general(&scaled, bulk.clone()));
        line(what, "1 - CoR", 1.0 - o.cor, 1e-9);
        line(
            what,
            "contact time / Hertz",
            rel_err(o.contact_time, hertz_contact_time(modulus)),
            1e-8,
        );
    }

    // K -> infinity: the incompressible result
    let inc = fast(&general(&terms, BulkInput::Incompressible));
    let stiff = fast(&general(&terms, BulkInput::Elastic(1e14)));
    line(
        "k_0 = 1e14 = incompressible",
        "CoR",
        rel_err(stiff.cor, inc.cor),
        1e-9,
    );

    // every term split into two equal halves
    let halves: Vec<(f64, f64)> = terms
        .iter()
        .flat_map(|&(g, t)| [(0.5 * g, t), (0.5 * g, t)])
        .collect();
    let whole = fast(&general(&terms, bulk.clone()));
    let split = fast(&general(&halves, bulk));
    line("split halves", "CoR", rel_err(split.cor, whole.cor), 1e-12);

    insta::with_settings!({
        snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"),
        prepend_module_to_snapshot => false,
        omit_expression => true,
    }, {
        insta::assert_snapshot!("general_limits", out);
    });
}
