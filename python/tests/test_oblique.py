"""Oblique impacts (docs/theory.md §14) from Python: the same numbers as `run --json` and
`curve --angle`, and the exact gross-slip limit."""

import csv
import io
import json

import numpy as np
import pytest

import mdr_impact as mi

KEYS = ["tangential_cor", "tangential_cor_centre", "spin_after", "rebound_angle_deg",
        "contact_patch_rebound_angle_deg", "friction_dissipated_energy"]


def test_oblique_matches_run_json(cli, root):
    path = root / "scenes" / "oblique_elastomer.toml"
    js = json.loads(cli("run", path, "--json").stdout)
    o = mi.oblique(mi.Scene.load(path))
    assert o["solver"] == js["solver"] == "mdr"
    assert o["cor"] == js["cor"]
    for k in KEYS:
        assert o[k] == js[k], k
    assert mi.Scene.load(path).run().cor == js["cor"]


def test_gross_slip_is_exact():
    # v_c = 5 m/s is far above (1 + 1/0.4) mu (1 + e) v_n for mu = 0.1 and v_n = 0.99 m/s
    o = mi.oblique(mi.Scene.default(), friction=0.1, tangential_velocity=5.0)
    dv = 5.0 * (1.0 - o["tangential_cor"])
    exact = 3.5 * 0.1 * (1.0 + o["cor"]) * 0.99
    assert dv == pytest.approx(exact, rel=1e-10)


def test_frictionless_is_the_normal_impact():
    s = mi.Scene.default()
    o = mi.oblique(s, friction=0.0, tangential_velocity=0.5)
    assert o["cor"] == s.run().cor
    assert o["tangential_cor"] == 1.0


def test_angle_curve_matches_cli(cli, root, tmp_path):
    path = root / "scenes" / "oblique_elastomer.toml"
    cli("curve", path, "--angle", "10:50:3", "--speed", "1.2", "--out", tmp_path)
    text = (tmp_path / "curve.csv").read_text()
    rows = list(csv.DictReader(io.StringIO(text)))
    c = mi.angle_curve(mi.Scene.load(path), [10.0, 30.0, 50.0], 1.2)
    assert list(rows[0].keys()) == ["angle_deg", "cor", "tangential_cor",
                                    "tangential_cor_centre", "rebound_angle_deg",
                                    "contact_patch_rebound_angle_deg", "spin_after"]
    for i, r in enumerate(rows):
        for k, v in r.items():
            assert float(v) == c[k][i], (k, i)
    assert np.all(np.diff(c["angle_deg"]) > 0)


def test_bad_inputs_raise():
    with pytest.raises(mi.Error, match="inertia_factor"):
        mi.oblique(mi.Scene.default(), friction=0.1, tangential_velocity=1.0, inertia_factor=2.0)
    with pytest.raises(mi.Error, match="angle"):
        mi.angle_curve(mi.Scene.default(), [95.0], 1.0, friction=0.1)
