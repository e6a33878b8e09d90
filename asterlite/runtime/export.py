"""Read a code_aster ``.export`` file: which deck files run, which files map
to which logical units.

A line ``F <type> <path> D <unit>`` declares an input (data) file; ``R``
lines declare results (asterlite writes results in its output folder, so
they are recorded but not used); ``P`` lines are run parameters. A bare
``.comm`` gets a synthetic export: the deck itself, a sibling mesh on unit
20 and any sibling ``.comN`` continuation files.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from asterlite.errors import AsterliteError, Location

MESH_UNIT = 20
MESH_SUFFIXES = (".mail", ".mmed", ".med")


@dataclass
class RunDescription:
    """What to run: deck files in order, input units, helper Python modules."""

    name: str
    deck_files: list[Path]
    units: dict[int, Path] = field(default_factory=dict)
    helper_modules: dict[str, Path] = field(default_factory=dict)  # module name -> .py file
    parameters: dict[str, str] = field(default_factory=dict)
    source: Path | None = None


class ExportError(AsterliteError):
    kind = "export error"


def read_export(path: Path) -> RunDescription:
    """Parse an ``.export`` file; paths are relative to its folder."""
    folder = path.parent
    run = RunDescription(name=path.stem, deck_files=[], source=path)
    text = path.read_text(encoding="utf-8", errors="replace")
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        fields = line.split()
        where = Location(str(path), number, 1, raw)
        if fields[0] == "P":
            run.parameters[fields[1]] = " ".join(fields[2:]) if len(fields) > 2 else ""
            continue
        if fields[0] not in ("F", "R"):
            raise ExportError(f"unrecognised line kind {fields[0]!r} (expected F, R or P)", where)
        if len(fields) < 5:
            raise ExportError("expected 'F <type> <path> D|R <unit>'", where)
        kind, file_type, name, direction, unit_text = fields[:5]
        if kind == "R" or "D" not in direction:
            continue  # results: asterlite writes into its own output folder
        file_path = (folder / name).resolve()
        if not file_path.exists():
            raise ExportError(f"file {name} named by the export does not exist", where)
        try:
            unit = int(unit_text)
        except ValueError:
            raise ExportError(f"logical unit {unit_text!r} is not an integer", where) from None
        if file_type == "comm":
            run.deck_files.append(file_path)
        elif file_type == "nom" or (file_path.suffix == ".py" and unit == 0):
            run.helper_modules[file_path.stem] = file_path
        else:
            run.units[unit] = file_path
    if not run.deck_files:
        raise ExportError(
            "the export names no deck file ('F comm ... D 1')", Location(str(path), 1)
        )
    return run


def describe_bare_deck(path: Path) -> RunDescription:
    """A run description for a ``.comm`` given without an export."""
    folder = path.parent
    run = RunDescription(name=path.stem, deck_files=[path.resolve()])
    continuation = sorted(folder.glob(f"{path.stem}.com[0-9]"))
    run.deck_files += [p.resolve() for p in continuation]
    for suffix in MESH_SUFFIXES:
        own = sorted(folder.glob(f"{path.stem}{suffix}"))
        candidates = own or sorted(folder.glob(f"*{suffix}"))
        if candidates:
            run.units[MESH_UNIT] = candidates[0].resolve()
            break
    for helper in folder.glob("*.py"):
        run.helper_modules[helper.stem] = helper.resolve()
    return run


def describe_run(path: Path) -> RunDescription:
    """Run description for a deck path: an ``.export`` or a bare deck file."""
    if not path.exists():
        raise ExportError(f"no such file: {path}")
    if path.suffix == ".export":
        return read_export(path)
    return describe_bare_deck(path)
