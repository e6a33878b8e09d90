"""Catalogues of the front-end commands (mesh, model, assembly, modes, projection).

Every call of these commands in the corpus decks is extracted with ``ast``
and validated against its catalogue; targeted tests then check type errors
with small fake concepts and that mistakes (misspelled keyword, value out of
``into``, missing mandatory keyword, broken rule) are rejected with the
keyword path.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from asterlite.catalog import load_catalogue, result_type, validate
from asterlite.concepts.base import Concept
from asterlite.errors import ValidationError
from asterlite.lang.values import CO, FactorDict, Unknown

CORPUS = Path("/work/shared/aster-corpus")

COMMANDS = (
    "DEBUT POURSUITE FIN LIRE_MAILLAGE DEFI_GROUP CREA_MAILLAGE MODI_MAILLAGE AFFE_MODELE "
    "AFFE_CARA_ELEM DEFI_MATERIAU AFFE_MATERIAU AFFE_CHAR_MECA AFFE_CHAR_MECA_F CALC_MATR_ELEM "
    "CALC_VECT_ELEM NUME_DDL ASSE_MATRICE ASSE_VECTEUR ASSEMBLAGE COMB_MATR_ASSE CREA_CHAMP "
    "MACRO_ELAS_MULT CALC_MODES NORM_MODE EXTR_MODE MODE_STATIQUE DEFI_BASE_MODALE "
    "CALC_CHAR_SEISME NUME_DDL_GENE PROJ_BASE PROJ_MATR_BASE PROJ_VECT_BASE CREA_RESU DYNA_LINE "
    "CALC_CHAMP POST_ELEM DETRUIRE DEFI_FICHIER IMPR_CO"
).split()


# --- turning deck source into validator input ------------------------------------------


def literal(node: ast.AST):
    """A deck expression as the evaluator would hand it to a command, or Unknown."""
    if isinstance(node, ast.Constant):
        return node.value
    if isinstance(node, (ast.Tuple, ast.List)):
        return tuple(literal(e) for e in node.elts)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        value = literal(node.operand)
        return -value if isinstance(value, (int, float)) else Unknown
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        if node.func.id == "_F":
            return FactorDict({k.arg: literal(k.value) for k in node.keywords if k.arg})
        if node.func.id == "CO" and node.args and isinstance(node.args[0], ast.Constant):
            return CO(node.args[0].value)
    return Unknown  # names, arithmetic, method calls: not computed by `asterlite check`


def corpus_calls():
    """(deck, line, command, kwargs) for every call of our commands in the corpus."""
    decks = sorted(CORPUS.glob("*/*.comm")) + sorted(CORPUS.glob("*/*.com1"))
    for deck in decks:
        tree = ast.parse(deck.read_text(encoding="utf-8", errors="replace"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
                if node.func.id in COMMANDS:
                    kwargs = {k.arg: literal(k.value) for k in node.keywords if k.arg}
                    yield deck, node.lineno, node.func.id, kwargs


CALLS = list(corpus_calls()) if CORPUS.is_dir() else []


def check(command: str, **kwargs):
    return validate(load_catalogue(command), kwargs)


# --- the corpus ------------------------------------------------------------------------


@pytest.mark.skipif(not CALLS, reason="corpus not available")
def test_every_corpus_call_validates():
    errors = []
    for deck, line, command, kwargs in CALLS:
        try:
            keywords = validate(load_catalogue(command), kwargs)
        except ValidationError as error:
            errors.append(f"{deck.name}:{line}: {error}")
            continue
        try:
            result_type(load_catalogue(command), keywords)
        except TypeError:
            pass  # an sd_prod that chooses by an input's type cannot tell from a name alone
        except ValidationError as error:
            errors.append(f"{deck.name}:{line}: {error}")
    assert not errors, f"{len(errors)} of {len(CALLS)} calls rejected:\n" + "\n".join(errors)


@pytest.mark.skipif(not CALLS, reason="corpus not available")
def test_corpus_uses_most_commands():
    used = {command for _, _, command, _ in CALLS}
    assert len(used) >= 30


@pytest.mark.parametrize("command", COMMANDS)
def test_catalogue_loads(command):
    catalogue = load_catalogue(command)
    assert catalogue is not None and catalogue.nom == command


# --- fake concepts for type checks -------------------------------------------------------


def concept(*types: str, name: str = "X") -> Concept:
    fake = type("Fake", (Concept,), {"aster_types": types})()
    fake.name = name
    return fake


MESH = concept("maillage_sdaster", name="MAIL")
MODEL = concept("modele_sdaster", name="MODELE")
RIGI = concept("matr_asse_depl_r", "matr_asse", name="RIGI")
MASS = concept("matr_asse_depl_r", "matr_asse", name="MASS")
MODES = concept("mode_meca", "resultat_sdaster", name="MODES")
NUMGEN = concept("nume_ddl_gene", name="NUMGEN")
KGEN = concept("matr_asse_gene_r", "matr_asse_gene", name="KGEN")
ELEM_HYST = concept("matr_elem_depl_c", name="KHYST")


def test_concept_of_wrong_type_is_rejected():
    with pytest.raises(ValidationError) as error:
        check(
            "AFFE_MODELE",
            MAILLAGE=MODEL,
            AFFE=FactorDict(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="DIS_T"),
        )
    assert error.value.path.endswith("MAILLAGE")
    assert "maillage_sdaster" in error.value.message


def test_matrix_type_checked_in_projection():
    with pytest.raises(ValidationError) as error:
        check("PROJ_MATR_BASE", BASE=MODES, NUME_DDL_GENE=NUMGEN, MATR_ASSE=MODES)
    assert error.value.path == "PROJ_MATR_BASE/MATR_ASSE"
    kw = check("PROJ_MATR_BASE", BASE=MODES, NUME_DDL_GENE=NUMGEN, MATR_ASSE=RIGI)
    assert result_type(load_catalogue("PROJ_MATR_BASE"), kw) == "matr_asse_gene_r"


def test_good_concepts_accepted_and_defaults_filled():
    kw = check(
        "CALC_MODES",
        MATR_RIGI=RIGI,
        MATR_MASS=MASS,
        OPTION="BANDE",
        CALC_FREQ=FactorDict(FREQ=(0.0, 10.0)),
    )
    assert kw["TYPE_RESU"] == "DYNAMIQUE"
    assert kw["CALC_FREQ"][0]["FREQ"] == (0.0, 10.0)
    assert kw["SOLVEUR_MODAL"][0]["METHODE"] == "SORENSEN"
    assert kw["VERI_MODE"][0]["STURM"] == "GLOBAL"
    assert result_type(load_catalogue("CALC_MODES"), kw) == "mode_meca"


def test_calc_modes_result_types():
    cata = load_catalogue("CALC_MODES")
    damped = check("CALC_MODES", MATR_RIGI=RIGI, MATR_MASS=MASS, MATR_AMOR=RIGI)
    assert result_type(cata, damped) == "mode_meca_c"
    gene = check("CALC_MODES", MATR_RIGI=KGEN, MATR_MASS=KGEN)
    assert result_type(cata, gene) == "mode_gene"


@pytest.mark.parametrize(
    ("type_cham", "expected"),
    [
        ("NOEU_DEPL_R", "cham_no_sdaster"),
        ("ELGA_SIEF_R", "cham_elem"),
        ("CART_NEUT_R", "carte_sdaster"),
    ],
)
def test_crea_champ_result_type(type_cham, expected):
    kw = check(
        "CREA_CHAMP",
        TYPE_CHAM=type_cham,
        OPERATION="AFFE",
        MAILLAGE=MESH,
        AFFE=FactorDict(TOUT="OUI", NOM_CMP="DX", VALE=0.0),
    )
    assert result_type(load_catalogue("CREA_CHAMP"), kw) == expected


def test_asse_matrice_follows_elementary_type():
    kw = check("ASSE_MATRICE", MATR_ELEM=ELEM_HYST, NUME_DDL=concept("nume_ddl_sdaster"))
    assert kw["MATR_ELEM"] == (ELEM_HYST,)
    assert result_type(load_catalogue("ASSE_MATRICE"), kw) == "matr_asse_depl_c"


def test_dyna_line_result_type():
    common = dict(
        BASE_CALCUL="GENE",
        MODELE=MODEL,
        INCREMENT=FactorDict(INST_FIN=1.0, PAS=1.0e-3),
        EXCIT=FactorDict(TYPE_APPUI="MONO", DIRECTION=(1.0, 0.0, 0.0), FONC_MULT=Unknown),
    )
    kw = check("DYNA_LINE", TYPE_CALCUL="TRAN", **common)
    assert kw["SCHEMA_TEMPS"][0]["SCHEMA"] == "DEVOGE"
    assert kw["ENRI_STAT"] == "OUI"
    assert result_type(load_catalogue("DYNA_LINE"), kw) == "dyna_trans"


def test_crea_resu_result_type():
    kw = check(
        "CREA_RESU",
        OPERATION="AFFE",
        TYPE_RESU="MULT_ELAS",
        AFFE=FactorDict(NOM_CHAM="DEPL", CHAM_GD=Unknown, NOM_CAS="CAS1"),
    )
    assert result_type(load_catalogue("CREA_RESU"), kw) == "mult_elas"


def test_outputs_through_co():
    kw = check(
        "ASSEMBLAGE",
        MODELE=MODEL,
        NUME_DDL=CO("NUME"),
        MATR_ASSE=(
            FactorDict(MATRICE=CO("RIGI"), OPTION="RIGI_MECA"),
            FactorDict(MATRICE=CO("MASS"), OPTION="MASS_MECA"),
        ),
    )
    assert [m["MATRICE"].name for m in kw["MATR_ASSE"]] == ["RIGI", "MASS"]
    assert kw["MATR_ASSE"][0]["MODE_FOURIER"] == 0
    with pytest.raises(ValidationError) as error:
        check("PROJ_BASE", BASE=MODES, MATR_ASSE_GENE=FactorDict(MATRICE=3, MATR_ASSE=RIGI))
    assert error.value.path == "PROJ_BASE/MATR_ASSE_GENE[1]/MATRICE"


def test_discrete_values_count_follows_cara():
    ok = FactorDict(CARA="K_T_D_N", GROUP_MA="P1", VALE=(1.0, 2.0, 3.0))
    check("AFFE_CARA_ELEM", MODELE=MODEL, DISCRET=ok)
    bad = FactorDict(CARA="K_TR_D_N", GROUP_MA="P1", VALE=(1.0, 2.0, 3.0))
    with pytest.raises(ValidationError) as error:
        check("AFFE_CARA_ELEM", MODELE=MODEL, DISCRET=bad)
    assert error.value.path.startswith("AFFE_CARA_ELEM/DISCRET[1]/VALE")


def test_deprecated_encastre_still_accepted():
    check("AFFE_CHAR_MECA", MODELE=MODEL, DDL_IMPO=FactorDict(GROUP_NO="A", LIAISON="ENCASTRE"))


# --- mutations: each mistake is rejected with its keyword path -----------------------------


def test_misspelled_keyword():
    with pytest.raises(ValidationError) as error:
        check("LIRE_MAILLAGE", FORMAT="MED", UNIT=20)
    assert error.value.path == "LIRE_MAILLAGE/UNIT"
    assert "UNITE" in error.value.message


def test_misspelled_keyword_in_factor():
    with pytest.raises(ValidationError) as error:
        check("DEBUT", CODE="OUI", ERREUR=FactorDict(ALARM="EXCEPTION"))
    assert error.value.path == "DEBUT/ERREUR[1]/ALARM"


def test_value_outside_into():
    with pytest.raises(ValidationError) as error:
        check(
            "AFFE_MODELE",
            MAILLAGE=MESH,
            AFFE=FactorDict(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="DIS_TX"),
        )
    assert error.value.path == "AFFE_MODELE/AFFE[1]/MODELISATION"


def test_missing_mandatory_keyword():
    with pytest.raises(ValidationError) as error:
        check("PROJ_VECT_BASE", BASE=MODES, NUME_DDL_GENE=NUMGEN, VECT_ASSE=Unknown)
    assert "TYPE_VECT" in error.value.path + error.value.message


def test_missing_mandatory_keyword_in_active_bloc():
    with pytest.raises(ValidationError) as error:
        check("CALC_MODES", MATR_MASS=MASS)
    assert "MATR_RIGI" in error.value.path + error.value.message


def test_violated_rule():
    with pytest.raises(ValidationError) as error:
        check("NUME_DDL_GENE", BASE=MODES, MODELE_GENE=Unknown)
    assert error.value.path.startswith("NUME_DDL_GENE")
    assert "UN_PARMI" in error.value.message


def test_violated_rule_in_factor():
    with pytest.raises(ValidationError) as error:
        check(
            "AFFE_MATERIAU", MAILLAGE=MESH, AFFE=FactorDict(TOUT="OUI", GROUP_MA="G", MATER=Unknown)
        )
    assert error.value.path == "AFFE_MATERIAU/AFFE[1]"


def test_keyword_of_inactive_bloc_rejected():
    with pytest.raises(ValidationError) as error:
        check("CALC_MATR_ELEM", OPTION="MASS_MECA", MODELE=MODEL, RIGI_MECA=Unknown)
    assert error.value.path == "CALC_MATR_ELEM/RIGI_MECA"


def test_reuse_required_for_in_place_commands():
    with pytest.raises(ValidationError, match="reuse= is mandatory"):
        check("MODI_MAILLAGE", MAILLAGE=MESH, ORIE_PEAU=FactorDict(GROUP_MA_PEAU="G"))
    # code_aster 17's DEFI_GROUP changes MAILLAGE in place with or without
    # reuse= (verification decks sdld102d/e call it bare)
    check("DEFI_GROUP", MAILLAGE=MESH, CREA_GROUP_MA=FactorDict(NOM="ALL", TOUT="OUI"))
    kw = validate(
        load_catalogue("DEFI_GROUP"),
        dict(MAILLAGE=MESH, CREA_GROUP_MA=FactorDict(NOM="ALL", TOUT="OUI")),
        reuse=MESH,
    )
    assert kw["CREA_GROUP_MA"][0]["TYPE_MAILLE"] == "TOUT"
