"""Reports as a reader sees them: a sweep's HTML report rendered by Debian's headless Chromium loads
without errors, is not blank, says FAIL where a reader looks first, and its numbers are the CSV's."""
import html.parser
import shutil
import subprocess

import numpy as np
import pytest

import inerta
from conftest import model, read_csv


def chrome():
    exe = shutil.which("chromium-headless-shell") or shutil.which("chromium")
    if exe is None:
        pytest.fail("chromium-headless-shell missing: `make test` installs it (scripts/install-deps)")
    return exe


class Cells(html.parser.HTMLParser):
    """The text of each <td> of the table with id `table`, row by row."""

    def __init__(self, table):
        super().__init__()
        self.table, self.inside, self.rows, self.cell = table, False, [], None

    def handle_starttag(self, tag, attrs):
        if tag == "table" and dict(attrs).get("id") == self.table:
            self.inside = True
        elif self.inside and tag == "tr":
            self.rows.append([])
        elif self.inside and tag == "td":
            self.cell = ""

    def handle_endtag(self, tag):
        if tag == "table":
            self.inside = False
        elif tag == "td" and self.cell is not None:
            self.rows[-1].append(self.cell)
            self.cell = None

    def handle_data(self, data):
        if self.cell is not None:
            self.cell += data


@pytest.fixture(scope="module")
def failing_sweep(cli, tmp_path_factory):
    d = tmp_path_factory.mktemp("report")
    # the 3-mass pantograph without its aerodynamic trim on a short line: its mean force is below the AC band
    cli("sweep", model("pantograph-3mass.yaml"), "--catenary", model("catenary-fe.yaml"), "--set", "line.spans=4",
        "--speeds", "200:50:300", "--unit", "kmh", "--acceptance", "en50367-ac", "--out", d / "s.csv",
        "--report", d / "s.html")
    return d


def test_the_reports_numbers_are_the_csvs(failing_sweep):
    d = failing_sweep
    csv = read_csv(d / "s.csv")
    rec = inerta.read_report(str(d / "s.html"))
    assert rec.command == "sweep" and rec.commit == inerta.build_info().commit
    assert inerta.compare_reports(rec, rec) == []
    for i, v in enumerate(csv["v_kmh"]):
        key = f"v={v:g} km/h"
        for col, name in [("mean", "raw/mean"), ("std", "raw/std"), ("f_std", "filtered/std"), ("f_max", "filtered/max")]:
            assert rec.numbers[f"{key}/{name}"] == pytest.approx(csv[col][i], rel=5e-6), (key, col)
    # the statistics table as shown: the same text as the CSV's cells
    cells = Cells("statistics")
    cells.feed((d / "s.html").read_text(encoding="utf-8"))
    shown = [r for r in cells.rows if r]
    assert len(shown) == len(csv["v_kmh"])
    with open(d / "s.csv", encoding="utf-8") as f:
        f.readline()
        for row, line in zip(shown, f):
            fields = line.strip().split(",")
            assert row[0] == fields[0] and row[1:8] == fields[2:9]
    # the verdict table: the acceptance CSV's values
    import csv as csvlib
    with open(d / "s.acceptance.csv", encoding="utf-8", newline="") as f:
        acc = list(csvlib.DictReader(f))
    assert acc
    for r in acc:
        key = f"verdict/v={float(r['v_kmh']):g} km/h/panto {r['pantograph']}/{r['criterion']}/value"
        if np.isfinite(float(r["value"])):
            assert rec.numbers[key] == pytest.approx(float(r["value"]), rel=5e-6), key
    # and the inputs' SHA-256 are those of the files
    for f in rec.inputs:
        with open(f.path, encoding="utf-8") as fh:
            assert f.sha256 == inerta.sha256(fh.read()), f.path


def test_a_failing_report_says_fail_first_in_a_real_browser(failing_sweep):
    d = failing_sweep
    rec = inerta.read_report(str(d / "s.html"))
    assert rec.verdict == "FAIL"
    exe = chrome()
    # the page as the browser builds it: loads, no console error, the verdict banner is FAIL
    r = subprocess.run([exe, "--no-sandbox", "--disable-gpu", "--enable-logging=stderr", "--v=0", "--dump-dom",
                        (d / "s.html").as_uri()], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    dom = r.stdout
    assert "CONSOLE" not in r.stderr and "Uncaught" not in r.stderr, r.stderr
    first = dom.find('class="verdict')
    assert first != -1 and dom.find("<h2>") > first, "the verdict is the first thing after the title"
    assert dom[first:first + 200].count("FAIL") >= 1
    # the picture: not blank, and the top of the page carries the FAIL banner's red
    png = d / "s.png"
    r = subprocess.run([exe, "--no-sandbox", "--disable-gpu", f"--screenshot={png}", "--window-size=1000,1400",
                        (d / "s.html").as_uri()], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and png.exists(), r.stderr
    import matplotlib.image as mpimg
    img = mpimg.imread(png)[..., :3]
    dark = (img.mean(axis=2) < 0.5).mean()
    assert 0.005 < dark < 0.6, f"{dark:.4f} of the page is drawn"
    top = img[:200]
    # FAIL banner background #fbe3e3 (0.984, 0.890, 0.890): reddish, light
    reddish = (top[..., 0] > 0.95) & (top[..., 1] < 0.92) & (top[..., 1] > 0.85) & (top[..., 2] < 0.92)
    assert reddish.mean() > 0.05, f"{reddish.mean():.3f} of the page's top is the FAIL banner"
    # the SVG figures are drawn inline (no external resource)
    assert dom.count("<svg") >= 3 and 'src="http' not in dom


def test_read_report_refuses_what_is_not_one(tmp_path):
    p = tmp_path / "x.html"
    p.write_text("<html></html>")
    with pytest.raises(inerta.ModelError, match="not an Inerta report"):
        inerta.read_report(str(p))


def test_python_writes_the_same_report_as_the_cli(cli, tmp_path):
    """inerta.report_html of a sweep: the numbers the CLI's --report gives for the same run; of a coupled
    simulation with its catenary: the line's masts and droppers marked."""
    m3 = inerta.load_model(model("pantograph-3mass.yaml"))
    line = inerta.load_catenary(model("catenary-fe.yaml"), {"line.spans": 4})
    speeds = inerta.kmh([200.0, 250.0])
    page = inerta.report_html(inerta.sweep(m3, line, speeds), "en50367-ac", catenary=line, model="3-mass")
    (tmp_path / "py.html").write_text(page, encoding="utf-8")
    cli("sweep", model("pantograph-3mass.yaml"), "--catenary", model("catenary-fe.yaml"), "--set", "line.spans=4",
        "--speeds", "200:50:250", "--unit", "kmh", "--acceptance", "en50367-ac", "--out", tmp_path / "s.csv",
        "--report", tmp_path / "cli.html")
    py, c = inerta.read_report(str(tmp_path / "py.html")), inerta.read_report(str(tmp_path / "cli.html"))
    assert py.verdict == c.verdict and py.argv[0] == "python3"
    assert inerta.compare_reports(c, py, rtol=1e-12) == []
    run = inerta.simulate_coupled(m3, line, inerta.kmh(250.0))
    page = inerta.report_html(run, catenary=line)
    assert 'class="mark mast"' in page and 'class="mark dropper"' in page and "NO CRITERIA" in page
    with pytest.raises(TypeError, match="catenary"):
        inerta.report_html(run, catenary="line.yaml")
    with pytest.raises(TypeError, match="result"):
        inerta.report_html(3)
