//! Section 1i of VALIDATION.md: `dem --modulus fit` on the rubber-like polyisobutylene spectrum
//! over 0.1–10 m/s. For each Hertz stiffness (`relaxed`, `glassy`, `fit`) the table gives each
//! DEM law's worst CoR and contact-time errors against our `e(v0)` and contact times, as
//! `dem --format json` reports them (`laws.*.worst_rel_error`,
//! `laws.*.worst_contact_time_rel_error`).

use crate::apps::curve::VelocityRange;
use crate::apps::dem::{self, DemReport, ModulusChoice};
use crate::error::Result;
use crate::report::markdown::Table;
use crate::{Impact, SolveOptions, SolverKind, Sphere};

/// The velocity range of the example (`--v0 0.1:10 --log`, 50 velocities).
pub const DEM_RANGE: &str = "0.1:10";

/// The three reports of `dem scenes/polyisobutylene.toml --v0 0.1:10 --log --modulus M`.
pub fn reports() -> Result<Vec<DemReport>> {
    let pib = crate::report::catalogue::general_entries()?
        .into_iter()
        .find(|e| e.id == "polyisobutylene")
        .ok_or(crate::Error::Internal("catalogue: no polyisobutylene"))?
        .material;
    // the scene's sphere and solver settings
    let impact = Impact::new(Sphere::new(4.11e-3, 5.0e-3)?, 0.99, pib)?;
    let opts = SolveOptions::with(SolverKind::Auto, 1e-6);
    let range = VelocityRange::parse(DEM_RANGE, true)?;
    [
        ModulusChoice::Relaxed,
        ModulusChoice::Glassy,
        ModulusChoice::Fit,
    ]
    .into_iter()
    .map(|m| dem::run(&impact, &opts, &range, m, &|| {}))
    .collect()
}

/// Mean of `ln(t_law / t)` over both laws and every velocity: zero at the `fit` stiffness
/// (its least-squares condition), which the table checks independently of how it was found.
pub fn mean_log_time_ratio(r: &DemReport) -> f64 {
    let mut s = 0.0;
    let mut n = 0usize;
    for law in [&r.constant_times.law, &r.viscoelastic_times.law] {
        for (t, row) in law.iter().zip(&r.rows) {
            s += (t / row.contact_time).ln();
            n += 1;
        }
    }
    s / n.max(1) as f64
}

/// The section's table.
pub fn table(reports: &[DemReport]) -> Table {
    let mut t = Table::new(&[
        "`--modulus`",
        "`E*` (Pa)",
        "constant CoR: worst CoR error",
        "constant CoR: worst contact-time error",
        "viscoelastic: worst CoR error",
        "viscoelastic: worst contact-time error",
        "mean ln(t_law / t)",
    ]);
    for r in reports {
        let pct = |x: f64| format!("{:.1} %", 100.0 * x);
        t.rows.push(vec![
            format!("`{}`", r.modulus.name()),
            format!("{:.3e}", r.contact.effective_modulus),
            pct(r.constant.fit.worst_rel_error),
            pct(r.constant_times.worst_rel_error),
            pct(r.viscoelastic.fit.worst_rel_error),
            pct(r.viscoelastic_times.worst_rel_error),
            format!("{:+.3}", mean_log_time_ratio(r)),
        ]);
    }
    t
}

/// The section's text (before the table).
pub const DEM_TEXT: &str = "`mdr-impact dem scenes/polyisobutylene.toml --v0 0.1:10 --log \
--modulus M --format json` for the three Hertz stiffnesses (docs/dem.md): the 30-term \
polyisobutylene hit by the default scene's steel ball at 50 log-spaced velocities from 0.1 to \
10 m/s, our `e(v0)` and contact times from `auto` at rtol 1e-6. Each DEM law (constant CoR; \
viscoelastic) is fitted to our `e(v0)` with the stiffness `E*` of the row, and its contact \
times come from integrating the law itself at that stiffness (Hertz spring and damping, \
Dormand–Prince 5(4) in `src/apps/dem/laws.rs`, sharing no code with our solvers). The columns are the JSON's \
`laws.*.worst_rel_error` and `laws.*.worst_contact_time_rel_error`. A law's CoR does not depend \
on `E*`, so the CoR columns agree between rows; `fit` chooses `E*` by least squares of \
`ln(t_law / t)`, so its last column is zero (up to rounding), while the limit moduli miss the \
contact times of this rubber by far: neither `G_eq(inf)` nor `G_eq(0)` is the right spring when \
the contact lasts longer than the fastest relaxation and shorter than the slowest. `dem` warns \
when a law's contact time misses ours by more than 10 % or its CoR by more than 5 %. Asserted \
in `tests/dem.rs`. Re-run: `mdr-impact validate`.\n\n";
