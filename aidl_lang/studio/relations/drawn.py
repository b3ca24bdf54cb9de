"""An imported drawing's inferred relations as the studio's sliders (issue 94): the program
``aidl import --infer`` writes for a drawing gives each size its own ``param`` with no range,
so a slider can move one size past another (a round flange at 70 mm with its 75 mm bolt circle:
the holes break through the edge; at 25 mm its 40 mm bore removes all of it: an empty file).
:func:`with_relations` writes the ranges that keep the features inside each other, as the
gallery's forms do (docs/studio.md, "Forms that cannot fail"): a bound follows the params
declared above it, and the compile worker moves a value that leaves its range back into it
(:func:`aidl_lang.studio.compiler.settle`), so the holes follow the body's size.

What is related (found in the program's syntax, never in its param names):

* a round body ``Circle(center=C, diameter=D)`` with a bolt circle about its centre, a
  ``for i in range(N)`` of holes ``Circle(center=polar(C, P / 2, ...), diameter=d)``, and a bore
  ``Circle(center=C, diameter=B)`` on the bolt circle's centre (optional): the holes stay
  :data:`WALL` inside the edge and clear of the bore, the bore inside the holes, and ``N``
  holes fit round the circle without touching.

A rectangular plate's grid of holes about its centre or from an end member, a panel's window
with its four screws, and its corner holes (:mod:`.plates`), are related the same
way.

Anything else of the program is left as it is (its sliders keep their default spans).
Not part of the stable API.
"""
from __future__ import annotations

from ... import ast as A
from .plates import (bore_skip, corner_ranges, grid_place, grid_ranges, window_place,
                              window_ranges)
from .syntax import WALL, _circles, _fmt, _kw, _name, _params, _text

__all__ = ["WALL", "flange_ranges", "with_relations"]


def _bolt_circle(source, prog, params):
    """``(N, P, d, centre text)`` of the first loop of holes on a pitch circle, or None."""
    for loop in (n for n in A.walk(prog) if isinstance(n, A.For)):
        it = loop.iter
        if not (isinstance(it, A.Call) and isinstance(it.func, A.Name) and it.func.id == "range"
                and len(it.args) == 1 and _name(it.args[0], params)):
            continue
        for c in _circles(loop.body):
            centre, d = _kw(c, "center"), _name(_kw(c, "diameter"), params)
            if not (d and isinstance(centre, A.Call) and isinstance(centre.func, A.Name)
                    and centre.func.id == "polar" and len(centre.args) >= 2):
                continue
            half = centre.args[1]
            if isinstance(half, A.BinOp) and half.op == "/" and isinstance(half.right, A.Num) \
                    and half.right.value == 2 and _name(half.left, params):
                return it.args[0].id, half.left.id, d, _text(source, centre.args[0])
    return None


def _round_body(source, prog, params, skip: set, centre: str) -> str | None:
    """The diameter param of the program's round outline: a ``Circle`` outside every
    ``hole`` (the body) centred where the bolt circle is (``centre``, or a name assigned
    that point as written)."""
    holes = {id(n) for s in A.walk(prog) if isinstance(s, A.StructDecl) and s.kind == "hole"
             for n in A.walk(s)}
    same = {centre} | {_text(source, a.value) for a in A.walk(prog)
                       if isinstance(a, A.Assign) and a.name == centre}
    for c in _circles(prog):
        d, at = _name(_kw(c, "diameter"), params), _kw(c, "center")
        if id(c) not in holes and d and d not in skip and at is not None \
                and _text(source, at) in same:
            return d
    return None


def _bore(source, prog, params, centre: str, skip: set) -> str | None:
    for c in _circles(prog):
        d, at = _name(_kw(c, "diameter"), params), _kw(c, "center")
        if d and d not in skip and at is not None and _text(source, at) == centre:
            return d
    return None


def flange_ranges(source: str, prog, params) -> dict[str, str]:
    """``{param: ", min = ..., max = ..."}`` of a round body with a bolt circle (and a bore),
    in the order they must be declared; {} when the program has none."""
    found = _bolt_circle(source, prog, params)
    if found is None:
        return {}
    n, pcd, d, centre = found
    body = _round_body(source, prog, params, {n, pcd, d}, centre)
    if body is None:
        return {}
    bore = _bore(source, prog, params, centre, {n, pcd, d, body})
    v = {k: params[k].value.value for k in (n, pcd, d, body) + ((bore,) if bore else ())}
    w = _fmt(WALL)
    lo_d = v[d] / 4
    lo_b = v[bore] / 4 if bore else 0.0
    inner = f"{bore} + {d} + {_fmt(2 * WALL)} mm" if bore else f"{d} + {_fmt(2 * WALL)} mm"
    out = {body: f", min = {_fmt(lo_b + 2 * lo_d + 4 * WALL)} mm, max = {_fmt(2 * v[body])} mm",
           d: f", min = {_fmt(lo_d)} mm, max = ({body} - {_fmt(lo_b + 4 * WALL)} mm) / 2"}
    if bore:
        out[bore] = f", min = {_fmt(lo_b)} mm, max = {body} - 2 * {d} - {_fmt(4 * WALL)} mm"
    out[pcd] = f", min = {inner}, max = {body} - {d} - {_fmt(2 * WALL)} mm"
    # N holes on the circle clear each other by WALL: the chord of 360/N is at least 0.8 of
    # its arc from N = 3 up (N = 2: the holes are a whole pitch circle apart)
    out[n] = (f", min = 1, max = max(2, min({max(16, 2 * int(v[n]))}, "
              f"floor(2.5 * {pcd} / ({d} + {w} mm))))")
    return out


