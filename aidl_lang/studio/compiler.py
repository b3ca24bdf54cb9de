"""What a studio worker process does (:mod:`aidl_lang.host.workers` runs it, memory- and
time-limited): compile a user's program into the page's view, encode a download, draw a
gallery thumbnail.  Nothing here touches HTTP; every request and answer is plain data.

Requests (tuples, the first item names the kind):

* ``("view", sid, folder, source, values[, defaults])``: the live preview, a JSON-ready dict
  as ``aidl serve`` sends it (``ok``, ``svg``, ``diagnostics``, ``params``, ``values``,
  ``timing``; see :meth:`aidl_lang.serve.session.Session.view`) with the shape checks
  included, and ``dropped`` (:func:`view`: the values that are not this program's).  Each
  session (``sid``) keeps a warm :class:`~aidl_lang.serve.session.Session` in the worker
  (at most :data:`MAX_SESSIONS`, the least recently used dropped): a slider move re-solves on
  the compiled tapes instead of compiling again.  The program is named ``folder/main.aidl``,
  so its imports and ``Drawing2D`` files resolve only inside the session's own folder (its
  uploads) and the standard library (:mod:`aidl_lang.library.sources`, the import sandbox).
* ``("download", folder, source, values, fmt, settings)``: ``(bytes, file name, media type)``
  or ``{"error": message, "diagnostics": [...]}``; ``settings`` as :func:`download` takes.
* ``("glb", sid, folder, source, values, settings)``: the 3D view's GLB
  (:func:`aidl_lang.output.writers.glb.to_view_glb`: fewer triangles, shared meshes) as
  ``(bytes, name, media type)`` or ``{"error"}``, made from the drawing the session's last
  ``view`` of this program and these values drew (no second compile), else compiled.
* ``("sweep", sid, folder, source, values[, scale])``: the program checked across its params' ranges,
  each slider alone at the others' ``values`` (:func:`aidl_lang.params.sweep.sweep`, bounded by its
  budget) as the sliders mark it (:func:`sweep_ranges`).
* ``("thumb", id)``: the gallery entry's picture as SVG text (``""`` when it fails).
* ``("import", folder, name, infer)``: the uploaded drawing ``name`` of the session's folder
  as a program (``aidl import [--infer]``; ``infer="drawing"``: a program that uses the
  drawing as it is, ``Drawing2D``): ``{"program", "notes"}`` or ``{"error"}``.

Answers are dicts or tuples; a mistake in the program is a diagnostic, a bug an ``E0900``,
never an exception through the pipe.
"""
from __future__ import annotations

import io
import os
import re
import time
import zipfile
from collections import OrderedDict

from ..host.workers import rss
from .hatching import sweep_ranges  # noqa: F401 - the sweep workers' answer (and its tests)

MAX_SESSIONS = 24               # warm sessions one worker keeps
MAX_CLAMPS = 4                  # compiles that move values back into dependent ranges
RETIRE_RSS = 900 << 20          # bytes: a worker past this answers, then is replaced
MACHINES = ("laser", "router", "plotter")
MAX_SHEET = 5000.0              # mm: the largest sheet side a download may ask for
PAGES = ("A4", "Letter", "A3", "Legal")     # PDF paper a download may tile over (+ -landscape)
# while a request compiles, Python's cycle collector runs on every YOUNG_OBJECTS new objects
# (generation 0), on the request's survivors every YOUNG_ROUNDS of those (generation 1: a long
# compile's garbage stays bounded), and never walks the whole heap (a full collection in the
# middle of a planetary slider move: 0.1 to 0.4 s of its 0.5 to 1.7 s); the rest is collected
# after the answer is sent (:func:`collect_garbage`)
YOUNG_OBJECTS = 50_000
YOUNG_ROUNDS = 20
WHOLE_LATEST = 3            # (collect_garbage: a whole-heap collection waits at most 3 rhythms)
# what a worker imports, imported once by the forkserver its workers are forked from
# (:func:`aidl_lang.host.workers.context`): the handler's imports and a compile's
PRELOAD = ("aidl_lang.studio.compiler", "aidl_lang.studio.wording", "aidl_lang.pipeline",
           "aidl_lang.serve.session", "aidl_lang.output.writers.mesh", "trimesh.exchange.gltf",
           "manifold3d", "svgwrite")


def can_make(fmt: str) -> bool:
    """Whether this installation writes format ``fmt`` (``step``, ``.step``, ...): STEP needs
    OCP (the ``step`` extra); the page offers only the formats this is true of."""
    if str(fmt).lower().lstrip(".") in ("step", "stp"):
        import importlib.util
        return importlib.util.find_spec("OCP") is not None
    return True


SESSION = "SESSION"              # what a visitor sees of the session's folder


