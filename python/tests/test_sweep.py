"""Sweeps and runs under a catenary: the same σ as `inerta sweep`/`simulate --catenary`, progress
on the calling thread, cancellation."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import inerta
from conftest import model, read_csv

SPEEDS_KMH = [150, 200, 250]


def test_sweep_equals_cli(cli, tmp_path, hsx, lumped):
    out = tmp_path / "s.csv"
    cli("sweep", model("hsx.yaml"), "--catenary", model("catenary.yaml"), "--speeds", "150:50:250", "--unit", "kmh",
        "--out", out)
    ref = read_csv(out)
    done = []
    r = inerta.sweep(hsx, lumped, inerta.kmh(SPEEDS_KMH), progress=lambda d, n: done.append((d, n)))
    assert len(r) == 3 and r.method == "time"
    np.testing.assert_allclose(r.speed, ref["v_ms"], rtol=1e-5)
    np.testing.assert_allclose(r.std, ref["std"], rtol=1e-5)  # the CSV has 6 significant digits
    np.testing.assert_allclose(r.mean, ref["mean"], rtol=1e-5)
    np.testing.assert_allclose(r.stat_max, ref["stat_max"], rtol=1e-5)
    np.testing.assert_allclose(r.loss_pct, ref["loss_pct"], atol=1e-12)
    assert done == [(1, 3), (2, 3), (3, 3)]
    sigma, v, mean = r.sigma_max
    assert v == pytest.approx(200 / 3.6) and sigma == r.std.max()
    assert r[1].speed == r.speed[1] and r[-1].stats.std == r.std[-1] and len(r[0].contacts) == 1
    assert (r.spans >= 6).all() and r.wall_s > 0
    assert len(r[0].F) == 0  # sweeps keep no histories


def test_sweep_periodic_equals_cli(cli, tmp_path, hsx, lumped):
    out = tmp_path / "p.csv"
    cli("sweep", model("hsx.yaml"), "--catenary", model("catenary.yaml"), "--speeds", "100:50:300", "--unit", "kmh",
        "--method", "periodic", "--harmonics", 6, "--out", out)
    ref = read_csv(out)
    r = inerta.sweep_periodic(hsx, lumped, inerta.kmh([100, 150, 200, 250, 300]), harmonics=6)
    assert r.method == "periodic"
    np.testing.assert_allclose(r.std, ref["std"], rtol=1e-5)
    np.testing.assert_allclose(r.mean, ref["mean"], rtol=1e-5)


def test_suspension_and_overrides_match_cli(cli, tmp_path, hsx):
    out = tmp_path / "s21.csv"
    cli("sweep", model("hsx.yaml"), "--catenary", model("catenary.yaml"), "--set", "catenary.kc0=5000",
        "--suspension", "S2-1", "--param", "b=500", "--param", "c=100", "--param", "k=50e3", "--speeds", "200:1:200",
        "--unit", "kmh", "--out", out)
    ref = read_csv(out)
    cat = inerta.load_catenary(model("catenary.yaml"), {"catenary.kc0": 5000})
    assert cat.catenary.point_model().k[0] == 5000
    m = hsx.with_suspension("S2-1", {"b": 500, "c": 100, "k": 50e3})
    assert len(m.history) == 1 and m.history[0] == "suspension b=500|c=100|k=50000"
    r = inerta.sweep(m, cat, [200 / 3.6])
    assert r.std[0] == pytest.approx(ref["std"][0], rel=1e-5)


def test_simulate_coupled_equals_cli(cli, tmp_path, hsx, lumped):
    out = tmp_path / "c.csv"
    cli("simulate", model("hsx.yaml"), "--catenary", model("catenary.yaml"), "--speed", 180, "--unit", "kmh",
        "--spans", 3, "--out", out)
    ref = read_csv(out)
    r = inerta.simulate_coupled(hsx, lumped, inerta.kmh(180), spans=3)
    assert r.names[-1] == "F_contact" and len(r.histories) == 1
    np.testing.assert_allclose(r.t, ref["t"], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(r["F_contact"], ref["F_contact"], rtol=1e-8, atol=1e-8)
    assert np.shares_memory(r["F_contact"], r.histories[0]["F_contact"])
    c = r.contacts[0]
    assert c.stats.mean == pytest.approx(r["F_contact"][r.t >= r.window_from - 1e-9].mean(), rel=1e-9)
    assert r.speed == pytest.approx(50) and r.span == 60 and r.t_end == pytest.approx(3 * 60 / 50)


def test_two_pantographs_on_a_wire_profile(cli, tmp_path, hsx):
    prof = inerta.load_catenary(model("wire-profile.yaml"))
    assert prof.catenary.type == "wire_profile" and prof.contact.kind == "penalty"
    out = tmp_path / "p2.csv"
    cli("simulate", model("hsx.yaml"), "--catenary", model("wire-profile.yaml"), "--speed", 100, "--unit", "kmh",
        "--positions", "0,30", "--spans", 2, "--out", out)
    ref = read_csv(out)
    r = inerta.simulate_coupled(hsx, prof, inerta.kmh(100), positions=[0, 30], spans=2)
    assert len(r.histories) == 2 and len(r.contacts) == 2
    np.testing.assert_allclose(r.histories[1]["F_contact"], ref["p2.F_contact"], rtol=1e-7, atol=1e-7)
    # the same from PantographOnLine objects
    line = [inerta.PantographOnLine(hsx, 0.0, prof.contact), inerta.PantographOnLine(hsx, 30.0, prof.contact)]
    r2 = inerta.simulate_coupled(line, prof.catenary, inerta.kmh(100), spans=2)
    np.testing.assert_array_equal(r2.histories[1]["F_contact"], r.histories[1]["F_contact"])


def test_catenaries_from_python_objects(hsx, lumped):
    own = inerta.Lumped(inerta.LumpedCatenary())  # the default set, as models/catenary.yaml
    assert own.point_model().k == lumped.catenary.point_model().k
    a = inerta.sweep_periodic(hsx, own, [50.0])
    b = inerta.sweep_periodic(hsx, lumped, [50.0])
    assert a.std[0] == pytest.approx(b.std[0], rel=1e-12)
    mean = own.mean()
    assert mean.point_model().k[1:] == [0, 0, 0] and mean.type == "lumped"
    x = np.linspace(0, 60, 13)
    profile = inerta.WireProfileCatenary(inerta.WireProfile(list(x), list(-0.06 * (1 - ((x - 30) / 30) ** 2))))
    assert profile.span == 60 and profile.max_pantographs > 1 and profile.point_model() is None
    s = inerta.sweep(hsx, profile, [100 / 3.6], contact=inerta.Contact("penalty", 50e3))
    assert s.std[0] > 0
    assert inerta.Contact().kind == "bilateral" and inerta.kind_name(inerta.Contact("penalty")) == "penalty"
    assert lumped.catenary.line_length == float("inf") and lumped.catenary.section()[0] == 0


def test_run_speed_keeps_the_history(hsx, lumped):
    s = inerta.run_speed(hsx, lumped, 50.0, options=inerta.RunOptions(min_spans=6, fixed_spans=True))
    assert s.spans == 6 and len(s.t) == len(s.F) > 6 * 400
    st = inerta.statistics(s.F[-800:])
    assert st.std == pytest.approx(s.stats.std, rel=1e-9)
    assert np.shares_memory(s.F, s.F)


def test_couple_lumped(hsx, lumped):
    c = inerta.couple_lumped(hsx, lumped.catenary.point_model(), lumped.contact, 50.0)
    assert c.model.n_coords == hsx.n_coords + 3 and c.bilateral
    assert c.model.output_names[-1] == "F_contact" and c.model.forces[c.element].type == "catenary"


@pytest.fixture(scope="module")
def round_time(hsx, lumped):
    """Wall time of a sweep of 4 speeds on this machine now (two rounds of the two cores): a
    load-independent yardstick for how long the running speeds of a cancelled sweep may take."""
    t0 = time.perf_counter()
    inerta.sweep(hsx, lumped, inerta.kmh([100, 200, 250, 300]))
    return time.perf_counter() - t0


def test_callback_exception_cancels_a_sweep(hsx, lumped, round_time):
    class Stop(Exception):
        pass

    def progress(done, total):
        raise Stop(f"{done}/{total}")

    t0 = time.perf_counter()
    with pytest.raises(Stop, match="1/51"):
        inerta.sweep(hsx, lumped, inerta.kmh(np.arange(50, 301, 5)), progress=progress)
    assert time.perf_counter() - t0 < 2 * round_time  # the whole sweep takes about 12 rounds


def test_ctrl_c_cancels_a_sweep(hsx, lumped, round_time):
    """SIGINT during a sweep (as Ctrl-C) raises KeyboardInterrupt once the running speeds finish."""
    speeds = inerta.kmh(np.arange(50, 301, 5))
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    t0 = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            inerta.sweep(hsx, lumped, speeds)
    finally:
        timer.cancel()
    assert time.perf_counter() - t0 < 0.3 + 2 * round_time  # the whole sweep takes about 12 rounds
    # the module still works afterwards
    assert len(inerta.sweep(hsx, lumped, [50.0])) == 1


def test_sweep_periodic_flags_unstable_speeds(hsx):
    """Issue 15: kc1 = 6500 N/m at 380–400 km/h is a parametric resonance (Floquet multiplier > 1)."""
    cat = inerta.load_catenary(model("catenary.yaml"), ["catenary.kc1=6500"])
    r = inerta.sweep_periodic(hsx, cat, inerta.kmh([380, 390, 400]))
    assert list(r.stable) == [0, 0, 0]
    assert min(r.floquet) > 1
    assert np.isnan(r.std).all() and not r[1].stable
    with pytest.raises(ValueError, match="no stable speed"):
        r.sigma_max
    s = inerta.sweep_periodic(hsx, inerta.load_catenary(model("catenary.yaml")), inerta.kmh([100, 200]))
    assert list(s.stable) == [1, 1] and max(s.floquet) < 1


def test_time_sweep_says_whether_it_settled(hsx, lumped):
    r = inerta.sweep(hsx, lumped, inerta.kmh([150]))
    assert r.converged[0] == 1 and r[0].converged and r[0].stable
