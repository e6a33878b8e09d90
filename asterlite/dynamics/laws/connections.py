"""COMPORTEMENT occurrences of the relations of this package, as shock rows.

``law_spec`` turns one validated occurrence (RELATION other than DIS_CHOC)
into a :class:`model.ShockSpec` carrying the packed law parameters
(``prepare_*``), the local frame the kernel (``laws.kernel``) expects and
the initial internal variables; ``law_fields`` names the archived internal
variables for RECU_FONCTION (VINT1.. and the law's descriptive names).
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.dynamics.geometry import local_frame, nautical_angles, rotation_matrix
from asterlite.dynamics.laws import RELATIONS
from asterlite.dynamics.laws import anti_sism as AS
from asterlite.dynamics.laws import choc_elas_trac as CET
from asterlite.dynamics.laws import dis_ecro_trac as DET
from asterlite.dynamics.laws import dis_visc as DV
from asterlite.dynamics.laws import flambage as FL
from asterlite.dynamics.laws import rela_effo_depl as RED
from asterlite.dynamics.laws import rotor_fiss as RF
from asterlite.dynamics.laws.tabulated import LawError
from asterlite.dynamics.model import COMPONENTS, ShockSpec

ROTATIONS = ("DRX", "DRY", "DRZ")
# where a FORMULE of a displacement or velocity (RELA_EFFO_*) is tabulated:
# 0 and ±10^-9..10^4 (linear formulas are reproduced to rounding)
_LOG = np.logspace(-9.0, 4.0, 6001)
FORMULA_SAMPLES = np.concatenate([-_LOG[::-1], [0.0], _LOG])


class ConnectionError_(ValueError):
    """A COMPORTEMENT occurrence that names nodes the mesh does not have."""

    def __init__(self, message: str, keyword: str):
        super().__init__(message)
        self.keyword = keyword


def find_node(mesh, occ, node_kw: str, group_kw: str) -> int | None:
    if occ.get(node_kw) is not None:
        index = mesh.find_node(occ[node_kw])
        if index is None:
            raise ConnectionError_(f"no node {occ[node_kw]!r} in the mesh", node_kw)
        return index
    if occ.get(group_kw) is not None:
        group = occ[group_kw]
        nodes = mesh.node_groups.get(group)
        if nodes is None:
            raise ConnectionError_(f"no node group {group!r} in the mesh", group_kw)
        if len(nodes) != 1:
            raise ConnectionError_(
                f"group {group!r} must hold exactly one node (it has {len(nodes)})", group_kw
            )
        return int(nodes[0])
    return None


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


def neighbour_of(mesh, node: int, other: int, keyword: str) -> int:
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
            keyword,
        )
    return int(found)


def rotor_frame(mesh, node_d: int, node_g: int) -> np.ndarray:
    """Global -> rotor frame (gamma = 0) of a ROTOR_FISS crack, as code_aster
    sets it up: x is neighbour(D) - neighbour(G), the nodes adjacent to the
    crack nodes on the rotor, whatever the crack nodes' own positions."""
    near_d = neighbour_of(mesh, node_d, node_g, "GROUP_NO_D")
    near_g = neighbour_of(mesh, node_g, node_d, "GROUP_NO_G")
    axis = np.asarray(mesh.coords[near_d], float) - np.asarray(mesh.coords[near_g], float)
    alpha, beta = nautical_angles(axis)
    return rotation_matrix(alpha, beta, 0.0)


def default_name(relation: str, number: int) -> str:
    return f"{relation:<16}{number:08d}"


