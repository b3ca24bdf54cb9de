"""Engraving (the strokes of ``drawing`` structures) against the material it is drawn on:

* ``W0505`` engraving outside the material or across a hole (the part grown by
  :data:`ENGRAVE_TOL`);
* ``W0516`` an engraved mark that runs along the cut edge (the laser engraves over the cut,
  so it is not seen), or that comes within :data:`CUT_CLEAR` of it (ends on it, or a hair
  short of it: the engraving meets the cut).

The sample points of engraving items and the distance tests are :mod:`.sampling`'s."""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ....base.diagnostics import Diagnostic, DiagnosticSink
from ....geometry.shapes.tessellate import CHORD_TOL
from ...part.build.booleans import Drawing
from ..common import _edges, _inside, _part_of, _pct, _signed, freed_share, written
from .allowed import meant_off
from .arcs import arc_on_material
from .segments import _crosses, _edge_arrays, _exact_circle_gaps, _pair_gap
from .sampling import (ENGRAVE_TOL, _sample, _n_samples, _samples, _all_on_material, _within, _share_on, _lengths)


def _cuts_crossed(d: Drawing, roots, part, off: np.ndarray) -> list:
    """The cuts of ``part`` whose region's box (grown by 2 :data:`ENGRAVE_TOL`) holds one of
    the points ``off`` (Nx2, mm) of an engraving over an opening, each with that box, in the
    order of the program."""
    out = []
    t = 2 * ENGRAVE_TOL
    for c in d.cuts:
        if c.region is None or c.region.is_empty() or _part_of(c.owner, roots) is not part:
            continue
        x0, y0, x1, y1 = c.region.bounds()
        if ((off[:, 0] >= x0 - t) & (off[:, 0] <= x1 + t)
                & (off[:, 1] >= y0 - t) & (off[:, 1] <= y1 + t)).any():
            out.append((c, (x0 - t, y0 - t, x1 + t, y1 + t)))
    return out


def _holes_crossed(d: Drawing, roots, part, off: np.ndarray) -> list[str]:
    """The holes of :func:`_cuts_crossed`, named `path`."""
    return [f"`{c.hole.path}`" for c, _ in _cuts_crossed(d, roots, part, off)]


# a centre line's share over the holes it crosses at most (more: a mark mostly lost)
CENTRE_LINE_OFF = 1 / 3


def _off_share(items, grown_loops) -> float:
    """The share of the length of ``items`` off the material (``grown_loops``)."""
    gl = _edges(grown_loops)
    lost, whole = _lengths(items, lambda P: ~_inside(P, gl))
    return lost / whole if whole > 0 else 1.0


def _centre_line(d: Drawing, roots, part, items, off: np.ndarray) -> bool:
    """The engraving ``items`` is one straight line running through the middle of every hole
    of ``part`` it crosses (``off``: its points off the material; each hole's cut region's
    box centred on the line within :data:`ENGRAVE_TOL`, both of its ends outside that box):
    a centre line, drawn so on purpose."""
    if len(items) != 1 or items[0][0] != "line":
        return False
    a, b = np.asarray(items[0][1], float), np.asarray(items[0][2], float)
    u = b - a
    n = float(np.hypot(*u))
    if n == 0.0:
        return False
    crossed = _cuts_crossed(d, roots, part, off)
    for _, (x0, y0, x1, y1) in crossed:
        m = np.array([(x0 + x1) / 2, (y0 + y1) / 2]) - a
        if abs(float(u[0] * m[1] - u[1] * m[0])) / n > ENGRAVE_TOL:
            return False
        if any(x0 <= e[0] <= x1 and y0 <= e[1] <= y1 for e in (a, b)):
            return False        # it ends in the hole, not through it (run cc's veins into a
            #                     lamp's well: lost there)
    return bool(crossed)


