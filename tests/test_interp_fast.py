"""The interpreter's fast paths (docs/dev/performance.md, "The interpreter") give exactly what the
general paths give.

* ``sub``, ``mul``, ``add``, ``func`` and ``contains_bbox`` against the code they replaced
  (kept here as the reference), with hypothesis; the records made without a class call
  (``model.equation``) and the constraint builders' shortcuts for a line's own points
  (``Horizontal``, ``Vertical``, ``Length``) against the general construction.
"""
import pytest
from hypothesis import given, settings, strategies as st

from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.geometry.relations.bbox import BBTerm, contains_bbox
from aidl_lang.geometry.relations import constraints as C
from aidl_lang.geometry.core.expr import Lin, Nl, add, func, hypot, mul, sub
from aidl_lang.geometry.core.model import Equation, equation
from aidl_lang.geometry.core.values import GeomRef, LEN, Q, owners_in, owners_of
from aidl_lang.interp import Interpreter
from aidl_lang.parser import parse
from aidl_lang.typecheck import check

from conftest import EXAMPLES, ROOT

PROGRAMS = EXAMPLES + sorted((ROOT / "tests" / "programs").glob("*.aidl"))


def _snippet_program(line: str) -> str:
    return ("units mm\nassembly top {\n    solid outer {\n        p = Point(1, 2)\n"
            "        l = Line((0, 0), (10, 1))\n        r = Rectangle(center=(5, 5), width=10, "
            "height=10)\n    }\n    solid inner {\n        k = Circle(center=(3, 3), radius=1)\n"
            "    }\n    " + line + "\n}\n")


def _key(e):
    """An expression as nested tuples, floats by their bits (``float.hex``)."""
    if isinstance(e, Lin):
        return ("L", tuple((k, float(v).hex()) for k, v in e.terms.items()), float(e.const).hex())
    if isinstance(e, Nl):
        return (e.op,) + tuple(_key(a) for a in e.args)
    if isinstance(e, BBTerm):
        t, f = e.target, e.frame
        return ("bb", getattr(t, "path", None) or getattr(t, "label", None), e.side,
                getattr(f, "path", None))
    if isinstance(e, float):
        return e.hex()
    return repr(e)


def test_a_wrong_box_argument_is_a_located_error(compile_text):
    """`Below("oops", ...)` was an internal error (a NameError in the message)."""
    c = compile_text(_snippet_program('Below("oops", inner, outer)'), do_solve=False)
    errs = [d for d in c.sink.items if d.is_error]
    assert [d.code for d in errs] == ["E0108"]
    assert "argument `a` of `Below` must be a structure or geometry, got string" in errs[0].message
    assert (errs[0].span.line, errs[0].span.col) == (11, 11)


# ---------------------------------------------------------------- expression arithmetic
def _mul_reference(a, b):
    """``mul`` before the interpreter work (dict comprehensions, isinstance)."""
    if not isinstance(a, (Lin, Nl, BBTerm)):
        a = Lin({}, float(a))
    if not isinstance(b, (Lin, Nl, BBTerm)):
        b = Lin({}, float(b))
    la, lb = isinstance(a, Lin), isinstance(b, Lin)
    ca = a.const if la and not a.terms else None
    cb = b.const if lb and not b.terms else None
    if ca is not None and lb:
        return Lin({k: v * ca for k, v in b.terms.items()}, b.const * ca)
    if cb is not None and la:
        return Lin({k: v * cb for k, v in a.terms.items()}, a.const * cb)
    if ca == 0.0 or cb == 0.0:
        return Lin({}, 0.0)
    return Nl("mul", (a, b))


def _contains_reference(e):
    if isinstance(e, BBTerm):
        return True
    if isinstance(e, Nl):
        return any(_contains_reference(a) for a in e.args)
    return False


floats = st.one_of(st.floats(allow_nan=False, width=64), st.sampled_from([0.0, -0.0, 1.0, -1.0]))
lins = st.builds(lambda t, c: Lin(dict(t), c),
                 st.lists(st.tuples(st.integers(0, 6), floats), max_size=4), floats)
leaves = st.one_of(lins, st.builds(lambda s: BBTerm(None, s, None), st.sampled_from(["left", "top"])))
exprs = st.recursive(leaves, lambda kids: st.builds(lambda op, a, b: Nl(op, (a, b)),
                                                    st.sampled_from(["mul", "add", "min"]), kids, kids),
                     max_leaves=8)
operands = st.one_of(exprs, floats)


@settings(max_examples=150, deadline=None)
@given(exprs, operands)
def test_sub_is_add_of_the_negation(a, b):
    assert _key(sub(a, b)) == _key(add(a, _mul_reference(-1.0, b)))
    assert _key(a - b) == _key(add(a, _mul_reference(-1.0, b)))


