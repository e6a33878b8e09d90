"""`asterlite check` on mutated copies of a corpus deck: each mistake is
reported with the deck line, the keyword path and, where one fits, a
"did you mean" suggestion."""

from __future__ import annotations

import pytest

from asterlite.runtime.runner import run_deck
from tests.conftest import CORPUS

DECK = CORPUS / "sdnd100a" / "sdnd100a.comm"

# (name, text to replace, replacement, fragments the message must contain)
MUTATIONS = [
    (
        "misspelled keyword",
        "RIGI_NOR=20.0",
        "RIGI_NORM=20.0",
        ["DYNA_VIBRA/COMPORTEMENT[1]/RIGI_NORM", "did you mean RIGI_NOR"],
    ),
    (
        "value outside into",
        'SCHEMA="DIFF_CENTRE"',
        'SCHEMA="DIFF_CENTRAL"',
        ["DYNA_VIBRA/SCHEMA_TEMPS[1]/SCHEMA", "DIFF_CENTRE"],
    ),
    (
        "wrong type",
        "PAS=0.0005",
        'PAS="0.0005"',
        ["DYNA_VIBRA/INCREMENT[1]/PAS", "real"],
    ),
    (
        "missing mandatory keyword",
        "    MATR_MASS=MASSEGEN,\n    MATR_RIGI=RIGIDGEN,",
        "    MATR_RIGI=RIGIDGEN,",
        ["DYNA_VIBRA", "MATR_MASS"],
    ),
    (
        "violated rule",
        'DDL_IMPO=_F(TOUT="OUI", DZ=0.0)',
        'DDL_IMPO=_F(TOUT="OUI")',
        ["AFFE_CHAR_MECA/DDL_IMPO[1]", "at least one of", "AU_MOINS_UN"],
    ),
    (
        "wrong concept type",
        "    MATR_MASS=MASSEGEN,\n    MATR_RIGI=RIGIDGEN,",
        "    MATR_MASS=MATRMASS,\n    MATR_RIGI=RIGIDGEN,",
        ["DYNA_VIBRA/MATR_MASS", "matr_asse_gene_r"],
    ),
    (
        "unknown concept name",
        "OBSTACLE=PLANZ,",
        "OBSTACLE=PLANX,",
        ["PLANX", "not defined"],
    ),
    (
        "misspelled command",
        "DYNAMODA = DYNA_VIBRA(",
        "DYNAMODA = DYNA_VIBR(",
        ["DYNA_VIBR", "not defined"],
    ),
]


@pytest.fixture
def deck_text(tmp_path):
    if not DECK.exists():
        pytest.skip("../shared/aster-corpus is not available")
    # the mesh beside the copied deck, as `asterlite run` would find it
    mesh = DECK.with_suffix(".mail")
    (tmp_path / mesh.name).write_bytes(mesh.read_bytes())
    return DECK.read_text()


def test_unmutated_deck_checks(deck_text, tmp_path):
    path = tmp_path / "sdnd100a.comm"
    path.write_text(deck_text)
    report = run_deck(path, check_only=True)
    assert report.status == "CHECKED", report.message


@pytest.mark.parametrize("name, old, new, fragments", MUTATIONS, ids=[m[0] for m in MUTATIONS])
def test_mutation_is_reported(deck_text, tmp_path, name, old, new, fragments):
    assert deck_text.count(old) == 1, f"mutation anchor not unique: {old!r}"
    mutated = deck_text.replace(old, new)
    path = tmp_path / "mutated.comm"
    path.write_text(mutated)
    report = run_deck(path, check_only=True)
    assert report.exit_code == 2
    # the line of the mutation (or of the call holding it) appears in the message
    changed_line = mutated[: mutated.index(new)].count("\n") + 1
    assert "mutated.comm:" in report.message
    line_numbers = [
        int(part.split(":")[1])
        for part in report.message.split()
        if part.startswith(str(path)) and part.count(":") >= 2
    ]
    assert line_numbers, report.message
    assert any(0 <= changed_line - n <= 40 for n in line_numbers), report.message
    for fragment in fragments:
        assert fragment in report.message, f"{fragment!r} not in:\n{report.message}"
