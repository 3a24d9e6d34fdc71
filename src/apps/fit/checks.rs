//! What a fit's numbers mean beyond their intervals: moduli that hold only for a `nu` the data
//! do not determine, the goodness of fit, and data that no viscoelastic solid explains.

use super::{Data, FitResult, ParamKind};

/// p-value below which the model is said not to fit the data (with standard deviations
/// given).
pub const GOODNESS_P_MIN: f64 = 0.01;

/// Chi-square goodness of fit, with standard deviations given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Goodness {
    /// `chi^2`, the weighted sum of squared residuals.
    pub chi2: f64,
    /// Degrees of freedom `n - rank`.
    pub dof: usize,
    /// `P(X >= chi^2)` for `X ~ chi^2(dof)`.
    pub p_value: f64,
}

/// The goodness of fit of `r` when every standard deviation was given (the residuals are then
/// standard normal at the truth); `None` otherwise or without degrees of freedom.
pub fn goodness(r: &FitResult) -> Option<Goodness> {
    use statrs::distribution::{ChiSquared, ContinuousCDF};
    if r.noise_scale != Some(1.0) || r.dof == 0 {
        return None;
    }
    let chi2: f64 = r.residuals.iter().map(|x| x.weighted * x.weighted).sum();
    let p_value = ChiSquared::new(r.dof as f64).ok()?.sf(chi2);
    Some(Goodness {
        chi2,
        dof: r.dof,
        p_value,
    })
}

/// Drops where the CoR rises with velocity by more than its noise: a linear viscoelastic solid
/// hit harder dissipates a larger share (its CoR falls with `v0` from the relaxed limit to its
/// minimum near `p3 = 1`, and rises again only far beyond it, towards the glassy limit), so a
/// CoR that rises over the measured range points to another material (a hydrogel, a foam, an
/// adhesive surface) or to the glassy side of the minimum.
pub fn rising_cor(data: &Data) -> Option<String> {
    let mut obs: Vec<_> = data.observations.iter().collect();
    if obs.len() < 3 {
        return None;
    }
    obs.sort_by(|a, b| a.v0.total_cmp(&b.v0));
    // slope of the least-squares line of e against ln v0, against its standard error
    let n = obs.len() as f64;
    let x: Vec<f64> = obs.iter().map(|o| o.v0.ln()).collect();
    let y: Vec<f64> = obs.iter().map(|o| o.cor).collect();
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    if !(sxx > 0.0) {
        return None;
    }
    let slope = x
        .iter()
        .zip(&y)
        .map(|(a, b)| (a - mx) * (b - my))
        .sum::<f64>()
        / sxx;
    let rss: f64 = x
        .iter()
        .zip(&y)
        .map(|(a, b)| (b - my - slope * (a - mx)).powi(2))
        .sum();
    let se = (rss / (n - 2.0) / sxx).sqrt();
    (slope > 0.0 && slope > 3.0 * se).then(|| {
        format!(
            "the CoR rises with impact velocity over the data (slope {slope:.3} per e-fold of v0, \
             {:.1} standard errors): a linear viscoelastic solid's CoR falls with v0 up to its \
             minimum, so these data come from another material (a hydrogel, a foam, an adhesive \
             contact) or from far beyond the minimum",
            slope / se
        )
    })
}

/// When `nu` was fitted but the data do not determine it, every fitted modulus and viscosity
/// holds only for the `nu` of the estimate: mark them not identifiable, conditional on it.
pub fn condition_on_nu(r: &mut FitResult) {
    let Some(inu) = r.model.slot(super::model::Parameter::Nu) else {
        return;
    };
    let nu = &r.parameters[inu];
    if nu.fixed || nu.identifiable {
        return;
    }
    let value = r.values[inu];
    r.conditional_on_nu = Some(value);
    for (e, p) in r.parameters.iter_mut().zip(&r.model.params) {
        if e.fixed || p.kind == ParamKind::Poisson || e.value.is_none() {
            continue;
        }
        e.identifiable = false;
        let why = format!(
            "conditional on nu = {value:.4}, which the data do not determine: with another nu \
             the moduli that fit these data differ"
        );
        e.note = if e.note.is_empty() {
            why
        } else {
            format!("{why}; {}", e.note)
        };
    }
}

