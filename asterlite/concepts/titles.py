"""The title (INTITULE) of each localized nonlinearity of a transient.

code_aster names a ``COMPORTEMENT`` occurrence given without ``INTITULE``
after its relation and its rank among every nonlinearity of the call
(``dtmprep_noli_choc.F90`` §3.3, ``nltype(NL_CHOC) // codent(i, 'D0')``):
the relation padded to 16 characters, then the 1-based rank on 8 digits,
``'DIS_CHOC        00000003'`` for the third. A ``GROUP_MA`` occurrence
makes one nonlinearity per cell, each with its own rank.

Where code_aster gives several nonlinearities the same title (an
``INTITULE`` repeated, or one occurrence over several cells) asterlite
makes them unique with ``_2``, ``_3``... so that every shock of a result
has one name, the same in ``message.log``, ``summary.json``, tables,
``results.h5``, the Python API and ``asterlite plot``. A title is matched
by :func:`same_title`, which ignores the padding (``DIS_CHOC00000003``
names the shock above on a command line).
"""

from __future__ import annotations


def default_title(relation: str, number: int) -> str:
    """code_aster's title of the ``number``-th nonlinearity (1-based)."""
    return f"{relation:<16}{number:08d}"


def unique_titles(titles: list[str]) -> list[str]:
    """The titles in order, a repeated one suffixed ``_2``, ``_3``...
    (the first keeps its title: it is the one code_aster finds by it)."""
    given = {title.strip() for title in titles}
    taken: set[str] = set()
    out = []
    for title in titles:
        name, n = title, 2
        # a suffixed name never takes a title the deck gives another shock
        while name.strip() in taken or (name is not title and name in given):
            name, n = f"{title.strip()}_{n}", n + 1
        taken.add(name.strip())
        out.append(name)
    return out


def compact(title: str) -> str:
    """A title without its blanks (``DIS_CHOC00000003``)."""
    return "".join(title.split())


def same_title(given: str, title: str) -> bool:
    """Whether ``given`` names ``title``: the same, or the same without blanks."""
    return given.strip() == title.strip() or compact(given) == compact(title)
