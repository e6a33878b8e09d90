"""Element fields computed from nodal displacements (CALC_CHAMP).

- ``EFGE_ELNO`` / ``SIEF_ELNO`` of beams: generalised internal forces N VY VZ
  MT MFY MFZ at both nodes (:func:`asterlite.fem.beam_elements.beam_local_forces`);
- ``SIPO_ELNO``: the stresses derived from them
  (:func:`asterlite.fem.beam_elements.beam_stresses`), ``SIPM_ELNO`` the
  extreme axial stresses over the section (``beam_extreme_stresses``);
- ``EFGE_ELGA`` / ``SIEF_ELGA``: the same forces at the 3 Gauss points, linear
  between the two nodes (exact for unloaded straight beams: constant forces,
  linear moments);
- dynamic results (``accelerations`` given: the ACCE field of a dyna_trans)
  add the element inertia forces to EFGE_ELNO, SIPO_ELNO and SIPM_ELNO,
  ``K_e u_e + M_e a_e``, as code_aster's beam elements do for transient
  results (the forces then balance the inertia distribution along each beam,
  so SN differs between its two nodes); SIEF_ELGA / EFGE_ELGA / SIEF_ELNO
  stay ``K_e u_e`` (code_aster computes them from the displacement alone);
- ``POU_D_TG``: EFGE_ELNO only, N VY VZ MT MFY MFZ and the bimoment BX,
  ``K_e u_e`` less EXCIT's line loads, never with inertia (code_aster's
  ef0344);
- ``*_NOEU``: the arithmetic mean, at each node, of the ELNO values of the
  cells sharing it (code_aster's nodal smoothing);
- discrete elements (``DIS_T``, ``DIS_TR``, ``2D_DIS_T``, ``2D_DIS_TR``):
  EFGE_ELNO / SIEF_ELNO hold the stiffness forces in the element frame,
  f = K_local P u, with the sign of a segment's first node reversed
  (components N VY VZ, MT MFY MFZ; code_aster's ef0042), real or complex;
- bars (``BARRE``, ``2D_BARRE``): EFGE_ELNO / SIEF_ELNO hold the axial force
  N = E A / L (u2 - u1)·e at both nodes, from the displacements alone, real
  or complex (code_aster's te0185, without inertia).

Values keep every order of the result: (n_orders, n_cells, 2, n_components).
The beam fields are computed by blocks of orders (``order_blocks``: the
temporaries stay bounded whatever the number of orders), with products that
round the same whatever the block (``beam_elements.per_cell_products``).
"""

from __future__ import annotations

import numpy as np

from asterlite.arrays import sorted_unique
from asterlite.concepts.assembly import ElementField, NodalComponentField
from asterlite.errors import UnsupportedError
from asterlite.fem.beam_elements import (
    EFGE_COMPONENTS,
    SIPM_COMPONENTS,
    SIPO_COMPONENTS,
    WARPING_EFGE_COMPONENTS,
    BeamForces,
    _material_values,
    beam_extreme_stresses,
    beam_stresses,
)
from asterlite.fem.discrete import local_matrix
from asterlite.fem.dofs import MODELISATION_COMPONENTS
from asterlite.fem.elements import ElementError, cell_frames
from asterlite.fem.frames import block_rotation

BEAM_COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
ELNO_OPTIONS = ("EFGE_ELNO", "SIEF_ELNO", "SIPO_ELNO", "SIPM_ELNO")
ELGA_OPTIONS = ("EFGE_ELGA", "SIEF_ELGA")
#: Positions (0..1 along the beam) of the 3 Gauss points of beam elements.
BEAM_GAUSS = (1.0 + np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])) / 2.0
NOEU_OPTIONS = ("EFGE_NOEU", "SIEF_NOEU", "SIPO_NOEU")
#: Bytes of one (orders, cells, DOFs) temporary of the beam fields: they are
#: computed by blocks of orders of about that size (the fields themselves
#: hold every order).
BLOCK_BYTES = 4 << 20


