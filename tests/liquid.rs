//! Viscoelastic liquids, `g_inf = 0` (docs/theory.md §15): accepted by every solver and command,
//! scaled by the glassy modulus; checked against the other solvers (no shared code beyond the
//! material) and against the limit `g_inf -> 0+` of solids, whose scale is `g_inf`.

use crate::common;

use common::{abs_rel_err, opts, run, stderr};
use mdr_impact::io::scene::Scene;
use mdr_impact::model::material::{carson, poles, BulkInput, BulkProny, Material, ShearProny};
use mdr_impact::{solve, Error, Impact, SolverKind, Sphere};

/// A 4.11 g, 5 mm ball at `v0` on a Maxwell fluid (`g_inf`, `G_1 = 1e7` Pa, `eta` Pa s).
fn maxwell(g_inf: f64, eta: f64, v0: f64) -> Impact {
    let m = Material::incompressible(g_inf, 1.0e7, eta).unwrap();
    Impact::new(Sphere::new(4.11e-3, 5.0e-3).unwrap(), v0, m).unwrap()
}

fn cor(imp: &Impact, solver: SolverKind, rtol: f64) -> f64 {
    solve(imp, &opts(solver, rtol)).unwrap().cor
}

/// A liquid relaxing slowly against the contact (tau = 0.5 ms, contact 0.8 ms) and a faster
/// one: `fast`, `reference` and `mdr` agree within their tolerances, and `auto` is `fast`.
#[test]
fn maxwell_fluid_cor_agrees_across_solvers() {
    for eta in [5.0e3, 2.0e4, 5.0e4] {
        let imp = maxwell(0.0, eta, 0.99);
        assert!(imp.groups().is_none() && imp.target().relaxes_to_zero());
        let fast = cor(&imp, SolverKind::Fast, 1e-9);
        let reference = cor(&imp, SolverKind::Reference, 1e-9);
        let mdr = cor(&imp, SolverKind::Mdr, 1e-5);
        assert!(fast > 0.0 && fast < 1.0, "eta {eta}: {fast}");
        assert!(
            abs_rel_err(reference, fast) < 1e-8,
            "eta {eta}: {reference} {fast}"
        );
        assert!(abs_rel_err(mdr, fast) < 1e-5, "eta {eta}: {mdr} {fast}");
        assert_eq!(cor(&imp, SolverKind::Auto, 1e-9), fast);
    }
}

/// The CoR is continuous at `g_inf = 0`: solids of relaxed modulus `eps G_1` approach the
/// liquid's CoR, their distance shrinking in proportion to `eps`.
#[test]
fn cor_is_continuous_as_g_inf_shrinks() {
    let liquid = cor(&maxwell(0.0, 5.0e3, 0.99), SolverKind::Fast, 1e-10);
    let mut last = f64::INFINITY;
    for eps in [1e-3, 1e-4, 1e-5, 1e-6] {
        let solid = cor(&maxwell(eps * 1.0e7, 5.0e3, 0.99), SolverKind::Fast, 1e-10);
        let gap = abs_rel_err(solid, liquid);
        assert!(gap < 2.0 * eps && gap < last, "eps {eps}: gap {gap:e}");
        last = gap;
    }
    assert!(last < 1e-5, "{last:e}");
}

/// A liquid whose bulk relaxes to zero too (constant Poisson ratio in time, as `prony`
/// writes with `--nu`): `G_eq` relaxes to zero, and both routes to it (`carson`, `poles`) and
/// the solvers built on them agree.
#[test]
fn liquid_with_a_bulk_relaxing_to_zero() {
    let shear = [(4.0e6, 1.0e-4), (3.0e6, 1.0e-3), (1.0e6, 1.0e-2)];
    let f = 2.0 * 1.45 / (3.0 * 0.1); // nu = 0.45
    let bulk: Vec<(f64, f64)> = shear.iter().map(|&(g, t)| (g * f, t)).collect();
    let m = Material::general(
        ShearProny::new(0.0, &shear).unwrap(),
        BulkInput::Prony(BulkProny::new(0.0, &bulk).unwrap()),
    )
    .unwrap();
    let (a, b) = (
        carson::equivalent_relaxation(&m).unwrap(),
        poles::equivalent_relaxation(&m).unwrap(),
    );
    assert_eq!((a.relaxed, b.relaxed), (0.0, 0.0));
    // G_eq = G (3f + 1) / (3f + 4): the shear series scaled
    let k = (3.0 * f + 1.0) / (3.0 * f + 4.0);
    for t in [0.0, 1e-4, 1e-3, 1e-2, 0.1] {
        let g: f64 = shear.iter().map(|&(g, tau)| g * (-t / tau).exp()).sum();
        assert!(abs_rel_err(a.eval(t), k * g) < 1e-13, "t {t}");
        assert!(abs_rel_err(b.eval(t), k * g) < 1e-13, "t {t}");
    }
    let imp = Impact::new(Sphere::new(4.11e-3, 5.0e-3).unwrap(), 1.0, m).unwrap();
    let fast = cor(&imp, SolverKind::Fast, 1e-9);
    let reference = cor(&imp, SolverKind::Reference, 1e-9);
    assert!(abs_rel_err(reference, fast) < 1e-8, "{reference} {fast}");
}

