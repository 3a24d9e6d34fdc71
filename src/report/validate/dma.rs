//! Section 1f of VALIDATION.md: the DMA round trip (docs/dma.md). Synthetic DMA data from a known
//! spectrum with a known WLF shift and multiplicative noise go through `prony` (shift factors,
//! shift law, Prony series); the recovered shifts and the CoR of the fitted material are
//! compared with the truth at several temperatures. `tests/dma.rs` asserts what the table shows.

use std::fmt::Write as _;

use rayon::prelude::*;

use crate::apps::dma::{self, data, prony_fit::PronySeries, shift::ShiftLaw};
use crate::error::Result;
use crate::model::material::{BulkInput, ShearProny};
use crate::report::markdown::{fmt_err, Table};
use crate::rng::SplitMix64;
use crate::{solve, Impact, Material, SolveOptions, Sphere};

/// The true material: `g_inf = 1 MPa` and 20 terms, `tau_i` log-spaced from 1e-6 s to 1e2 s,
/// `g_i = 2.0e7 Pa (tau_i / 1e-6 s)^(-0.4)` (a power-law transition; glassy ~0.16 GPa), at 20 °C.
pub fn truth() -> PronySeries {
    let terms = (0..20)
        .map(|k| {
            let tau = 1e-6 * 10f64.powf(8.0 * k as f64 / 19.0);
            (2.0e7 * (tau / 1e-6).powf(-0.4), tau)
        })
        .collect();
    PronySeries {
        g_inf: 1.0e6,
        terms,
    }
}

/// The true shift law: WLF, c1 = 8, c2 = 150 K at 20 °C.
pub fn true_law() -> Result<ShiftLaw> {
    ShiftLaw::wlf(8.0, 150.0, 20.0)
}

/// CSV text of synthetic DMA data of [`truth`] shifted by [`true_law`] ([`synthetic_of`]).
pub fn synthetic(temperatures: &[f64], per_decade: usize, noise: f64, seed: u64) -> Result<String> {
    synthetic_of(
        &truth(),
        &true_law()?,
        temperatures,
        per_decade,
        noise,
        seed,
    )
}

/// CSV text of synthetic DMA data: `temperatures` (°C), `per_decade` frequencies per decade
/// from 0.01 Hz to 100 Hz, `G'` and `G''` of `truth` at `omega a_T` (`a_T` of `law`), each
/// times `(1 + noise n)` with a standard normal `n` from `SplitMix64::new(seed)`.
pub fn synthetic_of(
    truth: &PronySeries,
    law: &ShiftLaw,
    temperatures: &[f64],
    per_decade: usize,
    noise: f64,
    seed: u64,
) -> Result<String> {
    let mut rng = SplitMix64::new(seed);
    let mut s = String::from("temperature,frequency,storage,loss\n");
    for &t in temperatures {
        let a = 10f64.powf(law.log10_a(t)?);
        let n = 4 * per_decade;
        for k in 0..=n {
            let f = 10f64.powf(-2.0 + 4.0 * k as f64 / n as f64);
            let w = std::f64::consts::TAU * f * a;
            let g1 = truth.storage(w) * (1.0 + noise * rng.normal());
            let g2 = truth.loss(w) * (1.0 + noise * rng.normal());
            let _ = writeln!(s, "{t},{f:.6e},{g1:.6e},{g2:.6e}");
        }
    }
    Ok(s)
}

/// The second truth, a real polymer's spectrum with a terminal zone: the 30 terms of
/// `scenes/polyisobutylene_prony.csv` (times 3.2e-12 s to 7.8e6 s) with `g_inf` = 1 kPa, as in
/// `scenes/polyisobutylene.toml`, its times taken at -20 °C.
pub fn polymer_truth() -> Result<PronySeries> {
    let terms = crate::io::prony_table::parse_prony_table(
        "scenes/polyisobutylene_prony.csv",
        include_bytes!("../../../scenes/polyisobutylene_prony.csv"),
    )?;
    let mut terms: Vec<(f64, f64)> = terms;
    terms.sort_by(|a, b| a.1.total_cmp(&b.1));
    Ok(PronySeries {
        g_inf: 1.0e3,
        terms,
    })
}

/// The second law: WLF with the "universal" constants c1 = 17.44, c2 = 51.6 K at -20 °C, a
/// steep shift (7.6 decades from -20 to 25 °C).
pub fn polymer_law() -> Result<ShiftLaw> {
    ShiftLaw::wlf(17.44, 51.6, -20.0)
}

/// The isotherms of the second round trip: -30 to 80 °C every 5 °C (23), as measured in a
/// typical temperature sweep.
pub fn polymer_grid() -> Vec<f64> {
    (0..23).map(|k| -30.0 + 5.0 * k as f64).collect()
}

/// Temperatures (°C) at which the second round trip compares the CoR.
pub const POLYMER_COR_TEMPERATURES: [f64; 5] = [-20.0, 0.0, 25.0, 50.0, 80.0];

/// The isotherms of the round trip: -30 to 80 °C every 10 °C.
pub fn grid() -> Vec<f64> {
    (0..12).map(|k| -30.0 + 10.0 * k as f64).collect()
}

