"""A rectangular plate's inferred relations as the studio's sliders (:mod:`.drawn`, issue
94): the ranges that keep a plate's holes inside it when its width or height slides, found in
the program's syntax (never in its param names).

* a grid of holes about the plate's centre (a NEMA 17 motor mount: four holes on a 31 mm
  square about its 22 mm bore): ``body = Rectangle(center=C, width=W, height=H)``, a
  ``for i in range(NX) { for j in range(NY) { hole ... Circle(center=(C.x + (i - (NX - 1) /
  2) * PX, C.y + (j - (NY - 1) / 2) * PY), diameter=D) } }`` (``C`` the body's centre as
  written, or a name assigned it; ``PX`` and ``PY`` may be one param) and, optional, a bore
  ``Circle(center=C, diameter=B)``.  The grid stays centred (the import wrote it about the
  centre) and :data:`~.syntax.WALL` inside the edges; its holes clear each other and
  the bore; a count fits the plate at the smallest pitch.  With a bore the loop's body is
  wrapped in ``if 2 * i != NX - 1 or 2 * j != NY - 1`` (:func:`bore_skip`): odd counts both
  ways would put the middle hole on the bore, and ``--set`` takes any whole count.
* the same grid from an end member along either axis (a Raspberry Pi's holes 8 mm from the
  left edge, centred on the height: ``8 + i * PX``, or ``W - 8 + (i - (NX - 1)) * PX`` from
  the right edge) on a plate whose corner is at the origin (centre ``(W / 2, H / 2)``): the
  end member keeps its distance, the row ``WALL`` inside the far edge (no bore).
* a panel's rectangular window ``Rectangle(center=C, width=WW, height=WH)`` (a hole) with a
  2 x 2 grid of screws about ``C = (X, Y)``, ``X`` and ``Y`` on the plate's centre line or a
  number of mm from an edge (an LCD's bezel, :func:`window_ranges`): the window and the
  screws stay ``WALL`` inside the edges and each screw ``WALL`` clear of the window's corner.
* holes at the plate's corners, ``CornerPattern(holes, body, inset=I)`` of a ``hole`` with a
  ``Circle(..., diameter=D)``: the inset keeps each hole ``WALL`` inside both edges and the
  holes clear of each other.

Each returns ``{param: ", min = ..., max = ..."}`` in the order the params must be declared
(a bound reads only the params above it), or {} when the program has no such plate.
Not part of the stable API.
"""
from __future__ import annotations

import math

from ... import ast as A
from .syntax import WALL, _circles, _fmt, _kw, _name, _text

COUNT_CAP = 16      # a count's slider reaches at least this far (or twice the drawing's)
EPS = 0.01          # mm a range keeps from its neighbour's end: at the smallest plate each
#                     range still holds a value after rounding (11.2 - 9.5 is 1.6999999999999993)


def _plate(source, prog, params):
    """``(name, W, H, centre node)`` of every ``X = Rectangle(center=..., width=W,
    height=H)`` outside ``hole``\\ s whose width and height are params."""
    holes = _in_holes(prog)
    out = []
    for a in A.walk(prog):
        if isinstance(a, A.Assign) and isinstance(a.value, A.Call) and id(a.value) not in holes \
                and isinstance(a.value.func, A.Name) and a.value.func.id == "Rectangle":
            w, h = _name(_kw(a.value, "width"), params), _name(_kw(a.value, "height"), params)
            at = _kw(a.value, "center")
            if w and h and w != h and isinstance(at, A.TupleLit) and len(at.items) == 2:
                out.append((a.name, w, h, at))
    return out


def _in_holes(prog) -> set:
    return {id(n) for s in _holes(prog) for n in A.walk(s)}


def _holes(prog) -> list:
    return [s for s in A.walk(prog) if isinstance(s, A.StructDecl) and s.kind == "hole"]


