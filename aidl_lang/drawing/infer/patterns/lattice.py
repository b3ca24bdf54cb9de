"""``aidl import --infer``: a row, column or grid of holes of one size and a staggered (hex)
grid, each written as loops over count and pitch params (docs/import.md, "What an edit
means": a row or grid is placed by its middle on a centre line, by its end member near an
edge, else by its middle from the nearer edge).  The lattice half of :class:`~.infer._Part`:
needs ``name``, ``p``, ``w``, ``at``, ``run_at``, ``origin``, ``surrounds``, ``shared``,
``size_params``, ``hole_block``, ``anchor``, ``stats``.  Coordinates in the drawing's unit;
the results are program text."""
from __future__ import annotations

import math

from ..params import _add0
from ..shapes import EQUAL_TOL, ROUND_TOL, Shape
from . import turns
from .groups import follows


class _Lattices:
    """Rows, grids and staggered grids of a part's holes (mixed into :class:`~.infer._Part`)."""

    def grid(self, depth: int, sh: Shape, base: str, gr: tuple, missing=()) -> None:
        """A row, column or grid (``gr`` from :func:`_grid`) as loops over count params:
        centred on the feature it surrounds or on the body where it is (``(i - (n - 1) /
        2) * pitch``), else from its first instance placed by the nearest edge or centre;
        one pitch param when the steps are equal both ways.  ``missing``: the nodes ``(i,
        j)`` of the lattice left out (:func:`_gapped_grid`), written as the loop's gap list
        (``if not (i == 2 and j == 1) { ... }``), so the pattern keeps its pitch and
        place."""
        x0, y0, dx, dy, nx, ny = gr
        mid = (x0 + dx * (nx - 1) / 2, y0 + dy * (ny - 1) / 2)
        around = self.surrounds(mid)
        hn = self.name({"Circle": "motor_holes"}.get(around, "screw_holes") if around
                       and sh.kind == "Circle" else base + "s")
        sizes = self.size_params(hn, sh, True)
        both = nx > 1 and ny > 1
        one = both and abs(dx - dy) <= EQUAL_TOL
        ox, oy, centred = self.origin(mid)
        body_c = self.anchor[0].center if self.anchor is not None else None
        out = []
        loops = []
        # equal steps both ways: one pitch (``one`` needs both counts above 1)
        shared = self.p(hn + "_pitch", dx, times=max(nx, ny)) if one else None
        for axis, (v0, step, n, var) in enumerate(((x0, dx, nx, "i"), (y0, dy, ny, "j"))):
            word = "_x" if axis == 0 else "_y"
            if n == 1:          # a row's line: its distance from its edge a param
                out.append(self.edge_param(hn + word, v0, axis, "its line"))
                continue
            if one:
                pitch = shared
            else:
                pitch = self.p(hn + ("_pitch_x" if axis == 0 else "_pitch_y") if both
                               else hn + "_pitch", step, times=n)
            cnt = self.p(hn + (("_cols" if axis == 0 else "_rows") if both else "_n"), n,
                         unit="")
            loops.append(f"for {var} in range({cnt}) {{")
            here = centred or (body_c is not None and abs(mid[axis] - body_c[axis]) <= EQUAL_TOL)
            if here:
                o = (ox, oy)[axis]
                term = f"({var} - ({cnt} - 1) / 2) * {pitch}"
                out.append(term if o == "0" else f"{o} + {term}")
            else:
                out.append(self.run_at(v0, v0 + (n - 1) * step, axis, var, cnt, pitch, step,
                                       hn + word))
        d = depth
        if follows(out):
            self.w.emit(d, f"# {'grid' if both else 'row'}: {follows(out)}"
                           + (f", about {self.shared(mid)}" if around else ""))
        for ln in loops:
            self.w.emit(d, ln)
            d += 1
        if missing:
            gaps = " or ".join(" and ".join(f"{v} == {k}" for v, k, n in
                                            (("i", i, nx), ("j", j, ny)) if n > 1)
                               for i, j in missing)
            many = len(missing) > 1
            self.w.emit(d, f"if not ({gaps}) {{     # the gap{'s' if many else ''}: "
                           f"{len(missing)} hole{'s' if many else ''} of the "
                           f"{'grid' if both else 'row'} left out, as drawn")
            d += 1
        self.hole_block(d, hn, sh, f"({out[0]}, {out[1]})", sizes, turns.grid(*gr))
        if missing:
            d -= 1
            self.w.emit(d, "}")
        for _ in loops:
            d -= 1
            self.w.emit(d, "}")
        kind = "grid" if both else "row"
        self.stats.patterns[kind + (" with a gap list" if missing else "")] += 1

    def stagger(self, depth: int, sh: Shape, base: str, st: tuple) -> None:
        """A staggered (hex) grid (``st`` from :func:`_stagger`) as one pattern: one pitch,
        the rows' step ``pitch * sqrt(3) / 2`` when it is a hex grid (else its own param),
        the counts params; each row centred on the body or the feature it surrounds where
        the grid is, else from its first hole."""
        xa, na, xb, nb, pitch, y0, dy, rows = st
        mid = ((xa + xa + (na - 1) * pitch) / 2, y0 + dy * (rows - 1) / 2)
        mid_b = (xb + xb + (nb - 1) * pitch) / 2
        hn = self.name(base + "s")
        sizes = self.size_params(hn, sh, True)
        p = self.p(hn + "_pitch", pitch, times=max(na, rows))
        if abs(dy - pitch * math.sqrt(3) / 2) <= ROUND_TOL / rows:
            step = f"{p} * sqrt(3) / 2"
        else:
            step = self.p(hn + "_row_pitch", dy, times=rows)
        cols = self.p(hn + "_cols", na, "in the first row, a row between one less or more" if
                      na != nb else "", unit="")
        nrows = self.p(hn + "_rows", rows, unit="")
        n_j = cols if na == nb else f"{cols} - j % 2" if nb < na else f"{cols} + j % 2"
        ox, oy, centred = self.origin(mid)
        body_c = self.anchor[0].center if self.anchor is not None else None

        def here(axis):
            return centred or (body_c is not None and abs(mid[axis] - body_c[axis]) <= EQUAL_TOL)
        # placed by its centre, the middle of its field (a grille's pitch or rows changed
        # keep it about that centre), not by its first hole
        if abs(mid_b - mid[0]) <= EQUAL_TOL:
            term = f"(i - ({n_j} - 1) / 2) * {p}"
            ex = _add0(ox if here(0) else self.at(mid[0], 0), term)
        else:
            sign = "+" if xb > xa else "-"
            ex = f"{self.at(xa, 0, ref=mid[0])} {sign} j % 2 * {p} / 2 + i * {p}"
        term = f"(j - ({nrows} - 1) / 2) * {step}"
        ey = _add0(oy if here(1) else self.at(mid[1], 1), term)
        self.w.emit(depth, f"for j in range({nrows}) {{")
        self.w.emit(depth + 1, f"for i in range({n_j}) {{")
        self.hole_block(depth + 2, hn, sh, f"({ex}, {ey})", sizes,
                        turns.stagger(xa, xb, pitch, y0, dy))
        self.w.emit(depth + 1, "}")
        self.w.emit(depth, "}")
        self.stats.patterns["staggered grid"] += 1
