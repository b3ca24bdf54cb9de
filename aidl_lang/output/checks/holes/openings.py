"""The holes of a part and the openings they cut:

* ``W0501`` a hole partly or wholly refilled by a sibling or ancestor solid (a hole cuts only
  the solid it is declared in; a solid united later fills it again), unless ``AllowOverlap``
  says so (:func:`_intended`) or the refilling shapes are drawn inside the opening (at least
  :data:`DRAWN_IN` of their area: a wheel's hub and spokes, a moon in a window);
* ``W0502`` a hole that cuts nothing (it lies outside its solid);
* ``W0503`` a hole that removes all of its solid;
* ``W0507`` (between features) a wall thinner than the minimum between two holes, or a hole and
  the outline, measured as the least distance between their boundaries, whatever the area
  (:func:`_analyse`, :func:`_report_openings`; the opening test of the rest is in
  :mod:`.walls`);
* ``W0508`` two separately declared holes that overlap or touch: one opening (a hole inside
  another that cuts a solid refilling it is said as a refill, :func:`_refiller`);
* ``W0512`` the faces one statement draws several times (in a loop) that overlap or touch,
  and two circles of one hole written apart that overlap (:mod:`.repeats`);
* ``W0514`` a hole inside its solid that only touches the outer edge (a wall of zero width);
* ``W0515`` an opening that no hole cut: a tiny void left between shapes that nearly meet, or
  a window the overlapping faces of one solid enclose (:mod:`.voids`).

Pairs of holes are found with a spatial index (:mod:`..nearby`), so the checks grow as
n log n in the number of holes; :func:`_analyse` also gives :mod:`.changes` the holes that
merge or reach the outline."""
from __future__ import annotations

import math

import re

import manifold3d as mf
import numpy as np

from ....base.records import Compared
from ....base.diagnostics import Diagnostic, DiagnosticSink, Label
from ....geometry.core.model import Structure
from ....geometry.shapes.tessellate import CHORD_TOL
from ...part.build.booleans import Drawing
from ...part.measure.nearby import (boundaries, boundary, box_pairs, box_pairs_between,
                                     close_pairs)
from .clearing import move_fix
from .contact import circle_of, contact_points
from .meant import MeantMerge
from ..common import (_apart, _template_own, written, MIN_AREA, MIN_WALL, _area, _body, _contributors, _cross, _depth, _edge_distance, _edges, _insert_fix,
                      _inside, _loop_boxes, _part_of, _pct, _signed, _significant, _union,
                      below)

def _intended(hole: Structure, owner: Structure, obj) -> bool:
    """``AllowOverlap(hole, x)`` was written for this hole (or a structure between it and
    the solid it cuts) with ``x`` the refilling ``obj`` (a shape or a solid), a structure
    around it, or a shape inside it."""
    allowed: set = set()
    s = hole
    while s is not None:
        allowed |= getattr(s, "overlap_ok", set())
        if s is owner:
            break
        s = s.parent
    if not allowed:
        return False
    t = obj if isinstance(obj, Structure) else obj.owner
    if obj in allowed:
        return True
    if isinstance(obj, Structure) and any(not isinstance(a, Structure) and a.owner.is_within(obj)
                                          for a in allowed):
        return True                  # a shape named in AllowOverlap, inside this solid
    while t is not None:
        if t in allowed:
            return True
        t = t.parent
    return False


def _perimeter(cs) -> float:
    return float(sum(np.hypot(*(np.roll(P, -1, axis=0) - P).T).sum()
                     for P in (np.asarray(p, dtype=float) for p in cs.to_polygons())))


def _check_flush(d: Drawing, s: Structure, shape, a: _Openings, cuts, min_wall: float,
                 sink) -> None:
    """W0514 for each hole of part ``s`` that lies wholly inside its solid (no part of it
    outside: not drawn as a notch) and yet only touches the outer edge (:func:`_analyse`'s
    notches): at a point, or along less than ``min_wall`` mm (at least :data:`MIN_WALL`), a
    wall of zero width that pinches the hole open onto the edge (a round hole tangent to the
    edge, a window's corner on the roof line).  A hole flush with the edge along more than
    that is a notch, as asked for a connector cut-out or a cross-halving slot, and is left
    alone.  The figure is the length of the contact, ``(P(filled) + P(hole) - P(filled -
    hole)) / 2`` over perimeters."""
    if not a.notches:
        return
    feats = [c for c in cuts if c.region is not None and not c.region.is_empty()
             and _area(c.region) > 1e-9]
    edges = None
    for j in sorted(a.notches):
        c = feats[j - 1]
        whole = _area(d.shapes.get(c.hole))
        if whole - _area(c.region) > max(MIN_AREA, 1e-6 * whole):
            continue                       # it overhangs the edge: a notch by design
        filled = shape + c.region
        contact = max(0.0, (_perimeter(filled) + _perimeter(c.region)
                            - _perimeter(filled - c.region)) / 2)
        if contact >= max(min_wall, MIN_WALL):
            continue                       # flush along a side: a notch
        where = "at a point" if contact < 2 * TOUCH else f"along only {contact:.2f} mm"
        circles = [k for k in (circle_of(np.asarray(f.to_polygons()[0], dtype=float))
                               for g, f in d.own.get(c.hole, ())
                               if g.kind == "Circle" and f is not None and not f.is_empty())
                   if k is not None]
        if edges is None:                  # the part's own circles, found once
            edges = [k for k in (circle_of(np.asarray(f.to_polygons()[0], dtype=float))
                                 for g, f in d.own.get(s, ())
                                 if g.kind == "Circle" and f is not None and not f.is_empty())
                     if k is not None]
        at = contact_points(c.region, filled, circles, edges)
        if not at:                         # (not found on the polygons: the hole's box)
            x0, y0, x1, y1 = c.region.bounds()
            at = [((x0 + x1) / 2, (y0 + y1) / 2)]
        said = " and ".join("({:.2f}, {:.2f})".format(*written(s, x, y)) for x, y in at[:4]) \
            + (f" and {len(at) - 4} more places" if len(at) > 4 else "")
        sink.warning("W0514", f"hole `{c.hole.path}` lies inside `{s.path}` but touches its "
                     f"outer edge {where} (a wall of zero width), so it opens onto the edge: "
                     f"the contact is at {said}", c.hole.span,
                     hint=f"move `{c.hole.name}` inward (by at least the minimum wall) to "
                          "leave material around it; if a notch is meant, let the hole run "
                          "past the edge (e.g. by 1 mm) so that the intent is explicit")


