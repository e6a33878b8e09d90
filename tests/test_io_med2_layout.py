"""MED 2.x files (code_aster 10's): the mesh's one state is stored in the mesh
group itself (ENS_MAA/<mesh>/NOE, MAI, FAS) instead of a time-step group;
the layout check takes both."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.test_io_med_mesh import write_mixed_mesh

DYNA = Path(__file__).resolve().parent.parent.parent / "shared" / "aster-corpus-dyna"


def _as_med2(path: Path) -> None:
    """Move the state of a MED 4 mesh into the mesh group, as MED 2.x lays it out."""
    import h5py

    with h5py.File(path, "r+") as f:
        mesh = f["ENS_MAA/mixed"]
        (step,) = [k for k in mesh.keys() if isinstance(mesh[k], h5py.Group)]
        for part in list(mesh[step].keys()):
            mesh.move(f"{step}/{part}", part)
        del mesh[step]
        if "FAS/mixed" in f:
            f.move("FAS/mixed", "ENS_MAA/mixed/FAS")
        f["INFOS_GENERALES"].attrs["MAJ"] = np.int64(2)


def test_validation_accepts_the_med2_layout(tmp_path):
    from asterlite.io.med_mesh import MedMeshError, validate_med

    path = tmp_path / "m.med"
    write_mixed_mesh(path, names=True)
    _as_med2(path)
    validate_med(path)  # NOE/COO found in the mesh group
    import h5py

    with h5py.File(path, "r+") as f:
        del f["ENS_MAA/mixed/NOE/COO"]
    with pytest.raises(MedMeshError, match="no node coordinates"):
        validate_med(path)


def test_a_code_aster_10_mesh_reads():
    path = DYNA / "sdlv131b" / "sdlv131a.mmed"
    if not path.is_file():
        pytest.skip("../shared/aster-corpus-dyna is not available")
    from asterlite.io.med_mesh import read_med_mesh

    mesh = read_med_mesh(path)
    assert mesh.n_nodes == 1029
    assert {"A", "AB", "TOUT_ELT"} <= set(mesh.node_groups) | set(mesh.cell_groups)
