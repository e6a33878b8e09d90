"""The output folder of a run, owned by the run for its lifetime.

What a run promises about its ``-o`` folder (docs/safety.md):

- every entry it makes, moves or replaces there goes through one
  :class:`WriteBoundary`: a descriptor of the folder, single names only
  (no ``/``, no ``..``), new files created with ``O_EXCL | O_NOFOLLOW``,
  moves that refuse to replace, and an existing entry written in place only
  when it is the run's own (same inode, no other name);
- it holds a lock (``.asterlite.lock``, ``flock``) while it runs: a second
  run into the same folder is refused. The lock file also records the
  command the run is in, so that a run killed outright can be told later
  (``asterlite status``); a lock nobody holds is taken over and cleared;
- an earlier asterlite result found there is moved aside into
  ``previous-<time>/`` before anything is written, so old and new files
  never mix. Only entries a verified manifest lists are moved
  (:mod:`asterlite.runtime.manifest`), or, for a summary that does not
  verify, the regular files and folders with the names asterlite always
  uses; never the run's inputs, never anything a summary merely claims.
  The ``keep`` most recent ``previous-*`` folders stay; older ones are
  deleted only as far as a verified manifest records them as asterlite's
  (:mod:`asterlite.runtime.previous_results`);
- ``message.log`` is written line by line and ``summary.json`` says RUNNING
  as the run goes; the files the deck writes wait in a hidden staging folder
  and appear under their names only when the run completes (else the staging
  folder becomes ``incomplete/``). A summary that cannot be replaced (a full
  disk) is rewritten in place over the RUNNING one, which leaves room for it.
"""

from __future__ import annotations

import errno
import fcntl
import json
import os
import re
import stat
import time
from pathlib import Path

from asterlite.errors import AsterliteError
from asterlite.runtime import manifest, previous_results
from asterlite.runtime.write_boundary import (
    _NOFOLLOW,
    OutputFolderError,
    WriteBoundary,
    copy_stream,
    create_file,
    entry_name,
    same_unshared,
)

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
# what asterlite makes under these names: moved aside with a summary that does
# not verify (older asterlite, another user's) when they are plain, unshared entries
_KNOWN_FILES = re.compile(
    r"^(fort\.\d+|results\.h5|report\.html|curves\.json|message\.log|summary\.json"
    r"|\.summary\.json\.tmp)$"
)
_KNOWN_FOLDERS = re.compile(r"^(incomplete(-\d+)?|\.asterlite-running|\.running)$")
_SUMMARY_READ_CAP = 64 * 1024 * 1024  # bytes of an earlier summary.json worth reading
# a RUNNING summary is padded to this size: the final status always fits in
# its place when the disk is full (JSON allows trailing blanks)
SUMMARY_RESERVE = 8192
LOCK_RECORD_SIZE = 512  # bytes of the lock file's record of the current command
__all__ = ["OutputFolder", "OutputFolderError", "create_file"]


class OutputFolderBusy(OutputFolderError):
    """Another run holds the folder's lock; ``record`` is what its lock says."""

    def __init__(self, message: str, record: dict):
        super().__init__(message)
        self.record = record


class OutputLimitError(AsterliteError):
    """The run wrote more than its output cap."""

    kind = "output limit exceeded"
    fatal = True  # ends the run even where other errors are collected (check)


# ---------------------------------------------------------------- the log


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


# ------------------------------------------------------- an earlier result


class EarlierResult:
    """The summary.json found in the folder: its data, the manifest's entries
    when it verifies (None otherwise) and the ``previous-*`` folders it
    records as asterlite's ({} unless it verifies)."""

    def __init__(self, data: dict, entries: dict | None, previous: dict | None = None):
        self.data = data
        self.entries = entries
        self.previous = previous or {}

    @property
    def status(self) -> str:
        return str(self.data.get("status"))

    @property
    def verified(self) -> bool:
        return self.entries is not None


