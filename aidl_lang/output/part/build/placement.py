"""Where the parts go in the assembled product: the matrices of ``Place``.

In: a part's structure and the solved values ``x`` (its frame offsets), its ancestors'
``Place`` (a position in mm and rotations about x, y, z in radians, fixed axes, or the 3x3
matrix of ``face=``/``up=``).  Out: the
4x4 matrix from the flat sheet (x, y in mm, z up through the thickness) to the assembled
product (:func:`placement_matrix`), read by the booleans into ``Drawing.placement`` for the
3D writers and the fit check (:mod:`aidl_lang.output.fabrication.assembly`).
"""
from __future__ import annotations

import math

import numpy as np

from ....geometry.core.model import Structure


def rotation_matrix(rx: float, ry: float, rz: float) -> np.ndarray:
    """The 3x3 rotation turning about x by ``rx``, then about y by ``ry``, then about z by
    ``rz`` (radians, fixed axes: ``Rz @ Ry @ Rx``); quarter turns are exact (cos 90 deg is 0,
    not 6e-17), so a box's panels land on the design's numbers to the last bit."""
    def cs(a):
        q = a / (math.pi / 2)
        if abs(q - round(q)) < 1e-12:
            return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(round(q)) % 4]
        return math.cos(a), math.sin(a)
    (cx, sx), (cy, sy), (cz, sz) = cs(rx), cs(ry), cs(rz)
    Rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]], dtype=float)
    Ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]], dtype=float)
    Rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]], dtype=float)
    return Rz @ Ry @ Rx


def _step(pl) -> np.ndarray:
    """The 4x4 of one ``Place``: its rotation (angles, or face=/up='s 3x3), then its position."""
    step = np.eye(4)
    rot = pl[1]
    step[:3, :3] = np.array(rot, dtype=float) if isinstance(rot[0], tuple) \
        else rotation_matrix(*rot)
    step[:3, 3] = pl[0]
    return step


def _holds_placed(s: Structure) -> bool:
    """Whether a structure below assembly ``s`` has a ``Place`` of its own (its parts then
    stand by their placements, not where ``s`` lies on the sheet)."""
    return s.kind == "assembly" and any(getattr(c, "placement", None) is not None
                                        for c in s.subtree() if c is not s)


def frame_matrix(s: Structure, x, placed_below: bool = False) -> np.ndarray:
    """The 4x4 matrix taking a point of structure ``s``'s own frame (x, y as written in it,
    z up from its bottom face) to the assembled product.  Each structure of the chain goes
    into its parent's by its ``Place`` (rotation, then position) or, unplaced, by its frame
    offset as on the sheet unless a structure nearer ``s`` is placed (``placed_below``: where
    a relation lays an assembly out on the sheet moves no part placed in it).  A ``Place``
    with ``on=`` (its fourth item, a structure) is set in that structure's frame
    (:func:`on_frame`), and the chain above it is not read."""
    steps = []
    for a in [s, *s.ancestors()]:              # s first: which steps a Place below replaces
        pl = getattr(a, "placement", None)
        if pl is not None:
            steps.append(_step(pl))
            on = pl[3] if len(pl) > 3 else None
            if on is not None:
                steps.append(on_frame(on, x))
                break
        elif not placed_below:
            step = np.eye(4)
            step[0, 3], step[1, 3] = x[a.fx], x[a.fy]
            steps.append(step)
        # (an unplaced assembly above a Place: its move on the sheet is layout, not 3D; run
        # dv: `RightOf(box, ...)` of a lid_box moved its Placed panels 247 mm off the origin)
        placed_below = placed_below or pl is not None
    M = np.eye(4)
    for step in reversed(steps):               # root first: M maps s's local frame to world
        M = M @ step
    return M


def on_frame(on: Structure, x) -> np.ndarray:
    """The frame a ``Place(part, on=ON, ...)`` sets its part in: ``on``'s own frame in the
    assembled product (:func:`frame_matrix`); for an assembly whose parts are placed, the
    frame those parts stand in (its own move on the sheet left out, as they leave it)."""
    return frame_matrix(on, x, placed_below=_holds_placed(on))


def origin_on_sheet(s: Structure, x) -> tuple[float, float]:
    """Where part ``s``'s own (0, 0) lies on the flat sheet (mm): the sum of its and its
    ancestors' frame offsets, or, for a pattern's copy placed by its own ``Place``, where the
    original's origin went (its ``copy_origin``): placed, it stands as its original would
    (run db: 45 fingers `Place`d one by one marched off in a diagonal, each 10 i mm along its
    own y)."""
    if getattr(s, "placement", None) is not None and s.copy_origin is not None:
        from ....geometry.core.expr import evaluate
        ox, oy = (float(evaluate(e, x)) for e in s.copy_origin)
        return ox, oy
    chain = [s, *s.ancestors()]
    return sum(float(x[a.fx]) for a in chain), sum(float(x[a.fy]) for a in chain)


