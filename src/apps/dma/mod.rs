//! From DMA data to a Prony series and a shift law (`mdr-impact prony`; docs/dma.md).
//!
//! Storage and loss moduli measured over frequency, optionally at several temperatures, become
//! a master curve at a reference temperature (shift factors found from the data, a WLF or
//! Arrhenius law fitted to them: [`shift`]), and a Prony series fitted to the master curve by
//! non-negative least squares ([`prony_fit`]). [`report`] writes the scene fragment
//! `material.toml`, the tables and the chart.
//!
//! The steps of [`fit`]:
//! 1. neighbouring isotherms (and next neighbours) are shifted onto each other by minimising the
//!    misfit of `log G'` and `log G''`, interpolated in log–log on their overlap
//!    ([`shift::pairwise_shift`]); the factors follow from all measured pair shifts by weighted
//!    least squares with the reference isotherm fixed ([`shift::global_shifts`]);
//! 2. refinement: a Prony series is fitted to the master curve and every isotherm but the
//!    reference is shifted again onto it (each factor by a one-dimensional search), twice; the
//!    smooth model carries information across all isotherms at once, which pair shifts on
//!    noisy data do not;
//! 3. the law is fitted to the factors ([`shift::fit_law`]); the Prony series is fitted to the
//!    final master curve, with `--terms N` as a cap.

pub mod data;
pub mod prony_fit;
pub mod report;
pub mod shift;

use std::path::PathBuf;

use crate::error::{Error, Result};
use data::{DmaData, Isotherm, ModulusKind};
use prony_fit::PronySeries;
use shift::{LawFit, LawKind, LogIsotherm, PairShift};

/// Default reference temperature (°C): the isotherm nearest to it is the reference.
pub const DEFAULT_T_REF: f64 = 25.0;

/// Pair shifts whose rms misfit of `log10 G'` and `log10 G''` exceeds this (decades) are
/// reported: the isotherms do not superpose (not thermorheologically simple, or too noisy).
pub const POOR_OVERLAP_RMS: f64 = 0.05;

/// Half-width (decades) of the search of each shift factor in the refinement.
pub const REFINE_SPAN: f64 = 0.5;

/// Refinement passes (Prony fit, then every factor again).
pub const REFINE_PASSES: usize = 2;

/// Largest shift (decades of frequency) of an isotherm to the reference temperature: beyond
/// it the reduced frequencies leave the range of double precision.
pub const MAX_SHIFT_DECADES: f64 = 100.0;

/// A fit whose rms relative error of `G'` and `G''` exceeds this is reported: the series
/// misses the data.
pub const POOR_FIT_RMS: f64 = 0.1;

/// The inputs of `prony`.
#[derive(Debug, Clone, PartialEq)]
pub struct PronyOptions {
    /// The DMA file (CSV).
    pub data: PathBuf,
    /// `--terms N`: at most `N` Prony terms; `None`: automatic.
    pub max_terms: Option<usize>,
    /// Shear or tensile moduli.
    pub modulus: ModulusKind,
    /// `--nu`: Poisson ratio (conversion of tensile data; bulk of the written material).
    pub nu: Option<f64>,
    /// `--t-ref` (°C); default: the isotherm nearest [`DEFAULT_T_REF`].
    pub t_ref: Option<f64>,
    /// The shift law to fit.
    pub shift: LawKind,
}

impl PronyOptions {
    /// Options with the defaults of the command (`--terms auto --modulus shear --shift wlf`).
    pub fn new(data: impl Into<PathBuf>) -> Self {
        Self {
            data: data.into(),
            max_terms: None,
            modulus: ModulusKind::Shear,
            nu: None,
            t_ref: None,
            shift: LawKind::Wlf,
        }
    }
}

/// Parse `--terms`: `auto` or a count `N >= 1`.
pub fn parse_terms(s: &str) -> Result<Option<usize>> {
    match s {
        "auto" => Ok(None),
        _ => match s.parse::<usize>() {
            Ok(n) if n >= 1 => Ok(Some(n)),
            _ => Err(Error::Parse {
                what: "--terms",
                input: crate::error::escape_text(s),
                expected: "auto or a count N >= 1".into(),
            }),
        },
    }
}

