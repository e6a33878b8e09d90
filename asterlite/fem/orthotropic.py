"""Hooke matrices of the 3D and plane solid elements, isotropic or
orthotropic (``DEFI_MATERIAU/ELAS_ORTH``), in the global frame.

Strains and stresses are Voigt vectors ``(xx, yy, zz, xy, xz, yz)`` with
engineering shear strains (``2 eps_xy``), as code_aster's solid elements.

An orthotropic material is given in its frame (L, T, N): its compliance has
``1/E_L, 1/E_T, 1/E_N`` on the diagonal, ``-NU_LT/E_L, -NU_LN/E_L,
-NU_TN/E_T`` off it (``NU_LT``: the contraction along T of a tension along L)
and ``1/G_LT, 1/G_LN, 1/G_TN`` on the shears; the Hooke matrix is its inverse
(code_aster's closed form in separ_RI_elas_3D). The material frame is the
global one turned by the nautical angles of ``AFFE_CARA_ELEM/MASSIF
ANGL_REP`` (the global frame without them). Plane modelisations take the
rows (xx, yy, zz, xy) of the 3D matrix, N being the out-of-plane axis (the
hoop direction in ``AXIS``) and only the first angle, a turn about Z,
counting (code_aster's dpao2d); plane stress (``C_PLAN``) condenses out
``sigma_zz = 0``.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem.element_errors import ElementError
from asterlite.fem.frames import rotation_from_angles

#: ELAS_ORTH parameters a solid element needs
ORTHOTROPIC = ("E_L", "E_T", "E_N", "NU_LT", "NU_LN", "NU_TN", "G_LT", "G_LN", "G_TN")
#: the tensor entries (i, j) of each Voigt component
_VOIGT = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))
#: plane components (xx, yy, zz, xy) among the 3D ones
PLANE_ROWS = (0, 1, 2, 3)


def material_hooke(p: dict[str, float]) -> np.ndarray:
    """(6, 6) Hooke matrix of an orthotropic material in its frame (L, T, N)."""
    e1, e2, e3 = p["E_L"], p["E_T"], p["E_N"]
    compliance = np.zeros((6, 6))
    compliance[0, 0], compliance[1, 1], compliance[2, 2] = 1.0 / e1, 1.0 / e2, 1.0 / e3
    compliance[0, 1] = compliance[1, 0] = -p["NU_LT"] / e1
    compliance[0, 2] = compliance[2, 0] = -p["NU_LN"] / e1
    compliance[1, 2] = compliance[2, 1] = -p["NU_TN"] / e2
    compliance[3, 3], compliance[4, 4], compliance[5, 5] = (
        1.0 / p["G_LT"],
        1.0 / p["G_LN"],
        1.0 / p["G_TN"],
    )
    return np.linalg.inv(compliance)


def isotropic_hooke(young, poisson) -> np.ndarray:
    """(e, 6, 6) isotropic Hooke matrices (complex for complex moduli)."""
    young = np.asarray(young)
    poisson = np.asarray(poisson)
    lam = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson))
    mu = young / (2.0 * (1.0 + poisson))
    d = np.zeros((len(young), 6, 6), dtype=np.result_type(young, poisson, float))
    d[:, :3, :3] = lam[:, None, None]
    for i in range(3):
        d[:, i, i] += 2.0 * mu
        d[:, 3 + i, 3 + i] = mu
    return d


def rotate_hooke(d: np.ndarray, p: np.ndarray) -> np.ndarray:
    """(..., 6, 6) Hooke matrices given in local frames -> global frame, ``p``
    (..., 3, 3) the global-to-local rotations (rows: local axes)."""
    # with engineering shears, the tensor C_ijkl is D's entry for (ij), (kl)
    index = np.zeros((3, 3), dtype=int)
    for k, (i, j) in enumerate(_VOIGT):
        index[i, j] = index[j, i] = k
    tensor = d[..., index[:, :, None, None], index[None, None, :, :]]
    turned = np.einsum("...ai,...bj,...ck,...dl,...abcd->...ijkl", p, p, p, p, tensor)
    rows = [i for i, _ in _VOIGT]
    cols = [j for _, j in _VOIGT]
    return turned[..., rows, cols, :, :][..., rows, cols]


def orthotropic_cells(materials, cells) -> np.ndarray:
    """Mask of ``cells`` whose material is orthotropic (ELAS_ORTH)."""
    return np.array(
        [
            (m := materials.material_of(int(c))) is not None and m.orthotropic is not None
            for c in np.asarray(cells, dtype=int)
        ],
        dtype=bool,
    )


def _orthotropic_parameters(material, name: str, family: str) -> dict[str, float]:
    varying = material.behaviours.get("ELAS_VARYING", {})
    moving = [k for k in ORTHOTROPIC if k in varying]
    if moving:
        raise ElementError(
            f"{', '.join(moving)} of material {material.name or '?'} vary with "
            f"{varying[moving[0]]}: asterlite applies no command variable field (AFFE_VARC) "
            "to evaluate them"
        )
    params = material.orthotropic
    missing = [k for k in ORTHOTROPIC if params.get(k) is None]
    if missing:
        raise ElementError(
            f"{family} elements on cell {name} need {', '.join(missing)} in the "
            f"orthotropic material {material.name or '?'} (ELAS_ORTH)"
        )
    return params


def global_hooke(materials, characteristics, cells, mesh, family: str, young, poisson):
    """(e, 6, 6) global-frame Hooke matrices of ``cells``: orthotropic cells
    from their ELAS_ORTH turned to the global frame by MASSIF's angles, the
    others isotropic from ``young`` and ``poisson`` (their E and NU)."""
    cells = np.asarray(cells, dtype=int)
    ortho = orthotropic_cells(materials, cells)
    d = isotropic_hooke(np.where(ortho, 1.0, young), np.where(ortho, 0.0, poisson))
    angles = getattr(characteristics, "material_angles", {}) or {}
    plane = family in ("D_PLAN", "C_PLAN", "AXIS")
    for k in np.flatnonzero(ortho):
        cell = int(cells[k])
        material = materials.material_of(cell)
        local = material_hooke(_orthotropic_parameters(material, mesh.cell_names[cell], family))
        turn = angles.get(cell)
        if turn is not None and np.any(turn):
            # plane elements turn their material about Z only (the first angle)
            turn = np.array([turn[0], 0.0, 0.0]) if plane else turn
            local = rotate_hooke(local, rotation_from_angles(turn))
        d[k] = local
    return d


def plane_hooke(d3: np.ndarray, modelisation: str) -> np.ndarray:
    """(e, 4, 4) Hooke matrices on (xx, yy, zz, xy) of plane elements from the
    3D ones: plane strain and axisymmetry keep those rows, plane stress
    condenses out ``sigma_zz = 0`` (its zz row and column are then 0)."""
    rows = list(PLANE_ROWS)
    d = d3[:, rows][:, :, rows].copy()
    if modelisation == "C_PLAN":
        column = d[:, :, 2].copy()
        d = d - column[:, :, None] * d[:, 2, None, :] / d[:, 2, 2, None, None]
        d[:, 2, :] = 0.0
        d[:, :, 2] = 0.0
    return d


def plane_stress_out_of_plane(d3: np.ndarray) -> np.ndarray:
    """(e, 4) coefficients c with ``eps_zz = c . (eps_xx, eps_yy, 0, gamma_xy)``
    under plane stress (``sigma_zz = 0``)."""
    rows = list(PLANE_ROWS)
    d = d3[:, rows][:, :, rows]
    c = -d[:, 2, :] / d[:, 2, 2, None]
    c[:, 2] = 0.0
    return c