def read_earlier_result(boundary: WriteBoundary) -> EarlierResult | None:
    """The folder's summary.json, None when there is none; OutputFolderError
    when it is not an asterlite summary."""
    info = boundary.lstat(SUMMARY_NAME)
    if info is None:
        return None
    summary = boundary.path / SUMMARY_NAME
    refusal = OutputFolderError(f"{summary} is not an asterlite summary: choose another folder")
    text = boundary.read_regular(SUMMARY_NAME, _SUMMARY_READ_CAP)
    if text is None:
        raise refusal
    try:
        data = json.loads(text.decode("utf-8"))
    except (ValueError, UnicodeDecodeError, RecursionError):
        raise refusal from None
    if not isinstance(data, dict) or "status" not in data or not {"deck", "output"} & set(data):
        raise refusal
    return EarlierResult(
        data,
        manifest.verified_entries(data, boundary.info),
        manifest.verified_previous(data, boundary.info),
    )


def earlier_result_names(
    boundary: WriteBoundary, earlier: EarlierResult, protected: frozenset = frozenset()
) -> list[str]:
    """What to move aside of an earlier result: the entries its verified
    manifest lists that are still what the run made; with a summary that does
    not verify, only unshared entries of this user named as asterlite names
    its files. Never the run's inputs (``protected``: (device, inode) pairs)."""
    present = set(boundary.names())
    chosen = []
    for name in sorted(present - {LOCK_NAME}):
        if name.startswith(PREVIOUS_PREFIX):
            continue
        info = boundary.lstat(name)
        if info is None or (info.st_dev, info.st_ino) in protected:
            continue
        if name in (SUMMARY_NAME, SUMMARY_TEMP):  # the summary itself; a write cut short
            keep = stat.S_ISREG(info.st_mode) and (name == SUMMARY_NAME or _plain_own(info))
        elif earlier.verified:
            keep = manifest.matches(earlier.entries.get(name), info)
        else:
            keep = _known_asterlite_entry(name, info)
        if keep:
            chosen.append(name)
    return chosen


def _plain_own(info: os.stat_result) -> bool:
    """A regular file of this user with no other name."""
    return stat.S_ISREG(info.st_mode) and info.st_nlink == 1 and info.st_uid == os.geteuid()


def _known_asterlite_entry(name: str, info: os.stat_result) -> bool:
    if _KNOWN_FILES.match(name):
        return _plain_own(info)
    if _KNOWN_FOLDERS.match(name):
        return stat.S_ISDIR(info.st_mode) and info.st_uid == os.geteuid()
    return False


# ------------------------------------------------------------ the folder


