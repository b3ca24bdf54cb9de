"""What the MCP tools do, without the protocol: plain functions over :mod:`aidl_lang.api`
that the server (:mod:`.server`) exposes.  Each takes a :class:`Workspace` (the allowed
folder) and returns JSON-ready dicts, or raises :class:`Refused` for a request the server must
turn down (a path outside the folder, both or neither of ``source``/``path``, a budget out of
range, a file that is not a program, an output through a link).  A mistake in the *program*
is never an exception: it is in ``diagnostics``, worded for agents (:mod:`.wording`).
"""
from __future__ import annotations

import os
from pathlib import Path

from ..api import NotCompiled, Result, compile as compile_program
from ..base.diagnostics import split_lines
from ..library.sources import SourceRefused, decode_program
from ..host.files import FileRefused, open_beneath, open_dir_beneath, read_regular
from .wording import for_agents, reword_diagnostics

MAX_BUDGET = 4.0          # a tool call may ask for at most 4x the default evaluation budget
MAX_SOURCE = 1_000_000    # characters of program text per call
MAX_PNG_WIDTH = 4096      # pixels


class Refused(Exception):
    """The request is turned down; the message says why (shown to the agent as a tool
    error), ``code`` what kind of refusal it is (:data:`.compact.CODES`), ``argument`` the
    argument at fault when there is one."""

    def __init__(self, message: str, code: str = "bad_argument",
                 argument: str | None = None) -> None:
        super().__init__(message)
        self.code, self.argument = code, argument

    def __reduce__(self):                     # across the worker's pipe, with its code
        return (Refused, (str(self), self.code, self.argument))


def one_program(source: str | None, path: str | None) -> None:
    """Refuse both or neither of ``source`` and ``path`` (None: not given).  Raises
    :class:`Refused`."""
    if (source is None) == (path is None):
        raise Refused("give exactly one of `source` (program text) or `path` (a .aidl file "
                      "inside the allowed folder)", "program_choice", "source")


def check_arguments(tool: str, arguments: dict, accepted: list[str]) -> None:
    """Refuse the arguments of a call to ``tool`` that it does not take (``accepted``: the
    names it does), naming them with the nearest accepted name and all of them, and for a
    tool that compiles, both or neither of ``source`` and ``path`` (:func:`one_program`).
    Raises :class:`Refused`."""
    unknown = [a for a in arguments if a not in accepted]
    if unknown:
        from ..base.diagnostics import did_you_mean
        near = did_you_mean(unknown[0], accepted, 1)
        said = ", ".join(f"`{a}`" for a in unknown)
        raise Refused(f"unknown argument{'s' if len(unknown) > 1 else ''} {said} for `{tool}`"
                      + (f"; did you mean `{near[0]}`?" if near else ";")
                      + f" `{tool}` takes: {', '.join(accepted)}", "unknown_argument",
                      unknown[0])
    if "source" in accepted and "path" in accepted:
        one_program(arguments.get("source"), arguments.get("path"))


NAME_MAX, PATH_MAX = 255, 4096      # bytes of a file name and of a path (Linux)


def given_path(path, argument: str) -> None:
    """Refuse (``bad_argument``) a path the agent gave that no file can have: not a
    non-empty string, a NUL in it, a part over :data:`NAME_MAX` bytes or the whole over
    :data:`PATH_MAX` (issue 110: a 300-character name was an internal error, the operating
    system's "File name too long")."""
    if not isinstance(path, str) or not path or "\x00" in path:
        raise Refused("give a path as a non-empty string", "bad_argument", argument)
    long = next((part for part in Path(path).parts
                 if len(part.encode("utf-8", "surrogateescape")) > NAME_MAX), None)
    if long is not None:
        raise Refused(f"`{long[:40]}...` in `{argument}` is {len(long.encode('utf-8', 'surrogateescape'))} "
                      f"bytes long: a file or folder name is at most {NAME_MAX}; give a "
                      "shorter name", "bad_argument", argument)
    if len(path.encode("utf-8", "surrogateescape")) > PATH_MAX:
        raise Refused(f"`{argument}` is longer than {PATH_MAX} bytes: give a shorter path",
                      "bad_argument", argument)


