"""simulate: the same numbers as `inerta simulate`, results as views of the library's memory,
progress and options."""
import gc

import numpy as np
import pytest

import inerta
from conftest import model, read_csv


@pytest.mark.parametrize("centripetal", [True, False])
def test_twobar_equals_cli(cli, tmp_path, twobar, centripetal):
    """The two-bar mechanism over 60 s, with and without the inerter's centripetal correction."""
    out = tmp_path / "tb.csv"
    cli("simulate", model("twobar.yaml"), "--t-end", 60, "--sample", 0.001, "--out", out,
        *([] if centripetal else ["--no-centripetal"]))
    ref = read_csv(out)
    m = twobar if centripetal else twobar.with_options(centripetal=False)
    r = inerta.simulate(m, t_end=60, sample=0.001)
    assert r.names == ["C_x", "C_y"]
    assert r.n_samples == len(ref["t"]) == 60001
    # the CSV holds 10 significant digits
    np.testing.assert_allclose(r.t, ref["t"], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(r["C_y"], ref["C_y"], rtol=1e-8, atol=1e-9)
    assert r["C_y"].max() == pytest.approx(ref["C_y"].max(), rel=1e-9)
    assert r.stats.steps > 0 and r.t_end == 60 and r.sample == 0.001


def test_correction_changes_the_motion(twobar):
    on = inerta.simulate(twobar, t_end=10)
    off = inerta.simulate(twobar.with_options(centripetal=False), t_end=10)
    assert abs(on["C_y"][-1] - off["C_y"][-1]) > 1e-3


def test_arrays_share_memory_with_the_result(twobar):
    r = inerta.simulate(twobar, t_end=1, sample=0.01)
    a, b = r["C_y"], r["C_y"]
    assert np.shares_memory(a, b)  # both are views of the library's vector, not copies
    assert np.shares_memory(r.t, r["t"])
    assert not a.flags.writeable and not a.flags.owndata
    assert not np.shares_memory(r.data, a)  # data is documented as a copy
    np.testing.assert_array_equal(r.data[1], a)
    d = r.to_dict()
    assert np.shares_memory(d["C_x"], r["C_x"])
    expected = a.copy()
    del r, d, b
    gc.collect()
    np.testing.assert_array_equal(a, expected)  # the view keeps the result alive
    with pytest.raises(ValueError):
        a[0] = 1.0


def test_result_protocol(twobar):
    r = inerta.simulate(twobar, t_end=0.5, sample=0.1)
    assert len(r) == 2 and list(r) == ["C_x", "C_y"] and r.keys() == ["C_x", "C_y"]
    assert "C_y" in r and "t" in r and "nope" not in r
    with pytest.raises(KeyError, match="no output 'nope'; outputs: t, C_x, C_y"):
        r["nope"]
    assert r.data.shape == (2, 6)
    s = inerta.summarise(r, 0.2)
    assert [x.name for x in s] == ["C_x", "C_y"] and s[1].samples == 4
    assert r.summary(0.2)[1].max == pytest.approx(r["C_y"][2:].max())
    assert "6 samples" in repr(r)


def test_options_and_steady_summary(twobar, cli):
    r = inerta.simulate(twobar, 2.0, 0.01, method="bdf", rtol=1e-7, atol=1e-9, steady_from=1.0)
    assert r.steady[1].name == "C_y" and r.steady[1].samples == 101
    o = inerta.IntegratorOptions("bdf", rtol=1e-7, atol=1e-9)
    r2 = inerta.simulate(twobar, 2.0, 0.01, integrator=o)
    np.testing.assert_array_equal(r["C_y"], r2["C_y"])
    assert o.method == "bdf" and "bdf" in repr(o)
    out = cli("simulate", model("twobar.yaml"), "--t-end", 2, "--sample", 0.01, "--integrator", "bdf",
              "--rtol", 1e-7, "--atol", 1e-9, "--steady-from", 1).stderr
    line = next(l for l in out.splitlines() if l.strip().startswith("C_y"))
    mn, mx = map(float, line.split()[2:4])
    assert r.steady[1].min == pytest.approx(mn, rel=1e-5) and r.steady[1].max == pytest.approx(mx, rel=1e-5)
    with pytest.raises(ValueError):
        inerta.simulate(twobar, 1.0, method="euler")


def test_defaults_from_the_model_and_equilibrium():
    m = inerta.load_model(model("onedof.yaml"))
    r = inerta.simulate(m, from_equilibrium=True, t_end=0.2)
    assert r.equilibrium is not None and r.equilibrium.iterations >= 0
    assert r.assembly.residual < 1e-9
    r = inerta.simulate(m.with_options(t_end=0.3, sample=0.1))
    assert r.n_samples == 4


def test_progress_is_called_on_the_calling_thread(twobar):
    import threading

    calls = []
    main = threading.get_ident()
    r = inerta.simulate(twobar, t_end=5, progress=lambda t, te: calls.append((t, te, threading.get_ident())))
    assert len(calls) >= 10
    assert all(c[2] == main for c in calls)
    assert all(te == 5 for _, te, _ in calls) and calls[-1][0] <= 5
    assert r.n_samples > 0


def test_progress_exception_stops_the_run(twobar):
    class Stop(Exception):
        pass

    def progress(t, te):
        if t > 1:
            raise Stop("enough")

    with pytest.raises(Stop):
        inerta.simulate(twobar, t_end=60, progress=progress)


def test_spatial_model():
    m = inerta.load_model(model("twobar3d.yaml"))
    assert m.dimension == 3 and m.n_coords == 14
    r = inerta.simulate(m, t_end=1, sample=0.01)
    assert np.isfinite(r["C_y"]).all()


def test_ctrl_c_stops_a_long_run(twobar):
    import os
    import signal
    import threading
    import time

    timer = threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT))
    t0 = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            inerta.simulate(twobar, t_end=5000, sample=0.01)  # several seconds of work
    finally:
        timer.cancel()
    # stopped at the next progress report (every t_end/50 of simulated time)
    t = time.perf_counter() - t0
    r = inerta.simulate(twobar, t_end=100, sample=0.01)
    assert t < 0.2 + 0.5 + 3 * r.wall_s  # r.wall_s: the time of 1/50 of the long run


