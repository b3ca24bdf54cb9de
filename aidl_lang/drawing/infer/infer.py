"""``aidl import --infer``: a drawing turned into the program a person would have written
(issue 60; docs/import.md, "Inferring the design").

Where :func:`~.program.to_program` writes every piece of the drawing as its own ``Line`` or
``Arc``, :func:`to_program_inferred` writes, for each part (a DXF layer, or with ``--parts``
each outer loop):

* its outline as the primitive it is (:func:`~.infer_shapes.recognise`: ``RoundedRectangle``,
  ``Slot``, ``RegularPolygon``, ...), or a recognised rectangle with *attachments* (a tab
  standing out of one side: the pieces off the rectangle's side, closed inside it), or a
  circle with teeth (a loop of turned ``Polygon``s), or one run of pieces turned ``n`` times
  round a centre (``CircularPattern`` of each), else the exact chain;
* its openings as ``hole`` children named by what they are, repeated ones as loops:
  four at the corners of a rectangular body (``corner_holes``, by the body's size and one
  inset), a bolt circle (``bolt_circle``: equal circles evenly round a centre, its diameter a
  ``param``), a bore (a circle on the bolt circle's or the body's centre), rows and grids
  (``for`` over equal steps), mirrored pairs (``for s in [-1, 1]``); equal sizes are one
  ``param``; copies of a whole part in a row are one ``solid`` in a ``for``;
* its engravings (open paths, text, engraved shapes) as one ``drawing``, ticks in a row or
  round a centre as one loop;
* ``Fixed`` on every recognised shape and the holds of every chain that stays
  (:func:`_holds`), so ``aidl check --dof`` has nothing to report: each shape is held where
  its expression puts it, and ``--set`` of a param moves and resizes what is written with
  it.

Parameters are named for the part (``plate_width``) when there are several parts, and
written with the shortest decimal within :data:`~.infer_shapes.ROUND_TOL` (1e-9 mm) of the
drawing's number; two sizes or steps are equal within :data:`~.infer_shapes.EQUAL_TOL`
(1e-7 mm).  The program's head says what was recognised (pieces -> shapes) and these
tolerances.  A part holding what this writer does not know is written by
:func:`~.program.to_program`'s own code, whole.

This module writes the program (:class:`_Part`: a part's body, holes and their patterns;
:func:`_engraving`; :func:`to_program_inferred`) from what its neighbours find:
:mod:`.infer_shapes` (the primitives), :mod:`.infer_attachments` (a rectangle with tabs, a
circle with teeth), :mod:`.infer_patterns` (bolt circles, rows, grids, turned outlines,
ticks, copies of a part) and :mod:`.infer_params` (numbers, params and constructors as text).
"""
from __future__ import annotations

import math
from collections import Counter

from ...geometry.shapes.curves import Loop
from .attachments import _attachments, _circle_attachments
from .params import _Params, _add0, _ctor, _deg, _hole_name, _r
from .patterns.find import (lattices, _Cells, _copies, _grid, _line, _off_circle, _polar, _runs,
                            _stagger, _hex_field, _hex_rect, _whole, _features, _unknown)
from .shapes import EQUAL_TOL, PRECISION, ROUND_TOL, Shape, _close, circular, recognise
from .anchors import _Anchored
from .body import _Bodies
from .engrave.engraving import _engraving
from .engrave.labels import _at_as_drawn, _label_place
from .holes.makers import SINGLE_PARAMS, _MakerFeatures
from .naming import _far, _named_parts, _short_names, _summary
from ..chains.layers import _hole_layers
from ..chains.containment import engraved_on
from .profiles.write import _Profiles
from .mirror import mirrored_pair, pair_gap, pair_items, write_pair
from .holes.sinks import Marks
from .patterns.groups import _Groups, corner_sets, corners_and_pattern, follows
from .patterns.irregular import _Irregular
from .patterns.mixed import _Mixed, alike
from .patterns.fields import _Fields
from .patterns.lattice import _Lattices
from .patterns.pairs import RING_MAX, RING_MIN, RING_WORK, _Pairs, _ring_about
from .beside import _beside, beside_order
from .patterns.rings import _start, ring_in_scatter, rings, start_angle
from .patterns import turns
from ..write.program import _containers, _cut_notes, _layer_items, _place, _whole_ellipse
from ..write.writer import _Names, _Writer, _emit_holds, _holds, _ident, _length, _num, _pt
from ..write.units import UNIT, in_unit
from ..model import Drawing, Note, _segs_box


class _Stats:
    def __init__(self) -> None:
        self.pieces = 0             # pieces of the drawing's outlines and holes
        self.in_shapes = 0          # of them, in recognised shapes
        self.kinds: Counter = Counter()
        self.patterns: Counter = Counter()
        self.readings: list = []    # where two readings fit one drawing: which was taken
        self.far: set = set()       # (axis, side): an edge that moves features are placed from


