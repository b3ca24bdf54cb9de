"""Writing output files safely: the rules of ``aidl render``'s ``-o`` (docs/outputs.md,
"Writing files") shared by the API's ``Result.write``, the command line (``render``,
``import``, ``fmt``), the MCP server, batch and ``aidl generate``: every file AIDL writes
goes through :func:`stage` and :func:`replace` (or :func:`write_in_dir`), here.

* :func:`check_output_path`: an output path as ``aidl render`` accepts it (a known
  extension, not a folder, not the program, not a link unless asked, never a link another
  user planted in ``/tmp``, not a read-only file unless forced, not a FIFO, device or
  socket); raises :class:`WriteError`.
* :func:`stage` / :func:`replace` / :func:`write_atomic`: the data written to a temporary
  file beside the target, then renamed over it (a link planted after the check is replaced,
  never followed).
* :func:`write_in_dir`: the same in a folder given by its descriptor (``aidl import``, the
  MCP server).
* :func:`not_regular` / :class:`NotRegularFile`: **only a regular file is ever replaced**.
  An existing target that is a FIFO, a character or block device (``/dev/null``), a socket
  or a directory is refused, never renamed over (issue 48: ``aidl import x.dxf -o
  /dev/null`` run as root replaced the system's ``/dev/null`` with a regular file).
* :func:`planted_link`: the kernel's ``fs.protected_symlinks`` rule for a link in a sticky
  world-writable folder.

What the check guarantees: the kind of the target is read with ``lstat`` (the node itself,
never opened: a FIFO is never waited on, a device never touched, a link never followed) when
the data is staged, for a clear error before anything moves.  The rename itself is
``renameat2(2)`` with ``RENAME_EXCHANGE`` (Linux 3.15+, glibc 2.28+): the staged file and
the target swap names in one step, and the node now under the temporary name, the old
target as it was at that instant, is looked at; a regular file (or a link) is removed, any
other node is swapped back, unchanged, and refused.  So no FIFO, device, socket or directory
is ever replaced, even one put there after every check (by the same name in the same folder,
``dir_fd`` when the folder was opened); at worst it spends a moment under the temporary
name.  A new name is taken with ``RENAME_NOREPLACE``.  Where the system has no
``renameat2`` (another kernel or libc, a filesystem without the flags) the check is repeated
just before a plain ``rename(2)``, leaving the one system call between them open.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import errno
import os
import stat as S
from functools import lru_cache
from pathlib import Path


class WriteError(OSError):
    """An output file cannot be written where asked (the program itself, a directory, an
    unknown extension, a folder that does not exist or is not writable, a FIFO or device);
    the message says why."""


class NotRegularFile(WriteError):
    """The existing target is not a regular file (``kind``: ``a FIFO``, ``a character
    device``, ``a block device``, ``a socket``, ``a directory``): refused, left as it is.
    ``path``: the path as the user gave it."""

    def __init__(self, path: str | os.PathLike, kind: str, hint: str | None = None) -> None:
        self.path, self.kind = os.fspath(path), kind
        super().__init__(refusal(path, kind, hint))

    def __str__(self) -> str:
        return self.args[0]


_KINDS = ((S.S_ISFIFO, "a FIFO"), (S.S_ISCHR, "a character device"),
          (S.S_ISBLK, "a block device"), (S.S_ISSOCK, "a socket"), (S.S_ISDIR, "a directory"))


def kind_of(mode: int) -> str | None:
    """What a file of ``st_mode`` ``mode`` is when it must not be replaced (``a FIFO``, ``a
    character device``, ...), or None for a regular file or a symbolic link (a link is
    replaced itself, never followed, by a rename)."""
    for test, kind in _KINDS:
        if test(mode):
            return kind
    return None


def not_regular(path: str | os.PathLike, dir_fd: int | None = None) -> str | None:
    """What the existing ``path`` (relative to the folder ``dir_fd`` when given) is when a
    write must not replace it (``a FIFO``, ``a character device``, ``a block device``, ``a
    socket``, ``a directory``), else None (a regular file, a symbolic link, nothing there).
    ``lstat`` only: nothing is opened or followed."""
    try:
        st = os.stat(path, dir_fd=dir_fd, follow_symlinks=False)
    except (FileNotFoundError, NotADirectoryError):
        return None
    return kind_of(st.st_mode)


def refusal(path: str | os.PathLike, kind: str, hint: str | None = None) -> str:
    """The message refusing to replace ``path``, which is ``kind``: which path, what it is,
    what to do (``hint``; default: choose another path)."""
    return (f"`{os.fspath(path)}` is {kind}, not a regular file; outputs are written by "
            f"replacing a regular file, so it is left as it is: "
            f"{hint or 'choose another path'}")


def check_replaceable(path: str | os.PathLike, shown: str | os.PathLike | None = None,
                      dir_fd: int | None = None, hint: str | None = None) -> None:
    """Raise :class:`NotRegularFile` (naming ``shown``, default ``path``) when ``path``
    exists and is not a regular file or a link (:func:`not_regular`)."""
    kind = not_regular(path, dir_fd)
    if kind is not None:
        raise NotRegularFile(shown if shown is not None else path, kind, hint)


def planted_link(out: Path) -> str | None:
    """Why the symbolic link ``out`` must not be followed even when asked to, or None: the
    kernel's ``fs.protected_symlinks`` rule — in a sticky world-writable folder (``/tmp``) a
    link is followed only by its owner or the folder's owner, since another user may have
    planted it to aim this write at a file of yours."""
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
    ``force``), not a FIFO, device or socket (nor a link to one: :class:`NotRegularFile`).
    Raises :class:`WriteError`."""
    from ..writers import FORMATS
    out = Path(path)
    if out.suffix.lower() not in FORMATS:
        raise WriteError(f"cannot tell the format of `{out}` from its extension; use one of "
                         + ", ".join(sorted(FORMATS)))
    if out.is_dir():
        raise WriteError(f"`{out}` is a directory; give a file name, e.g. {out / 'part.svg'}")
    check_replaceable(out)
    real = os.path.realpath(out)
    if program and os.path.exists(program) and os.path.exists(real) \
            and os.path.samefile(real, program):
        raise WriteError(f"`{out}` is the program being compiled; refusing to overwrite it")
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
    if follow_symlinks and kind_of(st.st_mode):
        raise NotRegularFile(out, f"a symbolic link to {kind_of(st.st_mode)} (`{real}`)")
    if not force and read_only(st, real):
        raise WriteError(f"`{out}` is read-only (mode {S.S_IMODE(st.st_mode):04o}); refusing "
                         "to replace it (force=True replaces it)")
    return out