class _Near:
    """The final shape of a part near a region, for W0501: a part's loops whose bounding
    boxes meet the region's (found for every cut at once with :func:`.nearby.box_pairs`)
    filled even-odd give the part's shape exactly inside the region's box, so each hole is
    intersected with its neighbourhood, not with the whole part (which made W0501 quadratic
    in the number of holes)."""

    def __init__(self, roots, loops, cuts):
        self.roots, self.loops = roots, loops
        self.near: dict = {}                  # id(region) -> indices of the part's loops
        by_part: dict = {}
        for c in cuts:
            part = _part_of(c.owner, roots)
            if part in loops and c.owner is not part and c.region is not None \
                    and not c.region.is_empty():      # (a part's own holes: not asked)
                by_part.setdefault(part, []).append(c.region)
        for part, regions in by_part.items():
            lp = loops[part]
            if len(lp) <= 8:                  # small part: intersect with the whole,
                if len(regions) > SHARED_BY and any(len(p) > SHARED_VERTS for p in lp):
                    self._near_refill(part, regions)       # unless a long loop is shared
                continue
            pairs = box_pairs(np.vstack([_loop_boxes(lp), np.array(
                [r.bounds() for r in regions], dtype=float).reshape(-1, 4)]))
            n = len(lp)
            hit = pairs[(pairs[:, 0] < n) & (pairs[:, 1] >= n)]
            if _shared_loop(lp, hit[:, 0]):
                self._near_refill(part, regions)
                continue
            found: dict = {i: [] for i in range(len(regions))}
            for i, j in hit:
                found[int(j) - n].append(int(i))
            for k, r in enumerate(regions):
                self.near[id(r)] = found[k]

    def _near_refill(self, part, regions) -> None:
        """The neighbourhoods of ``regions`` in the part's shape where one long loop meets
        many of them (the opening of a row of overlapping holes, 5,000 holes: each would be
        intersected with the whole row, quadratic): the part's shape within the regions
        (``G``, the final shape times their union, one boolean) stands for it, its loops
        found near each region as above.  A region meets the final shape only inside
        itself, so ``region ^ G`` is ``region ^ final``."""
        G = _united(regions, within=self.roots[part])
        lp = [np.asarray(p, dtype=float) for p in G.to_polygons()]
        lp = [p for p in lp if len(p) >= 3]
        self.loops = dict(self.loops)
        self.loops[part] = lp
        found: dict = {i: [] for i in range(len(regions))}
        if lp:
            pairs = box_pairs(np.vstack([_loop_boxes(lp), np.array(
                [r.bounds() for r in regions], dtype=float).reshape(-1, 4)]))
            n = len(lp)
            for i, j in pairs[(pairs[:, 0] < n) & (pairs[:, 1] >= n)]:
                found[int(j) - n].append(int(i))
        for k, r in enumerate(regions):
            self.near[id(r)] = found[k]

    def local(self, part, region) -> mf.CrossSection:
        idx = self.near.get(id(region))
        if idx is None:
            return self.roots[part]
        lp = self.loops[part]
        return mf.CrossSection([lp[i].tolist() for i in idx], mf.FillRule.EvenOdd) if idx \
            else mf.CrossSection()


SHARED_VERTS = 1000    # a loop of more vertices than this ...
SHARED_BY = 16         # ... that meets more regions than this: :meth:`_Near._near_refill`


def _shared_loop(lp, hit_loops) -> bool:
    """Whether one loop of ``lp`` of more than :data:`SHARED_VERTS` vertices meets more than
    :data:`SHARED_BY` regions (``hit_loops``: the loop of each (loop, region) pair)."""
    if not len(hit_loops):
        return False
    counts = np.bincount(np.asarray(hit_loops, dtype=np.intp), minlength=len(lp))
    big = np.array([len(p) > SHARED_VERTS for p in lp])
    return bool((counts[big] > SHARED_BY).any())


def _united(shapes, within=None, plus=None) -> mf.CrossSection:
    """The union of ``shapes`` in groups (:meth:`..part.booleans.Renderer.union`'s way: a
    row of them scanned along the row, turned a quarter turn and back, exact); ``within``: a
    shape the union is then intersected with, ``plus`` one it is then united with, in the
    same turn (a row of 5,000 circles intersected with the plate they cut: 5 s scanned
    across the row; the plate in the first group: 6 s)."""
    from ...part.build.booleans import UNION_GROUP
    from ...part.measure.nearby import faces_apart
    from ...part.build.scanwork import plan, turned, turned_back
    faces = [f for f in shapes if f is not None and not f.is_empty()]
    turn = plan(faces)[0] if faces else False
    if not turn:                    # not a row: one batch, as :func:`.common._union` does
        out = _union(([plus] if plus is not None else []) + faces)
        return out ^ within if within is not None else out
    faces = turned(faces)
    # faces apart (a row of holes with walls between them) unite in one pass, the same
    # polygons in the same order, as :meth:`..part.booleans.Renderer.union` does
    grouped = len(faces) > UNION_GROUP and not faces_apart(faces)
    while grouped and len(faces) > UNION_GROUP:
        faces = [mf.CrossSection.batch_boolean(faces[i:i + UNION_GROUP], mf.OpType.Add)
                 for i in range(0, len(faces), UNION_GROUP)]
    out = mf.CrossSection.batch_boolean(faces, mf.OpType.Add)
    if within is not None:
        out = out ^ turned([within])[0]
    if plus is not None and not plus.is_empty():
        out = out + turned([plus])[0]
    return turned_back(out)


# ------------------------------------------------------------ webs and merged holes
# mm: boundaries closer than this touch.  Curves are tessellated into inscribed polygons that
# deviate from them by up to CHORD_TOL each, so two circles that touch can come out up to
# 2 CHORD_TOL apart: below that, the gap is the tessellation's, not the design's.
TOUCH = 2 * CHORD_TOL
DRAWN_IN = 0.5      # of a refiller's area inside the hole it refills: drawn into the opening


class _Openings(Compared):
    """What :func:`_analyse` finds between the holes of one part and its outline."""
    __slots__ = ("names", "spans", "merges", "webs", "notches", "areas", "cuts")

    def __init__(self, names: list, spans: list, merges: list | None = None,
                 webs: list | None = None, notches: set | None = None, areas: list | None = None,
                 cuts: list | None = None):
        self.names = names  # feature names: 0 the outline, 1.. the holes
        self.spans = spans
        self.merges = [] if merges is None else merges  # (i, j, depth mm, common area mm^2 | None)
        self.webs = [] if webs is None else webs  # (i, j, width, length, (x, y))
        self.notches = set() if notches is None else notches  # holes that reach the outline
        self.areas = [] if areas is None else areas  # of the features' regions, mm^2
        self.cuts = [] if cuts is None else cuts  # the holes' cuts: cuts[k - 1] is feature k


# s of the reference machine for one candidate pair of holes in _analyse (a Manifold XOR of
# two overlapping regions: 1,200 circles stacked, 48.6 s for 11,242 runs of 64 pairs)
PAIR_SECONDS = 68e-6


