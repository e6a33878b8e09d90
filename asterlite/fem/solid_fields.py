"""Stresses, strains and energies of 3D and plane solid elements (CALC_CHAMP).

At the Gauss points of the ``RIGI`` family (code_aster's ELGA location):

- ``EPSI_ELGA``: the linear strain tensor ``EPXX EPYY EPZZ EPXY (EPXZ EPYZ)``
  (tensor shear components, not engineering ones); ``EPZZ`` is 0 in plane
  strain, ``u_r / r`` in axisymmetry and ``-nu/(1-nu) (EPXX + EPYY)`` in plane
  stress;
- ``SIEF_ELGA``: Hooke's law, isotropic or orthotropic (ELAS_ORTH in the
  frame of AFFE_CARA_ELEM MASSIF, :mod:`asterlite.fem.orthotropic`),
  ``SIXX SIYY SIZZ SIXY (SIXZ SIYZ)`` (``SIZZ = 0`` in plane stress, where
  an orthotropic ``EPZZ`` is the one that makes it so);
- ``ENEL_ELGA``: the elastic energy density ``sigma : eps / 2`` (``TOTALE``).

ELNO fields (``SIGM_ELNO``, ``SIEF_ELNO``, ``EPSI_ELNO``, ``ENEL_ELNO``) are
their ELGA fields taken to the nodes as code_aster does: a least-squares fit
of the Gauss values by the element's linear (vertex) shape functions, the
other nodes getting the linear element's values at their reference points
(means of edge or face vertices); a one-point family gives its value to
every node.

Per element (``TOTALE``): ``EPOT_ELEM`` is the integral of the energy density
on the RIGI family (``u_e^T K_e u_e / 2``), ``ECIN_ELEM`` is
``v_e^T M_e v_e / 2`` with the consistent mass (``v`` the VITE of a
transient result, ``omega^2`` times the mode shape's energy for a mode).

Values are (n_orders, n_cells, n_points, n_components), padded with NaN
where a cell type has fewer points than another of the same field.
"""

from __future__ import annotations

from functools import cache

import numpy as np

from asterlite.concepts.assembly import ElementField
from asterlite.fem.element_errors import ElementError
from asterlite.fem.orthotropic import global_hooke, orthotropic_cells, plane_hooke
from asterlite.fem.plane_elements import PLANE_MODELISATIONS, surface_cells
from asterlite.fem.solid_elements import jacobian_determinants, jacobians
from asterlite.fem.solid_reference import (
    REFERENCE_ELEMENTS,
    VOLUME_CELLS,
    gauss_family,
    tabulated,
)

#: the linear element whose functions extrapolate Gauss values (code_aster's inmat6)
_VERTEX_ELEMENT = {
    "HE8": "HE8",
    "H20": "HE8",
    "H27": "HE8",
    "PE6": "PE6",
    "P15": "PE6",
    "TE4": "TE4",
    "T10": "TE4",
    "PY5": "PY5",
    "P13": "PY5",
    "TR3": "TR3",
    "TR6": "TR3",
    "QU4": "QU4",
    "QU8": "QU4",
    "QU9": "QU4",
}

STRESS_3D = ("SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ")
STRAIN_3D = ("EPXX", "EPYY", "EPZZ", "EPXY", "EPXZ", "EPYZ")
STRESS_2D = STRESS_3D[:4]
STRAIN_2D = STRAIN_3D[:4]
#: the tensor entries (i, j) of each component, in order
_ENTRIES = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))

