"""The fit check of the assembled product, for a program that places its parts with
``Place`` (:func:`..assembly.fit` on the parts extruded by their thickness):

* ``W0517`` two parts whose solids collide (a slot narrower than its partner's thickness: the
  depth is by how much), unless ``AllowOverlap`` names them;
* ``W0518`` a part that touches no other (a tab short of its slot: the gap)."""
from __future__ import annotations

from ...diagnostics import DiagnosticSink, Label
from ..part.booleans import Drawing

def _check_fit(d: Drawing, sink: DiagnosticSink, deadline=None) -> None:
    """The fit check of the assembled product (:func:`.assembly.fit`, for a program that
    places its parts with ``Place``): W0517 for two parts whose solids collide (a slot
    narrower than its partner's thickness: the depth is by how much), W0518 for a part that
    touches no other (a tab short of its slot: the gap)."""
    from ..fabrication.assembly import extrude, fit, normals_of, plates_of
    parts = [(p.name, p.kind, p.shape, d.thickness.get(p.name)) for p in d.parts]
    hits, gaps = fit(extrude(parts, d.placement, deadline=deadline), deadline,
                     normals_of(d.placement), plates_of(parts, d.placement))

    def at(name):
        s = d.part_of.get(name)
        pl = getattr(s, "placement", None)
        return (pl[2] if pl is not None and pl[2] is not None else getattr(s, "span", None))
    from .parts import _allowed
    # the fit as data (the MCP tools' `fit`): what the warnings below say, AllowOverlap's
    # meant overlaps and the templates' designed gaps left out
    d.fit = {"checked": True, "collisions": [], "floating": []}
    for c in hits:
        sa_, sb_ = d.part_of.get(c.a), d.part_of.get(c.b)
        if sa_ is not None and sb_ is not None and _allowed(sa_, sb_):
            continue                     # AllowOverlap(a, b): meant (a press fit, an inlay)
        d.fit["collisions"].append({"a": c.a, "b": c.b, "volume": round(c.volume, 6),
                                    "depth": round(c.depth, 6),
                                    "box": [round(v, 6) for v in c.box]})
        x0, y0, z0, x1, y1, z1 = c.box
        sa = at(c.a)
        labels = [Label(sa, f"`{c.a}` is placed here", primary=False)] if sa else []
        sink.warning("W0517", f"assembled, parts `{c.a}` and `{c.b}` collide: they share "
                     f"{c.volume:.3g} mm^3, {c.depth:.3g} mm deep, in x {x0:.6g}..{x1:.6g}, "
                     f"y {y0:.6g}..{y1:.6g}, z {z0:.6g}..{z1:.6g} mm", at(c.b) or sa,
                     labels=labels,
                     hint=f"a slot or a gap is {c.depth:.3g} mm narrower than the part that "
                          "goes in it: widen it to the partner's thickness (or make the "
                          "material thinner), or move the part with its `Place`; if they are "
                          f"meant to share material (a press fit, an inlay), "
                          f"`AllowOverlap({c.a.split('.')[-1]}, {c.b.split('.')[-1]})` in their "
                          "assembly says so")
    from ...diagnostics import in_stdlib

    def templates(name) -> bool:
        sp = at(name)
        return sp is not None and in_stdlib(sp.file)
    for g in gaps:
        if templates(g.part) and templates(g.nearest):
            continue            # a gap a stdlib template places by design (gear_train's lift=)
        d.fit["floating"].append({"part": g.part, "nearest": g.nearest, "gap": round(g.gap, 6)})
        sink.warning("W0518", f"assembled, part `{g.part}` touches no other part: the nearest, "
                     f"`{g.nearest}`, is {g.gap:.3g} mm away", at(g.part),
                     hint=f"a tab does not reach its slot: move `{g.part}` {g.gap:.3g} mm "
                          "with its `Place`, or lengthen the tab")
