"""Where numba's compile time goes (issue 30, goal 1): each warmup kernel
compiled in this process on an empty cache, with the CPU seconds of the
kernel, of LLVM (numba's ``numba:llvm_lock`` events: optimisation and
machine code) and of numba's own passes (``numba:run_pass``, exclusive of
the passes nested in them: type inference, inlining, lowering; the LLVM
time falls mostly inside ``native_lowering``),
and the top-level functions that were compiled.

The cache must be empty for the figures to mean anything, so this refuses
a NUMBA_CACHE_DIR that already holds files unless ``--reuse`` is given.
Kernels are compiled in the order given (a later kernel finds the shared
functions an earlier one compiled, as in ``asterlite warmup -j 1``).

    NUMBA_CACHE_DIR=/tmp/empty python benchmarks/compile_profile.py \
        "shared force functions" DIFF_CENTRE
    NUMBA_CACHE_DIR=/tmp/empty python benchmarks/compile_profile.py --all
"""

from __future__ import annotations

import argparse
import collections
import os
import sys
import time
from pathlib import Path

from numba.core import event

PASS, LLVM, COMPILE = "numba:run_pass", "numba:llvm_lock", "numba:compile"


class CompileTimes(event.Listener):
    """CPU seconds of numba's events, outermost ones only for LLVM and
    compiles, exclusive of nested passes for passes."""

    def __init__(self):
        self.stack = []
        self.passes = collections.Counter()
        self.compiles = collections.Counter()
        self.llvm = 0.0

    def on_start(self, ev):
        self.stack.append((ev.kind, time.process_time(), ev.data))

    def on_end(self, ev):
        kind, started, data = self.stack.pop()
        spent = time.process_time() - started
        outer = [k for k, _, _ in self.stack]
        if kind == PASS:
            name = data["name"].split(" [")[0]  # "native_lowering [fast_loop]"
            self.passes[name] += spent
            for k, _, d in reversed(self.stack):
                if k == PASS:  # the enclosing pass did not spend this itself
                    self.passes[d["name"].split(" [")[0]] -= spent
                    break
        elif kind == LLVM and LLVM not in outer:
            self.llvm += spent
        elif kind == COMPILE and COMPILE not in outer:
            self.compiles[getattr(data.get("dispatcher"), "__qualname__", "?")] += spent


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("kernels", nargs="*", help="warmup kernel names, in order")
    parser.add_argument("--all", action="store_true", help="every kernel, in the warmup's order")
    parser.add_argument("--reuse", action="store_true", help="accept a non-empty cache")
    args = parser.parse_args()
    cache = os.environ.get("NUMBA_CACHE_DIR")
    if not cache:
        sys.exit("compile_profile: set NUMBA_CACHE_DIR to an empty folder")
    if not args.reuse and Path(cache).exists() and any(Path(cache).rglob("*.nbi")):
        sys.exit(f"compile_profile: {cache} already holds kernels (--reuse to accept)")

    times = CompileTimes()
    for kind in (PASS, LLVM, COMPILE):
        event.register(kind, times)
    from asterlite.dynamics import warmup

    names = list(warmup.KERNELS) if args.all else args.kernels
    unknown = [name for name in names if name not in warmup.KERNELS]
    if unknown or not names:
        sys.exit(f"compile_profile: kernels are {', '.join(warmup.KERNELS)}; got {unknown}")
    load = os.getloadavg()[0]
    first = time.process_time()
    for name in names:
        started = time.process_time()
        warmed = warmup.warm_one(name)
        failed = f" FAILED {warmed.error}" if warmed.error else ""
        print(f"{name}: {time.process_time() - started:.1f} s CPU{failed}", flush=True)
    total = time.process_time() - first
    print(f"total {total:.1f} s CPU, load {load:.1f} -> {os.getloadavg()[0]:.1f}")
    print(f"  LLVM (llvm_lock): {times.llvm:.1f} s ({100 * times.llvm / total:.0f} %)")
    for name, spent in times.passes.most_common(6):
        print(f"  numba pass {name}: {spent:.1f} s")  # native_lowering holds most of LLVM
    print("  outermost compiles:")
    for name, spent in times.compiles.most_common(8):
        print(f"    {spent:6.1f} s  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