_FINDERS = (   # the first that finds its relations in the program writes them
    (flange_ranges, "the bolt circle follows the outline's size: its holes stay {wall} mm "
                    "inside the edge and clear of the bore, and as many fit as its slider offers"),
    (grid_ranges, "the hole grid {place} as the plate's size changes: its holes "
                  "stay {wall} mm inside the edges and clear of each other and of a bore, and "
                  "as many fit as its sliders offer{skip}"),
    (corner_ranges, "the corner holes keep their inset as the plate's size changes: each "
                    "stays {wall} mm inside both edges, clear of the others"),
    (window_ranges, "the window and its screws stay {place} as the plate's size changes: "
                    "each {wall} mm inside the edges, the screws {wall} mm clear of the "
                    "window's corners"))
_PLACES = {grid_ranges: grid_place, window_ranges: window_place}


def with_relations(program: str, path: str = "main.aidl") -> tuple[str, list[str]]:
    """``program`` (what ``aidl import --infer`` wrote) with the ranges of the features it
    relates (see the module's docstring), its ``param`` lines in the order the ranges need,
    and a note for each relation written; the program as it is, ``[]``, when it has none or
    does not parse, or when a range would not hold the drawing's own values."""
    from ...base.diagnostics import DiagnosticSink
    from ...parser import parse
    sink = DiagnosticSink()
    prog = parse(program, path, sink)
    if sink.has_errors or prog is None:
        return program, []
    params = _params(prog)
    for find, note in _FINDERS:
        ranges = find(program, prog, params)
        if ranges:
            break
    else:
        return program, []
    lines = program.splitlines(keepends=True)
    skip = bore_skip(program, prog, params) if find is grid_ranges else None
    if skip is not None:
        _wrap(lines, *skip)
    decls = [s for s in prog.stmts if isinstance(s, A.ParamDecl)]
    rows = {s.name: s.span.line - 1 for s in decls}
    if any(s.span.line != s.span.end_line for s in decls if s.name in ranges):
        return program, []
    order = list(ranges)
    first = min(rows[n] for n in order)
    new = []
    for i, line in enumerate(lines):
        if i == first:
            for name in order:
                new.append(_ranged(lines[rows[name]], params[name], program, ranges[name]))
        if i in {rows[n] for n in order}:
            continue
        new.append(line)
    text = "".join(new)
    if not _holds(text, path):
        return program, []
    place = _PLACES[find](program, prog, params) if find in _PLACES else ""
    return text, [note.format(wall=_fmt(WALL), place=place, skip=(
        " (at odd counts both ways, the hole that would fall on the bore is left out)"
        if skip else ""))]


def _wrap(lines: list[str], first: int, last: int, condition: str) -> None:
    """Lines ``first``..``last`` of ``lines`` inside ``if condition { ... }``, one level in
    (each element may then hold several lines: the count of elements stays)."""
    pad = lines[first][:len(lines[first]) - len(lines[first].lstrip())]
    for k in range(first, last + 1):
        if lines[k].strip():
            lines[k] = "    " + lines[k]
    if not lines[last].endswith("\n"):
        lines[last] += "\n"
    lines[first] = f"{pad}if {condition} {{  # no hole on the bore\n" + lines[first]
    lines[last] += f"{pad}}}\n"


def _ranged(line: str, decl, source: str, options: str) -> str:
    """The ``param`` line with ``options`` after its value (its comment kept)."""
    end = decl.value.span.end - _line_start(source, decl.span.start)
    nl = "\n" if line.endswith("\n") else ""
    body = line.rstrip("\n")
    return body[:end] + options + body[end:] + nl


def _line_start(source: str, at: int) -> int:
    return source.rfind("\n", 0, at) + 1


def _holds(text: str, path: str) -> bool:
    """The program with its ranges still compiles at its own values (no E0124)."""
    import os
    import tempfile

    from ... import api
    with tempfile.TemporaryDirectory(prefix="aidl-relations-") as d:
        return api.compile(source=text, path=os.path.join(d, os.path.basename(path))).ok