def _check_engraving(d: Drawing, roots, sink: DiagnosticSink, loops: dict | None = None,
                     tick=None) -> list:
    """W0505 for each engraved geometry with sample points off its part's material (the part
    grown by :data:`ENGRAVE_TOL`); W0516 (:func:`_check_on_cut`, :func:`_check_meets_cut`).
    Returns ``[(part, [(text, its stroke items)])]``: the texts neither warned, for
    :func:`.clearance.check_text_near_cut`.
    ``tick(part)``: called before each part's work (the compile's deadline, which raises
    :class:`~aidl_lang.base.limits.OutOfBudget`).  The points of all the geometries of one part are tested
    in one :func:`_inside` call (a point's verdict does not depend on the other points), and
    a part whose points are all certainly on it (:func:`_all_on_material`) is not grown."""
    by_geom: dict = {}
    for style, item, g in d.strokes:
        if style in ("drawing", "fill") and g is not None:
            by_geom.setdefault(g, []).append(item)
    by_part: dict = {}
    for g, items in by_geom.items():
        part = _part_of(g.owner, roots)
        if part is None or part.kind != "solid" or roots[part].is_empty():
            continue
        by_part.setdefault(part, []).append((g, items))
    verdicts: dict = {}
    warned: set = set()             # the geometries a W0505 or W0516 already reports
    for part, geoms in by_part.items():
        if tick is not None:
            tick(part)
        shp = roots[part]
        pts = _samples([it for _, items in geoms for it in items])
        warned |= _check_on_cut(part, shp, geoms, pts, (loops or {}).get(part), sink)
        if _all_on_material(shp, pts, (loops or {}).get(part)):
            continue
        grown = shp.offset(ENGRAVE_TOL, mf.JoinType.Round, 2.0, 16)
        grown_loops = [np.asarray(p, dtype=float) for p in grown.to_polygons()]
        inside = _inside(pts, _edges(grown_loops))
        at = 0
        for g, items in geoms:
            n = sum(_n_samples(it) for it in items)
            verdicts[g] = (part, pts[at:at + n], inside[at:at + n], grown_loops, items)
            at += n
    outer_of: dict = {}
    pending: dict = {}              # (statement, where, part) -> its copies' warnings
    for g in by_geom:
        if g not in verdicts:
            continue
        part, pts, inside, grown_loops, items = verdicts[g]
        if inside.all():
            continue
        if part not in outer_of:
            outer_of[part] = _edges([p for p in grown_loops if _signed(p) > 0])
        in_outline = _inside(pts[~inside], outer_of[part])
        warned.add(g)
        if meant_off(g, part) or _from_centres(d, g, items, pts[~inside]):
            continue
        where = "across a hole" if in_outline.all() else (
            "outside the outline" if not in_outline.any() else "outside the outline and across a hole")
        holes = _holes_crossed(d, roots, part, pts[~inside][in_outline]) if in_outline.any() else []
        if where == "across a hole" and _centre_line(d, roots, part, items, pts[~inside]) \
                and _off_share(items, grown_loops) <= CENTRE_LINE_OFF:
            continue            # a centre line through its holes (run hj: a unit circle's
            #                     axes through the pointer's pivot hole)
        if in_outline.any() and not holes:       # a window the shapes enclose (a rainbow's arch
            where = where.replace("a hole", "an opening")    # over its bar), no hole structure
        if _is_flat_text(g, items):
            said = _text_off(d, roots, part, g, items, pts, inside, in_outline, tick)
            if said is not None:
                sink.warning("W0505", f"engraving `{_copy_label(g)}` runs {where} of "
                             f"`{part.path}` ({said[0]})", g.span, hint=said[1])
                continue
        n = freed_share(d, part, pts[~inside], ENGRAVE_TOL) if d.split else 0
        if n == 1 and not inside.any():
            continue            # on one piece a cut frees: laid out with it (run cr's wiggle
            #                     snake, a diamond on each link: "lies across 1 of the pieces")
        if n:                   # on the pieces a cut frees: right as drawn, not laid out
            sink.warning("W0505", f"engraving `{g.label}` lies across "
                         f"{n + int(inside.any())} of the pieces that the through-cuts free "
                         f"from `{part.path}`: engraved as drawn when the sheet is cut as "
                         "drawn, but a cutting layout (`--layout`) lays each piece out on its "
                         f"own and keeps it with `{part.path}`",
                         g.span, hint="cut the sheet as drawn (without `--layout`), or keep "
                         "each engraving within one piece")
            continue
        # by length, not by samples (run dh: two 15 mm mortises under a 170 mm line were 2
        # of its 9 samples, "22%", for 17.6 %); a letter's stroke over a screw hole is under
        # 1% of a long text: "0%" read as "nothing is off" (issue 84's door sign), so a small
        # share is said as such
        gl = _edges(grown_loops)
        if _is_flat_text(g, items) or g.kind == "Text":
            off = float((~inside).sum()) / len(pts)
        else:
            lost, whole = _lengths(items, lambda P: ~_inside(P, gl))
            if lost < OVERSHOOT:
                continue    # a hair past the edge: nothing of the mark is lost (run dt's
                #             ruler ticks 0.08 mm past a rounded corner)
            off = lost / whole if whole > 0 else 1.0
        share = _pct(off, 1.0) if off >= 0.005 else "under 1%"
        hint = _off_outline_hint(d, part, g, pts, pts[~inside])
        if where in ("across a hole", "across an opening"):
            hint = (f"it crosses {', '.join(holes) if holes else 'an opening'}: shrink or move "
                    "the drawing clear of it, or move the hole")
        arc = arc_on_material(g, items, roots[part], _within, CUT_CLEAR, part)
        if arc:
            hint = f"{arc}; or {hint}"
        if g.kind != "Text":        # (letters off the material are a slip, never meant)
            hint += f"; if it runs off the material on purpose (lines carried over a joint's " \
                    f"band), say so with {_allow_call(g, part)}"
        # the copies of one statement (a pattern, a loop) once (run cc: eight veins, eight
        # warnings, where W0516 says its copies together)
        pending.setdefault((g.span or id(g), where, part), []).append(
            (g, f"engraving `{_copy_label(g)}` runs {where} of `{part.path}` ({share} of it "
                f"is off the material)", hint))
    for rows in pending.values():
        g, message, hint = rows[0]
        if len(rows) > 1 and g.span is not None:
            names = ", ".join(f"`{_copy_label(r[0]).removeprefix(r[0].owner.parent.path + '.')}`"
                              if r[0].owner.parent is not None else f"`{_copy_label(r[0])}`"
                              for r in rows[1:4])
            message += (f"; so do {len(rows) - 1} more of this statement's copies ({names}"
                        f"{', ...' if len(rows) > 4 else ''})")
        sink.warning("W0505", message, g.span, hint=hint)
    d.engravings_judged = True          # (W0523: an AllowOverlap of an engraving that no W0505 needed)
    texts = []
    says: list = []                 # W0516's, said once per statement over a loop's parts
    for part, geoms in by_part.items():
        if tick is not None:
            tick(part)
        _check_meets_cut(part, roots[part], [(g, it) for g, it in geoms if g not in warned],
                         (loops or {}).get(part), says)
        texts.append((part, [(g, it) for g, it in geoms if g not in warned and g.kind == "Text"]))
    _say_over_parts(says, sink)
    return texts


def _say_over_parts(says: list, sink) -> None:
    """W0516 for each ``(part, group, hole, E0, E1, crossing)`` of :func:`_check_meets_cut`;
    the same statement in copies of one part (a template called in a loop: run en's five
    coins, five warnings of one ring) is said once, at its closest, naming the others."""
    by: dict = {}
    for s in says:
        part, group = s[0], [f for f in s[1] if not meant_off(f[0], s[0])]
        if not group:
            continue        # `AllowOverlap(mark, self)`: it meets the edge on purpose (runs
            #                 gj, go: ticks meeting at a rim, a tank's outline on mortises)
        s = (part, group, *s[2:])
        g = min(group, key=lambda f: f[3])[0]
        key = (g.span, part.span) if g.span is not None and part.span is not None else id(s)
        by.setdefault(key, []).append(s)
    for same in by.values():
        same.sort(key=lambda s: (round(min(f[3] for f in s[1]), 6), s[0].path))
        first, rest = same[0], same[1:]
        also = ""
        if rest:
            names = ", ".join(f"`{s[0].path}`" for s in rest[:3])
            also = (f"; the same in {len(rest)} more part{'s' if len(rest) > 1 else ''} "
                    f"made by this statement ({names}{', ...' if len(rest) > 3 else ''})")
        _say_meets_cut(*first, sink, also)


