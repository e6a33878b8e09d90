"""Fuzzing the run as a whole (docs/safety.md): decks generated from a small
grammar of hostile statements, and damaged meshes. Each run must end with a
normal status or a located error (exit status 0 or 2), within bounded time,
and leave in its output folder only what it listed as its own.

The CI budget is small (a few dozen decks); ASTERLITE_FUZZ_EXAMPLES raises
it (docs/safety.md gives the longer run and what it checked).
"""

from __future__ import annotations

import json
import os
import random
import tempfile
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from asterlite.io.aster_mesh import AsterMeshError, parse_aster_mesh
from asterlite.runtime.runner import run_deck
from tests.conftest import CORPUS

EXAMPLES = int(os.environ.get("ASTERLITE_FUZZ_EXAMPLES", "25"))
FUZZ = settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)

# ------------------------------------------------------------------ grammar

SIZES = ["0", "3", "150", "10**4", "10**7", "10**12", "-1"]
FILE_NAMES = [
    "table.txt",
    ".git",
    "deck.comm",
    "..",
    ".",
    "message.log",
    "summary.json",
    ".asterlite.lock",
    ".asterlite-running",
    "incomplete",
    "previous-1",
    "sub/dir",
    "/etc/passwd",
    "fort.8",
]
atoms = st.sampled_from(
    ["a", "b", "c", "t", "1", "2.5", "10**400", "'x'", "'{0.rows}'", "'%s'", "None", "T", "_F"]
    + [f"np.zeros({n})" for n in SIZES[:4]]
    + [f"range({n})" for n in SIZES]
)


def compound(inner):
    binary = st.tuples(inner, st.sampled_from("+ - * / // % **".split()), inner).map(
        lambda p: f"({p[0]} {p[1]} {p[2]})"
    )
    calls = st.tuples(
        st.sampled_from(
            [
                "len({})",
                "str({})",
                "repr({})",
                "set([{}])",
                "dict([({}, 1)])",
                "tuple([{}])",
                "sorted([{}])",
                "'{{}}'.format({})",
                "'%s' % ({},)",
                "np.concatenate([np.zeros(10)] * {})",
                "np.diff(np.zeros(10), n={})",
                "lcm({}, 10**300)",
                "({},)",
                "[{}]",
                "{{{}}}",
                "{{{}: 1}}",
                "list(zip([{}]))",
                "np.array({})",
                "np.linalg.inv(np.ones(({0}, {0})))",
            ]
        ),
        inner,
    ).map(lambda p: p[0].format(p[1]) if "{0}" not in p[0] else p[0].format(p[1]))
    return binary | calls


expressions = st.recursive(atoms, compound, max_leaves=6)
names = st.sampled_from(["a", "b", "c", "t"])
statements = st.one_of(
    st.tuples(names, expressions).map(lambda p: f"{p[0]} = {p[1]}"),
    expressions.map(lambda e: f"print({e})"),
    st.tuples(names, st.sampled_from(SIZES)).map(
        lambda p: f"for i in range({p[1]}):\n    {p[0]} = ({p[0]},)"
    ),
    st.sampled_from(FILE_NAMES).map(
        lambda n: f"DEFI_FICHIER(UNITE=31, FICHIER={n!r})\nIMPR_TABLE(UNITE=31, TABLE=T)"
    ),
    st.sampled_from(SIZES).map(lambda n: f"for i in range({n}):\n    print('y' * 100000)"),
    st.just("x = 0\nwhile True:\n    x = x + 1"),
    st.just("IMPR_TABLE(UNITE=8, TABLE=T)"),
)
decks = st.lists(statements, min_size=1, max_size=6).map(
    lambda body: (
        "DEBUT()\nimport numpy as np\n"
        "T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))\n"
        "a = 1\nb = 'x'\nc = (1, 2)\nt = ()\n" + "\n".join(body) + "\nFIN()\n"
    )
)

SENTINELS = {".git/HEAD": "ref: refs/heads/main\n", "deck.comm": "DEBUT()\nFIN()\n"}


def plant_sentinels(folder: Path) -> None:
    for name, text in SENTINELS.items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text(text)


@FUZZ
@given(text=decks)
def test_generated_decks_end_well_and_leave_only_their_files(text):
    with tempfile.TemporaryDirectory(prefix="asterlite-fuzz-") as scratch:
        scratch = Path(scratch)
        deck = scratch / "fuzz.comm"
        deck.write_text(text)
        out = scratch / "out"
        plant_sentinels(out)
        start = time.monotonic()
        report = run_deck(deck, out, time_limit=1.0, output_limit=2.0)
        assert time.monotonic() - start < 60
        assert report.status in ("DONE", "PASS", "ERROR", "UNSUPPORTED"), report.message
        assert report.exit_code in (0, 2)
        if report.status == "ERROR":
            assert "internal error" not in report.message, report.message + report.traceback
        for name, content in SENTINELS.items():
            assert (out / name).read_text() == content
        data = json.loads((out / "summary.json").read_text())
        assert data["status"] == report.status
        allowed = set(data["output"]["files"]) | {".git", "deck.comm"}
        assert set(os.listdir(out)) <= allowed
        sizes = sum(p.stat().st_size for p in out.rglob("*") if p.is_file())
        assert sizes < 3_000_000


# ------------------------------------------------------------------- meshes

MESH = """TITRE
fuzz
FINSF
COOR_3D
N1 0.0 0.0 0.0
N2 1.0 0.0 0.0
N3 1.0 1.0 0.0
FINSF
SEG2
M1 N1 N2
M2 N2 N3
FINSF
GROUP_NO
G1 N1 N3
FINSF
FIN
"""
TOKENS = ["N9", "1.E+999", "nan", "-", "SEG2", "FINSF", "GROUP_MA", "%", "M1", "", "\n", "0" * 50]


@FUZZ
@given(edits=st.lists(st.tuples(st.integers(0, len(MESH)), st.sampled_from(TOKENS)), max_size=6))
def test_mutated_aster_meshes_give_mesh_errors(edits):
    text = MESH
    for position, token in edits:
        text = text[:position] + token + text[position + 1 :]
    try:
        parse_aster_mesh(text, "fuzz.mail")
    except AsterMeshError:
        pass


MED = CORPUS / "forma02d" / "forma02d.mmed"


@pytest.mark.skipif(not MED.exists(), reason="corpus absent")
@settings(max_examples=max(4, EXAMPLES // 4), deadline=None, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1), count=st.integers(1, 12))
def test_mutated_med_meshes_never_crash_the_run(seed, count):
    from asterlite.io.med_mesh import MedMeshError, read_med_mesh

    rng = random.Random(seed)
    data = bytearray(MED.read_bytes())
    for _ in range(count):
        data[rng.randrange(len(data))] = rng.randrange(256)
    with tempfile.TemporaryDirectory(prefix="asterlite-fuzz-") as scratch:
        path = Path(scratch) / "m.med"
        path.write_bytes(bytes(data))
        try:
            read_med_mesh(path)
        except MedMeshError as error:
            assert str(path) in str(error)
