//! Regression snapshots (insta, in the top-level `snapshots/` folder): agreement of every solver
//! with the theory on the catalogue, the solvers' work counters, and the Hertz and incompressible
//! limits. Numbers are formatted to two significant digits (errors) or ten (values), never raw
//! f64, so the snapshots are stable; a change in a physical constant or in the work a solver
//! does shows up as a diff.

use mdr_impact::report::catalogue::IMPACTS;
use mdr_impact::report::validate::*;
use mdr_impact::solvers::mdr::indent::IndentResolution;
use mdr_impact::{solve, SolveOptions, SolverKind};

macro_rules! snap {
    ($name:expr, $value:expr) => {
        insta::with_settings!({
            snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"),
            prepend_module_to_snapshot => false,
            omit_expression => true,
        }, {
            insta::assert_snapshot!($name, $value);
        })
    };
}

/// MDR (rtol 1e-4) and the reference against the reference at 1e-11 on every catalogue case,
/// with the work counters of both.
#[test]
fn impact_agreement() {
    let mut out = String::from("case | e_ref | mdr: dE dT dF | mdr work: levels steps elements updates | reference work: steps evaluations\n");
    for case in IMPACTS {
        let reference = reference_outcome(case).unwrap();
        let imp = case.impact().unwrap();
        let m = solve(&imp, &SolveOptions::with(SolverKind::Mdr, 1e-4)).unwrap();
        let r8 = solve(&imp, &SolveOptions::with(SolverKind::Reference, 1e-8)).unwrap();
        let rel = |a: f64, b: f64| fmt_err((a - b) / b);
        out.push_str(&format!(
            "{} | {} | {} {} {} | {} {} {} {} | {} {}\n",
            case.id,
            fmt_val(reference.cor),
            rel(m.cor, reference.cor),
            rel(m.contact_time, reference.contact_time),
            rel(m.max_force, reference.max_force),
            m.work.levels,
            m.work.steps,
            m.work.elements,
            m.work.element_updates,
            r8.work.steps,
            r8.work.evaluations,
        ));
    }
    snap!("impact_agreement", out);
}

/// Displacement-driven MDR (200 elements, 400 steps) against Lee–Radok/Ting, force for force.
#[test]
fn prescribed_agreement() {
    let mut out = String::from("case | history | max force error / F_peak | separation time\n");
    let res = IndentResolution {
        elements: 200,
        steps: 400,
    };
    for case in IMPACTS {
        for (name, h) in prescribed_histories().unwrap() {
            let c = prescribed_comparison(case, name, &h, res).unwrap();
            out.push_str(&format!(
                "{} | {name} | {} | {}\n",
                case.id,
                fmt_err(c.force_error),
                fmt_val(c.separation_time)
            ));
        }
    }
    snap!("prescribed_agreement", out);
}

#[test]
fn hertz_limit() {
    snap!("hertz_limit", hertz_limit_table().unwrap().markdown());
}

#[test]
fn incompressible_limit() {
    snap!(
        "incompressible_limit",
        incompressible_limit_table(0.01, 1.0).unwrap().0.markdown()
    );
}

#[test]
fn asymptotes() {
    snap!("asymptotes", asymptote_table().unwrap().0.markdown());
}
