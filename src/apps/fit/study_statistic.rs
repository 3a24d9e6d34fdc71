//! The likelihood-ratio statistic of the truth in the box study (`fit-study --box`, VALIDATION.md
//! §11b): how often `W = S_p(truth) - SSR_fit` exceeds the 95 % threshold, per quantity and
//! reported status, and per design cell (docs/theory.md §16.1, "Coverage after selection").

use statrs::distribution::{ChiSquared, ContinuousCDF};

use super::study_box::{wilson, BoxReport, Cell, Pick, SetOutcome, Status, FACTORS, QUANTITIES};

/// The likelihood-ratio statistic of the truth `W` (the profile misfit at the truth's value
/// above the estimate's) against the threshold, per quantity: over every set where it was
/// evaluated, and split by the reported status.
pub fn markdown(r: &BoxReport, threshold: f64) -> String {
    let mut s = format!(
        "\n### The likelihood-ratio statistic at the truth\n\nPer quantity over every set where \
         it was fitted (the moduli only with contact times, since the CoR alone leaves their \
         common scale free): the share of sets in which the statistic of the truth, `W = \
         S_p(truth) - SSR_fit` (`profile_misfit` from the truth and from the estimate), exceeds \
         the threshold {threshold:.2}, with its 95 % Wilson interval; asymptotically `W` is \
         chi-square with one degree of freedom and the share 5 %. A likelihood-ratio set holds \
         the truth exactly when `W` is within the threshold, so the first column is the miss \
         rate of the likelihood-ratio sets whether they close or not; the other columns split \
         it by what `fit` reported. A higher miss rate among the determined intervals than \
         over all sets is the effect of selecting the sets whose profile closes \
         (docs/theory.md §16.1).\n\n| quantity | all sets: W > {threshold:.2} [95 % Wilson] | \
         determined | conditional on nu | not determined |\n| --- | --- | --- | --- | --- |\n"
    );
    for (q, name) in QUANTITIES.iter().enumerate() {
        let (k, n) = exceed(r, q, threshold, |_| true);
        // the sets whose reported status is one of `keep`'s
        let by = |keep: fn(Status) -> bool| {
            let status = |o: &SetOutcome| o.status.get(q).copied().flatten();
            let (k, n) = exceed(r, q, threshold, |o| status(o).is_some_and(keep));
            share(k, n)
        };
        s.push_str(&format!(
            "| {name} | {} | {} | {} | {} |\n",
            share_wilson(k, n),
            by(|st| matches!(st, Status::Determined(_))),
            by(|st| matches!(st, Status::Conditional(_))),
            by(|st| matches!(st, Status::NotDetermined))
        ));
    }
    s.push_str(&by_cell(r, threshold));
    s
}

/// `k/n = x %`, or `-` when `n` is 0.
fn share(k: usize, n: usize) -> String {
    if n == 0 {
        "-".to_string()
    } else {
        format!("{k}/{n} = {:.1} %", 100.0 * k as f64 / n as f64)
    }
}

/// [`share`] with its 95 % Wilson interval, `k/n = x % [lo, hi]`.
fn share_wilson(k: usize, n: usize) -> String {
    if n == 0 {
        return share(k, n);
    }
    let (lo, hi) = wilson(k, n);
    format!("{} [{:.1}, {:.1}]", share(k, n), 100.0 * lo, 100.0 * hi)
}

/// `(k, n)`: of the `n` sets picked in which the statistic of quantity `q` was evaluated, the
/// `k` in which it exceeds `threshold`.
fn exceed(
    r: &BoxReport,
    q: usize,
    threshold: f64,
    pick: impl Fn(&SetOutcome) -> bool,
) -> (usize, usize) {
    let w: Vec<f64> = r
        .outcomes
        .iter()
        .filter(|o| pick(o))
        .filter_map(|o| o.profile_excess.get(q).copied().flatten())
        .collect();
    (w.iter().filter(|x| **x > threshold).count(), w.len())
}

/// The degrees of freedom of Wilks' statistic `SSR_truth - SSR_fit` in a cell: the fit's
/// identifiable directions (the four parameters of the standard solid, less `nu` when fixed,
/// less the common scale of the moduli without contact times).
fn dof(c: &Cell) -> usize {
    4 - usize::from(!c.nu_free) - usize::from(!c.contact_times)
}

