"""The fit check of the assembled product, for a program that places its parts with
``Place`` (:func:`..assembly.fit` on the parts extruded by their thickness):

* ``W0517`` two parts whose solids collide (a slot narrower than its partner's thickness: the
  depth is by how much), unless ``AllowOverlap`` names them;
* ``W0518`` a part that touches no other (a tab short of its slot: the gap)."""
from __future__ import annotations

import math

from ...base.diagnostics import Diagnostic, DiagnosticSink, Label
from ...geometry.derived.corners import outline_shapes
from ..part.build.booleans import Drawing

# mm: a part with no Place this far or farther from every other part lies away from the
# product (drawn beside it on the sheet): W0518 for it is a note (run as: three cards laid
# `gap=5` apart were warned, their gaps 5 mm less a rounding, the fourth a note)
AWAY = 5.0
# mm: a collision this deep or deeper is a part misplaced, not a slot too narrow (runs av, aw:
# an arm sunk 6 mm into its back plate, a lip 6 mm into its ledge: "widen it" was first)
SLOT_SHORT = 1.0
CONTACT_DEPTH = 0.05     # mm: a common volume thinner than this is contact, under half a kerf


def _collision_hint(d: Drawing, c) -> str:
    """W0517's hint for collision ``c``: what follows from a joint that cut nothing (W0502
    said first: its tabs or slots are not there; run dk's end panels, their tab gaps run
    off the ends by a swapped `rotation=`), an edge pressed into a face (run dj), a slot too
    narrow, or a part misplaced; then the words that accept a meant overlap."""
    a, b = c.a.split(".")[-1], c.b.split(".")[-1]
    stray = [j for j in d.__dict__.get("stray_joints", ()) if j[0] in (c.a, c.b)]
    if stray:
        part, hole, what = stray[0]
        why = (f"this follows from W0502 above: {what} of `{hole}` cuts nothing, so `{part}` "
               "lacks those tabs or slots; turn or move that joint first (its `rotation=`), "
               "then check again")
    elif c.depth < SLOT_SHORT and c.into_face:
        why = (f"`{b}` runs {c.depth:.3g} mm into a face of `{a}` (an edge or a shoulder "
               "pressed into it, not a slot too narrow): move it that far off the face with "
               "its `Place`, or shorten it there")
    elif c.depth < SLOT_SHORT:
        why = (f"a slot or a gap is {c.depth:.3g} mm narrower than the part that goes in it: "
               "widen it to the partner's thickness (or make the material thinner), or move "
               "the part with its `Place`")
    elif (stack := _stacked(d, c)) is not None:
        why = stack
    else:
        why = (f"one part runs {c.depth:.3g} mm into the other, more than a slot is ever too "
               "narrow: move the part with its `Place` (its position or the sign of an "
               "offset), or widen the slot if it is one")
    # a whole-outline Fillet rounds the part's slots and tab roots too (runs gg, gn: tabs
    # hitting round slot ends, "move the part with its `Place`" pointed away from it)
    for name in (c.a, c.b):
        rounded = _whole_fillet(d.part_of.get(name))
        if rounded is not None:
            r, body = rounded
            why = (f"`{name.split('.')[-1]}` has `Fillet({r:g})` of its whole outline, "
                   f"which rounds its slots' and tabs' corners too (W0410 says where), so "
                   f"square tabs and slots no longer meet: round the outline's shapes "
                   f"alone, `Fillet({body}, {r:g})`; if that is not it: {why}")
            break
    # a part placed `on=` another: its turn is in that part's frame (run fw: ledges placed
    # `on=back` with the turns of the assembly's frame lay flat through the back)
    for name in (c.b, c.a):
        pl = getattr(d.part_of.get(name), "placement", None)
        if pl is not None and len(pl) > 3 and pl[3] is not None:
            why += (f"; `{name.split('.')[-1]}` is placed `on={pl[3].name}`: its position "
                    f"and its `face=`/`up=` (or `rotation=`) are in `{pl[3].name}`'s frame, "
                    f"turned with it")
            break
    # one of the two has no `Place` (run gw's hat rack: the backboard lay flat as drawn while
    # the pegs stood up through it; "move each peg 0.343 mm" hid it)
    loose = _unplaced(d, c)
    if loose is not None:
        u, other = loose
        t = d.thickness.get(u)
        why = (f"`{u.split('.')[-1]}` has no `Place`, so it lies as drawn, flat on the "
               f"x-y plane" + (f" (z 0 to {t:g} mm)" if t is not None else "")
               + f", while `{other.split('.')[-1]}` is placed: if it is to stand, give it "
               f"its `Place` (`face=\"front\"` stands it up facing -y); if it is meant to "
               f"lie so: {why}")
    return (f"{why}; if they are meant to share material (a press fit, an inlay), "
            f"`AllowOverlap({a}, {b})` in their assembly says so")


def _unplaced(d: Drawing, c) -> tuple | None:
    """(the part with no ``Place``, the other) of collision ``c`` when one of its two parts
    has a ``Place`` and the other none, else None."""
    has = [getattr(d.part_of.get(n), "placement", None) is not None for n in (c.a, c.b)]
    if has == [False, True]:
        return c.a, c.b
    if has == [True, False]:
        return c.b, c.a
    return None


