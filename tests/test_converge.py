"""Keyword overrides and ``asterlite converge`` (error against cost per scheme)."""

from __future__ import annotations

import csv
import math
from types import SimpleNamespace

import pytest

from asterlite.catalog import load_catalogue
from asterlite.lang.values import FactorDict
from asterlite.runtime import converge
from asterlite.runtime.runner import run_deck
from asterlite.runtime.session import KeywordOverride, apply_keyword_values
from tests.conftest import CORPUS, SAMPLES

FRICTION = SAMPLES / "friction_oscillator" / "friction_oscillator.export"
T1 = math.pi / math.sqrt(8.0e3 / 2.0)  # first half period: the first TEST_RESU instant
FIRST_SWING = r"ordre 1$"  # the first check: the smooth sliding half-swing


# ------------------------------------------------------------ keyword overrides


@pytest.fixture(scope="module")
def dyna_vibra():
    return load_catalogue("DYNA_VIBRA")


def test_override_replaces_scheme_and_drops_its_parameters(dyna_vibra):
    kwargs = {"SCHEMA_TEMPS": FactorDict(SCHEMA="NEWMARK", BETA=0.3, GAMMA=0.6)}
    edited = apply_keyword_values(
        dyna_vibra, kwargs, {"SCHEMA_TEMPS/SCHEMA": "DEVOGE", "SCHEMA_TEMPS/TOLERANCE": 1e-6}
    )
    assert dict(edited["SCHEMA_TEMPS"]) == {"SCHEMA": "DEVOGE", "TOLERANCE": 1e-6}
    assert dict(kwargs["SCHEMA_TEMPS"])["BETA"] == 0.3  # the deck's own call is untouched


def test_override_creates_a_missing_factor_and_removes_with_none(dyna_vibra):
    kwargs = {"INCREMENT": FactorDict(INST_FIN=1.0, PAS=1e-3, VERI_PAS="NON")}
    edited = apply_keyword_values(
        dyna_vibra,
        kwargs,
        {"SCHEMA_TEMPS/SCHEMA": "DIFF_CENTRE", "INCREMENT/PAS": 5e-4, "INCREMENT/VERI_PAS": None},
    )
    assert dict(edited["SCHEMA_TEMPS"]) == {"SCHEMA": "DIFF_CENTRE"}
    assert dict(edited["INCREMENT"]) == {"INST_FIN": 1.0, "PAS": 5e-4}


def test_override_of_one_occurrence(dyna_vibra):
    occurrences = (
        FactorDict(RELATION="DIS_CHOC", JEU=1.0),
        FactorDict(RELATION="DIS_CHOC", JEU=2.0),
    )
    kwargs = {"COMPORTEMENT": occurrences}
    edited = apply_keyword_values(dyna_vibra, kwargs, {"COMPORTEMENT[2]/JEU": 3.0})
    assert [dict(o)["JEU"] for o in edited["COMPORTEMENT"]] == [1.0, 3.0]


def test_run_deck_with_keyword_overrides_and_shock_summaries():
    keywords = {
        "SCHEMA_TEMPS/SCHEMA": "NEWMARK",
        "SCHEMA_TEMPS/BETA": 0.25,
        "INCREMENT/INST_FIN": 0.02,
        "INCREMENT/PAS": 1.0e-4,
    }
    report = run_deck(FRICTION, keyword_overrides=[KeywordOverride("DYNA_VIBRA", keywords)])
    # the deck's checks look at later instants than the shortened run: not a PASS
    assert report.transients and report.transients[0]["scheme"] == "NEWMARK"
    assert report.transients[0]["steps"] == 200
    assert report.keyword_edits[0]["call"] == 1
    (shock,) = report.shocks
    assert shock["shock"] == "FLOOR"
    assert shock["max_FN"] == pytest.approx(2.0 * 9.81)
    assert shock["wear_power"] > 0.0


def test_override_of_another_call_leaves_the_deck_alone():
    overrides = [KeywordOverride("DYNA_VIBRA", {"INCREMENT/PAS": 1.0e-4}, call=2)]
    report = run_deck(FRICTION, keyword_overrides=overrides)
    assert report.status == "PASS"
    assert report.transients[0]["step"] == 2.5e-4
    assert report.keyword_edits == []


# ------------------------------------------------------------ ladders and errors


def test_default_ladder_is_relative_to_the_deck_step():
    settings = converge.ladder(("DIFF_CENTRE", "RUNGE_KUTTA_54"))
    fixed = [s for s in settings if s.scheme == "DIFF_CENTRE"]
    assert [s.value for s in fixed] == list(converge.DEFAULT_FACTORS)
    assert all(s.relative for s in fixed)
    reference = converge.parse_reference(None, settings)
    assert reference.scheme == "DIFF_CENTRE" and reference.value == 0.125 / 2
    keywords = converge.scheme_keywords(fixed[0], {"step": 2.5e-4})
    assert keywords["INCREMENT/PAS"] == 2 * 2.5e-4


def test_devoge_fixed_step_pins_pas_mini_and_maxi():
    keywords = converge.scheme_keywords(converge.Setting("DEVOGE", 1e-4), {"step": 2.5e-4})
    assert keywords["SCHEMA_TEMPS/PAS_MINI"] == keywords["SCHEMA_TEMPS/PAS_MAXI"] == 1e-4
    adaptive = converge.scheme_keywords(converge.Setting("DEVOGE_ADAPT", 1e-6), {"step": 2.5e-4})
    assert adaptive["SCHEMA_TEMPS/SCHEMA"] == "DEVOGE"
    assert adaptive["SCHEMA_TEMPS/PAS_MAXI"] is None
    assert adaptive["SCHEMA_TEMPS/TOLERANCE"] == 1e-6


