"""The SVG reader (svgelements): the bytes of an SVG in, a :class:`~.model.Drawing` out
(:func:`_read_svg`).  A path's lines, circular and elliptical arcs, cubic and quadratic
Béziers (:func:`_svg_path`), the ``rect``, ``circle``, ``ellipse``, ``polygon``, ``polyline``
and ``line`` elements (:func:`_svg_element`) and ``<text>`` (:func:`_svg_text`), in millimetres
with the y axis up, each under its transform exactly (a circle, ellipse or arc under a skew or
any ``matrix``: the true ellipse or elliptic arc, :mod:`.affine`; a singular transform: the
shape left out, named in a ``W0130`` note): the root's ``width`` against its ``viewBox`` (CSS units, 96 px to the
inch: :func:`_css_mm`), or ``units=``; selected by element id, group id or Inkscape layer
label, and by colour.  Before svgelements reads the file, :func:`_svg_prescan` counts what it
draws with expat (XML entities refused, nested ``<use>`` multiplied out: ``E0304``) and finds
path data holding a word that is no number (:func:`_path_data_error`, SVG 1.1 section
8.3.9)."""
from __future__ import annotations

import io
import math
import re

from ...geometry.shapes.curves import Circle, Line
from .affine import arc_curve, singular, whole_curve
from ..chains.chain import _finish
from ..model import (_OPTS, JOIN_TOL, UNIT_MM, Drawing, DrawingError, Note, _check_made,
                     _finite, _lerp, _mm, _OutOfRange, _range_error, bezier_spline)


# work units of one SVG element read (svgelements' parse and our walk: about 0.3 ms)
SVG_ELEMENT_UNITS = 40


PRECISION_DIGITS = (3, 7)   # an SVG whose numbers carry at most 3 to 7 decimals is that precise


def _svg_precision(data: bytes, scale: float) -> float:
    """One unit of the last decimal the SVG ``data`` writes its numbers to, in mm (``scale``:
    mm per user unit, :func:`_svg_scale`): ``1e-6`` for centres like ``75.980762`` in a mm
    viewBox; 0 when some number carries more decimals than :data:`PRECISION_DIGITS` allows
    (a float's own precision, as svgwrite writes them) or none more than 2 (whole numbers
    and ``version="1.1"`` say nothing of the precision of a drawing)."""
    digits = max((len(m) for m in re.findall(rb"\d\.(\d+)", data)), default=0)
    if not PRECISION_DIGITS[0] <= digits <= PRECISION_DIGITS[1]:
        return 0.0
    return 10.0 ** -digits * scale


def _px_per_user(svg) -> float:
    """svgelements' px per user unit (its viewBox scale), 1 without a viewBox."""
    vb = getattr(svg, "viewbox", None)
    return (float(svg.width) / vb.width) if vb is not None and vb.width and svg.width else 1.0


def _svg_scale(svg, unit: str | None) -> tuple[float, str]:
    """``(scale, unit)``: mm per px of svgelements' numbers (its viewBox scale undone, the exact
    mm per user unit from ``unit``, else the width attribute and viewBox, else CSS px) and the
    drawing's unit."""
    vb = getattr(svg, "viewbox", None)
    k = _px_per_user(svg)
    if unit is not None:
        mm_per_user = UNIT_MM[unit]
    else:
        unit = "mm"
        mm_per_user = _css_mm(svg.values.get("width"), vb.width if vb is not None else None)
        if mm_per_user is None:
            mm_per_user = k * 25.4 / 96
    return mm_per_user / k, unit


def _svg_roots(S, svg, name: str, ident, layer) -> list:
    """The elements read: the whole ``svg``, or those ``ident`` (ids) and ``layer`` (group ids or
    Inkscape labels) select; E0132 naming the nearest ids for one that is not there."""
    roots = [svg]
    for sel, what in ((ident, "id"), (layer, "layer")):
        if sel is None:
            continue
        wanted = [sel] if isinstance(sel, str) else list(sel)
        found = []
        for w in wanted:
            el = svg.get_element_by_id(w)
            if el is None:
                for g in svg.elements(lambda x: isinstance(x, S.Group)):
                    if w in (g.values.get("inkscape:label"), g.values.get(
                            "{http://www.inkscape.org/namespaces/inkscape}label"), g.id):
                        el = g
                        break
            if el is None:
                ids = sorted({x.id for x in svg.elements() if getattr(x, "id", None)})
                from ...base.diagnostics import did_you_mean
                sugg = did_you_mean(w, ids)
                raise DrawingError("E0132", f"`{name}` has no element or group with {what} "
                                            f"`{w}`",
                                   ("did you mean " + ", ".join(f"`{s}`" for s in sugg) + "?")
                                   if sugg else "ids: " + ", ".join(ids)[:300])
            found.append(el)
        roots = found
    return roots


