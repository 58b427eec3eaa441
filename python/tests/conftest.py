"""Shared fixtures: the source tree, the CLI of the same build (INERTA_CLI, set by CTest), and a
runner for it. Run with PYTHONPATH=build/python (docs/python.md)."""
import os
import subprocess
from pathlib import Path

import pytest

SRC = Path(os.environ.get("INERTA_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = Path(os.environ.get("INERTA_CLI", SRC / "build" / "inerta"))


def model(name):
    return str(SRC / "models" / name)


def run_cli(*args, check=True):
    """Runs build/inerta; returns the CompletedProcess (text)."""
    r = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True, cwd=SRC)
    if check and r.returncode != 0:
        raise AssertionError(f"inerta {' '.join(map(str, args))} failed ({r.returncode}): {r.stderr}")
    return r


def read_csv(path):
    """{column: numpy array} of a CSV the CLI wrote."""
    import numpy as np

    with open(path, encoding="utf-8") as f:
        names = f.readline().strip().split(",")
    data = np.atleast_2d(np.loadtxt(path, delimiter=",", skiprows=1))
    return {n: data[:, i] for i, n in enumerate(names)}


@pytest.fixture(scope="session")
def cli():
    if not CLI.exists():
        pytest.skip(f"CLI not built: {CLI}")
    return run_cli


@pytest.fixture(scope="session")
def hsx():
    import inerta

    return inerta.load_model(model("hsx.yaml"))


@pytest.fixture(scope="session")
def lumped():
    import inerta

    return inerta.load_catenary(model("catenary.yaml"))


@pytest.fixture(scope="session")
def twobar():
    import inerta

    return inerta.load_model(model("twobar.yaml"))
