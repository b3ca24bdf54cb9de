"""What a :class:`~.result.Result` reports in: :class:`Value` (a solved value, named, in the
file's units), :class:`PartInfo`, :class:`Layout`; the file's units (:func:`file_units`), exact
boxes (:func:`exact_bbox`), and the walk over a solved model that names its values
(:func:`_values`).  Imports the stages below the API only.
"""
from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Literal


@dataclass(frozen=True)
class Value:
    """One solved value of a named entity.

    ``name``: the dotted path (``plate.corner[0].h.center``); ``kind``: ``point`` (``value`` is
    ``(x, y)``), ``length`` or ``angle`` or ``number`` (a float), ``box`` (``(left, bottom,
    right, top)``); ``unit``: the unit of ``value`` (the file's length unit, ``deg`` for
    angles, ``""`` for plain numbers).  ``mm`` holds the same value in millimetres (or radians
    for an angle): what the solver and the writers use."""

    name: str
    kind: Literal["point", "length", "angle", "number", "box"]
    value: float | tuple[float, ...]
    unit: str
    mm: float | tuple[float, ...]

    def text(self, digits: int = 3) -> str:
        """``name = value unit``, e.g. ``plate.bore.c.center = (-25.000, -15.000) mm``."""
        if isinstance(self.value, tuple):
            v = "(" + ", ".join(f"{c:.{digits}f}" for c in self.value) + ")"
        else:
            v = f"{self.value:.{digits}f}"
        return f"{self.name} = {v}" + (f" {self.unit}" if self.unit else "")

    def to_json(self) -> dict:
        """``{"name", "kind", "value", "unit", "mm"}``; tuples as lists."""
        def j(v):
            return list(v) if isinstance(v, tuple) else v
        return {"name": self.name, "kind": self.kind, "value": j(self.value), "unit": self.unit,
                "mm": j(self.mm)}


@dataclass(frozen=True)
class PartInfo:
    """One part of the final shape (after the booleans), in millimetres.

    ``name``: the structure's path; ``kind``: ``solid`` (or ``hole`` for a hole with no solid to
    cut); ``bbox``: ``(x0, y0, x1, y1)``; ``area``: mm² (holes subtracted); ``holes``: the
    number of inner loops (holes through the part); ``loops``: every loop (outer and inner)."""

    name: str
    kind: str
    bbox: tuple[float, float, float, float]
    area: float
    holes: int
    loops: int

    def to_json(self) -> dict:
        return {"name": self.name, "kind": self.kind, "bbox": list(self.bbox),
                "area": self.area, "holes": self.holes, "loops": self.loops}


class Layout:
    """A cutting layout (:meth:`Result.layout`, ``aidl render --layout sheet``): every solid
    part placed once, flat, without overlap, on sheets of ``size`` = (width, height) mm, one
    material thickness per sheet.

    ``sheets``: the number of sheets; ``parts``: the number of parts placed; ``dropped``: the
    engraving strokes outside every part, left out; ``text``: ``laid out 6 parts on 2 sheets
    of 200 x 150 mm``; ``where``: one dict part name -> turn in degrees per sheet.
    :meth:`encode` gives each sheet's file, :meth:`placements` where each part went."""

    def __init__(self, cut: list, solid: list, size: tuple[float, float], dropped: int,
                 where: list | None = None) -> None:
        self._cut, self._solid = cut, solid
        self.size = (float(size[0]), float(size[1]))
        self.sheets = len(cut)
        self.parts = sum(len(s.parts) for s in cut)
        self.dropped = dropped
        self.where = [{name: float(m.deg) for name, m in moves.items()}
                      for moves in (where or [])]

    def placements(self) -> list[dict]:
        """Where each part went: ``[{"part", "sheet" (1-based), "rotation" (degrees),
        "bbox" [x0, y0, x1, y1] mm on the sheet (as designed, before the kerf)}]``, and
        each sheet's use: :meth:`use`."""
        out = []
        for j, sheet in enumerate(self._solid):
            turns = self.where[j] if j < len(self.where) else {}
            for p in sheet.parts:
                box = exact_bbox(seg for lp in p.loops for seg in lp.segments)
                out.append({"part": p.name, "sheet": j + 1,
                            "rotation": turns.get(p.name, 0.0),
                            "bbox": [round(float(v), 6) for v in box]})
        return out

    def overlaps(self) -> list[dict]:
        """The parts that lie over each other on the sheets as placed, flat (2D, their true
        outlines as designed: :func:`overlapping`): ``[{"a", "b", "sheet" (1-based),
        "area" mm², "box" [x0, y0, x1, y1] mm on the sheet}]``; ``[]`` when none do (the
        nesting keeps them apart: this checks it).  Not :attr:`Result.fit`, the assembled
        product's 3D collisions."""
        return [dict(o, sheet=j + 1) for j, sheet in enumerate(self._solid)
                for o in overlapping(sheet.parts)]

    def use(self) -> list[float]:
        """Each sheet's use: the parts' area (holes subtracted) over the sheet's, 0 to 1."""
        whole = self.size[0] * self.size[1]
        return [round(sum(float(p.area) for p in s.parts) / whole, 4) for s in self._solid]

    @property
    def text(self) -> str:
        return (f"laid out {self.parts} parts on {self.sheets} "
                f"sheet{'s' if self.sheets != 1 else ''} of {self.size[0]:g} x {self.size[1]:g} mm")

    def encode(self, fmt: str, **options) -> list[bytes]:
        """Every sheet in format ``fmt`` (as :meth:`Result.encode`), one item per sheet: SVG,
        DXF and PNG the cuts as laid out (offset by half the kerf the layout was made with),
        STL, 3MF, STEP and GLB the designed parts placed as on the sheet.  ``options``: those
        of :meth:`Result.encode` but ``assembled``.  Raises :class:`ValueError` for an unknown
        format, :class:`~aidl_lang.output.part.part.MissingDependency` and
        :class:`~aidl_lang.output.part.part.OutputError`."""
        from ..output import CUT_FORMATS, FORMATS, Options, encode
        suffix = "." + fmt.lower().lstrip(".")
        if suffix not in FORMATS:
            raise ValueError(f"unknown output format `{fmt}`; use one of "
                             + ", ".join(sorted(f[1:] for f in FORMATS)))
        sheets = self._cut if suffix in CUT_FORMATS else self._solid
        return [encode(s, suffix, Options(**options)) for s in sheets]

    def __repr__(self) -> str:
        return f"<aidl Layout {self.text}>"


