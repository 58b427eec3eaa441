"""Library errors become Python exceptions with the CLI's message text (file:line)."""
import re

import pytest

import inerta
from conftest import SRC, model


def cli_error(cli, *args):
    r = cli(*args, check=False)
    assert r.returncode != 0
    line = r.stderr.strip().splitlines()[-1]
    return re.sub(r"^(error|numerical failure): ", "", line)


def test_classes():
    assert issubclass(inerta.ModelError, ValueError) and issubclass(inerta.ModelError, inerta.Error)
    assert issubclass(inerta.InvalidArgument, ValueError)
    assert issubclass(inerta.NumericalError, RuntimeError) and issubclass(inerta.NumericalError, inerta.Error)
    assert issubclass(inerta.NetworkError, ValueError)
    assert inerta.ModelError.__module__ == "inerta"


def bad_model(tmp_path, text):
    p = tmp_path / "bad.yaml"
    p.write_text(text)
    return p


def test_model_file_error_has_file_line_and_cli_text(cli, tmp_path):
    text = (SRC / "models" / "twobar.yaml").read_text().replace("k: 100, free_length", "k: -100, free_length")
    p = bad_model(tmp_path, text)
    with pytest.raises(inerta.ModelError) as e:
        inerta.load_model(p)
    msg = str(e.value)
    line = next(i for i, l in enumerate(text.splitlines(), 1) if "k: -100" in l)
    assert msg.startswith(f"{p}:{line}: ")
    assert msg == cli_error(cli, "check", p)


def test_yaml_syntax_error(cli, tmp_path):
    p = bad_model(tmp_path, "name: x\nbodies: [\n  {name: a\n")
    with pytest.raises(inerta.ModelError, match=rf"^{re.escape(str(p))}:\d+: YAML syntax error") as e:
        inerta.load_model(p)
    assert str(e.value) == cli_error(cli, "check", p)


def test_missing_file(cli):
    with pytest.raises(inerta.ModelError, match="nothere.yaml: cannot open the model file") as e:
        inerta.load_model("models/nothere.yaml")
    assert str(e.value) == cli_error(cli, "simulate", "models/nothere.yaml")


def test_bad_override(cli, twobar):
    with pytest.raises(inerta.ModelError) as e:
        inerta.load_model(model("twobar.yaml"), {"nosuch.k": 1})
    assert "no force element, body or joint named 'nosuch'" in str(e.value)
    with pytest.raises(inerta.ModelError, match=r"twobar.yaml:\d+: "):
        twobar.with_overrides({"k.k": -1})


def test_catenary_and_study_file_errors(cli, tmp_path):
    p = tmp_path / "cat.yaml"
    p.write_text("catenary:\n  span: 60\n  kc: [7000, 2100, 350, 140]\n  nonsense: 1\n")
    with pytest.raises(inerta.ModelError) as e:
        inerta.load_catenary(p)
    assert str(e.value).startswith(f"{p}:4: ")
    assert str(e.value) == cli_error(cli, "catenary-response", p, "--fp", "1:1:1")
    s = tmp_path / "study.yaml"
    s.write_text(f"model: {SRC}/models/hsx.yaml\ncatenary: {SRC}/models/catenary.yaml\n"
                 "speeds: {from: 100, to: 50, step: 10, unit: kmh}\nlayouts: [S2-1]\n")
    with pytest.raises(inerta.ModelError) as e:
        inerta.load_study(s)
    assert str(e.value).startswith(f"{s}:3: ")
    assert str(e.value) == cli_error(cli, "optimise", s)
    with pytest.raises(inerta.ModelError, match="cannot open"):
        inerta.load_catenary(tmp_path / "none.yaml")


def test_csv_errors_name_file_line_and_column(tmp_path):
    p = tmp_path / "m.csv"
    p.write_text("velocity,force\n0.1,10\n0.2,abc\n")
    t = inerta.CsvTable.read(p)
    assert t.names == ["velocity", "force"] and t.rows == 2 and t.line(1) == 3
    with pytest.raises(inerta.ModelError, match=rf"{re.escape(str(p))}:3: column 'force': 'abc' is not a finite number"):
        t.column("force")
    assert list(t["velocity"]) == [0.1, 0.2]


def test_invalid_argument_and_numerical_error(hsx, lumped):
    with pytest.raises(inerta.InvalidArgument) as e:
        inerta.Contact("penalty", stiffness=-1)
    assert e.value.parameter != "" or "stiffness" in str(e.value)
    with pytest.raises(inerta.InvalidArgument):
        inerta.Lumped(inerta.LumpedCatenary(span=-60))
    with pytest.raises(inerta.InvalidArgument, match="t_end"):
        inerta.simulate(hsx, t_end=float("inf"))
    # F_c reduced from 5374 N to 4000 N: the frame sinks and the bilateral contact would have to pull
    # the head down, a typed error with the time and the force (tests/pantograph/hsx_catenary_test.cpp)
    weak = hsx.with_overrides({"actuator.constant_force": -4000})
    with pytest.raises(inerta.NumericalError, match="bilateral contact force"):
        inerta.sweep(weak, lumped, [50.0])


