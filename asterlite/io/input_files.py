"""Opening and reading the files a study brings (deck, export, meshes,
function files, materials): regular files only, never more than their
checked size.

A FIFO named as a mesh would block the run forever without using any CPU
(so no CPU time limit fires), and ``/dev/zero`` or ``/dev/urandom`` report a
size of 0 but never end. So an input is refused unless it is a regular file:
checked with ``stat`` before opening (a device is never even opened), then
opened with ``O_NONBLOCK`` (opening a FIFO then returns at once instead of
waiting for a writer) and checked again with ``fstat`` on the open
descriptor, which is what is read (a FIFO swapped in between is caught).
Reads stop at the size checked: a file that grows meanwhile is read up to
that size only.

Parsing text into Python objects takes many times the file's size (tokens,
line numbers, lists): an ASTER mesh about 40 bytes of memory per byte of
text. A file whose reading would pass the run's memory limit, or a fixed
ceiling, is refused before it is read, with its size and what it would need.
"""

from __future__ import annotations

import os
import stat
from contextlib import contextmanager
from pathlib import Path

from asterlite import watchdog
from asterlite.errors import AsterliteError, Location
from asterlite.io.text_encoding import TextEncodingError, decode_text

MAX_TEXT_INPUT_BYTES = 1_000_000_000  # no text input beyond 1 GB, whatever the limits
_OPEN_FLAGS = (
    os.O_RDONLY
    | getattr(os, "O_NONBLOCK", 0)
    | getattr(os, "O_NOCTTY", 0)
    | getattr(os, "O_CLOEXEC", 0)
)


class InputFileError(ValueError):
    """An input file the run refuses to read."""


class InputTooLargeError(InputFileError):
    """A text input the run cannot afford to read."""


class NotARegularFileError(InputFileError):
    """A FIFO, a device, a socket or a folder where a file is expected."""


class InputRefusedError(AsterliteError):
    """A deck, export or helper file the run refuses to read (exit status 2)."""

    kind = "input file refused"


# bytes of memory parsing takes per byte of deck text (lark's tree: about 75)
DECK_BYTES_PER_BYTE = 100


def file_kind(mode: int) -> str:
    """What a ``st_mode`` is, in words (for messages)."""
    kinds = (
        (stat.S_ISFIFO, "a FIFO (named pipe)"),
        (stat.S_ISCHR, "a character device"),
        (stat.S_ISBLK, "a block device"),
        (stat.S_ISSOCK, "a socket"),
        (stat.S_ISDIR, "a folder"),
    )
    return next((text for test, text in kinds if test(mode)), "not a regular file")


def _refuse_unless_regular(path: Path, what: str, mode: int) -> None:
    if not stat.S_ISREG(mode):
        raise NotARegularFileError(
            f"{path}: this {what} is {file_kind(mode)}, not a regular file: refused "
            "(it could block the run or never end)"
        )


def check_regular_file(path: Path, what: str) -> int:
    """The size of the regular file at ``path`` (symlinks followed), else
    NotARegularFileError (FileNotFoundError when it does not exist)."""
    status = os.stat(path)
    _refuse_unless_regular(path, what, status.st_mode)
    return status.st_size


@contextmanager
def open_input(path: Path, what: str):
    """A descriptor on the regular file at ``path`` and its size: refused
    before opening if it is anything else, and again on the open descriptor."""
    check_regular_file(path, what)
    descriptor = os.open(path, _OPEN_FLAGS)
    try:
        status = os.fstat(descriptor)
        _refuse_unless_regular(path, what, status.st_mode)
        yield descriptor, status.st_size
    finally:
        os.close(descriptor)


def read_input_bytes(path: Path, what: str, bytes_per_byte: float = 1.0) -> bytes:
    """The bytes of an input file: a regular file, its size checked against
    the run's memory limit, read no further than that size."""
    with open_input(path, what) as (descriptor, size):
        _check_size(path, what, size, bytes_per_byte)
        return _read_at_most(descriptor, size)


def read_bounded_text(path: Path, what: str, bytes_per_byte: float) -> str:
    """The text of an input file (its encoding: :mod:`asterlite.io.text_encoding`)."""
    return read_decoded(path, what, bytes_per_byte)[0]


def read_decoded(path: Path, what: str, bytes_per_byte: float) -> tuple[str, str]:
    """``(text, encoding)`` of an input file: UTF-8 with or without a byte
    order mark, a declared encoding, else Windows-1252 or Latin-1; never a
    byte replaced (InputFileError for bytes that contradict the file's mark
    or declaration)."""
    data = read_input_bytes(path, what, bytes_per_byte)
    try:
        return decode_text(data)
    except TextEncodingError as error:
        raise InputFileError(f"{path}: this {what} cannot be decoded: {error}") from None


def read_head(path: Path, count: int, what: str = "input file") -> bytes:
    """The first ``count`` bytes of a regular file (a file's signature)."""
    with open_input(path, what) as (descriptor, size):
        return _read_at_most(descriptor, min(size, count))


def _read_at_most(descriptor: int, size: int) -> bytes:
    chunks, left = [], size
    while left > 0:
        chunk = os.read(descriptor, min(left, 1 << 24))
        if not chunk:  # the file shrank meanwhile
            break
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def check_input_size(path: Path, what: str, bytes_per_byte: float) -> int:
    """The size of the regular file at ``path``, or InputFileError when it is
    not one, or when reading it would take more than the run's memory limit
    (``bytes_per_byte`` of memory per byte)."""
    size = check_regular_file(path, what)
    _check_size(path, what, size, bytes_per_byte)
    return size


def _check_size(path: Path, what: str, size: int, bytes_per_byte: float) -> None:
    if size > MAX_TEXT_INPUT_BYTES:
        raise InputTooLargeError(
            f"{path}: {what} of {size / 1e6:.0f} MB, beyond the "
            f"{MAX_TEXT_INPUT_BYTES / 1e6:.0f} MB asterlite reads as text"
        )
    limit = watchdog.memory_limit_mb()
    needed = size * bytes_per_byte
    if limit and needed > limit * watchdog.MEGABYTE:
        raise InputTooLargeError(
            f"{path}: reading this {what} of {size / 1e6:.1f} MB takes about "
            f"{needed / 1e9:.1f} GB, beyond the run's memory limit of {limit:g} MB "
            "(P memory_limit, or asterlite run --memory-limit)"
        )


def read_deck_text(path: Path, what: str = "deck file") -> str:
    """The text of a deck, export or helper file, or InputRefusedError
    located at the file (not a regular file, or too large to parse)."""
    return read_deck(path, what)[0]


def read_deck(path: Path, what: str = "deck file") -> tuple[str, str]:
    """``(text, encoding)`` of a deck file (see :func:`read_decoded`), or
    InputRefusedError located at the file."""
    try:
        return read_decoded(path, what, DECK_BYTES_PER_BYTE)
    except InputFileError as error:
        raise InputRefusedError(str(error).split(": ", 1)[-1], Location(str(path), 1)) from None


def read_text_or_none(path: Path, what: str = "deck file") -> str | None:
    """The text of a deck file, or None when it cannot or may not be read
    (a look ahead at a deck's version, which the run proper reports)."""
    try:
        return read_bounded_text(Path(path), what, DECK_BYTES_PER_BYTE)
    except (OSError, InputFileError):
        return None
