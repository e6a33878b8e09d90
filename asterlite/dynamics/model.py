"""Numerical model of a DYNA_VIBRA TRAN/GENE run, in flat arrays for the kernels.

Everything here runs once, in numpy: generalized matrices, modal damping,
shock rows (frame, gaps, stiffnesses, friction, mode shapes at the nodes)
and code_aster's optimal tangential damping. The loads are in
:mod:`asterlite.dynamics.excitation`, the step limits and advice in
:mod:`asterlite.dynamics.step_limits`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from asterlite.dynamics import contact as C
from asterlite.dynamics.geometry import default_origin, local_frame, rest_side_signs
from asterlite.dynamics.laws import kernel as law_kernel
from asterlite.dynamics.layouts import Linear, Shocks

COMPONENTS = ("DX", "DY", "DZ")
# which of a shock's stiffnesses or dampings sets a stability limit, or the modes' own damping
NORMAL, TANGENTIAL, MODAL = "normal", "tangential", "modal"


def parameter_name(direction: str, quantity: str, names: Mapping[str, str] | None) -> str:
    """How a message names a shock's ``direction`` stiffness or damping
    (``quantity``): the caller's word when it gives one."""
    if names and direction in names:
        return names[direction]
    return f"{direction} {quantity}"


OBSTACLE_CODES = {
    "PLAN_Y": C.PLAN_Y,
    "PLAN_Z": C.PLAN_Z,
    "CERCLE": C.CERCLE,
    "DISCRET": C.DISCRET,
    "BI_PLAN_Y": C.BI_PLAN_Y,
    "BI_PLAN_Z": C.BI_PLAN_Z,
    "BI_CERCLE": C.BI_CERCLE,
    "BI_CERC_INT": C.BI_CERC_INT,
}


@dataclass
class LinearSystem:
    """Generalized M, K, C (dense (n, n)) and whether all three are diagonal."""

    mass: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    # code_aster's AMOR_DIA: c_i / m_i per mode when the damping is given per
    # mode (modal damping, or a damping matrix stored diagonal), None for a full damping matrix.
    # At variable rotation speed code_aster damps with M diag(rates) (dtmupmat),
    # at constant speed with diag(rates) M (dtmacce): ``damping`` is the latter.
    damping_rates: np.ndarray | None = None

    def __post_init__(self) -> None:
        self.diagonal = all(is_diagonal(m) for m in (self.mass, self.stiffness, self.damping))
        if self.diagonal:
            self.minv = np.diag(1.0 / np.diag(self.mass))
        else:
            self.minv = np.linalg.inv(self.mass)

    @property
    def n_modes(self) -> int:
        return self.mass.shape[0]

    @property
    def omega2(self) -> np.ndarray:
        """ω_i² from the diagonal terms (code_aster's per-mode pulsations)."""
        m, k = np.diag(self.mass), np.diag(self.stiffness)
        out = np.full(len(m), 1.0e-12)
        ok = np.abs(m) > np.finfo(float).eps
        out[ok] = np.abs(k[ok] / m[ok])
        return out

    def bundle(self):
        """(M⁻¹, K, C, diagonal flag) for the kernels: C-ordered float arrays
        whatever the caller built (a transposed product is Fortran-ordered),
        so that each loop compiles for one layout only (asterlite warmup)."""
        flag = np.array([1 if self.diagonal else 0], dtype=np.int64)
        return Linear(
            np.ascontiguousarray(self.minv, dtype=float),
            np.ascontiguousarray(self.stiffness, dtype=float),
            np.ascontiguousarray(self.damping, dtype=float),
            flag,
        )

    def kernel_matrices(self):
        """(M⁻¹, K, C) for the specialised kernels: 1-D diagonals when all
        three matrices are diagonal (one pass per acceleration), else the
        dense (n, n) matrices. The kernels dispatch on ``ndim`` at compile
        time."""
        if self.diagonal:  # copies: np.diag's read-only view would be kept for one
            return (  # mode, and a read-only array is another type to compile for
                np.array(np.diag(self.minv), dtype=float),
                np.array(np.diag(self.stiffness), dtype=float),
                np.array(np.diag(self.damping), dtype=float),
            )
        return (
            np.ascontiguousarray(self.minv),
            np.ascontiguousarray(self.stiffness),
            np.ascontiguousarray(self.damping),
        )


def rotate_rows(rot: np.ndarray, x: np.ndarray) -> np.ndarray:
    """rot @ x for a (3, n) x, summed as the kernels rotate a vector
    (r0 x0 + r1 x1 + r2 x2, left to right) so that a frame made of 0 and 1
    gives back exactly the same numbers."""
    return rot[:, 0, None] * x[0] + rot[:, 1, None] * x[1] + rot[:, 2, None] * x[2]


