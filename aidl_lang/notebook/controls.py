"""The form of :mod:`aidl_lang.notebook`: one ipywidgets control per ``param`` over the
drawing, redrawn (debounced) when a control moves (docs/notebook.md)."""
from __future__ import annotations

import json
import os

from .. import api

__all__ = ["form", "Form", "FormError", "NOTEBOOK_EXTRA"]

NOTEBOOK_EXTRA = "pip install 'aidl-lang[notebook]'"


class FormError(ValueError):
    """A value :meth:`Form.set` refuses (of the wrong type, or outside its control's range):
    nothing changed.  IPython shows it as its one line, not a traceback."""

    def _render_traceback_(self) -> list[str]:
        return [f"FormError: {self}"]


def _widgets():
    """The ``ipywidgets`` module, or an :class:`ImportError` naming the extra to install."""
    try:
        import ipywidgets
    except ImportError as e:
        raise ImportError("aidl_lang.notebook.form needs ipywidgets, the `notebook` extra: "
                          f"{NOTEBOOK_EXTRA}") from e
    return ipywidgets


def form(source: str | os.PathLike | api.Result, path: str | os.PathLike | None = None,
         debounce: float = 0.25, budget: float | None = None) -> Form:
    """A :class:`Form` for the program ``source``: its text, or a path to it (an
    :class:`os.PathLike`, or a one-line string ending in ``.aidl``: the file is read as
    UTF-8, with the sandbox of :func:`aidl_lang.compile`), or a compiled
    :class:`aidl_lang.Result` (its program; after :meth:`~aidl_lang.Result.sweep`, each
    slider spans only the clean range the sweep found, still holding the param's value).  ``path``: the name diagnostics
    are located in and where ``import "x.aidl"`` resolves from, when ``source`` is text
    (default ``<source>``).  ``debounce``: seconds a change waits for the next before the
    program is compiled again (0: at once).  ``budget``: a factor of the default evaluation
    budget, as for :func:`aidl_lang.compile`.

    A file that cannot be read, or a program that does not compile, is no exception: the form
    shows its located diagnostics (and no control when its params cannot be read).  Raises
    :class:`ImportError` (naming the ``notebook`` extra) without ipywidgets, and
    :class:`ValueError` for a negative ``debounce`` or a budget factor outside (0, 1000]."""
    widgets = _widgets()
    if not debounce >= 0:
        raise ValueError(f"debounce expects seconds >= 0, got {debounce!r}")
    if isinstance(source, api.Result):
        first = source
    elif isinstance(source, os.PathLike) or (
            isinstance(source, str) and "\n" not in source and source.strip().endswith(".aidl")):
        first = api.compile(path=os.fspath(source).strip(), budget=budget)
    else:
        if not isinstance(source, str):
            raise TypeError(f"form() expects the program's text or a path, got "
                            f"{type(source).__name__}")
        first = api.compile(source=source, path=os.fspath(path) if path else None,
                            budget=budget)
    return Form(widgets, first, debounce, budget)


