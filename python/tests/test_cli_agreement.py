"""The package answers exactly what the command line answers (the same library underneath)."""

import csv
import io
import json
import pathlib

import numpy as np
import pytest

import mdr_impact as mi


def _csv_rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_catalogue_cor_input_bit_for_bit(cli, tmp_path):
    cases = mi.catalogue()
    assert len(cases) > 0
    path = tmp_path / "groups.csv"
    path.write_text("nu,p2,p3\n" + "".join(f"{c['nu']!r},{c['p2']!r},{c['p3']!r}\n"
                                           for c in cases))
    rows = _csv_rows(cli("cor", "--input", path).stdout)
    assert len(rows) == len(cases)
    nu, p2, p3 = (np.array([c[k] for c in cases]) for k in ("nu", "p2", "p3"))
    e, t, d = mi.cor(nu, p2, p3, full_output=True)
    for i, r in enumerate(rows):
        assert float(r["cor"]) == e[i], cases[i]["id"]
        assert float(r["contact_time_canonical"]) == t[i], cases[i]["id"]
        assert float(r["max_indentation_canonical"]) == d[i], cases[i]["id"]


@pytest.mark.parametrize("solver,rtol", [("auto", 1e-6), ("fast", 1e-9), ("reference", 1e-6),
                                         ("mdr", 1e-3)])
def test_single_cor_matches_cli(cli, solver, rtol):
    for c in mi.catalogue()[3:6]:
        out = cli("cor", "--nu", c["nu"], "--p2", c["p2"], "--p3", c["p3"], "--solver", solver,
                  "--rtol", rtol).stdout
        assert float(out.strip().splitlines()[-1]) == mi.cor(c["nu"], c["p2"], c["p3"],
                                                             rtol=rtol, solver=solver)


def _same_outcome(js, r):
    for key in ("cor", "rebound_velocity", "contact_time", "max_indentation",
                "time_of_max_indentation", "max_force", "max_contact_radius",
                "dissipated_energy", "solver", "fallback"):
        assert js[key] == getattr(r, key), key
    assert js["estimated_rel_error"] == r.estimated_rel_error
    assert js["work"] == r.work


def test_default_scene_matches_run_json(cli):
    js = json.loads(cli("run", "--json").stdout)
    _same_outcome(js, mi.Scene.default().run())


SCENES = sorted(p.name for p in (pathlib.Path(__file__).resolve().parents[2] / "scenes")
                .glob("*.toml"))


@pytest.mark.parametrize("name", SCENES)
def test_shipped_scenes_match_run_json(cli, root, name):
    path = root / "scenes" / name
    js = json.loads(cli("run", path, "--json").stdout)
    r = mi.Scene.load(path).run()
    _same_outcome(js, r)
    if r.bodies is None:
        assert "bodies" not in js
    else:
        assert js["bodies"] == {"a": {"rebound_velocity": r.bodies["a"]},
                                "b": {"rebound_velocity": r.bodies["b"]}}


def test_curve_matches_cli(cli, tmp_path):
    cli("curve", "--v0", "0.01:10:7", "--log", "--out", tmp_path)
    rows = _csv_rows((tmp_path / "curve.csv").read_text())
    v0 = np.array([float(r["v0"]) for r in rows])
    c = mi.curve(mi.Scene.default(), v0)
    for key in ("cor", "contact_time", "max_force", "max_compression"):
        assert np.array_equal(np.array([float(r[key]) for r in rows]), getattr(c, key)), key


@pytest.mark.parametrize("args,call", [
    (("cor", "--nu", "0.7", "--p2", "1", "--p3", "1"), lambda: mi.cor(0.7, 1, 1)),
    (("cor", "--nu", "0.3", "--p2", "-1", "--p3", "1"), lambda: mi.cor(0.3, -1, 1)),
    (("cor", "--nu", "0.3", "--p2", "1", "--p3", "1", "--rtol", "0"),
     lambda: mi.cor(0.3, 1, 1, rtol=0)),
])
def test_error_messages_equal_cli(cli, args, call):
    p = cli(*args, check=False)
    assert p.returncode == 1
    with pytest.raises(mi.Error) as err:
        call()
    assert p.stderr.strip() == f"error: {err.value}"


def test_unknown_solver_is_a_usage_error_in_the_cli(cli):
    # the command line checks closed sets of values itself (exit 2, one line listing them);
    # the package raises its own error
    p = cli("cor", "--nu", "0.3", "--p2", "1", "--p3", "1", "--solver", "euler", check=False)
    assert p.returncode == 2
    assert p.stderr.count("\n") == 1
    assert "invalid value 'euler' for '--solver <SOLVER>'" in p.stderr
    assert "auto, mdr-euler, mdr, reference, fast" in p.stderr
    with pytest.raises(mi.Error, match="solver: cannot read 'euler': expected one of auto"):
        mi.cor(0.3, 1, 1, solver="euler")


