"""The catalogue vocabulary: commands, simple and factor keywords, blocks.

Catalogues are written as in code_aster::

    DEFI_OBSTACLE = OPER(nom="DEFI_OBSTACLE", sd_prod="table_fonction", reentrant="n",
                         TYPE=SIMP(statut="o", typ="TXM", into=("CERCLE", "PLAN_Y")),
                         b_cercle=BLOC(condition=equal_to("TYPE", "CERCLE"),
                                       RAYON=SIMP(statut="o", typ="R")))

Keyword arguments whose value is a ``SIMP``, ``FACT`` or ``BLOC`` are the
entries of the level; the other (lowercase) arguments are options. Options
code_aster has but asterlite does not use (``op``, ``docu``, ``validators``,
``ang``...) are accepted and ignored so catalogues can follow code_aster's.
"""

from __future__ import annotations

from collections.abc import Callable

from asterlite.catalog import conditions
from asterlite.catalog.conditions import Condition
from asterlite.catalog.rules import Rule

STATUTS = ("o", "f", "d", "c")
MANY = "**"  # code_aster's spelling of "no upper bound"


def _check_statut(statut: str, owner: str) -> str:
    if statut not in STATUTS:
        raise TypeError(f"{owner}: statut must be one of {STATUTS}, got {statut!r}")
    return statut


def _check_count(value, what: str, owner: str) -> int | str:
    if value == MANY or (isinstance(value, int) and value >= 0):
        return value
    raise TypeError(f"{owner}: {what} must be a non-negative int or '**', got {value!r}")


def _as_tuple(value) -> tuple:
    if value is None:
        return ()
    return tuple(value) if isinstance(value, (list, tuple)) else (value,)


def _check_rules(regles, owner: str) -> tuple[Rule, ...]:
    rules = _as_tuple(regles)
    for rule in rules:
        if not isinstance(rule, Rule):
            raise TypeError(f"{owner}: regles must hold rules such as UN_PARMI, got {rule!r}")
    return rules


class Entry:
    """Something that may appear in a level: a simple or factor keyword, or a block."""


class SIMP(Entry):
    """A simple keyword: one value or a list of values of given types."""

    def __init__(
        self,
        statut: str = "f",
        typ=None,
        defaut=None,
        into=None,
        min: int = 1,  # noqa: A002 - code_aster's option name
        max: int | str = 1,  # noqa: A002
        val_min=None,
        val_max=None,
        val_min_included: bool = True,
        val_max_included: bool = True,
        fr: str = "",
        no_effect: str = "",
        **ignored,
    ):
        if typ is None:
            raise TypeError("SIMP needs typ=")
        self.statut = _check_statut(statut, "SIMP")
        self.types: tuple = _as_tuple(typ)
        self.defaut = defaut
        self.into: tuple | None = _as_tuple(into) if into is not None else None
        self.min = _check_count(min, "min", "SIMP")
        self.max = _check_count(max, "max", "SIMP")
        self.val_min = val_min
        self.val_max = val_max
        self.val_min_included = val_min_included
        self.val_max_included = val_max_included
        self.fr = fr
        self.no_effect = no_effect  # why the keyword changes no result, if it does not

    @property
    def mandatory(self) -> bool:
        return self.statut == "o"

    @property
    def is_list(self) -> bool:
        """True when the validated value is a tuple (max other than 1)."""
        return self.max != 1

    def __repr__(self) -> str:
        return f"SIMP(statut={self.statut!r}, typ={self.types!r})"


# Keywords that change no result wherever they appear, and why. A command need
# not read them; any other keyword a deck gives must be used or refused.
NO_EFFECT_ANYWHERE = {
    "INFO": "verbosity of code_aster's message file",
    "TITRE": "title of the concept, printed only in code_aster's listings",
}


def has_no_effect(name: str, entry: Entry) -> bool:
    """True when giving ``name`` cannot change a result: the catalogue says so
    (``no_effect=``), or the keyword is mandatory with a single allowed value,
    so that the validated call already says all it says."""
    if getattr(entry, "no_effect", "") or name in NO_EFFECT_ANYWHERE:
        return True
    return (
        isinstance(entry, SIMP)
        and entry.mandatory
        and entry.into is not None
        and len(entry.into) == 1
    )


class Level(Entry):
    """Something holding entries and rules: a command, a factor keyword, a block."""

    def __init__(self, owner: str, regles, entries: dict):
        self.rules = _check_rules(regles, owner)
        self.entries: dict[str, Entry] = {}
        for name, entry in entries.items():
            if name == "reuse":  # code_aster lists it; asterlite passes reuse apart
                continue
            if isinstance(entry, Entry) and not isinstance(entry, Command):
                self.entries[name] = entry
            elif name.isupper():
                raise TypeError(f"{owner}: keyword {name} must be a SIMP, FACT or BLOC")
            # else: a code_aster option asterlite ignores (docu, ang, UIinfo...)

    @property
    def keywords(self) -> dict[str, Entry]:
        """The SIMP and FACT entries written directly at this level."""
        return {n: e for n, e in self.entries.items() if not isinstance(e, BLOC)}

    @property
    def blocs(self) -> dict[str, BLOC]:
        return {n: e for n, e in self.entries.items() if isinstance(e, BLOC)}


