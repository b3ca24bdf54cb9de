"""Law 3 of issue 109: *members are the geometry*.

Every member a program can read of a shape it can name (``.bb`` and its sides, ``.center``,
``.radius``, ``.width``, ``.points``, a line's ends ... : :func:`aidl_lang.geometry.relations.
members.member`, the box of :mod:`aidl_lang.geometry.relations.bbox`) equals the same measure
taken on the shape's drawn geometry: the exact curves the booleans draw for it
(:class:`aidl_lang.output.part.build.booleans.Renderer`, the outlines every writer and
``check --describe`` read), within :data:`TOL`.  Shapes made of other shapes (``Offset``,
``Inset``, ``Shell``, ``Hull``, ``Stroke``, ``Intersect``), copies of patterns and
``Mirrored``, the shapes of template instances and of ``Text`` are shapes like any other.

A violation is one line ``name.member: member value vs drawn value`` (mm, the model frame).
The documented exceptions (docs/laws.md (law 3): members that are by definition not the drawn
outline) are not measured: :data:`NOT_DRAWN`.

    python -m benchmarks.laws.run --law members      # over the corpus (helper corpus's runner)
    python -m benchmarks.laws.law_members FILE.aidl ... [--generated]   # without the runner
"""
from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from typing import Iterator

from .common import NotApplicable

NAME = "Members are the geometry: every member a program reads of a shape equals the drawn shape"
TOLERANCE = ("1e-6 mm (lengths and coordinates; beyond 1000 mm from the origin 1e-9 of the "
             "coordinates' size), 1e-9 rad (angles)")
TOL = 1e-6
SIDES = ("left", "right", "bottom", "top")

# (kind, member) measured on something else than the drawn outline, by definition (the
# reasons: docs/laws.md, law 3, "Exceptions")
NOT_DRAWN = {
    ("RoundedRectangle", "top_left"), ("RoundedRectangle", "top_right"),
    ("RoundedRectangle", "bottom_left"), ("RoundedRectangle", "bottom_right"),
    ("RoundedRectangle", "corners"), ("RoundedRectangle", "top"),
    ("RoundedRectangle", "bottom"), ("RoundedRectangle", "left"), ("RoundedRectangle", "right"),
    ("Polygon", "centroid"), ("Triangle", "centroid"),
}

try:                                # the corpus's record, once helper corpus's runner is in
    from .corpus import Entry
except ImportError:                 # pragma: no cover - before the corpus is merged
    @dataclass(frozen=True)
    class Entry:                    # the agreed interface (docs/laws.md)
        name: str
        source: str
        path: str
        overrides: dict = field(default_factory=dict)
        kind: str = "generated"

        def __hash__(self) -> int:
            return hash((self.name, self.source))


def applies(entry) -> bool:
    """Every program: any that compiles names shapes (one that does not: not applicable)."""
    return True


def check(entry) -> list[str]:
    """The violations of the law by ``entry``'s program (``[]``: it holds); raises
    :class:`NotApplicable` when the program does not compile and solve."""
    import aidl_lang
    try:
        res = aidl_lang.compile(source=entry.source, path=entry.path,
                                overrides=dict(entry.overrides) or None)
    except Exception as ex:         # noqa: BLE001 - a compile that raises: not this law's
        raise NotApplicable(f"compile raised {type(ex).__name__}") from ex
    c = res.compiled
    if c.model is None or c.solve is None or not c.solve.converged or c.drawing is None \
            or res.errors:
        raise NotApplicable("does not compile and solve")
    return violations(res)


def violations(res) -> list[str]:
    """The law over a compiled :class:`aidl_lang.api.Result`: one line per member of a named
    shape that differs from its drawn geometry."""
    from aidl_lang.output.part.build.booleans import Renderer
    model = res.compiled.model
    x = model.xs()
    r = Renderer(model)
    geo, _structs = res._named_geometry()
    out: list[str] = []
    seen: set = set()
    for name, g in geo.items():
        if id(g) in seen:
            continue
        seen.add(id(g))
        try:
            segs = drawn(r, g)
        except Exception as ex:     # noqa: BLE001 - nothing drawn to measure
            out.append(f"{name}: its drawn geometry cannot be read ({type(ex).__name__}: {ex})")
            continue
        if not segs:
            continue
        out += shape_violations(name, g, segs, x)
    return out


