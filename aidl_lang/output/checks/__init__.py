"""Geometry checks on the final shape: warnings about parts that solve but come out wrong.

In: the booleans' :class:`~aidl_lang.output.part.build.booleans.Drawing`, the exact output model and
(for the fit check) the assembled product.  Out: W05xx diagnostics on the sink, and what the
final part is as data and text (:mod:`.reports.describe`, ``aidl check --describe``) and its parts
list (:mod:`.reports.inventory`, ``aidl parts``).  Imports the part and fabrication stages, never the writers.

The booleans (:mod:`aidl_lang.output.part.build.booleans`) record each structure's shape and what each hole cut; these
checks read them (docs/outputs.md, "Checks"; every code is in :mod:`aidl_lang.base.codes`).
:func:`check_drawing` is the one entry point (run by :mod:`aidl_lang.pipeline` and the live
preview); :func:`check_topology` (W0510) is run beside it when param values are overridden.
One module per family, in rooms by what they look at (:mod:`.holes`, :mod:`.material`,
:mod:`.marks`; :mod:`.reports` for what they report), the contract in pyproject.toml:

* :mod:`.holes.openings`: ``W0501`` a hole refilled by a solid, ``W0502`` a hole that cuts nothing,
  ``W0503`` a hole that removes all of its solid, ``W0507`` a wall between two holes (or a
  hole and the outline) thinner than the minimum, ``W0508`` two holes that cut one opening,
  ``W0514`` a hole flush with the outer edge;
* :mod:`.holes.repeats`: ``W0512`` a statement's repeated faces (or two circles of one hole)
  that merge;
* :mod:`.holes.voids`: ``W0515`` an opening no hole cuts (a void, or a window the faces of
  one solid merge around);
* :mod:`.material.walls`: ``W0507`` a wall thinner than ``min_wall`` (default :data:`MIN_WALL`,
  0.5 mm), by a morphological opening of the part; :mod:`.material.necks`: ``W0507`` two
  members joined over a neck; :mod:`.material.slits`: ``W0519`` a slit of empty space
  narrower than ``min_wall`` between two shapes of one outline;
* :mod:`.parts`: ``W0504`` a part that falls apart into pieces, ``W0506`` a child solid that
  adds nothing, ``W0509`` a face of zero area, ``W0511`` parts that interpenetrate,
  ``W0520`` a ledge where one shape pokes past another's edge by less than ``min_wall``;
* :mod:`.marks.engravings`: ``W0505`` engraving off the material, ``W0516`` engraving along the cut,
  ``W0524`` a drawing's Line of zero length;
* :mod:`.allowances`: ``W0523`` an ``AllowOverlap`` that allows nothing;
* :mod:`.marks.text`: ``W0513`` text drawn over text or over an engraved mark;
* :mod:`.material.through`: ``W0522`` a through-cut off the material or along the outline (or a segment of one), or one
  along another, ``W0507`` a web thinner than the minimum between through-cuts (or a through-cut and the outline);
* :mod:`.assembly`: ``W0517`` parts that collide once assembled, ``W0518`` a part that
  touches no other;
* :mod:`.changes`: ``W0510`` a part whose topology differs from the defaults';
* :mod:`.material.toolpath_walls` (``aidl render``, not this entry point): ``W0507`` the material
  beside a through-cut that the cutter's own width (a router's bit, a laser's kerf) leaves
  thinner than the minimum wall, and ``W0510`` a part the bit cuts apart;
* :mod:`.common`: the tolerances and helpers they share.

:func:`check_drawing` itself writes ``W0509`` (from :func:`.parts.empty_faces`, and for a
solid part that comes out empty unexplained) and ``W0402`` (an open outline, drawn as
engraving).

Areas are compared with a tolerance that ignores the chord slivers of tessellated curves:
:data:`MIN_FRACTION` of the feature and at least :data:`MIN_AREA` mm^2.
"""
from __future__ import annotations

import math

import numpy as np

