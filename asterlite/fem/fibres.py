"""Multifibre beam sections (DEFI_GEOM_FIBRE) and the POU_D_EM element.

A fibre is a point (y, z) of the section with an area. code_aster builds
fibres from the surface cells of a section mesh (TRIA3: the vertex mean and
the triangle's area; QUAD4: the mean of the four vertices and the sum of the
areas of triangles 123 and 143), or takes them as given (FIBRE: triples
y, z, area or diameter). Coordinates are moved to the beam axis
(COOR_AXE_POUTRE) then turned by ANGLE (degrees) about it.

POU_D_EM, the Euler-Bernoulli multifibre beam, integrates its elastic
section over the fibres, E constant within a fibre group:

- stiffness: EA = Σ E A, ∫E y, ∫E z (axial-bending coupling when the section
  is not centred for E), EI_z = Σ E A y², EI_y = Σ E A z², ∫E y z; an
  incompatible (quadratic) axial mode, condensed, softens bending when
  ∫E y or ∫E z is not zero; torsion is G JX with JX of AFFE_CARA_ELEM/POUTRE
  and G from E, NU of the section material (DEFI_COMPOR MATER_SECT), with
  the terms code_aster adds for a torsion centre off the axis;
- mass (MASS_MECA): consistent cubic mass of the ρ-weighted integrals with
  the same incompatible-mode terms; MASS_MECA_DIAG: code_aster's lumped one.
"""

from __future__ import annotations

import numpy as np

#: section cell types that make fibres, and the types a section mesh may hold besides
FIBRE_CELLS = ("TRIA3", "QUAD4")
IGNORED_SECTION_CELLS = ("SEG2",)


class FibreError(ValueError):
    """Fibre data a section or an element cannot be built from."""


def section_fibres(coords: np.ndarray, cells: list[tuple[int, ...]], axis, angle_deg: float):
    """(y, z, area) arrays of the fibres of surface cells (node index tuples
    of TRIA3 / QUAD4 cells) of a plane section mesh (x -> y, y -> z)."""
    cc, ss = np.cos(np.radians(angle_deg)), np.sin(np.radians(angle_deg))
    xy = np.asarray(coords, dtype=float)[:, :2] - np.asarray(axis, dtype=float)
    turned = np.column_stack([xy[:, 0] * cc - xy[:, 1] * ss, xy[:, 0] * ss + xy[:, 1] * cc])
    y, z, area = [], [], []
    for nodes in cells:
        p = turned[list(nodes)]
        d1, d2 = p[1] - p[0], p[2] - p[0]
        surface = abs(d1[0] * d2[1] - d1[1] * d2[0]) / 2.0
        if len(nodes) == 4:
            d3 = p[3] - p[0]
            surface += abs(d3[0] * d2[1] - d3[1] * d2[0]) / 2.0
        centre = p.mean(axis=0)
        y.append(centre[0])
        z.append(centre[1])
        area.append(surface)
    return np.array(y), np.array(z), np.array(area)


def point_fibres(values, cara: str, axis, angle_deg: float):
    """(y, z, area) of FIBRE triples (y, z, SURFACE or DIAMETRE)."""
    v = np.asarray(values, dtype=float)
    if v.size % 3:
        raise FibreError(f"VALE gives {v.size} values, not triples (y, z, {cara.lower()})")
    v = v.reshape(-1, 3)
    cc, ss = np.cos(np.radians(angle_deg)), np.sin(np.radians(angle_deg))
    y0, z0 = v[:, 0] - axis[0], v[:, 1] - axis[1]
    area = v[:, 2] ** 2 * np.pi / 4.0 if cara == "DIAMETRE" else v[:, 2]
    return y0 * cc - z0 * ss, y0 * ss + z0 * cc, area


def section_integrals(y, z, area) -> np.ndarray:
    """(6,) Σ A, Σ y A, Σ z A, Σ y² A, Σ z² A, Σ y z A over fibres."""
    y, z, a = (np.asarray(v, dtype=float) for v in (y, z, area))
    return np.array(
        [
            a.sum(),
            (y * a).sum(),
            (z * a).sum(),
            (y * y * a).sum(),
            (z * z * a).sum(),
            (y * z * a).sum(),
        ]
    )


# -- POU_D_EM local matrices (DOFs u v w rx ry rz of node 1, then node 2) ---------------


