"""``W0513``: engraved text drawn over other text (their boxes overlap), run into another
label (closer than half the text size: they read as one string), over an engraved mark (a
line, arc or circle that runs through the text's box), or with a mark too close to it (its
end nearer the strokes than :data:`TEXT_CLEAR` of the text size, any of it nearer than
:data:`SIDE_CLEAR`, or into the text's box): two protractor labels on each other, a label on
its tick mark, a clock's 12 o'clock tick between the "1" and the "2", a frame grazing a
label's letters."""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ....base.diagnostics import DiagnosticSink, Label
from ...part.build.booleans import Drawing
from ...part.measure.nearby import box_pairs, box_pairs_between
from ..common import MIN_AREA, _area, _pct
from .engravings import (_copy_label, _mark_segments, _open_ends, _pair_gap,
                         _polyline, _seg_gap, stroke_gap)
from .sampling import _COS32, _SIN32
from .allowed import text_allowed
from .overdrawn import MIN_CLEAR, check_marks_over_marks

TEXT_OVERLAP = 0.10     # of the smaller text's box: two labels overlapping more are on each other
TEXT_MARGIN = 0.10      # of a text's size: a mark this far inside the text's box does not count
TEXT_GAP = 0.5          # of the smaller text's size (about a word space): closer labels read as one
# A mark closer to a text's strokes than the letters of a word stand to each other (0.24 to
# 0.45 of the cap height in the futural font) reads as a stroke of the text: the clearance is a
# quarter of the text size, and at least MIN_CLEAR, about an engraved line's width with its burn
TEXT_CLEAR = 0.25       # of a text's size: a mark that ends (points) at the text
SIDE_CLEAR = 0.125      # of a text's size: a mark that runs past it (a frame, a circle)
IN_BOX = 0.1            # mm of a mark inside a text's box: it enters the text (between letters)


def _text_box(g, L) -> tuple:
    """The box of a text's pen strokes ``L`` (k x 2 x 2: each stroke's two ends) in the text's
    own frame (turned by its rotation): ``(polygon 4 x 2 in the model frame, rotation,
    (u0, v0, u1, v1))``."""
    P = L.reshape(-1, 2)
    rot = float(g.data.get("rotation", 0.0) or 0.0)
    c, s_ = math.cos(rot), math.sin(rot)
    u, v = P[:, 0] * c + P[:, 1] * s_, -P[:, 0] * s_ + P[:, 1] * c
    u0, v0, u1, v1 = u.min(), v.min(), u.max(), v.max()
    corners = np.array([(u0, v0), (u1, v0), (u1, v1), (u0, v1)])
    poly = np.column_stack([corners[:, 0] * c - corners[:, 1] * s_,
                            corners[:, 0] * s_ + corners[:, 1] * c])
    return poly, rot, (u0, v0, u1, v1)


def _length_inside(seg: tuple, rot: float, box) -> float:
    """The length (mm) of the segments ``seg`` (starts, ends: k x 2 each) inside ``box``
    (u0, v0, u1, v1) of the frame turned by ``rot``: :func:`_clipped` summed, after a box
    test (no segment's box meets the box: 0)."""
    a, b = seg
    c, s_ = math.cos(rot), math.sin(rot)
    x, y = a[:, 0] * c + a[:, 1] * s_, -a[:, 0] * s_ + a[:, 1] * c
    bx, by = b[:, 0] * c + b[:, 1] * s_, -b[:, 0] * s_ + b[:, 1] * c
    u0, v0, u1, v1 = box
    if not ((np.maximum(x, bx) >= u0) & (np.minimum(x, bx) <= u1) & (np.maximum(y, by) >= v0)
            & (np.minimum(y, by) <= v1)).any():
        return 0.0              # no segment's box meets the box: nothing inside (box test first)
    return float(_clipped(x, y, bx, by, u0, v0, u1, v1).sum())


def _clipped(x, y, bx, by, u0, v0, u1, v1) -> np.ndarray:
    """The length of each segment (x, y)-(bx, by) inside the box u0..u1 x v0..v1 (all in the
    box's frame; the bounds one for all or one per segment): Liang-Barsky clipping."""
    dx, dy = bx - x, by - y
    t0, t1 = np.zeros(len(x)), np.ones(len(x))
    for p_, q_ in ((-dx, x - u0), (dx, u1 - x), (-dy, y - v0), (dy, v1 - y)):
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            r = q_ / p_
        par = p_ == 0
        t1 = np.where(par & (q_ < 0), 0.0, t1)           # parallel and outside
        t0 = np.where(~par & (p_ < 0), np.maximum(t0, r), t0)
        t1 = np.where(~par & (p_ > 0), np.minimum(t1, r), t1)
    return np.clip(t1 - t0, 0.0, None) * np.hypot(dx, dy)


def _combos(pairs, a_off, a_len, b_off, b_len) -> tuple:
    """Every (row of A, row of B) of each pair ``(i, j)`` of ``pairs``, where set ``i`` of A
    holds rows ``a_off[i]`` to ``a_off[i] + a_len[i]`` (likewise B): ``(pair, row of A, row
    of B)``, three arrays of the sum over the pairs of ``a_len[i] * b_len[j]``."""
    i, j = pairs[:, 0], pairs[:, 1]
    na, nb = a_len[i], b_len[j]
    n = na * nb
    pair = np.repeat(np.arange(len(pairs)), n)
    local = np.arange(int(n.sum())) - np.repeat(np.cumsum(n) - n, n)
    return pair, a_off[i][pair] + local // nb[pair], b_off[j][pair] + local % nb[pair]


