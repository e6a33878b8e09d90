"""DEFI_LIST_INST (METHODE='MANUEL', ECHEC on ERREUR) and DEFI_MATERIAU's
Iwan parameters, kept as code_aster keeps them."""

from __future__ import annotations

import numpy as np

import asterlite

DECK = """DEBUT(CODE="OUI")
TEMPS = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, PAS=0.25))
DL = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=TEMPS),
                    ECHEC=_F(SUBD_METHODE="MANUEL", SUBD_PAS=2, SUBD_NIVEAU=10))
DV = DEFI_LIST_INST(DEFI_LIST=_F(VALE=(0.0, 0.5, 2.0)))
SOL = DEFI_MATERIAU(ELAS=_F(E=5.0e8, NU=0.49, RHO=1800.0),
                    Iwan=_F(YoungModulus=5.0e8, PoissonRatio=0.49,
                            HypDistortion=1.25e-4, HypExponent=0.78))
{extra}
FIN()
"""


def run(tmp_path, extra=""):
    tmp_path.mkdir(exist_ok=True)
    (tmp_path / "d.comm").write_text(DECK.format(extra=extra))
    (tmp_path / "d.export").write_text("P time_limit 60\nP memory_limit 512\nF comm d.comm D 1\n")
    return asterlite.run(tmp_path / "d.export", tmp_path / "out")


def test_list_inst_and_iwan_material(tmp_path):
    done = run(tmp_path)
    assert done.status == "DONE", done
    listed = done.concepts.raw["DL"]
    assert listed.aster_type == "list_inst"
    np.testing.assert_array_equal(listed.values, [0.0, 0.25, 0.5, 0.75, 1.0])
    (failure,) = listed.failures
    assert failure["EVENEMENT"] == "ERREUR" and failure["ACTION"] == "DECOUPE"
    assert (failure["SUBD_PAS"], failure["SUBD_NIVEAU"], failure["SUBD_PAS_MINI"]) == (2, 10, 0.0)
    # the default ECHEC occurrence: code_aster's defaults
    (default,) = done.concepts.raw["DV"].failures
    assert (default["SUBD_PAS"], default["SUBD_NIVEAU"]) == (4, 3)
    iwan = done.concepts.raw["SOL"].behaviours["Iwan"]
    assert iwan["HypDistortion"] == 1.25e-4 and iwan["HypExponent"] == 0.78


def test_decreasing_instants_and_automatic_stepping_are_refused(tmp_path):
    done = run(tmp_path / "a", "DB = DEFI_LIST_INST(DEFI_LIST=_F(VALE=(0.0, 1.0, 0.5)))")
    assert done.status == "ERROR" and "strictly increasing" in done.message
    done = run(tmp_path / "b", "DA = DEFI_LIST_INST(METHODE='AUTO', DEFI_LIST=_F(VALE=(0.0, 1.0)))")
    assert done.status == "UNSUPPORTED", done
