"""``aidl/preview``: the picture of a document for an editor's preview pane (issue 27).

A custom language-server request (registered in :mod:`.server`).  Params::

    {"uri": "file:///.../part.aidl", "values": {"width": "40 mm", ...},   # values optional
     "assembled": true}                                                    # optional

Result (JSON)::

    {"uri", "version",          # the document version the picture is of
     "ok",                      # this version compiled without errors
     "stale",                   # svg is the last good picture of an earlier version
     "svg",                     # SVG text (mm, y up flipped as in `aidl render`), or null
     "shapes": [{"id", "kind", "name", "range"}],   # what the overlay elements stand for
     "params": [{"name", "kind", "value", "default", "unit", "min", "max", "step",
                 "declared", "range"}],
     "values": {...},           # the overrides the picture was drawn with
     "diagnostics": {"errors", "warnings", "first": {"code", "message", "range"} | null},
     "ms": compile time in milliseconds,
     "glb": base64 GLB of the assembled product (only with "assembled": true and ok)}

The SVG is ``aidl_lang.compile(...).to_svg(kerf=0)`` — what ``aidl render FILE --set ...``
writes, at the designed size (a program's ``kerf`` is left out, so the picture matches the
shapes below and the code) — plus one last group, ``<g id="aidl-shapes">``, drawn invisible (``fill`` and
``stroke`` transparent, so it can be hovered and clicked): one element per shape of the
program (a primitive's face as the booleans saw it, ``class="aidl-shape"``; an engraved or
open curve, ``class="aidl-stroke"``; a structure's whole shape, ``class="aidl-struct"``, drawn
first so shapes sit on top), each with ``id="aidl-N"`` and ``data-range="l0,c0,l1,c1"`` (the
LSP range, 0-based lines and UTF-16 columns, of the source that made it: the primitive's
call or the structure's declaration).  Shapes made by another file (an import) are not
listed.  The overlay's outlines are the booleans' polygons (within 0.005 mm of the exact
curves): they are for pointing at, never for output.

A document that does not compile answers ``ok: false`` with the last good picture of that
document (``stale: true``) and the diagnostics' summary, so the preview does not go blank while
the user types.  Param definitions (name, kind, range for a slider: ``min=``/``max=``/``step=``
from the file, else the span ``aidl serve`` chooses: :func:`aidl_lang.serve.params.declared_params`)
come from an interpretation of the document with its own values, made once per text.

With ``"assembled": true`` the result also carries ``glb``: the assembled product (every part
extruded by its thickness and placed by its ``Place``, one named node per part in the flat
view's colours; what ``aidl render --assembled -o X.glb`` writes), base64, for the preview's
3D view.
"""
from __future__ import annotations

import math
import time

from lsprotocol import types as T

from .analysis import span_range

MAX_SHAPES = 4000          # overlay elements; beyond this, the picture is sent without them


class Cache:
    """Per document: the last good result (its SVG and shapes) and the params of a text; the
    :data:`KEEP` documents previewed last (a closed document's entry ages out)."""

    KEEP = 16

    def __init__(self) -> None:
        self.good: dict[str, dict] = {}              # uri -> last ok result
        self.params: dict[str, tuple[str, list]] = {}  # uri -> (text, params)

    def touch(self, uri: str) -> None:
        """``uri`` was just previewed: move it last, forget the oldest beyond KEEP."""
        for d in (self.good, self.params):
            if uri in d:
                d[uri] = d.pop(uri)
            while len(d) > self.KEEP:
                d.pop(next(iter(d)))

    def forget(self, uri: str) -> None:
        self.good.pop(uri, None)
        self.params.pop(uri, None)


CACHE = Cache()
SERVER_GOOD = Cache()      # the server's copy of each document's last good picture: a worker
                           # that is replaced (killed for a newer edit, retired for its memory)
                           # takes its own pictures with it


