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
from asterlite.fem.multifibre_elements import cell_section

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

# beams with a gyroscopic matrix (code_aster's te0259/te0262): the multifibre
# ones take their section's rho-weighted fibre integrals (pmfitx), the warping
# ones (7 DOFs a node) the 12-DOF matrix with nothing on GRX (masstg)
GYRO_BEAMS = ("POU_D_E", "POU_D_T", "POU_D_EM", "POU_D_TG", "POU_D_TGM")
_EULER_GYRO_BEAMS = ("POU_D_E", "POU_D_EM")
_MULTIFIBRE_GYRO_BEAMS = ("POU_D_EM", "POU_D_TGM")
_WARPING_GYRO_BEAMS = ("POU_D_TG", "POU_D_TGM")
# solids have code_aster's MECA_GYRO too (te0159): not computed here
_GYRO_SOLIDS = ("3D", "3D_SI")

#: options a static superelement has a condensed matrix of (MACR_ELEM_STAT)
SUPERELEMENT_MATRICES = {"RIGI_MECA": "RIGI", "MASS_MECA": "MASS", "AMOR_MECA": "AMOR"}


def superelement_blocks(model, kind: str) -> list[ElementBlock]:
    """One block per super-cell of the model: its condensed matrix on the
    mesh nodes its external nodes became."""
    blocks = []
    for name, cell in model.substructures.items():
        macro = cell.macro
        if macro.matrices.get(kind) is None:
            what = {"RIGI": "RIGI_MECA", "MASS": "MASS_MECA", "AMOR": "AMOR_MECA"}[kind]
            raise ElementError(
                f"the superelement {macro.name} of super-cell {name} has no {what} matrix"
                + (" (its MODE_MESURE has no AMOR_GENE)" if kind == "AMOR" else "")
            )
        blocks.append(
            ElementBlock(
                nodes=np.asarray(cell.nodes, dtype=int).reshape(1, -1),
                components=tuple(macro.components),
                matrices=cell.matrix(kind)[None, :, :],
            )
        )
    return blocks


def _model_cells(model, cells) -> dict[str, np.ndarray]:
    wanted = None if cells is None else {int(c) for c in np.asarray(cells).ravel()}
    grouped: dict[str, list[int]] = defaultdict(list)
    for cell, modelisation in model.cell_modelisation.items():
        if wanted is None or cell in wanted:
            grouped[modelisation].append(int(cell))
    return {m: np.array(sorted(c), dtype=int) for m, c in sorted(grouped.items())}


def _beam_gyro_blocks(model, characteristics, materials, cells, option) -> list[ElementBlock]:
    """One modelisation's beam cells."""
    mesh = model.mesh
    modelisation = model.cell_modelisation[int(cells[0])]
    sections = characteristics.sections if characteristics is not None else {}
    missing = [c for c in cells if int(c) not in sections]
    if missing:
        names = ", ".join(mesh.cell_names[c] for c in missing[:5])
        raise ElementError(f"beam cells {names} have no section (AFFE_CARA_ELEM/POUTRE)")
    if materials is None:
        raise ElementError(f"{option} of beams needs a material field (CHAM_MATER)")
    if any(materials.material_of(c) is None for c in cells):
        raise ElementError(f"{option}: a beam cell has no material")
    poisson = materials.values(cells, "NU", 0.0)
    conn, lengths = beam.segment_cells(mesh, cells)
    if np.any(lengths <= 0.0):
        raise ElementError(f"{option}: beam element of zero length")

    def prop(name, default=0.0):
        return np.array([float(sections[int(c)].get(name, default)) for c in cells])

    if modelisation in _MULTIFIBRE_GYRO_BEAMS:
        # rho A, rho IY, rho IZ from the fibres: the density is in the integrals
        integrals = np.array(
            [cell_section(model, characteristics, materials, int(c)).density for c in cells]
        )
        density, area, iy, iz = 1.0, integrals[:, 0], integrals[:, 4], integrals[:, 3]
    else:
        density = materials.values(cells, "RHO", np.nan)
        if np.any(np.isnan(density)):
            raise ElementError(f"{option} of beams needs RHO in the material (ELAS)")
        area, iy, iz = prop("A"), prop("IY"), prop("IZ")
    euler = modelisation in _EULER_GYRO_BEAMS
    ay = 0.0 if euler else prop("AY")
    az = 0.0 if euler else prop("AZ")
    compute = (
        gyro.beam_gyro_damping_local if option == "MECA_GYRO" else gyro.beam_gyro_stiffness_local
    )
    local = compute(lengths, density, area, iy, iz, poisson, ay, az)
    rotations = beam.rotation_from_angles(cell_angles(model, characteristics, cells))
    matrices = beam.to_global(local, rotations, 6)
    components = beam.BEAM_COMPONENTS
    if modelisation in _WARPING_GYRO_BEAMS:  # no term on GRX
        keep = np.array([0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12])
        widened = np.zeros((len(cells), 14, 14))
        widened[:, keep[:, None], keep[None, :]] = matrices
        matrices, components = widened, MODELISATION_COMPONENTS[modelisation]
    return [ElementBlock(nodes=conn, components=components, matrices=matrices)]


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
        if modelisation in _GYRO_SOLIDS:
            raise ElementError(
                f"{option} of {modelisation} elements (code_aster's te0159) is not available"
            )
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
    if model.substructures and cells is not None:
        raise NotImplementedError("element matrices of some cells of a model with superelements")
    if model.substructures:
        # a model with superelements (AFFE_SOUS_STRUC): their condensed matrices too
        if option not in SUPERELEMENT_MATRICES:
            raise NotImplementedError(f"option {option} on a model with superelements")
        matrix, lumped = STANDARD_OPTIONS[option]
        elements = element_blocks(model, characteristics, matrix, materials=materials)
        return elements + superelement_blocks(model, SUPERELEMENT_MATRICES[option])
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