def _analyse(d: Drawing, s: Structure, shape, cuts, t: float, loops=None,
             tick=lambda ahead=0.0: None) -> _Openings:
    """The holes of part ``s`` (its ``cuts``) that overlap or touch each other (W0508) and the
    walls narrower than ``t`` between two holes or a hole and the outline (W0507), measured
    as the least distance between their boundaries (:func:`.nearby.close_pairs`; the hole's
    region is what it cut).  Candidate hole pairs come from :func:`.nearby.box_pairs`, so the
    work grows as n log n in the number of holes that are apart; holes stacked on each other
    pair all with all, so ``tick()`` is called every 64 intersections (the family's share of
    the budget, :class:`._Shares`: 1,200 circles drawn at one place ran 12 s here)."""
    feats = [c for c in cuts if c.region is not None and not c.region.is_empty()
             and _area(c.region) > 1e-9]
    res = _Openings([f"the outer edge of `{s.path}`"] + [f"hole `{c.hole.path}`" for c in feats],
                    [s.span] + [c.hole.span for c in feats], cuts=feats)
    if not feats or shape.is_empty():
        return res
    regions = [c.region for c in feats]
    res.areas = [0.0] + [_area(r) for r in regions] + [0.0]
    boxes = np.array([r.bounds() for r in regions], dtype=float)
    reach = max(t, TOUCH)
    meant = MeantMerge(d, shape, feats, res.areas)
    # 1. holes whose regions overlap: one opening
    merged = set()
    near = box_pairs(boxes, pad=reach / 2)
    for n, (i, j) in enumerate(near):
        if not n % 64:
            tick(64 * PAIR_SECONDS)         # the next 64 pairs' work, paid before it
        if (boxes[i, 0] > boxes[j, 2] or boxes[j, 0] > boxes[i, 2] or boxes[i, 1] > boxes[j, 3]
                or boxes[j, 1] > boxes[i, 3]):
            continue            # boxes apart: nothing in common (a row of holes 0.2 mm apart)
        common = regions[i] ^ regions[j]
        a = _area(common)
        if a > 1e-9:
            merged.add((i, j))
            if meant(i, j, common):
                continue        # a trim of the outline, or only a joint's overrun: as drawn
            res.merges.append((i + 1, j + 1, _depth(common, boxes[i], boxes[j]), a))
    # 2. the least distance between every two boundaries closer than `reach`
    # the outline: the part with its holes filled; its outer loops are feature 0, the loops
    # of openings no hole cut (between solids, or left by a fillet) the last feature
    # (many holes: united in groups, a row of them along the row, :func:`_united`; one
    # batch of 5,000 overlapping circles in a row took 4 s)
    filled = [np.asarray(p, dtype=float) for p in
              _filled_part(d, s, shape, cuts, feats).to_polygons()]
    inner = len(feats) + 1
    res.names.append(f"an inner edge of `{s.path}`")
    res.spans.append(s.span)
    outer_loops = [p for p in filled if _signed(p) > 0]
    # (a sliver of under MIN_AREA between the chords of one arc tessellated twice, the cut
    # region's and the finished outline's, is no opening: run z1's palette, a notch rounded
    # R6 at the rim, left 22 slivers of 0.001 mm^2 and a W0507 "0.46 mm wall" beside them)
    inner_loops = [p for p in filled if _signed(p) <= 0 and -_signed(p) >= MIN_AREA]
    # only the holes within reach of another feature are measured: a hole whose box, grown
    # by reach / 2, meets no other hole's box nor the box of any edge of the outline lies
    # farther than reach from all of them, so it is in no pair (a perforated sheet's 19,000
    # holes apart: their 855,000 vertices were paired against nothing)
    kept = _within_reach(boxes, near, outer_loops + inner_loops, reach)
    parts = [boundary(outer_loops, 0)]
    V, vf, A, B, sf = boundaries([[np.asarray(p, dtype=float) for p in regions[k].to_polygons()]
                                  for k in kept], 1)
    fid = np.asarray(kept, dtype=np.intp) + 1        # feature k + 1 of every kept hole k
    vf = sf = fid[vf - 1] if len(vf) else vf
    parts.append((V, vf, A, B, sf))
    parts.append(boundary(inner_loops, inner))
    V, vf, A, B, sf = (np.concatenate([p[k] for p in parts]) for k in range(5))
    # (sf runs 0, 1, ..., inner in order: each feature's segments are one slice of A, B)
    # (holes found overlapping above are skipped below: their pairs are not measured)
    v, sg, dist, foot = close_pairs(V, vf, A, B, sf, reach,
                                    skip=np.array(sorted(merged), dtype=np.int64) + 1
                                    if merged else None)
    if not len(v):
        return res
    fa, fb = vf[v], sf[sg]
    lo, hi = np.minimum(fa, fb), np.maximum(fa, fb)
    mid = (V[v] + foot) / 2
    key = lo * (inner + 1) + hi
    order = np.lexsort((dist, key))
    key, dist, mid, lo, hi = key[order], dist[order], mid[order], lo[order], hi[order]
    starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    ends = np.r_[starts[1:], len(key)]
    edges = _edges(loops if loops is not None else
                   [np.asarray(p, dtype=float) for p in shape.to_polygons()])
    in_material = _inside(mid[starts], edges)
    low, high = np.minimum.reduceat(mid, starts), np.maximum.reduceat(mid, starts)
    thin = []                    # the pairs (their index k) thinner than t in the material
    for k, (a0, a1) in enumerate(zip(starts, ends)):
        i, j, w = int(lo[a0]), int(hi[a0]), float(dist[a0])
        if i > 0 and j < inner and (i - 1, j - 1) in merged:
            continue
        if w <= TOUCH:
            if i == 0 and j < inner:
                res.notches.add(j)
            elif i > 0 and j < inner:
                merged.add((i - 1, j - 1))
                if not meant.opens_into(i - 1, j - 1):   # a joint's mouth in a notch: as drawn
                    res.merges.append((i, j, 0.0, None))
            continue
        if w < t and in_material[k]:
            thin.append(k)
    # located at the middle of a narrowest span (within 0.01 mm of the least width), the
    # one nearest to the close points' box centre: that centre alone can fall between two
    # stretches of one pair of features (two windows of one hole under the roof line: the
    # pillar between them, where nothing is thin); the centres' distances to the two
    # features' segments all at once (:func:`_seg_distances`; 5,000 webs of a row: 10,000
    # NumPy passes before)
    ks = np.asarray(thin, dtype=np.intp)
    first = starts[ks]
    centre = (low[ks] + high[ks]) / 2
    off = (_seg_distances(centre, lo[first], sf, A, B)
           + _seg_distances(centre, hi[first], sf, A, B) > dist[first] + 2 * TOUCH)
    for n, k in enumerate(thin):
        a0, a1 = starts[k], ends[k]
        i, j, w = int(lo[a0]), int(hi[a0]), float(dist[a0])
        (x0, y0), (x1, y1), c = low[k], high[k], centre[n]
        if off[n]:          # the centre is not in the wall: its nearest narrowest span's
            m = mid[a0:a1]                                              # middle is
            narrow = m[dist[a0:a1] <= w + TOUCH]
            c = narrow[int(np.argmin(np.hypot(*(narrow - c).T)))]
        res.webs.append((i, j, w, max(x1 - x0, y1 - y0), (float(c[0]), float(c[1]))))
    res.merges.sort(key=lambda m: (m[1], m[0]))      # in the order of the located hole
    res.webs.sort(key=lambda w: (w[1], w[0]))
    return res


