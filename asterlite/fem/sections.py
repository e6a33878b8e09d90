"""Beam cross-section properties from ``AFFE_CARA_ELEM/POUTRE`` data.

``section_properties(section, cara)`` turns the values given under
``SECTION='CERCLE' | 'RECTANGLE' | 'GENERALE'`` (constant section) into the
general characteristics the beam elements use, as code_aster computes them
when it builds the ``CARGENPO`` field:

- ``A`` area, ``IY`` / ``IZ`` second moments about the local y / z axes,
  ``JX`` torsion constant;
- ``AY`` / ``AZ`` shear coefficients: the inverse of the shear area factor
  (``A / AY`` is the effective shear area for shear along y), so they are
  >= 1 for real sections. code_aster interpolates them in tables for
  circular and hollow rectangular sections (reproduced below);
- ``EY`` / ``EZ`` shear centre offset, ``RY`` / ``RZ`` / ``RT`` fibre
  distances and torsion radius (stress recovery), ``AI`` inner area,
  ``JG``, ``IYR2``, ``IZR2`` (warping and higher-order terms, unused by
  POU_D_E / POU_D_T).

Geometric sections also keep their data (``R``, ``EP`` or ``HY``, ``HZ``,
``EPY``, ``EPZ``). Values are in the deck's units.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np


class SectionError(ValueError):
    """Missing, unknown or inconsistent section characteristics."""


#: CARA names accepted for each section with VARI_SECT='CONSTANT'.
SECTION_CARA = {
    "CERCLE": ("R", "EP"),
    "RECTANGLE": ("H", "EP", "HY", "HZ", "EPY", "EPZ"),
    "GENERALE": (
        "A",
        "IY",
        "IZ",
        "AY",
        "AZ",
        "EY",
        "EZ",
        "JX",
        "RY",
        "RZ",
        "RT",
        "JG",
        "IYR2",
        "IZR2",
        "AI",
    ),
}

# -- code_aster's shear coefficient tables -----------------------------------
# Circle: coefficient against alpha = inner radius / outer radius (linear
# interpolation, no extrapolation). Solid circle 1.16667 (~7/6), thin tube 2.
_CIRCLE_ALPHA = np.array([0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99, 1.0])
_CIRCLE_COEF = np.array(
    [
        1.16667,
        1.17442,
        1.19877,
        1.28947,
        1.41882,
        1.56277,
        1.69984,
        1.81536,
        1.90233,
        1.95983,
        1.99081,
        1.99781,
        1.99992,
        2.0,
    ]
)

# Hollow rectangle: AY(alpha, beta) with alpha = (HY - 2 EPY) / HY and
# beta = (HZ - 2 EPZ) / HZ, bilinear on this grid (rows: alpha, columns:
# beta); AZ is the same table read at (beta, alpha).
_RECT_GRID = np.array([0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95])
_RECT_COEF = np.array(
    [
        [1.2] * 12,
        [1.2, 1.2091, 1.22903, 1.29961, 1.41338, 1.57689]
        + [1.80293, 2.11482, 2.56072, 3.26505, 4.71451, 6.68937],
        [1.2, 1.21234, 1.23638, 1.31674, 1.44242, 1.62077]
        + [1.86614, 2.20702, 2.70395, 3.51953, 5.35808, 8.19368],
        [1.2, 1.21725, 1.24671, 1.3388, 1.47742, 1.67093]
        + [1.93642, 2.30888, 2.8664, 3.82993, 6.21611, 10.2937],
        [1.2, 1.22028, 1.25225, 1.34797, 1.48853, 1.6827]
        + [1.9487, 2.32387, 2.89403, 3.90732, 6.53601, 11.2361],
        [1.2, 1.22125, 1.25299, 1.34528, 1.47872, 1.66196]
        + [1.91269, 2.26723, 2.81021, 3.79004, 6.40058, 11.1893],
        [1.2, 1.22011, 1.24905, 1.33181, 1.45075, 1.61403]
        + [1.83775, 2.1543, 2.64029, 3.52423, 5.91643, 10.3749],
        [1.2, 1.21699, 1.24091, 1.30911, 1.40786, 1.54462]
        + [1.73307, 2.00002, 2.40936, 3.15426, 5.18602, 9.01404],
        [1.2, 1.21234, 1.22963, 1.27969, 1.35418, 1.45982]
        + [1.60759, 1.81808, 2.13953, 2.71977, 4.29975, 7.29574],
        [1.2, 1.20699, 1.21695, 1.24713, 1.29483, 1.36597]
        + [1.46914, 1.61905, 1.84773, 2.25238, 3.33064, 5.37206],
        [1.2, 1.20223, 1.20561, 1.21707, 1.23759, 1.27159]
        + [1.3254, 1.40907, 1.54135, 1.77105, 2.33808, 3.36741],
        [1.2, 1.20064, 1.20171, 1.20582, 1.2142, 1.22956]
        + [1.25619, 1.30111, 1.37761, 1.51661, 1.84134, 2.37116],
    ]
)

#: Ratio under which an inner dimension counts as zero (solid rectangle).
_SOLID_RATIO = 1.0e-3


def circle_shear_coefficient(inner_ratio: float) -> float:
    """code_aster's shear coefficient of a circular tube of radius ratio Ri/Re."""
    if not 0.0 <= inner_ratio <= 1.0:
        raise SectionError(f"inner/outer radius ratio {inner_ratio} outside [0, 1]")
    return float(np.interp(inner_ratio, _CIRCLE_ALPHA, _CIRCLE_COEF))


