"""W0118: a template's ``thickness=`` against the material its parts are cut from.

A template that makes parts (``finger_box``, ``flex_box``, ``finger_panel``: an assembly, or a
solid that is a part) draws its joints, bends and slots for its ``thickness=`` argument, while
its parts are cut from the material in force at the call: the ``thickness`` statement of the
nearest structure around it, else the file's, else 3 mm (what the 3D outputs, the parts list
and the fit check read).  When the two differ the joints are drawn for one material and the
parts made of another; issue 111's run dc called ``flex_box(thickness=3 mm)`` in a file of
``thickness 6 mm`` and got E0108 and five W0517 from inside the template, none naming the
cause.  A joint template (a ``hole`` or ``cut``: ``tab_and_slot``, ``finger_edge``) takes its
partner's thickness and is not judged."""
from __future__ import annotations

from .. import ast as A
from ..base.diagnostics import EvalError
from ..base.limits import MIN_WALL_LEAST, min_wall_problem
from ..geometry.core.values import LEN, NUM, Q

TOLERANCE = 1e-6            # mm


def note_material(child, bound: dict, spans: dict, call_span) -> None:
    """Keep on template instance ``child`` the ``thickness`` it was given (its parameter's
    value in mm, where it is written, and whether the call wrote it), for
    :func:`thickness_mismatch`; nothing when the template has no such parameter."""
    v = bound.get("thickness")
    if isinstance(v, Q) and v.dim == LEN and v.const() is not None:
        child.thickness_arg = (float(v.const()), spans.get("thickness", call_span),
                               "thickness" in spans)


def _material(s, model) -> tuple[float, bool]:
    """The material thickness structure ``s``'s parts are cut from (mm), and whether a
    ``thickness`` statement says it (else the 3 mm default)."""
    for a in (s, *s.ancestors()):
        t = getattr(a, "thickness", None)
        if t is not None:
            return float(t), True
    t = getattr(model, "thickness", None)
    if t is not None:
        return float(t), True
    from ..output.part.build.sunk import DEFAULT_THICKNESS      # what the outputs then use
    return DEFAULT_THICKNESS, False


def _is_part(s) -> bool:
    return s.kind == "solid" and all(a.kind == "assembly" for a in s.ancestors())


def _parts(s) -> list:
    if _is_part(s):
        return [s]
    out, todo = [], list(s.children.values())
    while todo:
        c = todo.pop()
        if _is_part(c):
            out.append(c)
        elif c.kind == "assembly":
            todo.extend(c.children.values())
    return out


def thickness_mismatch(model, sink) -> None:
    """W0118 at each call of a part-making template whose ``thickness`` is not the material
    its parts are cut from (one warning per call written, in a loop too)."""
    seen = set()
    for s in model.structures:
        got = getattr(s, "thickness_arg", None)
        if got is None or s.kind not in ("solid", "assembly") or \
                any(getattr(a, "thickness_arg", None) for a in s.ancestors()):
            continue            # (a template's own panels: judged at the outer call)
        value, span, written = got
        parts = _parts(s)
        if not parts or span in seen:
            continue
        materials = [_material(p, model) for p in parts]
        if any(abs(value - m) <= TOLERANCE for m, _ in materials):
            continue
        seen.add(span)
        material, stated = materials[0]
        name = s.path.split(".", 1)[1] if "." in s.path else s.path
        arg = f"`thickness={value:g} mm`" if written else \
            f"`thickness` ({value:g} mm, its default)"
        why = "the `thickness` in force there" if stated else \
            "no `thickness` statement: the 3 mm default"
        msg = (f"`{name} = {s.template}(...)` draws its joints for {arg}, but its parts are "
               f"cut from {material:g} mm material ({why}): assembled, they do not fit, and "
               f"the 3D outputs, the parts list and the fit check read {material:g} mm")
        if stated:
            leaf = name.split(".")[-1]
            hint = (f"give it `thickness={material:g} mm`, the material; or, for parts of "
                    f"{value:g} mm, put the call in a structure of its own that says "
                    f"`thickness {value:g} mm` (`assembly {leaf}_kit {{ ... }}` holding that "
                    f"line and the call)")
        else:
            hint = f"write `thickness {value:g} mm` at the top of the file: the material"
        sink.warning("W0118", msg, span, hint)


def material_statement(ip, st) -> None:
    """``thickness LENGTH`` (and ``kerf LENGTH``, ``min_wall LENGTH``) run by interpreter
    ``ip``: the model's default (top level) or a structure's own, in mm; ``min_wall`` may be 0
    (its checks off).  E0109 for a value that is no positive length known before solving."""
    word, eg = ("kerf", "kerf 0.15 mm") if isinstance(st, A.KerfDecl) else \
        ("min_wall", "min_wall 0.3 mm") if isinstance(st, A.MinWallDecl) else \
        ("thickness", "thickness 3 mm")
    v = ip.eval(st.value)
    if not isinstance(v, Q) or v.dim not in (LEN, NUM):
        raise EvalError("E0109", f"`{word}` expects a length", st.value.span,
                        hint=f"write it with a unit: `{eg}`")
    val = Q(ip._as_length(v, st.value.span), LEN).const()
    if word in ("min_wall", "kerf") and val is not None and val == 0:
        pass                # `min_wall 0`: the wall checks off; `kerf 0 mm`: not offset
    elif word == "min_wall" and val is not None and min_wall_problem(val) is not None:
        raise EvalError("E0109", f"`min_wall` {min_wall_problem(val)}", st.value.span,
                        hint=f"write `min_wall 0` for no wall checks, or a length from "
                             f"{MIN_WALL_LEAST:g} mm: `{eg}`")
    elif val is None or not val > 0:
        raise EvalError("E0109", f"`{word}` must be a " + (
            "positive length (or 0: no minimum)" if word == "min_wall" else
            "positive length (or 0: not offset)" if word == "kerf" else
            "positive length") + " known before solving", st.value.span,
            hint=f"use a number or a param: `{eg}`")
    setattr(ip.model if ip.struct is None else ip.struct, word, val)
    if word == "min_wall" and ip.struct is not None:
        ip.struct.min_wall_span = st.span      # where it is: W0101 where it does nothing
