//! Oblique impacts (docs/theory.md §14): the cases and checks of VALIDATION.md 1g, shared with
//! `tests/oblique.rs`.
//!
//! - gross slip: the exact change of the slip velocity `(1 + 1/kappa) mu (1 + e) v_n`;
//! - no slip: `mdr` at `mu = 1e4` against the tangential hereditary integral of
//!   `theory::oblique::no_slip`;
//! - two routes: `mdr` against `reference` (`theory::oblique`, no shared code) in partial slip;
//! - the Maw–Barber–Fawcett collapse: elastic impacts with equal `chi = (1 + 1/kappa)
//!   (1 - nu) / (2 - nu)` and equal `psi_1 = 2 (1 - nu) / ((2 - nu) mu) tan(theta_c)` have equal
//!   `psi_2` (the MDR's tangential problem depends on these two numbers only).

use rayon::prelude::*;

use crate::error::Result;
use crate::io::scene::Scene;
use crate::model::impact::Impact;
use crate::model::oblique::Oblique;
use crate::report::markdown::{fmt_err, Table};
use crate::solvers::oblique::{solve_oblique, ObliqueOutcome};
use crate::solvers::theory;
use crate::solvers::{SolveOptions, SolverKind};

/// A case: name and scene text (the tangential keys are set per check).
pub const CASES: [(&str, &str); 4] = [
    (
        "alumina on a rigid plane (elastic)",
        "[sphere]\nmass = 2.6180e-4\nradius = 2.5e-3\n[impact]\nvelocity = 3.9\n\
         [material.shear]\ng_inf = 1.5447e11\nterms = []\n[material.bulk]\npoisson = 0.23\n",
    ),
    (
        "standard solid (default scene)",
        "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n[impact]\nvelocity = 0.99\n\
         [material]\ng_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\npoisson = 0.49\n",
    ),
    (
        "three shear terms, relaxing bulk",
        "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n[impact]\nvelocity = 1.5\n\
         [material.shear]\ng_inf = 5.0e6\nterms = [[2.0e7, 1.0e-6], [3.0e7, 1.0e-5], [1.0e7, 1.0e-4]]\n\
         [material.bulk]\nk_inf = 2.0e8\nterms = [[1.0e8, 1.0e-5]]\n",
    ),
    (
        "two viscoelastic spheres",
        "[impact]\nvelocity = 1.0\n\
         [[body]]\nmass = 4.11e-3\nradius = 5.0e-3\n[body.material]\ng_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\npoisson = 0.45\n\
         [[body]]\nmass = 8.0e-3\nradius = 8.0e-3\n[body.material]\ng_inf = 3.0e6\ng_1 = 5.0e6\neta = 100.0\npoisson = 0.4\n",
    ),
];

/// `rtol` of the `mdr` runs of the checks.
pub const MDR_RTOL: f64 = 1e-5;

/// The impact of a case.
pub fn case_impact(text: &str) -> Result<Impact> {
    Ok(Scene::parse(text)?.impact)
}

/// Solve `impact` with tangential inputs `oblique` by `solver` at `rtol`.
pub fn solve_with(
    impact: &Impact,
    oblique: &Oblique,
    solver: SolverKind,
    rtol: f64,
) -> Result<ObliqueOutcome> {
    solve_oblique(
        impact,
        oblique,
        &SolveOptions {
            solver,
            rtol,
            ..Default::default()
        },
    )
}

/// Tangential inputs: friction `mu`, the centre's tangential velocity `v_t` (m/s), no spin.
pub fn inputs(mu: f64, v_t: f64) -> Oblique {
    Oblique {
        friction: mu,
        tangential_velocity: v_t,
        ..Default::default()
    }
}

