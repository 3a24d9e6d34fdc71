//! General materials as scene input: `[material.shear]` and `[material.bulk]` in all their forms,
//! the standard solid as the one-term case, strict errors, and the dispatch to the solvers.

use mdr_impact::io::scene::Scene;
use mdr_impact::model::material::{BulkInput, ShearProny};
use mdr_impact::{solve, Error, Impact, Material, SolverKind, Sphere};

use crate::common;
use common::{abs_rel_err, opts};

const HEAD: &str = "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n[impact]\nvelocity = 0.99\n";

fn scene(material: &str) -> String {
    format!("{HEAD}{material}")
}

/// The standard solid of the default scene written as a one-term general material has the
/// standard solid's shape: the same groups, the same `G_eq` (the closed form, for both) and the
/// same outcome to the bit with the same solver and rtol (`5.0e-5` is `500 / 1e7` rounded).
#[test]
fn one_term_general_equals_standard_solid() {
    let standard = Scene::parse(&scene(
        "[material]\ng_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\npoisson = 0.49\n",
    ))
    .unwrap();
    let general = Scene::parse(&scene(
        "[material.shear]\ng_inf = 1.0e6\nterms = [[1.0e7, 5.0e-5]]\n\
         [material.bulk]\npoisson = 0.49\n",
    ))
    .unwrap();
    assert_eq!(general.impact.groups(), standard.impact.groups());
    assert!(standard.impact.groups().is_some());
    assert_eq!(
        standard.impact.canonical_relaxation(),
        general.impact.canonical_relaxation()
    );
    for (solver, rtol) in [
        (SolverKind::Fast, 1e-6),
        (SolverKind::Fast, 1e-10),
        (SolverKind::Reference, 1e-6),
        (SolverKind::Auto, 1e-8),
    ] {
        let x = solve(&standard.impact, &opts(solver, rtol)).unwrap();
        let y = solve(&general.impact, &opts(solver, rtol)).unwrap();
        assert_eq!(x.solver, y.solver);
        assert_eq!(y.cor.to_bits(), x.cor.to_bits(), "{solver} rtol {rtol:e}");
        assert_eq!(y.work, x.work);
    }
}

/// The `k_0` and incompressible bulk forms match their standard-solid scenes too.
#[test]
fn bulk_forms_match_the_standard_solid() {
    for (std_bulk, gen_bulk) in [
        ("k_0 = 5.0e7", "k_0 = 5.0e7"),
        ("poisson = 0.5", "incompressible = true"),
    ] {
        let a = Scene::parse(&scene(&format!(
            "[material]\ng_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\n{std_bulk}\n"
        )))
        .unwrap();
        let b = Scene::parse(&scene(&format!(
            "[material.shear]\ng_inf = 1.0e6\nterms = [[1.0e7, 5.0e-5]]\n[material.bulk]\n{gen_bulk}\n"
        )))
        .unwrap();
        let o = opts(SolverKind::Fast, 1e-8);
        let (x, y) = (
            solve(&a.impact, &o).unwrap().cor,
            solve(&b.impact, &o).unwrap().cor,
        );
        assert!(abs_rel_err(y, x) <= 1e-12, "{gen_bulk}: {y} vs {x}");
    }
}

/// The normalised FE form `G(t) = G0 (1 - sum g_i (1 - exp(-t/tau_i)))` is the moduli form with
/// `g_inf = G0 (1 - sum g_i)` and moduli `g_i G0`; the same for the bulk.
#[test]
fn normalised_ratios_equal_moduli() {
    let ratios = Scene::parse(&scene(
        "[material.shear]\ninstantaneous = 1.0e7\nratios = [[0.5, 1.0e-5], [0.25, 1.0e-3]]\n\
         [material.bulk]\ninstantaneous = 4.0e9\nratios = [[0.5, 1.0e-4]]\n",
    ))
    .unwrap();
    let moduli = Scene::parse(&scene(
        "[material.shear]\ng_inf = 2.5e6\nterms = [[5.0e6, 1.0e-5], [2.5e6, 1.0e-3]]\n\
         [material.bulk]\nk_inf = 2.0e9\nterms = [[2.0e9, 1.0e-4]]\n",
    ))
    .unwrap();
    assert_eq!(ratios.impact, moduli.impact);
    let o = solve(&ratios.impact, &opts(SolverKind::Auto, 1e-6)).unwrap();
    assert!(o.cor > 0.0 && o.cor < 1.0);
}