def drawn(r, g) -> list:
    """The exact segments the booleans draw for shape ``g`` (root frame, mm): a closed
    shape's loops, an open curve's pieces, a Text's strokes (as lines; a Text in a font: its
    letters' loops, issue 112)."""
    from aidl_lang.geometry.shapes.curves import Line
    k = g.kind
    if k == "Point":
        return []
    if k == "Text" and not g.data.get("stencil") and not g.data.get("font"):
        from aidl_lang.geometry.shapes.text import text_strokes
        along = g.data.get("along")
        if along is not None:
            segs = r.text_along(g, along)
            p = (r.segment(along).center if along.kind == "Arc" else
                 r._pt(along.points["center"]))
        else:
            segs = text_strokes(g.data["text"], g.data["size"], g.data["anchor"],
                                g.data.get("valign", "baseline"), g.data.get("rotation", 0.0))
            p = r._pt(g.points["position"])
        return [Line((p[0] + a[0], p[1] + a[1]), (p[0] + b[0], p[1] + b[1])) for a, b in segs]
    if k == "Intersect" and not g.closed:
        return list(r.clipped(g))
    if k == "Drawing2D":
        loops, paths = r.drawing2d(g)
        return [sg for lp in loops for sg in lp.segments] + [sg for p in paths for sg in p]
    if k in ("Line", "Arc", "EllipticArc") or (k in ("Polyline", "Spline", "Bezier")
                                               and not g.closed):
        return list(r.pieces(g))
    return [sg for lp in r.loops_of(g) for sg in lp.segments]


def _box(segs) -> tuple:
    bs = [sg.box() for sg in segs]
    return (min(b[0] for b in bs), max(b[2] for b in bs), min(b[1] for b in bs),
            max(b[3] for b in bs))


def _tol(*vals) -> float:
    return TOL * max(1.0, max((abs(v) for v in vals), default=0.0) / 1000.0)


def _f(v) -> str:
    if isinstance(v, tuple):
        return "(" + ", ".join(f"{c:.6f}" for c in v) + ")"
    return f"{v:.6f}"


def shape_violations(name: str, g, segs: list, x) -> list[str]:
    """The members of shape ``g`` (named ``name``) against its drawn segments ``segs``."""
    from aidl_lang.geometry.core.expr import evaluate
    from aidl_lang.geometry.relations.bbox import side_expr
    from aidl_lang.geometry.relations.members import member, member_names
    from aidl_lang.geometry.core.values import PV, Q
    out: list[str] = []
    box = _box(segs)
    for i, side in enumerate(SIDES):
        v = float(evaluate(side_expr(g, side, None, x, set()), x))
        if not abs(v - box[i]) <= _tol(v, box[i]):
            out.append(f"{name}.bb.{side}: {_f(v)} vs drawn {_f(box[i])}")
    from aidl_lang.geometry.relations.bbox import contains_bbox, expand

    def ev(e) -> float:             # a member made of box sides (a stencil's center) too
        return float(evaluate(expand(e, x, set()) if contains_bbox(e) else e, x))

    def point(m):
        pv = member(g, m, None)
        return (ev(pv.x), ev(pv.y))

    meas = Measure(g, segs, box, point)
    for m in member_names(g):
        if m == "bb" or (g.kind, m) in NOT_DRAWN:
            continue
        try:
            val = member(g, m, None)
        except Exception:           # noqa: BLE001 - a member the kind does not make here
            continue
        want = meas.get(m)
        if want is None or val is None:
            continue
        if isinstance(val, PV):
            got = (ev(val.x), ev(val.y))
            if math.dist(got, want) > _tol(*got, *want):
                out.append(f"{name}.{m}: {_f(got)} vs drawn {_f(want)}")
        elif isinstance(val, Q):
            got = ev(val.expr)
            tol = 1e-9 if m == "angle" else _tol(got, want)
            diff = math.remainder(got - want, 2 * math.pi) if m == "angle" else got - want
            if not abs(diff) <= tol:
                out.append(f"{name}.{m}: {_f(got)} vs drawn {_f(want)}")
        elif isinstance(val, list) and val and all(isinstance(p, PV) for p in val):
            got = [(ev(p.x), ev(p.y)) for p in val]
            bad = _unmatched(got, want)
            if bad:
                out.append(f"{name}.{m}: {bad}")
    return out


