"""STEP writer (the optional ``step`` extra: OCP from ``cadquery-ocp``), built from the exact
profiles of :mod:`.part`, so circles stay circles and their extrusions cylinders, and a
spline stays a B-spline (``B_SPLINE_CURVE_WITH_KNOTS``; its extrusion a surface of it), an
ellipse an ``ELLIPSE`` (whole, or trimmed between its parameters).

Each solid part becomes one solid: its outer loops are faces (lines as straight edges, arcs
and circles as circular edges, ``gp_Circ``), its hole loops are inner wires of the face that
contains them, and the face is extruded along +z by the part's thickness
(``BRepPrimAPI_MakePrism``); a ``Countersink``'s cone and a ``Counterbore``'s step are cut
from its top face, exact (a cone and a cylinder: :func:`_sunk`).  Each part is one named, coloured shape of an XCAF document
(``--assembled``: moved by its placement), written as AP214 STEP in mm.
"""
from __future__ import annotations

import os
import tempfile

from ..part.part import Circle, EllipticArc, Line, Loop, MissingDependency, Output, Spline
from ..part.build.sunk import DEFAULT_THICKNESS



def _ocp():
    try:
        import OCP  # noqa: F401
    except ImportError:
        raise MissingDependency("STEP output needs OCP: pip install 'aidl-lang[step]'") from None


def _wire(loop: Loop, reverse: bool):
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeWire
    from OCP.GC import GC_MakeArcOfCircle
    from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Pnt
    mk = BRepBuilderAPI_MakeWire()
    for s in loop.segments:
        if isinstance(s, Spline):
            mk.Add(BRepBuilderAPI_MakeEdge(_bspline(s)).Edge())
        elif isinstance(s, EllipticArc):
            mk.Add(_ellipse_edge(s))
        elif isinstance(s, Line):
            a, b = gp_Pnt(*s.start, 0.0), gp_Pnt(*s.end, 0.0)
            if a.Distance(b) < 1e-9:
                continue
            mk.Add(BRepBuilderAPI_MakeEdge(a, b).Edge())
        elif isinstance(s, Circle):
            circ = gp_Circ(gp_Ax2(gp_Pnt(*s.center, 0.0), gp_Dir(0, 0, 1)), s.radius)
            mk.Add(BRepBuilderAPI_MakeEdge(circ).Edge())
        else:
            mid = s.at(s.start_angle + s.sweep / 2)
            arc = GC_MakeArcOfCircle(gp_Pnt(*s.start, 0.0), gp_Pnt(*mid, 0.0),
                                     gp_Pnt(*s.end, 0.0)).Value()
            mk.Add(BRepBuilderAPI_MakeEdge(arc).Edge())
    w = mk.Wire()
    return w.Reversed() if reverse else w