def hide_paths(obj, folder: str):
    """``obj`` (an answer: dicts, lists, tuples of strings and numbers) with the session's
    ``folder`` written ``SESSION`` in every string (spans' ``file``, labels, messages, hints,
    rendered texts, the SVG) and the studio's data folder above it ``SESSION/..``: no server
    path reaches a visitor (docs/studio.md).  Bytes (a download) are left as they are."""
    from ..base.diagnostics import _stdlib_roots
    folder = os.path.normpath(str(folder))
    pairs = []
    for f in dict.fromkeys((folder, os.path.realpath(folder))):
        pairs.append((f, SESSION))
        pairs.append((os.path.dirname(f), SESSION + "/.."))
    # a standard-library file as a program imports it (std/gears.aidl), as messages show it
    pairs[:0] = [(r, "std/") for r in _stdlib_roots()]

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
    from ..base.limits import DEFAULT_BUDGET
    from .wording import page_answer
    # trimesh (1.5 s to import on a busy machine) and Manifold now, in the new process, not
    # on its first 3D view
    from ..output.writers.mesh import _trimesh
    _trimesh().exchange.gltf  # noqa: B018
    import manifold3d  # noqa: F401
    sessions: OrderedDict = OrderedDict()
    scaled = DEFAULT_BUDGET.scaled(budget)
    import gc
    normal = gc.get_threshold()

    def handle(request):
        kind = request[0]
        oom = False
        started, cpu = time.perf_counter(), time.process_time()
        gc.set_threshold(YOUNG_OBJECTS, YOUNG_ROUNDS, 1 << 30)    # collect_garbage: back
        try:
            if kind == "view":
                answer = view(sessions, *request[1:], budget=scaled)
            elif kind == "checks":
                answer = checks(sessions, *request[1:], budget=scaled)
            elif kind == "download":
                answer = download(*request[1:], budget=scaled)
            elif kind == "glb":
                answer = view_glb(sessions, *request[1:], budget=scaled)
            elif kind == "sweep":       # (a sixth item: that many times the budget, issue 113)
                answer = sweep_ranges(request[2], request[3], budget=scaled if len(request) < 6
                                      else DEFAULT_BUDGET.scaled(budget * float(request[5])),
                                      values=request[4] if len(request) > 4 else None)
            elif kind == "thumb":
                answer = thumbnail(*request[1:])
            elif kind == "import":
                answer = import_upload(*request[1:], budget=scaled)
            else:
                answer = {"error": f"unknown request `{kind}`"}
        except Exception as e:          # noqa: BLE001 - answered, never a dead worker
            from ..base.limits import is_out_of_memory
            oom = is_out_of_memory(e)
            if not oom:                 # a fault of the studio: logged, said without Python
                import sys
                import traceback
                print(f"aidl studio: internal error answering {kind}:\n"
                      f"{traceback.format_exc()}", file=sys.stderr, flush=True)
                from .wording import FAULT, FAULT_HINT
                answer = {"error": f"{FAULT}; {FAULT_HINT}"}
        if oom:                         # said once the failed frames are gone
            sessions.clear()
            answer = out_of_memory_answer(request)
        if kind in ("view", "checks", "download", "glb", "sweep") and len(request) > 2:
            answer = hide_paths(answer, request[1] if kind == "download" else request[2])
        if isinstance(answer, dict):    # every text a visitor reads, worded for the page
            answer = page_answer(answer)
        if kind == "view" and isinstance(answer, dict) and isinstance(answer.get("timing"), dict):
            # the request's whole time in this worker (the compile, the shape checks, a move
            # into the ranges, the wording): the page's benchmark splits it from the transfer
            # (and its CPU time: the rest of worker_ms is the machine's other work)
            answer["timing"] = {**answer["timing"],
                                "worker_ms": round((time.perf_counter() - started) * 1000, 1),
                                "cpu_ms": round((time.process_time() - cpu) * 1000, 1)}
        if rss() > RETIRE_RSS and isinstance(answer, dict):
            answer["retire"] = True     # give the memory back: a fresh worker takes over
        return answer
    handle.idle = lambda: collect_garbage(normal)
    handle.quiet = lambda: collect_garbage(normal, whole=True)
    return handle


def collect_garbage(threshold: tuple, whole: bool = False) -> None:
    """After an answer is sent (:mod:`aidl_lang.host.workers` calls the handler's ``idle``): the
    young objects of the request just answered collected (its compile's cycles: 0.02 to 0.15
    s for a planetary move) and the collector's ``threshold`` set back until the next request.
    The whole heap (0.3-0.5 s in a worker that drew a planetary) is collected every
    ``threshold[2]``-th time (CPython's own rhythm) once the worker is quiet (``whole``: the
    handler's ``quiet``, when no request came right after the answer): it held back the 3D
    and checks the page asks for a moment after a picture (issue 104); after
    :data:`WHOLE_LATEST` times that many without a quiet moment, at once."""
    import gc
    gc.set_threshold(*threshold)
    gc.collect(1)
    if gc.get_count()[2] >= threshold[2] * (1 if whole else WHOLE_LATEST):
        gc.collect()


