"""DYNA_VIBRA's linear system and loads on a modal basis: the generalized
matrices and modal damping, EXCIT and EXCIT_RESU as load vectors times
multipliers, support motions (MULT_APPUI) and static corrections
(CORR_STAT) as the shocks see them, the rotating matrices
(VITESSE_VARIABLE='OUI')."""

from __future__ import annotations

import numpy as np
from asterlite.commands.dyna_vibra_keywords import list_values

from asterlite.concepts.function import Function
from asterlite.dynamics.model import (
    COMPONENTS,
    LinearSystem,
    diagonal_damping_rates,
    modal_damping_rates,
)
from asterlite.errors import missing_name
from asterlite.fem.selection import as_tuple
from asterlite.modal.renumber import transfer
from asterlite.modal.seismic import SeismicError, combined_static_shape


def linear_system(ctx, kw) -> LinearSystem:
    mass = np.array(kw["MATR_MASS"].matrix, dtype=float)
    stiffness = np.array(kw["MATR_RIGI"].matrix, dtype=float)
    rates = None  # code_aster's AMOR_DIA (LinearSystem.damping_rates)
    if kw.get("MATR_AMOR") is not None:
        damping = np.array(kw["MATR_AMOR"].matrix, dtype=float)
        numbering = getattr(kw["MATR_AMOR"], "numbering", None)
        if getattr(numbering, "storage", "PLEIN") == "DIAG" and damping.shape == mass.shape:
            rates = diagonal_damping_rates(mass, stiffness, damping)
    else:
        damping = np.zeros_like(mass)
        for occ in kw.factor("AMOR_MODAL"):
            ratios = occ.get("AMOR_REDUIT")
            if ratios is None and occ.get("LIST_AMOR") is not None:
                ratios = list_values(occ["LIST_AMOR"])
            if ratios is not None:
                ratios = np.atleast_1d(np.asarray(ratios, dtype=float))
                if ratios.size > mass.shape[0]:
                    ctx.error(
                        f"{ratios.size} damping ratios for {mass.shape[0]} modes",
                        "AMOR_REDUIT",
                        occ,
                    )
                rates = modal_damping_rates(mass, stiffness, ratios)
                damping = rates[:, None] * mass  # modal_damping
    if mass.shape != stiffness.shape or mass.shape != damping.shape:
        ctx.error("MATR_MASS, MATR_RIGI and the damping do not have the same size")
    return LinearSystem(mass, stiffness, damping, damping_rates=rates)


def excitations(ctx, kw, n_modes):
    loads = []
    for occ in kw.factor("EXCIT"):
        if occ.get("VECT_ASSE_GENE") is None:
            # a load on one generalized coordinate (code_aster's mdfext: f(NUME_ORDRE) += ...)
            number = int(occ["NUME_ORDRE"])
            if not 1 <= number <= n_modes:
                ctx.error(
                    f"NUME_ORDRE={number}: the basis has {n_modes} generalized coordinates",
                    "NUME_ORDRE",
                    occ,
                )
            vector = np.zeros(n_modes)
            vector[number - 1] = 1.0
        else:
            vector = np.asarray(occ["VECT_ASSE_GENE"].values, dtype=float)[:n_modes]
        mult = occ.get("FONC_MULT")
        if occ.get("ACCE") is not None:
            mult = occ["ACCE"]  # relative motion: the load is Φᵀ(-M ψ d) γ(t)
        elif mult is None:
            mult = float(occ.get("COEF_MULT", 1.0))
        loads.append((vector, mult))
    loads.extend(result_excitations(ctx, kw, n_modes))
    return loads


def load_labels(kw, count: int) -> list[str]:
    """How the deck names each excitation row: EXCIT[k], then EXCIT_RESU."""
    labels = [f"EXCIT[{k}]" for k in range(1, len(kw.factor("EXCIT")) + 1)]
    return (labels + ["EXCIT_RESU"] * count)[:count]


