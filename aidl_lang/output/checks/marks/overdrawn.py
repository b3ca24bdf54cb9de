"""``W0513`` for engraved marks drawn over each other on one part (:func:`check_marks_over_marks`):
a stroke burnt twice, or a pattern of open marks run into an outline.  Text against text and
marks is :mod:`.text`'s."""
from __future__ import annotations

import math

import numpy as np

from ....base.diagnostics import Diagnostic, DiagnosticSink, Label
from ...part.build.booleans import Drawing
from ..common import _pct
from .allowed import text_allowed
from .engravings import _copy_label, _mark_segments, _polyline, _seg_gap

MIN_CLEAR = 0.3         # mm: the least clearance between two engraved marks (a text's too)


OVERDRAWN_TOL = 0.05    # mm: two parallel strokes this close are one line burnt twice
OVERDRAWN_LEAST = MIN_CLEAR   # mm of one stroke along another: less is a touch, not a double burn
PARALLEL = math.sin(math.radians(1.0))    # the sine under which two strokes run parallel
INTO_LEAST = 3          # marks of one statement that end inside one outline they cross: a defect
CENTRED = 0.75          # a mark whose ends lie this near as far from the line it crosses is centred on it


def _closed(item) -> bool:
    return item[0] in ("poly", "circle")


def check_marks_over_marks(d: Drawing, sink: DiagnosticSink, tick=None) -> None:
    """W0513 for engraved marks (not text: :func:`_check_text_overlap` measures text) drawn
    over each other on one solid part (a drawing beside the parts, at assembly level, is an
    illustration and is not compared), one warning per pair of statements (copies made in a loop named by index,
    with the number of such pairs):

    * burnt twice: a stroke of one mark lies on a stroke of another (parallel within 1 degree,
      within :data:`OVERDRAWN_TOL`) over at least :data:`OVERDRAWN_LEAST` (a ruler's
      centimetre ticks drawn over its millimetre ticks, a border along a line): always a
      defect, the laser burns that stretch twice (a deeper, wider line);
    * drawn into an outline: open marks (lines, arcs) of one statement that cross a closed
      engraved outline of another statement and end inside it, :data:`INTO_LEAST` or more
      into one outline (a ruler's ticks running into the outlined bars of its centimetre
      scale).  What a maker means is left alone: one or two marks that cross into an outline
      (a dial's finger stop across its rim, a guitar's strings into its rosette), strokes that
      cross and go on (a grid, a crosshair through a target's rings), a mark that ends on an
      outline (within :data:`OVERDRAWN_TOL`: drawn to it), a mark centred across an outline's
      line (its ends within :data:`CENTRED` of as far from it: a dial's ticks across its
      ring), a mark wholly inside one (a clock's hands in its dial), outlines that cross (a
      Venn diagram).  The hint gives how far to
      move the outline's statement, along the marks, for the marks to stay
      :data:`MIN_CLEAR` from it.

    The segment pairs come from one box search (:func:`..part.nearby.box_pairs`), O(n log n)
    in the segments but for the pairs it finds."""
    found, items_of = _marks_over_marks(d, tick)
    for key, rows in found.items():
        if tick is not None:
            tick()
        rows = [r for r in rows if not text_allowed(r[1], r[2])]   # `AllowOverlap`: as meant
        if not rows:
            continue
        if key[0] == "into":
            # a pattern of marks run into one outline (a scale's ticks into a bar drawn over
            # them); one or two marks that cross into an outline are read as meant (a dial's
            # finger stop across its rim, a guitar's strings into its rosette)
            per: dict = {}
            for r in rows:
                per.setdefault(id(r[2]), set()).add(id(r[1]))
            if max(len(v) for v in per.values()) < INTO_LEAST:
                continue
        if key[0] == "twice":
            rows.sort(key=lambda r: -r[0])
            L, a, b, share = rows[0]
            more = (f"; {len(rows) - 1} more pair{'s' if len(rows) > 2 else ''} of these "
                    "statements on each other") if len(rows) > 1 else ""
            whole = " (all of it)" if share > 0.999 else f" ({_pct(share, 1.0)} of it)"
            # a line along a filled area's edge: its fill is burnt there too, the edge a
            # little darker, which makers draw on purpose (runs fr, fv: a flag's outline and
            # its pole on the filled flag; run bv's pole called it a slip): a note
            edge = bool(a.data.get("fill")) != bool(b.data.get("fill"))
            sink.add(Diagnostic(
                "W0513", f"the engraved `{_copy_label(b)}` lies on the engraved "
                f"`{_copy_label(a)}` over {L:.2f} mm{whole}: the laser burns that stretch "
                + ("twice, the line over the fill's edge (a darker edge)" if edge else
                   "twice (a deeper, wider line)") + more, b.span, "note" if edge else "warning",
                labels=[Label(a.span, f"`{a.label}` is here", primary=False)],
                hint=_twice_hint(a, b, share, rows)))
            continue
        p_g, q_g = rows[0][1], rows[0][2]
        count = len(rows)
        fix = _clearing_move([g for g in items_of if g.span == key[1]],
                             [g for g in items_of if g.span == key[2]], items_of, rows)
        how = (f"move `{q_g.name or q_g.label}` {fix[0]:.2f} mm (by ({fix[1]:.2f}, "
               f"{fix[2]:.2f}) mm) so that the marks stay {MIN_CLEAR:g} mm clear of it, or "
               if fix is not None else "move the outline clear of the marks, or ")
        sink.warning(
            "W0513", f"the engraved `{_copy_label(p_g)}` runs into the engraved outline "
            f"`{_copy_label(q_g)}` and ends inside it"
            + (f" ({count} such marks of these statements)" if count > 1 else "")
            + ": engraving drawn over engraving, the marks cross the outline's line",
            p_g.span, labels=[Label(q_g.span, f"`{q_g.label}` is here", primary=False)],
            hint=f"{how}end the marks on the outline or before it (a mark that crosses an "
                 "outline and goes on, as a grid's lines do, is not warned)")