def _only(prog, circles) -> bool:
    """Whether every ``hole`` of the program holds one of ``circles`` (a plate with another
    feature, a row of pot holes or a window, keeps its sliders' default spans: its ranges
    would not keep that feature inside)."""
    want = {id(c) for c in circles if c is not None}
    return all(any(id(n) in want for n in A.walk(s)) for s in _holes(prog))


def _about_middle(expr, var: str, params):
    """``(base, count, pitch)`` of ``base + (var - (count - 1) / 2) * pitch`` (params
    ``count`` and ``pitch``), or None."""
    if not (isinstance(expr, A.BinOp) and expr.op == "+" and isinstance(expr.right, A.BinOp)
            and expr.right.op == "*"):
        return None
    off, pitch = expr.right.left, _name(expr.right.right, params)
    if not (pitch and isinstance(off, A.BinOp) and off.op == "-"
            and isinstance(off.left, A.Name) and off.left.id == var):
        return None
    half = off.right
    if not (isinstance(half, A.BinOp) and half.op == "/" and isinstance(half.right, A.Num)
            and half.right.value == 2 and isinstance(half.left, A.BinOp)
            and half.left.op == "-" and isinstance(half.left.right, A.Num)
            and half.left.right.value == 1):
        return None
    count = _name(half.left.left, params)
    return (expr.left, count, pitch) if count else None


def _ranged_loop(node, params):
    """``(var, count)`` of ``for var in range(count)`` with ``count`` a param, or None."""
    it = node.iter if isinstance(node, A.For) else None
    if isinstance(it, A.Call) and isinstance(it.func, A.Name) and it.func.id == "range" \
            and len(it.args) == 1 and _name(it.args[0], params):
        return node.var, it.args[0].id
    return None


def _dist(node, params):
    """A distance from an edge as written: a number of mm (a float), a param's name (``holes_x``:
    what ``aidl import --infer`` writes since issue 114), or None."""
    if isinstance(node, A.Num) and node.unit in (None, "mm"):
        return float(node.value)
    return _name(node, params)


def _from_end(expr, var: str, params):
    """``(kind, a, count, pitch, side)`` of a row from its end member ``a`` from an edge:
    ``a + var * pitch`` (kind ``"low"``, side None: from the edge at 0) or ``side - a + (var
    - (count - 1)) * pitch`` (``"high"``: from the edge at ``side``, a param), ``a`` a number
    in mm or a param (:func:`_dist`); or None (count None for ``"low"``: the loop's)."""
    if not (isinstance(expr, A.BinOp) and expr.op == "+" and isinstance(expr.right, A.BinOp)
            and expr.right.op == "*"):
        return None
    left, k, pitch = expr.left, expr.right.left, _name(expr.right.right, params)
    if not pitch:
        return None
    if _dist(left, params) is not None and isinstance(k, A.Name) and k.id == var:
        return "low", _dist(left, params), None, pitch, None
    if isinstance(left, A.BinOp) and left.op == "-" and _name(left.left, params) \
            and _dist(left.right, params) is not None \
            and isinstance(k, A.BinOp) and k.op == "-" and isinstance(k.left, A.Name) \
            and k.left.id == var and isinstance(k.right, A.BinOp) and k.right.op == "-" \
            and _name(k.right.left, params) and isinstance(k.right.right, A.Num) \
            and k.right.right.value == 1:
        return "high", _dist(left.right, params), k.right.left.id, pitch, left.left.id
    return None


def _axis(source, expr, loops: dict, params):
    """One coordinate of a grid's hole: ``("mid", base text, count, pitch, var)`` about its
    middle (:func:`_about_middle`), ``("low" | "high", a, count, pitch, var, side)`` from an
    end member (:func:`_from_end`), or None."""
    for var, count in loops.items():
        m = _about_middle(expr, var, params)
        if m is not None and m[1] == count:
            return "mid", _text(source, m[0]), count, m[2], var
        e = _from_end(expr, var, params)
        if e is not None and e[2] in (None, count):
            return e[0], e[1], count, e[3], var, e[4]
    return None


