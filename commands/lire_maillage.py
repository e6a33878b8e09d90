"""LIRE_MAILLAGE: read a mesh (ASTER text format; MED through medcoupling; I-DEAS
universal files through pyuff; gmsh formats 1 and 2 as code_aster's PRE_GMSH)."""

from __future__ import annotations

from asterlite.fem.mesh_check import check_mesh
from asterlite.io.aster_mesh import AsterMeshError, read_aster_mesh
from asterlite.io.gmsh_mesh import GmshMeshError, read_gmsh_mesh
from asterlite.legacy.version import meshes_keep_names


def run(ctx, kw):
    unit = kw.get("UNITE", 20)
    fmt = kw.get("FORMAT", "MED")
    try:
        path = ctx.session.input_path(unit)
    except (KeyError, FileNotFoundError, LookupError) as exc:
        ctx.error(f"no file is mapped to logical unit {unit} ({exc})", "UNITE", kw)
    if fmt == "ASTER":
        try:
            mesh = read_aster_mesh(path)
        except AsterMeshError as exc:
            ctx.error(str(exc), "UNITE", kw)
    elif fmt == "MED":
        try:
            from asterlite.io.med_mesh import read_med_mesh
        except ImportError:
            ctx.unsupported("LIRE_MAILLAGE FORMAT='MED' (MED reader not available)", "FORMAT", kw)
        try:
            mesh = read_med_mesh(path, kw.get("NOM_MED"))
        except (ValueError, KeyError) as exc:
            ctx.error(str(exc), "UNITE", kw)
    elif fmt == "IDEAS":
        mesh = _read_ideas(ctx, kw, path)
    elif fmt == "GMSH":
        try:
            mesh = read_gmsh_mesh(path)
        except GmshMeshError as exc:
            ctx.error(str(exc), "UNITE", kw)
    else:
        ctx.unsupported(f"LIRE_MAILLAGE FORMAT={fmt!r}", "FORMAT", kw)
    ctx.log(
        f"mesh {path.name}: {mesh.n_nodes} nodes, {mesh.n_cells} cells, "
        f"{len(mesh.node_groups)} node groups, {len(mesh.cell_groups)} cell groups"
    )
    mesh.names_kept = meshes_keep_names(ctx.session)
    _check(ctx, kw, mesh)
    return mesh


def _check(ctx, kw, mesh) -> None:
    """VERI_MAIL (VERIF='OUI' by default): code_aster's mesh check, alarms in
    the log, errors stop the command (asterlite.fem.mesh_check)."""

    occ = (kw.factor("VERI_MAIL") or [{}])[0]
    if occ.get("VERIF", "OUI") != "OUI":
        return
    try:
        found = check_mesh(mesh, float(occ.get("APLAT", 1.0e-3)))
    except NotImplementedError as exc:
        if "VERI_MAIL" in kw.given:
            ctx.unsupported(f"VERI_MAIL: {exc}", "VERI_MAIL", kw)
        ctx.log(f"VERI_MAIL: {exc} is not made")
        return
    for alarm in found.alarms:
        ctx.log(f"alarm: VERI_MAIL: {alarm}")
    if found.errors:
        ctx.error("VERI_MAIL: " + "; ".join(found.errors), "VERI_MAIL", kw)


def _read_ideas(ctx, kw, path):
    # pyuff's reader, for the decks that read I-DEAS files only
    from asterlite.io.ideas_mesh import IdeasMeshError, IdeasMeshUnsupported, read_ideas_mesh

    try:
        mesh = read_ideas_mesh(path, color_groups=kw.get("CREA_GROUP_COUL") == "OUI")
    except IdeasMeshUnsupported as exc:
        ctx.unsupported(f"LIRE_MAILLAGE FORMAT='IDEAS': {exc}", "UNITE", kw)
    except IdeasMeshError as exc:
        ctx.error(str(exc), "UNITE", kw)
    for note in mesh.ideas_notes:
        ctx.log(f"<A> {note}")
    if mesh.ideas_skipped:
        numbers = ", ".join(str(n) for n in mesh.ideas_skipped)
        ctx.log(f"I-DEAS datasets not used for the mesh: {numbers}")
    return mesh
