"""The finite-element catenary, lumped pantographs, signal processing and the EN 50317 contact
quality: the same numbers as the CLI, and round trips on synthetic signals."""
import os
import signal
import subprocess
import time

import numpy as np
import pytest

import inerta
from conftest import CLI, SRC, model, read_csv

SHORT = {"line.spans": 4}  # a short line keeps the runs fast


def test_file_kinds():
    assert inerta.file_kind(model("hsx.yaml")) == "model"
    assert inerta.file_kind(model("pantograph-3mass.yaml")) == "lumped_pantograph"
    assert inerta.file_kind(model("catenary-fe.yaml")) == "catenary"
    with pytest.raises(inerta.ModelError):
        inerta.file_kind(model("nothere.yaml"))


def test_lumped_pantograph():
    p = inerta.load_model(model("pantograph-3mass.yaml"))
    assert p.is_pantograph and p.has_rig and p.output_names[-1] == "F_contact"
    d = inerta.load_lumped_pantograph_data(model("pantograph-3mass.yaml"), {"lumped_pantograph.static_uplift": 90})
    assert d.mass == [7.12, 6.0, 5.8] and d.static_uplift == 90
    q = inerta.make_lumped_pantograph(d)
    assert len(q.bodies) == 3 and q.aero is None
    d.aero_c = 10.0
    d.validate()
    a = inerta.make_lumped_pantograph(d)
    assert a.aero == {"body": 0, "a": 0.0, "b": 0.0, "c": 10.0} and a.aero_force(50) == 10
    fast = a.at_speed(50.0)
    assert fast.aero is None and "aerodynamic_uplift" in [f.name for f in fast.forces]
    assert inerta.at_speed(a, 50.0).history == ["at speed 50 m/s"]
    with pytest.raises(inerta.InvalidArgument):
        inerta.LumpedPantographData([1.0], [1.0, 2.0], [0.0]).validate()


def test_fe_catenary_file_and_line():
    f = inerta.read_catenary_file(model("catenary-fe.yaml"), SHORT)
    assert f.catenary is None and f.fe.spans == 4 and f.contact.kind == "penalty"
    d = inerta.read_fe_catenary_data(model("catenary-fe.yaml"), SHORT)
    assert d.messenger.tension == 16000 and d.contact_wire.wave_speed() == pytest.approx((22000 / 1.35) ** 0.5)
    c = inerta.load_catenary(model("catenary-fe.yaml"), SHORT)
    assert c.catenary.type == "finite_element" and c.fe.spans == 4 and c.catenary.line_length == 220
    line = c.catenary.line
    assert line.length == 220 and len(line.droppers) == 4 * 9 and line.n_dofs > 0
    assert abs(line.static_height(55.0)) < 1e-6  # the contact wire at a mast
    e = line.elasticity(np.array([55.0, 82.5]))
    assert e[1] > e[0] > 0  # softer at mid-span
    mats = line.matrices()
    (data, (row, col)), shape = mats["K"]
    assert shape == (line.n_dofs, line.n_dofs) and len(data) == len(row) == len(col)
    u, slack = line.static_displacement([82.5], [100.0])
    assert line.contact_displacement(u, 82.5) > 0 and len(slack) == len(line.droppers)
    own = inerta.FeCatenary(d)
    assert own.line.n_dofs == line.n_dofs and own.section()[1] <= 220
    assert inerta.beam_stiffness(195, 22000, 0.25).shape == (4, 4) and inerta.beam_mass(1.35, 0.25)[0, 0] > 0
    assert line.messenger_height(0) == pytest.approx(1.2) and line.dropper_length_error_max() < 0.05


def test_lumped_fit_equals_cli(cli, tmp_path):
    out, table = tmp_path / "fit.yaml", tmp_path / "fit.csv"
    text = cli("catenary", "fit", model("catenary-fe.yaml"), "--set", "line.spans=4", "--out", out,
               "--table", table).stdout
    line = inerta.FeLine(inerta.read_fe_catenary_data(model("catenary-fe.yaml"), SHORT))
    fit = inerta.fit_lumped(line)
    k = [float(v) for v in text.split("k_c = [")[1].split("]")[0].split(",")]
    np.testing.assert_allclose(fit.lumped.k, k, rtol=1e-4)
    inerta.write_lumped_catenary(tmp_path / "py.yaml", fit, inerta.Contact("penalty"), "catenary-fe.yaml")
    lumped = inerta.load_catenary(tmp_path / "py.yaml")
    np.testing.assert_allclose(lumped.catenary.point_model().k, fit.lumped.k, rtol=1e-5)
    inerta.write_fit_table(tmp_path / "py.csv", fit)
    np.testing.assert_allclose(read_csv(tmp_path / "py.csv")["x"], read_csv(table)["x"])
    assert fit.x.shape == fit.elasticity.shape and fit.max_elasticity_error >= fit.max_smoothed_error >= 0