def placement_matrix(s: Structure, x) -> np.ndarray:
    """The 4x4 matrix taking a point of part ``s`` on the flat sheet (absolute x, y in mm; z
    from 0 up through its thickness) to the assembled product: the point less where the
    part's own (0, 0) lies on the sheet (:func:`origin_on_sheet`), then its frame into the
    product (:func:`frame_matrix`), so a program with no ``Place`` is the sheet itself."""
    ox, oy = origin_on_sheet(s, x)
    to_local = np.eye(4)
    to_local[0, 3], to_local[1, 3] = -ox, -oy
    return frame_matrix(s, x) @ to_local


# ------------------------------------------------------------------ bends (``Bend``)
# The most cutting planes across a part's bend zones (refine_for_bends): past it they are set
# farther apart (the chord error grows, never the work)
MAX_BENT_PLANES = 2000


def bends_of(s: Structure, x) -> list[tuple[float, float, float]]:
    """The ``Bend``s of part ``s`` on the flat sheet: ``[(at, angle, radius)]`` sorted by
    ``at``, each the bend line's x in absolute sheet coordinates (mm; the ``at`` written, in
    the part's frame, plus the frame offsets, ``x`` the solved values), its angle (radians,
    positive: the part's top face, z = thickness, inside the bend) and inside radius (mm);
    [] when the program bends it nowhere."""
    got = getattr(s, "bends", None)
    if not got:
        return []
    ox = sum(float(x[a.fx]) for a in [s, *s.ancestors()])
    return sorted((float(at) + ox, float(angle), float(radius)) for at, angle, radius, _ in got)


def bend_zones(bends, t: float) -> list[tuple[float, float, float, float]]:
    """Each bend's zone on the flat sheet: ``(x0, x1, angle, radius)``, centred on its line
    ``at`` and ``|angle| * (radius + t / 2)`` wide (the sheet's middle keeps its length: a
    K-factor of 0.5), for material ``t`` mm thick."""
    out = []
    for at, a, r in bends:
        w = abs(a) * (r + t / 2)
        out.append((at - w / 2, at + w / 2, a, r))
    return out