class Workspace:
    """The one folder a server may read and write: ``root`` (resolved, real path).
    :meth:`inside` resolves a path given by the agent (relative to the root) and refuses
    anything whose real path (symlinks followed) is outside it."""

    def __init__(self, root: str | os.PathLike, budget: float = 1.0) -> None:
        self.root = Path(os.path.realpath(root))
        if not self.root.is_dir():
            raise NotADirectoryError(f"`{root}` is not a folder")
        self.budget = budget

    def inside(self, path: str, must_exist: bool = False, argument: str = "path") -> Path:
        """The real path of ``path`` (relative to the root, or absolute; the tool's argument
        ``argument``), checked to be inside the root.  Raises :class:`Refused`."""
        given_path(path, argument)
        p = Path(path)
        if not p.is_absolute():
            p = self.root / p
        try:
            real = Path(os.path.realpath(p))
        except (OSError, ValueError):          # a link swapped while it was resolved
            raise Refused(f"`{path}` changed while it was being resolved; try again",
                          "not_found", argument) from None
        if real != self.root and self.root not in real.parents:
            link = self._link_in(p)
            if link is not None:
                raise Refused(f"`{path}` goes through the symbolic link `{link[0]}` (inside "
                              f"the allowed folder), which points to `{link[1]}`: that target "
                              f"is outside the allowed folder {self.root} (the server's "
                              "`--root`); only files inside it can be read or written",
                              "outside_root", argument)
            raise Refused(f"`{path}` is outside the allowed folder {self.root} (the server's "
                          "`--root`); only files inside it can be read or written",
                          "outside_root", argument)
        if must_exist and not real.is_file():
            raise Refused(f"`{path}` is not a file in {self.root}", "not_found", argument)
        return real

    def _link_in(self, p: Path) -> tuple[str, str] | None:
        """``(link, target)``: the first symbolic link below the root on the way to ``p``
        (an absolute path written below the root), relative to the root, with what it points
        to; None when ``p`` is not written below the root or has none."""
        try:
            rel = Path(os.path.normpath(p)).relative_to(self.root)
        except ValueError:
            return None
        at = self.root
        for part in rel.parts:
            at = at / part
            if os.path.islink(at):
                try:
                    target = os.readlink(at)
                except OSError:
                    target = "?"
                return at.relative_to(self.root).as_posix(), target
        return None

    def output(self, path: str, argument: str = "output") -> Path:
        """The output file ``path`` (relative to the root, or absolute inside it) as a path
        below the root, ``..`` taken as written, with no symbolic link in any of its
        components: a link is refused wherever it points, inside the root too (outputs are
        never written through a link).  The file and its folders need not exist.  Raises
        :class:`Refused`."""
        given_path(path, argument)
        p = Path(path)
        outside = Refused(f"`{path}` is outside the allowed folder {self.root} (the server's "
                          "`--root`); only files inside it can be read or written",
                          "outside_root", argument)
        if p.is_absolute():
            try:
                p = p.relative_to(self.root)
            except ValueError:
                raise outside from None
        parts: list[str] = []
        for part in p.parts:
            if part == "..":
                if not parts:
                    raise outside
                parts.pop()
            elif part not in ("", "."):
                parts.append(part)
                if os.path.islink(self.root.joinpath(*parts)):
                    try:
                        to = f" (to `{os.readlink(self.root.joinpath(*parts))}`)"
                    except OSError:
                        to = ""
                    link = "is" if len(parts) == len([q for q in p.parts
                                                      if q not in ("", ".")]) else \
                        "goes through"
                    raise Refused(f"`{path}` {link} the symbolic link "
                                  f"`{'/'.join(parts)}`{to}; files are never written through "
                                  "a link, even one inside the allowed folder: give a path of "
                                  "real folders and files", "symlink", argument)
        if not parts:
            raise Refused(f"`{path}` is the allowed folder itself; give a file name",
                          "bad_argument", argument)
        return self.root.joinpath(*parts)

    def relative(self, p: Path | str) -> str:
        try:
            return str(Path(p).relative_to(self.root))
        except ValueError:
            return str(p)

    def compile(self, source: str | None, path: str | None,
                overrides: dict | None = None, budget: float | None = None) -> Result:
        """Compile ``source`` (named by ``path`` if given, else ``untitled.aidl`` in the root:
        imports resolve from there, in the sandbox of the importing file's folder) or the file
        ``path``.  Raises :class:`Refused`."""
        one_program(source, path)
        k = self.budget if budget is None else budget
        if not isinstance(k, (int, float)) or not 0 < k <= MAX_BUDGET:
            raise Refused(f"budget is a factor of the default evaluation budget, between 0 and "
                          f"{MAX_BUDGET:g}; got {budget!r}", "bad_argument", "budget")
        if overrides is not None and not isinstance(overrides, dict):
            raise Refused("overrides maps param names to values, e.g. {\"width\": \"40 mm\"}",
                          "bad_argument", "overrides")
        if source is not None:
            if len(source) > MAX_SOURCE:
                raise Refused(f"the program is longer than {MAX_SOURCE} characters",
                              "bad_argument", "source")
            return compile_program(source=source, path=str(self.root / "untitled.aidl"),
                                   overrides=overrides, budget=k)
        real, text = self.read(path)
        return compile_program(source=text, path=str(real), overrides=overrides, budget=k)

    def read(self, path: str) -> tuple[Path, str]:
        """``(real path, text)`` of the program file ``path``: its real path checked to be
        inside the root, then opened once from the root's folder without following any link
        (:func:`aidl_lang.host.files.open_beneath`: a file or folder swapped for a link after the
        check is refused, never read), a regular file of at most :data:`MAX_SOURCE` bytes of
        UTF-8 text, named ``.aidl`` (a drawing or any other file is refused, not parsed as
        AIDL).  Raises :class:`Refused`."""
        real = self.inside(path, must_exist=True)
        suffix = Path(path).suffix.lower()
        if suffix != ".aidl":
            why = f"`{path}` is not an .aidl file: `path` takes an AIDL program"
            if suffix in (".dxf", ".svg"):
                why += (f"; a program imports a drawing with Drawing2D(\"{path}\") "
                        "(DXF and SVG, docs/import.md)")
            raise Refused(why, "wrong_kind", "path")
        data = self.read_bytes(real, MAX_SOURCE, path)
        try:
            return real, decode_program(data, path)
        except SourceRefused as e:
            raise Refused(e.message, "wrong_kind", "path") from None

    def read_bytes(self, real: Path, limit: int, path: str) -> bytes:
        """The bytes of ``real`` (a real path :meth:`inside` gave), opened once from the root's
        folder without following any link, a regular file of at most ``limit`` bytes
        (``path``: as the agent wrote it, for messages).  Raises :class:`Refused`."""
        try:
            fd = open_beneath(self.root, real.relative_to(self.root))
            try:
                return read_regular(fd, limit, path)
            finally:
                os.close(fd)
        except OSError as e:
            raise Refused(f"cannot read `{path}`: {e}", "not_found", "path") from None


SOURCE_NAME = "<source>"     # the file of a program given as `source` in what a tool says


