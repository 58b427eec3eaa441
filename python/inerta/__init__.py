"""Inerta: inerter-based vibration suppression in multibody systems.

Python bindings of the Inerta C++ library (docs/python.md). SI units throughout: m, s, kg, N,
rad; speeds in m/s (``kmh`` converts km/h), frequencies in Hz.

    import inerta
    m = inerta.load_model("models/twobar.yaml")
    r = inerta.simulate(m, t_end=60)
    r["C_y"].max()
"""
from ._inerta import *  # noqa: F401,F403  (the compiled bindings)
from ._inerta import __doc__ as _bindings_doc  # noqa: F401
from . import _inerta

__version__ = "0.1.0"


def _find_installed_data():
    """An installed package (PREFIX/<site>/inerta, docs/install.md) reads PREFIX/share/inerta's criteria presets,
    models and scripts, not the checkout it was built from."""
    import os

    here = os.path.dirname(os.path.abspath(__file__))
    prefix = here
    for _ in range(len([p for p in _inerta._PYTHON_SITE.split("/") if p]) + 1):
        prefix = os.path.dirname(prefix)
    if os.path.normpath(os.path.join(prefix, _inerta._PYTHON_SITE, "inerta")) == here:
        _inerta._set_data_dir(os.path.join(prefix, _inerta._DATA_DIR))


_find_installed_data()


def kmh(v):
    """Speeds in km/h → m/s (v / 3.6, as the CLI's ``--unit kmh``); a number or an array."""
    import numpy as np

    a = np.asarray(v, dtype=float) / 3.6
    return float(a) if a.ndim == 0 else a


def sweep(model, catenary, speeds, *, client=None, **kwargs):
    """Speed sweep in the time domain (the library's sweep; docs/python.md). With ``client`` (a
    dask.distributed.Client) each speed is a task on the cluster and the result equals the serial
    sweep to the last bit (inerta.distributed.sweep; the model must come from a file, the catenary be
    a file name or load_catenary's CatenaryFile). Other keywords: contact, positions, options, method,
    rtol, atol, progress, as the library's sweep."""
    if client is None:
        return _inerta.sweep(model, catenary, speeds, **kwargs)
    from . import distributed

    return distributed.sweep(model, catenary, speeds, client, **kwargs)


sweep.__doc__ += "\n\nThe library's sweep:\n" + (_inerta.sweep.__doc__ or "")


