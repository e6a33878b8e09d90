"""The write boundary of a run's output folder.

Every entry asterlite makes, moves or rewrites in an output folder goes
through a :class:`WriteBoundary`: a descriptor of the folder taken when the
run starts, and single entry names relative to it (``openat``-style), so

- no path is ever joined: ``/``, ``.`` and ``..`` are refused as names;
- no symlink is followed: new files are created with
  ``O_CREAT | O_EXCL | O_NOFOLLOW`` (a name taken by anything fails);
- nothing is replaced by a move: ``renameat2(RENAME_NOREPLACE)``;
- an existing entry is written in place, replaced or removed only when it
  is one this run made (same device and inode) and has no other name (a
  hard link planted under the name of a run's file would otherwise have
  another file written or truncated; ``O_NOFOLLOW`` does not stop those).
"""

from __future__ import annotations

import ctypes
import errno
import os
import stat
from pathlib import Path

from asterlite.errors import AsterliteError

_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
_CREATE = os.O_WRONLY | os.O_CREAT | os.O_EXCL | _NOFOLLOW | os.O_CLOEXEC


class OutputFolderError(AsterliteError):
    """The output folder cannot be used, or a deck wants a name it may not take."""

    kind = "output folder"


def create_file(path: Path, mode: str = "w"):
    """Open a new file that must not exist yet (never through a symlink)."""
    descriptor = os.open(path, _CREATE, 0o644)
    return os.fdopen(descriptor, mode, encoding="utf-8" if "b" not in mode else None)


def entry_name(name: str) -> str:
    """``name`` if it names one entry of a folder (no path, no ``.``/``..``)."""
    if name in ("", ".", "..") or "/" in name or "\0" in name:
        raise OutputFolderError(f"{name!r} is not a file name")
    return name


# ------------------------------------------------------------ the boundary


