//! The DEM codes' tangential models against the MDR's partial slip (VALIDATION.md 1g, docs/dem.md).
//!
//! The real runs come from `validation/dem_clients/oblique.py`, which bounces the alumina sphere
//! of `scenes/oblique_alumina.toml` in LAMMPS 20220106 and LIGGGHTS 3.8.0 and writes
//! `validation/dem_clients/oblique.csv`; that file is committed and embedded here, so the report
//! needs neither code. Beside them: `mdr` on the same impacts, and the emulation of the Mindlin
//! models ([`crate::apps::dem::tangential`]), which must reproduce the real runs of the same
//! models within [`EMULATION_BOUND`] (asserted below and by the script in CI).

use rayon::prelude::*;

use crate::apps::dem::tangential::{dem_tangential_cor, DemTangential};
use crate::error::{Error, Result};
use crate::report::markdown::Table;
use crate::report::validate::oblique::{case_impact, inputs, solve_with, CASES, MDR_RTOL};
use crate::solvers::SolverKind;

/// Incidence angles (degrees) of the DEM comparison.
pub const DEM_ANGLES: [f64; 7] = [2.0, 5.0, 10.0, 20.0, 30.0, 45.0, 60.0];

/// Impact speed (m/s) and friction coefficient of the comparison (Chung & Ooi's inputs).
pub const DEM_SPEED: f64 = 3.9;
/// Friction coefficient of the comparison.
pub const DEM_MU: f64 = 0.092;

/// Largest absolute difference of the tangential CoR between the emulation and the real run
/// of the same model on the wall (`oblique.py` checks the same bound against the table's six
/// decimals). Both integrate the same equations with the same 20000 steps per contact time
/// from the same first overlap; observed up to 1.5e-10.
pub const EMULATION_BOUND: f64 = 1e-5;

/// The real runs, as `validation/dem_clients/oblique.py --csv` wrote them.
pub const REAL_RUNS_CSV: &str = include_str!("../../../validation/dem_clients/oblique.csv");

/// Small incidence angles (degrees, inclusive): where the contact point reverses or nearly so.
pub const SMALL_ANGLES: f64 = 10.0;

/// One real run.
#[derive(Debug, Clone, PartialEq)]
pub struct RealRun {
    /// `wall` or `spheres`.
    pub geometry: String,
    /// Incidence angle (degrees from the normal).
    pub angle_deg: f64,
    /// The code and its version.
    pub code: String,
    /// The tangential model.
    pub model: String,
    /// Tangential CoR of the contact point (after over before).
    pub tangential_cor: f64,
    /// Contact-patch rebound angle (degrees).
    pub rebound_angle_deg: f64,
    /// Normal CoR.
    pub cor: f64,
    /// `mdr`'s tangential CoR of the same impact (`run --json`).
    pub mdr_tangential_cor: f64,
    /// `mdr`'s contact-patch rebound angle (degrees).
    pub mdr_rebound_angle_deg: f64,
}

/// Parse the embedded CSV of the real runs.
pub fn real_runs() -> Result<Vec<RealRun>> {
    let bad = |line: usize, message: String| Error::Csv {
        file: "validation/dem_clients/oblique.csv".into(),
        line: line as u64 + 1,
        message,
    };
    let mut rows = Vec::new();
    for (i, l) in REAL_RUNS_CSV.lines().enumerate().skip(1) {
        let c: Vec<&str> = l.split(',').collect();
        if c.len() != 9 {
            return Err(bad(i, format!("{} fields, expected 9", c.len())));
        }
        let num = |k: usize| -> Result<f64> {
            c[k].parse::<f64>()
                .map_err(|_| bad(i, format!("field {} is not a number", k + 1)))
        };
        rows.push(RealRun {
            geometry: c[0].into(),
            angle_deg: num(1)?,
            code: c[2].into(),
            model: c[3].into(),
            tangential_cor: num(4)?,
            rebound_angle_deg: num(5)?,
            cor: num(6)?,
            mdr_tangential_cor: num(7)?,
            mdr_rebound_angle_deg: num(8)?,
        });
    }
    Ok(rows)
}

/// The models of the real runs, in the CSV's order: (code, model).
fn models(runs: &[RealRun]) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    for r in runs {
        let k = (r.code.clone(), r.model.clone());
        if !out.contains(&k) {
            out.push(k);
        }
    }
    out
}

/// The real run of `model` on `geometry` at `angle`.
fn find<'a>(runs: &'a [RealRun], geometry: &str, model: &str, angle: f64) -> Result<&'a RealRun> {
    runs.iter()
        .find(|r| r.geometry == geometry && r.model == model && r.angle_deg == angle)
        .ok_or(Error::Internal(
            "validation/dem_clients/oblique.csv lacks a run of the comparison",
        ))
}

