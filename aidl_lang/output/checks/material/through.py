"""Checks of through-cuts (a ``cut`` structure's open curves, :class:`~..part.booleans.Through`):

* ``W0522`` a through-cut that cuts nothing: no stretch of it lies on the material of its
  part (it is drawn off the part, or in a hole), or it has no length, or it lies along the
  part's outline (or a hole's) from end to end: the outline is cut anyway, so it adds nothing
  (the outputs leave it out: that line is cut once); or a segment of one does, while the rest
  cuts (:func:`_along_outline`: a Polyline's side, a Bezier's span); or it runs along another
  through-cut of its part (:func:`_overlapping`: overlapping collinear slits, copies);
* ``W0507`` a web thinner than the minimum wall that the through-cuts leave: the morphological
  opening (:func:`.walls._thin`) of the part with every through-cut's band taken out
  (:attr:`~..part.booleans.Drawing.slit_shapes`) removes more than the opening of the part itself;
  each extra piece of at least ``2 t^2`` mm^2 (the wall check's least) is one warning naming
  the cuts beside it.  The bands are 5e-7 mm wide, so a web's width is measured as between
  the cut lines themselves;
* ``W0507`` a bridge narrower than the minimum wall at a through-cut's free end
  (:func:`_end_bridges`): the material between the end of a slit and another cut, a hole or
  the outline that it stops short of.  A bridge has no length, so the opening above removes
  next to nothing there (two slits ending 0.05 mm apart held two halves of a plate by a 50 um
  bridge, and the check said nothing): it is measured directly, as the distance from the end
  to the nearest other boundary, exact on lines and circles;
* ``W0525`` a sheet-level cut (a ``cut`` directly in an assembly) that runs across a part's
  material (:func:`check_sheet_cuts`): the laser cuts that part there, but the part (its
  outline, area, 3D view, fit check) does not hold the cut.
"""
from __future__ import annotations

import manifold3d as mf
import numpy as np

from ....base.diagnostics import DiagnosticSink
from ....geometry.shapes.curves import Line, Loop, carrier, distance_to
from ....geometry.shapes.tessellate import CHORD_TOL
from ...part.build.booleans import SLIT_HALF, Drawing, _quad
from ...part.measure.nearby import close_pairs, meeting
from ...part.edges.shared import TWO_PI, _span
from ..common import _inside, _signed, below, written
from .walls import _thin


def _three(w: float, t: float) -> str:
    """A bridge's width ``w`` (mm) to three significant figures ("0.05", "0.123"), or more
    decimals where those would not read under the minimum ``t`` (:func:`..common.below`)."""
    text = f"{w:.3g}"
    return text if float(text) < t else below(w, t, 3)


OFF = 1e-3      # of the band's own area: a through-cut with less of it inside cuts nothing
# mm of a sheet-level cut's length on a part that W0525 lets pass: a cut that ends on a part's
# curved edge (a notch's outer rest) runs up to CHORD_TOL over the edge's chords at each end
ENDS = 4 * CHORD_TOL
# mm: an end this close to another cut or an edge reaches it (the bands meet: the analysis
# separates there), so it leaves no bridge
TOUCH = 2 * SLIT_HALF


def check_through(d: Drawing, roots: dict, sink: DiagnosticSink, min_wall_of,
                  tick=lambda ahead=0.0: None) -> None:
    """W0522 and W0507 (the module docstring) for the through-cuts of ``d``; ``roots``: part
    structure -> its final shape (:func:`.common._part_roots`); ``min_wall_of(s)``: the
    minimum wall of part ``s`` in mm (0: not checked)."""
    for th in getattr(d, "through", ()):
        tick()
        band = th.band.area()
        g = th.geometry
        if g.data.get("overrun") and band > 0:
            continue        # a cut's run past the edge, drawn off the material on purpose
            #                 (run cr's wiggle snake: W0522 "cuts nothing" for its overruns)
        if band <= 0:
            sink.warning("W0522", f"through-cut `{g.label}` has no length: it cuts nothing",
                         g.span or th.part.span,
                         hint="give it two different ends, or delete it")
        elif th.inside <= OFF * band:
            sink.warning("W0522", f"through-cut `{g.label}` cuts nothing: it lies off the "
                         f"material of `{th.part.path}`", g.span or th.part.span,
                         hint=f"move it onto `{th.part.path}` (a cut that frees a piece runs "
                              "from edge to edge; a slit ends inside the material), or delete "
                              "it; a line to engrave belongs in a `drawing`")
        elif getattr(th, "on_outline", False):
            sink.warning("W0522", f"through-cut `{g.label}` adds nothing: it lies along the "
                         f"outline of `{th.part.path}`, which is cut anyway (the outputs cut "
                         "it once)", g.span or th.part.span,
                         hint="delete it; to cut the part along a new line, draw the line "
                              "across the material")
        else:
            _along_outline(th, sink)
    _overlapping(d, sink, tick)
    for name, (whole, slit) in (getattr(d, "slit_shapes", None) or {}).items():
        s = d.part_of.get(name)
        if s is None or s not in roots:
            continue
        t = min_wall_of(s)
        if t <= 0 or slit.is_empty():
            continue
        tick()
        cuts = [th for th in d.through if th.part is s]
        seen: list = []         # the webs reported below: a bridge in one is not told again
        _webs(s, whole, slit, cuts, t, sink, seen, tick)
        _end_bridges(d, s, whole, cuts, t, sink, seen, tick)


