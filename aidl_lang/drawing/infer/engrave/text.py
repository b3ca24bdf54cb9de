"""``aidl import --infer``: engraved strokes that are a line of text in the built-in stroke
font (issue 71; docs/import.md, "Inferring the design"; used by :func:`~.engraving._engraving`).

In: line segments ``((x0, y0), (x1, y1))`` in mm (the engraving's polylines and polygons of
lines, as AIDL writes a ``Text``).  Out: ``(text, position, size, rotation)`` for ``Text(text,
position=, size=, anchor="start", valign="baseline", rotation=)`` when the segments are
exactly that text's strokes (:func:`~aidl_lang.geometry.shapes.text.text_strokes`, at any turn),
each within :data:`TOL`; else None.  Decoded glyph by glyph from the leftmost stroke: the
first glyph fixes the scale, the turn and the pen's origin (unturned: from one segment's
direction; turned: from two joined segments, whose angle and length ratio do not change
under a turn), each next one is the glyph whose strokes all lie at the pen (a space where
none does), until every segment is used; the text found is then drawn again by
:func:`~aidl_lang.geometry.shapes.text.text_strokes` and must give every segment back.
:func:`along_texts`: what is left, read as text laid along a circle (each letter upright on
it), ``Text(text, along=, angle=, size=)``.
"""
from __future__ import annotations

import math
from functools import lru_cache

from ....geometry.shapes.text import _baseline, _cap_height, _glyphs, _raw, text_strokes

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


def _place(segs, h) -> list:
    """Glyph segments in font units placed by the hypothesis ``h = (k, c, s, ox, oy)``:
    scale ``k``, turn ``(cos, sin)``, the pen's origin ``(ox, oy)`` in mm."""
    k, c, s, ox, oy = h
    return [((ox + k * (a[0] * c - a[1] * s), oy + k * (a[0] * s + a[1] * c)),
             (ox + k * (b[0] * c - b[1] * s), oy + k * (b[0] * s + b[1] * c))) for a, b in segs]


def _at(h, pen: float):
    """The hypothesis with its origin moved ``pen`` font units along the reading direction."""
    k, c, s, ox, oy = h
    return (k, c, s, ox + k * pen * c, oy + k * pen * s)


def _match(ix: _Index, segs, h) -> list | None:
    """The drawing's segments that are the glyph ``segs`` placed by ``h``, or None (placed
    one at a time: most tries fail at the first)."""
    taken: set = set()
    k, c, s, ox, oy = h
    for a, b in segs:
        i = ix.find((ox + k * (a[0] * c - a[1] * s), oy + k * (a[0] * s + a[1] * c)),
                    (ox + k * (b[0] * c - b[1] * s), oy + k * (b[0] * s + b[1] * c)), taken)
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
    """Every unturned hypothesis ``(char, its segments, (k, 1, 0, ox, oy))`` by which a
    glyph's segment is the segment ``s0`` (parallel, the same way or reversed)."""
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
                    yield c, gs, (k, 1.0, 0.0, s0[0][0] - k * p[0], s0[0][1] - k * p[1])


PAIR_STEP = 1e-2    # the pair table's buckets: turn (radians) and log of the length ratio


def _pair_key(a, b):
    """``(turn from a to b, log(|b| / |a|))`` of two segments, each ``((x0, y0), (x1,
    y1))``: unchanged by a turn, a shift and a scale; None for a segment of no length."""
    u = (a[1][0] - a[0][0], a[1][1] - a[0][1])
    v = (b[1][0] - b[0][0], b[1][1] - b[0][1])
    la, lb = math.hypot(*u), math.hypot(*v)
    if la <= 1e-12 or lb <= 1e-12:
        return None
    return (math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]),
            math.log(lb / la))


@lru_cache(maxsize=1)
def _by_pair() -> dict:
    """Every two segments of one glyph that meet end to start (either segment reversed
    where that makes them meet: a stroke read either way, two strokes joined by the
    reader), by :func:`_pair_key` in :data:`PAIR_STEP` buckets: ``{bucket: [(char, its
    segments, a, b)]}``."""
    out: dict = {}
    for c, gs, adv in _glyph_segments():
        ends = [s for g in gs for s in (g, (g[1], g[0]))]
        for a in ends:
            for b in ends:
                if a[1] != b[0] or {a, (a[1], a[0])} == {b, (b[1], b[0])}:
                    continue
                key = _pair_key(a, b)
                if key is not None:
                    out.setdefault((round(key[0] / PAIR_STEP), round(key[1] / PAIR_STEP)),
                                   []).append((c, gs, a, b))
    return out


