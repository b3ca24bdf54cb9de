"""The engraving of an inferred part (``aidl import --infer``): a line of text in the
built-in font as the ``Text`` it is, ticks in rows or round a centre as loops, recognised
shapes, polylines, else exact chains; texts placed by the caller's ``place`` (a label with the
feature it names)."""
from __future__ import annotations

import math

from ....geometry.shapes.curves import Line
from ...model import Drawing, Note
from ...write.writer import _Writer, _emit_holds, _holds, _num, _pt, _string
from ..params import _center, _ctor, _deg, _plus, _r
from ..patterns.find import _periodic, _tick_families
from ..shapes import ROUND_TOL, circular, recognise
from .text import along_texts, stroke_texts


def _write_family(w: _Writer, depth: int, f, k: int) -> str:
    """One family of ticks as a loop; returns the stroke's name."""
    nm = f"tick{k}"
    lens = f[-1]
    per = _periodic(lens)
    n = len(lens)
    L = _r(per[0]) if len(per) == 1 else \
        "[" + ", ".join(_r(x) for x in per) + f"][i % {len(per)}]"
    w.emit(depth, f"for i in range({n}) {{")
    w.emit(depth + 1, f"L = {L}")
    if f[0] == "row":
        _, p0, d, u, _ = f
        x = _plus(p0[0], f"i * {_num(d[0], ROUND_TOL / n)}") if abs(d[0]) > ROUND_TOL \
            else _r(p0[0])
        y = _plus(p0[1], f"i * {_num(d[1], ROUND_TOL / n)}") if abs(d[1]) > ROUND_TOL \
            else _r(p0[1])
        w.emit(depth + 1, f"x = {x}")
        w.emit(depth + 1, f"y = {y}")

        def off(c, uc):
            if abs(uc) <= 1e-15:
                return c
            if abs(uc - 1) <= 1e-15:
                return f"{c} + L"
            if abs(uc + 1) <= 1e-15:
                return f"{c} - L"
            return f"{c} + {_num(uc, 0)} * L"
        w.emit(depth + 1, f"{nm} = Line((x, y), ({off('x', u[0])}, {off('y', u[1])}))")
    else:
        _, C, R, a0, st, sign, _ = f
        c = _center(C)
        turn = f"i * {_num(math.degrees(st), 1e-10)} deg"
        w.emit(depth + 1, f"a = {_deg(a0)} + {turn}" if abs(a0) > 1e-15 else f"a = {turn}")
        w.emit(depth + 1, f"{nm} = Line(polar({c}, {_r(R)}, a), polar({c}, "
                          f"{_r(R)} {'-' if sign < 0 else '+'} L, a))")
    w.emit(depth + 1, f"Fixed({nm})")
    w.emit(depth, "}")
    return nm