def test_observed_order_and_relative_error():
    assert converge.observed_order(4e-4, 1e-4, 2.0, 1.0) == pytest.approx(2.0)
    assert math.isnan(converge.observed_order(0.0, 1e-4, 2.0, 1.0))
    assert converge.relative_error(1.01, 1.0) == pytest.approx(0.01)
    assert math.isnan(converge.relative_error(1.0, 0.0))
    with pytest.raises(converge.ConvergeError):
        converge.parse_schemes("DIFF_CENTER")


# ------------------------------------------------------------ studies


@pytest.fixture(scope="module")
def smooth_study():
    """DIFF_CENTRE and fixed-step DEVOGE on the first half-swing, with steps
    that divide it (no interpolation error at the checked instant)."""
    return converge.run_study(
        FRICTION,
        schemes=("DIFF_CENTRE", "DEVOGE"),
        steps=(T1 / 100, T1 / 200, T1 / 400),
        reference=f"DEVOGE:{T1 / 3200!r}",
        pattern=FIRST_SWING,
        target=1e-8,
    )


def test_orders_on_the_smooth_part(smooth_study):
    def last_order(scheme):
        runs = [o for o in smooth_study.rows if o.setting.scheme == scheme]
        assert [o.status for o in runs] == ["ok"] * 3
        return runs[-1].order

    centre, devoge = last_order("DIFF_CENTRE"), last_order("DEVOGE")
    # central differences: second order (3 at this swing extremum, where the
    # phase error enters quadratically); DEVOGE: fourth order
    assert 1.8 < centre < 3.3
    assert devoge > 3.6
    assert devoge > centre + 0.8
    assert smooth_study.quantity_names == ["RESU[1] DEPLPHY DEPL N1 DX ordre 1"]


def test_cheapest_and_outputs(smooth_study, tmp_path):
    best = converge.cheapest(smooth_study)
    assert best is not None and best.setting.scheme == "DEVOGE"
    assert best.max_error <= 1e-8
    paths = converge.write_outputs(smooth_study, tmp_path)
    csv_path, png_path, text_path, markdown_path = paths
    assert markdown_path.read_text().startswith("| scheme |")
    assert png_path.stat().st_size > 1000 and png_path.read_bytes()[:4] == b"\x89PNG"
    with csv_path.open() as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 7  # six rungs and the reference run
    assert {
        "error[RESU[1] DEPLPHY DEPL N1 DX ordre 1]",
        "order[RESU[1] DEPLPHY DEPL N1 DX ordre 1]",
    } <= set(rows[0])
    assert [r["meets_target"] for r in rows].count("best") == 1
    assert "cheapest setting meeting 1e-08: DEVOGE" in text_path.read_text()


def test_unstable_rung_is_a_row(tmp_path):
    study = converge.run_study(
        FRICTION, schemes=("DIFF_CENTRE",), steps=(5.0e-3, 2.5e-4), warmup=False
    )
    unstable, stable = study.rows
    assert unstable.status == "unstable"
    assert "stability limit" in unstable.message
    assert stable.status == "ok" and stable.max_error > 0
    assert "unstable" in converge.format_table(study)
    converge.write_outputs(study, tmp_path)
    assert (tmp_path / "converge.png").exists()


def test_against_reference_needs_reference_values():
    check = SimpleNamespace(reference="NON_REGRESSION", expected=1.0, label="x")
    with pytest.raises(converge.ConvergeError, match="no reference value"):
        converge.reference_values(SimpleNamespace(tests=[check]))
    check = SimpleNamespace(reference="ANALYTIQUE", expected=2.0, label="x")
    assert converge.reference_values(SimpleNamespace(tests=[check, check])) == {
        "x": 2.0,
        "x #2": 2.0,
    }


# ------------------------------------------------------------ the corpus deck, via the CLI


def test_cli_converge_on_sdnd100a(tmp_path, capsys):
    deck = CORPUS / "sdnd100a" / "sdnd100a.export"
    if not deck.is_file():
        pytest.skip("../shared/aster-corpus is not available")
    from asterlite.cli import main

    code = main(
        [
            "converge",
            str(deck),
            "--schemes",
            "DIFF_CENTRE,RUNGE_KUTTA_54",
            "--steps",
            "1e-3,5e-4",
            "--tolerances",
            "1e-5,1e-6",
            "--target",
            "1e-2",
            "--against",
            "reference",
            "-q",
            "-o",
            str(tmp_path),
        ]
    )
    out = capsys.readouterr().out
    assert code == 0, out
    assert "cheapest setting meeting 0.01" in out
    assert "relative to the deck's VALE_REFE" in out
    assert (tmp_path / "converge.csv").exists() and (tmp_path / "converge.png").exists()


def test_memory_cap_is_restored():
    resource = pytest.importorskip("resource")
    before = resource.getrlimit(resource.RLIMIT_AS)
    with converge.memory_cap(0.7):
        inside = resource.getrlimit(resource.RLIMIT_AS)
        assert inside[0] != resource.RLIM_INFINITY
    assert resource.getrlimit(resource.RLIMIT_AS) == before


def test_min_step_ratio_sets_pas_mini_of_adaptive_rungs():
    setting = converge.Setting("RUNGE_KUTTA_54", 1e-6)
    keywords = converge.scheme_keywords(setting, {"step": 2e-5}, min_step_ratio=1e-3)
    assert keywords["SCHEMA_TEMPS/PAS_MINI"] == pytest.approx(2e-8)
    assert converge.scheme_keywords(setting, {"step": 2e-5})["SCHEMA_TEMPS/PAS_MINI"] is None