def stage(out, data: bytes, follow_symlinks: bool = False,
          hint: str | None = None) -> tuple[str, Path]:
    """Write ``data`` to a temporary file beside ``out`` and return ``(temporary path,
    target)``; :func:`replace` of the one over the other finishes the write.  With
    ``follow_symlinks`` the target is a symlink's target (the link is kept), else the path
    itself (a link planted after the check is never followed); a new file gets ``0666 &
    ~umask``, an existing one keeps its mode.  A target that is not a regular file is
    refused before anything is written (:class:`NotRegularFile`, ``hint``: what to do).
    Raises ``OSError`` (nothing left behind)."""
    import tempfile
    target = Path(os.path.realpath(out)) if follow_symlinks else Path(os.path.abspath(out))
    check_replaceable(target, out, hint=hint)
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


def replace(tmp: str | os.PathLike, target: str | os.PathLike,
            shown: str | os.PathLike | None = None, dir_fd: int | None = None,
            hint: str | None = None) -> None:
    """Rename the staged ``tmp`` over ``target`` (both relative to the folder ``dir_fd`` when
    given): the last step of every write.  A target that is not a regular file (or a link) is
    refused (:class:`NotRegularFile` naming ``shown``) and left as it is, ``tmp`` too (the
    caller removes it): checked first, and again on the node the atomic exchange took out
    (see the module text).  Raises ``OSError``."""
    shown = shown if shown is not None else target
    check_replaceable(target, shown, dir_fd, hint)
    for _ in range(RETRIES):
        try:
            if not _renameat2(tmp, target, dir_fd, _RENAME_EXCHANGE):
                break                                   # no renameat2 here: plain rename
        except FileNotFoundError:                       # nothing at the target: take the name
            try:
                if _renameat2(tmp, target, dir_fd, _RENAME_NOREPLACE):
                    return
                break
            except FileExistsError:                     # something came meanwhile: again
                continue
        # the old target now has the temporary name: only a regular file (or link) may go
        kind = not_regular(tmp, dir_fd)
        if kind is not None:
            _put_back(tmp, target, dir_fd)
            raise NotRegularFile(shown, kind, hint)
        discard(tmp, dir_fd)
        return
    else:
        # the name came and went RETRIES times between two calls: never fall back to a plain
        # rename here (it could go over whatever came last: a FIFO, a device)
        raise OSError(errno.EAGAIN, "the output path keeps being replaced by another process "
                      "while it is written; nothing was written", os.fspath(shown))
    check_replaceable(target, shown, dir_fd, hint)
    if dir_fd is None:
        os.replace(tmp, target)
    else:
        os.replace(tmp, target, src_dir_fd=dir_fd, dst_dir_fd=dir_fd)


