"""Where programs come from: the standard library folder and the one import resolver
(docs/language.md §2.2 "import" and §8.2 "The import sandbox").

Every stage that follows an ``import`` — the static checker, the interpreter and the language
server — calls :func:`load_import`, which resolves the path and reads the file in one place,
before anything else looks at it.  A path is allowed when its *real* path (every symlink
resolved) is a regular ``.aidl`` file of at most :data:`MAX_IMPORT_BYTES` inside the importing
file's folder tree, or inside the bundled standard library for ``std/NAME.aidl``.  Anything
else raises :class:`ImportRefused`, whose message names only the path as written in the
program: nothing about the target (its contents, its kind, names defined in it, its absolute
path) reaches a diagnostic.
"""
from __future__ import annotations

import os
from pathlib import Path

from ..base.diagnostics import STDLIB
from ..base.limits import MAX_SOURCE_BYTES

# The example programs (``examples/*.aidl``, ``examples/generators``, ``examples/parts``):
# read by ``aidl prompt``, the MCP server (``aidl://examples/``) and the studio's gallery.
# Always the folder inside the package: a link to the repository's ``examples/`` in a
# checkout, the files themselves in the sdist and the wheel (never ``site-packages/examples``,
# which belongs to nobody).
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

MAX_IMPORT_BYTES = MAX_SOURCE_BYTES     # size of one imported file
MAX_IMPORT_PATH = 255            # characters of an import path as written
MAX_DRAWING_BYTES = 20_000_000   # size of one DXF or SVG drawing (Drawing2D, `aidl import`)
_SANDBOX_HINT = ("import only .aidl files in this file's folder tree (a relative path without "
                 "`..` leaving it), or `std/NAME.aidl`")


class ImportRefused(Exception):
    """An import that cannot be read: ``code`` (E0114), ``message``, ``hint`` and
    ``suggestions`` (file names of the same folder inside the sandbox, never outside it)."""

    def __init__(self, message: str, hint: str = _SANDBOX_HINT, suggestions=None,
                 code: str = "E0114"):
        super().__init__(message)
        self.code = code
        self.message = message
        self.hint = hint
        self.suggestions = list(suggestions or [])


def _inside(p: str, root: str) -> bool:
    return p == root or p.startswith(root.rstrip(os.sep) + os.sep)


def resolve_import(raw: str, importer: str) -> Path:
    """The real path of ``import "raw"`` written in the file ``importer``.

    Raises :class:`ImportRefused` for an overlong path, an absolute path, a path leaving the
    importing file's folder tree (lexically or through a symlink), a target that is not a
    regular ``.aidl`` file (directory, FIFO, device, a symlink to one), or a missing file (with
    did-you-mean from the same folder, which is inside the sandbox)."""
    if len(raw) > MAX_IMPORT_PATH or any(len(part) > 200 for part in raw.split("/")):
        raise ImportRefused(f"import path is too long ({len(raw)} characters)",
                            hint=f"import paths have at most {MAX_IMPORT_PATH} characters; "
                                 "name the file shorter")
    if "\0" in raw or "\\" in raw:
        raise ImportRefused("import path has a character that cannot be in a path",
                            hint="write the path with `/` between folder names")
    if raw.startswith(("std/", "std:")):
        base = str(STDLIB.resolve())
        rel = raw[4:]
        root = base
    else:
        base = os.path.dirname(os.path.realpath(importer))
        rel = raw
        # a file of the standard library may import its neighbours; a user file only its tree
        root = base
    if not rel.endswith(".aidl"):
        rel += ".aidl"
    if os.path.isabs(rel) or rel.startswith("~"):
        raise ImportRefused(f"import `{raw}` leaves the project folder")
    lexical = os.path.normpath(os.path.join(base, rel))
    if not _inside(lexical, root):
        raise ImportRefused(f"import `{raw}` leaves the project folder")
    try:
        real = os.path.realpath(lexical)
    except (OSError, ValueError):
        raise ImportRefused(f"cannot import `{raw}`")
    if not os.path.lexists(lexical):
        folder = os.path.dirname(lexical)
        cands = []
        if _inside(os.path.realpath(folder), root) and os.path.isdir(folder):
            try:
                cands = sorted(n for n in os.listdir(folder) if n.endswith(".aidl"))[:200]
            except OSError:
                cands = []
        from ..base.diagnostics import did_you_mean
        raise ImportRefused(f"cannot find `{raw}` to import",
                            hint="the path is relative to this file's folder; `std/NAME.aidl` "
                                 "is the standard library",
                            suggestions=did_you_mean(os.path.basename(lexical), cands))
    if not _inside(real, root) or not real.endswith(".aidl"):
        # a symlink leading out of the tree, or to something that is not a program
        raise ImportRefused(f"import `{raw}` is not a .aidl file inside the project folder")
    return Path(real)