def test_network_error_has_the_column():
    with pytest.raises(inerta.NetworkError) as e:
        inerta.parse("b-(k|c")
    assert e.value.column == 3
    with pytest.raises(inerta.NetworkError, match=r"no value for element\(s\) c"):
        inerta.assign(inerta.parse("k|c"), {"k": 1})
    with pytest.raises(ValueError):  # a NetworkError is a ValueError
        inerta.resolve("k|c-b")


# Each Python argument that mirrors a CLI option: the CLI's rule and message (the library's rule
# object, inerta::NumberRule/CountRule), checked before any computation.
M3 = model("pantograph-3mass.yaml")
CAT = model("catenary.yaml")
MIRRORED = [
    # (python function, keyword, value, CLI arguments up to the option, option, option's text)
    ("frf", "vc", -1, ["frf", M3, "--outputs", "y_head", "--freq", "1:1:2", "--method", "stepped-sine"], "--vc", "-1"),
    ("frf", "vc", float("nan"), ["frf", M3, "--outputs", "y_head", "--freq", "1:1:2", "--method", "stepped-sine"], "--vc", "nan"),
    ("frf", "cycles", 0, ["frf", M3, "--outputs", "y_head", "--freq", "1:1:2", "--method", "stepped-sine"], "--cycles", "0"),
    ("frf", "cycles", 2.5, ["frf", M3, "--outputs", "y_head", "--freq", "1:1:2", "--method", "stepped-sine"], "--cycles", "2.5"),
    ("frf", "analysed", 0, ["frf", M3, "--outputs", "y_head", "--freq", "1:1:2", "--method", "stepped-sine"], "--analysed", "0"),
    ("coupled", "spans", 0, ["simulate", M3, "--catenary", CAT, "--speed", "200"], "--spans", "0"),
    ("coupled", "spans", 10001, ["simulate", M3, "--catenary", CAT, "--speed", "200"], "--spans", "10001"),
    ("coupled", "t_end", -1, ["simulate", M3, "--catenary", CAT, "--speed", "200"], "--t-end", "-1"),
    ("coupled", "t_end", float("nan"), ["simulate", M3, "--catenary", CAT, "--speed", "200"], "--t-end", "nan"),
    ("coupled", "sample", 0, ["simulate", M3, "--catenary", CAT, "--speed", "200"], "--sample", "0"),
    ("response", "force", float("inf"), ["catenary-response", CAT, "--fp", "0.5:0.1:0.6"], "--force", "inf"),
    ("response", "force", 2e9, ["catenary-response", CAT, "--fp", "0.5:0.1:0.6"], "--force", "2e9"),
    ("sweep", "speeds", 0.0, ["sweep", M3, "--catenary", CAT, "--speeds", "0:10:20"], "--speeds", "ignored"),
    ("periodic", "speeds", 0.0, ["sweep", M3, "--catenary", CAT, "--speeds", "0:10:20", "--method", "periodic"],
     "--speeds", "ignored"),
    ("periodic", "harmonics", 0, ["sweep", M3, "--catenary", CAT, "--speeds", "50:10:60", "--method", "periodic"],
     "--harmonics", "0"),
    ("periodic", "harmonics", 257, ["sweep", M3, "--catenary", CAT, "--speeds", "50:10:60", "--method", "periodic"],
     "--harmonics", "257"),
    ("periodic", "harmonics", 2.5, ["sweep", M3, "--catenary", CAT, "--speeds", "50:10:60", "--method", "periodic"],
     "--harmonics", "2.5"),
]


def call(fn, kw, value, lumped):
    m3 = inerta.load_model(M3)
    if fn == "frf":
        if kw == "f":
            return inerta.frf_stepped_sine(m3, ["y_head"], [1.0, value])
        return inerta.frf_stepped_sine(m3, ["y_head"], [1.0], **{kw: value})
    if fn == "coupled":
        return inerta.simulate_coupled(m3, lumped, 50.0, **{kw: value})
    if kw == "speeds":
        return (inerta.sweep if fn == "sweep" else inerta.sweep_periodic)(m3, lumped, [50.0, value])
    if fn == "periodic":
        return inerta.sweep_periodic(m3, lumped, [50.0], **{kw: value})
    if kw == "fp":
        return inerta.catenary_response(lumped, [0.5, value])
    return inerta.catenary_response(lumped, [0.5], **{kw: value})


