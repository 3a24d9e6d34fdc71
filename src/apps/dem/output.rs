//! What `mdr-impact dem` writes: `dem.csv`, the input lines for LAMMPS and LIGGGHTS, the JSON
//! report and `dem.svg`.

use super::*;

/// The CSV header of `dem.csv`.
pub const CSV_HEADER: &str = "v0,cor,cor_constant,cor_viscoelastic,contact_time,\
                              contact_time_constant,contact_time_viscoelastic";

impl DemReport {
    /// The better of the two laws (smaller worst error): `true` for the viscoelastic one.
    pub fn viscoelastic_is_better(&self) -> bool {
        self.viscoelastic.fit.worst_rel_error < self.constant.fit.worst_rel_error
    }

    /// `dem.csv`: our CoR and contact time (s) and both laws' at every velocity (SI, full
    /// precision).
    pub fn csv_text(&self) -> String {
        let mut s = String::from(CSV_HEADER);
        s.push('\n');
        for (i, r) in self.rows.iter().enumerate() {
            s.push_str(&format!(
                "{},{},{},{},{},{},{}\n",
                fmt(r.v0),
                fmt(r.cor),
                fmt(self.constant.fit.cor[i]),
                fmt(self.viscoelastic.fit.cor[i]),
                fmt(r.contact_time),
                fmt(self.constant_times.law[i]),
                fmt(self.viscoelastic_times.law[i])
            ));
        }
        s
    }

    fn header(&self, comment: &str, pages: &[&str]) -> String {
        let c = &self.contact;
        let (v0, vn) = (self.rows[0].v0, self.rows[self.rows.len() - 1].v0);
        let pct = |x: f64| format!("{:.2} %", 100.0 * x);
        let mut s = String::new();
        let mut line = |t: String| {
            s.push_str(comment);
            s.push(' ');
            s.push_str(&t);
            s.push('\n');
        };
        line(format!(
            "mdr-impact dem: {} velocities from {v0:.4e} to {vn:.4e} m/s, SI units",
            self.rows.len()
        ));
        for p in pages {
            line(format!("syntax: {p}"));
        }
        line(format!(
            "Hertz ({} modulus): E* = {:.6e} Pa, R* = {:.6e} m, m* = {:.6e} kg, \
             k = 4/3 E* sqrt(R*) = {:.6e} N/m^1.5",
            self.modulus.name(),
            c.effective_modulus,
            c.radius,
            c.mass,
            c.stiffness()
        ));
        line(format!(
            "both types: E = 2 (1 - nu^2) E* = {:.6e} Pa with nu = {DEM_POISSON} (the codes \
             mix E* = E / (2 (1 - nu^2)))",
            c.dem_young()
        ));
        line(format!(
            "constant CoR: input e = {:.6}, produces e = {:.6}; worst error {}, rms {}",
            self.constant.cor_input,
            self.constant.cor,
            pct(self.constant.fit.worst_rel_error),
            pct(self.constant.fit.rms_rel_error)
        ));
        line(format!(
            "viscoelastic: A = {:.6e} s, eta_n0 = 2 E* A / m* = {:.6e} 1/(m s); worst error {}, \
             rms {}",
            self.viscoelastic.a,
            self.viscoelastic.eta_n0,
            pct(self.viscoelastic.fit.worst_rel_error),
            pct(self.viscoelastic.fit.rms_rel_error)
        ));
        let (t0, tn) = (
            self.rows[0].contact_time,
            self.rows[self.rows.len() - 1].contact_time,
        );
        line(format!(
            "contact time {t0:.4e} to {tn:.4e} s; the laws' differ by up to {} (constant CoR), \
             {} (viscoelastic)",
            pct(self.constant_times.worst_rel_error),
            pct(self.viscoelastic_times.worst_rel_error)
        ));
        line("forces are clipped at zero (no attraction at the end of contact), as below".into());
        for w in &self.warnings {
            line(format!("warning: {w}"));
        }
        s
    }

    /// LAMMPS input lines for the current LAMMPS ([`Self::lammps_text_for`]).
    pub fn lammps_text(&self) -> String {
        self.lammps_text_for(LammpsVersion::CURRENT)
    }

