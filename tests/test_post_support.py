"""Shared helpers for the post-processing tests: a fake session, keyword
trees, and a small hand-made modal transient (2 nodes, 2 modes)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from asterlite.catalog.keywords import Keywords
from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.modes import ModeResult
from asterlite.concepts.transient import ShockHistory, TranGene
from asterlite.runtime.context import CommandContext


class FakeSession:
    def __init__(self, output_dir: Path | None = None):
        self.messages: list[str] = []
        self.tests = []
        self.output_dir = output_dir

    def log(self, text):
        self.messages.append(text)

    def record_test(self, record):
        self.tests.append(record)

    def output_path(self, unit):
        self.output_dir.mkdir(parents=True, exist_ok=True)
        return self.output_dir / (f"fort.{unit}" if isinstance(unit, int) else str(unit))


def kw(**values) -> Keywords:
    """A Keywords tree; lists of dicts become factor occurrences."""
    out = Keywords(path="CMD")
    for key, value in values.items():
        if isinstance(value, list) and value and isinstance(value[0], dict):
            value = [Keywords(v, path=f"CMD/{key}[{i + 1}]") for i, v in enumerate(value)]
        out[key] = value
    return out


def context(command="CMD", tmp_path=None) -> CommandContext:
    return CommandContext(session=FakeSession(tmp_path), command=command)


def small_transient() -> TranGene:
    """Two nodes (NO1, NO2) with DX, DY; two modes; q1 = t, q2 = t²."""
    mesh = Mesh(
        coords=np.zeros((2, 3)),
        node_names=["NO1", "NO2"],
        cell_names=["EL1"],
        cell_types=["SEG2"],
        cell_nodes=[(0, 1)],
        node_groups={"NO1": np.array([0]), "NO2": np.array([1]), "ALL": np.array([0, 1])},
        cell_groups={"BAR": np.array([0])},
    )
    numbering = DofNumbering(mesh, [(0, "DX"), (0, "DY"), (1, "DX"), (1, "DY")])
    shapes = np.array([[1.0, 0.0], [0.0, 1.0], [2.0, 0.5], [0.0, -1.0]])
    basis = ModeResult(
        numbering, shapes, np.array([1.0, 2.0]), np.ones(2), np.array([4.0, 16.0]) * np.pi**2
    )
    times = np.linspace(0.0, 1.0, 11)
    q = np.column_stack([times, times**2])
    v = np.column_stack([np.ones_like(times), 2 * times])
    a = np.column_stack([np.zeros_like(times), 2 * np.ones_like(times)])
    shock = ShockHistory(
        "CHOC1", "DIS_CHOC", "NO2", None, {"FN": np.sin(np.pi * times), "VN": -np.cos(times)}
    )
    return TranGene(basis, times, np.arange(11), q, v, a, shocks=[shock])


def test_small_transient_is_consistent():
    result = small_transient()
    assert result.n_modes == 2
    assert result.basis.shape_at("NO2", "DX").tolist() == [2.0, 0.5]
