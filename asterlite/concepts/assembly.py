"""Concepts of the structural front end: model, characteristics, loads,
elementary matrices, DOF numbering, assembled matrices and nodal fields.

Owner: the front end (``asterlite.fem``). Other rooms read these through the
attributes documented here; add fields, do not rename them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.concepts.element_block import ElementBlock
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.numpy_api import assembled_to_numpy, assembled_triplets
from asterlite.errors import DeckRuntimeError, UnsupportedError
from asterlite.fem.dofs import MODELISATION_COMPONENTS, sort_components
from asterlite.fem.lagrange_layout import dualised_relations, lagrange_layout

#: modelisations of the (x, y) plane besides the ``2D_`` discrete elements and bars
_PLANE_MODELISATIONS = ("D_PLAN", "C_PLAN", "AXIS", "D_PLAN_ABSO")


def _dof_label(node, component: str) -> tuple[int, str]:
    # code_aster's node and component names of a multiplier of several terms
    return (int(node), component) if component else (-1, "LAGR:MPC")


@dataclass(eq=False)
class Model(Concept):
    """``AFFE_MODELE`` result: which modelisation each cell carries."""

    aster_types = ("modele_sdaster",)
    deck_methods = frozenset({"getName", "getMesh", "getFiniteElementDescriptor"})

    mesh: Mesh
    cell_modelisation: dict[int, str] = field(default_factory=dict)  # cell index -> "DIS_T", ...
    node_modelisation: dict[int, str] = field(default_factory=dict)  # node-supported elements
    # AFFE_SOUS_STRUC: super-cell name -> SuperCell (asterlite.concepts.static_substructure)
    substructures: dict[str, Any] = field(default_factory=dict)

    def node_components(self) -> dict[int, tuple[str, ...]]:
        """Components carried by each node of the model (union over its elements),
        in code_aster's order; nodes without elements are absent."""

        # the nodes of each modelisation's cells first, then one update per
        # (modelisation, node): a 3D mesh's nodes belong to eight cells each
        cells_of: dict[str, list[int]] = {}
        for cell, modelisation in self.cell_modelisation.items():
            cells_of.setdefault(modelisation, []).append(cell)
        cell_nodes = self.mesh.cell_nodes
        found: dict[int, set[str]] = {}
        for modelisation, cells in cells_of.items():
            comps = MODELISATION_COMPONENTS.get(modelisation, ())
            for node in set().union(*(cell_nodes[cell] for cell in cells)):
                found.setdefault(node, set()).update(comps)
        for node, modelisation in self.node_modelisation.items():
            found.setdefault(node, set()).update(MODELISATION_COMPONENTS.get(modelisation, ()))
        for cell in self.substructures.values():
            for node in cell.nodes:
                found.setdefault(int(node), set()).update(cell.macro.components)
        ordered: dict[frozenset[str], tuple[str, ...]] = {}
        out = {}
        for node in sorted(found):
            comps = frozenset(found[node])
            if comps not in ordered:
                ordered[comps] = sort_components(comps)
            out[node] = ordered[comps]
        return out

    def getMesh(self) -> Mesh:  # noqa: N802 - code_aster's name
        return self.mesh

    def getFiniteElementDescriptor(self) -> Model:  # noqa: N802
        # code_aster's descriptor of the model's elements: the model itself here,
        # which is all that the commands taking it (toFieldOnCells) need
        return self

    @property
    def dim(self) -> int:
        """2 when every modelisation is plane (``2D_...``, plane strain or
        stress, axisymmetric and their absorbing edges), else 3."""
        names = set(self.cell_modelisation.values()) | set(self.node_modelisation.values())
        plane = all(n.startswith("2D_") or n in _PLANE_MODELISATIONS for n in names)
        return 2 if names and plane else 3


@dataclass(eq=False)
class DiscreteAssignment:
    """One ``AFFE_CARA_ELEM/DISCRET`` characteristic assigned to a cell."""

    matrix: str  # K, M or A
    cara: str  # e.g. K_T_D_N
    values: np.ndarray
    repere: str = "GLOBAL"  # GLOBAL or LOCAL
    symmetric: bool = True
    hysteretic: float = 0.0  # AMOR_HYST