/// The bulk written beside the fitted shear series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BulkChoice {
    /// `incompressible = true` (shear data without `--nu`, or `nu = 0.5`).
    Incompressible,
    /// `poisson = nu`: elastic bulk from the relaxed shear modulus (shear data with `--nu`).
    Poisson(f64),
    /// Tensile data converted with a constant `nu < 0.5` (or shear data with `--nu` and
    /// `g_inf = 0`): the bulk series proportional to the shear series,
    /// `K(t) = G(t) 2 (1 + nu) / (3 (1 - 2 nu))`.
    Proportional(f64),
}

/// Everything `prony` found.
#[derive(Debug, Clone, PartialEq)]
pub struct PronyReport {
    /// The data file as given.
    pub file: String,
    /// The isotherms in shear, by increasing temperature.
    pub isotherms: Vec<Isotherm>,
    /// `log10 a_T` of each isotherm, referred to `t_ref` (after refinement).
    pub log10_shift: Vec<f64>,
    /// `log10 a_T` of each isotherm from the pair shifts alone (before refinement).
    pub log10_shift_pairwise: Vec<f64>,
    /// The measured pair shifts `(i, j, shift)`.
    pub pairs: Vec<(usize, usize, PairShift)>,
    /// Reference temperature (°C) of the master curve; `None` without temperatures.
    pub t_ref: Option<f64>,
    /// The fitted law, if any.
    pub law: Option<LawFit>,
    /// The Prony series at `t_ref`.
    pub series: PronySeries,
    /// Root-mean-square relative error of `G'` and `G''` of the fit over all points.
    pub rms_rel_error: f64,
    /// The bulk of `material.toml`.
    pub bulk: BulkChoice,
    /// Problems that did not stop the fit.
    pub warnings: Vec<String>,
}

impl PronyReport {
    /// Every point on the master curve: `(isotherm index, reduced omega (rad/s), G', G'')`.
    pub fn master_points(&self) -> Vec<(usize, f64, f64, f64)> {
        let mut out = Vec::new();
        for (k, iso) in self.isotherms.iter().enumerate() {
            let a = 10f64.powf(self.log10_shift[k]);
            out.extend(iso.points.iter().map(|&(w, s, l)| (k, w * a, s, l)));
        }
        out
    }
}

/// Read the data file of `opts` and [`fit`] it.
pub fn run(opts: &PronyOptions) -> Result<PronyReport> {
    let nu = opts.nu.unwrap_or(0.5);
    let data = data::read(&opts.data, opts.modulus, nu)?;
    fit(&data, opts)
}

fn reduced(isotherms: &[Isotherm], log_a: &[f64]) -> Vec<(f64, f64, f64)> {
    isotherms
        .iter()
        .zip(log_a)
        .flat_map(|(iso, &s)| {
            let a = 10f64.powf(s);
            iso.points.iter().map(move |&(w, g1, g2)| (w * a, g1, g2))
        })
        .collect()
}

fn log_isotherm(iso: &Isotherm) -> LogIsotherm {
    LogIsotherm {
        x: iso.points.iter().map(|p| p.0.log10()).collect(),
        y1: iso.points.iter().map(|p| p.1.log10()).collect(),
        y2: iso.points.iter().map(|p| p.2.log10()).collect(),
    }
}

/// Misfit of one isotherm shifted by `s` decades against a series.
fn model_misfit(series: &PronySeries, iso: &Isotherm, s: f64) -> f64 {
    let a = 10f64.powf(s);
    iso.points
        .iter()
        .map(|&(w, g1, g2)| {
            (series.storage(w * a).log10() - g1.log10()).powi(2)
                + (series.loss(w * a).log10() - g2.log10()).powi(2)
        })
        .sum()
}

fn range(v: &[f64]) -> (f64, f64) {
    v.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        })
}

