"""The export of :mod:`gen_drawings`' designs (ezdxf and svgwrite, as real programs write
them: see that module's doc) and the independent readers that check them (ezdxf,
svgelements); split out of gen_drawings.py for its size, which imports it back."""
from __future__ import annotations

import io
import math
import re

import ezdxf

from gen_drawings import (INCH, TAU, Design, base_kind, chain, circle, members, scaled,  # noqa: F401
                          seg_ends, slot_loop)


# --- export ----------------------------------------------------------------------------------------


def _bulges(loop) -> list:
    """``(x, y, bulge)`` vertices of a loop for an LWPOLYLINE (arcs of at most 180 degrees
    each: bigger ones split in two)."""
    out = []
    for g in loop:
        if g[0] == "L":
            out.append((g[1][0], g[1][1], 0.0))
            continue
        _, c, r, a, sw = g
        k = 1 if abs(sw) <= math.pi + 1e-12 else 2
        for j in range(k):
            t = a + sw * j / k
            out.append((c[0] + r * math.cos(t), c[1] + r * math.sin(t), math.tan(sw / k / 4)))
    return out


def _dxf_loop(m, loop, att, bulges: bool):
    if len(loop) == 1 and loop[0][0] == "A" and abs(loop[0][4]) >= TAU - 1e-12:
        m.add_circle(loop[0][1], loop[0][2], dxfattribs=att)
        return
    if bulges:
        m.add_lwpolyline(_bulges(loop), format="xyb", close=True, dxfattribs=att)
        return
    for g in loop:
        if g[0] == "L":
            m.add_line(g[1], g[2], dxfattribs=att)
        else:
            _, c, r, a, sw = g
            a0, a1 = (a, a + sw) if sw > 0 else (a + sw, a)
            m.add_arc(c, r, math.degrees(a0), math.degrees(a1), dxfattribs=att)


def _local_loops(f) -> list | None:
    """A pattern's one member at the origin, for a block (``None``: not drawn by blocks)."""
    k = base_kind(f)
    if k in ("grid", "hexgrid", "boltcircle", "flange", "board") or \
            (k == "row" and f["member"] == "hole"):
        return [circle((0.0, 0.0), f["d"] / 2)]
    if k in ("row", "ventrow"):
        return [slot_loop((0.0, 0.0), f["length"], f["w"], 0.0)]
    return None


def to_dxf(d: Design) -> bytes:
    """The design as a DXF, the way ``d.style`` says (see the module doc)."""
    st = d.style
    doc = ezdxf.new("R2010")
    if st.get("insunits", True):
        doc.units = 1 if d.units == "in" else 4
    elif st.get("insunits") is None:
        del doc.header["$INSUNITS"]         # no header variable at all
    else:
        doc.units = 0                       # "unitless"
    lay = st.get("layers") or ("0", "0", "0")
    for name in set(lay) - {"0"}:
        doc.layers.add(name)
    m = doc.modelspace()
    bul = st.get("bulges", True)
    _dxf_loop(m, d.outline(), {"layer": lay[0]}, bul)
    nb = 0
    for i, f in enumerate(d.features):
        if f["kind"] in ("notch", "label", "comb"):
            continue
        local = _local_loops(f) if st.get("blocks") else None
        if local is None:
            for lp in d.feature_loops(i):
                _dxf_loop(m, lp, {"layer": lay[1]}, bul)
            continue
        nb += 1
        blk = doc.blocks.new(f"P{nb}")
        for lp in local:
            _dxf_loop(blk, lp, {"layer": "0"}, bul)
        c = d.place(f)
        rot = 90.0 if f["kind"] == "row" and f["member"] == "slot" and f["dir"] == "x" else \
            float(f["angle"]) if f["kind"] == "ventrow" else 0.0
        for p in members(f, c):
            m.add_blockref(blk.name, p, dxfattribs={"layer": lay[1], "rotation": rot})
        if f["kind"] in ("boltcircle", "flange") and f.get("bore"):
            m.add_circle(c, f["bore"] / 2, dxfattribs={"layer": lay[1]})
    if d.marks():
        doc.layers.add("CSK")
    for c, r in d.marks():
        m.add_circle(c, r, dxfattribs={"layer": "CSK"})
    for _, text, (x, y), h, typ, align in d.labels():
        if typ == "TEXT":
            t = m.add_text(text, height=h, dxfattribs={"layer": lay[2]})
            t.set_placement((x, y), align=ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER
                            if align == "centre" else ezdxf.enums.TextEntityAlignment.LEFT)
        else:
            m.add_mtext(text, dxfattribs={"layer": lay[2], "char_height": h, "insert": (x, y),
                                          "attachment_point": 5 if align == "centre" else 7})
    s = io.StringIO()
    doc.write(s)
    return s.getvalue().encode()


