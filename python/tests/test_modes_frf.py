"""Modes, linear models, FRFs and the catenary response: the same numbers as the CLI."""
import json

import numpy as np
import pytest

import inerta
from conftest import model, read_csv


def test_modes_equal_cli(cli, tmp_path, hsx):
    out, js = tmp_path / "m.csv", tmp_path / "lin.json"
    cli("modes", model("hsx.yaml"), "--out", out, "--export", js)
    ref = read_csv(out)
    ma = inerta.modal_analysis_free_head(hsx)  # what `inerta modes` does for a model with a rig
    assert "head free" in ma.setting
    np.testing.assert_allclose(ma.frequencies, ref["f_hz"], rtol=1e-8)
    np.testing.assert_allclose(ma.damping_ratios, ref["zeta"], rtol=1e-8)
    assert ma.modes[0].eigenvalue.real == pytest.approx(ref["re_lambda"][0], rel=1e-8)
    np.testing.assert_allclose(ma.modes[0].shape, [ref[n][0] for n in hsx.coordinate_names], atol=1e-5)
    doc = json.loads(js.read_text())
    np.testing.assert_allclose(np.array(ma.to_json()["A"]), np.array(doc["A"]), rtol=1e-12)
    lin = ma.linear
    assert lin.A.shape == (2 * lin.dof + lin.nz,) * 2 and lin.M.shape == (lin.dof, lin.dof)
    assert not lin.A.flags.writeable  # a view of the library's matrix
    w = tmp_path / "lin2.json"
    inerta.write_linear_model(w, ma.model, lin)
    assert json.loads(w.read_text())["dof"] == doc["dof"]
    assert inerta.linear_model_json(ma.model, lin)["coordinates"] == doc["coordinates"]


def test_modes_under_a_catenary_and_plain(cli, hsx, lumped):
    out = cli("modes", model("hsx.yaml"), "--catenary", model("catenary.yaml")).stdout
    ma = inerta.modal_analysis(hsx, lumped)
    first = next(l for l in out.splitlines() if l.strip().startswith("1 "))
    assert float(first.split()[2]) == pytest.approx(ma.frequencies[0], rel=1e-5)  # columns: #, f_d, |λ|/2π, ζ
    assert float(first.split()[1]) == pytest.approx(ma.modes[0].damped_frequency_hz, rel=1e-5)
    tb = inerta.load_model(model("twobar.yaml"))
    plain = inerta.modal_analysis(tb)
    x, _ = inerta.assemble(tb)
    lin = inerta.linearise(tb, x)
    np.testing.assert_allclose([m.frequency_hz for m in inerta.modes(tb, lin)], plain.frequencies, rtol=1e-9)


def test_frf_equals_cli(cli, tmp_path, hsx):
    out = tmp_path / "f.csv"
    cli("frf", model("hsx.yaml"), "--outputs", "P_ay,E_ay", "--freq", "0.5:0.5:10", "--out", out)
    ref = read_csv(out)
    f = inerta.frf_linear(hsx, ["P_ay", "E_ay"], ref["f_hz"])
    assert f.outputs == ["P_ay", "E_ay"] and f.H.shape == (2, 20)
    np.testing.assert_allclose(np.abs(f.H[0]), ref["P_ay_mag"], rtol=1e-8)
    np.testing.assert_allclose(np.degrees(np.angle(f["E_ay"])), ref["E_ay_phase_deg"], rtol=1e-8, atol=1e-7)
    np.testing.assert_allclose(f.f, ref["f_hz"])


def test_stepped_sine_agrees_with_linear(hsx):
    f = [2.0, 5.0]
    lin = inerta.frf_linear(hsx, ["P_ay"], f)
    ss = inerta.frf_stepped_sine(hsx, ["P_ay"], f, vc=0.01, cycles=20, analysed=10)
    np.testing.assert_allclose(np.abs(ss.H), np.abs(lin.H), rtol=0.05)
    o = inerta.SteppedSine()
    assert o.vc == 0.06 and o.cycles == 100


def test_catenary_response_equals_cli(cli, tmp_path, lumped):
    out = tmp_path / "cr.csv"
    cli("catenary-response", model("catenary.yaml"), "--fp", "0.5:0.5:1", "--out", out)
    ref = read_csv(out)
    r = inerta.catenary_response(lumped, [0.5, 1.0])
    assert len(r) == 2 and r[0].stable()
    np.testing.assert_allclose(r.acc_amplitude, ref["acc_amplitude"], rtol=1e-8)
    np.testing.assert_allclose(r.speed, ref["v_ms"], rtol=1e-9)
    assert r.stable.dtype == bool and r.stable.all()
    r2 = inerta.catenary_response(lumped.catenary.point_model(), [0.5])
    assert r2.acc_amplitude[0] == r.acc_amplitude[0]
    with pytest.raises(inerta.ModelError, match="lumped catenary"):
        inerta.catenary_response(inerta.load_catenary(model("wire-profile.yaml")), [1.0])
