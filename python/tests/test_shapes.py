"""Indenter shapes from Python (docs/theory.md §11): the same numbers as `mdr-impact run --json`."""

import json

import pytest

import mdr_impact as mi

MATERIAL = dict(g_inf=1.0e6, g_1=1.0e7, eta=500.0, poisson=0.49)


@pytest.mark.parametrize(
    "scene_file, indenter, solver",
    [
        ("cone_indenter.toml", dict(shape="cone", half_angle_deg=70.3), "fast"),
        (
            "power_law_indenter.toml",
            dict(shape="power-law", exponent=3.0, coefficient=2.0e4),
            "fast",
        ),
        # no Ting phase: fast solves the flat punch by the modes of its linear ODE
        ("flat_punch.toml", dict(shape="flat", radius=1.0e-3), "fast"),
    ],
)
def test_indenter_objects_match_the_scene_and_the_cli(cli, root, scene_file, indenter, solver):
    path = root / "scenes" / scene_file
    loaded = mi.Scene.load(path)
    built = mi.Scene(
        velocity=0.99,
        indenter=mi.Indenter(4.11e-3, **indenter),
        material=mi.Material(**MATERIAL),
    )
    assert built.shape == loaded.shape == indenter["shape"]
    assert mi.Scene.from_toml(built.to_toml()) == built
    r = built.run()
    out = json.loads(cli("run", path, "--json").stdout)
    assert out["shape"] == indenter["shape"]
    assert r.cor == out["cor"] and r.max_contact_radius == out["max_contact_radius"]
    assert r.solver == out["solver"] == solver


def test_exact_sphere_profile_and_two_exact_spheres(cli, root):
    s = mi.Scene(
        velocity=8.0,
        sphere=mi.Sphere(4.11e-3, 5.0e-3, profile="sphere"),
        material=mi.Material(**MATERIAL),
    )
    assert s.shape == "sphere" and s.sphere.profile == "sphere"
    out = json.loads(cli("run", root / "scenes" / "exact_sphere.toml", "--json").stdout)
    assert s.run().cor == out["cor"]
    paraboloid = mi.Scene(
        velocity=8.0, sphere=mi.Sphere(4.11e-3, 5.0e-3), material=mi.Material(**MATERIAL)
    )
    # a/R = 0.64: the exact cap and Hertz's paraboloid differ by about 1 % in the CoR
    assert 0.005 < abs(s.run().cor / paraboloid.run().cor - 1) < 0.05
    pair = mi.Scene.load(root / "scenes" / "two_exact_spheres.toml")
    a, b = pair.bodies
    assert a.profile == b.profile == "sphere"
    assert mi.Scene.from_toml(pair.to_toml()) == pair


def test_shape_keys_are_checked():
    with pytest.raises(mi.Error, match="needs half_angle_deg"):
        mi.Indenter(1e-3, "cone")
    with pytest.raises(mi.Error, match="does not apply"):
        mi.Indenter(1e-3, "cone", half_angle_deg=70.0, radius=1e-3)
    with pytest.raises(mi.Error, match="half_angle_deg"):
        mi.Indenter(1e-3, "cone", half_angle_deg=95.0)
    with pytest.raises(mi.Error, match="profile"):
        mi.Sphere(1e-3, 1e-3, profile="cap")