/// Drops where the fitted material puts the model outside its validity
/// ([`crate::model::validity`]): how many, and the largest `a_max / R`.
pub fn validity(r: &FitResult) -> Option<String> {
    use crate::model::validity::Validity;
    use crate::solvers::{solve, SolveOptions, SolverKind};
    let opts = SolveOptions::with(SolverKind::Auto, 1e-6);
    let mut outside = 0usize;
    let mut worst: f64 = 0.0;
    for o in &r.data.observations {
        let sphere = r.data.setups[o.setup].sphere;
        let Ok(imp) = r.model.impact(sphere, o.v0, &r.values) else {
            continue;
        };
        let Ok(out) = solve(&imp, &opts) else {
            continue;
        };
        let v = Validity::of(&imp, &out);
        if !v.warnings.is_empty() {
            outside += 1;
            worst = worst.max(v.contact_radius_ratio);
        }
    }
    (outside > 0).then(|| {
        format!(
            "{outside} of {} drops lie outside the model's validity with the fitted material \
             (a_max/R up to {worst:.3}; `run --json` on such a drop says why): the fit treats \
             them as if it applied",
            r.data.observations.len()
        )
    })
}

/// A fitted contact time off its measurement by more than this factor either way is a gross
/// miss ([`gross_misses`]).
pub const GROSS_CONTACT_TIME_FACTOR: f64 = 2.0;

/// A fitted CoR off its measurement by more than this (absolute) is a gross miss.
pub const GROSS_COR_MISS: f64 = 0.2;

/// Drops the fitted model misses grossly, whatever the noise (a contact time off by more than
/// [`GROSS_CONTACT_TIME_FACTOR`], a CoR by more than [`GROSS_COR_MISS`]): data no viscoelastic
/// solid of the model explains, or a unit slip in a column. Without standard deviations no
/// chi-square test can say so, and the estimated noise scale absorbs any misfit.
pub fn gross_misses(r: &FitResult) -> Option<String> {
    let mut worst: Option<(f64, String)> = None;
    let mut count = 0usize;
    for x in &r.residuals {
        let (miss, text) = match x.quantity {
            "contact_time" => (
                (x.model / x.measured).ln().abs() / GROSS_CONTACT_TIME_FACTOR.ln(),
                format!(
                    "contact time {:.3e} s against {:.3e} s measured",
                    x.model, x.measured
                ),
            ),
            _ => (
                (x.model - x.measured).abs() / GROSS_COR_MISS,
                format!("CoR {:.4} against {:.4} measured", x.model, x.measured),
            ),
        };
        if miss > 1.0 {
            count += 1;
            let v0 = r.data.observations[x.observation].v0;
            if worst.as_ref().is_none_or(|w| miss > w.0) {
                worst = Some((miss, format!("{text} at v0 = {v0} m/s")));
            }
        }
    }
    worst.map(|(_, text)| {
        format!(
            "the fitted model misses {count} measured values grossly (a contact time by more than \
             a factor {GROSS_CONTACT_TIME_FACTOR}, a CoR by more than {GROSS_COR_MISS}; worst: \
             {text}): no material of this model explains the data; check the units of the \
             columns (s, m/s)"
        )
    })
}

/// Apply the checks to `r`: conditional moduli, goodness of fit and its warning, gross misses,
/// rising CoRs, drops outside the model's validity.
pub fn apply(r: &mut FitResult) {
    condition_on_nu(r);
    r.goodness = goodness(r);
    if let Some(g) = r.goodness.filter(|g| g.p_value < GOODNESS_P_MIN) {
        r.warnings.push(format!(
            "the model does not fit the data: chi^2 = {:.3} on {} degrees of freedom, p = {:.2e} \
             (below {GOODNESS_P_MIN}); the intervals assume it does",
            g.chi2, g.dof, g.p_value
        ));
    }
    r.warnings.extend(gross_misses(r));
    r.warnings.extend(rising_cor(&r.data));
    r.warnings.extend(validity(r));
    if let Some(nu) = r.conditional_on_nu {
        r.verdict = format!(
            "{}; the moduli hold only for nu = {nu:.4}",
            super::analysis::verdict(&r.parameters, &r.groups)
        );
    }
}
