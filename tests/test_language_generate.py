"""The language data generator: read a code_aster-like catalogue tree (a
fixture written here, not code_aster's text) without executing it, and
write the same bytes every time."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest

from asterlite.catalog.language.generate import dumps, generate, open_source
from asterlite.catalog.language.model import Language

FILES = {
    "Cata/Language/DataStructure.py": """
class DataStructure:
    pass
ASSD = DataStructure
class maillage_sdaster(ASSD):
    pass
class maillage_p(maillage_sdaster):
    pass
class fonction_sdaster(ASSD):
    pass
class fonction_c(ASSD):
    pass
class GEOM:
    pass
class grma(GEOM):
    pass
def UnitType(filter=None):
    return None
""",
    "Cata/Language/Syntax.py": """
AU_MOINS_UN = AtLeastOne
UN_PARMI = ExactlyOne
EXCLUS = AtMostOne
""",
    "Cata/Commons/__init__.py": "from .c_solver import C_SOLVER\n",
    "Cata/Commons/c_solver.py": """
from ..Language.Syntax import *
def C_SOLVER(command):
    methods = ["LDLT", "MUMPS"]
    if command.startswith("THING"):
        methods.append("GCPC")
    return FACT(statut="d", METHODE=SIMP(statut="f", typ="TXM", defaut="MUMPS",
                                         into=tuple(methods)))
""",
    "Cata/Commands/__init__.py": "import glob  # code_aster imports every module here\n",
    "Cata/Commands/defi_thing.py": '''
from ..Commons import *
from ..Language.DataStructure import *
from ..Language.Syntax import *

def defi_thing_prod(VALE_C, **args):
    if args.get("__all__"):
        return (fonction_sdaster, fonction_c)
    if VALE_C is not None:
        return fonction_c
    return fonction_sdaster

def compat_syntax(keywords):
    keywords["VALE"] = keywords.pop("VALEUR", None)

DEFI_THING = OPER(
    nom="DEFI_THING",
    op=99,
    sd_prod=defi_thing_prod,
    fr=tr("help text that must not be copied"),
    reentrant="f:MAILLAGE",
    compat_syntax=compat_syntax,
    regles=(UN_PARMI("VALE", "VALE_C"),),
    MAILLAGE=SIMP(statut="o", typ=maillage_sdaster),
    TYPE=SIMP(statut="f", typ="TXM", defaut="A", into=("A", "B")),
    VALE=SIMP(statut="f", typ="R", max="**", val_min=0.0),
    VALE_C=SIMP(statut="f", typ="C", max="**"),
    UNITE=SIMP(statut="f", typ=UnitType(), defaut=8),
    b_b=BLOC(
        condition="""equal_to("TYPE", 'B') and not exists("VALE_C")""",
        GROUP_MA=SIMP(statut="o", typ=grma, validators=NoRepeat(), max="**"),
    ),
    SOLVEUR=C_SOLVER("THING"),
)
''',
    "CodeCommands/__init__.py": "from .defi_thing import DEFI_THING, THING_AGAIN\n",
    "CodeCommands/defi_thing.py": """
class Thing(ExecuteCommand):
    command_name = "DEFI_THING"
DEFI_THING = Thing.run
THING_AGAIN = partial(Thing.run, caller="THING_AGAIN")
""",
}


@pytest.fixture
def tree(tmp_path) -> Path:
    root = tmp_path / "repo"
    for path, text in FILES.items():
        file = root / "code_aster" / path
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(text)
    return root


def test_generation_is_deterministic_and_holds_facts_only(tree):
    first, problems = generate(open_source(tree), 99)
    second, _ = generate(open_source(tree), 99)
    assert dumps(first) == dumps(second)
    assert problems == []
    text = dumps(first)
    assert "help text" not in text and "keywords.pop" not in text
    data = json.loads(text)
    thing = data["commands"]["DEFI_THING"]
    assert thing["reentrant"] == "f:MAILLAGE"
    assert thing["rules"] == [["UN_PARMI", "VALE", "VALE_C"]]
    assert thing["entries"]["VALE"] == {"k": "S", "typ": ["R"], "max": "**", "val_min": 0.0}
    assert thing["entries"]["UNITE"]["typ"] == ["UNITE"]
    # the shared piece was evaluated for this command (a branch on its name)
    solver = thing["entries"]["SOLVEUR"]
    assert solver["entries"]["METHODE"]["into"] == ["LDLT", "MUMPS", "GCPC"]
    # the block condition as an expression tree, not as code
    assert thing["entries"]["b_b"]["condition"] == [
        "and",
        ["call", "equal_to", ["c", "TYPE"], ["c", "B"]],
        ["not", ["call", "exists", ["c", "VALE_C"]]],
    ]
    # sd_prod as a decision table, its type set from the __all__ request
    sd_prod = thing["sd_prod"]
    assert sd_prod["types"] == ["fonction_c", "fonction_sdaster"]
    assert sd_prod["table"][0][1] == ["t", "fonction_c"]
    # keywords the compat_syntax hook reads (old spellings code_aster converts)
    assert "VALEUR" in thing["legacy"]
    # a deck name that runs another command's catalogue
    assert data["commands"]["THING_AGAIN"] == {"alias": "DEFI_THING"}
    # types with their bases; ASSD is an alias of the root, written assd
    assert data["header"]["types"]["maillage_p"] == ["maillage_sdaster"]
    assert data["header"]["types"]["maillage_sdaster"] == ["assd"]


def test_the_data_reads_back_one_command_at_a_time(tree):
    data, _ = generate(open_source(tree), 99)
    language = Language(99, dumps(data))
    assert language.command_names == {"DEFI_THING", "THING_AGAIN"}
    assert language.command("THING_AGAIN") is language.command("DEFI_THING")
    assert language.is_subtype("maillage_p", "maillage_sdaster")
    assert not language.is_subtype("maillage_sdaster", "maillage_p")


def test_a_git_directory_reads_as_its_checkout(tree, tmp_path):
    def git(*args):
        subprocess.run(["git", *args], cwd=tree, check=True, capture_output=True)

    git("init", "-q")
    git("add", ".")
    git("-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "fixture")
    from_git, _ = generate(open_source(tree / ".git", "HEAD"), 99)
    from_folder, _ = generate(open_source(tree), 99)
    assert from_git["commands"] == from_folder["commands"]
    assert len(from_git["header"]["source"]["commit"]) == 40


def test_catalogue_code_is_never_executed(tree):
    # a catalogue module calling something outside the reader's subset is
    # reported, and nothing runs
    bad = tree / "code_aster" / "Cata" / "Commands" / "bad.py"
    bad.write_text("import os\nos.system('touch /tmp/asterlite-never')\nBAD = OPER(nom='BAD')\n")
    data, problems = generate(open_source(tree), 99)
    assert "BAD" not in data["commands"]
    assert any("bad.py" in p for p in problems)
    assert not Path("/tmp/asterlite-never").exists()
