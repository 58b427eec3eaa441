"""The type stubs declare every public name of the module and every public member of its classes,
so that editors complete what exists."""
import ast
from pathlib import Path

import inerta
import inerta._inerta as ext

# The package's stub, assembled at build from python/stubs/*.pyi (one file a concept), which it must equal.
STUB = Path(inerta.__file__).resolve().parent / "_inerta.pyi"
PARTS = sorted((Path(__file__).resolve().parents[1] / "stubs").glob("*.pyi"))


def test_the_stub_is_its_parts():
    assert len(PARTS) > 1
    assert STUB.read_text(encoding="utf-8") == "".join(p.read_text(encoding="utf-8") for p in PARTS)


def stub_tree():
    tree = ast.parse(STUB.read_text(encoding="utf-8"))
    names, members = set(), {}

    def collect(body):
        out = set()
        for node in body:
            if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
                out.add(node.name)
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                out.add(node.target.id)
            elif isinstance(node, ast.Assign):
                out.update(t.id for t in node.targets if isinstance(t, ast.Name))
        return out

    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            names.add(node.name)
            members[node.name] = collect(node.body)
        elif isinstance(node, ast.FunctionDef):
            names.add(node.name)
    return names, members


def test_every_module_name_is_in_the_stub():
    names, _ = stub_tree()
    public = {n for n in dir(ext) if not n.startswith("_")}
    assert not public - names, f"missing in {STUB.name}: {sorted(public - names)}"
    assert not names - public - {"FloatArray"}, f"in the stub but not in the module: {sorted(names - public)}"


def test_every_class_member_is_in_the_stub():
    _, members = stub_tree()
    missing = []
    for n in dir(ext):
        cls = getattr(ext, n)
        if n.startswith("_") or not isinstance(cls, type) or issubclass(cls, BaseException):
            continue
        declared = members.get(n, set())
        for m in cls.__dict__:
            if m.startswith("_") or m in ("name", "value") and hasattr(cls, "__members__"):
                continue
            if m not in declared:
                missing.append(f"{n}.{m}")
    assert not missing, f"members missing in {STUB.name}: {missing}"


def test_docstrings():
    """Every bound function has a docstring (units are stated there)."""
    undocumented = [n for n in dir(ext) if callable(getattr(ext, n)) and not n.startswith("_")
                    and not isinstance(getattr(ext, n), type)
                    and len((getattr(ext, n).__doc__ or "").split("\n", 1)[-1].strip()) < 10]
    assert not undocumented, undocumented


def test_package_helpers():
    assert inerta.kmh(36) == 10
    assert list(inerta.kmh([36, 72])) == [10, 20]
