"""Transient results: obstacles, generalized (``tran_gene``) and physical
(``dyna_trans``) time histories."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.base import Concept
from asterlite.concepts.modes import ModeResult
from asterlite.post.deck_api import (
    archived_instants,
    axial_force,
    field_indexes,
    generalized_values,
    info_nonl,
    normal_force,
    relation_force,
    set_generalized_values,
    set_result_mesh,
    transient_field,
    vari_interne,
)


@dataclass(eq=False)
class Obstacle(Concept):
    """``DEFI_OBSTACLE``: the shape of a shock connection (no dimensions).

    ``polar`` holds (angle in degrees, radius) pairs for ``DISCRET`` obstacles
    and the circle / plane types defined by code_aster as polygons too.
    """

    aster_types = ("table_fonction", "table_sdaster")

    obstacle_type: str
    polar: np.ndarray | None = None  # (n, 2): angle (deg), radius


@dataclass(eq=False)
class ShockHistory:
    """Local quantities of one localized nonlinearity at the archived instants.

    ``fields`` maps code_aster's names to arrays of length n_archived:
    ``FN`` (normal force magnitude, >= 0), ``FT1``/``FT2`` (tangential force
    along t1 = (0, -sin, cos) in the contact plane and along NORM_OBST),
    ``DXLOC``/``DYLOC``/``DZLOC`` (node 1's local coordinates: rest position
    plus displacement, relative to ORIG_OBST, in the frame NORM_OBST +
    ANGL_VRIL, as code_aster stores them), ``DXLOC_2``... (node 2, zero for
    single-node obstacles), ``DXREL``... (node 1 minus node 2, or node 1),
    ``VN``, ``VT1``, ``VT2`` (relative normal/tangential velocities),
    ``ADHERENCE`` (1 sticking, 0 sliding) and ``VINT1``..``VINT20`` (the
    raw internal variables in code_aster's order). Forces are those the
    obstacle (or node 2) exerts on node 1.
    """

    name: str  # INTITULE (or generated)
    relation: str  # DIS_CHOC, FLAMBAGE, ...
    node_1: str
    node_2: str | None
    fields: dict[str, np.ndarray] = field(default_factory=dict)
    parameters: dict[str, Any] = field(default_factory=dict)  # gaps, stiffnesses, frame...


@dataclass(eq=False)
class TranGene(Concept):
    """``DYNA_VIBRA`` TRAN/GENE result: generalized coordinates at archived instants.

    ``depl``, ``vite``, ``acce`` are (n_archived, n_modes); ``times`` and
    ``order`` (NUME_ORDRE, the step index of each archived instant) have
    length n_archived.
    """

    aster_types = ("tran_gene",)
    deck_methods = frozenset(
        {
            "getName",
            "getNumberOfModes",
            "getIndexes",
            "getTimes",
            "INFO_NONL",
            "getDisplacementValues",
            "getVelocityValues",
            "getAccelerationValues",
            "setDisplacementValues",
            "setVelocityValues",
            "setAccelerationValues",
            "LIST_ARCH",
            "VARI_INTERNE",
            "FORCE_NORMALE",
            "FORCE_AXIALE",
            "FORCE_RELATION",
        }
    )

    basis: ModeResult
    times: np.ndarray
    order: np.ndarray
    depl: np.ndarray
    vite: np.ndarray
    acce: np.ndarray
    shocks: list[ShockHistory] = field(default_factory=list)
    scheme: str = ""
    step: float = 0.0
    info: dict[str, Any] = field(default_factory=dict)  # steps taken, rejections, timings...
    # per archived instant: the step that led to it (code_aster's PTEM) and
    # the steps rejected since the start (adaptive schemes); None if unknown
    step_sizes: np.ndarray | None = None
    rejections: np.ndarray | None = None
    # tables kept with the result (RECU_TABLE NOM_TABLE): ENERGIE's PARA_CALC
    tables: dict = field(default_factory=dict)
    # what the computation was made with, for CALC_CHAMP (None when unknown):
    # the model, fields of materials and characteristics, the mass matrix
    # (code_aster's REF_MASS_PREM, for the inertia of REAC_NODA) and the list
    # of loads, (AFFE_CHAR_MECA load, FONC_MULT function or COEF_MULT) pairs
    model: Any = None
    materials: Any = None
    characteristics: Any = None
    mass_matrix: Any = None
    loads: tuple = ()

    @property
    def n_modes(self) -> int:
        return self.depl.shape[1]

    # deck API (code_aster's TransientGeneralizedResult), see asterlite.post.deck_api
    def getNumberOfModes(self) -> int:  # noqa: N802
        return int(self.n_modes)

    def getIndexes(self) -> list[int]:  # noqa: N802
        return [int(o) for o in self.order]

    def getTimes(self) -> list[float]:  # noqa: N802
        return [float(t) for t in self.times]

    def getDisplacementValues(self, idx=None):  # noqa: N802

        return generalized_values(self.depl, idx)

    def getVelocityValues(self, idx=None):  # noqa: N802

        return generalized_values(self.vite, idx)

    def getAccelerationValues(self, idx=None):  # noqa: N802

        return generalized_values(self.acce, idx)

    def setDisplacementValues(self, idx, val) -> None:  # noqa: N802

        set_generalized_values(self.depl, idx, val)

    def setVelocityValues(self, idx, val) -> None:  # noqa: N802

        set_generalized_values(self.vite, idx, val)

    def setAccelerationValues(self, idx, val) -> None:  # noqa: N802

        set_generalized_values(self.acce, idx, val)

    def INFO_NONL(self):  # noqa: N802

        return info_nonl(self.shocks)

    # code_aster 15's nonlinearity accessors (inoli counts from 1, -1: the first)
    def LIST_ARCH(self):  # noqa: N802

        return archived_instants(self.times)

    def VARI_INTERNE(self, inoli=-1, describe=True):  # noqa: N802

        return vari_interne(self.shocks, inoli, describe)

    def FORCE_NORMALE(self, inoli=-1):  # noqa: N802

        return normal_force(self.shocks, inoli)

    def FORCE_AXIALE(self, inoli=-1):  # noqa: N802

        return axial_force(self.shocks, inoli)

    def FORCE_RELATION(self, inoli=-1):  # noqa: N802

        return relation_force(self.shocks, inoli)


@dataclass(eq=False)
class DynaTrans(Concept):
    """A physical transient result (``dyna_trans``): nodal fields per instant.

    ``fields`` maps ``DEPL``/``VITE``/``ACCE`` to (n_instants, n_dofs) arrays on
    ``numbering``'s DOFs.
    """

    aster_types = ("dyna_trans", "resultat_sdaster")
    deck_methods = frozenset(
        {"getName", "getField", "getIndexes", "getIndexesForFieldName", "getTimes", "setMesh"}
    )

    numbering: DofNumbering
    times: np.ndarray
    order: np.ndarray
    fields: dict[str, np.ndarray] = field(default_factory=dict)
    # tables kept with the result (RECU_TABLE NOM_TABLE): ENERGIE's PARA_CALC
    tables: dict = field(default_factory=dict)
    # what the computation was made with, for CALC_CHAMP (None when unknown):
    # the model, fields of materials and characteristics, the mass matrix
    # (code_aster's REF_MASS_PREM, for the inertia of REAC_NODA) and the list
    # of loads, (AFFE_CHAR_MECA load, FONC_MULT function or COEF_MULT) pairs
    model: Any = None
    materials: Any = None
    characteristics: Any = None
    mass_matrix: Any = None
    loads: tuple = ()
    # (modal basis, {field: generalized values per stored instant}) of a
    # result restituted on a whole modal basis (REST_GENE_PHYS), else None
    modal_source: Any = None

    # deck API (code_aster's TransientResult), see asterlite.post.deck_api
    def getField(self, name, value=None, para="NUME_ORDRE"):  # noqa: N802

        return transient_field(self, name, value, para)

    def getIndexes(self) -> list[int]:  # noqa: N802
        return [int(o) for o in self.order]

    def getIndexesForFieldName(self, name) -> list[int]:  # noqa: N802
        return field_indexes(self, name)

    def getTimes(self) -> list[float]:  # noqa: N802
        return [float(t) for t in self.times]

    def setMesh(self, mesh) -> None:  # noqa: N802

        set_result_mesh(self, mesh)
