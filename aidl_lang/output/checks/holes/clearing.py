"""W0508's machine fix: a move that clears the overlap, never an ``AllowOverlap`` that hides
it (issue 91: `AllowOverlap(pens, phone)` silenced a pen hole running 7 mm into a phone slot;
a repair loop applying it would have cut the merged opening).

For two different holes that overlap or touch, :func:`move_fix` moves one of them (the one
the warning points at, else the other) by the shortest translation that leaves ``t`` mm of
material between it and the other hole, and no less than that from every other hole of the
part and from its outline (when it lay inside it): nothing else is made worse.  The
translation is found exactly on the polygons: the places the moving shape may not go are
the Minkowski sums of each obstacle with the reflected shape (its convex hull, so the move is
never short), grown by the wall; the move is the nearest point outside all of them.

The fix is an edit of the moving shape's call: every point argument (a `center=`, a
Polygon's points) shifted by the move, written against the program's own expressions (`(-40
+ 20 * i, 20)` becomes `(-40 + 20 * i - 3.51, 20)`; a plain number becomes the moved number),
in the file's units.  No fix is offered when the shape is placed otherwise (a constraint on
it or on its hole, a point taken from another shape, a template's or a pattern's copy, a
hole of several statements that touch each other): the hint still says how far to move."""
from __future__ import annotations

import math
import re

import manifold3d as mf
import numpy as np

from ....base.diagnostics import Fix, in_stdlib
from ....geometry.core.model import Structure
from ....geometry.shapes.tessellate import CHORD_TOL
from ....registry import bind_variant, lookup
from ..common import _area, _edges, _inside, _signed

# mm added to the wall: the polygons' chords lie up to CHORD_TOL inside each curve (one per
# side), the wall's round joins up to 0.001 mm inside theirs (the move, its components
# rounded up to 0.01 mm, is then tested against the grown places, not trusted)
MARGIN = 2 * CHORD_TOL + 0.001
MAX_COPIES = 64        # copies moved by one edit (a loop's) past which no move is looked for
UNIT_MM = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4, "inch": 25.4, "ft": 304.8}
_POINT_KW = ("point", "points")


# ------------------------------------------------------------------ the move
def _hull(cs) -> np.ndarray:
    """The convex hull's vertices (k x 2) of CrossSection ``cs``."""
    polys = cs.hull().to_polygons()
    return np.asarray(polys[0], dtype=float) if polys else np.zeros((0, 2))


def _minkowski(obstacle, B: np.ndarray) -> mf.CrossSection:
    """``obstacle`` ⊕ (−B) for the convex polygon ``B``: the translations that put ``B`` on
    the obstacle (the union of each edge's sweep by −B, and the obstacle itself swept by one
    of −B's points)."""
    parts = [obstacle.translate((float(-B[0, 0]), float(-B[0, 1])))]
    for loop in obstacle.to_polygons():
        P = np.asarray(loop, dtype=float)
        Q = np.roll(P, -1, axis=0)
        for p, q in zip(P, Q):
            parts.append(mf.CrossSection.hull_points(np.vstack([p - B, q - B])))
    return mf.CrossSection.batch_boolean(parts, mf.OpType.Add)


def _window(box, pad: float) -> mf.CrossSection:
    x0, y0, x1, y1 = box
    return mf.CrossSection.square((x1 - x0 + 2 * pad, y1 - y0 + 2 * pad)).translate(
        (x0 - pad, y0 - pad))


