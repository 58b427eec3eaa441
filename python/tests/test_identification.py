"""Identification round trips on synthetic measurements: known parameters are recovered."""
import numpy as np
import pytest

import inerta
from conftest import model


def head_arm(m_H, k2, c2, f):
    """Head on k2 ‖ c2 above an arm of given FRF E: m_H A_H + 1 − Z (A_H − A_E)/ω² = 0 (eq. 4.19)."""
    w = 2 * np.pi * f
    E = (0.02 + 0.01j) / (1 + 1j * f / 5)
    Z = k2 + 1j * w * c2
    H = (-1 - Z * E / w**2) / (m_H - Z / w**2)
    return H, E


def test_head_suspension():
    f = np.arange(0.5, 20.01, 0.25)
    H, E = head_arm(7.0, 7000.0, 80.0, f)
    p = inerta.head_suspension_at(7.0, f[10], H[10], E[10])
    assert p.k2 == pytest.approx(7000, rel=1e-8) and p.c2 == pytest.approx(80, rel=1e-8)
    r = inerta.fit_head_suspension(7.0, f, H, E, 4, 20)
    assert r.k2 == pytest.approx(7000, rel=1e-8) and r.c2 == pytest.approx(80, rel=1e-8)
    assert r.points == 65 and len(r.per_frequency) == len(f) and r.rms_residual < 1e-9
    with pytest.raises(inerta.ModelError):
        inerta.fit_head_suspension(7.0, f, H, E, 30, 40)


def test_frf_fit_recovers_a_parameter(hsx):
    f = np.arange(0.5, 11.01, 0.5)
    outs = ["P_ay", "E_ay"]
    truth = hsx.with_overrides({"c2.c": 95.0})
    meas = inerta.frf_linear(truth, outs, f)
    assert inerta.frf_misfit(meas, meas) == 0
    band = inerta.frf_band(meas, 1, 5)
    assert band.f.min() >= 1 and band.f.max() <= 5 and band.H.shape[0] == 2
    o = inerta.SearchOptions(starts=1, min_step=1e-4)
    r = inerta.fit_frf(hsx, ["c2.c"], meas, o)  # bounds ÷10 … ×10 the file's value, as the CLI
    assert r.values[0] == pytest.approx(95.0, rel=1e-3) and r.cost < 1e-6 * r.initial_cost
    assert r.fitted.outputs == outs and r.evaluations > 0
    r2 = inerta.fit_frf(hsx, {"c2.c": (50.0, 200.0)}, meas, o)
    assert r2.values[0] == pytest.approx(95.0, rel=1e-3)
    r3 = inerta.fit_frf(lambda v: hsx.with_overrides({"c2.c": v[0]}), [inerta.Variable("c2.c", 50, 200, False, False)],
                        meas, o)  # a Python model function, called under the GIL
    assert r3.values[0] == pytest.approx(r2.values[0], rel=1e-9)
    with pytest.raises(inerta.ModelError):
        inerta.fit_frf(hsx, ["nosuch.k"], meas, o)
    m = inerta.Frf(meas.f, meas.outputs, meas.H)
    assert inerta.frf_misfit(m, meas) == 0


def test_actuator_static():
    v = np.array([-0.2, -0.1, -0.05, 0.05, 0.1, 0.2])
    F = -5374 + 30 * np.sign(v) + 900 * v
    r = inerta.fit_actuator_static(v, F)
    assert r.F_c == pytest.approx(-5374) and r.F_r == pytest.approx(30) and r.c1 == pytest.approx(900)
    assert r.forward.points == 3 and r.backward.slope == pytest.approx(900)
    line = inerta.fit_line([0, 1, 2], [1, 3, 5])
    assert line.slope == pytest.approx(2) and line.intercept == pytest.approx(1) and line.rms < 1e-12
    with pytest.raises(inerta.ModelError):
        inerta.fit_line([1], [1])


def test_actuator_dynamic():
    k1, c1, mp = 40e3, 10440.0, 3.45
    tests = []
    for f in (1.0, 3.0, 6.0):
        w = 2 * np.pi * f
        t = np.arange(0, 5 / f, 1 / (200 * f))
        X = 1e-3
        Y = inerta.maxwell_admittance(k1, c1, f)
        x = np.real(X * np.exp(1j * w * t))
        Fd = np.real(Y * 1j * w * X * np.exp(1j * w * t))
        F = -5374 + mp * np.real(-(w**2) * X * np.exp(1j * w * t)) + Fd
        tests.append(inerta.DynamicTest(f, t, x, F))
        assert inerta.harmonic_amplitude(t, x, f) == pytest.approx(X, abs=1e-12)
    r = inerta.fit_actuator_dynamic(tests, c1, mp, 0.0)
    assert r.k1 == pytest.approx(k1, rel=1e-4) and r.c1 == c1 and len(r.points) == 3
    assert inerta.admittance_cost(k1, c1, r.points) == pytest.approx(0, abs=1e-6)
    assert abs(r.points[0].Y_E) == pytest.approx(abs(inerta.maxwell_admittance(k1, c1, 1.0)), rel=1e-6)
    r2 = inerta.fit_actuator_dynamic(tests, 5000.0, mp, 0.0, fit_c1=True)
    assert r2.c1 == pytest.approx(c1, rel=1e-3)
    p = inerta.AdmittancePoint(1.0, 100 + 50j, 1e-3)
    assert p.Y_E == 100 + 50j
