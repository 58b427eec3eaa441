"""The pattern search with a Python cost, its helpers, and the cubic spline."""
import math

import numpy as np
import pytest

import inerta


def test_pattern_search_with_a_python_cost():
    calls = []

    def cost(v):
        calls.append(v)
        return (math.log10(v[0]) - 2) ** 2 + (math.log10(v[1]) + 1) ** 2

    vars = [inerta.Variable("a", 1e-3, 1e6, False, False), inerta.Variable("b", 1e-3, 1e6, False, False)]
    progress = []
    r = inerta.pattern_search(vars, cost, inerta.SearchOptions(starts=2, min_step=1e-4),
                              progress=lambda s, e, best: progress.append(best))
    assert r.values[0] == pytest.approx(100, rel=1e-3) and r.values[1] == pytest.approx(0.1, rel=1e-3)
    assert r.cost < 1e-6 and r.evaluations == len(calls) and progress


def test_cost_exception_propagates():
    def cost(v):
        raise ZeroDivisionError("bad cost")

    with pytest.raises(ZeroDivisionError, match="bad cost"):
        inerta.pattern_search([inerta.Variable("a")], cost)


def test_decode_describe():
    v = inerta.Variable("k", 1, 100)
    assert inerta.decode(v, 1.0) == pytest.approx(10)
    assert inerta.describe(0) == "open" and inerta.describe(float("inf")) == "rigid"
    assert inerta.decode(v, -10) == 0


def test_cubic_spline():
    x = np.linspace(0, 2 * np.pi, 41)
    s = inerta.CubicSpline(x, np.sin(x), "periodic")
    t = np.linspace(0, 6, 7)
    np.testing.assert_allclose(s(t), np.sin(t), atol=1e-4)
    np.testing.assert_allclose(s.slope(t), np.cos(t), atol=1e-3)
    assert s.curvature(1.0) == pytest.approx(-np.sin(1.0), abs=1e-2)
    assert s.mean() == pytest.approx(0, abs=1e-9) and s.x_max == pytest.approx(2 * np.pi)
    assert s.value(0.5) == pytest.approx(s(0.5))
    with pytest.raises(ValueError):
        inerta.CubicSpline([0, 1], [0, 1], "clamped")


def test_floquet_of_mathieus_equation():
    """x'' + (δ + ε cos t) x = 0: unstable in the tongue around δ = 1/4, det Φ = 1."""
    A = np.array([[0.0, 1.0], [-0.25, 0.0]])
    b = np.array([0.0, 1.0])
    r = lambda t: np.array([-0.1 * math.cos(t), 0.0])
    f = inerta.floquet(A, b, r, 2 * math.pi)
    assert not f.stable and f.largest > 1
    phi = inerta.monodromy(A, b, r, 2 * math.pi)
    assert np.linalg.det(phi) == pytest.approx(1.0, abs=1e-10)
    A[0, 0], A[1, 0] = 0.0, -0.5
    A[1, 1] = -0.02
    assert inerta.floquet(A, b, r, 2 * math.pi).stable