from ...base.diagnostics import Diagnostic, DiagnosticSink
from ..part.build.booleans import Drawing
from .allowances import check_allowances
from .assembly import _check_fit
from .changes import Topology, check_topology, topology, topology_changes
from .common import (MIN_AREA, MIN_FRACTION, MIN_WALL, _cut_openings, _edges, _inside,
                     _inside_loops, _part_of, _part_roots, _signed, _union, part_min_wall)
from .holes.pattern_edge import (CLOSED_OPENINGS, _check_closed_openings, check_open_mortises,
                                 check_pattern_edges)
from .material.kerf import check_kerf
from .holes.openings import TOUCH, _analyse, _check_flush, _check_hole, _intended, _Near, _report_openings
from .holes.repeats import _check_overlapping_circles, _check_repeated_faces
from .holes.sinks import check_sinks
from .holes.voids import _check_voids
from .marks.engravings import _check_engraving, _check_zero_lines
from .marks.sampling import _SURELY_GROWN, ENGRAVE_TOL, _n_samples, _sample, _samples, _within
from .parts import (_check_interpenetration, _check_steps, _check_invisible, _check_pieces,
                    check_loose_drawings, check_stray_holes, empty_faces)
from .marks.clearance import check_text_near_cut
from .marks.text import _check_text_overlap
from .material.through import check_sheet_cuts, check_through
from .material.necks import _check_necks
from .material.slits import _check_slits
from .material.walls import (THIN_SECONDS_PER_VERTEX, TILE_VERTS, UNION_GROUP, WHOLE_LOOPS, WHOLE_VERTS,
                             _check_walls, _isolated_loops, _loop_boxes, _open, _point_of, _thin)

# the names other modules, the tests and the benchmarks import from here (patching one of the
# others' helpers, e.g. walls._open, means patching it in the module that uses it)
__all__ = ["check_drawing", "check_loose_drawings", "check_stray_holes", "check_topology", "topology", "topology_changes", "Topology",
           "empty_faces", "MIN_WALL", "MIN_AREA", "MIN_FRACTION", "ENGRAVE_TOL", "TOUCH",
           "_SURELY_GROWN", "THIN_SECONDS_PER_VERTEX", "TILE_VERTS", "UNION_GROUP",
           "WHOLE_LOOPS", "WHOLE_VERTS", "_analyse", "_check_fit", "_check_hole",
           "_check_invisible", "_check_walls", "_edges", "_inside", "_inside_loops",
           "_intended", "_isolated_loops", "_loop_boxes", "_n_samples", "_Near", "_open",
           "_part_of", "_part_roots", "_point_of", "_report_openings", "_sample", "_samples",
           "_signed", "_thin", "_union", "_within"]


CHECK_SHARE = 0.2     # of the budget's work units (400,000 of the default 2,000,000): what
                      # each family of checks below may spend over all the parts before it
                      # stops (W0521)

# the families of checks that hold a share, in the order they run: (name, codes)
FAMILIES = {"holes": ("holes", "W0501-W0503"), "pieces": ("pieces", "W0504"),
            "invisible": ("shapes that add nothing", "W0506"),
            "engraving": ("engravings", "W0505, W0516"),
            "openings": ("walls between features", "W0507, W0508, W0514"),
            "voids": ("openings no hole cuts", "W0515"), "walls": ("thin walls", "W0507"),
            "slits": ("slits", "W0519"), "steps": ("ledges", "W0520"),
            "text": ("text over text or marks", "W0513"),
            "repeats": ("copies that merge", "W0512"),
            "through": ("through-cuts", "W0507, W0522"),
            "interpenetration": ("parts that interpenetrate", "W0511"),
            "allowances": ("AllowOverlap statements", "W0523"),
            "kerf": ("the kerf's offset", "E0504")}


class _OutOfShare(Exception):
    """A family of checks has used its :data:`CHECK_SHARE` of the compile's work units, or its
    next step (``ahead`` reference seconds, > 0) is priced past that share or past the
    compile's work budget."""

    def __init__(self, ahead: float = 0.0, past_deadline: bool = False):
        super().__init__(ahead)
        self.ahead, self.past_deadline = ahead, past_deadline