def _check_text_overlap(d: Drawing, sink: DiagnosticSink, tick=None) -> None:
    """W0513 for engraved text drawn over other text (their boxes, in each text's own frame,
    overlap by more than :data:`TEXT_OVERLAP` of the smaller) or over an engraved mark (a
    line, arc or circle that runs through the text's box, shrunk by :data:`TEXT_MARGIN` of the
    text's size, over more than a quarter of that size): two protractor labels on each other,
    a label on its tick mark.  Labels of two characters or more whose boxes come closer than
    :data:`TEXT_GAP` of their size run into each other (single letters are a word's letters
    laid out one by one, as ``text_on_arc`` does).  ``tick()``: called before each text's
    pairs are measured (the compile's deadline, which raises
    :class:`~aidl_lang.base.limits.OutOfBudget`)."""
    check_marks_over_marks(d, sink, tick)
    texts: dict = {}
    marks: dict = {}
    for style, item, g in d.strokes:
        if g is None or style == "cut":         # a through-cut is cut, not engraved
            continue
        if g.kind == "Text":
            texts.setdefault(g, []).append(item)
        else:
            marks.setdefault(g, []).append(item)
    if not texts:
        return
    tg = list(texts)
    strokes = [_text_strokes(texts[g]) for g in tg]      # each text's strokes: k x 2 x 2
    boxes = [_text_box(g, L) for g, L in zip(tg, strokes)]
    made: dict = {}

    def shape(k):             # a text's box as a CrossSection, made when a pair needs it
        if k not in made:
            made[k] = mf.CrossSection([boxes[k][0].tolist()])
        return made[k]
    bb = np.array([[b[0][:, 0].min(), b[0][:, 1].min(), b[0][:, 0].max(), b[0][:, 1].max()]
                   for b in boxes], dtype=float)
    said = set()
    close: dict = {}            # (span, span) -> [(gap, near, a, b)]: labels that run together
    sizes = [float(g.data.get("size", 0.0) or 0.0) or (b[2][3] - b[2][1])
             for g, b in zip(tg, boxes)]
    pad = TEXT_GAP * max(sizes) / 2
    for i, j in sorted(map(tuple, box_pairs(bb, pad))):
        if tick is not None:
            tick()
        a, b = tg[i], tg[j]
        if text_allowed(a, b):
            continue                            # `AllowOverlap(labels)`: close as meant
        if a.data.get("along") is not None or b.data.get("along") is not None:
            # along a curve, a text's straight box holds the curve's inside (run af's colour
            # wheel: 21 false alarms): how near their strokes come says it
            near = TEXT_GAP * min(sizes[i], sizes[j])
            gap = stroke_gap(strokes[i], strokes[j], bb[i], bb[j], near)
            word = min(len(str(g.data.get("text", "")).strip()) for g in (a, b)) > 1
            if gap < near and (word or gap <= 0) and a.span is not None and b not in said:
                said.add(b)
                close.setdefault((a.span, b.span), []).append((gap, near, a, b, "strokes"))
            continue
        common = _area(shape(i) ^ shape(j))
        small = min(_area(shape(i)), _area(shape(j)))
        if common <= max(MIN_AREA, TEXT_OVERLAP * small):
            gap = _quad_gap(boxes[i][0], boxes[j][0])
            near = TEXT_GAP * min(sizes[i], sizes[j])
            word = min(len(str(g.data.get("text", "")).strip()) for g in (a, b)) > 1
            # lines one above the other (a list of names, run bs: 29 false alarms at 10 mm
            # pitch) never read as one string: only lines that touch are said
            (ui0, _, ui1, _), (uj0, _, uj1, _) = boxes[i][2], boxes[j][2]
            lines = abs(boxes[i][1] - boxes[j][1]) < 1e-9 and min(ui1, uj1) > max(ui0, uj0)
            # corner to corner (no side of one box faces the other's): a dial's "25" and
            # "30" beside each other on a slant read apart (run et: 1.49 mm, said)
            diagonal = min(bb[i][2], bb[j][2]) < max(bb[i][0], bb[j][0]) \
                and min(bb[i][3], bb[j][3]) < max(bb[i][1], bb[j][1])
            if lines or diagonal:
                near = MIN_CLEAR
            # a figure whose box runs into a label's is said too (run dt: "0" of a map
            # scale into "1:50 000" below it, 0.25 mm over), single figures apart are not
            if gap < near and (word or common > MIN_AREA) and a.span is not None \
                    and b not in said:
                said.add(b)
                close.setdefault((a.span, b.span), []).append(
                    (gap, near, a, b, "lines" if lines else "boxes"))
            continue
        said.add(b)
        labels = [Label(a.span, f"`{a.label}` is here", primary=False)] if a.span else []
        sink.warning("W0513", f"text `{b.label}` (\"{b.data.get('text', '')}\") is drawn over "
                     f"text `{a.label}` (\"{a.data.get('text', '')}\"): their boxes overlap by "
                     f"{common:.2f} mm^2 ({_pct(common, small)} of the smaller)", b.span,
                     labels=labels,
                     hint=_apart(bb[i], bb[j], a, b, TEXT_GAP * min(sizes[i], sizes[j])))
    for found in close.values():
        gap, near, a, b, what = min(found, key=lambda f: f[0])
        more = f"; {len(found) - 1} more pairs of these labels as close" if len(found) > 1 else ""
        why = ("so the lines touch" if what == "lines" else
               "(half the text size), so they read as one string")
        sink.warning("W0513", f"text `{b.label}` (\"{b.data.get('text', '')}\") runs into "
                     f"text `{a.label}` (\"{a.data.get('text', '')}\"): their "
                     f"{'boxes' if what == 'lines' else what} are {gap:.2f} mm apart, less "
                     f"than {near:.2f} mm {why}{more}", b.span,
                     labels=[Label(a.span, f"`{a.label}` is here", primary=False)],
                     hint=f"leave at least {near:.2f} mm between them: space the labels "
                          "further apart (a larger radius or step), or make them smaller; if "
                          "they are laid out exactly as requested, say so: "
                          f"`AllowOverlap({_drawing_name(a, b)})`")
    if not marks:
        return
    # a text said to run into another is still said to lie over a mark (run bs: six names
    # under hearts were said only once the lines' false alarm was accepted)
    _check_marks(strokes, marks, tg, boxes, bb, sizes, set(), sink, tick)


