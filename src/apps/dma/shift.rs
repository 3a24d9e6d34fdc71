//! Time–temperature superposition: the shift laws of a thermorheologically simple material
//! ([`ShiftLaw`], the scene table `[material.shift]`), the shift factors of measured isotherms
//! found from the data ([`pairwise_shift`], [`global_shifts`]) and the least-squares fit of a
//! law to them ([`fit_law`]) (docs/theory.md §11 of the shared notes; docs/dma.md).
//!
//! Sign convention: at temperature `T` every relaxation time is `tau_i(T) = a_T tau_i(T_ref)`,
//! so an isotherm measured at angular frequency `omega` sits at the reduced frequency
//! `omega a_T` on the master curve at `T_ref`; `log10 a_T > 0` below `T_ref` (slower, stiffer).

use crate::error::{Error, Result};

pub use crate::model::material::shift::{ShiftLaw, GAS_CONSTANT, ZERO_CELSIUS_K};

/// Which law to fit to the shift factors (`--shift`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LawKind {
    /// Williams–Landel–Ferry.
    Wlf,
    /// Arrhenius.
    Arrhenius,
    /// No law: only the per-isotherm factors.
    None,
}

impl std::str::FromStr for LawKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "wlf" => Ok(LawKind::Wlf),
            "arrhenius" => Ok(LawKind::Arrhenius),
            "none" => Ok(LawKind::None),
            _ => Err(Error::Parse {
                what: "--shift",
                input: crate::error::escape_text(s),
                expected: "wlf, arrhenius or none".into(),
            }),
        }
    }
}

/// One isotherm in log–log form, sorted by frequency: `x = log10 omega` (rad/s) strictly
/// increasing, `y1 = log10 G'`, `y2 = log10 G''` (Pa).
#[derive(Debug, Clone, PartialEq)]
pub struct LogIsotherm {
    /// `log10 omega`, strictly increasing.
    pub x: Vec<f64>,
    /// `log10 G'`.
    pub y1: Vec<f64>,
    /// `log10 G''`.
    pub y2: Vec<f64>,
}

/// Piecewise-linear interpolation of `(xs, ys)` at `x` inside `[xs[0], xs[n-1]]`.
fn interp(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let k = xs.partition_point(|&v| v <= x).clamp(1, xs.len() - 1);
    let (x0, x1) = (xs[k - 1], xs[k]);
    let w = (x - x0) / (x1 - x0);
    ys[k - 1] + w * (ys[k] - ys[k - 1])
}

/// Least points of each isotherm that must fall inside the other's (shifted) frequency range
/// for a relative shift to be measured.
pub const MIN_OVERLAP_POINTS: usize = 3;

/// The misfit of `b` shifted by `delta` decades against `a`: the mean square of the
/// differences of `log10 G'` and `log10 G''` between each point of either isotherm that falls
/// inside the other's range and the other's log–log interpolation there, with the numbers of
/// points of `a` and of `b` that overlap.
fn misfit(a: &LogIsotherm, b: &LogIsotherm, delta: f64) -> (f64, usize, usize) {
    let (mut sum, mut na, mut nb) = (0.0, 0, 0);
    let (a0, a1) = (a.x[0], a.x[a.x.len() - 1]);
    let (b0, b1) = (b.x[0] + delta, b.x[b.x.len() - 1] + delta);
    for k in 0..b.x.len() {
        let x = b.x[k] + delta;
        if x >= a0 && x <= a1 {
            sum += (interp(&a.x, &a.y1, x) - b.y1[k]).powi(2)
                + (interp(&a.x, &a.y2, x) - b.y2[k]).powi(2);
            nb += 1;
        }
    }
    for k in 0..a.x.len() {
        let x = a.x[k];
        if x >= b0 && x <= b1 {
            sum += (interp(&b.x, &b.y1, x - delta) - a.y1[k]).powi(2)
                + (interp(&b.x, &b.y2, x - delta) - a.y2[k]).powi(2);
            na += 1;
        }
    }
    let n = 2 * (na + nb);
    (if n > 0 { sum / n as f64 } else { f64::INFINITY }, na, nb)
}

/// A measured relative shift between two isotherms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairShift {
    /// `log10 a_b - log10 a_a`: the decades by which `b` moves onto `a` on the frequency axis.
    pub delta: f64,
    /// Root-mean-square misfit of `log10 G'` and `log10 G''` at the optimum (decades).
    pub rms: f64,
    /// Points that overlap (both isotherms together).
    pub overlap: usize,
}

