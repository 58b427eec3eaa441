"""Sweeps and design studies on a Dask cluster (docs/distributed.md).

The C++ library does the work in each Dask worker process; this module only cuts it into tasks and
puts the results back in order, so a distributed run gives the serial run's numbers to the last bit:

* ``sweep(model, catenary, speeds, client)``: one task per speed (inerta.sweep(..., client=c) calls
  it). The model travels as its file's text and overrides, a catenary as its file's path and
  overrides: a worker reads each once and keeps it (a finite-element line's modes too).
* ``optimise(study_path, client, out=..., checkpoint=...)``: a study of named layouts. By the
  periodic fast path (milliseconds an evaluation) one task per layout; in the time domain (a
  finite-element line, or a multi-fidelity study's refinement) one task per design: each layout's
  search runs here (its coarse periodic search too) and sends every poll's designs to the workers,
  all layouts at once, so the cluster's workers are used beyond the number of layouts. Each finished
  layout, and in the time domain each evaluated design, is written to the checkpoint at once; a study
  started again with the same checkpoint runs only the layouts it lacks and evaluates no design twice
  (the searches are deterministic: they replay to where they stopped).

Faults: a task whose worker dies is run again on another worker by Dask (its result is the same:
the tasks are pure functions of their inputs); after ``distributed.scheduler.allowed-failures``
deaths of workers running it, the task fails and the study stops with Dask's KilledWorker, the
checkpoint keeping everything finished.

Command line (what ``inerta optimise STUDY --workers N`` / ``--scheduler ADDRESS`` runs)::

    python3 -m inerta.distributed optimise STUDY [--workers N | --scheduler tcp://HOST:PORT]
            [--out DIR] [--force] [--checkpoint FILE] [--no-plots]
"""
import argparse
import concurrent.futures
import os
import pickle
import sys
import threading
import time

from . import _inerta

# Per worker process: what it has read (models, catenaries, studies), by what identifies them.
_cache = {}


def _cached(key, make):
    try:
        return _cache[key]
    except KeyError:
        value = _cache[key] = make()
        return value


def _model_key(model):
    try:
        text, source, overrides = model.__getstate__()  # TypeError names why not
        return (text, source, tuple(overrides))
    except TypeError as e:
        raise TypeError(f"inerta.distributed: {e}") from None


def _catenary_key(catenary):
    if isinstance(catenary, (str, os.PathLike)):
        return (os.path.abspath(os.fspath(catenary)), ())
    if isinstance(catenary, _inerta.CatenaryFile):
        if not catenary.path:
            raise TypeError("inerta.distributed: this CatenaryFile was not read by load_catenary; "
                            "give the catenary as a file name or load_catenary(path, overrides)")
        return (os.path.abspath(catenary.path), tuple(catenary.overrides))
    raise TypeError("inerta.distributed: a catenary for Dask workers is a file name or a CatenaryFile from "
                    "load_catenary (the workers read the file again; a Catenary object cannot be sent)")


def _sweep_speed(model_key, catenary_key, speed, kwargs):
    model = _cached(("model",) + model_key,
                    lambda: _inerta.parse_model(model_key[0], model_key[1], list(model_key[2])))
    cat = _cached(("catenary",) + catenary_key,
                  lambda: _inerta.load_catenary(catenary_key[0], list(catenary_key[1])))
    return _inerta.sweep(model, cat, [speed], **kwargs)[0]


def sweep(model, catenary, speeds, client, *, progress=None, **kwargs):
    """inerta.sweep on a Dask cluster: one task per speed, gathered in order (a SweepResult equal to the
    serial one). kwargs: contact (a name), positions, options, method, rtol, atol, as inerta.sweep.
    progress(done, total) as speeds finish."""
    from distributed import as_completed

    t0 = time.perf_counter()
    mk, ck = _model_key(model), _catenary_key(catenary)
    speeds = [float(v) for v in speeds]
    futures = [client.submit(_sweep_speed, mk, ck, v, kwargs, pure=False) for v in speeds]
    done = 0
    for _ in as_completed(futures):
        done += 1
        if progress is not None:
            progress(done, len(futures))
    results = client.gather(futures)
    return _inerta.SweepResult(results, time.perf_counter() - t0, "time")


# ---- Studies ----------------------------------------------------------------------------------------

def _study(path, stamp):
    return _cached(("study", path, stamp), lambda: _inerta.load_study(path))


