"""Where an inferred part's features are placed from (issue 85, "anchoring as the drawing
means it"): the body grows from the point its drawing is drawn from (:meth:`_Anchored.
grows_from`: a corner at the origin, else its centre), and each feature is written from the
body's reference nearest it (an edge, or the centre line; ties to the centre), so that a new
width or height keeps it where the drawing ties it: a single feature by its centre
(:meth:`~_Anchored.at`), a cut-out by its near side (:meth:`~_Anchored.span_at`), a row by
its end member nearer an edge or by its middle (:meth:`~_Anchored.run_at`), a key, a tab or
a label with the feature it belongs to (:meth:`~_Anchored.beside`).  Coordinates in mm; the
results are program text."""
from __future__ import annotations

from .params import _center, _plus, _r
from .shapes import ROUND_TOL, Shape
from .patterns.turns import at_turn


def _add(text: str, d: float) -> str:
    """``text + d`` as text (``d`` in mm; the number alone when ``text`` is 0)."""
    if abs(d) <= ROUND_TOL:
        return text
    if text == "0":
        return _r(d)
    return f"{text} + {_r(d)}" if d > 0 else f"{text} - {_r(-d)}"


CENTRE_TOL = 1e-6   # mm: a feature (a span's middle) this near the centre line is on it
# a row's end member nearer its edge than this many pitches sits at a set distance from it
# (docs/import.md, "What an edit means": terminals 10 mm in on a 9 mm pitch keep that end;
# pots 30 mm in on a 20 mm pitch change pitch about their middle)
SET_END = 1.5


def _tied(gaps: dict) -> int:
    """The body's reference a feature is tied to, from its distances ``gaps`` (mm) to the
    centre line (key 0) and to the low and high edges (keys -1, 1): the centre line when
    it is on it (as far from both edges: a maker means the centre), else the nearer edge
    (a feature off the centre line is dimensioned from an edge; ties: the low edge)."""
    if gaps[0] <= CENTRE_TOL:
        return 0
    return min((-1, 1), key=lambda k: (round(gaps[k], 9), k))


