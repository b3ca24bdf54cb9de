"""``W0512``: the faces one statement draws several times (in a loop) that overlap or touch
(:func:`_check_repeated_faces`), and two circles of one hole written apart that overlap
(:func:`_check_overlapping_circles`): fewer openings than the program draws.
"""
from __future__ import annotations

import math

import numpy as np

from ....base.diagnostics import DiagnosticSink, Label
from ....geometry.core.model import Structure
from ...part.build.booleans import Drawing
from ...part.measure.nearby import box_pairs
from ..common import MIN_AREA, MIN_WALL, _area, _depth, _insert_fix, _union
from .openings import TOUCH, _ref


MERGES_COUNTED = 200    # W0512: pairs of copies measured before "at least N such pairs"


def _check_repeated_faces(d: Drawing, h: Structure, sink: DiagnosticSink,
                          tick=lambda: None) -> None:
    """W0512 for hole ``h``: the faces one statement draws several times (in a loop) that
    overlap or touch, so they cut fewer openings than the statement draws (a drill gauge of
    ten holes with nine openings).  Faces of different statements (a keyhole's circle and
    slot) are one opening by design and are not compared.  ``tick()``: before each pair's
    boolean (the deadline).  Past :data:`MERGES_COUNTED` merging pairs, one of them deeper
    than a wall (so the hint's fix is decided), the rest are not measured and the count is
    "at least": n concentric copies are n^2/2 pairs (1,000: 500,000 booleans, past the
    family's share, so no W0512 at all but a W0521 note)."""
    by_stmt: dict = {}
    # the material the hole cuts: copies that overlap only off it (run dw: three scallops,
    # circles of R85 whose overlaps lie in the air above the rim) cut separate openings
    before = next((c.before for c in d.cuts if c.hole is h and c.before is not None), None)
    for g, f in d.own.get(h, []):
        if g.span is not None and f is not None and not f.is_empty():
            by_stmt.setdefault(g.span, []).append((g, f))
    for span, faces in by_stmt.items():
        if len(faces) < 2:
            continue
        shapes = [f for _, f in faces]
        boxes = np.array([f.bounds() for f in shapes], dtype=float)
        merges, deep, cut_short = [], False, False
        for i, j in box_pairs(boxes, pad=TOUCH / 2).tolist():     # (rows sorted)
            if _allowed_pair(h, faces[i][0], faces[j][0]):
                continue                               # AllowOverlap(c): one opening, meant
            if len(merges) >= MERGES_COUNTED and deep:
                cut_short = True                       # the rest: "at least N"
                break
            tick()
            common = shapes[i] ^ shapes[j]
            runs = before is not None and (faces[i][0].data.get("overrun")
                                           or faces[j][0].data.get("overrun"))
            if runs:
                common = common ^ before             # (an overrun runs past the edge)
            a = _area(common)
            if a > 1e-9:
                merges.append((i, j, _depth(common, boxes[i], boxes[j]), a))
                deep = deep or merges[-1][2] >= MIN_WALL
            elif runs and len(((shapes[i] + shapes[j]) ^ before).decompose()) > 1:
                continue                               # apart where they cut the material
            elif (shapes[i] + shapes[j]).num_contour() < 2:
                merges.append((i, j, 0.0, 0.0))        # they touch: one contour
        if not merges:
            continue
        # pieces, not contours: five petals round a ring are one opening with an island (run
        # bw: "cuts 2 openings")
        united = _union(shapes)
        openings = len((united ^ before if before is not None else united).decompose())
        i, j, depth, a = merges[0]
        g = faces[0][0]
        how = (f"copies {i + 1} and {j + 1} overlap by {depth:.2f} mm ({a:.2f} mm^2 in common)"
               if a > 0 else f"copies {i + 1} and {j + 1} touch")
        more = (f" (at least {len(merges)} such pairs)" if cut_short else
                f" ({len(merges)} such pairs)" if len(merges) > 1 else "")
        # a pattern's copies by their list, which holds the original too (run bw: the hint's
        # `AllowOverlap(petal)`, one shape, was refused; `petals` is what takes them)
        ref = next((_ref(f, h) for f, _ in faces if f.name and f.name.endswith("]")),
                   _ref(g, h))
        stmt = f"AllowOverlap({ref})" if ref != "self" else None
        meant = (f", or say so: write `{stmt}` in `{h.path}`" if stmt else "")
        # copies that all graze (overlap by less than a wall, or only touch) were meant apart:
        # the fix a tool applies is not the AllowOverlap that would hide the slip (issue 84)
        grazed = max(m[2] for m in merges) < MIN_WALL
        sink.warning("W0512", f"`{g.label}` of hole `{h.path}` is drawn {len(faces)} times but "
                     f"cuts {openings} opening{'s' if openings != 1 else ''}: {how}{more}",
                     span,
                     hint=f"space the copies at least {depth + MIN_WALL:.2f} mm further apart "
                          "(or make them smaller) so that material is left between them; if one "
                          f"opening is meant, draw it as one shape (a Slot, a Polygon){meant}",
                     fix=_insert_fix(h, stmt, sink) if stmt and not grazed else None)