def result_excitations(ctx, kw, n_modes):
    """EXCIT_RESU (code_aster's mdrecf): the DEPL field of a tran_gene on
    the same modal basis, read as a generalized force history times
    COEF_MULT. Each generalized coordinate j gets a load on itself (as an
    EXCIT NUME_ORDRE=j) whose multiplier is the function of INST through
    the result's archived instants and values COEF_MULT DEPL_j, linear
    interpolation, PROL_GAUCHE/PROL_DROITE='EXCLU'."""

    basis = kw["MATR_MASS"].basis
    loads = []
    for number, occ in enumerate(kw.factor("EXCIT_RESU"), start=1):
        result = occ["RESULTAT"]
        alpha = float(occ["COEF_MULT"])
        same_basis = result.basis is basis or (
            result.basis.name is not None and result.basis.name == basis.name
        )
        if not same_basis:
            ctx.error(
                f"EXCIT_RESU occurrence {number}: the result {result.name or ''} is on the "
                f"modal basis {result.basis.name or '?'}, the generalized matrices on "
                f"{basis.name or '?'} (code_aster requires the same basis, ALGORITH17_18)",
                "RESULTAT",
                occ,
            )
        times = np.asarray(result.times, dtype=float)
        depl = np.asarray(result.depl, dtype=float)
        if depl.ndim != 2 or depl.shape[1] != n_modes:
            ctx.error(
                f"EXCIT_RESU occurrence {number}: the result holds {depl.shape[-1]} "
                f"generalized coordinates, the system {n_modes}",
                "RESULTAT",
                occ,
            )
        if times.size == 0 or np.any(np.diff(times) <= 0.0):
            ctx.error(
                f"EXCIT_RESU occurrence {number}: the result's instants must increase "
                "strictly (they become the abscissas of the force functions)",
                "RESULTAT",
                occ,
            )
        for j in range(n_modes):
            vector = np.zeros(n_modes)
            vector[j] = 1.0
            history = Function(
                abscissas=times.copy(),
                ordinates=alpha * depl[:, j],
                NOM_PARA="INST",
                INTERPOL=("LIN", "LIN"),
                PROL_GAUCHE="EXCLU",
                PROL_DROITE="EXCLU",
            )
            history.name = f"EXCIT_RESU{number}_{j + 1}"
            loads.append((vector, history))
    return loads


def static_corrections(ctx, kw, basis, system) -> list[dict]:
    """EXCIT CORR_STAT='OUI' (code_aster's mdrecf): for occurrence i, the
    static response to the load (field i of MODE_CORR) minus what the modes
    already carry, ψ_i = u_i - Σ_m (F_m / k_m) φ_m, times FONC_MULT,
    D_FONC_DT and D_FONC_DT2 for the DEPL / VITE / ACCE fields that
    REST_GENE_PHYS and RECU_FONCTION add. The generalized load itself is
    not modified (the shocks see ψ_i FONC_MULT as a support motion)."""

    corrections = []
    occs = kw.factor("EXCIT")
    for index, occ in enumerate(occs):
        if occ.get("CORR_STAT") != "OUI":
            continue
        static = kw.get("MODE_CORR")
        if static is None:
            ctx.error("EXCIT CORR_STAT='OUI' needs MODE_CORR", "MODE_CORR", kw)
        if occ.get("VECT_ASSE_GENE") is None or occ.get("FONC_MULT") is None:
            ctx.error("CORR_STAT='OUI' needs VECT_ASSE_GENE and FONC_MULT", "CORR_STAT", occ)
        fields = getattr(static, "fields", None)
        if fields is None:
            fields = static.shapes
        fields = np.asarray(fields, dtype=float)
        if index >= fields.shape[1]:
            ctx.error(
                f"MODE_CORR holds {fields.shape[1]} fields, EXCIT occurrence {index + 1} "
                "needs its own (code_aster pairs them by position)",
                "MODE_CORR",
                kw,
            )
        shape = transfer(fields[:, index], static.numbering, basis.numbering).copy()
        vector = np.asarray(occ["VECT_ASSE_GENE"].values, dtype=float)[: system.n_modes]
        stiffness = np.diag(system.stiffness)
        shapes = np.asarray(basis.shapes, dtype=float)
        for m in range(system.n_modes):
            shape -= vector[m] / stiffness[m] * shapes[:, m]
        corrections.append(
            {
                "shape": shape,
                "DEPL": occ["FONC_MULT"],
                "VITE": occ["D_FONC_DT"],
                "ACCE": occ["D_FONC_DT2"],
            }
        )
    return corrections


