"""``aidl import --infer``: a solid whose two parts are one part and its mirror image (a pair of
L-brackets drawn left and right; issue 71; used by :func:`~.infer.to_program_inferred`).

In: a solid's :class:`~.model.Drawing` (mm).  Out: :func:`mirrored_pair` gives ``(the first
part, the axis)`` when the drawing is exactly two parts (outer loops with their holes, no
open paths, texts or engravings: text cannot be mirrored) and the second is the first
mirrored about a vertical line ``("x", a)`` or a horizontal one ``("y", a)``, every piece of
it within :data:`TOL` of a mirrored piece of the first, one for one; else None.  The program
then writes the first part as a solid and the second as ``Mirrored(part, about=axis)``, so an
edit of the part is made to both and they stay mirror images.
"""
from __future__ import annotations

import math

from ...geometry.shapes.curves import Arc, Circle, Line
from ..model import Drawing

TOL = 1e-7              # mm: a mirrored piece against the other part's
MAX_PIECES = 4000       # pieces of a part compared (one for one, by their rounded keys)
MAX_LOOPS = 400         # loops of a solid looked at for two parts (found by containment)


def _box(d: Drawing):
    return d.box()


def _ends(p, q) -> tuple:
    """Two ends in an order that float noise cannot flip."""
    return tuple(sorted((p, q), key=lambda t: (round(t[0], 6), round(t[1], 6))))


def _keys(d: Drawing, flip=None) -> list | None:
    """Every piece of ``d`` as ``(kind, points, numbers)`` (a line's ends and an arc's
    ends sorted, so the direction a loop runs does not count), each point mirrored by
    ``flip`` when given; None when a piece is no line, arc or circle."""
    f = flip or (lambda p: p)
    out = []
    for c in d.circles:
        out.append(("C", (f(c.center),), (c.radius,)))
    for o in d.outlines:
        for s in o.segments:
            if isinstance(s, Line):
                out.append(("L", _ends(f(s.start), f(s.end)), ()))
            elif isinstance(s, Arc):
                mid = s.at(s.start_angle + s.sweep / 2)
                out.append(("A", (f(s.center), f(mid)) + _ends(f(s.start), f(s.end)),
                            (s.radius,)))
            elif isinstance(s, Circle):
                out.append(("C", (f(s.center),), (s.radius,)))
            else:
                return None
    return out


def _same(a: list, b: list) -> bool:
    """The pieces of ``a`` and ``b`` one for one within :data:`TOL` (matched by keys
    rounded to 1e-5 mm, then checked)."""
    if len(a) != len(b):
        return False
    from collections import defaultdict
    pool: dict = defaultdict(list)
    for k in b:
        pool[(k[0], round(k[1][0][0], 5), round(k[1][0][1], 5))].append(k)
    for k in a:
        cands = pool.get((k[0], round(k[1][0][0], 5), round(k[1][0][1], 5)), [])
        hit = next((i for i, c in enumerate(cands)
                    if len(c[1]) == len(k[1]) and
                    all(math.dist(p, q) <= TOL for p, q in zip(c[1], k[1])) and
                    all(abs(x - y) <= TOL for x, y in zip(c[2], k[2]))), None)
        if hit is None:
            return False
        cands.pop(hit)
    return True


def mirrored_pair(d: Drawing, deadline=None):
    """``(first part, (axis "x" or "y", its coordinate))`` when ``d`` is a part and its
    mirror image about a vertical or horizontal line (the module's docstring), else None.
    The first part is the one to the left (below)."""
    if d.paths or d.texts or d.ellipses or d.engrave is not None or \
            not 2 <= len(d.outlines) + len(d.circles) <= MAX_LOOPS:
        return None
    from ..write.program import _split_parts
    parts, loose = _split_parts(d, deadline)
    if len(parts) != 2 or (loose is not None and not loose.empty) or \
            any(p.paths or p.texts or p.ellipses or p.engrave is not None for p in parts):
        return None
    a, b = parts
    ba, bb = _box(a), _box(b)
    if ba is None or bb is None:
        return None
    if ba[0] > bb[0] or (ba[0] == bb[0] and ba[1] > bb[1]):
        a, b, ba, bb = b, a, bb, ba
    if sum(len(o.segments) for o in a.outlines) + len(a.circles) > MAX_PIECES:
        return None
    for axis in ("x", "y"):
        i = 0 if axis == "x" else 1
        c = (ba[i] + bb[i + 2]) / 2               # a's low side onto b's high side
        if abs((ba[i + 2] + bb[i]) / 2 - c) > TOL or \
                abs(ba[1 - i] - bb[1 - i]) > TOL or abs(ba[3 - i] - bb[3 - i]) > TOL:
            continue
        if axis == "x":
            def flip(p, c=c):
                return (2 * c - p[0], p[1])
        else:
            def flip(p, c=c):
                return (p[0], 2 * c - p[1])
        ka, kb = _keys(a, flip), _keys(b)
        if ka is not None and kb is not None and _same(ka, kb):
            return a, (axis, c)
    return None


