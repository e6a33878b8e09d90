"""Equivalent-linear response of a horizontally layered soil column to
vertically propagating shear waves (the SHAKE method), with the conventions
of code_aster's DEFI_SOL_EQUI:

- a layer's hysteretic damping is its loss factor η (AMOR_HYST): complex
  shear modulus G* = G (1 + iη) (code_aster's default, 'SCHNABEL'), or
  G (1 - η²/2 + iη √(1 - η²/4)) with CORR_AMOR='OUI' ('LYSMER'), which keeps
  the wave speed's modulus exact for a damping ratio η/2;
- the substratum below the last layer is an elastic half-space (its
  impedance ρ V* radiates the down-going waves), or rigid;
- the signal is given either at the outcropping rock (twice the up-going
  wave at the top of the substratum, LIEU_SIGNAL='AFFLEURANT') or at the
  free surface of the column (LIEU_SIGNAL='CHAMP_LIBRE', deconvolution);
- iteration k+1 takes in each layer G/Gmax and D of the curves at the
  effective strain COEF_GAMMA · γmax of iteration k, η = 2 D, and stops when
  the largest relative change of the layers' moduli is at most RESI_RELA, or
  after NMAX_ITER iterations.

In a layer of thickness h, with z downward from its top and e^{iωt}, the
displacement is u = A e^{ik*z} + B e^{-ik*z}, k* = ω √(ρ/G*) (A up-going,
B down-going). A free surface gives A₁ = B₁; continuity of displacement and
shear stress across an interface gives the next layer's amplitudes from the
impedance ratio α = √(ρ G*)ₘ / √(ρ G*)ₘ₊₁:

    Aₘ₊₁ = ½ Aₘ (1 + α) e^{ik*h} + ½ Bₘ (1 - α) e^{-ik*h}
    Bₘ₊₁ = ½ Aₘ (1 - α) e^{ik*h} + ½ Bₘ (1 + α) e^{-ik*h}

code_aster computes the column with plane-strain finite elements, one cell
per layer, and harmonic DYNA_VIBRA runs: ``fe_column_response`` is that
discretisation (second-order close to the wave solution as the cells
shrink); ``equivalent_linear`` iterates on the wave solution (each layer's
strain taken at mid-depth). The DEFI_SOL_EQUI command follows the macro's
own chain instead (asterlite.harmonic.sol_equi: its load, FFTs, filter and
strain at the Gauss points of the cells); these wave solutions are its
closed-form references."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class StrainCurve:
    """G/Gmax or damping ratio D as a function of the shear strain γ,
    interpolated linearly in log γ and constant beyond its ends (code_aster's
    INTERPOL=('LOG', 'LIN'), PROL_GAUCHE=PROL_DROITE='CONSTANT')."""

    strains: tuple[float, ...]
    values: tuple[float, ...]

    def __post_init__(self):
        gam = np.asarray(self.strains, dtype=float)
        if gam.size < 1 or gam.size != len(self.values):
            raise ValueError("a strain curve needs as many values as strains, at least one")
        if np.any(gam <= 0.0) or np.any(np.diff(gam) <= 0.0):
            raise ValueError("the strains of a curve must be positive and increasing")

    def __call__(self, gamma: float) -> float:
        gam = np.log(np.asarray(self.strains, dtype=float))
        if gamma <= 0.0:
            return float(self.values[0])
        return float(np.interp(np.log(gamma), gam, np.asarray(self.values, dtype=float)))


@dataclass
class SoilLayer:
    """One layer: thickness (m), Young's modulus, Poisson's ratio, density,
    loss factor η (AMOR_HYST) and the index of its curves (GDgam)."""

    thickness: float
    young: float
    poisson: float
    density: float
    loss_factor: float = 0.0
    curves: int | None = None

    @property
    def shear_modulus(self) -> float:
        return self.young / (2.0 * (1.0 + self.poisson))


def complex_shear_modulus(shear: float, loss: float, lysmer: bool = False) -> complex:
    """G* of a layer for its loss factor η, as DEFI_SOL_EQUI's materials."""
    if lysmer:
        return shear * complex(1.0 - loss * loss / 2.0, loss * np.sqrt(1.0 - loss * loss / 4.0))
    return shear * complex(1.0, loss)