class _Anchored:
    """The placing half of :class:`~.infer._Part`: needs ``anchor`` (the body Shape and its
    size params, or None), ``frame`` (per axis what stays: -1, 0, 1), ``shift`` (terms added
    to every position, or None), ``named`` / ``named_as`` (shared centres), ``shared`` and
    ``written`` (``{centre: (x text, y text)}``, :meth:`write_at`) and ``looped`` (the
    patterns written, ``(members, centre text, index)``: :meth:`written_at` places a label
    by its member's turn, :func:`~.turns.at_turn`)."""

    def plus(self, v: float, term: str, axis: int = 0) -> str:
        if self.shift is not None and self.shift[axis]:
            return _plus(v, f"{self.shift[axis]} + {term}")
        return _plus(v, term)

    def center(self, c) -> str:
        if self.shift is None:
            return _center(c)
        return "(" + ", ".join(_plus(c[i], self.shift[i]) if self.shift[i] else _r(c[i])
                               for i in (0, 1)) + ")"

    def lit(self, v: float, axis: int) -> str:
        """Coordinate ``v`` as a number (after the part's shift, when it has one)."""
        return self.center((v, v))[1:-1].split(", ")[axis]

    def grows_from(self, sh: Shape) -> tuple:
        """What stays of the body ``sh`` when its width (height) param changes, per axis
        (:attr:`frame`): the edge or the centre that the drawing's origin is on (a plate
        drawn from its corner at (0, 0) grows from that corner, one drawn about the origin
        about its centre); the centre when the origin is on none of them."""
        out = []
        for axis, key in ((0, "width"), (1, "height")):
            c, half = sh.center[axis], sh.args[key] / 2
            out.append(next((g for g in (-1, 1) if abs(c + g * half) <= ROUND_TOL), 0))
        return tuple(out)

    def edge(self, axis: int, side: int) -> str:
        """The body's centre (``side`` 0) or its left/right (bottom/top) edge (-1/1) along
        ``axis`` as the text that follows its size param from what stays (:attr:`frame`):
        ``width / 2`` for the centre of a plate that grows from its left edge at 0."""
        sh, sizes = self.anchor
        key = "width" if axis == 0 else "height"
        c, half = sh.center[axis], sh.args[key] / 2
        g = self.frame[axis]
        k = side - g                    # halves of the size from what stays
        if k == 0:
            return self.lit(c + side * half, axis)
        size = sizes[key]
        term = {1: f"{size} / 2", -1: f"-{size} / 2", 2: size, -2: f"-{size}"}[k]
        return self.plus(c + g * half, term, axis)

    def at(self, v: float, axis: int, ref: float | None = None, nearest: bool = False) -> str:
        """Coordinate ``v`` (``axis`` 0: x, 1: y) written from the body's reference that
        ``ref`` (default ``v``) is tied to (:func:`_tied`): its centre line when on it, else
        its nearer left/right (bottom/top) edge by the width (height) param, so that a new
        width moves what sits by an edge with the edge and keeps what sits on the centre
        line on it; a number where that reference is what stays (:meth:`edge`).
        ``nearest``: the reference nearest ``ref`` whatever it is, ties to the centre (a
        group of holes listed together, a board's, placed by its middle: it moves as one,
        with the centre it is nearest, as a board centred on the plate does)."""
        if self.anchor is None:
            return self.lit(v, axis)
        if getattr(self, "profile", None) is not None:
            return self.profile_at(v, axis)     # by the profile's faces (profiles/)
        sh, sizes = self.anchor
        key = "width" if axis == 0 else "height"
        c, half = sh.center[axis], sh.args[key] / 2
        r = v if ref is None else ref
        gaps = {k: abs(r - c - k * half) for k in (0, -1, 1)}
        side = min((0, -1, 1), key=lambda k: (round(gaps[k], 9), k != 0)) if nearest \
            else _tied(gaps)
        return self.from_side(v, axis, side)

    def from_side(self, v: float, axis: int, side: int) -> str:
        """Coordinate ``v`` written from the body's centre (``side`` 0) or its low/high edge
        (-1/1) along ``axis``; a number where that reference is what stays."""
        sh, _ = self.anchor
        c = sh.center[axis]
        half = sh.args["width" if axis == 0 else "height"] / 2
        if side == self.frame[axis]:
            return self.lit(v, axis)
        if side and side == -self.frame[axis] and getattr(self, "stats", None) is not None:
            self.stats.far.add((axis, side))        # said in the program's head
        return _add(self.edge(axis, side), v - (c + side * half))

    def write_at(self, c, at: tuple) -> None:
        """Note that the feature centred at ``c`` (mm) is written at ``at`` (its x and y
        text, :meth:`span_at`'s for a cut-out), so that its label follows it
        (:meth:`written_at`)."""
        self.written[(round(c[0], 9), round(c[1], 9))] = at

    def written_at(self, v: float, axis: int, base) -> str:
        """Coordinate ``v`` (mm along ``axis``) of a text beside the feature centred at
        ``base``: that feature's place as written plus the offset (a label under a cut-out
        moves with its centre when its width changes, :meth:`write_at`), else placed from
        the body's reference ``base`` is tied to (:meth:`at`)."""
        key = (round(base[0], 9), round(base[1], 9))
        got = self.written.get(key)
        if got is None and self.looped:         # a member of a pattern: its turn's place
            for members, center, index in self.looped:
                for m in members:
                    self.written.setdefault((round(m.center[0], 9), round(m.center[1], 9)),
                                            (center, index(m)))
            self.looped = []
            got = self.written.get(key)
        if got is not None and isinstance(got[1], tuple):
            got = self.written[key] = at_turn(*got)
        if got is None:
            return self.at(v, axis, ref=base[axis])
        return _add(got[axis], v - base[axis])

    def on_centre(self, v: float, axis: int) -> bool:
        """Whether coordinate ``v`` (mm along ``axis``) is on the body's centre line."""
        if self.anchor is None:
            return False
        sh = self.anchor[0]
        return abs(v - sh.center[axis]) <= CENTRE_TOL

    def span_at(self, lo: float, hi: float, axis: int, size: str) -> str:
        """The centre of a span ``lo..hi`` (a cut-out's sides along ``axis``, mm) whose size
        is the param ``size``: kept from the body's edge nearest its near side (``width -
        6 - cutout_width / 2``: a wider cut-out grows away from the edge it is dimensioned
        from) or, nearer the centre line, centred as :meth:`at` places it."""
        mid = (lo + hi) / 2
        if self.anchor is None:
            return self.at(mid, axis)
        sh = self.anchor[0]
        key = "width" if axis == 0 else "height"
        c, half = sh.center[axis], sh.args[key] / 2
        gaps = {0: abs(mid - c), -1: lo - (c - half), 1: (c + half) - hi}
        side = _tied(gaps)
        if side == 0:
            return self.at(mid, axis, ref=c)
        gap = gaps[side]
        edge = self.edge(axis, side)
        if edge == "0":
            head = f"{size} / 2" if side < 0 else f"-{size} / 2"
        else:
            head = f"{edge} {'+' if side < 0 else '-'} {size} / 2"
        return _add(head, -side * gap)

    def run_at(self, first: float, last: float, axis: int, var: str, cnt: str,
               pitch: str, step: float | None = None, name: str | None = None) -> str:
        """Member ``var`` of a row from ``first`` to ``last`` (mm along ``axis``, ``cnt``
        members ``pitch`` apart, ``step`` mm): by the spec (docs/import.md, "What an edit
        means"), by its end member when that end sits nearer its edge than :data:`SET_END`
        ``step`` (the row grows away from the edge), else by its middle placed from the
        body's nearer edge (a new pitch or count spreads it about its centre).  Without
        ``step``: from the body's edge nearer its end member than the row's middle is to the
        centre line, by that end member; nearer the centre line but not on it, by the end
        member nearer its edge (never by its first member).  ``name``: the param that holds
        the distance of the end member (or of the middle) from its edge, when it is placed
        from one (``holes_x``: "move the board 10 mm in" is one number, issue 114); without
        it that distance is a number in the text."""
        lo, hi = min(first, last), max(first, last)
        if step is not None and self.anchor is not None and self.on_centre((lo + hi) / 2, axis):
            k = f"({var} - ({cnt} - 1) / 2)" if last >= first else f"(({cnt} - 1) / 2 - {var})"
            return self.from_body_centre(axis, f"{k} * {pitch}", (lo + hi) / 2)
        if step is not None and self.anchor is not None:
            sh = self.anchor[0]
            key = "width" if axis == 0 else "height"
            c, half = sh.center[axis], sh.args[key] / 2
            gl, gh = lo - (c - half), (c + half) - hi
            if min(gl, gh) >= SET_END * step - 1e-9:    # no end at a set distance: its middle
                k = f"({var} - ({cnt} - 1) / 2)" if last >= first else \
                    f"(({cnt} - 1) / 2 - {var})"
                mid = self.edge_param(name, (lo + hi) / 2, axis, "its middle")
                return f"{k} * {pitch}" if mid == "0" else f"{mid} + {k} * {pitch}"
            side = -1 if gl <= gh else 1
        else:
            side = self.nearest(lo, hi, axis)
        if side == 0 and self.anchor is not None:
            # off the centre line (a centred run is written by its middle before this):
            # by the end nearer its edge, never by its first member
            sh = self.anchor[0]
            key = "width" if axis == 0 else "height"
            c, half = sh.center[axis], sh.args[key] / 2
            side = 1 if (c + half) - hi < lo - (c - half) else -1
        by_edge = name is not None and self.anchor is not None and side != 0 and \
            getattr(self, "profile", None) is None
        if side > 0 and last > first or side < 0 and last < first:
            end = self.from_edge(name, last, axis, side, "its end member") if by_edge else \
                self.from_side(last, axis, side) if self.anchor is not None else \
                self.at(last, axis, ref=last)
            term = f"({var} - ({cnt} - 1)) * {pitch}"
        else:
            end = self.from_edge(name, first, axis, side, "its end member") if by_edge else \
                self.from_side(first, axis, side) if self.anchor is not None and side else \
                self.at(first, axis, ref=(first + last) / 2)
            term = f"{var} * {pitch}"
        return term if end == "0" else f"{end} + {term}"

    def nearest(self, lo: float, hi: float, axis: int) -> int:
        """The body's reference a span ``lo..hi`` (mm along ``axis``) is tied to: -1 its low
        edge (by the span's near end), 1 its high edge, 0 its centre line (by the span's
        middle); ties go to the centre, then the low edge; 0 without a body."""
        if self.anchor is None:
            return 0
        sh = self.anchor[0]
        key = "width" if axis == 0 else "height"
        c, half = sh.center[axis], sh.args[key] / 2
        gaps = {0: abs((lo + hi) / 2 - c), -1: lo - (c - half), 1: (c + half) - hi}
        return _tied(gaps)

    def from_body_centre(self, axis: int, term: str, c: float) -> str:
        """``term`` added to the body's centre along ``axis`` (``c``, mm, as drawn), which
        follows the body's size param when the body grows from an edge (:meth:`edge`)."""
        if self.anchor is None or self.frame[axis] == 0:
            return self.plus(c, term, axis)
        e = self.edge(axis, 0)
        return f"{e} - {term[1:]}" if term.startswith("-") else f"{e} + {term}"

    def body_centre(self, sh: Shape) -> str:
        """The body's centre as written: numbers, or following its size params from the
        edge it grows from (:attr:`frame`)."""
        if self.anchor is None or self.anchor[0] is not sh:
            return self.center(sh.center)
        return f"({self.edge(0, 0)}, {self.edge(1, 0)})"

    def from_edge(self, name: str, v: float, axis: int, side: int, what: str) -> str:
        """Coordinate ``v`` (mm along ``axis``) written from the body's low (``side`` -1)
        or high (1) edge by a param ``name`` of its distance from that edge (``what`` it
        measures, said in its comment): ``board_x``, ``width - hole1_x``; a maker moves the
        feature in from its edge by that one number (issue 114)."""
        edge = self.anchor[0].center[axis] + side * self.anchor[0].args[
            "width" if axis == 0 else "height"] / 2
        word = {(0, -1): "left", (0, 1): "right", (1, -1): "bottom", (1, 1): "top"}[(axis, side)]
        g = self.p(name, -side * (v - edge), f"{what}, from the {word} edge")
        if side == -self.frame[axis] and getattr(self, "stats", None) is not None:
            self.stats.far.add((axis, side))        # said in the program's head
        e = self.edge(axis, side)
        if side < 0:
            return g if e == "0" else f"{e} + {g}"
        return f"-{g}" if e == "0" else f"{e} - {g}"

    def from_centre(self, name: str, v: float, axis: int, what: str) -> str:
        """Coordinate ``v`` (mm along ``axis``) written from the body's centre line by a param
        ``name`` of its signed distance from it (``what`` it measures, said in its comment;
        + to the right, upward): ``width / 2 + holes_x``; a set placed from the centre is
        moved by that one number, as one placed from an edge is (issue 114)."""
        sh = self.anchor[0]
        line, sense = ("vertical", "+ to the right") if axis == 0 else ("horizontal", "+ upward")
        g = self.p(name, v - sh.center[axis], f"{what}, from the {line} centre line ({sense})")
        e = self.edge(axis, 0)
        return g if e == "0" else f"{e} + {g}"

    def edge_param(self, name: str | None, v: float, axis: int, what: str) -> str:
        """Coordinate ``v`` (mm along ``axis``) of a set placed by ``what`` (its middle, its
        row's line): by :meth:`at`, but where that ties it to an edge, its distance from the
        edge the param ``name`` (:meth:`from_edge`); as :meth:`at` without ``name``, on the
        centre line, in a profile, without a body or outside the body."""
        if name is None or self.anchor is None or getattr(self, "profile", None) is not None:
            return self.at(v, axis)
        sh = self.anchor[0]
        half = sh.args["width" if axis == 0 else "height"] / 2
        side = _tied({k: abs(v - sh.center[axis] - k * half) for k in (0, -1, 1)})
        if side == 0 or -side * (v - sh.center[axis] - side * half) <= 0:
            return self.at(v, axis)
        return self.from_edge(name, v, axis, side, what)

    def pos_from_edges(self, hn: str, c) -> str:
        """:meth:`pos` of a single feature ``hn`` centred at ``c``, each coordinate tied to
        an edge (:meth:`at`) written by a param of its distance from it (``hn_x``,
        ``hn_y``: :meth:`from_edge`), so the maker's "move it 15 mm in" is one number."""
        if self.anchor is None or self.shared(c) is not None or \
                getattr(self, "profile", None) is not None:
            return self.pos(c)
        out = []
        for axis, word in ((0, "x"), (1, "y")):
            sh = self.anchor[0]
            half = sh.args["width" if axis == 0 else "height"] / 2
            side = _tied({k: abs(c[axis] - sh.center[axis] - k * half) for k in (0, -1, 1)})
            inside = -side * (c[axis] - sh.center[axis] - side * half) > 0   # (not in a tab)
            out.append(self.at(c[axis], axis) if side == 0 or not inside else
                       self.from_edge(f"{hn}_{word}", c[axis], axis, side, "its centre"))
        return f"({out[0]}, {out[1]})"

    def pos(self, c) -> str:
        """A point, as a shared centre's name when it is one, else placed by :meth:`at`."""
        return self.shared(c) or f"({self.at(c[0], 0)}, {self.at(c[1], 1)})"

    def beside(self, base, p) -> str:
        """Point ``p`` of a feature whose main shape is at ``base`` (a key beside its bore,
        a tab of a window): numbers where ``base`` is written as numbers, else ``base``'s
        place (:meth:`pos`) plus the offset, so that it moves with the feature."""
        if self.pos(base) == self.center(base):
            return self.center(p)
        return f"({self.at(p[0], 0, ref=base[0])}, {self.at(p[1], 1, ref=base[1])})"
