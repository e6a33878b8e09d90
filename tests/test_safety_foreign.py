"""No foreign code, ever: a study folder someone sent may hold ``json.py``,
``numpy.py``, ``lark.py``... beside the deck, and another local user may
plant files in the shared temporary folder. None of it may run when the
study is run or checked: neither in asterlite's process (``python3 -m
asterlite`` puts the current folder first) nor in the Python processes it
starts (the MED reader, ``asterlite corpus``'s runs, worker pools), nor
through a parser cache read from a folder others can write.

Every planted module writes a marker file when imported; the tests assert
no marker appears."""

from __future__ import annotations

import os
import pickle
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from asterlite.lang import parser_cache
from asterlite.lang.parser import GRAMMAR_PATH
from tests.conftest import SAMPLES

# third-party packages asterlite imports, beside every standard module
THIRD_PARTY = (
    "numpy",
    "scipy",
    "lark",
    "numba",
    "llvmlite",
    "h5py",
    "medcoupling",
    "meshio",
    "pyuff",
    "tqdm",
    "sitecustomize",
    "usercustomize",
)
PLANTED = sorted((set(sys.stdlib_module_names) | set(THIRD_PARTY)) - {"__future__"})
DECK = "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\nFIN()\n"
EXPORT = "F comm d.comm D 1\nF mmed mesh.med D 20\n"


class HostilePickle:
    """Unpickling this runs ``code`` (as a planted cache file would)."""

    def __init__(self, code: str):
        self.code = code

    def __reduce__(self):
        return (exec, (self.code,))


def _marker_code(markers: Path, name: str) -> str:
    return f"open({str(markers / name)!r}, 'w').close()\n"


def _plant_modules(folder: Path, markers: Path) -> None:
    for name in PLANTED:
        (folder / f"{name}.py").write_text(_marker_code(markers, name))


def _write_study(folder: Path) -> Path:
    """A deck reading a small MED mesh (the MED reader runs in a child)."""
    from asterlite.io.aster_mesh import read_aster_mesh
    from asterlite.io.med_writer import write_med

    folder.mkdir(parents=True)
    mesh = read_aster_mesh(SAMPLES / "friction_oscillator" / "friction_oscillator.mail")
    write_med(folder / "mesh.med", mesh, "MA")
    (folder / "d.comm").write_text(DECK)
    (folder / "d.export").write_text(EXPORT)
    return folder / "d.export"


@pytest.fixture
def hostile(tmp_path):
    """A study folder full of planted modules, its deck, a marker folder, and
    an environment whose temporary folder holds a hostile pickle where
    lark's cache used to be (``cache=True``: ``$TMPDIR/.lark_cache_*.tmp``)."""
    markers = tmp_path / "markers"
    markers.mkdir()
    study = tmp_path / "study"
    export = _write_study(study)
    _plant_modules(study, markers)
    shared_tmp = tmp_path / "tmp"
    shared_tmp.mkdir()
    environment = dict(os.environ, TMPDIR=str(shared_tmp), XDG_CACHE_HOME=str(tmp_path / "cache"))
    _plant_old_lark_cache(shared_tmp, markers, environment)
    return study, export, markers, environment


def _old_lark_parser_code() -> str:
    """How asterlite built its parser before: lark's own cache in $TMPDIR."""
    return textwrap.dedent(
        f"""
        from lark import Lark
        from asterlite.lang.parser import _indenter_class
        Lark(open({str(GRAMMAR_PATH)!r}, encoding="utf-8").read(), parser="lalr",
             start=["file_input", "eval_input"], postlex=_indenter_class()(),
             maybe_placeholders=True, cache=True)
        """
    )


def _plant_old_lark_cache(shared_tmp: Path, markers: Path, environment: dict) -> None:
    """Let the old code write its cache, then replace it by a hostile pickle
    with the same header, and check the old code would run it."""
    old = [sys.executable, "-I", "-c", _old_lark_parser_code()]
    subprocess.run(old, env=environment, check=True, cwd=shared_tmp)
    (cached,) = shared_tmp.glob(".lark_cache_*.tmp")
    header = cached.read_bytes().split(b"\n", 1)[0]
    payload = pickle.dumps(HostilePickle(_marker_code(markers, "old-lark-cache")))
    cached.write_bytes(header + b"\n" + payload)
    subprocess.run(old, env=environment, check=True, cwd=shared_tmp)
    assert (markers / "old-lark-cache").exists(), "the planted cache must be what lark loads"
    (markers / "old-lark-cache").unlink()


def _asterlite() -> str:
    return str(Path(sys.executable).with_name("asterlite"))


def _run(command: list[str], study: Path, environment: dict) -> subprocess.CompletedProcess:
    return subprocess.run(
        command, cwd=study, env=environment, capture_output=True, text=True, timeout=300
    )


def _ran(markers: Path) -> list[str]:
    return sorted(path.name for path in markers.iterdir())


