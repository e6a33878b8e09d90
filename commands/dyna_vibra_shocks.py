"""DYNA_VIBRA COMPORTEMENT on a modal basis: the DIS_CHOC shocks and the
relations of ``asterlite.dynamics.laws`` as shock specifications, their
fluid films (LAME_FLUIDE), their implicit treatment (TRAITEMENT_NONL), the
VERI_CHOC check of the basis, and the warnings about how a scheme treats
them."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from asterlite.catalog.validator import default_occurrence
from asterlite.concepts.titles import default_title
from asterlite.dynamics.basis_check import node_checks
from asterlite.dynamics.model import (
    COMPONENTS,
    MODAL,
    NORMAL,
    TANGENTIAL,
    ShockSpec,
    optimal_tangential_damping_v15,
)
from asterlite.dynamics.schemes import SCHEMES
from asterlite.dynamics.step_limits import contact_limit
from asterlite.errors import missing_name
from asterlite.fem.selection import as_tuple
from asterlite.legacy.v15 import computes
from asterlite.substructure.shocks import SubstructureError, in_global_frame

if TYPE_CHECKING:
    from asterlite.dynamics.fluid_film import FluidFilm
from asterlite.substructure.shocks import substructure_view as view

FRICTION_KEYWORDS = ("COULOMB", "COULOMB_DYNA", "COULOMB_STAT")
# the keywords of the stiffness or damping that sets a stability limit (model.StabilityLimit,
# model.DampedLimit), as the messages name them
STIFFNESS_KEYWORDS = {NORMAL: "RIGI_NOR", TANGENTIAL: "RIGI_TAN"}
DAMPING_KEYWORDS = {NORMAL: "AMOR_NOR", TANGENTIAL: "AMOR_TAN", MODAL: "AMOR_REDUIT"}


def shock_specs(ctx, occ, basis, n_modes, first: int = 1) -> list[ShockSpec]:
    """The shocks of one DIS_CHOC occurrence; ``first``: the rank of its
    first among the call's nonlinearities (code_aster's default INTITULE)."""
    relation = occ.get("RELATION")
    if relation != "DIS_CHOC":
        ctx.unsupported(f"COMPORTEMENT RELATION={relation!r} (only DIS_CHOC)", "RELATION", occ)
    basis_1, basis_2, norm_obst, orig = substructured_views(ctx, occ, basis)
    mesh = basis_1.numbering.mesh
    obstacle = occ["OBSTACLE"]
    kind = obstacle.obstacle_type
    if basis_2 is basis_1:
        pairs = node_pairs(ctx, occ, mesh)
    else:  # nodes of two substructures: each looked up in its own mesh
        pairs = [
            (
                single_node(ctx, occ, mesh, "NOEUD_1", "GROUP_NO_1"),
                single_node(ctx, occ, basis_2.numbering.mesh, "NOEUD_2", "GROUP_NO_2"),
            )
        ]
    mesh_2 = basis_2.numbering.mesh
    two_nodes = kind.startswith("BI_")
    specs = []
    for index, (n1, n2) in enumerate(pairs):
        if two_nodes and n2 is None:
            ctx.error(
                f"obstacle {kind} needs a second node (NOEUD_2/GROUP_NO_2 or GROUP_MA)",
                "OBSTACLE",
                occ,
            )
        friction = occ.get("FROTTEMENT")
        mu_dyn = mu_stat = 0.0
        if friction == "COULOMB":
            mu_dyn = mu_stat = float(occ["COULOMB"])
        elif friction == "COULOMB_STAT_DYNA":
            mu_dyn, mu_stat = float(occ["COULOMB_DYNA"]), float(occ["COULOMB_STAT"])
        name = occ.get("INTITULE") or default_title("DIS_CHOC", first + index)
        if occ.get("INTITULE") and len(pairs) > 1:
            name = f"{occ['INTITULE']}_{index + 1}"
        spec = ShockSpec(
            name=name,
            obstacle_type=kind,
            node_1=mesh.node_names[n1],
            node_2=mesh_2.node_names[n2] if n2 is not None else None,
            coord_1=np.array(mesh.coords[n1], dtype=float),
            coord_2=np.array(mesh_2.coords[n2], dtype=float) if n2 is not None else None,
            phi_1=node_shape(basis_1, n1, n_modes),
            phi_2=node_shape(basis_2, n2, n_modes) if n2 is not None else None,
            norm_obst=norm_obst,
            angl_vril=occ.get("ANGL_VRIL"),
            orig_obst=np.asarray(orig, dtype=float) if orig is not None else None,
            gap=float(occ["JEU"]),
            dist_1=float(occ.get("DIST_1") or 0.0),
            dist_2=float(occ.get("DIST_2") or 0.0),
            k_n=float(occ["RIGI_NOR"]),
            c_n=float(occ["AMOR_NOR"]),
            k_t=float(occ["RIGI_TAN"]),
            c_t=float(occ["AMOR_TAN"]) if occ.get("AMOR_TAN") is not None else None,
            mu_dyn=mu_dyn,
            mu_stat=mu_stat,
            unidirectional=occ.get("UNIDIRECTIONNEL") == "OUI",
            polar=obstacle.polar if kind == "DISCRET" else None,
        )
        if kind == "BI_CERC_INT" and spec.dist_2 < spec.dist_1:
            ctx.error("BI_CERC_INT needs DIST_2 (outer radius) >= DIST_1", "DIST_2", occ)
        specs.append(spec)
    return specs


def substructured_views(ctx, occ, basis):
    """(basis of node 1, basis of node 2, NORM_OBST, ORIG_OBST): with
    SOUS_STRUC_1/2 the modes seen on those substructures in the global
    frame, and the obstacle's frame REPERE turned into the global one
    (asterlite.substructure.shocks); otherwise ``basis`` twice."""

    norm, orig = np.asarray(occ["NORM_OBST"], dtype=float), occ.get("ORIG_OBST")
    orig = np.asarray(orig, dtype=float) if orig is not None else None
    names = (occ.get("SOUS_STRUC_1"), occ.get("SOUS_STRUC_2"))
    repere = occ["REPERE"]
    if names[0] is None and not hasattr(basis.numbering, "mesh"):  # modes of a mode_gene
        ctx.error("the basis is a mode_gene: name the node's substructure", "SOUS_STRUC_1", occ)
    if names == (None, None) and repere == "GLOBAL":
        return basis, basis, norm, orig
    if occ.get("GROUP_MA") or occ.get("MAILLE"):
        ctx.unsupported("GROUP_MA/MAILLE shocks on substructures", "GROUP_MA", occ)
    try:
        basis_1 = view(basis, names[0], "SOUS_STRUC_1") if names[0] else basis
        basis_2 = basis_1
        if names[1] and names[1] != names[0]:
            basis_2 = view(basis, names[1], "SOUS_STRUC_2")
        orig, norm = in_global_frame(basis, repere, orig, norm)
    except SubstructureError as exc:
        ctx.error(str(exc), exc.keyword, occ)
    return basis_1, basis_2, norm, orig


def node_pairs(ctx, occ, mesh) -> list[tuple[int, int | None]]:
    """(node 1, node 2) indices: one pair per SEG2 cell of GROUP_MA/MAILLE,
    or the single NOEUD_1/GROUP_NO_1 (+ NOEUD_2/GROUP_NO_2)."""
    cells = []
    for group in as_tuple(occ.get("GROUP_MA")):
        if group not in mesh.cell_groups:
            ctx.error(missing_name("cell group", group, mesh.cell_groups), "GROUP_MA", occ)
        cells.extend(int(c) for c in mesh.cell_groups[group])
    for name in as_tuple(occ.get("MAILLE")):
        cells.append(mesh.cell_index[name])
    if cells:
        pairs = []
        for c in cells:
            nodes = mesh.cell_nodes[c]
            if len(nodes) != 2:
                ctx.error(f"cell {mesh.cell_names[c]} is not a SEG2", "GROUP_MA", occ)
            pairs.append((int(nodes[0]), int(nodes[1])))
        return pairs
    n1 = single_node(ctx, occ, mesh, "NOEUD_1", "GROUP_NO_1")
    n2 = single_node(ctx, occ, mesh, "NOEUD_2", "GROUP_NO_2")
    return [(n1, n2)]


def single_node(ctx, occ, mesh, node_kw, group_kw) -> int | None:
    if occ.get(node_kw) is not None:
        name = occ[node_kw]
        index = mesh.find_node(name)  # also code_aster 17's positional N<i> names
        if index is None:
            ctx.error(f"no node {name!r} in the mesh", node_kw, occ)
        return index
    if occ.get(group_kw) is not None:
        group = occ[group_kw]
        if group not in mesh.node_groups:
            ctx.error(missing_name("node group", group, mesh.node_groups), group_kw, occ)
        nodes = mesh.node_groups[group]
        if len(nodes) != 1:
            ctx.error(
                f"group {group!r} must hold exactly one node (it has {len(nodes)})", group_kw, occ
            )
        return int(nodes[0])
    return None


def node_shape(basis, node: int, n_modes: int) -> np.ndarray:
    return np.array([basis.shape_at(node, c)[:n_modes] for c in COMPONENTS], dtype=float)


def continue_law_states(kw, specs) -> None:
    """ETAT_INIT=_F(RESULTAT=...): the laws' internal variables (crushing,
    viscous state...) continue from the previous run's state at that instant."""
    occs = kw.factor("ETAT_INIT")
    previous = occs[0].get("RESULTAT") if occs else None
    if previous is None or not getattr(previous, "shocks", None):
        return
    occ = occs[0]
    if occ.get("NUME_ORDRE") is not None:
        hits = np.nonzero(previous.order == occ["NUME_ORDRE"])[0]
        k = int(hits[0]) if hits.size else len(previous.times) - 1
    elif occ.get("INST_INIT") is not None:
        k = int(np.argmin(np.abs(previous.times - occ["INST_INIT"])))
    else:
        k = len(previous.times) - 1
    for index, spec in enumerate(specs):
        if spec.relation == "DIS_CHOC" or index >= len(previous.shocks):
            continue
        old = previous.shocks[index]
        if old.relation != spec.relation or spec.law_state is None and "VINT1" not in old.fields:
            continue
        values = []
        while f"VINT{len(values) + 1}" in old.fields:
            values.append(float(np.asarray(old.fields[f"VINT{len(values) + 1}"])[k]))
        if values:
            spec.law_state = np.array(values)


