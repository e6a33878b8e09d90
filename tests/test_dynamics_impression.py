"""DYNA_VIBRA/IMPRESSION: the DIS_VISC / DIS_ECRO_TRAC histories written to
logical units (asterlite.io.relation_history) and the shocks' local
quantities listed in the message log (asterlite.io.shock_listing)."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from asterlite.commands.lire_fonction import numeric_blocks

from asterlite.catalog.keywords import Keywords
from asterlite.concepts.transient import ShockHistory
from asterlite.errors import UnsupportedError
from asterlite.io import relation_history as RH
from asterlite.io import shock_listing as SL
from asterlite.io.export import RunDescription, describe_run
from asterlite.runtime.context import CommandContext
from asterlite.runtime.runner import run_deck
from asterlite.runtime.session import Session

# ----------------------------------------------------------------------------- pieces


def test_fortran_1pe18_10e3():
    assert RH.fortran_e(0.0) == "0.0000000000E+000"
    assert RH.fortran_e(-1234.5) == "-1.2345000000E+003"
    assert RH.fortran_e(2.5e-3) == "2.5000000000E-003"
    assert RH.fortran_e(1.0e-100) == "1.0000000000E-100"
    assert RH.fortran_e(0.1 + 0.2) == "3.0000000000E-001"


def law_history(relation, name, n_vint, times, seed):
    values = np.random.default_rng(seed).normal(size=(len(times), n_vint))
    fields = {f"VINT{i + 1}": values[:, i] for i in range(n_vint)}
    return ShockHistory(name, relation, "NO1", "NO22", fields)


def fake_result(times):
    times = np.asarray(times, dtype=float)
    choc = ShockHistory("C1", "DIS_CHOC", "NO5", None, {})
    visc = law_history("DIS_VISC", "V", 11, times, 1)
    ecro = law_history("DIS_ECRO_TRAC", "E", 20, times, 2)
    visc_2 = law_history("DIS_VISC", "W", 11, times, 3)
    return SimpleNamespace(times=times, shocks=[choc, visc, ecro, visc_2])


def test_dis_visc_block_layout():
    result = fake_result([0.0, 0.5, 1.0])
    lines = RH.history_lines(result, "DIS_VISC", "RESU")
    # one block per DIS_VISC relation, ranked among all the nonlinearities
    assert lines[:5] == [
        "#",
        "#" + "-" * 50,
        "#RESULTAT RESU    ",
        "#DIS_VISC     2 NO1      NO22    ",
        "".join(" " + n.rjust(18) for n in ("INST", "FORCE", "DEPLVISC", "DEPL", "PUISS")),
    ]
    assert lines[8 + 3] == "#DIS_VISC     4 NO1      NO22    "
    rows = lines[5:8]
    assert all(len(row) == 5 * 19 for row in rows)
    table = np.array([[float(x) for x in row.split()] for row in rows])
    fields = result.shocks[1].fields
    expected = np.column_stack([result.times] + [fields[f"VINT{i}"] for i in (8, 9, 10, 11)])
    assert np.allclose(table, expected, rtol=1e-10, atol=0.0)


def test_dis_ecro_trac_pairs_force_and_displacement():
    result = fake_result([0.0, 1.0])
    lines = RH.history_lines(result, "DIS_ECRO_TRAC", "R")
    assert lines[3] == "#DIS_ECRO_TRAC     3 NO1      NO22    "
    assert lines[4].split() == ["INST", "FX", "UX", "FY", "UY", "FZ", "UZ", "PUISS"]
    row = np.array([float(x) for x in lines[6].split()])
    fields = result.shocks[2].fields
    # force (VINT7..9), displacement (VINT10..12), dissipated energy (VINT13)
    expected = [1.0] + [fields[f"VINT{i}"][1] for i in (7, 10, 8, 11, 9, 12, 13)]
    assert np.allclose(row, expected, rtol=1e-10)


def session_in(tmp_path, units=None) -> Session:
    run = RunDescription(name="t", deck_files=[], units=dict(units or {}))
    return Session(run, output_dir=tmp_path)


def test_each_run_appends_a_block_read_back_by_lire_fonction(tmp_path):
    session = session_in(tmp_path)
    first, second = fake_result([0.0, 1.0]), fake_result([1.0, 1.5, 2.0])
    RH.write_histories(session, first, "A", {"UNITE_DIS_VISC": 35})
    RH.write_histories(session, second, "B", {"UNITE_DIS_VISC": 35})
    text = session.input_path(35).read_text()
    blocks = numeric_blocks(text)
    # two DIS_VISC relations per run, one block each
    assert [len(b) for b in blocks] == [2, 2, 3, 3]
    assert [row[0] for row in blocks[2]] == [1.0, 1.5, 2.0]
    assert text.count("#RESULTAT A") == 2 and text.count("#RESULTAT B") == 2


def test_no_relation_of_that_kind_writes_nothing(tmp_path):
    session = session_in(tmp_path)
    result = SimpleNamespace(times=np.zeros(1), shocks=[])
    notes = RH.write_histories(session, result, "A", {"UNITE_DIS_ECRO_TRAC": 38})
    assert "nothing written" in notes[0]
    assert 38 not in session.output_units


def test_a_unit_mapped_to_an_input_file_is_continued(tmp_path):
    given = tmp_path / "given.txt"
    given.write_text("1.0 2.0\n")
    out = tmp_path / "out"
    session = session_in(out, {35: given})
    RH.write_histories(session, fake_result([0.0]), "A", {"UNITE_DIS_VISC": 35})
    text = session.input_path(35).read_text()
    assert text.startswith("1.0 2.0\n#\n")
    assert given.read_text() == "1.0 2.0\n"  # the input itself is left alone


# ----------------------------------------------------------------------------- listing


def choc_result():
    times = np.linspace(0.0, 0.1, 11)
    fields = {name: np.arange(11.0) + k for k, name in enumerate(SL.SECTIONS["DEPL_LOC"][1])}
    for names in (SL.SECTIONS["FORC_LOC"][1], SL.SECTIONS["VITE_LOC"][1]):
        fields.update({name: -np.arange(11.0) for name in names})
    choc = ShockHistory("C1", "DIS_CHOC", "NO5", None, fields)
    return SimpleNamespace(times=times, order=np.arange(11), shocks=[choc])


def test_levels():
    assert SL.requested_levels("FORC_LOC", "OUI") == ("FORC_LOC",)
    assert set(SL.requested_levels(None, "OUI")) == set(SL.LEVELS)
    assert SL.requested_levels(None, None) == ()


def test_listing_window_and_columns():
    result = choc_result()
    lines = SL.listing_lines(result, ("DEPL_LOC",), 0.03, 0.06)
    rows = [line for line in lines if line.split()[0].isdigit()]
    # archive indices 4..7 (t = 0.03 .. 0.06: accumulated steps do not drop 0.06)
    assert [int(r.split()[0]) for r in rows] == [4, 5, 6, 7]
    values = [float(x.replace("D", "E")) for x in rows[0].split()[1:]]
    assert values == pytest.approx([0.03, 3.0, 4.0, 5.0])
    assert not any("contact forces" in line for line in lines)


def impression_call(tmp_path, occurrence: dict):
    session = session_in(tmp_path)
    ctx = CommandContext(session=session, command="DYNA_VIBRA")
    occ = Keywords(occurrence, path="DYNA_VIBRA/IMPRESSION[1]")
    basis = SimpleNamespace(stiffness=None)
    kw = Keywords({"IMPRESSION": [occ], "MATR_MASS": SimpleNamespace(basis=basis)})
    from asterlite.commands.dyna_vibra_result import impression

    system = SimpleNamespace(stiffness=np.eye(1))
    impression(ctx, kw, choc_result(), "R", [], system)
    return session


def test_tout_lists_every_level_in_the_message_log(tmp_path):
    with pytest.raises(UnsupportedError, match="TAUX_CHOC"):  # needs the basis stiffness
        impression_call(tmp_path, {"TOUT": "OUI"})
    session = impression_call(tmp_path, {"NIVEAU": "VITE_LOC", "INST_FIN": 0.02})
    log = "\n".join(session.messages)
    assert "local velocities at shock node NO5" in log and "local displacements" not in log
    assert sum(1 for m in session.messages if m.split()[0].isdigit()) == 3


def test_instants_alone_list_nothing_and_say_so(tmp_path):
    session = impression_call(tmp_path, {"INST_INIT": 0.01})
    assert any("nothing listed without NIVEAU" in m for m in session.messages)


# ----------------------------------------------------------------------------- deck

MESH = (
    """ TITRE
 IMPRESSION TEST
 FINSF
 %
 COOR_3D
 N1 0.0 0.0 0.0
 N2 0.1 0.0 0.0
 N3 0.2 0.0 0.0
 FINSF
 %
 POI1
 P1 N1
 P2 N2
 FINSF
 %
 SEG2
 S23 N2 N3
 FINSF
 %
