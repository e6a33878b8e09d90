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
import re
import time
from collections import ChainMap
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import asterlite.catalogues as package
from asterlite import watchdog
from asterlite.catalog import load_catalogue, result_type, validate
from asterlite.catalog.keywords import Keywords, unread_keywords
from asterlite.catalog.model import BLOC, FACT, SIMP
from asterlite.concepts.base import AnyPlaceholder, Concept, Placeholder
from asterlite.errors import (
    AsterliteError,
    CommandError,
    DeckSyntaxError,
    Location,
    UnsupportedError,
    ValidationError,
)
from asterlite.io.export import RunDescription
from asterlite.io.input_files import read_deck, read_deck_text
from asterlite.io.text_encoding import UTF8, UTF8_BOM
from asterlite.lang import Evaluator, base_namespace, parse_deck, savetxt, stdlib
from asterlite.lang.library import DeckModule
from asterlite.lang.values import CO, CallSite, DeckCallable, FactorDict, Unknown, co_outputs
from asterlite.legacy import v11  # what code_aster 11 decks meant (values, defaults)
from asterlite.legacy.forms import legacy_form
from asterlite.legacy.runtime import translate_call
from asterlite.legacy.v15_names import GeneratedNames, record_call
from asterlite.legacy.version import PYTHON2_LAST, session_version
from asterlite.post.check_record import TestRecord
from asterlite.runtime import checking, console
from asterlite.runtime.checking import (
    UnsupportedCommand,
    check_call,
    command_failed,
    note_unit_mapping,
    statement_failed,
    undecidable,
)
from asterlite.runtime.context import CommandContext
from asterlite.runtime.deck_api import code_aster_module
from asterlite.runtime.language_check import (
    bind_language_commands,
    bind_unparsed_names,
    checked_call,
    component_findings,
    finding_of_error,
    module_commands,
    refusal_of_valid_call,
)
from asterlite.runtime.outdir import create_file
from asterlite.runtime.summaries import RunSummaries


class DeckFinished(AsterliteError):
    """Raised by FIN() to stop evaluating the current deck file."""

    kind = "end of deck"


class UnknownOverrideError(AsterliteError):
    """A ``--set NAME=...`` override names a variable the deck never assigns."""

    kind = "unknown variable"


@dataclass
class CommandTiming:
    command: str
    location: Location | None
    result: str | None
    seconds: float


