"""Lists of reals and integers (``DEFI_LIST_REEL``, ``DEFI_LIST_ENTI``).

Owner: post-processing. Other rooms read ``values`` (a numpy array).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.concepts.base import Concept


@dataclass(eq=False)
class ListReal(Concept):
    """An ordered list of reals (``listr8_sdaster``), e.g. instants."""

    aster_types = ("listr8_sdaster",)
    deck_methods = frozenset({"getName", "Valeurs", "getValues"})

    values: np.ndarray

    def __post_init__(self) -> None:
        self.values = np.asarray(self.values, dtype=float).ravel()

    def __len__(self) -> int:
        return self.values.size

    def Valeurs(self):  # noqa: N802
        return self.values.tolist()

    def getValues(self):  # noqa: N802
        return self.values.tolist()


@dataclass(eq=False)
class ListInt(Concept):
    """An ordered list of integers (``listis_sdaster``), e.g. NUME_ORDRE."""

    aster_types = ("listis_sdaster",)
    deck_methods = frozenset({"getName", "Valeurs", "getValues"})

    values: np.ndarray

    def __post_init__(self) -> None:
        self.values = np.asarray(self.values, dtype=np.int64).ravel()

    def __len__(self) -> int:
        return self.values.size

    def Valeurs(self):  # noqa: N802
        return self.values.tolist()

    def getValues(self):  # noqa: N802
        return self.values.tolist()


@dataclass(eq=False)
class TimeStepping(Concept):
    """The instants of a nonlinear computation and its failure policy
    (``list_inst``, DEFI_LIST_INST): each failure event with its action and
    step subdivision, as given."""

    aster_types = ("list_inst",)
    deck_methods = frozenset({"getName", "getValues"})

    values: np.ndarray
    failures: list

    def __post_init__(self) -> None:
        self.values = np.asarray(self.values, dtype=float).ravel()

    def getValues(self):  # noqa: N802
        return self.values.tolist()
