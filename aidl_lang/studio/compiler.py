"""What a studio worker process does (:mod:`aidl_lang.workers` runs it, memory- and
time-limited): compile a user's program into the page's view, encode a download, draw a
gallery thumbnail.  Nothing here touches HTTP; every request and answer is plain data.

Requests (tuples, the first item names the kind):

* ``("view", sid, folder, source, values)``: the live preview, a JSON-ready dict as
  ``aidl serve`` sends it (``ok``, ``svg``, ``diagnostics``, ``params``, ``values``, ``timing``;
  see :meth:`aidl_lang.serve.session.Session.view`) with the shape checks included.  Each
  session (``sid``) keeps a warm :class:`~aidl_lang.serve.session.Session` in the worker
  (at most :data:`MAX_SESSIONS`, the least recently used dropped): a slider move re-solves on
  the compiled tapes instead of compiling again.  The program is named ``folder/main.aidl``,
  so its imports and ``Drawing2D`` files resolve only inside the session's own folder (its
  uploads) and the standard library (:mod:`aidl_lang.sources`, the import sandbox).
* ``("download", folder, source, values, fmt, settings)``: ``(bytes, file name, media type)``
  or ``{"error": message, "diagnostics": [...]}``; ``settings`` as :func:`download` takes.
* ``("thumb", id)``: the gallery entry's picture as SVG text (``""`` when it fails).
* ``("import", folder, name, infer)``: the uploaded drawing ``name`` of the session's folder
  as a program (``aidl import [--infer]``): ``{"program", "notes"}`` or ``{"error"}``.

Answers are dicts or tuples; a mistake in the program is a diagnostic, a bug an ``E0900``,
never an exception through the pipe.
"""
from __future__ import annotations

import io
import os
import zipfile
from collections import OrderedDict

from ..workers import rss

MAX_SESSIONS = 24               # warm sessions one worker keeps
RETIRE_RSS = 900 << 20          # bytes: a worker past this answers, then is replaced
MACHINES = ("laser", "router", "plotter")
MAX_SHEET = 5000.0              # mm: the largest sheet side a download may ask for


SESSION = "SESSION"              # what a visitor sees of the session's folder


def hide_paths(obj, folder: str):
    """``obj`` (an answer: dicts, lists, tuples of strings and numbers) with the session's
    ``folder`` written ``SESSION`` in every string (spans' ``file``, labels, messages, hints,
    rendered texts, the SVG) and the studio's data folder above it ``SESSION/..``: no server
    path reaches a visitor (docs/studio.md).  Bytes (a download) are left as they are."""
    folder = os.path.normpath(str(folder))
    pairs = []
    for f in dict.fromkeys((folder, os.path.realpath(folder))):
        pairs.append((f, SESSION))
        pairs.append((os.path.dirname(f), SESSION + "/.."))

    def fix(v):
        if isinstance(v, str):
            for a, b in pairs:
                if a and a != "/" and a in v:
                    v = v.replace(a, b)
            return v
        if isinstance(v, dict):
            return {fix(k): fix(x) for k, x in v.items()}
        if isinstance(v, list):
            return [fix(x) for x in v]
        if isinstance(v, tuple):
            return tuple(fix(x) for x in v)
        return v
    return fix(obj)


def handler(budget: float = 1.0):
    """The worker's request handler (run once in the new process); ``budget``: the factor of
    the default evaluation budget every compile gets (``aidl studio --budget``)."""
    from ..limits import DEFAULT_BUDGET
    sessions: OrderedDict = OrderedDict()
    scaled = DEFAULT_BUDGET.scaled(budget)

    def handle(request):
        kind = request[0]
        oom = False
        try:
            if kind == "view":
                answer = view(sessions, *request[1:], budget=scaled)
            elif kind == "download":
                answer = download(*request[1:], budget=scaled)
            elif kind == "thumb":
                answer = thumbnail(*request[1:])
            elif kind == "import":
                answer = import_upload(*request[1:], budget=scaled)
            else:
                answer = {"error": f"unknown request `{kind}`"}
        except Exception as e:          # noqa: BLE001 - answered, never a dead worker
            from ..limits import is_out_of_memory
            oom = is_out_of_memory(e)
            if not oom:
                answer = {"error": f"internal error: {type(e).__name__}: {e}"}
        if oom:                         # said once the failed frames are gone
            sessions.clear()
            answer = out_of_memory_answer(request)
        if kind in ("view", "download") and len(request) > 2:
            answer = hide_paths(answer, request[2] if kind == "view" else request[1])
        if rss() > RETIRE_RSS and isinstance(answer, dict):
            answer["retire"] = True     # give the memory back: a fresh worker takes over
        return answer
    return handle


