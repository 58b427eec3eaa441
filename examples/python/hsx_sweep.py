#!/usr/bin/env python3
"""HSX pantograph under the lumped catenary: σ of the contact force over 50–300 km/h (51 speeds,
time domain, both cores), with the model's suspension and with a plain spring of 93 kN/m in place
of the actuator's Maxwell element (study 2's best design). Saves hsx_sweep.png (--out).

    /usr/bin/python3 examples/python/hsx_sweep.py [--out hsx_sweep.png] [--step 5]
"""
import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
try:
    import inerta
except ImportError:  # not installed: use the build tree (docs/python.md)
    sys.path.insert(0, str(ROOT / "build" / "python"))
    import inerta

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="hsx_sweep.png", help="figure file (PNG)")
    ap.add_argument("--step", type=float, default=5, help="speed step, km/h")
    args = ap.parse_args()

    hsx = inerta.load_model(ROOT / "models" / "hsx.yaml")
    cat = inerta.load_catenary(ROOT / "models" / "catenary.yaml")
    speeds_kmh = np.arange(50, 300 + 1e-9, args.step)
    designs = {"model's suspension (S2-default)": hsx,
               "spring k = 93 kN/m (S2-5)": hsx.with_suspension("S2-5", {"k": 93e3})}
    print(f"HSX under {cat.describe()}; {len(speeds_kmh)} speeds")
    results = {}
    for label, m in designs.items():
        t0 = time.perf_counter()

        def progress(done, total):  # called on this thread after each speed
            print(f"\r  {label}: {done}/{total} speeds", end="", flush=True)

        r = inerta.sweep(m, cat, inerta.kmh(speeds_kmh), progress=progress if sys.stdout.isatty() else None)
        sigma, v, mean = r.sigma_max
        print(f"{chr(13) if sys.stdout.isatty() else ''}  {label}: σ_max = {sigma:.3f} N at {v * 3.6:.0f} km/h (mean {mean:.2f} N); "
              f"wall {time.perf_counter() - t0:.2f} s")
        results[label] = r

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    for label, r in results.items():
        inerta.plot_sweep(r, ax=ax, label=label)
    ax.set_title("HSX pantograph, lumped catenary: contact-force σ")
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