def law_spec(occ, basis, n_modes: int, number: int, options: dict) -> ShockSpec:
    """The shock row of one COMPORTEMENT occurrence of a relation of laws/.
    ``number``: the nonlinearity's 1-based rank (default INTITULE);
    ``options``: DYNA_VIBRA's INFO, VITE_ROTA, VITESSE_VARIABLE."""
    relation = occ["RELATION"]
    if relation not in RELATIONS:
        raise LawError(f"COMPORTEMENT RELATION={relation!r} is not available")
    mesh = basis.numbering.mesh
    if relation in ("RELA_EFFO_DEPL", "RELA_EFFO_VITE"):
        n1 = find_node(mesh, occ, "NOEUD", "GROUP_NO")
        n2 = None
    elif relation == "ROTOR_FISS":
        n1 = find_node(mesh, occ, "NOEUD_D", "GROUP_NO_D")
        n2 = find_node(mesh, occ, "NOEUD_G", "GROUP_NO_G")
    else:
        n1 = find_node(mesh, occ, "NOEUD_1", "GROUP_NO_1")
        n2 = find_node(mesh, occ, "NOEUD_2", "GROUP_NO_2")
    if n1 is None:
        raise ConnectionError_(f"{relation}: the node is missing", "GROUP_NO_1")
    if n2 is None and relation not in ("FLAMBAGE", "RELA_EFFO_DEPL", "RELA_EFFO_VITE"):
        raise ConnectionError_(f"{relation} needs two nodes", "GROUP_NO_2")
    c1 = np.array(mesh.coords[n1], dtype=float)
    c2 = np.array(mesh.coords[n2], dtype=float) if n2 is not None else None
    name = occ.get("INTITULE") or default_name(relation, number)
    spec = ShockSpec(
        name=name,
        obstacle_type="BI_PLAN_Y" if n2 is not None else "PLAN_Y",
        node_1=mesh.node_names[n1],
        node_2=mesh.node_names[n2] if n2 is not None else None,
        coord_1=c1,
        coord_2=c2,
        phi_1=shapes(basis, n1, n_modes, COMPONENTS),
        phi_2=shapes(basis, n2, n_modes, COMPONENTS),
        norm_obst=np.array([1.0, 0.0, 0.0]),
        gap=0.0,
        relation=relation,
        rphi_1=shapes(basis, n1, n_modes, ROTATIONS),
        rphi_2=shapes(basis, n2, n_modes, ROTATIONS),
    )
    if relation == "FLAMBAGE":
        obstacle = occ["OBSTACLE"]
        spec.obstacle_type = obstacle.obstacle_type
        if spec.obstacle_type.startswith("BI_") and n2 is None:
            raise ConnectionError_(f"obstacle {spec.obstacle_type} needs a second node", "OBSTACLE")
        if not spec.obstacle_type.startswith("BI_"):
            spec.node_2, spec.coord_2, spec.phi_2, spec.rphi_2 = None, None, None, None
        spec.norm_obst = np.asarray(occ["NORM_OBST"], dtype=float)
        spec.angl_vril = occ.get("ANGL_VRIL")
        if occ.get("ORIG_OBST") is not None:
            spec.orig_obst = np.asarray(occ["ORIG_OBST"], dtype=float)
        spec.gap = float(occ.get("JEU", 1.0))
        spec.dist_1 = float(occ.get("DIST_1") or 0.0)
        spec.dist_2 = float(occ.get("DIST_2") or 0.0)
        spec.polar = obstacle.polar if spec.obstacle_type == "DISCRET" else None
        if occ.get("FNOR_CRIT") is not None:  # code_aster 15's scalar law (hidden keywords)
            spec.law = FL.prepare_scalar_flambage(occ)
        else:
            spec.law = FL.prepare_flambage(occ)
        spec.law_state = FL.initial_state(spec.law)
    elif relation == "ANTI_SISM":
        frame = axis_frame(c1, c2)
        # BI_PLAN_Y whose y axis is node 1 -> node 2, JEU=0, DIST_1 = DIST_2 = gap/2
        spec.frame = np.array([frame[1], frame[0], -frame[2]])
        half = 0.5 * AS.reference_distance(c1, c2, int(options.get("INFO", 1)))
        spec.dist_1 = spec.dist_2 = half
        spec.law = AS.prepare_anti_sism(occ)
    elif relation in ("DIS_VISC", "DIS_ECRO_TRAC", "CHOC_ELAS_TRAC"):
        spec.frame = axis_frame(c1, c2)
        if relation == "DIS_VISC":
            spec.law = DV.prepare_dis_visc(occ)
        elif relation == "DIS_ECRO_TRAC":
            spec.law = DET.prepare_dis_ecro_trac(occ)
        else:
            spec.law = CET.prepare_choc_elas_trac(occ, float(np.linalg.norm(c2 - c1)))
    elif relation in ("RELA_EFFO_DEPL", "RELA_EFFO_VITE"):
        spec.law = RED.prepare_relation(occ, relation, sample=FORMULA_SAMPLES)
        component = RED.COMPONENTS[int(spec.law[RED.P_COMPONENT])]
        function_name = getattr(occ["FONCTION"], "name", None) or ""
        if not occ.get("INTITULE"):
            spec.name = f"{mesh_number(mesh, n1):<8}{component:<8}{function_name}"
    elif relation == "ROTOR_FISS":
        spec.frame = rotor_frame(mesh, n1, n2)
        variable = options.get("VITESSE_VARIABLE", "NON") == "OUI"
        # at variable speed VITE_ROTA is a function and the angle is ANGL_ROTA(t)
        speed = 0.0 if variable else float(options.get("VITE_ROTA") or 0.0)
        spec.law = RF.prepare_rotor_fiss(occ, speed, variable)
    return spec


def mesh_number(mesh, node: int) -> str:
    """code_aster's node number (1-based position in the mesh)."""
    return str(node + 1)


def law_fields(relation: str, v: np.ndarray) -> dict[str, np.ndarray]:
    """Archived quantities of a law row: VINT1.. and the law's names."""
    module = RELATIONS[relation]
    names = module.VINT_NAMES
    fields = {}
    for i, name in enumerate(names):
        fields[f"VINT{i + 1}"] = v[:, i]
        fields.setdefault(name, v[:, i])
    if relation in ("FLAMBAGE",):
        fields["DXLOC"] = v[:, FL.V_LOC1]
        fields["DYLOC"] = v[:, FL.V_LOC1 + 1]
        fields["DZLOC"] = v[:, FL.V_LOC1 + 2]
    return fields


def parameters(spec: ShockSpec) -> dict:
    return {"RELATION": spec.relation, "LAW": None if spec.law is None else spec.law.copy()}


__all__ = ["law_spec", "law_fields", "ConnectionError_", "math"]