ELGA_FIELDS = ("SIEF_ELGA", "EPSI_ELGA", "ENEL_ELGA")
ELNO_FIELDS = ("SIGM_ELNO", "SIEF_ELNO", "EPSI_ELNO", "ENEL_ELNO")
ELEM_FIELDS = ("EPOT_ELEM", "ECIN_ELEM")
NOEU_FIELDS = ("SIGM_NOEU", "SIEF_NOEU", "EPSI_NOEU")
SOLID_FIELDS = ELGA_FIELDS + ELNO_FIELDS + ELEM_FIELDS + NOEU_FIELDS
#: the ELGA field each ELNO field is taken from
_ELNO_SOURCE = {
    "SIGM_ELNO": "SIEF_ELGA",
    "SIEF_ELNO": "SIEF_ELGA",
    "EPSI_ELNO": "EPSI_ELGA",
    "ENEL_ELNO": "ENEL_ELGA",
}


@cache
def gauss_to_nodes(reference: str, family: str) -> np.ndarray:
    """(n_nodes, n_points) matrix taking Gauss values to the element's nodes."""
    ref = REFERENCE_ELEMENTS[reference]
    points = tabulated(reference, family)[2].size
    if points == 1:
        return np.ones((ref.n_nodes, 1))
    linear = REFERENCE_ELEMENTS[_VERTEX_ELEMENT[reference]]
    at_points = linear.values(gauss_family(reference, family)[0]).real  # (q, nnos)
    fit = np.linalg.solve(at_points.T @ at_points, at_points.T)  # (nnos, q)
    at_nodes = linear.values(ref.nodes).real  # (nno, nnos)
    return at_nodes @ fit


def _kind_of(model, cell: int):
    mesh = model.mesh
    modelisation = model.cell_modelisation.get(int(cell))
    kind = mesh.cell_types[int(cell)]
    if modelisation == "3D" and kind in VOLUME_CELLS:
        return modelisation, kind, VOLUME_CELLS[kind]
    if modelisation in PLANE_MODELISATIONS and kind in surface_cells(modelisation):
        return modelisation, kind, surface_cells(modelisation)[kind]
    return None


def solid_cells_of(model, cells) -> np.ndarray:
    """The cells among ``cells`` that are 3D volumes or plane surfaces."""
    return np.array([int(c) for c in cells if _kind_of(model, c) is not None], dtype=int)


def _gather(numbering, conn: np.ndarray, dim: int, values: np.ndarray) -> np.ndarray:
    """(n_orders, e, n, dim) element displacements from nodal values."""
    comps = ("DX", "DY", "DZ")[:dim]
    nodes = np.repeat(conn.ravel(), dim)
    rows = numbering.dof_indices(nodes, list(comps) * conn.size)
    out = np.zeros((values.shape[0], rows.size), dtype=values.dtype)
    present = rows >= 0
    out[:, present] = values[:, rows[present]]
    return out.reshape(values.shape[0], conn.shape[0], conn.shape[1], dim)


def _material(materials, cells, mesh, modelisation, characteristics):
    """E, NU, RHO of the cells and, when some are orthotropic, the (e, 6, 6)
    global Hooke matrices of all (else None)."""
    if materials is None:
        raise ElementError("solid element fields need a material field (CHAM_MATER)")
    missing = [int(c) for c in cells if materials.material_of(c) is None]
    if missing:
        names = ", ".join(mesh.cell_names[c] for c in missing[:5])
        raise ElementError(f"no material is assigned to the cells {names}")
    young = materials.values(cells, "E", np.nan)
    poisson = materials.values(cells, "NU", np.nan)
    ortho = orthotropic_cells(materials, cells)
    if np.any(np.isnan(young[~ortho])) or np.any(np.isnan(poisson[~ortho])):
        raise ElementError("solid element fields need E and NU in the material (ELAS)")
    hooke = None
    if np.any(ortho):
        hooke = global_hooke(materials, characteristics, cells, mesh, modelisation, young, poisson)
    return young, poisson, materials.values(cells, "RHO", 0.0), hooke


def _voigt(eps):
    """(..., 6) Voigt strains (engineering shears) of (..., 3, 3) tensors."""
    return np.stack([eps[..., i, j] * (1.0 if i == j else 2.0) for i, j in _ENTRIES], axis=-1)


