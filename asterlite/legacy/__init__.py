"""Legacy syntax (code_aster 10 to 14): run old decks, and port them.

- :mod:`asterlite.legacy.forms`: the legacy form of each command, by name;
- :mod:`asterlite.legacy.dyna`, :mod:`~asterlite.legacy.modes`,
  :mod:`~asterlite.legacy.misc`: the translations, as tables of renames and
  moves plus small functions;
- :mod:`asterlite.legacy.runtime`: what the dispatcher calls;
- :mod:`asterlite.legacy.v15_names`: code_aster 15's generated object names
  (``"0000001b"``), for decks that quote them;
- :mod:`asterlite.legacy.port`: ``asterlite port``, rewriting a deck's text.
"""

from asterlite.legacy.base import Env, Note, Src, Translation

__all__ = ["Env", "Note", "Src", "Translation"]