def _symmetric(upper: dict[tuple[int, int], float]) -> np.ndarray:
    """12x12 matrix from 1-based (i, j) entries, each pair given once."""
    m = np.zeros((12, 12))
    for (i, j), value in upper.items():
        m[i - 1, j - 1] = m[j - 1, i - 1] = value
    return m


def stiffness_local(length: float, cars, gj: float) -> np.ndarray:
    """12x12 local stiffness of a POU_D_EM element of length ``length``:
    ``cars`` the E-weighted section integrals (:func:`section_integrals`
    order), ``gj`` the torsion stiffness G JX."""
    L = float(length)
    ea, esy, esz, eiz, eiy, eiyz = (float(c) for c in cars)
    if not ea > 0.0:
        raise FibreError("the fibres of a POU_D_EM element give no axial stiffness (Σ E A = 0)")
    k: dict[tuple[int, int], float] = {}
    # axial, torsion
    k[1, 1] = k[7, 7] = ea / L
    k[1, 7] = -ea / L
    k[4, 4] = k[10, 10] = gj / L
    k[4, 10] = -gj / L
    # bending in xOy (v, rz) with EI_z, in xOz (w, ry) with EI_y (ry = -w')
    for (t1, r1, t2, r2), ei, s in (((2, 6, 8, 12), eiz, 1.0), ((3, 5, 9, 11), eiy, -1.0)):
        k[t1, t1] = k[t2, t2] = 12.0 * ei / L**3
        k[t1, t2] = -12.0 * ei / L**3
        k[t1, r1] = k[t1, r2] = s * 6.0 * ei / L**2
        k[r1, t2] = k[t2, r2] = -s * 6.0 * ei / L**2
        k[r1, r1] = k[r2, r2] = 4.0 * ei / L
        k[r1, r2] = 2.0 * ei / L
    # axial-bending coupling by the first moments: N = EA u' + ∫Ez ry' - ∫Ey rz'
    for rot, moment in ((5, esz), (6, -esy)):
        k[1, rot] = moment / L
        k[1, rot + 6] = -moment / L
        k[7, rot + 6] = moment / L
        k[rot, 7] = -moment / L
    # coupling of the two bending planes by the product of inertia
    c = eiyz
    k[2, 3] = 12.0 * c / L**3
    k[2, 9] = k[3, 8] = -12.0 * c / L**3
    k[8, 9] = 12.0 * c / L**3
    for (i, j), sign in (
        ((2, 5), -1), ((3, 6), 1), ((2, 11), -1), ((3, 12), 1),
        ((5, 8), 1), ((6, 9), -1), ((8, 11), 1), ((9, 12), -1),
    ):  # fmt: skip
        k[i, j] = sign * 6.0 * c / L**2
    k[5, 6] = k[11, 12] = -4.0 * c / L
    k[5, 12] = k[6, 11] = -2.0 * c / L
    out = _symmetric(k)
    # incompatible quadratic axial mode, condensed: -(1/(L EA)) b bᵀ
    root3 = np.sqrt(3.0)
    bv = np.zeros(12)
    bw = np.zeros(12)
    bv[[1, 5, 7, 11]] = root3 * np.array([2.0 / L, 1.0, -2.0 / L, 1.0])
    bw[[2, 4, 8, 10]] = root3 * np.array([2.0 / L, -1.0, -2.0 / L, -1.0])
    b = -esy * bv - esz * bw
    out -= np.outer(b, b) / (L * ea)
    _torsion_centre_terms(out, ety=esy / ea, etz=esz / ea)
    return out


def _torsion_centre_terms(k: np.ndarray, ety: float, etz: float) -> None:
    """Torsion-bending terms of a torsion centre at (ety, etz) from the axis,
    as code_aster adds them to the multifibre stiffness (in place)."""
    v1, w1, rx1, ry1, rz1, v2, w2, rx2, ry2, rz2 = 1, 2, 3, 4, 5, 7, 8, 9, 10, 11
    torsion = k[rx1, rx1] + etz**2 * k[v1, v1] + ety**2 * k[w1, w1]
    couple_v = -etz * k[v1, v1] + ety * k[v1, w1]
    couple_w = -etz * k[v1, w1] + ety * k[w1, w1]
    couple_ry = -etz * k[v1, ry1] + ety * k[w1, ry1]
    couple_rz = -etz * k[v1, rz1] + ety * k[w1, rz1]
    entries = {
        (rx1, rx1): torsion, (rx2, rx2): torsion, (rx1, rx2): -torsion,
        (v1, rx1): couple_v, (v1, rx2): -couple_v, (rx1, v2): -couple_v, (v2, rx2): couple_v,
        (w1, rx1): couple_w, (w1, rx2): -couple_w, (rx1, w2): -couple_w, (w2, rx2): couple_w,
        (rx1, ry1): couple_ry, (rx1, ry2): couple_ry,
        (ry1, rx2): -couple_ry, (rx2, ry2): -couple_ry,
        (rx1, rz1): couple_rz, (rx1, rz2): couple_rz,
        (rz1, rx2): -couple_rz, (rx2, rz2): -couple_rz,
    }  # fmt: skip
    for (i, j), value in entries.items():
        k[i, j] = k[j, i] = value


