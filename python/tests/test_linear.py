"""Linear analysis of any model (state space, FRF, random response) and model design studies,
equal to the CLI's numbers for the same inputs."""
import re
import subprocess

import numpy as np
import pytest

import inerta
from conftest import CLI, SRC


def quarter_car():
    return inerta.load_model(f"{SRC}/models/quarter_car.yaml")


def test_state_space_has_named_states_and_the_tyre_input():
    ss = inerta.state_space(quarter_car(), ["road"], ["a_body", "travel"])
    assert ss.states == ["wheel.y", "body.y", "wheel.y_dot", "body.y_dot"]
    assert ss.input_units == ["m"]
    assert ss.A.shape == (4, 4) and ss.B.shape == (4, 1) and ss.C.shape == (2, 4)
    # B = k_t / m_u on the wheel's rate row (hand derivation, docs/linear-analysis.md)
    assert ss.B[2, 0] == pytest.approx(160000 / 35, rel=1e-6)
    H = inerta.frequency_response(ss, [1.0, 10.0])
    assert H.shape == (2, 2, 1) and H.dtype == complex


def test_road_rms_equals_the_cli():
    ss = inerta.state_space(quarter_car(), ["road"], ["a_body", "travel", "tyre_force"])
    road = inerta.Road()
    road.gd0, road.speed, road.inputs = 256e-6, 25.0, ["road"]
    r = inerta.road_response(ss, road)
    out = subprocess.run([CLI, "rms", f"{SRC}/models/quarter_car.yaml", "--road", "C", "--speed", "25", "--inputs", "road",
                          "--outputs", "a_body,travel,tyre_force"], capture_output=True, text=True, check=True).stdout
    cli = [float(x) for x in re.findall(r"rms ([0-9.eE+-]+)", out)]
    assert np.allclose(r.rms, cli, rtol=1e-5)


def test_white_noise_h2_and_errors():
    ss = inerta.state_space(quarter_car(), ["F_body"], ["y_body"])
    r = inerta.white_noise_response(ss, np.eye(1))
    assert r.rms[0] > 0
    with pytest.raises(inerta.InvalidArgument, match="no input 'roud'"):
        inerta.state_space(quarter_car(), ["roud"], ["a_body"])
    ssa = inerta.state_space(quarter_car(), ["F_body"], ["a_body"])
    with pytest.raises(inerta.InvalidArgument, match="responds directly"):
        inerta.white_noise_response(ssa, np.eye(1))


def test_model_study_from_a_file_matches_the_cli(tmp_path):
    study = inerta.load_model_study(f"{SRC}/studies/quarter_car.yaml")
    assert study.objective.kind == "rms" and study.layouts[0] == "c"
    r = inerta.optimise_model_layout(study, "c")
    out = subprocess.run([CLI, "optimise", f"{SRC}/studies/quarter_car.yaml"], capture_output=True, text=True, check=True).stdout
    m = re.search(r"\[1/4\] c +J = ([0-9.eE+-]+)", out)
    assert m and float(m.group(1)) == pytest.approx(r.cost.J, rel=1e-5)
    # warm-started from the damper's optimum, a parallel inerter does at least as well
    rb = inerta.optimise_model_layout(study, "c|b", [r.values])
    assert rb.cost.J <= r.cost.J
    bad = tmp_path / "bad.yaml"
    bad.write_text(f"model: {SRC}/models/quarter_car.yaml\nstrut: k_s\n")
    with pytest.raises(inerta.ModelError, match=r"bad.yaml:2: 'strut': 'k_s' is not a network strut"):
        inerta.load_model_study(bad)


def test_the_linear_building_blocks_agree():
    qc = quarter_car()
    x, _ = inerta.assemble(qc)
    lin = inerta.linearise(qc, x)
    assert inerta.state_names(qc, lin) == ["wheel.y", "body.y", "wheel.y_dot", "body.y_dot"]
    sys = inerta.linear_system(qc, x, ["road"], ["travel"])
    assert np.allclose(sys.lin.A, lin.A, rtol=1e-6, atol=1e-6)
    assert sys.motion == [True] and sys.joint == [[j.name for j in qc.joints].index("road")]
    und = inerta.undamped_modes(qc, lin)
    # det(K − ω² M) = 0 for M = diag(m_u, m_s), K = [[k_s + k_t, −k_s], [−k_s, k_s]]
    ms, mu, ks, kt = 250.0, 35.0, 16000.0, 160000.0
    w2 = np.sort(np.roots([mu * ms, -(ms * (ks + kt) + mu * ks), ks * kt]).real)
    assert [m.frequency_hz for m in und] == pytest.approx(np.sqrt(w2) / (2 * np.pi), rel=1e-7)
    # lyapunov: A P + P Aᵀ + Q = 0
    P = inerta.lyapunov(lin.A, np.eye(4))
    assert np.allclose(lin.A @ P + P @ lin.A.T + np.eye(4), 0, atol=1e-9 * np.abs(P).max())
    assert inerta.road_velocity_intensity(256e-6, 25.0) == pytest.approx(2 * np.pi ** 2 * 0.01 * 256e-6 * 25)


