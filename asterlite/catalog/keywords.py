"""The validated keyword tree handed to a command implementation.

The catalogue validator turns a deck call into a :class:`Keywords` mapping:

- a simple keyword whose catalogue ``max`` is 1 maps to a scalar, one with
  ``max > 1`` (or ``"**"``) to a tuple, even when the deck gave one value;
- a factor keyword maps to a list of :class:`Keywords` (one per occurrence);
- defaults (``statut='d'`` / ``defaut=``) are filled in, including inside
  active ``BLOC``s and inside each factor occurrence;
- optional keywords the deck did not give and that have no default are
  absent: use ``kw.get(name)``.

``path`` is the keyword path for messages (``DYNA_VIBRA/COMPORTEMENT[1]``)
and ``location`` the deck position of the call or ``_F(...)`` occurrence.
Commands never re-validate: they trust types, counts, ``into`` and rules.

The mapping also remembers which keywords the deck *gave* (``given``, set by
the validator) and which the command *read* (``[]``, ``get``, ``in``,
``factor``, ``pop``; iterating over the whole mapping reads everything).
After a command returns, :func:`unread_keywords` lists the given keywords it
never looked at: the runtime refuses those rather than ignore them silently.
"""

from __future__ import annotations

from asterlite.errors import Location


class Keywords(dict):
    """A validated, defaulted keyword mapping with its path and location."""

    def __init__(self, *args, path: str = "", location: Location | None = None, **kwargs):
        super().__init__(*args, **kwargs)
        self.path = path
        self.location = location
        self.locations: dict[str, Location] = {}  # per-keyword positions when known
        self.given: frozenset[str] = frozenset()  # keywords written in the deck
        self.read: set[str] = set()  # keywords the command has looked at
        self.no_effect: frozenset[str] = frozenset()  # catalogue: changes no result
        # factor keywords of the open blocks the call left out: name -> (its
        # catalogue entry, the level's values), for validator.default_occurrence
        self.absent_factors: dict[str, tuple] = {}

    # --- reads are recorded so that an ignored keyword can be refused -------------------
    def __getitem__(self, name):
        self.read.add(name)
        return super().__getitem__(name)

    def get(self, name, default=None):
        self.read.add(name)
        return super().get(name, default)

    def __contains__(self, name) -> bool:
        self.read.add(name)
        return super().__contains__(name)

    def pop(self, name, *default):
        self.read.add(name)
        return super().pop(name, *default)

    def _read_all(self) -> None:
        self.read.update(super().keys())

    def __iter__(self):
        self._read_all()
        return super().__iter__()

    def keys(self):
        self._read_all()
        return super().keys()

    def items(self):
        self._read_all()
        return super().items()

    def values(self):
        self._read_all()
        return super().values()

    def copy(self) -> Keywords:
        """A copy reads nothing: reads of the copy count as reads of this level."""
        twin = Keywords(dict.items(self), path=self.path, location=self.location)
        twin.locations = dict(self.locations)
        twin.given = self.given
        twin.no_effect = self.no_effect
        twin.absent_factors = self.absent_factors
        twin.read = self.read  # shared on purpose
        return twin

    def mark_used(self, *names: str) -> None:
        """Count ``names`` as used without reading them: keywords whose effect is
        what the command does anyway (TOUT_ORDRE: every stored state), or that
        code_aster itself reads and then ignores in this case. Say why at the call."""
        self.read.update(names)

    def peek(self, name, default=None):
        """The value of ``name`` without counting it as used (for logs and summaries)."""
        return super().get(name, default)

    def where(self, keyword: str | None = None) -> tuple[str, Location | None]:
        """(keyword path, best location) for an error about ``keyword``."""
        path = f"{self.path}/{keyword}" if keyword else self.path
        return path, self.locations.get(keyword, self.location) if keyword else self.location

    def factor(self, name: str) -> list[Keywords]:
        """The occurrences of factor keyword ``name`` (empty list if absent)."""
        return self.get(name) or []


def unread_keywords(keywords: Keywords) -> list[tuple[Keywords, str]]:
    """(level, name) of every given keyword never read, through factor occurrences.

    Keywords the catalogue marks as having no effect on results (``INFO``...)
    need not be read. A factor keyword counts as used when one of its
    occurrences was looked at: the keywords inside are then judged one by one.
    """
    found = []
    for name in [n for n in dict.keys(keywords) if n in keywords.given]:
        value = dict.get(keywords, name)
        occurrences = value if _is_occurrences(value) else None
        if name in keywords.no_effect:
            continue
        if name not in keywords.read:
            # a factor whose given keywords all change no result is not owed a read
            if occurrences is None or any(map(unread_keywords, occurrences)):
                found.append((keywords, name))
        elif occurrences is not None:
            for occurrence in occurrences:
                found.extend(unread_keywords(occurrence))
    return found


def _is_occurrences(value) -> bool:
    return isinstance(value, list) and all(isinstance(v, Keywords) for v in value)