def _read_svg(data: bytes, name: str, layer, color, ident, unit: str | None) -> Drawing:
    import svgelements as S
    notes: list[Note] = []
    data = _svg_root(data, name, unit, notes)
    try:
        # reify=False: svgelements' reification folds a transform's scale into a circle's,
        # ellipse's or rect's own numbers, the signs of a negative one too (scale(-1,-1): r
        # -5), so each shape keeps its own numbers and its whole transform, applied here
        svg = S.SVG.parse(io.BytesIO(data), reify=False, ppi=96.0)
    except Exception as ex:
        raise DrawingError("E0130", f"`{name}` is not a readable SVG file ({type(ex).__name__})",
                           "save it as plain SVG") from None
    # svgelements gives px (its mm-to-px factor is rounded): undo its viewBox scale k (px per
    # user unit) and apply the exact mm per user unit from the width attribute and viewBox
    scale, unit = _svg_scale(svg, unit)
    roots = _svg_roots(S, svg, name, ident, layer)
    pieces, loops, circles, ellipses = [], [], [], []
    texts: list = []
    lost_text: list = []            # "`the words` (why)", each a text not written
    skipped: dict[str, int] = {}
    spec: list = []                 # shapes in error by the SVG spec (_spec_checked)
    flat: list = []                 # shapes under a transform with no area: not drawn
    count = 0

    def P(p):
        return (_mm(float(p[0]) * scale), _mm(-float(p[1]) * scale))

    def colour_ok(el) -> bool:
        if color is None:
            return True
        want = {c.lower() for c in ([color] if isinstance(color, str) else color)}
        have = set()
        for attr in ("stroke", "fill"):
            v = getattr(el, attr, None)
            if v is not None and getattr(v, "value", None) is not None:
                have.add(S.Color(v).hex.lower()[:7])
        return bool({S.Color(w).hex.lower()[:7] for w in want} & have)

    opts = _OPTS.get()

    def names_of(g) -> list:
        return [v for v in (getattr(g, "id", None), g.values.get("inkscape:label"), g.values.get(
            "{http://www.inkscape.org/namespaces/inkscape}label")) if v]

    def walk(node, names):
        """The shapes under ``node`` with the names (ids, Inkscape labels) of the groups
        they are in."""
        yield node, names
        if isinstance(node, (S.Group, S.Use)):
            inner = names + names_of(node)
            for ch in node:
                yield from walk(ch, inner)

    seen = set()
    for root in roots:
        for el, names in walk(root, []):
            if id(el) in seen:
                continue
            seen.add(id(el))
            if opts.deadline is not None and len(seen) % 512 == 1:
                # the next 512 elements paid before they are walked (svgelements: about
                # 0.3 ms each, parse and walk)
                opts.deadline.check("reading the drawing", ahead=512 * SVG_ELEMENT_UNITS)
            if opts.keep is not None and isinstance(el, (S.Shape, S.Text)):
                c = getattr(el, "stroke", None)
                if c is None or getattr(c, "value", None) is None:
                    c = getattr(el, "fill", None)
                rgb = (c.red, c.green, c.blue) if c is not None and \
                    getattr(c, "value", None) is not None else None
                if not opts.keep(names + names_of(el), rgb, None):
                    continue
            if isinstance(el, S.Text):
                if el.values.get("visibility") in ("hidden", "collapse") or \
                        el.values.get("display") == "none" or not colour_ok(el):
                    continue
                try:
                    got = _svg_text(el, P, scale)
                except _OutOfRange as ex:          # as a shape's: E0130 naming it
                    ident_ = getattr(el, "id", None)
                    raise _range_error(ex, "<text>" + (f" (id `{ident_}`)" if ident_ else ""),
                                       name) from None
                if isinstance(got, str):
                    lost_text.append(got)
                elif got is not None:
                    texts.append(got)
                continue
            if not isinstance(el, S.Shape):
                continue
            if el.values.get("visibility") in ("hidden", "collapse") or \
                    el.values.get("display") == "none":
                continue
            if not colour_ok(el):
                continue
            if isinstance(el, (S.Polyline, S.Polygon)) and isinstance(
                    el.values.get("points"), str) and _path_data_error(
                    el.values["points"].replace("M", "?").replace("m", "?")) is not None:
                continue        # svgelements would pair the numbers after it wrongly: noted
            el = _spec_checked(S, el, svg, spec)
            if el is None:              # a negative size: SVG draws no such shape (noted)
                continue
            count += 1
            if count > opts.max_shapes:
                raise DrawingError("E0130", f"`{name}` has more than {opts.max_shapes} shapes",
                                   "select fewer with id= or split the drawing")
            try:
                _svg_element(S, el, P, scale, pieces, loops, circles, ellipses, skipped, flat)
            except ValueError as ex:        # svgelements: a length it cannot resolve (a %
                tag = type(el).__name__.lower()     # with no viewBox to measure it by)
                why = f"{tag} with a length that cannot be resolved ({str(ex).rstrip('.')})"
                skipped[why] = skipped.get(why, 0) + 1
            except _OutOfRange as ex:
                tag = type(el).__name__.lower()
                ident_ = getattr(el, "id", None)
                raise _range_error(ex, f"<{tag}>" + (f" (id `{ident_}`)" if ident_ else ""),
                                   name) from None
    _skip_notes(skipped, notes, name)
    _spec_notes(spec, notes, name)
    flat_note = _flat_note(flat, data, name) if flat else None
    if flat_note is not None:
        notes.append(flat_note)
    if lost_text:
        n = len(lost_text)
        notes.append(Note("W0130", f"{n} text{'s' if n != 1 else ''} of `{name}` not "
                                   f"imported: " + "; ".join(lost_text[:8])
                                   + (f"; and {n - 8} more" if n > 8 else ""),
                          "write them with Text(...) in a `drawing` of the part"))
    d = _finish(pieces, loops, circles, ellipses, notes, unit, name)
    d.texts = texts
    d.precision = _svg_precision(data, scale * _px_per_user(svg))
    if flat_note is not None:         # the message of an import that gives nothing
        d.seen = "left out: " + flat_note.message
    return d