/// The alumina case at [`DEM_SPEED`] and `theta` degrees with friction [`DEM_MU`]: `mdr`'s
/// tangential CoR and the emulation's of each model of [`DemTangential::ALL`].
pub fn dem_row(theta: f64) -> Result<(f64, [f64; 4])> {
    let (v_n, v_t) = (
        DEM_SPEED * theta.to_radians().cos(),
        DEM_SPEED * theta.to_radians().sin(),
    );
    let imp = case_impact(CASES[0].1)?.at_velocity(v_n)?;
    let o = solve_with(&imp, &inputs(DEM_MU, v_t), SolverKind::Mdr, MDR_RTOL)?;
    Ok((o.tangential.tangential_cor, emulation(theta)?))
}

/// The emulation's tangential CoR of each model of [`DemTangential::ALL`] for the alumina
/// sphere of [`CASES`] on a rigid wall at [`DEM_SPEED`], `theta` degrees, friction [`DEM_MU`].
pub fn emulation(theta: f64) -> Result<[f64; 4]> {
    let (v_n, v_t) = (
        DEM_SPEED * theta.to_radians().cos(),
        DEM_SPEED * theta.to_radians().sin(),
    );
    let (g, nu, m, r) = (1.5447e11, 0.23, 2.6180e-4, 2.5e-3);
    let mut emu = [0.0; 4];
    for (e, model) in emu.iter_mut().zip(DemTangential::ALL) {
        *e = dem_tangential_cor(model, g, nu, m, r, 0.4, DEM_MU, v_n, v_t, 20_000)?;
    }
    Ok(emu)
}

/// Everything the tables need: per angle `mdr`'s tangential CoR and the emulation's.
pub fn dem_rows() -> Result<Vec<(f64, [f64; 4])>> {
    DEM_ANGLES.par_iter().map(|&th| dem_row(th)).collect()
}

/// The wall's real runs against `mdr` (computed here): per angle each model's tangential CoR
/// and, in brackets, its difference from `mdr`.
pub fn real_table(rows: &[(f64, [f64; 4])]) -> Result<Table> {
    let runs = real_runs()?;
    let ms = models(&runs);
    let mut heads = vec!["angle (deg)".to_string(), "mdr".to_string()];
    heads.extend(ms.iter().map(|(c, m)| format!("{c} {m}")));
    let refs: Vec<&str> = heads.iter().map(String::as_str).collect();
    let mut t = Table::new(&refs);
    for (&th, (m, _)) in DEM_ANGLES.iter().zip(rows) {
        let mut row = vec![format!("{th}"), format!("{m:.4}")];
        for (_, model) in &ms {
            let r = find(&runs, "wall", model, th)?;
            row.push(format!(
                "{:.4} ({:+.4})",
                r.tangential_cor,
                r.tangential_cor - m
            ));
        }
        t.rows.push(row);
    }
    Ok(t)
}

/// Per model: the largest absolute difference from `mdr` of the tangential CoR on the wall
/// (all angles, and up to [`SMALL_ANGLES`]), for two spheres, and of the contact-patch rebound
/// angle on the wall.
pub fn summary_table(rows: &[(f64, [f64; 4])]) -> Result<Table> {
    let runs = real_runs()?;
    let mut t = Table::new(&[
        "code, tangential model",
        "max abs diff, tangential CoR (wall, 2-60 deg)",
        "at 2-10 deg (wall)",
        "two spheres, 2-60 deg",
        "max abs diff, contact-patch rebound angle (wall, deg)",
    ]);
    for (code, model) in models(&runs) {
        let (mut all, mut small, mut two, mut ang) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for (&th, (m, _)) in DEM_ANGLES.iter().zip(rows) {
            let w = find(&runs, "wall", &model, th)?;
            let d = (w.tangential_cor - m).abs();
            all = all.max(d);
            if th <= SMALL_ANGLES {
                small = small.max(d);
            }
            ang = ang.max((w.rebound_angle_deg - w.mdr_rebound_angle_deg).abs());
            let s = find(&runs, "spheres", &model, th)?;
            two = two.max((s.tangential_cor - s.mdr_tangential_cor).abs());
        }
        t.rows.push(vec![
            format!("{code} {model}"),
            format!("{all:.3}"),
            format!("{small:.3}"),
            format!("{two:.3}"),
            format!("{ang:.2}"),
        ]);
    }
    Ok(t)
}

