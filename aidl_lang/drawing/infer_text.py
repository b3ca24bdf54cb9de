"""``aidl import --infer``: engraved strokes that are a line of text in the built-in stroke
font (issue 71; docs/import.md, "Inferring the design"; used by :func:`~.infer._engraving`).

In: line segments ``((x0, y0), (x1, y1))`` in mm (the engraving's polylines and polygons of
lines, as AIDL writes a ``Text``).  Out: ``(text, position, size)`` for ``Text(text,
position=, size=, anchor="start", valign="baseline")`` when the segments are exactly that
text's strokes (:func:`~aidl_lang.geometry.text.text_strokes`, unturned), each within
:data:`TOL`; else None.  Decoded glyph by glyph from the leftmost stroke: the first glyph
fixes the scale and the pen's origin, each next one is the glyph whose strokes all lie at
the pen (a space where none does), until every segment is used; the text found is then drawn
again by :func:`~aidl_lang.geometry.text.text_strokes` and must give every segment back.
"""
from __future__ import annotations

import math
from functools import lru_cache

from ..geometry.text import _baseline, _cap_height, _glyphs, _raw, text_strokes

TOL = 1e-7          # mm: each stroke end of the text found against the drawing's
MAX_SEGMENTS = 4000
MAX_SPACES = 1      # spaces in a row between two glyphs (two words)


class _Index:
    """The segments by the cells of their ends, each found once."""

    def __init__(self, segs: list, cell: float) -> None:
        self.segs, self.cell = segs, cell
        self.used = [False] * len(segs)
        self.cells: dict = {}
        for i, (a, b) in enumerate(segs):
            for p in (a, b):
                self.cells.setdefault(self._c(p), set()).add(i)

    def _c(self, p) -> tuple:
        return (math.floor(p[0] / self.cell), math.floor(p[1] / self.cell))

    def find(self, a, b, taken: set) -> int | None:
        cx, cy = self._c(a)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for i in self.cells.get((cx + dx, cy + dy), ()):
                    if self.used[i] or i in taken:
                        continue
                    s, e = self.segs[i]
                    if (math.dist(s, a) <= TOL and math.dist(e, b) <= TOL) or \
                            (math.dist(e, a) <= TOL and math.dist(s, b) <= TOL):
                        return i
        return None


def _glyph_segments() -> list:
    """``[(char, [segments in font units at pen 0], advance)]``: letters and digits first,
    then the rest, the glyphs of more segments first (a glyph whose strokes are a part of
    another's is tried after it)."""
    out = []
    for c, (strokes, adv) in _glyphs().items():
        segs = [s for st in strokes for s in zip(st, st[1:])]
        if segs and c.isprintable() and not c.isspace():
            out.append((c, segs, adv))
    out.sort(key=lambda t: (not t[0].isalnum(), -len(t[1]), t[0]))
    return out


def _place(segs, k: float, ox: float, oy: float) -> list:
    return [((ox + k * a[0], oy + k * a[1]), (ox + k * b[0], oy + k * b[1])) for a, b in segs]


def _match(ix: _Index, segs, k, ox, oy) -> list | None:
    taken: set = set()
    for a, b in _place(segs, k, ox, oy):
        i = ix.find(a, b, taken)
        if i is None:
            return None
        taken.add(i)
    return list(taken)


@lru_cache(maxsize=1)
def _by_direction() -> dict:
    """The glyphs' segments by their direction (radians mod pi, to 1e-3): ``{bucket: [(char,
    its segments, the segment's ends p, q in the direction's sense)]}``."""
    out: dict = {}
    for c, gs, adv in _glyph_segments():
        for a, b in gs:
            g = (b[0] - a[0], b[1] - a[1])
            if math.hypot(*g) <= 1e-12:
                continue
            t = math.atan2(g[1], g[0])
            p, q = (a, b) if 0 <= t < math.pi else (b, a)
            out.setdefault(round(math.atan2(q[1] - p[1], q[0] - p[0]) % math.pi, 3),
                           []).append((c, gs, p, q))
    return out


def _starts(s0, glyphs: list):
    """Every ``(char, its segments, scale, origin x, origin y)`` by which a glyph's segment is
    the segment ``s0`` (unturned: parallel, the same way or reversed)."""
    v = (s0[1][0] - s0[0][0], s0[1][1] - s0[0][1])
    L = math.hypot(*v)
    if L <= 1e-12:
        return
    key = round(math.atan2(v[1], v[0]) % math.pi, 3)
    table = _by_direction()
    for b in {key, round(key - 1e-3, 3), round(key + 1e-3, 3), 0.0, round(math.pi, 3)}:
        for c, gs, a, bq in table.get(b, ()):
            for p, q in ((a, bq), (bq, a)):
                g = (q[0] - p[0], q[1] - p[1])
                k = L / math.hypot(*g)
                if k > 1e-9 and abs(v[0] - k * g[0]) <= TOL and abs(v[1] - k * g[1]) <= TOL:
                    yield c, gs, k, s0[0][0] - k * p[0], s0[0][1] - k * p[1]


