"""DEFI_SOL_EQUI's equivalent-linear soil column under vertical S waves (2D),
following code_aster's macro step by step:

- the column is its own mesh: one 1 m wide QUAD4 D_PLAN cell per row of
  TABLE_MATER_ELAS (the layers, then the substratum's cell), the two sides
  tied (periodic), a D_PLAN_ABSO edge at the base. With the sides tied a
  horizontal motion u(y) is linear in each cell, so each cell is exactly a
  two-node shear element: stiffness G*/h [[1, -1], [-1, 1]] (RIGI_MECA_HYST,
  G* = G (1 + iη), or Lysmer's G (1 - η²/2 + iη √(1 - η²/4)) with
  CORR_AMOR), consistent mass ρh/6 [[2, 1], [1, 2]], and the absorbing edge
  the dashpot ρ Vs of the substratum;
- CHARGEMENT='ONDE_PLANE': the signal padded to a power of two; the load
  is the ONDE_PLANE force on the base edge,
  -2 ρ Vs v(t) along X (asterlite.fem.plane_wave's convention for
  DIRECTION=(0, 1), the wave's source at the base), v the integral of the
  accelerogram (INTEGRE), taken to frequency as REST_SPEC_TEMP
  METHODE='PROL_ZERO' SYMETRIE='NON'; the harmonic solution at df, 2 df, ...
  up to the cut frequency. From the free field (CHAMP_LIBRE) v is the
  macro's white noise and the responses are scaled by FDT_RACL, the
  signal's spectrum over the surface's response; the outcrop is the noise's
  acceleration iωV times FDT_RACL;
- CHARGEMENT='MONO_APPUI': the column relative to a unit base acceleration
  (load -M 1) at 0.1, 0.2, ... Hz up to the cut frequency; these transfer
  functions, interpolated onto the signal's grid, multiply the outcrop's
  spectrum: the signal's (AFFLEURANT) or the free-field signal's times
  FDT_RACL = FILTRE / (1 + H_surface) (CHAMP_LIBRE); accelerations are then
  the outcrop's plus the relative ones;
- the responses (accelerations -ω² u, the shear strain 2 EPXY, the nodal
  forces FORC_NODA DY on the left side, from the cells of the column only)
  are multiplied by the filter (0 at 0 Hz, 1 from df to FREQ_COUP, 0 at the
  next frequency of the grid) and brought back to time as CALC_FONCTION FFT
  SYME='NON';
- iteration k+1 takes G/Gmax and D of the curves at COEF_GAMMA · γmax of
  each layer, η = 2 D, until the largest relative change of the layers'
  moduli is at most RESI_RELA or NMAX_ITER analyses ran; the histories are
  those of the last analysis.

Nodes are numbered from the free surface (0) down to the base (rows), as the
left side of code_aster's mesh (N1, N2, ...)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from asterlite.concepts.function import Function
from asterlite.harmonic.soil_column import StrainCurve, complex_shear_modulus
from asterlite.post import functions as fops
from asterlite.post.result_fourier import time_to_frequency


@dataclass
class ColumnCell:
    """One row of TABLE_MATER_ELAS: the depth of its base Y, its name M,
    density, modulus E0 (COEF_VARI_MATE · Emax), Poisson's ratio, loss
    factor AH and the index of its curves."""

    depth: float
    name: str
    density: float
    young: float
    poisson: float
    loss: float
    curves: int


@dataclass
class ColumnAnalysis:
    """One harmonic analysis of the column, back in time: histories on the
    instants ``times`` (rows: surface, then the base of each layer, then the
    base of the substratum cell for the motions and forces; the layers for
    strains and stresses)."""

    acceleration: np.ndarray
    strain: np.ndarray  # GAM_k = 2 EPXY
    stress: np.ndarray  # TAU_k
    force: np.ndarray  # FORC_NODA DY at the left node
    gamma_max: np.ndarray  # per layer
    surface_harmonic: np.ndarray  # the free surface's acceleration, harmonic frequencies
    input_acceleration: np.ndarray | None = None  # the outcrop's, when found here


@dataclass
class SolEquiResult:
    """What the macro keeps: the instants, the input acceleration (filtered,
    AX_RA), the last analysis and the iterations' moduli, loss factors,
    G/Gmax and largest changes."""

    times: np.ndarray
    input_acceleration: np.ndarray | None = None
    analysis: ColumnAnalysis | None = None
    transfer: tuple[np.ndarray, np.ndarray] | None = None  # FDT_RACL: frequencies, values
    young: list[list[float]] = field(default_factory=list)
    loss: list[list[float]] = field(default_factory=list)
    ratio: list[list[float]] = field(default_factory=list)
    changes: list[float] = field(default_factory=list)


@dataclass(frozen=True)
class SignalGrid:
    """The signal's instants (padded to a power of two for ONDE_PLANE), the
    frequency step, the highest frequency, the cut frequency (FREQ_COUP, at
    most fmax) and its index on the grid, rounded down."""

    times: np.ndarray
    dt: float
    df: float
    fmax: float
    cut: float
    cut_index: int  # the filter keeps the frequencies 1 .. cut_index times df


def signal_grid(signal: Function, freq_cut: float | None, pad: bool = True) -> SignalGrid:
    """The macro's instants and frequencies: nbdt samples (the next power of
    two with ``pad``), df = 1 / (nbdt dt), fmax = 1 / (2 dt) - df."""
    tt = np.asarray(signal.abscissas, dtype=float)
    if tt.size < 2:
        raise ValueError("FONC_SIGNAL needs at least two instants")
    dt = float(tt[1] - tt[0])
    count = tt.size
    if pad:
        count = 1
        while count < tt.size:
            count *= 2
    df = 1.0 / (count * dt)
    fmax = 0.5 / dt - df
    cut = fmax if freq_cut is None else min(float(freq_cut), fmax)
    cut_index = int((cut + 1.0e-12) / df)
    if cut_index < 1:
        raise ValueError(f"the cut frequency {cut:g} Hz is below the frequency step {df:g} Hz")
    return SignalGrid(dt * np.arange(count), dt, df, fmax, cut, cut_index)


def column_response(
    cells: list[ColumnCell],
    young: list[float],
    loss: list[float],
    lysmer: bool,
    base_load: np.ndarray | None,
    freqs: np.ndarray,
) -> np.ndarray:
    """Nodal displacements (rows: nodes from the surface down; columns:
    frequencies) under the base load's spectrum ``base_load`` or, when it is
    None, relative to a unit base acceleration (CALC_CHAR_SEISME MONO_APPUI:
    the load -M 1). ``young`` and ``loss`` are the layers' current values
    (the substratum cell keeps its own)."""
    n = len(cells) + 1
    stiffness = np.zeros((n, n), dtype=complex)
    mass = np.zeros((n, n))
    top = 0.0
    for k, cell in enumerate(cells):
        h = cell.depth - top
        top = cell.depth
        layer = k < len(cells) - 1
        e = young[k] if layer else cell.young
        eta = loss[k] if layer else cell.loss
        g = complex_shear_modulus(e / (2.0 * (1.0 + cell.poisson)), eta, lysmer and layer)
        stiffness[k : k + 2, k : k + 2] += g / h * np.array([[1.0, -1.0], [-1.0, 1.0]])
        mass[k : k + 2, k : k + 2] += cell.density * h / 6.0 * np.array([[2.0, 1.0], [1.0, 2.0]])
    base = cells[-1]
    dashpot = np.sqrt(base.density * base.young / (2.0 * (1.0 + base.poisson)))  # ρ Vs
    out = np.empty((n, len(freqs)), dtype=complex)
    for j, f in enumerate(freqs):
        w = 2.0 * np.pi * f
        system = stiffness - w * w * mass
        system[-1, -1] += 1j * w * dashpot
        if base_load is None:
            rhs = -mass.sum(axis=1).astype(complex)
        else:
            rhs = np.zeros(n, dtype=complex)
            rhs[-1] = base_load[j]
        out[:, j] = np.linalg.solve(system, rhs)
    return out


def _to_time(grid: SignalGrid, spectra: np.ndarray) -> np.ndarray:
    """Histories (rows) from spectra on the grid 0, df, ... fmax (columns):
    CALC_FONCTION FFT SYME='NON', then the instants of the signal (COMB on
    LIST_PARA, the transform's own instants when the count is a power of
    two)."""
    freqs = grid.df * np.arange(spectra.shape[1])
    out = np.empty((spectra.shape[0], grid.times.size))
    for r, row in enumerate(spectra):
        back = fops.inverse_fft(Function(freqs, row, NOM_PARA="FREQ"), "COMPLET", False)
        if back.abscissas.size >= grid.times.size and np.allclose(
            back.abscissas[: grid.times.size], grid.times, rtol=0.0, atol=1e-9 * grid.dt
        ):
            out[r] = back.ordinates[: grid.times.size]
        else:
            out[r] = back.with_values(
                back.abscissas, back.ordinates, PROL_DROITE="CONSTANT", PROL_GAUCHE="CONSTANT"
            ).evaluate(grid.times)
    return out


def spectrum_grid(grid: SignalGrid) -> np.ndarray:
    """The frequencies 0, df, ... up to fmax (the macro's __lfreq)."""
    return grid.df * np.arange(int((grid.fmax + 1.0e-9 * grid.df) / grid.df) + 1)


def filter_values(grid: SignalGrid, freqs: np.ndarray) -> np.ndarray:
    """The macro's FILTRE: 0 at 0 Hz, 1 from df to the cut frequency, down to
    0 at the next frequency of the grid, linear between."""
    knots = [0.0, grid.df, grid.cut, (grid.cut_index + 1) * grid.df]
    return np.interp(freqs, knots, [0.0, 1.0, 1.0, 0.0])


def _interp_complex(x, xp, fp) -> np.ndarray:
    """Linear interpolation of complex values, constant beyond the ends."""
    fp = np.asarray(fp)
    return np.interp(x, xp, fp.real) + 1j * np.interp(x, xp, fp.imag)


def _harmonic_fields(cells, young, loss, lysmer, freqs, base_load=None):
    """Per frequency: relative accelerations (nodes), strains γ (cells),
    FORC_NODA DY at the left nodes, for the ONDE_PLANE base load or, when
    ``base_load`` is None, the unit base acceleration of MONO_APPUI."""
    disp = column_response(cells, young, loss, lysmer, base_load, freqs)
    omega = 2.0 * np.pi * freqs
    accel = -(omega**2) * disp
    heights = np.diff(np.concatenate([[0.0], [c.depth for c in cells]]))
    # y is upward: the shear strain of a cell is (u_top - u_bottom) / h
    gamma = (disp[:-1] - disp[1:]) / heights[:, None]
    layers = len(cells) - 1
    # the material's E (Lysmer's layers: E (1 - η²/2)); its AMOR_HYST enters
    # the hysteretic stiffness only, not the stresses
    elastic = np.array(
        [
            (young[k] * (1.0 - loss[k] ** 2 / 2.0 if lysmer else 1.0) if k < layers else c.young)
            / (2.0 * (1.0 + c.poisson))
            for k, c in enumerate(cells)
        ]
    )
    # FORC_NODA DY at a left node: each adjacent cell gives -σxy h / 2
    # (the integral of σxy ∂N/∂x), σxy = G γ
    share = -0.5 * elastic[:, None] * gamma * heights[:, None]
    force = np.zeros_like(disp)
    force[:-1] += share
    force[1:] += share
    return accel, gamma, force


def analyse(
    cells: list[ColumnCell],
    young: list[float],
    loss: list[float],
    lysmer: bool,
    grid: SignalGrid,
    excitation: Excitation,
) -> ColumnAnalysis:
    """One harmonic analysis and its histories."""
    layers = len(cells) - 1
    accel, gamma, force = _harmonic_fields(
        cells, young, loss, lysmer, excitation.freqs, excitation.base_load
    )
    fine = spectrum_grid(grid)
    outcrop_history = None
    if excitation.base_load is not None:
        # ONDE_PLANE: the harmonic frequencies are those of the grid; from
        # the free field, the responses to the noise are scaled by FDT_RACL,
        # the signal's spectrum over the surface's response
        scale = np.ones(grid.cut_index, dtype=complex)
        if excitation.signal is not None:
            scale = excitation.signal[1 : grid.cut_index + 1] / accel[0]
            outcrop = np.zeros(fine.size, dtype=complex)
            outcrop[1 : grid.cut_index + 1] = excitation.noise_accel[1 : grid.cut_index + 1] * scale
            outcrop_history = _to_time(grid, outcrop[None, :])[0]

        def on_grid(values):
            out = np.zeros((values.shape[0], fine.size), dtype=complex)
            out[:, 1 : grid.cut_index + 1] = values * scale
            return out
    else:
        # MONO_APPUI: transfer functions per unit base acceleration, on the
        # 0.1 Hz list, times the outcrop's spectrum and the filter
        weight = excitation.outcrop * filter_values(grid, fine)

        def on_grid(values):
            return np.array([_interp_complex(fine, excitation.freqs, v) for v in values]) * weight

    tau_modulus = np.array(
        [
            2.0 * complex_shear_modulus(young[k] / (2.0 * (1.0 + c.poisson)), loss[k], lysmer)
            for k, c in enumerate(cells[:-1])
        ]
    )
    strain = on_grid(gamma[:layers])
    histories = _to_time(
        grid,
        np.vstack([on_grid(accel), strain, (strain / 2.0) * tau_modulus[:, None], on_grid(force)]),
    )
    n = len(cells) + 1
    acc, gam = histories[:n], histories[n : n + layers]
    if excitation.base_load is None:
        acc = acc + excitation.outcrop_history  # relative to total accelerations
    tau, forces = histories[n + layers : n + 2 * layers], histories[n + 2 * layers :]
    return ColumnAnalysis(
        acc, gam, tau, forces, np.max(np.abs(gam), axis=1), accel[0], outcrop_history
    )


@dataclass
class Excitation:
    """The harmonic frequencies and the base load (ONDE_PLANE) or, for
    MONO_APPUI (base_load None), the outcrop's filtered spectrum on the grid
    0 .. fmax and its history."""

    freqs: np.ndarray
    base_load: np.ndarray | None = None
    outcrop: np.ndarray | None = None
    outcrop_history: np.ndarray | None = None
    # ONDE_PLANE from the free field: the signal's spectrum and the white
    # noise's acceleration spectrum on the grid 0 .. fmax
    signal: np.ndarray | None = None
    noise_accel: np.ndarray | None = None


def _pas_list(start: float, end: float, step: float) -> np.ndarray:
    """DEFI_LIST_REEL(DEBUT=start, INTERVALLE=_F(JUSQU_A=end, PAS=step))."""
    ratio = (end - start) / step
    count = int(np.floor(ratio + 0.5))
    if count < 1:
        return np.array([start])
    if abs((end - (start + (count - 1) * step) - step) / step) > 1.0e-3:
        if start + count * step > end:
            count -= 1
        return np.append(start + step * np.arange(count + 1), end)
    points = start + step * np.arange(count + 1)
    points[-1] = end
    return points


def equivalent_linear_column(
    cells: list[ColumnCell],
    accelerogram: Function,
    gg_curves: dict[int, StrainCurve],
    damping_curves: dict[int, StrainCurve],
    freq_cut: float | None = None,
    coef_gamma: float = 0.65,
    resi_rela: float = 0.05,
    nmax_iter: int = 10,
    lysmer: bool = False,
    amplitude: float = 1.0,
    loading: str = "ONDE_PLANE",
    location: str = "AFFLEURANT",
    noise: tuple[np.ndarray, np.ndarray] | None = None,
) -> tuple[SolEquiResult, SignalGrid]:
    """DEFI_SOL_EQUI's iterations on the column (the last row of ``cells``
    is the substratum's cell): ``loading`` 'ONDE_PLANE' (the signal at the
    outcrop only) or 'MONO_APPUI' (at the outcrop, 'AFFLEURANT', or at the
    free surface, 'CHAMP_LIBRE', deconvolved by the transfer function of the
    transfer function of each analysis, as the macro)."""
    if loading == "ONDE_PLANE" and location != "AFFLEURANT" and noise is None:
        raise ValueError("ONDE_PLANE from the free surface needs the macro's white noise")
    grid = signal_grid(accelerogram, freq_cut, pad=loading == "ONDE_PLANE")
    on_grid = Function(
        grid.times,
        amplitude
        * accelerogram.with_values(
            accelerogram.abscissas,
            accelerogram.ordinates,
            PROL_GAUCHE="CONSTANT",
            PROL_DROITE="CONSTANT",
        ).evaluate(grid.times),
        NOM_PARA="INST",
        PROL_GAUCHE="CONSTANT",
        PROL_DROITE="CONSTANT",
    )
    fine = spectrum_grid(grid)
    forward = fops.fft(on_grid, "COMPLET")
    signal_spectrum = _interp_complex(fine, forward.abscissas, forward.ordinates)
    layers = cells[:-1]
    young = [c.young for c in layers]
    loss = [c.loss for c in layers]
    if loading == "ONDE_PLANE":
        if location == "AFFLEURANT":
            velocity = fops.integrate(on_grid).ordinates
        else:
            # the white noise's velocity on the signal's instants, and its
            # acceleration's spectrum iω V (ACCEX0H)
            velocity = np.interp(grid.times, noise[0], noise[1])
            spectrum_v = fops.fft(Function(grid.times, velocity, NOM_PARA="INST"), "COMPLET")
            noise_accel = (
                2j
                * np.pi
                * fine
                * _interp_complex(fine, spectrum_v.abscissas, spectrum_v.ordinates)
            )
        base = cells[-1]
        rho_vs = np.sqrt(base.density * base.young / (2.0 * (1.0 + base.poisson)))
        _, spectrum = time_to_frequency(
            grid.times, (-2.0 * rho_vs * velocity)[:, None], "PROL_ZERO", False, 0
        )
        freqs = grid.df * np.arange(1, grid.cut_index + 1)
        excitation = Excitation(freqs, base_load=spectrum[1 : grid.cut_index + 1, 0])
        if location != "AFFLEURANT":
            excitation.signal = signal_spectrum
            excitation.noise_accel = noise_accel
    else:
        excitation = Excitation(_pas_list(0.1, grid.cut, 0.1))
    filtre = filter_values(grid, fine)
    input_spectrum = signal_spectrum * filtre
    result = SolEquiResult(grid.times)
    result.young.append(list(young))
    result.loss.append(list(loss))
    result.ratio.append([1.0] * len(layers))
    while True:
        if loading == "MONO_APPUI":
            # FDT_RACL: FILTRE / (1 + the surface's relative acceleration) on
            # the 0.1 Hz list; the outcrop's spectrum from the surface signal
            surface = _harmonic_fields(cells, young, loss, lysmer, excitation.freqs)[0][0]
            transfer = filter_values(grid, excitation.freqs) / (1.0 + surface)
            result.transfer = (excitation.freqs, transfer)
            outcrop = signal_spectrum
            if location == "CHAMP_LIBRE":
                outcrop = signal_spectrum * _interp_complex(fine, excitation.freqs, transfer)
            excitation.outcrop = outcrop * filtre
            excitation.outcrop_history = _to_time(grid, excitation.outcrop[None, :])[0]
            result.input_acceleration = excitation.outcrop_history
        else:
            result.input_acceleration = _to_time(grid, input_spectrum[None, :])[0]
        analysis = analyse(cells, young, loss, lysmer, grid, excitation)
        result.analysis = analysis
        if analysis.input_acceleration is not None:
            result.input_acceleration = analysis.input_acceleration
        if loading == "ONDE_PLANE":
            # FDT_RACL: the signal's spectrum over the surface's response
            result.transfer = (
                excitation.freqs,
                signal_spectrum[1 : grid.cut_index + 1] / analysis.surface_harmonic,
            )
        strains = [coef_gamma * g for g in analysis.gamma_max]
        ratio = [gg_curves[c.curves](s) for c, s in zip(layers, strains, strict=True)]
        new_loss = [2.0 * damping_curves[c.curves](s) for c, s in zip(layers, strains, strict=True)]
        new_young = [r * c.young for r, c in zip(ratio, layers, strict=True)]
        change = max(abs(a - b) / a for a, b in zip(young, new_young, strict=True))
        result.young.append(new_young)
        result.loss.append(new_loss)
        result.ratio.append(ratio)
        result.changes.append(change)
        if change <= resi_rela or len(result.changes) >= nmax_iter:
            return result, grid
        young, loss = new_young, new_loss