def unrooted(ws: Workspace, doc, source: bool):
    """``doc`` (a tool's answer: dicts, lists, tuples, strings; bytes left as they are) with
    the server's own paths said as an agent names them (issue 95): a file inside the root
    relative to it, the standard library's as ``std/...`` (never its install folder), and
    a program given as ``source`` (compiled as ``ROOT/untitled.aidl``) as ``<source>``."""
    from ..library.sources import STDLIB
    swaps = [(f"{os.path.realpath(STDLIB)}{os.sep}", "std/"), (f"{STDLIB}{os.sep}", "std/")]
    if source:
        swaps.append((str(ws.root / "untitled.aidl"), SOURCE_NAME))
    swaps.append((f"{ws.root}{os.sep}", ""))

    def walk(x):
        if isinstance(x, str):
            for old, new in swaps:
                if old in x:
                    x = x.replace(old, new)
            return x
        if isinstance(x, dict):
            return {k: walk(v) for k, v in x.items()}
        if isinstance(x, list):
            return [walk(v) for v in x]
        if isinstance(x, tuple):
            return tuple(walk(v) for v in x)
        return x
    return walk(doc)


def _summary(ws: Workspace, r: Result) -> dict:
    """``{"ok", "diagnostics", "units", "solve"?, "summary"?}`` of ``r``, the diagnostics
    worded for agents (:mod:`.wording`: tools and arguments, not command-line flags)."""
    reword_diagnostics(r.diagnostics)
    doc: dict = {"ok": r.ok, "diagnostics": r.diagnostics_json(), "units": r.units}
    w = r.compiled.work
    if w is not None:         # the work units spent and the budget: the same on any machine
        doc["work"] = {"spent": int(w.spent), "budget": int(w.limit)}
    s = r.compiled.solve
    if s is not None:
        doc["solve"] = {"converged": s.converged, "iterations": s.iterations,
                        "unknowns": s.n_unknowns, "equations": s.n_equations,
                        "settled": s.n_settled, "max_residual": s.max_residual}
    if not r.ok:
        n = len(r.errors)
        doc["summary"] = f"{n} error{'s' if n != 1 else ''}: " + "; ".join(
            f"{d.code} line {d.span.line if d.span else '-'}: {d.message}{_inside(d)}"
            for d in r.errors[:5])
    return doc


def _inside(d) -> str:
    """`` (inside `spur_gear`, at std/gears.aidl:22:5)`` for a diagnostic raised inside a
    template of another file (its line is the call's: issue 86; templates that call
    templates: ``inside `gear_pair` > `spur_gear`, at ...``), else ""."""
    outer = []
    for lab in d.labels:
        if not lab.message.startswith("inside "):
            break
        if ", at " in lab.message:
            return f" (inside {' > '.join(outer + [lab.message[7:]])})"
        outer.append(lab.message[7:].split(": ", 1)[0])
    return ""


def check(ws: Workspace, source: str | None = None, path: str | None = None,
          overrides: dict | None = None, dof: bool = False,
          budget: float | None = None, sweep: bool = False) -> dict:
    """``{"ok", "diagnostics" (JSON, with spans and fixes; redundant constraints as W0401,
    looked for at most 1 s, as ``aidl check``), "units", "solve", "freedom", "parts"}`` (the
    last two when the program solved; ``freedom`` per structure with ``dof``; with
    ``sweep``, ``sweep`` (:meth:`aidl_lang.params.sweep.SweepReport.to_json`) and its W0110 among
    the diagnostics)."""
    return _checked(ws, ws.compile(source, path, overrides, budget), dof, budget, sweep)


def _checked(ws: Workspace, r: Result, dof: bool = False, budget: float | None = None,
             sweep: bool = False) -> dict:
    """:func:`check`'s answer for the compiled program ``r``."""
    r.find_redundant()                    # W0401, as `aidl check` reports them
    report = None
    if sweep and r.ok:
        report = r.sweep(budget=ws.budget if budget is None else budget)
        for d in report.diagnostics:
            r.sink.add(d)
    parts = _after_compile(r, lambda: [p.to_json() for p in r.parts])
    doc = _summary(ws, r)
    if r.ok:
        doc["freedom"] = r.freedom(detail=bool(dof))
        text = doc["freedom"]["text"]
        if dof:     # the details are in this answer: not "call `check` with dof=true" again
            text = text.replace(", see --dof", " (each structure in `structures`)")
        doc["freedom"]["text"] = for_agents(text)
        doc["parts"] = parts
        doc["fit"] = r.fit
    if report is not None:
        doc["sweep"] = report.to_json() | {"text": report.text()}
    return doc


def _after_compile(r: Result, fn):
    """``fn()`` (reading the exact output of ``r``, a compiled program) or, when that output
    cannot be made within bounded work (:class:`~aidl_lang.output.part.part.OutputError`:
    thousands of curves on top of each other), None with the located ``E0304`` added to
    ``r``'s diagnostics, which makes ``r`` not ok: an answer, never an internal error."""
    if not r.ok:
        return None
    from ..output.part.part import OutputError
    try:
        return fn()
    except OutputError as e:
        from ..pipeline import output_error_sink
        for d in output_error_sink(r.path, r.source, e).items:
            r.sink.add(d)
        return None


def values(ws: Workspace, source: str | None = None, path: str | None = None,
           names: list[str] | None = None, overrides: dict | None = None,
           budget: float | None = None) -> dict:
    """``{"ok", "units", "values": [{"name", "kind", "value", "unit", "mm"}], "text"}`` for the
    names at or below ``names`` (all when empty); the diagnostics when it did not solve."""
    r = ws.compile(source, path, overrides, budget)
    if not r.ok:
        return _summary(ws, r)
    vals = r.values_matching(names or [], sizes=True)
    from ..base.diagnostics import did_you_mean
    every = sorted({n for v in r.sizes() for n in _prefixes(v.name)}) if names else []
    if names and not vals:
        asked = [n for n in names if isinstance(n, str)][:3]
        near = did_you_mean(asked[0], every, 3) if asked else []
        more = f" and {len(names) - 3} more" if len(names) > 3 else ""
        raise Refused(f"no value matches {', '.join(f'`{n[:80]}`' for n in asked)}{more}"
                      + (f"; did you mean {', '.join(f'`{n}`' for n in near)}?" if near
                         else "; call `values` without `names` for every name"),
                      "no_match", "names")
    doc = {"ok": True, "units": r.units, "values": [v.to_json() for v in vals],
           "text": "\n".join(v.text() for v in vals)}
    # a name among several that matches nothing is said (issue 95: it was left out silently)
    alone = [n for n in dict.fromkeys(names or []) if isinstance(n, str) and n.strip()
             and not r.values_matching([n], sizes=True)][:10]
    if alone:
        doc["unmatched"] = [
            f"no value matches `{n[:80]}`" + (f"; did you mean {', '.join(f'`{x}`' for x in near)}?"
                                             if (near := did_you_mean(n, every, 3)) else "")
            for n in alone]
    return doc