class _Shares:
    """Each family of checks (:data:`FAMILIES`) with its share of the compile's work
    (:data:`CHECK_SHARE` of the budget's work units, :class:`~aidl_lang.base.limits.Work`,
    summed over the parts it looks at): a family past its share, or refused by
    :class:`..nearby.TooManyPairs` (a cluster too dense to list its pairs), stops where it is,
    is not run on the parts after, and one ``W0521`` note per family says which parts it did
    not check and why.  A step of a family that cannot be interrupted (one call into Manifold)
    and is priced past the family's share or past the compile's budget is not started: the
    family stops with the same note (these checks only warn, so a guess never fails a
    compile).  The compile's budget, once spent, still ends everything with ``E0304``
    (:meth:`tick` pays through it), as does a step priced past it outside any family; without
    a deadline (a test, the live preview's own call) there are no shares, only the pair limit.
    Work, not CPU seconds: the same checks run and the same notes are said on every machine."""

    def __init__(self, deadline):
        self.deadline = deadline
        self.share = (deadline.budget.work * CHECK_SHARE if deadline is not None
                      else float("inf"))
        self.spent: dict = {}
        self.skipped: dict = {}      # family -> [reason, parts]
        self.family, self.since = None, 0.0

    def _spent(self) -> float:
        return self.deadline.work.spent if self.deadline is not None else 0.0

    def tick(self, s, ahead: float = 0.0) -> None:
        from ...base.limits import seconds_as_work
        units = seconds_as_work(ahead)
        if self.family is None or self.deadline is None:
            if self.deadline is not None:
                self.deadline.check("the shape checks", s, units)
            return
        work = self.deadline.work
        if self.spent.get(self.family, 0.0) + work.spent - self.since + 1.0 + units > self.share:
            raise _OutOfShare(ahead)
        if units and work.spent + 1.0 + units > work.limit:
            raise _OutOfShare(ahead, past_deadline=True)
        self.deadline.check("the shape checks", s, units)

    def run(self, family: str, part, fn):
        """``fn()`` as family ``family`` on ``part`` (a Structure or None); its result, or
        None when it was stopped or not run."""
        from ..part.measure.nearby import TooManyPairs
        if family in self.skipped:
            self.skipped[family][1].append(part)
            return None
        self.family, self.since = family, self._spent()
        try:
            if part is not None:
                self.tick(part)
            return fn()
        except _OutOfShare as ex:
            self.skipped[family] = [ex, [part]]
        except TooManyPairs as ex:
            self.skipped[family] = [ex, [part]]
        finally:
            self.spent[family] = self.spent.get(family, 0.0) + self._spent() - self.since
            self.family = None
        return None

    def guard(self, family: str, part, fn):
        """``fn()`` with no share of its own (it runs on the compile's deadline alone), only
        the pair limit: a family that must end with E0304 rather than stop early."""
        from ..part.measure.nearby import TooManyPairs
        try:
            return fn()
        except TooManyPairs as ex:
            self.skipped[family] = [ex, [part]]
        return None

    def notes(self, sink: DiagnosticSink, min_wall: float) -> None:
        """One ``W0521`` note per family that did not check everything."""
        from ...base.diagnostics import Diagnostic
        for family, (why, parts) in self.skipped.items():
            what, codes = FAMILIES[family]
            named = list(dict.fromkeys(f"`{p.path}`" for p in parts if p is not None))
            where = (" in " + ", ".join(named[:3]) + (f" and {len(named) - 3} more"
                                                      if len(named) > 3 else "")) if named else ""
            if isinstance(why, _OutOfShare):
                from ...base.limits import seconds_as_work
                total = self.deadline.budget.work
                share = (f"its share of the work ({int(self.share):,} of the {total:,} work "
                         "units of the budget)")
                step = f"{int(seconds_as_work(why.ahead)):,} work units"
                if why.past_deadline:
                    reason = (f"its next step, priced at {step}, would pass the compile's "
                              f"{total:,}: not started")
                elif why.ahead:
                    reason = f"its next step, priced at {step}, would pass {share}: not started"
                else:
                    reason = f"out of {share}"
                hint = "`--budget 2` (or more) gives every check twice the work"
            else:
                reason = (f"{why.count:,} pairs of edges or shapes within reach of one "
                          f"another, more than the {why.limit:,} it measures (a dense "
                          "cluster: thousands of edges all within the distance)")
                hint = ("scale the drawing to its real size (an imported map a few mm wide "
                        f"puts every edge within {min_wall:g} mm of hundreds of others), or "
                        "set a smaller minimum with --min-wall")
            first = next((p for p in parts if p is not None and p.span is not None), None)
            sink.add(Diagnostic("W0521", f"not checked: {what} ({codes}){where}: {reason}",
                                first.span if first is not None else None, "note",
                                hint=hint))


