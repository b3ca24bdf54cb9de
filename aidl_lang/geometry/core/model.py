"""The interpreted model: a tree of structures holding geometry, parameters and constraints.

Every number the solver may change lives in one parameter vector ``Model.x`` (mm, radians);
``Model.free[i]`` says whether parameter ``i`` is an unknown or held (paper: parameter =
⟨value, mutable⟩).  Points are pairs of parameters in their structure's local frame; each
structure has a translation frame (two parameters) relative to its parent; the root's is held.
"""
from __future__ import annotations

import numpy as np

from ...base.records import Record
from ...base.diagnostics import Span
from .expr import Expr, Lin, _new, var


class Model:
    def __init__(self) -> None:
        self.x: list[float] = []
        self.free: list[bool] = []
        self.param_owner: list["Structure | None"] = []
        self.param_label: list[str] = []
        self.root: Structure | None = None
        self.constraints: list[Constraint] = []
        self.structures: list[Structure] = []
        self.units = "mm"
        self.file_units: dict[str, str] = {}      # file -> its `units` (when not mm), for messages
        self.assertions: list[Assertion] = []     # `assert` statements left for after solving
        self.constants: dict = {}     # the main file's top-level names (params, constants)
        self.holds = 0                # constraints with ``hold`` (solver.holds.settle_holds)
        self.sinks: list[Sink] = []   # `Countersink` / `Counterbore` calls (issue 102)
        # (template, name) of every `instance.name` the program reads of a template instance's
        # scope: the members `values` lists beside its parameters (issue 111)
        self.members_read: set[tuple[str, str]] = set()
        # the lines `Mirrored`/`Flip` mirror about (derived.operations.hold_mirror_lines)
        self.mirror_lines: list = []

    def new_param(self, value: float, free: bool, owner: "Structure | None", label: str) -> int:
        self.x.append(float(value))
        self.free.append(bool(free))
        self.param_owner.append(owner)
        self.param_label.append(label)
        return len(self.x) - 1

    def new_pair(self, x0: float, y0: float, free: bool, owner: "Structure | None",
                 label: str) -> tuple[int, int]:
        """Two parameters ``label.x``, ``label.y`` (a point or a frame): ``new_param`` twice."""
        xs = self.x
        ix = len(xs)
        xs += (float(x0), float(y0))
        free = bool(free)
        self.free += (free, free)
        self.param_owner += (owner, owner)
        self.param_label += (label + ".x", label + ".y")
        return ix, ix + 1

    def xs(self) -> np.ndarray:
        return np.asarray(self.x, dtype=float)

    def all_geometry(self):
        for s in self.structures:
            yield from s.geometry


class Sink:
    """A ``Countersink`` or ``Counterbore`` call: ``kind`` (``countersink`` |
    ``counterbore``), the round holes it sinks (``circles``: Circle geometries of hole
    structures), the head's ``diameter`` (mm), a countersink's included ``angle`` (radians),
    a counterbore's ``depth`` (mm); ``span``: the call."""
    __slots__ = ("kind", "circles", "diameter", "angle", "depth", "span")

    def __init__(self, kind: str, circles: list, diameter: float, angle: float | None,
                 depth: float | None, span: Span | None):
        self.kind, self.circles, self.diameter = kind, circles, diameter
        self.angle, self.depth, self.span = angle, depth, span


