"""DEFI_SOL_EQUI's equivalent-linear soil column under a vertical S wave
(CHARGEMENT='ONDE_PLANE', signal at the outcropping rock, 2D), following
code_aster's macro step by step:

- the column is its own mesh: one 1 m wide QUAD4 D_PLAN cell per row of
  TABLE_MATER_ELAS (the layers, then the substratum's cell), the two sides
  tied (periodic), a D_PLAN_ABSO edge at the base. With the sides tied a
  horizontal motion u(y) is linear in each cell, so each cell is exactly a
  two-node shear element: stiffness G*/h [[1, -1], [-1, 1]] (RIGI_MECA_HYST,
  G* = G (1 + iη), or Lysmer's G (1 - η²/2 + iη √(1 - η²/4)) with
  CORR_AMOR), consistent mass ρh/6 [[2, 1], [1, 2]], and the absorbing edge
  the dashpot ρ Vs of the substratum;
- the load is the ONDE_PLANE force on that edge, -2 ρ Vs v(t) along X
  (asterlite.fem.plane_wave's convention for DIRECTION=(0, 1), the wave's
  source at the base), v the integral of the accelerogram (INTEGRE), taken
  to frequency as REST_SPEC_TEMP METHODE='PROL_ZERO' SYMETRIE='NON';
- the harmonic solution at df, 2 df, ... up to the cut frequency; the
  responses (accelerations -ω² u, the shear strain EPXY, the nodal forces
  FORC_NODA DY on the left side, from the cells of the column only) are
  multiplied by the filter (0 at 0 Hz, 1 from df to FREQ_COUP, 0 beyond) and
  brought back to time as CALC_FONCTION FFT SYME='NON';
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
    surface_harmonic: np.ndarray  # the free surface's acceleration at df .. cut


@dataclass
class SolEquiResult:
    """What the macro keeps: the instants, the input acceleration (filtered,
    AX_RA), the last analysis and the iterations' moduli, loss factors,
    G/Gmax and largest changes."""

    times: np.ndarray
    input_acceleration: np.ndarray
    analysis: ColumnAnalysis
    input_spectrum: np.ndarray  # FFT of the accelerogram at df .. cut
    young: list[list[float]] = field(default_factory=list)
    loss: list[list[float]] = field(default_factory=list)
    ratio: list[list[float]] = field(default_factory=list)
    changes: list[float] = field(default_factory=list)


@dataclass(frozen=True)
class SignalGrid:
    """The signal's instants (padded to a power of two), the frequency step,
    the highest frequency and the cut frequency rounded down to the grid."""

    times: np.ndarray
    dt: float
    df: float
    fmax: float
    cut_index: int  # the filter keeps the frequencies 1 .. cut_index times df


def signal_grid(signal: Function, freq_cut: float | None) -> SignalGrid:
    """The macro's padding and frequencies for CHARGEMENT='ONDE_PLANE'."""
    tt = np.asarray(signal.abscissas, dtype=float)
    if tt.size < 2:
        raise ValueError("FONC_SIGNAL needs at least two instants")
    dt = float(tt[1] - tt[0])
    count = 1
    while count < tt.size:
        count *= 2
    df = 1.0 / (count * dt)
    fmax = 0.5 / dt - df
    cut = fmax if freq_cut is None else min(float(freq_cut), fmax)
    cut_index = int((cut + 1.0e-12) / df)
    if cut_index < 1:
        raise ValueError(f"the cut frequency {cut:g} Hz is below the frequency step {df:g} Hz")
    return SignalGrid(dt * np.arange(count), dt, df, fmax, cut_index)


def column_response(
    cells: list[ColumnCell],
    young: list[float],
    loss: list[float],
    lysmer: bool,
    base_load: np.ndarray,
    freqs: np.ndarray,
) -> np.ndarray:
    """Nodal displacements (rows: nodes from the surface down; columns:
    frequencies) under the base load's spectrum ``base_load``. ``young`` and
    ``loss`` are the layers' current values (the substratum cell keeps its
    own)."""
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
        rhs = np.zeros(n, dtype=complex)
        rhs[-1] = base_load[j]
        out[:, j] = np.linalg.solve(system, rhs)
    return out


