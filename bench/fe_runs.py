#!/usr/bin/python3
"""Whole-process times of the FE line's runs (issue 39; docs/benchmarks.md "The FE line's first and
stored runs"): a first run on an empty mode store, the same run with its modes stored, the direct solve,
the HSX at 300 km/h stored and the 21-speed HSX sweep stored, each REPEAT times, side by side for one
or more builds of the CLI; then (issue 50) the HSX on the calibrated stitched line at 250 km/h, two HSX 200 m
apart through the overlap line at 250 km/h and one evaluation of the real-line study (studies/hsx-real-line.yaml:
the stock suspension commissioned, then 27 runs of nine lines — the build's Python module, beside its CLI), each
with its modes stored (a store of its own, filled once before the timed runs). With --split, the phases of one
first and one stored run (INERTA_TIMINGS=1).

    /usr/bin/python3 bench/fe_runs.py [--cli build/inerta ...] [--repeat 3] [--split]

Each CLI gets a store of its own under a temporary folder (emptied before every first run). Times are
wall seconds of the whole process; the median and the range are printed."""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
M3 = ["simulate", "models/pantograph-3mass.yaml", "--catenary", "models/catenary-fe.yaml", "--speed", "250", "--unit", "kmh"]
HSX = ["simulate", "models/hsx.yaml", "--catenary", "models/catenary-fe.yaml", "--speed", "300", "--unit", "kmh"]
SWEEP = ["sweep", "models/hsx.yaml", "--catenary", "models/catenary-fe.yaml", "--speeds", "150:10:350", "--unit", "kmh"]
STITCHED = ["simulate", "models/hsx.yaml", "--catenary", "models/catenary-fe-stitched.yaml", "--speed", "250", "--unit", "kmh"]
OVERLAP2 = ["simulate", "models/hsx.yaml", "--catenary", "models/catenary-fe-overlap.yaml", "--speed", "250", "--unit", "kmh",
            "--positions", "0,200"]
# One evaluation of the real-line study: the stock suspension (commissioned, then 27 runs), with the build's module.
EVALUATE = ("import inerta, sys; s = inerta.load_study(sys.argv[1]); "
            "c = inerta.evaluate(s, inerta.default_suspension(s)); print(c.J)")


def run_python(cli, store):
    """One real-line evaluation with the Python module beside `cli` (its build's python/ folder)."""
    env = dict(os.environ, INERTA_CACHE=store, PYTHONPATH=os.path.join(os.path.dirname(cli), "python"))
    t0 = time.perf_counter()
    p = subprocess.run(["/usr/bin/python3", "-c", EVALUATE, os.path.join(ROOT, "studies", "hsx-real-line.yaml")], cwd=ROOT,
                       env=env, capture_output=True, text=True)
    dt = time.perf_counter() - t0
    if p.returncode != 0:
        sys.exit(f"real-line evaluation with {cli}'s module: exit {p.returncode}\n{p.stderr}")
    return dt


def run(cli, args, store, out, timings=False):
    env = dict(os.environ, INERTA_CACHE=store)
    if timings:
        env["INERTA_TIMINGS"] = "1"
    for f in os.listdir(os.path.dirname(out)):
        os.remove(os.path.join(os.path.dirname(out), f))
    t0 = time.perf_counter()
    p = subprocess.run([cli] + args + ["--out", out], cwd=ROOT, env=env, capture_output=True, text=True)
    dt = time.perf_counter() - t0
    if p.returncode != 0:
        sys.exit(f"{cli} {' '.join(args)}: exit {p.returncode}\n{p.stderr}")
    return dt, p.stderr


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", action="append", help="an inerta executable (default build/inerta); repeat to compare builds")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--split", action="store_true", help="print the phases of a first and a stored run")
    a = ap.parse_args()
    clis = [os.path.abspath(c) for c in (a.cli or [os.path.join(ROOT, "build", "inerta")])]
    if a.repeat < 1:
        ap.error(f"--repeat {a.repeat}: expected a whole number of runs >= 1")
    for c in clis:
        if not (os.path.isfile(c) and os.access(c, os.X_OK)):
            ap.error(f"--cli {c}: not an executable file (build it with `make build`)")
    work = tempfile.mkdtemp(prefix="inerta-fe-runs-")
    outdir = os.path.join(work, "out")
    os.makedirs(outdir)
    out = os.path.join(outdir, "r.csv")
    try:
        rows = {}
        for k, cli in enumerate(clis):
            store = os.path.join(work, f"store{k}")
            cases = {"3-mass 250 km/h, first run (empty store)": [], "3-mass 250 km/h, stored": [],
                     "3-mass 250 km/h, direct": [], "HSX 300 km/h, stored": [], "HSX sweep 150:10:350, stored": []}
            for _ in range(a.repeat):  # interleaved, so that a slow moment of the machine spreads over all
                shutil.rmtree(store, ignore_errors=True)
                cases["3-mass 250 km/h, first run (empty store)"].append(run(cli, M3, store, out)[0])
                cases["3-mass 250 km/h, stored"].append(run(cli, M3, store, out)[0])
                cases["3-mass 250 km/h, direct"].append(run(cli, M3 + ["--set", "solver.type=direct"], store, out)[0])
                cases["HSX 300 km/h, stored"].append(run(cli, HSX, store, out)[0])
                cases["HSX sweep 150:10:350, stored"].append(run(cli, SWEEP, store, out)[0])
            # Issue 50's cases, each line's modes stored first (once: their own store, kept over the repeats).
            kept = os.path.join(work, f"kept{k}")
            run(cli, STITCHED, kept, out), run(cli, OVERLAP2, kept, out), run_python(cli, kept)
            cases.update({"HSX stitched 250 km/h, stored": [], "2 HSX 200 m apart, overlap 250 km/h, stored": [],
                          "real-line evaluation (27 runs + trim), stored": []})
            for _ in range(a.repeat):
                cases["HSX stitched 250 km/h, stored"].append(run(cli, STITCHED, kept, out)[0])
                cases["2 HSX 200 m apart, overlap 250 km/h, stored"].append(run(cli, OVERLAP2, kept, out)[0])
                cases["real-line evaluation (27 runs + trim), stored"].append(run_python(cli, kept))
            rows[cli] = cases
            if a.split:
                shutil.rmtree(store, ignore_errors=True)
                for what in ("first run", "stored run"):
                    dt, err = run(cli, M3, store, out, timings=True)
                    print(f"{cli}: {what}, {dt:.3f} s")
                    print(err[err.find("timings"):] if "timings" in err else err)
        names = list(next(iter(rows.values())).keys())
        print(f"{'case':44s}" + "".join(f"{os.path.relpath(c, ROOT)[-28:]:>32s}" for c in clis))
        for n in names:
            cells = []
            for c in clis:
                v = rows[c][n]
                cells.append(f"{statistics.median(v):.3f} s ({min(v):.2f}–{max(v):.2f})")
            print(f"{n:44s}" + "".join(f"{x:>32s}" for x in cells))
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