def _check_overlapping_circles(d: Drawing, h: Structure, sink: DiagnosticSink,
                               t: float = MIN_WALL, tick=lambda: None) -> None:
    """W0512 for hole ``h``: two circles drawn by DIFFERENT statements of the hole that
    overlap partly (neither inside the other), so the hole cuts one opening where the program
    draws two round holes (a drill gauge whose circles are written one by one, two of them
    too close).  Only circles are compared: other faces of one hole overlap by design (a
    keyhole's circle and slot, a cross of two rectangles), and a figure-eight of two circles
    is drawn as a Slot when it is meant.  The copies of one statement are
    :func:`_check_repeated_faces`'s.  The pairs come from :func:`.nearby.box_pairs`;
    ``tick()`` is called before each pair's boolean (the deadline)."""
    faces = [(g, f) for g, f in d.own.get(h, [])
             if g.kind == "Circle" and f is not None and not f.is_empty()]
    if len(faces) < 2:
        return
    shapes = [f for _, f in faces]
    others = [f for g, f in d.own.get(h, [])
              if g.kind != "Circle" and f is not None and not f.is_empty()]
    boxes = np.array([f.bounds() for f in shapes], dtype=float)
    areas = [_area(f) for f in shapes]
    merges = []
    # copies of one statement are W0512 above: their pairs left out at once (1,000 copies of
    # one circle are 500,000 pairs, one Python step each)
    stmt: dict = {}
    of = np.array([stmt.setdefault(g.span, len(stmt)) for g, _ in faces], dtype=np.intp)
    pairs = box_pairs(boxes)
    for i, j in pairs[of[pairs[:, 0]] != of[pairs[:, 1]]].tolist():      # (rows sorted)
        if _allowed_pair(h, faces[i][0], faces[j][0]):
            continue                                   # AllowOverlap(a, b): one opening, meant
        tick()
        common = shapes[i] ^ shapes[j]
        a = _area(common)
        if a <= MIN_AREA or a >= (1 - 1e-6) * min(areas[i], areas[j]):
            continue                                   # apart, or one inside the other
        if _in_figure(others, shapes[i], shapes[j], tick):
            continue                                   # one figure with another shape: meant
        if _notch(boxes[i], boxes[j]):
            continue                                   # a thumb notch on a pocket's rim: meant
        merges.append((i, j, _depth(common, boxes[i], boxes[j]), a))
    if not merges:
        return
    i, j, depth, a = merges[0]
    (gi, _), (gj, _) = faces[i], faces[j]
    openings = _union(shapes).num_contour()
    more = f"; {len(merges) - 1} more such pair{'s' if len(merges) > 2 else ''}" \
        if len(merges) > 1 else ""
    labels = [Label(gi.span, f"`{gi.label}` is here", primary=False)] if gi.span else []
    refs = list(dict.fromkeys(_ref(faces[k][0], h) for m in merges for k in m[:2]))
    stmt = f"AllowOverlap({', '.join(refs)})" if "self" not in refs else None
    meant = (f", or say so: write `{stmt}` in `{h.path}` (a scalloped bite)" if stmt else "")
    sink.warning("W0512", f"circles `{gj.label}` and `{gi.label}` of hole `{h.path}` overlap "
                 f"by {depth:.2f} mm ({a:.2f} mm^2 in common), so they cut one opening: the "
                 f"hole draws {len(faces)} circles but cuts {openings} "
                 f"opening{'s' if openings != 1 else ''}{more}", gj.span or h.span,
                 labels=labels,
                 hint=f"move `{gj.label}` {depth + t:.2f} mm further from `{gi.label}` (or make "
                      "one smaller) so that material is left between them; if one opening is "
                      f"meant, draw it as one shape (a Slot){meant}",
                 fix=_insert_fix(h, stmt, sink) if stmt and max(m[2] for m in merges) >= t
                 else None)


def _notch(a, b) -> bool:
    """Circles of boxes ``a`` and ``b`` (x0, y0, x1, y1) are a notch on a round opening's rim:
    the smaller at most 0.6 the larger's radius, its centre within half its own radius of
    the larger's rim (run em's clay dies: a 10 mm thumb notch centred on each 25.6 mm
    pocket's rim, drawn in the pocket's hole, was "two circles that cut one opening", and
    the hint moved the notch off the pocket).  A drill gauge's circles too close are near
    one size, or their centres well inside each other (a pitch's unit slip): still said."""
    (ax, ay, ra), (bx, by, rb) = ((float(x0 + x1) / 2, float(y0 + y1) / 2, float(x1 - x0) / 2)
                                  for x0, y0, x1, y1 in (a, b))
    small, big = sorted((ra, rb))
    d = math.hypot(ax - bx, ay - by)
    return small <= 0.6 * big and abs(d - big) <= 0.5 * small


def _in_figure(others: list, a, b, tick) -> bool:
    """Circles ``a`` and ``b`` both overlap one of the hole's other shapes ``others``: they
    are pieces of one figure with it, one opening by design (a bone-shaped window: a bar and
    two overlapping circles at each end, issue 111's dog-treat box; a drill gauge's two
    circles too close overlap nothing else)."""
    for f in others:
        fb, ab, bb = f.bounds(), a.bounds(), b.bounds()
        if any(fb[0] > q[2] or q[0] > fb[2] or fb[1] > q[3] or q[1] > fb[3] for q in (ab, bb)):
            continue
        tick()
        if _area(f ^ a) > MIN_AREA and _area(f ^ b) > MIN_AREA:
            return True
    return False


def _allowed_pair(h: Structure, a, b) -> bool:
    """``AllowOverlap`` written in hole ``h`` names both of its shapes ``a`` and ``b`` (or
    lists holding them): the one opening they cut is meant (W0512)."""
    ok = getattr(h, "overlap_ok", None)
    return bool(ok) and a in ok and b in ok
