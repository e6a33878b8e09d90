"""A scheme added through the documented places only (tests/toy_scheme.py:
its module and its entry in asterlite.dynamics.schemes) runs a deck: the
catalogue accepts its SCHEMA, the command checks and integrates it, and
the archived states follow the scheme's own map, not another scheme's."""

from __future__ import annotations

import numpy as np
import pytest

from tests.one_dof_deck import one_dof_prelude, run_in_a_new_python

DECK = (
    one_dof_prelude(2.0, 8.0e3, 3.0e-3)
    + """RESUGENE = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="GENE",
                      SCHEMA_TEMPS=_F(SCHEMA="TOY_EULER"),
                      MATR_MASS=MASSEGEN, MATR_RIGI=RIGIDGEN,
                      ETAT_INIT=_F(DEPL=DEPINI),
                      INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.1, PAS=1.0e-3))
FIN()
"""
)

RUN = """
import json, sys
import tests.toy_scheme
import asterlite
result = asterlite.run(sys.argv[1])
gene = result.concepts.raw["RESUGENE"]
stiffness = gene.basis.generalized_stiffness / gene.basis.generalized_mass
print(json.dumps({"status": result.status, "message": result.message, "scheme": gene.scheme,
                  "omega2": float(stiffness[0]), "times": gene.times.tolist(),
                  "q": gene.depl[:, 0].tolist(), "v": gene.vite[:, 0].tolist()}))
"""


@pytest.mark.slow
def test_a_toy_scheme_runs_a_deck_through_the_documented_places(tmp_path):
    run = run_in_a_new_python(tmp_path, DECK, RUN)
    assert run["status"] == "DONE", run["message"]  # no TEST_* in the deck
    assert run["scheme"] == "TOY_EULER"
    times, q, v = (np.array(run[k]) for k in ("times", "q", "v"))
    assert len(times) == 101 and times[-1] == pytest.approx(0.1)
    dt, w2 = 1.0e-3, run["omega2"]
    toy = np.array([[1.0, dt], [-w2 * dt, 1.0 - w2 * dt * dt]])  # q first, then v
    centre = np.array([[1.0 - w2 * dt * dt, dt], [-w2 * dt, 1.0]])  # DIFF_CENTRE: v first
    state = expected_toy = np.array([q[0], v[0]])
    expected_centre = state
    for k in range(1, len(times)):
        expected_toy = toy @ expected_toy
        expected_centre = centre @ expected_centre
        assert q[k] == pytest.approx(expected_toy[0], rel=1e-9, abs=1e-15)
        assert v[k] == pytest.approx(expected_toy[1], rel=1e-9, abs=1e-15)
    assert abs(q[-1] - expected_centre[0]) > 1e-6 * abs(q).max()  # another map: not DIFF_CENTRE
