"""Materials, bodies and scenes as Python objects; TOML round trips; results and histories."""

import doctest

import numpy as np
import pytest

import mdr_impact as mi


def test_default_scene_and_impact_of_a_material_agree():
    scene = mi.Scene.default()
    assert scene.velocity == 0.99 and scene.sphere.mass == 4.11e-3
    m = scene.material
    assert isinstance(m, mi.Material)
    assert (m.g_inf, m.g_1, m.eta) == (1.0e6, 1.0e7, 500.0)
    assert abs(m.poisson - 0.49) < 1e-15
    r = mi.impact(m, mass=4.11e-3, radius=5.0e-3, velocity=0.99)
    assert r.cor == scene.run(history=False).cor
    assert r.history is None
    assert 0 < r.cor < 1 and r.contact_time > 0 and r.max_force > 0


def test_histories_as_arrays():
    r = mi.Scene.default().run(history=True)
    h = r.history
    assert set(h) == {"t", "d", "v", "force", "a"}
    n = h["t"].size
    assert n > 100 and all(a.shape == (n,) for a in h.values())
    assert np.all(np.diff(h["t"]) > 0)
    assert np.isclose(h["force"].max(), r.max_force, rtol=1e-3)
    assert np.isclose(-h["v"][-1] / h["v"][0], r.cor, rtol=1e-3)
    # the default scene has no [output]: like `mdr-impact run`, it computes no history
    assert mi.Scene.default().run().history is None


def test_general_material_objects():
    shear = mi.Prony(1.0e3, [(2.0e5, 1e-3), (1.0e7, 1e-6), (0.0, 1.0)])
    g = mi.GeneralMaterial(shear, incompressible=True)
    assert g.bulk_kind == "incompressible" and g.k_0 == np.inf and g.bulk is None
    # normalised: sorted by time, zero modulus dropped
    assert np.array_equal(g.shear.terms, [[1.0e7, 1e-6], [2.0e5, 1e-3]])
    geq = g.equivalent_relaxation()
    assert geq(0.0) == pytest.approx(1.0e3 + 1.0e7 + 2.0e5, rel=1e-12)
    assert geq(np.array([0.0, 1e9])).shape == (2,)
    assert geq(1e9) == pytest.approx(1.0e3, rel=1e-12)
    bulk = mi.Prony(2.0e9, [[1.0e9, 1e-4]])
    g2 = mi.GeneralMaterial(shear, bulk=bulk)
    assert g2.bulk_kind == "prony" and g2.bulk == bulk and g2.k_0 == 2.0e9
    # the standard solid as its one-term case gives the same impact
    m = mi.Material(1.0e6, 1.0e7, 500.0, poisson=0.49)
    a = mi.impact(m, mass=4.11e-3, radius=5e-3, velocity=0.99)
    b = mi.impact(m.general(), mass=4.11e-3, radius=5e-3, velocity=0.99)
    assert abs(a.cor - b.cor) <= 1e-12 * a.cor


def test_two_bodies_from_python_objects():
    a = mi.Body(radius=1e-2, density=1100.0,
                material=mi.Material(1.0e6, 1.0e7, 500.0, poisson=0.49))
    wall = mi.Body(radius=np.inf, mass=np.inf, rigid=True)
    s = mi.Scene(bodies=(a, wall), velocity=1.0)
    assert s.material is None and s.bodies[1].rigid and s.bodies[0].material == a.material
    r = s.run()
    assert r.bodies["b"] == 0.0 and r.bodies["a"] == pytest.approx(-r.cor * 1.0)
    # a rigid wall is the one-sphere impact
    one = mi.Scene(sphere=mi.Sphere(a.mass, a.radius), material=a.material, velocity=1.0)
    assert one.run().cor == r.cor