def test_fe_run_equals_cli(cli, tmp_path):
    out = tmp_path / "fe.csv"
    cli("simulate", model("pantograph-3mass.yaml"), "--catenary", model("catenary-fe.yaml"), "--set", "line.spans=4",
        "--speed", 200, "--unit", "kmh", "--out", out)
    ref = read_csv(out)
    p = inerta.load_model(model("pantograph-3mass.yaml"))
    cat = inerta.load_catenary(model("catenary-fe.yaml"), SHORT)
    r = inerta.simulate_coupled(p, cat, inerta.kmh(200))
    assert "x_contact" in r.names and "wire_uplift" in r.names
    np.testing.assert_allclose(r["F_contact"], ref["F_contact"], rtol=1e-7, atol=1e-6)
    q = r.quality[0]
    assert q.raw.std > 0 and q.filtered.std <= q.raw.std and q.psd.f.shape == q.psd.S.shape
    assert 0 <= r.section[0] < r.section[1] <= 4 * 55
    assert r.supports.n_samples == r.histories[0].n_samples or len(r.support_x) == 0
    # statistics recomputed from the history over the section agree with the library's
    again = inerta.contact_quality(r.t, r["x_contact"], r["F_contact"], r.section)
    assert again.raw.std == pytest.approx(q.raw.std, rel=1e-12)
    s = inerta.run_speed(p, cat, inerta.kmh(200))
    assert len(s.filtered) == 1 and len(s.support_x) == len(s.support_uplift)


def test_mode_store_between_processes(tmp_path, monkeypatch):
    """INERTA_CACHE=DIR: the first process solves and stores the windows' modes, the second reads them;
    the two CSVs are the same bytes (docs/catenary-fe.md "Mode store")."""
    import subprocess
    from conftest import CLI, SRC

    if not CLI.exists():
        pytest.skip(f"CLI not built: {CLI}")
    store = tmp_path / "store"
    env = dict(os.environ, INERTA_CACHE=str(store))
    outs = []
    for k in range(2):
        out = tmp_path / f"run{k}.csv"
        subprocess.run([str(CLI), "simulate", model("pantograph-3mass.yaml"), "--catenary", model("catenary-fe.yaml"),
                        "--set", "line.spans=8", "--set", "solver.cutoff=40", "--speed", "250", "--unit", "kmh",
                        "--out", str(out)], check=True, cwd=SRC, env=env, capture_output=True)
        outs.append(out.read_bytes())
        if k == 0:
            first = sorted(p.name for p in store.iterdir())
            # first window, interior window, and the last one (the first mirrored) kept too
            assert len(first) == 3 and all(n.startswith("modes-") and n.endswith(".bin") for n in first)
            stamps = [p.stat().st_ino for p in sorted(store.iterdir())]
    assert outs[0] == outs[1]
    assert [p.stat().st_ino for p in sorted(store.iterdir())] == stamps  # read, not written again (a write renames a new file in)


def test_signal_processing():
    fs = 1000.0
    lp = inerta.butterworth_lowpass(20.0, fs, 4)
    assert lp.order == 4 and len(lp.sections) == 2 and lp.dc_gain() == pytest.approx(1)
    assert lp.magnitude(20.0)[0] == pytest.approx(2 ** -0.5, rel=1e-9)
    x = np.full(200, 3.0)
    np.testing.assert_allclose(inerta.filtfilt(lp, x), x, rtol=1e-12)
    assert inerta.filtfilt_padding(lp) == 15 and len(inerta.filter(lp, x)) == 200
    t = np.arange(4096) / fs
    assert inerta.uniform_sample_rate(t) == pytest.approx(fs)
    rng = np.random.default_rng(1)
    noise = rng.normal(0, 2.0, t.size)
    S = inerta.welch(noise, fs)
    assert S.integral() == pytest.approx(4.0, rel=0.1) and S.segments > 1 and S.resolution > 0
    sine = np.sin(2 * np.pi * 50 * t)
    P = inerta.periodogram(sine, fs)
    assert P.f[np.argmax(P.S)] == pytest.approx(50, abs=P.resolution)
    assert inerta.welch(sine, fs, inerta.WelchOptions(segment=1024, window=inerta.Window.hann)).integral(40, 60) == \
        pytest.approx(0.5, rel=0.05)
    f = inerta.SosFilter.__new__  # the type exists; instances come from butterworth_lowpass
    assert callable(f) and inerta.Biquad(1.0).b0 == 1.0