def _ellipse_edge(s: EllipticArc):
    """An OCP edge on a ``gp_Elips`` (STEP ``ELLIPSE``: centre, major axis direction, semi-
    axes), whole or trimmed between the arc's parameters (the eccentric anomaly, as OCP's;
    counter-clockwise: the wire orients its edges, as it does a hole's circle)."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    from OCP.GC import GC_MakeArcOfEllipse
    from OCP.gp import gp_Ax2, gp_Dir, gp_Elips, gp_Pnt
    import math
    e = s.curve
    ax = gp_Ax2(gp_Pnt(e.center[0], e.center[1], 0.0), gp_Dir(0, 0, 1),
                gp_Dir(math.cos(e.rotation), math.sin(e.rotation), 0.0))
    el = gp_Elips(ax, e.rx, e.ry)
    if s.whole:
        return BRepBuilderAPI_MakeEdge(el).Edge()
    a, b = (s.start_param, s.end_param) if s.sweep > 0 else (s.end_param, s.start_param)
    return BRepBuilderAPI_MakeEdge(GC_MakeArcOfEllipse(el, a, b, True).Value()).Edge()


def _bspline(s):
    """OCP ``Geom_BSplineCurve`` of a spline piece: the clamped degree-3 form of
    :meth:`~aidl_lang.geometry.shapes.curves.Spline.bspline` (distinct knots with multiplicities 4,
    3, ..., 3, 4), written as STEP ``B_SPLINE_CURVE_WITH_KNOTS``."""
    from OCP.Geom import Geom_BSplineCurve
    from OCP.gp import gp_Pnt
    try:                          # OCP 7.8 and later: NCollection arrays in OCP.collections
        from OCP.OCP.collections import (Array1_double as TColStd_Array1OfReal,
                                         Array1_gp_Pnt as TColgp_Array1OfPnt,
                                         Array1_int as TColStd_Array1OfInteger)
    except ImportError:           # earlier OCP
        from OCP.TColgp import TColgp_Array1OfPnt
        from OCP.TColStd import TColStd_Array1OfInteger, TColStd_Array1OfReal
    deg, knots, ctrl = s.bspline()
    poles = TColgp_Array1OfPnt(1, len(ctrl))
    for i, (x, y) in enumerate(ctrl):
        poles.SetValue(i + 1, gp_Pnt(x, y, 0.0))
    distinct = [knots[0]] + [k for a, k in zip(knots, knots[1:]) if k != a]
    mult = [knots.count(k) for k in distinct]
    K = TColStd_Array1OfReal(1, len(distinct))
    M = TColStd_Array1OfInteger(1, len(distinct))
    for i, (k, m) in enumerate(zip(distinct, mult)):
        K.SetValue(i + 1, k)
        M.SetValue(i + 1, m)
    return Geom_BSplineCurve(poles, K, M, deg)


def _contains(outer: Loop, inner: Loop) -> bool:
    """Is a point of ``inner`` inside ``outer`` (even-odd over ``outer``'s polyline)?"""
    P = outer.points()
    p = inner.points()[0]
    x, y = float(p[0]), float(p[1])
    inside = False
    n = len(P)
    for i in range(n):
        (x1, y1), (x2, y2) = P[i], P[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def solids(output: Output, thickness: float | None = None, assembled: bool = False):
    """(part name, OCP ``TopoDS_Shape``) per solid part (``assembled``: moved by its
    placement, the booleans' ``Drawing.placement``)."""
    _ocp()
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeFace
    from OCP.BRepPrimAPI import BRepPrimAPI_MakePrism
    from OCP.gp import gp_Vec
    d = output.drawing
    where = (getattr(d, "placement", None) or {}) if assembled and d is not None else {}
    out = []
    from ..part.part import sink_heads
    heads = sink_heads(output)
    for p in output.parts:
        if p.kind != "solid" or not p.loops:
            continue
        t = float(thickness or p.thickness or DEFAULT_THICKNESS)
        outers = [lp for lp in p.loops if lp.area > 0]
        holes = [lp for lp in p.loops if lp.area < 0]
        # nest: each hole goes to the smallest outer loop containing it
        owners: dict[int, list[Loop]] = {i: [] for i in range(len(outers))}
        for h in holes:
            cands = [i for i, o in enumerate(outers) if _contains(o, h)]
            if cands:
                owners[min(cands, key=lambda i: outers[i].area)].append(h)
        from OCP.TopoDS import TopoDS_Compound
        from OCP.BRep import BRep_Builder
        builder = BRep_Builder()
        comp = TopoDS_Compound()
        builder.MakeCompound(comp)
        for i, o in enumerate(outers):
            mf = BRepBuilderAPI_MakeFace(_wire(o, False), True)
            for h in owners[i]:
                mf.Add(_wire(h, False))
            prism = BRepPrimAPI_MakePrism(mf.Face(), gp_Vec(0, 0, t)).Shape()
            builder.Add(comp, prism)
        comp = _sunk(comp, [h for h in heads if h[1].part == p.name], t)
        M = where.get(p.name)
        if M is not None:
            comp = _moved(comp, M)
        out.append((p.name, comp))
    return out


def _sunk(shape, heads: list, t: float):
    """``shape`` (a part ``t`` mm thick) less its countersinks' cones and counterbores'
    cylinders (``heads``: :func:`~..part.part.sink_heads`), exact: a ``CONICAL_SURFACE`` from
    the hole's circle up to the head's at the top face, a ``CYLINDRICAL_SURFACE`` down a
    counterbore's depth (each tool from inside the hole to 0.01 mm above the top)."""
    if not heads:
        return shape
    import math
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeCone, BRepPrimAPI_MakeCylinder
    from OCP.ShapeFix import ShapeFix_Shape
    from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt
    # the prisms' faces oriented as a boolean needs them (a hole's wire as the face's inner
    # wire: the booleans cut nothing from the prism as made; the file read back is the same)
    fix = ShapeFix_Shape(shape)
    fix.Perform()
    shape = fix.Shape()
    e = 0.01
    for (x, y), r in heads:
        depth = r.cone_depth()
        if depth <= 0:
            continue
        if r.kind == "countersink":
            k = math.tan(r.angle / 2)
            low = r.hole_d / 4                  # from inside the hole: no rim on its wall
            z0 = t - depth - (r.hole_d / 2 - low) / k
            tool = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(x, y, z0), gp_Dir(0, 0, 1)), low,
                                        r.diameter / 2 + e * k, t + e - z0).Shape()
        else:
            tool = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, t - depth), gp_Dir(0, 0, 1)),
                                            r.diameter / 2, depth + e).Shape()
        shape = BRepAlgoAPI_Cut(shape, tool).Shape()
    return shape


