"""DEFI_CHAR_SOL from a file of soil signals (UNITE_TRAN_INIT) and the
AFFE_CHAR_MECA_F nodal forces of INST it makes, on the spring-mass system of
test_calc_champ_nodal_forces (spring k from the clamped NA to NB of mass m,
the step force F on NB through the load TIRE gives the transient U)."""

from __future__ import annotations

import numpy as np

import asterlite
from tests.test_calc_champ_nodal_forces import MESH, F, columns, deck

# TABLE_MATER_ELAS of one layer (base at Y = 10) on its substratum (Y = 20)
SOIL = """TSOL = CREA_TABLE(LISTE=(
    _F(PARA="Y", LISTE_R=(10.0, 20.0)), _F(PARA="M", LISTE_K=("C1", "SUB")),
    _F(PARA="RHO", LISTE_R=(2000.0, 2000.0)), _F(PARA="Emax", LISTE_R=(1.0e8, 1.0e9)),
    _F(PARA="NU", LISTE_R=(0.3, 0.3)), _F(PARA="AH", LISTE_R=(0.0, 0.0)),
    _F(PARA="GDgam", LISTE_I=(1, 1))))
"""

TRANSIENT = """V = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="PHYS", MODELE=MODELE, CARA_ELEM=CARA,
               MATR_MASS=MATRMASS, MATR_RIGI=MATRRIGI, SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"),
               EXCIT=(_F(CHARGE=BLOCAGE), _F(CHARGE=SOLF)),
               INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.2, PAS=1.0e-4))"""


def signal_file(surface: float, base: float) -> str:
    """Six blocks as DEFI_SOL_EQUI's UNITE_RESU_TRAN: the sixth holds INST,
    the surface force, the force at the layer's base and at the substratum's."""
    blocks = []
    for number in range(1, 7):
        rows = [f"{t:.4f} {surface if number == 6 else 9.0} {base if number == 6 else 9.0} 7.0"
                for t in np.linspace(0.0, 0.4, 5)]  # fmt: skip
        blocks.append(f"#\nBLOC {number}\nINST F0 F1 F2\n" + "\n".join(rows))
    return "\n".join(blocks) + "\n"


def run(tmp_path, extra: str, signals: str):
    (tmp_path / "springs.comm").write_text(deck(SOIL + extra))
    (tmp_path / "springs.mail").write_text(MESH)
    (tmp_path / "soil.41").write_text(signals)
    (tmp_path / "springs.export").write_text(
        "P time_limit 300\nP memory_limit 2048\nP ncpus 1\n"
        "F comm springs.comm D 1\nF mail springs.mail D 20\nF libr soil.41 D 41\n"
    )
    return asterlite.run(tmp_path / "springs.export", tmp_path / "out")


def test_file_forces_interpolated_at_the_node_height_load_as_the_step(tmp_path):
    # Z0 = 5: the surface at Y = 5, the layer's base at Y = -5; NB (Y = 0) is
    # halfway, so 2F at the surface and 0 at the base give F there (FX: NOM_CMP='DY')
    done = run(
        tmp_path,
        "SOLF = DEFI_CHAR_SOL(MODELE=MODELE, UNITE_TRAN_INIT=41, TABLE_MATER_ELAS=TSOL,"
        ' Z0=5.0, NOM_CMP="DY", GROUP_MA_GAUCHE="GB")\n' + TRANSIENT,
        signal_file(2 * F, 0.0),
    )
    assert done.status == "DONE", done
    reference = columns(done.concepts.raw["U"], "DEPL")[1]
    motion = columns(done.concepts.raw["V"], "DEPL")[1]
    np.testing.assert_allclose(motion, reference, rtol=0, atol=1e-10 * np.abs(reference).max())


def test_right_side_takes_the_opposite_force(tmp_path):
    done = run(
        tmp_path,
        "SOLF = DEFI_CHAR_SOL(MODELE=MODELE, UNITE_TRAN_INIT=41, TABLE_MATER_ELAS=TSOL,"
        ' Z0=5.0, NOM_CMP="DY", GROUP_MA_DROITE="GB")\n' + TRANSIENT,
        signal_file(0.0, -2 * F),
    )
    assert done.status == "DONE", done
    reference = columns(done.concepts.raw["U"], "DEPL")[1]
    motion = columns(done.concepts.raw["V"], "DEPL")[1]
    np.testing.assert_allclose(motion, reference, rtol=0, atol=1e-10 * np.abs(reference).max())


def test_a_node_outside_the_column_is_refused_as_the_nappe_excludes_it(tmp_path):
    # Z0 = -1: the column spans Y in [-21, -1] (down to the substratum's base),
    # NB is above it (no extension)
    done = run(
        tmp_path,
        "SOLF = DEFI_CHAR_SOL(MODELE=MODELE, UNITE_TRAN_INIT=41, TABLE_MATER_ELAS=TSOL,"
        ' Z0=-1.0, NOM_CMP="DY", GROUP_MA_GAUCHE="GB")\n' + TRANSIENT,
        signal_file(2 * F, 0.0),
    )
    assert done.status == "ERROR" and "PROL_DROITE='EXCLU'" in done.message, done.message


def test_force_nodale_of_inst_is_a_history_for_the_transient(tmp_path):
    done = run(
        tmp_path,
        f'FF = FORMULE(NOM_PARA="INST", VALE="{F} + 0.0 * INST")\n'
        'SOLF = AFFE_CHAR_MECA_F(MODELE=MODELE, FORCE_NODALE=_F(GROUP_NO="GB", FX=FF))\n'
        + TRANSIENT,
        signal_file(0.0, 0.0),
    )
    assert done.status == "DONE", done
    reference = columns(done.concepts.raw["U"], "DEPL")[1]
    motion = columns(done.concepts.raw["V"], "DEPL")[1]
    np.testing.assert_allclose(motion, reference, rtol=0, atol=1e-10 * np.abs(reference).max())


def test_force_nodale_of_inst_is_refused_where_a_fixed_vector_is_taken(tmp_path):
    done = run(
        tmp_path,
        f'FF = FORMULE(NOM_PARA="INST", VALE="{F} + 0.0 * INST")\n'
        'SOLF = AFFE_CHAR_MECA_F(MODELE=MODELE, FORCE_NODALE=_F(GROUP_NO="GB", FX=FF))\n'
        "VS = CALC_VECT_ELEM(OPTION='CHAR_MECA', CHARGE=SOLF, CARA_ELEM=CARA)\n",
        signal_file(0.0, 0.0),
    )
    assert done.status == "UNSUPPORTED"
    assert "functions of INST" in done.message, done.message