def overlapping(parts) -> list[dict]:
    """The solid ``parts`` (of an output) that lie over each other where they are drawn,
    flat: ``[{"a", "b", "area" mm², "box" [x0, y0, x1, y1] mm of the area they share}]``,
    pairs sharing more than a machine file allows (E0501's 0.05 mm²), by their true outlines
    (:func:`~aidl_lang.output.part.measure.gaps.stacked_parts`: Manifold's CrossSection, not
    boxes)."""
    from ..output.part.measure.gaps import stacked_parts
    from ..output.writers import STACKED_AREA
    return [{"a": a, "b": b, "area": round(area, 6), "box": [round(v, 6) for v in box]}
            for area, a, b, box in stacked_parts(parts, STACKED_AREA)]


_UNITS = re.compile(r"^[ \t]*units[ \t]+([A-Za-z]+)", re.M)


def file_units(source: str) -> tuple[str, float]:
    """The length unit a file declares (``units in``) and its size in mm; ``("mm", 1.0)``
    when it declares none or an unknown one."""
    from ..registry import UNITS_LENGTH
    for m in _UNITS.finditer(source):
        u = m.group(1).lower()
        if u in UNITS_LENGTH:
            name = {"inch": "in", "inches": "in"}.get(u, u)
            return name, UNITS_LENGTH[u]
    return "mm", 1.0


def exact_bbox(segments) -> tuple[float, float, float, float]:
    """``(x0, y0, x1, y1)`` of exact lines, arcs and circles (an arc's extreme points where
    it crosses an axis direction, not its chords); zeros when there are none."""
    from ..geometry.shapes.curves import Arc, Circle, EllipticArc, Spline
    xs: list[float] = []
    ys: list[float] = []
    for s in segments:
        if isinstance(s, (Spline, EllipticArc)):
            x0, y0, x1, y1 = s.box()
            xs += (x0, x1)
            ys += (y0, y1)
        elif isinstance(s, Circle):
            (cx, cy), r = s.center, s.radius
            xs += (cx - r, cx + r)
            ys += (cy - r, cy + r)
        elif isinstance(s, Arc):
            (cx, cy), r = s.center, s.radius
            a0, sw = s.start_angle, s.sweep
            lo, hi = (a0, a0 + sw) if sw >= 0 else (a0 + sw, a0)
            for a in (lo, hi):
                xs.append(cx + r * math.cos(a))
                ys.append(cy + r * math.sin(a))
            k = math.ceil(lo / (math.pi / 2))
            while k * math.pi / 2 <= hi:
                a = k * math.pi / 2
                xs.append(cx + r * round(math.cos(a)))
                ys.append(cy + r * round(math.sin(a)))
                k += 1
        else:
            for px, py in (s.start, s.end):
                xs.append(px)
                ys.append(py)
    if not xs:
        return (0.0, 0.0, 0.0, 0.0)
    return (float(min(xs)), float(min(ys)), float(max(xs)), float(max(ys)))


def _below(name: str, prefix: str) -> bool:
    return name == prefix or name.startswith((prefix + ".", prefix + "["))


