"""POST_NEWMARK on a dyna_trans of a plane model: the permanent displacement
of the sliding zone by Newmark's method (asterlite.post.sliding_block).

The zone is the cells of GROUP_MA_CALC with a node in the disc RAYON about
(CENTRE_X, CENTRE_Y), or inside MAILLAGE_GLIS. Its mass comes from the
result's model and materials (as POST_ELEM MASS_INER), its mean horizontal
acceleration from the zone's internal forces (FORC_NODA of its cells) summed
on the nodes of the other surface cells of GROUP_MA_CALC, times -1 with
POSITION='AMONT'. The table has INST, ACCE_MOY, VITE and DEPL.
RESULTAT_PESANTEUR (with RAYON; asterlite.post.newmark_safety): the slip
circle's safety factor at each instant (column FS) and, without KY, the
critical acceleration from them (column KY, in g).
MAILLAGE_RESU/MAILLAGE: the structure's mesh (its cells and nodes in some
group) with the zone as the cell group NOM_GROUP (default GLISSE).
VERI_MASSE='OUI': the zone's mass is taken on refined meshes instead, as
code_aster does it: the material field's mesh refined by HOMARD (about a
disc of 1.2 RAYON for a circle, uniformly for MAILLAGE_GLIS), the materials
of the parent cells on their children, the zone selected again on the
refined mesh, until two masses differ by RESI_RELA (relative) or after
ITER_MAXI refinements; MAILLAGE_MASSE is the last refined mesh.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import MaterialField, Model
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.table import Table
from asterlite.errors import missing_name
from asterlite.fem.mass_properties import mass_properties
from asterlite.fem.refinement import RefinementError, uniform_refinement
from asterlite.fem.selection import as_tuple
from asterlite.fem.zone_refinement import Zone, refine_zones
from asterlite.post import newmark_safety as safety
from asterlite.post import sliding_block as block
from asterlite.post import slip_line_safety
from asterlite.post.nodal_forces import internal_forces


def _groups(ctx, mesh, names, keyword, kw) -> np.ndarray:
    cells = []
    for name in as_tuple(names):
        if name not in mesh.cell_groups:
            ctx.error(missing_name("cell group", name, mesh.cell_groups), keyword, kw)
        cells.extend(int(c) for c in mesh.cell_groups[name])
    return np.array(sorted(set(cells)), dtype=int)


def _sliding_cells(ctx, kw, mesh, computed) -> np.ndarray:
    if kw.get("RAYON") is not None:
        # RAFF_CERCLE refines the disc of the safety factors: code_aster reads it
        # with RESULTAT_PESANTEUR only (_safety_factors)
        kw.mark_used("RAFF_CERCLE")
        radius = float(kw["RAYON"])
        if radius <= 0.0:
            ctx.error("RAYON must be positive", "RAYON", kw)
        centre = (float(kw["CENTRE_X"]), float(kw["CENTRE_Y"]))
        return block.cells_near_centre(mesh, computed, centre, radius)
    other = kw["MAILLAGE_GLIS"]
    if other.dim != 2 and np.any(other.coords[:, 2:] != 0.0):
        ctx.error("MAILLAGE_GLIS must be a plane mesh", "MAILLAGE_GLIS", kw)
    # GROUP_MA_GLIS and GROUP_MA_LIGNE give the rupture zone and line of the
    # safety factors (RESULTAT_PESANTEUR): code_aster reads their groups only
    for keyword in ("GROUP_MA_GLIS", "GROUP_MA_LIGNE"):
        if kw.get(keyword) is not None:
            _groups(ctx, other, kw[keyword], keyword, kw)
    return block.cells_inside_mesh(mesh, computed, other, np.arange(other.n_cells))


def _materials_on_children(materials, mesh: Mesh, parent: np.ndarray) -> MaterialField:
    """The material field on a refined mesh: each cell takes its parent's
    materials (code_aster assigns them again on the groups the field named,
    which the children inherit)."""
    field = MaterialField(mesh=mesh)
    for child, cell in enumerate(parent):
        material = materials.cell_material.get(int(cell))
        if material is not None:
            field.cell_material[child] = material
        every = materials.cell_materials.get(int(cell))
        if every is not None:
            field.cell_materials[child] = every
    return field


def _verified_mass(ctx, kw, materials, mass: float) -> tuple[float, Mesh]:
    """VERI_MASSE='OUI': the zone's mass on refined meshes and the last of them."""
    for keyword in ("RESI_RELA", "ITER_MAXI"):
        if kw.get(keyword) is None:
            # code_aster's catalogue means defaults (0.05, 2) but spells them
            # "default=", so its loop compares with None and stops
            ctx.error(f"VERI_MASSE='OUI' needs {keyword}", keyword, kw)
    if kw.get("CHAM_MATER") is not None:
        # code_aster reads CHAM_MATER only when RESULTAT has no material field
        kw.mark_used("CHAM_MATER")
    tolerance, iterations = float(kw["RESI_RELA"]), int(kw["ITER_MAXI"])
    mesh = materials.mesh
    masses, error, refined = [mass], 1.0, None
    while error > tolerance and len(masses) <= iterations:
        try:
            if kw.get("RAYON") is not None:
                zone = Zone(
                    "DISQUE",
                    {
                        "X_CENTRE": float(kw["CENTRE_X"]),
                        "Y_CENTRE": float(kw["CENTRE_Y"]),
                        "RAYON": 1.2 * float(kw["RAYON"]),
                    },
                )
                adapted = refine_zones(mesh, [zone])
                refined, parent = adapted.mesh, adapted.parent
            else:
                refined, parent = uniform_refinement(mesh)
        except RefinementError as exc:
            ctx.unsupported(f"VERI_MASSE='OUI': {exc}", "VERI_MASSE", kw)
        materials = _materials_on_children(materials, refined, parent)
        computed = _groups(ctx, refined, kw["GROUP_MA_CALC"], "GROUP_MA_CALC", kw)
        zone_cells = _sliding_cells(ctx, kw, refined, computed)
        plane = [int(c) for c in zone_cells if refined.cell_types[c] in block.SURFACES]
        # AFFE_MODELE D_PLAN on the whole refined mesh; its edges carry no mass
        model = Model(mesh=refined, cell_modelisation=dict.fromkeys(plane, "D_PLAN"))
        masses.append(float(mass_properties(model, None, materials, plane)["MASSE"]))
        error = abs((masses[-1] - masses[-2]) / masses[-1])
        ctx.log(
            f"POST_NEWMARK VERI_MASSE: refinement {len(masses) - 1}, {refined.n_nodes} nodes, "
            f"{refined.n_cells} cells, zone mass {masses[-1]:.10g}, relative change {error:.3g}"
        )
        mesh = refined
    if refined is None:
        ctx.error("VERI_MASSE='OUI' refined nothing (RESI_RELA >= 1)", "RESI_RELA", kw)
    _add_zone_groups(ctx, kw, refined, computed, zone_cells)
    return masses[-1], refined