# SVG text-anchor and dominant-baseline as Text's anchor and valign (Boxes.py writes
# text-anchor="left", which CSS does not know, for the start)
_SVG_ANCHOR = {"start": "start", "left": "start", "middle": "middle", "center": "middle",
               "end": "end", "right": "end"}
_SVG_BASELINE = {"hanging": "top", "text-before-edge": "top", "middle": "middle",
                 "central": "middle", "text-after-edge": "bottom", "ideographic": "bottom",
                 "alphabetic": "baseline", "auto": "baseline", "baseline": "baseline"}
CAP_HEIGHT_EM = 0.7      # the cap height of a sans-serif font in em (Helvetica, Arial 0.72)


def _svg_text(el, P, scale: float):
    """An SVG ``<text>`` as ``(text, position mm, cap height mm, rotation rad, anchor,
    valign)`` (:class:`Drawing`'s ``texts``), a string saying why it is not written (a
    mirrored or skewed transform, no size), or None when it has no words.  Its size is
    its ``font-size`` times :data:`CAP_HEIGHT_EM` (Text's size is the cap height: the
    single-stroke font stands in for the file's font, so the words and where they stand
    come through, not the letter shapes); ``text-anchor`` and ``dominant-baseline`` give
    ``anchor`` and ``valign`` (:data:`_SVG_ANCHOR`, :data:`_SVG_BASELINE`)."""
    words = " ".join((el.text or "").split())
    if not words:
        return None
    shown = words if len(words) <= 40 else words[:37] + "..."
    m = el.transform
    a, b, c, d = float(m.a), float(m.b), float(m.c), float(m.d)
    det = a * d - b * c
    if not all(math.isfinite(v) for v in (a, b, c, d)) or abs(det) < 1e-12:
        return f"`{shown}` (its transform has no size)"
    if det < 0:
        return f"`{shown}` (mirrored)"
    sx, sy = math.hypot(a, b), math.hypot(c, d)
    if abs(a * c + b * d) > 1e-9 * sx * sy or abs(sx - sy) > 1e-9 * max(sx, sy):
        return f"`{shown}` (skewed or stretched)"
    try:
        fs = float(el.font_size)
    except (TypeError, ValueError):
        fs = float("nan")
    if not math.isfinite(fs) or fs <= 0:
        return f"`{shown}` (no font size)"
    x, y = float(el.x or 0.0), float(el.y or 0.0)
    at = P(m.point_in_matrix_space((x, y)))
    size = _mm(fs * sx * scale * CAP_HEIGHT_EM, "a text height")
    rot = -math.atan2(b, a)          # the SVG's y axis points down
    anchor = _SVG_ANCHOR.get(str(el.values.get("text-anchor", "start")).strip().lower(),
                             "start")
    valign = _SVG_BASELINE.get(str(el.values.get("dominant-baseline", "auto")).strip().lower(),
                               "baseline")
    return (words, at, size, rot, anchor, valign)


_PATH_TOKEN = None


