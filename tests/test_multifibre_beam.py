"""POU_D_EM multifibre beams against closed forms: fibre geometry, a
cantilever frequency equal to the equivalent Euler-Bernoulli beam's, and the
axial-bending coupling of a section off the beam axis."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

from asterlite.fem import beam
from asterlite.fem.fibres import (
    FibreError,
    mass_local,
    point_fibres,
    section_fibres,
    section_integrals,
    stiffness_local,
)


def _rectangle_fibres(hy, hz, ny, nz, offset=(0.0, 0.0)):
    """QUAD4 fibres of a hy x hz rectangle centred at ``offset``."""
    ys = np.linspace(-hy / 2, hy / 2, ny + 1) + offset[0]
    zs = np.linspace(-hz / 2, hz / 2, nz + 1) + offset[1]
    coords = np.array([(y, z, 0.0) for z in zs for y in ys])
    cells = []
    for j in range(nz):
        for i in range(ny):
            a = j * (ny + 1) + i
            cells.append((a, a + 1, a + ny + 2, a + ny + 1))
    return section_fibres(coords, cells, axis=(0.0, 0.0), angle_deg=0.0)


def test_quad_and_triangle_fibres_have_their_area_and_centre():
    coords = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 1.0, 0.0], [0.0, 1.0, 0.0]])
    y, z, area = section_fibres(coords, [(0, 1, 2, 3), (0, 1, 2)], axis=(1.0, 0.0), angle_deg=0.0)
    np.testing.assert_allclose(area, [2.0, 1.0])
    np.testing.assert_allclose(y, [0.0, (0 + 2 + 2) / 3 - 1.0])
    np.testing.assert_allclose(z, [0.5, 1.0 / 3.0])


def test_point_fibres_diameter_axis_and_angle():
    y, z, area = point_fibres([1.0, 0.0, 0.02], "DIAMETRE", axis=(0.0, 0.0), angle_deg=90.0)
    np.testing.assert_allclose(area, [np.pi * 0.02**2 / 4])
    np.testing.assert_allclose([y[0], z[0]], [0.0, 1.0], atol=1e-15)
    with pytest.raises(FibreError):
        point_fibres([1.0, 2.0], "SURFACE", axis=(0.0, 0.0), angle_deg=0.0)


def test_rectangle_fibres_integrate_area_and_inertias():
    hy, hz = 0.2, 0.5
    integrals = section_integrals(*_rectangle_fibres(hy, hz, 40, 100))
    area = hy * hz
    assert integrals[0] == pytest.approx(area, rel=1e-12)
    assert abs(integrals[1]) < 1e-15 and abs(integrals[2]) < 1e-15
    # midpoint rule: I = b h^3 / 12 (1 - 1/n^2)
    assert integrals[4] == pytest.approx(hy * hz**3 / 12 * (1 - 1 / 100**2), rel=1e-10)
    assert integrals[3] == pytest.approx(hz * hy**3 / 12 * (1 - 1 / 40**2), rel=1e-10)


def test_centred_fibre_stiffness_is_the_euler_bernoulli_matrix():
    young, nu, length = 2.0e11, 0.3, 0.7
    integrals = section_integrals(*_rectangle_fibres(0.1, 0.3, 10, 30))
    area, iz, iy = integrals[0], integrals[3], integrals[4]
    jx = 1.0e-4
    shear = young / (2 * (1 + nu))
    expected = beam.beam_stiffness_local(length, young, shear, area, iy, iz, jx)[0]
    got = stiffness_local(length, young * integrals, shear * jx)
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-6 * np.abs(expected).max())


def _cantilever_frequencies(n_elements, length, young_cars, rho_cars, gj, lumped=False):
    size = 6 * (n_elements + 1)
    k = np.zeros((size, size))
    m = np.zeros((size, size))
    h = length / n_elements
    ke = stiffness_local(h, young_cars, gj)
    me = mass_local(
        h, rho_cars, young_cars[2] / young_cars[0], -young_cars[1] / young_cars[0], lumped
    )
    for e in range(n_elements):
        rows = slice(6 * e, 6 * e + 12)
        k[rows, rows] += ke
        m[rows, rows] += me
    free = slice(6, size)  # node 0 clamped
    eig = scipy.linalg.eigh(k[free, free], m[free, free], eigvals_only=True)
    return np.sqrt(np.abs(eig)) / (2 * np.pi)


def test_cantilever_frequency_of_a_fibre_section_is_the_beam_closed_form():
    young, rho, length = 2.0e11, 7800.0, 4.0
    hy, hz = 0.05, 0.08
    fibres = _rectangle_fibres(hy, hz, 20, 32)
    integrals = section_integrals(*fibres)
    area, iz = integrals[0], integrals[3]
    freqs = _cantilever_frequencies(20, length, young * integrals, rho * integrals, gj=1.0e6)
    # first bending mode in xOy (the weaker plane, EI_z): (1.8751)^2 / (2 pi L^2) sqrt(EI / rho A)
    beta1 = 1.8751040687119611
    closed = beta1**2 / (2 * np.pi * length**2) * np.sqrt(young * iz / (rho * area))
    assert freqs[0] == pytest.approx(closed, rel=2e-4)


def test_offset_section_tip_axial_load_gives_the_exact_generalised_strains():
    """A section moved by d along z: a tip axial force N on the axis gives the
    constant strains of [N, 0] = [[EA, ESz], [ESz, EIy]] [eps, kappa]; the
    incompatible mode makes the element exact for them."""
    young, length, n_elements, force = 3.0e10, 2.0, 4, 1.0e5
    fibres = _rectangle_fibres(0.2, 0.4, 8, 16, offset=(0.0, 0.1))
    cars = young * section_integrals(*fibres)
    ea, esz, eiy = cars[0], cars[2], cars[4]
    size = 6 * (n_elements + 1)
    k = np.zeros((size, size))
    ke = stiffness_local(length / n_elements, cars, gj=1.0e8)
    for e in range(n_elements):
        k[6 * e : 6 * e + 12, 6 * e : 6 * e + 12] += ke
    rhs = np.zeros(size)
    rhs[-6] = force
    u = np.zeros(size)
    u[6:] = np.linalg.solve(k[6:, 6:], rhs[6:])
    det = ea * eiy - esz**2
    eps = force * eiy / det
    assert u[-6] == pytest.approx(eps * length, rel=1e-10)
    # N = 0 at the fibres' centroid without the coupling would be eps = N / EA
    assert abs(u[-6] - force * length / ea) > 1e-3 * abs(u[-6])


def test_lumped_mass_keeps_the_total_mass():
    cars = 7800.0 * section_integrals(*_rectangle_fibres(0.1, 0.2, 4, 8))
    m = mass_local(1.5, cars, 0.0, 0.0, lumped=True)
    assert np.trace(m[np.ix_([0, 6], [0, 6])]) == pytest.approx(cars[0] * 1.5)
    consistent = mass_local(1.5, cars, 0.0, 0.0)
    ones = np.zeros(12)
    ones[[1, 7]] = 1.0  # rigid translation along y
    assert ones @ consistent @ ones == pytest.approx(cars[0] * 1.5, rel=1e-12)


def test_warping_multifibre_element_of_one_material_is_pou_d_tg():
    """POU_D_TGM with one material: POU_D_TG's matrices for the fibres' A, IY, IZ."""
    from asterlite.fem.multifibre_elements import _Section, _warping_local

    young, nu, rho, length = 2.1e11, 0.3, 7850.0, 0.8
    integrals = section_integrals(*_rectangle_fibres(0.06, 0.1, 6, 10))
    poutre = {"JX": 3.0e-6, "JG": 1.0e-9, "AY": 1.2, "AZ": 1.2, "EY": 0.0, "EZ": 0.0}
    shear = young / (2 * (1 + nu))
    section = _Section(young * integrals, rho * integrals, integrals, shear, 0.0, 0.0, poutre)
    geometric = {"A": integrals[0], "IY": integrals[4], "IZ": integrals[3], **poutre}
    for matrix in ("K", "M"):
        got = _warping_local(section, length, matrix, False, "test")
        expected = beam.local_matrices("POU_D_TG", matrix, length, geometric, young, nu, rho)[0]
        np.testing.assert_allclose(got, expected, rtol=1e-10, atol=1e-12 * np.abs(expected).max())
