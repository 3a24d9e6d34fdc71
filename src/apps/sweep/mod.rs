//! Parameter sweeps of the coefficient of restitution over the groups `(nu, p2, p3)` of Eq. (11):
//! the `sweep` command and the data behind every figure.
//!
//! A sweep is a [`Plan`] (a grid, or a random sample, of `nu`, `log10 p2`, `log10 p3`) turned into
//! numbered [`Point`]s. Each point is solved in parallel (rayon) either in canonical units
//! (`m = R = v0 = G_inf = 1`) or, like the paper, from **random dimensional inputs**
//! (`m`, `R`, `v0`, `G_inf` drawn log-uniformly, then `G_1 = G_inf / p2`,
//! `eta = p3 / (v0 R / (m^2 G_inf^3))^(1/5)` and `K_0` from `nu` via [`Material::with_poisson`]).
//! With dimensional inputs every `check_every`-th point is solved in canonical units too and the
//! relative deviation of the two CoRs is recorded: a running check of the scaling of Eq. (11).
//!
//! # Output and resume
//! Rows go to a CSV file with the columns [`COLUMNS`], **appended and flushed one by one** as they
//! finish, so an interrupted run loses at most the row being written. Started again on the same
//! file, a sweep skips every point whose `index` is already there (checking that the row's groups,
//! solver, rtol and input mode match the plan, so that two different sweeps are never mixed) and
//! drops a torn last line. When every planned point is present, the file is rewritten in index
//! order (atomically). A point whose solve fails is kept as a row with an empty `cor` and the
//! message in `error`; it is not retried on resume.

use std::collections::BTreeMap;
use std::fs::OpenOptions;
use std::io::{Read, Seek, SeekFrom};
use std::path::Path;
use std::sync::Mutex;
use std::time::Instant;

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::io::output::{fmt, write_atomic};
use crate::model::impact::{Groups, Impact, Sphere};
use crate::model::material::{Bulk, Material};
use crate::rng::SplitMix64;
use crate::solvers::{solve, SolveOptions};

mod records;
pub use records::*;

/// Default requested relative accuracy of the CoR in sweeps and figures (contour maps need a few
/// digits, not twelve).
pub const DEFAULT_SWEEP_RTOL: f64 = 1e-4;

/// Default spacing of the scaling check with dimensional inputs: every 10th point.
pub const DEFAULT_CHECK_EVERY: u64 = 10;

/// Log-uniform ranges of the random dimensional inputs, `(log10 min, log10 max)`:
/// mass (kg), radius (m), impact velocity (m/s), `G_inf` (Pa).
pub const DIMENSIONAL_RANGES: [(&str, f64, f64); 4] = [
    ("mass", -4.0, 1.0),
    ("radius", -4.0, -1.0),
    ("velocity", -2.0, 1.0),
    ("g_inf", 4.0, 9.0),
];

/// The CSV columns of a sweep, in order.
///
/// `index` numbers the planned point; `nu, p2, p3` are the groups of Eq. (11) (`nu = 0.5`:
/// incompressible) and `log10_p2, log10_p3` their planned logarithms; `cor` is Eq. (10);
/// `cor_error_estimate` the solver's estimate of its relative error (empty when unknown);
/// `contact_time, max_indentation` are in canonical units (divided by the Hertz scales);
/// `mass, radius, velocity, g_inf, g_1, eta, k_0` are the SI inputs actually solved (`k_0` empty
/// when incompressible; all empty for a point refused before its impact exists); `cor_canonical, scaling_dev` the canonical CoR and
/// `|cor - cor_canonical| / cor_canonical` on the checked subsample (empty elsewhere);
/// `solver, rtol, dimensional` the requested solver, accuracy and input mode (`1`: random
/// dimensional inputs); `seconds` the wall time of the point; `error` the failure message (empty on
/// success).
pub const COLUMNS: [&str; 24] = [
    "index",
    "nu",
    "p2",
    "p3",
    "log10_p2",
    "log10_p3",
    "cor",
    "cor_error_estimate",
    "contact_time",
    "max_indentation",
    "mass",
    "radius",
    "velocity",
    "g_inf",
    "g_1",
    "eta",
    "k_0",
    "cor_canonical",
    "scaling_dev",
    "solver",
    "rtol",
    "dimensional",
    "seconds",
    "error",
];

pub(super) fn header() -> Vec<&'static str> {
    COLUMNS.to_vec()
}

/// A range of `log10` values: `n` equally spaced values from `min` to `max` (both included).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogRange {
    /// Smallest `log10` value.
    pub min: f64,
    /// Largest `log10` value (`>= min`).
    pub max: f64,
    /// Number of grid values; `None` when given as `MIN:MAX` (enough for random samples).
    pub n: Option<usize>,
}

