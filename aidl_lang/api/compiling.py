"""The API's entry points: :func:`compile` (a program's text or file in, a
:class:`~.result.Result` out, never an exception for a mistake in the program) and
:func:`set_params` (a program's params given new values in its text, checked first:
:class:`ParamsRefused`).
"""
from __future__ import annotations

import math
import os
import re
from collections.abc import Mapping

from ..base.diagnostics import Diagnostic, DiagnosticSink
from ..base.limits import DEFAULT_BUDGET, Budget
from .result import Result


def compile(source: str | None = None, path: str | os.PathLike | None = None,
            overrides: Mapping[str, str | float] | None = None,
            budget: float | Budget | None = None, min_wall: float | None = None) -> Result:
    """Compile an AIDL program: parse, check, interpret, solve, booleans and the shape checks.

    Give ``source`` (the program text; ``path`` then only names it in diagnostics and is where
    ``import "x.aidl"`` is resolved from) or ``path`` alone (the file is read as UTF-8).
    ``overrides``: param values as ``aidl render --set`` takes them (``{"width": "40 mm"}``,
    numbers are in the file's units).  ``budget``: a factor of the default evaluation budget
    (``aidl --budget K``) or a :class:`~aidl_lang.base.limits.Budget`.  ``min_wall``: the W0507 wall
    thickness in mm (0: off), overriding the program's ``min_wall`` statements (None: theirs,
    else 0.5 mm).

    Never raises for a mistake in the program or an unreadable file (``E0004``): those are
    diagnostics and ``ok`` is False.  Raises :class:`TypeError` when neither ``source`` nor
    ``path`` is given, and :class:`ValueError` for a budget factor outside (0, 1000] or a
    ``min_wall`` that is neither 0 nor from 0.001 to 1e6 mm (NaN, negative, infinite:
    :func:`~aidl_lang.base.limits.min_wall_problem`)."""
    from ..pipeline import compile_source
    if source is None and path is None:
        raise TypeError("compile() needs source= (the program text) or path= (a file)")
    if budget is None:
        b = DEFAULT_BUDGET
    elif isinstance(budget, Budget):
        b = budget
    else:
        k = float(budget)
        if not 0 < k <= 1000:
            raise ValueError(f"budget expects a factor between 0 and 1000, got {budget!r}")
        b = DEFAULT_BUDGET.scaled(k)
    if min_wall is not None:
        from ..base.limits import min_wall_problem
        why = min_wall_problem(float(min_wall))
        if why is not None:
            raise ValueError(f"min_wall: {why}")
    name = os.fspath(path) if path is not None else "<source>"
    if source is None:
        from ..library.sources import SourceRefused, read_program
        try:
            source = read_program(name)
        except SourceRefused as e:
            return _unreadable(name, e)
    ov = {str(k): str(v) for k, v in (overrides or {}).items()}
    return Result(compile_source(source, name, ov or None, min_wall=min_wall, budget=b),
                  name, source)


def _unreadable(name: str, e: Exception) -> Result:
    from ..pipeline import Compiled
    sink = DiagnosticSink()
    from ..base.diagnostics import Span
    sink.add(Diagnostic("E0004", str(e), Span(name, 1, 1, 1, 1, 0, 0),
                        hint="give a regular UTF-8 .aidl file (programs and imports have at "
                             "most 1000000 bytes)"))
    return Result(Compiled(sink), name, None)


# ------------------------------------------------------------------ editing params
class ParamsRefused(ValueError):
    """:func:`set_params` refused the values: ``code`` ``no_match`` (a name that is not a
    top-level ``param`` of the file; ``nearest``: the nearest names) or ``bad_value`` (a value
    of the wrong kind or outside the param's declared range: ``diagnostics``, the E0113 or
    E0124 the compiler gives for it); ``name``: the param at fault."""

    def __init__(self, message: str, code: str, name: str,
                 nearest: list[str] | None = None,
                 diagnostics: list[Diagnostic] | None = None) -> None:
        super().__init__(message)
        self.code, self.name = code, name
        self.nearest = nearest or []
        self.diagnostics = diagnostics or []


