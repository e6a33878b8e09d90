"""Element matrices by code_aster option name, for CALC_MATR_ELEM, ASSEMBLAGE.

``option_blocks(model, characteristics, option, materials=None, cells=None)``
gives the global-frame :class:`ElementBlock` list of one option:

- ``RIGI_MECA``, ``MASS_MECA``, ``MASS_MECA_DIAG``, ``AMOR_MECA``: the
  element computers of :mod:`asterlite.fem.elements`;
- ``MECA_GYRO`` / ``RIGI_GYRO``: gyroscopic damping per unit spin and
  gyroscopic stiffness per unit spin acceleration of beams and disks
  (:mod:`asterlite.fem.gyro`); non-symmetric;
- ``RIGI_MECA_HYST``: the complex stiffness ``K_e (1 + i eta)`` with ``eta``
  the ``AMOR_HYST`` of the discrete characteristic (``AFFE_CARA_ELEM``) for
  discrete elements, of the material (``DEFI_MATERIAU/ELAS``) for the others;
  on cells of a viscoelastic material (``ELAS_VISCO``, 3D and plane solids)
  ``B^T D B`` with the complex Hooke matrix D of its complex G and NU, whose
  real part is RIGI_MECA (code_aster's te0050, te0230).
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from asterlite.concepts.assembly import ElementBlock
from asterlite.fem import beam, gyro
from asterlite.fem.beam import cell_angles
from asterlite.fem.discrete import local_matrix, parse_cara
from asterlite.fem.dofs import DISCRETE_MODELISATIONS, MODELISATION_COMPONENTS
from asterlite.fem.elements import ElementError, cell_frames, element_blocks

#: option -> (matrix code of element_blocks, lumped)
STANDARD_OPTIONS = {
    "RIGI_MECA": ("K", False),
    "MASS_MECA": ("M", False),
    "MASS_MECA_DIAG": ("M", True),
    "AMOR_MECA": ("A", False),
}
GYRO_OPTIONS = ("MECA_GYRO", "RIGI_GYRO")
COMPLEX_OPTIONS = ("RIGI_MECA_HYST",)
OPTIONS = (*STANDARD_OPTIONS, *GYRO_OPTIONS, *COMPLEX_OPTIONS)

#: kind of the assembled matrix of each option
MATRIX_KIND = {
    "RIGI_MECA": "RIGI",
    "MASS_MECA": "MASS",
    "MASS_MECA_DIAG": "MASS",
    "AMOR_MECA": "AMOR",
    "MECA_GYRO": "GYRO",
    "RIGI_GYRO": "RIGY",
    "RIGI_MECA_HYST": "RIGI",
}

GYRO_BEAMS = ("POU_D_E", "POU_D_T")


def _model_cells(model, cells) -> dict[str, np.ndarray]:
    wanted = None if cells is None else {int(c) for c in np.asarray(cells).ravel()}
    grouped: dict[str, list[int]] = defaultdict(list)
    for cell, modelisation in model.cell_modelisation.items():
        if wanted is None or cell in wanted:
            grouped[modelisation].append(int(cell))
    return {m: np.array(sorted(c), dtype=int) for m, c in sorted(grouped.items())}


def _beam_gyro_blocks(model, characteristics, materials, cells, option) -> list[ElementBlock]:
    mesh = model.mesh
    sections = characteristics.sections if characteristics is not None else {}
    missing = [c for c in cells if int(c) not in sections]
    if missing:
        names = ", ".join(mesh.cell_names[c] for c in missing[:5])
        raise ElementError(f"beam cells {names} have no section (AFFE_CARA_ELEM/POUTRE)")
    if materials is None:
        raise ElementError(f"{option} of beams needs a material field (CHAM_MATER)")
    if any(materials.material_of(c) is None for c in cells):
        raise ElementError(f"{option}: a beam cell has no material")
    density = materials.values(cells, "RHO", np.nan)
    if np.any(np.isnan(density)):
        raise ElementError(f"{option} of beams needs RHO in the material (ELAS)")
    poisson = materials.values(cells, "NU", 0.0)
    conn, lengths = beam.segment_cells(mesh, cells)
    if np.any(lengths <= 0.0):
        raise ElementError(f"{option}: beam element of zero length")
    euler = np.array([model.cell_modelisation[int(c)] == "POU_D_E" for c in cells])

    def prop(name, default=0.0):
        return np.array([float(sections[int(c)].get(name, default)) for c in cells])

    ay = np.where(euler, 0.0, prop("AY"))
    az = np.where(euler, 0.0, prop("AZ"))
    compute = (
        gyro.beam_gyro_damping_local if option == "MECA_GYRO" else gyro.beam_gyro_stiffness_local
    )
    local = compute(lengths, density, prop("A"), prop("IY"), prop("IZ"), poisson, ay, az)
    rotations = beam.rotation_from_angles(cell_angles(model, characteristics, cells))
    matrices = beam.to_global(local, rotations, 6)
    return [ElementBlock(nodes=conn, components=beam.BEAM_COMPONENTS, matrices=matrices)]


def disk_polar_inertia(assignment) -> float:
    """The (DRX, DRX) term of a nodal ``M_TR_*_N`` mass, as given."""
    _, kind, _, support = parse_cara(assignment.cara)
    if kind != "TR" or support != "N":
        raise ElementError(f"{assignment.cara} is not the mass of a disk (M_TR_D_N or M_TR_N)")
    return float(local_matrix(assignment.cara, assignment.values, 3, assignment.symmetric)[3, 3])


def _disk_gyro_blocks(model, characteristics, cells, option) -> list[ElementBlock]:
    """DIS_TR on POI1 with a mass: the rigid-disk term on its node."""
    mesh = model.mesh
    disks, inertia = [], []
    for cell in cells:
        if mesh.cell_types[cell] != "POI1":
            continue
        masses = characteristics.discrete.get(int(cell), {}) if characteristics else {}
        if "M" not in masses:
            continue
        disks.append(int(cell))
        inertia.append(disk_polar_inertia(masses["M"]))
    if not disks:
        return []
    disks = np.array(disks, dtype=int)
    compute = (
        gyro.disk_gyro_damping_local if option == "MECA_GYRO" else gyro.disk_gyro_stiffness_local
    )
    local = compute(np.array(inertia))
    rotations = cell_frames(model, disks, characteristics)
    matrices = beam.element_rotation(rotations, 6, n_nodes=1)
    matrices = np.einsum("eji,ejk,ekl->eil", matrices, local, matrices)
    nodes = np.array([mesh.cell_nodes[c] for c in disks], dtype=int).reshape(-1, 1)
    return [
        ElementBlock(nodes=nodes, components=MODELISATION_COMPONENTS["DIS_TR"], matrices=matrices)
    ]


def gyro_blocks(model, characteristics, option, materials=None, cells=None) -> list[ElementBlock]:
    """MECA_GYRO or RIGI_GYRO element matrices (global frame, non-symmetric)."""
    if option not in GYRO_OPTIONS:
        raise ValueError(f"not a gyroscopic option: {option}")
    blocks = []
    for modelisation, members in _model_cells(model, cells).items():
        if modelisation in GYRO_BEAMS:
            blocks.extend(_beam_gyro_blocks(model, characteristics, materials, members, option))
        elif modelisation == "DIS_TR":
            blocks.extend(_disk_gyro_blocks(model, characteristics, members, option))
    return blocks


def hysteretic_coefficients(model, characteristics, materials, cells) -> np.ndarray:
    """AMOR_HYST of each cell: the stiffness characteristic's for discrete
    elements, the material's (ELAS) for the others (0 when absent)."""
    out = np.zeros(len(cells))
    for k, cell in enumerate(np.asarray(cells, dtype=int)):
        if model.cell_modelisation[int(cell)] in DISCRETE_MODELISATIONS:
            assignment = (
                characteristics.discrete.get(int(cell), {}) if characteristics else {}
            ).get("K")
            out[k] = assignment.hysteretic if assignment is not None else 0.0
        elif materials is not None:
            material = materials.material_of(int(cell))
            if material is not None:
                out[k] = float(material.get("AMOR_HYST", 0.0) or 0.0)
    return out


