"""Design studies: from a file and from Python objects, J2 as `inerta optimise` prints it, the
optimisation of a layout, the figures' data and the writers."""
import json
import re

import numpy as np
import pytest

import inerta
from conftest import SRC, model

STUDY = """name: small
model: {src}/models/hsx.yaml
catenary: {src}/models/catenary.yaml
catenaries:
  - [catenary.kc0=5000]
  - [catenary.kc0=7000]
speeds: {{from: 100, to: 300, step: 50, unit: kmh}}
search: {{starts: 1, seed: 1, min_step: 0.05}}
layouts: [S2-5, S2-3]
"""


@pytest.fixture(scope="module")
def study_file(tmp_path_factory):
    from conftest import SRC

    p = tmp_path_factory.mktemp("study") / "small.yaml"
    p.write_text(STUDY.format(src=SRC))
    return p


@pytest.fixture(scope="module")
def study(study_file):
    return inerta.load_study(study_file)


@pytest.fixture(scope="module")
def cli_out(study_file):
    from conftest import run_cli

    return run_cli("optimise", study_file).stdout


def test_study_file(study):
    assert study.name == "small" and study.layouts == ["S2-5", "S2-3"]
    assert study.catenary_labels == ["catenary.kc0=5000", "catenary.kc0=7000"]
    np.testing.assert_allclose(study.speeds, np.arange(100, 301, 50) / 3.6)
    assert study.search.starts == 1 and study.search.min_step == 0.05 and study.harmonics == 8
    assert [c.point_model().k[0] for c in study.catenaries] == [5000, 7000]
    assert len(study.operating_length) == 2 and study.pantograph.is_pantograph
    assert inerta.operating_lengths(study) == study.operating_length


def test_default_j2_equals_cli(study, cli_out):
    base = inerta.default_suspension(study)
    cost = inerta.evaluate(study, base)
    m = re.search(r"default suspension \((.*)\) J2 = ([0-9.]+) N at ([0-9.]+) km/h", cli_out)
    assert m.group(1) == inerta.to_string(base, True)
    assert round(cost.J, 3) == float(m.group(2)) and round(cost.speed * 3.6) == float(m.group(3))
    curves = inerta.sigma_curves(study, base)
    assert len(curves) == 2 and inerta.worst_of(curves).J == pytest.approx(cost.J, rel=1e-12)
    assert curves[0].catenary == "catenary.kc0=5000" and curves[0].sigma.shape == (5,)


def test_optimised_layouts_equal_cli(study, cli_out):
    seen = []
    for layout in study.layouts:
        r = inerta.optimise_layout(study, layout, progress=lambda s, e, best: seen.append(e))
        m = re.search(rf"{re.escape(layout)}\s+J = ([0-9.]+) N after (\d+) evaluations", cli_out)
        assert f"{r.cost.J:.4f}" == m.group(1) and r.evaluations == int(m.group(2))
        assert inerta.evaluate(study, r.network()).J == pytest.approx(r.cost.J, rel=1e-12)
    assert seen
    assert inerta.free_parameters("S2-1*") == ["b", "k"]
    # A layout that fixes a value (S2-default's c): its result lists it, and network() keeps the layout's own.
    d = inerta.optimise_layout(study, "S2-default")
    assert "c" in d.values and inerta.to_string(d.network(), True) == inerta.to_string(inerta.default_suspension(study), True)


def test_time_domain_recheck_equals_cli(study, cli_out):
    best = inerta.optimise_layout(study, "S2-5")
    check = inerta.evaluate_time(study, "S2-5", best.values)
    m = re.search(r"time-domain re-check J2 = ([0-9.]+) N at ([0-9.]+) km/h", cli_out)
    assert f"{check.J:.3f}" == m.group(1)