def _path_d(loop) -> str:
    x, y = seg_ends(loop[0])[0]
    out = [f"M {x!r} {y!r}"]
    for g in loop:
        if g[0] == "L":
            out.append(f"L {g[2][0]!r} {g[2][1]!r}")
            continue
        _, c, r, a, sw = g
        k = 1 if abs(sw) < math.pi - 1e-9 else (2 if abs(sw) <= TAU - 1e-9 else 4)
        for j in range(1, k + 1):
            t = a + sw * j / k
            px, py = c[0] + r * math.cos(t), c[1] + r * math.sin(t)
            out.append(f"A {r!r} {r!r} 0 0 {1 if sw > 0 else 0} {px!r} {py!r}")
    return " ".join(out) + " Z"


def to_svg(d: Design) -> bytes:
    """The design as an SVG: a viewBox in the design's unit, the y axis turned by a group's
    ``matrix(1 0 0 -1 ...)``, patterns as groups translated to their centre (a row of slots
    turned by ``rotate(90)``), texts in a y-down group."""
    import svgwrite
    x0, y0 = d.origin
    W, H = d.width, d.height
    u = "in" if d.units == "in" else "mm"
    dw = svgwrite.Drawing(size=(f"{W!r}{u}", f"{H!r}{u}"), viewBox=f"0 0 {W!r} {H!r}",
                          profile="full", debug=False)
    style = {"fill": "none", "stroke": "black", "stroke_width": 0.1 if u == "mm" else 0.004}
    flip = dw.g(transform=f"matrix(1 0 0 -1 {-x0!r} {H + y0!r})", id="drawing")
    dw.add(flip)
    flip.add(dw.path(d=_path_d(d.outline()), **style))
    for i, f in enumerate(d.features):
        if f["kind"] in ("notch", "label", "comb"):
            continue
        c = d.place(f)
        local = _local_loops(f) if d.style.get("blocks") else None
        if local is None:
            for lp in d.feature_loops(i):
                if len(lp) == 1 and abs(lp[0][4]) >= TAU - 1e-12:
                    flip.add(dw.circle(center=lp[0][1], r=lp[0][2], **style))
                else:
                    flip.add(dw.path(d=_path_d(lp), **style))
            continue
        g = dw.g(transform=f"translate({c[0]!r} {c[1]!r})")
        flip.add(g)
        rot = 90 if f["kind"] == "row" and f["member"] == "slot" and f["dir"] == "x" else \
            f["angle"] if f["kind"] == "ventrow" else 0
        for p in members(f, c):
            q = dw.g(transform=f"translate({p[0] - c[0]!r} {p[1] - c[1]!r})"
                     + (f" rotate({rot})" if rot else ""))
            g.add(q)
            for lp in local:
                if len(lp) == 1:
                    q.add(dw.circle(center=(0, 0), r=lp[0][2], **style))
                else:
                    q.add(dw.path(d=_path_d(lp), **style))
        if f["kind"] in ("boltcircle", "flange") and f.get("bore"):
            flip.add(dw.circle(center=c, r=f["bore"] / 2, **style))
    texts = dw.g(id="labels")
    dw.add(texts)
    for _, text, (x, y), h, typ, align in d.labels():
        sx, sy = x - x0, H - (y - y0)
        t = dw.text(text, insert=(sx, sy), font_size=h / 0.7, fill="black")
        t["text-anchor"] = "middle" if align == "centre" else "start"
        if align == "centre":
            t["dominant-baseline"] = "middle"
        texts.add(t)
    return dw.tostring().encode()