def test_asterlite_run_and_check_import_nothing_from_the_study(hostile):
    study, export, markers, environment = hostile
    run = _run([_asterlite(), "run", str(export), "-o", "out"], study, environment)
    assert run.returncode == 0, run.stdout + run.stderr  # DONE: the MED mesh was read
    check = _run([_asterlite(), "check", str(export)], study, environment)
    assert check.returncode == 0, check.stdout + check.stderr
    assert _ran(markers) == []


def test_python_m_asterlite_imports_nothing_from_the_current_folder(hostile):
    study, export, markers, environment = hostile
    run = _run(
        [sys.executable, "-m", "asterlite", "run", "d.export", "-o", "out"], study, environment
    )
    assert run.returncode == 0, run.stdout + run.stderr
    check = _run([sys.executable, "-m", "asterlite", "check", "d.export"], study, environment)
    assert check.returncode == 0, check.stdout + check.stderr
    assert _ran(markers) == []


def test_asterlite_corpus_children_import_nothing_from_the_current_folder(hostile, tmp_path):
    study, export, markers, environment = hostile
    corpus = tmp_path / "corpus"
    shutil.copytree(study, corpus / "d")
    corpus_run = _run([_asterlite(), "corpus", str(corpus)], study, environment)
    assert corpus_run.returncode == 0, corpus_run.stdout + corpus_run.stderr
    assert "DONE: 1" in corpus_run.stdout
    assert _ran(markers) == []


def test_spawned_worker_pools_import_nothing_from_the_current_folder(tmp_path):
    """The warmup's pool (multiprocessing's spawn) and Dask's workers start
    ``python -c``, which puts the current folder first unless told not to."""
    markers = tmp_path / "markers"
    markers.mkdir()
    study = tmp_path / "study"
    study.mkdir()
    _plant_modules(study, markers)
    script = tmp_path / "pool.py"  # a script elsewhere: its own folder is first, not the study
    script.write_text(
        textwrap.dedent(
            """
            import sys
            from asterlite.isolation import protect_spawned_workers
            if sys.argv[1] == "protected":
                protect_spawned_workers()
            import multiprocessing
            from concurrent.futures import ProcessPoolExecutor
            if __name__ == "__main__":  # as asterlite.dynamics.warmup.warm starts its pool
                context = multiprocessing.get_context("spawn")
                with ProcessPoolExecutor(1, mp_context=context) as pool:
                    print(list(pool.map(abs, [-3])))
            """
        )
    )
    unprotected = _run([sys.executable, str(script), "plain"], study, dict(os.environ))
    assert "multiprocessing" in _ran(markers), unprotected.stderr  # what the warmup did
    for marker in markers.iterdir():
        marker.unlink()
    protected = _run([sys.executable, str(script), "protected"], study, dict(os.environ))
    assert protected.stdout.strip() == "[3]", protected.stderr
    assert _ran(markers) == []


def test_the_isolated_child_finds_this_asterlite(tmp_path, monkeypatch):
    """-I drops the user's site folder and PYTHONPATH: the child is given this
    process's search path instead (minus the current folder)."""
    import asterlite
    from asterlite.isolation import python_command

    probe = tmp_path / "probe"
    probe.mkdir()
    (probe / "where.py").write_text(
        "import asterlite, sys\nprint(asterlite.__file__, sys.argv[1:])\n"
    )
    monkeypatch.syspath_prepend(str(probe))
    command = python_command("where", "a", "b")
    assert command[1] == "-I"
    done = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, check=True)
    assert done.stdout.split()[0] == asterlite.__file__
    assert done.stdout.strip().endswith("['a', 'b']")


# ------------------------------------------------------------ parser cache