def order_blocks(n_orders: int, per_order: int, block_bytes: int | None = None):
    """Slices of consecutive orders whose (orders, ``per_order``) float
    temporaries take about ``block_bytes`` (BLOCK_BYTES by default)."""
    size = max(1, (BLOCK_BYTES if block_bytes is None else block_bytes) // max(1, 8 * per_order))
    return [slice(start, min(start + size, n_orders)) for start in range(0, n_orders, size)]


def element_displacements(
    mesh, numbering, cells, values: np.ndarray, components=BEAM_COMPONENTS
) -> np.ndarray:
    """(n_orders, n_cells, 2 len(components)) beam DOFs (DX..DRZ of both
    nodes, by default) gathered from nodal values (n_orders, n_dofs); DOFs
    absent from the numbering are 0."""
    cells = np.asarray(cells, dtype=int)
    per_node = len(components)
    conn = np.array([mesh.cell_nodes[c] for c in cells], dtype=int).reshape(-1, 2)
    nodes = np.repeat(conn, per_node, axis=1).ravel()
    comps = list(components) * (2 * len(cells))
    rows = numbering.dof_indices(nodes, comps)
    gathered = np.zeros((values.shape[0], rows.size))
    present = rows >= 0
    gathered[:, present] = values[:, rows[present]]
    return gathered.reshape(values.shape[0], len(cells), 2 * per_node)


def beam_element_fields(
    model,
    characteristics,
    materials,
    numbering,
    cells,
    values: np.ndarray,
    options,
    accelerations: np.ndarray | None = None,
    lumped_mass: bool = False,
    load_forces: np.ndarray | None = None,
) -> dict[str, ElementField]:
    """The requested ELNO fields of beam cells for nodal values (n_orders, n_dofs).

    ``accelerations`` (n_orders, n_dofs), when given, adds the inertia forces
    ``M_e a_e`` (consistent mass, or lumped with ``lumped_mass``) to
    EFGE_ELNO and SIPO_ELNO. ``load_forces`` (n_orders, n_cells, 2, 6), the
    distributed loads of CALC_CHAMP's EXCIT in the same convention, are taken
    off EFGE_ELNO, SIPO_ELNO and SIPM_ELNO (not SIEF: code_aster's options).
    POU_D_TG cells: see :func:`_warping_beam_fields`."""
    cells = np.asarray(cells, dtype=int)
    kinds = {model.cell_modelisation[int(c)] for c in cells}
    if "POU_D_TG" in kinds:
        if len(kinds) > 1:
            raise UnsupportedError(
                "element fields of POU_D_TG cells and of other beams in one CALC_CHAMP "
                "(their EFGE_ELNO differ in components: give them in separate calls)"
            )
        return _warping_beam_fields(
            model, characteristics, materials, numbering, cells, values, options, load_forces
        )
    forces = BeamForces(
        model, characteristics, materials, cells, accelerations is not None, lumped_mass
    )
    unknown = [n for n in options if n not in ELNO_OPTIONS + ELGA_OPTIONS]
    if unknown:  # a field code_aster computes on beams too (ECIN_ELEM, EPSI_ELNO...)
        raise UnsupportedError(f"{unknown[0]} of beam cells")
    stresses = any(n in ("SIPO_ELNO", "SIPM_ELNO") for n in options)
    sections = [characteristics.sections[int(c)] for c in cells] if stresses else []
    modelisations = [model.cell_modelisation[int(c)] for c in cells]
    n_orders = values.shape[0]
    points = {"SIPM_ELNO": (2, 2), **{n: (3, 6) for n in ELGA_OPTIONS}}
    # without inertia nor loads, EFGE_ELNO is SIEF_ELNO (one array for both)
    same = accelerations is None and load_forces is None
    arrays: dict[str, np.ndarray] = {}
    for name in options:
        if same and name in ("EFGE_ELNO", "SIEF_ELNO"):
            twin = "SIEF_ELNO" if name == "EFGE_ELNO" else "EFGE_ELNO"
            if twin in arrays:
                arrays[name] = arrays[twin]
                continue
        arrays[name] = np.empty((n_orders, len(cells)) + points.get(name, (2, 6)))
    xi = BEAM_GAUSS[None, None, :, None]
    for block in order_blocks(n_orders, 12 * len(cells)):
        u = element_displacements(model.mesh, numbering, cells, values[block])
        stiffness = forces.stiffness(u)
        dynamic = stiffness
        if accelerations is not None:
            a = element_displacements(model.mesh, numbering, cells, accelerations[block])
            dynamic = stiffness + forces.inertia(a)
        if load_forces is not None:
            dynamic = dynamic - load_forces[block]
        for name, target in arrays.items():
            if name == "EFGE_ELNO":
                target[block] = dynamic
            elif name == "SIEF_ELNO":
                target[block] = stiffness
            elif name in ELGA_OPTIONS:
                target[block] = (1.0 - xi) * stiffness[:, :, :1, :] + xi * stiffness[:, :, 1:, :]
            elif name == "SIPO_ELNO":
                target[block] = beam_stresses(dynamic, sections, modelisations)
            else:
                target[block] = beam_extreme_stresses(dynamic, sections)
    components = {"SIPO_ELNO": SIPO_COMPONENTS, "SIPM_ELNO": SIPM_COMPONENTS}
    return {
        name: ElementField(name, cells, components.get(name, EFGE_COMPONENTS), target)
        for name, target in arrays.items()
    }


def _warping_beam_fields(
    model, characteristics, materials, numbering, cells, values, options, load_forces
) -> dict[str, ElementField]:
    """EFGE_ELNO of POU_D_TG cells (N VY VZ MT MFY MFZ BX): the stiffness
    forces less the distributed loads of EXCIT, without inertia, as
    code_aster's ef0344 computes them for linear results."""
    other = [name for name in options if name != "EFGE_ELNO"]
    if other:
        raise UnsupportedError(f"{other[0]} of POU_D_TG cells")
    operators = BeamForces(model, characteristics, materials, cells, warping=True)
    forces = np.empty((values.shape[0], len(cells), 2, 7))
    for block in order_blocks(values.shape[0], 14 * len(cells)):
        u = element_displacements(
            model.mesh, numbering, cells, values[block], BEAM_COMPONENTS + ("GRX",)
        )
        forces[block] = operators.stiffness(u)
        if load_forces is not None:
            forces[block, ..., :6] -= load_forces[block]
    return {"EFGE_ELNO": ElementField("EFGE_ELNO", cells, WARPING_EFGE_COMPONENTS, forces)}


BAR_OPTIONS = ("EFGE_ELNO", "SIEF_ELNO")
#: the fields of bars: BAR_OPTIONS at the nodes, SIEF_ELGA at code_aster's
#: one Gauss point (MECA_BARRE: RIGI=FPG1)
BAR_FIELDS = (*BAR_OPTIONS, "SIEF_ELGA")
DISCRETE_COMPONENTS = {
    "DIS_T": ("N", "VY", "VZ"),
    "DIS_TR": ("N", "VY", "VZ", "MT", "MFY", "MFZ"),
    "2D_DIS_T": ("N", "VY"),
    "2D_DIS_TR": ("N", "VY", "MFZ"),
}


def discrete_element_fields(
    model, characteristics, numbering, cells, values: np.ndarray, options
) -> dict[str, ElementField]:
    """EFGE_ELNO / SIEF_ELNO of discrete cells of one modelisation for nodal
    values (n_orders, n_dofs), real or complex: f = K_local P u_e in the
    element frame (ORIENTATION, else x along the segment), the first node's
    sign reversed on segments; zero where a cell has no stiffness (code_aster
    warns). Points: the cell's nodes (a point cell's second is NaN)."""

    cells = np.asarray(cells, dtype=int)
    other = [name for name in options if name not in BAR_OPTIONS]
    if other:
        raise ValueError(f"{other[0]} is not computed for discrete elements (EFGE_ELNO, SIEF_ELNO)")
    kinds = {model.cell_modelisation[int(c)] for c in cells}
    if len(kinds) != 1:
        raise ValueError(f"discrete cells of several modelisations ({', '.join(sorted(kinds))})")
    modelisation = kinds.pop()
    dofs = MODELISATION_COMPONENTS[modelisation]
    dim = 2 if modelisation.startswith("2D_") else 3
    mesh = model.mesh
    values = np.asarray(values)
    out = np.full(
        (values.shape[0], len(cells), 2, len(dofs)), np.nan, dtype=np.result_type(values, float)
    )
    frames = cell_frames(model, cells, characteristics)
    for k, cell in enumerate(cells):
        nodes = list(mesh.cell_nodes[int(cell)])
        rows = numbering.dof_indices(np.repeat(nodes, len(dofs)), list(dofs) * len(nodes))
        u = np.zeros((values.shape[0], rows.size), dtype=values.dtype)
        u[:, rows >= 0] = values[:, rows[rows >= 0]]
        rotation = block_rotation(frames[k : k + 1], dofs, len(nodes))[0]
        assignment = (characteristics.discrete.get(int(cell), {}) if characteristics else {}).get(
            "K"
        )
        if assignment is None:
            forces = np.zeros_like(u)
        else:
            matrix = local_matrix(assignment.cara, assignment.values, dim, assignment.symmetric)
            if assignment.repere == "LOCAL":
                forces = (u @ rotation.T) @ matrix.T
            else:
                forces = (u @ matrix.T) @ rotation.T
        forces = forces.reshape(values.shape[0], len(nodes), len(dofs))
        if len(nodes) == 2:
            forces[:, 0] = -forces[:, 0]
        out[:, k, : len(nodes)] = forces
    components = DISCRETE_COMPONENTS[modelisation]
    return {name: ElementField(name, cells, components, out.copy()) for name in options}


def bar_element_fields(
    model, characteristics, materials, numbering, cells, values: np.ndarray, options
) -> dict[str, ElementField]:
    """EFGE_ELNO / SIEF_ELNO / SIEF_ELGA (component N, constant along the
    bar) of bar cells for nodal values (n_orders, n_dofs), real or complex."""

    cells = np.asarray(cells, dtype=int)
    other = [name for name in options if name not in BAR_FIELDS]
    if other:
        raise ValueError(f"{other[0]} is not computed for bars ({', '.join(BAR_FIELDS)})")
    mesh = model.mesh
    sections = characteristics.sections if characteristics is not None else {}
    without = [int(c) for c in cells if int(c) not in sections]
    if without:
        raise ElementError(f"bar cell {mesh.cell_names[without[0]]} has no section (BARRE)")
    young = _material_values(materials, cells, "BARRE", need_density=False)["E"]
    area = np.array([float(sections[int(c)]["A"]) for c in cells])
    conn = np.array([mesh.cell_nodes[c] for c in cells], dtype=int).reshape(-1, 2)
    axis = mesh.coords[conn[:, 1]] - mesh.coords[conn[:, 0]]
    length = np.linalg.norm(axis, axis=1)
    axis = axis / length[:, None]
    values = np.asarray(values)
    elongation = np.zeros((values.shape[0], len(cells)), dtype=np.result_type(values, float))
    for d, component in enumerate(("DX", "DY", "DZ")):
        rows = [numbering.dof_indices(conn[:, end], component) for end in (0, 1)]
        for sign, row in zip((-1.0, 1.0), rows, strict=True):
            present = row >= 0
            elongation[:, present] += sign * axis[present, d] * values[:, row[present]]
    force = elongation * (young * area / length)[None, :]
    points = {name: 1 if name.endswith("_ELGA") else 2 for name in options}
    return {
        name: ElementField(name, cells, ("N",), np.repeat(force[:, :, None, None], n, axis=2))
        for name, n in points.items()
    }


def nodal_average(field: ElementField, mesh, name: str) -> NodalComponentField:
    """``*_NOEU`` from an ELNO field: at each node, the mean over the cells
    holding it of their value at that node."""
    connectivity = [mesh.cell_nodes[c] for c in field.cells]
    nodes = sorted_unique(np.concatenate([np.asarray(c, dtype=int) for c in connectivity]))
    n_orders, _, _, n_cmp = field.values.shape
    # complex for a harmonic result's fields
    sums = np.zeros((n_orders, len(nodes), n_cmp), dtype=np.result_type(field.values, float))
    counts = np.zeros(len(nodes))
    # cells of one node count at a time (a field on several cell types is padded)
    sizes = np.array([len(c) for c in connectivity])
    for size in np.unique(sizes):
        rows = np.nonzero(sizes == size)[0]
        conn = np.array([connectivity[r] for r in rows], dtype=int)
        position = np.searchsorted(nodes, conn)  # (n_rows, size)
        for point in range(size):
            np.add.at(sums, (slice(None), position[:, point]), field.values[:, rows, point, :])
            np.add.at(counts, position[:, point], 1.0)
    return NodalComponentField(name, nodes, field.components, sums / counts[None, :, None])
