"""A program's top-level ``param`` declarations as a customizer shows them (sliders), shared by
``aidl serve`` (:mod:`aidl_lang.serve.session`) and the editor preview
(:mod:`aidl_lang.editor.lsp.preview`): :class:`Param` (name, kind, value, default, display
unit and the slider's ``min``/``max``/``step``: the file's ``min=``/``max=``/``step=``
(docs/language.md, "param and --set"), else :func:`default_span` around the value), and
:func:`declared_params`, the params of a source text with its own values (docs/api.md,
"Customizer params").  Not part of the stable API.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

@dataclass
class Param:
    """A ``param`` as the customizer shows it.  ``kind``: length (mm), angle (deg), number,
    bool or string; ``value``/``default``/``min``/``max``/``step`` in those display units;
    ``declared``: the range comes from the file (``min=``/``max=``/``step=``), else a default
    span chosen around the value."""

    name: str
    kind: str
    value: object
    default: object
    unit: str = ""
    min: float | None = None
    max: float | None = None
    step: float | None = None
    declared: bool = False
    line: int = 0

    def to_json(self) -> dict:
        return {k: v for k, v in self.__dict__.items() if k != "span"}


def _param(name: str, v, rng: dict | None, line: int, default=None) -> Param | None:
    """The customizer's view of a param's value ``v``; ``default``: the file's value when
    ``v`` is a customizer value (the default span is chosen around the file's value, so the
    slider does not rescale while it moves)."""
    if isinstance(v, bool):
        return Param(name, "bool", v, v if default is None else default, line=line)
    if isinstance(v, str):
        return Param(name, "string", v, v if default is None else default, line=line)
    from ..geometry.values import ANG, LEN, NUM, Q
    if not isinstance(v, Q) or v.const() is None:
        return None
    c = v.const()
    kind, unit, k = {LEN: ("length", "mm", 1.0), ANG: ("angle", "deg", 180 / math.pi),
                     NUM: ("number", "", 1.0)}.get(v.dim, (None, "", 1.0))
    if kind is None:
        return None
    val = round(c * k, 9)
    dflt = val if not isinstance(default, (int, float)) or isinstance(default, bool) else default
    p = Param(name, kind, val, dflt, unit, line=line)
    lo = rng.get("min") if rng else None
    hi = rng.get("max") if rng else None
    step = rng.get("step") if rng else None
    p.declared = rng is not None
    p.min, p.max = (lo * k if lo is not None else None), (hi * k if hi is not None else None)
    p.step = step * k if step is not None else None
    dlo, dhi, dstep = default_span(kind, dflt)
    if p.min is None:
        p.min = min(dlo, dflt) if p.max is None else min(dlo, dflt, p.max)
    if p.max is None:
        p.max = max(dhi, dflt, p.min)
    if p.step is None:
        p.step = dstep if kind != "number" or float(dflt).is_integer() else _nice((p.max - p.min) / 200)
    for a in ("min", "max", "step"):
        setattr(p, a, round(getattr(p, a), 9))
    return p


def default_span(kind: str, v: float, counts: bool | None = None) -> tuple[float, float, float]:
    """Slider span for a param without a declared range (and the range ``aidl check --sweep``
    sweeps it across, :mod:`aidl_lang.sweep_plan`): a quarter to twice a length or number, a
    full turn for an angle; a count (``counts``; None: any whole number) in whole steps from 1
    (0 for a count written 0) to twice it, at least 10 (a negative one: twice it to a
    quarter of it)."""
    if kind == "angle":
        return -180.0, 360.0 if v > 180 else 180.0, 1.0
    if counts is None:
        counts = kind == "number" and float(v).is_integer()
    if kind == "number" and counts:
        if v >= 1:
            return 1.0, float(math.ceil(max(2 * v, 10))), 1.0
        if v < 0:
            return float(math.floor(2 * v)), float(math.ceil(v / 4)), 1.0
        return 0.0, 10.0, 1.0
    if v == 0:
        return (-100.0, 100.0, 0.5) if kind == "length" else (-10.0, 10.0, 0.1)
    a, b = sorted((v / 4, v * 2)) if v > 0 else sorted((v * 2, v / 4))
    step = _nice((b - a) / 200)
    return math.floor(a / step) * step, math.ceil(b / step) * step, step


def _nice(x: float) -> float:
    """The 1-2-5 step not above ``x``."""
    if x <= 0:
        return 1.0
    e = math.floor(math.log10(x))
    for m in (5, 2, 1):
        if m * 10 ** e <= x:
            return m * 10 ** e
    return 10 ** e


def declared_params(source: str, path: str) -> list[Param] | None:
    """The top-level params of ``source`` (named ``path``) with the file's own values, in
    declaration order (``line``: 1-based, ``span``: the declaration's
    :class:`~aidl_lang.diagnostics.Span`, set as an attribute); ``None`` when the program does
    not parse, check or interpret (its diagnostics are for the compile to report)."""
    from .. import ast as A
    from ..diagnostics import DiagnosticSink
    from ..interp import Interpreter
    from ..parser import parse
    from ..pipeline import run_deep
    from ..typecheck import check
    sink = DiagnosticSink()
    try:
        program = parse(source, path, sink)
        if not sink.has_errors:
            check(program, sink)
        if sink.has_errors:
            return None
        interp = Interpreter(sink, {})
        run_deep(lambda: interp.run(program))
    except Exception:          # noqa: BLE001 - sliders are an extra; a bug here loses only them
        return None
    fctx = interp.file
    if fctx is None:
        return None
    ranges = getattr(fctx, "param_ranges", {})
    out = []
    for st in program.stmts:
        if isinstance(st, A.ParamDecl):
            p = _param(st.name, fctx.params.get(st.name), ranges.get(st.name),
                       st.span.line if st.span else 0)
            if p is not None:
                p.span = st.span
                out.append(p)
    return out
