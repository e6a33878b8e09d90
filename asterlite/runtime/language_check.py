"""``asterlite check``'s two verdicts: valid code_aster N, and computed by asterlite.

Every command call of a checked deck is validated against the language
data of the deck's version (:mod:`asterlite.catalog.language`): what fails
there is **invalid** (code_aster N itself would refuse the deck). The call
then goes through asterlite's own check, as before: what asterlite's
catalogue, readers or evaluator refuse in a valid call is **unsupported**
(a command, keyword or value asterlite does not compute, a file it cannot
read, Python its evaluator does not take), never invalid.

The session's :class:`~asterlite.runtime.checking.CheckFacts` keeps both:
``errors``, asterlite's own verdict exactly as before (what ``run`` would
meet: ``run_deck(check_only=True)``, ``asterlite.check``, ``sweep``), and
``findings``, the two verdicts ``asterlite check`` prints. A finding's
class tells its kind (:func:`finding_kind`):

- :class:`InvalidCall` and every other error: ``invalid``;
- :class:`NotComputed` (an :class:`UnsupportedError`): ``unsupported``;
- :class:`UnsupportedPython` (an :class:`UnsupportedError`):
  ``unsupported-python``: a statement asterlite's evaluator refuses or
  cannot evaluate under check (a module it does not provide, names
  starting with ``__``, arithmetic on results check did not compute...),
  counted as unsupported.

Inside a ``try`` with handlers (or a ``with`` block) an invalid call raises
the error code_aster would raise, so the deck's own handler sees it
(code_aster's tests of its error messages).

A version without language data (code_aster 10-12 today) is checked
against asterlite's catalogues alone, its errors told apart by kind.
"""

from __future__ import annotations

import ast
import builtins
import difflib
import re

from asterlite.catalog import load_catalogue
from asterlite.catalog.language import validate as language_validate
from asterlite.catalog.language import value_checks as language_value_checks
from asterlite.catalog.language.components import DISPLACEMENT_FIELDS, displacement_components
from asterlite.catalog.language.model import Language, available_versions, language
from asterlite.catalog.model import BLOC, FACT
from asterlite.concepts.base import Placeholder
from asterlite.errors import (
    AsterliteError,
    CommandError,
    DeckRuntimeError,
    DeckSyntaxError,
    UnsupportedError,
    ValidationError,
)
from asterlite.io.input_files import read_text_or_none
from asterlite.lang.values import CO, CallSite, DeckCallable, FactorDict, Unknown, co_outputs
from asterlite.legacy.forms import legacy_form
from asterlite.runtime.checking import MESH_COMMANDS, READERS, code_aster_commands


class InvalidCall(ValidationError):
    """A call code_aster N refuses (its language data says why)."""

    kind = "invalid"


class NotComputed(UnsupportedError):
    """Valid code_aster N that asterlite does not compute."""

    kind = "unsupported"


class UnsupportedPython(UnsupportedError):
    """A statement Python accepts that asterlite's evaluator does not take
    (or cannot evaluate under check)."""

    kind = "unsupported-python"


def finding_kind(error: BaseException) -> str:
    """``invalid``, ``unsupported`` or ``unsupported-python``."""
    if isinstance(error, UnsupportedPython):
        return "unsupported-python"
    if isinstance(error, UnsupportedError):
        return "unsupported"
    return "invalid"


# code_aster types that stand for plain Python values (DEFI_FICHIER's unit number...)
VALUE_TYPES = frozenset({"entier", "reel"})


# ------------------------------------------------------------------ version


def session_language(session) -> Language | None:
    """The language data the session's decks are checked with (None: no data)."""
    if not hasattr(session, "_language"):
        from asterlite.legacy.version import session_version

        session._language_version = session_version(session)
        session._language = language(session._language_version)
    return session._language


def deck_version(session) -> int:
    session_language(session)
    return session._language_version


def bind_language_commands(session) -> Language | None:
    """Under check: bind the code_aster commands asterlite lacks, those of
    every catalogue asterlite knows (as before) and those of the deck
    version's language (asterlite's own are bound again by the session)."""
    lang = session_language(session)
    for name, version in code_aster_commands().items():
        session.namespace[name] = LanguageCommand(name, session, version)
    if lang is not None:
        for name in lang.command_names:
            if lang.is_deck_command(name) and name not in session.namespace:
                session.namespace[name] = LanguageCommand(name, session, str(lang.version))
    return lang


