"""One program in, one result row out: compile, measure, render (docs/batch.md, "Rows").

:func:`run_one` runs in a worker process (:mod:`.child`) and never raises for a bad program:
errors are the row's data.  A row is a flat ``dict`` of JSON values, the same whichever engine
ran it (local pool or Dask), so the two can be compared field by field less :data:`TIMINGS`.
"""
from __future__ import annotations

import hashlib
import json
import time
from pathlib import Path

# the fields that differ from one run to the next (wall times)
TIMINGS = ("compile_s", "solve_s", "render_s")

# every field of a row, in file order (the Parquet schema in :mod:`.store` follows it)
FIELDS = ("id", "path", "sha256", "options", "status", "ok", "failure", "errors", "warnings",
          "dof", "parts", "holes", "bbox", "area", "compile_s", "solve_s", "render_s",
          "outputs")

STATUSES = ("ok", "error", "timeout", "crashed")

def sha256(data: str | bytes) -> str:
    if isinstance(data, str):
        data = data.encode("utf-8")
    return hashlib.sha256(data).hexdigest()


def options_key(overrides: dict, budget: float, cfg: dict) -> str:
    """What besides the source decides a row (a resumed batch redoes a row whose source *or*
    these changed): the ``--set`` values, the budget factor, the renders and their folder, the
    minimum wall."""
    return json.dumps({"set": overrides, "budget": budget, "render": cfg.get("render", []),
                       "out_dir": cfg.get("out_dir"), "min_wall": cfg.get("min_wall")},
                      sort_keys=True, separators=(",", ":"))


def blank_row(task: dict, status: str, failure: str | None = None, **extra) -> dict:
    """A row with every field present (``None`` where nothing was measured)."""
    row = {k: None for k in FIELDS}
    row.update(id=task["id"], path=task.get("path"), sha256=task["sha256"],
               options=task["options"], status=status, ok=status == "ok", failure=failure,
               errors=[], warnings=[], outputs=[])
    row.update(extra)
    return row


def _diag(d) -> dict:
    s = d.span
    return {"code": d.code, "line": s.line if s is not None else None,
            "column": s.col if s is not None else None, "message": d.message}


def run_one(task: dict, cfg: dict) -> dict:
    """The row of one task: ``task`` has ``id``, ``path`` (or None), ``source``, ``sha256``,
    ``options``, ``overrides``, ``budget`` (a factor) and ``stem`` (the rendered files' name);
    ``cfg`` has ``render`` (suffixes such as ``.svg``), ``out_dir``, ``min_wall``."""
    from ..base.limits import DEFAULT_BUDGET
    from ..pipeline import compile_source
    if task.get("read_error"):               # the parent could not read the file: E0004
        return blank_row(task, "error", errors=[{"code": "E0004", "line": None, "column": None,
                                                  "message": task["read_error"]}])
    t0 = time.perf_counter()
    res = compile_source(task["source"], task.get("path") or task["id"], task["overrides"],
                         min_wall=cfg.get("min_wall"),
                         budget=DEFAULT_BUDGET.scaled(task["budget"]))
    row = blank_row(task, "ok" if res.ok else "error",
                    errors=[_diag(d) for d in res.sink.items if d.is_error],
                    warnings=[_diag(d) for d in res.sink.items if d.severity == "warning"],
                    solve_s=res.solve_seconds if res.solve is not None else None)
    if res.ok and res.solve is not None:
        from ..solver.diagnosis.freedom import degrees_of_freedom
        # in what the compile left of the program's budget, as `aidl check` counts (issue 48)
        end = res.deadline.at if res.deadline is not None else None
        dofs = degrees_of_freedom(res.solve.solver, floating=False, deadline=end)
        row["dof"] = (None if any(d.rank < 0 for d in dofs)
                      else sum(max(0, d.dof) for d in dofs))
    output = None
    if res.ok and res.drawing is not None:
        from ..output import OutputError, build
        try:
            output = build(res.drawing, res.model.root.name, deadline=res.deadline)
        except OutputError as e:                # outlines past bounded work: say so
            row.update(status="error", ok=False, failure=f"output: {e}")
            row["compile_s"] = time.perf_counter() - t0
            return row
        row["parts"] = len(output.parts)
        row["holes"] = sum(lp.is_hole for p in output.parts for lp in p.loops)
        row["area"] = round(output.area, 9)
        if output.parts or output.engrave:
            row["bbox"] = [round(v, 9) for v in output.bounds()]
    row["compile_s"] = time.perf_counter() - t0
    if output is not None and cfg.get("render"):
        t1 = time.perf_counter()
        try:
            row["outputs"] = _render(output, cfg["render"], Path(cfg["out_dir"]), task["stem"],
                                     res.deadline)
        except Exception as e:                  # an impossible PNG size, a full disk
            row.update(status="error", ok=False, failure=f"render: {e}")
        row["render_s"] = time.perf_counter() - t1
    return row


def _render(output, suffixes: list[str], out_dir: Path, stem: str, deadline=None) -> list[str]:
    """Write each format as ``OUT_DIR/STEM.EXT`` (:func:`aidl_lang.output.writers.write.write_atomic`, as
    ``aidl render``: a reader never sees half a file; a writer that would end past the
    compile's ``deadline`` is refused, and nothing is written); returns the paths written."""
    from ..output.writers.write import write_atomic
    from ..output import CUT_FORMATS, encode, for_cutting
    # what a cutter reads has the program's `kerf` applied, as `aidl render` writes it
    cut = (for_cutting(output, deadline=deadline) if any(s in CUT_FORMATS for s in suffixes)
           else output)
    items = [(out_dir / f"{stem}{suffix}", encode(cut if suffix in CUT_FORMATS else output,
                                                  suffix, deadline=deadline))
             for suffix in suffixes]
    out_dir.mkdir(parents=True, exist_ok=True)
    written = []
    for path, data in items:
        write_atomic(path, data)
        written.append(str(path))
    return written
