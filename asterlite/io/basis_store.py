"""The basis of a stored ``tran_gene``, whatever its kind (the ``basis/``
group of :mod:`asterlite.io.result_store`, described in docs/results.md).

The generalized coordinates of a transient are on one of these bases; the
``basis_type`` attribute gives code_aster's type of the basis concept:

- ``mode_meca`` (``mode_flamb``, ``mode_meca_c``): a physical modal basis
  (:class:`ModeResult`: CALC_MODES, MODE_STATIQUE, DEFI_BASE_MODALE...),
  shapes on the DOFs of a mesh, stored with the mesh; a DEFI_BASE_MODALE
  basis that keeps its interfaces (``reduction_basis``) stores them too;
- ``mode_gene``: generalized modes (:class:`GeneralizedModes`), vectors in
  the unknowns of a NUME_DDL_GENE, stored in ``numbering/`` with what it is
  built on (``built_on``): a basis (nested, in this same layout) or a
  generalized model (``modele_gene``: the substructures' names, placements
  and macro-elements -- each with its own basis, interfaces and reduced
  matrices --, the links, each substructure's first unknown and the
  interface relations B q = 0). PROJ_BASE on CALC_MODES of a coupled
  model gives one; DYNA_VIBRA on the coupled model's assembled matrices
  integrates on the null space of B, a mode_gene on the model too
  (:mod:`asterlite.substructure.transient`);
- ``none``: no basis (REST_SPEC_TEMP of a harm_gene computed on the
  assembled matrices of a coupled model, which have none).

:func:`basis_from` rebuilds a concept of the same kind, down to the
substructures' macro-elements: the restitution on the substructures
(:mod:`asterlite.substructure.restitution`) works on a loaded result. Not
stored: a basis's assembled matrices (its MATR_MASS, MATR_RIGI) and the
linear relations of its DOF numbering.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.modes import (
    BucklingModes,
    ComplexModeResult,
    GeneralizedModes,
    GeneralizedNumbering,
    ModeResult,
)
from asterlite.concepts.substructure import (
    DynamicInterfaces,
    GeneralizedModel,
    Interface,
    Link,
    MacroElement,
    ReductionBasis,
    Substructure,
    SubstructuredNumbering,
)
from asterlite.io.hdf5_values import (
    read_attrs,
    read_group_arrays,
    read_strings,
    strings,
    unique_member_names,
)

NO_BASIS = "none"
# the classes of the physical bases, by code_aster type
PHYSICAL_TYPES = {
    "mode_meca": ModeResult,
    "mode_flamb": BucklingModes,
    "mode_meca_c": ComplexModeResult,
}


def _numbers(values) -> np.ndarray:
    """Real values as float64, complex ones (a mode_meca_c) as they are."""
    array = np.asarray(values)
    return array if array.dtype.kind == "c" else array.astype(float)


# =============================================================================
# writing
# =============================================================================


def write_mesh(group, mesh: Mesh) -> None:
    group.attrs["name"] = mesh.name or ""
    group.attrs["dim"] = int(mesh.dim)
    group.attrs["title"] = mesh.title or ""
    group["coords"] = np.asarray(mesh.coords, dtype=float)
    group["node_names"] = strings(mesh.node_names)
    group["cell_names"] = strings(mesh.cell_names)
    group["cell_types"] = strings(mesh.cell_types)
    sizes = np.array([len(c) for c in mesh.cell_nodes], dtype=np.int64)
    group["cell_offsets"] = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    flat = [n for c in mesh.cell_nodes for n in c]
    group["cell_connectivity"] = np.asarray(flat, dtype=np.int64)
    for kind, groups in (("node_groups", mesh.node_groups), ("cell_groups", mesh.cell_groups)):
        sub = group.create_group(kind, track_order=True)
        for name, members in groups.items():
            sub[name.replace("/", "_")] = np.asarray(members, dtype=np.int64)


def write_basis(group, basis) -> None:
    """Any basis a tran_gene can have, with ``basis_type`` saying which."""
    if basis is None:
        group.attrs["basis_type"] = NO_BASIS
    elif isinstance(basis, ModeResult) and basis.aster_type in PHYSICAL_TYPES:
        _write_physical(group, basis)
    elif isinstance(basis, GeneralizedModes):
        _write_generalized_modes(group, basis)
    else:  # a new kind of basis must get its layout here, never be stored half
        raise TypeError(f"the result store has no layout for a basis of type {type(basis)}")


def _write_per_mode(group, basis) -> None:
    """What every modal basis has, one value per mode."""
    group["frequencies"] = np.asarray(basis.frequencies, dtype=float)
    group["generalized_mass"] = _numbers(basis.generalized_mass)
    group["generalized_stiffness"] = _numbers(basis.generalized_stiffness)
    group["mode_numbers"] = np.asarray(basis.mode_numbers, dtype=np.int64)
    _write_parameters(group.create_group("parameters", track_order=True), basis)


def _write_parameters(group, basis) -> None:
    """The per-mode quantities by code_aster name (NUME_MODE, MASS_EFFE_DX,
    TYPE_MODE, NOEUD_CMP...): numbers as they are, text as strings (None
    as "", flagged ``none_is_empty``); anything else is listed in
    ``not_stored``."""
    keys = list(basis.parameters)
    skipped = []
    for member, key in zip(unique_member_names(keys, "PARA_{}"), keys, strict=True):
        array = np.asarray(basis.parameters[key])
        if array.shape != (basis.n_modes,):
            skipped.append(key)
            continue
        values = array.tolist()
        if array.dtype.kind in "biufc":
            dataset = group.create_dataset(member, data=array)
        elif all(v is None or isinstance(v, str) for v in values):
            dataset = group.create_dataset(member, data=strings(v or "" for v in values))
            if any(v is None for v in values):
                dataset.attrs["none_is_empty"] = True
        else:
            skipped.append(key)
            continue
        dataset.attrs["parameter"] = key
    if skipped:
        group.attrs["not_stored"] = ", ".join(skipped)


def _write_physical(group, basis: ModeResult) -> None:
    numbering = basis.numbering
    mesh = numbering.mesh
    group.attrs["basis_type"] = basis.aster_type
    group.attrs["name"] = basis.name or ""
    group.attrs["kind"] = basis.kind
    group.attrs["norm"] = basis.norm
    group.attrs["reduction_basis"] = isinstance(basis, ReductionBasis)
    group["shapes"] = _numbers(basis.shapes)
    group["dof_nodes"] = np.array([n for n, _ in numbering.dofs], dtype=np.int64)
    group["dof_components"] = strings(c for _, c in numbering.dofs)
    group["dof_labels"] = strings(f"{mesh.node_names[n]} {c}" for n, c in numbering.dofs)
    _write_per_mode(group, basis)
    if basis.mode_labels:
        group["mode_labels"] = strings(basis.mode_labels)
    if isinstance(basis, ComplexModeResult):
        group["eigenvalues"] = np.asarray(basis.eigenvalues, dtype=complex)
    interfaces = getattr(basis, "interfaces", None)
    if interfaces is not None:
        _write_interfaces(group.create_group("interfaces", track_order=True), interfaces)
    write_mesh(group.create_group("mesh"), mesh)


def _write_generalized_modes(group, modes: GeneralizedModes) -> None:
    group.attrs["basis_type"] = modes.aster_type
    group.attrs["name"] = modes.name or ""
    group.attrs["norm"] = modes.norm
    group["vectors"] = _numbers(modes.vectors)
    _write_per_mode(group, modes)
    _write_numbering(group.create_group("numbering"), modes.numbering)


def _write_numbering(group, numbering: GeneralizedNumbering) -> None:
    group.attrs["name"] = numbering.name or ""
    group.attrs["storage"] = numbering.storage
    if not isinstance(numbering, SubstructuredNumbering):
        group.attrs["built_on"] = "basis"
        write_basis(group.create_group("basis"), numbering.basis)
        return
    group.attrs["built_on"] = "modele_gene"
    group.attrs["method"] = numbering.method
    group["offsets"] = np.asarray(numbering.offsets, dtype=np.int64)
    group["constraints"] = np.asarray(numbering.constraints, dtype=float)
    if numbering.model is not None:
        names = [sub.name for sub in numbering.model.substructures]
        group["substructure_names"] = strings(names)
        _write_model(group.create_group("model"), numbering.model)


def _write_model(group, model: GeneralizedModel) -> None:
    group.attrs["name"] = model.name or ""
    # a macro-element placed several times is stored once
    distinct = list({id(sub.macro): sub.macro for sub in model.substructures}.values())
    members = unique_member_names([macro.name for macro in distinct], "MACR_ELEM_{}")
    macros = group.create_group("macros", track_order=True)
    for member, macro in zip(members, distinct, strict=True):
        _write_macro(macros.create_group(member), macro)
    member_of = {id(macro): member for member, macro in zip(members, distinct, strict=True)}
    subs = group.create_group("substructures", track_order=True)
    names = unique_member_names([sub.name for sub in model.substructures], "SOUS_STRUC_{}")
    for member, sub in zip(names, model.substructures, strict=True):
        placed = subs.create_group(member)
        placed.attrs["name"] = sub.name
        placed.attrs["macro"] = member_of[id(sub.macro)]
        placed["rotation"] = np.asarray(sub.rotation, dtype=float)
        placed["translation"] = np.asarray(sub.translation, dtype=float)
    links = group.create_group("links", track_order=True)
    for k, link in enumerate(model.links, start=1):
        linked = links.create_group(f"LIAISON_{k}")
        for key in ("substructure_1", "interface_1", "substructure_2", "interface_2"):
            linked.attrs[key] = getattr(link, key)
        linked["pairs"] = np.asarray(link.pairs, dtype=np.int64).reshape(-1, 2)


def _write_macro(group, macro: MacroElement) -> None:
    group.attrs["name"] = macro.name or ""
    group["stiffness"] = _numbers(macro.stiffness)
    group["mass"] = _numbers(macro.mass)
    if macro.damping is not None:
        group["damping"] = _numbers(macro.damping)
    write_basis(group.create_group("basis"), macro.basis)
    if macro.interfaces is not getattr(macro.basis, "interfaces", None):
        _write_interfaces(group.create_group("interfaces", track_order=True), macro.interfaces)


def _write_interfaces(group, interfaces: DynamicInterfaces) -> None:
    """DEFI_INTERF_DYNA's interfaces (DOF indices in the basis's numbering)."""
    group.attrs["name"] = interfaces.name or ""
    group.attrs["frequency"] = float(interfaces.frequency)
    members = unique_member_names([i.name for i in interfaces.interfaces], "INTERFACE_{}")
    for member, interface in zip(members, interfaces.interfaces, strict=True):
        sub = group.create_group(member)
        sub.attrs["name"] = interface.name
        sub.attrs["kind"] = interface.kind
        sub["masked"] = strings(interface.masked)
        sub["nodes"] = np.asarray(interface.nodes, dtype=np.int64)
        sub["dofs"] = np.asarray(interface.dofs, dtype=np.int64)
        sub["dof_nodes"] = np.asarray(interface.dof_nodes, dtype=np.int64)


# =============================================================================
# reading: plain data, then concepts
# =============================================================================


def read_mesh(group) -> dict[str, Any]:
    out = read_attrs(group)
    out["coords"] = group["coords"][()]
    for key in ("node_names", "cell_names", "cell_types"):
        out[key] = read_strings(group[key])
    out["cell_offsets"] = group["cell_offsets"][()]
    out["cell_connectivity"] = group["cell_connectivity"][()]
    out["node_groups"] = read_group_arrays(group["node_groups"])
    out["cell_groups"] = read_group_arrays(group["cell_groups"])
    return out


def read_basis(group) -> dict[str, Any]:
    """A stored basis as plain data; ``basis_type`` says which kind (files
    written before other kinds were stored hold a mode_meca)."""
    out = read_attrs(group)
    basis_type = str(out.setdefault("basis_type", "mode_meca"))
    if basis_type == NO_BASIS:
        return out
    if basis_type in PHYSICAL_TYPES:
        return _read_physical(group, out)
    if basis_type == "mode_gene":
        return _read_generalized_modes(group, out)
    raise ValueError(f"{group.name}: unknown basis_type {basis_type!r}")


def _read_per_mode(group, out: dict) -> dict[str, Any]:
    for key in ("frequencies", "generalized_mass", "generalized_stiffness", "mode_numbers"):
        out[key] = group[key][()]
    out["parameters"] = _read_parameters(group["parameters"]) if "parameters" in group else {}
    return out


def _read_parameters(group) -> dict[str, np.ndarray]:
    out = {}
    for member, dataset in group.items():
        key = str(dataset.attrs.get("parameter", member))
        if dataset.dtype.kind in "biufc":
            out[key] = dataset[()]
            continue
        values = read_strings(dataset)
        if dataset.attrs.get("none_is_empty", False):
            values = [v or None for v in values]
        out[key] = np.array(values, dtype=object)
    return out


def _read_physical(group, out: dict) -> dict[str, Any]:
    out["shapes"] = group["shapes"][()]
    out["dof_nodes"] = group["dof_nodes"][()]
    out["dof_components"] = read_strings(group["dof_components"])
    out["dof_labels"] = read_strings(group["dof_labels"])
    _read_per_mode(group, out)
    out["mode_labels"] = read_strings(group["mode_labels"]) if "mode_labels" in group else []
    if "eigenvalues" in group:
        out["eigenvalues"] = group["eigenvalues"][()]
    if "interfaces" in group:
        out["interfaces"] = _read_interfaces(group["interfaces"])
    out["mesh"] = read_mesh(group["mesh"])
    return out


def _read_interfaces(group) -> dict[str, Any]:
    out = read_attrs(group)
    out["interfaces"] = [
        {
            **read_attrs(sub),
            "masked": read_strings(sub["masked"]),
            "nodes": sub["nodes"][()],
            "dofs": sub["dofs"][()],
            "dof_nodes": sub["dof_nodes"][()],
        }
        for sub in group.values()
    ]
    return out


def _read_generalized_modes(group, out: dict) -> dict[str, Any]:
    out["vectors"] = group["vectors"][()]
    _read_per_mode(group, out)
    numbering = group["numbering"]
    data = read_attrs(numbering)
    if data.get("built_on") == "basis":
        data["basis"] = read_basis(numbering["basis"])
    else:
        data["offsets"] = numbering["offsets"][()]
        data["constraints"] = numbering["constraints"][()]
        if "model" in numbering:
            data["substructure_names"] = read_strings(numbering["substructure_names"])
            data["model"] = _read_model(numbering["model"])
    out["numbering"] = data
    return out


def _read_model(group) -> dict[str, Any]:
    out = read_attrs(group)
    out["macros"] = {}
    for member, macro in group["macros"].items():
        data = read_attrs(macro)
        for key in ("stiffness", "mass", "damping"):
            data[key] = macro[key][()] if key in macro else None
        data["basis"] = read_basis(macro["basis"])
        if "interfaces" in macro:
            data["interfaces"] = _read_interfaces(macro["interfaces"])
        out["macros"][member] = data
    out["substructures"] = [
        {**read_attrs(sub), "rotation": sub["rotation"][()], "translation": sub["translation"][()]}
        for sub in group["substructures"].values()
    ]
    out["links"] = [
        {**read_attrs(link), "pairs": link["pairs"][()]} for link in group["links"].values()
    ]
    return out


def mesh_from(data: dict[str, Any]) -> Mesh:
    offsets = data["cell_offsets"]
    conn = data["cell_connectivity"]
    cell_nodes = [
        tuple(int(n) for n in conn[offsets[i] : offsets[i + 1]]) for i in range(len(offsets) - 1)
    ]
    mesh = Mesh(
        coords=np.asarray(data["coords"], dtype=float),
        node_names=list(data["node_names"]),
        cell_names=list(data["cell_names"]),
        cell_types=list(data["cell_types"]),
        cell_nodes=cell_nodes,
        node_groups={k: np.asarray(v, dtype=int) for k, v in data["node_groups"].items()},
        cell_groups={k: np.asarray(v, dtype=int) for k, v in data["cell_groups"].items()},
        dim=int(data.get("dim", 3)),
        title=str(data.get("title", "")),
    )
    mesh.name = data.get("name") or None
    return mesh


def basis_from(data: dict[str, Any]):
    """The concept of :func:`read_basis`'s data: a ModeResult (BucklingModes,
    ComplexModeResult, ReductionBasis as stored), GeneralizedModes on their
    rebuilt numbering, or None."""
    basis_type = data.get("basis_type", "mode_meca")
    if basis_type == NO_BASIS:
        return None
    if basis_type == "mode_gene":
        return _generalized_modes_from(data)
    return _physical_from(data)


def _per_mode(data: dict[str, Any]) -> dict[str, Any]:
    parameters = dict(data.get("parameters") or {})
    parameters.setdefault("NUME_MODE", np.asarray(data["mode_numbers"], dtype=int))
    return {
        "frequencies": np.asarray(data["frequencies"], dtype=float),
        "generalized_mass": _numbers(data["generalized_mass"]),
        "generalized_stiffness": _numbers(data["generalized_stiffness"]),
        "parameters": parameters,
        "norm": str(data.get("norm", "")),
    }


def _physical_from(data: dict[str, Any]) -> ModeResult:
    mesh = mesh_from(data["mesh"])
    dofs = [(int(n), c) for n, c in zip(data["dof_nodes"], data["dof_components"], strict=True)]
    numbering = DofNumbering(mesh=mesh, dofs=dofs)
    fields = {
        "numbering": numbering,
        "shapes": _numbers(data["shapes"]),
        "kind": str(data.get("kind", "dynamic")),
        "mode_labels": list(data.get("mode_labels", [])),
        **_per_mode(data),
    }
    basis_type = data.get("basis_type", "mode_meca")
    if basis_type == "mode_meca_c":
        fields["eigenvalues"] = np.asarray(data["eigenvalues"], dtype=complex)
    if data.get("reduction_basis"):
        interfaces = data.get("interfaces")
        interfaces = None if interfaces is None else _interfaces_from(interfaces, numbering)
        basis = ReductionBasis(**fields, interfaces=interfaces)
    else:
        basis = PHYSICAL_TYPES[basis_type](**fields)
    basis.name = data.get("name") or None
    return basis


def _interfaces_from(data: dict[str, Any], numbering: DofNumbering) -> DynamicInterfaces:
    interfaces = [
        Interface(
            name=str(i["name"]),
            kind=str(i["kind"]),
            nodes=np.asarray(i["nodes"], dtype=int),
            masked=tuple(i["masked"]),
            dofs=np.asarray(i["dofs"], dtype=int),
            dof_nodes=np.asarray(i["dof_nodes"], dtype=int),
        )
        for i in data["interfaces"]
    ]
    out = DynamicInterfaces(numbering, interfaces, float(data.get("frequency", 1.0)))
    out.name = data.get("name") or None
    return out


def _generalized_modes_from(data: dict[str, Any]) -> GeneralizedModes:
    modes = GeneralizedModes(
        numbering=_numbering_from(data["numbering"]),
        vectors=_numbers(data["vectors"]),
        **_per_mode(data),
    )
    modes.name = data.get("name") or None
    return modes


def _numbering_from(data: dict[str, Any]) -> GeneralizedNumbering:
    storage = str(data.get("storage", "PLEIN"))
    if data.get("built_on") == "basis":
        numbering = GeneralizedNumbering(basis=basis_from(data["basis"]), storage=storage)
    else:
        model = _model_from(data["model"]) if "model" in data else None
        numbering = SubstructuredNumbering(
            basis=None,
            storage=storage,
            model=model,
            offsets=np.asarray(data["offsets"], dtype=int),
            constraints=np.asarray(data["constraints"], dtype=float),
            method=str(data.get("method", "CLASSIQUE")),
        )
    numbering.name = data.get("name") or None
    return numbering


def _model_from(data: dict[str, Any]) -> GeneralizedModel:
    macros = {member: _macro_from(macro) for member, macro in data["macros"].items()}
    substructures = [
        Substructure(
            name=str(sub["name"]),
            macro=macros[sub["macro"]],
            rotation=np.asarray(sub["rotation"], dtype=float),
            translation=np.asarray(sub["translation"], dtype=float),
        )
        for sub in data["substructures"]
    ]
    links = [
        Link(
            str(link["substructure_1"]),
            str(link["interface_1"]),
            str(link["substructure_2"]),
            str(link["interface_2"]),
            [(int(a), int(b)) for a, b in np.asarray(link["pairs"]).reshape(-1, 2)],
        )
        for link in data["links"]
    ]
    model = GeneralizedModel(substructures, links)
    model.name = data.get("name") or None
    return model


def _macro_from(data: dict[str, Any]) -> MacroElement:
    basis = basis_from(data["basis"])
    if "interfaces" in data:
        interfaces = _interfaces_from(data["interfaces"], basis.numbering)
    else:  # the basis's own (DEFI_BASE_MODALE's, as MACR_ELEM_DYNA takes them)
        interfaces = getattr(basis, "interfaces", None)
    macro = MacroElement(
        basis=basis,
        interfaces=interfaces,
        stiffness=_numbers(data["stiffness"]),
        mass=_numbers(data["mass"]),
        damping=None if data.get("damping") is None else _numbers(data["damping"]),
    )
    macro.name = data.get("name") or None
    return macro


__all__ = [
    "basis_from",
    "mesh_from",
    "read_basis",
    "read_mesh",
    "write_basis",
    "write_mesh",
]