class OutputFolder:
    """An output folder a run has opened: locked, cleared of any earlier
    result, with a staging folder for the deck's files."""

    def __init__(
        self,
        path: Path,
        *,
        log_cap: int | None = None,
        deck: str = "",
        protected: frozenset = frozenset(),
        keep_previous: int = previous_results.DEFAULT_KEEP,
    ):
        self.path = Path(path)
        self.deck = deck
        self.keep_previous = max(0, int(keep_previous))
        self.previous_records: dict = {}  # the previous-* folders asterlite made here
        self.previous_notes: list[str] = []  # what became of the older ones
        self.log_cap = log_cap
        self.protected = protected  # (device, inode) of the run's inputs: never moved
        self.created: list[str] = []  # names this run made in the folder
        self.foreign: set[str] = set()  # names there before the run: never touched
        self.moved_aside: Path | None = None
        self.earlier_note = ""  # what the run found of an earlier run (a killed one)
        self.started = time.time()
        self.log: StreamedLog | None = None
        self.boundary: WriteBoundary | None = None
        self._staging: WriteBoundary | None = None
        self._own: dict[str, os.stat_result] = {}  # the identity of each entry made
        self._lock_descriptor = None
        self.stale_record: dict | None = None  # the lock record of a run that died

    # ----------------------------------------------------------------- open
    def open(self) -> OutputFolder:
        """Take the folder; OutputFolderError (nothing left behind) when it cannot be."""
        try:
            self._make_folder()
            self.take()
            earlier = self.settle_earlier()
            self.moved_aside = self._move_earlier_result(earlier)
            self.foreign = set(self.boundary.names()) - {LOCK_NAME}
            for name in (LOG_NAME, SUMMARY_NAME, STAGING_NAME, SUMMARY_TEMP):
                if name in self.foreign:
                    raise OutputFolderError(
                        f"{self.path / name} exists and is not part of an earlier asterlite "
                        "result: choose another output folder"
                    )
            self._make_own_folder(STAGING_NAME)
            self._staging = self.boundary.folder(STAGING_NAME)
            self.log = StreamedLog(self._make_own_file(LOG_NAME), self.log_cap)
            if self.moved_aside is not None:  # said first: what this folder held before
                self.log.append(f"# the earlier result was moved to {self.moved_aside.name}/")
            for note in self.previous_notes:
                self.log.append(f"# {note}")
            if self.earlier_note:
                self.log.append(f"# {self.earlier_note}")
            self.write_summary(
                {"deck": self.deck, "status": "RUNNING", "message": self._running_message()},
                running=True,
            )
        except OSError as error:  # a full disk: nothing is left half made
            self._undo_open()
            raise OutputFolderError(f"{self.path}: {error.strerror or error}") from None
        except OutputLimitError as error:  # message.log's first lines on a full disk
            self._undo_open()
            raise OutputFolderError(f"{self.path}: {error.message}") from None
        except BaseException:  # refused, or a second stop signal while starting
            self._undo_open()
            raise
        return self

    def _running_message(self) -> str:
        text = f"running since {_clock(self.started)} (pid {os.getpid()})"
        if self.moved_aside is not None:
            text += f"; the earlier result was moved to {self.moved_aside.name}/"
        return text + (f"; {self.earlier_note}" if self.earlier_note else "")

    def _undo_open(self) -> None:
        """An open that failed (a full disk): remove what it made, so that the
        next run finds the folder as this one did (minus what it moved aside)."""
        if self.log is not None:
            self.log.close()
        if self._staging is not None:
            self._staging.close()
            self._staging = None
        if self.boundary is not None:
            for name in reversed(self.created):
                try:
                    self.boundary.remove_own(name, self._own.get(name))
                except OSError:
                    pass
        self.created.clear()
        self.release()

    @property
    def staging(self) -> Path:
        return self.path / STAGING_NAME

    def _make_folder(self) -> None:
        if self.path.exists() and not self.path.is_dir():
            raise OutputFolderError(f"{self.path} exists and is not a folder")
        self.path.mkdir(parents=True, exist_ok=True)

    def _make_own_folder(self, name: str) -> None:
        self.boundary.mkdir(name)
        self._own[name] = self.boundary.lstat(name)
        self.created.append(name)

    def _make_own_file(self, name: str, binary: bool = False):
        stream = self.boundary.create(name, binary)
        self._own[name] = os.fstat(stream.fileno())
        self.created.append(name)
        return stream

    # ----------------------------------------------------------------- lock
    def take(self) -> None:
        """Open the folder's descriptor and take its lock (OutputFolderBusy
        if a live run holds it). A lock file nobody holds is a run that died:
        its record is kept in ``stale_record`` and the lock taken over."""

        if self.boundary is None:
            self.boundary = WriteBoundary.open(self.path)
        descriptor, existed = self._open_lock_file()
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
            # the file may have been removed by the run that held it: then a
            # third run could lock a new one; refusing is right (a run was on)
            now = self.boundary.lstat(LOCK_NAME)
            if now is None or now.st_ino != os.fstat(descriptor).st_ino:
                raise BlockingIOError
        except (BlockingIOError, FileNotFoundError):
            record = lock_record(descriptor)
            os.close(descriptor)
            raise OutputFolderBusy(
                f"another asterlite run is using {self.path} (it holds {LOCK_NAME}): "
                "wait for it to end or choose another output folder",
                record,
            ) from None
        if existed:
            self.stale_record = lock_record(descriptor)
            os.ftruncate(descriptor, 0)  # our file (checked), and the lock is ours now
        self._lock_descriptor = descriptor
        self._own[LOCK_NAME] = os.fstat(descriptor)
        self.record_command(None, None, None)

    def _open_lock_file(self) -> tuple[int, bool]:
        """The lock file's descriptor, made now or found; one found must be
        a plain file of this user with no other name: a hard link planted
        there would have another file truncated."""
        try:
            flags = os.O_RDWR | os.O_CREAT | os.O_EXCL | _NOFOLLOW | os.O_CLOEXEC
            return os.open(LOCK_NAME, flags, 0o644, dir_fd=self.boundary.fd), False
        except FileExistsError:
            pass
        lock = self.path / LOCK_NAME
        try:
            flags = os.O_RDWR | _NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC
            descriptor = os.open(LOCK_NAME, flags, dir_fd=self.boundary.fd)
        except OSError as error:
            raise OutputFolderError(
                f"{lock} is not an asterlite lock ({error.strerror}): if no run is using "
                "the folder, remove it or choose another output folder"
            ) from None
        if not _plain_own(os.fstat(descriptor)):
            os.close(descriptor)
            raise OutputFolderError(
                f"{lock} is not an asterlite lock (another file's second name, or not a "
                "plain file of yours): if no run is using the folder, remove it or choose "
                "another output folder"
            )
        return descriptor, True

    def record_command(self, command: str | None, location, running: bool | None) -> None:
        """Write where the run is into its lock file (one pwrite in place): a
        run killed outright leaves it for ``asterlite status`` and the next run."""
        if self._lock_descriptor is None:
            return
        record = {"pid": os.getpid(), "started": round(self.started, 3)}
        if command is not None:
            record.update(command=str(command)[:64], running=bool(running))
            if location is not None:
                record.update(file=os.path.basename(str(location.file))[-200:], line=location.line)
        text = json.dumps(record)[: LOCK_RECORD_SIZE - 1].ljust(LOCK_RECORD_SIZE - 1) + "\n"
        try:
            os.pwrite(self._lock_descriptor, text.encode(), 0)
        except OSError:
            pass  # a hint for later: never a reason to stop the run

    def release(self) -> None:
        """Give the folder up: close the log, remove the lock file (this run's,
        made or taken over) and close the descriptors."""
        if self.log is not None:
            self.log.close()
        if self._staging is not None:
            self._staging.close()
            self._staging = None
        if self._lock_descriptor is not None:
            try:
                self.boundary.remove_own(LOCK_NAME, os.fstat(self._lock_descriptor))
            except OSError:
                pass
            os.close(self._lock_descriptor)
            self._lock_descriptor = None
        if self.boundary is not None:
            self.boundary.close()
            self.boundary = None

    # -------------------------------------------------------- earlier result
    def settle_earlier(self) -> EarlierResult | None:
        """Read the earlier summary; one that says RUNNING while nobody held
        the lock is a run that died: say so in its summary and log (when its
        manifest verifies), its staging folder becoming ``incomplete/``."""
        earlier = read_earlier_result(self.boundary)
        if earlier is None or earlier.status != "RUNNING":
            return earlier
        self.earlier_note = "the earlier run had ended without its result (KILLED)"
        if not earlier.verified:
            return earlier
        data = settled_summary(earlier.data, self.stale_record)
        entries = dict(earlier.entries)
        staging = self.boundary.lstat(STAGING_NAME)
        if staging is not None and manifest.matches(entries.get(STAGING_NAME), staging):
            incomplete = self._rename_to_incomplete(
                STAGING_NAME, self.boundary.folder(STAGING_NAME)
            )
            if incomplete is not None:
                entries[incomplete] = entries[STAGING_NAME]
            del entries[STAGING_NAME]
        _append_own_log(self.boundary, entries, f"KILLED: {data['message']}")
        output = data.get("output") if isinstance(data.get("output"), dict) else {}
        data["output"] = {**output, "files": sorted(set(entries) | {SUMMARY_NAME})}
        self._own[SUMMARY_NAME] = self.boundary.lstat(SUMMARY_NAME)  # verified: the dead run's
        try:
            self._replace_summary(_signed_text(data, self.boundary, entries, earlier.previous))
        finally:
            self._own.pop(SUMMARY_NAME, None)  # the new run's summary is not written yet
        return read_earlier_result(self.boundary)

    def _move_earlier_result(self, earlier: EarlierResult | None) -> Path | None:
        """Move what an earlier run left here into ``previous-<its start>/``,
        then keep the ``keep_previous`` most recent such folders."""
        if earlier is None:
            return None
        records = previous_results.live_records(self.boundary, earlier.previous)
        names = earlier_result_names(self.boundary, earlier, self.protected)
        moved = self._move_into_previous(earlier, names) if names else None
        if moved is not None:
            records[moved[0]] = moved[1]
        kept, deleted, left = previous_results.prune(self.boundary, records, self.keep_previous)
        self.previous_records = kept
        made = moved[0] if moved is not None else None
        self.previous_notes = previous_results.notes(self.keep_previous, made, deleted, left)
        return self.path / made if made is not None and made not in deleted else None

    def _move_into_previous(self, earlier: EarlierResult, names: list[str]) -> tuple[str, dict]:
        """Move ``names`` into a new ``previous-<time>/``: its name and its
        manifest record (what was moved that asterlite can tell as its own)."""
        mtime = self.boundary.lstat(SUMMARY_NAME).st_mtime
        stamp = time.strftime("%Y%m%d-%H%M%S", time.localtime(mtime))
        name, number = f"{PREVIOUS_PREFIX}{stamp}", 1
        while True:
            try:
                self.boundary.mkdir(name)
                break
            except FileExistsError:
                number += 1
                name = f"{PREVIOUS_PREFIX}{stamp}-{number}"
        made = time.time()
        target = self.boundary.folder(name)
        trusted = {}
        try:
            for entry in names:
                record = previous_results.trusted_record(self.boundary, earlier, entry)
                self.boundary.move(entry, target)
                if record is not None:
                    trusted[entry] = record
        finally:
            target.close()
        return name, previous_results.folder_record(self.boundary, name, trusted, made)

    # ------------------------------------------------------------ deck files
    def check_name(self, name: str) -> None:
        """Refuse a file name the deck may not write in this folder."""
        entry_name(name)
        if name in RESERVED or _RESERVED_PATTERN.match(name):
            raise OutputFolderError(f"'{name}' is a name the run keeps for itself")
        if name in self.foreign:
            raise OutputFolderError(
                f"the output folder already holds '{name}', which this run did not create: "
                "the run never replaces it (choose another name or another output folder)"
            )
        if self.boundary is not None and STAGING_NAME in self.created:
            now = self.boundary.lstat(STAGING_NAME)
            if now is None or not same_unshared(now, self._own.get(STAGING_NAME)):
                raise OutputFolderError(f"{self.staging} was replaced during the run")

    def publish(self) -> list[str]:
        """Move the staged files to their names (a complete run); the names
        that could not be placed (taken meanwhile) stay in the staging folder."""
        blocked = []
        for item in sorted(self._staging.names()):
            try:
                self._staging.move(item, self.boundary)
                self._own[item] = self.boundary.lstat(item)
                self.created.append(item)
            except FileExistsError:
                blocked.append(item)
        if not blocked:
            self._staging.close()
            self._staging = None
            self.boundary.remove_own(STAGING_NAME, self._own.get(STAGING_NAME))
            self.created.remove(STAGING_NAME)
        return blocked

    def keep_incomplete(self) -> str | None:
        """The staging folder becomes ``incomplete/`` (if it holds anything)."""
        staging, self._staging = self._staging, None
        if staging is None:
            staging = self.boundary.folder(STAGING_NAME)
        name = self._rename_to_incomplete(STAGING_NAME, staging)
        self.created.remove(STAGING_NAME)
        if name is not None:
            self.created.append(name)
            self._own[name] = self.boundary.lstat(name)
        return name

    def _rename_to_incomplete(self, name: str, folder: WriteBoundary) -> str | None:
        """Rename the folder ``name`` to ``incomplete`` (``incomplete-2``...),
        or remove it when it is empty; the new name, None if removed."""
        try:
            empty = not folder.names()
        finally:
            folder.close()
        if empty:
            os.rmdir(name, dir_fd=self.boundary.fd)
            return None
        number, target = 1, INCOMPLETE_NAME
        while True:
            try:
                self.boundary.move(name, self.boundary, target)
                return target
            except FileExistsError:
                number += 1
                target = f"{INCOMPLETE_NAME}-{number}"

    def owns(self, name: str) -> bool:
        """Whether the entry ``name`` is one this run made and still there as made."""
        info = self.boundary.lstat(name) if self.boundary is not None else None
        return (
            name in self.created and info is not None and same_unshared(info, self._own.get(name))
        )

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

    # ------------------------------------------------------------- R lines
    def copy_own_file(self, source: str, target: str) -> None:
        """Copy the run's file ``source`` to the new entry ``target`` of the
        folder (OutputFolderError / FileExistsError when it may not be made)."""
        self.check_name(target)
        if target in self.created:
            raise FileExistsError(errno.EEXIST, "this run already wrote it", target)
        reading = self.boundary.open_own(source, self._own.get(source), os.O_RDONLY)
        with os.fdopen(reading, "rb") as original:
            copy = self._make_own_file(target, binary=True)
            try:
                with copy:
                    copy_stream(original, copy)
            except BaseException:  # a full disk: no partial copy left behind
                self.boundary.remove_own(target, self._own.pop(target))
                self.created.remove(target)
                raise
        self._own[target] = self.boundary.lstat(target)

    def open_own_file(self, name: str):
        """One of the run's files, for reading (never a name taken meanwhile)."""
        return os.fdopen(self.boundary.open_own(name, self._own.get(name), os.O_RDONLY), "rb")

    # --------------------------------------------------------------- summary
    def write_summary(self, data: dict, running: bool = False) -> None:
        """summary.json, replaced whole (written aside, then renamed); a
        RUNNING one is padded to leave room for the final one (a full disk)."""
        data = dict(data)
        files = sorted(set(self.created) | {SUMMARY_NAME})
        data["output"] = {
            "files": files,
            "started": _clock(self.started),
            "pid": os.getpid(),
            "moved_aside": self.moved_aside.name if self.moved_aside else None,
        }
        entries = self._entries(finished=not running)
        text = _signed_text(data, self.boundary, entries, self.previous_records)
        if running:
            text = text.ljust(SUMMARY_RESERVE - 1) + "\n"
        self._own[SUMMARY_NAME] = self._replace_summary(text)
        if SUMMARY_NAME not in self.created:
            self.created.append(SUMMARY_NAME)

    def write_summary_in_place(self, data: dict) -> None:
        """The final summary written over the RUNNING one, in its place: no
        new disk block is needed. Only the status, message and manifest (or
        the status alone if they do not fit)."""
        own = self._own.get(SUMMARY_NAME)
        if own is None:
            raise FileNotFoundError(errno.ENOENT, "no summary written yet", SUMMARY_NAME)
        files = sorted(set(self.created) | {SUMMARY_NAME})
        short = {key: data.get(key) for key in ("deck", "status", "message")}
        short["output"] = {"files": files, "started": _clock(self.started), "pid": os.getpid()}
        text = _signed_text(short, self.boundary, self._entries(True), self.previous_records)
        if len(text.encode()) >= own.st_size:
            short.pop("output")
            text = json.dumps(short)
        encoded = text.encode()[: own.st_size - 1]
        descriptor = self.boundary.open_own(SUMMARY_NAME, own)
        try:
            os.pwrite(descriptor, encoded.ljust(own.st_size - 1) + b"\n", 0)
        finally:
            os.close(descriptor)

    def _entries(self, finished: bool) -> dict:
        """The manifest's entries: each name this run made, as it is now."""
        entries = {}
        for name in self.created:
            if name == SUMMARY_NAME:
                continue
            info = self.boundary.lstat(name)
            if info is not None and same_unshared(info, self._own.get(name)):
                entries[name] = previous_results.entry_record(self.boundary, name, finished)
        return entries

    def _replace_summary(self, text: str) -> os.stat_result:
        """Write ``text`` aside, then rename it over summary.json; nothing is
        left aside when the write fails (a full disk)."""
        stream = self.boundary.create(SUMMARY_TEMP)
        temporary = os.fstat(stream.fileno())
        try:
            with stream:
                stream.write(text)
            self.boundary.replace_own(SUMMARY_TEMP, SUMMARY_NAME, self._own.get(SUMMARY_NAME))
        except BaseException:
            try:
                self.boundary.remove_own(SUMMARY_TEMP, temporary)
            except OSError:
                pass
            raise
        return self.boundary.lstat(SUMMARY_NAME)