def _grid(source, prog, params, holes):
    """``(x axis, y axis (of :func:`_axis`), D, the Circle, the inner loop)`` of the first two
    nested loops of a hole ``Circle`` placed about the middle of both or from an end member,
    or None."""
    for outer in (n for n in A.walk(prog) if isinstance(n, A.For)):
        o = _ranged_loop(outer, params)
        for inner in (n for n in A.walk(outer.body) if isinstance(n, A.For)) if o else ():
            i = _ranged_loop(inner, params)
            if i is None:
                continue
            loops = dict([o, i])
            for c in _circles(inner.body):
                at, d = _kw(c, "center"), _name(_kw(c, "diameter"), params)
                if id(c) not in holes or not d or not isinstance(at, A.TupleLit) \
                        or len(at.items) != 2:
                    continue
                axes = [_axis(source, e, loops, params) for e in at.items]
                if None not in axes and axes[0][2] != axes[1][2] and axes[0][4] != axes[1][4]:
                    return axes[0], axes[1], d, c, inner
    return None


def _centre_texts(source, prog, centre, part: int | None) -> set:
    """How the program writes the point ``centre`` (a ``TupleLit``) or its x (``part`` 0) or
    y (1): as written, or through a name assigned it (``bore_c.x``)."""
    whole = _text(source, centre)
    names = {a.name for a in A.walk(prog) if isinstance(a, A.Assign)
             and _text(source, a.value) == whole}
    if part is None:
        return {whole} | names
    return {_text(source, centre.items[part])} | {f"{n}.{'xy'[part]}" for n in names}


def _grid_parts(source, prog, params):
    """``(grid of :func:`_grid`, plate of :func:`_plate`, bore param or None)`` of a plate
    with a grid of holes about its centre (and a bore on it) or from an end member at a set
    distance from an edge along either axis (then no bore), or None."""
    holes = _in_holes(prog)
    grid = _grid(source, prog, params, holes)
    if grid is None:
        return None
    ax, ay, d, hole = grid[:4]

    def fits(p, axis, a) -> bool:
        side = p[1 + axis]
        if a[0] == "mid":
            return a[1] in _centre_texts(source, prog, p[3], axis)
        # an end member from the edge at 0 (the plate's centre at side / 2) or at `side`
        return _text(source, p[3].items[axis]) == f"{side} / 2" and a[5] in (None, side)

    plate = next((p for p in _plate(source, prog, params) if fits(p, 0, ax) and fits(p, 1, ay)),
                 None)
    if plate is None:
        return None
    _, w, h, centre = plate
    same = _centre_texts(source, prog, centre, None)
    bore, bore_circle = next(((b, c) for c in _circles(prog) if id(c) in holes
                              and _text(source, _kw(c, "center") or c) in same
                              for b in [_name(_kw(c, "diameter"), params)]
                              if b and b not in (d, w, h)), (None, None))
    if bore and (ax[0], ay[0]) != ("mid", "mid"):
        return None                     # a bore beside a grid off the centre: not related
    if not _only(prog, (hole, bore_circle)):
        return None
    ends = {a[1] for a in (ax, ay) if a[0] != "mid" and isinstance(a[1], str)}
    used = {w, h, d, ax[2], ay[2], ax[3], ay[3]} | ({bore} if bore else set()) | ends
    if len(used) != 6 + bool(bore) + (ax[3] != ay[3]) + len(ends) or \
            len([a for a in (ax, ay) if a[0] != "mid" and isinstance(a[1], str)]) != len(ends):
        return None                     # one param in two roles: left as it is
    return grid, plate, bore


def bore_skip(source: str, prog, params) -> tuple[int, int, str] | None:
    """``(first line, last line, condition)`` (0-based) of the body of a grid's inner loop
    that a bore on the grid's centre wraps in ``if CONDITION { ... }``: with odd counts both
    ways the grid's middle hole sits on the bore's centre (``--set`` takes any whole count,
    whatever the slider's step), and the condition leaves that one hole out.  None without a
    bore, or when the body's statements do not stand on lines of their own."""
    parts = _grid_parts(source, prog, params)
    if parts is None or parts[2] is None:
        return None
    (ax, ay, _, _, inner), nx, ny = parts[0], parts[0][0][2], parts[0][1][2]
    vx, vy = ax[4], ay[4]
    stmts = inner.body.stmts
    if not stmts:
        return None
    first, last = stmts[0].span, stmts[-1].span
    head = source[source.rfind("\n", 0, first.start) + 1:first.start]
    end = source.find("\n", last.end)
    tail = source[last.end:end if end >= 0 else len(source)]
    if head.strip() or tail.strip() or inner.span.line >= first.line \
            or inner.span.end_line <= last.end_line:
        return None
    return (first.line - 1, last.end_line - 1,
            f"2 * {vx} != {nx} - 1 or 2 * {vy} != {ny} - 1")


def grid_place(source: str, prog, params) -> str:
    """How the grid keeps its place as the plate's size changes, in words (the studio's
    note): ``stays centred on the plate``, or from an end member along an axis (``keeps its
    end 8 mm from the left edge and stays centred on the height``)."""
    parts = _grid_parts(source, prog, params)
    if parts is None or (parts[0][0][0], parts[0][1][0]) == ("mid", "mid"):
        return "stays centred on the plate"
    ends, mids = [], []
    for a, edges, size in ((parts[0][0], ("left", "right"), "width"),
                           (parts[0][1], ("bottom", "top"), "height")):
        if a[0] == "mid":
            mids.append(f"stays centred on the {size}")
        else:
            ends.append(f"{_dist_text(a[1])} from the {edges[a[0] == 'high']} edge")
    return " and ".join([f"keeps its end {' and '.join(ends)}"] + mids)


def _dist_text(a) -> str:
    """A distance of :func:`_dist` as the program writes it: ``8 mm``, ``holes_x``."""
    return a if isinstance(a, str) else f"{_fmt(a)} mm"