class WriteBoundary:
    """One folder, reached through a descriptor taken when the run starts:
    every entry asterlite makes, moves or rewrites in the output folder goes
    through here, by single name (never a path, never through a symlink)."""

    def __init__(self, path: Path, descriptor: int):
        self.path = Path(path)
        self.fd = descriptor
        self.info = os.fstat(descriptor)

    @classmethod
    def open(cls, path: Path) -> WriteBoundary:
        """The folder the user named (a symlink to it is the user's choice)."""
        return cls(path, os.open(path, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC))

    def folder(self, name: str) -> WriteBoundary:
        """A folder inside this one (not through a symlink)."""
        flags = os.O_RDONLY | os.O_DIRECTORY | _NOFOLLOW | os.O_CLOEXEC
        return WriteBoundary(self.path / name, os.open(entry_name(name), flags, dir_fd=self.fd))

    def close(self) -> None:
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1

    def names(self) -> list[str]:
        return os.listdir(self.fd)

    def lstat(self, name: str) -> os.stat_result | None:
        try:
            return os.stat(entry_name(name), dir_fd=self.fd, follow_symlinks=False)
        except FileNotFoundError:
            return None

    def create(self, name: str, binary: bool = False):
        """A new file (fails if the name exists, whatever it is)."""
        descriptor = os.open(entry_name(name), _CREATE, 0o644, dir_fd=self.fd)
        if binary:
            return os.fdopen(descriptor, "wb")
        return os.fdopen(descriptor, "w", encoding="utf-8")

    def mkdir(self, name: str) -> None:
        os.mkdir(entry_name(name), 0o755, dir_fd=self.fd)

    def move(self, name: str, into: WriteBoundary, new_name: str | None = None) -> None:
        """Rename ``name`` to ``new_name`` in ``into``; FileExistsError if taken."""
        target = entry_name(new_name or name)
        entry_name(name)
        if _renameat2 is not None:
            result = _renameat2(self.fd, os.fsencode(name), into.fd, os.fsencode(target), 1)
            if result == 0:
                return
            code = ctypes.get_errno()
            if code not in (errno.ENOSYS, errno.EINVAL):  # a file system without the flag
                raise OSError(code, os.strerror(code), str(into.path / target))
        if into.lstat(target) is not None:
            raise FileExistsError(errno.EEXIST, "already exists", str(into.path / target))
        os.rename(name, target, src_dir_fd=self.fd, dst_dir_fd=into.fd)

    def replace_own(self, name: str, target: str, own: os.stat_result | None) -> None:
        """Rename ``name`` over ``target``, which must be absent or the entry
        ``own`` (this run's, unshared)."""
        there = self.lstat(target)
        if there is not None and not same_unshared(there, own):
            raise FileExistsError(errno.EEXIST, "not this run's file", str(self.path / target))
        os.replace(entry_name(name), entry_name(target), src_dir_fd=self.fd, dst_dir_fd=self.fd)

    def open_own(self, name: str, own: os.stat_result | None, flags: int = os.O_WRONLY) -> int:
        """A descriptor on ``name`` for writing in place, only when it is the
        entry ``own`` with no other name (a hard link planted there is not)."""
        descriptor = os.open(entry_name(name), flags | _NOFOLLOW | os.O_CLOEXEC, dir_fd=self.fd)
        if not same_unshared(os.fstat(descriptor), own):
            os.close(descriptor)
            raise FileExistsError(errno.EEXIST, "not this run's file", str(self.path / name))
        return descriptor

    def remove_own(self, name: str, own: os.stat_result | None) -> None:
        """Unlink ``name`` (a file) or remove it (an empty folder) if it is ``own``."""
        there = self.lstat(name)
        if there is None or own is None or (there.st_dev, there.st_ino) != (own.st_dev, own.st_ino):
            return
        if stat.S_ISDIR(there.st_mode):
            os.rmdir(name, dir_fd=self.fd)
        else:
            os.unlink(name, dir_fd=self.fd)

    def read_regular(self, name: str, cap: int) -> bytes | None:
        """The bytes of a regular file ``name`` of at most ``cap`` bytes, else
        None (absent, a symlink, a FIFO, too large)."""
        flags = os.O_RDONLY | _NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC
        try:
            descriptor = os.open(entry_name(name), flags, dir_fd=self.fd)
        except OSError:
            return None
        try:
            info = os.fstat(descriptor)
            if not stat.S_ISREG(info.st_mode) or info.st_size > cap:
                return None
            chunks, left = [], info.st_size
            while left > 0:
                chunk = os.read(descriptor, min(left, 1 << 20))
                if not chunk:
                    break
                chunks.append(chunk)
                left -= len(chunk)
            return b"".join(chunks)
        finally:
            os.close(descriptor)


def same_unshared(info: os.stat_result, own: os.stat_result | None) -> bool:
    """``info`` is the entry ``own`` and has no other name."""
    if own is None or (info.st_dev, info.st_ino) != (own.st_dev, own.st_ino):
        return False
    return stat.S_ISDIR(info.st_mode) or info.st_nlink == 1


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


def copy_stream(source, target) -> None:
    while True:
        chunk = source.read(1 << 20)
        if not chunk:
            return
        target.write(chunk)


def replace_outside(source, target: Path) -> None:
    """Write the stream ``source`` at ``target``, outside the output folder
    (``asterlite run --allow-result-paths`` only): a new file beside it,
    renamed over it, so a symlink or a second name there is replaced, never
    written through. Its folder must exist: none is made."""
    folder = WriteBoundary.open(Path(target).parent)
    temporary = f".asterlite-{os.getpid()}.tmp"
    try:
        copy = folder.create(temporary, binary=True)
        made = os.fstat(copy.fileno())
        try:
            with copy:
                copy_stream(source, copy)
            os.replace(
                temporary, entry_name(Path(target).name), src_dir_fd=folder.fd, dst_dir_fd=folder.fd
            )
        except BaseException:
            folder.remove_own(temporary, made)
            raise
    finally:
        folder.close()