def _along_outline(th, sink: DiagnosticSink) -> None:
    """W0522 for each run of segments of through-cut ``th`` that lies along its part's
    outline (:attr:`~..part.result.Through.along`) while the rest of the curve cuts: the
    outline cuts that stretch anyway, and the outputs cut it once (a Polyline's first side
    drawn on the plate's edge was cut there twice a pass, with no word)."""
    along = getattr(th, "along", ())
    if not along:
        return
    g, segs = th.geometry, getattr(th, "units", None) or th.segments
    runs: list = []
    for k in along:
        if runs and runs[-1][1] == k - 1:
            runs[-1][1] = k
        else:
            runs.append([k, k])
    for a, b in runs:
        p, q = segs[a].start, segs[b].end
        where = (f"segment {a + 1}" if a == b else f"segments {a + 1} to {b + 1}") + \
            f" of {len(segs)}, from {_xy(p)} to {_xy(q)}"
        if a == 0:
            fix = f"start the curve at {_xy(q)}"
        elif b == len(segs) - 1:
            fix = f"end the curve at {_xy(p)}"
        else:
            fix = f"draw it as two curves, one ending at {_xy(p)} and one from {_xy(q)}"
        sink.warning("W0522", f"through-cut `{g.label}` adds nothing along {where}: that "
                     f"stretch lies along the outline of `{th.part.path}`, which is cut "
                     "anyway (the outputs cut it once)", g.span or th.part.span,
                     hint=f"{fix}; the rest of `{g.label}` cuts as drawn")


def _xy(p) -> str:
    return f"({float(p[0]):.4g}, {float(p[1]):.4g})"


def _overlapping(d: Drawing, sink: DiagnosticSink, tick) -> None:
    """W0522 for two through-cuts of one part that run along each other (collinear slits
    that overlap, one arc over another of the same circle): the stretch both cover is cut
    once by the outputs (:func:`~..part.part._cut_once`), so the later cut adds
    nothing there.  Shared as between the pieces of a cut part (:func:`~..part.shared._span`:
    one carrier, parameter ranges overlapping by more than
    :data:`~..part.shared.SHARED_TOL` mm): each carrier's ranges sorted, O(n log n); one
    warning per pair of cuts, naming both."""
    ranges: dict = {}           # (part, carrier) -> [(lo, hi, cut index, segment, tol)]
    cuts = [th for th in getattr(d, "through", ())
            if not getattr(th, "on_outline", False) and th.inside > OFF * th.band.area() > 0]
    for i, th in enumerate(cuts):
        for k, seg in enumerate(getattr(th, "units", None) or th.segments):
            if k in getattr(th, "along", ()):
                continue
            key, lo, hi, _, tol, wrap = _span(seg)
            if key is None or hi - lo <= tol:
                continue
            for turn in ((0.0, TWO_PI) if wrap else (0.0,)):
                ranges.setdefault((th.part, key), []).append((lo + turn, hi + turn, i, k, tol))
    told = set()
    for (_, key), rs in ranges.items():
        if len(rs) < 2:
            continue
        tick()
        rs.sort()
        reach, owner = -np.inf, None         # the farthest end so far, and whose it is
        for lo, hi, i, k, tol in rs:
            if owner is not None and owner != (i, k) and reach - lo > tol:
                pair = (min(owner[0], i), max(owner[0], i))
                if pair not in told:
                    told.add(pair)
                    _tell_overlap(cuts[pair[0]], cuts[pair[1]], key, min(reach, hi) - lo,
                                  sink)
            if hi > reach:
                reach, owner = hi, (i, k)


