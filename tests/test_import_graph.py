"""The package's import graph (issue 28, item 4): no cycle, no climb.

Every ``import`` of the installed package is an edge, those at the top of a
module and those inside functions alike (an import deferred into a function
still ties the two modules together; it only hides the tie from the
interpreter). ``if TYPE_CHECKING:`` blocks never run and are left out.
Modules are named as installed: ``catalogues/x.py`` is ``asterlite.catalogues.x``,
``commands/x.py`` ``asterlite.commands.x``. Importing ``a.b.c`` also runs the
packages ``a`` and ``a.b``: an edge to them is added unless the importer is
inside them. ``from package import name`` is an edge to the submodule when
``name`` is one, else to the package.

The few edges still allowed are listed below with the work that removes
each; a listed edge that no longer exists fails the test, so the lists only
shrink.
"""

from __future__ import annotations

import ast
import copy
import functools
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# checkout folder -> the package it ships as (setup.py)
ROOTS = {
    "asterlite": "asterlite",
    "catalogues": "asterlite.catalogues",
    "commands": "asterlite.commands",
}

# Edges that close a cycle, each to be cut by the work named. Must become empty.
CYCLE_EDGES_ALLOWED = {
    # the legacy DYNA_VIBRA form checks a call against a legacy catalogue built from
    # today's DYNA_VIBRA catalogue, which names its legacy forms (compat_syntax): cut
    # when legacy/ looks the forms up by command name (DESIGN: catalogues do not import
    # the version layer)
    ("asterlite.legacy.forms", "asterlite.catalogues.common_legacy"): "forms by command name",
    # the language generator's command line dispatches to the old-layout reader,
    # which reuses the generator's converter: cut by a converter module of its own
    (
        "asterlite.catalog.language.generate",
        "asterlite.catalog.language.legacy_layout",
    ): "issue 27, generator",
}

# Rooms below the run (runtime/) and the commands: they never import upwards.
LOWER_ROOMS = (
    "asterlite.lang",
    "asterlite.catalog",
    "asterlite.concepts",
    "asterlite.fem",
    "asterlite.modal",
    "asterlite.dynamics",
    "asterlite.harmonic",
    "asterlite.substructure",
    "asterlite.io",
    "asterlite.post",
    "asterlite.legacy",
    "asterlite.errors",
    "asterlite.watchdog",
)
UPPER_ROOMS = (
    "asterlite.runtime",
    "asterlite.commands",
    "asterlite.cli",
    "asterlite.api",
    "asterlite.report",
)
# Climbs still allowed, each to be removed by the work named. Must become empty.
CLIMBS_ALLOWED = {
    # TEST_* records are defined by the run; post/checks makes them
    ("asterlite.post.checks", "asterlite.runtime.context"): "TestRecord beside the checks",
    # code_aster 15's generated names are kept by the session; the translation reads them
    ("asterlite.legacy.v15", "asterlite.runtime.v15_names"): "v15_names into legacy/",
    # the porter reads an export to find a study's decks and units
    ("asterlite.legacy.port", "asterlite.runtime.export"): "export reading into io/",
    # the astest sweep is a tool that checks decks as asterlite check does
    ("asterlite.catalog.language.astest_check", "asterlite.runtime.check_deck"): "a tools room",
}


def package_modules(root: Path = ROOT, roots: dict = ROOTS) -> dict[str, Path]:
    """Installed module name -> source file."""
    found = {}
    for folder, package in roots.items():
        base = root / folder
        for path in base.rglob("*.py"):
            parts = list(path.relative_to(base).with_suffix("").parts)
            if "__pycache__" in parts or (folder == "asterlite" and parts[0] in roots):
                continue
            if parts[-1] == "__init__":
                parts = parts[:-1]
            found[".".join([package, *parts])] = path
    return found


def _type_checking_nodes(tree: ast.AST) -> set[int]:
    skipped = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            skipped.update(id(n) for child in node.body for n in ast.walk(child))
    return skipped


