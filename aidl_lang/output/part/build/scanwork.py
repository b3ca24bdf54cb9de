"""What one Manifold union costs, and the direction that makes it cheap.

``CrossSection.batch_boolean`` (Clipper2's Vatti scan line) walks its active edge list once per
scan beam: its work is about, summed over the distinct y values of the input's vertices, the
number of edges crossing that scan line.  4,000 disjoint circles of different radii on one
horizontal row give about 100,000 scan beams of 8,000 active edges each (31 s); the same row
scanned along x (turned by 90 degrees) has 2 to 4 edges per beam (0.02 s).

:func:`scan_work` estimates that work from each face's interval along the scan axis, its
vertex count and its contours alone, in O(n log n) (sorted interval ends): every vertex of a
face meets the edges of the faces whose interval overlaps its own (2 per contour).  It counts
vertices at the same height (equal circles on a row) once each where Clipper counts the height
once, and a contour crossed by a scan line more than twice (a star, a comb) as crossed twice:
it decides when the exact count (:func:`exact_scan_work`, from the vertices, O(V log V)) is
worth taking, and which way to scan (:func:`plan`).
"""
from __future__ import annotations

import manifold3d as mf
import numpy as np

# s per unit of scan-line work (one active edge in one scan beam), at least: the least measured
# (CPU time of one batch_boolean, manifold3d 3.5) was 11.0 ns (3,600 circles on a 60 x 60
# grid, 6.4e6 units in 0.071 s; 2,000 random circles 11.4 ns); in beams of WIDE or more active
# edges, where it grows with the list (the active list leaves the cache), 27.9 ns (300 circles
# on a row; rows of 3,000-4,000 circles 50-57 ns, concentric circles 26-39 ns, tall rectangles
# and triangles 37-52 ns, a cross of two rows 34 ns); half of each, so that only a union sure
# to end past the deadline is refused before it starts (as UNION_SECONDS_PER_VERTEX)
SECONDS_PER_SCAN = 5.5e-9
SECONDS_PER_WIDE_SCAN = 13e-9
WIDE = 500
TURN_GAIN = 4.0        # scanned along x only when that is this many times less work
TURN_SECONDS = 0.05    # ... and the work along y is worth it (the examples' unions are less)
# a quarter turn and back, exact in floating point: (x, y) -> (-y, x) and (x, y) -> (y, -x)
TURN = ((0.0, -1.0, 0.0), (1.0, 0.0, 0.0))
TURN_BACK = ((0.0, 1.0, 0.0), (-1.0, 0.0, 0.0))


def _layout(faces: list) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each face's vertex count, number of contours and bounds (xmin, ymin, xmax, ymax)."""
    n = len(faces)
    v = np.fromiter((f.num_vert() for f in faces), float, n)
    k = np.fromiter((f.num_contour() for f in faces), float, n)
    b = np.array([f.bounds() for f in faces], float).reshape(n, 4)
    return v, k, b


