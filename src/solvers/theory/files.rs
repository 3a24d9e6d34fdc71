//! Reference force histories (canonical units) written to a directory with a manifest.
//!
//! [`generate_reference`] writes one CSV per case and `manifest.toml` describing each file: the
//! case, its parameters, the generating command (`mdr-impact reference --out reference`), the
//! method and the claimed accuracy. Files are written atomically (temporary file in the same
//! directory, then rename). The test `tests/theory_reference_files.rs` proves that the committed
//! files equal what the code produces now.
//!
//! Canonical units: `m = R = v0 = G_inf = 1`; the material is given by the groups
//! `(nu, p2, p3)` of Eq. (11) (`G_1 = 1/p2`, `eta = p3`, `tau = p2 p3`), and the prescribed
//! histories use rate `V = 1` and peak time `T = 0.75` on a sphere of radius `R = 1`.

use super::reference::impact_sampled;
use super::viscoelastic::{response, triangle_closed_form, IndentSample};
use crate::error::{Error, Result};
use crate::model::impact::Groups;
use crate::solvers::indentation::Prescribed;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// The command that regenerates the files (recorded in the manifest).
pub const REFERENCE_COMMAND: &str = "mdr-impact reference --out reference";
/// Rate `V` of the prescribed histories (canonical).
pub const PRESCRIBED_RATE: f64 = 1.0;
/// Peak time `T` of the prescribed histories (canonical).
pub const PRESCRIBED_PEAK_TIME: f64 = 0.75;
/// Number of equally spaced samples of a prescribed history over `[0, 2T]`.
pub const PRESCRIBED_SAMPLES: usize = 121;
/// rtol of the reference impacts written to the files.
pub const IMPACT_RTOL: f64 = 1e-11;
/// Number of equally spaced samples of an impact history over `[0, t_c]`.
pub const IMPACT_SAMPLES: usize = 201;

/// One material case of the reference set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Case {
    /// Short name used in file names.
    pub name: &'static str,
    /// What the case exercises.
    pub regime: &'static str,
    /// Groups of Eq. (11).
    pub groups: Groups,
}

/// The reference cases: elastic, strongly dissipative, near-incompressible (nu = 0.49, 0.499),
/// strongly compressible (nu = 0, p2 = 0.1), stiff (tau / T = 1e-4 and 1e-6).
pub fn cases() -> Vec<Case> {
    let g = |nu, p2, p3| Groups { nu, p2, p3 };
    vec![
        Case {
            name: "elastic",
            regime: "elastic (G_1 = 0), nu = 0.3",
            groups: g(0.3, f64::INFINITY, 0.0),
        },
        Case {
            name: "dissipative",
            regime: "strongly dissipative, nu = 0.3",
            groups: g(0.3, 0.01, 1.0),
        },
        Case {
            name: "nu0p49",
            regime: "near-incompressible nu = 0.49, dissipative",
            groups: g(0.49, 0.01, 1.0),
        },
        Case {
            name: "nu0p499",
            regime: "near-incompressible nu = 0.499, dissipative",
            groups: g(0.499, 0.01, 1.0),
        },
        Case {
            name: "compressible",
            regime: "strongly compressible nu = 0, p2 = 0.1",
            groups: g(0.0, 0.1, 1.0),
        },
        Case {
            name: "stiff1e-4",
            regime: "stiff, tau = 1e-4 (canonical)",
            groups: g(0.3, 0.01, 0.01),
        },
        Case {
            name: "stiff1e-6",
            regime: "stiff, tau = 1e-6 (canonical)",
            groups: g(0.3, 0.001, 0.001),
        },
    ]
}

/// What [`generate_reference`] wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    /// The CSV files, in manifest order.
    pub files: Vec<PathBuf>,
    /// The manifest.
    pub manifest: PathBuf,
}

fn write_atomic(path: &Path, text: &str) -> Result<()> {
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut tmp = tempfile::NamedTempFile::new_in(dir).map_err(|e| Error::io(dir, e))?;
    tmp.write_all(text.as_bytes())
        .map_err(|e| Error::io(tmp.path(), e))?;
    tmp.persist(path).map_err(|e| Error::io(path, e.error))?;
    Ok(())
}

fn fmt_num(x: f64) -> String {
    format!("{x:.16e}")
}

fn prescribed_csv(samples: &[IndentSample]) -> String {
    let mut s = String::from("t,d,a,force,t1\n");
    for p in samples {
        let _ = writeln!(
            s,
            "{},{},{},{},{}",
            fmt_num(p.t),
            fmt_num(p.d),
            fmt_num(p.a),
            fmt_num(p.force),
            fmt_num(p.t1)
        );
    }
    s
}

fn toml_f64(x: f64) -> String {
    if x.is_infinite() {
        "inf".into()
    } else {
        format!("{x:e}")
    }
}