def _drawing_name(a, b) -> str:
    """The name of the drawing holding both texts (for the hint's ``AllowOverlap``), from the
    structure it is written in; else the two texts'."""
    s = a.owner
    while s is not None and not (b.owner is s or b.owner.is_within(s)):
        s = s.parent
    if s is not None and s.kind == "drawing" and s.parent is not None:
        return s.name
    return f"{a.name or a.label}, {b.name or b.label}"


def _text_strokes(items) -> np.ndarray:
    """A text's strokes as segments (k x 2 x 2): the single-stroke font's lines, a font's
    outlines (issue 112) as the chords of their polylines."""
    if all(it[0] == "line" for it in items):
        return np.array([(it[1], it[2]) for it in items], dtype=float).reshape(-1, 2, 2)
    P = [_polyline(it) for it in items]
    return np.concatenate([np.stack([p[:-1], p[1:]], axis=1) for p in P if len(p) >= 2]
                          or [np.zeros((0, 2, 2))])


class _Segments:
    """Sets of segments in one array: ``a``, ``b`` (k x 2: each segment's ends), ``lo``,
    ``hi`` (k x 2: its box), and set ``i`` as rows ``off[i]`` to ``off[i] + n[i]``."""

    def __init__(self, sets):
        self.n = np.array([len(a) for a, _ in sets], dtype=np.intp)
        self.off = np.cumsum(self.n) - self.n
        self.a = np.concatenate([a for a, _ in sets]).reshape(-1, 2)
        self.b = np.concatenate([b for _, b in sets]).reshape(-1, 2)
        self.lo, self.hi = np.minimum(self.a, self.b), np.maximum(self.a, self.b)

    def boxes(self) -> np.ndarray:
        """Each set's box (x0, y0, x1, y1); a set of no segments gets an empty (inverted) box."""
        out = np.tile([np.inf, np.inf, -np.inf, -np.inf], (len(self.n), 1))
        has = self.n > 0
        if has.any():
            out[has, :2] = np.minimum.reduceat(self.lo, self.off[has], axis=0)
            out[has, 2:] = np.maximum.reduceat(self.hi, self.off[has], axis=0)
        return out


CHUNK = 1 << 20     # rows measured at once by the array passes below (about 100 MB at most)


def _chunks(pairs, rows, tick=None):
    """``pairs`` cut into runs of about :data:`CHUNK` ``rows`` (one figure per pair) each:
    ``(start, run)``; ``tick()`` before each run after the first."""
    ends = np.cumsum(rows)
    start = 0
    while start < len(pairs):
        stop = max(int(np.searchsorted(ends, (ends[start - 1] if start else 0) + CHUNK,
                                       side="right")), start + 1)
        if start and tick is not None:
            tick()
        yield start, pairs[start:stop]
        start = stop


def _inside_by_pair(pairs, rot, boxes, M: _Segments, tick=None) -> list:
    """For each pair ``(text i, mark j)`` and each of ``boxes`` (n x 4 each: u0, v0, u1, v1
    of each text in the frame turned by ``rot[i]``): the length (mm) of mark ``j``'s segments
    inside text ``i``'s box, all pairs in a few array operations (:func:`_clipped`)."""
    out = [np.zeros(len(pairs)) for _ in boxes]
    one = np.ones(len(rot), dtype=np.intp)
    for start, run in _chunks(pairs, M.n[pairs[:, 1]], tick):
        pair, _, row = _combos(run, np.arange(len(rot)), one, M.off, M.n)
        i = run[pair, 0]
        a, b = M.a[row], M.b[row]
        c, s_ = np.cos(rot[i]), np.sin(rot[i])
        x, y = a[:, 0] * c + a[:, 1] * s_, -a[:, 0] * s_ + a[:, 1] * c
        bx, by = b[:, 0] * c + b[:, 1] * s_, -b[:, 0] * s_ + b[:, 1] * c
        for k, box in enumerate(boxes):
            length = _clipped(x, y, bx, by, *box[i].T)
            out[k][start:start + len(run)] = np.bincount(pair, weights=length,
                                                         minlength=len(run))
    return out


def _segment_sets(marks, mg) -> dict:
    """:func:`~.engravings._mark_segments` of each mark of ``mg``: the marks that are one
    circle (rings, holes' outlines) taken together in one array operation (the same
    floating-point operations per point as :func:`~.engravings._sample`)."""
    out = {}
    circles = [m for m in mg if len(marks[m]) == 1 and marks[m][0][0] == "circle"]
    if circles:
        C = np.array([marks[m][0][1] for m in circles], dtype=float)
        R = np.array([float(marks[m][0][2]) for m in circles])[:, None]
        P = np.stack([C[:, :1] + R * _COS32, C[:, 1:] + R * _SIN32], axis=-1)   # n x 32 x 2
        Q = np.roll(P, -1, axis=1)
        out = {m: (P[k], Q[k]) for k, m in enumerate(circles)}
    return {m: out[m] if m in out else _mark_segments(marks[m]) for m in mg}


def _apart(bi, bj, a, b, near: float) -> str:
    """W0513's hint for text ``b`` drawn over text ``a`` (their boxes ``bi``, ``bj`` as x0,
    y0, x1, y1 in mm): the least of the four moves of ``b`` (right, left, up, down) that
    leaves ``near`` mm between the boxes (the gap under which two labels read as one
    string), rounded up to 0.01 mm.  Moved only by the overlap's depth (the hint of before,
    "at least 4.45 mm away"), the two touched and were warned again as running together
    (issue 84)."""
    moves = [(bi[2] - bj[0] + near, (1, 0), "right"), (bj[2] - bi[0] + near, (-1, 0), "left"),
             (bi[3] - bj[1] + near, (0, 1), "up"), (bj[3] - bi[1] + near, (0, -1), "down")]
    dist, (ux, uy), way = min(moves, key=lambda m: m[0])
    dist = math.ceil(dist * 100 - 1e-6) / 100
    return (f"move `{b.label}` {dist:.2f} mm {way}, by ({ux * dist + 0:.2f}, {uy * dist + 0:.2f}) "
            f"mm (clear of `{a.label}` and {near:.2f} mm apart, half the text size, so that "
            "the two do not read as one string), or make them smaller")