def _marks_over_marks(d: Drawing, tick=None) -> tuple[dict, dict]:
    """What :func:`check_marks_over_marks` reports, found: ``(found, items_of)``, the pairs of
    statements keyed ``("twice", span, span)`` (strokes on strokes: ``[(length, over, under,
    share)]``) or ``("into", span, span)`` (open marks ending inside an outline: ``[(gap,
    mark, outline, end inside, end outside)]``), and each engraved geometry's stroke items."""
    from ...part.measure.nearby import box_pairs
    from ..common import _edges, _inside, _part_of, _part_roots
    roots = _part_roots(d)
    items_of: dict = {}
    part_of: dict = {}
    for style, item, g in d.strokes:
        if g is None or style == "cut" or g.kind == "Text":
            continue
        if g not in part_of:
            part = _part_of(g.owner, roots)
            part_of[g] = part if part is not None and part.kind == "solid" else None
        if part_of[g] is not None:          # engraved on a part (not an illustration)
            items_of.setdefault(g, []).append(item)
    if len(items_of) < 2:
        return {}, items_of
    marks = list(items_of)
    home = np.array([id(part_of[g]) for g in marks])
    segs, owner, closed, curved = [], [], [], []
    for k, g in enumerate(marks):
        for it in items_of[g]:
            P = _polyline(it)
            if len(P) < 2:
                continue
            segs.append(np.stack([P[:-1], P[1:]], axis=1))
            owner.append(np.full(len(P) - 1, k))
            closed.append(np.full(len(P) - 1, _closed(it)))
            curved.append(np.full(len(P) - 1, it[0] in ("arc", "circle")))
    if not segs:
        return {}, items_of
    S = np.concatenate(segs)
    own = np.concatenate(owner)
    curve = np.concatenate(curved)
    A, B = S[:, 0], S[:, 1]
    lo, hi = np.minimum(A, B), np.maximum(A, B)
    if tick is not None:
        tick()
    pairs = box_pairs(np.column_stack([lo, hi]), OVERDRAWN_TOL)
    if len(pairs):
        # (two arcs' or circles' samples: compared exactly, by :func:`_arcs_on_arcs`)
        pairs = pairs[(own[pairs[:, 0]] != own[pairs[:, 1]])
                      & (home[own[pairs[:, 0]]] == home[own[pairs[:, 1]]])
                      & ~(curve[pairs[:, 0]] & curve[pairs[:, 1]])]
    found: dict = {}        # (span, span) -> [(length, a, b)]
    length: dict = _arcs_on_arcs(marks, items_of, home)
    if len(pairs) or length:
        i, j = pairs[:, 0], pairs[:, 1]
        da, db = B[i] - A[i], B[j] - A[j]
        la, lb = np.hypot(*da.T), np.hypot(*db.T)
        ok = (la > 1e-9) & (lb > 1e-9)
        i, j, da, db, la, lb = i[ok], j[ok], da[ok], db[ok], la[ok], lb[ok]
        cross = np.abs(da[:, 0] * db[:, 1] - da[:, 1] * db[:, 0])
        u = da / la[:, None]
        off0 = np.abs(u[:, 0] * (A[j] - A[i])[:, 1] - u[:, 1] * (A[j] - A[i])[:, 0])
        off1 = np.abs(u[:, 0] * (B[j] - A[i])[:, 1] - u[:, 1] * (B[j] - A[i])[:, 0])
        t0 = np.einsum("ij,ij->i", A[j] - A[i], u)
        t1 = np.einsum("ij,ij->i", B[j] - A[i], u)
        over = np.minimum(la, np.maximum(t0, t1)) - np.maximum(0.0, np.minimum(t0, t1))
        on = (cross <= PARALLEL * la * lb) & (off0 <= OVERDRAWN_TOL) & (off1 <= OVERDRAWN_TOL) \
            & (over >= OVERDRAWN_LEAST)
        for a, b, L in zip(own[i[on]].tolist(), own[j[on]].tolist(), over[on].tolist()):
            key = (min(a, b), max(a, b))
            length[key] = length.get(key, 0.0) + L
        total = np.bincount(own, weights=np.hypot(*(B - A).T), minlength=len(marks))
        for (a, b), L in length.items():
            ga, gb = marks[a], marks[b]
            if ga.span is None or gb.span is None:
                continue
            if ga.data.get("fill") and gb.data.get("fill"):
                continue        # two areas engraved filled that share an edge: each burnt
                #                 once up to it (run ep's hydrant marker, run bz's pines:
                #                 "twice"); a stroke along a filled area's edge is burnt
                #                 over it, deeper (run bv's flag pole on its pennant): said
            # the one more of whose strokes lies on the other is the one drawn again
            under, over_g = (ga, gb) if L / max(total[a], 1e-12) >= L / max(total[b], 1e-12) \
                else (gb, ga)
            share = min(1.0, L / max(total[a if under is ga else b], 1e-12))
            key = ("twice", under.span, over_g.span)
            found.setdefault(key, []).append((L, over_g, under, share))
    # open marks that cross a closed outline of another mark and end inside it
    if tick is not None:
        tick()
    boxes = np.full((len(marks), 4), np.inf)       # each mark's box (one pass over segments)
    boxes[:, 2:] = -np.inf
    for c in range(2):
        np.minimum.at(boxes[:, c], own, lo[:, c])
        np.maximum.at(boxes[:, 2 + c], own, hi[:, c])
    keep = np.isfinite(boxes).all(axis=1)
    boxes[~keep] = 0.0
    # (a filled area draws no outline for marks to run into: run ft's fretboard, strings
    # ended on the filled nut, "runs into the outline", its hint opening a gap)
    rings = {k: [_polyline(it)[:-1] for it in items_of[g] if _closed(it)]
             if not g.data.get("fill") else []
             for k, g in enumerate(marks)}
    ring_edges: dict = {}
    for a, b in box_pairs(boxes, OVERDRAWN_TOL).tolist():
        if home[a] != home[b] or not (keep[a] and keep[b]):
            continue
        for p, q in ((a, b), (b, a)):
            if not rings[q] or marks[p].span is None or marks[q].span is None:
                continue
            opens = [_polyline(it) for it in items_of[marks[p]] if not _closed(it)]
            if not opens:
                continue
            if q not in ring_edges:
                ring_edges[q] = (_edges(rings[q]), np.concatenate(rings[q]),
                                 np.concatenate([np.roll(R, -1, axis=0) for R in rings[q]]))
            edges, E0, E1 = ring_edges[q]
            circles = [it for it in items_of[marks[q]] if it[0] == "circle"]
            exact = len(circles) == len(rings[q])   # rings that are circles: measured exactly
            for P in opens:
                ends = np.array([P[0], P[-1]])
                if exact:   # (a 32-gon's chords lie 0.35 mm in at r 72: run u's ticks drawn
                    # to a dial's rim ended "inside" it between the polygon's corners)
                    dist = [np.hypot(*(ends - np.asarray(c, float)).T) - r for _, c, r in circles]
                    inside = np.sum([dd < 0 for dd in dist], axis=0) % 2 == 1
                    gaps = list(np.min(np.abs(dist), axis=0))
                else:
                    inside = _inside(ends, edges)
                    gaps = None
                if inside[0] == inside[1]:
                    continue
                if gaps is None:
                    gaps = [_seg_gap(E0, E1, e[None], e[None])[0] for e in ends]
                if min(gaps) <= OVERDRAWN_TOL:
                    continue            # drawn to the outline: meant
                if min(gaps) >= CENTRED * max(gaps):
                    continue            # across the line, as far in as out: a dial's ticks
                    #                     across its ring (run hj: 3 mm each side of r 120)
                into = ends[1] if inside[1] else ends[0]
                out_end = ends[0] if inside[1] else ends[1]
                key = ("into", marks[p].span, marks[q].span)
                found.setdefault(key, []).append((min(gaps), marks[p], marks[q], into, out_end))
    return found, items_of