def _idle_min_wall(d: Drawing, sink: DiagnosticSink) -> None:
    """W0101 for each ``min_wall`` statement that no check reads: one inside a structure
    that is neither a part nor holds one (a ``cut``, a ``hole``, a solid merged into its
    part): the wall checks hold a whole part to one minimum, found from the part up
    (:func:`part_min_wall`), so it must be written in the part or above it."""
    parts = set(d.part_of.values())
    if not parts:
        return
    above = set(parts)
    for p in parts:
        above.update(p.ancestors())
    root = next(iter(parts))
    while root.parent is not None:
        root = root.parent
    for n in root.subtree():
        if n in above or getattr(n, "min_wall", None) is None:
            continue
        part = next((a for a in n.ancestors() if a in parts), None)
        where = (f"in `solid {part.name}` (`{part.path}`: it covers the part's holes and "
                 "through-cuts)" if part is not None else "in the part it is meant for")
        why = (f"a {n.kind} inside a part is not a part of its own, and the wall checks "
               f"hold each part to its own minimum (`{part.path}`'s)" if part is not None else
               f"a {n.kind} that holds no part is not checked for thin walls")
        sink.warning("W0101", f"`min_wall` in {n.kind} `{n.path}` has no effect: {why}",
                     getattr(n, "min_wall_span", None) or n.span,
                     hint=f"write the `min_wall` statement {where}, or at the top of the file "
                          "for every part")


def check_drawing(d: Drawing, sink: DiagnosticSink, min_wall: float | None = None,
                  deadline=None) -> None:
    """Append the geometry warnings for the booleans' result ``d`` to ``sink``; ``min_wall``
    (mm) is W0507's minimum wall (0 turns that check off; W0508, holes that merge, stays on),
    overriding the program's ``min_wall`` statements (:func:`part_min_wall`); None: theirs,
    else :data:`MIN_WALL`.
    ``deadline``: the compile's :class:`~aidl_lang.base.limits.Deadline`, checked between
    structures and holes (raises :class:`~aidl_lang.base.limits.OutOfBudget`); each family of
    checks holds :data:`CHECK_SHARE` of it and past that stops with a ``W0521`` note
    (:class:`_Shares`)."""
    from . import common
    with common._LOCK:
        common._SHARING[0] += 1
    try:
        _check_drawing(d, sink, min_wall, deadline)
    finally:
        with common._LOCK:
            common._SHARING[0] -= 1
            if not common._SHARING[0]:
                common._SIGNED.clear()
                common._WITHIN.clear()


