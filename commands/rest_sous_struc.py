"""REST_SOUS_STRUC: results of a coupled generalized model on physical DOFs.

SOUS_STRUC restores Φ_k q_k on one substructure's numbering, in its own
frame (as code_aster's regeec); SQUELETTE restores every substructure,
rotated into the global frame, on the skeleton mesh. A mode_gene gives a
mode_meca (DEPL); a tran_gene a dyna_trans through REST_GENE_PHYS's
machinery with the restored basis."""

from __future__ import annotations

import numpy as np
from asterlite.commands.rest_gene_phys import chosen_modes, restore_harmonic, restore_transient

from asterlite.concepts.harmonic import HarmGene
from asterlite.concepts.modes import GeneralizedModes
from asterlite.concepts.substructure import SubstructuredNumbering
from asterlite.concepts.transient import TranGene
from asterlite.substructure.restitution import skeleton_modes, substructure_modes


def run(ctx, kw):
    for keyword in ("RESULTAT", "SECTEUR", "CYCLIQUE", "NUME_DDL"):
        if keyword in kw:
            ctx.unsupported(f"REST_SOUS_STRUC {keyword}", keyword, kw)
    result = kw["RESU_GENE"]
    if isinstance(result, GeneralizedModes):
        return _modes(ctx, kw, result)
    if isinstance(result, TranGene):
        return _transient(ctx, kw, result)
    if isinstance(result, HarmGene):
        return _harmonic(ctx, kw, result)
    ctx.unsupported(f"REST_SOUS_STRUC of a {result.aster_type}", "RESU_GENE", kw)


def _restored(ctx, kw, modes, indices):
    if not isinstance(modes.numbering, SubstructuredNumbering):
        ctx.error("RESU_GENE was not computed on a generalized model", "RESU_GENE", kw)
    if kw.get("SQUELETTE") is not None:
        skeleton = kw["SQUELETTE"]
        if skeleton.model is not modes.numbering.model:
            ctx.error("SQUELETTE was built on another generalized model", "SQUELETTE", kw)
        return skeleton_modes(modes, skeleton, indices)
    name = kw["SOUS_STRUC"]
    if modes.numbering.model.find(name) is None:
        ctx.error(f"no substructure {name!r} in the generalized model", "SOUS_STRUC", kw)
    return substructure_modes(modes, name, indices)


def _modes(ctx, kw, modes):
    names = [n for n in _names(kw.get("NOM_CHAM")) if n != "DEPL"]
    if names and kw.get("TOUT_CHAM") != "OUI":
        ctx.unsupported(f"NOM_CHAM={names[0]!r} of a mode_gene (DEPL only)", "NOM_CHAM", kw)
    for keyword in ("GROUP_NO", "NOEUD", "GROUP_MA", "MODE_MECA"):
        if keyword in kw:
            ctx.unsupported(f"REST_SOUS_STRUC {keyword} on a mode_gene", keyword, kw)
    chosen = chosen_modes(ctx, kw, modes)
    indices = np.arange(modes.n_modes) if chosen is None else np.asarray(chosen)
    return _restored(ctx, kw, modes, indices)


def _transient(ctx, kw, result):
    basis = result.basis
    if kw.get("MODE_MECA") is not None:
        basis = kw["MODE_MECA"]  # already restored on the skeleton / substructure
        kw.mark_used("SQUELETTE", "SOUS_STRUC")
    elif isinstance(basis, GeneralizedModes):
        basis = _restored(ctx, kw, basis, np.arange(basis.n_modes))
    else:
        ctx.unsupported(
            "REST_SOUS_STRUC of a transient computed on the assembled generalized matrices",
            "RESU_GENE",
            kw,
        )
    return restore_transient(ctx, kw, result, basis)


def _harmonic(ctx, kw, result):
    """A harm_gene (code_aster's rehaec / rehagl / harm75): computed on the
    coupled model's assembled matrices, each substructure's Φ_k q_k on
    SOUS_STRUC or, rotated, on the SQUELETTE; computed on a mode_gene, the
    modes restored by REST_SOUS_STRUC given as MODE_MECA. NOM_CHAM defaults
    to ACCE when TOUT_CHAM is absent, as in code_aster's catalogue."""

    if kw.peek("TOUT_CHAM") is None and kw.peek("NOM_CHAM") is None:
        dict.__setitem__(kw, "NOM_CHAM", ("ACCE",))
    basis = result.basis
    if isinstance(result.numbering, SubstructuredNumbering):
        if kw.get("MODE_MECA") is not None:
            ctx.error("MODE_MECA: the result is on the coupled model itself", "MODE_MECA", kw)
        n = result.numbering.n_modes
        unit = GeneralizedModes(
            numbering=result.numbering,
            vectors=np.eye(n),
            frequencies=np.zeros(n),
            generalized_mass=np.zeros(n),
            generalized_stiffness=np.zeros(n),
        )
        basis = _restored(ctx, kw, unit, np.arange(n))  # one shape per generalized DOF
    elif isinstance(basis, GeneralizedModes):
        if kw.get("MODE_MECA") is None:
            ctx.error(
                "give MODE_MECA: the modes of the mode_gene restored by REST_SOUS_STRUC",
                "MODE_MECA",
                kw,
            )
        basis = kw["MODE_MECA"]  # already restored on the skeleton / substructure
        kw.mark_used("SQUELETTE", "SOUS_STRUC")
    else:
        ctx.unsupported(
            "REST_SOUS_STRUC of a harmonic result on a mode_meca basis", "RESU_GENE", kw
        )
    return restore_harmonic(ctx, kw, result, basis)


def _names(value) -> tuple:
    if value is None:
        return ()
    return tuple(value) if isinstance(value, (list, tuple)) else (value,)
