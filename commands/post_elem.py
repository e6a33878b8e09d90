"""POST_ELEM MASS_INER: mass, centre of gravity and inertia into a table;
ENER_CIN: kinetic energy of element groups (asterlite.post.kinetic_energy)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import ModeResult
from asterlite.concepts.table import Table
from asterlite.errors import missing_name
from asterlite.fem.elements import ElementError
from asterlite.fem.mass_properties import mass_properties
from asterlite.fem.selection import as_tuple
from asterlite.post.kinetic_energy import kinetic_energy
from asterlite.post.restitution import selection_from_keywords

_COLUMNS = (
    "MASSE", "CDG_X", "CDG_Y", "CDG_Z", "IX_G", "IY_G", "IZ_G", "IXY_G", "IXZ_G", "IYZ_G",
    "IX_PRIN_G", "IY_PRIN_G", "IZ_PRIN_G",
)  # fmt: skip


def run(ctx, kw):
    if kw.factor("ENER_CIN"):
        return kinetic_energy_table(ctx, kw)
    if kw.get("GEOMETRIE", "INITIALE") != "INITIALE":
        ctx.unsupported("POST_ELEM GEOMETRIE='DEFORMEE'", "GEOMETRIE", kw)
    model = kw.get("MODELE")
    if model is None:
        ctx.error("MASS_INER needs MODELE", "MODELE", kw)
    characteristics = kw.get("CARA_ELEM")
    materials = kw.get("CHAM_MATER")
    mesh = model.mesh
    table = Table(title=kw.get("TITRE") or "")
    table.add_column("LIEU", "K24")
    table.add_column("ENTITE", "K8")
    for name in _COLUMNS:
        table.add_column(name, "R")
    for occ in kw.factor("MASS_INER"):
        if occ.get("TOUT") == "OUI":
            places = [(mesh.name or "MAILLAGE", "TOUT", None)]
        else:
            places = []
            for group in as_tuple(occ.get("GROUP_MA")):
                if group not in mesh.cell_groups:
                    ctx.error(missing_name("cell group", group, mesh.cell_groups), "GROUP_MA", occ)
                places.append((group, "GROUP_MA", mesh.cell_groups[group]))
        for lieu, entity, cells in places:
            try:
                values = mass_properties(model, characteristics, materials, cells)
            except NotImplementedError as exc:
                ctx.unsupported(str(exc), "MODELE", kw)
            except (ElementError, ValueError) as exc:
                ctx.error(str(exc), "CARA_ELEM", kw)
            table.add_row({"LIEU": lieu, "ENTITE": entity, **values})
            ctx.log(
                f"MASS_INER {lieu}: mass {values['MASSE']:.6g}, centre of gravity "
                f"({values['CDG_X']:.6g}, {values['CDG_Y']:.6g}, {values['CDG_Z']:.6g})"
            )
    return table


def kinetic_energy_table(ctx, kw):
    """ENER_CIN of a transient result (VITE) or of modes (½ ω² φᵀ M φ with
    DEPL): per order and group, TOTALE and its share of the whole model
    (POUR_CENT), as code_aster's table."""

    result = kw.get("RESULTAT")
    if result is None:
        ctx.unsupported("POST_ELEM ENER_CIN on a CHAM_GD", "CHAM_GD", kw)
    model, cara, materials = kw.get("MODELE"), kw.get("CARA_ELEM"), kw.get("CHAM_MATER")
    if model is None:
        ctx.error("ENER_CIN needs MODELE", "MODELE", kw)
    mesh = model.mesh
    if isinstance(result, ModeResult):
        para, times = "FREQ", np.asarray(result.frequencies, dtype=float)
        fields = np.asarray(result.shapes, dtype=float).T * np.sqrt(np.abs(result.omega2))[:, None]
        orders = np.arange(1, result.n_modes + 1)
        kw.mark_used("TOUT_ORDRE")
        if any(kw.get(k) is not None for k in ("NUME_ORDRE", "INST", "LIST_INST", "LIST_ORDRE")):
            ctx.unsupported("ENER_CIN on chosen modes (all modes only)", "NUME_ORDRE", kw)
    else:
        velocities = getattr(result, "fields", {}).get("VITE")
        if velocities is None:
            ctx.error("the result has no VITE field", "RESULTAT", kw)
        selection = selection_from_keywords(ctx, kw, result.times, result.order)
        para, times = "INST", np.asarray(selection.times, dtype=float)
        fields = selection.apply(np.asarray(velocities, dtype=float))
        orders = selection.order
    table = Table(title=kw.get("TITRE") or "")
    table.add_column("NUME_ORDRE", "I")
    table.add_column(para, "R")
    for name, kind in (("LIEU", "K24"), ("ENTITE", "K8"), ("TOTALE", "R"), ("POUR_CENT", "R")):
        table.add_column(name, kind)
    try:
        whole = None
        for occ in kw.factor("ENER_CIN"):
            option = occ.get("OPTION", "MASS_MECA")
            whole = kinetic_energy(model, cara, materials, result.numbering, fields, None, option)
            for lieu, entity, cells in _places(ctx, occ, mesh):
                energy = kinetic_energy(
                    model, cara, materials, result.numbering, fields, cells, option
                )
                share = np.divide(100.0 * energy, whole, out=np.zeros_like(energy), where=whole > 0)
                for k in range(len(times)):
                    table.add_row(
                        {
                            "NUME_ORDRE": int(orders[k]),
                            para: float(times[k]),
                            "LIEU": lieu,
                            "ENTITE": entity,
                            "TOTALE": float(energy[k]),
                            "POUR_CENT": float(share[k]),
                        }
                    )
    except NotImplementedError as exc:
        ctx.unsupported(str(exc), "MODELE", kw)
    except (ElementError, ValueError) as exc:
        ctx.error(str(exc), "CARA_ELEM", kw)
    return table


def _places(ctx, occ, mesh):
    """(LIEU, ENTITE, cells) of one occurrence: the mesh for TOUT, else each group."""
    if occ.get("TOUT") == "OUI":
        return [(mesh.name or "MAILLAGE", "TOUT", None)]
    places = []
    for group in as_tuple(occ.get("GROUP_MA")):
        if group not in mesh.cell_groups:
            ctx.error(missing_name("cell group", group, mesh.cell_groups), "GROUP_MA", occ)
        places.append((group, "GROUP_MA", mesh.cell_groups[group]))
    return places