def _arcs_on_arcs(marks: list, items_of: dict, home) -> dict:
    """Arcs and circles of two marks on one part that lie on each other, compared exactly:
    the same centre and radius within :data:`OVERDRAWN_TOL`, the length of their common
    angle (at least :data:`OVERDRAWN_LEAST`), ``{(mark index, mark index): mm}`` (run fe's
    roulette wheel: a circle of r 110 on each of 16 sectors' inner arcs, unsaid: the two
    curves' samples are not parallel chords).  Hashed by centre and radius in cells of the
    tolerance (each item against its cell and the 26 around it): near-linear."""
    cell = OVERDRAWN_TOL
    grid: dict = {}
    rows = []
    for k, g in enumerate(marks):
        for c, r, a1, a2, loop in _curves(items_of[g]):
            c = np.asarray(c, dtype=float)
            lo, span = (min(a1, a2), abs(a2 - a1)) if abs(a2 - a1) < 2 * math.pi - 1e-12 \
                else (0.0, 2 * math.pi)
            key = (round(c[0] / cell), round(c[1] / cell), round(r / cell))
            rows.append((k, c, r, lo % (2 * math.pi), span, key, loop))
            grid.setdefault(key, []).append(len(rows) - 1)
    out: dict = {}
    for n, (k, c, r, lo, span, key, loop) in enumerate(rows):
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dr in (-1, 0, 1):
                    for m in grid.get((key[0] + dx, key[1] + dy, key[2] + dr), ()):
                        k2, c2, r2, lo2, span2, _, loop2 = rows[m]
                        if m <= n or k2 == k or home[k2] != home[k] or abs(r2 - r) > cell \
                                or np.hypot(*(c2 - c)) > cell or loop and loop2:
                            continue    # (two outlines' arcs: sampled alike, the chords say)
                        common = _common_angle(lo, span, lo2, span2)
                        if common * r >= OVERDRAWN_LEAST:
                            pair = (min(k, k2), max(k, k2))
                            out[pair] = out.get(pair, 0.0) + common * r
    return out