def _signed_text(
    data: dict, boundary: WriteBoundary, entries: dict, previous: dict | None = None
) -> str:
    """The summary as written: indented JSON with its signed manifest."""
    data = dict(data)
    manifest.sign(data, boundary.info, entries, previous)
    return json.dumps(data, indent=1)


def _clock(seconds: float) -> str:
    return time.strftime("%Y-%m-%dT%H:%M:%S", time.localtime(seconds))


def lock_record(descriptor: int) -> dict:
    """What a lock file says about its run (pid, command...), {} if unreadable."""
    try:
        text = os.pread(descriptor, LOCK_RECORD_SIZE, 0).decode("utf-8", "replace")
        record = json.loads(text)
    except (OSError, ValueError):
        return {}
    return record if isinstance(record, dict) else {}


def describe_record(record: dict | None) -> str:
    """``during IMPR_TABLE (d.comm:3)``, ``after ...``, or ''."""
    if not record or not isinstance(record.get("command"), str):
        return ""
    command = re.sub(r"[^A-Za-z0-9_.]", "?", record["command"])[:64]
    where = ""
    if isinstance(record.get("file"), str) and isinstance(record.get("line"), int):
        name = re.sub(r"[^\w.+-]", "?", record["file"])[:200]
        where = f" ({name}:{record['line']})"
    return f"{'during' if record.get('running') else 'after'} {command}{where}"