def _filled_part(d: Drawing, s: Structure, shape, cuts, feats) -> mf.CrossSection:
    """Part ``s`` (its final ``shape``) with the regions its holes cut (``feats``: the cuts
    of ``cuts`` that cut some area) filled: its outline and the openings no hole cut.  When
    every cut is the part's own, each cut from one shape before the holes and the part that
    shape less its holes (no Fillet or Chamfer after them, no through-cut), the union is that
    shape itself (``before``, the booleans' own): the union of 19,000 regions with the part
    took 0.3 s; else the union (:func:`_united`)."""
    regions = [c.region for c in feats]
    before = feats[0].before if feats else None
    if (len(feats) == len(cuts) and before is not None and shape is d.shapes.get(s)
            and not getattr(s, "finish", None) and s.path not in (d.slit_shapes or {})
            and all(c.owner is s and c.before is before for c in cuts)):
        return before
    return _united(regions, plus=shape) if len(regions) > 64 else _union([shape] + regions)


def _within_reach(boxes: np.ndarray, pairs: np.ndarray, loops: list, reach: float) -> list:
    """The indices (ascending) of the holes (their regions' ``boxes``, n x 4) that may lie
    within ``reach`` (mm) of another feature: of a pair of ``pairs`` (:func:`.nearby.box_pairs`
    of the boxes grown by ``reach / 2``), or whose box grown by ``reach / 2`` meets the box of
    an edge of the outline's ``loops`` grown as much.  Any other lies farther than ``reach``
    from every other feature (the boxes apart by more than ``reach`` along x or y)."""
    near = np.zeros(len(boxes), dtype=bool)
    near[np.asarray(pairs, dtype=np.intp).ravel()] = True
    edges = [np.hstack([np.minimum(P, Q), np.maximum(P, Q)])
             for P in loops if len(P) for Q in (np.roll(P, -1, axis=0),)]
    if edges:
        hit = box_pairs_between(boxes, np.concatenate(edges), pad=reach / 2)
        near[hit[:, 0]] = True
    return np.flatnonzero(near).tolist()


def _seg_distances(P: np.ndarray, F: np.ndarray, sf: np.ndarray, A: np.ndarray,
                   B: np.ndarray, chunk: int = 1 << 20) -> np.ndarray:
    """For each point ``P[q]`` (mm) the least distance (mm) to the segments ``A[k]``-``B[k]``
    of feature ``F[q]`` (``sf``: each segment's feature, sorted), inf where it has none, in
    passes over at most ``chunk`` point-segment pairs."""
    out = np.full(len(P), np.inf)
    s0, s1 = np.searchsorted(sf, F), np.searchsorted(sf, F + 1)
    L = s1 - s0
    total = np.cumsum(L)
    q0 = 0
    while q0 < len(P):
        base = total[q0 - 1] if q0 else 0
        q1 = max(q0 + 1, int(np.searchsorted(total, base + chunk, "right")))
        n = L[q0:q1]
        at = np.cumsum(n) - n
        q = np.repeat(np.arange(q0, q1), n)
        seg = np.repeat(s0[q0:q1] - at, n) + np.arange(int(n.sum()))
        a, p = A[seg], P[q]
        d = B[seg] - a
        L2 = np.einsum("ij,ij->i", d, d)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.clip(np.where(L2 > 0, np.einsum("ij,ij->i", p - a, d) / L2, 0.0), 0.0, 1.0)
        e = a + t[:, None] * d - p
        some = n > 0
        if some.any():
            least = np.minimum.reduceat(np.einsum("ij,ij->i", e, e), at[some])
            out[q0:q1][some] = np.sqrt(least)
        q0 = q1
    return out


# the share of the smaller hole's area inside the other past which W0508 reads one opening as
# meant (a round hole centred on a window's edge, a common slip, is 0.5)
SHARE_MEANT = 0.55


def _share_inside(a, i: int, j: int, common: float | None):
    """``(fraction, name)`` when more than :data:`SHARE_MEANT` of the smaller of holes ``i``
    and ``j`` (by area) lies inside the other (a slit placed from a knob hole's centre to the
    edge: 61 %): the two are then drawn as one opening, and W0508's hint leads with
    `AllowOverlap`, the move second (moving them apart cuts the slit off its hole: 105e #01);
    None for a shallower overlap, or without the areas."""
    if common is None or len(a.areas) <= max(i, j):
        return None
    k = i if a.areas[i] <= a.areas[j] else j
    if a.areas[k] <= 0 or common <= SHARE_MEANT * a.areas[k]:
        return None
    return min(1.0, common / a.areas[k]), a.names[k]


def _inner(a: _Openings, i: int, j: int, common) -> int | None:
    """Which of holes ``i`` and ``j`` lies wholly inside the other (their common area is
    all of its area), if one does."""
    if common is None:
        return None
    for k in (j, i):
        if common >= (1 - 1e-6) * a.areas[k] - 1e-9:
            return k
    return None