def _layout_task(path, stamp, layout):
    return _inerta.optimise_layout(_study(path, stamp), layout)


def _design_task(path, stamp, layout, params):
    return _inerta.design_cost(_study(path, stamp), layout, params)


def _read_checkpoint(path, study_path, stamp):
    """(finished layouts, evaluated designs) of a checkpoint file, or two empty dicts."""
    if not path or not os.path.exists(path):
        return {}, {}
    with open(path, "rb") as f:
        data = pickle.load(f)
    if data.get("study") != study_path or data.get("stamp") != stamp:
        raise RuntimeError(f"{path}: a checkpoint of another study or of an earlier version of {study_path} "
                           "(its file changed); remove it to start again")
    return data["layouts"], data.get("designs", {})


def _write_checkpoint(path, study_path, stamp, layouts, designs):
    tmp = f"{path}.{os.getpid()}.{threading.get_ident()}.tmp"
    with open(tmp, "wb") as f:
        pickle.dump({"study": study_path, "stamp": stamp, "layouts": layouts, "designs": designs}, f)
    os.replace(tmp, path)  # never a half-written checkpoint


def optimise(study_path, client, *, checkpoint=None, progress=None, stats=None):
    """Optimises every layout of a study file on the cluster (one task per layout by the periodic
    fast path, one per design in the time domain); returns (study, default_cost, results) with
    results in the study's order, equal to the serial run's. checkpoint: a file that keeps each
    finished layout and each evaluated design (read first: finished layouts are not run again,
    evaluated designs not sent again). progress(layout, result, done, total) as layouts finish (an
    exception it raises stops the study; the checkpoint keeps what finished). stats: a dict that
    receives "designs_sent", the designs sent to the workers."""
    from distributed import as_completed

    path = os.path.abspath(os.fspath(study_path))
    st = os.stat(path)
    stamp = (st.st_mtime_ns, st.st_size)
    study = _inerta.load_study(path)
    if study.all_networks:
        raise ValueError(f"{study_path}: `layouts: all` is not distributed yet (each network's search is warm-started "
                         "from its sub-networks'); run it with `inerta optimise` on one machine")
    done, designs = _read_checkpoint(checkpoint, path, stamp)
    todo = [l for l in study.layouts if l not in done]
    default = client.submit(lambda p, s: _inerta.evaluate(_study(p, s), _inerta.default_suspension(_study(p, s))),
                            path, stamp, pure=False)
    if stats is not None:
        stats["designs_sent"] = 0
    if study.method == "time":
        lock = threading.Lock()
        stop = threading.Event()  # set when the study stops early: the other layouts stop at their next poll

        def batch_for(layout):
            def batch(params):  # one task per design not evaluated yet, gathered in order
                if stop.is_set():
                    raise KeyboardInterrupt("the study was stopped")
                keys = [(layout, tuple(sorted(p.items()))) for p in params]
                with lock:
                    missing = [i for i, k in enumerate(keys) if k not in designs]
                futures = [client.submit(_design_task, path, stamp, layout, params[i], pure=False) for i in missing]
                costs = client.gather(futures)
                with lock:
                    for i, c in zip(missing, costs):
                        designs[keys[i]] = c
                    if stats is not None:
                        stats["designs_sent"] += len(missing)
                    if checkpoint:
                        _write_checkpoint(checkpoint, path, stamp, done, designs)
                    return [designs[k] for k in keys]
            return batch

        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, len(todo))) as pool:
            running = {pool.submit(_inerta.optimise_layout, study, l, batch=batch_for(l)): l for l in todo}
            try:
                for fut in concurrent.futures.as_completed(running):
                    layout = running[fut]
                    with lock:
                        done[layout] = fut.result()
                        if checkpoint:
                            _write_checkpoint(checkpoint, path, stamp, done, designs)
                    if progress is not None:
                        progress(layout, done[layout], len(done), len(study.layouts))
            except BaseException:
                stop.set()
                raise
    else:
        futures = {client.submit(_layout_task, path, stamp, l, pure=False): l for l in todo}
        for fut in as_completed(list(futures)):
            layout = futures[fut]
            done[layout] = fut.result()
            if checkpoint:
                _write_checkpoint(checkpoint, path, stamp, done, designs)
            if progress is not None:
                progress(layout, done[layout], len(done), len(study.layouts))
    return study, default.result(), [done[l] for l in study.layouts]


