"""DEFI_MODELE_GENE: place the macro-elements and glue their interfaces.

Each SOUS_STRUC is put in the global frame (x = R x_local + TRANS, R from
ANGL_NAUT in degrees); each LIAISON pairs the nodes of two interfaces by
proximity in the global frame, as code_aster does, and the pairing is
checked against VERIF's PRECISION (relative to the size of the model, or
absolute)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.substructure import GeneralizedModel, Link, Substructure
from asterlite.substructure.coupling import CouplingError, pair_nodes, placement_rotation


def run(ctx, kw):
    return build_model(ctx, kw)


def build_model(ctx, kw):
    """The model of SOUS_STRUC, LIAISON and VERIF (also ASSE_ELEM_SSD's,
    where ANGL_NAUT and TRANS may be left out: no rotation, no shift)."""
    substructures = []
    for occ in kw.factor("SOUS_STRUC"):
        if any(s.name == occ["NOM"] for s in substructures):
            ctx.error(f"substructure {occ['NOM']!r} is defined twice", "NOM", occ)
        translation = np.zeros(3)
        given = np.asarray(occ.get("TRANS") or (0.0,), dtype=float).ravel()[:3]
        translation[: given.size] = given
        rotation = placement_rotation(occ.get("ANGL_NAUT") or (0.0,))
        substructures.append(Substructure(occ["NOM"], occ["MACR_ELEM_DYNA"], rotation, translation))
    model = GeneralizedModel(substructures, [])
    verif = (kw.factor("VERIF") or [{}])[0]
    precision = float(verif.get("PRECISION", 1.0e-3))
    relative = verif.get("CRITERE", "RELATIF") == "RELATIF"
    stop = verif.get("STOP_ERREUR", "OUI") == "OUI"
    for occ in kw.factor("LIAISON"):
        model.links.append(_link(ctx, occ, model, precision, relative, stop))
    ctx.log(f"generalized model: {len(substructures)} substructures, {len(model.links)} links")
    return model


def _link(ctx, occ, model, precision, relative, stop) -> Link:
    for keyword in ("GROUP_MA_MAIT_1", "GROUP_MA_MAIT_2"):
        if keyword in occ:
            ctx.unsupported(f"LIAISON {keyword} (incompatible interface meshes)", keyword, occ)
    if occ.get("OPTION", "CLASSIQUE") != "CLASSIQUE":
        ctx.unsupported("LIAISON OPTION='REDUIT'", "OPTION", occ)
    sides = []
    for k in ("1", "2"):
        sub = model.find(occ[f"SOUS_STRUC_{k}"])
        if sub is None:
            ctx.error(f"no substructure {occ[f'SOUS_STRUC_{k}']!r}", f"SOUS_STRUC_{k}", occ)
        interface = sub.macro.interfaces.find(occ[f"INTERFACE_{k}"])
        if interface is None:
            ctx.error(
                f"substructure {sub.name} has no interface {occ[f'INTERFACE_{k}']!r}",
                f"INTERFACE_{k}",
                occ,
            )
        sides.append((sub, interface))
    (s1, i1), (s2, i2) = sides
    try:
        pairs = pair_nodes(s1, i1, s2, i2, precision if stop else np.inf, relative)
    except CouplingError as exc:
        ctx.error(str(exc), "LIAISON", occ)
    return Link(s1.name, i1.name, s2.name, i2.name, pairs)
