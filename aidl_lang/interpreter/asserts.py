"""``assert`` statements (docs/language.md, "assert"): the condition's alternatives (``and``
binds tighter than ``or``; ``!=`` allowed: a check, not a constraint), judged at once on what
is known before solving (params, constants), the rest kept on the model and checked after
solving (:mod:`aidl_lang.geometry.relations.assertions`, E0405).  A mixin of the
interpreter (:class:`aidl_lang.interp.Interpreter`): it reads ``eval``, ``_compare_eqs``,
``_sides_of`` and ``_unify`` of :class:`.statements.Statements`."""
from __future__ import annotations

from .. import ast as A
from ..base.diagnostics import EvalError
from ..geometry.core.values import GeomRef, Q
from .common import _const, _value


class Asserts:
    """The ``assert`` statement of :class:`aidl_lang.interp.Interpreter`."""

    def _assert(self, st) -> None:
        """``assert cond[, "message"]``: comparisons joined by ``and`` and ``or`` (``!=``
        allowed: a check, not a constraint).  Alternatives known now (params, constants)
        are judged at once; the rest are kept on the model
        (:class:`~aidl_lang.geometry.core.model.Assertion`) and checked after solving (E0405)."""
        self.in_assert = True           # (`distance` of shapes: measured at the solution)
        try:
            groups = self._assert_groups(st.expr)
        finally:
            self.in_assert = False
        a = self._assertion(st, self.struct)
        a.reads = self._assert_reads(st.expr)
        verdict, a.groups, known = judge_known(groups)
        if verdict is False:
            # reported now, and the program goes on: every false assert is reported, those
            # checked after solving too (the pipeline solves when E0405 is the only error)
            from ..geometry.relations.assertions import describe
            self.sink.error("E0405", describe(a, known, len(groups)), st.span,
                            hint=ASSERT_HINT)
        elif verdict is None:
            self.model.assertions.append(a)

    def _assert_groups(self, e) -> list:
        """The alternatives of an assert's condition (its disjunctive normal form: ``a and
        (b or c)`` is ``[[a, b], [a, c]]``), each a list of sides ``(op, left, right,
        dim)``; at most :data:`MAX_ALTERNATIVES` (E0108 past it)."""
        if isinstance(e, A.BoolOp):
            left, right = self._assert_groups(e.left), self._assert_groups(e.right)
            out = left + right if e.op == "or" else [x + y for x in left for y in right]
            if len(out) > MAX_ALTERNATIVES:
                raise EvalError("E0108", f"the condition of this `assert` has {len(out)} "
                                f"alternatives (at most {MAX_ALTERNATIVES})", e.span,
                                hint="split it into several asserts")
            return out
        if not isinstance(e, A.Compare):
            raise EvalError("E0108", "`assert` takes comparisons (`a <= b`), joined by `and` "
                            "or `or`", e.span, hint="write e.g. `assert plate.body.width <= "
                                                    "300 mm`")
        vals = [self.eval(x) for x in e.operands]
        sides: list = []
        for op, (l, r) in zip(e.ops, zip(vals, vals[1:])):
            self._pair_sides(op, l, r, e.span, sides)
        return [sides]

    def _pair_sides(self, op, l, r, span, sides: list) -> None:
        """The sides ``(op, left, right, dim)`` of one comparison ``l op r``, appended to
        ``sides``; two lists compare with ``==`` item by item (run bu: `assert [a.d, b.d,
        c.d] == [20 mm, 25 mm, 30 mm]` was E0108 "cannot constrain a list == a list"), their
        lengths first."""
        if isinstance(l, (list, tuple)) and isinstance(r, (list, tuple)) and not (
                (isinstance(l, tuple) or isinstance(r, tuple))   # `(x, y)`: a point
                and len(l) == len(r) == 2 and all(isinstance(v, Q) for v in (*l, *r))):
            if op != "==":
                raise EvalError("E0108", f"two lists compare with `==` (item by item), not "
                                f"`{op}`", span, hint="compare their items: `a[0] " + op
                                + " b[0]`, or each in a loop of asserts")
            if len(l) != len(r):
                sides.append(("==", f"a list of {len(l)}", f"a list of {len(r)}", "text"))
                return
            for a, b in zip(l, r):
                self._pair_sides(op, a, b, span, sides)
            return
        if isinstance(l, (str, bool)) and isinstance(r, (str, bool)) \
                and type(l) is type(r):          # `assert f"{d:.1f}" == "1.0"`
            if op not in ("==", "!="):
                raise EvalError("E0108", f"{'strings' if isinstance(l, str) else 'true and false'}"
                                f" compare with `==` and `!=`, not `{op}`", span)
            sides.append((op, l, r, "text"))
            return
        if op == "!=" and isinstance(l, Q) and isinstance(r, Q):
            le, re_, dim = self._unify(l, r, span)
            sides.append(("!=", le, re_, dim))
            return
        for eq in self._compare_eqs(op, l, r, span):
            # each equation is `left - right` (== 0 or >= 0); keep the two sides apart
            sides.append(self._sides_of(op, l, r, span, eq))

    def _assert_reads(self, e) -> list:
        """``(text, expression, dim)`` of each name and member chain inside a side of the
        condition ``e`` (``ring.bb.width``, ``wall`` of ``abs(ring.bb.width - 2 * wall) <
        1 mm``; at most :data:`MAX_READS`, each once), for E0405's message: the values a
        model would otherwise work out by hand (issue 111).  A side that is itself a chain
        is said as the side; a chain whose value is not a number, length or angle is left
        out."""
        from .common import _src
        out: list = []
        seen: set = set()
        todo = [e]
        while todo and len(out) < MAX_READS:
            n = todo.pop()
            if isinstance(n, (A.Name, A.Member)) and _chain(n):
                text = _src(self.sink, n.span)
                if text and text not in seen:
                    seen.add(text)
                    try:
                        v = self.eval(n)
                    except EvalError:
                        continue
                    if isinstance(v, Q):
                        out.append((text, v.expr, v.dim))
                        spine = _slot_spine(self, n)
                        if spine is not None:       # run ci: a Slot's length is end to end
                            out.append((_src(self.sink, n.obj.span), spine, "slot"))
                    elif isinstance(v, list) and v and all(isinstance(i, list) for i in v):
                        # a nested loop's names (run aq: `len(crumbs.c) == 9` for 3 x 3
                        # holes was 3): the rows, not every copy; every level of them (run
                        # dw: 5 x 2 x 2 windows said "5 lists of 2 each", its sum 10)
                        out.append((text, _nested_said(v, text), "said"))
                continue
            if isinstance(n, A.Call):
                todo += reversed(list(n.args) + [k.value for k in n.kwargs])
                continue
            if isinstance(n, A.Compare):    # a side that is a name is said as the side
                todo += reversed([x for x in n.operands if not _chain(x)])
                for x in n.operands:
                    spine = _slot_spine(self, x) if _chain(x) else None
                    if spine is not None:   # run ci: a Slot's length is end to end
                        out.append((_src(self.sink, x.obj.span), spine, "slot"))
                continue
            todo += reversed([c for c in _children(n)])
        return out

    def _assertion(self, st, owner):
        """The :class:`~aidl_lang.geometry.core.model.Assertion` of statement ``st`` (its text,
        reason and the file's length unit for messages), without its alternatives yet."""
        from ..geometry.core.model import Assertion
        from .common import _src
        scale = self.unit_scale
        unit = {1.0: "mm", 10.0: "cm", 1000.0: "m", 25.4: "in", 304.8: "ft"}.get(scale, "mm")
        return Assertion(st.span, _src(self.sink, st.expr.span) or "condition", st.message,
                         owner, [], unit, scale)


