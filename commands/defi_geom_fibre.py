"""DEFI_GEOM_FIBRE: fibre groups from the TRIA3 / QUAD4 cells of section
meshes (SECTION) or from given points (FIBRE), as code_aster's op0119."""

from __future__ import annotations

from asterlite.concepts.fibres import FibreGeometry, FibreGroup
from asterlite.fem.fibres import (
    FIBRE_CELLS,
    IGNORED_SECTION_CELLS,
    FibreError,
    point_fibres,
    section_fibres,
)
from asterlite.fem.selection import as_tuple


def _axis(ctx, occ) -> tuple[float, float]:
    if occ.get("TABLE_CARA") is not None:
        ctx.unsupported(
            "DEFI_GEOM_FIBRE TABLE_CARA (section axis from a MACR_CARA_POUTRE table)",
            "TABLE_CARA",
            occ,
        )
    axis = as_tuple(occ["COOR_AXE_POUTRE"])
    return float(axis[0]), float(axis[1])


def _new_group(ctx, result, name, occ):
    if name in result.groups:
        ctx.error(f"the fibre group {name!r} is defined twice", "GROUP_FIBRE", occ)


def _section(ctx, result, occ) -> None:
    name = occ["GROUP_FIBRE"]
    _new_group(ctx, result, name, occ)
    mesh = occ["MAILLAGE_SECT"]
    axis = _axis(ctx, occ)
    angle = float(occ.get("ANGLE", 0.0))
    if occ.get("TOUT_SECT") == "OUI":
        cells = list(range(mesh.n_cells))
    else:
        cells = []
        for group in as_tuple(occ["GROUP_MA_SECT"]):
            if group not in mesh.cell_groups:
                ctx.error(f"the section mesh has no cell group {group!r}", "GROUP_MA_SECT", occ)
            cells.extend(int(c) for c in mesh.cell_groups[group])
        cells = list(dict.fromkeys(cells))
    surface = []
    for cell in cells:
        kind = mesh.cell_types[cell]
        if kind in FIBRE_CELLS:
            surface.append(tuple(mesh.cell_nodes[cell]))
        elif kind not in IGNORED_SECTION_CELLS:
            ctx.error(
                f"section cell {mesh.cell_names[cell]} is a {kind}: fibres come from "
                "TRIA3 and QUAD4 cells (SEG2 cells are skipped)",
                "MAILLAGE_SECT",
                occ,
            )
    if not surface:
        ctx.error(
            f"the section of fibre group {name!r} has no TRIA3 or QUAD4 cell", "MAILLAGE_SECT", occ
        )
    y, z, area = section_fibres(mesh.coords, surface, axis, angle)
    result.groups[name] = FibreGroup(y=y, z=z, area=area)


def _points(ctx, result, occ) -> None:
    name = occ["GROUP_FIBRE"]
    _new_group(ctx, result, name, occ)
    axis = _axis(ctx, occ)
    try:
        y, z, area = point_fibres(
            as_tuple(occ["VALE"]), occ.get("CARA", "SURFACE"), axis, float(occ.get("ANGLE", 0.0))
        )
    except FibreError as exc:
        ctx.error(str(exc), "VALE", occ)
    result.groups[name] = FibreGroup(y=y, z=z, area=area)


def run(ctx, kw):
    if kw.factor("ASSEMBLAGE_FIBRE"):
        ctx.unsupported(
            "DEFI_GEOM_FIBRE ASSEMBLAGE_FIBRE (assemblies of beams, POU_D_SQUE)",
            "ASSEMBLAGE_FIBRE",
            kw,
        )
    result = FibreGeometry()
    for occ in kw.factor("SECTION"):
        _section(ctx, result, occ)
    for occ in kw.factor("FIBRE"):
        _points(ctx, result, occ)
    kw.get("INFO")
    for name, group in result.groups.items():
        ctx.log(f"fibre group {name}: {len(group.area)} fibres, area {group.area.sum():.6g}")
    return result
