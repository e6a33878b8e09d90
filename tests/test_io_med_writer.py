"""MED writing (asterlite.io.med_writer) and IMPR_RESU / IMPR_GENE outputs."""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest
from asterlite.commands import impr_gene, impr_resu, rest_gene_phys

from asterlite.concepts.assembly import DofNumbering, NodalField
from asterlite.concepts.mesh import Mesh
from asterlite.errors import CommandError, UnsupportedError
from asterlite.io.aster_mesh import read_aster_mesh
from asterlite.io.med_mesh import read_med_mesh
from asterlite.io.med_writer import (
    NodalSeries,
    dofs_to_nodal,
    med_field_name,
    med_field_names,
    write_med,
)

from .test_post_support import context, kw, small_transient

mc = pytest.importorskip("medcoupling")


def mdump_text(path) -> str | None:
    """mdump's dump of a MED file (None when libmed-tools is not installed);
    asserts that mdump reads the file."""
    if shutil.which("mdump") is None:
        return None
    done = subprocess.run(
        ["mdump", str(path), "NODALE", "FULL_INTERLACE", "0"],
        capture_output=True,
        text=True,
        stdin=subprocess.DEVNULL,
        timeout=60,
    )
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    return done.stdout


def assert_mdump_reads(path, *names):
    text = mdump_text(path)
    if text is not None:
        for name in names:
            assert name in text, f"{name} not in mdump output"


def mixed_mesh() -> Mesh:
    """A hexahedron, two segments and a point cell, in scrambled type order."""
    coords = np.array(
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
        + [[2, 0, 0]],
        dtype=float,
    )
    mesh = Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(9)],
        cell_names=["S1", "H1", "P1", "S2"],
        cell_types=["SEG2", "HEXA8", "POI1", "SEG2"],
        cell_nodes=[(1, 8), (0, 1, 2, 3, 4, 5, 6, 7), (8,), (0, 4)],
        node_groups={"TOUS": np.arange(9), "TIP": np.array([8])},
        cell_groups={"BEAM": np.array([0, 3]), "TIP": np.array([2]), "VOL": np.array([1])},
    )
    mesh.name = "MAIL"
    return mesh


def test_mesh_round_trip_keeps_types_names_groups_and_connectivity(tmp_path):
    path = write_med(tmp_path / "m.med", mixed_mesh(), "MAIL")
    back = read_med_mesh(path)
    assert back.cell_names == ["P1", "S1", "S2", "H1"]  # sorted by MED type
    assert back.cell_types == ["POI1", "SEG2", "SEG2", "HEXA8"]
    assert back.cell_nodes[3] == (0, 1, 2, 3, 4, 5, 6, 7)
    assert back.node_names == [f"N{i + 1}" for i in range(9)]
    assert back.node_groups["TIP"].tolist() == [8]
    assert back.cell_groups["TIP"].tolist() == [0]  # same name at both levels
    assert back.cell_groups["BEAM"].tolist() == [1, 2]
    assert np.allclose(back.coords, mixed_mesh().coords)
    assert_mdump_reads(path, "MAIL", "BEAM", "VOL", "MED_HEXA8")


