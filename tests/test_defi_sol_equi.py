"""DEFI_SOL_EQUI: the column of two-node shear cells against the closed-form
transfer functions of vertical S waves, the strain iteration, and the
command on a small deck (its files, its refusals)."""

from __future__ import annotations

import numpy as np
import pytest

import asterlite
from asterlite.concepts.function import Function
from asterlite.harmonic.soil_column import StrainCurve
from asterlite.harmonic.sol_equi import ColumnCell, column_response, equivalent_linear_column

RHO, NU = 2000.0, 0.3


def _young(vs, rho=RHO, nu=NU):
    return 2.0 * (1.0 + nu) * rho * vs * vs


def _fine_column(layers, substratum, step):
    """Cells of at most ``step`` m: layers [(thickness, vs, eta)], then a
    substratum cell (thickness, vs)."""
    cells, depth = [], 0.0
    for thickness, vs, eta in layers:
        n = int(round(thickness / step))
        for _ in range(n):
            depth += thickness / n
            cells.append(ColumnCell(depth, "C", RHO, _young(vs), NU, eta, 1))
    thickness, vs = substratum
    cells.append(ColumnCell(depth + thickness, "SUB", RHO, _young(vs), NU, 0.0, 1))
    return cells


def _incident_response(cells, freqs, lysmer=False):
    """Nodal displacements per unit incident velocity at the base: the
    ONDE_PLANE load -2 ρ Vs v (asterlite.fem.plane_wave's S wave along +y,
    polarised along -x)."""
    base = cells[-1]
    rho_vs = np.sqrt(base.density * base.young / (2.0 * (1.0 + base.poisson)))
    load = -2.0 * rho_vs * np.ones(len(freqs))
    young = [c.young for c in cells[:-1]]
    loss = [c.loss for c in cells[:-1]]
    return column_response(cells, young, loss, lysmer, load, freqs)


def test_a_uniform_column_lets_the_wave_through_to_a_doubled_surface_motion():
    # no contrast: the surface moves twice the incident displacement -v/(iω),
    # delayed by the whole height over Vs
    vs, height = 300.0, 60.0
    cells = _fine_column([(59.75, vs, 0.0)], (0.25, vs), 0.25)
    freqs = np.array([0.5, 2.0, 5.0])
    surface = _incident_response(cells, freqs)[0]
    w = 2 * np.pi * freqs
    exact = 2.0 * (-1.0 / (1j * w)) * np.exp(-1j * w * height / vs)
    assert np.allclose(surface, exact, rtol=2e-3)


@pytest.mark.parametrize("lysmer", [False, True])
def test_a_damped_layer_on_a_stiff_rock_amplifies_as_its_closed_form(lysmer):
    # surface / outcrop = 1 / (cos k*H + i α sin k*H), α = √(ρ G*)₁ / (ρ Vs)₂,
    # the outcrop moving twice the incident wave at the top of the rock
    vs1, vs2, eta, h_layer, h_rock = 200.0, 1500.0, 0.1, 30.0, 20.0
    # the rock: undamped cells, the last one the substratum's
    cells = _fine_column([(h_layer, vs1, eta), (h_rock - 0.1, vs2, 0.0)], (0.1, vs2), 0.1)
    freqs = np.array([0.8, 1.6, 3.0, 4.5])
    nodes = _incident_response(cells, freqs, lysmer)
    w = 2 * np.pi * freqs
    g = RHO * vs1**2
    g_star = (
        g * (1 - eta**2 / 2 + 1j * eta * np.sqrt(1 - eta**2 / 4)) if lysmer else g * (1 + 1j * eta)
    )
    k_star = w * np.sqrt(RHO / g_star)
    alpha = np.sqrt(RHO * g_star) / (RHO * vs2)
    outcrop = 2.0 * (-1.0 / (1j * w)) * np.exp(-1j * w * h_rock / vs2)
    exact = 1.0 / (np.cos(k_star * h_layer) + 1j * alpha * np.sin(k_star * h_layer))
    assert np.allclose(nodes[0] / outcrop, exact, rtol=5e-3)
    # the first resonance Vs / 4H is where the amplification peaks
    assert abs(exact[1]) > abs(exact[0]) and abs(exact[1]) > abs(exact[2])