def grid_ranges(source: str, prog, params) -> dict[str, str]:
    """The ranges of a plate with a grid of holes about its centre (and a bore) or from an
    end member a set distance ``a`` from an edge (a Raspberry Pi's four holes 8 mm from the
    left edge, centred on the height); {} without.  Along an axis about the middle the grid
    spans at most ``S - D - 2 WALL`` of the side ``S``; from an end member at most ``S - a -
    D / 2 - WALL``, and the hole keeps ``WALL`` to its edge (``D <= 2 (a - WALL)``).  Where
    ``a`` is a param (``holes_x``, issue 114) it gets a range too: from ``D / 2 + WALL`` to
    what the side leaves for one pitch, ``S - 3 D / 2 - 2 WALL`` (then ``D`` is bounded as
    about the middle, and ``S`` at least as much).  About a
    bore, the counts go by 1 where :func:`bore_skip` can leave out the hole on the bore (odd
    counts both ways), else by 2 from 2 (and an odd ``--set`` count still puts a hole on the
    bore)."""
    parts = _grid_parts(source, prog, params)
    if parts is None:
        return {}
    (ax, ay, d, hole, _), (_, w, h, _), bore = parts
    nx, px, ny, py = ax[2], ax[3], ay[2], ay[3]
    moved = [(a[1], side) for a, side in ((ax, w), (ay, h))
             if a[0] != "mid" and isinstance(a[1], str)]     # a param's distance from the edge
    used = {w, h, d, nx, ny, px, py} | ({bore} if bore else set()) | {m for m, _ in moved}
    v = {k: params[k].value.value for k in used}
    skips = bool(bore) and bore_skip(source, prog, params) is not None
    if bore and not skips and (v[nx] % 2 or v[ny] % 2):
        return {}                       # a hole on the bore's centre: nothing to keep
    lo_d, lo_b = v[d] / 4, (v[bore] / 4 if bore else 0.0)
    wall, two = _fmt(WALL), _fmt(2 * WALL)
    ends = [a[1] for a in (ax, ay) if a[0] != "mid" and not isinstance(a[1], str)]
    if any(2 * (a - WALL) < lo_d + EPS for a in ends) or \
            any(v[m] < v[d] / 2 + WALL or v[m] > v[s] - 1.5 * v[d] - 2 * WALL - 2 * EPS
                for m, s in moved):
        return {}                       # the drawing's hole is (nearly) at its edge
    avail, least = {}, {}
    for a, side in ((ax, w), (ay, h)):  # each bound EPS inside the next one's: see EPS
        if a[0] == "mid":
            avail[side] = f"{side} - {d} - {two} mm"
            least[side] = lo_b + 2 * lo_d + 4 * WALL + 4 * EPS if bore else \
                2 * lo_d + 3 * WALL + 2 * EPS
        elif isinstance(a[1], str):     # D's max (below) keeps the param's range open by 2 EPS
            avail[side] = f"{side} - {a[1]} - {d} / 2 - {wall} mm"
            least[side] = 2 * lo_d + 3 * WALL + 6 * EPS
        else:
            avail[side] = f"{side} - {_fmt(a[1])} mm - {d} / 2 - {wall} mm"
            least[side] = a[1] + 2 * WALL + 1.5 * (lo_d + EPS) + 2 * EPS
    if bore:
        d_max = f"(min({w}, {h}) - {_fmt(lo_b + 4 * WALL + 3 * EPS)} mm) / 2"
        pitch_min = f"{bore} + {d} + {two} mm"
    elif not ends and not moved:
        d_max = f"(min({w}, {h}) - {_fmt(3 * WALL + EPS)} mm) / 2"
        pitch_min = f"{d} + {wall} mm"
    else:
        terms = [f"({side} - {_fmt(3 * WALL + EPS)} mm) / 2" if a[0] == "mid" else
                 f"({side} - {_fmt(3 * WALL + 4 * EPS)} mm) / 2" if isinstance(a[1], str) else
                 f"2 * ({side} - {_fmt(a[1] + 2 * WALL + EPS)} mm) / 3"
                 for a, side in ((ax, w), (ay, h))]
        terms += [f"{_fmt(2 * (min(ends) - WALL))} mm"] if ends else []
        d_max = f"min({', '.join(terms)})"
        pitch_min = f"{d} + {wall} mm"
    out = {w: f", min = {_fmt(least[w])} mm, max = {_fmt(2 * v[w])} mm",
           h: f", min = {_fmt(least[h])} mm, max = {_fmt(2 * v[h])} mm",
           d: f", min = {_fmt(lo_d)} mm, max = {d_max}"}
    if bore:                # 2 EPS: at the bore's max two holes a side still fit by EPS
        out[bore] = f", min = {_fmt(lo_b)} mm, max = min({w}, {h}) - 2 * {d} - " \
                    f"{_fmt(4 * WALL + 2 * EPS)} mm"
    for m, side in moved:   # the end member WALL inside its edge, one pitch's room beyond it
        out[m] = f", min = {d} / 2 + {wall} mm, max = {side} - 3 * {d} / 2 - " \
                 f"{_fmt(2 * WALL + 2 * EPS)} mm"
    for n, side in ((nx, w), (ny, h)):     # as many as fit at the smallest pitch (and EPS)
        cap = max(COUNT_CAP, 2 * int(v[n]))
        fit = f"({avail[side]}) / ({pitch_min} + {_fmt(EPS)} mm)"
        out[n] = (f", min = 2, max = min({cap}, 2 * floor(({fit} + 1) / 2)), step = 2"
                  if bore and not skips else
                  f", min = {2 if bore else 1}, max = min({cap}, floor({fit}) + 1)")
    spans = [f"({avail[side]}) / max({n} - 1, 1)"
             for n, side, p in ((nx, w, px), (ny, h, py)) if p == px]
    out[px] = f", min = {pitch_min}, max = " + (spans[0] if len(spans) == 1 else
                                                  f"min({', '.join(spans)})")
    if py != px:
        out[py] = f", min = {pitch_min}, max = ({avail[h]}) / max({ny} - 1, 1)"
    return out


