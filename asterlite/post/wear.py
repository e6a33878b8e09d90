"""Wear of tubes and their supports (POST_USURE, code_aster U4.84.05).

Three steps, each a small function:

1. *wear power* P (W): given (PUIS_USURE), or the Archard power of a shock
   history (:func:`wear_power`, code_aster's definition, the one every
   wear power of asterlite uses: POST_DYNA_MODA_T's PUIS_USURE, the run
   summary, ``asterlite plot --quantity wear``), or per angular sector of the
   contact point (SECTEUR);
2. *worn volume* V(t) of the tube (mobile) and of the obstacle from a wear
   law: ARCHARD V = K·P·t, KWU_EPRI V = K·W·P·t (W a weighting of the
   impact/sliding regime from the histogram of (FN, V_T) couples), EDF_MZ
   V = A·P^B·(d·t + (1 - d)(1 - exp(-N·t))/N) with d = S/(A·P^B);
3. *wear depth* of the tube from the volumes and the contact geometry
   (CONTACT): closed forms for TUBE_BAV, TUBE_TUBE, TUBE_ALESAGE without
   RAYON_OBST, and a root of "volume of the worn lens = tube volume" for the
   others (bisection, as code_aster, so results agree to its tolerance).

Angles are given in degrees and converted here. A depth that cannot be
computed (the tube is worn through) is 9999, code_aster's marker.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from asterlite.errors import CommandError

WORN_THROUGH = 9999.0
NO_VALUE = 9999.0  # what a geometric volume function returns outside its domain

# --------------------------------------------------------------------------
# material data bank (MATER_USURE): wear coefficients measured at EDF for a
# (contact, tube material _ obstacle material) couple; (mobile, obstacle)
# --------------------------------------------------------------------------

ARCHARD_BANK: dict[str, dict[str, tuple[float | None, float | None]]] = {
    "TUBE_BAV": {
        "I600_I600": (1.2e-13, None), "I600TT_I600": (4.5e-14, None),
        "I600TT_I600TT": (1.4e-15, None), "I600_I600CR": (7.2e-14, None),
        "I600TT_I600CR": (9.1e-16, None), "I690TT_I600CR": (1.2e-15, None),
        "I600_Z10C13": (9.9e-14, None), "I600_A405": (6.2e-14, None),
        "I690_A405": (4.1e-16, None), "I600TT_Z6C13": (9.2e-15, None),
        "I600_Z6C13": (7.1e-15, None), "I690_Z6C13": (7.7e-15, None),
        "I600_A347": (1.0e-13, None),
    },
    "TUBE_ALESAGE": {
        "I690_Z10C13": (6.0e-17, None), "I600_I600": (1.6e-13, None),
        "I690_I600": (5.2e-14, None), "I600_I600CR": (2.2e-15, None),
        "I690_I600CR": (4.4e-15, None),
    },
    "TUBE_4_ENCO": {
        "I600_Z10C13": (2.4e-16, None), "I690_Z10C13": (8.2e-17, None),
        "I600_A405": (6.5e-14, None), "I600TT_A405": (1.4e-15, None),
        "I690_A405": (7.8e-15, None),
    },
    "TUBE_3_ENCO": {"I600_Z10C13": (2.5e-16, None), "I690_Z10C13": (2.4e-16, None)},
    "TUBE_TUBE": {"I600_I600": (1.8e-13, None), "I690_I690": (1.0e-12, None)},
    "GRAPPE_ALESAGE": {
        "A304L_A304L": (10.0e-15, 15.0e-15), "A316L_A304L": (10.0e-15, 5.0e-15),
        "NITRURE_A304L": (0.1e-15, 70.0e-15), "CHROME_A304L": (0.1e-15, 50.0e-15),
    },
    "GRAPPE_1_ENCO": {"A304L_A304L": (20.0e-15, 20.0e-15), "A316L_A304L": (30.0e-15, 20.0e-15)},
}  # fmt: skip

# KWU_EPRI: (COEF_USURE, COEF_FNOR, COEF_VTAN, COEF_K, COEF_C) of the mobile
KWU_BANK = {"TUBE_BAV": {"I600_I600": (1.4e-15, 1.4e-15, 1.4e-15, 5.0, 10.0)}}
# EDF_MZ: (COEF_USURE, COEF_S, COEF_B, COEF_N) of the mobile
EDF_MZ_BANK = {"TUBE_BAV": {"I600_I600": (1.0e-13, 1.14e-16, 1.2, 2.44e-8)}}


def bank_entry(bank: dict, contact: str, material: str, law: str):
    try:
        return bank[contact][material]
    except KeyError:
        raise CommandError(
            f"MATER_USURE={material!r} has no {law} coefficients for CONTACT={contact!r}"
        ) from None


# --------------------------------------------------------------------------
# wear power
# --------------------------------------------------------------------------


def block_slices(n: int, n_blocks: int) -> list[slice]:
    """NB_BLOC consecutive blocks of n // NB_BLOC samples (the remainder is
    left out, as code_aster does)."""
    n_blocks = max(int(n_blocks), 1)
    size = n // n_blocks
    return [slice(b * size, (b + 1) * size) for b in range(n_blocks)]


def wear_power(t, fn, vt1, vt2, adherence=None, n_blocks: int = 1) -> float:
    """The Archard wear power PUIS_USURE (W) of an archived shock history, as
    code_aster defines it (statpu, pusure): the history is cut into NB_BLOC
    blocks of n // NB_BLOC instants (the remainder left out); in each block,
    the trapezoid integral of |FN|·|V_T| (V_T = (VT1, VT2), the sliding
    velocity) over the intervals whose first instant is not sticking
    (``adherence`` 0, code_aster's IADH; None: no stick flag, every
    interval), divided by the block's duration; the power is the mean over
    the blocks. A block of fewer than two instants, or of no duration,
    counts as 0."""
    t = np.asarray(t, dtype=float)
    power = np.abs(np.asarray(fn, dtype=float) * np.hypot(vt1, vt2))
    sliding = None if adherence is None else np.asarray(adherence) == 0
    powers = []
    for block in block_slices(t.size, n_blocks):
        tb, pb = t[block], power[block]
        if tb.size < 2 or tb[-1] == tb[0]:
            powers.append(0.0)
            continue
        intervals = (pb[1:] + pb[:-1]) * np.diff(tb) / 2
        if sliding is not None:
            intervals = intervals[sliding[block][:-1]]
        powers.append(float(intervals.sum() / (tb[-1] - tb[0])))
    return float(np.mean(powers))


def history_wear_power(times, fields: dict, n_blocks: int = 1) -> float:
    """:func:`wear_power` of a shock's archived fields (FN, VT1, VT2 and the
    stick flag ADHERENCE, or IADH); 0 without a normal force (relations
    other than DIS_CHOC)."""
    times = np.asarray(times, dtype=float)
    if "FN" not in fields:
        return 0.0
    zeros = np.zeros(times.size)
    adherence = fields.get("ADHERENCE", fields.get("IADH"))
    return wear_power(
        times, fields["FN"], fields.get("VT1", zeros), fields.get("VT2", zeros), adherence, n_blocks
    )


@dataclass
class SectorPower:
    """Archard power per angular sector of the contact point."""

    power: np.ndarray  # mean power while the contact point is in the sector (W)
    occurrences: np.ndarray  # number of intervals spent in the sector
    presence: np.ndarray  # fraction of intervals in the sector

    def weighted(self, coefficients) -> float:
        """Σ coef·occurrences·power / Σ occurrences (the global sector power)."""
        total = self.occurrences.sum()
        if total == 0:
            return 0.0
        return float(np.sum(np.asarray(coefficients) * self.occurrences * self.power) / total)


def contact_angle(dy, dz) -> np.ndarray:
    """Polar angle (degrees) of the contact point in the obstacle plane; 0 at the origin."""
    dy, dz = np.asarray(dy, dtype=float), np.asarray(dz, dtype=float)
    return np.where((dy != 0) | (dz != 0), np.degrees(np.arctan2(dz, dy)), 0.0)


def sector_power(t, fn, vt1, vt2, angle, bounds, n_blocks: int = 1) -> SectorPower:
    """Archard power in each sector ]bounds[i], bounds[i+1]] of the contact
    angle: per block, the trapezoid integral of |FN|·|V_T| over the intervals
    whose first sample lies in the sector, divided by their duration; then
    averaged over the blocks."""
    t, angle = np.asarray(t, dtype=float), np.asarray(angle, dtype=float)
    power = np.abs(np.asarray(fn, dtype=float) * np.hypot(vt1, vt2))
    bounds = np.asarray(bounds, dtype=float)
    n_sect = bounds.size - 1
    sums, counts = np.zeros(n_sect), np.zeros(n_sect, dtype=int)
    for block in block_slices(t.size, n_blocks):
        tb, pb, ab = t[block], power[block], angle[block]
        energy = (pb[1:] + pb[:-1]) * np.diff(tb) / 2
        dt = np.diff(tb)
        for k in range(n_sect):
            inside = (ab[:-1] <= bounds[k + 1]) & (ab[:-1] > bounds[k])
            duration = dt[inside].sum()
            sums[k] += energy[inside].sum() / duration if duration > 0 else 0.0
            counts[k] += int(inside.sum())
    mean_power = sums / max(int(n_blocks), 1)
    total = counts.sum()
    presence = counts / total if total else np.zeros(n_sect)
    return SectorPower(mean_power, counts, presence)


# --------------------------------------------------------------------------
# KWU_EPRI weighting
# --------------------------------------------------------------------------


def kwu_weight(fn, vg, coef_fnor, coef_vtan, k=5.0, c=10.0, fn_max=None, vg_max=None):
    """KWU_EPRI intensity factor W = S_g² / (S_g + S_i).

    The (FN > 0, V_T) couples are sorted in 5 × 5 classes: force classes of
    width int(round(max FN)) // 5 (an integer, as code_aster), velocity
    classes of width max V_T / 5. The impact category (lowest velocity class)
    is weighted by COEF_FNOR·K·(F/C)³, the sliding category by
    COEF_VTAN·F·V² (F, V: class mid-points), the first class counting in
    both. Raises when the force is too small to build classes, or when
    sliding dominates (S_i < S_g), which the law does not cover.
    """
    fn, vg = np.asarray(fn, dtype=float), np.asarray(vg, dtype=float)
    f_top = fn.max(initial=0.0) if fn_max is None else fn_max
    v_top = vg.max(initial=0.0) if vg_max is None else vg_max
    step = int(np.rint(f_top)) // 5
    if step == 0:
        raise CommandError(
            f"KWU_EPRI: the largest normal force ({f_top:g}) is too small to build force classes"
        )
    f_edges = step * np.arange(1, 6, dtype=float)  # upper edges
    v_edges = v_top / 5.0 * np.arange(1, 6)
    loaded = fn > 0
    # class index 0..4: number of upper edges 1..4 strictly exceeded
    fi = np.sum(fn[loaded, None] > f_edges[None, :4], axis=1)
    vi = np.sum(vg[loaded, None] > v_edges[None, :4], axis=1)
    counts = np.zeros((5, 5))  # [velocity class, force class]
    np.add.at(counts, (vi, fi), 1.0)
    share = counts / counts.sum()
    f_mid = (np.concatenate([[0.0], f_edges[:-1]]) + f_edges) / 2
    v_mid = (np.concatenate([[0.0], v_edges[:-1]]) + v_edges) / 2
    impact = coef_fnor * k * (f_mid / c) ** 3
    sliding = coef_vtan * f_mid[None, :] * v_mid[:, None] ** 2
    s_impact = float(np.sum(share[0] * impact))
    s_sliding = float(np.sum(share[1:] * sliding[1:]) + share[0, 0] * sliding[0, 0])
    if s_impact < s_sliding:
        raise CommandError(
            "KWU_EPRI: the sliding category outweighs the impact category "
            f"({s_sliding:g} > {s_impact:g}): the law does not apply"
        )
    return s_sliding**2 / (s_sliding + s_impact)


# --------------------------------------------------------------------------
# wear laws: volume as a function of time
# --------------------------------------------------------------------------


def archard_volume(k: float, power: float, times) -> np.ndarray:
    return k * power * np.asarray(times, dtype=float)


def edf_mz_volume(power, times, a=1.0e-13, b=1.2, n=2.44e-8, s=1.14e-16) -> np.ndarray:
    """EDF_MZ: wear rate A·P^B slowing down with time towards the threshold S."""
    v0 = a * power**b
    d = s / v0
    if d > 1.0:
        raise CommandError(
            f"EDF_MZ: the threshold COEF_S={s:g} exceeds the initial wear rate "
            f"A·P^B={v0:g}: no wear"
        )
    t = np.asarray(times, dtype=float)
    return v0 * (d * t + (1.0 - d) / n * (1.0 - np.exp(-n * t)))


# --------------------------------------------------------------------------
# contact geometries: worn volume as a function of the depth
# --------------------------------------------------------------------------


def _half_angle(chord: float, radius: float) -> float:
    s = chord / radius
    return math.atan2(s, math.sqrt(abs(1.0 - s * s)))


def lens_area(d: float, r_tube: float, r_hole: float) -> float | None:
    """Cross-section worn when a tube of radius r_tube penetrates by d the wall
    of a hole of radius r_hole (two intersecting circles); None outside."""
    c0 = r_hole - r_tube + d
    c1 = r_hole**2 - r_tube**2 - c0**2
    u = r_tube**2 - c1**2 / (4.0 * c0**2)
    if u <= 0:
        return None
    x = math.sqrt(u)
    return r_tube**2 * _half_angle(x, r_tube) + x * c0 - r_hole**2 * _half_angle(x, r_hole)


def _notch_area(d, rt, rs, isthmus):
    area = lens_area(d, rt, rs)
    return None if area is None else area + math.tan(isthmus) * d**2


def tube_hole_volume(d, rt, rs, length):
    area = lens_area(d, rt, rs)
    return NO_VALUE if area is None else 2.0 * length * area


def tube_hole_tilted_short(d, rt, rs, theta):
    """Inclined tube in a hole, depth below L·θ: a wedge of the lens."""
    area = lens_area(d, rt, rs)
    return NO_VALUE if area is None else 2.0 * d * area / (3.0 * theta)


def _frustum(s, s1, length, factor):
    return factor * length * (s + s1 + math.sqrt(s * s1))


def tube_hole_tilted_long(d, rt, rs, length, theta):
    """Inclined tube in a hole, depth above L·θ: a frustum between the lenses
    at both ends of the support."""
    s, s1 = lens_area(d, rt, rs), lens_area(d - length * theta, rt, rs)
    if s is None or s1 is None:
        return NO_VALUE
    return _frustum(s, s1, length, 2.0 / 3.0)


def tube_notch_volume(d, rt, rs, length, isthmus):
    area = _notch_area(d, rt, rs, isthmus)
    return NO_VALUE if area is None else length * area / 2.0


def tube_notch_tilted_short(d, rt, rs, theta, isthmus):
    area = _notch_area(d, rt, rs, isthmus)
    return NO_VALUE if area is None else d * area / (6.0 * theta)


def tube_notch_tilted_long(d, rt, rs, length, theta, isthmus):
    s = _notch_area(d, rt, rs, isthmus)
    s1 = _notch_area(d - length * theta, rt, rs, isthmus)
    if s is None or s1 is None:
        return NO_VALUE
    return _frustum(s, s1, length, 1.0 / 6.0)


def rod_hole_area(d, r_rod, r_hole):
    """Control rod (radius r_rod) worn against a guide hole (radius r_hole):
    the rod-side segment of the lens of the two circles at depth d."""
    c0 = r_hole - r_rod + d
    f_rod = d * (2 * r_hole + d) / (2 * c0)
    f_hole = d * (2 * r_rod - d) / (2 * c0)
    u_rod = f_rod * (2 * r_rod - f_rod)
    u_hole = f_hole * (2 * r_hole - f_hole)
    if u_rod <= 0 or u_hole <= 0:
        return NO_VALUE

    def segment_angle(f, r):
        cos = (r - f) / r
        return math.atan2(math.sqrt(abs(1.0 - cos * cos)), cos)

    return (
        r_rod**2 * segment_angle(f_rod, r_rod)
        - r_hole**2 * segment_angle(f_hole, r_hole)
        - (r_rod - f_rod) * math.sqrt(u_rod)
        + (r_hole - f_hole) * math.sqrt(u_hole)
    )


def bisect_for(func: Callable[[float], float], target: float, lo: float, hi: float,
               rel_tol: float = 1e-6, max_iter: int = 100) -> float | None:  # fmt: skip
    """x in [lo, hi] with func(x) = target for an increasing func, by
    bisection stopped when |func(x) - target| <= rel_tol·|target| (code_aster's
    criterion); None when it does not converge."""
    tolerance = rel_tol * abs(target)
    if abs(func(lo) - target) <= tolerance:
        return lo
    if abs(func(hi) - target) <= tolerance:
        return hi
    left, right = lo, hi
    for _ in range(max_iter):
        x = 0.5 * (left + right)
        value = func(x)
        if abs(value - target) <= tolerance:
            return x
        if value < target:
            left = x
        else:
            right = x
    return None


def root_in(func: Callable[[float], float], lo: float, hi: float) -> float | None:
    """A root of func in [lo, hi] (func changes sign), else None."""
    from scipy.optimize import brentq

    f_lo, f_hi = func(lo), func(hi)
    if f_lo == 0:
        return lo
    if f_lo * f_hi > 0:
        return None
    return brentq(func, lo, hi, xtol=1e-15, rtol=1e-13, maxiter=200)


# --------------------------------------------------------------------------
# depth of the tube
# --------------------------------------------------------------------------

# cubic fits (m³ vs m) of the worn volume of a control rod in a notched guide card
ROD_NOTCH_FIT = (-48.89e3 / 11.0, 106.03 / 11.0, -0.88e-3 / 11.0)
ROD_NOTCH_DEPTH_MAX = 0.00144


@dataclass
class ContactGeometry:
    """CONTACT and its dimensions (lengths in m, angles in degrees)."""

    kind: str
    r_mobile: float | None = None
    r_obstacle: float | None = None
    width: float | None = None  # LARGEUR_OBST
    incline: float | None = None  # ANGL_INCLI
    isthmus: float | None = None  # ANGL_ISTHME
    impact: float | None = None  # ANGL_IMPACT

    def need(self, *names: str) -> None:
        keywords = {
            "r_mobile": "RAYON_MOBILE", "r_obstacle": "RAYON_OBST", "width": "LARGEUR_OBST",
        }  # fmt: skip
        for name in names:
            if getattr(self, name) is None:
                raise CommandError(f"CONTACT={self.kind!r} needs {keywords[name]}")


def tube_depth(geometry: ContactGeometry, v_tube, v_obst) -> np.ndarray:
    """Wear depth of the tube at each instant (P_USUR_TUBE)."""
    v_tube = np.asarray(v_tube, dtype=float)
    v_obst = np.asarray(v_obst, dtype=float)
    kind = geometry.kind
    solver = {
        "TUBE_BAV": _depth_tube_bar,
        "TUBE_ALESAGE": _depth_tube_hole,
        "TUBE_4_ENCO": _depth_tube_notch,
        "TUBE_3_ENCO": _depth_tube_notch,
        "TUBE_TUBE": _depth_tube_tube,
        "GRAPPE_ALESAGE": _depth_rod_hole,
        "GRAPPE_1_ENCO": _depth_rod_notch,
        "GRAPPE_2_ENCO": _depth_rod_notch,
    }.get(kind)
    if solver is None:
        raise CommandError(f"CONTACT={kind!r} is not a known wear geometry")
    return solver(geometry, v_tube, v_obst)


def _depth_tube_bar(g: ContactGeometry, v_tube, v_obst):
    """Tube against an anti-vibration bar: Hertz-like contact ellipse; the
    total depth is split between tube and bar in proportion to volumes."""
    g.need("r_mobile", "width")
    r, width = g.r_mobile, g.width
    ratio = math.cos(math.radians(g.impact)) if g.impact is not None else 1.0
    vt, vo = v_tube * ratio, v_obst * ratio
    total = vt + vo
    with np.errstate(divide="ignore", invalid="ignore"):
        share = vt / total
    if g.incline is None:
        return share * (1.0 / (2.0 * r)) ** (1 / 3) * (3.0 / (4.0 * width) * total) ** (2 / 3)
    theta = math.radians(g.incline)
    edge = width * theta  # depth at which the whole bar width is worn
    depth = share * (1.0 / (2.0 * r)) ** 0.2 * (15.0 * theta / 8.0 * total) ** 0.4
    for i in np.flatnonzero(depth > edge):
        if depth[i] >= r:
            depth[i] = WORN_THROUGH
            continue
        scale = 1.0 + vo[i] / vt[i]  # total depth / tube depth
        factor = 8.0 * math.sqrt(2 * r) / (15.0 * theta * scale)

        def residual(d, vt_i=vt[i], scale=scale, factor=factor):
            total_depth = d * scale
            return vt_i - factor * (abs(total_depth) ** 2.5 - abs(total_depth - edge) ** 2.5)

        root = root_in(residual, edge, r)
        depth[i] = WORN_THROUGH if root is None else root
    return depth


def _monotone_depths(volume_of_depth, targets, lo, hi, check_top=True):
    """Solve volume(d) = target for each instant, starting each search from
    the previous depth (wear only grows)."""
    depths = np.full(len(targets), WORN_THROUGH)
    start = lo
    for i, target in enumerate(targets):
        d = bisect_for(volume_of_depth, target, start, hi)
        if d is None or (check_top and d >= hi):
            continue
        depths[i] = d
        start = d
    return depths


def _two_regime_depths(short, long, targets, edge, hi):
    """Inclined contacts: the 'short' volume law below depth L·θ, the 'long'
    one above."""
    depths = np.full(len(targets), WORN_THROUGH)
    start = 0.0
    for i, target in enumerate(targets):
        d = bisect_for(short, target, start, hi)
        if d is not None and d > edge:
            d = bisect_for(long, target, start, hi)
        if d is None:
            continue
        depths[i] = d
        start = d
    return depths


def _depth_tube_hole(g: ContactGeometry, v_tube, v_obst):
    g.need("r_mobile", "width")
    rt, width = g.r_mobile, g.width
    if g.r_obstacle is None:  # uniform wear around the tube
        return v_tube / (2.0 * math.pi * width * rt)
    rs = g.r_obstacle
    if g.incline is None:
        return _monotone_depths(lambda d: tube_hole_volume(d, rt, rs, width), v_tube, 0.0, rt)
    theta = math.radians(g.incline)
    return _two_regime_depths(
        lambda d: tube_hole_tilted_short(d, rt, rs, theta),
        lambda d: tube_hole_tilted_long(d, rt, rs, width, theta),
        v_tube,
        width * theta,
        2.0 * rs,
    )


def _depth_tube_notch(g: ContactGeometry, v_tube, v_obst):
    g.need("r_mobile", "r_obstacle", "width")
    rt, rs, width = g.r_mobile, g.r_obstacle, g.width
    isthmus = math.radians(g.isthmus) if g.isthmus is not None else 0.0
    # a four-lobed hole touches the tube on two lobes: each takes half the volume
    targets = v_tube / 2.0 if g.kind == "TUBE_4_ENCO" else v_tube
    if g.incline is None:
        return _monotone_depths(
            lambda d: tube_notch_volume(d, rt, rs, width, isthmus), targets, 0.0, rt
        )
    theta = math.radians(g.incline)
    return _two_regime_depths(
        lambda d: tube_notch_tilted_short(d, rt, rs, theta, isthmus),
        lambda d: tube_notch_tilted_long(d, rt, rs, width, theta, isthmus),
        targets,
        width * theta,
        2.0 * rs,
    )


def _depth_tube_tube(g: ContactGeometry, v_tube, v_obst):
    g.need("r_mobile")
    theta = math.radians(g.incline) if g.incline is not None else 0.0
    return (1.0 / (2.0 * g.r_mobile)) ** 0.2 * (15.0 * theta / 8.0 * v_tube) ** 0.4


def _depth_rod_hole(g: ContactGeometry, v_tube, v_obst):
    g.need("r_mobile", "r_obstacle")
    rt, rs = g.r_mobile, g.r_obstacle
    return _monotone_depths(lambda d: rod_hole_area(d, rt, rs), v_tube, 0.0, rs)


def _depth_rod_notch(g: ContactGeometry, v_tube, v_obst):
    """Rod in a guide card with one or two notches: the root of a cubic fit
    of the worn volume, found as code_aster finds it (:func:`guarded_newton`,
    whose absolute step test stops after a few iterations at these depths:
    code_aster's depths are this method's, not the exact roots)."""
    scale = 1.0 if g.kind == "GRAPPE_2_ENCO" else 0.5
    a, b, c = (scale * k for k in ROD_NOTCH_FIT)

    def volume(d):
        return ((a * d + b) * d + c) * d

    def slope(d):
        return (3.0 * a * d + 2.0 * b) * d + c

    limit = volume(ROD_NOTCH_DEPTH_MAX)
    depths = np.full(v_tube.size, WORN_THROUGH)
    start = 0.0
    for i, target in enumerate(v_tube):
        if target > limit:
            continue
        root = guarded_newton(
            lambda d, target=target: (volume(d) - target, slope(d)), start, ROD_NOTCH_DEPTH_MAX
        )
        if root is None or root >= ROD_NOTCH_DEPTH_MAX:
            continue
        depths[i] = start = root
    return depths


def guarded_newton(func, lo: float, hi: float, epsi: float = 1.0e-6, max_iter: int = 100):
    """code_aster's safeguarded Newton iteration for wear depths (USUNEW).

    ``func(x)`` gives (f, f'). Starts at the middle of [lo, hi]; a Newton
    step leaving the bracket or converging too slowly is replaced by
    code_aster's fallback, which sets x to half the bracket width times its
    lower end. Stops when the change is below ``epsi`` relative to x, or the
    step below ``epsi`` in absolute value; None after ``max_iter`` steps."""
    low, high = lo, hi
    x = 0.5 * (lo + hi)
    step = abs(hi - lo)
    f, df = func(x)
    for _ in range(max_iter):
        previous_step = step
        outside = ((x - high) * df - f) * ((x - low) * df - f) >= 0.0
        if outside or abs(2.0 * f) > abs(previous_step * df):
            step = 0.5 * (high - low)
            x = step * low
            if abs(low - x) <= epsi * abs(x):
                return x
        else:
            step = f / df
            before = x
            x = x - step
            if abs(before - x) <= epsi * abs(x):
                return x
        if abs(step) < epsi:
            return x
        f, df = func(x)
        if f < 0.0:
            low = x
        else:
            high = x
    return None


def sector_depth(radius: float, volume, width: float, angle_span: float):
    """Approximate depth worn in one sector (angle_span in degrees, as
    code_aster uses it): the volume spread as a circular segment."""
    inner = radius * radius - 2.0 * np.asarray(volume, dtype=float) / (width * angle_span)
    if np.any(inner < 0):
        raise CommandError("POST_USURE: a sector is worn through (depth beyond the radius)")
    return radius - np.sqrt(inner)