@dataclass(eq=False)
class ElementCharacteristics(Concept):
    """``AFFE_CARA_ELEM`` result.

    ``discrete[cell][matrix]`` is the last :class:`DiscreteAssignment` of that
    kind (K, M, A) given to the cell; ``orientation[cell]`` its nautical
    angles in radians (ORIENTATION); ``extra`` keeps other keywords (POUTRE,
    BARRE...) as validated, keyed by keyword, for the rooms that use them.
    """

    aster_types = ("cara_elem",)

    model: Model
    discrete: dict[int, dict[str, DiscreteAssignment]] = field(default_factory=dict)
    orientation: dict[int, np.ndarray] = field(default_factory=dict)
    extra: dict[str, Any] = field(default_factory=dict)
    # beam / bar section properties per cell (asterlite.fem.sections output)
    sections: dict[int, dict[str, Any]] = field(default_factory=dict)
    # plate characteristics per cell (COQUE: EPAIS, COEF_RIGI_DRZ, INER_ROTA 1/0)
    shells: dict[int, dict[str, float]] = field(default_factory=dict)
    # multifibre beams (MULTIFIBRE): the fibre groups of each cell, from geom_fibre
    fibre_groups: dict[int, tuple[str, ...]] = field(default_factory=dict)
    # solids (MASSIF ANGL_REP): nautical angles in radians of the material frame (L, T, N)
    material_angles: dict[int, np.ndarray] = field(default_factory=dict)
    geom_fibre: Any = None  # asterlite.concepts.fibres.FibreGeometry
    # pipe cells' geometry and node frames (asterlite.fem.pipe_elements.PipeCell),
    # from their lines and GENE_TUYAU
    pipe_frames: dict[int, Any] = field(default_factory=dict)


@dataclass(eq=False)
class LinearRelation:
    """sum(coef * u[node, component]) = rhs, as given by DDL_IMPO or LIAISON_DDL."""

    terms: list[tuple[int, str, float]]  # (node index, component "DX", coefficient)
    rhs: float = 0.0
    # AFFE_CHAR_MECA_F of INST: the right-hand side in time (``rhs`` is its
    # value at INST=0, code_aster's instant for a computation that gives none)
    rhs_in_time: ValueInTime | None = None
    # AFFE_CHAR_CINE_F / AFFE_CHAR_MECA_F of FREQ: the right-hand side at each
    # frequency of a harmonic response (``rhs`` is then 0: no other
    # computation evaluates it)
    rhs_in_frequency: ValueInFrequency | None = None
    # code_aster dualises the relation with two multipliers, or one when its
    # load says DOUBLE_LAGRANGE='NON' (asterlite.fem.lagrange_layout)
    double_lagrange: bool = True


@dataclass(frozen=True, eq=False)
class ValueInTime:
    """A load function of INST (and X, Y, Z, fixed at ``point``) as a
    function of time: ``evaluate(times)``. ``key`` is the same for values
    equal at every instant (one function, one point or none used)."""

    function: Any
    point: tuple[float, float, float]
    #: the names the function's varying parameter may have
    parameters: ClassVar[tuple[str, ...]] = ("INST", "TOUTPARA")

    @property
    def key(self) -> tuple:
        names = tuple(self.function.nom_para)
        uses_point = any(p in ("X", "Y", "Z") for p in names)
        return (id(self.function), self.point if uses_point else None)

    def evaluate(self, times) -> np.ndarray:
        times = np.atleast_1d(np.asarray(times, dtype=float))
        at = dict(zip(("X", "Y", "Z"), self.point, strict=True))
        args = [times if p in self.parameters else at.get(p, 0.0) for p in self.function.nom_para]
        values = np.real(np.asarray(self.function.evaluate_many(*args), dtype=complex))
        return np.broadcast_to(values, times.shape).astype(float)


@dataclass(frozen=True, eq=False)
class ValueInFrequency(ValueInTime):
    """A load function of FREQ (and X, Y, Z, fixed at ``point``):
    ``evaluate(frequencies)``, real as code_aster's kinematic values."""

    parameters: ClassVar[tuple[str, ...]] = ("FREQ", "TOUTPARA")


@dataclass(eq=False)
class MechanicalLoad(Concept):
    """``AFFE_CHAR_MECA`` result: kinematic relations and nodal forces."""

    aster_types = ("char_meca",)

    model: Model
    relations: list[LinearRelation] = field(default_factory=list)
    nodal_forces: list[tuple[int, str, float]] = field(default_factory=list)
    extra: dict[str, Any] = field(default_factory=dict)  # other load kinds, keyed by keyword


