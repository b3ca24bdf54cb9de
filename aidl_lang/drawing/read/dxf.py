"""The DXF reader (ezdxf): the bytes of a DXF (ASCII or binary) in, a :class:`~.model.Drawing`
out (:func:`_read_dxf`).  One reader per entity kind behind a table (:data:`_ENTITY_READERS`):
``LINE``, ``ARC``, ``CIRCLE``, ``LWPOLYLINE``/``POLYLINE`` (bulges are arcs), ``SPLINE``
(non-rational, degree 1 to 3: its Bézier pieces, raised to cubics), ``ELLIPSE`` (whole, or an
exact ``EllipticArc``), ``HATCH`` boundary paths (closed loops), ``TEXT``/``MTEXT``; an
``INSERT``/``MINSERT`` places its block, every copy, under the entity budget (``E0304``) and
its full matrix, nested INSERTs composed, curves exact (:mod:`.affine`).  An
entity not in the XY plane, one whose numbers give no shape and a kind with no exact form here
are skipped and counted in ``W0130`` notes by kind, reason and layer (:func:`_dxf_finish`).
Units: ``$INSUNITS`` (:data:`INSUNITS_MM`, exact factors; 0 is read as millimetres with a
note), or ``units=``."""
from __future__ import annotations

import io
import math
from contextlib import contextmanager
from contextvars import ContextVar

from ...geometry.shapes.curves import Circle
from ...base.limits import MAX_EXTENT
from .affine import arc_curve, dxf_conic, flattens, whole_curve
from ..chains.chain import _chain, _finish
from .dxf_entities import (FLAT_TOL, _entity_arc, _entity_circle, _entity_ellipse, _entity_line, _entity_lwpolyline, _entity_polyline, _entity_spline, _entity_text, _ocs_flipped, _poly_segments)
from ..model import (_OPTS, JOIN_TOL, UNIT_MM, Drawing, DrawingError, Note,
                     _check_made, _mm, _OutOfRange, _plural, _range_error, _Skip)


# DXF $INSUNITS: (name, millimetres) exactly (ezdxf's factors are off by 1e-11 for inches)
INSUNITS_MM = {1: ("in", 25.4), 2: ("ft", 304.8), 3: ("mi", 1609344.0), 4: ("mm", 1.0),
               5: ("cm", 10.0), 6: ("m", 1000.0), 7: ("km", 1e6), 8: ("microinch", 25.4e-6),
               9: ("mil", 0.0254), 10: ("yd", 914.4), 11: ("angstrom", 1e-7), 12: ("nm", 1e-6),
               13: ("um", 1e-3), 14: ("dm", 100.0)}


def _dxf_line(data: bytes, handle: str | None) -> int | None:
    """The 1-based line of the ASCII DXF ``data`` where the entity of ``handle`` starts (its
    type name; the handle's own line when the type is not just before it), or None."""
    import re
    if not handle or data.startswith(b"AutoCAD Binary DXF"):
        return None
    m = re.search(rb"(?m)^[ \t]*5[ \t]*\r?\n[ \t]*" + re.escape(handle.encode("ascii", "replace"))
                  + rb"[ \t]*\r?$", data)
    if m is None:
        return None
    line = data.count(b"\n", 0, m.start()) + 1
    before = data[:m.start()].splitlines()[-2:]
    return line - 1 if len(before) == 2 and before[0].strip() == b"0" else line


_SKIP_QUIET = {"POINT", "VIEWPORT", "ATTDEF", "ATTRIB", "SEQEND", "VERTEX"}


NAMED = 3                # entities named in a note of a defect (a malformed SPLINE)
MAX_BLOCK_DEPTH = 16     # blocks inside blocks (INSERT in a block definition), as templates
GARBAGE = 1e15           # mm: a number past this (or inf, nan) is noise: the entity is skipped


class _EzdxfLog:
    """ezdxf's own log lines (``Found non-unique entity handle #C, ...``) while a drawing is
    read: kept in ``lines`` for a ``W0130`` note instead of reaching the terminal."""

    def __init__(self) -> None:
        self.lines: list[str] = []

    def __enter__(self):
        import logging

        class H(logging.Handler):
            def emit(h, record) -> None:
                try:
                    msg = record.getMessage()
                except Exception:
                    msg = str(record.msg)
                if len(self.lines) < 1000:
                    self.lines.append(msg)
        self.log = logging.getLogger("ezdxf")
        self.handler = H(logging.WARNING)         # its INFO lines were never shown
        self.saved = self.log.propagate
        self.log.addHandler(self.handler)
        self.log.propagate = False
        return self

    def __exit__(self, *exc) -> None:
        self.log.removeHandler(self.handler)
        self.log.propagate = self.saved


# within :func:`one_parse`: id(data) -> (data, its document, ezdxf's log lines of the parse)
_PARSED: ContextVar[dict | None] = ContextVar("aidl_dxf_parsed", default=None)


@contextmanager
def one_parse():
    """Within it, the DXF of one ``data`` (the same bytes object) is parsed once: ``aidl
    import`` reads a file for its layer names, then each layer, and each role (cut, engrave)
    of it, and ezdxf's parse is most of the import's time (a 20,000-hole panel: 3.5 s a
    parse, three of them).  The document is only read, never changed; ezdxf's log lines of
    the parse are said again on each later read (for the ``W0130`` note of the read that
    keeps them).  Inside another, the outer one's."""
    if _PARSED.get() is not None:
        yield
        return
    token = _PARSED.set({})
    try:
        yield
    finally:
        _PARSED.reset(token)


