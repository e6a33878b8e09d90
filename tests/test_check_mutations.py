"""`asterlite check` on mutated copies of every deck of ../shared/aster-corpus
(issue 27, acceptance): each copy carries one mistake, and check must call
the deck INVALID with a finding at the mutated line.

The mistakes, one per copy, each on a command call at the top level of the
deck's first command file (a statement check always reaches):

- a misspelt keyword (two letters swapped, or one dropped): an unknown
  keyword at the keyword's line;
- a misspelt command: an undefined name at the call's line;
- a text value outside a closed list (``into``): at the keyword's line;
- a mandatory keyword left out: at the line of the call or ``_F(`` that
  lacks it.

Where to mutate is read from Python's syntax tree of the deck and from the
language data of the deck's version (which keywords are mandatory, which
have an ``into``); the first fitting place of the deck is taken. The sweep
over every deck is slow-marked; a few decks run in the fast suite. The
older hand-made mutations of sdnd100a (a message's wording, a did-you-mean)
are kept below.
"""

from __future__ import annotations

import ast
import shutil
from pathlib import Path

import pytest

from asterlite.catalog.language.model import language
from asterlite.runtime.check_deck import check_deck
from asterlite.runtime.runner import run_deck
from tests.conftest import CORPUS, corpus_decks

KINDS = ("keyword", "command", "into", "mandatory")
FAST_DECKS = ("sdnd100a", "sdld103a", "sdnl111a", "sdll126b")


# ----------------------------------------------------------------- mutations


def command_file(folder: Path) -> Path:
    export = next(folder.glob("*.export"))
    for line in export.read_text().splitlines():
        fields = line.split()
        if len(fields) >= 3 and fields[:2] == ["F", "comm"]:
            return folder / Path(fields[2]).name
    return export.with_suffix(".comm")


def top_level_calls(tree: ast.Module, lang) -> list[ast.Call]:
    """Command calls that are whole top-level statements (``X = CMD(...)``, ``CMD(...)``)."""
    calls = []
    for statement in tree.body:
        value = statement.value if isinstance(statement, (ast.Assign, ast.Expr)) else None
        if (
            isinstance(value, ast.Call)
            and isinstance(value.func, ast.Name)
            and lang.command(value.func.id) is not None
            and value.keywords
            and all(k.arg is not None for k in value.keywords)
        ):
            calls.append(value)
    return calls


def levels(call: ast.Call, spec: dict):
    """(keywords, spec, node holding them) for the call and each ``_F(...)``
    given to one of its factor keywords (a tuple of them too)."""
    yield call.keywords, spec, call
    for keyword in call.keywords:
        entry = find_entries(spec, keyword.arg)
        facts = [e for e in entry if e["k"] == "F"]
        if len(facts) != 1:
            continue
        items = (
            keyword.value.elts
            if isinstance(keyword.value, (ast.Tuple, ast.List))
            else [keyword.value]
        )
        for item in items:
            if (
                isinstance(item, ast.Call)
                and isinstance(item.func, ast.Name)
                and item.func.id == "_F"
                and all(k.arg is not None for k in item.keywords)
            ):
                yield item.keywords, facts[0], item


def find_entries(spec: dict, key: str) -> list[dict]:
    """Every definition of ``key`` at this level, its blocks' included."""
    found = []
    for name, entry in spec.get("entries", {}).items():
        if entry["k"] == "B":
            found += find_entries(entry, key)
        elif name == key:
            found.append(entry)
    return found


def vocabulary(spec: dict) -> set[str]:
    names = set()
    for name, entry in spec.get("entries", {}).items():
        names |= vocabulary(entry)
        if entry["k"] != "B":
            names.add(name)
    return names


def misspell(name: str, taken) -> str:
    """A typo of ``name`` not in ``taken``: two letters swapped, else one dropped."""
    for i in range(len(name) - 1):
        swapped = name[:i] + name[i + 1] + name[i] + name[i + 2 :]
        if swapped != name and swapped not in taken and swapped.isidentifier():
            return swapped
    for i in range(len(name)):
        dropped = name[:i] + name[i + 1 :]
        if dropped not in taken and dropped.isidentifier():
            return dropped
    return name + "X"


def absolute(lines: list[str], line: int, column: int) -> int:
    """Text offset of ast's (line, UTF-8 byte column)."""
    head = lines[line - 1].encode()[:column].decode()
    return sum(len(x) for x in lines[: line - 1]) + len(head)


