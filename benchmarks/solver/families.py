"""Benchmark sketch families with known solutions, as AIDL source and as SolveSpace sketches.

Each family is well-constrained (zero degrees of freedom) and has a known solution; the starting
point is that solution moved by up to 10% of the family's feature size (a chord, a link, a
rectangle side) per coordinate.  :func:`family` returns a :class:`Case` with the AIDL source (the
perturbed start written as the points' starting guesses), the known solution per point name,
and a builder for the same sketch in SolveSpace (``slvs`` from PyPI) when it is installed.

Families (parameter count = 2 x points):

* ``rectangles``: a chain of rectangles, each built from 4 points and 4 lines with horizontal,
  vertical and length constraints, its bottom-left corner coincident with the previous
  bottom-right one; the first corner fixed.  8 parameters per rectangle.
* ``ring``: points on a fixed circle, consecutive chords equal, the polygon closed, the first
  point fixed.  2 parameters per point.
* ``linkage``: an open chain of links with given lengths and relative angles, the first joint
  fixed and the first link horizontal.  2 parameters per joint.
* ``hierarchy``: (not flat) a tree of structures, each a small sketch of about 10 constraints,
  placed by structural relations (``RightOf``, ``Above``, ``AlignCenterY``) and equations on
  their members; used for hierarchical-versus-flat timing.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass
class Case:
    name: str
    n_params: int
    source: str
    solution: dict = field(default_factory=dict)     # point name -> (x, y)
    slvs: object = None                              # () -> (solve() -> ok, read(name) -> (x, y))
    spec: dict = field(default_factory=dict)         # the sketch as data, for other peers


def _fmt(v: float) -> str:
    return f"{v:.12f}"


def rectangles(n_params: int, seed: int = 0, chained: bool = True) -> Case:
    rng = np.random.default_rng(seed)
    n = max(1, n_params // 8)
    w = rng.uniform(8, 12, n)
    h = rng.uniform(8, 12, n)
    sol = {}
    x0 = y0 = 0.0
    for i in range(n):
        if not chained:                     # islands: a grid of separate rectangles
            x0, y0 = 15.0 * (i % 20), 15.0 * (i // 20)
        sol[f"a{i}"] = (x0, y0)
        sol[f"b{i}"] = (x0 + w[i], y0)
        sol[f"c{i}"] = (x0 + w[i], y0 + h[i])
        sol[f"d{i}"] = (x0, y0 + h[i])
        x0 += w[i]
    fixed = {"a0"} if chained else {f"a{i}" for i in range(n)}
    start = _perturb(sol, rng, 1.0, fixed=fixed)
    lines = ["units mm", "solid chain {"]
    for k, (x, y) in start.items():
        lines.append(f"    {k} = Point({_fmt(x)}, {_fmt(y)})")
    cons = []
    for i in range(n):
        a, b, c, d = (f"{p}{i}" for p in "abcd")
        lines += [f"    bot{i} = Line({a}, {b})", f"    rgt{i} = Line({b}, {c})",
                  f"    top{i} = Line({c}, {d})", f"    lft{i} = Line({d}, {a})",
                  f"    Horizontal(bot{i})", f"    Horizontal(top{i})",
                  f"    Vertical(lft{i})", f"    Vertical(rgt{i})",
                  f"    Length(bot{i}, {_fmt(w[i])})", f"    Length(lft{i}, {_fmt(h[i])})"]
        cons += [("horizontal", a, b), ("horizontal", c, d), ("vertical", d, a),
                 ("vertical", b, c), ("distance", a, b, float(w[i])),
                 ("distance", d, a, float(h[i]))]
        if i and chained:
            lines.append(f"    Coincident(a{i}, b{i - 1})")
            cons.append(("coincident", a, f"b{i - 1}"))
    lines += [f"    Fixed({k})" for k in sorted(fixed, key=lambda k: int(k[1:]))] + ["}"]

    def build():
        import slvs
        slvs.clear_sketch()
        wp = slvs.add_base_2d(1)
        g = 2
        P = {k: slvs.add_point_2d(g, x, y, wp) for k, (x, y) in start.items()}
        for k in fixed:
            slvs.dragged(g, P[k], wp)
        for i in range(n):
            a, b, c, d = (P[f"{p}{i}"] for p in "abcd")
            bot, rgt = slvs.add_line_2d(g, a, b, wp), slvs.add_line_2d(g, b, c, wp)
            top, lft = slvs.add_line_2d(g, c, d, wp), slvs.add_line_2d(g, d, a, wp)
            slvs.horizontal(g, bot, wp)
            slvs.horizontal(g, top, wp)
            slvs.vertical(g, lft, wp)
            slvs.vertical(g, rgt, wp)
            slvs.distance(g, a, b, float(w[i]), wp)
            slvs.distance(g, d, a, float(h[i]), wp)
            if i and chained:
                slvs.coincident(g, a, P[f"b{i - 1}"], wp)
        return _slvs_handles(g, P)

    spec = {"points": start, "fixed": sorted(fixed), "constraints": cons}
    return Case("rectangles" if chained else "islands", 8 * n,
                "\n".join(lines) + "\n", sol, build, spec)


def islands(n_params: int, seed: int = 0) -> Case:
    """Independent rectangles (each with its own fixed corner): one solid, many components."""
    return rectangles(n_params, seed, chained=False)


def ring(n_params: int, seed: int = 0) -> Case:
    rng = np.random.default_rng(seed)
    n = max(4, n_params // 2)
    R = 10.0 * n / (2 * math.pi)            # chords of about 10 mm
    chord = 2 * R * math.sin(math.pi / n)
    sol = {f"p{i}": (R * math.cos(2 * math.pi * i / n), R * math.sin(2 * math.pi * i / n))
           for i in range(n)}
    start = _perturb(sol, rng, 0.1 * chord, fixed={"p0"})
    lines = ["units mm", "solid ring {", f"    c = Circle(center=(0, 0), radius={_fmt(R)})",
             "    Fixed(c)"]
    for k, (x, y) in start.items():
        lines.append(f"    {k} = Point({_fmt(x)}, {_fmt(y)})")
    for i in range(n):
        lines.append(f"    s{i} = Line(p{i}, p{(i + 1) % n})")
    for i in range(1, n):
        lines.append(f"    OnCircle(p{i}, c)")
    for i in range(n - 1):
        lines.append(f"    Equal(s{i}, s{i + 1})")
    lines += ["    Fixed(p0)", "}"]

    def build():
        import slvs
        slvs.clear_sketch()
        wp = slvs.add_base_2d(1)
        g = 2
        ctr = slvs.add_point_2d(g, 0.0, 0.0, wp)
        slvs.dragged(g, ctr, wp)
        P = {k: slvs.add_point_2d(g, x, y, wp) for k, (x, y) in start.items()}
        nm = slvs.add_normal_3d(1, 1.0, 0.0, 0.0, 0.0)
        rad = slvs.add_distance(g, R, wp)
        circ = slvs.add_circle(g, nm, ctr, rad, wp)
        slvs.diameter(g, circ, 2 * R)
        slvs.dragged(g, P["p0"], wp)
        S = [slvs.add_line_2d(g, P[f"p{i}"], P[f"p{(i + 1) % n}"], wp) for i in range(n)]
        for i in range(1, n):
            slvs.add_constraint(g, slvs.ConstraintType.PT_ON_CIRCLE, wp, 0.0,
                                P[f"p{i}"], slvs.E_NONE, circ)
        for i in range(n - 1):
            slvs.equal(g, S[i], S[i + 1], wp)
        return _slvs_handles(g, P)

    cons = [("on_circle", f"p{i}", 0.0, 0.0, R) for i in range(1, n)]
    cons += [("equal_length", f"p{i}", f"p{i + 1}", f"p{i + 1}", f"p{(i + 2) % n}")
             for i in range(n - 1)]
    spec = {"points": start, "fixed": ["p0"], "constraints": cons}
    return Case("ring", 2 * (n - 1), "\n".join(lines) + "\n", sol, build, spec)


def linkage(n_params: int, seed: int = 0) -> Case:
    rng = np.random.default_rng(seed)
    n = max(2, n_params // 2)               # links
    length = rng.uniform(8, 12, n)
    turn = rng.uniform(30, 60, n) * rng.choice([-1, 1], n)     # degrees, relative
    sol = {"q0": (0.0, 0.0)}
    x = y = heading = 0.0
    for i in range(n):
        if i:
            heading += math.radians(turn[i])
        x += length[i] * math.cos(heading)
        y += length[i] * math.sin(heading)
        sol[f"q{i + 1}"] = (x, y)
    start = _perturb(sol, rng, 1.0, fixed={"q0"})
    lines = ["units mm", "solid linkage {"]
    for k, (px, py) in start.items():
        lines.append(f"    {k} = Point({_fmt(px)}, {_fmt(py)})")
    for i in range(n):
        lines += [f"    l{i} = Line(q{i}, q{i + 1})", f"    Length(l{i}, {_fmt(length[i])})"]
        if i:
            lines.append(f"    Angle(l{i - 1}, l{i}, {_fmt(abs(turn[i]))} deg)")
    lines += ["    Fixed(q0)", "    Horizontal(l0)", "}"]

    def build():
        import slvs
        slvs.clear_sketch()
        wp = slvs.add_base_2d(1)
        g = 2
        P = {k: slvs.add_point_2d(g, px, py, wp) for k, (px, py) in start.items()}
        slvs.dragged(g, P["q0"], wp)
        L = [slvs.add_line_2d(g, P[f"q{i}"], P[f"q{i + 1}"], wp) for i in range(n)]
        slvs.horizontal(g, L[0], wp)
        for i in range(n):
            slvs.distance(g, P[f"q{i}"], P[f"q{i + 1}"], float(length[i]), wp)
            if i:
                # SolveSpace measures the angle between the direction vectors through acos;
                # `inverse` would measure it from the reversed second line
                slvs.angle(g, L[i - 1], L[i], float(abs(turn[i])), wp)
        return _slvs_handles(g, P)

    cons = [("horizontal", "q0", "q1")]
    for i in range(n):
        cons.append(("distance", f"q{i}", f"q{i + 1}", float(length[i])))
        if i:   # the signed turn from link i-1 to link i (radians)
            cons.append(("angle", f"q{i - 1}", f"q{i}", f"q{i}", f"q{i + 1}",
                         math.radians(turn[i])))
    spec = {"points": start, "fixed": ["q0"], "constraints": cons}
    return Case("linkage", 2 * n, "\n".join(lines) + "\n", sol, build, spec)


def hierarchy(n_structures: int, seed: int = 0) -> Case:
    """About ``n_structures`` structures: a row of parts in groups of 10 under
    sub-assemblies, each part a small sketch (a plate of 4 points and 4 lines with a hole
    centered in it: 10 constraints, 2 structures) placed by structural constraints
    (``RightOf``, ``AlignBottom``) and a member equation; every part starts off its place."""
    rng = np.random.default_rng(seed)
    n_structures = max(1, round((n_structures - 1) / 2.1))     # parts: 2 structures each
    groups = max(1, math.ceil(n_structures / 10))
    lines = ["units mm", "assembly row {"]
    made = 0
    for gi in range(groups):
        k = min(10, n_structures - made)
        lines.append(f"    assembly g{gi} {{")
        for j in range(k):
            w, h = rng.uniform(18, 22), rng.uniform(9, 11)
            dx, dy = rng.uniform(-2, 2, 2)
            x0 = 25.0 * j + dx
            lines += [
                f"        solid p{j} {{",
                f"            a = Point({_fmt(x0)}, {_fmt(dy)})",
                f"            b = Point({_fmt(x0 + w * 1.1)}, {_fmt(dy + 0.5)})",
                f"            c = Point({_fmt(x0 + w)}, {_fmt(dy + h * 0.9)})",
                f"            d = Point({_fmt(x0 - 0.5)}, {_fmt(dy + h)})",
                "            bot = Line(a, b)",
                "            rgt = Line(b, c)",
                "            top = Line(c, d)",
                "            lft = Line(d, a)",
                "            Horizontal(bot)",
                "            Horizontal(top)",
                "            Vertical(lft)",
                "            Vertical(rgt)",
                f"            Length(bot, {_fmt(w)})",
                f"            Length(lft, {_fmt(h)})",
                f"            hole bore {{ k = Circle(center=({_fmt(x0 + w / 2 + 1)}, "
                f"{_fmt(dy + h / 2 - 1)}), radius=2) }}",
                "            CenterInside(bore, self)",
                "        }",
            ]
            if j:
                lines.append(f"        RightOf(p{j}, p{j - 1}, gap=5)")
                lines.append(f"        AlignBottom(p{j}, p{j - 1})")
        lines.append("    }")
        if gi:
            lines.append(f"    RightOf(g{gi}, g{gi - 1}, gap=10)")
            lines.append(f"    g{gi}.p0.bb.bottom == g{gi - 1}.p0.bb.bottom")
        made += k
    lines.append("}")
    return Case("hierarchy", 0, "\n".join(lines) + "\n")


def _slvs_handles(g, P):
    import slvs

    def run():
        return slvs.solve_sketch(g, False)["result"] in (0, 4)

    def read(name):
        p = P[name]["param"]
        return slvs.get_param_value(p[0]), slvs.get_param_value(p[1])

    return run, read


def _perturb(sol: dict, rng, size: float, fixed: set) -> dict:
    out = {}
    for k, (x, y) in sol.items():
        if k in fixed:
            out[k] = (x, y)
        else:
            dx, dy = rng.uniform(-size, size, 2)
            out[k] = (x + dx, y + dy)
    return out


FLAT = {"rectangles": rectangles, "islands": islands, "ring": ring, "linkage": linkage}
