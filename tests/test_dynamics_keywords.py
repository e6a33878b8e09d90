"""No keyword name of DYNA_VIBRA's catalogue under asterlite/dynamics/ (issue 28).

The dynamics room receives typed problems and parameter records (the
relations' ``*Parameters`` of ``asterlite.dynamics.laws``); the commands
read the keywords. Every keyword name of the catalogue (simple and factor
keywords at every level, in every block: COMPORTEMENT's relations
included) is collected, and a Python string literal under
``asterlite/dynamics/`` whose whole value is one of them fails the test,
unless the name is listed below as a word of another vocabulary the
dynamics room uses with its own meaning. Keyword names inside longer
strings (messages, docstrings) are prose, not keyword reading: they are not
looked for. ``SCHEMA`` values ('NEWMARK', ...) and RELATION values
('FLAMBAGE', ...) are values, not keyword names.
"""

from __future__ import annotations

import ast
from pathlib import Path

from asterlite.catalog.model import BLOC, FACT

ROOT = Path(__file__).resolve().parent.parent
DYNAMICS = ROOT / "asterlite" / "dynamics"

# keyword names that are also words of another vocabulary, with that meaning
OTHER_VOCABULARY = {
    "INST": "the instant: the first column of the PARA_CALC energy table and the "
    "parameter of a function of time (NOM_PARA='INST')",
    "DEPL": "the name of RELA_EFFO_DEPL's first archived internal variable (the displacement)",
    "VITE": "the name of RELA_EFFO_VITE's first archived internal variable (the velocity)",
    "FX": "a force component: the name of DIS_ECRO_TRAC's archived axial force",
}


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


def keyword_literals(names: set[str], folder: Path = DYNAMICS) -> dict[str, list[str]]:
    """{keyword: ['file:line', ...]} of the string literals equal to a keyword."""
    found: dict[str, list[str]] = {}
    for path in sorted(folder.rglob("*.py")):
        tree = ast.parse(path.read_text(), filename=str(path))
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                if node.value in names:
                    where = f"{path.relative_to(folder)}:{node.lineno}"
                    found.setdefault(node.value, []).append(where)
    return found


def test_the_catalogue_names_the_relations_keywords():
    names = catalogue_keywords()
    # a sample from several levels: the command, SCHEMA_TEMPS, COMPORTEMENT and its relations
    assert {"MATR_MASS", "SCHEMA_TEMPS", "PAS_MAXI", "COMPORTEMENT", "RIGI_NOR"} <= names
    assert {"RIGI_K1", "UNSUR_K2", "FNOR_POST_FL", "DK_DPHI", "NOM_CMP", "GROUP_NO_D"} <= names
    assert set(OTHER_VOCABULARY) <= names  # each exception is a keyword name indeed


def test_no_keyword_name_under_dynamics():
    found = keyword_literals(catalogue_keywords())
    leaked = {name: places for name, places in found.items() if name not in OTHER_VOCABULARY}
    assert not leaked, "keyword names of DYNA_VIBRA under asterlite/dynamics/: " + "; ".join(
        f"{name} at {', '.join(places)}" for name, places in sorted(leaked.items())
    )
    unused = set(OTHER_VOCABULARY) - set(found)
    assert not unused, f"no longer used under asterlite/dynamics/, remove from the list: {unused}"


def test_the_scan_finds_a_keyword_literal_wherever_it_stands(tmp_path):
    """A key, a default, a tuple item, a part of an f-string; not prose."""
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "law.py").write_text(
        'def f(occ):\n'
        '    k = occ.get("RIGI_NOR", 0.0)\n'
        '    for key in ("AMOR_NOR", "x"):\n'
        '        print(f"{key}" "DX_MAX", "RIGI_NOR must be > 0")\n'
    )  # fmt: skip
    found = keyword_literals(catalogue_keywords(), tmp_path)
    assert found == {
        "RIGI_NOR": ["sub/law.py:2"],
        "AMOR_NOR": ["sub/law.py:3"],
        "DX_MAX": ["sub/law.py:4"],
    }