def _off_outline_hint(d: Drawing, part, g, pts: np.ndarray, off: np.ndarray) -> str:
    """W0505's hint for engraving ``g`` of ``part`` off its outline (``pts``: its samples,
    n x 2 mm; ``off``: those off the material): where it leaves (the off sample nearest their
    middle, mm), and a constraint only where one mends it: the mark reaches past the box of
    the part's largest own shape, and fits in it with :data:`CUT_CLEAR` to spare, so
    `Inside(d.mark, body, margin=0.5 mm)` (the names as written in the part) moves it onto
    the material, clear of the cut; a mark larger than that shape is told to shrink.
    Before (issue 84): "e.g. `Inside(label, body)`" named shapes the program did not have,
    was offered for a knight's mane crossing the outline inside the box (which no box
    constraint mends), and, made as `Inside(d.mark, body)`, set the mark on the cut edge
    (W0516 again); made with `self` it conflicted (E0401)."""
    label, prefix = getattr(g, "label", ""), part.path + "."
    p = off[int(np.argmin(np.hypot(*(off - off.mean(axis=0)).T)))]
    wx, wy = written(part, *p)      # (run fo: given where the layout had moved the part)
    hint = (f"it leaves the material at about ({wx:.2f}, {wy:.2f}): move, shrink or "
            f"redraw `{label.rsplit('.', 1)[-1]}` so that it lies on the material, or move "
            "the part's edge")
    if not label.startswith(prefix):
        return hint
    found = _drawn_over(d, part, pts)
    if found is None:
        return hint
    name, (x0, y0, x1, y1) = found
    lo, hi = off.min(axis=0), off.max(axis=0)
    if not (lo[0] < x0 - ENGRAVE_TOL or lo[1] < y0 - ENGRAVE_TOL or hi[0] > x1 + ENGRAVE_TOL
            or hi[1] > y1 + ENGRAVE_TOL):
        return hint             # it crosses the outline inside the box: no box constraint mends it
    w, h = np.ptp(pts[:, 0]), np.ptp(pts[:, 1])
    if w + 2 * CUT_CLEAR > x1 - x0 or h + 2 * CUT_CLEAR > y1 - y0:
        return (f"shrink the drawing to fit on `{name}`, or move it onto the material "
                f"({hint})")
    mark = label[len(prefix):]
    return (f"{hint}; or constrain it onto the material: `Inside({mark}, {name}, "
            f"margin={CUT_CLEAR} mm)` in `{part.path}` (its box inside `{name}`'s, "
            f"{CUT_CLEAR} mm clear of the cut)")


def _allow_call(g, part) -> str:
    """The statement that says engraving ``g`` runs off ``part`` on purpose, and where:
    `` `AllowOverlap(grid.h, self)` in `board.left` `` for a drawing inside the part; for one
    that ``CutInto`` gives to it, the call in the structure both are in
    (`` `AllowOverlap(label.word, box.front)` in `kit` ``)."""
    label = g.label or "NAME"
    if g.owner.is_within(part):
        return f"`AllowOverlap({label[len(part.path) + 1:]}, self)` in `{part.path}`"
    where = g.owner
    while where is not None and not part.is_within(where):
        where = where.parent
    if where is None:
        return f"`AllowOverlap({label}, {part.path})`"
    cut = len(where.path) + 1
    return f"`AllowOverlap({label[cut:]}, {part.path[cut:]})` in `{where.path}`"


def _is_flat_text(g, items) -> bool:
    """True for an engraved Text on a straight baseline (not along a curve, not a stencil)
    whose strokes are at hand as lines."""
    return (getattr(g, "kind", None) == "Text" and g.data.get("along") is None
            and not g.data.get("stencil") and bool(items) and items[0][0] == "line")


FIT_LEAST = 0.25          # of a text's size: a smaller fit at its place is no fit (move it)


def _letters_of(text: str, n_items: int) -> list[int] | None:
    """The index in ``text`` of the letter each of its ``n_items`` strokes draws (the strokes
    in the order :func:`~aidl_lang.geometry.shapes.text.text_strokes` gives them), or None
    when the count does not match."""
    from ....geometry.shapes.text import _glyphs
    glyphs, out = _glyphs(), []
    for i, ch in enumerate(text):
        gl = glyphs.get(ch)
        if gl is not None:
            out += [i] * sum(max(len(st) - 1, 0) for st in gl[0])
    return out if len(out) == n_items else None


def _say_letters(text: str, idx) -> str:
    """Letters ``idx`` of ``text`` as a reader finds them: ``"B" and "Y"``; a letter the text
    holds more than once with its place, ``"M" (letter 1) and "M" (letter 11)``."""
    def one(i: int) -> str:
        nth = sum(1 for ch in text[:i + 1] if not ch.isspace())      # spaces are no letters
        return f'"{text[i]}"' + (f" (letter {nth})" if text.count(text[i]) > 1 else "")
    return " and ".join(", ".join(one(i) for i in idx).rsplit(", ", 1)) if idx else ""