def _check_marks(strokes, marks, tg, boxes, bb, sizes, said, sink, tick=None) -> None:
    """W0513 for engraved marks against texts: a mark that runs through a text (below), then
    the marks that come too close (:func:`_check_clearance`).  Every text and mark whose
    boxes meet is measured in one array pass (:func:`_inside_by_pair`); only the pairs found
    are reported one by one."""
    mg = list(marks)
    segs = _segment_sets(marks, mg)
    M = _Segments(list(segs.values()))
    mb = M.boxes()
    n = len(tg)
    pairs = box_pairs_between(bb, mb)                   # (text, mark), in order
    rot = np.array([b[1] for b in boxes], dtype=float)
    full = np.array([b[2] for b in boxes], dtype=float)
    e = TEXT_MARGIN * np.array(sizes, dtype=float)
    inner = full + np.column_stack([e, e, -e, -e])
    through, inside = _inside_by_pair(pairs, rot, (inner, full), M, tick)
    for k, (i, j) in enumerate(pairs.tolist()):
        if tg[i] in said:
            continue
        if tick is not None:
            tick()
        g, m = tg[i], mg[j]
        if text_allowed(g, m):
            continue                            # `AllowOverlap(text, mark)`: as meant
        size = sizes[i]
        if inner[i, 0] >= inner[i, 2] or inner[i, 1] >= inner[i, 3]:
            continue
        length = float(through[k])
        if length <= max(0.2, 0.25 * size):
            continue
        if g.data.get("along") is not None and \
                _seg_gap(strokes[i][:, 0], strokes[i][:, 1], *segs[m])[0] > 0.005:
            continue        # its box is its arc's, not its letters' (run u's medal: a border
            #                 8 mm clear of "CITY RUN 2026" was said to cross "C" and "6")
        said.add(g)
        labels = [Label(m.span, f"`{m.label}` is here", primary=False)] if m.span else []
        at = _letters_crossed(g, strokes[i], segs[m], boxes[i][1], inner[i])
        at = f" at {at}" if at else ""
        if _is_tick(marks[m], boxes[i][1], full[i], size):     # a dial's tick mark
            sink.warning("W0513", f"text `{_copy_label(g)}` (\"{g.data.get('text', '')}\") is "
                         f"drawn over the engraved `{_copy_label(m)}`: the mark crosses it{at}, "
                         f"{length:.2f} mm of it inside the text's box", g.span, labels=labels,
                         hint=f"move `{g.label}` clear of `{m.label}` (beside a tick mark, not "
                              "on it: e.g. further out along the same direction), or shorten "
                              "the mark")
            continue
        fit = _fitting_size((strokes[i][:, 0], strokes[i][:, 1]), segs[m],
                            _open_ends(*segs[m]), boxes[i], size, g)
        ways = []
        if fit and fit < SHRINK_LEAST * size:
            fit = 0.0       # so small it no longer reads as the same text (run fh: 5 mm
            #                 numbers told `size=0.45 mm`): move it instead
        if fit:
            u0, _, u1, _ = boxes[i][2]
            w = math.floor((u1 - u0) * fit / size * 10) / 10
            ways.append(f"shrink it clear of the mark: `max_width={w:g} mm` in `{g.label.rsplit('.', 1)[-1]}` "
                        f"(it shrinks about its position point; it is {u1 - u0:.1f} mm wide), "
                        f"or `size={fit:g} mm`")
        ways.append(f"move `{g.label}` clear of `{m.label}`")
        if fit is None:                 # not measured (0.0: no smaller text clears the mark)
            ways.append("make the text smaller")
        sink.warning("W0513", f"text `{_copy_label(g)}` (\"{g.data.get('text', '')}\") is drawn "
                     f"over the engraved `{_copy_label(m)}`: `{m.label.rsplit('.', 1)[-1]}` crosses it{at}, "
                     f"{length:.2f} mm of it inside the text's box", g.span, labels=labels,
                     hint="; or ".join(ways))
    entering = {(i, j) for (i, j), x in zip(pairs.tolist(), inside)
                if x > IN_BOX - 1e-9 and tg[i].data.get("along") is None}
    _check_clearance(strokes, marks, tg, mg, boxes, bb, mb, sizes, said, segs,
                     M, entering, sink, tick)


# the least share of its size a text's shrink hint offers (W0513): smaller, it is another text
SHRINK_LEAST = 0.6


def _is_tick(items, rot: float, box, size: float) -> bool:
    """True for a mark that is one straight line with an end at the text (in its box, in the
    frame turned by ``rot``, grown by the text's ``size``): a dial's tick under its number,
    whose fix is to move the label beside it.  A line that runs through and past the text on
    both sides, a ring, an arc or an outline is not a tick (issue 105: a ring around a word was
    told "beside a tick mark")."""
    if len(items) != 1 or items[0][0] != "line":
        return False
    u0, v0, u1, v1 = box
    c, s_ = math.cos(rot), math.sin(rot)
    for p in (items[0][1], items[0][2]):
        u, v = p[0] * c + p[1] * s_, -p[0] * s_ + p[1] * c
        if u0 - size <= u <= u1 + size and v0 - size <= v <= v1 + size:
            return True
    return False


