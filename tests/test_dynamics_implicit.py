"""TRAITEMENT_NONL='IMPLICITE' (code_aster's dtmprep_noli): the implicit
treatment concerns DIS_CHOC connections only. Without any, the run is the
explicit one; with some, asterlite refuses the deck and says why."""

import numpy as np
import pytest

from asterlite.errors import UnsupportedError
from tests.test_dynamics_vibra import friction_shock, kws, one_mode, run_vibra, vector


def test_implicit_without_shocks_is_the_explicit_run():
    gnum, m, kk = one_mode(400.0)
    load = [kws("DYNA_VIBRA/EXCIT", VECT_ASSE_GENE=vector(gnum, 2.0, "FORC"), COEF_MULT=1.5)]
    runs = [
        run_vibra(
            m,
            kk,
            "NEWMARK",
            1.0e-3,
            0.5,
            etat={"DEPL": vector(gnum, 0.01)},
            EXCIT=load,
            TRAITEMENT_NONL=treatment,
        )  # fmt: skip
        for treatment in ("EXPLICITE", "IMPLICITE")
    ]
    np.testing.assert_array_equal(runs[1].depl, runs[0].depl)
    assert np.max(np.abs(runs[0].depl)) > 5e-3


def test_implicit_with_dis_choc_is_refused_with_the_reason():
    gnum, m, kk = one_mode(1.0e4)
    with pytest.raises(UnsupportedError, match="TRAITEMENT_NONL='IMPLICITE'.*EXPLICITE"):
        run_vibra(
            m, kk, "NEWMARK", 1.0e-4, 0.1, etat={"DEPL": vector(gnum, 1e-3)},
            comportement=[friction_shock()], TRAITEMENT_NONL="IMPLICITE",
        )  # fmt: skip


def test_explicit_with_dis_choc_runs():
    gnum, m, kk = one_mode(1.0e4)
    result = run_vibra(
        m, kk, "NEWMARK", 1.0e-4, 0.05, etat={"DEPL": vector(gnum, 1e-3)},
        comportement=[friction_shock()], TRAITEMENT_NONL="EXPLICITE",
    )  # fmt: skip
    assert result.shocks and np.all(np.isfinite(result.depl))