@dataclass(eq=False)
class KinematicLoad(MechanicalLoad):
    """``AFFE_CHAR_CINE``/``_F`` result: imposed values of DOFs (relations
    with one term). code_aster eliminates these DOFs from the assembled
    system instead of dualising them; asterlite applies them through the same
    elimination as DDL_IMPO, which gives the same solution."""

    aster_types = ("char_cine_meca",)


@dataclass(eq=False)
class ElementaryMatrices(Concept):
    """``CALC_MATR_ELEM`` result: element matrices of one option plus the loads
    whose kinematic relations come with them (code_aster's Lagrange terms).

    Large element matrices are not held between commands: with ``recompute``
    (the computation that made them, from concepts that never change) the
    blocks are dropped once made (:meth:`release`) and made again by
    :meth:`element_blocks` for the command that reads them, as code_aster's
    memory manager moves large objects out of memory until they are read."""

    aster_types = ("matr_elem_depl_r",)

    model: Model
    option: str  # RIGI_MECA, MASS_MECA, AMOR_MECA...
    blocks: list[ElementBlock] | None = field(default_factory=list)
    loads: list[MechanicalLoad] = field(default_factory=list)
    characteristics: ElementCharacteristics | None = None
    materials: Any = None  # MaterialField (CHAM_MATER) the matrices were computed with
    recompute: Any = None  # () -> list[ElementBlock], the same matrices again

    #: element matrices of more than this many bytes are released once made
    RELEASE_BYTES: ClassVar[int] = 16 * 1024 * 1024

    def element_blocks(self) -> list[ElementBlock]:
        """The element matrices (made again if they were released)."""
        if self.blocks is not None:
            return self.blocks
        return self.recompute()

    def release(self) -> None:
        """Drop the element matrices when they are large and can be made again."""
        if self.recompute is None or self.blocks is None:
            return
        if sum(block.nbytes for block in self.blocks) > self.RELEASE_BYTES:
            self.blocks = None


@dataclass(eq=False)
class ComplexElementaryMatrices(ElementaryMatrices):
    """``CALC_MATR_ELEM`` result of a complex option (RIGI_MECA_HYST): the
    blocks hold complex matrices."""

    aster_types = ("matr_elem_depl_c",)


@dataclass(eq=False)
class ElementaryVectors(Concept):
    """``CALC_VECT_ELEM`` result: nodal load terms (node, component, value)."""

    aster_types = ("vect_elem_depl_r",)

    model: Model | None
    option: str
    loads: list[MechanicalLoad] = field(default_factory=list)
    terms: list[tuple[int, str, float]] = field(default_factory=list)