def test_mono_appui_relative_motion_on_a_stiff_rock_is_the_rigid_base_amplification():
    # per unit base acceleration, 1 + the surface's relative acceleration is
    # 1 / cos(k*H) on a rigid base; a stiff, dense substratum comes close
    vs1, eta, h_layer = 200.0, 0.1, 30.0
    cells = _fine_column([(h_layer, vs1, eta)], (0.5, 2.0e6), 0.1)
    freqs = np.array([0.8, 1.6, 3.0])
    young = [c.young for c in cells[:-1]]
    loss = [c.loss for c in cells[:-1]]
    disp = column_response(cells, young, loss, False, None, freqs)
    w = 2 * np.pi * freqs
    k_star = w * np.sqrt(RHO / (RHO * vs1**2 * (1 + 1j * eta)))
    assert np.allclose(1.0 - w**2 * disp[0], 1.0 / np.cos(k_star * h_layer), rtol=5e-3)


def _pulse(dt=0.01, count=300, amplitude=3.0):
    t = dt * np.arange(count)
    acc = amplitude * np.sin(2 * np.pi * 2.0 * t) * np.exp(-(((t - 1.0) / 0.3) ** 2))
    return Function(t, acc, NOM_PARA="INST")


def test_the_iteration_takes_the_moduli_of_the_curves_at_the_effective_strain():
    cells = [
        ColumnCell(10.0, "C1", RHO, _young(150.0), NU, 0.02, 1),
        ColumnCell(20.0, "C2", RHO, _young(250.0), NU, 0.02, 1),
        ColumnCell(30.0, "SUB", RHO, _young(1000.0), NU, 0.0, 1),
    ]
    strains = (1e-6, 1e-5, 1e-4, 1e-3, 1e-2)
    gg = {1: StrainCurve(strains, (1.0, 0.95, 0.7, 0.35, 0.1))}
    dg = {1: StrainCurve(strains, (0.01, 0.02, 0.05, 0.1, 0.15))}
    result, grid = equivalent_linear_column(
        cells, _pulse(), gg, dg, freq_cut=15.0, resi_rela=0.02, nmax_iter=8
    )
    assert grid.times.size == 512 and grid.cut_index == int(15.0 / grid.df)
    assert result.changes[-1] <= 0.02 or len(result.changes) == 8
    assert all(c > 0.02 for c in result.changes[:-1])
    # the last analysis's strains give the next moduli, η = 2 D
    last = result.analysis.gamma_max
    for k, cell in enumerate(cells[:-1]):
        assert result.young[-1][k] == pytest.approx(gg[1](0.65 * last[k]) * cell.young)
        assert result.loss[-1][k] == pytest.approx(2.0 * dg[1](0.65 * last[k]))
    assert result.young[-1][0] < 0.9 * cells[0].young  # the soft layer softened


def test_linear_curves_stop_after_one_analysis_with_the_tables_own_moduli():
    cells = [
        ColumnCell(10.0, "C1", RHO, _young(300.0), NU, 0.0, 1),
        ColumnCell(20.0, "SUB", RHO, _young(300.0), NU, 0.0, 1),
    ]
    flat = {1: StrainCurve((1e-6, 1e-2), (1.0, 1.0))}
    damping = {1: StrainCurve((1e-6, 1e-2), (0.01, 0.01))}
    result, _ = equivalent_linear_column(cells, _pulse(), flat, damping, freq_cut=20.0)
    assert result.changes == [0.0]
    assert result.young[-1] == [cells[0].young] and result.loss[-1] == [0.02]


