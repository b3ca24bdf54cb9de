"""``Text(..., font=...)`` built (issue 112): the letters as the closed outlines of a font
(:mod:`.font`), held in the text's own frame and placed at the solved position point.

What a font Text keeps in ``g.data``: ``font`` (the :class:`~.font.Face`), ``text``, ``size``
(the cap height drawn, mm), ``fill`` (True: its area engraved), ``anchor``, ``valign``,
``rotation`` (radians), ``extent`` (the glyphs' true box about the position, turned: ``(x0,
x1, y0, y1)`` mm), and for a stencil ``bridge`` (mm).  :func:`local_loops` gives its exact loops about the position point, turned
(outer loops counter-clockwise; glyphs may overlap: the filled area is where the winding is
positive); :func:`bridges` the stencil's bridges over each counter.
"""
from __future__ import annotations

from . import font as F
from .curves import Line, Loop


def build_font_text(ctx, g, a, const) -> None:
    """The rest of ``Text``'s build when ``font=`` is given (``a["_font"]``: the face the
    interpreter found): max_width fitted by the font's advances and ink, a stencil's bridge,
    the extent; along= and weight= refused (:class:`~.font.FontError`, E0108 at the call)."""
    face = a["_font"]
    if a.get("weight") is not None:
        raise F.FontError("a Text in a font has the font's own stroke weight: weight= is "
                          "the single-stroke stencil's",
                          hint="choose a heavier style instead, e.g. `font=\"sans:Bold\"` "
                               "or `\"sans:Black\"`")
    g.data["font"] = face
    if a.get("fill"):
        g.data["fill"] = True        # a drawing engraves its area (style "fill")
    text, size = g.data["text"], g.data["size"]
    if not size > 0:
        raise F.FontError(f"a Text needs a positive size, got {size:g}")
    if a.get("max_width") is not None:
        m = const(ctx, a["max_width"], "max_width")
        if not m > 0:
            raise F.FontError(f"a Text's max_width is more than 0, got {m:g} mm")
        fit, wide = F.fit_size(face, text, size, m)
        g.data["max_width"] = m
        if fit < size:
            g.data["shrunk"] = (size, wide)
            g.data["size"] = size = fit
    if a.get("stencil"):
        b = a.get("bridge")
        g.data["bridge"] = size / 10 if b is None else const(ctx, b, "bridge")
        if not g.data["bridge"] > 0:
            raise F.FontError(f"a stencil Text's bridge is more than 0, got "
                                 f"{g.data['bridge']:g}")
        g.data["stencil"] = True
    g.data["extent"] = turned_extent(g)
    g.closed = True


def along_loops(g, r: float, angle: float, bands: bool = False) -> list[Loop]:
    """The loops of font Text ``g`` laid along a circle of radius ``r`` mm about its center
    (the loops relative to it), as the single-stroke font is laid
    (:func:`~.text.text_strokes_along`): clockwise, each glyph rigid and upright (its up away
    from the center; ``flip``: counter-clockwise, up toward it), its middle on the circle at
    the arc length of its middle in the straight text, the text's position point (anchor,
    valign) at ``angle`` (radians).  ``bands``: a stencil's bridges instead
    (:func:`bridges`), each laid with its glyph."""
    import math
    from .drawing2d import copied, moved
    d = g.data
    sh = F.shaped(d["font"], d["text"], d["size"])
    dx, dy = F.placement(sh, d["anchor"], d["valign"])
    sg = -1.0 if d.get("flip") else 1.0
    out: list[Loop] = []
    pen = 0.0
    for _, idx, adv in sh.glyphs:
        mid = pen + adv / 2 + dx
        t = angle - sg * mid / r
        tg = (sg * math.sin(t), -sg * math.cos(t))
        mine = _glyph_bands(sh.loops, idx, d["bridge"] / 2) if bands else \
            [sh.loops[i] for i in idx]
        if not mine:
            pen += adv
            continue
        here = [Loop(moved(lp.segments, dx - mid, dy)) for lp in mine]
        here = copied(here, [], math.atan2(tg[1], tg[0]))[0]
        out += [Loop(moved(lp.segments, r * math.cos(t), r * math.sin(t))) for lp in here]
        pen += adv
    return out


