"""Sweeps and studies on a Dask LocalCluster of 2 worker processes (issue 24, docs/distributed.md): the
same results as the serial runs to the last bit, a worker killed mid-task, a study resumed from its
checkpoint, and the CLI's --workers."""
import os
import pickle
import signal
import subprocess
import time

import numpy as np
import pytest

import inerta
from conftest import CLI, SRC, model

distributed = pytest.importorskip("distributed")

STUDY = """name: small distributed
model: {src}/models/hsx.yaml
catenary: {src}/models/catenary.yaml
speeds: {{from: 150, to: 300, step: 75, unit: kmh}}
search: {{starts: 1, seed: 3, min_step: 0.2}}
layouts: [S2-default, S2-5, S2-4, S2-3]
"""


# A time-domain study on a short finite-element line (3 spans, modes below 30 Hz): one task per design.
FE_STUDY = """name: small distributed FE
model: {src}/models/hsx.yaml
catenary: {src}/models/catenary-fe.yaml
catenaries: [[line.spans=3, solver.cutoff=30]]
speeds: {{from: 200, to: 200, step: 10, unit: kmh}}
search: {{starts: 1, seed: 7, min_step: 0.5, max_evaluations: 4}}
layouts: [S2-default, S2-5, S2-4]
"""


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture()
def study_file(tmp_path):
    p = tmp_path / "study.yaml"
    p.write_text(STUDY.format(src=SRC))
    return p


def same_sweep(a, b):
    assert len(a) == len(b)
    for x, y in zip(a, b):
        assert pickle.dumps(x) == pickle.dumps(y)  # every field, bit for bit


def test_results_travel_exactly():
    m = inerta.load_model(model("hsx.yaml"), ["k2.k=6000"])
    m2 = pickle.loads(pickle.dumps(m))
    assert m2.name == m.name and m2.overrides == m.overrides
    cat = inerta.load_catenary(model("catenary.yaml"), ["catenary.kc0=5000"])
    cat2 = pickle.loads(pickle.dumps(cat))
    assert cat2.path == cat.path and cat2.overrides == ["catenary.kc0=5000"]
    r = inerta.sweep(m, cat, [inerta.kmh(200)])
    same_sweep(r, pickle.loads(pickle.dumps(r.results)))
    s = inerta.load_study(os.path.join(SRC, "studies", "hsx-s2-demo.yaml"))
    lr = inerta.optimise_layout(s.replace(speeds=[60.0], layouts=["S2-5"]), "S2-5")
    lr2 = pickle.loads(pickle.dumps(lr))
    assert (lr2.layout, lr2.values, lr2.cost.J, lr2.evaluations) == (lr.layout, lr.values, lr.cost.J, lr.evaluations)


def test_what_cannot_travel_is_refused_with_the_reason():
    m = inerta.load_model(model("hsx.yaml")).with_options(centripetal=False)
    with pytest.raises(TypeError, match="transformed"):
        pickle.dumps(m)
    cat = inerta.load_catenary(model("catenary.yaml")).catenary
    with pytest.raises(TypeError, match="file name or a CatenaryFile"):
        inerta.distributed._catenary_key(cat)


def test_sweep_equals_the_serial_sweep(client):
    m = inerta.load_model(model("hsx.yaml"))
    speeds = inerta.kmh([150, 200, 250, 300])
    same_sweep(inerta.sweep(m, model("catenary.yaml"), speeds, client=client),
               inerta.sweep(m, model("catenary.yaml"), speeds))
    # a finite-element line (short, few modes): each worker decomposes it once and keeps it
    fe = inerta.load_catenary(model("catenary-fe.yaml"), ["line.spans=3", "solver.cutoff=30"])
    got = inerta.sweep(m, fe, inerta.kmh([200, 250]), client=client)
    same_sweep(got, inerta.sweep(m, fe, inerta.kmh([200, 250])))
    assert len(got[0].support_uplift) > 0


