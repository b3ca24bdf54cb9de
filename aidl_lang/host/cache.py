"""The user's own cache folder: files that are slow to make and safe to remake.

``$XDG_CACHE_HOME/aidl`` (else ``~/.cache/aidl``), created 0700.  What is kept there is plain
data (JSON, text), never a pickle, and a file is read only when this user owns it and no one
else can write it (issue 15: a file another local user could plant must never be loaded).
Users: the parse table (:func:`aidl_lang.parsing.tables.data`) and the Hershey font
(:mod:`aidl_lang.geometry.shapes.text`).  Anything in the folder may be deleted at any time.
"""
from __future__ import annotations

import os
import stat
from pathlib import Path


def cache_dir() -> Path | None:
    """The cache folder, made if missing; ``None`` (cache nothing) unless it is a real
    directory owned by this user.  A folder of ours with group or other bits is narrowed to
    0700 first."""
    base = os.environ.get("XDG_CACHE_HOME", "")
    if not os.path.isabs(base):
        base = os.path.join(os.path.expanduser("~"), ".cache")
    d = os.path.join(base, "aidl")
    try:
        os.makedirs(d, mode=0o700, exist_ok=True)
        st = os.lstat(d)
        if not stat.S_ISDIR(st.st_mode) or st.st_uid != os.getuid():
            return None
        if st.st_mode & 0o077:
            os.chmod(d, 0o700)
    except OSError:
        return None
    return Path(d)


def read_owned(path: Path) -> str | None:
    """The text of ``path`` if it is a regular file owned by this user that no one else can
    write (a symbolic link is not followed); else ``None``.  Opening never blocks (a FIFO or
    a device at the path is opened non-blocking, then refused by its ``fstat``)."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0)
                     | getattr(os, "O_NONBLOCK", 0))
    except OSError:
        return None
    with os.fdopen(fd, "r", encoding="utf-8") as f:
        st = os.fstat(f.fileno())
        if not stat.S_ISREG(st.st_mode) or st.st_uid != os.getuid() or st.st_mode & 0o022:
            return None
        try:
            return f.read()
        except (OSError, UnicodeDecodeError):
            return None


def read_checked(path: Path, key: str) -> str | None:
    """The payload :func:`write_checked` stored at ``path`` under ``key``, or ``None`` when
    the file is unreadable, not ours (:func:`read_owned`), for another key, truncated or
    changed (its length and CRC-32 are kept in a header line and compared): an entry that
    fails any of this is ignored, and the caller makes it again."""
    import json
    import zlib
    text = read_owned(path)
    if text is None:
        return None
    head, sep, payload = text.partition("\n")
    if not sep:
        return None
    try:
        h = json.loads(head)
    except ValueError:
        return None
    if not isinstance(h, dict) or h.get("key") != key or h.get("len") != len(payload):
        return None
    if h.get("crc") != zlib.crc32(payload.encode("utf-8")):
        return None
    return payload


def write_checked(path: Path, key: str, payload: str) -> bool:
    """Store ``payload`` at ``path`` (:func:`write_atomic`) after a one-line header with
    ``key``, the payload's length and its CRC-32, for :func:`read_checked`."""
    import json
    import zlib
    head = json.dumps({"key": key, "len": len(payload),
                       "crc": zlib.crc32(payload.encode("utf-8"))})
    return write_atomic(path, head + "\n" + payload)


def write_atomic(path: Path, text: str) -> bool:
    """Write ``text`` to ``path`` through a temporary file beside it (mode 0600), renamed over
    it; False (and nothing left behind) when that fails."""
    import tempfile
    try:
        fd, tmp = tempfile.mkstemp(prefix="." + path.name + ".", suffix=".tmp", dir=path.parent)
    except OSError:
        return False
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, path)
        return True
    except OSError:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        return False