def _upload_bytes(folder: str, name: str) -> bytes:
    """The bytes of the session's upload ``name``, opened once beneath ``folder`` without
    following a link, at most the drawings' size limit; ``OSError`` when it cannot be."""
    from ..host.files import open_beneath, read_regular
    from ..library.sources import MAX_DRAWING_BYTES
    fd = open_beneath(folder, name)
    try:
        return read_regular(fd, MAX_DRAWING_BYTES, name)
    finally:
        os.close(fd)


def _unreadable(name: str, e: OSError) -> dict:
    return {"error": f"cannot read `{name}`: {getattr(e, 'strerror', None) or e}"}


def _refused(name: str, e) -> dict:
    """A :class:`~aidl_lang.drawing.model.DrawingError` as the page shows it."""
    return {"error": f"{name}: error[{e.code}]: {e.message}"
                     + (f" (help: {e.hint})" if e.hint else "")}


def import_upload(folder: str, name: str, infer: bool, budget=None) -> dict:
    """The upload ``name`` (a ``.dxf`` or ``.svg`` of the session's ``folder``, read without
    following a link) as an AIDL program: ``{"program", "notes"}``, its notes as ``aidl
    import`` prints them; ``{"error"}`` for a drawing the importer refuses (docs/import.md)."""
    from ..drawing.infer import import_drawing
    from ..drawing.model import DrawingError
    if not name.lower().endswith((".dxf", ".svg")):
        return {"error": f"`{name}` is not a .dxf or .svg drawing"}
    if infer == "drawing":
        return drawing_program(folder, name)
    try:
        text, notes = import_drawing(_upload_bytes(folder, name), name, infer=infer,
                                     budget=budget)
    except OSError as e:
        return _unreadable(name, e)
    except DrawingError as e:
        return _refused(name, e)
    related: list[str] = []
    if infer is True:               # its sizes' relations as ranges that follow each other
        from .relations import with_relations
        text, related = with_relations(text)
    return {"program": text,
            "notes": [f"{name}: warning[{n.code}]: {n.message}" for n in notes] + related}


def drawing_program(folder: str, name: str) -> dict:
    """A program that uses the upload ``name`` as it is (``Drawing2D``): a ``solid`` of its
    closed outlines, or a ``drawing`` (lines only) when it has open paths or nothing closed;
    its size in a comment.  ``{"program", "notes"}`` or ``{"error"}`` as :func:`import_upload`."""
    from ..drawing.model import DrawingError
    from ..drawing.read import read_drawing
    try:
        d = read_drawing(_upload_bytes(folder, name), name)
    except OSError as e:
        return _unreadable(name, e)
    except DrawingError as e:
        return _refused(name, e)
    import json
    import re
    closed = bool(d.outlines or d.circles or d.ellipses)
    kind = "solid" if closed and not d.paths else "drawing"
    box = d.box()
    size = f", {box[2] - box[0]:.6g} x {box[3] - box[1]:.6g} mm" if box else ""
    ident = re.sub(r"\W", "_", os.path.splitext(name)[0]).strip("_").lower() or "part"
    if not ident[0].isalpha():
        ident = "part_" + ident
    why = "" if kind == "solid" else \
        "\n# a drawing (lines only): it has open paths, so it is engraved or drawn, not cut out"
    program = (f"# {name} as it is{size} (Drawing2D: its curves exactly, where the file puts "
               f"them){why}\n{kind} {ident} {{\n"
               f"    shape = Drawing2D({json.dumps(name)})\n}}\n")
    return {"program": program,
            "notes": [f"{name}: warning[{n.code}]: {n.message}" for n in d.notes][:8]}