def _open_dxf(data: bytes, name: str):
    """The ezdxf document of the DXF ``data`` (ASCII or binary, read from these bytes: the
    file is opened once; within :func:`one_parse` also parsed once): ezdxf's normal loader,
    its recover mode when that fails.  Raises :class:`DrawingError` ``E0130``."""
    parsed = _PARSED.get()
    if parsed is None:
        return _parse_dxf(data, name)
    hit = parsed.get(id(data))
    if hit is not None and hit[0] is data:
        import logging
        log = logging.getLogger("ezdxf")
        for line in hit[2]:
            log.warning("%s", line)
        return hit[1]
    with _EzdxfLog() as log:            # beside the caller's: the lines to say again
        doc = _parse_dxf(data, name)
    parsed[id(data)] = (data, doc, log.lines)
    return doc


def _parse_dxf(data: bytes, name: str):
    """:func:`_open_dxf` without the sharing."""
    doc = _fast_dxf(data)
    if doc is not None:
        return doc
    try:
        if data.startswith(b"AutoCAD Binary DXF"):
            from ezdxf.document import Drawing as _Doc
            from ezdxf.lldxf.tagger import binary_tags_loader
            return _Doc.load(binary_tags_loader(data, errors="surrogateescape"))
        from ezdxf import recover
        return recover.read(io.BytesIO(data))[0]      # damaged: recover mode (slower)
    except Exception as ex:          # ezdxf raises DXFStructureError and others on garbage
        raise DrawingError("E0130", f"`{name}` is not a readable DXF file ({type(ex).__name__})",
                           "export it again as DXF R12 or later (ASCII or binary)") from None


def _layers_text(by_layer: dict) -> str:
    """``layer `0``` or ``layers `A` (20), `B` (10)``."""
    items = sorted(by_layer.items(), key=lambda kv: (-kv[1], kv[0]))
    if len(items) == 1:
        return f"layer `{items[0][0]}`"
    shown = ", ".join(f"`{ly}` ({n})" for ly, n in items[:6])
    return f"layers {shown}" + (f" and {len(items) - 6} more" if len(items) > 6 else "")


_REASON_HINT = {
    "plane": "turn the drawing into the XY plane (the world UCS) in the drawing program, "
             "or select other layers",
    "number": "fix the entity in the drawing program (it has no size or a broken number)",
    "width": "widths are not cut: draw a wide line as an outline if it is one",
    "text": "write the text with Text(...) in a `drawing`",
    "z": "the drawing is read in the XY plane: z only places it in 3D",
    "exact": "convert it to lines, arcs or splines in the drawing program, or select other "
             "layers",
    "spline": "draw the spline again in the drawing program (its definition gives no curve)",
    "hatch": "",
    "height": "give the text a height above 0 in the drawing program (or its text style a "
              "fixed height)",
    "singular": "give the INSERT a scale other than 0 in the drawing program, or delete it",
}


def _read_dxf(data: bytes, name: str, layer, color, unit: str | None) -> Drawing:
    """The :class:`~.model.Drawing` of the DXF ``data`` (``layer``, ``color``: the selection;
    ``unit``: overrides ``$INSUNITS``), ezdxf's log lines kept for a note.  Raises
    :class:`DrawingError`."""
    with _EzdxfLog() as log:
        d = _read_dxf_doc(data, name, layer, color, unit, log)
    return d


def _read_dxf_doc(data: bytes, name: str, layer, color, unit: str | None, log) -> Drawing:
    """The drawing of the DXF ``data``: its unit (:func:`_dxf_unit`), the selected layers
    checked (:func:`_check_layers`), the model space read entity by entity (:func:`_walk`)
    and the notes of what was left out (:func:`_dxf_finish`; ``log``: the
    :class:`_EzdxfLog` of ezdxf's own lines)."""
    doc = _open_dxf(data, name)
    notes: list[Note] = []
    unit, scale = _dxf_unit(doc, name, unit, notes, _has_header(data))
    layers = None if layer is None else {s.lower() for s in
                                         ([layer] if isinstance(layer, str) else layer)}
    colors = None if color is None else set([color] if isinstance(color, (int, float))
                                             else color)
    msp = doc.modelspace()
    if layers is not None:
        _check_layers(doc, msp, name, layer, layers)
    ctx = _DxfReading(doc, data, name, scale, layers, colors)
    _walk(ctx, list(msp), 0)
    if ctx.style_height:
        n = sum(ctx.style_height.values())
        its = "its" if n == 1 else "their"
        notes.append(Note("W0130", f"{n} text{'s' if n != 1 else ''} of `{name}` with no "
                                   f"height of {its} own (" + ", ".join(
                                       f"{w}: {k}" for w, k in sorted(ctx.style_height.items()))
                                   + f"): written at {its} text style's fixed height",
                          "give the text its own height in the drawing program"))
    return _dxf_finish(ctx.pieces, ctx.loops, ctx.circles, ctx.ellipses, ctx.hatch_circles,
                       ctx.texts, notes, ctx.skipped, ctx.seen, ctx.widths, ctx.zs, log, unit,
                       name, ctx.named)


def _dxf_unit(doc, name: str, unit: str | None, notes: list,
              header: bool = True) -> tuple[str, float]:
    """The drawing's unit and its millimetres: ``unit`` when given (``units=``), else the
    header's ``$INSUNITS`` (:data:`INSUNITS_MM`).  A file that gives no unit is read as
    millimetres with a note in ``notes``: ``$INSUNITS`` 0 (unitless) or absent, or no HEADER
    section at all (``header`` False, :func:`_has_header`: ezdxf then makes a default header
    of its own, whose ``$INSUNITS`` 6, metres, the file never said).  Raises
    :class:`DrawingError` ``E0130`` for an unknown ``$INSUNITS``."""
    if unit is not None:
        return unit, UNIT_MM[unit]
    code = int(doc.header.get("$INSUNITS", 0) or 0) if header else 0
    if code == 0:
        why = "no HEADER section" if not header else (
            "$INSUNITS = 0" if "$INSUNITS" in doc.header else "no $INSUNITS in its header")
        notes.append(Note("W0130", f"`{name}` gives no unit ({why}): read as "
                                   f"millimetres", 'give units="in" (or another unit) '
                                                   "to read it in another unit"))
        return "mm", 1.0
    if code not in INSUNITS_MM:
        raise DrawingError("E0130", f"`{name}` has an unknown unit ($INSUNITS = {code})",
                           'give units="mm" (or another unit)')
    return INSUNITS_MM[code]


