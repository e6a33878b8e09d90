"""MECA_GYRO of the multifibre and warping beams (code_aster's te0259): a
POU_D_EM section's polar inertia comes from its fibres' rho-weighted
integrals, and POU_D_TG/POU_D_TGM carry the 12-DOF matrix with nothing on
GRX; solids, whose gyroscopic matrix is not computed, are refused."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.fem import gyro
from asterlite.fem.elements import ElementError
from asterlite.fem.options import gyro_blocks
from tests.test_fem_structures import beam_model, line_mesh
from tests.test_fem_support import FakeSession
from tests.test_multifibre_commands import A0, HALF, LENGTH, N_EL, _cantilever


def test_multifibre_beam_takes_the_fibres_polar_inertia():
    result, inertia = _cantilever(FakeSession())
    (block,) = gyro_blocks(result.model, result.characteristics, "MECA_GYRO", result.materials)
    # the beam lies along X: local and global frames agree
    expected = gyro.beam_gyro_damping_local(LENGTH / N_EL, 7800.0, 4 * A0, inertia, inertia, 0.3)
    assert inertia == pytest.approx(4 * A0 * HALF**2)
    np.testing.assert_allclose(block.matrices, np.broadcast_to(expected, block.matrices.shape))
    assert np.abs(block.matrices).max() > 0.0


def test_warping_beam_has_the_timoshenko_matrix_and_nothing_on_grx():
    section = ("CERCLE", ("R",), (0.05,))
    plain = _blocks(FakeSession(), "POU_D_T", section)
    warping = _blocks(FakeSession(), "POU_D_TG", section)
    keep = [0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12]
    np.testing.assert_array_equal(warping.matrices[:, keep][:, :, keep], plain.matrices)
    assert not warping.matrices[:, [6, 13]].any() and not warping.matrices[:, :, [6, 13]].any()
    assert warping.components[-1] == "GRX"


def _blocks(session, modelisation, section):
    model, field, cara = beam_model(session, line_mesh(3, 1.5), modelisation, section)
    (block,) = gyro_blocks(model, cara, "MECA_GYRO", field)
    return block


def test_solids_are_refused_by_name():
    class Model:
        cell_modelisation = {0: "3D"}

    with pytest.raises(ElementError, match="MECA_GYRO of 3D elements"):
        gyro_blocks(Model(), None, "MECA_GYRO")
