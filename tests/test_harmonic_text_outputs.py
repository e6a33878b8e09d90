"""Harmonic results through the commands that print and read them, as
code_aster: IMPR_RESU FORMAT='RESULTAT' of a dyna_harmo (a complex value
printed as its real parts then, on an unlabelled row, its imaginary parts,
ircnc8; PARTIE picks one), PARTIE's values (ircmva: also on real fields),
RECU_FONCTION's NOM_RESU (the component on a physical result, focrr0),
TEST_RESU OBJET's check sum (tstvec) and an extracted table's Array."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.harmonic import DynaHarmo, HarmGene
from asterlite.concepts.table import Table, TableView
from asterlite.io.med_writer import complex_part
from tests.test_fem_support import FakeSession, chain_mesh, run


def _harmonic():
    mesh = chain_mesh(2)
    numbering = DofNumbering(mesh=mesh, dofs=[(0, "DX"), (1, "DX"), (1, "DY")])
    depl = np.array([[1.0 + 2.0j, -3.0 + 0.5j, 0.25j], [2.0, 4.0 - 1.0j, -1.0]])
    result = DynaHarmo(
        numbering=numbering,
        frequencies=np.array([10.0, 20.0]),
        order=np.array([1, 2]),
        fields={"DEPL": depl},
    )
    result.name = "HARM"
    return result


class _Session(FakeSession):
    def __init__(self, folder):
        super().__init__()
        self.folder = folder
        self.tests = []

    def output_path(self, unit):
        return self.folder / f"fort.{unit}"

    def record_test(self, record) -> None:
        self.tests.append(record)


def _node_rows(text: str) -> list[list[str]]:
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(" NOEUD "))
    return [line.split() for line in lines[start + 1 :] if line.strip()]


def test_impr_resu_text_of_a_dyna_harmo(tmp_path):
    result = _harmonic()
    session = _Session(tmp_path)
    run(session, "IMPR_RESU", FORMAT="RESULTAT", UNITE=8,
        RESU={"RESULTAT": result, "NOM_CHAM": "DEPL", "NUME_ORDRE": 1})  # fmt: skip
    text = (tmp_path / "fort.8").read_text()
    assert "RESULTAT HARM (dyna_harmo)" in text and "FREQ: 1.00000E+01" in text
    rows = _node_rows(text)
    # N1 carries DX only (listed alone, as ircnc8 does): 1+2i; then a new
    # header for N2's DX DY: -3+0.5i, 0.25i
    assert rows[0][0] == "N1" and [float(v) for v in rows[0][1:]] == [1.0]
    assert [float(v) for v in rows[1]] == [2.0]
    assert rows[2] == ["NOEUD", "DX", "DY"]
    assert rows[3][0] == "N2" and [float(v) for v in rows[3][1:]] == [-3.0, 0.0]
    assert [float(v) for v in rows[4]] == [0.5, 0.25]
    run(session, "IMPR_RESU", FORMAT="RESULTAT", UNITE=9,
        RESU={"RESULTAT": result, "NOM_CHAM": "DEPL", "NUME_ORDRE": 2,
              "PARTIE": "MODULE"})  # fmt: skip
    rows = _node_rows((tmp_path / "fort.9").read_text())
    assert len(rows) == 3  # one row per node, a header where the components change
    np.testing.assert_allclose([float(v) for v in rows[2][1:]], [abs(4.0 - 1.0j), 1.0], 1e-13)


def test_partie_values_as_code_aster_writes_them():
    values = np.array([1.0 + 1.0j, -2.0 + 0.0j])
    np.testing.assert_array_equal(complex_part(values, "REEL"), [1.0, -2.0])
    np.testing.assert_array_equal(complex_part(values, "IMAG"), [1.0, 0.0])
    np.testing.assert_allclose(complex_part(values, "MODULE"), [np.sqrt(2.0), 2.0])
    np.testing.assert_allclose(complex_part(values, "PHASE"), [45.0, 180.0])
    real = np.array([-1.5, 2.0])  # a real field: zero imaginary part, phase 0 or 180
    np.testing.assert_array_equal(complex_part(real, "IMAG"), [0.0, 0.0])
    np.testing.assert_array_equal(complex_part(real, "PHASE"), [180.0, 0.0])
    np.testing.assert_array_equal(complex_part(real, "MODULE"), [1.5, 2.0])


def test_recu_fonction_of_a_dyna_harmo_is_named_after_the_component():
    result = _harmonic()
    function = run(FakeSession(), "RECU_FONCTION", RESULTAT=result, NOM_CHAM="DEPL",
                   NOM_CMP="DX", NOEUD="N2", TOUT_ORDRE="OUI")  # fmt: skip
    assert function.NOM_RESU == "DX"
    np.testing.assert_array_equal(function.ordinates, [-3.0 + 0.5j, 4.0 - 1.0j])


def test_test_resu_objet_is_the_sum_of_real_and_imaginary_parts(tmp_path):
    depl = np.array([[1.0 + 2.0j, -0.5j], [3.0, 4.0 - 1.0j]])
    result = HarmGene(basis=None, numbering=None, frequencies=np.array([1.0, 2.0]),
                      order=np.array([1, 2]), fields={"DEPL": depl})  # fmt: skip
    result.name = "HG"
    session = _Session(tmp_path)
    session.namespace = {"HG": result}
    run(session, "TEST_RESU", OBJET={"NOM": "HG                 .DEPL", "VALE_CALC": 8.5})
    (record,) = session.tests
    assert record.value == pytest.approx(1 + 2 - 0.5 + 3 + 4 - 1) and record.ok


def test_extracted_table_array():
    table = Table()
    table.add_column("INST", "R")
    table.add_column("DX", "R")
    table.add_row({"INST": 0.5, "DX": 2.0})
    table.add_row({"INST": 1.5, "DX": -1.0})
    array = TableView(table).deck_getattr("Array")("INST", "DX")
    np.testing.assert_array_equal(array, [[0.5, 2.0], [1.5, -1.0]])


def test_get_field_of_a_harmonic_result():
    """getField(name, NUME_ORDRE) / getField(name, freq, 'FREQ') give the
    complex nodal field; a missing order and an element field are refused."""
    from asterlite.errors import CommandError, UnsupportedError

    result = _harmonic()
    assert result.getField("DEPL", 1).getValues() == [1.0 + 2.0j, -3.0 + 0.5j, 0.25j]
    assert result.getField("DEPL", 20.0, "FREQ").getValues() == [2.0, 4.0 - 1.0j, -1.0]
    assert result.getField("DEPL").getValues() == [2.0, 4.0 - 1.0j, -1.0]
    with pytest.raises(CommandError, match="NUME_ORDRE 3 is not stored"):
        result.getField("DEPL", 3)
    result.element_fields["EFGE_ELNO"] = object()
    with pytest.raises(UnsupportedError, match="EFGE_ELNO of a dyna_harmo"):
        result.getField("EFGE_ELNO", 1)


def test_impr_resu_med_of_a_dyna_harmo_writes_the_part_asked(tmp_path):
    """MED holds real values: a dyna_harmo is written one PARTIE at a time,
    the frequency as the step's time; without PARTIE, code_aster stops."""
    from asterlite.errors import CommandError
    from asterlite.io.med_result import read_nodal_field

    result = _harmonic()
    session = _Session(tmp_path)
    for unit, part in ((20, "IMAG"), (21, "PHASE")):
        run(session, "IMPR_RESU", FORMAT="MED", UNITE=unit,
            RESU={"RESULTAT": result, "NOM_CHAM": "DEPL", "PARTIE": part,
                  "NOM_CHAM_MED": f"DEPL_{part}"})  # fmt: skip
        back = read_nodal_field(tmp_path / f"fort.{unit}", f"DEPL_{part}")
        assert [step.time for step in back.steps] == [10.0, 20.0]
        second = back.steps[1]
        expected = complex_part(result.fields["DEPL"][1], part)
        # N1 carries DX only (DY written as zero); N2 DX then DY
        np.testing.assert_allclose(second.values[0, 0], expected[0])
        np.testing.assert_allclose(second.values[1, :2], expected[1:], rtol=1e-14)
    with pytest.raises(CommandError, match="one PARTIE at a time"):
        run(session, "IMPR_RESU", FORMAT="MED", UNITE=22,
            RESU={"RESULTAT": result, "NOM_CHAM": "DEPL"})  # fmt: skip


