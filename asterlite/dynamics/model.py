"""Numerical model of a DYNA_VIBRA TRAN/GENE run, in flat arrays for the kernels.

Everything here runs once, in numpy: generalized matrices, modal damping,
shock rows (frame, gaps, stiffnesses, friction, mode shapes at the nodes),
tabulated excitations, the critical step and code_aster's optimal
tangential damping.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from asterlite.dynamics import contact as C
from asterlite.dynamics.formula import STACK_DEPTH, formula_program, program_tables
from asterlite.dynamics.geometry import default_origin, local_frame, rest_side_signs
from asterlite.dynamics.laws import kernel as law_kernel

COMPONENTS = ("DX", "DY", "DZ")
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
    # mode (AMOR_MODAL, or a MATR_AMOR stored DIAG), None for a full MATR_AMOR.
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
        return (
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
    """code_aster's AMOR_DIA for a MATR_AMOR stored DIAG (dtmprep): c_i / m_i,
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
    # relations other than DIS_CHOC (asterlite.dynamics.laws): the packed law
    # parameters, the internal variables before the first step, the local
    # frame when it is not the obstacle's (rows: local axes) and the
    # rotation mode shapes (DRX, DRY, DRZ rows) of the nodes
    relation: str = "DIS_CHOC"
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
        return (
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
        (3, n_modes) and ``rest[s, node]`` = rot (coord - ORIG_OBST)."""
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
            flags[s, C.F_LAW] = law_kernel.LAW_CODES[spec.relation]
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
    """The AMOR_TAN code_aster 13 to 15 computed when RIGI_TAN is given
    without it (dtmprep_noli_choc of those versions, §3.5): the mode of
    largest generalized mass (whatever its motion at the contact), its
    AMOR_DIA entry (2 ξ ω for AMOR_MODAL, c/m for a MATR_AMOR stored DIAG;
    C_ii for a full MATR_AMOR) taken in place of ξ, and no floor at 0:

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


@dataclass(frozen=True)
class StabilityLimit:
    """What sets the shortest period of code_aster's VERI_PAS estimate.

    ``period`` is the shortest period (s); ``mode`` the 1-based index of
    the mode it belongs to (0 when no mode has a nonzero frequency); when a
    shock stiffens that mode, ``shock`` / ``node`` name the connection and
    the node, ``stiffness`` is the keyword (``RIGI_NOR`` or ``RIGI_TAN``),
    ``stiffness_value`` its value and ``component`` the global component
    (DX, DY, DZ) of the mode shape it acts on.
    """

    period: float
    mode: int = 0
    mode_frequency: float = 0.0
    shock: str | None = None
    node: str | None = None
    stiffness: str | None = None
    stiffness_value: float = 0.0
    component: str | None = None

    @property
    def frequency(self) -> float:
        """Frequency (Hz) of the shortest period (stiffened by the shock, if any)."""
        return 1.0 / self.period

    def cause(self) -> str:
        """A sentence naming what sets the period, for messages."""
        if self.mode == 0:
            return "no mode with a nonzero frequency"
        if self.shock is None:
            return f"mode {self.mode} ({self.mode_frequency:.6g} Hz), no shock stiffens it more"
        node = f" (node {self.node})" if self.node else ""
        return (
            f"shock {self.shock!r}{node}: {self.stiffness}={self.stiffness_value:.6g} N/m "
            f"on the {self.component} component of mode {self.mode} "
            f"({self.mode_frequency:.6g} Hz) raises it to {self.frequency:.6g} Hz"
        )


def stability_limit(system: LinearSystem, shocks: ShockSet) -> StabilityLimit:
    """Smallest period among the modes, each stiffened by every shock's normal
    and tangential stiffness on each of its shape components (code_aster's
    VERI_PAS estimate), with what sets it (see :class:`StabilityLimit`)."""
    omega = np.sqrt(system.omega2)
    masses = np.diag(system.mass)
    eps = np.finfo(float).eps * 1.0e5
    best = StabilityLimit(period=1.0e10)
    for j, w in enumerate(omega):
        if abs(w) > eps:
            period = 2.0 * math.pi / w
            if best.mode == 0 or period < best.period:
                best = StabilityLimit(period, j + 1, w / (2.0 * math.pi))
    for s in range(shocks.count):
        k_n, k_t = shocks.params[s, C.P_KN], shocks.params[s, C.P_KT]
        nodes = 2 if shocks.flags[s, C.F_TWO_NODES] else 1
        spec = shocks.specs[s]
        for node in range(nodes):
            phi = shocks.phis[s, node]
            for j in range(system.n_modes):
                if abs(omega[j]) <= eps or abs(masses[j]) <= eps:
                    continue
                for keyword, k in (("RIGI_NOR", k_n), ("RIGI_TAN", k_t)):
                    if abs(k) > eps:
                        for c in range(3):
                            period = (
                                2.0
                                * math.pi
                                / math.sqrt(omega[j] ** 2 + k * phi[c, j] ** 2 / masses[j])
                            )
                            if period < best.period:
                                best = StabilityLimit(
                                    period,
                                    j + 1,
                                    omega[j] / (2.0 * math.pi),
                                    spec.name,
                                    spec.node_1 if node == 0 else spec.node_2,
                                    keyword,
                                    float(k),
                                    COMPONENTS[c],
                                )
    return best


def contact_limit(system: LinearSystem, shocks: ShockSet) -> StabilityLimit:
    """:func:`stability_limit` with only the DIS_CHOC normal stiffnesses:
    the shortest period of a mode while a shock is in contact
    (``mode == 0`` when no shock has a normal stiffness)."""
    dis_choc = [s for s in range(shocks.count) if shocks.specs[s].relation == "DIS_CHOC"]
    normal_only = ShockSet(
        [shocks.specs[s] for s in dis_choc],
        shocks.flags[dis_choc],
        shocks.params[dis_choc].copy(),
        shocks.rots[dis_choc],
        shocks.phis[dis_choc],
        shocks.polars[dis_choc],
    )
    normal_only.params[:, C.P_KT] = 0.0
    limit = stability_limit(system, normal_only)
    return limit if limit.shock is not None else StabilityLimit(period=limit.period)


def stability_period(system: LinearSystem, shocks: ShockSet) -> float:
    """Smallest period among the modes, each stiffened by every shock's normal
    and tangential stiffness on each of its shape components (code_aster's
    VERI_PAS estimate); :func:`stability_limit` also says what sets it."""
    return stability_limit(system, shocks).period


@dataclass(frozen=True)
class DampedLimit:
    """The largest stable step of code_aster's explicit DIFF_CENTRE
    (v += dt a, then q += dt v) once damping is counted, and what sets it.

    For one mode of pulsation ω (stiffened as in :func:`stability_limit`)
    and damping c per unit mass (modal 2 ξ ω, plus AMOR_NOR or AMOR_TAN
    times the squared shape component over the modal mass), the update is
    stable while (ω dt)² + 2 c dt <= 4, i.e. dt <= 4 / (c + sqrt(c² + 4 ω²))
    (2/ω without damping, about 1/(ξ ω) for heavy damping). ``shock`` is
    None when the mode's own damping sets it; ``damping`` is then
    ``AMOR_REDUIT``."""

    step: float
    mode: int = 0
    ratio: float = 0.0  # equivalent reduced damping c / (2 ω)
    shock: str | None = None
    node: str | None = None
    damping: str | None = None
    damping_value: float = 0.0
    component: str | None = None
    per_mass: float = 0.0  # the damping per unit mass c (1/s): c·dt is the stage's figure

    def cause(self) -> str:
        if self.mode == 0:
            return "no mode with a nonzero frequency"
        if self.shock is None:
            return f"the modal damping of mode {self.mode} (reduced damping {self.ratio:.6g})"
        node = f" (node {self.node})" if self.node else ""
        return (
            f"shock {self.shock!r}{node}: {self.damping}={self.damping_value:.6g} N.s/m on "
            f"the {self.component} component of mode {self.mode} (equivalent reduced "
            f"damping {self.ratio:.6g})"
        )


def explicit_step(omega2: float, damping: float) -> float:
    """Largest stable step of v += dt (-ω² q - c v), q += dt v."""
    return 4.0 / (damping + math.sqrt(damping * damping + 4.0 * omega2))


def damped_step_limit(system: LinearSystem, shocks: ShockSet) -> DampedLimit:
    """The damping-aware stability limit of the explicit DIFF_CENTRE update
    (see :class:`DampedLimit`): modal damping (diagonal terms) and each
    shock's AMOR_NOR / AMOR_TAN with its RIGI_NOR / RIGI_TAN on each shape
    component of each mode. Without damping it is 2/ω = T/π, far above
    VERI_PAS's T/20: it only binds for heavy damping (an equivalent reduced
    damping above about 3)."""
    omega2 = system.omega2
    masses = np.diag(system.mass)
    damping = np.diag(system.damping)
    eps = np.finfo(float).eps * 1.0e5
    best = DampedLimit(step=math.inf)
    usable = [
        j for j in range(system.n_modes) if math.sqrt(omega2[j]) > eps and abs(masses[j]) > eps
    ]
    for j in usable:
        c = damping[j] / masses[j]
        step = explicit_step(omega2[j], c)
        if step < best.step:
            ratio = c / (2.0 * math.sqrt(omega2[j]))
            best = DampedLimit(step, j + 1, ratio, damping="AMOR_REDUIT")
    for s in range(shocks.count):
        p = shocks.params[s]
        pairs = (("AMOR_NOR", p[C.P_KN], p[C.P_CN]), ("AMOR_TAN", p[C.P_KT], p[C.P_CT]))
        nodes = 2 if shocks.flags[s, C.F_TWO_NODES] else 1
        spec = shocks.specs[s]
        for node in range(nodes):
            phi = shocks.phis[s, node]
            for j in usable:
                for keyword, k, c_shock in pairs:
                    if abs(c_shock) <= eps:
                        continue
                    for c in range(3):
                        share = phi[c, j] ** 2 / masses[j]
                        w2 = omega2[j] + abs(k) * share
                        c_total = damping[j] / masses[j] + c_shock * share
                        step = explicit_step(w2, c_total)
                        if step < best.step:
                            best = DampedLimit(
                                step,
                                j + 1,
                                c_total / (2.0 * math.sqrt(w2)),
                                spec.name,
                                spec.node_1 if node == 0 else spec.node_2,
                                keyword,
                                float(c_shock),
                                COMPONENTS[c],
                            )
    return best


def shock_damping_limit(
    system: LinearSystem, shocks: ShockSet, radius: float, modal: bool = True
) -> DampedLimit:
    """Largest step at which the explicit stages of an adaptive scheme stay
    stable once a shock's AMOR_NOR / AMOR_TAN acts (what sets it, see
    :class:`DampedLimit`), ``math.inf`` without shock damping.

    For each mode and each shape component of each damped shock, with
    ω² stiffened by RIGI_NOR / RIGI_TAN and c the shock damping per unit
    mass (plus the modal damping when ``modal``: RUNGE_KUTTA_* treat it
    explicitly, DEVOGE implicitly), the step is ``radius / 2`` times
    :func:`explicit_step`: ``radius / c`` for a heavy damping, where the
    stiff real eigenvalue -c must stay inside the scheme's real stability
    interval [-radius, 0] (2.51 for RUNGE_KUTTA_32, 3.31 for
    RUNGE_KUTTA_54, 2 for DEVOGE's finite-difference shock velocities).
    Error control alone does not keep the step there: entering a stiffly
    damped contact after a long free flight, an over-large step can
    amplify the stages so much that code_aster's estimate misjudges it.
    The same numbers as the kernels' cap (:func:`asterlite.dynamics.
    adapt_control.shock_damping_step`), for diagonal mass matrices."""
    omega2 = system.omega2
    masses = np.diag(system.mass)
    damping = np.diag(system.damping)
    eps = np.finfo(float).eps * 1.0e5
    best = DampedLimit(step=math.inf)
    usable = [j for j in range(system.n_modes) if abs(masses[j]) > eps]
    for s in range(shocks.count):
        p = shocks.params[s]
        pairs = (("AMOR_NOR", p[C.P_KN], p[C.P_CN]), ("AMOR_TAN", p[C.P_KT], p[C.P_CT]))
        nodes = 2 if shocks.flags[s, C.F_TWO_NODES] else 1
        spec = shocks.specs[s]
        for node in range(nodes):
            phi = shocks.phis[s, node]
            for j in usable:
                own = damping[j] / masses[j] if modal else 0.0
                for keyword, k, c_shock in pairs:
                    if abs(c_shock) <= eps:
                        continue
                    for c in range(3):
                        share = phi[c, j] ** 2 / masses[j]
                        if share <= 0.0:
                            continue
                        w2 = omega2[j] + abs(k) * share
                        c_total = own + c_shock * share
                        step = 0.5 * radius * explicit_step(w2, c_total)
                        if step < best.step:
                            best = DampedLimit(
                                step,
                                j + 1,
                                c_total / (2.0 * math.sqrt(w2)),
                                spec.name,
                                spec.node_1 if node == 0 else spec.node_2,
                                keyword,
                                float(c_shock),
                                COMPONENTS[c],
                                c_total,
                            )
    return best


def suggested_step(limit: float) -> float:
    """A round step at or below ``limit``: the largest 1, 2, 2.5 or 5 × 10^k
    not above it (``limit`` itself when it is not a positive finite number)."""
    if not (limit > 0.0 and math.isfinite(limit)):
        return limit
    decade = 10.0 ** math.floor(math.log10(limit))
    for mantissa in (10.0, 5.0, 2.5, 2.0, 1.0):
        step = mantissa * decade
        if step <= limit * (1.0 + 1.0e-12):
            return min(step, limit)
    return limit


SAMPLES_PER_WINDOW = 1 << 16  # samples of a windowed multiplier held at a time


@dataclass
class SampledMultiplier:
    """A multiplier without linear points of its own (a FORMULE, a function
    with logarithmic interpolation...), sampled on the regular grid
    t0 + h k, k < count, one window of samples at a time."""

    function: object
    t0: float
    h: float
    count: int

    def window(self, t: float, dt: float):
        """(first index, end index) of the window for a loop standing at
        t with step dt: from two samples before t to at least 4 dt ahead."""
        first = max(0, int(math.floor((t - self.t0) / self.h)) - 2)
        ahead = int(math.ceil((t + 4.0 * abs(dt) - self.t0) / self.h)) + 3
        end = min(self.count, max(first + SAMPLES_PER_WINDOW, ahead))
        return first, end

    def samples(self, first: int, end: int):
        times = self.t0 + self.h * np.arange(first, end)
        return times, np.asarray(self.function.evaluate(times), dtype=float)


@dataclass
class Excitation:
    """Generalized load vectors, each times a piecewise-linear multiplier.

    Row e of ``abscissas``/``ordinates`` holds the multiplier's points
    (``layout[e] = (count, left, right)``, extension codes PROL_CONSTANT or
    PROL_LINEAIRE beyond the ends): a DEFI_FONCTION with linear
    interpolation keeps its own points, so the kernels evaluate it exactly
    as code_aster does at any instant; a FORMULE of INST becomes a program
    the kernels run at each instant (``programs``, :mod:`formula`); other
    multipliers (formulas calling functions, log interpolation) are
    sampled on a regular grid, one window at a time
    (``pending[e] == 1`` while samples follow the window: the time loops
    pause with STATUS_LOADS before stepping past it and :meth:`refill`
    tabulates the next window). ``cursors`` keep each row's last interval.
    """

    vectors: np.ndarray  # (n_exc, n_modes)
    abscissas: np.ndarray  # (n_exc, n_points)
    ordinates: np.ndarray  # (n_exc, n_points)
    layout: np.ndarray  # (n_exc, 3) int: count, left, right
    # MULT_APPUI support motion seen by the shocks: static modes at each
    # shock node (n_shocks, 2, 3, n_supports) and, rows 2k / 2k+1, the
    # displacement / velocity of support k tabulated as the multipliers
    drive_shapes: np.ndarray | None = None
    drive_abscissas: np.ndarray | None = None
    drive_ordinates: np.ndarray | None = None
    drive_layout: np.ndarray | None = None
    sampled: list = field(default_factory=list)  # per row: SampledMultiplier or None
    drive_sampled: list = field(default_factory=list)
    programs: list = field(default_factory=list)  # per row: formula program or None

    def __post_init__(self) -> None:
        n_exc = self.vectors.shape[0]
        self.programs = list(self.programs) or [None] * n_exc
        self.program_codes, self.program_constants = program_tables(self.programs)
        self.program_stack = np.zeros(STACK_DEPTH)
        self.pending = np.zeros(n_exc, dtype=np.int64)
        self.cursors = np.zeros(n_exc, dtype=np.int64)
        self.sampled = list(self.sampled) or [None] * n_exc
        if self.drive_shapes is None:
            self.drive_shapes = np.zeros((0, 2, 3, 0))
            self.drive_abscissas = np.zeros((0, 1))
            self.drive_ordinates = np.zeros((0, 1))
            self.drive_layout = np.zeros((0, 3), dtype=np.int64)
        n_drive = self.drive_layout.shape[0]
        self.drive_pending = np.zeros(n_drive, dtype=np.int64)
        self.drive_cursors = np.zeros(n_drive, dtype=np.int64)
        self.drive_sampled = list(self.drive_sampled) or [None] * n_drive

    def bundle(self):
        return (
            self.vectors,
            self.abscissas,
            self.ordinates,
            self.layout,
            self.drive_shapes,
            self.drive_abscissas,
            self.drive_ordinates,
            self.drive_layout,
            self.pending,
            self.cursors,
            self.drive_pending,
            self.drive_cursors,
            self.program_codes,
            self.program_constants,
            self.program_stack,
        )

    def add_support_motion(self, shapes: np.ndarray, motions, t0, t_end, h) -> None:
        """``shapes``: (n_shocks, 2, 3, n_supports); ``motions``: one
        (displacement, velocity) pair of functions per support."""
        points = [multiplier_points(f, t0, t_end, h) for pair in motions for f in pair]
        width = table_width(points)
        self.drive_shapes = np.ascontiguousarray(shapes, dtype=float)
        self.drive_abscissas = np.zeros((len(points), width))
        self.drive_ordinates = np.zeros((len(points), width))
        self.drive_layout = np.zeros((len(points), 3), dtype=np.int64)
        self.drive_pending = np.zeros(len(points), dtype=np.int64)
        self.drive_cursors = np.zeros(len(points), dtype=np.int64)
        self.drive_sampled = [None] * len(points)
        for r, row in enumerate(points):
            if isinstance(row, SampledMultiplier):
                self.drive_sampled[r] = row
            else:
                xs, ys, left, right = row
                self.drive_abscissas[r, : len(xs)] = xs
                self.drive_ordinates[r, : len(xs)] = ys
                self.drive_layout[r] = (len(xs), left, right)
        self.refill(t0, 0.0)

    def refill(self, t: float, dt: float) -> bool:
        """Tabulate the window of every sampled row that does not cover
        [t, t + 2 dt] (all of them at the first call). Returns whether the
        tables were reallocated (then bundles must be rebuilt)."""
        grown = False
        for kind in ("", "drive_"):
            sampled = getattr(self, kind + "sampled")
            for row, source in enumerate(sampled):
                if source is None:
                    continue
                xs = getattr(self, kind + "abscissas")
                layout = getattr(self, kind + "layout")
                pending = getattr(self, kind + "pending")
                count = layout[row, 0]
                starts_before = count > 0 and xs[row, 0] <= max(t, source.t0)
                reaches = count > 0 and (pending[row] == 0 or t + 2.0 * dt < xs[row, count - 1])
                if starts_before and reaches:
                    continue
                first, end = source.window(t, dt)
                times, values = source.samples(first, end)
                if len(times) > xs.shape[1]:
                    grown = True
                    for name in ("abscissas", "ordinates"):
                        old = getattr(self, kind + name)
                        new = np.zeros((old.shape[0], len(times)))
                        new[:, : old.shape[1]] = old
                        setattr(self, kind + name, new)
                    xs = getattr(self, kind + "abscissas")
                ys = getattr(self, kind + "ordinates")
                xs[row, : len(times)] = times
                ys[row, : len(times)] = values
                layout[row] = (len(times), PROL_CONSTANT, PROL_CONSTANT)
                pending[row] = 1 if end < source.count else 0
                getattr(self, kind + "cursors")[row] = 0
        return grown


def table_width(points) -> int:
    widths = [1]
    for row in points:
        if isinstance(row, SampledMultiplier):
            widths.append(min(row.count, SAMPLES_PER_WINDOW))
        else:
            widths.append(len(row[0]))
    return max(widths)


PROL_CONSTANT, PROL_LINEAIRE = 0, 1


def multiplier_points(mult, t0: float, t_end: float, h: float):
    """(abscissas, ordinates, left, right) of one multiplier, or a
    :class:`SampledMultiplier` for one sampled every ``h`` by windows."""
    if isinstance(mult, (int, float)):
        return np.array([t0]), np.array([float(mult)]), PROL_CONSTANT, PROL_CONSTANT
    xs = getattr(mult, "abscissas", None)
    ys = getattr(mult, "ordinates", None)
    linear = tuple(getattr(mult, "INTERPOL", ("LIN", "LIN"))) == ("LIN", "LIN")
    if xs is not None and ys is not None and linear and np.isrealobj(ys) and len(xs) > 0:
        mult.evaluate(np.array([t0, t_end]))  # raises for PROL_*='EXCLU' outside the points
        left = PROL_LINEAIRE if getattr(mult, "PROL_GAUCHE", "") == "LINEAIRE" else PROL_CONSTANT
        right = PROL_LINEAIRE if getattr(mult, "PROL_DROITE", "") == "LINEAIRE" else PROL_CONSTANT
        return np.asarray(xs, dtype=float), np.asarray(ys, dtype=float), left, right
    n = max(2, int(math.ceil((t_end - t0) / h)) + 2)
    return SampledMultiplier(mult, t0, h, n)


def kernel_program(mult):
    """The formula program of a multiplier without points of its own, or None."""
    if isinstance(mult, (int, float)) or getattr(mult, "abscissas", None) is not None:
        return None
    return formula_program(mult)


def tabulate_excitation(n_modes: int, loads, t0: float, t_end: float, h: float) -> Excitation:
    """``loads``: list of (vector, multiplier) with multiplier a float, a
    tabulated function (``abscissas``, ``ordinates``, ``INTERPOL``,
    ``PROL_GAUCHE``/``PROL_DROITE``) or any object with ``evaluate(t_array)``
    (a FORMULE of INST runs as a program in the kernels; anything else is
    sampled every ``h`` over [t0, t_end], one window at a time)."""
    programs = [kernel_program(mult) for _, mult in loads]
    points = [
        (np.array([t0]), np.zeros(1), PROL_CONSTANT, PROL_CONSTANT)
        if program is not None
        else multiplier_points(mult, t0, t_end, h)
        for (_, mult), program in zip(loads, programs, strict=True)
    ]
    width = table_width(points)
    vectors = np.zeros((len(loads), n_modes))
    abscissas = np.zeros((len(loads), width))
    ordinates = np.zeros((len(loads), width))
    layout = np.zeros((len(loads), 3), dtype=np.int64)
    sampled = [None] * len(loads)
    for e, ((vector, _), row) in enumerate(zip(loads, points, strict=True)):
        vectors[e] = vector
        if isinstance(row, SampledMultiplier):
            sampled[e] = row
            continue
        xs, ys, left, right = row
        abscissas[e, : len(xs)] = xs
        ordinates[e, : len(xs)] = ys
        layout[e] = (len(xs), left, right)
    excitation = Excitation(
        vectors, abscissas, ordinates, layout, sampled=sampled, programs=programs
    )
    excitation.refill(t0, 0.0)
    return excitation