def _prefixes(name: str) -> list[str]:
    """``a.b[0].c`` -> ``a``, ``a.b``, ``a.b[0]``, ``a.b[0].c``: the names ``values`` takes."""
    import re
    cuts = [m.start() for m in re.finditer(r"[.\[]", name)]
    return [name[:k] for k in cuts if k] + [name]


def _mm(value, name: str, example: str, zero: bool = False, most: float | None = None
        ) -> float | None:
    """A length argument in mm, as ``aidl render`` reads it: a number (mm) or a string with
    its unit (``"0.15mm"``, ``"0.25 in"``); None when not given.  Raises :class:`Refused`."""
    if value is None:
        return None
    from ..output.fabrication.layout import parse_length
    ok = isinstance(value, (str, int, float)) and not isinstance(value, bool)
    v = parse_length(str(value), zero=zero) if ok else None
    if v is None or most is not None and v > most:
        size = "of 0 or more" if zero else "above 0" + (f" up to {most:g} mm" if most else "")
        raise Refused(f"{name} is a length {size}: a number of mm or a string with its unit, "
                      f"such as {example}; got {value!r}", "bad_argument", name)
    return v


def _sheet_names(target: Path, n: int) -> list[Path]:
    """The files of ``n`` sheets, as ``aidl render --layout sheet`` names them: ``cut.svg``
    for one sheet, else ``cut-1.svg``, ``cut-2.svg``, ..."""
    if n == 1:
        return [target]
    return [target.with_name(f"{target.stem}-{k + 1}{target.suffix}") for k in range(n)]


def _layout_refused(e, r: Result, source: str | None) -> Refused:
    """The refusal of a render the layout refused (a part larger than the sheet, no part at
    all); of one whose kerf a cut cannot take, its located ``E0504``
    (:meth:`~aidl_lang.output.fabrication.layout.KerfError.diagnostic`) as one line."""
    if not hasattr(e, "kerf"):
        return Refused(str(e), "bad_argument", "sheet" if not hasattr(e, "holds") else
                       "source" if source is not None else "path")
    d = e.diagnostic(r.compiled.drawing)
    at = f"line {d.span.line}, column {d.span.col}: " if d.span is not None else ""
    return Refused(f"{at}E0504 {d.message}; hint: {d.hint}", "output_failed",
                   "source" if source is not None else "path")


