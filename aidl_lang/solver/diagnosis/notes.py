"""The notes of E0401's message (a conflict set of constraints): how each member is named
(:func:`member_words`), the instance of a standard-library template its own rows stand for
(:func:`library_instance`), and the hint's notes on shapes held by their literal points, by
the sizes written in their calls, or by ``Rigid``.  Read by :func:`aidl_lang.pipeline.report_failure`."""
from __future__ import annotations

from ...base.diagnostics import in_stdlib


def member_words(c) -> str:
    """How E0401 names conflict member ``c``: its text, its line (or the constructor that
    holds it) and its structure."""
    line = f"line {c.span.line}" if c.span is not None else "no line"
    what = f"held by a constructor ({line})" if c.implicit else line
    return f"`{c.describe()}` ({what}, in `{c.owner.path}`)"


def literal_note(items) -> str:
    """A hint's note on the shapes of a conflict held by their literal coordinates (a
    Triangle, Polygon, Polyline, Spline or Bezier whose points are all numbers): they keep
    their shape unless ``flexible=true`` (issue 73: models did not know Triangle takes it)."""
    kinds = sorted({(c.text or "").split(" shape (literal")[0] for c, _ in items
                    if (c.text or "").endswith("shape (literal coordinates)")})
    if not kinds:
        return ""
    lines = sorted({c.span.line for c, _ in items
                    if (c.text or "").endswith("shape (literal coordinates)") and c.span})
    at = f" (line {', '.join(map(str, lines))})" if lines else ""
    return (f". The {' and '.join(kinds)}{at} keep{'s' if len(lines) < 2 else ''} the shape "
            "its literal coordinates give; if its points should follow the constraints, add "
            "`flexible=true` to its call")


def library_instance(c):
    """The outermost standard-library template instance whose own constraint (or held
    shape) ``c`` is, written in the program; None for a constraint the program states."""
    if c.span is None or not in_stdlib(c.span.file):
        return None
    s, found = c.owner, None
    while s is not None:
        if getattr(s, "template", None) and s.span is not None and not in_stdlib(s.span.file):
            found = s
        s = s.parent
    return found


def sizes_note(items) -> str:
    """A hint's note on the shapes of a conflict held by the sizes written in their calls
    (run aa's cake topper: a rail's placeholder `width=100` between `AlignLeft` and
    `AlignRight` of two stars): a relation does not stretch a size written as a number.  A
    size that reads another structure's box cannot be written into the call (E0201): the
    corners form then (run eh's sign: a backer `letters.bb.width + 60 mm` wide)."""
    lines = sorted({c.span.line for c, _ in items if c.implicit and c.span is not None
                    and (c.text or "").endswith(" shape")})
    if not lines:
        return ""
    at = ", ".join(map(str, lines))
    return (f". The shape{'s' if len(lines) > 1 else ''} on line{'s' if len(lines) > 1 else ''} "
            f"{at} keep{'' if len(lines) > 1 else 's'} the sizes written in "
            f"{'their calls' if len(lines) > 1 else 'its call'} (`width=100`): if the relations should set one, write that size as the "
            "expression it is (`width=b.bb.right - a.bb.left`) or, where it reads another "
            "structure's box, draw the shape by two corners (`Rectangle(corner=(-50, -25), "
            "opposite=(50, 25))`, `RoundedRectangle(corner=..., opposite=..., "
            "corner_radius=6)`): its size is then a guess the relations set")


def rigid_note(s) -> str:
    """A hint's note on the rigid structures (``Rigid(part)``) below ``s``: they were only
    moved, never bent, so a conflict there may ask for a change of shape."""
    rigid, todo = [], list(s.children.values())
    while todo:
        t = todo.pop()
        if getattr(t, "rigid", False):
            rigid.append(t)
        else:
            todo += t.children.values()
    if not rigid:
        return ""
    names = ", ".join(f"`{t.path}`" for t in sorted(rigid, key=lambda t: t.path)[:3])
    return (f". {names} {'is' if len(rigid) == 1 else 'are'} rigid (`Rigid(...)`): moved as "
            "one body, never bent; if the shape must change, drop `Rigid` or constrain inside it")
