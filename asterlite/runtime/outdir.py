"""The output folder of a run, owned by the run for its lifetime.

What a run promises about its ``-o`` folder (docs/safety.md):

- it holds a lock (``.asterlite.lock``, ``flock``) while it runs: a second
  run into the same folder is refused;
- an earlier asterlite result found there (its ``summary.json`` lists the
  files that run made) is moved aside into ``previous-<time>/`` before
  anything is written, so old and new files never mix; anything else in
  the folder is left alone, and a deck may not write a file whose name is
  already taken;
- ``message.log`` is written line by line and ``summary.json`` says RUNNING
  as the run goes; the files the deck writes wait in a hidden staging folder
  and appear under their names only when the run completes (else the staging
  folder becomes ``incomplete/``);
- nothing is ever deleted, replaced or written through a symbolic link
  unless this run made it: files are created with ``O_EXCL | O_NOFOLLOW``
  and moved with a rename that refuses to replace.
"""

from __future__ import annotations

import ctypes
import errno
import json
import os
import re
import time
from pathlib import Path

from asterlite.errors import AsterliteError

LOCK_NAME = ".asterlite.lock"
STAGING_NAME = ".asterlite-running"
LOG_NAME = "message.log"
SUMMARY_NAME = "summary.json"
INCOMPLETE_NAME = "incomplete"
PREVIOUS_PREFIX = "previous-"
SUMMARY_TEMP = ".summary.json.tmp"
# names a deck may not write (the run's own files)
RESERVED = frozenset({LOCK_NAME, STAGING_NAME, LOG_NAME, SUMMARY_NAME, SUMMARY_TEMP, ".running"})
_RESERVED_PATTERN = re.compile(rf"^({INCOMPLETE_NAME}(-\d+)?|{PREVIOUS_PREFIX}.*)$")
# what a run made before summaries listed their files (asterlite up to 0.x)
_LEGACY_NAMES = re.compile(
    r"^(fort\.\d+|results\.h5|incomplete|\.running|message\.log|summary\.json)$"
)
_SUMMARY_READ_CAP = 64 * 1024 * 1024  # bytes of an earlier summary.json worth reading
_CREATE = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0)


class OutputFolderError(AsterliteError):
    """The output folder cannot be used, or a deck wants a name it may not take."""

    kind = "output folder"


class OutputLimitError(AsterliteError):
    """The run wrote more than its output cap."""

    kind = "output limit exceeded"
    fatal = True  # ends the run even where other errors are collected (check)


def create_file(path: Path, mode: str = "w"):
    """Open a new file that must not exist yet (never through a symlink)."""
    descriptor = os.open(path, _CREATE, 0o644)
    return os.fdopen(descriptor, mode, encoding="utf-8" if "b" not in mode else None)


def rename_no_replace(source: Path, target: Path) -> None:
    """Rename ``source`` to ``target``; FileExistsError if ``target`` exists."""
    if _renameat2 is not None:
        result = _renameat2(-100, os.fsencode(source), -100, os.fsencode(target), 1)
        if result == 0:
            return
        code = ctypes.get_errno()
        if code not in (errno.ENOSYS, errno.EINVAL):  # e.g. a file system without the flag
            raise OSError(code, os.strerror(code), str(target))
    if os.path.lexists(target):
        raise FileExistsError(errno.EEXIST, "already exists", str(target))
    os.rename(source, target)


def _load_renameat2():
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        function = libc.renameat2
    except (OSError, AttributeError):
        return None
    function.argtypes = [
        ctypes.c_int,
        ctypes.c_char_p,
        ctypes.c_int,
        ctypes.c_char_p,
        ctypes.c_uint,
    ]
    function.restype = ctypes.c_int
    return function


_renameat2 = _load_renameat2()


class StreamedLog(list):
    """The run's messages: kept in memory (``session.messages``) and written
    to ``message.log`` as they come, up to ``cap`` bytes."""

    def __init__(self, stream, cap: int | None):
        super().__init__()
        self.stream = stream
        self.cap = cap
        self.written = 0
        self.full = False
        self.on_line = None  # called after each line (the runner's output cap)

    def append(self, text) -> None:
        text = str(text)
        size = len(text.encode("utf-8", "replace")) + 1
        if self.cap is not None and self.written + size > self.cap:
            if not self.full:
                self.full = True
                self._write(f"[message.log stops here: it reached its cap of {self.cap:,} bytes]")
            raise OutputLimitError(
                f"message.log would exceed its cap of {self.cap / 1e6:g} MB "
                "(deck prints or command messages; asterlite run --output-limit to change it)"
            )
        super().append(text)
        self._write(text)
        self.written += size
        if self.on_line is not None:
            self.on_line()

    def extend(self, texts) -> None:
        for text in texts:
            self.append(text)

    def final(self, text: str) -> None:
        """Lines the runner adds at the end (the summary): past the cap too."""
        self._write(text)

    def _write(self, text: str) -> None:
        if self.stream is None:
            return
        try:
            self.stream.write(text + "\n")
            self.stream.flush()
        except OSError as error:
            stream, self.stream = self.stream, None  # stop writing a broken log
            try:
                stream.close()
            except OSError:
                pass
            raise OutputLimitError(f"cannot write message.log: {error.strerror or error}") from None

    def close(self) -> None:
        if self.stream is not None:
            try:
                self.stream.close()
            except OSError:
                pass
            self.stream = None


