"""Small edges of the command line: --version, ``run DIR``, which comparison of
a check failed in summary.json, the VERI_PAS hint, a ladder that does not
converge, the wear plot's noise floor, and the message of a missing extra."""

from __future__ import annotations

import dataclasses
import json
import math
import sys
from pathlib import Path

import numpy as np
import pytest

import asterlite
from asterlite.cli import main
from asterlite.runtime import converge
from asterlite.runtime.runner import run_deck
from asterlite.runtime.session import KeywordOverride

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "friction_oscillator"


def test_version(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    assert capsys.readouterr().out.strip() == f"asterlite {asterlite.__version__}"


# ------------------------------------------------------------------ run DIR


def test_run_a_deck_folder_runs_its_export(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["run", str(SAMPLE), "-o", str(out), "-q"]) == 0
    assert json.loads((out / "summary.json").read_text())["deck"] == "friction_oscillator"


def test_run_a_folder_with_one_comm(tmp_path):
    folder = tmp_path / "deck"
    folder.mkdir()
    (folder / "f.comm").write_text(
        'DEBUT()\nF = DEFI_FONCTION(NOM_PARA="INST", VALE=(0, 0, 1, 1))\nFIN()\n'
    )
    (folder / "notes.txt").write_text("not a deck")
    assert main(["run", str(folder), "-o", str(tmp_path / "out"), "-q"]) == 0
    assert (tmp_path / "out" / "summary.json").exists()


def test_run_a_folder_without_one_deck_says_so(tmp_path, capsys):
    empty = tmp_path / "empty"
    empty.mkdir()
    assert main(["run", str(empty)]) == 2
    err = capsys.readouterr().err
    assert str(empty) in err and "no .export or .comm" in err and "Traceback" not in err
    two = tmp_path / "two"
    two.mkdir()
    for name in ("a.export", "b.export"):
        (two / name).write_text("")
    assert main(["run", str(two)]) == 2
    assert "2 .export files (a.export, b.export)" in capsys.readouterr().err


# ------------------------------------------------------------------ summary.json


def test_summary_names_the_comparison_that_failed(tmp_path):
    """MU=0.3: the sample's analytic reference follows MU, its VALE_CALC
    (code_aster's value at MU=0.15) does not."""
    run_deck(SAMPLE / "friction_oscillator.export", tmp_path, overrides={"MU": 0.3})
    first = json.loads((tmp_path / "summary.json").read_text())["tests"][0]
    assert first["ok"] is False and first["failed"] == ["VALE_CALC"]
    refe, calc = first["comparisons"]["VALE_REFE"], first["comparisons"]["VALE_CALC"]
    assert refe["ok"] is True and refe["reference"] == "ANALYTIQUE"
    assert refe["expected"] == first["expected"]  # "expected" still shows VALE_REFE
    assert calc["ok"] is False and calc["expected"] == pytest.approx(-2.2641789701675e-03)
    assert calc["error"] > calc["tolerance"]


def test_summary_of_a_passing_check_has_both_comparisons(tmp_path):
    run_deck(SAMPLE / "friction_oscillator.export", tmp_path)
    tests = json.loads((tmp_path / "summary.json").read_text())["tests"]
    assert all(
        t["failed"] == [] and set(t["comparisons"]) == {"VALE_REFE", "VALE_CALC"} for t in tests
    )


# ------------------------------------------------------------------ VERI_PAS


def test_step_refusal_says_where_veri_pas_goes(tmp_path):
    big_step = KeywordOverride("DYNA_VIBRA", {"INCREMENT/PAS": 0.01})
    report = run_deck(SAMPLE / "friction_oscillator.export", tmp_path, keyword_overrides=[big_step])
    assert report.status == "ERROR" and "exceeds the stability limit" in report.message
    assert "INCREMENT=_F(VERI_PAS='NON')" in report.message


# ------------------------------------------------------------------ converge


def outcome(scheme: str, step: float, error: float) -> converge.Outcome:
    run = converge.Outcome(converge.Setting(scheme, step), converge.OK, step=step)
    run.max_error, run.text = error, f"{step:g}"
    return run


def study_of(outcomes) -> converge.Study:
    converge.fill_orders(outcomes)
    return converge.Study(
        deck="impact.comm",
        against="finest",
        target=None,
        transients=[{"step": 1e-4}],
        outcomes=outcomes,
        reference=None,
        reference_values={"X": 1.0},
        quantity_names=["X"],
    )


def test_a_ladder_whose_errors_never_decrease_is_said_not_to_converge():
    steps, errors = (2e-4, 1e-4, 5e-5, 2.5e-5), (0.8, 1.3, 0.6, 1.1)  # chaotic impacts
    study = study_of([outcome("DIFF_CENTRE", h, e) for h, e in zip(steps, errors, strict=True)])
    assert any(o.order < 0 for o in study.rows if not math.isnan(o.order))
    notes = converge.convergence_notes(study)
    assert len(notes) == 1 and notes[0].startswith("DIFF_CENTRE: the ladder does not converge")
    assert "8.00e-01 (PAS=0.0002) to 1.10e+00 (PAS=2.5e-05)" in notes[0]
    assert notes[0] in converge.format_table(study)


def test_a_converging_ladder_gets_no_note():
    steps = (2e-4, 1e-4, 5e-5)
    study = study_of([outcome("DEVOGE", h, (h / 1e-4) ** 4 * 1e-3) for h in steps])
    study.outcomes += [
        outcome("RUNGE_KUTTA_54", 1e-4, 1e-12),
        outcome("RUNGE_KUTTA_54", 5e-5, 2e-12),
    ]
    assert converge.convergence_notes(study) == []  # errors at rounding level count as converged


def test_converge_outputs_without_matplotlib(tmp_path, monkeypatch):
    # matplotlib and every submodule an earlier test of this worker imported
    # (import_module returns a cached submodule without its parent)
    for name in [m for m in sys.modules if m.partition(".")[0] == "matplotlib"]:
        monkeypatch.setitem(sys.modules, name, None)
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    study = study_of([outcome("DIFF_CENTRE", h, e) for h, e in ((2e-4, 1e-2), (1e-4, 2.5e-3))])
    paths = converge.write_outputs(study, tmp_path)
    assert [p.name for p in paths] == ["converge.csv", "converge.txt", "converge.md"]
    text = (tmp_path / "converge.txt").read_text()
    assert "converge.png not drawn" in text and "pip install 'asterlite[plot]'" in text


# ------------------------------------------------------------------ wear plot


@pytest.fixture(scope="module")
def tran(tmp_path_factory):
    from asterlite.io.result_store import load_tran_gene

    folder = tmp_path_factory.mktemp("wear")
    run_deck(SAMPLE / "friction_oscillator.export", folder, save_results=True)
    return load_tran_gene(folder / "results.h5")


def with_sticking_shock(tran, name: str, slip: float):
    """One more support pressed as hard but sliding at ``slip`` m/s (rounding noise)."""
    floor = tran.shocks[0]
    fields = {
        **floor.fields,
        "VT1": np.full(len(tran.times), slip),
        "VT2": np.zeros(len(tran.times)),
    }
    return dataclasses.replace(
        tran, shocks=[*tran.shocks, dataclasses.replace(floor, name=name, fields=fields)]
    )


def test_wear_noise_is_drawn_as_zero_and_said(tran):
    pytest.importorskip("matplotlib")
    from asterlite.post import plots

    noisy = with_sticking_shock(tran, "STUCK", 1.5e-15)  # 19.62 N x 1.5e-15 m/s ~ 3e-14 W
    rates = plots.wear_work_rates(noisy)
    assert 0 < rates["STUCK"] < 1e-13 < rates["FLOOR"]
    alone = plots.wear_figure(noisy, ["STUCK"])  # drawn alone it filled the axes
    assert [bar.get_height() for bar in alone.axes[0].patches] == [0.0]
    note = " ".join(text.get_text() for text in alone.axes[0].texts)
    assert "drawn as 0" in note and "STUCK" in note and "largest rate" in note
    both = plots.wear_figure(noisy)
    assert [bar.get_height() for bar in both.axes[0].patches] == [rates["FLOOR"], 0.0]
    clean = plots.wear_figure(tran)
    assert not clean.axes[0].texts  # nothing drawn as zero, nothing said


def test_wear_bars_floor_is_relative_to_the_largest():
    from asterlite.post.plots import wear_bars

    drawn, noise = wear_bars({"A": 2.0, "B": 1e-10, "C": 3e-9, "D": 0.0})
    assert drawn == {"A": 2.0, "B": 0.0, "C": 3e-9, "D": 0.0} and noise == {"B": 1e-10}
    assert wear_bars({"A": 3e-14}) == ({"A": 3e-14}, {})  # alone, small is not noise


# ------------------------------------------------------------------ extras


def test_sweep_without_its_extra_names_it(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "distributed", None)
    deck = str(SAMPLE / "friction_oscillator.export")
    assert main(["sweep", deck, "--set", "MU=0.1", "-o", str(tmp_path), "-q"]) == 2
    err = capsys.readouterr().err
    assert "asterlite sweep needs distributed" in err and "pip install 'asterlite[sweep]'" in err
    assert "Traceback" not in err and not any(tmp_path.iterdir())  # stopped before any run


def test_plot_without_matplotlib_names_the_extra(tmp_path, monkeypatch, capsys):
    assert main(["run", str(SAMPLE), "-o", str(tmp_path), "--save-results", "-q"]) == 0
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    assert main(["plot", str(tmp_path / "results.h5"), "--shock", "FLOOR"]) == 2
    assert "pip install 'asterlite[plot]'" in capsys.readouterr().err


def test_impr_fonction_image_without_matplotlib_is_located(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    deck = tmp_path / "png.comm"
    deck.write_text(
        'DEBUT()\nF = DEFI_FONCTION(NOM_PARA="INST", VALE=(0, 0, 1, 1))\n'
        'IMPR_FONCTION(FORMAT="XMGRACE", UNITE=29,\n'
        '              PILOTE="PNG", COURBE=_F(FONCTION=F))\nFIN()\n'
    )
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "ERROR"
    assert "png.comm:4" in report.message and "IMPR_FONCTION/PILOTE" in report.message
    assert "pip install 'asterlite[plot]'" in report.message