/// Largest number of values of one grid axis.
pub const MAX_AXIS: usize = 100_000;

impl LogRange {
    /// Parse `MIN:MAX:N`, `MIN:MAX` or a single value `V` (= `V:V:1`); `field` names the option
    /// in errors. Requires finite `MIN <= MAX`, `1 <= N <= 100000`, and `N = 1` only if
    /// `MIN = MAX`.
    pub fn parse(field: &'static str, s: &str) -> Result<Self> {
        let bad = |what: &str| Error::Parse {
            what: field,
            input: crate::error::escape_text(s),
            expected: format!(
                "MIN:MAX:N (log10 values, MIN <= MAX, N >= 1), MIN:MAX or a single value; {}",
                crate::error::escape_text(what)
            ),
        };
        let parts: Vec<&str> = s.split(':').map(str::trim).collect();
        let num = |t: &str| -> Result<f64> {
            let v: f64 = t
                .parse()
                .map_err(|_| bad(&format!("'{t}' is not a number")))?;
            if v.is_finite() && v.abs() <= 300.0 {
                Ok(v)
            } else {
                Err(Error::OutOfRange {
                    field,
                    value: v,
                    allowed: "-300 <= log10 value <= 300",
                })
            }
        };
        let (min, max, n) = match parts.as_slice() {
            [v] => {
                let v = num(v)?;
                (v, v, Some(1))
            }
            [a, b] => (num(a)?, num(b)?, None),
            [a, b, n] => {
                let n: usize = n
                    .parse()
                    .map_err(|_| bad(&format!("N = '{n}' is not a whole number")))?;
                (num(a)?, num(b)?, Some(n))
            }
            _ => return Err(bad("wrong number of ':'-separated parts")),
        };
        if min > max {
            return Err(Error::OutOfRange {
                field,
                value: min,
                allowed: "MIN <= MAX",
            });
        }
        if let Some(n) = n {
            if n == 0 || n > MAX_AXIS {
                return Err(Error::OutOfRange {
                    field,
                    value: n as f64,
                    allowed: "1 <= N <= 100000",
                });
            }
            if n == 1 && min != max {
                return Err(bad("N = 1 needs MIN = MAX"));
            }
        }
        Ok(Self { min, max, n })
    }

    /// The grid's `log10` values (exact at both ends); an error when `n` is missing.
    pub fn values(&self, field: &'static str) -> Result<Vec<f64>> {
        let n = self.n.ok_or_else(|| Error::NotSupported {
            solver: field,
            what: "a grid needs MIN:MAX:N (MIN:MAX is enough for --random only)".into(),
        })?;
        if n == 1 {
            return Ok(vec![self.min]);
        }
        let step = (self.max - self.min) / (n - 1) as f64;
        Ok((0..n)
            .map(|i| {
                if i == n - 1 {
                    self.max
                } else {
                    self.min + step * i as f64
                }
            })
            .collect())
    }
}

/// Parse a list of static Poisson ratios, comma-separated: numbers in `(-1, 0.5]`, or
/// `inc` / `incompressible` for `0.5`. Duplicates are an error.
pub fn parse_nu_list(s: &str) -> Result<Vec<f64>> {
    let mut out = Vec::new();
    for t in s.split(',').map(str::trim) {
        let v = match t {
            "inc" | "incompressible" => 0.5,
            _ => t.parse::<f64>().map_err(|_| Error::Parse {
                what: "nu",
                input: crate::error::escape_text(t),
                expected: "a comma-separated list of numbers in (-1, 0.5] or 'inc'".into(),
            })?,
        };
        if !(v > -1.0 && v <= 0.5) {
            return Err(Error::OutOfRange {
                field: "nu",
                value: v,
                allowed: "-1 < nu <= 0.5",
            });
        }
        if out.contains(&v) {
            return Err(Error::Parse {
                what: "nu",
                input: crate::error::escape_text(s),
                expected: format!("each value once ({v} is listed twice)"),
            });
        }
        out.push(v);
    }
    Ok(out)
}

/// How the points of a [`Plan`] are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sampling {
    /// Cartesian product `nu x log10 p2 x log10 p3` (`nu` outermost, `p3` innermost).
    Grid,
    /// `n` points: `nu` drawn from the list, `log10 p2`, `log10 p3` uniform in their ranges.
    Random {
        /// Number of points.
        n: usize,
        /// Seed of the generator.
        seed: u64,
    },
}