def clearing_move(moving: list, obstacles: list, t: float, reach: float) -> tuple | None:
    """The shortest translation ``(dx, dy)`` mm, its components rounded to 0.01 mm, that
    puts every shape of ``moving`` (CrossSections moved together) at least ``t`` mm (and
    :data:`MARGIN`) from every shape of ``obstacles``, no longer than ``reach`` mm; None when
    there is none."""
    c = t + MARGIN
    pad = reach + c + 1.0
    bad = []
    for m in moving:
        B = _hull(m)
        if len(B) < 3:
            return None
        win = _window(m.bounds(), pad)
        for o in obstacles:
            near = o ^ win
            if near.is_empty():
                continue
            bad.append(_minkowski(near, B))
    if not bad:
        return 0.0, 0.0
    F = mf.CrossSection.batch_boolean(bad, mf.OpType.Add).offset(
        c, mf.JoinType.Round, 2.0, _segments(c))
    loops = [np.asarray(p, dtype=float) for p in F.to_polygons()]
    loops = [P for P in loops if len(P) >= 3]
    if not loops:
        return 0.0, 0.0
    edges = _edges(loops)
    if not _inside(np.zeros((1, 2)), edges)[0]:
        return 0.0, 0.0                      # already clear
    A = np.concatenate(loops)
    B = np.concatenate([np.roll(P, -1, axis=0) for P in loops])
    d = B - A
    L2 = np.einsum("ij,ij->i", d, d)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.clip(np.where(L2 > 0, -(A * d).sum(axis=1) / L2, 0.0), 0.0, 1.0)
    feet = A + s[:, None] * d
    dist = np.hypot(*feet.T)
    for k in np.argsort(dist, kind="stable")[:64]:
        if dist[k] > reach:
            break
        u = feet[k] / dist[k] if dist[k] > 0 else feet[k]
        for extra in (0.0, 0.01, 0.02):         # rounded inward: a hair further out
            v = _rounded(u * (dist[k] + extra))
            if not _inside(v[None], edges)[0]:
                return float(v[0]), float(v[1])
    return None


def _rounded(p: np.ndarray) -> np.ndarray:
    """``p`` with each component rounded to 0.01 mm away from zero (a component under
    0.005 mm is 0: a move along an axis stays along it)."""
    out = np.zeros(2)
    for k in range(2):
        x = float(p[k])
        if abs(x) >= 0.005:
            out[k] = math.copysign(math.ceil(round(abs(x) * 100, 6)) / 100, x)
    return out


def _segments(r: float) -> int:
    """Segments of a round join of radius ``r`` whose sagitta is under 0.001 mm."""
    if r <= 0.001:
        return 8
    return max(8, int(math.ceil(math.pi / math.acos(max(-1.0, 1 - 0.001 / r)))))


# ------------------------------------------------------------------ the edit
def _file_scale(src: str) -> tuple:
    """The file's length unit: ``(name, mm per unit)``."""
    m = re.search(r"^[ \t]*units[ \t]+([A-Za-z]+)", src, re.M)
    name = m.group(1) if m else "mm"
    return name, UNIT_MM.get(name, 1.0)


def _split_top(text: str, sep: str = ",") -> list | None:
    """``text`` split at the ``sep`` characters outside brackets and strings: ``[(start,
    end)]`` offsets; None when a bracket does not close or a comment is inside."""
    out, depth, start, k, n = [], 0, 0, 0, len(text)
    while k < n:
        ch = text[k]
        if ch in "\"'":
            j = text.find(ch, k + 1)
            if j < 0:
                return None
            k = j + 1
            continue
        if ch == "#" or text.startswith("//", k) or text.startswith("/*", k):
            return None
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
            if depth < 0:
                return None
        elif ch == sep and depth == 0:
            out.append((start, k))
            start = k + 1
        k += 1
    if depth:
        return None
    out.append((start, n))
    return out


_NAME = re.compile(r"\s*([A-Za-z_]\w*)\s*[=:](?!=)\s*")
_NUMBER = re.compile(r"\s*(-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*\Z")
_ATOM = re.compile(r"\s*[-+]?[\w.]+(\([^()]*\))?\s*\Z")


def _shifted(expr: str, delta: float, unit: str) -> str:
    """The coordinate expression ``expr`` plus ``delta`` (in the file's unit): a plain number
    is the moved number, anything else keeps its expression (its params) and adds the move."""
    if abs(delta) < 1e-12:
        return expr
    lead = expr[:len(expr) - len(expr.lstrip())]
    trail = expr[len(expr.rstrip()):]
    body = expr.strip()
    m = _NUMBER.match(body)
    if m:
        return f"{lead}{_num(float(m.group(1)) + delta)}{trail}"
    safe = body if _additive_safe(body) else f"({body})"
    step = _num(abs(delta)) + ("" if unit == "mm" else " mm")
    return f"{lead}{safe} {'+' if delta > 0 else '-'} {step}{trail}"