# ------------------------------------------------------------------ solved values
def _values(model, scale: float, unit: str, sizes: bool = False,
            internals: bool = False) -> list[Value]:
    """The solved values of ``model`` (:attr:`Result.values`).  A template instance's named
    numbers and points are the parameters its call gives and its members (its ``Members:``
    sentence's, and those the program reads, ``pair.center_distance``), not the template's
    own locals (``i``, ``found``); a pattern's copy of one (and the original under its second
    name, ``holes[0]``) gives its geometry, not its parameters again (the original's, said
    once).  ``internals``: every name, as before issue 111 (what ``values`` gives when asked
    for a name)."""
    from ..geometry.relations.bbox import numeric_box
    from ..geometry.core.expr import evaluate
    x = model.x
    xs = model.xs()

    def length(n, mm):
        return Value(n, "length", mm / scale, unit, mm)

    def point(n, px, py):
        return Value(n, "point", (px / scale, py / scale), unit, (px, py))

    def geometry(g, name: str, ox: float, oy: float) -> list[Value]:
        """The points and sizes of geometry ``g`` (of a structure whose frame is at ``(ox,
        oy)``), named ``name.center``, ``name.radius``, ..."""
        vals = []
        pts = {pn: (x[p.ix] + ox, x[p.iy] + oy) for pn, p in g.points.items()}
        if "center" not in pts and {"bottom_left", "top_right"} <= set(pts):
            a, c = pts["bottom_left"], pts["top_right"]
            pts = {"center": ((a[0] + c[0]) / 2, (a[1] + c[1]) / 2), **pts}
        for pn, (px, py) in pts.items():
            vals.append(point(f"{name}.{pn}", px, py))
        for sn, sc in g.scalars.items():
            v = x[sc.index]
            if sc.dim == "length":
                vals.append(length(f"{name}.{sn}", v))
            elif sc.dim == "angle":
                vals.append(Value(f"{name}.{sn}", "angle", math.degrees(v), "deg", v))
            else:
                vals.append(Value(f"{name}.{sn}", "number", v, "", v))
            if sizes and sn == "radius" and sc.dim == "length":   # a circle's size as drawn
                vals.append(length(f"{name}.diameter", 2 * v))
        # a rounded rectangle's corners (fixed when it is built: data, not solved scalars)
        if sizes and isinstance(g.data.get("corner_radius"), (int, float)):
            radii = g.data.get("corner_radii")
            if radii is None:
                vals.append(length(f"{name}.corner_radius", float(g.data["corner_radius"])))
            else:                                           # bottom_left, ..., top_left
                for cn, r in zip(("bottom_left", "bottom_right", "top_right", "top_left"),
                                 radii):
                    vals.append(length(f"{name}.corner_radius.{cn}", float(r)))
        return vals

    def structure(s, base: str) -> list[Value]:
        """The values of structure ``s`` named from ``base`` (its path, or the name it also
        has in a pattern's list: ``holes[0]``): origin, bbox, named geometry, scope."""
        vals = []
        ox = oy = 0.0
        t = s
        while t is not None:
            ox += x[t.fx]
            oy += x[t.fy]
            t = t.parent
        prefix = base + "." if base else ""
        # a copy's frame is held on its parent's: its origin is where the original's went
        origin = (ox, oy) if s.copy_origin is None else \
            tuple(evaluate(e, x) for e in s.copy_origin)
        vals.append(point(prefix + "origin", *origin))
        box = numeric_box(s, None, xs)
        if box is not None:
            l, r, b, tp = (float(v) for v in box)
            vals.append(Value(prefix + "bbox", "box", tuple(v / scale for v in (l, b, r, tp)),
                              unit, (l, b, r, tp)))
        for gname, g in _geometry_names(s):
            vals += geometry(g, prefix + gname, ox, oy)
        scope = s.scope if internals else _shown_scope(model, s, base, seen)
        vals += _named_quantities(scope, prefix, x, (ox, oy), scale, unit)
        return vals

    seen: dict[int, str] = {}

    # first the file's own params and constants (`param width = 40 mm`, `length = width * 2`)
    out: list[Value] = _named_quantities(model.constants, "", x, (0.0, 0.0), scale, unit)
    for base, s in named_structures(model):
        out += structure(s, base)
    return out


def _shown_scope(model, s, base: str, seen: dict[int, str]) -> dict:
    """The part of structure ``s``'s scope :func:`_values` lists under the name ``base``: all
    of it for a structure written in the program; for a template instance the parameters its
    call gives (not the defaults it left) and its members (:func:`_members_of`); for a copy of one (or the original under a second name)
    only its members that are points (a copy's points moved with it; its numbers are the
    original's).  ``seen``: id of each structure listed -> the name it was first listed as."""
    first = seen.setdefault(id(s), base)
    if s.template is None:
        return s.scope
    given = getattr(s, "given", None)
    members = _members_of(model, s.template, given)
    if given is None or first != base:          # a copy, or the original once more
        from ..geometry.core.values import PV
        return {k: v for k, v in s.scope.items() if k in members and isinstance(v, PV)}
    return {k: v for k, v in s.scope.items() if k in members or k in given[0]}