/// Shift, fit and report the validated `data` with the options `opts` (its `data` path is
/// only used as the file name in the report).
pub fn fit(data: &DmaData, opts: &PronyOptions) -> Result<PronyReport> {
    if let Some(t) = opts.t_ref {
        crate::error::check(
            "--t-ref",
            t,
            t > -shift::ZERO_CELSIUS_K,
            "-273.15 < --t-ref < inf (°C)",
        )?;
    }
    let isotherms = data.isotherms.clone();
    let mut warnings = data.warnings.clone();
    let n = isotherms.len();
    let temps: Vec<f64> = isotherms.iter().filter_map(|i| i.temperature).collect();
    let (mut t_ref, reference) = match (temps.len() == n && n > 0, opts.t_ref) {
        (true, want) => {
            let want = want.unwrap_or(DEFAULT_T_REF);
            let k = (0..n)
                .min_by(|&a, &b| (temps[a] - want).abs().total_cmp(&(temps[b] - want).abs()))
                .unwrap_or(0);
            (Some(opts.t_ref.unwrap_or(temps[k])), k)
        }
        (false, t) => (t, 0),
    };
    let mut pairs = Vec::new();
    let mut log_a = vec![0.0; n];
    if n > 1 {
        let logs: Vec<LogIsotherm> = isotherms.iter().map(log_isotherm).collect();
        for i in 0..n - 1 {
            let (a, b) = (&logs[i], &logs[i + 1]);
            let (ta, tb) = (temps[i], temps[i + 1]);
            let (s_a, s_b) = (range(&a.y1), range(&b.y1));
            let (l_a, l_b) = (range(&a.y2), range(&b.y2));
            let disjoint = |p: (f64, f64), q: (f64, f64)| p.1 < q.0 || q.1 < p.0;
            let none = || Error::NotSupported {
                solver: "prony",
                what: format!(
                    "the isotherms at {ta} °C and {tb} °C do not overlap (storage moduli \
                     {:.3e}..{:.3e} Pa and {:.3e}..{:.3e} Pa, loss moduli {:.3e}..{:.3e} Pa and \
                     {:.3e}..{:.3e} Pa): measure at temperatures closer together or over a \
                     wider frequency range",
                    10f64.powf(s_a.0),
                    10f64.powf(s_a.1),
                    10f64.powf(s_b.0),
                    10f64.powf(s_b.1),
                    10f64.powf(l_a.0),
                    10f64.powf(l_a.1),
                    10f64.powf(l_b.0),
                    10f64.powf(l_b.1),
                ),
            };
            if disjoint(s_a, s_b) && disjoint(l_a, l_b) {
                return Err(none());
            }
            let p = shift::pairwise_shift(a, b).ok_or_else(|| Error::NotSupported {
                solver: "prony",
                what: format!(
                    "the isotherms at {ta} °C and {tb} °C ({} and {} points) share fewer than \
                     {} points of each other's frequency range at every shift: measure more \
                     frequencies per isotherm or at temperatures closer together",
                    a.x.len(),
                    b.x.len(),
                    shift::MIN_OVERLAP_POINTS
                ),
            })?;
            if p.rms > POOR_OVERLAP_RMS {
                warnings.push(format!(
                    "the isotherms at {ta} °C and {tb} °C superpose poorly (rms misfit {:.3} \
                     decades of log G', log G''): the material may not be thermorheologically \
                     simple there",
                    p.rms
                ));
            }
            pairs.push((i, i + 1, p));
            if i + 2 < n
                && let Some(p2) = shift::pairwise_shift(a, &logs[i + 2])
                && p2.rms <= 2.0 * p.rms.max(POOR_OVERLAP_RMS)
            {
                pairs.push((i, i + 2, p2));
            }
        }
        log_a = shift::global_shifts(n, reference, &pairs);
    }
    let pairwise = log_a.clone();
    if n > 1 {
        for _ in 0..REFINE_PASSES {
            let series = prony_fit::fit_prony(&reduced(&isotherms, &log_a), None)?;
            for k in (0..n).filter(|&k| k != reference) {
                let s0 = log_a[k];
                let f = |s: f64| model_misfit(&series, &isotherms[k], s);
                // coarse scan, then golden sections around the best point
                let m = 40;
                let mut best = (s0, f(s0));
                for j in 0..=m {
                    let s = s0 - REFINE_SPAN + 2.0 * REFINE_SPAN * j as f64 / m as f64;
                    let v = f(s);
                    if v < best.1 {
                        best = (s, v);
                    }
                }
                let h = 2.0 * REFINE_SPAN / m as f64;
                log_a[k] = shift::golden(f, best.0 - h, best.0 + h, 1e-7).0;
            }
        }
    }
    let mut law = None;
    if n > 1 && opts.shift != LawKind::None {
        if opts.shift == LawKind::Wlf && n < 3 {
            return Err(Error::NotSupported {
                solver: "prony --shift wlf",
                what: format!(
                    "{n} isotherms determine one shift factor, not the two WLF constants: use \
                     --shift arrhenius or none, or measure more temperatures"
                ),
            });
        }
        let t = t_ref.unwrap_or(DEFAULT_T_REF);
        let f = shift::fit_law(opts.shift, &temps, &log_a, t)?;
        for s in log_a.iter_mut() {
            *s += f.offset;
        }
        // a reference far from the data shifts the reduced frequencies out of the range of
        // double precision (a WLF law diverges at t_ref - c2)
        let worst = log_a.iter().fold(0.0f64, |m, s| m.max(s.abs()));
        if !(worst <= MAX_SHIFT_DECADES) {
            let (t_lo, t_hi) = range(&temps);
            return Err(Error::NotSupported {
                solver: "prony --t-ref",
                what: format!(
                    "the {} law fitted to the isotherms ({t_lo} °C to {t_hi} °C) shifts them by \
                     {worst:.3e} decades to --t-ref {t} °C (at most {MAX_SHIFT_DECADES} \
                     allowed): choose a reference temperature nearer the measured ones",
                    f.law.kind()
                ),
            });
        }
        if f.rms > POOR_OVERLAP_RMS {
            warnings.push(format!(
                "the {} law fits the shift factors with an rms residual of {:.3} decades",
                f.law.kind(),
                f.rms
            ));
        }
        if f.c2_at_bound {
            warnings.push(format!(
                "WLF c2 ran to its bound {:e} K: the factors are nearly linear in T and only \
                 c1/c2 is determined; consider --shift arrhenius",
                shift::WLF_C2_MAX
            ));
        }
        law = Some(f);
    } else if n > 1 {
        if let Some(t) = opts.t_ref
            && (t - temps[reference]).abs() > 1e-9
        {
            warnings.push(format!(
                "--shift none: the master curve refers to the isotherm at {} °C, not to \
                     --t-ref {t} °C",
                temps[reference]
            ));
        }
        t_ref = Some(temps[reference]);
    } else if opts.shift != LawKind::None && !temps.is_empty() {
        warnings.push("one isotherm: no shift law fitted".into());
    }
    let pairwise: Vec<f64> = match &law {
        Some(f) => pairwise.iter().map(|s| s + f.offset).collect(),
        None => pairwise,
    };
    let points = reduced(&isotherms, &log_a);
    let series = prony_fit::fit_prony(&points, opts.max_terms)?;
    let rms_rel_error = series.rms_rel_error(&points);
    if !(rms_rel_error <= POOR_FIT_RMS) {
        warnings.push(format!(
            "the Prony series misses the data: rms relative error {rms_rel_error:.3} of G' and \
             G'' (master.csv has both side by side); check the data (a loss modulus far above \
             the storage modulus, or points that no sum of Maxwell terms can follow){}",
            match opts.max_terms {
                Some(n) => format!(", or allow more than --terms {n}"),
                None => String::new(),
            }
        ));
    }
    let liquid = series.g_inf == 0.0;
    if liquid {
        warnings.push(
            "g_inf = 0: the data show no relaxed plateau at low frequency, so the material is \
             written as a viscoelastic liquid (its relaxed limits do not apply)"
                .into(),
        );
    }
    let nu = opts.nu.unwrap_or(0.5);
    let bulk = match (opts.modulus, opts.nu) {
        (_, None) => BulkChoice::Incompressible,
        (_, Some(_)) if nu == 0.5 => BulkChoice::Incompressible,
        // a static Poisson ratio would give K_0 = 0 with g_inf = 0: keep nu constant in time
        (ModulusKind::Shear, Some(nu)) if liquid => {
            warnings.push(format!(
                "g_inf = 0: --nu {nu} written as a constant Poisson ratio (bulk series \
                 proportional to the shear series), since a static ratio would give K_0 = 0"
            ));
            BulkChoice::Proportional(nu)
        }
        (ModulusKind::Shear, Some(nu)) => BulkChoice::Poisson(nu),
        (ModulusKind::Tensile, Some(nu)) => BulkChoice::Proportional(nu),
    };
    Ok(PronyReport {
        file: opts.data.display().to_string(),
        isotherms,
        log10_shift: log_a,
        log10_shift_pairwise: pairwise,
        pairs,
        t_ref,
        law,
        series,
        rms_rel_error,
        bulk,
        warnings,
    })
}

pub use report::{json, summary, write_outputs};