def out_of_memory_answer(request) -> dict:
    """The answer to a ``view`` or ``download`` whose compile ran out of memory: the
    program's located ``E0304`` (:func:`aidl_lang.pipeline.out_of_memory_sink`), and the
    worker retired (a fresh process gives the memory back)."""
    from ..pipeline import out_of_memory_sink
    kind = request[0]
    folder, source = (request[1], request[2]) if kind == "download" else (request[2], request[3])
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
         defaults: dict | None = None, later: bool = False, budget=None) -> dict:
    """The live preview of ``source`` with the customizer's ``values`` ({name: "40 mm"});
    ``defaults``: ``{name: default}`` (display units, as the answer's params give them) the
    page chose ``values`` against; ``budget``: a :class:`~aidl_lang.base.limits.Budget` (None:
    the default).

    The answer depends on the request only, never on what this worker compiled before for
    the session (its other worker may have answered the previous request): the params'
    ``default`` is the program's own value; a value whose param the program does not have,
    or whose default differs from the one in ``defaults``, is dropped and named in
    ``dropped`` (a new program starts from its own values); ``values`` is what the picture
    was drawn with (the kept values, and the ``clamped`` ones moved into their ranges).  An
    answer whose program does not check has no ``params`` and no ``svg`` (the last good
    picture of another program is not this program's).

    ``later``: a slider move's shape checks (W0402, W0501-W0510: the warnings; 0.2 of a
    planetary move's 0.5 s) are left for :func:`checks`, asked right after the picture is
    shown; the answer says ``"checks": "pending"``."""
    from ..serve.session import Session, keep_values
    s = sessions.pop(sid, None)
    if s is None:
        s = Session(os.path.join(folder, "main.aidl"))
        if budget is not None:
            s.budget = budget
    sessions[sid] = s
    while len(sessions) > MAX_SESSIONS:
        sessions.popitem(last=False)
    values = {str(k): str(v) for k, v in (values or {}).items()}
    values, chose = to_choices(source, values)
    assumed = defaults if isinstance(defaults, dict) else {}
    files = _listing(folder)        # an upload changes what the same program draws
    if s.source != source or s.program is None or files != getattr(s, "files", None):
        s.files = files
        s.values = dict(values)
        doc = s.load(source, assumed=assumed)
        kept = keep_values(values, s.defaults, assumed) if s.program is not None else {}
        if kept and doc.get("ok") and s.values != kept:
            # load drops the values its compile with them fails: the visitor's values (what
            # the sliders show) apply, with their error or moved into their ranges (below)
            doc = s.set_params(kept)
            if not later:
                doc = s.update_checks() or doc
    else:
        kept = keep_values(values, s.defaults, assumed)
        if kept != s.values:
            doc = s.set_params(kept)
            if not later:
                doc = s.update_checks() or doc
        else:
            doc = s.view()
    clamped: dict = {}
    if not doc.get("ok") and s.program is not None:
        settled, clamped = settle(s.set_params, s.values, doc)
        if clamped:         # (with `later`, its checks too: a planetary move's sun moved onto
            # its step spent 0.2-0.4 s on them before its picture)
            doc = settled if later else s.update_checks() or settled
        elif settled is not doc:
            s.set_params(kept)          # no better: the visitor's values, and their error
    doc = dict(doc)
    if later and getattr(s, "_checks_pending", None) is not None and doc.get("ok"):
        doc["checks"] = "pending"       # the page asks /api/checks for them
    chose = {k: v for k, v in chose.items() if k in kept}
    if chose:                       # a text value none of its choices: the program's own used
        clamped = {**clamped, **{k: v[0] for k, v in chose.items()}}
        doc["moved"] = {k: v[1] for k, v in chose.items()}     # what the page says of each
    if clamped:
        doc["clamped"] = clamped
    doc["dropped"] = sorted(set(values) - set(kept))
    if s.program is None:
        doc["params"] = None            # the params of a program that checked before, not this
    if s.svg_source != source:          # the last good picture is another program's
        doc["svg"], doc["values"] = None, {}
    elif s.shown is not None and getattr(s.shown[1], "title", None):
        doc["title"] = s.shown[1].title  # its design's name: a pasted program's header
    if doc.get("params"):               # a text param of a few values: the page's list
        from .forms.choices import choices
        listed = choices(source)
        doc["params"] = [{**p, "choices": listed[p["name"]]}
                         if p.get("kind") == "string" and p.get("name") in listed else p
                         for p in doc["params"]]
    doc.pop("file", None)
    doc.pop("source", None)             # the page has it
    return doc


def checks(sessions: OrderedDict, sid: str, folder: str, source: str, values: dict,
           budget=None) -> dict:
    """The shape checks a ``view`` with ``later`` left (see :func:`view`): ``{"ok",
    "version", "values", "diagnostics"}`` of the picture of ``source`` with ``values`` (the
    ``--set`` texts it was drawn with), every message of it, the checks' warnings included.
    Run on the session ``sid`` this worker keeps when it drew that picture (its drawing is
    checked: no compile); else (another worker drew it) the picture's compile again here."""
    values = {str(k): str(v) for k, v in (values or {}).items()}
    s = sessions.get(sid)
    if s is None or s.source != source or s.svg_values != values:
        doc = view(sessions, sid, folder, source, values, None, budget=budget)
    else:
        doc = s.update_checks() or s.view()
    return {"ok": bool(doc.get("ok")), "version": doc.get("version"),
            "values": doc.get("values") or {}, "diagnostics": doc.get("diagnostics") or []}