@dataclass
class ColumnWaves:
    """Up- and down-going amplitudes at the top of each layer and of the
    substratum (rows), per frequency (columns), for a unit free surface
    amplitude A₁ = B₁ = 1 (the surface motion is 2)."""

    freqs: np.ndarray
    up: np.ndarray
    down: np.ndarray
    wavenumbers: np.ndarray  # k* of each layer (rows) per frequency
    rigid_base: bool = False


def propagate(
    layers: list[SoilLayer],
    substratum: SoilLayer | None,
    freqs: np.ndarray,
    lysmer: bool = False,
) -> ColumnWaves:
    """Wave amplitudes down the column; a substratum of None is rigid (only
    the total motion at its top is then meaningful)."""
    freqs = np.asarray(freqs, dtype=float)
    omega = 2.0 * np.pi * freqs
    nlay = len(layers)
    up = np.empty((nlay + 1, freqs.size), dtype=complex)
    down = np.empty_like(up)
    kstar = np.empty((nlay, freqs.size), dtype=complex)
    up[0] = down[0] = 1.0
    gstar = [complex_shear_modulus(ly.shear_modulus, ly.loss_factor, lysmer) for ly in layers]
    below = substratum
    for m, layer in enumerate(layers):
        kstar[m] = omega * np.sqrt(layer.density / gstar[m])
        if m + 1 < nlay:
            g_next, rho_next = gstar[m + 1], layers[m + 1].density
        elif below is not None:
            g_next = complex_shear_modulus(below.shear_modulus, below.loss_factor, lysmer)
            rho_next = below.density
        else:
            g_next, rho_next = None, None
        phase = np.exp(1j * kstar[m] * layer.thickness)
        if g_next is None:  # rigid base: keep the layer's own waves at its bottom
            up[m + 1] = up[m] * phase
            down[m + 1] = down[m] / phase
            continue
        alpha = np.sqrt(layer.density * gstar[m]) / np.sqrt(rho_next * g_next)
        up[m + 1] = 0.5 * up[m] * (1.0 + alpha) * phase + 0.5 * down[m] * (1.0 - alpha) / phase
        down[m + 1] = 0.5 * up[m] * (1.0 - alpha) * phase + 0.5 * down[m] * (1.0 + alpha) / phase
    return ColumnWaves(freqs, up, down, kstar, rigid_base=below is None)


def reference_motion(waves: ColumnWaves, location: str) -> np.ndarray:
    """The motion, per frequency, of the place where the signal is given:
    'AFFLEURANT' the outcropping rock (2 × the up-going wave at the top of
    the substratum), 'CHAMP_LIBRE' the free surface, 'BASE' the total motion
    at the top of the substratum (a rigid base's motion)."""
    if location == "AFFLEURANT":
        if not np.all(np.isfinite(waves.up[-1])) or waves.rigid_base:
            raise ValueError("a signal at the outcropping rock needs an elastic substratum")
        return 2.0 * waves.up[-1]
    if location == "CHAMP_LIBRE":
        return 2.0 * waves.up[0]
    if location == "BASE":
        return waves.up[-1] + waves.down[-1]
    raise ValueError(f"unknown signal location {location!r}")


def interface_transfer(waves: ColumnWaves, location: str) -> np.ndarray:
    """Displacement at the free surface and at the top of each layer below
    it and of the substratum (rows), per unit motion at the signal's place."""
    return (waves.up + waves.down) / reference_motion(waves, location)