def _has_header(data: bytes) -> bool:
    """Whether the DXF ``data`` (ASCII or binary) has a HEADER section: a ``2`` tag whose
    value is ``HEADER`` (group code 2, then the name; binary: the code as one or two bytes,
    the name ended by a zero byte).  ezdxf fills a file without one with its own defaults,
    so its header cannot tell."""
    import re
    if data.startswith(b"AutoCAD Binary DXF"):
        return re.search(rb"\x02(?:\x00)?HEADER\x00", data) is not None
    return re.search(rb"(?m)^[ \t]*2[ \t]*\r?\n[ \t]*HEADER[ \t]*\r?$", data) is not None


def _check_layers(doc, msp, name: str, layer, layers: set) -> None:
    """Raises :class:`DrawingError` ``E0132`` (the names like it, or the drawing's layers)
    when a layer of the selection ``layer`` is not in the layer table of ``doc`` and no
    entity of the model space ``msp`` lies on a selected layer (``layers``: lower case)."""
    known = {ly.dxf.name.lower() for ly in doc.layers}
    missing = [ly for ly in ([layer] if isinstance(layer, str) else layer)
               if ly.lower() not in known]
    if missing and not any(entity_layer(e).lower() in layers for e in msp):
        from ...base.diagnostics import did_you_mean
        sugg = did_you_mean(missing[0], [ly.dxf.name for ly in doc.layers])
        raise DrawingError("E0132", f"`{name}` has no layer `{missing[0]}`",
                           ("did you mean " + ", ".join(f"`{s}`" for s in sugg) + "?")
                           if sugg else "layers: " + ", ".join(
                               sorted(ly.dxf.name for ly in doc.layers))[:300])


def entity_layer(e) -> str:
    """The layer of DXF entity ``e`` (``"0"`` when it names none).  An entity of a type
    ezdxf does not know (a DXFTagStorage: its own attributes raise DXFAttributeError) keeps
    its group codes as raw tags: its layer is its group 8 there."""
    if e.dxf.is_supported("layer"):
        return e.dxf.get("layer", "0")
    for tags in getattr(getattr(e, "xtags", None), "subclasses", ()):
        for tag in tags:
            if tag.code == 8:
                return str(tag.value)
    return "0"


def _unknown_type(e) -> bool:
    """Whether ``e`` is of an entity type ezdxf does not know (it has no layer attribute)."""
    return not e.dxf.is_supported("layer")


class _DxfReading:
    """One DXF being read, handed to every entity reader: the ezdxf document ``doc``, its
    bytes ``data`` (for an entity's line) and ``name``; ``scale``, mm per drawing unit; the
    selection, ``layers`` (lower case) and ``colors`` (ACI numbers), None for all.  The lists
    the readers append to: ``pieces`` (open chains of segments), ``loops`` (``(segments,
    source)``), ``circles``, ``ellipses`` (``(cx, cy, rx, ry, rotation)``), ``texts``
    (:func:`_dxf_text`'s tuples) and ``hatch_circles``.  What the notes count: ``skipped``
    (``(kind, reason, class) -> {layer: count}``), ``seen`` and ``widths`` (``(type, layer)
    -> count``), ``zs`` (type -> the z of each entity read off z = 0).  ``count``: the
    entities walked (copies placed by INSERTs included); ``layer``: the layer of the entity
    being read; ``sizes``: each block's expanded size (:func:`_block_size`)."""

    def __init__(self, doc, data: bytes, name: str, scale: float, layers, colors) -> None:
        self.doc, self.data, self.name, self.scale = doc, data, name, scale
        self.layers, self.colors = layers, colors
        self.pieces: list = []
        self.loops: list = []
        self.circles: list = []
        self.ellipses: list = []
        self.texts: list = []
        self.hatch_circles: list = []
        self.skipped: dict = {}
        self.named: dict = {}      # (kind, reason, class) -> where the first few are
        self.seen: dict = {}
        self.widths: dict = {}
        self.zs: dict = {}
        self.sizes: dict = {}
        self.style_height: dict = {}     # texts of no height of their own: why -> count
        self.count = 0
        self.layer = "0"
        self.m = None              # the block's Matrix44 of the entity being read, or None

    def skip(self, kind: str, reason: str, cls: str, e=None) -> None:
        """Count an entity of ``kind`` left out for ``reason`` (of class ``cls``) on the
        current layer; ``e``, the entity to name in the note (its handle and line: the first
        :data:`NAMED` of each reason)."""
        by = self.skipped.setdefault((kind, reason, cls), {})
        by[self.layer] = by.get(self.layer, 0) + 1
        if e is not None:
            got = self.named.setdefault((kind, reason, cls), [])
            if len(got) < NAMED:
                w, _line = self.where(e)
                if w:
                    got.append(w)

    def P(self, v) -> tuple[float, float]:
        """The point ``v`` (drawing units) in mm, its numbers checked (:func:`_mm`)."""
        return (_mm(float(v[0]) * self.scale), _mm(float(v[1]) * self.scale))

    def aci(self, e, inherited) -> int:
        """The ACI colour of ``e``: its own, its layer's (BYLAYER), or ``inherited``, the
        colour of the INSERT that placed it (BYBLOCK)."""
        c = e.dxf.get("color", 256) if e.dxf.is_supported("color") else 256
        if c == 0 and inherited is not None:          # BYBLOCK: the insert's colour
            return inherited
        if c == 256:
            try:
                c = self.doc.layers.get(e.dxf.layer).dxf.color
            except Exception:
                c = 7
        return abs(int(c))

    def where(self, e) -> tuple[str, int | None]:
        """``handle 2F, line 30`` of entity ``e`` (what is known of them) and its line."""
        handle = e.dxf.get("handle", None)
        line = _dxf_line(self.data, handle)
        return ", ".join(x for x in (f"handle {handle}" if handle else "",
                                     f"line {line}" if line else "") if x), line

    def at_z(self, t: str, z: float, flip: bool = False) -> None:
        """Note the elevation ``z`` (drawing units; ``flip``: of an OCS upside down) of an
        entity of type ``t`` when it is off z = 0; a z that is no number raises
        :class:`_OutOfRange`."""
        z = float(z) * self.scale * (-1.0 if flip else 1.0)
        if not math.isfinite(z) or abs(z) > GARBAGE:
            raise _OutOfRange("a z coordinate", z)
        if abs(z) > FLAT_TOL:
            self.zs.setdefault(t, []).append(z)

    def flat(self, t: str, vs) -> None:
        """WCS points ``vs`` must share one z (a plane parallel to XY)."""
        z = [float(v[2]) * self.scale for v in vs]
        if not z:
            return
        for v in z:
            if not math.isfinite(v) or abs(v) > GARBAGE:
                raise _OutOfRange("a z coordinate", v)
        if max(z) - min(z) > FLAT_TOL:
            raise _Skip("not in the drawing plane: its points lie at different z",
                        cls="plane")
        self.at_z(t, z[0] / self.scale)

    def add_poly(self, t: str, vs, closed: bool, flip: bool) -> None:
        """The polyline of type ``t`` through ``vs`` (``((x, y) mm, bulge)``; ``flip``: of an
        OCS upside down, mirrored in x) as a loop when it is closed or comes back to its
        start, else as an open piece."""
        if flip:
            vs = [((-p[0], p[1]), -b) for p, b in vs]
        segs = _poly_segments(vs, closed)
        if segs is None:
            raise _Skip("zero length (all its vertices at one point)", cls="number")
        if closed or math.dist(segs[0].start, segs[-1].end) <= JOIN_TOL:
            self.loops.append((segs, t))
        else:
            self.pieces.append(segs)

    def mark(self) -> tuple:
        """The lengths of the lists, to take back what one entity made."""
        return (len(self.pieces), len(self.loops), len(self.circles), len(self.ellipses),
                len(self.texts), len(self.hatch_circles))

    def made_since(self, made: tuple) -> list:
        """What was made since :meth:`mark` gave ``made`` (for :func:`_check_made`)."""
        return (self.pieces[made[0]:] + [seg for seg, _ in self.loops[made[1]:]]
                + self.circles[made[2]:] + self.ellipses[made[3]:] + self.texts[made[4]:]
                + self.hatch_circles[made[5]:])

    def drop_since(self, made: tuple) -> None:
        """Take back what was made since :meth:`mark` gave ``made``."""
        del self.pieces[made[0]:], self.loops[made[1]:], self.circles[made[2]:]
        del self.ellipses[made[3]:], self.texts[made[4]:], self.hatch_circles[made[5]:]