def _whole_fillet(s) -> tuple | None:
    """(radius, the outline's shapes as a Fillet names them) of a ``Fillet(r)`` of part
    ``s``'s whole outline (no ``at``, r > 0) where the part has holes or cut-ins (a slot, a
    tab's gaps), else None."""
    if s is None:
        return None
    whole = [r for kind, r, at, _ in getattr(s, "finish", []) if kind == "Fillet"
             and at is None and r > 0]
    if not whole or not any(c.kind == "hole" for c in s.subtree() if c is not s):
        return None
    return whole[0], outline_shapes(s) or "SHAPE"


def _thickness_source(d: Drawing, name: str) -> str:
    """Where part ``name``'s thickness comes from, in words: its own `thickness` statement
    (or an enclosing structure's), else the file's."""
    s = d.part_of.get(name)
    for a in ([s, *s.ancestors()] if s is not None else []):
        if getattr(a, "thickness", None) is not None:
            own = a is s
            return (f"its own `thickness {a.thickness:g} mm`" if own else
                    f"`{a.name}`'s `thickness {a.thickness:g} mm`")
    t = d.thickness.get(name)
    return f"the file's `thickness {t:g} mm`" if t is not None else "the default thickness"


def _stacked(d: Drawing, c) -> str | None:
    """W0517's words for two plates lying flat one on the other that overlap through their
    thickness (run gg's shot ski: 3 mm halves placed at z = 3 on bases that took the file's
    `thickness 6 mm`; the hint "move the part or AllowOverlap" would have hidden it): which
    one is how thick and from where, and how far the upper one starts above the lower's
    bottom; None when the two are not parallel plates stacked."""
    import numpy as np
    M = getattr(d, "placement", None) or {}
    if c.a not in M or c.b not in M:
        return None
    na, nb = np.asarray(M[c.a])[:3, 2], np.asarray(M[c.b])[:3, 2]
    if np.linalg.norm(np.cross(na, nb)) > 1e-9:
        return None
    spans = {}
    for name, nz in ((c.a, na), (c.b, nb)):
        t = d.thickness.get(name)
        if t is None:
            return None
        o = float(np.asarray(M[name])[:3, 3] @ na)
        spans[name] = tuple(sorted((o, o + t * float(nz @ na))))
    (low, (l0, l1)), (up, (u0, u1)) = sorted(spans.items(), key=lambda kv: kv[1])
    if not (l0 < u0 < l1 < u1 + 1e-9) or abs((l1 - u0) - c.depth) > 1e-6 * max(1.0, c.depth):
        return None
    lo, hi = low.split(".")[-1], up.split(".")[-1]
    return (f"the two lie flat one on the other: `{lo}` is {l1 - l0:g} mm thick "
            f"({_thickness_source(d, low)}) and `{hi}` starts {u0 - l0:.6g} mm above its "
            f"bottom face, so {c.depth:.6g} mm of them are one: place `{hi}` "
            f"{c.depth:.6g} mm further from `{lo}` with its `Place` (or `on={lo}`, which "
            f"stands it on `{lo}`'s top face), or give `{lo}` the thickness meant "
            f"(`thickness {u0 - l0:.6g} mm` in it)")