class Structure(Record):
    """A structure of the model: kind, parent, frame translation parameters, children, geometry."""
    __slots__ = ("name", "kind", "parent", "span", "fx", "fy", "children", "geometry",
                 "constraints", "scope", "template", "copy_origin", "pattern_original",
                 "cuts_into", "cut_by")

    def __init__(self, name: str, kind: str, parent: "Structure | None", span: Span | None,
                 fx: int = -1, fy: int = -1, children: dict[str, "Structure"] | None = None,
                 geometry: list["Geometry"] | None = None,
                 constraints: list["Constraint"] | None = None, scope: dict | None = None,
                 template: str | None = None, copy_origin: tuple | None = None,
                 pattern_original: "Structure | None" = None, cuts_into: "Structure | None" = None,
                 cut_by: list | None = None):
        self.name = name
        self.kind = kind  # solid | hole | cut | drawing | assembly
        self.parent = parent
        self.span = span
        self.fx = fx  # frame translation parameters
        self.fy = fy
        self.children = {} if children is None else children
        self.geometry = [] if geometry is None else geometry
        self.constraints = [] if constraints is None else constraints
        self.scope = {} if scope is None else scope  # names visible as members (s.NAME)
        self.template = template
        # a copy made by an operation (Mirrored, a pattern) is held on its parent's frame: where
        # the original's origin went, (x, y) expressions in the model frame (Result.values)
        self.copy_origin = copy_origin
        # the first copy of a pattern whose list starts with its original (`holes[1]` of
        # `holes = LinearPattern(bolt, ...)`): that original, which is also `holes[0]`
        self.pattern_original = pattern_original
        # `CutInto(hole, part)`: a hole declared in an assembly cuts the solid `part` (of a
        # template instance, typically) instead of being a part of its own (a drawing so
        # given is engraved on it, issue 111's tea box); `cut_by` on the solid
        self.cuts_into = cuts_into
        self.cut_by = [] if cut_by is None else cut_by

    @property
    def path(self) -> str:
        parts = []
        s = self
        while s is not None:
            parts.append(s.name)
            s = s.parent
        return ".".join(reversed(parts))

    @property
    def depth(self) -> int:
        d, s = 0, self.parent
        while s is not None:
            d, s = d + 1, s.parent
        return d

    def ancestors(self):
        s = self.parent
        while s is not None:
            yield s
            s = s.parent

    def in_drawing(self) -> bool:
        """This structure is a drawing or lies inside one (what it draws is engraved)."""
        return self.kind == "drawing" or any(a.kind == "drawing" for a in self.ancestors())

    def held_by(self):
        """This structure and those that hold it in the output, nearest first: its parents,
        or, for one that ``CutInto`` gives to a solid (a hole, or a drawing engraved on a
        template's part), that solid and its parents."""
        s = self
        while s is not None:
            yield s
            s = s.cuts_into if s.cuts_into is not None else s.parent

    def is_within(self, other: "Structure") -> bool:
        """True if ``self`` is ``other`` or a descendant of it."""
        s = self
        while s is not None:
            if s is other:
                return True
            s = s.parent
        return False

    def subtree(self):
        yield self
        for c in self.children.values():
            yield from c.subtree()

    def frame_offset(self, relative_to: "Structure | None") -> tuple[Expr, Expr]:
        """Translation from this structure's local frame to ``relative_to``'s local frame."""
        tx, ty = {}, {}
        s = self
        while s is not None and s is not relative_to:
            tx[s.fx] = tx.get(s.fx, 0.0) + 1.0
            ty[s.fy] = ty.get(s.fy, 0.0) + 1.0
            s = s.parent
        return Lin(tx), Lin(ty)

    _own = None                    # frozenset({self}) once made (not a field)

    def owner_set(self) -> frozenset:
        """``frozenset({self})``, made once (the owners of every value that refers to this
        structure's geometry)."""
        own = self._own
        if own is None:
            own = self._own = frozenset((self,))
        return own

    def __repr__(self):
        return f"<{self.kind} {self.path}>"


def within_index(items, structure_of) -> dict:
    """Each structure -> the ``items`` whose structure (``structure_of(item)``) is it or lies
    within it, in the items' order: what asking :meth:`Structure.is_within` of every item for
    every structure gives, in O(items x depth) instead of O(items x structures)."""
    out: dict = {}
    for item in items:
        s = structure_of(item)
        for a in (s, *s.ancestors()):
            out.setdefault(a, []).append(item)
    return out


class Point(Record):
    """A point: the indices of its x and y parameters in the model's parameter vector."""
    __slots__ = ("ix", "iy", "owner", "span", "label")

    def __init__(self, ix: int, iy: int, owner: Structure, span: Span | None, label: str = ""):
        self.ix = ix
        self.iy = iy
        self.owner = owner
        self.span = span
        self.label = label

    def local(self) -> tuple[Expr, Expr]:
        return var(self.ix), var(self.iy)

    def in_frame(self, s: Structure | None) -> tuple[Expr, Expr]:
        if self.owner is s:            # the common case: no frame offset
            x, y = _new(Lin), _new(Lin)
            x.terms, x.const, y.terms, y.const = {self.ix: 1.0}, 0.0, {self.iy: 1.0}, 0.0
            return x, y
        ox, oy = self.owner.frame_offset(s)
        ox.terms[self.ix] = ox.terms.get(self.ix, 0.0) + 1.0
        oy.terms[self.iy] = oy.terms.get(self.iy, 0.0) + 1.0
        return ox, oy


class Scalar(Record):
    """A named scalar parameter of a geometry (radius, width, ...): an index, held or free."""
    __slots__ = ("index", "owner", "dim", "label")

    def __init__(self, index: int, owner: Structure, dim: str = "length", label: str = ""):
        self.index = index
        self.owner = owner
        self.dim = dim  # length | angle | number
        self.label = label


class Geometry(Record):
    """A primitive (line, circle, ...): its named points and scalar parameters."""
    __slots__ = ("kind", "owner", "span", "name", "points", "scalars", "data", "parts",
                 "construction", "closed", "listed", "pattern_original")

    def __init__(self, kind: str, owner: Structure, span: Span | None, name: str = "",
                 points: dict[str, Point] | None = None, scalars: dict[str, Scalar] | None = None,
                 data: dict | None = None, parts: dict | None = None, construction: bool = False,
                 closed: bool = False, listed: bool = False,
                 pattern_original: "Geometry | None" = None):
        self.kind = kind  # Point | Line | Circle | Arc | Rectangle | ...
        self.owner = owner
        self.span = span
        self.name = name
        self.points = {} if points is None else points
        self.scalars = {} if scalars is None else scalars
        self.data = {} if data is None else data  # kind-specific: corner radius, text, ...
        self.parts = {} if parts is None else parts  # sub-geometry (rectangle edges, ...)
        self.construction = construction
        self.closed = closed
        self.listed = listed  # in its owner's ``geometry`` (else a part: an edge, a spine)
        # the first copy of a pattern whose list starts with its original (`dots[1]` of
        # `dots = LinearPattern(c, ...)`): that original, which is also `dots[0]`
        self.pattern_original = pattern_original

    @property
    def label(self) -> str:
        return f"{self.owner.path}.{self.name}" if self.name else f"{self.kind} in {self.owner.path}"


