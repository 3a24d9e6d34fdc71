//! The design targets of `fast`, checked against the timings of a run.

use std::fmt::Write as _;

use super::*;

/// Design targets of `fast` (checked by [`targets()`]): median CoR-only time per impact in every
/// group of [`timing_groups`] at rtol 1e-6 and 1e-10 (s).
pub const TARGET_MEDIAN_SECONDS: [f64; 2] = [20e-6, 200e-6];
/// Design target: `mdr-euler` time over `fast` time at equal CoR error (at most 1e-4).
pub const TARGET_SPEEDUP: f64 = 1000.0;
/// Design target: `cor --input` rows at rtol 1e-6 and the wall time allowed for them (s).
pub const TARGET_BATCH: (usize, f64) = (100_000, 1.0);

/// A list stating which design targets this run met and which it did not (with the measured
/// values): [`TARGET_MEDIAN_SECONDS`] per group of rows, [`TARGET_SPEEDUP`] and
/// [`TARGET_BATCH`] (when measured).
pub fn targets(
    timed: &[(TimedRows, Vec<RowTiming>)],
    speedup: Option<f64>,
    batch: Option<BatchTiming>,
    general: &[String],
) -> String {
    let mut parts = Vec::new();
    for (kind, rows) in timed {
        let stats = group_stats(rows);
        for (k, (&rtol, &limit)) in TIMING_RTOLS.iter().zip(&TARGET_MEDIAN_SECONDS).enumerate() {
            let missed: Vec<String> = stats
                .iter()
                .filter(|g| g.median[k] > limit)
                .map(|g| format!("{} ({})", g.name, fmt_time(g.median[k])))
                .collect();
            let verdict = if missed.is_empty() {
                format!("met in all {} groups", stats.len())
            } else {
                format!(
                    "met in {} of {} groups, **not met** in {}",
                    stats.len() - missed.len(),
                    stats.len(),
                    missed.join(", ")
                )
            };
            parts.push(format!(
                "median at most {} at rtol {rtol:.0e} on the {}: {verdict}",
                fmt_time(limit),
                kind.title()
            ));
        }
    }
    if let Some(x) = speedup {
        let verdict = if x >= TARGET_SPEEDUP {
            "met"
        } else {
            "**not met**"
        };
        parts.push(format!(
            "at least {TARGET_SPEEDUP:.0}x less time than `mdr-euler` at equal CoR error: {verdict} ({x:.0}x)"
        ));
    }
    if let Some(b) = batch {
        let (want, limit) = TARGET_BATCH;
        if b.rows >= want {
            let verdict = if b.seconds <= limit {
                "met"
            } else {
                "**not met**"
            };
            // what the solves alone need, verified and as one unverified solve per row
            let (verified, one) = b.solves;
            let (and, above) = if one > limit {
                ("and ", ": above the target even without any verification")
            } else {
                ("", "")
            };
            let floor = format!(
                "; the solves alone took {verified:.2} s, {and}one unverified solve per row \
                 {one:.2} s{above}"
            );
            parts.push(format!(
                "{want} rows through `cor --input` in at most {limit} s: {verdict} ({} rows in {:.2} s{floor})",
                b.rows, b.seconds
            ));
        }
    }
    parts.extend(general.iter().cloned());
    let mut s = String::from("Design targets of `fast`, checked in this run:\n\n");
    for p in parts {
        let _ = writeln!(s, "- {p}.");
    }
    s
}

/// The CoR group of `r` (its name) and `r` timed in alternation with the standard solids of the
/// random sample in it ([`GeneralTiming::group`]).
fn same_group(r: &GeneralTiming) -> Option<(&'static str, Paired)> {
    let (name, _) = cor_groups().into_iter().find(|(_, member)| member(r.cor))?;
    Some((name, r.group?))
}

/// Half width of the CoR band in which the general materials are also compared with the
/// standard solids: a group of [`cor_groups`] spans CoRs whose cost differs by more than the
/// terms do (the dissipative group's median sits near its elastic end).
pub const COR_BAND: f64 = 0.05;

/// Design target: `fast` at rtol 1e-6 on a real polymer of at least 30 terms
/// ([`crate::report::catalogue::POLYMERS`]) takes at most this multiple of the median time of the
/// standard solid in the same CoR group.
pub const TARGET_GENERAL_RATIO: f64 = 2.0;

/// The target [`TARGET_GENERAL_RATIO`] for the real polymers of at least 30 `G_eq` terms among
/// `rows`, each timed in alternation with the standard solids of its CoR group
/// ([`GeneralTiming::group`]; one list entry per paired polymer, none without the random
/// sample).
pub fn general_targets(rows: &[GeneralTiming]) -> Vec<String> {
    rows.iter()
        .filter(|r| r.terms >= 30 && crate::report::catalogue::POLYMERS.iter().any(|p| p.id == r.id))
        .filter_map(|r| {
            let (name, g) = same_group(r)?;
            let x = g.ratio();
            let band = r.band.map_or(String::new(), |b| {
                format!(
                    "; {:.1}x the {} standard solids within {COR_BAND} of its CoR ({} against {})",
                    b.ratio(),
                    b.rows,
                    fmt_time(b.case),
                    fmt_time(b.standard)
                )
            });
            let verdict = if x <= TARGET_GENERAL_RATIO {
                "met"
            } else {
                "**not met**"
            };
            Some(format!(
                "the {}-term real polymer `{}` at rtol 1e-6 in at most {TARGET_GENERAL_RATIO:.0}x the \
                 median time of the standard solid in its CoR group ({name}): {verdict} ({x:.1}x: {} \
                 against {}, timed in alternation with {} of the group's rows{band})",
                r.terms,
                r.id,
                fmt_time(g.case),
                fmt_time(g.standard),
                g.rows
            ))
        })
        .collect()
}

/// Markdown table of [`general_timing`], each case beside the standard solids of the random
/// sample ([`TimedRows::Random`]) in the same CoR group and beside those within [`COR_BAND`] of
/// its CoR, timed in alternation with them ([`pair_with_standard_solids`]; "-" where a case was
/// not paired), with the ratios of the median times.
pub fn general_timing_table(rows: &[GeneralTiming]) -> String {
    let mut s = format!(
        "| case | G_eq terms | CoR | median time | steps / evaluations | without the merge of far terms (`fast::reduce`) | standard solids of the same CoR group (random rows), timed in alternation with the case: rows, their median time / the case's, steps / evaluations | ratio | the same for the standard solids within {COR_BAND} of the CoR | ratio |\n\
         | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n",
    );
    for r in rows {
        let cell = |p: &Paired| {
            format!(
                "{}, {} / {}, {:.1} / {:.0}",
                p.rows,
                fmt_time(p.standard),
                fmt_time(p.case),
                p.work.0,
                p.work.1
            )
        };
        let (std_text, ratio) = match same_group(r) {
            Some((name, p)) => (format!("{name}: {}", cell(&p)), format!("{:.1}", p.ratio())),
            None => ("-".to_string(), "-".to_string()),
        };
        let (band_text, band_ratio) = match &r.band {
            Some(p) => (cell(p), format!("{:.1}", p.ratio())),
            None => ("-".to_string(), "-".to_string()),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {:.4} | {} | {} / {} | {} | {std_text} | {ratio} | {band_text} | {band_ratio} |",
            r.id,
            r.terms,
            r.cor,
            fmt_time(r.seconds),
            r.steps,
            r.evaluations,
            fmt_time(r.unreduced_seconds)
        );
    }
    s
}
