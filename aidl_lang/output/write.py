"""Writing output files safely: the rules of ``aidl render``'s ``-o`` (docs/outputs.md,
"Writing files") shared by the API's ``Result.write``, the command line, the MCP server and
batch.

* :func:`check_output_path`: an output path as ``aidl render`` accepts it (a known
  extension, not a folder, not the program, not a link unless asked, never a link another
  user planted in ``/tmp``, not a read-only file unless forced); raises :class:`WriteError`.
* :func:`stage` / :func:`write_atomic`: the data written to a temporary file beside the
  target, then renamed over it (a link planted after the check is replaced, never followed).
* :func:`planted_link`: the kernel's ``fs.protected_symlinks`` rule for a link in a sticky
  world-writable folder.
"""
from __future__ import annotations

import os
from pathlib import Path


class WriteError(OSError):
    """An output file cannot be written where asked (the program itself, a directory, an
    unknown extension, a folder that does not exist or is not writable); the message says
    why."""


def planted_link(out: Path) -> str | None:
    """Why the symbolic link ``out`` must not be followed even when asked to, or None: the
    kernel's ``fs.protected_symlinks`` rule — in a sticky world-writable folder (``/tmp``) a
    link is followed only by its owner or the folder's owner, since another user may have
    planted it to aim this write at a file of yours."""
    import stat as S
    link, folder = os.lstat(out), os.stat(out.parent)
    if folder.st_mode & S.S_ISVTX and folder.st_mode & S.S_IWOTH \
            and link.st_uid not in (os.geteuid(), folder.st_uid):
        return (f"`{out}` is a symbolic link that another user (uid {link.st_uid}) made in the "
                f"shared folder `{out.parent}`; refusing to write through it even when asked "
                "to follow links (it may aim this write at a file of yours): write to a path of "
                "your own")
    return None


def check_output_path(path: str | os.PathLike, program: str | None = None,
                      follow_symlinks: bool = False, force: bool = False) -> Path:
    """``path`` as an output file the way ``aidl render`` accepts it: a known extension, not a
    directory, not the program ``program`` itself, not a symbolic link (unless
    ``follow_symlinks``; never one that another user made in a sticky world-writable folder
    such as /tmp, the kernel's ``fs.protected_symlinks`` rule), not a read-only file (unless
    ``force``).  Raises :class:`WriteError`."""
    from .formats import FORMATS
    out = Path(path)
    if out.suffix.lower() not in FORMATS:
        raise WriteError(f"cannot tell the format of `{out}` from its extension; use one of "
                         + ", ".join(sorted(FORMATS)))
    if out.is_dir():
        raise WriteError(f"`{out}` is a directory; give a file name, e.g. {out / 'part.svg'}")
    real = os.path.realpath(out)
    if program and os.path.exists(program) and os.path.exists(real) \
            and os.path.samefile(real, program):
        raise WriteError(f"`{out}` is the program being compiled; refusing to overwrite it")
    import stat as S
    if os.path.islink(out):
        if not follow_symlinks:
            raise WriteError(f"`{out}` is a symbolic link; refusing to write through it "
                             "(follow_symlinks=True writes the file it points to)")
        planted = planted_link(out)
        if planted:
            raise WriteError(planted)
    try:
        st = os.stat(real if follow_symlinks else out)
    except OSError:
        return out
    if S.S_ISREG(st.st_mode) and not force and (
            not st.st_mode & S.S_IWUSR or not os.access(real, os.W_OK)):
        raise WriteError(f"`{out}` is read-only (mode {S.S_IMODE(st.st_mode):04o}); refusing "
                         "to replace it (force=True replaces it)")
    return out


def stage(out, data: bytes, follow_symlinks: bool = False) -> tuple[str, Path]:
    """Write ``data`` to a temporary file beside ``out`` and return ``(temporary path,
    target)``; :func:`os.replace` of the one over the other finishes the write.  With
    ``follow_symlinks`` the target is a symlink's target (the link is kept), else the path
    itself (a link planted after the check is never followed); a new file gets ``0666 &
    ~umask``, an existing one keeps its mode.  Raises ``OSError`` (nothing left behind)."""
    import tempfile
    target = Path(os.path.realpath(out)) if follow_symlinks else Path(os.path.abspath(out))
    try:
        mode = os.stat(target).st_mode & 0o7777
    except FileNotFoundError:
        mask = os.umask(0)
        os.umask(mask)
        mode = 0o666 & ~mask
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=str(target.parent))
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.chmod(tmp, mode)
    except OSError:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
    return tmp, target


def write_atomic(out: Path, data: bytes, follow_symlinks: bool = False) -> None:
    """Write ``data`` to ``out`` through a temporary file beside it, renamed over it
    (:func:`stage`, then :func:`os.replace`).  Raises :class:`WriteError`."""
    tmp = None
    try:
        tmp, target = stage(out, data, follow_symlinks)
        os.replace(tmp, target)
        tmp = None
    except OSError as e:
        raise WriteError(f"cannot write `{out}`: {e.strerror or e}") from None
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass
