"""``aidl import --infer``: the patterns found in what a drawing repeats (issue 60;
docs/import.md, "Inferring the design"; used by :mod:`.infer`, which writes them as loops).

In: points, pieces and parts in mm (angles in radians); out: the pattern's numbers, or None
when there is none.  Every pattern is checked member by member to
:data:`~.infer_shapes.EQUAL_TOL` (1e-7 mm), so writing it moves nothing:

* points (the centres of equal holes): a whole turn round a centre (:func:`_polar`, a bolt
  circle), an axis-aligned row, column or grid (:func:`_grid`), evenly spaced on one line
  (:func:`_line`), runs of equal steps (:func:`_runs`), a staggered grid (:func:`_stagger`),
  a square-set grid clipped to a round field (:func:`_grid_field`, a fan grille), a row or
  grid with nodes missing (:func:`_gapped_grid`, written with a gap list), a row or
  grid CAD rounded up to 0.05 mm off its pitch (:func:`_near_grid`, written with offsets),
  a hex lattice clipped to a round or rectangular field (:func:`_hex_field`,
  :func:`_hex_rect`; the field's size by :func:`_field_size`);
* an outline that is one run of pieces turned ``n`` times round a centre (:func:`_polar_chain`,
  a gear or a star) and polygons turned evenly round a centre (:func:`_polar_polys`, teeth);
* single strokes that are a family of ticks, along a line or round a centre
  (:func:`_tick_families`; their lengths' period, :func:`_periodic`);
* parts that are copies of one part moved evenly along a line (:func:`_copies`, by each
  simple part's :func:`_signature`; :func:`_unknown`: a drawing holding what the inferred
  writer does not write).
"""
from __future__ import annotations

import bisect
import math

from ....geometry.shapes.curves import Arc, Line
from ..params import _r
from ..shapes import EQUAL_TOL, PRECISION, _snap_angle, circular, recognise
from ...write.program import _containers
from ...write.writer import _ident, _num
from ...model import Drawing


# ------------------------------------------------------------------ points
def _steps(vals: list) -> float | None:
    """The common step of sorted ``vals``: ``(last - first) / (n - 1)`` when every value
    lies within EQUAL_TOL of ``first + k * step`` (a pitch holds every instance, not only
    each step: steps each 0.9e-7 mm longer than the first add up); else None."""
    if len(vals) < 2:
        return None
    step = (vals[-1] - vals[0]) / (len(vals) - 1)
    if any(abs(v - (vals[0] + k * step)) > EQUAL_TOL for k, v in enumerate(vals)):
        return None
    return step


def _distinct(vals: list) -> list:
    out: list = []
    for v in sorted(vals):
        if not out or v - out[-1] > EQUAL_TOL:
            out.append(v)
    return out


def _polar(centers: list):
    """``(centre, radius, first angle, n)`` when ``centers`` are evenly round a circle (a
    whole turn), else None."""
    n = len(centers)
    if n < 3:
        return None
    cx = sum(p[0] for p in centers) / n
    cy = sum(p[1] for p in centers) / n
    rad = [math.dist((cx, cy), p) for p in centers]
    R = sum(rad) / n
    if R <= EQUAL_TOL or max(rad) - min(rad) > EQUAL_TOL:
        return _polar_as_drawn(centers, (cx, cy))
    step = 2 * math.pi / n
    a0 = min(math.atan2(p[1] - cy, p[0] - cx) % (2 * math.pi) for p in centers) % step
    a0 = _snap_angle(a0, R)
    if not _each_once(centers, ((cx + R * math.cos(a0 + k * step),
                                 cy + R * math.sin(a0 + k * step)) for k in range(n))):
        return _polar_as_drawn(centers, (cx, cy))
    return (cx, cy), R, a0, n


def _off_circle(centers: list, pol) -> float:
    """How far the farthest of ``centers`` is from its place on the bolt circle ``pol``
    (:func:`_polar`'s), in mm: 0 for an exact one, up to two units of the drawing's last
    decimal for one :func:`_polar_as_drawn` found."""
    (cx, cy), R, a0, n = pol
    step = 2 * math.pi / n
    out = 0.0
    for p in centers:
        a = a0 + step * round((math.atan2(p[1] - cy, p[0] - cx) - a0) / step)
        out = max(out, math.dist(p, (cx + R * math.cos(a), cy + R * math.sin(a))))
    return out


POLAR_AS_DRAWN = 360    # holes at most, of a bolt circle equal within the drawing's precision


def _polar_as_drawn(centers: list, mid):
    """:func:`_polar` within the drawing's own precision (:data:`~.shapes.PRECISION`, issue
    114: an SVG whose centres carry 6 decimals): every centre within two units of its last
    decimal of its place on the circle, the centre and radius the shortest decimals within
    one, the first hole's angle a round number of degrees within one at the radius; None
    when the drawing writes floats (no precision of its own) or they are not one."""
    tol = 2 * PRECISION.get()
    n = len(centers)
    if tol <= EQUAL_TOL or n > POLAR_AS_DRAWN:
        return None
    cx, cy = (float(_num(v, tol / 2)) for v in mid)
    rad = [math.dist((cx, cy), p) for p in centers]
    R = float(_num(sum(rad) / n, tol / 2))
    if R <= tol or max(abs(r - R) for r in rad) > tol:
        return None
    step = 2 * math.pi / n
    a0 = min(math.atan2(p[1] - cy, p[0] - cx) % (2 * math.pi) for p in centers) % step
    if step - a0 <= tol / R:            # the first hole a hair below the x axis: on it
        a0 = 0.0
    d = math.degrees(a0)
    a0 = next((math.radians(round(d, k)) for k in range(10)
               if abs(math.radians(round(d, k)) - a0) * R <= tol / 2), a0)
    taken: set = set()
    for k in range(n):
        q = (cx + R * math.cos(a0 + k * step), cy + R * math.sin(a0 + k * step))
        hit = next((i for i, p in enumerate(centers) if i not in taken and math.dist(p, q) <= tol),
                   None)
        if hit is None:
            return None
        taken.add(hit)
    return (cx, cy), R, a0, n


