"""The catalogue vocabulary and the validator, on small catalogues defined here."""

from __future__ import annotations

import sys
import types

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    ENSEMBLE,
    EXCLUS,
    FACT,
    MACRO,
    OPER,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    PROC,
    SIMP,
    TOUT_OU_RIEN,
    UN_PARMI,
    Condition,
    Keywords,
    absent,
    equal_to,
    exists,
    greater_than,
    is_in,
    less_than,
    load_catalogue,
    result_type,
    validate,
)
from asterlite.concepts.base import Concept, Placeholder
from asterlite.errors import Location, ValidationError
from asterlite.lang.values import CO, CallSite, FactorDict, Unknown


class FakeConcept(Concept):
    def __init__(self, name: str, *aster_types: str):
        self.name = name
        self.aster_types = aster_types


MODES = FakeConcept("MODES", "mode_meca", "resultat_sdaster")
MATR = FakeConcept("MATR", "matr_asse_gene_r")


def simple(**simp_options) -> OPER:
    """A command with one simple keyword X."""
    return OPER(nom="CMD", sd_prod="table_sdaster", X=SIMP(**simp_options))


def error_of(catalogue, kwargs, **options) -> ValidationError:
    with pytest.raises(ValidationError) as caught:
        validate(catalogue, kwargs, **options)
    return caught.value


# --- statut ------------------------------------------------------------------------------


def test_mandatory_keyword_missing_names_it_and_the_call_location():
    site = CallSite(location=Location("deck.comm", 7))
    error = error_of(simple(statut="o", typ="R"), {}, site=site)
    assert error.message == "missing mandatory keyword X"
    assert error.path == "CMD/X"
    assert error.location == Location("deck.comm", 7)


def test_optional_keyword_absent_is_absent_and_given_is_kept():
    assert validate(simple(statut="f", typ="R"), {}) == {}
    assert validate(simple(statut="f", typ="R"), {"X": 2.0}) == {"X": 2.0}


def test_defaulted_keyword_is_filled_and_can_be_overridden():
    catalogue = simple(statut="d", typ="TXM", defaut="OUI", into=("OUI", "NON"))
    assert validate(catalogue, {}) == {"X": "OUI"}
    assert validate(catalogue, {"X": "NON"}) == {"X": "NON"}


def test_cached_statut_behaves_like_optional():
    assert validate(simple(statut="c", typ="I"), {}) == {}
    assert validate(simple(statut="c", typ="I"), {"X": 3}) == {"X": 3}


def test_none_and_empty_list_count_as_not_given():
    assert validate(simple(statut="f", typ="R", max="**"), {"X": None}) == {}
    assert validate(simple(statut="f", typ="R", max="**"), {"X": []}) == {}
    assert "missing" in error_of(simple(statut="o", typ="R"), {"X": None}).message


# --- types -------------------------------------------------------------------------------


def test_real_accepts_int_and_returns_float():
    value = validate(simple(typ="R"), {"X": 3})["X"]
    assert value == 3.0 and isinstance(value, float)


def test_real_rejects_text_saying_what_was_expected():
    error = error_of(simple(typ="R"), {"X": "abc"})
    assert error.message == "expected a real number (R), got text 'abc'"
    assert error.path == "CMD/X"


def test_real_rejects_logical():
    assert "got logical True" in error_of(simple(typ="R"), {"X": True}).message


def test_integer_accepts_integral_float_only():
    value = validate(simple(typ="I"), {"X": 4.0})["X"]
    assert value == 4 and isinstance(value, int)
    assert error_of(simple(typ="I"), {"X": 2.5}).message == "expected an integer (I), got real 2.5"


@pytest.mark.parametrize("typ", ["TXM", "TX"])
def test_text_types(typ):
    assert validate(simple(typ=typ), {"X": "abc"}) == {"X": "abc"}
    assert error_of(simple(typ=typ), {"X": 1}).message == f"expected a text ({typ}), got integer 1"


@pytest.mark.parametrize(
    ("given", "expected"),
    [(2, 2 + 0j), (1.5, 1.5 + 0j), (1 + 2j, 1 + 2j), (("RI", 1.0, -2.0), 1 - 2j)],
)
def test_complex_accepts_reals_and_old_notation(given, expected):
    assert validate(simple(typ="C"), {"X": given})["X"] == expected


def test_complex_modulus_phase_notation_uses_degrees():
    value = validate(simple(typ="C"), {"X": ("MP", 2.0, 90.0)})["X"]
    assert value == pytest.approx(2j)


def test_complex_list_of_old_notations():
    catalogue = simple(typ="C", max="**")
    value = validate(catalogue, {"X": (("RI", 1, 0), ("RI", 0, 1))})["X"]
    assert value == (1 + 0j, 1j)