/// `file = "prony.csv"` (a `tau,modulus` table, path relative to the scene file) equals the
/// inline `terms`, for the shear and the bulk.
#[test]
fn csv_file_equals_inline_terms() {
    let dir = tempfile::tempdir().unwrap();
    let sub = dir.path().join("tables");
    std::fs::create_dir(&sub).unwrap();
    std::fs::write(
        sub.join("shear.csv"),
        "\u{feff}tau,modulus\r\n3.2187e-6,1.859e6\r\n\"1.0e-3\",4.0e5\r\n\r\n0.1, 2.5e4\r\n",
    )
    .unwrap();
    std::fs::write(sub.join("bulk.csv"), "tau,modulus\n1.0e-4,1.0e9\n").unwrap();
    let inline = scene(
        "[material.shear]\ng_inf = 1.0e4\nterms = [[1.859e6, 3.2187e-6], [4.0e5, 1.0e-3], [2.5e4, 0.1]]\n\
         [material.bulk]\nk_inf = 2.0e9\nterms = [[1.0e9, 1.0e-4]]\n",
    );
    let filed = scene(
        "[material.shear]\ng_inf = 1.0e4\nfile = \"tables/shear.csv\"\n\
         [material.bulk]\nk_inf = 2.0e9\nfile = \"tables/bulk.csv\"\n",
    );
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, &filed).unwrap();
    let a = Scene::parse(&inline).unwrap();
    let b = Scene::load(&path).unwrap();
    assert_eq!(a.impact, b.impact);
    let o = opts(SolverKind::Reference, 1e-6);
    assert_eq!(
        solve(&a.impact, &o).unwrap().cor,
        solve(&b.impact, &o).unwrap().cor
    );
    // a bad row names the file and its line
    std::fs::write(sub.join("shear.csv"), "tau,modulus\n1e-3,2e6\n1e-2,-5\n").unwrap();
    let e = Scene::load(&path).unwrap_err().to_string();
    assert!(e.contains("shear.csv:3") && e.contains("modulus"), "{e}");
    std::fs::write(sub.join("shear.csv"), "modulus,tau\n2e6,1e-3\n").unwrap();
    let e = Scene::load(&path).unwrap_err().to_string();
    assert!(
        e.contains("shear.csv:1") && e.contains("tau,modulus"),
        "{e}"
    );
    std::fs::remove_file(sub.join("shear.csv")).unwrap();
    let e = Scene::load(&path).unwrap_err().to_string();
    assert!(e.contains("shear.csv"), "{e}");
}