def corner_ranges(source: str, prog, params) -> dict[str, str]:
    """The ranges of a plate with a hole at each corner, ``inset`` in from the edges, and a
    bore at its centre or none (a square NEMA 17 mount: the import reads its four holes as
    at the corners); {} without.  With a bore of diameter ``B`` the corner holes (``D``) keep
    ``WALL`` from it: a hole's centre is at least sqrt(2) (min(W, H) / 2 - inset) from the
    plate's centre, so ``inset <= min(W, H) / 2 - (B / 2 + D / 2 + WALL) / sqrt(2)``; the
    bore's and the hole's ranges keep that above the least inset (``D / 2 + WALL``)."""
    plates = {p[0]: p for p in _plate(source, prog, params)}
    structs = {s.name: s for s in A.walk(prog) if isinstance(s, A.StructDecl)
               and s.kind == "hole"}
    holes = _in_holes(prog)
    for call in A.walk(prog):
        if not (isinstance(call, A.Call) and isinstance(call.func, A.Name)
                and call.func.id == "CornerPattern" and len(call.args) == 2
                and all(isinstance(a, A.Name) for a in call.args)):
            continue
        hole, plate = structs.get(call.args[0].id), plates.get(call.args[1].id)
        inset = _name(_kw(call, "inset"), params)
        circles = _circles(hole) if hole is not None else []
        d = _name(_kw(circles[0], "diameter"), params) if len(circles) == 1 else None
        if plate is None or not inset or not d or len({d, inset, plate[1], plate[2]}) != 4:
            continue
        _, w, h, centre = plate
        same = _centre_texts(source, prog, centre, None)
        bore, bore_circle = next(((b, c) for c in _circles(prog) if id(c) in holes
                                  and _text(source, _kw(c, "center") or c) in same
                                  for b in [_name(_kw(c, "diameter"), params)]
                                  if b and b not in (d, w, h, inset)), (None, None))
        if not _only(prog, circles + [bore_circle]):
            continue
        v = {k: params[k].value.value for k in (w, h, d, inset) + ((bore,) if bore else ())}
        lo_d = v[d] / 4
        s_ = f"min({w}, {h})"
        if not bore:
            least = 2 * lo_d + 3 * WALL + 2 * EPS
            return {w: f", min = {_fmt(least)} mm, max = {_fmt(2 * v[w])} mm",
                    h: f", min = {_fmt(least)} mm, max = {_fmt(2 * v[h])} mm",
                    d: f", min = {_fmt(lo_d)} mm, "
                       f"max = ({s_} - {_fmt(3 * WALL + EPS)} mm) / 2",
                    inset: f", min = {d} / 2 + {_fmt(WALL)} mm, "
                           f"max = ({s_} - {d} - {_fmt(WALL)} mm) / 2"}
        # the bore's largest with the holes at their least inset: r2 (S - D - 2 WALL) - D -
        # 2 WALL (r2 = sqrt 2), and inside the plate; each bound EPS inside the next (EPS)
        r2, lo_b = math.sqrt(2), v[bore] / 4
        least = max(2 * lo_d + 3 * WALL + 2 * EPS, lo_b + 2 * WALL + 3 * EPS,
                    ((1 + r2) * (lo_d + EPS) + lo_b + (2 + 2 * r2) * WALL + 2 * EPS) / r2)
        return {w: f", min = {_fmt(least)} mm, max = {_fmt(2 * v[w])} mm",
                h: f", min = {_fmt(least)} mm, max = {_fmt(2 * v[h])} mm",
                d: f", min = {_fmt(lo_d)} mm, max = min(({s_} - {_fmt(3 * WALL + EPS)} mm) / 2, "
                   f"(sqrt(2) * {s_} - {_fmt(lo_b + (2 + 2 * r2) * WALL + 2 * EPS)} mm) / "
                   f"(1 + sqrt(2)))",
                bore: f", min = {_fmt(lo_b)} mm, max = min({s_} - {_fmt(2 * WALL + EPS)} mm, "
                      f"sqrt(2) * ({s_} - {d} - {_fmt(2 * WALL)} mm) - {d} - "
                      f"{_fmt(2 * WALL + EPS)} mm)",
                inset: f", min = {d} / 2 + {_fmt(WALL)} mm, "
                       f"max = min(({s_} - {d} - {_fmt(WALL)} mm) / 2, {s_} / 2 - "
                       f"({bore} + {d} + {_fmt(2 * WALL)} mm) / (2 * sqrt(2)))"}
    return {}