def import_upload(folder: str, name: str, infer: bool, budget=None) -> dict:
    """The upload ``name`` (a ``.dxf`` or ``.svg`` of the session's ``folder``, read without
    following a link) as an AIDL program: ``{"program", "notes"}``, its notes as ``aidl
    import`` prints them; ``{"error"}`` for a drawing the importer refuses (docs/import.md)."""
    from ..drawing.infer import import_drawing
    from ..drawing.read import DrawingError
    from ..files import open_beneath, read_regular
    from ..sources import MAX_DRAWING_BYTES
    if not name.lower().endswith((".dxf", ".svg")):
        return {"error": f"`{name}` is not a .dxf or .svg drawing"}
    try:
        fd = open_beneath(folder, name)
        try:
            data = read_regular(fd, MAX_DRAWING_BYTES, name)
        finally:
            os.close(fd)
    except OSError as e:
        return {"error": f"cannot read `{name}`: {getattr(e, 'strerror', None) or e}"}
    try:
        text, notes = import_drawing(data, name, infer=infer, budget=budget)
    except DrawingError as e:
        return {"error": f"{name}: error[{e.code}]: {e.message}"
                         + (f" (help: {e.hint})" if e.hint else "")}
    return {"program": text,
            "notes": [f"{name}: warning[{n.code}]: {n.message}" for n in notes]}


def out_of_memory_answer(request) -> dict:
    """The answer to a ``view`` or ``download`` whose compile ran out of memory: the
    program's located ``E0304`` (:func:`aidl_lang.pipeline.out_of_memory_sink`), and the
    worker retired (a fresh process gives the memory back)."""
    from ..pipeline import out_of_memory_sink
    kind = request[0]
    folder, source = (request[2], request[3]) if kind == "view" else (request[1], request[2])
    path = os.path.join(folder, "main.aidl")
    sink = out_of_memory_sink(path, source if isinstance(source, str) else None)
    diags = [{k: d.to_json(sink.sources)[k] for k in
              ("code", "severity", "message", "span", "hint", "rendered")} for d in sink.items]
    msg = diags[0]["message"]
    if kind == "view":
        return {"ok": False, "svg": None, "params": None, "diagnostics": diags, "error": msg,
                "retire": True}
    return {"error": msg, "diagnostics": diags, "retire": True}


def view(sessions: OrderedDict, sid: str, folder: str, source: str, values: dict,
         budget=None) -> dict:
    """The live preview of ``source`` with the customizer's ``values`` ({name: "40 mm"});
    ``budget``: a :class:`~aidl_lang.limits.Budget` (None: the default)."""
    from ..serve.session import Session
    s = sessions.pop(sid, None)
    if s is None:
        s = Session(os.path.join(folder, "main.aidl"))
        if budget is not None:
            s.budget = budget
    sessions[sid] = s
    while len(sessions) > MAX_SESSIONS:
        sessions.popitem(last=False)
    values = {str(k): str(v) for k, v in (values or {}).items()}
    files = _listing(folder)        # an upload changes what the same program draws
    if s.source != source or s.program is None or files != getattr(s, "files", None):
        s.files = files
        s.values = values
        doc = s.load(source)
    elif values != s.values:
        doc = s.set_params(values)
        doc = s.update_checks() or doc
    else:
        doc = s.view()
    doc = dict(doc)
    doc.pop("file", None)
    doc.pop("source", None)             # the page has it
    return doc


def _listing(folder: str) -> tuple:
    """The session folder's files as ``(name, size, mtime_ns)``, sorted."""
    try:
        with os.scandir(folder) as it:
            return tuple(sorted((e.name, e.stat(follow_symlinks=False).st_size,
                                 e.stat(follow_symlinks=False).st_mtime_ns) for e in it))
    except OSError:
        return ()


def _number(settings: dict, key: str, lo: float, hi: float) -> float | None:
    v = settings.get(key)
    if v is None or v == "":
        return None
    try:
        x = float(v)
    except (TypeError, ValueError):
        raise ValueError(f"{key} expects a number in mm, got `{str(v)[:40]}`") from None
    if not lo <= x <= hi:
        raise ValueError(f"{key} expects a number between {lo:g} and {hi:g} mm, got {x:g}")
    return x