def is_diagonal(a: np.ndarray) -> bool:
    return not np.any(a - np.diag(np.diag(a)))


def modal_damping(mass: np.ndarray, stiffness: np.ndarray, ratios) -> np.ndarray:
    """Reduced damping as code_aster builds it: C = diag(2 ξ_i ω_i) · M with
    ω_i = sqrt(|k_ii / m_ii|), i.e. c_i = 2 ξ_i sqrt(k_i m_i) for a diagonal
    mass, each row of a full (Ritz basis) mass scaled otherwise. Missing
    ratios repeat the last one given."""
    return modal_damping_rates(mass, stiffness, ratios)[:, None] * mass


def modal_damping_rates(mass: np.ndarray, stiffness: np.ndarray, ratios) -> np.ndarray:
    """The per-mode rates 2 ξ_i ω_i of :func:`modal_damping` (code_aster's
    AMOR_DIA, dtmprep_damp): ω_i = sqrt(|k_ii / m_ii|), 1e-6 and ξ_i = 1 for
    a massless coordinate (critically damped)."""
    n = mass.shape[0]
    xi = np.asarray(list(ratios), dtype=float)
    if xi.size == 0:
        xi = np.zeros(1)
    if xi.size < n:
        xi = np.concatenate([xi, np.full(n - xi.size, xi[-1])])
    xi = xi[:n].copy()
    m, k = np.diag(mass), np.diag(stiffness)
    tiny = np.abs(m) <= np.finfo(float).eps
    omega = np.where(tiny, 1.0e-6, np.sqrt(np.abs(k / np.where(tiny, 1.0, m))))
    xi[np.abs(m) < np.finfo(float).eps] = 1.0  # a massless coordinate is critically damped
    return 2.0 * xi * omega


def diagonal_damping_rates(mass: np.ndarray, stiffness: np.ndarray, damping) -> np.ndarray:
    """code_aster's AMOR_DIA for a damping matrix stored diagonal (dtmprep): c_i / m_i,
    or 2 ω_i for a massless coordinate."""
    m, c = np.diag(mass), np.diag(damping)
    tiny = np.abs(m) <= np.finfo(float).eps
    rates = modal_damping_rates(mass, stiffness, np.zeros(1))  # 2 ω_i where massless
    return np.where(tiny, rates, c / np.where(tiny, 1.0, m))


@dataclass
class ShockSpec:
    """One DIS_CHOC connection as read from the deck (physical description)."""

    name: str
    obstacle_type: str
    node_1: str
    node_2: str | None
    coord_1: np.ndarray
    coord_2: np.ndarray | None
    phi_1: np.ndarray  # (3, n_modes): DX, DY, DZ rows
    phi_2: np.ndarray | None
    norm_obst: np.ndarray
    angl_vril: float | None = None
    orig_obst: np.ndarray | None = None
    gap: float = 1.0
    dist_1: float = 0.0
    dist_2: float = 0.0
    k_n: float = 0.0
    c_n: float = 0.0
    k_t: float = 0.0
    c_t: float | None = None  # None: optimal value computed when k_t > 0
    mu_dyn: float = 0.0
    mu_stat: float = 0.0
    unidirectional: bool = False
    polar: np.ndarray | None = None  # DISCRET: (angle deg, radius) rows
    extra: dict = field(default_factory=dict)
    source: str = ""  # where the deck gives it (a keyword path below the command), for messages
    # relations other than DIS_CHOC (asterlite.dynamics.laws): the packed law
    # parameters, the internal variables before the first step, the local
    # frame when it is not the obstacle's (rows: local axes) and the
    # rotation mode shapes (DRX, DRY, DRZ rows) of the nodes
    relation: str = "DIS_CHOC"
    law_code: int = 0  # the relation's branch in laws.kernel (0: DIS_CHOC)
    law: np.ndarray | None = None
    law_state: np.ndarray | None = None
    frame: np.ndarray | None = None
    rphi_1: np.ndarray | None = None
    rphi_2: np.ndarray | None = None


