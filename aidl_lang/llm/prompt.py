"""The system prompt for an LLM that writes AIDL (``aidl prompt``).

Built from the registry (every primitive, constraint, structural relation, operation and
function with its signature and one-line doc; of the synonyms only those that swap their
arguments, since the others are accepted silently), from the standard library's doc comments
(every template with its signature and the first sentence of the comment above its ``def``:
:func:`aidl_lang.library.reference.stdlib_lines`) and from a few bundled example programs, so it never
drifts from the implementation.  It is kept compact because a model reads it on every
call: :func:`word_count` measures it (about 0.75 words per token for English and code).
"""
from __future__ import annotations

import re

from ..library.reference import stdlib_lines
from ..registry import (BBOX_MEMBERS, ENTRIES, FUNCTIONS, SWAPPED, SYNONYMS, UNITS_ANGLE,
                        UNITS_LENGTH)
from ..library.sources import EXAMPLES as EXAMPLES_DIR    # inside the package: shipped in the wheel
# short and varied, most useful first: holes, loops and bounding-box equations; templates,
# fillets and patterns; hierarchy + stacking relations; drawings, text and params.
# `aidl prompt` gives the first DEFAULT_EXAMPLES; `--examples N` the first N.
PROMPT_EXAMPLES = ["bottle_opener.aidl", "bracket.aidl", "toy_sword.aidl", "name_tag.aidl"]
DEFAULT_EXAMPLES = 2