# ------------------------------------------------------------------ walking the entities
def _walk(ctx: _DxfReading, entities, depth: int, top=None, inh_layer=None,
          inh_color=None, m=None) -> None:
    """Read ``entities`` (the model space's, or a block's an INSERT places: ``top`` the INSERT
    of the model space, ``depth`` how deep in blocks, ``inh_layer`` and ``inh_color`` what an
    entity on layer 0 or of colour BYBLOCK takes, ``m`` the ezdxf ``Matrix44`` from the
    block's coordinates to the world's, every INSERT's on the way composed) into ``ctx``:
    each counted against
    :data:`MAX_ENTITIES` (``E0130``), an INSERT expanded (:func:`_expand_insert`), the
    selection and the roles applied, the rest read by its reader (:func:`_read_checked`).
    The limit is the reading's ``max_shapes`` (:data:`MAX_ENTITIES`, or ``aidl import``'s
    scaled by its ``--budget``, as the SVG reader's)."""
    limit = _OPTS.get().max_shapes
    for e in entities:
        ctx.count += 1
        if ctx.count > limit:
            raise DrawingError("E0130", f"`{ctx.name}` has more than {limit} entities",
                               "select fewer with layer= or split the drawing")
        t = e.dxftype()
        ly = entity_layer(e)
        if ly == "0" and inh_layer is not None:         # layer 0 in a block: the insert's
            ly = inh_layer
        if t == "INSERT":
            _expand_insert(ctx, e, depth, top or e, ly, ctx.aci(e, inh_color), m)
            continue
        if ctx.layers is not None and ly.lower() not in ctx.layers:
            continue
        if ctx.colors is not None and ctx.aci(e, inh_color) not in ctx.colors:
            continue
        if t in _SKIP_QUIET:
            continue
        ctx.layer = ly
        ctx.seen[(t, ly)] = ctx.seen.get((t, ly), 0) + 1
        if _OPTS.get().keep is not None and not _OPTS.get().keep(
                [ly], _dxf_rgb(e, ctx.aci(e, inh_color)), ctx.aci(e, inh_color)):
            continue            # roles (cut=, engrave=, ignore=): another role's entity
                                # (in a block: the insert's layer and colour, as above)
        ctx.m = m
        _read_checked(ctx, e, t, top)


def _read_checked(ctx: _DxfReading, e, t: str, top) -> None:
    """Read entity ``e`` of type ``t`` (``top``: the INSERT that placed it, or None) by its
    reader (:func:`_read_entity`) and check the numbers of what it made (:func:`_check_made`).
    An entity its reader leaves out (:class:`_Skip`) is counted; one with a number that is
    not finite or past :data:`GARBAGE` is taken back and counted; one with a number beyond
    the model extent is ``E0130`` naming it (:func:`_range_error`)."""
    if t == "CIRCLE" and ctx.m is None and _plain_circle(e, ctx):
        return
    made = ctx.mark()
    try:
        _read_entity(e, t, ctx)
        _check_made(ctx.made_since(made))
    except _Skip as s:
        ctx.skip(s.kind or t, s.what, s.cls, (top or e) if s.named else None)
    except _OutOfRange as ex:
        ctx.drop_since(made)
        v = ex.value
        if not math.isfinite(v) or abs(v) > GARBAGE:
            ctx.skip(t, f"{ex.what} that is " + ("not a number" if v != v else "infinite"
                                                  if math.isinf(v) else
                                                  f"beyond {GARBAGE:g} mm"), "number")
            return
        w, line = ctx.where(top or e)
        label = t + (f" (in the block of INSERT {w})" if top is not None and w
                     else f" ({w})" if w else "")
        raise _range_error(ex, label, ctx.name, line) from None


