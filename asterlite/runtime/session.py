"""A deck session: namespace, logical units, output folder, test records,
and the dispatcher that joins the evaluator, the catalogues and the commands.

The evaluator knows nothing about particular commands: every command name
is bound to a :class:`CommandProxy`, which validates the call against its
catalogue and hands the keyword tree to ``asterlite.commands.<name>.run``.
Only the commands that steer the session itself (DEBUT, POURSUITE, FIN,
DETRUIRE, DEFI_FICHIER) are handled here.
"""

from __future__ import annotations

import difflib
import importlib
import pkgutil
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from asterlite.catalog import load_catalogue, result_type, validate
from asterlite.catalog.keywords import Keywords
from asterlite.concepts.base import Concept, Placeholder
from asterlite.errors import AsterliteError, CommandError, Location, UnsupportedError
from asterlite.lang.values import CO, CallSite, DeckCallable, FactorDict, Unknown
from asterlite.runtime.context import CommandContext, TestRecord
from asterlite.runtime.export import RunDescription


class DeckFinished(AsterliteError):
    """Raised by FIN() to stop evaluating the current deck file."""

    kind = "end of deck"


class UnknownOverrideError(AsterliteError):
    """A ``--set NAME=...`` override names a variable the deck never assigns."""

    kind = "unknown variable"


class AnyPlaceholder(Placeholder):
    """Stands for a concept of a type ``asterlite check`` cannot tell."""

    def __init__(self, produced_by: str = ""):
        super().__init__("*", produced_by)

    def satisfies(self, type_name: str) -> bool:
        return True


@dataclass
class CommandTiming:
    command: str
    location: Location | None
    result: str | None
    seconds: float


def catalogue_command_names() -> list[str]:
    """Names of every command that has a catalogue (no module is imported)."""
    import asterlite.catalogues as package

    return sorted(
        info.name.upper()
        for info in pkgutil.iter_modules(package.__path__)
        if not info.name.startswith("common") and not info.name.startswith("_")
    )


