"""Maker drawings with a known design (issue 85: "measure it on drawings nobody tuned to").

A :class:`Design` is what a maker means: a plate (its width and height, square, rounded or
chamfered corners, in mm or inches) and features each TIED to the plate: an anchor per axis,
``("L", 6)`` "6 from the left edge", ``("R", 6)`` from the right one, ``("C", 0)`` on the centre
line (``B``/``T``/``C`` along y).  An edge anchor measures to the feature's near side for a
cut-out or a notch (the span a maker dimensions), to the first (or last) member's centre for a
row or a grid, and to the centre for the rest.  Feature kinds: ``hole``, ``slot`` (obround,
any angle), ``cutout`` (rectangle, corners square or rounded), ``notch`` (square, round-bottom
or V, in one of the plate's edges), ``row`` (holes or slots), ``grid`` (rectangular),
``hexgrid`` (staggered, clipped to a round or rectangular field), ``boltcircle`` (with or
without a bore), ``keyhole``, ``dhole`` (a D: a circle with one flat), ``arcslot`` (about a
centre: radius, start angle, sweep, width); drawn only when asked (:data:`NEW_KINDS`):
``ddhole`` (a double-D: two flats ``af`` apart), ``keyway`` (a bore with a key slot: width
``kw``, ``depth`` past the bore), ``ventrow`` (a row of slots turned at an angle to it) and
``csk`` (a row of ``n`` countersunk holes: each hole ``d`` and the top circle of its countersink,
``D``, on a CSK layer: marked, not cut; DXF only); drawn only when asked too (issue 93,
:data:`ROUND5_KINDS`), their truths written from the spec (docs/import.md, "What an edit
means") and not from the inference: ``corners`` (four holes or slots at the plate's corners,
``inset`` in), ``comb`` (``n`` notches ``p`` apart in one edge, ``w`` wide, ``depth`` deep),
``board`` (an Arduino Uno's or a sensor's holes, one set from the corner nearest them) and
``flange`` (a bolt circle whose first hole is at ``a0`` degrees: an edit turns it);
and ``label`` (a DXF TEXT or MTEXT, an SVG
``text``) tied to a feature (it moves with it) or to the plate.

A row, grid or comb is placed as the spec reads it (:func:`_spec_anchor`: by its end
member when that end sits within one and a half pitches of its edge, else by its middle from
the nearer edge), whatever anchor it was drawn from.

The design is data (:meth:`Design.edit` changes one number and checks the design still makes
sense), so the drawing a person meant after an edit is the edited design drawn again.  Its
geometry, :meth:`Design.loops` (every outline and hole as exact lines and arcs, in mm), is
the truth; :func:`to_dxf` and :func:`to_svg` (in gen_io.py, with the readers) export it as
real programs do: ezdxf with layers,
blocks and rotated INSERTs, LWPOLYLINEs with bulges or ARC+LINE corners, ``$INSUNITS`` set,
0 or missing (mm only: a headerless inch drawing is the user's to say); svgwrite with a mm (or
inch) viewBox, the y axis turned by a transformed group, patterns in nested translated and
rotated groups, arcs as path ``A`` commands.

A loop is compared by its exact :func:`signature` (area, centroid, perimeter and bounding box
from the lines' and arcs' own integrals), so a circle drawn as one CIRCLE or four arcs, or an
outline as one polyline or as lines and arcs, are the same loop.

Used by benchmarks/imports/infer_edits.py (the generated set) and tests/test_infer_generated.py.
"""
from __future__ import annotations

import copy
import math
import random
from dataclasses import dataclass, field


TAU = 2 * math.pi
INCH = 25.4

KINDS = ("hole", "slot", "cutout", "notch", "row", "grid", "hexgrid", "boltcircle",
         "keyhole", "dhole", "arcslot")
# kinds drawn only when asked (``random_design(pool=ALL_KINDS)``, benchmarks/imports/infer_edits.py
# --kinds): the drawings of KINDS from a seed stay the ones they were before these were added
NEW_KINDS = ("ddhole", "keyway", "ventrow", "csk")
# issue 93 (round five), drawn only when asked (--kinds round5), their truths from the spec
# (docs/import.md, "What an edit means"): four holes or slots at the corners by their inset,
# a comb's notches (count, pitch, width, depth), a board's holes (an Arduino's, one set from
# its nearest corner), a flange's bolt circle at a drawn first-hole angle (an edit turns it)
ROUND5_KINDS = ("corners", "comb", "board", "flange")
# issue 103 (round six), drawn only when asked (--kinds irregular): drawings that are not
# perfectly regular, as makers' files are, their truths from the spec (docs/import.md, "What an
# edit means"): four corner holes one of which is drilled larger (``odd``: its index in
# :meth:`Design.corner_members`, ``d_odd`` its diameter; it keeps its own size and its corner),
# a grid with a node left out (``gaps``: ``[(i, j)]``, column and row from the lower left; the
# gap stays at its turn when the counts change), a row of holes a CAD program rounded (``off``:
# each hole's offset off the pitch, at most 0.03 mm or 0.0015 in; it stays as drawn)
IRREGULAR_KINDS = ("oddcorners", "gapgrid", "cadrow")
BASE_KINDS = {"oddcorners": "corners", "gapgrid": "grid", "cadrow": "row"}
# issue 103 (round six, continued), drawn only when asked (--kinds round6), their truths from the
# spec: two holes or slots mirrored about a centre line, each ``inset`` from its own edge (the
# far one too; ``dir`` the axis they are apart along, the other axis tied by its anchor:
# ``edgepair``), a perforated plate (``perforated``: round holes ``d`` on a square ``p`` filling
# the plate less its ``margin``, as many each way as lie whole in it, centred), two 2 x 2 groups
# of one hole size each ``inset`` from its end of the plate along ``dir``, the first with a hole
# CAD rounded off its node (``off_at``: 0.03 mm, 0.0015 in), the second with one left out
# (``gap``) (``twogroups``: each group kept from its own edge)
ROUND6_KINDS = ("edgepair", "perforated", "twogroups")
# issue 114 (round seven), drawn only when asked (--kinds round7), their truths from the spec:
# a lattice of holes of two sizes (``checker``: ``nx`` x ``ny`` on ``px`` / ``py``, ``d`` and
# ``d2``, the second where ``(i + j) % 2 == 1`` (``mode`` parity) or at the nodes ``odd``
# (``mixed``), centred on the plate (``at`` "C") or its first hole ``ix``, ``iy`` in from the
# lower left corner, within one and a half pitches: one grid, each hole its own size on its
# turn), a single hole ``ox`` from the left or right edge (``sx``) and ``oy`` from the bottom
# or top (``sy``), nearer them than the centre lines (``edgehole``: its distances params), two
# holes of one size in line along ``dir`` on the centre line, ``a`` from the low edge and ``b``
# from the high one, not mirrored (``asympair``: each kept from its own edge)
ROUND7_KINDS = ("checker", "edgehole", "asympair")
ALL_KINDS = KINDS + NEW_KINDS + ROUND5_KINDS + IRREGULAR_KINDS + ROUND6_KINDS + ROUND7_KINDS


def base_kind(f) -> str:
    """The kind a feature is drawn as (an irregular kind's regular one)."""
    return BASE_KINDS.get(f["kind"], f["kind"])
# a board's hole sets (mm, from the set's lower left): an Arduino Uno's, a sensor's
BOARDS = [[(14.0, 2.5), (15.3, 50.7), (66.1, 7.6), (66.1, 35.5)],
          [(0.0, 0.0), (20.3, 3.8), (5.1, 17.8)]]


# --- exact geometry of lines and arcs --------------------------------------------------------
# a segment is ("L", (x0, y0), (x1, y1)) or ("A", (cx, cy), r, start angle, signed sweep)


def seg_ends(s) -> tuple:
    if s[0] == "L":
        return s[1], s[2]
    _, c, r, a, sw = s
    return ((c[0] + r * math.cos(a), c[1] + r * math.sin(a)),
            (c[0] + r * math.cos(a + sw), c[1] + r * math.sin(a + sw)))


def seg_reversed(s):
    if s[0] == "L":
        return ("L", s[2], s[1])
    return ("A", s[1], s[2], s[3] + s[4], -s[4])


def circle(c, r) -> list:
    return [("A", tuple(c), r, 0.0, TAU)]


