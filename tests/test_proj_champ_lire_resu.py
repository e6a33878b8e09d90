"""PROJ_CHAMP (collocation of nodal fields between meshes) and LIRE_RESU
(FORMAT='MED': modes and transients read back from a MED file)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from asterlite.concepts.assembly import AssembledMatrix, DofNumbering, NodalField
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import CommandError, UnsupportedError
from asterlite.io.med_writer import NodalSeries, write_med
from tests.test_fem_support import FakeSession, chain_mesh, run

WIDER = Path(__file__).resolve().parent.parent.parent / "shared" / "aster-corpus-wider"
COMPONENTS = ("DX", "DY")


def line(xs, seg3: bool = False) -> Mesh:
    """Nodes along x; SEG2 cells between neighbours (or SEG3 over triples)."""
    coords = np.zeros((len(xs), 3))
    coords[:, 0] = xs
    if seg3:
        cells = [(k, k + 2, k + 1) for k in range(0, len(xs) - 2, 2)]
        types = ["SEG3"] * len(cells)
    else:
        cells = [(k, k + 1) for k in range(len(xs) - 1)]
        types = ["SEG2"] * len(cells)
    return Mesh(
        coords=coords,
        node_names=[f"N{k + 1}" for k in range(len(xs))],
        cell_names=[f"M{k + 1}" for k in range(len(cells))],
        cell_types=types,
        cell_nodes=cells,
        node_groups={"ALL": np.arange(len(xs))},
        cell_groups={"LINE": np.arange(len(cells))},
    )


def numbering(mesh, components=COMPONENTS) -> DofNumbering:
    return DofNumbering(mesh=mesh, dofs=[(n, c) for n in range(mesh.n_nodes) for c in components])


def transient(mesh, times=(0.0, 0.5, 1.0)) -> DynaTrans:
    """DX = x (1 + t), DY = x^2 at each instant."""
    num = numbering(mesh)
    x = mesh.coords[:, 0]
    values = np.array([np.column_stack([x * (1 + t), x**2]).ravel() for t in times])
    return DynaTrans(
        numbering=num,
        times=np.array(times),
        order=np.arange(1, len(times) + 1),
        fields={"DEPL": values, "VITE": 2 * values},
    )


# -- PROJ_CHAMP -----------------------------------------------------------------


def test_collocation_on_segments_and_coincident_nodes():
    source = line([0.0, 0.5, 1.0])
    target = line([0.25, 0.5, 0.9, 1.4])
    result = transient(source)
    projected = run(
        FakeSession(),
        "PROJ_CHAMP",
        PROJECTION="OUI",
        METHODE="AUTO",
        RESULTAT=result,
        MAILLAGE_1=source,
        MAILLAGE_2=target,
        TOUT_CHAM="OUI",
        INST=0.5,
        CRITERE="RELATIF",
        PRECISION=1e-6,
    )
    assert isinstance(projected, DynaTrans) and list(projected.times) == [0.5]
    assert list(projected.order) == [2]  # the source's order number
    depl = projected.fields["DEPL"][0].reshape(-1, 2)
    # DX linear: exact; DY = x^2 interpolated linearly on each segment
    assert np.allclose(depl[:3, 0], 1.5 * np.array([0.25, 0.5, 0.9]))
    assert depl[1, 1] == 0.25  # coincident node: the node's value
    assert depl[0, 1] == pytest.approx(0.5 * 0.0 + 0.5 * 0.25)
    # beyond the last cell: projected on the nearest point of the nearest cell
    assert depl[3, 0] == pytest.approx(1.5 * 1.0)
    assert np.allclose(projected.fields["VITE"], 2 * projected.fields["DEPL"])


def test_distance_max_prol_vale_and_target_numbering():
    source = line([0.0, 0.5, 1.0])
    target = line([0.25, 1.4])
    target_num = numbering(target, ("DX", "DY", "DZ"))
    projected = run(
        FakeSession(),
        "PROJ_CHAMP",
        PROJECTION="OUI",
        METHODE="COLLOCATION",
        RESULTAT=transient(source),
        MAILLAGE_1=source,
        MAILLAGE_2=target,
        NOM_CHAM="DEPL",
        NUME_DDL=target_num,
        DISTANCE_MAX=0.1,
        PROL_VALE=7.0,
        VIS_A_VIS={"GROUP_MA_1": "LINE", "TOUT_2": "OUI"},
    )
    values = projected.fields["DEPL"][0].reshape(-1, 3)
    assert projected.numbering is target_num and projected.fields.keys() == {"DEPL"}
    assert values[0, 0] == pytest.approx(0.25) and values[0, 2] == 7.0  # no DZ in the source
    assert np.all(values[1] == 7.0)  # 0.4 beyond DISTANCE_MAX


def test_seg3_interpolation_is_exact_for_a_quadratic_field():
    source = line([0.0, 0.5, 1.0], seg3=True)
    target = line([0.1, 0.3, 0.8])
    projected = run(
        FakeSession(),
        "PROJ_CHAMP",
        PROJECTION="OUI",
        METHODE="AUTO",
        RESULTAT=transient(source),
        MAILLAGE_1=source,
        MAILLAGE_2=target,
        NOM_CHAM="DEPL",
        TOUT_ORDRE="OUI",
    )
    depl = projected.fields["DEPL"][0].reshape(-1, 2)
    assert np.allclose(depl[:, 1], np.array([0.1, 0.3, 0.8]) ** 2, atol=1e-14)


def test_nodal_field_projection():
    source = line([0.0, 1.0])
    field = NodalField(numbering=numbering(source), values=np.array([0.0, 1.0, 2.0, 3.0]))
    target = line([0.5, 0.75])
    projected = run(
        FakeSession(),
        "PROJ_CHAMP",
        PROJECTION="OUI",
        METHODE="AUTO",
        CHAM_GD=field,
        MAILLAGE_1=source,
        MAILLAGE_2=target,
    )
    assert isinstance(projected, NodalField)
    assert np.allclose(projected.values, [1.0, 2.0, 1.5, 2.5])


def test_refusals():
    session = FakeSession()
    source = chain_mesh(3)
    quad = Mesh(
        coords=np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float),
        node_names=["A", "B", "C", "D"],
        cell_names=["Q"],
        cell_types=["QUAD4"],
        cell_nodes=[(0, 1, 2, 3)],
    )
    inside = line([0.5])
    # inside a QUAD4 now: interpolated (tests/test_field_projection_cells.py)
    field = NodalField(numbering=numbering(quad), values=np.arange(8.0))
    out = run(session, "PROJ_CHAMP", PROJECTION="OUI", METHODE="AUTO", CHAM_GD=field,
              MAILLAGE_1=quad, MAILLAGE_2=inside)  # fmt: skip
    np.testing.assert_allclose(out.values, [1.0, 2.0])  # halfway between A and B
    field = NodalField(numbering=numbering(source), values=np.zeros(6))
    with pytest.raises(UnsupportedError, match="NUAGE_DEG_0"):
        run(session, "PROJ_CHAMP", PROJECTION="OUI", METHODE="NUAGE_DEG_0", CHAM_GD=field,
            MAILLAGE_1=source, MAILLAGE_2=inside, CHAM_NO_REFE=field)  # fmt: skip
    with pytest.raises(CommandError, match="does not lie on mesh 1"):
        run(session, "PROJ_CHAMP", PROJECTION="OUI", METHODE="AUTO", CHAM_GD=field,
            MAILLAGE_1=line([0.0, 1.0, 2.0]), MAILLAGE_2=inside)  # fmt: skip


# -- LIRE_RESU --------------------------------------------------------------------


def med_file(tmp_path, mesh, name, values, times, orders) -> Path:
    path = tmp_path / "fort.81"
    series = NodalSeries(name, COMPONENTS, values, np.asarray(times), np.asarray(orders))
    write_med(path, mesh, "MAYA", [series])
    return path


def test_lire_resu_mode_meca(tmp_path):
    mesh = line([0.0, 0.5, 1.0])
    num = numbering(mesh)
    shapes = np.array([[[0, 0], [1, 0], [2, 1]], [[0, 0], [1, 2], [0, -1]]], dtype=float)
    path = med_file(tmp_path, mesh, "MODES___DEPL", shapes, [3.5, 7.25], [1, 2])
    mass = AssembledMatrix(numbering=num, matrix=2.0 * np.eye(num.n_dofs), kind="MASS")
    modes = run(
        FakeSession({81: path}),
        "LIRE_RESU",
        FORMAT="MED",
        UNITE=81,
        TYPE_RESU="MODE_MECA",
        FORMAT_MED={"NOM_CHAM": "DEPL", "NOM_RESU": "MODES"},
        MATR_MASS=mass,
        MAILLAGE=mesh,
        TOUT_ORDRE="OUI",
        PROL_ZERO="OUI",
    )
    assert list(modes.frequencies) == [3.5, 7.25]
    assert np.array_equal(modes.shapes[:, 1], shapes[1].ravel())
    assert modes.generalized_mass == pytest.approx([2.0 * 6, 2.0 * 6])
    assert list(modes.parameters["NUME_MODE"]) == [1, 2]


def test_lire_resu_dyna_trans_selection_and_errors(tmp_path):
    mesh = line([0.0, 1.0])
    values = np.arange(3 * 2 * 2, dtype=float).reshape(3, 2, 2)
    path = med_file(tmp_path, mesh, "TRAN_DEPL", values, [0.0, 0.1, 0.2], [4, 5, 6])
    session = FakeSession({81: path})
    common = dict(FORMAT="MED", UNITE=81, TYPE_RESU="DYNA_TRANS", MAILLAGE=mesh, PROL_ZERO="OUI")
    fmt = {"NOM_CHAM": "DEPL", "NOM_CHAM_MED": "TRAN_DEPL"}
    tran = run(session, "LIRE_RESU", FORMAT_MED=fmt, INST=0.1, CRITERE="RELATIF",
               PRECISION=1e-6, **common)  # fmt: skip
    assert list(tran.times) == [0.1] and list(tran.order) == [1]  # renumbered from 1
    assert np.array_equal(tran.fields["DEPL"][0], values[1].ravel())
    tran = run(session, "LIRE_RESU", FORMAT_MED=fmt, NUME_ORDRE=[6, 4], **common)
    assert list(tran.order) == [6, 4]
    with pytest.raises(CommandError, match="no field 'NOPE'"):
        run(session, "LIRE_RESU", FORMAT_MED={"NOM_CHAM": "DEPL", "NOM_CHAM_MED": "NOPE"},
            TOUT_ORDRE="OUI", **common)  # fmt: skip
    with pytest.raises(CommandError, match="no step"):
        run(session, "LIRE_RESU", FORMAT_MED=fmt, INST=0.15, CRITERE="RELATIF",
            PRECISION=1e-6, **common)  # fmt: skip
    with pytest.raises(UnsupportedError, match="IDEAS"):  # element datasets (57)
        run(session, "LIRE_RESU", FORMAT="IDEAS", UNITE=19, TYPE_RESU="DYNA_TRANS",
            MAILLAGE=mesh, TOUT_ORDRE="OUI", NOM_CHAM="VARI_ELNO")  # fmt: skip


def test_sdll113a_passes(tmp_path):
    export = WIDER / "sdll113a" / "sdll113a.export"
    if not export.is_file():
        pytest.skip("../shared/aster-corpus-wider is not available")
    from asterlite.api import run as run_deck

    result = run_deck(export, tmp_path / "out")
    assert result.status == "PASS"


class Shift:
    """A deck function of X, Y, Z: one coordinate plus an offset."""

    nom_para = ("X", "Y", "Z")

    def __init__(self, axis, offset=0.0):
        self.name, self.axis, self.offset = f"F{axis}", axis, offset

    def evaluate_many(self, x, y, z):
        return (x, y, z)[self.axis] + self.offset


class Constant:
    """DEFI_CONSTANTE: a function of TOUTPARA."""

    nom_para = ("TOUTPARA",)
    name = "ZERO"

    def evaluate_many(self, anything):
        return np.zeros_like(anything)


def test_vis_a_vis_transf_geom_2_cas_figure_and_prol_zero():
    # mesh 2 lies one unit beyond mesh 1: TRANSF_GEOM_2 (X-1, Y, Z) brings its
    # nodes back onto mesh 1, where DX = x (1 + t) is interpolated exactly
    source = line([0.0, 0.5, 1.0])
    target = line([1.25, 1.9, 3.5])
    projected = run(
        FakeSession(),
        "PROJ_CHAMP",
        PROJECTION="OUI",
        METHODE="COLLOCATION",
        RESULTAT=transient(source),
        MAILLAGE_1=source,
        MAILLAGE_2=target,
        NOM_CHAM="DEPL",
        INST=1.0,
        CRITERE="RELATIF",
        PRECISION=1e-6,
        DISTANCE_MAX=0.1,
        PROL_VALE=7.0,
        PROL_ZERO="OUI",
        VIS_A_VIS={
            "GROUP_MA_1": "LINE",
            "TOUT_2": "OUI",
            "CAS_FIGURE": "1.5D",
            "TRANSF_GEOM_2": (Shift(0, -1.0), Shift(1), Constant()),
        },
    )
    values = projected.fields["DEPL"][0].reshape(-1, 2)
    assert values[0, 0] == pytest.approx(2.0 * 0.25) and values[1, 0] == pytest.approx(1.8)
    assert np.all(values[2] == 0.0)  # 1.5 beyond DISTANCE_MAX: PROL_ZERO wins over PROL_VALE
    with pytest.raises(CommandError, match="no cell of dimension 2"):
        run(FakeSession(), "PROJ_CHAMP", PROJECTION="OUI", METHODE="COLLOCATION",
            RESULTAT=transient(source), MAILLAGE_1=source, MAILLAGE_2=target,
            NOM_CHAM="DEPL", VIS_A_VIS={"GROUP_MA_1": "LINE", "TOUT_2": "OUI",
                                        "CAS_FIGURE": "2D"})  # fmt: skip


def test_lire_resu_ideas_mode_meca_reads_the_modes_parameters(tmp_path):
    # datasets 55 of two modes (record 7: 2 4 order mode; record 8: FREQ
    # MASS_GENE damping 0), read back as code_aster's lridea stores them
    from asterlite.io.ideas_result import field_lines

    mesh = line([0.0, 0.5, 1.0])
    num = numbering(mesh)
    shapes = np.array([[0.0, 0.0, 1.0, 0.5, 2.0, 1.0], [0.0, 0.0, 1.0, -2.0, 0.0, 1.0]])
    lines = []
    for k, (freq, mass, damping) in enumerate([(3.5, 0.25, 0.01), (7.25, 0.5, 0.02)]):
        lines += field_lines(num, shapes[k], "DEPL", 2, (2, 4, k + 1, k + 3),
                             (freq, mass, damping, 0.0), "T", "S")  # fmt: skip
    path = tmp_path / "modes.unv"
    path.write_text("\n".join(lines) + "\n")
    modes = run(
        FakeSession({21: path}),
        "LIRE_RESU",
        FORMAT="IDEAS",
        UNITE=21,
        TYPE_RESU="MODE_MECA",
        MAILLAGE=mesh,
        NOM_CHAM="DEPL",
        TOUT_ORDRE="OUI",
        FORMAT_IDEAS={
            "NOM_CHAM": "DEPL",
            "NUME_DATASET": 55,
            "RECORD_6": (1, 2, 3, 8, 2, 6),
            "POSI_ORDRE": (7, 3),
            "POSI_NUME_MODE": (7, 4),
            "POSI_FREQ": (8, 1),
            "POSI_MASS_GENE": (8, 2),
            "POSI_AMOR_GENE": (8, 3),
            "NOM_CMP": ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"),
        },
    )
    assert list(modes.frequencies) == [3.5, 7.25]
    assert list(modes.parameters["NUME_MODE"]) == [3, 4]
    assert list(modes.generalized_mass) == [0.25, 0.5]
    assert list(modes.parameters["AMOR_REDUIT"]) == [0.01, 0.02]
    rows = [modes.numbering.index[dof] for dof in num.dofs]  # the file's six slots were read
    np.testing.assert_allclose(modes.shapes[rows].T, shapes, rtol=1e-6)


def test_mesh_labels_rename_every_node_and_cell():
    mesh = line([0.0, 0.5, 1.0])
    mesh.addNodeLabels(["A", "B", "C"])
    assert mesh.node_names == ["A", "B", "C"] and mesh.find_node("B") == 1
    mesh.addCellLabels([f"E{k}" for k in range(mesh.n_cells)])
    assert mesh.find_cell("E0") == 0
    from asterlite.errors import DeckRuntimeError

    with pytest.raises(DeckRuntimeError, match="Bad label size"):
        mesh.addNodeLabels(["A", "B"])
    with pytest.raises(DeckRuntimeError, match="repeat"):
        mesh.addNodeLabels(["A", "A", "C"])


def test_lire_resu_ideas_reads_fields_without_format_ideas_in_code_asters_default_format(
    tmp_path,
):
    # code_aster's crsdfi defaults: dataset 55, record 6 data type 8 (DEPL) or
    # 11 (VITE), order at record 7 field 4, instant at record 8 field 1
    from asterlite.io.ideas_result import field_lines

    mesh = line([0.0, 0.5, 1.0])
    num = numbering(mesh)
    depl = np.array([0.0, 0.0, 1.0, 0.5, 2.0, 1.0])
    lines = []
    for order, time in ((1, 0.5), (2, 1.0)):
        lines += field_lines(num, order * depl, "DEPL", 4, (2, 4, 1, order), (time,), "T", "S")
        lines += field_lines(num, -order * depl, "VITE", 4, (2, 4, 1, order), (time,), "T", "S")
    path = tmp_path / "resu.unv"
    path.write_text("\n".join(lines) + "\n")
    result = run(
        FakeSession({38: path}),
        "LIRE_RESU",
        FORMAT="IDEAS",
        UNITE=38,
        TYPE_RESU="DYNA_TRANS",
        MAILLAGE=mesh,
        NOM_CHAM=("DEPL", "VITE"),
        TOUT_ORDRE="OUI",
    )
    assert list(result.times) == [0.5, 1.0]
    rows = [result.numbering.index[dof] for dof in num.dofs]
    np.testing.assert_allclose(result.fields["DEPL"][1][rows], 2 * depl, rtol=1e-6)
    np.testing.assert_allclose(result.fields["VITE"][0][rows], -depl, rtol=1e-6)
    with pytest.raises(UnsupportedError, match="element dataset"):
        run(FakeSession({38: path}), "LIRE_RESU", FORMAT="IDEAS", UNITE=38,
            TYPE_RESU="DYNA_TRANS", MAILLAGE=mesh, NOM_CHAM="SIEF_ELNO",
            TOUT_ORDRE="OUI")  # fmt: skip