/// Bad Prony input: one-line errors naming the key (and the term), never a panic.
#[test]
fn bad_general_input_names_the_key() {
    let shear_ok = "[material.shear]\ng_inf = 1.0e6\nterms = [[1.0e7, 5.0e-5]]\n";
    let bulk_ok = "[material.bulk]\npoisson = 0.45\n";
    let cases: Vec<(String, &str)> = vec![
        // shear
        (
            format!("[material.shear]\nterms = []\n{bulk_ok}"),
            "[material.shear]: missing g_inf",
        ),
        (
            format!("[material.shear]\ng_inf = 1.0e6\n{bulk_ok}"),
            "[material.shear]: missing terms",
        ),
        (
            format!("[material.shear]\ng_inf = -1.0\nterms = []\n{bulk_ok}"),
            "[material.shear]: g_inf",
        ),
        (
            format!("[material.shear]\ng_inf = nan\nterms = []\n{bulk_ok}"),
            "[material.shear]: g_inf",
        ),
        (
            format!("[material.shear]\ng_inf = 1.0\nterms = [[1.0, 1.0], [-2.0, 1.0]]\n{bulk_ok}"),
            "[material.shear] terms: g_i[1] = -2e0",
        ),
        (
            format!("[material.shear]\ng_inf = 1.0\nterms = [[1.0, nan]]\n{bulk_ok}"),
            "[material.shear] terms: tau_i[0] = NaN",
        ),
        (
            format!("[material.shear]\ng_inf = 1.0\nterms = [[1.0, 0.0]]\n{bulk_ok}"),
            "[material.shear] terms: tau_i[0]",
        ),
        (
            format!("[material.shear]\ng_inf = 1.0\nterms = [[1.0, 1.0, 2.0]]\n{bulk_ok}"),
            "[material.shear] terms[0]: expected a pair",
        ),
        (
            format!("[material.shear]\ng_inf = 1.0\nterms = []\nfile = \"x.csv\"\n{bulk_ok}"),
            "[material.shear]: give either terms or file",
        ),
        (
            format!("[material.shear]\ng_inf = 1.0\nterms = []\nextra = 1\n{bulk_ok}"),
            "extra",
        ),
        // normalised form
        (
            format!("[material.shear]\ninstantaneous = 1.0e7\nratios = [[0.6, 1.0], [0.4, 2.0]]\n{bulk_ok}"),
            "[material.shear]: ratios = 1e0",
        ),
        (
            format!("[material.shear]\ninstantaneous = 1.0e7\nratios = [[1.5, 1.0]]\n{bulk_ok}"),
            "[material.shear] ratios: g_i[0]",
        ),
        (
            format!("[material.shear]\ninstantaneous = 1.0e7\nratios = [[0.5, -1.0]]\n{bulk_ok}"),
            "[material.shear] ratios: tau_i[0]",
        ),
        (
            format!("[material.shear]\ninstantaneous = 0.0\nratios = [[0.5, 1.0]]\n{bulk_ok}"),
            "[material.shear]: instantaneous",
        ),
        (
            format!("[material.shear]\nratios = [[0.5, 1.0]]\n{bulk_ok}"),
            "[material.shear]: missing instantaneous",
        ),
        (
            format!("[material.shear]\ng_inf = 1.0\ninstantaneous = 2.0\nratios = []\n{bulk_ok}"),
            "[material.shear]: instantaneous/ratios",
        ),
        // bulk
        (
            format!("{shear_ok}[material.bulk]\nk_inf = 0.0\nterms = [[1.0e9, 1.0e-4]]\n"),
            "[material.bulk]: k_inf",
        ),
        (
            format!("{shear_ok}[material.bulk]\nk_inf = -3.0\nterms = [[1.0e9, 1.0e-4]]\n"),
            "[material.bulk]: k_inf",
        ),
        (
            format!("{shear_ok}[material.bulk]\nk_inf = 1.0e9\nterms = []\n"),
            "[material.bulk]: no relaxing term (terms = [] or ratios = []): an elastic bulk is k_0",
        ),
        (
            format!("{shear_ok}[material.bulk]\nk_inf = 1.0e9\nterms = [[1.0e9, -1.0]]\n"),
            "[material.bulk] terms: theta_j[0]",
        ),
        (
            format!("{shear_ok}[material.bulk]\nterms = [[1.0e9, 1.0]]\n"),
            "[material.bulk]: missing k_inf",
        ),
        (
            format!("{shear_ok}[material.bulk]\ninstantaneous = 1.0e9\nratios = [[0.7, 1.0], [0.3, 2.0]]\n"),
            "[material.bulk]: ratios = 1e0",
        ),
        (
            format!("{shear_ok}[material.bulk]\npoisson = 0.45\nk_0 = 1.0e9\n"),
            "found k_0 and poisson",
        ),
        (
            format!("{shear_ok}[material.bulk]\nincompressible = true\nk_inf = 1.0e9\nterms = []\n"),
            "found incompressible and a relaxing bulk",
        ),
        (
            format!("{shear_ok}[material.bulk]\n"),
            "[material.bulk]: give exactly one",
        ),
        (
            format!("{shear_ok}[material.bulk]\nincompressible = false\n"),
            "[material.bulk] incompressible = false",
        ),
        (
            format!("{shear_ok}[material.bulk]\npoisson = 0.6\n"),
            "[material.bulk]: poisson",
        ),
        (
            format!("{shear_ok}[material.bulk]\nk_0 = -1.0\n"),
            "[material.bulk]: k_0",
        ),
        (format!("{shear_ok}[material.bulk]\nnu = 0.3\n"), "nu"),
        // mixing
        (
            format!("[material]\ng_inf = 1.0e6\n{shear_ok}{bulk_ok}"),
            "[material]: g_inf cannot be mixed",
        ),
        (
            format!("[material]\npoisson = 0.3\n{shear_ok}"),
            "[material]: poisson cannot be mixed",
        ),
        (shear_ok.to_string(), "[material]: missing [material.bulk]"),
        (bulk_ok.to_string(), "[material]: missing [material.shear]"),
        (
            "[material]\ng_1 = 1.0\neta = 1.0\npoisson = 0.3\n".to_string(),
            "[material]: missing g_inf",
        ),
    ];
    for (material, needle) in cases {
        let text = scene(&material);
        let e = match std::panic::catch_unwind(|| Scene::parse(&text)) {
            Ok(r) => r.expect_err(&material).to_string(),
            Err(_) => panic!("panicked on {material}"),
        };
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(
            e.contains(needle),
            "'{needle}' not in '{e}' for\n{material}"
        );
    }
}