def _additive_safe(body: str) -> bool:
    """``body`` can take ``+ d`` at its end and mean ``(body) + d``: no comparison, no
    conditional, no boolean at its top level."""
    flat = _blank_brackets(body)
    return not re.search(r"[<>!]=?|==|\bif\b|\belse\b|\band\b|\bor\b|\bnot\b|\?", flat)


def _blank_brackets(s: str) -> str:
    out, depth = [], 0
    for ch in s:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        out.append(ch if depth == 0 and ch not in ")]}" else " ")
    return "".join(out)


def _num(x: float) -> str:
    s = f"{x:.4f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _tuple_items(text: str) -> list | None:
    """The offsets of the items of a point literal ``(x, y)`` (``text`` stripped of
    blanks around it), or None."""
    body = text.strip()
    if not (body.startswith("(") and body.endswith(")")):
        return None
    inner = body[1:-1]
    parts = _split_top(inner)
    if parts is None or len(parts) != 2 or _split_top(inner, ")") is None:
        return None
    off = text.find("(") + 1
    return [(off + a, off + b) for a, b in parts]


def move_text(call: str, dx: float, dy: float, unit: str) -> str | None:
    """The shape call ``call`` (its source text, e.g. ``Circle(center=(-40 + 20 * i, 20),
    radius=pen_d / 2)``) with every point argument shifted by ``(dx, dy)`` in the file's unit
    ``unit`` (its name): ``Circle(center=(-40 + 20 * i - 3.51, 20), radius=pen_d / 2)``.
    None when the call's arguments are not all readable, or when an argument that places the
    shape is not a point literal (``(x, y)``) or a list of them (a point of another shape: a
    shared point, which the move would tear away)."""
    m = re.match(r"\s*([A-Za-z_]\w*)\s*\(", call)
    if m is None or not call.rstrip().endswith(")"):
        return None
    entry = lookup(m.group(1))
    if entry is None or entry.category != "primitive":
        return None
    inner0, inner1 = m.end(), len(call.rstrip()) - 1
    args = _split_top(call[inner0:inner1])
    if args is None:
        return None
    pos, kws = [], []
    for a, b in args:
        text = call[inner0 + a:inner0 + b]
        if not text.strip():
            continue
        k = _NAME.match(text)
        if k:
            kws.append((k.group(1), inner0 + a + k.end(), inner0 + b))
        elif kws:
            return None
        else:
            pos.append((inner0 + a, inner0 + b))
    variant, ren, _ = bind_variant(entry, len(pos), [k for k, _, _ in kws])
    if variant is None:
        return None
    typed = [(variant[n].type, s, e) for n, (s, e) in enumerate(pos)]
    by_name = {a.name: a.type for a in variant}
    typed += [(by_name.get(ren.get(k, k)), s, e) for k, s, e in kws]
    edits = []
    for type_, s, e in typed:
        if type_ == "point":
            items = _tuple_items(call[s:e])
            if items is None:
                return None
            edits += [(s + a, s + b, d) for (a, b), d in zip(items, (dx, dy))]
        elif type_ == "points":
            body = call[s:e].strip()
            if not (body.startswith("[") and body.endswith("]")):
                return None
            off = call.find("[", s) + 1
            inner = call[off:off + len(body) - 2]
            parts = _split_top(inner)
            if parts is None:
                return None
            for a, b in parts:
                if not inner[a:b].strip():
                    continue
                items = _tuple_items(inner[a:b])
                if items is None:
                    return None
                edits += [(off + a + p, off + a + q, d) for (p, q), d in zip(items, (dx, dy))]
    if not edits:
        return None
    out, at = [], 0
    for s, e, d in sorted(edits):
        out += [call[at:s], _shifted(call[s:e], d, unit)]
        at = e
    return "".join(out) + call[at:]


# ------------------------------------------------------------------ W0508's fix
def _expr_vars(e, out: set) -> None:
    terms = getattr(e, "terms", None)
    if terms is not None:
        out.update(terms)
        return
    for a in getattr(e, "args", ()) or ():
        _expr_vars(a, out)