/// Gross slip (`v_t` ten times the threshold): the relative deviation of `v_c - v_c'` from
/// `(1 + 1/kappa) mu (1 + e) v_n` for `mdr` and for `reference`.
pub fn gross_slip(impact: &Impact) -> Result<(f64, f64)> {
    let mu = 0.2;
    let v_n = impact.velocity();
    let ob = inputs(mu, 10.0 * 3.5 * mu * 2.0 * v_n);
    let dev = |solver| -> Result<f64> {
        let o = solve_with(impact, &ob, solver, MDR_RTOL)?;
        let lambda = ob.tangential(impact)?.compliance;
        let exact = lambda * mu * (1.0 + o.normal.cor) * v_n;
        let dv = ob.tangential_velocity - o.tangential.slip_velocity_after;
        Ok(dv / exact - 1.0)
    };
    Ok((dev(SolverKind::Mdr)?, dev(SolverKind::Reference)?))
}

/// The tangential CoR of `mdr` and `reference` at the incidence `theta` (degrees, at the
/// impact's speed `v_n / cos theta`... kept as `v_t = v_n tan theta`) with friction `mu`.
pub fn routes(impact: &Impact, mu: f64, theta_deg: f64) -> Result<(f64, f64)> {
    let ob = inputs(mu, impact.velocity() * theta_deg.to_radians().tan());
    let m = solve_with(impact, &ob, SolverKind::Mdr, MDR_RTOL)?;
    let r = solve_with(impact, &ob, SolverKind::Reference, 1e-8)?;
    Ok((m.tangential.tangential_cor, r.tangential.tangential_cor))
}

/// No slip: `mdr`'s tangential CoR at `mu = 1e4` and the hereditary integral's, at
/// `v_t = 0.3 v_n`.
pub fn no_slip(impact: &Impact) -> Result<(f64, f64)> {
    let ob = inputs(1e4, 0.3 * impact.velocity());
    let m = solve_with(impact, &ob, SolverKind::Mdr, MDR_RTOL)?;
    let contact = impact.contact()?;
    let t = ob.tangential(impact)?;
    let v = theory::oblique::no_slip(&contact, &t, 1e-8, 3000)?;
    Ok((m.tangential.tangential_cor, v / t.slip_velocity))
}

/// `psi_2` of the Maw–Barber–Fawcett collapse for an elastic sphere of Poisson ratio `nu` and
/// inertia factor `kappa` at `psi_1` (module docs), friction 0.1, by `mdr`.
pub fn mbf_psi2(nu: f64, kappa: f64, psi1: f64) -> Result<f64> {
    let text = format!(
        "[sphere]\nmass = 2.6e-4\nradius = 2.5e-3\ninertia_factor = {kappa}\n[impact]\n\
         velocity = 1.0\n[material.shear]\ng_inf = 1.5e11\nterms = []\n[material.bulk]\npoisson = {nu}\n"
    );
    let imp = case_impact(&text)?;
    let mu = 0.1;
    let k = 2.0 * (1.0 - nu) / (2.0 - nu);
    let ob = Oblique {
        friction: mu,
        tangential_velocity: psi1 * mu / k,
        inertia: kappa,
        ..Default::default()
    };
    let o = solve_with(&imp, &ob, SolverKind::Mdr, MDR_RTOL)?;
    Ok(-k * o.tangential.slip_velocity_after / (mu * o.normal.cor))
}

/// The table of VALIDATION.md 1g.
pub fn oblique_table() -> Result<Table> {
    let mut t = Table::new(&[
        "case",
        "gross slip: mdr",
        "gross slip: reference",
        "no slip: mdr vs integral",
        "partial slip 20°: mdr vs reference",
        "partial slip 45°: mdr vs reference",
    ]);
    let rows: Vec<Vec<String>> = CASES
        .par_iter()
        .map(|(name, text)| -> Result<Vec<String>> {
            let imp = case_impact(text)?;
            let (gm, gr) = gross_slip(&imp)?;
            let (nm, ni) = no_slip(&imp)?;
            let (a, b) = routes(&imp, 0.3, 20.0)?;
            let (c, d) = routes(&imp, 0.3, 45.0)?;
            Ok(vec![
                (*name).into(),
                fmt_err(gm),
                fmt_err(gr),
                fmt_err(nm - ni),
                fmt_err(a - b),
                fmt_err(c - d),
            ])
        })
        .collect::<Result<_>>()?;
    t.rows = rows;
    Ok(t)
}