def render(ws: Workspace, source: str | None = None, path: str | None = None,
           output: str | None = None, width: int = 800, overrides: dict | None = None,
           budget: float | None = None, style: str = "preview", assembled: bool = False,
           layout: str | None = None, sheet: str | None = None, gap=None, rotate=None,
           kerf=None, thickness=None, machine=None,
           page: str | None = None, picture: bool = False,
           files: list | None = None) -> tuple[dict, list[bytes]]:
    """Compile, write ``output`` and draw: ``(summary, pictures)``.  The summary gives the
    figures of what was made (``size`` [width, height] mm of the drawing, ``parts``, ``fit``
    (3D: the product assembled by ``Place``), ``overlaps`` (2D: parts over each other as cut,
    true outlines, as drawn or on each sheet); ``job`` for a cutting file; ``layout`` on
    sheets); with ``picture``, the PNGs ``width`` pixels wide: one of the parts, or one per
    sheet with a layout (none without ``picture``, or with errors).  ``output``:
    also write the drawing there (``.svg``, ``.dxf``, ``.png``, ...; inside the allowed
    folder, made if missing, never through a link, never over the program).
    ``assembled``: the picture (and a 3D or PNG ``output``) is the assembled product, every
    part placed by its ``Place``, collisions boxed in red; an SVG or DXF ``output`` is
    refused.  The options of ``aidl render``, with its meanings: ``layout="sheet"``: the
    cutting sheets (:meth:`aidl_lang.api.Result.layout`) of ``sheet`` (``"600x400mm"``),
    ``gap`` (mm, default 3) and ``rotate`` (``"0,90"``, ``"any"``), one file per sheet
    (``cut-1.svg``, ... when there are several); ``kerf`` (mm: every cut of SVG, DXF and PNG
    offset by half of it; default the program's own); ``thickness`` (mm: the extrusion of
    STL, 3MF, STEP, GLB; default the program's, else 3); ``page`` (a ``.pdf`` output tiled
    over paper of this size, ``"A4"``, ``"A4-landscape"``, ...; default one page the drawing's
    size).  Lengths are numbers of mm or strings with a unit.  ``machine``: G-code's machine
    profile, ``laser``, ``router``, ``plotter``, a TOML file inside the allowed folder, or a
    profile's table as an object (``{"kind": "router", "tool_diameter": 6}``: the keys of a
    profile file, ``aidl docs machine``).
    ``files``: a list to put each file's ``(target, data, program, shown)`` in instead of
    writing it (the server writes them in the order the calls were made: :mod:`.order`)."""
    put = files.append if files is not None else lambda f: write_inside(ws, *f)
    if not isinstance(width, int) or not 16 <= width <= MAX_PNG_WIDTH:
        raise Refused(f"width is a number of pixels from 16 to {MAX_PNG_WIDTH}; got {width!r}",
                      "bad_argument", "width")
    if style not in ("preview", "laser"):
        raise Refused("style is `preview` or `laser`", "bad_argument", "style")
    from ..output.fabrication.layout import parse_rotate, parse_sheet
    if layout not in (None, "sheet"):
        raise Refused(f"layout is \"sheet\" (the cutting sheets) or not given; got {layout!r}",
                      "bad_argument", "layout")
    if layout is None and (sheet, gap, rotate) != (None, None, None):
        raise Refused("`sheet`, `gap` and `rotate` are for a cutting layout: add "
                      "layout=\"sheet\"", "bad_argument",
                      next(k for k, v in (("sheet", sheet), ("gap", gap), ("rotate", rotate))
                           if v is not None))
    if layout and assembled:
        raise Refused("`assembled` and `layout` do not go together: the assembled product is "
                      "in 3D, a layout is flat", "bad_argument", "assembled")
    sheet_mm = parse_sheet(sheet) if isinstance(sheet, str) else (600.0, 400.0)
    if sheet is not None and (not isinstance(sheet, str) or sheet_mm is None):
        raise Refused(f"sheet is WIDTHxHEIGHT with a unit, such as \"600x400mm\" or "
                      f"\"24x12in\"; got {sheet!r}", "bad_argument", "sheet")
    gap_mm = _mm(gap, "gap", "3 or \"3mm\"", zero=True)
    try:
        turns = parse_rotate("0,90" if rotate is None else str(rotate))
    except ValueError:
        raise Refused(f"rotate is the angles in degrees parts may be turned by, such as "
                      f"\"0,90\" or \"0\", or \"any\"; got {rotate!r}", "bad_argument",
                      "rotate") from None
    kerf_mm = _mm(kerf, "kerf", "0.15 or \"0.15mm\"", most=10.0)
    thick_mm = _mm(thickness, "thickness", "3 or \"3mm\"")
    target = ws.output(output) if output is not None else None
    from ..output.fabrication.machine import KINDS, MachineError, default, from_dict, load
    try:
        if isinstance(machine, dict):       # a profile's table: the router's bit, its relief
            prof = from_dict(machine, "the `machine` argument")
        else:
            prof = None if machine is None else default(machine) if machine in KINDS else \
                load(ws.inside(machine, must_exist=True, argument="machine"))
    except MachineError as e:
        raise Refused(str(e), "bad_argument", "machine") from None
    if page is not None:
        from ..output import OutputError
        from ..output.writers.pdf import page_size
        if target is None or target.suffix.lower() != ".pdf":
            raise Refused("page is the paper size of a PDF template: give an output "
                          "ending in .pdf", "bad_argument", "page")
        try:
            page_size(str(page))
        except OutputError as e:
            raise Refused(str(e), "bad_argument", "page") from None
    if assembled and target is not None:
        from ..output import ASSEMBLED_FORMATS
        if target.suffix.lower() not in ASSEMBLED_FORMATS:
            raise Refused(f"assembled, the output is .stl, .3mf, .step, .glb or .png, not "
                          f"`{target.suffix}` (SVG and DXF are the flat parts)", "wrong_kind",
                          "output")
    r = ws.compile(source, path, overrides, budget)
    doc = _summary(ws, r)
    if not r.ok:
        return doc, []
    from ..api import WriteError
    from ..output import MissingDependency, OutputError
    from ..output.fabrication.layout import LayoutError
    from ..output.writers.write import check_output_path
    prog = None if path is None else str(ws.inside(path))
    drawn = {"style": style, "width": width, "thickness": thick_mm}
    try:
        if layout:
            sheets = r.layout(sheet_mm, 3.0 if gap_mm is None else gap_mm, turns, kerf_mm)
            pngs = sheets.encode("png", **drawn) if picture else []
            if target is not None:
                files = _sheet_names(target, sheets.sheets)
                for f in files:
                    check_output_path(f, prog)
                for f, data in zip(files, sheets.encode(target.suffix, machine=prof, page=page,
                                                        **drawn)):
                    put((f, data, prog, ws.relative(f)))
                doc["written"] = ws.relative(files[0])
            use = sheets.use()
            doc["overlaps"] = sheets.overlaps()
            doc["layout"] = {"sheets": sheets.sheets, "size": list(sheets.size),
                             "files": [ws.relative(f) for f in files] if target else [],
                             "text": sheets.text + ", use " + ", ".join(
                                 f"{u * 100:.0f}%" for u in use),
                             "use": use, "placements": sheets.placements()}
            if target is not None and target.suffix.lower() not in _SOLID_FORMATS:
                doc["job"] = _job(sheets._cut, prof, thick_mm)
        else:
            pngs = [r.encode("png", kerf_mm, assembled=assembled, **drawn)] if picture else []
            if target is not None:
                out = check_output_path(target, prog)
                data = r.encode(out.suffix, kerf_mm, assembled=assembled, machine=prof,
                                page=page, **drawn)
                put((target, data, prog, output))
                doc["written"] = ws.relative(out)
                if not assembled and out.suffix.lower() not in _SOLID_FORMATS:
                    from ..output import for_cutting
                    cut = for_cutting(r.output, kerf_mm)
                    doc["job"] = _job([cut], prof, thick_mm)
                    _machine_warnings(r, cut, out.suffix.lower(), prof, kerf_mm, doc)
    except LayoutError as e:                # a part larger than the sheet, no part, a kerf
        raise _layout_refused(e, r, source) from None
    except (MissingDependency, OutputError, WriteError, NotCompiled, OSError) as e:
        raise Refused(str(e), "output_failed", "output" if target is not None else
                      "layout" if layout else "source" if source is not None else "path") \
            from None
    doc["parts"] = [p.to_json() for p in r.parts]
    boxes = [p["bbox"] for p in doc["parts"]]
    if boxes:
        doc["size"] = [round(max(b[2] for b in boxes) - min(b[0] for b in boxes), 6),
                       round(max(b[3] for b in boxes) - min(b[1] for b in boxes), 6)]
    doc["fit"] = r.fit
    if not layout:          # 2D, the parts as drawn (a layout's: each sheet's, above)
        doc["overlaps"] = r.overlaps()
    if pngs:
        doc["image"] = {"format": "png", "width": width,
                        "view": "assembled" if assembled else "flat"}
    return doc, pngs


