"""MODI_REPERE: the stresses of a pressurised thick cylinder (Lame's solution)
turned from the global frame into code_aster's cylindrical one (e_r, e_z,
e_theta: SIXX = srr, SIYY = szz, SIZZ = stt), and nodal vectors turned by
nautical angles."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands.modi_repere import cylindrical_axes

from asterlite.concepts.assembly import ElementField, NodalComponentField
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import UnsupportedError
from tests.solid_meshes import box_mesh
from tests.test_fem_structures import beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

A, B, SZZ = 2.0, 5.0, 0.3  # srr = A - B / r^2, stt = A + B / r^2
COMPONENTS = ("SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ")


def _lame(points):
    """Global components of the cylinder's stresses at points (n, 3)."""
    x, y = points[:, 0], points[:, 1]
    r2 = x * x + y * y
    srr, stt = A - B / r2, A + B / r2
    c, s = x / np.sqrt(r2), y / np.sqrt(r2)
    zeros = np.zeros_like(x)
    sxx = srr * c * c + stt * s * s
    syy = srr * s * s + stt * c * c
    sxy = (srr - stt) * s * c
    return np.stack([sxx, syy, zeros + SZZ, sxy, zeros, zeros], axis=1), srr, stt


def test_cylindrical_axes():
    axes = cylindrical_axes(np.array([[3.0, 0.0, 1.0], [0.0, 0.0, 4.0]]), (0, 0, 0), (0, 0, 2.0))
    np.testing.assert_allclose(axes[0], [[1, 0, 0], [0, 0, 1], [0, 1, 0]], atol=1e-15)
    np.testing.assert_allclose(axes[1], [[1, 0, 0], [0, 0, 1], [0, 1, 0]], atol=1e-15)


def _result():
    mesh = box_mesh("HEXA8", n=(2, 2, 1), size=(1.0, 1.0, 1.0))
    mesh.coords[:, :2] += 1.0  # away from the axis
    model = run(FakeSession(), "AFFE_MODELE", MAILLAGE=mesh,
                AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "3D"})  # fmt: skip
    numbering = run(FakeSession(), "NUME_DDL", MODELE=model)
    result = DynaTrans(numbering, np.array([0.0]), np.array([1]), {})
    cells = np.arange(mesh.n_cells)
    elno = np.zeros((1, len(cells), 8, 6))
    for k, cell in enumerate(cells):
        elno[0, k] = _lame(mesh.coords[list(mesh.cell_nodes[cell])])[0]
    result.element_fields = {"SIGM_ELNO": ElementField("SIGM_ELNO", cells, COMPONENTS, elno)}
    nodes = np.arange(mesh.n_nodes)
    result.node_fields = {
        "SIGM_NOEU": NodalComponentField(
            "SIGM_NOEU", nodes, COMPONENTS, _lame(mesh.coords)[0][None]
        )
    }
    return mesh, result


@pytest.mark.parametrize("name", ["SIGM_ELNO", "SIGM_NOEU"])
def test_thick_cylinder_stresses_in_the_cylindrical_frame(name):
    mesh, result = _result()
    out = run(
        FakeSession(),
        "MODI_REPERE",
        RESULTAT=result,
        REPERE="CYLINDRIQUE",
        MODI_CHAM={"TYPE_CHAM": "TENS_3D", "NOM_CHAM": name},
        AFFE={"TOUT": "OUI", "ORIGINE": (0.0, 0.0, 0.0), "AXE_Z": (0.0, 0.0, 1.0)},
    )
    if name == "SIGM_ELNO":
        field = out.element_fields[name]
        points = np.array([mesh.coords[list(mesh.cell_nodes[c])] for c in field.cells])
        values = field.values[0].reshape(-1, 6)
        points = points.reshape(-1, 3)
    else:
        field = out.node_fields[name]
        values, points = field.values[0], mesh.coords[field.nodes]
    _, srr, stt = _lame(points)
    np.testing.assert_allclose(values[:, 0], srr, rtol=1e-13)
    np.testing.assert_allclose(values[:, 1], SZZ, rtol=1e-13)
    np.testing.assert_allclose(values[:, 2], stt, rtol=1e-13)
    np.testing.assert_allclose(values[:, 3:], 0.0, atol=1e-13)
    # the input result is unchanged
    source = result.element_fields if name == "SIGM_ELNO" else result.node_fields
    assert source[name].values[0].reshape(-1, 6)[0, 2] == pytest.approx(SZZ)


