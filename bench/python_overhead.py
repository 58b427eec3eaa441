#!/usr/bin/env python3
"""Python overhead of the inerta module against the CLI (docs/benchmarks.md#python-module).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--repeat 15] [--sweeps 3]

For each workload it measures, interleaved:
  CLI      the end-to-end wall time of build/inerta (process start, model loading, run, output),
  Python   the wall time of the Python call (inerta.simulate / inerta.sweep), and
  library  the wall time of the library call inside it (Result.wall_s, measured in C++),
and reports the Python overhead = Python − library (thread hand-off, argument conversion, result
wrapping) as a percentage of the CLI's time. Medians over the repetitions.
"""
import argparse
import os
import re
import statistics
import subprocess
import time
from pathlib import Path

import inerta

ROOT = Path(__file__).resolve().parents[1]
CLI = Path(os.environ.get("INERTA_CLI", ROOT / "build" / "inerta"))


def cli(*args):
    t0 = time.perf_counter()
    r = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True, check=True)
    return time.perf_counter() - t0, r.stdout


def report(name, cli_t, py_t, lib_t, extra=""):
    c, p, l = statistics.median(cli_t), statistics.median(py_t), statistics.median(lib_t)
    over = [a - b for a, b in zip(py_t, lib_t)]
    o = statistics.median(over)
    print(f"{name}: CLI {c * 1e3:.1f} ms, Python {p * 1e3:.1f} ms, library {l * 1e3:.1f} ms; "
          f"Python overhead {o * 1e3:.3f} ms = {100 * o / c:.2f} % of the CLI (max {100 * max(over) / c:.2f} %)"
          f"{extra}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=15, help="two-bar repetitions")
    ap.add_argument("--sweeps", type=int, default=3, help="sweep repetitions")
    a = ap.parse_args()

    # one 60 s two-bar run (60 001 samples of C_x, C_y)
    m = inerta.load_model(ROOT / "models" / "twobar.yaml")
    inerta.simulate(m, t_end=60, sample=0.001)  # warm-up
    cli_t, py_t, lib_t = [], [], []
    for _ in range(a.repeat):
        cli_t.append(cli("simulate", ROOT / "models" / "twobar.yaml", "--t-end", 60, "--sample", 0.001, "--out",
                         "/tmp/inerta-bench-tb.csv")[0])
        t0 = time.perf_counter()
        r = inerta.simulate(m, t_end=60, sample=0.001)
        y = r["C_y"].max()
        py_t.append(time.perf_counter() - t0)
        lib_t.append(r.wall_s)
        del r
    report("two-bar 60 s", cli_t, py_t, lib_t, f"; C_y max {y:.6f} m")

    # one 51-speed sweep 50:5:300 km/h of the HSX under the lumped catenary (both cores)
    hsx = inerta.load_model(ROOT / "models" / "hsx.yaml")
    cat = inerta.load_catenary(ROOT / "models" / "catenary.yaml")
    speeds = inerta.kmh(range(50, 301, 5))
    cli_t, py_t, lib_t, cli_lib = [], [], [], []
    for _ in range(a.sweeps):
        t, out = cli("sweep", ROOT / "models" / "hsx.yaml", "--catenary", ROOT / "models" / "catenary.yaml",
                     "--speeds", "50:5:300", "--unit", "kmh", "--out", "/tmp/inerta-bench-sweep.csv")
        cli_t.append(t)
        cli_lib.append(float(re.search(r"wall ([0-9.]+) s", out).group(1)))
        t0 = time.perf_counter()
        r = inerta.sweep(hsx, cat, speeds)
        s = r.sigma_max
        py_t.append(time.perf_counter() - t0)
        lib_t.append(r.wall_s)
    report("HSX sweep 51 speeds", cli_t, py_t, lib_t,
           f"; CLI's own sweep wall {statistics.median(cli_lib):.2f} s; σ_max {s[0]:.3f} N at {s[1] * 3.6:.0f} km/h")


if __name__ == "__main__":
    main()
