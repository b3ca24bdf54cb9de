"""The result of a compile, :class:`Result`: the diagnostics, the solved values and what the
program made (parts, outputs, measures, the degrees of freedom), each made when first read;
:class:`NotCompiled` for a failed result asked for geometry.  Made by :mod:`.compiling`; the
records it reports in are :mod:`.values`.
"""
from __future__ import annotations

import math
import os
from collections.abc import Iterable
from pathlib import Path

from ..base.diagnostics import Diagnostic, DiagnosticSink
from ..base.limits import DEFAULT_BUDGET, Budget, now
from .values import (Layout, PartInfo, Value, _below, _geometry_names, _values, exact_bbox,
                     file_units, overlapping)

# `aidl check`, the language server and MCP's `check` look for redundant constraints (W0401)
# for at most this long, in blocks of at most this many rows sharing unknowns (`aidl check
# --dof` looks without these bounds; docs/solver.md, section 6)
REDUNDANCY_SECONDS = 1.0
REDUNDANCY_ROWS = 1000

class NotCompiled(RuntimeError):
    """Raised when a :class:`Result` whose program has errors is asked for geometry or an
    output (``parts``, ``to_svg``, ``write``, ...); read :attr:`Result.diagnostics` instead."""


class Result:
    """What :func:`compile` made.

    Attributes: ``ok`` (no error diagnostics), ``diagnostics`` (every
    :class:`~aidl_lang.base.diagnostics.Diagnostic`, errors and warnings, in the order found),
    ``sink`` (the :class:`~aidl_lang.base.diagnostics.DiagnosticSink`: diagnostics and source texts,
    for :meth:`diagnostics_json`), ``path`` (the file name diagnostics are located in),
    ``source`` (the program text), ``units`` and ``unit_scale`` (the file's length unit and its
    size in mm), ``compiled`` (the pipeline's :class:`~aidl_lang.pipeline.Compiled`: model,
    solve, drawing), ``not_searched`` (the user constraints :meth:`find_redundant` did not
    look at) and ``not_searched_why`` (why: ``"out of time"``, ``"too large"`` or both, joined
    by " and "; "" when all were searched), ``deadline`` (a
    :class:`~aidl_lang.base.limits.Deadline` bounding :attr:`output` and :attr:`description`;
    None, the default: the program's budget's seconds from each call)."""

    def __init__(self, compiled, path: str, source: str | None) -> None:
        self.compiled = compiled
        self.sink: DiagnosticSink = compiled.sink
        self.path = path
        self.source = source
        self.units, self.unit_scale = file_units(source or "")
        self._values: list[Value] | None = None
        self._sizes: list[Value] | None = None
        self._every: dict[bool, list[Value]] = {}   # with a template's internals (by sizes)
        self._output = None
        self._redundant: list[Diagnostic] | None = None
        self._sliding = None           # what the freedom left means (find_redundant)
        self.swept = None              # the last sweep() report (the forms' clean ranges)
        self.not_searched = 0          # user constraints find_redundant did not look at
        self.not_searched_why = ""     # why ("out of time", "too large")
        # the wall-time end (limits.Deadline) of the work read from the output after the
        # compile; None: a fresh budget from each call (_after_deadline)
        self.deadline = None
        # the Jupyter display (_display): made once, on the first display
        self._svg_done = False
        self._svg_text: str | None = None
        self._svg_problem: list[Diagnostic] | None = None
        self._names: tuple[dict, dict] | None = None     # measure's named geometry
        self._measure_renderer = None

    # ------------------------------------------------------------------ status
    @property
    def work(self) -> dict | None:
        """The work units the compile's stages spent: ``{"spent", "budget", "stages"}``
        (:meth:`aidl_lang.base.limits.Work.to_json`), the same on every machine and at any
        load; grows as outputs are made from the same budget; None before any stage ran."""
        w = self.compiled.work
        return w.to_json() if w is not None else None

    @property
    def ok(self) -> bool:
        """True when the program has no errors (warnings allowed) and solved."""
        return self.compiled.ok and self.compiled.drawing is not None

    @property
    def diagnostics(self) -> list[Diagnostic]:
        return list(self.sink.items)

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.sink.items if d.is_error]

    def diagnostics_json(self) -> list[dict]:
        """Every diagnostic in its JSON form (code, severity, message, span, labels, hint,
        suggestions, fix, rendered text): the ``diagnostics`` of ``aidl check --json``."""
        return [d.to_json(self.sink.sources) for d in self.sink.items]

    def _need(self, what: str):
        if self.compiled.model is None or self.compiled.solve is None \
                or not self.compiled.solve.converged:
            raise NotCompiled(f"no {what}: the program did not compile and solve "
                              f"({len(self.errors)} errors; see .diagnostics)")

    # ------------------------------------------------------------------ values
    @property
    def values(self) -> list[Value]:
        """Every named entity's solved values (see :class:`Value`), in model order: for each
        structure its frame ``origin`` and ``bbox``; for each named geometry its points
        (``center``, ``start``, ``end``, corners; a rectangle's ``center`` too) and scalars
        (``radius``, ``width``, ``height``, ...; with :meth:`sizes` also each radius's
        ``diameter`` and a rounded rectangle's ``corner_radius``); of a template instance
        the parameters its call gives and its members, not the template's own locals, and of a
        pattern's copy of one its geometry, not the parameters again (:meth:`values_matching`
        and :meth:`value` give a local by its name).  Raises :class:`NotCompiled` when the
        program did not solve."""
        self._need("values")
        if self._values is None:
            self._values = _values(self.compiled.model, self.unit_scale, self.units)
        return self._values

    def sizes(self) -> list[Value]:
        """:attr:`values` with the sizes a maker reads too, each after its geometry's own:
        a circle's or arc's ``diameter`` (after its ``radius``) and a rounded rectangle's
        ``corner_radius`` (``corner_radius.bottom_left``, ... for ``corner_radii``), in the
        file's units (the MCP ``values`` tool lists these).  Raises :class:`NotCompiled`."""
        self._need("values")
        if self._sizes is None:
            self._sizes = _values(self.compiled.model, self.unit_scale, self.units, True)
        return self._sizes

    def values_matching(self, names: Iterable[str] = (), sizes: bool = False) -> list[Value]:
        """The :attr:`values` (with ``sizes``: :meth:`sizes`) whose name is one of ``names``
        or below one of them (a dotted prefix: ``plate.corner`` covers
        ``plate.corner[0].h.center``); all of them when ``names`` is empty.  The root
        structure's name may be left out.  Asked by name, a template instance's own locals
        are given too (``plate.h.d``), which the whole listing leaves out."""
        names = [n.strip() for n in names if n.strip()]
        if not names:
            return list(self.sizes() if sizes else self.values)
        vals = self._all(sizes)          # a name asked for is given, a template's local too
        root = self.compiled.model.root.name + "."
        wanted = set()
        for n in names:
            # `X.bb`, as the language names a box, is listed as `X.bbox` (run fu: "no value
            # matches" for the member the program reads)
            for m in (n, n[:-3] + ".bbox") if n.endswith(".bb") else (n,):
                wanted.add(m)
                if not m.startswith(root):
                    wanted.add(root + m)
        return [v for v in vals if any(_below(v.name, w) for w in wanted)]

    def value(self, name: str) -> Value:
        """The one value called ``name`` (exactly; the root's name may be left out).  Raises
        :class:`KeyError` (with the nearest names) when there is none."""
        for v in self._all(False):
            if v.name == name or v.name == f"{self.compiled.model.root.name}.{name}":
                return v
        from ..base.diagnostics import did_you_mean
        near = did_you_mean(name, [v.name for v in self.values])
        raise KeyError(f"no value `{name}`" + (f"; did you mean {', '.join(near)}?" if near else ""))

    def freedom(self, detail: bool = False, deadline: float | None = None) -> dict:
        """Degrees of freedom left after solving: ``{"dof": N or None (not counted: too
        large, or out of time), "text": "fully constrained" | "N degrees of freedom left,
        ..."}``; with ``detail``, ``"structures"``: per structure ``{"structure", "unknowns",
        "dof", "floating"}`` (entities still free to move; costs a null-space computation;
        ``dof`` None and ``"not_counted"`` the reason for a structure not counted).
        ``deadline`` (:func:`aidl_lang.base.limits.now`: CPU seconds) bounds the count; by default
        the program's budget from now (15 s of CPU time), so no call runs unbounded (issue 48).  Raises
        :class:`NotCompiled`."""
        self._need("degrees of freedom")
        from ..solver.diagnosis.freedom import degrees_of_freedom, freedom_text
        if deadline is None:
            budget = self.compiled.deadline.budget if self.compiled.deadline else DEFAULT_BUDGET
            deadline = now() + budget.backstop
        from ..base.limits import is_out_of_memory, memory_text
        try:
            dofs = degrees_of_freedom(self.compiled.solve.solver, floating=detail,
                                      deadline=deadline)
        except (MemoryError, SystemError) as ex:
            if not is_out_of_memory(ex):
                raise
            dofs = None
        if dofs is None:          # said once the count's frames (and what they held) are gone
            import gc
            gc.collect()
            why = f"the count ran out of memory: {memory_text()}"
            return {"dof": None, "text": f"degrees of freedom not counted ({why})"} | (
                {"structures": [], "not_counted": why} if detail else {})
        counted = all(d.rank >= 0 for d in dofs)
        doc: dict = {"dof": sum(max(0, d.dof) for d in dofs) if counted else None,
                     "text": freedom_text(dofs, self.sliding())}
        if detail:
            doc["structures"] = [{"structure": d.structure.path, "unknowns": d.unknowns,
                                  "dof": d.dof if d.rank >= 0 else None,
                                  "floating": list(d.floating)}
                                 | ({"not_counted": d.why} if d.rank < 0 else {})
                                 for d in dofs]
        return doc

    def sliding(self):
        """What the freedom left means (:class:`~aidl_lang.solver.diagnosis.sliding.Sliding`: the parts
        whose whole body may move, harmless, and the features that can slide relative to
        their part, ``W0404``), or None for a model too large to search.  Raises
        :class:`NotCompiled`."""
        self._need("degrees of freedom")
        if self._sliding is None:
            from ..pipeline import MAX_SLIDING_UNKNOWNS
            from ..solver.diagnosis.sliding import sliding
            solver = self.compiled.solve.solver
            if int(solver.free.sum()) <= MAX_SLIDING_UNKNOWNS:
                self._sliding = sliding(solver)
        return self._sliding

    def sweep(self, budget: float | Budget | None = None, points: int | None = None,
              seconds: float | None = None):
        """This program checked across its params' ranges (``aidl check --sweep``, MCP
        ``check`` with ``sweep: true``; docs/language.md, "Sweeping the ranges": the declared
        ``min=``/``max=``, else the span the studio's slider gives the param): a
        :class:`~aidl_lang.params.sweep.SweepReport` whose ``findings`` (``W0110``, located at the
        ``param`` lines) name each value where the design stops compiling, a part changes
        topology or a new warning appears, with the largest clean sub-range.  ``budget``: a
        factor or :class:`~aidl_lang.base.limits.Budget` for each compile, scaling the sweep's work
        budget (:data:`aidl_lang.params.sweep_plan.WORK`: the same answer on any machine), and in
        CPU seconds the whole sweep's outer guard (``seconds`` overrides it); ``points``: the Latin
        hypercube's size (default :data:`aidl_lang.params.sweep.LHS_POINTS`).  The report is kept
        as :attr:`swept`: a notebook form made from this result
        (:func:`aidl_lang.notebook.form`) offers only its clean ranges.  Raises
        :class:`TypeError` for a result with no source text."""
        from ..params.sweep import LHS_POINTS, sweep
        if self.source is None:
            raise TypeError("sweep() needs the program's source text")
        self.swept = sweep(self.source, self.path, budget,
                           LHS_POINTS if points is None else points, seconds)
        return self.swept

    def find_redundant(self, seconds: float | None = REDUNDANCY_SECONDS,
                       max_rows: int | None = REDUNDANCY_ROWS,
                       deadline: float | None = None) -> list[Diagnostic]:
        """Look for constraints that others already imply and add each as a ``W0401`` warning
        to :attr:`diagnostics` (what ``aidl check`` does; docs/solver.md §6); returns those
        warnings.  ``seconds`` bounds the search (None: no bound), and so does ``deadline``
        (a :func:`aidl_lang.base.limits.now` value: the end of the run's budget in CPU seconds), ``max_rows``
        the blocks of rows it ranks; the user constraints not looked at (out of time, or in
        a block too large) are counted in :attr:`not_searched`.  Runs once per result; []
        when the program did not solve.  A search that runs out of memory adds one located
        ``E0304`` instead (and returns it)."""
        if self._redundant is None:
            self._redundant = []
            if self.compiled.ok and self.compiled.solve is not None:
                from ..base.limits import is_out_of_memory
                from ..pipeline import out_of_memory_sink, report_redundancies, report_sliding
                before = len(self.sink.items)
                why: set = set()
                try:
                    self.not_searched = report_redundancies(self.sink, self.compiled.solve,
                                                            seconds, max_rows, deadline, why)
                    self.not_searched_why = " and ".join(sorted(why))
                    self._sliding = report_sliding(self.sink, self.compiled.solve)
                    failed = False
                except (MemoryError, SystemError) as ex:
                    if not is_out_of_memory(ex):
                        raise
                    failed = True
                if failed:        # said once the search's frames (and what they held) are gone
                    self.not_searched_why = "out of memory"
                    for d in out_of_memory_sink(self.path, self.source,
                                                "the redundancy search").items:
                        self.sink.add(d)
                self._redundant = list(self.sink.items[before:])
        return list(self._redundant)

    def _all(self, sizes: bool) -> list[Value]:
        """Every value, a template instance's own locals too (:func:`.values._values`'s
        ``internals``)."""
        self._need("values")
        if sizes not in self._every:
            self._every[sizes] = _values(self.compiled.model, self.unit_scale, self.units,
                                         sizes, internals=True)
        return self._every[sizes]

    # ------------------------------------------------------------------ measuring
    def measure(self, a: str, b: str) -> dict:
        """What lies between the named entities ``a`` and ``b`` (names as :attr:`values`
        gives them: a point ``plate.bore.c.center``, a line or a rectangle's edge
        ``plate.body.top``, a circle ``plate.bore.c``, any shape, a structure or part
        ``gear_a``), in mm and degrees, exact (to 1e-9 mm):

        ``{"a": {name, kind}, "b": ..., "distance", "points": [[x, y], [x, y]]}``: the
        smallest distance between them (points; lines as segments; shapes and parts by their
        outlines) and where; ``center_distance`` when both have a centre (a point, a circle,
        an arc; a structure's or part's: its own first circle, a gear's ``hub``, else its
        first shape's centre that has one, else the centre of its outline's box, as
        ``part.center`` reads it: a Polygon's, an imported sheet's part of lines; else its
        origin), and ``centers`` the two;
        ``angle`` between two lines (0 to 180 degrees, from ``a``'s direction to ``b``'s);
        ``clearance`` and ``contact`` between two closed shapes or parts
        (:func:`aidl_lang.output.part.measure.gaps.clearance`: ``apart`` with the gap, ``touching``
        0, ``overlapping`` negative: how deep one runs into the other, and
        ``overlap_area`` mm², exact for outlines of lines, arcs and circles, else an estimate
        with ``overlap_area_within`` its bound).  An assembly (a structure with no outline
        of its own) is measured as its parts together.  Raises :class:`NotCompiled`, and :class:`KeyError` for a
        name that is none of these: ``args`` (the message, with the nearest names; ``"a"``
        or ``"b"``)."""
        self._need("measure")
        from ..output.part.measure import gaps as G
        found = []
        for which, name in (("a", a), ("b", b)):
            try:
                found.append(self._entity(name))
            except KeyError as e:
                raise KeyError(e.args[0], which) from None
        ea, eb = found
        d, p, q = G.gap(ea["pieces"], eb["pieces"])
        out: dict = {"a": {"name": a, "kind": ea["kind"]}, "b": {"name": b, "kind": eb["kind"]},
                     "unit": "mm", "distance": d, "points": [list(p), list(q)]}
        if ea.get("center") is not None and eb.get("center") is not None:
            out["center_distance"] = math.dist(ea["center"], eb["center"])
            out["centers"] = [list(ea["center"]), list(eb["center"])]
        if ea["kind"] == "line" and eb["kind"] == "line":
            (p0, p1), (q0, q1) = ea["ends"], eb["ends"]
            t = math.atan2(q1[1] - q0[1], q1[0] - q0[0]) - math.atan2(p1[1] - p0[1],
                                                                     p1[0] - p0[0])
            out["angle"] = abs(math.degrees(math.remainder(t, 2 * math.pi)))
        if ea.get("loops") and eb.get("loops"):
            c = G.clearance(ea["loops"], eb["loops"])
            out["clearance"], out["contact"] = c["clearance"], c["contact"]
            for k in ("overlap_area", "overlap_area_within"):
                if k in c:
                    out[k] = c[k]
            out["points"] = c["points"]
        sunk = self._sinks_at(a, b)
        if sunk:
            out["sinks"] = sunk
        return out

    def _sinks_at(self, *names: str) -> list[dict]:
        """The countersinks and counterbores (issue 102) on the holes ``names`` name (a
        hole's Circle, or a structure or part holding it), as the parts list gives them."""
        d = getattr(self.compiled, "drawing", None)
        out = []
        for sk in getattr(d, "sinks", None) or ():
            if any(sk.hole == n or sk.hole.startswith(n + ".") for n in names):
                item = {"kind": sk.kind, "hole": sk.hole, "center": list(sk.center),
                        "hole_d": sk.hole_d, "diameter": sk.diameter,
                        "depth": sk.cone_depth()}
                if sk.kind == "countersink":
                    item["angle"] = math.degrees(sk.angle)
                out.append(item)
        return out

    def _entity(self, name: str) -> dict:
        """``{"kind", "pieces", "center"?, "ends"?, "loops"?}`` of the entity named ``name``
        (see :meth:`measure`).  Raises :class:`KeyError`."""
        from ..output.part.measure import gaps as G
        geo, structs = self._named_geometry()
        points = {v.name: v for v in self._all(False) if v.kind == "point"}
        root = self.compiled.model.root.name
        if all(name not in d for d in (geo, structs, points)) and any(
                f"{root}.{name}" in d for d in (geo, structs, points)):
            name = f"{root}.{name}"         # the root structure's name may be left out
        g = geo.get(name)
        if g is not None:
            return self._geometry_entity(g)
        if name in points:
            p = tuple(points[name].mm)
            return {"kind": "point", "pieces": [("L", p, p)], "center": p}
        s = structs.get(name)
        if s is not None:
            part = next((pt for pt in self.output.parts if pt.name == s.path), None)
            loops = part.loops if part is not None else [
                lp for gg in s.geometry if not gg.construction
                for lp in self._renderer().loops_of(gg)]
            if not loops and part is None:     # an assembly: the parts inside it, each a region
                inner = [pt for pt in self.output.parts if pt.name.startswith(s.path + ".")]
                if not inner:
                    raise KeyError(f"`{name}` has no outline of its own and no parts inside "
                                   "it: nothing to measure; measure a shape or part in it")
                loops = [pt.loops for pt in inner]
                part = False
            own = [gg for gg in s.geometry if not gg.construction
                   and ("center" in gg.points or "top_right" in gg.points)]
            first = next((gg for gg in own if gg.kind == "Circle"), own[0] if own else None)
            flat = [lp for r in G.regions(loops) for lp in r]
            segs = [sg for lp in flat for sg in lp.segments]
            if first is not None:
                center = self._geometry_entity(first)["center"]
            elif segs:       # an outline of lines and curves (a Polygon, an import): its box's
                x0, y0, x1, y1 = exact_bbox(segs)       # centre, as `part.center` reads it
                center = ((x0 + x1) / 2, (y0 + y1) / 2)
            else:
                center = next((tuple(v.mm) for v in self._all(False)
                               if v.name == name + ".origin"), None)
            kind = "assembly" if part is False else "part" if part is not None else "structure"
            return {"kind": kind, "loops": loops, "pieces": G.pieces(segs), "center": center}
        from ..base.diagnostics import did_you_mean
        every = sorted(set(geo) | set(structs) | set(points))
        near = did_you_mean(name, every, 3)
        raise KeyError(f"nothing is named `{name}`"
                       + (f"; did you mean {', '.join(f'`{n}`' for n in near)}?" if near
                          else ""))

    def _renderer(self):
        if self._measure_renderer is None:
            from ..output.part.build.booleans import Renderer
            self._measure_renderer = Renderer(self.compiled.model)
        return self._measure_renderer

    def _geometry_entity(self, g) -> dict:
        """The entity of geometry ``g`` (model frame, mm): :func:`..output.part.measure.gaps.entity`."""
        from ..output.part.measure import gaps as G
        return G.entity(g, self._renderer())

    def _named_geometry(self) -> tuple[dict, dict]:
        """``({name: geometry}, {name: structure})`` named as :attr:`values` names them
        (a rectangle's edges ``body.top`` too)."""
        if self._names is not None:
            return self._names
        from .values import named_structures
        geo: dict = {}
        structs: dict = {}
        for base, s in named_structures(self.compiled.model):
            if base:
                structs[base] = s
            prefix = base + "." if base else ""
            for n, g in _geometry_names(s):
                geo[prefix + n] = g
                for pn, sub in g.parts.items():
                    if getattr(sub, "kind", None) in ("Line", "Point", "Circle", "Arc"):
                        geo[f"{prefix}{n}.{pn}"] = sub
        self._names = (geo, structs)
        return self._names

    # ------------------------------------------------------------------ outputs
    @property
    def output(self):
        """The exact output model (:class:`~aidl_lang.output.part.part.Output`: lines, arcs and
        circles per part, mm) every writer reads.  Raises :class:`NotCompiled`, and
        :class:`~aidl_lang.output.part.part.OutputError` when the outlines cannot be recovered
        within bounded work (thousands of curves on top of each other)."""
        return self._built(None)

    def _built(self, deadline):
        """:attr:`output`, built (once) within ``deadline`` (None: :meth:`_after_deadline`)."""
        self._need("output")
        if self.compiled.drawing is None:
            raise NotCompiled("no output: the solved model failed the extent check (E0305)")
        if self._output is None:
            from ..output import build
            self._output = build(self.compiled.drawing, self.compiled.model.root.name,
                                 deadline=deadline or self._after_deadline())
        return self._output

    def _after_deadline(self):
        """The :class:`~aidl_lang.base.limits.Deadline` of the output, the parts list and the
        description: :attr:`deadline` when set (``aidl check --describe`` sets the compile's
        own, one budget for the whole command), else the program's budget's seconds from now
        (past it: :class:`~aidl_lang.output.part.part.OutputError`, a located ``E0304``)."""
        if self.deadline is not None:
            return self.deadline
        from ..base.limits import Deadline
        budget = self.compiled.deadline.budget if self.compiled.deadline else DEFAULT_BUDGET
        return Deadline.starting(budget)

    @property
    def description(self) -> dict:
        """What the final part is, as JSON-ready data (``aidl check --describe --json``): for
        each part its outline's kind, size and box, each opening's kind (circle ``d``, slot
        ``w`` x ``l``, rectangle, polygon ``n``, outline), centre and size, its engravings
        (text with its string) and place, its copies and symmetries; mm and degrees
        (:func:`aidl_lang.output.checks.reports.describe.describe`): a part of the same shape as one
        described, with nothing of its own, is one of its ``copies`` (name and box).  Raises
        :class:`NotCompiled`, and :class:`~aidl_lang.output.part.part.OutputError` past the
        wall-time budget (:meth:`_after_deadline`)."""
        from ..output.checks.reports.describe import describe
        deadline = self._after_deadline()
        return describe(self._built(deadline), deadline)

    def describe(self) -> str:
        """:attr:`description` as compact text, one line per feature, e.g. ``circle d=6 at
        (10, 5)`` (``aidl check --describe``).  Raises :class:`NotCompiled`."""
        from ..output.checks.reports.describe import describe_text
        return describe_text(self.description)

    @property
    def parts(self) -> list[PartInfo]:
        """The parts of the final shape (see :class:`PartInfo`).  Raises :class:`NotCompiled`."""
        out = []
        for p in self.output.parts:
            bbox = exact_bbox(seg for lp in p.loops for seg in lp.segments)
            inner = sum(1 for lp in p.loops if lp.area < 0)
            out.append(PartInfo(p.name, p.kind, tuple(float(v) for v in bbox), float(p.area),
                                inner, len(p.loops)))
        return out

    @property
    def fit(self) -> dict:
        """The fit check of the assembled product (for a program whose parts are placed with
        ``Place``; the data of its ``W0517``/``W0518``): ``{"checked": bool, "collisions":
        [{"a", "b", "volume" mm^3, "depth" mm, "box" [x0, y0, z0, x1, y1, z1] mm}],
        "floating": [{"part", "nearest", "gap" mm}]}``; ``checked`` false (and the lists
        empty) when nothing is placed or the check did not run.  Overlaps an
        ``AllowOverlap`` accepts and gaps a template makes by design are not listed.  Raises
        :class:`NotCompiled`."""
        self._need("fit")
        found = getattr(self.compiled.drawing, "fit", None)
        if not isinstance(found, dict):
            return {"checked": False, "collisions": [], "floating": []}
        return {"checked": True, "collisions": list(found["collisions"]),
                "floating": list(found["floating"])}

    def overlaps(self) -> list[dict]:
        """The parts that lie over each other where the program draws them, flat (2D, their
        true outlines: :func:`.values.overlapping`): ``[{"a", "b", "area" mm², "box" [x0,
        y0, x1, y1] mm}]``, ``[]`` when none do: a sheet drawn by the program (or imported)
        cuts as drawn only then (a machine file refuses it: E0501).  Not :attr:`fit`, the
        assembled product's 3D collisions; :meth:`Layout.overlaps` for a cutting layout.
        Raises :class:`NotCompiled`."""
        self._need("overlaps")
        return overlapping(self.output.parts)

    def encode(self, fmt: str, kerf: float | None = None, **options) -> bytes:
        """The output in format ``fmt`` (``svg``, ``dxf``, ``pdf``, ``png``, ``stl``, ``3mf``,
        ``step``, ``glb``; a leading dot is allowed) as bytes, as ``aidl render`` writes it: the
        cutting formats (SVG, DXF, PDF, PNG) with every cut offset by half the kerf — ``kerf`` in mm, ``None`` for
        the program's own ``kerf`` statements, 0 for none; STL, 3MF and STEP are the designed
        solid.  ``options``: those of :class:`~aidl_lang.output.writers.Options` (``show``,
        ``style``, ``dpi``, ``width``, ``thickness`` mm, ``margin`` mm, ``assembled``: the
        3D formats with every part placed by its ``Place``, PNG a picture of that; ``page``:
        the PDF tiled over paper, ``"A4"``, ``"Letter-landscape"``, ...).  Raises
        :class:`ValueError` for an unknown format, :class:`NotCompiled`,
        :class:`~aidl_lang.output.part.part.MissingDependency` (a format's library is not
        installed) and :class:`~aidl_lang.output.part.part.OutputError` (also a kerf larger than a
        feature, naming the part)."""
        from ..output import CUT_FORMATS, FORMATS, Options, encode, for_cutting
        suffix = "." + fmt.lower().lstrip(".")
        if suffix not in FORMATS:
            raise ValueError(f"unknown output format `{fmt}`; use one of "
                             + ", ".join(sorted(f[1:] for f in FORMATS)))
        cutting = suffix in CUT_FORMATS and not options.get("assembled")
        out = for_cutting(self.output, kerf) if cutting else self.output
        return encode(out, suffix, Options(**options))

    def layout(self, sheet: tuple[float, float] = (600.0, 400.0), gap: float = 3.0,
               rotate: tuple[float, ...] | None = (0.0, 90.0), kerf: float | None = None,
               nest_time: int = 0) -> Layout:
        """The cutting layout of the parts (``aidl render --layout sheet``): every solid part
        placed once, flat, without overlap, on sheets of ``sheet`` = (width, height) mm, at
        least ``gap`` mm from each other and from the edges, turned only by the angles of
        ``rotate`` (degrees; None: any angle), by true-shape nesting (the ``layout`` extra);
        the cuts offset by half the kerf (``kerf`` mm as for :meth:`encode`: None for the
        program's own).  ``nest_time``: seconds the nesting may spend improving its first
        packing, added to the program's wall-time budget, which bounds the nesting.  Raises
        :class:`NotCompiled`, :class:`~aidl_lang.output.part.part.MissingDependency` (no
        ``spyrrow``) and :class:`~aidl_lang.output.part.part.OutputError` (a part larger than the
        sheet, a kerf larger than a feature, a nesting that would end past the budget)."""
        from ..output import for_cutting
        from ..output.fabrication.layout import place, plan
        deadline = self.compiled.deadline
        if deadline is not None and nest_time:
            from ..base.limits import Deadline
            from ..output.fabrication.layout import nest_cpu_seconds
            from ..base.limits import seconds_as_work
            deadline = Deadline(deadline.at + nest_cpu_seconds(nest_time), deadline.budget,
                                work=deadline.work)
            deadline.work.limit += seconds_as_work(nest_cpu_seconds(nest_time))
        cut = for_cutting(self.output, kerf, deadline, apart=True)   # pieces apart: whole
        where = plan(cut, sheet, gap, rotate, nest_time, deadline=deadline)
        flat, dropped = place(cut, where, sheet)
        solid, _ = place(self.output, where, sheet)
        return Layout(flat, solid, sheet, dropped, where)

    def to_svg(self, kerf: float | None = None, **options) -> str:
        """The SVG text (mm page; ``kerf`` and ``options`` as for :meth:`encode`)."""
        return self.encode("svg", kerf, **options).decode()

    def to_png(self, kerf: float | None = None, **options) -> bytes:
        """PNG bytes (``dpi``, or ``width`` in pixels; neither: 96 dpi, the longer side at
        most 2000 pixels; needs the ``png`` extra;
        ``kerf`` as for :meth:`encode`)."""
        return self.encode("png", kerf, **options)

    def to_dxf(self, kerf: float | None = None) -> str:
        """The DXF text (R2010, mm, ``cut``/``engrave`` layers; ``kerf`` as for
        :meth:`encode`: the program's own unless given)."""
        return self.encode("dxf", kerf).decode()

    def write(self, path: str | os.PathLike, follow_symlinks: bool = False,
              force: bool = False, kerf: float | None = None, **options) -> Path:
        """Write the output to ``path``, the format by its extension, with the rules of
        ``aidl render`` (docs/outputs.md, "Writing files"): never over the program itself,
        never a directory, a symlink refused unless ``follow_symlinks`` (then written
        through), a read-only file refused unless ``force``, a FIFO, device, socket or
        directory always refused and left as it is
        (:class:`~aidl_lang.output.writers.write.NotRegularFile`), written to a temporary file
        beside it and renamed, a new file gets the umask's permissions.  Returns the path.
        Raises :class:`~aidl_lang.output.writers.write.WriteError`, :class:`NotCompiled` and the errors of :meth:`encode`."""
        from ..output.writers.write import check_output_path, write_atomic
        out = check_output_path(path, self.path, follow_symlinks, force)
        data = self.encode(out.suffix, kerf, **options)
        write_atomic(out, data, follow_symlinks)
        return out

    def to_json(self, values: Iterable[str] | None = None) -> dict:
        """``{"ok", "diagnostics", "units", "values"?, "parts"?}``: ``values`` (those matching
        ``values``, see :meth:`values_matching`) and ``parts`` only when the program solved."""
        doc: dict = {"ok": self.ok, "diagnostics": self.diagnostics_json(), "units": self.units}
        if self.ok:
            if values is not None:
                doc["values"] = [v.to_json() for v in self.values_matching(values)]
            doc["parts"] = [p.to_json() for p in self.parts]
        return doc

    def __repr__(self) -> str:
        return f"<aidl Result {self.path} ok={self.ok} diagnostics={len(self.sink.items)}>"

    # ------------------------------------------------------------------ Jupyter
    def _repr_svg_(self) -> str | None:
        """The drawing as SVG text for Jupyter (what ``aidl render -o x.svg`` writes: the
        ``preview`` style, mm page, the program's kerf); None when the program has errors or
        the output could not be made (the ``text/html`` of :meth:`_repr_mimebundle_` then
        lists why).  Made on the first call and kept."""
        return self._display()[0]

    def _repr_mimebundle_(self, include=None, exclude=None) -> dict:
        """What Jupyter shows (docs/notebook.md): ``image/svg+xml``, the drawing (as
        :meth:`_repr_svg_`; left out when the program has errors); ``text/html``, the
        drawing with every diagnostic listed under it (severity, code, ``line:column``,
        message; HTML-escaped), or, for a program with errors, the located errors (with the
        source line and caret) instead of a drawing; ``text/plain``, one summary line
        (:meth:`summary`).  The SVG is made once, on the first display, and kept."""
        svg, problem = self._display()
        bundle = {"text/plain": self.summary(), "text/html": _html(self, svg, problem)}
        if svg is not None:
            bundle["image/svg+xml"] = svg
        return bundle

    def summary(self) -> str:
        """One line: the file, ``ok`` with the number of parts and the drawing's size (mm)
        once it was drawn for a display, or the number of errors and the first one located
        (``1 error; first: 3:5 E0101 ...``), or ``not drawn:`` and why (a located ``E0304``
        for a drawing past its bounded work); then the number of warnings."""
        errors = [d for d in self.sink.items if d.is_error]
        warnings = [d for d in self.sink.items if d.severity == "warning"]
        if errors:
            first = errors[0]
            at = f"{first.span.line}:{first.span.col} " if first.span else ""
            text = (f"{len(errors)} error{'s' if len(errors) != 1 else ''}; first: {at}"
                    f"{first.code} {first.message}")
            if len(text) > 160:
                text = text[:157] + "..."
        elif self._svg_done and self._svg_problem:
            first = self._svg_problem[0]
            at = f"{first.span.line}:{first.span.col} " if first.span else ""
            text = f"not drawn: {at}{first.code} {first.message}"
            if len(text) > 160:
                text = text[:157] + "..."
        elif self._svg_done:
            bx = [p.bbox for p in self.parts]
            w = max(b[2] for b in bx) - min(b[0] for b in bx) if bx else 0.0
            h = max(b[3] for b in bx) - min(b[1] for b in bx) if bx else 0.0
            text = f"ok, {len(bx)} part{'s' if len(bx) != 1 else ''}, {w:g} x {h:g} mm"
        else:
            text = "ok" if self.ok else "not drawn"
        if warnings:
            text += f", {len(warnings)} warning{'s' if len(warnings) != 1 else ''}"
        return f"aidl {self.path}: {text}"

    def _display(self) -> tuple[str | None, list | None]:
        """``(svg, problem)`` made once: the SVG text, or None and the diagnostics that say
        why (the result's errors, or one for an output that could not be made: a located
        ``E0304`` for bounded work that ran out)."""
        if not self._svg_done:
            self._svg_done = True
            if self.errors:
                self._svg_problem = self.errors
            else:
                from ..output import OutputError
                try:
                    self._svg_text = self.to_svg()
                except NotCompiled as e:
                    self._svg_problem = [Diagnostic("E0305", str(e), None)]
                except OutputError as e:
                    self._svg_problem = _output_problem(e)
        return self._svg_text, self._svg_problem