def _check_fit(d: Drawing, sink: DiagnosticSink, deadline=None) -> None:
    """The fit check of the assembled product (:func:`.assembly.fit`, for a program that
    places its parts with ``Place``): W0517 for two parts whose solids collide (a slot
    narrower than its partner's thickness: the depth is by how much), W0518 for a part that
    touches no other (a tab short of its slot: the gap)."""
    from ..fabrication.assembly import Bodies, fit, normals_of, plates_of
    _check_bends(d, sink)
    parts = [(p.name, p.kind, p.shape, d.thickness.get(p.name)) for p in d.parts]
    bends = getattr(d, "bends", None)
    # what the check did (vertices, booleans, distances): a sweep's work (sweep_plan.work)
    d.fit_counts = {}
    bodies = Bodies(parts, d.placement, deadline=deadline, bends=bends)
    hits, gaps = fit(bodies, deadline, normals_of(d.placement),
                     plates_of(parts, d.placement, bends=bends), counts=d.fit_counts)

    def at(name):
        s = d.part_of.get(name)
        pl = getattr(s, "placement", None)
        return (pl[2] if pl is not None and pl[2] is not None else getattr(s, "span", None))
    from .parts import _allowed
    # the fit as data (the MCP tools' `fit`): what the warnings below say, AllowOverlap's
    # meant overlaps and the templates' designed gaps left out
    d.fit = {"checked": True, "collisions": [], "floating": []}
    from ...geometry.shapes.tessellate import CHORD_TOL
    pairs_of: dict = {}                  # (instance, instance) -> its collisions
    for c in hits:
        pair = _instances(d.part_of.get(c.a), d.part_of.get(c.b))
        if pair is not None:
            pairs_of[pair] = pairs_of.get(pair, 0) + 1
    together: dict = {}
    for c in hits:
        sa_, sb_ = d.part_of.get(c.a), d.part_of.get(c.b)
        if sa_ is not None and sb_ is not None and _allowed(sa_, sb_):
            continue                     # AllowOverlap(a, b): meant (a press fit, an inlay)
        if c.depth < CONTACT_DEPTH:
            continue                     # under half a kerf: parts in contact (run fa's rails
            #                              on a box's corner edge, 0.0017-0.04 mm: four W0517)
        x0, y0, z0, x1, y1, z1 = c.box
        sides = sorted((x1 - x0, y1 - y0, z1 - z0))
        if bends and (bends.get(c.a) or bends.get(c.b)) and (
                c.depth < CHORD_TOL or c.volume < CHORD_TOL * sides[1] * sides[2]):
            continue                     # a bent part's chords within their tolerance of a
            #                              part it wraps (run bv: a zoetrope's strip round its
            #                              disc, "0.00268 mm deep"; run cs: a mailbox's bent
            #                              roof on its arches, 0.0322 mm^3 over 160 x 79 mm,
            #                              "3 mm deep"): contact
        d.fit["collisions"].append({"a": c.a, "b": c.b, "volume": round(c.volume, 6),
                                    "depth": round(c.depth, 6),
                                    "box": [round(v, 6) for v in c.box]})
        pair = _instances(sa_, sb_)
        if pair is not None and pairs_of.get(pair, 0) > 1:
            together.setdefault(pair, []).append(c)
            continue                     # two template instances in one place: said once
        x0, y0, z0, x1, y1, z1 = c.box
        sa = at(c.a)
        loose = _unplaced(d, c)
        labels = [Label(sa, f"`{c.a}` has no `Place`: it lies as drawn" if loose is not None
                        and loose[0] == c.a else f"`{c.a}` is placed here", primary=False)] \
            if sa else []
        where = (f"in x {x0:.6g}..{x1:.6g}, y {y0:.6g}..{y1:.6g}, z {z0:.6g}..{z1:.6g} mm"
                 if not c.places else f"in {len(c.places)} places: " + "; ".join(
                     f"x {q[0]:.6g}..{q[3]:.6g}, y {q[1]:.6g}..{q[4]:.6g}, z {q[2]:.6g}.."
                     f"{q[5]:.6g}" for q in c.places[:4])
                 + (f"; and {len(c.places) - 4} more" if len(c.places) > 4 else "") + " mm")
        sink.warning("W0517", f"assembled, parts `{c.a}` and `{c.b}` collide: they share "
                     f"{c.volume:.3g} mm^3, {c.depth:.3g} mm deep, {where}", at(c.b) or sa,
                     labels=labels, hint=_collision_hint(d, c))
    _say_together(together, sink)
    _check_covered_text(d, bodies, sink)
    from ...base.diagnostics import in_stdlib

    def templates(name) -> bool:
        sp = at(name)
        return sp is not None and in_stdlib(sp.file)
    groups: dict = {}       # (statement, severity) -> [(gap, message, hint)]: a loop's copies once
    pins = _Pins(d)
    loose = _Loose(d, bodies)
    for g in gaps:
        if templates(g.part) and templates(g.nearest):
            continue            # a gap a stdlib template places by design (gear_train's lift=)
        d.fit["floating"].append({"part": g.part, "nearest": g.nearest, "gap": round(g.gap, 6)})
        unplaced = getattr(d.part_of.get(g.part), "placement", None) is None
        short = g.part.split(".")[-1]
        if not math.isfinite(g.gap):    # no solid of it was made (a mesh no manifold)
            said = ("warning", f"assembled, part `{g.part}` could not be made in 3D (its "
                    "solid came out empty), so the fit check and the 3D views leave it out",
                    "the parts are cut as drawn either way; report the program: this is a "
                    "fault of the 3D model, not of the part")
        elif unplaced and (g.gap >= AWAY - 1e-6 or getattr(
                d.part_of.get(g.nearest), "placement", None) is None):
            # a note: a part never placed, away from the product (runs z7, ai: "touches no
            # other part" read as a defect of the cut parts) or beside another never placed
            # (run bq: a game's 80 loose tokens laid 4 mm apart); one just short of a placed
            # part (a base 0.25 mm under its wall) stays a warning
            said = ("note", f"assembled, part `{g.part}` has no `Place` and touches no other "
                    f"part (the nearest, `{g.nearest}`, is {g.gap:.3g} mm away): it lies flat "
                    "where it is drawn",
                    f"the parts are cut as drawn either way; to put `{short}` in the "
                    f"assembled product (3D views, 3MF, the fit check), give it "
                    f"`Place({short}, ...)`")
        elif (pin := pins.through(g.part, g.nearest) or pins.through_any(g.part)) is not None:
            # a pivot: a round hole of it on one axis with another part's (run cn: a boom
            # with 0.6 mm of play each side of a dowel through it and its uprights; "move it
            # 0.6 mm" would have made it rub)
            other, d_mm = pin
            said = ("note", f"assembled, part `{g.part}` touches no other part (the nearest, "
                    f"`{g.nearest}`, is {g.gap:.3g} mm away): a round hole of it (d "
                    f"{d_mm:.3g} mm) lines up with one of `{other}`, so a pin, an axle or a "
                    "bolt through them holds it, the gap its play",
                    f"held by the pin: nothing is needed; if a tab of it should reach a slot, "
                    f"move `{short}` {g.gap:.3g} mm with its `Place`")
        elif (through := loose.in_opening(g.part, g.nearest)) or \
                loose.in_opening(g.nearest, g.part):
            # it stands in an opening of the part it comes nearest, or that part in one of
            # it (run ds: butter spreaders loose in 7 mm slots of a 5 mm stand, "move it
            # 0.58 mm" for the play; run dx: a cross-staff's transom on its staff)
            said = _in_opening(g, short, through, through and loose.drops(g.part, g.nearest))
        elif (inner := loose.enclosed(g.part, g.nearest)) or \
                loose.enclosed(g.nearest, g.part):
            what = f"it lies inside `{g.nearest}`" if inner else f"`{g.nearest}` lies inside it"
            said = ("note", f"assembled, part `{g.part}` touches no other part (the nearest, "
                    f"`{g.nearest}`, is {g.gap:.3g} mm away): {what} (a drawer in its "
                    "sleeve, a tray in its band), held there with that play",
                    f"sliding or sitting loose in it is as drawn: nothing is needed; for a "
                    f"snug fit, move `{short}` with its `Place` or make it larger by the play")
        elif g.gap >= AWAY - 1e-6:      # placed 5 mm or more from all: carried by what is not
            # cut (run bf: a wheel on a dowel axle, a sign on S-hooks; "a tab does not reach
            # its slot: move it 7 mm" would have made the wheel rub its stand)
            said = ("note", f"assembled, part `{g.part}` touches no other part (the nearest, "
                    f"`{g.nearest}`, is {g.gap:.3g} mm away): held by what is not cut (an "
                    "axle, hooks, hardware), or placed too far",
                    f"if a tab of it should reach a slot, move `{short}` {g.gap:.3g} mm with "
                    "its `Place`; held by hardware: nothing is needed")
        else:
            said = ("warning", f"assembled, part `{g.part}` touches no other part: the "
                    f"nearest, `{g.nearest}`, is {g.gap:.3g} mm away",
                    f"`{short}` has no `Place`: assembled, it lies flat where it is drawn; "
                    f"give it one, `Place({short}, ...)`, to put it in the product (the parts "
                    "are cut as drawn either way)" if unplaced else
                    f"move `{g.part}` {g.gap:.3g} mm towards `{g.nearest}` with its `Place` "
                    "(or, where a tab falls short of its slot, lengthen the tab)")
        span = at(g.part)           # (a part of no statement is said on its own)
        said = _with_origin(d, g, said, templates)
        groups.setdefault((span, said[0], g.part if span is None else ""), []).append(
            (g, *said[1:]))
    _say_floating(groups, sink)


