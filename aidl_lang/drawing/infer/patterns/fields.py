"""``aidl import --infer``: grids of holes clipped to a field, written as one grid that
refills its field (docs/import.md, "What it recognises"): a hex grid clipped to a round or
rectangular field (:meth:`_Fields.hex_field`, a vent or a grille), a square-set grid clipped
to a round one (:meth:`_Fields.grid_field`, issue 103: a fan grille), each with its field's
size as a param; a perforated plate's square-set field over most of the plate
(:meth:`_Fields.perforated`, issue 103), the plate less its margin.  The field half of :class:`~.infer._Part`: needs ``w``, ``p``, ``stats``,
``name``, ``at``, ``size_params`` and ``hole_block``.  Coordinates in the drawing's unit;
the results are program text."""
from __future__ import annotations

from ..params import _add0, _r
from ..shapes import EQUAL_TOL, Shape
from ...write.units import UNIT
from ...write.writer import _num
from . import turns
from .find import _roundest


PERFORATED_MIN = 5      # holes each way, at least, of a perforated plate's field
PERFORATED_MARGIN = 3   # pitches: a perforated field's outer holes nearer the edges than this
PERFORATED_SHARE = 2 / 3  # of the plate's width and height, at least, its holes span


def _perforated(body, c, spans: tuple, pitch: float, d: float) -> bool:
    """Whether holes ``d`` across (mm) on ``pitch`` about ``c``, spanning ``spans`` (across
    and up, outer edge to outer edge), are a perforated plate's field on ``body``: an upright
    rectangle centred on them, the holes spanning :data:`PERFORATED_SHARE` of it each way,
    a margin left (wider than the web between two holes, within :data:`PERFORATED_MARGIN`
    pitches); a fan's vent field on a panel spans less of it, a grid laid out from the
    plate's edges (holes half a pitch in) leaves no margin."""
    if body.kind not in ("Rectangle", "RoundedRectangle") or \
            abs(body.args.get("rotation", 0.0)) > EQUAL_TOL:
        return False
    for axis, key in ((0, "width"), (1, "height")):
        size = body.args[key]
        margin = (size - spans[axis]) / 2
        if abs(c[axis] - body.center[axis]) > EQUAL_TOL or spans[axis] < PERFORATED_SHARE * size \
                or not pitch - d + EQUAL_TOL < margin < PERFORATED_MARGIN * pitch:
            return False
    return True


def _margin(lo: float, hi: float) -> float:
    """The roundest margin (:func:`~.find._roundest`) in ``(lo, hi]`` (mm): of the margins
    that keep exactly the holes drawn, the one a maker would have dimensioned."""
    return _roundest(lo + 1e3 * EQUAL_TOL, hi + 1e3 * EQUAL_TOL)


def _margin_params(self, hn: str, got: list, ranges: list) -> tuple[str, str, list]:
    """The margin params of a perforated field (``holes_margin``, or ``_margin_x`` and
    ``_margin_y``) of values ``got`` (mm, :func:`_margin`), each comment saying the range
    ``ranges`` (``(lo, hi]`` per axis, mm) the drawing fixes it to: any margin in it keeps
    the holes drawn, so the value is a reading (the roundest), not a number the drawing
    holds (issue 114's maker run, #11: a 12 mm margin read as 10); and the head's lines
    that say so (:attr:`stats.readings`, after the field's own)."""
    u = UNIT.get()

    def why(span: tuple, where: str) -> str:
        return (f"from the {where} to the field's: the roundest of the margins over "
                f"{_num(span[0])} and up to {_num(span[1])} {u}, each keeps the holes drawn")
    if got[0] == got[1]:            # one margin all round: what both axes allow
        both = (max(ranges[0][0], ranges[1][0]), min(ranges[0][1], ranges[1][1]))
        mx = my = self.p(hn + "_margin", got[0], why(both, "plate's edges"))
        names, spans = [mx], [both]
    else:
        mx = self.p(hn + "_margin_x", got[0], why(ranges[0], "left and right edges"))
        my = self.p(hn + "_margin_y", got[1], why(ranges[1], "top and bottom edges"))
        names, spans = [mx, my], ranges
    notes = [f"`{nm}` = {_num(v)} {u}, the roundest reading: every margin over {_num(lo)} "
             f"and up to {_num(hi)} {u} keeps these holes (the drawing fixes no one number); "
             f"set the one you dimensioned" for nm, (lo, hi), v in zip(names, spans, got)]
    return mx, my, notes


