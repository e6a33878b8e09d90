"""Size bounds for the text files a deck reads (ASTER meshes, function files).

Parsing text into Python objects takes many times the file's size (tokens,
line numbers, lists): an ASTER mesh about 40 bytes of memory per byte of
text. A file whose reading would pass the run's memory limit, or a fixed
ceiling, is refused before it is read, with its size and what it would need.
"""

from __future__ import annotations

from pathlib import Path

MAX_TEXT_INPUT_BYTES = 1_000_000_000  # no text input beyond 1 GB, whatever the limits


class InputTooLargeError(ValueError):
    """A text input the run cannot afford to read."""


def check_input_size(path: Path, what: str, bytes_per_byte: float) -> int:
    """The file's size, or InputTooLargeError when reading it would take more
    than the run's memory limit (``bytes_per_byte`` of memory per byte)."""
    from asterlite.runtime import watchdog

    size = Path(path).stat().st_size
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
    return size


def read_bounded_text(path: Path, what: str, bytes_per_byte: float) -> str:
    check_input_size(path, what, bytes_per_byte)
    return Path(path).read_text(encoding="utf-8", errors="replace")
