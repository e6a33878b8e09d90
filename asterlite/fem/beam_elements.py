"""Element computers of straight beams and bars (``POU_D_E``, ``POU_D_T``,
``POU_D_TG``, ``BARRE``, ``2D_BARRE``) for :func:`asterlite.fem.elements.element_blocks`.

Each cell needs a section (``AFFE_CARA_ELEM/POUTRE`` or ``BARRE``, kept in
``characteristics.sections``) and a material (``CHAM_MATER``: E, NU, RHO,
AMOR_ALPHA, AMOR_BETA). Cells sharing modelisation, section and material are
computed in one vectorised call of :func:`asterlite.fem.beam.global_matrices`.

Damping (AMOR_MECA) is code_aster's Rayleigh damping per element:
``C_e = AMOR_ALPHA K_e + AMOR_BETA M_e`` with the consistent mass.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from asterlite.concepts.assembly import ElementBlock
from asterlite.fem import beam
from asterlite.fem.beam import BeamError, cell_angles, global_matrices
from asterlite.fem.element_errors import ElementError
from asterlite.fem.frames import rotation_from_angles
from asterlite.fem.multifibre_elements import local_matrix
from asterlite.fem.sections import SectionError

BEAM_MODELISATIONS = ("POU_D_E", "POU_D_T", "POU_D_TG", "BARRE", "2D_BARRE")


def _section_key(section: dict) -> tuple:
    return tuple(sorted((k, v) for k, v in section.items() if not isinstance(v, str)))


def _material_values(materials, cells, modelisation: str, need_density: bool):
    """E, NU, RHO, AMOR_ALPHA, AMOR_BETA arrays for the cells (checked)."""
    mesh_names = None
    if materials is None:
        raise ElementError(f"{modelisation} elements need a material field (CHAM_MATER)")
    missing = [c for c in cells if materials.material_of(c) is None]
    if missing:
        mesh_names = materials.mesh.cell_names
        names = ", ".join(mesh_names[c] for c in missing[:5])
        raise ElementError(f"no material is assigned to the {modelisation} cells {names}")
    values = {
        name: materials.values(cells, name, default)
        for name, default in (
            ("E", np.nan),
            ("NU", 0.0),
            ("RHO", np.nan),
            ("AMOR_ALPHA", 0.0),
            ("AMOR_BETA", 0.0),
        )
    }
    if np.any(np.isnan(values["E"])):
        raise ElementError(f"the material of {modelisation} elements has no E (ELAS)")
    if need_density and np.any(np.isnan(values["RHO"])):
        raise ElementError(f"the mass of {modelisation} elements needs RHO in the material (ELAS)")
    values["RHO"] = np.nan_to_num(values["RHO"])
    return values


def beam_blocks(
    model, characteristics, matrix, cells, materials=None, lumped=False, **_options
) -> list[ElementBlock]:
    """Global-frame matrices (K, M or A) of beam and bar cells."""
    if matrix not in ("K", "M", "A"):
        raise ElementError(f"unknown element matrix {matrix!r}")
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    modelisation = model.cell_modelisation[int(cells[0])]
    sections = characteristics.sections if characteristics is not None else {}
    without = [int(c) for c in cells if int(c) not in sections]
    if without:
        names = ", ".join(mesh.cell_names[c] for c in without[:5])
        keyword = "BARRE" if "BARRE" in modelisation else "POUTRE"
        raise ElementError(
            f"{modelisation} cells {names} have no section (AFFE_CARA_ELEM/{keyword})"
        )
    values = _material_values(materials, cells, modelisation, need_density=matrix != "K")
    # group cells sharing section and material values
    groups: dict[tuple, list[int]] = defaultdict(list)
    for k, cell in enumerate(cells):
        key = (
            _section_key(sections[int(cell)]),
            tuple(float(values[n][k]) for n in ("E", "NU", "RHO", "AMOR_ALPHA", "AMOR_BETA")),
        )
        groups[key].append(k)
    components = beam.COMPONENTS[modelisation]
    angles = cell_angles(model, characteristics, cells)
    conn = np.array([mesh.cell_nodes[c] for c in cells], dtype=int).reshape(-1, 2)
    out = np.zeros((len(cells), 2 * len(components), 2 * len(components)))
    for (_, (young, poisson, density, alpha, beta)), rows in groups.items():
        rows = np.asarray(rows, dtype=int)
        section = sections[int(cells[rows[0]])]
        x1, x2 = mesh.coords[conn[rows, 0]], mesh.coords[conn[rows, 1]]

        material = (young, poisson, density)

        def matrices(kind, lump=False, rows=rows, x1=x1, x2=x2, section=section, mat=material):
            return global_matrices(
                modelisation, kind, x1, x2, section, *mat, angles=angles[rows], lumped=lump
            )

        try:
            if matrix == "K":
                out[rows] = matrices("K")
            elif matrix == "M":
                out[rows] = matrices("M", lumped)
            else:
                block = np.zeros((len(rows),) + out.shape[1:])
                if alpha:
                    block += alpha * matrices("K")
                if beta:
                    block += beta * matrices("M")
                out[rows] = block
        except (BeamError, SectionError) as exc:
            names = ", ".join(mesh.cell_names[c] for c in cells[rows][:3])
            raise ElementError(f"{modelisation} cells {names}: {exc}") from None
    return [ElementBlock(nodes=conn, components=components, matrices=out)]


# -- internal forces ------------------------------------------------------------------

#: Components of EFGE_ELNO / SIEF_ELNO for beams and bars.
EFGE_COMPONENTS = ("N", "VY", "VZ", "MT", "MFY", "MFZ")
#: Components of SIPO_ELNO.
SIPO_COMPONENTS = ("SN", "SVY", "SVZ", "SMT", "SMFY", "SMFZ")


def per_cell_products(matrices: np.ndarray, values: np.ndarray) -> np.ndarray:
    """(n_orders, n_cells, m) products ``A_e v_oe`` of per-cell matrices
    (n_cells, m, n) and values (n_orders, n_cells, n), summed over n term by
    term (one multiplication then one addition per term, each rounded): an
    order's result is the same whatever the number of orders computed
    together (batched BLAS products round differently with the batch size)."""
    out = values[:, :, None, 0] * matrices[None, :, :, 0]
    for j in range(1, matrices.shape[2]):
        out += values[:, :, None, j] * matrices[None, :, :, j]
    return out


class BeamForces:
    """The per-cell operators of the internal forces of two-node beam cells,
    built once and applied to blocks of orders: the rotations to the local
    frames and the local stiffness (and mass, with ``inertia``) matrices.

    ``POU_D_E`` / ``POU_D_T`` / ``POU_D_EM`` cells: 6 DOFs a node, forces N VY
    VZ MT MFY MFZ; ``warping`` (``POU_D_TG`` cells): 7 DOFs a node, the
    bimoment BX after them, stiffness only (code_aster's ef0344 adds no
    inertia, whatever the result). The mass is the consistent one, or the
    lumped one (MASS_MECA_DIAG) with ``lumped``; without RHO it is 0
    (code_aster takes 0)."""

    def __init__(
        self,
        model,
        characteristics,
        materials,
        cells,
        inertia: bool = False,
        lumped: bool = False,
        warping: bool = False,
    ):
        cells = np.asarray(cells, dtype=int)
        self.per_node = 7 if warping else 6
        angles = cell_angles(model, characteristics, cells)
        _, lengths = beam.segment_cells(model.mesh, cells)
        self.rotations = beam.element_rotation(beam.rotation_from_angles(angles), self.per_node)
        if warping:
            self.stiffness_matrices = _warping_stiffness(
                model, characteristics, materials, cells, lengths
            )
            self.mass_matrices = None
            return
        self.stiffness_matrices = _local_matrices(
            model, characteristics, materials, cells, lengths, "K"
        )
        self.mass_matrices = (
            _local_matrices(model, characteristics, materials, cells, lengths, "M", lumped)
            if inertia
            else None
        )

    def _section_forces(self, matrices, values) -> np.ndarray:
        local = per_cell_products(self.rotations, values)
        nodal = per_cell_products(matrices, local)
        out = nodal.reshape(nodal.shape[:-1] + (2, self.per_node))
        out[..., 0, :] *= -1.0
        return out

    def stiffness(self, displacements: np.ndarray) -> np.ndarray:
        """(n_orders, n_cells, 2, per_node) ``K_local u_local`` with node 1's
        sign reversed (code_aster's EFGE_ELNO / SIEF_ELNO: internal forces on
        the section, not nodal forces), from (n_orders, n_cells, 2 per_node)
        global-frame element DOFs (node 1 then node 2)."""
        return self._section_forces(self.stiffness_matrices, displacements)

    def inertia(self, accelerations: np.ndarray) -> np.ndarray:
        """The part ``M_local a_local`` of the internal forces, same
        convention as :meth:`stiffness`."""
        if self.mass_matrices is None:
            raise ValueError("BeamForces built without inertia")
        return self._section_forces(self.mass_matrices, accelerations)


def _local_matrices(
    model, characteristics, materials, cells, lengths, matrix: str, lumped: bool = False
) -> np.ndarray:
    """(n_cells, 12, 12) local-frame matrices of POU_D_E / POU_D_T / POU_D_EM
    cells: the stiffness ('K') or the mass ('M', lumped as MASS_MECA_DIAG
    with ``lumped``)."""
    sections = characteristics.sections if characteristics is not None else {}
    # no RHO: no inertia (code_aster takes 0)
    props = _material_values(materials, cells, "beam", need_density=False)
    out = np.zeros((len(cells), 12, 12))
    for k, cell in enumerate(cells):
        modelisation = model.cell_modelisation[int(cell)]
        if modelisation == "POU_D_EM":
            # the fibre-integrated element (code_aster's ef0142 / poefgr use pmfrig, pmfmas)
            out[k] = local_matrix(
                model, characteristics, materials, int(cell), lengths[k], matrix, lumped
            )
            continue
        if modelisation not in ("POU_D_E", "POU_D_T"):
            raise ElementError(f"internal forces of {modelisation} cells are not available")
        out[k] = beam.local_matrices(
            modelisation,
            matrix,
            lengths[k],
            sections[int(cell)],
            props["E"][k],
            props["NU"][k],
            props["RHO"][k],
            lumped,
        )[0]
    return out


def section_forces(nodal_forces: np.ndarray) -> np.ndarray:
    """(..., 12) local element end forces -> (..., 2, 6) internal forces on
    the sections: node 1's sign reversed (code_aster's EFGE convention)."""
    out = nodal_forces.reshape(nodal_forces.shape[:-1] + (2, 6)).copy()
    out[..., 0, :] *= -1.0
    return out


#: Components of POU_D_TG's EFGE_ELNO: the bimoment BX after the six others.
WARPING_EFGE_COMPONENTS = EFGE_COMPONENTS + ("BX",)


def _warping_stiffness(model, characteristics, materials, cells, lengths) -> np.ndarray:
    """(n_cells, 14, 14) local stiffness matrices of POU_D_TG cells (DX..DRZ,
    GRX of each node)."""
    sections = characteristics.sections if characteristics is not None else {}
    props = _material_values(materials, cells, "POU_D_TG", need_density=False)
    out = np.zeros((len(cells), 14, 14))
    for k, cell in enumerate(cells):
        out[k] = beam.local_matrices(
            "POU_D_TG", "K", lengths[k], sections[int(cell)], props["E"][k], props["NU"][k]
        )[0]
    return out


#: Components of SIPM_ELNO.
SIPM_COMPONENTS = ("SIXXMIN", "SIXXMAX")


def beam_extreme_stresses(efge: np.ndarray, sections: list[dict]) -> np.ndarray:
    """SIPM_ELNO (n_orders, n_cells, 2, 2) from EFGE_ELNO: the smallest and
    largest axial stress over the section, N/A -+ the bending part, which is
    |MFY| HZ/(2 IY) + |MFZ| HY/(2 IZ) for a rectangle and
    R sqrt(MFY² + MFZ²)/IY for a circle (code_aster's rule; it has no value
    for other sections)."""
    out = np.zeros(efge.shape[:-1] + (2,))
    for k, section in enumerate(sections):
        f = efge[:, k]
        kind = section.get("SECTION", "GENERALE")
        if kind == "RECTANGLE":
            bending = np.abs(f[..., 4]) / section["IY"] * section["HZ"] / 2.0
            bending += np.abs(f[..., 5]) / section["IZ"] * section["HY"] / 2.0
        elif kind == "CERCLE":
            bending = section["R"] / section["IY"] * np.hypot(f[..., 4], f[..., 5])
        else:
            raise ValueError("SIPM_ELNO needs a RECTANGLE or CERCLE section")
        axial = f[..., 0] / section["A"]
        out[:, k, :, 0] = axial - bending
        out[:, k, :, 1] = axial + bending
    return out


def beam_stresses(efge: np.ndarray, sections: list[dict], modelisations: list[str]) -> np.ndarray:
    """SIPO_ELNO (n_orders, n_cells, 2, 6) from EFGE_ELNO: SN = N/A,
    SVY = VY/(A/AY), SVZ = VZ/(A/AZ) (A for POU_D_E), SMT = MT RT/JX,
    SMFY = MFY z/IY, SMFZ = -MFZ y/IZ at the fibre (y, z) = (HY/2, HZ/2) of a
    rectangle, (R, R) of a circle, (RY, RZ) of a general section."""
    out = np.zeros_like(efge)
    for k, (section, modelisation) in enumerate(zip(sections, modelisations, strict=True)):
        area = section["A"]
        ay = 0.0 if modelisation == "POU_D_E" else section.get("AY", 0.0)
        az = 0.0 if modelisation == "POU_D_E" else section.get("AZ", 0.0)
        shear_y = area / ay if ay else area
        shear_z = area / az if az else area
        kind = section.get("SECTION", "GENERALE")
        if kind == "RECTANGLE":
            fibre_y, fibre_z = section["HY"] / 2.0, section["HZ"] / 2.0
        elif kind == "CERCLE":
            fibre_y = fibre_z = section["R"]
        else:
            fibre_y, fibre_z = section.get("RY", 1.0), section.get("RZ", 1.0)
        f = efge[:, k]
        out[:, k, :, 0] = f[..., 0] / area
        out[:, k, :, 1] = f[..., 1] / shear_y
        out[:, k, :, 2] = f[..., 2] / shear_z
        out[:, k, :, 3] = f[..., 3] / section["JX"] * section.get("RT", 1.0)
        out[:, k, :, 4] = f[..., 4] / section["IY"] * fibre_z
        out[:, k, :, 5] = -f[..., 5] / section["IZ"] * fibre_y
    return out


# -- mass and inertia (POST_ELEM MASS_INER) -------------------------------------------

#: Beams whose mass and inertia code_aster computes from the section (te0038).
SECTION_INERTIA_BEAMS = ("POU_D_E", "POU_D_T", "POU_D_TG")


def beam_cell_inertias(model, characteristics, materials, cells) -> list:
    """(mass, centre, inertia tensor about the centre) of each straight beam
    cell, from code_aster's MASS_INER of a constant section (te0038): the mass
    rho A L at the cell's middle and, in the beam's frame, rho L (IY + IZ)
    about its axis and rho L (I + A L^2 / 12) about the section's y and z axes
    (section offsets EY, EZ play no part)."""
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    mesh = model.mesh
    sections = characteristics.sections if characteristics is not None else {}
    without = [int(c) for c in cells if int(c) not in sections]
    if without:
        names = ", ".join(mesh.cell_names[c] for c in without[:5])
        raise ElementError(f"beam cells {names} have no section (AFFE_CARA_ELEM/POUTRE)")
    modelisation = model.cell_modelisation[int(cells[0])]
    density = _material_values(materials, cells, modelisation, need_density=True)["RHO"]
    conn, lengths = beam.segment_cells(mesh, cells)
    to_local = rotation_from_angles(cell_angles(model, characteristics, cells))
    found = []
    for k, cell in enumerate(cells):
        section = sections[int(cell)]
        length, rho, area = lengths[k], density[k], section["A"]
        bending = area * length**2 / 12.0
        local = (
            rho
            * length
            * np.diag(
                [section["IY"] + section["IZ"], section["IY"] + bending, section["IZ"] + bending]
            )
        )
        centre = mesh.coords[conn[k]].mean(axis=0)
        found.append((rho * area * length, centre, to_local[k].T @ local @ to_local[k]))
    return found
