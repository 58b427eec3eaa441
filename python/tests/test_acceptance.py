"""The acceptance verdict from Python (inerta.acceptance): the CLI's table as a NumPy structured array."""
import csv

import numpy as np
import pytest

import inerta
from conftest import model, run_cli


def short_line():
    return inerta.load_catenary(model("catenary-fe.yaml"), {"line.spans": 4})


def test_a_sweep_verdict_has_every_speed_and_criterion_and_reads_the_run_statistics():
    m = inerta.load_model(model("pantograph-3mass.yaml"))
    r = inerta.sweep(m, short_line(), inerta.kmh([200.0, 300.0]))
    t = inerta.acceptance(r, "en50367-ac")
    assert t.dtype.names == ("speed", "pantograph", "criterion", "unit", "value", "limit", "margin", "passed", "assessed",
                             "statistic", "assumed", "source")
    assert len(t) == 2 * 7
    sigma = t[t["criterion"] == "sigma"]
    # σ ≤ 0.3 F_m of the 20 Hz statistics, as the run gives them
    for row, s in zip(sigma, r):
        assert row["value"] == s.filtered[0].std
        assert row["limit"] == pytest.approx(0.3 * s.filtered[0].mean, rel=1e-15)
        assert row["passed"] == (row["margin"] >= 0)
    lower = t[t["criterion"] == "mean_lower"]
    assert lower["limit"] == pytest.approx([0.00047 * 200**2 + 60, 0.00047 * 300**2 + 60])
    # Each row says what it judged and where its number comes from (issue 53): the AC set's are unverified.
    top = t[t["criterion"] == "max_force"]
    assert list(top["statistic"]) == ["filtered, F_m + 3σ"] * 2 and top["assumed"].all()
    assert list(top["limit"]) == [350.0, 350.0]  # from 200 km/h
    for row, s in zip(top, r):
        assert row["value"] == pytest.approx(s.filtered[0].mean + 3 * s.filtered[0].std, rel=1e-12)
    assert all(len(str(x)) > 10 for x in t[t["assessed"]]["source"])
    uplift = t[t["criterion"] == "support_uplift"]
    assert not uplift["assessed"].any()  # the bundled line has no registration.uplift_limit
    # The same set given as an object, and the CLI's table of the same runs.
    c = inerta.load_acceptance("en50367-ac")
    assert c.name == "en50367-ac" and c.has_target and c.target(300 / 3.6) == pytest.approx(132.3)
    assert c.target_speeds == (200.0, 320.0)
    with pytest.raises(inerta.InvalidArgument, match="not assessed"):
        c.target(150 / 3.6)  # the source's upper edge there, not a target
    assert "stands in for the measured percentage of arcing" in c.arcing_text
    assert np.array_equal(inerta.acceptance(r, c)["passed"], t["passed"])


def test_the_cli_and_python_give_the_same_table(tmp_path):
    out = tmp_path / "s.csv"
    run_cli("sweep", model("pantograph-3mass.yaml"), "--catenary", model("catenary-fe.yaml"), "--set", "line.spans=4",
            "--speeds", "250:50:300", "--unit", "kmh", "--acceptance", "en50367-ac", "--out", out)
    with open(tmp_path / "s.acceptance.csv", encoding="utf-8") as f:
        cli = list(csv.DictReader(f))
    m = inerta.load_model(model("pantograph-3mass.yaml"))
    t = inerta.acceptance(inerta.sweep(m, short_line(), inerta.kmh([250.0, 300.0])), "en50367-ac")
    assert [r["criterion"] for r in cli] == list(t["criterion"])
    assert [r["status"] for r in cli] == ["not assessed" if not a else "PASS" if p else "FAIL"
                                          for p, a in zip(t["passed"], t["assessed"])]
    for r, value in zip(cli, t["value"]):
        assert (r["value"] == "nan" and np.isnan(value)) or float(r["value"]) == pytest.approx(value, rel=1e-5)


def test_the_verdict_line_never_passes_what_it_did_not_assess():
    m = inerta.load_model(model("pantograph-3mass.yaml"))
    # The wire profile gives no 20 Hz statistics and no loss events: nothing assessed (issue 52).
    r = inerta.sweep(m, inerta.load_catenary(model("wire-profile.yaml")), inerta.kmh([300.0]))
    v = inerta.verdict(r, "en50367-ac")
    assert v.status == "NOT ASSESSED" and not v and v.failed == []
    assert set(v.not_assessed) == set(inerta.acceptance(r, "en50367-ac")["criterion"])
    # The FE line: a verdict from the rows, the support uplift named as not assessed.
    r = inerta.sweep(m, short_line(), inerta.kmh([250.0]))
    t = inerta.acceptance(r, "en50367-ac")
    v = inerta.verdict(r, "en50367-ac")
    assessed = t[t["assessed"]]
    assert v.status == ("PASS" if assessed["passed"].all() else "FAIL")
    assert v.failed == [str(c) for c in assessed[~assessed["passed"]]["criterion"]]
    assert v.not_assessed == ["support_uplift"]


