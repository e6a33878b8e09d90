"""The relations of this package as shock rows.

``law_spec`` turns one :class:`LawConnection` (a relation other than
DIS_CHOC, its typed parameter record and its nodes, as the command read
them) into a :class:`model.ShockSpec` carrying the packed law parameters
(``prepare_*``), the local frame the kernel (``laws.kernel``) expects and
the initial internal variables; ``law_fields`` names the archived internal
variables for RECU_FONCTION (VINT1.. and the law's descriptive names).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType

import numpy as np

from asterlite.dynamics.geometry import local_frame, nautical_angles, rotation_matrix
from asterlite.dynamics.laws import anti_sism as AS
from asterlite.dynamics.laws import choc_elas_trac as CET
from asterlite.dynamics.laws import dis_ecro_trac as DET
from asterlite.dynamics.laws import dis_visc as DV
from asterlite.dynamics.laws import flambage as FL
from asterlite.dynamics.laws import kernel as LK
from asterlite.dynamics.laws import rela_effo_depl as RED
from asterlite.dynamics.laws import rela_effo_vite as REV
from asterlite.dynamics.laws import rotor_fiss as RF
from asterlite.dynamics.laws.tabulated import LawError
from asterlite.dynamics.model import COMPONENTS, ShockSpec

ROTATIONS = ("DRX", "DRY", "DRZ")
# where a formula of a displacement or velocity (RELA_EFFO_*) is tabulated:
# 0 and ±10^-9..10^4 (linear formulas are reproduced to rounding)
_LOG = np.logspace(-9.0, 4.0, 6001)
FORMULA_SAMPLES = np.concatenate([-_LOG[::-1], [0.0], _LOG])


class ConnectionError_(ValueError):
    """A relation whose nodes cannot carry it; ``end``: the node at fault
    (0: the first, 1: the second), for the caller to locate the message."""

    def __init__(self, message: str, end: int):
        super().__init__(message)
        self.end = end


@dataclass(frozen=True)
class Obstacle:
    """The obstacle of a buckling support: DEFI_OBSTACLE's table (its type
    and polar), the normal, the twist angle (degrees, None: none), the
    origin (None: the node's), the gap and the distances taken off it on
    each side."""

    table: object
    normal: np.ndarray
    twist: float | None
    origin: np.ndarray | None
    gap: float
    distance_1: float
    distance_2: float


@dataclass(frozen=True)
class Rotation:
    """The transient's rotation as a cracked rotor sees it: constant speed
    (rad/s) or a variable speed (its angle is then a function of time)."""

    speed: float
    variable: bool


@dataclass(frozen=True)
class LawConnection:
    """One relation of this package in a transient: its name in ``RELATIONS``,
    its parameter record (the module's ``*Parameters``), its nodes (indices
    in the mesh; ``node_2`` None for a one-node relation), its title (None:
    code_aster's default after ``number``, the nonlinearity's 1-based rank),
    the obstacle of a buckling support, and the quantities of the transient
    that some relations read: the rotation, and whether code_aster's
    diagnostics level asked for the true node distance (ANTI_SISM)."""

    relation: str
    parameters: object
    node_1: int
    node_2: int | None
    number: int
    title: str | None = None
    obstacle: Obstacle | None = None
    rotation: Rotation = Rotation(0.0, False)
    true_distance: bool = False


def shapes(basis, node: int | None, n_modes: int, components) -> np.ndarray | None:
    if node is None:
        return None
    rows = []
    for c in components:
        try:
            rows.append(np.asarray(basis.shape_at(node, c), dtype=float)[:n_modes])
        except (KeyError, ValueError, IndexError):
            rows.append(np.zeros(n_modes))
    return np.array(rows, dtype=float)


def axis_frame(c1, c2) -> np.ndarray:
    """Local frame whose x axis is node 1 -> node 2 (code_aster's nautical angles)."""
    axis = np.asarray(c2, float) - np.asarray(c1, float)
    if np.linalg.norm(axis) == 0.0:
        axis = np.array([1.0, 0.0, 0.0])
    return local_frame("PLAN_Y", axis, None, c1, None)


def neighbour_of(mesh, node: int, other: int, end: int) -> int:
    """code_aster's neighbour of ``node`` along the rotor (dtmprep_noli_rotf):
    over the cells of 2 or 3 nodes, in mesh order, that hold ``node`` but
    not ``other``, the neighbour is the cell's second node when ``node`` is
    its first, its first node when ``node`` is its second; the last such
    cell wins."""
    found = None
    for conn in mesh.cell_nodes:
        if not 1 < len(conn) < 4 or other in conn:
            continue
        if conn[0] == node:
            found = conn[1]
        elif conn[1] == node:
            found = conn[0]
    if found is None:
        raise ConnectionError_(
            f"ROTOR_FISS: node {mesh.node_names[node]} is not the end of a rotor segment "
            "(a cell of 2 or 3 nodes without the other crack node), the rotor axis is undefined",
            end,
        )
    return int(found)


def rotor_frame(mesh, node_d: int, node_g: int) -> np.ndarray:
    """Global -> rotor frame (gamma = 0) of a ROTOR_FISS crack, as code_aster
    sets it up: x is neighbour(D) - neighbour(G), the nodes adjacent to the
    crack nodes on the rotor, whatever the crack nodes' own positions."""
    near_d = neighbour_of(mesh, node_d, node_g, 0)
    near_g = neighbour_of(mesh, node_g, node_d, 1)
    axis = np.asarray(mesh.coords[near_d], float) - np.asarray(mesh.coords[near_g], float)
    alpha, beta = nautical_angles(axis)
    return rotation_matrix(alpha, beta, 0.0)


def default_name(relation: str, number: int) -> str:
    return f"{relation:<16}{number:08d}"


def law_spec(connection: LawConnection, basis, n_modes: int) -> ShockSpec:
    """The shock row of one relation of this package: what every relation
    shares (nodes, shapes, title), then its :class:`Relation`'s ``build``."""
    relation = RELATIONS.get(connection.relation)
    if relation is None:
        raise LawError(f"no relation {connection.relation!r} is registered (connections.RELATIONS)")
    mesh = basis.numbering.mesh
    n1, n2 = connection.node_1, connection.node_2
    spec = ShockSpec(
        name=connection.title or default_name(relation.name, connection.number),
        obstacle_type="BI_PLAN_Y" if n2 is not None else "PLAN_Y",
        node_1=mesh.node_names[n1],
        node_2=mesh.node_names[n2] if n2 is not None else None,
        coord_1=np.array(mesh.coords[n1], dtype=float),
        coord_2=np.array(mesh.coords[n2], dtype=float) if n2 is not None else None,
        phi_1=shapes(basis, n1, n_modes, COMPONENTS),
        phi_2=shapes(basis, n2, n_modes, COMPONENTS),
        norm_obst=np.array([1.0, 0.0, 0.0]),
        gap=0.0,
        relation=relation.name,
        law_code=relation.code,
        rphi_1=shapes(basis, n1, n_modes, ROTATIONS),
        rphi_2=shapes(basis, n2, n_modes, ROTATIONS),
    )
    relation.build(connection, spec, mesh)
    return spec


def build_flambage(connection: LawConnection, spec: ShockSpec, mesh) -> None:
    data, obstacle = connection.parameters, connection.obstacle
    spec.obstacle_type = obstacle.table.obstacle_type
    if spec.obstacle_type.startswith("BI_") and connection.node_2 is None:
        raise ConnectionError_(f"obstacle {spec.obstacle_type} needs a second node", 1)
    if not spec.obstacle_type.startswith("BI_"):
        spec.node_2, spec.coord_2, spec.phi_2, spec.rphi_2 = None, None, None, None
    spec.norm_obst = np.asarray(obstacle.normal, dtype=float)
    spec.angl_vril = obstacle.twist
    if obstacle.origin is not None:
        spec.orig_obst = np.asarray(obstacle.origin, dtype=float)
    spec.gap = float(obstacle.gap)
    spec.dist_1 = float(obstacle.distance_1)
    spec.dist_2 = float(obstacle.distance_2)
    spec.polar = obstacle.table.polar if spec.obstacle_type == "DISCRET" else None
    if isinstance(data, FL.ScalarFlambageParameters):  # code_aster 15's scalar law
        spec.law = FL.prepare_scalar_flambage(data)
    else:
        spec.law = FL.prepare_flambage(data)
    spec.law_state = FL.initial_state(spec.law)


def build_anti_sism(connection: LawConnection, spec: ShockSpec, mesh) -> None:
    frame = axis_frame(spec.coord_1, spec.coord_2)
    # BI_PLAN_Y whose y axis is node 1 -> node 2, no gap, each side half the reference distance
    spec.frame = np.array([frame[1], frame[0], -frame[2]])
    info = 2 if connection.true_distance else 1
    half = 0.5 * AS.reference_distance(spec.coord_1, spec.coord_2, info)
    spec.dist_1 = spec.dist_2 = half
    spec.law = AS.prepare_anti_sism(connection.parameters)


def build_dis_visc(connection: LawConnection, spec: ShockSpec, mesh) -> None:
    spec.frame = axis_frame(spec.coord_1, spec.coord_2)
    spec.law = DV.prepare_dis_visc(connection.parameters)


def build_dis_ecro_trac(connection: LawConnection, spec: ShockSpec, mesh) -> None:
    spec.frame = axis_frame(spec.coord_1, spec.coord_2)
    spec.law = DET.prepare_dis_ecro_trac(connection.parameters)


def build_choc_elas_trac(connection: LawConnection, spec: ShockSpec, mesh) -> None:
    spec.frame = axis_frame(spec.coord_1, spec.coord_2)
    rest = float(np.linalg.norm(spec.coord_2 - spec.coord_1))
    spec.law = CET.prepare_choc_elas_trac(connection.parameters, rest)


def build_nodal_relation(connection: LawConnection, spec: ShockSpec, mesh) -> None:
    """RELA_EFFO_DEPL / RELA_EFFO_VITE: untitled, named after the node's
    number, the component and the function, as code_aster names them."""
    data = connection.parameters
    spec.law = RED.prepare_relation(data, spec.relation, sample=FORMULA_SAMPLES)
    component = RED.COMPONENTS[int(spec.law[RED.P_COMPONENT])]
    function_name = getattr(data.function, "name", None) or ""
    if not connection.title:
        spec.name = f"{mesh_number(mesh, connection.node_1):<8}{component:<8}{function_name}"


def build_rotor_fiss(connection: LawConnection, spec: ShockSpec, mesh) -> None:
    spec.frame = rotor_frame(mesh, connection.node_1, connection.node_2)
    rotation = connection.rotation
    # at variable speed the speed is a function and the angle is given as one of time
    speed = 0.0 if rotation.variable else float(rotation.speed)
    spec.law = RF.prepare_rotor_fiss(connection.parameters, speed, rotation.variable)


@dataclass(frozen=True)
class Relation:
    """A relation of this package: its name (the relation's name in the deck), its
    module (``N_VINT``, ``VINT_NAMES``: the archived internal variables),
    its force's branch in the time loop (a code of ``laws.kernel``) and
    ``build(connection, spec, mesh)``, which completes the shock row (law
    parameters, local frame, initial internal variables)."""

    name: str
    module: ModuleType
    code: int
    build: Callable[[LawConnection, ShockSpec, object], None]


RELATIONS: dict[str, Relation] = {
    relation.name: relation
    for relation in (
        Relation("FLAMBAGE", FL, LK.FLAMBAGE, build_flambage),
        Relation("ANTI_SISM", AS, LK.ANTI_SISM, build_anti_sism),
        Relation("DIS_VISC", DV, LK.DIS_VISC, build_dis_visc),
        Relation("DIS_ECRO_TRAC", DET, LK.DIS_ECRO_TRAC, build_dis_ecro_trac),
        Relation("CHOC_ELAS_TRAC", CET, LK.CHOC_ELAS_TRAC, build_choc_elas_trac),
        Relation("RELA_EFFO_DEPL", RED, LK.RELA_EFFO_DEPL, build_nodal_relation),
        Relation("RELA_EFFO_VITE", REV, LK.RELA_EFFO_VITE, build_nodal_relation),
        Relation("ROTOR_FISS", RF, LK.ROTOR_FISS, build_rotor_fiss),
    )
}


def register(relation: Relation) -> None:
    """Add a relation (from outside the package: a module of its own whose
    force is one of the kernel's branches)."""
    if relation.name in RELATIONS:
        raise ValueError(f"relation {relation.name!r} is already registered")
    RELATIONS[relation.name] = relation


def internal_variable_names(relation: str) -> tuple[str, ...]:
    """Descriptive names of a relation's archived internal variables (VINT1..)."""
    return RELATIONS[relation].module.VINT_NAMES


def mesh_number(mesh, node: int) -> str:
    """code_aster's node number (1-based position in the mesh)."""
    return str(node + 1)


def law_fields(relation: str, v: np.ndarray) -> dict[str, np.ndarray]:
    """Archived quantities of a law row: VINT1.. and the law's names."""
    names = internal_variable_names(relation)
    fields = {}
    for i, name in enumerate(names):
        fields[f"VINT{i + 1}"] = v[:, i]
        fields.setdefault(name, v[:, i])
    if relation in ("FLAMBAGE",):
        fields["DXLOC"] = v[:, FL.V_LOC1]
        fields["DYLOC"] = v[:, FL.V_LOC1 + 1]
        fields["DZLOC"] = v[:, FL.V_LOC1 + 2]
    return fields


__all__ = [
    "RELATIONS", "ConnectionError_", "LawConnection", "Obstacle", "Relation", "Rotation",
    "internal_variable_names", "law_fields", "law_spec", "math", "register",
]  # fmt: skip