def rectangle_shear_coefficient(alpha: float, beta: float) -> float:
    """code_aster's shear coefficient (AY) of a rectangular tube.

    ``alpha`` = (HY - 2 EPY) / HY and ``beta`` = (HZ - 2 EPZ) / HZ; AZ is
    ``rectangle_shear_coefficient(beta, alpha)``. Beyond 0.95 (very thin
    walls) code_aster has no data and stops.
    """
    grid = _RECT_GRID
    if not (0.0 <= alpha <= grid[-1] and 0.0 <= beta <= grid[-1]):
        raise SectionError(
            "rectangular tube too thin for code_aster's shear coefficient table "
            f"((HY-2EPY)/HY = {alpha:.4g}, (HZ-2EPZ)/HZ = {beta:.4g}, both must be <= 0.95)"
        )
    # bilinear: interpolate each alpha row at beta, then across alpha
    at_beta = np.array([np.interp(beta, grid, row) for row in _RECT_COEF])
    return float(np.interp(alpha, grid, at_beta))


def _require(cara: Mapping[str, float], name: str, section: str) -> float:
    if name not in cara:
        raise SectionError(f"SECTION='{section}' needs CARA '{name}'")
    return float(cara[name])


def _positive(value: float, name: str, section: str) -> None:
    if not value > 0.0:
        raise SectionError(f"SECTION='{section}': {name} must be > 0, got {value}")


def circle_properties(cara: Mapping[str, float]) -> dict[str, float]:
    """Solid (R) or hollow (R, EP) circle; EP defaults to R (solid)."""
    r = _require(cara, "R", "CERCLE")
    _positive(r, "R", "CERCLE")
    ep = float(cara.get("EP", r))
    if not 0.0 < ep <= r:
        raise SectionError(f"SECTION='CERCLE': EP must be in ]0, R] (R={r}, EP={ep})")
    ri = r - ep
    iy = np.pi * (r**4 - ri**4) / 4.0
    shear = circle_shear_coefficient(ri / r)
    return {
        "A": np.pi * (r * r - ri * ri),
        "IY": iy,
        "IZ": iy,
        "AY": shear,
        "AZ": shear,
        "EY": 0.0,
        "EZ": 0.0,
        "JX": 2.0 * iy,
        "RY": r,
        "RZ": r,
        "RT": r,
        "AI": np.pi * ri * ri,
        "JG": 0.0,
        "IYR2": 0.0,
        "IZR2": 0.0,
        "R": r,
        "EP": ep,
    }