@dataclass
class Session:
    """State shared by every deck file of one run."""

    run: RunDescription
    output_dir: Path | None = None
    check_only: bool = False
    echo: bool = False
    namespace: dict[str, Any] = field(default_factory=dict)
    tests: list[TestRecord] = field(default_factory=list)
    timings: list[CommandTiming] = field(default_factory=list)
    messages: list[str] = field(default_factory=list)
    output_units: dict[int, Path] = field(default_factory=dict)
    current_file: str = ""
    # deck-level variables to replace by value (asterlite sweep --set), and those replaced
    overrides: dict[str, Any] = field(default_factory=dict)
    overrides_used: set[str] = field(default_factory=set)
    # keyword values replaced in command calls before validation (asterlite converge)
    keyword_overrides: list[KeywordOverride] = field(default_factory=list)
    call_counts: dict[str, int] = field(default_factory=dict)  # calls per command so far
    keyword_edits: list[dict] = field(default_factory=list)  # what the overrides replaced
    # (command, result name, concept) of every command that made a concept
    produced: list[tuple[str, str | None, Any]] = field(default_factory=list)

    def __post_init__(self) -> None:
        from asterlite.lang import base_namespace

        self.namespace.update(base_namespace(print_hook=self._print))
        for name in catalogue_command_names():
            self.namespace[name] = CommandProxy(name, self)

    # ----------------------------------------------------------- services
    def _print(self, text: str) -> None:
        """Where the deck's print() goes: the message log."""
        for line in text.rstrip("\n").split("\n"):
            self.log(line)

    def log(self, text: str) -> None:
        self.messages.append(text)
        if self.echo:
            print(text, flush=True)

    def record_test(self, record: TestRecord) -> None:
        self.tests.append(record)

    def input_path(self, unit: int) -> Path:
        """The input file the run maps to logical ``unit``."""
        if unit in self.output_units and self.output_units[unit].exists():
            return self.output_units[unit]
        try:
            return self.run.units[unit]
        except KeyError:
            known = ", ".join(str(u) for u in sorted(self.run.units)) or "none"
            raise CommandError(
                f"no file is mapped to logical unit {unit} (mapped units: {known})"
            ) from None

    def output_path(self, unit_or_name: int | str) -> Path:
        """A path in the output folder for a logical unit or a file name."""
        if self.output_dir is None:
            raise CommandError("this run has no output folder")
        self.output_dir.mkdir(parents=True, exist_ok=True)
        if isinstance(unit_or_name, int):
            if unit_or_name not in self.output_units:
                self.output_units[unit_or_name] = self.output_dir / f"fort.{unit_or_name}"
            return self.output_units[unit_or_name]
        return self.output_dir / Path(unit_or_name).name

    def bind_output(self, output: Any, concept: Any) -> None:
        if not isinstance(output, CO):
            raise CommandError(f"expected a CO('NAME') output, got {output!r}")
        if isinstance(concept, Concept):
            concept.name = output.name
        self.namespace[output.name] = concept

    # ----------------------------------------------------------- running
    def load_module(self, name: str) -> dict | None:
        """Modules a deck may import besides math and numpy."""
        if name in ("code_aster.Commands", "code_aster.Cata.Commands"):
            return {n: v for n, v in self.namespace.items() if isinstance(v, CommandProxy)}
        if name == "code_aster":
            from asterlite.runtime.deck_api import code_aster_module

            return code_aster_module(self)
        if name == "aster":
            return {}
        if name in self.run.helper_modules:
            from asterlite.lang import Evaluator, parse_deck

            path = self.run.helper_modules[name]
            module = parse_deck(path.read_text(encoding="utf-8", errors="replace"), str(path))
            namespace = dict(self.namespace)
            Evaluator(namespace, module_loader=self.load_module).run(module)
            return namespace
        return None

    def run_file(self, path: Path) -> None:
        """Parse and evaluate one deck file in the session namespace."""
        from asterlite.lang import Evaluator, parse_deck

        self.current_file = str(path)
        self.log(f"# deck {path.name}")
        module = parse_deck(path.read_text(encoding="utf-8", errors="replace"), str(path))
        evaluator = Evaluator(
            self.namespace, module_loader=self.load_module, overrides=self.overrides
        )
        try:
            evaluator.run(module)
        except DeckFinished:
            pass
        finally:
            self.overrides_used |= evaluator.overrides_used

    def run_all(self) -> None:
        if self.check_only:  # placeholders print nothing; keep start-up light
            self._run_files()
        else:
            from asterlite.post import deck_api

            # what concept methods print (INFO_NONL...) goes to this run's log
            deck_api.set_sink(self.log)
            try:
                self._run_files()
            finally:
                deck_api.set_sink(None)
        self.check_overrides_used()

    def _run_files(self) -> None:
        for path in self.run.deck_files:
            self.run_file(path)

    def unused_overrides(self) -> list[str]:
        return sorted(set(self.overrides) - self.overrides_used)

    def check_overrides_used(self) -> None:
        """An override the deck never assigned is a typo: the run did not vary
        what the user asked for, so its results must not pass for a variant."""
        unused = self.unused_overrides()
        if not unused:
            return
        variables = deck_variables(self.namespace)
        hints = []
        for name in unused:
            close = difflib.get_close_matches(name, variables, n=1)
            hints.append(f"{name} (did you mean {close[0]}?)" if close else name)
        listed = ", ".join(variables) or "none"
        raise UnknownOverrideError(
            f"not assigned at module level by the deck: {', '.join(hints)} "
            f"(its deck-level variables: {listed})"
        )


def deck_variables(namespace: dict) -> list[str]:
    """Names the deck bound to plain numbers or strings: what --set can vary."""
    from asterlite.lang import base_namespace

    builtins = base_namespace()
    return sorted(
        name
        for name, value in namespace.items()
        if isinstance(value, (int, float, str))
        and not isinstance(value, bool)
        and not name.startswith("_")
        and name not in builtins
    )