/// The collapse table: `psi_2` for pairs `(nu, kappa)` of equal `chi` at several `psi_1`.
pub fn mbf_table() -> Result<Table> {
    let mut t = Table::new(&[
        "psi_1",
        "psi_2 (nu = 0.23, kappa = 0.4)",
        "psi_2 (nu = 0.4, same chi)",
        "difference",
    ]);
    // chi = (1 + 1/kappa)(1 - nu)/(2 - nu) held fixed
    let chi = 3.5 * 0.77 / 1.77;
    let nu2: f64 = 0.4;
    let kappa2 = 1.0 / (chi * (2.0 - nu2) / (1.0 - nu2) - 1.0);
    let rows: Vec<Vec<String>> = [0.5, 1.0, 2.0, 4.0, 8.0]
        .par_iter()
        .map(|&psi1| -> Result<Vec<String>> {
            let a = mbf_psi2(0.23, 0.4, psi1)?;
            let b = mbf_psi2(nu2, kappa2, psi1)?;
            Ok(vec![
                format!("{psi1}"),
                format!("{a:.4}"),
                format!("{b:.4}"),
                fmt_err(a - b),
            ])
        })
        .collect::<Result<_>>()?;
    t.rows = rows;
    Ok(t)
}

/// The text above the table of VALIDATION.md 1g.
pub const OBLIQUE_TEXT: &str = "Oblique impacts with Coulomb friction (docs/theory.md §14), \
cases `report::validate::oblique::CASES` (SI): an alumina sphere on a rigid plane (E = 380 GPa, \
nu = 0.23, 4000 kg/m^3, R = 2.5 mm, 3.9 m/s normal; the inputs of the oblique benchmark of \
Chung & Ooi 2011), the default scene's standard solid, three shear terms on a relaxing bulk, two \
viscoelastic spheres (Goodman's uncoupling). Columns: *gross slip*: the relative deviation of \
the change of the contact point's velocity from the exact `(1 + 1/kappa) mu (1 + e) v_n` \
(`mu = 0.2`, `v_t` ten times the gross-slip threshold); `mdr` meets it to round-off because its \
slip velocity uses the same trapezoidal sum as the normal velocity. *No slip*: `mdr` at \
`mu = 1e4` against the tangential hereditary integral \
`Q = 8 int (G_t/4)(t - t') min(a*(t'), a(t)) u'(t') dt'` on the Lee–Radok/Ting history \
(`theory::oblique::no_slip`, 3000 steps), `v_t = 0.3 v_n`; absolute difference of the \
tangential CoR. *Partial slip*: `mdr` (rtol 1e-5) against `reference` \
(`theory::oblique`: the Lee–Radok/Ting normal history, Gauss–Legendre nodes leaving with Ting's \
`a(t)`, Heun's rule for the impactor; no code shared with `mdr::oblique`), `mu = 0.3`, \
`v_t = v_n tan(theta)`; absolute difference of the tangential CoR (it crosses zero). Asserted \
in `tests/oblique.rs`. Re-run: `mdr-impact validate`; one case: \
`mdr-impact run scenes/oblique_alumina.toml`.\n\n";

/// The text above the collapse table.
pub const MBF_TEXT: &str = "\nMaw, Barber & Fawcett (1976, 1981) showed that the oblique \
impact of elastic spheres depends on one material and inertia number \
`chi = (1 + 1/kappa)(1 - nu)/(2 - nu)` and the normalised incidence \
`psi_1 = 2 (1 - nu) / ((2 - nu) mu) tan(theta_c)` (`theta_c` of the contact point, `e = 1`); \
their curves of the normalised rebound `psi_2 = -2 (1 - nu) / ((2 - nu) mu) v_c' / (e v_n)` are \
not reproduced here as numbers (no tabulated values were at hand). What the table checks is \
the collapse itself on `mdr`: two elastic spheres of equal `chi` but different `nu` and `kappa` \
give the same `psi_2`; gross slip gives `psi_2 = 4 chi - psi_1` (here `chi` = 1.523, so from \
about `psi_1` = 6).\n\n";