def _text_off(d: Drawing, roots, part, g, items, pts, inside, in_outline, tick=None):
    """W0505's share and hint for an engraved Text on a straight baseline that runs off its
    part's material: ``(share, hint)``, or None when its strokes cannot be read as letters.
    The share is in letters (which reach off the material, of how many), as the picture
    shows it: "2%" of the sample points said nothing of a "Y" off the end (issue 105's dog
    tag).  The hint says each place it leaves the material (each hole it crosses and at which
    letters; off the outline, at which letters and about where) and the fix a text takes:
    ``max_width=`` the width it has room for where it is written (scaled about its position
    point, as a smaller size draws it, every sample inside the part and :data:`CUT_CLEAR` from
    the cut, rounded down to 0.1 mm), or that ``size=``; ``Inside(...)`` of its box conflicts
    (E0401) when the text is wider than the room (the dog tag's hint of before).  ``pts``,
    ``inside``: its samples (9 a stroke) and which are on the material; ``in_outline``: of
    the samples off it, which lie inside the outer outline (over a hole)."""
    from ....geometry.shapes.text import text_strokes
    text = str(g.data.get("text", ""))
    per = _letters_of(text, len(items))
    if per is None:
        return None
    per = np.repeat(np.asarray(per), 9)
    off_idx = np.flatnonzero(~inside)
    hole_pts, out_pts = off_idx[in_outline], off_idx[~in_outline]
    shown = [i for i, ch in enumerate(text) if not ch.isspace() and (per == i).any()]
    off_letters = sorted(set(per[off_idx].tolist()))
    share = (f"the letter{'s' if len(off_letters) > 1 else ''} {_say_letters(text, off_letters)}"
             f", {len(off_letters)} of its {len(shown)}, reach{'' if len(off_letters) > 1 else 'es'}"
             " off the material")
    places = []
    if len(hole_pts):
        holes = _holes_crossed(d, roots, part, pts[hole_pts])
        places.append(f"it crosses {' and '.join(holes) if holes else 'an opening'} at "
                      f"{_say_letters(text, sorted(set(per[hole_pts].tolist())))}")
    if len(out_pts):
        o = pts[out_pts]
        q = o[int(np.argmin(np.hypot(*(o - o.mean(axis=0)).T)))]
        places.append(f"it runs off the outline at "
                      f"{_say_letters(text, sorted(set(per[out_pts].tolist())))} (about "
                      f"({q[0]:.2f}, {q[1]:.2f}))")
    # a box constraint (`Inside(...)`) knows nothing of holes: it may move the text onto one
    holed = any(c.region is not None and not c.region.is_empty()
                and _part_of(c.owner, roots) is part for c in d.cuts)
    size = float(g.data.get("size", 0.0) or 0.0)
    rel = text_strokes(text, size, g.data.get("anchor", "middle"),
                       g.data.get("valign", "baseline"), g.data.get("rotation", 0.0))
    name = str(getattr(g, "label", "")).rsplit(".", 1)[-1] or "text"
    where = "; ".join(places)
    # one copy of a loop's statement (a ruler's "15" over its hanging hole, issue 111): a size
    # given to the statement shrinks every copy, so the hint leads with the move instead
    copy = _copy_label(g)
    one_of_many = "" if copy == g.label else (
        f"{where}: `{copy.rsplit('.', 1)[-1]}` is one of the copies its statement draws in a "
        "loop, and `max_width=` or `size=` there would change every copy: move what it "
        "crosses, or this copy (skip it in the loop with an `if`, or draw it apart)")
    if not rel or not size > 0:
        return share, f"{where}: make `{name}` smaller or move it onto the material"
    at = np.asarray(items[0][1], float) - np.asarray(rel[0][0], float)     # its position point
    loops = [np.asarray(p, dtype=float) for p in roots[part].to_polygons()]
    edges = _edges(loops)
    if tick is not None:
        tick(part)

    def fits(k: float) -> bool:
        q = at + k * (pts - at)
        return bool(_inside(q, edges).all() and not _within(q, edges, CUT_CLEAR).any())
    k = 1.0
    while k > FIT_LEAST and not fits(k):
        k -= 0.02
    if k <= FIT_LEAST:
        told = f"{where}: it has no room where it is written (its position point is at " \
               f"({at[0]:.2f}, {at[1]:.2f}))"
        if not len(hole_pts) and not holed:      # the box constraint may move it
            return share, f"{told}; {_off_outline_hint(d, part, g, pts, pts[~inside])}"
        if one_of_many:
            return share, f"{one_of_many}; where it is written this copy has no room"
        return share, f"{told}: move `{name}` onto the material, where it has room, or make it smaller"
    lo, hi = k, min(k + 0.02, 1.0)
    for _ in range(30):
        m = (lo + hi) / 2
        lo, hi = (m, hi) if fits(m) else (lo, m)
    rot = float(g.data.get("rotation", 0.0) or 0.0)
    u = pts[:, 0] * math.cos(rot) + pts[:, 1] * math.sin(rot)
    wide = float(u.max() - u.min())
    w = math.floor(lo * wide * 10) / 10
    s_new = math.floor(lo * size * 100) / 100
    fit = (f"{where}. Where it is written it has room for {w:g} mm along its baseline "
           f"({CUT_CLEAR} mm clear of the cut; it is {wide:.1f} mm wide): `max_width={w:g} mm` "
           f"in `{name}` (it shrinks to fit about its position point), or `size={s_new:g} mm`")
    if one_of_many:
        return share, (f"{one_of_many}; where it is written this copy has room for {w:g} mm "
                       f"along its baseline (it is {wide:.1f} mm wide)")
    if not len(hole_pts) and lo < 0.9 and not holed:    # much smaller: moving it may be better
        other = _off_outline_hint(d, part, g, pts, pts[~inside])
        if "`Inside(" in other:
            return share, (f"{fit}; or, if no other relation places it, "
                           f"{other[other.index('constrain it onto'):]}")
    return share, f"{fit}; or move it where it has room"


def _from_centres(d: Drawing, g, items, off: np.ndarray) -> bool:
    """Engraved line ``g`` (one straight stroke, ``items``) leaves the material only inside
    round openings centred on its ends (``off``: its samples off the material): a diagram's
    link drawn from pivot to pivot over the axle holes (issue 111's run dp, a strandbeest
    leg: W0505 x4).  The laser's pass over the hole marks nothing, and the line shows from
    the hole's edge, as drawn."""
    if len(items) != 1 or items[0][0] != "line" or not len(off):
        return False
    ends = np.array([items[0][1], items[0][2]], dtype=float)
    circles = np.array(d.circles, dtype=float).reshape(-1, 3)
    if not len(circles):
        return False
    at_end = circles[np.min(np.hypot(circles[:, None, 0] - ends[None, :, 0],
                                     circles[:, None, 1] - ends[None, :, 1]), axis=1) < 1e-6]
    if not len(at_end):
        return False
    inside = np.hypot(off[:, None, 0] - at_end[None, :, 0],
                      off[:, None, 1] - at_end[None, :, 1]) <= at_end[None, :, 2] + ENGRAVE_TOL
    return bool(inside.any(axis=1).all())


def _drawn_over(d: Drawing, part, pts: np.ndarray):
    """``(name, box)`` of the shape of solid ``part`` an engraving is drawn over (``pts``:
    its samples, n x 2 mm): among the named shapes of ``part`` and of the solids within it
    (``head.skull`` of a child solid, named as written in ``part``), the one whose face holds
    the most samples, the nearest to their middle among equals (or when none holds one); its
    box (x0, y0, x1, y1), mm.  None: ``part`` has no named shape.  Issue 111: the largest
    shape was taken, and a cat's whisker off its head was told `Inside(face.w2, haunch)`,
    which drags it to the hips."""
    from ..common import _solids_within
    mid = pts.mean(axis=0)
    prefix = part.path + "."
    best, key = None, None
    for st, fs in _solids_within(d, part):
        if st is not part and not st.path.startswith(prefix):
            continue
        at = "" if st is part else st.path[len(prefix):] + "."
        for geo, f in fs:
            if f is None or f.is_empty() or not geo.name:
                continue
            x0, y0, x1, y1 = f.bounds()
            held = int(_inside(pts, _edges([np.asarray(p, dtype=float)
                                            for p in f.to_polygons()])).sum())
            far = math.hypot(max(x0 - mid[0], 0.0, mid[0] - x1),
                             max(y0 - mid[1], 0.0, mid[1] - y1))
            k = (-held, far)
            if key is None or k < key:
                best, key = (at + geo.name, (x0, y0, x1, y1)), k
    return best


ON_CUT = 1 / 3           # of an engraving's samples: more on the outline is engraved over the cut


