//! Fits of the damping laws to our `e(v0)`, and their errors in CoR and contact time.

use super::*;

/// Errors of a law's `e(v0)` against ours, relative to ours.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The law's CoR at each velocity of the curve (our integration of its force law).
    pub cor: Vec<f64>,
    /// Largest `|e_law - e| / e` over the range.
    pub worst_rel_error: f64,
    /// Root mean square of `(e_law - e) / e` over the range.
    pub rms_rel_error: f64,
}

impl Fit {
    pub(super) fn new(cor: Vec<f64>, target: &[f64]) -> Self {
        let rel: Vec<f64> = cor
            .iter()
            .zip(target)
            .map(|(a, b)| ((a - b) / b).abs())
            .collect();
        let worst_rel_error = rel.iter().copied().fold(0.0, f64::max);
        let rms_rel_error = (rel.iter().map(|r| r * r).sum::<f64>() / rel.len() as f64).sqrt();
        Self {
            cor,
            worst_rel_error,
            rms_rel_error,
        }
    }
}

/// Contact times of a law against ours (the time until the contact force vanishes).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactTimes {
    /// The law's contact time (s) at each velocity of the curve, with the Hertz stiffness of
    /// the report.
    pub law: Vec<f64>,
    /// Largest `|t_law - t| / t` over the range.
    pub worst_rel_error: f64,
}

/// The fitted constant-CoR law.
#[derive(Debug, Clone, PartialEq)]
pub struct ConstantLaw {
    /// The CoR to write into the DEM input (`coeff_restitution`, `coefficientRestitution`).
    pub cor_input: f64,
    /// The CoR that input produces (our integration, the same at every velocity).
    pub cor: f64,
    /// True when the least-squares constant lies below what the law can produce: the input is
    /// then [`MIN_COR_INPUT`].
    pub at_floor: bool,
    /// Errors against our curve.
    pub fit: Fit,
}

/// The fitted viscoelastic (Brilliantov) law.
#[derive(Debug, Clone, PartialEq)]
pub struct ViscoelasticLaw {
    /// Dissipative constant `A` (s).
    pub a: f64,
    /// LAMMPS `damping viscoelastic` prefactor `eta_n0 = 2 E* A / m` (1/(m s)).
    pub eta_n0: f64,
    /// Errors against our curve.
    pub fit: Fit,
}

/// The CoR of the constant-CoR law with input `e_in`.
fn constant_cor(cor_input: f64) -> Result<f64> {
    Ok(integrate(0.25, cor_gamma(cor_input)?)?.cor)
}

/// The constant-CoR law closest to `target` (least squares of the relative error: the constant
/// `sum(1/e) / sum(1/e^2)`), its input CoR found by bisection so that the law produces it.
pub fn fit_constant(target: &[f64]) -> Result<ConstantLaw> {
    let want = target.iter().map(|e| 1.0 / e).sum::<f64>()
        / target.iter().map(|e| 1.0 / (e * e)).sum::<f64>();
    // e(e_in) rises from its floor at e_in -> 0 (gamma -> sqrt 5) to 1 at e_in = 1
    let (mut lo, mut hi) = (MIN_COR_INPUT, 1.0);
    let at_floor = want < 1.0 && constant_cor(lo)? >= want;
    let cor_input = if want >= 1.0 {
        1.0
    } else if at_floor {
        lo
    } else {
        for _ in 0..crate::model::tolerances::ROOT_MAX_ITER {
            let mid = if hi / lo > 4.0 {
                (lo * hi).sqrt()
            } else {
                0.5 * (lo + hi)
            };
            if mid <= lo || mid >= hi || (hi - lo) < 1e-14 * hi {
                break;
            }
            if constant_cor(mid)? < want {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let cor = constant_cor(cor_input)?;
    Ok(ConstantLaw {
        cor_input,
        cor,
        at_floor,
        fit: Fit::new(vec![cor; target.len()], target),
    })
}

/// The viscoelastic law's CoR at the velocities `v0` (m/s) for the coefficient scale `s`
/// (`c = s v0^(1/5)`); in parallel, results in velocity order.
pub(super) fn visco_cors(s: f64, v0: &[f64]) -> Result<Vec<f64>> {
    v0.par_iter()
        .map(|v| integrate(0.5, s * v.powf(0.2)).map(|d| d.cor))
        .collect()
}

fn rel_sq(cor: &[f64], target: &[f64]) -> f64 {
    cor.iter()
        .zip(target)
        .map(|(a, b)| ((a - b) / b).powi(2))
        .sum()
}

/// The viscoelastic law closest to `target` at `v0` (m/s) in least squares of the relative
/// error: a scan of the dissipative constant over seven decades, then a golden-section search
/// around the best scan point.
pub fn fit_viscoelastic(
    contact: &HertzContact,
    v0: &[f64],
    target: &[f64],
) -> Result<ViscoelasticLaw> {
    // s = (3/2) A (k/m)^(2/5): c = s v0^(1/5); scan c at the largest velocity up to MAX_VISCO_C
    let vmax = v0.iter().copied().fold(0.0, f64::max);
    let top = MAX_VISCO_C / vmax.powf(0.2);
    const SCAN: usize = 57;
    let scan: Vec<f64> = (0..SCAN)
        .map(|i| top * 10f64.powf(-7.0 * (SCAN - 1 - i) as f64 / (SCAN - 1) as f64))
        .collect();
    let obj = |s: f64| -> Result<f64> { Ok(rel_sq(&visco_cors(s, v0)?, target)) };
    let mut best = (0.0, rel_sq(&vec![1.0; target.len()], target), usize::MAX);
    for (i, &s) in scan.iter().enumerate() {
        let f = obj(s)?;
        if f < best.1 {
            best = (s, f, i);
        }
    }
    let mut s_best = best.0;
    if best.2 != usize::MAX {
        // golden section in ln s between the scan neighbours
        let i = best.2;
        let mut a = if i == 0 {
            scan[0].ln() - 7.0 / (SCAN - 1) as f64 * std::f64::consts::LN_10
        } else {
            scan[i - 1].ln()
        };
        let mut b = if i + 1 == SCAN {
            scan[i].ln()
        } else {
            scan[i + 1].ln()
        };
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let mut x1 = b - g * (b - a);
        let mut x2 = a + g * (b - a);
        let (mut f1, mut f2) = (obj(x1.exp())?, obj(x2.exp())?);
        for _ in 0..crate::model::tolerances::ROOT_MAX_ITER {
            if b - a < 1e-10 {
                break;
            }
            if f1 < f2 {
                b = x2;
                x2 = x1;
                f2 = f1;
                x1 = b - g * (b - a);
                f1 = obj(x1.exp())?;
            } else {
                a = x1;
                x1 = x2;
                f1 = f2;
                x2 = a + g * (b - a);
                f2 = obj(x2.exp())?;
            }
        }
        let (s_mid, f_mid) = if f1 < f2 {
            (x1.exp(), f1)
        } else {
            (x2.exp(), f2)
        };
        if f_mid < best.1 {
            s_best = s_mid;
        }
    }
    let cor = visco_cors(s_best, v0)?;
    // s = (3/2) A (k/m)^(2/5), i.e. A = c(v0 = 1 m/s) / ((3/2) (k/m)^(2/5))
    let a = contact.viscoelastic_a(s_best, 1.0);
    Ok(ViscoelasticLaw {
        a,
        eta_n0: contact.lammps_eta_n0(a),
        fit: Fit::new(cor, target),
    })
}