@settings(max_examples=150, deadline=None)
@given(operands, operands)
def test_mul_is_the_reference(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return                                  # two plain numbers are never an expression
    assert _key(mul(a, b)) == _key(_mul_reference(a, b))


@settings(max_examples=150, deadline=None)
@given(exprs)
def test_contains_bbox_is_the_reference(e):
    assert contains_bbox(e) is _contains_reference(e)


def _add_reference(a, b):
    """``add`` before the interpreter work (isinstance, constructors)."""
    if not isinstance(a, (Lin, Nl, BBTerm)):
        a = Lin({}, float(a))
    if not isinstance(b, (Lin, Nl, BBTerm)):
        b = Lin({}, float(b))
    if isinstance(a, Lin) and isinstance(b, Lin):
        t = dict(a.terms)
        for k, v in b.terms.items():
            t[k] = t.get(k, 0.0) + v
        return Lin(t, a.const + b.const)
    return Nl("add", (a, b))


def _func_reference(op, *args):
    """``func`` before the interpreter work: lift every argument, fold constants."""
    args = tuple(a if isinstance(a, (Lin, Nl, BBTerm)) else Lin({}, float(a)) for a in args)
    consts = [a.const if isinstance(a, Lin) and not a.terms else None for a in args]
    if None not in consts:
        import math
        f = {"sqrt": math.sqrt, "abs": abs, "min": min, "max": max}[op]
        return Lin({}, f(consts) if op in ("min", "max") else f(consts[0]))
    return Nl(op, args)


@settings(max_examples=150, deadline=None)
@given(operands, operands)
def test_add_is_the_reference(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return
    assert _key(add(a, b)) == _key(_add_reference(a, b))


@settings(max_examples=150, deadline=None)
@given(st.sampled_from(["min", "max", "abs"]), st.lists(operands, min_size=1, max_size=3))
def test_func_is_the_reference(op, args):
    if op == "abs":
        args = args[:1]
    assert _key(func(op, *args)) == _key(_func_reference(op, *args))


def test_equation_is_the_record():
    e = Lin({3: 1.0}, 2.0)
    for args in ((e,), (e, True), (e, False, Lin({1: 1.0}))):
        a, b = Equation(*args), equation(*args)
        assert type(a) is type(b) and repr(a) == repr(b) and vars(a) == vars(b)


def test_owners_in_is_owners_of(compile_text):
    m = compile_text(_snippet_program("AlignLeft(inner, outer)")).model
    outer, inner = (s for s in m.structures if s.name in ("outer", "inner"))
    vals = [GeomRef(outer.geometry[0]), Q(Lin({}, 1.0), LEN), [GeomRef(inner.geometry[0])], None]
    assert owners_in(vals) == owners_of(*vals) == frozenset({outer, inner})


class _Ctx:
    """What the builders use of the interpreter: the structure being run and the values."""

    def __init__(self, model, struct):
        self.model, self.struct = model, struct

    def value_of(self, e):
        return Interpreter.value_of(self, e)


@pytest.mark.parametrize("same_point", [False, True])
def test_line_builders_equal_the_general_construction(compile_text, same_point):
    """Horizontal, Vertical and Length of a line of the structure being run build their
    expressions straight from the point indices; the general path goes through the end points'
    values (``_line``) and the operators.  Also for a line whose ends share a parameter."""
    m = compile_text(_snippet_program("Horizontal(outer.l)")).model
    outer = next(s for s in m.structures if s.name == "outer")
    line = next(g for g in outer.geometry if g.kind == "Line")
    if same_point:                      # a degenerate line: both ends the same point
        line.points["end"] = line.points["start"]
    ctx, ref = _Ctx(m, outer), GeomRef(line)
    s, e = C._line(ctx, ref, "a")
    assert _key(C.horizontal(ctx, ref)[0].expr) == _key(s.y - e.y)
    assert _key(C.vertical(ctx, ref)[0].expr) == _key(s.x - e.x)
    L = Q(Lin({}, 7.0), LEN)
    if same_point:
        with pytest.raises(C.ConstraintError, match="zero length"):
            C.length(ctx, ref, L)
    else:
        assert _key(C.length(ctx, ref, L)[0].expr) == _key(hypot(e.x - s.x, e.y - s.y) - L.expr)


@pytest.mark.parametrize("path", PROGRAMS, ids=lambda p: p.name)
def test_constraint_text_is_the_source(path):
    """A written constraint's text is cut from its file when first read: the call's source,
    blanks collapsed, as ``_src`` gives it."""
    from aidl_lang.interpreter.common import _src
    sink = DiagnosticSink()
    prog = parse(path.read_text(), str(path), sink)
    check(prog, sink)
    model = Interpreter(sink).run(prog)
    written = [c for c in model.constraints if not c.implicit]
    for c in written:
        assert c.text == _src(sink, c.span) and c.describe() == (c.text or c.kind)


# ---------------------------------------------------------------- issue 38: the slider move
_finite = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e12, max_value=1e12)


@settings(max_examples=300, deadline=None)
@given(_finite, _finite, st.sampled_from(["*", "/"]),
       st.sampled_from([(0, 0), (1, 0), (0, 1)]), st.sampled_from([(0, 0), (1, 0), (0, 1)]))
def test_two_constants_fold_as_mul_and_div_do(a, b, op, da, db):
    """``_q_op``'s two-constant shortcut gives the bits ``mul`` / ``div`` give (``a / b`` is
    ``a * (1 / b)`` there, not a correctly rounded quotient), its dimension and owners."""
    from aidl_lang import ast as A
    from aidl_lang.base.diagnostics import Span
    from aidl_lang.geometry.core.expr import div
    from aidl_lang.geometry.core.values import mul_dim
    if op == "/" and b == 0.0:
        b = 1.0
    it = Interpreter(DiagnosticSink(), {})
    sp = Span("t", 1, 1, 1, 2)
    node = A.BinOp(op=op, left=A.Num(value=a, unit=None, span=sp),
                   right=A.Num(value=b, unit=None, span=sp), span=sp)
    got = it._q_op(op, Q(Lin({}, a), da), Q(Lin({}, b), db), node)
    want = mul(Lin({}, a), Lin({}, b)) if op == "*" else div(Lin({}, a), Lin({}, b))
    assert _key(got.expr) == _key(want)
    assert got.dim == mul_dim(da, db, 1 if op == "*" else -1)
    assert got.owners == frozenset()


def test_the_circle_runs_sweeps_at_once_equal_each_runs_sweep():
    """``exact._circle_sweeps`` (all runs of a result polygon in one array operation) gives
    each run the very float :func:`exact._sweep_sum` gives it, on the gear pair's outlines
    (about a thousand arcs)."""
    from aidl_lang.output.part.edges import exact as X
    from aidl_lang.pipeline import compile_source
    path = ROOT / "examples" / "gear_pair.aidl"
    c = compile_source(path.read_text(), str(path))
    prov = c.drawing.exact
    checked = 0
    for part in c.drawing.parts:
        for poly in part.shape.to_polygons():
            P = X.np.asarray(poly, dtype=float).reshape(-1, 2)
            scale = max(1.0, float(abs(P).max()))
            runs = X._runs(prov._match(P, scale), prov.carriers, scale)
            if not runs:
                continue
            at_once = X._circle_sweeps(P, runs, prov.carriers)
            for k, f, l in runs:
                if k >= 0 and prov.carriers[k][0] == "C":
                    assert at_once[(f, l)].hex() == X._sweep_sum(P, prov.carriers[k], f, l).hex()
                    checked += 1
    assert checked > 900


@pytest.mark.parametrize("index, code, value", [
    ("2", None, 30.0), ("-1", None, 30.0), ("-3", None, 10.0), ("1 + 0.5 * 2", None, 30.0),
    ("1.5", "E0108", None), ("3", "E0110", None), ("-4", "E0110", None)])
def test_a_list_index_fast_or_not_gives_the_same_item_or_error(compile_text, index, code, value):
    """``_e_Index``'s shortcut (a list, a whole number in range) and the general path agree:
    the item, or the error of a fractional index (E0108) or one out of range (E0110)."""
    c = compile_text("xs = [10, 20, 30]\nsolid s {\n    c = Circle(center=(0, 0), "
                     f"radius=xs[{index}])\n}}\n", do_solve=False)
    errs = [d.code for d in c.sink.items if d.is_error]
    if code is not None:
        assert errs == [code]
        return
    assert errs == []
    g = next(g for s in c.model.structures for g in s.geometry if g.kind == "Circle")
    assert c.model.x[g.scalars["radius"].index] == value


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 50), st.integers(0, 50), st.one_of(_finite, st.just(-0.0)))
def test_an_arc_ends_offset_row_is_the_operators_row(i, j, d):
    """``primitives._offset`` (an ``Arc``'s end from its center, built directly) is the very
    ``Lin`` the operators make of ``var(i) - var(j) - d``: terms in order, floats by bits."""
    from aidl_lang.geometry.core.expr import var
    from aidl_lang.geometry.shapes.primitives import _offset
    if i == j:
        j = i + 1
    assert _key(_offset(i, j, d)) == _key(var(i) - var(j) - d)


