"""Opening files that a hostile neighbour may be changing: the one place that reads a program,
an import or an agent's file and writes an output without following a link it did not check
(issue 37, "Security: races and links").

Checking a path and then opening it by name leaves a window in which another process can
swap a file or a folder on the path for a symbolic link to something else.  These helpers
close it by opening once and checking what was opened:

* :func:`open_dir_beneath` walks a relative path from a trusted folder one component at a
  time, each opened relative to the previous folder's descriptor with ``O_NOFOLLOW |
  O_DIRECTORY``: a component that is (or has just become) a link, or is not a folder, fails;
  nothing outside the folder is ever reached (asked to, it makes the missing folders the
  same way).
* :func:`open_beneath` does the same and opens the last component with ``O_NOFOLLOW``.
* :func:`read_regular` reads from a descriptor only when ``fstat`` says it is a regular file
  of at most ``limit`` bytes; :func:`read_file` opens a path non-blocking first (a FIFO or a
  device never hangs the reader, ``/dev/zero`` is refused before a byte is read).
* writing a file in a folder given by its descriptor (a temporary file renamed over the
  name, never over a link, a FIFO or a device) is
  :func:`aidl_lang.output.writers.write.write_in_dir`, with every other write.
* :func:`open_append` opens a journal for appending, refusing a link and anything but a
  regular file.

Every refusal is a :class:`FileRefused` (an ``OSError``) whose message says why in the
user's terms ("is a symbolic link", "is not a regular file", "is larger than N bytes").
"""
from __future__ import annotations

import errno
import os
import stat

NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
NONBLOCK = getattr(os, "O_NONBLOCK", 0)
DIRECTORY = getattr(os, "O_DIRECTORY", 0)
CLOEXEC = getattr(os, "O_CLOEXEC", 0)


