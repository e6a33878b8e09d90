"""Element computer of the pipe elements ``TUYAU_3M`` (SEG3, SEG4) and
``TUYAU_6M`` (SEG3) for :func:`asterlite.fem.elements.element_blocks`, their
frames along the pipe lines and their internal forces (EFGE_ELNO).

Each cell needs a section (``AFFE_CARA_ELEM/POUTRE`` SECTION='CERCLE', R and
EP, with TUYAU_NSEC, TUYAU_NCOU, MODI_METRIQUE) and a material (E, NU, RHO,
AMOR_ALPHA, AMOR_BETA). A cell whose inner nodes leave the chord is an
elbow (:mod:`asterlite.fem.pipe_elbow`).

Frames (code_aster's aceatu / angcou): the pipe cells are chained into lines
(node 2 of a cell is node 1 of the next); on each line the generating line
starts from ORIENTATION GENE_TUYAU at the line's first or last node (else a
default vector normal to the first cell) and is carried from cell to cell,
made orthogonal to each cell's axis.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass

import numpy as np

from asterlite.concepts.assembly import ElementBlock, ElementField
from asterlite.fem import pipe
from asterlite.fem.beam_elements import _material_values
from asterlite.fem.element_errors import ElementError
from asterlite.fem.pipe_elbow import elbow_frames, elbow_frames_seg4

PIPE_MODELISATIONS = ("TUYAU_3M", "TUYAU_6M")
FOURIER_MODES = {"TUYAU_3M": 3, "TUYAU_6M": 6}
PIPE_COMPONENTS = {name: pipe.node_components(m) for name, m in FOURIER_MODES.items()}
#: The Fourier DOFs DDL_IMPO BLOCAGE='TUYAU_FOURIER' fixes (up to mode 6).
FOURIER_COMPONENTS = pipe.node_components(6)[6:]
EFGE_COMPONENTS = ("N", "VY", "VZ", "MT", "MFY", "MFZ")


@dataclass(frozen=True, eq=False)
class PipeCell:
    """A pipe cell's geometry (its length, or its :class:`pipe.Elbow`) and
    its nodes' global-to-local rotations (n_nodes, 3, 3)."""

    geometry: float | pipe.Elbow
    frames: np.ndarray


def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def pipe_lines(mesh, cells) -> list[list[int]]:
    """Pipe cells chained into lines, each in its node-1-to-node-2 order."""
    cells = [int(c) for c in cells]
    first = {}
    second = {}
    for c in cells:
        a, b = mesh.cell_nodes[c][0], mesh.cell_nodes[c][1]
        if a in first or b in second:
            raise pipe.PipeError(
                f"pipe cell {mesh.cell_names[c]}: a node starts or ends two pipe cells "
                "(code_aster needs lines whose cells follow node 1 to node 2)"
            )
        first[a], second[b] = c, c
    lines = []
    for c in cells:
        if mesh.cell_nodes[c][0] in second:
            continue  # not the start of a line
        line = [c]
        while mesh.cell_nodes[line[-1]][1] in first:
            line.append(first[mesh.cell_nodes[line[-1]][1]])
            if len(line) > len(cells):
                raise pipe.PipeError("a closed pipe line has no start")
        lines.append(line)
    if sum(len(line) for line in lines) != len(cells):
        raise pipe.PipeError("a closed pipe line has no start")
    return lines


def _straight(coords, tolerance: float, relative: bool) -> bool:
    """code_aster's elbow test: the sine of the angle between the chords
    node 1 -> middle and middle -> node 2."""
    middle = coords[2:].mean(axis=0)
    t1, t2 = middle - coords[0], coords[1] - middle
    n1, n2 = np.linalg.norm(t1), np.linalg.norm(t2)
    sine = np.linalg.norm(np.cross(t2 / n2, t1 / n1))
    if np.dot(t1, t2) <= 0.0:
        raise pipe.PipeError("its middle node is not between its end nodes")
    limit = tolerance if relative else tolerance / n1 / n2
    return sine <= limit


