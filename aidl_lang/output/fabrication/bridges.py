"""What a router's bit does to a part's through-cuts (docs/machines.md, "CNC router").

A through-cut (a ``cut`` structure's curve: a slit, a relief cut) has no width in the design;
a laser cuts it a kerf wide, a router as wide as its bit: the tool's centre runs along the
line, so the cut is the line's capsule of the tool radius, round past each end.  Material the
design leaves between a through-cut and the part's outline, a hole or another through-cut
(a *bridge*) narrower than that is cut away: a slit stopped 1 mm short of a plate's edges
becomes, with a 3.175 mm bit, a slot through both edges, and the plate comes out in two
pieces although `aidl check` and `aidl parts` (which see the design) say one.

:func:`router_bridges` finds them: each bridge the bit cuts through (its width in the design
and what the bit leaves of it, below 0: cut away) and each part the bit cuts into more pieces
than the design has (W0510 in `aidl render`, a ``; warning:`` line in the G-code).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

# mm: a through-cut nearer than this to a loop meets it in the design (measured on chords,
# which lie up to CHORD_TOL, 0.005 mm, inside a curve: a relief cut ending on a round hole was
# a 'bridge' of 0.00367 mm that W0510 named instead of the one the bit cut through)
TOUCH = 0.01
SLIVER = 1e-6     # mm^2: pieces of less area left by the booleans' rounding are not pieces


@dataclass(frozen=True)
class Bridge:
    """Material between through-cut ``cut`` (its geometry's path) and ``other`` (words:
    ``the outline of `p```, ``a hole of `p```, ``through-cut `p.s.l```) of part ``part``:
    ``width`` mm in the design;
    ``left`` mm of it after the bit (``width`` less the tool radius, twice for two
    through-cuts), negative where the bit cuts through it."""
    part: str
    cut: str
    other: str
    width: float
    left: float


@dataclass(frozen=True)
class Split:
    """Part ``part`` comes out of the router in ``pieces`` pieces where the design has
    ``design`` (its outer loops); ``bridges``: the bridges the bit cuts through."""
    part: str
    pieces: int
    design: int
    bridges: list = field(default_factory=list)
    cuts: list = field(default_factory=list)   # with no bridge measured: the cut that meets an edge


def _polyline(segments, closed: bool) -> np.ndarray:
    """The chords of exact ``segments`` as a polyline (k x 2, mm), closed back to its start
    when ``closed``."""
    from ...geometry.shapes.curves import sample_xy
    xs, ys = [], []
    sample_xy(segments, xs, ys)
    if closed:
        xs.append(xs[0])
        ys.append(ys[0])
    else:
        end = segments[-1].end
        xs.append(end[0])
        ys.append(end[1])
    return np.column_stack([xs, ys])


def _point_seg(P: np.ndarray, A: np.ndarray, B: np.ndarray) -> float:
    """The least distance from the points ``P`` (m x 2) to the segments ``A``-``B``
    (n x 2 each)."""
    e = B - A
    L2 = (e * e).sum(1)
    L2 = np.where(L2 > 0, L2, 1.0)
    d = P[:, None, :] - A[None, :, :]
    t = np.clip((d * e[None]).sum(2) / L2[None], 0.0, 1.0)
    q = d - t[..., None] * e[None]
    return float(np.sqrt((q * q).sum(2)).min())


def _crosses(P: np.ndarray, Q: np.ndarray) -> bool:
    """Some chord of polyline ``P`` crosses or touches some chord of ``Q``."""
    a, b = P[:-1, None, :], P[1:, None, :]
    c, d = Q[None, :-1, :], Q[None, 1:, :]

    def orient(p, q, r):
        return (q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - \
            (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0])
    o1, o2 = orient(a, b, c), orient(a, b, d)
    o3, o4 = orient(c, d, a), orient(c, d, b)
    return bool(((o1 * o2 <= 0) & (o3 * o4 <= 0)).any())


def distance(P: np.ndarray, Q: np.ndarray) -> float:
    """The least distance (mm) between polylines ``P`` and ``Q`` (k x 2 each): 0 where they
    cross, else the least of their vertices' distances to the other's chords."""
    if len(P) < 2 or len(Q) < 2:
        return math.inf
    if _crosses(P, Q):
        return 0.0
    return min(_point_seg(P, Q[:-1], Q[1:]), _point_seg(Q, P[:-1], P[1:]))


def _capsules(P: np.ndarray, r: float, n: int = 32):
    """The region within ``r`` of polyline ``P``: the union of each chord's capsule, as a
    manifold3d CrossSection."""
    from manifold3d import CrossSection, OpType
    ring = np.column_stack([np.cos(np.linspace(0, 2 * math.pi, n, endpoint=False)),
                            np.sin(np.linspace(0, 2 * math.pi, n, endpoint=False))]) * r
    caps = [CrossSection.hull_points(np.vstack([ring + a, ring + b]))
            for a, b in zip(P[:-1], P[1:])]
    return CrossSection.batch_boolean(caps, OpType.Add)


def router_bridges(output, diameter: float) -> tuple[list[Bridge], list[Split]]:
    """The bridges a router's bit of ``diameter`` mm cuts through (:class:`Bridge`: between a
    through-cut of ``output`` and its part's outline or holes, less than the tool radius
    wide, or between two through-cuts, less than the diameter) and the parts it cuts into
    more pieces than the design has (:class:`Split`), part by part in ``output``'s order.
    ``output``: the design's :class:`~..part.part.Output` (not the tool paths)."""
    r = diameter / 2.0
    if r <= 0:
        return [], []
    by_part: dict = {}
    for st in output.cuts:
        if st.segments and st.part:
            by_part.setdefault(st.part, []).append(st)
    bridges, splits = [], []
    for p in output.parts:
        strokes = by_part.get(p.name)
        if not strokes or not p.loops:
            continue
        cuts = [(st.source or "a through-cut", _polyline(st.segments, st.closed))
                for st in strokes]
        loops = [((f"a hole of `{p.name}`" if lp.is_hole else f"the outline of `{p.name}`"),
                  _polyline(lp.segments, True)) for lp in p.loops]
        found, meets = [], []
        for i, (name, P) in enumerate(cuts):
            lo, hi = P.min(0) - 2 * r, P.max(0) + 2 * r
            others = [(what, Q, r) for what, Q in loops] + \
                [(f"through-cut `{n2}`", Q, 2 * r) for j, (n2, Q) in enumerate(cuts) if j > i]
            for what, Q, reach in others:
                if (Q.max(0) < lo).any() or (Q.min(0) > hi).any():
                    continue
                d = distance(P, Q)
                if TOUCH < d < reach:
                    found.append(Bridge(p.name, name, what, d, d - reach))
                elif d <= TOUCH:
                    meets.append(name)
        bridges += found
        if not found and not meets:
            continue
        # a cut that meets an edge hides the bridges at its other end from the distance
        # (0 to the edge): a slit from the top edge that turns and stops 1.2 mm short of the
        # side cuts a corner off, said by nothing), so the pieces are counted then too
        from manifold3d import CrossSection, OpType
        swept = CrossSection.batch_boolean([_capsules(P, r) for _, P in cuts], OpType.Add)
        left = p.shape - swept
        pieces = sum(1 for c in left.decompose() if c.area() > SLIVER)
        design = sum(1 for lp in p.loops if not lp.is_hole)
        if pieces > design:
            splits.append(Split(p.name, pieces, design, found, meets[:1]))
    return bridges, splits


