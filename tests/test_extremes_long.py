"""A long run (issue 7): 10^7 steps of an impacting oscillator archived
every 1000 steps. Memory must follow the archive (10^4 instants), not the
step count, and the result must be finite and keep its energy.

The run happens in a subprocess (a fresh interpreter: its peak resident
size and tracemalloc's peak are its own), after a 10^4-step warm-up of the
same deck that loads the compiled kernels.
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import numpy as np

from tests.conftest import ROOT
from tests.test_extremes_decks import Chain, Shock, outputs_are_finite, write

STEPS = 10_000_000
PAS_ARCH = 1000
DT = 1.0e-5

CHILD = textwrap.dedent(
    """
    import json, resource, sys, time, tracemalloc
    from pathlib import Path
    from asterlite.runtime.runner import run_deck

    warm, long, out = (Path(p) for p in sys.argv[1:4])
    run_deck(warm, out / "warm", save_results=True)
    rss_warm = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    tracemalloc.start()
    start = time.perf_counter()
    report = run_deck(long, out / "long", save_results=True)
    seconds = time.perf_counter() - start
    traced_peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    rss_long = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    print(json.dumps({
        "status": report.status, "message": report.message, "seconds": seconds,
        "transients": report.transients, "traced_peak": traced_peak,
        "rss_warm_kb": rss_warm, "rss_long_kb": rss_long,
    }))
    """
)


def impacting(inst_fin: float) -> Chain:
    # ω = 100 rad/s, contact 1000 rad/s (VERI_PAS limit 3.1e-4 s): 10^7
    # steps are 100 s of motion, about 3200 impacts
    return Chain(
        vite={1: (0.0, 0.1, 0.0)},
        shocks=[Shock(1, 5.0e-4, 1.0e6)],
        pas=DT,
        inst_fin=inst_fin,
        pas_arch=PAS_ARCH,
    )


def test_ten_million_steps_with_sparse_archiving(tmp_path):
    warm = write(impacting(1.0e4 * DT), tmp_path / "warm")
    long = write(impacting(STEPS * DT), tmp_path / "long")
    child = subprocess.run(
        [sys.executable, "-c", CHILD, str(warm), str(long), str(tmp_path / "out")],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=ROOT,
    )
    assert child.returncode == 0, child.stderr[-3000:]
    figures = json.loads(child.stdout.strip().splitlines()[-1])
    print(figures)
    assert figures["status"] == "DONE", figures["message"]  # no TEST_*: DONE
    (transient,) = figures["transients"]
    assert transient["steps"] == STEPS
    # Everything Python allocates during the run (archive buffers included):
    # 10^4 archived instants of (3 + 20 shock values) doubles are 2 MB;
    # keeping every step would be 1.8 GB. 64 MB leaves room for the deck.
    assert figures["traced_peak"] <= 64 * 2**20, figures
    # and the process does not grow beyond the warm-up run by more than that
    assert figures["rss_long_kb"] - figures["rss_warm_kb"] <= 64 * 1024, figures

    out = tmp_path / "out" / "long"
    assert not outputs_are_finite(out)
    import h5py

    with h5py.File(out / "results.h5", "r") as f:
        group = f["TRAN"]
        times = group["times"][()]
        depl, vite, acce = group["depl"][()], group["vite"][()], group["acce"][()]
        mass = group["basis/generalized_mass"][()]
        stiffness = group["basis/generalized_stiffness"][()]
        fn = group["shocks/C1/FN"][()]
    assert len(times) == STEPS // PAS_ARCH + 1
    # every PAS_ARCH steps, the last one at INST_FIN: instants are sums of
    # 10^7 steps, off by about n·eps·t = 1e-7 s at the end (1e-5 of a period)
    assert np.allclose(np.diff(times), PAS_ARCH * DT, rtol=1.0e-5, atol=0.0)
    assert times[-1] == STEPS * DT
    # the energy at the archived instants (velocity synchronised to t_n,
    # contact spring F_N²/2K_N) over 3200 impacts: DIFF_CENTRE is
    # symplectic, its energy error stays O((ω_c dt)²) = 1e-4 (measured 3e-5)
    velocity = vite + 0.5 * DT * acce
    velocity[0] = vite[0]
    energy = 0.5 * (velocity**2 @ mass + depl**2 @ stiffness) + 0.5 * fn**2 / 1.0e6
    assert np.max(np.abs(energy - energy[0])) <= 1.0e-4 * energy[0]
    assert np.count_nonzero(fn) > 0
