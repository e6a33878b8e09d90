"""Element matrices of a model for one option, grouped into vectorised blocks.

``element_blocks(model, characteristics, matrix, materials=None, lumped=False)``
returns the global-frame :class:`ElementBlock` list for ``matrix`` in ``K``
(RIGI_MECA), ``M`` (MASS_MECA, or MASS_MECA_DIAG with ``lumped``) or ``A``
(AMOR_MECA). Each modelisation has a computer in :data:`ELEMENT_COMPUTERS`
called as ``fn(model, characteristics, matrix, cells, materials=..., lumped=...)``.
Discrete elements (here): cells sharing one characteristic are computed
together, one local matrix then one batched rotation when the values are
given in the LOCAL frame. The other families have a module each
(:data:`ELEMENT_FAMILIES`).
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from asterlite.concepts.assembly import ElementBlock, ElementCharacteristics, Model
from asterlite.fem.absorbing_elements import ABSORBING_MODELISATIONS, absorbing_blocks
from asterlite.fem.beam_elements import BEAM_MODELISATIONS, beam_blocks
from asterlite.fem.discrete import local_matrix, parse_cara
from asterlite.fem.dofs import DISCRETE_MODELISATIONS, MODELISATION_COMPONENTS
from asterlite.fem.element_errors import ElementError
from asterlite.fem.frames import angles_from_axis, block_rotation, rotation_from_angles
from asterlite.fem.multifibre_elements import MULTIFIBRE_MODELISATIONS, multifibre_blocks
from asterlite.fem.pipe_elements import PIPE_MODELISATIONS, pipe_blocks
from asterlite.fem.plane_elements import PLANE_MODELISATIONS, plane_blocks
from asterlite.fem.plate_elements import PLATE_MODELISATIONS, plate_blocks
from asterlite.fem.solid_elements import SOLID_MODELISATIONS, solid_blocks


def cell_frames(model: Model, cells: np.ndarray, characteristics) -> np.ndarray:
    """(n, 3, 3) global-to-local rotations of cells: ORIENTATION when given,
    else x along the segment (SEG2) or the global frame (POI1)."""
    mesh = model.mesh
    angles = np.zeros((len(cells), 3))
    for k, cell in enumerate(cells):
        given = characteristics.orientation.get(int(cell)) if characteristics else None
        if given is not None:
            angles[k] = given
        elif mesh.cell_types[cell] == "SEG2":
            a, b = mesh.cell_nodes[cell]
            angles[k] = angles_from_axis(mesh.coords[b] - mesh.coords[a])
    return rotation_from_angles(angles)


def _discrete_blocks(model, characteristics, matrix, cells, **_options) -> list[ElementBlock]:
    """Discrete elements: the characteristics as given (masses are used as
    given by MASS_MECA_DIAG too; AMOR_MECA is the A_* characteristic only, as
    code_aster: the material's Rayleigh coefficients do not apply to them)."""
    mesh = model.mesh
    # group cells sharing modelisation, cell type and characteristic values
    groups: dict[tuple, list[int]] = defaultdict(list)
    for cell in cells:
        assignment = (characteristics.discrete.get(int(cell), {}) if characteristics else {}).get(
            matrix
        )
        if assignment is None:
            continue
        key = (
            model.cell_modelisation[cell],
            mesh.cell_types[cell],
            assignment.cara,
            tuple(np.atleast_1d(assignment.values).tolist()),
            assignment.repere,
            assignment.symmetric,
        )
        groups[key].append(int(cell))
    blocks = []
    for (modelisation, cell_type, cara, values, repere, symmetric), members in groups.items():
        members = np.array(members, dtype=int)
        dim = 2 if modelisation.startswith("2D_") else 3
        components = MODELISATION_COMPONENTS[modelisation]
        _, kind, _, support = parse_cara(cara)
        wanted_kind = "TR" if modelisation.endswith("_TR") else "T"
        if kind != wanted_kind:
            raise ElementError(f"{cara} does not match modelisation {modelisation}")
        if (support == "N") != (cell_type == "POI1"):
            raise ElementError(f"{cara} cannot be assigned to {cell_type} cells")
        local = local_matrix(cara, values, dim, symmetric)
        n_nodes = 1 if cell_type == "POI1" else 2
        nodes = np.array([mesh.cell_nodes[c] for c in members], dtype=int).reshape(-1, n_nodes)
        if repere == "LOCAL" and not _rotation_invariant(local, components, n_nodes):
            rot = block_rotation(cell_frames(model, members, characteristics), components, n_nodes)
            mats = np.einsum("eji,jk,ekl->eil", rot, local, rot)  # Pᵀ A P
        else:
            mats = np.broadcast_to(local, (len(members),) + local.shape).copy()
        blocks.append(ElementBlock(nodes=nodes, components=components, matrices=mats))
    return blocks


def _rotation_invariant(local: np.ndarray, components, n_nodes: int) -> bool:
    """True when every per-node 3x3 (or 2x2) vector block is isotropic, so any
    rotation leaves the matrix unchanged (saves the batched rotation)."""
    per = len(components)
    idx = {c: k for k, c in enumerate(components)}
    groups = [[idx[c] for c in t if c in idx] for t in (("DX", "DY", "DZ"), ("DRX", "DRY", "DRZ"))]
    groups = [g for g in groups if len(g) >= 2]
    for a in range(n_nodes):
        for b in range(n_nodes):
            blk = local[a * per : (a + 1) * per, b * per : (b + 1) * per]
            for g in groups:
                for h in groups:
                    sub = blk[np.ix_(g, h)]
                    if g == h:
                        if not np.allclose(sub, sub[0, 0] * np.eye(len(g))):
                            return False
                    elif np.any(sub):
                        return False
    return True


#: Element computations by modelisation, one row per family (a new family:
#: its module gives its modelisations and computer, and one row here):
#: fn(model, characteristics, matrix, cells, materials=None, lumped=False)
#: -> list[ElementBlock].
ELEMENT_FAMILIES = (
    (DISCRETE_MODELISATIONS, _discrete_blocks),
    (BEAM_MODELISATIONS, beam_blocks),  # beams and bars
    (MULTIFIBRE_MODELISATIONS, multifibre_blocks),  # multifibre beams
    (PLANE_MODELISATIONS, plane_blocks),  # plane strain, plane stress, axisymmetric solids
    (SOLID_MODELISATIONS, solid_blocks),  # 3D solids
    (PLATE_MODELISATIONS, plate_blocks),  # DKT plates
    (ABSORBING_MODELISATIONS, absorbing_blocks),  # paraxial (absorbing) boundaries
    (PIPE_MODELISATIONS, pipe_blocks),  # straight pipes with ovalisation (TUYAU_3M, TUYAU_6M)
)
ELEMENT_COMPUTERS = {name: compute for names, compute in ELEMENT_FAMILIES for name in names}
if len(ELEMENT_COMPUTERS) != sum(len(names) for names, _ in ELEMENT_FAMILIES):
    raise ImportError("a modelisation is given to two element families")


def element_blocks(
    model: Model,
    characteristics: ElementCharacteristics | None,
    matrix: str,
    materials=None,
    lumped: bool = False,
    cells=None,
    complex_stiffness: bool = False,
) -> list[ElementBlock]:
    """Global-frame element matrices of the model for ``matrix`` (K, M or A).

    ``materials`` is the CHAM_MATER (needed by beams and bars), ``lumped``
    asks for MASS_MECA_DIAG, ``cells`` restricts the computation to a subset
    of the model's cells (default: all of them). ``complex_stiffness``
    keeps the imaginary part of K on viscoelastic cells (RIGI_MECA_HYST):
    only the 3D and plane solids take such materials.
    """
    wanted = None if cells is None else {int(c) for c in np.asarray(cells).ravel()}
    by_modelisation: dict[str, list[int]] = defaultdict(list)
    for cell, modelisation in model.cell_modelisation.items():
        if wanted is None or cell in wanted:
            by_modelisation[modelisation].append(cell)
    missing = sorted(m for m in by_modelisation if m not in ELEMENT_COMPUTERS)
    if missing:
        raise NotImplementedError(f"element matrices of modelisation {', '.join(missing)}")
    blocks = []
    for modelisation, members in sorted(by_modelisation.items()):
        compute = ELEMENT_COMPUTERS[modelisation]
        blocks.extend(
            compute(
                model,
                characteristics,
                matrix,
                np.array(sorted(members), dtype=int),
                materials=materials,
                lumped=lumped,
                **({"complex_stiffness": True} if complex_stiffness else {}),
            )
        )
    return blocks
