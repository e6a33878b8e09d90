"""AFFE_CHAR_CINE_F: imposed DOF values given by functions of X, Y, Z (at
the node) and INST (evaluated in time where a transient on the physical
basis reads it, as AFFE_CHAR_MECA_F DDL_IMPO of INST) or FREQ (evaluated at
each frequency of a harmonic response, DYNA_VIBRA TYPE_CALCUL='HARM')."""

from __future__ import annotations

from asterlite.commands import affe_char_cine, affe_char_meca_f


def run(ctx, kw):
    def evaluator(model, occ, in_time, in_frequency):
        return affe_char_meca_f._evaluator(ctx, model, occ, in_time, in_frequency)

    return affe_char_cine.impose(ctx, kw, evaluator=evaluator)
