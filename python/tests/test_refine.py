"""The refinement's optimiser (issue 36): Study.refine_optimiser, inerta.model_search (NLopt's BOBYQA
and COBYLA), DesignCost's J and excess, and a BOBYQA refinement on a Dask cluster equal to the serial
one, resumed from its checkpoint without evaluating a design twice."""
import math
import pickle

import pytest

import inerta
from conftest import SRC

LUMPED = """name: small refine
model: {src}/models/hsx.yaml
catenary: {src}/models/catenary.yaml
speeds: {{from: 100, to: 300, step: 50, unit: kmh}}
search: {{starts: 1, seed: 7, min_step: 0.1}}
layouts: [S2-5, S2-4]
coarse: {{speeds: {{from: 100, to: 300, step: 100, unit: kmh}}}}
refine: {{{refine}}}
"""

# The FE line (3 spans, modes below 30 Hz) refined from the FE-fitted lumped line's optimum.
FE = """name: small refine FE
model: {src}/models/hsx.yaml
catenary: {src}/models/catenary-fe.yaml
catenaries: [[line.spans=3, solver.cutoff=30]]
speeds: {{from: 200, to: 200, step: 10, unit: kmh}}
layouts: [S2-5, S2-4]
coarse:
  catenary: {src}/models/catenary-fe-lumped.yaml
  catenaries: [[catenary.mc1=0, catenary.mc2=0, catenary.mc3=0]]
  speeds: {{from: 150, to: 300, step: 50, unit: kmh}}
  search: {{starts: 1, seed: 1, min_step: 0.2}}
refine: {{optimiser: bobyqa, initial_step: 0.25, min_step: 0.1, max_evaluations: 5}}
"""


def test_the_study_attribute(tmp_path):
    p = tmp_path / "s.yaml"
    for name in ["pattern", "bobyqa", "cobyla"]:
        p.write_text(LUMPED.format(src=SRC, refine=f"optimiser: {name}, max_evaluations: 20"))
        assert inerta.load_study(str(p)).refine_optimiser == name
    p.write_text(LUMPED.format(src=SRC, refine="max_evaluations: 20"))
    study = inerta.load_study(str(p))
    assert study.refine_optimiser == "cobyla"  # the default (docs/studies.md "Refinement optimisers")
    p.write_text(LUMPED.format(src=SRC, refine="optimiser: simplex"))
    with pytest.raises(inerta.ModelError, match=r"s\.yaml:8: 'optimiser': unknown optimiser"):
        inerta.load_study(str(p))
    # DesignCost: J2 and the excess besides the ranked cost, kept by pickle
    c = inerta.design_cost(study, "S2-5", {"k": 3e5})
    assert c.J == c.cost and c.excess == 0
    d = pickle.loads(pickle.dumps(c))
    assert (d.cost, d.unstable, d.J, d.excess) == (c.cost, c.unstable, c.J, c.excess)


def test_model_search_from_python():
    box = [inerta.Variable("x", 1e-2, 1e4, False, False), inerta.Variable("y", 1e-2, 1e4, False, False)]
    o = inerta.SearchOptions()
    o.initial_values = [[0.1, 1.0]]
    o.initial_step, o.min_step, o.max_evaluations = 0.5, 1e-7, 5000

    def rosenbrock(x):
        a, b = math.log10(x[0]), math.log10(x[1])
        return (1 - a) ** 2 + 100 * (b - a * a) ** 2

    r = inerta.model_search(box, rosenbrock, o, optimiser="bobyqa")
    assert abs(math.log10(r.values[0]) - 1) < 1e-2 and r.cost < 1e-4
    # (f, g): g <= 0 feasible; COBYLA reaches the constrained optimum u = v = 1
    r = inerta.model_search(box, lambda x: ((math.log10(x[0]) - 2) ** 2 + (math.log10(x[1]) - 2) ** 2,
                                            math.log10(x[0]) + math.log10(x[1]) - 2), o, optimiser="cobyla")
    assert abs(math.log10(r.values[0]) - 1) < 1e-2 and abs(r.cost - 2) < 1e-2
    with pytest.raises(ValueError):
        inerta.model_search(box, rosenbrock, o, optimiser="newuoa")


