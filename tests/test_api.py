"""The Python API (asterlite.api): run, check, load, and concepts as data,
with xarray/pandas when installed and plain numpy dicts without them."""

from __future__ import annotations

import json
import runpy
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import asterlite
from asterlite import api
from asterlite.io import frames

ROOT = Path(__file__).resolve().parent.parent
SAMPLE = ROOT / "samples" / "friction_oscillator"

DATA_DECK = """
DEBUT(CODE="OUI")
SCALE = 2.0
NAMES = ["A", "B"]
F = DEFI_FONCTION(NOM_PARA="INST", NOM_RESU="DEPL", VALE=(0.0, 0.0, 1.0, SCALE, 2.0, 0.5))
T = CREA_TABLE(LISTE=(_F(PARA="NUME", LISTE_I=(1, 2, 3)),
                      _F(PARA="VALE", LISTE_R=(0.5, 1.5, SCALE)),
                      _F(PARA="NOM", LISTE_K=("a", "b", "c"))))
TEST_FONCTION(VALEUR=_F(FONCTION=F, VALE_PARA=0.5, VALE_CALC=1.0, VALE_REFE=0.5 * SCALE,
                        REFERENCE="ANALYTIQUE"))
FIN()
"""


@pytest.fixture
def no_optional(monkeypatch):
    """As if neither xarray nor pandas were installed."""
    monkeypatch.setattr(frames, "optional", lambda module: None)


def data_deck(tmp_path) -> Path:
    path = tmp_path / "data.comm"
    path.write_text(DATA_DECK)
    return path


@pytest.fixture(scope="module")
def sample_run():
    return asterlite.run(SAMPLE)


# ------------------------------------------------------------------ run / check


def test_run_reports_status_checks_and_concepts(sample_run):
    assert isinstance(sample_run, api.RunResult)
    assert sample_run.status == "PASS", sample_run.message
    assert sample_run.ok and sample_run.exit_code == 0
    assert len(sample_run.checks) == 4 and all(c.ok for c in sample_run.checks)
    first = sample_run.checks[0]
    assert first.reference == "ANALYTIQUE" and first.line == 112
    assert set(first.comparisons) == {"VALE_REFE", "VALE_CALC"} and first.failed == ()
    assert first.value == pytest.approx(-2.26425e-3, rel=1e-4)
    assert sample_run.concepts.raw["RESUGENE"].aster_type == "tran_gene"
    assert sample_run.variables["MU"] == 0.15 and "pi" not in sample_run.variables
    assert sample_run.shocks[0]["shock"] == "FLOOR" and sample_run.output is None
    assert sample_run.summary["status"] == "PASS"


def test_run_overrides_deck_variables_and_refuses_unknown_ones(tmp_path):
    out = tmp_path / "out"
    result = asterlite.run(SAMPLE / "friction_oscillator.export", out, MU=0.3)
    assert result.variables["MU"] == 0.3 and result.status == "NOOK" and not result.ok
    # the analytic reference follows MU, the VALE_CALC (computed at 0.15) does not
    assert result.checks[0].failed == ("VALE_CALC",)
    assert json.loads((out / "summary.json").read_text())["overrides"] == {"MU": 0.3}
    with pytest.raises(ValueError, match="NOT_IN_DECK"):
        asterlite.run(SAMPLE, NOT_IN_DECK=1.0)


def test_a_missing_deck_raises_and_a_failing_deck_does_not(tmp_path):
    with pytest.raises(api.DeckNotFound, match="no such deck"):
        asterlite.run(tmp_path / "nothing.comm")
    bad = tmp_path / "bad.comm"
    bad.write_text('DEBUT()\nF = DEFI_FONCTION(NOM_PARA="INST", VALEUR=(0.0, 1.0))\nFIN()\n')
    result = asterlite.run(bad)
    assert result.status == "ERROR" and "VALEUR" in result.message and not result.ok


def test_check_validates_without_computing(tmp_path):
    assert asterlite.check(SAMPLE).ok
    bad = tmp_path / "bad.comm"
    bad.write_text('DEBUT()\nF = DEFI_FONCTION(NOM_PARA="INST", VALEUR=(0.0, 1.0))\nFIN()\n')
    checked = asterlite.check(bad)
    assert not checked.ok and checked.status == "ERROR"
    assert any("bad.comm:2" in error for error in checked.errors)