_SOLID_FORMATS = (".stl", ".3mf", ".step", ".stp", ".glb", ".png")


def _machine_warnings(r, cut, suffix: str, prof, kerf_mm, doc: dict) -> None:
    """What the cutter does beside the through-cuts of ``cut`` (written as ``suffix``), as
    ``aidl render`` says it (:func:`~aidl_lang.output.checks.material.toolpath_walls.machine_warnings`:
    a router's G-code, W0510 and W0507; else a kerf applied, W0507), added to ``r``'s
    diagnostics and ``doc``'s."""
    from ..output.checks.material.toolpath_walls import machine_warnings
    from ..output.writers.gcode import GCODE_FORMATS
    before = len(r.sink.items)
    drawing = r.compiled.drawing
    if prof is not None and prof.kind == "router" and suffix in GCODE_FORMATS:
        machine_warnings(drawing, cut, r.output, prof.tool_diameter, True, r.sink,
                         relief=prof.relief)
        from ..output.checks.assembly import check_routed_fit     # the parts as routed
        check_routed_fit(drawing, r.output, prof.tool_diameter, prof.relief, r.sink)
    elif cut is not r.output:
        machine_warnings(drawing, r.output, r.output,
                         kerf_mm if kerf_mm is not None else drawing.kerf, False, r.sink)
    if len(r.sink.items) > before:
        reword_diagnostics(r.sink.items[before:])
        doc["diagnostics"] = r.diagnostics_json()


def _job(outputs: list, machine, thickness: float | None) -> dict:
    """The job figures of cutting ``outputs`` (one per sheet; the kerf applied) on
    ``machine`` (None: the built-in laser), as the G-code writer plans them
    (:func:`aidl_lang.output.writers.gcode.job`): ``{"path_mm" (one pass of every cut),
    "passes" (how many times the path is run, when the same for every cut: else the text
    says each part's), "cut_mm" (every
    pass), "travel_mm", "seconds", "machine", "text"}``, summed over the sheets."""
    from ..output.writers.gcode import estimate_text, job, passes
    cut = travel = seconds = dark = path = 0.0
    runs: dict = {}
    kind = "laser" if machine is None else machine.kind
    for out in outputs:
        j = job(out, machine, thickness)
        cut, travel, seconds = cut + j.cut, travel + j.travel, seconds + j.seconds
        dark, path = dark + j.dark, path + j.path
        for n, (p, c) in j.runs.items():
            run = runs.setdefault(n, [0.0, 0.0])
            run[0], run[1] = run[0] + p, run[1] + c
    doc = {"path_mm": round(path, 3), "passes": passes(runs), "cut_mm": round(cut, 3),
           "travel_mm": round(travel, 3), "seconds": round(seconds, 1), "machine": kind,
           "text": estimate_text(cut, travel, seconds, dark, runs).replace(
               "the profile's", f"the {kind} profile's")}
    if doc["passes"] is None:
        doc.pop("passes")
    return doc


def docs(name: str | None = None) -> str:
    """The reference of one topic (a shape, constraint, statement or stdlib template), as
    ``aidl docs NAME`` prints it; no name: the list of topics.  Raises :class:`Refused` for an
    unknown name, with the nearest topics."""
    from ..library.reference import index_text, lookup_text
    if not (name or "").strip():
        return for_agents(index_text())
    text, found = lookup_text(name)
    if not found:
        raise Refused(for_agents(text.strip()), "no_match", "name")
    return for_agents(text)


def describe(ws: Workspace, source: str | None = None, path: str | None = None,
             overrides: dict | None = None, budget: float | None = None) -> dict:
    """``{"ok", "diagnostics", "units", "text", "describe"}``: what the final part is, in words
    (``text``, as ``aidl check --describe``) and as data (``describe``: each part's outline,
    openings with kind, centre and size, engravings, copies, symmetries; mm); the
    diagnostics alone when the program did not solve."""
    r = ws.compile(source, path, overrides, budget)
    described = _after_compile(r, lambda: r.description)
    doc = _summary(ws, r)
    if r.ok:
        from ..output.checks.reports.describe import describe_text
        doc["describe"] = described
        doc["text"] = describe_text(described)
    return doc


def write_inside(ws: Workspace, target: Path, data: bytes, program: str | None,
                  shown: str) -> None:
    """Write ``data`` to ``target`` (a path below the root with no link in it, checked when
    the call came in: :meth:`Workspace.output`) through the folder opened from the root
    without following links (:func:`aidl_lang.host.files.open_dir_beneath`, ``O_NOFOLLOW`` at
    each step), so a folder swapped for a link while the program compiled is refused, never
    written through, and a link at the file itself is refused
    (:func:`aidl_lang.output.writers.write.write_in_dir`); never over the program file ``program``.
    Raises ``OSError`` (:class:`aidl_lang.host.files.FileRefused`)."""
    from ..output.writers.write import write_in_dir
    rel = target.relative_to(ws.root)
    dfd = open_dir_beneath(ws.root, rel.parent, create=True)
    try:
        if program is not None:
            try:
                here = os.stat(rel.name, dir_fd=dfd, follow_symlinks=False)
                prog = os.stat(program)
            except FileNotFoundError:
                pass
            else:
                if (here.st_dev, here.st_ino) == (prog.st_dev, prog.st_ino):
                    raise FileRefused(f"`{shown}` is the program being compiled; refusing to "
                                      "overwrite it")
        write_in_dir(dfd, rel.name, data, shown)
    finally:
        os.close(dfd)