def test_one_call_runs_the_whole_study_as_the_cli(study_file, study, cli_out, tmp_path):
    events = []
    o = inerta.optimise(study_file, out=tmp_path / "o", progress=lambda event, *values: events.append(event))
    # the CLI's closing line is the engine's verified best
    m = re.search(r"best: (\S+) \((.*)\) — time-domain re-check J2 = ([0-9.]+) N", cli_out)
    assert (o.best.layout, o.best.expression) == (m.group(1), m.group(2)) and f"{o.best.J2:.3f}" == m.group(3)
    best = min((inerta.optimise_layout(study, l) for l in study.layouts), key=lambda r: r.cost.penalised())
    assert o.best.values == best.values
    assert o.best.J2 == pytest.approx(inerta.evaluate_time(study, best.network()).J, rel=1e-9)
    assert o.report is not None and o.time_check.J == o.best.J2
    # events: each layout, the searches' end, then the report's steps
    events = [e for e in events if e != "searching"]  # the searches' own progress, as many as they report
    assert events[:3] == ["searched", "searched", "searches_done"] and set(events[3:]) == {"report"}
    # the files are the outcome's, written again the same
    files = {f.name: f.read_bytes() for f in (tmp_path / "o").iterdir()}
    written = inerta.write_study_outcome(o, str(tmp_path / "again"))
    written.append(inerta.write_study_report(o, str(tmp_path / "again")))
    assert sorted(p.split("/")[-1] for p in written) == sorted(files)
    assert all((tmp_path / "again" / n).read_bytes() == b for n, b in files.items() if n != "report.html")
    # report.html: its date differs, its numbers do not; the ranking's networks are drawn
    first, again = inerta.read_report(str(tmp_path / "o" / "report.html")), inerta.read_report(str(tmp_path / "again" / "report.html"))
    assert first.command == "optimise" and inerta.compare_reports(first, again) == []
    assert first.numbers["best/J"] == o.best.J2
    page = (tmp_path / "o" / "report.html").read_text(encoding="utf-8")
    assert page.count('class="schematic"') >= 1 + len(o.results) or page.count("<svg") >= 1 + len(o.results)
    assert any(f.path.endswith(".yaml") for f in first.inputs)
    # a model study through the same call
    mo = inerta.optimise(inerta.load_model_study(f"{SRC}/studies/tmd.yaml"))
    assert mo.model is not None and mo.study is None
    assert mo.best.layout == mo.model.results[mo.model.best].layout and mo.best.J == mo.model.results[mo.model.best].cost.J
    # one rule for the best design of both kinds: the first smallest penalised cost
    assert mo.model.best == inerta.best_design([r.cost.penalised for r in mo.model.results])
    assert o.best.index == inerta.best_design([r.cost.penalised() for r in o.results])


def test_study_from_python_objects(study, hsx):
    cats = [inerta.load_catenary(model("catenary.yaml"), {"catenary.kc0": k}) for k in (5000, 7000)]
    s = inerta.Study(hsx, cats, inerta.kmh(range(100, 301, 50)), ["S2-5", "S2-3"],
                     search=inerta.SearchOptions(starts=1, seed=1, min_step=0.05))
    assert s.contact.kind == "bilateral" and len(s.catenary_labels) == 2 and s.source == "<python>"
    np.testing.assert_allclose(s.operating_length, study.operating_length, rtol=1e-12)
    base = inerta.default_suspension(s)
    assert inerta.evaluate(s, base).J == inerta.evaluate(study, base).J
    r = inerta.optimise_layout(s, "S2-5")
    assert r.cost.J == inerta.optimise_layout(study, "S2-5").cost.J
    fewer = s.replace(speeds=inerta.kmh([200]), layouts=["S2-5"])
    assert len(fewer.speeds) == 1 and fewer.layouts == ["S2-5"] and len(s.speeds) == 5
    assert inerta.evaluate(fewer, "k", {"k": 1e5}).J > 0
    with pytest.raises(inerta.InvalidArgument):
        inerta.Study(hsx, cats, [0.0], ["S2-5"])
    with pytest.raises(inerta.NetworkError):
        inerta.Study(hsx, cats, [50.0], ["k|"])