def test_scene_round_trips(root, tmp_path):
    shipped = [mi.Scene.load(p) for p in sorted((root / "scenes").glob("*.toml"))]
    assert len(shipped) >= 2
    for scene in [mi.Scene.default(), *shipped]:
        back = mi.Scene.from_toml(scene.to_toml())
        assert back == scene
        assert back.run(history=False).cor == scene.run(history=False).cor
    shear = mi.Prony(5.0e6, [(2.0e7, 1e-6), (3.0e7, 1e-5)])
    built = mi.Scene(
        bodies=(mi.Body(radius=2e-2, mass=1e-2, material=mi.GeneralMaterial(shear, k_0=1e9)),
                mi.Body(radius=1e-2, mass=5e-3,
                        material=mi.Material(1e6, 1e7, 500.0, k_0=5e7))),
        velocity=2.0, solver="mdr", rtol=1e-4, history_csv=str(tmp_path / "out" / "h.csv"))
    path = tmp_path / "built.toml"
    built.save(path)
    loaded = mi.Scene.load(path)
    assert loaded == built
    assert loaded.solver == "mdr" and loaded.rtol == 1e-4
    assert loaded.history_csv == tmp_path / "out" / "h.csv"
    assert loaded.with_solver(solver="fast") != loaded
    assert loaded.with_velocity(3.0).velocity == 3.0


def test_to_toml_keeps_a_poisson_ratio_as_given():
    """A bulk given as a Poisson ratio comes back as that ratio, not as the k_0 it gives."""
    m = mi.Material(1.0e6, 1.0e7, 500.0, poisson=0.49)
    scene = mi.Scene(sphere=mi.Sphere(4.11e-3, 5e-3), material=m, velocity=0.99)
    text = scene.to_toml()
    assert "\npoisson = 0.49 " in text and "k_0" not in text
    assert mi.Scene.from_toml(text) == scene
    assert "\npoisson = 0.49 " in mi.Scene.default().to_toml()
    general = mi.GeneralMaterial(mi.Prony(1e6, [(1e7, 5e-5)]), poisson=0.3)
    text = mi.Scene(sphere=mi.Sphere(1e-3, 1e-3), material=general, velocity=1.0).to_toml()
    assert "[material.bulk]\npoisson = 0.3 " in text
    text = mi.Scene(sphere=mi.Sphere(1e-3, 1e-3), material=mi.Material(1e6, 1e7, 500.0, k_0=5e7),
                    velocity=1.0).to_toml()
    assert "k_0 = 50000000.0 " in text and "poisson" not in text


def test_prony_table_files_are_relative_to_the_scene(tmp_path):
    (tmp_path / "g.csv").write_text("tau,modulus\n1e-6,1e7\n1e-3,2e5\n")
    (tmp_path / "s.toml").write_text(
        "[sphere]\nmass = 1e-3\nradius = 1e-3\n[impact]\nvelocity = 1.0\n"
        "[material.shear]\ng_inf = 1e3\nfile = \"g.csv\"\n[material.bulk]\nk_0 = 1e9\n")
    s = mi.Scene.load(tmp_path / "s.toml")
    assert np.array_equal(s.material.shear.terms, [[1e7, 1e-6], [2e5, 1e-3]])
    assert mi.Scene.from_toml((tmp_path / "s.toml").read_text(), base=tmp_path) == s


