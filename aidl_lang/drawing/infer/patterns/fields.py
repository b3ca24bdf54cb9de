"""``aidl import --infer``: grids of holes clipped to a field, written as one grid that
refills its field (docs/import.md, "What it recognises"): a hex grid clipped to a round or
rectangular field (:meth:`_Fields.hex_field`, a vent or a grille), a square-set grid clipped
to a round one (:meth:`_Fields.grid_field`, issue 103: a fan grille), each with its field's
size as a param.  The field half of :class:`~.infer._Part`: needs ``w``, ``p``, ``stats``,
``name``, ``at``, ``size_params`` and ``hole_block``.  Coordinates in the drawing's unit;
the results are program text."""
from __future__ import annotations

from ..params import _add0, _r
from ..shapes import EQUAL_TOL, Shape
from . import turns


class _Fields:
    def hex_field(self, depth: int, sh: Shape, base: str, hf: tuple) -> None:
        """A hex grid clipped to a round field (``hf`` from :func:`_hex_field`) or to a
        rectangular one (:func:`_hex_rect`) as one grid: every node of the lattice about the
        field's centre whose hole lies whole in the field, so that a new pitch, hole size or
        field keeps one grid filling its field; placed by its centre (:meth:`pos`); params
        ``_pitch``, ``_d`` and ``_field_d`` (``_field_width``, ``_field_height``)."""
        (cx, cy), pitch, shift, *field = hf
        hn = self.name(base + "s")
        sizes = self.size_params(hn, sh, True)
        p = self.p(hn + "_pitch", pitch, times=int(max(field) / pitch) + 1)
        if len(field) == 1:
            f = [self.p(hn + "_field_d", field[0], "the round field the holes lie whole in")]
        else:
            f = [self.p(hn + "_field_width", field[0], "the field the holes lie whole in"),
                 self.p(hn + "_field_height", field[1])]
        k = self.name(hn + "_k")
        par = "j % 2" if not shift else "(j + 1) % 2"
        x = f"(i + {par} / 2) * {p}"
        y = f"j * {p} * sqrt(3) / 2"
        d = sizes.get("diameter", _r(2 * sh.args["radius"]))
        ax, ay = self.at(cx, 0), self.at(cy, 1)
        w = self.w
        # lengths as points' norms: a bare number given for one (`--set holes_pitch=8`) is
        # in mm there, as in a point, so that range() still has a plain count
        big = ", ".join(f"norm(({v}, 0))" for v in f)
        big = big if len(f) == 1 else f"max({big})"
        w.emit(depth, f"{k} = floor({big} / norm(({p}, 0))) + 1     # nodes each way from "
                      f"the centre")
        w.emit(depth, f"for j in range(-{k}, {k} + 1) {{")
        w.emit(depth + 1, f"for i in range(-{k}, {k} + 1) {{")
        # the hole whole in the field: round, or across and up in a rectangle
        ifs = [f"norm(({x}, {y})) + {d} / 2 <= {f[0]} / 2 + 1e-7 mm"] if len(f) == 1 else \
            [f"abs({v}) + {d} / 2 <= {fk} / 2 + 1e-7 mm" for v, fk in ((x, f[0]), (y, f[1]))]
        for n, cond in enumerate(ifs):
            w.emit(depth + 2 + n, f"if {cond} {{")
        self.hole_block(depth + 2 + len(ifs), hn, sh, f"({_add0(ax, x)}, {_add0(ay, y)})",
                        sizes, turns.hex_nodes((cx, cy), pitch, shift))
        for n in reversed(range(len(ifs))):
            w.emit(depth + 2 + n, "}")
        w.emit(depth + 1, "}")
        w.emit(depth, "}")
        self.stats.patterns["hex grid in a " + ("round" if len(f) == 1 else "rectangular")
                            + " field"] += 1

    def grid_field(self, depth: int, sh: Shape, base: str, gf: tuple) -> None:
        """A square-set grid clipped to a round field (``gf`` from :func:`_grid_field`, a
        fan grille) as one grid: every node of the lattice about the field's centre whose
        hole lies whole in the field, so that a new pitch, hole size or field diameter keeps
        one grid filling its field; placed by its centre (:meth:`at`); params ``_pitch``
        (``_pitch_x``, ``_pitch_y``), ``_d`` and ``_field_d``."""
        (cx, cy), (dx, dy), half, field = gf
        hn = self.name(base + "s")
        sizes = self.size_params(hn, sh, True)
        times = int(field / min(dx, dy)) + 1
        if abs(dx - dy) <= EQUAL_TOL:
            px = py = self.p(hn + "_pitch", dx, times=times)
        else:
            px = self.p(hn + "_pitch_x", dx, times=times)
            py = self.p(hn + "_pitch_y", dy, times=times)
        f = self.p(hn + "_field_d", field, "the round field the holes lie whole in")
        k = self.name(hn + "_k")
        x = f"(i + 0.5) * {px}" if half[0] else f"i * {px}"
        y = f"(j + 0.5) * {py}" if half[1] else f"j * {py}"
        d = sizes.get("diameter", _r(2 * sh.args["radius"]))
        w = self.w
        least = f"min(norm(({px}, 0)), norm(({py}, 0)))" if px != py else f"norm(({px}, 0))"
        w.emit(depth, f"# a grid clipped to a round field, about its centre")
        w.emit(depth, f"{k} = floor(norm(({f}, 0)) / {least}) + 1     # nodes each way from "
                      f"the centre")
        w.emit(depth, f"for j in range(-{k}, {k} + 1) {{")
        w.emit(depth + 1, f"for i in range(-{k}, {k} + 1) {{")
        w.emit(depth + 2, f"if norm(({x}, {y})) + {d} / 2 <= {f} / 2 + 1e-7 mm {{")
        self.hole_block(depth + 3, hn, sh, f"({_add0(self.at(cx, 0), x)}, "
                                           f"{_add0(self.at(cy, 1), y)})",
                        sizes, turns.grid_nodes((cx, cy), (dx, dy), half))
        w.emit(depth + 2, "}")
        w.emit(depth + 1, "}")
        w.emit(depth, "}")
        self.stats.patterns["grid in a round field"] += 1