    /// LAMMPS input lines for `version`: `pair_style granular` with `hertz/material` and both
    /// damping laws, the better one active and the other commented out; `pair_coeff 1 2` for two
    /// particles, `fix wall/gran granular` for a wall. The tangential model is a frictionless
    /// placeholder. Before [`LAMMPS_WALL_MIX_SINCE`] a wall gets
    /// [`HertzContact::lammps_legacy_wall_young`]; before [`LAMMPS_COEFF_RESTITUTION_SINCE`]
    /// the constant-CoR law is written as `damping tsuji` with [`tsuji_input`], or left out
    /// with a note when no input gives it.
    pub fn lammps_text_for(&self, version: LammpsVersion) -> String {
        let mut s = self.header(
            "#",
            &[
                "https://docs.lammps.org/pair_granular.html",
                "https://docs.lammps.org/fix_wall_gran.html",
            ],
        );
        let legacy_wall = self.geometry == Geometry::Wall && version.legacy_wall_modulus();
        let young = if legacy_wall {
            self.contact.lammps_legacy_wall_young()
        } else {
            self.contact.dem_young()
        };
        s.push_str(&format!(
            "# for {}; state yours with --lammps-version YYYYMMDD (the date `lmp -h` prints)\n",
            version.label()
        ));
        if version.proven() {
            s.push_str(&format!(
                "# proven on LAMMPS {LAMMPS_PROVEN} (Debian lammps, `lmp -h`: 29 Sep 2021 - \
                 Update 2) by validation/dem_clients/verify.py\n"
            ));
        } else {
            s.push_str(&format!(
                "# written from the LAMMPS sources, not run here; proven on LAMMPS \
                 {LAMMPS_PROVEN} (--lammps-version {LAMMPS_PROVEN})\n"
            ));
        }
        if legacy_wall {
            s.push_str(&format!(
                "# wall: this version's fix wall/gran takes E* = E / (2 (1 - nu)), so the wall \
                 gets E = 2 (1 - nu) E* = {} Pa\n",
                fmt_num(young)
            ));
        }
        let (head, tail) = match self.geometry {
            Geometry::Pair => ("pair_coeff 1 2 hertz/material".to_string(), String::new()),
            Geometry::Wall => (
                "fix wall all wall/gran granular hertz/material".to_string(),
                " zplane 0.0 NULL".to_string(),
            ),
        };
        let tangential = "tangential linear_nohistory 0.0 0.0";
        let line = |damp: f64, model: &str| {
            format!(
                "{head} {} {} {DEM_POISSON} {tangential} damping {model} limit_damping{tail}",
                fmt_num(young),
                fmt_num(damp)
            )
        };
        let gamma = cor_gamma(self.constant.cor_input).ok();
        let constant = if version.has_coeff_restitution() {
            Ok(line(self.constant.cor_input, "coeff_restitution"))
        } else {
            match gamma.and_then(tsuji_input) {
                Some(e) => Ok(line(e, "tsuji")),
                None => Err(format!(
                    "# the constant CoR law: {} has no coeff_restitution, and no damping tsuji \
                     input gives its prefactor {:.6e} (tsuji covers {:.4e} to {:.4e})",
                    version.label(),
                    gamma.unwrap_or(f64::NAN),
                    tsuji_alpha(1.0),
                    tsuji_alpha(0.0)
                )),
            }
        };
        if !version.has_coeff_restitution() {
            s.push_str(&format!(
                "# constant CoR law: {} has no damping coeff_restitution; damping tsuji with \
                 the input whose Marshall polynomial equals the law's prefactor gives the same \
                 force\n",
                version.label()
            ));
        }
        let visco = line(self.viscoelastic.eta_n0, "viscoelastic");
        s.push_str("# tangential: frictionless placeholder, set your own friction model\n");
        s.push_str("pair_style granular\n");
        match self.geometry {
            Geometry::Wall => {
                s.push_str("# particle-particle contacts: your own pair_coeff lines\n")
            }
            // LAMMPS refuses to run without the like-type coefficients too
            Geometry::Pair => s.push_str(
                "# like-type contacts (pair_coeff 1 1, pair_coeff 2 2): your own lines; \
                 these parameters are for the 1-2 contact\n",
            ),
        }
        match constant {
            Ok(constant) => {
                let (on, off) = if self.viscoelastic_is_better() {
                    (visco, constant)
                } else {
                    (constant, visco)
                };
                s.push_str(&on);
                s.push('\n');
                s.push_str("# the other law:\n# ");
                s.push_str(&off);
                s.push('\n');
            }
            Err(note) => {
                s.push_str(&visco);
                s.push('\n');
                s.push_str(&note);
                s.push('\n');
            }
        }
        s
    }