def optimise(study, *, out=None, client=None, progress=None, checkpoint=None, force=False, stats=None, early_stops=True):
    """Runs a whole design study in one call (the library's study engine, optim::run_study; docs/python.md):
    the default design, the searches, a ``layouts: all`` study's time-domain re-checks, the verified best
    design, the admittance bounds and, with ``out``, the report's data and every file ``inerta optimise
    --out`` writes (the same bytes but for wall-clock columns). Returns a StudyOutcome: ``o.best`` has
    ``layout``, ``expression``, ``values`` and ``J2``.

    study: a Study, a ModelStudy or a study file's path. client: a dask.distributed.Client — the engine's
    searches and evaluations become Dask tasks (inerta.distributed.DaskExecutor; studies from a file),
    the outcome equal to the serial run's; ``checkpoint`` (default ``out/checkpoint.pkl``) keeps what
    finished, and the same call again resumes there. progress(event, *values): see run_study. force:
    replace the result files in ``out`` (and start afresh). stats: a dict that receives the Dask tasks
    sent ("designs_sent", "searches_sent", "checks_sent"). early_stops: stop the re-checks and a screen's
    evaluations once they cannot win (exact: the same winner and networks refined; a stopped design's J is a
    lower bound, ``stopped`` set); False evaluates every one in full."""
    import os

    # The arguments checked here, by name (issue 52), not deep inside a running study.
    if isinstance(study, (str, os.PathLike)):
        path = os.fspath(study)
        study = _inerta.load_model_study(path) if _inerta.is_model_study(path) else _inerta.load_study(path)
    elif not isinstance(study, (_inerta.Study, _inerta.ModelStudy)):
        raise TypeError(f"optimise: study: expected a Study, a ModelStudy or a study file's path, got {type(study).__name__}")
    if progress is not None and not callable(progress):
        raise TypeError(f"optimise: progress: expected a callable progress(event, *values), got {type(progress).__name__}")
    if not isinstance(early_stops, bool):
        raise TypeError(f"optimise: early_stops: expected True or False, got {type(early_stops).__name__}")
    if out is not None and not isinstance(out, (str, os.PathLike)):
        raise TypeError(f"optimise: out: expected a folder's path, got {type(out).__name__}")
    if client is None:
        for name, value in (("checkpoint", checkpoint), ("stats", stats)):
            if value is not None:
                raise ValueError(f"optimise: {name}= is about the Dask tasks and needs client=; without a client the "
                                 "study runs in this process (no checkpoint, no task counts)")
    else:
        if not (hasattr(client, "submit") and hasattr(client, "gather")):
            raise TypeError(f"optimise: client: expected a dask.distributed.Client, got {type(client).__name__}")
        if stats is not None and not isinstance(stats, dict):
            raise TypeError(f"optimise: stats: expected a dict that receives the task counts, got {type(stats).__name__}")
        if checkpoint is not None and not isinstance(checkpoint, (str, os.PathLike)):
            raise TypeError(f"optimise: checkpoint: expected a file's path, got {type(checkpoint).__name__}")
    executor = None
    if client is not None:
        from . import distributed

        if checkpoint is None and out is not None:
            checkpoint = os.path.join(os.fspath(out), "checkpoint.pkl")
        if checkpoint is not None and force and os.path.exists(checkpoint):
            os.remove(checkpoint)
        executor = distributed.DaskExecutor(study, client, checkpoint=checkpoint, stats=stats)
    if out is not None:
        out = os.fspath(out)
        resuming = executor is not None and checkpoint is not None and os.path.exists(checkpoint)
        if not resuming:  # a folder with its study's checkpoint is this study's: resume there
            _inerta.prepare_output_folder(out, _inerta.study_output_names(), force)
    outcome = _inerta.run_study(study, _inerta.StudyOptions(report=out is not None, early_stops=early_stops), progress=progress,
                                executor=executor)
    if out is not None:
        _inerta.write_study_outcome(outcome, out)
        _inerta.write_study_report(outcome, out)
    return outcome


def __getattr__(name):  # inerta.distributed on first use (PEP 562): `python3 -m inerta.distributed` stays clean
    if name == "distributed":
        import importlib

        return importlib.import_module(".distributed", __name__)
    raise AttributeError(f"module 'inerta' has no attribute '{name}'")


def plot_sweep(result, ax=None, label=None, unit="kmh", **kwargs):
    """Draws σ of the contact force against speed for a SweepResult on a matplotlib axis
    (created if None); returns the axis. unit: 'kmh' or 'ms' for the horizontal axis."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots()
    v = result.speed * (3.6 if unit == "kmh" else 1.0)
    ax.plot(v, result.std, marker="o", markersize=3, label=label, **kwargs)
    ax.set_xlabel("speed [km/h]" if unit == "kmh" else "speed [m/s]")
    ax.set_ylabel("σ of the contact force [N]")
    ax.grid(True, alpha=0.3)
    if label is not None:
        ax.legend()
    return ax


def plot_result(result, names=None, ax=None, **kwargs):
    """Draws outputs of a Result (all, or `names`) against time on a matplotlib axis; returns it."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots()
    for n in names or result.names:
        ax.plot(result.t, result[n], label=n, **kwargs)
    ax.set_xlabel("t [s]")
    ax.legend()
    ax.grid(True, alpha=0.3)
    return ax


__all__ = [n for n in dir(_inerta) if not n.startswith("_")] + ["kmh", "optimise", "plot_sweep", "plot_result", "sweep"]