def test_complex_rejects_text():
    assert error_of(simple(typ="C"), {"X": "i"}).message.startswith("expected a complex number (C)")


def test_logical():
    assert validate(simple(typ="L"), {"X": False}) == {"X": False}
    assert "expected a logical (L), got integer 0" == error_of(simple(typ="L"), {"X": 0}).message


def test_output_name_accepts_co_and_rejects_plain_text():
    co = CO("MATR")
    assert validate(simple(typ="CO"), {"X": co})["X"] is co
    assert error_of(simple(typ="CO"), {"X": "MATR"}).message == (
        "expected an output name CO(\"...\") (CO), got text 'MATR'"
    )


def test_concept_type_checked_with_satisfies():
    catalogue = simple(typ="resultat_sdaster")
    assert validate(catalogue, {"X": MODES})["X"] is MODES


def test_concept_of_wrong_type_names_its_type_and_name():
    error = error_of(simple(typ="matr_asse_gene_r"), {"X": MODES})
    assert error.message == "expected a concept of type matr_asse_gene_r, got mode_meca MODES"


def test_concept_type_rejects_plain_values():
    error = error_of(simple(typ="maillage_sdaster"), {"X": 1.5})
    assert error.message == "expected a concept of type maillage_sdaster, got real 1.5"


def test_placeholder_checked_by_its_declared_type():
    catalogue = simple(typ="matr_asse_gene_r")
    placeholder = Placeholder("matr_asse_gene_r", produced_by="ASSE_MATR_GENE")
    assert validate(catalogue, {"X": placeholder})["X"] is placeholder
    wrong = Placeholder("mode_meca")
    assert error_of(catalogue, {"X": wrong}).message.endswith("got a mode_meca")


def test_several_types_any_matches_and_the_message_lists_them():
    catalogue = simple(typ=("R", "fonction_sdaster", "nappe_sdaster"))
    assert validate(catalogue, {"X": 1})["X"] == 1.0
    function = FakeConcept("F", "fonction_sdaster")
    assert validate(catalogue, {"X": function})["X"] is function
    assert error_of(catalogue, {"X": MATR}).message == (
        "expected a real number (R) or a concept of type fonction_sdaster or nappe_sdaster,"
        " got matr_asse_gene_r MATR"
    )


# --- normalisation -----------------------------------------------------------------------


def test_single_value_in_a_list_is_unwrapped_for_max_1():
    assert validate(simple(typ="R"), {"X": [2.5]}) == {"X": 2.5}
    assert validate(simple(typ="TXM"), {"X": ("A",)}) == {"X": "A"}


def test_scalar_is_wrapped_for_max_above_1():
    assert validate(simple(typ="R", max="**"), {"X": 2}) == {"X": (2.0,)}
    assert validate(simple(typ="R", max=3), {"X": [1, 2]}) == {"X": (1.0, 2.0)}


def test_default_of_a_list_keyword_is_a_tuple():
    assert validate(simple(statut="d", typ="TXM", max="**", defaut="DEPL"), {}) == {"X": ("DEPL",)}


def test_numpy_scalars_become_python_numbers():
    real = validate(simple(typ="R"), {"X": np.float64(0.25)})["X"]
    integer = validate(simple(typ="I"), {"X": np.int64(7)})["X"]
    assert type(real) is float and real == 0.25
    assert type(integer) is int and integer == 7


def test_numpy_array_becomes_tuple_of_python_floats():
    value = validate(simple(typ="R", max="**"), {"X": np.linspace(0.0, 1.0, 3)})["X"]
    assert value == (0.0, 0.5, 1.0)
    assert all(type(v) is float for v in value)


def test_numpy_elements_inside_a_list():
    value = validate(simple(typ="R", max="**"), {"X": [np.float64(1.5), 2]})["X"]
    assert value == (1.5, 2.0) and all(type(v) is float for v in value)


def test_empty_numpy_array_counts_as_not_given():
    assert validate(simple(typ="R", max="**"), {"X": np.array([])}) == {}


@given(st.lists(st.floats(allow_nan=False, allow_infinity=False), min_size=1, max_size=20))
def test_real_lists_round_trip_as_tuples(values):
    assert validate(simple(typ="R", max="**"), {"X": values})["X"] == tuple(values)


# --- counts, into, bounds ----------------------------------------------------------------


def test_too_many_values():
    assert error_of(simple(typ="R"), {"X": (1, 2, 3)}).message == "expects at most 1 value, got 3"
    assert error_of(simple(typ="R", max=2), {"X": (1, 2, 3)}).message == (
        "expects at most 2 values, got 3"
    )


