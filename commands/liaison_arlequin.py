"""AFFE_CHAR_MECA/LIAISON_ELEM OPTION='3D_POU_ARLEQUIN': the keywords of one
occurrence turned into the beam and solid cells the coupling ties
(asterlite.fem.arlequin), then into linear relations of the load."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import LinearRelation
from asterlite.fem.arlequin import COUPLED_SOLIDS, BeamCell, arlequin_relations
from asterlite.fem.beam import cell_angles
from asterlite.fem.element_errors import ElementError
from asterlite.fem.frames import rotation_from_angles
from asterlite.fem.selection import cell_group_members


def _unique(cells) -> list[int]:
    return list(dict.fromkeys(int(c) for c in cells))


def _beam_cells(ctx, model, occ) -> list[BeamCell]:
    mesh = model.mesh
    characteristics = occ["CARA_ELEM"]
    materials = occ["CHAM_MATER"]
    beams = []
    for cell in _unique(cell_group_members(ctx, occ, mesh, "GROUP_MA_2")):
        name = mesh.cell_names[cell]
        modelisation = model.cell_modelisation.get(cell)
        if mesh.cell_types[cell] != "SEG2" or modelisation != "POU_D_T":
            ctx.error(
                f"cell {name} ({mesh.cell_types[cell]}, {modelisation}): the Arlequin "
                "coupling ties POU_D_T beams on SEG2 cells",
                "GROUP_MA_2",
                occ,
            )
        n1, n2 = (int(n) for n in mesh.cell_nodes[cell])
        start, end = mesh.coords[n1], mesh.coords[n2]
        length = float(np.linalg.norm(end - start))
        rotation = rotation_from_angles(cell_angles(model, characteristics, [cell])[0])
        if not np.allclose(rotation, np.eye(3), rtol=0.0, atol=1.0e-12):
            ctx.log(
                f"alarm: LIAISON_ELEM 3D_POU_ARLEQUIN: beam cell {name}'s local frame is not "
                "the global one; as code_aster, its local-frame coupling terms multiply "
                "the global DOFs of its nodes"
            )
        section = characteristics.sections.get(cell)
        if section is None:
            ctx.error(f"beam cell {name} has no section in CARA_ELEM", "CARA_ELEM", occ)
        if materials.material_of(cell) is None:
            ctx.error(f"beam cell {name} has no material in CHAM_MATER", "CHAM_MATER", occ)
        young = float(materials.values([cell], "E", np.nan)[0])
        if np.isnan(young):
            ctx.error(f"the material of beam cell {name} has no E (ELAS)", "CHAM_MATER", occ)
        missing = [k for k in ("A", "IY", "IZ", "AY", "AZ") if k not in section]
        if missing:
            ctx.error(
                f"the section of beam cell {name} lacks {', '.join(missing)}", "CARA_ELEM", occ
            )
        beams.append(
            BeamCell(
                name=name,
                nodes=(n1, n2),
                start=start.astype(float),
                end=end.astype(float),
                rotation=rotation,
                length=length,
                young=young,
                poisson=float(materials.values([cell], "NU", 0.0)[0]),
                area=float(section["A"]),
                iy=float(section["IY"]),
                iz=float(section["IZ"]),
                ay=float(section["AY"]),
                az=float(section["AZ"]),
            )
        )
    return beams


def _check_node_names(ctx, mesh, relations, occ) -> None:
    """code_aster writes the relations on the nodes named 'N' + their number
    (five digits at most): on a mesh named otherwise it ties other nodes or
    stops, so such meshes are refused."""
    for terms, _ in relations:
        for node, _, _ in terms:
            if mesh.node_names[node] != f"N{node + 1}" or node + 1 > 99999:
                ctx.unsupported(
                    f"LIAISON_ELEM 3D_POU_ARLEQUIN on node {mesh.node_names[node]} (number "
                    f"{node + 1}): code_aster names the coupled nodes 'N' + their number",
                    "GROUP_MA_1",
                    occ,
                )


def arlequin_link(ctx, model, components, load, occ) -> None:
    """Append the Arlequin relations of one LIAISON_ELEM occurrence to the load."""
    mesh = model.mesh
    solids = _unique(cell_group_members(ctx, occ, mesh, "GROUP_MA_1"))
    for cell in solids:
        kind = mesh.cell_types[cell]
        if kind not in COUPLED_SOLIDS or model.cell_modelisation.get(cell) != "3D":
            ctx.error(
                f"cell {mesh.cell_names[cell]} ({kind}): the Arlequin coupling ties 3D cells "
                f"of types {', '.join(COUPLED_SOLIDS)}",
                "GROUP_MA_1",
                occ,
            )
    beams = _beam_cells(ctx, model, occ)
    for beam in beams:
        for node in beam.nodes:
            if not all(c in components.get(node, ()) for c in ("DRX", "DRY", "DRZ")):
                ctx.error(f"beam node {mesh.node_names[node]} has no rotation DOF", "GROUP_MA_2")
    try:
        relations = arlequin_relations(mesh, solids, beams)
    except ElementError as exc:
        ctx.error(str(exc), "GROUP_MA_2", occ)
    _check_node_names(ctx, mesh, relations, occ)
    for terms, rhs in relations:
        load.relations.append(LinearRelation(terms, rhs))
