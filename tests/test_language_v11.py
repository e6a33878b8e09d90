"""The language of code_aster 10-12: the old catalogue layout (one Python 2
``cata.py``, or ``catapy/`` pieces) read without executing it, on small
catalogues written here, and the committed ``v11.json`` reproduced from its
snapshot when that snapshot is on this machine."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from asterlite.catalog.language.generate import dumps
from asterlite.catalog.language.legacy_layout import (
    generate_legacy,
    merge_older,
    python3,
    read_catalogue,
)
from asterlite.catalog.language.model import data_version, language
from asterlite.runtime.check_deck import check_deck

HEADER = """#& MODIF ENTETE  DATE 01/01/2011   AUTEUR X
from Accas import *
import ops
JdC = JDC_CATA(code='ASTER', regles=(AU_MOINS_UN('DEBUT', 'POURSUITE'),))
class no(GEOM): pass
class grno(GEOM): pass
class maillage_sdaster(ASSD):
   def check(self):
      if len(self.x) <> 2:
         print "python 2"
class table_sdaster(ASSD): pass
class table_fonction(table_sdaster): pass
class post_comp(object): pass
"""
COMMON = """#& MODIF COMMUN  DATE 01/01/2011   AUTEUR X
def C_CHAMPS(typ=None):
  import types
  every = ["DEPL", "SIEF_ELGA", "VARI_ELGA"]
  if type(typ) == types.StringType:
    typ = [typ]
  return tuple(c for c in every if typ is None or c.split('_')[-1] in typ)
"""
COMMAND = """#& MODIF COMMANDE  DATE 01/01/2011   AUTEUR X
def lire_prod(FORMAT, **args):
  if FORMAT == 'TABLE': return table_fonction
  raise AsException("type de concept resultat non prevu")