def test_mono_appui_finds_the_free_field_signal_again_at_the_surface():
    # CHAMP_LIBRE: the outcrop signal is deconvolved by FILTRE / (1 + H) on
    # the 0.1 Hz list, then the surface is that signal times (1 + H): the
    # given signal, filtered, up to the interpolations between the lists
    cells = [
        ColumnCell(10.0, "C1", RHO, _young(150.0), NU, 0.05, 1),
        ColumnCell(20.0, "C2", RHO, _young(250.0), NU, 0.05, 1),
        ColumnCell(30.0, "SUB", RHO, _young(800.0), NU, 0.0, 1),
    ]
    flat = {1: StrainCurve((1e-6, 1e-2), (1.0, 1.0))}
    damping = {1: StrainCurve((1e-6, 1e-2), (0.025, 0.025))}
    pulse = _pulse(count=512)
    common = dict(freq_cut=10.0, loading="MONO_APPUI")
    free, grid = equivalent_linear_column(
        cells, pulse, flat, damping, location="CHAMP_LIBRE", **common
    )
    assert grid.times.size == 512 and free.changes == [0.0]
    spectrum = np.fft.rfft(pulse.ordinates)
    spectrum[grid.cut_index + 1 :] = 0.0
    spectrum[0] = 0.0
    filtered = np.fft.irfft(spectrum, 512)
    surface = free.analysis.acceleration[0]
    assert np.max(np.abs(surface - filtered)) < 0.03 * np.max(np.abs(filtered))
    # and AFFLEURANT amplifies the same signal given at the outcrop
    outcrop, _ = equivalent_linear_column(cells, pulse, flat, damping, **common)
    assert np.max(np.abs(outcrop.analysis.acceleration[0])) > 1.2 * np.max(np.abs(filtered))
    assert np.allclose(outcrop.input_acceleration, filtered, atol=1e-9)


def test_onde_plane_from_the_free_field_deconvolves_what_the_outcrop_reconvolves():
    # CHAMP_LIBRE: a white noise drives the column, FDT_RACL = signal /
    # surface response scales it: the outcrop motion found, given back at
    # the outcrop (AFFLEURANT), gives the free-field signal again (up to the
    # trapezoidal integration of the outcrop's accelerogram)
    cells = [
        ColumnCell(10.0, "C1", RHO, _young(150.0), NU, 0.05, 1),
        ColumnCell(20.0, "C2", RHO, _young(250.0), NU, 0.05, 1),
        ColumnCell(30.0, "SUB", RHO, _young(800.0), NU, 0.0, 1),
    ]
    flat = {1: StrainCurve((1e-6, 1e-2), (1.0, 1.0))}
    damping = {1: StrainCurve((1e-6, 1e-2), (0.025, 0.025))}
    pulse = _pulse(count=512)
    rng = np.random.default_rng(3)
    noise = (0.005 * np.arange(1024), rng.standard_normal(1024))
    free, grid = equivalent_linear_column(
        cells, pulse, flat, damping, freq_cut=10.0, location="CHAMP_LIBRE", noise=noise
    )
    spectrum = np.fft.rfft(pulse.ordinates)
    spectrum[grid.cut_index + 1 :] = 0.0
    spectrum[0] = 0.0
    filtered = np.fft.irfft(spectrum, 512)
    assert np.allclose(free.analysis.acceleration[0], filtered, atol=1e-9 * np.abs(filtered).max())
    outcrop = Function(grid.times, free.input_acceleration, NOM_PARA="INST")
    again, _ = equivalent_linear_column(cells, outcrop, flat, damping, freq_cut=10.0)
    surface = again.analysis.acceleration[0]
    assert np.max(np.abs(surface - filtered)) < 0.03 * np.max(np.abs(filtered))


DECK = """DEBUT(CODE="OUI")
t = [0.01 * k for k in range(300)]
ACC = DEFI_FONCTION(NOM_PARA="INST", ABSCISSE=t,
    ORDONNEE=[3.0 * sin(2 * pi * 2.0 * x) * exp(-((x - 1.0) / 0.3) ** 2) for x in t])
FREQS = DEFI_LIST_REEL(DEBUT=0.5, INTERVALLE=_F(JUSQU_A=20.0, PAS=0.5))
TAB = DEFI_SOL_EQUI(
    GROUP_MA_DROITE="DR", GROUP_MA_GAUCHE="GA", GROUP_MA_COL="SURF", GROUP_MA_SUBSTR="BAS",
    MATERIAU=_F(GAMMA=(1e-6, 1e-4, 1e-2), G_GMAX=(1.0, 0.8, 0.2), D=(0.02, 0.05, 0.15)),
    COUCHE=(_F(GROUP_MA="C1", EPAIS=10.0, E=1.17e8, NU=0.3, RHO=2000.0, AMOR_HYST=0.04,
               NUME_MATE=1),
            _F(GROUP_MA="C2", EPAIS=10.0, E=3.25e8, NU=0.3, RHO=2000.0, AMOR_HYST=0.04,
               NUME_MATE=1),
            _F(GROUP_MA="SUB", EPAIS=10.0, E=5.2e9, NU=0.3, RHO=2000.0, AMOR_HYST=0.0,
               NUME_MATE=1)),
    CHARGEMENT="ONDE_PLANE", LIEU_SIGNAL="AFFLEURANT", FONC_SIGNAL=ACC, SURF="OUI",
    FREQ_COUP=15.0, LIST_FREQ_SPEC_OSCI=FREQS, UNITE_TABLE_RESU=39, UNITE_RESU_TRAN=41,
    UNITE_RESU_SPEC=42, {extra})
{after}
FIN()
"""