def module_commands(session, module: str) -> dict | None:
    """``from code_aster.MacroCommands.defi_cont import DEFI_CONT``: the user
    macros the language says that module defines."""
    lang = session_language(session)
    if lang is None:
        return None
    names = lang.module_commands(module)
    return {name: LanguageCommand(name, session) for name in names} or None


# ------------------------------------------------------------------ placeholders


# ------------------------------------------------------------------ calls


def check_language(session, name: str, kwargs: dict, site: CallSite, *, record: bool = True):
    """Validate a call against the deck version's language. None when there
    is no language data; else the
    :class:`~asterlite.catalog.language.validate.CallCheck` (its findings
    recorded unless ``record`` is false)."""
    lang = session_language(session)
    if lang is None:
        return None
    version = deck_version(session)
    kwargs = blur_empty_sequences(dict(kwargs))
    reuse = kwargs.pop("reuse", None)
    if lang.command(name) is None:
        check = language_validate.CallCheck()
        check.findings.append(InvalidCall(not_a_command(name, lang, version), site.location, name))
    else:
        check = language_validate.check_call(lang, name, kwargs, site, reuse=reuse)
        check.findings[:] = [InvalidCall(f.message, f.location, f.path) for f in check.findings]
        if not check.findings:
            check.findings += component_findings(name, kwargs, site)
    if record:
        for finding in check.findings:
            session.check.record(finding)
    return check


def component_findings(name: str, kwargs: dict, site: CallSite) -> list:
    """``NOM_CMP`` beside ``NOM_CHAM='DEPL'`` (``VITE``, ``ACCE``...) of a
    result: each component must be one of code_aster's DEPL_R (a field given
    with CHAM_GD may carry another quantity under that name: not judged)."""

    found = []

    def visit(level: dict, path: str, locations: dict, where) -> None:
        field, components = level.get("NOM_CHAM"), level.get("NOM_CMP")
        if (
            isinstance(field, str)
            and field in DISPLACEMENT_FIELDS
            and components is not None
            and level.get("CHAM_GD") is None
        ):
            names = components if isinstance(components, (list, tuple)) else [components]
            for component in names:
                if isinstance(component, str) and component not in displacement_components():
                    close = difflib.get_close_matches(
                        component, sorted(displacement_components()), n=1, cutoff=0.6
                    )
                    hint = f", did you mean {close[0]!r}?" if close else ""
                    found.append(
                        InvalidCall(
                            f"{component!r} is not a component of {field} (quantity DEPL_R){hint}",
                            locations.get("NOM_CMP", where),
                            f"{path}/NOM_CMP",
                        )
                    )
        for key, value in level.items():
            occurrences = value if isinstance(value, (list, tuple)) else [value]
            for index, occurrence in enumerate(occurrences, start=1):
                if isinstance(occurrence, dict):
                    visit(
                        occurrence,
                        f"{path}/{key}[{index}]",
                        getattr(occurrence, "keyword_locations", {}) or {},
                        getattr(occurrence, "location", None) or locations.get(key, where),
                    )

    if kwargs.get("CHAM_GD") is None:
        visit(kwargs, name, dict(site.keyword_locations), site.location)
    return found