# Commands that steer the session rather than compute: handled here.
SESSION_COMMANDS = {"DEBUT", "POURSUITE", "FIN", "DEBUG", "DETRUIRE", "DEFI_FICHIER"}


class CommandProxy(DeckCallable):
    """A deck command: validates against its catalogue, then dispatches."""

    def __init__(self, name: str, session: Session):
        self.name = name
        self.session = session

    def __repr__(self) -> str:
        return f"<command {self.name}>"

    def deck_call(self, args: list, kwargs: dict, site: CallSite):
        session = self.session
        if args:
            raise UnsupportedError(
                f"{self.name} takes keyword arguments only", site.location, self.name
            )
        catalogue = load_catalogue(self.name)
        if catalogue is None:
            raise UnsupportedError(f"command {self.name} is not supported", site.location)
        kwargs = dict(kwargs)
        reuse = kwargs.pop("reuse", None)
        if catalogue.compat_syntax is not None:  # legacy syntax: check as written, translate
            from asterlite.legacy.runtime import translate_call

            modern = translate_call(catalogue, kwargs, site, session, reuse=reuse)
            if modern is not None:
                name, catalogue, kwargs = modern
                if name != self.name:  # a renamed legacy command: the modern one runs it
                    return CommandProxy(name, session)._call(catalogue, kwargs, reuse, site)
        return self._call(catalogue, kwargs, reuse, site)

    def _call(self, catalogue, kwargs: dict, reuse, site: CallSite):
        """Validate a (modern) call against ``catalogue`` and dispatch it."""
        session = self.session
        count = session.call_counts[self.name] = session.call_counts.get(self.name, 0) + 1
        if session.keyword_overrides:
            kwargs = override_keywords(self.name, count, catalogue, kwargs, session)
        extra = {}
        if catalogue.extra_keywords:
            known = set(catalogue.keyword_names())
            extra = {k: v for k, v in kwargs.items() if k not in known}
            kwargs = {k: v for k, v in kwargs.items() if k in known}
        if session.check_only:
            kwargs = _blur_empty_sequences(kwargs)
        keywords = validate(catalogue, kwargs, site, reuse=reuse)
        if extra:
            keywords["_extra"] = extra
        if self.name in SESSION_COMMANDS:
            return self._session_command(keywords, site)
        if session.check_only:
            return self._placeholder(catalogue, keywords)
        return self._execute(keywords, site, reuse)

    # ---------------------------------------------------------------- check
    def _placeholder(self, catalogue, keywords: Keywords):
        for output in _co_outputs(keywords):
            self.session.bind_output(output, AnyPlaceholder(self.name))
        try:
            produced = result_type(catalogue, keywords)
        except Exception:  # sd_prod read a value check mode could not compute
            return AnyPlaceholder(self.name)
        if produced is None:
            return None
        return Placeholder(produced, self.name)

    # ------------------------------------------------------------------ run
    def _execute(self, keywords: Keywords, site: CallSite, reuse: Any):
        session = self.session
        module_name = f"asterlite.commands.{self.name.lower()}"
        try:
            module = importlib.import_module(module_name)
        except ModuleNotFoundError as missing:
            if missing.name != module_name:
                raise
            raise UnsupportedError(
                f"command {self.name} is not implemented yet", site.location
            ) from None
        ctx = CommandContext(
            session=session,
            command=self.name,
            location=site.location,
            result_name=site.assigned_name,
            reuse=reuse,
        )
        where = f"{Path(site.location.file).name}:{site.location.line}" if site.location else ""
        target = f" -> {site.assigned_name}" if site.assigned_name else ""
        session.log(f"{self.name} ({where}){target}")
        start = time.perf_counter()
        try:
            concept = module.run(ctx, keywords)
        except AsterliteError as error:
            if error.location is None:
                error.location = site.location
            if not error.path:
                error.path = self.name
            raise
        seconds = time.perf_counter() - start
        session.timings.append(CommandTiming(self.name, site.location, site.assigned_name, seconds))
        session.log(f"  done in {seconds:.3f} s")
        if isinstance(concept, Concept):
            session.produced.append((self.name, site.assigned_name, concept))
        # a reused concept keeps its name; a new one takes the deck's name
        if isinstance(concept, Concept) and site.assigned_name:
            if reuse is None or concept.name is None:
                concept.name = site.assigned_name
        return concept

    # -------------------------------------------------------------- session
    def _session_command(self, keywords: Keywords, site: CallSite):
        session = self.session
        if self.name == "FIN":
            session.log("FIN")
            raise DeckFinished("FIN reached", site.location)
        if self.name in ("DEBUT", "POURSUITE", "DEBUG"):
            session.log(self.name)
            return None
        if self.name == "DETRUIRE":
            for occurrence in keywords.factor("CONCEPT"):
                names = occurrence.get("NOM") or ()
                for concept in names if isinstance(names, tuple) else (names,):
                    for key, value in list(session.namespace.items()):
                        if value is concept:
                            del session.namespace[key]
            return None
        if self.name == "DEFI_FICHIER":
            unit = keywords.get("UNITE")
            name = keywords.get("FICHIER")
            if unit is not None and name and session.output_dir is not None:
                session.output_units[int(unit)] = session.output_path(str(name))
            return None
        return None


