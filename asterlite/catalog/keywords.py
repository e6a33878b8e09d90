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

    def where(self, keyword: str | None = None) -> tuple[str, Location | None]:
        """(keyword path, best location) for an error about ``keyword``."""
        path = f"{self.path}/{keyword}" if keyword else self.path
        return path, self.locations.get(keyword, self.location) if keyword else self.location

    def factor(self, name: str) -> list[Keywords]:
        """The occurrences of factor keyword ``name`` (empty list if absent)."""
        return self.get(name) or []
