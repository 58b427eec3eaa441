"""Every public function and class of the library is bound, or excluded with a reason."""
import fnmatch

import inerta
from api_headers import public_api
from api_manifest import BOUND, EXCLUDED
from conftest import SRC


def resolve(path):
    obj = inerta
    for part in path.split("."):
        obj = getattr(obj, part)
    return obj


def excluded(symbol):
    return any(fnmatch.fnmatchcase(symbol, pattern) for pattern in EXCLUDED)


def test_headers_are_parsed():
    api = public_api(SRC / "include" / "inerta")
    # a sample of what must be found, so that a broken parser cannot pass the test below
    for s in ["analysis::simulate", "analysis::sweep", "mbs::Model", "io::load_model", "network::parse",
              "optim::optimise_layout", "catenary::Catenary", "ModelError", "solve::Method"]:
        assert s in api, s
    assert len(api) > 150


def test_every_public_symbol_is_bound_or_excluded():
    api = public_api(SRC / "include" / "inerta")
    missing = sorted(s for s in api if s not in BOUND and not excluded(s))
    assert not missing, ("not bound and not excluded with a reason (python/tests/api_manifest.py): "
                         + ", ".join(f"{s} ({api[s]})" for s in missing))


def test_bound_names_exist():
    absent = []
    for symbol, path in BOUND.items():
        try:
            resolve(path)
        except AttributeError:
            absent.append(f"{symbol} -> inerta.{path}")
    assert not absent, "bound names missing from the module: " + ", ".join(absent)


def test_manifest_has_no_stale_entries():
    api = public_api(SRC / "include" / "inerta")
    stale = [s for s in BOUND if s not in api]
    stale += [p for p in EXCLUDED if not any(fnmatch.fnmatchcase(s, p) for s in api)]
    assert not stale, "manifest entries without a header symbol: " + ", ".join(stale)
    assert not set(BOUND) & set(EXCLUDED)
    assert all(len(reason) > 10 for reason in EXCLUDED.values())
