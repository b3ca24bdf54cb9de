"""Per-session folders of ``aidl studio``: where a visitor's uploads live, and the only place
(besides the standard library) a visitor's program may import from or read a drawing from.

Every session (one browser tab) gets a random id (:func:`new_id`, 144 bits) and a folder
``BASE/ID`` (mode 0700) under the server's data folder.  The folder holds the visitor's uploads
(``.dxf`` and ``.svg`` drawings for ``Drawing2D``, ``.aidl`` files to import), each written by
the server with ``O_CREAT | O_EXCL | O_NOFOLLOW`` into a temporary name in the folder and
renamed over the upload's name, so nothing in it is ever a link; the program itself never
touches the disk (it is compiled from memory and only *named* ``ID/main.aidl``).  Limits:
:data:`MAX_UPLOAD` bytes per file, :data:`MAX_FILES` files and :data:`MAX_TOTAL` bytes per
session.  A folder is removed when its page closes (:meth:`Folders.close`) or after
:data:`IDLE_SECONDS` without a request (:meth:`Folders.sweep`); the server removes its data
folder on exit.

Errors: :class:`Refused` with a message for the visitor (bad id, bad name, too large).
"""
from __future__ import annotations

import os
import re
import secrets
import shutil
import time

MAX_UPLOAD = 2_000_000          # bytes of one uploaded file
MAX_FILES = 12                  # files in one session
MAX_TOTAL = 8_000_000           # bytes of one session's files
IDLE_SECONDS = 2 * 3600         # a session without a request this long is removed
_ID = re.compile(r"[A-Za-z0-9_-]{24}")
_NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]{0,63}")
KINDS = (".dxf", ".svg", ".aidl")


class Refused(Exception):
    """A session request that cannot be done; the message is for the visitor."""


def new_id() -> str:
    """A fresh session id (24 URL-safe characters)."""
    return secrets.token_urlsafe(18)


def upload_name(name: str) -> str:
    """``name`` checked as an upload's file name: letters, digits, ``.``, ``_``, ``-``, at
    most 64 characters, ending ``.dxf``, ``.svg`` or ``.aidl`` (``main.aidl`` is the program's
    own name and refused).  Raises :class:`Refused`."""
    if not isinstance(name, str) or not _NAME.fullmatch(name) or ".." in name:
        raise Refused("a file name has letters, digits, `.`, `_` and `-` only (at most 64), "
                      "such as `board.dxf`")
    if not name.lower().endswith(KINDS):
        raise Refused("upload a .dxf or .svg drawing (for Drawing2D) or an .aidl file to import")
    if name == "main.aidl":
        raise Refused("`main.aidl` is the program's own name; name the file differently")
    return name


class Folders:
    """The session folders under ``base`` (created, mode 0700)."""

    idle = IDLE_SECONDS             # s: :meth:`sweep` removes a folder idle this long

    def __init__(self, base: str | os.PathLike) -> None:
        self.base = os.path.realpath(base)
        os.makedirs(self.base, mode=0o700, exist_ok=True)
        self.last_sweep = 0.0

    def folder(self, sid: str, create: bool = True) -> str:
        """The folder of session ``sid`` (made when missing, its time of use updated).
        Raises :class:`Refused` for an id that is not one :func:`new_id` makes."""
        if not isinstance(sid, str) or not _ID.fullmatch(sid):
            raise Refused("this page's session is not valid; reload the page")
        path = os.path.join(self.base, sid)
        if create:
            try:
                os.mkdir(path, 0o700)
            except FileExistsError:
                pass
            if os.path.islink(path) or not os.path.isdir(path):
                raise Refused("this page's session is not valid; reload the page")
            os.utime(path)
        return path

    def files(self, sid: str) -> list[dict]:
        """The session's uploads: ``[{"name", "bytes"}]`` sorted by name."""
        path = self.folder(sid)
        out = []
        with os.scandir(path) as it:
            for e in it:
                if e.is_file(follow_symlinks=False) and not e.name.startswith("."):
                    out.append({"name": e.name, "bytes": e.stat(follow_symlinks=False).st_size})
        return sorted(out, key=lambda f: f["name"])

    def upload(self, sid: str, name: str, data: bytes) -> dict:
        """Store ``data`` as ``name`` in the session's folder (replacing an upload of that
        name).  Raises :class:`Refused` past the limits."""
        name = upload_name(name)
        if len(data) > MAX_UPLOAD:
            raise Refused(f"`{name}` has {len(data):,} bytes; an upload has at most "
                          f"{MAX_UPLOAD:,}")
        have = {f["name"]: f["bytes"] for f in self.files(sid)}
        if name not in have and len(have) >= MAX_FILES:
            raise Refused(f"a session holds at most {MAX_FILES} files; delete one first")
        if sum(have.values()) - have.get(name, 0) + len(data) > MAX_TOTAL:
            raise Refused(f"a session holds at most {MAX_TOTAL:,} bytes of files")
        path = self.folder(sid)
        dfd = os.open(path, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW)
        try:
            tmp = f".{name}.{secrets.token_hex(6)}"
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600,
                         dir_fd=dfd)
            try:
                with os.fdopen(fd, "wb") as f:
                    f.write(data)
                os.replace(tmp, name, src_dir_fd=dfd, dst_dir_fd=dfd)
            except BaseException:
                try:
                    os.unlink(tmp, dir_fd=dfd)
                except OSError:
                    pass
                raise
        finally:
            os.close(dfd)
        return {"name": name, "bytes": len(data)}

    def delete(self, sid: str, name: str) -> None:
        """Remove the upload ``name`` (a missing one is not an error)."""
        name = upload_name(name)
        dfd = os.open(self.folder(sid), os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW)
        try:
            os.unlink(name, dir_fd=dfd)
        except FileNotFoundError:
            pass
        finally:
            os.close(dfd)

    def close(self, sid: str) -> None:
        """Remove the session's folder and everything in it."""
        path = self.folder(sid, create=False)
        shutil.rmtree(path, ignore_errors=True)

    def ping(self) -> None:
        """Nothing to reach: a local folder (:class:`.store.RedisFolders` checks Redis)."""

    def sweep(self, now: float | None = None, every: float = 60.0) -> int:
        """Remove the folders of sessions idle for :attr:`idle` seconds (at most once per
        ``every`` seconds); returns how many."""
        now = time.time() if now is None else now
        if now - self.last_sweep < every:
            return 0
        self.last_sweep = now
        gone = 0
        with os.scandir(self.base) as it:
            for e in it:
                try:
                    if e.is_dir(follow_symlinks=False) and \
                            now - e.stat(follow_symlinks=False).st_mtime > self.idle:
                        shutil.rmtree(e.path, ignore_errors=True)
                        gone += 1
                except OSError:
                    pass
        return gone