def settled_summary(data: dict, record: dict | None) -> dict:
    """The summary of a run that died while RUNNING: status KILLED, saying
    where it was (from its lock file's record)."""
    settled = dict(data)
    where = describe_record(record)
    settled["status"] = "KILLED"
    settled["message"] = (
        f"the run ended without writing its result{' ' + where if where else ''}: it was "
        "killed (SIGKILL, the out-of-memory killer, or the time limit's last backstop "
        "SIGVTALRM) or the machine stopped; its files are under incomplete/"
    )
    settled["settled"] = _clock(time.time())
    return settled


def _append_own_log(boundary: WriteBoundary, entries: dict, text: str) -> None:
    """End a dead run's message.log with what became of it (its own log only)."""
    info = boundary.lstat(LOG_NAME)
    if info is None or not manifest.matches(entries.get(LOG_NAME), info):
        return
    try:
        descriptor = boundary.open_own(LOG_NAME, info, os.O_WRONLY | os.O_APPEND)
    except OSError:
        return
    try:
        os.write(descriptor, f"\n[{text}]\n".encode("utf-8", "replace"))
        entries[LOG_NAME] = manifest.identity(os.fstat(descriptor))
    except OSError:
        pass
    finally:
        os.close(descriptor)


def list_in_summary(path: Path, name: str) -> bool:
    """Add the entry ``name`` (written after the run, e.g. by ``asterlite
    report``) to the verified summary of the folder ``path``; False when the
    summary does not verify (then nothing is changed)."""
    folder = OutputFolder(path)
    try:
        folder.take()
        earlier = read_earlier_result(folder.boundary)
        info = folder.boundary.lstat(name)
        if earlier is None or not earlier.verified or info is None:
            return False
        entries = dict(earlier.entries)
        entries[name] = manifest.identity(info)
        data = dict(earlier.data)
        files = sorted(set(data.get("output", {}).get("files", [])) | {name})
        data["output"] = {**data.get("output", {}), "files": files}
        folder._own[SUMMARY_NAME] = folder.boundary.lstat(SUMMARY_NAME)
        folder._replace_summary(_signed_text(data, folder.boundary, entries, earlier.previous))
        return True
    except (OSError, OutputFolderError):
        return False
    finally:
        folder.release()
