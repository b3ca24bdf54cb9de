"""Every diagnostic code with a title and a longer explanation (``aidl explain CODE``)."""

CODES: dict[str, tuple[str, str]] = {
    "E0001": ("syntax error", """
The text does not follow AIDL's grammar. The message lists what the parser expected at that
point. The parser skips the bad statement and goes on, so later errors are reported too.

    solid plate {
        body = Rectangle(center=(0, 0) width=40, height=20)   # missing `,`
    }
"""),
    "E0002": ("unexpected character or unterminated string", """
A character that cannot start any token, or a string without its closing quote.

    label = "Hello      # close the string: "Hello"
"""),
    "E0003": ("nesting too deep", """
Brackets are nested more than 64 levels deep. Split the expression into named constants.
"""),
    "E0004": ("cannot read the input file", "The file does not exist, is not a regular file (a folder, a FIFO, a device such as /dev/zero), is larger than 1000000 bytes (the limit of an import too), or is not UTF-8 text; it is refused before it is read whole or lexed."),
    "E0101": ("unknown name", """
A name is used that is not defined in this structure, an enclosing one, or the file
(params, constants, templates). The message suggests the nearest known names.

    solid s { c = Circle(center=(0, 0), radius=rad) }   # `rad` is not defined
"""),
    "E0102": ("unknown member", """
`thing.member` names a member that `thing` does not have. Rectangles have top_left, top_right,
bottom_left, bottom_right, center, top/bottom/left/right (edges), width, height, bb; lines have
start, end, midpoint, length; circles have center, radius, diameter; structures have their
children, their named geometry and `bb`.

    corner = body.top_lft     # did you mean `top_left`?
"""),
    "E0103": ("unknown function, primitive or constraint", """
The called name is not a primitive (Circle, Rectangle, ...), a constraint (Coincident, Above,
...), a function (sin, sqrt, range, ...) or a template defined with `def`.

    Rotate(body, 30 deg)     # there is no Rotate: use `rotation=30 deg` or Angle(...)
"""),
    "E0104": ("wrong number or combination of arguments", """
The call has more positional arguments than the primitive or constraint takes, in any of its
forms, or arguments that no one form takes together. The message names the arguments that do
not fit with the others (those outside a form the rest complete); the hint lists the accepted
forms.

    Circle((0, 0), 5, 7)     # Circle(center, radius)
    Arc(radius=5, start=(0, 0), end=(10, 0))
        # `Arc` has no form taking `radius` with `start` and `end`: Arc(center, start, end),
        # Arc(center, radius, start_angle, end_angle) or Arc(start, through, end)
"""),
    "E0105": ("unknown keyword argument", """
A keyword argument that the primitive, constraint or template does not have.

    Circle(center=(0, 0), radius=5, width=3)     # a circle has no `width`: its size is `radius`

When the argument belongs to a sibling constructor the message names it and the fix is the same
call under the sibling's name: `Rectangle(..., corner_radius=3)` (or `fillet=`, `radius=`,
`rounded=`) becomes `RoundedRectangle(..., corner_radius=3)`; `Circle(..., rx=, ry=)` an
`Ellipse`, `Ellipse(..., radius=)` a `Circle`, `Arc(..., width=)` an `ArcSlot`. Only the standard
library's templates take `cx`, `cy`: given to a template of your file (with no such parameter)
they are one error whose fix places the instance by a constraint instead
(`k = knob(r=4, cx=10, cy=5)` becomes `k = knob(r=4)` and `k.bb.center == (10, 5)`).
"""),
    "E0106": ("missing argument", """
A required argument is missing. Dimensions (width, height, radius) are required because they
are the design intent that the solver holds.

    Rectangle(center=(0, 0), width=10)     # height is missing
"""),
    "E0107": ("name defined twice", """
Two geometry objects or structures of one structure have the same name.

    a = Circle((0, 0), 2)
    a = Circle((5, 0), 2)     # name the second one `b`

A param is declared once, and no top-level `name = ...` assigns its name: the second
declaration would silently win, even for code above it, and its slider and `--set` would read
the other range.

    param w = 60 mm, min = 10 mm, max = 100 mm
    param w = 80 mm, min = 70 mm, max = 90 mm     # keep one `param w`

A template or function is defined once in a file (a `def` written in a structure is defined for
the whole file): the later one would be what every call made, those above it too.
"""),
    "E0108": ("wrong type", """
A value of the wrong kind: a length where a point is expected, a Circle where a Line is
expected, constraints joined with `or` (an `assert`, a check, takes `or` and `!=`), and so on. A template's argument of another kind
than its parameter's default is this error at the argument, before the template runs, with the
template's reasons for that parameter as the hint.

    Horizontal(wheel)      # Horizontal takes a Line or two points, wheel is a Circle
    Scale(plaque, 0)       # a factor is more than 0 (0.7: 30 % smaller; a mirror is Flip)
    g = spur_gear(teeth="twelve")   # `teeth` of `spur_gear` is a number like its default `20`
"""),
    "E0109": ("unit mismatch", """
Lengths, angles and plain numbers cannot be mixed in + - and comparisons. A bare number
adapts: it is in the file's unit next to a length and in degrees next to an angle. A
template's argument of the other unit kind than its default (`thickness=3 deg` for
`thickness=3 mm`; in the standard library, a length for a count such as `teeth=20`) is this
error at the argument.

    w = 10 mm + 30 deg      # a length plus an angle
"""),
    "E0110": ("index out of range", """
A list is indexed past its end. Lists from loops and comprehensions are indexed from 0.

    holes = [Circle((i * 10, 0), 2) for i in range(4)]
    Fixed(holes[4])      # valid indices are 0 to 3
"""),
    "E0111": ("not iterable / not callable / not indexable", """
A `for` loop over something that is not a list, a call of a value, or indexing a non-list.
"""),
    "E0112": ("math error", "Division by zero, sqrt of a negative number, and similar."),
    "E0113": ("bad --set override", """
`--set NAME=VALUE` names a param the file does not declare, its value cannot be read, or the
value is of another kind than the param's default (a length for an angle, a word for a
number). The error names the `--set` argument (also a value given to `aidl_lang.compile`
or a live-preview slider); the file is then compiled with the default, so its uses of the
param are not blamed. Declare overridable values with `param NAME = VALUE` at the top of
the file. `aidl set` and MCP `set_params` also refuse a value that holds a comment
(`aidl set f.aidl 'w=40 mm # x'`): written in place of the value it would comment out the
rest of the line, the param's `min=`/`max=` with it (located at the value, the file left as
it was).

    param leg = 100 mm
    aidl check part.aidl --set leg=100 deg   # `leg` is a length like its default `100 mm`
"""),
    "E0114": ("import not found or not allowed", """
`import "file.aidl"` resolves relative to the importing file and must stay inside that file's
folder tree; `import "std/NAME.aidl"` reads the standard library. Nothing else can be read.
"""),
    "E0115": ("import cycle", "Two files import each other. Move shared templates to a third file."),
    "E0130": ("drawing cannot be read", """
`Drawing2D("FILE")` (or `aidl import FILE`) names a DXF or SVG drawing that cannot be read:
missing (with did-you-mean from the same folder), outside the program's folder tree, not a
regular .dxf or .svg file, larger than 20000000 bytes, with more than 120000 entities, not a
DXF or SVG its reader understands, or with an unknown unit; or an entity of it has a
coordinate, radius or size that is not finite (inf, nan) or beyond the model extent of 1e6 mm
(1 km), as a program's may not be: the message names the entity (DXF: its kind, handle and
line; SVG: the element and its id). Nothing is written.

    board = Drawing2D("../board.dxf")      # leaves the project folder: copy it next to the program
"""),
    "E0131": ("drawing chain not closed where an outline is needed", """
A `Drawing2D` in a solid or hole must give closed outlines, but the drawing (or the layers,
colours or ids selected) holds an open chain of lines, arcs or splines, or a loop that crosses
itself. The message gives the gap and its two ends (or the crossing point) in the drawing's
coordinates. Close the outline in the drawing, select only the closed outlines, or put the
Drawing2D in a `drawing` (engraving) or give it `construction=true`.

    solid plate { d = Drawing2D("sketch.dxf") }     # a chain with a 0.2 mm gap: close it
"""),
    "E0132": ("nothing selected in the drawing", """
The layer, colour or id given to `Drawing2D` (or `aidl import --layer`) selects nothing that
can be imported: no such layer or id (the message suggests the nearest ones), or only entities
that were left out. For a DXF the message lists what the file (or the selection) holds, counted
by type and layer, and why each kind was left out (not in the drawing plane, no exact form
here, numbers that give no shape), in `Drawing2D` and `aidl import` alike.

    board = Drawing2D("board.dxf", layer="Edge_Cuts")   # did you mean `Edge.Cuts`?
"""),
    "E0133": ("font cannot be found or read", """
`Text(..., font=...)` names a font that cannot be had: a family that is not installed (the
hint lists the families found: `"sans"` and `"serif"`, which install with the package, every
`fontpkg-*` family installed from PyPI, and, where fontconfig is present, the families it
knows), a style word that is no weight or slant, a weight the family lacks, or a `.ttf`,
`.otf` or `.ttc` file that is missing, outside the program's folder tree, larger than
50000000 bytes or not a font fontTools can read.

    t = Text("HAPPY", position=(0, 0), size=20, font="Comic Sans")   # not installed: "sans"
"""),
    "E0134": ("text draws nothing", """
A `Text` whose every character (but spaces) is missing from its font draws nothing: nothing is
engraved, and a stencil cuts nothing. The single-stroke font (no `font=`) covers printable
ASCII and the symbols `° ± × µ Ø ø ⌀`; a font named by `font=` covers what its file holds
(`"sans"` and `"serif"`: Latin, Greek and Cyrillic). The error names the characters; where
fontconfig is present, the hint names an installed family that has them all (run ec's `福`:
`font="Droid Sans Fallback"`). Some characters missing, the rest drawn, is `W0105`.

    drawing labels { t = Text("福", (0, 0), size=20) }    # no glyph: nothing drawn
"""),
    "E0116": ("top-level statement inside a structure", """
`param`, `import` and `units` belong at the top level of a file. (A `def` may stand inside a
structure: it is defined for the whole file, as if written above the structure.)
"""),
    "E0117": ("geometry outside a structure", """
Geometry and constraints live in a structure. Loose top-level geometry is put into an implicit
root named `model`, but inside a template call or a constant it has nowhere to go.
"""),
    "E0118": ("value depends on the solver", """
Conditions (`if`, `a if c else b`, comprehension filters), `//`, `%`, round() and f-strings need
values known before solving. Geometry positions are only known after the solve: write a
constraint instead, or test a param.
"""),
    "E0119": ("template instance without a name", """
A template call creates a child structure, and structures have names: `left = wheel(r=10)`.
In a list comprehension (`[wheel(r=i) for i in range(3)]`) its instances cannot be named:
write a loop, `for i in range(3) { w = wheel(r=i) }`; after it `w` is the list of the copies.
"""),
    "E0120": ("Text outside a drawing", """
Text is drawn as single-stroke lines, so it belongs in a `drawing` structure:

    solid tag {
        plate = RoundedRectangle(center=(0, 0), width=60, height=20, corner_radius=3)
        drawing label { t = Text("AIDL", position=(0, -2), size=8) }
    }

To cut the letters out (a stencil, bridged), write `stencil=true` and put it in a hole:
`hole letters { t = Text("HELLO", position=(0, 0), size=30, stencil=true) }`. A Text in a
font (`font="sans"`: the letters' closed outlines) stands in a solid (material), a hole
(openings) or a drawing (engraved outlines); in a `cut` or an `assembly` it is E0120.
"""),
    "E0124": ("param value outside its range", """
A param may declare the range its value is meant to take (used by `aidl serve` for its
sliders, and checked by `--set`):

    param width = 40 mm, min=20 mm, max=80 mm, step=1 mm

The value, and any `--set width=...`, must lie between `min` and `max` (both optional);
`min`, `max` and `step` have the param's unit (a bare number means the file's unit), `min` is
not larger than `max`, and `step` is positive.  Choose a value inside the range or widen it.

A `min` larger than its `max` written as numbers is a slip: the hint says to swap them when
the swapped range holds the value.  Bounds that follow other params (`min = max(a, 10 mm),
max = min(c, 70 mm)`) are never swapped (that changes what they mean): the message says what
each bound came to at the other params' values, and the hint which values of which param
empty the range ("`a` above 60 mm empties it with `c` = 60 mm"), found along that param's
declared range.  Bounds written as expressions of numbers alone (`min = max(10 mm,
25 mm)`) are not swapped either: the hint asks for the wrong bound to be changed.
"""),
    "E0125": ("a `cut` where it cuts nothing", """
A `cut` structure holds through-cuts: the laser cuts along each of its curves, open or closed,
through the solid the cut sits in. So a cut belongs inside a `solid` (or inside another `cut`),
or directly in an `assembly`, where it is a sheet-level cut (cut where it is drawn, in no part:
W0525 if it runs across a part), and holds only curves and other cuts. At the top level (a
program of one cut), in a `drawing` (whose lines are engraved) or a `hole` (removed whole
already) it has no material to cut:

    drawing marks { cut slits { l = Line(start=(0, 0), end=(10, 0)) } }   # error

    solid panel {
        body = Rectangle(center=(0, 0), width=60, height=30)
        cut slits { l = Line(start=(-20, 0), end=(20, 0)) }                 # cut through
    }
"""),
    "E0201": ("geometry refers to another structure (validity rule 1)", """
Geometry may only be built from geometry of its own structure. This keeps each structure
solvable on its own. Give the geometry its own starting value and relate it to the other
structure with a constraint in a structure that contains both:

    solid phone {
        solid base { body = Rectangle(center=(0, 0), width=60, height=30) }
        solid dial {
            plate = Circle(center=base.body.center, radius=10)   # error: base is another structure
            plate = Circle(center=(0, 0), radius=10)             # fix
        }
        CenterInside(dial, base)                                  # relate them here
    }
"""),
    "E0202": ("constraint outside its structure's subtree (validity rule 2)", """
A constraint may only refer to its own structure and its descendants. A constraint relating two
sibling structures belongs in their common parent; the hint names it.

    solid phone {
        solid base { body = Rectangle(center=(0, 0), width=60, height=30) }
        solid dial {
            plate = Circle(center=(0, 0), radius=10)
            CenterInside(self, base)      # error: base is not inside dial
        }
        CenterInside(dial, base)          # fix: in the common parent
    }
"""),
    "E0204": ("template argument is geometry", """
Template parameters are values (numbers, lengths, angles, booleans, strings). Relate a template
instance to other parts with constraints in the parent structure.
"""),
    "E0301": ("loop too large", "Loops, ranges and comprehensions are limited to 10000 items "
                                   "(times `--budget K`)."),
    "E0302": ("nesting too deep", "Templates may nest at most 16 deep; expressions at most 64 brackets."),
    "E0303": ("too much geometry", "A model is limited to 50000 geometry objects (times "
                                      "`--budget K`)."),
    "E0304": ("evaluation budget exhausted", """
One compile has one evaluation budget (`aidl check --budget K` multiplies it): 250 000 steps (every loop
iteration, comprehension element, call and template instance counts one), 120 000 points,
geometry objects, structures and constraints together, 1 000 000 characters in one string or items in
one list (and 64 000 000 characters in all the strings a compile builds), and 2 000 000 work
units for the whole compile (each stage pays for what it walks before it walks it: steps,
objects, Newton steps, vertices, pairs, segments; about 15 s of the reference machine, and the
same count on every machine at any load, so the same program gets the same answer, the same
message and the same output everywhere). CPU time is only a backstop,
at 6 times 15 s, and its message says so; wall time an outer guard, at 10 times 15 s, for a
machine too busy to give the compile the CPU it needs (its message says the CPU the compile got
in that time and its share of a core). Each construct's own limit
(E0301, E0302, E0303) stops one loop or template that is too large by itself; the budget stops
their product: nested loops, a template that instantiates itself several times per level.
The error points at the outermost loop or template instance running when the budget ran out
and labels the ones inside it.

    solid s {
        for i in range(1000) {
            for j in range(1000) { ... }    # 1 000 000 iterations: over the budget
        }
    }

Build less, or, if the model really needs it, raise every figure with `--budget K`
(e.g. `aidl render model.aidl --budget 4`); the message names the `--budget K` that covers
what was needed. The work reaches every stage after the
solve too, each paying as it goes (every few parts, pairs or cells): the booleans, the
shape checks, the exact outlines, the writers, `aidl parts`' list and `aidl check
--describe`'s description (one budget for the whole command; `Result.output` and
`Result.description` of the Python API, and the MCP `describe`, get a fresh budget per call)
and the comparison with the defaults under `--set` (W0510): "the program ran out of its
evaluation budget in the parts list of `sheet.p[12]`: it needs more than 1,000,512 work units,
past its budget of 1,000,000", at that part's structure, with the hint "... raise the budget
with `--budget 0.53`". A program that runs out of memory
before any figure of the budget is also `E0304`, wherever it happens (interpreting, solving,
the booleans, the shape checks, the exact outlines, a writer) and in every front end (the
CLI, the Python API, `aidl serve`, `aidl studio`, MCP, the editor, `aidl batch`): "the program
ran out of memory while compiling" (or "in the booleans of `plate`", "in the SVG writer of
`kit.plate`"), "it needs more memory than this compile may use (12 GB)", shown at the
structure being worked on, else at the first structure. `aidl check`, `render`, `parts` and
`import` cap their own memory (address space) so that this is said before the machine runs
out: by default half the machine's memory (or of the cgroup's limit when that is lower), at
least 3 GB; `--memory 16G` raises the cap, `--memory none` removes it. One bound no `--budget` raises: `aidl render` matches the edges of the
final outlines back to the exact curves in at most 10 000 000 (edge, curve) pairs, so
thousands of copies of one curve at one place (a template or pattern repeated without moving
it) are `E0304` "in the exact outlines" of the part, with the fix: draw each curve once.
"""),
    "E0305": ("number not finite or beyond the model extent", """
A computed number is infinite or not a number (NaN), e.g. `1 / 5e-324` or `x - x` with an
infinite `x`, or a coordinate, size or length is beyond the model extent of 1e6 mm (1 km).
Such numbers would make the solver and the writers produce nothing useful, so the expression
that produced them is an error.

    i = 1 / 5e-324                                 # inf
    c = Circle(center=(0, 0), radius=i - i)        # NaN radius: E0305
"""),
    "E0401": ("constraints cannot be satisfied", """
After solving, some constraints still do not hold: they contradict each other or a dimension
held by a constructor (width, radius, ...). The message lists them with their residuals (how far
off they are, in mm or radians). When the solver can find the smallest set of constraints that
contradict each other (a rank-revealing factorization of the Jacobian), the error names exactly
that set, one label per member, constructor-held dimensions included. A constraint on sizes
that constructors hold and nothing else (below) is named with those sizes, a label on each
constructor. Change one member of the set so that they agree; the others can stay.

    solid s {
        c = Circle(center=(0, 0), radius=5)
        Radius(c, 7)      # contradicts radius=5 given to the constructor
    }
"""),
    "E0402": ("solver iteration budget exhausted", """
The solver stops after a fixed number of Newton steps for the whole model (20000) instead of
running on: this happens when the constraints are far from satisfiable from the starting
positions. Give starting positions closer to the intended shape and check the constraints named
by other errors.
"""),
    "E0405": ("assertion failed", """
An `assert` statement's condition is false at the solved values (every false one is reported;
after a failed solve, those that read only params, constants and held sizes). The message gives the condition, the reason written
after it and the values found, in the file's units, then the value of each name and member a
side computes with (`(where ring.bb.width = 124 mm, wall = 3 mm)`); a structure's box that its
drawings widen is said so, with the material's own size (`` `marker.bb` holds its drawing
`marker.label`: its material alone spans 25 x 150 mm``: the engraved word is wider than the
stake); a Slot's `length` it reads is said to be end to end, with its centre-to-centre
length (`first.shank.spine.length`), as a request's "34.5 mm between the ends' centres" is
the spine; one inside a template of another file (the standard
library's, an imported one) is reported at the template's call, its own line a note. A
template's assert written over its arguments (reading only its parameters and values computed
from them) is checked at the call before the body runs: false, it is one error at the
argument(s) it reads (*argument `module` of `spur_gear`: assertion failed: `module > 0 mm`*)
and the instance is not built. An `assert` is a check, not a constraint: the
solver never moves geometry to satisfy it. Change the values or constraints so that it holds.

    param width = 400 mm
    solid plate {
        body = Rectangle(center=(0, 0), width=width, height=100)
        assert body.width <= 300 mm, "fits the laser bed"   # 400 mm <= 300 mm is false
    }
"""),
    "E0406": ("offset leaves nothing", """
An `Offset` (or `Inset`) with a negative distance, or a `Shell` with a negative thickness,
removes a band that wide along the whole outline of its shape; when the shape is nowhere
wider than twice that, nothing is left. The shape's size is only known after the solve, so
this is found then; the error points at the call. Use a smaller inset.

    solid s {
        body = Rectangle(center=(0, 0), width=40, height=20)
        inner = Offset(body, -12)     # 20 mm high: an inset of at most 10 mm leaves something
    }
"""),
    "E0407": ("operation cannot stay exact on a spline", """
A `Fillet` or `Chamfer` asked for a corner where a `Spline` meets another curve (a hole or a
cut that crosses the spline, or a line the open spline is chained with). The rounding arc
would have to be tangent to a cubic spline, and its end on the spline is no line, arc or
spline piece that the exact outputs can write: AIDL refuses rather than write chords. The
error points at the `Spline`. Choose the corners with `Fillet(r, at=[...])` away from the
spline, or let the spline itself turn smoothly there (give it a point at the corner).
A corner of the spline itself (a point its `corners=` names, given to `Fillet` by its point)
is refused so too, at the `Fillet`: round it within the spline, two points close either side
of the tip and the index dropped from `corners=`.
(`Hull` of a Spline is refused at its call, E0108; its `Offset`, `Inset` and `Shell`, and a
cutting layout's kerf on a part with a spline, are followed by circular arcs within 1e-4 mm.) The same holds
at a corner where an `Ellipse` meets another ellipse or a spline: the error points at the
`Ellipse` (where it meets a line or an arc the fillet is exact; its `Offset`, `Inset`,
`Shell` and kerf are within 1e-4 mm, its `Hull` exact).

    solid pick {
        body = Spline(points=[(0, -30), (20, 0), (0, 20), (-20, 0)], closed=true)
        hole notch {
            c = Circle(center=(20, 0), radius=5)      # two corners on the spline
        }
        Fillet(1)
    }
"""),
    "E0408": ("Fillet or Chamfer corner that is no corner", """
A `Fillet` or `Chamfer` names a corner with `at` (two edges, a point, a line's ends or a
shape's corners) and the final outline of its structure, after the booleans, has no corner
there, so nothing would be rounded. Two edges make a corner where they meet: at their ends,
where they cross (the inside corner of an L made of two rectangles), or where one ends on the
other. The error points at the call, names both edges and says why: they are parallel (or lie
on one line); they do not meet (how far past which end their lines cross); or they meet where
the outline runs straight on, or inside the material (a third shape covers the point), or
outside it. The hint gives the nearest corner of the outline. A line's two ends or a shape's
corners are an error only when none of them is a corner. Nothing is written.

    solid hook {
        solid stem { body = Rectangle(center=(0, 0), width=10, height=60) }
        solid arm { body = Rectangle(center=(20, -25), width=50, height=10) }
        Fillet([stem.body.right, arm.body.top], 6)       # they cross: the inside corner, made
        Fillet([stem.body.right, stem.body.left], 2)     # parallel: E0408
    }
"""),
    "E0502": ("a sheet layout of a design with no solid part", """
`--layout sheet` nests the design's solid parts on sheets, and this design has none: only
drawings (engraved lines and text) or nothing to cut. Nothing is written. Render it without
`--layout` to get the drawing as it is, or put the drawing inside the `solid` plate it is
engraved on (then the plate is laid out, with its engraving).

    drawing label { t = Text("HI", position=(0, 0), size=5) }     # --layout sheet: E0502
"""),
    "E0501": ("parts lie over each other in a machine file", """
A machine file (G-code, LightBurn, HP-GL) is written as the program draws the parts, and two
separate parts lie over each other there: the machine would cut one part through the other.
An assembly may draw its parts over each other (a bird house's walls all at the origin, placed
in 3D with `Place` for the assembled view; a clock's hands on its face, with `AllowOverlap`): a
picture shows that, a cutter cannot make it. The message names the pair with the most area in
common and how many pairs overlap; nothing is written. Write the cutting layout instead,
`aidl render house.aidl --layout sheet -o house.gcode` (the parts laid apart on sheets, one file
per sheet), or place the parts apart in the program. SVG, DXF and PDF are written as drawn.

    assembly house {
        solid front { r = Rectangle(center=(0, 0), width=120, height=110) }
        solid back { r = Rectangle(center=(0, 0), width=120, height=110) }   # on the front
        Place(back, rotation=(90 deg, 0, 0), position=(0, 60, 0))
    }
"""),
    "E0503": ("countersinks or counterbores leave nothing of a part, or cut it apart", """
A `Countersink` whose cone, or a `Counterbore` whose recess, goes through the part (W0529) takes
from its bottom face a disc as wide as the cone is there (`diameter - 2 x thickness x
tan(angle / 2)`; a counterbore's `diameter`). When those discs cover the whole part, or cut it
into pieces, the part cannot be made as drawn: an STL, 3MF or GLB would hold nothing (or loose
pieces) while the SVG and DXF draw the whole plate and a router's G-code cut cones into it. The
error is at the call of the widest head, the compile stops, and no format is written (a file
written before is left as it was); `--thickness` given to `aidl render` is judged the same
way. Give the head the screw's size (an M4 flat-head screw: a 4.5 mm hole, a 9 mm head), a
wider angle, a shallower counterbore, or thicker material.

    thickness 6 mm
    solid plate {
        body = Rectangle(center=(0, 0), width=80, height=50)
        hole screws { c = Circle(center=(-30, -15), diameter=4.5 mm) }
        corners = CornerPattern(screws, body, inset=10)
        Countersink(corners, diameter=200 mm)      # 188 mm wide at the bottom: E0503
    }
"""),
    "E0504": ("a kerf the part's cuts cannot be offset by", """
A laser's beam (the program's `kerf`, or `--kerf`) is as wide as the kerf, so a machine file
offsets every outline and hole by half of it to cut the part to size. An opening narrower than the kerf, or a curve of an opening with a radius under half
of it, has no such offset: the beam alone cuts wider than drawn. `aidl render` writes nothing
for a cut format (a file written before is left as it was) and says where, at the hole nearest
the point the message names, else at the part; `aidl check` says it too for the program's own
`kerf` statements (not for `--kerf`, which only `render` takes). Widen the
opening to the kerf or more (a slit as wide as the beam is a `cut` line, cut along its length
with no offset), give the curve a radius of half the kerf or more, or render with a narrower
`--kerf` (`kerf 0 mm` in the part writes it as drawn).

    kerf 0.5 mm
    solid plate {
        body = Rectangle(center=(0, 0), width=60, height=40)
        hole s { sl = Rectangle(center=(0, 0), width=20, height=0.4) }   # render: E0504
    }
"""),
    "E0900": ("internal error in aidl", """
A bug in aidl, not in your program: a stage of the compiler raised an exception it should have
turned into a diagnostic. `aidl check` and `aidl render` report it and exit with status 3; the
live preview (`aidl serve`) shows it beside the last good picture, logs it, and goes on watching
the file. Please report it with the input file.
"""),
    "W0401": ("redundant constraint", """
The constraint holds already because other constraints (or a constructor's held dimension) imply
it: it adds no information. It is harmless, but if a value in it changes later the model becomes
over-constrained. Reported by every `aidl check`. What it follows from is named as a reader
finds it in the code: a written constraint as written, a shape's own relations as `the shape of
`picks[1].tri``, a pattern's or mirror's tie to its original as `the pattern `picks`'s copy
rule`. Constraints that each follow from the others
(two `Fixed` of points of one held shape, `Coincident(a, b)` beside `a == b`) are one warning
for the group, whose hint says which to keep and which to drop: the drop set frees nothing
(the kept constraints still hold every unknown the group held; each member follows from the
others, not any two from any one), tried from the last written back, so the first written is
kept. A statement that makes geometry is never one to drop: a `CornerPattern` beside a
`HorizontalDistance` and a `VerticalDistance` that place its hole the same way keeps the pattern
(it makes the copies) and drops the two distances; when only such statements are left the
warning names the redundancy without a drop list. A standard-library template's own
constraints are never the ones to drop either (its user cannot edit them): beside one the hint
names the user's line and where the template holds it (`std/joints.aidl line 154`), and a
redundancy wholly inside a template is not reported. A template instance's hold of its own
place (`Fixed(self)`: a joint "holds itself where `cx`, `cy` put it") is where it starts,
which the constraints placing it override (the solver moves the instance): nothing placing
an instance (`AlignRight(tail, panel)`, `CenterInside(h, body)`) is redundant with it, even
where the two agree, and no hint says to drop such a placement (dropped, the instance went
back to where the template started it: issue 109). Every edit a W0401 proposes, applied,
leaves the design where it was (law 4 of the project's laws). A line that makes several constraints (a loop's
body) of which only some are implied is never offered for dropping: the warning says how many
of them are redundant and that removing the line would free what the others hold, and its hint
narrows the other statement instead (`AlignCenterX(pockets, body)` for a `CenterInside` whose y
the loop's `AlignCenterY`s already say).

    solid s {
        r = Rectangle(center=(0, 0), width=30, height=20)
        Horizontal(r.top)     # a Rectangle's top is already horizontal
    }
"""),
    "W0403": ("constraint ended on another branch", """
Convention-dependent constraints (Angle sense, Tangent side, point-line Distance side) pick the
branch nearest to satisfied at the starting geometry. This warning says the solve ended on the
other branch (for Angle: a line now points the opposite way), which usually means the
starting positions were far from the intended shape.
"""),
    "W0404": ("feature that can slide", """
A structure inside a part (a hole, a drawing, a solid child) can move relative to its part
along an axis that a constraint reads, and the solve cannot keep it where it is written: it
is tied along x or y only to other features that are free there too, each placed on another
in a cycle (the holes' x on the labels and the labels' y on the holes), so only the starting
positions hold the group, and the solve moves each some of the way. The warning names the
feature, the free direction and the part; place it with a constraint in its parent that ties
it to the part's shapes: the hint gives the one that keeps it where the solve left it
(`bits.bb.center.y == plate.bb.center.y + 1.75 mm`), or another (`AlignCenterY(bits, plate)`,
`bits.bb.top == plate.bb.top - 5`); `Fixed(bits)` holds it only where the part is fixed too (it pins the feature to the sheet,
not to the part). Freedom of a whole part (where it sits on the sheet) is harmless and not
reported; `aidl check` says it as "free: only where the whole part sits (harmless)". Nor is a
feature along an axis that no constraint reads (its coordinates alone place it there): the
solve keeps it where it is written, and the ok line says "hole `plate.recess` free but stays
where written on its part (harmless)" (it moves with its part), whether nothing places it (`plate.recess`) or a constraint places
it along the other axis (`AlignTop(groove, body)` and its x as written; issue 111). Nor is a
feature placed on a sibling that stays where written (of two features related, the
first-named moves to the second: labels `Below(labels, bits, gap=4)` of holes written by their
coordinates, two screws with `VerticalDistance(bottom, top, 60.3)`): the ok line says "hole
`plate.top` free but stays where written on its part; hole `plate.bottom` placed on it
(harmless)". A structure declared inside a standard-library template is the template's affair and is not
reported to its user. Features in one cycle slide together and are each reported: tie one
and check again (the others follow it); tying both with `.bb.center ==` repeats the relation
between them (W0401).

    solid gauge {
        plate = Rectangle(center=(0, 0), width=120, height=40)
        hole bits { h = Circle(center=(0, 5), diameter=3) }
        drawing labels { t = Text("3", (10, -12), size=5) }
        Below(labels, bits, gap=4)       # the labels' y placed on the holes
        AlignCenterX(bits, labels)       # the holes' x on the labels: a cycle, W0404 on each
    }
"""),
    "W0405": ("box read before Fillet or Chamfer", """
A constraint reads a side of the box of a structure (`AlignLeft(x0, board)`, `x0.bb.left`,
`Above`, `Inside`, ...) that has a `Fillet` or `Chamfer`, and its final outline does not
reach that side: the box is read from the shapes as drawn, before the rounding (which acts on
the finished outline after the booleans), so where a rounded corner is the box's extreme the
outline ends short of it (a 45-degree X filleted by 1.5 mm: 0.621 mm in from the board's
edge). The warning gives both sides and the difference; write that side as an equation with
the difference to 1e-6 mm (`x0.bb.left + 0.62132 mm == board.bb.left`: an equation on box
values is taken as written, never warned, and moves the first-named as the `Align*` did), or
round only the corners away from that side (`Fillet(at=[...], radius=...)`). An `assert` on
such a box is judged on it too (E0405 when false there); where its verdict on the final
outline would be the other one, W0405 says so at the assert; so too for the box of a shape
that is its structure's outline on the side read (`assert body.bb.height == 180 mm` on a tent
stake whose `Fillet(2)` took 21.4 mm off its 9.8-degree point), and for the box of a shape
whose structure's own holes cut the outline on that side (`assert sail.body.bb.width == 70 mm`
on a sail whose notch cut a corner off: "before its holes"; not a joint template's cut, which
its mate fills: a cross-halving slot at a rocket's nose). The assert's fix is not the
difference added (the assert is judged as drawn, so it would fail there): draw the corner round
(a `Hull` with a `Circle` at the tip) or round only the corners away from that side. A side a
rounding moves by less than 0.05 mm (a corner a little off square) is not said; an assert
that holds to the sharp corners, each side in by no more than three times the rounding's size
(the way a drawing gives a rounded outline's size: any corner of 29 degrees or more, a 45-degree
set square's R2 tips 2.8 mm in), is a note; a needle point rounded far back is not. Holes
are named only where they cut the side read (a hanging hole inside the part is not). Relations between separate parts of an
assembly that places them with `Place` lay them out on the sheet and are not warned. Also a relation
on the box of a shape made from others whose box is its drawn outline's (an `Inset`, a
miter-joined `Offset` or `Shell`, an `Intersect`: exact at the solution) that the solution
still misses after the solver solved again from it: the solve moved the shapes it is made
from apart (an `Intersect`'s two shapes), so its outline changed under the relation.
An assert that holds on a shape a hole of its structure runs out through (drawn past the side
it cuts, with material left beside it: a fork notched into an arm's round end) is a note: the
shape's size as drawn is the one meant (run ha); a hole trimming the whole side stays a warning.

    solid board { b = Rectangle(center=(0, 0), width=90, height=90) }
    solid x0 {
        a = Rectangle(center=(10, 10), width=24, height=4, rotation=45 deg)
        c = Rectangle(center=(10, 10), width=24, height=4, rotation=-45 deg)
        Fillet(radius=1.5)
    }
    AlignLeft(x0, board)        # the rounded X ends 0.621 mm in: W0405
"""),
    "W0406": ("Fillet or Chamfer smaller than asked, or changing nothing", """
A corner chosen with `at` is rounded with a smaller radius (or a shorter chamfer leg) than
asked, or not at all: a corner takes at most half of each outline piece beside it, and a
fillet's arc must touch both pieces, so where they are short the size shrinks to fit. The
warning points at the call, names the corner and gives the size it got; ask for at most that,
or make the edges beside the corner longer. Also a `Fillet(radius)` (or `Chamfer(distance)`)
of the whole outline that finds no corner to round (no outside corner to cut): an outline of
circles and smooth joins only. (A whole-outline fillet that shrinks at a short piece is said
nowhere: rounding every corner up to the radius is what it is for, except at a hole: W0410.)

    solid s {
        stem = Rectangle(center=(0, 0), width=10, height=60)
        arm = Rectangle(center=(20, -25), width=50, height=10)
        Fillet([stem.right, arm.top], 30)    # 20 mm: arm.top's 40 mm piece, half each corner
    }
"""),
    "W0410": ("whole-outline Fillet rounds a narrow hole's ends", """
A note, not a warning: a `Fillet(radius)` without `at` rounds every
corner of the part's final outline, the holes cut into it included, and a hole narrower than
two radii can take only half its width at each corner: a 4.2 mm slot under `Fillet(4)` gets
its ends rounded by 2.1 mm, and a square tab no longer fits it. The note names the hole (its
centre and least width) and the size that fitted. A notch cut into the outer outline narrower
than two radii (a 3 mm cable slit: its bottom comes out round and its mouth flares) gets the
same note. Nothing to change when round ends are meant; to round the part's own outline alone,
name its shapes, `Fillet(plate, 4)` (or `Fillet([left, right], 4)`). A step where a bar's side
runs between two circles (a 14 mm arm between a 36 mm hub and a 32 mm lobe leaves 2 mm of
straight side) is no notch that naming shapes helps: the fillets at its two inside corners do
not fit on it and it comes out as a small round pit; the note says so, how far from the
circles' centers the side must lie for the fillets to fit (a bar centred on them: how wide),
or to draw the neck as the circles' `Hull(a, b)` (two circles of one structure: tangent to
both, no step) in place of the bar:

    solid bracket {
        plate = Rectangle(center=(0, 0), width=100, height=60)
        Fillet(4)                  # also the slot's four corners: W0410
        hole tab { s = Rectangle(center=(0, -20), width=40, height=4.2) }
    }
"""),
    "W0411": ("Fillet cuts a sharp tip back", """
A fillet's arc is tangent to both sides of its corner, so in a sharp tip it lies far from the
point: a round of radius r in a corner of angle a lies r / sin(a / 2) - r from it, 19.7 mm for
3 mm in a 15 degree tail, 21.4 mm for 2 mm in a tent stake's 9.8 degree point. The part then
ends that much short of the point drawn, and an assert on the shape's box (read before the
rounding) does not see it. The warning names the tip, its angle and how far it went back
(when more than 5 mm and more than three radii; a tip of the material, not a window's sharp
end, whose rounding keeps material), and the radius that cuts it back 1 mm; to keep
the length, draw the tip round: the `Hull` of the shape and a `Circle` of that radius whose
edge touches the point.

    solid stake {
        body = Polygon([(-12, 0), (12, 0), (0, -140)])
        Fillet(2)                   # the 9.8 deg point goes back 21.4 mm: W0411
    }
"""),
    "W0412": ("Spline swings off a straight run of its points (note)", """
A Spline is the smooth (C2) curve through its points, so where the points run straight and
then turn sharply, the curve overshoots before the turn: a shield's flat top through (-100,
318), (0, 320), (100, 318) humps 5.6 mm up between them to round a 35 degree shoulder at
(100, 318), a yoke's straight edge swells into a knob before its rounded end. The warning names
the span between two points (`points[i]`, as the members count them, a mirrored half's too)
where the curve leaves the line of a straight run (a point the points turn at by 3 degrees or
less) by more than 3 % of the span and 1 mm (points in line, turned 0.5 degrees or less: 1 %
and 0.25 mm, a paddle's side bowed 0.67 mm), how far, and the point near it where the points
turn most; the middle of an S (its neighbours turning each way) is no straight run, and an
engraved curve (a wave) is not looked at. It is a note: a free-form outline (a pond, a hill)
may mean the wave. To keep the run straight, add a point where the turn begins, so the curve
has room to round it, or make the turn a corner (`corners=[i]`); a Polygon rounded by `Fillet`
keeps straight sides straight.

    solid shield {
        outline = Spline([(0, 320), (100, 318), (125, 300), (128, 220), (0, 0),
                          (-128, 220), (-125, 300), (-100, 318)], closed=true)   # W0412
    }
"""),
    "W0501": ("hole refilled by another solid", """
A hole cuts only the solid it is declared in. When that solid is then united with a sibling
(or its parent's own geometry) that covers the hole, the hole is filled again and does not cut
the final part. The warning names every solid or shape that refills it at once (the copies one
loop statement makes count as one, with their number), the share of the hole each covers, and how
much of the hole still cuts. Declare the hole in the common parent, so that it cuts everything
united there:

    solid lock {
        solid body { b = Rectangle(center=(0, 0), width=40, height=30)
                     hole key { k = Circle(center=(0, 8), radius=3) } }
        solid shackle { s = Rectangle(center=(0, 14), width=30, height=8) }   # covers `key`
    }
    # fix: move `hole key { ... }` out of `body` into `lock`

When the refill is intended (a boss over a relief cut, say), silence it for that pair only
with `AllowOverlap(body.key, shackle)` written in `lock` (`aidl docs AllowOverlap`). It takes
any number of refillers and lists: `AllowOverlap(rim.inner, spoke, frame)`, where `spoke` is
the list a `for` loop made, allows all the spokes and the frame; the hint writes that call,
naming a pattern's list beside its original (`AllowOverlap(rim.inner, spoke, spokes)` for
`spokes = CircularPattern(spoke, 8, ...)`) so that every copy is allowed.
A shape drawn inside the opening (at least half of its area lies in the hole: a wheel's hub
and spokes in its rim's opening, a moon in a window) is put there on purpose and not
reported; only what covers the hole from outside it is.
"""),
    "W0502": ("hole cuts nothing", """
The hole lies wholly outside the solid it is declared in, so it removes nothing. Move it onto the
solid (for example `CenterInside(bore, self)`) or declare it in the solid it should cut.
One shape of a hole lying wholly off the solid's extent while the hole's other shapes cut it
(a mounting hole written at y = 70 mm on a plate 60 mm high) is named the same way: it vanished
from the part, the rest of the hole is cut.
"""),
    "W0503": ("hole removes all of its solid", """
The hole covers the whole solid it is declared in, so nothing of that solid is left. Make the
hole smaller, or move it so that material remains around it.
"""),
    "W0504": ("solid falls apart into separate pieces", """
The final shape of a solid part is several disconnected pieces; the warning lists which children
or geometry make up each piece. Usually a child floats free of the body (feet, a handle) because
a constraint places it with a gap, or it touches the body at a single point (a round end
resting on a flat edge). Make the pieces overlap (`Above(foot, body, gap=-1 mm)`) or share an
edge: for two pieces of one shape each, drawn apart along x or y, the hint writes the relation
that holds as drawn, the smaller piece first (it moves), `Below(foot, body, gap=-1 mm)` in
`p`; if they really are separate parts, make the structure an
`assembly` (its parts are separate by design and are not checked against each other).
When a hole cuts one shape apart (a slot across a strip, a ring of overlapping arc slots
around a hub), the warning names the hole(s) and the shape, and the hint says to move,
shorten or shrink them: an `assembly` there would ship a part in pieces.
When a piece is scaled in place (`Scale(star, 0.5)`), the hint says so: it is scaled about
its own centre and stays where its constraints place it (they carry to the scaled copy), so
the pieces are joined by changing that placement or the factor, not by a second placement.
"""),
    "W0505": ("engraving off the material", """
A drawing inside a solid part runs outside the part's outline or across one of its holes, where
there is no material to engrave. Move or shrink the drawing so that it lies on the material, or
put a drawing that is only an illustration at assembly level, beside the part.
The share off the material is said as a percentage of the drawing's length ("under 1%": a
letter's stroke over a screw hole); across a hole, the hint names the holes it crosses (a window
the shapes enclose that no hole cut, a rainbow's arch over its bar, is said as an opening).
Off the outline, the hint says where the mark leaves the material (x, y); where the mark
reaches past the box of the shape it is drawn over and fits in it, it also writes the
constraint that sets it there clear of the cut, `Inside(d.mark, body, margin=0.5 mm)` (a mark
that touches the cut is W0516), and a mark larger than that shape is told to shrink. That
shape is the one of the part (or of a solid within it, `head.skull`) that holds most of the
mark, the nearest among equals: a whisker off a cat's head is told `Inside(face.w2,
head.skull, ...)`, not the hips, the part's largest shape (issue 111).
An engraved Circle or Arc that crosses the outline or a hole (a ring that meets a notch in the
rim) is offered the arc that stops at the cut: the longest arc of it on the material, 1 mm
clear of the cut, written as the `Arc(center=..., radius=..., start_angle=..., end_angle=...)`
that replaces it.
Engraved text (on a straight baseline) is said in letters: which letters reach off the
material, of how many ("the letters "B" and "Y", 2 of its 5"), and each place it leaves it: the
hole it crosses and at which letters, the end that runs off the outline and where. Its fix is
the width it has room for where it is written, computed (scaled about its position point, as a
smaller size draws it, 0.5 mm clear of the cut): `max_width=29.9 mm` (it shrinks to fit), or
that `size=`. An `Inside(...)` of its box is offered only when it leaves by the outline alone, the
part has no hole, and the fit would shrink it by more than a tenth; a text wider than the room
conflicts (E0401) with such a constraint. One copy of a loop's statement (a ruler's `num[15]` over its hanging
hole) is named with its index, and its hint offers no `max_width=` or `size=` for the
statement (that would shrink every copy): it leads with moving what it crosses, or that copy.
A mark that runs off the material on purpose (a checkerboard's grid lines carried across the
dovetail band of each half, so that the rows read continuous once the halves are joined) is said
so with `AllowOverlap(grid.h, self)` in the part (the engraving, or the drawing around it, and
the part or a shape of it; for a drawing given to a part by `CutInto`, the call in the assembly:
`AllowOverlap(label.word, box.front)`; written in the drawing itself, `AllowOverlap(grid, self)`
means the same, `self` there being the drawing on its part); the hint of a mark that is not text writes that call
after its fix. Engraving off the material burns air, so nothing reaches the machine that was not
drawn; an `AllowOverlap` of an engraving that lies on the material is W0523. A straight line
that leaves the material only inside round holes centred on its ends (a linkage diagram drawn
pivot to pivot over its axle holes: run dp) is drawn as meant and not warned, nor is a mark
of which less than 0.25 mm runs past the material (a ruler's tick a hair past a rounded corner:
run dt), nothing of it lost; nor a straight line through the middle of every hole it crosses,
a third of it at most over them (a centre line: axes through a pivot hole, a divider across a
mortise: runs hj, dh).
"""),
    "W0506": ("geometry that adds nothing", """
A child solid lies wholly inside the rest of its parent, so it changes nothing in the final
shape: typically copies of a pattern that land inside a filled solid, or a feature placed at the
wrong position. Move it where it shows, make it a `hole` if it should cut, or delete it. When a
hole of the same structure cuts it away (a hole cuts every solid of the structure it is declared
in, children included), the warning names that hole and the share it cuts: to keep the solid
over the hole, declare it beside that structure (a sibling's material survives the hole);
when that structure is the part itself, its shapes and hole go in a `solid` of their own
inside it, beside the solid kept. A solid that would be an island in the opening (touching
no material around it, nor another solid that does: a letter crossed by a bar that reaches
the ring is kept with it) or would fill the whole opening is only offered deletion.
When one filled shape of the parent covers it whole (`frame = Circle(...)` meant as a ring,
over a spider and its threads), the warning names that shape and counts the other shapes it
hides, and the hint offers the likely intent: a ring (`Shell(frame, 3)`) or
`construction=true`.
"""),
    "W0507": ("wall thinner than the minimum", """
Some material of the final part is narrower than the minimum wall (0.5 mm by default; the
program's `min_wall LENGTH` statement sets it for the file or a structure, `aidl docs
min_wall`, and `aidl check --min-wall MM` or `aidl render --min-wall MM` overrides both; 0 turns it
off): a laser or router
burns through or breaks such a wall. Between two holes, or a hole and the outline, the width
is the measured least distance between their boundaries (to 0.01 mm); other thin walls are
found by an opening of the part (what a disc of the minimum's diameter cannot reach, in pieces
of at least 2 x minimum^2, so that ordinary corners do not count) and measured across: the
least distance between the two sides of the wall that face each other, over the length of
its centre line, at a place inside it. The warning names the holes and the outer edge that
the wall lies between, its width and length and where it is. Move or shrink the hole so that
enough material is left. A thin wall of the outline alone is located at the shape that makes
it (the face covering most of it, in the solid or one of its solid children). When it is a
corner sharper than 60 degrees (an outline that tapers to a point: a needle-thin Triangle, a
spike) the warning names the corner by its vertex and angle and says over how much of its
length it is narrower than the minimum; a corner of about 11 degrees or more is never
reported (what burns is its very point), a sharper one at any minimum, so the hint says to
blunt the tip, or `min_wall 0` in the part when the tip is asked for. For a wall of one
shape as the program states it (a 0.34 mm angle leg), the `--json` fix is the statement
`min_wall W` (W just under the measured width) before the part: a wall this thin, asked for,
is then accepted; otherwise widen the shape. Through-cuts (`cut`) count too: a web between
two cuts or a cut and the outline, and a bridge at a cut's free end that stops short of
another cut, a hole or the outline (two slits ending 0.05 mm apart, a slit ending 0.01 mm from
the edge), named with the cut, what it stops short of and the width (exact on lines and
circles: a living hinge's bridges exactly `min_wall` wide pass). End the cut farther away, or
run it on to meet the other curve when it is meant to cut through.
Also from `aidl render` (a machine file): what the cutter leaves. A through-cut has no width
in the design; a router's bit cuts it as wide as itself (`--machine router`: its
`tool_diameter`), a laser as wide as its kerf (the program's `kerf`, or `--kerf`), round past
each end, while the outlines and holes are offset to keep their size. So the material beside
a through-cut is narrower than drawn by the tool's radius (by its diameter between two
through-cuts): a slit 1.6 mm from a plate's edge passes at 0.5 mm, and a 3.175 mm bit leaves
0.0125 mm of that bridge. Every bridge, rim or strip the tool leaves thinner than the minimum
wall (or cuts away: "nothing is left there") is a warning at the through-cut, with the width
as drawn, the width left, where (and over how much of the cut, for a strip along it), and how
far to keep the cut; measured between the tool's own paths (exact on lines and circles), the
first five of a part said and the rest counted. A bridge already thinner than the minimum as
drawn is the warning above, not said again; a part the bit cuts into pieces is W0510.

    solid plate {
        body = Rectangle(center=(30, 20), width=60, height=40)
        cut slit { l = Line((30, 1.6), (30, 38.4)) }    # --machine router: 0.0125 mm left
    }

Two members of one part (shapes of its union, its own or a solid child's) that join over a neck
narrower than the minimum, or only at a point's worth of overlap (a hook's loop resting on the
tip of a leaf's stem: the part hangs by it), are named with the neck's width and place: the
part eroded by half the minimum falls into more pieces than it has, the width is the least
erosion that parts it, and the two members are the shapes on either side. The hint gives how
far to move the member on the smaller side towards the other for a neck of the minimum
(followed, the warning goes). Members that only touch at a point are two pieces (W0504).

    solid plate {
        body = Rectangle(center=(0, 0), width=40, height=20)
        hole slot { r = Rectangle(center=(0, 6.85), width=10, height=6) }   # 0.15 mm to the edge
    }

    solid pendant {
        leaf = Ellipse(center=(0, 0), rx=12, ry=20)
        stem = Polygon(points=[(-1, 19), (1, 19), (0, 26)])
        loop = Shell(Circle(center=(0, 29.9), radius=2.5), 1.5)   # on the tip: a 0.03 mm neck
    }
"""),
    "W0508": ("holes merge into one opening", """
Two separately declared holes (two hole structures, or two copies of a pattern) overlap or
touch, so they cut one opening where the program declares two: usually an edit or a `--set`
moved or multiplied one of them (a bolt row grown into a ring of vents). The warning names
both holes and says by how much they overlap (the depth along the line between them and the
common area). Move one of them away (by the overlap plus the minimum wall; the hint's figure is
rounded up, with the circles' chord error, so the move as written clears it), or shrink it. The
suggested fix moves the smaller hole, never one more than four times the other's area (a
window stays where it is for a thumb notch on its edge: run dd). A
single opening made of several shapes (a keyhole: a circle and a slot) is drawn as the faces
of ONE hole structure, whose faces may overlap without a warning.
A hole wholly inside another cuts nothing of its own; the warning says so (its size or place is
often in another unit or frame than meant). Unless it cuts a solid that the other hole does not
cut and that refills that hole's opening: a solid drawn inside the opening (at least half of it
there: a moon in a frame's window bitten by its own hole into a crescent, a hub with its axle
hole in a rim's opening) is the design and not warned; one that covers the opening from outside
it (a tab reaching over a window, with a hole inside the window) is named with the area the
inner hole cuts from it, and `AllowOverlap(window, tab)` in the structure holding both solids
marks the refill as intended (it silences this warning and W0501 for the pair).
A hole that runs out through the part's edge into a larger opening (a USB notch from the
case's edge into its board pocket: run dn) is a channel, one opening as drawn, and not warned.
Two holes meant to cut one opening (a screw hole on the edge of a window) are said with
`AllowOverlap(window, screw)` in the structure holding both, as the hint writes (or draw the
shapes in one hole structure); a copy made by a pattern with no name (`first_pattern[4]` of
`CircularPattern(first, 8, c)`) has no name a program can write, so the hint asks for the
pattern's statement to be named first (`NAME = ` before it, then `AllowOverlap(bolt, NAME)`).
Two holes that cross (each runs past the other on both sides, at any rotation: a pin channel
across a window, two mortises crossing for a halved post) are a note, not a warning: they cut
one cross-shaped opening, meant in every case the corpus holds; the hint says how to say so
and, if two openings were meant, how far to move one.
When more than 55 % of the smaller hole lies inside the other
and relations place both (a slit placed from a knob hole's centre out to the edge), one
opening looks meant: the hint leads with `AllowOverlap` and gives the move second.
The suggested fix (`--json`, the editors' quick fix) never hides the overlap. Two different
holes that overlap or touch are never taken as meant (one opening is drawn in one hole): the
fix moves one of them clear, the one the warning points at, else the other, by the shortest
move that leaves the minimum wall to the other hole and as much to every other hole of the
part and to its outline (when the moved shape lay inside it), computed on the outlines (the
Minkowski sums of the obstacles with the moving shape's hull, grown by the wall). It is written
in the shape's own call, every point argument shifted and its expressions kept, in the file's
units: `Circle(center=(-40 + 20 * i, 20), radius=pen_d / 2)` becomes `Circle(center=(-40 +
20 * i - 3.52, 20), radius=pen_d / 2)` (every copy of that statement moves with it, and is
checked). The hint gives the move, `by (dx, dy) mm`, and for a round hole whose centre lies
outside the other the radius that would clear instead. No fix is offered when the shape is
placed otherwise (a constraint on it or on its hole, a point shared with another shape, a
template's or a pattern's copy, a hole whose shapes of several statements touch): the hint
says how far to move. The one overlap taken as meant: copies of one pattern (or loop) that
overlap by at least the minimum wall (a row of vents drawn into one slot), whose fix is
`AllowOverlap(the pattern's list)`; copies that only graze (less than a wall, or touch) were
meant apart and get no fix.
Two overlaps are the design and not warned: a hole that trims the outline (at least half of
it drawn off the part, and it cuts at least a quarter of the part: a rectangle that halves a
ring, whose opening then opens onto the new edge as drawn), and an overlap that lies wholly in
a joint template's run past its cut (its `overrun=true` shapes: a `dovetail` spanning a ring's
width runs 1 mm into the ring's opening, as it runs 1 mm past any edge to cut cleanly).

    solid plate {
        body = Rectangle(center=(0, 0), width=60, height=30)
        hole bore { c = Circle(center=(0, 0), radius=8) }
        hole bolt { c = Circle(center=(9, 0), radius=3) }    # overlaps the bore by 2 mm
    }
"""),
    "W0509": ("face or part with no area", """
A closed shape that encloses nothing: a loop of lines that goes out and comes back along the
same path (a line and its own mirror image, `Mirrored(l, about=l)`), points all on one line, a
zero width, height or radius. It adds nothing to a solid and cuts nothing from a hole. Also
reported for a solid part whose final shape is empty although it has geometry, when no other
warning (W0503, W0402) explains why. Give the face an inside, or delete it.

    solid s {
        l = Line((0, 0), (10, 0))
        m = Mirrored(l, about=l)     # the same segment back: a loop of zero area
    }
"""),
    "W0510": ("part changes topology under a param value or the router's bit", """
With `--set NAME=VALUE` (or a slider in `aidl serve`), a part has another topology than with
the program's own defaults: a different number of pieces or openings, two holes that now merge
(or no longer do), a hole that now breaks through the outline, or two faces of different
structures that now overlap (or no longer do), a through-cut (`cut`) that now cuts a piece
off the part (or no longer does: "its through-cuts cut it into 2 parts instead of 1"). Such a
change is rarely what a parameter is
for: a bigger count that runs holes into each other, a width that pushes the cradle into the
handset. The warning names the part, the values and what changed; the baseline is the same
program compiled with its defaults. Choose another value, make the design follow the param
(spacing derived from the count), or declare the param's `min=`/`max=` to keep values that
fit. A hole a count (or a field that a new pitch refills) adds or takes away, cutting its own
opening, is what the param is for: no warning.

    # aidl check examples/bracket.aidl --set bolts=5
    # warning[W0510]: with bolts=5, part `bracket` changes: hole `bracket.holes[2]` merges
    #                 with hole `bracket.first_pattern[4]`

Also from `aidl render --machine router` (G-code): a part the router's bit cuts into more
pieces than the design has. A through-cut has no width in the design; the bit cuts it as wide
as itself, round past each end, so a bridge of material narrower than the bit's radius between
a through-cut and the part's outline or a hole (narrower than its diameter between two
through-cuts) is cut away. A slit stopped 1 mm short of both edges of a plate comes out, with a
3.175 mm bit, as a slot through both edges: two pieces where `aidl check` and `aidl parts`
say one. The warning is located at the through-cut and gives the bridge's width and the bit's
reach; a bridge cut away that splits nothing, or left thinner than the minimum wall, is W0507
(located too, and a `; warning:` line in the G-code). Leave bridges wider than
the bit's radius or use a smaller tool (the profile's `tool_diameter`).

    solid plate {
        body = Rectangle(center=(30, 20), width=60, height=40)
        cut slit { l = Line((30, 1), (30, 39)) }     # 1 mm bridges: less than 1.5875 mm
    }
"""),
    "W0511": ("parts of an assembly interpenetrate", """
Two separate parts (the solid children of an assembly) overlap: parts cut from a sheet cannot
occupy the same place, so the drawing shows them wrongly placed (two gears closer than their
centre distance, whose teeth run into each other). The warning names both parts, the overlap's
area and its depth along the line between them. Move one part away (meshing spur gears sit at
the centre distance module * (teeth1 + teeth2) / 2, which `gear_pair` in std/gears.aidl keeps),
or shrink it; if the overlap is meant (a picture of parts stacked, a clock's hand over its
face), say so with `AllowOverlap(a, b)` (the two parts) in the assembly. Parts overlapping by more than a quarter of the smaller
one are taken as laid on each other in the assembly view (a gear drawn on its mounting plate, a
clock's hands) and not warned: parts meant to mesh or touch collide at their rims. Except
where each of the two parts is placed in 3D by a `Place` of its own (or of an assembly that
holds it, below the one that holds both): then the assembled view is the 3D one and the flat
drawing is the parts to cut, so parts that overlap there, by any share, would be cut through
each other (issue 111: a cat cot's leg drawn on its top). One warning per assembly names every
such part ("7 parts, ... overlap (20 pairs)"); its hint lays them side by side with a relation
(`RightOf(front, floor, gap=5 mm)`: a relation moves a placed part on the sheet, not in 3D) or
cuts them with `aidl render --layout sheet`.

    import "std/gears.aidl"
    assembly drive {
        a = spur_gear(teeth=12, module=1.5 mm, cx=0 mm, cy=0 mm)
        b = spur_gear(teeth=36, module=1.5 mm, cx=34 mm, cy=0 mm)   # 36 mm apart is right
    }
"""),
    "W0512": ("copies of one shape merge into one opening", """
One statement of a hole structure draws a shape several times (in a `for` loop), and some of
the copies overlap or touch, so the hole cuts fewer openings than the shapes drawn: a drill
gauge asked for ten holes comes out with nine. (Shapes of one hole structure may overlap by
design, a keyhole's circle and slot; only copies made by one statement are compared.) The
warning says how many times the shape is drawn, how many openings it cuts, and which copies
overlap by how much. Copies drawn with `overrun=true` are compared where they cut the
material: three scallops whose circles overlap only in the air above the rim are three
openings (run dw). Space the copies further apart or make them smaller; if one opening is
meant, draw it as one shape. Two CIRCLES of one hole written as separate statements (a drill
gauge's holes written out one by one) that overlap partly (neither inside the other) are
reported the same way, with the depth of the overlap, the common area and how far to move
one; other shapes of one hole (a keyhole's circle and slot, a cross of two rectangles) may
overlap by design, and so may two circles that both overlap another shape of the hole (a
bone: a bar and two circles at each end, one figure), and so may a small circle centred on a
round opening's rim, a notch (run em's clay dies: a 10 mm thumb notch on each 25.6 mm
pocket); a figure-eight of two circles is drawn as one Slot when it is meant.
One opening meant of several overlapping shapes (a scalloped bite of three circles) is said
with `AllowOverlap(a, b, c)` (or `AllowOverlap(c)` for a loop's list) in the hole, as the hint
writes: the shapes it names together are not compared. Copies that only graze (every overlap
under the minimum wall) were meant apart: no fix inserts `AllowOverlap` then.

    hole drills {
        for i in range(10) {
            c = Circle(center=(i * 6, 0), radius=1 + i * 0.25)   # the last two overlap
        }
    }
"""),
    "W0513": ("text or a mark drawn over or too close to text or another mark", """
Engraved text is drawn over other text, or over an engraved mark (a line, arc, circle or
outline), or so close to a mark that the two read as touching: two protractor labels placed on
each other, a number on its tick mark, a clock's 12 o'clock tick running in between the "1" and
the "2", a frame whose edge grazes the letters. Text counts by the box of its pen strokes (in
its own frame, turned with it): two texts whose boxes overlap by more than 10% of the smaller
one, or a mark running through a text's box (less a margin of a tenth of its size) over more
than a quarter of its size. Two labels whose boxes come closer than half the text size (about a
word space) run into each other and read as one string ("140130120" along a protractor's arc;
single letters, as `text_on_arc` lays out, are not compared); two whose boxes lie corner to
corner (no side of one facing the other: a dial's "25" and "30" on a slant) or one above the
other read apart unless they come within 0.3 mm. A mark too close: it comes nearer
the text's strokes than the text's clearance, a quarter of its size and at least 0.3 mm (the
letters of a word stand 0.24 to 0.45 of the size apart, so a closer mark reads as one of its
strokes; 0.3 mm is about an engraved line's width), or it enters the text's box by more than
0.1 mm (between its letters). Close labels and close marks give one warning per pair of
statements (the closest pair, copies made in a loop named by index: `ticks[0]`), with the
number of such pairs. The warning names both, with the overlap's area, the gap, or the length
of the mark inside the text, and how much to shorten the mark or move the text (a move
along or away from the mark in the page's words and as a vector too, `3.05 mm left, along the
mark's line (by (-3.05, 0.00) mm)`; beside a text of the same size, "NAME" over "PHONE", the move
leads and a smaller size says it would set the text apart; text drawn over text: the least move right, left, up or down, as a vector, that leaves half the text size
between the two boxes, `move `p.d.b` 6.96 mm right, by (6.96, 0.00) mm`). Move the text
clear (beside the tick, further out), shorten the mark, grow the frame, or make the text
smaller: the hint gives the largest size at which the clearance holds (`size=N mm`: the
strokes and the clearance scale with the size about the text's position), and says nothing of
size when no smaller text clears the mark.
A mark drawn through a text names the letters it crosses (`ring` crosses it at "S" and "F",
or "every letter"). For a tick through a label (one straight line with an end at the text) the
hint says to move the label beside the tick; for any other mark (a ring around a word, an arc, an outline) it offers the width at which the text
clears it where it is written, computed (`max_width=26.4 mm`: it shrinks about its position
point), or that `size=`, or moving the text.
Engraved marks drawn over each other (text aside): a stroke that lies on another mark's stroke
(parallel, within 0.05 mm, over at least 0.3 mm: a ruler's millimetre ticks drawn again under
its centimetre ticks, a bar's side along a tick) is burnt twice, a deeper and wider line,
always a defect; the warning names the mark drawn again and what it lies on, with the length.
Three or more marks of one statement that cross a closed engraved outline and end inside it
(a ruler's ticks running into the outlined bars of its scale) are engraving over engraving;
the hint gives how far to move the outline, along the marks, to leave them 0.3 mm clear. What
a maker means is not warned: strokes that cross and go on (a grid, a crosshair through a
target's rings), a mark that ends on an outline, one or two marks crossing into an outline (a
dial's finger stop across its rim), outlines that cross each other. Labels laid out exactly as
requested (numbers round a braiding disc, each under its slit) are said so with
`AllowOverlap(numbers)` (the drawing, or the texts and marks, named): no W0513 between them.
A mark centred across an outline's line, its ends about as far either side (a dial's ticks
across its ring: run hj), is drawn so on purpose and not "run into" it.

    drawing scale {
        tick = Line(start=(40, 0), end=(48, 0))
        zero = Text(position=(44, 0), text="0", size=4, valign="middle")   # on the tick
        frame = Rectangle(center=(0, 20), width=22, height=10)
        name = Text("SCALE", (0, 20), size=5, valign="middle")     # 0.29 mm from the frame
        for i in range(11) { mm = Line((i, 30), (i, 33)) }
        cm = Line((0, 30), (0, 36))                                 # over the first mm tick
    }
"""),
    "W0514": ("hole only touches the outer edge", """
A hole lies wholly inside its solid (no part of it is drawn past the edge) and only touches the
outer edge: at a point (a circle tangent to the edge, a window's corner on the roof line) or
along less than the minimum wall (0.5 mm unless `--min-wall`). The wall between them has zero
width, so the hole is pinched open onto the edge: neither a closed hole nor a clean notch. The
warning names the hole, says how long the contact is and where it is: the point of contact
itself, each one (a circle in a corner touches two edges), to 0.01 mm (on a hole's circle the
point of the circle nearest the edge), not the hole's centre. Move the hole inward to leave
material around it, or out past the edge to make a notch. A hole flush with the edge along more
than the minimum wall is a notch (a connector cut-out, a cross-halving slot) and is not warned.

    solid board {
        body = Rectangle(center=(0, 0), width=60, height=40)
        hole bolt { c = Circle(center=(-20, 10), radius=10) }   # tangent to two edges
    }
"""),
    "W0515": ("opening no hole cuts", """
An opening is cut through a solid part where no hole declares one: the shapes around it,
united, leave a window the program never names (the part comes out with it; the warning says
so, never "filled"). A small one (less than 1 mm^2, or twice the minimum wall squared) is a
void where the shapes nearly meet but leave a gap, which a laser cuts out as a sliver: the warning gives its area, width, length and place, and names the shapes around it (at the first of them); make the shapes overlap (a
negative gap, a larger size). A part says its first 5 voids, the fifth ending "(and N more
like it in `part`)". A larger one enclosed by the faces of ONE solid structure,
some of them overlapping (a dinosaur's legs and belly that merge around a window, a bracket's
gusset window), is a note: 10 of the 13 such windows the model runs met were meant. It says
plainly that the opening is cut through the part (the part comes
out with that window, around an island of material when one lies inside it), names the faces
around it, its size (width x height of its box, area) and centre. If it is not meant, fill
it: make the shapes overlap across it (the opening is then gone). If it is meant, say so with
`AllowOverlap` naming the shapes around it, written in their solid, as the hint (and the
`--json` fix) writes: `AllowOverlap(base, post, brace)`. The part is unchanged by it (the
opening stays cut), the statement names the shapes, not coordinates, so it holds whatever the
params make of them, and it adds nothing to solve (`--dof` says the same). Naming only some
of the shapes around it does not say it. A `hole` declared over the opening (cutting no
material) declares it as well, and is not W0502. Not warned: an opening framed by several
solid structures (a telephone's cradle between its base and handset), or by faces that only
abut edge to edge (a frame of bars), or one that a hole cuts or covers.

    solid frame {
        left = Rectangle(center=(-5, 0), width=10, height=10)
        right = Rectangle(center=(5.05, 0), width=10, height=10)   # 0.05 mm from `left`
        top = Rectangle(center=(0, 6), width=30, height=2)
        bottom = Rectangle(center=(0, -6), width=30, height=2)
    }

    solid dino {
        belly = Rectangle(center=(0, 0), width=60, height=20)
        front_leg = Rectangle(center=(-8, -20), width=8, height=24)
        back_leg = Rectangle(center=(8, -20), width=8, height=24)
        feet = Rectangle(center=(0, -31), width=30, height=4)   # an 8 x 19 mm window
    }
"""),
    "W0516": ("engraving meets the cut edge", """
An engraved mark meets the part's cut edge (its outline or a hole's edge), so the laser engraves
where it cuts. Along the edge: the mark lies on the outline (within 0.05 mm) over more than a
third of it and is lost in the cut (a protractor's 0 and 180 degree ticks drawn on its straight
edge, a border drawn on the outline); the warning says how much of the mark lies on it. Against
the edge: the mark ends on the edge or comes within 0.5 mm of it (a knight's mouth
line drawn to the outline, a line ending a hair short of it: the sliver left between engraving
and cut chars or breaks off); the warning gives the gap in mm, which edge and where (x, y), and
how far inside to end or move the mark (to 1 mm clear: at 0.5 mm a mark still reads as on the
edge). The same statement in several parts a loop made (a template called five times) is said
once, naming the other parts. Straight ticks that end on the edge and meet it square,
three or more on one part, are a scale hanging from the edge (a ruler, a protractor) and are
not warned; nor are two or more pieces of one straight line, each ending square on the edge (a
line across the part broken by a hole or a word: a router template's door-edge line); nor a
closed mark with a side lying on the edge, run out at the cut (a toy track's filled grooves
ending at the deck's ends: run dh), nor a filled mark (`fill=true`) run up to or along the
edge: engraved to the cut, it is seen, and no sliver is left (run dq's moon phases, dark to the
disc's rim); one that stops within 0.5 mm of it is warned; nor lines clipped to an area
(`Intersect(area, lines)`, a hatch) that end on the edge where the area's edge is the cut (run
eu's thread lines clipped to a reel's barrel). How much of a mark lies on the edge
is measured along its length. Letters: a text's strokes (or a font's outlines) within 0.2 mm of the edge
(letters set tight beside a hole on purpose, farther than that, are not warned); the warning
gives the gap and how far to move the text. Move the mark inside, or leave it out: the cut already draws the edge.
A mark meant to meet the edge (ticks meeting at a rim, a footprint on the edge of the mortises
a panel fills: runs gj, go) is said so by `AllowOverlap(MARK, self)` in the part (a gap
within the chords' 0.01 mm of 0.5 mm is clear: a mark set 0.5 mm in is not warned). A tick
ending at an inside corner is square when it is square to either edge it ends on (a depth
scale's zero tick where the fence meets the body: run gn).

    solid plate {
        body = Rectangle(center=(0, 0), width=60, height=40)
        drawing marks {
            edge = Line((-30, -20), (30, -20))   # on the bottom edge
            arrow = Line((0, 0), (30, 10))       # ends on the right edge
        }
    }
"""),
    "W0517": ("parts collide when assembled", """
The program places its parts in 3D (`Place`), and two parts' solids, each its profile extruded
by its `thickness` and placed, overlap by more than 0.001 mm^3 and 0.05 mm deep (thinner is
contact, under half a kerf: run fa's rails resting on a box's corner edge, 0.002-0.04 mm):
assembled, they cannot both be there. Most often a slot (or the gap between two fingers) is narrower than the thickness of the
part that goes in it, or the material is thicker than the joint was drawn for. The warning
names both parts, the common volume, its depth (the smallest side of its box: by how much the
slot is too narrow) and the box where it lies. Widen the slot to the partner's thickness, use
the material the joint was drawn for, or move the part with its `Place`; a collision 1 mm
deep or more is a part misplaced (an offset's sign, a position), and the hint leads with
moving it. When the common volume is thinnest across the other part's sheet, not across the
part that goes in, an edge or a shoulder presses into that part's face (a riser's shoulder
0.3 mm into a sloping plank's underside: run dj), and the hint says so, not a slot. Two
standard-library template instances that stand in one place (neither placed, laid out only on
the sheet, which moves no part in 3D) are one warning naming the two, its hint their `Place`
(run ax's two drawers, ten of their panels colliding). Two parts meant to
share material (a press fit drawn to size, an inlay) are named in `AllowOverlap(a, b)` in
their assembly, which this check then leaves alone, as W0511 does. The check reads the
designed parts: a `kerf` is compensated in the cut files, so the parts come out that size.
A bent part (`Bend`) is made of chords within 0.005 mm of its bend: an overlap with it no
deeper than that, or thinner than that on average over its box (a bent roof lying on its
arches), is contact, not a collision. The depth is that of the thickest piece of the common
volume, each piece measured on its own where faces the parts share join pieces by sheets of no
thickness (roof tabs 0.964 mm off their slots down a slope: run gm). A part with no `Place`
among placed ones lies flat as drawn, and the hint says so first (run gw's hat rack).

    import "std/joints.aidl"
    thickness 3.5 mm                # the material is thicker than the fingers were cut for
    assembly kit { box = finger_box(thickness=3 mm) }
"""),
    "W0518": ("part touches no other part when assembled", """
The program places its parts in 3D (`Place`), and one part comes no nearer than 0.1 mm to any
other: assembled, it floats free, as when a tab does not reach its slot or a placement is off
by a figure. Nearer is contact: the clearance of a fit (meshing gears' backlash, a slot cut a
little wider than its tab) is not a gap. The warning names the part, the nearest other part
and the gap. Move the part by the gap with its `Place`, or lengthen the tab. A gap between two
parts that one standard-library template places (the gears `gear_train(lift=...)` stands
above its plate) is the template's design and not reported. A part with no `Place` that lies
5 mm or more from every other (drawn beside the product on the sheet, never put in it) is a
note: the parts are cut as drawn either way, and `Place` puts it in the assembled product.
A placed part 5 mm or more from every other (carried by an axle, hooks, hardware) is a note
too, and so is one with a round hole whose axis, assembled, runs through a round hole of
the part it comes nearest (within 0.05 mm; holes at most 26 mm across, one at most three times
the other, in planes up to 150 mm apart; a part with more than 200 such circles is not looked
at): a pin, an axle or a bolt holds it and its gap is play (a boom on a dowel between its
uprights, a toy's wheels on their axles). So is a part that passes through an opening of the
part it comes nearest (a spreader loose in its stand's slot: run ds), held there with play,
and one that lies inside another's box as placed, or round one (a drawer in its sleeve: run
fk's matchbox, 0.18 mm of play all round).

    thickness 3 mm
    assembly kit {
        solid base { r = Rectangle(center=(0, 0), width=40, height=40) }
        solid wall { r = Rectangle(center=(0, 0), width=40, height=20) }
        Place(wall, rotation=(90 deg, 0, 0), position=(0, 0, 14))   # 1 mm above the base
    }
"""),
    "W0519": ("slit narrower than the minimum", """
Two parts of one outline almost meet and leave a slit of EMPTY space narrower than the minimum
wall (0.5 mm unless `--min-wall`; 0 turns it off) reaching into the part: narrower than a
laser or router cuts, so it comes out as a ragged notch or not at all (a dog-bone tag whose
two end lobes nearly touch beyond the bar). Found between the non-adjacent edges of one loop
of the outline that face each other (opposite within 30 degrees) across empty space, over at
least the minimum's length; the openings that holes cut are not searched (a narrow hole is
declared so). The warning gives the least width, the length, the place and the shapes on its
two sides. Make them overlap by at least the minimum (a bare overlap of two round sides
leaves a V-notch at their junction, as narrow), or open the gap to at least the minimum. Where the two sides
meet at the slit's floor in a corner sharper than 60 degrees (a nick: an arm joined low on a
rounded corner), moving one away would part them (W0504) and moving it in only moves the
nick; the hint then rounds that inner corner alone, `Fillet(at=[(x, y)], radius=min_wall)`,
which fills the nick and leaves the rest of the outline as it was. Where one side leaves the
other along its tangent (a cusp: an arm flush with the straight side of a rounded corner) no
move or fillet closes it, and the hint says to cover the rounded corner whole or square it.
The moves are rounded up to 0.01 mm (made as written, the gap reaches the minimum). A part
says its first 5 slits; the fifth ends "(and N more like it in `part`)"
with the count of the rest (a part of thousands of discs that falls apart).

    solid tag {
        bar = Rectangle(center=(0, 0), width=30, height=12)
        top = Circle(center=(15, 6.1), radius=6)
        bottom = Circle(center=(15, -6.1), radius=6)   # 0.2 mm from `top`
    }
"""),
    "W0520": ("ledge where two edges almost align", """
One shape of a solid pokes past another's edge by less than the minimum wall (0.5 mm unless
`--min-wall`), so the outline has a tiny ledge where the two edges were meant to align: a
music note's stem 0.2 mm past its head's side, a heart's round lobes bulging a hair past the
triangle's straight sides. Found in the final outline as two corners of opposite turns (over
30 degrees each) at most twice the minimum apart between stretches that keep their
direction, offset sideways by 0.01 mm to the minimum; or as a shallow crossing (2 to 30
degrees) after a straight side where the other shape strays out past that side's line by
0.01 mm to the minimum and comes back across it. Only corners where two different shapes
meet count (a step drawn in one polygon is meant); a shape set back from another's side
counts as that other poking past it. The warning names both shapes and the ledge's size and
place, and the hint the move that aligns the poking shape, as a vector (`move `note.stem`
by (-0.200, 0.000) mm`: resized about its centre instead, a shape's edge moves half as
far). Align the edges (a constraint, or the number that is off), or make the offset clear
if a ledge is meant. A part says its first 5 ledges; the fifth ends "(and N more like it in
`part`)". A ledge under 0.1 mm is a note: it hardly shows once cut (a trapezoid's sloping
side 0.07 mm off a joint's notch), and is worth aligning only where it is a fit. A shape
that pokes past another by the same on both sides (a star's petals past a stem) is said
once, its hint a resize that keeps its middle: a move would double the other side's ledge.

    solid note {
        head = Ellipse(center=(0, 0), rx=8, ry=6)
        stem = Rectangle(center=(6.7, 25), width=3, height=50)   # 0.2 mm past the head
    }
"""),
    "W0101": ("statement has no effect", """
An expression statement that is neither geometry nor a constraint. Also a `min_wall`
statement where no check reads it: inside a structure that is not a part (a `cut`, a `hole`, a
solid merged into its part). The wall checks hold each part to one minimum, so write it in the
part (it covers the part's holes and through-cuts) or at the top of the file.

    solid plate {
        body = Rectangle(center=(0, 0), width=60, height=30)
        cut slits {
            min_wall 0.3 mm          # no effect here: write it above `body`, in `plate`
            a = Line((-20, 0), (20, 0))
        }
    }
"""),
    "W0103": ("a size that depends on solved geometry", """
A constructor argument that fixes a shape's own size or angle (a `Line`'s `length` and
`angle`, an `Arc`'s radius and angles, a `rotation`, a rectangle's `width`...) is read once,
when the shape is made. If it depends on geometry that the solver moves (`c.radius` of a
circle constrained later), the value before solving is used and held: the shape does not follow
the solved value. Give a number or a param, or relate the shapes with a constraint.

    c = Circle(center=(0, 0), radius=5)
    l = Line(start=(0, 0), length=c.radius, angle=0 deg)    # 5, even if c is solved to 8
    l = Line(start=(0, 0), end=(8, 0))                      # instead: draw it, then
    Length(l, c.radius)                                     # relate it with a constraint
"""),
    "W0106": ("floor division used as a length", """
`//` between two numbers or lengths is floor division (`7 // 2` is 3), and its result is used
as a length, or is a length (`80 mm // 3` is 26 mm): the fraction is dropped, which is rarely
meant for a size. Write `/` for division. `//` is read as floor division after an operand and
before code (`aidl docs comments`); if it was meant as a comment, write `#`.

    r = Rectangle(center=(0, 0), width=80 // 3, height=10)   # 26 mm: write 80 / 3
    w = 80 // width        # floor division by `width`; a comment is `# width`
"""),
    "W0107": ("a plain number read as radians", """
`sin`, `cos` and `tan` read a plain number as radians, unlike arguments that are angles
(`rotation=30` is 30 degrees). A plain number past a whole turn (2 pi) there is almost surely
meant as degrees: labels every 10 degrees written `cos(i * 10)` land at 10 rad = 573 deg, scattered
round the circle. Write the unit: `cos(i * 10 deg)`. Warned once per call; not for a number
made from `pi` or `tau` (`cos(3 * pi)`), which counts radians (`aidl docs pi`).

    x = 40 * cos(i * 10)       # radians: write cos(i * 10 deg)
"""),
    "W0108": ("a setting written as a constant that nothing reads", """
A top-level name that nothing reads and that means a setting. `thickness = 4 mm` and `kerf =
0.2 mm` make ordinary constants: the material thickness (3D outputs, the parts list, the fit
check) stays 3 mm and the cuts get no kerf; the settings are the statements `thickness 4 mm`
and `kerf 0.2 mm` (no `=`), which the fix writes (`param thickness = 4 mm`: the fix adds
`thickness thickness` below it, so the slider sets it). Likewise a top-level name that a
template call of the program leaves at its default (`module = 2 mm` beside
`spur_gear(teeth=20)`): a template sees the file's names only as arguments, so the fix passes
it (`spur_gear(teeth=20, module=module)`).

    thickness = 4 mm        # warning: write `thickness 4 mm`
"""),
    "W0109": ("hole declared in an assembly cuts nothing", """
A hole cuts only the solid it is declared in. One declared in an assembly (beside a template
instance, meant for its lid) is a part of its own: the lid comes out whole, and no output
cuts the hole (the preview SVG draws it dashed where it lies; the laser SVG, DXF, PDF and
G-code leave it out, as the meshes and the parts list do). The warning names
the solid part the hole lies over, and its fix writes `CutInto(HOLE, PART)` in the assembly,
which cuts that part (a part of a template instance cannot be cut any other way: its body is
the template's). `CutInto` is written where both are, so it keeps the subtree rules; place the
hole with constraints as usual.

    assembly kit {
        box = finger_box(length=80 mm, depth=80 mm, height=50 mm)
        hole lid_hole { c = Circle(center=(0, 0), diameter=20) }   # warning: cuts nothing
        CenterInside(lid_hole, box.lid)
        CutInto(lid_hole, box.lid)                                 # the fix: a hole in the lid
    }
"""),
    "W0110": ("design breaks inside a param's range", """
`aidl check --sweep` (and `Result.sweep()`, MCP `check` with `sweep: true`) compiles the
design across its params' ranges: the declared `min=`..`max=`, or for a param that declares
none the span the studio's slider gives it. Each param at its low end, middle and high end
(the others at their written values), then a small seeded Latin hypercube of combinations,
within a budget of work that is the same on any machine (what it leaves is said as "not
judged, out of budget", never as bisected). This warning, located at the `param` line (the
other params of a combination as labels), names the values at which the design stops
compiling (an error; values that leave a dependent range empty, E0124, too), a part changes
its topology (a solid falls into pieces, a hole leaves its solid or breaks through its
outline, holes merge: as W0510), or a warning appears that the written values do not have;
the message gives that code and its message. The hint gives the largest clean range found
by bisection between the written values and the failing ones, and the fix writes it into
the `param` line: narrow (or declare) the range to it, or fix the design so that it holds
across the range.

    param offset = 10 mm, min = 0 mm, max = 30 mm   # warning: with offset=30 mm, W0502
    solid plate {
        body = Rectangle(center=(0, 0), width=50, height=30)
        hole h { c = Circle(center=(offset, 0), radius=3) }   # leaves the plate past 21.4 mm
    }
"""),
    "W0111": ("text along a curve longer than its circle", """
A `Text(..., along=c)` is laid along the circle of `c` (a Circle, or an Arc's circle) letter by
letter, and the text is longer than that whole circle: its last letters run round onto its
first ones, on top of them. The warning gives the text's length and the circle's, and the fix:
the largest size that fits, the smallest radius that holds it, or a shorter text. It points at
the Text.

    drawing d {
        c = Circle(center=(0, 0), radius=5, construction=true)      # 31.4 mm around
        t = Text("HELLO WORLD AGAIN", along=c, size=5)              # 74.5 mm long: W0111
    }
"""),
    "W0112": ("bidirectional control or line separator in a comment or string", """
A character that makes the source read otherwise than it runs ("Trojan source"): a
bidirectional embedding, override or isolate (U+202A to U+202E, U+2066 to U+2069), which
reorders how the rest of the line is displayed (a comment that seems to end before the code
after it, a string that seems to hold other words), or a line or paragraph separator (U+2028,
U+2029), which some editors show as a line break that the compiler does not count: lines end
at LF, CR LF and a lone CR, so every line number a diagnostic gives stays the one the editor
shows. In a comment or a string it is this warning, one per character, with a caret under it
and the code point named (`U+202E RIGHT-TO-LEFT OVERRIDE`); the fix deletes it. In code it
cannot start a token: `E0002`, which names the code point too. A diagnostic that prints a
source line holding one shows it as U+FFFD, one column wide, so the line is not reordered
under its caret.

    # admin<U+202E> nimda      <- with the character itself there, the rest of the comment
                               #    shows reversed: W0112 at line 1, column 8
"""),
    "W0113": ("text shrunk to fit its max_width", """
A `Text(..., max_width=w)` whose text is wider than `w` along its baseline at its `size` is
drawn at the size at which it is exactly `w` wide (a note, not a warning: the program asked for
it). The note gives the size asked, the width it had and the size drawn. Nothing to change
when fitting is meant: the size follows `max_width` and the text whenever they change (a hard
size would not); for a set size instead, give that size (or less) without `max_width`, or a
wider `max_width`. A stencil's width counts its stroke
`weight`; along a curve the width is its length along the curve.

    drawing label {
        t = Text("ROSEMARY", position=(0, 0), size=10 mm, max_width=60 mm)
        # note: 75.2 mm wide at size 10 mm: drawn at size 7.98 mm, 60 mm wide
    }
"""),
    "W0114": ("unknown escape in a string", """
A backslash in a string starts an escape: `\\n` a line break, `\\t` a tab, `\\\\` a backslash,
`\\"` and `\\'` a quote. Any other backslash is kept as written, backslash and all, and warned:
`Text("50\\% off")` engraves `50\\% off`. Write `\\\\` for a backslash you mean, or leave the
backslash out. A path such as `"C:\\temp\\new"` holds a tab and a line break: write
`"C:\\\\temp\\\\new"`.
"""),
    "W0115": ("param that nothing reads", """
A `param` that no statement of the program reads: its slider (`aidl studio`, `aidl serve`) and
`--set NAME=...` change nothing, which is rarely what was meant (a size written as a number
where the param should be). Use it where the size it names is written (`width=plate_w`), or
delete the line.

    param plate_w = 120 mm, min = 80 mm, max = 200 mm
    solid plate { body = Rectangle(center=(0, 0), width=120 mm, height=60) }   # width=plate_w
"""),
    "W0116": ("drawing in an assembly lies on a part, engraved on none", """
A drawing declared in an assembly is an illustration beside the parts, engraved on none of
them. One that lies on a solid part of the assembly (all of it on the part's material: "TEA" beside `box = finger_box(...)`, placed on the front) is engraved there by the
flat sheet, while a cutting layout (`aidl render --layout sheet`) and `aidl parts` carry the
part without it: the front comes out of the nested sheet blank. The fix writes
`CutInto(DRAWING, PART)` in the assembly, which engraves it on that part in every output (a
part of a template instance cannot be given a drawing any other way). `aidl import` writes
that call for a drawing layer that lies on a part (a board's silkscreen on its outline).

    assembly kit {
        box = finger_box(length=150 mm, depth=75 mm, height=80 mm)
        drawing label { word = Text("TEA", position=(0, 0), size=25) }   # warning
        CenterInside(label, box.front)
        CutInto(label, box.front)                                         # the fix
    }
"""),
    "W0117": ("template or function that nothing calls", """
A `def` of the program's own file that no statement calls, in a file that draws a design (a
file of only templates is a library, and gets no warning): nothing of the template is made, so
a part or a hole the program meant to have may be missing (run aa's lipstick stand kept a
`def joint_slots(x) -> hole` it never used). Call it where its part belongs, or delete it if
it is left over.

    def slot(x) -> hole { s = Rectangle(center=(x, 0), width=3, height=20) }   # warning
    solid plate { body = Rectangle(center=(0, 0), width=100, height=60) }
"""),
    "W0118": ("template's thickness is not its parts' material", """
A template that makes parts (`finger_box`, `flex_box`, `finger_panel`, a stand) draws its
joints, bends and slots for its `thickness=` argument (3 mm unless given), while its parts are
cut from the material in force at the call: the `thickness` statement of the nearest structure
around it, else the file's, else 3 mm (what the 3D outputs, the parts list and the fit check
read). When the two differ, the joints are drawn for one material and the parts made of
another: assembled they do not fit, and the errors and collisions that follow come from inside
the template (run dc's drum: `flex_box(thickness=3 mm)` in a file of `thickness 6 mm`, its
bends overlapping). Give the call `thickness=` the material, or put the call in a structure of
its own that says `thickness` for its parts. A joint template (`tab_and_slot`, `finger_edge`,
`cross_halving`: a hole) takes its partner's thickness and is not judged.

    thickness 6 mm
    assembly toy {
        drum = flex_box(thickness=3 mm)      # warning: its parts are 6 mm
    }
"""),
    "W0104": ("empty drawing", """
The file is empty (nothing but comments), or its structures build no geometry at all, so the
SVG would be empty. Add shapes, or instantiate a template. A file of only templates, params and
constants is a library and gets no warning.
"""),
    "W0105": ("character not in the engraving font", """
`Text` is drawn with a single-stroke (Hershey) font that covers printable ASCII and the
symbols of dimensions `° ± × µ Ø ø ⌀` (what DXF's `%%d %%p %%c` decode to). Characters
outside it (accents, other scripts, tabs, symbols such as `☃`) cannot be drawn and are left
out; the warning names each one with its code point.

    drawing labels { t = Text("Café", (0, 0)) }    # `é` (U+00E9) is left out
"""),
    "W0521": ("shape check not finished (note)", """
A note, not a warning: a family of the shape checks on the final part stopped before it had
looked at everything, so what it would have said about the parts named is not known. Each
family (holes, pieces, engravings, walls between features, openings, thin walls, slits,
ledges, text, copies that merge) holds a share of the compile's work (a fifth of the
budget: 400 000 of the default 2 000 000 units, the same on every machine) and stops past it,
or before a step that cannot be interrupted (one Manifold call) when that step's price would
pass its share or the compile's budget; and none lists more than 3,000,000 pairs
of edges or shapes within reach of one another (a map of a country imported a few mm wide
puts every edge within the minimum wall of hundreds of others). Nothing is wrong with the
part because of it: `--budget 2` gives every check twice the work; a drawing scaled to its
real size (or a smaller `--min-wall`) has fewer edges within reach.

    aidl check usa.aidl
    # note[W0521]: not checked: slits (W0519) in `borders`: out of its share of the work (400,000 of the 2,000,000 work units of the budget)
"""),
    "W0522": ("through-cut that cuts nothing (or a stretch already cut)", """
A curve of a `cut` structure is a through-cut: the laser cuts along it through the part. This
one has no stretch on the material of its part (it is drawn beside the part, or inside a hole),
or no length (its ends on each other), so it cuts nothing. Move it onto the part, or delete it; a line meant to be engraved belongs in
a `drawing`. A through-cut drawn along the part's outline (or a hole's) from end to end adds
nothing either: the outline is cut anyway, and the outputs cut that line once (no stroke is
written for the cut). Delete it; to cut the part along a new line, draw it across the
material. Every segment of every curve is judged alike: a Polyline (Spline, Bezier) whose
first side lies on the outline while the rest cuts into the part is W0522 naming that side
(start the curve past it), and the outputs cut the outline there once. So is a through-cut
that runs along another of the same part (two slits on one line that overlap, an arc over
another of the same circle, copies of one cut at one place): the warning names both, and the
outputs cut the stretch they share once. Cuts that only meet end to end share nothing. A
through-cut that separates material makes the piece it cuts off a part of its own (or a hole,
when the piece is enclosed); one that leaves a web thinner than the minimum wall between two
cuts, or a cut and the outline, is W0507.

    solid panel {
        body = Rectangle(center=(0, 0), width=60, height=30)
        cut slits {
            a = Line(start=(40, 0), end=(50, 0))       # beside the panel: cuts nothing
            b = Line(start=(-30, -15), end=(30, -15))  # along its bottom edge: adds nothing
            c = Polyline([(-30, -15), (-20, -15), (-20, 0)])   # its first side: the same
            d = Line(start=(0, 5), end=(20, 5))
            e = Line(start=(10, 5), end=(25, 5))       # runs along d for 10 mm
        }
    }
"""),
    "W0523": ("AllowOverlap that allows nothing", """
An `AllowOverlap` statement none of whose names overlap or touch in the final drawing, so it
silences no warning: it concerns a hole and what refills it (W0501), two holes that cut one
opening (W0508), the shapes of one hole that merge (W0512), or two parts of an assembly
(W0511; a program that places its parts in 3D with `Place` is not judged, W0517). Shapes of
one solid named together say that the window they enclose is meant (W0515): such a statement
allows nothing when no W0515 opening has all its bounding shapes among them (it is said so:
"enclose no opening that is warned about"). Usually it names other shapes than meant (a pattern's original where its copies overlap: name the
pattern's list), or an edit moved the overlap away. Name the shapes a warning named (its hint
writes the call), or delete the statement.

    solid plate {
        body = Rectangle(center=(0, 0), width=80, height=40)
        hole a { c = Circle(center=(-20, 0), radius=5) }
        hole b { c = Circle(center=(20, 0), radius=5) }
        AllowOverlap(a, b)          # 30 mm apart: W0523
    }
"""),
    "W0524": ("line of zero length in a drawing", """
A `Line` of a `drawing` whose start and end are one point (`Line((x, y), (x, y))`, often a
loop's formula that gives both ends the same value): it engraves no line, only a plunge at a
point, and nothing holds its two points (each is a free starting guess, so the degrees of
freedom left count them). One warning per statement, with the number of its copies. Give the
Line two different points, or delete it; a dot is a small Circle.

    drawing strings {
        for i in range(5) { s = Line((-30 + 15 * i, 0), (-30 + 15 * i, 0)) }   # W0524
    }
"""),
    "W0525": ("sheet-level cut across a part", """
A `cut` directly in an assembly is a sheet-level cut: the laser cuts along each of its curves
where it is drawn, in no part (the rest of a slot drawn across a plate's edge, lines in the
scrap between parts; `aidl import` writes the cut paths of a drawing that lie in no part so).
This curve runs across the material of a part: the laser cuts that part there, but the part's
outline, area, 3D view and fit check are without the cut. To cut the part, move the curve into
a `cut` inside the part's solid; a sheet-level cut belongs beside the parts, off their material.

    assembly sheet {
        solid plate { r = Rectangle(center=(0, 0), width=60, height=40) }
        cut scrap { a = Line(start=(40, -10), end=(40, 10)) }     # beside the plate: fine
        cut slits { b = Line(start=(-10, 0), end=(10, 0)) }       # across the plate: W0525
    }
"""),
    "W0526": ("hole in a drawing that hides none of its lines", """
A `hole` inside a `drawing` hides that drawing's lines where it covers them (engraving minus
engraving: a compass rose's points behind the ones in front). This hole covers none of them:
it is somewhere else, or in the wrong drawing (it hides only the drawing it is declared in and
that drawing's children). Move it over the lines it should hide, or delete it.

    drawing back {
        p = Polygon(points=[(0, 0), (20, 5), (30, 30), (5, 20)])
        hole front { q = Circle(center=(60, 0), radius=5) }     # covers nothing: W0526
    }
"""),
    "W0528": ("countersink or counterbore head larger than the material around it", """
The head of a `Countersink` or `Counterbore` (its `diameter`) must be larger than its hole and
fit the material around it: a head that reaches past the part's edge or into another hole
leaves a screw's head unsupported there (and a router's V-bit cuts the edge away). Move the
hole half the head's diameter or more from the edges and the other holes, or give a smaller
head (an M4 flat-head screw: a 4.5 mm hole, a 9 mm head).

    solid plate {
        body = Rectangle(center=(0, 0), width=40, height=20)
        hole h { c = Circle(center=(17, 0), diameter=4.5 mm) }
        Countersink(h, diameter=9 mm)                # 3 mm from the edge: W0528
    }
"""),
    "W0529": ("countersink or counterbore deeper than the part", """
A countersink's cone is `(diameter - hole) / 2 / tan(angle / 2)` deep; a counterbore is its
`depth` deep. At or past the part's thickness the head goes through the part and leaves no
seat for the screw's head. Give a smaller head, a wider angle or a shallower depth, or use
thicker material.

    thickness 3 mm
    solid plate {
        body = Rectangle(center=(0, 0), width=40, height=20)
        hole h { c = Circle(center=(0, 0), diameter=4 mm) }
        Counterbore(h, diameter=8 mm, depth=4 mm)    # 4 mm in 3 mm: W0529
    }
"""),
    "W0530": ("a closed opening runs out through the part's edge", """
A hole made by a standard template whose opening is meant to be closed (`keyhole`,
`clearance_hole`, `nut_trap`, `hex_pocket`) reaches past the part's outer edge, so the part
gets an open notch where a closed opening was asked: a keyhole whose slot (10 mm long by
default) runs out through the top edge no longer holds on its screw. The warning names the
hole, how far it runs out (its farthest point from the part's edge, and where) and the fix:
shorten its slot (`length=`) or shrink it, or move it inward, by that much and a wall of twice
the minimum. An edge notch meant as one (a finger notch, a cable exit, drawn with a shape of
its own) is not warned. So too the slots of a `tab_and_slot(part="slot")`, a mortise, that
lie on the outer edge or run past it (a lip's slots drawn flush with a ledge's front edge): the
mortise is cut open into a notch the tab can slide out of, and no wall is left to call thin.

The same for a pattern's copy that runs out through the outer edge while the pattern's original
is a closed hole (a pattern of holes, or of shapes in one hole): `AlignCenterX(peg, body)`
centres the original, so of two peg holes 80 mm apart the second breaks out of a 160 mm plate.
The warning names the deepest copy, how far it runs out and where, and how many copies do; to
centre a pattern, place its original half the pattern's span off the centre. A row of notches
whose original runs out too is drawn open on purpose and is not warned. So too the letters of
a font Text in a hole (a stencil name cut through a panel) that reach past the edge: a letter
is cut open there (a word 85 mm wide on an 80 mm wall); fit it with `max_width=`, a smaller
size, or move it inward.

    import "std/plates.aidl"
    solid plate {
        body = Rectangle(center=(0, 0), width=60, height=40)
        hang = keyhole(head=8 mm, cx=0 mm, cy=12 mm)    # its 10 mm slot reaches y = 24
    }
"""),
    "W0527": ("inside corners the router's bit does not reach", """
A router's bit is round: at an inside corner of a part's material (the bottom of a finger
joint's slot, a tab's slot, a halving, a rectangular hole) its centre runs the outline offset by
its radius r, so its edge stays r / sin(a/2) - r from the drawn corner (0.658 mm for a 90 degree
corner and a 3.175 mm bit) and the mating part's square corner does not seat. `aidl render
--machine` with a router profile whose `relief = "none"` says it, at the part, naming the
corners and how far the material stays. Set `relief = "dogbone"` (the bit runs along the
corner's bisector until its edge touches it; the built-in router profile's default) or
`relief = "tbone"` (along the longer side) in the profile; the SVG and DXF stay as drawn.

With a relief, a corner where the relief cannot be cut as asked is said the same way, at the
hole (or outline) it is on, with the reason: a corner sharper than 60 degrees, where the bit's
stroke from the tool path's corner would gouge both edges (a 10 degree corner's dogbone takes
3.5 times the bit's disc), or a wall the stroke would cut through or leave thinner than the
minimum wall (`min_wall`; a T-bone into a 1.2 mm wall cuts the part in two). There a T-bone is
cut as a dogbone when that fits, else the corner is left as the offset path leaves it. Widen
the corner to 60 degrees or more, keep the wall the bit's radius plus the minimum wall, or use
a smaller bit.

    # router.toml
    kind = "router"
    relief = "dogbone"
    # program: a 20 x 10 mm hole 0.4 mm from a 60 mm plate's edge, min_wall 0.3 mm
    hole window { w = Rectangle(bottom_left=(39.6, 15), width=20, height=10) }   # W0527
"""),
    "W0531": ("parts nearer each other than the tool is wide", """
A router's bit runs its centre a radius off each part's outline, so it cuts a whole diameter
away from the part; a laser's kerf likewise.  Two parts drawn (or laid out) nearer each other
than that lose material to each other's cut: `aidl render --machine router` of parts 3 mm apart
takes 0.175 mm from each with the 3.175 mm bit.  Draw the parts at least the tool's width
apart, or lay them out for cutting with a larger gap (`--layout sheet --gap 5mm`).  Parts that
touch (pieces a cut freed, sharing an edge that is cut once) are not said. Said where the kerf
or the bit is applied: `aidl render` (and the MCP server's `render`), not `aidl check`, which
cuts nothing (run ek: parts touching on the sheet passed the check clean); a program that
states its `kerf` is judged by `aidl render -o x.svg` too.

    solid a { r = Rectangle(center=(0, 0), width=12, height=12) }
    solid b { r = Rectangle(center=(15, 0), width=12, height=12) }   # 3 mm apart: W0531
"""),
    "W0532": ("engraved text under another part", """
A note, or a warning where the covering part passes through the text's part (it reaches past
both of its faces: a cross-halving's other panel, a shelf through its mortise), so a joint
holds it there and nothing moves off (runs fg, fi: two coat stands' names half hidden where
the other panel crosses). The program places its parts in 3D (`Place`), and engraved `Text` of a
part lies under another part as placed: two or more of 16 points along its letters, just off
the face the laser engraves (the face up on the sheet), lie inside the other part's solid. If
that part turns, slides or lifts off (a volvelle's disc with its window, a pantograph's arm, a
lid), nothing is needed. If it is fixed there, the text cannot be seen (runs ei and em: a
pocket mirror's back engraved facing the ring glued on it, a greeting under the disc glued on
top; only the pictures showed it): the laser engraves the face that is up on the sheet, so turn
the part with its `Place` (`face=`, `up=`) so that face looks out, mirroring the text
(`Mirrored`) if it must read from the other side, or move the text clear. One note per pair
of parts, naming the texts. Other engraved marks are not judged: an outline engraved where a
part is glued is a guide. A text meant to lie there (run gc's mould box: the size under the
slot in use, read before the wall goes in) is said so by `AllowOverlap(DRAWING, PART)` in
their assembly, the text's drawing and the part over it.

    assembly mirror {
        solid back {
            disc = Circle(center=(0, 0), radius=30)
            drawing words { t = Text("EMMA", position=(0, 0), size=8, valign="middle") }
        }
        solid glass { c = Circle(center=(0, 0), radius=25) }
        RightOf(glass, back, gap=5)        # on the sheet: beside it
        Place(back, position=(0, 0, 0))
        Place(glass, position=(0, 0, 3))   # assembled: on the engraved face, W0532
    }
"""),
    "W0533": ("a drawing's hole hides a whole shape", """
A hole inside a `drawing` hides the engraving under it (a label's box kept clear of the lines
that cross it); here it covers every line of one of the drawing's own shapes, so that shape
is not engraved at all (run es's garden gnome: the hole meant to trim the beard hid the whole
nose, and no message said so). Move or shrink the hole so that it leaves the shape, or draw
the shape in a drawing of its own beside this one, which the hole does not hide. The copies a
loop makes are not judged (grid lines inside a masked label's box are meant).

    drawing face {
        nose = Circle(center=(0, 0), radius=5)
        hole trim { r = Rectangle(center=(0, 0), width=20, height=20) }   # hides the nose
    }
"""),
    "W0534": ("part larger than the default sheet (note)", """
A note, not a warning: a part's box does not fit the 600 x 400 mm sheet that `aidl render
--layout sheet` fills when no `--sheet` is given (3 mm from its edges), laid or turned 90
degrees, so that layout would refuse it (runs eg and ew: a 600 mm band and 600 mm arms checked
clean, and only the layout said so). For a larger bed give its size (`--layout sheet --sheet
1000x600mm`); for this one, make the part smaller or cut it in pieces that join.

    solid band { r = Rectangle(center=(0, 0), width=620, height=40) }
"""),
    "W0130": ("drawing entities skipped", """
Entities of a drawing that have no exact form here are skipped and counted, named by kind:
rational or high-degree splines, hatches, dimensions, images, a mirrored or skewed SVG text
(an ELLIPSE, whole or partial, and an SVG elliptical arc are read exactly; DXF TEXT and MTEXT
and SVG text are engraved); a DXF without `$INSUNITS` is read as millimetres (give `units=`).
What the import changed is counted too: gaps closed, paths closed where their end crosses
their start (the overshoot trimmed), small self-crossing loops cut off, open paths on a cut
role written as through-cuts (`cut`), and an SVG path's data that stops at a number that
cannot be read (`inf`, `nan`) or does not begin with a moveto, with its place.  A DXF entity of a type the reader does not
know is skipped and counted by type; a SPLINE whose definition gives no curve (a degree
below 1, too few control points, a count of knots or weights that does not match them, knots
that decrease, a knot repeated so often that the curve breaks apart, a weight not above 0,
fewer than two fit points or two at one place) is
skipped naming its handle and line and what is wrong; the rest of the drawing is read (in
`aidl import`, a layer of only skipped entities is said, not dropped).  Every default
is said: a DXF with no HEADER section (ezdxf's own default header says metres) is read as
millimetres; a TEXT or MTEXT of height 0 or negative takes its text style's fixed height,
else it is skipped; an SVG shape of negative size is not drawn and a negative `rx`/`ry`
ignored (SVG: `auto`), a size in percent read as the viewBox's size, a viewBox of negative
width or height left out (not mirrored).  With `--parts`, an open path on a cut role that
lies in no part is cut, not engraved: closed into a part when it ends within 0.5 mm of its
start, a cut of the part it reaches, else a sheet-level cut.  A shape under a
transform with no area (an SVG `matrix(a,b,c,d,e,f)` with a*d = b*c or a scale of 0, a DXF
INSERT of x or y scale 0) is not drawn, named by its id and line (SVG) or handle and line
(DXF); any other transform is applied exactly.  On a cut role, a hole drawn across its
part's edge is the part's notch, and the rest of its loop (outside the part) is a
sheet-level cut, counted with its length; so are the pieces of holes of one part drawn
overlapping that lie inside another of them (the opening is their union).

    board = Drawing2D("board.dxf")     # warning: 2 HATCH entities of `board.dxf` skipped
"""),
    "W0402": ("open outline", """
Lines and arcs in a solid or hole form faces only when their endpoints meet in a closed loop;
an open chain is written as engraving, not cut.
Share endpoints (`Line(start=a.end, end=b.start)`) or add Coincident constraints.
"""),
}


def codes_markdown() -> str:
    """``docs/codes.md``: every code with its title and explanation (``aidl explain CODE``),
    one heading per code (anchor ``#e0103``, the target of the language server's
    ``codeDescription.href``).  Regenerated by ``python editors/gen_codes_doc.py``."""
    out = ["# Diagnostic codes\n",
           "Every diagnostic `aidl` reports has a stable code: `E` errors, `W` warnings, `N` "
           "notes. This page is generated from `aidl_lang/base/codes.py` "
           "(`python editors/gen_codes_doc.py`); `aidl explain CODE` prints the same text, and "
           "the language server links each diagnostic here.\n"]
    for code in sorted(CODES):
        title, text = CODES[code]
        out.append(f"## {code}\n\n**{title}**\n\n{text.strip()}\n")
    return "\n".join(out)