def _placed(hole: Structure, shapes: list, part: Structure) -> bool:
    """A written constraint reaches ``hole`` (or a structure around it below ``part``) or
    the points of ``shapes``: the position written in the call is not where it ends."""
    frames = set()
    s = hole
    while s is not None and s is not part:
        frames |= {s.fx, s.fy}
        s = s.parent
    pts = {i for g in shapes for p in _all_points(g) for i in (p.ix, p.iy)}
    word = re.compile(rf"\b{re.escape(hole.name)}\b")
    for node in part.subtree():
        for c in node.constraints:
            if c.implicit:
                continue
            if c.args and any(isinstance(x, Structure) and x is not part
                              and (x.is_within(hole) or hole.is_within(x))
                              for x in _flat(c.args)):
                return True
            if _touches(c, frames | pts):
                return True
            if c.deferred and c.span is not None and word.search(c.text or ""):
                return True                 # a box of it (`pens.bb.left == 5`)
    return False


def _touches(c, ids: set) -> bool:
    used: set = set()
    for eq in c.equations:
        _expr_vars(eq.expr, used)
    return bool(used & ids)


def _flat(args):
    for a in args:
        if isinstance(a, (list, tuple)):
            yield from _flat(a)
        else:
            yield a


def _all_points(g) -> list:
    out = list(g.points.values())
    for p in g.parts.values():
        if hasattr(p, "points"):
            out += list(p.points.values())
    return out


def _patterned(moving: list) -> bool:
    """The faces of one statement include a pattern's or a mirror's copies of its shape
    (``cs[1]`` of ``cs = CircularPattern(c, ...)``: named otherwise than the original, the
    first marked): moving the original moves them by turned or mirrored moves, not by the
    same one.  A loop's copies (``holes[0]``, ``holes[1]``, ...) all move alike."""
    bases = {(g.name or "").split("[", 1)[0] for g, _ in moving}
    return len(bases) > 1 or any(g.pattern_original is not None for g, _ in moving)


def _copied(hole: Structure, part: Structure) -> bool:
    """``hole`` (or a structure around it below ``part``) is a template's instance, a copy
    a pattern or mirror made, or one of several that one statement (a loop) declares: an
    edit of its call would move every instance, not this one."""
    s = hole
    while s is not None and s is not part:
        if s.template or s.copy_origin is not None or s.pattern_original is not None:
            return True
        if s.parent is not None and sum(1 for c in s.parent.children.values()
                                        if c.span == s.span) > 1:
            return True
        s = s.parent
    return False