def _put_back(tmp, target, dir_fd: int | None) -> None:
    """The node an exchange took out (now at ``tmp``) goes back to ``target``, unchanged:
    swapped with the staged file, or renamed back if the target's name is gone meanwhile.
    When another process removed the staged file from ``target`` and put its own node there
    meanwhile, the swap moves that node to ``tmp``: it is left there, moved but never
    removed (only one node can have the name, and neither is ours to delete)."""
    try:
        _renameat2(tmp, target, dir_fd, _RENAME_EXCHANGE)
    except FileNotFoundError:
        try:
            _renameat2(tmp, target, dir_fd, _RENAME_NOREPLACE)
        except OSError:
            pass                    # something else took the name: the node stays at tmp


def discard(tmp, dir_fd: int | None = None) -> None:
    """Remove the staged file ``tmp`` after a failed write: only a regular file (a node that
    an exchange could not put back is left where it is); errors are ignored."""
    try:
        if not_regular(tmp, dir_fd) is None:
            os.unlink(tmp, dir_fd=dir_fd)
    except OSError:
        pass


_AT_FDCWD = -100
RETRIES = 16        # exchanges tried while another process makes and removes the target
_RENAME_NOREPLACE, _RENAME_EXCHANGE = 1, 2


@lru_cache(maxsize=1)
def _libc_renameat2():
    """libc's ``renameat2`` (glibc 2.28+), or None."""
    try:
        fn = ctypes.CDLL(ctypes.util.find_library("c") or None, use_errno=True).renameat2
    except (OSError, AttributeError):
        return None
    fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                   ctypes.c_uint]
    fn.restype = ctypes.c_int
    return fn


def _renameat2(src, dst, dir_fd: int | None, flags: int) -> bool:
    """``renameat2(src, dst, flags)`` in the folder ``dir_fd`` (else the working folder);
    True when done, False when this system cannot (no such call, or flags the filesystem
    does not take); raises ``OSError`` (``FileNotFoundError``, ``FileExistsError``, ...)."""
    fn = _libc_renameat2()
    if fn is None:
        return False
    d = _AT_FDCWD if dir_fd is None else dir_fd
    if fn(d, os.fsencode(src), d, os.fsencode(dst), flags) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.EOPNOTSUPP):
        return False
    raise OSError(err, os.strerror(err), os.fspath(dst))