"""
    + "".join(
        f" GROUP_{kind}\n {name}\n {name}\n FINSF\n %\n"
        for kind, name in (("NO", "N1"), ("NO", "N2"), ("NO", "N3"), ("MA", "P1"), ("MA", "P2"))
    )
    + " GROUP_MA\n S23\n S23\n FINSF\n %\n FIN\n"
)

DECK = """DEBUT(CODE="OUI")
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE",
                     MODELISATION="DIS_T"))
CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(
    _F(GROUP_MA="P1", CARA="M_T_D_N", VALE=0.0),
    _F(GROUP_MA="P1", CARA="K_T_D_N", VALE=(0.0, 0.0, 0.0)),
    _F(GROUP_MA="P2", CARA="M_T_D_N", VALE=1.0),
    _F(GROUP_MA="P2", CARA="K_T_D_N", VALE=(0.0, 0.0, 0.0)),
    _F(GROUP_MA="S23", CARA="M_T_D_L", VALE=0.0),
    _F(GROUP_MA="S23", CARA="K_T_D_L", VALE=(100.0, 100.0, 100.0)),
))
BLOCAGE = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=(
    _F(GROUP_NO=("N1", "N3"), DX=0.0, DY=0.0, DZ=0.0),
    _F(GROUP_NO="N2", DY=0.0, DZ=0.0),
))
RIGIELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION="RIGI_MECA")
MASSELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION="MASS_MECA")
NUMEROTA = NUME_DDL(MATR_RIGI=RIGIELEM)
RIGI = ASSE_MATRICE(MATR_ELEM=RIGIELEM, NUME_DDL=NUMEROTA)
MASS = ASSE_MATRICE(MATR_ELEM=MASSELEM, NUME_DDL=NUMEROTA)
MODES = CALC_MODES(MATR_RIGI=RIGI, MATR_MASS=MASS, OPTION="PLUS_PETITE",
                   CALC_FREQ=_F(NMAX_FREQ=1))