class _OnOutline:
    """The measure of a polygon's points: each on the drawn outline, each drawn corner one
    of them."""

    def __init__(self, segs: list):
        self.segs = segs


def _on_outline(got: list, want: _OnOutline) -> str:
    corners = [sg.start for sg in want.segs]
    for q in corners:
        p = min(got, key=lambda w: math.dist(q, w))
        if math.dist(p, q) > _tol(*p, *q):
            return f"drawn corner {_f(q)} is none of the points (nearest {_f(p)})"
    for p in got:
        d = min(_seg_dist(p, sg) for sg in want.segs)
        if d > _tol(*p):
            return f"{_f(p)} is {d:.6f} mm off the drawn outline"
    return ""


def _seg_dist(p, sg) -> float:
    (x0, y0), (x1, y1) = sg.start, sg.end
    dx, dy = x1 - x0, y1 - y0
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / L2))
    return math.dist(p, (x0 + t * dx, y0 + t * dy))


def _unmatched(got: list, want) -> str:
    """"" when every point of ``got`` is one of ``want`` (and as many), else what differs."""
    if isinstance(want, _OnOutline):
        return _on_outline(got, want)
    if len(got) != len(want):
        return f"{len(got)} points vs drawn {len(want)}"
    for p in got:
        q = min(want, key=lambda w: math.dist(p, w))
        if math.dist(p, q) > _tol(*p, *q):
            return f"{_f(p)} vs nearest drawn {_f(q)}"
    return ""