def _engraving(w: _Writer, depth: int, d: Drawing, stats, place=None) -> None:
    """Every loop, path, ellipse and text of ``d`` (and its engraved shapes) as strokes:
    a line of text in the built-in font (all its loops and paths of lines) as the ``Text``
    it is, at any turn (:func:`~.text.stroke_texts`), recognised shapes, ``Polygon``/``Polyline``
    for runs of lines, else exact chains.  ``place``: a text's position as written (a
    label placed with the feature it names: :func:`~.infer._solid`), a function of the
    position and the text's height; None: where the drawing puts it."""
    if place is None:
        def place(p, size):
            return _pt(p)
    k = 0
    held: list[str] = []        # rigid shapes, held where the file put them
    parts = [d] + ([d.engrave] if getattr(d, "engrave", None) is not None else [])
    for dd in parts:
        skip: set = set()
        lined = [o for o in list(dd.outlines) + list(dd.paths)
                 if all(isinstance(g, Line) for g in o.segments)]
        found = stroke_texts([[(g.start, g.end) for g in o.segments] for o in lined]) \
            if len(lined) <= 2000 else []
        for text, pos, size, deg, whole in found:
            k += 1
            turn = f", rotation={_num(deg)} deg" if deg else ""
            w.emit(depth, f"t{k} = Text({_string(text)}, position={place(pos, size)}, "
                          f"size={_num(size)}, anchor=\"start\", valign=\"baseline\"{turn})")
            stats.patterns["stroke text"] += 1
            held.append(f"t{k}")
            skip |= {id(lined[i]) for i in whole}
        rings: dict = {}
        for text, (c, r), deg, size, whole in along_texts(
                [[(g.start, g.end) for g in o.segments] for o in lined],
                {i for *_, wh in found for i in wh}) if len(lined) <= 2000 else []:
            key = (round(c[0], 6), round(c[1], 6), round(r, 6))
            if key not in rings:
                rings[key] = f"ring{len(rings) + 1}"
                w.emit(depth, f"{rings[key]} = Circle(center={_pt(c)}, radius={_num(r)}, "
                              f"construction=true)")
                held.append(rings[key])
            k += 1
            w.emit(depth, f"t{k} = Text({_string(text)}, along={rings[key]}, angle={_num(deg)} "
                          f"deg, size={_num(size)})")
            stats.patterns["stroke text"] += 1
            skip |= {id(lined[i]) for i in whole}
        for j, segs in enumerate([circular(o.segments) for o in dd.outlines
                                  if id(o) not in skip] + [[c] for c in dd.circles]):
            if w.deadline is not None and j % 128 == 0:
                w.deadline.check("recognising the engraved shapes")
            k += 1
            sh = recognise(segs)
            if sh is not None:
                stats.kinds[sh.kind] += 1
                w.emit(depth, f"g{k} = {_ctor(sh, _center(sh.center))}")
                held.append(f"g{k}")
            elif w.chain(depth, segs, True, f"g{k}_"):
                held += _holds(segs, f"g{k}_")
        for cx, cy, rx, ry, rot in dd.ellipses:
            k += 1
            w.emit(depth, f"g{k} = Ellipse(center={_pt((cx, cy))}, rx={_num(rx)}, "
                          f"ry={_num(ry)}, rotation={_num(math.degrees(rot))} deg)")
            held.append(f"g{k}")
        if w.deadline is not None:
            w.deadline.check("finding the engraved ticks")
        strokes = [p for p in dd.paths if len(p.segments) == 1 and id(p) not in skip and
                   isinstance(p.segments[0], Line)]
        fams, used = _tick_families([(p.segments[0].start, p.segments[0].end)
                                     for p in strokes])
        done = {id(strokes[i]) for i in used}
        for f in fams:
            k += 1
            _write_family(w, depth, f, k)
            stats.patterns["ticks in a row" if f[0] == "row" else "ticks round a centre"] += 1
        for j, p in enumerate(dd.paths):
            if w.deadline is not None and j % 128 == 0:
                w.deadline.check("writing the engraved paths")
            if id(p) in done or id(p) in skip:
                continue
            k += 1
            closed = math.dist(p.start, p.end) <= 1e-6 and p.crossing is not None
            if all(isinstance(s, Line) for s in p.segments):
                pts = [p.segments[0].start] + [s.end for s in p.segments]
                w.emit(depth, f"g{k} = Polyline([{', '.join(_pt(q) for q in pts)}])")
                held.append(f"g{k}")
            elif w.chain(depth, p.segments, closed, f"g{k}_"):
                held += _holds(p.segments, f"g{k}_", closed)
            else:
                w.notes.append(Note("W0130", "an engraved path holds a piece no statement "
                                             "writes: left out"))
        for i, (text, (x, y), h, rot, anchor, valign) in enumerate(dd.texts):
            deg = round(math.degrees(rot), 9)
            rot_txt = f", rotation={_num(deg)} deg" if deg else ""
            k += 1
            w.emit(depth, f"t{k} = Text({_string(text)}, position={place((x, y), h)}, "
                          f"size={_num(h)}, anchor=\"{anchor}\", valign=\"{valign}\"{rot_txt})")
            held.append(f"t{k}")
    _emit_holds(w, depth, held, "g")