def _add_zone_groups(ctx, kw, mesh: Mesh, computed, zone_cells) -> None:
    """The groups code_aster's macro leaves on the last refined mesh: ALL
    (GROUP_MA_CALC), GLISSE_ (the cells the zone reaches), the zone (NOM_GROUP,
    default GLISSE: GLISSE_ in ALL) and NGLISSE (the other surface cells of
    ALL), with the node groups of the last two."""
    name = next((o.get("NOM_GROUP") for o in kw.factor("MAILLAGE_RESU")), None) or "GLISSE"
    reached = _sliding_cells(ctx, kw, mesh, np.arange(mesh.n_cells))
    zone = set(int(c) for c in zone_cells)
    rest = [int(c) for c in computed if int(c) not in zone and mesh.cell_types[c] in block.SURFACES]
    mesh.cell_groups["ALL"] = np.asarray(computed, dtype=int)
    mesh.cell_groups["GLISSE_"] = np.asarray(reached, dtype=int)
    mesh.cell_groups[name] = np.asarray(zone_cells, dtype=int)
    mesh.cell_groups["NGLISSE"] = np.array(rest, dtype=int)
    mesh.node_groups["NGLISSE"] = mesh.nodes_of_cells(rest)
    mesh.node_groups[name] = mesh.nodes_of_cells(zone_cells)