@dataclass(eq=False)
class DofNumbering(Concept):
    """``NUME_DDL`` result: the physical unknowns and the constraints on them.

    ``dofs[i] = (node index, component)``; ``index[(node, component)] = i``.
    Constraints (from the loads given to the matrices) are kept as linear
    relations; assembled matrices live on the physical DOFs only and the
    eigen solver / static solver apply the relations (equivalent to
    code_aster's dualised Lagrange multipliers).
    """

    aster_types = ("nume_ddl_sdaster",)
    deck_methods = frozenset(
        {
            "getName",
            "getPhysicalDOFs",
            "getNumberOfDOFs",
            "getLagrangeDOFs",
            "getDictOfLagrangeDOFs",
            "getMesh",
            "getNodeAndComponentFromDOF",
            "getComponentFromDOF",
            "getNodeFromDOF",
        }
    )

    mesh: Mesh
    dofs: list[tuple[int, str]]
    relations: list[LinearRelation] = field(default_factory=list)
    # the model (and, when known, characteristics / material field) the
    # numbering was built for: CALC_CHAMP finds them from a result's numbering
    model: Any = None
    characteristics: Any = None
    materials: Any = None

    def __post_init__(self) -> None:
        self.index = {dof: i for i, dof in enumerate(self.dofs)}
        # the kinematic loads (AFFE_CHAR_CINE) whose values are in ``relations``
        self.kinematic_loads: tuple = ()

    @property
    def n_dofs(self) -> int:
        return len(self.dofs)

    # deck API: code_aster's numbering of these DOFs, with two Lagrange
    # multipliers per dualised constraint (asterlite.fem.lagrange_layout)
    def getPhysicalDOFs(self, local=False) -> list[int]:  # noqa: N802
        return lagrange_layout(self).physical.tolist()

    def getNumberOfDOFs(self, local=False) -> int:  # noqa: N802
        return lagrange_layout(self).size

    def getLagrangeDOFs(self, local=False) -> list[int]:  # noqa: N802
        return lagrange_layout(self).lagrange.tolist()

    def getNodeAndComponentFromDOF(self, dof: int | None = None, local=False):  # noqa: N802
        """(0-based node, component) of a DOF of code_aster's numbering, or of
        every DOF without ``dof``: a DDL_IMPO multiplier gives its constrained
        node and 'LAGR:<component>', a relation of several terms (-1, 'LAGR:MPC')."""
        layout = lagrange_layout(self)
        if dof is None:
            return [_dof_label(node, component) for node, component in layout.labels]
        if not 0 <= int(dof) < layout.size:
            raise DeckRuntimeError(f"DOF {dof} is outside the numbering (0..{layout.size - 1})")
        return _dof_label(*layout.labels[int(dof)])

    def getDictOfLagrangeDOFs(self, local=False) -> dict[int, list[int]]:  # noqa: N802
        """{1: positions of the first multipliers, 2: of the second ones}."""
        layout = lagrange_layout(self)
        return {1: sorted(layout.first.tolist()), 2: sorted(layout.second.tolist())}

    def getComponentFromDOF(self, dof: int, local=False) -> str:  # noqa: N802
        return self.getNodeAndComponentFromDOF(dof)[1]

    def getNodeFromDOF(self, dof: int, local=False) -> int:  # noqa: N802
        return self.getNodeAndComponentFromDOF(dof)[0]

    def getMesh(self) -> Mesh:  # noqa: N802
        return self.mesh

    def dof_index(self, node: int | str, component: str) -> int:
        """Index of (node, component); raises KeyError when absent."""
        if isinstance(node, str):
            found = self.mesh.find_node(node)
            if found is None:
                raise KeyError(node)
            node = found
        return self.index[(node, component)]

    def dof_indices(self, nodes, components) -> np.ndarray:
        """Vectorised lookup: indices of (nodes[i], components[i]) pairs, -1 when absent.

        ``components`` may be one name for every node."""
        nodes = np.atleast_1d(np.asarray(nodes))
        if isinstance(components, str):
            components = [components] * len(nodes)
        out = np.empty(len(nodes), dtype=int)
        for k, (n, c) in enumerate(zip(nodes, components, strict=True)):
            if isinstance(n, str):
                found = self.mesh.find_node(n)
                n = -1 if found is None else found
            out[k] = self.index.get((int(n), c), -1)
        return out

    @property
    def dof_nodes(self) -> np.ndarray:
        return np.array([n for n, _ in self.dofs], dtype=int)

    @property
    def dof_components(self) -> list[str]:
        return [c for _, c in self.dofs]

    def constraint_matrix(self, rhs_in_time: bool = False, rhs_in_frequency: bool = False):
        """(B, b): the relations as a sparse (n_relations, n_dofs) matrix and rhs.

        A right-hand side given in time (AFFE_CHAR_MECA_F DDL_IMPO of INST)
        is refused unless the caller evaluates it in time itself or does not
        use b (``rhs_in_time=True``); one given in frequency likewise
        (``rhs_in_frequency=True``)."""
        from asterlite.fem.constraints import relation_matrix

        if not rhs_in_frequency and any(r.rhs_in_frequency is not None for r in self.relations):
            raise UnsupportedError(
                "an imposed value given as a function of FREQ (AFFE_CHAR_CINE_F, "
                "AFFE_CHAR_MECA_F DDL_IMPO): only DYNA_VIBRA TYPE_CALCUL='HARM' evaluates it; "
                f"the numbering {self.name or ''} holds such a relation"
            )
        if not rhs_in_time and any(r.rhs_in_time is not None for r in self.relations):
            raise UnsupportedError(
                "AFFE_CHAR_MECA_F DDL_IMPO of INST (an imposed value varying in time): only "
                "DYNA_VIBRA TYPE_CALCUL='TRAN' BASE_CALCUL='PHYS' (NEWMARK) evaluates it in "
                f"time; the numbering {self.name or ''} holds such a relation"
            )

        return relation_matrix(self.relations, self.index, self.n_dofs)

    def with_kinematic(self, loads) -> DofNumbering:
        """This numbering with the imposed values of kinematic loads
        (ASSE_MATRICE CHAR_CINE) added to its relations; the same loads give
        the same numbering object, so the matrices assembled with them share it."""
        fresh = [load for load in loads if not any(load is r for r in self.kinematic_loads)]
        if not fresh:
            return self
        key = tuple(id(load) for load in fresh)
        cache = self.__dict__.setdefault("_with_kinematic", {})
        if key not in cache:
            relations = list(self.relations)
            for load in fresh:
                relations.extend(load.relations)
            derived = DofNumbering(
                mesh=self.mesh,
                dofs=self.dofs,
                relations=relations,
                model=self.model,
                characteristics=self.characteristics,
                materials=self.materials,
            )
            derived.name = self.name
            derived.kinematic_loads = (*self.kinematic_loads, *fresh)
            cache[key] = derived
        return cache[key]

    def label(self, i: int) -> str:
        node, comp = self.dofs[i]
        return f"{self.mesh.node_names[node]} {comp}"