def rectangle_properties(cara: Mapping[str, float]) -> dict[str, float]:
    """Solid or hollow rectangle: H [EP] (square) or HY, HZ [EPY, EPZ].

    HY is the side along local y, HZ along local z. Wall thicknesses default
    to half the side (solid section).
    """
    if "H" in cara:
        mixed = sorted({"HY", "HZ", "EPY", "EPZ"} & set(cara))
        if mixed:
            raise SectionError(f"SECTION='RECTANGLE': H excludes {', '.join(mixed)}")
        hy = hz = _require(cara, "H", "RECTANGLE")
        epy = epz = float(cara.get("EP", hy / 2.0))
    else:
        if "EP" in cara:
            raise SectionError("SECTION='RECTANGLE': EP goes with H, use EPY/EPZ with HY/HZ")
        hy = _require(cara, "HY", "RECTANGLE")
        hz = _require(cara, "HZ", "RECTANGLE")
        epy = float(cara.get("EPY", hy / 2.0))
        epz = float(cara.get("EPZ", hz / 2.0))
    for name, value in (("HY", hy), ("HZ", hz), ("EPY", epy), ("EPZ", epz)):
        _positive(value, name, "RECTANGLE")
    if epy > hy / 2.0 or epz > hz / 2.0:
        raise SectionError(
            f"SECTION='RECTANGLE': wall thickness above half the side "
            f"(HY={hy}, EPY={epy}, HZ={hz}, EPZ={epz})"
        )
    hyi, hzi = hy - 2.0 * epy, hz - 2.0 * epz
    props = {
        "A": hy * hz - hyi * hzi,
        "IY": (hy * hz**3 - hyi * hzi**3) / 12.0,
        "IZ": (hz * hy**3 - hzi * hyi**3) / 12.0,
        "EY": 0.0,
        "EZ": 0.0,
        "RY": hy / 2.0,
        "RZ": hz / 2.0,
        "JG": 0.0,
        "IYR2": 0.0,
        "IZR2": 0.0,
        "HY": hy,
        "HZ": hz,
        "EPY": epy,
        "EPZ": epz,
    }
    if abs(hyi / hy) <= _SOLID_RATIO or abs(hzi / hz) <= _SOLID_RATIO:
        # solid rectangle: series approximation of Saint-Venant's torsion
        # constant with a >= b the half-sides; shear coefficient 6/5
        a, b = max(hy, hz) / 2.0, min(hy, hz) / 2.0
        jx = a * b**3 * (16.0 / 3.0 - 3.36 * b / a * (1.0 - b**4 / (12.0 * a**4)))
        props.update(
            AY=1.2,
            AZ=1.2,
            JX=jx,
            RT=jx * (3.0 * a + 1.8 * b) / (8.0 * a * a * b * b),
            AI=0.0,
        )
    else:
        # thin-walled closed tube (Bredt) and tabulated shear coefficients
        jx = (
            2.0
            * epy
            * epz
            * (hy - epy) ** 2
            * (hz - epz) ** 2
            / (hy * epy + hz * epz - epy**2 - epz**2)
        )
        alpha, beta = hyi / hy, hzi / hz
        props.update(
            AY=rectangle_shear_coefficient(alpha, beta),
            AZ=rectangle_shear_coefficient(beta, alpha),
            JX=jx,
            RT=jx / (2.0 * epz * hyi * hzi),
            AI=hyi * hzi,
        )
    return props


#: Defaults code_aster gives to absent GENERALE characteristics.
_GENERAL_DEFAULTS = {
    "EY": 0.0,
    "EZ": 0.0,
    "AI": 0.0,
    "JG": 0.0,
    "IYR2": 0.0,
    "IZR2": 0.0,
    "RY": 1.0,
    "RZ": 1.0,
    "RT": 1.0,
}