def _run(tmp_path, extra="", after=""):
    tmp_path.mkdir(exist_ok=True)
    (tmp_path / "sol.comm").write_text(DECK.format(extra=extra, after=after))
    (tmp_path / "sol.export").write_text(
        "P time_limit 300\nP memory_limit 2048\nP ncpus 1\nF comm sol.comm D 1\n"
    )
    return asterlite.run(tmp_path / "sol.export", tmp_path / "out")


def _blocks(path):
    from asterlite.commands.lire_fonction import numeric_blocks

    return numeric_blocks(path.read_text())


def test_the_command_writes_the_tables_and_the_six_blocks_defi_char_sol_reads(tmp_path):
    done = _run(tmp_path, after="IMPR_TABLE(TABLE=TAB, UNITE=8)")
    assert done.status == "DONE", done
    # the result: the layers for MISS (strain-compatible moduli), the
    # substratum's cell, the half-space
    table = done.concepts.raw["TAB"]
    assert table.column("NUME_COUCHE") == [1, 2, 3, 4]
    assert table.column("EPAIS") == [10.0, 10.0, 10.0, 0.0]
    assert table.column("SUBSTRATUM")[-1] == "OUI"
    assert table.column("E")[2:] == [5.2e9, 5.2e9] and table.column("E")[0] < 1.17e8
    # the column's own table on UNITE_TABLE_RESU
    printed = (tmp_path / "out" / "fort.39").read_text()
    for name in ("Efin", "AHfin", "G/Gmax", "gamma_max", "accxmax", "VSfin"):
        assert name in printed
    blocks = _blocks(tmp_path / "out" / "fort.41")
    assert len(blocks) == 6
    counts = [len(b[0]) for b in blocks]
    # INST, then CL, RA, 2 layers, BH (three blocks), 2 strains, 2 stresses,
    # and the forces at the surface, the layers' bases and the substratum's
    assert counts == [6, 6, 6, 3, 3, 5]
    times = np.array([row[0] for row in blocks[0]])
    assert times.size == 512 and times[1] == pytest.approx(0.01)
    # the stress is 2 G* EPXY with the last analysis's modulus: same sign
    # and nearly G γ (small damping)
    table_g = [row["E"] / 2.6 for row in table.rows[:2]]
    gam = np.array([[row[1] for row in blocks[3]], [row[2] for row in blocks[3]]])
    tau = np.array([[row[1] for row in blocks[4]], [row[2] for row in blocks[4]]])
    for k in range(2):
        peak = np.argmax(np.abs(gam[k]))
        assert tau[k][peak] == pytest.approx(table_g[k] * gam[k][peak], rel=0.1)
    spectra = _blocks(tmp_path / "out" / "fort.42")
    assert len(spectra[0]) == 40 and len(spectra[0][0]) == 1 + 5


def test_mono_appui_deck_writes_its_blocks_without_the_fields_by_default(tmp_path):
    text = DECK.replace('CHARGEMENT="ONDE_PLANE", LIEU_SIGNAL="AFFLEURANT", ', "")
    (tmp_path / "sol.comm").write_text(
        text.format(extra='CHARGEMENT="MONO_APPUI", LIEU_SIGNAL="CHAMP_LIBRE"', after="")
    )
    (tmp_path / "sol.export").write_text(
        "P time_limit 300\nP memory_limit 2048\nP ncpus 1\nF comm sol.comm D 1\n"
    )
    done = asterlite.run(tmp_path / "sol.export", tmp_path / "out")
    assert done.status == "DONE", done
    # TOUT_CHAM defaults to 'NON' for MONO_APPUI: accelerations, GAM, TAU;
    # no padding (300 instants)
    blocks = _blocks(tmp_path / "out" / "fort.41")
    assert [len(b[0]) for b in blocks] == [6, 3, 3] and len(blocks[0]) == 300
    transfer = _blocks(tmp_path / "out" / "fort.42")[1]
    assert transfer[0][0] == pytest.approx(0.1) and transfer[-1][0] == pytest.approx(15.0)