def test_too_few_values():
    error = error_of(simple(typ="R", min=2, max="**"), {"X": 1.0})
    assert error.message == "expects at least 2 values, got 1"


def test_type_error_in_a_list_names_the_value_position():
    error = error_of(simple(typ="R", max="**"), {"X": (1.0, "b")})
    assert error.message == "value 2: expected a real number (R), got text 'b'"


def test_into_rejects_with_choices_and_close_match():
    catalogue = simple(typ="TXM", into=("DIFF_CENTRE", "NEWMARK"))
    error = error_of(catalogue, {"X": "DIFF_CENTRAL"})
    assert error.message == (
        "'DIFF_CENTRAL' is not one of: 'DIFF_CENTRE', 'NEWMARK', did you mean 'DIFF_CENTRE'?"
    )


def test_into_suggests_the_right_case():
    catalogue = simple(typ="TXM", into=("OUI", "NON"))
    assert error_of(catalogue, {"X": "oui"}).message.endswith("did you mean 'OUI'?")


def test_into_without_close_match_has_no_suggestion():
    error = error_of(simple(typ="TXM", into=("OUI", "NON")), {"X": "ZZZZZZ"})
    assert error.message == "'ZZZZZZ' is not one of: 'OUI', 'NON'"


def test_numeric_into():
    catalogue = simple(typ="I", into=(1, 2))
    assert validate(catalogue, {"X": 2.0}) == {"X": 2}
    assert error_of(catalogue, {"X": 3}).message == "3 is not one of: 1, 2"


def test_into_checks_each_value_of_a_list():
    catalogue = simple(typ="TXM", into=("DX", "DY"), max="**")
    assert validate(catalogue, {"X": ("DX", "DY")})["X"] == ("DX", "DY")
    assert error_of(catalogue, {"X": ("DX", "DZ")}).message.startswith("value 2: 'DZ'")


def test_bounds_inclusive_by_default():
    catalogue = simple(typ="R", val_min=0.0, val_max=1.0)
    assert validate(catalogue, {"X": 0})["X"] == 0.0
    assert validate(catalogue, {"X": 1})["X"] == 1.0
    assert error_of(catalogue, {"X": -0.5}).message == "expected a value >= 0.0, got -0.5"
    assert error_of(catalogue, {"X": 2}).message == "expected a value <= 1.0, got 2.0"


def test_bounds_exclusive():
    catalogue = simple(
        typ="R", val_min=0.0, val_min_included=False, val_max=1, val_max_included=False
    )
    assert error_of(catalogue, {"X": 0.0}).message == "expected a value > 0.0, got 0.0"
    assert error_of(catalogue, {"X": 1.0}).message == "expected a value < 1, got 1.0"


# --- Unknown -----------------------------------------------------------------------------


def test_unknown_passes_type_into_bounds_and_counts():
    assert validate(simple(typ="R", val_min=0.0), {"X": Unknown})["X"] is Unknown
    assert validate(simple(typ="TXM", into=("A",)), {"X": Unknown})["X"] is Unknown
    assert validate(simple(typ="mode_meca"), {"X": Unknown})["X"] is Unknown
    assert validate(simple(typ="R", max="**", min=2), {"X": Unknown})["X"] is Unknown


def test_unknown_inside_a_list():
    assert validate(simple(typ="R", max="**"), {"X": [1, Unknown]})["X"] == (1.0, Unknown)


def test_unknown_in_a_condition_accepts_the_block_keywords_without_requiring_them():
    catalogue = OPER(
        nom="CMD",
        sd_prod="t",
        TYPE=SIMP(statut="o", typ="TXM", into=("A", "B")),
        b_a=BLOC(condition=equal_to("TYPE", "A"), RAYON=SIMP(statut="o", typ="R")),
    )
    assert validate(catalogue, {"TYPE": Unknown}) == {"TYPE": Unknown}
    assert validate(catalogue, {"TYPE": Unknown, "RAYON": 1})["RAYON"] == 1.0
    assert "expected a real" in error_of(catalogue, {"TYPE": Unknown, "RAYON": "r"}).message


def test_unknown_factor_value_gives_no_occurrence():
    catalogue = OPER(nom="CMD", sd_prod="t", F=FACT(statut="f", A=SIMP(typ="R")))
    assert validate(catalogue, {"F": Unknown}) == {"F": []}


# --- blocks ------------------------------------------------------------------------------


