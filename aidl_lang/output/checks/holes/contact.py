"""Where a hole touches the outer edge of its part (W0514, :func:`.openings._check_flush`):
the points of contact themselves, not the hole's centre (issue 91: a round hole tangent to
the edge was said "near" its centre, 10 mm off).

The contact is found on the polygons the booleans made (the hole's cut region and the outer
loops of the part with that hole filled): the boundary points of either that lie within
:data:`NEAR` of the other, grouped into stretches (a circle tangent to two edges touches at
two places), each said at the middle of its stretch.  A stretch on one of the hole's
circles is put back on the exact circle: the point of the circle nearest to the edge, on the
line from its centre to the edge's nearest point (a polygon inscribed in the circle would
place it up to half a chord off)."""
from __future__ import annotations

import numpy as np

from ....geometry.shapes.tessellate import CHORD_TOL
from ..common import _signed

NEAR = 4 * CHORD_TOL     # mm: boundary points this close to the other boundary are in contact
ON_CIRCLE = 0.25         # mm: a stretch's middle this close to a hole's circle lies along it
GAP = 1.0                # mm: contact points further apart than this are separate stretches


def _segments(loops) -> tuple:
    """The segments ``(A, B)`` (n x 2 each) of closed polylines ``loops``."""
    if not loops:
        return np.zeros((0, 2)), np.zeros((0, 2))
    A = np.concatenate(loops)
    B = np.concatenate([np.roll(P, -1, axis=0) for P in loops])
    return A, B