def _work(v: np.ndarray, k: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> float:
    """:func:`scan_work` from the faces' vertex counts, contours and intervals."""
    w = 2.0 * k
    o = np.argsort(lo, kind="stable")
    slo, clo = lo[o], np.concatenate(([0.0], np.cumsum(w[o])))
    o = np.argsort(hi, kind="stable")
    shi, chi = hi[o], np.concatenate(([0.0], np.cumsum(w[o])))
    total = clo[-1]
    below = chi[np.searchsorted(shi, lo, "left")]          # faces ending below this one
    above = total - clo[np.searchsorted(slo, hi, "right")]  # faces starting above it
    return float(v @ (total - below - above))


def scan_work(faces: list, axis: int = 1) -> float:
    """Estimated scan-line work (active edges x scan beams, no unit) of one union of
    ``faces`` (``mf.CrossSection``) scanned along ``axis`` (1: y, Clipper's own; 0: x): the
    sum over faces of their vertex count times twice the contours of the faces whose interval
    along ``axis`` overlaps theirs.  A row of n equal-sized faces along x costs ~n^2 along y,
    ~n along x.  O(n log n) in the number of faces."""
    if not faces:
        return 0.0
    v, k, b = _layout(faces)
    return _work(v, k, b[:, axis], b[:, axis + 2])


def exact_scan_work(faces: list, axis: int = 1) -> tuple[float, float]:
    """The scan-line work of one union of ``faces`` from their vertices: the sum over the
    distinct coordinates along ``axis`` of the vertices (Clipper's scan beams) of the edges
    that cross or start at that scan line; as (the sum over beams of fewer than :data:`WIDE`
    active edges, the sum over the others).  O(V log V) in the number of vertices."""
    polys = [p for f in faces for p in f.to_polygons() if len(p)]
    if not polys:
        return 0.0, 0.0
    c = np.concatenate([np.asarray(p, dtype=float)[:, axis] for p in polys])
    sizes = np.fromiter((len(p) for p in polys), np.int64, len(polys))
    nxt = np.arange(1, len(c) + 1)
    ends = np.cumsum(sizes)
    nxt[ends - 1] = ends - sizes                 # each contour's last vertex: back to its first
    d = c[nxt]
    lo, hi = np.sort(np.minimum(c, d)), np.sort(np.maximum(c, d))
    beams = np.unique(c)
    active = np.searchsorted(lo, beams, "right") - np.searchsorted(hi, beams, "right")
    wide = active >= WIDE
    return float(active[~wide].sum()), float(active[wide].sum())


def union_seconds(faces: list, left: float, vertices: int | None = None) -> float:
    """The least time (s) one ``batch_boolean`` union of ``faces`` is expected to take by its
    scan-line work, looked at only as closely as ``left`` (the seconds before the deadline)
    needs (``vertices``: their number of vertices, when known): 0 when even every face
    overlapping every other could not come near ``left``; the exact work
    (:func:`exact_scan_work`) when the estimate (:func:`scan_work`, which can count a
    non-convex contour short) comes within 4 times of it."""
    if len(faces) < 2:
        return 0.0
    if vertices is None:
        vertices = sum(f.num_vert() for f in faces)
    # every face overlapping every other, each contour of at least 3 vertices
    if 2.0 * vertices * (vertices / 3) * SECONDS_PER_WIDE_SCAN * 4 <= left:
        return 0.0
    if scan_work(faces) * SECONDS_PER_WIDE_SCAN * 4 <= left:
        return 0.0
    narrow, wide = exact_scan_work(faces)
    return narrow * SECONDS_PER_SCAN + wide * SECONDS_PER_WIDE_SCAN


def plan(faces: list, left: float = float("inf")) -> tuple[bool, bool]:
    """How to unite ``faces`` (in groups, :meth:`~.booleans.Renderer.union`): (turned: scan
    along x, the faces turned a quarter turn, :data:`TURN`, and the result back,
    :data:`TURN_BACK`, when the work along y is worth it, more than :data:`TURN_SECONDS`,
    and :data:`TURN_GAIN` times that along x: a row; watched: the work of uniting them all at
    once comes within 4 times of ``left``, the seconds before the deadline, so that each
    group's union is to be weighed (:func:`union_seconds`) before it starts)."""
    if len(faces) < 2:
        return False, False
    v = sum(f.num_vert() for f in faces)
    bound = 2.0 * v * (v / 3)        # every face overlapping every other
    if bound * SECONDS_PER_SCAN <= TURN_SECONDS and bound * SECONDS_PER_WIDE_SCAN * 4 <= left:
        return False, False
    vs, k, b = _layout(faces)
    along_y = _work(vs, k, b[:, 1], b[:, 3])
    turn = False
    if along_y * SECONDS_PER_SCAN > TURN_SECONDS:
        along_x = _work(vs, k, b[:, 0], b[:, 2])
        if along_y > TURN_GAIN * along_x:
            turn, along_y = True, along_x
    return turn, along_y * SECONDS_PER_WIDE_SCAN * 4 > left


def decompose(shape: mf.CrossSection, loops: list) -> list:
    """``shape.decompose()`` (its pieces: Clipper's scan line too), scanned along x when its
    ``loops`` (its polygons, Nx2 arrays) lie on a row along x (:func:`plan`'s test on the
    loops as faces); the pieces turned back, exact."""
    if len(loops) < 2:
        return shape.decompose()
    v = np.fromiter((len(p) for p in loops), float, len(loops))
    lo = np.array([p.min(axis=0) for p in loops], float).reshape(-1, 2)
    hi = np.array([p.max(axis=0) for p in loops], float).reshape(-1, 2)
    k = np.ones(len(loops))
    along_y = _work(v, k, lo[:, 1], hi[:, 1])
    if along_y * SECONDS_PER_SCAN <= TURN_SECONDS or \
            along_y <= TURN_GAIN * _work(v, k, lo[:, 0], hi[:, 0]):
        return shape.decompose()
    return [turned_back(p) for p in shape.transform(TURN).decompose()]


def turned(faces: list) -> list:
    """``faces`` turned a quarter turn counter-clockwise (exact: coordinates swapped and
    negated, applied by Manifold when the shapes are next read)."""
    return [f.transform(TURN) for f in faces]


def turned_back(shape: mf.CrossSection) -> mf.CrossSection:
    """``shape`` turned back a quarter turn clockwise (exact)."""
    return shape.transform(TURN_BACK)
