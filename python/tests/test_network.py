"""Networks: parsing, values, simplification, admittance (as `inerta admittance`), layouts,
rational form and realisation."""
import numpy as np
import pytest

import inerta
from conftest import read_csv


def test_parse_assign_simplify():
    n = inerta.parse("b-(k|c)")
    assert str(n) == "b-(k|c)" and n.kind == inerta.Network.Kind.series
    assert inerta.parameter_names(n) == n.parameter_names() == ["b", "k", "c"]
    v = inerta.assign(n, {"b": 10, "k": 100, "c": 100})
    assert inerta.to_string(v, True) == "b=10-(k=100|c=100)"
    assert [c.kind for c in v.children] == [inerta.Network.Kind.inerter, inerta.Network.Kind.parallel]
    assert v.children[0].value == 10 and v.children[0].is_element() and v.children[0].column == 1
    s = inerta.simplify(inerta.assign(n, {"b": 10, "k": 0, "c": float("inf")}))
    assert s.kind == inerta.Network.Kind.inerter
    assert inerta.simplify(inerta.assign(n, {"b": 0, "k": 1, "c": 1})).kind == inerta.Network.Kind.open
    assert inerta.Network("k|c").simplify is not None


def test_admittance_equals_cli(cli, tmp_path):
    out = tmp_path / "y.csv"
    cli("admittance", "b-(k|c)", "--param", "b=10", "--param", "k=100", "--param", "c=100", "--freq", "0.5:0.5:5",
        "--out", out)
    ref = read_csv(out)
    n = inerta.resolve("b-(k|c)", {"b": 10, "k": 100, "c": 100})
    s = 2j * np.pi * ref["f_hz"]
    y = inerta.admittance(n, s)
    assert y.dtype == complex and y.shape == s.shape
    np.testing.assert_allclose(y.real, ref["re"], rtol=1e-9)
    np.testing.assert_allclose(y.imag, ref["im"], rtol=1e-9)
    assert inerta.admittance(n, s[0]) == pytest.approx(y[0])
    np.testing.assert_allclose(n.admittance(s), y)


def test_layouts():
    names = [l.name for l in inerta.layouts()]
    assert "S2-default" in names and "S2-1*" in names
    l = inerta.find_layout("S2-1*")
    assert l.expression == "b|c|k" and "c" in l.fixed
    assert inerta.find_layout("nope") is None
    n = inerta.resolve("S2-1*", {"b": 100, "k": 1e5})
    assert inerta.to_string(n, True).startswith("b=100|c=")
    with pytest.raises(inerta.NetworkError):
        inerta.resolve("S2-1*", {"b": 1, "k": 1, "c": 5})  # a fixed value cannot be overridden


def test_rational_and_realisation():
    n = inerta.simplify(inerta.resolve("b-(k|c)", {"b": 10, "k": 100, "c": 100}))
    r = inerta.rational_admittance(n)
    assert r.num == [0, 1000, 1000] and r.den == [100, 100, 10]
    s = np.array([1j, 2j, 0.5 + 3j])
    np.testing.assert_allclose(r(s), inerta.admittance(n, s))
    z = inerta.realise(n)
    assert z.n_states == 2 and z.A.shape == (2, 2) and z.d2 == 0
    np.testing.assert_allclose(z.dynamic_stiffness(s), s * inerta.admittance(n, s), rtol=1e-10)
    assert z.static_stiffness() == pytest.approx(0, abs=1e-9)
    assert z.steady_state(0.01).shape == (2,)
    with pytest.raises(inerta.NetworkError):
        inerta.realise(inerta.simplify(inerta.resolve("k", {"k": 0})))