/// Two bodies of which one or both are liquids.
#[test]
fn two_bodies_with_liquids() {
    for (ga, gb) in [(0.0, 1.0e6), (0.0, 0.0)] {
        let text = format!(
            "[impact]\nvelocity = 0.99\n\n\
             [[body]]\nradius = 5.0e-3\nmass = 4.11e-3\n[body.material]\ng_inf = {ga:?}\n\
             g_1 = 1.0e7\neta = 5000.0\npoisson = 0.5\n\n\
             [[body]]\nradius = 5.0e-3\nmass = 4.11e-3\n[body.material]\ng_inf = {gb:?}\n\
             g_1 = 1.0e7\neta = 5000.0\npoisson = 0.5\n"
        );
        let sc = Scene::parse(&text).unwrap();
        assert!(sc.impact.target().relaxes_to_zero());
        let fast = cor(&sc.impact, SolverKind::Fast, 1e-9);
        let reference = cor(&sc.impact, SolverKind::Reference, 1e-9);
        let mdr = cor(&sc.impact, SolverKind::Mdr, 1e-5);
        assert!(
            abs_rel_err(reference, fast) < 1e-8,
            "{ga} {gb}: {reference} {fast}"
        );
        assert!(abs_rel_err(mdr, fast) < 1e-5, "{ga} {gb}: {mdr} {fast}");
    }
}

/// What has no meaning is refused, naming the field: no modulus at all, and a static Poisson
/// ratio below 0.5 (it would give `K_0 = 0`).
#[test]
fn refusals_name_the_field() {
    let field = |r: Result<Material, Error>| match r {
        Err(Error::OutOfRange { field, .. }) => field,
        other => panic!("expected OutOfRange, got {other:?}"),
    };
    assert_eq!(field(Material::incompressible(0.0, 0.0, 1.0)), "g_inf");
    assert_eq!(field(Material::incompressible(0.0, 1.0, 0.0)), "g_inf");
    assert_eq!(field(Material::with_poisson(0.0, 1.0, 1.0, 0.3)), "nu");
    assert!(matches!(
        ShearProny::new(0.0, &[]),
        Err(Error::OutOfRange { field: "g_inf", .. })
    ));
    assert!(matches!(
        Material::general(
            ShearProny::new(0.0, &[(1.0, 1.0)]).unwrap(),
            BulkInput::Poisson(0.3)
        ),
        Err(Error::OutOfRange { field: "nu", .. })
    ));
    // a bulk relaxing to zero beside a solid shear: a relaxed Poisson ratio of -1
    let relaxing = || BulkInput::Prony(BulkProny::new(0.0, &[(1.0, 1.0)]).unwrap());
    assert!(matches!(
        Material::general(ShearProny::new(1.0, &[(1.0, 1.0)]).unwrap(), relaxing()),
        Err(Error::OutOfRange { field: "k_inf", .. })
    ));
    assert!(Material::general(ShearProny::new(0.0, &[(1.0, 1.0)]).unwrap(), relaxing()).is_ok());
    // the scene names the table and key
    let e = Scene::parse(
        "[sphere]\nmass = 1e-3\nradius = 1e-3\n[impact]\nvelocity = 1.0\n\
         [material.shear]\ng_inf = 0.0\nterms = []\n[material.bulk]\nincompressible = true\n",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("g_inf") && !e.contains('\n'), "{e}");
}

/// A solid whose relaxed modulus could not hold the sphere fails as a liquid does, and says so
/// (`g_inf = 1e-300` Pa beside `G_1 = 1e7` Pa gave only "Newton update is not finite (NaN)"):
/// the relaxed Hertz estimate `a_max/R` is named; a solid that holds it keeps the plain error.
#[test]
fn a_nearly_liquid_solid_that_fails_says_why() {
    for g_inf in [1e-300, 1e-100, 1e-20] {
        let e = solve(&maxwell(g_inf, 500.0, 0.99), &opts(SolverKind::Auto, 1e-6))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("a nearly liquid material: on its relaxed modulus alone the sphere would sink to a_max/R = "),
            "g_inf {g_inf}: {e}"
        );
        assert!(!e.contains('\n'), "{e}");
    }
    // still answered where a solver succeeds (g_inf = 1e-5 Pa: e near 0)
    let o = solve(&maxwell(1e-5, 500.0, 0.99), &opts(SolverKind::Auto, 1e-6)).unwrap();
    assert!(o.cor >= 0.0 && o.cor < 1e-3, "{}", o.cor);
}