def legacy_tangential_damping(ctx, system, specs) -> None:
    """A deck of code_aster 13 to 15 giving RIGI_TAN without AMOR_TAN: the
    default AMOR_TAN those versions computed (it can be negative), set on
    the shock before the model is built; code_aster 17's otherwise."""
    if not computes(ctx.session, "AMOR_TAN_DEFAULT_MAX_MODAL_MASS"):
        return
    for spec in specs:
        if spec.relation != "DIS_CHOC" or spec.c_t is not None:
            continue
        if spec.k_t > np.finfo(float).eps:
            spec.c_t = optimal_tangential_damping_v15(spec, system)
            ctx.log(
                f"{spec.name}: AMOR_TAN = {spec.c_t:.6g} as code_aster 13-15 computed it "
                "(mode of largest generalized mass, its AMOR_DIA taken for the reduced "
                "damping, not floored at 0)"
            )


def fluid_film(ctx, kw, scheme, system, occurrences) -> FluidFilm | None:
    """The fluid films of the shocks (COMPORTEMENT/LAME_FLUIDE='OUI', an
    asterlite extension reached from code_aster 10-14 decks), or None."""
    films = [occ for occ in occurrences if occ.get("LAME_FLUIDE") == "OUI"]
    if not films:
        return None
    from asterlite.dynamics.fluid_film import N_FILM, FluidFilm, film_row  # films' decks only

    where = films[0]
    # code_aster 10-12's EULER (asterlite's DIFF_CENTRE arithmetic, the name
    # legacy decks are translated to), and its ADAPT_ORDRE2 (mdadap) in decks
    # of those versions (Scheme.film, Scheme.film_legacy)
    entry = SCHEMES[scheme]
    legacy_adapt = entry.film_legacy and computes(ctx.session, "ADAPT_ORDRE2_MDADAP")
    if not entry.film and not legacy_adapt:
        ctx.unsupported(
            f"LAME_FLUIDE='OUI' with SCHEMA={scheme!r} (only code_aster 10-12's EULER, "
            "SCHEMA='DIFF_CENTRE' here, and that version's ADAPT_ORDRE2 in its decks)",
            "LAME_FLUIDE",
            where,
        )
    if not system.diagonal:
        ctx.unsupported(
            "LAME_FLUIDE='OUI' with non-diagonal generalized matrices (code_aster 11 "
            "modifies a diagonal modal mass only)",
            "LAME_FLUIDE",
            where,
        )
    for occ in occurrences:
        if occ.get("RELATION") != "DIS_CHOC":
            ctx.unsupported(
                f"LAME_FLUIDE='OUI' together with RELATION={occ.get('RELATION')!r}",
                "RELATION",
                occ,
            )
    for occ in films:
        for key in FRICTION_KEYWORDS:
            if occ.get(key):
                ctx.unsupported(f"{key} on a shock with LAME_FLUIDE='OUI'", key, occ)
    rows = np.zeros((len(occurrences), N_FILM))
    for s, occ in enumerate(occurrences):
        if occ.get("LAME_FLUIDE") == "OUI":
            rows[s] = film_row(occ["ALPHA"], occ["BETA"], occ["CHI"], occ["DELTA"])
    # the iterations' controls: the deck's, or the defaults of an empty
    # occurrence where it gives none
    [controls] = kw.factor("PARA_LAME_FLUI") or default_occurrence(kw, "PARA_LAME_FLUI")
    return FluidFilm(
        rows,
        max_iterations=int(controls["NMAX_ITER"]),
        tolerance=float(controls["RESI_RELA"]),
        relaxation=float(controls["LAMBDA"]),
    )