def test_errors_name_what_is_wrong():
    with pytest.raises(inerta.ModelError, match="unknown preset 'nope'"):
        inerta.load_acceptance("nope")
    assert inerta.acceptance_presets() == ["en50367-ac", "en50367-ac15", "en50367-dc1.5", "en50367-dc3"]
    with pytest.raises(TypeError, match="expected the result of inerta.sweep"):
        inerta.acceptance(42, "en50367-ac")


def test_the_aerodynamic_fit_brings_the_mean_force_to_the_target():
    m = inerta.load_model(model("pantograph-3mass.yaml"))
    f = inerta.fit_aerodynamic(m, short_line(), 300 / 3.6, "en50367-ac")
    assert f.reached and f.a > 0
    assert f.target == pytest.approx(0.00047 * 300**2 + 90)
    assert abs(f.mean - f.target) <= 0.05
    assert f.mean_without < f.target
    # The fitted uplift in the model gives that mean force (the same runs: the same statistics).
    fitted = inerta.load_model(model("pantograph-3mass.yaml"), {"lumped_pantograph.aerodynamic.a": f.a})
    r = inerta.sweep(fitted, short_line(), [300 / 3.6])
    assert r[0].filtered[0].mean == pytest.approx(f.mean, abs=1e-9)


def test_a_pickled_sweep_keeps_what_the_verdict_reads():
    # Dask workers return SpeedResults by pickle: the loss events, the sampling step and the line's
    # uplift limit travel with them, so a distributed sweep's verdict equals the serial one.
    import pickle

    m = inerta.load_model(model("pantograph-3mass.yaml"))
    line = inerta.load_catenary(model("catenary-fe.yaml"),
                                {"line.spans": 4, "registration.uplift_limit": 0.2, "registration.uplift_limited": True})
    r = inerta.sweep(m, line, inerta.kmh([300.0]))
    s = pickle.loads(pickle.dumps(r[0]))
    assert s.loss_runs == r[0].loss_runs and s.sample_dt == r[0].sample_dt and s.uplift_limit == 0.2
    assert r[0].uplift_limited and s.uplift_limited  # the stop (issue 53) travels too
    back = inerta.SweepResult([s])
    a, b = inerta.acceptance(r, "en50367-ac"), inerta.acceptance(back, "en50367-ac")
    assert np.array_equal(a["passed"], b["passed"]) and np.array_equal(a["value"], b["value"], equal_nan=True)
    up = a[a["criterion"] == "support_uplift"]
    assert up["assessed"].all()  # the line's limit: assessed now
    assert up["limit"][0] == pytest.approx(0.2 / 1.5)  # a stop limits the uplift: 1.5 S0
    assert np.array_equal(b[b["criterion"] == "support_uplift"]["limit"], up["limit"])


def test_commissioning_relaxes_trims_and_holds_the_static_force_over_the_working_range():
    # Issue 49: the HSX commissioned on a short line with its stock suspension and with a static spring
    # in parallel. Relaxed at standstill, both start from the same static force; the trim meets the
    # target within 0.05 N; over the working range the stock (Maxwell) suspension adds nothing, the
    # static spring moves the force by about its stiffness through the linkage's ratio squared.
    hsx = inerta.load_model(model("hsx.yaml"))
    line = short_line()
    stock, c0 = inerta.commission(hsx, line, 250 / 3.6, "en50367-ac", suspension="S2-default")
    assert c0.reached and abs(c0.mean - c0.target) <= 0.05
    assert c0.target == pytest.approx(0.00047 * 250**2 + 90)
    assert c0.static_stiffness == 0.0
    assert c0.range_force == pytest.approx([c0.static_force] * 5, abs=1e-9)
    assert len(c0.range_model) == 5 and c0.range_model[0] != c0.range_model[-1]  # the frame's own springs
    spring, c1 = inerta.commission(hsx, line, 250 / 3.6, "en50367-ac", suspension="k1|(k2-c)",
                                   params={"k1": 2e4, "k2": 1.41e5, "c": 1.044e4},
                                   working_range=inerta.WorkingRange(0.05, 0.05, 3))
    assert c1.static_stiffness == pytest.approx(2e4)
    assert c1.static_force == pytest.approx(c0.static_force, rel=1e-9)  # relaxed where the stock one holds the head
    assert c1.range_height == pytest.approx([-0.05, 0.0, 0.05])
    assert c1.range_force[0] > c1.static_force > c1.range_force[2]  # a spring pushes back on a rising wire
    # The static force the head meets at a height, by the library's rig: what the range is made of.
    assert inerta.static_force_at(hsx, c0.head_offset) == pytest.approx(c0.static_force, rel=1e-12)
    assert isinstance(spring, inerta.Model) and isinstance(stock, inerta.Model)
    t = inerta.Trim()
    t.speed, t.target = 70.0, 120.0
    assert (t.speed, t.target, t.periodic) == (70.0, 120.0, False)
