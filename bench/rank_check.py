#!/usr/bin/python3
"""Does a multi-fidelity study's coarse stage rank networks as its fine stage does?

Takes the coarse search's results of a study run (`structure.csv` in its `--out` folder), picks N
feasible networks spread evenly over the coarse ranking, evaluates each at its coarse optimum on the
study's fine stage (the same values, no refinement: `inerta.evaluate`) and prints Spearman's rank
correlation of the coarse and the fine objective over them (docs/benchmarks.md, issue 49).

    PYTHONPATH=build/python /usr/bin/python3 bench/rank_check.py studies/hsx-real-line.yaml /tmp/real/structure.csv --networks 16
"""
import argparse
import csv
import sys
import time

import inerta


def ranks(values):
    order = sorted(range(len(values)), key=lambda i: values[i])
    r = [0.0] * len(values)
    i = 0
    while i < len(order):  # ties share their mean rank
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            r[order[k]] = (i + j) / 2 + 1
        i = j + 1
    return r


def spearman(a, b):
    ra, rb = ranks(a), ranks(b)
    n = len(a)
    ma, mb = sum(ra) / n, sum(rb) / n
    cov = sum((x - ma) * (y - mb) for x, y in zip(ra, rb))
    va = sum((x - ma) ** 2 for x in ra) ** 0.5
    vb = sum((y - mb) ** 2 for y in rb) ** 0.5
    return cov / (va * vb)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("study")
    ap.add_argument("structure", help="structure.csv of a run of the study")
    ap.add_argument("--networks", type=int, default=16, help="how many networks to evaluate (default 16)")
    a = ap.parse_args()
    if a.networks < 3:
        sys.exit("rank_check: --networks must be at least 3")
    study = inerta.load_study(a.study)
    try:
        with open(a.structure, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["feasible"] == "1" and r["values"]]
    except (OSError, KeyError) as e:
        sys.exit(f"rank_check: {a.structure}: not a study's structure.csv ({e})")
    rows.sort(key=lambda r: float(r["J"]))
    n = min(a.networks, len(rows))
    if n < 3:
        sys.exit(f"rank_check: {a.structure}: fewer than 3 feasible networks")
    pick = [rows[round(i * (len(rows) - 1) / (n - 1))] for i in range(n)]
    coarse, fine = [], []
    print(f"{'coarse rank':>11}  {'network':<28} {'coarse J':>10} {'fine J':>10} feasible  s")
    for r in pick:
        params = {kv.split("=")[0]: float(kv.split("=")[1]) for kv in r["values"].split(";")}
        t0 = time.time()
        c = inerta.evaluate(study, r["network"], params)
        coarse.append(float(r["J"]))
        fine.append(c.penalised())
        print(f"{r['rank']:>11}  {r['network']:<28} {float(r['J']):10.5g} {c.J:10.5g} {int(c.feasible):>8}  {time.time() - t0:.1f}",
              flush=True)
    print(f"Spearman's rho over {n} networks (coarse J vs fine penalised J at the coarse optimum): {spearman(coarse, fine):.3f}")


if __name__ == "__main__":
    main()