def _check_drawing(d: Drawing, sink: DiagnosticSink, given: float | None, deadline) -> None:
    shares = _Shares(deadline)
    tick = shares.tick
    run = shares.run
    roots = _part_roots(d)
    loops = {s: [np.asarray(p, dtype=float) for p in shape.to_polygons()]
             for s, shape in roots.items() if s.kind == "solid"}
    near = run("holes", None, lambda: _Near(roots, loops, d.cuts))
    explained: set = set()          # parts whose emptiness a warning already explains
    owner_areas: dict = {}          # a solid's final area, taken once for all its holes
    for cut in d.cuts:
        tick(cut.hole)
        if near is None:
            run("holes", cut.hole, lambda: None)
        elif run("holes", cut.hole, lambda: _check_hole(d, cut, roots, sink, near.local,
                                                         owner_areas,
                                                         lambda: tick(cut.hole))) == "W0503":
            explained.add(_part_of(cut.owner, roots))
    for s, shape in roots.items():
        if s.kind == "solid":
            tick(s)
            run("pieces", s, lambda: _check_pieces(d, s, shape, sink, loops[s]))
    for s in list(d.shapes):
        if s.kind == "solid":
            tick(s)
            run("invisible", s, lambda: _check_invisible(d, s, sink))
    tick(next(iter(roots), None))   # past the deadline: at the first part (E0304 located)
    run("engraving", None, lambda: check_text_near_cut(
        _check_engraving(d, roots, sink, loops, tick), roots, loops, sink, d.shapes))
    by_part: dict = {}
    for c in d.cuts:
        by_part.setdefault(_part_of(c.owner, roots), []).append(c)
    for s, shape in roots.items():
        if s.kind == "solid":
            tick(s)
            cuts = by_part.get(s, [])
            min_wall = part_min_wall(d, s, given)

            def openings():
                a = _analyse(d, s, shape, cuts, min_wall, loops[s],
                             tick=lambda ahead=0.0: tick(s, ahead))
                covered = _report_openings(a, s, min_wall, sink, d.shapes, d, shape)
                _check_flush(d, s, shape, a, cuts, min_wall, sink)
                _check_closed_openings(d, s, shape, cuts, min_wall, sink)
                check_open_mortises(d, s, shape, cuts, min_wall, sink)
                check_pattern_edges(d, s, cuts, min_wall, sink, set(CLOSED_OPENINGS))
                return covered
            covered = run("openings", s, openings)
            shared: dict = {}       # which loops are holes' openings, found once per part

            def voids():
                shared["cut_open"] = _cut_openings(loops[s], cuts)
                _check_voids(d, s, loops[s], cuts, min_wall, sink,
                             tick=lambda ahead=0.0: tick(s, ahead), cut_open=shared["cut_open"])
            run("voids", s, voids)
            tick(s)
            if min_wall > 0:
                run("walls", s, lambda: _check_walls(
                    d, s, shape, min_wall, cuts, sink, covered=covered or set(),
                    loops=loops[s], tick=lambda ahead=0.0: tick(s, ahead)))
                run("walls", s, lambda: _check_necks(d, s, shape, min_wall, cuts, sink,
                                                     tick=lambda ahead=0.0: tick(s, ahead)))
                run("slits", s, lambda: _check_slits(d, s, loops[s], cuts, min_wall, sink,
                                                     tick=lambda ahead=0.0: tick(s, ahead),
                                                     cut_open=shared.get("cut_open")))
                run("steps", s, lambda: _check_steps(d, s, loops[s], cuts, min_wall, sink,
                                                     tick=lambda: tick(s),
                                                     cut_open=shared.get("cut_open")))
    if getattr(d, "sheet_cuts", ()):
        tick(None)
        run("sheet cuts", None, lambda: check_sheet_cuts(
            d, roots, sink, tick=lambda ahead=0.0: tick(None, ahead)))
    if getattr(d, "through", ()):
        tick(None)
        run("through", None, lambda: check_through(
            d, roots, sink, lambda s: part_min_wall(d, s, given),
            tick=lambda ahead=0.0: tick(None, ahead)))
    tick(None)
    shares.guard("interpenetration", None,
                 lambda: _check_interpenetration(d, roots, sink, deadline))
    run("text", None, lambda: _check_text_overlap(d, sink, lambda: tick(None)))
    if getattr(d, "placement", None):
        tick(None)
        _check_fit(d, sink, deadline)
    if getattr(d, "sinks", None):
        run("sinks", None, lambda: check_sinks(d, sink, lambda: tick(None)))
    for s in list(d.shapes):
        # (both compare two faces of the hole: one of a single face, a loop's round hole,
        # has nothing to compare, 19,000 such holes looked at for nothing)
        if s.kind == "hole" and len(d.own.get(s, ())) > 1:
            t = part_min_wall(d, _part_of(s, roots), given)
            run("repeats", s, lambda: (
                _check_repeated_faces(d, s, sink, lambda: tick(s)),
                _check_overlapping_circles(d, s, sink, t if t > 0 else MIN_WALL,
                                           lambda: tick(s))))
    run("allowances", None, lambda: check_allowances(d, sink, lambda: tick(None)))
    run("kerf", None, lambda: check_kerf(d, sink, deadline))
    _check_zero_lines(d, sink)
    shares.notes(sink, given if given is not None else MIN_WALL)
    for g, *_ in getattr(d, "shape_errors", None) or ():
        explained.add(_part_of(getattr(g, "owner", g), roots))     # an E0406 says why the part is empty
    for s, g, area in empty_faces(d):
        part = _part_of(s, roots)
        explained.add(part)
        what = "cuts" if s.kind == "hole" else "adds"
        sink.warning("W0509", f"`{g.label}` closes a loop of zero area ({abs(area):.2g} mm^2) "
                     f"in {s.kind} `{s.path}`: it encloses nothing, so it {what} nothing",
                     g.span,
                     hint="a face needs an inside: give it a non-zero width, height or radius, "
                          "or points that are not all on one line (a line and its own mirror "
                          "image close a loop with nothing inside); delete it if it is not "
                          "needed")
    for g in d.open_curves:
        explained.add(_part_of(g.owner, roots))
        sink.warning("W0402", f"`{g.label}` is not part of a closed outline, so it is drawn as a "
                     "line (engraved), not filled", g.span,
                     hint="share endpoints between lines and arcs so they form a loop, or put "
                          "the curve in a `drawing` structure")
    _idle_min_wall(d, sink)
    _check_sheet(roots, sink)
    for s, shape in roots.items():
        if s.kind == "solid" and shape.is_empty() and s not in explained and any(
                not g.construction for n in s.subtree() for g in n.geometry):
            drawn = [n for n in s.children.values() if n.kind == "drawing"]
            only_drawn = drawn and not any(
                not g.construction for n in s.subtree() if not n.in_drawing()
                for g in n.geometry)
            # a solid holding only a drawing (run fo: the rings and names meant for a
            # template's base, in a solid of their own: "give it a closed shape" would have
            # made a part to carry them)
            name = drawn[0].name if drawn else ""
            sink.warning("W0509", f"solid `{s.path}` comes out empty: none of its geometry "
                         "encloses any area" + (f" (its shapes are in drawing `{name}`, "
                                                "which engraves and adds no material)"
                                                if only_drawn else ""), s.span,
                         hint=(f"to engrave `{name}` on a part, declare the drawing in that "
                               f"part; on a template's part, move `drawing {name}` out of "
                               f"`{s.name}` into the assembly and give it to the part: "
                               f"`CutInto({name}, PART)` (`{s.name}`, empty, then goes)")
                         if only_drawn else
                         "give the part a closed shape with an inside (a Rectangle, a "
                         "Circle, lines and arcs that close a loop around some area)")