def _decode(ix: _Index, glyphs: list, space: float, k: float, ox: float, oy: float):
    """The text read from the pen at ``(ox, oy)`` on scale ``k``: glyph after glyph (a
    space where none lies at the pen), and the segments it used."""
    text, pen, spaces, used = "", 0.0, 0, []
    while True:
        for c, gs, adv in glyphs:
            got = _match(ix, gs, k, ox + k * pen, oy)
            if got is not None:
                for i in got:
                    ix.used[i] = True
                used += got
                text += " " * spaces + c
                pen += adv
                spaces = 0
                break
        else:
            spaces += 1
            pen += space
            if spaces > MAX_SPACES or space <= 0:
                return text, used


MAX_TRIES = 100     # texts read in all (a start whose glyph lies whole at it)
MAX_LOOKS = 5000    # (start segment, glyph, scale) hypotheses looked at in all


def _left(ix: _Index, glyphs: list, space: float, k: float, ox: float, oy: float):
    """The glyphs before the pen at ``ox`` (a text's start found inside it): ``(the new
    origin x, their text, the segments they used)``."""
    text, used = "", []
    while True:
        for n in range(MAX_SPACES + 1):
            hit = None
            for c, gs, adv in glyphs:
                x = ox - k * (adv + n * space)
                got = _match(ix, gs, k, x, oy)
                if got is not None:
                    hit = (c, x, got)
                    break
            if hit is not None:
                break
        if hit is None:
            return ox, text, used
        c, ox, got = hit
        for i in got:
            ix.used[i] = True
        used += got
        text = c + " " * n + text


def stroke_texts(polys: list) -> list:
    """The lines of unturned built-in-font text among ``polys`` (each a list of segments
    ``((x0, y0), (x1, y1))`` in mm: a polyline or polygon of the engraving): ``[(text,
    (x, y), size, {indices of the polys it is})]``, each text two or more glyphs made of
    whole polys and drawn again by ``Text`` to :data:`TOL`.  What is no text (a tick, a
    shape) is left.  At most :data:`MAX_TRIES` reads and :data:`MAX_LOOKS` hypotheses in
    all, started on strokes of several segments only (a text of one-line glyphs alone,
    ``HI``, stays strokes)."""
    segs = [s for p in polys for s in p]
    if not 2 <= len(segs) <= MAX_SEGMENTS:
        return []
    owner = [i for i, p in enumerate(polys) for _ in p]
    members: dict = {}
    for j, i in enumerate(owner):
        members.setdefault(i, []).append(j)
    glyphs = _glyph_segments()
    space = _glyphs().get(" ", ((), 0.0))[1]
    ix = _Index(segs, max(1e-3, 64 * TOL))
    out: list = []
    tries = looks = 0
    while ix.used.count(False) >= 2 and tries < MAX_TRIES:
        # starts on strokes of several segments (a glyph's; a tick is one line): a text is
        # read from any of its glyphs, both ways
        order = sorted((j for j in range(len(segs)) if not ix.used[j] and
                        len(members[owner[j]]) > 1),
                       key=lambda j: (min(segs[j][0][0], segs[j][1][0]), j))
        found = None
        for j0 in order:
            seen: set = set()
            for c, gs, k, ox, oy in _starts(segs[j0], glyphs):
                key = (round(k, 9), round(ox, 6), round(oy, 6))
                if key in seen:
                    continue
                seen.add(key)
                looks += 1
                if looks > MAX_LOOKS:
                    tries = MAX_TRIES + 1
                    break
                if _match(ix, gs, k, ox, oy) is None:
                    continue            # the glyph the start is of is not whole here
                tries += 1
                if tries > MAX_TRIES:
                    break
                x0, pre, before = _left(ix, glyphs, space, k, ox, oy)
                text, used = _decode(ix, glyphs, space, k, ox, oy)
                text, used, ox = pre + text, before + used, x0
                whole = {owner[j] for j in used}
                good = sum(ch.isalnum() for ch in text) >= 2 and not text.startswith(" ") \
                    and j0 in used and sum(len(members[i]) for i in whole) == len(used) \
                    and any(len(gs) >= 3 for ch, gs, _ in glyphs if ch in text)
                got = _check(text, k, ox, oy, [segs[j] for j in used]) if good else None
                if got is None:
                    for j in used:
                        ix.used[j] = False
                    continue
                found = (_words(got[0]),) + got[1:] + (whole,)
                break
            if found is not None or tries > MAX_TRIES:
                break
        if found is None:
            break
        out.append(found)
    return out


def _words(text: str) -> str:
    """``I`` and ``l`` are one glyph in the font: ``l`` beside a lower-case letter."""
    out = list(text)
    for i, c in enumerate(out):
        if c == "I" and any(0 <= j < len(out) and out[j].islower() for j in (i - 1, i + 1)):
            out[i] = "l"
    return "".join(out)


def _check(text: str, k: float, ox: float, oy: float, segs: list):
    """The text drawn again as ``Text`` draws it: ``(text, position, size)`` when it gives
    every segment back, else None."""
    raw = _raw(text)
    lo = min(p[0] for s in raw for p in s)
    size = k * _cap_height()
    pos = (ox + k * lo, oy + k * _baseline())
    again = [((pos[0] + a[0], pos[1] + a[1]), (pos[0] + b[0], pos[1] + b[1]))
             for a, b in text_strokes(text, size, "start", "baseline")]
    if len(again) != len(segs):
        return None
    ix = _Index(segs, max(1e-3, 64 * TOL))
    for a, b in again:
        i = ix.find(a, b, set())
        if i is None:
            return None
        ix.used[i] = True
    return text, pos, size
