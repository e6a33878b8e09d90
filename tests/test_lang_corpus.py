"""Every corpus deck parses, and evaluates with recording stand-ins for commands.

The corpus (../shared/aster-corpus) is read-only data beside the repository;
these tests skip when it is absent.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from asterlite.lang import (
    CO,
    CallSite,
    DeckCallable,
    DeckModule,
    Evaluator,
    Unknown,
    base_namespace,
    parse_deck,
)

CORPUS = Path(__file__).resolve().parents[1].parent / "shared" / "aster-corpus"

pytestmark = pytest.mark.corpus


def _deck_folders() -> list[Path]:
    if not CORPUS.is_dir():
        return []
    return sorted(folder for folder in CORPUS.iterdir() if list(folder.glob("*.export")))


def _source_files() -> list[Path]:
    files = []
    for folder in _deck_folders():
        files += sorted(folder.glob("*.comm")) + sorted(folder.glob("*.com[0-9]"))
        files += [folder / name for name in _export_entries(folder, "nom") if name.endswith(".py")]
    return files


def _export_entries(folder: Path, kind: str) -> list[str]:
    """File names of one kind (comm, nom, mail...) listed by the folder's .export, in order."""
    export = next(folder.glob("*.export"))
    pattern = re.compile(rf"^F\s+{kind}\s+(\S+)\s+D\s+\d+", re.MULTILINE)
    return pattern.findall(export.read_text(encoding="utf-8"))


def _read(path: Path) -> str:
    return path.read_text(encoding="utf-8")


def _needs_corpus():
    if not CORPUS.is_dir():
        pytest.skip("../shared/aster-corpus is absent")


# ------------------------------------------------------------------ stand-ins


class Stub(DeckCallable):
    """A concept stand-in: any method or attribute gives Unknown, and calling it
    (FORMULE results are called with an abscissa) gives Unknown too."""

    def __init__(self, command: str, name: str | None):
        self.command, self.name = command, name

    def deck_getattr(self, name: str):
        return Unknown

    def deck_call(self, args, kwargs, site: CallSite):
        return Unknown


class Recorder:
    """Records each command call; every command returns a Stub and binds a Stub
    to each ``CO("NAME")`` output it receives, as commands do."""

    def __init__(self):
        self.calls: list[tuple[str, CallSite, dict]] = []
        self.namespace: dict = {}

    def bind_outputs(self, value, command: str) -> None:
        if isinstance(value, CO):
            self.namespace[value.name] = Stub(command, value.name)
        elif isinstance(value, dict):
            for item in value.values():
                self.bind_outputs(item, command)
        elif isinstance(value, (list, tuple)):
            for item in value:
                self.bind_outputs(item, command)

    def command(self, name: str) -> DeckCallable:
        recorder = self

        class Command(DeckCallable):
            def deck_call(self, args, kwargs, site: CallSite):
                assert not args, f"{name} called with positional arguments"
                assert site.location is not None
                assert set(site.keyword_locations) == set(kwargs)
                recorder.calls.append((name, site, kwargs))
                recorder.bind_outputs(kwargs, name)
                return Stub(name, site.assigned_name)

        return Command()


class TestCase:
    """code_aster's CA.TestCase, reduced to what decks call."""

    deck_methods = frozenset({"assertTrue", "assertFalse", "assertEqual", "printSummary"})

    def assertTrue(self, value, msg=None):  # noqa: N802 - code_aster's name
        return None

    def assertFalse(self, value, msg=None):  # noqa: N802
        return None

    def assertEqual(self, first, second, msg=None):  # noqa: N802
        return None

    def printSummary(self):  # noqa: N802
        return None


def _command_names(text: str) -> set[str]:
    return set(re.findall(r"\b([A-Z][A-Z0-9_]*)\s*\(", text)) - {"CO"}


def _session(folder: Path, recorder: Recorder):
    """A namespace and evaluator as the runtime would set them up for one deck."""
    printed: list[str] = []
    namespace = base_namespace(print_hook=printed.append)
    recorder.namespace = namespace
    sources = [folder / name for name in _export_entries(folder, "comm")]
    commands = set()
    for source in sources:
        commands |= _command_names(_read(source))
    commands_module = {name: recorder.command(name) for name in sorted(commands)}

    def load(module_name: str):
        if module_name == "code_aster.Commands":
            return dict(commands_module)
        if module_name == "code_aster":
            test_case = DeckModule("CA", {"TestCase": TestCase})
            return {"CA": test_case, "Commands": DeckModule("code_aster.Commands", commands_module)}
        if module_name == "aster":
            return {}
        helper = folder / f"{module_name}.py"
        if module_name.isidentifier() and helper.is_file():
            helper_namespace = base_namespace(print_hook=printed.append)
            Evaluator(helper_namespace, module_loader=load).run(
                parse_deck(_read(helper), str(helper))
            )
            return helper_namespace
        return None

    # commands are also reachable without "from code_aster.Commands import *",
    # as in code_aster's own deck execution
    namespace.update(commands_module)
    return namespace, Evaluator(namespace, module_loader=load), sources, printed


# ---------------------------------------------------------------------- tests


@pytest.mark.parametrize("path", _source_files(), ids=lambda p: p.name)
def test_corpus_file_parses(path: Path):
    module = parse_deck(_read(path), str(path))
    assert module.tree.data == "file_input"
    assert module.lines == _read(path).splitlines()


@pytest.mark.parametrize("folder", _deck_folders(), ids=lambda p: p.name)
def test_corpus_deck_evaluates(folder: Path):
    recorder = Recorder()
    namespace, evaluator, sources, _ = _session(folder, recorder)
    for source in sources:
        evaluator.run(parse_deck(_read(source), str(source)))
    assert len(recorder.calls) > 0
    names = [name for name, _, _ in recorder.calls]
    assert names[0] in ("DEBUT", "POURSUITE")
    assert names[-1] == "FIN"


def test_corpus_is_complete():
    _needs_corpus()
    assert len(_deck_folders()) == 54


def test_corpus_assigned_names_and_keyword_locations():
    _needs_corpus()
    folder = CORPUS / "sdld103a"
    recorder = Recorder()
    _, evaluator, sources, _ = _session(folder, recorder)
    text = _read(sources[0])
    evaluator.run(parse_deck(text, str(sources[0])))
    lines = text.splitlines()
    mesh_calls = [(site, kw) for name, site, kw in recorder.calls if name == "LIRE_MAILLAGE"]
    site, kwargs = mesh_calls[0]
    assert site.assigned_name is not None
    assert lines[site.location.line - 1].lstrip().startswith(site.assigned_name)
    for keyword, location in site.keyword_locations.items():
        assert lines[location.line - 1][location.column - 1 :].startswith(keyword)


def test_corpus_helper_module_is_imported():
    _needs_corpus()
    folder = CORPUS / "sdnd121a"
    recorder = Recorder()
    namespace, evaluator, sources, _ = _session(folder, recorder)
    for source in sources:
        evaluator.run(parse_deck(_read(source), str(source)))
    values = namespace["F_linst"]()
    assert isinstance(values, (list, tuple)) and len(values) > 10


def test_corpus_largest_deck_parses_the_same_with_the_parser_built():
    # (parsing speed is a benchmark's, not a timed test's)
    _needs_corpus()
    path = CORPUS / "sdld103a" / "sdld103a.comm"
    text = _read(path)
    first = parse_deck(text, str(path))  # builds the parser once
    assert repr(parse_deck(text, str(path))) == repr(first)