small = st.floats(min_value=-1e3, max_value=1e3, allow_nan=False)
small_lins = st.builds(lambda t, c: Lin(dict(t), c),
                       st.lists(st.tuples(st.integers(0, 6), small), max_size=3), small)
terms = st.one_of(small, small_lins,
                  st.builds(lambda a, b: Nl("mul", (a, b)), small_lins, small_lins))


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(small, terms), min_size=1, max_size=5), small,
       st.lists(small, min_size=7, max_size=7))
def test_combine_is_the_sum_of_its_products(pairs, c, x):
    """``combine`` (a copy's point as one affine combination) is ``c + sum(k * e)``: one Lin
    when every term is affine or a number, else the plain sum, each constant counted once."""
    from aidl_lang.geometry.core.expr import combine, evaluate
    got = combine(pairs, c)
    want = c + sum(k * evaluate(e, x) for k, e in pairs)
    assert abs(evaluate(got, x) - want) <= 1e-9 * max(1.0, sum(
        abs(k) * (abs(evaluate(e, x)) + 1.0) for k, e in pairs) + abs(c))
    if all(not isinstance(e, Nl) for _, e in pairs):
        assert isinstance(got, Lin)


frame_lins = st.builds(lambda t: Lin(dict(t), 0.0),          # a point in a frame: no constant
                       st.lists(st.tuples(st.integers(0, 6), small), min_size=1, max_size=3))