def catalogue_command_names() -> list[str]:
    """Names of every command that has a catalogue (no module is imported)."""

    return sorted(
        info.name.upper()
        for info in pkgutil.iter_modules(package.__path__)
        if not info.name.startswith("common")
        and not info.name.startswith("_")
        and not info.ispkg  # the language data (catalogues/language/)
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
    # the summary of each transient a command made (not the results themselves)
    summaries: RunSummaries = field(default_factory=RunSummaries)
    started: bool = False  # DEBUT or POURSUITE called in the current deck file
    # code_aster 15's generated object names ("0000001b") that decks may quote
    generated_names: GeneratedNames = field(default_factory=GeneratedNames)
    check: Any = None  # under check: asterlite.runtime.checking.CheckFacts
    # the code_aster version the decks are read in (asterlite run --aster-version);
    # None: detected from their text (asterlite.legacy.version)
    aster_version: int | None = None
    # refuses an output file name the run may not take (asterlite.runtime.outdir)
    output_guard: Any = None
    # files the deck wrote itself (numpy.savetxt), which it may write again
    deck_written: set = field(default_factory=set)
    # where the run is: (command, location, running) of the last command started
    current_command: tuple | None = None
    # told each command's start and end (the output folder's lock record)
    command_hook: Any = None

    def __post_init__(self) -> None:
        self.namespace.update(base_namespace(print_hook=self._print))

        self.namespace.update(stdlib.namespace_builtins(self.namespace))  # globals(): these names
        if self.check_only:
            self.check = checking.CheckFacts(session=self, finding_of_error=finding_of_error)
            # refused by name as before, and validated in the deck version's language
            bind_language_commands(self)
        else:
            # code_aster commands asterlite lacks are refused by name when called
            for name, version in checking.code_aster_commands().items():
                self.namespace[name] = checking.UnsupportedCommand(name, version)
        for name in catalogue_command_names():
            self.namespace[name] = CommandProxy(name, self)

    @property
    def check_errors(self) -> list:
        return self.check.errors if self.check is not None else []

    # ----------------------------------------------------------- services
    def _print(self, text: str) -> None:
        """Where the deck's print() goes: the message log."""
        for line in text.rstrip("\n").split("\n"):
            self.log(line)

    def log(self, text: str) -> None:
        self.messages.append(text)
        if self.echo:  # a closed pipe or terminal silences the echo, not the run
            console.say(text)

    def note_command(self, name: str, location, running: bool) -> None:
        """The command the run is in (``running``) or has just ended."""
        self.current_command = (name, location, running)
        if self.command_hook is not None:
            self.command_hook(name, location, running)

    def record_test(self, record: TestRecord) -> None:
        self.tests.append(record)

    def command(self, name: str) -> CommandProxy:
        """The deck command ``name`` run in this session (what a deck calling
        it gets; legacy translations and the code_aster object API call it)."""
        return CommandProxy(name, self)

    def input_path(self, unit: int) -> Path:
        """The input file the run maps to logical ``unit``."""
        if unit in self.output_units and self.output_units[unit].exists():
            return self.output_units[unit]
        try:
            return self.run.units[unit]
        except KeyError:
            raise CommandError(unmapped_unit_text(self.run, unit, self.output_units)) from None

    def free_unit(self, location=None) -> int:
        """The logical unit code_aster gives a file named without one
        (``ulnume``): the highest of 99 down to 70 not in use."""
        used = set(self.run.units) | set(self.output_units)
        if self.check is not None:
            used |= self.check.units_open
        for unit in range(99, 69, -1):
            if unit not in used:
                return unit
        raise CommandError("no free logical unit is left among 70 to 99", location)

    def output_path(self, unit_or_name: int | str) -> Path:
        """A path in the output folder for a logical unit or a file name."""
        if self.output_dir is None:
            raise CommandError("this run has no output folder")
        self.output_dir.mkdir(parents=True, exist_ok=True)
        if isinstance(unit_or_name, int):
            if unit_or_name not in self.output_units:
                self.output_units[unit_or_name] = self._output_file(f"fort.{unit_or_name}")
            return self.output_units[unit_or_name]
        return self._output_file(Path(unit_or_name).name)

    def _output_file(self, name: str) -> Path:
        if self.output_guard is not None:
            self.output_guard(name)
        elif name in ("", ".", ".."):
            raise CommandError(f"{name!r} is not a file name")
        return self.output_dir / name

    def bind_output(self, output: Any, concept: Any) -> None:
        if not isinstance(output, CO):
            raise CommandError(f"expected a CO('NAME') output, got {output!r}")
        if isinstance(concept, Concept):
            concept.name = output.name
        self.namespace[output.name] = concept

    # ----------------------------------------------------------- running
    def load_module(self, name: str) -> dict | None:
        """Modules a deck may import besides math and numpy."""
        if name in COMMAND_MODULES:  # the commands, which the namespace already holds
            commands = (CommandProxy, UnsupportedCommand)
            return {n: v for n, v in self.namespace.items() if isinstance(v, commands)}
        if name == "code_aster.CA":
            from asterlite.runtime.deck_api import code_aster_ca_module

            return code_aster_ca_module(self)
        if name.startswith("code_aster.") and self.check is not None:
            found = module_commands(self, name)  # user macros: code_aster.MacroCommands...
            if found:
                return found
        if name.startswith("code_aster."):
            raise UnsupportedError(
                f"module {name}: asterlite provides code_aster's commands "
                "(code_aster.Commands) and some of code_aster.CA, not this module"
            )
        if name == "code_aster":
            from asterlite.runtime.deck_api import code_aster_module

            return code_aster_module(self)
        if name == "aster":
            from asterlite.runtime.deck_api import aster_module

            return aster_module(self)
        if name in ("os", "os.path"):  # os.path's file tests see the output folder only
            from asterlite.lang import stdlib
            from asterlite.lang.limits import Limits

            module = stdlib.os_module(lambda: self.output_dir, Limits(), self.log)
            return module if name == "os" else module.attribute("path")
        if name in self.run.helper_modules:
            from asterlite.lang import Evaluator, parse_deck

            path = self.run.helper_modules[name]
            text = read_deck_text(path, "helper module")
            module = parse_deck(text, str(path), study_file=True)
            namespace = dict(self.namespace)
            Evaluator(namespace, module_loader=self.load_module).run(module)
            return namespace
        return None

    def run_file(self, path: Path) -> None:
        """Parse and evaluate one deck file in the session namespace."""

        self.current_file = str(path)
        self.started = False
        self.log(f"# deck {path.name}")
        try:
            text, encoding = read_deck(path)
            if encoding not in (UTF8, UTF8_BOM):  # said, since the deck's strings carry it
                self.log(f"# deck {path.name} read as {encoding}, not UTF-8")
            module = parse_deck(text, str(path), study_file=True)
            if module.python2:
                self._python2_allowed(module, path)
            else:
                module = self._python2_meaning(module, text, path)
        except AsterliteError as error:
            if self.check is None:
                raise
            self.check.record(error)  # check goes on with the next deck file
            bind_unparsed_names(self, path)  # its names are unknown, not undefined
            return
        evaluator = Evaluator(
            self.namespace, module_loader=self.load_module, overrides=self.overrides
        )
        evaluator.caught_hook = self._caught
        self._evaluator = evaluator
        self._code_aster_imports(text)
        try:
            evaluator.run(module, on_error=self._statement_failed if self.check else None)
        except DeckFinished:
            pass
        finally:
            self.overrides_used |= evaluator.overrides_used
        if not self.started:  # an empty deck, or one that never starts a study
            self._no_start(DeckStartError(NO_START, Location(str(path), 1)))

    def _code_aster_imports(self, text: str) -> None:
        """What code_aster's run_aster adds to a deck that imports nothing of
        code_aster and starts with DEBUT or POURSUITE (run_aster/command_files.py,
        add_import_commands): ``import code_aster`` and ``from code_aster import CA``
        (the commands are in every namespace already)."""
        if CODE_ASTER_IMPORTED.search(text) or not STARTS_STUDY.search(text):
            return

        members = code_aster_module(self)
        self.namespace.setdefault("CA", members["CA"])
        self.namespace.setdefault("code_aster", DeckModule("code_aster", members))

    def _python2_allowed(self, module, path: Path) -> None:
        """A Python 2 deck runs as one of code_aster 13 or older; in a run read
        as a later version, its Python 3 syntax error stands."""
        version = session_version(self)
        if version > PYTHON2_LAST:
            error = module.python3_error
            raise DeckSyntaxError(
                f"{error.message} (the deck reads as Python 2, as decks of code_aster "
                f"{PYTHON2_LAST} and older were; this run reads it as code_aster {version})",
                error.location,
            )
        self.log(
            f"# deck {path.name} is Python 2 (code_aster {version}): print statements, "
            "integer division, lists from map/zip/range/dict.keys() as Python 2 had them"
        )

    def _python2_meaning(self, module, text: str, path: Path):
        """A deck of code_aster 13 or older ran under Python 2 even when its
        text also reads as Python 3: its '/' of integers, map/zip/range...
        meant Python 2's (asterlite.lang.python2)."""

        version = session_version(self)
        if version > PYTHON2_LAST:
            return module
        try:
            old = parse_deck(text, str(path), study_file=True, python2=True)
        except AsterliteError:  # Python 3 only (f-strings...): read as written
            return module
        self.log(
            f"# deck {path.name} is read as Python 2 (code_aster {version}): integer "
            "division, lists from map/zip/range/dict.keys() as Python 2 had them"
        )
        return old

    def deck_may_catch(self) -> bool:
        """A try (with handlers) or with block of the deck file is under way."""
        return getattr(getattr(self, "_evaluator", None), "catching", 0) > 0

    def _caught(self, error, location) -> None:
        """An error the deck catches (try/except, assertRaises) is said in the log."""
        where = f"{Path(location.file).name}:{location.line}" if location is not None else ""
        self.log(f"# caught by the deck ({where}): {error.kind}: {error.message}")

    def _statement_failed(self, error, statement) -> None:
        """Under check: record the error of a top-level statement and go on."""
        if isinstance(error, DeckFinished):
            raise error
        statement_failed(self, statement, error)

    def _no_start(self, error: AsterliteError) -> None:
        """A command before DEBUT/POURSUITE: an error (recorded once under check)."""
        if self.check is None:
            raise error
        self.check.record(error)
        self.started = True

    def open_deck_file(self, name: str):
        """A new text stream for a file the deck writes itself (numpy.savetxt) in
        the output folder (one it wrote before is replaced); None under check."""

        if self.check_only:
            return None
        path = self.output_path(name)
        if path in self.deck_written:
            path.unlink(missing_ok=True)
        stream = create_file(path)
        self.deck_written.add(path)
        self.log(f"  deck file {path.name} written (numpy.savetxt)")
        return stream

    def run_all(self) -> None:
        token = savetxt.set_writer(self.open_deck_file)
        try:
            self._run_all()
        finally:
            savetxt.reset_writer(token)

    def _run_all(self) -> None:
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


def unmapped_unit_text(run, unit: int, written: dict) -> str:
    """Why a deck reads a logical unit no file is mapped to, and every place
    looked: the export's F lines, the bare deck's sibling files, the units
    the deck itself wrote."""
    known = ", ".join(str(u) for u in sorted(run.units)) or "none"
    if unit in run.unmapped:  # a bare deck's mesh: where it was looked for
        return f"logical unit {unit}: {run.unmapped[unit]}"
    if run.source is not None:
        looked = f"the export {run.source} maps units {known} ('F <type> <file> D <unit>' lines)"
    else:
        looked = f"a bare deck maps only its sibling mesh to unit 20 (mapped units: {known})"
    wrote = ", ".join(str(u) for u in sorted(written)) or "none"
    return (
        f"no file is mapped to logical unit {unit}: {looked}; "
        f"the deck wrote no file on it earlier (units written: {wrote})"
    )


def deck_variables(namespace: dict) -> list[str]:
    """Names the deck bound to plain numbers or strings: what --set can vary."""

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
# Commands that start a study: every deck file calls one before any other command.
STARTERS = ("DEBUT", "POURSUITE")
NO_START = "the deck file calls neither DEBUT() nor POURSUITE(), which every study starts with"
# Modules that only bring the command namespace asterlite already provides.
COMMAND_MODULES = ("code_aster.Commands", "code_aster.Cata.Commands", "code_aster.CodeCommands")


# run_aster's tests (add_import_commands) for a deck that imports code_aster itself
CODE_ASTER_IMPORTED = re.compile(r"^from +code_aster(\.Commands| +import +CA)", re.M)
STARTS_STUDY = re.compile(r"^(DEBUT|POURSUITE)", re.M)


class DeckStartError(AsterliteError):
    """A deck file without DEBUT()/POURSUITE(), or a command before it."""

    kind = "deck error"


class CommandProxy(DeckCallable):
    """A deck command: validates against its catalogue, then dispatches."""

    def __init__(self, name: str, session: Session):
        self.name = name
        self.session = session

    def __repr__(self) -> str:
        return f"<command {self.name}>"

    def deck_call(self, args: list, kwargs: dict, site: CallSite):
        if self.session.check is None:
            return self._deck_call(args, kwargs, site)
        # check: valid code_aster N (the deck's version), then what asterlite computes
        return checked_call(self, args, kwargs, site)

    def _checked_call(self, args: list, kwargs: dict, site: CallSite):
        """asterlite's own check of a call (its catalogue, mesh names, units)."""
        if self.session.deck_may_catch():
            # a try or with block of the deck may catch the error, as in a run
            return self._deck_call(args, kwargs, site)
        try:
            return self._deck_call(args, kwargs, site)
        except DeckFinished:
            raise
        except AsterliteError as error:  # check: record, the outputs become Unknown
            if error.location is None:
                error.location = site.location
            command_failed(self.session, self.name, kwargs, error)
            return Unknown

    def _deck_call(self, args: list, kwargs: dict, site: CallSite):
        session = self.session
        if not session.started and self.name not in STARTERS:
            session._no_start(
                DeckStartError(f"{self.name} comes before DEBUT() or POURSUITE()", site.location)
            )
        session.started = True
        if not session.check_only:
            watchdog.check_limits()  # between commands: the run's time and memory limits
        if args:
            raise UnsupportedError(
                f"{self.name} takes keyword arguments only", site.location, self.name
            )
        catalogue = load_catalogue(self.name)
        if catalogue is None:
            raise UnsupportedError(f"command {self.name} is not supported", site.location)
        kwargs = dict(kwargs)
        reuse = kwargs.pop("reuse", None)
        kwargs = v11.before_call(self.name, kwargs, site, session)
        if legacy_form(self.name) is not None:  # legacy syntax: check as written, translate
            modern = translate_call(catalogue, kwargs, site, session, reuse=reuse)
            if modern is not None:
                name, catalogue, kwargs = modern
                # a renamed legacy command: the modern one runs it
                proxy = CommandProxy(name, session) if name != self.name else self
                return modern.finish(proxy._call(catalogue, kwargs, reuse, site))
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
        try:
            keywords = validate(catalogue, kwargs, site, reuse=reuse)
        except ValidationError as error:
            # a keyword code_aster has and asterlite lacks is unsupported, never invalid
            given = dict(kwargs, reuse=reuse) if reuse is not None else kwargs
            refusal = (
                None
                if session.check_only
                else refusal_of_valid_call(session, self.name, given, site, error)
            )
            if refusal is None:
                raise
            raise refusal from None
        if extra:
            keywords["_extra"] = extra
        if self.name in SESSION_COMMANDS:
            return self._session_command(keywords, site)
        if session.check_only:
            return check_call(self, catalogue, keywords, site, reuse)
        # what the language closes beyond the catalogue (NOM_CMP of a displacement
        # field): refused before computing, as check reports it
        for finding in component_findings(self.name, kwargs, site):
            raise finding
        return self._execute(keywords, site, reuse)

    # ---------------------------------------------------------------- check
    def _placeholder(self, catalogue, keywords: Keywords):
        try:
            # sd_prod also types the CO outputs (CO.produced_type), as code_aster's does
            produced = result_type(catalogue, keywords)
        except Exception:  # sd_prod read a value check mode could not compute
            produced = AnyPlaceholder
        for output in co_outputs(keywords):
            typed = getattr(output, "produced_type", None)
            concept = Placeholder(typed, self.name) if typed else AnyPlaceholder(self.name)
            self.session.bind_output(output, concept)
        if produced is AnyPlaceholder or undecidable(catalogue, keywords):
            # a type chosen from uncomputed inputs could be wrong: any type will do
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
        session.note_command(self.name, site.location, True)
        start = time.perf_counter()
        try:
            concept = module.run(ctx, keywords)
        except MemoryError:
            limit = watchdog.memory_limit_mb()
            what = f"the run's limit of {limit:g} MB" if limit else "the memory available"
            raise watchdog.MemoryLimitError(
                f"the command needs more memory than {what} (export 'P memory_limit', "
                "or asterlite run --memory-limit to change it)",
                site.location,
                self.name,
            ) from None
        except AsterliteError as error:
            if error.location is None:
                error.location = site.location
            if not error.path:
                error.path = self.name
            raise
        refuse_unread(keywords)
        concept = v11.after_run(self.name, concept, session)
        seconds = time.perf_counter() - start
        session.timings.append(CommandTiming(self.name, site.location, site.assigned_name, seconds))
        session.log(f"  done in {seconds:.3f} s")
        session.note_command(self.name, site.location, False)
        if isinstance(concept, Concept):
            session.summaries.add(self.name, site.assigned_name, concept)
        record_call(session, self.name, keywords, concept, reuse, site.location)
        # results past their share of the memory limit go to disk, and the
        # pages of those on disk the command and its summary read go back to
        # the system (numpy's stack: a command has run)
        from asterlite.runtime import result_paging

        result_paging.after_command(session.namespace, concept, session.output_dir)
        # a reused concept keeps its name; a new one takes the deck's name
        if isinstance(concept, Concept) and site.assigned_name:
            if reuse is None or concept.name is None:
                concept.name = site.assigned_name
        return concept

    # -------------------------------------------------------------- session
    def _session_command(self, keywords: Keywords, site: CallSite):
        result = self._run_session_command(keywords, site)
        refuse_unread(keywords)
        return result

    def _run_session_command(self, keywords: Keywords, site: CallSite):
        session = self.session
        if self.name == "FIN":
            session.log("FIN")
            raise DeckFinished("FIN reached", site.location)
        if self.name in ("DEBUT", "POURSUITE", "DEBUG"):
            if keywords.get("MODE") == "POURSUITE":  # continue a saved code_aster database
                path, location = keywords.where("MODE")
                raise UnsupportedError(
                    "MODE='POURSUITE' continues a code_aster database, which asterlite "
                    "does not read: run the earlier deck in the same .export instead",
                    location,
                    path,
                )
            session.log(self.name)
            return None
        if self.name == "DETRUIRE":
            # NOM (code_aster 13+) or CONCEPT=_F(NOM=...) (older decks): every
            # deck name bound to a destroyed concept goes
            given = [keywords.get("NOM")]
            given += [occurrence.get("NOM") for occurrence in keywords.factor("CONCEPT")]
            for names in given:
                for concept in names if isinstance(names, (tuple, list)) else (names,):
                    if concept is None:
                        continue
                    for key, value in list(session.namespace.items()):
                        if value is concept:
                            del session.namespace[key]
            return None
        if self.name == "DEFI_FICHIER":
            unit = keywords.get("UNITE")
            name = keywords.get("FICHIER")
            if keywords.get("ACTION", "ASSOCIER") == "LIBERER":
                # the unit is closed: what is written to it later goes to fort.<unit>
                if isinstance(unit, int):  # under check, a unit may be unknown
                    session.output_units.pop(int(unit), None)
                elif unit is None and isinstance(name, str):
                    for number, path in list(session.output_units.items()):
                        if path.name == Path(name).name:
                            del session.output_units[number]
                return None
            # a file named without a unit: code_aster chooses a free one and
            # returns it (DEFI_FICHIER's result is then an integer)
            chosen = unit is None and isinstance(name, str)
            if chosen:
                unit = session.free_unit(site.location)
            if unit is not None and name and session.output_dir is not None:
                session.output_units[int(unit)] = session.output_path(str(name))
            if session.check is not None:
                note_unit_mapping(session, keywords, unit)
            return int(unit) if chosen else None
        return None


def refuse_unread(keywords: Keywords) -> None:
    """Stop on any keyword the deck gave that the command did not use.

    A keyword accepted and ignored would leave a result that looks valid but
    is not what code_aster computes: refusing it is the honest answer.
    """
    unread = unread_keywords(keywords)
    if not unread:
        return
    level, name = unread[0]
    path, location = level.where(name)
    others = [lvl.where(n)[0] for lvl, n in unread[1:]]
    more = f" (also not used: {', '.join(others)})" if others else ""
    raise UnsupportedError(
        "given, but asterlite does not implement what this keyword does in code_aster: "
        f"refused rather than ignored{more}",
        location,
        path,
    )


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


__all__ = [
    "Session",
    "CommandProxy",
    "DeckFinished",
    "AnyPlaceholder",
    "UnknownOverrideError",
    "KeywordOverride",
]