def _curves(items) -> list:
    """The circular curves of a mark's engraving items, ``(centre, radius, angle from, angle
    to, of an outline)`` (radians; a circle 0 to 2 pi): its arcs and circles, and those of an
    outline's exact loop (a Sector's two arcs; ``True`` last)."""
    from ....geometry.shapes.curves import Arc, Circle
    out = []
    for it in items:
        if it[0] == "arc":
            out.append((it[1], float(it[2]), float(it[3]), float(it[4]), False))
        elif it[0] == "circle":
            out.append((it[1], float(it[2]), 0.0, 2 * math.pi, False))
        elif it[0] == "poly" and len(it) > 2 and hasattr(it[2], "segments"):
            for s in it[2].segments:
                if isinstance(s, Arc):
                    out.append((s.center, float(s.radius), float(s.start_angle),
                                float(s.start_angle + s.sweep), True))
                elif isinstance(s, Circle):
                    out.append((s.center, float(s.radius), 0.0, 2 * math.pi, True))
    return out


def _common_angle(lo1: float, s1: float, lo2: float, s2: float) -> float:
    """The angle (radians) two arcs of one circle share: each from ``lo`` (0 to 2 pi)
    counter-clockwise through ``s``."""
    tau = 2 * math.pi
    if s1 >= tau - 1e-12 or s2 >= tau - 1e-12:
        return min(s1, s2)
    total = 0.0
    for shift in (-tau, 0.0, tau):
        a, b = max(lo1, lo2 + shift), min(lo1 + s1, lo2 + shift + s2)
        total += max(0.0, b - a)
    return min(total, s1, s2)