def test_impr_resu_text_of_a_complex_elno_field_on_segments_and_points(tmp_path):
    """EFGE_ELNO of a dyna_harmo on two-node springs and point cells (values
    padded with NaN past a point cell's node): each cell lists its own nodes,
    a complex value as its real parts then its imaginary parts (ircecl)."""
    from asterlite.concepts.assembly import ElementField

    result = _harmonic()
    values = np.full((2, 2, 2, 1), np.nan, dtype=complex)
    values[:, 0, :, 0] = [[1.0 + 2.0j, -1.0 - 2.0j], [3.0, -3.0]]  # spring S1
    values[:, 1, 0, 0] = [0.5j, 4.0 + 0.0j]  # point cell P1
    result.element_fields["EFGE_ELNO"] = ElementField("EFGE_ELNO", np.array([0, 1]), ("N",), values)
    session = _Session(tmp_path)
    run(session, "IMPR_RESU", FORMAT="RESULTAT", UNITE=8,
        RESU={"RESULTAT": result, "NOM_CHAM": "EFGE_ELNO", "NUME_ORDRE": 1})  # fmt: skip
    lines = (tmp_path / "fort.8").read_text().splitlines()
    start = lines.index(" MAILLE S1")
    rows = [line.split() for line in lines[start:] if line.strip()]
    assert rows[1] == ["NOEUD", "N"]
    assert rows[2][0] == "N1" and float(rows[2][1]) == 1.0 and float(rows[3][0]) == 2.0
    assert rows[4][0] == "N2" and float(rows[4][1]) == -1.0 and float(rows[5][0]) == -2.0
    assert rows[6] == ["MAILLE", "P1"] and rows[7] == ["NOEUD", "N"]
    assert rows[8][0] == "N1" and float(rows[8][1]) == 0.0 and float(rows[9][0]) == 0.5
    assert len(rows) == 10  # no row for the padding of the point cell
