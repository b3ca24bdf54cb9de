"""SVG writer (``svgwrite``) for a :class:`~aidl_lang.output.booleans.Drawing`.

y points up in the model and is flipped for the page; the viewBox fits the model with a margin;
width and height are in mm.
"""
from __future__ import annotations

import numpy as np

from .booleans import Drawing


STYLES = {
    "solid": dict(fill="#cfd8dc", stroke="#263238"),
    "hole_part": dict(fill="none", stroke="#c62828"),
    "hole": dict(fill="none", stroke="#c62828"),
    "drawing": dict(fill="none", stroke="#1565c0"),
    "open": dict(fill="none", stroke="#ef6c00"),
}


def to_svg(drawing: Drawing, title: str = "") -> str:
    import svgwrite
    x0, y0, x1, y1 = drawing.bounds()
    w, h = max(x1 - x0, 1e-3), max(y1 - y0, 1e-3)
    margin = max(0.05 * max(w, h), 1.0)
    vx, vy = x0 - margin, -(y1 + margin)
    vw, vh = w + 2 * margin, h + 2 * margin
    sw = max(vw, vh) / 500.0
    # debug=False: no per-attribute validation (2-3x faster, same text; the live preview
    # redraws on every slider move)
    d = svgwrite.Drawing(size=(f"{vw:.3f}mm", f"{vh:.3f}mm"), profile="full", debug=False)
    d.viewbox(vx, vy, vw, vh)
    if title:
        d.set_desc(title=title)
    g_solid = d.g(id="solids", fill=STYLES["solid"]["fill"], stroke=STYLES["solid"]["stroke"],
                  stroke_width=sw, fill_rule="evenodd")
    for p in drawing.parts:
        if p.shape.is_empty():
            continue
        path = " ".join(_path(np.asarray(poly)) for poly in p.shape.to_polygons())
        if p.kind == "solid":
            g_solid.add(d.path(d=path, id=_id(p.name)))
        else:
            g_solid.add(d.path(d=path, fill="none", stroke=STYLES["hole"]["stroke"],
                               stroke_dasharray=f"{4 * sw},{2 * sw}", id=_id(p.name)))
    d.add(g_solid)
    if drawing.hole_outlines:
        gh = d.g(id="holes", fill="none", stroke=STYLES["hole"]["stroke"], stroke_width=sw * 0.8,
                 stroke_dasharray=f"{4 * sw},{2 * sw}")
        for pl in drawing.hole_outlines:
            gh.add(d.path(d=_path(pl)))
        d.add(gh)
    if drawing.lines:
        gd = d.g(id="drawings", fill="none", stroke_width=sw, stroke_linecap="round",
                 stroke_linejoin="round")
        for style, pl in drawing.lines:
            gd.add(d.path(d=_path(pl, close=False), stroke=STYLES[style]["stroke"]))
        d.add(gd)
    return d.tostring()


def _id(name: str) -> str:
    return "part-" + "".join(c if c.isalnum() or c in "-_" else "_" for c in name)


def _path(pl: np.ndarray, close: bool = True) -> str:
    if len(pl) == 0:
        return ""
    pts = " ".join(f"{x:.4f},{-y:.4f}" for x, y in pl)
    return f"M{pts}" + ("Z" if close else "")