/// The relative shift `delta = log10 a_b - log10 a_a` that minimises the misfit of `log10 G'`
/// and `log10 G''` of `b` shifted onto `a` (both interpolated linearly in log–log on their
/// overlap, both directions), searched on a grid of 0.005 decades over every shift where at
/// least [`MIN_OVERLAP_POINTS`] points of each overlap the other, then refined by golden
/// sections. `None` when no shift gives that overlap.
pub fn pairwise_shift(a: &LogIsotherm, b: &LogIsotherm) -> Option<PairShift> {
    if a.x.len() < 2 || b.x.len() < 2 {
        return None;
    }
    let lo = a.x[0] - b.x[b.x.len() - 1];
    let hi = a.x[a.x.len() - 1] - b.x[0];
    let valid = |d: f64| {
        let (m, na, nb) = misfit(a, b, d);
        (na >= MIN_OVERLAP_POINTS && nb >= MIN_OVERLAP_POINTS).then_some(m)
    };
    let step = 0.005;
    let n = ((hi - lo) / step).ceil() as usize;
    let mut best: Option<(f64, f64)> = None;
    for k in 0..=n {
        let d = lo + (hi - lo) * k as f64 / n.max(1) as f64;
        if let Some(m) = valid(d)
            && best.is_none_or(|(_, bm)| m < bm)
        {
            best = Some((d, m));
        }
    }
    let (d0, m0) = best?;
    let h = (hi - lo) / n.max(1) as f64;
    let f = |d: f64| valid(d).unwrap_or(f64::INFINITY);
    let (d, m) = golden(f, d0 - h, d0 + h, 1e-6);
    let (d, m) = if m <= m0 { (d, m) } else { (d0, m0) };
    let (_, na, nb) = misfit(a, b, d);
    Some(PairShift {
        delta: d,
        rms: m.sqrt(),
        overlap: na + nb,
    })
}