def pipe_frames(mesh, cells, generators=()) -> dict[int, PipeCell]:
    """{cell: PipeCell} of pipe cells, straight or elbows.

    ``generators``: (node, vector, PRECISION, CRITERE) of each ORIENTATION
    GENE_TUYAU; its node must start or end a pipe line."""
    frames: dict[int, np.ndarray] = {}
    lines = pipe_lines(mesh, cells)
    starts = {}
    for node, vector, precision, criterion in generators:
        found = False
        for k, line in enumerate(lines):
            for end, sense in (
                (mesh.cell_nodes[line[0]][0], 1),
                (mesh.cell_nodes[line[-1]][1], -1),
            ):
                if end == node:
                    if k in starts:
                        raise pipe.PipeError("two GENE_TUYAU are given on one pipe line")
                    starts[k] = (sense, _unit(vector), precision, criterion)
                    found = True
        if not found:
            raise pipe.PipeError(
                f"GENE_TUYAU node {mesh.node_names[node]} is not an end of a pipe line"
            )
    for k, line in enumerate(lines):
        sense, generator, precision, criterion = starts.get(k, (1, None, 1.0e-4, "RELATIF"))
        order = line if sense > 0 else line[::-1]
        if generator is None:
            a, b = mesh.cell_nodes[line[0]][:2]
            v = mesh.coords[b] - mesh.coords[a]
            generator = np.array([-v[1], v[0], 0.0])
            if np.linalg.norm(generator) < 1.0e-4 * np.linalg.norm(v):
                generator = np.array([0.0, -v[2], v[1]])
            generator = _unit(generator)
        given = k in starts
        for cell in order:
            coords = mesh.coords[np.asarray(mesh.cell_nodes[cell])]
            name = mesh.cell_names[cell]
            try:
                if _straight(coords, precision, criterion == "RELATIF"):
                    frame = pipe.local_frame(coords[1] - coords[0], generator)
                    # rounded: cells of one length share their matrices
                    length = round(float(np.linalg.norm(coords[1] - coords[0])), 12)
                    frames[cell] = PipeCell(length, np.array([frame] * len(coords)))
                    generator = -frame[2]  # carried to the next cell
                    continue
                compute = elbow_frames if len(coords) == 3 else elbow_frames_seg4
                elbow, node_frames, generator, *_ = compute(
                    coords, generator, sense < 0, given, criterion == "RELATIF"
                )
                frames[cell] = PipeCell(elbow, np.array(node_frames))
            except pipe.PipeError as exc:
                raise pipe.PipeError(f"pipe cell {name}: {exc}") from None
    return frames


def _pipe_section(section: dict) -> pipe.PipeSection:
    return pipe.PipeSection(
        radius=float(section["R"]),
        thickness=float(section["EP"]),
        layers=int(section.get("TUYAU_NCOU", 3)),
        sectors=int(section.get("TUYAU_NSEC", 16)),
        metric=bool(section.get("MODI_METRIQUE", 0.0)),
    )


def _checked(model, characteristics, cells):
    mesh = model.mesh
    sections = characteristics.sections if characteristics is not None else {}
    frames = getattr(characteristics, "pipe_frames", {}) if characteristics is not None else {}
    for cell in cells:
        name = mesh.cell_names[int(cell)]
        section = sections.get(int(cell))
        if section is None or "R" not in section or "EP" not in section:
            raise ElementError(
                f"pipe cell {name} has no section (AFFE_CARA_ELEM/POUTRE SECTION='CERCLE')"
            )
        if int(cell) not in frames:
            raise ElementError(f"pipe cell {name} has no frame (AFFE_CARA_ELEM on the model)")
    return sections, frames


def _element_rotation(frames: np.ndarray, per: int) -> np.ndarray:
    """Each node's frame on its translations and rotations, identity elsewhere."""
    n_nodes = len(frames)
    p = np.eye(n_nodes * per)
    for a in range(n_nodes):
        for offset in (0, 3):
            start = a * per + offset
            p[start : start + 3, start : start + 3] = frames[a]
    return p


