"""Runtime values of the interpreter and their unit arithmetic.

A scalar is a :class:`Q`: an expression over the parameter vector (mm / radians) with a
dimension ``(L, A)`` — length exponent and angle exponent.  ``(0, 0)`` is a bare number: it takes
the file's length unit where a length is expected and degrees where an angle is expected,
except a :class:`Radians` (``pi``, ``tau`` and numbers made from them), which is radians there.
Points are :class:`PV` (x, y expressions in the frame of the structure being evaluated).
Every value records the structures whose geometry it references (``owners``) so that the
validity rules can be checked where the value is used.
"""
from __future__ import annotations

from ...base.records import Record
from .expr import Expr, _lin, as_const, lift
from .model import Geometry, Point, Structure

NUM = (0, 0)
LEN = (1, 0)
ANG = (0, 1)

_EMPTY: frozenset = frozenset()


class UnitError(Exception):
    pass


class Q(Record):
    """A quantity: an expression with its dimension (length, angle, number) and the structures it reads."""
    __slots__ = ("expr", "dim", "owners")

    def __init__(self, expr: Expr, dim: tuple = NUM, owners: frozenset = _EMPTY):
        self.expr = expr
        self.dim = dim
        self.owners = owners

    @staticmethod
    def num(v: float, dim=NUM) -> "Q":
        return Q(_lin({}, float(v)), dim)

    def const(self) -> float | None:
        return as_const(self.expr)


class Radians(Q):
    """A value that carries radians as a unit of its own: ``pi`` and ``tau`` (``power`` 1),
    and what arithmetic makes of them, the power of the radian counted as any unit's is:
    ``2 * pi / n``, ``-pi``, ``tau - 0.1`` (a plain number next to radians is radians, as
    in ``sin``), ``pi * module / pitch_r`` (an arc length over a radius) have power 1;
    ``pi * pi`` 2, ``1 / pi`` -1, ``pi / pi`` 0 (a plain number again).  In arithmetic it is
    the number it is (3.14159...); a bare number of power 1 that meets an angle (``+``,
    ``-``, comparisons, ``min``/``max``, ``atan2``, an angle argument) is that many radians,
    not degrees: ``theta + pi / 2`` is ``theta + 90 deg`` (issue 84: ``tau - 2 * theta`` read
    tau as 6.28 deg).  ``dim`` is its dimension as for any :class:`Q`; ``power`` is kept in
    the instance's ``__dict__`` (1 unless set)."""
    __slots__ = ()
    power = 1


def radians_of(q: "Q", power: int = 1) -> "Q":
    """``q`` (same expression, dimension and owners) carrying radians to ``power``: a
    :class:`Radians`, or a plain :class:`Q` for power 0."""
    if not power:
        return q if type(q) is Q else Q(q.expr, q.dim, q.owners)
    r = Radians(q.expr, q.dim, q.owners)
    if power != 1:
        r.power = power
    return r


def rad_power(q) -> int:
    """The power of the radian ``q`` carries: ``q.power`` for a :class:`Radians`, else 0."""
    return q.power if type(q) is Radians else 0


def angle_scale(q, deg: float) -> float:
    """The factor that makes the bare number ``q`` an angle in radians: 1 for a number of
    radians (a :class:`Radians` of power 1: ``pi``, ``tau / 8``), ``deg`` (pi / 180) for
    any other bare number."""
    return 1.0 if type(q) is Radians and q.power == 1 else deg


class PV(Record):
    """A point value: coordinates in the current structure's frame; ``obj`` if it is a point."""
    __slots__ = ("x", "y", "obj", "owners")

    def __init__(self, x: Expr, y: Expr, obj: Point | None = None, owners: frozenset = _EMPTY):
        self.x = x
        self.y = y
        self.obj = obj
        self.owners = owners


class GeomRef(Record):
    """A value naming a primitive."""
    __slots__ = ("geom",)

    def __init__(self, geom: Geometry):
        self.geom = geom

    @property
    def owners(self):
        return self.geom.owner.owner_set()


class StructRef(Record):
    """A value naming a structure."""
    __slots__ = ("struct",)

    def __init__(self, struct: Structure):
        self.struct = struct

    @property
    def owners(self):
        return self.struct.owner_set()


class BBoxRef(Record):
    """``x.bbox``: the bounding box of a structure or primitive, its terms expanded before solving."""
    __slots__ = ("target",)

    def __init__(self, target: object):
        self.target = target  # Structure | Geometry

    @property
    def owners(self):
        t = self.target
        return (t if isinstance(t, Structure) else t.owner).owner_set()