/// Temperatures (°C) at which the round trip compares the CoR.
pub const COR_TEMPERATURES: [f64; 6] = [-20.0, 0.0, 20.0, 40.0, 60.0, 80.0];

/// CoR of a 10 mm steel ball (4.11 g) at 1 m/s on the incompressible `series`.
pub fn cor(series: &PronySeries) -> Result<f64> {
    let shear = ShearProny::new(series.g_inf, &series.terms)?;
    let m = Material::general(shear, BulkInput::Incompressible)?;
    let impact = Impact::new(Sphere::new(4.11e-3, 5.0e-3)?, 1.0, m)?;
    Ok(solve(&impact, &SolveOptions::default())?.cor)
}

/// `prony` on CSV `text` with the default options.
pub fn fit_text(text: &str, opts: &dma::PronyOptions) -> Result<dma::PronyReport> {
    let d = data::parse(text, "synthetic.csv", data::ModulusKind::Shear, 0.5)?;
    dma::fit(&d, opts)
}

/// One round trip: the largest error of the recovered `log10 a_T` over the isotherms
/// (decades), the fit's rms relative error, its number of terms, and the largest relative CoR
/// error (fitted material with the fitted law against the truth) over [`COR_TEMPERATURES`].
pub fn round_trip(noise: f64, seed: u64) -> Result<(f64, f64, usize, f64)> {
    round_trip_of(
        &truth(),
        &true_law()?,
        &grid(),
        None,
        &COR_TEMPERATURES,
        noise,
        seed,
    )
}

/// The round trip of the real polymer ([`polymer_truth`], [`polymer_law`], [`polymer_grid`],
/// `--t-ref -20`, CoR at [`POLYMER_COR_TEMPERATURES`]), as [`round_trip`].
pub fn polymer_round_trip(noise: f64, seed: u64) -> Result<(f64, f64, usize, f64)> {
    round_trip_of(
        &polymer_truth()?,
        &polymer_law()?,
        &polymer_grid(),
        Some(-20.0),
        &POLYMER_COR_TEMPERATURES,
        noise,
        seed,
    )
}

/// A round trip of `truth` shifted by `law` over `isotherms` (5 frequencies per decade),
/// fitted with `--t-ref t_ref` (the default when `None`), CoRs compared at `cor_temperatures`.
fn round_trip_of(
    truth: &PronySeries,
    law: &ShiftLaw,
    isotherms: &[f64],
    t_ref: Option<f64>,
    cor_temperatures: &[f64],
    noise: f64,
    seed: u64,
) -> Result<(f64, f64, usize, f64)> {
    let mut opts = dma::PronyOptions::new("synthetic.csv");
    opts.t_ref = t_ref;
    let r = fit_text(&synthetic_of(truth, law, isotherms, 5, noise, seed)?, &opts)?;
    let mut worst_shift: f64 = 0.0;
    for (k, iso) in r.isotherms.iter().enumerate() {
        if let Some(t) = iso.temperature {
            worst_shift = worst_shift.max((r.log10_shift[k] - law.log10_a(t)?).abs());
        }
    }
    let fitted = r
        .law
        .as_ref()
        .ok_or(crate::Error::Internal("the round trip fits a shift law"))?
        .law;
    let mut worst_cor: f64 = 0.0;
    for &t in cor_temperatures {
        let true_cor = cor(&truth.shifted(10f64.powf(law.log10_a(t)?)))?;
        let fit_cor = cor(&r.series.shifted(10f64.powf(fitted.log10_a(t)?)))?;
        worst_cor = worst_cor.max(((fit_cor - true_cor) / true_cor).abs());
    }
    Ok((
        worst_shift,
        r.rms_rel_error,
        r.series.terms.len(),
        worst_cor,
    ))
}

/// The section's table: each truth without noise and at 1 % noise (five seeds for the smooth
/// spectrum, three for the polymer).
pub fn round_trip_table() -> Result<Table> {
    let mut t = Table::new(&[
        "spectrum",
        "noise",
        "seed",
        "max error of log10 a_T (decades)",
        "rms rel. error of the fit",
        "terms",
        "max rel. CoR error",
    ]);
    let runs: Vec<(bool, f64, u64)> = std::iter::once((false, 0.0, 1))
        .chain((1..=5).map(|s| (false, 0.01, s)))
        .chain(std::iter::once((true, 0.0, 1)))
        .chain((1..=3).map(|s| (true, 0.01, s)))
        .collect();
    let rows: Vec<Result<Vec<String>>> = runs
        .par_iter()
        .map(|&(polymer, noise, seed)| {
            let (shift, rms, terms, cor) = match polymer {
                false => round_trip(noise, seed)?,
                true => polymer_round_trip(noise, seed)?,
            };
            Ok(vec![
                match polymer {
                    false => "smooth, 20 terms (-20 to 80 °C)".to_string(),
                    true => "polyisobutylene, 30 terms (-20 to 80 °C)".to_string(),
                },
                format!("{:.0} %", 100.0 * noise),
                seed.to_string(),
                fmt_err(shift),
                fmt_err(rms),
                terms.to_string(),
                fmt_err(cor),
            ])
        })
        .collect();
    for r in rows {
        t.rows.push(r?);
    }
    Ok(t)
}