def test_a_killed_worker_loses_nothing(client):
    m = inerta.load_model(model("hsx.yaml"))
    speeds = inerta.kmh(np.arange(100, 321, 20))
    before = client.run(os.getpid)
    futures = [client.submit(inerta.distributed._sweep_speed, inerta.distributed._model_key(m),
                             inerta.distributed._catenary_key(model("catenary.yaml")), float(v), {}, pure=False)
               for v in speeds]
    deadline = time.time() + 30
    while not any(f.status == "finished" for f in futures) and time.time() < deadline:
        time.sleep(0.02)
    victim = next(iter(before.values()))
    os.kill(victim, signal.SIGKILL)  # mid-study: the other tasks are running or waiting
    results = client.gather(futures)
    same_sweep(results, inerta.sweep(m, model("catenary.yaml"), speeds).results)
    client.wait_for_workers(2, timeout=60)
    assert victim not in client.run(os.getpid).values()  # the nanny started a new worker process


def same_layouts(a, b):
    assert [r.layout for r in a] == [r.layout for r in b]
    for x, y in zip(a, b):
        assert pickle.dumps(x) == pickle.dumps(y)  # every field, bit for bit


def test_a_study_resumes_from_its_checkpoint(client, study_file, tmp_path):
    cp = tmp_path / "checkpoint.pkl"
    seen = []

    def stop_after_one(event, *values):
        if event == "searched":
            seen.append(values[1].layout)
            raise KeyboardInterrupt  # as Ctrl-C after the first finished layout

    with pytest.raises(KeyboardInterrupt):
        inerta.distributed.optimise(study_file, client, checkpoint=cp, progress=stop_after_one)
    assert cp.exists() and len(seen) == 1
    stats = {}
    o = inerta.optimise(inerta.load_study(study_file), client=client, checkpoint=cp, stats=stats)
    assert stats["searches_sent"] <= 3  # the finished layout is not run again
    serial = inerta.optimise(inerta.load_study(study_file))
    same_layouts(o.results, serial.results)
    assert (o.best.layout, o.best.J2) == (serial.best.layout, serial.best.J2)
    # a checkpoint of another study is refused
    other = tmp_path / "other.yaml"
    other.write_text(STUDY.format(src=SRC).replace("S2-3]", "S2-1]"))
    with pytest.raises(RuntimeError, match="another study"):
        inerta.distributed.optimise(other, client, checkpoint=cp)


def test_a_time_domain_study_sends_designs_and_never_evaluates_one_twice(client, tmp_path):
    p = tmp_path / "fe.yaml"
    p.write_text(FE_STUDY.format(src=SRC))
    cp = tmp_path / "fe-checkpoint.pkl"
    stats = {}
    o = inerta.distributed.optimise(p, client, checkpoint=cp, stats=stats)
    study = o.study
    assert study.method == "time"
    serial = [inerta.optimise_layout(study, l) for l in study.layouts]
    same_layouts(o.results, serial)
    searched = sum(r.evaluations for r in serial if inerta.free_parameters(r.layout))
    assert 0 < stats["designs_sent"] <= searched  # the searches' designs went to the workers
    assert stats["checks_sent"] == 1  # the default suspension's cost
    # As if stopped after every design but before any layout was recorded: the searches replay from
    # the checkpoint's designs and send none again.
    with open(cp, "rb") as f:
        data = pickle.load(f)
    assert len(data["designs"]) == stats["designs_sent"]
    data["layouts"] = {}
    with open(cp, "wb") as f:
        pickle.dump(data, f)
    again = {}
    resumed = inerta.distributed.optimise(p, client, checkpoint=cp, stats=again)
    assert again["designs_sent"] == 0 and again["checks_sent"] == 0
    same_layouts(resumed.results, serial)
    # a design's cost on a worker is the library's
    r = serial[1]
    assert inerta.design_cost(study, r.layout, {k: r.values[k] for k in inerta.free_parameters(r.layout)}).cost == \
        r.cost.penalised()


# A small `layouts: all` study: every network of up to two elements, one catenary, three speeds, the
# admittance bound of degree 2 (seconds).
ALL_STUDY = """name: small all
model: {src}/models/hsx.yaml
catenary: {src}/models/catenary.yaml
speeds: {{from: 150, to: 250, step: 50, unit: kmh}}
layouts: all
networks: {{max_elements: 2}}
admittance: [2]
search: {{starts: 1, seed: 1, min_step: 0.2}}
"""