def _letters_crossed(g, L, mseg, rot: float, box) -> str:
    """The letters of text ``g`` (its strokes ``L``, k x 2 x 2, in the order of its font) at
    which the mark's segments ``mseg`` (starts, ends) run inside the box ``box`` (u0, v0, u1,
    v1 in the frame turned by ``rot``): each letter whose strokes span the u of a point of
    the mark inside the box (its segments' ends and midpoints), said as ``"S" and "F"``; ""
    when the strokes cannot be read as letters."""
    from .engravings import _letters_of, _say_letters
    text = str(g.data.get("text", ""))
    per = _letters_of(text, len(L))
    if per is None:
        return ""
    c, s_ = math.cos(rot), math.sin(rot)
    u0, v0, u1, v1 = box
    A, B = np.asarray(mseg[0], float), np.asarray(mseg[1], float)
    au, av = A[:, 0] * c + A[:, 1] * s_, -A[:, 0] * s_ + A[:, 1] * c
    bu, bv = B[:, 0] * c + B[:, 1] * s_, -B[:, 0] * s_ + B[:, 1] * c
    meet = ((np.maximum(au, bu) >= u0) & (np.minimum(au, bu) <= u1)
            & (np.maximum(av, bv) >= v0) & (np.minimum(av, bv) <= v1))
    # the segments whose box meets the text's, each at 65 points (a long line through the
    # whole word: its ends and middle alone named one letter)
    t = np.linspace(0.0, 1.0, 65)[None, :]
    u = (au[meet][:, None] + t * (bu - au)[meet][:, None]).ravel()
    v = (av[meet][:, None] + t * (bv - av)[meet][:, None]).ravel()
    u = u[(u >= u0) & (u <= u1) & (v >= v0) & (v <= v1)]
    if not len(u):
        return ""
    su = L[:, :, 0] * c + L[:, :, 1] * s_            # k x 2: the strokes' ends along the baseline
    per = np.asarray(per)
    spans = {i: (su[per == i].min(), su[per == i].max()) for i in set(per.tolist())}
    hit = set()
    for x in u:
        near = min(spans, key=lambda i: max(spans[i][0] - x, x - spans[i][1], 0.0))
        hit.add(near)
    if len(hit) > 2 and len(hit) == len(spans):
        return "every letter"
    return _say_letters(text, sorted(hit))


def _clear_of(tseg, mseg, rot, box, c: float, shift=(0.0, 0.0)) -> bool:
    """True when the mark's segments ``mseg`` (starts, ends), moved by ``-shift`` (the text
    moved by ``shift``), stay ``c`` mm from the text's strokes ``tseg`` and do not enter its
    box (``rot``, ``box`` as :func:`_text_box` gives; ``box`` None: not measured)."""
    a, b = mseg[0] - shift, mseg[1] - shift
    if _seg_gap(tseg[0], tseg[1], a, b)[0] < c:
        return False
    return box is None or _length_inside((a, b), rot, box) <= IN_BOX


def _least(ok, top: float) -> float | None:
    """The least ``x`` in [0, ``top``] (to 0.001 mm, rounded up to 0.01 mm) with ``ok(x)``,
    by bisection (the measures grow with ``x``: the reported figure is one that works); None
    when ``ok(top)`` fails."""
    if not ok(top):
        return None
    lo, hi = 0.0, top
    while hi - lo > 1e-3:
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if ok(mid) else (mid, hi)
    x = math.ceil(hi * 100 - 1e-9) / 100
    return x if ok(x) else hi


def _gap_below(tseg, lo, hi, q, c: float) -> float:
    """The distance from point ``q`` to the strokes ``tseg`` (starts, ends; their boxes
    ``lo``-``hi``) when it is below ``c``, else a figure of at least ``c`` (only the strokes
    whose boxes come within ``c`` of it are measured)."""
    near = np.flatnonzero((lo[:, 0] - c <= q[0]) & (hi[:, 0] + c >= q[0])
                          & (lo[:, 1] - c <= q[1]) & (hi[:, 1] + c >= q[1]))
    if not len(near):
        return math.inf
    return _seg_gap(tseg[0][near], tseg[1][near], q[None], q[None])[0]


def _near_pairs(strokes, pairs, bb, mb, clear, M: _Segments, tick=None) -> set:
    """The pairs ``(text i, mark j)`` of ``pairs`` with a stroke of text ``i`` (``strokes[i]``,
    k x 2 x 2) and a segment of mark ``j`` nearer than the text's clearance ``clear[i]`` (mm,
    to 1e-9): every stroke and segment whose boxes come that near, measured in one array pass
    (:func:`~.engravings._pair_gap`); the other pairs are farther apart."""
    if not len(pairs):
        return set()
    c = np.asarray(clear, dtype=float)
    i, j = pairs[:, 0], pairs[:, 1]
    ci = c[i]
    pairs = pairs[(bb[i, 0] - mb[j, 2] <= ci) & (mb[j, 0] - bb[i, 2] <= ci)
                  & (bb[i, 1] - mb[j, 3] <= ci) & (mb[j, 1] - bb[i, 3] <= ci)]
    T = _Segments([(L[:, 0], L[:, 1]) for L in strokes])
    near: set = set()
    for _, run in _chunks(pairs, T.n[pairs[:, 0]] * M.n[pairs[:, 1]], tick):
        pair, a, b = _combos(run, T.off, T.n, M.off, M.n)
        cp = c[run[pair, 0]]
        ok = ((T.lo[a, 0] - cp <= M.hi[b, 0]) & (T.hi[a, 0] + cp >= M.lo[b, 0])
              & (T.lo[a, 1] - cp <= M.hi[b, 1]) & (T.hi[a, 1] + cp >= M.lo[b, 1]))
        if not ok.any():
            continue
        pair, a, b, cp = pair[ok], a[ok], b[ok], cp[ok]
        d = _pair_gap(T.a[a], T.b[a], M.a[b], M.b[b])[0]
        near.update(map(tuple, run[pair[d < cp + 1e-9]].tolist()))
    return near


# mm: a mark this little nearer than the clearance is at it (run cl's astrolabe: ticks ended
# "1.00 mm" from the numerals for a clearance of 1.00 mm, the strokes' chords 0.004 mm nearer;
# the hint's "0.01 mm further" changed nothing a person sees)
AT_CLEAR = 0.01