/// What to sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// Static Poisson ratios (`0.5`: incompressible).
    pub nu: Vec<f64>,
    /// Range of `log10 p2`.
    pub log_p2: LogRange,
    /// Range of `log10 p3`.
    pub log_p3: LogRange,
    /// Grid or random sample.
    pub sampling: Sampling,
}

/// One planned point of a sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    /// Position in the plan (the `index` column).
    pub index: u64,
    /// Static Poisson ratio.
    pub nu: f64,
    /// `log10 p2`.
    pub log10_p2: f64,
    /// `log10 p3`.
    pub log10_p3: f64,
}

impl Point {
    /// The validated groups `(nu, 10^log10_p2, 10^log10_p3)`.
    pub fn groups(&self) -> Result<Groups> {
        Groups::new(
            self.nu,
            10f64.powf(self.log10_p2),
            10f64.powf(self.log10_p3),
        )
    }
}

/// Largest number of points of one plan.
pub const MAX_POINTS: usize = 100_000_000;

impl Plan {
    /// The numbered points of the plan (deterministic for a given plan and seed).
    pub fn points(&self) -> Result<Vec<Point>> {
        if self.nu.is_empty() {
            return Err(Error::Parse {
                what: "nu",
                input: String::new(),
                expected: "at least one value".into(),
            });
        }
        let mut pts = Vec::new();
        match self.sampling {
            Sampling::Grid => {
                let p2 = self.log_p2.values("log-p2")?;
                let p3 = self.log_p3.values("log-p3")?;
                let total = self.nu.len() as f64 * p2.len() as f64 * p3.len() as f64;
                if total > MAX_POINTS as f64 {
                    return Err(Error::OutOfRange {
                        field: "number of grid points",
                        value: total,
                        allowed: "<= 1e8",
                    });
                }
                for &nu in &self.nu {
                    for &a in &p2 {
                        for &b in &p3 {
                            pts.push(Point {
                                index: pts.len() as u64,
                                nu,
                                log10_p2: a,
                                log10_p3: b,
                            });
                        }
                    }
                }
            }
            Sampling::Random { n, seed } => {
                if n == 0 || n > MAX_POINTS {
                    return Err(Error::OutOfRange {
                        field: "random",
                        value: n as f64,
                        allowed: "1 <= random <= 1e8",
                    });
                }
                let mut rng = SplitMix64::new(seed);
                for i in 0..n {
                    let nu = self.nu[(rng.next_u64() % self.nu.len() as u64) as usize];
                    let a = self.log_p2.min + (self.log_p2.max - self.log_p2.min) * rng.uniform();
                    let b = self.log_p3.min + (self.log_p3.max - self.log_p3.min) * rng.uniform();
                    pts.push(Point {
                        index: i as u64,
                        nu,
                        log10_p2: a,
                        log10_p3: b,
                    });
                }
            }
        }
        for p in &pts {
            p.groups()?; // refuse p2 or p3 overflowing to 0 or inf before any work is done
        }
        Ok(pts)
    }
}

/// Random dimensional inputs for the point `index` (deterministic in `seed` and `index`), with
/// `G_1`, `eta` and `K_0` set so that the impact has exactly the groups `g` (up to rounding).
pub fn dimensional_impact(g: Groups, seed: u64, index: u64) -> Result<Impact> {
    let mut rng = SplitMix64::new(seed ^ index.wrapping_mul(0xD1B5_4A32_D192_ED03));
    let mut draw = |k: usize| {
        let (_, lo, hi) = DIMENSIONAL_RANGES[k];
        10f64.powf(lo + (hi - lo) * rng.uniform())
    };
    let (m, r, v0, g_inf) = (draw(0), draw(1), draw(2), draw(3));
    let g_1 = if g.p2.is_infinite() {
        0.0
    } else {
        g_inf / g.p2
    };
    // eta = p3 / (v0 R / (m^2 G_inf^3))^(1/5), in logs.
    let eta = if g.p3 == 0.0 {
        0.0
    } else {
        (g.p3.ln() - 0.2 * (v0.ln() + r.ln() - 2.0 * m.ln() - 3.0 * g_inf.ln())).exp()
    };
    let mat = Material::with_poisson(g_inf, g_1, eta, g.nu)?;
    Impact::new(Sphere::new(m, r)?, v0, mat)
}

/// How to run a sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepOptions {
    /// Solver, accuracy and limits of each solve.
    pub solve: SolveOptions,
    /// Random dimensional inputs (seed) instead of canonical units.
    pub dimensional: Option<u64>,
    /// With dimensional inputs, also solve every `check_every`-th point (`index % k == 0`) in
    /// canonical units and record the deviation; `0`: never.
    pub check_every: u64,
    /// Keep the rows already in the output file and skip their points; `false`: start afresh.
    pub resume: bool,
}