def result_files(folder):
    """The files of an outcome, the wall-clock column of structure.csv/json masked."""
    out = {}
    for f in sorted(folder.iterdir()):
        if f.name == "checkpoint.pkl":
            continue
        if f.name == "report.html":  # its date and command line differ: its numbers do not
            import inerta
            out[f.name] = sorted(inerta.read_report(str(f)).numbers.items())
            continue
        text = f.read_text()
        if f.name == "structure.csv":
            text = "\n".join(",".join(c for i, c in enumerate(l.split(",")) if i != 14) for l in text.splitlines())
        elif f.name == "structure.json":
            import re
            text = re.sub(r'"seconds": [0-9.e+-]+', '"seconds": 0', text)
        out[f.name] = text
    return out


def test_the_outcome_is_the_same_from_the_cli_python_and_dask(client, tmp_path):
    p = tmp_path / "all.yaml"
    p.write_text(ALL_STUDY.format(src=SRC))
    python = inerta.optimise(inerta.load_study(p), out=tmp_path / "python")
    dask = inerta.optimise(inerta.load_study(p), out=tmp_path / "dask", client=client)
    assert python.best.verified and python.best.layout == dask.best.layout
    assert python.best.J2 == dask.best.J2 and python.best.values == dask.best.values
    assert [e.expression for e in python.entries] == [e.expression for e in dask.entries]
    same_layouts(python.results, dask.results)
    files = result_files(tmp_path / "python")
    assert {"recheck.csv", "structure.csv", "admittance.csv", "results.csv", "report.json"} <= set(files)
    assert (tmp_path / "dask" / "checkpoint.pkl").exists()
    assert result_files(tmp_path / "dask") == files
    if CLI.exists():
        cli = subprocess.run([str(CLI), "optimise", str(p), "--out", str(tmp_path / "cli"), "--no-plots"],
                             capture_output=True, text=True, cwd=SRC)
        assert cli.returncode == 0, cli.stderr
        assert result_files(tmp_path / "cli") == files
        assert f"best: {python.best.layout} " in cli.stdout and f"J2 = {python.best.J2:.3f} N" in cli.stdout


# A model study (objective:) runs through the same engine and executor: its named layouts in turn (each
# warm-started from the earlier optima) a task each, with layouts: all a task per network.
MODEL_ALL_STUDY = """name: small model all
model: {src}/models/tmd.yaml
strut: absorber
objective: {{type: hinf, input: F, outputs: {{x: 1}}, band: {{from: 3, to: 8, points: 200}}}}
layouts: all
networks: {{max_elements: 2}}
search: {{starts: 1, seed: 1, lo: 0.01, hi: 1.0e7, min_step: 0.05}}
"""


def test_a_model_study_on_dask_is_the_serial_one(client, tmp_path, capsys):
    quarter_car = os.path.join(SRC, "studies", "quarter_car.yaml")
    serial = inerta.optimise(quarter_car, out=tmp_path / "serial")
    # the driver of `inerta optimise --workers/--scheduler`, on this cluster
    assert inerta.distributed.main(["optimise", quarter_car, "--scheduler", client.scheduler.address,
                                    "--out", str(tmp_path / "dask"), "--no-plots"]) == 0
    files = result_files(tmp_path / "serial")
    assert {"results.csv", "results.json", "frf.csv", "report.html"} <= set(files)
    assert result_files(tmp_path / "dask") == files
    assert (tmp_path / "dask" / "checkpoint.pkl").exists()
    table = inerta.model_study_table(serial.model)
    assert table[:table.rindex("wall")] in capsys.readouterr().out
    p = tmp_path / "all.yaml"
    p.write_text(MODEL_ALL_STUDY.format(src=SRC))
    stats = {}
    dask = inerta.optimise(p, client=client, stats=stats)
    here = inerta.optimise(p)
    assert stats["searches_sent"] == len(here.model.entries) and stats["checks_sent"] == 1
    assert [pickle.dumps(r) for r in dask.model.results] == [pickle.dumps(r) for r in here.model.results]
    assert (dask.best.expression, dask.best.J) == (here.best.expression, here.best.J)


