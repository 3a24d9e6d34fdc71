//! `fast` against the SciPy script a user would write (`python/scipy_cor.py`: DOP853 on the
//! Lee–Radok/Ting equations at rtol 1e-8) on the same rows, when `python3` with numpy and scipy
//! is at hand; otherwise "not measured" with the reason.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::error::{Error, Result};
use crate::model::impact::{Groups, Impact};
use crate::rng::SplitMix64;
use crate::solvers::{solve, SolveOptions, SolverKind};

use super::median_time;

/// Rows of the comparison.
pub const SCIPY_ROWS: usize = 20;
/// The accuracy both are asked for.
pub const SCIPY_RTOL: f64 = 1e-8;
/// Smallest `tau = p2 p3` of the rows: DOP853 is explicit, and below this its steps follow
/// `tau` instead of the motion (a user would not pick it there).
pub const SCIPY_MIN_TAU: f64 = 1e-2;
/// The script, in the source tree this program was built from.
pub const SCIPY_SCRIPT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/python/scipy_cor.py");

/// The comparison of one run.
#[derive(Debug, Clone, PartialEq)]
pub enum ScipyComparison {
    /// Both timed on the same rows.
    Measured {
        /// Rows.
        rows: usize,
        /// Sum over the rows of the script's median time per row (s).
        scipy_seconds: f64,
        /// Sum over the rows of `fast`'s median time per row (s), one thread.
        fast_seconds: f64,
        /// Largest relative difference of their CoRs.
        max_cor_difference: f64,
    },
    /// Not measured, and why.
    NotMeasured(String),
}

impl ScipyComparison {
    /// The script's time over `fast`'s, when measured.
    pub fn ratio(&self) -> Option<f64> {
        match self {
            Self::Measured {
                scipy_seconds,
                fast_seconds,
                ..
            } => Some(scipy_seconds / fast_seconds),
            Self::NotMeasured(_) => None,
        }
    }

    /// One paragraph for the report.
    pub fn text(&self) -> String {
        match self {
            Self::Measured {
                rows,
                scipy_seconds,
                fast_seconds,
                max_cor_difference,
            } => format!(
                "`fast` against the SciPy script a user would write (`python/scipy_cor.py`: \
                 `solve_ivp(method=\"DOP853\")` on the Lee–Radok/Ting equations, Ting's root by \
                 `brentq`), both at rtol {SCIPY_RTOL:.0e}, on the same {rows} random rows (`nu` in \
                 [-0.5, 0.5], `p2` in [1e-3, 1e2], `p3` in [1e-2, 1e3], log-uniform, \
                 `tau = p2 p3 >= {SCIPY_MIN_TAU:.0e}` where an explicit method is usable), one \
                 thread, sum of the per-row medians: {scipy_seconds:.3} s against {:.2} ms, a \
                 ratio of **{:.0}**. Largest relative difference of their CoRs: \
                 {max_cor_difference:.1e}.\n",
                fast_seconds * 1e3,
                scipy_seconds / fast_seconds
            ),
            Self::NotMeasured(why) => {
                format!("`fast` against the SciPy script (`python/scipy_cor.py`): not measured ({why}).\n")
            }
        }
    }
}

/// The rows of the comparison, from `seed`: the distribution of [`super::baseline_rows_csv`],
/// rows with `tau < SCIPY_MIN_TAU` drawn again.
pub fn scipy_rows(seed: u64) -> Vec<(f64, f64, f64)> {
    let mut rng = SplitMix64::new(seed);
    let mut out = Vec::with_capacity(SCIPY_ROWS);
    while out.len() < SCIPY_ROWS {
        let nu = -0.5 + rng.uniform();
        let p2 = 10f64.powf(-3.0 + 5.0 * rng.uniform());
        let p3 = 10f64.powf(-2.0 + 5.0 * rng.uniform());
        if p2 * p3 >= SCIPY_MIN_TAU {
            out.push((nu, p2, p3));
        }
    }
    out
}

/// The Python interpreter: `MDR_IMPACT_PYTHON`, else `python3`.
fn python() -> PathBuf {
    std::env::var_os("MDR_IMPACT_PYTHON").map_or_else(|| PathBuf::from("python3"), PathBuf::from)
}

/// Time `fast` against the script on [`SCIPY_ROWS`] rows (`repeats` solves per row for the
/// script, medians within `budget` seconds per row for `fast`). "Not measured" when the script
/// is missing or the interpreter lacks numpy or scipy; an error when the script fails.
pub fn scipy_comparison(budget: f64, repeats: usize) -> Result<ScipyComparison> {
    let script = Path::new(SCIPY_SCRIPT);
    if !script.is_file() {
        return Ok(ScipyComparison::NotMeasured(format!(
            "{} not found",
            script.display()
        )));
    }
    let py = python();
    let has = Command::new(&py)
        .args(["-c", "import numpy, scipy"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status();
    if !matches!(has, Ok(s) if s.success()) {
        return Ok(ScipyComparison::NotMeasured(format!(
            "`{}` with numpy and scipy not found; set MDR_IMPACT_PYTHON",
            py.display()
        )));
    }
    let rows = scipy_rows(28);
    let dir = tempfile::tempdir().map_err(|e| Error::io(Path::new("tempdir"), e))?;
    let input = dir.path().join("rows.csv");
    let mut csv = String::from("nu,p2,p3\n");
    for (nu, p2, p3) in &rows {
        csv.push_str(&format!("{nu:e},{p2:e},{p3:e}\n"));
    }
    std::fs::write(&input, csv).map_err(|e| Error::io(&input, e))?;
    let out = Command::new(&py)
        .arg(script)
        .arg("--input")
        .arg(&input)
        .args(["--rtol", &format!("{SCIPY_RTOL:e}")])
        .args(["--repeats", &repeats.max(1).to_string()])
        .stderr(Stdio::piped())
        .output()
        .map_err(|e| Error::io(&py, e))?;
    if !out.status.success() {
        return Err(Error::io(
            script,
            format!(
                "exited with {}: {}",
                out.status,
                String::from_utf8_lossy(&out.stderr).trim()
            ),
        ));
    }
    let text = String::from_utf8_lossy(&out.stdout);
    let parsed: Vec<(f64, f64)> = text
        .lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            Some((f.get(3)?.parse().ok()?, f.get(4)?.parse().ok()?))
        })
        .collect();
    if parsed.len() != rows.len() {
        return Err(Error::io(
            script,
            format!("expected {} rows, got {}", rows.len(), parsed.len()),
        ));
    }
    let opts = SolveOptions::with(SolverKind::Fast, SCIPY_RTOL);
    let (mut fast_seconds, mut max_cor_difference) = (0.0, 0.0f64);
    for (&(nu, p2, p3), &(cor_py, _)) in rows.iter().zip(&parsed) {
        let imp = Impact::from_groups(Groups::new(nu, p2, p3)?)?;
        let cor = solve(&imp, &opts)?.cor;
        max_cor_difference = max_cor_difference.max(((cor - cor_py) / cor).abs());
        fast_seconds += median_time(budget, || solve(&imp, &opts).map(|_| ()))?.0;
    }
    Ok(ScipyComparison::Measured {
        rows: rows.len(),
        scipy_seconds: parsed.iter().map(|p| p.1).sum(),
        fast_seconds,
        max_cor_difference,
    })
}