def replace(text: str, node, new: str, *, start=None, end=None) -> str:
    lines = text.splitlines(keepends=True)
    begin = absolute(lines, *(start or (node.lineno, node.col_offset)))
    stop = absolute(lines, *(end or (node.end_lineno, node.end_col_offset)))
    return text[:begin] + new + text[stop:]


def mutation(text: str, lang, kind: str):
    """(mutated text, line the finding must be at, what was done), or None."""
    tree = ast.parse(text)
    commands = lang.command_names
    for call in top_level_calls(tree, lang):
        spec = lang.command(call.func.id)
        legacy = set(spec.get("legacy", ()))
        if kind == "command":
            name = misspell(call.func.id, commands)
            return replace(text, call.func, name), call.lineno, f"{call.func.id} -> {name}"
        for keywords, level, holder in levels(call, spec):
            for keyword in keywords:
                entries = find_entries(level, keyword.arg)
                if not entries or keyword.arg in legacy:
                    continue
                if kind == "keyword":
                    taken = vocabulary(spec) | legacy
                    name = misspell(keyword.arg, taken)
                    end = (keyword.lineno, keyword.col_offset + len(keyword.arg))
                    mutated = replace(text, keyword, name, end=end)
                    return mutated, keyword.lineno, f"{keyword.arg} -> {name}"
                if kind == "into":
                    value = keyword.value
                    if not (isinstance(value, ast.Constant) and isinstance(value.value, str)):
                        continue
                    if not all(e["k"] == "S" and e.get("into") for e in entries):
                        continue
                    choices = {c for e in entries for c in e["into"] if isinstance(c, str)}
                    wrong = value.value + "Z"
                    if value.value not in choices or wrong in choices:
                        continue
                    quoted = repr(wrong)
                    return (
                        replace(text, value, quoted),
                        keyword.lineno,
                        f"{value.value!r} -> {quoted}",
                    )
                if kind == "mandatory":
                    direct = level.get("entries", {}).get(keyword.arg)
                    if direct is None or direct.get("statut") != "o" or direct["k"] == "B":
                        continue
                    return (
                        remove_keyword(text, keyword),
                        holder.lineno,
                        f"{keyword.arg} removed",
                    )
    return None


def remove_keyword(text: str, keyword: ast.keyword) -> str:
    """``KEY=value`` and the comma after it taken out of the text."""
    lines = text.splitlines(keepends=True)
    begin = absolute(lines, keyword.lineno, keyword.col_offset)
    stop = absolute(lines, keyword.value.end_lineno, keyword.value.end_col_offset)
    rest = text[stop:]
    stripped = rest.lstrip(" \t\n\r")
    if stripped.startswith(","):
        stop += len(rest) - len(stripped) + 1
    return text[:begin] + text[stop:]


# --------------------------------------------------------------------- tests


def deck_cases(decks) -> list:
    return [pytest.param(deck, kind, id=f"{deck}-{kind}") for deck in decks for kind in KINDS]


def mutated_check(deck: str, kind: str, tmp_path: Path):
    folder = CORPUS / deck
    if not folder.is_dir():
        pytest.skip(f"../shared/aster-corpus/{deck} is not available")
    copy = tmp_path / deck
    shutil.copytree(folder, copy)
    original = check_deck(copy)
    assert original.status != "ERROR", original.message
    lang = language(original.version)
    comm = command_file(copy)
    text = comm.read_text()
    found = mutation(text, lang, kind)
    if found is None:
        pytest.skip(f"{deck}: no top-level call fits a {kind} mutation")
    mutated, line, what = found
    comm.write_text(mutated)
    result = check_deck(copy)
    before = {(f.line, f.keyword, f.message) for f in original.findings}
    invalid = [
        f
        for f in result.findings
        if f.kind == "invalid" and (f.line, f.keyword, f.message) not in before
    ]
    report = f"{deck} {kind} ({what}, line {line}):\n" + "\n".join(
        f.text() for f in result.findings
    )
    assert result.status == "INVALID", report + f"\n{result.message}"
    assert any(Path(f.file or "").name == comm.name and f.line == line for f in invalid), report


@pytest.mark.corpus
@pytest.mark.parametrize("deck, kind", deck_cases(FAST_DECKS))
def test_mutation_found_fast(deck, kind, tmp_path):
    mutated_check(deck, kind, tmp_path)


@pytest.mark.slow
@pytest.mark.corpus
@pytest.mark.parametrize("deck, kind", deck_cases(d for d in corpus_decks() if d not in FAST_DECKS))
def test_mutation_found_every_deck(deck, kind, tmp_path):
    mutated_check(deck, kind, tmp_path)


# ----------------------------------------------- hand-made mutations of sdnd100a

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