def test_a_killed_worker_during_a_layouts_all_study_loses_nothing(client, tmp_path):
    p = tmp_path / "all.yaml"
    p.write_text(ALL_STUDY.format(src=SRC))
    before = client.run(os.getpid)
    victim = next(iter(before.values()))
    killed = []

    def kill_once(event, *values):
        if event == "network" and not killed:  # the first network is in: the others are running or waiting
            os.kill(victim, signal.SIGKILL)
            killed.append(victim)

    o = inerta.optimise(inerta.load_study(p), client=client, progress=kill_once)
    assert killed
    serial = inerta.optimise(inerta.load_study(p))
    same_layouts(o.results, serial.results)
    assert o.recheck_csv() == serial.recheck_csv()
    assert (o.best.expression, o.best.J2) == (serial.best.expression, serial.best.J2)
    assert victim not in client.run(os.getpid).values()  # (the nanny's restart: test_a_killed_worker_loses_nothing)


def test_cli_workers_give_the_serial_table(study_file, tmp_path):
    if not CLI.exists():
        pytest.skip(f"CLI not built: {CLI}")
    serial = subprocess.run([str(CLI), "optimise", str(study_file), "--out", str(tmp_path / "a"), "--no-plots"],
                            capture_output=True, text=True, cwd=SRC)
    assert serial.returncode == 0, serial.stderr
    dist = subprocess.run([str(CLI), "optimise", str(study_file), "--workers", "2", "--out", str(tmp_path / "b"),
                           "--no-plots"], capture_output=True, text=True, cwd=SRC)
    assert dist.returncode == 0, dist.stderr + dist.stdout
    assert (tmp_path / "a" / "results.csv").read_bytes() == (tmp_path / "b" / "results.csv").read_bytes()
    assert (tmp_path / "a" / "results.json").read_bytes() == (tmp_path / "b" / "results.json").read_bytes()
    table = serial.stdout[serial.stdout.index("\n  layout"):serial.stdout.index("default suspension")]
    assert table in dist.stdout
    bad = subprocess.run([str(CLI), "optimise", str(study_file), "--workers", "2", "--scheduler", "tcp://x:1"],
                         capture_output=True, text=True, cwd=SRC)
    assert bad.returncode != 0 and "excludes" in bad.stderr
    missing = subprocess.run([str(CLI), "optimise", str(tmp_path / "none.yaml"), "--workers", "1"],
                             capture_output=True, text=True, cwd=SRC)
    assert missing.returncode == 2 and missing.stderr.startswith("error: ") and "Traceback" not in missing.stderr


# Every network on a short FE line (issue 37): the exhaustive search on the FE-fitted lumped line as a
# task per network, then the best two reduced networks refined on the FE line with their designs on the
# workers.
FE_ALL_STUDY = """name: small FE all
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
refine: {{best_networks: 2, screen: 3, initial_step: 0.3, min_step: 0.1, max_evaluations: 4}}
"""


def test_every_network_on_the_fe_line_is_the_same_on_dask(client, tmp_path):
    p = tmp_path / "fe-all.yaml"
    p.write_text(FE_ALL_STUDY.format(src=SRC))
    stats = {}
    local = inerta.optimise(inerta.load_study(p))
    dask = inerta.distributed.optimise(p, client, stats=stats)
    assert len(local.results) == 2 and [f.entry for f in local.refinements] == [f.entry for f in dask.refinements]
    same_layouts(local.results, dask.results)
    assert local.best.J2 == dask.best.J2 and local.best.values == dask.best.values
    assert stats["searches_sent"] == len(local.entries)  # a task per network of the coarse search
    assert stats["designs_sent"] > 0                     # the refinements' designs went to the workers
    assert local.refined_csv() == dask.refined_csv()
    # The screen (issue 49): its evaluations are checks sent to the workers, its ranking the same.
    assert len(local.screened) == 3 and sum(c.refined for c in local.screened) == 2
    assert local.screened_csv() == dask.screened_csv()
    assert stats["checks_sent"] >= 1 + 3
    assert local.coarse_rank_agreement == dask.coarse_rank_agreement