class FileRefused(OSError):
    """A file that must not be read or written as asked; ``str(e)`` says why."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message

    def __str__(self) -> str:
        return self.message


def _parts(rel: str | os.PathLike) -> list[str]:
    parts = [p for p in os.fspath(rel).split(os.sep) if p not in ("", ".")]
    if os.path.isabs(os.fspath(rel)) or ".." in parts:
        raise FileRefused(f"`{os.fspath(rel)}` leaves the folder")
    return parts


def _why(e: OSError, shown: str, dfd: int | None = None, name: str = "") -> FileRefused:
    if e.errno == errno.ENOTDIR and dfd is not None:
        try:            # O_DIRECTORY | O_NOFOLLOW on a link says ENOTDIR: say what it is
            if stat.S_ISLNK(os.stat(name, dir_fd=dfd, follow_symlinks=False).st_mode):
                e = OSError(errno.ELOOP, "")
        except OSError:
            pass
    if e.errno in (errno.ELOOP, errno.EMLINK):
        return FileRefused(f"`{shown}` is (or passes through) a symbolic link; refusing to "
                           "follow it")
    if e.errno == errno.ENOTDIR:
        return FileRefused(f"`{shown}` passes through something that is not a folder")
    if e.errno == errno.ENOENT:
        return FileRefused(f"`{shown}` does not exist")
    return FileRefused(f"cannot open `{shown}`: {e.strerror or e}")


def open_dir_beneath(root: str | os.PathLike, rel: str | os.PathLike = "",
                     create: bool = False) -> int:
    """A descriptor of the folder ``root/rel``, reached from ``root`` (trusted, followed as
    given) one component of ``rel`` at a time without following a link; with ``create``, a
    missing folder is made (in the folder reached so far, ``0777 & ~umask``).  The caller
    closes it.  Raises :class:`FileRefused` (a link, not a folder, missing, ``..``)."""
    parts = _parts(rel)
    fd = os.open(os.fspath(root), os.O_RDONLY | DIRECTORY | CLOEXEC)
    try:
        for i, part in enumerate(parts):
            try:
                if create:
                    try:
                        os.mkdir(part, 0o777, dir_fd=fd)
                    except FileExistsError:
                        pass
                nxt = os.open(part, os.O_RDONLY | DIRECTORY | NOFOLLOW | CLOEXEC, dir_fd=fd)
            except OSError as e:
                raise _why(e, os.path.join(*parts[:i + 1]), fd, part) from None
            os.close(fd)
            fd = nxt
    except BaseException:
        os.close(fd)
        raise
    return fd


def open_beneath(root: str | os.PathLike, rel: str | os.PathLike,
                 flags: int = os.O_RDONLY) -> int:
    """A descriptor of the file ``root/rel`` opened with ``flags`` (``O_NOFOLLOW`` and
    ``O_NONBLOCK`` added), no component of ``rel`` followed if it is a link (see
    :func:`open_dir_beneath`).  Raises :class:`FileRefused`."""
    parts = _parts(rel)
    if not parts:
        raise FileRefused("give a file name, not the folder itself")
    dfd = open_dir_beneath(root, os.path.join(*parts[:-1]) if len(parts) > 1 else "")
    try:
        return os.open(parts[-1], flags | NOFOLLOW | NONBLOCK | CLOEXEC, dir_fd=dfd)
    except OSError as e:
        raise _why(e, os.path.join(*parts), dfd, parts[-1]) from None
    finally:
        os.close(dfd)


def read_regular(fd: int, limit: int, shown: str) -> bytes:
    """The bytes of the open file ``fd`` when it is a regular file of at most ``limit`` bytes
    (checked with ``fstat`` before reading, and again while reading: a file growing under the
    reader is cut at ``limit + 1`` and refused).  Raises :class:`FileRefused`."""
    st = os.fstat(fd)
    if not stat.S_ISREG(st.st_mode):
        raise FileRefused(f"`{shown}` is not a regular file")
    if st.st_size > limit:
        raise FileRefused(f"`{shown}` is larger than {limit} bytes ({st.st_size} bytes)")
    chunks, n = [], 0
    while n <= limit:
        b = os.read(fd, min(1 << 20, limit + 1 - n))
        if not b:
            break
        chunks.append(b)
        n += len(b)
    if n > limit:
        raise FileRefused(f"`{shown}` is larger than {limit} bytes")
    return b"".join(chunks)


def read_file(path: str | os.PathLike, limit: int, follow_symlinks: bool = True) -> bytes:
    """The bytes of the regular file ``path`` (at most ``limit``), opened non-blocking (a FIFO
    or a device is refused, never waited on or read); a link is followed unless
    ``follow_symlinks`` is False.  Raises :class:`FileRefused` (and ``OSError`` of the
    open, e.g. ``FileNotFoundError``)."""
    flags = os.O_RDONLY | NONBLOCK | CLOEXEC | (0 if follow_symlinks else NOFOLLOW)
    try:
        fd = os.open(os.fspath(path), flags)
    except OSError as e:
        if e.errno == errno.ELOOP and not follow_symlinks:
            raise _why(e, os.fspath(path)) from None
        raise
    try:
        return read_regular(fd, limit, os.fspath(path))
    finally:
        os.close(fd)


def open_append(path: str | os.PathLike):
    """``path`` opened for reading and appending (text, UTF-8; created when missing), never
    through a link and only when it is a regular file.  Raises :class:`FileRefused`."""
    p = os.fspath(path)
    try:
        fd = os.open(p, os.O_RDWR | os.O_APPEND | os.O_CREAT | NOFOLLOW | NONBLOCK | CLOEXEC,
                     0o666)
    except OSError as e:
        if e.errno == errno.ELOOP:
            raise FileRefused(f"`{p}` is a symbolic link; refusing to write through it") \
                from None
        raise
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        raise FileRefused(f"`{p}` is not a regular file")
    os.set_blocking(fd, True)
    return os.fdopen(fd, "a+", encoding="utf-8")


def is_link(path: str | os.PathLike) -> bool:
    """True when ``path`` itself is a symbolic link (not followed)."""
    return os.path.islink(os.fspath(path))