def _restricted_copy(mesh: Mesh) -> Mesh:
    """The mesh restricted to the cells of its groups and the nodes of those
    cells and of its node groups (CREA_MAILLAGE RESTREINT on every group)."""
    grouped = sorted({int(c) for cells in mesh.cell_groups.values() for c in cells})
    if len(grouped) == mesh.n_cells and all(len(nodes) == 0 for nodes in mesh.node_groups.values()):
        used = {n for c in grouped for n in mesh.cell_nodes[c]}
        if len(used) == mesh.n_nodes:
            return mesh.copy()
    nodes = sorted(
        {n for c in grouped for n in mesh.cell_nodes[c]}
        | {int(n) for group in mesh.node_groups.values() for n in group}
    )
    new_node = {old: new for new, old in enumerate(nodes)}
    new_cell = {old: new for new, old in enumerate(grouped)}
    return Mesh(
        coords=mesh.coords[nodes].copy(),
        node_names=[mesh.node_names[n] for n in nodes],
        cell_names=[mesh.cell_names[c] for c in grouped],
        cell_types=[mesh.cell_types[c] for c in grouped],
        cell_nodes=[tuple(new_node[n] for n in mesh.cell_nodes[c]) for c in grouped],
        node_groups={
            k: np.array([new_node[int(n)] for n in v], dtype=int)
            for k, v in mesh.node_groups.items()
        },
        cell_groups={
            k: np.array([new_cell[int(c)] for c in v], dtype=int)
            for k, v in mesh.cell_groups.items()
        },
        dim=mesh.dim,
        title=mesh.title,
    )


def _safety_factors(ctx, kw, result, sign) -> np.ndarray:
    """The slip circle's safety factor at each instant (RESULTAT_PESANTEUR)."""
    if kw.get("METHODE", "ECLA_PG") != "ECLA_PG":
        ctx.unsupported("METHODE='COLLOCATION' (ECLA_PG is computed)", "METHODE", kw)
    if kw.get("RAYON") is None:
        ctx.unsupported(
            "RESULTAT_PESANTEUR on MAILLAGE_GLIS (asterlite computes it on a slip circle, RAYON)",
            "RESULTAT_PESANTEUR",
            kw,
        )
    static = kw["RESULTAT_PESANTEUR"]
    if getattr(static, "model", None) is None:
        ctx.error("RESULTAT_PESANTEUR has no model", "RESULTAT_PESANTEUR", kw)
    refine = kw.get("RAFF_CERCLE")
    try:
        return safety.dynamic_safety_factors(
            result,
            static,
            kw["CHAM_PHI"],
            kw["CHAM_COHESION"],
            (float(kw["CENTRE_X"]), float(kw["CENTRE_Y"])),
            float(kw["RAYON"]),
            7 if refine is None else int(refine),  # code_aster's default level
            sign,
        )
    except safety.SafetyError as exc:
        ctx.error(str(exc), "RESULTAT_PESANTEUR", kw)