def test_contact_quality_and_support_uplift():
    fs = 500.0
    t = np.arange(5000) / fs
    x = 10.0 + 50.0 * t  # m along the line
    F = 100 + 10 * np.sin(2 * np.pi * 2 * t) + 5 * np.sin(2 * np.pi * 60 * t)
    q = inerta.contact_quality(t, x, F, 100.0, 400.0, inerta.ContactQualityOptions(cutoff=20))
    assert q.x_from == 100 and q.sample_rate == pytest.approx(fs)
    assert q.raw.std == pytest.approx(np.hypot(10, 5) / 2 ** 0.5, rel=0.01)
    assert q.filtered.std == pytest.approx(10 / 2 ** 0.5, rel=0.02)  # the 60 Hz part filtered out
    assert q.loss_pct == 0 and q.psd.integral() == pytest.approx(q.raw.std ** 2, rel=0.05)
    with pytest.raises(inerta.InvalidArgument):
        inerta.contact_quality(t, x, F, 1000.0, 2000.0)
    # Over parts of the section (the overlaps of a line of tension sections): a part where the force
    # is constant 100 N has σ 0; the whole section as the one part gives contact_quality's numbers.
    Fp = np.where((x >= 200) & (x <= 250), 100.0, F)
    part = inerta.part_statistics(t, x, Fp, inerta.Section(100.0, 400.0), [inerta.Section(200.0, 250.0)])
    assert part.raw.std == pytest.approx(0, abs=1e-12) and part.raw.samples == np.count_nonzero((x >= 200) & (x <= 250))
    whole = inerta.part_statistics(t, x, F, inerta.Section(100.0, 400.0), [inerta.Section(0.0, 1000.0)])
    assert whole.raw.std == pytest.approx(q.raw.std, rel=1e-12) and whole.filtered.std == pytest.approx(q.filtered.std, rel=1e-12)
    up = inerta.support_uplift([0.0, 1.0, 2.0], [50.0, 100.0], [[0.0, 0.0], [0.01, 0.02], [0.005, 0.03]], 0, 75)
    assert len(up) == 1 and up[0].max_uplift == 0.01 and up[0].t_max == 1.0 and up[0].x == 50


def test_stepper(twobar):
    x, _ = inerta.assemble(twobar)
    s = inerta.Stepper(twobar, x, 0.0, inerta.IntegratorOptions(rtol=1e-9, atol=1e-11))
    s.advance(0.5)
    s.advance(1.0)
    assert s.time == 1.0 and s.stats.steps > 0
    y, _ = inerta.integrate(twobar, x, 0.0, 1.0, 1.0, rtol=1e-9, atol=1e-11)
    np.testing.assert_allclose(s.state.q, y.q, atol=1e-6)


def test_modal_solver_and_compare():
    # The file's modal solve against the direct one (inerta.compare, as `inerta catenary check-reduction`),
    # on a short line with the whole line in one window; the data's solver fields round-trip and are checked.
    sets = {"line.spans": 3, "solver.window_behind": -1, "solver.cutoff": 150}
    d = inerta.read_fe_catenary_data(model("catenary-fe.yaml"), sets)
    assert d.solver == "modal" and d.modal_cutoff == 150 and d.window_behind == -1 and d.window_ahead == 3
    with pytest.raises(inerta.InvalidArgument):
        d.solver = "fast"
    direct = inerta.load_catenary(model("catenary-fe.yaml"), {**sets, "solver.type": "direct"})
    modal = inerta.load_catenary(model("catenary-fe.yaml"), sets)
    p = inerta.load_model(model("pantograph-3mass.yaml"))
    rows = inerta.compare(p, direct, modal, [inerta.kmh(200)])
    assert len(rows) == 1 and rows[0].speed == pytest.approx(200 / 3.6)
    ref, cand = rows[0].reference.stats.std, rows[0].candidate.stats.std
    assert ref > 5 and abs(cand - ref) < 0.01 * ref
    assert rows[0].reference_s > 0 and rows[0].candidate_s > 0
    bad = dict(sets)
    bad["solver.window_ahead"] = -2
    with pytest.raises(inerta.ModelError, match="window_ahead"):
        inerta.read_fe_catenary_data(model("catenary-fe.yaml"), bad)