LIRE_TRUC=OPER(nom="LIRE_TRUC", op=ops.build_truc, sd_prod=lire_prod, reentrant='f',
   fr="aide", regles=(UN_PARMI('NOEUD', 'GROUP_NO'), DERIVABLE('NOEUD'),),
   FORMAT=SIMP(statut='o', typ='TXM', into=("TABLE", "MAIL")),
   NOEUD=SIMP(statut='f', typ=no, max='**'),
   GROUP_NO=SIMP(statut='f', typ=grno, max=01),
   CHAMP=SIMP(statut='f', typ='TXM', into=C_CHAMPS('ELGA')),
   OPTION=SIMP(statut='f', typ='TXM', max='**'),
   b_table=BLOC(condition="FORMAT <> 'MAIL' and NOEUD != None",
      PRECISION=SIMP(statut='f', typ='R', defaut=1.E-6, val_min=0.),
   ),
   b_option=BLOC(condition="au_moins_un(OPTION, ('A', 'B'))",
      SEUIL=SIMP(statut='o', typ='R'),
   ),
   CODE=FACT("nom de l'etude", statut='f', min=01,
      NOM=SIMP(statut='o', typ='TXM'),
   ),
   LISTE=SIMP(statut='c', typ='TXM', defaut=("A", "B", "C")),
)
DEBUT=MACRO(nom="DEBUT", op=OPS("ops.build_debut"), sd_prod=ops.DEBUT,
   PAR_LOT=SIMP(statut='f', typ='TXM', defaut="OUI", into=("OUI", "NON")),
)
"""
CATA = HEADER + COMMON + COMMAND


def test_python2_spellings_rewritten_outside_strings():
    assert python3("a <> b") == "a != b"
    assert python3("f(min=01, max=010, n=10L)") == "f(min=1, max=8, n=10)"
    assert python3("x = '<> 01'  # 07") == "x = '<> 01'  # 07"
    assert python3("y = 0.5 + 1.E-6 + 0") == "y = 0.5 + 1.E-6 + 0"


def test_old_catalogue_read_as_data():
    data, problems = generate_legacy(CATA, 11, {"file": "cata.py"})
    assert problems == []
    header = data["header"]
    assert header["version"] == 11
    assert header["types"]["table_fonction"] == ["table_sdaster"]
    assert header["types"]["maillage_sdaster"] == ["assd"]
    assert header["types"]["no"] == ["GEOM"]
    assert "post_comp" not in header["types"]  # not a concept type
    command = data["commands"]["LIRE_TRUC"]
    assert command["kind"] == "OPER" and command["reentrant"] == "f"
    # the sensitivity rule names how derived concepts are made: not kept
    assert command["rules"] == [["UN_PARMI", "NOEUD", "GROUP_NO"]]
    entries = command["entries"]
    assert entries["GROUP_NO"] == {"k": "S", "typ": ["grno"], "max": 1}
    assert entries["CHAMP"]["into"] == ["SIEF_ELGA", "VARI_ELGA"]
    assert entries["CODE"]["min"] == 1 and "NOM" in entries["CODE"]["entries"]
    # a keyword not given was None in old Accas's conditions
    condition = entries["b_table"]["condition"]
    assert condition == [
        "and",
        ["cmp", ["kv", "FORMAT"], ["!=", ["c", "MAIL"]]],
        ["cmp", ["kv", "NOEUD"], ["!=", ["c", None]]],
    ]
    assert entries["b_option"]["condition"] == [
        "call",
        "is_in",
        ["c", "OPTION"],
        ["tuple", ["c", "A"], ["c", "B"]],
    ]
    assert command["sd_prod"]["types"] == ["table_fonction"]
    assert "sd_prod" not in data["commands"]["DEBUT"]  # a supervisor function
    # facts only: no help text anywhere
    text = dumps(data)
    assert "aide" not in text and "etude" not in text and "python 2" not in text


def test_same_bytes_each_time():
    first = dumps(generate_legacy(CATA, 11, {"file": "cata.py"})[0])
    second = dumps(generate_legacy(CATA, 11, {"file": "cata.py"})[0])
    assert first == second


def test_catapy_folder_and_types_module(tmp_path):
    # code_aster's own layout: catapy/{entete,commun,commande}/*.capy, the
    # header's accas.capy first; concept types in bibpyt/SD/co_*.py (code_aster 10)
    (tmp_path / "catapy/entete").mkdir(parents=True)
    (tmp_path / "catapy/commun").mkdir()
    (tmp_path / "catapy/commande").mkdir()
    (tmp_path / "bibpyt/SD").mkdir(parents=True)
    (tmp_path / "catapy/entete/accas.capy").write_text(HEADER.replace("class table", "#"))
    (tmp_path / "catapy/entete/co_zz.capy").write_text("#& MODIF ENTETE\nclass zz(ASSD): pass\n")
    (tmp_path / "catapy/commun/c_champs.capy").write_text(COMMON)
    (tmp_path / "catapy/commande/lire_truc.capy").write_text(COMMAND)
    (tmp_path / "bibpyt/SD/co_table.py").write_text(
        "from SD import *\nclass table_sdaster(ASSD, sd_table):\n    def f(self): print 'x'\n"
        "class table_fonction(table_sdaster): pass\n"
    )
    text, where, types = read_catalogue(tmp_path, 11)
    assert where == {"catalogues": "catapy"}
    assert text.index("JDC_CATA") < text.index("class zz") < text.index("def C_CHAMPS")
    data, problems = generate_legacy(text, 11, where, types)
    assert problems == []
    assert data["header"]["types"]["table_fonction"] == ["table_sdaster"]
    assert data["header"]["types"]["zz"] == ["assd"]
    assert data["commands"]["LIRE_TRUC"]["sd_prod"]["types"] == ["table_fonction"]


def test_older_catalogue_names_kept_as_legacy():
    older, _ = generate_legacy(
        CATA.replace("CHAMP=SIMP", "CHAMP_OLD=SIMP")
        + "ANCIEN=PROC(nom='ANCIEN', op=1, X=SIMP(statut='o', typ='R'))\n",
        10,
        {"file": "old.py"},
    )
    data, _ = generate_legacy(CATA, 11, {"file": "cata.py"})
    merged = merge_older(data, older, "10")
    assert merged["commands"]["LIRE_TRUC"]["legacy"] == ["CHAMP_OLD"]
    assert merged["commands"]["ANCIEN"]["older"] == "10"
    assert merged["header"]["older"] == [{"version": "10", "file": "old.py"}]


def test_versions_10_and_11_read_with_11():
    assert language(11) is not None
    assert data_version(10) == data_version(11) == 11
    assert data_version(12) is None  # no catalogue of the snapshot fits its decks
    assert data_version(13) == 15 and data_version(16) == 17


def test_v11_data_has_the_old_commands():
    lang = language(11)
    for name in ("DYNA_TRAN_MODAL", "DYNA_LINE_TRAN", "DYNA_LINE_HARM", "MACRO_PROJ_BASE"):
        assert lang.command(name) is not None, name
    choc = lang.command("DYNA_TRAN_MODAL")["entries"]["CHOC"]["entries"]
    assert choc["OBSTACLE"]["typ"] == ["table_fonction"]


def test_v11_deck_misspelt_keyword_is_invalid(tmp_path):
    path = tmp_path / "d.comm"
    path.write_text(
        "DEBUT()\n"
        "M = LIRE_MAILLAGE()\n"
        "P = MACRO_PROJ_BASE(BASE=M, NB_VECTT=2)\n"
        "TEST_RESU(RESU=_F(RESULTAT=M, NUME_ORDRE=1, NOM_CHAM='DEPL', VALE=1.0))\n"
        "FIN()\n"
    )
    check = check_deck(path)
    invalid = [(f.kind, f.keyword) for f in check.findings if f.kind == "invalid"]
    assert ("invalid", "MACRO_PROJ_BASE/NB_VECTT") in invalid
    message = next(f.message for f in check.findings if f.keyword == "MACRO_PROJ_BASE/NB_VECTT")
    assert "did you mean NB_VECT?" in message


CORPUS_V11 = Path(__file__).resolve().parents[2] / "shared" / "aster-corpus-v11"
CORPUS_V11_DECKS = (
    sorted(p.name for p in CORPUS_V11.iterdir() if p.is_dir()) if CORPUS_V11.is_dir() else []
)


@pytest.mark.skipif(not CORPUS_V11.is_dir(), reason="shared/aster-corpus-v11 absent")
@pytest.mark.parametrize(
    "name",
    sorted(p.name for p in CORPUS_V11.iterdir() if p.is_dir()) if CORPUS_V11.is_dir() else [],
)
def test_corpus_v11_decks_are_valid_code_aster_11(name):
    check = check_deck(CORPUS_V11 / name / f"{name}.export")
    assert check.version == 11 and check.language == 11
    assert check.status in ("VALID", "UNSUPPORTED"), [f.message for f in check.findings]


EFICAS = Path("/work/.mirror/SalomePlatform+eficas_tools/repo")


@pytest.mark.skipif(
    not EFICAS.is_dir() or shutil.which("git") is None, reason="the snapshot is not fetched here"
)
def test_committed_v11_reproduced_from_its_snapshot(tmp_path):
    committed = _data_file(11)
    header = json.loads(committed.read_text().split("\n", 2)[1].removeprefix('"header": ')[:-1])
    out = tmp_path / "v11.json"
    older = [f"{o['version']}:{o['commit']}:{o['catalogues']}" for o in header["older"]]
    subprocess.run(
        [
            "python3",
            "-m",
            "asterlite.catalog.language.generate",
            str(EFICAS),
            "--version",
            "11",
            "--commit",
            header["source"]["commit"],
            "--catalogue",
            header["source"]["catalogues"],
            *[arg for given in older for arg in ("--older", given)],
            "--output",
            str(out),
        ],
        check=True,
        capture_output=True,
    )
    assert out.read_bytes() == committed.read_bytes()


def _data_file(version: int) -> Path:
    import asterlite.catalogues.language as package

    return Path(package.__path__[0]) / f"v{version}.json"


def test_old_defaults_read_from_the_data():
    from asterlite.legacy.language_data import old_default

    assert old_default("MODE_ITER_SIMULT", "CALC_FREQ", "OPTION") == "PLUS_PETITE"
    assert old_default("MODE_ITER_INV", "CALC_FREQ", "OPTION") == "AJUSTE"
    assert old_default("PROJ_VECT_BASE", "TYPE_VECT") == "FORC"
    assert old_default("DYNA_TRAN_MODAL", "PARA_LAME_FLUI", "RESI_RELA") == 1.0e-3
    with pytest.raises(LookupError):
        old_default("DYNA_TRAN_MODAL", "PARA_LAME_FLUI", "NO_SUCH")
    with pytest.raises(LookupError):  # only PARA_LAME_FLUI's and SOLVEUR's in 11
        old_default("DYNA_TRAN_MODAL", "NMAX_ITER")


def test_command_removed_after_12_refused_by_name(tmp_path):
    from asterlite.runtime.runner import run_deck

    (tmp_path / "d.comm").write_text("DEBUT()\nT = CALC_NO(RESULTAT=None)\nFIN()\n")
    report = run_deck(tmp_path / "d.comm", tmp_path / "out")
    assert report.status == "UNSUPPORTED"
    assert "CALC_NO is a code_aster 10-12 command that code_aster 15 and 17" in (report.message)