const LIQUID_SCENE: &str = "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n\n[impact]\n\
    velocity = 0.99\n\n[material]\ng_inf = 0.0\ng_1 = 1.0e7\neta = 5000.0\npoisson = 0.5\n";

/// The commands: `run` says the relaxed limits do not apply, `curve` says so for its relaxed
/// limit, `dem --modulus relaxed` is refused in one line and `glassy`/`fit` answer; no output
/// prints NaN or inf.
#[test]
fn commands_accept_a_liquid_and_say_what_does_not_apply() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("liquid.toml"), LIQUID_SCENE).unwrap();
    let clean = |o: &std::process::Output| {
        let text = String::from_utf8_lossy(&o.stdout).to_lowercase();
        assert!(o.status.success(), "{}", stderr(o));
        let number = |w: &str| ["nan", "inf", "-inf"].contains(&w);
        assert!(
            !text
                .split(|c: char| c.is_whitespace() || c == ',')
                .any(number),
            "{text}"
        );
        text
    };
    let text = clean(&run(&["run", "liquid.toml"], dir.path()));
    assert!(
        text.contains("relaxed limits") && text.contains("do not apply"),
        "{text}"
    );
    assert!(!text.contains("groups (eq. 11)"), "{text}");
    let text = clean(&run(
        &["curve", "liquid.toml", "--v0", "0.5:2:3", "--out", "c"],
        dir.path(),
    ));
    assert!(text.contains("does not apply"), "{text}");
    let o = run(
        &[
            "dem",
            "liquid.toml",
            "--v0",
            "0.5:2:3",
            "--format",
            "json",
            "--modulus",
            "relaxed",
            "--out",
            "d",
        ],
        dir.path(),
    );
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("g_inf = 0") && e.trim().lines().count() == 1,
        "{e}"
    );
    assert!(!dir.path().join("d").exists());
    for modulus in ["glassy", "fit"] {
        clean(&run(
            &[
                "dem",
                "liquid.toml",
                "--v0",
                "0.5:2:3",
                "--format",
                "json",
                "--modulus",
                modulus,
                "--out",
                modulus,
            ],
            dir.path(),
        ));
    }
    let o = run(
        &[
            "indent",
            "--scene",
            "liquid.toml",
            "--history",
            "triangle",
            "--rate",
            "1e-3",
            "--peak-time",
            "1e-3",
        ],
        dir.path(),
    );
    clean(&o);
}

/// `prony` on the moduli of a Maxwell liquid (three terms, no plateau) finds `g_inf = 0`, and
/// its `material.toml` (with `--nu`, a bulk relaxing to zero) runs.
#[test]
fn prony_of_a_liquid_runs() {
    let dir = tempfile::tempdir().unwrap();
    let mut csv = String::from("frequency,storage,loss\n");
    let terms = [(5.0e6, 1.0e-4), (3.0e6, 1.0e-3), (1.0e6, 1.0e-2)];
    for i in 0..41 {
        let f = 10f64.powf(-1.0 + 0.15 * i as f64);
        let w = 2.0 * std::f64::consts::PI * f;
        let (s, l) = terms.iter().fold((0.0, 0.0), |(s, l), &(g, t)| {
            let x = w * t;
            (s + g * x * x / (1.0 + x * x), l + g * x / (1.0 + x * x))
        });
        csv.push_str(&format!("{f:e},{s:e},{l:e}\n"));
    }
    std::fs::write(dir.path().join("maxwell.csv"), csv).unwrap();
    let o = run(
        &[
            "prony",
            "maxwell.csv",
            "--nu",
            "0.45",
            "--out",
            "p",
            "--json",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["g_inf"].as_f64(), Some(0.0));
    let material = std::fs::read_to_string(dir.path().join("p/material.toml")).unwrap();
    let sc = Scene::parse(&format!(
        "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n[impact]\nvelocity = 1.0\n{material}"
    ))
    .unwrap();
    let fast = cor(&sc.impact, SolverKind::Fast, 1e-8);
    let reference = cor(&sc.impact, SolverKind::Reference, 1e-8);
    assert!(
        fast > 0.0 && abs_rel_err(reference, fast) < 1e-7,
        "{reference} {fast}"
    );
}
