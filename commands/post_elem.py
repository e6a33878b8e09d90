"""POST_ELEM MASS_INER: mass, centre of gravity and inertia into a table."""

from __future__ import annotations

from asterlite.concepts.table import Table
from asterlite.fem.elements import ElementError
from asterlite.fem.mass_properties import mass_properties
from asterlite.fem.selection import as_tuple

_COLUMNS = (
    "MASSE", "CDG_X", "CDG_Y", "CDG_Z", "IX_G", "IY_G", "IZ_G", "IXY_G", "IXZ_G", "IYZ_G",
    "IX_PRIN_G", "IY_PRIN_G", "IZ_PRIN_G",
)  # fmt: skip


def run(ctx, kw):
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
                    ctx.error(f"the mesh has no cell group {group!r}", "GROUP_MA", occ)
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