def _tell_overlap(first, second, key: tuple, length: float, sink: DiagnosticSink) -> None:
    """W0522 for through-cut ``second`` running along ``first`` (the same one: back along
    itself) on carrier ``key`` (:func:`~..part.shared._span`) for ``length`` of its
    parameter."""
    a, b = first.geometry, second.geometry
    mm = length if key[0] == "L" else length * key[3] if key[0] == "C" else None
    how = f" for {mm:.4g} mm" if mm is not None else ""
    other = "back along itself" if first is second else f"along through-cut `{a.label}`"
    sink.warning("W0522", f"through-cut `{b.label}` runs {other}{how}: the outputs cut that "
                 f"stretch of `{second.part.path}` once, so `{b.label}` adds nothing there",
                 b.span or a.span or second.part.span,
                 hint="end one cut where the other begins, or draw the two as one curve; "
                      "copies of one cut at one place: draw it once")


def check_sheet_cuts(d: Drawing, roots: dict, sink: DiagnosticSink,
                     tick=lambda ahead=0.0: None) -> None:
    """W0525 (the module docstring) for each curve of a sheet-level cut of ``d``
    (:attr:`~..part.result.Drawing.sheet_cuts`) whose band (:data:`SLIT_HALF` either side)
    has more than :data:`OFF` of its area on a part's final shape (``roots``: part structure
    -> shape), and more than :data:`ENDS` mm of its length (the tessellated curved edge it
    ends on); a curve only touching a part's outline, or lying in its holes, is off it.
    Each curve is measured only against the parts whose bounding boxes meet its own."""
    items = getattr(d, "sheet_cuts", ())
    parts = [(s, shp) for s, shp in roots.items() if not shp.is_empty()]
    if not items or not parts:
        return
    bands = []
    for _, _, polys in items:
        tick()
        quads = [_quad(P[i], P[i + 1], SLIT_HALF) for P in polys for i in range(len(P) - 1)]
        bands.append(mf.CrossSection.batch_boolean(quads, mf.OpType.Add) if quads
                     else mf.CrossSection())
    for (g, c, _), band, near in zip(items, bands, meeting(bands, [shp for _, shp in parts])):
        whole = band.area()
        for i in near:
            tick()
            s, shp = parts[i]
            if (band ^ shp).area() > max(OFF * whole, ENDS * 2 * SLIT_HALF) and whole > 0:
                sink.warning("W0525", f"sheet-level cut `{g.label}` runs across the material of "
                             f"part `{s.path}`: the laser cuts `{s.path}` there, but the part "
                             "does not hold the cut (its outline, area and 3D view are without "
                             "it)", g.span or c.span,
                             hint=f"to cut `{s.path}`, move the curve into a `cut` inside "
                                  f"solid `{s.path}`; a sheet-level cut (a `cut` in an assembly) "
                                  "belongs beside the parts, off their material")
                break


def _webs(s, whole, slit, cuts: list, t: float, sink: DiagnosticSink, seen: list,
          tick) -> None:
    """W0507 for the webs thinner than ``t`` mm that the through-cuts ``cuts`` leave in part
    ``s`` (the module docstring); each web's neighbourhood (``t`` around it) to ``seen``."""
    least = 2 * t * t
    with_cuts = _union(_thin(slit, t, tick=tick, least=least))
    if with_cuts.is_empty():
        return
    # what the opening removes anyway (corners, the part's own thin walls: W0507 already)
    before = _union(_thin(whole, t, tick=tick))
    extra = with_cuts - before
    for piece in extra.decompose():
        if piece.area() < least * (1 - 1e-9):
            continue
        tick()
        near = piece.offset(t, mf.JoinType.Round, 2.0, 16)
        seen.append(near)
        by = [th.geometry for th in cuts if (near ^ th.band).area() > 0]
        names = " and ".join(f"`{g.label}`" for g in by[:2]) + (
            f" (and {len(by) - 2} more)" if len(by) > 2 else "")
        x0, y0, x1, y1 = piece.bounds()
        span = by[0].span if by and by[0].span is not None else s.span
        where = f"beside through-cut{'s' if len(by) > 1 else ''} {names} " if by else ""
        wx, wy = written(s, (x0 + x1) / 2, (y0 + y1) / 2)
        sink.warning(
            "W0507", f"a web of `{s.path}` {where}near ({wx:.2f}, "
            f"{wy:.2f}) is thinner than {t:g} mm: the laser leaves a strip "
            f"too weak to hold (or burns it away)", span,
            hint=f"space the cuts at least {t:g} mm apart and from the outline; if the "
                 f"design means this, say so: `min_wall 0` in `{s.path}` or a smaller "
                 "`min_wall`")


