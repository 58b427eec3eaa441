"""The examples in examples/python/ run as scripts (Agg backend, figures written, not shown)."""
import os
import subprocess
import sys

import pytest

from conftest import SRC

EXAMPLES = SRC / "examples" / "python"


def run(tmp_path, script, *args):
    env = dict(os.environ, MPLBACKEND="Agg")
    out = tmp_path / (script.replace(".py", ".png"))
    r = subprocess.run([sys.executable, str(EXAMPLES / script), "--out", str(out), *args], capture_output=True,
                       text=True, cwd=tmp_path, env=env, timeout=240)
    assert r.returncode == 0, r.stderr
    assert out.stat().st_size > 10_000  # a real figure
    with open(out, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    return r.stdout


def test_twobar(tmp_path):
    out = run(tmp_path, "twobar.py")
    # the figures of `make demo` (README): peak-to-peak and mean offset in mm, correction on and off
    assert "on                                 161.904             22.824" in out
    assert "off                                140.752             72.229" in out


def test_hsx_sweep(tmp_path):
    out = run(tmp_path, "hsx_sweep.py", "--step", "25")
    assert "11 speeds" in out and "σ_max" in out


def test_design_study(tmp_path):
    out = run(tmp_path, "design_study.py")
    assert "default suspension k=141000-c=10440: J2 = 9.584 N at 175 km/h" in out
    assert "best:" in out