def refuse_with_film(ctx, kw, implicit, rotation, energy, driven) -> None:
    """What the fluid film loop does not combine with, refused by keyword."""
    refused = (
        (implicit, "TRAITEMENT_NONL", "TRAITEMENT_NONL='IMPLICITE'"),
        (rotation is not None, "VITESSE_VARIABLE", "VITESSE_VARIABLE='OUI'"),
        (energy, "ENERGIE", "ENERGIE"),
        (bool(driven), "EXCIT", "support motions (MULT_APPUI) or static corrections"),
    )
    for present, keyword, what in refused:
        if present:
            ctx.unsupported(f"{what} with LAME_FLUIDE='OUI'", keyword, kw)


def implicit_shocks(ctx, kw) -> bool:
    """TRAITEMENT_NONL='IMPLICITE': whether the shocks' normal forces are
    treated implicitly (:mod:`asterlite.dynamics.implicit_shocks`). As in
    code_aster (dtmprep_noli), only DIS_CHOC connections are concerned:
    without any, the run is the explicit one."""
    if kw.get("TRAITEMENT_NONL") != "IMPLICITE":
        return False
    if not any(occ.get("RELATION") == "DIS_CHOC" for occ in kw.factor("COMPORTEMENT")):
        ctx.log(
            "TRAITEMENT_NONL='IMPLICITE' without DIS_CHOC: explicit treatment, as code_aster "
            "(its implicit treatment only concerns DIS_CHOC connections)"
        )
        return False
    if kw.get("VITESSE_VARIABLE") == "OUI":
        ctx.unsupported(
            "TRAITEMENT_NONL='IMPLICITE' with VITESSE_VARIABLE='OUI' (the contact "
            "linearisation and the rotation speed would both rewrite K and C)",
            "TRAITEMENT_NONL",
            kw,
        )
    return True