def _in_opening(g, short: str, through: bool, drops: bool) -> tuple:
    """W0518's (severity, message, hint) for part ``g.part`` that stands in an opening of
    the part it comes nearest (``through``), or that part in one of it: a note, the opening
    holds it with that play; a warning where it fits through the opening seen from above,
    off the floor (``drops``: run gb's sit-and-reach pusher, 6 mm ply on edge in a 6.5 mm
    slot of the top with nothing under it, was "held with that play")."""
    if drops:
        return ("warning", f"assembled, part `{g.part}` touches no other part (the nearest, "
                f"`{g.nearest}`, is {g.gap:.3g} mm away): it passes through an opening of "
                f"`{g.nearest}` and fits through it whole seen from above, so nothing holds "
                f"it up: it drops through",
                f"rest it on something: a shoulder wider than the opening (a tab each side "
                f"that stands on `{g.nearest.split('.')[-1]}`), a part under it, or move "
                f"`{short}` with its `Place` onto one")
    what = (f"it passes through an opening of `{g.nearest}`, which holds it" if through
            else f"`{g.nearest}` passes through an opening of it, which holds it")
    return ("note", f"assembled, part `{g.part}` touches no other part (the nearest, "
            f"`{g.nearest}`, is {g.gap:.3g} mm away): {what} with that play",
            f"standing loose in the opening is as drawn: nothing is needed; for a snug fit, "
            f"narrow the opening by the play or move `{short}` with its `Place`")


def _with_origin(d: Drawing, g, said: tuple, templates) -> tuple:
    """W0518's ``said`` (severity, message, hint) with where the material of the floating
    part or its nearest lies from its own (0, 0), when far (:func:`_off_origin`; runs em, eo:
    a spacer drawn at (0, -40) in its own frame and placed at its origin hung 40 mm below its
    plate, and the note said to move the plate); a template's panels are so by design."""
    off = next(((n, o) for n in (g.part, g.nearest) if not templates(n)
                and (o := _off_origin(d, n))), None)
    if off is None:
        return said
    n, (ox, oy) = off
    return (said[0], said[1] + f"; `{n}`'s material lies ({ox:.1f}, {oy:.1f}) mm from its own "
            "(0, 0), the point its `Place` puts at `position=`",
            f"if `{n.split('.')[-1]}` was drawn where it stands beside the others, draw it "
            "about its own (0, 0) (or add that offset to its `Place`'s position); " + said[2])


def _say_floating(groups: dict, sink: DiagnosticSink) -> None:
    """W0518 once per statement and severity: the copies a loop makes are one statement (run
    bq: 80 W0518 for the tokens of a bingo board), the others named after it."""
    for (span, severity, _), rows in groups.items():
        g, message, hint = rows[0]
        if len(rows) > 1 and span is not None:
            names = ", ".join(f"`{r[0].part.split('.')[-1]}`" for r in rows[1:4])
            message += (f"; so do {len(rows) - 1} more part{'s' if len(rows) > 2 else ''} of "
                        f"this statement ({names}{', ...' if len(rows) > 4 else ''})")
        sink.add(Diagnostic("W0518", message, span, severity, hint=hint))