class Function(Record):
    """A ``def name(params) = expr`` function with the scope it was defined in."""
    __slots__ = ("node", "scope")

    def __init__(self, node: object, scope: object):
        self.node = node  # ast.Func
        self.scope = scope  # the defining file's scope


class Template(Record):
    """A ``def`` template with the scope it was defined in."""
    __slots__ = ("node", "scope", "file_units")

    def __init__(self, node: object, scope: object, file_units: float = 1.0):
        self.node = node  # ast.Def
        self.scope = scope  # the defining file's scope
        self.file_units = file_units


class Builtin(Record):
    """A registry builtin (primitive, constraint, function) used as a value."""
    __slots__ = ("name",)

    def __init__(self, name: str):
        self.name = name  # registry entry or function name


class Namespace(Record):
    """An imported file's scope, named by its ``as`` alias."""
    __slots__ = ("name", "scope")

    def __init__(self, name: str, scope: object):
        self.name = name
        self.scope = scope


def dim_name(d: tuple) -> str:
    if d == NUM:
        return "number"
    if d == LEN:
        return "length"
    if d == ANG:
        return "angle"
    if d == (2, 0):
        return "area"
    parts = []
    if d[0]:
        parts.append("length" + (f"^{d[0]}" if d[0] != 1 else ""))
    if d[1]:
        parts.append("angle" + (f"^{d[1]}" if d[1] != 1 else ""))
    return "·".join(parts)


def type_name(v) -> str:
    if isinstance(v, Q):
        return dim_name(v.dim)
    if isinstance(v, PV):
        return "point"
    if isinstance(v, GeomRef):
        return v.geom.kind
    if isinstance(v, StructRef):
        return f"{v.struct.kind} structure"
    if isinstance(v, BBoxRef):
        return "bounding box"
    if isinstance(v, bool):
        return "boolean"
    if isinstance(v, str):
        return "string"
    if isinstance(v, (list, tuple)):
        return "list"
    if isinstance(v, Template):
        return "template"
    if isinstance(v, Builtin):
        return "function"
    if v is None:
        return "nothing"
    return type(v).__name__


def owners_of(*vals) -> frozenset:
    """The structures whose geometry ``vals`` refer to (lists and tuples looked into)."""
    return owners_in(vals)


def owners_in(vals) -> frozenset:
    """:func:`owners_of` of the values in the iterable ``vals`` (``owners_in(d.values())``
    without unpacking them into a call, which re-enters the bytecode loop)."""
    out = set()
    for v in vals:
        t = type(v)
        if t is Q or t is PV:
            o = v.owners
        elif t is GeomRef:
            out.add(v.geom.owner)
            continue
        elif t is StructRef:
            out.add(v.struct)
            continue
        else:
            o = getattr(v, "owners", None)
        if o:
            out |= o
        elif isinstance(v, (list, tuple)):
            out |= owners_of(*v)
    return frozenset(out)


def unify_add(a: Q, b: Q, scale: float, deg: float) -> tuple[Expr, Expr, tuple]:
    """Bring two operands of + - or a comparison to one dimension (bare numbers adapt: to a
    length in the file's unit ``scale``, to an angle in degrees ``deg``, or in radians for a
    :class:`Radians`).  Raises :class:`UnitError` for two different dimensions."""
    if a.dim == b.dim:
        return a.expr, b.expr, a.dim
    if a.dim == NUM:
        return lift(a.expr) * _coef(b.dim, scale, angle_scale(a, deg)), b.expr, b.dim
    if b.dim == NUM:
        return a.expr, lift(b.expr) * _coef(a.dim, scale, angle_scale(b, deg)), a.dim
    an = {n: ("an " if n[:1] in "aeiou" else "a ") + n for n in (dim_name(a.dim), dim_name(b.dim))}
    raise UnitError(f"cannot combine {an[dim_name(a.dim)]} with {an[dim_name(b.dim)]}")


def _coef(dim: tuple, scale: float, deg: float) -> float:
    if dim == LEN:
        return scale
    if dim == ANG:
        return deg
    if dim[1] == 0 and dim[0] > 0:
        return scale ** dim[0]
    raise UnitError(f"a bare number cannot stand for a {dim_name(dim)}; give it a unit")


def mul_dim(a: tuple, b: tuple, sign: int = 1) -> tuple:
    d = (a[0] + sign * b[0], a[1] + sign * b[1])
    if d[0] != 0 and d[1] != 0:        # radians are dimensionless next to a length (arc length)
        d = (d[0], 0)
    return d