def _groups(model, characteristics, cells, values):
    """Cells sharing modelisation, node count, geometry, section and material."""
    mesh = model.mesh
    sections = characteristics.sections
    groups: dict[tuple, list[int]] = defaultdict(list)
    for k, cell in enumerate(cells):
        conn = mesh.cell_nodes[int(cell)]
        section = _pipe_section(sections[int(cell)])
        key = (
            model.cell_modelisation[int(cell)],
            len(conn),
            characteristics.pipe_frames[int(cell)].geometry,
            section,
            tuple(float(values[n][k]) for n in ("E", "NU", "RHO", "AMOR_ALPHA", "AMOR_BETA")),
        )
        groups[key].append(k)
    return groups


def pipe_blocks(
    model, characteristics, matrix, cells, materials=None, lumped=False, **_options
) -> list[ElementBlock]:
    """Global-frame matrices (K, M or A) of pipe cells."""
    if matrix not in ("K", "M", "A"):
        raise ElementError(f"unknown element matrix {matrix!r}")
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    if lumped:
        raise ElementError("MASS_MECA_DIAG of pipe elements (code_aster has no such option)")
    mesh = model.mesh
    _, frames = _checked(model, characteristics, cells)
    values = _material_values(materials, cells, "TUYAU", need_density=matrix != "K")
    blocks = []
    for (modelisation, n_nodes, geometry, section, mat), rows in _groups(
        model, characteristics, cells, values
    ).items():
        young, poisson, density, alpha, beta = mat
        modes = FOURIER_MODES[modelisation]
        try:
            if matrix == "K":
                local = pipe.stiffness(modes, geometry, section, young, poisson, n_nodes)
            elif matrix == "M":
                local = pipe.mass(modes, geometry, section, density, n_nodes)
            else:
                local = np.zeros((n_nodes * (9 + 6 * (modes - 1)),) * 2)
                if alpha:
                    local = local + alpha * pipe.stiffness(
                        modes, geometry, section, young, poisson, n_nodes
                    )
                if beta:
                    local = local + beta * pipe.mass(modes, geometry, section, density, n_nodes)
        except pipe.PipeError as exc:
            name = mesh.cell_names[cells[rows[0]]]
            raise ElementError(f"{modelisation} cell {name}: {exc}") from None
        local = 0.5 * (local + local.T)
        per = len(PIPE_COMPONENTS[modelisation])
        members = cells[rows]
        rotations = np.array([_element_rotation(frames[int(c)].frames, per) for c in members])
        matrices = np.einsum("eji,jk,ekl->eil", rotations, local, rotations)
        nodes = np.array([mesh.cell_nodes[int(c)] for c in members], dtype=int)
        blocks.append(
            ElementBlock(nodes=nodes, components=PIPE_COMPONENTS[modelisation], matrices=matrices)
        )
    return blocks


def pipe_element_fields(
    model, characteristics, materials, numbering, cells, values: np.ndarray, options
) -> dict[str, ElementField]:
    """EFGE_ELNO of pipe cells for nodal values (n_orders, n_dofs), real or
    complex: the section integrals of the linear-elastic stresses at the RIGI
    Gauss points, taken to the nodes as code_aster's (no inertia term: its
    pipe forces come from the stresses alone)."""
    other = [name for name in options if name != "EFGE_ELNO"]
    if other:
        raise ValueError(f"{other[0]} is not computed for pipe elements (EFGE_ELNO)")
    cells = np.asarray(cells, dtype=int)
    mesh = model.mesh
    _, frames = _checked(model, characteristics, cells)
    props = _material_values(materials, cells, "TUYAU", need_density=False)
    values = np.asarray(values)
    max_nodes = max(len(mesh.cell_nodes[int(c)]) for c in cells)
    out = np.full(
        (values.shape[0], len(cells), max_nodes, 6), np.nan, dtype=np.result_type(values, float)
    )
    for (modelisation, n_nodes, geometry, section, mat), rows in _groups(
        model, characteristics, cells, props
    ).items():
        components = PIPE_COMPONENTS[modelisation]
        per = len(components)
        extrapolation = pipe.gauss_to_nodes(n_nodes)
        for k in rows:
            cell = int(cells[k])
            nodes = list(mesh.cell_nodes[cell])
            dofs = numbering.dof_indices(np.repeat(nodes, per), list(components) * n_nodes)
            u = np.zeros((values.shape[0], dofs.size), dtype=values.dtype)
            u[:, dofs >= 0] = values[:, dofs[dofs >= 0]]
            u_local = u @ _element_rotation(frames[cell].frames, per).T
            parts = [np.real(u_local)] + ([np.imag(u_local)] if np.iscomplexobj(u_local) else [])
            gauss = [
                pipe.section_forces_at_gauss(
                    FOURIER_MODES[modelisation], geometry, section, mat[0], mat[1], n_nodes, p
                )
                for p in parts
            ]
            at_gauss = gauss[0] if len(gauss) == 1 else gauss[0] + 1j * gauss[1]
            out[:, k, :n_nodes, :] = np.einsum("ng,ogc->onc", extrapolation, at_gauss)
    return {name: ElementField(name, cells, EFGE_COMPONENTS, out.copy()) for name in options}


