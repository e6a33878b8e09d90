"""The layouts of what the compiled kernels exchange, named in one place.

The model, the state, the archive, the energy balance and the implicit
treatment are tuples of arrays (numba compiles a loop once per tuple
type); their parts are named here so that no kernel addresses them by
number. numba types a namedtuple defined at module level like a tuple,
with attribute access compiled to the same load: the machine code and the
results are those of the positional tuples, and the cache keeps working
(the class is pickled by its module and name).

The model and a scheme's memory vary in length (a 4th bundle for the
loops in local frames; the extra arrays of the variable-speed and
implicit loops), so they stay plain tuples indexed by the constants below.
This module imports no numba.
"""

from __future__ import annotations

from collections import namedtuple

# the model: (linear, shocks, loads) and, for the loops that take the shocks
# in their local frames, a 4th bundle (integrate.local_frame_bundle)
LINEAR, SHOCKS, LOADS, LOCAL = range(4)
# a scheme's memory: its rows of length n, its scalars, its coefficient
# table, then what the loop adds (the rotation's bundle and the scheme's
# code, or the implicit treatment)
ROWS, SCALARS, TABLE, EXTRA = range(4)
ROTATION_CODE = 4  # the scheme's dispatch code, after the rotation bundle

# model.LinearSystem.bundle(): M⁻¹, K, C and a one-element diagonal flag
Linear = namedtuple("Linear", "minv stiffness damping diagonal")

# model.ShockSet.bundle(): per shock, its flags and parameters (contact.F_*,
# contact.P_*), local frame, mode shapes at its nodes, polar obstacle, and
# the rows of the relations of laws/ (packed parameters, shapes, scratch)
Shocks = namedtuple("Shocks", "flags params rots phis polars laws rphis law_scratch")

# excitation.Excitation.bundle(): the load rows (vectors, tabulated multipliers
# and their layout), the support motions (drive_*), the sampling windows
# still to come (pending), the interval searched last (cursors), and the
# formula programs run in the kernel (formula.py)
Loads = namedtuple(
    "Loads",
    "vectors abscissas ordinates layout drive_shapes drive_abscissas drive_ordinates "
    "drive_layout pending cursors drive_pending drive_cursors codes constants stack",
)

# the state a step advances in place: q, v, a, the force f, the shocks'
# internal variables and their copy before a trial, a (5, 3) scratch
State = namedtuple("State", "q v a f vint vint_save work")

# the archive buffers: instants, step numbers, q, v, a, internal variables,
# kernel.INFO_* per row
Archive = namedtuple("Archive", "times order depl vite acce vint info")

# the energy balance (energy.new_energy): accumulators, matrices, vector
# scratch, a copy of the internal variables, scratch, the archived rows and
# each shock's quantities at the previous and the current state
Balance = namedtuple("Balance", "acc matrices vectors vint_copy work rows local")

# the implicit treatment of shocks (implicit_shocks.prepare)
Treatment = namedtuple(
    "Treatment",
    "stiffness0 damping0 diagonal0 active trial ints kinematics gradient work backup "
    "keep vint_keep active_at_start planned",
)