class Equation(Record):
    """``expr == 0`` (``ineq=False``) or ``expr >= 0`` (``ineq=True``)."""
    __slots__ = ("expr", "ineq", "branch")

    def __init__(self, expr: Expr, ineq: bool = False, branch: Expr | None = None):
        self.expr = expr
        self.ineq = ineq
        # convention-dependent constraints: an expression that is > 0 on the branch chosen at the
        # start; the solve warns (W0403) when it ends <= 0 (the part flipped to another branch)
        self.branch = branch


def equation(expr: Expr, ineq: bool = False, branch: Expr | None = None) -> Equation:
    """``Equation(expr, ineq, branch)`` without the class call (the same record; the
    interpreter makes thousands, and a class call re-enters the bytecode loop)."""
    e = _new(Equation)
    e.expr = expr
    e.ineq = ineq
    e.branch = branch
    return e


class Constraint(Record):
    """A constraint as written in the source and the equations it adds."""
    # ``text`` is a property (below): a written constraint's text is cut from ``_src``
    __slots__ = ("kind", "owner", "span", "equations", "deferred", "text", "implicit", "hold",
                 "released", "args", "reach")

    def __init__(self, kind: str, owner: Structure, span: Span | None,
                 equations: list[Equation] | None = None, deferred: list[Equation] | None = None,
                 text: str = "", implicit: bool = False, hold: bool = False,
                 released: bool = False):
        self.kind = kind  # canonical constraint name or "equation" / "internal"
        self.owner = owner
        self.span = span
        self.equations = [] if equations is None else equations
        # equations holding bounding-box terms, expanded just before solving (aidl_lang.bbox)
        self.deferred = deferred
        self.text = text
        self.implicit = implicit  # created by a constructor, not written by the user
        # a hold (a Drawing2D's placement at its `at`): its rows are kept only along what the
        # other constraints leave free (aidl_lang.solver.core.holds.settle_holds)
        self.hold = hold
        self.released = released  # a hold given up after a failed solve (settle_holds)
        # the structures each argument reaches, in the order written (a written constraint
        # relating more than one structure; else None): the first-named moves to the later
        # ones (aidl_lang.solver.core.hierarchy, "who moves")
        self.args = None
        # the parameters each argument reads, in the order written (a written constraint
        # relating two or more shapes of its own structure; else None): between shapes too,
        # the first-named moves to the later ones (aidl_lang.solver.core.tree._shape_ranks)
        self.reach = None
        # (``arg_reach``, set only on a constraint relating structures, one of them its own
        # structure with construction geometry: the parameters each argument reads, so a
        # helper named after another structure's shape is held while that moves,
        # aidl_lang.solver.core.tree._held_helpers)

    def describe(self) -> str:
        return self.text or self.kind


def _constraint_text(c: Constraint) -> str:
    t = c._text
    if t is None:          # a written constraint: its source text, made on first use
        sp = c.span
        t = c._text = " ".join(c._src[sp.start:sp.end].split())[:120]
    return t


def _set_constraint_text(c: Constraint, value: str) -> None:
    c._text = value


# ``text``: what the constraint is called in messages.  The interpreter gives a written
# constraint its file's text (``_src``) and ``_text = None``; the text (its source, blanks
# collapsed, at most 120 characters) is cut only when a message asks for it.
Constraint.text = property(_constraint_text, _set_constraint_text)


class Assertion(Record):
    """An ``assert`` statement whose condition depends on solved values: ``groups`` are its
    alternatives (the condition's disjunctive normal form: `a and b or c` is ``[[a, b],
    [c]]``), each a list of sides ``(op, left, right, dim)`` (``op`` one of ``==`` ``!=``
    ``<=`` ``<`` ``>=`` ``>``; ``left``, ``right`` expressions in mm or radians, box terms
    allowed; ``dim`` the values' dimension); it holds at the solution when every side of
    some group does.  ``text``: the condition as written; ``message``: the user's reason, or
    None; ``unit``/``scale``: the file's length unit for messages; ``reads``: ``(text,
    expression, dim)`` of each name and member the condition reads (issue 111: the message
    gives their values, `ring.bb.width = 155 mm`)."""
    __slots__ = ("span", "text", "message", "owner", "groups", "unit", "scale", "reads")

    def __init__(self, span: Span | None, text: str, message: str | None, owner: Structure,
                 groups: list | None = None, unit: str = "mm", scale: float = 1.0):
        self.span = span
        self.text = text
        self.message = message
        self.owner = owner
        self.groups = [] if groups is None else groups
        self.unit = unit
        self.scale = scale
        self.reads: list = []