def export(d: Design) -> tuple[str, bytes]:
    """``(file name suffix, bytes)`` of the design in its style's format."""
    if d.style.get("format") == "svg":
        return ".svg", to_svg(d)
    return ".dxf", to_dxf(d)


# --- independent readers -------------------------------------------------------------------------


def _dxf_segments(e, out, texts):
    t = e.dxftype()
    if t == "INSERT":
        for v in e.virtual_entities():
            _dxf_segments(v, out, texts)
    elif t in ("LWPOLYLINE", "POLYLINE"):
        for v in e.virtual_entities():
            _dxf_segments(v, out, texts)
    elif t == "LINE":
        out.append((e.dxf.layer, ("L", (e.dxf.start.x, e.dxf.start.y), (e.dxf.end.x, e.dxf.end.y))))
    elif t == "ARC":
        a0, a1 = math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)
        out.append((e.dxf.layer, ("A", (e.dxf.center.x, e.dxf.center.y), e.dxf.radius, a0,
                                  (a1 - a0) % TAU or TAU)))
    elif t == "CIRCLE":
        out.append((e.dxf.layer, ("A", (e.dxf.center.x, e.dxf.center.y), e.dxf.radius, 0.0, TAU)))
    elif t in ("TEXT", "MTEXT"):
        texts.append(e)


def read_dxf(data, scale: float = 1.0) -> tuple[dict, list]:
    """``({layer: [loops]}, [TEXT/MTEXT entities])`` of a DXF read by ezdxf alone: blocks
    placed with ezdxf's ``virtual_entities``, polylines exploded, pieces chained (each loop
    scaled by ``scale``)."""
    if isinstance(data, bytes):
        data = data.decode()
    doc = ezdxf.read(io.StringIO(data))
    segs, texts = [], []
    for e in doc.modelspace():
        _dxf_segments(e, segs, texts)
    out = {}
    for layer in {s[0] for s in segs}:
        loops, open_ = chain([s for lay, s in segs if lay == layer])
        out[layer] = [scaled(lp, scale) for lp in loops] + [("open", o) for o in open_]
    return out, texts


def read_svg(data: bytes) -> tuple[list, list]:
    """``(loops in mm, [(text, x, y)])`` of an SVG read by svgelements alone (its root's
    ``width`` in mm or inches over svgelements' pixels; y turned up)."""
    import svgelements as se
    svg = se.SVG.parse(io.BytesIO(data))
    # svgelements takes 1 mm as 3.7795296 px (rounded): the root's own width says the scale
    m = re.search(rb'<svg[^>]*?\swidth="([\d.e+-]+)(mm|in)"', data)
    k = float(m.group(1)) * (INCH if m.group(2) == b"in" else 1.0) / svg.width
    segs, texts = [], []

    def pt(p):
        return (p.x * k, -p.y * k)
    for el in svg.elements():
        if isinstance(el, se.Text):
            texts.append((el.text, el.x * k, -el.y * k))
            continue
        if not isinstance(el, se.Shape):
            continue
        for s in se.Path(el).segments():
            if isinstance(s, se.Line):
                segs.append(("L", pt(s.start), pt(s.end)))
            elif isinstance(s, se.Arc):
                c, a = pt(s.center), pt(s.start)
                segs.append(("A", c, math.dist(c, a), math.atan2(a[1] - c[1], a[0] - c[0]),
                             -s.sweep))
    loops, open_ = chain(segs)
    return loops, texts
