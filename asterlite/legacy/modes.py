"""MODE_ITER_SIMULT and MODE_ITER_INV as CALC_MODES (code_aster 12 merged them).

The search option moved from ``CALC_FREQ/OPTION`` to ``OPTION``; the
eigensolver parameters (method, Lanczos/Sorensen/Jacobi/QZ tolerances,
inverse-iteration controls of ``CALC_FREQ`` and ``CALC_MODE``) went into
``SOLVEUR_MODAL``. Older decks also wrote ``MATR_A``/``MATR_B``/``MATR_C``.
MODE_ITER_INV's default option was ``AJUSTE`` (CALC_MODES: ``PLUS_PETITE``),
so it is written out.
"""

from __future__ import annotations

from asterlite.legacy.base import Env, Translation, factor, lit, single
from asterlite.legacy.language_data import old_default

TARGET = "CALC_MODES"
MATRIX_RENAMES = {"MATR_A": "MATR_RIGI", "MATR_B": "MATR_MASS", "MATR_C": "MATR_AMOR"}
TOP_RENAMES = {**MATRIX_RENAMES, "STOP_FREQ_VIDE": "STOP_BANDE_VIDE"}
# MODE_ITER_SIMULT top-level keywords that belong to SOLVEUR_MODAL
SIMULT_SOLVER_TOP = (
    "METHODE", "PREC_ORTHO", "NMAX_ITER_ORTHO", "PREC_LANCZOS", "NMAX_ITER_QR",
    "PREC_BATHE", "NMAX_ITER_BATHE", "PREC_JACOBI", "NMAX_ITER_JACOBI",
    "PREC_SOREN", "NMAX_ITER_SOREN", "PARA_ORTHO_SOREN", "TYPE_QZ",
)  # fmt: skip
# CALC_FREQ (or CALC_CHAR_CRIT) keywords that belong to SOLVEUR_MODAL
SIMULT_SOLVER_FREQ = ("APPROCHE", "DIM_SOUS_ESPACE", "COEF_DIM_ESPACE")
INV_SOLVER_FREQ = ("NMAX_ITER_SEPARE", "PREC_SEPARE", "NMAX_ITER_AJUSTE", "PREC_AJUSTE")
# MODE_ITER_INV/CALC_MODE -> SOLVEUR_MODAL
INV_CALC_MODE = {"OPTION": "OPTION_INV", "PREC": "PREC_INV", "NMAX_ITER": "NMAX_ITER_INV"}
# buckling windows written as CALC_FREQ in the oldest decks
BUCKLING_RENAMES = {"NMAX_FREQ": "NMAX_CHAR_CRIT", "SEUIL_FREQ": "SEUIL_CHAR_CRIT"}
DROPPED = ("NPREC_SOLVEUR",)


def translate_mode_iter_simult(kwargs: dict, env: Env) -> Translation:
    return _translate(kwargs, env, "MODE_ITER_SIMULT")


def translate_mode_iter_inv(kwargs: dict, env: Env) -> Translation:
    return _translate(kwargs, env, "MODE_ITER_INV")


def _window_name(kw: dict) -> str:
    buckling = lit(kw.get("TYPE_RESU")) == "MODE_FLAMB"
    return "CALC_CHAR_CRIT" if buckling else "CALC_FREQ"


def _translate(kwargs: dict, env: Env, command: str) -> Translation:
    env.note(command, "CALC_MODES")
    kw = dict(kwargs)
    window_name = _window_name(kw)
    solver = factor({})
    option = _window_option(kw, window_name, solver, env, command)
    out: dict = {}
    for key, value in kw.items():
        if key in TOP_RENAMES:
            out[TOP_RENAMES[key]] = value
            env.note(f"{command}/{key}", f"CALC_MODES/{TOP_RENAMES[key]}", None, key)
        elif key in SIMULT_SOLVER_TOP:
            solver[key] = value
            env.note(f"{command}/{key}", f"SOLVEUR_MODAL=_F({key}=...)", None, key)
        elif key == "OPTION":  # MODE_ITER_SIMULT: rigid body modes or not
            if lit(value) == "MODE_RIGIDE":
                solver["MODE_RIGIDE"] = "OUI"
            env.note(f"{command}/OPTION={lit(value)!r}", "SOLVEUR_MODAL=_F(MODE_RIGIDE=...)")
        elif key in ("CALC_FREQ", "CALC_CHAR_CRIT"):
            out["OPTION"] = option
            if kw[key]:
                out[window_name] = kw[key]
        elif key == "CALC_MODE":
            _inverse_controls(value, solver, env, command)
        elif key == "SENSIBILITE":
            env.unsupported("SENSIBILITE (sensitivity) was removed from code_aster", None, key)
        else:
            out[key] = value
    if "OPTION" not in out and option is not None:
        out = {"OPTION": option, **out}
    if solver:
        out["SOLVEUR_MODAL"] = solver
    return Translation(TARGET, out, env.notes)


def _window_option(kw: dict, window_name: str, solver: dict, env: Env, command: str):
    """Move CALC_FREQ/OPTION to OPTION and solver keywords to SOLVEUR_MODAL."""
    source = "CALC_CHAR_CRIT" if "CALC_CHAR_CRIT" in kw else "CALC_FREQ"
    occurrence = single(kw.get(source)) if source in kw else None
    default = old_default(command, "CALC_FREQ", "OPTION")  # what code_aster 11 gave
    if occurrence is None:
        if command == "MODE_ITER_INV":
            env.note(f"{command} without OPTION (legacy default {default})", f"OPTION={default!r}")
            return default
        return None
    window = factor({}, occurrence)
    option = default
    for key, value in occurrence.items():
        if key == "OPTION":
            option = value
            env.note(f"{source}/OPTION", "CALC_MODES/OPTION", occurrence, key)
        elif key in SIMULT_SOLVER_FREQ + INV_SOLVER_FREQ:
            solver[key] = value
            env.note(f"{source}/{key}", f"SOLVEUR_MODAL/{key}", occurrence, key)
        elif key in DROPPED:
            env.note(f"{source}/{key}", "(removed: see SOLVEUR/NPREC)", occurrence, key)
        elif window_name == "CALC_CHAR_CRIT" and key in BUCKLING_RENAMES:
            window[BUCKLING_RENAMES[key]] = value
            env.note(f"{source}/{key}", f"CALC_CHAR_CRIT/{BUCKLING_RENAMES[key]}", occurrence, key)
        else:
            window[key] = value
    if "OPTION" not in occurrence and command == "MODE_ITER_INV":
        env.note(f"{command} without OPTION (legacy default {default})", f"OPTION={default!r}")
    if source != window_name:
        env.note(f"{command}/{source}", f"CALC_MODES/{window_name}", None, source)
    kw[source] = window
    if source != window_name:
        kw[window_name] = kw.pop(source)
    return option


def _inverse_controls(value, solver: dict, env: Env, command: str) -> None:
    occurrence = single(value)
    if occurrence is None:
        return
    for key, item in occurrence.items():
        new = INV_CALC_MODE.get(key)
        if new is None:
            env.unsupported(f"CALC_MODE/{key} has no modern place", occurrence, key)
        solver[new] = item
        env.note(f"{command}/CALC_MODE/{key}", f"SOLVEUR_MODAL/{new}", occurrence, key)
