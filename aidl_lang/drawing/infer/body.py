"""A part's body written (``aidl import --infer``; docs/import.md, "Inferring the design"):
its outer loop as the primitive it is (:func:`~.shapes.recognise`), a rectangle with equal
notches in one side (a comb: one row of ``hole`` s), a profile (:mod:`.profiles`), a plate
with notches of any shape in its sides, a chamfered plate, a rectangle with tabs, a circle
with teeth, one run turned round a centre, else the exact chain.  The mixin of
:class:`~.infer._Part` that writes it (needs its ``p``, ``w``, ``name``, ``shape_line``,
``stats``, the placing of :class:`~.anchors._Anchored` and the notches of
:class:`~.holes.makers._MakerFeatures`)."""
from __future__ import annotations

from .attachments import _attachments, _circle_attachments, _notches
from .chamfers import _chamfered, _clear_of_chamfers
from .holes.features import edge_notches, notch_rows
from .params import _deg, _r
from .patterns.find import _polar_chain, _polar_polys, _steps
from .shapes import EQUAL_TOL, Shape, _snap_angle, recognise
from ..write.writer import _emit_holds, _holds, _num


class _Bodies:
    """Writes a part's outer loops (module doc)."""

    # the body ---------------------------------------------------------------
    def body(self, depth: int, segs: list, first: bool) -> tuple | None:
        """Write an outer loop; returns the body's (Shape, param names) when it is a
        rectangle-like shape the holes may be placed by."""
        st = self.stats
        st.pieces += len(segs)
        sh = recognise(segs)
        tabs = None
        teeth = None
        if sh is None:          # a circle with teeth, before a rectangle with tabs
            got = _circle_attachments(segs)
            if got is not None:
                sh, teeth = got
        if sh is None or sh.kind == "Polygon" and len(segs) > 4:
            got = _notches(segs)
            if got is not None:
                return self.notched(depth, segs, first, got)
        if first and (sh is None or sh.kind == "Polygon") and len(segs) >= 6:
            got = self.profile_body(depth, segs)      # an L, T, U, Z, a stepped plate
            if got is not None:
                return got
        cuts = None
        corners_drawn = False       # a chamfered plate written corner by corner
        if first and (sh is None or sh.kind == "Polygon"):
            got = edge_notches(segs)        # notches of any shape cut into the sides
            if got is not None:
                plain = recognise(got[0])
                cut_corner = _chamfered(plain)
                if cut_corner is not None or \
                        plain is not None and plain.kind in ("Rectangle", "RoundedRectangle") \
                        and abs(plain.args.get("rotation", 0.0)) <= 1e-15:
                    sh, cuts = plain, got[1]
                    # a notch within two chamfer legs of a corner: `Chamfer` (at most half
                    # of each side it meets) cannot cut that corner, so the plate's eight
                    # corners are written from its width, height and chamfer
                    corners_drawn = cut_corner is not None and \
                        not _clear_of_chamfers(got[1], *cut_corner)
        if sh is None or sh.kind == "Polygon" and len(segs) > 4:
            got = _attachments(segs)
            if got is not None:
                sh, tabs = got
        nm = self.name("body" if first else "outline")
        chamfer = _chamfered(sh) if first else None
        if chamfer is not None:
            sh, leg = chamfer
        if sh is None:
            pc = _polar_chain(segs)
            if pc is not None:
                C, n, period = pc
                self.stats.patterns["outline turned round a centre"] += 1
                self.stats.in_shapes += len(segs)
                pre = nm + "_s"
                if self.w.chain(depth, period, False, pre):
                    names = [f"{pre}{i}" for i in range(len(period))]
                    _emit_holds(self.w, depth, _holds(period, pre, False))
                    self.w.emit(depth, f"for e in [{', '.join(names)}] {{ "
                                       f"CircularPattern(e, {n}, {self.center(C)}) }}")
                    # its centre names a bore (no pieces to place holes by)
                    return Shape("Circle", C, {"radius": 0.0}, (), 0), {}, nm
            if self.w.chain(depth, segs, True, nm + "_s"):
                _emit_holds(self.w, depth, _holds(segs, nm + "_s"))
            return None
        st.kinds[sh.kind] += 1
        st.in_shapes += sh.pieces
        sizes: dict = {}
        if first and sh.kind in ("Rectangle", "RoundedRectangle"):
            sizes["width"] = self.p("width", sh.args["width"])
            sizes["height"] = self.p("height", sh.args["height"])
            if "corner_radius" in sh.args:
                sizes["corner_radius"] = self.p("corner_radius", sh.args["corner_radius"])
        elif first and sh.kind == "Circle":
            sizes["diameter"] = self.p("diameter", 2 * sh.args["radius"])
        if "width" in sizes and abs(sh.args.get("rotation", 0.0)) <= 1e-15:
            self.anchor = (sh, sizes)
            self.frame = self.grows(sh)
        if chamfer is not None and corners_drawn and "width" in sizes:
            ch = self.p("chamfer", leg, "at each corner")
            L, R, B, T = (self.edge(0, -1), self.edge(0, 1), self.edge(1, -1),
                          self.edge(1, 1))

            def at(edge: str, sign: str) -> str:     # an edge moved in by the chamfer
                if edge == "0":
                    return ch if sign == "+" else f"-{ch}"
                return f"{edge} {sign} {ch}"
            pts = [(at(L, "+"), B), (at(R, "-"), B), (R, at(B, "+")), (R, at(T, "-")),
                   (at(R, "-"), T), (at(L, "+"), T), (L, at(T, "-")), (L, at(B, "+"))]
            self.w.emit(depth, f"{nm} = Polygon([" + ", ".join(f"({a}, {b})" for a, b in pts)
                        + "])")
            self.w.emit(depth, f"Fixed({nm})")
            st.patterns["chamfered corners"] += 1
        else:
            self.shape_line(depth, nm, sh, self.body_centre(sh), sizes)
            self.w.emit(depth, f"Fixed({nm})")
        if chamfer is not None and not (corners_drawn and "width" in sizes):
            self.w.emit(depth, f"Chamfer({nm}, {self.p('chamfer', leg, 'at each corner')})")
            st.patterns["chamfered corners"] += 1
        for group in notch_rows(cuts or []):
            if len(group) > 2:
                self.notch_row(depth, group)
                st.patterns["notches in a side"] += 1
                continue
            for cut in group:
                self.edge_notch(depth, cut)
                st.patterns["notch in a side"] += 1
        if teeth:
            self.teeth(depth, sh, teeth, "tooth")
        own = {id(x) for x in segs}
        for chain in tabs or []:
            tn = self.name("tab")
            if isinstance(chain, Shape):
                st.kinds[chain.kind] += 1
                st.in_shapes += 3
                self.shape_line(depth, tn, chain, self.pos(chain.center))
                self.w.emit(depth, f"Fixed({tn})")
                continue
            t = recognise(chain)
            if t is not None and t.kind != "Polygon":
                st.kinds[t.kind] += 1
                self.shape_line(depth, tn, t, self.pos(t.center))
                self.w.emit(depth, f"Fixed({tn})")
            elif t is not None:
                self.shape_line(depth, tn, t, "")
                self.w.emit(depth, f"Fixed({tn})")
            elif self.w.chain(depth, chain, True, tn + "_s"):
                _emit_holds(self.w, depth, _holds(chain, tn + "_s"))
            st.in_shapes += sum(1 for s in chain if id(s) in own)
        if sh.kind in ("Rectangle", "RoundedRectangle", "Circle") and \
                abs(sh.args.get("rotation", 0.0)) <= 1e-15:
            return sh, sizes, nm
        return None

    def notched(self, depth: int, segs: list, first: bool, got: tuple) -> tuple:
        """A rectangle with equal notches cut into one side (:func:`_notches`): the
        rectangle, and the notches as one row of ``hole``s flush with that side (their
        count, pitch, width and depth params; centred on the body where they are)."""
        rect, side, centres, w, dep = got
        self.stats.kinds["Rectangle"] += 1
        self.stats.in_shapes += len(segs)
        nm = self.name("body" if first else "outline")
        sizes = {"width": self.p("width", rect.args["width"]),
                 "height": self.p("height", rect.args["height"])} if first else {}
        if sizes:
            self.anchor = (rect, sizes)
            self.frame = self.grows(rect)
        self.shape_line(depth, nm, rect, self.body_centre(rect), sizes)
        self.w.emit(depth, f"Fixed({nm})")
        n = len(centres)
        along = 0 if side in ("top", "bottom") else 1
        across = 1 - along
        hn = self.name("notches")
        pitch = _steps(centres)
        cnt = self.p(hn + "_n", n, unit="")
        nw = self.p(hn + "_width", w)
        nd = self.p(hn + "_depth", dep)
        c = rect.center
        mid = (centres[0] + centres[-1]) / 2
        if pitch is not None:
            pp = self.p(hn + "_pitch", pitch, times=n)
            if abs(mid - c[along]) <= EQUAL_TOL:
                pos = self.from_body_centre(along, f"(i - ({cnt} - 1) / 2) * {pp}", c[along])
            else:           # by its middle, or its end within a pitch of an edge (the spec)
                pos = self.run_at(centres[0], centres[-1], along, "i", cnt, pp, pitch)
            head = f"for i in range({cnt}) {{"
        else:
            pos = "x"
            head = f"for x in [{', '.join(self.at(v, along) for v in centres)}] {{"
        size = sizes.get("height" if across else "width") or \
            _r(rect.args["height" if across else "width"])
        sign = "" if side in ("top", "right") else "-"
        dpos = self.from_body_centre(across, f"{sign}({size} / 2 - {nd} / 2)", c[across])
        xy = (pos, dpos) if along == 0 else (dpos, pos)
        wh = (nw, nd) if along == 0 else (nd, nw)
        self.w.emit(depth, head)
        self.w.emit(depth + 1, f"hole {hn} {{ h = Rectangle(center=({xy[0]}, {xy[1]}), "
                               f"width={wh[0]}, height={wh[1]}) }}")
        self.w.emit(depth + 1, f"Fixed({hn}.h)")
        self.w.emit(depth, "}")
        self.stats.patterns["notches in a side"] += 1
        return rect, sizes, nm

    def teeth(self, depth: int, base: Shape, teeth: list, word: str) -> None:
        """The polygons standing out of a circle: one loop when they are one polygon turned
        evenly round it (a gear's teeth), else each on its own."""
        C = base.center
        pol = _polar_polys(teeth, C)
        c = self.center(C)
        if pol is not None:
            n, verts = pol
            step = _num(360 / n, 1e-10)
            pts = ", ".join(f"polar({c}, {_num(r)}, {_deg(_snap_angle(a, r))} + "
                            f"i * {step} deg)" for r, a in verts)
            self.w.emit(depth, f"for i in range({n}) {{")
            self.w.emit(depth + 1, f"{word} = Polygon([{pts}])")
            self.w.emit(depth + 1, f"Fixed({word})")
            self.w.emit(depth, "}")
            self.stats.patterns[f"{'teeth' if word == 'tooth' else word + 'es'} round a "
                                f"circle"] += 1
            self.stats.kinds["Polygon"] += n
            return
        for t in teeth:
            tn = self.name(word)
            pts = ", ".join(self.center(p) for p in t)
            self.w.emit(depth, f"{tn} = Polygon([{pts}])")
            self.w.emit(depth, f"Fixed({tn})")
            self.stats.kinds["Polygon"] += 1
