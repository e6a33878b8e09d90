"""What the language data of code_aster 10-12 says, for the version layer.

The old defaults the version layer fills in when it translates a deck of
code_aster 10-12 are read from that version's language data
(``catalogues/language/v11.json``, generated from code_aster's own
catalogue, :mod:`asterlite.catalog.language.legacy_layout`), not written
by hand: ``old_default("MODE_ITER_INV", "CALC_FREQ", "OPTION")`` is what
the code_aster 11 catalogue gave ``CALC_FREQ/OPTION`` when a deck gave none.
"""

from __future__ import annotations

from functools import cache

from asterlite.catalog.language.model import language
from asterlite.catalog.language.value_checks import decode

OLD_VERSION = 11  # the data decks of code_aster 10-12 are read with


@cache
def old_language():
    found = language(OLD_VERSION)
    if found is None:  # the data ships with asterlite: its absence is a broken install
        raise RuntimeError(f"asterlite's language data of code_aster {OLD_VERSION} is missing")
    return found


def old_default(command: str, *path: str):
    """The default code_aster 10-12 gave keyword ``path`` (factor keywords,
    then the keyword) of ``command``: looked for at each level and inside its
    blocks; where several blocks define it, they must agree."""
    data = old_language().command(command)
    if data is None:
        raise LookupError(f"code_aster {OLD_VERSION} has no command {command}")
    levels = [data]
    for name in path:
        levels = [entry for level in levels for entry in _definitions(level, name)]
        if not levels:
            raise LookupError(f"code_aster {OLD_VERSION}'s {command} has no {'/'.join(path)}")
    defaults = {repr(entry.get("defaut")) for entry in levels}
    if len(defaults) != 1 or levels[0].get("defaut") is None:
        raise LookupError(f"code_aster {OLD_VERSION}'s {command}/{'/'.join(path)}: no one default")

    return decode(levels[0]["defaut"])


def _definitions(level: dict, name: str) -> list[dict]:
    """The definitions of keyword ``name`` at ``level``, its blocks' included."""
    found = []
    for key, entry in level.get("entries", {}).items():
        if entry["k"] == "B":
            found += _definitions(entry, name)
        elif key == name:
            found.append(entry)
    return found