def _check_on_cut(part, shape, geoms, pts: np.ndarray, loops, sink) -> set:
    """W0516 for each engraved geometry of ``part`` of which more than :data:`ON_CUT` of the
    sample points (at least 3) lie within :data:`ENGRAVE_TOL` of the part's outline: a mark
    drawn along the cut edge (a protractor's 0 and 180 deg ticks on its straight edge), which
    the laser engraves over the cut, so it is not seen.  ``pts``: the samples of ``geoms`` in
    order (:func:`_samples`).  Returns the geometries warned."""
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    edges = _edges(loops)
    on = _within(pts, edges, ENGRAVE_TOL)
    said: set = set()
    if not on.any():
        return said
    at = 0
    for g, items in geoms:
        n = sum(_n_samples(it) for it in items)
        k = int(on[at:at + n].sum())
        at += n
        if k < 3 or k <= ON_CUT * n or g.data.get("fill"):
            continue            # (a filled area along the edge is engraved up to it: seen)
        share = _share_on(items, edges)         # by length: a polygon's samples are its corners
        if share <= ON_CUT:
            continue
        said.add(g)
        sink.warning("W0516", f"engraving `{g.label}` runs along the cut edge of `{part.path}` "
                     f"({_pct(share, 1.0)} of it lies on the outline): the laser "
                     "engraves over the cut, so the mark is not seen", g.span,
                     hint="move the mark inside the outline (start it at least its line "
                          "width from the edge) or leave it out; the cut already draws the edge")
    return said


CUT_CLEAR = 0.5          # mm: an engraved mark closer to the cut edge runs into it
SHOWN_CLEAR = 1.0        # mm: the clearance a W0516 hint moves a mark to (twice the least: it shows)
SAG = 2 * CHORD_TOL      # mm: an edge's chord and a mark's each lie up to CHORD_TOL off their arcs
OVERSHOOT = 0.25         # mm of a mark past the material (W0505): below it, nothing is lost
SQUARE = math.radians(15)   # a straight mark ending on the edge this near square is a tick
SCALE = 3                # ticks ending square on the edges of one part: a scale (a ruler)


def _check_meets_cut(part, shape, geoms, loops, sink: list) -> None:
    """W0516 for an engraved mark (not text) of ``part`` that comes within :data:`CUT_CLEAR`
    of the part's cut edge (its outline or a hole's edge) without running along it (that is
    :func:`_check_on_cut`) or off the material (W0505): a knight's mouth line drawn to the
    outline, a line ending a hair short of it.  The laser's engraving meets the cut, and a
    sliver under half a millimetre between them chars or breaks off.  Straight marks that
    end on the edge (within :data:`ENGRAVE_TOL`) and meet it square (within :data:`SQUARE`),
    :data:`SCALE` or more on one part, are a scale's ticks hanging from the edge (a ruler, a
    protractor) and are not warned, nor are pieces of one straight line that each end square
    on it (:func:`_split_bands`); nor is a mark whose ends all lie at the edge (a band or a
    seam drawn across the part, a cord wrapped round a grip), nor any copy of a loop statement
    of which half the copies or more are such bands, nor a straight mark that is a band's
    copy (the same run, each its own statement: `aidl import` writes a loop's copies so).  The warning names the mark, the part, which edge, the gap in mm and where
    (x, y), and how far inside to end or move the mark.  ``geoms``: (geometry, its stroke
    items); near-linear (the marks' and edges' boxes paired by :func:`box_pairs`).  What is
    found goes to ``sink``, a list, as :func:`_say_meets_cut`'s arguments (said by
    :func:`_say_over_parts`)."""
    from ...part.measure.nearby import box_pairs_between
    geoms = [(g, items) for g, items in geoms if g.kind != "Text"]
    if not geoms:
        return
    edges = _edge_arrays(shape, loops)
    if edges is None:
        return
    E0, E1, hole = edges
    segs = [_mark_segments(items) for _, items in geoms]
    S0 = np.concatenate([sg[0] for sg in segs])
    S1 = np.concatenate([sg[1] for sg in segs])
    owner = np.repeat(np.arange(len(segs)), [len(sg[0]) for sg in segs])
    pairs = box_pairs_between(np.column_stack([np.minimum(S0, S1), np.maximum(S0, S1)]),
                              np.column_stack([np.minimum(E0, E1), np.maximum(E0, E1)]),
                              CUT_CLEAR / 2)       # marks against edges, not edge pairs
    if not len(pairs):
        return
    si, ej_all = pairs[:, 0], pairs[:, 1]
    d, pa, _ = _pair_gap(S0[si], S1[si], E0[ej_all], E1[ej_all])
    _exact_circle_gaps(geoms, owner[si], E0[ej_all], E1[ej_all], d)
    across = _crosses(S0[si], S1[si], E0[ej_all], E1[ej_all])
    mk = owner[si]
    order = np.lexsort((d, mk))
    mk, d, pa, ej_all, across = mk[order], d[order], pa[order], ej_all[order], across[order]
    starts = np.r_[0, np.flatnonzero(mk[1:] != mk[:-1]) + 1]
    stops = np.r_[starts[1:], len(mk)]
    # 0.5 mm clear to within the chords' sag is clear: a mark set by `Inside(..., margin=0.5
    # mm)` ends 0.4999999 mm from the edge after solving (W0505's hint, issue 84), and the
    # edges and marks are measured as chords that lie up to CHORD_TOL inside their arcs (runs
    # gb, gj: quadrants and ticks asked for 0.5 mm inside a disc's rim read 0.495, warned)
    close = [(int(mk[a]), a, z) for a, z in zip(starts, stops) if d[a] < CUT_CLEAR - SAG]
    # each close mark's open ends against the edges near it, all in one array operation
    ends = [_open_ends(*segs[k]) for k, _, _ in close]
    qi, qe, qo, near_edges = [], [], [], []
    for c, ((k, a, z), q) in enumerate(zip(close, ends)):
        e = np.sort(ej_all[a:z])                 # np.unique imports numpy.ma (18 ms cold)
        e = e[np.r_[True, e[1:] != e[:-1]]]
        near_edges.append(e)
        for t in range(len(q)):
            qi.append(np.full(len(e), len(qo)))
            qe.append(e)
            qo.append((c, t))
    de_of: dict = {}
    if qo:
        qi, qe = np.concatenate(qi), np.concatenate(qe)
        Q = np.array([ends[c][t] for c, t in qo])
        dq, _, _ = _pair_gap(Q[qi], Q[qi], E0[qe], E1[qe])
        o = np.lexsort((dq, qi))
        qi, dq, qe = qi[o], dq[o], qe[o]
        first = np.r_[0, np.flatnonzero(qi[1:] != qi[:-1]) + 1]
        for f in first:
            de_of[qo[int(qi[f])]] = (float(dq[f]), int(qe[f]))
    found = []
    bands: dict = {}                 # statement span -> its copies that run edge to edge
    band_runs: set = set()           # the (dx, dy) of the straight bands
    crossing: set = set()            # the marks that run across the edge (r06's border)
    for c, (k, a, z) in enumerate(close):
        g, items = geoms[k]
        gap, pm, ej = float(d[a]), pa[a], int(ej_all[a])
        if g.data.get("fill") and gap <= ENGRAVE_TOL:
            continue            # a filled area run up to the cut: no sliver between (run dq)
        q = ends[c]
        de = np.array([de_of.get((c, t), (math.inf, -1))[0] for t in range(len(q))])
        if len(q) >= 2 and (de < CUT_CLEAR).all():
            bands[g.span] = bands.get(g.span, 0) + 1
            if len(items) == 1 and items[0][0] == "line":
                band_runs.add(_run(items[0]))
            continue                         # edge to edge: a band, a seam across the part
        if _side_on_edge(items, E0, E1, near_edges[c]):
            continue                         # a closed mark run out at the edge (a groove)
        end = None
        if len(q) and de.min() < CUT_CLEAR and de.min() - gap <= max(ENGRAVE_TOL, 1e-6):
            t = int(np.argmin(de))
            end, pm = q[t], q[t]
            gap, ej = de_of[(c, t)]
        if end is not None and gap <= ENGRAVE_TOL and g.kind == "Intersect" and not g.closed:
            continue        # a hatch clipped to an area runs out at its edge by design (run
            #                 eu's pattern weight: thread lines clipped to the reel's barrel)
        tick = False
        line = len(items) == 1 and items[0][0] == "line"
        if line and end is not None and gap <= ENGRAVE_TOL:
            # square to an edge it ends on: at an inside corner, to either (run gn's scratch
            # stock: a depth scale's zero tick ending where the fence's edge meets the body's,
            # in line with the body's)
            e = near_edges[c]
            at = np.repeat(np.asarray(end, float)[None, :], len(e), axis=0)
            on = e[_pair_gap(at, at, E0[e], E1[e])[0] <= ENGRAVE_TOL]
            u, w = np.asarray(items[0][2], float) - items[0][1], E1[on] - E0[on]
            nu, nw = float(np.hypot(*u)), np.hypot(w[:, 0], w[:, 1])
            square = (nw > 0) & (np.abs(w @ u) <= math.sin(SQUARE) * nu * nw)
            tick = nu > 0 and bool(square.any())
        found.append((g, items, near_edges[c], gap, ej, pm, end, line, tick))
        if end is None and across[a:z].any():
            crossing.add(id(g))             # it runs across the edge: part of it is off
    scale = sum(f[-1] for f in found) >= SCALE
    split = _split_bands([f for f in found if f[-1]])
    copies: dict = {}
    for g, _ in geoms:
        copies[g.span] = copies.get(g.span, 0) + 1
    by_statement: dict = {}
    for f in found:
        if f[-1] and (scale or id(f[0]) in split):
            continue        # a scale's ticks hanging from the edge, or a band split in pieces
        if f[0].span is not None and 2 * bands.get(f[0].span, 0) >= copies[f[0].span]:
            continue                         # one of a loop of bands (its last one ends inside)
        if f[7] and _run(f[1][0]) in band_runs:
            continue                         # a band's copy, each its own statement (imported)
        by_statement.setdefault(f[0].span or f[0], []).append(f)
    for group in by_statement.values():
        sink.append((part, group, hole, E0, E1, crossing))


