"""Every shock of a result has one name, code_aster's, the same everywhere.

Four stops given without INTITULE were all called ``DIS_CHOC1`` (the rank
within their own COMPORTEMENT occurrence): message.log, summary.json and
the Python API named the four the same, ``asterlite plot --shock`` reached
only the first and refused the names results.h5 stored (``DIS_CHOC1_2``),
and the wear chart drew one bar for four supports. code_aster names such
an occurrence after its rank among every nonlinearity of the call
(``dtmprep_noli_choc.F90``: ``nltype(NL_CHOC) // codent(i, 'D0')``), which
is what asterlite does now (:mod:`asterlite.concepts.titles`).
"""

from __future__ import annotations

import json
import re

import h5py
import pytest

from asterlite.concepts.titles import default_title, same_title, unique_titles
from tests.test_extremes_decks import Chain, Shock, write

TITLES = [f"DIS_CHOC        0000000{k}" for k in (1, 2, 3, 4)]


def unnamed_stops(folder):
    """Four masses, each against its own PLAN_Y stop given without INTITULE."""
    chain = Chain(
        masses=(1.0, 1.0, 1.0, 1.0),
        ground=((1.0e4, 1.0e4, 1.0e4),) * 4,
        coupling=1.0e3,
        depl={1: (0.0, 2.0e-3, 0.0), 3: (0.0, -1.5e-3, 0.0)},
        shocks=[Shock(k, 5.0e-4, 1.0e6, mu=0.2, k_t=1.0e5) for k in (1, 2, 3, 4)],
        pas=1.0e-5,
        inst_fin=0.2,
        pas_arch=10,
    )
    export = write(chain, folder)
    comm = export.with_suffix(".comm")
    text, count = re.subn(r'INTITULE="C\d+", ', "", comm.read_text())
    assert count == 4
    comm.write_text(text)
    return export


@pytest.fixture(scope="module")
def ran(tmp_path_factory):
    from asterlite.runtime.runner import run_deck

    folder = tmp_path_factory.mktemp("unnamed")
    export = unnamed_stops(folder / "deck")
    report = run_deck(export, folder / "out", save_results=True)
    assert report.status == "DONE", report.message
    return report, folder / "out"


def test_code_aster_titles():
    assert default_title("DIS_CHOC", 3) == "DIS_CHOC        00000003"
    assert len(default_title("DIS_CHOC", 3)) == 24  # K24, as code_aster stores it
    assert unique_titles(["A", "A", "B", "A_2"]) == ["A", "A_3", "B", "A_2"]
    assert same_title("DIS_CHOC00000003", "DIS_CHOC        00000003")
    assert not same_title("DIS_CHOC00000003", "DIS_CHOC        00000004")


def test_log_summary_and_tables_name_each_stop(ran):
    report, out = ran
    assert [shock["shock"] for shock in report.shocks] == TITLES
    summary = json.loads((out / "summary.json").read_text())
    assert [shock["shock"] for shock in summary["shocks"]] == TITLES
    log = (out / "message.log").read_text()
    for title in TITLES:
        assert f"TRAN/{title}:" in log
    stats = (out / "fort.31").read_text()  # POST_DYNA_MODA_T's INTITULE column
    for title in TITLES:
        assert title in stats


def test_results_file_and_api_name_each_stop(ran):
    import asterlite

    _, out = ran
    with h5py.File(out / "results.h5", "r") as f:
        stored = list(f["TRAN"]["shocks"])
    assert stored == TITLES
    data = asterlite.load(out / "results.h5")["TRAN"]
    shocks = data["shock"] if "shock" in data else data.coords["shock"]
    assert [str(name) for name in list(getattr(shocks, "values", shocks))] == TITLES


def test_plot_reaches_every_stop(ran, tmp_path):
    pytest.importorskip("matplotlib")
    from asterlite.cli import main
    from asterlite.io.result_store import load_tran_gene
    from asterlite.post import plots

    _, out = ran
    store = out / "results.h5"
    for given, expected in (("DIS_CHOC00000002", 1), (TITLES[3], 3)):
        picture = tmp_path / f"fn{expected}.png"
        assert main(["plot", str(store), "--shock", given, "-o", str(picture)]) == 0
        assert picture.stat().st_size > 0
        tran = load_tran_gene(store)
        assert plots.find_shock(tran, given) is tran.shocks[expected]
    assert main(["plot", str(store), "--shock", "DIS_CHOC00000009"]) == 2
    figure = plots.wear_figure(load_tran_gene(store))
    assert len(figure.axes[0].patches) == 4  # one bar per support


def test_results_saved_with_repeated_names_are_reached_by_their_stored_names():
    """A results.h5 written before the names were unique holds DIS_CHOC1 four
    times, in groups DIS_CHOC1, DIS_CHOC1_2...: each is reached by its group."""
    pytest.importorskip("matplotlib")
    import numpy as np

    from asterlite.concepts.transient import ShockHistory, TranGene
    from asterlite.post import plots

    times = np.linspace(0.0, 1.0, 11)
    shocks = [
        ShockHistory("DIS_CHOC1", "DIS_CHOC", f"N{k}", None, {"FN": (k + 1.0) * times})
        for k in range(4)
    ]
    tran = TranGene(None, times, np.arange(11), *(np.zeros((11, 1)),) * 3, shocks=shocks)
    assert plots.shock_names(tran) == ["DIS_CHOC1", "DIS_CHOC1_2", "DIS_CHOC1_3", "DIS_CHOC1_4"]
    assert plots.find_shock(tran, "DIS_CHOC1_3") is shocks[2]
    figure = plots.shock_history_figure(tran, "DIS_CHOC1_4", "FN")
    np.testing.assert_array_equal(figure.axes[0].lines[0].get_ydata(), 4.0 * times)