class Measure:
    """What each member of a shape measures on its drawn segments (root frame, mm), or None
    where the law has no measure of it (its value is then not compared)."""

    def __init__(self, g, segs: list, box: tuple, value):
        from aidl_lang.geometry.shapes.curves import Arc, Circle, Line
        self.g, self.segs, self.box, self.value = g, segs, box, value
        self.lines = [s for s in segs if isinstance(s, Line)]
        self.arcs = [s for s in segs if isinstance(s, (Arc, Circle))]
        self.Arc, self.Circle, self.Line = Arc, Circle, Line

    def vertices(self) -> list:
        return [s.start for s in self.segs]

    def get(self, m: str):
        k = self.g.kind
        f = getattr(self, "_" + k, None)
        v = f(m) if f is not None else None
        if v is None and m == "center" and k in ("Hull", "Text"):
            b = self.box
            return ((b[0] + b[1]) / 2, (b[2] + b[3]) / 2)
        return v

    # ---------------------------------------------------------- per kind
    def _Circle(self, m):
        (c,) = self.arcs
        cx, cy = c.center
        r = c.radius
        return {"center": c.center, "radius": r, "diameter": 2 * r, "top": (cx, cy + r),
                "bottom": (cx, cy - r), "left": (cx - r, cy), "right": (cx + r, cy)}.get(m)

    def _Arc(self, m):
        (a,) = self.arcs
        return {"center": a.center, "radius": a.radius, "diameter": 2 * a.radius,
                "start": a.start, "end": a.end,
                "midpoint": a.at(a.start_angle + a.sweep / 2)}.get(m)

    def _Line(self, m):
        (ln,) = self.lines
        (x0, y0), (x1, y1) = ln.start, ln.end
        return {"start": ln.start, "end": ln.end, "midpoint": ((x0 + x1) / 2, (y0 + y1) / 2),
                "length": math.hypot(x1 - x0, y1 - y0), "dx": x1 - x0, "dy": y1 - y0,
                "angle": math.atan2(y1 - y0, x1 - x0)}.get(m)

    def _corners(self):
        return [ln.start for ln in self.lines] if len(self.lines) == len(self.segs) else None

    def _mean(self, pts):
        return (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))

    def _Rectangle(self, m):
        v = self._corners()
        if v is None or len(v) != 4:
            return None
        if m in ("corners",):
            return v
        if m == "center":
            return self._mean(v)
        if m in ("top_left", "top_right", "bottom_left", "bottom_right"):
            return self._nearest(v, self.value(m))
        if m in ("width", "height"):    # between the drawn corners the member corners name
            a = self._nearest(v, self.value("bottom_left"))
            b = self._nearest(v, self.value("bottom_right" if m == "width" else "top_left"))
            return math.dist(a, b)
        if m in ("start", "end") and m in self.g.points:
            # a bar's (Rectangle(start, end, width)): its centre line's end, the middle of
            # the drawn edge at that end (bottom at the start, top at the end)
            ends = ("bottom_left", "bottom_right") if m == "start" else ("top_left", "top_right")
            return self._mean([self._nearest(v, self.value(n)) for n in ends])
        return None

    @staticmethod
    def _nearest(v: list, p):
        return min(v, key=lambda q: math.dist(p, q))

    def _RoundedRectangle(self, m):
        if m == "center" and len(self.lines) == 4:
            # the sharp corners: where consecutive sides' carriers cross; their mean
            ls = self.lines
            return self._mean([_cross(ls[i - 1], ls[i]) for i in range(4)])
        return None

    def _polygon(self, m):
        v = self._corners()
        if v is None:
            return None
        if m in ("points", "vertices", "corners"):
            return v
        if m == "center":
            return self._mean(v)
        return None

    _Trapezoid = _polygon

    def _Polygon(self, m):
        # a Polygon's points are its points as written: a point on an edge, or twice, is no
        # drawn corner; each must lie on the outline, each drawn corner be one of them
        # (its `center`, their mean, is by definition: docs/laws.md, law 3)
        if m in ("points", "vertices", "corners"):
            return _OnOutline(self.segs)
        return None

    def _Triangle(self, m):
        if m == "center" and "center" in self.g.points:
            # by base and height: the middle of its height, turned with it; the box's center
            # at multiples of 90 degrees (docs/laws.md, law 3, "Exceptions")
            q = self.g.data.get("rotation", 0.0) / (math.pi / 2)
            if abs(q - round(q)) > 1e-12:
                return None
            b = self.box
            return ((b[0] + b[1]) / 2, (b[2] + b[3]) / 2)
        return self._polygon(m)

    def _RegularPolygon(self, m):
        v = self._corners()
        if v is None:
            return None
        c = self._mean(v)
        return {"points": v, "vertices": v, "corners": v, "center": c,
                "radius": math.dist(c, v[0])}.get(m)

    def _Star(self, m):
        if self.arcs:                   # rounded tips: the notches and the tip arcs
            c = self._mean([a.center for a in self.arcs])
            if m == "tip_radius":
                return self.arcs[0].radius
            if m == "center":
                return c
            if m == "inner_radius":
                return min(math.dist(c, ln.start) for ln in self.lines)
            return None
        v = self._corners()
        if v is None:
            return None
        c = self._mean(v)
        d = [math.dist(c, p) for p in v]
        return {"points": v, "vertices": v, "corners": v, "center": c, "outer_radius": max(d),
                "inner_radius": min(d), "tip_radius": 0.0}.get(m)

    def _Slot(self, m):
        if len(self.arcs) != 2:
            return None
        a, b = self.arcs
        r = a.radius
        (ax, ay), (bx, by) = a.center, b.center
        return {"center": ((ax + bx) / 2, (ay + by) / 2), "radius": r, "width": 2 * r,
                "length": math.hypot(bx - ax, by - ay) + 2 * r}.get(m)

    def _Ellipse(self, m):
        if m == "center":
            b = self.box
            return ((b[0] + b[1]) / 2, (b[2] + b[3]) / 2)
        return None


def _cross(a, b):
    """Where the carriers of lines ``a`` and ``b`` cross."""
    (x1, y1), (x2, y2) = a.start, a.end
    (x3, y3), (x4, y4) = b.start, b.end
    d = (x1 - x2) * (y3 - y4) - (y1 - y2) * (x3 - x4)
    t = ((x1 - x3) * (y3 - y4) - (y1 - y3) * (x3 - x4)) / d
    return (x1 + t * (x2 - x1), y1 + t * (y2 - y1))