def view_glb(sessions: OrderedDict, sid: str, folder: str, source: str, values: dict,
             settings: dict, budget=None):
    """The 3D view of ``source`` with ``values``: ``(GLB bytes, "view.glb", media type)`` or
    ``{"error": message}``.  ``settings``: ``thickness`` (mm, 0.1-100; empty: the parts' own).
    Made from the drawing session ``sid``'s last view drew when it drew this program with
    these values (the page asks for the 3D right after its picture: no second compile), else
    from a fresh compile (another worker drew the picture)."""
    from ..output.part.part import OutputError
    from ..output.writers.glb import to_view_glb
    values = {str(k): str(v) for k, v in (values or {}).items()}
    try:
        thickness = _number(settings if isinstance(settings, dict) else {}, "thickness",
                            0.1, 100.0)
    except ValueError as e:
        return {"error": str(e)}
    s = sessions.get(sid)
    shown = getattr(s, "shown", None) if s is not None else None
    if s is not None and shown is not None and s.source == source and s.ok \
            and s.svg_values == values and shown[1] is not None:
        output = shown[1]
    else:
        from .. import api
        res = api.compile(source=source, path=os.path.join(folder, "main.aidl"),
                          overrides=values, budget=budget)
        if not res.ok:
            return {"error": "the program does not compile with these values"}
        try:
            output = res.output
        except OutputError as e:
            return {"error": str(e)}
    if not any(p.kind == "solid" for p in output.parts) and not output.engrave:
        # a hole that removes all of its part: the right reason in this pane (it said "only
        # lines: a drawing")
        return {"error": "nothing to show in 3D with these values: no part is left (the "
                         "messages under the program say why)"}
    try:
        return to_view_glb(output, thickness), "view.glb", "model/gltf-binary"
    except (OutputError, ValueError) as e:
        return {"error": str(e)}


def settle(run, values: dict, doc: dict) -> tuple[dict, dict]:
    """Compile again, at most :data:`MAX_CLAMPS` times, with the values of the failed
    ``doc`` (``run(values)``'s answer: ``ok``, ``params`` as the view's JSON rows) that left
    a range depending on other params moved back into it (:func:`into_range`).  Returns
    ``(answer, {name: number moved to})``: the first answer that compiles and what was
    moved, or the last answer tried and ``{}`` when none compiles."""
    clamped: dict = {}
    values = dict(values)
    for _ in range(MAX_CLAMPS):
        # values out of their ranges first; then those between their sliders' steps too (a
        # step that depends on other params: the planetary's sun steps by its planets)
        fixed = into_range(doc.get("params") or []) or \
            into_range(doc.get("params") or [], grid=True)
        if not fixed:
            break
        values.update({k: t for k, (t, _) in fixed.items()})
        clamped.update({k: x for k, (_, x) in fixed.items()})
        doc = run(dict(values))
        if doc.get("ok"):
            return doc, clamped
    return doc, {}


def to_choices(source: str, values: dict) -> tuple[dict, dict]:
    """``values`` (``--set`` texts) with a text param's value that is none of the values it
    takes (:func:`.forms.choices.choices`: the mounting plate's ``fit`` is fine, medium or
    coarse) replaced by the program's own, and ``{name: (value used, sentence)}`` for each
    (issue 113: a share link's ``fit = "tight"`` showed the template's assertion, a blank
    list and a broken picture)."""
    from .forms.choices import _PARAM, choices
    listed = choices(source) if any(k for k in values) else {}
    if not listed:
        return values, {}
    own = {m.group(1): m.group(2) for m in _PARAM.finditer(source)}
    out, chose = dict(values), {}
    for name, text in values.items():
        took = listed.get(name)
        got = text.strip()
        if len(got) >= 2 and got[0] == got[-1] == '"':
            got = got[1:-1]
        if not took or got in took or own.get(name) not in took:
            continue
        said = ", ".join(took[:-1]) + f" or {took[-1]}" if len(took) > 1 else took[0]
        out[name] = f'"{own[name]}"'
        chose[name] = (own[name], f"{name} is {said}: “{got[:40]}” is none of them, so "
                                  f"{own[name]} is used")
    return out, chose