def read_import(real: Path, raw: str) -> str:
    """Read a resolved import: a regular file of at most ``MAX_IMPORT_BYTES``, UTF-8 (a BOM
    is dropped).  ``real`` has no link in it (:func:`resolve_import` took its realpath), so
    it is opened from ``/`` one folder at a time, each relative to the previous one's
    descriptor with ``O_NOFOLLOW | O_DIRECTORY`` (:func:`aidl_lang.host.files.open_beneath`): a
    folder on the path swapped for a link after the check is refused, never followed out of
    the project.  Opening never blocks (FIFOs and devices are refused before reading)."""
    from ..host.files import FileRefused, open_beneath, read_regular
    shown = os.fspath(real)
    try:
        fd = open_beneath(os.sep, os.path.relpath(shown, os.sep))
    except FileRefused as e:
        if "symbolic link" in e.message:
            raise ImportRefused(f"import `{raw}` passed through a symbolic link while it was "
                                "read; refusing to follow it") from None
        raise ImportRefused(f"cannot read `{raw}`") from None
    except OSError:
        raise ImportRefused(f"cannot read `{raw}`") from None
    try:
        data = read_regular(fd, MAX_IMPORT_BYTES, raw)
    except FileRefused as e:
        if "larger than" in e.message:
            raise ImportRefused(f"import `{raw}` is larger than {MAX_IMPORT_BYTES} bytes",
                                hint="split it into smaller files") from None
        raise ImportRefused(f"import `{raw}` is not a .aidl file inside the project "
                            "folder") from None
    finally:
        os.close(fd)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise ImportRefused(f"import `{raw}` is not UTF-8 text",
                            hint="save the imported file as UTF-8")
    return text[1:] if text.startswith("\ufeff") else text


def load_import(raw: str, importer: str) -> tuple[Path, str]:
    """Resolve and read ``import "raw"`` of ``importer``: ``(real path, text)``; raises
    :class:`ImportRefused` (see :func:`resolve_import`, :func:`read_import`)."""
    real = resolve_import(raw, importer)
    return real, read_import(real, raw)