def _clearing_move(A_marks, B_marks, items_of, rows):
    """How far to move the outlines ``B_marks`` (every copy of one statement) along the
    marks that run into them (the mean direction from each mark's outer end to its end
    inside, ``rows``) for every stroke of ``A_marks`` to stay :data:`MIN_CLEAR` from every
    stroke of them: ``(distance, dx, dy)`` mm (the least on a 0.25 mm scan, then bisected to
    0.01 mm and rounded up), or None (no move within the two sets' extent clears them, or too
    many strokes to measure)."""
    u = np.sum([r[3] - r[4] for r in rows], axis=0)
    nu = float(np.hypot(*u))
    if nu < 1e-9:
        return None
    u = u / nu
    a0, a1 = zip(*[_mark_segments(items_of[g]) for g in A_marks])
    b0, b1 = zip(*[_mark_segments(items_of[g]) for g in B_marks])
    a0, a1, b0, b1 = map(np.concatenate, (a0, a1, b0, b1))
    if len(a0) * len(b0) > 400_000:
        return None
    ext = lambda P: float(np.ptp(P @ u)) if len(P) else 0.0     # noqa: E731
    top = ext(np.vstack([a0, a1])) + ext(np.vstack([b0, b1])) + 2 * MIN_CLEAR

    def clear(s):
        return _seg_gap(a0, a1, b0 + s * u, b1 + s * u)[0] >= MIN_CLEAR
    s, step = 0.0, 0.25
    while s <= top and not clear(s):
        s += step
    if s > top:
        return None
    lo, hi = max(0.0, s - step), s
    while hi - lo > 1e-3:
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if clear(mid) else (mid, hi)
    m = math.ceil(hi * 100 - 1e-9) / 100
    if not clear(m):
        m = hi
    return m, float(u[0] * m), float(u[1] * m)


CLOSED_KINDS = ("Triangle", "Rectangle", "Polygon", "RegularPolygon", "RoundedRectangle")


def _twice_hint(a, b, share: float, rows) -> str:
    """W0513's hint for ``b`` lying on ``a`` (``share`` of ``b``'s length; ``rows`` the pairs
    of the two statements): skip the copies of ``b``'s loop that lie on ``a`` only where
    some copies do not (run eg's backgammon board: all 24 points' bases on the border, and
    "skip those copies" would have deleted every point); a closed shape with a side on the
    other is drawn without that side."""
    copies = [h for h in getattr(b.owner, "geometry", ()) if h.name == b.name
              and h.span == b.span and not h.data.get("fill")] \
        if b.name and b.span is not None else [b]           # (a filled copy is not judged)
    on = {id(r[2]) for r in rows}
    ways = []
    if b.data.get("fill") and not a.data.get("fill") and not copies:
        # a filled area cannot lose a side (a Polyline is open, E0108: run fr's dive slate,
        # a flag's filled fields on its outline): the outline is the one to redraw (unless
        # the statement has open copies too: run eg's backgammon points, alternately filled)
        a, b = b, a
        share = 0.0
        copies = [b]
    circle = a if a.kind == "Circle" else b if b.kind == "Circle" else None
    if circle is not None and (b if circle is a else a).kind != "Circle":
        # a ring drawn over the arcs of shapes set round it (run fe: a circle of r 110 on
        # every pocket's inner arc): the shapes draw it where they stand
        other = b if circle is a else a
        return (f"draw each stroke once: leave the Circle `{circle.label}` out where "
                f"`{other.label}` draws its arc (`Arc`s between them, or none if they go all "
                "round), or move one of them clear")
    same = a.span is not None and a.span == b.span       # two copies of one statement
    if b.kind in CLOSED_KINDS and share < 0.999 and same:
        # two copies of one loop's shape side by side (run hd's timescale: "draw
        # `plaque.eons.e` without the side that lies on `plaque.eons.e`")
        ways.append(f"draw the copies of `{b.label}` without the sides they share: one "
                    f"outline round them all and a `Line` at each boundary")
    elif b.kind in CLOSED_KINDS and share < 0.999:
        ways.append(f"draw `{_copy_label(b)}` without the side that lies on "
                    f"`{_copy_label(a)}` (a `Polyline` through its other corners)")
    if 1 < len(copies) and len(on) < len(copies) and not same:
        ways.append(f"leave out the copies of `{b.label}`'s loop that lie on `{a.label}`")
    elif not ways:
        ways.append(f"leave `{b.label}` out where `{a.label}` already runs")
    return "draw each stroke once: " + ", or ".join(ways) + ", or move one of them clear"