def refuse_moving_gaps(ctx, kw, driven) -> None:
    """Implicit shocks linearise each gap into K q plus a constant force; a
    support motion (MULT_APPUI, CORR_STAT) moves the gap with time."""
    if driven:
        ctx.unsupported(
            "TRAITEMENT_NONL='IMPLICITE' with support motions seen by the shocks "
            "(MULT_APPUI or CORR_STAT): the linearised gap would not follow the supports; "
            "use TRAITEMENT_NONL='EXPLICITE'",
            "TRAITEMENT_NONL",
            kw,
        )


# the energy gain per impact beyond which warn_lagged_shocks warns
# (docs/accuracy.md measured the gains on elastic bounces)
IMPACT_GAIN_WARNED = 0.01


def warn_lagged_shocks(ctx, scheme, system, shocks, dt) -> None:
    """NEWMARK and TRBDF2 with TRAITEMENT_NONL='EXPLICITE' take the shock
    forces of the previous state into their implicit step: every elastic
    impact gains energy, about ``Scheme.lagged_impact_gain``·ω_c·dt of it with ω_c the
    pulsation of the mode stiffened by the shock. Warn, naming the shock and
    the steps that keep the gain below 1 %, when it exceeds 1 %."""
    factor = SCHEMES[scheme].lagged_impact_gain
    if factor is None or not shocks.count:
        return

    limit = contact_limit(system, shocks)
    if limit.shock is None:
        return
    omega = 2.0 * math.pi / limit.period
    gain = factor * omega * dt
    if gain <= IMPACT_GAIN_WARNED:
        return
    step = IMPACT_GAIN_WARNED / (factor * omega)
    ctx.log(
        f"warning: {scheme} with TRAITEMENT_NONL='EXPLICITE' applies the shock forces of "
        f"the previous state: each elastic impact gains about {100.0 * gain:.3g} % of its "
        f"energy at PAS={dt:.6g} ({factor:g}·ω·dt, ω = {omega:.6g} rad/s set by "
        f"{limit.cause(STIFFNESS_KEYWORDS)}); use TRAITEMENT_NONL='IMPLICITE' "
        "(energy-consistent impacts) or "
        f"PAS <= {step:.3g} for less than 1 %"
    )