def test_the_parser_cache_is_private_and_reused(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    folder = parser_cache.cache_folder()
    assert folder == tmp_path / "cache" / "asterlite" / "parser"
    assert folder.stat().st_mode & 0o777 == 0o700
    from asterlite.lang.parser import _parser

    built = _parser.__wrapped__()
    (stored,) = folder.glob("deck-parser-*.pickle")
    assert stored.stat().st_mode & 0o077 == 0
    key = parser_cache.cache_key(GRAMMAR_PATH.read_text(encoding="utf-8"))
    assert parser_cache.load_tables(folder, key) is not None
    loaded = _parser.__wrapped__()
    deck = "x = [1, 2]\nif x:\n    y = _F(A=1.E+04, B='t')\n"
    assert loaded.parse(deck, start="file_input") == built.parse(deck, start="file_input")


def test_a_hostile_pickle_in_the_parser_cache_never_runs(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    folder = parser_cache.cache_folder()
    key = parser_cache.cache_key(GRAMMAR_PATH.read_text(encoding="utf-8"))
    marker = tmp_path / "ran"
    planted = folder / f"deck-parser-{key}.pickle"
    planted.write_bytes(pickle.dumps(HostilePickle(f"open({str(marker)!r}, 'w').close()")))
    planted.chmod(0o600)
    assert parser_cache.load_tables(folder, key) is None
    from asterlite.lang.parser import _parser

    assert _parser.__wrapped__().parse("a = 1\n", start="file_input")
    assert not marker.exists()
    assert parser_cache.load_tables(folder, key) is not None  # replaced by real tables


@pytest.mark.parametrize("mode", [0o755, 0o770, 0o777])
def test_a_cache_folder_others_can_enter_or_write_is_not_used(tmp_path, monkeypatch, mode):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    folder = tmp_path / "cache" / "asterlite" / "parser"
    folder.mkdir(parents=True)
    folder.chmod(mode)
    assert parser_cache.cache_folder() is None


def test_a_cache_folder_below_a_folder_others_can_write_is_not_used(tmp_path, monkeypatch):
    shared = tmp_path / "shared"
    shared.mkdir()
    shared.chmod(0o777)  # not sticky: another user could rename our folder away
    monkeypatch.setenv("XDG_CACHE_HOME", str(shared))
    assert parser_cache.cache_folder() is None


def test_a_symlinked_cache_file_is_not_read(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    folder = parser_cache.cache_folder()
    key = parser_cache.cache_key(GRAMMAR_PATH.read_text(encoding="utf-8"))
    elsewhere = tmp_path / "elsewhere.pickle"
    elsewhere.write_bytes(pickle.dumps({"data": {}, "memo": {}}))
    (folder / f"deck-parser-{key}.pickle").symlink_to(elsewhere)
    assert parser_cache.load_tables(folder, key) is None


def test_numba_kernel_cache_is_never_read_from_a_folder_others_may_write(tmp_path, monkeypatch):
    """numba's cache index files are pickles: a NUMBA_CACHE_DIR (or a digest
    folder) that another user may write is passed over for a trusted one."""
    from asterlite import dynamics

    shared = tmp_path / "shared"
    shared.mkdir()
    shared.chmod(0o777)  # world-writable, not sticky: anyone may plant an index
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "home-cache"))
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(shared))
    folder = dynamics.kernel_cache_folder()
    assert shared not in folder.parents
    # a digest folder others may write, in a trusted root, is passed over too
    private = tmp_path / "private"
    private.mkdir(mode=0o700)
    planted = private / folder.name
    planted.mkdir()
    planted.chmod(0o777)
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(private))
    chosen = dynamics.kernel_cache_folder()
    assert chosen != planted and chosen.name == folder.name
    # a trusted NUMBA_CACHE_DIR is used as the root
    planted.chmod(0o700)
    assert dynamics.kernel_cache_folder() == planted


def test_a_deck_tree_comes_back_from_the_cache_with_its_positions(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    from asterlite.lang import parser as P

    deck = "x = [1, 2]\nif x:\n    y = _F(A=1.E+04, B=f'{x!r:>4}t')\nz = 3 / 2\n"
    monkeypatch.setattr(P, "_RECENT_TREES", {})
    parsed = P.parse_deck(deck, "a.comm")
    (stored,) = (tmp_path / "cache" / "asterlite" / "parser").glob("deck-tree-*.pickle")
    assert stored.stat().st_mode & 0o077 == 0

    def refuse(*args, **kwargs):
        raise AssertionError("parsed again")

    monkeypatch.setattr(P, "_RECENT_TREES", {})  # a new process: only the disk has it
    monkeypatch.setattr(P, "_parse_text", refuse)
    cached = P.parse_deck(deck, "b.comm")
    assert cached.tree == parsed.tree and cached.future == parsed.future

    def positions(tree):
        return [
            (t.type, str(t), t.start_pos, t.line, t.column, t.end_line, t.end_column, t.end_pos)
            for t in tree.scan_values(lambda v: hasattr(v, "end_pos"))
        ]

    assert positions(cached.tree) == positions(parsed.tree) != []
    with pytest.raises(AssertionError, match="parsed again"):  # another text is parsed
        P.parse_deck(deck + "w = 1\n", "c.comm")


def test_a_hostile_pickle_in_the_tree_cache_never_runs(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    from asterlite.lang import parser as P

    deck = "a = 1\nb = a + 2\n"
    folder = parser_cache.cache_folder()
    marker = tmp_path / "ran"
    planted = folder / f"deck-tree-{P._tree_key(deck, 'file_input', False)}.pickle"
    planted.write_bytes(pickle.dumps(HostilePickle(f"open({str(marker)!r}, 'w').close()")))
    planted.chmod(0o600)
    monkeypatch.setattr(P, "_RECENT_TREES", {})
    assert P.parse_deck(deck, "a.comm").tree is not None  # parsed: the file is refused
    assert not marker.exists()
    monkeypatch.setattr(P, "_RECENT_TREES", {})
    assert P._stored_tree(folder, deck, "file_input", False) is not None  # replaced


def test_the_tree_cache_keeps_the_newest_trees(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.setattr(parser_cache, "TREES_KEPT", 3)
    from asterlite.lang import parser as P

    folder = parser_cache.cache_folder()
    names = []
    for i in range(6):
        monkeypatch.setattr(P, "_RECENT_TREES", {})
        P.parse_deck(f"a = {i}\n", "a.comm")
        names.append(f"deck-tree-{P._tree_key(f'a = {i}' + chr(10), 'file_input', False)}.pickle")
        os.utime(folder / names[-1], (i, i))  # the order they were written in
    assert sorted(path.name for path in folder.glob("deck-tree-*.pickle")) == sorted(names[3:])
