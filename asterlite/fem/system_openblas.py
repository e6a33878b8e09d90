"""The kernels of the system OpenBLAS that MUMPS links, named from the CPU.

An OpenBLAS built for many CPUs (``DYNAMIC_ARCH``, as Debian's) picks its
kernels once, when it loads, from the CPU's model number. A model newer than
the library is taken for a generic core: Debian 12's OpenBLAS 0.3.21 runs an
Emerald Rapids Xeon (family 6, model 207) on its Prescott kernels, whose
DGEMM reached 8 GFlop/s there against 67 for the SkylakeX kernels the CPU
can run, and the 98 172-DOF bar's MUMPS factorisation took 9.5 s instead of
4.7. ``OPENBLAS_CORETYPE`` names the core instead. asterlite sets it from
the CPU's instruction sets while MUMPS (hence the system OpenBLAS) loads,
unless the user has set it, and removes it afterwards: numpy's own OpenBLAS
is loaded already and chooses for itself, as do the processes a run starts.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator

#: the variable a DYNAMIC_ARCH OpenBLAS reads when it loads
VARIABLE = "OPENBLAS_CORETYPE"

#: (instruction sets the kernels need, OpenBLAS's name of the core), best first
FEATURE_CORES = (
    (frozenset({"avx512f", "avx512dq", "avx512cd", "avx512bw", "avx512vl"}), "SkylakeX"),
    (frozenset({"avx2", "fma"}), "Haswell"),
)


def cpu_flags(path: str = "/proc/cpuinfo") -> frozenset[str]:
    """The instruction sets Linux reports for the first CPU (it lists only
    those the kernel has enabled); empty where there is no such file."""
    try:
        with open(path, encoding="ascii", errors="replace") as stream:
            for line in stream:
                name, _, value = line.partition(":")
                if name.strip() == "flags":
                    return frozenset(value.split())
    except OSError:
        pass
    return frozenset()


def core_for(flags: frozenset[str]) -> str | None:
    """The best OpenBLAS core these instruction sets run; None below AVX2,
    where OpenBLAS's own choice stands."""
    for needed, core in FEATURE_CORES:
        if needed <= flags:
            return core
    return None


@contextlib.contextmanager
def named_core() -> Iterator[str | None]:
    """``OPENBLAS_CORETYPE`` set to the CPU's core for the block (the core,
    or None when the user's value or OpenBLAS's own choice stands)."""
    core = None if VARIABLE in os.environ else core_for(cpu_flags())
    if core is None:
        yield None
        return
    os.environ[VARIABLE] = core
    try:
        yield core
    finally:
        os.environ.pop(VARIABLE, None)
