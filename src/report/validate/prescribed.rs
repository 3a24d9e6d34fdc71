//! Prescribed indentations: the displacement-driven MDR against the Lee–Radok/Ting force by
//! checked quadrature, and its refinement.

use crate::error::Result;
use crate::model::material::Prony;
use crate::report::catalogue::Case;
use crate::solvers::indentation::Prescribed;
use crate::solvers::mdr;
use crate::solvers::theory;

// the report's building blocks, re-exported where the validation tables have always been

/// One MDR-vs-theory comparison of a prescribed indentation.
#[derive(Debug, Clone, PartialEq)]
pub struct PrescribedComparison {
    /// Case id of the material.
    pub case: &'static str,
    /// History name.
    pub history: &'static str,
    /// Max |F_mdr - F_theory| / max F_theory over the samples.
    pub force_error: f64,
    /// Max |a_mdr - a_theory| / max a_theory.
    pub radius_error: f64,
    /// Separation time from theory (canonical units).
    pub separation_time: f64,
    /// Samples (t, F_theory, F_mdr) for plots.
    pub samples: Vec<(f64, f64, f64)>,
}

/// Canonical prescribed histories used for the force-for-force comparison: peak at `t = 1`,
/// peak depth 0.3 (R = 1).
pub fn prescribed_histories() -> Result<Vec<(&'static str, Prescribed)>> {
    Ok(vec![
        ("triangle", Prescribed::triangle(0.3, 1.0)?),
        ("half-sine", Prescribed::half_sine(0.3, 1.0)?),
    ])
}

/// MDR (displacement-driven, given resolution) against Lee–Radok/Ting on one material.
pub fn prescribed_comparison(
    case: &Case,
    history_name: &'static str,
    history: &Prescribed,
    res: mdr::indent::IndentResolution,
) -> Result<PrescribedComparison> {
    let prony = canonical_prony(case)?;
    let times: Vec<f64> = (0..=200)
        .map(|i| history.end_time() * i as f64 / 200.0)
        .collect();
    let th = theory::response(&prony, 1.0, history, &times)?;
    let md = mdr::indent::response(&prony, 1.0, history, &times, res)?;
    let f_peak = th.iter().map(|s| s.force).fold(0.0, f64::max);
    let a_peak = th.iter().map(|s| s.a).fold(0.0, f64::max);
    let mut fe: f64 = 0.0;
    let mut ae: f64 = 0.0;
    let mut samples = Vec::with_capacity(times.len());
    for (a, b) in th.iter().zip(&md) {
        fe = fe.max((a.force - b.force).abs() / f_peak);
        ae = ae.max((a.a - b.a).abs() / a_peak);
        samples.push((a.t, a.force, b.force));
    }
    Ok(PrescribedComparison {
        case: case.id,
        history: history_name,
        force_error: fe,
        radius_error: ae,
        separation_time: theory::separation_time(&prony, 1.0, history)?,
        samples,
    })
}

fn canonical_prony(case: &Case) -> Result<Prony> {
    Ok(case.impact()?.canonical_relaxation())
}

/// Observed orders from errors at successively doubled resolutions: `log2(e_i / e_{i+1})`.
pub fn observed_orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

/// Refinement study of the displacement-driven MDR against theory for one case: (elements,
/// steps, force error) with both doubled per level.
pub fn prescribed_refinement(
    case: &Case,
    history: &Prescribed,
    levels: usize,
) -> Result<Vec<(usize, usize, f64)>> {
    (0..levels)
        .map(|l| {
            let res = mdr::indent::IndentResolution {
                elements: 25 << l,
                steps: 50 << l,
            };
            let c = prescribed_comparison(case, "h", history, res)?;
            Ok((res.elements, res.steps, c.force_error))
        })
        .collect()
}