def _moved(shape, M):
    """``shape`` moved by the rigid 4x4 matrix ``M`` (rotation and translation, mm)."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
    from OCP.gp import gp_Trsf
    tr = gp_Trsf()
    tr.SetValues(*(float(M[i][j]) for i in range(3) for j in range(4)))
    return BRepBuilderAPI_Transform(shape, tr, True).Shape()


def to_step(output: Output, thickness: float | None = None, assembled: bool = False) -> bytes:
    """AP214 STEP bytes of every solid part, extruded (mm): one solid per part, named after
    it (an XCAF document: the product names a STEP reader shows) and coloured like the flat
    assembly view; ``assembled``: each placed by its ``Place`` (a part's ``Bend``s are not
    applied: it stays flat, as cut; the mesh formats show it bent, and ``aidl render`` says so)."""
    _ocp()
    from OCP.Interface import Interface_Static
    from OCP.Quantity import Quantity_Color, Quantity_TOC_RGB
    from OCP.STEPCAFControl import STEPCAFControl_Writer
    from OCP.STEPControl import STEPControl_AsIs
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.TDataStd import TDataStd_Name
    from OCP.TDocStd import TDocStd_Document
    from OCP.XCAFDoc import XCAFDoc_ColorType, XCAFDoc_DocumentTool
    from ..part.part import PALETTE
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    shapes = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    colours = XCAFDoc_DocumentTool.ColorTool_s(doc.Main())
    for i, (name, shape) in enumerate(solids(output, thickness, assembled)):
        label = shapes.AddShape(shape, False)
        TDataStd_Name.Set_s(label, TCollection_ExtendedString(name))
        c = PALETTE[i % len(PALETTE)]
        rgb = [int(c[k:k + 2], 16) / 255 for k in (1, 3, 5)]
        colours.SetColor(label, Quantity_Color(*rgb, Quantity_TOC_RGB),
                         XCAFDoc_ColorType.XCAFDoc_ColorSurf)
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    Interface_Static.SetCVal_s("write.step.schema", "AP214IS")
    w = STEPCAFControl_Writer()
    w.SetNameMode(True)
    w.SetColorMode(True)
    fd, tmp = tempfile.mkstemp(suffix=".step")
    os.close(fd)
    try:
        with _quiet():                 # OCP prints transfer statistics on the C stdout
            w.Transfer(doc, STEPControl_AsIs)
            w.Write(tmp)
        with open(tmp, "rb") as f:
            return f.read()
    finally:
        os.unlink(tmp)


class _quiet:
    def __enter__(self):
        import sys
        sys.stdout.flush()
        self.saved = os.dup(1)
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        os.close(devnull)

    def __exit__(self, *exc):
        os.dup2(self.saved, 1)
        os.close(self.saved)


def write(output: Output, options) -> bytes:
    """The registry's ``.step`` / ``.stp`` (:data:`~.FORMATS`): :func:`to_step` with the
    :class:`~.Options` ``thickness`` and ``assembled``."""
    return to_step(output, options.thickness, options.assembled)
