"""A linear static result (``evol_elas``, MECA_STATIQUE): displacements at the
instants of the computation, laid out as a physical transient's."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from asterlite.concepts.transient import DynaTrans


@dataclass(eq=False)
class EvolElas(DynaTrans):
    """``fields["DEPL"]`` is (n_instants, n_dofs) on ``numbering``; ``model``,
    ``materials`` and ``characteristics`` are those of the computation."""

    aster_types = ("evol_elas", "resultat_sdaster")

    model: Any = None
    materials: Any = None
    characteristics: Any = None