INTRO = """\
You write AIDL, a text language for 2D CAD parts (output: SVG, DXF, PDF, G-code, LightBurn
`.lbrn2`, HPGL `.plt`). Reply with one complete program in a ```aidl code block.

A program is a tree of named structures: `solid NAME { ... }` (filled; unions its children),
`hole NAME { ... }` (cut out of the enclosing solid; in a drawing: hides its lines there, drawing none of its own,
which a solid's hole does not: they run across it), `cut NAME { ... }` (in a solid: the
laser cuts along each curve, open Lines too: slits; in an assembly: on the sheet, no part), `drawing NAME { ... }` (engraved lines
and text; a closed shape with `fill=true`: its area engraved filled), `assembly NAME { ... }` (separate parts). Inside a structure: geometry
(`body = Rectangle(center=(0, 0), width=40, height=20)`), child structures, constraints as
statements (`Above(lid, body)`, `Coincident(a.end, b.start)`) and equations
(`lid.bb.width == body.bb.width`, `x <= 60`; join with `and`). Geometry and constraints only
live inside structures. Top of file: `units mm` (default; also `units in`), `param NAME = VALUE,
min = LO, max = HI` (always declare the range it still works across: sliders use it; a
param may be computed from params and constants above it, `param h = w / 2`, and follows
`--set w=60`),
constants `NAME = expr`, functions `def f(v) = 225 deg - v * 27 deg` (one line, a value or a shape), templates `def NAME(p1, p2=default) -> solid { ... }` (at the top or in a structure; instantiate:
`part = NAME(p1=...)`, numbers known before solving, not a shape's `bb`; `part.p1` reads its argument, a stdlib one's too), `import "file.aidl"` or `import stdlib.shapes` (or
`.gears`, `.joints`, `.fasteners`, `.plates`). Control flow:
`for i in range(n) { ... }` (a name set in a loop: the current copy inside, the list after:
`knob[0]`; nested loops: `dia[i][j]`; a relation per copy, labels on holes:
`for i in range(4) { At(names.t[i].position, holes.c[i].center, dy=-8) }`),
`if c { } else { }`, `[f(i) for i in xs]`, `xs + ys` (lists join). Operators: `+ - * / % **`, `//` (floor division),
comparisons, `and or not`, `a if c else b`; `range(start, stop, step)`. A statement ends at
the line break: continue a long one inside `( )` or `[ ]`, or end the line with `,` or an operator (`and`, `+`) and indent the next deeper. Comments start with `#` (not `//`). Numbers take units (`5 mm`, `2 in`, `30 deg`); a bare
number is a length in the file unit or an angle in degrees where one is expected (passed to a
`def`, it stays plain: `f(p, 10 mm)`; but `sin`/`cos`/`tan` read
radians: write `cos(i * 10 deg)`); `pi`, `tau` count radians: `a + pi / 2` is `a + 90 deg`;
`x * 1 rad` is an angle.

Constructor dimensions (width, radius, ...) are held; positions are starting guesses: what
no constraint pulls on stays exactly where it is written; a part stays, its features (holes,
child solids, pattern targets) are placed on it (no `Fixed` needed), a feature whole (placing one
Text of a drawing moves the drawing: give it its own); of two parts or two shapes
related, the first-named moves to the second (`AlignCenterX(knight, base)` moves the knight). A point at a radius and angle
from a centre: `Coincident(p, polar(c.center, 20, 30 deg))` (exact; Distance + Horizontal
also fit its mirror image); points add and scale: a quarter along a line is
`l.start + (l.end - l.start) * 0.25`. Relate parts with
constraints instead of computing coordinates. A shape given by literal coordinates
(`Polygon([(0, 0), (10, 0), (5, 8)])`) keeps its shape when constraints move it;
`flexible=true` (Triangle, Polygon, Polyline, Spline, Bezier) frees its points. A definition
may only use names defined above it; constraint statements may name geometry defined later.
A child structure's geometry is `child.name`, the current one is `self`; every geometry and
structure has `.bb` (bounding box). A structure's box covers all it holds, holes included (a
hole poking past the edge widens it; construction geometry and `overrun=true` shapes do not
count): for the material
alone use a shape's box (`plate.body.bb`); a Spline's box swells past its points (assert on `points[i]` for a point; the box is the cut part).
Rules: a constraint may only refer to its own structure's subtree; geometry may only reuse
points of its own structure (in `hole ring { }` a Circle cannot read its parent's `word.bb.left`
(E0201): give it numbers and place it by a constraint in the parent, `Concentric(ring.c, loop)`). Booleans: a solid is the union of its shapes and solid children
(touching or overlapping parts merge into one outline; Lines and Arcs meeting end to end
close into one: an arched top is `Arc(start=..., through=..., end=...)` between Lines) minus
its hole children. So
a hole cuts the solid it is declared in, that solid's own shapes and solid children alike:
```aidl
solid plate {
    body = Rectangle(center=(0, 0), width=60, height=30)
    solid boss { c = Circle(center=(-15, 10), radius=8) }  # plate's child: bore cuts it too
    hole bore { c = Circle(center=(-15, 10), radius=4) }   # opening through body and boss
}
```
A hole declared inside `boss` would cut only boss, and plate's `body` would fill it again:
the cut solid is united with its own siblings, which are not cut. Patterns and Mirrored put
copies beside the original, in the original's structure.
`Fixed(x)` holds a point, shape or structure where it starts in its structure, which
carries it when placed (an instance moved by `RightOf` takes its holes along). A shape with a `rotation=` (0
when not given: Rectangle, Slot by center, RegularPolygon, Ellipse, Star, Text) or a Polygon
of literal points never turns while solving: it only moves. Shapes through guessed points (a
Line, an Arc, a Slot or Rectangle by start and end) may turn; a Line needs two distinct points (W0524). `Rigid(a, b, ...)` keeps
shapes placed relative to each other (moved together);
`Rigid(s)` makes a structure move whole, never bent; `Rigid(s1, s2, ...)` moves any number of
structures as one body.
`assert cond, "why"` (in a structure or at the top) is a requirement checked after solving,
never solved for (false: error E0405): write limits ("fits the bed") as asserts and what the
solver should make true as constraints. Also assert the request's own numbers and counts as it
words them (`assert len(feet) == 2`, `assert lip.bb.top - base.bb.top == 8 mm`: differences,
as a relation that lays a part out moves its coordinates; an assert reads `Place`d parts where
they are written; `assert distance(label, holes) >= 2 mm`: the gap between shapes), each number
copied from the request, never from the program: a slip then fails the check instead of reaching the cutter. `thickness 3 mm` (the material, for 3D outputs and
the parts list; a box template's `thickness=` is the same), `kerf 0.15 mm` (the laser's cut width: cuts are offset by half of it)
and `min_wall 0.3 mm` (W0507 warns of walls thinner than 0.5 mm, which a laser burns through;
a thin wall or sharp tip the request asks for is meant: state `min_wall`, never change a
requested size; `min_wall 0`: not laser-cut) are statements without `=` (`thickness = 3 mm` is a mere constant) that
stand at the top or inside a structure (for it and its children); `-o x.gcode`: G-code
(`aidl docs machine`).
Conventions: y points up; angles and `rotation=` turn counter-clockwise from +x. At rotation
0: a RegularPolygon's first vertex is on +x (a hexagon has flats at top and bottom), a
Triangle(center, base, height) points up (apex c at +y; center: its box's, so a hexagram is
two `RegularPolygon(center, radius, 3)`, rotation 90 and 270 deg; a heart: `Hull(Circle(center=(-8, 5),
radius=9), Point(0, -16))` and its mirror at x 8, in a structure with `Rigid(self)` when a relation
places it), a Slot lies along x; a Slot's length
is end to end; a Text position is on the baseline (set `valign="middle"` to center it).
Letters as the part (cake topper, sign, house number): `Text(..., font="sans:Bold")` (or "serif",
a .ttf) is filled outlines: material in a solid (join them: a rail `width=word.bb.width`, a bar under each letter, or
one solid per letter),
openings in a hole (`stencil=true` holds counters), engraved in a drawing (`fill=true`: their
area); without `font=` Text is engraved strokes, in ASCII only (other letters: `font=`).
Each child of an `assembly` is a separate part (written inside it, or `part = TEMPLATE()`; `part = NAME` of a
solid outside it makes no part: E0202 or E0108), drawn where the solver puts it (`RightOf` sets x only, `Below` y only: pair each with an
`AlignTop`/`AlignLeft`; overlapping parts: W0511 unless
`AllowOverlap(a, b)`; `aidl render --layout sheet` nests them for cutting).
- Place(part, position=(x, y, z), face="front", up="up") in its assembly places a part in 3D
(numbers known before solving) for `--assembled`: face= where its top face (engraving,
countersinks) looks ("front" is -y, "back", "left", "right", "up", "down", or (0, -1, 1)), up=
where its drawing's +y goes, position= its bottom face's (0, 0) (or rotation=(rx, ry, rz));
on=part: position and turn in that part's frame ((x, y): on its top face);
W0517/W0518: parts collide, or touch nothing.
- Bend(part, at=x, angle=90 deg, radius=r) bends a placed part there (a living hinge).
Screw heads: `Countersink(holes, diameter=9 mm)` on the holes (a pattern's copies follow their original), never an engraved ring.
A warning on a design exactly as requested is accepted in the program, never by changing a
requested size: `min_wall` (W0507, W0519, W0520), `AllowOverlap(a, b)` (W0501, W0508, W0511,
W0512, W0517; `AllowOverlap(lines, self)`: W0505, W0516; `AllowOverlap(labels)`: W0513; `AllowOverlap(labels, part)`: W0532), `construction=true` (W0506), an `assembly` for separate pieces (W0504).
`aidl check` ends
with `fully constrained` or `N degrees of freedom left`: harmless: "stays where written on its part" (it moves with its part);
"can slide" needs constraints.
`aidl check --describe` describes the final part. `aidl import --infer d.dxf` writes a
drawing as a program. `aidl set f.aidl NAME=VALUE` changes a param's value in the file. `aidl check --sweep` tries each `param`'s range and says the clean one.
There is no Rotate/Union. A warning means the program runs but probably not as
meant: fix it. When fixing errors, keep
every structure and constraint that carries design intent: correct the call rather than
delete it.
"""