@dataclass(eq=False)
class AssembledMatrix(Concept):
    """``ASSE_MATRICE`` result on the physical DOFs (scipy sparse CSR)."""

    aster_types = ("matr_asse_depl_r", "matr_asse")
    deck_methods = frozenset(
        {"getName", "toNumpy", "getDOFNumbering", "EXTR_MATR", "getValuesWithDescription"}
    )

    #: arrays a run past its memory share may move to disk
    #: (asterlite.runtime.result_paging): the CSR's terms and their columns
    PAGED_ARRAYS: ClassVar[tuple[str, ...]] = ("matrix.data", "matrix.indices")

    numbering: DofNumbering
    matrix: Any  # scipy.sparse.csr_matrix (n_dofs, n_dofs)
    kind: str = "RIGI"  # RIGI, MASS, AMOR; GYRO (MECA_GYRO), RIGY (RIGI_GYRO): non-symmetric
    # what the matrix was built from (code_aster keeps them in the matrix):
    # Model, ElementCharacteristics, MaterialField, or None
    model: Any = None
    characteristics: Any = None
    materials: Any = None

    def toNumpy(self) -> np.ndarray:  # noqa: N802 - code_aster's name
        """The values as a dense array, as code_aster's: on its numbering with
        Lagrange multipliers, kinematically imposed DOFs eliminated
        (asterlite.concepts.numpy_api)."""

        return assembled_to_numpy(self)

    def getValuesWithDescription(self, epsilon=None):  # noqa: N802
        """(values, rows, columns, size) of the stored terms (numpy_api)."""

        return assembled_triplets(self, epsilon)

    def EXTR_MATR(self, sparse=False, epsilon=None):  # noqa: N802
        """code_aster's older name: toNumpy(), or getValuesWithDescription()
        with ``sparse=True``."""

        return assembled_triplets(self, epsilon) if sparse else assembled_to_numpy(self)

    def getDOFNumbering(self) -> DofNumbering:  # noqa: N802
        return self.numbering


@dataclass(eq=False)
class ComplexAssembledMatrix(AssembledMatrix):
    """A complex assembled matrix (``matr_asse_depl_c``, e.g. RIGI_MECA_HYST:
    ``K (1 + i eta)``); ``matrix`` is a complex scipy.sparse CSR matrix."""

    aster_types = ("matr_asse_depl_c", "matr_asse")