def plain(obj):
    """A request's params as plain data: pygls hands unknown requests' params over as
    namedtuples (``_asdict``); lists and dicts are walked."""
    if hasattr(obj, "_asdict"):
        return {k: plain(v) for k, v in obj._asdict().items()}
    if isinstance(obj, dict):
        return {k: plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [plain(v) for v in obj]
    return obj


def keep_last_good(out: dict, uri: str, cache: Cache) -> dict:
    """Remember ``out`` (a preview result) as ``uri``'s last good picture when it has a fresh
    SVG; when it has none, give it the last good one (``stale: true``, ``drawn_version``,
    ``drawn_values``).  Returns ``out``."""
    if out.get("svg") is not None and not out.get("stale"):
        cache.good[uri] = {k: out.get(k) for k in ("svg", "shapes", "values", "version")}
    elif out.get("svg") is None and uri in cache.good:
        good = cache.good[uri]
        out.update(svg=good["svg"], shapes=good["shapes"], stale=True,
                   drawn_version=good["version"], drawn_values=good["values"])
    return out


def preview(source: str, path: str, uri: str, version: int | None = None,
            values: dict | None = None, cache: Cache = CACHE, assembled: bool = False) -> dict:
    """The ``aidl/preview`` result for ``source`` (named ``path``) with the param ``values``
    (``--set`` texts or numbers in the file's units); ``assembled``: also ``glb``, the
    assembled product (base64).  Never raises for a bad program."""
    import aidl_lang
    t0 = time.perf_counter()
    values = {str(k): str(v) for k, v in (values or {}).items() if v is not None}
    r = aidl_lang.compile(source=source, path=path, overrides=values or None)
    out = {"uri": uri, "version": version, "ok": r.ok, "stale": False, "svg": None,
           "shapes": [], "values": values,
           "diagnostics": _summary(r, source, path)}
    if r.ok and r.compiled.drawing is not None:
        try:
            svg = r.to_svg(kerf=0)        # the designed size, as the shapes below
            overlay, shapes = _overlay(r.compiled.drawing, source, path)
            out["svg"] = svg.replace("</svg>", overlay + "</svg>") if overlay else svg
            out["shapes"] = shapes
            if assembled:
                import base64
                out["glb"] = base64.b64encode(r.encode("glb", assembled=True)).decode("ascii")
        except Exception as e:   # noqa: BLE001 - an output that cannot be drawn is a message
            out["ok"] = False
            out["diagnostics"]["errors"] += 1
            out["diagnostics"]["first"] = {"code": "E0900", "range": None,
                                           "message": f"cannot draw the preview: {e}"}
    keep_last_good(out, uri, cache)
    out["params"] = params(source, path, uri, values, cache)
    cache.touch(uri)
    out["ms"] = round((time.perf_counter() - t0) * 1000, 1)
    return out


def _summary(r, source: str, path: str) -> dict:
    errors = [d for d in r.diagnostics if d.severity == "error"]
    warnings = [d for d in r.diagnostics if d.severity == "warning"]
    first = None
    for d in errors or warnings:
        rng = None
        if d.span is not None and d.span.file == path:
            rng = _range(span_range(source, d.span))
        first = {"code": d.code, "message": d.message, "range": rng}
        break
    return {"errors": len(errors), "warnings": len(warnings), "first": first}


def _range(rng: T.Range) -> list[int]:
    return [rng.start.line, rng.start.character, rng.end.line, rng.end.character]


def params(source: str, path: str, uri: str, values: dict, cache: Cache = CACHE) -> list[dict]:
    """The document's top-level params for sliders (see the module doc), with ``value`` the
    override when one is given (a number in the param's display unit when it reads as one)."""
    hit = cache.params.get(uri)
    if hit is None or hit[0] != source:
        found = _params(source, path)
        if found is None:                       # does not interpret: keep the last ones
            found = hit[1] if hit is not None else []
        cache.params[uri] = (source, found)
        hit = cache.params[uri]
    out = []
    for p in hit[1]:
        p = dict(p)
        if p["name"] in values:
            v = values[p["name"]]
            try:
                p["value"] = float(v.split()[0]) if p["kind"] in ("length", "angle", "number") \
                    else (v.lower() == "true" if p["kind"] == "bool" else v)
            except (ValueError, IndexError):
                pass
        out.append(p)
    return out


def _params(source: str, path: str) -> list[dict] | None:
    from ...serve.params import declared_params as declared
    found = declared(source, path)
    if found is None:
        return None
    out = []
    for p in found:
        j = p.to_json()
        j.pop("line", None)
        j["range"] = _range(span_range(source, p.span)) if p.span else None
        out.append(j)
    return out


# ------------------------------------------------------------------ the overlay
def _f(v: float) -> str:
    s = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _poly_d(polys, close: bool = True) -> str:
    import numpy as np
    parts = []
    for pl in polys:
        pl = np.asarray(pl, dtype=float)
        if len(pl) < 2:
            continue
        parts.append("M" + " ".join(f"{_f(x)},{_f(-y)}" for x, y in pl) + ("Z" if close else ""))
    return " ".join(parts)


def _item_d(item) -> str:
    from ...output.writers.svg import _item_points
    kind = item[0]
    return _poly_d([_item_points(item)], close=kind in ("circle", "poly"))


def _attr(s: str) -> str:
    return (s.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")
            .replace(">", "&gt;"))


def _overlay(drawing, source: str, path: str) -> tuple[str, list[dict]]:
    """The invisible ``<g id="aidl-shapes">`` group and its shapes' list (module doc)."""
    shapes: list[dict] = []
    elems: list[str] = []
    ranges: dict = {}

    def rng(span):
        if span is None or span.file != path:
            return None
        key = tuple(span)
        if key not in ranges:
            ranges[key] = _range(span_range(source, span))
        return ranges[key]

    def add(cls: str, kind: str, name: str, span, d: str) -> None:
        r = rng(span)
        if r is None or not d or len(shapes) >= MAX_SHAPES:
            return
        i = len(shapes)
        shapes.append({"id": f"aidl-{i}", "kind": kind, "name": name, "range": r,
                       "class": cls})
        elems.append(f'<path id="aidl-{i}" class="{cls}" data-kind="{_attr(kind)}" '
                     f'data-name="{_attr(name)}" data-range="{",".join(map(str, r))}" '
                     f'd="{d}" />')

    for s, cs in drawing.shapes.items():
        if cs is not None and not cs.is_empty():
            add("aidl-struct", s.kind, s.path, s.span, _poly_d(cs.to_polygons()))
    for s, faces in drawing.own.items():
        for g, cs in faces:
            add("aidl-shape", g.kind, g.label, g.span, _poly_d(cs.to_polygons()))
    for _style, item, g in drawing.strokes:
        if g is not None:
            add("aidl-stroke", g.kind, g.label, g.span, _item_d(item))
    if not elems:
        return "", shapes
    x0, y0, x1, y1 = drawing.bounds() if hasattr(drawing, "bounds") else (0, 0, 1, 1)
    w = max(abs(x1 - x0), abs(y1 - y0), 1e-3) if all(map(math.isfinite, (x0, y0, x1, y1))) \
        else 100.0
    group = (f'<g id="aidl-shapes" fill="transparent" stroke="transparent" '
             f'stroke-width="{_f(w / 150)}" fill-rule="evenodd" stroke-linejoin="round">'
             + "".join(elems) + "</g>")
    return group, shapes


# ------------------------------------------------------------------ the request
_lock = None
_latest: dict[str, int] = {}
_seq = 0


async def handle(ls, params, analyzer=None) -> dict:
    """The ``aidl/preview`` handler (:mod:`.server` registers it): validates the params,
    compiles in ``analyzer``'s worker process (:meth:`.worker.Analyzer.preview`; on a thread
    without one), one at a time; a request overtaken by a newer one for the same
    document while it waited answers ``{"superseded": true}`` at once)."""
    import asyncio

    from pygls.exceptions import JsonRpcInvalidParams
    global _lock, _seq
    p = plain(params)
    if not isinstance(p, dict) or not isinstance(p.get("uri"), str):
        raise JsonRpcInvalidParams("invalid params: aidl/preview needs {\"uri\": string, "
                                   "\"values\"?: {name: value}}")
    values = p.get("values") or {}
    if not isinstance(values, dict):
        raise JsonRpcInvalidParams("invalid params: `values` must be an object {name: value}")
    uri = p["uri"]
    _seq += 1
    me = _latest[uri] = _seq
    if _lock is None:
        _lock = asyncio.Lock()
    async with _lock:
        if _latest.get(uri) != me:
            return {"uri": uri, "superseded": True}
        doc = ls.workspace.get_text_document(uri)
        path = doc.path or "untitled.aidl"
        assembled = p.get("assembled") is True
        if analyzer is None:
            loop = asyncio.get_running_loop()
            return await loop.run_in_executor(None, preview, doc.source, path, uri,
                                              doc.version, values, CACHE, assembled)
        # compiled where the diagnostics are (the killable worker, within its memory limit)
        try:
            out = await analyzer.preview(doc.source, path, uri, doc.version, values,
                                         lambda: preview(doc.source, path, uri, doc.version,
                                                         values, CACHE, assembled),
                                         assembled)
        except (EOFError, RuntimeError, TimeoutError, Exception) as e:   # noqa: BLE001 - a
            # timeout (worker.AnalysisTimeout), a worker that died or ran out of memory
            out = {"uri": uri, "version": doc.version, "ok": False, "stale": False,
                   "svg": None, "shapes": [], "values": values, "params": [],
                   "diagnostics": {"errors": 1, "warnings": 0, "first": {
                       "code": "E0900", "range": None,
                       "message": f"cannot draw the preview: {e}"}}}
        # the worker keeps the last good pictures, but a replaced worker (killed for a newer
        # edit, retired for its memory) starts without them: the server keeps its own copy
        keep_last_good(out, uri, SERVER_GOOD)
        SERVER_GOOD.touch(uri)
        return out


__all__ = ["preview", "handle", "params", "plain", "keep_last_good", "Cache", "CACHE",
           "SERVER_GOOD"]