def import_drawing(ws: Workspace, path: str, infer: bool = True, parts: bool = False,
                   units: str | None = None, output: str | None = None,
                   budget: float | None = None, files: list | None = None) -> dict:
    """``aidl import [--infer] [--parts] [--units U] FILE [-o OUTPUT]`` for the drawing
    ``path`` (a ``.dxf`` or ``.svg`` inside the root): ``{ok, program, notes, output}``, or
    ``{ok: false, diagnostics}`` for a drawing the importer refuses (its ``E013x``/``E0304``,
    docs/import.md).  ``infer``: the design (recognised shapes, loops, params: docs/import.md,
    "Inferring the design"), else the pieces.  ``output``: also write the program there
    (``.aidl``, inside the root, never through a link; with ``files``, put there as
    :func:`render` does).  Raises :class:`Refused`."""
    from ..drawing.infer import import_drawing as _import
    from ..drawing.model import DrawingError
    from ..base.limits import DEFAULT_BUDGET
    from ..library.sources import MAX_DRAWING_BYTES
    real = ws.inside(path, must_exist=True)
    if Path(path).suffix.lower() not in (".dxf", ".svg"):
        raise Refused(f"`{path}` is not a .dxf or .svg drawing", "wrong_kind", "path")
    if units is not None and units not in ("mm", "cm", "m", "in", "ft", "pt", "px"):
        raise Refused(f"units is one of mm, cm, m, in, ft, pt, px; got {units!r}",
                      "bad_argument", "units")
    target = ws.output(output) if output is not None else None
    if target is not None and target.suffix.lower() != ".aidl":
        raise Refused(f"`{output}` is not an .aidl file: the import writes a program",
                      "wrong_kind", "output")
    k = ws.budget if budget is None else budget
    if not isinstance(k, (int, float)) or not 0 < k <= MAX_BUDGET:
        raise Refused(f"budget is a factor of the default evaluation budget, between 0 and "
                      f"{MAX_BUDGET:g}; got {budget!r}", "bad_argument", "budget")
    data = ws.read_bytes(real, MAX_DRAWING_BYTES, path)
    from ..base.limits import Work
    work = Work(DEFAULT_BUDGET.scaled(k).work)
    try:
        text, notes = _import(data, path, unit=units, parts=parts, infer=infer,
                              budget=DEFAULT_BUDGET.scaled(k), work=work)
    except DrawingError as e:
        return {"ok": False, "diagnostics": [{"code": e.code, "message": e.message,
                                              "hint": e.hint, "line": e.line}],
                "work": {"spent": int(work.spent), "budget": int(work.limit)}}
    doc = {"ok": True, "program": text,
           "work": {"spent": int(work.spent), "budget": int(work.limit)},
           "notes": [{"code": n.code, "message": n.message, "hint": n.hint} for n in notes]}
    if target is not None:
        if files is not None:
            files.append((target, text.encode("utf-8"), None, output))
        else:
            try:
                write_inside(ws, target, text.encode("utf-8"), None, output)
            except OSError as e:
                raise Refused(str(e), "output_failed", "output") from None
        doc["output"] = ws.relative(target)
    doc["check"] = _check_summary(ws, text, target or real.with_suffix(".aidl"), k)
    return doc


def _check_summary(ws: Workspace, text: str, where: Path, budget: float) -> dict:
    """The check of the program ``text`` (compiled as the file ``where``) in short: ``{"ok",
    "dof", "parts", "warnings": ["W0502 line 4: ...", ...], "summary"?}`` (issue 86:
    ``import_drawing`` says whether the program it wrote checks, without another call)."""
    r = compile_program(source=text, path=str(where), budget=budget)
    parts = _after_compile(r, lambda: [p.to_json() for p in r.parts])
    doc = _summary(ws, r)
    out: dict = {"ok": r.ok}
    if not r.ok:
        out["summary"] = doc.get("summary", "")
        return out
    reword_diagnostics(r.diagnostics)
    out["warnings"] = [f"{d.code} line {d.span.line if d.span else '-'}: {d.message}"
                       for d in r.diagnostics if d.severity == "warning"][:10]
    out["dof"] = r.freedom()["dof"]
    out["parts"] = parts
    return out


def write_program(ws: Workspace, path: str, text: str | None = None, old: str | None = None,
                  new: str | None = None, start: int | None = None, end: int | None = None,
                  dof: bool = False, files: list | None = None) -> dict:
    """Write the program file ``path`` (``.aidl``, inside the root, never through a link,
    its folders made) and check it: the whole ``text``; or a patch of the file as it is:
    ``old`` -> ``new`` (``old`` found exactly once), or the characters ``start`` to ``end``
    (0-based offsets, end excluded, as a diagnostic's span and fix give them) replaced with
    ``new``.  Returns :func:`check`'s result of the file written, with ``written`` (the path)
    and ``lines``.  Raises :class:`Refused` (``no_match``: ``old`` not found; ``not_unique``:
    found more than once; ``bad_argument``: a mix of the three ways, or offsets outside the
    file).  ``files``: a list to put the file in instead of writing it, as :func:`render`
    does (the check is of the text, as the file will hold it)."""
    ways = [text is not None, old is not None, start is not None or end is not None]
    if sum(ways) != 1:
        raise Refused("give one of: `text` (the whole program), `old` with `new` (replace "
                      "that text, found once), or `start` and `end` with `new` (replace "
                      "those characters)", "bad_argument", "text")
    if not isinstance(path, str) or Path(path).suffix.lower() != ".aidl":
        raise Refused(f"`{path}` is not an .aidl file: `write_program` writes programs",
                      "wrong_kind", "path")
    target = ws.output(path, "path")
    ws.inside(path)                           # (no link on the way: the same file)
    if text is None:
        if new is None:
            raise Refused("`new` is the replacement text (\"\" to delete)", "bad_argument",
                          "new")
        _, current = ws.read(path)
        if old is not None:
            n = current.count(old) if old else 0
            if n != 1:
                at = [i + 1 for i, ln in enumerate(split_lines(current)) if old and old in ln]
                raise Refused(f"`old` is found {n} times in `{path}`"
                              + (f" (lines {', '.join(map(str, at[:10]))})" if at else "")
                              + ": give text found exactly once (add the words around it), "
                                "or `start` and `end`", "no_match" if n == 0 else "not_unique",
                              "old")
            text = current.replace(old, new, 1)
        else:
            if not (isinstance(start, int) and isinstance(end, int)
                    and 0 <= start <= end <= len(current)):
                raise Refused(f"`start` and `end` are character offsets with 0 <= start <= "
                              f"end <= {len(current)} (the file's length); got {start!r}, "
                              f"{end!r}", "bad_argument", "start")
            text = current[:start] + new + current[end:]
    if len(text) > MAX_SOURCE:
        raise Refused(f"the program is longer than {MAX_SOURCE} characters", "bad_argument",
                      "text")
    doc = _written_and_checked(ws, target, text, path, files, dof)
    doc["lines"] = text.count("\n") + (not text.endswith("\n") and bool(text))
    return doc