def _side_on_edge(items, E0, E1, e) -> bool:
    """Whether the closed mark ``items`` (one polygon) has a side at least :data:`CUT_CLEAR`
    long lying on one of the edges ``e`` (its ends and middle within :data:`ENGRAVE_TOL`):
    the mark runs out at the cut, as a band drawn across the part does (issue 111's run dh:
    a toy railway bridge's filled track grooves ending square at the deck's ends, as a track
    groove must).  A mark touching the edge at a corner or a point is not such a mark."""
    if len(items) != 1 or items[0][0] != "poly" or not len(e):
        return False
    P = np.asarray(items[0][1], float)
    A, B = P, np.roll(P, -1, axis=0)
    keep = np.hypot(*(B - A).T) >= CUT_CLEAR
    if not keep.any():
        return False
    A, B = A[keep], B[keep]
    n, m = len(A), len(e)
    on = np.ones((n, m), dtype=bool)
    for Q in (A, B, (A + B) / 2):
        Qr = np.repeat(Q, m, axis=0)
        d, _, _ = _pair_gap(Qr, Qr, np.tile(E0[e], (n, 1)), np.tile(E1[e], (n, 1)))
        on &= d.reshape(n, m) <= ENGRAVE_TOL
    return bool(on.any())


def _say_meets_cut(part, group: list, hole, E0, E1, crossing: set, sink, also: str = "") -> None:
    """W0516 for the close marks of one statement (``group``, :func:`_check_meets_cut`'s
    tuples), the closest first: how it meets the edge (ends on, touches, runs across), where,
    and how far to end or move it; ``hole``: whether each edge is a hole's, ``E0``, ``E1``
    the edges' ends, ``crossing`` the ids of the marks that run across an edge."""
    group.sort(key=lambda f: f[3])
    g, items, e, gap, ej, pm, end, line, _ = group[0]
    which = "a hole's edge" if hole[ej] else "the outline"
    t = r = None
    if line and end is not None:
        p, q = np.asarray(items[0][1], float), np.asarray(items[0][2], float)
        if np.hypot(*(end - p)) < np.hypot(*(end - q)):
            p, q = q, p                              # q: the end at the edge
        t, r = _shorten_clear(p, q, E0[e], E1[e])
    # a gap that two decimals round up to the clearance is said to three (run fo: "ends 0.50
    # mm from the cut edge" beside "a mark needs 0.5 mm clear")
    shown = f"{gap:.3f}" if round(gap, 2) >= CUT_CLEAR else f"{gap:.2f}"
    if end is not None:
        how = "ends on" if gap <= ENGRAVE_TOL else f"ends {shown} mm from"
    elif id(g) in crossing:
        how = "runs across"
    else:
        how = "touches" if gap <= ENGRAVE_TOL else f"comes {shown} mm from"
    if id(g) in crossing and end is None:       # run r's place card: a border through a slot
        fix = (f"it crosses {which} there, so part of it lies off the material: shrink "
               f"or move `{g.label}` to stay on it, {CUT_CLEAR} mm clear of the edge (or "
               "leave a gap in it round the opening)")
    elif t is not None:
        rx, ry = written(part, *r)
        fix = (f"end `{g.label}` {t:.2f} mm further inside, at ({rx:.2f}, {ry:.2f}) "
               f"(shorten it by {t:.2f} mm), so that it stops {CUT_CLEAR} mm short of the "
               "edge")
        if len(group) > 1:
            ts = [_shorten_clear(*_far_near(f), E0[f[2]], E1[f[2]])[0]
                  if f[7] and f[6] is not None else None for f in group]
            if all(x is not None for x in ts):
                fix = (f"end each copy of `{g.label}` at least {max(ts):.2f} mm further "
                       f"inside (shorten it), so that it stops {CUT_CLEAR} mm short of the "
                       "edge")
            else:
                fix = (f"end or move each copy of `{g.label}` at least {CUT_CLEAR} mm "
                       "inside the edge")
    else:
        # to a clearance that shows (run en's coin: the least the check takes, 0.01 mm
        # further, passed it and left the ring reading as on the edge)
        fix = (f"keep `{g.label}` {math.ceil(round((SHOWN_CLEAR - gap) * 100, 6)) / 100:.2f} mm "
               f"further from the edge (move it, or change its size), {SHOWN_CLEAR:g} mm clear: "
               f"at the {CUT_CLEAR} mm the check takes, a mark still reads as on the edge")
    more = ""
    if len(group) > 1:
        rest = ", ".join(f"`{_copy_label(f[0], short=True)}` ({f[3]:.2f} mm at "
                         f"({written(part, *f[5])[0]:.2f}, {written(part, *f[5])[1]:.2f}))"
                         for f in group[1:4])
        more = (f"; {len(group) - 1} more cop{'ies' if len(group) > 2 else 'y'} of this "
                f"statement as close: {rest}{', ...' if len(group) > 4 else ''}")
    wx, wy = written(part, *pm)
    # a line run on across an opening's edge leaves no sliver: it is engraved up to the
    # edge, as drawn, a note (runs eq, ey, fg, fj: a border across a foot's slot, a ring
    # through its peg holes, a vine's stems into its leaf cut-outs, all meant; run r's
    # place card, a border through a slot, called a slip: said either way)
    across = id(g) in crossing and end is None and g.kind != "Text"
    sink.add(Diagnostic(
        "W0516", f"engraving `{_copy_label(g)}` {how} the cut edge of "
        f"`{part.path}` ({which}) at ({wx:.2f}, {wy:.2f}): " + (
            "engraved up to the edge where it crosses, as drawn (a mark meant to stop short "
            f"needs {CUT_CLEAR} mm clear of the edge)" if across else
            f"the engraving meets the cut (a mark needs {CUT_CLEAR} mm clear of the edge), "
            "so it runs into the edge") + f"{more}{also}", g.span,
        "note" if across else "warning", hint=fix + "; the cut already draws the edge; if "
        f"it is meant to meet the edge, {_allow_call(g, part)} says so"))


