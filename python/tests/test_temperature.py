"""Temperature in Python scenes (a material's ``shift=``, ``Scene(temperature=)``) equals the
scene file's ``[material.shift]`` and ``[impact] temperature`` bit for bit, through the library
and through ``mdr-impact run --json``; viscoelastic liquids (``g_inf = 0``) run as on the
command line."""

import json

import pytest

import mdr_impact as mi

SHEAR = [(5.0e6, 1.0e-5), (2.0e6, 1.0e-3)]


def _toml(shift_line, temperature, g_inf=1.0e6):
    t = "" if temperature is None else f"temperature = {temperature!r}\n"
    return (
        "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n\n"
        f"[impact]\nvelocity = 1.0\n{t}\n"
        f"[material.shear]\ng_inf = {g_inf!r}\n"
        f"terms = [[{SHEAR[0][0]!r}, {SHEAR[0][1]!r}], [{SHEAR[1][0]!r}, {SHEAR[1][1]!r}]]\n\n"
        "[material.bulk]\nk_inf = 1.0e9\nterms = [[5.0e8, 3.0e-5]]\n\n"
        f"[material.shift]\n{shift_line}\n"
    )


def _material(shift, g_inf=1.0e6):
    return mi.GeneralMaterial(
        mi.Prony(g_inf, SHEAR), bulk=mi.Prony(1.0e9, [(5.0e8, 3.0e-5)]), shift=shift
    )


LAWS = [
    (mi.Shift.wlf(8.86, 101.6, 25.0), "wlf = { c1 = 8.86, c2 = 101.6, t_ref = 25.0 }"),
    (
        mi.Shift.arrhenius(2.0e5, 25.0),
        "arrhenius = { activation_energy = 2.0e5, t_ref = 25.0 }",
    ),
]


@pytest.mark.parametrize("law,line", LAWS)
@pytest.mark.parametrize("temperature", [None, -10.0, 25.0, 60.0])
def test_shift_equals_the_scene_file_and_the_command(law, line, temperature, tmp_path, cli):
    sphere = mi.Sphere(4.11e-3, 5.0e-3)
    py = mi.Scene(sphere=sphere, material=_material(law), velocity=1.0, temperature=temperature)
    text = _toml(line, temperature)
    from_file = mi.Scene.from_toml(text)
    assert py.temperature == from_file.temperature == temperature
    assert py.shifts == from_file.shifts
    (tag, log10_a), = py.shifts
    assert tag == "[material]"
    assert log10_a == law.log10_a(25.0 if temperature is None else temperature)
    r = py.run(history=False)
    assert r.cor == from_file.run(history=False).cor
    path = tmp_path / "scene.toml"
    path.write_text(text)
    out = json.loads(cli("run", str(path), "--json").stdout)
    assert r.cor == out["cor"] and r.contact_time == out["contact_time"]


def test_shift_equals_the_hand_shifted_series():
    """At T the shifted material is the series with every time times a_T, to the last bit."""
    law = mi.Shift.wlf(8.86, 101.6, 25.0)
    a = 10.0 ** law.log10_a(0.0)
    sphere = mi.Sphere(4.11e-3, 5.0e-3)
    shifted = mi.Scene(sphere=sphere, material=_material(law), velocity=1.0, temperature=0.0)
    hand = mi.GeneralMaterial(
        mi.Prony(1.0e6, [(g, t * a) for g, t in SHEAR]),
        bulk=mi.Prony(1.0e9, [(5.0e8, 3.0e-5 * a)]),
    )
    plain = mi.Scene(sphere=sphere, material=hand, velocity=1.0)
    assert shifted.run(history=False).cor == plain.run(history=False).cor


