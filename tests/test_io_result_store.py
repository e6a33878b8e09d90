"""HDF5 result store (asterlite.io.result_store): layout and round trips."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.table import Table
from asterlite.concepts.transient import TranGene
from asterlite.errors import CommandError
from asterlite.io.result_store import (
    ResultSteps,
    load_tran_gene,
    nodal_series,
    read_tran_gene_dict,
    result_steps,
    save_session_results,
    save_tran_gene,
    select_steps,
    stored_names,
)

from .test_post_support import small_transient

h5py = pytest.importorskip("h5py")


def rich_transient() -> TranGene:
    result = small_transient()
    result.name = "TRAN"
    result.basis.name = "MODES"
    result.basis.numbering.mesh.name = "MESH"
    result.scheme = "DIFF_CENTRE"
    result.step = 1e-3
    result.info = {
        "steps": 1000,
        "rejected_steps": 3,
        "adaptive": False,
        "min_step": 1e-3,
        "history": np.array([1e-3, 2e-3]),
        "mult_appui": [object()],  # not storable: listed, not lost silently
    }
    shock = result.shocks[0]
    shock.parameters = {
        "OBSTACLE": "PLAN_Y",
        "JEU": 1e-3,
        "RIGI_NOR": 1e7,
        "NORM_OBST": np.array([0.0, 0.0, 1.0]),
        "LOCAL_FRAME": np.eye(3),
        "UNIDIRECTIONNEL": False,
    }
    return result


def test_round_trip_gives_back_the_tran_gene(tmp_path):
    original = rich_transient()
    path = save_tran_gene(tmp_path / "r.h5", original)
    back = load_tran_gene(path, "TRAN")
    assert back.name == "TRAN" and back.scheme == "DIFF_CENTRE" and back.step == 1e-3
    for field in ("times", "order", "depl", "vite", "acce"):
        assert np.array_equal(getattr(back, field), getattr(original, field))
    assert back.info["steps"] == 1000 and back.info["rejected_steps"] == 3
    assert back.info["history"].tolist() == [1e-3, 2e-3]
    assert "mult_appui" in back.info["info_not_stored"]
    shock = back.shocks[0]
    assert (shock.name, shock.relation, shock.node_1, shock.node_2) == (
        "CHOC1",
        "DIS_CHOC",
        "NO2",
        None,
    )
    assert np.array_equal(shock.fields["FN"], original.shocks[0].fields["FN"])
    assert shock.parameters["OBSTACLE"] == "PLAN_Y" and shock.parameters["JEU"] == 1e-3
    assert np.array_equal(shock.parameters["LOCAL_FRAME"], np.eye(3))
    basis = back.basis
    assert np.array_equal(basis.shapes, original.basis.shapes)
    assert basis.numbering.dofs == original.basis.numbering.dofs
    assert basis.frequencies.tolist() == [1.0, 2.0]
    assert basis.mode_numbers.tolist() == [1, 2]
    mesh = basis.numbering.mesh
    assert mesh.name == "MESH" and mesh.node_names == ["NO1", "NO2"]
    assert mesh.cell_nodes == [(0, 1)] and mesh.node_groups["ALL"].tolist() == [0, 1]
    # the restored basis restitutes like the original
    assert np.allclose(basis.shape_at("NO2", "DX"), [2.0, 0.5])


def test_layout_is_readable_with_plain_h5py(tmp_path):
    path = save_tran_gene(tmp_path / "r.h5", rich_transient(), "RUN1")
    with h5py.File(path, "r") as f:
        group = f["RUN1"]
        assert group.attrs["aster_type"] == "tran_gene"
        assert group.attrs["n_modes"] == 2 and group.attrs["n_archived"] == 11
        assert group["depl"].shape == (11, 2)
        assert list(group["shocks"]) == ["CHOC1"]
        assert group["shocks/CHOC1"].attrs["RIGI_NOR"] == 1e7
        assert group["scheme"].attrs["steps"] == 1000
        labels = group["basis/dof_labels"].asstr()[()].tolist()
        assert labels == ["NO1 DX", "NO1 DY", "NO2 DX", "NO2 DY"]
        # physical displacement of NO2 DX, as docs/results.md shows it
        phi = group["basis/shapes"][()]
        u = group["depl"][()] @ phi[labels.index("NO2 DX")]
        times = group["times"][()]
    assert np.allclose(u, 2 * times + 0.5 * times**2)


def test_plain_dict_and_several_results_per_file(tmp_path):
    path = tmp_path / "r.h5"
    first, second = rich_transient(), small_transient()
    second.shocks = []
    namespace = {"TRAN": first, "ALIAS": first, "OTHER": second, "X": 1.0}
    assert save_session_results(path, namespace) == ["TRAN", "OTHER"]
    assert stored_names(path) == ["TRAN", "OTHER"]
    data = load_tran_gene(path, "OTHER", concept=False)
    assert data["depl"].shape == (11, 2) and data["shocks"] == []
    assert data["basis"]["dof_components"] == ["DX", "DY", "DX", "DY"]
    # saving again replaces the group, keeps the others
    save_tran_gene(path, second, "OTHER")
    assert stored_names(path) == ["TRAN", "OTHER"]
    with pytest.raises(KeyError, match="no tran_gene named 'NOPE'"):
        load_tran_gene(path, "NOPE")


def test_duplicate_and_empty_shock_names_get_distinct_groups(tmp_path):
    result = rich_transient()
    extra = [s for s in small_transient().shocks] + [s for s in small_transient().shocks]
    extra[1].name = ""
    result.shocks += extra
    path = save_tran_gene(tmp_path / "r.h5", result)
    with h5py.File(path, "r") as f:
        assert list(f["TRAN/shocks"]) == ["CHOC1", "CHOC1_2", "CHOC_3"]
    assert [s.name for s in load_tran_gene(path).shocks] == ["CHOC1", "CHOC1", ""]


def test_steps_and_nodal_series_of_results():
    basis = small_transient().basis
    steps = result_steps(basis)
    assert steps.orders.tolist() == [1, 2] and steps.parameters(1) == {
        "NUME_MODE": 2,
        "FREQ": 2.0,
    }
    nodes, comps, values = nodal_series(basis, "DEPL", nodes=[1], components=("DY",))
    assert nodes.tolist() == [1] and comps == ("DY",)
    assert values[:, 0, 0].tolist() == [0.0, -1.0]
    with pytest.raises(KeyError):
        nodal_series(basis, "VITE")


def test_select_steps_by_each_access():
    steps = ResultSteps(np.array([1, 3, 5]), times=np.array([0.0, 0.5, 1.0]))
    assert select_steps(steps).tolist() == [0, 1, 2]
    assert select_steps(steps, nume_ordre=(5, 1)).tolist() == [2, 0]
    assert select_steps(steps, inst=(0.5 + 1e-9,)).tolist() == [1]
    assert select_steps(steps, inst=(0.52,), precision=0.05, criterion="ABSOLU").tolist() == [1]
    with pytest.raises(CommandError, match="no stored instant matches 0.7"):
        select_steps(steps, inst=(0.7,))
    with pytest.raises(CommandError, match="NUME_ORDRE 2 is not stored"):
        select_steps(steps, nume_ordre=(2,))
    with pytest.raises(CommandError, match="FREQ needs"):
        select_steps(steps, freq=(1.0,))


# ----------------------------------------------------------------- tables kept with a result


def mixed_table() -> Table:
    """Sparse rows and every kind of column: R (with a NaN value, kept),
    I, K16, C, and parameter names HDF5 cannot take as they are."""
    table = Table(title="MIXED\nsecond line")
    table.add_column("INST", "R")
    table.add_column("NUME_ORDRE", "I")
    table.add_column("NOEUD", "K16")
    table.add_column("VALE_C", "C")
    table.add_column("A/B", "R")
    table.add_column("A_B", "R")
    table.add_column("A.B", "R")
    table.add_row({"INST": 0.0, "NUME_ORDRE": 1, "NOEUD": "N1", "VALE_C": 1 + 2j, "A/B": 1.0})
    table.add_row({"INST": 0.5, "NUME_ORDRE": 2, "A_B": 2.0, "A.B": float("nan")})
    table.add_row({})  # a row with no value at all stays a row
    table.add_row({"NOEUD": "a longer name", "NUME_ORDRE": 3, "A/B": -1.5e-300})
    return table


def assert_same_table(back: Table, original: Table) -> None:
    assert back.columns == original.columns
    assert back.types == original.types
    assert back.title == original.title
    assert len(back.rows) == len(original.rows)
    for got, want in zip(back.rows, original.rows, strict=True):
        assert set(got) == set(want)
        for key, value in want.items():
            assert type(got[key]) is type(value), key
            assert got[key] == value or (value != value and got[key] != got[key]), key


def test_tables_round_trip_with_types_and_absent_values(tmp_path):
    original = rich_transient()
    table = mixed_table()
    original.tables = {"MIXED": table, "EMPTY": Table(title="nothing")}
    path = save_tran_gene(tmp_path / "r.h5", original)
    back = load_tran_gene(path)
    assert list(back.tables) == ["MIXED", "EMPTY"]
    assert_same_table(back.tables["MIXED"], table)
    assert_same_table(back.tables["EMPTY"], original.tables["EMPTY"])
    assert back.tables["MIXED"]["NOEUD", 4] == "a longer name"
    assert back.tables["MIXED"]["VALE_C", 2] is None
    # plain data: typed arrays, fillers where a row lacks the parameter
    data = read_tran_gene_dict(path)["tables"]["MIXED"]
    assert data["n_rows"] == 4 and data["types"]["NOEUD"] == "K16"
    assert data["columns"]["NUME_ORDRE"].dtype == np.int64
    assert data["columns"]["VALE_C"].dtype.kind == "c"
    assert data["columns"]["NOEUD"] == ["N1", "", "", "a longer name"]
    assert data["present"]["INST"].tolist() == [True, True, False, False]
    assert "A/B" in data["present"] and "VALE_C" in data["present"]
    with h5py.File(path, "r") as f:
        group = f["TRAN/tables/MIXED"]
        assert group.attrs["name"] == "MIXED" and group.attrs["n_rows"] == 4
        assert list(group["columns"]) == [
            "INST", "NUME_ORDRE", "NOEUD", "VALE_C", "A_B", "A_B_2", "A_B_3"
        ]  # fmt: skip
        assert group["columns/A_B"].attrs["parameter"] == "A/B"
        assert group["columns/A_B_3"].attrs["parameter"] == "A.B"
        # absent values are filled with 0, not NaN: only the stored NaN is one
        assert group["columns/INST"][()].tolist() == [0.0, 0.5, 0.0, 0.0]
        assert np.isnan(group["columns/A_B_3"][()]).tolist() == [False, True, False, False]
        assert "EMPTY" in f["TRAN/tables"] and "present" not in f["TRAN/tables/EMPTY"]


def test_a_result_without_tables_round_trips(tmp_path):
    original = rich_transient()
    assert original.tables == {}
    path = save_tran_gene(tmp_path / "r.h5", original)
    with h5py.File(path, "r") as f:
        assert list(f["TRAN/tables"]) == []
    assert load_tran_gene(path).tables == {}
    # files written before tables were stored (layout_version 1) load too
    with h5py.File(path, "a") as f:
        del f["TRAN/tables"]
        f["TRAN"].attrs["layout_version"] = 1
    back = load_tran_gene(path)
    assert back.tables == {} and np.array_equal(back.depl, original.depl)


def test_a_failed_save_leaves_the_file_as_it_was(tmp_path):
    path = tmp_path / "r.h5"
    save_tran_gene(path, rich_transient())
    before = path.read_bytes()
    broken = rich_transient()
    broken.name = "BROKEN"
    table = Table()
    table.add_row({"X": 1.0})
    table.rows[0]["X"] = "not a number"  # an R cell that cannot be written
    broken.tables = {"T": table}
    with pytest.raises(ValueError):
        save_tran_gene(path, broken)
    with pytest.raises(ValueError):
        save_session_results(path, {"OTHER": small_transient(), "BROKEN": broken})
    assert path.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.h5"]  # no temporary left
    assert stored_names(path) == ["TRAN"]
    with pytest.raises(ValueError):
        save_tran_gene(tmp_path / "new.h5", broken)
    assert not (tmp_path / "new.h5").exists()


def test_a_run_saves_the_energy_table_of_its_tran_gene(tmp_path):
    """``asterlite run --save-results`` on a deck with ENERGIE=_F(): the
    PARA_CALC table comes back from results.h5 as the run built it."""
    from asterlite.dynamics.energy import COLUMNS
    from asterlite.runtime.runner import run_deck

    from .test_energy_gene import friction_session

    session = friction_session(tmp_path)
    table = session.namespace["RESUGENE"].tables["PARA_CALC"]
    report = run_deck(tmp_path / "deck.export", tmp_path / "run", save_results=True)
    assert report.status == "PASS"
    store = tmp_path / "run" / "results.h5"
    back = load_tran_gene(store, "RESUGENE")
    assert list(back.tables) == ["PARA_CALC"]
    assert back.tables["PARA_CALC"].columns == list(COLUMNS)
    assert_same_table(back.tables["PARA_CALC"], table)
    assert len(table.rows) == len(back.times)
    # an in-memory save of the session gives the same table
    save_session_results(tmp_path / "session.h5", session.namespace)
    assert_same_table(load_tran_gene(tmp_path / "session.h5").tables["PARA_CALC"], table)
    with h5py.File(store, "r") as f:
        columns = f["RESUGENE/tables/PARA_CALC/columns"]
        assert columns["RESIDU"].attrs["type"] == "R"
        assert np.array_equal(columns["INST"][()], back.times)