# ------------------------------------------------------------------ generated programs
BASES = {
    "rect": "Rectangle(center=({x}, {y}), width={a}, height={b}, rotation={t} deg)",
    "circle": "Circle(center=({x}, {y}), radius={a})",
    "star": "Star(center=({x}, {y}), points={n}, outer_radius={a} + {b}, inner_radius={a}, "
            "rotation={t} deg)",
    "rstar": "Star(center=({x}, {y}), points={n}, outer_radius={a} + {b}, inner_radius={a}, "
             "rotation={t} deg, tip_radius=1)",
    "poly": "Polygon(points=[({x}, {y}), ({x} + {a}, {y}), ({x} + {a}, {y} + {b}), "
            "({x} + {a} / 2, {y} + {b} / 3), ({x}, {y} + {b})])",
    "hexagon": "RegularPolygon(center=({x}, {y}), radius={a}, sides={n}, rotation={t} deg)",
    "slot": "Slot(center=({x}, {y}), length={a} + {b}, width={b}, rotation={t} deg)",
    "rrect": "RoundedRectangle(center=({x}, {y}), width={a} + 6, height={b} + 6, "
             "corner_radius=2)",
    "ellipse": "Ellipse(center=({x}, {y}), rx={a}, ry={b}, rotation={t} deg)",
    "trapezoid": "Trapezoid(center=({x}, {y}), bottom_width={a} + {b}, top_width={a}, "
                 "height={b}, rotation={t} deg)",
    "sector": "Sector(center=({x}, {y}), radius={a} + {b}, start_angle={t} deg, "
              "end_angle={t} deg + 130 deg)",
    "arcslot": "ArcSlot(center=({x}, {y}), radius={a}, start_angle={t} deg, "
               "end_angle={t} deg + 100 deg, width=5)",
}
OPS = {
    "offset": "Offset({s}, {d})", "offset_miter": 'Offset({s}, {d}, join="miter")',
    "inset": "Inset({s}, {e})", "inset_miter": 'Inset({s}, {e}, join="miter")',
    "shell": "Shell({s}, {d})", "shell_in": "Shell({s}, -{e})",
    "shell_miter": 'Shell({s}, {d}, join="miter")',
    "hull": "Hull([{s}, Circle(center=({x} + 30, {y} - 10), radius={d})])",
    "intersect": "Intersect([{s}, Circle(center=({x} + 3, {y} + 2), radius=9)])",
}
NO_OFFSET = ("ellipse",)            # an ellipse's offset is within 1e-4 mm (biarcs): not exact
TAILS = {
    "none": "",
    "pattern": "    copies = CircularPattern(shape, count=3, center=(0, 0), angle=360 deg)\n",
    "mirror": "    twin = Mirrored(shape, line=Line(start=(0, -50), end=(10, 50)))\n",
    "align": "    AlignLeft(shape, frame_box)\n    AlignTop(shape, frame_box)\n",
    "scaled": "    big = Scaled(shape, 1.5, center=(5, -3))\n",
    "row": "    row = LinearPattern(shape, 3, (70, 5))\n",
}
# Text: plain, turned, anchored, stencilled (in a hole), along a circle, and its box related
TEXTS = [
    'Text("AIDL 109", position=(3, -4), size=7)',
    'Text("Wg!", position=(0, 0), size=12, anchor="start", valign="top", rotation=25 deg)',
    'Text("members", position=(-5, 2), size=6, anchor="end", valign="bottom")',
    'Text("OBA", position=(0, 0), size=20, valign="middle", stencil=true)',
    'Text("around", along=Circle(center=(0, 0), radius=30, construction=true), size=5)',
    'Text("under", along=Circle(center=(4, 1), radius=25, construction=true), size=4, '
    'flip=true)',
    # in a font (issue 112): its letters' outlines, plain, turned, stencilled, along a circle
    'Text("HAPPY 30", position=(2, -3), size=12, font="sans:Bold")',
    'Text("Wg!", position=(0, 0), size=12, font="serif", anchor="start", valign="top", '
    'rotation=25 deg)',
    'Text("BOX", position=(0, 0), size=20, font="sans", valign="middle", stencil=true)',
    'Text("round", along=Circle(center=(0, 0), radius=30, construction=true), size=5, '
    'font="sans")',
]