def _plain_circle(e, ctx: _DxfReading) -> bool:
    """Read the CIRCLE ``e`` when it is the plain case, and say so: extrusion +Z (or none),
    at z = 0 (within :data:`FLAT_TOL`), its centre and radius (mm) within the extent and
    the radius above 0; the same :class:`Circle` :func:`_entity_circle` makes, without its
    per-entity bookkeeping (a perforated panel is tens of thousands of these).  Anything
    else is False: the general reader reads it, and says what is wrong with it."""
    try:
        dxf = e.dxf
        if dxf.hasattr("extrusion"):
            ext = dxf.extrusion
            if not (ext[0] == 0 and ext[1] == 0 and 0 < ext[2] < math.inf):
                return False
        c, k = dxf.center, ctx.scale
        x, y, z, r = float(c[0]) * k, float(c[1]) * k, float(c[2]) * k, float(dxf.radius) * k
    except Exception:
        return False
    if abs(x) <= MAX_EXTENT and abs(y) <= MAX_EXTENT and abs(z) <= FLAT_TOL \
            and 0 < r <= MAX_EXTENT:
        ctx.circles.append(Circle((x, y), r))
        WORK["plain_circles"] += 1
        return True
    return False


WORK = {"plain_circles": 0}
"""Counts of what the reader did, summed over calls (the tests hold the reading linear):
``plain_circles``, CIRCLEs read by :func:`_plain_circle`."""


def _read_entity(e, t: str, ctx: _DxfReading) -> None:
    """Read entity ``e`` of type ``t`` into ``ctx`` by its reader in
    :data:`_ENTITY_READERS`; a type not there has no exact form here (:class:`_Skip`)."""
    reader = _ENTITY_READERS.get(t)
    if reader is None:
        raise _Skip("an entity type the DXF reader does not know" if _unknown_type(e) else
                    "no exact form here", cls="exact")
    if ctx.m is None:
        reader(e, ctx)
    else:
        _read_placed(e, t, reader, ctx)


def _read_placed(e, t: str, reader, ctx: _DxfReading) -> None:
    """Read entity ``e`` of a block under the block's matrix ``ctx.m``, exactly: a CIRCLE,
    ARC or ELLIPSE as the ellipse (a circle under a similarity) its conjugate semi-diameters
    give (:func:`_placed_conic`); a polyline with bulges under a map that is no similarity
    as its lines and arcs, each so; a HATCH's boundary edges each so; anything else as
    ezdxf's transformed copy (lines, splines, polylines, text: an affine map keeps them)."""
    from ezdxf.entities.dxfentity import CopyNotSupported
    from ezdxf.math import NonUniformScalingError
    if t in ("CIRCLE", "ARC", "ELLIPSE"):
        return _placed_conic(e, t, ctx)
    if t == "HATCH":
        return reader(e, ctx)               # its edges come back here
    if t in ("LWPOLYLINE", "POLYLINE") and not _similar(ctx.m) and any(
            abs(float(b)) > 0 for b in _bulges(e, t)):
        if e.has_width:
            ctx.widths[(t, ctx.layer)] = ctx.widths.get((t, ctx.layer), 0) + 1
        for x in e.virtual_entities():      # its lines and arcs, in the block's frame
            _read_entity(x, x.dxftype(), ctx)
        return
    try:
        x = e.copy()
        x.transform(ctx.m)
    except (CopyNotSupported, NonUniformScalingError, NotImplementedError) as ex:
        raise _Skip(f"cannot be placed by its INSERT ({type(ex).__name__})") from None
    m, ctx.m = ctx.m, None
    try:
        reader(x, ctx)
    finally:
        ctx.m = m


def _bulges(e, t: str) -> list:
    """The bulges of LWPOLYLINE or POLYLINE ``e``."""
    if t == "LWPOLYLINE":
        return [b for _x, _y, b in e.get_points("xyb")]
    return [v.dxf.get("bulge", 0.0) for v in e.vertices]


def _similar(m) -> bool:
    """Whether the ezdxf ``Matrix44`` ``m`` maps the XY plane by a similarity (turns,
    mirrors and one scale: a circle stays a circle)."""
    from ezdxf.math import X_AXIS, Y_AXIS
    ux, uy = m.transform_direction(X_AXIS), m.transform_direction(Y_AXIS)
    a, b = ux.magnitude, uy.magnitude
    return abs(a - b) <= 1e-12 * max(a, b) and abs(ux.dot(uy)) <= 1e-12 * a * b


def _placed_conic(e, t: str, ctx: _DxfReading) -> None:
    """CIRCLE, ARC or ELLIPSE ``e`` of a block under ``ctx.m``: its centre and conjugate
    semi-diameters (:func:`~.affine.dxf_conic`) mapped by the matrix, then the exact curve
    (:func:`~.affine.whole_curve`, :func:`~.affine.arc_curve`: a Circle or Arc when the map
    is a similarity, else an ellipse or EllipticArc); out of the XY plane it is skipped."""
    try:
        c, u, v, t0, sweep = dxf_conic(e, t)
    except ValueError as ex:
        raise _Skip(str(ex), cls="number") from None
    m, k = ctx.m, ctx.scale
    c = m.transform(c)
    u, v = m.transform_directions((u, v))
    if (abs(u.z) + abs(v.z)) * k > FLAT_TOL:
        raise _Skip("not in the drawing plane: its INSERT turns it out of the XY plane",
                    cls="plane")
    ctx.at_z(t, c.z)
    cm = ctx.P(c)
    um = (_mm(u.x * k, "a semi-axis"), _mm(u.y * k, "a semi-axis"))
    vm = (_mm(v.x * k, "a semi-axis"), _mm(v.y * k, "a semi-axis"))
    got = whole_curve(cm, um, vm) if sweep is None else arc_curve(cm, um, vm, t0, sweep)
    if got is None:
        raise _Skip("flattened by its INSERT to no area", cls="number")
    if sweep is not None:
        ctx.pieces.append([got])
    elif isinstance(got, Circle):
        ctx.circles.append(got)
    else:
        ctx.ellipses.append(got)