/// The emulation of the Mindlin models on the wall, with the worst difference from the real run
/// of the same model at each angle (`oblique.py` reads the emulation's columns).
pub fn emulation_table(rows: &[(f64, [f64; 4])]) -> Result<Table> {
    let runs = real_runs()?;
    let mut heads = vec!["angle (deg)"];
    heads.extend(DemTangential::ALL.iter().map(|m| m.keyword()));
    heads.push("worst abs(emulation - real run)");
    let mut t = Table::new(&heads);
    for (&th, (_, emu)) in DEM_ANGLES.iter().zip(rows) {
        let mut row = vec![format!("{th}")];
        let mut worst = 0.0f64;
        for (e, model) in emu.iter().zip(DemTangential::ALL) {
            let r = find(&runs, "wall", model.keyword(), th)?;
            worst = worst.max((e - r.tangential_cor).abs());
            row.push(format!("{e:.6}"));
        }
        row.push(format!("{worst:.1e}"));
        t.rows.push(row);
    }
    Ok(t)
}

/// The text above the real runs' table.
pub const DEM_TEXT: &str = "\nThe tangential models of the DEM codes, run in the codes \
themselves: `validation/dem_clients/oblique.py` bounces the alumina sphere of \
`scenes/oblique_alumina.toml` (3.9 m/s, friction 0.092) on a wall and two such spheres against \
each other in LAMMPS 20220106 (`fix wall/gran granular` / `pair_style granular`: \
`hertz/material` without damping and each tangential model: `linear_history` with \
`k_t = 8 G a_max / (2 - nu)`, the Mindlin stiffness at the normal impact's largest contact \
radius; the four Mindlin models with `k_t = 8 G / (2 - nu)` (force `k_t a xi`); no tangential \
damping, `rolling none`, `twisting none`) and in LIGGGHTS 3.8.0 (`model hertz tangential \
history`, restitution 1), 20000 steps per contact time, and reads the contact point's \
tangential velocity after the impact. The last LAMMPS column is the closest model and stiffness \
found: `mindlin_rescale/force` with `k_t` times 0.8 (a scan of the factor, docs/dem.md). Its numbers are committed \
(`validation/dem_clients/oblique.csv`, rerun in CI). On the wall, each model's tangential CoR \
and in brackets its difference from `mdr` (rtol 1e-5):\n\n";

/// The text between the real runs' table and the summary.
pub const SUMMARY_TEXT: &str = "\nPer model, the largest absolute difference from `mdr` (two \
spheres: the runs' own `mdr` column, `run --json` at rtol 1e-6; the line of centres turns by \
about 2e-3 rad during the contact, which the MDR's fixed normal does not, so even gross slip \
differs there by up to 1.4e-3):\n\n";

/// The text above the emulation's table.
pub const EMULATION_TEXT: &str = "\nThe real runs against the emulation of the four Mindlin \
models (`apps::dem::tangential`: the equations of the LAMMPS documentation, Hertz normal force, \
`k_t = 8 G a / (2 - nu)`, the Coulomb limit on the total force, velocity Verlet with 20000 steps \
per contact time, the same first overlap), tangential CoR on the wall. Asserted within 1e-5 \
(absolute) in `report::validate::oblique_dem` and by `oblique.py` in CI.\n\n";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn real_runs_cover_every_angle_model_and_geometry() {
        let runs = real_runs().unwrap();
        let ms = models(&runs);
        assert_eq!(ms.len(), 7, "{ms:?}");
        for (_, model) in &ms {
            for th in DEM_ANGLES {
                for geometry in ["wall", "spheres"] {
                    let r = find(&runs, geometry, model, th).unwrap();
                    assert!(r.tangential_cor.is_finite() && r.cor > 0.99, "{r:?}");
                }
            }
        }
    }

    #[test]
    fn emulation_reproduces_the_real_lammps_runs() {
        let runs = real_runs().unwrap();
        let mut worst = 0.0f64;
        for th in DEM_ANGLES {
            let emu = emulation(th).unwrap();
            for (e, model) in emu.iter().zip(DemTangential::ALL) {
                let r = find(&runs, "wall", model.keyword(), th).unwrap();
                let d = e - r.tangential_cor;
                worst = worst.max(d.abs());
                assert!(
                    d.abs() <= EMULATION_BOUND,
                    "{th} deg {}: emulation {e}, LAMMPS {}",
                    model.keyword(),
                    r.tangential_cor
                );
            }
        }
        eprintln!("worst abs(emulation - LAMMPS): {worst:.1e}");
    }

    #[test]
    fn gross_slip_is_exact_in_every_model_on_the_wall() {
        // from about 33 deg the sphere slides throughout: every model meets mdr
        let runs = real_runs().unwrap();
        for r in runs
            .iter()
            .filter(|r| r.geometry == "wall" && r.angle_deg >= 45.0)
        {
            assert!(
                (r.tangential_cor - r.mdr_tangential_cor).abs() < 1e-3,
                "{r:?}"
            );
        }
    }
}