def _written_and_checked(ws: Workspace, target: Path, text: str, shown: str,
                         files: list | None, dof: bool, budget: float | None = None) -> dict:
    """Write the program ``text`` to ``target`` (or put it in ``files``: :func:`render`) and
    :func:`check` it as that file: the answer, with ``written``."""
    if files is not None:
        files.append((target, text.encode("utf-8"), None, shown))
    else:
        try:
            write_inside(ws, target, text.encode("utf-8"), None, shown)
        except OSError as e:
            raise Refused(str(e), "output_failed", "path") from None
    k = ws.budget if budget is None else budget
    doc = _checked(ws, compile_program(source=text, path=str(target), budget=k), dof, budget)
    doc["written"] = ws.relative(target)
    return doc


def set_params(ws: Workspace, path: str, values: dict, dof: bool = False,
               budget: float | None = None, files: list | None = None) -> dict:
    """Set the ``param`` values ``values`` (name -> value: ``"50 mm"``, a number in the
    param's own unit, written with it: ``40`` on ``param w = 60 mm`` is ``40 mm``; a bool) in the program file ``path`` (:func:`aidl_lang.api.set_params`:
    only each value's text changes, comments and formatting kept), write it and check it:
    :func:`check`'s result with ``written``.
    Raises :class:`Refused` (``no_match``: an unknown name, with the nearest;
    ``bad_argument``: a value of the wrong kind or outside its declared range, E0113/E0124:
    the file is left as it was)."""
    from ..api import ParamsRefused, set_params as _set
    if not isinstance(values, dict) or not values:
        raise Refused("values maps param names to values, e.g. {\"width\": \"50 mm\"}",
                      "bad_argument", "values")
    real, current = ws.read(path)
    target = ws.output(path, "path")
    k = ws.budget if budget is None else budget
    try:
        text, _ = _set(current, values, str(real), k)
    except ParamsRefused as e:
        raise Refused(for_agents(str(e)), "no_match" if e.code == "no_match" else
                      "bad_argument", "values") from None
    except ValueError as e:
        raise Refused(str(e), "bad_argument", "path") from None
    return _written_and_checked(ws, target, text, path, files, dof, budget)


def measure(ws: Workspace, a: str, b: str, source: str | None = None,
            path: str | None = None, overrides: dict | None = None,
            budget: float | None = None) -> dict:
    """Compile, then what lies between the named entities ``a`` and ``b``
    (:meth:`aidl_lang.api.Result.measure`: distance, centre distance, angle, clearance; mm
    and degrees, exact): ``{"ok", "units", "measure"}``; the diagnostics when the program
    did not solve.  Raises :class:`Refused` (``no_match``: a name that names nothing, with
    the nearest names, ``argument`` ``a`` or ``b``)."""
    r = ws.compile(source, path, overrides, budget)
    if not r.ok:
        return _summary(ws, r)
    try:
        got = r.measure(a, b)
    except KeyError as e:
        raise Refused(e.args[0], "no_match", e.args[1]) from None
    return {"ok": True, "units": r.units, "measure": _rounded(got)}


def _rounded(doc):
    """``doc`` with its floats rounded to 1e-9 (mm, degrees): exact to that, short."""
    if isinstance(doc, float):
        v = round(doc, 9)
        return 0.0 if v == 0 else v
    if isinstance(doc, dict):
        return {k: _rounded(v) for k, v in doc.items()}
    if isinstance(doc, (list, tuple)):
        return [_rounded(v) for v in doc]
    return doc


WARM = """units mm
solid plate {
    body = RoundedRectangle(center=(0, 0), width=40, height=20, corner_radius=2)
    hole bore { c = Circle(center=(10, 0), radius=4) }
    hole slot { s = Slot(start=(-15, 0), end=(-5, 0), width=3) }
}
"""


def warm(ws: Workspace) -> dict:
    """Compile, check, describe and draw a small program (PNG, SVG, DXF, G-code) without
    writing anything: the imports and first-call work of every tool done once, so the
    agent's first call costs what the later ones do.  Returns ``{"ok"}``."""
    r = compile_program(source=WARM, path=str(ws.root / "untitled.aidl"))
    r.find_redundant()
    _ = r.parts, r.description, r.values, r.fit
    for fmt in ("png", "svg", "dxf", "gcode"):
        r.encode(fmt, width=64) if fmt == "png" else r.encode(fmt)
    from ..output import for_cutting
    _job([for_cutting(r.output, None)], None, None)
    return {"ok": r.ok}


def explain(code: str) -> str:
    """``CODE: title`` and the explanation (as ``aidl explain``).  Raises :class:`Refused` for
    an unknown code, naming the known ones."""
    from ..base.codes import CODES
    c = (code or "").strip().upper()
    if c not in CODES:
        raise Refused(f"unknown code `{code}`; known codes: {', '.join(sorted(CODES))}",
                      "no_match", "code")
    title, text = CODES[c]
    return f"{c}: {title}\n\n{text.strip()}"
