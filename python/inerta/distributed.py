"""Sweeps and design studies on a Dask cluster (docs/distributed.md).

The C++ library does the work in each Dask worker process; this module only cuts it into tasks and
puts the results back in order, so a distributed run gives the serial run's numbers to the last bit:

* ``sweep(model, catenary, speeds, client)``: one task per speed (inerta.sweep(..., client=c) calls
  it). The model travels as its file's text and overrides, a catenary as its file's path and
  overrides: a worker reads each once and keeps it (a finite-element line's modes too).
* ``DaskExecutor``: the study engine's executor (inerta.optimise(study, client=c) uses it; ``optimise``
  here is that call): the engine's searches and evaluations become tasks — by the periodic fast path
  (milliseconds an evaluation) one task per search (a layout, or a network of ``layouts: all`` with the
  warm start from its sub-networks, the networks of one size at once); in the time domain one task per
  design (each search runs here in a thread and sends its polls' designs to the workers, all searches at
  once); a model study's the same way (its layouts a task each, in turn; a network of ``layouts: all`` a
  task). Each finished search, design and check is written to the checkpoint at once; a study started
  again with the same checkpoint runs only what it lacks and evaluates no design twice (the engine is
  deterministic: it replays to where it stopped).

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


# ---- Studies: the study engine's evaluations as Dask tasks ------------------------------------------

def _load(path):
    return _inerta.load_model_study(path) if _inerta.is_model_study(path) else _inerta.load_study(path)


def _study(path, stamp):
    return _cached(("study", path, stamp), lambda: _load(path))


def _search_task(path, stamp, task):
    return _inerta.run_search(_study(path, stamp), task)


def _design_task(path, stamp, layout, params):
    return _inerta.design_cost(_study(path, stamp), layout, params)


def _check_task(path, stamp, task):
    return _inerta.run_check(_study(path, stamp), task)


def _read_checkpoint(path, study_path, stamp):
    """(finished searches, evaluated designs, checks) of a checkpoint file, or three empty dicts."""
    if not path or not os.path.exists(path):
        return {}, {}, {}
    with open(path, "rb") as f:
        data = pickle.load(f)
    if data.get("study") != study_path or data.get("stamp") != stamp:
        raise RuntimeError(f"{path}: a checkpoint of another study or of an earlier version of {study_path} "
                           "(its file changed); remove it to start again")
    return data["layouts"], data.get("designs", {}), data.get("checks", {})


def _write_checkpoint(path, study_path, stamp, layouts, designs, checks):
    tmp = f"{path}.{os.getpid()}.{threading.get_ident()}.tmp"
    with open(tmp, "wb") as f:
        pickle.dump({"study": study_path, "stamp": stamp, "layouts": layouts, "designs": designs, "checks": checks}, f)
    os.replace(tmp, path)  # never a half-written checkpoint


def _params_key(params):
    return tuple(sorted(params.items()))


def _search_key(task):
    return (task.layout, task.network, task.coarse, task.refine, tuple(_params_key(w) for w in task.warm))


class DaskExecutor(_inerta.StudyExecutor):
    """The study engine's executor on a Dask cluster (inerta.optimise(client=...)): its searches and checks
    become tasks, results equal to the serial run's. By the periodic fast path (milliseconds an evaluation)
    one task per search (a layout, or a network of layouts: all with its warm start); in the time domain one
    task per design: each search runs here in a thread and sends every poll's designs to the workers, all
    searches at once. The checks (the default, the re-checks) are a task each. A model study (ModelStudy) goes
    through the same methods: its searches and checks are tasks. Every finished
    search, design and check is written to the checkpoint at once; a study started again with it runs only
    what it lacks (the engine is deterministic: it replays to where it stopped)."""

    def __init__(self, study, client, *, checkpoint=None, stats=None):
        super().__init__()
        if not study.source or study.source.startswith("<"):
            raise ValueError("inerta.distributed: the workers read the study from its file; this Study was built in "
                             "Python — load it with inerta.load_study(path)")
        self.client = client
        self.path = os.path.abspath(study.source)
        st = os.stat(self.path)
        self.stamp = (st.st_mtime_ns, st.st_size)
        self.checkpoint = os.fspath(checkpoint) if checkpoint is not None else None
        self.searches, self.designs, self.checks = _read_checkpoint(self.checkpoint, self.path, self.stamp)
        self.stats = stats if stats is not None else {}
        for k in ("designs_sent", "searches_sent", "checks_sent"):
            self.stats[k] = 0
        self.lock = threading.Lock()
        self.stop = threading.Event()  # set when the study stops early: running searches stop at their next poll

    def _save(self):
        if self.checkpoint:
            _write_checkpoint(self.checkpoint, self.path, self.stamp, self.searches, self.designs, self.checks)

    def _batch(self, layout):
        def batch(params):  # one task per design not evaluated yet, gathered in order
            if self.stop.is_set():
                raise KeyboardInterrupt("the study was stopped")
            keys = [(layout, _params_key(p)) for p in params]
            with self.lock:
                missing = [i for i, k in enumerate(keys) if k not in self.designs]
            futures = [self.client.submit(_design_task, self.path, self.stamp, layout, params[i], pure=False)
                       for i in missing]
            costs = self.client.gather(futures)
            with self.lock:
                for i, c in zip(missing, costs):
                    self.designs[keys[i]] = c
                self.stats["designs_sent"] += len(missing)
                self._save()
                return [self.designs[k] for k in keys]
        return batch

    def search(self, study, tasks, done, searching):
        from distributed import as_completed

        results = [None] * len(tasks)
        keys = [_search_key(t) for t in tasks]
        todo = []
        for i, k in enumerate(keys):
            if k in self.searches:
                results[i] = self.searches[k]
            else:
                todo.append(i)
        for i in range(len(tasks)):  # the checkpoint's first, in order
            if results[i] is not None:
                done(i, results[i])

        def finished(i, r):
            results[i] = r
            with self.lock:
                self.searches[keys[i]] = r
                self._save()
            done(i, r)

        if not todo:
            return results
        # A time-domain search runs here and sends its designs; a coarse one (the exhaustive search of a
        # multi-fidelity layouts: all, by the periodic fast path) is a task of its own.
        if isinstance(study, _inerta.Study) and study.method == "time" and not any(tasks[i].coarse for i in todo):
            with concurrent.futures.ThreadPoolExecutor(max_workers=len(todo)) as pool:
                running = {pool.submit(_inerta.run_search, study, tasks[i], batch=self._batch(tasks[i].layout)): i
                           for i in todo}
                try:
                    for fut in concurrent.futures.as_completed(running):
                        finished(running[fut], fut.result())
                except BaseException:
                    self.stop.set()
                    raise
        else:
            futures = {self.client.submit(_search_task, self.path, self.stamp, tasks[i], pure=False): i for i in todo}
            self.stats["searches_sent"] += len(futures)
            for fut in as_completed(list(futures)):
                finished(futures[fut], fut.result())
        return results

    def check(self, study, tasks):
        keys = [(t.layout, _params_key(t.values), t.time, t.stop_above, t.stop_catenary,
                 t.stop_speed if t.stop_speed == t.stop_speed else None) for t in tasks]  # NaN: no key equals it
        missing = [i for i, k in enumerate(keys) if k not in self.checks]
        futures = [self.client.submit(_check_task, self.path, self.stamp, tasks[i], pure=False) for i in missing]
        self.stats["checks_sent"] += len(futures)
        for i, r in zip(missing, self.client.gather(futures)):
            self.checks[keys[i]] = r
        if missing:
            with self.lock:
                self._save()
        return [self.checks[k] for k in keys]


def optimise(study, client, *, out=None, checkpoint=None, progress=None, stats=None, force=False, early_stops=True):
    """inerta.optimise(study, client=client, ...): the study engine with its evaluations on the cluster."""
    from . import optimise as _optimise

    return _optimise(study, out=out, client=client, progress=progress, checkpoint=checkpoint, force=force, stats=stats,
                     early_stops=early_stops)


def _j2_progress(study):
    """The driver's view of a J2 study's progress events (the CLI's lines and tables)."""
    objective, unit = ("J2", " N") if study.objective == "j2" else ("sigma/F_m", "")

    def report(event, *values):
        if event == "searched":
            i, r = values
            print(f"  [{i + 1}/{len(study.layouts)}] {study.layouts[i]:<12} J = {r.cost.J:.4f}{unit} after "
                  f"{r.evaluations} evaluations", flush=True)
        elif event == "network" and (values[0] == values[1] or values[0] % max(1, values[1] // 20) == 0):
            print(f"  [{values[0]}/{values[1]}] networks, best {objective} so far {values[2]:.4f}{unit}", flush=True)
        elif event == "screening":
            print(f"\n  screening the best {len(values[0])} distinct reduced networks of the coarse search on this study "
                  f"(each at its coarse optimum); the best {study.refine_networks} by that are refined", flush=True)
        elif event == "refining":
            stage = "screen" if study.refine_screen > study.refine_networks else "coarse search"
            print(f"\n  refining the best {len(values[0])} distinct reduced networks of the {stage} on this study:",
                  flush=True)
        elif event == "refined":
            k, r = values
            print(f"    {k + 1}. {r.expression:<28} here {r.coarse_here.J:.4f}{unit} -> refined {r.cost.J:.4f}{unit} after "
                  f"{r.evaluations} evaluations" + ("" if r.cost.feasible else f"; outside the limits: {r.cost.violation}"),
                  flush=True)
        elif event == "searches_done":
            o = values[0]
            if study.all_networks and study.coarse is not None:
                print(f"\n  the refined networks, ranked by this study's {objective} (default {o.default_cost.J:.4f}{unit}):")
                for r, f in zip(o.results, o.refinements):
                    if r.stock:  # the stock suspension, ranked with them (a commissioned study)
                        print(f"    {'default ' + r.expression:<28} {r.cost.J:.4f}{unit}"
                              + ("" if r.cost.feasible else f"; outside: {r.cost.violation}"))
                        continue
                    e = o.entries[f.entry]
                    print(f"    {r.expression:<28} coarse {e.J:.4f}{unit} (#{f.coarse_rank}"
                          + (f", screen #{f.screen_rank}" if f.screen_rank else "") + f"), start {r.coarse_here.J:.4f}{unit}, "
                          f"refined {r.cost.J:.4f}{unit}" + ("" if r.cost.feasible else f"; outside: {r.cost.violation}"))
                if o.screened and o.rank_agreement == o.rank_agreement:
                    print(f"    rank agreement with this study's order (Spearman): the screen's {o.rank_agreement:.3f}, "
                          f"the coarse search's {o.coarse_rank_agreement:.3f}")
                elif o.rank_agreement == o.rank_agreement:
                    print(f"    rank agreement of the coarse and the fine stage (Spearman): {o.rank_agreement:.3f}")
            elif study.all_networks:
                print("\n  best networks (periodic fast path):")
                for r in o.results[:10]:
                    print(f"    {r.expression:<40} J2 = {r.cost.J:.4f} N")
                print("  time-domain re-check (ranked by the time-domain J2):")
                for c in o.rechecks:
                    e = o.entries[c.entry]
                    time = (f"failed ({c.failure})" if c.failure else f"stopped: J2 ≥ {c.time.J:.4f} N" if c.stopped
                            else f"{c.time.J:.4f} N")
                    print(f"    {e.reduced:<44} periodic {e.J:.4f} N, time {time}")
            else:
                print(_inerta.study_table(study, o.default_cost, o.results), end="")
            print(f"default suspension {objective} = {o.default_cost.J:.4f}{unit} at {o.default_cost.speed * 3.6:.0f} km/h; "
                  f"wall {o.seconds:.1f} s", flush=True)
        elif event == "bound":
            b = values[0]
            print(f"  admittance bound, degree {b.result.degree}: J = {b.result.J:.6g} N", flush=True)
        elif event == "report" and values[2]:
            print(f"  [{values[0]}/{values[1]}] {values[2]}", flush=True)

    return report


def _model_progress(study):
    """The driver's view of a model study's progress events (the CLI's lines and table)."""
    n = len(study.layouts)

    def report(event, *values):
        if event == "searched":
            i, r = values
            print(f"  [{i + 1}/{n}] {study.layouts[i]:<14} J = {r.cost.J:.6g}"
                  + ("" if r.cost.feasible else " (a limit is exceeded)") + f" after {r.evaluations} evaluations", flush=True)
        elif event == "network" and (values[0] == values[1] or values[0] % max(1, values[1] // 20) == 0):
            print(f"  [{values[0]}/{values[1]}] networks, best J so far {values[2]:.6g}", flush=True)
        elif event == "searches_done":
            m = values[0].model
            print(_inerta.model_study_table(m), end="")
            if m.entries:
                print(f"{len(m.entries)} networks, {sum(e.evaluations for e in m.entries)} evaluations", flush=True)
        elif event == "bound":
            b = values[0]
            print(f"  admittance bound, degree {b.result.degree}: J = {b.result.J:.6g}", flush=True)

    return report


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
    o.add_argument("--no-early-stops", action="store_true",
                   help="evaluate every re-check and screened design in full (the early stops are exact)")
    args = p.parse_args(argv)
    if args.workers is not None and not 1 <= args.workers <= 1024:  # the CLI's range (inerta optimise --workers)
        p.error(f"--workers: {args.workers} is out of range; expected 1 ... 1024")
    if args.scheduler is not None and not args.scheduler.strip():
        p.error("--scheduler: empty; expected the address of a running scheduler, tcp://HOST:PORT")
    checkpoint = args.checkpoint or (os.path.join(args.out, "checkpoint.pkl") if args.out else None)
    resuming = bool(checkpoint) and os.path.exists(checkpoint) and not args.force
    study = _load(args.study)
    client, cluster = _client(args)
    try:
        n = len(client.scheduler_info()["workers"])
        print(f"study {args.study}: on {n} Dask worker(s) at {client.scheduler.address}"
              + (f", {'resuming from' if resuming else 'checkpoint'} {checkpoint}" if checkpoint else ""), flush=True)

        report = _model_progress(study) if isinstance(study, _inerta.ModelStudy) else _j2_progress(study)
        out = args.out or None
        o = optimise(args.study, client, out=out, checkpoint=checkpoint, progress=report, force=args.force,
                     early_stops=not args.no_early_stops)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    model = isinstance(study, _inerta.ModelStudy)
    if args.out:
        print(f"wrote the study's files in {args.out} (as `inerta optimise --out`)")
        scripts = os.path.join(_inerta.data_dir(), "scripts")
        if not args.no_plots:
            import subprocess

            every = bool(o.model.entries) if model else study.all_networks
            for name in (["plot-structure"] if every else []) + ["plot-model-study" if model else "plot-study"]:
                script = os.path.join(scripts, name)
                if not (os.path.exists(script) and subprocess.run([sys.executable, script, args.out]).returncode == 0):
                    print(f"note: no plots (scripts/{name} not found or failed); the CSV files in {args.out} are complete")
    if model:  # the table's last line names the best design
        return 0
    best = o.results[o.best.index]
    stock = "the stock suspension " if o.stock_best else ""
    if study.method == "time" and study.objective == "sigma_over_mean":
        c = best.cost
        print(f"best: {stock}{best.layout} ({best.expression}) — sigma/F_m = {c.J:.4f} (σ {c.sigma:.3f} N, F_m {c.mean:.2f} N) "
              f"at {c.speed * 3.6:.0f} km/h (time domain)" + ("" if c.feasible else f"; no design keeps the limits: {c.violation}"))
    elif study.method == "time":
        print(f"best: {stock}{best.layout} ({best.expression}) — J2 = {best.cost.J:.3f} N at {best.cost.speed * 3.6:.0f} km/h "
              "(time domain)" + ("" if best.cost.feasible else f"; no design keeps the limits: {best.cost.violation}"))
    else:
        t = o.time_check
        print(f"best: {best.layout} ({best.expression}) — time-domain re-check J2 = {t.J:.3f} N at {t.speed * 3.6:.0f} "
              f"km/h (periodic {best.cost.J:.3f} N, {100 * (best.cost.J - t.J) / t.J:+.2f} %)")
    return 0


if __name__ == "__main__":
    # Run the package's module, not this __main__ copy: the tasks then travel as references to
    # inerta.distributed's functions and its per-worker cache persists between tasks.
    from inerta import distributed as _module

    sys.exit(_module.main())