def midlayer_strain_transfer(
    waves: ColumnWaves, layers: list[SoilLayer], location: str
) -> np.ndarray:
    """Shear strain du/dz at each layer's mid-depth per unit displacement at
    the signal's place (rows: layers)."""
    half = np.array([ly.thickness / 2.0 for ly in layers])[:, None]
    k = waves.wavenumbers
    gamma = (
        1j * k * (waves.up[:-1] * np.exp(1j * k * half) - waves.down[:-1] * np.exp(-1j * k * half))
    )
    return gamma / reference_motion(waves, location)


@dataclass
class EquivalentLinearResult:
    """The strain-compatible column: the layers of the last iteration, the
    iterations' moduli ratios, loss factors, γmax and largest relative
    modulus change, and the time histories of that last iteration."""

    layers: list[SoilLayer]
    ratios: list[list[float]] = field(default_factory=list)
    loss_factors: list[list[float]] = field(default_factory=list)
    gamma_max: list[list[float]] = field(default_factory=list)
    changes: list[float] = field(default_factory=list)
    times: np.ndarray | None = None
    interface_acceleration: np.ndarray | None = None  # rows: surface, layer tops, substratum
    strain: np.ndarray | None = None  # rows: layers (mid-depth)


def padded_spectrum(accel: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray, int]:
    """One-sided spectrum of the accelerogram zero-padded to a power of two
    (as DEFI_SOL_EQUI for CHARGEMENT='ONDE_PLANE'), with its frequencies."""
    n = 1
    while n < accel.size:
        n *= 2
    spectrum = np.fft.rfft(accel, n)
    return np.fft.rfftfreq(n, dt), spectrum, n


def equivalent_linear(
    layers: list[SoilLayer],
    substratum: SoilLayer | None,
    accel: np.ndarray,
    dt: float,
    gg_curves: dict[int, StrainCurve],
    damping_curves: dict[int, StrainCurve],
    location: str = "AFFLEURANT",
    coef_gamma: float = 0.65,
    resi_rela: float = 0.05,
    nmax_iter: int = 10,
    freq_cut: float | None = None,
    lysmer: bool = False,
) -> EquivalentLinearResult:
    """Iterate linear frequency-domain solutions until the layers' moduli are
    compatible with their effective strains. The signal's spectrum above
    freq_cut (FREQ_COUP) is discarded."""
    accel = np.asarray(accel, dtype=float)
    freqs, spectrum, n = padded_spectrum(accel, dt)
    if freq_cut is not None:
        spectrum = np.where(freqs <= freq_cut, spectrum, 0.0)
    omega = 2.0 * np.pi * freqs
    # acceleration and displacement share a transfer function; the strain
    # needs displacements: U = -A / ω² (the static term is dropped)
    disp = np.zeros_like(spectrum)
    disp[1:] = -spectrum[1:] / omega[1:] ** 2
    young0 = [ly.young for ly in layers]
    current = [
        SoilLayer(ly.thickness, ly.young, ly.poisson, ly.density, ly.loss_factor, ly.curves)
        for ly in layers
    ]
    result = EquivalentLinearResult(layers=current)
    for _ in range(nmax_iter):
        analysed = [
            SoilLayer(ly.thickness, ly.young, ly.poisson, ly.density, ly.loss_factor, ly.curves)
            for ly in current
        ]
        waves = propagate(analysed, substratum, freqs, lysmer)
        strain_tf = midlayer_strain_transfer(waves, analysed, location)
        strain = np.fft.irfft(strain_tf * disp, n)[:, : accel.size]
        gmax = np.max(np.abs(strain), axis=1)
        ratios, losses, changes = [], [], []
        for layer, e0, gam in zip(current, young0, gmax, strict=True):
            if layer.curves is None:
                raise ValueError("every layer needs its G/Gmax and damping curves")
            ratio = gg_curves[layer.curves](coef_gamma * gam)
            loss = 2.0 * damping_curves[layer.curves](coef_gamma * gam)
            new_young = ratio * e0
            changes.append(abs(layer.young - new_young) / layer.young)
            ratios.append(ratio)
            losses.append(loss)
            layer.young, layer.loss_factor = new_young, loss
        result.ratios.append(ratios)
        result.loss_factors.append(losses)
        result.gamma_max.append(gmax.tolist())
        result.changes.append(max(changes))
        if max(changes) <= resi_rela:
            break
    # as DEFI_SOL_EQUI, the histories are those of the last analysis (the
    # properties it found for a next one are in ratios and loss_factors)
    result.layers = analysed
    motion_tf = interface_transfer(waves, location)
    result.times = dt * np.arange(accel.size)
    result.interface_acceleration = np.fft.irfft(motion_tf * spectrum, n)[:, : accel.size]
    result.strain = strain
    return result


