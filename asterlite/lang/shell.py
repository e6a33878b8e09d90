"""``os.system`` for decks: the few file commands decks give it, run inside
the run's output folder without a shell.

Verification decks call ``os.system`` to show a file they wrote (``ls -l
fort.38``, ``cat fort.38``) or to lay out files for a later command
(``mkdir``, ``echo text > file``, ``cp``). These run here as Python code on
the output folder: a path that leaves it (absolute, ``..``, a link out of
it) is refused by name, as is every other program, pipe, command list,
substitution or redirection but ``>``/``>>`` of standard output. The
output goes to the run's log; the value returned is the wait status
``os.system`` gives (exit status times 256). Without an output folder
(``asterlite check``) a command is validated and not run.
"""

from __future__ import annotations

import re
import shlex
import shutil
import time
from collections.abc import Callable
from pathlib import Path

from asterlite.errors import DeckRuntimeError, UnsupportedError

COMMANDS = ("ls", "cat", "echo", "mkdir", "cp")
_OPERATORS = set("|;&<>()")
_GLOB = set("*?[")


def run(
    command: str,
    output_folder: Callable[[], Path | None],
    say: Callable[[str], None],
    max_length: int,
) -> int:
    """Run ``command`` as ``os.system`` would; return its wait status."""
    if not isinstance(command, str):
        raise DeckRuntimeError("os.system takes a string")
    if len(command) > max_length:
        raise DeckRuntimeError(f"limit exceeded: string length (limit {max_length:,})")
    words, target, append = _parse(command)
    name, arguments = words[0], words[1:]
    folder = output_folder()
    if folder is None:  # validation only
        return 0
    folder = folder.resolve()
    lines: list[str] = []  # output chunks, each ending its line but echo -n's
    try:
        status = _RUNNERS[name](arguments, folder, lines, say)
        text = "".join(lines)
        if target is None:
            shown = text[:max_length]
            for line in shown.splitlines():
                say(line)
            if len(text) > len(shown):
                say(f"({len(text) - len(shown):,} more characters not shown)")
        else:
            path = _inside(folder, target, command)
            with path.open("a" if append else "w") as stream:
                stream.write(text)
    except OSError as error:  # what the shell would say, and its failure status
        say(f"{name}: {error.strerror or error}: {error.filename or ''}".rstrip(": "))
        status = 1
    return status * 256


def _parse(command: str) -> tuple[list[str], str | None, bool]:
    if "`" in command or "$" in command:
        raise UnsupportedError(
            f"os.system({command[:80]!r}): substitutions and variables are not run in decks"
        )
    if re.search(r"(^|\s)\d+>", command):
        raise UnsupportedError(
            f"os.system({command[:80]!r}): redirections of other streams than standard "
            "output are not run in decks"
        )
    lexer = shlex.shlex(command, posix=True, punctuation_chars="|;&<>()")
    lexer.whitespace_split = True
    try:
        tokens = list(lexer)
    except ValueError as error:
        raise DeckRuntimeError(f"os.system({command[:80]!r}): {error}") from None
    target, append = None, False
    if len(tokens) >= 2 and tokens[-2] in (">", ">>"):
        target, append = tokens[-1], tokens[-2] == ">>"
        tokens = tokens[:-2]
    for token in tokens:
        if token and set(token) <= _OPERATORS:
            raise UnsupportedError(
                f"os.system({command[:80]!r}): '{token}': decks may run one command of "
                f"{', '.join(COMMANDS)} with '>' or '>>' of its output, no pipe, list or "
                "other redirection"
            )
    if not tokens:
        raise DeckRuntimeError("os.system(''): no command")
    if tokens[0] not in COMMANDS:
        raise UnsupportedError(
            f"os.system({command[:80]!r}): '{tokens[0]}': decks may run "
            f"{', '.join(COMMANDS)} on the run's output folder, no other program"
        )
    return tokens, target, append


def _inside(folder: Path, name: str, command: str) -> Path:
    """``name`` as a path of the output folder, refused if it leads out of it."""
    path = Path(name)
    resolved = (folder / path).resolve()
    if path.is_absolute() or not resolved.is_relative_to(folder):
        raise UnsupportedError(
            f"os.system({command[:80]!r}): '{name}': decks may only touch files of the "
            "run's output folder (a relative path inside it)"
        )
    return resolved


