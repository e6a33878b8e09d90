"""Checking and normalising a command call against its catalogue.

:func:`validate` walks the catalogue level by level (the command, then each
factor occurrence). At each level it:

1. checks and normalises the given simple keywords and fills defaults;
2. activates the ``BLOC``s whose condition holds on the level's values
   (seen over the enclosing levels' values, as code_aster does), repeating
   until no more block opens, since a block may depend on another block's
   keywords or defaults;
3. rejects keywords of no active entry (did-you-mean, or "only with ...");
4. checks the rules (defaults count as present, as in code_aster), the
   mandatory keywords, then validates the factor occurrences.

The first problem raises :class:`ValidationError` with the keyword path and
the most precise location known. Under ``asterlite check`` a keyword may be
``Unknown``: it passes every check, and a block whose condition depends on
it is "undetermined": its keywords are accepted but neither required nor
defaulted.
"""

from __future__ import annotations

import difflib
from collections import ChainMap
from collections.abc import Mapping

from asterlite.catalog.keywords import Keywords
from asterlite.catalog.model import BLOC, FACT, MANY, SIMP, Command, Entry, Level, has_no_effect
from asterlite.catalog.values import TypeMismatch, accept, describe_value, is_old_complex, plain
from asterlite.concepts.base import Concept
from asterlite.errors import ValidationError
from asterlite.lang.values import CallSite, Unknown

# --- entry point -------------------------------------------------------------------------


def validate(
    catalogue: Command, kwargs: dict, site: CallSite | None = None, *, reuse=None
) -> Keywords:
    """The validated, defaulted keywords of a call to ``catalogue``."""
    site = site or CallSite()
    kwargs = dict(kwargs)
    if reuse is None:  # the runtime strips reuse=; accept it here too
        reuse = kwargs.pop("reuse", None)
    else:
        kwargs.pop("reuse", None)
    result = Keywords(path=catalogue.nom, location=site.location)
    result.locations.update(site.keyword_locations)
    _check_reuse(catalogue, reuse, result)
    return _validate_level(catalogue, kwargs, result, context={})


def result_type(catalogue: Command, keywords: Keywords) -> str | None:
    """The type name of the concept the call produces (None for a PROC)."""
    sd_prod = catalogue.sd_prod
    type_name = sd_prod(keywords) if callable(sd_prod) else sd_prod
    if type_name is not None and not isinstance(type_name, str):
        raise TypeError(f"{catalogue.nom}: sd_prod must give a type name, got {type_name!r}")
    return type_name


def _fail(result: Keywords, message: str, keyword: str | None = None) -> ValidationError:
    path, location = result.where(keyword)
    return ValidationError(message, location, path)


def _check_reuse(catalogue: Command, reuse, result: Keywords) -> None:
    if reuse is None and catalogue.reentrant == "o":
        raise _fail(result, "reuse= is mandatory: this command modifies an existing concept")
    if reuse is not None and catalogue.reentrant == "n":
        raise _fail(result, "reuse= is not allowed: this command always makes a new concept")
    expected = catalogue.sd_prod
    if isinstance(expected, str) and isinstance(reuse, Concept) and not reuse.satisfies(expected):
        raise _fail(
            result, f"reuse= expects a concept of type {expected}, got {describe_value(reuse)}"
        )


# --- one level ---------------------------------------------------------------------------


def _is_undefined(value) -> bool:
    """code_aster treats None and empty lists as "keyword not given"."""
    if value is None:
        return True
    if isinstance(value, (list, tuple)):
        return len(value) == 0 or (len(value) == 1 and value[0] is None)
    return _is_empty_array(value)


def _is_empty_array(value) -> bool:
    return type(value).__module__ == "numpy" and getattr(value, "size", 1) == 0


