"""AFFE_CHAR_MECA/LIAISON_GROUP: nodes of list 1, moved by ANGL_NAUT about
CENTRE then TRAN, paired with the nearest nodes of list 2 (code_aster's
pacoap), one relation per pair."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import Model
from asterlite.concepts.mesh import Mesh
from asterlite.errors import CommandError
from tests.test_fem_support import FakeSession, run


def _model():
    xs = [0.0, 1.0, 2.0]
    coords = [(x, 0.0, 0.0) for x in xs] + [(x, 1.0, 0.0) for x in reversed(xs)]
    mesh = Mesh(
        coords=np.array(coords),
        node_names=["A1", "A2", "A3", "B3", "B2", "B1"],
        cell_names=[f"P{i}" for i in range(6)],
        cell_types=["POI1"] * 6,
        cell_nodes=[(i,) for i in range(6)],
        node_groups={"A": np.array([0, 1, 2]), "B": np.array([3, 4, 5]), "B1": np.array([5])},
    )
    return Model(mesh=mesh, cell_modelisation={c: "DIS_T" for c in range(6)})


def _liaison(model, **extra):
    occ = {
        "GROUP_NO_1": "A",
        "GROUP_NO_2": "B",
        "DDL_1": ("DX", "DY"),
        "COEF_MULT_1": (1.0, 2.0),
        "DDL_2": ("DX",),
        "COEF_MULT_2": (-1.0,),
        "COEF_IMPO": 0.25,
        **extra,
    }
    return run(FakeSession(), "AFFE_CHAR_MECA", MODELE=model, LIAISON_GROUP=occ)


def test_pairs_by_translation():
    model = _model()
    load = _liaison(model, TRAN=(0.0, 1.0, 0.0))
    names = model.mesh.node_names
    pairs = [(names[r.terms[0][0]], names[r.terms[2][0]]) for r in load.relations]
    assert pairs == [("A1", "B1"), ("A2", "B2"), ("A3", "B3")]
    first = load.relations[0]
    assert [(c, k) for _, c, k in first.terms] == [("DX", 1.0), ("DY", 2.0), ("DX", -1.0)]
    assert first.rhs == 0.25


def test_pairs_by_rotation_and_exclusion():
    """A half turn about z through (1, 0.5, 0) takes A1 to (2, 1, 0): B3."""
    model = _model()
    load = _liaison(model, ANGL_NAUT=(180.0, 0.0, 0.0), CENTRE=(1.0, 0.5, 0.0), SANS_GROUP_NO="B1")
    names = model.mesh.node_names
    pairs = [(names[r.terms[0][0]], names[r.terms[2][0]]) for r in load.relations]
    assert pairs == [("A1", "B3"), ("A2", "B2")]  # A3 faces B1, left out


def test_two_nodes_facing_one_is_an_error():
    model = _model()
    model.mesh.coords[4] = (2.0, 1.0, 0.0)  # B2 moved onto B3's neighbourhood
    model.mesh.coords[3] = (5.0, 5.0, 0.0)
    with pytest.raises(CommandError, match="both face"):
        _liaison(model, TRAN=(0.0, 1.0, 0.0))


def test_liaison_chamno_one_relation_from_the_non_zero_values():
    from asterlite.concepts.assembly import NodalField

    model = _model()
    numbering = run(FakeSession(), "NUME_DDL", MODELE=model)
    values = np.zeros(numbering.n_dofs)
    values[numbering.dof_indices([0], "DY")[0]] = 1.0
    values[numbering.dof_indices([4], "DY")[0]] = -2.5
    field = NodalField(numbering=numbering, values=values)
    load = run(
        FakeSession(),
        "AFFE_CHAR_MECA",
        MODELE=model,
        LIAISON_CHAMNO={"CHAM_NO": field, "COEF_IMPO": 0.5},
    )
    (relation,) = load.relations
    assert sorted(relation.terms) == [(0, "DY", 1.0), (4, "DY", -2.5)]
    assert relation.rhs == 0.5
    with pytest.raises(CommandError, match="no non-zero value"):
        run(
            FakeSession(),
            "AFFE_CHAR_MECA",
            MODELE=model,
            LIAISON_CHAMNO={"CHAM_NO": NodalField(numbering, 0 * values), "COEF_IMPO": 0.0},
        )
