"""Gyroscopic matrices of rotors: straight beams and rigid disks.

A rotor spins at ``Ω(t)`` about the local x axis of its elements (beam axis,
node 1 to node 2; for a ``DIS_TR`` disk, the local x of its ORIENTATION,
global X without one), positive in the trigonometric sense about x. The
equation of motion of the rotating structure reads

    M q'' + (C + Ω G) q' + (K + Ω' Kg) q = F

with ``G`` the gyroscopic damping matrix per unit spin (option
``MECA_GYRO``, antisymmetric) and ``Kg`` the gyroscopic stiffness per unit
spin acceleration (option ``RIGI_GYRO``, one off-diagonal block).

Both come from the spin part of the kinetic energy of the cross sections
(polar inertia ``rho Ip``, ``Ip = IY + IZ``) or of the disk (``Ixx``):
``T_gyro = Ω q'^T S q`` with ``S = rho Ip ∫ N_ry^T N_rz dx`` built on the
section-rotation shape functions, and ``G = S - S^T``. For a rigid disk
``S`` has the single term ``S[DRY, DRZ] = Ixx``, so ``G[DRY, DRZ] = Ixx``:
``Ixx θy'' + Ω Ixx θz' = My`` (checked against the unbalance responses of
code_aster's sdll126b and sdll144a).

``Kg`` is ``S^T`` as code_aster assembles RIGI_GYRO (its element routines
write ``S`` into a row-major non-symmetric storage); a Lagrangian of the
form above would give ``S`` instead. The difference is a term
``Ω' (S - S^T)`` of opposite sign; ``S^T`` reproduces code_aster's
transient results (sdll144a, to 2e-5). code_aster's beam routine also
misplaces some RIGI_GYRO terms (an indexing slip that moves the rows of
DRZ1, DY2, DRZ2 to DRX1, DRY1, DX2); that slip is not reproduced here (its
effect is negligible beside the disks' in the corpus decks).

code_aster conventions followed here:

- the rotation shape functions are those of the Timoshenko beam with one
  shear parameter for both planes, ``phi = 12 Ip (1 + NU) / (A L^2) * 2 /
  (AY + AZ)`` (``phi = 0`` for POU_D_E), as code_aster computes it for these
  options (note: the inverse of the mean shear coefficient, not the one the
  stiffness uses);
- a disk's ``Ixx`` is the (DRX, DRX) term of its ``M_TR_*_N`` mass as given
  (with the eccentricity term ``m (ey² + ez²)`` for ``M_TR_D_N``), turned to
  the global frame with the cell's orientation whatever ``REPERE``;
- the beams (``POU_D_E``, ``POU_D_T``, ``POU_D_EM``, ``POU_D_TG``,
  ``POU_D_TGM``: :mod:`asterlite.fem.options`) and ``DIS_TR`` on ``POI1``
  contribute; bars, ``DIS_T`` and link discretes have no gyroscopic term,
  solids' (te0159) is refused.
"""

from __future__ import annotations

import numpy as np

# local DOF indices of the 12-DOF beam (node 1 then node 2: DX DY DZ DRX DRY DRZ)
_V1, _W1, _RY1, _RZ1 = 1, 2, 4, 5
_V2, _W2, _RY2, _RZ2 = 7, 8, 10, 11

_GAUSS, _WEIGHTS = np.polynomial.legendre.leggauss(3)  # exact for degree 5


def gyro_shear_parameter(length, area, iy, iz, poisson, ay=0.0, az=0.0) -> np.ndarray:
    """code_aster's shear parameter of the gyroscopic beam matrices:
    ``12 Ip (1 + NU) alfinv / (A L^2)`` with ``alfinv = 2 / (AY + AZ)``
    (0 when AY + AZ = 0, the Euler-Bernoulli case)."""
    length, area, iy, iz, poisson, ay, az = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (length, area, iy, iz, poisson, ay, az))
    )
    total = ay + az
    alfinv = np.divide(2.0, total, out=np.zeros_like(total), where=total > 0.0)
    return 12.0 * (iy + iz) * (1.0 + poisson) * alfinv / (area * length * length)


