"""Parameter sweeps on Dask: settings, one real LocalCluster for the module,
the gathered table, and the CLI."""

from __future__ import annotations

import csv
import shutil
from pathlib import Path

import pytest

from asterlite.cli import main
from asterlite.runtime import sweep

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "friction_oscillator"
DECK = SAMPLE / "friction_oscillator.export"
CHECK_LABELS = [f"RESU[{n}] DEPLPHY DEPL N1 DX ordre {n}" for n in (1, 2, 3, 4)]


@pytest.fixture(scope="module")
def client():
    pytest.importorskip("distributed")
    with sweep.dask_client(workers=2) as dask_client:
        yield dask_client


@pytest.fixture(scope="module")
def friction_sweep(client, tmp_path_factory):
    """MU at its own value (PASS), another value (NOOK), and text (ERROR)."""
    output = tmp_path_factory.mktemp("sweep")
    settings = [sweep.parse_setting("MU=0.15,0.1,abc")]
    rows = sweep.run_sweep(DECK, settings, output, client)
    sweep.write_tables(rows, ["MU"], output)
    return output, rows


# ----------------------------------------------------------------- settings


@pytest.mark.parametrize(
    "text, expected",
    [("3", 3), ("0.15", 0.15), ("1.E+04", 1.0e4), ("-8e3", -8000.0), ("abc", "abc"), ("'7'", "7")],
)
def test_values_are_python_numbers_or_text(text, expected):
    value = sweep.parse_value(text)
    assert value == expected and type(value) is type(expected)


def test_settings_combine_into_every_variant_first_setting_slowest():
    settings = [sweep.parse_setting("MU=0.1,0.2"), sweep.parse_setting("K=1,2,3")]
    combos = sweep.variants(settings)
    assert len(combos) == 6
    assert combos[0] == {"MU": 0.1, "K": 1} and combos[-1] == {"MU": 0.2, "K": 3}
    assert sweep.variant_folder(combos[1]) == "MU=0.1_K=2"


@pytest.mark.parametrize("text", ["MU", "=1", "1MU=2", "MU="])
def test_malformed_settings_are_rejected(text):
    with pytest.raises(sweep.SweepError):
        sweep.parse_setting(text)


def test_a_name_set_twice_is_rejected():
    with pytest.raises(sweep.SweepError, match="MU"):
        sweep.variants([sweep.parse_setting("MU=1"), sweep.parse_setting("MU=2")])


def test_folder_names_are_sanitized_and_unique():
    folders = sweep.unique_folders([{"S": "a/b"}, {"S": "a-b"}])
    assert folders == ["S=a-b", "S=a-b_2"]


def test_unknown_name_is_an_error_naming_it_before_any_worker_starts(capsys):
    code = main(["sweep", str(DECK), "--set", "MU=0.1", "--set", "NOPE=1"])
    assert code == 2
    assert "NOPE" in capsys.readouterr().err


def test_malformed_set_on_the_command_line_exits_2(capsys):
    assert main(["sweep", str(DECK), "--set", "MU"]) == 2
    assert "NAME=value" in capsys.readouterr().err


def test_a_variant_row_holds_the_cells_of_one_row_tables(tmp_path):
    """In-process (no cluster): the sample with a one-row table appended."""
    deck_dir = tmp_path / "deck"
    shutil.copytree(SAMPLE, deck_dir)
    comm = deck_dir / "friction_oscillator.comm"
    table = 'TAB = CREA_TABLE(LISTE=(_F(PARA="SWING4", LISTE_R=(SWINGS[3],)),))\nFIN()'
    comm.write_text(comm.read_text().replace("FIN()", table))
    row = sweep.run_variant(str(deck_dir / DECK.name), str(tmp_path / "out"), {"MU": 0.1})
    assert row["status"] == "NOOK"
    # the analytic fourth swing with MU = 0.1: U0 - 8 MU G / W0**2
    assert row["TAB.SWING4"] == pytest.approx(3.0e-3 - 8 * 0.1 * 9.81 / 4000.0)


# ------------------------------------------------------------------ on Dask


def test_one_row_per_variant_in_order_with_its_status(friction_sweep):
    _, rows = friction_sweep
    assert [row["MU"] for row in rows] == [0.15, 0.1, "abc"]
    assert [row["status"] for row in rows] == ["PASS", "NOOK", "ERROR"]
    assert sweep.sweep_exit_code(rows) == 2
    assert sweep.sweep_exit_code(rows[:2]) == 0


def test_the_error_row_carries_the_located_message(friction_sweep):
    error = friction_sweep[1][2]
    assert "COULOMB" in error["message"] and "'abc'" in error["message"]
    assert "friction_oscillator.comm:" in error["message"]
    assert error["checks_total"] == 0


def test_check_values_vary_with_the_variable(friction_sweep):
    passed, nook, _ = friction_sweep[1]
    for label in CHECK_LABELS:
        assert isinstance(passed[label], float) and isinstance(nook[label], float)
        assert passed[label] != pytest.approx(nook[label], rel=1e-3)
    # less friction, slower decay: the fourth swing is larger
    assert abs(nook[CHECK_LABELS[3]]) > abs(passed[CHECK_LABELS[3]])
    # the MU = 0.15 run is the sample itself: its analytic value
    assert passed[CHECK_LABELS[0]] == pytest.approx(-2.26425e-3, rel=1e-3)


def test_each_variant_has_its_own_output_folder(friction_sweep):
    output, _ = friction_sweep
    for folder in ("MU=0.15", "MU=0.1", "MU=abc"):
        assert (output / folder / "summary.json").is_file()


def test_csv_and_parquet_tables_hold_every_row(friction_sweep):
    pq = pytest.importorskip("pyarrow.parquet")
    output, rows = friction_sweep
    with (output / "sweep.csv").open(newline="") as stream:
        table = list(csv.DictReader(stream))
    assert [r["status"] for r in table] == ["PASS", "NOOK", "ERROR"]
    assert list(table[0])[:3] == ["MU", "status", "seconds"]
    assert float(table[1][CHECK_LABELS[0]]) == pytest.approx(rows[1][CHECK_LABELS[0]])
    parquet = pq.read_table(output / "sweep.parquet").to_pylist()
    assert parquet[0][CHECK_LABELS[2]] == pytest.approx(rows[0][CHECK_LABELS[2]])
    assert parquet[2][CHECK_LABELS[2]] is None
    assert parquet[2]["MU"] == "abc"  # a column mixing numbers and text is text


def test_printed_table_shows_each_variant_and_the_failure(friction_sweep):
    text = sweep.format_sweep_table(friction_sweep[1], ["MU"])
    assert "PASS" in text and "NOOK" in text and "c4: " + CHECK_LABELS[3] in text
    assert "MU=abc: ERROR:" in text


def test_cli_on_an_existing_scheduler(client, tmp_path, capsys):
    address = client.scheduler.address
    code = main(
        ["sweep", str(DECK), "--set", "MU=0.15,0.12", "--scheduler", address, "-o", str(tmp_path)]
    )
    out = capsys.readouterr().out
    assert code == 0
    assert (tmp_path / "sweep.csv").is_file() and (tmp_path / "MU=0.12").is_dir()
    assert "MU=0.12: NOOK" in out and "table:" in out