@dataclass
class ShockSet:
    """Flat per-shock arrays for the kernels, plus what the result keeps."""

    specs: list[ShockSpec]
    flags: np.ndarray
    params: np.ndarray
    rots: np.ndarray
    phis: np.ndarray
    polars: np.ndarray
    laws: np.ndarray | None = None  # (n, width) packed law parameters, width 0 without laws
    rphis: np.ndarray | None = None  # (n, 2, 3, n_modes) rotation shapes (laws only)

    def __post_init__(self) -> None:
        if self.laws is None:
            self.laws = np.zeros((self.count, 0))
        if self.rphis is None:
            self.rphis = np.zeros((self.count, 2, 3, 0))
        self.law_scratch = law_kernel.scratch()

    @property
    def count(self) -> int:
        return len(self.specs)

    @property
    def has_laws(self) -> bool:
        """Whether a relation other than DIS_CHOC is present (general path only)."""
        return any(spec.relation != "DIS_CHOC" for spec in self.specs)

    @property
    def vint_width(self) -> int:
        return law_kernel.VINT_WIDTH if self.has_laws else C.N_VINT

    def initial_vint(self, t0: float) -> np.ndarray:
        """Internal variables before the first step (laws: their initial
        state and the instant of that state)."""
        vint = np.zeros((self.count, self.vint_width))
        for s, spec in enumerate(self.specs):
            if spec.relation == "DIS_CHOC":
                continue
            if spec.law_state is not None:
                vint[s, : len(spec.law_state)] = spec.law_state
            vint[s, law_kernel.V_TIME] = t0
        return vint

    def bundle(self):
        return Shocks(
            self.flags,
            self.params,
            self.rots,
            self.phis,
            self.polars,
            self.laws,
            self.rphis,
            self.law_scratch,
        )

    def local_arrays(self):
        """(shapes, rest) in each shock's local frame, for
        :func:`contact.local_shock_forces`: ``shapes[s, node]`` = rot Φ
        (3, n_modes) and ``rest[s, node]`` = rot (coord - obstacle origin)."""
        ns = self.count
        shapes = np.zeros_like(self.phis)
        rest = np.zeros((ns, 2, 3))
        for s in range(ns):
            rot = self.rots[s]
            origin = self.params[s, C.P_ORIGIN : C.P_ORIGIN + 3]
            nodes = 2 if self.flags[s, C.F_TWO_NODES] else 1
            for node in range(nodes):
                base = C.P_COORD1 if node == 0 else C.P_COORD2
                coord = self.params[s, base : base + 3]
                shapes[s, node] = rotate_rows(rot, self.phis[s, node])
                rest[s, node] = rotate_rows(rot, (coord - origin)[:, None])[:, 0]
        return shapes, rest


def build_shocks(specs: list[ShockSpec], system: LinearSystem) -> ShockSet:
    n_modes = system.n_modes
    ns = len(specs)
    npol = max([2] + [len(s.polar) for s in specs if s.polar is not None])
    flags = np.zeros((ns, C.N_FLAGS), dtype=np.int64)
    params = np.zeros((ns, C.N_PARAMS))
    rots = np.zeros((ns, 3, 3))
    phis = np.zeros((ns, 2, 3, n_modes))
    polars = np.zeros((ns, npol, 2))
    law_rows = [spec.law for spec in specs if spec.relation != "DIS_CHOC"]
    width = max([0] + [len(law) for law in law_rows if law is not None])
    if law_rows:
        width = max(width, 1)
    laws = np.zeros((ns, width))
    rphis = np.zeros((ns, 2, 3, n_modes if law_rows else 0))
    for s, spec in enumerate(specs):
        two = spec.obstacle_type.startswith("BI_")
        coord2 = spec.coord_2 if two else None
        if spec.frame is not None:
            rot = np.asarray(spec.frame, dtype=float)
        else:
            rot = local_frame(
                spec.obstacle_type, spec.norm_obst, spec.angl_vril, spec.coord_1, coord2
            )
        if spec.relation != "DIS_CHOC":
            if spec.law_code == law_kernel.DIS_CHOC:
                raise ValueError(f"{spec.relation} {spec.name!r}: no branch of laws.kernel given")
            flags[s, C.F_LAW] = spec.law_code
            if spec.law is not None:
                laws[s, : len(spec.law)] = spec.law
            for node, shape in enumerate((spec.rphi_1, spec.rphi_2)):
                if shape is not None:
                    rphis[s, node] = shape
        origin = (
            spec.orig_obst if spec.orig_obst is not None else default_origin(spec.coord_1, coord2)
        )
        origin = np.asarray(origin, dtype=float)
        sign_y, sign_z = rest_side_signs(rot, origin, spec.coord_1, coord2)
        flags[s, C.F_GEOMETRY] = OBSTACLE_CODES[spec.obstacle_type]
        flags[s, C.F_TWO_NODES] = 1 if two else 0
        flags[s, C.F_UNIDIR] = 1 if spec.unidirectional else 0
        rots[s] = rot
        phis[s, 0] = spec.phi_1
        if two:
            phis[s, 1] = spec.phi_2
        if spec.polar is not None:
            pol = np.asarray(spec.polar, dtype=float)
            flags[s, C.F_NPOLAR] = len(pol)
            polars[s, : len(pol), 0] = np.radians(pol[:, 0])
            polars[s, : len(pol), 1] = pol[:, 1]
        c_t = spec.c_t
        if c_t is None:
            c_t = (
                optimal_tangential_damping(spec, rot, system)
                if spec.k_t > np.finfo(float).eps
                else 0.0
            )
        p = params[s]
        p[C.P_GAP], p[C.P_DIST1], p[C.P_DIST2] = spec.gap, spec.dist_1, spec.dist_2
        p[C.P_KN], p[C.P_CN], p[C.P_KT], p[C.P_CT] = spec.k_n, spec.c_n, spec.k_t, c_t
        p[C.P_MU_DYN], p[C.P_MU_STAT] = spec.mu_dyn, spec.mu_stat
        p[C.P_SIGN_Y], p[C.P_SIGN_Z] = sign_y, sign_z
        p[C.P_ORIGIN : C.P_ORIGIN + 3] = origin
        p[C.P_COORD1 : C.P_COORD1 + 3] = spec.coord_1
        if two:
            p[C.P_COORD2 : C.P_COORD2 + 3] = spec.coord_2
    return ShockSet(specs, flags, params, rots, phis, polars, laws, rphis)


