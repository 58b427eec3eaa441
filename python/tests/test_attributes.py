"""Every bound function is called by the suite, and every property of every bound class is read
on an object that a real call produced (a binding that cannot convert its value fails here)."""
import pathlib
import re

import numpy as np
import pytest

import inerta
import inerta._inerta as ext
from conftest import model

TESTS = pathlib.Path(__file__).resolve().parent


def test_every_function_is_called_by_the_suite():
    src = "\n".join(p.read_text(encoding="utf-8") for p in TESTS.glob("test_*.py"))
    functions = [n for n in dir(ext) if not n.startswith("_") and not isinstance(getattr(ext, n), type)]
    uncalled = [n for n in functions if not re.search(rf"\binerta\.{n}\(", src)]
    assert not uncalled, f"bound functions that no test calls: {uncalled}"


def properties(cls):
    return [n for c in cls.__mro__ for n, v in vars(c).items() if isinstance(v, property) and not n.startswith("_")]


def touch(obj, seen):
    cls = type(obj)
    if cls.__module__ not in ("inerta", "inerta._inerta") or isinstance(obj, (int, float, str)):
        return
    first = cls.__name__ not in seen
    seen.update(c.__name__ for c in cls.__mro__)
    if not first:
        return
    for name in properties(cls):
        value = getattr(obj, name)
        items = value if isinstance(value, (list, tuple)) else [value]
        for v in items[:2]:
            if v is not None:
                touch(v, seen)