/// The term errors carry the variant with the index.
#[test]
fn bad_term_is_a_prony_term_error() {
    let text = scene(
        "[material.shear]\ng_inf = 1.0\nterms = [[1.0, 1.0], [1.0, 2.0], [-1.0, 3.0]]\n\
         [material.bulk]\nincompressible = true\n",
    );
    let e = Scene::parse(&text).unwrap_err();
    assert!(
        matches!(e.root(), Error::PronyTerm { index: 2, .. }),
        "{e:?}"
    );
}

fn general_impact(terms: &[(f64, f64)], bulk: BulkInput) -> Impact {
    let shear = ShearProny::new(1.0e6, terms).unwrap();
    let m = Material::general(shear, bulk).unwrap();
    Impact::with_general(Sphere::new(4.11e-3, 5.0e-3).unwrap(), 0.99, m).unwrap()
}

/// `mdr-euler` runs the paper's explicit Euler on a general material's network and `mdr` on
/// the same network with its exponential scheme (tests/mdr_general.rs); an explicit resolution
/// means `mdr` for `auto` too.
#[test]
fn mdr_schemes_take_general_material() {
    let imp = general_impact(
        &[(0.5e7, 5.0e-5), (0.5e7, 5.0e-4)],
        BulkInput::Poisson(0.49),
    );
    assert_eq!(
        solve(&imp, &opts(SolverKind::MdrEuler, 1e-3))
            .unwrap()
            .solver,
        "mdr-euler"
    );
    assert_eq!(
        solve(&imp, &opts(SolverKind::Mdr, 1e-4)).unwrap().solver,
        "mdr"
    );
    // an explicit resolution means mdr for auto too
    let mut o = opts(SolverKind::Auto, 1e-4);
    o.resolution = Some(mdr_impact::Resolution {
        elements: 50,
        steps: 200,
    });
    assert_eq!(solve(&imp, &o).unwrap().solver, "mdr");
    // an elastic general material is Hertz whatever the solver
    let elastic = general_impact(&[], BulkInput::Poisson(0.3));
    let h = solve(&elastic, &opts(SolverKind::Mdr, 1e-4)).unwrap();
    assert_eq!((h.solver.name(), h.cor), ("hertz", 1.0));
}