def local_bundle(system: LinearSystem, shocks: ShockSet):
    """The specialised kernels' arrays (4th entry of the model tuple):
    (M⁻¹, K, C) as :meth:`LinearSystem.kernel_matrices`, the shock shapes
    and rest positions in their local frames (:meth:`ShockSet.local_arrays`)
    and a (n_shocks, 2, 6) scratch for the support motion."""
    mass_inverse, stiffness, damping = system.kernel_matrices()
    shapes, rest = shocks.local_arrays()
    return mass_inverse, stiffness, damping, shapes, rest, np.zeros((shocks.count, 2, 6))


def optimal_tangential_damping(spec: ShockSpec, rot: np.ndarray, system: LinearSystem) -> float:
    """C_T = 2 sqrt(m (k + K_T)) - 2 ξ sqrt(k m) for the mode that carries the
    most mass in the tangential motion at the contact (seed §6.5 footnote,
    mode choice and normalisation as code_aster)."""
    omega2 = system.omega2
    masses = np.diag(system.mass)
    weights = np.zeros(system.n_modes)
    for j in range(system.n_modes):
        if omega2[j] * omega2[j] < 1.0e-10:
            continue  # static mode: fictitious mass
        shape = spec.phi_1[:, j].copy()
        if spec.obstacle_type.startswith("BI_"):
            shape = spec.phi_2[:, j] - shape
        loc = rot @ shape
        kind = spec.obstacle_type
        if kind in ("BI_PLAN_Y", "PLAN_Y"):
            tangential2 = loc[0] ** 2 + loc[2] ** 2
        elif kind in ("BI_PLAN_Z", "PLAN_Z"):
            tangential2 = loc[0] ** 2 + loc[1] ** 2
        elif kind == "BI_CERCLE":
            axis = spec.coord_1 - spec.coord_2
            axis = axis / np.linalg.norm(axis)
            tangential2 = loc @ loc - (loc @ axis) ** 2
        else:
            tangential2 = loc[0] ** 2
        weights[j] = masses[j] * math.sqrt(tangential2)
    j = int(np.argmax(weights)) if system.n_modes > 1 else 0
    m = masses[j]
    k = omega2[j] * m
    xi = system.damping[j, j] / (2.0 * math.sqrt(omega2[j]) * m)
    return max(0.0, 2.0 * math.sqrt(m * (k + spec.k_t)) - 2.0 * xi * math.sqrt(k * m))


def optimal_tangential_damping_v15(spec: ShockSpec, system: LinearSystem) -> float:
    """The tangential damping code_aster 13 to 15 computed when a tangential stiffness is given
    without it (dtmprep_noli_choc of those versions, §3.5): the mode of
    largest generalized mass (whatever its motion at the contact), its
    AMOR_DIA entry (2 ξ ω for modal damping, c/m for a damping matrix stored diagonal;
    C_ii for a full damping matrix) taken in place of ξ, and no floor at 0:

        C_T = 2 sqrt(m (k + K_T)) - 2 a sqrt(k m),  k = ω² m.

    ``a`` being 2 ξ ω instead of ξ, any modal damping turns the value
    negative once ω ξ exceeds about sqrt(1 + K_T / k) / 2 (the tube of
    ../shared/tube-references: -1.2e6 N s/m where code_aster 17 takes
    +8.0e3): a stick phase then amplifies the tangential velocity instead
    of damping it, and friction slides at the Coulomb cap."""
    masses = np.diag(system.mass)
    j = int(np.argmax(masses))  # the first of equal maxima, as the strict > scan
    m = masses[j]
    omega2 = system.omega2[j]
    if system.damping_rates is not None:
        rate = system.damping_rates[j]
    else:
        rate = system.damping[j, j]  # code_aster's AMOR_FUL(j, j), the full matrix's term
    k = omega2 * m
    return 2.0 * math.sqrt(m * (k + spec.k_t)) - 2.0 * rate * math.sqrt(k * m)