def test_report_and_writers(study, tmp_path):
    results = [inerta.optimise_layout(study, l) for l in study.layouts]
    o = inerta.ReportOptions()
    o.frf_f = [1.0, 2.0, 4.0]
    o.map_size = 0
    steps = []
    rep = inerta.make_report(study, results, o, progress=lambda *a: steps.append(a))
    assert rep.best.layout == "S2-5" and rep.frf_best.H.shape == (1, 3) and rep.map is None
    assert len(rep.sigma_best) == 2 and len(rep.history_best) == 2 and rep.history_best[0].F.size > 0
    assert rep.time_check.J > 0 and steps and steps[-1][3] == steps[-1][4]
    files = inerta.write_study_report(rep, tmp_path / "rep")
    assert any(f.endswith("report.json") for f in files)
    default = inerta.evaluate(study, inerta.default_suspension(study))
    written = inerta.write_study_results(tmp_path / "res", study.name, default, results)
    doc = json.loads((tmp_path / "res" / "results.json").read_text())
    assert len(written) == 2 and doc == inerta.study_results_json(study.name, default, results)
    assert doc["layouts"][0]["J2"] == pytest.approx(results[0].cost.J)


def test_maps_and_helpers(study, hsx):
    base = inerta.default_suspension(study)
    rig = inerta.rig_model(study, base)
    assert rig.has_rig
    cm = inerta.cost_map(study, "S2-1", {"c": 0.0}, "b", [0.0, 100.0], "k", [5e4, 1e5])
    assert cm.J.shape == (2, 2) and np.isfinite(cm.J).all() and list(cm.xs) == [0, 100]
    assert inerta.has_inerter(inerta.resolve("b|k", {"b": 10, "k": 1})) and not inerta.has_inerter(base)
    results = [inerta.optimise_layout(study, "S2-5")]
    assert inerta.best_with(results, "b", "k") == -1
    h = inerta.contact_histories(study, base, 200 / 3.6)
    assert len(h) == 2 and h[0].t.shape == h[0].F.shape and h[0].stats.std > 0
    curves = inerta.sigma_curves_time(study.replace(speeds=[200 / 3.6]), base, centripetal=False)
    assert curves[0].sigma[0] > 0


def test_limits_bounds_and_the_table(tmp_path):
    """Studies with limits and element bounds (issue 24): the same rules as the CLI's, from Python."""
    from conftest import SRC

    p = tmp_path / "limits.yaml"
    p.write_text(f"""name: limits
model: {SRC}/models/hsx.yaml
catenary: {SRC}/models/catenary.yaml
speeds: {{from: 100, to: 300, step: 100, unit: kmh}}
search: {{starts: 1, seed: 3, min_step: 0.2}}
limits: {{mean: [60, 80], contact_loss: 0}}
bounds: {{inerter: [0.1, 1000]}}
layouts: [S2-default, S2-3]
""")
    s = inerta.load_study(p)
    assert s.method == "periodic" and s.coarse is None and not s.all_networks
    assert s.limits.mean_min == 60 and s.limits.any() and s.bounds["b"].hi == 1000
    b, c = inerta.search_variables(s, "S2-3")
    assert (b.name, b.hi, b.can_rigid) == ("b", 1000, False) and c.can_rigid
    sweeps = [inerta.sweep_periodic(s.pantograph, s.catenaries[0], s.speeds).results]
    cost = inerta.cost_of(s, sweeps)
    assert cost.J == max(r.stats.std for r in sweeps[0]) and cost.feasible and cost.penalised() == cost.J
    default = inerta.evaluate(s, inerta.default_suspension(s))
    assert default.J == pytest.approx(cost.J, rel=1e-9)  # the default suspension relaxed there is the model's own
    results = [inerta.optimise_layout(s, l) for l in s.layouts]
    assert results[1].values["b"] <= 1000
    table = inerta.study_table(s, default, results)
    assert "S2-3" in table and "limits (every catenary and speed): mean 60–80 N; contact loss ≤ 0 %" in table
    names = inerta.study_output_names()
    assert "results.csv" in names and "checkpoint.pkl" in names
    out = tmp_path / "out"
    out.mkdir()
    (out / "mine.txt").write_text("a user's file")
    with pytest.raises(inerta.InvalidArgument):
        inerta.prepare_output_folder(str(out), names, False)
    inerta.prepare_output_folder(str(out), names, True)
    assert (out / "mine.txt").exists()