def viscoelastic_cells(materials, cells) -> np.ndarray:
    """The mask of ``cells`` whose material is viscoelastic (ELAS_VISCO)."""
    if materials is None:
        return np.zeros(len(cells), dtype=bool)
    return np.array(
        [
            (material := materials.material_of(int(c))) is not None
            and material.viscoelastic is not None
            for c in cells
        ],
        dtype=bool,
    )


def hysteretic_blocks(model, characteristics, materials=None, cells=None) -> list[ElementBlock]:
    """RIGI_MECA_HYST: complex element stiffnesses ``K_e (1 + i eta_e)``, or
    of the complex Hooke matrix on viscoelastic cells."""
    members = np.array(
        sorted(c for group in _model_cells(model, cells).values() for c in group), dtype=int
    )
    # discrete elements read no material: their AMOR_HYST is the characteristic's
    visco = viscoelastic_cells(materials, members) & np.array(
        [model.cell_modelisation[int(c)] not in DISCRETE_MODELISATIONS for c in members],
        dtype=bool,
    )
    blocks = []
    if np.any(visco):
        blocks.extend(
            element_blocks(
                model,
                characteristics,
                "K",
                materials=materials,
                cells=members[visco],
                complex_stiffness=True,
            )
        )
        members = members[~visco]
    eta = hysteretic_coefficients(model, characteristics, materials, members)
    for value in np.unique(eta):
        group = members[eta == value]
        for block in element_blocks(model, characteristics, "K", materials=materials, cells=group):
            blocks.append(block.scaled(complex(1.0, float(value))))
    return blocks


def option_blocks(model, characteristics, option, materials=None, cells=None) -> list[ElementBlock]:
    """Element matrices of any supported option (see the module docstring)."""
    if option in STANDARD_OPTIONS:
        matrix, lumped = STANDARD_OPTIONS[option]
        return element_blocks(
            model, characteristics, matrix, materials=materials, lumped=lumped, cells=cells
        )
    if option in GYRO_OPTIONS:
        return gyro_blocks(model, characteristics, option, materials, cells)
    if option == "RIGI_MECA_HYST":
        return hysteretic_blocks(model, characteristics, materials, cells)
    raise NotImplementedError(f"element matrices of option {option}")