class _Fields:
    def hex_field(self, depth: int, sh: Shape, base: str, hf: tuple) -> None:
        """A hex grid clipped to a round field (``hf`` from :func:`_hex_field`) or to a
        rectangular one (:func:`_hex_rect`) as one grid: every node of the lattice about the
        field's centre whose hole lies whole in the field, so that a new pitch, hole size or
        field keeps one grid filling its field; placed by its centre (:meth:`pos`); params
        ``_pitch``, ``_d`` and ``_field_d`` (``_field_width``, ``_field_height``)."""
        (cx, cy), pitch, shift, *field = hf
        ranges, field = field[2:], field[:2]
        hn = self.name(base + "s")
        sizes = self.size_params(hn, sh, True)
        p = self.p(hn + "_pitch", pitch, times=int(max(field) / pitch) + 1)
        plate = self.plate_field(hn, (cx, cy), pitch, 2 * sh.args["radius"], ranges) \
            if ranges and sh.kind == "Circle" else None
        if len(field) == 1:
            f = [self.p(hn + "_field_d", field[0], "the round field the holes lie whole in")]
        elif plate is not None:         # a perforated plate: the plate less its margin
            f = plate
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

    def plate_field(self, hn: str, c, pitch: float, d: float, ranges) -> list | None:
        """A hex grid's rectangular field as the plate less its margin (``[width - 2 *
        holes_margin, height - 2 * holes_margin]``, program text) when it is a perforated
        plate's (issue 103): centred on an upright rectangular body, at least
        :data:`PERFORATED_MIN` pitches across each way, its holes ``d`` across (mm) a
        perforated plate's (:func:`_perforated`); ``ranges``: the field's widths and heights
        that keep the holes drawn (``[lo, hi)``, mm); else None."""
        if self.anchor is None or min(lo for lo, _ in ranges) < PERFORATED_MIN * pitch:
            return None
        body, sizes = self.anchor
        if not _perforated(body, c, [lo for lo, _ in ranges], pitch, d):
            return None
        m = [((body.args[key] - hi) / 2, (body.args[key] - lo) / 2)
             for key, (lo, hi) in zip(("width", "height"), ranges)]
        got = [_margin(*m[0]), _margin(*m[1])]
        for a in (0, 1):                        # one margin all round when one fits both
            if m[1 - a][0] + 1e3 * EQUAL_TOL < got[a] <= m[1 - a][1] + 1e3 * EQUAL_TOL:
                got[1 - a] = got[a]
        mx, my, notes = _margin_params(self, hn, got, m)
        self.stats.readings.append(
            f"{hn}: a hex field over the plate but for a margin (perforated), refilled by a "
            f"new pitch, hole or plate size")
        self.stats.readings.extend(notes)
        return [f"({sizes['width']} - 2 * {mx})", f"({sizes['height']} - 2 * {my})"]

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

    def perforated(self, depth: int, sh: Shape, base: str, gr: tuple) -> bool:
        """A perforated plate (issue 103; docs/import.md, "What an edit means"): a square-set
        grid of round holes (``gr`` from :func:`~.find._grid`, at least
        :data:`PERFORATED_MIN` each way, one pitch) over the plate but for a margin
        (:func:`_perforated`), written as the plate
        less its margin filled with as many holes as fit, about the plate's centre: a new
        pitch or hole size refills it, a new width or height grows it, the margin (from the
        plate's edge to the field's, the roundest that keeps the holes drawn) a param.
        False (nothing written) when the grid is no such field."""
        x0, y0, dx, dy, nx, ny = gr
        if self.anchor is None or sh.kind != "Circle" or min(nx, ny) < PERFORATED_MIN:
            return False
        body, sizes = self.anchor
        r = sh.args["radius"]
        spans = ((nx - 1) * dx + 2 * r, (ny - 1) * dy + 2 * r)
        mid = (x0 + dx * (nx - 1) / 2, y0 + dy * (ny - 1) / 2)
        if abs(dx - dy) > EQUAL_TOL or not _perforated(body, mid, spans, dx, 2 * r):
            return False
        ranges = []
        for span, step, key in ((spans[0], dx, "width"), (spans[1], dy, "height")):
            tight = (body.args[key] - span) / 2     # the edge to the outer holes' edges
            ranges.append((tight - step / 2, tight))
        m = [_margin(*ranges[0]), _margin(*ranges[1])]
        for a in (0, 1):                        # one margin all round when one fits both
            if ranges[1 - a][0] + 1e3 * EQUAL_TOL < m[a] <= ranges[1 - a][1] + 1e3 * EQUAL_TOL:
                m[1 - a] = m[a]
        hn = self.name(base + "s")
        hole = self.size_params(hn, sh, True)
        d = hole.get("diameter", _r(2 * r))
        mx, my, notes = _margin_params(self, hn, m, ranges)
        px = py = self.p(hn + "_pitch", dx, times=max(nx, ny))
        w = self.w
        w.emit(depth, "# a perforated field: the plate less its margin, as many holes as fit, "
                      "about the plate's centre")
        out, loops = [], []
        for axis, (size, margin, pitch, var) in enumerate(
                ((sizes["width"], mx, px, "i"), (sizes["height"], my, py, "j"))):
            cnt = self.name(hn + ("_cols" if axis == 0 else "_rows"))
            w.emit(depth, f"{cnt} = floor(norm(({size} - 2 * {margin} - {d}, 0)) / "
                          f"norm(({pitch}, 0)) + 1e-6) + 1")
            loops.append(f"for {var} in range({cnt}) {{")
            out.append(self.from_body_centre(axis, f"({var} - ({cnt} - 1) / 2) * {pitch}",
                                             body.center[axis]))
        for k, ln in enumerate(loops):
            w.emit(depth + k, ln)
        looped = len(self.looped)
        self.hole_block(depth + 2, hn, sh, f"({out[0]}, {out[1]})", hole, turns.grid(*gr))
        # a label beside the field is placed as a feature is: the counts are the solid's own
        # names, which a drawing block beside the part does not see
        del self.looped[looped:]
        w.emit(depth + 1, "}")
        w.emit(depth, "}")
        self.stats.readings.append(
            f"{nx} x {ny} {base}s over the plate but for a margin: a perforated field, "
            f"refilled by a new pitch, hole or plate size")
        self.stats.readings.extend(notes)
        self.stats.patterns["perforated field"] += 1
        return True
