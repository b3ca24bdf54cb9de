"""Solved values in the code: inlay hints after named geometry and a code lens per structure
with its degrees of freedom.

The analysis worker turns a solved program into *facts* (:func:`solved_facts`, plain JSON:
computed once per analysis, with the diagnostics); the server places them in the document
(:func:`inlay_hints`, :func:`code_lenses`) by walking its syntax tree, so hints follow the text
without another solve.  Both come from :mod:`aidl_lang.api` (``Result.values`` as
``aidl check --values`` prints them, ``Result.freedom`` as ``aidl check --dof``).

* inlay hint after ``c = Circle(...)``: ``r=5 mm @ (10, 0)`` (file units; a rectangle
  ``40 × 20 mm @ (0, 0)``, a line ``(0, 0) → (10, 0), L=10 mm``, a point ``@ (3, 4)``; a name
  made in a loop shows its first copy and the number of others), after a structure's name its
  frame origin when it is not ``(0, 0)``, after a param its value (``= 10 mm``) unless the
  param is that literal already;
* code lens on each structure: ``fully constrained`` or ``3 DOF: body, bore (position)`` (the
  entities the degrees-of-freedom analysis finds still free, named relative to the
  structure; counted without names when a structure has over :data:`MAX_NAMED_UNKNOWNS`
  unknowns), ``DOF not counted (too large)``.
"""
from __future__ import annotations

import math

from ... import ast as A

MAX_NAMED_UNKNOWNS = 5000        # structures up to this many unknowns get their floating names
MAX_NAMED = 4                     # floating entities named in a lens


def _num(v: float) -> str:
    s = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _pt(p) -> str:
    return f"({_num(p[0])}, {_num(p[1])})"


def _summary(vals: dict[str, object], unit: str) -> str | None:
    """A short text for one geometry's solved values (``member -> Value``)."""
    u = f" {unit}" if unit else ""
    c = vals.get("center")
    if "radius" in vals:
        r = vals["radius"].value
        return f"r={_num(r)}{u}" + (f" @ {_pt(c.value)}" if c is not None else "")
    if "width" in vals and "height" in vals:
        w, h = vals["width"].value, vals["height"].value
        return f"{_num(w)} × {_num(h)}{u}" + (f" @ {_pt(c.value)}" if c is not None else "")
    if "start" in vals and "end" in vals:
        a, b = vals["start"].value, vals["end"].value
        return f"{_pt(a)} → {_pt(b)}, L={_num(math.hypot(b[0] - a[0], b[1] - a[1]))}{u}"
    pts = [v for v in vals.values() if v.kind == "point"]
    if len(vals) == 1 and len(pts) == 1:
        return f"@ {_pt(pts[0].value)}"
    if c is not None:
        return f"@ {_pt(c.value)}"
    return None


def solved_facts(result) -> dict:
    """``{"geometry": {path: text}, "origins": {path: text}, "structures": {path: text},
    "unit": unit}`` for a solved :class:`aidl_lang.api.Result`: a summary of each named
    geometry's values (:func:`_summary`), each structure's frame origin and its degrees of
    freedom (see the module doc).  Paths are those of ``Result.values`` (the implicit root's
    name left out)."""
    values = result.values
    unit = result.units
    structures = {v.name[:-len(".origin")] if v.name != "origin" else ""
                  for v in values if v.name == "origin" or v.name.endswith(".origin")}
    by_geom: dict[str, dict] = {}
    origins: dict[str, str] = {}
    for v in values:
        base, _, member = v.name.rpartition(".")
        if base in structures or not base:      # a structure's origin, bbox, named numbers
            if member == "origin" and (abs(v.value[0]) > 5e-10 or abs(v.value[1]) > 5e-10):
                origins[base] = f"@ {_pt(v.value)}"
            continue
        by_geom.setdefault(base, {})[member] = v
    geometry = {}
    for g, vals in by_geom.items():
        text = _summary(vals, unit)
        if text:
            geometry[g] = text
    return {"geometry": geometry, "origins": origins, "structures": _freedom(result),
            "params": _params(result), "unit": unit}


def _params(result) -> dict[str, str]:
    """name -> value text of the main file's params, lengths in the file's unit, angles in
    degrees (``--set`` overrides included)."""
    import math as _m
    out = {}
    for name, v in (getattr(result.compiled, "params", None) or {}).items():
        if isinstance(v, bool):
            out[name] = "true" if v else "false"
        elif isinstance(v, str):
            out[name] = repr(v)
        else:
            c = v.const() if hasattr(v, "const") else None
            dim = getattr(v, "dim", None)
            if c is None:
                continue
            if dim == (1, 0):
                out[name] = f"{_num(c / result.unit_scale)} {result.units}"
            elif dim == (0, 1):
                out[name] = f"{_num(_m.degrees(c))} deg"
            elif dim == (0, 0):
                out[name] = _num(c)
    return out