def _check_clearance(strokes, marks, tg, mg, boxes, bb, mb, sizes, said, segs, M, entering,
                     sink, tick=None) -> None:
    """W0513 for an engraved mark that comes closer to a text's strokes than the text's
    clearance (:data:`TEXT_CLEAR` of its size, at least :data:`MIN_CLEAR`) or enters the
    text's box by more than :data:`IN_BOX` (between its letters: a clock's 12 o'clock tick
    into the "12"), without running through it: the two read as touching.  One warning per
    pair of statements (a loop of ticks against a loop of numerals), for the closest pair,
    naming the copies (``ticks[0]``), with the gap in mm, the other pairs, and the fix: how
    much shorter the mark (a straight line ending at the text) or how far the text must
    move.  Texts along a curve are measured by their strokes only (their box is not the
    text's).  Only the pairs that may be too close are measured one by one: those with a
    stroke and a segment nearer than the clearance (:func:`_near_pairs`) and ``entering``,
    the pairs whose mark is inside the text's box by more than :data:`IN_BOX`."""
    clear = [max(TEXT_CLEAR * s, MIN_CLEAR) for s in sizes]
    pairs = box_pairs_between(bb, mb, max(clear))
    maybe = entering | _near_pairs(strokes, pairs, bb, mb, clear, M, tick)
    tsegs: dict = {}
    ends_of: dict = {}          # a mark's open ends, taken once for all the texts near it
    found: dict = {}
    for i, j in pairs.tolist():
        if tg[i] in said or (i, j) not in maybe:
            continue
        if tick is not None:
            tick()
        g, m = tg[i], mg[j]
        if text_allowed(g, m):
            continue                            # `AllowOverlap(text, mark)`: close as meant
        c = clear[i]
        if (bb[i, 0] - mb[j, 2] > c or mb[j, 0] - bb[i, 2] > c
                or bb[i, 1] - mb[j, 3] > c or mb[j, 1] - bb[i, 3] > c):
            continue
        if g not in tsegs:
            tsegs[g] = (strokes[i][:, 0], strokes[i][:, 1])
        box = None if g.data.get("along") is not None else boxes[i][2]
        # box tests first: the boxes' gap is at most the strokes' gap, and a mark whose box
        # misses the text's box has no length inside it
        far = math.hypot(max(bb[i, 0] - mb[j, 2], mb[j, 0] - bb[i, 2], 0.0),
                         max(bb[i, 1] - mb[j, 3], mb[j, 1] - bb[i, 3], 0.0)) > c + 1e-9
        if far and box is None:
            continue
        apart = (bb[i, 0] > mb[j, 2] or mb[j, 0] > bb[i, 2]
                 or bb[i, 1] > mb[j, 3] or mb[j, 1] > bb[i, 3])
        inside = 0.0 if box is None or apart else _length_inside(segs[m], boxes[i][1], box)
        if far and inside <= IN_BOX:
            continue
        # the strokes and the mark's segments whose boxes come within c of one another: the
        # other pairs are farther apart than c
        lo, hi = np.minimum(*tsegs[g]), np.maximum(*tsegs[g])
        mlo, mhi = np.minimum(*segs[m]), np.maximum(*segs[m])
        near = ((lo[:, None, 0] - c <= mhi[None, :, 0]) & (hi[:, None, 0] + c >= mlo[None, :, 0])
                & (lo[:, None, 1] - c <= mhi[None, :, 1]) & (hi[:, None, 1] + c >= mlo[None, :, 1]))
        rows, cols = np.flatnonzero(near.any(axis=1)), np.flatnonzero(near.any(axis=0))
        if len(rows):
            gap, _, k, pt, pm = _seg_gap(tsegs[g][0][rows], tsegs[g][1][rows],
                                         segs[m][0][cols], segs[m][1][cols])
        if (not len(rows) or gap >= c - AT_CLEAR) and (box is None or inside <= IN_BOX):
            continue
        if len(rows) and gap < c:           # the same pair as among all of them
            k = int(cols[k])
        else:
            gap, _, k, pt, pm = _seg_gap(*tsegs[g], *segs[m])
        if m not in ends_of:
            ends_of[m] = _open_ends(*segs[m])
        ends = ends_of[m]
        head = min((_gap_below(tsegs[g], lo, hi, q, c) for q in ends), default=math.inf)
        side = max(SIDE_CLEAR * sizes[i], MIN_CLEAR)
        if head >= c - AT_CLEAR and gap >= side - AT_CLEAR and inside <= IN_BOX:
            continue
        cc = c if head < c or inside > IN_BOX else side
        found.setdefault((g.span, m.span), []).append((gap, -inside, i, g, m, k, pt, pm, cc))
    for pairs in found.values():
        pairs.sort(key=lambda f: (f[0], f[1], f[2]))
        gap, inside, i, g, m, k, pt, pm, c = pairs[0]
        side = max(SIDE_CLEAR * sizes[i], MIN_CLEAR)
        fix = [_fix(tsegs[f[3]], segs[f[4]], marks[f[4]], boxes[f[2]], f[3], f[5], f[6], f[7],
                    f[8], f[0]) for f in pairs]
        what = f"`{_copy_label(m)}`"
        text = f"text `{_copy_label(g)}` (\"{g.data.get('text', '')}\")"
        end = fix[0][0]
        if gap >= 0.005:
            how = f"{'ends' if end else 'comes'} {gap:.2f} mm from its strokes"
        elif end and _seg_gap(*tsegs[g], fix[0][3][None], fix[0][3][None])[0] < 0.005:
            how = "ends on its strokes"
        else:
            how = "crosses its strokes"
        # a length of the mark, not a depth (run ej: "enters its box by 11.45 mm" of a star
        # whose tips overlapped the word by 1.7 mm)
        into = f", {-inside:.2f} mm of the mark inside the text's box" if -inside > IN_BOX else ""
        more = ""
        if len(pairs) > 1:
            rest = ", ".join(f"`{_copy_label(f[4], short=True)}` and \"{f[3].data.get('text', '')}\" "
                             f"({f[0]:.2f} mm)" for f in pairs[1:4])
            more = (f"; {len(pairs) - 1} more pair{'s' if len(pairs) > 2 else ''} of these "
                    f"statements as close: {rest}{', ...' if len(pairs) > 4 else ''}")
        labels = [Label(m.span, f"`{m.label}` is here", primary=False)] if m.span else []
        shorten = [f[1] for f in fix]
        move = [f[2] for f in fix]
        ways = []
        if all(x is not None for x in shorten) and all(f[0] for f in fix):
            ways.append(f"shorten {'each' if len(pairs) > 1 else 'the'} mark to end "
                        f"{max(shorten):.2f} mm further from the text")
        frame = [f[4] for f in fix]
        framed = all(x is not None for x in frame)     # a ring or border around the word
        # a move that clears a frame by crossing it (run bn: a score moved 40 mm out of its
        # target's ring) is no fix; one inward, about the clearance missing, is; nor is one
        # longer than the text is tall (run bq: a token's number moved 11 mm, off its 22 mm
        # token, to clear a bar 0.25 mm too near)
        far = any(x is not None for x in move) and max(
            x for x in move if x is not None) > sizes[i]
        if all(x is not None for x in move) and not far and not (
                framed and max(move) > 2 * max(frame) + 0.01):
            along = "along the mark" if all(f[0] for f in fix) else "away from the mark"
            # which way, in the page's words and as a vector (a model read "further along
            # the mark" both ways, issue 111)
            way = fix[0][5]         # set wherever a move is (_fix)
            dx, dy = (round(max(move) * float(w), 2) + 0.0 for w in way)
            if all(float(np.hypot(*(f[5] - way))) < 1e-6 for f in fix):
                line = "along the mark's line" if along == "along the mark" else along
                ways.append(f"move the text {max(move):.2f} mm {_page_way(way)}, {line} "
                            f"(by ({dx:.2f}, {dy:.2f}) mm)")
            else:
                ways.append(f"move the text {max(move):.2f} mm further {along}")
        twin = _same_size_sibling(g, sizes[i], tg, sizes)
        if len(ways) == 2 and twin is not None:
            ways.reverse()          # a shorter mark than its sibling's: moving leads
        if framed:
            ways.append(f"grow `{m.label}` by {max(frame):.2f} mm on each side")
        fits = [_fitting_size(tsegs[f[3]], segs[f[4]], ends_of[f[4]], boxes[f[2]], sizes[f[2]],
                              f[3]) for f in pairs]
        smaller = ("" if twin is None else
                   f", smaller than `{_copy_label(twin)}` beside it at {sizes[i]:g} mm")
        if fits and all(x is not None and x > 0 for x in fits) and \
                min(fits) >= SHRINK_LEAST * sizes[i]:
            ways.append(f"make the text at most {min(fits):g} mm (size={min(fits):g} mm"
                        f"{smaller})")
        elif not any(x == 0.0 or x is not None and x < SHRINK_LEAST * sizes[i]
                     for x in fits):      # 0: no smaller size clears the mark
            ways.append("make the text smaller" + (f" ({smaller[2:]})" if smaller else ""))
        if not any(w.startswith("move the text") for w in ways) and not framed:
            ways.insert(0, "move the text or the mark clear of each other")   # (run ag: only
            #                 "make the text smaller", which shrinks a size the request gave)
        sink.warning("W0513", f"{text} is too close to the engraved {what}: the mark {how}"
                     f"{into} (the clearance is {c:.2f} mm, {'a quarter' if c > side else 'an eighth'}"
                     f" of the text size{' for a mark beside it' if c <= side else ''}), so "
                     f"they read as touching{more}", g.span, labels=labels,
                     hint=f"leave {c:.2f} mm between the text and `{m.label}`: "
                          + ", or ".join(ways))