@pytest.fixture(scope="module")
def objects(hsx, lumped, twobar, tmp_path_factory):
    out = []
    x, rep = inerta.assemble(twobar)
    out += [twobar, hsx, x, rep, twobar.check(), inerta.static_equilibrium(twobar)[1], twobar.options]
    out += hsx.bodies[:1] + hsx.markers[:1] + hsx.joints[:1] + hsx.forces + hsx.outputs[:1]
    r = inerta.simulate(twobar, 1.0, 0.1, steady_from=0.5, from_equilibrium=True)
    out += [r, r.summary(0.0)[0], inerta.IntegratorOptions(), inerta.RunOptions(), inerta.SteppedSine()]
    s = inerta.sweep(hsx, lumped, [50.0], options=inerta.RunOptions(min_spans=6, fixed_spans=True))
    out += [s, s[0], inerta.run_speed(hsx, lumped, 50.0, options=inerta.RunOptions(min_spans=6, fixed_spans=True))]
    c = inerta.simulate_coupled(hsx, lumped, 50.0, spans=2)
    out += [c, c.contacts[0], lumped, lumped.catenary, lumped.contact, lumped.catenary.point_model()]
    prof = inerta.load_catenary(model("wire-profile.yaml"))
    out += [prof.catenary, prof.catenary.profile]
    out += [inerta.PantographOnLine(hsx), inerta.couple_lumped(hsx, lumped.catenary.point_model(), lumped.contact, 50.0)]
    ma = inerta.modal_analysis(hsx)
    out += [ma, ma.linear, ma.modes[0], inerta.frf_linear(hsx, ["P_ay"], [1.0, 2.0])]
    cr = inerta.catenary_response(lumped, [0.5], settle=5, periods=2)
    out += [cr, cr[0]]
    n = inerta.simplify(inerta.resolve("b-(k|c)", {"b": 10, "k": 100, "c": 100}))
    out += [n, inerta.layouts()[0], inerta.rational_admittance(n), inerta.realise(n)]
    st = inerta.Study(hsx, [lumped], [50.0, 60.0], ["S2-5"], search=inerta.SearchOptions(starts=1, min_step=0.1))
    lr = inerta.optimise_layout(st, "S2-5")
    out += [st, lr, lr.cost, inerta.sigma_curves(st, "k", {"k": 1e5})[0], st.search, st.limits,
            inerta.design_cost(st, "S2-5", {"k": 1e5})]
    bounded = tmp_path_factory.mktemp("bounds") / "bounds.yaml"
    bounded.write_text(f"name: b\nmodel: {model('hsx.yaml')}\ncatenary: {model('catenary.yaml')}\n"
                       "speeds: {from: 100, to: 100, step: 10, unit: kmh}\nbounds: {spring: [1, 1.0e6]}\nlayouts: [k]\n")
    out += [inerta.load_study(bounded).bounds["k"]]
    out += [inerta.contact_histories(st, "k", 50.0, {"k": 1e5})[0]]
    out += [inerta.cost_map(st, "S2-1", {"c": 0.0}, "b", [0.0, 10.0], "k", [1e5, 2e5])]
    o = inerta.ReportOptions()
    o.map_size, o.frf_f = 0, [1.0]
    out += [inerta.make_report(st.replace(layouts=["S2-5"]), [lr], o), o]
    o.best = 1  # one result: index 1 does not exist
    with pytest.raises(ValueError, match="best = 1 but there are 1 layout results"):
        inerta.make_report(st.replace(layouts=["S2-5"]), [lr], o)
    o.best = 0
    out += inerta.read_fe_catenary_data(model("catenary-fe-overlap.yaml")).linked_sections()[:1]
    p = tmp_path_factory.mktemp("csv") / "m.csv"
    p.write_text("a,b\n1,2\n3,4\n")
    t = inerta.CsvTable.read(p)
    assert t.has("a") and not t.has("c")
    t.require_rows(2, "this test")
    out += [t]
    f = np.arange(1.0, 10.0)
    H = (-1 - 7000 * 0.02 / (2 * np.pi * f) ** 2) / (7 - 7000 / (2 * np.pi * f) ** 2) + 0j
    out += [inerta.fit_head_suspension(7.0, f, H, np.full(f.shape, 0.02 + 0j), 1, 9)]
    meas = inerta.frf_linear(hsx, ["P_ay"], [1.0, 2.0, 3.0])
    out += [inerta.fit_frf(hsx, ["c2.c"], meas, inerta.SearchOptions(starts=1, min_step=0.1))]
    out += [inerta.fit_line([0, 1], [0, 1]), inerta.fit_actuator_static([-0.1, -0.2, 0.1, 0.2], [-1, -2, 1, 2])]
    tt = np.linspace(0, 2, 400)
    dt = inerta.DynamicTest(1.0, tt, 1e-3 * np.sin(2 * np.pi * tt), 10 * np.cos(2 * np.pi * tt))
    out += [dt, inerta.fit_actuator_dynamic([dt], 1e4, 0.0, 0.0), inerta.Variable("k")]
    out += [inerta.pattern_search([inerta.Variable("k", 1, 10, False, False)], lambda v: (v[0] - 3) ** 2)]
    out += [inerta.CubicSpline([0, 1, 2], [0, 1, 0])]
    fe = inerta.load_catenary(model("catenary-fe.yaml"), {"line.spans": 3})
    out += [fe, fe.catenary, fe.catenary.line, fe.fe, inerta.fit_lumped(fe.catenary, points=32)]
    fe_direct = inerta.load_catenary(model("catenary-fe.yaml"), {"line.spans": 3, "solver.type": "direct"})
    out += inerta.compare(inerta.load_model(model("pantograph-3mass.yaml")), fe_direct, fe, [60.0])
    out += [inerta.load_lumped_pantograph_data(model("pantograph-3mass.yaml"))]
    out += [inerta.load_acceptance("en50367-ac"),
            inerta.fit_aerodynamic(inerta.load_model(model("pantograph-3mass.yaml")), fe, 80.0, "en50367-ac")]
    out += [inerta.commission(inerta.load_model(model("pantograph-3mass.yaml")), fe, 80.0, "en50367-ac")[1],
            inerta.Trim(), inerta.WorkingRange()]
    lp = inerta.butterworth_lowpass(20.0, 1000.0)
    tt = np.arange(2000) / 1000.0
    FF = 100 + np.sin(2 * np.pi * 3 * tt)
    out += [lp, inerta.welch(FF, 1000.0), inerta.WelchOptions(), inerta.ContactQualityOptions()]
    out += [inerta.contact_quality(tt, 10 * tt, FF, 1.0, 15.0)]
    out += [inerta.part_statistics(tt, 10 * tt, FF, inerta.Section(1.0, 15.0), [inerta.Section(2.0, 5.0)])]
    out += inerta.support_uplift([0.0, 1.0], [5.0], [[0.0], [0.01]], 0, 10)
    out += [inerta.Stepper(twobar, x), inerta.Section(0, 1)]
    qc = inerta.load_model(model("quarter_car.yaml"))
    ss = inerta.state_space(qc, ["road"], ["a_body", "travel"])
    road = inerta.Road()
    road.speed, road.inputs = 25.0, ["road"]
    xq, _ = inerta.assemble(qc)
    linq = inerta.linearise(qc, xq)
    out += [ss, ss.system, inerta.road_response(ss, road), road, inerta.undamped_modes(qc, linq)[0]]
    ms = inerta.load_model_study(pathlib.Path(model("tmd.yaml")).parent.parent / "studies" / "tmd.yaml")
    mr = inerta.optimise_model_layout(ms, "k|c")
    out += [ms, ms.objective, ms.objective.outputs[0], mr, mr.cost]
    out += [inerta.objective_map(ms, "k|c", mr.values, "k", "c", n=2), inerta.study_frf(ms, "k|c", mr.values, [5.0])]
    bound_study = tmp_path_factory.mktemp("study") / "tmd-bound.yaml"
    bound_study.write_text(f"""name: one layout and the degree-1 bound
model: {model("tmd.yaml")}
strut: absorber
objective: {{type: hinf, input: F, outputs: {{x: 1}}, band: {{from: 3, to: 8, points: 50}}}}
layouts: ["k|c"]
admittance: [1]
search: {{starts: 1, seed: 1, min_step: 0.05}}
""")
    msr = inerta.run_model_study(inerta.load_model_study(bound_study))
    out += [msr, inerta.model_study_figures(msr)]
    qs = inerta.load_model_study(pathlib.Path(model("quarter_car.yaml")).parent.parent / "studies" / "quarter_car.yaml")
    out += [qs.objective.limits[0]]
    opts = inerta.EnumerationOptions(max_elements=2, inerters=False)
    entries, _ = inerta.optimise_all(ms)  # the four fixed layouts of studies/tmd.yaml as a structure search
    out += [opts, inerta.count_elements(inerta.parse("k|c")), inerta.positive_real([1.0], [1.0]),
            inerta.synthesise([1.0, 1.0, 1.0], [4.0, 1.0, 1.0]), entries[0], inerta.pareto_points(entries)[0]]
    out += [inerta.admittance_bound(ms, 1, inerta.resolve("k|c", mr.values))]
    out += [inerta.floquet([[0.0, 1.0], [-1.0, -0.1]], [0.0, 1.0], lambda t: [0.0, 0.0], 1.0)]
    so = inerta.run_study(st, inerta.StudyOptions(report=False), executor=inerta.LocalExecutor())
    all_study = tmp_path_factory.mktemp("all") / "all.yaml"
    all_study.write_text(f"name: all\nmodel: {model('hsx.yaml')}\ncatenary: {model('catenary.yaml')}\n"
                         "speeds: {from: 150, to: 200, step: 50, unit: kmh}\nlayouts: all\nnetworks: {max_elements: 1}\n"
                         "search: {starts: 1, seed: 1, min_step: 0.3}\n")
    sa = inerta.run_study(inerta.load_study(all_study))
    out += [so, so.best, sa, sa.rechecks[0], inerta.StudyOptions(), inerta.LocalExecutor(), inerta.SearchTask("k"),
            inerta.CheckTask("k", {"k": 1e5}), inerta.run_check(st, inerta.CheckTask()),
            inerta.run_search(st, inerta.SearchTask("S2-5")), inerta.run_study(inerta.load_model_study(bound_study)),
            inerta.run_check(ms, inerta.CheckTask())]
    # Every network on a short FE line with the acceptance set as limits (issue 37): Refinement, MarginRow; its
    # screen (issue 49): Screened.
    fe_all = tmp_path_factory.mktemp("feall") / "fe-all.yaml"
    fe_all.write_text(FE_ALL.format(hsx=model("hsx.yaml"), fe=model("catenary-fe.yaml"),
                                    lumped=model("catenary-fe-lumped.yaml")))
    ro = inerta.ReportOptions()
    ro.map_size = 0
    fa = inerta.run_study(inerta.load_study(fe_all), inerta.StudyOptions(report=True, report_options=ro))
    out += [fa, fa.refinements[0], fa.report.margins[0], fa.screened[0]]
    # The verdict line and a study's estimate (issue 52).
    m3 = inerta.load_model(model("pantograph-3mass.yaml"))
    out += [inerta.verdict(inerta.sweep(m3, inerta.load_catenary(model("wire-profile.yaml")), [80.0]), "en50367-ac"),
            inerta.estimated_study_seconds(inerta.load_study(fe_all))]
    # Reports (issue 53): a report's record, its inputs, the differences between two, the build.
    from conftest import run_cli
    rp = tmp_path_factory.mktemp("reports")
    for v in ("200", "250"):
        run_cli("sweep", model("pantograph-3mass.yaml"), "--catenary", model("catenary-fe.yaml"), "--set", "line.spans=3",
                "--speeds", f"{v}:1:{v}", "--unit", "kmh", "--out", rp / f"{v}.csv", "--report", rp / f"{v}.html")
    r200, r250 = inerta.read_report(str(rp / "200.html")), inerta.read_report(str(rp / "250.html"))
    out += [r200, inerta.compare_reports(r200, r250)[0], inerta.build_info()]
    return out


FE_ALL = """name: fe all
model: {hsx}
catenary: {fe}
catenaries: [[line.spans=3, solver.cutoff=30]]
speeds: {{from: 200, to: 200, step: 10, unit: kmh}}
limits: {{acceptance: en50367-ac}}
layouts: all
networks: {{max_elements: 1}}
coarse:
  catenary: {lumped}
  catenaries: [[catenary.mc1=0, catenary.mc2=0, catenary.mc3=0]]
  speeds: {{from: 150, to: 250, step: 50, unit: kmh}}
  search: {{starts: 1, seed: 1, min_step: 0.3}}
refine: {{best_networks: 1, screen: 2, initial_step: 0.3, min_step: 0.2, max_evaluations: 2}}
"""


def test_every_class_is_produced_and_its_properties_convert(objects):
    seen = set()
    for o in objects:
        touch(o, seen)
    classes = {n for n in dir(ext) if isinstance(getattr(ext, n), type) and not n.startswith("_")
               and not issubclass(getattr(ext, n), BaseException) and not hasattr(getattr(ext, n), "__members__")}
    assert not classes - seen, f"classes no test object exercises: {sorted(classes - seen)}"
