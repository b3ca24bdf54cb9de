"""Checks of through-cuts (a ``cut`` structure's open curves, :class:`~..part.booleans.Through`):

* ``W0522`` a through-cut that cuts nothing: no stretch of it lies on the material of its
  part (it is drawn off the part, or in a hole), or it has no length, or it lies along the
  part's outline (or a hole's) from end to end: the outline is cut anyway, so it adds nothing
  (the outputs leave it out: that line is cut once);
* ``W0507`` a web thinner than the minimum wall that the through-cuts leave: the morphological
  opening (:func:`.walls._thin`) of the part with every through-cut's band taken out
  (:attr:`~..part.booleans.Drawing.slit_shapes`) removes more than the opening of the part itself;
  each extra piece of at least ``2 t^2`` mm^2 (the wall check's least) is one warning naming
  the cuts beside it.  The bands are 5e-7 mm wide, so a web's width is measured as between
  the cut lines themselves.
"""
from __future__ import annotations

import manifold3d as mf

from ...diagnostics import DiagnosticSink
from ..part.booleans import SLIT_HALF, Drawing
from .walls import _thin

OFF = 1e-3      # of the band's own area: a through-cut with less of it inside cuts nothing


def check_through(d: Drawing, roots: dict, sink: DiagnosticSink, min_wall_of,
                  tick=lambda ahead=0.0: None) -> None:
    """W0522 and W0507 (the module docstring) for the through-cuts of ``d``; ``roots``: part
    structure -> its final shape (:func:`.common._part_roots`); ``min_wall_of(s)``: the
    minimum wall of part ``s`` in mm (0: not checked)."""
    for th in getattr(d, "through", ()):
        tick()
        band = th.band.area()
        g = th.geometry
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
    for name, (whole, slit) in (getattr(d, "slit_shapes", None) or {}).items():
        s = d.part_of.get(name)
        if s is None or s not in roots:
            continue
        t = min_wall_of(s)
        if t <= 0 or slit.is_empty():
            continue
        tick()
        least = 2 * t * t
        cuts = [th for th in d.through if th.part is s]
        with_cuts = _union(_thin(slit, t, tick=tick, least=least))
        if with_cuts.is_empty():
            continue
        # what the opening removes anyway (corners, the part's own thin walls: W0507 already)
        before = _union(_thin(whole, t, tick=tick))
        extra = with_cuts - before
        for piece in extra.decompose():
            if piece.area() < least * (1 - 1e-9):
                continue
            tick()
            near = piece.offset(t, mf.JoinType.Round, 2.0, 16)
            by = [th.geometry for th in cuts if (near ^ th.band).area() > 0]
            names = " and ".join(f"`{g.label}`" for g in by[:2]) + (
                f" (and {len(by) - 2} more)" if len(by) > 2 else "")
            x0, y0, x1, y1 = piece.bounds()
            span = by[0].span if by and by[0].span is not None else s.span
            where = f"beside through-cut{'s' if len(by) > 1 else ''} {names} " if by else ""
            sink.warning(
                "W0507", f"a web of `{s.path}` {where}near ({(x0 + x1) / 2:.2f}, "
                f"{(y0 + y1) / 2:.2f}) is thinner than {t:g} mm: the laser leaves a strip "
                f"too weak to hold (or burns it away)", span,
                hint=f"space the cuts at least {t:g} mm apart and from the outline; if the "
                     f"design means this, say so: `min_wall 0` in `{s.path}` or a smaller "
                     "`min_wall`")


def _union(parts: list):
    parts = [p for p in parts if not p.is_empty()]
    if not parts:
        return mf.CrossSection()
    return mf.CrossSection.batch_boolean(parts, mf.OpType.Add)


__all__ = ["check_through", "SLIT_HALF"]