@dataclass(eq=False)
class NodalField(Concept):
    """A field on nodes (``cham_no_sdaster``): one value per DOF of a numbering."""

    aster_types = ("cham_no_sdaster", "cham_gd_sdaster")
    deck_methods = frozenset({"getName", "getValues", "getValuesWithDescription"})

    #: arrays a run past its memory share may move to disk (result_paging)
    PAGED_ARRAYS: ClassVar[tuple[str, ...]] = ("values",)

    numbering: DofNumbering
    values: np.ndarray
    # ASSE_VECTEUR's second member: the imposed values of its loads'
    # relations (code_aster's Lagrange terms), by id of the relation
    relation_values: dict[int, float] | None = None

    def getValues(self) -> list:  # noqa: N802 - code_aster's name
        """One value per DOF (real or complex). Refused when code_aster's
        numbering would also hold Lagrange multipliers (dualised constraints),
        whose values asterlite does not compute."""
        dualised = len(dualised_relations(self.numbering))
        if dualised:
            raise UnsupportedError(
                f"{self.name or 'field'}.getValues(): code_aster's field holds Lagrange "
                f"multiplier values for the {dualised} constraints of its numbering, which "
                "asterlite keeps as relations"
            )
        return np.asarray(self.values).tolist()

    def getValuesWithDescription(self, components=(), groups=()):  # noqa: N802
        """(values, (nodes, components)) of the DOFs of ``components`` (all when
        empty) at the nodes of ``groups`` of nodes (all when empty), in the
        numbering's order, nodes from 0 (code_aster's FieldOnNodes method).
        Lagrange multipliers ('LAGR:...') are refused: asterlite keeps the
        constraints as relations."""
        wanted = {components} if isinstance(components, str) else set(components)
        if any(str(name).startswith("LAGR") for name in wanted):
            raise UnsupportedError(
                f"{self.name or 'field'}.getValuesWithDescription(): values of Lagrange "
                "multipliers, which asterlite keeps as relations"
            )
        names = [groups] if isinstance(groups, str) else list(groups)
        mesh = self.numbering.mesh
        nodes = set(mesh.getNodes(names)) if names else None
        picked = [
            (i, node, component)
            for i, (node, component) in enumerate(self.numbering.dofs)
            if (not wanted or component in wanted) and (nodes is None or node in nodes)
        ]
        values = np.asarray(self.values)[[i for i, _, _ in picked]].tolist()
        return values, ([int(n) for _, n, _ in picked], [c for _, _, c in picked])


@dataclass(eq=False)
class NodalFunctionField(Concept):
    """A field of functions on nodes (``CREA_CHAMP TYPE_CHAM='NOEU_NEUT_F'``):
    one function (DEFI_FONCTION, FORMULE, DEFI_CONSTANTE) per (node,
    component) of ``numbering``, evaluated by ``CREA_CHAMP OPERATION='EVAL'``."""

    aster_types = ("cham_no_sdaster",)
    deck_methods = frozenset({"getName"})

    numbering: DofNumbering
    functions: list


@dataclass(eq=False)
class Material(Concept):
    """``DEFI_MATERIAU`` result: one material's parameters by behaviour.

    ``behaviours["ELAS"]`` maps code_aster names (E, NU, RHO, AMOR_ALPHA,
    AMOR_BETA, AMOR_HYST, ALPHA...) to floats; ELAS_FO values are stored
    there too once evaluated (constant functions); ``behaviours["ELAS_VISCO"]``
    holds a viscoelastic material's complex G and NU and its RHO;
    ``behaviours["ELAS_ORTH"]`` an orthotropic material's E_L ... G_TN in its
    frame (L, T, N), with RHO and the Rayleigh and hysteretic coefficients.
    ``get(name, default)`` reads an elastic parameter (an orthotropic
    material has no E nor NU).
    """

    aster_types = ("mater_sdaster",)

    behaviours: dict[str, dict[str, Any]] = field(default_factory=dict)

    def get(self, name: str, default: float | None = None) -> float | None:
        elastic = self.behaviours.get("ELAS")
        if elastic is None and name == "RHO":
            # a viscoelastic material's density is its ELAS_VISCO's
            elastic = self.behaviours.get("ELAS_VISCO")
        if elastic is None:
            # density and damping of an orthotropic material are its ELAS_ORTH's
            elastic = self.behaviours.get("ELAS_ORTH")
        return (elastic or {}).get(name, default)

    @property
    def orthotropic(self) -> dict[str, float] | None:
        """ELAS_ORTH's parameters, None for other materials."""
        return self.behaviours.get("ELAS_ORTH")

    @property
    def viscoelastic(self) -> dict[str, complex] | None:
        """ELAS_VISCO's complex G and NU (and RHO), None for other materials."""
        return self.behaviours.get("ELAS_VISCO")

    @property
    def young(self) -> float:
        return float(self.get("E", 0.0))

    @property
    def poisson(self) -> float:
        return float(self.get("NU", 0.0))

    @property
    def density(self) -> float:
        return float(self.get("RHO", 0.0))