def bend_points(v: np.ndarray, bends, t: float) -> np.ndarray:
    """The points ``v`` (n x 3, the flat sheet: x, y mm, z 0..``t`` up through the thickness)
    of a part bent by ``bends`` (:func:`bends_of`), in the same frame: the part left of the
    first bend zone stays; in a zone a point at flat x goes round the bend's axis (parallel to
    y, ``radius`` from the face inside the bend) by ``angle`` times its way across the zone,
    its depth in the sheet kept (the inside face at the radius); past a zone the rest of the
    part turns rigidly by ``angle`` and runs on along the last tangent.  y never changes."""
    v = np.asarray(v, dtype=float)
    out = v.copy()
    X = np.eye(3)                           # (x, z, 1) of the frame so far: flat -> bent
    done = np.zeros(len(v), dtype=bool)
    for x0, x1, a, r in bend_zones(bends, t):
        before = ~done & (v[:, 0] < x0)
        out[before, 0], out[before, 2] = _apply(X, v[before, 0], v[before, 2])
        done |= before
        zone = ~done & (v[:, 0] <= x1)
        rn = r + t / 2
        s = 1.0 if a >= 0 else -1.0
        z = v[zone, 2] if s > 0 else t - v[zone, 2]       # depth from the outside face
        phi = (v[zone, 0] - x0) / rn
        rho = t + r - z
        bx, bz = x0 + rho * np.sin(phi), (t + r) - rho * np.cos(phi)
        out[zone, 0], out[zone, 2] = _apply(X, bx, bz if s > 0 else t - bz)
        done |= zone
        # past the zone: turned by the angle about the axis, then on along the tangent
        c, sn = np.cos(a), np.sin(a)
        cz = t + r if s > 0 else -r                        # the axis' z on the flat sheet
        B = np.array([[c, -sn, 0.0], [sn, c, 0.0], [0.0, 0.0, 1.0]])
        # the zone's end x1 goes to where the axis turns x0 by the angle: rotate about (x0, cz)
        # after shifting the rest back by the zone's width
        T1 = np.array([[1.0, 0.0, -(x1 - x0)], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
        about = np.array([[1.0, 0.0, x0], [0.0, 1.0, cz], [0.0, 0.0, 1.0]])
        back = np.array([[1.0, 0.0, -x0], [0.0, 1.0, -cz], [0.0, 0.0, 1.0]])
        X = X @ about @ B @ back @ T1
    rest = ~done
    out[rest, 0], out[rest, 2] = _apply(X, v[rest, 0], v[rest, 2])
    return out


def _apply(X: np.ndarray, px: np.ndarray, pz: np.ndarray):
    return X[0, 0] * px + X[0, 1] * pz + X[0, 2], X[1, 0] * px + X[1, 1] * pz + X[1, 2]


def refine_for_bends(v: np.ndarray, f: np.ndarray, bends, t: float, tol: float):
    """The mesh ``v`` (n x 3, the flat sheet), ``f`` (m x 3 vertex indices) of a part to be
    bent, cut across each bend zone by evenly spaced planes x = const: as many as the chords
    of an arc of the inside radius over the bend's angle need
    (:func:`~aidl_lang.geometry.shapes.tessellate.segments_for`, the tessellation of every arc
    written), times the least whole number that keeps the outside face's chords within ``tol``
    mm too, so the inside face's vertices fall on those of a concentric arc drawn with that
    radius (a lid's lip at zero clearance touches the wall, and shares no volume with it).  The
    bend is a cylinder along y: only x needs cutting.  Each cut splits the triangles it crosses
    at a vertex shared by both sides of each edge, so a watertight mesh stays watertight.  At
    most :data:`MAX_BENT_PLANES` planes in all (fewer past it: the chords grow, never the
    work).  Returns the new ``(v, f)``."""
    from ....geometry.shapes.tessellate import segments_for
    zones = bend_zones(bends, t)
    counts = []
    for x0, x1, a, r in zones:
        inner = segments_for(r, abs(a), tol, least=1)
        counts.append(inner * int(np.ceil(segments_for(r + t, abs(a), tol, least=1) / inner)))
    if sum(counts) > MAX_BENT_PLANES:
        counts = [max(1, c * MAX_BENT_PLANES // sum(counts)) for c in counts]
    planes = np.unique(np.concatenate([np.linspace(x0, x1, n + 1)
                                       for (x0, x1, _, _), n in zip(zones, counts)]))
    return _cut_x(v, f, _snapped(planes, v[:, 0]))


SNAP = 1e-6     # mm: a cutting plane this near a vertex's x goes through the vertex


def _snapped(planes: np.ndarray, x: np.ndarray) -> np.ndarray:
    """``planes`` with each one within :data:`SNAP` of a vertex's ``x`` moved onto it: a
    plane a rounding off a vertex cut slivers of no width off the triangles there, and the
    mesh was no manifold (run bq's roof bent 180 degrees, its zone exactly the band between
    its tabs, planes 1e-14 and 3e-10 mm off their corners: the roof was not drawn, 179.9
    degrees was)."""
    xs = np.unique(x)
    if not len(xs):
        return planes
    k = np.searchsorted(xs, planes)
    lo, hi = xs[np.clip(k - 1, 0, len(xs) - 1)], xs[np.clip(k, 0, len(xs) - 1)]
    near = np.where(np.abs(lo - planes) < np.abs(hi - planes), lo, hi)
    return np.unique(np.where(np.abs(near - planes) < SNAP, near, planes))


def _cut_x(v: np.ndarray, f: np.ndarray, planes: np.ndarray):
    """The mesh ``(v, f)`` cut by the planes x = ``planes`` (sorted): each triangle a plane
    crosses is clipped to every slab between two planes (a convex polygon: the triangle's
    boundary points within the slab, in order, fanned into triangles, its orientation kept);
    a point where an edge crosses a plane is one new vertex, shared by the triangles on both
    sides of the edge, so the mesh stays watertight and grows by about three triangles per
    slab a triangle spans (not by a fan per plane)."""
    x = v[:, 0]
    tx = x[f]
    lo, hi = tx.min(axis=1), tx.max(axis=1)
    first = np.searchsorted(planes, lo, side="right")       # the first plane > the least x
    last = np.searchsorted(planes, hi, side="left")         # past the last plane < the most x
    crossing = np.flatnonzero(last > first)
    if not len(crossing):
        return v, f
    new: list = []
    ids: dict = {}

    def cut(a: int, b: int, k: int) -> int:
        key = (a, b, k) if a < b else (b, a, k)
        i = ids.get(key)
        if i is None:
            c = planes[k]
            w = (c - x[a]) / (x[b] - x[a])
            p = v[a] + w * (v[b] - v[a])
            p[0] = c
            i = ids[key] = len(v) + len(new)
            new.append(p)
        return i

    out = [f[np.setdiff1d(np.arange(len(f)), crossing)]]
    tris = []
    for n in crossing.tolist():
        ring = []                                  # (vertex id, x) round the triangle
        tri = f[n]
        for e in range(3):
            a, b = int(tri[e]), int(tri[(e + 1) % 3])
            ring.append((a, x[a]))
            xa, xb = x[a], x[b]
            ks = np.flatnonzero((planes > min(xa, xb)) & (planes < max(xa, xb)))
            if xb < xa:
                ks = ks[::-1]
            ring += [(cut(a, b, int(k)), planes[k]) for k in ks]
        xs = np.array([q[1] for q in ring])
        bounds = np.concatenate([[-np.inf], planes[first[n]:last[n]], [np.inf]])
        for s0, s1 in zip(bounds[:-1], bounds[1:]):
            poly = [ring[i][0] for i in np.flatnonzero((xs >= s0) & (xs <= s1))]
            for i in range(1, len(poly) - 1):
                tris.append((poly[0], poly[i], poly[i + 1]))
    v = np.vstack([v, np.array(new).reshape(-1, 3)])
    f = np.vstack(out + [np.array(tris, dtype=np.int64).reshape(-1, 3)])
    # drop triangles of no area (a slab the triangle only touches at a vertex on its plane)
    e1, e2 = v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]
    return v, f[np.linalg.norm(np.cross(e1, e2), axis=1) > 1e-18]