def general_properties(cara: Mapping[str, float]) -> dict[str, float]:
    """SECTION='GENERALE': A, IY, IZ, JX required; AY, AZ kept only when given.

    Timoshenko elements need AY and AZ: code_aster only warns when they are
    missing and then works with an infinite coefficient (no bending
    stiffness); asterlite's beam elements refuse that instead.
    """
    props = {name: _require(cara, name, "GENERALE") for name in ("A", "IY", "IZ", "JX")}
    for name in ("A", "IY", "IZ", "JX"):
        _positive(props[name], name, "GENERALE")
    for name in ("RY", "RZ", "RT", "AI"):
        if name in cara:
            _positive(float(cara[name]), name, "GENERALE")
    for name in ("AY", "AZ"):
        if name in cara:
            # 0 is allowed: no shear deformation in that plane (Euler)
            if float(cara[name]) < 0.0:
                raise SectionError(f"SECTION='GENERALE': {name} must be >= 0, got {cara[name]}")
            props[name] = float(cara[name])
    for name, default in _GENERAL_DEFAULTS.items():
        props[name] = float(cara.get(name, default))
    return props


_BUILDERS = {
    "CERCLE": circle_properties,
    "RECTANGLE": rectangle_properties,
    "GENERALE": general_properties,
}


def section_properties(
    section: str, cara: Mapping[str, float], vari_sect: str = "CONSTANT"
) -> dict:
    """General characteristics of a constant beam section.

    ``cara`` maps CARA names to values (``dict(zip(CARA, VALE))``). The result
    has at least A, IY, IZ, JX, EY, EZ, RY, RZ, RT, AI, JG, IYR2, IZR2, and
    AY, AZ (always for CERCLE and RECTANGLE, when given for GENERALE), plus
    ``SECTION`` and the geometric data for CERCLE / RECTANGLE.
    """
    section = section.upper()
    if section not in _BUILDERS:
        if section == "COUDE":
            raise SectionError("SECTION='COUDE' (elbow flexibility) is not a beam section")
        raise SectionError(f"unknown SECTION '{section}' (CERCLE, RECTANGLE or GENERALE)")
    if vari_sect.upper() != "CONSTANT":
        raise SectionError(f"VARI_SECT='{vari_sect}' is not supported, only constant sections")
    unknown = sorted(set(cara) - set(SECTION_CARA[section]))
    if unknown:
        raise SectionError(
            f"SECTION='{section}' does not accept CARA {', '.join(unknown)} "
            f"(expected among {', '.join(SECTION_CARA[section])})"
        )
    props = _BUILDERS[section](cara)
    props["SECTION"] = section
    return props


def uniform_varying_section(section: str, vari_sect: str, cara: Mapping[str, float]):
    """The constant-section CARA of a ``VARI_SECT`` section whose start and
    end values are equal (``R_DEBUT``/``R_FIN``, ``HY1``/``HY2``, ``A1``/``A2``
    ...), or None when the section really varies along the beam."""
    section, vari_sect = section.upper(), vari_sect.upper()
    if section == "CERCLE":
        ends = ("_DEBUT", "_FIN")
    else:
        ends = ("1", "2")
    constant: dict[str, float] = {}
    pairs: dict[str, list] = {}
    for name, value in cara.items():
        for k, end in enumerate(ends):
            if name.endswith(end):
                pairs.setdefault(name[: -len(end)], [None, None])[k] = float(value)
                break
        else:  # AFFINE rectangles keep HY, EPY constant
            constant[name] = float(value)
    for base, (start, finish) in pairs.items():
        if start is None or finish is None:
            raise SectionError(f"VARI_SECT='{vari_sect}': {base} needs both its start and end")
        if start != finish:
            return None
        constant[base] = start
    return constant


def cara_dict(cara, vale) -> dict[str, float]:
    """``CARA``/``VALE`` keyword values (scalars or sequences) as a mapping."""
    names = [cara] if isinstance(cara, str) else list(cara)
    values = np.atleast_1d(np.asarray(vale, dtype=float)).tolist()
    if len(names) != len(values):
        raise SectionError(f"CARA has {len(names)} names but VALE {len(values)} values")
    if len(set(names)) != len(names):
        raise SectionError(f"CARA repeats a name: {', '.join(names)}")
    return dict(zip((n.upper() for n in names), values, strict=True))
