"""`mdr_impact.fit`: the same report as `mdr-impact fit --json` on the same data."""

import json

import pytest

import mdr_impact as mi


def _close(a, b):
    """Reports equal up to the last bits of the floats (the fit runs in parallel)."""
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_close(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return len(a) == len(b) and all(_close(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, float):
        return a == b or abs(a - b) <= 1e-9 * max(abs(a), abs(b))
    return a == b


def test_fit_matches_the_command_line(cli, root, tmp_path):
    data = root / "examples" / "data" / "drops.csv"
    r = mi.fit(data, fix={"nu": 0.49}, out=tmp_path / "py")
    out = json.loads(cli("fit", data, "--fix", "nu=0.49", "--json", "--out", tmp_path / "cli").stdout)
    assert _close(r, out)
    names = [p["name"] for p in r["parameters"]] if isinstance(r["parameters"], list) else list(
        r["parameters"]
    )
    assert "g_inf" in names
    assert (tmp_path / "py" / "fit.toml").is_file() and (tmp_path / "py" / "fit.svg").is_file()


def test_fit_errors_are_python_errors(root):
    data = root / "examples" / "data" / "drops.csv"
    with pytest.raises(mi.Error, match="model"):
        mi.fit(data, model="maxwell")
    with pytest.raises(mi.Error, match="g_inf"):
        mi.fit(data, fix={"g_inf": -1.0})
    with pytest.raises(mi.Error):
        mi.fit(root / "no-such-file.csv")
