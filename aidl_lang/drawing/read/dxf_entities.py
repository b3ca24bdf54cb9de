"""The DXF reader's entities, one reader per kind behind a table (:data:`_ENTITY_READERS`,
read by :mod:`.dxf`): ``LINE``, ``ARC``, ``CIRCLE``, ``LWPOLYLINE``/``POLYLINE`` (bulges are
arcs: :func:`_bulge_arc`), ``SPLINE``, ``ELLIPSE``, ``HATCH`` boundary paths and
``TEXT``/``MTEXT`` (:func:`_dxf_text`), each an exact curve in the reading's context (its
scale, its layer and colour filters, the notes of what is skipped).  Split out of
:mod:`.dxf` (issue 96); ``ctx`` is its reading (``dxf._DxfReading``)."""
from __future__ import annotations

import math

FLAT_TOL = 1e-9          # mm: z values this close lie in one plane parallel to XY

from ...geometry.shapes.curves import Arc, Circle, Line, elliptic_arc
from .dxf_spline import _check_spline, _dxf_spline
from ..model import _finite, _mm, _Skip


def _bulge_arc(p, q, b) -> Arc | Line:
    """The arc from ``p`` to ``q`` of DXF bulge ``b`` (tan of a quarter of the sweep; > 0
    counter-clockwise)."""
    if abs(b) < 1e-15 or p == q:
        return Line(p, q)
    sweep = 4 * math.atan(b)
    d = math.dist(p, q)
    r = d / (2 * abs(math.sin(sweep / 2)))
    mx, my = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
    ux, uy = (q[0] - p[0]) / d, (q[1] - p[1]) / d
    # the centre is on the left of p->q for a counter-clockwise arc under 180 degrees, on the
    # right over 180 (cos of half the sweep < 0); mirrored for a clockwise one
    h = r * math.cos(sweep / 2) * (1.0 if sweep > 0 else -1.0)
    c = (mx - uy * h, my + ux * h)
    return Arc(c, r, math.atan2(p[1] - c[1], p[0] - c[0]), sweep)

# ------------------------------------------------------------------ one reader per entity kind
def _ocs_flipped(e) -> bool:
    """Whether the OCS entity ``e`` lies in the drawing plane (extrusion +Z or -Z), True
    for -Z (its OCS x axis is the world's -x: ezdxf's arbitrary axis algorithm); else
    raises _Skip."""
    ext = tuple(float(v) for v in e.dxf.get("extrusion", (0, 0, 1))) \
        if e.dxf.hasattr("extrusion") else (0.0, 0.0, 1.0)
    if not all(math.isfinite(v) for v in ext):
        raise _Skip("an extrusion that is not a number", cls="number")
    n = math.sqrt(sum(v * v for v in ext))
    if n == 0 or abs(ext[0]) > 1e-12 * n or abs(ext[1]) > 1e-12 * n:
        raise _Skip("not in the drawing plane: the extrusion (normal) is not +Z or -Z "
                    "(drawn in a tilted UCS)", cls="plane")
    return ext[2] < 0


def _poly_segments(vs, closed: bool) -> list | None:
    """The segments of ``vs`` ((x, y) mm, bulge), or None (all at one point)."""
    segs = []
    n = len(vs)
    for i in range(n if closed else n - 1):
        (p, b), (q, _) = vs[i], vs[(i + 1) % n]
        if math.dist(p, q) <= 1e-12:
            continue
        segs.append(_bulge_arc(p, q, b))
    return segs or None


def _entity_line(e, ctx) -> None:
    """LINE: a piece of one :class:`Line` (of zero length: skipped)."""
    ctx.flat("LINE", (e.dxf.start, e.dxf.end))
    a, b = ctx.P(e.dxf.start), ctx.P(e.dxf.end)
    if math.dist(a, b) <= 1e-12:
        raise _Skip("zero length", cls="number")
    ctx.pieces.append([Line(a, b)])


def _ocs_circle(e, t: str, ctx) -> tuple[tuple[float, float], float, bool]:
    """The centre (mm) and radius of the CIRCLE or ARC ``e`` (of type ``t``) and whether its
    extrusion is -Z (the centre then mirrored in x), its z noted; a radius not above 0 is
    skipped."""
    flip = _ocs_flipped(e)
    c = ctx.P(e.dxf.center)
    ctx.at_z(t, e.dxf.center[2], flip)
    r = _mm(float(e.dxf.radius) * ctx.scale, "a radius")
    if r <= 0:
        raise _Skip("a radius not above 0", cls="number")
    if flip:
        c = (-c[0], c[1])
    return c, r, flip