def _cell_inertia(coords, section, cell: PipeCell, density: float):
    """(mass, centre of gravity, 3x3 inertia tensor about it) of a pipe
    cell by code_aster's own formulas (te0038), not from its mass matrix."""
    outer, thickness = float(section["R"]), float(section["EP"])
    inner, mean = outer - thickness, outer - thickness / 2.0
    area = np.pi * (outer**2 - inner**2)
    bending = np.pi * (outer**4 - inner**4) / 4.0
    middle = (coords[0] + coords[1]) / 2.0
    geometry = cell.geometry
    if not isinstance(geometry, pipe.Elbow):
        length = float(geometry)
        mass = density * area * length
        local = np.diag(
            [
                density * 2.0 * bending * length,
                density * length * (bending + area * length**2 / 12.0),
                density * length * (bending + area * length**2 / 12.0),
            ]
        )
        frame = cell.frames[0]
        return mass, middle, frame.T @ local @ frame
    theta, radius = geometry.angle, geometry.radius
    length = theta * radius
    mass = density * area * length
    if len(coords) == 3:
        frame = cell.frames[2]
    else:  # the chord's frame in the bend plane of the inner nodes' midpoint
        inner_middle = (coords[2] + coords[3]) / 2.0
        t1 = _unit(inner_middle - coords[0])
        t2 = _unit(coords[1] - inner_middle)
        chord = coords[1] - coords[0]
        frame = np.array(_chord_frame(chord, np.cross(chord, _unit(np.cross(t2, t1)))))
    spread = 1.0 + (mean**2 + thickness**2 / 4.0) / (2.0 * radius**2)
    offset = -radius * (np.sin(theta / 2.0) / (theta / 2.0) * spread - np.cos(theta / 2.0))
    centre = middle + frame.T @ np.array([0.0, offset, 0.0])
    # code_aster's te0038 terms as written (outer radius in both)
    xa = area * outer**2 + 3.0 * bending
    xb = outer * np.sin(theta / 2.0) / theta / 2.0
    xb *= 1.0 + (mean**2 + thickness**2 / 4.0) / (2.0 * outer**2)
    local = np.diag(
        [
            density * length * (bending + xa * (0.5 + np.sin(theta) / (4.0 * theta)))
            - mass * xb**2,
            density * length * (bending + xa * (0.5 - np.sin(theta) / (4.0 * theta))),
            density * length * xa - mass * xb**2,
        ]
    )
    return mass, centre, frame.T @ local @ frame


def _chord_frame(x, y):
    x = _unit(x)
    y = _unit(y - np.dot(y, x) * x)
    return [x, y, np.cross(x, y)]


def pipe_cell_inertias(model, characteristics, materials, cells) -> list:
    """(mass, centre, inertia tensor about the centre) of each pipe cell, from
    code_aster's MASS_INER formulas of pipes (te0038)."""
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    mesh = model.mesh
    sections, frames = _checked(model, characteristics, cells)
    density = _material_values(materials, cells, "TUYAU", need_density=True)["RHO"]
    found = []
    for k, cell in enumerate(cells):
        coords = mesh.coords[np.asarray(mesh.cell_nodes[int(cell)])]
        found.append(
            _cell_inertia(coords, sections[int(cell)], frames[int(cell)], float(density[k]))
        )
    return found


