"""Reference elements and integration families of 3D solid elements.

Each cell type of ``MODELISATION='3D'`` maps to code_aster's reference
element (``HE8``, ``H20``... with its node coordinates in parametric space)
and to the Gauss families its element catalogue names for the stiffness
(``RIGI``) and the mass (``MASS``): the numbers below are code_aster's point
sets (``elraga``), so that element matrices agree with it to rounding even on
distorted cells, where a quadrature is not exact.

Shape functions of the polynomial elements are the Lagrange basis of their
monomial space on the reference nodes (a Vandermonde solve, so no table of
formulas to get wrong); pyramids are rational and written out. Derivatives
are taken by complex step, exact to rounding for these analytic functions.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from itertools import product

import numpy as np

# -- reference nodes (code_aster's parametric coordinates, in its node order) -----------

_HEX_VERTICES = [
    (-1, -1, -1),
    (1, -1, -1),
    (1, 1, -1),
    (-1, 1, -1),
    (-1, -1, 1),
    (1, -1, 1),
    (1, 1, 1),
    (-1, 1, 1),
]
_HEX_EDGES = [
    (0, -1, -1),
    (1, 0, -1),
    (0, 1, -1),
    (-1, 0, -1),
    (-1, -1, 0),
    (1, -1, 0),
    (1, 1, 0),
    (-1, 1, 0),
    (0, -1, 1),
    (1, 0, 1),
    (0, 1, 1),
    (-1, 0, 1),
]
_HEX_FACES_CENTRE = [(0, 0, -1), (0, -1, 0), (1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, 0, 1), (0, 0, 0)]
_TET_VERTICES = [(0, 1, 0), (0, 0, 1), (0, 0, 0), (1, 0, 0)]
_TET_EDGES = [(0, 0.5, 0.5), (0, 0, 0.5), (0, 0.5, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0.5, 0, 0)]
# wedges: x is the axis (-1 bottom, +1 top), (y, z) the triangle
_PENTA_VERTICES = [(-1, 1, 0), (-1, 0, 1), (-1, 0, 0), (1, 1, 0), (1, 0, 1), (1, 0, 0)]
_PENTA_EDGES = [
    (-1, 0.5, 0.5),
    (-1, 0, 0.5),
    (-1, 0.5, 0),
    (0, 1, 0),
    (0, 0, 1),
    (0, 0, 0),
    (1, 0.5, 0.5),
    (1, 0, 0.5),
    (1, 0.5, 0),
]
_PYRAM_VERTICES = [(1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0), (0, 0, 1)]
_PYRAM_EDGES = [
    (0.5, 0.5, 0),
    (-0.5, 0.5, 0),
    (-0.5, -0.5, 0),
    (0.5, -0.5, 0),
    (0.5, 0, 0.5),
    (0, 0.5, 0.5),
    (-0.5, 0, 0.5),
    (0, -0.5, 0.5),
]
_QUAD_NODES = [(-1, -1), (1, -1), (1, 1), (-1, 1), (0, -1), (1, 0), (0, 1), (-1, 0), (0, 0)]
_TRIA_NODES = [(0, 0), (1, 0), (0, 1), (0.5, 0), (0.5, 0.5), (0, 0.5)]

# -- monomial spaces ------------------------------------------------------------------


def _box(dim: int, top: int) -> list[tuple[int, ...]]:
    return list(product(range(top + 1), repeat=dim))


def _simplex(dim: int, degree: int) -> list[tuple[int, ...]]:
    return [e for e in _box(dim, degree) if sum(e) <= degree]


def _serendipity(dim: int) -> list[tuple[int, ...]]:
    """Quadratic serendipity: every exponent <= 2, at most one of them equal to 2."""
    return [e for e in _box(dim, 2) if sum(1 for a in e if a == 2) <= 1]


def _wedge(quadratic: bool) -> list[tuple[int, ...]]:
    """x along the axis, (y, z) on the triangle: P1 x P1 (6 nodes) or
    P2(y, z) x P1(x) plus P1(y, z) x^2 (15 nodes)."""
    if not quadratic:
        return [(a, b, c) for a in (0, 1) for (b, c) in _simplex(2, 1)]
    low = [(a, b, c) for a in (0, 1) for (b, c) in _simplex(2, 2)]
    return low + [(2, b, c) for (b, c) in _simplex(2, 1)]


# -- reference elements --------------------------------------------------------------


@dataclass(frozen=True)
class ReferenceElement:
    """A code_aster reference element: its nodes and its shape functions."""

    name: str
    nodes: np.ndarray  # (n_nodes, dim)
    exponents: tuple | None  # monomial space of a polynomial element, None for pyramids

    @property
    def dim(self) -> int:
        return self.nodes.shape[1]

    @property
    def n_nodes(self) -> int:
        return self.nodes.shape[0]

    def values(self, points) -> np.ndarray:
        """(n_points, n_nodes) shape functions at reference points (real or complex)."""
        points = np.atleast_2d(points)
        if self.exponents is None:
            return _pyramid_values(self.name, points)
        return _monomials(points, self.exponents) @ _lagrange_coefficients(self.name)

    def gradients(self, points) -> np.ndarray:
        """(n_points, n_nodes, dim) derivatives of the shape functions (complex step)."""
        points = np.atleast_2d(np.asarray(points, dtype=float))
        step = 1e-30
        out = np.empty((len(points), self.n_nodes, self.dim))
        for axis in range(self.dim):
            shifted = points.astype(complex)
            shifted[:, axis] += 1j * step
            out[:, :, axis] = self.values(shifted).imag / step
        return out


def _monomials(points: np.ndarray, exponents) -> np.ndarray:
    powers = np.asarray(exponents)
    return np.prod(points[:, None, :] ** powers[None, :, :], axis=2)


@cache
def _lagrange_coefficients(name: str) -> np.ndarray:
    """Coefficients C with N(x) = m(x) C: the inverse Vandermonde matrix."""
    ref = REFERENCE_ELEMENTS[name]
    vandermonde = _monomials(ref.nodes, ref.exponents)
    return np.linalg.inv(vandermonde)


def _pyramid_values(name: str, points: np.ndarray) -> np.ndarray:
    """Rational shape functions of the 5- and 13-node pyramids (square base
    with vertices on the axes, apex at z = 1); at the apex itself only the
    apex function is 1."""
    x, y, z = points[:, 0], points[:, 1], points[:, 2]
    apex = np.abs(z - 1.0) < 1e-6
    gap = np.where(apex, 1.0, 1.0 - z)
    # the four lateral faces: each vanishes on one face of the pyramid
    f1 = x + y + z - 1.0
    f2 = -x + y + z - 1.0
    f3 = -x - y + z - 1.0
    f4 = x - y + z - 1.0
    if name == "PY5":
        out = np.stack([f2 * f3, f3 * f4, f1 * f4, f1 * f2, 4.0 * gap * z], axis=1) / (
            4.0 * gap[:, None]
        )
        nodes = 5
    else:
        half = 2.0 * gap
        out = np.stack(
            [
                f2 * f3 * (x - 0.5) / half,
                f3 * f4 * (y - 0.5) / half,
                f4 * f1 * (-x - 0.5) / half,
                f1 * f2 * (-y - 0.5) / half,
                2.0 * z * (z - 0.5) + 0.0 * x,
                -f2 * f3 * f4 / half,
                -f3 * f4 * f1 / half,
                -f4 * f1 * f2 / half,
                -f1 * f2 * f3 / half,
                z * f2 * f3 / gap,
                z * f3 * f4 / gap,
                z * f4 * f1 / gap,
                z * f1 * f2 / gap,
            ],
            axis=1,
        )
        nodes = 13
    if np.any(apex):
        out[apex] = 0.0
        out[apex, 4] = 1.0
    assert out.shape[1] == nodes
    return out


def _element(name, nodes, exponents) -> ReferenceElement:
    coords = np.array(nodes, dtype=float)
    space = None if exponents is None else tuple(tuple(e) for e in exponents)
    if space is not None and len(space) != len(coords):
        raise AssertionError(f"{name}: {len(space)} monomials for {len(coords)} nodes")
    return ReferenceElement(name, coords, space)


REFERENCE_ELEMENTS: dict[str, ReferenceElement] = {
    ref.name: ref
    for ref in (
        _element("HE8", _HEX_VERTICES, _box(3, 1)),
        _element("H20", _HEX_VERTICES + _HEX_EDGES, _serendipity(3)),
        _element("H27", _HEX_VERTICES + _HEX_EDGES + _HEX_FACES_CENTRE, _box(3, 2)),
        _element("TE4", _TET_VERTICES, _simplex(3, 1)),
        _element("T10", _TET_VERTICES + _TET_EDGES, _simplex(3, 2)),
        _element("PE6", _PENTA_VERTICES, _wedge(False)),
        _element("P15", _PENTA_VERTICES + _PENTA_EDGES, _wedge(True)),
        _element("PY5", _PYRAM_VERTICES, None),
        _element("P13", _PYRAM_VERTICES + _PYRAM_EDGES, None),
        _element("QU4", _QUAD_NODES[:4], _box(2, 1)),
        _element("QU8", _QUAD_NODES[:8], _serendipity(2)),
        _element("QU9", _QUAD_NODES, _box(2, 2)),
        _element("TR3", _TRIA_NODES[:3], _simplex(2, 1)),
        _element("TR6", _TRIA_NODES, _simplex(2, 2)),
    )
}

# -- Gauss families (code_aster's point sets and weights) ------------------------------

_R13 = np.sqrt(1.0 / 3.0)
_R35 = np.sqrt(3.0 / 5.0)
_GAUSS_1D = {
    2: (np.array([-_R13, _R13]), np.array([1.0, 1.0])),
    3: (np.array([-_R35, 0.0, _R35]), np.array([5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0])),
}


def _hexa_rule(n: int):
    """Tensor Gauss rule, x outermost then y then z (code_aster's point order)."""
    a, h = _GAUSS_1D[n]
    pts = np.array([(a[i], a[j], a[k]) for i in range(n) for j in range(n) for k in range(n)])
    wts = np.array([h[i] * h[j] * h[k] for i in range(n) for j in range(n) for k in range(n)])
    return pts, wts


def _quad_rule(n: int):
    """2x2 and 3x3 Gauss rules on the square, in code_aster's point order
    (corners counter-clockwise, then edge midpoints, then the centre)."""
    if n == 2:
        pts = np.array([(-_R13, -_R13), (_R13, -_R13), (_R13, _R13), (-_R13, _R13)])
        return pts, np.ones(4)
    a = _R35
    pts = np.array(
        [(-a, -a), (a, -a), (a, a), (-a, a), (0, -a), (a, 0), (0, a), (-a, 0), (0, 0)], dtype=float
    )
    wts = np.array([25, 25, 25, 25, 40, 40, 40, 40, 64], dtype=float) / 81.0
    return pts, wts


def _triangle_rules() -> dict:
    sixth = 1.0 / 6.0
    a1, b1 = 0.445948490915965, 0.091576213509771
    h1, h2 = 0.111690794839005, 0.054975871827661
    return {
        "FPG3": (
            np.array([(sixth, sixth), (2.0 / 3.0, sixth), (sixth, 2.0 / 3.0)]),
            np.full(3, sixth),
        ),
        "COT3": (np.array([(0.5, 0.5), (0.0, 0.5), (0.5, 0.0)]), np.full(3, sixth)),
        "FPG6": (
            np.array(
                [
                    (b1, b1),
                    (1.0 - 2.0 * b1, b1),
                    (b1, 1.0 - 2.0 * b1),
                    (a1, 1.0 - 2.0 * a1),
                    (a1, a1),
                    (1.0 - 2.0 * a1, a1),
                ]
            ),
            np.array([h2, h2, h2, h1, h1, h1]),
        ),
        "FPG7": _hammer7(),
    }


def _hammer7():
    """Degree-5 seven-point rule on the triangle."""
    r15 = np.sqrt(15.0)
    a, b = (6.0 + r15) / 21.0, (6.0 - r15) / 21.0
    pa, pb = (155.0 + r15) / 2400.0, (155.0 - r15) / 2400.0
    pts = np.array(
        [
            (1.0 / 3.0, 1.0 / 3.0),
            (a, a),
            (1.0 - 2.0 * a, a),
            (a, 1.0 - 2.0 * a),
            (b, b),
            (1.0 - 2.0 * b, b),
            (b, 1.0 - 2.0 * b),
        ]
    )
    return pts, np.array([9.0 / 80.0, pa, pa, pa, pb, pb, pb])


def _wedge_rule(n_axis: int, triangle):
    """Gauss points along the axis (outer loop) times a triangle rule (inner)."""
    a, h = _GAUSS_1D[n_axis]
    tri_pts, tri_wts = triangle
    pts = np.array([(a[i], *tri_pts[k]) for i in range(n_axis) for k in range(len(tri_wts))])
    wts = np.array([h[i] * tri_wts[k] for i in range(n_axis) for k in range(len(tri_wts))])
    return pts, wts


def _tetra_rules() -> dict:
    r5, r15 = np.sqrt(5.0), np.sqrt(15.0)
    a, b = (5.0 - r5) / 20.0, (5.0 + 3.0 * r5) / 20.0
    fpg4 = np.full((4, 3), a)
    fpg4[1, 2] = fpg4[2, 1] = fpg4[3, 0] = b
    fpg5 = np.full((5, 3), 1.0 / 6.0)
    fpg5[0] = 0.25
    fpg5[2, 2] = fpg5[3, 1] = fpg5[4, 0] = 0.5
    b1, b2 = (7.0 + r15) / 34.0, (7.0 - r15) / 34.0
    c1, c2 = (13.0 - 3.0 * r15) / 34.0, (13.0 + 3.0 * r15) / 34.0
    d, e = (5.0 - r15) / 20.0, (5.0 + r15) / 20.0
    h1 = (2665.0 - 14.0 * r15) / 226800.0
    h2 = (2665.0 + 14.0 * r15) / 226800.0
    fpg15 = np.array(
        [(0.25, 0.25, 0.25)]
        + [(b1, b1, b1), (b1, b1, c1), (b1, c1, b1), (c1, b1, b1)]
        + [(b2, b2, b2), (b2, b2, c2), (b2, c2, b2), (c2, b2, b2)]
        + [(d, d, e), (d, e, d), (e, d, d), (d, e, e), (e, d, e), (e, e, d)]
    )
    w15 = np.array([8.0 / 405.0] + [h1] * 4 + [h2] * 4 + [5.0 / 567.0] * 6)
    return {
        "FPG4": (fpg4, np.full(4, 1.0 / 24.0)),
        "FPG5": (fpg5, np.array([-2.0 / 15.0] + [3.0 / 40.0] * 4)),
        "FPG15": (fpg15, w15),
    }


def _pyramid_rules() -> dict:
    h1, h2 = 0.1531754163448146, 0.6372983346207416
    fpg5 = np.array([(0.5, 0, h1), (0, 0.5, h1), (-0.5, 0, h1), (0, -0.5, h1), (0, 0, h2)])
    p, q, r = 0.3252907781991163, 0.65796699712169, 0.3223841495782137
    fpg10 = np.array(
        [
            (0, 0, 0.6772327888861374),
            (0, 0, 0.1251369531087465),
            (-p, -p, r),
            (-p, p, r),
            (p, p, r),
            (p, -p, r),
            (-q, 0, 0.0392482838988154),
            (0, -q, 0.0392482838988154),
            (0, q, 0.0392482838988154),
            (q, 0, 0.0392482838988154),
        ]
    )
    w10 = np.array(
        [0.07582792211376127, 0.1379222683930349]
        + [0.07088305859288367] * 4
        + [0.04234606044708394] * 4
    )
    return {"FPG5": (fpg5, np.full(5, 2.0 / 15.0)), "FPG10": (fpg10, w10)}


def _families() -> dict[tuple[str, str], tuple[np.ndarray, np.ndarray]]:
    out = {}
    for ref in ("HE8", "H20", "H27"):
        out[ref, "FPG8"] = _hexa_rule(2)
        out[ref, "FPG27"] = _hexa_rule(3)
    triangle = _triangle_rules()
    for ref in ("PE6", "P15"):
        out[ref, "FPG6"] = _wedge_rule(2, triangle["COT3"])
        out[ref, "FPG21"] = _wedge_rule(3, triangle["FPG7"])
    for ref in ("TE4", "T10"):
        out.update({(ref, k): v for k, v in _tetra_rules().items()})
    for ref in ("PY5", "P13"):
        out.update({(ref, k): v for k, v in _pyramid_rules().items()})
    for ref in ("QU4", "QU8", "QU9"):
        out[ref, "FPG4"] = _quad_rule(2)
        out[ref, "FPG9"] = _quad_rule(3)
    for ref in ("TR3", "TR6"):
        out.update({(ref, k): triangle[k] for k in ("FPG3", "FPG6", "COT3")})
    return out


#: (reference element, family) -> (points (n, dim), weights (n,))
GAUSS_FAMILIES = _families()


def gauss_family(reference: str, family: str) -> tuple[np.ndarray, np.ndarray]:
    """Points and weights of a family; FPG1 is code_aster's one-point rule at
    the mean of the reference nodes, weighted by the reference volume."""
    if family == "FPG1":
        ref = REFERENCE_ELEMENTS[reference]
        volume = float(np.sum(GAUSS_FAMILIES[reference, _VOLUME_RULE[reference]][1]))
        return ref.nodes.mean(axis=0)[None, :], np.array([volume])
    return GAUSS_FAMILIES[reference, family]


_VOLUME_RULE = {
    "HE8": "FPG8",
    "H20": "FPG8",
    "H27": "FPG8",
    "TE4": "FPG4",
    "T10": "FPG4",
    "PE6": "FPG6",
    "P15": "FPG6",
    "PY5": "FPG5",
    "P13": "FPG5",
    "QU4": "FPG4",
    "QU8": "FPG4",
    "QU9": "FPG4",
    "TR3": "FPG3",
    "TR6": "FPG3",
}


@dataclass(frozen=True)
class CellKind:
    """What the 3D modelisation uses on one cell type."""

    reference: str
    rigi: str  # Gauss family of the stiffness (and loads, mass properties)
    mass: str  # Gauss family of the mass


#: volume cells of MODELISATION='3D' (code_aster's MECA_HEXA8 ... MECA_PYRAM13)
VOLUME_CELLS = {
    "HEXA8": CellKind("HE8", "FPG8", "FPG8"),
    "HEXA20": CellKind("H20", "FPG27", "FPG27"),
    "HEXA27": CellKind("H27", "FPG27", "FPG27"),
    "PENTA6": CellKind("PE6", "FPG6", "FPG6"),
    "PENTA15": CellKind("P15", "FPG21", "FPG21"),
    "TETRA4": CellKind("TE4", "FPG1", "FPG4"),
    "TETRA10": CellKind("T10", "FPG5", "FPG15"),
    "PYRAM5": CellKind("PY5", "FPG5", "FPG5"),
    "PYRAM13": CellKind("P13", "FPG10", "FPG10"),
}
#: face cells of MODELISATION='3D' (MECA_FACE3 ... MECA_FACE9): loads only
FACE_CELLS = {
    "TRIA3": CellKind("TR3", "FPG3", "FPG3"),
    "TRIA6": CellKind("TR6", "FPG6", "FPG6"),
    "QUAD4": CellKind("QU4", "FPG4", "FPG4"),
    "QUAD8": CellKind("QU8", "FPG9", "FPG9"),
    "QUAD9": CellKind("QU9", "FPG9", "FPG9"),
}
#: edge cells MODELISATION='3D' also takes (MECA_ARETE2/3): no matrix
EDGE_CELLS = ("SEG2", "SEG3")


@cache
def tabulated(reference: str, family: str):
    """(values (q, n), gradients (q, n, dim), weights (q,)) of a reference
    element on a family, computed once."""
    ref = REFERENCE_ELEMENTS[reference]
    points, weights = gauss_family(reference, family)
    return ref.values(points).real, ref.gradients(points), weights