impl Default for SweepOptions {
    fn default() -> Self {
        Self {
            solve: SolveOptions {
                rtol: DEFAULT_SWEEP_RTOL,
                ..Default::default()
            },
            dimensional: None,
            check_every: DEFAULT_CHECK_EVERY,
            resume: true,
        }
    }
}

/// Solve one point (never fails: a failed solve becomes a record with `error` set).
pub fn solve_point(p: &Point, opts: &SweepOptions) -> Record {
    let t0 = Instant::now();
    let mut rec = Record {
        point: *p,
        p2: 10f64.powf(p.log10_p2),
        p3: 10f64.powf(p.log10_p3),
        cor: None,
        cor_error_estimate: None,
        contact_time: None,
        max_indentation: None,
        inputs: [f64::NAN; 6],
        k_0: None,
        cor_canonical: None,
        scaling_dev: None,
        solver: opts.solve.solver.name().to_string(),
        rtol: opts.solve.rtol,
        dimensional: opts.dimensional.is_some(),
        seconds: 0.0,
        error: String::new(),
    };
    let result = (|| -> Result<()> {
        let g = p.groups()?;
        let impact = match opts.dimensional {
            Some(seed) => dimensional_impact(g, seed, p.index)?,
            None => Impact::from_groups(g)?,
        };
        let m = impact
            .standard_solid()
            .expect("sweeps are over the standard solid's groups");
        let s = impact.sphere();
        rec.inputs = [
            s.mass(),
            s.radius(),
            impact.velocity(),
            m.g_inf(),
            m.g_1(),
            m.eta(),
        ];
        rec.k_0 = match m.bulk() {
            Bulk::Modulus(k) => Some(k),
            Bulk::Incompressible => None,
        };
        let o = solve(&impact, &opts.solve)?;
        let sc = impact.scales();
        rec.cor = Some(o.cor);
        rec.cor_error_estimate = o.cor_error_estimate;
        rec.contact_time = Some(o.contact_time / sc.time);
        rec.max_indentation = Some(o.max_indentation / sc.length);
        if opts.dimensional.is_some()
            && opts.check_every > 0
            && p.index.is_multiple_of(opts.check_every)
        {
            let c = solve(&Impact::from_groups(g)?, &opts.solve)?;
            rec.cor_canonical = Some(c.cor);
            rec.scaling_dev = Some((o.cor - c.cor).abs() / c.cor.abs().max(f64::MIN_POSITIVE));
        }
        Ok(())
    })();
    if let Err(e) = result {
        rec.cor = None;
        rec.error = e.to_string();
    }
    rec.seconds = t0.elapsed().as_secs_f64();
    rec
}

/// What a sweep did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Summary {
    /// Points in the plan.
    pub planned: usize,
    /// Points skipped because their rows were already in the file.
    pub resumed: usize,
    /// Points computed by this run.
    pub computed: usize,
    /// Rows (old and new) whose solve failed.
    pub failed: usize,
    /// Rows (old and new) with a scaling check.
    pub checks: usize,
    /// Largest scaling deviation over those rows.
    pub max_scaling_dev: Option<f64>,
    /// Wall time of this run (s).
    pub seconds: f64,
}

/// Check that a row read back belongs to the planned sweep.
fn matches(path: &Path, r: &Record, p: &Point, opts: &SweepOptions) -> Result<()> {
    let same = r.point.nu == p.nu
        && r.point.log10_p2 == p.log10_p2
        && r.point.log10_p3 == p.log10_p3
        && r.solver == opts.solve.solver.name()
        && r.rtol == opts.solve.rtol
        && r.dimensional == opts.dimensional.is_some();
    if same {
        Ok(())
    } else {
        Err(Error::NotSupported {
            solver: "sweep",
            what: format!(
            "{}: row {} (nu = {}, log10 p2 = {}, log10 p3 = {}, solver {}, rtol {}, dimensional {}) \
             was made by a different sweep than the one asked for (nu = {}, log10 p2 = {}, \
             log10 p3 = {}, solver {}, rtol {}, dimensional {}); use another --out, or --fresh to \
             discard its rows and start afresh",
            path.display(),
            r.point.index,
            r.point.nu,
            r.point.log10_p2,
            r.point.log10_p3,
            r.solver,
            r.rtol,
            r.dimensional,
            p.nu,
            p.log10_p2,
            p.log10_p3,
            opts.solve.solver.name(),
            opts.solve.rtol,
            opts.dimensional.is_some()
        ),
        })
    }
}