def test_model_study_pieces():
    study = inerta.load_model_study(f"{SRC}/studies/tmd.yaml")
    assert inerta.is_model_study(f"{SRC}/studies/tmd.yaml") and not inerta.is_model_study(f"{SRC}/studies/hsx-s2.yaml")
    net = inerta.default_network(study)
    assert inerta.to_string(net) == "k|c"
    c = inerta.evaluate_model(study, "k|c", {"k": 4535.147, "c": 38.32899})
    assert c.J * 1e5 == pytest.approx(np.sqrt(1 + 2 / 0.05), rel=0.02)  # Den Hartog's peak x k / F
    m2 = inerta.with_strut_network(study.model, study.strut, "k", {"k": 4535.147})
    assert m2.n_states == 0
    mp = inerta.objective_map(study, "k|c", {"k": 4535.147, "c": 38.32899}, "k", "c", n=3, decades=0.1)
    assert len(mp.J) == 3 and min(min(r) for r in mp.J) <= c.J + 1e-12
    fr = inerta.study_frf(study, "k|c", {"k": 4535.147, "c": 38.32899}, [4.0, 5.0])
    assert fr.outputs == ["x"] and len(fr.magnitude[0]) == 2


def test_a_model_studys_files_from_python_equal_the_clis(cli, tmp_path):
    """inerta.run_model_study + inerta.write_study_results write what `inerta optimise --out` writes,
    byte for byte (the same library writer, io::write_model_study_results)."""
    printed = cli("optimise", "studies/tmd.yaml", "--out", tmp_path / "cli", "--no-plots").stdout
    calls = []
    r = inerta.run_model_study(inerta.load_model_study(f"{SRC}/studies/tmd.yaml"),
                               progress=lambda done, total, best: calls.append((done, total, best)))
    assert [c[:2] for c in calls] == [(1, 4), (2, 4), (3, 4), (4, 4)]
    assert calls[-1][2] == min(x.cost.J for x in r.results)
    assert r.results[r.best].cost.J == calls[-1][2] and r.baseline_cost.J > calls[-1][2]
    table = inerta.model_study_table(r)  # the CLI's table, but for its wall time
    assert table[:table.rindex("wall")] in printed
    paths = inerta.write_study_results(r, tmp_path / "py")
    names = [p.rsplit("/", 1)[1] for p in paths]
    assert names == ["results.csv", "results.json", "frf.csv", "map.csv"]
    for n in names:
        assert (tmp_path / "py" / n).read_bytes() == (tmp_path / "cli" / n).read_bytes(), n
    fig = inerta.model_study_figures(r)
    assert fig.frf_default.outputs == ["x"] and fig.map.layout == r.results[r.best].layout


def test_a_model_studys_admittance_bounds_from_python_equal_the_clis(cli, tmp_path):
    study = tmp_path / "tmd-bound.yaml"
    study.write_text(f"""name: TMD, one layout and the degree-2 bound
model: {SRC}/models/tmd.yaml
strut: absorber
objective: {{type: hinf, input: F, outputs: {{x: 1}}, band: {{from: 3, to: 8, points: 200}}}}
layouts: ["k|c"]
admittance: [2]
search: {{starts: 2, seed: 1, lo: 0.01, hi: 1.0e7, min_step: 0.01}}
""")
    out = cli("optimise", study, "--out", tmp_path / "cli", "--no-plots").stdout
    assert "degree 2: J =" in out
    r = inerta.run_model_study(inerta.load_model_study(study))
    (b,) = r.admittance
    # any network of ≤ 2 springs+inerters is a degree-2 admittance: the bound is below the best such network
    assert b.result.degree == 2 and b.feasible and b.best is not None and b.result.J <= b.best.J * (1 + 1e-9)
    assert b.gap_pct == pytest.approx(100 * (b.best.J - b.result.J) / b.result.J)
    paths = inerta.write_study_results(r, tmp_path / "py")
    assert [p.rsplit("/", 1)[1] for p in paths[:2]] == ["admittance.csv", "admittance.json"]
    for n in ["admittance.csv", "admittance.json", "results.csv", "results.json"]:
        assert (tmp_path / "py" / n).read_bytes() == (tmp_path / "cli" / n).read_bytes(), n
    again = inerta.write_admittance_results(tmp_path / "again", r.admittance, r.baseline_cost.J)
    assert open(again[0], "rb").read() == (tmp_path / "cli" / "admittance.csv").read_bytes()