def _off_origin(d: Drawing, name: str):
    """``(dx, dy)`` mm from placed part ``name``'s own origin (its frame's (0, 0), which its
    `Place` puts at `position=`) to the centre of its material's box, when the origin lies
    outside that box by more than half the box's larger side; else None."""
    s = d.part_of.get(name)
    part = next((p for p in d.parts if p.name == name), None)
    origin = (getattr(d, "origins", None) or {}).get(name)          # on the sheet
    if getattr(s, "placement", None) is None or origin is None or part is None \
            or part.shape.is_empty():
        return None
    x0, y0, x1, y1 = part.shape.bounds()
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    out = max(x0 - origin[0], origin[0] - x1, y0 - origin[1], origin[1] - y1)
    if out <= max(x1 - x0, y1 - y0) / 2:
        return None
    return float(cx - origin[0]), float(cy - origin[1])


def check_routed_fit(d: Drawing, output, diameter: float, relief: str, sink: DiagnosticSink,
                     deadline=None) -> None:
    """The fit check of the assembled product as a router cuts it (``aidl render --machine``
    with a router profile, a program that places its parts): each part as the bit of
    ``diameter`` mm leaves it (:func:`~..fabrication.reliefs.routed_shape` of ``output``'s
    exact parts: inside corners rounded to the bit, less the profile's ``relief`` where it is
    cut, as in the G-code: :func:`~..fabrication.reliefs.plan` at the part's minimum wall), W0517 for
    each pair that collides so and not as drawn (the material the bit leaves in an inside
    corner where the partner's square corner must go)."""
    if not getattr(d, "placement", None) or not diameter:
        return
    from ..fabrication.assembly import Bodies, fit, normals_of, plates_of
    from ..fabrication.reliefs import routed_shape
    drawn = {(c["a"], c["b"]) for c in (getattr(d, "fit", None) or {}).get("collisions", ())}
    from .common import part_min_wall
    parts = [(p.name, p.kind,
              routed_shape(p, diameter / 2, relief, part_min_wall(d, d.part_of.get(p.name))),
              d.thickness.get(p.name)) for p in output.parts]
    hits, _ = fit(Bodies(parts, d.placement, deadline=deadline), deadline,
                  normals_of(d.placement), plates_of(parts, d.placement))
    from .parts import _allowed
    for c in hits:
        sa_, sb_ = d.part_of.get(c.a), d.part_of.get(c.b)
        if (c.a, c.b) in drawn or (c.b, c.a) in drawn or \
                (sa_ is not None and sb_ is not None and _allowed(sa_, sb_)):
            continue
        how = "with no relief" if relief == "none" else f"with {relief} reliefs"
        sp = getattr(d.part_of.get(c.b), "span", None) or getattr(sa_, "span", None)
        sink.warning("W0517", f"assembled as the router cuts them ({diameter:g} mm bit, {how}), "
                     f"parts `{c.a}` and `{c.b}` collide: they share {c.volume:.3g} mm^3, "
                     f"{c.depth:.3g} mm deep: the bit leaves material in the inside corners "
                     "where the partner's corners go", sp,
                     hint="set `relief = \"dogbone\"` (or `\"tbone\"`) in the machine "
                          "profile, or use a smaller bit (`tool_diameter`)")


def _check_bends(d: Drawing, sink: DiagnosticSink) -> None:
    """E0108 at a ``Bend`` whose zone on the sheet (``|angle| * (radius + thickness / 2)``
    wide, known once the part's thickness is) runs into the previous bend's of its part."""
    from ..part.build.sunk import DEFAULT_THICKNESS
    from ..part.build.placement import bend_zones
    for name, bends in (getattr(d, "bends", None) or {}).items():
        t = float(d.thickness.get(name) or DEFAULT_THICKNESS)
        s = d.part_of.get(name)
        spans = [b[3] for b in sorted(getattr(s, "bends", None) or [], key=lambda b: b[0])]
        zones = bend_zones(bends, t)
        for k in range(1, len(zones)):
            if zones[k][0] < zones[k - 1][1] - 1e-9:
                w0, w1 = zones[k - 1][1] - zones[k - 1][0], zones[k][1] - zones[k][0]
                sink.error("E0108", f"the bends of `{name}` overlap on the sheet: each takes "
                           f"|angle| * (radius + thickness / 2) of it, {w0:.4g} and {w1:.4g} mm "
                           f"here, centred {bends[k][0] - bends[k - 1][0]:.4g} mm apart",
                           spans[k] if k < len(spans) else None,
                           hint=f"set them at least {(w0 + w1) / 2:.4g} mm apart, or make "
                                "the radius or the angle smaller")


# mm: how near two round holes' axes must run, assembled, to take one pin (a dowel through a
# boom and its uprights' pivot holes lines up to the design's numbers; a hole 0.05 mm off its
# partner's axis is drawn so)
PIN_AXIS = 0.05
# mm: the largest hole a pin, an axle or a bolt goes through (an M24 bolt's clearance is 26 mm;
# two rings' 200 mm openings in line hold nothing: run bf's Ferris wheel); the larger of the two
# holes at most three times the other (a 608 bearing's 22 mm seat and its 8 mm shaft's hole)
PIN_MAX = 26.0
# mm: the farthest apart along the pin two of its holes stand (a dowel axle between a toy's
# frames; two holes in one plane are one place, not a pin)
PIN_SPAN = 150.0
# the most round holes of a part looked at as pins (each is one small boolean)
PIN_HOLES = 200