class SourceRefused(Exception):
    """The main file cannot be compiled as given (E0004): missing, not a regular file (a
    FIFO, a device, a folder), larger than :data:`MAX_IMPORT_BYTES`, or not UTF-8;
    ``message`` says which."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message

    def diagnostic(self, path: str | os.PathLike):
        """The refusal as the ``E0004`` :class:`~aidl_lang.base.diagnostics.Diagnostic` every
        command shows (``aidl check``, ``render``, ``fmt``, ``serve``), at the start of
        ``path``, with the hint to give a regular UTF-8 file within the size limit."""
        from ..base.diagnostics import Diagnostic, Span
        shown = os.fspath(path)
        return Diagnostic("E0004", self.message, Span(shown, 1, 1, 1, 1, 0, 0),
                          hint=f"give a regular UTF-8 .aidl file (programs and imports have "
                               f"at most {MAX_IMPORT_BYTES} bytes)")


def read_program(path: str | os.PathLike, keep_bom: bool = False) -> str:
    """The text of the main file ``path``, read the way imports are (:func:`read_import`): a
    regular file only, opened non-blocking (a FIFO or ``/dev/zero`` is refused, not waited on
    or read), at most :data:`MAX_IMPORT_BYTES` (checked before reading it whole and before
    lexing), UTF-8 (a BOM is dropped, unless ``keep_bom``: the formatter keeps it); line
    endings as they are.  A link is followed: the user named this file.  Raises
    :class:`SourceRefused`."""
    from ..host.files import FileRefused, read_file
    shown = os.fspath(path)
    try:
        data = read_file(shown, MAX_IMPORT_BYTES)
    except FileRefused as e:
        raise SourceRefused(e.message) from None
    except OSError as e:
        raise SourceRefused(f"cannot read `{shown}`: {e.strerror or e}") from None
    return decode_program(data, shown, keep_bom)


def decode_program(data: bytes, shown: str, keep_bom: bool = False) -> str:
    """The text of a program file's bytes ``data`` (``shown``: its name in the message):
    UTF-8, a BOM dropped unless ``keep_bom``.  Raises :class:`SourceRefused` naming the
    first byte that is not UTF-8.  Shared by the CLI, the API, MCP and batch."""
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise SourceRefused(f"cannot read `{shown}`: not UTF-8 text ({e.reason} at byte "
                            f"{e.start})") from None
    return text[1:] if text.startswith("\ufeff") and not keep_bom else text


DRAWING_EXTS = (".dxf", ".svg")


def load_drawing(raw: str, importer: str | None) -> tuple[Path, bytes]:
    """Resolve and read the drawing ``raw`` named by ``Drawing2D("raw")`` in ``importer``
    (None: a program without a file, read relative to the working folder): the same sandbox
    as :func:`resolve_import` — a relative path inside the program's folder tree (or
    ``std/drawings/NAME``, the sample drawings bundled with the standard library) whose real
    path is a regular ``.dxf`` or ``.svg`` file of at most :data:`MAX_DRAWING_BYTES`, opened
    once, non-blocking.  Returns ``(real path, bytes)``; raises :class:`ImportRefused` with
    code ``E0130`` and a message naming only the path as written."""
    return _load_beside(raw, importer, DRAWING_EXTS, "drawing", "E0130", MAX_DRAWING_BYTES,
                        "give a .dxf or .svg file in this program's folder or below it (a "
                        "relative path)",
                        "select what you need in the drawing program and save that, or "
                        "split the drawing", allow_std=True)


FONT_EXTS = (".ttf", ".otf", ".ttc")
MAX_FONT_BYTES = 50_000_000      # one font file of Text(..., font="FILE") (a CJK .ttc: ~30 MB)


def load_font(raw: str, importer: str | None) -> tuple[Path, bytes]:
    """Resolve and read the font file ``raw`` of ``Text(..., font="raw")`` in ``importer``:
    the sandbox of :func:`load_drawing` (a relative path inside the program's folder tree)
    for a regular ``.ttf``, ``.otf`` or ``.ttc`` file of at most :data:`MAX_FONT_BYTES`.
    Returns ``(real path, bytes)``; raises :class:`ImportRefused` with code ``E0133``."""
    return _load_beside(raw, importer, FONT_EXTS, "font", "E0133", MAX_FONT_BYTES,
                        "give a .ttf, .otf or .ttc file in this program's folder or below it "
                        "(a relative path), or a family: `font=\"sans\"`",
                        "use a smaller font file")


def _load_beside(raw: str, importer: str | None, exts: tuple, what: str, code: str,
                 max_bytes: int, hint: str, smaller: str,
                 allow_std: bool = False) -> tuple[Path, bytes]:
    """A file named by a program (a drawing, a font) read through the import sandbox:
    ``exts`` its extensions, ``what`` its word in messages, ``code`` their code, ``hint``
    the fix of a refused path and ``smaller`` of a file too large."""
    words = ", ".join(exts[:-1]) + " or " + exts[-1]
    if len(raw) > MAX_IMPORT_PATH or "\0" in raw or "\\" in raw:
        raise ImportRefused(f"{what} path `{raw[:80]}` is too long or has a character that "
                            f"cannot be in a path", hint=hint, code=code)
    if not raw.lower().endswith(exts):
        raise ImportRefused(f"`{raw}` is not a {words} {what}", hint=hint, code=code)
    if allow_std and raw.startswith("std/"):     # the sample drawings bundled with the library
        base, raw_rel = str(STDLIB.resolve()), raw[4:]
    else:
        base = os.path.dirname(os.path.realpath(importer)) if importer and \
            not importer.startswith("<") else os.path.realpath(os.getcwd())
        raw_rel = raw
    if os.path.isabs(raw) or raw.startswith("~"):
        raise ImportRefused(f"{what} `{raw}` leaves the project folder", hint=hint, code=code)
    lexical = os.path.normpath(os.path.join(base, raw_rel))
    if not _inside(lexical, base):
        raise ImportRefused(f"{what} `{raw}` leaves the project folder", hint=hint, code=code)
    if not os.path.lexists(lexical):
        folder = os.path.dirname(lexical)
        cands = []
        if _inside(os.path.realpath(folder), base) and os.path.isdir(folder):
            try:
                cands = sorted(n for n in os.listdir(folder)
                               if n.lower().endswith(exts))[:200]
            except OSError:
                cands = []
        from ..base.diagnostics import did_you_mean
        raise ImportRefused(f"cannot find the {what} `{raw}`",
                            hint="the path is relative to this program's folder",
                            suggestions=did_you_mean(os.path.basename(lexical), cands),
                            code=code)
    real = os.path.realpath(lexical)
    if not _inside(real, base) or not real.lower().endswith(exts):
        raise ImportRefused(f"{what} `{raw}` is not a {words} file inside the project "
                            f"folder", hint=hint, code=code)
    from ..host.files import FileRefused, read_file
    try:
        data = read_file(real, max_bytes, follow_symlinks=False)
    except FileRefused as e:
        msg = str(e)
        if "larger" in msg:
            raise ImportRefused(f"{what} `{raw}` is larger than {max_bytes} bytes",
                                hint=smaller, code=code) from None
        raise ImportRefused(f"cannot read the {what} `{raw}`: it is not a regular file",
                            hint=hint, code=code) from None
    except OSError:
        raise ImportRefused(f"cannot read the {what} `{raw}`", hint=hint, code=code) from None
    return Path(real), data