def _path_data_error(d: str, path: bool = False) -> tuple[int, str] | None:
    """Where the SVG path data ``d`` stops being readable (SVG 1.1 section 8.3.9: command
    letters, numbers, whitespace and commas): ``(character offset, the word there)``, or
    None.  svgelements stops reading a path at such a word (``inf``, ``nan``, ``1,5e``) and
    drops the rest of it without a word; the caller counts it (``W0130``).  ``path``: ``d``
    is a path's data, which must begin with a moveto (svgelements gave the segments before
    it no start point)."""
    import re
    global _PATH_TOKEN
    if _PATH_TOKEN is None:
        _PATH_TOKEN = re.compile(r"[\s,]+|[MmZzLlHhVvCcSsQqTtAa]|"
                                 r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
    i, n = 0, len(d)
    if path:
        lead = len(d) - len(d.lstrip(" \t\r\n,"))
        if lead < n and d[lead] not in "Mm":
            word = re.match(r"[^\s,]{1,20}", d[lead:])
            return lead, word.group(0) if word else d[lead:lead + 1]
    while i < n:
        m = _PATH_TOKEN.match(d, i)
        if m is None or m.end() == i:
            word = re.match(r"[^\s,]{1,20}", d[i:])
            return i, word.group(0) if word else d[i:i + 1]
        i = m.end()
    return None


def _svg_prescan(data: bytes, name: str, limit: int) -> list:
    """Count what the SVG ``data`` draws before svgelements reads it, with the standard
    library's expat parser (no entity expansion, no network): a file that declares XML
    entities (``<!ENTITY``: the "billion laughs") is refused, and each ``<use>`` counts as
    the elements it copies, nested ``<use>`` multiplied out, so a few kilobytes of nested
    references that would expand to millions of shapes are refused (``E0304``, at the
    ``<use>`` that copies the most) before they are expanded; more than ``limit`` elements
    drawn is ``E0130``.  A file expat cannot parse is left to svgelements (its message).

    Returns the paths (``d``) and polylines or polygons (``points``) whose data holds a word
    that is no number or command (:func:`_path_data_error`: ``inf``, ``nan``): ``(tag, id or
    None, line, offset, word, characters left out)`` each, for the ``W0130`` note of
    :func:`read_drawing`."""
    import xml.parsers.expat as X
    tags: list = []         # per element: local tag, id, href, line
    kids: list = []
    stack: list = []
    ids: dict = {}
    bad_data: list = []

    class _Refused(Exception):
        pass

    def start(tag, attrs):
        local = tag.rsplit("}", 1)[-1].rsplit(":", 1)[-1]
        href = attrs.get("href") or attrs.get("http://www.w3.org/1999/xlink}href") or \
            attrs.get("xlink:href")
        i = len(tags)
        tags.append((local, attrs.get("id"), href, p.CurrentLineNumber))
        kids.append([])
        if stack:
            kids[stack[-1]].append(i)
        if attrs.get("id") is not None:
            ids.setdefault(attrs["id"], i)
        data_attr = "d" if local == "path" else "points" if local in ("polyline", "polygon") \
            else None
        if data_attr is not None and attrs.get(data_attr):
            text = attrs[data_attr]
            err = _path_data_error(text, True) if data_attr == "d" else \
                _path_data_error(text.replace("M", "?").replace("m", "?"))
            if err is not None:
                bad_data.append((local, attrs.get("id"), p.CurrentLineNumber, err[0], err[1],
                                 len(text) - err[0]))
        stack.append(i)
        if len(stack) > 500:
            raise DrawingError("E0130", f"`{name}` nests its elements more than 500 deep",
                               "save it again as plain SVG with fewer nested groups",
                               p.CurrentLineNumber)
        if len(tags) > 50 * limit + 1000:
            raise _Refused()

    def end(tag):
        stack.pop()

    def entity(*a):
        raise DrawingError("E0130", f"`{name}` declares XML entities (<!ENTITY ...>): not read",
                           "save it again as plain SVG (Inkscape: Save As, Plain SVG)",
                           p.CurrentLineNumber)
    p = X.ParserCreate(namespace_separator="}")
    p.StartElementHandler, p.EndElementHandler = start, end
    p.EntityDeclHandler = entity
    try:
        p.Parse(data, True)
    except DrawingError:
        raise
    except _Refused:
        raise DrawingError("E0130", f"`{name}` has more than {limit} shapes",
                           "select fewer with id= or split the drawing") from None
    except Exception:
        return []               # not XML: svgelements says so
    cap = 10 * limit + 1
    weight: dict = {}
    busy: set = set()

    def w(i: int) -> int:
        if i in weight:
            return weight[i]
        if i in busy:
            local, ident, _href, line = tags[i]
            raise DrawingError("E0130", f"<{local}>" + (f" (id `{ident}`)" if ident else "")
                               + f" of `{name}` refers to itself through <use>",
                               "remove the circular <use> reference", line)
        busy.add(i)
        local, _ident, href, _line = tags[i]
        n = 1 if local in ("path", "rect", "circle", "ellipse", "line", "polyline",
                           "polygon", "text") else 0
        for k in kids[i]:
            n = min(cap, n + w(k))
        if local == "use" and href and href.startswith("#") and href[1:] in ids:
            n = min(cap, n + w(ids[href[1:]]))
        busy.discard(i)
        weight[i] = n
        return n
    import sys
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, 20000))
    try:
        total = w(0) if tags else 0
    except RecursionError:
        raise DrawingError("E0130", f"`{name}` nests its elements too deeply",
                           "save it again as plain SVG with fewer nested groups") from None
    finally:
        sys.setrecursionlimit(old)
    if total > limit:
        uses = [i for i, t in enumerate(tags) if t[0] == "use"]
        if uses:
            i = max(uses, key=lambda i: (weight.get(i, 0), -i))
            local, ident, href, line = tags[i]
            more = "more than " if weight[i] >= cap else ""
            raise DrawingError("E0304", f"<use>" + (f" (id `{ident}`)" if ident else "")
                               + f" of `{name}` copies `{href}` into {more}{weight[i]} shapes "
                                 f"(nested <use> references): the drawing would hold more than "
                                 f"the {limit} shapes an import may read",
                               "replace the nested <use> copies by the shapes they copy "
                               "(Inkscape: Edit > Clone > Unlink Clone), or draw fewer",
                               line)
        raise DrawingError("E0130", f"`{name}` has more than {limit} shapes",
                           "select fewer with id= or split the drawing")
    return bad_data