def read_only(st: os.stat_result, path, dir_fd: int | None = None) -> bool:
    """Whether the regular file ``path`` (``st``: its stat) is read-only for this user: no
    write bit for its owner (so for root too, whom ``os.access`` lets through), or no write
    access."""
    return S.S_ISREG(st.st_mode) and (not st.st_mode & S.S_IWUSR
                                      or not os.access(path, os.W_OK, dir_fd=dir_fd))


def edit_program(path: Path, data: bytes) -> None:
    """Rewrite the program file ``path`` with ``data`` as an edit (``aidl set``, ``aidl fmt``):
    through a symbolic link (the file it names is replaced atomically, the link kept), never
    over a read-only file (issue 110: ``aidl set`` replaced a link by a regular file and
    rewrote a 0444 file).  Raises :class:`WriteError`."""
    real = os.path.realpath(path)
    try:
        st = os.stat(real)
    except OSError:
        st = None
    if st is not None and read_only(st, real):
        raise WriteError(f"`{path}` is read-only (mode {S.S_IMODE(st.st_mode):04o}); "
                         "refusing to edit it (make it writable first: chmod u+w)")
    write_atomic(Path(path), data, follow_symlinks=True)


def write_atomic(out: Path, data: bytes, follow_symlinks: bool = False,
                 hint: str | None = None) -> None:
    """Write ``data`` to ``out`` through a temporary file beside it, renamed over it
    (:func:`stage`, then :func:`replace`): never over a FIFO, device, socket or directory.
    Raises :class:`WriteError` (:class:`NotRegularFile` for those)."""
    tmp = None
    try:
        tmp, target = stage(out, data, follow_symlinks, hint)
        replace(tmp, target, out, hint=hint)
        tmp = None
    except NotRegularFile:
        raise
    except OSError as e:
        raise WriteError(f"cannot write `{out}`: {e.strerror or e}") from None
    finally:
        if tmp is not None:
            discard(tmp)


def write_in_dir(dfd: int, name: str, data: bytes, shown: str | None = None,
                 hint: str | None = None) -> None:
    """Write ``data`` as the file ``name`` of the folder ``dfd``: a temporary file made there
    (``O_CREAT | O_EXCL | O_NOFOLLOW``), then renamed over ``name`` (:func:`replace`).  A new
    file gets ``0666 & ~umask``, an existing regular file keeps its mode; a link at ``name``
    is refused (checked without following it), and one planted after the check is replaced
    by the rename, never written through; a FIFO, device, socket or directory is refused
    (:class:`NotRegularFile`, before anything is written and again before the rename).
    ``shown``: the path as the user gave it, for messages.  Raises :class:`WriteError`,
    :class:`aidl_lang.host.files.FileRefused` or ``OSError`` (nothing left behind)."""
    import secrets

    from ...host.files import CLOEXEC, NOFOLLOW, FileRefused
    shown = shown or name
    if os.sep in name or name in ("", ".", ".."):
        raise FileRefused(f"`{shown}` is not a file name")
    try:
        st = os.stat(name, dir_fd=dfd, follow_symlinks=False)
    except FileNotFoundError:
        mask = os.umask(0)
        os.umask(mask)
        mode = 0o666 & ~mask
    else:
        if S.S_ISLNK(st.st_mode):
            raise FileRefused(f"`{shown}` is a symbolic link; refusing to write through it")
        if kind_of(st.st_mode):
            raise NotRegularFile(shown, kind_of(st.st_mode), hint)
        mode = S.S_IMODE(st.st_mode)
        if read_only(st, name, dfd):
            raise FileRefused(f"`{shown}` is read-only (mode {mode:04o}); refusing to "
                              "replace it (make it writable first: chmod u+w)")
    tmp = f".{name[:200]}.{secrets.token_hex(6)}.tmp"
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | NOFOLLOW | CLOEXEC, 0o600,
                 dir_fd=dfd)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            os.fchmod(f.fileno(), mode)
        replace(tmp, name, shown, dfd, hint)
    except BaseException:
        discard(tmp, dfd)
        raise