def obstacle() -> OPER:
    return OPER(
        nom="OBST",
        sd_prod="table_fonction",
        TYPE=SIMP(statut="o", typ="TXM", into=("CERCLE", "PLAN_Y", "DISCRET")),
        VERIF=SIMP(statut="d", typ="TXM", defaut="FERME", into=("FERME", "OUVERT")),
        b_cercle=BLOC(
            condition=equal_to("TYPE", "CERCLE"),
            RAYON=SIMP(statut="o", typ="R", val_min=0.0),
            NB_PAS=SIMP(statut="d", typ="I", defaut=8),
            b_ferme=BLOC(
                condition=equal_to("VERIF", "FERME"),
                JEU=SIMP(statut="d", typ="R", defaut=0.5),
            ),
        ),
        b_plan=BLOC(condition=equal_to("TYPE", "PLAN_Y"), JEU=SIMP(statut="f", typ="R")),
    )


def test_active_block_fills_defaults_including_nested_blocks():
    result = validate(obstacle(), {"TYPE": "CERCLE", "RAYON": 1})
    assert result == {"TYPE": "CERCLE", "VERIF": "FERME", "RAYON": 1.0, "NB_PAS": 8, "JEU": 0.5}


def test_nested_block_closed_by_an_outer_keyword():
    result = validate(obstacle(), {"TYPE": "CERCLE", "RAYON": 1, "VERIF": "OUVERT"})
    assert "JEU" not in result


def test_inactive_block_keyword_is_refused_with_its_condition():
    error = error_of(obstacle(), {"TYPE": "DISCRET", "RAYON": 1.0})
    assert error.message == "not allowed here: only with TYPE='CERCLE'"
    assert error.path == "OBST/RAYON"


def test_keyword_of_several_closed_blocks_lists_every_condition():
    error = error_of(obstacle(), {"TYPE": "DISCRET", "JEU": 1.0})
    assert error.message == (
        "not allowed here: only with TYPE='CERCLE' and VERIF='FERME', or with TYPE='PLAN_Y'"
    )


def test_mandatory_keyword_of_an_active_block_says_why():
    error = error_of(obstacle(), {"TYPE": "CERCLE"})
    assert error.message == "missing mandatory keyword RAYON (required when TYPE='CERCLE')"


def test_block_condition_on_a_default_value():
    catalogue = OPER(
        nom="CMD",
        sd_prod="t",
        SCHEMA=SIMP(statut="d", typ="TXM", defaut="RUNGE_KUTTA_32"),
        b_rk=BLOC(
            condition=is_in("SCHEMA", ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54")),
            TOLERANCE=SIMP(statut="d", typ="R", defaut=1e-3),
        ),
    )
    assert validate(catalogue, {}) == {"SCHEMA": "RUNGE_KUTTA_32", "TOLERANCE": 1e-3}
    assert validate(catalogue, {"SCHEMA": "NEWMARK"}) == {"SCHEMA": "NEWMARK"}


def test_block_opened_by_a_keyword_of_another_block():
    catalogue = OPER(
        nom="CMD",
        sd_prod="t",
        b_second=BLOC(condition=exists("B"), C=SIMP(statut="d", typ="I", defaut=3)),
        A=SIMP(statut="f", typ="I"),
        b_first=BLOC(condition=exists("A"), B=SIMP(statut="d", typ="I", defaut=2)),
    )
    assert validate(catalogue, {"A": 1}) == {"A": 1, "B": 2, "C": 3}
    assert validate(catalogue, {}) == {}


def test_block_inside_a_factor_sees_the_command_level():
    catalogue = OPER(
        nom="CMD",
        sd_prod="t",
        TYPE_CALCUL=SIMP(statut="d", typ="TXM", defaut="TRAN"),
        F=FACT(
            statut="d",
            b_tran=BLOC(
                condition=equal_to("TYPE_CALCUL", "TRAN"), PAS=SIMP(statut="d", typ="R", defaut=0.1)
            ),
        ),
    )
    assert validate(catalogue, {})["F"] == [{"PAS": 0.1}]
    assert validate(catalogue, {"TYPE_CALCUL": "HARM"})["F"] == [{}]


def test_block_rules_apply_only_when_open():
    catalogue = OPER(
        nom="CMD",
        sd_prod="t",
        MODE=SIMP(statut="o", typ="TXM"),
        A=SIMP(typ="R"),
        B=SIMP(typ="R"),
        b=BLOC(condition=equal_to("MODE", "STRICT"), regles=(UN_PARMI("A", "B"),)),
    )
    assert validate(catalogue, {"MODE": "LIBRE"}) == {"MODE": "LIBRE"}
    assert "exactly one of A, B" in error_of(catalogue, {"MODE": "STRICT"}).message


def test_string_conditions_as_code_aster_writes_them():
    catalogue = OPER(
        nom="CMD",
        sd_prod="t",
        A=SIMP(typ="TXM"),
        B=SIMP(typ="R"),
        b=BLOC(
            condition="""exists("B") and equal_to("A", 'OUI')""",
            C=SIMP(statut="d", typ="I", defaut=1),
        ),
    )
    assert validate(catalogue, {"A": "OUI", "B": 1.0})["C"] == 1
    assert "C" not in validate(catalogue, {"A": "OUI"})


# --- conditions --------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("condition", "values", "expected"),
    [
        (equal_to("T", "A"), {"T": "A"}, True),
        (equal_to("T", "A", "B"), {"T": "B"}, True),
        (equal_to("T", ("A", "B")), {"T": "C"}, False),
        (equal_to("T", "A"), {}, False),
        (is_in("T", ("DX", "DY")), {"T": ("DZ", "DY")}, True),
        (is_in("T", ("DX", "DY")), {"T": ("DZ",)}, False),
        (exists("T"), {"T": 0.0}, True),
        (exists("T"), {}, False),
        (absent("T"), {}, True),
        (absent("T"), {"T": 1}, False),
        (greater_than("N", 2), {"N": 3}, True),
        (greater_than("N", 2), {"N": 2}, False),
        (greater_than("N", 2), {}, False),
        (less_than("N", 2), {"N": 1.5}, True),
        (less_than("N", 2), {"N": "text"}, False),
        (exists("A") & exists("B"), {"A": 1}, False),
        (exists("A") | exists("B"), {"A": 1}, True),
        (~exists("A"), {"A": 1}, False),
    ],
)
def test_conditions(condition, values, expected):
    assert condition(values) is expected


