"""Mass, centre of gravity and inertia of a model (POST_ELEM MASS_INER).

The element mass matrices are assembled on the model's DOFs and projected on
the six rigid-body motions about the origin (three translations ``e_i`` and
three rotations ``e_i x x``, with the rotation DOFs turning by ``e_i``):
``Rᵀ M R = [[m I, m [c]×ᵀ], [m [c]×, J_O]]``. This gives the mass m, the
centre of gravity c and the inertia tensor about the origin for any element
(discrete masses with eccentricity and rotary inertia, consistent beam
masses), then the tensor about c by the parallel-axis theorem. Pipes and
straight beams use code_aster's own formulas instead (te0038: the exact tube
section, an elbow's centre of gravity off its chord; a beam's section
inertia about its axis and its own axes, which its mass matrix lacks).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.fem.assemble import assemble_blocks, build_numbering_dofs
from asterlite.fem.beam_elements import SECTION_INERTIA_BEAMS, beam_cell_inertias
from asterlite.fem.elements import element_blocks
from asterlite.fem.pipe_elements import PIPE_MODELISATIONS, pipe_cell_inertias
from asterlite.fem.solid_loads import solid_cells, solid_inertia

_TRANS = ("DX", "DY", "DZ")
_ROTS = ("DRX", "DRY", "DRZ")


def rigid_body_modes(numbering: DofNumbering) -> np.ndarray:
    """(n_dofs, 6) translations then rotations about the origin."""
    coords = numbering.mesh.coords
    modes = np.zeros((numbering.n_dofs, 6))
    nodes = numbering.dof_nodes
    comps = numbering.dof_components
    for row, (node, comp) in enumerate(zip(nodes, comps, strict=True)):
        x = coords[node]
        if comp in _TRANS:
            i = _TRANS.index(comp)
            modes[row, i] = 1.0
            for k in range(3):
                # (e_k x x)_i
                e = np.zeros(3)
                e[k] = 1.0
                modes[row, 3 + k] = np.cross(e, x)[i]
        elif comp in _ROTS:
            modes[row, 3 + _ROTS.index(comp)] = 1.0
    return modes


def cells_rigid_inertia(found) -> np.ndarray:
    """6x6 projection on the rigid motions about the origin of cells given as
    (mass, centre, inertia tensor about the centre): m I, m [e_k x c]_i,
    J_c + m (|c|^2 I - c c^T)."""
    rigid = np.zeros((6, 6))
    for mass, centre, inertia in found:
        coupling = mass * np.array([np.cross(e, centre) for e in np.eye(3)])
        rigid[:3, :3] += mass * np.eye(3)
        rigid[3:, :3] += coupling
        rigid[:3, 3:] += coupling.T
        rigid[3:, 3:] += inertia + mass * (centre @ centre * np.eye(3) - np.outer(centre, centre))
    return rigid


def mass_properties(model, characteristics=None, materials=None, cells=None) -> dict:
    """MASSE, CDG_X/Y/Z and the inertia about the centre of gravity
    (IX_G, IY_G, IZ_G, IXY_G, IXZ_G, IYZ_G: products as integrals of
    (x - xg)(y - yg) dm) and the principal moments IX_PRIN_G <= ... of the
    cells (default: the whole model)."""
    # 3D solids: volume integrals on code_aster's RIGI points; others: R^T M R
    solid = solid_cells(model, cells)
    rigid = solid_inertia(model, materials, solid) if len(solid) else np.zeros((6, 6))
    pool = model.cell_modelisation if cells is None else np.asarray(cells, dtype=int).ravel()
    others = sorted({int(c) for c in pool} - set(solid.tolist()))
    # pipes and beams: code_aster's own formulas of their mass, centre and inertia
    for families, cell_inertias in (
        (PIPE_MODELISATIONS, pipe_cell_inertias),
        (SECTION_INERTIA_BEAMS, beam_cell_inertias),
    ):
        chosen = [c for c in others if model.cell_modelisation.get(c) in families]
        for modelisation in sorted({model.cell_modelisation[c] for c in chosen}):
            same = [c for c in chosen if model.cell_modelisation[c] == modelisation]
            found = cell_inertias(model, characteristics, materials, same)
            rigid = rigid + cells_rigid_inertia(found)
        others = [c for c in others if c not in set(chosen)]
    if others:
        numbering = DofNumbering(
            mesh=model.mesh, dofs=build_numbering_dofs(model.node_components())
        )
        blocks = element_blocks(model, characteristics, "M", materials=materials, cells=others)
        mass_matrix = assemble_blocks(blocks, numbering)
        modes = rigid_body_modes(numbering)
        rigid = rigid + modes.T @ (mass_matrix @ modes)
    m = float(np.mean(np.diag(rigid)[:3])) if model.dim == 3 else float(rigid[0, 0])
    coupling = rigid[3:, :3]  # [e_k x x]·e_i summed: m (e_k x c)_i
    if m > 0.0:
        cz = -coupling[0, 1] / m
        cx = -coupling[1, 2] / m
        cy = -coupling[2, 0] / m
        centre = np.array([cx, cy, cz])
    else:
        centre = np.zeros(3)
    inertia_o = rigid[3:, 3:]
    shift = m * (centre @ centre * np.eye(3) - np.outer(centre, centre))
    inertia_g = inertia_o - shift
    principal = np.linalg.eigvalsh(0.5 * (inertia_g + inertia_g.T))
    return {
        "MASSE": m,
        "CDG_X": centre[0],
        "CDG_Y": centre[1],
        "CDG_Z": centre[2],
        "IX_G": inertia_g[0, 0],
        "IY_G": inertia_g[1, 1],
        "IZ_G": inertia_g[2, 2],
        "IXY_G": -inertia_g[0, 1],
        "IXZ_G": -inertia_g[0, 2],
        "IYZ_G": -inertia_g[1, 2],
        "IX_PRIN_G": principal[0],
        "IY_PRIN_G": principal[1],
        "IZ_PRIN_G": principal[2],
    }