def test_nodal_vectors_turned_by_nautical_angles_on_a_group():
    session = FakeSession()
    model, _, _ = beam_model(session, line_mesh(2, 1.0))
    numbering = run(session, "NUME_DDL", MODELE=model)
    depl = np.zeros((1, numbering.n_dofs))
    for node in range(3):
        for comp, value in zip(("DX", "DY", "DZ"), (1.0, 2.0, 3.0), strict=True):
            depl[0, numbering.dof_indices([node], comp)[0]] = value
    result = DynaTrans(numbering, np.array([0.0]), np.array([1]), {"DEPL": depl})
    out = run(
        session,
        "MODI_REPERE",
        RESULTAT=result,
        REPERE="UTILISATEUR",
        MODI_CHAM={"TYPE_CHAM": "VECT_3D", "NOM_CHAM": "DEPL"},
        AFFE={"GROUP_NO": "B", "ANGL_NAUT": (90.0, 0.0, 0.0)},
    )
    turned = {
        c: out.fields["DEPL"][0, numbering.dof_indices([2], c)[0]] for c in ("DX", "DY", "DZ")
    }
    assert turned == pytest.approx({"DX": 2.0, "DY": -1.0, "DZ": 3.0})  # x' = y, y' = -x
    kept = out.fields["DEPL"][0, numbering.dof_indices([0], "DX")[0]]
    assert kept == 1.0 and result.fields["DEPL"][0, numbering.dof_indices([2], "DX")[0]] == 1.0


@pytest.mark.parametrize("repere", ["COQUE", "COQUE_UTIL_CYL"])
def test_other_frames_are_refused(repere):
    """A shell frame of a solid's field; the cylindrical frame of shells."""
    _, result = _result()
    with pytest.raises(UnsupportedError, match="COQUE"):
        run(
            FakeSession(),
            "MODI_REPERE",
            RESULTAT=result,
            REPERE=repere,
            MODI_CHAM={"TYPE_CHAM": "TENS_3D", "NOM_CHAM": "SIGM_ELNO"},
            AFFE={"TOUT": "OUI", "ANGL_REP": (0.0, 0.0)}
            if repere == "COQUE"
            else {"TOUT": "OUI", "ORIGINE": (0.0, 0.0, 0.0), "AXE_Z": (0.0, 0.0, 1.0)},
        )


def test_rotations_turned_with_translations_on_the_chosen_orders():
    """VECT_3D of a field with rotations turns DRX DRY DRZ as DX DY DZ
    (selectCompN/chrpno); NUME_ORDRE keeps only that order (rsutnu). With
    x' = (1, 1, 1)/√3 and y' = (-1, 1, 0)/√2, z' = (-1, -1, 2)/√6."""
    session = FakeSession()
    model, _, _ = beam_model(session, line_mesh(2, 1.0))
    numbering = run(session, "NUME_DDL", MODELE=model)
    acce = np.zeros((2, numbering.n_dofs))
    for order, scale in enumerate((1.0, 10.0)):
        acce[order, numbering.dof_indices([1], "DZ")[0]] = 2.0 * scale
        acce[order, numbering.dof_indices([1], "DRZ")[0]] = scale
    result = DynaTrans(numbering, np.array([0.0, 0.1]), np.array([1, 2]), {"ACCE": acce})
    out = run(
        session,
        "MODI_REPERE",
        RESULTAT=result,
        NUME_ORDRE=2,
        REPERE="UTILISATEUR",
        MODI_CHAM={"TYPE_CHAM": "VECT_3D", "NOM_CHAM": "ACCE"},
        AFFE={"TOUT": "OUI", "VECT_X": (1.0, 1.0, 1.0), "VECT_Y": (-1.0, 1.0, 0.0)},
    )
    assert out.order.tolist() == [2] and out.times.tolist() == [0.1]
    assert out.fields["ACCE"].shape == (1, numbering.n_dofs)

    def at(components):
        return [out.fields["ACCE"][0, numbering.dof_indices([1], c)[0]] for c in components]

    np.testing.assert_allclose(
        at(("DRX", "DRY", "DRZ")), [10 / np.sqrt(3), 0.0, 20 / np.sqrt(6)], atol=1e-12
    )
    np.testing.assert_allclose(
        at(("DX", "DY", "DZ")), [20 / np.sqrt(3), 0.0, 40 / np.sqrt(6)], atol=1e-12
    )
    assert result.fields["ACCE"].shape == (2, numbering.n_dofs)  # the input is untouched