def test_bodies_carry_their_shift(tmp_path, cli):
    law, line = LAWS[0]
    a = mi.Body(radius=5.0e-3, mass=4.11e-3, material=_material(law))
    b = mi.Body(radius=float("inf"), mass=float("inf"), rigid=True)
    py = mi.Scene(bodies=(a, b), velocity=1.0, temperature=10.0)
    assert [s[0] for s in py.shifts] == ["[[body]] A [body.material]"]
    text = (
        "[impact]\nvelocity = 1.0\ntemperature = 10.0\n\n"
        "[[body]]\nradius = 5.0e-3\nmass = 4.11e-3\n[body.material.shear]\ng_inf = 1.0e6\n"
        f"terms = [[{SHEAR[0][0]!r}, {SHEAR[0][1]!r}], [{SHEAR[1][0]!r}, {SHEAR[1][1]!r}]]\n"
        "[body.material.bulk]\nk_inf = 1.0e9\nterms = [[5.0e8, 3.0e-5]]\n"
        f"[body.material.shift]\n{line}\n\n"
        "[[body]]\nradius = inf\nmass = inf\nrigid = true\n"
    )
    path = tmp_path / "two.toml"
    path.write_text(text)
    out = json.loads(cli("run", str(path), "--json").stdout)
    assert py.run(history=False).cor == out["cor"]


def test_temperature_errors_name_the_key():
    sphere = mi.Sphere(4.11e-3, 5.0e-3)
    with pytest.raises(mi.Error, match="temperature"):
        mi.Scene(sphere=sphere, material=_material(None), velocity=1.0, temperature=10.0)
    # at or below t_ref - c2 the WLF law has no meaning
    with pytest.raises(mi.Error, match="shift"):
        mi.Scene(
            sphere=sphere, material=_material(LAWS[0][0]), velocity=1.0, temperature=-80.0
        )
    with pytest.raises(mi.Error, match="c1"):
        mi.Shift.wlf(-1.0, 101.6, 25.0)


def test_a_liquid_runs_as_on_the_command_line(tmp_path, cli):
    """g_inf = 0: a Maxwell fluid as Material and as GeneralMaterial, equal to `run --json`."""
    sphere = mi.Sphere(4.11e-3, 5.0e-3)
    maxwell = mi.Material(0.0, 1.0e7, 5000.0, poisson=0.5)
    assert maxwell.g_inf == 0.0 and maxwell.tau == 5000.0 / 1.0e7
    scene = mi.Scene(sphere=sphere, material=maxwell, velocity=0.99)
    assert scene.groups is None
    r = scene.run(history=False)
    general = mi.GeneralMaterial(mi.Prony(0.0, [(1.0e7, 5.0e-4)]), incompressible=True)
    assert mi.Scene(sphere=sphere, material=general, velocity=0.99).run(history=False).cor == r.cor
    path = tmp_path / "liquid.toml"
    path.write_text(
        "[sphere]\nmass = 4.11e-3\nradius = 5.0e-3\n[impact]\nvelocity = 0.99\n"
        "[material]\ng_inf = 0.0\ng_1 = 1.0e7\neta = 5000.0\npoisson = 0.5\n"
    )
    out = json.loads(cli("run", str(path), "--json").stdout)
    assert r.cor == out["cor"] and 0.0 < r.cor < 1.0
    with pytest.raises(mi.Error, match="nu"):
        mi.Material(0.0, 1.0e7, 5000.0, poisson=0.3)
    with pytest.raises(mi.Error, match="g_inf"):
        mi.GeneralMaterial(mi.Prony(0.0, []), incompressible=True)


def test_a_temperature_outside_the_calibrated_range_is_warned(tmp_path, cli):
    """``calibrated=`` as the scene file's ``calibrated``: outside it the answer carries the same
    warning as ``run --json``; inside it none."""
    law = mi.Shift.wlf(8.86, 101.6, 25.0, calibrated=(-20.0, 80.0))
    assert law.calibrated == (-20.0, 80.0)
    assert "calibrated=(-20.0, 80.0)" in repr(law)
    sphere = mi.Sphere(4.11e-3, 5.0e-3)
    line = "wlf = { c1 = 8.86, c2 = 101.6, t_ref = 25.0 }\ncalibrated = [-20.0, 80.0]"
    for t, warned in [(100.0, True), (0.0, False)]:
        r = mi.Scene(sphere=sphere, material=_material(law), velocity=1.0, temperature=t).run(
            history=False
        )
        path = tmp_path / "scene.toml"
        path.write_text(_toml(line, t))
        out = json.loads(cli("run", str(path), "--json").stdout)
        assert r.warnings == out["warnings"] and r.cor == out["cor"]
        assert any("calibrated on" in w for w in r.warnings) == warned
    with pytest.raises(mi.Error, match="calibrated"):
        mi.Shift.arrhenius(2.0e5, 25.0, calibrated=(80.0, -20.0))