    /// LIGGGHTS input lines: `pair_style gran model hertz` with `limitForce on`, the material
    /// of both types by `fix property/global` (constant-CoR law only: LIGGGHTS's hertz model has
    /// no viscoelastic damping), and for a wall a `fix wall/gran` of type 2.
    pub fn liggghts_text(&self) -> String {
        let mut s = self.header(
            "#",
            &[
                "https://www.cfdem.com/media/DEM/docu/gran_model_hertz.html",
                "https://www.cfdem.com/media/DEM/docu/fix_property.html",
                "https://www.cfdem.com/media/DEM/docu/fix_wall_gran.html",
            ],
        );
        let y = fmt_num(self.contact.dem_young());
        let e = fmt_num(self.constant.cor_input);
        s.push_str(&format!(
            "# proven on {LIGGGHTS_PROVEN} (Debian liggghts) by validation/dem_clients/verify.py\n"
        ));
        s.push_str("# the viscoelastic law has no counterpart in LIGGGHTS's model hertz\n");
        s.push_str(&format!(
            "fix m1 all property/global youngsModulus peratomtype {y} {y}\n"
        ));
        s.push_str(&format!(
            "fix m2 all property/global poissonsRatio peratomtype {DEM_POISSON} {DEM_POISSON}\n"
        ));
        s.push_str(&format!(
            "fix m3 all property/global coefficientRestitution peratomtypepair 2 {e} {e} {e} {e}\n"
        ));
        s.push_str("# friction: a frictionless placeholder, set your own\n");
        s.push_str(
            "fix m4 all property/global coefficientFriction peratomtypepair 2 0.0 0.0 0.0 0.0\n",
        );
        s.push_str("pair_style gran model hertz tangential history limitForce on\n");
        s.push_str("pair_coeff * *\n");
        if self.geometry == Geometry::Wall {
            // LIGGGHTS 3.8 wants the wall's keywords (primitive ...) before limitForce
            s.push_str(
                "fix wall all wall/gran model hertz tangential history primitive type 2 zplane \
                 0.0 limitForce on\n",
            );
        }
        s
    }

    /// One JSON object: velocities, our curve, the Hertz stiffness, both laws with their
    /// parameters and errors, the warnings (SI units).
    pub fn json(&self) -> String {
        let c = &self.contact;
        let curve: Vec<serde_json::Value> = self
            .rows
            .iter()
            .enumerate()
            .map(|(i, r)| {
                serde_json::json!({
                    "v0": r.v0,
                    "cor": r.cor,
                    "cor_constant": self.constant.fit.cor[i],
                    "cor_viscoelastic": self.viscoelastic.fit.cor[i],
                    "contact_time": r.contact_time,
                    "contact_time_constant": self.constant_times.law[i],
                    "contact_time_viscoelastic": self.viscoelastic_times.law[i],
                })
            })
            .collect();
        serde_json::json!({
            "velocities": {
                "min": self.rows[0].v0,
                "max": self.rows[self.rows.len() - 1].v0,
                "n": self.rows.len(),
                "log": self.log,
            },
            "hertz": {
                "modulus": self.modulus.name(),
                "effective_modulus": c.effective_modulus,
                "effective_radius": c.radius,
                "effective_mass": c.mass,
                "stiffness": c.stiffness(),
                "young_modulus": c.dem_young(),
                "poisson_ratio": DEM_POISSON,
                "geometry": match self.geometry {
                    Geometry::Pair => "pair",
                    Geometry::Wall => "wall",
                },
            },
            "laws": {
                "constant": {
                    "cor_input": self.constant.cor_input,
                    "cor": self.constant.cor,
                    "worst_rel_error": self.constant.fit.worst_rel_error,
                    "rms_rel_error": self.constant.fit.rms_rel_error,
                    "worst_contact_time_rel_error": self.constant_times.worst_rel_error,
                },
                "viscoelastic": {
                    "dissipative_constant": self.viscoelastic.a,
                    "lammps_eta_n0": self.viscoelastic.eta_n0,
                    "worst_rel_error": self.viscoelastic.fit.worst_rel_error,
                    "rms_rel_error": self.viscoelastic.fit.rms_rel_error,
                    "worst_contact_time_rel_error": self.viscoelastic_times.worst_rel_error,
                },
            },
            "curve": curve,
            "warnings": self.warnings,
        })
        .to_string()
    }

    /// The text of `format`: input lines, or the JSON object.
    pub fn text(&self, format: Format) -> String {
        match format {
            Format::Lammps(v) => self.lammps_text_for(v),
            Format::Liggghts => self.liggghts_text(),
            Format::Json => self.json(),
        }
    }
}

/// A number for an input file: seven significant digits.
fn fmt_num(x: f64) -> String {
    format!("{x:.6e}")
}

/// Files written by [`write_outputs`].
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    /// `DIR/dem.csv`, `DIR/dem.svg` and, for `lammps` / `liggghts`, `DIR/dem_lammps.in` /
    /// `DIR/dem_liggghts.in`.
    pub files: Vec<PathBuf>,
}