def test_a_bobyqa_refinement_on_dask_equals_the_serial_one_and_resumes(tmp_path):
    distributed = pytest.importorskip("distributed")
    p = tmp_path / "fe.yaml"
    p.write_text(FE.format(src=SRC))
    cp = tmp_path / "checkpoint.pkl"
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    client = distributed.Client(cluster)
    try:
        stats = {}
        o = inerta.distributed.optimise(p, client, checkpoint=cp, stats=stats)
        study, results = o.study, o.results
        assert study.refine_optimiser == "bobyqa" and study.method == "time"
        serial = [inerta.optimise_layout(study, l) for l in study.layouts]
        for a, b in zip(results, serial):
            assert pickle.dumps(a) == pickle.dumps(b)  # every field, bit for bit
        assert 0 < stats["designs_sent"] <= sum(r.evaluations for r in serial)
        with open(cp, "rb") as f:
            data = pickle.load(f)
        data["layouts"] = {}  # as if stopped after every design, before any layout was recorded
        with open(cp, "wb") as f:
            pickle.dump(data, f)
        again = {}
        resumed = inerta.distributed.optimise(p, client, checkpoint=cp, stats=again).results
        assert again["designs_sent"] == 0
        for a, b in zip(resumed, serial):
            assert pickle.dumps(a) == pickle.dumps(b)
    finally:
        client.close()
        cluster.close()


# Every network on a short FE line (issue 37): the coarse search's best reduced networks refined there.
FE_ALL = """name: small FE all
model: {src}/models/hsx.yaml
catenary: {src}/models/catenary-fe.yaml
catenaries: [[line.spans=3, solver.cutoff=30]]
speeds: {{from: 200, to: 200, step: 10, unit: kmh}}
bounds: {{inerter: [0.1, 1000], spring: [1, 1.0e6], damper: [1, 1.0e5]}}
layouts: all
networks: {{max_elements: 2}}
coarse:
  catenary: {src}/models/catenary-fe-lumped.yaml
  catenaries: [[catenary.mc1=0, catenary.mc2=0, catenary.mc3=0]]
  speeds: {{from: 150, to: 250, step: 50, unit: kmh}}
  search: {{starts: 1, seed: 1, min_step: 0.1}}
refine: {{best_networks: 2, initial_step: 0.3, min_step: 0.1, max_evaluations: 4}}
"""


def test_every_network_refined_on_the_fe_line_from_python(tmp_path):
    p = tmp_path / "fe-all.yaml"
    p.write_text(FE_ALL.format(src=SRC))
    study = inerta.load_study(p)
    assert study.refine_networks == 2 and study.coarse is not None
    o = inerta.optimise(study)
    assert len(o.results) == 2 == len(o.refinements)
    # Each result is its reduced network refined directly from its coarse optimum (bit for bit).
    for r, f in zip(o.results, o.refinements):
        expression, values = inerta.reduced_design(o.entries[f.entry])
        assert expression == r.expression
        direct = inerta.run_search(study, inerta.SearchTask(expression, [values], refine=True))
        assert pickle.dumps(direct.values) == pickle.dumps(r.values) and direct.cost.J == r.cost.J
    assert o.results[0].cost.penalised() <= o.results[1].cost.penalised()
    # refine_layout from a named layout's coarse result: what optimise_layout's refinement does.
    named = tmp_path / "named.yaml"
    named.write_text(FE_ALL.format(src=SRC).replace("layouts: all\nnetworks: {max_elements: 2}\n", "layouts: [S2-5]\n")
                     .replace("best_networks: 2, ", ""))
    ns = inerta.load_study(named)
    coarse = inerta.optimise_layout(ns.coarse, "S2-5")
    assert pickle.dumps(inerta.refine_layout(ns, "S2-5", coarse)) == pickle.dumps(inerta.optimise_layout(ns, "S2-5"))
