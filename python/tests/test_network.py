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


def test_draw_network_equals_cli_and_draws_every_element(cli, tmp_path):
    params = {"k1": 5.285e5, "k2": 1.671e5, "c": 6.19e4, "b": 526.5}
    svg = inerta.draw_network("k1|(k2-c-b)", params, title="k1|(k2-c-b)")
    out = tmp_path / "net.svg"
    cli("networks", "draw", "k1|(k2-c-b)", *[a for k, v in params.items() for a in ("--param", f"{k}={v}")],
        "--out", out)
    assert out.read_text() == svg
    assert svg.startswith("<svg") or svg.startswith("<?xml")
    for kind, name, label in [("spring", "k1", "k1 = 528 kN/m"), ("spring", "k2", "k2 = 167 kN/m"),
                              ("damper", "c", "c = 61.9 kN·s/m"), ("inerter", "b", "b = 526 kg")]:
        assert f'class="element {kind}" data-name="{name}"' in svg, name
        assert label in svg, label
    # the same from a bound Network, and names only without values
    assert inerta.draw_network(inerta.resolve("k1|(k2-c-b)", params), title="k1|(k2-c-b)") == svg
    bare = inerta.draw_network("k|c")
    assert 'data-name="k"' in bare and "kN/m" not in bare
    with pytest.raises(TypeError, match="network"):
        inerta.draw_network(3)
    with pytest.raises(inerta.NetworkError):
        inerta.draw_network("k|(c")


def test_a_schematic_renders_in_a_browser(tmp_path):
    """As a reader sees it: Debian's headless Chromium draws the SVG, and the picture is not blank."""
    import shutil
    import subprocess
    import matplotlib.image as mpimg
    chrome = shutil.which("chromium-headless-shell") or shutil.which("chromium")
    if chrome is None:
        pytest.fail("chromium-headless-shell missing: `make test` installs it (scripts/install-deps)")
    svg = tmp_path / "net.svg"
    svg.write_text(inerta.draw_network("k1|(k2-c-b)", {"k1": 5e5, "k2": 1.6e5, "c": 6e4, "b": 500}))
    png = tmp_path / "net.png"
    r = subprocess.run([chrome, "--no-sandbox", "--disable-gpu", f"--screenshot={png}", "--window-size=700,300",
                        svg.as_uri()], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and png.exists(), r.stderr
    img = mpimg.imread(png)[..., :3]
    dark = (img.mean(axis=2) < 0.5).mean()
    assert 0.002 < dark < 0.5, f"{dark:.4f} of the page is drawn"