class _Cells:
    """Points (mm) hashed into square cells of 2 EQUAL_TOL, so that the points within
    EQUAL_TOL of a place are found in the nine cells about it, not along the whole list."""

    def __init__(self, points: list) -> None:
        self.points, self.cells = [], {}
        for p in points:
            self.add(p)

    def add(self, p) -> int:
        """Point ``p`` added; its index."""
        self.points.append(p)
        self.cells.setdefault(self._key(p), []).append(len(self.points) - 1)
        return len(self.points) - 1

    @staticmethod
    def _key(p) -> tuple[int, int]:
        return math.floor(p[0] / (2 * EQUAL_TOL)), math.floor(p[1] / (2 * EQUAL_TOL))

    def near(self, q) -> list[int]:
        """The indices of the points within EQUAL_TOL of ``q``, in the points' order."""
        cx, cy = self._key(q)
        return sorted(i for a in (cx - 1, cx, cx + 1) for b in (cy - 1, cy, cy + 1)
                      for i in self.cells.get((a, b), ())
                      if math.dist(self.points[i], q) <= EQUAL_TOL)


def _each_once(points: list, targets) -> bool:
    """Whether each of ``targets`` (in turn) has a point of ``points`` within EQUAL_TOL
    not taken by an earlier one, the first such point in ``points``' order taken (found in
    :class:`_Cells`, not along the list: a bolt circle or a slanted row of 20,000 holes,
    2e8 distances)."""
    cells = _Cells(points)
    taken: set = set()
    for q in targets:
        hit = next((i for i in cells.near(q) if i not in taken), None)
        if hit is None:
            return False
        taken.add(hit)
    return True


def _grid(centers: list):
    """``(x0, y0, dx, dy, cols, rows)`` when ``centers`` are an axis-aligned lattice (a row,
    a column or a grid, equal steps), else None."""
    xs = _distinct([p[0] for p in centers])
    ys = _distinct([p[1] for p in centers])
    if len(xs) * len(ys) != len(centers):
        return None
    dx = _steps(xs) if len(xs) > 1 else 0.0
    dy = _steps(ys) if len(ys) > 1 else 0.0
    if dx is None or dy is None:
        return None
    # every node (x, y) of the lattice holds a centre within EQUAL_TOL on both axes: each
    # centre marks the nodes it holds (found by binary search in xs and ys), not each node
    # a scan of every centre (20,000 holes: 4e8 comparisons)
    held = set()
    for p in centers:
        for i in _near(xs, p[0]):
            held.update((i, j) for j in _near(ys, p[1]))
    if len(held) != len(centers):
        return None
    return xs[0], ys[0], dx, dy, len(xs), len(ys)


def _near(vals: list, v: float) -> list[int]:
    """The indices ``k`` of sorted ``vals`` with ``abs(v - vals[k]) <= EQUAL_TOL``
    (a binary search; at most two of :func:`_distinct`'s values)."""
    k = bisect.bisect_left(vals, v - 2 * EQUAL_TOL)
    out = []
    while k < len(vals) and vals[k] <= v + 2 * EQUAL_TOL:
        if abs(v - vals[k]) <= EQUAL_TOL:
            out.append(k)
        k += 1
    return out


def _stagger(centers: list):
    """``(x0 even, n even, x0 odd, n odd, pitch, y0, row step, rows)`` when ``centers`` are a
    staggered (hex) grid: rows on equal steps in y, each row on one pitch, the even rows
    alike and the odd rows alike shifted half a pitch (their counts equal or one apart);
    every centre checked to EQUAL_TOL; else None."""
    ys = _distinct([p[1] for p in centers])
    if len(ys) < 3 or _steps(ys) is None:
        return None
    # each centre in the rows within EQUAL_TOL of its y (a binary search), not each row a
    # scan of every centre
    rows: list = [[] for _ in ys]
    for p in centers:
        for k in _near(ys, p[1]):
            rows[k].append(p[0])
    rows = [sorted(r) for r in rows]
    if sum(len(r) for r in rows) != len(centers) or any(len(r) < 2 for r in rows):
        return None
    pitch = _steps(rows[0])
    if pitch is None or pitch <= EQUAL_TOL:
        return None
    for k, r in enumerate(rows):
        ref = rows[k % 2]
        if len(r) != len(ref) or abs(r[0] - ref[0]) > EQUAL_TOL or \
                any(abs(x - (r[0] + i * pitch)) > EQUAL_TOL for i, x in enumerate(r)):
            return None
    (a, b) = rows[0], rows[1]
    if abs(abs(b[0] - a[0]) - pitch / 2) > EQUAL_TOL or abs(len(a) - len(b)) > 1:
        return None
    return a[0], len(a), b[0], len(b), pitch, ys[0], _steps(ys), len(ys)


def _roundest(lo: float, hi: float) -> float:
    """The roundest number in ``[lo, hi)`` (the multiple of the largest step 10, 5, 2.5, 2, 1,
    0.5, ... times a power of ten that lies in it), the one a person would have dimensioned
    a size by that the drawing only bounds (a field the holes lie in, not drawn)."""
    for e in range(6, -10, -1):
        for m in (1.0, 0.5, 0.25, 0.2):
            step = m * 10.0 ** e
            v = math.ceil(lo / step - 1e-9) * step
            if lo - EQUAL_TOL <= v < hi - EQUAL_TOL:
                return v
    return lo


