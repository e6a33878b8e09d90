"""Peak memory of a long tube run: 10^7 DIFF_CENTRE steps, PAS_ARCH=1000.

Run in a fresh process (tube_benchmark.py starts it that way) so that the
peak resident set size (resource.getrusage, ru_maxrss) is this run's own.
Prints one line of key=value pairs.

Run: python benchmarks/tube_memory.py [n_steps] [pas_arch] [formula|sampled|table]
(the force multiplier as a FORMULE, run by the kernel at each step; as a
function known only by ``evaluate``, sampled every half step one window at
a time; or as a DEFI_FONCTION of 64 points per period).

An archive past its memory budget (archive_store: 512 MB in a run without
a memory limit) is written out to unnamed files in the system's temporary
folder while the loop runs: ``python benchmarks/tube_memory.py 100000000 10``
(10^7 archived instants, 9.9 GB on disk) measures the peak of that case.
"""

from __future__ import annotations

import resource
import sys
import time

import tube_model as T


def peak_rss_mb() -> float:
    """Peak RSS (Linux: ru_maxrss in kB). Linux carries the parent's peak
    over fork + exec, so also see high_water_mark_mb()."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def high_water_mark_mb() -> float:
    """This process image's own peak RSS (VmHWM, reset at exec)."""
    for line in open("/proc/self/status"):
        if line.startswith("VmHWM:"):
            return float(line.split()[1]) / 1024.0
    return peak_rss_mb()


def main() -> None:
    n_steps = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000_000
    pas_arch = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
    multiplier = sys.argv[3] if len(sys.argv) > 3 else "formula"
    problem = T.tube_problem()
    dt = T.stable_step(problem)
    T.run_engine(problem, 100, dt, pas_arch)  # load the compiled kernels
    before = high_water_mark_mb()
    started = time.perf_counter()
    result = T.run_engine(problem, n_steps, dt, pas_arch, multiplier)
    wall = time.perf_counter() - started
    print(
        f"multiplier={multiplier} steps={result.info['steps']} archived={result.info['archived']} "
        f"rss_before_mb={before:.1f} peak_rss_mb={high_water_mark_mb():.1f} "
        f"ru_maxrss_mb={peak_rss_mb():.1f} "
        f"integration_s={result.info['integration_seconds']:.2f} wall_s={wall:.2f} "
        f"archive_gb={archive_bytes(result) / 1024**3:.2f} "
        f"archive_on_disk={result.info['archive_on_disk']}"
    )


def archive_bytes(result) -> int:
    parts = (result.times, result.order, result.depl, result.vite, result.acce, result.vint)
    return sum(part.nbytes for part in parts) + result.step_info.nbytes


if __name__ == "__main__":
    main()