def _anchor(source, expr, side: str, params):
    """Where a coordinate ``expr`` of a point sits along a plate's side ``side`` (its
    corner at the origin): ``("mid", None)`` at ``side / 2``, ``("low", c)`` at ``c``,
    ``("high", c)`` at ``side - c``, ``c`` a number of mm or a param (``window_y``: what
    ``aidl import --infer`` writes since issue 114, :func:`_dist`); or None."""
    if _text(source, expr) == f"{side} / 2":
        return "mid", None
    if _dist(expr, params) is not None and _dist(expr, params) != side:
        return "low", _dist(expr, params)
    if isinstance(expr, A.BinOp) and expr.op == "-" and isinstance(expr.left, A.Name) \
            and expr.left.id == side and _dist(expr.right, params) not in (None, side):
        return "high", _dist(expr.right, params)
    return None


def _window(source, prog, params):
    """``(plate, window centre name, (x anchor, y anchor), window width, height, grid)`` of
    a plate (its corner at the origin) with a rectangular ``hole`` window centred on a point
    ``C = (X, Y)`` and a 2 x 2 grid of screw holes about ``C`` (an LCD's bezel), or None."""
    holes = _in_holes(prog)
    grid = _grid(source, prog, params, holes)
    if grid is None or grid[0][0] != "mid" or grid[1][0] != "mid":
        return None
    points = {a.name: a.value for a in A.walk(prog) if isinstance(a, A.Assign)
              and isinstance(a.value, A.TupleLit) and len(a.value.items) == 2}
    for r in (n for n in A.walk(prog) if isinstance(n, A.Call) and id(n) in holes
              and isinstance(n.func, A.Name) and n.func.id == "Rectangle"):
        at = _kw(r, "center")
        ww, wh = _name(_kw(r, "width"), params), _name(_kw(r, "height"), params)
        if not (isinstance(at, A.Name) and at.id in points and ww and wh and not _kw(r, "rotation")
                and (grid[0][1], grid[1][1]) == (f"{at.id}.x", f"{at.id}.y")):
            continue
        for plate in _plate(source, prog, params):
            _, w, h, centre = plate
            if _text(source, centre) != f"({w} / 2, {h} / 2)":
                continue
            anchors = (_anchor(source, points[at.id].items[0], w, params),
                       _anchor(source, points[at.id].items[1], h, params))
            if None not in anchors and _only(prog, (grid[3], r)):
                return plate, at.id, anchors, ww, wh, grid
    return None


def _across(anchor, side: str) -> str:
    """Twice the half-room about a point anchored ``anchor`` along ``side``, as text:
    ``side`` (on the centre line), or ``2 * min(c, side - c)``."""
    kind, c = anchor
    if kind == "mid":
        return side
    return f"2 * min({_dist_text(c)}, {side} - {_dist_text(c)})"


def window_place(source: str, prog, params) -> str:
    """Where the window and its screws stay, in words (the studio's note)."""
    found = _window(source, prog, params)
    if found is None:
        return ""
    said = []
    for (kind, c), edges, size in zip(found[2], (("left", "right"), ("bottom", "top")),
                                      ("width", "height")):
        said.append(f"centred on the {size}" if kind == "mid" else
                    f"{_dist_text(c)} from the {edges[kind == 'high']} edge")
    return " and ".join(said)