def generated_source(base: str, ops: list[str], tail: str, v: dict) -> str:
    """A program of one base shape with ``ops`` applied in turn (the first innermost), named
    ``shape``, and ``tail``'s copies or relations, asserting nothing."""
    e = BASES[base].format(**v)
    for op in ops:
        e = OPS[op].format(s=e, **v)
    frame = ("    frame_box = Rectangle(center=(200, 200), width=10, height=10)\n"
             if tail == "align" else "")
    return (f"units mm\nsolid part {{\n{frame}    shape = {e}\n{TAILS[tail]}"
            f"    w = shape.bb.width\n}}\n")


def generated_cases(n: int | None = None) -> list[tuple[str, str]]:
    """Fixed generated programs: every base under every operation, and nestings of two and
    three, under a pattern, a mirror or relations on the box (``(name, source)``, the same
    on every machine: the sizes cycle through fixed lists)."""
    out = []
    # a Shell's wall (d) more than twice the inset (e) that may follow it: something left
    sizes = [dict(x=0, y=0, a=12, b=7, n=5, t=0, d=3, e=1.25),
             dict(x=3.5, y=-2, a=15, b=9, n=8, t=17, d=2.5, e=1),
             dict(x=-7, y=4, a=10, b=6, n=6, t=33, d=4, e=1.5)]
    bases = sorted(BASES)
    ops = sorted(OPS)
    tails = sorted(TAILS)
    k = 0
    combos = [[o] for o in ops] + [[a, b] for a in ops for b in ops if a != b] + \
        [[a, b, c] for a in ("inset", "offset_miter") for b in ("offset", "shell")
         for c in ("shell", "hull", "inset_miter")]
    for ch in combos:
        for base in bases:
            if base in NO_OFFSET and any(o != "hull" and o != "intersect" for o in ch):
                continue
            v = sizes[k % len(sizes)]
            tail = tails[k % len(tails)]
            k += 1
            out.append((f"generated/members/{base}+{'+'.join(ch)}@{tail}",
                        generated_source(base, ch, tail, v)))
    for i, t in enumerate(TEXTS):
        for tail in ("none", "pattern", "mirror", "scaled"):
            kind = "hole" if "stencil" in t else "drawing"
            body = ("    plate = Rectangle(center=(0, 0), width=200, height=120)\n"
                    if kind == "hole" else "")
            copies = TAILS[tail].replace("(shape,", "(label,")
            out.append((f"generated/members/text{i}@{tail}",
                        f"units mm\nsolid part {{\n{body}    {kind} label {{\n"
                        f"        t = {t}\n    }}\n{copies}    w = label.t.bb.width\n}}\n"))
    return out[:n] if n is not None else out


def generated(n: int | None = None) -> Iterator:
    """The generated programs as corpus entries (kind ``generated``)."""
    import tempfile
    from pathlib import Path
    path = str(Path(tempfile.gettempdir()) / "law_members.aidl")
    for name, src in generated_cases(n):
        yield Entry(name=name, source=src, path=path, overrides={}, kind="generated")


def main(argv: list[str]) -> int:
    """``FILE.aidl ...`` and/or ``--generated``: each program's violations, then the counts
    (held, failed, not applicable); exit status 1 when one failed."""
    entries = []
    for p in argv:
        if p == "--generated":
            entries += list(generated())
        else:
            entries.append(Entry(name=p, source=open(p, encoding="utf-8").read(), path=p,
                                 overrides={}, kind="examples"))
    held = failed = skipped = 0
    for e in entries:
        try:
            lines = check(e)
        except NotApplicable:
            skipped += 1
            continue
        for ln in lines:
            print(f"{e.name}: {ln}")
        failed += bool(lines)
        held += not lines
    print(f"{len(entries)} programs: {held} held, {failed} failed, {skipped} not applicable")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
