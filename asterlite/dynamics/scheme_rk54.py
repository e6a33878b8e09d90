"""RUNGE_KUTTA_54: the Dormand-Prince 5(4) pair driving the Runge-Kutta kernel."""

from asterlite.dynamics.scheme_runge_kutta import DORMAND_PRINCE_54, prepare_with, step

TABLEAU = DORMAND_PRINCE_54


def prepare(system, dt, options):
    return prepare_with(TABLEAU, system, dt, options)


__all__ = ["TABLEAU", "prepare", "step"]