# the alternatives an `assert` may have (its condition in disjunctive normal form)
MAX_ALTERNATIVES = 64
# the names and members whose values a failed assert's message gives
MAX_READS = 6


def _chain(n) -> bool:
    """Whether ``n`` is a name or a chain of members of one (``ring.bb.width``)."""
    while isinstance(n, A.Member):
        n = n.obj
    return isinstance(n, A.Name)


def _children(n) -> list:
    """The expression nodes directly under ``n``."""
    out = []
    for slot in getattr(type(n), "__slots__", ()):
        v = getattr(n, slot, None)
        if isinstance(v, A.Node):
            out.append(v)
        elif isinstance(v, list):
            out += [x for x in v if isinstance(x, A.Node)]
    return out


def judge_known(groups: list) -> tuple:
    """An assert's alternatives judged on what is known before solving: ``(True, [], [])``
    when one holds on params and constants alone, ``(False, [], found)`` when each fails on
    one of those (``found``: the false sides' ``(op, left, right, dim)``), else ``(None,
    left, [])``: the alternatives left to judge after solving, their known sides (all
    true) dropped."""
    from ..geometry.relations.assertions import holds
    left: list = []
    known: list = []
    for group in groups:
        later, wrong = [], []
        for side in group:
            op, l, r, dim = side
            if dim == "text":               # two strings (or truth values): known now
                if (l == r) != (op == "=="):
                    wrong.append(side)
            elif _const(l) and _const(r):
                if not holds(op, _value(l), _value(r), "right"):
                    wrong.append((op, _value(l), _value(r), dim))
            else:
                later.append(side)
        if wrong:
            known += wrong
        elif not later:
            return True, [], []
        else:
            left.append(later)
    if not left:
        return False, [], known
    return None, left, []


