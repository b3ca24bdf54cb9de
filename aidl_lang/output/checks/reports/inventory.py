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

import math

from ....geometry.shapes.curves import Arc, Circle, EllipticArc, Line
from ...fabrication.layout import part_box
from ...part.part import Output, OutputError, PartOutline

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
    return _same(_signature(a), _signature(b), tol)


def _signature(p: PartOutline) -> tuple:
    """``(area, perimeter, sorted segment measures)`` of ``p`` (mm^2, mm), each loop read once."""
    area = perimeter = 0.0
    for lp in p.loops:
        area += lp.area
        perimeter += lp.perimeter
    return area, perimeter, _measures(p)


def _same(sa: tuple, sb: tuple, tol: float) -> bool:
    if abs(sa[0] - sb[0]) > tol or abs(sa[1] - sb[1]) > tol:
        return False
    ma, mb = sa[2], sb[2]
    return len(ma) == len(mb) and all(
        x[0] == y[0] and abs(x[1] - y[1]) <= tol and abs(x[2] - y[2]) <= tol
        for x, y in zip(ma, mb))


CHECK_EVERY = 256        # parts (or exact comparisons) between two looks at the deadline


def shape_groups(parts: list[PartOutline], deadline=None, where=lambda p: None,
                 tol: float = SAME) -> list[int]:
    """The 0-based shape number of each of ``parts``, in order of first appearance: a part
    takes the number of the first earlier part that starts a shape (is not itself a copy)
    and has the same kind and the same shape (:func:`same_shape`), else a new one.

    Found by a key, not by comparing every pair (4,000 circles of different radii were 8
    million comparisons): the parts that start a shape are filed under their kind, the kinds
    of their sorted segments and their area and perimeter in cells of ``tol``; a part is
    compared exactly only with those in its own and the neighbouring cells (the only ones
    within ``tol`` in both), so the work is linear in the parts for shapes that differ by
    more than ``tol``.  ``deadline`` (:class:`~aidl_lang.base.limits.Deadline`) is looked at every
    :data:`CHECK_EVERY` parts and comparisons (raises
    :class:`~aidl_lang.base.limits.OutOfBudget` at ``where(part)``, its structure)."""
    import math
    starts: dict = {}                 # key -> [(shape number, signature)]
    group: list[int] = []
    n = looked = 0
    for i, p in enumerate(parts):
        if deadline is not None and i % CHECK_EVERY == 0:
            deadline.check("the parts list", where(p))
        sig = _signature(p)
        kinds = (p.kind, tuple(m[0] for m in sig[2]))
        ka, kp = math.floor(sig[0] / tol), math.floor(sig[1] / tol)
        best = None
        for da in (-1, 0, 1):
            for dp in (-1, 0, 1):
                for g, other in starts.get((kinds, ka + da, kp + dp), ()):
                    if best is not None and g > best:
                        continue
                    looked += 1
                    if deadline is not None and looked % CHECK_EVERY == 0:
                        deadline.check("the parts list", where(p))
                    if _same(other, sig, tol):
                        best = g
        if best is None:
            best = n
            n += 1
            starts.setdefault((kinds, ka, kp), []).append((best, sig))
        group.append(best)
    return group


def parts_list(output: Output, deadline=None) -> list[dict]:
    """One dict per part of ``output`` (lengths in mm, areas in mm²): ``path``, ``kind``,
    ``bbox`` [x0, y0, x1, y1], ``width``, ``height``, ``area``, ``perimeter``, ``thickness``
    (None when the program gives none), ``holes`` (hole loops), ``copies`` (parts of this
    shape, itself included) and ``shape`` (1-based number of its shape, in order of first
    appearance, :func:`shape_groups`).  ``deadline``: the compile's
    :class:`~aidl_lang.base.limits.Deadline` (None: no wall-time bound); raises
    :class:`~..part.part.OutputError` (its ``budget`` naming the part's structure) past it."""
    from collections import Counter
    parts = output.parts
    group = _groups(output, deadline)
    count = Counter(group)
    rows = []
    for i, p in enumerate(parts):
        x0, y0, x1, y1 = part_box(p)
        rows.append({"path": p.name, "kind": p.kind, "bbox": [x0, y0, x1, y1],
                     "width": x1 - x0, "height": y1 - y0, "area": abs(p.area),
                     "perimeter": p.perimeter, "thickness": p.thickness,
                     "holes": sum(1 for lp in p.loops if lp.is_hole),
                     "copies": count[group[i]], "shape": group[i] + 1})
        sunk = sinks_of(output, p.name)
        if sunk:
            rows[-1]["sinks"] = sunk
    return rows


def sinks_of(output: Output, part: str) -> list[dict]:
    """The countersinks and counterbores of part ``part`` (issue 102), one dict per hole:
    ``kind``, ``hole`` (the hole's Circle), ``center`` [x, y], ``hole_d``, ``diameter`` (the
    head's), ``depth`` (how deep the head goes), and a countersink's ``angle`` (deg); mm."""
    out = []
    for sk in getattr(output.drawing, "sinks", None) or ():
        if sk.part != part:
            continue
        d = {"kind": sk.kind, "hole": sk.hole, "center": list(sk.center),
             "hole_d": sk.hole_d, "diameter": sk.diameter, "depth": sk.cone_depth()}
        if sk.kind == "countersink":
            d["angle"] = math.degrees(sk.angle)
        out.append(d)
    return out


def sinks_text(rows: list[dict]) -> list[str]:
    """The parts' countersinks and counterbores in words, one line per part and kind, alike
    holes counted (``plate: 4 countersinks, 4.5 mm holes, 9 mm heads at 90 deg, 2.25 mm
    deep``)."""
    from collections import Counter
    lines = []
    for r in rows:
        seen = Counter((d["kind"], round(d["hole_d"], 6), round(d["diameter"], 6),
                        round(d.get("angle", 0.0), 6), round(d["depth"], 6))
                       for d in r.get("sinks", ()))
        for (kind, hd, dd, ang, depth), n in seen.items():
            how = f" at {ang:g} deg" if kind == "countersink" else ""
            lines.append(f"{r['path']}: {n} {kind}{'s' if n != 1 else ''}, {hd:g} mm "
                         f"hole{'s' if n != 1 else ''}, {dd:g} mm head{'s' if n != 1 else ''}"
                         f"{how}, {depth:.4g} mm deep")
    return lines


def _groups(output: Output, deadline) -> list[int]:
    """:func:`shape_groups` of ``output``'s parts, running out of time as an
    :class:`~..part.part.OutputError` (what a front end reading the output reports as a
    located ``E0304``)."""
    from ....base.limits import OutOfBudget
    try:
        return shape_groups(output.parts, deadline, lambda p: structure_of(output, p.name))
    except OutOfBudget as ex:
        raise OutputError(f"the parts list ran out of time: {ex.what}", ex) from None


def structure_of(output: Output, name: str):
    """The structure part ``name`` of ``output`` comes from (a piece a through-cut frees: its
    part's), or the drawing's first part structure with a place in the source; None without
    the booleans' result."""
    part_of = getattr(output.drawing, "part_of", None) or {}
    s = part_of.get(name)
    while s is None and "." in name:
        name = name.rsplit(".", 1)[0]
        s = part_of.get(name)
    if s is None:
        s = next((t for t in part_of.values() if getattr(t, "span", None) is not None), None)
    return s


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
    sunk = sinks_text(rows)
    if sunk:
        lines += ["countersinks and counterbores:", *(f"  {x}" for x in sunk)]
    return "\n".join(lines)
