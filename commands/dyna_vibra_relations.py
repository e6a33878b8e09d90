"""DYNA_VIBRA COMPORTEMENT: the relations other than DIS_CHOC, read.

Each relation of :mod:`asterlite.dynamics.laws` has a :class:`Reader`
here: the keywords that name its nodes, and ``read(occ)``, which fills the
relation's typed parameter record (``asterlite.dynamics.laws.<module>.
*Parameters``) from its validated COMPORTEMENT occurrence. The keywords are
read here only: the dynamics room receives the record, the nodes and the
transient's quantities a relation uses, as a
:class:`~asterlite.dynamics.laws.connections.LawConnection`.

``READERS`` is the table; :func:`register` adds a relation's reader (with
its entry in ``connections.RELATIONS`` and its catalogue block, see
docs/architecture.md).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

from asterlite.commands.dyna_vibra_shocks import single_node

from asterlite.dynamics.laws.anti_sism import AntiSismParameters
from asterlite.dynamics.laws.choc_elas_trac import ChocElasTracParameters
from asterlite.dynamics.laws.connections import (
    ConnectionError_,
    LawConnection,
    Obstacle,
    Rotation,
    law_spec,
)
from asterlite.dynamics.laws.dis_ecro_trac import DisEcroTracParameters
from asterlite.dynamics.laws.dis_visc import DisViscParameters
from asterlite.dynamics.laws.flambage import FlambageParameters, ScalarFlambageParameters
from asterlite.dynamics.laws.rela_effo_depl import RelationParameters
from asterlite.dynamics.laws.rotor_fiss import RotorFissParameters
from asterlite.dynamics.laws.tabulated import LawError
from asterlite.dynamics.model import ShockSpec
from asterlite.errors import worded

TWO_ENDS = (("NOEUD_1", "GROUP_NO_1"), ("NOEUD_2", "GROUP_NO_2"))


@dataclass(frozen=True)
class Reader:
    """How a relation's occurrence is read: the (node, group) keywords of
    its first and, if any, second node; whether the second may be absent;
    ``read(occ)``, the relation's parameter record from its validated
    occurrence (the catalogue filled its defaults: a reader restates none;
    a ``LawError`` for data that cannot define it); whether it acts on an obstacle (FLAMBAGE); and
    ``words``, the keyword of each field of the record, with which the
    messages of its module are worded (:func:`relation_words`)."""

    read: Callable[[object], object]
    ends: tuple[tuple[str, str], ...] = TWO_ENDS
    second_optional: bool = False
    obstacle: bool = False
    words: dict[str, str] = field(default_factory=dict)


def reals(value) -> tuple[float, ...]:
    if value is None:
        return ()
    return tuple(float(v) for v in (value if isinstance(value, (list, tuple)) else (value,)))


def read_flambage(occ):
    criterion = occ["CRIT_AMOR"]
    if occ.get("FNOR_CRIT") is not None:  # code_aster 15's scalar law (hidden keywords)
        return ScalarFlambageParameters(
            stiffness=float(occ["RIGI_NOR"]),
            damping=float(occ["AMOR_NOR"]),
            critical_force=float(occ["FNOR_CRIT"]),
            post_buckling_force=float(occ["FNOR_POST_FL"]),
            drop=float(occ["ENFO_FL"]),
            plateau=float(occ["LARG_PLAT"]),
            crushings=reals(occ.get("DEPL_POST_FL")),
            post_stiffnesses=reals(occ.get("RIGI_POST_FL")),
            post_dampings=reals(occ.get("AMOR_POST_FL")),
            buckling_damping=float(occ["AMOR_FL"]) if occ.get("AMOR_FL") is not None else None,
            damping_in_criterion=criterion == "INCLUS",
        )
    if criterion not in ("INCLUS", "EXCLUS"):
        raise LawError(f"FLAMBAGE/CRIT_AMOR: INCLUS or EXCLUS expected, not {criterion!r}")
    return FlambageParameters(
        force_threshold=occ.get("FX"),
        stiffness=occ.get("RIGI_NOR"),
        damping=occ.get("AMOR_NOR"),
        damping_in_criterion=criterion == "INCLUS",
    )


def read_anti_sism(occ):
    return AntiSismParameters(
        initial_stiffness=float(occ["RIGI_K1"]),
        final_stiffness=float(occ["RIGI_K2"]),
        threshold=float(occ["SEUIL_FX"]),
        viscosity=float(occ["C"]),
        exponent=float(occ["PUIS_ALPHA"]),
        stroke=float(occ["DX_MAX"]),
    )


def flexibility(occ, stiffness_key: str, flexibility_key: str) -> float:
    """A spring given by its stiffness or its flexibility, as a flexibility."""
    if occ.get(stiffness_key) is not None:
        k = float(occ[stiffness_key])
        if k <= 0.0:
            raise LawError(f"DIS_VISC: {stiffness_key} must be > 0")
        return 1.0 / k
    if occ.get(flexibility_key) is not None:
        s = float(occ[flexibility_key])
        if s < 0.0:
            raise LawError(f"DIS_VISC: {flexibility_key} must be >= 0")
        return s
    raise LawError(f"DIS_VISC: give {stiffness_key} or {flexibility_key}")


def read_dis_visc(occ):
    series = flexibility(occ, "K1", "UNSUR_K1")
    branch = flexibility(occ, "K3", "UNSUR_K3")
    if occ.get("K2") is not None:
        parallel = float(occ["K2"])
    elif occ.get("UNSUR_K2") is not None:
        if float(occ["UNSUR_K2"]) <= 0.0:
            raise LawError("DIS_VISC: UNSUR_K2 must be > 0")
        parallel = 1.0 / float(occ["UNSUR_K2"])
    else:
        raise LawError("DIS_VISC: give K2 or UNSUR_K2")
    return DisViscParameters(
        series_flexibility=series,
        parallel_stiffness=parallel,
        branch_flexibility=branch,
        viscosity=float(occ["C"]),
        exponent=float(occ["PUIS_ALPHA"]),
        max_iterations=int(occ["ITER_INTE_MAXI"]),
        tolerance=float(occ["RESI_INTE"]),
    )


def read_dis_ecro_trac(occ):
    axial = occ.get("FX") is not None
    key = "FX" if axial else "FTAN"
    if occ.get(key) is None:
        raise LawError("DIS_ECRO_TRAC: give FX or FTAN")
    kinematic = False
    if not axial:
        hardening = occ.get("ECROUISSAGE")
        if hardening not in ("ISOTROPE", "CINEMATIQUE"):
            raise LawError("DIS_ECRO_TRAC: FTAN needs ECROUISSAGE='ISOTROPE' or 'CINEMATIQUE'")
        kinematic = hardening == "CINEMATIQUE"
    return DisEcroTracParameters(
        curve=occ[key],
        axial=axial,
        kinematic=kinematic,
        max_iterations=int(occ["ITER_INTE_MAXI"]),
        tolerance=float(occ["RESI_INTE"]),
        curve_label=f"DIS_ECRO_TRAC/{key}",
    )


def read_choc_elas_trac(occ):
    return ChocElasTracParameters(
        force_curve=occ.get("FX"),
        distance_1=float(occ.get("DIST_1") or 0.0),
        distance_2=float(occ.get("DIST_2") or 0.0),
    )


def read_nodal_relation(occ):
    return RelationParameters(component=occ.get("NOM_CMP"), function=occ.get("FONCTION"))


def read_rotor_fiss(occ):
    return RotorFissParameters(
        stiffness=occ.get("K_PHI"),
        stiffness_derivative=occ.get("DK_DPHI"),
        initial_angle=float(occ["ANGL_INIT"]),
        angle=occ.get("ANGL_ROTA"),
    )


ONE_NODE = (("NOEUD", "GROUP_NO"),)
# the keyword each field of a relation's parameter record is read from
FLAMBAGE_WORDS = {
    "force_threshold": "FX",
    "stiffness": "RIGI_NOR",
    "damping": "AMOR_NOR",
    "critical_force": "FNOR_CRIT",
    "post_buckling_force": "FNOR_POST_FL",
    "drop": "ENFO_FL",
    "plateau": "LARG_PLAT",
    "crushings": "DEPL_POST_FL",
    "post_stiffnesses": "RIGI_POST_FL",
    "post_dampings": "AMOR_POST_FL",
    "buckling_damping": "AMOR_FL",
}
ANTI_SISM_WORDS = {
    "initial_stiffness": "RIGI_K1",
    "final_stiffness": "RIGI_K2",
    "threshold": "SEUIL_FX",
    "viscosity": "C",
    "exponent": "PUIS_ALPHA",
    "stroke": "DX_MAX",
}
LOCAL_INTEGRATION_WORDS = {"max_iterations": "ITER_INTE_MAXI", "tolerance": "RESI_INTE"}
DIS_VISC_WORDS = {
    "series_flexibility": "UNSUR_K1",
    "parallel_stiffness": "K2",
    "branch_flexibility": "UNSUR_K3",
    "viscosity": "C",
    "exponent": "PUIS_ALPHA",
    **LOCAL_INTEGRATION_WORDS,
}
NODAL_WORDS = {"component": "NOM_CMP", "function": "FONCTION"}
ROTOR_FISS_WORDS = {
    "stiffness": "K_PHI",
    "stiffness_derivative": "DK_DPHI",
    "initial_angle": "ANGL_INIT",
    "angle": "ANGL_ROTA",
}
READERS: dict[str, Reader] = {
    "FLAMBAGE": Reader(read_flambage, second_optional=True, obstacle=True, words=FLAMBAGE_WORDS),
    "ANTI_SISM": Reader(read_anti_sism, words=ANTI_SISM_WORDS),
    "DIS_VISC": Reader(read_dis_visc, words=DIS_VISC_WORDS),
    "DIS_ECRO_TRAC": Reader(read_dis_ecro_trac, words=LOCAL_INTEGRATION_WORDS),
    "CHOC_ELAS_TRAC": Reader(read_choc_elas_trac, words={"force_curve": "FX"}),
    "RELA_EFFO_DEPL": Reader(read_nodal_relation, ONE_NODE, words=NODAL_WORDS),
    "RELA_EFFO_VITE": Reader(read_nodal_relation, ONE_NODE, words=NODAL_WORDS),
    "ROTOR_FISS": Reader(
        read_rotor_fiss,
        (("NOEUD_D", "GROUP_NO_D"), ("NOEUD_G", "GROUP_NO_G")),
        words=ROTOR_FISS_WORDS,
    ),
}


@contextmanager
def relation_words(relation: str) -> Iterator[None]:
    """A ``LawError`` raised inside, worded with the keywords of
    ``relation``'s occurrence (its reader's ``words``)."""
    try:
        yield
    except LawError as error:
        reader = READERS.get(relation)
        raise LawError(worded(str(error), reader.words if reader else {})) from None


def register(relation: str, reader: Reader) -> None:
    """Add the reader of a relation registered in ``connections.RELATIONS``."""
    if relation in READERS:
        raise ValueError(f"relation {relation!r} already has a reader")
    READERS[relation] = reader


def read_obstacle(ctx, occ, second_node: bool) -> Obstacle:
    table = occ["OBSTACLE"]
    if table.obstacle_type.startswith("BI_") and not second_node:
        ctx.error(f"obstacle {table.obstacle_type} needs a second node", "OBSTACLE", occ)
    origin = occ.get("ORIG_OBST")
    return Obstacle(
        table=table,
        normal=occ["NORM_OBST"],
        twist=occ.get("ANGL_VRIL"),
        origin=origin,
        gap=float(occ["JEU"]),
        distance_1=float(occ.get("DIST_1") or 0.0),
        distance_2=float(occ.get("DIST_2") or 0.0),
    )


def transient_rotation(kw) -> Rotation:
    """DYNA_VIBRA's rotation as a cracked rotor sees it: at variable speed
    VITE_ROTA is a function and the angle is ANGL_ROTA(t)."""
    variable = kw["VITESSE_VARIABLE"] == "OUI"
    return Rotation(0.0 if variable else float(kw["VITE_ROTA"]), variable)


def nonlinearity_spec(ctx, kw, occ, basis, n_modes, number) -> ShockSpec:
    """A COMPORTEMENT occurrence of a relation other than DIS_CHOC
    (``asterlite.dynamics.laws``); ``number``: its 1-based rank among the
    call's nonlinearities (code_aster's default INTITULE)."""
    relation = occ["RELATION"]
    reader = READERS.get(relation)
    if reader is None:
        ctx.unsupported(f"COMPORTEMENT RELATION={relation!r}", "RELATION", occ)
    if occ.get("SOUS_STRUC_1") or occ.get("SOUS_STRUC_2"):
        ctx.unsupported("two-node nonlinearities on substructures", "SOUS_STRUC_1", occ)
    if not occ.get("SOUS_STRUC") and not hasattr(basis.numbering, "mesh"):
        ctx.error("the basis is a mode_gene: name the node's substructure", "SOUS_STRUC", occ)
    if occ.get("SOUS_STRUC"):  # the node's modes seen on its substructure
        from asterlite.substructure.shocks import SubstructureError, substructure_view

        try:
            basis = substructure_view(basis, occ["SOUS_STRUC"], "SOUS_STRUC")
        except SubstructureError as exc:
            ctx.error(str(exc), exc.keyword, occ)
    mesh = basis.numbering.mesh
    nodes = [single_node(ctx, occ, mesh, node_kw, group_kw) for node_kw, group_kw in reader.ends]
    if nodes[0] is None:
        ctx.error(f"{relation}: the node is missing", reader.ends[0][1], occ)
    node_2 = nodes[1] if len(nodes) > 1 else None
    if len(reader.ends) > 1 and node_2 is None and not reader.second_optional:
        ctx.error(f"{relation} needs two nodes", reader.ends[1][1], occ)
    try:
        with relation_words(relation):
            connection = LawConnection(
                relation=relation,
                parameters=reader.read(occ),
                node_1=nodes[0],
                node_2=node_2,
                number=number,
                title=occ.get("INTITULE"),
                obstacle=read_obstacle(ctx, occ, node_2 is not None) if reader.obstacle else None,
                rotation=transient_rotation(kw),
                true_distance=int(kw.get("INFO", 1)) == 2,
            )
            return law_spec(connection, basis, n_modes)
    except ConnectionError_ as error:
        ctx.error(str(error), reader.ends[min(error.end, len(reader.ends) - 1)][1], occ)
    except LawError as error:
        ctx.error(str(error), "RELATION", occ)