def _report_openings(a: _Openings, s: Structure, t: float, sink: DiagnosticSink,
                     shapes: dict | None = None, d: Drawing | None = None,
                     shape=None) -> set:
    """W0508 for each two holes that cut one opening and W0507 for each web of ``a``; returns
    the name pairs reported (the opening test of :func:`_check_walls` skips them).
    ``shapes``: the booleans' shape of each structure (``Drawing.shapes``), which tells a
    solid drawn inside another hole's opening (:func:`_refiller`); ``d`` and ``shape`` (the
    part's final shape): for W0508's fix, a move that clears (:func:`_merge_fix`)."""
    covered = set()
    split: list = []                    # whether the part is in pieces, found once (_apart)

    def apart() -> bool:
        if not split:
            split.append(_apart(shape))
        return split[0]
    moves = 0                           # W0508 moves looked for (at most MAX_MOVES a part)
    near: dict = {}                     # what the moves share: the holes' boxes, made once
    for i, j, depth, common in a.merges:
        first, second = a.names[i], a.names[j]
        covered.add(frozenset((first, second)))
        if a.cuts and _holes_allowed(a.cuts[i - 1], a.cuts[j - 1]):
            continue                  # AllowOverlap(first, second): one opening, meant
        inner = _inner(a, i, j, common)
        if inner is not None and a.cuts:
            refill = _refiller(a.cuts[i + j - inner - 1], a.cuts[inner - 1], shapes)
            if refill is not None:
                if refill[0] is not None:
                    _report_refilled(a, inner, i + j - inner, common, refill, s, sink)
                continue
        if inner is not None:
            outer = a.names[i + j - inner]
            labels = [Label(a.spans[i + j - inner], f"{outer} is here", primary=False)] \
                if a.spans[i + j - inner] else []
            sink.warning("W0508", f"{a.names[inner]} lies wholly inside {outer} of `{s.path}`: "
                         f"the two cut one opening, and {a.names[inner]} cuts nothing of its "
                         f"own ({common:.2f} mm^2)", a.spans[inner], labels=labels,
                         hint=f"move {a.names[inner]} clear of {outer} (its size or position may "
                              "be in another unit or frame than meant), or delete one of the "
                              f"two: as drawn the opening is {outer}'s (a countersink or "
                              "counterbore is a second depth, which a through cut cannot make: "
                              "keep the screw's through hole and delete the wider one, or "
                              "engrave the wider outline in a `drawing`)")
            continue
        crossing = common is not None and a.cuts and _cross(a.cuts[i - 1].region,
                                                                a.cuts[j - 1].region)
        if common is None:
            how, far = "touch", f"{t:g} mm" if t > 0 else "a little"
        else:
            how = (f"cross ({common:.2f} mm^2 in common)" if crossing else
                   f"overlap by {depth:.2f} mm ({common:.2f} mm^2 in common)")
            far = f"{_enough(depth + t if t > 0 else depth)} mm"
        labels = [Label(a.spans[i], f"{first} is here", primary=False)] if a.spans[i] else []
        where, stmt = _allow_holes(a.cuts[i - 1].hole, a.cuts[j - 1].hole) if a.cuts \
            else (None, None)
        unnamed = bool(stmt) and stmt.endswith(", NAME)")   # a copy of an unnamed pattern
        meant = (f"name the pattern statement that copies it (`NAME = ` before it) and write "
                 f"`{stmt}` after it" if unnamed else
                 f"write `{stmt}` in {_body(where)}, or draw both shapes in one hole "
                 "structure (whose faces may overlap)" if stmt else
                 "name the pattern statement that copies them (`NAME = ` before it) and "
                 "write `AllowOverlap(NAME)` after it (the list holds the original and every "
                 "copy)" if stmt == "" else
                 "draw both shapes in one hole structure (the faces of one hole may overlap)")
        move, fix = f"move {second} {far} further from {first}", None
        own = _template_own(a, i, j)
        if crossing:
            # a note: every crossing of the corpus was meant (run ag's halved mortises, "move
            # it 3.67 mm" broke them; run at's pin channels across a tambourine's windows)
            sink.add(Diagnostic("W0508", f"{first} and {second} of `{s.path}` {how}: they cut "
                                "one cross-shaped opening", a.spans[j], "note", labels=labels,
                                hint=own + f"if it is meant, nothing is needed (to say so: "
                                     f"{meant}); if two openings are meant, {move}"))
            continue
        if stmt and not unnamed \
                and _copies_of_one(stmt, a.cuts[i - 1].hole, a.cuts[j - 1].hole) \
                and depth >= max(t, MIN_WALL) and not apart():
            fix = _insert_fix(where, stmt, sink)     # copies that overlap deeply: meant
        elif d is not None and shape is not None and a.cuts and moves < MAX_MOVES \
                and not _shared(d, s, a.cuts[j - 1].hole):
            moves += 1
            move, fix = _merge_fix(d, s, shape, a, i, j, t, sink, move, near)
        # most of one inside the other, both placed by relations (no call to edit): one
        # opening looks meant, and the hint leads with it (no machine fix either way)
        share = _share_inside(a, i, j, common) if fix is None else None
        if share is not None:
            smaller, other = share[1], (second if share[1] == first else first)
            hint = (f"one opening looks meant ({share[0]:.0%} of {smaller} lies inside "
                    f"{other}): {meant}; if two are meant, {move}, or shrink one of them so "
                    "that material is left between them")
        else:
            hint = (f"{move}; or shrink one of them so that material is left between them; "
                    f"if one opening is meant, {meant}")
        sink.warning("W0508", f"{first} and {second} of `{s.path}` {how}, so they cut one "
                     "opening, not two", a.spans[j], labels=labels, hint=own + hint, fix=fix)
    inner = len(a.names) - 1
    for i, j, w, length, (x, y) in a.webs:
        covered.add(frozenset((a.names[i], a.names[j])))
        if i == 0 or j == inner:          # a hole and an edge of the outline
            hole, edge = (j, i) if i == 0 else (i, j)
            pair, away, labels = f"{a.names[hole]} and {a.names[edge]}", \
                a.names[edge].split(" of ")[0], []
        else:                             # two holes, located at the later one
            hole, pair, away = j, f"{a.names[i]} and {a.names[j]}", a.names[i]
            labels = [Label(a.spans[i], "the other side of the wall", primary=False)] \
                if a.spans[i] else []
        wx, wy = written(s, x, y)
        sink.warning("W0507", f"a wall of `{s.path}` between {pair} is "
                     f"{below(w, t)} mm wide, thinner than {t:g} mm (over {length:.1f} mm, near "
                     f"({wx:.1f}, {wy:.1f}))", a.spans[hole], labels=labels,
                     hint=f"move {a.names[hole]} {_enough(t - w)} mm further from {away} (or shrink "
                          f"it) so that at least {t:g} mm of material is left (a laser or "
                          "router cannot hold a thinner wall); the minimum is set with "
                          "--min-wall")
    return covered


def _enough(v: float) -> str:
    """A distance to move by, ``v`` mm measured on the chords of curved outlines: rounded
    up to 0.01 mm after adding two chords' error (``2 * CHORD_TOL``, one per side), so that
    the move, made as written, clears the check (issue 84: "0.78 mm" for an overlap of
    0.29 mm at a 0.5 mm minimum left a 0.49 mm wall, W0507)."""
    from ....geometry.shapes.tessellate import CHORD_TOL
    return f"{math.ceil(round((v + 2 * CHORD_TOL) * 100, 6)) / 100:.2f}"


MAX_MOVES = 16         # W0508 fixes (moves) looked for in one part; later pairs: the hint


def _copies_of_one(stmt: str, hi: Structure, hj: Structure) -> bool:
    """Holes ``hi`` and ``hj`` are copies of one pattern: ``stmt`` allows them by its list
    (``AllowOverlap(vents)``), or one is the pattern's original and the other its first copy
    (``vent`` and ``vents[1]``)."""
    return "," not in stmt or hi.pattern_original is hj or hj.pattern_original is hi


# W0508's fix moves the smaller of two holes, or one at most this many times the other's
# area: issue 111's run dd moved a 201 x 201 mm window 10.5 mm off its engraved index to part
# it from a 20 mm thumb notch centred on its edge (the notch could not move)
LARGER_STAYS = 4.0