def turned_extent(g) -> tuple[float, float, float, float]:
    """``(x0, x1, y0, y1)``: the glyphs' true box of font Text ``g`` about its position at
    its own rotation (a turned or mirrored copy's too, mm); along a curve, about the curve's
    center at its starting radius and its angle (without one, the arc's middle)."""
    d = g.data
    if d.get("along") is None:
        return F.extent(d["font"], d["text"], d["size"], d["anchor"], d["valign"],
                        d.get("rotation", 0.0))
    bs = [sg.box() for lp in along_local(g) for sg in lp.segments]
    if not bs:
        return (0.0, 0.0, 0.0, 0.0)
    return (min(b[0] for b in bs), max(b[2] for b in bs), min(b[1] for b in bs),
            max(b[3] for b in bs))


def along_local(g) -> list[Loop]:
    """The loops of font Text ``g`` along its curve as built (:func:`along_loops` at its
    starting radius and its angle, else the arc's middle), relative to the curve's center:
    its extent's and its letters' boxes (W0504)."""
    d = g.data
    ang = d["angle"] if d.get("angle") is not None else d["start_angle"]
    return along_loops(g, d["radius0"], ang)


def local_loops(g) -> list[Loop]:
    """The exact loops of font Text ``g`` about its position point, turned by its rotation
    (mm)."""
    d = g.data
    loops = F.outlines(d["font"], d["text"], d["size"], d["anchor"], d["valign"])
    return _turned(loops, d.get("rotation", 0.0))


def _turned(loops, rot: float) -> list[Loop]:
    if not rot:
        return list(loops)
    from .drawing2d import copied
    return copied(loops, [], rot)[0]


def bridges(g) -> list[Loop]:
    """A stencil font Text's bridges about its position, turned: over each counter (a loop
    that winds negatively: the inside of an O, A, B, P, 0, 4, 6, 8, 9) a band ``bridge`` mm
    wide, upright through the counter's middle across its whole glyph, so that the counter
    stays joined to the plate above and below it (counter-clockwise rectangles)."""
    d = g.data
    loops = F.outlines(d["font"], d["text"], d["size"], d["anchor"], d["valign"])
    sh = F.shaped(d["font"], d["text"], d["size"])
    out = [b for _, idx, _ in sh.glyphs for b in _glyph_bands(loops, idx, d["bridge"] / 2)]
    return _turned(out, d.get("rotation", 0.0))


def _glyph_bands(loops, idx, h: float) -> list[Loop]:
    """The bridges of one glyph (its loops ``loops[i]`` for ``i`` in ``idx``): over each
    counter a band ``2 h`` mm wide, upright through its middle, from below the glyph to above
    it (counter-clockwise rectangles, in the loops' frame)."""
    mine = [loops[i] for i in idx]
    counters = [lp for lp in mine if lp.area < 0]
    if not counters:
        return []
    boxes = [s.box() for lp in mine for s in lp.segments]
    y0 = min(b[1] for b in boxes) - 2 * h
    y1 = max(b[3] for b in boxes) + 2 * h
    out = []
    for lp in counters:
        cb = [s.box() for s in lp.segments]
        cx = (min(b[0] for b in cb) + max(b[2] for b in cb)) / 2
        p = [(cx - h, y0), (cx + h, y0), (cx + h, y1), (cx - h, y1)]
        out.append(Loop([Line(p[i], p[(i + 1) % 4]) for i in range(4)]))
    return out


def counter_letters(g) -> list[str]:
    """The characters of a font Text whose glyphs have counters (loops that wind
    negatively), each once, in order: what falls out of a plate the text is cut from."""
    d = g.data
    sh = F.shaped(d["font"], d["text"], d["size"])
    out: list[str] = []
    for chars, idx, _ in sh.glyphs:
        if any(sh.loops[i].area < 0 for i in idx) and chars not in out:
            out.append(chars)
    return out