def _output_problem(e: Exception) -> list[Diagnostic]:
    """The diagnostic shown instead of a drawing that could not be made: the located
    ``E0304`` ``aidl render`` prints for bounded work that ran out, else the message."""
    budget = getattr(e, "budget", None)
    if budget is not None:
        from ..pipeline import report_out_of_budget
        sink = DiagnosticSink()
        report_out_of_budget(sink, budget)
        return list(sink.items)
    return [Diagnostic("E0304", str(e), None)]


def _html(result: Result, svg: str | None, problem: list[Diagnostic] | None) -> str:
    """The ``text/html`` of :meth:`Result._repr_mimebundle_`: the drawing (as an ``<img>`` of
    the SVG, so that several results on one page share no element ids), then a list of the
    diagnostics (``severity[CODE] line:col message``), or the located errors when there is no
    drawing; every text escaped."""
    import base64
    from html import escape
    from ..base.diagnostics import render_text
    parts = [f'<div class="aidl-result"><div style="font-family:monospace">'
             f'{escape(result.summary())}</div>']
    if svg is not None:
        data = base64.b64encode(svg.encode("utf-8")).decode("ascii")
        parts.append(f'<img style="max-width:100%;background:white" alt="{escape(result.path)}" '
                     f'src="data:image/svg+xml;base64,{data}">')
    if problem is not None:
        sources = result.sink.sources
        parts.append('<pre style="color:#b00">'
                     + escape("\n\n".join(render_text(d, sources) for d in problem))
                     + "</pre>")
    shown = [d for d in result.sink.items if problem is None or d not in problem]
    if shown:
        rows = []
        for d in shown:
            at = f"{d.span.line}:{d.span.col}" if d.span else "-"
            rows.append(f"<li><code>{escape(d.severity)}[{escape(d.code)}]</code> "
                        f"<code>{escape(at)}</code> {escape(d.message)}</li>")
        parts.append('<ul class="aidl-diagnostics">' + "".join(rows) + "</ul>")
    return "".join(parts) + "</div>"


