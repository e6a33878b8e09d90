"""Values the deck language creates besides plain Python data.

These types are shared by the evaluator (which creates them), the catalogue
validator (which recognises them) and the runtime (which consumes them).
Nothing here imports numpy.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from asterlite.errors import DeckRuntimeError, Location


@dataclass(frozen=True)
class CallSite:
    """Where a call happens in the deck, and the name it is assigned to."""

    location: Location | None = None
    keyword_locations: dict[str, Location] = field(default_factory=dict)
    assigned_name: str | None = None


class DeckCallable:
    """An object the deck may call; the evaluator passes the call site."""

    def deck_call(self, args: list, kwargs: dict, site: CallSite):
        raise NotImplementedError


class FactorDict(dict):
    """One occurrence of a factor keyword, as written with ``_F(...)``."""

    def __init__(self, *args, location: Location | None = None, keyword_locations=None, **kw):
        super().__init__(*args, **kw)
        self.location = location
        self.keyword_locations: dict[str, Location] = dict(keyword_locations or {})


class FactorBuilder(DeckCallable):
    """The ``_F`` builtin: keyword arguments only."""

    def deck_call(self, args: list, kwargs: dict, site: CallSite) -> FactorDict:
        if args:
            raise DeckRuntimeError("_F takes keyword arguments only", site.location)
        return FactorDict(kwargs, location=site.location, keyword_locations=site.keyword_locations)


class CO:
    """``CO("NAME")``: a name a command will bind an output concept to."""

    def __init__(self, name: str):
        self.name = name

    def __repr__(self) -> str:
        return f"CO({self.name!r})"


def co_outputs(value) -> list[CO]:
    """Every CO(...) output name inside a keyword tree."""
    if isinstance(value, CO):
        return [value]
    if isinstance(value, dict):
        return [co for v in value.values() for co in co_outputs(v)]
    if isinstance(value, (list, tuple)):
        return [co for v in value for co in co_outputs(v)]
    return []


class COBuilder(DeckCallable):
    """The ``CO`` builtin."""

    def deck_call(self, args: list, kwargs: dict, site: CallSite) -> CO:
        if len(args) != 1 or kwargs or not isinstance(args[0], str) or not args[0].isidentifier():
            raise DeckRuntimeError('CO takes one name, as in CO("MATR")', site.location)
        return CO(args[0])


class _UnknownType:
    """The value of something ``asterlite check`` does not compute.

    Arithmetic, indexing, calls and attribute access on it give Unknown; it is
    falsy and iterates as empty. The catalogue accepts it for any type.
    """

    _instance = None

    def __new__(cls):
        if cls._instance is None:
            cls._instance = super().__new__(cls)
        return cls._instance

    def __repr__(self) -> str:
        return "<unknown>"

    def __bool__(self) -> bool:
        return False

    def __iter__(self):
        return iter(())

    def __len__(self) -> int:
        return 0

    def __hash__(self) -> int:
        return 0x5EED

    def _unknown(self, *args, **kwargs):
        return self

    # Python-level operations (inside sorted(), numpy object arrays, ...) stay
    # Unknown too, so a check never fails on an uncomputed value.
    __add__ = __radd__ = __sub__ = __rsub__ = __mul__ = __rmul__ = _unknown
    __truediv__ = __rtruediv__ = __floordiv__ = __rfloordiv__ = _unknown
    __mod__ = __rmod__ = __pow__ = __rpow__ = __neg__ = __pos__ = __abs__ = _unknown
    __and__ = __rand__ = __or__ = __ror__ = __xor__ = __rxor__ = __invert__ = _unknown
    __lt__ = __le__ = __gt__ = __ge__ = __eq__ = __ne__ = _unknown
    __getitem__ = __call__ = __round__ = _unknown


Unknown = _UnknownType()


def is_unknown(value) -> bool:
    return value is Unknown


class DeckModule:
    """A module as a deck sees it: a fixed mapping of member names."""

    __slots__ = ("name", "_members", "_loader")

    def __init__(self, name: str, members: dict | None = None, loader=None):
        self.name = name
        self._members = members
        self._loader = loader  # builds the members on first use (numpy)

    @property
    def members(self) -> dict:
        if self._members is None:
            self._members = self._loader()
        return self._members

    def attribute(self, name: str):
        try:
            return self.members[name]
        except KeyError:
            raise DeckRuntimeError(
                f"module '{self.name}' has no attribute '{name}' available in decks"
            ) from None

    def public_names(self) -> dict:
        return {k: v for k, v in self.members.items() if not k.startswith("_") or k == "_F"}

    def __repr__(self) -> str:
        return f"<module '{self.name}'>"