@pytest.mark.parametrize("make,message", [
    (lambda: mi.Material(1e6, 1e7, 500.0), "missing poisson"),
    (lambda: mi.Material(1e6, 1e7, 500.0, poisson=0.3, k_0=1e9), "not both"),
    (lambda: mi.Material(-1.0, 1e7, 500.0, poisson=0.3), "g_inf = -1e0 is out of range"),
    (lambda: mi.GeneralMaterial(mi.Prony(1.0, [(1.0, 1.0), (-1.0, 2.0)]), k_0=1.0),
     r"g_i\[1\] = -1e0 is out of range"),
    (lambda: mi.GeneralMaterial(mi.Prony(1.0), k_0=1.0, poisson=0.3), "exactly one bulk"),
    (lambda: mi.GeneralMaterial(mi.Prony(1.0), bulk=mi.Prony(1.0, [(1.0, 0.0)])),
     r"theta_j\[0\] = 0e0 is out of range"),
    (lambda: mi.Sphere(0.0, 1.0), "mass = 0e0 is out of range"),
    (lambda: mi.Body(radius=1.0, mass=1.0, density=1.0, rigid=True), "not both"),
    (lambda: mi.Body(radius=-1.0, mass=1.0, rigid=True), "^radius = -1e0 is out of range"),
    (lambda: mi.Scene(velocity=1.0), "give sphere and material"),
    (lambda: mi.Scene(velocity=0.0, sphere=mi.Sphere(1, 1),
                      material=mi.Material(1, 1, 1, poisson=0.3)), "velocity = 0e0"),
    (lambda: mi.Scene(velocity=1.0, bodies=(mi.Body(radius=1, mass=1, rigid=True),
                                            mi.Body(radius=1, mass=1, rigid=True))),
     "both bodies are rigid"),
    (lambda: mi.Scene.from_toml("[impact]\nvelocity = 1\n"), "^scene: missing \\[sphere\\]"),
    (lambda: mi.Scene.from_toml(mi.DEFAULT_SCENE.replace("rtol = 1e-6", "rtol = nan")),
     "rtol = NaN is out of range"),
    (lambda: mi.Scene.default().with_velocity(float("inf")), "velocity = inf"),
    (lambda: mi.Scene.default().with_solver(rtol=0.5), "rtol = 5e-1"),
])
def test_bad_objects_raise_value_error(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_wrong_types_raise_type_error():
    with pytest.raises(TypeError):
        mi.Body(radius=1.0, mass=1.0, material="rubber")
    with pytest.raises(TypeError):
        mi.curve("default", [1.0])


def test_curve_shapes_and_errors():
    scene = mi.Scene.default()
    v = np.logspace(-2, 1, 6).reshape(2, 3)
    c = mi.curve(scene, v)
    assert c.cor.shape == (2, 3) and np.array_equal(c.v0, v)
    for idx in np.ndindex(v.shape):
        assert c.cor[idx] == scene.with_velocity(v[idx]).run(history=False).cor
    assert c.limits["p3_unit_velocity"] > 0 and c.limits["relaxed_crossover"] is None
    with pytest.raises(mi.Error, match=r"^index \(1,\): at v0 = -1e0 m/s: velocity = -1e0"):
        mi.curve(scene, [1.0, -1.0])


def test_docstring_examples():
    failures, tried = doctest.testmod(mi, verbose=False)
    assert tried > 0 and failures == 0


def test_every_public_name_has_its_own_docstring():
    """help() says what each public function, class, method and attribute is (with units)."""
    import inspect
    missing = []
    for name in mi.__all__:
        obj = getattr(mi, name)
        if not callable(obj):
            continue
        if not (obj.__doc__ or "").strip():
            missing.append(name)
        if inspect.isclass(obj) and not issubclass(obj, Exception):
            for k, v in vars(obj).items():
                if k.startswith("_"):  # slots (__call__, ...) are in the class's docstring
                    continue
                doc = inspect.getdoc(getattr(obj, k)) or ""
                if not doc.strip():
                    missing.append(f"{name}.{k}")
    assert missing == []


def test_validity_and_warnings_as_run_json():
    """An answer says when the model does not apply, as `run --json` does."""
    inside = mi.Scene.default().with_velocity(1.0).run(history=False)
    assert inside.warnings == []
    v = inside.validity
    assert abs(v["contact_radius_ratio"] - inside.max_contact_radius / 5.0e-3) < 1e-12
    assert v["wave_transit_ratio"] is None
    outside = mi.Scene.default().with_velocity(100.0).run(history=False)
    assert len(outside.warnings) == 1 and "a_max/R" in outside.warnings[0]
    c = mi.curve(mi.Scene.default(), np.array([0.1, 1.0, 100.0]))
    assert c.contact_radius_ratio.shape == (3,)
    assert list(c.outside_validity) == [False, False, True]
    assert np.all(np.diff(c.indentation_ratio) > 0)
    assert np.all(np.isnan(c.wave_transit_ratio))


def test_curve_wave_transit_ratio_with_a_density(tmp_path):
    """With a density the curve carries the quasi-static measure of every velocity."""
    path = tmp_path / "dense.toml"
    path.write_text(
        "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n[impact]\nvelocity = 1.0\n"
        "[material]\ng_inf = 1.0e6\ng_1 = 1.0e7\neta = 500.0\npoisson = 0.45\n"
        "density = 1100.0\n"
    )
    scene = mi.Scene.load(str(path))
    v = np.array([0.1, 1.0])
    c = mi.curve(scene, v)
    for i, v0 in enumerate(v):
        one = scene.with_velocity(float(v0)).run(history=False)
        assert c.wave_transit_ratio[i] == one.validity["wave_transit_ratio"]