def test_tout_acce_non_keeps_the_listed_layers_and_the_forces(tmp_path):
    done = _run(tmp_path, extra='TOUT_ACCE="NON", LIST_COUCHE_ACCE=("C2", "C9")')
    assert done.status == "DONE", done
    # accelerations at CL, RA, C2's base, BH; no velocities, strains or
    # stresses; the forces (TOUT_CHAM) still; C9 is left out with a message
    blocks = _blocks(tmp_path / "out" / "fort.41")
    assert [len(b[0]) for b in blocks] == [5, 5]
    assert "layer C9 is not in the soil table" in (tmp_path / "out" / "message.log").read_text()


DRAW = """SP = DEFI_FONCTION(NOM_PARA="FREQ", VALE_C=({vale}), PROL_DROITE="CONSTANT",
                   PROL_GAUCHE="CONSTANT")
IS = DEFI_INTE_SPEC(DIMENSION=1, PAR_FONCTION=_F(NUME_ORDRE_I=1, NUME_ORDRE_J=1, FONCTION=SP))
{name} = GENE_FONC_ALEA(INTE_SPEC=IS, DUREE_TIRAGE={duree}, FREQ_INIT=0.0, FREQ_FIN={fmax},
                        NB_TIRAGE=1)
"""


def test_the_macro_draws_its_white_noise_from_the_decks_random_stream(tmp_path):
    # a later GENE_FONC_ALEA gives what it gives after the macro's own draw
    # (512 instants of 0.01 s: df = 1/5.12, fmax = 50 - df, cut 15 Hz)
    df = 1.0 / 5.12
    macro = dict(
        vale=f"0.0, 1.0, 0.0, {df}, 1.0, 0.0, 15.0, 1.0, 0.0, {15.0 + df}, 0.0, 0.0",
        duree=5.12,
        fmax=50.0 - df,
    )
    later = DRAW.format(name="LATER", vale="0.0, 1.0, 0.0, 20.0, 1.0, 0.0", duree=2.0, fmax=20.0)
    after = _run(tmp_path / "a", after=later)
    assert after.status == "DONE", after
    head = DECK.split("TAB = DEFI_SOL_EQUI(")[0]
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "sol.comm").write_text(
        head + DRAW.format(name="FIRST", **macro) + later + "FIN()\n"
    )
    (tmp_path / "b" / "sol.export").write_text(
        "P time_limit 300\nP memory_limit 2048\nP ncpus 1\nF comm sol.comm D 1\n"
    )
    twice = asterlite.run(tmp_path / "b" / "sol.export", tmp_path / "b" / "out")
    assert twice.status == "DONE", twice
    first = after.concepts.raw["LATER"].values[0]
    second = twice.concepts.raw["LATER"].values[0]
    assert np.array_equal(first, second)


@pytest.mark.parametrize(
    "extra, keyword",
    [
        ('CORRECTION="BYRNE"', "CORRECTION"),
        ('LIAISON="SANS"', "LIAISON"),
        ('INTEGRATION="FREQUENCE"', "INTEGRATION"),
    ],
)
def test_branches_not_computed_are_refused_by_name(tmp_path, extra, keyword):
    text = DECK.replace('LIEU_SIGNAL="AFFLEURANT", ', "")
    (tmp_path / "sol.comm").write_text(text.format(extra=extra, after=""))
    (tmp_path / "sol.export").write_text(
        "P time_limit 300\nP memory_limit 2048\nP ncpus 1\nF comm sol.comm D 1\n"
    )
    done = asterlite.run(tmp_path / "sol.export", tmp_path / "out")
    assert done.status == "UNSUPPORTED", done
    assert f"DEFI_SOL_EQUI/{keyword}" in done.message, done.message