def _check_sheet(roots: dict, sink) -> None:
    """W0534, a note, for each solid part too large for the sheet `aidl render --layout
    sheet` fills when told none (:data:`~..fabrication.layout.DEFAULT_SHEET`, with its gap),
    laid or turned (runs eg, ew: a 600 mm band and 600 mm arms checked clean; only the layout
    refused them)."""
    from ..fabrication.layout import DEFAULT_GAP, DEFAULT_SHEET, fits
    W, H = DEFAULT_SHEET
    for s, shape in roots.items():
        if s.kind != "solid" or shape.is_empty():
            continue
        x0, y0, x1, y1 = shape.bounds()
        w, h = x1 - x0, y1 - y0
        if fits(w, h):
            continue
        sink.add(Diagnostic("W0534", f"part `{s.path}` is {w:.1f} x {h:.1f} mm: it does not "
                            f"fit the {W:g} x {H:g} mm sheet that `aidl render --layout sheet` "
                            f"fills unless told another ({DEFAULT_GAP:g} mm from its edges), "
                            "laid or turned", s.span, "note",
                            hint=f"for a larger bed, give its size (`--layout sheet --sheet "
                                 f"1000x600mm`: this part needs at least "
                                 f"{math.ceil(max(w, h) + 2 * DEFAULT_GAP)} x "
                                 f"{math.ceil(min(w, h) + 2 * DEFAULT_GAP)} mm); for this one, "
                                 "make the part smaller or cut it in pieces that join"))