def _bad_data_note(bad: list, name: str) -> Note:
    """The ``W0130`` note of the paths whose data stops at a word that is no number
    (:func:`_svg_prescan`), each with its place."""
    where = "; ".join(f"<{tag}>" + (f" (id `{i}`)" if i else "") + f" at line {ln}, "
                      f"character {off + 1}: `{w}` (" + (f"{left} characters left out"
                                                         if tag == "path" else
                                                         "the whole shape left out") + ")"
                      for tag, i, ln, off, w, left in bad[:5])
    more = f"; and {len(bad) - 5} more" if len(bad) > 5 else ""
    n = len(bad)
    return Note("W0130", f"{n} path{'s' if n != 1 else ''} of `{name}` "
                         f"{'holds' if n == 1 else 'hold'} a number that cannot be read: a "
                         f"path's data is read up to it: {where}{more}",
                "write a finite number there (inf and nan are no coordinates), or save the "
                "drawing again from its program")


def _svg_element(S, el, P, scale, pieces, loops, circles, ellipses, skipped,
                 flat: list | None = None) -> None:
    """Read the shape ``el`` into the lists, its transform applied exactly (a circle or
    ellipse under any affine map is the true ellipse, :mod:`.affine`); its numbers checked
    (:func:`_check_made`: raises :class:`_OutOfRange`).  A shape whose transform (the
    groups' and its own, in all) has no area, a singular matrix, is not drawn: its label
    goes to ``flat`` (:func:`_svg_label`) for the ``W0130`` note."""
    made = (len(pieces), len(loops), len(circles), len(ellipses))
    if _flattened(S, el):
        if flat is not None:
            flat.append(_svg_label(el))
        return
    if isinstance(el, (S.Circle, S.Ellipse)) and not isinstance(el, S.Path):
        # the element's own cx, cy, rx, ry under its whole transform (the file is read
        # without svgelements' reification, :func:`_read_svg`): the images of its semi-axes
        # are conjugate semi-diameters of the ellipse drawn, whatever the map's signs
        rx, ry = float(el.rx), float(el.ry)
        if not (rx > 0 and ry > 0):
            return
        m = el.transform
        a, b, c, d = float(m.a), float(m.b), float(m.c), float(m.d)
        o = P(m.point_in_matrix_space((float(el.cx), float(el.cy))))
        u = (_mm(a * rx * scale, "a radius"), _mm(-b * rx * scale, "a radius"))
        v = (_mm(c * ry * scale, "a radius"), _mm(-d * ry * scale, "a radius"))
        got = whole_curve(o, u, v)
        if got is None:
            if flat is not None:
                flat.append(_svg_label(el))
        elif isinstance(got, Circle):
            circles.append(got)
        else:
            ellipses.append(got)
    else:
        path = S.Path(el)
        if not path.transform.is_identity():        # a rect or polygon svgelements left
            path = abs(path)                          # under its transform: applied
        _svg_path(S, path, P, pieces, loops, skipped, scale)
    _check_made(pieces[made[0]:] + [seg for seg, _ in loops[made[1]:]] + circles[made[2]:]
                + ellipses[made[3]:])


