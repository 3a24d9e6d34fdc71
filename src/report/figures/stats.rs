//! The paper's claims in numbers: statistics of the CoR maps and curves, as Markdown tables.
//!
//! Notation: `e` is the CoR of the compressible solid, `e_inc` the incompressible one at the same
//! `(p2, p3)`, `delta = (e_inc - e) / e` the relative error made by assuming incompressibility
//! (negative: underestimated), and `e / e_inc - 1 = (e - e_inc) / e_inc` the same error relative
//! to the incompressible prediction.

use std::fmt::Write as _;

use super::contour::Field;
use super::{nu_name, DatasetRun, Map};
use crate::error::{Error, Result};

/// `(e_inc - e) / e` on the grid of two maps (NaN where either is missing).
pub fn relative_error(e: &Field, e_inc: &Field) -> Result<Field> {
    if e.x != e_inc.x || e.y != e_inc.y {
        return Err(Error::NotSupported {
            solver: "relative error",
            what: "the two maps are on different grids".into(),
        });
    }
    let z =
        e.z.iter()
            .zip(&e_inc.z)
            .map(|(&a, &b)| if a > 0.0 { (b - a) / a } else { f64::NAN })
            .collect();
    Field::new(e.x.clone(), e.y.clone(), z)
}

/// Spearman rank correlation of paired samples (ties get their average rank); NaN pairs are
/// dropped; `None` with fewer than 3 pairs or a constant sample.
pub fn spearman(a: &[f64], b: &[f64]) -> Option<f64> {
    let pairs: Vec<(f64, f64)> = a
        .iter()
        .zip(b)
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .map(|(&x, &y)| (x, y))
        .collect();
    if pairs.len() < 3 {
        return None;
    }
    let rank = |v: Vec<f64>| -> Vec<f64> {
        let mut idx: Vec<usize> = (0..v.len()).collect();
        idx.sort_by(|&i, &j| v[i].total_cmp(&v[j]));
        let mut r = vec![0.0; v.len()];
        let mut i = 0;
        while i < idx.len() {
            let mut j = i;
            while j + 1 < idx.len() && v[idx[j + 1]] == v[idx[i]] {
                j += 1;
            }
            let avg = 0.5 * (i + j) as f64 + 1.0;
            for &k in &idx[i..=j] {
                r[k] = avg;
            }
            i = j + 1;
        }
        r
    };
    let ra = rank(pairs.iter().map(|p| p.0).collect());
    let rb = rank(pairs.iter().map(|p| p.1).collect());
    let n = ra.len() as f64;
    let (ma, mb) = (ra.iter().sum::<f64>() / n, rb.iter().sum::<f64>() / n);
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in ra.iter().zip(&rb) {
        sab += (x - ma) * (y - mb);
        saa += (x - ma) * (x - ma);
        sbb += (y - mb) * (y - mb);
    }
    if saa == 0.0 || sbb == 0.0 {
        return None;
    }
    Some(sab / (saa * sbb).sqrt())
}

/// One curve of Figs. 5 / 6 with its incompressible counterpart.
#[derive(Debug, Clone)]
pub struct LineData {
    /// Poisson ratio.
    pub nu: f64,
    /// `log10 p2` of the curve.
    pub log10_p2: f64,
    /// `log10 p3` values.
    pub x: Vec<f64>,
    /// CoR.
    pub e: Vec<f64>,
    /// Incompressible CoR at the same points.
    pub e_inc: Vec<f64>,
}

/// How the numbers were made.
#[derive(Debug, Clone)]
pub struct Setup {
    /// Solver name.
    pub solver: String,
    /// Requested rtol.
    pub rtol: f64,
    /// Map grid sizes and curve points.
    pub n_p2: usize,
    /// See `n_p2`.
    pub n_p3: usize,
    /// See `n_p2`.
    pub n_line: usize,
    /// Seed of the dimensional inputs (`None`: canonical units).
    pub dimensional: Option<u64>,
    /// Rayon threads.
    pub threads: usize,
    /// Wall time of the sweeps (s).
    pub compute_seconds: f64,
    /// Wall time of plotting (s).
    pub figure_seconds: f64,
    /// The sweeps.
    pub runs: Vec<DatasetRun>,
}

fn pct(x: f64) -> String {
    if x.is_finite() {
        format!("{:.1} %", 100.0 * x)
    } else {
        "–".into()
    }
}

