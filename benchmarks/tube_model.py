"""The tube benchmark: a clamped steel tube on three circular supports.

A 2 m tube (R_ext 10 mm, thickness 1 mm, steel) meshed with 40 POU_D_E
elements along X, clamped at both ends, its first 20 modes computed with
asterlite's own beam element functions and scipy. Three CERCLE supports
(gap 0.1 mm, Coulomb friction) hold the nodes at 1/4, 1/2 and 3/4 of the
length; a force turning in the (Y, Z) plane near the first frequency acts
at mid-span and drives the tube into the supports.

``tube_problem()`` returns every number the three integrators share;
``engine_inputs()`` turns it into asterlite's engine objects exactly as
DYNA_VIBRA does (LinearSystem, build_shocks, tabulate_excitation).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg

from asterlite.fem.beam import global_matrices
from asterlite.fem.sections import section_properties

# Tube and material
LENGTH = 2.0
N_ELEMENTS = 40
R_EXT = 0.010
THICKNESS = 0.001
YOUNG = 2.0e11
POISSON = 0.3
DENSITY = 7800.0
N_MODES = 20
DAMPING_RATIO = 0.01

# Supports (DIS_CHOC, OBSTACLE CERCLE, NORM_OBST along the tube axis X)
SUPPORT_NODES = (10, 20, 30)  # 1/4, 1/2, 3/4 of the length
GAP = 1.0e-4
K_NORMAL = 1.0e6
C_NORMAL = 20.0
K_TANGENT = 1.0e5
C_TANGENT = 20.0
MU = 0.3

# Force at mid-span turning in the (Y, Z) plane: FY = F0 sin(W t), FZ = F0 cos(W t)
FORCE_NODE = 20
FORCE_AMPLITUDE = 5.0
FORCE_FREQUENCY_RATIO = 1.0  # forcing frequency / first frequency

DOFS_PER_NODE = 6  # DX DY DZ DRX DRY DRZ


@dataclass
class TubeProblem:
    coords: np.ndarray  # (n_nodes, 3)
    frequencies: np.ndarray  # (N_MODES,) Hz
    omega: np.ndarray  # (N_MODES,) rad/s
    phi_supports: np.ndarray  # (n_supports, 3, N_MODES): DX, DY, DZ rows at each support
    force_y: np.ndarray  # (N_MODES,) generalized vector of FY = 1 N at FORCE_NODE
    force_z: np.ndarray  # (N_MODES,) generalized vector of FZ = 1 N
    forcing_omega: float  # rad/s

    @property
    def mass(self) -> np.ndarray:
        return np.ones(N_MODES)  # modes normalised to unit generalized mass

    @property
    def stiffness(self) -> np.ndarray:
        return self.omega**2

    @property
    def damping(self) -> np.ndarray:
        return 2.0 * DAMPING_RATIO * self.omega

    def support_coords(self) -> np.ndarray:
        return self.coords[list(SUPPORT_NODES)]


def clamped_clamped_frequencies(count: int) -> np.ndarray:
    """Analytic bending frequencies (Hz) of a clamped-clamped Euler beam."""
    beta_l = [4.730040745, 7.853204624, 10.99560784, 14.13716549, 17.27875966]
    beta_l += [(2 * n + 1) * math.pi / 2.0 for n in range(5, count)]
    props = section_properties("CERCLE", {"R": R_EXT, "EP": THICKNESS})
    ei, rho_a = YOUNG * props["IY"], DENSITY * props["A"]
    return np.array([(b / LENGTH) ** 2 * math.sqrt(ei / rho_a) / (2 * math.pi) for b in beta_l])[
        :count
    ]


def assemble_tube():
    """Dense global K and M (6 DOF per node) and the node coordinates."""
    n_nodes = N_ELEMENTS + 1
    coords = np.zeros((n_nodes, 3))
    coords[:, 0] = np.linspace(0.0, LENGTH, n_nodes)
    section = section_properties("CERCLE", {"R": R_EXT, "EP": THICKNESS})
    x1, x2 = coords[:-1], coords[1:]
    args = dict(section=section, young=YOUNG, poisson=POISSON, density=DENSITY)
    k_elem = global_matrices("POU_D_E", "K", x1, x2, **args)
    m_elem = global_matrices("POU_D_E", "M", x1, x2, **args)
    n_dofs = DOFS_PER_NODE * n_nodes
    stiffness, mass = np.zeros((n_dofs, n_dofs)), np.zeros((n_dofs, n_dofs))
    for e in range(N_ELEMENTS):
        dofs = np.arange(DOFS_PER_NODE * e, DOFS_PER_NODE * (e + 2))
        stiffness[np.ix_(dofs, dofs)] += k_elem[e]
        mass[np.ix_(dofs, dofs)] += m_elem[e]
    return coords, stiffness, mass


def tube_problem() -> TubeProblem:
    coords, stiffness, mass = assemble_tube()
    n_dofs = stiffness.shape[0]
    clamped = set(range(DOFS_PER_NODE)) | set(range(n_dofs - DOFS_PER_NODE, n_dofs))
    free = np.array([d for d in range(n_dofs) if d not in clamped])
    eigvals, vectors = scipy.linalg.eigh(
        stiffness[np.ix_(free, free)], mass[np.ix_(free, free)], subset_by_index=(0, N_MODES - 1)
    )
    shapes = np.zeros((n_dofs, N_MODES))
    shapes[free] = vectors  # eigh normalises to unit generalized mass
    omega = np.sqrt(eigvals)
    phi_supports = np.array(
        [shapes[DOFS_PER_NODE * node : DOFS_PER_NODE * node + 3] for node in SUPPORT_NODES]
    )
    force_y = shapes[DOFS_PER_NODE * FORCE_NODE + 1].copy()
    force_z = shapes[DOFS_PER_NODE * FORCE_NODE + 2].copy()
    return TubeProblem(
        coords=coords,
        frequencies=omega / (2.0 * math.pi),
        omega=omega,
        phi_supports=phi_supports,
        force_y=force_y,
        force_z=force_z,
        forcing_omega=FORCE_FREQUENCY_RATIO * omega[0],
    )


# --------------------------------------------------------------------------- engine side


class Harmonic:
    """A multiplier known only through ``evaluate(times)`` (what a FORMULE
    calling a deck function is to DYNA_VIBRA): the engine samples it every
    half step, one window at a time (excitation.tabulate_excitation)."""

    def __init__(self, amplitude: float, omega: float, phase: float) -> None:
        self.amplitude, self.omega, self.phase = amplitude, omega, phase

    def evaluate(self, times) -> np.ndarray:
        return self.amplitude * np.sin(self.omega * np.asarray(times) + self.phase)


class TabulatedHarmonic(Harmonic):
    """The same multiplier as a DEFI_FONCTION with linear interpolation and
    ``points_per_period`` points per period: the engine keeps its points."""

    INTERPOL = ("LIN", "LIN")
    PROL_GAUCHE = PROL_DROITE = "CONSTANT"

    def __init__(self, amplitude, omega, phase, t_end, points_per_period=64) -> None:
        super().__init__(amplitude, omega, phase)
        count = int(math.ceil(t_end * omega / (2.0 * math.pi) * points_per_period)) + 2
        self.abscissas = np.linspace(0.0, t_end, count)
        self.ordinates = Harmonic.evaluate(self, self.abscissas)

    def evaluate(self, times) -> np.ndarray:
        return np.interp(times, self.abscissas, self.ordinates)


def harmonic_formula(amplitude: float, omega: float, phase: float):
    """FORMULE(VALE='A*sin(W*INST+P)', NOM_PARA='INST', A=..., W=..., P=...):
    the engine runs it as a compiled program at each instant."""
    from asterlite.concepts.function import Formula

    return Formula(
        VALE="A*sin(W*INST+P)", NOM_PARA="INST", extra={"A": amplitude, "W": omega, "P": phase}
    )


def engine_inputs(problem: TubeProblem, t_end: float, dt: float, multiplier: str = "formula"):
    """(system, shocks, excitation) built by asterlite's model functions,
    as commands/dyna_vibra.py builds them. ``multiplier``: 'formula' (a
    FORMULE, evaluated exactly at each instant by the kernel), 'sampled'
    (a function known only by ``evaluate``, sampled every half step by
    windows) or 'table' (a DEFI_FONCTION with 64 points per period)."""
    from asterlite.dynamics.excitation import tabulate_excitation
    from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks, modal_damping

    mass = np.diag(problem.mass)
    stiffness = np.diag(problem.stiffness)
    system = LinearSystem(mass, stiffness, modal_damping(mass, stiffness, [DAMPING_RATIO]))
    specs = [
        ShockSpec(
            name=f"SUPPORT{i + 1}",
            obstacle_type="CERCLE",
            node_1=f"N{node + 1}",
            node_2=None,
            coord_1=problem.coords[node].copy(),
            coord_2=None,
            phi_1=problem.phi_supports[i].copy(),
            phi_2=None,
            norm_obst=np.array([1.0, 0.0, 0.0]),
            orig_obst=problem.coords[node].copy(),
            gap=GAP,
            k_n=K_NORMAL,
            c_n=C_NORMAL,
            k_t=K_TANGENT,
            c_t=C_TANGENT,
            mu_dyn=MU,
            mu_stat=MU,
        )
        for i, node in enumerate(SUPPORT_NODES)
    ]
    shocks = build_shocks(specs, system)
    w = problem.forcing_omega
    if multiplier == "table":
        sine = TabulatedHarmonic(FORCE_AMPLITUDE, w, 0.0, t_end)
        cosine = TabulatedHarmonic(FORCE_AMPLITUDE, w, math.pi / 2.0, t_end)
    elif multiplier == "sampled":
        sine = Harmonic(FORCE_AMPLITUDE, w, 0.0)
        cosine = Harmonic(FORCE_AMPLITUDE, w, math.pi / 2.0)
    else:
        sine = harmonic_formula(FORCE_AMPLITUDE, w, 0.0)
        cosine = harmonic_formula(FORCE_AMPLITUDE, w, math.pi / 2.0)
    loads = [(problem.force_y, sine), (problem.force_z, cosine)]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    return system, shocks, excitation


def stable_step(problem: TubeProblem) -> float:
    """A round step below DIFF_CENTRE's limit (1/20 of the shortest period,
    shock stiffness included, as DYNA_VIBRA's VERI_PAS)."""
    from asterlite.dynamics.integrate import step_limit

    system, shocks, _ = engine_inputs(problem, 1.0e-3, 1.0e-4)
    limit = step_limit(system, shocks, "DIFF_CENTRE")
    exponent = math.floor(math.log10(limit))
    for mantissa in (5.0, 2.0, 1.0):
        if mantissa * 10.0**exponent <= limit:
            return mantissa * 10.0**exponent
    return 10.0**exponent


def run_engine(
    problem: TubeProblem, n_steps: int, dt: float, pas_arch: int = 1, multiplier: str = "formula"
):
    """asterlite's DYNA_VIBRA entry point (dynamics.integrate.integrate),
    DIFF_CENTRE, from rest. Returns its RunResult."""
    from asterlite.commands.dyna_vibra_problem import catalogue_options

    from asterlite.dynamics.integrate import integrate

    t_end = n_steps * dt
    system, shocks, excitation = engine_inputs(problem, t_end, dt, multiplier)
    zeros = np.zeros(N_MODES)
    return integrate(
        system,
        shocks,
        excitation,
        "DIFF_CENTRE",
        zeros,
        zeros,
        0.0,
        t_end,
        dt,
        np.array([t_end]),
        pas_arch,
        catalogue_options("DIFF_CENTRE"),
    )