class OutputFolder:
    """An output folder a run has opened: locked, cleared of any earlier
    result, with a staging folder for the deck's files."""

    def __init__(self, path: Path, *, log_cap: int | None = None, deck: str = ""):
        self.path = Path(path)
        self.deck = deck
        self.log_cap = log_cap
        self.created: list[str] = []  # names this run made in the folder
        self.foreign: set[str] = set()  # names there before the run: never touched
        self.moved_aside: Path | None = None
        self.started = time.time()
        self.log: StreamedLog | None = None
        self._lock_descriptor = None
        self._lock_created = False

    # ----------------------------------------------------------------- open
    def open(self) -> OutputFolder:
        """Take the folder; OutputFolderError (nothing written) when it cannot be."""
        try:
            self._make_folder()
            self._lock()
            self.moved_aside = self._move_earlier_result()
            self.foreign = set(os.listdir(self.path)) - {LOCK_NAME}
            for name in (LOG_NAME, SUMMARY_NAME, STAGING_NAME):
                if name in self.foreign:
                    raise OutputFolderError(
                        f"{self.path / name} exists and is not part of an earlier asterlite "
                        "result: choose another output folder"
                    )
            os.mkdir(self.staging)
            self.created.append(STAGING_NAME)
            self.log = StreamedLog(create_file(self.path / LOG_NAME), self.log_cap)
            self.created.append(LOG_NAME)
            self.write_summary({"deck": self.deck, "status": "RUNNING"})
        except OSError as error:
            self.release()
            raise OutputFolderError(f"{self.path}: {error.strerror or error}") from None
        except OutputFolderError:
            self.release()
            raise
        return self

    @property
    def staging(self) -> Path:
        return self.path / STAGING_NAME

    def _make_folder(self) -> None:
        if self.path.exists() and not self.path.is_dir():
            raise OutputFolderError(f"{self.path} exists and is not a folder")
        self.path.mkdir(parents=True, exist_ok=True)

    def _lock(self) -> None:
        import fcntl

        lock = self.path / LOCK_NAME
        try:
            descriptor = os.open(lock, _CREATE & ~os.O_WRONLY | os.O_RDWR, 0o644)
            self._lock_created = True
        except FileExistsError:
            descriptor = os.open(lock, os.O_RDWR | getattr(os, "O_NOFOLLOW", 0))
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
            # the file may have been removed by the run that held it: then a
            # third run could lock a new one; refusing is right (a run was on)
            if os.fstat(descriptor).st_ino != os.lstat(lock).st_ino:
                raise BlockingIOError
        except (BlockingIOError, FileNotFoundError):
            os.close(descriptor)
            self._lock_created = False
            raise OutputFolderError(
                f"another asterlite run is using {self.path} (it holds {LOCK_NAME}): "
                "wait for it to end or choose another output folder"
            ) from None
        os.ftruncate(descriptor, 0)
        os.write(descriptor, f"{os.getpid()}\n".encode())
        self._lock_descriptor = descriptor

    def release(self) -> None:
        """Give the folder up (remove the lock file when this run made it)."""
        if self.log is not None:
            self.log.close()
        if self._lock_descriptor is None:
            return
        if self._lock_created:
            try:
                os.unlink(self.path / LOCK_NAME)
            except OSError:
                pass
        os.close(self._lock_descriptor)
        self._lock_descriptor = None

    # -------------------------------------------------------- earlier result
    def _move_earlier_result(self) -> Path | None:
        """Move what an earlier run left here into ``previous-<its start>/``."""
        names = earlier_result_names(self.path)
        if not names:
            return None
        summary = self.path / SUMMARY_NAME
        stamp = time.strftime("%Y%m%d-%H%M%S", time.localtime(summary.lstat().st_mtime))
        target = self.path / f"{PREVIOUS_PREFIX}{stamp}"
        number = 1
        while True:
            try:
                os.mkdir(target)
                break
            except FileExistsError:
                number += 1
                target = self.path / f"{PREVIOUS_PREFIX}{stamp}-{number}"
        for name in names:
            rename_no_replace(self.path / name, target / name)
        return target

    # ------------------------------------------------------------ deck files
    def check_name(self, name: str) -> None:
        """Refuse a file name the deck may not write in this folder."""
        if name in ("", ".", "..") or "/" in name or "\0" in name:
            raise OutputFolderError(f"{name!r} is not a file name")
        if name in RESERVED or _RESERVED_PATTERN.match(name):
            raise OutputFolderError(f"'{name}' is a name the run keeps for itself")
        if name in self.foreign:
            raise OutputFolderError(
                f"the output folder already holds '{name}', which this run did not create: "
                "the run never replaces it (choose another name or another output folder)"
            )

    def publish(self) -> list[str]:
        """Move the staged files to their names (a complete run); the names
        that could not be placed (taken meanwhile) stay in the staging folder."""
        blocked = []
        for item in sorted(os.listdir(self.staging)):
            try:
                rename_no_replace(self.staging / item, self.path / item)
                self.created.append(item)
            except FileExistsError:
                blocked.append(item)
        if not blocked:
            os.rmdir(self.staging)
            self.created.remove(STAGING_NAME)
        return blocked

    def keep_incomplete(self) -> str | None:
        """The staging folder becomes ``incomplete/`` (if it holds anything)."""
        if not os.listdir(self.staging):
            os.rmdir(self.staging)
            self.created.remove(STAGING_NAME)
            return None
        number, name = 1, INCOMPLETE_NAME
        while True:
            try:
                rename_no_replace(self.staging, self.path / name)
                break
            except FileExistsError:
                number += 1
                name = f"{INCOMPLETE_NAME}-{number}"
        self.created[self.created.index(STAGING_NAME)] = name
        return name

    def owns(self, path: Path) -> bool:
        """Whether ``path`` is a file of this folder that this run made."""
        try:
            relative = Path(os.path.abspath(path)).relative_to(os.path.abspath(self.path))
        except ValueError:
            return False
        return len(relative.parts) == 1 and relative.parts[0] in self.created

    def inside(self, path: Path) -> bool:
        try:
            Path(os.path.abspath(path)).relative_to(os.path.abspath(self.path))
        except ValueError:
            return False
        return True

    def staged_bytes(self) -> int:
        """Bytes of the files the deck wrote so far (the staging folder)."""
        total = 0
        pending = [self.staging]
        while pending:
            try:
                entries = list(os.scandir(pending.pop()))
            except OSError:
                continue
            for entry in entries:
                if entry.is_dir(follow_symlinks=False):
                    pending.append(Path(entry.path))
                else:
                    total += entry.stat(follow_symlinks=False).st_size
        return total

    # --------------------------------------------------------------- summary
    def write_summary(self, data: dict) -> None:
        """summary.json, replaced whole (written aside, then renamed)."""
        data = dict(data)
        data["output"] = {
            "files": sorted(set(self.created) | {SUMMARY_NAME}),
            "started": time.strftime("%Y-%m-%dT%H:%M:%S", time.localtime(self.started)),
            "pid": os.getpid(),
            "moved_aside": self.moved_aside.name if self.moved_aside else None,
        }
        temporary = self.path / SUMMARY_TEMP
        with create_file(temporary) as stream:
            stream.write(json.dumps(data, indent=1))
        os.replace(temporary, self.path / SUMMARY_NAME)
        if SUMMARY_NAME not in self.created:
            self.created.append(SUMMARY_NAME)