def check_basis_for_shocks(ctx, kw, specs, basis, system) -> None:
    """VERI_CHOC: warn, or stop with STOP_CRITERE='OUI', when the basis misses
    too much of a shock node's static compliance (asterlite.dynamics.basis_check)."""

    occ = kw.factor("VERI_CHOC")[0]
    stop = occ["STOP_CRITERE"] == "OUI"
    if getattr(basis, "stiffness", None) is None:  # also a mode_gene (no physical matrices)
        ctx.unsupported("VERI_CHOC on a basis without its assembled stiffness", "VERI_CHOC", kw)
    checks = node_checks(specs, basis, np.diag(system.stiffness))
    for check in checks:
        ctx.log(
            f"VERI_CHOC {check.shock} node {check.node}: static flexibility "
            f"{check.static_flexibility:.4g}, restitution by the modes {check.restitution:.4f}, "
            f"criterion {check.criterion:.4g}"
        )
    worst = max((c.criterion for c in checks), default=0.0)
    if worst > occ["SEUIL"]:
        message = (
            f"the modal basis misses the static deflection of a shock node: criterion "
            f"{worst:.4g} > SEUIL {occ['SEUIL']:g} (add modes or static modes at the shock nodes)"
        )
        if stop:
            ctx.error(message, "VERI_CHOC", kw)
        ctx.log(f"warning: {message}")
