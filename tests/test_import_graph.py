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

Both allow-lists below are empty. An edge listed there (with the work that
removes it) must exist, or the test fails: the lists only shrink.

Imports sit at the top of their module. One inside a function must say why
it waits, in one of the ways :func:`deferral_reason` recognises: it loads a
library whose import costs start-up time (:data:`DEFERRED_LIBRARIES`, each
with its measured cost), it keeps modules off the path every ``asterlite
check`` and ``run`` takes (measured by running a check), it is optional
(``try``/``except ImportError``) or needed in one branch only (under an
``if``).
"""

from __future__ import annotations

import ast
import copy
import functools
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# checkout folder -> the package it ships as (setup.py)
ROOTS = {
    "asterlite": "asterlite",
    "catalogues": "asterlite.catalogues",
    "commands": "asterlite.commands",
}

# Edges that close a cycle, each with the work that cuts it (none is left: a new
# cycle is cut by moving code to the room it belongs to, not by listing it).
CYCLE_EDGES_ALLOWED: dict[tuple[str, str], str] = {}

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
    "asterlite.tools",
)
# Climbs still allowed, each with the work that removes it (none is left: a new
# climb is a module in the wrong room, moved rather than listed).
CLIMBS_ALLOWED: dict[tuple[str, str], str] = {}


# Libraries a function may import when it needs them: `python -X importtime -c
# "import X"`, cumulative, this 2-core machine, 2026-11-28, load 5 (ms)
DEFERRED_LIBRARIES = {
    "numpy": 55,
    "scipy": 143,  # scipy.sparse.linalg 423, scipy.linalg 387
    "numba": 206,
    "llvmlite": 120,
    "h5py": 90,
    "medcoupling": 132,
    "MEDLoader": 132,
    "lark": 45,
    "meshio": 267,
    "pyuff": 157,
    "tqdm": 68,
    "multiprocessing": 26,
    "concurrent": 7,  # and the threads its executors start
    "matplotlib": 400,
    "pyarrow": 300,
    "mumps": 328,  # the large extra (python-mumps and its MPI libraries)
}
# Rooms whose imports inside functions are not yet sorted (each with the work
# that sorts them; the list only shrinks)
DEFERRAL_PENDING: dict[str, str] = {}


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


def import_targets(node, module: str, path: Path, modules) -> tuple[set, set]:
    """(modules of the package, external top names) one import statement runs:
    the module it names (or holds the name) and the packages on the way to it."""
    ours, theirs = set(), set()
    for name in _imported_names(node, module, path.name == "__init__.py", modules):
        target = name
        while target and target not in modules:
            target = target.rpartition(".")[0]
        if not target:
            theirs.add(name.split(".")[0])
            continue
        if target != module:
            ours.add(target)
        parts = target.split(".")
        for k in range(1, len(parts)):
            package = ".".join(parts[:k])
            if package in modules and not (module == package or module.startswith(package + ".")):
                ours.add(package)
    return ours, theirs


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
            ours, _ = import_targets(node, module, path, modules)
            for target in sorted(ours):
                edges.setdefault(target, node.lineno)
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


def _function_imports(tree: ast.AST):
    """(import node, its chain of enclosing nodes up to the function) of every
    import inside a function."""
    found = []

    def visit(node, chain):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.Import, ast.ImportFrom)) and chain:
                found.append((child, chain))
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                visit(child, [child])
            else:
                visit(child, chain + [child] if chain else [])

    visit(tree, [])
    return found


def _optional_or_conditional(chain: list) -> bool:
    for node in chain[1:]:
        if isinstance(node, ast.If):
            return True
        if isinstance(node, ast.Try) and any(
            handler.type is None or "ImportError" in ast.unparse(handler.type)
            for handler in node.handlers
        ):
            return True
    return False


@functools.cache
def _top_level() -> dict[str, tuple[frozenset, frozenset]]:
    """module -> (modules of the package, external top names) imported at its top level."""
    modules = package_modules()
    found = {}
    for module, path in modules.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        inner = {id(node) for node, _ in _function_imports(tree)}
        skipped = _type_checking_nodes(tree)
        edges, external = set(), set()
        for node in ast.walk(tree):
            if not isinstance(node, (ast.Import, ast.ImportFrom)) or id(node) in skipped | inner:
                continue
            ours, theirs = import_targets(node, module, path, modules)
            edges |= ours
            external |= theirs
        found[module] = (frozenset(edges), frozenset(external))
    return found


def _closure(start) -> tuple[set, set]:
    """(package modules, external libraries) that importing ``start`` runs."""
    top = _top_level()
    seen, libraries, pending = set(), set(), list(start)
    while pending:
        module = pending.pop()
        if module in seen or module not in top:
            continue
        seen.add(module)
        edges, external = top[module]
        libraries |= external
        pending.extend(edges)
    return seen, libraries


# What every start of asterlite runs: importing the package and the command
# line's parser (no numerical library), and checking a deck (the bundled sample)
START_UP = {
    "import": "import asterlite; asterlite.run; asterlite.check; asterlite.load; "
    "from asterlite.cli import build_parser; build_parser()",
    "check": "from asterlite.cli import main; main(['check', sys.argv[1]])",
    "run": "import tempfile; from asterlite.cli import main; "
    "main(['run', sys.argv[1], '-o', tempfile.mkdtemp(), '-q'])",
}


@functools.cache
def start_up_paths() -> tuple[frozenset, ...]:
    """The modules of the package each start of :data:`START_UP` imports."""
    sample = ROOT / "samples" / "friction_oscillator" / "friction_oscillator.comm"
    paths = []
    for code in START_UP.values():
        listing = "print(' '.join(m for m in sys.modules if m.startswith('asterlite')))"
        out = subprocess.run(
            [sys.executable, "-c", f"import sys; {code}; {listing}", str(sample)],
            capture_output=True,
            text=True,
            check=True,
        )
        paths.append(frozenset(out.stdout.strip().splitlines()[-1].split()))
    return tuple(paths)


def deferral_reason(module: str, node, chain: list) -> str | None:
    """Why the import ``node`` inside a function of ``module`` waits, or None."""
    modules = package_modules()
    ours, theirs = import_targets(node, module, modules[module], modules)
    have_modules, have_libraries = _closure([module])
    reached, libraries = _closure(ours)
    new_libraries = (libraries | theirs) & set(DEFERRED_LIBRARIES)
    if new_libraries - have_libraries:
        return f"defers {', '.join(sorted(new_libraries - have_libraries))}"
    if _optional_or_conditional(chain):
        return "optional or conditional"
    for path in start_up_paths():
        if module in path and not reached <= path:
            return "keeps modules off a start-up path"
    if module.startswith(tuple(DEFERRAL_PENDING)):
        return "pending"
    return None


def test_imports_inside_functions_say_why_they_wait():
    unexplained, pending_rooms = [], set()
    for module, path in package_modules().items():
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        for node, chain in _function_imports(tree):
            why = deferral_reason(module, node, chain)
            if why is None:
                unexplained.append(f"  {path.relative_to(ROOT)}:{node.lineno}: {ast.unparse(node)}")
            elif why == "pending":
                pending_rooms.add(next(r for r in DEFERRAL_PENDING if module.startswith(r)))
    assert not unexplained, "imports inside functions that could be at the top:\n" + "\n".join(
        unexplained
    )
    assert pending_rooms == set(DEFERRAL_PENDING), "rooms sorted: unlist them"


if __name__ == "__main__":  # python tests/test_import_graph.py: the cycles, listed
    edges = import_edges(package_modules())
    for component in cycles(edges):
        print(_described(component, edges))
    sys.exit(0)
