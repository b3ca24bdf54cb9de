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

from ..params.sweep_plan import _nice, default_span  # noqa: F401 - the sliders' default span

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
    from ..geometry.core.values import ANG, LEN, NUM, Q
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


def declared_params(source: str, path: str) -> list[Param] | None:
    """The top-level params of ``source`` (named ``path``) with the file's own values, in
    declaration order (``line``: 1-based, ``span``: the declaration's
    :class:`~aidl_lang.base.diagnostics.Span`, set as an attribute); ``None`` when the program does
    not parse, check or interpret (its diagnostics are for the compile to report)."""
    from .. import ast as A
    from ..base.diagnostics import DiagnosticSink
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