def mass_local(length: float, cars, kk12: float, kk13: float, lumped: bool = False) -> np.ndarray:
    """12x12 local mass of a POU_D_EM element: ``cars`` the ρ-weighted section
    integrals, ``kk12`` = ∫E z / ∫E A and ``kk13`` = -∫E y / ∫E A (the
    stiffness centre, which the incompatible mode follows)."""
    L = float(length)
    c1, c2, c3, c4, c5, c6 = (float(c) for c in cars)
    if lumped:
        half = c1 * L / 2.0
        polar = L * (c4 + c5) / 2.0
        rotary = 2.0 * half * L * L / 105.0
        diag = [half, half, half, polar, rotary + 2.0 * c5 * L / 15.0, rotary + 2.0 * c4 * L / 15.0]
        return np.diag(np.tile(diag, 2))
    ms11 = c1
    ms44, ms55, ms66 = c4 + c5, c5, c4
    ms15, ms16 = c3, -c2
    ms24, ms34, ms56 = -ms15, -ms16, -c6
    m: dict[tuple[int, int], float] = {}
    m[1, 1] = m[7, 7] = ms11 * L / 3.0
    m[1, 7] = ms11 * L / 6.0
    m[1, 2] = -ms16 / 2.0
    m[1, 3] = ms15 / 2.0
    m[1, 5] = ms15 * L / 12.0
    m[1, 6] = ms16 * L / 12.0
    m[1, 8], m[1, 9], m[1, 11], m[1, 12] = -m[1, 2], -m[1, 3], -m[1, 5], -m[1, 6]
    m[2, 2] = m[8, 8] = 13.0 * L / 35.0 * ms11 + 6.0 / (5.0 * L) * ms66
    m[2, 3] = m[8, 9] = -6.0 / (5.0 * L) * ms56
    m[2, 4] = m[8, 10] = 7.0 * L / 20.0 * ms24
    m[2, 5] = m[2, 11] = ms56 / 10.0
    m[8, 11] = -ms56 / 10.0
    m[2, 6] = 11.0 * L * L / 210.0 * ms11 + ms66 / 10.0
    m[8, 12] = -m[2, 6]
    m[2, 7] = m[1, 2]
    m[2, 8] = 9.0 * L / 70.0 * ms11 - 6.0 / (5.0 * L) * ms66
    m[2, 9] = m[3, 8] = 6.0 / (5.0 * L) * ms56
    m[2, 10] = m[4, 8] = 3.0 * L / 20.0 * ms24
    m[2, 12] = -13.0 * L * L / 420.0 * ms11 + ms66 / 10.0
    m[3, 3] = m[9, 9] = 13.0 * L / 35.0 * ms11 + 6.0 / (5.0 * L) * ms55
    m[3, 4] = m[9, 10] = 7.0 * L / 20.0 * ms34
    m[3, 5] = -11.0 * L * L / 210.0 * ms11 - ms55 / 10.0
    m[9, 11] = -m[3, 5]
    m[3, 6] = m[3, 12] = -ms56 / 10.0
    m[9, 12] = m[6, 9] = ms56 / 10.0
    m[3, 7] = m[1, 3]
    m[3, 9] = 9.0 * L / 70.0 * ms11 - 6.0 / (5.0 * L) * ms55
    m[3, 10] = m[4, 9] = 3.0 * L / 20.0 * ms34
    m[3, 11] = 13.0 * L * L / 420.0 * ms11 - ms55 / 10.0
    m[4, 4] = m[10, 10] = L / 3.0 * ms44
    m[4, 5] = -L * L / 20.0 * ms34
    m[10, 11] = -m[4, 5]
    m[4, 6] = L * L / 20.0 * ms24
    m[10, 12] = -m[4, 6]
    m[4, 10] = L / 6.0 * ms44
    m[4, 11] = L * L / 30.0 * ms34
    m[5, 10] = -m[4, 11]
    m[4, 12] = -L * L / 30.0 * ms24
    m[6, 10] = -m[4, 12]
    m[5, 5] = m[11, 11] = L**3 / 105.0 * ms11 + 2.0 * L / 15.0 * ms55
    m[5, 6] = m[11, 12] = 2.0 * L / 15.0 * ms56
    m[5, 7] = m[1, 11]
    m[5, 8] = m[3, 6]
    m[5, 9] = -m[3, 11]
    m[5, 11] = -(L**3) / 140.0 * ms11 - L / 30.0 * ms55
    m[5, 12] = m[6, 11] = -L / 30.0 * ms56
    m[6, 6] = m[12, 12] = L**3 / 105.0 * ms11 + 2.0 * L / 15.0 * ms66
    m[6, 7] = m[1, 12]
    m[6, 8] = -m[2, 12]
    m[6, 12] = -(L**3) / 140.0 * ms11 - L / 30.0 * ms66
    m[7, 8], m[7, 9] = m[1, 8], m[1, 9]
    m[7, 11], m[7, 12] = -m[1, 11], -m[1, 12]
    out = _symmetric(m)
    _incompatible_mass(out, L, c2, c3, ms11, kk12, kk13)
    return out