def _blur_empty_sequences(value):
    """Under check, an empty list may stand for data built from uncomputed
    results (a loop over Unknown appends nothing): treat it as Unknown."""
    if isinstance(value, (list, tuple)) and not value:
        return Unknown
    if isinstance(value, FactorDict):
        blurred = FactorDict(
            {k: _blur_empty_sequences(v) for k, v in value.items()},
            location=value.location,
            keyword_locations=value.keyword_locations,
        )
        return blurred
    if isinstance(value, dict):
        return {k: _blur_empty_sequences(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return type(value)(_blur_empty_sequences(v) for v in value)
    return value


@dataclass(frozen=True)
class KeywordOverride:
    """Keyword values put into calls of ``command`` before validation.

    ``keywords`` maps a path to its new value: ``"NAME"`` at the top level,
    ``"FACT/NAME"`` in every occurrence of a factor keyword (created when the
    call has none), ``"FACT[2]/NAME"`` in one occurrence; ``None`` removes
    the keyword. ``call``: only the n-th call (1-based), None for every one.
    Keywords a replaced value closes (e.g. BETA/GAMMA of NEWMARK once
    SCHEMA is DEVOGE) are dropped so that the call still validates.
    """

    command: str
    keywords: dict[str, Any]
    call: int | None = None

    def applies(self, command: str, count: int) -> bool:
        return command == self.command and self.call in (None, count)


def override_keywords(name: str, count: int, catalogue, kwargs: dict, session: Session) -> dict:
    """``kwargs`` with the session's keyword overrides for this call applied."""
    for override in session.keyword_overrides:
        if override.applies(name, count):
            kwargs = apply_keyword_values(catalogue, kwargs, override.keywords, session.log)
            session.keyword_edits.append({"command": name, "call": count, **override.keywords})
    return kwargs


def apply_keyword_values(catalogue, kwargs: dict, values: dict, log=None) -> dict:
    """A copy of a call's raw keywords with ``values`` (path -> value) put in;
    the levels edited lose the catalogue keywords their new values close."""
    from asterlite.catalog.model import FACT

    kwargs = dict(kwargs)
    edited: dict[str, set] = {}  # factor -> occurrence numbers edited ("" = top level)
    for path, value in values.items():
        factor, _, simple = path.rpartition("/")
        if not factor:
            _set_or_drop(kwargs, simple, value)
            edited.setdefault("", set())
            continue
        factor, index = _factor_index(factor)
        occurrences = _copied_occurrences(kwargs.get(factor)) or [FactorDict()]
        for number, occurrence in enumerate(occurrences, start=1):
            if index in (None, number):
                _set_or_drop(occurrence, simple, value)
                edited.setdefault(factor, set()).add(number)
        kwargs[factor] = tuple(occurrences) if len(occurrences) > 1 else occurrences[0]
    dropped = _drop_closed(catalogue, kwargs, {}) if "" in edited else []
    entries = _all_entries(catalogue)
    for factor, numbers in edited.items():
        if not isinstance(entries.get(factor), FACT):
            continue
        occurrences = _copied_occurrences(kwargs[factor])
        for number in numbers:
            closed = _drop_closed(entries[factor], occurrences[number - 1], kwargs)
            dropped += [f"{factor}/{name}" for name in closed]
        kwargs[factor] = tuple(occurrences) if len(occurrences) > 1 else occurrences[0]
    if dropped and log is not None:
        log(f"keyword override: dropped {', '.join(dropped)} (not allowed with the new values)")
    return kwargs


def _set_or_drop(level: dict, name: str, value) -> None:
    if value is None:
        level.pop(name, None)
    else:
        level[name] = value


def _factor_index(text: str) -> tuple[str, int | None]:
    """``"FACT[2]"`` -> ("FACT", 2); ``"FACT"`` -> ("FACT", None)."""
    if text.endswith("]") and "[" in text:
        name, _, number = text[:-1].partition("[")
        return name, int(number)
    return text, None


def _copied_occurrences(value) -> list[FactorDict]:
    if value is None:
        return []
    items = value if isinstance(value, (list, tuple)) else [value]
    return [
        FactorDict(
            dict(item),
            location=getattr(item, "location", None),
            keyword_locations=getattr(item, "keyword_locations", None),
        )
        if isinstance(item, dict)
        else item
        for item in items
    ]


def _all_entries(level) -> dict:
    """Every SIMP and FACT of a level, blocks included."""
    from asterlite.catalog.model import BLOC

    found = {}
    for name, entry in level.entries.items():
        if isinstance(entry, BLOC):
            found.update({n: e for n, e in _all_entries(entry).items() if n not in found})
        else:
            found.setdefault(name, entry)
    return found


def _active_names(level, given: dict, context: dict) -> set[str]:
    """Keywords allowed at ``level`` with the given values (blocks opened as
    the validator opens them: on given values and defaults)."""
    from collections import ChainMap

    from asterlite.catalog.model import BLOC, SIMP

    active, values, pending = set(), dict(given), [level]
    opened = True
    while opened:
        opened = False
        for block in list(pending):
            if block is not level and not block.condition(ChainMap(values, context)):
                continue
            pending.remove(block)
            opened = True
            for name, entry in block.entries.items():
                if isinstance(entry, BLOC):
                    pending.append(entry)
                    continue
                active.add(name)
                if isinstance(entry, SIMP) and name not in values and entry.defaut is not None:
                    values[name] = entry.defaut
    return active


def _drop_closed(level, given: dict, context: dict) -> list[str]:
    """Remove from ``given`` (in place) the catalogue keywords its values close."""
    known = _all_entries(level)
    active = _active_names(level, given, context)
    closed = [n for n in given if n in known and n not in active]
    for name in closed:
        del given[name]
    return closed


def _co_outputs(value) -> list[CO]:
    """Every CO(...) output name inside a keyword tree."""
    if isinstance(value, CO):
        return [value]
    if isinstance(value, dict):
        return [co for v in value.values() for co in _co_outputs(v)]
    if isinstance(value, (list, tuple)):
        return [co for v in value for co in _co_outputs(v)]
    return []


__all__ = [
    "Session",
    "CommandProxy",
    "DeckFinished",
    "AnyPlaceholder",
    "UnknownOverrideError",
    "KeywordOverride",
]