def run(ctx, kw):
    result = kw.get("RESULTAT")
    if result is None:
        # code_aster then gives the static safety factor and CHAM_FS only
        ctx.unsupported(
            "POST_NEWMARK without RESULTAT (the static safety factor and CHAM_FS)",
            "RESULTAT_PESANTEUR",
            kw,
        )
    model, materials = getattr(result, "model", None), getattr(result, "materials", None)
    if model is None or materials is None:
        ctx.error("RESULTAT has no model or no material field", "RESULTAT", kw)
    mesh = model.mesh
    if mesh.dim == 3 and np.any(mesh.coords[:, 2] != 0.0):
        ctx.error("POST_NEWMARK applies to plane models (code_aster's POST0_51)", "RESULTAT", kw)
    if kw.get("KY") is None and kw.get("RESULTAT_PESANTEUR") is None:
        # code_aster has no critical acceleration then either
        ctx.error("POST_NEWMARK needs KY or RESULTAT_PESANTEUR", "KY", kw)
    if "DEPL" not in result.fields:
        ctx.error("RESULTAT holds no DEPL field", "RESULTAT", kw)
    computed = _groups(ctx, mesh, kw["GROUP_MA_CALC"], "GROUP_MA_CALC", kw)
    sliding = _sliding_cells(ctx, kw, mesh, computed)
    if not sliding.size:
        ctx.error("the sliding zone holds no cell of GROUP_MA_CALC", "GROUP_MA_CALC", kw)
    surfaces = {int(c) for c in computed if mesh.cell_types[c] in block.SURFACES}
    rest = sorted(surfaces - {int(c) for c in sliding})
    boundary = np.unique(np.concatenate([mesh.cell_nodes[c] for c in rest])) if rest else []

    characteristics = getattr(result, "characteristics", None)
    masses = mass_properties(model, characteristics, materials, sliding)
    mass = float(masses["MASSE"])
    if mass <= 0.0:
        ctx.error("the sliding zone has no mass (RHO)", "RESULTAT", kw)
    mass_mesh = None
    if kw.get("VERI_MASSE", "NON") == "OUI":
        mass, mass_mesh = _verified_mass(ctx, kw, materials, mass)
    numbering = result.numbering
    forces = internal_forces(
        model, characteristics, materials, numbering, result.fields["DEPL"], cells=sliding
    )
    rows = numbering.dof_indices(boundary, ["DX"] * len(boundary))
    sign = -1.0 if kw.get("POSITION", "AVAL") == "AMONT" else 1.0
    times = np.asarray(result.times, dtype=float)
    acceleration = sign * forces[:, rows[rows >= 0]].sum(axis=1) / mass
    columns = {"INST": times, "ACCE_MOY": acceleration}
    if kw.get("RESULTAT_PESANTEUR") is not None:
        # CHAM_FS: code_aster produces it only without RESULTAT, so not here
        kw.mark_used("CHAM_FS")
        factors = _safety_factors(ctx, kw, result, sign)
        ky = kw.get("KY")
        if ky is None:
            try:
                critical = slip_line_safety.critical_acceleration(
                    factors, acceleration, float(kw.get("NB_ECART_TYPE", 3.0))
                )
            except ValueError as exc:
                ctx.error(str(exc), "RESULTAT_PESANTEUR", kw)
            ky_column = np.full(times.size, critical / block.GRAVITY)
    if kw.get("KY") is not None:
        critical = float(kw["KY"]) * block.GRAVITY
    velocity, displacement = block.newmark_displacement(times, acceleration, critical)
    columns |= {"VITE": velocity, "DEPL": displacement}
    if kw.get("RESULTAT_PESANTEUR") is not None:
        columns["FS"] = factors
        if kw.get("KY") is None:
            columns["KY"] = ky_column

    table = Table(title="")
    for name in columns:
        table.add_column(name, "R")
    for k in range(times.size):
        table.add_row({name: float(values[k]) for name, values in columns.items()})
    ctx.log(
        f"POST_NEWMARK: sliding zone of {sliding.size} cells, mass {mass:.6g}; "
        f"a_y = {critical:g}, final displacement {displacement[-1]:.6g}"
    )
    for occ in kw.factor("MAILLAGE_RESU"):
        if occ.get("MAILLAGE_MASSE") is not None:
            if mass_mesh is None:
                # code_aster's macro would fail on its undefined refined mesh
                ctx.error(
                    "MAILLAGE_MASSE is made with VERI_MASSE='OUI' only", "MAILLAGE_MASSE", occ
                )
            ctx.bind(occ["MAILLAGE_MASSE"], mass_mesh)
        name = occ.get("NOM_GROUP") or "GLISSE"
        if occ.get("MAILLAGE") is not None:
            out = _restricted_copy(mesh)
            kept = {c: k for k, c in enumerate(out.cell_names)}
            out.cell_groups[name] = np.array(
                [kept[mesh.cell_names[c]] for c in sliding if mesh.cell_names[c] in kept],
                dtype=int,
            )
            out.refresh_indices()
            ctx.bind(occ["MAILLAGE"], out)
    return table