def into_range(params: list[dict], grid: bool = False) -> dict[str, tuple[str, float]]:
    """The values of a failed compile's ``params`` (the view's JSON rows) that left their
    declared range moved into it, onto its slider's steps (``grid``: also the values inside
    it that lie between steps): ``{name: (--set text, number)}`` (display units).  A range
    may depend on other params (``param depth = 70 mm, min = rows * (hole + 4 mm)``,
    docs/language.md): moving ``rows`` moves it, and the form's ``depth`` follows instead of
    the compile failing (docs/studio.md, "Forms that cannot fail")."""
    out = {}
    for p in params:
        lo, hi, step, v = p.get("min"), p.get("max"), p.get("step"), p.get("value")
        if p.get("kind") not in ("length", "angle", "number") or not p.get("declared") \
                or not isinstance(v, (int, float)) or lo is None or hi is None or lo > hi:
            continue
        if not grid and lo - 1e-9 <= v <= hi + 1e-9:
            continue
        w = min(max(v, lo), hi)
        near = 1e-6 * max(1.0, abs(w))  # the page sends values rounded to 1e-6
        if abs(v - hi) <= near or abs(v - lo) <= near:
            w = hi if abs(v - hi) <= near else lo   # a slider's end: that end, not a step
        elif step and step > 0:         # onto the slider's grid, inside the range
            w = lo + round((w - lo) / step) * step
            if w > hi + 1e-9:
                w -= step
            w = max(w, lo)
        w = round(w, 9)
        if abs(w - v) > 1e-9 * max(1.0, abs(v)):
            out[p["name"]] = (f"{w:.12g} {p.get('unit') or ''}".strip(), w)
    return out


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
    except (TypeError, ValueError, OverflowError):
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
    nested on sheets of that size; several sheets come as a ZIP of one file per sheet),
    ``page`` (PDF: the paper it is tiled over 1:1, ``A4``, ``Letter-landscape``, ... of
    :data:`PAGES`, as ``aidl render --page``).  G-code without ``layout`` has the drawing's
    lower-left corner on the machine's origin (the sheet's corner: no negative coordinate)."""
    from .. import api
    from ..output import FORMATS
    from ..output.part.part import MissingDependency, OutputError
    suffix = "." + str(fmt).lower().lstrip(".")
    if suffix not in FORMATS:
        return {"error": f"unknown format `{fmt}`; use one of "
                         + ", ".join(sorted(f[1:] for f in FORMATS))}
    try:
        got = download_settings(suffix, settings)
    except ValueError as e:
        return {"error": str(e)}
    kerf, layout, sheet, options = got["kerf"], got["layout"], got["sheet"], got["options"]
    overrides = {str(k): str(v) for k, v in (values or {}).items()}
    path = os.path.join(folder, "main.aidl")
    res = api.compile(source=source, path=path, overrides=overrides, budget=budget)
    if not res.ok and overrides:
        # the values as the preview draws them: a value outside a range that follows the
        # other params is moved into it (:func:`settle`), so /api/view and /api/download
        # agree; a value that cannot be moved keeps its error
        drawn = view(OrderedDict(), "", folder, source, overrides, None, budget=budget)
        if drawn.get("ok") and drawn.get("clamped") and drawn.get("values"):
            res = api.compile(source=source, path=path, overrides=dict(drawn["values"]),
                              budget=budget)
    if not res.ok:
        return {"error": "the program does not compile with these values",
                "diagnostics": _errors(res)[:8]}
    if not res.output.parts and not res.output.engrave:
        return nothing_to_make(res)
    name = file_base(settings.get("name") if isinstance(settings, dict) else None) or (
        res.compiled.model.root.name if res.compiled.model is not None else "part")
    if options.get("style") == "preview":
        name += "-preview"              # the picture, never under the cutting file's name
    media = FORMATS[suffix].media
    tags = settings_tags(suffix, got)   # what the settings change: never one name for two files
    try:
        if layout:
            options.pop("assembled")
            sheets = res.layout(sheet=sheet, kerf=kerf).encode(suffix, **options)
            if len(sheets) == 1:
                return sheets[0], f"{name}-sheet{tags}{suffix}", media
            buf = io.BytesIO()
            with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
                for i, data in enumerate(sheets, 1):
                    z.writestr(f"{name}-sheet-{i}{tags}{suffix}", data)
            # one name per format: the DXF, SVG and PDF sheets never overwrite each other
            return buf.getvalue(), f"{name}-sheets{tags}-{suffix[1:]}.zip", "application/zip"
        assembled = options.get("assembled")
        if suffix == ".stl" and assembled:
            return closed_stl(res.output, options["thickness"]), f"{name}{tags}{suffix}", media
        if FORMATS[suffix].module == "gcode" and not assembled:
            return (gcode_at_origin(res.output, kerf, suffix, options), f"{name}{tags}{suffix}",
                    media)
        return res.encode(suffix, kerf, **options), f"{name}{tags}{suffix}", media
    except (MissingDependency, OutputError, ValueError) as e:
        if getattr(e, "budget", None) is not None:      # bounded work or memory: E0304
            from ..pipeline import report_out_of_budget
            report_out_of_budget(res.sink, e.budget)
            return {"error": str(e), "diagnostics": _errors(res)}
        return {"error": str(e)}


SVG_STYLES = ("laser", "preview")
DEFAULT_SHEET = (600.0, 400.0)  # mm: the cutting sheet of a download that names none


def settings_tags(suffix: str, got: dict) -> str:
    """What a download's settings (``got``: :func:`download_settings`' answer for the format
    ``suffix``) change in its file, as its name's tail (issue 113: ``finger_box-sheet.dxf``
    was one name for the sheet with no kerf and with 0.2 mm, for 600 x 400 and 1000 x 1000
    sheets; ``.gcode`` for the laser and the router; ``.pdf`` for one page and A4 tiles):
    ``-kerf0.2`` (a kerf given, cutting formats), ``-1000x1000`` (a sheet other than
    :data:`DEFAULT_SHEET`, nested), ``-router`` / ``-plotter`` (G-code for a machine other
    than the laser it is written for by default), ``-a4tiles`` / ``-letter-landscapetiles``
    (a PDF tiled over paper).  ``""`` for the defaults: the names of files made with them
    stay as they were."""
    from ..output import FORMATS
    fmt, opts = FORMATS[suffix], got["options"]
    tags = []
    if got["kerf"] is not None and fmt.cut and not opts.get("assembled"):
        tags.append(f"kerf{got['kerf']:g}")
    if got["layout"] and tuple(float(x) for x in got["sheet"]) != DEFAULT_SHEET:
        tags.append("x".join(f"{float(x):g}" for x in got["sheet"]))
    if fmt.module == "gcode" and opts.get("machine") not in (None, "laser"):
        tags.append(opts["machine"])
    if opts.get("page"):
        tags.append(f"{opts['page'].lower()}tiles")
    return "".join(f"-{t}" for t in tags)


def download_settings(suffix: str, settings) -> dict:
    """A download's ``settings`` (see :func:`download`) checked for the format ``suffix``
    (``.svg``): ``{"kerf", "layout", "sheet", "options"}``, ``options`` the writer's
    (``thickness``, ``machine``, ``assembled``, ``page``; ``style`` for SVG: ``laser`` unless
    ``preview`` is asked).  Raises :class:`ValueError` with a sentence for a setting that is
    not one the download takes (the server answers it 400 before any compile)."""
    from ..output import ASSEMBLED_FORMATS, FORMATS
    if settings is None:
        settings = {}
    if not isinstance(settings, dict):
        raise ValueError("`settings` is an object of download settings (kerf, sheet, machine...)")
    kerf = _number(settings, "kerf", 0.0, 10.0)
    thickness = _number(settings, "thickness", 0.1, 100.0)
    machine = settings.get("machine") or None
    if machine is not None and machine not in MACHINES:
        raise ValueError(f"machine expects one of {', '.join(MACHINES)}, got "
                         f"`{str(machine)[:40]}`")
    assembled = bool(settings.get("assembled")) and suffix in ASSEMBLED_FORMATS
    page = _page(settings.get("page")) if suffix == ".pdf" else None
    layout = bool(settings.get("layout")) and FORMATS[suffix].cut
    sheet = settings.get("sheet") or [600, 400]
    if layout:
        if not (isinstance(sheet, (list, tuple)) and len(sheet) == 2):
            raise ValueError("sheet expects [width, height] in mm")
        sheet = tuple(_number({"sheet": v}, "sheet", 10.0, MAX_SHEET) for v in sheet)
    name = settings.get("name")
    if name is not None and not isinstance(name, str):
        raise ValueError("name expects a text (the file's name)")
    options = {"thickness": thickness, "machine": machine, "assembled": assembled, "page": page}
    style = settings.get("style") or "laser"
    if style not in SVG_STYLES:
        raise ValueError(f"style expects laser (the cutting file) or preview (the picture), "
                         f"got `{str(style)[:40]}`")
    if suffix == ".svg" and not assembled:
        # the cutting file by default (`aidl render --svg-style laser`): red cut and blue
        # engrave hairlines, one element per loop, no sheet outline; the page's picture
        # (filled parts) only when asked
        options["style"] = style
    return {"kerf": kerf, "layout": layout, "sheet": sheet, "options": options}


def nothing_to_make(res) -> dict:
    """The answer to a download whose design holds nothing with these values (a hole that
    removes all of its solid): an error naming why, never an empty file (issue 94: a DXF of 0
    entities, an empty ZIP, both behind HTTP 200)."""
    from ..serve.wording import for_forms
    for d in res.diagnostics:
        d.reword(for_forms)
    said = [{k: d[k] for k in ("code", "severity", "message", "rendered")}
            for d in res.diagnostics_json() if d["severity"] in ("error", "warning")]
    said.sort(key=lambda d: d["code"] != "W0503")      # "removes all of solid" first
    why = f": {said[0]['message']}" if said else ""
    return {"error": f"nothing to make with these values{why}", "diagnostics": said[:8]}


def file_base(text) -> str:
    """A download's name as the page asks for it (the design and its changed values:
    ``divider_tray-rows_5-cols_2``): letters, digits, ``.``, ``_``, ``-``, at most 96; "" for
    none."""
    base = re.sub(r"[^\w.-]+", "_", str(text or ""))[:96].strip("._-")
    return base


def closed_stl(output, thickness=None) -> bytes:
    """The assembled product as one closed STL: every placed part's body joined by Manifold's
    union (the bodies of a finger box meet face to face at every finger: written side by
    side, their shared faces made 852 edges of more than two faces once read back)."""
    import manifold3d as mf
    import numpy as np

    from ..output.writers.mesh import _trimesh, bodies
    trimesh = _trimesh()
    solids = [mf.Manifold(mf.Mesh(vert_properties=np.asarray(m.vertices, dtype=np.float32),
                                  tri_verts=np.asarray(m.faces, dtype=np.uint32)))
              for _, m in bodies(output, thickness, assembled=True)]
    if not solids or any(m.status() != mf.Error.NoError for m in solids):
        from ..output.writers.mesh import to_stl    # (a bent body Manifold does not take)
        return to_stl(output, thickness, assembled=True)
    mesh = mf.Manifold.batch_boolean(solids, mf.OpType.Add).to_mesh64()
    return trimesh.Trimesh(np.asarray(mesh.vert_properties)[:, :3],
                           np.asarray(mesh.tri_verts), process=False).export(file_type="stl")


def _errors(res) -> list[dict]:
    """The errors of the compile ``res`` (an :class:`~aidl_lang.api.Result`) as the page shows
    them: code, severity, message, rendered text, a param value named as the form's field
    (:func:`~aidl_lang.serve.wording.for_forms`), not as the command line's ``--set``."""
    from ..serve.wording import for_forms
    for d in res.diagnostics:
        d.reword(for_forms)
    return [{k: d[k] for k in ("code", "severity", "message", "rendered")}
            for d in res.diagnostics_json() if d["severity"] == "error"]