def test_nodal_series_round_trip_with_times_orders_and_profile(tmp_path):
    mesh = mixed_mesh()
    full = NodalSeries(
        "RES_____DEPL",
        ("DX", "DY"),
        np.arange(3 * 9 * 2, dtype=float).reshape(3, 9, 2),
        np.array([0.0, 0.1, 0.2]),
        np.array([1, 5, 9]),
    )
    part = NodalSeries(
        "RES_____VITE",
        ("DZ",),
        np.array([[[1.0], [2.0]], [[3.0], [4.0]]]),
        np.array([0.0, 0.1]),
        np.array([1, 5]),
        nodes=np.array([8, 0]),  # unsorted on purpose
    )
    path = write_med(tmp_path / "f.med", mesh, "MAIL", [full, part])
    assert med_field_names(path) == ["RES_____DEPL", "RES_____VITE"]
    multi = mc.MEDFileFieldMultiTS.New(str(path), "RES_____DEPL")
    assert [it for it, _, _ in multi.getTimeSteps()] == [1, 5, 9]
    assert [t for _, _, t in multi.getTimeSteps()] == pytest.approx([0.0, 0.1, 0.2])
    read = mc.ReadFieldNode(str(path), "MAIL", 0, "RES_____DEPL", 5, -1)
    assert read.getArray().getInfoOnComponents() == ["DX", "DY"]
    assert np.allclose(read.getArray().toNumPyArray(), full.values[1])
    one = mc.MEDFileField1TS(str(path), "RES_____VITE", 5, -1)
    values, profile = one.getFieldWithProfile(mc.ON_NODES, 0, mc.MEDFileMesh.New(str(path)))
    assert profile.toNumPyArray().tolist() == [0, 8]  # increasing, values follow
    assert values.toNumPyArray().ravel().tolist() == [4.0, 3.0]
    assert_mdump_reads(path, "PFL_RES_____VITE", "RES_____VITE")


@pytest.mark.parametrize("version", ["3.3.1", "4.0.0", "4.1.0"])
def test_every_med_version_is_readable_by_mdump(tmp_path, version):
    mesh = mixed_mesh()
    series = NodalSeries("R_______DEPL", ("DX",), np.ones((1, 9, 1)), np.zeros(1), np.ones(1))
    path = write_med(tmp_path / f"v{version}.med", mesh, "MAIL", [series], version=version)
    assert_mdump_reads(path, "MAIL", "R_______DEPL")


def test_field_names_and_dof_spreading():
    assert med_field_name("MODES", "DEPL") == "MODES___DEPL"
    assert med_field_name("DYNATRANS1", "ACCE") == "DYNATRANACCE"
    mesh = small_transient().basis.numbering.mesh
    numbering = DofNumbering(mesh, [(0, "DX"), (1, "DY"), (1, "DRZ")])
    nodes, comps, values = dofs_to_nodal(numbering, [[1.0, 2.0, 3.0]])
    assert nodes.tolist() == [0, 1] and comps == ("DX", "DY", "DRZ")
    assert values[0].tolist() == [[1.0, 0.0, 0.0], [0.0, 2.0, 3.0]]
    nodes, comps, values = dofs_to_nodal(numbering, [[1.0, 2.0, 3.0]], [1], ("DRZ",))
    assert nodes.tolist() == [1] and values[0].tolist() == [[3.0]]


def physical_transient():
    result = small_transient()
    result.basis.numbering.mesh.name = "MESH"
    phys = rest_gene_phys.run(context(), kw(RESU_GENE=result, TOUT_CHAM="OUI"))
    phys.name = "DYNA"
    return phys


def test_impr_resu_med_writes_result_restricted_and_appends(tmp_path):
    ctx = context("IMPR_RESU", tmp_path)
    phys = physical_transient()
    impr_resu.run(
        ctx,
        kw(
            FORMAT="MED",
            UNITE=80,
            VERSION_MED="4.0.0",
            RESU=[{"RESULTAT": phys, "NOM_CHAM": ("DEPL",), "NUME_ORDRE": (2, 4)}],
        ),
    )
    impr_resu.run(
        ctx,
        kw(
            FORMAT="MED",
            UNITE=80,
            VERSION_MED="4.0.0",
            RESU=[
                {
                    "RESULTAT": phys,
                    "NOM_CHAM": ("VITE",),
                    "GROUP_NO": ("NO2",),
                    "NOM_CMP": ("DY",),
                    "INST": (0.5,),
                    "CRITERE": "RELATIF",
                    "PRECISION": 1e-6,
                }
            ],
        ),
    )
    path = tmp_path / "fort.80"
    assert med_field_names(path) == ["DYNA____DEPL", "DYNA____VITE"]
    depl = mc.ReadFieldNode(str(path), "MESH", 0, "DYNA____DEPL", 4, -1)
    # NO2 DX = 2 q1 + 0.5 q2 at t = 0.4
    assert depl.getArray().toNumPyArray()[1, 0] == pytest.approx(2 * 0.4 + 0.5 * 0.16)
    multi = mc.MEDFileFieldMultiTS.New(str(path), "DYNA____VITE")
    assert [t for _, _, t in multi.getTimeSteps()] == pytest.approx([0.5])
    assert_mdump_reads(path, "MESH", "DYNA____DEPL", "DYNA____VITE")