def _page_way(way) -> str:
    """A unit vector in the page's words: "left", "up", "left and up" (x right, y up)."""
    x = "right" if way[0] > 1e-6 else "left" if way[0] < -1e-6 else ""
    y = "up" if way[1] > 1e-6 else "down" if way[1] < -1e-6 else ""
    return " and ".join(w for w in (x, y) if w)


def _same_size_sibling(g, size: float, tg: list, sizes: list):
    """Another text statement of ``g``'s structure at the same size (a "NAME" label beside
    "PHONE"), or None: shrinking ``g`` alone to clear a mark would set it apart from it
    (issue 111's luggage tag), so moving it leads W0513's hint."""
    owner = getattr(g, "owner", None)
    for k, t in enumerate(tg):
        if (t is not g and t.span != g.span and getattr(t, "owner", None) is owner
                and abs(sizes[k] - size) <= 1e-9 * max(1.0, size)):
            return t
    return None


def _fitting_size(tseg, mseg, ends, box3, size: float, g) -> float | None:
    """The largest text size (mm, rounded down to 0.01 mm) at which text ``g`` (its strokes
    ``tseg``: starts, ends; its box ``box3`` as :func:`_text_box` gives; its ``size``) is
    clear of the mark (its segments ``mseg``, its open ``ends``) as :func:`_check_clearance`
    measures it: the strokes, the box and the clearance (:data:`TEXT_CLEAR` and
    :data:`SIDE_CLEAR` of the size, at least :data:`MIN_CLEAR`) all scale with the size about
    the text's position point (:func:`...geometry.text.text_strokes`), so the scale that
    holds is found by bisection (to 1e-4 of the size).  None (not measured) for a text along
    a curve or a text whose strokes are not its font's at its position (placed by a
    transform); 0.0 when no size down to a twentieth of it clears the mark (the mark runs
    through the position, or ends nearer it than :data:`MIN_CLEAR`: no smaller text helps)."""
    from ....geometry.shapes.text import text_strokes
    if g.data.get("along") is not None or not size > 0 or g.data.get("text") is None:
        return None
    if g.data.get("font") is not None:
        # a font's outlines (issue 112): their chords scale about the position point, found
        # from the glyphs' true box about it (a chord lies within CHORD_TOL of its curve);
        # a size that max_width shrank is not the `size=` a hint can give
        ext = g.data.get("extent")
        if ext is None or g.data.get("shrunk") or not len(tseg[0]):
            return None
        pts = np.concatenate([tseg[0], tseg[1]])
        p = np.array([pts[:, 0].min() - ext[0], pts[:, 1].min() - ext[2]])
    else:
        own = np.asarray(text_strokes(g.data["text"], size, g.data.get("anchor", "middle"),
                                      g.data.get("valign", "baseline"),
                                      g.data.get("rotation", 0.0) or 0.0), dtype=float)
        if own.shape != (len(tseg[0]), 2, 2):
            return None
        p = tseg[0][0] - own[0, 0]
        if not (np.allclose(tseg[0] - p, own[:, 0], atol=1e-6)
                and np.allclose(tseg[1] - p, own[:, 1], atol=1e-6)):
            return None
    rot, box = box3[1], box3[2]
    c_, s_ = math.cos(rot), math.sin(rot)
    pu, pv = p[0] * c_ + p[1] * s_, -p[0] * s_ + p[1] * c_

    def ok(f):
        a, b = p + f * (tseg[0] - p), p + f * (tseg[1] - p)
        bx = (pu + f * (box[0] - pu), pv + f * (box[1] - pv), pu + f * (box[2] - pu),
              pv + f * (box[3] - pv))
        clear = max(TEXT_CLEAR * size * f, MIN_CLEAR)
        side = max(SIDE_CLEAR * size * f, MIN_CLEAR)
        if _length_inside(mseg, rot, bx) > IN_BOX:
            return False
        gap = _seg_gap(a, b, mseg[0], mseg[1])[0]
        if gap >= clear:
            return True
        if gap < side:
            return False
        return all(_seg_gap(a, b, q[None], q[None])[0] >= clear for q in ends)
    lo, hi = 0.05, 1.0
    if not ok(lo):
        return 0.0
    while hi - lo > 1e-4:
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if ok(mid) else (lo, mid)
    n = math.floor(lo * size * 100 + 1e-9) / 100
    while n > 0 and not ok(n / size):
        n = round(n - 0.01, 2)
    return max(n, 0.0)