@dataclass(eq=False)
class MaterialField(Concept):
    """``AFFE_MATERIAU`` result: the material of each cell (last assignment wins)."""

    aster_types = ("cham_mater",)

    mesh: Mesh
    cell_material: dict[int, Material] = field(default_factory=dict)
    # every material AFFE gave a cell (the fibre groups of multifibre beams take theirs there)
    cell_materials: dict[int, tuple[Material, ...]] = field(default_factory=dict)
    # AFFE_COMPOR: the multifibre behaviour of a cell (asterlite.concepts.fibres)
    cell_behaviour: dict[int, Any] = field(default_factory=dict)

    def material_of(self, cell: int) -> Material | None:
        return self.cell_material.get(int(cell))

    def material_groups(self, cells) -> list[tuple[Material | None, np.ndarray]]:
        """The materials of ``cells`` in order of first appearance, each with
        the positions in ``cells`` of the cells it is assigned to (None for
        cells without one): parameters are then read once per material, not
        once per cell (tens of thousands of cells on a 3D mesh)."""
        found: dict[int, tuple[Material | None, list[int]]] = {}
        lookup = self.cell_material.get
        for k, cell in enumerate(np.asarray(cells, dtype=int).tolist()):
            material = lookup(cell)
            group = found.get(id(material))
            if group is None:
                found[id(material)] = group = (material, [])
            group[1].append(k)
        return [(material, np.array(rows, dtype=int)) for material, rows in found.values()]

    def values(self, cells, name: str, default: float = 0.0, groups=None) -> np.ndarray:
        """(len(cells),) elastic parameter ``name`` of each cell's material
        (``groups``: :meth:`material_groups` of ``cells``, when known)."""
        out = np.full(len(cells), float(default))
        for material, rows in self.material_groups(cells) if groups is None else groups:
            if material is None:
                continue
            varying = material.behaviours.get("ELAS_VARYING", {})
            if name in varying:
                raise ValueError(
                    f"{name} of material {material.name or '?'} varies with {varying[name]}: "
                    "asterlite applies no command variable field (AFFE_VARC) to evaluate it"
                )
            value = material.get(name)
            if value is not None:
                out[rows] = float(value)
        return out


@dataclass(eq=False)
class ElementField:
    """A field by element node (``*_ELNO``) or on elements (``*_ELGA``),
    at every stored instant/mode of a result.

    ``values`` is (n_orders, n_cells, n_points, n_components) for the cells
    ``cells`` (mesh cell indices), ``components`` their names (``N``,
    ``VY``... for EFGE_ELNO); points are the cell's nodes for ELNO (in
    connectivity order) or its Gauss points for ELGA. A field on sub-points
    (the fibres of multifibre beams) has ``sub_points`` > 1: point index
    ``p * sub_points + s`` for Gauss point p and sub-point s (NaN past a
    cell's own sub-points).
    """

    name: str
    cells: np.ndarray
    components: tuple[str, ...]
    values: np.ndarray
    sub_points: int = 1

    def at(self, cell: int, point: int, component: str) -> np.ndarray:
        """Values along the orders of one cell, point (0-based) and component."""
        row = int(np.flatnonzero(self.cells == cell)[0])
        return self.values[:, row, point, self.components.index(component)]


@dataclass(eq=False)
class NodalComponentField:
    """A nodal field with named components (``*_NOEU`` such as SIPO_NOEU):
    ``values`` is (n_orders, n_nodes_listed, n_components) on ``nodes``.
    ``defined`` (n_nodes_listed, n_components) marks the components each node
    holds when they differ from node to node (OBSERVATION's FILTRE); None
    when every listed node holds every component."""

    name: str
    nodes: np.ndarray
    components: tuple[str, ...]
    values: np.ndarray
    defined: np.ndarray | None = None

    def at(self, node: int, component: str) -> np.ndarray:
        row = int(np.flatnonzero(self.nodes == node)[0])
        return self.values[:, row, self.components.index(component)]

    def holds(self, node: int, component: str) -> bool:
        """Whether the listed ``node`` holds ``component``."""
        if self.defined is None:
            return True
        row = int(np.flatnonzero(self.nodes == node)[0])
        return bool(self.defined[row, self.components.index(component)])
