"""The key schema of finite-element line files (issue 51 item 1): docs/model-format.md's key table agrees
with inerta.fe_keys() key by key — unit, required, default and range — and every key of the schema is in it."""
import pathlib
import re

import inerta

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "model-format.md"
ROW = re.compile(r"^\| `([A-Za-z_.]+)` \| (.*?) \| (.*?) \| (.*?) \| (.*?) \| (.*) \|$")


def table():
    rows = {}
    text = DOC.read_text(encoding="utf-8")
    start = text.index("| key | unit | required | default | range | meaning |")
    for line in text[start:].split("\n")[2:]:
        if not line.startswith("|"):
            break
        m = ROW.match(line)
        assert m, f"a row of the key table that is not `key` | unit | required | default | range | meaning: {line}"
        rows[m.group(1)] = m.groups()[1:]
    return rows


def test_the_docs_key_table_is_the_schema():
    rows = table()
    keys = inerta.fe_keys()
    paths = {k["path"] for k in keys}
    assert paths <= set(rows), f"keys of the schema missing in docs/model-format.md: {sorted(paths - set(rows))}"
    extra = set(rows) - paths - {"contact.type", "contact.stiffness", "contact.damping"}
    assert not extra, f"rows of docs/model-format.md that are no key of the schema: {sorted(extra)}"
    for k in keys:
        unit, required, default, rng, meaning = rows[k["path"]]
        assert unit == (k["unit"] or "—"), (k["path"], unit, k["unit"])
        assert required == ("yes" if k["required"] else "no"), (k["path"], required)
        assert default == (k["default"] or "—"), (k["path"], default, k["default"])
        assert rng == k["range"], (k["path"], rng, k["range"])
        assert meaning, k["path"]


def test_the_sections_pass_places_the_sections_and_leaves_the_data_as_written():
    """A line of tension sections (issue 51 item 2): linked_sections() places each section along the line, its
    heights from the overlaps; the data read from the file keep what it says."""
    line = pathlib.Path(__file__).resolve().parents[2] / "models" / "catenary-fe-overlap.yaml"
    d = inerta.read_fe_catenary_data(line)
    linked = d.linked_sections()
    assert [s.first_span for s in linked] == [0, 9, 19]  # 12, 13, 12 spans sharing 3-span overlaps
    assert [s.line_start for s in linked] == [0.0, 585.0, 1235.0]
    assert [s.wire_label for s in linked] == [1, 2, 1]
    assert d.spans == 31 and d.span == 65
    assert all(len(s.mast_height) == 0 for s in d.tension_sections)  # as written
    assert linked[1].line.mast_height[0] == 0.5 and linked[0].line.mast_height[-1] == 0.5  # the anchors, raised
    assert len(linked[1].line.mast_height) == linked[1].line.spans + 1