def test_impr_resu_med_mesh_only_modes_and_cham_gd(tmp_path):
    ctx = context("IMPR_RESU", tmp_path)
    mesh = mixed_mesh()
    impr_resu.run(ctx, kw(FORMAT="MED", UNITE=81, RESU=[{"MAILLAGE": mesh}]))
    assert read_med_mesh(tmp_path / "fort.81").n_cells == 4
    basis = small_transient().basis
    basis.name = "MODES"
    basis.numbering.mesh.name = "MESH"
    field = NodalField(basis.numbering, np.array([1.0, 2.0, 3.0, 4.0]))
    field.name = "CHAMP"
    impr_resu.run(
        ctx,
        kw(
            FORMAT="MED",
            UNITE=82,
            RESU=[{"RESULTAT": basis}, {"CHAM_GD": field, "NOM_CHAM_MED": ("MON_CHAMP",)}],
        ),
    )
    path = tmp_path / "fort.82"
    assert med_field_names(path) == ["MODES___DEPL", "MON_CHAMP"]
    multi = mc.MEDFileFieldMultiTS.New(str(path), "MODES___DEPL")
    assert [t for _, _, t in multi.getTimeSteps()] == pytest.approx([1.0, 2.0])  # frequencies
    assert_mdump_reads(path, "MESH", "MODES___DEPL", "MON_CHAMP")


def test_impr_resu_errors_name_the_keyword(tmp_path):
    ctx = context("IMPR_RESU", tmp_path)
    phys = physical_transient()
    with pytest.raises(CommandError, match="NUME_ORDRE 99"):
        impr_resu.run(ctx, kw(FORMAT="MED", RESU=[{"RESULTAT": phys, "NUME_ORDRE": (99,)}]))
    with pytest.raises(CommandError, match="no field SIEF_ELGA"):
        impr_resu.run(ctx, kw(FORMAT="MED", RESU=[{"RESULTAT": phys, "NOM_CHAM": ("SIEF_ELGA",)}]))
    with pytest.raises(CommandError, match="no component DRZ"):
        impr_resu.run(ctx, kw(FORMAT="MED", RESU=[{"RESULTAT": phys, "NOM_CMP": ("DRZ",)}]))
    with pytest.raises(UnsupportedError, match="GMSH"):
        impr_resu.run(ctx, kw(FORMAT="GMSH", RESU=[{"MAILLAGE": mixed_mesh()}]))


def test_impr_resu_resultat_text_listing(tmp_path):
    ctx = context("IMPR_RESU", tmp_path)
    basis = small_transient().basis
    basis.name = "MODES"
    impr_resu.run(
        ctx,
        kw(
            FORMAT="RESULTAT",
            UNITE=8,
            RESU=[
                {
                    "RESULTAT": basis,
                    "NUME_MODE": (2,),
                    "TOUT_PARA": "OUI",
                    "IMPR_COOR": "OUI",
                    "VALE_MAX": "OUI",
                    "FORMAT_R": "1PE12.5",
                }
            ],
        ),
    )
    text = (tmp_path / "fort.8").read_text()
    assert "RESULTAT MODES (mode_meca)" in text
    assert "CHAMP AUX NOEUDS DE NOM SYMBOLIQUE  DEPL" in text
    assert "NUMERO D'ORDRE:        2 NUME_MODE: 2 FREQ: 2.00000E+00" in text
    no2 = next(line for line in text.splitlines() if line.startswith(" NO2"))
    assert no2.split()[-2:] == ["5.00000E-01", "-1.00000E+00"]
    assert "VALE_MAX DX" in text and "COOR_X" in text


