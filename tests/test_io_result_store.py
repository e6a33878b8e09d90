"""HDF5 result store (asterlite.io.result_store): layout and round trips."""

from __future__ import annotations

from pathlib import Path

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
    table.add_row({"X": "\udcff"})  # a text cell that cannot be written (no UTF-8 form)
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


# ----------------------------------------------------------------- bases of every kind


def assert_same_physical_basis(back, original) -> None:
    assert type(back) is type(original) and back.name == original.name
    assert back.numbering.dofs == original.numbering.dofs
    assert back.kind == original.kind and back.norm == original.norm
    np.testing.assert_array_equal(back.shapes, original.shapes)
    np.testing.assert_array_equal(back.frequencies, original.frequencies)
    np.testing.assert_array_equal(back.generalized_mass, original.generalized_mass)
    np.testing.assert_array_equal(back.mode_numbers, original.mode_numbers)
    assert back.mode_labels == original.mode_labels
    assert back.numbering.mesh.node_names == original.numbering.mesh.node_names
    np.testing.assert_array_equal(back.numbering.mesh.coords, original.numbering.mesh.coords)
    for key, value in original.parameters.items():
        assert np.asarray(back.parameters[key]).tolist() == np.asarray(value).tolist(), key


def assert_same_interfaces(back, original) -> None:
    assert back.name == original.name and back.frequency == original.frequency
    assert [i.name for i in back.interfaces] == [i.name for i in original.interfaces]
    for got, want in zip(back.interfaces, original.interfaces, strict=True):
        assert (got.kind, tuple(got.masked)) == (want.kind, tuple(want.masked))
        for key in ("nodes", "dofs", "dof_nodes"):
            np.testing.assert_array_equal(getattr(got, key), getattr(want, key))


def assert_same_substructured_modes(back, original) -> None:
    """Generalized modes on a DEFI_MODELE_GENE numbering, rebuilt down to the
    substructures' macro-elements, their bases and interfaces."""
    from asterlite.concepts.modes import GeneralizedModes
    from asterlite.concepts.substructure import ReductionBasis, SubstructuredNumbering
    from asterlite.substructure.coupling import constraint_rows
    from asterlite.substructure.restitution import substructure_modes

    assert isinstance(back, GeneralizedModes) and back.name == original.name
    for key in ("vectors", "frequencies", "generalized_mass", "generalized_stiffness"):
        np.testing.assert_array_equal(getattr(back, key), getattr(original, key))
    np.testing.assert_array_equal(back.mode_numbers, original.mode_numbers)
    numbering, want = back.numbering, original.numbering
    assert isinstance(numbering, SubstructuredNumbering) and numbering.basis is None
    assert (numbering.name, numbering.storage, numbering.method) == (
        want.name,
        want.storage,
        want.method,
    )
    np.testing.assert_array_equal(numbering.offsets, want.offsets)
    np.testing.assert_array_equal(numbering.constraints, want.constraints)
    model, model_want = numbering.model, want.model
    assert model.name == model_want.name
    assert [s.name for s in model.substructures] == ["COTE1", "COTE2"]
    for sub, sub_want in zip(model.substructures, model_want.substructures, strict=True):
        np.testing.assert_array_equal(sub.rotation, sub_want.rotation)
        np.testing.assert_array_equal(sub.translation, sub_want.translation)
        macro, macro_want = sub.macro, sub_want.macro
        assert macro.name == macro_want.name
        np.testing.assert_array_equal(macro.stiffness, macro_want.stiffness)
        np.testing.assert_array_equal(macro.mass, macro_want.mass)
        assert isinstance(macro.basis, ReductionBasis)
        assert_same_physical_basis(macro.basis, macro_want.basis)
        assert macro.interfaces is macro.basis.interfaces  # as MACR_ELEM_DYNA shares them
        assert_same_interfaces(macro.interfaces, macro_want.interfaces)
    assert [vars(link) for link in model.links] == [vars(link) for link in model_want.links]
    # it couples and restores as the original: the same relations, the same shapes
    np.testing.assert_allclose(constraint_rows(model, numbering.offsets), want.constraints)
    every = np.arange(back.n_modes)
    restored = substructure_modes(back, "COTE2", every).shapes
    np.testing.assert_array_equal(restored, substructure_modes(original, "COTE2", every).shapes)


