"""RUNGE_KUTTA_32 (code_aster 17's default for a GENE transient): the
Bogacki-Shampine 3(2) pair driving the Runge-Kutta kernel."""

from asterlite.dynamics.scheme_runge_kutta import BOGACKI_SHAMPINE_32, prepare_with, step

TABLEAU = BOGACKI_SHAMPINE_32


def prepare(system, dt, options):
    return prepare_with(TABLEAU, system, dt, options)


__all__ = ["TABLEAU", "prepare", "step"]
