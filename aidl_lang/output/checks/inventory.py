"""The parts list of an output (``aidl parts``): for each part its path in the structure tree,
exact bounding box, area, perimeter, thickness, number of holes and how many parts share its
shape.

Two parts have the same shape (are copies) when a rigid motion could take one onto the other,
as far as these measures tell: their areas and perimeters agree within :data:`SAME` (mm², mm)
and so do their sorted segment measures (each line's length, each arc's radius and length,
each circle's radius).  A mirror image has the same measures, so it counts as a copy too (a
laser-cut part can be turned over, though its engraving would then be mirrored).
"""
from __future__ import annotations

from ...geometry.curves import Arc, Circle, EllipticArc, Line
from ..fabrication.layout import part_box
from ..part.part import Output, PartOutline

SAME = 1e-6


def _measures(p: PartOutline) -> list[tuple]:
    out = []
    for lp in p.loops:
        for s in lp.segments:
            if isinstance(s, Line):
                out.append((0, s.length, 0.0))
            elif isinstance(s, Arc):
                out.append((1, s.radius, s.length))
            elif isinstance(s, Circle):
                out.append((2, s.radius, s.length))
            elif isinstance(s, EllipticArc):
                out.append((4, s.curve.rx, s.length))
            else:                                   # a spline piece
                out.append((3, s.length, s.area_term))
    return sorted(out)


def same_shape(a: PartOutline, b: PartOutline, tol: float = SAME) -> bool:
    """True when ``a`` and ``b`` have the same area, perimeter and sorted segment measures
    within ``tol``."""
    if abs(a.area - b.area) > tol or abs(a.perimeter - b.perimeter) > tol:
        return False
    ma, mb = _measures(a), _measures(b)
    return len(ma) == len(mb) and all(
        x[0] == y[0] and abs(x[1] - y[1]) <= tol and abs(x[2] - y[2]) <= tol
        for x, y in zip(ma, mb))


def parts_list(output: Output) -> list[dict]:
    """One dict per part of ``output`` (lengths in mm, areas in mm²): ``path``, ``kind``,
    ``bbox`` [x0, y0, x1, y1], ``width``, ``height``, ``area``, ``perimeter``, ``thickness``
    (None when the program gives none), ``holes`` (hole loops), ``copies`` (parts of this
    shape, itself included) and ``shape`` (1-based number of its shape, in order of first
    appearance)."""
    parts = output.parts
    group = [-1] * len(parts)
    n = 0
    for i, p in enumerate(parts):
        if group[i] >= 0:
            continue
        group[i] = n
        for j in range(i + 1, len(parts)):
            if group[j] < 0 and parts[j].kind == p.kind and same_shape(p, parts[j]):
                group[j] = n
        n += 1
    rows = []
    for i, p in enumerate(parts):
        x0, y0, x1, y1 = part_box(p)
        rows.append({"path": p.name, "kind": p.kind, "bbox": [x0, y0, x1, y1],
                     "width": x1 - x0, "height": y1 - y0, "area": abs(p.area),
                     "perimeter": p.perimeter, "thickness": p.thickness,
                     "holes": sum(1 for lp in p.loops if lp.is_hole),
                     "copies": group.count(group[i]), "shape": group[i] + 1})
    return rows


def parts_text(rows: list[dict]) -> str:
    """The parts list as an aligned text table (mm, mm²)."""
    head = ("part", "shape", "copies", "width mm", "height mm", "area mm²", "holes",
            "thickness mm")
    body = [(r["path"] + (" (hole)" if r["kind"] == "hole" else ""), str(r["shape"]),
             str(r["copies"]), f"{r['width']:.3f}", f"{r['height']:.3f}", f"{r['area']:.3f}",
             str(r["holes"]), "-" if r["thickness"] is None else f"{r['thickness']:g}")
            for r in rows]
    w = [max(len(x) for x in col) for col in zip(head, *body)]
    lines = []
    for k, row in enumerate([head, *body]):
        lines.append("  ".join(c.ljust(w[i]) if i == 0 else c.rjust(w[i])
                               for i, c in enumerate(row)).rstrip())
    shapes = len({r["shape"] for r in rows})
    lines.append(f"{len(rows)} part{'s' if len(rows) != 1 else ''}, {shapes} "
                 f"shape{'s' if shapes != 1 else ''}")
    return "\n".join(lines)
