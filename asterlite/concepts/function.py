"""Functions of one variable (``fonction_sdaster``, ``fonction_c``) and
formulas (``formule``).

Owner: post-processing (``asterlite.post``). Other rooms evaluate functions
with ``Function.evaluate(x)`` / ``Formula.evaluate(x)`` (numpy arrays in,
arrays out) or ``f(x)`` for a scalar; both raise :class:`FunctionDomainError`
(a :class:`CommandError`) outside an ``EXCLU`` range.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.errors import CommandError
from asterlite.lang.numeric import CONSTANTS, FUNCTIONS
from asterlite.lang.values import DeckCallable
from asterlite.post.expression import CompiledExpression

PROLONGATIONS = ("CONSTANT", "LINEAIRE", "EXCLU")


class FunctionDomainError(CommandError):
    """A function was evaluated where it is not defined (EXCLU, INTERPOL='NON')."""


def _axis_kinds(interpol: Any) -> tuple[str, str]:
    """INTERPOL as (abscissa kind, ordinate kind): LIN, LOG or NON."""
    if isinstance(interpol, str):
        interpol = (interpol,)
    kinds = tuple(interpol) or ("LIN",)
    if len(kinds) == 1:
        kinds = (kinds[0], kinds[0])
    return kinds[0], kinds[1]


def interpolate(
    x: np.ndarray,
    abscissas: np.ndarray,
    ordinates: np.ndarray,
    interpol: Any = ("LIN", "LIN"),
    left: str = "EXCLU",
    right: str = "EXCLU",
    name: str = "",
) -> np.ndarray:
    """Piecewise interpolation with code_aster's INTERPOL and PROL_* rules.

    ``ordinates`` may be complex. Within the range the value is interpolated
    (on log axes when asked); outside, CONSTANT repeats the end value,
    LINEAIRE extends the end segment, EXCLU raises FunctionDomainError.
    """
    x = np.asarray(x, dtype=float)
    xs = np.asarray(abscissas, dtype=float)
    ys = np.asarray(ordinates)
    kind_x, kind_y = _axis_kinds(interpol)
    label = f"function {name}" if name else "function"
    if xs.size == 0:
        raise FunctionDomainError(f"{label} has no values")
    # as code_aster, a point outside an EXCLU end by less than 1e-6 of the end
    # interval is taken at the end (round-off in computed abscissas)
    if xs.size > 1:
        slack_left, slack_right = 1e-6 * (xs[1] - xs[0]), 1e-6 * (xs[-1] - xs[-2])
    else:
        slack_left = slack_right = 1e-6 * max(abs(xs[0]), 1.0)
    if left == "EXCLU":
        x = np.where((x < xs[0]) & (x >= xs[0] - slack_left), xs[0], x)
    if right == "EXCLU":
        x = np.where((x > xs[-1]) & (x <= xs[-1] + slack_right), xs[-1], x)
    below, above = x < xs[0], x > xs[-1]
    if left == "EXCLU" and below.any():
        raise FunctionDomainError(
            f"{label} is evaluated at {x[below].min():g}, left of its first abscissa "
            f"{xs[0]:g} (PROL_GAUCHE='EXCLU')"
        )
    if right == "EXCLU" and above.any():
        raise FunctionDomainError(
            f"{label} is evaluated at {x[above].max():g}, right of its last abscissa "
            f"{xs[-1]:g} (PROL_DROITE='EXCLU')"
        )
    if xs.size == 1:
        return np.full(x.shape, ys[0], dtype=ys.dtype)
    if kind_x == "NON" or kind_y == "NON":
        return _exact_lookup(x, xs, ys, label)

    # segment index for each point (end segments for points outside)
    seg = np.clip(np.searchsorted(xs, x, side="right") - 1, 0, xs.size - 2)
    x0, x1 = xs[seg], xs[seg + 1]
    y0, y1 = ys[seg], ys[seg + 1]
    if kind_x == "LOG":
        u, u0, u1 = np.log(x), np.log(x0), np.log(x1)
    else:
        u, u0, u1 = x, x0, x1
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.where(u1 != u0, (u - u0) / np.where(u1 != u0, u1 - u0, 1.0), 0.0)
    if kind_y == "LOG":
        values = np.exp(np.log(y0) + w * (np.log(y1) - np.log(y0)))
    else:
        values = y0 + w * (y1 - y0)
    values = np.asarray(values, dtype=np.result_type(ys.dtype, float))
    if left == "CONSTANT":
        values = np.where(below, ys[0], values)
    if right == "CONSTANT":
        values = np.where(above, ys[-1], values)
    return values


def _exact_lookup(x, xs, ys, label):
    idx = np.clip(np.searchsorted(xs, x), 0, xs.size - 1)
    closest = np.where(
        np.abs(xs[np.maximum(idx - 1, 0)] - x) < np.abs(xs[idx] - x), np.maximum(idx - 1, 0), idx
    )
    scale = max(np.abs(xs).max(), 1.0)
    bad = np.abs(xs[closest] - x) > 1e-10 * scale
    if bad.any():
        raise FunctionDomainError(f"{label} has INTERPOL='NON' and no value at {x[bad][0]:g}")
    return ys[closest]


@dataclass(eq=False)
class Function(Concept, DeckCallable):
    """A tabulated function y(x) with its interpolation and extension rules."""

    aster_types = ("fonction_sdaster", "fonction_class")
    deck_methods = frozenset(
        {"getName", "Valeurs", "Absc", "Ordo", "getValues", "Parametres", "getProperties"}
    )

    abscissas: np.ndarray
    ordinates: np.ndarray
    NOM_PARA: str = "TOUTPARA"
    NOM_RESU: str = "TOUTRESU"
    INTERPOL: tuple[str, str] = ("LIN", "LIN")
    PROL_GAUCHE: str = "EXCLU"
    PROL_DROITE: str = "EXCLU"
    title: str = ""

    def __post_init__(self) -> None:
        self.abscissas = np.asarray(self.abscissas, dtype=float)
        self.ordinates = np.asarray(self.ordinates)
        if self.ordinates.dtype.kind not in "fc":
            self.ordinates = self.ordinates.astype(float)
        self.INTERPOL = _axis_kinds(self.INTERPOL)

    @property
    def is_complex(self) -> bool:
        return self.ordinates.dtype.kind == "c"

    @property
    def nom_para(self) -> tuple[str, ...]:
        return (self.NOM_PARA,)

    def evaluate(self, x) -> np.ndarray:
        """Values at the points ``x`` (array or scalar)."""
        return interpolate(
            np.asarray(x, dtype=float),
            self.abscissas,
            self.ordinates,
            self.INTERPOL,
            self.PROL_GAUCHE,
            self.PROL_DROITE,
            self.name or "",
        )

    def evaluate_many(self, *args) -> np.ndarray:
        if len(args) != 1:
            raise CommandError(f"function {self.name or ''} takes one parameter, got {len(args)}")
        return self.evaluate(args[0])

    def __call__(self, *args, **kwargs):
        if kwargs:
            if len(kwargs) != 1 or self.NOM_PARA not in kwargs:
                raise CommandError(f"function {self.name or ''} depends on {self.NOM_PARA} only")
            args = tuple(kwargs.values())
        value = self.evaluate_many(*args)
        if np.ndim(value) == 0:
            return complex(value) if self.is_complex else float(value)
        return value

    def deck_call(self, args, kwargs, site):
        return self(*args, **kwargs)

    # code_aster's deck API ------------------------------------------------
    def Valeurs(self):  # noqa: N802
        if self.is_complex:
            return [
                self.abscissas.tolist(),
                self.ordinates.real.tolist(),
                self.ordinates.imag.tolist(),
            ]
        return [self.abscissas.tolist(), self.ordinates.tolist()]

    def Absc(self):  # noqa: N802
        return self.abscissas.tolist()

    def Ordo(self):  # noqa: N802
        return self.ordinates.tolist()

    def getValues(self):  # noqa: N802
        """Abscissas then ordinates in one flat list (code_aster's .VALE
        layout), built in place (no third list joining the two)."""
        values = self.abscissas.tolist()
        if self.is_complex:
            values.extend(
                np.column_stack([self.ordinates.real, self.ordinates.imag]).ravel().tolist()
            )
        else:
            values.extend(self.ordinates.tolist())
        return values

    def Parametres(self):  # noqa: N802
        return {
            "TYPE_FONC": "FONCT_C" if self.is_complex else "FONCTION",
            "NOM_PARA": self.NOM_PARA,
            "NOM_RESU": self.NOM_RESU,
            "INTERPOL": list(self.INTERPOL),
            "PROL_GAUCHE": self.PROL_GAUCHE,
            "PROL_DROITE": self.PROL_DROITE,
        }

    def getProperties(self):  # noqa: N802
        kind = "FONCT_C" if self.is_complex else "FONCTION"
        interp = " ".join(self.INTERPOL)
        prol = self.PROL_GAUCHE[0] + self.PROL_DROITE[0]
        return [kind, interp, self.NOM_PARA, self.NOM_RESU, prol, self.name or ""]

    def with_values(self, abscissas, ordinates, **changes) -> Function:
        """A copy with new values (and optionally other attributes)."""
        params = dict(
            NOM_PARA=self.NOM_PARA,
            NOM_RESU=self.NOM_RESU,
            INTERPOL=self.INTERPOL,
            PROL_GAUCHE=self.PROL_GAUCHE,
            PROL_DROITE=self.PROL_DROITE,
        )
        params.update(changes)
        cls = ComplexFunction if np.iscomplexobj(ordinates) else Function
        return cls(np.asarray(abscissas, dtype=float), np.asarray(ordinates), **params)


@dataclass(eq=False)
class ComplexFunction(Function):
    """A function with complex ordinates (``fonction_c``)."""

    aster_types = ("fonction_c",)


@dataclass(eq=False)
class Formula(Concept, DeckCallable):
    """``FORMULE``: an expression of NOM_PARA names and the deck's extra values.

    The expression is parsed and checked once by the formula front end
    (:mod:`asterlite.lang.formula`: the deck's parser, one whitelist, never
    ``eval``) and evaluated on arrays by :mod:`asterlite.post.expression`.
    ``extra`` holds the constants and functions passed as extra keywords.
    """

    aster_types = ("formule",)
    deck_methods = frozenset({"getName", "Parametres", "getProperties"})

    VALE: str
    NOM_PARA: tuple[str, ...]
    extra: dict[str, Any] = field(default_factory=dict)
    complex_result: bool = False

    def __post_init__(self) -> None:
        if isinstance(self.NOM_PARA, str):
            self.NOM_PARA = (self.NOM_PARA,)
        self.NOM_PARA = tuple(self.NOM_PARA)
        self.compiled = CompiledExpression(self.VALE)
        unknown = [
            n
            for n in self.compiled.names
            if n not in self.NOM_PARA and n not in self.extra and not _is_builtin_name(n)
        ]
        if unknown:
            raise CommandError(
                f"FORMULE {self.VALE!r} uses {', '.join(unknown)}: give "
                f"{'it' if len(unknown) == 1 else 'them'} in NOM_PARA or as keyword arguments"
            )

    @property
    def nom_para(self) -> tuple[str, ...]:
        return self.NOM_PARA

    @property
    def NOM_RESU(self) -> str:  # noqa: N802
        return "TOUTRESU"

    def evaluate(self, *args, **kwargs) -> np.ndarray:
        """Values for arrays of the parameters, positionally in NOM_PARA order
        or by name; a single parameter may be passed as one array."""
        values = dict(zip(self.NOM_PARA, args, strict=False))
        values.update(kwargs)
        missing = [p for p in self.NOM_PARA if p not in values]
        if missing or len(args) > len(self.NOM_PARA):
            raise CommandError(
                f"formula {self.name or self.VALE!r} takes {', '.join(self.NOM_PARA)}"
            )
        namespace = dict(self.extra)
        namespace.update({k: np.asarray(v, dtype=float) for k, v in values.items()})
        with np.errstate(all="ignore"):  # a non-finite value is reported below
            result = self.compiled.evaluate(namespace)
        shape = np.broadcast_shapes(*[np.shape(namespace[p]) for p in self.NOM_PARA])
        dtype = complex if self.complex_result else float
        values = np.broadcast_to(np.asarray(result, dtype=dtype), shape).copy()
        self._check_finite(values, namespace, shape)
        return values

    def _check_finite(self, values: np.ndarray, namespace: dict, shape: tuple) -> None:
        """code_aster computes formulas with Python floats, which raise where
        numpy gives NaN or inf (1/0, sqrt(-1), exp(1000)): refuse such a value,
        naming the formula and the first point giving it."""
        bad = ~np.isfinite(values)
        if not bad.any():
            return
        index = np.unravel_index(int(np.argmax(bad)), shape) if shape else ()
        point = ", ".join(
            f"{p}={float(np.broadcast_to(namespace[p], shape)[index])!r}" for p in self.NOM_PARA
        )
        label = f"formula {self.name}" if self.name else "formula"
        raise CommandError(
            f"{label} {self.VALE!r} evaluates to {values[index].item()!r} at {point}: "
            "a finite value is expected"
        )

    def evaluate_many(self, *args) -> np.ndarray:
        return self.evaluate(*args)

    def __call__(self, *args, **kwargs):
        value = self.evaluate(*args, **kwargs)
        if np.ndim(value) == 0:
            return complex(value) if self.complex_result else float(value)
        return value

    def deck_call(self, args, kwargs, site):
        return self(*args, **kwargs)

    def Parametres(self):  # noqa: N802
        return {"NOM_PARA": list(self.NOM_PARA), "NOM_RESU": "TOUTRESU"}

    def getProperties(self):  # noqa: N802
        return ["FORMULE", "", " ".join(self.NOM_PARA), "TOUTRESU", "", self.name or ""]


def _is_builtin_name(name: str) -> bool:
    return name in CONSTANTS or name in FUNCTIONS


def as_callable_values(func: Function | Formula, x) -> np.ndarray:
    """Evaluate a function or a one-parameter formula at ``x``."""
    if isinstance(func, Formula) and len(func.NOM_PARA) != 1:
        raise CommandError(
            f"formula {func.name or ''} has parameters {func.NOM_PARA}: one parameter expected"
        )
    return func.evaluate(np.asarray(x, dtype=float))


@dataclass(eq=False)
class Nappe(Concept, DeckCallable):
    """A function of two parameters (``nappe_sdaster``): one :class:`Function`
    of NOM_PARA_FONC per value of NOM_PARA, interpolated between them."""

    aster_types = ("nappe_sdaster",)
    deck_methods = frozenset({"getName", "Valeurs", "Parametres", "getProperties"})

    parameters: np.ndarray
    functions: list[Function]
    NOM_PARA: str = "TOUTPARA"
    NOM_RESU: str = "TOUTRESU"
    NOM_PARA_FONC: str = "TOUTPARA"
    INTERPOL: tuple[str, str] = ("LIN", "LIN")
    PROL_GAUCHE: str = "EXCLU"
    PROL_DROITE: str = "EXCLU"
    title: str = ""

    def __post_init__(self) -> None:
        self.parameters = np.asarray(self.parameters, dtype=float)
        self.INTERPOL = _axis_kinds(self.INTERPOL)
        if len(self.functions) != self.parameters.size:
            raise CommandError("a nappe needs one function per parameter value")

    @property
    def nom_para(self) -> tuple[str, ...]:
        return (self.NOM_PARA, self.NOM_PARA_FONC)

    def evaluate_many(self, p, x) -> np.ndarray:
        """Values at (p, x): each function at x, then interpolated in p."""
        p, x = np.broadcast_arrays(np.asarray(p, dtype=float), np.asarray(x, dtype=float))
        if self.INTERPOL[1] == "LIN":
            # linear in the ordinates (prolongations included): the value is
            # Σ_k w_k(p) f_k(x), w_k interpolating the k-th unit vector, on whole arrays
            columns = np.array([f.evaluate(x) for f in self.functions], dtype=float)
            unit = np.eye(self.parameters.size)
            weights = np.array(
                [
                    interpolate(
                        p,
                        self.parameters,
                        unit[k],
                        self.INTERPOL,
                        self.PROL_GAUCHE,
                        self.PROL_DROITE,
                        self.name or "",
                    )  # fmt: skip
                    for k in range(self.parameters.size)
                ]
            )
            return np.sum(weights * columns, axis=0)
        out = np.empty(p.shape)
        for index in np.ndindex(p.shape):
            column = np.array([f.evaluate(x[index]) for f in self.functions], dtype=float)
            out[index] = interpolate(
                p[index], self.parameters, column, self.INTERPOL, self.PROL_GAUCHE,
                self.PROL_DROITE, self.name or "",
            )  # fmt: skip
        return out

    def __call__(self, *args, **kwargs):
        if kwargs:
            args = (kwargs[self.NOM_PARA], kwargs[self.NOM_PARA_FONC])
        if len(args) != 2:
            raise CommandError(f"nappe {self.name or ''} takes two parameters")
        value = self.evaluate_many(*args)
        return float(value) if np.ndim(value) == 0 else value

    def deck_call(self, args, kwargs, site):
        return self(*args, **kwargs)

    def Valeurs(self):  # noqa: N802
        return [self.parameters.tolist(), [f.Valeurs() for f in self.functions]]

    def Parametres(self):  # noqa: N802
        first = self.functions[0] if self.functions else None
        return {
            "NOM_PARA": self.NOM_PARA,
            "NOM_RESU": self.NOM_RESU,
            "NOM_PARA_FONC": self.NOM_PARA_FONC,
            "INTERPOL": list(self.INTERPOL),
            "PROL_GAUCHE": self.PROL_GAUCHE,
            "PROL_DROITE": self.PROL_DROITE,
            "INTERPOL_FONC": list(first.INTERPOL) if first else ["LIN", "LIN"],
            "PROL_GAUCHE_FONC": first.PROL_GAUCHE if first else "EXCLU",
            "PROL_DROITE_FONC": first.PROL_DROITE if first else "EXCLU",
        }

    def getProperties(self):  # noqa: N802
        prol = self.PROL_GAUCHE[0] + self.PROL_DROITE[0]
        return ["NAPPE", " ".join(self.INTERPOL), self.NOM_PARA, self.NOM_RESU, prol,
                self.name or "", self.NOM_PARA_FONC]  # fmt: skip