def axis_line(axis: tuple, box: tuple) -> tuple:
    """The mirror line's two ends: ``axis`` ``("x", a)`` or ``("y", a)`` across ``box``
    (the whole drawing's ``(x0, y0, x1, y1)``)."""
    kind, c = axis
    if kind == "x":
        return (c, box[1]), (c, box[3])
    return (box[0], c), (box[2], c)



def pair_gap(first: Drawing, axis: tuple, params, stats) -> tuple | None:
    """The shift (program text per axis, as :func:`~.beside._beside` gives one) that places
    ``first``, the part drawn beside its mirror image about ``axis`` (``("x", a)``), from
    the mirror line by half a gap param (``gap``: between the part and its image, issue
    114: the gap was a literal mirror line), so a new gap moves both parts apart about the
    line; None when the part touches the line (no gap)."""
    from .params import _r
    k = 0 if axis[0] == "x" else 1
    box = first.box()
    if box is None:
        return None
    a = axis[1]
    near = box[k + 2] if abs(box[k + 2] - a) <= abs(box[k] - a) else box[k]
    if abs(a - near) <= TOL:
        return None
    g = params.add("gap", 2 * abs(a - near), "between the part and its mirror image")
    stats.readings.append(f"a part and its mirror image {_r(2 * abs(a - near))} apart: the "
                          f"gap a param, `{g}`, about the mirror line")
    term = f"({_r(a - near)} {'-' if near < a else '+'} {g} / 2)"
    return (term, None) if k == 0 else (None, term)


def write_pair(w, depth: int, name: str, first: Drawing, axis: tuple, box: tuple, word: str,
               solid) -> None:
    """``assembly NAME { solid WORD {...} ... WORD_mirror = Mirrored(WORD, about=axis) }``:
    the first part written by ``solid(depth, part name, drawing)`` (the inferred solid's
    writer), its mirror image made by ``Mirrored`` about a held construction line; an
    assembly, the two parts being apart (a solid of both would be ``W0504``)."""
    from ..write.writer import _pt
    inner = word if word != name else f"{word}_a"
    w.emit(depth, f"assembly {name} {{")
    solid(depth + 1, inner, first)
    w.emit(depth + 1, f"Fixed({inner})")
    p0, p1 = axis_line(axis, box)
    w.emit(depth + 1, f"axis = Line({_pt(p0)}, {_pt(p1)}, construction=true)   "
                      f"# the mirror line")
    w.emit(depth + 1, "Fixed(axis)")
    w.emit(depth + 1, f"{inner}_mirror = Mirrored({inner}, about=axis)")
    w.emit(depth, "}")


def pair_items(items: list, deadline=None) -> list:
    """``items`` (``(kind, name, drawing, ...)``, as :func:`~.infer.to_program_inferred`
    has them) with two solids in a row that are a part and its mirror image (a sheet of
    parts, ``--parts``) made one solid of both, which is then written as the part and
    ``Mirrored`` of it."""
    import os

    from ..write.writer import _ident
    used = {it[1] for it in items}
    out, i = [], 0
    while i < len(items):
        a = items[i]
        if i + 1 < len(items) and len(a) == 3 and len(items[i + 1]) == 3 and \
                a[0] == items[i + 1][0] == "solid":
            b = items[i + 1]
            both = Drawing(outlines=list(a[2].outlines) + list(b[2].outlines),
                           circles=list(a[2].circles) + list(b[2].circles), unit=a[2].unit,
                           paths_cut=a[2].paths_cut)
            if not (a[2].paths or b[2].paths or a[2].texts or b[2].texts or a[2].ellipses or
                    b[2].ellipses or a[2].engrave is not None or b[2].engrave is not None) \
                    and mirrored_pair(both, deadline) is not None:
                name = os.path.commonprefix([a[1], b[1]]).rstrip("_0123456789")
                used -= {a[1], b[1]}
                name = _ident(name if len(name) >= 2 and name != "l" else "part", used)
                out.append(("solid", name, both))
                i += 2
                continue
        out.append(a)
        i += 1
    return out