def test_conditions_with_unknown_are_undetermined_in_three_valued_logic():
    values = {"T": Unknown, "A": 1}
    assert equal_to("T", "A").evaluate(values) is None
    assert (equal_to("T", "A") & absent("A")).evaluate(values) is False
    assert (equal_to("T", "A") | exists("A")).evaluate(values) is True
    assert (~equal_to("T", "A")).evaluate(values) is None
    assert greater_than("T", 1).evaluate(values) is None


def test_custom_condition_that_fails_to_evaluate_is_false():
    def positive(level) -> bool:
        return level["N"] > 0

    condition = Condition(positive, "N > 0")
    assert condition({"N": 2}) is True
    assert condition({}) is False
    assert condition({"N": "text"}) is False
    assert (condition | exists("A")).evaluate({"A": 1}) is True
    undetermined = Condition(lambda level: Unknown, "undetermined")
    assert undetermined.evaluate({}) is None


def test_condition_text():
    assert str(equal_to("TYPE", "CERCLE")) == "TYPE='CERCLE'"
    assert str(is_in("T", ("A", "B")) & ~exists("X")) == "(T in ('A', 'B') and not X given)"


# --- factor keywords ---------------------------------------------------------------------


def dyna() -> OPER:
    return OPER(
        nom="DYNA_VIBRA",
        sd_prod="tran_gene",
        COMPORTEMENT=FACT(
            statut="f",
            max="**",
            RELATION=SIMP(statut="o", typ="TXM", into=("DIS_CHOC", "FLAMBAGE")),
            b_choc=BLOC(
                condition=equal_to("RELATION", "DIS_CHOC"),
                RIGI_NOR=SIMP(statut="o", typ="R"),
                AMOR_NOR=SIMP(statut="d", typ="R", defaut=0.0),
            ),
        ),
        INCREMENT=FACT(statut="o", max=1, PAS=SIMP(statut="o", typ="R", val_min=0.0)),
        ARCHIVAGE=FACT(statut="d", max=1, PAS_ARCH=SIMP(statut="d", typ="I", defaut=1)),
    )


def test_factor_occurrences_become_lists_of_keywords_with_defaults():
    result = validate(
        dyna(),
        {
            "COMPORTEMENT": FactorDict(RELATION="DIS_CHOC", RIGI_NOR=1e6),
            "INCREMENT": {"PAS": 1e-4},
        },
    )
    assert result["COMPORTEMENT"] == [{"RELATION": "DIS_CHOC", "RIGI_NOR": 1e6, "AMOR_NOR": 0.0}]
    assert result["INCREMENT"] == [{"PAS": 1e-4}]
    assert result["ARCHIVAGE"] == [{"PAS_ARCH": 1}]
    assert all(isinstance(occ, Keywords) for occ in result["COMPORTEMENT"])
    assert result["COMPORTEMENT"][0].path == "DYNA_VIBRA/COMPORTEMENT[1]"
    assert result.factor("ABSENT") == []


