"""No keyword name of DYNA_VIBRA's catalogue under asterlite/dynamics/ (issue 28).

The dynamics room receives typed problems and parameter records (the
relations' ``*Parameters`` of ``asterlite.dynamics.laws``); the commands
read the keywords, and word the dynamics room's messages, which name the
problem's fields (``asterlite.errors.field``), with the keyword of each
field. Every keyword name of the catalogue (simple and factor keywords at
every level, in every block: COMPORTEMENT's relations included) is
collected, and every word of every line under ``asterlite/dynamics/``
(code, comments, docstrings, messages) is compared with them: a word equal
to one fails the test, unless it is listed below as a word of another
vocabulary, with the files where it is used in that meaning only.
``SCHEMA`` values ('NEWMARK', ...) and relation names ('FLAMBAGE', ...)
are values, not keyword names.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from asterlite.catalog.model import BLOC, FACT

ROOT = Path(__file__).resolve().parent.parent
DYNAMICS = ROOT / "asterlite" / "dynamics"
WORD = re.compile(r"\b[A-Z][A-Z0-9_]+\b")

# keyword names that are also words of another vocabulary: their meaning
# there, and the only files (below asterlite/dynamics/) using them so
OTHER_VOCABULARY = {
    "INST": (
        "the instant: the first column of the energy table code_aster names so, and "
        "the parameter of a function of time (NOM_PARA='INST')",
        {"energy.py", "physical/energy.py", "formula.py", "laws/rotor_fiss.py",
         "physical/imposed.py"},
    ),
    "DEPL": (
        "the name code_aster gives RELA_EFFO_DEPL's first archived internal variable",
        {"laws/rela_effo_depl.py"},
    ),
    "VITE": (
        "the name code_aster gives RELA_EFFO_VITE's first archived internal variable",
        {"laws/rela_effo_vite.py"},
    ),
    "FX": (
        "a force component: the name of DIS_ECRO_TRAC's archived axial force",
        {"laws/dis_ecro_trac.py"},
    ),
}  # fmt: skip


def catalogue_keywords() -> set[str]:
    from asterlite.catalogues.dyna_vibra import DYNA_VIBRA

    names: set[str] = set()

    def walk(level) -> None:
        for name, entry in level.entries.items():
            if isinstance(entry, BLOC):
                walk(entry)
                continue
            names.add(name)
            if isinstance(entry, FACT):
                walk(entry)

    walk(DYNA_VIBRA)
    return names


def keyword_words(names: set[str], folder: Path = DYNAMICS) -> dict[str, dict[str, list[int]]]:
    """{keyword: {file: [line, ...]}} of the words equal to a keyword name,
    on every line of every Python file below ``folder``."""
    found: dict[str, dict[str, list[int]]] = {}
    for path in sorted(folder.rglob("*.py")):
        where = path.relative_to(folder).as_posix()
        for number, line in enumerate(path.read_text().splitlines(), 1):
            for word in WORD.findall(line):
                if word in names:
                    found.setdefault(word, {}).setdefault(where, []).append(number)
    return found


def test_the_catalogue_names_the_relations_keywords():
    names = catalogue_keywords()
    # a sample from several levels: the command, SCHEMA_TEMPS, COMPORTEMENT and its relations
    assert {"MATR_MASS", "SCHEMA_TEMPS", "PAS_MAXI", "COMPORTEMENT", "RIGI_NOR"} <= names
    assert {"RIGI_K1", "UNSUR_K2", "FNOR_POST_FL", "DK_DPHI", "NOM_CMP", "GROUP_NO_D"} <= names
    assert set(OTHER_VOCABULARY) <= names  # each exception is a keyword name indeed


def test_no_keyword_name_under_dynamics():
    found = keyword_words(catalogue_keywords())
    leaked = {
        f"{name} at {where}:{','.join(map(str, lines))}"
        for name, files in found.items()
        for where, lines in files.items()
        if where not in OTHER_VOCABULARY.get(name, ("", set()))[1]
    }
    assert not leaked, "keyword names of DYNA_VIBRA under asterlite/dynamics/: " + "; ".join(
        sorted(leaked)
    )
    unused = {
        f"{name} in {where}"
        for name, (_, files) in OTHER_VOCABULARY.items()
        for where in files
        if where not in found.get(name, {})
    }
    assert not unused, f"no longer used there, remove from the list: {sorted(unused)}"


def test_the_scan_finds_a_keyword_name_wherever_it_stands(tmp_path):
    """A key, a default, a tuple item, a part of an f-string, a message, a
    docstring, a comment; a longer identifier or a lower-case word is not one."""
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "law.py").write_text(
        '"""The law of RIGI_NOR."""\n'
        'def f(occ):\n'
        '    k = occ.get("AMOR_NOR", 0.0)  # the DX_MAX stroke\n'
        '    print(f"{k}" "FNOR_CRIT must be > 0", VERI_PAS_FRACTION, rigi_nor)\n'
    )  # fmt: skip
    found = keyword_words(catalogue_keywords(), tmp_path)
    assert found == {
        "RIGI_NOR": {"sub/law.py": [1]},
        "AMOR_NOR": {"sub/law.py": [3]},
        "DX_MAX": {"sub/law.py": [3]},
        "FNOR_CRIT": {"sub/law.py": [4]},
    }


FIELD_CALL = re.compile(r"""\b(?:named|field)\(\s*["']([A-Za-z_][\w.]*)["']\s*\)""")


def test_every_field_a_message_names_has_its_keyword():
    """A message of dynamics/ names fields (``errors.field``); the commands
    word each with its keyword: the transient's vocabulary or a relation
    reader's words. A field missing from them would reach the user as a
    field name."""
    from asterlite.commands.dyna_vibra_relations import READERS
    from asterlite.commands.dyna_vibra_words import TRANSIENT

    known = set(TRANSIENT).union(*(reader.words for reader in READERS.values()))
    named = {
        f"{path.relative_to(DYNAMICS)}: {name}"
        for path in DYNAMICS.rglob("*.py")
        for name in FIELD_CALL.findall(path.read_text())
        if name not in known
    }
    assert not named, f"fields without a keyword: {sorted(named)}"
    assert (
        len(FIELD_CALL.findall((DYNAMICS / "integrate.py").read_text())) > 5
    )  # the scan sees them


def test_an_error_is_worded_with_the_keywords_of_its_fields():
    from asterlite.commands.dyna_vibra_words import TRANSIENT, transient_words

    from asterlite.errors import NumericalError, field, worded

    error = NumericalError(f"raise {field('options.dt_min')}", path=field("grid.step"))
    with pytest.raises(NumericalError) as raised, transient_words():
        raise error
    assert raised.value.message == "raise PAS_MINI" and raised.value.path == "INCREMENT/PAS"
    assert worded(f"{field('unknown.field')} x", TRANSIENT) == "unknown.field x"
    assert str(error) == "numerical error: grid.step: raise options.dt_min"