def _merge_fix(d: Drawing, s: Structure, shape, a: _Openings, i: int, j: int, t: float, sink,
               move: str, near: dict) -> tuple:
    """W0508's hint sentence and fix for holes ``i`` and ``j`` of ``a`` that are not copies
    of one pattern overlapping by design: a move of ``j`` (else ``i``) that leaves ``t`` mm
    (at least :data:`MIN_WALL`) of material to the other and to everything around it
    (:func:`.clearing.move_fix`), never of a hole more than :data:`LARGER_STAYS` times the
    other's area, or no fix at all, never an ``AllowOverlap`` that would hide the defect (``move``: the sentence when no move is found; ``near``: what the part's
    moves share, :func:`.clearing.move_fix`)."""
    wall = max(t, MIN_WALL)
    # a countersink's or counterbore's head needs the material under it too (run t's hay
    # feeder: the move left 0.5 mm beside the drill and W0528 said the head was over the slot)
    sinks = getattr(d, "sinks", None) or ()
    extra = sum(max([(sk.diameter - sk.hole_d) / 2 for sk in sinks
                     if sk.hole.startswith(a.cuts[k - 1].hole.path + ".")], default=0.0)
                for k in (i, j)) if sinks else 0.0
    for mover, other in ((j, i), (i, j)):
        if len(a.areas) > max(i, j) and a.areas[mover] > LARGER_STAYS * a.areas[other]:
            continue        # a window is not moved for a notch on its edge (run dd)
        got = move_fix(d, s, shape, a.cuts, mover - 1, other - 1, wall + extra, sink, near)
        if got is None:
            continue
        fix, (dx, dy), g, n, size = got
        what = f"`{g.label}`" if n == 1 else \
            f"the {n} copies of `{g.label.rsplit('[', 1)[0]}` (one statement)"
        smaller = f"; or make its radius {size} so that it clears" if size else ""
        return (f"move {a.names[mover]} {_enough(math.hypot(dx, dy) - 2 * CHORD_TOL)} mm "
                f"further from {a.names[other]}: by ({dx:.2f}, {dy:.2f}) mm, the shortest move "
                f"that leaves {wall + extra:g} mm of material between them"
                + (f" (the countersink's or counterbore's head {extra:g} mm of it)"
                   if extra else "")
                + f" and as much to the other holes and the outline (the suggested fix moves "
                f"{what} so){smaller}", fix)
    return move, None


def _holes_allowed(ci, cj) -> bool:
    """``AllowOverlap`` names the holes of cuts ``ci`` and ``cj`` together (or lists or
    structures holding them): the one opening they cut is meant (W0508)."""
    return _intended(ci.hole, ci.owner, cj.hole) or _intended(cj.hole, cj.owner, ci.hole)


# a reference the program can write: names, indices and members (`rings[0][1]`, `a.b[2]`); a
# copy made by a pattern with no name is `ring[0]_pattern[1]`, which no program can write
_NAMEABLE = re.compile(r"[A-Za-z_]\w*(\[\d+\])*(\.[A-Za-z_]\w*(\[\d+\])*)*\Z")


def _shared(d: Drawing, s: Structure, h: Structure) -> bool:
    """Whether the statement that draws hole ``h`` of part ``s`` draws others too (a loop's
    copy, a template's body called for several parts): a machine fix edits it for all of
    them (run bc's yarn bowl: moving one ring's guide moved the next ring's)."""
    if "[" in h.path[len(s.path):]:
        return True
    t = getattr(s, "template", None)
    return t is not None and sum(getattr(p, "template", None) == t
                                 for p in d.part_of.values()) > 1


def _allow_holes(hi: Structure, hj: Structure) -> tuple:
    """The ``AllowOverlap`` statement that says two merging holes ``hi`` and ``hj`` cut one
    opening as meant, and the structure to write it in (their nearest common ancestor):
    ``(structure, statement)``, ``(None, None)`` when either would be named ``self``, and
    ``(structure, "")`` when one is a copy made by a pattern with no name (the pattern's
    statement must be named first: ``NAME = CircularPattern(...)``), ``(structure,
    "AllowOverlap(bolt, NAME)")`` when the other has a name.  A copy of `first` by an
    unnamed pattern is `first_pattern[4]`, a name no program binds (issue 109, law 4: the
    hint said to write `AllowOverlap(bolt, first_pattern)`, E0101 once written): a reference
    is written only when its first name is one the structure's body binds."""
    common = hi.parent
    while common is not None and not hj.is_within(common):
        common = common.parent
    if common is None:
        return None, None
    refs = [_ref(hi, common), _ref(hj, common)]
    if "self" in refs:
        return None, None
    if not all(_NAMEABLE.match(r) for r in refs):
        return common, ""                        # a copy of a pattern with no name
    bound = [re.match(r"[A-Za-z_]\w*", r).group(0) in common.scope for r in refs]
    if not all(bound):                           # `first_pattern[4]`: no name binds it
        return common, (f"AllowOverlap({refs[bound.index(True)]}, NAME)" if any(bound)
                        else "")
    if refs[0] == refs[1]:                       # two copies of one pattern: the list
        return common, f"AllowOverlap({refs[0]})"
    return common, f"AllowOverlap({refs[0]}, {refs[1]})"


def _refiller(outer, inner, shapes: dict | None = None):
    """When hole cut ``inner`` lies wholly inside hole cut ``outer`` but cuts a solid that
    ``outer`` does not (its solid is not ``outer``'s solid or inside it: a moon inside a
    frame's window, bitten by its own hole), that solid refills ``outer`` there and ``inner``
    cuts it: ``(refiller, common)``, the structure below the two solids' common ancestor
    ``common`` that holds ``inner``'s solid; ``(None, None)`` when ``AllowOverlap(outer's
    hole, refiller)`` says the refill is intended, when the refiller is drawn inside the
    opening (at least :data:`DRAWN_IN` of its shape in ``shapes`` lies in ``outer``'s hole: a
    hub with its axle hole in a rim's opening, a moon bitten by its own hole in a window), or
    when ``inner`` is declared in that ancestor itself (a wheel's axle hole inside its rim's
    opening, which the wheel's own hub refills: a hole cuts every solid of its structure, the
    refill included, as meant); None
    when ``outer`` cuts ``inner``'s solid too (``inner`` then cuts nothing of its own)."""
    if inner.owner.is_within(outer.owner):
        return None
    common = outer.owner
    while common is not None and not inner.owner.is_within(common):
        common = common.parent
    if common is None:
        return None
    if inner.owner is common:
        return None, None
    refill = inner.owner
    while refill.parent is not common:
        refill = refill.parent
    if _intended(outer.hole, outer.owner, refill):
        return None, None
    if shapes is not None:
        shp, opening = shapes.get(refill), shapes.get(outer.hole)
        if opening is not None and _area(shp) > 0 \
                and _area(shp ^ opening) >= DRAWN_IN * _area(shp):
            return None, None
    return refill, common