def fe_column_response(
    layers: list[SoilLayer],
    substratum: SoilLayer,
    substratum_thickness: float,
    freqs: np.ndarray,
    lysmer: bool = False,
    cells_per_layer: int = 1,
) -> np.ndarray:
    """Displacements of the nodes of code_aster's finite-element column (the
    free surface first, then each layer's base, the top and the base of the
    substratum cell), per unit displacement of the outcropping rock (twice
    the incident wave), at each frequency.

    DEFI_SOL_EQUI meshes the column 1 m wide with one QUAD4 D_PLAN cell per
    layer and one for the substratum, ties its two sides (LIAISON_GROUP on DX
    and DY) and closes it with a D_PLAN_ABSO edge. With the sides tied, a
    horizontal shear motion is u(y) in each cell, linear between its nodes:
    the cell is exactly a two-node shear element, stiffness G*/h [[1, -1],
    [-1, 1]] (RIGI_MECA_HYST) and consistent mass ρh/6 [[2, 1], [1, 2]]
    (MASS_MECA), per metre of width. The absorbing edge is the dashpot ρVs of
    the substratum's elastic modulus; an incident wave of displacement u_i
    at the base loads it with 2 iω ρVs u_i (the incident wave's traction and
    the dashpot's share of its velocity). ``cells_per_layer`` splits every
    cell (1 is code_aster's mesh)."""
    freqs = np.asarray(freqs, dtype=float)
    omega = 2.0 * np.pi * freqs
    cells = [
        (layer, layer.thickness / cells_per_layer)
        for layer in layers
        for _ in range(cells_per_layer)
    ]
    cells += [(substratum, substratum_thickness / cells_per_layer)] * cells_per_layer
    n = len(cells) + 1
    stiffness = np.zeros((n, n), dtype=complex)
    mass = np.zeros((n, n))
    for k, (soil, h) in enumerate(cells):
        g = complex_shear_modulus(soil.shear_modulus, soil.loss_factor, lysmer)
        stiffness[k : k + 2, k : k + 2] += g / h * np.array([[1.0, -1.0], [-1.0, 1.0]])
        mass[k : k + 2, k : k + 2] += soil.density * h / 6.0 * np.array([[2.0, 1.0], [1.0, 2.0]])
    impedance = np.sqrt(substratum.density * substratum.shear_modulus)
    out = np.empty((n, freqs.size), dtype=complex)
    for j, w in enumerate(omega):
        if w == 0.0:  # the column moves with the rock
            out[:, j] = 1.0
            continue
        system = stiffness - w * w * mass
        system[-1, -1] += 1j * w * impedance
        force = np.zeros(n, dtype=complex)
        force[-1] = 2j * w * impedance * 0.5  # incident wave of half the outcrop motion
        out[:, j] = np.linalg.solve(system, force)
    # the nodes at the layers' bases (and the substratum's top), as in code_aster's mesh
    keep = [0] + [cells_per_layer * (m + 1) for m in range(len(layers))] + [n - 1]
    return out[keep]
