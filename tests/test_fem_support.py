"""Test support (no tests here): run front-end commands without the deck
runtime -- hand-made Keywords and a minimal session (log, input_path,
bind_output) -- and build spring-mass chains programmatically."""

from __future__ import annotations

import importlib
from pathlib import Path

import numpy as np

from asterlite.catalog import load_catalogue, validate
from asterlite.catalog.keywords import Keywords
from asterlite.concepts.mesh import Mesh
from asterlite.runtime.context import CommandContext


class FakeSession:
    def __init__(self, units: dict[int, Path] | None = None):
        self.units = dict(units or {})
        self.lines: list[str] = []
        self.bound: dict[str, object] = {}
        self.check_only = False

    def log(self, text: str) -> None:
        self.lines.append(text)

    def input_path(self, unit: int) -> Path:
        return self.units[unit]

    def bind_output(self, co, concept) -> None:
        name = getattr(co, "name", co)
        concept.name = name
        self.bound[name] = concept


class CO:
    def __init__(self, name: str):
        self.name = name


def keywords(command: str, values: dict) -> Keywords:
    """Nested dicts (or lists of dicts) become factor-keyword occurrences."""
    kw = Keywords(path=command)
    for key, value in values.items():
        if isinstance(value, dict):
            value = [value]
        if isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            value = [keywords(f"{command}/{key}[{i + 1}]", v) for i, v in enumerate(value)]
        kw[key] = value
    return kw


def run(session: FakeSession, command: str, **values):
    module = importlib.import_module(f"asterlite.commands.{command.lower()}")
    ctx = CommandContext(session=session, command=command)
    return module.run(ctx, keywords(command, values))


def validated_run(session: FakeSession, command: str, **values):
    """``run`` through the command's catalogue, as a deck's call: the
    keywords checked and the catalogue's defaults filled (the commands that
    restate none, DYNA_VIBRA's wing, need them)."""
    module = importlib.import_module(f"asterlite.commands.{command.lower()}")
    ctx = CommandContext(session=session, command=command)
    return module.run(ctx, validate(load_catalogue(command), values))


def chain_mesh(n_nodes: int, length: float = 1.0, dim: int = 3) -> Mesh:
    """Nodes N1..Nn on the x axis, springs S1..S(n-1), point cells P1..Pn,
    groups RESSORTS (SEG2), MASSES (POI1), ENDS (first and last node)."""
    coords = np.zeros((n_nodes, 3))
    coords[:, 0] = np.linspace(0.0, length, n_nodes)
    n_springs = n_nodes - 1
    cell_nodes = [(i, i + 1) for i in range(n_springs)] + [(i,) for i in range(n_nodes)]
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(n_nodes)],
        cell_names=[f"S{i + 1}" for i in range(n_springs)] + [f"P{i + 1}" for i in range(n_nodes)],
        cell_types=["SEG2"] * n_springs + ["POI1"] * n_nodes,
        cell_nodes=cell_nodes,
        node_groups={"ENDS": np.array([0, n_nodes - 1]), "FIRST": np.array([0])},
        cell_groups={
            "RESSORTS": np.arange(n_springs),
            "MASSES": np.arange(n_springs, n_springs + n_nodes),
        },
        dim=dim,
    )


def chain_matrices(n_nodes, k_values, m_value, modelisation="DIS_T", ddl_impo=None, session=None):
    """Assembled K, M (and the model) of a chain through the real commands."""
    session = session or FakeSession()
    mesh = chain_mesh(n_nodes)
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": modelisation},
    )
    keyword = "DISCRET_2D" if modelisation.startswith("2D_") else "DISCRET"
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        **{
            keyword: [
                {"GROUP_MA": "RESSORTS", "CARA": "K_T_D_L", "VALE": tuple(k_values)},
                {"GROUP_MA": "MASSES", "CARA": "M_T_D_N", "VALE": m_value},
            ]
        },
    )
    charge = run(session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO=ddl_impo or [])
    common = {"MODELE": model, "CHARGE": charge, "CARA_ELEM": cara}
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", **common)
    mass = run(session, "CALC_MATR_ELEM", OPTION="MASS_MECA", **common)
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    k = run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering)
    m = run(session, "ASSE_MATRICE", MATR_ELEM=mass, NUME_DDL=numbering)
    return session, model, k, m
