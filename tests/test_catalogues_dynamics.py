"""The dynamics, function, table and test catalogues against the corpus and against mistakes.

Every call of these commands in the corpus decks is extracted with Python's
``ast`` module (literal values kept, ``_F``/``CO`` rebuilt, anything computed
replaced by ``Unknown`` as ``asterlite check`` does) and must validate. Then
typical mistakes (misspelled keyword, value outside its choices, missing
mandatory keyword, broken rule, keyword out of its block) must be rejected
with the keyword path in the message.
"""

from __future__ import annotations

import ast
from collections import Counter
from pathlib import Path

import pytest

from asterlite.catalog import load_catalogue, result_type, validate
from asterlite.concepts.base import Placeholder
from asterlite.errors import ValidationError
from asterlite.lang.values import CO, FactorDict, Unknown

from .conftest import CORPUS

COMMANDS = (
    "DEFI_OBSTACLE", "DYNA_VIBRA", "DEFI_FONCTION", "DEFI_CONSTANTE", "DEFI_LIST_REEL",
    "DEFI_LIST_ENTI", "FORMULE", "CALC_FONC_INTERP", "LIRE_FONCTION", "CALC_FONCTION",
    "INFO_FONCTION", "IMPR_FONCTION", "REST_GENE_PHYS", "RECU_FONCTION", "RECU_GENE",
    "EXTR_RESU", "POST_GENE_PHYS", "POST_RELEVE_T", "POST_DYNA_MODA_T", "POST_USURE",
    "POST_RCCM", "CREA_TABLE", "CALC_TABLE", "RECU_TABLE", "IMPR_TABLE", "IMPR_RESU",
    "IMPR_GENE", "TEST_RESU", "TEST_TABLE", "TEST_FONCTION",
)  # fmt: skip


# --- extracting the corpus calls ---------------------------------------------------------


