"""``W0513``: engraved text drawn over other text (their boxes overlap), run into another
label (closer than half the text size: they read as one string) or over an engraved mark (a
line, arc or circle that runs through the text's box): two protractor labels on each other, a
label on its tick mark."""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ...diagnostics import DiagnosticSink, Label
from ..booleans import Drawing
from ..nearby import box_pairs
from .common import MIN_AREA, _area, _depth, _pct
from .engravings import _sample, _samples

TEXT_OVERLAP = 0.10     # of the smaller text's box: two labels overlapping more are on each other
TEXT_MARGIN = 0.10      # of a text's size: a mark this far inside the text's box does not count
TEXT_GAP = 0.5          # of the smaller text's size (about a word space): closer labels read as one


def _text_box(g, items) -> tuple:
    """The box of a text's pen strokes in the text's own frame (turned by its rotation):
    ``(polygon 4 x 2 in the model frame, rotation, (u0, v0, u1, v1))``."""
    P = np.concatenate([np.array([it[1], it[2]], dtype=float) for it in items])
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
    (u0, v0, u1, v1) of the frame turned by ``rot``: each clipped exactly (Liang-Barsky), all
    in one array operation."""
    a, b = seg
    c, s_ = math.cos(rot), math.sin(rot)
    x, y = a[:, 0] * c + a[:, 1] * s_, -a[:, 0] * s_ + a[:, 1] * c
    dx, dy = b[:, 0] * c + b[:, 1] * s_ - x, -b[:, 0] * s_ + b[:, 1] * c - y
    u0, v0, u1, v1 = box
    t0, t1 = np.zeros(len(x)), np.ones(len(x))
    for p_, q_ in ((-dx, x - u0), (dx, u1 - x), (-dy, y - v0), (dy, v1 - y)):
        with np.errstate(divide="ignore", invalid="ignore"):
            r = q_ / p_
        par = p_ == 0
        t1 = np.where(par & (q_ < 0), 0.0, t1)           # parallel and outside
        t0 = np.where(~par & (p_ < 0), np.maximum(t0, r), t0)
        t1 = np.where(~par & (p_ > 0), np.minimum(t1, r), t1)
    return float((np.clip(t1 - t0, 0.0, None) * np.hypot(dx, dy)).sum())


def _mark_segments(items) -> tuple:
    """The segments of an engraved mark's ``items`` as (starts, ends), k x 2 each: lines
    exact, curves as the polylines of their W0505 samples."""
    a, b = [], []
    for it in items:
        P = _polyline(it)
        a.append(P[:-1])
        b.append(P[1:])
    return np.concatenate(a), np.concatenate(b)


def _check_text_overlap(d: Drawing, sink: DiagnosticSink) -> None:
    """W0513 for engraved text drawn over other text (their boxes, in each text's own frame,
    overlap by more than :data:`TEXT_OVERLAP` of the smaller) or over an engraved mark (a
    line, arc or circle that runs through the text's box, shrunk by :data:`TEXT_MARGIN` of the
    text's size, over more than a quarter of that size): two protractor labels on each other,
    a label on its tick mark.  Labels of two characters or more whose boxes come closer than
    :data:`TEXT_GAP` of their size run into each other (single letters are a word's letters
    laid out one by one, as ``text_on_arc`` does)."""
    texts: dict = {}
    marks: dict = {}
    for style, item, g in d.strokes:
        if g is None:
            continue
        if g.kind == "Text":
            texts.setdefault(g, []).append(item)
        else:
            marks.setdefault(g, []).append(item)
    if not texts:
        return
    tg = list(texts)
    boxes = [_text_box(g, texts[g]) for g in tg]
    shapes = [mf.CrossSection([b[0].tolist()]) for b in boxes]
    bb = np.array([[b[0][:, 0].min(), b[0][:, 1].min(), b[0][:, 0].max(), b[0][:, 1].max()]
                   for b in boxes], dtype=float)
    said = set()
    close: dict = {}            # (span, span) -> [(gap, near, a, b)]: labels that run together
    sizes = [float(g.data.get("size", 0.0) or 0.0) or (b[2][3] - b[2][1])
             for g, b in zip(tg, boxes)]
    pad = TEXT_GAP * max(sizes) / 2
    for i, j in sorted(map(tuple, box_pairs(bb, pad))):
        common = _area(shapes[i] ^ shapes[j])
        small = min(_area(shapes[i]), _area(shapes[j]))
        a, b = tg[i], tg[j]
        if common <= max(MIN_AREA, TEXT_OVERLAP * small):
            gap = _quad_gap(boxes[i][0], boxes[j][0])
            near = TEXT_GAP * min(sizes[i], sizes[j])
            word = min(len(str(g.data.get("text", "")).strip()) for g in (a, b)) > 1
            if gap < near and word and a.span is not None and b not in said:
                said.add(b)
                close.setdefault((a.span, b.span), []).append((gap, near, a, b))
            continue
        said.add(b)
        depth = _depth(shapes[i] ^ shapes[j], bb[i], bb[j])
        labels = [Label(a.span, f"`{a.label}` is here", primary=False)] if a.span else []
        sink.warning("W0513", f"text `{b.label}` (\"{b.data.get('text', '')}\") is drawn over "
                     f"text `{a.label}` (\"{a.data.get('text', '')}\"): their boxes overlap by "
                     f"{common:.2f} mm^2 ({_pct(common, small)} of the smaller)", b.span,
                     labels=labels,
                     hint=f"move `{b.label}` at least {depth:.2f} mm away from `{a.label}` (or "
                          "make them smaller) so that both can be read")
    for found in close.values():
        gap, near, a, b = min(found, key=lambda f: f[0])
        more = f"; {len(found) - 1} more pairs of these labels as close" if len(found) > 1 else ""
        sink.warning("W0513", f"text `{b.label}` (\"{b.data.get('text', '')}\") runs into "
                     f"text `{a.label}` (\"{a.data.get('text', '')}\"): their boxes are "
                     f"{gap:.2f} mm apart, less than {near:.2f} mm (half the text size), so "
                     f"they read as one string{more}", b.span,
                     labels=[Label(a.span, f"`{a.label}` is here", primary=False)],
                     hint=f"leave at least {near:.2f} mm between them: space the labels "
                          "further apart (a larger radius or step), or make them smaller")
    if not marks:
        return
    mg = list(marks)
    mpts = [_samples(marks[g]) for g in mg]
    mb = np.array([[p[:, 0].min(), p[:, 1].min(), p[:, 0].max(), p[:, 1].max()] for p in mpts],
                  dtype=float)
    n = len(tg)
    segs: dict = {}
    pairs = box_pairs(np.vstack([bb, mb]))
    for i, j in sorted(map(tuple, pairs)):
        if not (i < n <= j) or tg[i] in said:
            continue
        g, m = tg[i], mg[j - n]
        size = float(g.data.get("size", 0.0) or 0.0) or (boxes[i][2][3] - boxes[i][2][1])
        u0, v0, u1, v1 = boxes[i][2]
        e = TEXT_MARGIN * size
        inner = (u0 + e, v0 + e, u1 - e, v1 - e)
        if inner[0] >= inner[2] or inner[1] >= inner[3]:
            continue
        if m not in segs:
            segs[m] = _mark_segments(marks[m])
        length = _length_inside(segs[m], boxes[i][1], inner)
        if length <= max(0.2, 0.25 * size):
            continue
        said.add(g)
        labels = [Label(m.span, f"`{m.label}` is here", primary=False)] if m.span else []
        sink.warning("W0513", f"text `{g.label}` (\"{g.data.get('text', '')}\") is drawn over "
                     f"the engraved `{m.label}`: it runs {length:.2f} mm through the text",
                     g.span, labels=labels,
                     hint=f"move `{g.label}` clear of `{m.label}` (beside a tick mark, not on "
                          "it: e.g. further out along the same direction), or shorten the mark")


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
            t = np.clip(((pt - s0) * d).sum(1) / (d * d).sum(1), 0.0, 1.0)
            best = min(best, float(np.hypot(*(s0 + t[:, None] * d - pt).T).min()))
    return best


def _polyline(item) -> np.ndarray:
    """An engraving item as a polyline (lines exact, curves sampled as in W0505)."""
    if item[0] == "line":
        return np.array([item[1], item[2]], dtype=float)
    if item[0] == "poly":
        P = np.asarray(item[1], dtype=float)
        return np.vstack([P, P[:1]])
    if item[0] == "circle":
        P = _sample(item)
        return np.vstack([P, P[:1]])
    return _sample(item)
