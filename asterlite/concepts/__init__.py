"""The data types commands hand to each other (code_aster's "concepts").

Each class names the code_aster types it satisfies in ``aster_types`` (its own
type first, then broader ones such as ``resultat_sdaster``); the catalogue
checks keyword values against those names without importing this package's
numerical modules. Deck code may only call the methods listed in
``deck_methods``.
"""

from asterlite.concepts.base import Concept, Placeholder

__all__ = ["Concept", "Placeholder"]