def _hex_field(centers: list, r: float):
    """``(centre, pitch, shift, field diameter)`` when ``centers`` are the holes (radius
    ``r``) of a hexagonal lattice that lie whole inside a round field centred on it: rows
    ``pitch * sqrt(3) / 2`` apart, symmetric about the middle row, alternate rows shifted
    half a pitch (``shift`` 1: the middle row has no hole on the centre), every node of the
    lattice whose hole fits in the field a hole and no other (a fan grille in a round
    cut-out, whose rows are not of two counts as :func:`_stagger` needs); the field's
    diameter, of those that keep exactly those holes, a whole number of pitches (the grille
    dimensioned as so many holes across) or else the roundest (:func:`_roundest`); else
    None."""
    ys = _distinct([p[1] for p in centers])
    if len(ys) < 3 or len(ys) % 2 == 0 or len(centers) < 7:
        return None
    dy = _steps(ys)
    if dy is None:
        return None
    rows: list = [[] for _ in ys]
    for p in centers:
        for k in _near(ys, p[1]):
            rows[k].append(p[0])
    if sum(len(r_) for r_ in rows) != len(centers):
        return None
    pitch = dy * 2 / math.sqrt(3)
    xs = [x for row in rows for x in row]
    cx, cy = (min(xs) + max(xs)) / 2, ys[len(ys) // 2]
    mid = len(ys) // 2
    held = set()
    shift = None
    for k, row in enumerate(rows):
        j = k - mid
        for x in row:
            t = (x - cx) / pitch * 2                # half pitches from the centre
            if abs(t - round(t)) * pitch / 2 > EQUAL_TOL:
                return None
            s = (round(t) - j) % 2                  # the middle row's half-pitch shift
            if shift is None:
                shift = s
            if s != shift:
                return None
            held.add(((round(t) - (j + shift) % 2) // 2, j))
    if len(held) != len(centers):
        return None
    # the field: every hole inside it, every other node of the lattice near it outside
    def dist(i, j):
        return math.hypot((i + (j + shift) % 2 / 2) * pitch, j * dy)
    inside = max(dist(i, j) for i, j in held)
    big = max(max(abs(i) for i, _ in held), mid) + 2
    outside = min((dist(i, j) for j in range(-mid - 2, mid + 3) for i in range(-big, big + 1)
                   if (i, j) not in held), default=math.inf)
    if outside - inside <= 2 * EQUAL_TOL:
        return None
    return (cx, cy), pitch, shift, _field_size(2 * (inside + r), 2 * (outside + r), pitch)


def _field_size(lo: float, hi: float, pitch: float) -> float:
    """The size (mm) of a field the holes of a grid lie whole in, which the drawing bounds
    to ``[lo, hi)`` (it keeps exactly those holes) but does not draw: a whole number of
    pitches (the grille dimensioned as so many holes across), else the roundest number in
    the range (:func:`_roundest`)."""
    k = math.ceil(lo / pitch - 1e-9)
    return k * pitch if k * pitch < hi - EQUAL_TOL else _roundest(lo, hi)


def _hex_rect(centers: list, r: float):
    """``(centre, pitch, shift, field width, field height, (width lo, hi), (height lo,
    hi))`` when ``centers`` are the holes
    (radius ``r``) of a hexagonal lattice that lie whole inside a rectangular field centred
    on it: a staggered grid (:func:`_stagger`) of an odd number of rows ``pitch * sqrt(3) /
    2`` apart, every row centred on one vertical line (so each row holds every node of the
    lattice within the field's width: a vent field cut into a panel); ``shift`` 1 when the
    middle row has no hole on the centre; the field's width and height by
    :func:`_field_size` (the fewest whole pitches that keep those holes, as for a round
    field), of the ranges ``[lo, hi)`` of sizes that keep them; else None."""
    st = _stagger(centers)
    if st is None:
        return None
    xa, na, xb, nb, pitch, y0, dy, rows = st
    ha, hb = (na - 1) * pitch / 2, (nb - 1) * pitch / 2
    if rows % 2 == 0 or abs(xa + ha - xb - hb) > EQUAL_TOL or \
            abs(dy - pitch * math.sqrt(3) / 2) > EQUAL_TOL:
        return None
    mid = rows // 2
    cx, cy = xa + ha, y0 + mid * dy
    # the middle row's count: odd when it has a hole on the centre
    n_mid = na if mid % 2 == 0 else nb
    shift = 0 if n_mid % 2 else 1
    # the widths and heights that keep exactly these holes, each its own size
    wide = (2 * (max(ha, hb) + r), 2 * (min(ha, hb) + pitch + r))
    high = (2 * (mid * dy + r), 2 * ((mid + 1) * dy + r))
    return (cx, cy), pitch, shift, _field_size(*wide, pitch), _field_size(*high, pitch), \
        wide, high


MAX_GAPS = 1 / 4     # of a lattice's nodes, at most this share may be missing (a gap list)


def _lattice_axis(vals: list):
    """``(v0, step, n)`` when sorted distinct ``vals`` lie on one pitch with some nodes
    missing (``v0 + k step``, ``k`` whole, each within EQUAL_TOL): the pitch is the
    shortest step between them; else None.  One value: ``(v, 0, 1)``."""
    if len(vals) == 1:
        return vals[0], 0.0, 1
    step = min(b - a for a, b in zip(vals, vals[1:]))
    if step <= EQUAL_TOL:
        return None
    n = round((vals[-1] - vals[0]) / step) + 1
    if n > 2 * len(vals) + 2:
        return None
    step = (vals[-1] - vals[0]) / (n - 1)
    if any(abs(v - vals[0] - round((v - vals[0]) / step) * step) > EQUAL_TOL for v in vals):
        return None
    return vals[0], step, n


def _gapped_grid(centers: list):
    """``((x0, y0, dx, dy, cols, rows), missing)`` when ``centers`` are an axis-aligned
    lattice (a row or a grid) with some nodes left out (a 4 x 3 grid with one hole
    missing, a perforated row with a gap): at least four holes, at least one node missing
    and at most :data:`MAX_GAPS` of them, every hole on a node to EQUAL_TOL; ``missing``
    the nodes' ``(i, j)`` (column, row from ``(x0, y0)``); else None."""
    n = len(centers)
    if n < 4:
        return None
    ax = _lattice_axis(_distinct([p[0] for p in centers]))
    ay = _lattice_axis(_distinct([p[1] for p in centers]))
    if ax is None or ay is None:
        return None
    (x0, dx, nx), (y0, dy, ny) = ax, ay
    nodes = nx * ny
    if nodes <= n or nodes - n > max(1, int(nodes * MAX_GAPS)) or (nx < 3 and ny < 3):
        return None
    return _on_lattice(centers, x0, y0, dx, dy, nx, ny)


def _grid_field(centers: list, r: float):
    """``(centre, (dx, dy), (half_x, half_y), field diameter)`` when ``centers`` are the
    holes (radius ``r``) of an axis-aligned lattice that lie whole inside a round field
    centred on it (a fan grille of square-set holes in a round cut-out): every node of the
    lattice whose hole fits in the field a hole and no other, at least three rows and
    columns, the lattice not full; ``half_x`` when the centre falls between two columns (an
    even count: nodes at ``(i + 0.5) dx``); the field's diameter, of those that keep exactly
    those holes, a whole number of pitches or else the roundest (:func:`_field_size`); else
    None."""
    n = len(centers)
    if n < 9 or r <= 0:
        return None
    ax = _lattice_axis(_distinct([p[0] for p in centers]))
    ay = _lattice_axis(_distinct([p[1] for p in centers]))
    if ax is None or ay is None or ax[2] < 3 or ay[2] < 3 or ax[2] * ay[2] == n or \
            ax[2] * ay[2] > 2 * n:      # a round field holds 79 % of its square's nodes
        return None
    (x0, dx, nx), (y0, dy, ny) = ax, ay
    held = set()
    for p in centers:
        i, j = round((p[0] - x0) / dx), round((p[1] - y0) / dy)
        if math.dist(p, (x0 + i * dx, y0 + j * dy)) > EQUAL_TOL or (i, j) in held:
            return None
        held.add((i, j))
    mx, my = (nx - 1) / 2, (ny - 1) / 2

    def dist(i, j):
        return math.hypot((i - mx) * dx, (j - my) * dy)
    inside = max(dist(i, j) for i, j in held)
    outside = min((dist(i, j) for i in range(-2, nx + 2) for j in range(-2, ny + 2)
                   if (i, j) not in held), default=math.inf)
    if outside - inside <= 2 * EQUAL_TOL:
        return None
    c = (x0 + mx * dx, y0 + my * dy)
    return c, (dx, dy), (nx % 2 == 0, ny % 2 == 0), \
        _field_size(2 * (inside + r), 2 * (outside + r), min(dx, dy))


PITCH_TOL = 0.05    # mm: a hole this near its node is on a pattern CAD rounded (issue 103)
MAX_OFF = 64        # holes off their node a pattern writes as offsets (else none)


def _clusters(vals: list, tol: float) -> list[list[float]]:
    """Sorted ``vals`` in runs whose neighbours are within ``2 tol`` of each other."""
    out: list = []
    for v in sorted(vals):
        if out and v - out[-1][-1] <= 2 * tol:
            out[-1].append(v)
        else:
            out.append([v])
    return out


def _short(v: float) -> bool:
    """Whether ``v`` (the drawing's unit) is within 1e-9 of a decimal of at most 4 places
    (what a CAD program that rounds writes: 38.5, 46.87 mm; 0.251 in)."""
    return abs(v - round(v, 4)) <= 1e-9


def _nearest(vals: list, v: float) -> int:
    """The index of the value of sorted ``vals`` nearest ``v`` (a binary search)."""
    k = bisect.bisect_left(vals, v)
    return min((j for j in (k - 1, k) if 0 <= j < len(vals)), key=lambda j: abs(vals[j] - v))


def _round_fit(vals: list, k: list, tol: float):
    """``(v0, step)``: the shortest decimals (0 to 6 places, in the unit the program is
    written in: an inch drawing's 0.6 in) with every ``vals[m]`` within ``tol`` of ``v0 +
    k[m] step``, from the least-squares line; None when none is."""
    n = len(vals)
    km = sum(k) / n
    vm = sum(vals) / n
    den = sum((x - km) ** 2 for x in k)
    step = sum((x - km) * (v - vm) for x, v in zip(k, vals)) / den if den else 0.0
    v0 = vm - step * km
    for places in range(7):
        a, b = round(v0, places), round(step, places)
        if all(abs(v - a - x * b) <= tol for v, x in zip(vals, k)):
            return a, b
    return None


def _near_grid(centers: list, tol: float | None = None, least: int = 3):
    """``((x0, y0, dx, dy, cols, rows), offsets)`` when ``centers`` are an axis-aligned row
    or grid of at least three holes whose positions a CAD program rounded: every hole
    within ``tol`` (0.05 mm) of its node along each axis, the pitch at least 20 ``tol``,
    the lattice's numbers the shortest decimals that hold them all (:func:`_round_fit`);
    ``offsets`` ``{index: (dx, dy)}`` of the holes off their node by more than EQUAL_TOL
    (at most :data:`MAX_OFF`), so that the pattern, written with them, draws every hole
    exactly where the drawing has it; else None (and None when the lattice is exact:
    :func:`_grid`, or has fewer than ``least`` holes along both axes: a 2 x 2 is one only
    beside a sibling group, :func:`_features`)."""
    n = len(centers)
    if n < 3 or _grid(centers) is not None:
        return None
    if tol is None:                 # 0.05 mm in the unit the drawing is inferred in
        from ...write.units import UNIT
        tol = PITCH_TOL / (25.4 if UNIT.get() == "in" else 1.0)
    fits, idx = [], []
    cls = [_clusters([p[axis] for p in centers], tol) for axis in (0, 1)]
    if len(cls[0]) * len(cls[1]) != n:
        return None                 # not every node of one lattice held once
    for axis in (0, 1):
        cl = cls[axis]
        mids = [sum(c) / len(c) for c in cl]
        if len(cl) > 1:
            pitch = (mids[-1] - mids[0]) / (len(cl) - 1)
            if pitch < 20 * tol or any(abs(m - mids[0] - j * pitch) > 2 * tol
                                       for j, m in enumerate(mids)):
                return None         # (a node missing too: gap lists are exact)
        if len(cl) > 1 and any(not _short(p[axis]) for p in centers):
            return None             # not CAD rounding (a drift of 1e-5 mm is no rounding)
        ks = [_nearest(mids, p[axis]) for p in centers]
        fit = _round_fit([p[axis] for p in centers], ks, tol)
        if fit is None:
            return None
        fits.append((fit, len(cl)))
        idx.append(ks)
    ((x0, dx), nx), ((y0, dy), ny) = fits
    if nx * ny != n or len(set(zip(*idx))) != n or max(nx, ny) < least:
        return None
    offs = {}
    for m, p in enumerate(centers):
        d = (p[0] - x0 - idx[0][m] * dx, p[1] - y0 - idx[1][m] * dy)
        if max(abs(d[0]), abs(d[1])) > EQUAL_TOL:
            offs[m] = d
    if not offs or len(offs) > MAX_OFF or len(centers) > 4 * MAX_OFF:
        return None
    return (x0, y0, dx, dy, nx, ny), offs


def _whole(centers: list, r: float) -> bool:
    """Whether ``centers`` (holes of radius ``r``, a circle's; 0 for other shapes) are one
    pattern: a bolt circle, a grid, a staggered or clipped hex grid, or a row."""
    return len(centers) >= 2 and (_grid(centers) is not None or _line(centers) is not None or
                                  _polar(centers) is not None or _stagger(centers) is not None
                                  or (r > 0 and _hex_field(centers, r) is not None)
                                  or (r > 0 and _grid_field(centers, r) is not None)
                                  or _gapped_grid(centers) is not None
                                  or _near_grid(centers) is not None)


MAX_SPLIT = 400     # equal holes split into features by their neighbours (n^2 distances)


def _features(centers: list, r: float) -> list[list[int]] | None:
    """Equal holes of no one pattern (a hex grille and a grid of the same holes) split into
    the features they are: the groups of holes each within 1.5 times its nearest
    neighbour's distance of the next (single linkage), when there are several and every
    group of more than one is of three or more and a pattern (:func:`_whole`); else None.  Only up to
    :data:`MAX_SPLIT` holes."""
    n = len(centers)
    if n < 4 or n > MAX_SPLIT:
        return None
    nn = [min(math.dist(p, q) for j, q in enumerate(centers) if j != i)
          for i, p in enumerate(centers)]
    near: list = [[] for _ in range(n)]
    for i in range(n):
        for j in range(i + 1, n):
            if math.dist(centers[i], centers[j]) <= 1.5 * min(nn[i], nn[j]) + EQUAL_TOL:
                near[i].append(j)
                near[j].append(i)
    groups: dict = {}
    seen: set = set()
    for i in range(n):                  # each group: the holes reached from its first
        if i in seen:
            continue
        todo, groups[i] = [i], []
        seen.add(i)
        while todo:
            k = todo.pop()
            groups[i].append(k)
            todo += [j for j in near[k] if j not in seen]
            seen.update(near[k])
    groups = {k: sorted(v) for k, v in groups.items()}
    out = sorted(groups.values())
    # a group of two is no evidence of a feature of its own (a board's four holes in two
    # pairs would become two diagonal "rows" of two): the holes stay one set; a group that
    # is a sibling's lattice with a hole left out (issue 103: two 2 x 2 groups, one of three)
    whole = [len(g) > 2 and (_whole([centers[i] for i in g], r) or _near_grid(
        [centers[i] for i in g], least=2) is not None) for g in out]
    kin = lattices([[centers[i] for i in g] for g, w in zip(out, whole) if w])
    if len(out) < 2 or not all(len(g) == 1 or w or len(g) > 2 and any(
            _gapped_as([centers[i] for i in g], lat) for lat in kin)
            for g, w in zip(out, whole)):
        return None
    return out


def lattices(groups: list) -> list:
    """``[(dx, dy, cols, rows)]``: the lattice of each group of centres that is a row or
    grid, exact (:func:`_grid`), with holes left out (:func:`_gapped_grid`) or CAD rounded
    (:func:`_near_grid`); the others left out."""
    out = []
    for cs in groups:
        gr = _grid(cs) or (_gapped_grid(cs) or _near_grid(cs, least=2) or [None])[0]
        if gr is not None and gr[4] * gr[5] > 1:
            out.append(gr[2:])
    return out


def _gapped_as(centers: list, lat: tuple):
    """``((x0, y0, dx, dy, cols, rows), missing)`` when ``centers`` are a lattice of the
    counts of ``lat`` (``(dx, dy, cols, rows)``, a sibling group's: its pitch may differ)
    with at least one node and at most :data:`MAX_GAPS` of them left out (one of a 2 x 2):
    every hole on a node to EQUAL_TOL, the holes spanning the whole lattice; else None."""
    _, _, nx, ny = lat
    n = len(centers)
    nodes = nx * ny
    if n < 3 or not nodes - max(1, int(nodes * MAX_GAPS)) <= n < nodes:
        return None
    x0, y0 = min(p[0] for p in centers), min(p[1] for p in centers)
    dx = (max(p[0] for p in centers) - x0) / (nx - 1) if nx > 1 else 0.0
    dy = (max(p[1] for p in centers) - y0) / (ny - 1) if ny > 1 else 0.0
    if (nx > 1 and dx <= EQUAL_TOL) or (ny > 1 and dy <= EQUAL_TOL):
        return None
    return _on_lattice(centers, x0, y0, dx, dy, nx, ny)


def _on_lattice(centers: list, x0: float, y0: float, dx: float, dy: float, nx: int, ny: int):
    """``((x0, y0, dx, dy, nx, ny), the missing (i, j) nodes)`` when every centre sits on its
    own node of the ``nx`` x ``ny`` lattice from ``(x0, y0)`` by ``(dx, dy)`` (mm, within
    ``EQUAL_TOL``), else None."""
    held = set()
    for p in centers:
        i = round((p[0] - x0) / dx) if nx > 1 else 0
        j = round((p[1] - y0) / dy) if ny > 1 else 0
        if math.dist(p, (x0 + i * dx, y0 + j * dy)) > EQUAL_TOL or (i, j) in held:
            return None
        held.add((i, j))
    missing = [(i, j) for i in range(nx) for j in range(ny) if (i, j) not in held]
    return (x0, y0, dx, dy, nx, ny), missing


def _line(centers: list):
    """``(p0, (dx, dy), n)`` when ``centers`` are evenly spaced on one line, else None."""
    n = len(centers)
    if n < 2:
        return None
    a, b = min(centers), max(centers)
    d = ((b[0] - a[0]) / (n - 1), (b[1] - a[1]) / (n - 1))
    if not _each_once(centers, ((a[0] + k * d[0], a[1] + k * d[1]) for k in range(n))):
        return None
    return a, d, n


# ------------------------------------------------------------------ turned round a centre
def _rotated(g, C, a: float):
    """Piece ``g`` turned by ``a`` about ``C``."""
    c, s = math.cos(a), math.sin(a)

    def R(p):
        x, y = p[0] - C[0], p[1] - C[1]
        return (C[0] + x * c - y * s, C[1] + x * s + y * c)
    if isinstance(g, Line):
        return Line(R(g.start), R(g.end))
    return Arc(R(g.center), g.radius, g.start_angle + a, g.sweep)


def _polar_chain(segs: list):
    """``(centre, n, the pieces of one turn)`` when the loop ``segs`` (lines and arcs) is
    one run of pieces turned ``n`` times evenly round a centre (a gear's outline, a star),
    each copy checked piece by piece to EQUAL_TOL; else None."""
    if len(segs) < 6 or not all(isinstance(g, (Line, Arc)) for g in segs):
        return None
    n_all = len(segs)
    pts = [g.start for g in segs]
    C = (sum(p[0] for p in pts) / n_all, sum(p[1] for p in pts) / n_all)
    C = (float(_r(C[0])), float(_r(C[1])))

    def sig(g):
        m = g.at(g.start_angle + g.sweep / 2) if isinstance(g, Arc) else \
            ((g.start[0] + g.end[0]) / 2, (g.start[1] + g.end[1]) / 2)
        return (isinstance(g, Arc), round(g.length, 6), round(math.dist(m, C), 6))
    sigs = [sig(g) for g in segs]
    from ..shapes import _same
    for n in range(n_all // 2, 2, -1):
        if n_all % n:
            continue
        p = n_all // n
        if not all(sigs[i] == sigs[(i + p) % n_all] for i in range(n_all)):
            continue
        step = 2 * math.pi / n
        # the copy k of piece i is piece i + k p, turned either way round
        for sign in (1, -1):
            if all(_same(_rotated(segs[i], C, sign * k * step), segs[(i + k * p) % n_all])
                   for k in range(1, n) for i in range(p)):
                period = segs[:p] if sign > 0 else segs[:p]
                if sign < 0:        # the loop runs clockwise: the pattern turns the other way
                    return None
                return C, n, period
    return None


def _polar_polys(teeth: list, C):
    """``(n, first angle, [(radius, angle) of each vertex of the first])`` when the polygons
    ``teeth`` are one polygon turned evenly round ``C`` (a whole turn), else None."""
    n = len(teeth)
    if n < 2 or any(len(t) != len(teeth[0]) for t in teeth):
        return None

    def ang(t):
        cx = sum(p[0] for p in t) / len(t) - C[0]
        cy = sum(p[1] for p in t) / len(t) - C[1]
        return math.atan2(cy, cx)
    order = sorted(teeth, key=lambda t: ang(t) % (2 * math.pi))
    first = order[0]
    step = 2 * math.pi / n
    polar = [(math.dist(p, C), math.atan2(p[1] - C[1], p[0] - C[0])) for p in first]
    for k, t in enumerate(order):
        for (r, a), p in zip(polar, t):
            q = (C[0] + r * math.cos(a + k * step), C[1] + r * math.sin(a + k * step))
            if math.dist(p, q) > EQUAL_TOL:
                return None
    return n, polar


# ------------------------------------------------------------------ ticks
def _periodic(vals: list) -> list:
    """The shortest list ``P`` with ``vals[i] == P[i % len(P)]`` (within EQUAL_TOL).

    Only the periods of the values' labels can be one (two values within EQUAL_TOL are in
    one cluster of the sorted values whose gaps are at most EQUAL_TOL, so they have one
    label): those come from the labels' prefix function (Knuth-Morris-Pratt), shortest
    first, each then checked value by value; not every length from 1 checked (20,000 ticks
    of no period: 2e8 comparisons)."""
    n = len(vals)
    if n == 0:
        return vals
    label = [0] * n
    order = sorted(range(n), key=vals.__getitem__)
    for a, b in zip(order, order[1:]):
        label[b] = label[a] + (vals[b] - vals[a] > EQUAL_TOL)
    border = [0] * n            # the longest proper border of label[:i + 1]
    for i in range(1, n):
        k = border[i - 1]
        while k and label[i] != label[k]:
            k = border[k - 1]
        border[i] = k + (label[i] == label[k])
    periods = []
    k = border[-1]
    while k:
        periods.append(n - k)
        k = border[k - 1]
    for p in periods:
        if all(abs(vals[i] - vals[i % p]) <= EQUAL_TOL for i in range(n)):
            return vals[:p]
    return vals


def _runs(idx_pos: list, step: float) -> list[list]:
    """Maximal runs of consecutive members (positions ``step`` apart) of sorted
    ``(position, item)`` pairs."""
    runs: list[list] = []
    for pos, it in idx_pos:
        # against the run's first member: every member within EQUAL_TOL of start + k step
        if runs and abs(pos - runs[-1][0][0] - len(runs[-1]) * step) <= EQUAL_TOL:
            runs[-1].append((pos, it))
        else:
            runs.append([(pos, it)])
    return runs


MIN_FAMILY = 5      # strokes in a row (ticks) written as one loop


def _tick_families(lines: list) -> tuple[list, list]:
    """Single strokes (``(a, b)`` point pairs) that are one family: ticks along a line
    (starts evenly spaced on a line, one direction, lengths repeating) or round a centre
    (radial, evenly turned, one radius at their anchored end).  Returns ``([family], the
    indices of the strokes in them)``,
    a family ``("row", p0, step, u, lengths)`` or ``("polar", C, R, a0, step, sign,
    lengths)``."""
    fams = []
    left = list(range(len(lines)))
    # ticks along a line: group by direction
    by_dir: dict = {}
    for i in left:
        a, b = lines[i]
        L = math.dist(a, b)
        u = ((b[0] - a[0]) / L, (b[1] - a[1]) / L)
        by_dir.setdefault((round(u[0], 7), round(u[1], 7)), []).append(i)
    used: set = set()
    for u, idx in by_dir.items():
        if len(idx) < MIN_FAMILY:
            continue
        # starts on one line across u: group by the start's coordinate along u
        along: dict = {}
        for i in idx:
            a = lines[i][0]
            along.setdefault(round(a[0] * u[0] + a[1] * u[1], 6), []).append(i)
        for key, grp in along.items():
            if len(grp) < MIN_FAMILY:
                continue
            v = (-u[1], u[0])
            pos = sorted(((lines[i][0][0] * v[0] + lines[i][0][1] * v[1]), i) for i in grp)
            gaps = [b[0] - a[0] for a, b in zip(pos, pos[1:])]
            step = min(gaps) if gaps else 0
            if step <= EQUAL_TOL:
                continue
            for run in _runs(pos, step):
                if len(run) < MIN_FAMILY:
                    continue
                items = [i for _, i in run]
                p0 = lines[items[0]][0]
                d = (lines[items[1]][0][0] - p0[0], lines[items[1]][0][1] - p0[1])
                ok = all(math.dist(lines[i][0], (p0[0] + k * d[0], p0[1] + k * d[1]))
                         <= EQUAL_TOL for k, i in enumerate(items))
                if not ok:
                    continue
                lens = [math.dist(*lines[i]) for i in items]
                fams.append(("row", p0, d, (u[0], u[1]), lens))
                used.update(items)
    rest = [i for i in left if i not in used]
    # ticks round a centre: the centre from two strokes' carriers
    tries = 0
    while len(rest) >= MIN_FAMILY and tries < 4:
        tries += 1
        C = None
        a0, b0 = lines[rest[0]]
        for j in rest[1:]:
            a1, b1 = lines[j]
            d0 = (b0[0] - a0[0], b0[1] - a0[1])
            d1 = (b1[0] - a1[0], b1[1] - a1[1])
            den = d0[0] * d1[1] - d0[1] * d1[0]
            if abs(den) > 1e-9 * math.hypot(*d0) * math.hypot(*d1):
                t = ((a1[0] - a0[0]) * d1[1] - (a1[1] - a0[1]) * d1[0]) / den
                C = (a0[0] + t * d0[0], a0[1] + t * d0[1])
                break
        if C is None:
            break
        radial = []
        for i in rest:
            a, b = lines[i]
            ra, rb = math.dist(a, C), math.dist(b, C)
            if min(ra, rb) <= EQUAL_TOL:
                continue
            aa = math.atan2(a[1] - C[1], a[0] - C[0])
            ab = math.atan2(b[1] - C[1], b[0] - C[0])
            if abs(math.remainder(aa - ab, 2 * math.pi)) * max(ra, rb) <= EQUAL_TOL:
                radial.append(i)
        if len(radial) < MIN_FAMILY:
            rest = rest[1:]
            continue
        # the anchored end: the outer ends on one radius, else the inner ends
        found = False
        for outer in (True, False):
            ends = {}
            for i in radial:
                a, b = lines[i]
                ra, rb = math.dist(a, C), math.dist(b, C)
                anchor, free = (a, b) if (ra >= rb) == outer else (b, a)
                ends.setdefault(round(math.dist(anchor, C), 6), []).append((i, anchor, free))
            R_key, grp = max(ends.items(), key=lambda kv: len(kv[1]))
            if len(grp) < MIN_FAMILY:
                continue
            R = sum(math.dist(an, C) for _, an, _ in grp) / len(grp)
            def turn(p):
                t = math.atan2(p[1] - C[1], p[0] - C[0]) % (2 * math.pi)
                return 0.0 if t > 2 * math.pi - 1e-12 else t
            pos = sorted((turn(an), (i, an, fr)) for i, an, fr in grp)
            step = min(b[0] - a[0] for a, b in zip(pos, pos[1:]))
            if step * R <= EQUAL_TOL:
                continue
            for run in _runs(pos, step):
                if len(run) < MIN_FAMILY:
                    continue
                a0 = _snap_angle(run[0][0], R)
                st = _snap_angle(step, R * len(run))
                good = all(math.dist(an, (C[0] + R * math.cos(a0 + k * st),
                                          C[1] + R * math.sin(a0 + k * st))) <= EQUAL_TOL
                           for k, (_, (i, an, fr)) in enumerate(run))
                if not good:
                    continue
                lens = [math.dist(an, fr) for _, (i, an, fr) in run]
                fams.append(("polar", C, R, a0, st, -1 if outer else 1, lens))
                used.update(i for _, (i, _, _) in run)
                found = True
            if found:
                break
        rest = [i for i in rest if i not in used]
        if not found:
            break
    return fams, used


# ------------------------------------------------------------------ copies of a whole part
def _signature(d: Drawing):
    """``(numbers, body centre)`` of a simple part (one recognised outline, recognised holes,
    nothing else), its numbers the same for two parts that are copies of each other moved;
    None for any other part."""
    if d.paths or d.texts or d.ellipses or (d.engrave is not None and not d.engrave.empty) \
            or _unknown(d):
        return None
    loops = [circular(o.segments) for o in d.outlines] + [[c] for c in d.circles]
    dep = [len(c) for c in _containers(loops)] if loops else []
    if sum(1 for k in dep if k == 0) != 1 or any(k > 1 for k in dep):
        return None
    body = recognise(loops[dep.index(0)])
    if body is None or body.kind == "Polygon":
        return None
    holes = []
    for segs, k in zip(loops, dep):
        if k == 1:
            h = recognise(segs)
            if h is None or h.kind == "Polygon":
                return None
            holes.append((h.kind, h.size, h.center[0] - body.center[0],
                          h.center[1] - body.center[1]))
    holes.sort(key=lambda t: (t[0], round(t[2], 6), round(t[3], 6)))
    return (body.kind, body.size, holes), body.center


def _rounded(x):
    if isinstance(x, (list, tuple)):
        return tuple(_rounded(y) for y in x)
    return round(x, 5) + 0.0 if isinstance(x, float) else x


def _same_sig(a, b) -> bool:
    def flat(x):
        if isinstance(x, (list, tuple)):
            return [v for y in x for v in flat(y)]
        return [x]
    fa, fb = flat(a), flat(b)
    if len(fa) != len(fb):
        return False
    for x, y in zip(fa, fb):
        if isinstance(x, str) or isinstance(y, str):
            if x != y:
                return False
        elif abs(x - y) > EQUAL_TOL:
            return False
    return True


# what a Drawing holds that the inferred writer writes (a field it does not know, added to
# the reader later, sends the part to the piece-by-piece writer, so nothing is dropped)
_KNOWN = {"outlines", "circles", "ellipses", "paths", "notes", "unit", "texts", "seen",
          "engrave", "paths_cut", "precision"}


def _unknown(d: Drawing) -> bool:
    from dataclasses import fields
    return any(getattr(d, f.name) for f in fields(d) if f.name not in _KNOWN)


def _copies(items: list, deadline=None) -> list:
    """``items`` with each run of parts that are copies of one part moved evenly along a line
    (the washers laid out under a plate) as one item ``(kind, name, first part, (start,
    step, count))``."""
    sigs = []
    for k, (kind, _, d) in enumerate(items):
        if deadline is not None and k % 64 == 0:
            deadline.check("finding the copies of a part")
        sigs.append(_signature(d) if kind == "solid" else None)
    names = {name for _, name, _ in items}
    # parts whose numbers round alike, then each checked against the first to EQUAL_TOL
    buckets: dict = {}
    for j, sg in enumerate(sigs):
        if sg is not None:
            buckets.setdefault(repr(_rounded(sg[0])), []).append(j)
    out = []
    taken: set = set()
    for i, (kind, name, d) in enumerate(items):
        if i in taken:
            continue
        if sigs[i] is None:
            out.append((kind, name, d))
            continue
        group = [j for j in buckets[repr(_rounded(sigs[i][0]))] if j >= i and j not in taken
                 and _same_sig(sigs[i][0], sigs[j][0])]
        ln = _line([sigs[j][1] for j in group]) if len(group) >= 2 else None
        if ln is None:
            out.append((kind, name, d))
            sigs_done = set(group)      # no row: each on its own, never grouped again
            for j in sigs_done:
                sigs[j] = None if j != i else sigs[j]
            continue
        p0, step, n = ln
        first = min(group, key=lambda j: sigs[j][1])
        taken.update(group)
        base = _common_name([items[j][1] for j in group])
        if base in names:
            base = _ident(base, names)
        names.add(base)
        out.append(("solid", base, items[first][2], (p0, step, n)))
    return out


def _common_name(names: list) -> str:
    import os
    pre = os.path.commonprefix(names).rstrip("_0123456789")
    if pre.startswith("l_") or len(pre) < 2:     # layer `0`'s parts (`l_01`, ...)
        return "part"
    return pre