def test_impr_resu_aster_mesh_round_trip(tmp_path):
    ctx = context("IMPR_RESU", tmp_path)
    impr_resu.run(ctx, kw(FORMAT="ASTER", UNITE=26, RESU=[{"MAILLAGE": mixed_mesh()}]))
    back = read_aster_mesh(tmp_path / "fort.26")
    mesh = mixed_mesh()
    assert back.cell_names == mesh.cell_names and back.cell_types == mesh.cell_types
    assert back.cell_nodes == mesh.cell_nodes
    assert back.cell_groups["BEAM"].tolist() == [0, 3]
    assert np.allclose(back.coords, mesh.coords)


def test_impr_gene_lists_generalized_fields(tmp_path):
    ctx = context("IMPR_GENE", tmp_path)
    result = small_transient()
    result.name = "TRAN"
    impr_gene.run(
        ctx,
        kw(
            UNITE=8,
            GENE=[
                {
                    "RESU_GENE": result,
                    "NOM_CHAM": ("VITE",),
                    "NUME_CMP_GENE": (2,),
                    "INST": (0.5,),
                    "CRITERE": "RELATIF",
                    "PRECISION": 1e-6,
                    "INFO_GENE": "OUI",
                }
            ],
        ),
    )
    text = (tmp_path / "fort.8").read_text()
    assert "RESULTAT GENERALISE TRAN (tran_gene)" in text
    assert "CHAMP GENERALISE VITE" in text
    assert "NUMERO D'ORDRE:        5 INST: 5.00000E-01" in text
    assert "             2  1.00000000000000E+00" in text  # q2' = 2 t at t = 0.5
    assert "NON-LINEARITES: CHOC1" in text


def test_text_units_accumulate_and_med_replaces_a_stale_file(tmp_path):
    (tmp_path / "fort.8").write_text("table written earlier\n")
    (tmp_path / "fort.80").write_bytes(b"not a MED file from an older run")
    ctx = context("IMPR_RESU", tmp_path)
    basis = small_transient().basis
    impr_resu.run(ctx, kw(FORMAT="RESULTAT", UNITE=8, RESU=[{"RESULTAT": basis}]))
    impr_resu.run(ctx, kw(FORMAT="RESULTAT", UNITE=8, RESU=[{"RESULTAT": basis}]))
    text = (tmp_path / "fort.8").read_text()
    assert text.startswith("table written earlier") and text.count("RESULTAT ") == 2
    impr_resu.run(ctx, kw(FORMAT="MED", UNITE=80, RESU=[{"MAILLAGE": mixed_mesh()}]))
    assert read_med_mesh(tmp_path / "fort.80").n_cells == 4