def pipe_gravity_terms(model, characteristics, materials, cells, acceleration) -> list:
    """(node, component, force) of a uniform acceleration on pipe cells, as
    code_aster's te0583: each node's DX, DY, DZ take the integral of its shape
    function times rho g over the volume (MASS points; an elbow's fibres by
    their own length), no moment and no ovalisation term."""
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    mesh = model.mesh
    sections, frames = _checked(model, characteristics, cells)
    density = _material_values(materials, cells, "TUYAU", need_density=True)["RHO"]
    terms = []
    for k, cell in enumerate(cells):
        nodes = mesh.cell_nodes[int(cell)]
        h = pipe.lagrange(len(nodes), pipe.MASS_POINTS)[0]
        weights = pipe.quadrature_weights(
            frames[int(cell)].geometry,
            _pipe_section(sections[int(cell)]),
            pipe.MASS_POINTS,
            len(nodes),
        )
        shares = density[k] * h.T @ weights.sum(axis=(1, 2))  # (nno,)
        for node, share in zip(nodes, shares, strict=True):
            terms.extend(
                (int(node), c, share * a)
                for c, a in zip(("DX", "DY", "DZ"), acceleration, strict=True)
            )
    return terms


def pipe_pressure_terms(model, characteristics, cells, pressure: float) -> list:
    """(node, component, force) of a uniform pressure inside pipe cells, as
    code_aster's te0583 (FORCE_TUYAU): on the inner surface, at the MASS
    points along the axis and the section's Simpson points; a straight cell
    loads the swelling WO only, an elbow also its translations (the inner
    fibres are shorter) and WI1, WO1."""
    cells = np.asarray(cells, dtype=int)
    mesh = model.mesh
    sections, frames = _checked(model, characteristics, cells)
    terms = []
    for cell in cells:
        nodes = mesh.cell_nodes[int(cell)]
        n_nodes = len(nodes)
        per = len(PIPE_COMPONENTS[model.cell_modelisation[int(cell)]])
        section = _pipe_section(sections[int(cell)])
        h, _, _, xi, gauss = pipe.lagrange(n_nodes, pipe.MASS_POINTS)
        sectors = section.sectors
        phi = np.arange(2 * sectors + 1) * np.pi / sectors
        sector_weights = pipe.simpson(sectors) * np.pi / sectors  # sum: 2 pi
        inner = section.radius - section.thickness
        geometry = frames[int(cell)].geometry
        forces = np.zeros((n_nodes, per))
        wo = 6 + 6 * (FOURIER_MODES[model.cell_modelisation[int(cell)]] - 1)
        if isinstance(geometry, pipe.Elbow):
            theta, omega = geometry.angle, geometry.omega
            half_length = theta * (geometry.radius + inner * np.sin(phi)) / 2.0  # (sectors,)
            arc = (1.0 + xi)[:, None] * theta / 2.0 - geometry.node_angles(n_nodes)[None, :]
            for a in range(n_nodes):
                # (npg, sectors) weights of the inner surface
                w = (gauss * h[:, a])[:, None] * (sector_weights * half_length)[None, :]
                w = w * inner * pressure
                ck, sk = np.cos(arc[:, a])[:, None], np.sin(arc[:, a])[:, None]
                sin, cos = np.sin(phi)[None, :], np.cos(phi)[None, :]
                forces[a, 0] = np.sum(w * sin * sk)
                forces[a, 1] = -np.sum(w * sin * ck)
                forces[a, 2] = -np.sum(w * cos)
                forces[a, wo] = np.sum(w)
                forces[a, wo + 1] = np.sum(w * np.cos(phi - omega)[None, :])
                forces[a, wo + 2] = np.sum(w * np.sin(phi - omega)[None, :])
        else:
            shares = (gauss[:, None] * h).sum(axis=0) * float(geometry) / 2.0
            forces[:, wo] = shares * sector_weights.sum() * inner * pressure
        rotation = _element_rotation(frames[int(cell)].frames, per)
        global_forces = (rotation.T @ forces.ravel()).reshape(n_nodes, per)
        components = PIPE_COMPONENTS[model.cell_modelisation[int(cell)]]
        for a, node in enumerate(nodes):
            for c, value in zip(components, global_forces[a], strict=True):
                if value != 0.0:
                    terms.append((int(node), c, float(value)))
    return terms