class FACT(Level):
    """A factor keyword: occurrences ``_F(...)`` each holding keywords."""

    def __init__(
        self,
        statut: str = "f",
        min: int = 1,  # noqa: A002
        max: int | str = 1,  # noqa: A002
        regles=(),
        fr: str = "",
        no_effect: str = "",
        **entries,
    ):
        super().__init__("FACT", regles, entries)
        self.statut = _check_statut(statut, "FACT")
        self.min = _check_count(min, "min", "FACT")
        self.max = _check_count(max, "max", "FACT")
        self.fr = fr
        self.no_effect = no_effect

    @property
    def mandatory(self) -> bool:
        return self.statut == "o"

    def __repr__(self) -> str:
        return f"FACT(statut={self.statut!r}, {', '.join(self.entries)})"


def _as_condition(condition) -> Condition:
    """A Condition from a Condition, a callable, or a code_aster condition string."""
    if isinstance(condition, Condition):
        return condition
    if isinstance(condition, str):
        return _string_condition(condition)
    if callable(condition):
        return Condition(condition, getattr(condition, "__name__", "condition"))
    raise TypeError(f"BLOC: condition must be built with equal_to, exists... got {condition!r}")


def _string_condition(source: str) -> Condition:
    """code_aster writes conditions as strings such as ``\"\"\"exists('A')\"\"\"``."""
    text = " ".join(source.split())
    code = compile(text, "<BLOC condition>", "eval")
    helpers = ("equal_to", "is_in", "exists", "absent", "greater_than", "less_than")

    def bound(helper, values):
        # each helper evaluates against this level so ``and``/``or`` work on bools
        return lambda *args: helper(*args).evaluate(values)

    def test(values) -> bool | None:
        scope = {name: bound(getattr(conditions, name), values) for name in helpers}
        scope["value"] = lambda name, default="": values.get(name, default)
        return bool(eval(code, {"__builtins__": {}}, scope))  # catalogue text, not deck text

    return Condition(test, text)


class BLOC(Level):
    """Keywords allowed only when ``condition`` holds on the level's values."""

    def __init__(self, condition, regles=(), fr: str = "", **entries):
        super().__init__("BLOC", regles, entries)
        self.condition = _as_condition(condition)
        self.fr = fr

    def __repr__(self) -> str:
        return f"BLOC({self.condition}, {', '.join(self.entries)})"


def _level_keyword_names(level: Level):
    for name, entry in level.entries.items():
        if isinstance(entry, BLOC):
            yield from _level_keyword_names(entry)
        else:
            yield name


SdProd = str | Callable[..., str | None] | None


class Command(Level):
    """A command: ``OPER`` (makes a concept), ``PROC`` (nothing), ``MACRO``."""

    kind = "command"

    def __init__(
        self,
        nom: str,
        sd_prod: SdProd = None,
        reentrant: str = "n",
        fr: str = "",
        regles=(),
        op=None,
        extra_keywords: bool = False,
        **entries,
    ):
        super().__init__(nom, regles, entries)
        # FORMULE-like commands take arbitrary extra keywords (names their
        # expression refers to); the dispatcher sets those apart before validating.
        self.extra_keywords = extra_keywords
        if reentrant not in ("n", "o", "f"):
            raise TypeError(f"{nom}: reentrant must be 'n', 'o' or 'f', got {reentrant!r}")
        self.nom = nom
        self.sd_prod = sd_prod
        self.reentrant = reentrant
        self.fr = fr

    @property
    def name(self) -> str:
        return self.nom

    def keyword_names(self) -> tuple[str, ...]:
        """Every keyword the command declares at its top level, blocs included."""
        names = []
        for name, entry in self.entries.items():
            if isinstance(entry, BLOC):
                names += list(_level_keyword_names(entry))
            else:
                names.append(name)
        return tuple(names)

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.nom})"


class OPER(Command):  # noqa: N801 - code_aster's name
    """A command producing a concept."""

    kind = "operator"


class PROC(Command):  # noqa: N801
    """A command producing nothing."""

    kind = "procedure"

    def __init__(self, nom: str, fr: str = "", regles=(), op=None, **entries):
        entries.pop("sd_prod", None)
        reentrant = entries.pop("reentrant", "n")
        super().__init__(nom, None, reentrant, fr, regles, op, **entries)


class MACRO(Command):  # noqa: N801
    """A command that may produce a concept and ``CO`` outputs."""

    kind = "macro"