def _imported_names(node, module: str, is_package: bool, modules) -> list[str]:
    if isinstance(node, ast.Import):
        return [alias.name for alias in node.names]
    if node.level:  # relative: from the module's package upwards
        package = (module if is_package else module.rpartition(".")[0]).split(".")
        package = package[: len(package) - node.level + 1]
        base = ".".join(package + ([node.module] if node.module else []))
    else:
        base = node.module or ""
    submodules = [f"{base}.{alias.name}" for alias in node.names]
    names = [name for name in submodules if name in modules]
    if len(names) < len(submodules):  # a name defined by the package itself
        names.append(base)
    return names


def import_edges(modules: dict[str, Path]) -> dict[str, dict[str, int]]:
    """module -> {imported module of the package: line of the first import}."""
    graph = {}
    for module, path in modules.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        skipped = _type_checking_nodes(tree)
        edges: dict[str, int] = {}
        for node in ast.walk(tree):
            if id(node) in skipped or not isinstance(node, (ast.Import, ast.ImportFrom)):
                continue
            for name in _imported_names(node, module, path.name == "__init__.py", modules):
                target = name
                while target and target not in modules:  # a name inside a module
                    target = target.rpartition(".")[0]
                if not target or target == module:
                    continue
                edges.setdefault(target, node.lineno)
                parts = target.split(".")
                for k in range(1, len(parts)):  # the packages importing it runs
                    package = ".".join(parts[:k])
                    inside = module == package or module.startswith(package + ".")
                    if package in modules and not inside:
                        edges.setdefault(package, node.lineno)
        graph[module] = edges
    return graph


def cycles(graph: dict[str, dict]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan,
    iterative), each sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []
    for start in graph:
        if start in index:
            continue
        work = [(start, iter(graph[start]))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            for child in children:
                if child not in graph:
                    continue
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(graph[child])))
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            else:
                work.pop()
                if work:
                    parent = work[-1][0]
                    low[parent] = min(low[parent], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return found


def _described(component: list[str], graph: dict) -> str:
    members = set(component)
    lines = [
        f"  {module} -> {target} (line {line})"
        for module in component
        for target, line in graph[module].items()
        if target in members
    ]
    return "cycle:\n" + "\n".join(lines)


@functools.cache
def _package_graph() -> dict[str, dict[str, int]]:
    return import_edges(package_modules())


def test_the_package_has_no_import_cycle():
    graph = copy.deepcopy(_package_graph())
    for (module, target), why in CYCLE_EDGES_ALLOWED.items():
        assert target in graph.get(module, {}), f"{module} -> {target} is gone ({why}): unlist it"
        del graph[module][target]
    found = cycles(graph)
    assert not found, "\n".join(_described(c, graph) for c in found)


def test_lower_rooms_do_not_import_the_run_or_the_commands():
    graph = _package_graph()
    climbs = {
        (module, target)
        for module, targets in graph.items()
        if module.startswith(LOWER_ROOMS)
        for target in targets
        if target.startswith(UPPER_ROOMS)
        # a package run on the way to one of its modules: that module is the climb
        and not any(other.startswith(target + ".") for other in targets)
    }
    gone = set(CLIMBS_ALLOWED) - climbs
    assert not gone, f"allowed climbs no longer made (unlist them): {sorted(gone)}"
    new = sorted(climbs - set(CLIMBS_ALLOWED))
    assert not new, "imports from a lower room up to the run or the commands:\n" + "\n".join(
        f"  {module} -> {target} (line {graph[module][target]})" for module, target in new
    )


def test_the_graph_sees_imports_inside_functions(tmp_path):
    """A cycle closed by an import inside a function is found; one closed
    only under TYPE_CHECKING is not (it never runs)."""
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "a.py").write_text("from pkg import b\n")
    (package / "b.py").write_text("def later():\n    from pkg.a import x\n")
    (package / "c.py").write_text("from . import d\n")
    (package / "d.py").write_text(
        "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from pkg.c import y\n"
    )
    graph = import_edges(package_modules(tmp_path, {"pkg": "pkg"}))
    assert graph["pkg.b"] == {"pkg.a": 2} and graph["pkg.c"] == {"pkg.d": 1}
    assert cycles(graph) == [["pkg.a", "pkg.b"]]


if __name__ == "__main__":  # python tests/test_import_graph.py: the cycles, listed
    edges = import_edges(package_modules())
    for component in cycles(edges):
        print(_described(component, edges))
    sys.exit(0)
