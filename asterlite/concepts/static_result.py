"""A linear static result (``evol_elas``, MECA_STATIQUE): displacements at the
instants of the computation, laid out as a physical transient's."""

from __future__ import annotations

from dataclasses import dataclass

from asterlite.concepts.transient import DynaTrans


@dataclass(eq=False)
class EvolElas(DynaTrans):
    """``fields["DEPL"]`` is (n_instants, n_dofs) on ``numbering``; ``model``,
    ``materials`` and ``characteristics`` are those of the computation."""

    aster_types = ("evol_elas", "resultat_sdaster")


@dataclass(eq=False)
class EvolChar(DynaTrans):
    """A load history (``evol_char``, CREA_RESU CONV_RESU): ``fields["FORC_NODA"]``
    is (n_instants, n_dofs) nodal forces on ``numbering``, which AFFE_CHAR_MECA
    EVOL_CHAR applies interpolated linearly in time."""

    aster_types = ("evol_char", "resultat_sdaster")