fn num(x: f64) -> String {
    if x.is_finite() {
        format!("{x:.4}")
    } else {
        "–".into()
    }
}

fn loc(f: &Field, i: usize) -> String {
    let nx = f.x.len();
    format!("({:.2}, {:.2})", f.y[i / nx], f.x[i % nx])
}

/// Index of the extreme finite value (`max = true`: largest).
fn arg_extreme(z: &[f64], max: bool) -> Option<usize> {
    z.iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite())
        .max_by(|a, b| {
            if max {
                a.1.total_cmp(b.1)
            } else {
                b.1.total_cmp(a.1)
            }
        })
        .map(|(i, _)| i)
}

/// `log10 p2` and `log10 p3` extents of the grid nodes where `pred` holds.
fn extent(f: &Field, pred: impl Fn(usize) -> bool) -> Option<((f64, f64), (f64, f64))> {
    let nx = f.x.len();
    let mut r: Option<((f64, f64), (f64, f64))> = None;
    for i in 0..f.z.len() {
        if pred(i) {
            let (p2, p3) = (f.y[i / nx], f.x[i % nx]);
            r = Some(match r {
                None => ((p2, p2), (p3, p3)),
                Some(((a, b), (c, d))) => ((a.min(p2), b.max(p2)), (c.min(p3), d.max(p3))),
            });
        }
    }
    r
}

/// Bins of `e_inc` for the "small e, large error" table.
pub const E_BINS: [(f64, f64); 5] = [(0.0, 0.2), (0.2, 0.4), (0.4, 0.6), (0.6, 0.8), (0.8, 1.01)];