class _LevelState:
    """The entries, rules and values of one level while its blocks open."""

    def __init__(self, level: Level, given: dict, result: Keywords, context: Mapping):
        self.given = given
        self.result = result
        self.context = context
        self.entries: dict[str, Entry] = {}
        self.rules = list(level.rules)
        self.values: dict = {}  # normalised simple values, raw factor values
        self.tolerated: dict[str, Entry] = {}  # keywords of undetermined blocks
        self.closed: dict[str, list[str]] = {}  # keyword -> conditions of closed blocks
        self.opened_by: dict[str, str] = {}  # keyword -> condition of its open block
        self.pending: list[tuple[BLOC, str]] = []  # unopened blocks, enclosing condition
        self._open(level, condition="")

    def _open(self, level: Level, condition: str) -> None:
        """Activate the keywords of ``level``, opened under ``condition`` ('' if always)."""
        new = {n: e for n, e in level.keywords.items() if n not in self.entries}
        self.entries.update(new)
        for name, entry in new.items():
            if condition:
                self.opened_by[name] = condition
            self._collect(name, entry)
        self.pending.extend((bloc, condition) for bloc in level.blocs.values())

    def _collect(self, name: str, entry: Entry) -> None:
        """Record the given (checked) or default value of a newly active keyword."""
        if isinstance(entry, SIMP):
            if name in self.given:
                self.values[name] = check_simple(entry, self.given[name], self.result, name)
            elif entry.defaut is not None:
                self.values[name] = check_simple(entry, entry.defaut, self.result, name)
        elif isinstance(entry, FACT):
            if name in self.given:
                self.values[name] = self.given[name]
            elif entry.statut in ("d", "c"):
                self.values[name] = [{}]

    def open_blocks(self) -> None:
        """Open blocks until none changes state (blocks may depend on blocks)."""
        changed = True
        while changed:
            changed = False
            scope = ChainMap(self.values, self.context)
            for bloc, prefix in list(self.pending):
                state = bloc.condition.evaluate(scope)
                if state is False:
                    continue
                self.pending.remove((bloc, prefix))
                changed = True
                if state:
                    self.rules.extend(bloc.rules)
                    self._open(bloc, _both(prefix, bloc))
                else:
                    self.tolerated.update(_all_keywords(bloc))
        for bloc, prefix in self.pending:
            self._note_closed(bloc, prefix)

    def _note_closed(self, bloc: BLOC, prefix: str) -> None:
        text = _both(prefix, bloc)
        for name in bloc.keywords:
            self.closed.setdefault(name, []).append(text)
        for inner in bloc.blocs.values():
            self._note_closed(inner, text)

    def present(self) -> set[str]:
        """Keywords given or defaulted (code_aster's rules see the defaults)."""
        return set(self.values)


def _both(prefix: str, bloc: BLOC) -> str:
    return f"{prefix} and {bloc.condition}" if prefix else str(bloc.condition)


def _all_keywords(level: Level) -> dict[str, Entry]:
    found = dict(level.keywords)
    for bloc in level.blocs.values():
        found.update({n: e for n, e in _all_keywords(bloc).items() if n not in found})
    return found


def _validate_level(level: Level, given: Mapping, result: Keywords, context: Mapping) -> Keywords:
    given = {name: value for name, value in given.items() if not _is_undefined(value)}
    state = _LevelState(level, given, result, context)
    state.open_blocks()
    _reject_unexpected(state)
    _check_tolerated(state)
    _check_rules(state)
    _check_mandatory(state)
    _fill(state)
    return result


def _reject_unexpected(state: _LevelState) -> None:
    for name in state.given:
        if name in state.entries or name in state.tolerated:
            continue
        if name in state.closed:
            conditions = ", or with ".join(dict.fromkeys(state.closed[name]))
            raise _fail(state.result, f"not allowed here: only with {conditions}", name)
        raise _fail(state.result, _unknown_message(name, state), name)


def _unknown_message(name: str, state: _LevelState) -> str:
    allowed = list(state.entries) + [n for n in state.tolerated if n not in state.entries]
    close = difflib.get_close_matches(name, allowed, n=1, cutoff=0.6)
    if close:
        return f"unknown keyword, did you mean {close[0]}?"
    if not allowed:
        return "unknown keyword: no keyword is allowed here"
    shown = ", ".join(allowed[:20]) + (", ..." if len(allowed) > 20 else "")
    return f"unknown keyword, expected one of: {shown}"


def _check_tolerated(state: _LevelState) -> None:
    """Keywords of undetermined blocks are type-checked when given."""
    for name, entry in state.tolerated.items():
        if name in state.entries or name not in state.given:
            continue
        if isinstance(entry, SIMP):
            state.values[name] = check_simple(entry, state.given[name], state.result, name)
        else:
            state.values[name] = state.given[name]
        state.entries[name] = entry  # given, so never reported missing


def _check_rules(state: _LevelState) -> None:
    present = state.present()
    for rule in state.rules:
        message = rule.check(present)
        if message:
            raise _fail(state.result, message)


def _check_mandatory(state: _LevelState) -> None:
    for name, entry in state.entries.items():
        if getattr(entry, "mandatory", False) and name not in state.values:
            kind = "factor keyword" if isinstance(entry, FACT) else "keyword"
            message = f"missing mandatory {kind} {name}"
            if name in state.opened_by:
                message += f" (required when {state.opened_by[name]})"
            path, _ = state.result.where(name)
            raise ValidationError(message, state.result.location, path)