def _cut_chords(cuts: list):
    """The chords of the through-cuts ``cuts`` (each :class:`~..part.booleans.Through`):
    ``(A, B, feature, carriers, kind)`` with A, B (n x 2, mm), each chord's cut index, and
    the carrier (:func:`~aidl_lang.geometry.shapes.curves.carrier`) of the exact segment it
    follows; and each cut's two ends (m x 2 x 2)."""
    A, B, F, C = [], [], [], []
    ends = np.zeros((len(cuts), 2, 2))
    for i, th in enumerate(cuts):
        segs = th.segments
        ends[i] = (segs[0].start, segs[-1].end)
        for seg in segs:
            P = (np.asarray([seg.start, seg.end], dtype=float) if isinstance(seg, Line) else
                 np.vstack([np.asarray(Loop([seg]).points(), dtype=float).reshape(-1, 2),
                            [seg.end]]))
            A.append(P[:-1])
            B.append(P[1:])
            F.append(np.full(len(P) - 1, i))
            C += [carrier(seg)] * (len(P) - 1)
    return A, B, F, C, ends


def _end_bridges(d: Drawing, s, whole, cuts: list, t: float, sink: DiagnosticSink,
                 seen: list, tick) -> None:
    """W0507 for each bridge narrower than ``t`` mm at a free end of the through-cuts
    ``cuts`` of part ``s`` (``whole``: its shape before them).

    A free end lies inside the material and reaches nothing (no cut, hole or outline within
    :data:`TOUCH`: an end on another cut is a joint of a longer cut, an end on an edge cuts
    through it).  Its bridge is the distance to the nearest boundary that is not its own and
    lies ahead of the end or beside it: another cut not joined to it (cuts that touch form
    one chain, whose own bends are no bridges) or a loop of ``whole`` (the outline or an
    opening); behind the end lies the cut's own side (a cut that crosses another and
    overshoots it by 0.1 mm leaves a corner there, no bridge).  Distances are taken on the
    chords of every curve (within :data:`~aidl_lang.geometry.shapes.tessellate.CHORD_TOL`), then
    exactly where the nearest point lies inside a chord of a circle; so a bridge exactly
    ``t`` wide, on lines or arcs, passes.  A bridge inside a web already reported (``seen``)
    is not told again, nor the same bridge from its other end."""
    cuts = [th for th in cuts if th.inside > OFF * th.band.area() > 0]   # else W0522
    if not cuts:
        return
    tick()
    A, B, F, C, ends = _cut_chords(cuts)
    m = len(cuts)
    # each end's direction out of its cut (its last chord's, continued)
    ca, cb, cf = np.concatenate(A), np.concatenate(B), np.concatenate(F)
    first = np.searchsorted(cf, np.arange(m))
    last = np.r_[first[1:], len(cf)] - 1
    out = np.stack([ca[first] - cb[first], cb[last] - ca[last]], axis=1).reshape(-1, 2)
    loops = [np.asarray(p, dtype=float) for p in whole.to_polygons()]
    for k, P in enumerate(loops):
        A.append(P)
        B.append(np.roll(P, -1, axis=0))
        F.append(np.full(len(P), m + k))
    A, B, F = np.concatenate(A), np.concatenate(B), np.concatenate(F)
    V = ends.reshape(-1, 2)
    vf = np.repeat(np.arange(m), 2)
    v, sg, dist, ft = close_pairs(V, vf, A, B, F, t + CHORD_TOL)
    tick()
    # exact where the nearest point lies inside a chord of a circle (a chord's ends lie on
    # its curve): the carriers of the cuts' chords are known, the loops' are matched
    lc = np.full(len(A), -1, dtype=np.int64)
    on_loop = np.flatnonzero(F[sg] >= m)
    if len(on_loop) and d.exact is not None:
        k = np.unique(sg[on_loop])
        lc[k] = d.exact._chords().match(A[k], B[k], 1e-6)
    L2 = np.einsum("ij,ij->i", B[sg] - A[sg], B[sg] - A[sg])
    u = np.einsum("ij,ij->i", ft - A[sg], B[sg] - A[sg]) / np.where(L2 > 0, L2, 1.0)
    exact = dist.copy()
    for q in np.flatnonzero((u > 1e-9) & (u < 1 - 1e-9)):
        c = (C[sg[q]] if F[sg[q]] < m else
             d.exact.carriers[lc[sg[q]]] if lc[sg[q]] >= 0 else None)
        if c is not None and c[0] == "C":
            exact[q] = distance_to(c, tuple(V[v[q]]))
    # the chains: cuts whose ends touch another cut are one
    root = list(range(m))

    def find(i):
        while root[i] != i:
            root[i] = root[root[i]]
            i = root[i]
        return i
    touch = exact <= TOUCH
    for q in np.flatnonzero(touch & (F[sg] < m)):
        root[find(int(vf[v[q]]))] = find(int(F[sg[q]]))
    free = np.ones(len(V), dtype=bool)
    free[v[touch]] = False
    free &= _inside(V, loops)
    # a bridge lies ahead of the end or beside it; what lies behind it (the cut it crossed
    # and overshot, the corner between them) is the cut's own side, not a bridge
    toward = ft - V[v]
    ahead = np.einsum("ij,ij->i", toward, out[v]) >= -1e-3 * (
        np.hypot(*toward.T) * np.hypot(*out[v].T))
    best: dict = {}             # free end -> (width, chord, foot)
    for q in np.flatnonzero(free[v] & ~touch & ahead & (exact < t - 1e-9 * max(1.0, t))):
        f = int(F[sg[q]])
        if f < m and find(f) == find(int(vf[v[q]])):
            continue
        e = int(v[q])
        if e not in best or exact[q] < best[e][0]:
            best[e] = (float(exact[q]), int(sg[q]), ft[q])
    if not best:
        return
    order = sorted(best)
    mids = np.array([(V[e] + best[e][2]) / 2 for e in order])
    near = [np.asarray(p, dtype=float) for n in seen for p in n.to_polygons()]
    in_web = _inside(mids, near) if near else np.zeros(len(order), dtype=bool)
    told: dict = {}             # (cut, other cut) -> the middles of their bridges told
    for e, mid, web in zip(order, mids, in_web):
        w, chord, at = best[e]
        i, f = e // 2, int(F[chord])
        if web:
            continue
        if f < m:
            pair = (min(i, f), max(i, f))
            if any(np.hypot(*(mid - m2)) <= t for m2 in told.get(pair, ())):
                continue        # the same bridge seen from the other cut's end
            told.setdefault(pair, []).append(mid)
        tick()
        g = cuts[i].geometry
        if f < m:
            other = f"through-cut `{cuts[f].geometry.label}`"
        elif _signed(loops[f - m]) > 0:
            other = f"the outer edge of `{s.path}`"
        else:
            other = _opening_name(d, s, at)
        x, y = V[e]
        sink.warning(
            "W0507", f"a bridge of `{s.path}` between the end of through-cut `{g.label}` at "
            f"({x:.2f}, {y:.2f}) and {other} is {_three(w, t)} mm wide, thinner than {t:g} mm: the "
            "laser burns it through or leaves a strip too weak to hold", g.span or s.span,
            hint=f"end `{g.label}` at least {t:g} mm from {other}, or run it on to meet it if "
                 f"the cut is meant to go through; if the design means this bridge, say so: "
                 f"a smaller `min_wall` in `{s.path}` (or `min_wall 0`)")


def _opening_name(d: Drawing, s, at) -> str:
    """The hole of part ``s`` whose opening's edge passes through ``at`` (mm), by name, or
    the words for an opening of ``s``."""
    x, y = float(at[0]), float(at[1])
    for c in d.cuts:
        if c.owner is not s and getattr(c.owner, "parent", None) is not s:
            continue
        x0, y0, x1, y1 = c.region.bounds()
        if x0 - 1e-6 <= x <= x1 + 1e-6 and y0 - 1e-6 <= y <= y1 + 1e-6:
            return f"hole `{c.hole.path}`"
    return f"the edge of an opening of `{s.path}`"


def _union(parts: list):
    parts = [p for p in parts if not p.is_empty()]
    if not parts:
        return mf.CrossSection()
    return mf.CrossSection.batch_boolean(parts, mf.OpType.Add)


__all__ = ["check_through", "SLIT_HALF"]