NUMEGE = NUME_DDL_GENE(BASE=MODES, STOCKAGE="DIAG")
MGEN = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=MASS)
KGEN = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=RIGI)
VITPHY = CREA_CHAMP(OPERATION="AFFE", TYPE_CHAM="NOEU_DEPL_R", MAILLAGE=MAIL,
    AFFE=_F(GROUP_NO="N2", NOM_CMP=("DX", "DY", "DZ"), VALE=(1.0, 0.0, 0.0)))
VITGEN = PROJ_VECT_BASE(BASE=MODES, VECT_ASSE=VITPHY, NUME_DDL_GENE=NUMEGE, TYPE_VECT="VITE")
OBS = DEFI_OBSTACLE(TYPE="PLAN_Y")
CHOC = _F(RELATION="DIS_CHOC", INTITULE="BUTEE", GROUP_NO_1="N2", OBSTACLE=OBS,
          ORIG_OBST=(0.1, 0.0, 0.0), NORM_OBST=(1.0, 0.0, 0.0), JEU=1.0, RIGI_NOR=1.0e4)
VISC = _F(RELATION="DIS_VISC", GROUP_NO_1="N1", GROUP_NO_2="N2",
          K1=120.0, K2=10.0, K3=60.0, C=1.7, PUIS_ALPHA=0.5)
COURBE = DEFI_FONCTION(NOM_PARA="DX", VALE=(0.0, 0.0, 0.01, 1.0, 0.02, 1.5, 10.0, 5.0))
ECRO = _F(RELATION="DIS_ECRO_TRAC", GROUP_NO_1="N1", GROUP_NO_2="N2", FX=COURBE)
COMMON = dict(TYPE_CALCUL="TRAN", BASE_CALCUL="GENE", MATR_MASS=MGEN, MATR_RIGI=KGEN,
              SCHEMA_TEMPS=_F(SCHEMA="DIFF_CENTRE"), ARCHIVAGE=_F(PAS_ARCH=10),
              COMPORTEMENT=(CHOC, VISC, ECRO))
R1 = DYNA_VIBRA(INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.2, PAS=1.0e-3),
    ETAT_INIT=_F(VITE=VITGEN), IMPRESSION=_F(UNITE_DIS_VISC=35, UNITE_DIS_ECRO_TRAC=36),
    **COMMON)
