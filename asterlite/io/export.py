"""Read a code_aster ``.export`` file: which deck files run, which files map
to which logical units.

A line ``F <type> <path> D <unit>`` declares an input (data) file; a line
``R <type> <path> R <unit>`` a result to keep: what the deck writes on that
unit is copied to the path when the run completes (asterlite writes every
result into its own output folder first). ``P`` lines are run parameters;
asterlite enforces two of them as code_aster does: ``time_limit`` (seconds
for the whole run) and ``memory_limit`` (megabytes the run may allocate
beyond what the process held when it started, as code_aster adds its
start-up footprint to the limit), and runs with ``ncpus`` threads
(:mod:`asterlite.runtime.threads`). A bare ``.comm`` gets a synthetic export:
the deck itself, a sibling mesh on unit 20 and any sibling ``.comN``
continuation files.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from asterlite.errors import AsterliteError, Location, UnquotedLocation
from asterlite.io.input_files import file_kind, read_deck_text
from asterlite.io.non_finite import NonFiniteNumber, finite_float

MESH_UNIT = 20
MESH_SUFFIXES = (".mail", ".mmed", ".med")


@dataclass(frozen=True)
class ResultFile:
    """An ``R`` line: the file the deck writes on ``unit``, kept at ``path``."""

    file_type: str
    path: Path
    unit: int
    location: Location | None = None


@dataclass
class RunDescription:
    """What to run: deck files in order, input units, helper Python modules."""

    name: str
    deck_files: list[Path]
    units: dict[int, Path] = field(default_factory=dict)
    helper_modules: dict[str, Path] = field(default_factory=dict)  # module name -> .py file
    parameters: dict[str, str] = field(default_factory=dict)
    # A lines: code_aster's own command-line arguments (``A args --max_base=100``):
    # its database, echo and syntax-check settings, which do not change results
    arguments: dict[str, str] = field(default_factory=dict)
    source: Path | None = None
    results: list[ResultFile] = field(default_factory=list)  # R lines, in order
    time_limit: float | None = None  # seconds (P time_limit)
    memory_limit: float | None = None  # megabytes (P memory_limit)
    threads: int = 1  # P ncpus: threads of the run's numerical libraries
    # why a unit has no file, said when the deck reads it: where a bare deck's
    # mesh was looked for, or the meshes it could not choose between
    unmapped: dict[int, str] = field(default_factory=dict)


class ExportError(AsterliteError):
    kind = "export error"


def read_export(path: Path) -> RunDescription:
    """Parse an ``.export`` file; paths are relative to its folder."""
    folder = path.parent
    run = RunDescription(name=path.stem, deck_files=[], source=path)
    recognised = False  # no line quoted before a first F, R or P line
    text = read_deck_text(path, "export file")
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        fields = line.split()
        if not recognised and fields[0] not in ("F", "R", "P", "A"):
            # not an export (a private file linked as one?): where, never what
            where = UnquotedLocation(str(path), number, 1, reason=NOT_AN_EXPORT)
            raise ExportError(NOT_AN_EXPORT, where)
        recognised = True
        where = Location(str(path), number, 1, raw)
        if fields[0] == "P":
            if len(fields) < 2:
                raise ExportError("expected 'P <name> <value>'", where)
            run.parameters[fields[1]] = " ".join(fields[2:]) if len(fields) > 2 else ""
            if fields[1] in LIMITS:
                setattr(run, fields[1], _limit(fields, where))
            elif fields[1] == "ncpus":
                run.threads = _threads(fields, where)
            continue
        if fields[0] == "A":
            if len(fields) < 2:
                raise ExportError("expected 'A <name> <value>'", where)
            run.arguments[fields[1]] = " ".join(fields[2:])
            continue
        if fields[0] not in ("F", "R"):
            raise ExportError(
                f"unrecognised line kind {fields[0]!r} (expected F, R, P or A)", where
            )
        if len(fields) < 5:
            raise ExportError("expected 'F <type> <path> D|R <unit>'", where)
        kind, file_type, name, direction, unit_text = fields[:5]
        try:
            unit = int(unit_text)
        except ValueError:
            raise ExportError(f"logical unit {unit_text!r} is not an integer", where) from None
        if "R" in direction:  # absolute, symlinks not followed (the copy replaces a link)
            path_kept = Path(os.path.abspath(folder / name))
            run.results.append(ResultFile(file_type, path_kept, unit, where))
        if kind == "R" or "D" not in direction:
            continue  # an output only: nothing to read
        file_path = (folder / name).resolve()
        if not file_path.exists():
            raise ExportError(f"file {name} named by the export does not exist", where)
        if file_type in ("comm", "nom") and not file_path.is_file():  # read as text
            raise ExportError(f"{name} named by the export is not a file", where)
        if not (file_path.is_file() or file_path.is_dir()):  # a FIFO would block the run
            kind = file_kind(file_path.stat().st_mode)
            raise ExportError(f"{name} named by the export is {kind}: refused", where)
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


NOT_AN_EXPORT = "not an export file: F, R, P or A lines were expected; the line is not shown"
# P lines asterlite enforces, both positive numbers (seconds, megabytes)
LIMITS = ("time_limit", "memory_limit")
# the largest limits taken (time: CPU seconds, about 31 years; memory and
# output: megabytes, a petabyte): beyond them the clocks and resource limits
# that enforce a limit overflow (P time_limit 1e308 ended in an internal error)
LIMIT_MAXIMA = {"time_limit": 1e9, "memory_limit": 1e9, "output_limit": 1e9}
# P ncpus: code_aster reads a whole number of threads; more than this is a typo
MAX_THREADS = 4096
LIMIT_UNITS = {"time_limit": "seconds", "memory_limit": "MB", "output_limit": "MB"}
# R-line types asterlite cannot make: code_aster's databases and folders
NOT_PRODUCED = frozenset({"base", "bhdf", "repe"})


def _limit(fields: list[str], where: Location) -> float:
    text = fields[2] if len(fields) > 2 else ""
    try:
        value = finite_float(text)
    except NonFiniteNumber as error:  # P time_limit inf would be no limit at all
        raise ExportError(f"P {fields[1]}: {error}", where) from None
    except ValueError:
        value = 0.0
    refusal = limit_refusal(fields[1], value, zero_means_none=False)
    if refusal:
        raise ExportError(f"P {refusal}, got {text!r}", where)
    return value


def _threads(fields: list[str], where: Location) -> int:
    text = fields[2] if len(fields) > 2 else ""
    try:
        count = int(text)
    except ValueError:
        count = 0
    if not 1 <= count <= MAX_THREADS:
        raise ExportError(
            f"P ncpus must be a whole number of threads from 1 to {MAX_THREADS}, got {text!r}",
            where,
        )
    return count


def limit_refusal(name: str, value, zero_means_none: bool = True) -> str:
    """Why ``value`` cannot be the limit ``name`` ('' when it can): a finite
    positive number up to LIMIT_MAXIMA (0 means no limit where allowed)."""
    low = "a number >= 0 (0: no limit)" if zero_means_none else "a positive number"
    maximum = LIMIT_MAXIMA[name]
    wanted = f"{name} must be {low} of {LIMIT_UNITS[name]}, at most {maximum:g}"
    try:
        number = float(value)
    except (TypeError, ValueError, OverflowError):
        return wanted
    if number != number or not (0 < number <= maximum or (zero_means_none and number == 0)):
        return wanted
    return ""


def describe_bare_deck(path: Path) -> RunDescription:
    """A run description for a ``.comm`` given without an export."""
    folder = path.parent
    run = RunDescription(name=path.stem, deck_files=[path.resolve()])
    continuation = sorted(folder.glob(f"{path.stem}.com[0-9]"))
    run.deck_files += [p.resolve() for p in continuation]
    mesh, why = sibling_mesh(path)
    if mesh is not None:
        run.units[MESH_UNIT] = mesh.resolve()
    else:
        run.unmapped[MESH_UNIT] = why
    for helper in folder.glob("*.py"):
        run.helper_modules[helper.stem] = helper.resolve()
    return run


def sibling_mesh(deck: Path) -> tuple[Path | None, str]:
    """The mesh of a bare deck (unit 20): the deck's namesake (``d.mail``,
    ``d.mmed``, ``d.med``, in that order), else the one mesh file of its
    folder; (None, why) when there is none, or several to choose from (never
    the first in alphabetical order: which one the deck means is not known)."""
    folder = deck.parent
    for suffix in MESH_SUFFIXES:
        own = folder / f"{deck.stem}{suffix}"
        if own.is_file():
            return own, ""
    found = sorted(p for suffix in MESH_SUFFIXES for p in folder.glob(f"*{suffix}") if p.is_file())
    if len(found) == 1:
        return found[0], ""
    namesakes = ", ".join(f"{deck.stem}{suffix}" for suffix in MESH_SUFFIXES)
    patterns = ", ".join(f"*{suffix}" for suffix in MESH_SUFFIXES)
    if not found:
        return None, (
            f"no mesh beside the deck {deck.name}: looked for {namesakes}, then for "
            f"{patterns} in {folder.resolve()}; put the mesh there, or name it in an "
            f".export ('F mail <file> D {MESH_UNIT}')"
        )
    names = ", ".join(p.name for p in found)
    return None, (
        f"{len(found)} meshes beside the deck {deck.name} ({names}) and none named "
        f"{namesakes}: which one to read is not known; name it in an .export "
        f"('F mail {found[0].name} D {MESH_UNIT}') or rename it {deck.stem}{found[0].suffix}"
    )


def describe_run(path: Path) -> RunDescription:
    """Run description for a deck path: an ``.export`` or a bare deck file."""
    if not path.exists():
        raise ExportError(f"no such file: {path}")
    if path.suffix == ".export":
        return read_export(path)
    return describe_bare_deck(path)