def _client(args):
    from distributed import Client, LocalCluster

    if args.scheduler:
        return Client(args.scheduler), None
    cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=":0")
    return Client(cluster), cluster


def main(argv=None):
    """The command line; errors as the CLI reports them (docs/cli.md "Exit codes"): `error: …` and exit
    code 2 for a file error, `numerical failure: …` and 3, `error: …` and 1 otherwise."""
    try:
        return _main(argv)
    except _inerta.ModelError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except _inerta.NumericalError as e:
        print(f"numerical failure: {e}", file=sys.stderr)
        return 3
    except (_inerta.InvalidArgument, _inerta.Error, RuntimeError, ValueError, OSError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 1


def _main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m inerta.distributed",
                                description="Inerta design studies on a Dask cluster (docs/distributed.md)")
    sub = p.add_subparsers(dest="command", required=True)
    o = sub.add_parser("optimise", help="optimise a study's layouts: a Dask task per design (time domain) or per layout")
    o.add_argument("study")
    where = o.add_mutually_exclusive_group(required=True)
    where.add_argument("--workers", type=int, help="start a local cluster of N worker processes")
    where.add_argument("--scheduler", help="address of a running scheduler, tcp://HOST:PORT")
    o.add_argument("--out", default="", help="folder for results.csv, results.json and the report")
    o.add_argument("--force", action="store_true", help="replace the result files in --out")
    o.add_argument("--checkpoint", default=None, help="default: OUT/checkpoint.pkl with --out")
    o.add_argument("--no-plots", action="store_true")
    args = p.parse_args(argv)
    if args.workers is not None and not 1 <= args.workers <= 1024:  # the CLI's range (inerta optimise --workers)
        p.error(f"--workers: {args.workers} is out of range; expected 1 ... 1024")
    if args.scheduler is not None and not args.scheduler.strip():
        p.error("--scheduler: empty; expected the address of a running scheduler, tcp://HOST:PORT")
    checkpoint = args.checkpoint or (os.path.join(args.out, "checkpoint.pkl") if args.out else None)
    resuming = bool(checkpoint) and os.path.exists(checkpoint) and not args.force
    if args.out and not resuming:  # a folder with its study's checkpoint is this study's: resume there
        _inerta.prepare_output_folder(args.out, _inerta.study_output_names(), args.force)
    client, cluster = _client(args)
    try:
        n = len(client.scheduler_info()["workers"])
        print(f"study {args.study}: on {n} Dask worker(s) at {client.scheduler.address}"
              + (f", {'resuming from' if resuming else 'checkpoint'} {checkpoint}" if checkpoint else ""), flush=True)
        t0 = time.perf_counter()

        def report(layout, r, done, total):
            print(f"  [{done}/{total}] {layout:<12} J = {r.cost.J:.4f} N after {r.evaluations} evaluations", flush=True)

        study, default, results = optimise(args.study, client, checkpoint=checkpoint, progress=report)
        wall = time.perf_counter() - t0
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    print(_inerta.study_table(study, default, results), end="")
    print(f"default suspension J2 = {default.J:.3f} N at {default.speed * 3.6:.0f} km/h; wall {wall:.1f} s")
    if args.out:
        _inerta.write_study_results(args.out, study.name, default, results)
        print(f"wrote {args.out}/results.csv and {args.out}/results.json")
        print("post-processing for the figures (on this machine):", flush=True)
        report = _inerta.make_report(study, results)
        files = _inerta.write_study_report(report, args.out)
        print("wrote " + " ".join(os.path.basename(f) for f in files) + f" in {args.out}")
        script = os.path.join(os.environ.get("INERTA_SOURCE_DIR", ""), "scripts", "plot-study")
        if not args.no_plots:
            import subprocess

            if os.path.exists(script) and subprocess.run([script, args.out]).returncode == 0:
                pass
            else:
                print(f"note: no plots (scripts/plot-study not found or failed); the CSV files in {args.out} are complete")
    best = min(results, key=lambda r: r.cost.penalised())
    print(f"best: {best.layout} ({best.expression}) — J2 = {best.cost.J:.3f} N at {best.cost.speed * 3.6:.0f} km/h"
          + ("" if best.cost.feasible else f"; no design keeps the limits: {best.cost.violation}"))
    return 0


if __name__ == "__main__":
    # Run the package's module, not this __main__ copy: the tasks then travel as references to
    # inerta.distributed's functions and its per-worker cache persists between tasks.
    from inerta import distributed as _module

    sys.exit(_module.main())