def _css_mm(width, vb_width) -> float | None:
    """Millimetres per user unit from the root ``width`` (a CSS length: mm, cm, in, pt, pc,
    px or a bare number, px) over the ``viewBox`` width (none: one user unit is one px, the
    width only sizes the viewport, SVG 2 section 8.2)."""
    import re
    if width is None:
        return (25.4 / 96) if vb_width is None else None
    m = re.fullmatch(r"\s*([0-9.eE+-]+)\s*(mm|cm|in|pt|pc|px|)\s*", str(width))
    if not m:
        return None
    try:
        w = float(m.group(1))
    except ValueError:
        return None
    per = {"mm": 1.0, "cm": 10.0, "in": 25.4, "pt": 25.4 / 72, "pc": 25.4 / 6, "px": 25.4 / 96,
           "": 25.4 / 96}[m.group(2)]
    # no viewBox: no viewport transform, a user unit is a CSS px whatever the width says
    return w * per / vb_width if vb_width else 25.4 / 96


def _svg_path(S, path, P, pieces, loops, skipped, scale: float) -> None:
    """The segments of the svgelements ``path`` (its transform applied: user units, y
    down) as pieces and loops in mm (``P``: a point in mm; ``scale``: mm per unit)."""
    cur: list = []

    def flush(closed: bool) -> None:
        nonlocal cur
        if cur:
            if closed or math.dist(cur[0].start, cur[-1].end) <= JOIN_TOL:
                loops.append((cur, "path"))
            else:
                pieces.append(cur)
        cur = []

    for seg in path:
        if isinstance(seg, S.Move):
            flush(False)
            continue
        if isinstance(seg, S.Close):
            if cur and math.dist(cur[-1].end, cur[0].start) > JOIN_TOL:
                cur.append(Line(cur[-1].end, cur[0].start))
            flush(True)
            continue
        if seg.start is None or seg.end is None:
            # data before its first moveto: in error from its start, so none of it is drawn
            # (SVG 1.1 8.3.9), as the note says (_path_data_error)
            return
        a, b = P(seg.start), P(seg.end)
        if isinstance(seg, S.Line):
            cur.append(Line(a, b))          # one of zero length: dropped and counted later
        elif isinstance(seg, S.CubicBezier):
            cur.append(bezier_spline([[a, P(seg.control1), P(seg.control2), b]]))
        elif isinstance(seg, S.QuadraticBezier):
            c = P(seg.control)
            cur.append(bezier_spline([[a, _lerp(a, c, 2 / 3), _lerp(b, c, 2 / 3), b]]))
        elif isinstance(seg, S.Arc):
            got = _svg_arc(seg, P, a, b, scale)
            if got is None:
                skipped["elliptical arc"] = skipped.get("elliptical arc", 0) + 1
                continue
            cur.append(got)
        else:
            skipped[type(seg).__name__] = skipped.get(type(seg).__name__, 0) + 1
    flush(False)


def _svg_arc(seg, P, a, b, scale: float):
    """The exact circular or elliptic arc of the svgelements ``Arc`` ``seg`` from ``a`` to
    ``b`` (mm), or None when it spans no area or no length.  svgelements keeps an arc under
    a transform as its centre and the images ``prx``, ``pry`` of the points at parameter 0
    and a quarter turn: conjugate semi-diameters ``u``, ``v`` (perpendicular only under a
    similarity); its ``sweep`` is the parameter's, its sign turned over by a mirror (so the
    parameter runs by ``sweep`` times the sign of ``u x v``).  The start's parameter comes
    from ``u``, ``v`` (:mod:`.affine`)."""
    cx, cy = float(seg.center.x), float(seg.center.y)
    u = (float(seg.prx.x) - cx, float(seg.prx.y) - cy)
    v = (float(seg.pry.x) - cx, float(seg.pry.y) - cy)
    um, vm = ((_mm(w[0] * scale, "a semi-axis"), _mm(-w[1] * scale, "a semi-axis"))
              for w in (u, v))                  # P's linear part: y turns over
    if singular(u, v) or math.dist(a, b) <= 1e-12:
        return None
    det = u[0] * v[1] - u[1] * v[0]
    sx, sy = float(seg.start.x) - cx, float(seg.start.y) - cy
    t0 = math.atan2((u[0] * sy - u[1] * sx) / det, (sx * v[1] - sy * v[0]) / det)
    sweep = _finite(seg.sweep, "an angle") * (1.0 if det > 0 else -1.0)
    return arc_curve(P(seg.center), um, vm, t0, sweep, a, b)