/// The share of sets with `W` above the threshold by design cell, over all sets of the cell
/// whatever `fit` reported: a share well above 5 % in one cell is the statistic's own law
/// departing from chi-square there, which no selection of the reported sets explains.
fn by_cell(r: &BoxReport, threshold: f64) -> String {
    // the four combinations of the two factors that set the fit's dimension, then the levels
    // of the other two factors (noise, nu range: the last four of `FACTORS`)
    let combinations: [(&str, Pick); 4] = [
        ("nu free, CoR + contact time", |c| {
            c.nu_free && c.contact_times
        }),
        ("nu free, CoR only", |c| c.nu_free && !c.contact_times),
        ("nu fixed, CoR + contact time", |c| {
            !c.nu_free && c.contact_times
        }),
        ("nu fixed, CoR only", |c| !c.nu_free && !c.contact_times),
    ];
    // Wilks' statistic of all parameters at once (it needs no profile)
    let wilks = |c: &Cell| ChiSquared::new(dof(c) as f64).map_or(f64::NAN, |d| d.inverse_cdf(0.95));
    // fitted sets in the smallest combination of the two factors that has any
    let per_cell = combinations
        .iter()
        .map(|(_, pick)| r.outcomes.iter().filter(|o| pick(&o.cell)).count())
        .filter(|&n| n > 0)
        .min()
        .unwrap_or(0);
    let mut s = format!(
        "\nThe same share over all sets of each design cell (whatever `fit` reported; each row \
         pools the sets of the cells it names), with the 95 % Wilson interval where the \
         quantity is `p2`, fitted in every set. A cell's share well above 5 % is either the \
         statistic's own law departing from chi-square there, which no selection of the \
         reported sets explains, or sampling noise ({per_cell} sets per cell: {two_se:.1} % is \
         two standard errors above 5 %); the same cell's sets of another seed \
         (`--seed 2 --only ...`) tell the two apart (docs/theory.md §16.1). The last column \
         checks the law without any profile: the share of sets whose truth's misfit exceeds \
         the estimate's by more than the 95 % point of chi-square with as many degrees of \
         freedom as the fit has identifiable directions (Wilks' statistic of all parameters at \
         once: 4 with `nu` free and contact times, one fewer for `nu` fixed, one fewer without \
         contact times), and the mean of that excess over its degrees of freedom (1 for \
         chi-square):\n\n| sets | {} | all parameters: SSR_truth - SSR_fit above chi-square \
         95 % [95 % Wilson], mean excess / dof |\n| --- |{}\n",
        QUANTITIES.join(" | "),
        " --- |".repeat(QUANTITIES.len() + 1),
        two_se = 100.0 * (0.05 + 2.0 * (0.05 * 0.95 / per_cell.max(1) as f64).sqrt()),
    );
    for (label, pick) in combinations.into_iter().chain(FACTORS[4..].iter().copied()) {
        s.push_str(&format!("| {label} |"));
        for (q, name) in QUANTITIES.iter().enumerate() {
            let (k, n) = exceed(r, q, threshold, |o| pick(&o.cell));
            let entry = if *name == "p2" {
                share_wilson(k, n)
            } else {
                share(k, n)
            };
            s.push_str(&format!(" {entry} |"));
        }
        let sets: Vec<&SetOutcome> = r.outcomes.iter().filter(|o| pick(&o.cell)).collect();
        if sets.is_empty() {
            s.push_str(" - |\n");
            continue;
        }
        let above = sets
            .iter()
            .filter(|o| o.ssr.1 - o.ssr.0 > wilks(&o.cell))
            .count();
        let per_dof: f64 = sets
            .iter()
            .map(|o| (o.ssr.1 - o.ssr.0) / dof(&o.cell) as f64)
            .sum::<f64>()
            / sets.len() as f64;
        s.push_str(&format!(
            " {}, {per_dof:.2} |\n",
            share_wilson(above, sets.len())
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::apps::fit::study_box::BoxConfig;

    /// A set of cell `k` whose truth's misfit exceeds the estimate's by `excess`, with the
    /// statistic `w` for `p2` and none for the other quantities.
    fn set(k: u64, excess: f64, w: f64) -> SetOutcome {
        let p2 = QUANTITIES.iter().position(|q| *q == "p2").unwrap();
        let mut profile_excess = vec![None; QUANTITIES.len()];
        profile_excess[p2] = Some(w);
        SetOutcome {
            set: k,
            cell: Cell::of(k),
            truth: [1e6, 1e7, 1e3, 0.3],
            ssr: (10.0, 10.0 + excess),
            status: vec![Some(Status::NotDetermined); QUANTITIES.len()],
            reported: vec![(None, None); QUANTITIES.len()],
            profile_excess,
        }
    }

    /// The table by cell counts `W` above the threshold and Wilks' statistic above the 95 %
    /// point of chi-square with the cell's degrees of freedom: cell 3 (`nu` fixed, CoR only)
    /// has 2 of them, so 5.99 separates 5.5 from 6.5; cell 0 (`nu` free, contact times) has 4
    /// (9.49). The mean excess per degree of freedom is exact.
    #[test]
    fn table_by_cell_counts_against_each_cells_law() {
        assert_eq!(dof(&Cell::of(3)), 2);
        assert_eq!(dof(&Cell::of(0)), 4);
        assert_eq!(dof(&Cell::of(1)), 3);
        let r = BoxReport {
            config: BoxConfig {
                sets: 4,
                seed: 1,
                velocities: 10,
            },
            // cells 3 and 19 are `nu` fixed, CoR only; 0 and 16 `nu` free with contact times
            outcomes: vec![
                set(3, 5.5, 4.0),
                set(19, 6.5, 1.0),
                set(0, 9.0, 3.0),
                set(16, 10.2, 5.0),
            ],
            failures: vec![],
        };
        let md = by_cell(&r, 3.84);
        // the cells of a row: label, the six quantities, Wilks' statistic
        let row = |label: &str| -> Vec<String> {
            let line = md
                .lines()
                .find(|l| l.starts_with(&format!("| {label} |")))
                .unwrap_or_else(|| panic!("no row {label} in\n{md}"));
            line.split('|').map(|c| c.trim().to_string()).collect()
        };
        let p2 = 2 + QUANTITIES.iter().position(|q| *q == "p2").unwrap();
        let fixed = row("nu fixed, CoR only");
        assert!(fixed[p2].starts_with("1/2 = 50.0 % ["), "{fixed:?}");
        assert!(fixed[8].starts_with("1/2 = 50.0 % ["), "{fixed:?}");
        assert!(fixed[8].ends_with("], 3.00"), "{fixed:?}");
        let free = row("nu free, CoR + contact time");
        assert!(free[p2].starts_with("1/2 = 50.0 % ["), "{free:?}");
        assert!(free[8].starts_with("1/2 = 50.0 % ["), "{free:?}");
        assert!(free[8].ends_with("], 2.40"), "{free:?}");
        // no set in the cell: no entries
        let empty = row("nu free, CoR only");
        assert_eq!((empty[p2].as_str(), empty[8].as_str()), ("-", "-"));
    }
}
