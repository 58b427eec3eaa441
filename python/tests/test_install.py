"""The install (issue 51, docs/install.md): `cmake --install BUILD --prefix P` puts the program, the Python
module, the criteria presets, the default models, the plotting scripts and the Dask driver under P, and each
finds the others there — run from another folder, with a preset that exists only in the installed copy (so a
lookup in the checkout would fail)."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import inerta

BUILD = Path(inerta.__file__).resolve().parents[2]  # BUILD/python/inerta/__init__.py


def test_the_installed_program_and_module_run_without_the_checkout(tmp_path):
    prefix = tmp_path / "prefix"
    r = subprocess.run(["cmake", "--install", str(BUILD), "--prefix", str(prefix)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    data = prefix / "share" / "inerta"
    for f in ("criteria/en50367-ac.yaml", "models/hsx.yaml", "models/catenary-fe-stitched.yaml", "scripts/plot-study"):
        assert (data / f).is_file(), f
    assert os.access(data / "scripts" / "plot-study", os.X_OK)
    site = prefix / inerta._inerta._PYTHON_SITE
    assert (site / "inerta" / "distributed.py").is_file() and list((site / "inerta").glob("_inerta*.so"))
    # A preset only the installed copy has.
    shutil.copy(data / "criteria" / "en50367-ac.yaml", data / "criteria" / "installed-only.yaml")
    away = tmp_path / "elsewhere"
    away.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "INERTA_DATA_DIR", "INERTA_SOURCE_DIR")}
    exe = prefix / "bin" / "inerta"
    r = subprocess.run([str(exe), "simulate", str(data / "models" / "pantograph-3mass.yaml"), "--catenary",
                        str(data / "models" / "catenary.yaml"), "--speed", "200", "--unit", "kmh", "--t-end", "2",
                        "--acceptance", "installed-only", "--out", str(away / "run.csv")],
                       capture_output=True, text=True, cwd=away, env=env)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "verdict" in r.stdout and (away / "run.acceptance.csv").is_file()
    # The checkout's program does not know it: the lookup above was the installed copy's.
    r = subprocess.run([str(BUILD / "inerta"), "simulate", str(data / "models" / "pantograph-3mass.yaml"), "--catenary",
                        str(data / "models" / "catenary.yaml"), "--speed", "200", "--unit", "kmh", "--t-end", "2",
                        "--acceptance", "installed-only", "--out", str(away / "run2.csv")],
                       capture_output=True, text=True, cwd=away, env=env)
    assert r.returncode != 0 and "installed-only" in r.stderr
    # The installed module: found on its site folder, reading the installed data.
    code = ("import inerta, sys; print(inerta.__file__); print(inerta.data_dir()); "
            "print(inerta.load_acceptance('installed-only').source)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=away,
                       env={**env, "PYTHONPATH": str(site)})
    assert r.returncode == 0, r.stderr
    file, data_dir, source = r.stdout.split("\n")[:3]
    assert Path(file).resolve().is_relative_to(prefix.resolve())
    assert Path(data_dir).resolve() == data.resolve()
    assert Path(source).resolve() == (data / "criteria" / "installed-only.yaml").resolve()