def download(folder: str, source: str, values: dict, fmt: str, settings: dict, budget=None):
    """The program in format ``fmt`` (``svg``, ``dxf``, ``pdf``, ``gcode``, ...; see
    :data:`aidl_lang.output.FORMATS`): ``(bytes, file name, media type)``, or
    ``{"error", "diagnostics"}``.

    ``settings``: ``kerf`` (mm, 0-10; empty: the program's own ``kerf``), ``thickness`` (mm,
    0.1-100: the sheet's thickness for the 3D formats), ``machine`` (``laser``, ``router``,
    ``plotter``: the G-code profile), ``assembled`` (bool: the 3D formats with every part
    placed), ``sheet`` ([width, height] mm with ``layout`` true: the cutting sheet, every part
    nested on sheets of that size; several sheets come as a ZIP of one file per sheet)."""
    from .. import api
    from ..output import ASSEMBLED_FORMATS, FORMATS
    from ..output.part import MissingDependency, OutputError
    suffix = "." + str(fmt).lower().lstrip(".")
    if suffix not in FORMATS:
        return {"error": f"unknown format `{fmt}`; use one of "
                         + ", ".join(sorted(f[1:] for f in FORMATS))}
    settings = settings if isinstance(settings, dict) else {}
    try:
        kerf = _number(settings, "kerf", 0.0, 10.0)
        thickness = _number(settings, "thickness", 0.1, 100.0)
        machine = settings.get("machine") or None
        if machine is not None and machine not in MACHINES:
            raise ValueError(f"machine expects one of {', '.join(MACHINES)}, got `{machine}`")
        assembled = bool(settings.get("assembled")) and suffix in ASSEMBLED_FORMATS
        layout = bool(settings.get("layout")) and FORMATS[suffix].cut
        sheet = settings.get("sheet") or [600, 400]
        if layout:
            if not (isinstance(sheet, (list, tuple)) and len(sheet) == 2):
                raise ValueError("sheet expects [width, height] in mm")
            sheet = tuple(_number({"sheet": v}, "sheet", 10.0, MAX_SHEET) for v in sheet)
    except ValueError as e:
        return {"error": str(e)}
    res = api.compile(source=source, path=os.path.join(folder, "main.aidl"),
                      overrides={str(k): str(v) for k, v in (values or {}).items()},
                      budget=budget)
    if not res.ok:
        return {"error": "the program does not compile with these values",
                "diagnostics": [{k: d[k] for k in ("code", "severity", "message", "rendered")}
                                for d in res.diagnostics_json() if d["severity"] == "error"][:8]}
    name = res.compiled.model.root.name if res.compiled.model is not None else "part"
    options = {"thickness": thickness, "machine": machine, "assembled": assembled}
    media = FORMATS[suffix].media
    try:
        if layout:
            options.pop("assembled")
            sheets = res.layout(sheet=sheet, kerf=kerf).encode(suffix, **options)
            if len(sheets) == 1:
                return sheets[0], f"{name}-sheet{suffix}", media
            buf = io.BytesIO()
            with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
                for i, data in enumerate(sheets, 1):
                    z.writestr(f"{name}-sheet-{i}{suffix}", data)
            return buf.getvalue(), f"{name}-sheets.zip", "application/zip"
        return res.encode(suffix, kerf, **options), f"{name}{suffix}", media
    except (MissingDependency, OutputError, ValueError) as e:
        if getattr(e, "budget", None) is not None:      # bounded work or memory: E0304
            from ..pipeline import report_out_of_budget
            report_out_of_budget(res.sink, e.budget)
            return {"error": str(e),
                    "diagnostics": [{k: d[k] for k in ("code", "severity", "message", "rendered")}
                                    for d in res.diagnostics_json() if d["severity"] == "error"]}
        return {"error": str(e)}


def thumbnail(entry_id: str) -> str:
    """The gallery entry's default picture (SVG text; ``""`` when it does not render)."""
    from . import gallery
    e = gallery.entry(entry_id)
    if e is None:
        return ""
    try:
        return gallery.thumbnail(e)
    except Exception:               # noqa: BLE001 - a missing picture, not a broken gallery
        return ""