def rotation_shapes(xi, length, phi) -> np.ndarray:
    """(n_points, n_elements, 4) section-rotation shape functions of a
    Timoshenko beam in one bending plane: the slope-like rotation
    ``beta`` from (t1, beta1, t2, beta2) where ``beta = dt/dx`` in the
    Euler-Bernoulli limit (``phi = 0``, derivative of the Hermite cubics)."""
    s = np.asarray(xi, dtype=float)[:, None]
    L = np.atleast_1d(np.asarray(length, dtype=float))[None, :]
    p = np.atleast_1d(np.asarray(phi, dtype=float))[None, :]
    den = 1.0 + p
    n = np.stack(
        [
            6.0 * (s * s - s) / L,
            3.0 * s * s - 4.0 * s + 1.0 + p * (1.0 - s),
            -6.0 * (s * s - s) / L,
            3.0 * s * s - 2.0 * s + p * s,
        ],
        axis=-1,
    )
    return n / den[..., None]


def beam_gyro_coupling_local(length, density, area, iy, iz, poisson, ay=0.0, az=0.0) -> np.ndarray:
    """(n, 12, 12) ``S = rho Ip ∫ N_ry^T N_rz dx`` of straight beams in their
    local frame (see the module docstring); ``G = S - S^T``, ``Kg = S^T``."""
    L, rho, A, Iy, Iz, nu, ay, az = np.broadcast_arrays(
        *(
            np.atleast_1d(np.asarray(v, dtype=float))
            for v in (length, density, area, iy, iz, poisson, ay, az)
        )
    )
    phi = gyro_shear_parameter(L, A, Iy, Iz, nu, ay, az)
    xi, wts = (_GAUSS + 1.0) / 2.0, _WEIGHTS / 2.0
    beta = rotation_shapes(xi, L, phi)  # (p, n, 4)
    n = len(L)
    # rz = dv/dx on (v1, rz1, v2, rz2); ry = -dw/dx, i.e. beta(w1, -ry1, w2, -ry2) negated
    n_rz = np.zeros((len(xi), n, 12))
    n_rz[..., [_V1, _RZ1, _V2, _RZ2]] = beta
    n_ry = np.zeros((len(xi), n, 12))
    n_ry[..., [_W1, _RY1, _W2, _RY2]] = beta * np.array([-1.0, 1.0, -1.0, 1.0])
    integral = np.einsum("p,pni,pnj->nij", wts, n_ry, n_rz) * L[:, None, None]
    return (rho * (Iy + Iz))[:, None, None] * integral


def beam_gyro_damping_local(*args, **kwargs) -> np.ndarray:
    """(n, 12, 12) antisymmetric gyroscopic damping per unit spin (MECA_GYRO)."""
    s = beam_gyro_coupling_local(*args, **kwargs)
    return s - np.swapaxes(s, 1, 2)


def beam_gyro_stiffness_local(*args, **kwargs) -> np.ndarray:
    """(n, 12, 12) gyroscopic stiffness per unit spin acceleration (RIGI_GYRO),
    ``S^T`` as code_aster assembles it."""
    return np.swapaxes(beam_gyro_coupling_local(*args, **kwargs), 1, 2)


def disk_gyro_coupling_local(polar_inertia) -> np.ndarray:
    """(n, 6, 6) ``S`` of rigid disks on one node: ``S[DRY, DRZ] = Ixx``."""
    ixx = np.atleast_1d(np.asarray(polar_inertia, dtype=float))
    s = np.zeros((len(ixx), 6, 6))
    s[:, 4, 5] = ixx
    return s


def disk_gyro_damping_local(polar_inertia) -> np.ndarray:
    """``S - S^T``: ``G[DRY, DRZ] = Ixx = -G[DRZ, DRY]``."""
    s = disk_gyro_coupling_local(polar_inertia)
    return s - np.swapaxes(s, 1, 2)


def disk_gyro_stiffness_local(polar_inertia) -> np.ndarray:
    """``S^T``: the single term ``Kg[DRZ, DRY] = Ixx`` (code_aster's RIGI_GYRO)."""
    return np.swapaxes(disk_gyro_coupling_local(polar_inertia), 1, 2)