SUBSTRUCTURED_TRANSIENTS = """
PUSH = AFFE_CHAR_MECA(MODELE=MODEL, FORCE_NODALE=_F(NOEUD="N2", FY=-200.0))
FEL = CALC_VECT_ELEM(OPTION="CHAR_MECA", CHARGE=PUSH)
FAS = ASSE_VECTEUR(VECT_ELEM=FEL, NUME_DDL=NU_R)
FGEN = ASSE_VECT_GENE(NUME_DDL_GENE=NUMEGE, CHAR_SOUS_STRUC=_F(SOUS_STRUC="COTE2", VECT_ASSE=FAS))
NUMODE = NUME_DDL_GENE(BASE=RESGEN, STOCKAGE="DIAG")
KPRO = PROJ_MATR_BASE(BASE=RESGEN, NUME_DDL_GENE=NUMODE, MATR_ASSE_GENE=KGEN)
MPRO = PROJ_MATR_BASE(BASE=RESGEN, NUME_DDL_GENE=NUMODE, MATR_ASSE_GENE=MGEN)
FPRO = PROJ_VECT_BASE(BASE=RESGEN, NUME_DDL_GENE=NUMODE, VECT_ASSE_GENE=FGEN, TYPE_VECT="FORC")
ON_MODES = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="GENE", SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"),
    MATR_MASS=MPRO, MATR_RIGI=KPRO, EXCIT=_F(VECT_ASSE_GENE=FPRO, COEF_MULT=1.0),
    INCREMENT=_F(INST_INIT=0.0, INST_FIN=1.0e-3, PAS=1.0e-5))
DIRECT = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="GENE", SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"),
    MATR_MASS=MGEN, MATR_RIGI=KGEN, EXCIT=_F(VECT_ASSE_GENE=FGEN, COEF_MULT=1.0),
    INCREMENT=_F(INST_INIT=0.0, INST_FIN=1.0e-3, PAS=1.0e-5))
FIN()
"""


def test_substructured_transients_are_saved_and_read_back_as_they_are(tmp_path):
    """``--save-results`` on a coupled model (DEFI_MODELE_GENE): a transient on
    the coupled modes (a mode_gene, PROJ_BASE) and one on the assembled
    generalized matrices (the null space of the interface relations) come
    back with their generalized bases, never as a physical basis."""
    from asterlite import api
    from asterlite.concepts.modes import GeneralizedModes
    from asterlite.post.plots import PlotError, node_history
    from asterlite.runtime.runner import run_deck
    from asterlite.substructure.restitution import substructure_modes

    from .test_substructure_beam import LENGTH, beam_mesh, substructured_deck

    deck = substructured_deck(nmax=2, clamped=True).replace("FIN()\n", SUBSTRUCTURED_TRANSIENTS)
    (tmp_path / "cut.comm").write_text(deck)
    (tmp_path / "cut.mail").write_text(beam_mesh(4, LENGTH / 2))
    report = run_deck(tmp_path / "cut.comm", tmp_path / "run", save_results=True)
    assert report.status == "DONE", report.message
    store = tmp_path / "run" / "results.h5"
    assert stored_names(store) == ["ON_MODES", "DIRECT"]
    for name in ("ON_MODES", "DIRECT"):
        original, back = report.namespace[name], load_tran_gene(store, name)
        assert isinstance(original.basis, GeneralizedModes)
        for field in ("times", "order", "depl", "vite", "acce"):
            np.testing.assert_array_equal(getattr(back, field), getattr(original, field))
        assert_same_substructured_modes(back.basis, original.basis)
    assert load_tran_gene(store, "ON_MODES").basis.name == "RESGEN"
    # as plain data and with h5py: the kind of basis and what it is built on
    data = read_tran_gene_dict(store, "DIRECT")["basis"]
    assert data["basis_type"] == "mode_gene" and "shapes" not in data
    assert data["numbering"]["built_on"] == "modele_gene"
    assert data["numbering"]["substructure_names"] == ["COTE1", "COTE2"]
    assert data["vectors"].shape == (8, 6)  # 4 unknowns per side, 2 interface relations
    with h5py.File(store, "r") as f:
        basis = f["ON_MODES/basis"]
        assert basis.attrs["basis_type"] == "mode_gene" and basis.attrs["name"] == "RESGEN"
        assert f["ON_MODES"].attrs["layout_version"] == 3
        numbering = basis["numbering"]
        assert numbering["offsets"][()].tolist() == [0, 4, 8]
        assert list(numbering["model/macros"]) == ["ME_L", "ME_R"]
        cote2 = numbering["model/substructures/COTE2"]
        assert cote2.attrs["macro"] == "ME_R" and cote2["translation"][()][0] == LENGTH / 2
        macro_basis = numbering["model/macros/ME_R/basis"]
        assert macro_basis.attrs["basis_type"] == "mode_meca"
        assert list(macro_basis["interfaces"]) == ["GAUCHE"]
        # COTE2's physical displacement as docs/results.md restores it
        q = f["ON_MODES/depl"][()] @ basis["vectors"][()].T
        u = q[:, 4:8] @ macro_basis["shapes"][()].T
    original = report.namespace["ON_MODES"]
    every = np.arange(original.n_modes)
    restored = substructure_modes(original.basis, "COTE2", every).shapes
    np.testing.assert_allclose(u, original.depl @ restored.T, rtol=0, atol=1e-12 * abs(u).max())
    # as data (asterlite.load) and for plots, a generalized basis is what it is
    data = api.load(store, "DIRECT")
    assert np.asarray(data["vectors"]).shape == (8, 6) and "shapes" not in data
    with pytest.raises(PlotError, match="the result has a mode_gene basis"):
        node_history(load_tran_gene(store, "DIRECT"), "N2", "DY")