@pytest.mark.parametrize("fn,kw,value,args,option,text", MIRRORED)
def test_an_argument_is_refused_with_its_cli_options_message(cli, lumped, fn, kw, value, args, option, text):
    r = cli(*args, check=False) if text == "ignored" else cli(*args, option, text, check=False)  # "ignored": in args
    assert r.returncode == 105, r.stderr
    cli_message = r.stderr.splitlines()[0]
    assert cli_message.startswith(option + ": ")
    with pytest.raises(inerta.InvalidArgument) as e:
        call(fn, kw, value, lumped)
    assert str(e.value).startswith(kw + ": ")
    py, cl = str(e.value).split(": ", 1)[1], cli_message.split(": ", 1)[1]
    assert py.split("; expected")[-1] == cl.split("; expected")[-1]
    assert ("out of range" in py) == ("out of range" in cl) and ("whole number" in py) == ("whole number" in cl)
    assert ("finite" in py) == ("finite" in cl)


@pytest.mark.parametrize("fn,kw,value,message", [
    ("frf", "analysed", 200, "analysed: 200 is more than cycles (100); expected 1 … cycles"),
    ("coupled", "window_spans", 0, "window_spans: 0 is out of range; expected 1 … 10000"),
    ("response", "settle", -1, "settle: -1 is out of range; expected >= 0 s"),
    ("response", "periods", 0, "periods: 0 is out of range; expected 1 … 100000"),
    ("frf", "f", 0.0, "f: 0 is out of range; expected > 0 Hz, at most 1e6 Hz"),
    ("response", "fp", float("nan"), "fp: expected a finite number, got 'nan'"),
])
def test_arguments_without_a_cli_option_follow_the_library_rule(lumped, fn, kw, value, message):
    with pytest.raises(inerta.InvalidArgument, match=re.escape(message)):
        call(fn, kw, value, lumped)


def test_analysed_beyond_cycles_has_the_same_words_in_the_cli(cli):
    r = cli("frf", M3, "--outputs", "y_head", "--freq", "1:1:2", "--method", "stepped-sine", "--cycles", "10", "--analysed", "20", check=False)
    assert r.returncode == 105
    assert r.stderr.splitlines()[0] == "--analysed: 20 is more than cycles (10); expected 1 … cycles"


@pytest.mark.parametrize("field,value,message", [
    ("max_spans", 0, "max_spans: 0 is out of range; expected 1 … 10000"),
    ("window_spans", 0, "window_spans: 0 is out of range; expected 1 … 10000"),
    ("samples_per_span", 1, "samples_per_span: 1 is out of range; expected 10 … 1000000"),
])
def test_run_options_are_refused_before_the_run_not_crashed_on(lumped, field, value, message):
    m3 = inerta.load_model(M3)
    o = inerta.RunOptions(**{field: value})
    for run in (lambda: inerta.run_speed(m3, lumped, 50.0, options=o), lambda: inerta.sweep(m3, lumped, [50.0], options=o)):
        with pytest.raises(inerta.InvalidArgument, match=re.escape(message)):
            run()


def test_silent_accepts_of_the_real_line_inputs_are_errors():
    """Issue 52: False in an override dict is false; a study without speeds or layouts; two heads at one point."""
    stitched = model("catenary-fe-stitched.yaml")
    assert "70 droppers" in repr(inerta.load_catenary(stitched, {"stitch.enabled": False}))
    with pytest.raises(TypeError, match="'stitch.enabled': expected a number, a string or True/False"):
        inerta.load_catenary(stitched, {"stitch.enabled": [1]})
    s = inerta.load_study(f"{SRC}/studies/hsx-s2.yaml")
    with pytest.raises(inerta.InvalidArgument, match="speeds: empty"):
        s.replace(speeds=[])
    with pytest.raises(inerta.InvalidArgument, match="layouts: empty"):
        s.replace(layouts=[])
    m3 = inerta.load_model(M3)
    fe = inerta.load_catenary(model("catenary-fe.yaml"), {"line.spans": 4})
    with pytest.raises(inerta.InvalidArgument, match="pantographs 1 and 2 are both at x0 = 100 m"):
        inerta.simulate_coupled(m3, fe, 70.0, positions=[100.0, 100.0], t_end=0.05)


def test_the_study_calls_check_their_arguments_by_name():
    """Issue 52: no "Unable to cast", no AttributeError from inside a running study."""
    path = f"{SRC}/studies/hsx-s2.yaml"
    for call, message in [
        (lambda: inerta.optimise({}), "optimise: study: expected a Study"),
        (lambda: inerta.optimise(5), "optimise: study: expected a Study"),
        (lambda: inerta.run_study(path), "run_study: study: expected a Study or a ModelStudy"),
        (lambda: inerta.run_study(inerta.load_study(path), progress=5), "run_study: progress: expected a callable"),
        (lambda: inerta.optimise(path, client=object()), "optimise: client: expected a dask.distributed.Client"),
        (lambda: inerta.optimise(path, progress=5), "optimise: progress: expected a callable"),
        (lambda: inerta.optimise(path, early_stops="no"), "optimise: early_stops: expected True or False"),
    ]:
        with pytest.raises(TypeError, match=re.escape(message)):
            call()
    for kw in ({"stats": []}, {"checkpoint": "/tmp/never.pkl"}):
        with pytest.raises(ValueError, match="needs client="):
            inerta.optimise(path, **kw)