def _say_together(together: dict, sink: DiagnosticSink) -> None:
    """One W0517 for each two template instances whose parts collide because both stand
    where their templates put them (``together``: (instance, instance) -> collisions; run
    ax's two drawers, ten panels colliding)."""
    for (ia, ib), cs in together.items():
        vol = sum(c.volume for c in cs)
        short = ib.path.split(".")[-1]
        sink.warning("W0517", f"assembled, `{ia.path}` and `{ib.path}` (`{ia.template}` and "
                     f"`{ib.template}`) stand in one place: {len(cs)} of their parts collide "
                     f"({vol:.3g} mm^3 in all; the first, `{cs[0].a}` and `{cs[0].b}`)",
                     ib.span, labels=[Label(ia.span, f"`{ia.path}` is made here",
                                            primary=False)] if ia.span else [],
                     hint=f"a template's parts stand where its docs put them, and laying it "
                          "out on the sheet moves none in 3D: give one of them its place, "
                          f"`Place({short}, position=(x, y, z))` in their assembly")


def _instances(sa, sb):
    """``(instance, instance)``: the outermost standard-library template instances holding
    parts ``sa`` and ``sb`` when they are two, neither placed by its own ``Place`` nor
    below a placed one (their parts stand where the template puts them); else None."""
    from ...base.diagnostics import in_stdlib

    def outer(s):
        found = None
        while s is not None:
            if getattr(s, "template", None) and s.span is not None and \
                    not in_stdlib(s.span.file):
                found = s
            s = s.parent
        if found is None or any(getattr(a, "placement", None) is not None
                                for a in (found, *found.ancestors())):
            return None
        return found
    if sa is None or sb is None:
        return None
    ia, ib = outer(sa), outer(sb)
    if ia is None or ib is None or ia is ib:
        return None
    return (ia, ib) if ia.path < ib.path else (ib, ia)


class _Loose:
    """Whether a placed part passes through an opening of another (a slot, a window: the
    other's outline with its holes filled, extruded and placed, meets the part's solid,
    while the two solids touch nowhere): a part standing loose in its slot."""

    def __init__(self, d: Drawing, bodies):
        self.d, self.bodies = d, bodies
        self.index = {name: i for i, (name, _, _) in enumerate(bodies.parts)}
        self.filled: dict = {}          # part -> its outline, holes filled, placed (or None)

    def enclosed(self, name: str, other: str) -> bool:
        """Whether placed part ``name`` lies within the box of part ``other`` (both as placed,
        bent): inside it, as a drawer in its sleeve or a tray in a bent band (run fk: a
        matchbox's sleeve 0.18 mm clear of its drawer, "move it 0.182 mm")."""
        i, j = self.index.get(name), self.index.get(other)
        where = self.d.placement or {}
        if i is None or j is None or where.get(name) is None or where.get(other) is None:
            return False
        a, b = self.bodies.box(i), self.bodies.box(j)
        return all(b[k] <= a[k] + 1e-6 for k in range(3)) and \
            all(a[k] <= b[k] + 1e-6 for k in range(3, 6))

    def drops(self, name: str, other: str) -> bool:
        """Whether placed part ``name``, standing in an opening of ``other``, fits through
        it seen from above (+z, the assembled product's up): the two parts' shadows on the
        ground meet over less than :data:`VOLUME_IN` mm^2, so nothing of ``other`` is under
        it to hold it up, and it is not on the floor (the lowest of the parts' bottoms)."""
        i, j = self.index.get(name), self.index.get(other)
        if i is None or j is None or self.bodies.bends.get(name):
            return False
        floor = min(self.bodies.box(k)[2] for k in range(len(self.index)))
        if self.bodies.box(i)[2] <= floor + SLOT_SHORT:
            return False        # it stands on what the product stands on, or drops less than
            #                     1 mm onto it (run ds: spreaders through a stand's slots,
            #                     their rounded tips 0.005 mm over the table)
        a, b = self.bodies[i][1].project(), self.bodies[j][1].project()
        return (a ^ b).area() < VOLUME_IN

    def in_opening(self, name: str, other: str) -> bool:
        i = self.index.get(name)
        if i is None or (self.d.placement or {}).get(name) is None or self.bodies.bends.get(name):
            return False
        solid = self._filled(other)
        if solid is None:
            return False
        common = self.bodies[i][1] ^ solid
        return not common.is_empty() and common.volume() > VOLUME_IN

    def _filled(self, name: str):
        """Part ``name``'s outer outline, its openings filled, extruded and placed; None
        for a part not made or bent."""
        if name not in self.filled:
            import manifold3d as mf
            from ..fabrication.assembly import extrude
            from .common import _signed
            j = self.index.get(name)
            made = []
            if j is not None and not self.bodies.bends.get(name):
                _, shape, t = self.bodies.parts[j]
                outer = [p for p in shape.to_polygons() if _signed(p) > 0]
                if outer:
                    made = extrude([(name, "solid", mf.CrossSection(outer, mf.FillRule.Positive),
                                     t)], self.d.placement, self.bodies.thickness)
            self.filled[name] = made[0][1] if made else None
        return self.filled[name]


VOLUME_IN = 1e-3        # mm^3 of a part inside another's filled outline: it passes through


