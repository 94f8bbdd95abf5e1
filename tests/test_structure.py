"""The package's shape: no import cycle between modules, no module over 400 lines.

The import graph is read from the source with :mod:`ast` (nothing is imported): every
``import birdsim.x`` and ``from birdsim.x import y`` anywhere in a module (at the top, in
a function, under ``TYPE_CHECKING``) is an edge to the module it names (``birdsim.x.y``
when ``y`` is a module, else ``birdsim.x``).  Importing a module also runs its packages'
``__init__`` files, but those edges are left out: a package's ``__init__`` re-exports its
modules by design, and counting it would put every module on a cycle with ``birdsim``.
Cycles are the graph's strongly connected components with more than one module (or a
module importing itself), from :func:`scipy.sparse.csgraph.connected_components`.
"""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
import pytest
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import connected_components

PACKAGE = Path(__file__).resolve().parent.parent / "birdsim"
MAX_LINES = 400

#: Modules over 400 lines that other engineers are changing on their branches right now
#: (they keep them under 400 there); the lead removes these exemptions after merging.
OVER_LIMIT_ELSEWHERE: set[str] = set()


def module_name(path: Path) -> str:
    rel = path.relative_to(PACKAGE.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def modules() -> dict[str, Path]:
    return {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def imports_of(name: str, path: Path, known: set[str]) -> set[str]:
    """The birdsim modules that module ``name`` (file ``path``) imports anywhere."""
    tree = ast.parse(path.read_text(), filename=str(path))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base_parts = package.split(".")
                base_parts = base_parts[: len(base_parts) - (node.level - 1)]
                base = ".".join(base_parts + ([node.module] if node.module else []))
            else:
                base = node.module or ""
            targets = []
            for alias in node.names:
                sub = f"{base}.{alias.name}"
                targets.append(sub if sub in known else base)
        else:
            continue
        for target in targets:
            # `import birdsim.a.b` names birdsim.a.b; keep the longest known prefix
            while target and target not in known:
                target = target.rpartition(".")[0]
            if target and target.startswith("birdsim"):
                out.add(target)
    return out


def import_graph() -> dict[str, set[str]]:
    mods = modules()
    known = set(mods)
    graph = {}
    for name, path in mods.items():
        edges = imports_of(name, path, known)
        # a package's own __init__ is not an edge (see the module docstring)
        graph[name] = {t for t in edges if not (modules_is_package(t, mods) and t != name)}
    return graph


def modules_is_package(name: str, mods: dict[str, Path]) -> bool:
    return mods[name].name == "__init__.py"


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    names = sorted(graph)
    index = {n: i for i, n in enumerate(names)}
    rows, cols = [], []
    for a, targets in graph.items():
        for b in targets:
            rows.append(index[a])
            cols.append(index[b])
    adj = csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(len(names), len(names)))
    _, labels = connected_components(adj, directed=True, connection="strong")
    groups: dict[int, list[str]] = {}
    for n, lab in zip(names, labels):
        groups.setdefault(int(lab), []).append(n)
    found = [g for g in groups.values() if len(g) > 1]
    found += [[n] for n in names if n in graph[n]]
    return sorted(found)


def test_the_graph_reader_sees_a_cycle_and_lazy_imports(tmp_path: Path) -> None:
    """The checker itself: a two-module cycle through a function-level import, and an
    acyclic chain, on a toy graph; and the real graph has the edges we know of."""
    assert cycles({"a": {"b"}, "b": {"a"}, "c": {"a"}}) == [["a", "b"]]
    assert cycles({"a": {"b"}, "b": {"c"}, "c": set()}) == []
    assert cycles({"a": {"a"}}) == [["a"]]
    graph = import_graph()
    # a top-level import and a function-level one, both read
    assert "birdsim.errors" in graph["birdsim.commands.fly"]
    assert "birdsim.flight.freeflight" in graph["birdsim.commands.fly"]
    assert "birdsim.report.plots" in graph["birdsim.report.page"]


def test_no_import_cycle_between_modules() -> None:
    found = cycles(import_graph())
    assert not found, "import cycles: " + "; ".join(" <-> ".join(c) for c in found)


def _lines(path: Path) -> int:
    return len(path.read_text().splitlines())


@pytest.mark.parametrize("rel", sorted(str(p.relative_to(PACKAGE)) for p in PACKAGE.rglob("*.py")))
def test_no_module_over_400_lines(rel: str) -> None:
    if rel in OVER_LIMIT_ELSEWHERE:
        pytest.skip(
            f"birdsim/{rel} exempt for now: being changed on another engineer's branch, which "
            "keeps it under 400 lines; the lead removes the exemption after merging "
            f"(exempt: {', '.join(sorted(OVER_LIMIT_ELSEWHERE))})"
        )
    n = _lines(PACKAGE / rel)
    assert n <= MAX_LINES, f"birdsim/{rel} has {n} lines; allowed: at most {MAX_LINES}"
