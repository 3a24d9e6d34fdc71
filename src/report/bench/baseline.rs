//! Today's `fast` against an earlier build of this program on the same rows: both binaries run
//! `cor --input ROWS --solver fast` on one thread, alternately, in one run (the earlier build
//! comes from the history: `scripts/build-baseline.sh`, by default the commit before the
//! answers were verified).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

use crate::error::{Error, Result};
use crate::rng::SplitMix64;

use super::median;

/// Rows of the comparison: `nu` uniform in [-0.5, 0.5], `p2` log-uniform in [1e-3, 1e2], `p3`
/// in [1e-2, 1e3].
pub const BASELINE_ROWS: usize = 20_000;
/// Alternating repeats of each binary (the median is reported).
pub const BASELINE_REPEATS: usize = 5;

/// The comparison of two builds on the same rows.
#[derive(Debug, Clone, PartialEq)]
pub struct BaselineRatio {
    /// The earlier build.
    pub baseline: PathBuf,
    /// Rows.
    pub rows: usize,
    /// Median wall time (s) of the earlier build, one thread.
    pub baseline_seconds: f64,
    /// Median wall time (s) of this build, one thread.
    pub today_seconds: f64,
    /// Largest relative difference of the two builds' CoRs.
    pub max_cor_difference: f64,
}

impl BaselineRatio {
    /// This build's time over the earlier build's.
    pub fn ratio(&self) -> f64 {
        self.today_seconds / self.baseline_seconds
    }

    /// One paragraph for the report.
    pub fn text(&self) -> String {
        format!(
            "Today's verified `fast` against the unverified `fast` of an earlier build \
             (`{}`, built by `scripts/build-baseline.sh`): `cor --input --solver fast` on the same \
             {} random rows (`nu` in [-0.5, 0.5], `p2` in [1e-3, 1e2], `p3` in [1e-2, 1e3], log-uniform; \
             rtol 1e-6), one thread each (`RAYON_NUM_THREADS=1`), the two binaries alternated, \
             median wall time of {BASELINE_REPEATS}: {:.3} s against {:.3} s, a ratio of **{:.2}** \
             (target 1.3). Largest relative difference of their CoRs: {:.1e}.\n",
            self.baseline.display(),
            self.rows,
            self.today_seconds,
            self.baseline_seconds,
            self.ratio(),
            self.max_cor_difference
        )
    }
}

/// The rows of the comparison as CSV text (`nu,p2,p3`), from `seed`.
pub fn baseline_rows_csv(rows: usize, seed: u64) -> String {
    let mut rng = SplitMix64::new(seed);
    let mut s = String::from("nu,p2,p3\n");
    for _ in 0..rows {
        let nu = -0.5 + rng.uniform();
        let p2 = 10f64.powf(-3.0 + 5.0 * rng.uniform());
        let p3 = 10f64.powf(-2.0 + 5.0 * rng.uniform());
        s.push_str(&format!("{nu:e},{p2:e},{p3:e}\n"));
    }
    s
}

/// Run `bin cor --input input --solver fast` on one thread: wall time (s) and the CoR column.
fn timed_run(bin: &Path, input: &Path) -> Result<(f64, Vec<f64>)> {
    let t0 = Instant::now();
    let out = Command::new(bin)
        .args(["cor", "--solver", "fast", "--input"])
        .arg(input)
        .env("RAYON_NUM_THREADS", "1")
        .stderr(Stdio::null())
        .output()
        .map_err(|e| Error::io(bin, e))?;
    let secs = t0.elapsed().as_secs_f64();
    if !out.status.success() {
        return Err(Error::io(
            bin,
            format!("cor --input exited with {}", out.status),
        ));
    }
    let text = String::from_utf8_lossy(&out.stdout);
    let cors = text
        .lines()
        .skip(1)
        .filter_map(|l| l.split(',').nth(3).and_then(|x| x.parse().ok()))
        .collect();
    Ok((secs, cors))
}

/// Time `baseline` against `today` (this program) on [`BASELINE_ROWS`] rows.
pub fn baseline_ratio(baseline: &Path, today: &Path) -> Result<BaselineRatio> {
    let dir = tempfile::tempdir().map_err(|e| Error::io(Path::new("tempdir"), e))?;
    let input = dir.path().join("rows.csv");
    std::fs::write(&input, baseline_rows_csv(BASELINE_ROWS, 28))
        .map_err(|e| Error::io(&input, e))?;
    let (mut tb, mut tt) = (Vec::new(), Vec::new());
    let (mut cb, mut ct) = (Vec::new(), Vec::new());
    for _ in 0..BASELINE_REPEATS {
        let (s, c) = timed_run(baseline, &input)?;
        tb.push(s);
        cb = c;
        let (s, c) = timed_run(today, &input)?;
        tt.push(s);
        ct = c;
    }
    if cb.len() != BASELINE_ROWS || ct.len() != BASELINE_ROWS {
        return Err(Error::io(
            baseline,
            format!(
                "expected {BASELINE_ROWS} CoRs from each build, got {} and {}",
                cb.len(),
                ct.len()
            ),
        ));
    }
    let max_cor_difference = cb
        .iter()
        .zip(&ct)
        .map(|(b, t)| ((t - b) / t).abs())
        .fold(0.0, f64::max);
    Ok(BaselineRatio {
        baseline: baseline.to_path_buf(),
        rows: BASELINE_ROWS,
        baseline_seconds: median(&mut tb),
        today_seconds: median(&mut tt),
        max_cor_difference,
    })
}
