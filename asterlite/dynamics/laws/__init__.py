"""Localized nonlinearities of a modal transient other than DIS_CHOC.

One module per localized nonlinearity of DYNA_VIBRA (TRAN/GENE) other than the shock: a compiled
force law working on local scalars and flat float64 arrays (parameters,
internal variables in code_aster's archived layout), a frozen
``*Parameters`` record of the relation's data with named fields (the
command fills it from the deck) and a plain-Python ``prepare_*`` turning
the record into the parameter array. The time-loop kernel (``kernel``)
computes the local kinematics (frames, distances, relative velocities) and
projects the returned local forces on the modes; see each module's
docstring for what it needs.

``connections.RELATIONS`` is the table of the relations: each one's
module, its branch in the kernel and how its shock row is built
(``connections.register`` adds one).
"""

from __future__ import annotations

from asterlite.dynamics.laws.tabulated import LawError

__all__ = ["LawError"]
