"""The assembled product: every solid part extruded by its thickness and moved by its ``Place``
(docs/language.md, "Placing parts in 3D"), as GLB (one named node per part, in the flat
assembly view's colours), the fit check on it with Manifold's 3D booleans (W0517 parts that
collide, W0518 a part that reaches no other), and a picture of it (PNG: the triangles projected
and painted back to front with Pillow).

Placements come from the booleans' :attr:`~.booleans.Drawing.placement` (a 4x4 matrix per
part from the flat sheet to the product); without any ``Place`` each part stays where it is on
the sheet, z from 0 up through its thickness.  All lengths are in millimetres.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..part.part import Output
from ..part.build.sunk import DEFAULT_THICKNESS

# mm^3 and mm: a smaller common volume, or one thinner than this, is parts touching (faces flush)
VOLUME_TOL = 1e-3
DEPTH_TOL = 1e-6
# mm: a part farther than this from every other part reaches none (a tab short of its slot);
# nearer, it touches: the clearance of a fit (meshing gears' backlash, 0.05 mm in
# std/gears.aidl; a slot cut 0.1 mm wider than its tab) is contact, not a part floating free
GAP_TOL = 0.1


def placements(output: Output) -> dict[str, np.ndarray]:
    """Part name -> 4x4 matrix (flat sheet to assembled product) of every part the program
    places (or whose assembly it places); {} when it places none."""
    d = output.drawing
    got = getattr(d, "placement", None) if d is not None else None
    return dict(got) if got else {}


def colours(output: Output) -> dict[str, str]:
    """Part name -> ``#rrggbb``: the flat assembly view's colour of each solid part (the SVG
    preview's :data:`~.part.PALETTE`, in the parts' order)."""
    from ..part.part import PALETTE
    solids = [p for p in output.parts if p.kind == "solid"]
    return {p.name: PALETTE[i % len(PALETTE)] for i, p in enumerate(solids)}


def solids(output: Output, thickness: float | None = None) -> list[tuple[str, object]]:
    """(part name, ``manifold3d.Manifold``) per solid part: its profile extruded by its
    thickness (``thickness`` mm overrides) and placed."""
    return extrude([(p.name, p.kind, p.shape, p.thickness) for p in output.parts],
                   placements(output), thickness, bends=bends_of(output))


def bends_of(output: Output) -> dict[str, list]:
    """Part name -> its ``Bend``s on the sheet (:func:`~..part.placement.bends_of`); {}."""
    d = output.drawing
    return dict(getattr(d, "bends", None) or {}) if d is not None else {}


def extrude(parts, where: dict, thickness: float | None = None, deadline=None,
            bends: dict | None = None) -> list[tuple[str, object]]:
    """(name, ``manifold3d.Manifold``) of each solid of ``parts`` = [(name, kind,
    CrossSection, thickness mm or None)], extruded, bent by ``bends[name]`` (its ``Bend``s:
    :func:`~..part.placement.bend_points`, chords within ``CHORD_TOL``) and moved by
    ``where[name]`` (4x4).  ``deadline``: a :class:`~aidl_lang.base.limits.Deadline` checked
    before each part (raises :class:`~aidl_lang.base.limits.OutOfBudget`)."""
    import manifold3d as mf
    out = []
    bends = bends or {}
    for name, kind, shape, t in parts:
        if kind != "solid" or shape is None or shape.is_empty():
            continue
        if deadline is not None:
            deadline.check("the fit check", None)
        t = float(thickness or t or DEFAULT_THICKNESS)
        m = mf.Manifold.extrude(shape, t)
        if bends.get(name):
            m = bent(m, bends[name], t)
        M = where.get(name)
        if M is not None:
            m = m.transform(np.asarray(M[:3, :4], dtype=float))
        out.append((name, m))
    return out


def bent(m, bends, t: float, tol: float | None = None):
    """The ``manifold3d.Manifold`` ``m`` (a part extruded on the flat sheet, ``t`` mm thick)
    bent by its ``bends`` (:func:`~..part.placement.bend_points`): cut across its bend zones so
    each chord stays within ``tol`` mm (default ``CHORD_TOL``) of the bent surface
    (:func:`~..part.placement.refine_for_bends`), then every vertex moved."""
    import manifold3d as mf
    from ...geometry.shapes.tessellate import CHORD_TOL
    from ..part.build.placement import bend_points, refine_for_bends
    mesh = m.to_mesh64()
    v, f = refine_for_bends(np.asarray(mesh.vert_properties, dtype=float)[:, :3],
                            np.asarray(mesh.tri_verts, dtype=np.int64), bends, t,
                            CHORD_TOL if tol is None else tol)
    return mf.Manifold(mf.Mesh64(vert_properties=bend_points(v, bends, t),
                                 tri_verts=f.astype(np.uint64)))


def _rgba(colour: str) -> list[int]:
    return [int(colour[i:i + 2], 16) for i in (1, 3, 5)] + [255]


# ------------------------------------------------------------------ fit check
@dataclass
class Collision:
    """Two parts whose solids share ``volume`` mm^3 inside ``box`` (x0, y0, z0, x1, y1, z1 mm);
    ``depth``: how far one part runs into the other, across both sheets (a slot that much
    too narrow, :func:`_depth`); ``places``: each connected piece's box, where there are
    several (else empty)."""
    a: str
    b: str
    volume: float
    box: tuple
    depth: float
    # each connected piece's box where there are several (two tabs too thick for their two
    # slots: runs cm, cu read one box spanning both and the part between)
    places: tuple = ()
    # the common volume is thinnest across `a`'s sheet (not `b`'s): `b`'s edge or shoulder
    # runs into `a`'s face, no slot too narrow (run dj: a riser's shoulder 0.3 mm into a
    # sloping plank's underside, read as its slots 0.3 mm too narrow)
    into_face: bool = False


@dataclass
class Gap:
    """A part that touches no other part: ``nearest`` is ``gap`` mm away."""
    part: str
    nearest: str
    gap: float


def fit(bodies, deadline=None, normals: dict | None = None,
        plates: dict | None = None, counts: dict | None = None
        ) -> tuple[list[Collision], list[Gap]]:
    """The fit check of the assembled product with Manifold's 3D booleans: every pair of parts
    whose solids overlap by more than :data:`VOLUME_TOL` (and :data:`DEPTH_TOL` deep), and,
    with two parts or more, every part that comes no nearer than :data:`GAP_TOL` to any
    other (a tab that does not reach its slot).  ``bodies``: (name, ``Manifold``) placed
    (:func:`solids`, :func:`extrude`), or a :class:`Bodies` that extrudes each when first
    needed; ``normals``: part name -> the unit normal of its sheet
    (the placement's z axis; +z when missing), for the depth (:func:`_depth`).

    Only the pairs whose bounding boxes overlap (:func:`box_pairs`, a sort and sweep) are
    intersected; a part's nearest neighbour is sought in the order of the boxes' distances,
    stopping at the first box farther than the best gap found.  ``deadline``: a
    :class:`~aidl_lang.base.limits.Deadline` checked before every boolean and every distance
    (raises :class:`~aidl_lang.base.limits.OutOfBudget`), so the check ends within the compile's
    budget plus one Manifold call.

    ``plates``: part name -> (``CrossSection``, 4x4 placement or None, thickness mm), the
    plates ``bodies`` were extruded from (:func:`plates_of`): two parallel plates whose
    sheets are apart along their normal, or meet face to face over a common area (a carrier
    stacked on its gears), are decided from their outlines in 2D (:func:`_stacked`), without
    the 3D boolean (the same answer: 20 to 60 ms a pair of toothed plates -> under 1 ms).

    ``counts``: a dict given is filled with what the check did, the same on any machine
    (``vertices`` of the bodies, ``booleans`` 3D intersections, ``gaps`` distances asked):
    the sweep's work (:func:`aidl_lang.params.sweep_plan.work`)."""
    if not isinstance(bodies, Bodies):
        bodies = _Made(bodies)
    tally = {"vertices": 0, "booleans": 0, "gaps": 0}
    if counts is not None:
        counts.update(tally)
        tally = counts

    def tick():
        if deadline is not None:
            deadline.check("the fit check", None)
    boxes = np.array([bodies.box(i) for i in range(len(bodies))], dtype=float).reshape(-1, 6)
    normals = normals or {}
    hits: list[Collision] = []
    touching = set()
    n = len(bodies)
    for i, j in box_pairs(boxes, GAP_TOL):
        tick()
        na, nb = bodies.name(i), bodies.name(j)
        if plates is not None and na in plates and nb in plates:
            stacked = _stacked(plates[na], plates[nb])
            if stacked is not None:
                if stacked:
                    touching.update((i, j))
                continue
            # each plate cut to the pair's common box (grown by the gap's reach) before the
            # boolean: what lies outside it is in no common part and no nearer than
            # 2 GAP_TOL (a lid's vents far from its walls' tabs); a whole solid extruded
            # only when the box holds all of its outline
            near = _common_box(boxes[i], boxes[j], 2 * GAP_TOL)
            ma = _within(plates[na], near, lambda: bodies[i][1], tally)
            mb = _within(plates[nb], near, lambda: bodies[j][1], tally)
        else:
            ma, mb = bodies[i][1], bodies[j][1]
        common = ma ^ mb
        tally["booleans"] += 1
        vol = float(common.volume()) if not common.is_empty() else 0.0
        if vol > VOLUME_TOL:
            # the connected pieces with volume (Manifold leaves zero-volume sheets where
            # faces touch)
            solids = [m for m in common.decompose() if m.volume() > VOLUME_TOL] or [common]
            pieces = np.array([_box(m) for m in solids], dtype=float)
            box = tuple(float(v) for v in np.concatenate([pieces[:, :3].min(axis=0),
                                                          pieces[:, 3:].max(axis=0)]))
            depth, into_face = _depth(common, normals.get(na), normals.get(nb), box)
            parallel = _parallel(normals.get(na), normals.get(nb))
            depth = _capped(depth, max(_thinnest(m, normals.get(na), normals.get(nb))
                                        for m in solids), parallel)
            if depth > DEPTH_TOL:
                places = tuple(tuple(float(v) for v in q) for q in pieces) \
                    if len(pieces) > 1 else ()
                hits.append(Collision(na, nb, vol, box, depth, places, into_face))
                touching.update((i, j))
                continue
        if i not in touching or j not in touching:
            # faces in contact leave a common part of no volume; else ask how far apart
            tally["gaps"] += common.is_empty()
            if not common.is_empty() or ma.min_gap(mb, 2 * GAP_TOL) <= GAP_TOL:
                touching.update((i, j))
    gaps = []
    if n >= 2:
        for i in range(n):
            if i in touching:
                continue
            d = np.sqrt(np.sum(_box_gaps(boxes[i], boxes) ** 2, axis=1))
            d[i] = np.inf
            best = None
            for j in np.argsort(d, kind="stable"):
                if best is not None and d[j] >= best[0]:
                    break            # no nearer part can be in a box this far
                tick()
                g = float(d[j])
                if g < 1e3:
                    # Manifold answers the search length itself when nothing is nearer: widen
                    # it until the gap is inside (run bz: a paddle 3 mm and 27 mm off its frame,
                    # their boxes overlapping, was said "1 mm away")
                    reach = g + 1.0
                    while True:
                        tally["gaps"] += 1
                        got = float(bodies[i][1].min_gap(bodies[j][1], reach))
                        if got < reach - 1e-9 or reach >= 1e4:
                            break
                        reach *= 8.0
                    g = got
                if best is None or g < best[0]:
                    best = (g, bodies.name(j))
            if not any(g.part == best[1] and g.nearest == bodies.name(i) for g in gaps):
                gaps.append(Gap(bodies.name(i), best[1], best[0]))    # a pair is said once
    tally["vertices"] += bodies.vertices
    return hits, gaps


def plates_of(parts, where: dict, thickness: float | None = None,
              bends: dict | None = None) -> dict:
    """Part name -> (``CrossSection``, 4x4 placement or None, thickness mm) of each flat solid
    of ``parts`` (as :func:`extrude` takes them), for :func:`fit`'s ``plates``; a part with
    ``Bend``s (``bends[name]``) is no plate: the 3D booleans decide it."""
    bends = bends or {}
    return {name: (shape, where.get(name), float(thickness or t or DEFAULT_THICKNESS))
            for name, kind, shape, t in parts
            if kind == "solid" and shape is not None and not shape.is_empty()
            and not bends.get(name)}


def _rigid(M) -> np.ndarray | None:
    """``M`` (4x4, None: identity) when its 3x3 part is a rotation or a mirror, else None."""
    M = np.eye(4) if M is None else np.asarray(M, dtype=float)
    R = M[:3, :3]
    return M if np.allclose(R.T @ R, np.eye(3), rtol=0.0, atol=1e-12) else None


def _stacked(a, b) -> bool | None:
    """Two plates ``(CrossSection, placement, thickness)`` decided without a 3D boolean:
    ``False`` when their sheets are parallel and more than :data:`GAP_TOL` apart along the
    normal (no common volume, nothing within reach); ``True`` when they are parallel, meet in
    one plane (faces flush, within 1e-9 mm) and their outlines share an area there (they
    touch: no common volume, 0 apart); ``None`` for everything else (the 3D booleans say)."""
    Ma, Mb = _rigid(a[1]), _rigid(b[1])
    if Ma is None or Mb is None:
        return None
    Ra = Ma[:3, :3]
    R = Ra.T @ Mb[:3, :3]                       # b in a's frame
    t = Ra.T @ (Mb[:3, 3] - Ma[:3, 3])
    if abs(abs(R[2, 2]) - 1.0) > 1e-12 or np.abs(R[2, :2]).max() > 1e-12 \
            or np.abs(R[:2, 2]).max() > 1e-12:
        return None                             # not parallel
    zb = sorted((t[2], t[2] + R[2, 2] * b[2]))
    gap = max(0.0, zb[0]) - min(a[2], zb[1])    # > 0: apart along the normal
    if gap > GAP_TOL:
        return False
    if abs(gap) > 1e-9:
        return None
    flat = b[0].transform(np.array([[R[0, 0], R[0, 1], t[0]], [R[1, 0], R[1, 1], t[1]]]))
    area = (a[0] ^ flat).area()
    return True if area > 1e-6 and area * 1e-9 < VOLUME_TOL / 2 else None


def box_pairs(boxes: np.ndarray, pad: float = 0.0) -> list[tuple[int, int]]:
    """The pairs ``(i, j)``, ``i < j``, of ``boxes`` (n x 6: x0, y0, z0, x1, y1, z1, mm) that
    overlap once each is grown by ``pad`` on every side, sorted: the boxes are swept in the
    order of x0, each meeting only those that start before it ends (sort and sweep)."""
    b = np.asarray(boxes, dtype=float).reshape(-1, 6)
    lo, hi = b[:, :3] - pad, b[:, 3:] + pad
    order = np.argsort(lo[:, 0], kind="stable")
    ends = np.searchsorted(lo[order, 0], hi[order, 0], side="right")
    pairs = []
    for k, i in enumerate(order):
        js = order[k + 1:ends[k]]
        if len(js):
            ok = np.all((lo[js, 1:] <= hi[i, 1:]) & (lo[i, 1:] <= hi[js, 1:]), axis=1)
            pairs.extend((min(i, j), max(i, j)) for j in js[ok].tolist())
    return sorted(pairs)


def _box_gaps(a: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """Per box of ``boxes`` (n x 6), how far it is from box ``a`` along x, y and z (0 where
    they overlap); n x 3."""
    return np.maximum(0.0, np.maximum(a[:3] - boxes[:, 3:], boxes[:, :3] - a[3:]))


def normals_of(where: dict) -> dict:
    """Part name -> the unit normal of its sheet in the product (its placement's z axis)."""
    return {name: np.asarray(M[:3, 2], dtype=float) for name, M in where.items()}


def _depth(common, na, nb, box) -> tuple[float, bool]:
    """How far two plates run into each other, and whether across plate a's sheet:
    ``common`` (their common volume) cut across the line where their planes meet (``na`` x
    ``nb``), at seven heights along it; in each cut the pieces' widths are summed along each
    normal (a slot 0.5 mm too narrow leaves 0.25 mm each side: 0.5), the smaller sum taken;
    the most frequent figure of the cuts.  The second value is True when that figure is the
    sum along ``na`` in every cut that gives it (b's edge runs into a's face; a slot of a too narrow for b is thin along
    ``nb``).  Parallel plates (or no normals): the common volume's extent along the normal,
    False."""
    z = np.array([0.0, 0.0, 1.0])
    na = z if na is None else na
    nb = z if nb is None else nb
    d = np.cross(na, nb)
    if np.linalg.norm(d) < 1e-9:
        v = np.asarray(common.to_mesh().vert_properties, dtype=float)[:, :3] @ na
        return float(v.max() - v.min()), False
    e3 = d / np.linalg.norm(d)
    e1 = na - (na @ e3) * e3
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(e3, e1)
    R = np.eye(4)[:3]
    R[:, :3] = np.array([e1, e2, e3])
    turned = common.transform(R)
    ub = np.array([nb @ e1, nb @ e2])
    ub /= np.linalg.norm(ub)
    lo, hi = turned.bounding_box()[2], turned.bounding_box()[5]
    figures, across_a = [], []
    for f in (0.13, 0.27, 0.38, 0.5, 0.62, 0.73, 0.87):
        polys = [np.asarray(p, dtype=float) for p in turned.slice(lo + f * (hi - lo)).to_polygons()]
        polys = [p for p in polys if len(p) >= 3]
        if not polys:
            continue
        sa = sum(float(p[:, 0].max() - p[:, 0].min()) for p in polys)
        sb = sum(float((p @ ub).max() - (p @ ub).min()) for p in polys)
        figures.append(round(min(sa, sb), 6))
        across_a.append(sa < sb - 1e-9)
    if not figures:
        return float(min(box[3] - box[0], box[4] - box[1], box[5] - box[2])), False
    best = max(set(figures), key=lambda v: (figures.count(v), -v))
    # across a's sheet in every cut of that figure (a cross-halving's two slots too narrow
    # are thin across one sheet above the crossing's middle, the other below: a slot)
    return best, all(a for f, a in zip(figures, across_a) if f == best)


def _parallel(na, nb) -> bool:
    """Whether two plates' normals (None: +z) are parallel: the plates lie one on the other
    or side by side in one plane."""
    z = np.array([0.0, 0.0, 1.0])
    return bool(np.linalg.norm(np.cross(z if na is None else na, z if nb is None else nb))
                < 1e-9)


def _thinnest(piece, na=None, nb=None) -> float:
    """A piece of a common volume: its thickness where thinnest (mm), the least of its
    extents across each face of its convex hull (an upper bound of its least width; 0 for a
    flat piece).  Where faces of the two plates lie on each other, the common volume keeps
    a sheet of no thickness that can stretch a sliver's piece far past it (run gm's garage:
    a roof tab's end 0.964 mm past its slot, with sheets along the roof's underside and the
    slot's side: a hull 9 mm across every way); such sheets lie across a plate's normal
    ``na``, ``nb`` or the line where the plates meet, so the piece is first cut to what a
    copy moved :data:`SHEET` each way along those keeps (the sheets go, the slivers stay,
    2 SHEET thinner) and each sliver measured on its own: the thickest of them."""
    whole = _hull_width(piece)
    if na is None or nb is None or _parallel(na, nb):
        return whole
    d = np.cross(na, nb)
    kept = piece
    for n in (np.asarray(na, float), np.asarray(nb, float), d / np.linalg.norm(d)):
        for sign in (1.0, -1.0):
            kept = kept ^ piece.translate(tuple(sign * SHEET * n))
    slivers = [m for m in kept.decompose() if m.volume() > VOLUME_TOL]
    if not slivers:
        return whole
    return min(whole, max(_hull_width(m) for m in slivers) + 2 * SHEET)


# how far a copy of a common piece is moved each way to cut the sheets of no thickness
# from it (:func:`_thinnest`), mm
SHEET = 1e-4


def _hull_width(piece) -> float:
    """The least of ``piece``'s extents across each face of its convex hull (mm; 0 for a
    flat piece)."""
    from scipy.spatial import ConvexHull, QhullError
    v = np.asarray(piece.to_mesh().vert_properties, dtype=float)[:, :3]
    try:
        normals = ConvexHull(v).equations[:, :3]
    except (QhullError, ValueError):
        return 0.0
    proj = v @ normals.T
    return float((proj.max(axis=0) - proj.min(axis=0)).min())


def _capped(figure: float, thinnest: float, parallel: bool) -> float:
    """How deep two parts run into each other: ``figure`` (:func:`_depth`), unless the
    thickest piece of their common volume, ``thinnest`` across, is thinner: side by side in
    one plane the overlap's width, not the sheet's thickness (run fe: a pull disc 1.5 mm into
    its rails' ends, "3 mm deep"); across each other, a piece under half the figure (a slot
    too narrow leaves a sliver of half the figure each side) is a nib or a tenon off its
    mortise, which runs only its own thickness in (runs fd, ff: a 0.07 mm nib "3.84 mm
    deep", a tenon 3.3 mm down the slope from its mortise "9 mm deep")."""
    if parallel:
        return min(figure, thinnest)
    return thinnest if thinnest < figure / 2 - 1e-9 else figure


# a plate is cut to a pair's common box (:func:`_within`) when that holds at most this part
# of its outline's bounds: else the whole solid, extruded once, serves every pair
CLIP = 0.25


def _common_box(a: np.ndarray, b: np.ndarray, pad: float) -> np.ndarray:
    """The box (x0, y0, z0, x1, y1, z1) common to ``a`` and ``b`` each grown by ``pad``."""
    return np.concatenate([np.maximum(a[:3], b[:3]) - pad, np.minimum(a[3:], b[3:]) + pad])


def _within(plate, box: np.ndarray, whole, tally: dict):
    """The plate ``(CrossSection, placement, thickness)`` extruded and placed as
    :func:`extrude` does, cut first to the rectangle of its sheet that holds all of ``box``
    (its eight corners taken back through the placement; its vertices counted in
    ``tally``); ``whole()`` (its whole solid) when that rectangle holds the whole outline."""
    import manifold3d as mf
    shape, M, t = plate
    corners = np.array([[box[0 + 3 * (k & 1)], box[1 + 3 * (k >> 1 & 1)],
                         box[2 + 3 * (k >> 2 & 1)], 1.0] for k in range(8)])
    local = corners if M is None else corners @ np.linalg.inv(np.asarray(M, float)).T
    x0, y0 = local[:, :2].min(axis=0)
    x1, y1 = local[:, :2].max(axis=0)
    bx0, by0, bx1, by1 = shape.bounds()
    x0, y0, x1, y1 = max(x0, bx0), max(y0, by0), min(x1, bx1), min(y1, by1)
    if (x1 - x0) * (y1 - y0) > CLIP * (bx1 - bx0) * (by1 - by0):
        return whole()
    rect = mf.CrossSection.square((max(x1 - x0, 1e-9), max(y1 - y0, 1e-9))).translate((x0, y0))
    m = mf.Manifold.extrude(shape ^ rect, t)
    tally["vertices"] += int(m.num_vert())
    return m if M is None else m.transform(np.asarray(M, dtype=float)[:3, :4])


class _Made:
    """``(name, Manifold)`` solids already made (a list as :func:`extrude` gives), read the
    way :func:`fit` reads a :class:`Bodies`."""

    def __init__(self, bodies) -> None:
        self.items = list(bodies)
        self.vertices = sum(int(m.num_vert()) for _, m in self.items)

    def __len__(self) -> int:
        return len(self.items)

    def __getitem__(self, i: int):
        return self.items[i]

    def name(self, i: int) -> str:
        return self.items[i][0]

    def box(self, i: int) -> tuple:
        return _box(self.items[i][1])


class Bodies:
    """``(name, Manifold)`` of each solid of ``parts`` (as :func:`extrude` takes them and
    makes them), each extruded when first asked for: the fit check cuts a pair of plates to
    their common box and extrudes that (:func:`_within`), so a plate whose every pair is cut
    is never extruded whole (a lid's hundred vents).  ``box(i)``: the bounding box of body
    ``i`` from its outline's bounds and placement (its solid's for a bent part), without
    extruding it; ``vertices``: those of the bodies extruded so far."""

    def __init__(self, parts, where: dict, thickness: float | None = None, deadline=None,
                 bends: dict | None = None):
        self.parts = [(name, shape, t) for name, kind, shape, t in parts
                      if kind == "solid" and shape is not None and not shape.is_empty()]
        self.where, self.thickness, self.deadline = where, thickness, deadline
        self.bends = bends or {}
        self.made: dict = {}
        self.vertices = 0

    def __len__(self) -> int:
        return len(self.parts)

    def __getitem__(self, i: int):
        if i not in self.made:
            name, shape, t = self.parts[i]
            bends = {name: self.bends[name]} if self.bends.get(name) else None
            (got,) = extrude([(name, "solid", shape, t)], self.where, self.thickness,
                             self.deadline, bends)
            self.made[i] = got
            self.vertices += int(got[1].num_vert())
        return self.made[i]

    def __iter__(self):
        return (self[i] for i in range(len(self)))

    def name(self, i: int) -> str:
        return self.parts[i][0]

    def box(self, i: int) -> tuple:
        name, shape, t = self.parts[i]
        if self.bends.get(name):
            return _box(self[i][1])
        t = float(self.thickness or t or DEFAULT_THICKNESS)
        x0, y0, x1, y1 = shape.bounds()
        c = np.array([[x, y, z, 1.0] for x in (x0, x1) for y in (y0, y1) for z in (0.0, t)])
        M = self.where.get(name)
        if M is not None:
            c = c @ np.asarray(M, dtype=float).T
        return tuple(float(v) for v in np.concatenate([c[:, :3].min(axis=0),
                                                       c[:, :3].max(axis=0)]))


def _box(m) -> tuple:
    b = m.bounding_box()
    return tuple(b)
