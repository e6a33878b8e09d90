"""IMPR_RESU to MED: megabytes of field data written per second, before and after.

Two shapes of result, written with ``asterlite.io.med_writer.write_med``
(what IMPR_RESU(FORMAT='MED') calls) as MED 4.0:

- tube: the tube benchmark's archive, a 41-node beam with 6 components
  (DX..DRZ) at 20 000 instants: 39 MB of field data in 2 kB steps;
- block: a 20 000-node mesh with 6 components at 100 instants: 96 MB in
  1 MB steps.

"before" is ``med_writer.py`` of the commit given by ``--before`` (loaded
from git into a scratch module), "after" the working tree's. The two files
are compared object by object (groups, attributes, datasets and their
values; the mesh's creation-date attribute aside) to show the content is
unchanged. "floor" is the cost of the HDF5 objects MED needs per time step
alone (3 groups, 10 attributes, 1 dataset), created with h5py's low-level
API in a fresh file: no MED writer can go below it on this machine.
Timings are CPU seconds of the process (steadier than wall time on a shared
machine; the writes go to the page cache either way), best of 3.

    python benchmarks/med_output.py [--before COMMIT] [--steps N]
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from asterlite.concepts.mesh import Mesh
from asterlite.io import med_writer

ROOT = Path(__file__).resolve().parents[1]
BASELINE_COMMIT = "41d4f8f"
COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")


def load_writer(commit: str):
    text = subprocess.run(
        ["git", "show", f"{commit}:asterlite/io/med_writer.py"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    path = Path(tempfile.mkdtemp(prefix="asterlite-before-")) / "med_writer_before.py"
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location("med_writer_before", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def line_mesh(n_nodes: int) -> Mesh:
    """A straight line of SEG2 cells, a node group at one end, one cell group."""
    coords = np.zeros((n_nodes, 3))
    coords[:, 0] = np.linspace(0.0, 2.0, n_nodes)
    mesh = Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(n_nodes)],
        cell_names=[f"M{i + 1}" for i in range(n_nodes - 1)],
        cell_types=["SEG2"] * (n_nodes - 1),
        cell_nodes=[(i, i + 1) for i in range(n_nodes - 1)],
        node_groups={"A": np.array([0]), "B": np.array([n_nodes - 1])},
        cell_groups={"TUBE": np.arange(n_nodes - 1)},
    )
    mesh.name = "MAIL"
    return mesh


def series(n_nodes: int, n_steps: int) -> med_writer.NodalSeries:
    values = np.random.default_rng(0).standard_normal((n_steps, n_nodes, len(COMPONENTS)))
    times = np.arange(n_steps) * 1.0e-4
    return med_writer.NodalSeries("TRAN____DEPL", COMPONENTS, values, times, np.arange(n_steps))


def seconds(writer, path: Path, mesh: Mesh, field, repeats: int = 3) -> float:
    best = math.inf
    for _ in range(repeats):
        path.unlink(missing_ok=True)
        start = time.process_time()
        writer.write_med(path, mesh, "MAIL", [field])
        best = min(best, time.process_time() - start)
    return best


def content(path: Path) -> dict:
    """Every group, attribute and dataset of an HDF5 file, comparable."""
    import h5py

    found = {}

    def visit(name, item):
        attributes = {
            key: (value.tobytes() if hasattr(value, "tobytes") else value)
            for key, value in item.attrs.items()
            if key != "UNV"  # the mesh's creation date
        }
        data = None
        if isinstance(item, h5py.Dataset):
            data = (str(item.dtype), item.shape, item[()].tobytes())
        found[name] = (attributes, data)

    with h5py.File(path, "r") as handle:
        handle.visititems(visit)
    return found


def floor_seconds(path: Path, n_steps: int, values_per_step: int) -> float:
    """The HDF5 objects of ``n_steps`` MED time steps, nothing else."""
    import h5py

    path.unlink(missing_ok=True)
    data = np.zeros(values_per_step)
    scalar = h5py.h5s.create(h5py.h5s.SCALAR)
    start = time.process_time()
    with h5py.File(path, "w", libver="earliest") as handle:
        field = handle.create_group("CHA/TRAN____DEPL").id
        for step in range(n_steps):
            group = h5py.h5g.create(field, f"{step:020d}{-1:020d}".encode())
            entity = h5py.h5g.create(group, b"NOE")
            profile = h5py.h5g.create(entity, b"MED_NO_PROFILE_INTERNAL")
            for owner, names in ((group, 5), (entity, 2), (profile, 3)):
                for k in range(names):
                    attribute = h5py.h5a.create(owner, b"A%d" % k, h5py.h5t.STD_I64LE, scalar)
                    attribute.write(np.array(step, dtype=np.int64))
            space = h5py.h5s.create_simple((values_per_step,))
            dataset = h5py.h5d.create(profile, b"CO", h5py.h5t.IEEE_F64LE, space)
            dataset.write(h5py.h5s.ALL, h5py.h5s.ALL, data)
    return time.process_time() - start


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", default=BASELINE_COMMIT)
    parser.add_argument("--steps", type=int, default=20_000, help="instants of the tube case")
    options = parser.parse_args(argv)
    before = load_writer(options.before)
    folder = Path(tempfile.mkdtemp(prefix="asterlite-med-"))
    cases = [("tube", 41, options.steps), ("block", 20_000, 100)]
    print(f"{'case':6} {'MB':>6} {'before s':>9} {'after s':>8} {'before MB/s':>12} "
          f"{'after MB/s':>11} {'floor MB/s':>11}  same content")  # fmt: skip
    for label, n_nodes, n_steps in cases:
        mesh, field = line_mesh(n_nodes), series(n_nodes, n_steps)
        megabytes = field.values.nbytes / 1e6
        old = seconds(before, folder / f"{label}-before.med", mesh, field)
        new = seconds(med_writer, folder / f"{label}-after.med", mesh, field)
        floor = floor_seconds(folder / "floor.h5", n_steps, n_nodes * len(COMPONENTS))
        same = content(folder / f"{label}-before.med") == content(folder / f"{label}-after.med")
        print(
            f"{label:6} {megabytes:6.1f} {old:9.2f} {new:8.2f} {megabytes / old:12.1f} "
            f"{megabytes / new:11.1f} {megabytes / floor:11.1f}  {same}"
        )


if __name__ == "__main__":
    main()