/// A 10-term shear series (incompressible: `G_eq = G`, 10 terms) through `auto`: answered by
/// `fast` (up to `FAST_MAX_TERMS` = 128 terms; beyond that `auto` answers with `reference` and
/// says why), its estimate within rtol and its CoR within 2 rtol of `reference` at 1e-8.
#[test]
fn ten_terms_through_auto() {
    let terms: Vec<(f64, f64)> = (0..10)
        .map(|i| (2.0e6 / (1.0 + i as f64), 1.0e-7 * 10f64.powi(i)))
        .collect();
    let imp = general_impact(&terms, BulkInput::Incompressible);
    assert_eq!(imp.canonical_relaxation().terms.len(), 10);
    let rtol = 1e-6;
    let o = solve(&imp, &opts(SolverKind::Auto, rtol)).unwrap();
    if imp.canonical_relaxation().terms.len() > mdr_impact::solvers::fast::FAST_MAX_TERMS {
        assert_eq!(o.solver, "reference");
        let why = o.fallback.as_deref().unwrap();
        assert!(matches!(why, Error::TooManyTerms { .. }), "{why}");
    } else {
        assert_eq!(o.solver, "fast");
    }
    let est = o.cor_error_estimate.unwrap();
    assert!(est <= rtol, "{est:e}");
    assert!(o.cor > 0.0 && o.cor < 1.0);
    let r = solve(&imp, &opts(SolverKind::Reference, 1e-8)).unwrap();
    assert!(
        abs_rel_err(o.cor, r.cor) <= 2.0 * rtol,
        "{} vs {}",
        o.cor,
        r.cor
    );
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 64, ..Default::default() })]

    /// Random general materials through the public `solve` (1 to 40 shear terms with times over
    /// 20 decades, moduli over 6, every bulk form, SI sphere and speed over decades; `auto` and
    /// `reference` at random rtol): never a panic, and either a CoR in `(0, 1]` with finite
    /// outputs and an estimate within rtol, or a one-line error.
    #[test]
    fn random_general_materials_never_panic(
        g_inf in 3.0f64..9.0,
        shear in proptest::collection::vec((3.0f64..9.0, -12.0f64..8.0), 1..=40),
        kind in 0u8..4,
        bulk_scale in 4.0f64..11.0,
        nu in -0.9f64..0.5,
        bulk in proptest::collection::vec((3.0f64..9.0, -10.0f64..6.0), 1..=5),
        lv in -3.0f64..2.0,
        lrtol in -10.0f64..-3.0,
        reference in proptest::bool::ANY,
    ) {
        let p = |v: &[(f64, f64)]| -> Vec<(f64, f64)> {
            v.iter().map(|&(m, t)| (10f64.powf(m), 10f64.powf(t))).collect()
        };
        let shear = ShearProny::new(10f64.powf(g_inf), &p(&shear)).unwrap();
        let bulk = match kind {
            0 => BulkInput::Incompressible,
            1 => BulkInput::Elastic(10f64.powf(bulk_scale)),
            2 => BulkInput::Poisson(nu),
            _ => BulkInput::Prony(
                mdr_impact::model::material::BulkProny::new(10f64.powf(bulk_scale), &p(&bulk)).unwrap(),
            ),
        };
        let m = Material::general(shear, bulk).unwrap();
        let imp = Impact::with_general(Sphere::new(4.11e-3, 5e-3).unwrap(), 10f64.powf(lv), m)
            .unwrap();
        let rtol = 10f64.powf(lrtol);
        let solver = if reference { SolverKind::Reference } else { SolverKind::Auto };
        match solve(&imp, &opts(solver, rtol)) {
            Ok(o) => {
                proptest::prop_assert!(o.cor > 0.0 && o.cor <= 1.0, "CoR {}", o.cor);
                proptest::prop_assert!(o.contact_time.is_finite() && o.max_force.is_finite());
                if let Some(est) = o.cor_error_estimate {
                    proptest::prop_assert!(est <= rtol, "estimate {est:e} > rtol {rtol:e}");
                }
            }
            Err(e) => {
                let msg = e.to_string();
                proptest::prop_assert!(!msg.contains('\n') && !msg.is_empty(), "{msg:?}");
            }
        }
    }
}