def earlier_result_names(folder: Path) -> list[str]:
    """Names an earlier asterlite run left in ``folder`` (from its summary),
    [] when there is none; OutputFolderError when summary.json is not ours."""
    summary = folder / SUMMARY_NAME
    try:
        info = summary.lstat()
    except FileNotFoundError:
        return []
    import stat

    if not stat.S_ISREG(info.st_mode) or info.st_size > _SUMMARY_READ_CAP:
        raise OutputFolderError(f"{summary} is not an asterlite summary: choose another folder")
    try:
        data = json.loads(summary.read_text(encoding="utf-8"))
        if not isinstance(data, dict) or "status" not in data or not {"deck", "output"} & set(data):
            raise ValueError
    except (ValueError, UnicodeDecodeError):
        raise OutputFolderError(
            f"{summary} is not an asterlite summary: choose another folder"
        ) from None
    present = set(os.listdir(folder))
    listed = (
        (data.get("output") or {}).get("files") if isinstance(data.get("output"), dict) else None
    )
    if isinstance(listed, list):
        names = {name for name in listed if isinstance(name, str)}
    else:  # a summary from before the lists: the names asterlite always used
        names = {name for name in present if _LEGACY_NAMES.match(name)}
    names.add(SUMMARY_NAME)
    safe = []
    for name in sorted(names & present):
        if name in ("", ".", "..", LOCK_NAME) or "/" in name or name.startswith(PREVIOUS_PREFIX):
            continue
        if os.path.islink(folder / name):  # not something a run makes: leave it
            continue
        safe.append(name)
    return safe