def _fix(tseg, mseg, items, box3, g, k, pt, pm, c: float, gap: float) -> tuple:
    """How to clear a text of a mark: ``(ends, shorten, move, end, frame, way)``.  ``ends``: the mark is one
    straight line whose end is its point nearest the text; ``shorten``: by how much (mm) that
    end must come back along the line (None when no shortening clears it, or not a line);
    ``move``: how far (mm) the text must move, along the line past that end (a line) or
    straight away from the mark's nearest point ``pm`` (else), None when no move within
    three text boxes clears it; ``end``: the line's end nearest the text (else ``pm``);
    ``frame``: when the mark is a closed outline around the text (a frame), by how much (mm)
    to grow it on each side (the clearance less the ``gap``), else None; ``way``: the unit
    vector the text moves along (None with ``move``)."""
    rot, box = box3[1], (None if g.data.get("along") is not None else box3[2])
    ends, u, shorten, q = False, None, None, np.asarray(pm, float)
    if len(items) == 1 and items[0][0] == "line":
        p, q = np.asarray(items[0][1], float), np.asarray(items[0][2], float)
        if _seg_gap(*tseg, p[None], p[None])[0] < _seg_gap(*tseg, q[None], q[None])[0]:
            p, q = q, p                                  # q: the end nearest the text
        length = float(np.hypot(*(q - p)))
        if length > 0:
            u = (q - p) / length
            ends = float(np.hypot(*(pm - q))) < 1e-6 or float(np.hypot(*(pt - pm))) < 1e-9

            def short(t):
                e = q - t * u
                return _clear_of(tseg, (p[None], e[None]), rot, box, c)
            shorten = _least(short, length * (1 - 1e-9))
            if not ends:
                u = None
    if u is None:
        v = np.asarray(pt, float) - np.asarray(pm, float)
        nv = float(np.hypot(*v))
        if nv < 1e-9:
            return ends, shorten, None, q, None, None
        u = v / nv
    size = float(g.data.get("size", 0.0) or 0.0) or 1.0
    move = _least(lambda s: _clear_of(tseg, mseg, rot, box, c, s * u), 3 * size + c)
    frame = None
    if len(items) == 1 and items[0][0] in ("poly", "circle"):       # a frame around the text
        from ..common import _edges, _inside
        ring = _polyline(items[0])
        if bool(_inside(np.vstack([tseg[0], tseg[1]]), _edges([ring[:-1]])).all()):
            frame = math.ceil((c - gap) * 100 - 1e-9) / 100
    return ends, shorten, move, q, frame, u


def _quad_gap(p, q) -> float:
    """The distance (mm) between two convex quadrilaterals ``p``, ``q`` (4 x 2, in order):
    0 when they overlap, else the least distance of a corner of one to an edge of the other."""
    def inside(pt, poly):
        e = np.roll(poly, -1, axis=0) - poly
        w = pt - poly
        cross = e[:, 0] * w[:, 1] - e[:, 1] * w[:, 0]
        return bool((cross >= 0).all() or (cross <= 0).all())
    if any(inside(pt, q) for pt in p) or any(inside(pt, p) for pt in q):
        return 0.0
    best = math.inf
    for a, b in ((p, q), (q, p)):
        s0, s1 = b, np.roll(b, -1, axis=0)
        d = s1 - s0
        for pt in a:
            # a zero-length edge (a glyph box squeezed to a line) is its end point: t = 0
            t = np.clip(((pt - s0) * d).sum(1) / np.maximum((d * d).sum(1), 1e-300), 0.0, 1.0)
            best = min(best, float(np.hypot(*(s0 + t[:, None] * d - pt).T).min()))
    return best