def _turned_starts(s0, s1):
    """Every turned hypothesis ``(char, its segments, (k, cos, sin, ox, oy))`` by which two
    segments of a glyph that meet are ``s0`` then ``s1`` (``s0``'s end on ``s1``'s
    start)."""
    key = _pair_key(s0, s1)
    if key is None:
        return
    t0, r0 = round(key[0] / PAIR_STEP), round(key[1] / PAIR_STEP)
    table = _by_pair()
    for dt in (-1, 0, 1):
        for dr in (-1, 0, 1):
            for c, gs, a, b in table.get((t0 + dt, r0 + dr), ()):
                g = (a[1][0] - a[0][0], a[1][1] - a[0][1])
                v = (s0[1][0] - s0[0][0], s0[1][1] - s0[0][1])
                k = math.hypot(*v) / math.hypot(*g)
                turn = math.atan2(v[1], v[0]) - math.atan2(g[1], g[0])
                cs, sn = math.cos(turn), math.sin(turn)
                h = (k, cs, sn, s0[0][0] - k * (a[0][0] * cs - a[0][1] * sn),
                     s0[0][1] - k * (a[0][0] * sn + a[0][1] * cs))
                (p, q), = _place([b], h)
                if k > 1e-9 and math.dist(p, s1[0]) <= TOL and math.dist(q, s1[1]) <= TOL:
                    yield c, gs, h


def _decode(ix: _Index, glyphs: list, space: float, h):
    """The text read from the pen at ``h``'s origin: glyph after glyph (a space where none
    lies at the pen), and the segments it used."""
    text, pen, spaces, used = "", 0.0, 0, []
    while True:
        for c, gs, adv in glyphs:
            got = _match(ix, gs, _at(h, pen))
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


MAX_TRIES = 400     # reads that found no text, in all (a start whose glyph lies whole at it)
MAX_LOOKS = 5000    # (start segment, glyph, scale) hypotheses looked at, in all ...
LOOKS_PER_TEXT = 500    # ... and this many more for each text found
STARTS = 2          # segments of each polyline a read starts on (its first ones)


def _left(ix: _Index, glyphs: list, space: float, h):
    """The glyphs before the pen at ``h``'s origin (a text's start found inside it): ``(the
    new hypothesis, their text, the segments they used)``."""
    text, used = "", []
    while True:
        for n in range(MAX_SPACES + 1):
            hit = None
            for c, gs, adv in glyphs:
                x = _at(h, -(adv + n * space))
                got = _match(ix, gs, x)
                if got is not None:
                    hit = (c, x, got)
                    break
            if hit is not None:
                break
        if hit is None:
            return h, text, used
        c, h, got = hit
        for i in got:
            ix.used[i] = True
        used += got
        text = c + " " * n + text


def _hypotheses(segs: list, owner: list, j0: int, glyphs: list):
    """The hypotheses started on segment ``j0``: unturned first, then turned ones from it
    and the next segment of its polyline where they meet."""
    yield from _starts(segs[j0], glyphs)
    if j0 + 1 < len(segs) and owner[j0 + 1] == owner[j0] and \
            math.dist(segs[j0][1], segs[j0 + 1][0]) <= TOL:
        for c, gs, h in _turned_starts(segs[j0], segs[j0 + 1]):
            if abs(h[2]) > 1e-12 or h[1] < 0:
                yield c, gs, h


def _text_ok(text: str, glyphs: list, single: bool) -> bool:
    """A reading is a text: two or more letters or digits with a glyph of three or more
    segments among them; or, when ``single`` (upright, and no longer text is left to
    read: an ``n`` of a text upside down is a ``u``), one digit of two or more segments
    alone (a dial's or a ruler's numbers; a turned glyph alone is a letter of text along a
    curve, kept as strokes)."""
    n = {ch: len(gs) for ch, gs, _ in glyphs}
    if text.startswith(" "):
        return False
    if len(text) == 1:
        return single and text.isdigit() and n.get(text, 0) >= 2
    return sum(ch.isalnum() for ch in text) >= 2 and any(n.get(ch, 0) >= 3 for ch in text)


