#!/usr/bin/python3
"""Speed-up of a 40-task sweep on Dask with 1 and 2 worker processes (issue 24; docs/distributed.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/distributed_sweep.py [--tasks 40]

Each task is one speed of the HSX on the lumped catenary in the time domain. Prints the wall time of
the serial library sweep on one thread-pool (all cores), of the Dask sweep with 1 and 2 workers (the
cluster started beforehand, not timed), and checks that every result equals the serial one."""
import argparse
import os
import pickle
import time

import inerta
from distributed import Client, LocalCluster

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--tasks", type=int, default=40)
    a = p.parse_args()
    m = inerta.load_model(os.path.join(SRC, "models", "hsx.yaml"))
    cat = os.path.join(SRC, "models", "catenary.yaml")
    speeds = [inerta.kmh(100 + 220 * k / (a.tasks - 1)) for k in range(a.tasks)]
    t0 = time.perf_counter()
    serial = inerta.sweep(m, cat, speeds)
    t_serial = time.perf_counter() - t0
    print(f"{a.tasks} speeds, serial library sweep (oneTBB, all cores): {t_serial:.2f} s")
    times = {}
    for n in (1, 2):
        with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
                Client(cluster) as client:
            inerta.sweep(m, cat, speeds[:n], client=client)  # each worker reads the model once
            t0 = time.perf_counter()
            r = inerta.sweep(m, cat, speeds, client=client)
            times[n] = time.perf_counter() - t0
        same = all(pickle.dumps(x) == pickle.dumps(y) for x, y in zip(r, serial))
        print(f"Dask, {n} worker(s): {times[n]:.2f} s; equal to the serial sweep: {same}")
    print(f"speed-up 1 → 2 workers: {times[1] / times[2]:.2f}")


if __name__ == "__main__":
    main()