def _report_refilled(a: _Openings, inner: int, outer: int, area: float, refill, s: Structure,
                     sink: DiagnosticSink) -> None:
    """W0508 for hole ``inner`` wholly inside hole ``outer`` where a solid refills ``outer``
    and ``inner`` cuts that solid (:func:`_refiller`): said as a refill, with the way to mark
    it intended (``AllowOverlap``, which also silences W0501 for the pair)."""
    solid, parent = refill
    hole = a.cuts[outer - 1].hole
    labels = [Label(a.spans[outer], f"{a.names[outer]} is here", primary=False)] \
        if a.spans[outer] else []
    if solid.span is not None:
        labels.append(Label(solid.span, "refills it", primary=False))
    sink.warning("W0508", f"{a.names[inner]} lies wholly inside {a.names[outer]} of "
                 f"`{s.path}`, which solid `{solid.path}` refills: {a.names[inner]} cuts "
                 f"{area:.2f} mm^2 of `{solid.path}` inside the opening, not the opening "
                 "itself", a.spans[inner], labels=labels,
                 hint=f"if `{solid.path}` is meant to fill {a.names[outer]} and "
                      f"{a.names[inner]} to cut it (keep both), write "
                      f"`AllowOverlap({_rel(hole, parent)}, {_rel(solid, parent)})` in "
                      f"`{parent.path}`; else move {a.names[inner]} clear of "
                      f"{a.names[outer]} or `{solid.path}` out of it")


def _check_hole(d: Drawing, cut, roots, sink: DiagnosticSink, local=None,
                owner_areas: dict | None = None, tick=lambda: None) -> str | None:
    """W0501-W0503 for one cut; ``local(part, region)``: the part's final shape near
    ``region`` (:class:`_Near`), else the whole final shape is intersected;
    ``owner_areas``: the owners' final areas by structure, filled as they are taken (a plate's
    area is O(its vertices): once per hole, it made 5,000 holes quadratic, issue 38);
    ``tick()``: before each boolean with a shape that may refill it (the deadline)."""
    h, s = cut.hole, cut.owner
    hole_shape = d.shapes.get(h)
    whole = _area(hole_shape)
    cut_area = _area(cut.region)
    before = _area(cut.before)
    if whole <= 0:
        return
    if cut_area <= max(1e-9, 1e-6 * whole):
        if _over_opening(d, hole_shape, whole, _part_of(s, roots), roots):
            return                       # it declares an opening the solids enclose (W0515)
        copy = getattr(h, "copy_origin", None) is not None
        hint = (f"`{h.name}` is a copy a pattern (or a mirror) made: move the pattern, its "
                f"original, step or count, so that every copy lies on `{s.path}` (a constraint "
                "on one copy would move it apart from the rest)" if copy else
                f"move the {h.kind} inside `{s.path}` (for example `CenterInside({h.name}, "
                "self)`), or declare it in the solid it should cut")
        sink.warning("W0502", f"{h.kind} `{h.path}` cuts nothing: it lies outside solid "
                     f"`{s.path}`", h.span, hint=hint)
        return
    _check_stray_shapes(d, cut, _part_of(s, roots), roots, sink)
    if owner_areas is None:
        owner_areas = {}
    if before > 0 and s not in owner_areas:
        owner_areas[s] = _area(d.shapes.get(s))
    if before > 0 and owner_areas[s] <= max(1e-9, 1e-6 * before):
        sink.warning("W0503", f"hole `{h.path}` removes all of solid `{s.path}`", h.span,
                     hint=f"make the hole smaller than `{s.path}` or move it so that material "
                          "is left around it")
        return "W0503"
    part = _part_of(s, roots)
    if part is None or s is part:
        return     # (a part's own hole: no structure between its owner and the part to refill
        #            it, W0501 has no one to name: 20,000 holes of a plate were 20,000
        #            intersections with the part's shape, 0.4 s, every one then dropped)
    final = local(part, cut.region) if local is not None else roots[part]
    refilled = _area(cut.region ^ final)
    if not _significant(refilled, cut_area):
        return
    # who refills it: the other contributors of each ancestor between the owner and the part,
    # grouped by the statement that made them (the copies of a loop are one refiller)
    groups: dict = {}                   # (statement span, kind) -> [obj, span, level, shapes]
    allowed: dict = {}
    node = s
    while node is not part and node.parent is not None:
        a = node.parent
        for name, span, shp, obj in _contributors(d, a, skip=node, objects=True):
            tick()
            if _significant(_area(cut.region ^ shp), cut_area):
                into = allowed if _intended(h, s, obj) else groups   # AllowOverlap(hole, this)
                key = (span, isinstance(obj, Structure)) if span is not None else id(obj)
                g = into.setdefault(key, [obj, span, a, [], []])
                g[3].append(shp)
                g[4].append(obj)
        if node.parent is part:
            break
        node = a
    # shapes drawn inside the opening (a hub and spokes in a rim's opening, a moon in a
    # window) are put there on purpose: only what covers the hole from outside it is reported
    drawn_in = {}
    for key, (obj, span, a, shapes, _) in list(groups.items()):
        shp = shapes[0] if len(shapes) == 1 else _union(shapes)
        if _area(shp ^ hole_shape) >= DRAWN_IN * _area(shp):
            drawn_in[key] = groups.pop(key)
    if not groups:
        return
    survives = max(0.0, cut_area - refilled)
    # the outermost structure holding a refiller: the common parent of the hole and all of them
    outer = max((g[2] for g in groups.values()), key=lambda x: -len(x.path.split(".")),
                default=part)
    hole_ref = _rel(h, outer)

    def said(gs):
        out = []
        for obj, span, _, shapes, _ in gs:
            share = _area(cut.region ^ (shapes[0] if len(shapes) == 1 else _union(shapes)))
            what = f"solid `{obj.path}`" if isinstance(obj, Structure) else f"`{obj.label}`"
            many = f"{len(shapes)} copies, " if len(shapes) > 1 else ""
            out.append(f"{what} ({many}{_pct(share, cut_area)} of the hole)")
        return out
    who = said(groups.values())
    who = ", ".join(who[:-1]) + " and " + who[-1] if len(who) > 1 else who[0]
    also = ""
    if allowed:
        also = "; AllowOverlap already allows " + ", ".join(said(allowed.values()))
    if drawn_in:
        also += "; drawn inside the opening, so meant: " + ", ".join(said(drawn_in.values()))
    refs, unnamed = [], False
    for *_, objs in groups.values():
        # every object of the group (a pattern's original and its copies are one statement's
        # group: `spoke` and the list `spokes` both, so that one call allows all of them)
        named = any(not isinstance(o, Structure) and o.name for o in objs)
        for o in objs:
            if named and not isinstance(o, Structure) and not o.name and o.owner is outer:
                unnamed = True          # a copy of a named shape by a pattern with no name
                continue
            r = _ref(o, outer)
            if r not in refs:
                refs.append(r)
    labels = [Label(span, "refills the hole", primary=False)
              for _, span, _, _, _ in groups.values() if span is not None]
    stmt = f"AllowOverlap({hole_ref}, {', '.join(refs + ['NAME'] * unnamed)})"
    how = (f"name the pattern statement that copies it (`NAME = ` before it) and add "
           f"`{stmt}` to `{outer.path}`" if unnamed else f"write `{stmt}` in `{outer.path}`")
    sink.warning(
        "W0501",
        f"hole `{h.path}` is refilled by {who}: only {_pct(survives, cut_area)} of it still "
        f"cuts through{also}",
        h.span, labels=labels,
        hint=(f"a hole cuts only the solid it is declared in (`{s.path}`); declare the hole in "
              f"`{outer.path}`, the common parent, so that it cuts everything united there, "
              f"or move it clear of the solids that cover it; if the overlap is intended, {how}"),
        fix=None if unnamed else _insert_fix(outer, stmt, sink))


