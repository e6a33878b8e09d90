"""A relation added through the documented places only (tests/toy_relation.py:
its module, and its entries in connections.RELATIONS, dyna_vibra_relations.
READERS and the COMPORTEMENT catalogue) runs a deck: the catalogue accepts
RELATION='TOY_RESSORT' and its keywords, the command reads them into the
relation's record, and the time loop applies F = -RAIDEUR u. On the
one-node oscillator (mass 2, stiffness 8e3 on DX) a spring of 8e3 to the
ground doubles the stiffness: DIFF_CENTRE's archived states follow its map
with ω² = (8e3 + 8e3)/2 step by step, and the closed form u0 cos(ω t) to
the scheme's error (ω dt), far from the oscillator's own ω² = 8e3/2."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.one_dof_deck import one_dof_prelude, run_in_a_new_python

MASS, STIFFNESS, SPRING, U0, DT, T_END = 2.0, 8.0e3, 8.0e3, 3.0e-3, 1.0e-4, 0.1

DECK = (
    one_dof_prelude(MASS, STIFFNESS, U0)
    + f"""RESUGENE = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="GENE",
                      SCHEMA_TEMPS=_F(SCHEMA="DIFF_CENTRE"),
                      MATR_MASS=MASSEGEN, MATR_RIGI=RIGIDGEN,
                      ETAT_INIT=_F(DEPL=DEPINI),
                      COMPORTEMENT=_F(RELATION="TOY_RESSORT", GROUP_NO="N1", NOM_CMP="DX",
                                      RAIDEUR={SPRING}),
                      INCREMENT=_F(INST_INIT=0.0, INST_FIN={T_END}, PAS={DT}))
FIN()
"""
)

RUN = """
import json, sys
import tests.toy_relation
import asterlite
result = asterlite.run(sys.argv[1])
gene = result.concepts.raw["RESUGENE"]
(spring,) = gene.shocks
print(json.dumps({"status": result.status, "message": result.message,
                  "relation": spring.relation, "name": spring.name, "node": spring.node_1,
                  "times": gene.times.tolist(), "q": gene.depl[:, 0].tolist(),
                  "u": spring.fields["ALLONGEMENT"].tolist(),
                  "force": spring.fields["VINT2"].tolist()}))
"""


@pytest.mark.slow
def test_a_toy_relation_runs_a_deck_through_the_documented_places(tmp_path):
    run = run_in_a_new_python(tmp_path, DECK, RUN)
    assert run["status"] == "DONE", run["message"]  # no TEST_* in the deck
    assert (run["relation"], run["node"]) == ("TOY_RESSORT", "N1")
    assert run["name"].startswith("TOY_RESSORT") and run["name"].endswith("00000001")
    times, q, u, force = (np.array(run[k]) for k in ("times", "q", "u", "force"))
    assert len(times) == round(T_END / DT) + 1 and times[-1] == pytest.approx(T_END)
    assert u[0] == pytest.approx(U0, rel=1e-12)
    # the archived force is the spring's, on the displacement the kernel saw
    np.testing.assert_allclose(force, -SPRING * u, rtol=1e-12, atol=1e-12 * SPRING * U0)
    np.testing.assert_allclose(u, u[0] / q[0] * q, rtol=1e-12)  # u = φ q, one mode
    # DIFF_CENTRE's map (v first, then q) with the spring's stiffness added
    w2 = (STIFFNESS + SPRING) / MASS
    centre = np.array([[1.0 - w2 * DT * DT, DT], [-w2 * DT, 1.0]])
    state = np.array([U0, 0.0])
    for k in range(1, len(times)):
        state = centre @ state
        assert u[k] == pytest.approx(state[0], rel=1e-9, abs=1e-12 * U0)
    # the closed form, to the scheme's error: DIFF_CENTRE starts from v0 without a
    # half step, which shifts the phase by about ω dt / 2 (measured: 0.45 % of u0)
    omega = math.sqrt(w2)
    exact = U0 * np.cos(omega * times)
    assert np.max(np.abs(u - exact)) < omega * DT * U0
    own = U0 * np.cos(math.sqrt(STIFFNESS / MASS) * times)
    assert np.max(np.abs(u - own)) > 0.5 * U0  # the spring acts: not the bare oscillator
