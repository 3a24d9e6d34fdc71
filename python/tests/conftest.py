"""Shared fixtures: the repository's folders and the `mdr-impact` binary of the same source."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _binary():
    """The command-line binary: $MDR_IMPACT_BIN, else the release build of this checkout."""
    env = os.environ.get("MDR_IMPACT_BIN")
    if env:
        return pathlib.Path(env)
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "mdr-impact"


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def cli(tmp_path_factory):
    """Run `mdr-impact ARGS...`; returns the CompletedProcess (text mode).

    Without the binary the tests that need it are skipped, except under CI (CI=true), where a
    missing binary is a failure: .ci/run builds it before running pytest.
    """
    exe = _binary()
    if not exe.is_file():
        message = f"mdr-impact binary not found at {exe} (set MDR_IMPACT_BIN)"
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail(message)
        pytest.skip(message)

    # commands that write into the working directory (curve, dem, stress) keep out of the tree
    cwd = tmp_path_factory.mktemp("cli-cwd")

    def run(*args, check=True):
        p = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True,
                           timeout=600, cwd=cwd)
        if check and p.returncode != 0:
            raise AssertionError(f"mdr-impact {' '.join(map(str, args))}: {p.stderr}")
        return p

    return run
