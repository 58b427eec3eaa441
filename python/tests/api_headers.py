"""The library's public API as its headers declare it (include/inerta/**/*.hpp), found in a simple
way that relies on the project's formatting (clang-format, namespaces not indented): every class,
struct or enum and every free function declared at column 0 inside a namespace, qualified by its
namespace below `inerta` ("analysis::simulate", "mbs::Model", "ModelError"). Members, type
aliases (`using`) and anything in a `detail` namespace are not listed."""
import re
from pathlib import Path

_TYPE = re.compile(r"^(?:struct|class|enum class|enum)\s+(\w+)(?:\s+final)?\s*(?::[^;{]*)?(?:\{.*)?$")
_FUNC = re.compile(r"^(?:\[\[\w+\]\]\s*)?(?:inline\s+|static\s+|constexpr\s+)*[\w:<>,\s\*&]+?[\s\*&](\w+)\s*\(")
_NS_OPEN = re.compile(r"^namespace\s+([\w:]+)\s*\{")
_NS_CLOSE = re.compile(r"^\}\s*//\s*namespace")


def _strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//.*", "", text)


def public_api(include_dir):
    """{qualified name: header path relative to include_dir} of every public symbol."""
    include_dir = Path(include_dir)
    found = {}
    for path in sorted(include_dir.rglob("*.hpp")):
        ns = []
        for raw in path.read_text(encoding="utf-8").splitlines():
            if _NS_CLOSE.match(raw):
                if ns:
                    ns.pop()
                continue
            line = _strip_comments(raw).rstrip()
            m = _NS_OPEN.match(line)
            if m:
                ns.append(m.group(1))
                continue
            if not line or line[0].isspace() or line.startswith(("#", "}", "using ", "template")):
                continue
            if not ns or any("detail" in n for n in ns):
                continue
            parts = "::".join(ns).split("::")
            if parts[0] != "inerta":
                continue
            prefix = "::".join(parts[1:])
            name = None
            m = _TYPE.match(line)
            if m and ("{" in line or not line.endswith(";")):
                name = m.group(1)
            elif "(" in line and not line.startswith(("return", "if", "for", "while", "struct", "class")):
                m = _FUNC.match(line)
                if m and m.group(1) not in ("operator",):
                    name = m.group(1)
            if name:
                found[(prefix + "::" if prefix else "") + name] = str(path.relative_to(include_dir))
    return found


if __name__ == "__main__":
    import sys

    for k, v in sorted(public_api(sys.argv[1] if len(sys.argv) > 1 else "include/inerta").items()):
        print(f"{k:45} {v}")