def _sig(entry) -> str:
    outs = []
    for v in entry.variants:
        parts = []
        for a in v:
            if a.kw_only:
                continue
            if a.shown_required or entry.varargs:
                parts.append(a.name)
            else:
                parts.append(f"{a.name}={a.default_text}")
        outs.append(f"{entry.name}({', '.join(parts + ['...'] * entry.varargs)})")
    return " | ".join(outs)


def vocabulary() -> str:
    """Signatures and one-line docs of the whole registry, grouped by category."""
    titles = {"primitive": "Geometry (every form also takes `construction=true`: solved, not drawn)",
              "constraint": "Geometric constraints", "structural": "Structural relations "
              "(between structures or geometry, by bounding box)",
              "operation": "Operations"}
    out = []
    for cat, title in titles.items():
        rows = [f"- {_sig(e)}: {e.doc}" for e in ENTRIES.values() if e.category == cat]
        if rows:
            out.append(f"{title}:\n" + "\n".join(rows))
    out.append(members())
    # other names a model guesses (Orthogonal, ConvexHull, ...) are accepted silently and
    # need no words here; only the ones with swapped arguments change the meaning
    out.append(" ".join(f"{s}(a, b) means {SYNONYMS[s]}(b, a)." for s in SWAPPED))
    out.append("Functions: " + ", ".join(f"{n}" for n in FUNCTIONS) + " (asin, acos, atan, "
               "atan2 give angles); f-strings "
               "`f\"{d:.1f} mm\"`; constants pi, tau, true, false; units " + ", ".join(list(UNITS_LENGTH) + list(UNITS_ANGLE)) + ".")
    return "\n\n".join(out)


