"""Reading a DXF (``ezdxf``) or SVG (``svgelements``) drawing as exact curves.

:func:`read_drawing` turns the bytes of a drawing into a :class:`Drawing` in millimetres with
the y axis up: its closed **outlines** (loops of :class:`~aidl_lang.geometry.shapes.curves.Line`,
``Arc`` and ``Spline`` pieces, counter-clockwise, largest area first), its **circles**, its
full **ellipses** ``(cx, cy, rx, ry, rotation)`` and its open **paths**.  Nothing is
approximated: a DXF ``LINE``, ``ARC``, ``CIRCLE``, ``LWPOLYLINE``/``POLYLINE`` (bulges are
arcs), ``SPLINE`` (non-rational, degree 1 to 3: its Bézier pieces, raised to cubics),
``ELLIPSE`` (whole, or a partial one as an exact ``EllipticArc``), ``HATCH`` boundary paths
(closed loops), ``INSERT``/``MINSERT`` blocks placed (every copy, under the entity budget:
``E0304``), ASCII or binary; an SVG path's lines,
circular and elliptical arcs, cubic and quadratic Béziers, and its
``rect``, ``circle``, ``ellipse``, ``polygon``, ``polyline`` and ``line`` elements.  What has
no exact form here (a rational spline, dimensions, images), a DXF entity not in the XY plane
(extrusion neither +Z nor -Z, or points at different z) and one whose numbers give no shape
(radius <= 0, zero length, inf, nan, beyond 1e15 mm) is skipped and counted in a
:class:`Note` (``W0130``, DXF: by type and layer).  Text (DXF ``TEXT``/``MTEXT``, SVG
``<text>``) is read into the drawing's ``texts``; an SVG path whose data holds a word that is
no number (``inf``, ``nan``) is read up to it and counted with its place.

Loose pieces are joined end to end (within :data:`JOIN_TOL`) into chains: a chain that comes
back to its start is an outline, otherwise a path; a chain whose end runs past its start,
crossing it, is closed at the crossing (:func:`~.chain._overshoot`), and a loop's small
loops where it crosses itself are cut off (:func:`~.chain._trim_small_loops`), and on a cut
role a loop that still crosses itself is split at its crossings (:func:`~.chain._lobes`).  A
loop that crosses itself, a selection that finds nothing and a file past :data:`MAX_ENTITIES` raise
:class:`DrawingError` (its ``code``, ``message`` and ``hint``: the caller places it at the
call).

Every number read is checked before it is used: a coordinate, radius, semi-axis or text
height (in mm, after the unit) that is not finite (``inf``, ``nan``) or beyond
:data:`~aidl_lang.base.limits.MAX_EXTENT` (1e6 mm, the model extent of a program), and a number
derived from them (the centre and radius of a DXF bulge, a spline's steps), is ``E0130``
naming the entity (DXF: its kind, handle and line; SVG: the element and its id).

Units: DXF ``$INSUNITS`` (0, unitless, is read as millimetres with a note), the SVG's
``width``/``height`` against its ``viewBox`` (CSS units: 96 px to the inch); ``units=``
overrides them (for SVG: one user unit of the ``viewBox`` is one ``units``).

This module is the entry: it picks the reader by the file's extension and applies the roles.
The pieces live by what they do: :mod:`.model` (the drawing, its errors, the number checks),
:mod:`.dxf` (the DXF reader, one function per entity kind), :mod:`.svg` (the SVG reader),
:mod:`.chain` (joining and closing the pieces) and :mod:`.roles` (cut, engrave, ignore).
"""
from __future__ import annotations

from ..chains.chain import open_gaps
from .dxf import _read_dxf
from ..model import (_OPTS, CLOSE_TOL, JOIN_TOL, MAX_ENTITIES, UNIT_MM, Drawing, DrawingError,
                     Note, Outline, Path, _Options)
from .roles import _colour_name, _role_of
from .svg import _bad_data_note, _read_svg, _svg_prescan

# the drawing model is read from here too (drawing/infer/, the tests, docs/api.md)
__all__ = ["read_drawing", "Drawing", "DrawingError", "Note", "Outline", "Path", "open_gaps",
           "CLOSE_TOL", "JOIN_TOL", "MAX_ENTITIES", "UNIT_MM"]