/// Write the reference force histories and `manifest.toml` into `dir` (created if missing).
///
/// Per case: `triangle_<case>.csv` (closed form with Dawson's integral, cross-checked against
/// quadrature to 1e-10), `halfsine_<case>.csv` (quadrature, [`super::QUAD_RTOL`]) with columns
/// `t,d,a,force,t1`, and `impact_<case>.csv` (reference solver, rtol [`IMPACT_RTOL`]) with
/// columns `t,d,v,force,a` at [`IMPACT_SAMPLES`] equally spaced times over the contact (dense
/// output, independent of the adaptive steps).
pub fn generate_reference(dir: &Path) -> Result<Written> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let (v, tp) = (PRESCRIBED_RATE, PRESCRIBED_PEAK_TIME);
    let times: Vec<f64> = (0..PRESCRIBED_SAMPLES)
        .map(|i| 2.0 * tp * i as f64 / (PRESCRIBED_SAMPLES - 1) as f64)
        .collect();
    let mut manifest = String::new();
    let _ = writeln!(
        manifest,
        "# Reference force histories, canonical units m = R = v0 = G_inf = 1.\n\
         # Generated by `{REFERENCE_COMMAND}` (library: mdr_impact::solvers::theory::generate_reference).\n\
         # Checked by tests/theory_reference_files.rs (regenerate: cargo test --test \
         suite theory_reference_files:: -- --ignored).\n"
    );
    let mut files = Vec::new();
    for case in cases() {
        let g = case.groups;
        let prony = g.canonical_material()?.equivalent_relaxation()?;
        let tau_min = prony.min_tau();
        let common = format!(
            "case = \"{}\"\nregime = \"{}\"\nnu = {}\np2 = {}\np3 = {}\ntau_min = {}\n\
             command = \"{REFERENCE_COMMAND}\"\n",
            case.name,
            case.regime,
            toml_f64(g.nu),
            toml_f64(g.p2),
            toml_f64(g.p3),
            toml_f64(tau_min)
        );
        // triangle: closed form
        let (tri, ts) = triangle_closed_form(&prony, 1.0, v, tp, &times)?;
        let name = format!("triangle_{}.csv", case.name);
        write_atomic(&dir.join(&name), &prescribed_csv(&tri))?;
        let _ = writeln!(
            manifest,
            "[[file]]\nname = \"{name}\"\nhistory = \"triangle\"\nrate = {v:e}\npeak_time = {tp:e}\n\
             radius = 1.0\nseparation_time = {ts:.16e}\ncolumns = \"t,d,a,force,t1\"\n{common}\
             method = \"Lee-Radok/Ting in closed form (Dawson's integral, Newton roots)\"\n\
             accuracy = \"force to 1e-13 of its peak, t1 and separation time to 1e-14 (agrees with quadrature to 1e-10)\"\n"
        );
        files.push(dir.join(&name));
        // half sine: quadrature
        let hs = Prescribed::half_sine(v, tp)?;
        let sam = response(&prony, 1.0, &hs, &times)?;
        let ts = super::viscoelastic::separation_time(&prony, 1.0, &hs)?;
        let name = format!("halfsine_{}.csv", case.name);
        write_atomic(&dir.join(&name), &prescribed_csv(&sam))?;
        let _ = writeln!(
            manifest,
            "[[file]]\nname = \"{name}\"\nhistory = \"half-sine\"\nrate = {v:e}\npeak_time = {tp:e}\n\
             radius = 1.0\nseparation_time = {ts:.16e}\ncolumns = \"t,d,a,force,t1\"\n{common}\
             method = \"Lee-Radok/Ting by checked double-exponential quadrature, safeguarded Newton roots\"\n\
             accuracy = \"force to 1e-10 of its peak (quadrature tolerance 1e-12 of the integral scale)\"\n"
        );
        files.push(dir.join(&name));
        // impact: reference solver
        let o = impact_sampled(&prony, IMPACT_RTOL, IMPACT_SAMPLES)?;
        let h = o
            .history
            .as_ref()
            .ok_or(Error::Internal("reference impact returned no history"))?;
        let mut csv = String::from("t,d,v,force,a\n");
        for i in 0..h.len() {
            let _ = writeln!(
                csv,
                "{},{},{},{},{}",
                fmt_num(h.t[i]),
                fmt_num(h.d[i]),
                fmt_num(h.v[i]),
                fmt_num(h.force[i]),
                fmt_num(h.a[i])
            );
        }
        let name = format!("impact_{}.csv", case.name);
        write_atomic(&dir.join(&name), &csv)?;
        let _ = writeln!(
            manifest,
            "[[file]]\nname = \"{name}\"\nhistory = \"impact\"\nrtol = {IMPACT_RTOL:e}\n\
             cor = {:.16e}\ncor_error_estimate = {:e}\ncontact_time = {:.16e}\nmax_indentation = {:.16e}\n\
             columns = \"t,d,v,force,a\"\n{common}\
             method = \"reference impact solver: Lee-Radok/Ting with exponential Radau IIA collocation (s = 5), step doubling; 201 equally spaced samples over [0, t_c] from the dense record\"\n\
             accuracy = \"CoR relative error below rtol = 1e-11 (two-level estimate); histories to about 1e-10\"\n",
            o.cor,
            o.cor_error_estimate.unwrap_or(f64::NAN),
            o.contact_time,
            o.max_indentation
        );
        files.push(dir.join(&name));
    }
    let mpath = dir.join("manifest.toml");
    write_atomic(&mpath, &manifest)?;
    Ok(Written {
        files,
        manifest: mpath,
    })
}