def _entity_circle(e, ctx) -> None:
    """CIRCLE: a :class:`Circle`."""
    c, r, _flip = _ocs_circle(e, "CIRCLE", ctx)
    ctx.circles.append(Circle(c, r))


FULL_TURN_DEG = 1e-9     # degrees: an ARC whose end angle is this close to its start is whole


def _entity_arc(e, ctx) -> None:
    """ARC: a piece of one :class:`Arc`, counter-clockwise from its start angle (clockwise
    seen from an extrusion down).  An ARC whose end angle is its start angle (a whole turn,
    0 to 360 degrees, or any span of whole turns; within :data:`FULL_TURN_DEG`) is the
    whole circle: a :class:`Circle`, as a CIRCLE is."""
    c, r, flip = _ocs_circle(e, "ARC", ctx)
    d1 = _finite(e.dxf.start_angle, "an angle")
    d2 = _finite(e.dxf.end_angle, "an angle")
    span = (d2 - d1) % 360.0
    if span <= FULL_TURN_DEG or span >= 360.0 - FULL_TURN_DEG:
        ctx.circles.append(Circle(c, r))
        return
    a1, sweep = math.radians(d1), math.radians(span)
    ctx.pieces.append([Arc(c, r, math.pi - a1, -sweep) if flip else Arc(c, r, a1, sweep)])


def _entity_lwpolyline(e, ctx) -> None:
    """LWPOLYLINE: lines and, where a vertex has a bulge, arcs (:func:`_bulge_arc`); its
    widths counted (read as the centre line)."""
    t = "LWPOLYLINE"
    flip = _ocs_flipped(e)
    ctx.at_z(t, e.dxf.get("elevation", 0.0), flip)
    vs = [(ctx.P((x, y)), _finite(b, "a bulge")) for x, y, b in e.get_points("xyb")]
    if e.has_width:
        ctx.widths[(t, ctx.layer)] = ctx.widths.get((t, ctx.layer), 0) + 1
    ctx.add_poly(t, vs, e.closed, flip)


def _entity_polyline(e, ctx) -> None:
    """POLYLINE: a 2D one as an LWPOLYLINE, a 3D one (world coordinates, no bulges) when its
    points share one z; a mesh is skipped."""
    t = "POLYLINE"
    if e.is_polygon_mesh or e.is_poly_face_mesh:
        raise _Skip("a mesh (3D faces): no outline here", cls="exact")
    if e.is_3d_polyline:         # world coordinates, no bulges
        locs = [v.dxf.location for v in e.vertices]
        ctx.flat(t, locs)
        vs = [(ctx.P(v), 0.0) for v in locs]
        flip = False
    else:
        flip = _ocs_flipped(e)
        ctx.at_z(t, e.dxf.get("elevation", (0, 0, 0))[2], flip)
        vs = [(ctx.P(v.dxf.location), _finite(v.dxf.get("bulge", 0.0), "a bulge"))
              for v in e.vertices]
        if e.has_width:
            ctx.widths[(t, ctx.layer)] = ctx.widths.get((t, ctx.layer), 0) + 1
    ctx.add_poly(t, vs, e.is_closed, flip)


def _entity_spline(e, ctx) -> None:
    """SPLINE: a piece of one :class:`Spline` (:func:`_dxf_spline`), its numbers checked
    before ezdxf's tools compute with them."""
    ctx.flat("SPLINE", list(e.control_points) or list(e.fit_points))
    for v in e.control_points:       # before ezdxf's tools compute with them
        ctx.P(v)
    for k in (*e.knots, *e.weights):
        _finite(k, "a knot or weight")
    _check_spline(e, ctx.P)
    ctx.pieces.append([_dxf_spline(e, ctx.P)])