def _members_of(model, template: str, given) -> set[str]:
    """The members of template ``template`` that :func:`_values` lists: those its doc
    comment's ``Members:`` sentence names (a standard-library template's) and those the
    program reads (``instance.NAME``)."""
    out = {n for t, n in getattr(model, "members_read", ()) if t == template}
    f = given[1] if given is not None else None
    if f is None or _in_stdlib(f):
        from ..library.reference import stdlib_templates
        std = stdlib_templates().get(template)
        if std is not None:
            out.update(std.members)
    return out


@functools.lru_cache(maxsize=256)
def _in_stdlib(file: str) -> bool:
    """Whether the file ``file`` is one of the standard library's."""
    from ..base.diagnostics import STDLIB
    return Path(file).resolve().parent == STDLIB


def named_structures(model):
    """``(name, structure)`` of every structure as :attr:`Result.values` names it: its path
    (without the implicit ``model.``), and a pattern's original also under the pattern's
    name, before its copies (``holes = LinearPattern(bolt, ...)``: ``holes[0]`` is ``bolt``,
    its children with it; ``measure`` takes the same names, issue 111)."""
    root = model.root
    implicit = root.name == "model" and root.span is not None and root.span.start == 0

    def name_of(s) -> str:
        return s.path[len("model"):].lstrip(".") if implicit else s.path

    def subtree(s):
        yield s
        for ch in s.children.values():
            yield from subtree(ch)
    for s in model.structures:
        base = name_of(s)
        first = s.pattern_original
        if first is not None and base.endswith("[1]"):
            alias, own = base[:-3] + "[0]", name_of(first)
            for t in subtree(first):
                yield alias + name_of(t)[len(own):], t
        yield base, s


def _geometry_names(s) -> list[tuple[str, object]]:
    """``(name, geometry)`` of each named geometry of structure ``s`` as :attr:`Result.values`
    names it: ``c``, or ``c[0]``, ``c[1]`` when a name is given to several (a loop's);
    a pattern's original first as ``dots[0]`` (``dots = LinearPattern(c, ...)``: its first
    copy is ``dots[1]``)."""
    counts: dict[str, int] = {}
    for g in s.geometry:
        if g.name:
            counts[g.name] = counts.get(g.name, 0) + 1
    seen: dict[str, int] = {}
    out: list[tuple[str, object]] = []
    for g in s.geometry:
        if not g.name:
            continue
        gname = g.name
        if counts[g.name] > 1:
            gname = f"{g.name}[{seen.get(g.name, 0)}]"
            seen[g.name] = seen.get(g.name, 0) + 1
        if g.pattern_original is not None and gname.endswith("[1]"):
            out.append((gname[:-3] + "[0]", g.pattern_original))
        out.append((gname, g))
    return out


def _named_quantities(scope: dict, prefix: str, x, origin, scale: float,
                      unit: str) -> list[Value]:
    """The named numbers and points of a structure's ``scope`` (its template's parameters and
    its ``name = expression`` constants, e.g. ``pair.center_distance``) or of the file's
    (params and constants), solved: lengths in the file's unit, angles in degrees, bare
    numbers as they are, points in the model frame.  Geometry, structures, lists and other
    dimensions (an area) are left out."""
    from ..geometry.core.expr import evaluate as _evaluate
    from ..geometry.core.values import ANG, LEN, NUM, PV, Q
    from ..geometry.relations.bbox import collect, contains_bbox, exclusions, expand

    def evaluate(e, x):
        # a box's side (`top = body.bb.top`) is expanded at the solution first, as an
        # `assert` reads it (issue 109: `values` raised on it)
        if contains_bbox(e):
            e = expand(e, x, exclusions(collect(e, [])))
        return _evaluate(e, x)

    out = []
    for name, v in scope.items():
        n = prefix + name
        if isinstance(v, Q) and v.dim in (LEN, ANG, NUM):
            mm = evaluate(v.expr, x)
            if v.dim == LEN:
                out.append(Value(n, "length", mm / scale, unit, mm))
            elif v.dim == ANG:
                out.append(Value(n, "angle", math.degrees(mm), "deg", mm))
            else:
                out.append(Value(n, "number", mm, "", mm))
        elif isinstance(v, PV) and v.obj is None:       # a point that is not a geometry's
            px, py = evaluate(v.x, x) + origin[0], evaluate(v.y, x) + origin[1]
            out.append(Value(n, "point", (px / scale, py / scale), unit, (px, py)))
    return out