def _nearest(P: np.ndarray, A: np.ndarray, B: np.ndarray) -> tuple:
    """For each point of ``P`` the least distance to the segments ``A``-``B`` and the foot
    of it: ``(dist, foot)``."""
    if not len(A) or not len(P):
        return np.full(len(P), np.inf), P.copy()
    d = B - A
    L2 = np.einsum("ij,ij->i", d, d)
    out = np.full(len(P), np.inf)
    foot = P.copy()
    for k in range(0, len(P), 256):
        p = P[k:k + 256, None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(L2 > 0, np.einsum("ijk,jk->ij", p - A[None], d) / L2, 0.0)
        t = np.clip(t, 0.0, 1.0)
        q = A[None] + t[..., None] * d[None]
        e = np.hypot(*(q - p).transpose(2, 0, 1))
        j = np.argmin(e, axis=1)
        rows = np.arange(len(j))
        out[k:k + 256] = e[rows, j]
        foot[k:k + 256] = q[rows, j]
    return out, foot


def _exact_edge_point(c: np.ndarray, A: np.ndarray, B: np.ndarray, W) -> np.ndarray:
    """The point of the edge (segments ``A``-``B``) nearest to ``c``: on the circle that the
    vertices ``W`` (the edge's around it, in order along it) lie on when they lie on one (an
    edge that is an arc: the nearest chord's foot would be off by up to half a chord), else
    the nearest foot."""
    if len(W) >= 3:
        k = _fitted_circle(W)
        if k is not None:
            C, R = np.array(k[:2]), k[2]
            on = np.abs(np.hypot(*(W - C).T) - R).max() <= CHORD_TOL   # (crossings: on chords)
            u = c - C
            n = float(np.hypot(*u))
            if on and n > 0 and R < 1e6:
                return C + R * u / n
    _, q = _nearest(c[None], A, B)
    return q[0]


def _fitted_circle(W: np.ndarray) -> tuple | None:
    """The circle ``(cx, cy, r)`` nearest to the points ``W`` in least squares (Kasa's fit:
    the boolean's crossing vertices lie a little inside an arc edge, so three of them can
    miss it), or None when they lie on a line."""
    M = np.column_stack([W, np.ones(len(W))])
    sol, *_ = np.linalg.lstsq(M, -(W ** 2).sum(axis=1), rcond=None)
    cx, cy = -sol[0] / 2, -sol[1] / 2
    r2 = cx * cx + cy * cy - sol[2]
    if not np.isfinite(r2) or r2 <= 0:
        return None
    return float(cx), float(cy), float(np.sqrt(r2))


def _to_segments(p: np.ndarray, A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """The distance from point ``p`` to each segment ``A``-``B``."""
    d = B - A
    L2 = np.einsum("ij,ij->i", d, d)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(L2 > 0, ((p - A) * d).sum(axis=1) / L2, 0.0), 0.0, 1.0)
    return np.hypot(*(A + t[:, None] * d - p).T)


def _near_box(A, B, box, pad) -> np.ndarray:
    x0, y0, x1, y1 = box
    lo, hi = np.minimum(A, B), np.maximum(A, B)
    return ((hi[:, 0] >= x0 - pad) & (lo[:, 0] <= x1 + pad) & (hi[:, 1] >= y0 - pad)
            & (lo[:, 1] <= y1 + pad))


def _groups(P: np.ndarray) -> list:
    """``P`` (contact points) split into stretches: points within :data:`GAP` of one of a
    stretch's are in it (single linkage, in the order of the first point found)."""
    left = list(range(len(P)))
    out = []
    while left:
        grow, group = [left.pop(0)], []
        while grow:
            k = grow.pop()
            group.append(k)
            if not left:
                continue
            rest = np.array(left)
            close = np.hypot(*(P[rest] - P[k]).T) <= GAP
            grow += rest[close].tolist()
            left = rest[~close].tolist()
        out.append(P[group])
    return out


def circle_of(poly: np.ndarray) -> tuple | None:
    """The circle ``(cx, cy, r)`` through the vertices of ``poly``, a polygon inscribed in
    one (a tessellated Circle: every vertex on it), from three vertices a third of the way
    round from each other; None when they are in a line."""
    n = len(poly)
    if n < 3:
        return None
    (ax, ay), (bx, by), (cx, cy) = poly[0], poly[n // 3], poly[(2 * n) // 3]
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if abs(d) < 1e-12:
        return None
    a2, b2, c2 = ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy
    ux = (a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / d
    uy = (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / d
    return float(ux), float(uy), float(np.hypot(ax - ux, ay - uy))


def contact_points(region, filled, circles=(), edges=()) -> list:
    """The points (x, y) mm where the hole's cut ``region`` (a CrossSection) touches the
    outer loops of ``filled`` (the part with the hole filled in), one per stretch of contact,
    in the order found; ``circles``: the hole's circles ``(cx, cy, r)`` (exact), onto which a
    stretch lying along one is put back; ``edges``: the part's own circles (exact), whose
    point nearest a hole circle's centre is the contact where the stretch lies along one (a
    round hole tangent inside a disc: the tessellated disc's chords near a small hole are too
    few to fit their circle, and a chord's foot is off by up to its sagitta)."""
    H = [np.asarray(p, dtype=float) for p in region.to_polygons()]
    H = [P for P in H if len(P) >= 3]
    O = [np.asarray(p, dtype=float) for p in filled.to_polygons()]
    O = [P for P in O if len(P) >= 3 and _signed(P) > 0]
    if not H or not O:
        return []
    box = region.bounds()
    HA, HB = _segments(H)
    OA, OB = _segments(O)
    keep = _near_box(OA, OB, box, 2 * NEAR)
    OA, OB = OA[keep], OB[keep]
    if not len(OA):
        return []
    dh, fh = _nearest(HA, OA, OB)                 # the hole's vertices to the edge
    x0, y0, x1, y1 = box
    ov = OA[(OA[:, 0] >= x0 - NEAR) & (OA[:, 0] <= x1 + NEAR) & (OA[:, 1] >= y0 - NEAR)
            & (OA[:, 1] <= y1 + NEAR)]
    do, fo = _nearest(ov, HA, HB)                 # the edge's vertices to the hole
    P = np.vstack([((HA + fh) / 2)[dh <= NEAR], ((ov + fo) / 2)[do <= NEAR]])
    if not len(P):
        return []
    out = []
    for G in _groups(P):
        mid = (G.min(axis=0) + G.max(axis=0)) / 2   # the middle of the stretch
        out.append(_on_circle(mid, circles, OA, OB, edges))
    return out


def _on_circle(p: np.ndarray, circles, OA, OB, edges=()) -> tuple:
    """``p`` put back on the hole circle it lies along (within :data:`ON_CIRCLE`: the middle
    of a curved stretch lies inside the arc), at the point
    nearest to the edge near it (on an ``edges`` circle that ``p`` lies along, exactly);
    else ``p``."""
    off = [abs(float(np.hypot(p[0] - cx, p[1] - cy)) - r) for cx, cy, r in circles]
    for k in np.argsort(off, kind="stable"):
        cx, cy, r = circles[k]
        c = np.array([cx, cy])
        if off[k] > ON_CIRCLE:
            break
        far = _to_segments(p, OA, OB)
        near = far <= GAP
        if not near.any():
            continue
        wide = far <= max(5 * GAP, r)               # enough of an arc edge to fit its circle
        q = _exact_edge_point(c, OA[near], OB[near], OA[wide])
        for ex, ey, er in edges:                    # the part's own circle it lies along
            u = c - (ex, ey)
            m = float(np.hypot(*u))
            if m > 0 and abs(float(np.hypot(p[0] - ex, p[1] - ey)) - er) <= GAP:
                q = np.array([ex, ey]) + er * u / m
                break
        v = q - c
        n = float(np.hypot(*v))
        if n > 0:
            return float(cx + r * v[0] / n), float(cy + r * v[1] / n)
    return float(p[0]), float(p[1])
