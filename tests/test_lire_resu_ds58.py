"""LIRE_RESU FORMAT='IDEAS_DS58' (measured functions at nodes and directions)
and PROJ_MESU_MODAL on sensors in those directions."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import DofNumbering, Model
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.modes import ModeResult
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.errors import CommandError
from asterlite.io.ideas_ds58 import read_datasets_58
from tests.test_fem_support import FakeSession, validated_run
from tests.test_proj_champ_lire_resu import line


def _header(node: str, direction: int, nature: int, count: int, even: bool, kind: int):
    spacing = "  0.00000E+00  1.00000E-01  0.00000E+00" if even else ""
    return [
        "    -1",
        "    58",
        *(["NONE"] * 5),
        f"    1         0    0         0 {node:<18} 0 {direction:>3} NONE               0   0",
        f"{nature:>10}{count:>10}{int(even):>10}{spacing}",
        "        17    0    0    0 NONE                 s",
        f"{kind:>10}    0    0    0 NONE                 m",
        "         0    0    0    0 NONE                 NONE",
        "         0    0    0    0 NONE                 NONE",
    ]


def _single(values) -> list[str]:
    """6E13.5 lines."""
    return ["".join(f"{v:13.5E}" for v in values[k : k + 6]) for k in range(0, len(values), 6)]


def _double(values) -> list[str]:
    """4E20.12 lines."""
    return ["".join(f"{v:20.12E}" for v in values[k : k + 4]) for k in range(0, len(values), 4)]


SIGNAL = np.array([0.0, 1.0, -2.0, 3.5, 0.25, -1.0, 2.0, 4.0])


@pytest.fixture
def transient_file(tmp_path):
    lines = []
    lines += _header("N1", 1, 2, 8, True, 8) + _single(SIGNAL) + ["    -1"]
    lines += _header("N2", -2, 2, 8, True, 8) + _single(2 * SIGNAL) + ["    -1"]
    lines += _header("N2", 3, 2, 8, True, 2) + _single(SIGNAL) + ["    -1"]  # stress SIZZ
    path = tmp_path / "mesures.58"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_reader_single_and_double_precision(tmp_path, transient_file):
    functions = read_datasets_58(transient_file)
    assert [(f.node_name, f.direction, f.ordinate_kind) for f in functions] == [
        ("N1", 1, 8),
        ("N2", -2, 8),
        ("N2", 3, 2),
    ]
    np.testing.assert_allclose(functions[0].abscissas, 0.1 * np.arange(8))
    np.testing.assert_allclose(functions[1].values, 2 * SIGNAL)
    # complex values in double precision at uneven abscissas: (x, re, im) triplets
    x = np.array([1.0, 2.5, 7.0])
    data = np.column_stack([x, [1.0, 2.0, 3.0], [-1.0, 0.5, 0.0]]).ravel()
    path = tmp_path / "harm.58"
    path.write_text("\n".join(_header("N1", 2, 6, 3, False, 8) + _double(data) + ["    -1"]))
    (function,) = read_datasets_58(path)
    np.testing.assert_allclose(function.abscissas, x)
    np.testing.assert_allclose(function.values, [1 - 1j, 2 + 0.5j, 3.0])


def test_transient_with_directions_signs_and_orientation(transient_file):
    mesh = line([0.0, 1.0])
    result = validated_run(
        FakeSession({33: transient_file}),
        "LIRE_RESU",
        FORMAT="IDEAS_DS58",
        UNITE=33,
        MAILLAGE=mesh,
        TYPE_RESU="DYNA_TRANS",
        NOM_CHAM=("DEPL", "SIEF_NOEU"),
        REDEFI_ORIENT={"CODE_DIR": 2, "DIRECTION": (0.0, 1.0, 1.0), "NOEUD": "N2"},
        NUME_ORDRE=(2, 4),
    )
    assert isinstance(result, DynaTrans)
    np.testing.assert_allclose(result.times, [0.1, 0.3])
    assert list(result.order) == [2, 4]
    index, depl = result.numbering.index, result.fields["DEPL"]
    np.testing.assert_allclose(depl[:, index[(0, "D1")]], SIGNAL[[1, 3]])
    np.testing.assert_allclose(depl[:, index[(0, "D1X")]], 1.0)  # the X axis
    np.testing.assert_allclose(depl[:, index[(1, "D2")]], -2 * SIGNAL[[1, 3]])  # direction -2
    orientation = [depl[0, index[(1, f"D2{a}")]] for a in "XYZ"]
    np.testing.assert_allclose(orientation, [0.0, 1.0, 1.0])  # REDEFI_ORIENT
    np.testing.assert_allclose(result.fields["SIEF_NOEU"][:, index[(1, "SIZZ")]], SIGNAL[[1, 3]])


def test_real_data_cannot_make_a_harmonic_result(transient_file):
    with pytest.raises(CommandError, match="real data cannot make a DYNA_HARMO"):
        validated_run(
            FakeSession({33: transient_file}),
            "LIRE_RESU",
            FORMAT="IDEAS_DS58",
            UNITE=33,
            MAILLAGE=line([0.0, 1.0]),
            TYPE_RESU="DYNA_HARMO",
            NOM_CHAM="DEPL",
            TOUT_ORDRE="OUI",
        )


def _spring_basis(mesh) -> ModeResult:
    dofs = [(n, c) for n in range(mesh.n_nodes) for c in ("DX", "DY", "DZ")]
    x = mesh.coords[:, 0]
    shapes = np.array(
        [
            [xv if c == "DX" else 0.0, xv**2 if c == "DY" else 0.0]
            for (n, c), xv in zip(dofs, x[[n for n, _ in dofs]], strict=True)
        ]
    )
    return ModeResult(
        numbering=DofNumbering(mesh=mesh, dofs=dofs),
        shapes=shapes,
        frequencies=np.array([1.0, 2.0]),
        generalized_mass=np.ones(2),
        generalized_stiffness=np.ones(2),
    )


def test_discrete_model_pairs_nearest_nodes_and_sensor_directions():
    """A discrete (DIS_T) calculation model: each sensor takes the value of the
    nearest calculation node (no interpolation), along its direction."""
    calc = line([0.0, 1.0, 2.0, 3.0])
    sensors = line([1.1, 2.8])  # nearest: calculation nodes at 1.0 and 3.0
    basis = _spring_basis(calc)
    times = np.linspace(0.0, 1.0, 5)
    eta = np.column_stack([np.sin(times), times])
    direction = np.array([1.0, 1.0, 0.0])  # D1 of the second sensor
    dofs = [(0, "D1"), (0, "D1X"), (0, "D1Y"), (0, "D1Z"), (1, "D1")]
    dofs += [(1, "D1X"), (1, "D1Y"), (1, "D1Z")]
    numbering = DofNumbering(mesh=sensors, dofs=dofs)
    values = np.zeros((times.size, len(dofs)))
    values[:, 0] = eta[:, 0] * 1.0  # D1 along X at calc node 1.0: mode 1 is x
    values[:, 1] = 1.0
    seen = (eta[:, 0] * 3.0 + eta[:, 1] * 9.0) / np.sqrt(2.0)  # (x, x², 0)·(1, 1, 0)/√2 at x = 3
    values[:, 4] = seen
    values[:, 5:8] = direction
    measured = DynaTrans(
        numbering=numbering, times=times, order=np.arange(1, 6), fields={"DEPL": values}
    )
    result = validated_run(
        FakeSession(),
        "PROJ_MESU_MODAL",
        MODELE_CALCUL={"MODELE": _discrete(calc), "BASE": basis},
        MODELE_MESURE={"MODELE": _discrete(sensors), "MESURE": measured},
    )
    assert isinstance(result, TranGene)
    np.testing.assert_allclose(result.depl, eta, atol=1e-12)


def _discrete(mesh) -> Model:
    return Model(mesh=mesh, cell_modelisation={c: "DIS_T" for c in range(mesh.n_cells)})


def test_harmonic_ds58_file(tmp_path):
    data = np.array([1.0, -1.0, 2.0, 0.5, 3.0, 0.0])  # three complex values, even abscissas
    path = tmp_path / "harm.58"
    path.write_text("\n".join(_header("N2", 1, 5, 3, True, 8) + _single(data) + ["    -1"]))
    result = validated_run(
        FakeSession({33: path}),
        "LIRE_RESU",
        FORMAT="IDEAS_DS58",
        UNITE=33,
        MAILLAGE=line([0.0, 1.0]),
        TYPE_RESU="DYNA_HARMO",
        NOM_CHAM="DEPL",
        TOUT_ORDRE="OUI",
    )
    assert isinstance(result, DynaHarmo)
    np.testing.assert_allclose(result.frequencies, [0.0, 0.1, 0.2])
    np.testing.assert_allclose(
        result.fields["DEPL"][:, result.numbering.index[(1, "D1")]], [1 - 1j, 2 + 0.5j, 3.0]
    )


def test_gauges_compared_with_the_basis_nodal_stresses():
    """Measured SIEF_NOEU (SIXX at one node, SIYY at another) explained by the
    basis' SIGM_NOEU at the paired calculation nodes."""
    from asterlite.concepts.assembly import NodalComponentField

    calc = line([0.0, 1.0, 2.0])
    sensors = line([0.1, 1.9])  # nearest: calculation nodes 0 and 2
    basis = _spring_basis(calc)
    stresses = np.zeros((2, 3, 2))  # (modes, nodes, [SIXX, SIYY])
    stresses[0] = [[1.0, 0.0], [0.0, 0.0], [0.5, 2.0]]
    stresses[1] = [[3.0, 0.0], [0.0, 0.0], [0.0, -1.0]]
    basis.node_fields = {
        "SIGM_NOEU": NodalComponentField("SIGM_NOEU", np.arange(3), ("SIXX", "SIYY"), stresses)
    }
    times = np.linspace(0.0, 1.0, 4)
    eta = np.column_stack([times, 1.0 - times**2])
    dofs = [(0, "SIXX"), (1, "SIXX"), (1, "SIYY")]
    seen = np.array([[1.0, 3.0], [0.5, 0.0], [2.0, -1.0]])
    measured = DynaTrans(
        numbering=DofNumbering(mesh=sensors, dofs=dofs),
        times=times,
        order=np.arange(1, 5),
        fields={"SIEF_NOEU": eta @ seen.T},
    )
    result = validated_run(
        FakeSession(),
        "PROJ_MESU_MODAL",
        MODELE_CALCUL={"MODELE": _discrete(calc), "BASE": basis},
        MODELE_MESURE={"MODELE": _discrete(sensors), "MESURE": measured, "NOM_CHAM": "SIEF_NOEU"},
    )
    np.testing.assert_allclose(result.depl, eta, atol=1e-12)
    del basis.node_fields
    with pytest.raises(CommandError, match="no SIGM_NOEU field"):
        validated_run(
            FakeSession(),
            "PROJ_MESU_MODAL",
            MODELE_CALCUL={"MODELE": _discrete(calc), "BASE": basis},
            MODELE_MESURE={
                "MODELE": _discrete(sensors),
                "MESURE": measured,
                "NOM_CHAM": "SIEF_NOEU",
            },
        )
