"""Every network up to N elements, the positive-real test, synthesis, the exhaustive structure
search and the admittance bound from Python (docs/networks.md), against the same library facts the
C++ tests prove: the enumeration's counts by hand, canonical forms, exact PR decisions, a
synthesised network with the target's admittance, and a search that finds a known optimum."""
import json
import math

import numpy as np
import pytest

import inerta
from conftest import SRC


def test_enumeration_counts_options_and_canonical_forms():
    nets = inerta.enumerate_networks(inerta.EnumerationOptions(max_elements=2))
    assert nets[:3] == ["b", "c", "k"]
    assert len(nets) == 9  # 3 single elements, 3 pairs of types in series or in parallel
    opts = inerta.EnumerationOptions(max_elements=3, inerters=False, static_load=inerta.StaticLoad.required)
    for e in inerta.enumerate_networks(opts):
        n = inerta.parse(e)
        assert inerta.static_path(n)
        assert inerta.count_elements(n).inerters == 0
    n = inerta.assign(inerta.parse("(k1|k2)-c"), {"k1": 1000, "k2": 3000, "c": 50})
    c = inerta.canonical(n)
    assert inerta.structure(c) == "k-c"
    assert inerta.to_string(inerta.renamed(c)) == "k-c"
    assert inerta.count_elements(c).elements == 2
    s = 2j * math.pi * np.array([0.5, 3.0])
    assert np.allclose(inerta.admittance(c, s), inerta.admittance(n, s), rtol=1e-12)
    with pytest.raises(inerta.NetworkError):
        inerta.enumerate_networks(inerta.EnumerationOptions(max_elements=9))


def test_positive_real_and_synthesis():
    # k|c|b is positive real; a negative damper is not; the closed form agrees.
    assert inerta.positive_real([1000.0, 50.0, 2.0], [0.0, 1.0]).positive_real
    bad = inerta.positive_real([1.0, -0.5, 1.0], [1.0, 1.0, 1.0])
    assert not bad.positive_real and bad.reason
    assert inerta.biquadratic_positive_real(1, 1, 1, 1, 1, 1)
    assert not inerta.biquadratic_positive_real(1, 0.01, 1, 9, 0.01, 0.2)
    # A minimum function (Re Y touches 0 at ω = √2) needs a Bott–Duffin step; its realisation has
    # the target's admittance.
    num, den = [1.0, 1.0, 1.0], [4.0, 1.0, 1.0]
    assert inerta.positive_real(num, den).positive_real
    syn = inerta.synthesise(num, den)
    assert syn.bott_duffin and not syn.minimal_reactive
    s = 1j * np.logspace(-2, 2, 50)
    target = np.polyval(num[::-1], s) / np.polyval(den[::-1], s)
    assert np.allclose(inerta.admittance(syn.network, s), target, rtol=1e-9)
    leaf = inerta.admittance_leaf(num, den)
    assert leaf.kind == inerta.Network.Kind.admittance and leaf.num == num and leaf.den == den
    assert np.allclose(inerta.admittance(leaf, s), target, rtol=1e-12)
    assert inerta.reactive_elements(leaf) == 2
    with pytest.raises(inerta.NetworkError):
        inerta.synthesise([1.0, -0.5, 1.0], [1.0, 1.0, 1.0])


def test_prune_removes_what_does_not_matter():
    spring = inerta.assign(inerta.parse("k"), {"k": 1000})

    def cost(p):
        n = inerta.assign(inerta.parse("k|c"), p)
        s = 2j * math.pi * np.array([0.5, 5.0])
        return float(np.max(np.abs(inerta.admittance(n, s) - inerta.admittance(spring, s)))) + 1.0

    p = inerta.prune("k|c", {"k": 1000.0, "c": 1e-9}, cost, 1e-4)
    assert p["c"] == 0 and p["k"] == 1000


def test_exhaustive_search_of_a_model_study(tmp_path):
    study = tmp_path / "tmd-all.yaml"
    study.write_text(
        f"model: {SRC / 'models' / 'tmd.yaml'}\nstrut: absorber\n"
        "objective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8, points: 100}}\n"
        "layouts: all\nnetworks: {max_elements: 2, elements: [k, c]}\n"
        "search: {starts: 1, min_step: 0.02, lo: 0.01, hi: 1.0e7}\n")
    s = inerta.load_model_study(study)
    calls = []
    entries, results = inerta.optimise_all(s, progress=lambda *a: calls.append(a))
    assert len(entries) == len(results) == 4  # c, k, k-c, k|c
    order = inerta.ranking(entries)
    best = entries[order[0]]
    assert best.expression == "k|c"  # a spring–damper absorber beats any single element or series pair
    # The ranked best is at least as good as the same layout optimised on its own.
    alone = inerta.optimise_model_layout(s, "k|c")
    assert best.J <= alone.cost.J * (1 + 1e-9)
    assert calls and calls[-1][0] == calls[-1][1] == len(entries)
    pts = inerta.pareto_points(entries)
    assert any(p.pareto and p.elements == 2 for p in pts)
    doc = inerta.structure_results_json("tmd", "hinf", "m/N", entries[0].J, entries)
    assert doc["networks"][0]["network"] == "k|c"
    files = inerta.write_structure_results(tmp_path / "out", "tmd", "hinf", "m/N", entries[0].J, entries)
    assert [p.split("/")[-1] for p in files] == ["structure.csv", "structure.json", "pareto.csv"]
    assert json.loads((tmp_path / "out" / "structure.json").read_text())["objective"] == "hinf"
    # The degree-1 bound from the best network: never worse, positive real, realised.
    warm = inerta.assign(inerta.parse(best.expression), best.values)
    b = inerta.admittance_bound(s, 1, warm)
    assert b.J <= best.J * (1 + 1e-9)
    assert b.pr.positive_real
    assert b.synthesis is not None and b.synthesis.minimal_reactive
    assert b.J_realised == pytest.approx(b.J, rel=1e-6)
    assert b.degree == 1 and b.evaluations > 0 and b.synthesis_error == "" and b.warm_from
    assert b.cost == pytest.approx(b.J)
    assert len(b.y.num) <= 2 and len(b.y.den) <= 2