def _run(item) -> tuple:
    """A straight stroke's (dx, dy), rounded to 1e-6 mm: copies of one band share it (a grip's
    wraps, each written as its own line by `aidl import`, the last ending inside the part)."""
    return tuple(np.round(np.asarray(item[2], float) - np.asarray(item[1], float), 6))


def _split_bands(ticks: list) -> set:
    """The ids of the straight marks among ``ticks`` (each ending square on the edge) that
    lie on one line with another of them: the pieces of one line drawn across the part,
    broken where a hole or a word stands (a router template's door-edge line either side of
    its cup hole, 105d #10: it was warned, and a model ended each piece 0.5 mm short of the
    edge the line is there to meet).  Grouped by the line's direction and its distance from
    the origin (to 1e-4 rad and 0.01 mm): O(n)."""
    lines: dict = {}
    for f in ticks:
        p, q = np.asarray(f[1][0][1], float), np.asarray(f[1][0][2], float)
        u = q - p
        n = float(np.hypot(*u))
        if n <= 0:
            continue
        u = u / n
        if u[0] < -1e-12 or (abs(u[0]) <= 1e-12 and u[1] < 0):
            u = -u                          # one direction per line
        key = (round(math.atan2(u[1], u[0]), 4), round(float(u[0] * p[1] - u[1] * p[0]), 2))
        lines.setdefault(key, []).append(id(f[0]))
    return {k for ids in lines.values() if len(ids) >= 2 for k in ids}


def _far_near(f) -> tuple:
    """A found straight mark's ends as (far, near): near is its end at the edge."""
    items, end = f[1], f[6]
    p, q = np.asarray(items[0][1], float), np.asarray(items[0][2], float)
    return (q, p) if np.hypot(*(end - p)) < np.hypot(*(end - q)) else (p, q)


