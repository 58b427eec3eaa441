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