def _incompatible_mass(m: np.ndarray, L: float, c2, c3, ms11, kk12, kk13) -> None:
    """Add the inertia of the incompatible axial mode centred on the
    stiffness centre (kk12, kk13) to the consistent mass (in place)."""
    z = 3.0 * ms11 / (10.0 * L)
    kk, kk2, kk3 = z * kk12 * kk13, z * kk12 * kk12, z * kk13 * kk13
    k3m3, k2m2 = -c2 * kk13, c3 * kk12
    k2m3, k3m2 = -c2 * kk12, c3 * kk13
    cross = k2m3 + k3m2
    a12, a13 = kk13 / 2.0 * ms11, kk12 / 2.0 * ms11
    b12, b13 = L / 4.0 * kk12 * ms11, L / 4.0 * kk13 * ms11
    vv = 4.0 * kk3 - 12.0 / (5.0 * L) * k3m3
    vw = -4.0 * kk + 6.0 / (5.0 * L) * cross
    ww = 4.0 * kk2 - 12.0 / (5.0 * L) * k2m2
    v_ry = 2.0 * L * kk - k3m2 / 10.0 - 3.0 / 5.0 * k2m3
    v_rz = 2.0 * L * kk3 - 7.0 / 10.0 * k3m3
    w_ry = -2.0 * L * kk2 + 7.0 / 10.0 * k2m2
    w_rz = -2.0 * L * kk + k2m3 / 10.0 + 3.0 / 5.0 * k3m2
    ryry = L * L * kk2 - L / 10.0 * k2m2
    ryrz = L * L * kk - L / 20.0 * cross
    rzrz = L * L * kk3 - L / 10.0 * k3m3
    added = {
        (1, 2): a12, (1, 3): -a13, (1, 5): b12, (1, 6): b13,
        (1, 8): -a12, (1, 9): a13, (1, 11): b12, (1, 12): b13,
        (2, 2): vv, (2, 3): vw, (2, 5): v_ry, (2, 6): v_rz, (2, 7): a12,
        (2, 8): -vv, (2, 9): -vw, (2, 11): v_ry, (2, 12): v_rz,
        (3, 3): ww, (3, 5): w_ry, (3, 6): w_rz, (3, 7): -a13,
        (3, 8): -vw, (3, 9): -ww, (3, 11): w_ry, (3, 12): w_rz,
        (5, 5): ryry, (5, 6): ryrz, (5, 7): b12, (5, 8): -v_ry, (5, 9): -w_ry,
        (5, 11): ryry, (5, 12): ryrz,
        (6, 6): rzrz, (6, 7): b13, (6, 8): -v_rz, (6, 9): -w_rz, (6, 11): ryrz, (6, 12): rzrz,
        (7, 8): -a12, (7, 9): a13, (7, 11): b12, (7, 12): b13,
        (8, 8): vv, (8, 9): vw, (8, 11): -v_ry, (8, 12): -v_rz,
        (9, 9): ww, (9, 11): -w_ry, (9, 12): -w_rz,
        (11, 11): ryry, (11, 12): ryrz, (12, 12): rzrz,
    }  # fmt: skip
    for (i, j), value in added.items():
        m[i - 1, j - 1] += value
        if i != j:
            m[j - 1, i - 1] += value