class _Part(_Bodies, _Anchored, _MakerFeatures, _Groups, _Profiles, _Irregular, _Fields,
            _Pairs, _Mixed, _Lattices):
    """One part's statements, written into ``w`` at ``depth``."""

    def __init__(self, w: _Writer, params: _Params, stats: _Stats, prefix: str) -> None:
        self.w, self.params, self.stats, self.prefix = w, params, stats, prefix
        self.used: set = _Names()
        self.shift: tuple | None = None     # (x term, y term) added to every position
        self.anchor: tuple | None = None    # (body Shape, its size params): edges to place by
        self.frame = (0, 0)                 # per axis, what stays when the body's size param
        #                                     changes: -1 its left (bottom) edge, 1 its right
        #                                     (top) edge, 0 its centre (:meth:`grows_from`)
        self.named = _Cells([])             # centres written once, shared (their names:
        self.named_as: list[str] = []       # named_as[i] is named.points[i]'s)
        self.kinds: dict = {}               # (kind, sizes) -> size params (kind_params)
        self.written: dict = {}             # centre -> its place as written (write_at)
        self.looped: list = []              # patterns (members, centre, index): written_at
        self.sink_members: list = []        # the holes the next hole statement writes
        self.marks: Marks | None = None     # the import's countersink marks (sinks.py)
        self.sunk: dict = {}                # id(hole Shape) -> its mark (Marks.attach)
        self.sinks = None                   # the marks of the holes being written, or None
        self.keep = None                    # a mirrored pair's mirror line (grows)
        self.rects: set = set()             # names written as a Rectangle or RoundedRectangle

    def grows(self, sh: Shape) -> tuple:
        """:meth:`grows_from`, but a part drawn beside its mirror image (:attr:`keep`, the
        mirror line) keeps its edge nearest that line, so the gap between the two stays."""
        out = list(self.grows_from(sh))
        if self.keep is not None:
            axis = 0 if self.keep[0] == "x" else 1
            key = "width" if axis == 0 else "height"
            lo = sh.center[axis] - sh.args[key] / 2
            hi = lo + sh.args[key]
            out[axis] = -1 if abs(lo - self.keep[1]) <= abs(hi - self.keep[1]) else 1
        if getattr(self, "after", None) is not None:
            out[self.after] = -1        # beside the part before it: from its near edge
        return tuple(out)

    def shared(self, c) -> str | None:
        """The name of the first shared centre within EQUAL_TOL of ``c``, or None."""
        hit = self.named.near(c)
        return self.named_as[hit[0]] if hit else None

    def origin(self, c) -> tuple[str, str, bool]:
        """The x and y text of a pattern's centre ``c`` and whether it is a shared centre
        (a feature the pattern surrounds) or the body's centre."""
        nm = self.shared(c)
        if nm is not None:
            return f"{nm}.x", f"{nm}.y", True
        on_body = self.anchor is not None and math.dist(self.anchor[0].center, c) <= EQUAL_TOL
        return self.at(c[0], 0), self.at(c[1], 1), on_body

    def p(self, name: str, value: float, comment: str = "", unit: str = "mm",
          times: int = 1) -> str:
        return self.params.add(self.prefix + name, value, comment, unit, times)

    def name(self, base: str) -> str:
        return _ident(base, self.used)

    def numbered(self, base: str) -> str:
        """``base`` with the first free number from 1 (``hole1``), counting on from the
        last one given (:class:`~.program._Names`: not from 1 for each of 20,000 holes)."""
        k = self.used.next.get(("numbered", base), 1)
        while f"{base}{k}" in self.used:
            k += 1
        self.used.add(f"{base}{k}")
        self.used.next[("numbered", base)] = k + 1
        return f"{base}{k}"

    def shape_line(self, depth: int, nm: str, sh: Shape, center: str, sizes=None) -> None:
        self.w.emit(depth, f"{nm} = {_ctor(sh, center, sizes)}")
        if sh.kind in ("Rectangle", "RoundedRectangle"):
            self.rects.add(nm)          # a CornerPattern's rectangle (_corner_set)

    # the holes --------------------------------------------------------------
    def holes(self, depth: int, loops: list, body) -> None:
        shapes = []
        for k, segs in enumerate(loops):
            self.check(k, "recognising the holes of the drawing")
            self.stats.pieces += len(segs)
            sh = recognise(segs)
            if sh is None:
                self.compound_hole(depth, segs, body)
                continue
            self.stats.kinds[sh.kind] += 1
            self.stats.in_shapes += sh.pieces
            shapes.append(sh)
        groups: dict = {}
        for sh in shapes:
            key = (sh.kind,) + tuple(round(x, 6) if isinstance(x, float) else x
                                     for x in sh.size)
            groups.setdefault(key, []).append(sh)
        if self.marks is not None:
            self.sunk = self.marks.attach(shapes)
        singles = []
        centres = []          # bolt circle centres, for naming a bore
        self.share_centres(depth, groups, body)
        self.merge_odd(groups, body)
        self.merge_mixed(groups)        # one lattice of holes of two sizes (a checkerboard)
        # the middles of the groups of three or more and how far their holes are from it
        # (a motor plate's corner slots about its bore, outside its motor holes)
        self.rings_at = [(mid, sum(math.dist(h.center, mid) for h in g) / len(g))
                         for g in groups.values() if len(g) >= 3
                         for mid in [(sum(h.center[0] for h in g) / len(g),
                                      sum(h.center[1] for h in g) / len(g))]]
        for k, (key, g) in enumerate(groups.items()):
            if len(g) == 1 or g[0].kind == "Polygon":
                singles += g
                continue
            self.check(k, "finding the patterns of the holes", every=1)
            r = g[0].args.get("radius", 0.0) if g[0].kind == "Circle" else 0.0
            cs = [sh.center for sh in g]
            parts = None if _whole(cs, r) else corner_sets(cs, body) or \
                corners_and_pattern(cs, body, r) or _features(cs, r) or \
                rings(cs, ([body[0].center] if body is not None else []) + self.named.points) \
                or corner_sets(cs, body, rest=True) or ring_in_scatter(cs)
            # equal holes of several features (a grille and a grid): each its own pattern;
            # a sibling's lattice for one with a hole left out (irregular: _gapped_as)
            self.kin = lattices([[cs[i] for i in part] for part in parts or []])
            # alike groups of one size (two 2 x 2s): one size param for all (issue 114)
            self.one_size = [g[0].kind, g[0].size, None] if alike(parts, cs, self.kin) else None
            for part in parts or [range(len(g))]:
                sub = [g[i] for i in part]
                if len(sub) == 1:
                    singles += sub
                elif not self.sunk_as(sub) or not self.pattern(depth, sub, body, centres):
                    singles += sub
        self.one_size = None
        few = len(singles) <= SINGLE_PARAMS
        for k, sh in enumerate(singles):
            self.check(k, "writing the holes")
            self.sunk_as([sh])
            self.single(depth, sh, body, centres, few)
        self.sinks = None

    def check(self, k: int, stage: str, every: int = 128) -> None:
        """The import's deadline looked at (``stage``) on every ``every``-th step ``k``."""
        if self.w.deadline is not None and k % every == 0:
            self.w.deadline.check(stage)

    def share_centres(self, depth: int, groups: dict, body) -> None:
        """A feature that a pattern of other holes surrounds (a bore inside its motor
        holes, a window inside its screws): its centre written once as a name
        (``bore_c = (x, y)``) that both use, so moving one moves the other."""
        many = [g for g in groups.values() if len(g) > 1 and g[0].kind != "Polygon"]
        mids = _Cells([(sum(h.center[0] for h in g) / len(g),
                        sum(h.center[1] for h in g) / len(g)) for g in many])
        # a motor's four holes round its bore among more holes of their size (two more by
        # the far edge): the group's middle is not the bore's, four of them are about it
        ringed = [g for g in many if RING_MIN < len(g) <= RING_MAX]
        if sum(map(len, ringed)) * sum(len(g) == 1 for g in groups.values()) > RING_WORK:
            ringed = []
        for g in groups.values():
            if len(g) != 1 or g[0].kind not in ("Circle", "Rectangle", "RoundedRectangle",
                                                 "RegularPolygon"):
                continue
            sh = g[0]
            if not mids.near(sh.center) and not any(_ring_about(sh.center, h) for h in ringed):
                continue
            if self.shared(sh.center) is not None:
                continue
            base = "bore" if sh.kind == "Circle" else _hole_name(sh)
            hn = self.name(base)
            self.used.discard(hn)           # the hole itself takes the name (single)
            var = _ident(hn + "_c", self.used)
            # placed from its edge by a param (`bore_x`: the motor 35 mm from the right edge)
            self.w.emit(depth, f"{var} = {self.pos_from_edges(hn, sh.center)}")
            self.named.add(sh.center)
            self.named_as.append(var)
            self.shared_kind = getattr(self, "shared_kind", {})
            self.shared_kind[var] = sh.kind
            self.shared_shape = getattr(self, "shared_shape", {})
            self.shared_shape[var] = sh        # (groups: corner holes nearer the corners)

    def compound_hole(self, depth: int, segs: list, body) -> None:
        """A hole no one primitive makes: a circle with a keyway (a tooth), a rectangle with
        a tab, both written in one ``hole``; an arc slot, a keyhole, a D-hole
        (:meth:`maker_hole`); else the exact chain."""
        w = self.w
        if self.maker_hole(depth, segs):
            self.stats.in_shapes += len(segs)
            return
        got = _circle_attachments(segs)
        if got is not None:
            circle, teeth = got
            concentric = body is not None and _close(circle.center, body[0].center)
            hn = self.name("bore" if concentric else "round_hole")
            w.emit(depth, f"hole {hn} {{")
            w.emit(depth + 1, f"h = {_ctor(circle, self.pos(circle.center))}")
            names = ["h"]
            sub = _Part(w, self.params, self.stats, self.prefix)
            sub.shift = self.shift
            word = "key" if len(teeth) == 1 else "notch"
            if len(teeth) == 1:
                pts = ", ".join(self.beside(circle.center, p) for p in teeth[0])
                w.emit(depth + 1, f"key = Polygon([{pts}])")
                names.append("key")
                self.stats.kinds["Polygon"] += 1
            else:
                sub.teeth(depth + 1, circle, teeth, word)
            w.emit(depth, "}")
            w.emit(depth, f"for x in [{', '.join(f'{hn}.{f}' for f in names)}] {{ Fixed(x) }}")
            self.stats.kinds["Circle"] += 1
            self.stats.in_shapes += len(segs)
            return
        got = _attachments(segs)
        if got is not None:
            rect, tabs = got
            hn = self.name("window")
            w.emit(depth, f"hole {hn} {{")
            w.emit(depth + 1, f"h = {_ctor(rect, self.pos(rect.center))}")
            fixed = ["h"]
            for k, t in enumerate(tabs):
                nm = f"tab{k + 1}"
                if isinstance(t, Shape):
                    w.emit(depth + 1, f"{nm} = {_ctor(t, self.beside(rect.center, t.center))}")
                else:
                    tt = recognise(t)
                    if tt is None:
                        if w.chain(depth + 1, t, True, nm + "_"):
                            fixed += _holds(t, nm + "_")
                        continue
                    w.emit(depth + 1, f"{nm} = {_ctor(tt, self.beside(rect.center, tt.center))}")
                fixed.append(nm)
            w.emit(depth, "}")
            _emit_holds(w, depth, [f"{hn}.{f}" for f in fixed])
            self.stats.kinds[rect.kind] += 1
            self.stats.in_shapes += len(segs)
            return
        hn = self.name("cutout")
        w.emit(depth, f"hole {hn} {{")
        ref = _place(segs)
        box = _segs_box(segs)           # placed by the reference nearest the cut-out's middle
        where = self.beside(((box[0] + box[2]) / 2, (box[1] + box[3]) / 2), ref)
        if where != self.center(ref):       # placed from an edge or the centre: the chain
            w.emit(depth + 1, f"p = {where}")   # drawn from its first point, which follows
            w.rel = ref
        ok = w.chain(depth + 1, segs, True, "e")
        w.rel = None
        w.emit(depth, "}")
        if ok:
            _emit_holds(w, depth, _holds(segs, f"{hn}.e"))

    def hole_block(self, depth: int, hn: str, sh: Shape, center: str, sizes=None,
                   index=None) -> None:
        """``hole hn { h = ... }`` and its ``Fixed``, and the countersink marks of the holes
        it writes (:attr:`sinks`), a subset of a loop's by ``index`` (Shape -> the loop's
        variables on its turn, :meth:`~.sinks.Marks.write`)."""
        sizes = self.own_sizes(hn, sh, sizes, index)
        center = self.off_turns(center, index)
        self.w.emit(depth, f"hole {hn} {{ h = {_ctor(sh, center, sizes)} }}")
        self.w.emit(depth, f"Fixed({hn}.h)")
        if index is not None:       # a label beside a member follows it (written_at)
            self.looped.append((self.sink_members, center, index))
        if self.sinks is not None and sh.kind == "Circle":
            self.marks.write(self, depth, hn, sh, center, self.sinks, self.sink_members, index)

    def sunk_as(self, members: list) -> bool:
        """Say that the holes written next are ``members`` (:attr:`sinks`: their marks by
        size, :meth:`~.sinks.Marks.common`); True."""
        self.sinks = Marks.common(self.sunk, members) if self.sunk else None
        self.sink_members = members
        return True

    def size_params(self, base: str, sh: Shape, many: bool) -> dict:
        """Params for a repeated shape's sizes (``many``), else none (literal numbers)."""
        if not many:
            return {}
        one = getattr(self, "one_size", None)       # groups of one size (holes): one param
        if one is not None and (sh.kind, sh.size) == (one[0], one[1]):
            if one[2] is None:
                self.one_size = None
                one[2] = self.size_params(base, sh, many)
                self.one_size = one
            return one[2]
        a = sh.args
        if sh.kind == "Circle":
            return {"diameter": self.p(base + "_d", 2 * a["radius"])}
        if sh.kind == "Slot":
            return {"length": self.p(base + "_length", a["length"]),
                    "width": self.p(base + "_width", a["width"])}
        if sh.kind in ("Rectangle", "RoundedRectangle"):
            out = {"width": self.p(base + "_width", a["width"]),
                   "height": self.p(base + "_height", a["height"])}
            if "corner_radius" in a:
                out["corner_radius"] = self.p(base + "_corner_radius", a["corner_radius"])
            return out
        if sh.kind == "RegularPolygon":
            return {"radius": self.p(base + "_radius", a["radius"])}
        return {}

    def _corner_set(self, depth: int, g: list, body, sh, base: str, cs: list) -> bool:
        """Four holes at the corners of the body, centred on it, as a corner set (a loop over
        ``sx``, ``sy`` with the inset from the edges); False when they are not one."""
        w = self.w
        mid_all = (sum(c[0] for c in cs) / len(cs), sum(c[1] for c in cs) / len(cs))
        if len(g) == 4 and body is not None and body[0].kind != "Circle" and \
                self.at_corners(g, mid_all):
            bsh, bsizes, bname = body
            gr = _grid(cs)
            if gr is not None and gr[4] == 2 and gr[5] == 2:
                x0, y0, dx, dy = gr[:4]
                mid = (x0 + dx / 2, y0 + dy / 2)
                W, H = bsh.args.get("width", 0.0), bsh.args.get("height", 0.0)
                ix, iy = (W - dx) / 2, (H - dy) / 2
                # at the corners: nearer the edges than the centre lines (else a square
                # or a bolt circle about the centre, placed by it)
                if math.dist(mid, bsh.center) <= EQUAL_TOL and 0 < ix < W / 4 and 0 < iy < H / 4:
                    # a second set at the corners: corner_2_inset, corner_2_hole_d (a name
                    # that ends as every inset's and diameter's)
                    pre, k = "corner", 1
                    while self.prefix + pre + "_inset" in self.params.used or \
                            self.prefix + pre + "_inset_x" in self.params.used:
                        k += 1
                        pre = f"corner_{k}"
                    sizes = self.size_params(f"{pre}_{base}", sh, True)
                    if abs(ix - iy) <= ROUND_TOL:
                        inx = iny = self.p(f"{pre}_inset", ix, "from the edges")
                    else:
                        inx = self.p(f"{pre}_inset_x", ix, "from the left and right edges")
                        iny = self.p(f"{pre}_inset_y", iy, "from the top and bottom edges")
                    hn = self.name(f"{pre}_{base}s")
                    wx, hy = bsizes.get("width"), bsizes.get("height")
                    ex = f"sx * ({wx} / 2 - {inx})" if wx else f"sx * {_r(dx / 2)}"
                    ey = f"sy * ({hy} / 2 - {iny})" if hy else f"sy * {_r(dy / 2)}"
                    c = f"({self.from_body_centre(0, ex, mid[0])}, {self.from_body_centre(1, ey, mid[1])})"
                    w.emit(depth, f"# at the corners, {inx if inx == iny else inx + ' and ' + iny}"
                                  f" in from the edges")
                    if self.sinks is None and bname in self.rects and \
                            not any(id(m) in getattr(self, "odd", {}) or id(m) in self.mixed for m in g):
                        # the language's own: the inset is one word to change (issue 93)
                        first = c.replace("sx", "-1").replace("sy", "-1")
                        if wx and hy:       # the bottom-left corner's, where it goes
                            first = f"({_add0(self.edge(0, -1), inx)}, {_add0(self.edge(1, -1), iny)})"
                        w.emit(depth, f"hole {hn} {{ h = {_ctor(sh, first, sizes)} }}")
                        w.emit(depth, f"CornerPattern({hn}, {bname}, inset="
                                      f"{inx if inx == iny else f'({inx}, {iny})'})")
                        self.looped.append((self.sink_members, c, turns.corners(mid)))
                        self.stats.patterns["corner"] += 1
                        return True
                    w.emit(depth, "for sx in [-1, 1] {")
                    w.emit(depth + 1, "for sy in [-1, 1] {")
                    self.hole_block(depth + 2, hn, sh, c, sizes, turns.corners(mid))
                    w.emit(depth + 1, "}")
                    w.emit(depth, "}")
                    self.stats.patterns["corner"] += 1
                    return True
        return False

    def _bolt_circle(self, depth: int, sh, cs: list, centres: list) -> bool:
        """Circles evenly round a centre as a bolt circle (its count, diameter and first
        hole's angle params); False when they are not one."""
        w = self.w
        if sh.kind == "Circle":
            pol = _polar(cs)
            sq = _grid(cs) if len(cs) == 4 else None
            if pol is not None and sq is not None and sq[4] == sq[5] == 2 and \
                    abs(sq[2] - sq[3]) <= EQUAL_TOL and len(_r(sq[2])) < len(_r(2 * pol[1])):
                pol = None      # a square given by its side (31 mm), not its circle (43.84)
            if pol is not None:
                C, R, a0, n = pol
                if PRECISION.get() > EQUAL_TOL and _off_circle(cs, pol) > EQUAL_TOL:
                    self.stats.readings.append(
                        f"{n} holes evenly round a centre to the drawing's own precision "
                        f"({_num(PRECISION.get())} {UNIT.get()}): one bolt circle, its holes "
                        f"written on it exactly")
                around = self.surrounds(C)
                hn = self.name("motor_holes" if around == "Circle" and n == 4 else "bolt_circle")
                pcd = self.p(f"{hn}_pcd", 2 * R, "pitch circle diameter")
                sizes = self.size_params(hn, sh, True)
                cnt = self.p(f"{hn}_n", n, "holes", unit="")
                ang = start_angle(self, hn, a0, n, cnt)
                on_body = self.anchor is not None and \
                    math.dist(C, self.anchor[0].center) <= EQUAL_TOL
                about = self.shared(C) or ("the body centre" if on_body else "its centre")
                w.emit(depth, f"# about {about}, its first hole at {ang.split(' + ')[0]}")
                w.emit(depth, f"for i in range({cnt}) {{")
                self.hole_block(depth + 1, hn, sh, f"polar({self.pos(C)}, {pcd} / 2, {ang})",
                                sizes, turns.polar(C, _start(a0, n), n))
                w.emit(depth, "}")
                centres.append(C)
                self.stats.patterns["bolt circle"] += 1
                return True
        return False

    def pattern(self, depth: int, g: list, body, centres: list) -> bool:
        w = self.w
        cs = [sh.center for sh in g]
        sh = g[0]
        base = _hole_name(sh)
        # four at the corners of the body, centred on it
        if self._corner_set(depth, g, body, sh, base, cs):
            return True
        # a bolt circle: circles evenly round a centre, its count a param
        if self._bolt_circle(depth, sh, cs, centres):
            return True
        # a pair placed symmetrically about the body's centre (mirrored about its axis)
        if self.mirrored(depth, g, body, sh, base, cs):
            return True
        # two in line on either side of the centre line, not mirrored: each from its edge
        if self.straddling(depth, g, sh, base, cs):
            return True
        # a row, a column or a grid
        gr = _grid(cs)
        if gr is not None:
            if not self.perforated(depth, sh, base, gr):    # a field over most of the plate
                self.grid(depth, sh, base, gr)
            return True
        if self.irregular(depth, g, sh, base, cs):  # a fan grille, a gap list, CAD rounding
            return True
        # a hex lattice clipped to a round field, else to a rectangular one (the rosette
        # of seven is a round field), before any other staggered grid
        r = sh.args["radius"] if sh.kind == "Circle" else None
        hf = (_hex_field(cs, r) or _hex_rect(cs, r)) if r is not None else None
        if hf is not None:
            self.hex_field(depth, sh, base, hf)
            return True
        st = _stagger(cs)
        if st is not None:
            self.stagger(depth, sh, base, st)
            return True
        if len(g) == 2:
            # two on a slant: no row a person dimensions; each placed from its own
            # reference, one size param (`holes_2_d` when `holes` is taken)
            sizes = self.size_params(self.name(base + "s"), sh, True)
            for m in g:
                self.sunk_as([m])
                self.hole_block(depth, self.numbered(base) if base == "hole" else
                                self.name(base), m, self.pos(m.center), sizes)
            self.stats.patterns["equal sizes"] += 1
            return True
        ln = _line(cs)
        if ln is not None:
            p0, (dx, dy), n = ln
            hn = self.name(base + "s")
            sizes = self.size_params(hn, sh, True)
            # a slanted row: its pitch along it and its count params, from its first hole
            mid = (p0[0] + dx * (n - 1) / 2, p0[1] + dy * (n - 1) / 2)
            first = f"({self.at(p0[0], 0, mid[0])}, {self.at(p0[1], 1, mid[1])})"
            pitch = self.p(hn + "_pitch", math.hypot(dx, dy), times=n)
            cnt = self.p(hn + "_n", n, unit="")
            c = f"polar({first}, i * {pitch}, {_deg(math.atan2(dy, dx))})"
            w.emit(depth, f"for i in range({cnt}) {{")
            self.hole_block(depth + 1, hn, sh, c, sizes, turns.row(p0, (dx, dy)))
            w.emit(depth, "}")
            self.stats.patterns["row"] += 1
            return True
        # no pattern for them all: rows and columns of three or more among them, the rest
        # one by one, one size param for all
        # (one size param named for the holes, `holes_2_d` when `holes` is taken: a name
        # ending in `_d` as every diameter's)
        stem = next(t for k in range(1, 10 ** 6) for t in [f"{base}s" + (f"_{k}" if k > 1 else "")]
                    if t not in self.used and not any(u.startswith(self.prefix + t + "_")
                                                      for u in self.params.used))
        sizes = self.size_params(stem, sh, True)
        rest = list(g)
        done: set = set()               # (ids) in rows: left out of `rest` after each axis
        for axis in (1, 0):             # equal y: a row along x; equal x: a column
            lines: dict = {}
            for m in rest:
                lines.setdefault(round(m.center[axis], 6), []).append(m)
            for k, members in enumerate(lines.values()):
                self.check(k, "finding the rows among the holes", every=8)
                if len(members) < 3:
                    continue
                pos = sorted(((m.center[1 - axis], m) for m in members), key=lambda t: t[0])
                step = min(b[0] - a[0] for a, b in zip(pos, pos[1:]))
                if step <= EQUAL_TOL:
                    continue
                for run in _runs(pos, step):
                    if len(run) < 3:
                        continue
                    first = run[0][1].center
                    mid = (run[0][0] + run[-1][0]) / 2
                    hn = self.name_near(base + "s", (mid, first[axis]) if axis else
                                        (first[axis], mid))
                    pitch = self.p(hn + "_pitch", step, times=len(run))
                    c = [None, None]
                    cnt = self.p(hn + "_n", len(run), unit="")
                    # by its middle on the centre line, else by its end nearer an edge
                    # (never by its first member: a new pitch or count keeps that end)
                    c[1 - axis] = self.from_body_centre(
                        1 - axis, f"(i - ({cnt} - 1) / 2) * {pitch}", mid) \
                        if self.on_centre(mid, 1 - axis) else \
                        self.run_at(run[0][0], run[-1][0], 1 - axis, "i", cnt, pitch, step)
                    c[axis] = self.at(first[axis], axis)
                    w.emit(depth, f"# row: {follows(c) or 'about its middle'}")
                    w.emit(depth, f"for i in range({cnt}) {{")
                    self.sunk_as([m for _, m in run])
                    self.hole_block(depth + 1, hn, sh, f"({c[0]}, {c[1]})", sizes,
                                    turns.row(first, (step, 0) if axis else (0, step)))
                    w.emit(depth, "}")
                    self.stats.patterns["row"] += 1
                    done.update(id(m) for _, m in run)
            rest = [m for m in rest if id(m) not in done]
        if len(rest) > 2:       # no pattern: a board's holes, one loop, one size
            self.hole_set(depth, rest, sh, base, sizes)
        else:                   # one or two: each from its own reference; beside a row of
            for s in rest:      # their size, each a feature of its own (its own size param)
                hn = self.numbered(base) if base == "hole" else self.name(base)
                own = self.size_params(hn, s, True) if done else sizes
                self.sunk_as([s])
                self.hole_block(depth, hn, s, self.pos(s.center), own)
        if rest:
            self.stats.patterns["equal sizes"] += 1
        return True

    def name_near(self, base: str, c) -> str:
        """``base`` when it is free, else named for where ``c`` sits on the body
        (``top_holes``, ``left_holes``, ``centre_holes``), else numbered."""
        if base not in self.used or self.anchor is None:
            return self.name(base)
        return self._near(base, c)

    def _near(self, base: str, c) -> str:
        sh = self.anchor[0]
        words = []
        for axis, key, lo, hi in ((1, "height", "bottom", "top"), (0, "width", "left", "right")):
            d = c[axis] - sh.center[axis]
            if abs(d) > sh.args[key] / 4:
                words.append(hi if d > 0 else lo)
        return self.name("_".join(words or ["centre"]) + "_" + base)

    def surrounds(self, c) -> str | None:
        """The kind of the shared-centre feature at ``c`` (:meth:`share_centres`), or None."""
        nm = self.shared(c)
        return None if nm is None else getattr(self, "shared_kind", {}).get(nm)

    def single(self, depth: int, sh: Shape, body, centres: list, few: bool = False) -> None:
        """One hole of a size no other has: its sizes params named after it (``slot_length``,
        ``cutout_width``) when the part has ``few`` such holes (:data:`SINGLE_PARAMS`), else
        numbers; a bore (on the body's centre or a pattern's) its ``bore_d``."""
        base = _hole_name(sh)
        sizes: dict = {}
        if sh.kind == "Circle":
            on_axis = any(math.dist(sh.center, c) <= EQUAL_TOL for c in centres) or \
                self.surrounds(sh.center) is not None or \
                (body is not None and math.dist(sh.center, body[0].center) <= EQUAL_TOL)
            if on_axis:
                base = "bore"
                own = self.name("bore")         # (the next free: bore, bore_2, ...)
                sizes = {"diameter": self.p(own + "_d", 2 * sh.args["radius"])}
                self.used.discard(own)          # the hole itself takes it, below
        hn = self.numbered(base) if base == "hole" else self.name(base)
        if few and not sizes:
            sizes = self.size_params(hn, sh, True)
        if sh.kind in ("Rectangle", "RoundedRectangle") and "width" in sizes and \
                abs(sh.args.get("rotation", 0.0)) <= 1e-15 and self.shared(sh.center) is None:
            (x0, y0), (x1, y1) = ((sh.center[k] - sh.args[key] / 2 for k, key in
                                   ((0, "width"), (1, "height"))),
                                  (sh.center[k] + sh.args[key] / 2 for k, key in
                                   ((0, "width"), (1, "height"))))
            xy = (self.span_at(x0, x1, 0, sizes["width"]),
                  self.span_at(y0, y1, 1, sizes["height"]))
            self.write_at(sh.center, xy)
            at = f"({xy[0]}, {xy[1]})"
            self.hole_block(depth, hn, sh, at, sizes)
            return
        if sh.kind == "Polygon":
            self.w.emit(depth, f"hole {hn} {{ h = {_ctor(sh, '')} }}")
            self.w.emit(depth, f"Fixed({hn}.h)")
            return
        # a feature of its own by an edge: its distance from it a param (issue 114)
        self.hole_block(depth, hn, sh, self.pos_from_edges(hn, sh.center) if few and sizes
                        else self.pos(sh.center), sizes)