def _entity_ellipse(e, ctx) -> None:
    """ELLIPSE: a whole one as ``(cx, cy, rx, ry, rotation)``, a partial one as a piece of
    one exact :class:`~aidl_lang.geometry.shapes.curves.EllipticArc`."""
    t = "ELLIPSE"
    # center and major axis are in world coordinates (not the OCS of ARC and
    # CIRCLE); the extrusion only turns the parameter: the minor axis is
    # extrusion x major axis, so an extrusion down runs the parameter clockwise
    flip = _ocs_flipped(e)
    if abs(float(e.dxf.major_axis[2]) * ctx.scale) > FLAT_TOL:
        raise _Skip("not in the drawing plane: its major axis leaves the XY plane",
                    cls="plane")
    ctx.at_z(t, e.dxf.center[2])
    s0 = _finite(e.dxf.start_param, "an angle")
    s1 = _finite(e.dxf.end_param, "an angle")
    c = ctx.P(e.dxf.center)
    mx = _mm(float(e.dxf.major_axis[0]) * ctx.scale, "a semi-axis")
    my = _mm(float(e.dxf.major_axis[1]) * ctx.scale, "a semi-axis")
    rx = _mm(math.hypot(mx, my), "a semi-axis")
    ratio = _finite(e.dxf.ratio, "an axis ratio")
    ry = _mm(rx * ratio, "a semi-axis")
    if rx <= 0 or ry <= 0:
        raise _Skip("a semi-axis not above 0", cls="number")
    rot = math.atan2(my, mx)
    sweep = (s1 - s0) % (2 * math.pi)
    if sweep < 1e-9 or sweep > 2 * math.pi - 1e-9:
        ctx.ellipses.append((c[0], c[1], rx, ry, rot))
        return
    nx, ny = (-my * ratio, mx * ratio) if not flip else (my * ratio, -mx * ratio)

    def at(tp):
        cs, sn = math.cos(tp), math.sin(tp)
        return (c[0] + mx * cs + nx * sn, c[1] + my * cs + ny * sn)
    ctx.pieces.append([elliptic_arc(c, rx, ry, rot, at(s0), at(s0 + sweep / 2),
                                    at(s0 + sweep))])


def _entity_text(e, ctx) -> None:
    """TEXT and MTEXT: their lines into ``texts`` (:func:`_dxf_text`); mirrored text (an
    extrusion down) is skipped; one whose height is not above 0 takes its style's fixed
    height (counted for a note), else is skipped (:func:`~.dxf_text.text_height`)."""
    from .dxf_text import text_height
    t = e.dxftype()
    if t == "TEXT" or e.dxf.hasattr("extrusion"):
        if _ocs_flipped(e):                  # mirrored text: not read
            raise _Skip("mirrored (extrusion down): not read", cls="text")
    h, why = text_height(e, t, ctx.doc)
    if why is not None and h <= 0:
        raise _Skip(f"{why}, and its text style has no fixed height: not read", cls="height",
                    named=True)
    if why is not None:
        ctx.style_height[why] = ctx.style_height.get(why, 0) + 1
    ctx.texts.extend(_dxf_text(e, t, ctx.P, ctx.scale, h))


# the reader of each entity kind (INSERT is expanded by the walk itself: before the
# selection, with the layer and colour its entities inherit); any other kind is skipped
_HALIGN = {0: "start", 1: "middle", 2: "end", 3: "middle", 4: "middle", 5: "middle"}
_VALIGN = {0: "baseline", 1: "bottom", 2: "middle", 3: "top"}


def _dxf_text(e, t: str, P, scale: float, height: float) -> list:
    """The lines of a TEXT or MTEXT entity as ``(text, position, height, rotation, anchor,
    valign)`` in mm and radians: its words with their codes decoded
    (:func:`~.dxf_text.dxf_words`), the insertion (or alignment) point, ``height`` (drawing
    units) as the cap height, MTEXT's lines one below the other (5/3 of the height apart,
    times its line spacing factor)."""
    import math as m
    from .dxf_text import dxf_words
    lines = dxf_words(e, t)
    h = float(height) * scale
    if t == "TEXT":
        text = lines[0] if lines else ""
        rot = m.radians(float(e.dxf.get("rotation", 0.0)))
        ha, va = int(e.dxf.get("halign", 0)), int(e.dxf.get("valign", 0))
        at = e.dxf.insert if (ha, va) == (0, 0) or not e.dxf.hasattr("align_point") \
            else e.dxf.align_point
        return [(text, P(at), h, rot, _HALIGN.get(ha, "start"), _VALIGN.get(va, "baseline"))] \
            if text.strip() else []
    try:
        rot = m.radians(float(e.get_rotation()))
    except Exception:
        rot = m.radians(float(e.dxf.get("rotation", 0.0)))
    ap = int(e.dxf.get("attachment_point", 1))
    anchor = ("start", "middle", "end")[(ap - 1) % 3]
    valign = ("top", "middle", "bottom")[(ap - 1) // 3] if len(lines) == 1 else "top"
    step = 5 / 3 * h * float(e.dxf.get("line_spacing_factor", 1.0))
    x0, y0 = P(e.dxf.insert)
    out = []
    for i, line in enumerate(lines):
        if line.strip():
            out.append((line, (x0 + m.sin(rot) * step * i, y0 - m.cos(rot) * step * i), h,
                        rot, anchor, valign))
    return out