# ------------------------------------------------------------------ blocks
def _expand_insert(ctx: _DxfReading, e, depth: int, top, eff_layer: str, eff_color,
                   parent=None) -> None:
    """Read what the INSERT or MINSERT ``e`` places (every copy of an array) by
    :func:`_walk`, its size checked first (:func:`_check_insert`; ``top``: the INSERT of the
    model space it is under; ``eff_layer``, ``eff_color``: what its entities on layer 0 or
    of colour BYBLOCK take; ``parent``: the matrix of the block ``e`` is in, or None): the
    block's own entities under the copy's full matrix (``Insert.matrix44()`` times
    ``parent``: nested blocks compose their scales, turns, mirrors and extrusions, exact
    where an INSERT could not hold the product), read by :func:`_read_placed`.  A copy whose
    x or y scale is 0 (a singular map) is skipped with a note naming the INSERT; a block
    ezdxf cannot place is skipped and counted."""
    rows, cols = int(e.dxf.get("row_count", 1) or 1), int(e.dxf.get("column_count", 1) or 1)
    arr = rows * cols > 1
    label_top, line = ctx.where(top)
    kind = "MINSERT" if arr else "INSERT"
    at = f" ({label_top})" if label_top else ""
    head = (f"{kind}{at}" if top is e else
            f"INSERT{at}, through its {kind} of block `{e.dxf.name}`,")
    _check_insert(ctx, e, depth, head, line, rows, cols)
    if rows * cols > 1:
        inserts = list(e.multi_insert())
        ctx.count += rows * cols - len(inserts)          # copies at one place: counted
    else:
        inserts = [e]

    for ins in inserts:
        try:
            m = ins.matrix44() if parent is None else ins.matrix44() @ parent
            blk = ins.block()
            if blk is None:
                raise LookupError
            ents = [x for x in blk if x.dxftype() != "ATTDEF"]
        except Exception as ex:
            ctx.layer = eff_layer
            ctx.skip(kind, f"its block `{e.dxf.name}` cannot be placed ({type(ex).__name__})",
                     "exact")
            continue
        if flattens(m):
            ctx.layer = eff_layer
            sx, sy = (float(e.dxf.get(a, 1.0)) for a in ("xscale", "yscale"))
            ctx.skip(kind, f"its block `{e.dxf.name}` not placed: x scale {sx:g}, y scale "
                           f"{sy:g} flatten it to no area (a singular map)", "singular", e)
            continue
        _walk(ctx, ents, depth + 1, top, eff_layer, eff_color, m)


def _check_insert(ctx: _DxfReading, e, depth: int, head: str, line, rows: int,
                  cols: int) -> None:
    """Raises :class:`DrawingError` ``E0304`` (``head``: the INSERT as the message names it,
    ``line``: its line) when the block of INSERT ``e`` (``rows`` x ``cols`` copies) inserts
    itself, nests blocks past :data:`MAX_BLOCK_DEPTH`, or places more entities, each copy
    counted (:func:`_block_size`), than the reading's limit (:data:`MAX_ENTITIES`, or
    ``aidl import``'s scaled one) leaves."""
    name = ctx.name
    arr = rows * cols > 1
    try:
        size = _block_size(ctx, e.dxf.name, ())
        n = _copies(e) * max(1, size)            # each copy counts, even an empty one
    except _Deep as ex:
        chain = " > ".join(f"`{b}`" for b in ex.chain[:MAX_BLOCK_DEPTH + 1])
        cyc = ex.chain[-1] in ex.chain[:-1]
        raise DrawingError("E0304", f"{head} of `{name}` " + (
            f"places block `{ex.chain[-1]}`, which inserts itself ({chain}): it never ends"
            if cyc else f"nests blocks more than {MAX_BLOCK_DEPTH} deep ({chain})"),
            "remove the INSERT of the block from its own definition" if cyc else
            "explode some of the blocks in the drawing program", line) from None
    if depth + 1 > MAX_BLOCK_DEPTH:
        raise DrawingError("E0304", f"{head} of `{name}` nests blocks more than "
                                    f"{MAX_BLOCK_DEPTH} deep", "explode some of the blocks "
                                                               "in the drawing program", line)
    limit = _OPTS.get().max_shapes
    if ctx.count + n > limit:
        each = f" ({_plural(size, 'entity')} each)"
        grid = f"an array of {rows} x {cols} copies of block `{e.dxf.name}`{each}" if arr \
            else f"block `{e.dxf.name}`"
        raise DrawingError("E0304", f"{head} of `{name}` is {grid}: "
                                    f"{n:,} entities in all, "
                                    f"more than the {limit:,} entities one drawing "
                                    f"may give",
                           "draw one copy and repeat it with a `for` loop in the program, "
                           "or select other layers", line)


def _block_size(ctx: _DxfReading, bname: str, stack: tuple) -> int:
    """The entities block ``bname`` expands to, its nested blocks and arrays included
    (each copy counted); a block that inserts itself or nests past MAX_BLOCK_DEPTH
    raises _Deep."""
    sizes = ctx.sizes
    if bname in sizes:
        return sizes[bname]
    if bname in stack or len(stack) >= MAX_BLOCK_DEPTH:
        raise _Deep(stack + (bname,))
    blk = ctx.doc.blocks.get(bname)
    n = 0
    if blk is not None:
        for x in blk:
            if x.dxftype() == "INSERT":
                n += _copies(x) * max(1, _block_size(ctx, x.dxf.name, stack + (bname,)))
            else:
                n += 1
    sizes[bname] = n
    return n