def _solid(w: _Writer, params: _Params, stats: _Stats, depth: int, name: str, d: Drawing,
           prefix: str, shift=None, marks: Marks | None = None, keep=None, after=None,
           made: list | None = None):
    """Write the solid ``name`` of ``d``; returns how its labels are placed
    (:func:`_label_place`: a drawing of texts on their own layer uses it too).  ``after``:
    the axis along which the part follows the one before it (:func:`_beside`: it grows
    from its edge nearer that part); ``made``: a list the written :class:`_Part` is added
    to."""
    if _unknown(d) or (d.engrave is not None and _unknown(d.engrave)):
        from ..write.program import _structure
        _structure(w, depth, "solid", name, d)
        return lambda p, size: _pt(p)
    part = _Part(w, params, stats, prefix)
    part.shift = shift
    part.marks = marks
    part.keep = keep
    part.after = after
    if made is not None:
        made.append(part)
    loops = [circular(o.segments) for o in d.outlines] + [[c] for c in d.circles]
    # whole ellipses are loops too: a part's outline, a hole, an island in a hole
    every = loops + [[_whole_ellipse(el)] for el in d.ellipses]
    dep = [len(c) for c in _containers(every, w.deadline)] if every else []
    outer = [segs for segs, k in zip(loops, dep) if k == 0]
    holes = [segs for segs, k in zip(loops, dep) if k % 2 == 1]
    islands = [segs for segs, k in zip(loops, dep) if k and k % 2 == 0]
    ell_dep = dep[len(loops):]
    ell_body = [el for el, k in zip(d.ellipses, ell_dep) if k == 0]
    ell_holes = [el for el, k in zip(d.ellipses, ell_dep) if k % 2 == 1]
    ell_islands = [el for el, k in zip(d.ellipses, ell_dep) if k and k % 2 == 0]
    w.emit(depth, f"solid {name} {{")
    body = None
    outer.sort(key=lambda s: -abs(Loop(list(s)).area))
    for i, segs in enumerate(outer):
        if w.deadline is not None and i % 128 == 0:
            w.deadline.check("recognising the outlines of the drawing")
        got = part.body(depth + 1, segs, i == 0)
        if i == 0:
            body = got
    for cx, cy, rx, ry, rot in ell_body:
        w.emit(depth + 1, f"{part.name('oval')} = Ellipse(center={_pt((cx, cy))}, "
                          f"rx={_num(rx)}, ry={_num(ry)}, rotation={_num(math.degrees(rot))} deg)")
    part.holes(depth + 1, holes, body)
    for cx, cy, rx, ry, rot in ell_holes:
        hn = part.name("oval")
        w.emit(depth + 1, f"hole {hn} {{ e = Ellipse(center={_pt((cx, cy))}, rx={_num(rx)}, "
                          f"ry={_num(ry)}, rotation={_num(math.degrees(rot))} deg) }}")
    # a cut role's open paths are through-cuts (as `aidl import` writes them); its loops
    # that cross themselves stay engraved, counted
    cut = [p for p in d.paths if p.crossing is None] if d.paths_cut else []
    if cut:
        w.emit(depth + 1, "cut cuts {")
        w.cut_paths += len(cut)
        w.cut_length += sum(_length(p.segments) for p in cut)
        for i, p in enumerate(cut):
            if w.deadline is not None and i % 128 == 0:
                w.deadline.check("writing the cut paths")
            if w.chain(depth + 2, p.segments, False, f"p{i + 1}_"):
                _emit_holds(w, depth + 2, _holds(p.segments, f"p{i + 1}_", False), "q")
            else:
                w.notes.append(Note("W0130", f"a cut path of `{name}` holds a piece no "
                                             f"statement writes: left out"))
        w.emit(depth + 1, "}")
        w.emit(depth + 1, "Fixed(cuts)")
    cut_ids = {id(p) for p in cut}
    drawn = [p for p in d.paths if id(p) not in cut_ids]
    if d.paths_cut:
        w.crossed += len(drawn)
    eng = Drawing(paths=drawn, texts=list(d.texts), engrave=d.engrave)
    place = _label_place(part, holes)
    if eng.paths or eng.texts or (eng.engrave is not None and
                                  (not eng.engrave.empty or eng.engrave.texts)):
        w.emit(depth + 1, "drawing engraving {")
        _engraving(w, depth + 2, eng, stats, place)
        w.emit(depth + 1, "}")
        w.emit(depth + 1, "Fixed(engraving)")
    w.emit(depth, "}")
    for k, segs in enumerate(islands):
        w.emit(depth, f"solid {name}_island{k + 1} {{")
        isl = _Part(w, params, stats, prefix)
        isl.shift = shift
        isl.body(depth + 1, segs, False)
        w.emit(depth, "}")
    for k, (cx, cy, rx, ry, rot) in enumerate(ell_islands, start=len(islands) + 1):
        w.emit(depth, f"solid {name}_island{k} {{")
        w.emit(depth + 1, f"oval = Ellipse(center={_pt((cx, cy))}, rx={_num(rx)}, "
                          f"ry={_num(ry)}, rotation={_num(math.degrees(rot))} deg)")
        w.emit(depth, "}")
    return place


