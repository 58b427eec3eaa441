"""Issue 38: nothing hangs or silently guesses from Python either — the cost guard (max_seconds=),
the speed rules of every run, non-regular model files."""
import os

import pytest

import inerta
from conftest import model


def test_load_model_refuses_a_device_as_the_cli_does():
    # /dev/zero would be read without end; a FIFO without a writer would block open().
    with pytest.raises(inerta.ModelError, match="not a regular file"):
        inerta.load_model("/dev/zero")


def test_load_model_refuses_a_fifo_without_waiting(tmp_path):
    fifo = tmp_path / "m.yaml"
    os.mkfifo(fifo)
    with pytest.raises(inerta.ModelError, match="not a regular file"):
        inerta.load_model(fifo)


def fe_line(**overrides):
    # Loading builds nothing (the line is built when first used), so the guard comes first.
    return inerta.load_catenary(model("catenary-fe.yaml"), overrides)


def test_an_expensive_run_is_refused_before_its_setup():
    panto = inerta.load_pantograph(model("pantograph-3mass.yaml"))
    cat = fe_line(**{"line.spans": 1000, "solver.type": "direct"})
    with pytest.raises(inerta.ModelError, match=r"this run is estimated at .* above the limit of 600 s; pass max_seconds="):
        inerta.simulate_coupled(panto, cat, inerta.kmh(250))
    with pytest.raises(inerta.ModelError, match=r"above the limit of 30 s"):
        inerta.sweep(panto, fe_line(**{"line.spans": 1000}), [inerta.kmh(250)], max_seconds=30)
    with pytest.raises(inerta.InvalidArgument, match="max_seconds"):
        inerta.simulate_coupled(panto, cat, inerta.kmh(250), max_seconds=float("nan"))


def test_speeds_without_end_or_beyond_any_train_are_refused():
    hsx = inerta.load_pantograph(model("hsx.yaml"))
    lumped = model("catenary.yaml")
    with pytest.raises(inerta.ModelError, match="beyond the limit of 1e"):
        inerta.sweep(hsx, lumped, [inerta.kmh(1e-9)])
    with pytest.raises(inerta.ModelError, match="beyond the limit of 1e"):
        inerta.simulate_coupled(hsx, lumped, inerta.kmh(1e-9))
    with pytest.raises(inerta.ModelError, match="above the fastest run accepted"):
        inerta.sweep(hsx, lumped, [1e300])


def test_above_the_wave_speed_unless_allowed(capfd):
    panto = inerta.load_pantograph(model("pantograph-3mass.yaml"))
    with pytest.raises(inerta.ModelError, match="above the contact wire's wave speed"):
        inerta.simulate_coupled(panto, fe_line(), inerta.kmh(600))
    # Near it (76 %): a warning on stderr, and the run goes on (a short one here).
    inerta.simulate_coupled(panto, fe_line(**{"solver.type": "direct", "line.spans": 3}), inerta.kmh(350))
    assert "76 % of the contact wire's wave speed" in capfd.readouterr().err


def test_distributed_workers_and_scheduler_are_checked_as_the_cli_does(tmp_path):
    import subprocess
    import sys

    from conftest import CLI, SRC

    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    r = subprocess.run([sys.executable, "-m", "inerta.distributed", "optimise", "study.yaml", "--workers", "100000"],
                       capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 2 and "expected 1 ... 1024" in r.stderr, r.stderr
    r = subprocess.run([sys.executable, "-m", "inerta.distributed", "optimise", "study.yaml", "--scheduler", ""],
                       capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 2 and "--scheduler: empty" in r.stderr, r.stderr
    r = subprocess.run([str(CLI), "optimise", str(SRC / "studies" / "tmd.yaml"), "--scheduler", ""],
                       capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 105 and "empty; expected the address of a running scheduler" in r.stderr, r.stderr


def test_simulate_refuses_what_the_cli_refuses():
    m = inerta.load_model(model("onedof.yaml"))
    with pytest.raises(inerta.InvalidArgument, match="steady_from"):
        inerta.simulate(m, t_end=0.01, steady_from=float("nan"))
    # True is not a number of seconds, nor a string: a TypeError naming the argument.
    with pytest.raises(TypeError, match="t_end: expected a number, got bool True"):
        inerta.simulate(m, t_end=True)
    with pytest.raises(TypeError, match="t_end: expected a number, got str '1'"):
        inerta.simulate(m, t_end="1")
    assert inerta.simulate(m, t_end=0.01, sample=0.005).t[-1] == pytest.approx(0.01)


def test_a_binary_or_non_utf8_file_is_a_model_error(tmp_path):
    png = tmp_path / "image.yaml"
    png.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\xff\xfe")
    with pytest.raises(inerta.ModelError, match=r"a binary file \(a NUL byte at offset 8\)"):
        inerta.load_model(png)
    latin = tmp_path / "latin.yaml"
    latin.write_bytes(b"bodies: [\xe9t\xe9]\n")  # Latin-1, not UTF-8: the message escapes its bytes
    with pytest.raises(inerta.ModelError):
        inerta.load_model(latin)


def test_a_model_too_large_for_the_dense_system_matrix_is_refused_at_its_line():
    # 100 000 bodies ended in std::bad_alloc; the limit is 10 000 coordinates.
    bodies = "".join(f"  - {{name: b{i}, mass: 1, inertia: 1, position: [{i}, 0]}}\n" for i in range(3334))
    with pytest.raises(inerta.ModelError, match=r"<text>:\d+: 'bodies': 3334 bodies \(10002 coordinates\): at most 10000"):
        inerta.parse_model("name: big\nbodies:\n" + bodies)
    inerta.parse_model("name: ok\nbodies:\n" + bodies[: bodies.index("  - {name: b100,")])  # 100 bodies: as before


def test_a_wrong_argument_type_is_named():
    # pybind's "Unable to cast Python instance of type ... to C++ type" named neither argument nor type.
    hsx = inerta.load_pantograph(model("hsx.yaml"))
    with pytest.raises(TypeError, match="options: expected a RunOptions, got dict"):
        inerta.sweep(hsx, model("catenary.yaml"), [50.0], options={"max_spans": 6})
    with pytest.raises(TypeError, match="t_end: expected a number, got str"):
        inerta.estimated_seconds(hsx, model("catenary-fe.yaml"), 50.0, "10")
