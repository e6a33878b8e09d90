"""Is a command call valid code_aster N? Every finding of a call, in one pass.

:func:`check_call` follows code_aster's own syntax checker
(``code_aster/Cata/Language/SyntaxChecker.py`` and ``SyntaxObjects.py``)
over the language data of the deck's version:

1. defaults are added level by level as code_aster adds them: simple
   keywords, then factor keywords (each occurrence with the defaults of its
   own level), then the blocks whose condition holds on what is known so
   far (a block's defaults stay inside it);
2. each level (the command, each factor occurrence) is then checked: the
   keywords given (a keyword of the level itself, else of a block whose
   condition holds on the level's values seen over the command's), each
   value (type, count, ``into``, ``val_min``/``val_max``, validators), the
   rules of the level and of its open blocks, and the mandatory keywords.

Where code_aster stops at the first error, every one is reported, the root
first: at each level unknown keywords (with a close match from the
version's vocabulary of that level), then keywords of closed blocks, then
the values, then the rules and mandatory keywords, which an unknown keyword
often breaks in turn.

Values ``asterlite check`` did not compute (``Unknown``, concepts of untold
type) pass every check; a block whose condition depends on one is
undetermined: its keywords are accepted, neither required nor defaulted.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field

from asterlite.catalog.language import expression
from asterlite.catalog.language.expression import UNDETERMINED, Scope, holds
from asterlite.catalog.language.model import Language
from asterlite.catalog.language.value_checks import (
    _bounds_problem,
    _in_choices,
    _into_message,
    _is_int,
    _is_output,
    _is_real,
    _names,
    _plain,
    _rule_message,
    _unit_number,
    _validator_problem,
    decode,
    is_undefined,
)
from asterlite.catalog.values import describe_types, describe_value
from asterlite.errors import Location, ValidationError
from asterlite.lang.values import CO, CallSite, Unknown

MANY = "**"
TEXT_TYPES = frozenset({"TXM", "Fichier", "", "Sauvegarde"})
ANY_TYPES = frozenset({"any", "not_checked"})


@dataclass
class CallCheck:
    """What :func:`check_call` found: the findings (root causes first), the
    keywords with code_aster's defaults (for the result type), the type of
    the result (a name, a set of possible names, or None) and the CO
    outputs it types."""

    findings: list = field(default_factory=list)
    keywords: dict = field(default_factory=dict)
    result: object = None
    outputs: dict = field(default_factory=dict)


# ------------------------------------------------------------- values


def _is_sequence(value) -> bool:
    return isinstance(value, (list, tuple)) or (
        type(value).__module__ == "numpy" and type(value).__name__ == "ndarray"
    )


def _force_list(value) -> list:
    value = _plain(value)
    return list(value) if isinstance(value, (list, tuple)) else [value]


def _old_complex(value):
    if isinstance(value, (list, tuple)) and len(value) == 3 and value[0] in ("RI", "MP"):
        try:
            if value[0] == "RI":
                return complex(value[1], value[2])
            phase = value[2] * math.pi / 180.0
            return complex(value[1] * math.cos(phase), value[1] * math.sin(phase))
        except TypeError:
            return value
    return value


def concept_types(value):
    """The code_aster types a concept may have: a tuple (most specific first),
    "any" when it could be of any type, None for a value that is no concept."""
    language = getattr(value, "language_types", None)  # set by asterlite's check
    if language is not None:
        return language
    types = getattr(value, "aster_types", None)
    if types is None:
        return None
    if "*" in types:
        return "any"
    return tuple(types)


def describe(value) -> str:
    return describe_value(value)


# ------------------------------------------------------------ the checker


def check_call(
    language: Language,
    name: str,
    kwargs: dict,
    site: CallSite | None = None,
    *,
    reuse=None,
) -> CallCheck:
    """Check a call of command ``name`` against ``language``."""
    site = site or CallSite()
    command = language.command(name)
    checker = _Checker(language, name, command, site)
    return checker.run(kwargs, reuse)


class _Level:
    """One level being checked: its definition, values and where it is."""

    def __init__(self, spec: dict, user: dict, given: set, path: str, locations: dict, where):
        self.spec = spec
        self.user = user  # values with defaults, as code_aster sees them
        self.given = given  # names the deck wrote
        self.path = path
        self.locations = locations
        self.location = where


class _Checker:
    def __init__(self, language: Language, name: str, command: dict, site: CallSite):
        self.language = language
        self.name = name
        self.command = command
        self.site = site
        self.findings: list[ValidationError] = []
        # keyword names code_aster's compat_syntax hook of the command reads or
        # sets (old spellings it converts before checking)
        self.compat = frozenset((command or {}).get("legacy", ()))
        # code_aster 13-15's checker reads a keyword's max as given (none: no
        # limit on a sequence's length); from 16 on it defaults to 1
        self.count_max_default = None if 13 <= language.version <= 15 else 1
        # and a factor keyword without max= any number of occurrences (15's
        # SyntaxChecker: 1e9); from 16 on one
        self.factor_max_default = MANY if 13 <= language.version <= 15 else 1

    # ------------------------------------------------------------ findings
    def fail(self, level: _Level, message: str, keyword: str | None = None) -> None:
        path = f"{level.path}/{keyword}" if keyword else level.path
        location = level.locations.get(keyword, level.location) if keyword else level.location
        self.findings.append(ValidationError(message, location, path))

    # ---------------------------------------------------------------- run
    def run(self, kwargs: dict, reuse) -> CallCheck:
        result = CallCheck(findings=self.findings)
        # reuse, and what the command's wrapper takes out before checking
        taken = {"reuse", *(self.command or {}).get("supervisor", ())}
        kwargs = {k: v for k, v in kwargs.items() if k not in taken}
        top = _Level(
            self.command,
            {},
            set(),
            self.name,
            dict(self.site.keyword_locations),
            self.site.location,
        )
        if self.command.get("kind") == "FORM":
            # FORMULE takes the names its expression uses as extra keywords
            known = set(_vocabulary(self.command))
            kwargs = {k: v for k, v in kwargs.items() if k in known}
        user = {k: _copy(v) for k, v in kwargs.items() if not is_undefined(v)}
        top.user, top.given = user, set(user)
        self._check_reuse(top, reuse)
        self._add_defaults(self.command, user, {})
        self._check_level(top, context=user, command_level=True)
        result.keywords = user
        if not self.findings:
            self._result_type(result, user)
        return result

    def _check_reuse(self, level: _Level, reuse) -> None:
        if reuse is None:
            return
        reentrant = str(self.command.get("reentrant", "n")).split(":")[0]
        if reentrant not in ("o", "f"):
            self.fail(level, "reuse= is not allowed: this command always makes a new concept")

    # ------------------------------------------------------------ defaults
    def _add_defaults(self, spec: dict, user: dict, parent: dict) -> None:
        """code_aster's addDefaultKeywords, on ``user`` in place."""
        context = dict(parent)
        entries = spec.get("entries", {})
        for key, entry in _by_kind(entries):
            kind = entry["k"]
            if kind == "S":
                value = user.get(key, _default(entry))
                if value is None:
                    continue
                if _is_list(entry) and not _is_sequence(value) and value is not Unknown:
                    value = [value]  # (an uncomputed value may be a whole list)
                user[key] = value
                context[key] = value
            elif kind == "F":
                value = user.get(key)
                if value is None:
                    value = _fact_default(entry)
                if value is None:
                    continue
                if isinstance(value, (list, tuple)):
                    for occurrence in value:
                        if isinstance(occurrence, dict):
                            self._add_defaults(entry, occurrence, context)
                elif isinstance(value, dict):
                    self._add_defaults(entry, value, context)
                    if _is_list(entry):
                        value = [value]
                user[key] = value
                context[key] = value
            elif self._enabled(entry, context) is True:
                self._add_defaults(entry, user, context)

    # ------------------------------------------------------------ blocks
    def _enabled(self, bloc: dict, context: dict) -> bool | None:
        condition = bloc.get("condition")
        if not condition or condition == ["unread"]:
            return None
        scope = Scope(context, self._type_of, _is_output)
        return holds(condition, scope)

    def _type_of(self, value):
        types = concept_types(value)
        if types is None:
            return None
        if types == "any" or (len(types) != 1 and getattr(value, "language_types", None)):
            return UNDETERMINED  # one of several types: the condition cannot tell
        for name in types:  # the most specific type the language knows
            if self.language.is_type(name):
                return name
        return types[0]

    def _walk_blocks(self, spec: dict, context: dict):
        """(entries of the level and of its open blocks, undetermined blocks'
        entries, closed blocks' entries with their conditions)."""
        open_entries: dict = {}  # key -> every definition (several blocks may define it)
        tolerated: dict = {}
        closed: dict = {}
        rules: list = list(spec.get("rules", ()))

        def visit(level: dict, state: str, conditions: tuple) -> None:
            for key, entry in level.get("entries", {}).items():
                if entry["k"] != "B":
                    if state == "open":
                        open_entries.setdefault(key, []).append(entry)
                    elif state == "maybe":
                        tolerated.setdefault(key, []).append(entry)
                    else:
                        closed.setdefault(key, []).append(conditions)
                    continue
                inner = self._enabled(entry, context) if state != "closed" else False
                both = (*conditions, entry.get("condition") or ["c", "?"])
                if state == "open" and inner is True:
                    rules.extend(entry.get("rules", ()))
                    visit(entry, "open", both)
                elif state != "closed" and inner is not False:
                    visit(entry, "maybe", both)  # undetermined here or above
                else:
                    visit(entry, "closed", both)

        visit(spec, "open", ())
        return open_entries, tolerated, closed, rules

    # ------------------------------------------------------------- a level
    def _check_level(self, level: _Level, context: dict, command_level: bool = False) -> None:
        """Check one level: the command (``context`` its own values) or a
        factor occurrence (``context`` the command's values)."""
        scope_values = dict(context)
        scope_values.update(level.user)
        open_entries, tolerated, closed, rules = self._walk_blocks(level.spec, scope_values)
        vocabulary = _vocabulary(level.spec)
        legacy = self.compat
        unknown, elsewhere = [], []
        for key in level.user:
            if key not in level.given:
                continue
            if key in open_entries or key in tolerated:
                continue
            if key in closed:
                elsewhere.append(key)
            elif key not in legacy:
                unknown.append(key)
        for key in unknown:  # root causes first
            self.fail(level, _unknown_message(key, vocabulary, self.language), key)
        for key in elsewhere:
            texts = (
                " and ".join(expression.readable(part) for part in c if part != ["c", True])
                for c in closed[key]
            )
            conditions = ", or with ".join(dict.fromkeys(texts))
            self.fail(level, f"not allowed here: only with {conditions}", key)
        for key in list(level.user):
            definitions = open_entries.get(key, []) + tolerated.get(key, [])
            if not definitions:
                continue
            value = level.user[key]
            if definitions[0].get("statut") == "c" and key not in level.given:
                continue  # a hidden keyword's default: the supervisor's, not the deck's
            self._check_definitions(level, key, definitions, value, context)
        if any(key in legacy and key not in vocabulary for key in level.given):
            return  # an old spelling code_aster's compat_syntax converts: not judged further
        self._check_rules(level, [r for r in rules if not legacy.intersection(_names(r))], unknown)
        self._check_mandatory(level, level.spec, scope_values, "")

    def _check_definitions(self, level, key, definitions, value, context) -> None:
        """A keyword that blocks open or undetermined define more than once:
        the value is valid when one definition takes it (else the first
        definition's findings)."""
        start = len(self.findings)
        first = None
        for entry in {id(e): e for e in definitions}.values():
            if entry["k"] == "S":
                self._check_simple(level, key, entry, value)
            else:
                self._check_factor(level, key, entry, value, context)
            if len(self.findings) == start:
                return
            if first is None:
                first = self.findings[start:]
            del self.findings[start:]
        self.findings.extend(first or ())

    def _check_rules(self, level: _Level, rules: list, unknown: list) -> None:
        for rule in rules:
            message = _rule_message(rule, level.user)
            if message:
                self.fail(level, message)

    def _check_mandatory(self, level: _Level, spec: dict, values: dict, condition: str) -> None:
        for key, entry in spec.get("entries", {}).items():
            if entry["k"] == "B":
                state = self._enabled(entry, values)
                if state is True:
                    text = expression.readable(entry.get("condition") or ["c", "?"])
                    both = f"{condition} and {text}" if condition else text
                    self._check_mandatory(level, entry, values, both)
                continue
            if key in self.compat:
                continue  # code_aster's compat_syntax may set it
            if entry.get("statut") == "o" and is_undefined(level.user.get(key)):
                kind = "factor keyword" if entry["k"] == "F" else "keyword"
                message = f"missing mandatory {kind} {key}"
                if condition:
                    message += f" (required when {condition})"
                path = f"{level.path}/{key}"
                self.findings.append(ValidationError(message, level.location, path))

    # ------------------------------------------------------------ factors
    def _check_factor(self, level: _Level, key: str, entry: dict, value, context: dict) -> None:
        if value is Unknown:
            return
        if isinstance(value, dict):
            occurrences = [value]
        elif isinstance(value, (list, tuple)) and all(isinstance(v, dict) for v in value):
            occurrences = list(value)
        else:
            self.fail(
                level, f"expected one or more _F(...) occurrences, got {describe(value)}", key
            )
            return
        low, high = entry.get("min", 0), entry.get("max", self.factor_max_default)
        if len(occurrences) < low:
            self.fail(
                level, f"expects at least {_count(low, 'occurrence')}, got {len(occurrences)}", key
            )
        if high != MANY and len(occurrences) > high:
            self.fail(
                level, f"expects at most {_count(high, 'occurrence')}, got {len(occurrences)}", key
            )
        for index, occurrence in enumerate(occurrences, start=1):
            given = getattr(occurrence, "given_names", None)
            if given is None:
                given = set(occurrence)
            locations = getattr(occurrence, "keyword_locations", {}) or {}
            where = getattr(occurrence, "location", None) or level.locations.get(
                key, level.location
            )
            child = _Level(
                entry,
                occurrence,
                given,
                f"{level.path}/{key}[{index}]",
                dict(locations),
                where,
            )
            self._check_level(child, context)

    # ------------------------------------------------------------ simples
    def _check_simple(self, level: _Level, key: str, entry: dict, value) -> None:
        value = _plain(value)
        if value is Unknown:
            return
        types = entry.get("typ", ())
        complex_allowed = "C" in types
        high = entry.get("max", 1)
        # code_aster counts the values of a sequence only (a lone value is
        # never too few); up to 15 a keyword without max= takes any number
        counted = _is_sequence(value)
        count_max = entry.get("max", self.count_max_default)
        if high == 1 and _is_sequence(value) and len(value) == 1:
            value = value[0]
        elif high != 1 and not _is_sequence(value):
            value = [value]
        elif high != 1 and complex_allowed and value and isinstance(value[0], str):
            value = [value]  # ("RI", re, im) given alone
        if complex_allowed:
            value = _old_complex(value)
        if _is_sequence(value):
            low = entry.get("min")
            if counted and count_max not in (MANY, None) and len(value) > count_max:
                self.fail(
                    level, f"expects at most {_count(count_max, 'value')}, got {len(value)}", key
                )
            if counted and low is not None and len(value) < low:
                self.fail(level, f"expects at least {_count(low, 'value')}, got {len(value)}", key)
            items = list(value)
        else:
            items = [value]
        for index, item in enumerate(items, start=1):
            prefix = f"value {index}: " if len(items) > 1 else ""
            message = self._item_problem(entry, _old_complex(item) if complex_allowed else item)
            if message:
                self.fail(level, prefix + message, key)
                return
        for validator in entry.get("validators", ()):
            message = _validator_problem(validator, items)
            if message:
                self.fail(level, message, key)

    def _item_problem(self, entry: dict, item) -> str | None:
        item = _plain(item)
        if item is Unknown:
            return None
        types = entry.get("typ", ())
        if "UNITE" in types:
            unit = _unit_number(item)
            if unit is None:
                return f"expected a logical unit (an integer), got {describe(item)}"
            item = unit
        elif not self._type_ok(types, item):
            return f"expected {self._describe_types(types)}, got {describe(item)}"
        into = entry.get("into")
        if into is not None and not _in_choices(item, into):
            return _into_message(item, into)
        return _bounds_problem(entry, item)

    def _type_ok(self, types, item) -> bool:
        if any(t in ANY_TYPES for t in types):
            return True
        kinds = concept_types(item)
        for name in types:
            if name in TEXT_TYPES or self._is_entity(name):
                if isinstance(item, str):
                    return True
            elif name == "I":
                if _is_int(item):
                    return True
            elif name == "R":
                if _is_real(item):
                    return True
            elif name == "C":
                if _is_real(item) or isinstance(item, complex):
                    return True
            elif name == "L":
                if isinstance(item, bool):
                    return True
            elif name == "CO" or self.language.is_subtype(name, "CO"):
                if isinstance(item, CO) or kinds is not None:
                    return True
            elif isinstance(item, CO):
                # a CO a macro typed earlier: code_aster's CO object became its result
                return True
            elif kinds == "any":
                return True
            elif kinds is not None and any(self._satisfies(k, name, item) for k in kinds):
                return True
        return False

    def _satisfies(self, kind: str, expected: str, item) -> bool:
        if self.language.is_type(kind):
            return self.language.is_subtype(kind, expected)
        # a concept type the language does not name: ask the concept itself
        satisfies = getattr(item, "satisfies", None)
        return bool(satisfies and satisfies(expected))

    def _is_entity(self, name: str) -> bool:
        return self.language.is_type(name) and self.language.is_subtype(name, "GEOM")

    def _describe_types(self, types) -> str:
        names = tuple("TXM" if self._is_entity(t) else t for t in types)
        return describe_types(names)

    # --------------------------------------------------------- result type
    def _result_type(self, result: CallCheck, user: dict) -> None:
        sd_prod = self.command.get("sd_prod")
        if sd_prod is None:
            return
        if "type" in sd_prod:
            result.result = sd_prod["type"]
            return
        if "depends" in sd_prod:
            result.result = set(sd_prod["depends"]) or None
            return
        scope = Scope(user, self._type_of, _is_output)
        possible: set = set()
        for row in sd_prod.get("table", ()):
            condition, outcome = row[0], row[1]
            try:
                state = expression.evaluate(condition, scope)
            except (expression.Undefined, expression.Failed):
                continue
            if state is not UNDETERMINED and not expression._truth(state):
                continue
            self._type_outputs(row[2] if len(row) > 2 else (), scope, result)
            named = self._outcome(outcome, scope, sd_prod)
            if state is UNDETERMINED:
                possible |= named if isinstance(named, set) else {named}
                continue
            if isinstance(named, str) and not possible:
                result.result = named
                return
            possible |= named if isinstance(named, set) else {named}
            break
        possible.discard(None)
        if "error" in possible and possible == {"error"}:
            self.findings.append(
                ValidationError(
                    "code_aster cannot type the result of this call", self.site.location, self.name
                )
            )
            return
        possible.discard("error")
        if len(possible) == 1:
            result.result = possible.pop()
        else:
            result.result = possible or set(sd_prod.get("types", ())) or None

    def _outcome(self, outcome, scope: Scope, sd_prod: dict):
        if isinstance(outcome, dict):
            return "error"
        try:
            value = expression.evaluate(outcome, scope)
        except (expression.Undefined, expression.Failed):
            return "error"
        if isinstance(value, expression.TypeValue) and not isinstance(value, expression.PyType):
            return value.name
        if value is None:
            return None
        if value is UNDETERMINED or value is Unknown:
            # AsType of a value check did not compute: some concrete type the
            # request's list (abstract parents, resultat_sdaster) stands for
            return "assd"
        return set(sd_prod.get("types", ())) or None

    def _type_outputs(self, outputs, scope: Scope, result: CallCheck) -> None:
        for condition, target, kind in outputs:
            if holds(condition, scope) is not True:
                continue
            try:
                output = expression.evaluate(target, scope)
                type_value = expression.evaluate(kind, scope)
            except (expression.Undefined, expression.Failed):
                continue
            if isinstance(output, CO) and isinstance(type_value, expression.TypeValue):
                result.outputs[output.name] = type_value.name