# ------------------------------------------------------------------ the readers' table
def _entity_hatch(e, ctx: _DxfReading) -> None:
    """HATCH: its boundary paths (polyline paths with bulges; edge paths of lines, arcs,
    ellipses and splines, each edge read by its own reader), each a closed loop: an island
    is a loop inside another, so it becomes a hole as any inner loop does; in a block
    (``ctx.m``) each edge is placed as its kind is (:func:`_read_placed`)."""
    if ctx.m is None:
        _ocs_flipped(e)
    l0 = len(ctx.loops)
    for path in _hatch_paths(e):
        n0 = len(ctx.pieces)
        for x in path:
            xt = x.dxftype()
            if xt == "ARC" and len(path) == 1 and \
                    (float(x.dxf.end_angle) - float(x.dxf.start_angle)) % 360.0 == 0.0:
                if ctx.m is not None:                   # placed: a circle or an ellipse
                    n = len(ctx.circles)
                    _placed_conic(x, "CIRCLE", ctx)
                    ctx.hatch_circles.extend(ctx.circles[n:])
                    del ctx.circles[n:]
                    continue
                flip = _ocs_flipped(x)                  # a full-circle edge: a circle
                c = ctx.P(x.dxf.center)
                r = _mm(float(x.dxf.radius) * ctx.scale, "a radius")
                if r <= 0:
                    raise _Skip("a boundary radius not above 0", cls="number")
                ctx.hatch_circles.append(Circle((-c[0], c[1]) if flip else c, r))
                continue
            try:
                _read_entity(x, xt, ctx)
            except _Skip as s:
                raise _Skip(f"a boundary {xt}: {s.what}", cls=s.cls) from None
        mine = ctx.pieces[n0:]
        del ctx.pieces[n0:]
        closed, open_ = _chain(mine)
        ctx.loops.extend((c, "HATCH") for c in closed)
        ctx.pieces.extend(open_)
    ctx.loops[l0:] = [(segs, "HATCH") for segs, _ in ctx.loops[l0:]]


_ENTITY_READERS = {
    "LINE": _entity_line,
    "CIRCLE": _entity_circle,
    "ARC": _entity_arc,
    "LWPOLYLINE": _entity_lwpolyline,
    "POLYLINE": _entity_polyline,
    "SPLINE": _entity_spline,
    "ELLIPSE": _entity_ellipse,
    "HATCH": _entity_hatch,
    "TEXT": _entity_text,
    "MTEXT": _entity_text,
}


def _hatch_paths(e) -> list:
    """The boundary paths of HATCH ``e`` as virtual entities, one list a path: a polyline
    path an LWPOLYLINE (with its bulges), an edge path its LINE, ARC, ELLIPSE and SPLINE
    edges, in the hatch's plane (ezdxf's ``virtual_boundary_path_entities``, whose polyline
    paths fail in ezdxf 1.4)."""
    from ezdxf.entities import LWPolyline
    from ezdxf.entities.boundary_paths import EdgePath, EdgeType, PolylinePath
    from ezdxf.explode import _virtual_edge_path
    attribs = {"layer": e.dxf.get("layer", "0")}
    elevation = float(e.dxf.elevation.z)
    ocs = e.ocs()
    out = []
    for path in e.paths:
        if isinstance(path, PolylinePath):
            p = LWPolyline.new(dxfattribs=dict(attribs))
            p.append_points(path.vertices, format="xyb")
            p.dxf.extrusion = ocs.uz
            p.dxf.elevation = elevation
            p.closed = path.is_closed
            out.append([p])
        elif isinstance(path, EdgePath):
            for edge in path.edges:         # ezdxf divides by an ellipse edge's axis ratio
                if edge.type == EdgeType.ELLIPSE and not 0.0 < float(edge.ratio) < math.inf:
                    raise _Skip("a boundary ELLIPSE: a semi-axis not above 0", cls="number")
            try:
                out.append(_virtual_edge_path(path, dict(attribs), ocs, elevation))
            except (ArithmeticError, ValueError) as ex:
                raise _Skip(f"a boundary path that gives no curve ({ex})", cls="number") \
                    from None
    return out


class _Deep(Exception):
    def __init__(self, chain: tuple) -> None:
        self.chain = chain


def _copies(e) -> int:
    """The copies an INSERT places: rows x columns of a MINSERT, else 1."""
    try:
        return max(1, int(e.dxf.get("row_count", 1) or 1)) * \
            max(1, int(e.dxf.get("column_count", 1) or 1))
    except (TypeError, ValueError):
        return 1


def _loop_key(segs) -> tuple:
    """A loop's segments as a set of rounded starts and kinds (the same loop whatever its
    direction and first segment)."""
    from ...geometry.shapes.curves import reverse
    a = sorted((type(s).__name__, round(s.start[0], 6), round(s.start[1], 6),
                round(s.end[0], 6), round(s.end[1], 6)) for s in segs)
    b = sorted((type(s).__name__, round(r.start[0], 6), round(r.start[1], 6),
                round(r.end[0], 6), round(r.end[1], 6)) for s in segs for r in [reverse(s)])
    return tuple(min(a, b))