def test_several_occurrences_are_numbered_from_one():
    occurrences = (
        FactorDict(RELATION="FLAMBAGE"),
        FactorDict(RELATION="DIS_CHOC", RIGI_NOR=2.0),
    )
    result = validate(dyna(), {"COMPORTEMENT": occurrences, "INCREMENT": FactorDict(PAS=0.1)})
    assert [occ.path for occ in result["COMPORTEMENT"]] == [
        "DYNA_VIBRA/COMPORTEMENT[1]",
        "DYNA_VIBRA/COMPORTEMENT[2]",
    ]
    assert result["COMPORTEMENT"][0] == {"RELATION": "FLAMBAGE"}


def test_unknown_keyword_in_a_factor_gets_path_location_and_close_match():
    deck = Location("study.comm", 12, 5)
    keyword = Location("study.comm", 13, 9)
    occurrence = FactorDict(
        RELATION="DIS_CHOC", RIGI_NORM=1.0, location=deck, keyword_locations={"RIGI_NORM": keyword}
    )
    error = error_of(dyna(), {"COMPORTEMENT": [occurrence], "INCREMENT": FactorDict(PAS=0.1)})
    assert error.path == "DYNA_VIBRA/COMPORTEMENT[1]/RIGI_NORM"
    assert error.message == "unknown keyword, did you mean RIGI_NOR?"
    assert error.location == keyword
    assert str(error).startswith(
        "study.comm:13:9: invalid keywords: DYNA_VIBRA/COMPORTEMENT[1]/RIGI_NORM: unknown keyword"
    )


def test_missing_mandatory_keyword_in_an_occurrence_uses_its_location():
    where = Location("study.comm", 20)
    error = error_of(dyna(), {"INCREMENT": FactorDict(location=where)})
    assert error.path == "DYNA_VIBRA/INCREMENT[1]/PAS"
    assert error.location == where


def test_missing_mandatory_factor_keyword():
    error = error_of(dyna(), {})
    assert (error.message, error.path) == (
        "missing mandatory factor keyword INCREMENT",
        "DYNA_VIBRA/INCREMENT",
    )


def test_too_many_occurrences():
    error = error_of(dyna(), {"INCREMENT": (FactorDict(PAS=1.0), FactorDict(PAS=2.0))})
    assert error.message == "expects at most 1 occurrence, got 2"
    assert error.path == "DYNA_VIBRA/INCREMENT"


def test_too_few_occurrences():
    catalogue = OPER(nom="CMD", sd_prod="t", F=FACT(statut="o", min=2, max="**", A=SIMP(typ="R")))
    assert (
        error_of(catalogue, {"F": FactorDict(A=1)}).message
        == "expects at least 2 occurrences, got 1"
    )


def test_factor_keyword_given_a_plain_value():
    site = CallSite(
        location=Location("d.comm", 1), keyword_locations={"INCREMENT": Location("d.comm", 2)}
    )
    error = error_of(dyna(), {"INCREMENT": 0.1}, site=site)
    assert error.message == "expected one or more _F(...) occurrences, got real 0.1"
    assert error.location == Location("d.comm", 2)


def test_occurrence_without_location_falls_back_to_the_keyword_location():
    site = CallSite(
        location=Location("d.comm", 1), keyword_locations={"INCREMENT": Location("d.comm", 4)}
    )
    error = error_of(dyna(), {"INCREMENT": {"PAS": -1.0}}, site=site)
    assert error.path == "DYNA_VIBRA/INCREMENT[1]/PAS"
    assert error.location == Location("d.comm", 4)


def test_keywords_carry_locations_of_given_keywords():
    site = CallSite(
        location=Location("d.comm", 1),
        keyword_locations={"INCREMENT": Location("d.comm", 2)},
    )
    occurrence = FactorDict(
        PAS=0.1,
        location=Location("d.comm", 2, 15),
        keyword_locations={"PAS": Location("d.comm", 2, 18)},
    )
    result = validate(dyna(), {"INCREMENT": occurrence}, site=site)
    assert result.location == Location("d.comm", 1)
    assert result.locations == {"INCREMENT": Location("d.comm", 2)}
    increment = result["INCREMENT"][0]
    assert increment.location == Location("d.comm", 2, 15)
    assert increment.where("PAS") == ("DYNA_VIBRA/INCREMENT[1]/PAS", Location("d.comm", 2, 18))


# --- unknown keywords --------------------------------------------------------------------


def test_unknown_keyword_with_close_match_at_command_level():
    site = CallSite(
        location=Location("d.comm", 3), keyword_locations={"TYPPE": Location("d.comm", 3, 20)}
    )
    error = error_of(obstacle(), {"TYPPE": "CERCLE"}, site=site)
    assert (error.path, error.message) == ("OBST/TYPPE", "unknown keyword, did you mean TYPE?")
    assert error.location == Location("d.comm", 3, 20)