def polygon(pts) -> list:
    return [("L", pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]


def _arc_integrals(c, r, a, sw):
    """(area, x moment, y moment) contributions of an arc: Green's theorem, exactly."""
    cx, cy = c

    def f(t):
        s, k = math.sin(t), math.cos(t)
        area = 0.5 * (r * cx * s - r * cy * k + r * r * t)
        mx = 0.5 * r * (cx * cx * s + 2 * cx * r * (t / 2 + math.sin(2 * t) / 4)
                        + r * r * (s - s ** 3 / 3))
        my = 0.5 * r * (-cy * cy * k + 2 * cy * r * (t / 2 - math.sin(2 * t) / 4)
                        + r * r * (-k + k ** 3 / 3))
        return area, mx, my
    f0, f1 = f(a), f(a + sw)
    return tuple(y - x for x, y in zip(f0, f1))


def _arc_box(s):
    _, c, r, a, sw = s
    pts = list(seg_ends(s))
    lo, hi = min(a, a + sw), max(a, a + sw)
    k = math.ceil(lo / (math.pi / 2))
    while k * math.pi / 2 <= hi:
        t = k * math.pi / 2
        pts.append((c[0] + r * math.cos(t), c[1] + r * math.sin(t)))
        k += 1
    return pts


def signature(loop) -> tuple:
    """``(area, cx, cy, perimeter, xmin, ymin, xmax, ymax)`` of a closed loop of segments
    (mm): the area unsigned, the centroid from the first moments; exact for lines and arcs."""
    area = mx = my = per = 0.0
    pts = []
    for s in loop:
        if s[0] == "L":
            (x0, y0), (x1, y1) = s[1], s[2]
            dx, dy = x1 - x0, y1 - y0
            area += 0.5 * (x0 * y1 - x1 * y0)
            mx += 0.5 * dy * (x0 * x0 + x0 * dx + dx * dx / 3)
            my -= 0.5 * dx * (y0 * y0 + y0 * dy + dy * dy / 3)
            per += math.hypot(dx, dy)
            pts += [s[1], s[2]]
        else:
            da, dmx, dmy = _arc_integrals(s[1], s[2], s[3], s[4])
            area, mx, my = area + da, mx + dmx, my + dmy
            per += abs(s[2] * s[4])
            pts += _arc_box(s)
    if area == 0:
        return (0.0, 0.0, 0.0, per, 0.0, 0.0, 0.0, 0.0)
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return (abs(area), mx / area, my / area, per, min(xs), min(ys), max(xs), max(ys))


def chain(segments, tol: float = 1e-6) -> tuple[list, list]:
    """Segments joined end to end into ``(closed loops, open chains)``."""
    todo = list(segments)
    loops, open_ = [], []
    while todo:
        cur = [todo.pop(0)]
        while True:
            start, end = seg_ends(cur[0])[0], seg_ends(cur[-1])[1]
            if math.dist(start, end) <= tol and (len(cur) > 1 or cur[0][0] == "A"):
                loops.append(cur)
                break
            for i, s in enumerate(todo):
                a, b = seg_ends(s)
                if math.dist(a, end) <= tol:
                    cur.append(todo.pop(i))
                    break
                if math.dist(b, end) <= tol:
                    cur.append(seg_reversed(todo.pop(i)))
                    break
                if math.dist(b, start) <= tol:
                    cur.insert(0, todo.pop(i))
                    break
                if math.dist(a, start) <= tol:
                    cur.insert(0, seg_reversed(todo.pop(i)))
                    break
            else:
                open_.append(cur)
                break
    return loops, open_


def _shifted(sig, dx, dy):
    a, cx, cy, p, x0, y0, x1, y1 = sig
    return (a, cx - dx, cy - dy, p, x0 - dx, y0 - dy, x1 - dx, y1 - dy)


def normalised(sigs: list) -> tuple[list, tuple]:
    """Signatures moved so that the largest loop's box starts at (0, 0), and that shift."""
    if not sigs:
        return [], (0.0, 0.0)
    big = max(sigs, key=lambda s: s[0])
    return [_shifted(s, big[4], big[5]) for s in sigs], (big[4], big[5])


def same_sig(a, b, tol: float = 1e-6) -> bool:
    return (abs(a[0] - b[0]) <= tol * max(1.0, a[3]) and abs(a[3] - b[3]) <= tol * 10
            and all(abs(x - y) <= tol for x, y in zip(a[1:3] + a[4:], b[1:3] + b[4:])))


def match(want: list, got: list, tol: float = 1e-6) -> tuple[list, list]:
    """``(indices of want with no partner in got, signatures of got left over)``."""
    rest = list(got)
    left = []
    for i, w in enumerate(want):
        for j, g in enumerate(rest):
            if same_sig(w, g, tol):
                rest.pop(j)
                break
        else:
            left.append(i)
    return left, rest


# --- the design --------------------------------------------------------------------------------


@dataclass
class Design:
    """A plate and its features, in ``units`` (``"mm"`` or ``"in"``); see the module doc."""
    units: str
    width: float
    height: float
    corner: tuple = ("square", 0.0)          # ("round" | "chamfer", size)
    origin: tuple = (0.0, 0.0)               # where the lower-left corner is drawn
    features: list = field(default_factory=list)
    style: dict = field(default_factory=dict)  # how it is exported (format, layers, ...)

    @property
    def u(self) -> float:
        """mm per design unit."""
        return INCH if self.units == "in" else 1.0

    # where things are
    def _axis(self, anchor, span: float, axis: int) -> float:
        ref, off = anchor
        lo = self.origin[axis]
        size = self.width if axis == 0 else self.height
        if ref in ("L", "B"):
            return lo + off + span
        if ref in ("R", "T"):
            return lo + size - off - span
        return lo + size / 2 + off

    def place(self, f) -> tuple:
        """The centre of feature ``f`` (design units)."""
        if f["kind"] == "label" and "of" in f:
            cx, cy = self.place(self.features[f["of"]])
            return (cx + f["dx"], cy + f["dy"])
        if "ax" not in f:           # at the corners, a comb: the plate's centre
            return (self.origin[0] + self.width / 2, self.origin[1] + self.height / 2)
        sx, sy = span(f)
        return (self._axis(f["ax"], sx, 0), self._axis(f["ay"], sy, 1))

    def outline(self) -> list:
        """The plate's outline, counter-clockwise, with its notches (design units)."""
        x0, y0 = self.origin
        x1, y1 = x0 + self.width, y0 + self.height
        corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        dirs = [(1, 0), (0, 1), (-1, 0), (0, -1)]
        kind, c = self.corner
        c = c if kind != "square" else 0.0
        segs = []
        notches = [f for f in self.features if f["kind"] == "notch"] + \
            [g for f in self.features if f["kind"] == "comb" for g in self.comb_notches(f)]
        for i in range(4):
            e, n = dirs[i], (-dirs[i][1], dirs[i][0])
            p, q = corners[i], corners[(i + 1) % 4]
            a = (p[0] + c * e[0], p[1] + c * e[1])
            b = (q[0] - c * e[0], q[1] - c * e[1])
            pts = [a]
            side = "BRTL"[i]
            along = []
            for f in notches:
                if f["edge"] != side:
                    continue
                w, h = f["w"], f["depth"]
                if side in "BT":
                    s = self._axis(f["at"], w / 2, 0)
                else:
                    s = self._axis(f["at"], w / 2, 1)
                along.append((s, f))
            along.sort(key=lambda t: t[0] * (e[0] + e[1]))
            out = []
            cur = a
            for s, f in along:
                w, h = f["w"], f["depth"]
                m = (s, p[1]) if side in "BT" else (p[0], s)

                def at(t, d, m=m):
                    return (m[0] + t * e[0] + d * n[0], m[1] + t * e[1] + d * n[1])
                p0, p1 = at(-w / 2, 0), at(w / 2, 0)
                out.append(("L", cur, p0))
                if f["shape"] == "square":
                    out += polygon([p0, at(-w / 2, h), at(w / 2, h), p1])[:3]
                elif f["shape"] == "V":
                    out += [("L", p0, at(0, h)), ("L", at(0, h), p1)]
                else:                       # round bottom: sides, a half circle (clockwise)
                    cc = at(0, h - w / 2)
                    ang = math.atan2(-e[1], -e[0])
                    out += [("L", p0, at(-w / 2, h - w / 2)), ("A", cc, w / 2, ang, -math.pi),
                            ("L", at(w / 2, h - w / 2), p1)]
                cur = p1
            del pts
            out.append(("L", cur, b))
            segs += out
            if c:
                nxt = dirs[(i + 1) % 4]
                if kind == "round":
                    cc = (q[0] - c * e[0] + c * n[0], q[1] - c * e[1] + c * n[1])
                    segs.append(("A", cc, c, math.atan2(-n[1], -n[0]), math.pi / 2))
                else:
                    segs.append(("L", b, (q[0] + c * nxt[0], q[1] + c * nxt[1])))
        return segs

    def comb_notches(self, f) -> list:
        """A comb's notches as notch features, each placed by its centre (design units)."""
        axis = 0 if f["edge"] in "BT" else 1
        c = self._axis(f["at"], span(f)[axis], axis)
        mid = self.origin[axis] + (self.width if axis == 0 else self.height) / 2
        return [{"kind": "notch", "edge": f["edge"], "shape": "square", "w": f["w"],
                 "depth": f["depth"], "at": ("C", c - mid + (i - (f["n"] - 1) / 2) * f["p"])}
                for i in range(f["n"])]

    def corner_members(self, f) -> list:
        """The centres of four features at the plate's corners, ``f["inset"]`` in."""
        x0, y0 = self.origin
        t = f["inset"]
        return [(x, y) for x in (x0 + t, x0 + self.width - t) for y in (y0 + t, y0 + self.height - t)]

    def plate_members(self, f) -> list:
        """The centres of a feature placed by the plate's size (design units): an edge pair's
        two, each ``inset`` from its own edge; a perforated plate's field, as many each way as
        lie whole in the plate less its margin, centred on it; two groups' holes, each group
        ``inset`` from its own end."""
        x0, y0 = self.origin
        W, H = self.width, self.height
        k = f["kind"]
        if k in ROUND7_KINDS:
            return [c for c, _ in round7_members(f, (x0, y0), W, H)]
        if k == "edgepair":
            if f["dir"] == "y":
                x = self._axis(f["ax"], 0.0, 0)
                return [(x, y0 + f["inset"]), (x, y0 + H - f["inset"])]
            y = self._axis(f["ay"], 0.0, 1)
            return [(x0 + f["inset"], y), (x0 + W - f["inset"], y)]
        if k == "perforated":
            nx = math.floor((W - 2 * f["margin"] - f["d"]) / f["p"] + 1e-9) + 1
            ny = math.floor((H - 2 * f["margin"] - f["d"]) / f["p"] + 1e-9) + 1
            return [(x0 + W / 2 + (i - (nx - 1) / 2) * f["p"],
                     y0 + H / 2 + (j - (ny - 1) / 2) * f["p"]) for i in range(nx)
                    for j in range(ny)]
        p, t = f["p"], f["inset"]
        size, across = (W, H) if f["dir"] == "x" else (H, W)
        out = []
        for g, start in ((0, t), (1, size - t - p)):
            for i in range(2):
                for j in range(2):
                    if g == 1 and (i, j) == tuple(f["gap"]):
                        continue
                    a = start + i * p + (f["q"] if g == 0 and (i, j) == tuple(f["off_at"])
                                         else 0.0)
                    b = across / 2 + (j - 0.5) * p
                    out.append((x0 + a, y0 + b) if f["dir"] == "x" else (x0 + b, y0 + a))
        return out

    def feature_loops(self, i: int) -> list:
        """The loops of feature ``i`` (design units): its holes (a notch: none, it is in the
        outline; a label: none)."""
        f = self.features[i]
        if f["kind"] in ROUND7_KINDS:
            return [circle(c, d / 2) for c, d in round7_members(f, self.origin, self.width,
                                                                 self.height)]
        if f["kind"] in ROUND6_KINDS:
            if f.get("member") == "slot":
                return [slot_loop(c, f["length"], f["w"], math.radians(f["angle"]))
                        for c in self.plate_members(f)]
            return [circle(c, f["d"] / 2) for c in self.plate_members(f)]
        if base_kind(f) == "corners":
            if f["member"] == "hole":
                return [circle(c, (f["d_odd"] if k == f.get("odd") else f["d"]) / 2)
                        for k, c in enumerate(self.corner_members(f))]
            return [slot_loop(c, f["length"], f["w"], math.radians(f["angle"]))
                    for c in self.corner_members(f)]
        return loops_of(f, self.place(f)) if f["kind"] not in ("notch", "label", "comb") else []

    def loops(self) -> list:
        """``[(owner, loop in mm)]``: ``owner`` is ``-1`` for the outline, else the feature's
        index."""
        u = self.u
        out = [(-1, scaled(self.outline(), u))]
        for i in range(len(self.features)):
            out += [(i, scaled(lp, u)) for lp in self.feature_loops(i)]
        return out

    def marks(self) -> list:
        """``[(centre, radius)]`` of the countersinks' top circles (design units): marked
        about their holes, not cut."""
        return [(m, f["D"] / 2) for f in self.features if f["kind"] == "csk"
                for m in members(f, self.place(f))]

    def labels(self) -> list:
        """``[(index, text, (x, y), height, kind, align)]`` in design units."""
        return [(i, f["text"], self.place(f), f["h"], f["type"], f["align"])
                for i, f in enumerate(self.features) if f["kind"] == "label"]

    def describe(self) -> str:
        """The design as a maker says it, one feature a line: "plate 100 x 60 mm, square
        corners", "row of 5 holes d 4, pitch 12, along x: x centred, y 10 from the top"."""
        u = self.units

        def at(a, axis):
            ref, off = a
            if ref == "C":
                return f"{'xy'[axis]} centred" + (f" {off:+g}" if off else "")
            side = {"L": "left", "R": "right", "B": "bottom", "T": "top"}[ref]
            return f"{'xy'[axis]} {off:g} from the {side}"
        out = [f"plate {self.width:g} x {self.height:g} {u}, {self.corner[0]} corners"
               + (f" {self.corner[1]:g}" if self.corner[0] != "square" else "")
               + f", drawn from ({self.origin[0]:g}, {self.origin[1]:g}); "
               + ", ".join(f"{k} {v}" for k, v in self.style.items())]
        for i, f in enumerate(self.features):
            k = base_kind(f)
            sizes = ", ".join(f"{key} {v:g}" if isinstance(v, (int, float)) else f"{key} {v}"
                              for key, v in f.items()
                              if key not in ("kind", "ax", "ay", "at", "of", "dx", "dy"))
            if k == "label" and "of" in f:
                where = f"{f['dx']:+g}, {f['dy']:+g} from feature {f['of']}"
            elif k in ("notch", "comb"):
                where = at(f["at"], 0 if f["edge"] in "BT" else 1)
            elif k == "corners":
                where = f"at the corners, {f['inset']:g} in"
            elif "ax" not in f:
                where = "by the plate's size"
            else:
                where = f"{at(f['ax'], 0)}, {at(f['ay'], 1)}"
            out.append(f"{i}: {k} ({sizes}): {where}")
        return "\n".join(out)

    # editing
    def edits(self) -> list:
        """Every edit a maker might make: ``Edit`` without a new value."""
        out = [Edit("body", "plate", -1, "width", "plate width",
                    [(r"(plate_|body_|panel_)?(width|w)", 1.0)], whole=True),
               Edit("body", "plate", -1, "height", "plate height",
                    [(r"(plate_|body_|panel_)?(height|h)", 1.0)], whole=True)]
        D = [(r"d|dia|diameter|size", 1.0), (r"r|radius", 0.5)]
        P = [(r"pitch(_[xy])?|spacing(_[xy])?|d[xy]", 1.0)]
        N = [(r"n(_[xy])?|count|cols|rows|n[xy]", 1.0)]
        for i, f in enumerate(self.features):
            k = base_kind(f)

            def add(kind, key, label, pats):
                out.append(Edit(kind, f["kind"], i, key, f"{f['kind']} {label}", pats))
            if k in ("hole", "grid", "hexgrid", "boltcircle", "dhole"):
                add("size", "d", "diameter", D)
            if k == "row":
                add("size", "d" if f["member"] == "hole" else "length",
                    "diameter" if f["member"] == "hole" else "slot length",
                    D if f["member"] == "hole" else [(r"length|len|l", 1.0)])
            if k == "slot":
                add("size", "length", "length", [(r"length|len|l", 1.0)])
                add("size", "w", "width", [(r"width|w", 1.0), (r"r|radius", 0.5)])
            if k == "cutout":
                add("size", "w", "width", [(r"width|w", 1.0)])
                add("size", "h", "height", [(r"height|h", 1.0)])
            if k == "notch":
                add("size", "w", "width", [(r"width|w", 1.0)])
                add("size", "depth", "depth", [(r"depth|d", 1.0)])
            if k == "keyhole":
                add("size", "D", "head diameter", [(r"(head_|big_)?(d|dia|diameter)", 1.0),
                                                  (r"(head_|big_)?(r|radius)", 0.5)])
            if k == "arcslot":
                add("size", "w", "width", [(r"width|w", 1.0)])
                add("size", "R", "radius", [(r"radius|r", 1.0), (r"d|diameter", 2.0)])
            if k == "ddhole":
                add("size", "d", "diameter", D)
                add("size", "af", "across flats", [(r"flat|af|across_flats", 1.0)])
            if k == "keyway":
                add("size", "d", "bore", [(r"(bore_)?(d|dia|diameter)", 1.0)])
                add("size", "kw", "key width", [(r"(key_)?(w|width)", 1.0)])
                add("size", "depth", "key depth", [(r"(key_)?depth", 1.0)])
            if k == "ventrow":
                add("size", "length", "slot length", [(r"length|len|l", 1.0)])
                add("pitch", "p", "pitch", P)
                add("count", "n", "count", N)
            if k == "csk":
                add("size", "d", "diameter", D)
                add("size", "D", "countersink diameter",
                    [(r"(countersink_|csk_|sink_)(d|dia|diameter)", 1.0)])
                add("pitch", "p", "pitch", P)
                add("count", "n", "count", N)
            if k in ("boltcircle", "flange") and f.get("bore"):
                add("size", "bore", "bore", [(r"(bore_)?(d|diameter)", 1.0)])
            if k == "edgepair":
                if f["member"] == "hole":
                    add("size", "d", "diameter", D)
                else:
                    add("size", "length", "slot length", [(r"length|len|l", 1.0)])
                add("pitch", "inset", "inset", [(r"inset|margin", 1.0)])
            if k in ROUND7_KINDS:
                add("size", "d", "diameter", D)
            if k == "checker":
                add("size", "d2", "second diameter", D)
                add("pitch", "px", "pitch", P)
                if f["py"] is not None:
                    add("pitch", "py", "pitch y", P)
                if f["mode"] == "parity":       # a new column keeps the checkerboard
                    add("count", "nx", "count", N)
            if k == "edgehole":
                add("pitch", "ox", "distance from its side edge", [(r"x", 1.0)])
                add("pitch", "oy", "distance from its top or bottom edge", [(r"y", 1.0)])
            if k == "perforated":
                add("size", "d", "diameter", D)
                add("pitch", "p", "pitch", P)
                add("pitch", "margin", "margin", [(r"margin", 1.0)])
            if k == "corners":
                if f["member"] == "hole":
                    add("size", "d", "diameter", D)
                else:
                    add("size", "length", "slot length", [(r"length|len|l", 1.0)])
                add("pitch", "inset", "inset", [(r"inset|margin", 1.0)])
            if k == "comb":
                add("size", "w", "notch width", [(r"width|w", 1.0)])
                add("size", "depth", "notch depth", [(r"depth", 1.0)])
                add("pitch", "p", "pitch", P)
                add("count", "n", "count", N)
            if k == "board":
                add("size", "d", "diameter", D)
            if k == "flange":
                add("size", "d", "diameter", D)
                add("pitch", "pcd", "pitch circle", [(r"pcd|pitch_d|pitch_circle_d", 1.0)])
                add("count", "n", "count", N)
                add("pitch", "a0", "first hole's angle", [(r"angle|start_angle", 1.0)])
            if k in ("row", "grid"):
                add("pitch", "p" if k == "row" else "px", "pitch", P)
                add("count", "n" if k == "row" else "nx", "count", N)
            if k == "grid" and f["py"]:
                add("pitch", "py", "pitch y", P)
            if k == "grid":
                add("count", "ny", "count y", N)
            if k == "hexgrid":
                add("pitch", "p", "pitch", P)
                add("size", "field", "field size",
                    [(r"(field_)?(d|diameter|width|size)", 1.0), (r"(field_)?(r|radius)", 0.5)])
            if k == "boltcircle":
                add("pitch", "pcd", "pitch circle", [(r"pcd|pitch_d|pitch_circle_d|circle_d|"
                                                      r"diameter", 1.0),
                                                     (r"radius|r|pitch_r", 0.5)])
                add("count", "n", "count", N)
        return out

    def value(self, e: "Edit") -> float:
        if e.feature < 0:
            return self.width if e.key == "width" else self.height
        return self.features[e.feature][e.key]

    def edited(self, e: "Edit", new: float) -> "Design":
        d = copy.deepcopy(self)
        if e.feature < 0:
            setattr(d, e.key, new)
        else:
            d.features[e.feature][e.key] = new
        return d

    def valid(self) -> bool:
        return _valid(self)


@dataclass
class Edit:
    """One change a maker makes: ``kind`` (size, pitch, count, body), the feature's kind, its
    index (-1: the plate), the design key it changes, a label, the param name patterns it
    may go by (``(regex, factor)``: the param's value is factor x the design's), ``whole``:
    the regex must match the whole name (else any ``_``-separated tail)."""
    kind: str
    feature_kind: str
    feature: int
    key: str
    label: str
    patterns: list
    whole: bool = False
    new: float | None = None


def span(f) -> tuple:
    """Half the span an edge anchor measures to (design units): none along an axis the
    feature is placed by its middle (``f["mid"]``, the spec's rows and grids)."""
    out = _span(f)
    mid = f.get("mid", ())
    return tuple(0.0 if a in mid else v for a, v in enumerate(out))


def _span(f) -> tuple:
    k = base_kind(f)
    if k == "board":
        pts = _board(f)
        return ((max(p[0] for p in pts) - min(p[0] for p in pts)) / 2,
                (max(p[1] for p in pts) - min(p[1] for p in pts)) / 2)
    if k == "comb":
        s = (f["n"] - 1) * f["p"] / 2
        return (s, 0.0) if f["edge"] in "BT" else (0.0, s)
    if k == "cutout":
        return f["w"] / 2, f["h"] / 2
    if k in ("row", "ventrow", "csk"):
        s = (f["n"] - 1) * f["p"] / 2
        return (s, 0.0) if f["dir"] == "x" else (0.0, s)
    if k == "grid":
        return (f["nx"] - 1) * f["px"] / 2, (f["ny"] - 1) * (f["py"] or f["px"]) / 2
    return 0.0, 0.0


def _rot(pts_or_loop, c, ang):
    """A loop in local coordinates turned by ``ang`` and moved to ``c``."""
    k, s = math.cos(ang), math.sin(ang)

    def p(q):
        return (c[0] + k * q[0] - s * q[1], c[1] + s * q[0] + k * q[1])
    out = []
    for g in pts_or_loop:
        if g[0] == "L":
            out.append(("L", p(g[1]), p(g[2])))
        else:
            out.append(("A", p(g[1]), g[2], g[3] + ang, g[4]))
    return out


def slot_loop(c, length, w, ang) -> list:
    r, a = w / 2, (length - w) / 2
    return _rot([("L", (-a, -r), (a, -r)), ("A", (a, 0.0), r, -math.pi / 2, math.pi),
                 ("L", (a, r), (-a, r)), ("A", (-a, 0.0), r, math.pi / 2, math.pi)], c, ang)


def rect_loop(c, w, h, r=0.0) -> list:
    x0, y0, x1, y1 = c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2
    if not r:
        return polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
    return [("L", (x0 + r, y0), (x1 - r, y0)), ("A", (x1 - r, y0 + r), r, -math.pi / 2, math.pi / 2),
            ("L", (x1, y0 + r), (x1, y1 - r)), ("A", (x1 - r, y1 - r), r, 0.0, math.pi / 2),
            ("L", (x1 - r, y1), (x0 + r, y1)), ("A", (x0 + r, y1 - r), r, math.pi / 2, math.pi / 2),
            ("L", (x0, y1 - r), (x0, y0 + r)), ("A", (x0 + r, y0 + r), r, math.pi, math.pi / 2)]


def keyhole_loop(c, D, w, L, ang) -> list:
    R, a = D / 2, w / 2
    s = math.sqrt(R * R - a * a)
    t0, t1 = math.atan2(-s, a), math.atan2(-s, -a)
    return _rot([("A", (0.0, 0.0), R, t0, (t1 - t0) % TAU), ("L", (-a, -s), (-a, -L)),
                 ("A", (0.0, -L), a, math.pi, math.pi), ("L", (a, -L), (a, -s))], c, ang)


def dhole_loop(c, d, flat, ang) -> list:
    r = d / 2
    h = math.sqrt(r * r - flat * flat)
    t = math.atan2(h, flat)
    return _rot([("A", (0.0, 0.0), r, t, TAU - 2 * t), ("L", (flat, -h), (flat, h))], c, ang)


def ddhole_loop(c, d, af, ang) -> list:
    """A double-D: a circle of diameter ``d`` with two flats ``af`` apart, normal ``ang``."""
    r, f = d / 2, af / 2
    h = math.sqrt(r * r - f * f)
    t = math.atan2(h, f)
    return _rot([("A", (0.0, 0.0), r, t, math.pi - 2 * t), ("L", (-f, h), (-f, -h)),
                 ("A", (0.0, 0.0), r, math.pi + t, math.pi - 2 * t), ("L", (f, -h), (f, h))],
                c, ang)


def keyway_loop(c, d, kw, depth, ang) -> list:
    """A bore of diameter ``d`` with a key slot ``kw`` wide running ``depth`` past the bore
    toward ``ang``."""
    r, a = d / 2, kw / 2
    s, T = math.sqrt(r * r - a * a), r + depth
    t0 = math.atan2(a, s)
    return _rot([("A", (0.0, 0.0), r, t0, TAU - 2 * t0), ("L", (s, -a), (T, -a)),
                 ("L", (T, -a), (T, a)), ("L", (T, a), (s, a))], c, ang)


def arcslot_loop(c, R, a0, sw, w) -> list:
    a1 = a0 + sw
    e0 = (c[0] + R * math.cos(a0), c[1] + R * math.sin(a0))
    e1 = (c[0] + R * math.cos(a1), c[1] + R * math.sin(a1))
    return [("A", c, R + w / 2, a0, sw), ("A", e1, w / 2, a1, math.pi),
            ("A", c, R - w / 2, a1, -sw), ("A", e0, w / 2, a0 + math.pi, math.pi)]


def _board(f) -> list:
    """A board's hole set in design units, from its lower left."""
    return [(x / f["u"], y / f["u"]) for x, y in BOARDS[f["board"]]]


def members(f, c) -> list:
    """The centres of a pattern's members (design units)."""
    k = base_kind(f)
    if k == "flange":
        a0 = math.radians(f["a0"])
        return [(c[0] + f["pcd"] / 2 * math.cos(a0 + TAU * i / f["n"]),
                 c[1] + f["pcd"] / 2 * math.sin(a0 + TAU * i / f["n"])) for i in range(f["n"])]
    if k == "board":
        pts = _board(f)
        mx = (max(p[0] for p in pts) + min(p[0] for p in pts)) / 2
        my = (max(p[1] for p in pts) + min(p[1] for p in pts)) / 2
        return [(c[0] + x - mx, c[1] + y - my) for x, y in pts]
    if k in ("row", "ventrow", "csk"):
        off = f.get("off", [])          # a CAD-rounded row: each hole's offset off the pitch
        s = [(i - (f["n"] - 1) / 2) * f["p"] + (off[i] if i < len(off) else 0.0)
             for i in range(f["n"])]
        return [(c[0] + t, c[1]) if f["dir"] == "x" else (c[0], c[1] + t) for t in s]
    if k == "grid":
        py = f["py"] or f["px"]
        return [(c[0] + (i - (f["nx"] - 1) / 2) * f["px"], c[1] + (j - (f["ny"] - 1) / 2) * py)
                for i in range(f["nx"]) for j in range(f["ny"]) if (i, j) not in f.get("gaps", ())]
    if k == "boltcircle":
        # the first hole on the x axis, on the y axis, or the axis between two holes: kept so
        # when the count changes
        a0 = {"axis": 0.0, "top": math.pi / 2, "between": f["a0r"]}[f["start"]]
        return [(c[0] + f["pcd"] / 2 * math.cos(a0 + TAU * i / f["n"]),
                 c[1] + f["pcd"] / 2 * math.sin(a0 + TAU * i / f["n"])) for i in range(f["n"])]
    if k == "hexgrid":
        p, r = f["p"], f["d"] / 2
        dy = p * math.sqrt(3) / 2
        out = []
        big = int(f["field"] / p) + 2
        for j in range(-big, big + 1):
            off = p / 2 if j % 2 else 0.0
            for i in range(-big, big + 1):
                x, y = i * p + off, j * dy
                if f["shape"] == "circle":
                    ok = math.hypot(x, y) + r <= f["field"] / 2 + 1e-9
                else:
                    ok = abs(x) + r <= f["field"] / 2 + 1e-9 and abs(y) + r <= f["fh"] / 2 + 1e-9
                if ok:
                    out.append((c[0] + x, c[1] + y))
        return out
    return [c]


def loops_of(f, c) -> list:
    k = base_kind(f)
    if k == "hole":
        return [circle(c, f["d"] / 2)]
    if k == "slot":
        return [slot_loop(c, f["length"], f["w"], math.radians(f["angle"]))]
    if k == "cutout":
        return [rect_loop(c, f["w"], f["h"], f.get("r", 0.0))]
    if k == "keyhole":
        return [keyhole_loop(c, f["D"], f["w"], f["L"], math.radians(f["angle"]))]
    if k == "dhole":
        return [dhole_loop(c, f["d"], f["flat"], math.radians(f["angle"]))]
    if k == "ddhole":
        return [ddhole_loop(c, f["d"], f["af"], math.radians(f["angle"]))]
    if k == "keyway":
        return [keyway_loop(c, f["d"], f["kw"], f["depth"], math.radians(f["angle"]))]
    if k == "ventrow":
        return [slot_loop(m, f["length"], f["w"], math.radians(f["angle"]))
                for m in members(f, c)]
    if k == "arcslot":
        return [arcslot_loop(c, f["R"], math.radians(f["a0"]), math.radians(f["sweep"]), f["w"])]
    if k == "row" and f["member"] == "slot":
        return [slot_loop(m, f["length"], f["w"], math.pi / 2 if f["dir"] == "x" else 0.0)
                for m in members(f, c)]
    out = [circle(m, f["d"] / 2) for m in members(f, c)]
    if k in ("boltcircle", "flange") and f.get("bore"):
        out.append(circle(c, f["bore"] / 2))
    return out


def scaled(loop, u: float) -> list:
    if u == 1.0:
        return loop
    out = []
    for g in loop:
        if g[0] == "L":
            out.append(("L", (g[1][0] * u, g[1][1] * u), (g[2][0] * u, g[2][1] * u)))
        else:
            out.append(("A", (g[1][0] * u, g[1][1] * u), g[2] * u, g[3], g[4]))
    return out


def _poly(loop):
    """A shapely polygon of a loop (arcs in 5-degree steps): for the sanity checks only."""
    from shapely.geometry import Polygon
    pts = []
    for g in loop:
        if g[0] == "L":
            pts.append(g[1])
        else:
            k = max(2, int(abs(g[4]) / math.radians(5)) + 1)
            pts += [(g[1][0] + g[2] * math.cos(g[3] + g[4] * t / k),
                     g[1][1] + g[2] * math.sin(g[3] + g[4] * t / k)) for t in range(k)]
    return Polygon(pts)


def _label_box(d: Design, f):
    from shapely.geometry import box
    x, y = d.place(f)
    w, h = len(f["text"]) * f["h"] * 0.9, f["h"]
    return box(x - w / 2, y - h / 2, x + w / 2, y + h / 2) if f["align"] == "centre" else \
        box(x, y, x + w, y + h)


def _reads_as_tied(d: Design, f) -> bool:
    """Whether a label tied to the plate sits in line with a hole of a round-five kind
    (:data:`ROUND5_KINDS`; the kinds before them are drawn as they always were): the spec
    reads such a label as its hole's (docs/import.md, "What an edit means"), so a design
    that means otherwise is not drawn."""
    if not any(g["kind"] in ROUND5_KINDS for g in d.features):
        return False
    x, y = d.place(f)
    for i, g in enumerate(d.features):
        if g["kind"] in ("label", "notch", "comb"):
            continue
        for lp in d.feature_loops(i):
            _, cx, cy, *_ = signature(lp)
            if abs(cx - x) <= 1e-9 or abs(cy - y) <= 1e-9:
                return True
    return False


def _roundest_margin(size: float, f) -> float:
    """The margin docs/import.md reads off a perforated plate's holes along a side ``size``
    long: of the margins that keep exactly those holes (``(tight - p / 2, tight]``, tight
    from the edge to the outer holes' edges), the roundest (the multiple of the largest step
    10, 5, 2.5, 2, 1, 0.5, ... times a power of ten in it)."""
    n = math.floor((size - 2 * f["margin"] - f["d"]) / f["p"] + 1e-9) + 1
    tight = (size - (n - 1) * f["p"] - f["d"]) / 2
    lo, hi = tight - f["p"] / 2, tight
    for e in range(6, -10, -1):
        for k in (1.0, 0.5, 0.25, 0.2):
            step = k * 10.0 ** e
            v = math.floor(hi / step + 1e-9) * step
            if lo + 1e-9 < v <= hi + 1e-9:
                return round(v, 9)
    return hi


def _valid(d: Design) -> bool:
    """Every feature well inside the plate, clear of every other, each shape sound."""
    m = 1.5 / d.u
    if d.width <= 0 or d.height <= 0:
        return False
    if d.corner[0] != "square" and d.corner[1] * 2 >= min(d.width, d.height) - 4 * m:
        return False
    for f in d.features:
        if any(v is not None and v <= 0 for k, v in f.items() if k in ("d", "w", "h", "length", "D", "p", "px",
                                                      "py", "pcd", "depth", "field", "R", "L", "af", "kw")):
            return False
        if f.get("n", 2) < 2 or f.get("nx", 2) < 2 or f.get("ny", 2) < 2:
            return False
        k = base_kind(f)
        if (k == "slot" or (k == "row" and f["member"] == "slot")) and f["length"] <= f["w"] + m:
            return False
        if k == "keyhole" and not (f["w"] < f["D"] - m and f["L"] > f["D"] / 2 + m):
            return False
        if k == "dhole" and f["flat"] >= f["d"] / 2 - m / 4:
            return False
        if k == "ddhole" and f["af"] >= f["d"] - m / 2:
            return False
        if k == "keyway" and not (f["kw"] < f["d"] - m and f["depth"] > m / 4):
            return False
        if k == "ventrow" and (f["length"] <= f["w"] + m or f["p"] * abs(math.sin(
                math.radians(f["angle"]) - (0 if f["dir"] == "x" else math.pi / 2))) < f["w"] + m):
            return False
        if k == "notch" and f["shape"] == "round" and f["depth"] <= f["w"] / 2 + m:
            return False
        if k == "csk" and (f["D"] < f["d"] + m or f["p"] < f["D"] + m):
            return False
        if k == "arcslot" and f["w"] >= f["R"]:
            return False
        if k == "cutout" and f.get("r", 0) * 2 >= min(f["w"], f["h"]):
            return False
        if k in ("row", "grid") and min(f.get("p", 1e9), f.get("px", 1e9), f.get("py") or 1e9) \
                < f.get("d", f.get("w", 0)) + m:
            return False
        if k == "row" and f["member"] == "slot" and f["p"] < f["w"] + m:
            return False
        if k == "boltcircle" and (f["pcd"] * math.sin(math.pi / f["n"]) < f["d"] + m
                                  or (f.get("bore") and f["bore"] + f["d"] + 2 * m > f["pcd"])):
            return False
        if k == "hexgrid" and (f["p"] < f["d"] + m or len(members(f, (0, 0))) < 3):
            return False
        if k == "comb":
            axis = 0 if f["edge"] in "BT" else 1
            c = d._axis(f["at"], span(f)[axis], axis)
            lo = d.origin[axis] + (d.corner[1] if d.corner[0] != "square" else 0) + 2 * m
            hi = d.origin[axis] + (d.width if axis == 0 else d.height) - (lo - d.origin[axis])
            half = (f["n"] - 1) * f["p"] / 2 + f["w"] / 2
            if f["p"] < f["w"] + 2 * m or c - half < lo or c + half > hi or f["depth"] > \
                    (d.height if axis == 0 else d.width) / 3:
                return False
        if k == "board" and any(g is not f and g["kind"] == "board" and g["d"] == f["d"]
                                for g in d.features):
            return False        # two boards' holes of one size: one set (no pattern tells)
        if f["kind"] == "gapgrid" and (f["nx"] * f["ny"] < 6 or
                                       not any(i < f["nx"] and j < f["ny"] for i, j in f["gaps"])):
            return False        # a gap list needs a lattice a gap leaves one (issue 103)
        if k == "edgepair" and not 0 < f["inset"] * 4 < \
                (d.width if f["dir"] == "x" else d.height) - 1e-9:
            return False        # nearer its edge than the centre line (a tie: no edge pair)
        if k == "perforated":
            for size in (d.width, d.height):
                n = math.floor((size - 2 * f["margin"] - f["d"]) / f["p"] + 1e-9) + 1
                if n < 5 or (n - 1) * f["p"] + f["d"] < 2 / 3 * size or \
                        not f["p"] - f["d"] < f["margin"] - 1e-9 or f["margin"] >= 3 * f["p"]:
                    return False    # a field over the plate but for its margin (issue 103)
            if f["p"] < f["d"] + m or any(_roundest_margin(size, f) != f["margin"]
                                          for size in (d.width, d.height)):
                return False        # the margin the spec reads (its roundest) is another
        if k in ROUND6_KINDS and any(g is not f and (g.get("d"), g.get("w")) ==
                                     (f.get("d"), f.get("w")) for g in d.features):
            return False            # holes of one size of two features: one set (no pattern)
        if k in ROUND7_KINDS and any(
                g is not f and {g.get("d"), g.get("w"), g.get("d2")} & {f.get("d"), f.get("d2")}
                - {None} for g in d.features):
            return False            # (round seven's: its second size too)
        if k in ROUND7_KINDS and not _round7_valid(d, f, m):
            return False
        if k == "twogroups" and ((d.width if f["dir"] == "x" else d.height)
                                 - 2 * f["inset"] - 2 * f["p"] <= 2 * f["p"]
                                 or f["p"] < f["d"] + m):
            return False        # two groups apart (each nearer its own than the other)
        if k == "corners" and f["inset"] * 4 >= min(d.width, d.height) - 1e-9:
            return False        # nearer the edges than the centre lines (a tie: no corner)
        if k == "flange" and (f["pcd"] * math.sin(math.pi / f["n"]) < f["d"] + m
                              or (f.get("bore") and f["bore"] + f["d"] + 2 * m > f["pcd"])):
            return False
    plate = _poly(d.outline())
    if not plate.is_valid:
        return False
    inner = plate.buffer(-m)
    shapes = []
    for i, f in enumerate(d.features):
        if f["kind"] == "notch":
            continue
        if f["kind"] == "label":
            b = _label_box(d, f)
            if not inner.contains(b):
                return False
            shapes.append((i, b, True))
            if "of" not in f and _reads_as_tied(d, f):
                return False
            continue
        for lp in d.feature_loops(i):
            p = _poly(lp)
            if not p.is_valid or not inner.contains(p):
                return False
            shapes.append((i, p, False))
        if f["kind"] == "csk":          # the marks too: clear of the other features
            for c in members(f, d.place(f)):
                p = _poly(circle(c, f["D"] / 2))
                if not inner.contains(p):
                    return False
                shapes.append((i, p, False))
    for a in range(len(shapes)):
        for b in range(a + 1, len(shapes)):
            ia, pa, la = shapes[a]
            ib, pb, lb = shapes[b]
            if ia != ib and pa.distance(pb) < m:
                return False
    return True


# --- random designs ------------------------------------------------------------------------------

MM = {"plate": [40, 50, 60, 70, 80, 90, 100, 120, 150, 160, 180, 200],
      "d": [2.5, 3, 3.2, 3.4, 4, 4.5, 5, 5.5, 6, 8, 10],
      "off": [4, 5, 6, 8, 10, 12, 15, 20], "pitch": [8, 10, 12, 15, 20, 25],
      "big": [10, 12, 16, 20, 22, 25, 30], "step": [2, 5, 10, 15, 20, 30], "r": [3, 4, 5, 8],
      "text": [3, 4, 5]}
IN = {"plate": [2, 2.5, 3, 3.5, 4, 4.5, 5, 6, 7],
      "d": [0.125, 0.15, 0.1875, 0.2, 0.25, 0.3125],
      "off": [0.2, 0.25, 0.3, 0.375, 0.5, 0.75], "pitch": [0.4, 0.5, 0.6, 0.75, 1.0],
      "big": [0.5, 0.625, 0.75, 0.875, 1.0], "step": [0.125, 0.25, 0.5, 1.0], "r": [0.125, 0.2, 0.25],
      "text": [0.125, 0.15, 0.2]}
WORDS = ["PWR", "USB", "M3", "FAN", "IN", "OUT", "VOL", "LED", "12V", "GND", "TOP"]


def _anchor(rng, T, axis):
    lo, hi = ("L", "R") if axis == 0 else ("B", "T")
    r = rng.random()
    if r < 0.35:
        return ("C", 0.0)
    return (lo if r < 0.7 else hi, rng.choice(T["off"]))


def random_feature(rng: random.Random, T: dict, kind: str) -> dict:
    f = {"kind": kind, "ax": _anchor(rng, T, 0), "ay": _anchor(rng, T, 1)}
    d = rng.choice(T["d"])
    if kind == "hole":
        f["d"] = rng.choice(T["d"] + T["big"][:2])
    elif kind == "slot":
        f.update(w=d, length=d + rng.choice(T["pitch"]), angle=rng.choice([0, 90, 90, 45, 30]))
    elif kind == "cutout":
        f.update(w=rng.choice(T["big"]), h=rng.choice(T["big"]),
                 r=rng.choice([0.0, 0.0, T["r"][0]]))
    elif kind == "notch":
        f = {"kind": kind, "edge": rng.choice("BRTL"), "shape": rng.choice(["square", "round", "V"]),
             "w": rng.choice(T["pitch"][:4])}
        f["depth"] = f["w"] * rng.choice([1, 1.5, 2])
        f["at"] = _anchor(rng, T, 0 if f["edge"] in "BT" else 1)
    elif kind == "cadrow":              # a row of holes a CAD program rounded
        f.update(dir=rng.choice("xy"), n=rng.randint(3, 6), p=rng.choice(T["pitch"]),
                 member="hole", d=d)
        q = 0.01 if T is MM else 0.0005          # 0.01 mm, 0.0005 in: 0.0127 mm
        f["off"] = [rng.choice([-3, -2, -1, 0, 1, 2, 3]) * q for _ in range(f["n"])]
        f["off"][rng.randrange(f["n"])] = q
    elif kind == "row":
        f.update(dir=rng.choice("xy"), n=rng.randint(3, 6), p=rng.choice(T["pitch"]),
                 member=rng.choice(["hole", "hole", "slot"]), d=d)
        if f["member"] == "slot":
            f.update(w=d, length=d + rng.choice(T["pitch"]))
            del f["d"]
    elif kind == "grid":
        f.update(nx=rng.randint(2, 5), ny=rng.randint(2, 4), px=rng.choice(T["pitch"]), d=d)
        f["py"] = rng.choice([None, rng.choice(T["pitch"])])  # None: a square grid, one pitch
        if f["py"] == f["px"]:
            f["py"] = None
    elif kind == "hexgrid":
        f.update(p=rng.choice(T["pitch"][:3]), d=d, shape=rng.choice(["circle", "rect"]))
        f["field"] = f["p"] * rng.choice([3, 4, 5])
        f["fh"] = f["field"] * rng.choice([0.6, 0.8, 1.0])
    elif kind == "boltcircle":
        f.update(n=rng.choice([3, 4, 5, 6, 8]), d=d, pcd=rng.choice(T["big"]) * 2,
                 bore=rng.choice([0, rng.choice(T["big"])]))
        f["start"] = rng.choice(["axis", "between", "top"])
        # one reading of the holes drawn (the spec's: a new count keeps the first hole where
        # it is, on the x axis, else at the top, else at its drawn angle): with one at the
        # top, 4 or 8 have one on the x axis; 6 half a pitch off it have one at the top
        if f["start"] == "top" and f["n"] % 4 == 0:
            f["start"] = "axis"
        if f["start"] == "between" and f["n"] == 6:
            f["start"] = "top"
        f["a0r"] = math.pi / f["n"]          # "between": drawn half a pitch off, kept so
    elif kind == "keyhole":
        f.update(D=rng.choice(T["big"][:3]) / 2, angle=rng.choice([0, 0, 90, 180]))
        f["w"] = f["D"] / 2
        f["L"] = f["D"] * 1.25
    elif kind == "dhole":
        f.update(d=rng.choice(T["big"][:4]) / 2, angle=rng.choice([0, 90, 0]))
        f["flat"] = f["d"] / 2 * rng.choice([0.6, 0.7, 0.8])
    elif kind == "ddhole":
        f.update(d=rng.choice(T["big"][:4]), angle=rng.choice([0, 90, 0]))
        f["af"] = round(f["d"] * rng.choice([0.6, 0.7, 0.8]), 4)
    elif kind == "keyway":
        f.update(d=rng.choice(T["big"]), angle=rng.choice([90, 90, 0, 270]))
        f["kw"] = round(f["d"] * rng.choice([0.2, 0.25, 0.3]), 4)
        f["depth"] = round(f["kw"] / 2, 4)
    elif kind == "ventrow":
        f.update(dir=rng.choice("xy"), n=rng.randint(3, 6), p=rng.choice(T["pitch"]), w=d,
                 angle=rng.choice([30, 45, 60, -45, 120]))
        f["length"] = d + rng.choice(T["pitch"]) * 2
    elif kind == "csk":
        f.update(dir=rng.choice("xy"), n=rng.randint(2, 4), p=rng.choice(T["pitch"]), d=d,
                 D=round(d * rng.choice([1.6, 2.0, 2.2]), 4))
    elif kind == "oddcorners":          # one of four corner holes drilled larger
        f = {"kind": kind, "member": "hole", "d": d, "inset": rng.choice(T["off"][1:]),
             "odd": rng.randrange(4)}
        f["d_odd"] = round(d * 1.1, 1) if T is MM else d + 1 / 64
    elif kind == "gapgrid":             # a grid with one node left out
        f.update(nx=rng.randint(3, 5), ny=rng.randint(2, 4), px=rng.choice(T["pitch"]), d=d)
        f["py"] = rng.choice([None, rng.choice(T["pitch"])])
        if f["py"] == f["px"]:
            f["py"] = None
        f["gaps"] = [(rng.randrange(f["nx"]), rng.randrange(f["ny"]))]
    elif kind == "edgepair":            # two mirrored about a centre line, by their edges
        f.update(dir=rng.choice("xy"), member=rng.choice(["hole", "hole", "slot"]), d=d,
                 inset=rng.choice(T["off"]))
        f["ay" if f["dir"] == "y" else "ax"] = ("C", 0.0)
        if f["member"] == "slot":
            f.update(w=d, length=d + rng.choice(T["pitch"][:3]), angle=rng.choice([0, 90]))
            del f["d"]
    elif kind in ROUND7_KINDS:          # issue 114: round seven (gen_round7.py)
        f = random_round7(rng, T, kind, d)
    elif kind == "perforated":          # a field over the plate but for its margin
        f = {"kind": kind, "d": rng.choice(T["d"][:7]), "p": rng.choice(T["pitch"][1:]),
             "margin": rng.choice(T["off"][2:])}
    elif kind == "twogroups":           # two 2 x 2 groups of one size, one at each end
        f = {"kind": kind, "dir": rng.choice("xy"), "d": d, "p": rng.choice(T["pitch"]),
             "inset": rng.choice(T["off"]), "gap": (rng.randrange(2), rng.randrange(2)),
             "off_at": (rng.randrange(2), rng.randrange(2)),
             "q": 0.03 if T is MM else 0.0015}
    elif kind == "corners":
        f = {"kind": kind, "member": rng.choice(["hole", "hole", "slot"]), "d": d,
             "inset": rng.choice(T["off"][1:])}
        if f["member"] == "slot":
            f.update(w=d, length=d + rng.choice(T["pitch"][:3]), angle=rng.choice([0, 90]))
            del f["d"]
    elif kind == "comb":
        f = {"kind": kind, "edge": rng.choice("BRTL"), "n": rng.randint(3, 8),
             "p": rng.choice(T["pitch"][:4]), "w": rng.choice(T["pitch"][:2]) / 2}
        f["depth"] = f["w"] * rng.choice([2, 3, 4])
        f["at"] = _anchor(rng, T, 0 if f["edge"] in "BT" else 1)
    elif kind == "board":
        f.update(board=rng.randrange(len(BOARDS)), d=rng.choice(T["d"][2:6]),
                 u=INCH if T is IN else 1.0)
        f["ax"] = (rng.choice("LR"), rng.choice(T["off"]))
        f["ay"] = (rng.choice("BT"), rng.choice(T["off"]))
    elif kind == "flange":
        f.update(n=rng.choice([3, 4, 5, 6, 8]), d=d, pcd=rng.choice(T["big"]) * 2,
                 bore=rng.choice([0, rng.choice(T["big"])]))
        # a first hole at a drawn angle none of the x axis, the top or straddling it
        f["a0"] = rng.choice([15, 20, 25, 35, 40]) % (360 / f["n"])
    elif kind == "arcslot":
        f.update(R=rng.choice(T["big"]), w=rng.choice(T["d"][:4]), a0=rng.choice([0, 30, 45, 200]),
                 sweep=rng.choice([45, 60, 90]))
    return f


def _spec_anchor(d: Design, f) -> dict:
    """``f`` (a row, a grid, a comb) placed as the spec reads it (docs/import.md, "What an
    edit means"), per axis along which it has a pitch: on the centre line, centred; with an
    end member nearer its edge than one and a half pitches, by that end from that edge (ties: the low
    one); else by its middle, from the edge nearer it (``f["mid"]``: no span on that axis)."""
    k = base_kind(f)
    if k in ("row", "ventrow", "csk"):
        axes = [(0 if f["dir"] == "x" else 1, f["p"], "ax" if f["dir"] == "x" else "ay")]
    elif k == "grid":
        axes = [(0, f["px"], "ax"), (1, f["py"] or f["px"], "ay")]
    elif k == "comb":
        axes = [(0 if f["edge"] in "BT" else 1, f["p"], "at")]
    else:
        return f
    for axis, p, key in axes:
        sp = span(f)[axis]
        c = d._axis(f[key], sp, axis)
        lo = d.origin[axis]
        hi = lo + (d.width if axis == 0 else d.height)
        mid = set(f.get("mid", ())) - {axis}
        f["mid"] = tuple(sorted(mid))
        full = _span(f)[axis]
        if abs(c - (lo + hi) / 2) < 1e-9:
            f[key] = ("C", 0.0)
            continue
        gl, gh = c - full - lo, hi - (c + full)
        names = ("L", "R") if axis == 0 else ("B", "T")
        if min(gl, gh) < 1.5 * p - 1e-9:       # the inference's SET_END
            f[key] = (names[0], gl) if gl <= gh else (names[1], gh)
        else:
            f["mid"] = tuple(sorted(mid | {axis}))
            f[key] = (names[0], c - lo) if c - lo <= hi - c else (names[1], hi - c)
    return f


def _dimensioned(v: float, units: str) -> bool:
    """Whether a distance ``v`` (design units) is one a maker dimensions, as the inference
    reads it (``infer/patterns/groups.py``): above 0, a whole number of 0.5 mm or of 0.025 in."""
    mm = v * (INCH if units == "in" else 1.0)
    return v > 1e-7 and any(abs(mm / q - round(mm / q)) * q <= 1e-6 for q in (0.5, 0.635))


def _plain_anchor(d: Design, f) -> dict:
    """``f`` with an edge anchor that puts it on the plate's centre line said as centred: as
    far from both edges, a maker means the centre (the design must not be ambiguous); a
    row, grid or comb placed as the spec reads it (:func:`_spec_anchor`)."""
    if base_kind(f) in ("row", "ventrow", "csk", "grid", "comb"):
        return _spec_anchor(d, f)
    if f["kind"] == "board":        # one set, from the reference nearest its holes' middle
        ms = members(f, d.place(f))
        for axis, key, names in ((0, "ax", "LR"), (1, "ay", "BT")):
            m = sum(p[axis] for p in ms) / len(ms)
            lo = d.origin[axis]
            hi = lo + (d.width if axis == 0 else d.height)
            c, sp = d.place(f)[axis], span(f)[axis]
            near = c - sp - lo <= hi - c - sp + 1e-9       # its extent's nearer edge: the low
            gap = c - sp - lo if near else hi - c - sp
            if abs(m - (lo + hi) / 2) <= min(m - lo, hi - m) and \
                    (abs(c - (lo + hi) / 2) <= 1e-7 or not _dimensioned(gap, d.units)):
                f[key] = ("C", c - (lo + hi) / 2)
            elif abs(m - (lo + hi) / 2) <= min(m - lo, hi - m):
                # off the centre line, its nearest hole a dimensioned distance from the nearer
                # edge: from that edge, as it was drawn (issue 114's Mega)
                f[key] = (names[0], gap) if near else (names[1], gap)
            else:
                f[key] = (names[0], c - sp - lo) if m - lo <= hi - m else (names[1], hi - c - sp)
        return f
    keys = [("at", 0 if f["edge"] in "BT" else 1)] if f["kind"] == "notch" else \
        [("ax", 0), ("ay", 1)] if "ax" in f else []
    for key, axis in keys:
        if f[key][0] != "C":
            sp = (f["w"] / 2, 0.0) if f["kind"] == "notch" else span(f)
            pos = d._axis(f[key], sp[axis if f["kind"] != "notch" else 0], axis)
            mid = d.origin[axis] + (d.width if axis == 0 else d.height) / 2
            if abs(pos - mid) < 1e-9:
                f[key] = ("C", 0.0)
    return f


def random_design(rng: random.Random, kinds=None, pool=KINDS) -> Design:
    """A random maker plate: 2 to 5 features (``kinds`` first, each once, then 1 to 3 drawn
    from ``pool``), 0 to 2 labels, an export style."""
    units = "in" if rng.random() < 0.25 else "mm"
    T = IN if units == "in" else MM
    for _ in range(200):
        w, h = rng.choice(T["plate"]), rng.choice(T["plate"])
        if max(w, h) > 2.5 * min(w, h):
            continue
        corner = rng.choice([("square", 0.0), ("square", 0.0), ("round", rng.choice(T["r"])),
                             ("chamfer", rng.choice(T["r"]))])
        origin = rng.choice([(0.0, 0.0), (0.0, 0.0), (-w / 2, -h / 2), (rng.choice(T["step"]),
                                                                        rng.choice(T["step"]))])
        d = Design(units, w, h, corner, origin)
        want = list(kinds or []) + [rng.choice(pool) for _ in range(rng.randint(1, 3))]
        for k in want:
            for _ in range(40):
                d.features.append(_plain_anchor(d, random_feature(rng, T, k)))
                if d.valid():
                    break
                d.features.pop()
        if not [f for f in d.features if f["kind"] != "notch"] or \
                (kinds and not all(any(f["kind"] == k for f in d.features) for k in kinds)):
            continue
        for _ in range(rng.choice([0, 1, 1, 2])):
            for _ in range(20):
                tied = rng.random() < 0.6
                lab = {"kind": "label", "text": rng.choice(WORDS), "h": rng.choice(T["text"]),
                       "type": rng.choice(["TEXT", "MTEXT"]), "align": rng.choice(["centre", "left"])}
                if tied:
                    i = rng.choice([i for i, f in enumerate(d.features)
                                    if f["kind"] in ("hole", "slot", "cutout", "keyhole", "dhole",
                                                     "ddhole", "keyway")]
                                   or [None])
                    if i is None:
                        tied = False
                    else:
                        lab.update({"of": i, "dx": 0.0, "dy": -rng.choice(T["off"][2:]) * 1.5})
                if not tied:
                    lab.update(ax=_anchor(rng, T, 0), ay=_anchor(rng, T, 1))
                d.features.append(_plain_anchor(d, lab))
                if d.valid():
                    break
                d.features.pop()
        d.style = random_style(rng, d)
        return d
    raise RuntimeError("no design found")


def random_style(rng: random.Random, d: Design) -> dict:
    fmt = "svg" if rng.random() < 0.25 else "dxf"
    if any(f["kind"] == "csk" for f in d.features):
        fmt = "dxf"                 # a countersink's layer: a DXF's
    return {"format": fmt,
            "layers": rng.choice([None, None, ("OUTLINE", "HOLES", "LABELS")]),
            "blocks": rng.random() < 0.4,
            "bulges": rng.random() < 0.6,
            "insunits": True if d.units == "in" or rng.random() < 0.7 else
            rng.choice([False, None])}


def random_edit(rng: random.Random, d: Design, e: Edit) -> Design | None:
    """``d`` with ``e`` made by a random amount a maker would (``e.new`` set), or ``None`` when
    no such change leaves a design that makes sense."""
    T = IN if d.units == "in" else MM
    now = d.value(e)
    for _ in range(12):
        if e.kind == "count":
            new = now + rng.choice([-1, 1])
        elif e.kind == "body":
            new = now + rng.choice([-1, 1, 1]) * rng.choice(T["step"])
        else:
            step = T["step"][0] if now < 4 * T["step"][0] else T["step"][1]
            new = now + rng.choice([-1, 1]) * step * rng.choice([0.1, 0.2, 0.5, 1])
            new = round(new, 4)
        if new == now:
            continue
        out = d.edited(e, new)
        if out.valid():
            e.new = new
            return out
    return None


# --- export and the independent readers: gen_io.py (this module's size) ----------------------------

from gen_round7 import _round7_valid, random_round7, round7_members  # noqa: E402
from gen_io import (_bulges, _dxf_loop, _dxf_segments, _local_loops, _path_d,  # noqa: E402,F401
                    export, read_dxf, read_svg, to_dxf, to_svg)