def beam_element_mesh() -> Mesh:
    """Three SEG2 beams and a POI1 cell (a lower MED level)."""
    mesh = Mesh(
        coords=np.array([[0.0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]),
        node_names=["N1", "N2", "N3", "N4"],
        cell_names=["M1", "M2", "M3", "P1"],
        cell_types=["SEG2", "SEG2", "SEG2", "POI1"],
        cell_nodes=[(0, 1), (1, 2), (2, 3), (3,)],
        node_groups={},
        cell_groups={"TWO": np.array([0, 2])},
    )
    mesh.name = "MAIL"
    return mesh


def test_element_series_elno_and_elga_are_read_by_mdump(tmp_path):
    from asterlite.io.med_writer import ElementSeries, MedWriteError, gauss_localization

    mesh = beam_element_mesh()
    elno = ElementSeries(
        "DYN_____SIPO_ELNO",
        "ELNO",
        np.array([2, 0]),
        ("SN", "SVY"),
        np.arange(2 * 2 * 2 * 2, dtype=float).reshape(2, 2, 2, 2),
        np.array([0.0, 0.5]),
        np.array([1, 2]),
    )
    elga = ElementSeries(
        "DYN_____EFGE_ELGA",
        "ELGA",
        np.array([0, 1, 2]),
        ("N",),
        np.ones((1, 3, 3, 1)),
        np.array([0.0]),
        np.array([1]),
    )
    path = write_med(tmp_path / "el.med", mesh, "MAIL", [elno, elga])
    assert set(med_field_names(path)) == {"DYN_____SIPO_ELNO", "DYN_____EFGE_ELGA"}
    import medcoupling as mc

    read = mc.MEDFileField1TS(str(path), "DYN_____SIPO_ELNO", 2, -1)
    field = read.getFieldOnMeshAtLevel(mc.ON_GAUSS_NE, 0, mc.MEDFileMesh.New(str(path)))
    # profile cells M1, M3 in increasing order: the rows of M1 (second in the series) first
    assert field.getArray().toNumPyArray().tolist()[:2] == [[12.0, 13.0], [14.0, 15.0]]
    assert gauss_localization("SEG2", 3)[2] == pytest.approx([5 / 9, 8 / 9, 5 / 9])
    text = mdump_text(path)
    if text is not None:
        assert "MED_NOEUD_MAILLE" in text and "DYN_____EFGE_ELGA" in text
    with pytest.raises(MedWriteError, match="Gauss points of TRIA3"):
        gauss_localization("TRIA3", 3)


def test_impr_resu_element_fields_med_text_and_cham_elem(tmp_path):
    from asterlite.commands import test_resu

    from asterlite.concepts.assembly import ElementField
    from asterlite.concepts.modes import FieldOnElements

    ctx = context("IMPR_RESU", tmp_path)
    phys = physical_transient()
    n = len(phys.times)
    values = np.arange(n * 2 * 1, dtype=float).reshape(n, 1, 2, 1)
    phys.element_fields = {"SIPO_ELNO": ElementField("SIPO_ELNO", np.array([0]), ("SN",), values)}
    impr_resu.run(
        ctx, kw(FORMAT="MED", RESU=[{"RESULTAT": phys, "NOM_CHAM": ("DEPL", "SIPO_ELNO")}])
    )
    path = tmp_path / "fort.80"
    assert "DYNA____SIPO_ELNO" in med_field_names(path)
    assert_mdump_reads(path, "DYNA____SIPO_ELNO")
    cham = FieldOnElements(
        mesh=phys.numbering.mesh,
        field_type="ELNO_SIEF_R",
        field_name="SIPO_ELNO",
        cells=np.array([0]),
        components=("SN", "SMFZ"),
        values=np.array([[[1.5, -2.0], [3.0, 4.0]]]),
    )
    cham.name = "MAXABS"
    impr_resu.run(ctx, kw(FORMAT="MED", UNITE=81, RESU=[{"CHAM_GD": cham}]))
    assert_mdump_reads(tmp_path / "fort.81", "MAXABS")
    impr_resu.run(
        ctx,
        kw(
            FORMAT="RESULTAT",
            RESU=[{"CHAM_GD": cham, "FORMAT_R": "1PE12.5"}, {"RESULTAT": phys, "NUME_ORDRE": (2,)}],
        ),
    )
    text = (tmp_path / "fort.8").read_text()
    assert "CHAMP PAR ELEMENT AUX NOEUDS MAXABS" in text
    assert "CHAMP PAR ELEMENT AUX NOEUDS DE NOM SYMBOLIQUE  SIPO_ELNO" in text
    lines = text.splitlines()
    at = lines.index(" MAILLE EL1")
    assert lines[at + 2].split() == ["NO1", "1.50000E+00", "-2.00000E+00"]
    test_ctx = context("TEST_RESU", tmp_path)
    test_resu.run(
        test_ctx,
        kw(
            CHAM_ELEM=[
                {"CHAM_GD": cham, "GROUP_MA": "BAR", "NOEUD": "NO2", "NOM_CMP": "SMFZ",
                 "VALE_CALC": 4.0},
                {"CHAM_GD": cham, "TYPE_TEST": "SOMM_ABS", "VALE_CALC": 10.5},
            ]
        ),
    )  # fmt: skip
    assert [t.ok for t in test_ctx.session.tests] == [True, True]