class Form:
    """The controls of a program's params over its drawing (made by :func:`form`).

    ``widget``: the ipywidgets ``VBox`` shown (a cell whose value is the form shows it);
    ``params``: the :class:`~aidl_lang.serve.params.Param` of each control (name, kind,
    display unit ``mm``/``deg``/``""``, default, min, max, step), in declaration order;
    ``controls``: name → the control widget; ``output``: the ``HTML`` widget holding the
    drawing (``text/html`` of :meth:`aidl_lang.Result._repr_mimebundle_`: the SVG with the
    diagnostics under it, or the located errors); ``result``: the last
    :class:`aidl_lang.Result`; ``path``/``source``: the program; ``redraws``: how many
    compiles the form ran (the first one included)."""

    def __init__(self, widgets, first: api.Result, debounce: float,
                 budget: float | None) -> None:
        from ..serve.params import declared_params
        self._w = widgets
        self.path, self.source = first.path, first.source
        self.debounce, self.budget = debounce, budget
        self.result = first
        self.redraws = 1
        self._pending = None
        self._quiet = False
        declared = declared_params(self.source, self.path) if self.source is not None else None
        self.params = declared or []
        swept = getattr(first, "swept", None)
        clean = swept.clean_ranges() if swept is not None and swept.ok else {}
        for p in self.params:
            if p.name in clean and p.kind in ("length", "angle", "number"):
                lo, hi = clean[p.name]        # the sweep's clean range, the value kept in it
                p.min, p.max = max(p.min, min(lo, p.value)), min(p.max, max(hi, p.value))
        self.controls = {p.name: self._control(p) for p in self.params}
        for c in self.controls.values():
            c.observe(self._changed, names="value")
        self.output = widgets.HTML(value=self._html(first))
        rows = list(self.controls.values()) or [widgets.Label(
            "This program declares no `param`." if declared is not None else
            "No controls: the program does not compile far enough to read its params "
            "(its errors are below).")]
        self.widget = widgets.VBox([widgets.VBox(rows), self.output])

    # ------------------------------------------------------------------ controls
    def _control(self, p):
        w = self._w
        style = {"description_width": "initial"}
        label = f"{p.name} ({p.unit})" if p.unit else p.name
        if p.kind == "bool":
            return w.Checkbox(value=bool(p.value), description=p.name, style=style,
                              indent=False)
        if p.kind == "string":
            return w.Text(value=str(p.value), description=p.name, style=style,
                          continuous_update=False)
        if _integral(p):
            return w.IntSlider(value=int(p.value), min=int(p.min), max=int(p.max),
                               step=int(p.step), description=label, style=style)
        return w.FloatSlider(value=float(p.value), min=float(p.min), max=float(p.max),
                             step=float(p.step), description=label, style=style,
                             readout_format=_readout(float(p.step)))

    @property
    def values(self) -> dict:
        """name → the control's value, in the display units (mm, degrees)."""
        return {n: c.value for n, c in self.controls.items()}

    def overrides(self) -> dict[str, str]:
        """The values that differ from the file's, as ``--set`` texts (``60mm``, ``15deg``,
        ``true``, ``"text"``): the ``overrides`` the next compile gets."""
        out = {}
        for p in self.params:
            v = self.controls[p.name].value
            if v != p.default:
                out[p.name] = _set_text(p.kind, v)
        return out

    def set(self, **values) -> api.Result:
        """Move controls to ``values`` (name → value in the display units: mm, degrees) and
        redraw at once (no debounce); returns the new result.

        All or nothing: every value is checked before any control moves, and a refused
        ``set`` changes no control and no drawing.  Raises :class:`KeyError` for a name that
        is not a param of the form (with the names it has), and :class:`FormError` (a
        :class:`ValueError`, shown in a notebook as its one line) for a value of the wrong
        type (a number for a slider, a whole number for a count, True/False for a checkbox,
        text for a text box) or outside its control's range (the param's ``min=``/``max=``,
        or the span around the file's value when it declares none)."""
        unknown = [n for n in values if n not in self.controls]
        if unknown:
            raise KeyError(f"no param {', '.join(map(repr, unknown))}; the form has "
                           + (", ".join(self.controls) or "none"))
        params = {p.name: p for p in self.params}
        checked = {n: _checked(params[n], self.controls[n], v) for n, v in values.items()}
        before = {n: self.controls[n].value for n in checked}
        self._quiet = True
        try:
            for n, v in checked.items():
                self.controls[n].value = v
        except Exception as e:          # a control refusing what was checked: none moves
            for n, v in before.items():
                self.controls[n].value = v
            raise FormError(f"{n}: {e}") from None
        finally:
            self._quiet = False
        return self.redraw()

    # ------------------------------------------------------------------ drawing
    def _changed(self, _change) -> None:
        """A control moved: redraw after ``debounce`` seconds without another change (on the
        kernel's event loop; at once when there is no running loop)."""
        if self._quiet:
            return
        if self._pending is not None:
            self._pending.cancel()
            self._pending = None
        loop = None
        if self.debounce > 0:
            import asyncio
            try:
                loop = asyncio.get_running_loop()
            except RuntimeError:
                loop = None
        if loop is None:
            self.redraw()
        else:
            self._pending = loop.call_later(self.debounce, self._fire)

    def _fire(self) -> None:
        self._pending = None
        self.redraw()

    def redraw(self) -> api.Result:
        """Compile the program with the controls' values and show it; returns the result."""
        self.result = api.compile(source=self.source, path=self.path,
                                  overrides=self.overrides(), budget=self.budget)
        self.redraws += 1
        self.output.value = self._html(self.result)
        return self.result

    @staticmethod
    def _html(result: api.Result) -> str:
        return result._repr_mimebundle_()["text/html"]

    # ------------------------------------------------------------------ display
    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    def __repr__(self) -> str:
        return (f"<aidl Form {self.path}: {len(self.controls)} controls "
                f"({', '.join(self.controls) or 'none'}); {self.result.summary()}>")