def _page(v) -> str | None:
    """The PDF paper of a download's settings (``A4``, ``letter-landscape``: any case), or None;
    raises :class:`ValueError` naming the choices."""
    if v is None or v == "":
        return None
    text = str(v)[:40]
    base = text.lower().removesuffix("-landscape")
    if base not in (p.lower() for p in PAGES):
        raise ValueError(f"page expects one of {', '.join(PAGES)} (or -landscape), got `{text}`")
    return text


def at_origin(output, by=(0.0, 0.0)):
    """``output`` moved so that its lower-left corner (the exact bounding box of every cut
    and stroke) is at ``by`` (mm; default (0, 0))."""
    from ..output import Output
    from ..output.fabrication.layout import Motion
    boxes = [s.box() for p in output.parts for lp in p.loops for s in lp.segments]
    boxes += [s.box() for st in output.engrave for s in st.segments]
    if not boxes:
        return output
    x0, y0 = min(b[0] for b in boxes), min(b[1] for b in boxes)
    m = Motion(0.0, (x0, y0), by)
    return Output([m.part(p) for p in output.parts], [m.stroke(st) for st in output.engrave],
                  output.title, None, None)


_XY = re.compile(r"(?<![A-Z])([XY])(-?\d+(?:\.\d*)?)")


def gcode_at_origin(output, kerf, suffix: str, options: dict) -> bytes:
    """The G-code of ``output`` (offset by the ``kerf``, :func:`~..output.for_cutting`) with
    the job's lower-left corner on the machine's origin, the sheet's corner: the drawing's
    box at (0, 0), then moved again by what the tool path reaches past it (a router's tool
    radius, a lead-in), so that no X or Y of the job is negative."""
    from ..output import Options, encode, for_cutting
    cut = for_cutting(output, kerf)
    data = encode(at_origin(cut), suffix, Options(**options))
    lows = {"X": 0.0, "Y": 0.0}
    for line in data.decode("ascii", "replace").splitlines():
        code = line.split(";", 1)[0].split("(", 1)[0].upper()
        if not code.startswith(("G0", "G1", "G2", "G3")):
            continue
        for axis, v in _XY.findall(code):
            lows[axis] = min(lows[axis], float(v))
    if lows["X"] < 0 or lows["Y"] < 0:
        data = encode(at_origin(cut, (-lows["X"], -lows["Y"])), suffix, Options(**options))
    return data


def thumbnail(entry_id: str) -> str:
    """The gallery entry's default picture (SVG text; ``""`` when it does not render).  An
    empty ``entry_id`` (the health probe's warm-up) answers at once, without building the
    gallery (1.7 s of CPU)."""
    if not entry_id:
        return ""
    from . import gallery
    e = gallery.entry(entry_id)
    if e is None:
        return ""
    try:
        return gallery.thumbnail(e)
    except Exception:               # noqa: BLE001 - a missing picture, not a broken gallery
        return ""