def _operands(arguments: list[str], folder: Path, command: str) -> tuple[set, list[Path]]:
    flags, paths = set(), []
    for word in arguments:
        if word.startswith("-") and len(word) > 1:
            flags.update(word[1:])
            continue
        if _GLOB & set(word):
            _inside(folder, word.split("*")[0] or ".", command)
            matches = sorted(folder.glob(word))
            paths.extend(_inside(folder, str(match), command) for match in matches)
            if not matches:
                paths.append(_inside(folder, word, command))
            continue
        paths.append(_inside(folder, word, command))
    return flags, paths


def _shown(path: Path, folder: Path) -> str:
    return str(path.relative_to(folder)) if path != folder else "."


def _ls(arguments, folder, lines, say) -> int:
    flags, paths = _operands(arguments, folder, "ls " + " ".join(arguments))
    unknown = flags - set("ltra1hS")
    if unknown:
        raise UnsupportedError(f"os.system('ls'): option -{''.join(sorted(unknown))} is not run")
    status = 0
    entries: list[Path] = []
    for path in paths or [folder]:
        if not path.exists():
            say(f"ls: cannot access '{_shown(path, folder)}': No such file or directory")
            status = 2
        elif path.is_dir():
            entries.extend(
                child for child in path.iterdir() if "a" in flags or not child.name.startswith(".")
            )
        else:
            entries.append(path)
    if "t" in flags:
        entries.sort(key=lambda entry: entry.stat().st_mtime, reverse=True)
    else:
        entries.sort()
    if "r" in flags:
        entries.reverse()
    for entry in entries:
        shown = _shown(entry, folder) if entry.parent != folder else entry.name
        if "l" in flags:
            stat = entry.stat()
            kind = "d" if entry.is_dir() else "-"
            stamp = time.strftime("%b %d %H:%M", time.localtime(stat.st_mtime))
            lines.append(f"{kind} {stat.st_size:>10} {stamp} {shown}\n")
        else:
            lines.append(shown + "\n")
    return status


def _cat(arguments, folder, lines, say) -> int:
    _flags, paths = _operands(arguments, folder, "cat " + " ".join(arguments))
    status = 0
    for path in paths:
        if not path.is_file():
            say(f"cat: {_shown(path, folder)}: No such file or directory")
            status = 1
            continue
        lines.append(path.read_text(errors="replace"))
    return status


def _echo(arguments, folder, lines, say) -> int:
    newline = not (arguments and arguments[0] == "-n")
    words = arguments if newline else arguments[1:]
    lines.append(" ".join(words) + ("\n" if newline else ""))
    return 0


def _mkdir(arguments, folder, lines, say) -> int:
    flags, paths = _operands(arguments, folder, "mkdir " + " ".join(arguments))
    status = 0
    for path in paths:
        if path.exists() and not ("p" in flags and path.is_dir()):
            say(f"mkdir: cannot create directory '{_shown(path, folder)}': File exists")
            status = 1
            continue
        path.mkdir(parents="p" in flags, exist_ok="p" in flags)
    return status


def _cp(arguments, folder, lines, say) -> int:
    flags, paths = _operands(arguments, folder, "cp " + " ".join(arguments))
    if flags - set("pf"):
        raise UnsupportedError(
            f"os.system('cp'): option -{''.join(sorted(flags - set('pf')))} is not run"
        )
    if len(paths) < 2:
        say("cp: missing destination file operand")
        return 1
    *sources, destination = paths
    if len(sources) > 1 and not destination.is_dir():
        say(f"cp: target '{_shown(destination, folder)}' is not a directory")
        return 1
    status = 0
    for source in sources:
        if not source.is_file():
            say(f"cp: cannot stat '{_shown(source, folder)}': No such file or directory")
            status = 1
            continue
        shutil.copyfile(source, destination / source.name if destination.is_dir() else destination)
    return status


_RUNNERS = {"ls": _ls, "cat": _cat, "echo": _echo, "mkdir": _mkdir, "cp": _cp}