def _value(node: ast.AST):
    """A literal deck value as the evaluator would build it; Unknown when computed."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        if node.func.id == "_F" and not node.args:
            return FactorDict({k.arg: _value(k.value) for k in node.keywords if k.arg})
        if node.func.id == "CO" and len(node.args) == 1:
            name = node.args[0]
            if isinstance(name, ast.Constant) and isinstance(name.value, str):
                return CO(name.value)
        return Unknown
    if isinstance(node, ast.Tuple):
        return tuple(_value(e) for e in node.elts)
    if isinstance(node, ast.List):
        return [_value(e) for e in node.elts]
    try:
        return ast.literal_eval(node)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return Unknown


def corpus_files() -> list[Path]:
    if not CORPUS.is_dir():
        return []
    return sorted(list(CORPUS.glob("*/*.comm")) + list(CORPUS.glob("*/*.com1")))


def corpus_calls(path: Path):
    """(command, line, kwargs) for each call of the catalogued commands in a deck.

    Calls with a ``**mapping`` argument are skipped: their keywords are not known
    without running the deck.
    """
    tree = ast.parse(path.read_text(encoding="utf-8", errors="replace"), filename=str(path))
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)):
            continue
        if node.func.id not in COMMANDS or any(k.arg is None for k in node.keywords):
            continue
        yield node.func.id, node.lineno, {k.arg: _value(k.value) for k in node.keywords}


def declared_keywords(catalogue) -> set[str]:
    names = set(catalogue.keywords)
    for bloc in catalogue.blocs.values():
        names |= declared_keywords(bloc)
    return names


def check_call(command: str, kwargs: dict):
    catalogue = load_catalogue(command)
    if getattr(catalogue, "extra_keywords", False):
        # FORMULE: keywords besides VALE/VALE_C/NOM_PARA name the expression's context
        known = declared_keywords(catalogue) | {"reuse"}
        kwargs = {k: v for k, v in kwargs.items() if k in known}
    return validate(catalogue, kwargs)


@pytest.mark.corpus
@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.name)
def test_corpus_calls_validate(path: Path):
    errors = []
    for command, line, kwargs in corpus_calls(path):
        try:
            check_call(command, kwargs)
        except ValidationError as error:
            errors.append(f"{path.name}:{line}: {error}")
    assert not errors, "\n".join(errors)


@pytest.mark.corpus
def test_corpus_coverage():
    """The corpus exercises (nearly) every catalogue here; report the counts."""
    if not CORPUS.is_dir():
        pytest.skip("../shared/aster-corpus is not available")
    counts = Counter(command for path in corpus_files() for command, _, _ in corpus_calls(path))
    assert counts["DYNA_VIBRA"] >= 100
    assert counts["TEST_RESU"] >= 300
    assert set(COMMANDS) - set(counts) <= {"IMPR_GENE"}


def test_every_catalogue_loads():
    for command in COMMANDS:
        catalogue = load_catalogue(command)
        assert catalogue is not None and catalogue.nom == command


# --- a typical DIS_CHOC transient, to mutate -------------------------------------------


#: broader code_aster types a concept of the key type also satisfies (as the concepts declare)
BROADER = {
    "dyna_trans": ("resultat_sdaster",),
    "mode_meca": ("resultat_sdaster",),
    "evol_elas": ("resultat_sdaster",),
    "table_fonction": ("table_sdaster",),
}


def gene(type_name: str) -> Placeholder:
    """A stand-in concept of ``type_name`` (and its broader types, like the real concepts)."""
    concept = Placeholder(type_name)
    concept.aster_types = (type_name, *BROADER.get(type_name, ()))
    return concept


def dyna_vibra_call(**changes) -> dict:
    call = dict(
        TYPE_CALCUL="TRAN",
        BASE_CALCUL="GENE",
        MATR_MASS=gene("matr_asse_gene_r"),
        MATR_RIGI=gene("matr_asse_gene_r"),
        AMOR_MODAL=FactorDict(AMOR_REDUIT=(0.01, 0.02)),
        SCHEMA_TEMPS=FactorDict(SCHEMA="DIFF_CENTRE"),
        INCREMENT=FactorDict(INST_INIT=0.0, INST_FIN=1.0, PAS=1.0e-4),
        ARCHIVAGE=FactorDict(PAS_ARCH=10),
        EXCIT=FactorDict(VECT_ASSE_GENE=gene("vect_asse_gene"), FONC_MULT=gene("formule")),
        COMPORTEMENT=FactorDict(
            RELATION="DIS_CHOC",
            GROUP_NO_1="NO2",
            OBSTACLE=gene("table_fonction"),
            NORM_OBST=(0.0, 0.0, 1.0),
            ORIG_OBST=(1.0, 0.0, 0.0),
            JEU=1.0e-3,
            RIGI_NOR=1.0e6,
            AMOR_NOR=10.0,
            FROTTEMENT="COULOMB",
            COULOMB=0.3,
            RIGI_TAN=1.0e5,
        ),
    )
    call.update(changes)
    return call


def reject(command: str, kwargs: dict) -> ValidationError:
    with pytest.raises(ValidationError) as info:
        validate(load_catalogue(command), kwargs)
    return info.value


def test_dis_choc_transient_validates_with_code_aster_defaults():
    kw = validate(load_catalogue("DYNA_VIBRA"), dyna_vibra_call())
    assert result_type(load_catalogue("DYNA_VIBRA"), kw) == "tran_gene"
    shock = kw["COMPORTEMENT"][0]
    assert shock["UNIDIRECTIONNEL"] == "NON"
    assert shock["REPERE"] == "GLOBAL"
    assert shock["NORM_OBST"] == (0.0, 0.0, 1.0)
    assert kw["TRAITEMENT_NONL"] == "EXPLICITE"
    assert kw["VITE_ROTA"] == 0.0
    assert kw["INCREMENT"][0]["VERI_PAS"] == "OUI"


def test_default_scheme_of_a_gene_transient_is_runge_kutta_32():
    call = dyna_vibra_call()
    del call["SCHEMA_TEMPS"]
    kw = validate(load_catalogue("DYNA_VIBRA"), call)
    schema = kw["SCHEMA_TEMPS"][0]
    assert schema["SCHEMA"] == "RUNGE_KUTTA_32"
    assert schema["TOLERANCE"] == 1.0e-5
    assert schema["NMAX_ITER_PAS"] == 16


def test_default_scheme_of_a_phys_transient_is_newmark():
    kw = validate(
        load_catalogue("DYNA_VIBRA"),
        dict(
            TYPE_CALCUL="TRAN",
            BASE_CALCUL="PHYS",
            MATR_MASS=gene("matr_asse_depl_r"),
            MATR_RIGI=gene("matr_asse_depl_r"),
            INCREMENT=FactorDict(PAS=1.0e-3, INST_FIN=1.0),
            EXCIT=FactorDict(CHARGE=gene("char_meca"), FONC_MULT=gene("fonction_sdaster")),
        ),
    )
    schema = kw["SCHEMA_TEMPS"][0]
    assert (schema["SCHEMA"], schema["BETA"], schema["GAMMA"]) == ("NEWMARK", 0.25, 0.5)
    assert result_type(load_catalogue("DYNA_VIBRA"), kw) == "dyna_trans"


@pytest.mark.parametrize(
    "scheme, parameter, default",
    [
        ("ADAPT_ORDRE2", "VITE_MIN", "NORM"),
        ("ADAPT_ORDRE1", "COEF_DIVI_PAS", 1.3333334),
        ("RUNGE_KUTTA_54", "TOLERANCE", 1.0e-5),
        ("DEVOGE", "ALPHA", 0.0),
        ("NEWMARK", "GAMMA", 0.5),
    ],
)
def test_scheme_parameters(scheme, parameter, default):
    call = dyna_vibra_call(SCHEMA_TEMPS=FactorDict(SCHEMA=scheme))
    schema = validate(load_catalogue("DYNA_VIBRA"), call)["SCHEMA_TEMPS"][0]
    assert schema[parameter] == default


def test_misspelled_comportement_keyword():
    call = dyna_vibra_call()
    call["COMPORTEMENT"] = FactorDict(call["COMPORTEMENT"])
    call["COMPORTEMENT"]["RIGI_NORM"] = call["COMPORTEMENT"].pop("RIGI_NOR")
    error = reject("DYNA_VIBRA", call)
    assert error.path == "DYNA_VIBRA/COMPORTEMENT[1]/RIGI_NORM"
    assert "RIGI_NOR?" in str(error)


def test_scheme_outside_its_choices():
    error = reject("DYNA_VIBRA", dyna_vibra_call(SCHEMA_TEMPS=FactorDict(SCHEMA="DIFF_CENTRAL")))
    assert error.path == "DYNA_VIBRA/SCHEMA_TEMPS[1]/SCHEMA"
    assert "did you mean 'DIFF_CENTRE'" in str(error)


def test_relation_outside_its_choices():
    call = dyna_vibra_call(COMPORTEMENT=FactorDict(RELATION="DIS_CHOQ", GROUP_NO_1="N"))
    error = reject("DYNA_VIBRA", call)
    assert error.path == "DYNA_VIBRA/COMPORTEMENT[1]/RELATION"
    assert "DIS_CHOC" in str(error)


def test_missing_mandatory_increment():
    call = dyna_vibra_call()
    del call["INCREMENT"]
    error = reject("DYNA_VIBRA", call)
    assert "INCREMENT" in error.path and "missing mandatory" in str(error)


def test_missing_normal_of_the_obstacle():
    call = dyna_vibra_call()
    call["COMPORTEMENT"] = FactorDict(call["COMPORTEMENT"])
    del call["COMPORTEMENT"]["NORM_OBST"]
    error = reject("DYNA_VIBRA", call)
    assert error.path == "DYNA_VIBRA/COMPORTEMENT[1]/NORM_OBST"


def test_coulomb_required_by_friction():
    call = dyna_vibra_call()
    call["COMPORTEMENT"] = FactorDict(call["COMPORTEMENT"])
    del call["COMPORTEMENT"]["COULOMB"]
    error = reject("DYNA_VIBRA", call)
    assert error.path == "DYNA_VIBRA/COMPORTEMENT[1]/COULOMB"
    assert "FROTTEMENT" in str(error)


def test_coulomb_out_of_place_without_friction():
    call = dyna_vibra_call()
    call["COMPORTEMENT"] = FactorDict(call["COMPORTEMENT"], FROTTEMENT="NON")
    error = reject("DYNA_VIBRA", call)
    assert error.path == "DYNA_VIBRA/COMPORTEMENT[1]/COULOMB"
    assert "only with" in str(error)


def test_step_and_list_of_instants_exclude_each_other():
    increment = FactorDict(PAS=1.0e-4, INST_FIN=1.0, LIST_INST=gene("listr8_sdaster"))
    error = reject("DYNA_VIBRA", dyna_vibra_call(INCREMENT=increment))
    assert error.path.startswith("DYNA_VIBRA/INCREMENT[1]")
    assert "UN_PARMI" in str(error)


def test_modal_damping_excludes_damping_matrix():
    error = reject("DYNA_VIBRA", dyna_vibra_call(MATR_AMOR=gene("matr_asse_gene_r")))
    assert "EXCLUS" in str(error) and "AMOR_MODAL" in str(error)


def test_gene_matrices_have_the_right_type():
    error = reject("DYNA_VIBRA", dyna_vibra_call(MATR_MASS=gene("matr_asse_depl_r")))
    assert error.path == "DYNA_VIBRA/MATR_MASS"


def test_every_relation_of_code_aster_17_is_catalogued():
    catalogue = load_catalogue("DYNA_VIBRA")
    comportement = catalogue.blocs["b_excit_tran_mod"].keywords["COMPORTEMENT"]
    assert set(comportement.keywords["RELATION"].into) == {
        "DIS_CHOC", "ROTOR_FISS", "FLAMBAGE", "ANTI_SISM", "DIS_VISC", "DIS_ECRO_TRAC",
        "CHOC_ELAS_TRAC", "RELA_EFFO_DEPL", "RELA_EFFO_VITE",
    }  # fmt: skip


def test_dis_visc_needs_one_stiffness_or_flexibility_per_branch():
    call = dyna_vibra_call(
        COMPORTEMENT=FactorDict(
            RELATION="DIS_VISC", GROUP_NO_1="A", GROUP_NO_2="B", K1=1.0, K2=1.0, C=1.0
        )
    )
    error = reject("DYNA_VIBRA", call)
    assert "K3" in str(error) and "UN_PARMI" in str(error)


# --- TEST_RESU / TEST_TABLE / TEST_FONCTION ------------------------------------------


def resu(**changes) -> dict:
    occurrence = FactorDict(
        RESULTAT=gene("dyna_trans"), NOM_CHAM="DEPL", NOM_CMP="DX", GROUP_NO="N2", INST=0.5,
        VALE_CALC=1.25e-3, REFERENCE="ANALYTIQUE", VALE_REFE=1.2e-3, PRECISION=0.05,
    )  # fmt: skip
    occurrence.update(changes)
    return dict(RESU=occurrence)


def test_test_resu_reference_and_defaults():
    kw = validate(load_catalogue("TEST_RESU"), resu())
    occurrence = kw["RESU"][0]
    assert occurrence["VALE_CALC"] == (1.25e-3,)
    assert occurrence["VALE_REFE"] == (1.2e-3,)
    assert occurrence["PRECISION"] == 0.05
    assert occurrence["VALE_ABS"] == "NON"


def test_test_resu_misspelled_keyword():
    call = resu()
    call["RESU"]["VALE_CAL"] = call["RESU"].pop("VALE_CALC")
    error = reject("TEST_RESU", call)
    assert error.path == "TEST_RESU/RESU[1]/VALE_CAL"
    assert "VALE_CALC?" in str(error)


def test_test_resu_reference_outside_its_choices():
    error = reject("TEST_RESU", resu(REFERENCE="ANALYTIC"))
    assert error.path == "TEST_RESU/RESU[1]/REFERENCE"
    assert "ANALYTIQUE" in str(error)


def test_test_resu_needs_a_computed_value():
    call = resu()
    del call["RESU"]["VALE_CALC"]
    error = reject("TEST_RESU", call)
    assert error.path.startswith("TEST_RESU/RESU[1]") and "VALE_CALC" in str(error)


def test_test_resu_missing_result():
    call = resu()
    del call["RESU"]["RESULTAT"]
    error = reject("TEST_RESU", call)
    assert error.path == "TEST_RESU/RESU[1]/RESULTAT"


def test_test_resu_one_access_only():
    error = reject("TEST_RESU", resu(NUME_ORDRE=3))
    assert "UN_PARMI" in str(error) and "INST" in str(error)


def test_test_resu_precision_only_with_a_reference():
    call = resu()
    for name in ("REFERENCE", "VALE_REFE"):
        del call["RESU"][name]
    error = reject("TEST_RESU", call)
    assert error.path == "TEST_RESU/RESU[1]/PRECISION"


def test_test_resu_gene_of_a_transient():
    occurrence = FactorDict(
        RESU_GENE=gene("tran_gene"), NOM_CHAM="VITE", NUME_CMP_GENE=2, INST=0.1, VALE_CALC=0.5
    )
    kw = validate(load_catalogue("TEST_RESU"), dict(GENE=occurrence))
    assert kw["GENE"][0]["NUME_CMP_GENE"] == 2
    del occurrence["NOM_CHAM"]
    error = reject("TEST_RESU", dict(GENE=occurrence))
    assert error.path == "TEST_RESU/GENE[1]/NOM_CHAM"


def test_test_resu_nothing_to_test():
    error = reject("TEST_RESU", {})
    assert "AU_MOINS_UN" in str(error)


def test_test_table_and_test_fonction_defaults():
    kw = validate(
        load_catalogue("TEST_TABLE"),
        dict(
            TABLE=gene("table_sdaster"),
            NOM_PARA="F_MAX",
            FILTRE=FactorDict(NOM_PARA="NOEUD", VALE_K="N2"),
            VALE_CALC=12.5,
        ),
    )
    assert kw["CRITERE"] == "RELATIF" and kw["TOLE_MACHINE"] == 1.0e-6
    assert kw["FILTRE"][0]["CRIT_COMP"] == "EQ"
    kw = validate(
        load_catalogue("TEST_FONCTION"),
        dict(VALEUR=FactorDict(FONCTION=gene("fonction_sdaster"), VALE_PARA=0.5, VALE_CALC=1.0)),
    )
    assert kw["VALEUR"][0]["VALE_PARA"] == (0.5,)


# --- result types ------------------------------------------------------------------------


RESULT_TYPES = [
    ("DEFI_OBSTACLE", dict(TYPE="BI_PLAN_Z"), "table_fonction"),
    ("EXTR_RESU", dict(RESULTAT=gene("dyna_trans")), "dyna_trans"),
    ("EXTR_RESU", dict(RESULTAT=gene("evol_elas")), "evol_elas"),
    ("REST_GENE_PHYS", dict(RESU_GENE=gene("tran_gene")), "dyna_trans"),
    ("REST_GENE_PHYS", dict(RESU_GENE=gene("mode_gene")), "mode_meca"),
    ("REST_GENE_PHYS", dict(RESU_GENE=Unknown), "dyna_trans"),
    (
        "RECU_FONCTION",
        dict(RESU_GENE=gene("tran_gene"), NOM_CHAM="DEPL", NUME_CMP_GENE=1),
        "fonction_sdaster",
    ),
    (
        "RECU_FONCTION",
        dict(TABLE=gene("table_sdaster"), PARA_X="FREQ", PARA_Y="VALE_C"),
        "fonction_c",
    ),
    ("DEFI_FONCTION", dict(NOM_PARA="INST", VALE_C=(0.0, 1.0, 0.0, 1.0, 2.0, 0.0)), "fonction_c"),
    ("DEFI_FONCTION", dict(NOM_PARA="INST", VALE=(0.0, 1.0, 1.0, 2.0)), "fonction_sdaster"),
    (
        "CALC_FONCTION",
        dict(COMB=FactorDict(FONCTION=gene("nappe_sdaster"), COEF=2.0)),
        "nappe_sdaster",
    ),
    ("CALC_FONCTION", dict(FFT=FactorDict(FONCTION=gene("fonction_sdaster"))), "fonction_c"),
    (
        "CALC_FONCTION",
        dict(SPEC_OSCI=FactorDict(FONCTION=gene("fonction_sdaster"), NORME=9.81)),
        "nappe_sdaster",
    ),
    ("FORMULE", dict(VALE="2*INST", NOM_PARA="INST"), "formule"),
    (
        "LIRE_FONCTION",
        dict(UNITE=21, NOM_PARA="INST", TYPE="NAPPE", NOM_PARA_FONC="AMOR", INDIC_ABSCISSE=(1, 2)),
        "nappe_sdaster",
    ),
    ("CREA_TABLE", dict(LISTE=FactorDict(PARA="X", LISTE_R=(1.0, 2.0))), "table_sdaster"),
    (
        "POST_DYNA_MODA_T",
        dict(RESU_GENE=gene("tran_gene"), CHOC=FactorDict(OPTION="IMPACT")),
        "table_sdaster",
    ),
]


@pytest.mark.parametrize("command, kwargs, expected", RESULT_TYPES)
def test_result_types(command, kwargs, expected):
    catalogue = load_catalogue(command)
    assert result_type(catalogue, validate(catalogue, kwargs)) == expected


def test_formule_declares_its_extra_keywords():
    catalogue = load_catalogue("FORMULE")
    assert getattr(catalogue, "extra_keywords", False) is True
    assert set(catalogue.keyword_names()) == {"VALE", "VALE_C", "NOM_PARA"}
    kw = check_call("FORMULE", dict(VALE="F(INST)", NOM_PARA="INST", F=Unknown))
    assert kw["NOM_PARA"] == ("INST",) and "F" not in kw