@settings(max_examples=200, deadline=None)
@given(frame_lins, frame_lins, small_lins, small_lins, st.floats(-7.0, 7.0))
def test_a_rotated_copys_point_is_the_four_term_combination(px, py, cx, cy, th):
    """``CircularPattern``'s transform makes ``(I - R) c`` once per copy (when no unknown is
    in both of the center's coordinates): each point is then the very Lin of the four-term
    ``combine``, terms in order and floats by bits, so the pinned values do not change."""
    import math
    from aidl_lang.geometry.core.expr import combine
    from aidl_lang.geometry.derived.operations import _rotate
    from aidl_lang.geometry.core.values import PV
    xf, rot, flip = _rotate(PV(cx, cy), th)
    cs, sn = math.cos(th), math.sin(th)
    X, Y = xf(px, py)
    assert _key(X) == _key(combine(((cs, px), (-sn, py), (1.0 - cs, cx), (sn, cy))))
    assert _key(Y) == _key(combine(((sn, px), (cs, py), (-sn, cx), (1.0 - cs, cy))))
    assert (rot, flip) == (th, False)


def _copy_point_reference(turn, model, p, dest, eqs):
    """A copied point as ``_Cloner.point`` made it before ``_Turn.copy_point``: the image's
    expressions, their values, a new point and its two rows by the operators."""
    from aidl_lang.geometry.core.expr import evaluate
    from aidl_lang.geometry.core.model import Point
    X, Y = turn(*p.in_frame(dest))
    ix, iy = model.new_pair(evaluate(X, model.x), evaluate(Y, model.x), True, dest, p.label)
    q = Point(ix, iy, dest, None, p.label)
    qx, qy = q.in_frame(dest)
    eqs += [equation(qx - X), equation(qy - Y)]
    return q


@settings(max_examples=300, deadline=None)
@given(st.integers(0, 6), st.integers(0, 6), small_lins, small_lins, st.floats(-7.0, 7.0),
       st.lists(small, min_size=7, max_size=7))
def test_a_turned_copys_rows_are_the_operators_rows(ix, iy, cx, cy, th, xs):
    """``CircularPattern``'s copied point (``_Turn.copy_point``: its two rows and its start
    value made directly) is the point the image's expressions and the operators make: the
    same new unknowns, start values by bits, rows with their terms in order and floats by
    bits, including a center sharing an unknown with the point (then the general path)."""
    from aidl_lang.geometry.core.model import Model, Point, Structure
    from aidl_lang.geometry.derived.operations import _Turn
    from aidl_lang.geometry.core.values import PV
    if ix == iy:
        iy = (ix + 1) % 7
    made = []
    for make in ("fast", "reference"):
        m = Model()
        S = Structure("s", "solid", None, None)
        for v in xs:
            m.new_param(v, True, S, "u")
        turn, eqs = _Turn(PV(cx, cy), th), []
        p = Point(ix, iy, S, None, "p")
        q = turn.copy_point(m, p, S, eqs) if make == "fast" else None
        if make == "fast":
            shared = q is None
        if q is None:
            q = _copy_point_reference(turn, m, p, S, eqs)
        made.append(((q.ix, q.iy, q.label, q.owner is S), [v.hex() for v in m.x],
                     [(_key(e.expr), e.ineq, e.branch) for e in eqs]))
    assert made[0] == made[1]
    both = set(cx.terms) | set(cy.terms)
    assert shared == bool(set(cx.terms) & set(cy.terms) or {ix, iy} & both)