def _slot_spine(interp, n):
    """The centre-to-centre length (an expression, mm) of the Slot whose ``.length`` chain
    ``n`` reads, else None (issue 111, run ci: a hook's shank asserted 34.5 mm centre to centre
    read 39.5 mm, a Slot's length being end to end)."""
    if not (isinstance(n, A.Member) and n.name == "length"):
        return None
    try:
        g = interp.eval(n.obj)
    except EvalError:
        return None
    if not (isinstance(g, GeomRef) and g.geom.kind == "Slot"):
        return None
    spine = interp.eval(A.Member(n.span, A.Member(n.span, n.obj, "spine", n.name_span),
                                 "length", n.name_span))
    return spine.expr if isinstance(spine, Q) else None


# E0405's hint, here and in the pipeline; the assert may be the slip (run hk: a list read flat)
ASSERT_HINT = ("an `assert` states what must be true of the design: change the values or "
               "constraints so that it holds, or the assert where it reads the wrong thing or "
               "its own arithmetic is off (it is not a constraint: the solver does not try to "
               "satisfy it)")


def _nested_said(v: list, text: str) -> str:
    """How E0405 says a list of lists ``v`` (written ``text``): its sizes level by level, its
    items in all, the index to write and the expression that counts every item
    (``sum([sum([len(r2) for r2 in r1]) for r1 in X])`` three deep)."""
    depth, level, sizes = 0, [v], []
    while level and all(isinstance(i, list) for i in level):
        got = sorted({len(i) for i in level})
        sizes.append(f"{got[0]}" if len(got) == 1 else f"{got[0]} to {got[-1]}")
        depth += 1
        level = [j for i in level for j in i]
    if depth == 2:                      # (the wording of round ten's run aq)
        got = sorted({len(i) for i in v})
        each = f" of {got[0]} each" if len(got) == 1 else f" of {got[0]} to {got[-1]}"
        return (f"a list of {len(v)} lists{each} (`{text}[i][j]`; every item: "
                f"`sum([len(r) for r in {text}])`)")
    index = "".join(f"[{c}]" for c in "ijklmn"[:depth])
    expr = f"len(r{depth - 1})"
    for k in range(depth - 1, 1, -1):
        expr = f"sum([{expr} for r{k} in r{k - 1}])"
    expr = f"sum([{expr} for r1 in {text}])"
    return (f"a list of lists, {' x '.join(sizes)} ({len(level)} items in all: "
            f"`{text}{index}`; every item: `{expr}`)")
