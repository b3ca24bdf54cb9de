"""The interpreted model: a tree of structures holding geometry, parameters and constraints.

Every number the solver may change lives in one parameter vector ``Model.x`` (mm, radians);
``Model.free[i]`` says whether parameter ``i`` is an unknown or held (paper: parameter =
⟨value, mutable⟩).  Points are pairs of parameters in their structure's local frame; each
structure has a translation frame (two parameters) relative to its parent; the root's is held.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..diagnostics import Span
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


@dataclass(eq=False)
class Structure:
    """A structure of the model: kind, parent, frame translation parameters, children, geometry."""
    name: str
    kind: str                      # solid | hole | cut | drawing | assembly
    parent: "Structure | None"
    span: Span | None
    fx: int = -1                   # frame translation parameters
    fy: int = -1
    children: dict[str, "Structure"] = field(default_factory=dict)
    geometry: list["Geometry"] = field(default_factory=list)
    constraints: list["Constraint"] = field(default_factory=list)
    scope: dict = field(default_factory=dict)     # names visible as members (s.NAME)
    template: str | None = None
    # a copy made by an operation (Mirrored, a pattern) is held on its parent's frame: where
    # the original's origin went, (x, y) expressions in the model frame (Result.values)
    copy_origin: tuple | None = None
    # the first copy of a pattern whose list starts with its original (`holes[1]` of
    # `holes = LinearPattern(bolt, ...)`): that original, which is also `holes[0]`
    pattern_original: "Structure | None" = None
    # `CutInto(hole, part)`: a hole declared in an assembly cuts the solid `part` (of a
    # template instance, typically) instead of being a part of its own; `cut_by` on the solid
    cuts_into: "Structure | None" = None
    cut_by: list = field(default_factory=list)

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


@dataclass(eq=False)
class Point:
    """A point: the indices of its x and y parameters in the model's parameter vector."""
    ix: int
    iy: int
    owner: Structure
    span: Span | None
    label: str = ""

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


@dataclass(eq=False)
class Scalar:
    """A named scalar parameter of a geometry (radius, width, ...): an index, held or free."""

    index: int
    owner: Structure
    dim: str = "length"            # length | angle | number
    label: str = ""


@dataclass(eq=False)
class Geometry:
    """A primitive (line, circle, ...): its named points and scalar parameters."""
    kind: str                      # Point | Line | Circle | Arc | Rectangle | ...
    owner: Structure
    span: Span | None
    name: str = ""
    points: dict[str, Point] = field(default_factory=dict)
    scalars: dict[str, Scalar] = field(default_factory=dict)
    data: dict = field(default_factory=dict)      # kind-specific: corner radius, text, ...
    parts: dict = field(default_factory=dict)      # sub-geometry (rectangle edges, ...)
    construction: bool = False
    closed: bool = False
    listed: bool = False           # in its owner's ``geometry`` (else a part: an edge, a spine)
    # the first copy of a pattern whose list starts with its original (`dots[1]` of
    # `dots = LinearPattern(c, ...)`): that original, which is also `dots[0]`
    pattern_original: "Geometry | None" = None

    @property
    def label(self) -> str:
        return f"{self.owner.path}.{self.name}" if self.name else f"{self.kind} in {self.owner.path}"


@dataclass(eq=False)
class Equation:
    """``expr == 0`` (``ineq=False``) or ``expr >= 0`` (``ineq=True``)."""

    expr: Expr
    ineq: bool = False
    # convention-dependent constraints: an expression that is > 0 on the branch chosen at the
    # start; the solve warns (W0403) when it ends <= 0 (the part flipped to another branch)
    branch: Expr | None = None


def equation(expr: Expr, ineq: bool = False, branch: Expr | None = None) -> Equation:
    """``Equation(expr, ineq, branch)`` without the class call (the same record; the
    interpreter makes thousands, and a class call re-enters the bytecode loop)."""
    e = _new(Equation)
    e.expr = expr
    e.ineq = ineq
    e.branch = branch
    return e


@dataclass(eq=False)
class Constraint:
    """A constraint as written in the source and the equations it adds."""
    kind: str                      # canonical constraint name or "equation" / "internal"
    owner: Structure
    span: Span | None
    equations: list[Equation] = field(default_factory=list)
    # equations holding bounding-box terms, expanded just before solving (aidl_lang.bbox)
    deferred: list[Equation] | None = None
    text: str = ""
    implicit: bool = False         # created by a constructor, not written by the user
    # a hold (a Drawing2D's placement at its `at`): its rows are kept only along what the
    # other constraints leave free (aidl_lang.solver.holds.settle_holds)
    hold: bool = False
    released: bool = False         # a hold given up after a failed solve (settle_holds)

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


@dataclass(eq=False)
class Assertion:
    """An ``assert`` statement whose condition depends on solved values: each of ``sides`` is
    ``(op, left, right, dim)`` (``op`` one of ``==`` ``<=`` ``<`` ``>=`` ``>``; ``left``,
    ``right`` expressions in mm or radians, box terms allowed; ``dim`` the values' dimension),
    all of which must hold at the solution.  ``text``: the condition as written; ``message``:
    the user's reason, or None; ``unit``/``scale``: the file's length unit for messages."""

    span: Span | None
    text: str
    message: str | None
    owner: Structure
    sides: list = field(default_factory=list)
    unit: str = "mm"
    scale: float = 1.0