def bridge_note(b: Bridge, diameter: float) -> str:
    """A bridge the bit cuts through, in words."""
    reach = "its radius" if b.other.startswith(("the outline", "a hole")) else "its diameter"
    return (f"the router's bit ({diameter:g} mm across) joins through-cut `{b.cut}` to "
            f"{b.other}: the "
            f"bridge between them is {b.width:.3g} mm wide, less than {reach} "
            f"({b.width - b.left:g} mm), and is cut away")


def split_message(s: Split, diameter: float) -> str:
    """W0510's words for a part the bit cuts into pieces."""
    if not s.bridges:           # only cuts that meet an edge: the bridges at their ends
        return (f"part `{s.part}` comes out of the router in {s.pieces} pieces, not "
                f"{s.design}: the bit ({diameter:g} mm across) cuts its through-cuts as wide "
                f"as itself and cuts away the bridges they leave (at the end of through-cut "
                f"`{s.cuts[0] if s.cuts else 'a through-cut'}`: W0507 says each); leave "
                "bridges wider "
                "than the bit's radius or use a smaller tool (the profile's `tool_diameter`)")
    first = s.bridges[0]
    more = len(s.bridges) - 1
    return (f"part `{s.part}` comes out of the router in {s.pieces} pieces, not {s.design}: the "
            f"bit ({diameter:g} mm across) cuts its through-cuts as wide as itself and cuts "
            f"away the bridges they leave (between through-cut `{first.cut}` and {first.other}: "
            f"{first.width:.3g} mm wide, less than the bit's reach, "
            f"{first.width - first.left:g} mm"
            + (f"; and {more} more bridge{'s' if more != 1 else ''}" if more else "")
            + "); leave bridges wider than the bit's radius or use a smaller tool (the "
            "profile's `tool_diameter`)")