/// Golden-section search for a minimum of `f` on `[a, b]` to an interval of `tol`: the
/// minimiser and the value there.
pub(crate) fn golden(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, tol: f64) -> (f64, f64) {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    while (b - a).abs() > tol {
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    if fc <= fd {
        (c, fc)
    } else {
        (d, fd)
    }
}

/// The shift factor of every isotherm from measured pair shifts, by weighted least squares:
/// minimise `sum w_ij (s_j - s_i - delta_ij)^2` over the `s` with `s[reference] = 0`
/// (weights: the overlap counts). `pairs` are `(i, j, shift)`; every isotherm must be
/// connected to the reference through the pairs (the caller checks neighbours).
pub fn global_shifts(n: usize, reference: usize, pairs: &[(usize, usize, PairShift)]) -> Vec<f64> {
    use nalgebra::{DMatrix, DVector};
    if n <= 1 {
        return vec![0.0; n];
    }
    let col = |k: usize| if k < reference { k } else { k - 1 };
    let mut a = DMatrix::<f64>::zeros(pairs.len(), n - 1);
    let mut b = DVector::<f64>::zeros(pairs.len());
    for (r, &(i, j, p)) in pairs.iter().enumerate() {
        let w = (p.overlap as f64).sqrt();
        if j != reference {
            a[(r, col(j))] += w;
        }
        if i != reference {
            a[(r, col(i))] -= w;
        }
        b[r] = w * p.delta;
    }
    let s = a
        .svd(true, true)
        .solve(&b, 1e-12)
        .unwrap_or_else(|_| DVector::zeros(n - 1));
    (0..n)
        .map(|k| if k == reference { 0.0 } else { s[col(k)] })
        .collect()
}

/// A law fitted to shift factors.
#[derive(Debug, Clone, PartialEq)]
pub struct LawFit {
    /// The law, referred to `t_ref` (`log10 a_T(t_ref) = 0`).
    pub law: ShiftLaw,
    /// The decades to add to every measured `log10 a_T` so that it refers to `t_ref` (0 when
    /// `t_ref` is one of the isotherms, whose factor is 0 by construction).
    pub offset: f64,
    /// Root-mean-square residual of the measured factors about the law (decades).
    pub rms: f64,
    /// True when WLF's `c2` ran to the upper bound of the search (the factors are nearly
    /// linear in `T`: only `c1 / c2` is determined).
    pub c2_at_bound: bool,
}

/// Largest `c2` (K) the WLF fit considers.
pub const WLF_C2_MAX: f64 = 1.0e4;

/// Least-squares fit of `kind` (not `None`) to the factors `log_a` at temperatures `temps`
/// (°C), referred to `t_ref`. When `t_ref` is one of `temps` the factor there is 0 and the law
/// passes through it; otherwise a constant offset of the measured factors is fitted too.
/// WLF: `c1` (and the offset) linear for each `c2`, `c2` by golden sections on `log c2` between
/// just above `t_ref - min(temps)` and [`WLF_C2_MAX`]. Arrhenius: linear.
pub fn fit_law(kind: LawKind, temps: &[f64], log_a: &[f64], t_ref: f64) -> Result<LawFit> {
    let with_offset = !temps.iter().any(|&t| (t - t_ref).abs() < 1e-9);
    // linear least squares of y ~ c f + k (k only with_offset): (c, k, sum of squares)
    let linear = |f: &dyn Fn(f64) -> f64| -> (f64, f64, f64) {
        let n = temps.len() as f64;
        let (mut sf, mut sy, mut sff, mut sfy) = (0.0, 0.0, 0.0, 0.0);
        for (&t, &y) in temps.iter().zip(log_a) {
            let v = f(t);
            sf += v;
            sy += y;
            sff += v * v;
            sfy += v * y;
        }
        let (c, k) = if with_offset {
            let det = n * sff - sf * sf;
            if det.abs() < 1e-300 {
                (0.0, sy / n)
            } else {
                ((n * sfy - sf * sy) / det, (sff * sy - sf * sfy) / det)
            }
        } else if sff > 0.0 {
            (sfy / sff, 0.0)
        } else {
            (0.0, 0.0)
        };
        let ss = temps
            .iter()
            .zip(log_a)
            .map(|(&t, &y)| (y - c * f(t) - k).powi(2))
            .sum::<f64>();
        (c, k, ss)
    };
    let n = temps.len().max(1) as f64;
    match kind {
        LawKind::Wlf => {
            let t_min = temps.iter().copied().fold(f64::INFINITY, f64::min);
            let c2_lo = (t_ref - t_min).max(0.0) + 1e-3;
            if !(c2_lo < WLF_C2_MAX) {
                // the law diverges at t_ref - c2, which must lie below every isotherm
                return Err(Error::NotSupported {
                    solver: "prony --shift wlf",
                    what: format!(
                        "a WLF law referred to --t-ref {t_ref} °C needs c2 > {:.4e} K (its \
                         divergence t_ref - c2 below the coldest isotherm, {t_min} °C), beyond \
                         the c2 the fit considers (up to {WLF_C2_MAX:e} K): choose --t-ref \
                         nearer the measured temperatures or use --shift arrhenius",
                        t_ref - t_min
                    ),
                });
            }
            let at = |lc2: f64| {
                let c2 = lc2.exp();
                linear(&|t: f64| -(t - t_ref) / (c2 + t - t_ref))
            };
            // coarse scan then golden sections around the best point
            let (l0, l1) = (c2_lo.ln(), WLF_C2_MAX.ln());
            let m = 200;
            let mut best = (l0, f64::INFINITY);
            for k in 0..=m {
                let l = l0 + (l1 - l0) * k as f64 / m as f64;
                let ss = at(l).2;
                if ss < best.1 {
                    best = (l, ss);
                }
            }
            let h = (l1 - l0) / m as f64;
            let (l, _) = golden(
                |l| at(l.clamp(l0, l1)).2,
                (best.0 - h).max(l0),
                (best.0 + h).min(l1),
                1e-10,
            );
            let (c1, k, ss) = at(l);
            if !(c1 > 0.0) {
                return Err(Error::NotSupported {
                    solver: "prony --shift wlf",
                    what: format!(
                        "the shift factors do not decrease with temperature (best WLF c1 = \
                         {c1:.3e}); check the temperature column or use --shift none"
                    ),
                });
            }
            Ok(LawFit {
                law: ShiftLaw::wlf(c1, l.exp(), t_ref)?,
                offset: -k,
                rms: (ss / n).sqrt(),
                c2_at_bound: l > l1 - 2.0 * h,
            })
        }
        LawKind::Arrhenius => {
            let rk = t_ref + ZERO_CELSIUS_K;
            let scale = GAS_CONSTANT * std::f64::consts::LN_10;
            let (c, k, ss) = linear(&|t: f64| (1.0 / (t + ZERO_CELSIUS_K) - 1.0 / rk) / scale);
            if !(c > 0.0) {
                return Err(Error::NotSupported {
                    solver: "prony --shift arrhenius",
                    what: format!(
                        "the shift factors do not decrease with temperature (best activation \
                         energy {c:.3e} J/mol); check the temperature column or use --shift none"
                    ),
                });
            }
            Ok(LawFit {
                law: ShiftLaw::arrhenius(c, t_ref)?,
                offset: -k,
                rms: (ss / n).sqrt(),
                c2_at_bound: false,
            })
        }
        LawKind::None => Err(Error::Internal("fit_law called with LawKind::None")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toml_round_trip_in_the_scene_shape() {
        for law in [
            ShiftLaw::wlf(8.86, 101.6, 25.0).unwrap(),
            ShiftLaw::arrhenius(2.0e5, 25.0).unwrap(),
        ] {
            let back: ShiftLaw = toml::from_str(&law.toml_line()).unwrap();
            assert_eq!(back, law);
            let ser: ShiftLaw = toml::from_str(&toml::to_string(&law).unwrap()).unwrap();
            assert_eq!(ser, law);
        }
        assert!(toml::from_str::<ShiftLaw>("wlf = { c1 = 8.86, c2 = 101.6 }").is_err());
        assert!(toml::from_str::<ShiftLaw>(
            "wlf = { c1 = 8.86, c2 = 101.6, t_ref = 25.0, x = 1.0 }"
        )
        .is_err());
        assert!(
            toml::from_str::<ShiftLaw>("wlf = { c1 = -1.0, c2 = 101.6, t_ref = 25.0 }").is_err()
        );
    }

    #[test]
    fn arrhenius_spot_value() {
        // E_a = R ln10 * 1000 K: log10 a = 1000 (1/T - 1/T_ref)
        let law =
            ShiftLaw::arrhenius(GAS_CONSTANT * std::f64::consts::LN_10 * 1000.0, 25.0).unwrap();
        let want = 1000.0 * (1.0 / 273.15 - 1.0 / 298.15);
        assert!((law.log10_a(0.0).unwrap() - want).abs() < 1e-12);
        assert_eq!(law.log10_a(25.0).unwrap(), 0.0);
    }

    #[test]
    fn wlf_fit_recovers_exact_factors_with_and_without_offset() {
        let law = ShiftLaw::wlf(8.0, 150.0, 25.0).unwrap();
        let temps: Vec<f64> = (0..12).map(|k| -30.0 + 10.0 * k as f64).collect();
        let y: Vec<f64> = temps.iter().map(|&t| law.log10_a(t).unwrap()).collect();
        let f = fit_law(LawKind::Wlf, &temps, &y, 25.0).unwrap();
        let ShiftLaw::Wlf { c1, c2, .. } = f.law else {
            panic!()
        };
        assert!(
            (c1 - 8.0).abs() < 1e-5 && (c2 - 150.0).abs() < 1e-3,
            "{c1} {c2}"
        );
        // factors referred to 20 °C instead: the fit finds the offset
        let y20: Vec<f64> = y.iter().map(|v| v - law.log10_a(20.0).unwrap()).collect();
        let f = fit_law(LawKind::Wlf, &temps, &y20, 25.0).unwrap();
        assert!(
            (f.offset - law.log10_a(20.0).unwrap()).abs() < 1e-6,
            "{f:?}"
        );
    }

    #[test]
    fn pairwise_shift_of_a_power_law() {
        // G' = omega^0.5, G'' = omega^0.3 (log-log lines): b = a moved by 0.7 decades
        let a = LogIsotherm {
            x: (0..21).map(|k| -2.0 + 0.2 * k as f64).collect(),
            y1: (0..21).map(|k| 0.5 * (-2.0 + 0.2 * k as f64)).collect(),
            y2: (0..21).map(|k| 0.3 * (-2.0 + 0.2 * k as f64)).collect(),
        };
        let mut b = a.clone();
        for k in 0..b.x.len() {
            b.y1[k] = 0.5 * (b.x[k] + 0.7);
            b.y2[k] = 0.3 * (b.x[k] + 0.7);
        }
        let p = pairwise_shift(&a, &b).unwrap();
        assert!((p.delta - 0.7).abs() < 1e-5, "{p:?}");
    }
}