def test_unknown_keyword_close_to_an_active_block_keyword():
    error = error_of(obstacle(), {"TYPE": "CERCLE", "RAYONN": 1.0})
    assert error.message == "unknown keyword, did you mean RAYON?"


def test_unknown_keyword_without_close_match_lists_the_allowed_ones():
    error = error_of(obstacle(), {"TYPE": "DISCRET", "ZZZ": 1})
    assert error.message == "unknown keyword, expected one of: TYPE, VERIF"


# --- rules -------------------------------------------------------------------------------


def ruled(rule) -> OPER:
    return OPER(
        nom="CMD",
        sd_prod="t",
        regles=(rule,),
        A=SIMP(typ="R"),
        B=SIMP(typ="R"),
        C=SIMP(typ="R"),
        D=SIMP(statut="d", typ="R", defaut=0.0),
    )


@pytest.mark.parametrize(
    ("rule", "given", "message"),
    [
        (UN_PARMI("A", "B"), {}, "exactly one of A, B must be given (UN_PARMI)"),
        (
            UN_PARMI("A", "B"),
            {"A": 1, "B": 2},
            "exactly one of A, B must be given, got A, B (UN_PARMI)",
        ),
        (
            EXCLUS("A", "B", "C"),
            {"A": 1, "C": 2},
            "at most one of A, B, C may be given, got A, C (EXCLUS)",
        ),
        (AU_MOINS_UN("A", "B"), {}, "at least one of A, B must be given (AU_MOINS_UN)"),
        (
            PRESENT_PRESENT("A", "B", "C"),
            {"A": 1, "B": 1},
            "A requires B, C, missing C (PRESENT_PRESENT)",
        ),
        (
            PRESENT_ABSENT("A", "B", "C"),
            {"A": 1, "C": 1},
            "A excludes B, C, got C (PRESENT_ABSENT)",
        ),
        (ENSEMBLE("A", "B"), {"B": 1}, "A, B go together: all or none, got B without A (ENSEMBLE)"),
        (
            TOUT_OU_RIEN("A", "B"),
            {"A": 1},
            "A, B go together: all or none, got A without B (TOUT_OU_RIEN)",
        ),
    ],
)
def test_rule_violations(rule, given, message):
    error = error_of(ruled(rule), given)
    assert (error.message, error.path) == (message, "CMD")


@pytest.mark.parametrize(
    ("rule", "given"),
    [
        (UN_PARMI("A", "B"), {"B": 1}),
        (EXCLUS("A", "B"), {}),
        (EXCLUS("A", "B"), {"A": 1}),
        (AU_MOINS_UN("A", "B"), {"A": 1, "B": 1}),
        (PRESENT_PRESENT("A", "B"), {"B": 1}),
        (PRESENT_PRESENT("A", "B"), {"A": 1, "B": 1}),
        (PRESENT_ABSENT("A", "B"), {"B": 1}),
        (PRESENT_ABSENT("A", "B"), {"A": 1}),
        (ENSEMBLE("A", "B"), {}),
        (ENSEMBLE("A", "B"), {"A": 1, "B": 1}),
        (TOUT_OU_RIEN("A", "B"), {}),
    ],
)
def test_rules_satisfied(rule, given):
    assert set(validate(ruled(rule), given)) >= set(given)


def test_defaults_count_as_present_for_rules_as_in_code_aster():
    assert "EXCLUS" in error_of(ruled(EXCLUS("A", "D")), {"A": 1}).message


def test_rules_inside_factor_occurrences():
    catalogue = OPER(
        nom="CMD",
        sd_prod="t",
        F=FACT(
            statut="o",
            max="**",
            regles=(UN_PARMI("NOEUD", "GROUP_NO"),),
            NOEUD=SIMP(typ="TXM"),
            GROUP_NO=SIMP(typ="TXM"),
        ),
    )
    error = error_of(catalogue, {"F": (FactorDict(NOEUD="N1"), FactorDict())})
    assert error.path == "CMD/F[2]"
    assert error.message == "exactly one of NOEUD, GROUP_NO must be given (UN_PARMI)"


# --- reentrant, result type, commands ----------------------------------------------------


def reentrant(flag: str) -> OPER:
    return OPER(nom="CMD", sd_prod="table_sdaster", reentrant=flag, A=SIMP(typ="R"))


def test_reentrant_o_needs_reuse():
    error = error_of(reentrant("o"), {"A": 1})
    assert error.message.startswith("reuse= is mandatory")
    table = FakeConcept("T", "table_sdaster")
    assert validate(reentrant("o"), {"A": 1}, reuse=table) == {"A": 1.0}


def test_reentrant_n_forbids_reuse():
    table = FakeConcept("T", "table_sdaster")
    assert error_of(reentrant("n"), {}, reuse=table).message.startswith("reuse= is not allowed")