def stroke_texts(polys: list) -> list:
    """The lines of built-in-font text among ``polys`` (each a list of segments ``((x0,
    y0), (x1, y1))`` in mm: a polyline or polygon of the engraving), at any turn: ``[(text,
    (x, y), size, rotation in degrees, {indices of the polys it is})]``, each text made of
    whole polys and drawn again by ``Text`` to :data:`TOL` (:func:`_text_ok` says which
    readings count).  What is no text (a tick, a shape) is left.  At most
    :data:`MAX_TRIES` reads that find nothing and :data:`MAX_LOOKS` hypotheses (plus
    :data:`LOOKS_PER_TEXT` per text found) in all, started on the first :data:`STARTS`
    segments of strokes of several segments only (a text of one-line glyphs alone,
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
    dead: set = set()       # segments of a glyph whose read found no text: no more starts
    singles = False         # texts of one glyph: once no longer one is found ...
    later: set = set()      # ... read from these starts only (where one was seen)
    while ix.used.count(False) >= 1 and tries < MAX_TRIES:
        # starts on the first segments of strokes of several segments (a glyph's; a tick
        # is one line): a text is read from any of its glyphs, both ways
        order = sorted((j for j in (later if singles else range(len(segs)))
                        if not ix.used[j] and j not in dead and
                        len(members[owner[j]]) > 1 and j - members[owner[j]][0] < STARTS),
                       key=lambda j: (min(segs[j][0][0], segs[j][1][0]), j))
        found = None
        for j0 in order:
            seen: set = set()
            for c, gs, h in _hypotheses(segs, owner, j0, glyphs):
                key = tuple(round(v, 9) for v in h[:3]) + (round(h[3], 6), round(h[4], 6))
                if key in seen:
                    continue            # read from this placement already
                looks += 1
                if looks > MAX_LOOKS + LOOKS_PER_TEXT * len(out):
                    tries = MAX_TRIES + 1
                    break
                first = _match(ix, gs, h)
                if first is None:
                    continue            # the glyph the start is of is not whole here
                seen.add(key)
                h0, pre, before = _left(ix, glyphs, space, h)
                text, used = _decode(ix, glyphs, space, h)
                text, used = pre + text, before + used
                whole = {owner[j] for j in used}
                good = _text_ok(text, glyphs, singles and h[2] == 0.0 and h[1] > 0) and \
                    j0 in used and \
                    sum(len(members[i]) for i in whole) == len(used)
                got = _check(text, h0, [segs[j] for j in used]) if good else None
                if got is None:
                    for j in used:
                        ix.used[j] = False
                    if not singles and h[2] == 0.0 and h[1] > 0 and \
                            _text_ok(text, glyphs, True):
                        later.add(j0)
                    dead.update(first)
                    tries += 1
                    if tries > MAX_TRIES:
                        break
                    continue
                found = (_words(got[0]),) + got[1:] + (whole,)
                break
            if found is not None or tries > MAX_TRIES:
                break
        if found is None:
            if singles or tries > MAX_TRIES:
                break
            singles, dead = True, set()
            continue
        out.append(found)
    return out


def _words(text: str) -> str:
    """``I`` and ``l`` are one glyph in the font: ``l`` beside a lower-case letter."""
    out = list(text)
    for i, c in enumerate(out):
        if c == "I" and any(0 <= j < len(out) and out[j].islower() for j in (i - 1, i + 1)):
            out[i] = "l"
    return "".join(out)


def _turn(c: float, s: float) -> float:
    """The turn of ``(cos, sin)`` in degrees, in (-180, 180], a whole millionth of a degree
    when it is one within 1e-9 degrees (as a program writes it)."""
    deg = math.degrees(math.atan2(s, c))
    near = round(deg, 6)
    deg = near if abs(near - deg) <= 1e-9 else deg
    return 180.0 if deg == -180.0 else deg + 0.0


def _check(text: str, h, segs: list):
    """The text drawn again as ``Text`` draws it: ``(text, position, size, rotation in
    degrees)`` when it gives every segment back, else None."""
    k, c, s, ox, oy = h
    raw = _raw(text)
    lo = min(p[0] for s_ in raw for p in s_)
    size = k * _cap_height()
    deg = _turn(c, s)
    rot = math.radians(deg)
    (pos, _), = _place([((lo, _baseline()), (lo, _baseline()))], h)
    again = [((pos[0] + a[0], pos[1] + a[1]), (pos[0] + b[0], pos[1] + b[1]))
             for a, b in text_strokes(text, size, "start", "baseline", rot)]
    if len(again) != len(segs):
        return None
    ix = _Index(segs, max(1e-3, 64 * TOL))
    for a, b in again:
        i = ix.find(a, b, set())
        if i is None:
            return None
        ix.used[i] = True
    return text, pos, size, deg


MAX_ALONG = 400     # glyphs alone looked at for text laid along a circle


def along_texts(polys: list, taken: set) -> list:
    """Text laid along a circle (``Text(text, along=c, angle=a, size=)``, its middle at
    ``a``, each letter upright on the circle, reading clockwise) among the ``polys`` not in
    ``taken`` (indices of polys already read as text): ``[(text, (centre, radius), angle in
    degrees, size, {indices of the polys it is})]``.  Each letter is found alone, turned
    (:func:`_turned_starts`); two or more on one circle (the lines through each letter's
    baseline middle square to it meet at one centre) whose middles are the font's advances
    apart along it are one text, drawn again by
    :func:`~aidl_lang.geometry.shapes.text.text_strokes_along` and checked to :data:`TOL`."""
    from ....geometry.shapes.text import text_strokes_along
    idx = [i for i, p in enumerate(polys) if i not in taken]
    segs = [s for i in idx for s in polys[i]]
    owner = [i for i in idx for _ in polys[i]]
    if len(segs) < 4 or len(segs) > MAX_SEGMENTS:
        return []
    members: dict = {}
    for j, i in enumerate(owner):
        members.setdefault(i, []).append(j)
    glyphs = _glyph_segments()
    adv = {c: a for c, _, a in glyphs}
    ix = _Index(segs, max(1e-3, 64 * TOL))
    base = _baseline()
    cands = []      # per letter: its readings (a round glyph reads turned half a turn too)
    for i in idx:
        if len(cands) >= MAX_ALONG:
            break
        js = members[i]
        if len(js) < 2 or ix.used[js[0]]:
            continue
        best: list = []
        for c, gs, h in _turned_starts(segs[js[0]], segs[js[1]]):
            got = _match(ix, gs, h)
            if got is None or (best and len(gs) < len(best[0][1])):
                continue
            whole = {owner[j] for j in got}
            if sum(len(members[p]) for p in whole) == len(got):
                best = [b for b in best if len(b[1]) == len(gs)] + [(c, gs, h, got, whole)]
        if not best:
            continue
        for j in best[0][3]:
            ix.used[j] = True
        one = []
        for c, gs, h, got, whole in best:
            k, cs, sn, ox, oy = h
            m = _place([((adv[c] / 2, base), (adv[c] / 2, base))], h)[0][0]
            one.append((c, k, math.atan2(sn, cs), m, whole))
        cands.append(one)
    out: list = []
    left = list(range(len(cands)))
    while len(left) >= 2:
        ring = None
        for a in cands[left[0]]:
            for b_i in left[1:]:
                for b in cands[b_i]:
                    ring = _ring(a, b)
                    if ring is not None:
                        break
                if ring is not None:
                    break
            if ring is not None:
                break
        if ring is None:
            left.pop(0)
            continue
        (cx, cy), r, k = ring
        on, lts = [], []
        for i in left:
            hit = next((lt for lt in cands[i] if abs(lt[1] - k) <= 1e-9 * max(1.0, k) and
                        abs(math.dist(lt[3], (cx, cy)) - r) <= 10 * TOL and
                        abs(math.remainder(math.atan2(lt[3][1] - cy, lt[3][0] - cx) -
                                           lt[2] - math.pi / 2, 2 * math.pi)) <= 1e-7), None)
            if hit is not None:
                on.append(i)
                lts.append(hit)
        if not on:
            left.pop(0)
            continue
        left = [i for i in left if i not in on]
        # clockwise: the reading order along the circle
        ang = [math.atan2(lt[3][1] - cy, lt[3][0] - cx) for lt in lts]
        order = sorted(range(len(lts)), key=lambda n: -ang[n])
        gaps = [(ang[order[n - 1]] - ang[order[n]]) % (2 * math.pi) for n in range(len(order))]
        cut = max(range(len(order)), key=lambda n: gaps[n])   # start after the widest gap
        order = order[cut:] + order[:cut]
        out += _along_words([lts[n] for n in order], (cx, cy), r,
                            {n: ang[o] for n, o in enumerate(order)}, list(range(len(order))),
                            text_strokes_along, polys)
    return out


def _tidy(v: float, most: int = 9) -> float:
    """``v`` as the number of fewest decimals (at most ``most``) within 1e-9 of it."""
    for digits in range(most + 1):
        r = round(v, digits)
        if abs(r - v) <= 1e-9:
            return r + 0.0
    return v


def _ring(a, b):
    """The circle two letters stand upright on: ``(centre, radius, scale)`` where the lines
    up through their baseline middles meet below both, or None."""
    if abs(a[1] - b[1]) > 1e-9 * max(1.0, a[1]):
        return None
    ua = (-math.sin(a[2]), math.cos(a[2]))
    ub = (-math.sin(b[2]), math.cos(b[2]))
    den = ua[0] * ub[1] - ua[1] * ub[0]
    if abs(den) < 1e-9:
        return None
    d = (b[3][0] - a[3][0], b[3][1] - a[3][1])
    t = (d[0] * ub[1] - d[1] * ub[0]) / den
    u = (d[0] * ua[1] - d[1] * ua[0]) / den
    if t >= 0 or u >= 0 or abs(t - u) > 1e-6 * abs(t):
        return None             # the centre above a letter, or not as far from both
    return (a[3][0] + t * ua[0], a[3][1] + t * ua[1]), -t, a[1]


def _along_words(lts: list, centre, r: float, ang: dict, ids: list, strokes_along,
                 polys: list) -> list:
    """The letters of one circle, in reading order, cut into texts where the next letter is
    not the font's advance on (a space at most), each checked again whole."""
    glyph_adv = {c: a for c, _, a in _glyph_segments()}
    space = _glyphs().get(" ", ((), 0.0))[1]
    words, cur = [], []
    for n, lt in enumerate(lts):
        if cur:
            prev = cur[-1]
            k = lt[1]
            step = (ang[ids[n - 1]] - ang[ids[n]]) % (2 * math.pi) * r / k   # font units
            want = (glyph_adv[prev[0]] + glyph_adv[lt[0]]) / 2
            if abs(step - want) <= 1e-6 * max(1.0, want):
                cur.append(lt)
                continue
            if abs(step - want - space) <= 1e-6 * max(1.0, want):
                cur.append((" ",) + lt[1:])
                cur.append(lt)
                continue
            words.append(cur)
            cur = []
        cur.append(lt)
    if cur:
        words.append(cur)
    out = []
    for w in words:
        real = [lt for lt in w if lt[0] != " "]
        text = "".join(lt[0] for lt in w)
        if len(real) < 2 and not (len(real) == 1 and text.isdigit()):
            continue
        k = real[0][1]
        size = k * _cap_height()
        raw = _raw(text)
        xs = [p[0] for s in raw for p in s]
        centre, r = (_tidy(centre[0]), _tidy(centre[1])), _tidy(r)
        t0 = math.atan2(real[0][3][1] - centre[1], real[0][3][0] - centre[0])
        angle = t0 + (glyph_adv[real[0][0]] / 2 - (min(xs) + max(xs)) / 2) * k / r
        deg = _tidy(math.degrees(angle), 6)
        deg = 180.0 if deg == -180.0 else deg
        whole = set().union(*(lt[4] for lt in real))
        mine = [s for i in whole for s in polys[i]]
        again = [((centre[0] + a[0], centre[1] + a[1]), (centre[0] + b[0], centre[1] + b[1]))
                 for a, b in strokes_along(text, size, r, math.radians(deg))]
        if len(again) != len(mine):
            continue
        ix = _Index(mine, max(1e-3, 64 * TOL))
        ok = True
        for a, b in again:
            i = ix.find(a, b, set())
            if i is None:
                ok = False
                break
            ix.used[i] = True
        if ok:
            out.append((_words(text), (centre, r), deg, size, whole))
    return out