def move_fix(d, part: Structure, shape, cuts: list, mover: int, other: int, t: float,
             sink, near: dict | None = None) -> tuple | None:
    """The fix of W0508 between the holes of ``cuts[mover]`` and ``cuts[other]`` (of part
    ``part``, whose final shape is ``shape``) that moves the first: ``(Fix, (dx, dy) mm, the
    moved shape (the first copy), how many copies the edit moves, the radius that would
    clear instead or "")``, or None (see the module's docstring for when).  Only the holes
    and the outline within reach are looked at (``near``, a dict kept by the caller for the
    part, holds the holes' boxes, made once: a plate of 20,000 holes is not intersected
    20,000 times per move)."""
    hole = cuts[mover].hole
    region = cuts[other].region
    if hole.children or _copied(hole, part):
        return None
    faces = [(g, f) for g, f in d.own.get(hole, ()) if f is not None and not f.is_empty()]
    if not faces:
        return None
    grown = region.offset(2 * CHORD_TOL, mf.JoinType.Miter, 2.0, 16)
    meets = [g.span for g, f in faces if _area(f ^ grown) > 1e-9]
    spans = set(meets)
    if len(spans) != 1 or None in spans:
        return None
    span = meets[0]
    moving = [(g, f) for g, f in faces if g.span == span]
    staying = [f for g, f in faces if g.span != span]
    if len(moving) > MAX_COPIES or _patterned(moving):
        return None
    if staying:
        together = mf.CrossSection.batch_boolean([f for _, f in moving], mf.OpType.Add)
        around = together.offset(t + MARGIN, mf.JoinType.Round, 2.0, 32)
        if any(_area(around ^ f) > 1e-9 for f in staying):
            return None                # one opening of several statements: a move tears it
    g = moving[0][0]
    src = getattr(sink, "sources", {}).get(span.file)
    if src is None or in_stdlib(span.file) or span.end > len(src):
        return None
    if _placed(hole, [x for x, _ in moving], part):
        return None
    unit, scale = _file_scale(src)
    whole = mf.CrossSection.batch_boolean([f for _, f in moving], mf.OpType.Add)
    reach = max(10.0, 2 * max(_diagonal(f) for _, f in moving))
    bx0, by0, bx1, by1 = whole.bounds()
    pad = reach + t + MARGIN + 2.0
    box = (bx0 - pad, by0 - pad, bx1 + pad, by1 + pad)
    win = _window(whole.bounds(), pad)
    if near is None:
        near = {}
    if "boxes" not in near:
        near["boxes"] = np.array([c.region.bounds() if c.region is not None
                                  and not c.region.is_empty() else (np.inf, np.inf, -np.inf,
                                                                    -np.inf) for c in cuts],
                                 dtype=float).reshape(-1, 4)
    B = near["boxes"]
    hit = np.flatnonzero((B[:, 0] <= box[2]) & (B[:, 2] >= box[0]) & (B[:, 1] <= box[3])
                         & (B[:, 3] >= box[1]))
    regions = [cuts[k].region for k in hit.tolist()]
    obstacles = [cuts[k].region for k in hit.tolist() if k != mover] + staying
    # the outline near the moving shapes: the part with its holes (and the windows its
    # solids enclose) filled, clipped to the reach; outside it is an obstacle when the
    # shapes lay inside it (a notch drawn past the edge may stay a notch)
    local = mf.CrossSection.batch_boolean([shape ^ win] + [r ^ win for r in regions],
                                          mf.OpType.Add)
    outer = [p for p in local.to_polygons()
             if len(p) >= 3 and _signed(np.asarray(p, dtype=float)) > 0]
    if outer:
        inside = mf.CrossSection(outer, mf.FillRule.Positive)
        if _area(whole - inside) <= 1e-6:
            obstacles.append(_window(whole.bounds(), pad + 1.0) - inside)
    v = clearing_move([f for _, f in moving], obstacles, t, reach)
    if v is None or v == (0.0, 0.0):
        return None
    call = src[span.start:span.end]
    new = move_text(call, *(_in_unit(x, scale) for x in v), unit)
    if new is None:
        return None
    return Fix(span, new), v, g, len(moving), _radius_that_clears(g, moving, region, t, unit,
                                                                  scale)


def _diagonal(f) -> float:
    x0, y0, x1, y1 = f.bounds()
    return math.hypot(x1 - x0, y1 - y0)


def _in_unit(x: float, scale: float) -> float:
    """``x`` mm in the file's unit (``scale`` mm each), rounded away from zero to 1e-4 of it
    (so the move, written with 4 decimals, is never shorter than found)."""
    if scale == 1.0:
        return x
    return math.copysign(math.ceil(round(abs(x) / scale * 1e4, 6)) / 1e4, x)


def _radius_that_clears(g, moving: list, region, t: float, unit: str, scale: float) -> str:
    """For one moving Circle whose centre lies outside the other hole's ``region``: the
    radius (in the file's unit, rounded down to 0.01 mm) that leaves ``t`` mm to it, when
    that keeps at least a third of the radius; else ""."""
    from .contact import _nearest, circle_of, _segments
    if g.kind != "Circle" or len(moving) != 1:
        return ""
    k = circle_of(np.asarray(moving[0][1].to_polygons()[0], dtype=float))
    if k is None:
        return ""
    cx, cy, r = k
    loops = [np.asarray(p, dtype=float) for p in region.to_polygons()]
    if _inside(np.array([[cx, cy]]), _edges(loops))[0]:
        return ""
    A, B = _segments(loops)
    dist = float(_nearest(np.array([[cx, cy]]), A, B)[0][0])
    new = math.floor(round((dist - t - 2 * CHORD_TOL) * 100, 6)) / 100
    if new < r / 3:
        return ""
    if unit == "mm":
        return f"{_num(new)} mm"
    return f"{_num(math.floor(new / scale * 1e4) / 1e4)} {unit} ({new:.2f} mm)"