class _Pins:
    """The round holes of the parts of ``d`` on the assembled product's axes (the sheet's
    circles at most :data:`PIN_MAX` across with no material of the part whose box holds them
    a tenth in from their rim, placed by its ``Place``), found for a part when first asked:
    :meth:`through` says whether a hole of a part lines up with one of the part it comes
    nearest (a pivot, an axle: W0518 is then a note).  A part with more than
    :data:`PIN_HOLES` such circles in its box is not looked at (its W0518 stays a warning):
    the probes are one small boolean each."""

    def __init__(self, d: Drawing):
        import numpy as np
        self.d = d
        self.axes: dict = {}
        c = np.array(d.circles, dtype=float).reshape(-1, 3)
        self.circles = c[(c[:, 2] > 0) & (2 * c[:, 2] <= PIN_MAX)]

    def _holes(self, name: str):
        """Part ``name``'s round holes assembled: (centres n x 3, axis 3, diameters n)."""
        if name not in self.axes:
            import manifold3d as mf
            import numpy as np
            d = self.d
            part = next((p for p in d.parts if p.name == name), None)
            M = (d.placement or {}).get(name)
            out = None
            if part is not None and M is not None and not part.shape.is_empty():
                x0, y0, x1, y1 = part.shape.bounds()
                C = self.circles
                C = C[(C[:, 0] > x0) & (C[:, 0] < x1) & (C[:, 1] > y0) & (C[:, 1] < y1)]
                got = []
                for cx, cy, r in (C if len(C) <= PIN_HOLES else ()):
                    e = min(r / 8, 1e-3)  # no material a tenth in from its rim: a hole (the
                    #                            meshed circle's chords lie inside the rim)
                    probes = mf.CrossSection.compose([
                        mf.CrossSection.square((e, e)).translate(
                            (cx + 0.9 * r * u - e / 2, cy + 0.9 * r * v - e / 2))
                        for u, v in ((1, 0), (0, 1), (-1, 0), (0, -1))])
                    if (part.shape ^ probes).area() > 1e-12:
                        continue
                    # and material all round it just past its rim: a whole round hole, not
                    # the round end of a slot (run ef's racket press: its 100 x 18 carrying
                    # slot was "a round hole (d 18 mm)" lined up with the other frame's)
                    k = r + max(r / 20, 2 * e)
                    ring = mf.CrossSection.compose([
                        mf.CrossSection.square((e, e)).translate(
                            (cx + k * math.cos(a) - e / 2, cy + k * math.sin(a) - e / 2))
                        for a in (i * math.pi / 4 for i in range(8))])
                    if (part.shape ^ ring).area() >= ring.area() - 1e-12:
                        got.append((cx, cy, 2 * r))
                if got:
                    g = np.array(got, dtype=float)
                    M = np.asarray(M, dtype=float)
                    c = g[:, :2] @ M[:3, :2].T + M[:3, 3]
                    out = (c, M[:3, 2] / np.linalg.norm(M[:3, 2]), g[:, 2])
            self.axes[name] = out
        return self.axes[name]

    def through_any(self, name: str):
        """:meth:`through` against each other placed part, by name, the first that lines up
        (run eo's cuttlebone holder: its frame bolted to the cage bars, the ledge its nearest
        part, was "touches no other part" with a hint that would push it into the bars);
        None when none does."""
        for other in sorted(n for n in (self.d.placement or {}) if n != name):
            got = self.through(name, other)
            if got is not None:
                return got
        return None

    def through(self, name: str, nearest: str):
        """``(nearest, hole diameter mm)`` for a round hole of part ``name`` whose axis,
        assembled, runs within :data:`PIN_AXIS` of a round hole's of part ``nearest``, both
        axes parallel, in two planes at most :data:`PIN_SPAN` apart along it, the larger hole
        at most three times the other; else None."""
        import numpy as np
        mine, theirs = self._holes(name), self._holes(nearest)
        if mine is None or theirs is None:
            return None
        c, z, dia = mine
        if np.linalg.norm(np.cross(z, theirs[1])) > 1e-6:
            return None
        rel = theirs[0][None, :, :] - c[:, None, :]          # mine x theirs x 3
        off = rel - (rel @ z)[:, :, None] * z                # off the axis
        near = np.argwhere(np.linalg.norm(off, axis=2) <= PIN_AXIS)
        along = np.abs(rel @ z)
        for i, j in near:                   # a pin's holes: in two planes, alike enough
            a, b = float(dia[i]), float(theirs[2][j])
            if max(a, b) <= 3 * min(a, b) and 1e-3 < along[i, j] <= PIN_SPAN:
                return nearest, a
        return None


COVER_EPS = 0.2         # mm above the engraved face where a part lying on it is looked for
COVER_PROBES = 16       # points of a text's strokes looked at
COVER_SHARE = 0.125     # of them under another part (2 of 16): the text is covered


def _through(body, M, t: float) -> bool:
    """Whether solid ``body`` (placed, mm) reaches past both faces of the part placed by
    ``M`` (4x4) and ``t`` mm thick: it passes through that part (a cross-halving's other
    panel, a shelf through its side's mortise), held there by the joint, not a disc or a lid
    lying on it."""
    import numpy as np
    v = np.asarray(body.to_mesh().vert_properties, dtype=float)[:, :3]
    z = (v - np.asarray(M, dtype=float)[:3, 3]) @ np.asarray(M, dtype=float)[:3, 2]
    return bool(z.min() < -0.01 and z.max() > t + 0.01)