def members() -> str:
    """The members of every shape and of bounding boxes by kind, from the registry: points
    (for Coincident, At, Distance, ...), lines (Parallel, Horizontal, Length, ...) and numbers
    (lengths, coordinates, angles: for equations).  ``.bb`` is omitted per shape: the intro says
    every geometry and structure has it.  Shapes with the same members share a row."""
    kinds = {"point": "points", "points": "point lists", "line": "lines", "lines": "line lists",
             "shapes": "lists", "circles": "lists", "curves": "lists"}
    rows, seen = [], {}
    for e in list(ENTRIES.values()) + [None]:
        table = BBOX_MEMBERS if e is None else e.members
        name = ".bb" if e is None else e.name
        if not table:
            continue
        groups: dict[str, list[str]] = {k: [] for k in ("points", "lines", "numbers",
                                                         "point lists", "line lists")}
        for m, kind in table.items():
            if m != "bb":
                groups.setdefault(kinds.get(kind, "numbers"), []).append(m)
        cells = "; ".join(f"{k}: {' '.join(v)}" for k, v in groups.items() if v)
        if cells in seen:
            seen[cells].append(name)
        else:
            seen[cells] = [name]
            rows.append(cells)
    lines = [f"- {', '.join(next(n for c, n in seen.items() if c == cells))} | {cells}"
             for cells in rows]
    return ("Members by kind (`rect.top_left` is a point, `rect.top` a line, `s.bb.center_x` a "
            "number):\n" + "\n".join(lines))


def _strip(text: str) -> str:
    """An example without its `Try:` line and blank-line runs."""
    lines = [ln for ln in text.splitlines() if not re.match(r"\s*#\s*Try:", ln)]
    return re.sub(r"\n{3,}", "\n\n", "\n".join(lines)).strip()


def example_programs(names: list[str] | None = None) -> list[tuple[str, str]]:
    """(file name, program text) of the prompt's examples."""
    out = []
    for n in names or PROMPT_EXAMPLES:
        out.append((n, _strip((EXAMPLES_DIR / n).read_text(encoding="utf-8"))))
    return out


def stdlib(defaults: bool = True) -> str:
    """The standard library's templates, one line each, from their doc comments (without the
    parameters' defaults when ``defaults`` is false: ``aidl docs NAME`` gives them)."""
    return ("Standard library: templates to instantiate, never to rewrite by hand (each also "
            "takes `cx, cy`: the point after `@` on its line, `@ X` the centre of X; yours do "
            "not: `part.bb.center == (x, y)` "
            "places them; `aidl docs NAME` gives every "
            + ("" if defaults else "default, ") + "unit, "
            "member and an example):\n" + stdlib_lines(defaults))


AGENT_EXAMPLES = 1       # the MCP prompt's examples; the rest are resources (aidl://examples/)


def agent_prompt() -> str:
    """The system prompt for an agent that has ``aidl mcp``'s tools (``aidl://prompt``, the
    ``aidl`` prompt; the server words it for the tools): :func:`system_prompt` with the
    standard library's signatures without their defaults (the ``docs`` tool gives them, with
    units and an example) and :data:`AGENT_EXAMPLES` example program (every example is a
    resource), so that what the tools' descriptions and ``docs`` say is not said twice
    (issue 86: 29,460 characters before)."""
    parts = [INTRO, vocabulary(), stdlib(defaults=False), "Examples (more: the resources "
             "aidl://examples/NAME.aidl):"]
    for name, text in example_programs(PROMPT_EXAMPLES[:AGENT_EXAMPLES]):
        parts.append(f"```aidl\n{text}\n```")
    return "\n\n".join(p.strip() for p in parts) + "\n"


def system_prompt(examples: bool | int = True) -> str:
    """The whole system prompt: description, vocabulary, standard library and example
    programs: ``examples`` of them (``True``: :data:`DEFAULT_EXAMPLES`; ``False``/0: none;
    at most all of :data:`PROMPT_EXAMPLES`)."""
    n = DEFAULT_EXAMPLES if examples is True else int(examples)
    parts = [INTRO, vocabulary(), stdlib()]
    if n > 0:
        parts.append("Examples:")
        for name, text in example_programs(PROMPT_EXAMPLES[:n]):
            parts.append(f"```aidl\n{text}\n```")
    return "\n\n".join(p.strip() for p in parts) + "\n"


def word_count(text: str) -> int:
    """Whitespace-separated words (a rough token estimate: tokens ~ 1.3-1.5 x words for code)."""
    return len(text.split())


def code_blocks(text: str) -> list[str]:
    """The contents of every ```aidl fenced block in ``text``."""
    return re.findall(r"```aidl\n(.*?)```", text, re.S)
