"""Harmonic results: generalized (``harm_gene``) and physical (``dyna_harmo``)
complex responses, one state per frequency.

Owner: the harmonic room (``asterlite.harmonic``) and the commands that read
them. A state is the complex amplitude ``u`` of ``Re(u e^{iωt})``; velocity
and acceleration are ``iω u`` and ``-ω² u`` (code_aster's ``comdlh``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.base import Concept
from asterlite.post.deck_api import field_indexes, harmonic_field

HARMONIC_FIELDS = ("DEPL", "VITE", "ACCE")


@dataclass(eq=False)
class HarmGene(Concept):
    """``DYNA_VIBRA`` HARM/GENE result: complex generalized coordinates.

    ``fields`` maps the computed names among ``DEPL``/``VITE``/``ACCE``
    (NOM_CHAM, all three by default) to (n_freq, n_modes) complex arrays;
    ``frequencies`` (Hz) and ``order`` (NUME_ORDRE, 1..n) have length n_freq.
    ``basis`` is the basis the generalized matrices were projected on (a
    ``mode_meca``, a ``mode_gene`` or a coupled generalized model's modes),
    ``numbering`` the matrices' generalized numbering.
    """

    aster_types = ("harm_gene",)
    deck_methods = frozenset({"getName", "getIndexes", "getFrequencies", "getNumberOfModes"})

    basis: Any
    numbering: Any
    frequencies: np.ndarray
    order: np.ndarray
    fields: dict[str, np.ndarray] = field(default_factory=dict)
    info: dict[str, Any] = field(default_factory=dict)

    @property
    def n_modes(self) -> int:
        return next(iter(self.fields.values())).shape[1]

    def getIndexes(self) -> list[int]:  # noqa: N802
        return [int(o) for o in self.order]

    def getFrequencies(self) -> list[float]:  # noqa: N802
        return [float(f) for f in self.frequencies]

    def getNumberOfModes(self) -> int:  # noqa: N802
        return int(self.n_modes)


@dataclass(eq=False)
class DynaHarmo(Concept):
    """A physical harmonic result (``dyna_harmo``): complex nodal fields per
    frequency.

    ``fields`` maps ``DEPL``/``VITE``/``ACCE`` to (n_freq, n_dofs) complex
    arrays on ``numbering``'s DOFs; ``frequencies`` (Hz, code_aster's FREQ
    parameter) and ``order`` (NUME_ORDRE) have length n_freq.
    ``element_fields`` holds what CALC_CHAMP computed (complex ElementField).
    """

    aster_types = ("dyna_harmo", "resultat_sdaster")
    deck_methods = frozenset(
        {"getName", "getField", "getIndexes", "getIndexesForFieldName", "getFrequencies"}
    )

    numbering: DofNumbering
    frequencies: np.ndarray
    order: np.ndarray
    fields: dict[str, np.ndarray] = field(default_factory=dict)
    # what the result was computed with (CALC_CHAMP finds the model there)
    model: Any = None
    materials: Any = None
    characteristics: Any = None
    element_fields: dict = field(default_factory=dict)
    # the MATR_MASS of the computation (code_aster's REF_MASS_PREM): the
    # inertia M a of CALC_CHAMP REAC_NODA; None when unknown
    mass_matrix: Any = None
    # (rows, F - (K + iωC - ω²M) u on those rows (n_freq, n_rows)): the reactions
    # of the dualised constraints, whose multipliers code_aster's fields hold,
    # and the stiffness's Lagrange coefficient (asterlite.fem.lagrange_layout);
    # None when unknown (a result read or built otherwise)
    reactions: tuple | None = None
    lagrange_beta: float = 1.0
    # (modal basis, {field: generalized coordinates (n_freq, n_modes)}) of a
    # recombined harm_gene (REST_GENE_PHYS): its multipliers are the modes'
    modal_source: tuple | None = None

    @property
    def n_freq(self) -> int:
        return int(np.size(self.frequencies))

    def getIndexes(self) -> list[int]:  # noqa: N802
        return [int(o) for o in self.order]

    def getFrequencies(self) -> list[float]:  # noqa: N802
        return [float(f) for f in self.frequencies]

    def getIndexesForFieldName(self, name) -> list[int]:  # noqa: N802
        return field_indexes(self, name)

    def getField(self, name, value=None, para="NUME_ORDRE"):  # noqa: N802
        return harmonic_field(self, name, value, para)