def to_program_inferred(layers: list[tuple[str, Drawing]], source: str, parts: bool = False,
                        deadline=None) -> tuple[str, list[Note]]:
    """:func:`_inferred` with the drawing's own precision (:data:`~.shapes.PRECISION`, in
    the program's unit: the coarsest of its layers', issue 114) in force."""
    from ..model import UNIT_MM
    prec = max((getattr(d, "precision", 0.0) for _, d in layers), default=0.0)
    token = PRECISION.set(prec / UNIT_MM[UNIT.get()])
    try:
        return _inferred(layers, source, parts, deadline)
    finally:
        PRECISION.reset(token)


def _inferred(layers: list[tuple[str, Drawing]], source: str, parts: bool = False,
              deadline=None) -> tuple[str, list[Note]]:
    """The AIDL text of a drawing read layer by layer, as :func:`~.program.to_program` takes
    it (``parts``: a sheet, one solid per outer loop; ``deadline``: the import's), written as
    recognised shapes, patterns and parameters (module doc), its head comment saying what
    was recognised (pieces -> shapes, patterns) and the tolerances; and the notes of what was
    left out.  Lengths in mm.  Raises :class:`~.model.DrawingError` ``E0304`` before any
    inference when :func:`infer_seconds` would end past ``deadline``, and
    :class:`~aidl_lang.base.limits.OutOfBudget` once it has passed (each stage looks at it as it
    goes; :func:`~.program.import_drawing` words it as ``E0304``)."""
    _refuse_too_large(layers, source, deadline)
    w = _Writer(deadline)
    params = _Params()
    stats = _Stats()
    layers, moved = _hole_layers(layers, deadline)
    items = in_unit(_layer_items(layers, parts, deadline, source, w.notes, w.overlaps))
    items = _copies(items, deadline)
    items = beside_order(_named_parts(pair_items(items, deadline)), parts)
    marks = Marks(items)        # countersinks, written with their holes
    solids = sum(1 for it in items if it[0] == "solid")
    multi = len(items) > 1 or any(len(it) > 3 for it in items)
    depth = 1 if multi else 0
    if multi:
        w.emit(0, "assembly " + ("sheet" if parts else "drawing_import") + " {")
    short = _short_names([it[1] for it in items])
    names = []
    prev = None             # the plain part written last: (name, Drawing, _Part)
    drawings = []           # (line index, name, d): written after the parts, placed by them
    place = _at_as_drawn
    for kind, name, d, *rep in items:
        if kind == "drawing":
            drawings.append((len(w.lines), name, d))
        elif rep:
            (x0, y0), (dx, dy), n = rep[0]
            pre = short[name] + "_"
            nm_x = pre + "pitch_x" if abs(dy) > ROUND_TOL else pre + "pitch"
            sx = f"k * {params.add(nm_x, dx, times=n)}" \
                if abs(dx) > ROUND_TOL else None
            sy = f"k * {params.add(pre + 'pitch_y' if sx else pre + 'pitch', dy, times=n)}" \
                if abs(dy) > ROUND_TOL else None
            w.emit(depth, f"for k in range({params.add(pre + 'n', n, 'copies', unit='')}) {{")
            _solid(w, params, stats, depth + 1, name, d, pre, (sx, sy), marks)
            if multi:
                w.emit(depth + 1, f"Fixed({name})")
            w.emit(depth, "}")
            stats.patterns["row of parts"] += 1
            prev = None
            continue
        elif kind == "solid" and (pair := mirrored_pair(d, deadline)) is not None:
            word = _named_parts([("solid", "part", pair[0])])[0][1]
            write_pair(w, depth, name if name != word else word + "s", pair[0], pair[1], d.box(),
                       word, lambda dp, nm, dd: _solid(w, params, stats, dp, nm, dd, "", marks=marks,
                                                         keep=pair[1], shift=pair_gap(dd, pair[1], params, stats)))
            stats.patterns["mirrored part"] += 1
            name = name if name != word else word + "s"
            prev = None
        else:
            pre = short[name] + "_" if solids > 1 else ""
            got = _beside(prev, d, params, pre, stats) if not parts and solids <= 3 else None
            made: list = []
            placed = _solid(w, params, stats, depth, name, d, pre, marks=marks,
                            shift=got and got[1], after=got and got[0], made=made)
            place = placed if solids == 1 else _at_as_drawn
            names.append(name)
            prev = (name, d, made[0] if made else None)
            continue
        names.append(name)
    # a layer of texts beside one part (LABELS beside OUTLINE): its labels placed with the
    # part's features, as the part's own engraving is
    for at, name, d in reversed(drawings):
        if (d := marks.left(name, d)) is None:
            names.remove(name)          # every mark of it written with its hole
            continue
        start = len(w.lines)
        w.emit(depth, f"drawing {name} {{")
        _engraving(w, depth + 1, d, stats, place)
        w.emit(depth, "}")
        written = w.lines[start:]
        del w.lines[start:]
        w.lines[at:at] = written
    if multi and len(names) > 1:
        w.emit(depth, f"for p in [{', '.join(names)}] {{ Fixed(p) }}")
    elif multi and names:
        w.emit(depth, f"Fixed({names[0]})")
    if multi:           # a drawing layer on a part (a board's silkscreen): engraved on it
        kept = set(names)
        on = engraved_on([(it[1], it[2]) for it in items if it[0] == "drawing" and it[1] in kept],
                         [(it[1], it[2]) for it in items if it[0] == "solid" and it[1] in kept])
        for drawn, part in on.items():
            w.emit(depth, f"CutInto({drawn}, {part})")
        w.emit(0, "}")
    _cut_notes(w, source)
    head = [f"# imported from {source} by `aidl import --infer`: edit freely"]
    head += ["# " + ln for ln in _summary(stats) + moved + stats.readings + _far(stats)] + \
        [f"units {UNIT.get()}"]
    text = "\n".join(head + params.lines + w.lines) + "\n"
    return text, w.notes