def _to_time(grid: SignalGrid, spectra: np.ndarray) -> np.ndarray:
    """Histories (rows) from responses at df .. cut (columns): the filter,
    then CALC_FONCTION FFT SYME='NON' on the grid 0 .. fmax."""
    half = grid.times.size // 2
    freqs = grid.df * np.arange(half)
    out = np.empty((spectra.shape[0], grid.times.size))
    for r, row in enumerate(spectra):
        full = np.zeros(half, dtype=complex)
        full[1 : grid.cut_index + 1] = row
        back = fops.inverse_fft(Function(freqs, full, NOM_PARA="FREQ"), "COMPLET", False)
        out[r] = back.ordinates[: grid.times.size]
    return out


def analyse(
    cells: list[ColumnCell],
    young: list[float],
    loss: list[float],
    lysmer: bool,
    grid: SignalGrid,
    load_spectrum: np.ndarray,
) -> ColumnAnalysis:
    """One harmonic analysis and its histories."""
    freqs = grid.df * np.arange(1, grid.cut_index + 1)
    disp = column_response(cells, young, loss, lysmer, load_spectrum, freqs)
    omega = 2.0 * np.pi * freqs
    accel = -(omega**2) * disp
    heights = np.diff(np.concatenate([[0.0], [c.depth for c in cells]]))
    # y is upward: the shear strain of a cell is (u_top - u_bottom) / h
    gamma = (disp[:-1] - disp[1:]) / heights[:, None]
    layers = len(cells) - 1
    elastic = np.array(
        [
            (young[k] if k < layers else c.young) / (2.0 * (1.0 + c.poisson))
            for k, c in enumerate(cells)
        ]
    )
    # FORC_NODA DY at a left node: each adjacent cell gives -σxy h / 2
    # (the integral of σxy ∂N/∂x), σxy = G γ with the elastic modulus
    share = -0.5 * elastic[:, None] * gamma * heights[:, None]
    force = np.zeros_like(disp)
    force[:-1] += share
    force[1:] += share
    tau_modulus = np.array(
        [
            2.0 * complex_shear_modulus(young[k] / (2.0 * (1.0 + c.poisson)), loss[k], lysmer)
            for k, c in enumerate(cells[:-1])
        ]
    )
    histories = _to_time(
        grid,
        np.vstack([accel, gamma[:layers], (gamma[:layers] / 2.0) * tau_modulus[:, None], force]),
    )
    n = len(cells) + 1
    acc, gam = histories[:n], histories[n : n + layers]
    tau, forces = histories[n + layers : n + 2 * layers], histories[n + 2 * layers :]
    return ColumnAnalysis(acc, gam, tau, forces, np.max(np.abs(gam), axis=1), accel[0])


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
) -> tuple[SolEquiResult, SignalGrid]:
    """DEFI_SOL_EQUI's iterations on the column (the last row of ``cells``
    is the substratum's cell)."""
    grid = signal_grid(accelerogram, freq_cut)
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
    velocity = fops.integrate(on_grid).ordinates
    base = cells[-1]
    rho_vs = np.sqrt(base.density * base.young / (2.0 * (1.0 + base.poisson)))
    load = -2.0 * rho_vs * velocity
    _, spectrum = time_to_frequency(grid.times, load[:, None], "PROL_ZERO", False, 0)
    load_spectrum = spectrum[1 : grid.cut_index + 1, 0]
    # AX_RA: the input accelerogram, filtered
    forward = fops.fft(on_grid, "COMPLET").ordinates[: grid.times.size // 2]
    input_acc = _to_time(grid, forward[None, 1 : grid.cut_index + 1])[0]
    layers = cells[:-1]
    young = [c.young for c in layers]
    loss = [c.loss for c in layers]
    result = SolEquiResult(grid.times, input_acc, None, forward[1 : grid.cut_index + 1])  # type: ignore[arg-type]
    result.young.append(list(young))
    result.loss.append(list(loss))
    result.ratio.append([1.0] * len(layers))
    while True:
        analysis = analyse(cells, young, loss, lysmer, grid, load_spectrum)
        result.analysis = analysis
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