def window_ranges(source: str, prog, params) -> dict[str, str]:
    """The ranges of a panel with a rectangular window and a 2 x 2 grid of screws about its
    centre (an LCD's bezel: the screws just beyond the window's corners), the window's centre
    on the plate's centre line or a set distance ``c`` from an edge along each axis; {}
    without.  With ``R`` the half-room about that centre (``S / 2``, or ``min(c, S - c)``):
    the window and the screws stay ``WALL`` inside the edges (``ww <= 2 Rx - 2 WALL``, ``px
    <= 2 Rx - D - 2 WALL``, the same in y), and each screw ``WALL`` clear of the window's
    corner: ``py >= wh + 2 sqrt((D / 2 + WALL)^2 - max(px - ww, 0)^2 / 4)`` (its height then
    keeps ``py``'s range open: ``wh <= 2 Ry - 2 D - 4 WALL``); the counts stay 2 (more
    screws would sit on the window's sides).  Where ``c`` is a param (``window_y``, issue
    114) its range keeps the half-room the smallest window and screws need (``N``, from the
    drawing's sizes / 4) on both sides: ``N + EPS <= c <= S - N - EPS``."""
    found = _window(source, prog, params)
    if found is None:
        return {}
    (_, w, h, _), _, (axx, axy), ww, wh, ((_, _, nx, px, _), (_, _, ny, py, _), d, _, _) = found
    moved = [(c, side) for (kind, c), side in ((axx, w), (axy, h)) if isinstance(c, str)]
    used = {w, h, d, ww, wh, nx, ny, px, py} | {c for c, _ in moved}
    if len(used) != 9 + len(moved):
        return {}
    v = {k: params[k].value.value for k in used}
    if (v[nx], v[ny]) != (2, 2):
        return {}
    lo_d, lo_ww, lo_wh = v[d] / 4, v[ww] / 4, v[wh] / 4
    need = {w: max(2 * lo_d + 3 * WALL + 3 * EPS, lo_ww + 2 * WALL + EPS) / 2,
            h: (2 * lo_d + 4 * WALL + lo_wh + 4 * EPS) / 2}
    least = {}
    for anchor, side in ((axx, w), (axy, h)):
        kind, c = anchor
        c = v[c] if isinstance(c, str) else c
        if kind != "mid" and (c < need[side] + EPS or v[side] - c < need[side] + EPS):
            return {}                   # the drawing's window sits too near its edge
        least[side] = 2 * need[side] + EPS if kind == "mid" else \
            2 * need[side] + 3 * EPS if isinstance(anchor[1], str) else c + need[side] + EPS
    rx, ry = _across(axx, w), _across(axy, h)
    wall = _fmt(WALL)
    out = {w: f", min = {_fmt(least[w])} mm, max = {_fmt(2 * v[w])} mm",
           h: f", min = {_fmt(least[h])} mm, max = {_fmt(2 * v[h])} mm"}
    for c, side in moved:   # the window's centre keeps the least half-room on both sides
        out[c] = f", min = {_fmt(need[side] + EPS)} mm, max = {side} - " \
                 f"{_fmt(need[side] + EPS)} mm"
    return {**out,
            d: f", min = {_fmt(lo_d)} mm, max = min(({rx} - {_fmt(3 * WALL + EPS)} mm) / 2, "
               f"({ry} - {_fmt(4 * WALL + lo_wh + 2 * EPS)} mm) / 2)",
            ww: f", min = {_fmt(lo_ww)} mm, max = {rx} - {_fmt(2 * WALL)} mm",
            wh: f", min = {_fmt(lo_wh)} mm, max = {ry} - 2 * {d} - {_fmt(4 * WALL + EPS)} mm",
            nx: ", min = 2, max = 2", ny: ", min = 2, max = 2",
            px: f", min = {d} + {wall} mm, max = {rx} - {d} - {_fmt(2 * WALL)} mm",
            py: f", min = max({d} + {wall} mm, {wh} + 2 * sqrt(max(square({d} / 2 + {wall} mm) "
                f"- square(max({px} - {ww}, 0 mm) / 2), 0 mm * 0 mm))), "
                f"max = {ry} - {d} - {_fmt(2 * WALL)} mm"}
