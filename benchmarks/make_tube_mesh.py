"""Write the tube benchmark's mesh in ASTER text format.

40 SEG2 cells along X from 0 to 2 m (nodes N1..N41), with the groups the
deck samples/tube_supports/tube_supports.comm uses:

- GROUP_MA TUBE: every cell;
- GROUP_NO ENCASTR: both ends (N1, N41);
- GROUP_NO SUPP1, SUPP2, SUPP3: the support nodes at 1/4, 1/2, 3/4 (N11, N21, N31);
- GROUP_NO MILIEU: the mid-span node where the force acts (N21).

Run: python benchmarks/make_tube_mesh.py [output.mail]
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import tube_model as T

DEFAULT_OUTPUT = Path(__file__).resolve().parents[1] / "samples/tube_supports/tube_supports.mail"


def node_name(index: int) -> str:
    return f"N{index + 1}"


def group_block(kind: str, name: str, members: list[str]) -> list[str]:
    return [f" {kind}", f" {name}", *(f" {m}" for m in members), " FINSF", " %"]


def tube_mesh_text() -> str:
    n_nodes = T.N_ELEMENTS + 1
    xs = np.linspace(0.0, T.LENGTH, n_nodes)
    lines = [
        " TITRE",
        " ASTERLITE SAMPLE - CLAMPED TUBE ON THREE CIRCULAR SUPPORTS",
        " FINSF",
        " %",
    ]
    lines.append(" COOR_3D")
    lines += [f" {node_name(i):<8} {x:22.14E} {0.0:22.14E} {0.0:22.14E}" for i, x in enumerate(xs)]
    lines += [" FINSF", " %", " SEG2"]
    lines += [f" M{e + 1:<7} {node_name(e):<8} {node_name(e + 1)}" for e in range(T.N_ELEMENTS)]
    lines += [" FINSF", " %"]
    lines += group_block("GROUP_MA", "TUBE", [f"M{e + 1}" for e in range(T.N_ELEMENTS)])
    lines += group_block("GROUP_NO", "ENCASTR", [node_name(0), node_name(n_nodes - 1)])
    for k, node in enumerate(T.SUPPORT_NODES):
        lines += group_block("GROUP_NO", f"SUPP{k + 1}", [node_name(node)])
    lines += group_block("GROUP_NO", "MILIEU", [node_name(T.FORCE_NODE)])
    lines.append(" FIN")
    return "\n".join(lines) + "\n"


def main() -> None:
    output = Path(sys.argv[1]) if len(sys.argv) > 1 else DEFAULT_OUTPUT
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(tube_mesh_text())
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