def read_drawing(data: bytes, name: str, layer=None, color=None, ident=None,
                 unit: str | None = None, keep_text: bool = False,
                 close_tolerance: float | None = None, cut=None, engrave=None, ignore=None,
                 roles=None, deadline=None, max_shapes: int | None = None) -> Drawing:
    """The drawing in ``data`` (``name``: its path as written, for messages; ``.dxf`` or
    ``.svg`` decides the reader).  ``layer``: DXF layer name(s) or SVG group id / Inkscape
    layer label(s); ``color``: DXF ACI number(s) or SVG colour(s); ``ident``: SVG element or
    group id(s); ``unit``: overrides the file's unit; ``keep_text``: a selection that holds
    only DXF text is not empty (``aidl import`` writes it).  ``close_tolerance``: chains
    whose ends meet within it (mm; default :data:`CLOSE_TOL`) are closed exactly.
    ``cut``/``engrave``/``ignore``/``roles``: the role of each shape by layer or colour
    (:func:`_role_of`): what is cut is the drawing, what is engraved its ``engrave``
    drawing, the rest left out (counted in a note).  ``deadline``: a
    :class:`~aidl_lang.base.limits.Deadline` the reading is held to (``E0304``, raised as
    :class:`~aidl_lang.base.limits.OutOfBudget`); ``max_shapes``: the shape limit (default
    :data:`MAX_ENTITIES`).  Raises :class:`DrawingError`."""
    if unit is not None and unit not in UNIT_MM:
        raise DrawingError("E0130", f"unknown unit `{unit}`",
                           "units: " + ", ".join(UNIT_MM))
    tol = CLOSE_TOL if close_tolerance is None else close_tolerance
    try:
        tol = float(tol)
    except (TypeError, ValueError):
        tol = float("nan")
    if not 0 <= tol <= 10:
        raise DrawingError("E0130", f"close_tolerance must be between 0 and 10 mm, not "
                                    f"{close_tolerance!r}",
                           f"the default is {CLOSE_TOL:g} mm; 0 closes only what meets")
    bad_data = []
    if name.lower().endswith(".svg"):
        bad_data = _svg_prescan(data, name, max_shapes or MAX_ENTITIES)
    role = _role_of(cut, engrave, ignore, roles)
    base = _Options(tol, deadline, None, max_shapes or MAX_ENTITIES)
    if role is None:
        token = _OPTS.set(base)
        try:
            d = _read_one(data, name, layer, color, ident, unit, keep_text)
        finally:
            _OPTS.reset(token)
        if bad_data:
            d.notes.append(_bad_data_note(bad_data, name))
        return d
    ignored: dict = {}
    # what `ignore=` itself names is left out as asked, unsaid (a warning on a design exactly
    # as meant is noise a model obeys); what a preset or an unnamed colour leaves out is counted
    named = _role_of(None, None, ignore, None) if ignore is not None else None

    def keep_for(want):
        def keep(layers, rgb, aci) -> bool:
            r = role(layers, rgb, aci)
            if want == "cut" and r == "ignore" and (
                    named is None or named(layers, rgb, aci) != "ignore"):
                what = (f"layer `{layers[0]}`" if layers and name.lower().endswith(".dxf")
                        else _colour_name(rgb))
                ignored[what] = ignored.get(what, 0) + 1
            return r == want
        return keep
    out = []
    from .dxf import one_parse
    with one_parse():           # each role reads the same file: parsed once
        for want in ("cut", "engrave"):
            token = _OPTS.set(_Options(tol, deadline, keep_for(want), base.max_shapes,
                                       split_crossings=want == "cut"))
            try:
                out.append(_read_one(data, name, layer, color, ident, unit, keep_text,
                                     allow_empty=True))
            finally:
                _OPTS.reset(token)
    d, e = out
    d.paths_cut = True
    if not e.empty or e.texts:
        d.engrave = e
        d.notes += [n for n in e.notes if n.message not in {m.message for m in d.notes}]
    if bad_data:
        d.notes.append(_bad_data_note(bad_data, name))
    if ignored:
        n = sum(ignored.values())
        d.notes.append(Note("W0130", f"{n} shape{'s' if n > 1 else ''} of `{name}` left out by "
                                     f"their role: " + ", ".join(
                                         f"{k} ({v})" for k, v in sorted(ignored.items())),
                            "give cut=, engrave= or ignore= (by layer or colour) to choose"))
    if d.empty and d.engrave is None and not (keep_text and d.texts):
        raise DrawingError("E0132", f"nothing to cut or engrave in `{name}` with these roles",
                           "name the layers or colours that hold the parts with cut= (or "
                           "roles=\"laser\": black and blue cut, green engraved)")
    return d


def _read_one(data: bytes, name: str, layer, color, ident, unit, keep_text,
              allow_empty: bool = False) -> Drawing:
    low = name.lower()
    if low.endswith(".dxf"):
        if ident is not None:
            raise DrawingError("E0130", "id= selects SVG elements; a DXF selects by layer= "
                                        "and color=", "give layer= for a DXF")
        d = _read_dxf(data, name, layer, color, unit)
    elif low.endswith(".svg"):
        d = _read_svg(data, name, layer, color, ident, unit)
    else:
        raise DrawingError("E0130", f"`{name}` is neither a .dxf nor a .svg file",
                           "give a DXF or SVG drawing")
    if allow_empty:
        return d
    if d.empty and not (keep_text and d.texts):      # `aidl import` keeps a text layer
        what = (f" on layer {layer!r}" if layer is not None else "") + \
               (f" with id {ident!r}" if ident is not None else "") + \
               (f" of colour {color!r}" if color is not None else "")
        raise DrawingError("E0132", f"nothing to import from `{name}`{what}"
                           + (f": {d.seen}" if d.seen else ""),
                           "select a layer, colour or id that holds lines, arcs, circles or "
                           "splines" + ("; or fix what was left out in the drawing program"
                                        if d.seen and "left out" in d.seen else ""))
    return d