def set_params(source: str, values: Mapping[str, str | float | bool],
               path: str | os.PathLike = "<source>",
               budget: float | Budget | None = None) -> tuple[str, Result]:
    """The program ``source`` with the value of each top-level ``param NAME = VALUE`` named in
    ``values`` replaced, and its :class:`Result`: ``(new text, result)``.  Only the value's
    text changes (``param width = 40 mm, min=20 mm`` -> ``param width = 50 mm, min=20 mm``):
    comments, spacing and every other line stay as written.  A value is a string read as the
    program reads one (``"50 mm"``, ``"2 * 25"``), a number (a bare number for a length or
    angle param is in the param's own unit and written with it: ``40`` on ``param w = 60 mm``
    writes ``40 mm``) or a bool; a string param's new text is quoted when it is not already.

    The values are first checked as :func:`compile`'s ``overrides`` are (the kind of the
    param's value, its declared ``min``/``max``).  Raises :class:`ParamsRefused`
    (``no_match`` for an unknown name, with the nearest; ``bad_value`` with the E0113/E0124
    diagnostic: nothing is returned to write), :class:`ValueError` for a program that does not
    parse (its params cannot be found) or an empty ``values``."""
    from ..base.diagnostics import did_you_mean
    from ..parser import parse
    from .. import ast as A
    if not values:
        raise ValueError("give at least one param name and value")
    name = os.fspath(path)
    sink = DiagnosticSink()
    program = parse(source, name, sink)
    if sink.has_errors:
        raise ValueError("the program does not parse: fix its syntax first (`check` says where)")
    decls = {st.name: st for st in program.stmts if isinstance(st, A.ParamDecl)}
    for k in values:
        if k not in decls:
            near = did_you_mean(str(k), list(decls), 3)
            raise ParamsRefused(
                f"the program has no param `{k}`"
                + (f"; did you mean {', '.join(f'`{n}`' for n in near)}?" if near else "")
                + (f" (params: {', '.join(sorted(decls))})" if decls else
                   " (it declares none: add `param NAME = VALUE` at the top)"),
                "no_match", str(k), near)
    texts = {k: _param_text(v, decls[k].value) for k, v in values.items()}
    from ..params.set_values import comment_problem
    for k, t in texts.items():
        d = comment_problem(source, decls[k], t)
        if d is not None:           # `w=40 mm # x` would comment out the range (E0113)
            raise ParamsRefused(d.message, "bad_value", k, diagnostics=[d])
    # the values checked as overrides: the kind of value and the declared range
    checked = compile(source=source, path=name, overrides=texts, budget=budget)
    for d in checked.diagnostics:
        if d.code in ("E0113", "E0124") and "`--set " in d.message:
            at = next((k for k in texts if f"`--set {k}=" in d.message), next(iter(texts)))
            d.message = d.message.replace("`--set ", "`")
            if d.hint:
                d.hint = d.hint.replace("`--set ", "`")
            raise ParamsRefused(d.message, "bad_value", at, diagnostics=[d])
    texts = _units_written(source, decls, texts, checked.compiled.params or {})
    out, last = [], 0
    for st in sorted((decls[k] for k in texts), key=lambda s: s.value.span.start):
        out += [source[last:st.value.span.start], texts[st.name]]
        last = st.value.span.end
    text = "".join(out) + source[last:]
    return text, compile(source=text, path=name, budget=budget)


_NUMBER = re.compile(r"[+-]?\s*(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


def _units_written(source: str, decls: dict, texts: dict[str, str],
                   params: dict) -> dict[str, str]:
    """``texts`` with a bare number given to a length or angle param written with the
    param's own unit (issue 105: ``w=40`` on ``param w = 60 mm, min = 20 mm`` wrote
    ``param w = 40, min = 20 mm``, which no longer compiled): ``40 mm``, as the check compile
    read it (:func:`~aidl_lang.interpreter.param_units.own_unit`); an expression of bare
    numbers as ``(2 * 20) * 1 mm``.  ``params``: the checked compile's values, name -> value
    (their dimensions); a value that names anything but ``pi``/``tau`` stays as given."""
    from .. import ast as A
    from ..base.diagnostics import DiagnosticSink
    from ..geometry.core.values import ANG, LEN, Q
    from ..interpreter.param_units import own_unit
    from ..parsing.lalr import parse_expression
    from ..registry import CONSTANTS
    from .values import file_units
    out = dict(texts)
    for k, t in texts.items():
        v = params.get(k)
        if not isinstance(v, Q) or v.dim not in (LEN, ANG):
            continue
        sink = DiagnosticSink()
        try:
            node = parse_expression(t, "<set>", sink)
        except Exception:       # noqa: BLE001 - the check compile read it; leave it be
            continue
        if sink.has_errors or any(isinstance(n, A.Num) and n.unit is not None
                                  or isinstance(n, A.Name) and n.id not in CONSTANTS
                                  or isinstance(n, (A.Str, A.Call)) for n in A.walk(node)):
            continue
        unit = own_unit(decls[k].value, v.dim, file_units(source)[0])
        plain = _NUMBER.fullmatch(t.strip()) is not None
        out[k] = f"{t} {unit}" if plain else f"({t}) * 1 {unit}"
    return out


def _param_text(value, old) -> str:
    """The text of a param's new ``value`` (as :func:`set_params` takes it) in place of the
    expression ``old``: a bool as ``true``/``false``, a number as Python writes it, a string
    as given, quoted when the param's value was a string literal and it is not quoted."""
    from .. import ast as A
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        if not math.isfinite(value):
            raise ParamsRefused(f"{value!r} is not a finite number", "bad_value", "")
        return repr(value) if isinstance(value, int) or not value.is_integer() \
            else str(int(value))
    text = str(value).strip()
    if isinstance(old, A.Str) and not text.startswith('"'):
        import json
        return json.dumps(text)
    if "\n" in text or not text:
        raise ParamsRefused(f"a param's value is one line of text; got {value!r}",
                            "bad_value", "")
    return text