def _tensor(voigt):
    """(..., 3, 3) symmetric tensors of (..., 6) Voigt stresses."""
    out = np.zeros(voigt.shape[:-1] + (3, 3), dtype=voigt.dtype)
    for k, (i, j) in enumerate(_ENTRIES):
        out[..., i, j] = out[..., j, i] = voigt[..., k]
    return out


def _strains(modelisation, spec, coords, u, poisson, hooke=None):
    """(o, e, q, 3, 3) strain tensors and (e, q) weights w |J| (r)."""
    values, grads, weights = tabulated(spec.reference, spec.rigi)
    g, det = jacobians(coords, grads)
    dim = coords.shape[2]
    # displacement gradient H[o, e, q, i, j] = sum_a u[o, e, a, i] dN_a/dx_j
    h = np.einsum("oeai,eqaj->oeqij", u, g)
    eps = np.zeros(h.shape[:3] + (3, 3), dtype=h.dtype)
    eps[..., :dim, :dim] = 0.5 * (h + np.swapaxes(h, -1, -2))
    scale = det * weights[None, :]
    if modelisation == "AXIS":
        radius = np.einsum("qa,ea->eq", values, coords[..., 0])
        eps[..., 2, 2] = np.einsum("qa,oea->oeq", values, u[..., 0]) / radius[None]
        scale = scale * radius
    elif modelisation == "C_PLAN" and hooke is not None:
        # the out-of-plane strain that leaves sigma_zz = 0 (eps_zz is 0 in eps here)
        coupling = hooke[:, 2, [0, 1, 3]] / hooke[:, 2, 2, None]
        in_plane = np.stack([eps[..., 0, 0], eps[..., 1, 1], 2.0 * eps[..., 0, 1]], axis=-1)
        eps[..., 2, 2] = -np.einsum("ek,oeqk->oeq", coupling, in_plane)
    elif modelisation == "C_PLAN":
        ratio = (poisson / (1.0 - poisson))[None, :, None]
        eps[..., 2, 2] = -ratio * (eps[..., 0, 0] + eps[..., 1, 1])
    return eps, scale


def _stresses(modelisation, eps, young, poisson, hooke=None):
    if hooke is not None:
        if modelisation in PLANE_MODELISATIONS:
            # plane strain and axisymmetry keep the 3D law on (xx, yy, zz, xy);
            # plane stress condenses sigma_zz out
            d = np.zeros_like(hooke)
            d[:, :4, :4] = plane_hooke(hooke, modelisation)
        else:
            d = hooke
        sig = np.einsum("eij,oeqj->oeqi", d, _voigt(eps))
        return _tensor(sig)
    lam = (young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson)))[None, :, None]
    mu = (young / (2.0 * (1.0 + poisson)))[None, :, None]
    if modelisation == "C_PLAN":
        # plane stress: sigma_zz = 0, in-plane law with lambda* = 2 lam mu / (lam + 2 mu)
        lam = 2.0 * lam * mu / (lam + 2.0 * mu)
        trace = eps[..., 0, 0] + eps[..., 1, 1]
    else:
        trace = np.trace(eps, axis1=-2, axis2=-1)
    sig = 2.0 * mu[..., None, None] * eps
    sig += (lam * trace)[..., None, None] * np.eye(3)
    if modelisation == "C_PLAN":
        sig[..., 2, 2] = 0.0
    return sig


def _components(tensor, n_components):
    return np.stack([tensor[..., i, j] for i, j in _ENTRIES[:n_components]], axis=-1)


#: bytes of one (orders, cells, points, 3, 3) work tensor: the orders of a
#: result computed at once are as many as fit (at least one); the strains,
#: stresses and their temporaries are a few such tensors
WORK_BYTES = 4 * 1024**2