def _ref(obj, base: Structure) -> str:
    """An expression, in structure ``base``'s body, for refiller ``obj`` (a structure or a
    shape below ``base``) that ``AllowOverlap`` takes: its name, or for a copy of a loop or a
    pattern (named ``NAME[k]``) the list ``NAME`` (all the copies); a shape without a name
    is named by its structure (``self`` when that is ``base``)."""
    if not isinstance(obj, Structure) and not obj.name:
        obj = obj.owner
    if obj is base:
        return "self"
    r = _rel(obj, base)
    head, sep, _ = r.rpartition("[")
    return head if sep and r.endswith("]") and "[" not in head else r


def _check_stray_shapes(d: Drawing, cut, part, roots, sink: DiagnosticSink) -> None:
    """W0502 for a shape of a hole that cuts something while this shape lies wholly off its
    solid: its box misses the solid's box (``cut.before``, mm), so it removes nothing (a
    mounting hole written at y = 70 on a plate 60 mm high vanished silently, issue 84). A
    shape over an opening the part's solids enclose declares it (W0515) and is left alone.
    Once per statement (the copies of a loop: how many)."""
    if cut.before is None or cut.before.is_empty():
        return
    h, s = cut.hole, cut.owner
    x0, y0, x1, y1 = cut.before.bounds()
    stray: dict = {}
    for g, f in d.own.get(h, ()):
        if f is None or f.is_empty():
            continue
        a, b, c, e = f.bounds()
        if a < x1 - 1e-6 and c > x0 + 1e-6 and b < y1 - 1e-6 and e > y0 + 1e-6:
            continue
        if g.data.get("overrun") and a <= x1 + OVERRUN_NEAR and c >= x0 - OVERRUN_NEAR \
                and b <= y1 + OVERRUN_NEAR and e >= y0 - OVERRUN_NEAR:
            continue            # past the edge on purpose, at it (run ak's squeegee hanger)
        if _over_opening(d, f, _area(f), part, roots):
            continue
        stray.setdefault(g.span, []).append(g)
    tpl = h.template
    turn = ""
    if tpl and isinstance(h.scope, dict) and "rotation" in h.scope:
        # the rotation that runs it the other way, from the one given (run ha: a side tenon
        # at `rotation=270 deg`, the hint's fixed "rotation=180 deg" still cut nothing)
        rot = getattr(h.scope["rotation"], "const", lambda: None)()
        other = (f"`rotation={(math.degrees(rot) + 180) % 360:g} deg` (it has "
                 f"{math.degrees(rot) % 360:g} deg)" if isinstance(rot, float)
                 and math.isfinite(rot) else "a rotation 180 deg from its own")
        turn = (f"; or turn it: `{tpl}(...)` runs from its anchor (cx, cy) the way its "
                f"`rotation=` says (`aidl docs {tpl}`), and {other} runs it the other way")
    for span, gs in stray.items():      # (run ab's extractor: a cross_halving's mouth on the
        #                                 bottom edge, at rotation 0 running down off the plate)
        what = f"`{gs[0].label}`" + (f" ({len(gs)} copies)" if len(gs) > 1 else "")
        if tpl:                         # a joint whose tabs or slots are not there: the fit
            stray_joints(d).append((part.path, h.path, what))     # check says it (run dk)
        sink.warning("W0502", f"{what} of {h.kind} `{h.path}` cuts nothing: it lies outside "
                     f"solid `{s.path}` (from ({x0:.2f}, {y0:.2f}) to ({x1:.2f}, {y1:.2f}))",
                     span, hint=f"move it onto `{s.path}`: check its coordinates against the "
                                f"solid's extent (a sign or a unit off?){turn}")


OVERRUN_NEAR = 0.5      # mm: an `overrun=true` shape this near its solid's box is at its edge


def stray_joints(d: Drawing) -> list:
    """``[(part path, hole path, what)]``: the template holes (a joint's) of which W0502 said
    a shape cuts nothing, kept on the drawing for W0517's hint (its tabs are not there)."""
    if "stray_joints" not in d.__dict__:
        d.stray_joints = []
    return d.stray_joints


def _over_opening(d: Drawing, hole_shape, whole: float, part, roots) -> bool:
    """Whether a hole that cuts nothing (``hole_shape``, of area ``whole`` mm^2) lies inside
    an opening of ``part`` that its solids enclose (within the part's outer loops, meeting no
    other hole's cut): it declares that opening, as W0515's hint proposes, and is not
    "outside" the solid."""
    if part is None or part not in roots:
        return False
    x0, y0, x1, y1 = hole_shape.bounds()
    for c in d.cuts:
        r = c.region
        if r is None or r.is_empty() or _part_of(c.owner, roots) is not part:
            continue
        a, b, cc, e = r.bounds()
        if a <= x1 and cc >= x0 and b <= y1 and e >= y0 and _area(r ^ hole_shape) > 1e-9:
            return False                 # in an opening another hole cuts
    outer = [p for p in roots[part].to_polygons() if _signed(np.asarray(p, dtype=float)) > 0]
    if not outer:
        return False
    filled = mf.CrossSection(outer, mf.FillRule.Positive)
    return _area(hole_shape - filled) <= max(1e-9, 1e-6 * whole)


def _rel(obj, base: Structure) -> str:
    """How structure ``base``'s body names ``obj`` (a structure or a named shape below it)."""
    if isinstance(obj, Structure):
        path, own = obj.path, None
    else:
        path, own = obj.owner.path, obj.name or obj.kind
    rel = path[len(base.path) + 1:] if path.startswith(base.path + ".") else \
        ("" if path == base.path else path)
    return ".".join(p for p in (rel, own) if p)