def _check_covered_text(d: Drawing, bodies, sink: DiagnosticSink) -> None:
    """W0532, a note, for the engraved texts of a placed, unbent part whose face (the one the
    laser engraves, z = the thickness) another part covers as placed, in whole or in part: at
    least :data:`COVER_SHARE` of :data:`COVER_PROBES` points of its strokes, lifted
    :data:`COVER_EPS` off the face, lie inside another part's solid (runs ei, em: a mirror's
    back engraved facing the ring glued on it; a greeting under the disc glued on top; the
    pictures showed it, no message did).  A note, one per pair of parts: in 228 corpus
    programs with `Place` and `Text`, 19 have such texts and most are meant (a volvelle's
    years under its turning disc, 77 of them; a pantograph's scales under its arms; labels
    under a lift-off lid).  Other marks are left alone: an outline engraved where a part is
    glued is a maker's guide."""
    import manifold3d as mf
    import numpy as np
    from ..part.build.sunk import DEFAULT_THICKNESS
    from .common import _part_of, _part_roots
    from .marks.engravings import _copy_label, _polyline
    where = getattr(d, "placement", None) or {}
    bends = getattr(d, "bends", None) or {}
    if not where or len(bodies) < 2:
        return
    roots = _part_roots(d)
    pts: dict = {}
    for style, item, g in d.strokes:
        if g is None or style == "cut" or g.kind != "Text":
            continue
        part = _part_of(g.owner, roots)
        if part is None or part.kind != "solid" or part.path not in where \
                or bends.get(part.path):
            continue
        P = _polyline(item)
        if len(P):
            pts.setdefault((g, part.path), []).append(np.asarray(P, dtype=float))
    covered: dict = {}              # (part, the part over it) -> [(text, points under, of)]
    for (g, name), runs in pts.items():
        P = np.concatenate(runs)
        P = P[np.linspace(0, len(P) - 1, min(COVER_PROBES, len(P))).astype(int)]
        t = float(d.thickness.get(name) or DEFAULT_THICKNESS)
        M = np.asarray(where[name], dtype=float)
        Q = np.column_stack([P, np.full(len(P), t + COVER_EPS)]) @ M[:3, :3].T + M[:3, 3]
        lo, hi = Q.min(axis=0) - 0.1, Q.max(axis=0) + 0.1
        e = 0.05
        probes = None
        for j in range(len(bodies)):
            other = bodies.name(j)
            if other == name:
                continue
            b = bodies.box(j)
            if (np.asarray(b[3:]) < lo).any() or (np.asarray(b[:3]) > hi).any():
                continue
            if probes is None:
                probes = mf.Manifold.batch_boolean(
                    [mf.Manifold.cube((e, e, e), True).translate(tuple(q)) for q in Q],
                    mf.OpType.Add)
            n = int(round((probes ^ bodies[j][1]).volume() / (e ** 3)))   # probes inside
            if n >= math.ceil(COVER_SHARE * len(Q) - 1e-9):
                covered.setdefault((name, other), []).append(
                    (g, n, len(Q), _through(bodies[j][1], M, t)))
                break
    from .marks.allowed import meant_off
    for (name, other), rows in covered.items():
        sb = d.part_of.get(other)
        # AllowOverlap(the text's drawing, the part over it): meant (run gc's mould box: the
        # size under the slot in use, read before the wall goes in)
        rows = [r for r in rows if sb is None or not meant_off(r[0], sb)]
        if not rows:
            continue
        g, n, m, fixed = rows[0]
        short, cover = name.split(".")[-1], other.split(".")[-1]
        owner = g.owner.path
        drawn = owner[len(name) - len(short):] if owner.startswith(name) else short
        what = (f"the engraved text `{_copy_label(g)}` (\"{g.data.get('text', '')}\") of "
                f"`{name}` lies under `{other}` as placed ({n} of {m} points of its letters)"
                if len(rows) == 1 else
                f"{len(rows)} engraved texts of `{name}` lie under `{other}` as placed "
                f"(`{_copy_label(g)}`, \"{g.data.get('text', '')}\", and "
                + ", ".join(f"`{_copy_label(r[0], short=True)}`" for r in rows[1:4])
                + (", ..." if len(rows) > 4 else "") + ")")
        it = "it" if len(rows) == 1 else "they"
        if fixed:               # through it: a joint holds it, nothing moves off
            sink.add(Diagnostic(
                "W0532", f"assembled, {what}: `{cover}` passes through `{short}` there (a "
                f"joint holds it), so {it} cannot be seen", g.span, "warning",
                hint="the laser engraves the face that is up on the sheet: move the text "
                     f"clear of `{cover}` (beside the joint), or turn `{short}` with its "
                     "`Place` (`face=`, `up=`) so that face looks out (the text mirrored, "
                     "`Mirrored`, if it must read from the other side); if it is meant (a "
                     f"label read before `{cover}` goes in), `AllowOverlap({drawn}, {cover})` "
                     "in their assembly says so"))
            continue
        sink.add(Diagnostic(
            "W0532", f"assembled, {what}: {'it shows' if len(rows) == 1 else 'they show'} "
            f"only where `{cover}` moves off (a dial's window, a lid); fixed there, "
            f"{it} cannot be seen", g.span, "note",
            hint=f"if `{cover}` turns, slides or lifts off, nothing is needed; if it is fixed "
                 "there: the laser engraves the face that is up on the sheet, so turn "
                 f"`{short}` with its `Place` (`face=`, `up=`) so that face looks out (the "
                 "text mirrored, `Mirrored`, if it must read from the other side), or move "
                 f"the text clear of `{cover}`"))