/// Every table of RESULTS.md, as Markdown.
pub fn tables(maps: &[Map], lines: &[LineData], s: &Setup) -> Result<String> {
    let inc = maps
        .iter()
        .find(|m| m.nu == 0.5)
        .ok_or(Error::NotSupported {
            solver: "tables",
            what: "no incompressible map".into(),
        })?;
    let comp: Vec<&Map> = maps.iter().filter(|m| m.nu != 0.5).collect();
    let mut o = String::new();
    let w = &mut o;
    let cells = inc.field.z.len();
    let _ = writeln!(
        w,
        "Made by `mdr-impact figures` with solver `{}`, rtol {:e}, on a grid of {} x {} \
         (log10 p2 in [{}, {}] x log10 p3 in [{}, {}]) = {} points per map, {} points per curve, \
         {}; {} threads. Locations are given as (log10 p2, log10 p3) of grid nodes.\n",
        s.solver,
        s.rtol,
        s.n_p2,
        s.n_p3,
        super::LOG_P2_RANGE.0,
        super::LOG_P2_RANGE.1,
        super::LOG_P3_RANGE.0,
        super::LOG_P3_RANGE.1,
        cells,
        s.n_line,
        match s.dimensional {
            Some(seed) => format!(
                "random dimensional inputs as in the paper (seed {seed}; m, R, v0, G_inf \
                 log-uniform, G_1, eta, K_0 set from the groups)"
            ),
            None => "canonical units m = R = v0 = G_inf = 1".into(),
        },
        s.threads
    );

    // --- Table 1: where the CoR is small
    let _ = writeln!(
        w,
        "### T1. Compressibility matters most where the CoR is small\n"
    );
    let _ = writeln!(
        w,
        "Mean and max of |delta| = |e_inc - e| / e over the map nodes, binned by the \
         incompressible CoR e_inc (Fig. 4), and Spearman rank correlation of |delta| with e_inc and \
         with e.\n"
    );
    let _ = write!(w, "| e_inc bin | nodes |");
    for m in &comp {
        let _ = write!(w, " mean / max \\|delta\\| {} |", nu_name(m.nu));
    }
    let _ = writeln!(w);
    let _ = writeln!(w, "|---|---|{}", "---|".repeat(comp.len()));
    let rels: Vec<Field> = comp
        .iter()
        .map(|m| relative_error(&m.field, &inc.field))
        .collect::<Result<_>>()?;
    for &(lo, hi) in &E_BINS {
        let in_bin: Vec<usize> = (0..cells)
            .filter(|&i| inc.field.z[i] >= lo && inc.field.z[i] < hi)
            .collect();
        let _ = write!(
            w,
            "| [{lo:.1}, {:.1}{} | {} |",
            hi.min(1.0),
            if hi > 1.0 { "]" } else { ")" },
            in_bin.len()
        );
        for rel in &rels {
            let v: Vec<f64> = in_bin
                .iter()
                .map(|&i| rel.z[i].abs())
                .filter(|x| x.is_finite())
                .collect();
            if v.is_empty() {
                let _ = write!(w, " – |");
            } else {
                let mean = v.iter().sum::<f64>() / v.len() as f64;
                let max = v.iter().copied().fold(0.0, f64::max);
                let _ = write!(w, " {} / {} |", pct(mean), pct(max));
            }
        }
        let _ = writeln!(w);
    }
    let _ = write!(w, "| Spearman(\\|delta\\|, e_inc) | |");
    for rel in &rels {
        let a: Vec<f64> = rel.z.iter().map(|x| x.abs()).collect();
        let r = spearman(&a, &inc.field.z).unwrap_or(f64::NAN);
        let _ = write!(w, " {} |", num(r));
    }
    let _ = writeln!(w);
    let _ = write!(w, "| Spearman(\\|delta\\|, e) | |");
    for (rel, m) in rels.iter().zip(&comp) {
        let a: Vec<f64> = rel.z.iter().map(|x| x.abs()).collect();
        let r = spearman(&a, &m.field.z).unwrap_or(f64::NAN);
        let _ = write!(w, " {} |", num(r));
    }
    let _ = writeln!(w, "\n");
    let _ = writeln!(
        w,
        "| nu | min e (where) | min e_inc (where) | max \\|delta\\| (where) |\n|---|---|---|---|"
    );
    for (rel, m) in rels.iter().zip(&comp) {
        let a: Vec<f64> = rel.z.iter().map(|x| x.abs()).collect();
        let (ie, ii, ia) = (
            arg_extreme(&m.field.z, false),
            arg_extreme(&inc.field.z, false),
            arg_extreme(&a, true),
        );
        let f = |i: Option<usize>, z: &[f64], p: bool| match i {
            Some(i) => format!(
                "{} at {}",
                if p { pct(z[i]) } else { num(z[i]) },
                loc(&m.field, i)
            ),
            None => "–".into(),
        };
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} |",
            m.nu,
            f(ie, &m.field.z, false),
            f(ii, &inc.field.z, false),
            f(ia, &a, true)
        );
    }
    let _ = writeln!(w);

    // --- Table 2: under- or overestimated
    let _ = writeln!(
        w,
        "### T2. Assuming incompressibility usually underestimates the CoR\n"
    );
    let _ = writeln!(
        w,
        "Share of the map nodes where e_inc < e (underestimate), where delta < -1 % and where \
         delta > +1 % (overestimate), and the extreme values of delta.\n"
    );
    let _ = writeln!(
        w,
        "| nu | e_inc < e | delta < -1 % | delta > +1 % | min delta (where) | max delta (where) |\n\
         |---|---|---|---|---|---|"
    );
    for (rel, m) in rels.iter().zip(&comp) {
        let n = rel.z.iter().filter(|x| x.is_finite()).count().max(1) as f64;
        let under = (0..cells)
            .filter(|&i| inc.field.z[i] < m.field.z[i])
            .count() as f64;
        let u1 = rel.z.iter().filter(|&&x| x < -0.01).count() as f64;
        let o1 = rel.z.iter().filter(|&&x| x > 0.01).count() as f64;
        let mn = arg_extreme(&rel.z, false);
        let mx = arg_extreme(&rel.z, true);
        let f = |i: Option<usize>| match i {
            Some(i) => format!("{} at {}", pct(rel.z[i]), loc(&m.field, i)),
            None => "–".into(),
        };
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {} |",
            m.nu,
            pct(under / n),
            pct(u1 / n),
            pct(o1 / n),
            f(mn),
            f(mx)
        );
    }
    let _ = writeln!(w);

    // --- Table 3: errors of 100 % and more
    let _ = writeln!(
        w,
        "### T3. Errors of 100 % and more, even close to nu = 0.5\n"
    );
    let _ = writeln!(
        w,
        "Two ways to measure the error: relative to the true (compressible) CoR, delta = \
         (e_inc - e)/e, which cannot fall below -100 % when e_inc underestimates; and relative to \
         the incompressible prediction, e/e_inc - 1 = (e - e_inc)/e_inc, which exceeds 100 % \
         wherever e >= 2 e_inc (delta <= -50 %).\n"
    );
    let _ = writeln!(
        w,
        "| nu | max (e - e_inc)/e_inc (where) | nodes with e >= 2 e_inc | their log10 p2 range | \
         their log10 p3 range | nodes with \\|delta\\| >= 100 % |\n|---|---|---|---|---|---|"
    );
    for (rel, m) in rels.iter().zip(&comp) {
        let ratio: Vec<f64> = (0..cells)
            .map(|i| m.field.z[i] / inc.field.z[i] - 1.0)
            .collect();
        let im = arg_extreme(&ratio, true);
        let big = |i: usize| ratio[i] >= 1.0;
        let nbig = (0..cells).filter(|&i| big(i)).count();
        let ext = extent(&m.field, big);
        let n100 = rel.z.iter().filter(|x| x.abs() >= 1.0).count();
        let _ = writeln!(
            w,
            "| {} | {} | {} ({}) | {} | {} | {} ({}) |",
            m.nu,
            match im {
                Some(i) => format!("{} at {}", pct(ratio[i]), loc(&m.field, i)),
                None => "–".into(),
            },
            nbig,
            pct(nbig as f64 / cells as f64),
            ext.map_or("–".into(), |((a, b), _)| format!("[{a:.2}, {b:.2}]")),
            ext.map_or("–".into(), |(_, (c, d))| format!("[{c:.2}, {d:.2}]")),
            n100,
            pct(n100 as f64 / cells as f64),
        );
    }
    let _ = writeln!(w);

    // --- Table 4: the curves of Figs. 5 and 6
    let _ = writeln!(w, "### T4. Figs. 5 and 6: CoR against p3\n");
    let _ = writeln!(
        w,
        "Per curve: the minimum of e over log10 p3 in [{}, {}], the values at p3 = 10 \
         (log10 p3 = 1, the point the paper names for Fig. 6), and the largest |delta| on the \
         curve.\n",
        super::LOG_P3_RANGE.0,
        super::LOG_P3_RANGE.1
    );
    let _ = writeln!(
        w,
        "| log10 p2 | nu | min e (at log10 p3) | e at p3 = 10 | e_inc at p3 = 10 | delta at p3 = 10 \
         | (e - e_inc)/e_inc at p3 = 10 | max \\|delta\\| (at log10 p3) |\n\
         |---|---|---|---|---|---|---|---|"
    );
    for l in lines {
        let imin = arg_extreme(&l.e, false);
        let at10 = l.x.iter().position(|&x| (x - 1.0).abs() < 1e-9);
        let rel: Vec<f64> =
            l.e.iter()
                .zip(&l.e_inc)
                .map(|(&e, &ei)| (ei - e) / e)
                .collect();
        let abs: Vec<f64> = rel.iter().map(|x| x.abs()).collect();
        let ia = arg_extreme(&abs, true);
        let (e10, ei10) = at10.map_or((f64::NAN, f64::NAN), |i| (l.e[i], l.e_inc[i]));
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {} | {} | {} |",
            l.log10_p2,
            if l.nu == 0.5 {
                "0.5 (inc.)".to_string()
            } else {
                l.nu.to_string()
            },
            imin.map_or("–".into(), |i| format!("{} ({:.2})", num(l.e[i]), l.x[i])),
            num(e10),
            num(ei10),
            pct((ei10 - e10) / e10),
            pct((e10 - ei10) / ei10),
            ia.map_or("–".into(), |i| format!("{} ({:.2})", pct(abs[i]), l.x[i])),
        );
    }
    let _ = writeln!(w);

    // --- Table 5: scaling check and runs
    let _ = writeln!(w, "### T5. Scaling check and work\n");
    let _ = writeln!(
        w,
        "With random dimensional inputs, every K-th point is solved again in canonical units; \
         deviation = |e - e_canonical| / e_canonical. (Wall times are printed by the command, not \
         kept here, so that the committed tables are reproducible.)\n"
    );
    let _ = writeln!(
        w,
        "| data file | points | failed | checked | max deviation |\n|---|---|---|---|---|"
    );
    for r in &s.runs {
        let name = std::path::Path::new(&r.file)
            .file_name()
            .map_or(r.file.clone(), |n| n.to_string_lossy().to_string());
        let _ = writeln!(
            w,
            "| `data/{}` | {} | {} | {} | {} |",
            name,
            r.summary.planned,
            r.summary.failed,
            r.summary.checks,
            r.summary
                .max_scaling_dev
                .map_or("–".into(), |d| format!("{d:.1e}"))
        );
    }
    Ok(o)
}
