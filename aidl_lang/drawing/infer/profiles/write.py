"""A profile written as a polygon of params (issue 93: "profiles as a polygon of params, legs,
widths, thickness, with their fillets"; docs/import.md, "What an edit means"):

    param leg = 40 mm
    param wall = 15 mm          # the thickness (`thickness` is the language's keyword)
    body = Polygon([(0, 0), (leg, 0), (leg, wall), (wall, wall), (wall, leg), (0, leg)])
    Fixed(body)
    Fillet(at=[(wall, wall)], radius=fillet)

each corner's x and y the text of the face it lies on (:mod:`.faces`: an edge by the width
or height param, an inner face by the thickness, a centred width or its own step), so that
"longer leg" or "thicker" is one param; the holes in it are placed by those faces
(:meth:`_Profiles.profile_at`).  The mixin of :class:`~..infer._Part` that writes it."""
from __future__ import annotations

from ..holes.features import edge_notches
from ..params import _r
from ..shapes import EQUAL_TOL, Shape
from .faces import Faces, find_faces, hole_place
from .read import read_profile

KINDS = {6: "an L", 8: "a T, U or Z"}


def _plus(base: str, term: str, sign: int) -> str:
    """``base + term`` (``sign`` 1) or ``base - term`` (-1) as text."""
    if base == "0":
        return term if sign > 0 else f"-{term}"
    return f"{base} {'+' if sign > 0 else '-'} {term}"


def notch_reading(segs: list) -> bool:
    """Whether a profile reads as a plate with notches cut into its sides
    (:func:`~..features.edge_notches`): two or more notches, or one that is not a square
    one wider than half its side (that is a U's opening: the U keeps its walls' thickness)."""
    got = edge_notches(segs)
    if got is None or not got[1]:
        return False
    if len(got[1]) != 1:
        return True
    side, shape, lo, hi, _ = got[1][0]
    boxes = [s.box() for s in segs]
    along = 0 if side in ("bottom", "top") else 1
    size = max(b[along + 2] for b in boxes) - min(b[along] for b in boxes)
    return not (shape == "square" and hi - lo > size / 2)


class _Profiles:
    """Writes a profile body (needs :class:`~..infer._Part`'s ``p``, ``w``, ``edge``,
    ``grows_from``, ``anchor``, ``frame``, ``stats``)."""

    profile: Faces | None = None

    def profile_body(self, depth: int, segs: list) -> tuple | None:
        """Write the outline ``segs`` as a profile (module doc); returns the body's
        ``(Shape of its box, size params, name)`` or None when it is no profile (or reads
        as a plate with notches: :func:`notch_reading`)."""
        got = read_profile(segs)
        if got is None or notch_reading(segs):
            return None
        nm = self.name("body")
        corners, radii, convex = got
        fc = find_faces(corners, convex)
        x0, y0, x1, y1 = fc.box
        box = Shape("Rectangle", ((x0 + x1) / 2, (y0 + y1) / 2),
                    {"width": x1 - x0, "height": y1 - y0}, ("Rectangle",), len(segs))
        if fc.equal_legs:
            leg = self.p("leg", x1 - x0, "each leg, to the outside")
            sizes = {"width": leg, "height": leg}
        else:
            sizes = {"width": self.p("width", x1 - x0), "height": self.p("height", y1 - y0)}
        self.anchor = (box, sizes)
        self.frame = self.grows(box)
        self.profile = fc
        self._names: list = []          # (value, role, axis) -> param, equal values one
        text = [{}, {}]
        for axis in (0, 1):
            for v in fc.values(axis):
                text[axis][v] = self._face_text(fc, v, axis, text[axis])
        pts = [(text[0][fc.face(p[0], 0).value], text[1][fc.face(p[1], 1).value])
               for p in corners]
        self.w.emit(depth, f"# a profile of {len(corners)} corners at right angles: its "
                           f"faces by the edges and the walls' thickness")
        self.w.emit(depth, f"{nm} = Polygon([" + ", ".join(f"({a}, {b})" for a, b in pts) + "])")
        self.w.emit(depth, f"Fixed({nm})")
        groups: list = []       # [radius, name, [points]]
        for k, r in enumerate(radii):
            if r <= EQUAL_TOL:
                continue
            g = next((g for g in groups if abs(g[0] - r) <= EQUAL_TOL), None)
            if g is None:
                g = [r, None, [], convex[k]]
                groups.append(g)
            g[2].append(pts[k])
        for g in groups:
            inside = not g[3]
            g[1] = self.p("fillet" if inside or len(groups) == 1 else "corner_radius", g[0],
                          "inside corners" if inside else "outside corners")
            self.w.emit(depth, "Fillet(at=[" + ", ".join(f"({a}, {b})" for a, b in g[2])
                        + f"], radius={g[1]})")
        self.stats.kinds["Polygon"] += 1
        self.stats.in_shapes += len(segs)
        self.stats.patterns["profile"] += 1
        return box, sizes, nm

    def _param(self, value: float, role: str, axis: int) -> str:
        for v, nm in self._names:
            if abs(v - value) <= EQUAL_TOL:
                return nm
        base = {"thickness": "wall", "width": "stem_width", "step": "step"}[role]
        if role == "thickness" and abs(value - self.profile.thickness) > EQUAL_TOL:
            base = "wall_" + "xy"[axis]
        elif role == "step":
            base = "step_" + "xy"[axis]
        nm = self.p(base, value, {"thickness": "", "width": "centred",
                                  "step": "from the nearer edge"}[role])
        self._names.append((value, nm))
        return nm

    def _face_text(self, fc: Faces, v: float, axis: int, done: dict) -> str:
        f = fc.face(v, axis)
        if f.how == "edge" and f.role == "outer":
            return self.edge(axis, f.side)
        p = self._param(f.dist, f.role, axis)
        if f.how == "edge":
            return _plus(self.edge(axis, f.side), p, -f.side)
        if f.how == "mid":
            return _plus(self.edge(axis, 0), f"{p} / 2", f.side)
        ref = done.get(f.ref)
        if ref is None:
            ref = done[f.ref] = self._face_text(fc, f.ref, axis, done)
        return _plus(ref, p, f.side)

    def profile_at(self, v: float, axis: int) -> str:
        """A hole's coordinate ``v`` in the profile: midway between the faces either side
        of it, else from the nearest face (:func:`~.faces.hole_place`)."""
        fc = self.profile
        how = hole_place(fc, v, axis)
        if how[0] == "mid":
            a, b = (self._face_text(fc, w, axis, {}) for w in how[1:])
            one = b if a == "0" else a if b == "0" else None
            if one is not None:
                return f"{one} / 2" if one.isidentifier() else f"({one}) / 2"
            return f"({a} + {b}) / 2"
        base = self._face_text(fc, how[1], axis, {})
        d = how[2]
        if abs(d) <= 1e-9:
            return base
        return _plus(base, _r(abs(d)), 1 if d > 0 else -1)