def _dxf_finish(pieces, loops, circles, ellipses, hatch_circles, texts, notes, skipped, seen,
                widths, zs, log, unit, name, named=None) -> Drawing:
    """The drawing of what was read, a HATCH boundary that repeats an outline drawn by other
    entities read once, and the notes: skipped entities by kind, reason and layer (numbers
    that are no size in one note; ``named``: the entities a reason names, by handle and
    line), widths ignored, z left out, ezdxf's own log lines."""
    d = _finish(pieces, loops, circles, ellipses, notes, unit, name, hatch_circles)
    drawn = {_loop_key(o.segments) for o in d.outlines if o.source != "HATCH"}
    keep, dup = [], 0
    for o in d.outlines:
        if o.source == "HATCH":
            k = _loop_key(o.segments)
            if k in drawn:
                dup += 1
                continue
            drawn.add(k)
        keep.append(o)
    d.outlines = keep
    have = {(round(c.center[0], 6), round(c.center[1], 6), round(c.radius, 6)) for c in d.circles}
    for c in hatch_circles:
        k = (round(c.center[0], 6), round(c.center[1], 6), round(c.radius, 6))
        if k in have:
            dup += 1
            continue
        have.add(k)
        d.circles.append(Circle(c.center, c.radius))
    d.circles.sort(key=lambda c: (-c.radius, c.center[0], c.center[1]))
    d.texts = texts
    if dup:
        notes.append(Note("W0130", f"{_plural(dup, 'HATCH boundary')} of `{name}` "
                                   f"repeat{'s' if dup == 1 else ''} an outline drawn by other "
                                   "entities: read once", ""))
    bad = []
    for (kind, reason, cls), by in sorted(skipped.items()):
        n = sum(by.values())
        if cls == "number":
            bad.append((n, kind, reason, by))
            continue
        word = "entity" if n == 1 else "entities"
        reason = _with_named(reason, (named or {}).get((kind, reason, cls)), n)
        notes.append(Note("W0130", f"{n} {kind} {word} of `{name}` skipped ({_layers_text(by)})"
                                   f": {reason}", _REASON_HINT.get(cls, "")))
    if bad:
        total = sum(b[0] for b in bad)
        parts = "; ".join(f"{n} {kind} with {reason} ({_layers_text(by)})"
                          if not reason.startswith(("zero", "a boundary")) else
                          f"{n} {kind} of {reason} ({_layers_text(by)})"
                          for n, kind, reason, by in bad)
        notes.append(Note("W0130", f"{total} {'entity' if total == 1 else 'entities'} of "
                                   f"`{name}` skipped for numbers that give no shape: {parts}",
                          _REASON_HINT["number"]))
    if widths:
        n = sum(widths.values())
        by: dict = {}
        kinds = sorted({k for k, _ in widths})
        for (k, ly), m in widths.items():
            by[ly] = by.get(ly, 0) + m
        notes.append(Note("W0130", f"{n} {'/'.join(kinds)} {'entity' if n == 1 else 'entities'}"
                                   f" of `{name}` ({_layers_text(by)}) {'has' if n == 1 else 'have'} widths: read as "
                                   "their centre lines, the widths ignored",
                          _REASON_HINT["width"]))
    if zs:
        allz = [z for v in zs.values() for z in v]
        rng = f"z = {allz[0]:g}" if max(allz) - min(allz) <= FLAT_TOL else \
            f"z from {min(allz):g} to {max(allz):g}"
        kinds = ", ".join(f"{len(v)} {k}" for k, v in sorted(zs.items()))
        notes.append(Note("W0130", f"{len(allz)} {'entity' if len(allz) == 1 else 'entities'}"
                                   f" of `{name}` ({kinds}) {'lies' if len(allz) == 1 else 'lie'} off the XY plane ({rng} mm): "
                                   "read in the XY plane", _REASON_HINT["z"]))
    if log.lines:
        first = log.lines[0].strip()
        more = f" (and {len(log.lines) - 1} more)" if len(log.lines) > 1 else ""
        notes.append(Note("W0130", f"ezdxf, reading `{name}`, said: \"{first}\"{more}",
                          "the file was read as ezdxf repaired it: check the import, or save "
                          "the drawing again from its program"))
    # what was seen and why each kind was left out: the message of an empty import
    kinds: dict = {}
    for (t, ly), n in seen.items():
        kinds.setdefault(t, {})[ly] = n
    held = ", ".join(f"{sum(by.values())} {t} ({_layers_text(by)})"
                     for t, by in sorted(kinds.items()))
    why = "; ".join(f"{sum(by.values())} {kind}: "
                    f"{_with_named(reason, (named or {}).get((kind, reason, c)), 0)}"
                    for (kind, reason, c), by in sorted(skipped.items()))
    d.seen = (f"it holds {held}" if held else "it holds no drawable entities") + \
        (f", left out: {why}" if why else "")
    return d


def _with_named(reason: str, which, n: int) -> str:
    """``reason`` followed by the entities it names (``which``: where the first few are;
    ``n``: how many there are, ``...`` when more than those)."""
    if not which:
        return reason
    return f"{reason} ({'; '.join(which)}{'; ...' if n > len(which) else ''})"


def _dxf_rgb(e, aci: int) -> tuple | None:
    """The RGB colour of DXF entity ``e``: its true colour (group 420), else that of its ACI
    ``aci`` (7, white on a dark screen, black on paper: black)."""
    try:
        tc = e.dxf.get("true_color", None)
        if tc is not None:
            return ((tc >> 16) & 255, (tc >> 8) & 255, tc & 255)
        if aci in (0, 7, 256):
            return (0, 0, 0)
        from ezdxf.colors import aci2rgb
        return tuple(aci2rgb(aci))
    except Exception:
        return None


# TEXT halign (0 left, 1 center, 2 right; 3-5 aligned/middle/fit: centred) and valign
# (0 baseline, 1 bottom, 2 middle, 3 top); MTEXT attachment 1-9 (top/middle/bottom x
# left/center/right): as Text's anchor and valign
def _fast_dxf(data: bytes):
    """An ASCII DXF read by ezdxf's normal loader (several times faster than its recover
    mode), or None when that fails or the file is binary."""
    import ezdxf
    if data.startswith(b"AutoCAD Binary DXF"):
        return None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        text = data.decode("cp1252", errors="replace")
    try:
        return ezdxf.read(io.StringIO(text))
    except Exception:
        return None