@pytest.mark.parametrize("kind", ["none", "mode_gene", "mode_meca_c", "mode_flamb"])
def test_every_kind_of_basis_round_trips(tmp_path, kind):
    """No basis (REST_SPEC_TEMP of a harm_gene on a coupled model's
    matrices), generalized modes on a projection basis (a mode_gene of
    PROJ_MATR_BASE's matrices), complex and buckling modes."""
    from asterlite.concepts.modes import (
        BucklingModes,
        ComplexModeResult,
        GeneralizedModes,
        GeneralizedNumbering,
    )

    result = rich_transient()
    physical = result.basis
    if kind == "none":
        result.basis = None
    elif kind == "mode_gene":
        numbering = GeneralizedNumbering(basis=physical, storage="DIAG")
        numbering.name = "NUMGEN"
        result.basis = GeneralizedModes(
            numbering=numbering,
            vectors=np.array([[1.0, 0.5], [0.0, 2.0]]),
            frequencies=np.array([1.5, 3.0]),
            generalized_mass=np.ones(2),
            generalized_stiffness=np.array([9.0, 36.0]) * np.pi**2,
            parameters={"NUME_MODE": np.array([1, 2]), "MASS_EFFE_DX": np.array([0.2, 0.1])},
        )
    else:
        cls = ComplexModeResult if kind == "mode_meca_c" else BucklingModes
        fields = {f: getattr(physical, f) for f in physical.__dataclass_fields__}
        fields["parameters"] = {"NUME_MODE": np.array([1, 2]), "CHAR_CRIT": np.array([-2.0, 5.0])}
        if kind == "mode_meca_c":
            fields["shapes"] = physical.shapes * (1.0 + 0.5j)
            fields["eigenvalues"] = np.array([-0.1 + 6.0j, -0.2 + 12.0j])
        result.basis = cls(**fields)
        result.basis.name = "MODES"
    path = save_tran_gene(tmp_path / "r.h5", result)
    back = load_tran_gene(path).basis
    assert read_tran_gene_dict(path)["basis"]["basis_type"] == kind
    if kind == "none":
        assert back is None
    elif kind == "mode_gene":
        assert isinstance(back, GeneralizedModes) and back.numbering.name == "NUMGEN"
        assert back.numbering.storage == "DIAG"
        np.testing.assert_array_equal(back.vectors, result.basis.vectors)
        assert back.parameters["MASS_EFFE_DX"].tolist() == [0.2, 0.1]
        assert_same_physical_basis(back.numbering.basis, physical)
    else:
        assert_same_physical_basis(back, result.basis)
        if kind == "mode_meca_c":
            np.testing.assert_array_equal(back.eigenvalues, result.basis.eigenvalues)


SUBSTRUCTURING_CORPUS = Path(__file__).resolve().parents[2] / "shared" / "aster-corpus-wider"


@pytest.mark.parametrize("name", ["sdld102a", "sdll113a"])
def test_save_results_of_substructuring_corpus_decks(tmp_path, name):
    """The code_aster tests of dynamic substructuring with ``--save-results``:
    every tran_gene saved (transients on a coupled model's modes or on its
    assembled matrices, and on physical bases), each with its own kind of basis."""
    from asterlite.runtime.runner import run_deck

    export = SUBSTRUCTURING_CORPUS / name / f"{name}.export"
    if not export.exists():
        pytest.skip("the wider corpus is not here")
    pytest.importorskip("pyuff")  # both read an I-DEAS mesh
    report = run_deck(export, tmp_path / "out", save_results=True)
    assert report.status == "PASS", report.message
    store = tmp_path / "out" / "results.h5"
    saved = {n: v for n, v in report.namespace.items() if isinstance(v, TranGene)}
    assert sorted(stored_names(store)) == sorted(saved)
    kinds = set()
    for key, original in saved.items():
        back = load_tran_gene(store, key)
        assert type(back.basis) is type(original.basis)
        np.testing.assert_array_equal(back.depl, original.depl)
        kinds.add(read_tran_gene_dict(store, key)["basis"]["basis_type"])
    assert kinds == {"mode_gene", "mode_meca"}