def _flat_note(flat: list, data: bytes, name: str) -> Note:
    """The ``W0130`` note of the shapes ``flat`` (:func:`_svg_label`) left out because their
    transform is singular, each with its line when it has an id."""
    import re

    def where(label: str) -> str:
        m = re.search(r"\(id `(.*)`\)$", label)
        at = data.find(f'id="{m.group(1)}"'.encode()) if m else -1
        line = data.count(b"\n", 0, at) + 1
        return label + (f" at line {line}" if at >= 0 else "")
    n = len(flat)
    shown = "; ".join(where(x) for x in flat[:5]) + (f"; and {n - 5} more" if n > 5 else "")
    return Note("W0130", f"{n} shape{'s' if n != 1 else ''} of `{name}` not drawn: "
                         f"{'its' if n == 1 else 'their'} transform has no area (a singular "
                         f"matrix flattens {'it' if n == 1 else 'them'} onto a line or a "
                         f"point): {shown}",
                "fix the transform in the drawing (a scale of 0, or a matrix(a,b,c,d,e,f) "
                "with a*d = b*c, draws nothing), or delete the shape")


def _flattened(S, el) -> bool:
    """Whether the transform of shape ``el`` in all (its groups' and its own, as svgelements
    gathers them in its ``transform`` value) is singular: no area (a zero scale,
    ``matrix(1,1,1,1,0,0)``)."""
    try:
        m = S.Matrix(el.values.get("transform", "")) if el.values.get("transform") \
            else el.transform
        a, b, c, d = float(m.a), float(m.b), float(m.c), float(m.d)
    except (TypeError, ValueError, AttributeError):
        return False
    if not all(math.isfinite(x) for x in (a, b, c, d)):
        return False                # not a number: the range checks say so (E0130)
    return singular((a, b), (c, d))


def _svg_label(el) -> str:
    """``<circle> (id `c`)``, or the element's own numbers when it has no id."""
    tag = {"SimpleLine": "line"}.get(type(el).__name__, type(el).__name__.lower())
    ident = getattr(el, "id", None)
    if ident:
        return f"<{tag}> (id `{ident}`)"
    own = [f'{k}="{el.values[k]}"' for k in ("x", "y", "cx", "cy", "r", "rx", "ry", "width",
                                             "height", "x1", "y1", "d", "points")
           if isinstance(el.values.get(k), str)]
    text = " ".join(own)
    return f"<{tag} {text[:60]}{'...' if len(text) > 60 else ''}>" if own else f"<{tag}>"


def _skip_notes(skipped: dict, notes: list, name: str) -> None:
    for what, n in sorted(skipped.items()):
        if what in ("TEXT", "MTEXT", "text"):
            notes.append(Note("W0130", f"{n} {what} {'entity' if n == 1 else 'entities'} of "
                                       f"`{name}` skipped: text is not imported",
                              "write the text with Text(...) in a `drawing`"))
        else:
            notes.append(Note("W0130", f"{n} {what} {'entity' if n == 1 else 'entities'} of "
                                       f"`{name}` skipped: no exact form here",
                              "convert it to lines, arcs or splines in the drawing program, "
                              "or select other layers"))


# ------------------------------------------------------------------ errors by the SVG spec
_NUMBER = r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)"


def _negative(v) -> bool:
    """Whether the attribute value ``v`` (a length: ``-3``, ``-2mm``) is below 0."""
    import re
    m = re.match(_NUMBER, str(v)) if v is not None else None
    return m is not None and float(m.group(1)) < 0