/// Run a sweep over `points`, appending rows to `out` (see the module docs for resume).
/// Returns the summary; the rows are in the file (read them with [`read_records`]).
/// `tick` is called once per point (for a progress bar of `points.len()` units): at once for the
/// points resumed from the file, after its solve for every other.
pub fn run(
    points: &[Point],
    out: &Path,
    opts: &SweepOptions,
    tick: &(dyn Fn() + Sync),
) -> Result<Summary> {
    opts.solve.validate()?;
    let t0 = Instant::now();
    let by_index: BTreeMap<u64, &Point> = points.iter().map(|p| (p.index, p)).collect();
    if by_index.len() != points.len() {
        return Err(Error::Internal("sweep: duplicate point indices"));
    }
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    }
    let mut file = OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(out)
        .map_err(|e| Error::io(out, e))?;
    let mut done: BTreeMap<u64, Record> = BTreeMap::new();
    if opts.resume {
        let mut bytes = Vec::new();
        file.read_to_end(&mut bytes)
            .map_err(|e| Error::io(out, e))?;
        let keep = complete_len(&bytes);
        for r in parse_records(out, &bytes[..keep])? {
            let p = by_index
                .get(&r.point.index)
                .ok_or_else(|| Error::NotSupported {
                    solver: "sweep",
                    what: format!(
                    "{}: row index {} is not in the planned sweep of {} points; use another --out, \
                     or --fresh to discard its rows and start afresh",
                    out.display(),
                    r.point.index,
                    points.len()
                ),
                })?;
            matches(out, &r, p, opts)?;
            done.insert(r.point.index, r);
        }
        // drop a torn last line (a run killed while writing it)
        file.set_len(keep as u64).map_err(|e| Error::io(out, e))?;
    } else {
        file.set_len(0).map_err(|e| Error::io(out, e))?;
    }
    file.seek(SeekFrom::End(0)).map_err(|e| Error::io(out, e))?;
    let is_empty = file.metadata().map_err(|e| Error::io(out, e))?.len() == 0;
    let mut w = csv::WriterBuilder::new().from_writer(file);
    if is_empty {
        w.write_record(header()).map_err(|e| Error::io(out, e))?;
        w.flush().map_err(|e| Error::io(out, e))?;
    }
    let pending: Vec<&Point> = points
        .iter()
        .filter(|p| !done.contains_key(&p.index))
        .collect();
    for _ in 0..done.len() {
        tick();
    }
    let writer = Mutex::new(w);
    let new_rows: Mutex<Vec<Record>> = Mutex::new(Vec::with_capacity(pending.len()));
    pending.par_iter().try_for_each(|p| -> Result<()> {
        let rec = solve_point(p, opts);
        {
            let mut w = writer
                .lock()
                .map_err(|_| Error::Internal("sweep: writer lock poisoned"))?;
            w.write_record(rec.fields())
                .map_err(|e| Error::io(out, e))?;
            w.flush().map_err(|e| Error::io(out, e))?;
        }
        if let Ok(mut v) = new_rows.lock() {
            v.push(rec);
        }
        tick();
        Ok(())
    })?;
    drop(writer);
    let computed = pending.len();
    let resumed = done.len();
    for r in new_rows.into_inner().unwrap_or_default() {
        done.insert(r.point.index, r);
    }
    // complete: rewrite in index order, atomically
    if done.len() == points.len() {
        write_atomic(out, |wr| {
            let mut c = csv::Writer::from_writer(wr);
            c.write_record(header()).map_err(|e| Error::io(out, e))?;
            for r in done.values() {
                c.write_record(r.fields()).map_err(|e| Error::io(out, e))?;
            }
            c.flush().map_err(|e| Error::io(out, e))
        })?;
    }
    let devs: Vec<f64> = done.values().filter_map(|r| r.scaling_dev).collect();
    Ok(Summary {
        planned: points.len(),
        resumed,
        computed,
        failed: done.values().filter(|r| r.cor.is_none()).count(),
        checks: devs.len(),
        max_scaling_dev: devs.iter().copied().reduce(f64::max),
        seconds: t0.elapsed().as_secs_f64(),
    })
}

impl std::fmt::Display for Summary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} points planned, {} already done, {} computed, {} failed in {:.2} s",
            self.planned, self.resumed, self.computed, self.failed, self.seconds
        )?;
        if let Some(d) = self.max_scaling_dev {
            write!(
                f,
                "; scaling check: max |e - e_canonical| / e_canonical = {d:.2e} over {} points",
                self.checks
            )?;
        }
        Ok(())
    }
}