def _open_ends(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The open ends (k x 2) of a mark's segments (starts ``a``, ends ``b``): the points that
    end one segment only (a line's two ends; none for a circle or a closed outline)."""
    P = np.vstack([a, b])
    if len(a) == 1:
        return P if float(np.hypot(*(a[0] - b[0]))) > 1e-9 else P[:0]
    key = (np.round(P, 9) + 0.0).view(np.complex128).ravel()     # x + iy; + 0.0: -0.0 is 0.0
    order = np.argsort(key)             # equal points side by side (np.unique imports numpy.ma)
    k = key[order]
    run = np.cumsum(np.r_[True, k[1:] != k[:-1]]) - 1
    once = np.empty(len(k), dtype=bool)
    once[order] = np.bincount(run)[run] == 1
    return P[once]


def _shorten_clear(p, q, E0, E1) -> tuple:
    """How much (mm, to 0.01) to shorten the line ``p``-``q`` at ``q`` so that it stays
    :data:`CUT_CLEAR` from the edges ``E0``-``E1``, and its new end (rounded to 0.01 mm, the
    figures a hint prints, checked to clear): ``(t, end)``, or ``(None, None)``."""
    length = float(np.hypot(*(q - p)))
    if length <= 0:
        return None, None
    u = (q - p) / length

    def clear(t):
        r = q - t * u
        return _seg_gap(p[None], r[None], E0, E1)[0] >= CUT_CLEAR
    top = length * (1 - 1e-9)
    if not clear(top):
        return None, None
    lo, hi = 0.0, top
    while hi - lo > 1e-3:
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if clear(mid) else (mid, hi)
    t = math.ceil(hi * 100 - 1e-9) / 100
    for _ in range(5):                  # the figures as printed must clear the edge
        r = np.round(q - t * u, 2)
        if _seg_gap(p[None], r[None], E0, E1)[0] >= CUT_CLEAR:
            return t, r
        t += 0.01
    return None, None


def _copy_label(g, short: bool = False) -> str:
    """``g``'s label (``short``: its name alone), with ``[k]`` when ``g`` is the k-th copy of
    a statement run in a loop (the geometries of its structure with its name and its
    statement's span, in the order made): ``clock.dial.ticks[0]``.  Copies made by nested
    loops are counted as one run."""
    owner = getattr(g, "owner", None)
    name = g.name if short and g.name else g.label
    if not getattr(g, "name", None) or owner is None or g.span is None:
        return name
    same = [h for h in owner.geometry if h.name == g.name and h.span == g.span]
    if len(same) < 2 or g not in same:
        return name
    return f"{name}[{same.index(g)}]"


def stroke_gap(P, Q, bp, bq, pad: float) -> float:
    """The least distance (mm) between the strokes ``P`` and ``Q`` (k x 2 x 2) of two texts,
    each one's strokes within ``pad`` of the other's box (``bp``, ``bq``: x0, y0, x1, y1)."""
    def within(S, b):
        lo, hi = S.min(axis=1), S.max(axis=1)
        return S[(hi[:, 0] >= b[0] - pad) & (lo[:, 0] <= b[2] + pad)
                 & (hi[:, 1] >= b[1] - pad) & (lo[:, 1] <= b[3] + pad)]
    P, Q = within(P, bq), within(Q, bp)
    return _seg_gap(P[:, 0], P[:, 1], Q[:, 0], Q[:, 1])[0] if len(P) and len(Q) else math.inf


def _seg_gap(A0, A1, B0, B1) -> tuple:
    """The least distance (mm) between the segments ``A0[i]``-``A1[i]`` (n x 2 each) and
    ``B0[j]``-``B1[j]`` (m x 2): ``(d, i, j, pa, pb)`` with the nearest points ``pa`` on
    segment ``i`` of A and ``pb`` on segment ``j`` of B (0 and the crossing point when two
    segments cross).  All n x m pairs in one array operation: for the small sets of one mark
    and one text, or one mark and the edges near it.  ``(inf, -1, -1, None, None)`` when
    either set is empty."""
    A0, A1 = np.asarray(A0, float).reshape(-1, 2), np.asarray(A1, float).reshape(-1, 2)
    B0, B1 = np.asarray(B0, float).reshape(-1, 2), np.asarray(B1, float).reshape(-1, 2)
    if not len(A0) or not len(B0):
        return math.inf, -1, -1, None, None
    a0, a1 = A0[:, None, :], A1[:, None, :]
    b0, b1 = B0[None, :, :], B1[None, :, :]
    da, db = a1 - a0, b1 - b0

    def foot(p, s0, d):             # the nearest point to p on the segments s0 + t d
        l2 = (d * d).sum(-1)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.clip(np.where(l2 > 0, ((p - s0) * d).sum(-1) / l2, 0.0), 0.0, 1.0)
        return s0 + t[..., None] * d
    cands = []                      # (distance n x m, point on A, point on B)
    for p, on_b in ((a0, True), (a1, True), (b0, False), (b1, False)):
        if on_b:
            q = foot(p, b0, db)
            pa, pb = np.broadcast_to(p, q.shape), q
        else:
            q = foot(p, a0, da)
            pa, pb = q, np.broadcast_to(p, q.shape)
        cands.append((np.hypot(*(pa - pb).transpose(2, 0, 1)), pa, pb))
    d = np.minimum.reduce([c[0] for c in cands])
    # proper crossings: the ends of each segment on opposite sides of the other
    def cross(u, v):
        return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
    s1, s2 = cross(da, b0 - a0), cross(da, b1 - a0)
    s3, s4 = cross(db, a0 - b0), cross(db, a1 - b0)
    hit = (s1 * s2 < 0) & (s3 * s4 < 0)
    d = np.where(hit, 0.0, d)
    i, j = np.unravel_index(int(np.argmin(d)), d.shape)
    if hit[i, j]:
        t = s3[i, j] / (s3[i, j] - s4[i, j])
        p = A0[i] + t * (A1[i] - A0[i])
        return 0.0, int(i), int(j), p, p.copy()
    best = min(cands, key=lambda c: c[0][i, j])
    return float(best[0][i, j]), int(i), int(j), np.array(best[1][i, j]), np.array(best[2][i, j])


def _mark_segments(items) -> tuple:
    """The segments of an engraved mark's ``items`` as (starts, ends), k x 2 each: lines
    exact, curves as the polylines of their W0505 samples."""
    a, b = [], []
    for it in items:
        P = _polyline(it)
        a.append(P[:-1])
        b.append(P[1:])
    return np.concatenate(a), np.concatenate(b)


def _polyline(item) -> np.ndarray:
    """An engraving item as a polyline (lines exact, curves sampled as in W0505)."""
    if item[0] == "line":
        return np.array([item[1], item[2]], dtype=float)
    if item[0] == "poly":
        P = np.asarray(item[1], dtype=float)
        return np.vstack([P, P[:1]])
    if item[0] == "circle":
        P = _sample(item)
        return np.vstack([P, P[:1]])
    return _sample(item)


def _check_zero_lines(d: Drawing, sink: DiagnosticSink) -> None:
    """W0524 for each statement of a ``drawing`` whose Line has no length (its start and
    end at one place, within 1e-9 mm: ``Line((x, y), (x, y))``): it engraves no line, only a
    plunge at a point, and nothing holds its two points (each a free starting guess).  One
    warning per statement, with the number of its copies (a loop's)."""
    lines = [(g, item) for style, item, g in d.strokes
             if style == "drawing" and g is not None and item[0] == "line" and g.span is not None]
    if not lines:
        return
    # every line's length in one array operation (a text's strokes are lines too: hundreds)
    ends = np.array([(item[1], item[2]) for _, item in lines], dtype=float)     # k x 2 x 2
    by_span: dict = {}
    for k in np.flatnonzero(np.hypot(*(ends[:, 1] - ends[:, 0]).T) <= 1e-9).tolist():
        g = lines[k][0]
        by_span.setdefault(g.span, []).append((g, ends[k, 0]))
    for span, hits in by_span.items():
        g, p = hits[0]
        many = f" ({len(hits)} copies)" if len(hits) > 1 else ""
        sink.warning("W0524", f"`{g.label}` is a Line of zero length{many}: its start and end "
                     f"are both at ({p[0]:.6g}, {p[1]:.6g}), so it engraves no line (a "
                     "plunge at a point) and nothing holds its two points", span,
                     hint="give the Line two different points (its end where the stroke should "
                          "end, e.g. `Line((x, y), (x + 10, y))`), or delete it; a dot is a "
                          "small Circle")