R2 = DYNA_VIBRA(INCREMENT=_F(INST_INIT=0.2, INST_FIN=0.4, PAS=1.0e-3),
    ETAT_INIT=_F(RESULTAT=R1), IMPRESSION=_F(UNITE_DIS_VISC=35), **COMMON)
R3 = DYNA_VIBRA(INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.2, PAS=1.0e-3),
    ETAT_INIT=_F(VITE=VITGEN), IMPRESSION=_F(NIVEAU="DEPL_LOC", INST_INIT=0.05,
    INST_FIN=0.1), **COMMON)
FORCE_B = LIRE_FONCTION(UNITE=35, NOM_PARA="INST", NOM_RESU="FORCE", INDIC_PARA=[2, 1],
                        INDIC_RESU=[2, 2])
FIN()
"""


@pytest.fixture(scope="module")
def deck_run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("impression")
    (folder / "d.mail").write_text(MESH)
    (folder / "d.comm").write_text(DECK)
    export = folder / "d.export"
    export.write_text("P time_limit 600\nF comm d.comm D 1\nF mail d.mail D 20\n")
    out = folder / "out"
    session = Session(describe_run(export), output_dir=out)
    session.run_all()
    return session, out


def file_blocks(path: Path):
    return [np.array(b) for b in numeric_blocks(path.read_text())]


def test_deck_history_is_the_archived_internal_variables(deck_run):
    session, out = deck_run
    r1, r2 = session.namespace["R1"], session.namespace["R2"]
    visc_1, visc_2 = file_blocks(out / "fort.35")
    (ecro_1,) = file_blocks(out / "fort.36")
    for block, result in ((visc_1, r1), (visc_2, r2)):
        fields = result.shocks[1].fields  # the DIS_VISC, second nonlinearity
        expected = np.column_stack([result.times] + [fields[f"VINT{i}"] for i in (8, 9, 10, 11)])
        assert block.shape == (21, 5)
        assert np.allclose(block, expected, rtol=1e-10, atol=1e-300)
    fields = r1.shocks[2].fields
    assert np.allclose(ecro_1[:, 1], fields["FX"], rtol=1e-10)
    assert np.allclose(ecro_1[:, 2], fields["DX"], rtol=1e-10)
    assert np.allclose(ecro_1[:, 7], fields["DISSIP"], rtol=1e-10)
    assert np.any(fields["DISSIP"] > 0.0)  # the curve was yielded: a real history
    # LIRE_FONCTION INDIC_PARA=[2, 1] reads the second run
    force_b = session.namespace["FORCE_B"]
    assert np.allclose(force_b.abscissas, r2.times)
    assert np.allclose(force_b.ordinates, r2.shocks[1].fields["FORCE"], rtol=1e-10)
    text = (out / "fort.35").read_text()
    assert "#RESULTAT R1" in text and "#RESULTAT R2" in text
    assert "#DIS_VISC     2 N1       N2" in text


def test_deck_niveau_lists_in_the_message_log(deck_run):
    session, _ = deck_run
    log = session.messages
    start = log.index("  ***** shock results (DYNA_VIBRA/IMPRESSION) *****")
    rows = [m for m in log[start:] if m.split() and m.split()[0].isdigit()]
    r3 = session.namespace["R3"]
    assert [int(r.split()[0]) for r in rows] == list(range(6, 12))  # t = 0.05 .. 0.1
    dxloc = float(rows[0].split()[2].replace("D", "E"))
    assert dxloc == pytest.approx(r3.shocks[0].fields["DXLOC"][5], rel=1e-9)


def test_unit_and_listing_keywords_exclude_each_other(tmp_path):
    """UNITE_DIS_VISC with NIVEAU is a catalogue error (PRESENT_ABSENT)."""
    (tmp_path / "d.mail").write_text(MESH)
    bad = DECK.replace(
        "IMPRESSION=_F(UNITE_DIS_VISC=35), **COMMON",
        'IMPRESSION=_F(UNITE_DIS_VISC=35, NIVEAU="DEPL_LOC"), **COMMON',
    )
    (tmp_path / "d.comm").write_text(bad)
    export = tmp_path / "d.export"
    export.write_text("F comm d.comm D 1\nF mail d.mail D 20\n")
    report = run_deck(export, check_only=True)
    assert report.status == "ERROR" and "IMPRESSION" in report.message
