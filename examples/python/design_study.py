#!/usr/bin/env python3
"""A small structure-based design study (spec/07) built from Python objects: the HSX pantograph,
two catenaries (k_c0 = 5000 and 10 000 N/m), speeds 50–300 km/h every 25 km/h, three candidate
layouts for the base suspension, one start each. J2 = max over the catenaries of σ_max (periodic
fast path); the best design is re-checked in the time domain. Saves design_study.png (--out).

    /usr/bin/python3 examples/python/design_study.py [--out design_study.png]
"""
import argparse
import sys
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
    ap.add_argument("--out", default="design_study.png", help="figure file (PNG)")
    args = ap.parse_args()

    hsx = inerta.load_pantograph(ROOT / "models" / "hsx.yaml")
    cats = [inerta.load_catenary(ROOT / "models" / "catenary.yaml", {"catenary.kc0": k}) for k in (5000, 10000)]
    study = inerta.Study(hsx, cats, inerta.kmh(np.arange(50, 301, 25)), ["S2-default", "S2-1", "S2-5"],
                         labels=["k_c0 = 5000 N/m", "k_c0 = 10000 N/m"],
                         search=inerta.SearchOptions(starts=1, seed=1, min_step=0.02), name="small HSX study")
    base = inerta.default_suspension(study)
    default = inerta.evaluate(study, base)
    print(f"{study.name}: {len(study.layouts)} layouts, {len(cats)} catenaries, {len(study.speeds)} speeds")
    print(f"default suspension {inerta.to_string(base, True)}: J2 = {default.J:.3f} N at "
          f"{default.speed * 3.6:.0f} km/h")
    print(f"  {'layout':<12}{'network':<9}{'values':<40}{'J2 [N]':>8}{'vs default':>12}")
    results = []
    for layout in study.layouts:
        r = inerta.optimise_layout(study, layout)
        values = ", ".join(f"{k} = {inerta.describe(v) if v in (0, float('inf')) else f'{v:.4g}'}"
                           for k, v in r.values.items())
        print(f"  {r.layout:<12}{r.expression:<9}{values:<40}{r.cost.J:>8.3f}"
              f"{100 * (r.cost.J - default.J) / default.J:>11.1f}%")
        results.append(r)
    best = min(results, key=lambda r: r.cost.J)
    check = inerta.evaluate_time(study, best.network())
    print(f"best: {best.layout} — time-domain re-check J2 = {check.J:.3f} N (periodic {best.cost.J:.3f} N)")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    for name, net, style in (("default", base, "--"), (best.layout, best.network(), "-")):
        for c in inerta.sigma_curves(study, net):
            ax.plot(c.speed * 3.6, c.sigma, style, marker="o", markersize=3, label=f"{name}, {c.catenary}")
    ax.set_xlabel("speed [km/h]")
    ax.set_ylabel("σ of the contact force [N]")
    ax.set_title("design study: default vs best suspension (periodic fast path)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