# ------------------------------------------------------------------ helpers


def _copy(value):
    """A copy of a deck value code_aster may add defaults to (factor occurrences)."""
    value = _plain(value) if type(value).__module__ == "numpy" else value
    if isinstance(value, dict):
        twin = _Occurrence(((k, _copy(v)) for k, v in value.items() if not is_undefined(v)))
        twin.location = getattr(value, "location", None)
        twin.keyword_locations = getattr(value, "keyword_locations", {})
        twin.given_names = set(twin)
        return twin
    if isinstance(value, list):
        return [_copy(v) for v in value]
    if isinstance(value, tuple):
        return tuple(_copy(v) for v in value)
    return value


class _Occurrence(dict):
    """A factor occurrence being checked (the deck's own is left untouched)."""

    location: Location | None = None
    keyword_locations: dict = {}
    given_names: set = set()


def _by_kind(entries: dict):
    """code_aster's iterItemsByType: simple keywords, factor keywords, blocks."""
    for kind in ("S", "F", "B"):
        for key, entry in entries.items():
            if entry["k"] == kind:
                yield key, entry


def _is_list(entry: dict) -> bool:
    return entry.get("max", 1) != 1


def _default(entry: dict):
    value = entry.get("defaut")
    return decode(value) if value is not None else None


def _fact_default(entry: dict):
    if entry.get("statut", "f") not in ("c", "d"):
        return None
    return [_Occurrence()] if _is_list(entry) else _Occurrence()


def _vocabulary(spec: dict) -> list[str]:
    """Every keyword of a level, its blocks' included, in catalogue order
    (kept in the level's data once made)."""
    found = spec.get("\0vocabulary")
    if found is None:
        found = spec["\0vocabulary"] = _make_vocabulary(spec)
    return found


def _make_vocabulary(spec: dict) -> list[str]:
    found = []

    def visit(level: dict) -> None:
        for key, entry in level.get("entries", {}).items():
            if entry["k"] == "B":
                visit(entry)
            elif key not in found:
                found.append(key)

    visit(spec)
    return found


def _unknown_message(key: str, vocabulary: list[str], language: Language) -> str:
    close = difflib.get_close_matches(key, vocabulary, n=1, cutoff=0.6)
    if not close:
        close = [k for k in vocabulary if k.upper() == key.upper()]
    if close:
        return f"unknown keyword, did you mean {close[0]}?"
    if not vocabulary:
        return "unknown keyword: no keyword is allowed here"
    shown = ", ".join(vocabulary[:20]) + (", ..." if len(vocabulary) > 20 else "")
    return f"unknown keyword, expected one of: {shown}"


def _count(number: int, noun: str) -> str:
    return f"{number} {noun}" if number == 1 else f"{number} {noun}s"