def test_a_study_of_two_pantographs_keeps_their_positions(tmp_path):
    text = open(f"{SRC}/studies/hsx-s2-fe-line.yaml", encoding="utf-8").read().replace("../models/", f"{SRC}/models/")
    p = tmp_path / "two.yaml"
    p.write_text(text + "pantographs: [0, 200]\n")
    s = inerta.load_study(p)
    assert s.positions == [0.0, 200.0] and inerta.load_study(f"{SRC}/studies/hsx-s2-fe-line.yaml").positions == [0.0]
    assert inerta.estimated_evaluation_seconds(s) > inerta.estimated_evaluation_seconds(
        inerta.load_study(f"{SRC}/studies/hsx-s2-fe-line.yaml"))


def test_evaluate_batch_equals_evaluate_one_by_one(tmp_path):
    """Issue 50: a batch of designs on a time-domain study (a short FE line, stepped together in lanes) gives the
    StudyCosts of evaluate one by one, bit for bit (pickled: every field); a failing design raises its exception."""
    p = tmp_path / "batch.yaml"
    p.write_text(f"""name: batch
model: {SRC}/models/hsx.yaml
catenary: {SRC}/models/catenary-fe.yaml
catenaries: [[line.spans=3, solver.cutoff=30]]
speeds: {{from: 200, to: 200, step: 10, unit: kmh}}
layouts: [S2-5]
""")
    s = inerta.load_study(p)
    assert s.method == "time"
    designs = [inerta.default_suspension(s), ("k", {"k": 1e4}), ["c|k", {"c": 2e3, "k": 3e3}], "S2-default",
               (inerta.parse("b|c"), {"b": 10, "c": 100})]
    one = [inerta.evaluate(s, d[0], d[1]) if isinstance(d, (tuple, list)) else inerta.evaluate(s, d) for d in designs]
    got = inerta.evaluate_batch(s, designs)
    import pickle

    assert [pickle.dumps(c) for c in got] == [pickle.dumps(c) for c in one]
    assert inerta.evaluate_batch(s, []) == []
    # A rigid design among good ones: evaluate's exception.
    with pytest.raises(inerta.ModelError) as alone:
        inerta.evaluate(s, "k", {"k": float("inf")})
    with pytest.raises(inerta.ModelError) as batch:
        inerta.evaluate_batch(s, [("k", {"k": 1e4}), ("k", {"k": float("inf")}), ("c", {"c": 1e3})])
    assert str(batch.value) == str(alone.value)
    # A design of the wrong form names its place in the list and the forms expected, before any run.
    for bad in [("k",), 42]:
        with pytest.raises(TypeError, match=r"designs\[1\] = .*expected a \(layout or expression, params\) pair"):
            inerta.evaluate_batch(s, [("k", {"k": 1e4}), bad])


def test_evaluate_batch_on_the_periodic_path(study):
    designs = [("S2-5", {"k": 1e4}), ("S2-3", {"b": 5, "c": 2e3}), inerta.default_suspension(study)]
    import pickle

    assert [pickle.dumps(c) for c in inerta.evaluate_batch(study, designs)] == [
        pickle.dumps(inerta.evaluate(study, *d) if isinstance(d, tuple) else inerta.evaluate(study, d)) for d in designs]