def _fill(state: _LevelState) -> None:
    """Store the values in catalogue order, validating factor occurrences."""
    result = state.result
    parent = ChainMap(state.values, state.context)
    for name, entry in state.entries.items():
        if name not in state.values:
            if isinstance(entry, FACT):
                result.absent_factors[name] = (entry, parent)
            continue
        if isinstance(entry, FACT):
            result[name] = validate_factor(entry, state.values[name], result, name, parent)
        else:
            result[name] = state.values[name]
    result.locations = {n: loc for n, loc in result.locations.items() if n in state.given}
    result.given = frozenset(n for n in state.given if dict.__contains__(result, n))
    result.no_effect = frozenset(n for n, e in state.entries.items() if has_no_effect(n, e))


# --- factor keywords ---------------------------------------------------------------------


def _occurrences(value, result: Keywords, name: str) -> list:
    if isinstance(value, dict):
        return [value]
    if isinstance(value, (list, tuple)) and all(isinstance(v, dict) for v in value):
        return list(value)
    raise _fail(
        result, f"expected one or more _F(...) occurrences, got {describe_value(value)}", name
    )


def validate_factor(
    fact: FACT, value, result: Keywords, name: str, context: Mapping
) -> list[Keywords]:
    """Each occurrence of factor keyword ``name`` validated as its own level."""
    if value is Unknown:
        return []
    occurrences = _occurrences(value, result, name)
    _check_count(len(occurrences), fact.min, fact.max, "occurrence", result, name)
    validated = []
    for index, occurrence in enumerate(occurrences, start=1):
        path, fallback = result.where(name)
        child = Keywords(
            path=f"{path}[{index}]", location=getattr(occurrence, "location", None) or fallback
        )
        child.locations.update(getattr(occurrence, "keyword_locations", {}))
        validated.append(_validate_level(fact, occurrence, child, context))
    return validated


def default_occurrence(keywords: Keywords, name: str) -> list[Keywords]:
    """The one occurrence an empty ``_F()`` of the factor keyword ``name``
    would give (its defaults filled), for a factor keyword the call left out
    whose defaults still apply. ``name`` must be a keyword of the call's
    open blocks that the call did not give."""
    fact, parent = keywords.absent_factors[name]
    return validate_factor(fact, [{}], keywords, name, parent)


# --- simple keywords ---------------------------------------------------------------------


def _plural(count: int, noun: str) -> str:
    return f"{count} {noun}" if count == 1 else f"{count} {noun}s"


def _check_count(count: int, low, high, noun: str, result: Keywords, name: str) -> None:
    if high != MANY and count > high:
        message = f"expects at most {_plural(high, noun)}, got {count}"
        raise _fail(result, message, name)
    if count < low:
        raise _fail(result, f"expects at least {_plural(low, noun)}, got {count}", name)


def _items(simp: SIMP, value) -> list:
    """The values given to a simple keyword, as a list."""
    if "C" in simp.types and is_old_complex(value):
        return [value]
    if isinstance(value, (list, tuple)):
        return list(value)
    return [value]


def check_simple(simp: SIMP, raw, result: Keywords, name: str):
    """A simple keyword's value checked and shaped: scalar (max 1) or tuple."""
    value = plain(raw)
    if value is Unknown:
        return Unknown
    items = _items(simp, value)
    _check_count(len(items), simp.min, simp.max, "value", result, name)
    checked = []
    for index, item in enumerate(items, start=1):
        prefix = f"value {index}: " if len(items) > 1 else ""
        try:
            checked.append(_check_item(simp, item))
        except TypeMismatch as mismatch:
            raise _fail(result, f"{prefix}{mismatch}", name) from None
    return tuple(checked) if simp.is_list else checked[0]


def _check_item(simp: SIMP, item):
    value = accept(simp.types, item)
    if value is Unknown:
        return value
    if simp.into is not None:
        _check_into(simp.into, value)
    _check_bounds(simp, value)
    return value


def _check_into(into: tuple, value) -> None:
    try:
        if value in into:
            return
    except TypeError:
        pass
    choices = ", ".join(map(repr, into))
    message = f"{value!r} is not one of: {choices}"
    texts = [c for c in into if isinstance(c, str)]
    if isinstance(value, str):
        close = difflib.get_close_matches(value, texts, n=1, cutoff=0.6)
        if not close:  # case slips (newmark for NEWMARK) are common in decks
            close = [c for c in texts if c.upper() == value.upper()]
        if close:
            message += f", did you mean {close[0]!r}?"
    raise TypeMismatch(message)


def _check_bounds(simp: SIMP, value) -> None:
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return
    low, high = simp.val_min, simp.val_max
    if low is not None:
        below = value < low if simp.val_min_included else value <= low
        if below:
            sign = ">=" if simp.val_min_included else ">"
            raise TypeMismatch(f"expected a value {sign} {low!r}, got {value!r}")
    if high is not None:
        above = value > high if simp.val_max_included else value >= high
        if above:
            sign = "<=" if simp.val_max_included else "<"
            raise TypeMismatch(f"expected a value {sign} {high!r}, got {value!r}")