/// Write `dir/dem.csv`, `dir/dem.svg` and the format's input file. Everything is rendered in
/// memory first and each file written atomically; on an error the files already written are
/// removed, so the folder gets all of them or none.
pub fn write_outputs(dir: &Path, report: &DemReport, format: Format) -> Result<Written> {
    let svg = dir.join("dem.svg");
    let mut bodies = vec![
        (dir.join("dem.csv"), report.csv_text()),
        (svg.clone(), dem_svg(&svg, report)?),
    ];
    match format {
        Format::Lammps(v) => bodies.push((dir.join("dem_lammps.in"), report.lammps_text_for(v))),
        Format::Liggghts => bodies.push((dir.join("dem_liggghts.in"), report.liggghts_text())),
        Format::Json => {}
    }
    let mut files = Vec::new();
    for (path, body) in bodies {
        if let Err(e) = write_atomic(&path, |w| {
            w.write_all(body.as_bytes())
                .map_err(|e| Error::io(&path, e))
        }) {
            for f in &files {
                let _ = std::fs::remove_file(f);
            }
            return Err(e);
        }
        files.push(path);
    }
    Ok(Written { files })
}

/// The SVG text of `mdr-impact dem`'s plot: above, our `e(v0)` and the `e(v0)` of each fitted
/// DEM law (our integration of its force law); below, the contact times of ours and of each law
/// with the report's Hertz stiffness; on a linear or (with the report's `log`) logarithmic
/// velocity axis. Rendered in memory only; `path` names the file in errors.
pub fn dem_svg(path: &Path, report: &DemReport) -> Result<String> {
    let rows = &report.rows;
    let span = velocity_span(path, &rows.iter().map(|r| r.v0).collect::<Vec<_>>())?;
    let pct = |x: f64| format!("{:.1} %", 100.0 * x);
    let along = |cor: &[f64]| -> Vec<(f64, f64)> {
        rows.iter().zip(cor).map(|(r, e)| (r.v0, *e)).collect()
    };
    let (c, v) = (&report.constant, &report.viscoelastic);
    let lines: Vec<CorLine> = vec![
        (
            "e(v0), this model".to_string(),
            rows.iter().map(|r| (r.v0, r.cor)).collect(),
            RGBColor(30, 80, 200),
            2,
        ),
        (
            format!(
                "constant CoR e = {:.4}, input e = {:.4} (worst {}, rms {})",
                c.cor,
                c.cor_input,
                pct(c.fit.worst_rel_error),
                pct(c.fit.rms_rel_error)
            ),
            along(&c.fit.cor),
            RGBColor(200, 30, 30),
            2,
        ),
        (
            format!(
                "viscoelastic, A = {:.3e} s (worst {}, rms {})",
                v.a,
                pct(v.fit.worst_rel_error),
                pct(v.fit.rms_rel_error)
            ),
            along(&v.fit.cor),
            RGBColor(30, 140, 60),
            2,
        ),
    ];
    let (ct, vt) = (&report.constant_times, &report.viscoelastic_times);
    let times = |t: &[f64]| -> Vec<(f64, f64)> {
        rows.iter().zip(t).map(|(r, t)| (r.v0, 1e3 * t)).collect()
    };
    let time_lines: Vec<CorLine> = vec![
        (
            "contact time, this model".to_string(),
            rows.iter().map(|r| (r.v0, 1e3 * r.contact_time)).collect(),
            RGBColor(30, 80, 200),
            2,
        ),
        (
            format!("constant CoR law (worst {})", pct(ct.worst_rel_error)),
            times(&ct.law),
            RGBColor(200, 30, 30),
            2,
        ),
        (
            format!("viscoelastic law (worst {})", pct(vt.worst_rel_error)),
            times(&vt.law),
            RGBColor(30, 140, 60),
            2,
        ),
    ];
    let t_max = time_lines
        .iter()
        .flat_map(|l| l.1.iter().map(|p| p.1))
        .fold(0.0, f64::max);
    let c = &report.contact;
    let panels = [
        Panel {
            caption: format!(
                "DEM damping laws fitted to e(v0): Hertz stiffness {}, E* = {:.3e} Pa",
                match report.modulus {
                    ModulusChoice::Fit => "fitted to the contact times".to_string(),
                    m => format!("of the {} modulus", m.name()),
                },
                c.effective_modulus
            ),
            y_label: "coefficient of restitution e".into(),
            y_range: (0.0, COR_AXIS_TOP),
            lines,
            shaded: Default::default(),
        },
        Panel {
            caption: format!(
                "Contact times (m* = {:.3e} kg, R* = {:.3e} m)",
                c.mass, c.radius
            ),
            y_label: "contact time (ms)".into(),
            y_range: (0.0, 1.08 * t_max),
            lines: time_lines,
            shaded: Default::default(),
        },
    ];
    panels_svg(path, span, report.log, "impact velocity v0 (m/s)", &panels)
}
