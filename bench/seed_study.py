#!/usr/bin/env python3
"""A seed study of an irregular line from Python (issue 34 item 4; docs/benchmarks.md
"Stitched and irregular lines").

    PYTHONPATH=build/python /usr/bin/python3 bench/seed_study.py [--seeds 20] [--std 0.005]
        [--speeds 200,250,300] [--solver modal|direct] [--catenary models/catenary-fe.yaml]

For each seed: the line with `irregularity.dropper_length_std` and `irregularity.seed` set
(inerta.load_catenary), then one inerta.sweep over the speeds (the speeds in parallel on all cores,
the GIL released). Prints σ per seed and speed, the mean and spread per speed, and the wall time
of the whole study and of one seed. The perfect line's sweep is timed first for comparison.
"""
import argparse
import statistics
import time
from pathlib import Path

import inerta

ROOT = Path(__file__).resolve().parents[1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--std", type=float, default=0.005, help="dropper-length error std, m")
    ap.add_argument("--speeds", default="200,250,300", help="km/h")
    ap.add_argument("--solver", default="modal", choices=["modal", "direct"])
    ap.add_argument("--catenary", default=str(ROOT / "models" / "catenary-fe.yaml"))
    ap.add_argument("--model", default=str(ROOT / "models" / "pantograph-3mass.yaml"))
    a = ap.parse_args()
    speeds_kmh = [float(s) for s in a.speeds.split(",")]
    speeds = inerta.kmh(speeds_kmh)
    model = inerta.load_model(a.model)
    base = [f"solver.type={a.solver}"]

    t0 = time.perf_counter()
    perfect = inerta.sweep(model, inerta.load_catenary(a.catenary, base), speeds)
    t_perfect = time.perf_counter() - t0
    print(f"perfect line: sigma {', '.join(f'{s:.2f}' for s in perfect.std)} N at {a.speeds} km/h; {t_perfect:.2f} s")

    sig = []
    times = []
    t0 = time.perf_counter()
    for seed in range(1, a.seeds + 1):
        t1 = time.perf_counter()
        cat = inerta.load_catenary(a.catenary, base + [f"irregularity.dropper_length_std={a.std}", f"irregularity.seed={seed}"])
        r = inerta.sweep(model, cat, speeds)
        times.append(time.perf_counter() - t1)
        sig.append(list(r.std))
        print(f"seed {seed:3d}: sigma {', '.join(f'{s:.2f}' for s in r.std)} N; {times[-1]:.2f} s", flush=True)
    total = time.perf_counter() - t0
    for j, v in enumerate(speeds_kmh):
        col = [s[j] for s in sig]
        print(f"{v:g} km/h: sigma mean {statistics.mean(col):.2f} N, std over seeds {statistics.stdev(col) if len(col) > 1 else 0:.2f} N"
              f" (perfect {perfect.std[j]:.2f} N)")
    print(f"{a.seeds} seeds x {len(speeds)} speeds ({a.solver}): {total:.1f} s in all, "
          f"{statistics.median(times):.2f} s a seed (median) against {t_perfect:.2f} s for the perfect line "
          f"({statistics.median(times) / t_perfect:.2f} x)")


if __name__ == "__main__":
    main()