def orders_per_chunk(n_cells: int, n_points: int, itemsize: int) -> int:
    """Orders whose tensors at ``n_points`` points of ``n_cells`` cells fit :data:`WORK_BYTES`."""
    return max(1, WORK_BYTES // max(1, n_cells * n_points * 9 * itemsize))


def solid_element_fields(
    model,
    materials,
    numbering,
    cells,
    values,
    names,
    velocities=None,
    omega2=None,
    characteristics=None,
) -> dict[str, ElementField]:
    """The requested fields (names among SOLID_FIELDS but the _NOEU ones) on
    the solid cells ``cells`` for nodal values (n_orders, n_dofs), real or
    complex. ECIN_ELEM needs ``velocities`` (n_orders, n_dofs) or, for modes,
    ``omega2`` (n_orders,) with the mode shapes as ``values``."""
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    dims = {3 if model.cell_modelisation[int(c)] == "3D" else 2 for c in cells}
    if len(dims) != 1:
        raise ElementError("CALC_CHAMP on 3D and plane cells at once: give GROUP_MA")
    dim = dims.pop()
    n_cmp = 6 if dim == 3 else 4
    stress_names, strain_names = (STRESS_3D, STRAIN_3D) if dim == 3 else (STRESS_2D, STRAIN_2D)
    values = np.asarray(values)
    if np.iscomplexobj(values) or np.iscomplexobj(velocities):
        return _complex_fields(
            model, materials, numbering, cells, values, names, velocities, omega2, characteristics
        )
    n_orders = values.shape[0]
    groups: dict[tuple, list[int]] = {}
    for k, cell in enumerate(cells):
        modelisation, kind, _ = _kind_of(model, cell)
        groups.setdefault((modelisation, kind), []).append(k)
    specs = {key: _kind_of(model, cells[rows[0]])[2] for key, rows in groups.items()}
    max_points = max(tabulated(spec.reference, spec.rigi)[2].size for spec in specs.values())
    max_nodes = max(len(mesh.cell_nodes[c]) for c in cells)
    dtype = np.result_type(values, float)
    # only the Gauss-point fields asked for or read by an asked ELNO field are
    # kept: each is as large as the result's displacements times the points
    wanted = set(names) | {_ELNO_SOURCE[name] for name in names if name in _ELNO_SOURCE}
    widths = {"SIEF_ELGA": n_cmp, "EPSI_ELGA": n_cmp, "ENEL_ELGA": 1}
    gauss = {
        name: np.full((n_orders, len(cells), max_points, width), np.nan, dtype)
        for name, width in widths.items()
        if name in wanted
    }
    nodal = {name: None for name in ELNO_FIELDS}
    elem = {name: np.full((n_orders, len(cells), 1, 1), np.nan, dtype) for name in ELEM_FIELDS}
    for (modelisation, kind), rows in groups.items():
        rows = np.asarray(rows, dtype=int)
        members = cells[rows]
        spec = specs[modelisation, kind]
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        coords = mesh.coords[conn][..., :dim]
        young, poisson, density, hooke = _material(
            materials, members, mesh, modelisation, characteristics
        )
        to_nodes = gauss_to_nodes(spec.reference, spec.rigi)
        # a few orders at a time: the (orders, cells, points, 3, 3) tensors of
        # a long transient would otherwise be held all at once, several times
        points = tabulated(spec.reference, spec.rigi)[2].size
        chunk = orders_per_chunk(rows.size, points, np.dtype(dtype).itemsize)
        for start in range(0, n_orders, chunk):
            o = slice(start, min(start + chunk, n_orders))
            u = _gather(numbering, conn, dim, values[o])
            eps, scale = _strains(modelisation, spec, coords, u, poisson, hooke)
            sig = _stresses(modelisation, eps, young, poisson, hooke)
            q = scale.shape[1]
            density_of_energy = 0.5 * np.einsum("oeqij,oeqij->oeq", sig, eps)
            if "SIEF_ELGA" in gauss:
                gauss["SIEF_ELGA"][o, rows, :q] = _components(sig, n_cmp)
            if "EPSI_ELGA" in gauss:
                gauss["EPSI_ELGA"][o, rows, :q] = _components(eps, n_cmp)
            if "ENEL_ELGA" in gauss:
                gauss["ENEL_ELGA"][o, rows, :q] = density_of_energy[..., None]
            elem["EPOT_ELEM"][o, rows, 0, 0] = np.einsum("oeq,eq->oe", density_of_energy, scale)
            del u, eps, sig, density_of_energy
            if "ECIN_ELEM" in names:
                motion = (
                    numbering,
                    conn,
                    dim,
                    values[o],
                    None if velocities is None else np.asarray(velocities)[o],
                    None if omega2 is None else np.asarray(omega2)[o],
                )
                elem["ECIN_ELEM"][o, rows, 0, 0] = _kinetic(
                    modelisation, spec, coords, density, *motion
                )
        for name, source in _ELNO_SOURCE.items():
            if name not in names:
                continue
            if nodal[name] is None:
                width = gauss[source].shape[-1]
                nodal[name] = np.full((n_orders, len(cells), max_nodes, width), np.nan, dtype)
            n = to_nodes.shape[0]
            q = to_nodes.shape[1]
            taken = np.einsum("nq,oeqc->oenc", to_nodes, gauss[source][:, rows, :q])
            nodal[name][:, rows, :n] = taken
    components = {
        "SIEF_ELGA": stress_names,
        "EPSI_ELGA": strain_names,
        "ENEL_ELGA": ("TOTALE",),
        "SIGM_ELNO": stress_names,
        "SIEF_ELNO": stress_names,
        "EPSI_ELNO": strain_names,
        "ENEL_ELNO": ("TOTALE",),
        "EPOT_ELEM": ("TOTALE",),
        "ECIN_ELEM": ("TOTALE",),
    }
    out = {}
    for name in names:
        data = gauss.get(name)
        if data is None:
            data = nodal.get(name) if name in nodal else elem[name]
        out[name] = ElementField(name, cells, components[name], data)
    return out


def _complex_fields(
    model, materials, numbering, cells, values, names, velocities, omega2, characteristics
):
    """Fields of complex states (a harmonic result), as code_aster computes
    them: the stresses and strains of the real and imaginary parts make a
    complex field, the energies are the sum of the parts' energies."""
    parts = []
    for part in (np.real, np.imag):
        speeds = None if velocities is None else np.ascontiguousarray(part(velocities))
        parts.append(
            solid_element_fields(
                model,
                materials,
                numbering,
                cells,
                np.ascontiguousarray(part(values)),
                names,
                speeds,
                omega2,
                characteristics,
            )
        )
    out = {}
    for name, real in parts[0].items():
        imag = parts[1][name].values
        energy = name.startswith(("ENEL", "EPOT", "ECIN"))
        combined = real.values + imag if energy else real.values + 1j * imag
        out[name] = ElementField(name, real.cells, real.components, combined)
    return out


def _kinetic(modelisation, spec, coords, density, numbering, conn, dim, values, velocities, omega2):
    """(o, e) kinetic energies v^T M_e v / 2 with the consistent mass."""
    shape, grads, weights = tabulated(spec.reference, spec.mass)
    det = jacobian_determinants(coords, grads)
    scale = det * weights[None, :] * density[:, None]
    if modelisation == "AXIS":
        scale = scale * np.einsum("qa,ea->eq", shape, coords[..., 0])
    if velocities is not None:
        v = _gather(numbering, conn, dim, np.asarray(velocities))
        factor = 1.0
    elif omega2 is not None:
        v = _gather(numbering, conn, dim, values)
        factor = np.asarray(omega2, dtype=float)[:, None]
    else:
        raise ElementError("ECIN_ELEM needs the velocities (VITE) of the result")
    at_points = np.einsum("qa,oeai->oeqi", shape, v)
    return 0.5 * factor * np.einsum("eq,oeqi,oeqi->oe", scale, at_points, at_points)