def test_run_time_estimates_follow_the_solvers_cost_laws():
    """Catenary.estimated_seconds: the direct solve's work is the line's unknowns × steps (quadratic
    in the spans at a speed), the modal solve's the window's (linear); a lumped line's run its length
    (issue 52: a crawl is no longer free)."""
    m3 = inerta.load_model(model("pantograph-3mass.yaml"))
    v = 250 / 3.6

    def est(spans, solver):
        c = inerta.load_catenary(model("catenary-fe.yaml"), {"line.spans": spans, "solver.type": solver})
        return inerta.estimated_seconds(m3, c, v)

    assert est(20, "direct") / est(10, "direct") == pytest.approx(4, rel=0.1)
    first_modes = est(10, "modal") - (est(20, "modal") - est(10, "modal"))  # the constant part
    assert (est(40, "modal") - first_modes) / (est(10, "modal") - first_modes) == pytest.approx(4, rel=0.05)
    assert est(10, "modal") < est(10, "direct")
    lumped = inerta.load_catenary(model("catenary.yaml"))
    # t_end given: proportional to it; None: a sweep's longest run, 40 spans at that speed.
    assert inerta.estimated_seconds(m3, lumped, 50.0, 20.0) == pytest.approx(2 * inerta.estimated_seconds(m3, lumped, 50.0, 10.0))
    assert inerta.estimated_seconds(m3, lumped, 1e-4) == pytest.approx(1000 * inerta.estimated_seconds(m3, lumped, 0.1))
    assert inerta.estimated_seconds(m3, lumped, 1e-4) > 3600
    c = inerta.load_catenary(model("catenary-fe.yaml"))
    speeds = [150 / 3.6, 200 / 3.6, 250 / 3.6, 300 / 3.6]
    serial = sum(inerta.estimated_seconds(m3, c, s) for s in speeds)
    assert serial / 4 <= inerta.estimated_sweep_seconds(m3, c, speeds) <= serial
    study = inerta.load_study(f"{SRC}/studies/hsx-s2-fe-line.yaml")
    assert inerta.estimated_evaluation_seconds(study) > 0
    assert inerta.estimated_evaluation_seconds(inerta.load_study(f"{SRC}/studies/hsx-s2.yaml")) == 0
    # A whole study, every stage (issue 52): the coarse search of every network at about 60 evaluations per
    # free value, the refinements at their limit with the time domain's evaluation.
    real = inerta.load_study(f"{SRC}/studies/hsx-s2-fe-all.yaml")
    e = inerta.estimated_study_seconds(real)
    assert e.search_evaluations == sum(min(60 * len(inerta.free_parameters(n)), real.coarse.search.max_evaluations)
                                       for n in real.layouts)
    assert e.refine_evaluations == real.refine.max_evaluations * real.refine_networks
    assert e.refine_seconds == pytest.approx(e.refine_evaluations * inerta.estimated_evaluation_seconds(real))
    assert e.search_seconds > 0 and e.seconds == pytest.approx(e.search_seconds + e.refine_seconds)


def test_a_run_estimated_at_hours_says_so_first_and_ctrl_c_leaves_no_file(tmp_path):
    """The cost guard: an FE line of 300 spans with the direct solve (hours; refused without --max-seconds,
    tests/apps/guard_cli_test.cpp) prints its estimate before the run; SIGINT then stops it and no output
    file, complete or partial, is left."""
    out = tmp_path / "long.csv"
    p = subprocess.Popen([str(CLI), "simulate", model("pantograph-3mass.yaml"), "--catenary", model("catenary-fe.yaml"),
                          "--speed", "250", "--unit", "kmh", "--set", "line.spans=300", "--set", "solver.type=direct",
                          "--out", str(out), "--max-seconds", "100000"],  # above the default limit (600 s): allowed
                         stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True, cwd=SRC)
    try:
        line = p.stderr.readline()
        assert line.startswith("note: this run is estimated at about ") and "on a 2-core machine" in line, line
        value, unit = line.split("about ")[1].split()[:2]
        minutes = float(value) * {"min": 1, "h": 60}[unit]
        assert 20 < minutes < 180  # 300 spans direct: 35 ns × 264k unknowns × 238k steps of 1 ms ≈ 37 min
        time.sleep(0.5)
        p.send_signal(signal.SIGINT)
        assert p.wait(timeout=30) != 0
    finally:
        p.kill()
    assert not out.exists() and not [f for f in os.listdir(tmp_path) if "partial" in f]