@pytest.mark.parametrize("arg,option,value", [("t_end", "--t-end", 0), ("t_end", "--t-end", -1),
                                              ("t_end", "--t-end", float("nan")), ("t_end", "--t-end", 1e8),
                                              ("sample", "--sample", 0), ("sample", "--sample", float("inf")),
                                              ("rtol", "--rtol", 0), ("rtol", "--rtol", 2),
                                              ("rtol", "--rtol", float("nan")), ("atol", "--atol", 0),
                                              ("atol", "--atol", -1), ("max_step", "--max-step", -1),
                                              ("max_step", "--max-step", float("inf"))])
def test_run_length_refused_as_by_the_cli(twobar, arg, option, value):
    """t_end, sample, rtol, atol and max_step follow the CLI's rule (analysis::t_end_rule, sample_rule,
    solve::rtol_rule, atol_rule, max_step_rule) with its message; not given (None), the model's options apply."""
    from conftest import run_cli
    text = {0: "0", -1: "-1", 1e8: "1e8", 2: "2"}.get(value, str(value))
    r = run_cli("simulate", model("twobar.yaml"), option, text, check=False)
    assert r.returncode == 105
    cli_message = r.stderr.splitlines()[0].split(": ", 1)[1]  # after "--t-end: "
    with pytest.raises(inerta.InvalidArgument) as e:
        inerta.simulate(twobar, **{arg: value})
    py_message = str(e.value).split(": ", 1)[1]  # after "t_end: "
    assert py_message.split("; expected")[-1] == cli_message.split("; expected")[-1]
    assert ("out of range" in py_message) == ("out of range" in cli_message)
    assert ("finite" in py_message) == ("finite" in cli_message)