def _freedom(result) -> dict[str, str]:
    """structure path -> its degrees-of-freedom text.  The count per structure is cheap (ranks,
    as ``aidl check`` counts them); naming what floats needs a null space per structure, so it
    is done (``Result.freedom(detail=True)``, as ``aidl check --dof``: propagation, then an
    SVD of what is left, ~0.1 s for the 5 000-unknown gear pair) only when no structure has
    more than :data:`MAX_NAMED_UNKNOWNS` unknowns."""
    from ...solver.diagnosis.freedom import degrees_of_freedom
    model = result.compiled.model
    counts = degrees_of_freedom(result.compiled.solve.solver, floating=False)
    root = model.root
    implicit = root.name == "model" and root.span is not None and root.span.start == 0

    def rel(path: str) -> str:
        if implicit and (path == "model" or path.startswith("model.")):
            return path[len("model"):].lstrip(".")
        return path
    named = {}
    if counts and max(d.unknowns for d in counts) <= MAX_NAMED_UNKNOWNS:
        named = {s["structure"]: s["floating"] for s in result.freedom(detail=True)["structures"]}
    out: dict[str, str] = {}
    for d in counts:
        path = d.structure.path
        if d.rank < 0:
            out[rel(path)] = "DOF not counted (too large)"
            continue
        dof = max(0, d.dof)
        if dof == 0:
            out[rel(path)] = "fully constrained"
            continue
        prefix = path + "."
        names = [f[len(prefix):] if f.startswith(prefix) else f for f in named.get(path, [])]
        more = f", +{len(names) - MAX_NAMED}" if len(names) > MAX_NAMED else ""
        out[rel(path)] = f"{dof} DOF" + (f": {', '.join(names[:MAX_NAMED])}{more}" if names else "")
    return out


# ------------------------------------------------------------------ placing facts in the text
def _walk(stmts, prefix: str, out: list, in_struct: bool) -> None:
    """(kind, path, node) for structures and for assignments directly in a structure body
    (through ``if`` blocks; loops make indexed names and are matched by their plain name)."""
    for st in stmts:
        if isinstance(st, A.StructDecl):
            path = prefix + st.name
            out.append(("structure", path, st))
            _walk(st.body.stmts, path + ".", out, True)
        elif isinstance(st, A.Assign) and in_struct or isinstance(st, A.Assign) and not prefix:
            out.append(("geometry", prefix + st.name, st))
        elif isinstance(st, (A.For, A.If, A.Block)):
            body = st.stmts if isinstance(st, A.Block) else st.body.stmts
            _walk(body, prefix, out, in_struct)
            if isinstance(st, A.If) and st.orelse is not None:
                _walk(st.orelse.stmts, prefix, out, in_struct)


def placed(program: A.Program) -> list[tuple[str, str, object]]:
    """Every param, structure and named assignment of ``program`` with its value path."""
    out: list = [("param", st.name, st) for st in program.stmts if isinstance(st, A.ParamDecl)]
    _walk([s for s in program.stmts if not isinstance(s, (A.Def, A.ParamDecl))], "", out, False)
    return out


def _lookup(table: dict[str, str], path: str) -> str | None:
    if path in table:
        return table[path]
    copies = [k for k in table if k.startswith(path + "[")]
    if copies:
        first = table[copies[0]]
        return first + (f" (+{len(copies) - 1} copies)" if len(copies) > 1 else "")
    return None


def inlay_hints(src: str, program: A.Program, facts: dict, first_line: int = 0,
                last_line: int | None = None) -> list[dict]:
    """LSP ``InlayHint`` dicts (``{"position", "label", "kind", "paddingLeft"}``) for the
    lines ``first_line..last_line`` (0-based): after each named geometry's statement its
    :func:`_summary`, after a structure's name its origin when not at ``(0, 0)``."""
    from .plain import u16len
    lines = src.split("\n")
    out = []
    geometry, origins = facts.get("geometry") or {}, facts.get("origins") or {}
    params = facts.get("params") or {}
    for kind, path, node in placed(program):
        if kind == "param":
            text = params.get(path)
            sp = node.value.span
            if text is None or src[sp.start:sp.end].replace(" ", "") == text.replace(" ", ""):
                continue                      # a literal that says it already
            text = f"= {text}"
            line, col = sp.end_line - 1, sp.end_col - 1
        elif kind == "geometry":
            text = _lookup(geometry, path)
            sp = node.span
            line, col = sp.end_line - 1, sp.end_col - 1
        else:
            text = _lookup(origins, path)
            sp = node.name_span
            line, col = sp.line - 1, sp.col - 1 + len(node.name)
        if not text or line < first_line or (last_line is not None and line > last_line):
            continue
        ln = lines[line] if line < len(lines) else ""
        out.append({"position": {"line": line, "character": u16len(ln[:col])},
                    "label": text, "kind": 1, "paddingLeft": True})
    return out


def code_lenses(src: str, program: A.Program, facts: dict) -> list[dict]:
    """LSP ``CodeLens`` dicts, one per structure (a ``solid``/``hole``/... block or a
    template instance ``b = f(...)``) with a known degrees-of-freedom text, on its name; its command is empty (``""``), so clients show the title and do nothing on a click."""
    from .plain import span_range
    structures = facts.get("structures") or {}
    out = []
    for kind, path, node in placed(program):
        if kind == "param":
            continue
        text = structures.get(path)            # a structure, or a template instance `b = f()`
        if text is None and kind == "structure" and "." not in path and len(structures) == 1:
            text = next(iter(structures.values()))          # the whole-model count
        if text is None:
            continue
        out.append({"range": span_range(src, node.name_span),
                    "command": {"title": text, "command": ""}})
    return out