def _svg_root(data: bytes, name: str, unit: str | None, notes: list) -> bytes:
    """``data`` with what the SVG spec makes no size of the root ``<svg>`` left out, each
    said in a ``W0130`` appended to ``notes``: a ``viewBox`` of negative width or height is an
    error that disables it (SVG 2 section 8.6: svgelements would mirror the drawing by it),
    so the user unit is one px; a ``width`` or ``height`` in percent refers to a containing
    block a file does not have, so both are left out and the drawing is its ``viewBox``'s
    size, one user unit one px (CSS: 96 to the inch; svgelements would take the percentage
    of a 1000 px window, or of the viewBox, shrinking or shifting the drawing).  ``unit``
    (``units=``) sets the user unit itself: the percentages are then left out unsaid."""
    import re
    tag = re.search(rb"<(?:[A-Za-z_][\w.-]*:)?svg\b(?:[^>\"']|\"[^\"]*\"|'[^']*')*>", data)
    if tag is None:
        return data
    head = tag.group(0)
    attr = re.compile(rb"""(\s)(width|height|viewBox)\s*=\s*("[^"]*"|'[^']*')""")
    vals = {m.group(2).decode(): m.group(3)[1:-1].decode("utf-8", "replace")
            for m in attr.finditer(head)}
    drop = set()
    vb = vals.get("viewBox")
    if vb is not None:
        nums = re.findall(_NUMBER, vb)
        if len(nums) == 4 and (float(nums[2]) < 0 or float(nums[3]) < 0):
            drop.add("viewBox")
            notes.append(Note("W0130", f"`{name}` has a viewBox of negative "
                                       f"{'width' if float(nums[2]) < 0 else 'height'} "
                                       f"(viewBox=\"{vb}\"), an error in SVG: the viewBox is "
                                       f"left out, not mirrored"
                                       + ("" if unit else "; one user unit read as one px "
                                                          "(0.2646 mm)"),
                              'give units="mm" (or another unit) for the size of a user unit, '
                              "or fix the viewBox in the drawing program"))
    pct = [k for k in ("width", "height") if "%" in vals.get(k, "")]
    if pct:
        drop.update(("width", "height"))
        if unit is None:
            what = ", ".join(f'{k}="{vals[k]}"' for k in pct)
            notes.append(Note("W0130", f"`{name}` gives its size in percent ({what}), which a "
                                       f"file has nothing to take it of: read "
                                       + ("at the size of its viewBox, " if vb is not None
                                          and "viewBox" not in drop else "")
                                       + "one user unit as one px (0.2646 mm)",
                              'give units="mm" (or another unit) for the size of a user unit'))
    if not drop:
        return data
    new = attr.sub(lambda m: m.group(0) if m.group(2).decode() not in drop else m.group(1)
                   + b"data-aidl-dropped-" + m.group(2) + b'=""', head)
    return data[:tag.start()] + new + data[tag.end():]


def _spec_checked(S, el, svg, spec: list):
    """The shape ``el`` as the SVG spec draws it (SVG 2 chapter 7, geometry properties), or
    None when it draws nothing: a ``rect`` of negative ``width`` or ``height`` and a
    ``circle`` of negative ``r`` are not drawn (an illegal value: the initial 0); a negative
    ``rx`` or ``ry`` of a ``rect`` or ``ellipse`` is ignored (``auto``: the other radius,
    both ignored: a rect of square corners, no ellipse).  Each case is appended to ``spec``
    as ``(drawn, "<rect> width=\"-3\"")`` for the note (:func:`_spec_notes`); ``svg``: the
    root, whose viewport sizes a rebuilt shape's percentages."""
    if isinstance(el, S.Path) or not isinstance(el, (S.Rect, S.Circle, S.Ellipse)):
        return el
    v = el.values
    tag = "rect" if isinstance(el, S.Rect) else "circle" if isinstance(el, S.Circle) \
        else "ellipse"
    ident = getattr(el, "id", None)
    label = f"<{tag}>" + (f" (id `{ident}`)" if ident else "")
    sizes = {"rect": ("width", "height"), "circle": ("r",), "ellipse": ()}[tag]
    bad = [k for k in sizes if _negative(v.get(k))]
    if bad:
        spec.append((False, label + " " + " ".join(f'{k}="{v.get(k)}"' for k in bad)))
        return None
    radii = [k for k in ("rx", "ry") if tag != "circle" and _negative(v.get(k))]
    if not radii:
        return el
    spec.append((True, label + " " + " ".join(f'{k}="{v.get(k)}"' for k in radii)))
    good = [k for k in ("rx", "ry") if k not in radii and v.get(k) is not None]
    fixed = dict(v)
    for k in radii:
        if good:
            fixed[k] = v.get(good[0])
        elif tag == "rect":
            fixed[k] = "0"                   # both auto: square corners
        else:
            return None                      # an ellipse of no radius: not drawn
    new = type(el)(fixed)
    try:
        new.render(ppi=96.0, width=float(svg.width or 1000), height=float(svg.height or 1000))
    except Exception:
        return el
    return new


def _spec_notes(spec: list, notes: list, name: str) -> None:
    """The ``W0130`` notes of :func:`_spec_checked`'s cases: the shapes not drawn, the radii
    ignored (the first five of each named)."""
    for drawn, what, hint in ((False, "not drawn: a negative size is an error in SVG",
                               "fix the size in the drawing program (a browser does not draw "
                               "them either)"),
                              (True, "drawn with the negative radius ignored, as SVG does "
                                     "(auto: the other radius, else 0)",
                               "fix the radius in the drawing program")):
        got = [w for d, w in spec if d is drawn]
        if got:
            n = len(got)
            shown = "; ".join(got[:5]) + (f"; and {n - 5} more" if n > 5 else "")
            notes.append(Note("W0130", f"{n} shape{'s' if n != 1 else ''} of `{name}` "
                                       f"{what}: {shown}", hint))