def blur_empty_sequences(value):
    """Under check, an empty list may stand for data built from uncomputed
    results (a loop over Unknown appends nothing): it is Unknown."""
    if isinstance(value, (list, tuple)) and not value:
        return Unknown
    if isinstance(value, FactorDict):
        return FactorDict(
            {k: blur_empty_sequences(v) for k, v in value.items()},
            location=value.location,
            keyword_locations=value.keyword_locations,
        )
    if isinstance(value, dict):
        return {k: blur_empty_sequences(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return type(value)(blur_empty_sequences(v) for v in value)
    return value


def not_a_command(name: str, lang: Language, version: int) -> str:
    """Why ``name`` is no command of the deck's version (and which has it)."""

    others = []
    for other in available_versions():
        found = language(other)
        if found is not None and found is not lang and found.command(name) is not None:
            others.append(str(found.version))
    text = f"{name} is not a command of code_aster {version}"
    if others:
        text += f" (code_aster {', '.join(others)} has it)"
    close = difflib.get_close_matches(name, sorted(lang.command_names), n=1, cutoff=0.7)
    if close:
        text += f", did you mean {close[0]}?"
    return text


def note_units(session, name: str, keywords: dict) -> None:
    """Logical units a command other than a reader may write (every UNITE*
    value, code_aster's defaults included: IMPR_RESU in MED writes unit 80)."""
    if name in READERS:
        return
    for value in _unit_values(keywords):
        session.check.units_open.add(value)


def note_not_computed(session, name: str, kwargs: dict, keywords: dict | None = None) -> None:
    """A valid call asterlite does not compute: what it may have written or
    changed (logical units, a mesh's groups) is no longer judged."""
    facts = session.check
    for value in _unit_values(kwargs):
        facts.units_open.add(value)
    note_units(session, name, keywords or {})
    lang = session_language(session)
    command = lang.command(name) if lang is not None else None
    sd_prod = (command or {}).get("sd_prod") or {}
    produced = set(sd_prod.get("types", ())) | set(sd_prod.get("depends", ()))
    if "type" in sd_prod:
        produced.add(sd_prod["type"])
    if (
        name in MESH_COMMANDS
        or kwargs.get("reuse") is not None
        or any(t.startswith("maillage") or t in ("assd", "squelette") for t in produced)
    ):
        facts.close_names()


def _unit_values(kwargs):
    for key, value in dict.items(kwargs) if isinstance(kwargs, dict) else ():
        if isinstance(value, dict):
            yield from _unit_values(value)
        elif isinstance(value, (list, tuple)):
            for item in value:
                if isinstance(item, dict):
                    yield from _unit_values(item)
        elif key.startswith("UNITE") and isinstance(value, int) and not isinstance(value, bool):
            yield value


class CallState:
    """A command call under way: whether the language found it valid (then
    asterlite's refusals of it are unsupported findings) or invalid (then
    asterlite's errors about it are no findings of their own: the language
    reported the call at its root)."""

    def __init__(self, name: str, kwargs: dict, site: CallSite, valid: bool):
        self.name = name
        self.kwargs = kwargs
        self.site = site
        self.valid = valid


class _Call:
    def __init__(self, facts, state: CallState):
        self.facts = facts
        self.state = state

    def __enter__(self):
        self.facts.calls.append(self.state)
        return self.state

    def __exit__(self, *exc):
        self.facts.calls.remove(self.state)
        return False


def checked_call(proxy, args: list, kwargs: dict, site: CallSite):
    """A call of a command asterlite implements, under check: the language
    first (findings), then asterlite's own check exactly as before (errors)."""
    session = proxy.session
    facts = session.check
    catching = session.deck_may_catch()
    language = check_language(session, proxy.name, kwargs, site, record=False)
    if language is None:
        return proxy._checked_call(args, kwargs, site)
    if language.findings and catching:  # code_aster raises here: the deck's handler sees it
        raise language.findings[0]
    for finding in language.findings:
        facts.note(finding)
    state = CallState(proxy.name, kwargs, site, valid=not language.findings)
    if state.valid:
        note_units(session, proxy.name, language.keywords)
    with _Call(facts, state):
        if catching:
            try:
                result = proxy._checked_call(args, kwargs, site)
            except AsterliteError as error:
                if state.valid and refused_by_asterlite(error):
                    for finding in refusal_findings(state, error, session):
                        facts.note(finding)
                raise
        else:
            result = proxy._checked_call(args, kwargs, site)
    return _annotate(result, language, kwargs)


def _annotate(result, language, kwargs: dict):
    """asterlite's placeholder for a result it did not compute, given the
    types the language gives it (code_aster's sd_prod may type it otherwise
    than asterlite's catalogue; with ``reuse=``, the concept reused keeps its
    own: a parallel mesh stays one through MODI_MAILLAGE). asterlite's own
    checks go on seeing the placeholder as before."""
    if not isinstance(result, Placeholder) or type(result).__name__ not in (
        "Placeholder",
        "AnyPlaceholder",
    ):
        return result
    reused = kwargs.get("reuse")
    if reused is not None:
        types = language_types(reused)
        result.language_types = types if types is not None else "any"
        return result
    wanted = language.result
    if wanted is None:
        return result
    if isinstance(wanted, str):
        wanted = {wanted}
    if not wanted or wanted & VALUE_TYPES or "assd" in wanted:
        result.language_types = "any"
    else:
        result.language_types = tuple(sorted(wanted))
    return result


def language_types(value):
    """The types the language gives a concept (a tuple, or "any"), None for
    a value that is no concept; see :func:`asterlite.catalog.language.validate.concept_types`."""
    if value is Unknown:
        return "any"
    return language_validate.concept_types(value)


def refusal_findings(state: CallState, error: AsterliteError, session) -> list:
    """asterlite's refusal of a call the language accepts: unsupported, with
    every keyword asterlite's catalogue lacks (not only the first it met)."""
    missing = unsupported_keywords(state.name, state.kwargs, state.site)
    return missing or [as_unsupported(error, deck_version(session))]


def finding_of_error(session, error: AsterliteError) -> list:
    """The findings an error of asterlite's own check gives (see
    :class:`CheckFacts.record <asterlite.runtime.checking.CheckFacts>`)."""
    if getattr(error, "finding_made", False):
        return []
    facts = session.check
    state = facts.calls[-1] if facts.calls else None
    if state is not None and session_language(session) is not None:
        if not state.valid:
            return []  # the language reported this call already, at its root
        if refused_by_asterlite(error):
            note_not_computed(session, state.name, state.kwargs)
            return refusal_findings(state, error, session)
        return [error]  # a deck error asterlite's check sees (a missing group, a unit)
    found = classify_deck_error(session, error)
    return [] if found is None else [found]


class LanguageCommand(DeckCallable):
    """A code_aster command asterlite does not implement: under check,
    validated by the language of the deck's version (a command of another
    version is said so), and refused by name as before (asterlite's error);
    under run, refused by name."""

    def __init__(self, name: str, session, version: str = "17"):
        self.name = name
        self.session = session
        self.version = version  # of code_aster's catalogue that names it (as before)

    def __repr__(self) -> str:
        return f"<code_aster command {self.name} (not in asterlite)>"

    def _refusal(self, site: CallSite) -> UnsupportedError:
        where = "current" if self.version == "17" else f"version {self.version}"
        return UnsupportedError(
            f"{self.name} is a code_aster command ({where} catalogue) that asterlite "
            "does not implement",
            site.location,
            self.name,
        )

    def deck_call(self, args, kwargs, site: CallSite):
        session = self.session
        refusal = self._refusal(site)
        if session.check is None:
            raise refusal
        refusal.finding_made = True  # the finding is the language's, below
        facts = session.check
        catching = session.deck_may_catch()
        lang = session_language(session)
        version = deck_version(session)
        check = None
        if args:
            findings = [
                InvalidCall(f"{self.name} takes keyword arguments only", site.location, self.name)
            ]
        elif lang is None:
            findings = [NotComputed(refusal.message, site.location, self.name)]
        else:
            check = check_language(session, self.name, kwargs, site, record=False)
            findings = check.findings or [
                NotComputed(
                    f"{self.name} is valid code_aster {version}, but asterlite does not "
                    "compute this command",
                    site.location,
                    self.name,
                )
            ]
        if catching:
            if isinstance(findings[0], InvalidCall):
                raise findings[0]  # as code_aster: the deck's handler sees it
            facts.note(findings[0])
            raise refusal  # asterlite's refusal, which no deck catches
        for finding in findings:
            facts.note(finding)
        facts.errors.append(refusal)  # asterlite's own verdict, as before
        for output in co_outputs(kwargs):
            session.namespace[output.name] = Unknown
        if check is not None and not check.findings:
            note_not_computed(session, self.name, kwargs, check.keywords)
        facts.close_names()  # what the command made, a mesh maybe, is unknown
        return Unknown


# ------------------------------------------------------------- asterlite's side


def unsupported_keywords(name: str, kwargs: dict, site: CallSite) -> list[NotComputed]:
    """Keywords of a language-valid call that asterlite's catalogue does not
    have, at every level (each one found, not only the first)."""

    catalogue = load_catalogue(name)
    found: list[NotComputed] = []
    if catalogue is None or catalogue.extra_keywords or legacy_form(name) is not None:
        return found  # a legacy spelling asterlite translates first: its refusal says

    def visit(levels: list, given: dict, path: str, locations: dict, where) -> None:
        vocabulary = _asterlite_vocabulary(levels)
        for key, value in given.items():
            if key == "reuse" or language_value_checks.is_undefined(value):
                continue
            entries = vocabulary.get(key)
            if not entries:
                found.append(
                    NotComputed(
                        "valid code_aster keyword that asterlite does not implement",
                        locations.get(key, where),
                        f"{path}/{key}",
                    )
                )
                continue
            facts = [e for e in entries if isinstance(e, FACT)]
            if not facts:
                continue
            occurrences = value if isinstance(value, (list, tuple)) else [value]
            for index, occurrence in enumerate(occurrences, start=1):
                if isinstance(occurrence, dict):
                    visit(
                        facts,
                        occurrence,
                        f"{path}/{key}[{index}]",
                        getattr(occurrence, "keyword_locations", {}) or {},
                        getattr(occurrence, "location", None) or locations.get(key, where),
                    )

    visit([catalogue], kwargs, name, dict(site.keyword_locations), site.location)
    return found


def refusal_of_valid_call(
    session, name: str, kwargs: dict, site: CallSite, error: ValidationError
) -> UnsupportedError | None:
    """``run``: asterlite's catalogue refused a call (``error``); when the
    deck version's language accepts it, the refusal is asterlite's limit,
    not the deck's error: the first keyword asterlite lacks (or the
    catalogue's message), as unsupported. None when code_aster would
    refuse the call too, or when there is no language data to tell."""
    check = check_language(session, name, kwargs, site, record=False)
    if check is None or check.findings:
        return None
    missing = unsupported_keywords(name, kwargs, site)
    if missing:
        return missing[0]
    return as_unsupported(error, deck_version(session))


def _asterlite_vocabulary(levels: list) -> dict[str, list]:
    """Every keyword of ``levels`` (blocks included) -> its definitions: a
    factor keyword defined in several blocks allows the keywords of each."""

    found: dict[str, list] = {}

    def visit(level) -> None:
        for key, entry in level.entries.items():
            if isinstance(entry, BLOC):
                visit(entry)
            else:
                found.setdefault(key, []).append(entry)

    for level in levels:
        visit(level)
    return found


def refused_by_asterlite(error: AsterliteError) -> bool:
    """asterlite's catalogue, implementation or readers refused a call the
    language accepts (not a deck error such as a group missing from a mesh)."""
    if isinstance(error, (ValidationError, UnsupportedError)):
        return True
    return isinstance(error, CommandError) and getattr(error, "asterlite_limit", False)


def as_unsupported(error: AsterliteError, version: int) -> NotComputed:
    """asterlite's refusal of a call code_aster ``version`` accepts."""
    if isinstance(error, NotComputed):
        return error
    message = error.message
    if isinstance(error, ValidationError):
        message = f"valid code_aster {version}, but not in asterlite's catalogue: {message}"
    found = NotComputed(message, error.location, error.path)
    found.original = error
    return found


# --------------------------------------------------------------- deck level


def classify_deck_error(session, error: AsterliteError) -> AsterliteError | None:
    """A statement's error under check, as the finding it is: what Python
    itself would raise on the deck's own values (an undefined name, a
    syntax error Python shares) stays invalid; Python asterlite's evaluator
    refuses, a module it lacks, or an error on values check did not compute
    is :class:`UnsupportedPython`."""
    if isinstance(error, UnsupportedError):
        return error
    if type(error).__name__ == "DeckStartError" and _file_had_unsupported(session, error):
        return None  # the file's study may start in what check could not follow
    refusal = python_refusal(error, _file_of(error, session))
    if refusal is not None:
        return refusal
    if isinstance(error, DeckSyntaxError):
        if deck_version(session) < 13:  # Python 2 decks: asterlite reads a part of it
            return _unsupported_python(error, "Python 2 that asterlite does not read")
        return error
    if not isinstance(error, DeckRuntimeError):
        return error
    if type(error).__name__ == "DeckRaised":
        # the deck's own raise, on values check computed without running the
        # study (a file a tool makes first, a result): no verdict on the language
        return _unsupported_python(error, "the deck raises here; check cannot tell if a run would")
    kind = getattr(error, "python_type", None)
    if kind is None and type(error) is DeckRuntimeError:
        return _unsupported_python(error, "refused by asterlite's deck evaluator")
    if kind is NameError:
        return _name_error(session, error)
    if kind is not None:
        return _unsupported_python(error, "check could not evaluate this statement")
    return error


def python_refusal(error: AsterliteError, file: str) -> UnsupportedPython | None:
    """The error as the refusal it is when the deck is valid Python that
    asterlite does not take (a run and a check say UNSUPPORTED, not that the
    deck is wrong), else None: a construct Python parses but asterlite's deck
    parser refuses (``class``, ``global``...), an import of a module it does
    not provide. Its safety limits (a string too long...) stay errors."""
    if isinstance(error, DeckSyntaxError):
        if _python_accepts(file):
            return _unsupported_python(error, "a construct asterlite's deck parser does not take")
        return None
    kind = getattr(error, "python_type", None)
    if type(error) is DeckRuntimeError and kind is not None and issubclass(kind, ImportError):
        return _unsupported_python(error, "a module asterlite does not provide")
    return None


def _file_had_unsupported(session, error: AsterliteError) -> bool:
    file = _file_of(error, session)
    return any(
        isinstance(found, UnsupportedError) and getattr(found.location, "file", None) == file
        for found in session.check.errors
    )


def _unsupported_python(error: AsterliteError, why: str) -> UnsupportedPython:
    found = UnsupportedPython(f"{why}: {error.message}", error.location, error.path)
    found.original = error
    return found


def _name_error(session, error: DeckRuntimeError) -> AsterliteError:
    """An undefined name: a command of another code_aster version is said so."""
    match = re.match(r"name '([A-Za-z_][A-Za-z0-9_]*)' is not defined", error.message)
    if match is not None and match.group(1) in dir(builtins):
        return _unsupported_python(error, "a Python builtin asterlite's evaluator does not provide")
    if match is not None and match.group(1) in deck_bound_names(session):
        # the deck binds it somewhere check could not follow (a branch or loop
        # on uncomputed values, a statement asterlite refused)
        return _unsupported_python(error, "check could not follow where the deck binds it")
    opaque = [n[1:] for n in deck_bound_names(session) if n.startswith("*")]
    if match is not None and opaque:
        return _unsupported_python(error, f"it may come from 'from {opaque[0]} import *'")
    lang = session_language(session)
    if match is None or lang is None or not match.group(1).isupper():
        return error
    name = match.group(1)
    text = not_a_command(name, lang, deck_version(session))
    if "has it" not in text:
        return error
    found = InvalidCall(text, error.location, error.path)
    found.original = error
    return found


# modules whose every name asterlite binds on ``from M import *``
FULLY_PROVIDED = frozenset({"code_aster.Commands", "code_aster", "math", "cmath"})


def deck_bound_names(session) -> frozenset[str]:
    """Every name the run's deck files and helper modules bind anywhere
    (Python's syntax trees, parsed only)."""
    found = getattr(session, "_deck_bound_names", None)
    if found is None:
        run = getattr(session, "run", None)
        paths = list(getattr(run, "deck_files", ()) or ())
        paths += list((getattr(run, "helper_modules", None) or {}).values())
        # files an INCLUDE or an import may run (F libr/nom lines): small Python ones
        paths += [p for p in (getattr(run, "units", None) or {}).values() if _small(p)]
        names: set[str] = set()
        for path in dict.fromkeys(paths):
            tree = _python_tree(str(path))
            if tree is not None:
                names |= _bound_names(tree)
        found = session._deck_bound_names = frozenset(names)
    return found


def _file_of(error: AsterliteError, session) -> str:
    location = error.location
    return getattr(location, "file", None) or getattr(session, "current_file", "")


def _python_tree(path: str):
    """Python 3's syntax tree of a deck file (parsed only, never compiled to
    code or run), or None when Python does not parse it."""

    text = read_text_or_none(path) if path else None
    if text is None:
        return None
    try:
        return ast.parse(text, filename=path)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None


def _small(path, limit: int = 1_000_000) -> bool:
    try:
        return path.is_file() and path.stat().st_size < limit
    except (OSError, AttributeError):
        return False


def _python_accepts(path: str) -> bool:
    return _python_tree(path) is not None


def bind_unparsed_names(session, path) -> None:
    """A deck file asterlite could not parse: the names it would bind are
    unknown (not undefined), so that later uses are no findings of their own."""
    tree = _python_tree(str(path))
    if tree is None:
        return
    for name in _bound_names(tree):
        if name not in session.namespace:
            session.namespace[name] = Unknown


def _bound_names(tree) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                if alias.name != "*":
                    names.add(alias.asname or alias.name.split(".")[0])
                elif getattr(node, "module", None) not in FULLY_PROVIDED:
                    # what a module asterlite does not give in full binds is unknown
                    names.add(f"*{node.module}")
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
            if node.func.id == "CO" and node.args and isinstance(node.args[0], ast.Constant):
                if isinstance(node.args[0].value, str):
                    names.add(node.args[0].value)
    return names


def is_output_name(value) -> bool:
    return isinstance(value, CO)
