"""CREA_ELEM_SSD: a dynamic macro-element in one command.

As code_aster's macro: the stiffness and mass of the model under CHARGE,
their numbering (bound to NUME_DDL's CO("NAME")), the modes of CALC_FREQ
(one search per band with OPTION='BANDE'), the interfaces, the classical
basis (NMAX_MODE = NMAX_FREQ) and the macro-element on those matrices."""

from __future__ import annotations

import numpy as np
from asterlite.commands.defi_base_modale import classical_basis
from asterlite.commands.nume_ddl import numbering_for

from asterlite.concepts.assembly import AssembledMatrix
from asterlite.concepts.substructure import DynamicInterfaces, Interface, MacroElement
from asterlite.fem.assemble import assemble_blocks
from asterlite.fem.constraints import ConstraintError
from asterlite.fem.elements import ElementError
from asterlite.fem.options import option_blocks
from asterlite.fem.selection import as_tuple, select_nodes
from asterlite.modal.calc import build_mode_result, constrained_pencil, residuals, select_modes
from asterlite.modal.eigen import EigenError
from asterlite.modal.projection import project_matrix
from asterlite.substructure.interfaces import interface_dofs


def run(ctx, kw):
    if kw.factor("BASE_MODALE")[0]["TYPE"] != "CLASSIQUE":
        ctx.unsupported("CREA_ELEM_SSD BASE_MODALE TYPE='RITZ'", "BASE_MODALE", kw)
    kw.mark_used("SOLVEUR", "INFO")
    model, loads = kw["MODELE"], list(as_tuple(kw.get("CHARGE")))
    cara, mater = kw.get("CARA_ELEM"), kw.get("CHAM_MATER")
    numbering = numbering_for(model, loads, cara, mater)
    if kw.get("NUME_DDL") is not None:
        ctx.bind(kw["NUME_DDL"], numbering)
    stiffness = _assembled(ctx, kw, numbering, "RIGI_MECA", "RIGI")
    mass = _assembled(ctx, kw, numbering, "MASS_MECA", "MASS")
    calc_freq = kw.factor("CALC_FREQ")[0]
    modes = _modes(ctx, calc_freq, stiffness, mass)
    interfaces = _interfaces(ctx, kw, numbering)
    nmax = int(calc_freq.get("NMAX_FREQ", 10))
    basis = classical_basis(ctx, kw, interfaces, (modes,), (nmax,))
    ctx.log(f"macro-element: {basis.n_modes} generalized DOFs")
    return MacroElement(
        basis=basis,
        interfaces=interfaces,
        stiffness=project_matrix(basis.shapes, stiffness.matrix),
        mass=project_matrix(basis.shapes, mass.matrix),
    )


def _assembled(ctx, kw, numbering, option, kind):
    model, cara, mater = kw["MODELE"], kw.get("CARA_ELEM"), kw.get("CHAM_MATER")
    try:
        blocks = option_blocks(model, cara, option, materials=mater)
    except NotImplementedError as exc:
        ctx.unsupported(str(exc), "MODELE", kw)
    except (ElementError, ValueError) as exc:
        ctx.error(str(exc), "CARA_ELEM", kw)
    matrix = assemble_blocks(blocks, numbering)
    return AssembledMatrix(numbering, matrix, kind, model, cara, mater)


def _modes(ctx, occ, stiffness, mass):
    """The modes of CALC_FREQ, bands one after the other."""
    option = occ.get("OPTION", "PLUS_PETITE")
    if option == "SANS":
        ctx.unsupported("CALC_FREQ OPTION='SANS' with a CLASSIQUE basis", "OPTION", occ)
    occ.mark_used("APPROCHE", "DIM_SOUS_ESPACE")
    nmax = int(occ.get("NMAX_FREQ", 10))
    if option == "BANDE":
        freq = as_tuple(occ["FREQ"])
        searches = [("BANDE", (freq[k], freq[k + 1])) for k in range(len(freq) - 1)]
    elif option == "CENTRE":
        if occ.get("AMOR_REDUIT") is not None:
            ctx.unsupported("CALC_FREQ AMOR_REDUIT", "AMOR_REDUIT", occ)
        searches = [("CENTRE", as_tuple(occ["FREQ"]))]
    else:
        searches = [("PLUS_PETITE", ())]
    try:
        pencil = constrained_pencil(stiffness, mass)
        found = [select_modes(pencil, name, window, nmax) for name, window in searches]
    except (EigenError, ConstraintError) as exc:
        ctx.error(str(exc), "CALC_FREQ", occ)
    omega2 = np.concatenate([w for w, _ in found])
    vecs = np.hstack([v for _, v in found])
    if omega2.size == 0:
        ctx.error("no eigenmode found for this selection", "CALC_FREQ", occ)
    res = residuals(pencil, omega2, vecs)
    if occ.get("STOP_ERREUR", "OUI") == "OUI" and np.any(res > 1e-6):
        ctx.error(f"a mode has a residual {res.max():.3g} above 1e-06", "STOP_ERREUR", occ)
    modes = build_mode_result(stiffness, mass, omega2, pencil.expand(vecs))
    for k, f in enumerate(modes.frequencies, start=1):
        ctx.log(f"mode {k:4d}  {f:14.6e} Hz")
    return modes


def _interfaces(ctx, kw, numbering) -> DynamicInterfaces:
    """DEFI_INTERF_DYNA of the INTERFACE occurrences; FREQ is the first
    occurrence's, or the last one that differs from it (code_aster warns)."""
    interfaces, frequency = [], None
    for occ in kw.factor("INTERFACE"):
        nodes = np.sort(select_nodes(ctx, occ, numbering.mesh))
        masked = as_tuple(occ.get("MASQUE"))
        dofs, owners = interface_dofs(numbering, nodes, masked)
        if dofs.size == 0:
            ctx.error(f"interface {occ['NOM']!r} holds no DOF", "GROUP_NO", occ)
        interfaces.append(Interface(occ["NOM"], occ["TYPE"], nodes, masked, dofs, owners))
        value = float(occ.get("FREQ", 1.0))
        if frequency is None:
            frequency = first = value
        elif value != first:
            frequency = value
    if frequency != first:
        ctx.log(f"warning: the interfaces' FREQ differ; {frequency} is used")
    return DynamicInterfaces(numbering, interfaces, frequency)