def test_scene_error_messages_equal_cli(cli, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(mi.DEFAULT_SCENE.replace("eta = 500.0", "eta = -1.0"))
    unknown = tmp_path / "unknown.toml"
    unknown.write_text(mi.DEFAULT_SCENE + "\n[extra]\nkey = 1\n")
    for path in (bad, unknown, tmp_path / "missing.toml"):
        p = cli("run", path, check=False)
        assert p.returncode == 1
        with pytest.raises(mi.Error) as err:
            mi.Scene.load(path)
        assert p.stderr.strip() == f"error: {err.value}"


def test_dem_matches_cli(cli, root, tmp_path):
    path = root / "scenes" / "polymer_ball_on_steel.toml"
    out = cli("dem", path, "--v0", "0.5:5:12", "--log", "--format", "json", "--out", tmp_path)
    js = json.loads(out.stdout)
    r = mi.dem(mi.Scene.load(path), "0.5:5:12", log=True)
    assert r.pop("lammps") == cli("dem", path, "--v0", "0.5:5:12", "--log", "--format",
                                  "lammps", "--out", tmp_path / "l").stdout
    r.pop("liggghts")
    assert r == js
    with pytest.raises(mi.Error) as err:
        mi.dem(mi.Scene.load(path), "5:0.5")
    p = cli("dem", path, "--v0", "5:0.5", "--format", "json", check=False)
    assert p.stderr.strip() == f"error: {err.value}"
    # the same range as a tuple: the same report
    t = mi.dem(mi.Scene.load(path), v0=(0.5, 5, 12), log=True)
    t.pop("liggghts")
    t.pop("lammps")
    assert t == js


@pytest.mark.parametrize("v0,message", [
    ((5.0, 0.5), r"^v0: cannot read '\(5\.0, 0\.5\)': expected \(MIN, MAX\) or \(MIN, MAX, N\) "
                 r".*N = 50 when left out\); MIN = 5e0 is not below MAX = 5e-1$"),
    ((0.5, 5.0, 1), r"^v0: .*; N = 1 is out of range: allowed 2 <= N <= 100000 "
                    r"\(one velocity: use impact\)$"),
    ((0.5, 5.0, -3), r"; N = -3 is out of range"),
    ((0.0, 5.0), r"; MIN = 0e0 is out of range: allowed 0 < velocity < inf \(m/s\)$"),
    ((0.5, float("inf"), 4), r"; MAX = inf is out of range"),
    ((0.5, 5.0, 2.5), r"^v0: N = 2\.5 is not a whole number$"),
    ((0.5,), r"^v0: expected \(MIN, MAX\) or \(MIN, MAX, N\).*not 1 values$"),
    (5.0, r"^v0: expected \(MIN, MAX\) or \(MIN, MAX, N\).*not float$"),
    (("a", 5.0), r"^v0 MIN: not a real number"),
    (([0.5, 1.0], 5.0), r"^v0: MIN is a number, not an array of shape \(2,\)$"),
])
def test_dem_velocity_errors_name_v0(v0, message):
    """`dem(v0=...)`: errors in Python terms, naming `v0`, never the command line's `--v0`."""
    with pytest.raises(mi.Error, match=message) as err:
        mi.dem(mi.Scene.default(), v0=v0)
    assert "--v0" not in str(err.value)


def test_prony_equals_the_command(root, tmp_path, cli):
    """`prony` gives the command's JSON report and files."""
    data = root / "scenes" / "dma_example.csv"
    report = mi.prony(data, out=tmp_path / "py")
    o = cli("prony", str(data), "--json", "--out", str(tmp_path / "cli"))
    assert report == json.loads(o.stdout)
    assert (tmp_path / "py" / "material.toml").read_text() == \
        (tmp_path / "cli" / "material.toml").read_text()
    assert report["shift"]["kind"] == "wlf"
    with pytest.raises(mi.Error, match="--terms"):
        mi.prony(data, terms="zero")


def test_version_is_the_crates_and_the_packages(cli, root):
    """`__version__`: the installed package's metadata, the crate's and `mdr-impact --version`."""
    import importlib.metadata
    import re

    assert re.fullmatch(r"\d+\.\d+\.\d+\S*", mi.__version__)
    assert mi.__version__ == importlib.metadata.version("mdr-impact")
    crate = re.search(r'^version = "([^"]+)"', (root / "Cargo.toml").read_text(), re.M)
    assert mi.__version__ == crate.group(1)
    assert cli("--version").stdout.split() == ["mdr-impact", mi.__version__]
