//! `Scene::to_toml`: every kind of scene written back as TOML parses to an equal scene (bit for
//! bit), and the written scene solves to the same CoR.

use mdr_impact::io::scene::Scene;
use mdr_impact::solve;

fn round_trip(scene: &Scene) -> Scene {
    let text = scene.to_toml();
    let back = Scene::parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(&back, scene, "{text}");
    // written twice: the same text
    assert_eq!(back.to_toml(), text);
    back
}

#[test]
fn default_and_two_body_scenes_round_trip() {
    round_trip(&Scene::default_scene());
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/two_spheres.toml");
    let two = Scene::load(std::path::Path::new(dir)).expect("two_spheres.toml");
    let back = round_trip(&two);
    let (a, b) = (
        solve(&two.impact, &two.options).expect("solve"),
        solve(&back.impact, &back.options).expect("solve"),
    );
    assert_eq!(a.cor, b.cor);
}

#[test]
fn every_material_and_solver_form_round_trips() {
    let scenes = [
        // incompressible standard solid, explicit resolution, outputs with a quote in the path
        r#"
[sphere]
mass = 1e-3
radius = 2e-3
[impact]
velocity = 0.5
[material]
g_inf = 1e6
g_1 = 3e6
eta = 10.0
poisson = 0.5
[solver]
name = "mdr"
elements = 40
steps = 400
[output]
history = "out/a \"b\".csv"
plot = "out/f.svg"
"#,
        // general material, normalised FE form in shear, relaxing bulk in ratios
        r#"
[sphere]
mass = 2.5
radius = 0.1
[impact]
velocity = 3.0
[material.shear]
instantaneous = 1e7
ratios = [[0.3, 1e-4], [0.5, 1e-2]]
[material.bulk]
instantaneous = 5e8
ratios = [[0.2, 1e-3]]
[solver]
name = "fast"
rtol = 1e-8
"#,
        // general material, elastic bulk from a Poisson ratio, unsorted duplicate terms
        r#"
[sphere]
mass = 1.0
radius = 1.0
[impact]
velocity = 1.0
[material.shear]
g_inf = 1.0
terms = [[5.0, 10.0], [2.0, 0.1], [3.0, 10.0]]
[material.bulk]
poisson = 0.3
"#,
        // a sphere against a rigid wall, incompressible general bulk
        r#"
[impact]
velocity = 1.5
[[body]]
mass = 0.01
radius = 0.02
[body.material.shear]
g_inf = 2e6
terms = [[1e7, 1e-5]]
[body.material.bulk]
incompressible = true
[[body]]
mass = inf
radius = inf
rigid = true
"#,
    ];
    for text in scenes {
        let scene = Scene::parse(text).unwrap_or_else(|e| panic!("{e}\n{text}"));
        round_trip(&scene);
    }
}

/// A bulk given as a Poisson ratio is written back as that ratio, not as the `k_0` computed from
/// it (issue 27); one given as a modulus stays a modulus.
#[test]
fn a_poisson_ratio_is_written_back_as_given() {
    let default = Scene::default_scene(); // [material] poisson = 0.49
    let text = round_trip(&default).to_toml();
    assert!(text.contains("\npoisson = 0.49 "), "{text}");
    assert!(!text.contains("k_0"), "{text}");

    let general = Scene::parse(
        "[sphere]\nmass = 1.0\nradius = 1.0\n[impact]\nvelocity = 1.0\n\
         [material.shear]\ng_inf = 1.0\nterms = [[5.0, 10.0]]\n[material.bulk]\npoisson = 0.3\n",
    )
    .unwrap();
    let text = round_trip(&general).to_toml();
    assert!(text.contains("[material.bulk]\npoisson = 0.3 "), "{text}");

    let modulus = Scene::default_scene()
        .to_toml()
        .replace("poisson = 0.49", "k_0 = 5e7");
    let text = round_trip(&Scene::parse(&modulus).unwrap()).to_toml();
    assert!(
        text.contains("k_0 = 50000000.0 ") && !text.contains("poisson"),
        "{text}"
    );
}