# CPU seconds of inferring a design, to refuse one sure to end past the deadline before it
# starts: a start and each piece of the drawing (a quiet machine, issue 83: the 20,000-hole
# panel 0.69 s, 35 us a piece; the slowest drawings measured, 8,000 holes in no one
# pattern or each of its own size, 46 us)
INFER_START = 0.05
INFER_PER_PIECE = 60e-6


def infer_seconds(layers: list[tuple[str, Drawing]]) -> float:
    """The estimate (s) of :func:`to_program_inferred` of ``layers``: :data:`INFER_START`
    and :data:`INFER_PER_PIECE` for each line, arc, curve, circle, ellipse and text."""
    from ..write.program import _count_segments
    return INFER_START + INFER_PER_PIECE * sum(_count_segments(d) for _, d in layers)


def _refuse_too_large(layers: list, source: str, deadline) -> None:
    """``E0304`` (a :class:`~.model.DrawingError`) before any inference when
    :func:`infer_seconds` of ``layers`` would end past ``deadline`` (the import's)."""
    if deadline is None:
        return
    from ...base.limits import OutOfBudget, seconds_as_work
    from ..model import DrawingError
    from ..write.program import _count_segments
    try:
        deadline.check("inferring the design", ahead=seconds_as_work(infer_seconds(layers)))
    except OutOfBudget as ex:
        pieces = sum(_count_segments(d) for _, d in layers)
        raise DrawingError(
            "E0304", f"inferring the design of `{source}` ({pieces} lines, arcs, curves and "
                     f"texts) would end past the budget ({ex.what}): refused before it "
                     f"started",
            "import it without --infer (its exact pieces), a part of it with --layer, or "
            "raise --budget") from None


def import_drawing(data: bytes, name: str, infer: bool = False, **options):
    """``aidl import [--infer]``: :func:`~.program.import_drawing` of ``data`` (``name``: its
    file name, ``options`` its keywords: ``unit``, ``layer``, ``parts``, ``budget``, ...),
    the program written by :func:`to_program_inferred` when ``infer``, else piece by piece.
    Returns ``(program text, notes)``; raises :class:`~.read.DrawingError`."""
    from ..write.program import import_drawing as _import
    return _import(data, name, writer=to_program_inferred if infer else None, **options)