def _checked(p, control, v):
    """The value ``v`` for ``control``, the control of param ``p`` (a
    :class:`~aidl_lang.serve.params.Param`), as the control holds it; raises
    :class:`FormError` for a value of another type than the control's or outside its range
    (inclusive, in the display units)."""
    import math
    kind = type(control).__name__
    if kind == "Checkbox":
        if not isinstance(v, bool):
            raise FormError(f"`{p.name}` takes True or False, not {v!r}; nothing changed")
        return v
    if kind == "Text":
        if not isinstance(v, str):
            raise FormError(f"`{p.name}` takes text (a str), not {v!r}; nothing changed")
        return v
    unit = f" {p.unit}" if p.unit else ""
    what = "a whole number" if kind == "IntSlider" else f"a number{f' in {p.unit}' if unit else ''}"
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise FormError(f"`{p.name}` takes {what}, not {v!r}; nothing changed")
    if kind == "IntSlider":
        if not float(v).is_integer():
            raise FormError(f"`{p.name}` takes {what}, not {v!r}; nothing changed")
        v = int(v)
    if not control.min <= v <= control.max:
        raise FormError(
            f"`{p.name}` = {_fmt(v)}{unit} is outside its control's range {_fmt(control.min)} .. "
            f"{_fmt(control.max)}{unit}; nothing changed"
            + ("" if p.declared else f" (`param {p.name}` declares no range: its `min=` and "
                                     f"`max=` give it one)"))
    return v


def _integral(p) -> bool:
    """A count: a number param whose default, range and step are whole (the studio's
    ``integer`` rows, :func:`aidl_lang.studio.gallery.param_rows`)."""
    return p.kind == "number" and all(
        isinstance(v, (int, float)) and float(v).is_integer()
        for v in (p.default, p.value, p.min, p.max, p.step))


def _readout(step: float) -> str:
    """The slider's readout format: as many decimals as the step has (at most 6)."""
    text = f"{step:.6f}".rstrip("0").rstrip(".")
    decimals = len(text.split(".")[1]) if "." in text else 0
    return f".{decimals}f"


def _fmt(v: float) -> str:
    """A control's number to 6 decimals, without trailing zeros or an exponent."""
    return f"{float(v):.6f}".rstrip("0").rstrip(".")


def _set_text(kind: str, v) -> str:
    """The ``--set`` text of a control's value (the customizer's syntax)."""
    if kind == "length":
        return f"{_fmt(v)}mm"
    if kind == "angle":
        return f"{_fmt(v)}deg"
    if kind == "bool":
        return "true" if v else "false"
    if kind == "string":
        return json.dumps(str(v))
    return _fmt(v)