def support_motions(ctx, kw, basis) -> list[dict]:
    """MULT_APPUI supports: ψ = Σ_nodes Σ_c DIRECTION_c · (static mode of the
    node's component c) on the basis DOFs, with the support's DEPL / VITE /
    ACCE functions (REST_GENE_PHYS adds Σ ψ_k d_k(t) for absolute motion)."""
    supports = []
    kw.mark_used("MODE_STAT")  # support_shape reads it: code_aster uses it for MULT_APPUI only
    for occ in kw.factor("EXCIT"):
        if occ.get("MULT_APPUI") != "OUI":
            # without MULT_APPUI, code_aster (mdrecf) reads neither VITE nor DEPL:
            # ACCE alone multiplies the load vector
            occ.mark_used("VITE", "DEPL")
            continue
        shape = support_shape(ctx, kw, occ)
        supports.append(
            {"shape": shape, "DEPL": occ["DEPL"], "VITE": occ["VITE"], "ACCE": occ["ACCE"]}
        )
    return supports


def support_shape(ctx, kw, occ) -> np.ndarray:
    """Static shape of one EXCIT support (MULT_APPUI): Σ of MODE_STAT's modes
    at its nodes along DIRECTION, on MODE_STAT's numbering."""
    static = kw.get("MODE_STAT")
    if static is None:
        ctx.error("EXCIT MULT_APPUI='OUI' needs MODE_STAT", "MODE_STAT", kw)
    mesh = static.numbering.mesh
    nodes = []
    for group in as_tuple(occ.get("GROUP_NO")):
        if group not in mesh.node_groups:
            ctx.error(missing_name("node group", group, mesh.node_groups), "GROUP_NO", occ)
        nodes.extend(int(n) for n in mesh.node_groups[group])
    for name in as_tuple(occ.get("NOEUD")):
        index = mesh.find_node(name)
        if index is None:
            ctx.error(f"no node {name!r} in the mesh", "NOEUD", occ)
        nodes.append(index)
    direction = np.asarray(as_tuple(occ.get("DIRECTION")) or (1.0, 0.0, 0.0), dtype=float)
    try:
        return combined_static_shape(static, [mesh.node_names[n] for n in nodes], direction)
    except SeismicError as error:
        ctx.error(f"MODE_STAT: {error}", "MODE_STAT", kw)


def shock_support_shapes(shocks, basis, supports) -> np.ndarray:
    """ψ_k at each shock node: (n_shocks, 2, 3, n_supports)."""
    out = np.zeros((shocks.count, 2, 3, len(supports)))
    numbering = basis.numbering
    for s, spec in enumerate(shocks.specs):
        for j, node in enumerate((spec.node_1, spec.node_2)):
            if node is None:
                continue
            for c, comp in enumerate(COMPONENTS):
                try:
                    row = numbering.dof_index(node, comp)
                except KeyError:
                    continue
                for k, support in enumerate(supports):
                    out[s, j, c, k] = support["shape"][row]
    return out


def rotating_matrices(ctx, kw, system, t0, t_end, dt):
    """VITESSE_VARIABLE='OUI': C + Ω(t) G and K + Ω'(t) K_gy (or None)."""
    if kw.get("VITESSE_VARIABLE") != "OUI":
        return None

    n = system.n_modes
    gyro = np.array(kw["MATR_GYRO"].matrix, dtype=float)
    rigy = kw.get("MATR_RIGY")
    rigy = np.array(rigy.matrix, dtype=float) if rigy is not None else np.zeros((n, n))
    for name, matrix in (("MATR_GYRO", gyro), ("MATR_RIGY", rigy)):
        if matrix.shape != (n, n):
            ctx.error(f"{name} is {matrix.shape}, the system has {n} modes", name, kw)
    # code_aster (dtmupmat): a damping given per mode (AMOR_DIA: AMOR_MODAL, or a
    # MATR_AMOR stored DIAG) becomes M diag(c_i / m_i) there, the transpose of the
    # diag(c_i / m_i) M its constant-speed path applies (dtmacce); a full MATR_AMOR
    # is used as it is
    damping = system.damping
    if system.damping_rates is not None:
        damping = system.mass * system.damping_rates[None, :]
    # without ACCE_ROTA code_aster takes Ω' = 0 (and then ignores MATR_RIGY)
    acceleration = kw.get("ACCE_ROTA") if kw.get("MATR_RIGY") is not None else None
    from asterlite.dynamics.rotation import Rotation  # imported for the decks that vary it

    rotation = Rotation(damping, system.stiffness, gyro, rigy, kw["VITE_ROTA"], acceleration)
    rotation.tabulate(t0, t_end, dt / 2.0)
    return rotation