def test_reentrant_f_allows_both():
    table = FakeConcept("T", "table_sdaster")
    assert validate(reentrant("f"), {}) == {}
    assert validate(reentrant("f"), {}, reuse=table) == {}


def test_reuse_concept_must_have_the_produced_type():
    error = error_of(reentrant("f"), {}, reuse=MODES)
    assert error.message == "reuse= expects a concept of type table_sdaster, got mode_meca MODES"


def test_reuse_given_among_keywords_is_taken_as_reuse():
    table = FakeConcept("T", "table_sdaster")
    assert validate(reentrant("o"), {"reuse": table}) == {}
    assert error_of(reentrant("n"), {"reuse": table}).message.startswith("reuse= is not allowed")


def test_result_type_from_a_name_or_a_function():
    assert result_type(reentrant("n"), Keywords()) == "table_sdaster"

    def produced(keywords: Keywords) -> str:
        return "dyna_trans" if keywords["BASE_CALCUL"] == "PHYS" else "tran_gene"

    catalogue = OPER(
        nom="DYNA_VIBRA",
        sd_prod=produced,
        BASE_CALCUL=SIMP(statut="o", typ="TXM", into=("PHYS", "GENE")),
    )
    assert result_type(catalogue, validate(catalogue, {"BASE_CALCUL": "GENE"})) == "tran_gene"
    assert result_type(catalogue, validate(catalogue, {"BASE_CALCUL": "PHYS"})) == "dyna_trans"


def test_proc_produces_nothing_and_macro_takes_co_outputs():
    proc = PROC(nom="IMPR", UNITE=SIMP(statut="d", typ="I", defaut=6))
    assert validate(proc, {}) == {"UNITE": 6}
    assert result_type(proc, Keywords()) is None
    macro = MACRO(nom="PROJ", sd_prod=None, MATR=SIMP(statut="f", typ=("CO", "matr_asse_gene_r")))
    output = CO("K")
    assert validate(macro, {"MATR": output})["MATR"] is output
    assert validate(macro, {"MATR": MATR})["MATR"] is MATR


def test_catalogue_options_code_aster_has_are_ignored():
    catalogue = OPER(
        nom="CMD",
        op=42,
        sd_prod="t",
        docu="U4.00.00",
        fr="A command",
        reuse=SIMP(statut="c", typ=CO),
        A=SIMP(statut="f", typ="R", validators=object(), position="global"),
    )
    assert list(catalogue.entries) == ["A"]
    assert catalogue.fr == "A command"


@pytest.mark.parametrize(
    "build",
    [
        lambda: SIMP(statut="x", typ="R"),
        lambda: SIMP(statut="o"),
        lambda: SIMP(typ="R", max=-1),
        lambda: FACT(statut="q"),
        lambda: OPER(nom="CMD", A=3),
        lambda: OPER(nom="CMD", reentrant="yes"),
        lambda: OPER(nom="CMD", regles=("A",)),
        lambda: BLOC(condition=3),
        lambda: UN_PARMI(),
    ],
)
def test_catalogue_mistakes_fail_at_definition(build):
    with pytest.raises(TypeError):
        build()


# --- loading -----------------------------------------------------------------------------


def test_load_catalogue_imports_the_lowercase_module(monkeypatch):
    module = types.ModuleType("asterlite.catalogues.zz_fake_cmd")
    module.ZZ_FAKE_CMD = PROC(nom="ZZ_FAKE_CMD")
    monkeypatch.setitem(sys.modules, module.__name__, module)
    load_catalogue.cache_clear()
    try:
        assert load_catalogue("ZZ_FAKE_CMD") is module.ZZ_FAKE_CMD
        assert load_catalogue("ZZ_NO_SUCH_CMD") is None
        assert load_catalogue("not a name") is None
    finally:
        load_catalogue.cache_clear()


def test_catalog_package_does_not_load_numpy():
    import subprocess

    code = (
        "import sys, asterlite.catalog\n"
        "print(any(m.split('.')[0] in ('numpy', 'scipy') for m in sys.modules))"
    )
    output = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert output.stdout.strip() == "False"


def test_mesh_entity_names_lose_trailing_blanks():
    from asterlite.catalog import PROC, SIMP, validate

    command = PROC(
        nom="NAMES", GROUP_NO=SIMP(statut="f", typ="grno", max="**"), T=SIMP(statut="f", typ="TXM")
    )
    keywords = validate(command, {"GROUP_NO": ("N5 ", "A"), "T": "x "})
    assert keywords["GROUP_NO"] == ("N5", "A")
    assert keywords["T"] == "x "  # free text keeps its blanks