def test_import_stays_light():
    code = (
        "import sys, asterlite; asterlite.run; asterlite.check; asterlite.load;"
        " from asterlite.cli import build_parser; build_parser();"
        " print(sorted(m for m in ('numpy', 'scipy', 'numba') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
    assert "run" in dir(asterlite)
    with pytest.raises(AttributeError):
        asterlite.not_an_api_name  # noqa: B018


# ------------------------------------------------------------------ data


def test_transient_without_xarray_is_xarrays_dict_form(sample_run, no_optional):
    tran = sample_run.concepts.raw["RESUGENE"]
    data = frames.as_python(tran)
    assert isinstance(data, dict) and set(data) == {"dims", "coords", "data_vars", "attrs"}
    assert data["dims"] == {"time": 1001, "mode": 1, "shock": 1, "dof": 3}
    assert data["data_vars"]["depl"]["dims"] == ("time", "mode")
    np.testing.assert_array_equal(data["depl"], tran.depl)
    np.testing.assert_array_equal(data["FN"][:, 0], tran.shocks[0].fields["FN"])
    assert data.dims_of("FN") == ("time", "shock") and "FN" in data
    assert data["shock"].tolist() == ["FLOOR"] and data["dof"][0] == "N1 DX"
    assert data["attrs"]["scheme"] == "DIFF_CENTRE"
    # depl @ shapes.T restitutes the physical motion
    physical = data["depl"] @ data["shapes"].T
    assert physical[0, 0] == pytest.approx(3.0e-3)


def test_transient_with_xarray_is_a_dataset(sample_run):
    xr = pytest.importorskip("xarray")
    tran = sample_run.concepts.raw["RESUGENE"]
    data = frames.as_python(tran)
    assert isinstance(data, xr.Dataset)
    assert data["FN"].dims == ("time", "shock")
    np.testing.assert_array_equal(data["FN"].sel(shock="FLOOR").values, tran.shocks[0].fields["FN"])
    assert float(data["frequency"][0]) == pytest.approx(np.sqrt(8000.0 / 2.0) / (2 * np.pi))


def test_the_dict_form_is_what_xarray_reads(sample_run, monkeypatch):
    xr = pytest.importorskip("xarray")
    tran = sample_run.concepts.raw["RESUGENE"]
    dataset = frames.as_python(tran)
    monkeypatch.setattr(frames, "optional", lambda module: None)
    plain = frames.as_python(tran)
    assert xr.Dataset.from_dict(plain).identical(dataset)


def test_physical_results_by_step_node_and_component(sample_run, no_optional):
    modes = frames.as_python(sample_run.concepts.raw["MODES"])
    assert modes.dims_of("DEPL") == ("mode", "node", "component")
    assert modes["node"].tolist() == ["N1"] and modes["component"].tolist() == ["DX", "DY", "DZ"]
    assert modes["frequency"][0] == pytest.approx(np.sqrt(4000.0) / (2 * np.pi), rel=1e-9)
    phys = frames.as_python(sample_run.concepts.raw["DEPLPHY"])
    assert phys.dims_of("DEPL") == ("time", "node", "component")
    assert phys["DEPL"][:, 0, 0] == pytest.approx([c.value for c in sample_run.checks])


def test_tables_and_functions_without_pandas(tmp_path, no_optional):
    result = asterlite.run(data_deck(tmp_path))
    assert result.status == "PASS", result.message
    assert result.variables == {"SCALE": 2.0, "NAMES": ["A", "B"]}
    function = result.concepts["F"]
    assert isinstance(function, frames.Columns) and function.columns == ["INST", "DEPL"]
    np.testing.assert_array_equal(function.to_numpy(), [[0.0, 0.0], [1.0, 2.0], [2.0, 0.5]])
    table = result.concepts["T"]
    assert table.columns == ["NUME", "VALE", "NOM"] and table.n_rows == 3
    assert table["NUME"].dtype.kind == "i" and table["VALE"].tolist() == [0.5, 1.5, 2.0]
    assert table["NOM"].tolist() == ["a", "b", "c"]


def test_tables_and_functions_with_pandas(tmp_path):
    pd = pytest.importorskip("pandas")
    result = asterlite.run(data_deck(tmp_path))
    function, table = result.concepts["F"], result.concepts["T"]
    assert isinstance(function, pd.DataFrame) and list(function.columns) == ["INST", "DEPL"]
    assert function.attrs["name"] == "F" and function["DEPL"].tolist() == [0.0, 2.0, 0.5]
    assert isinstance(table, pd.DataFrame) and table["VALE"].sum() == pytest.approx(4.0)
    assert table.to_numpy().shape == (3, 3)


def test_sparse_table_columns_hold_nan_or_none(no_optional):
    from asterlite.concepts.table import Table

    table = Table(columns=["N", "X", "K"], types={"N": "I", "X": "R", "K": "K8"})
    table.rows = [{"N": 1, "X": 0.5, "K": "a"}, {"N": 2}]
    data = frames.as_python(table)
    assert data["N"].tolist() == [1, 2] and np.isnan(data["X"][1]) and data["K"][1] is None
    table.add_row({"X": 1.0})
    assert np.isnan(frames.as_python(table)["N"][2])  # a missing integer makes floats


def test_load_reads_saved_results(tmp_path, no_optional):
    from asterlite.cli import main

    assert main(["run", str(SAMPLE), "-o", str(tmp_path), "--save-results", "-q"]) == 0
    saved = asterlite.load(tmp_path / "results.h5")
    assert list(saved) == ["RESUGENE"] and saved["RESUGENE"]["dims"]["time"] == 1001
    raw = asterlite.load(tmp_path / "results.h5", "RESUGENE", raw=True)
    assert raw.aster_type == "tran_gene" and raw.shocks[0].name == "FLOOR"
    with pytest.raises(FileNotFoundError):
        asterlite.load(tmp_path / "missing.h5")


# ------------------------------------------------------------------ docs


def test_the_documented_example_runs():
    runpy.run_path(str(ROOT / "docs" / "examples" / "api_example.py"), run_name="__main__")


def test_docs_name_every_public_function():
    text = (ROOT / "docs" / "api.md").read_text()
    for name in ("asterlite.run(", "asterlite.check(", "asterlite.load(", "comparisons"):
        assert name in text
