"""PNG writer: the flat drawing (:func:`to_png`: the SVG of :mod:`.svg` rasterised with
``cairosvg``, the ``png`` extra: ``pip install 'aidl-lang[png]'``, on a white background) or a
picture of the assembled product (:func:`to_assembled_png`, painted with Pillow).

``dpi`` sets the resolution: the SVG is sized in millimetres, so 96 dpi draws 1 mm as 3.78
pixels; ``width`` (pixels) overrides it.  With neither, the page is drawn at
:data:`DEFAULT_DPI` unless its longer side would pass :data:`DEFAULT_SIDE` pixels, and then
scaled down to that side (issue 49: a drawing in metres asked for a million pixels a side):
parts up to about half a metre keep their 96 dpi picture, a whole cutting sheet or a building
plan fits a screen.  An explicit ``dpi`` is honoured as given (and refused past
:data:`MAX_SIDE` / :data:`MAX_AREA`).
"""
from __future__ import annotations

import re

import numpy as np

from ..part.part import MissingDependency, Output, OutputError
from .svg import to_svg


MAX_SIDE = 32_767            # cairo's largest image side (pixels)
MAX_AREA = 100_000_000       # 400 MB of RGBA at most
DEFAULT_DPI = 96.0           # with no dpi and no width: a screen's 96 dpi ...
DEFAULT_SIDE = 2000          # ... the longer side at most this many pixels
STROKE_PX = DEFAULT_SIDE / 500.0   # the preview's widest line in pixels (the default's)


def pixels_per_mm(w_mm: float, h_mm: float, dpi: float | None = None,
                  width: int | None = None) -> float:
    """The PNG's scale for a page of ``w_mm`` x ``h_mm``: ``width`` pixels across, else
    ``dpi``, else :data:`DEFAULT_DPI` with the longer side held to :data:`DEFAULT_SIDE`."""
    if width:
        return width / w_mm
    if dpi is not None:
        return dpi / 25.4
    px = DEFAULT_DPI / 25.4
    longer = max(w_mm, h_mm)
    return px if longer * px <= DEFAULT_SIDE else DEFAULT_SIDE / longer


def to_png(output: Output, dpi: float | None = None, width: int | None = None, show=(),
           style: str = "preview", margin: float | None = None) -> bytes:
    """PNG bytes of ``output`` (the page of :func:`~.svg.to_svg` with ``show``, ``style`` and
    ``margin``, mm) at ``dpi`` or ``width`` pixels across (neither: :func:`pixels_per_mm`'s
    default).  Raises :class:`MissingDependency` without ``cairosvg`` and
    :class:`OutputError` for a non-positive size or an image over :data:`MAX_SIDE` a side or
    :data:`MAX_AREA` pixels."""
    try:
        import cairosvg
    except (ImportError, OSError) as e:      # OSError: the cairo C library is missing
        raise MissingDependency(
            "PNG output needs cairosvg and the cairo library: pip install 'aidl-lang[png]' "
            f"(and apt-get install libcairo2 on Debian/Ubuntu) ({e})") from None
    svg = to_svg(output, show=show, style=style, margin=margin).encode()
    if width is not None and width < 1 or width is None and dpi is not None and not dpi > 0:
        raise OutputError(f"a PNG needs a positive {'--png-width' if width is not None else '--dpi'}")
    w_mm = re.search(rb' width="([0-9.]+)mm"', svg)
    h_mm = re.search(rb' height="([0-9.]+)mm"', svg)
    if w_mm and h_mm:
        w_mm, h_mm = float(w_mm[1]), float(h_mm[1])
        px = pixels_per_mm(w_mm, h_mm, dpi, width)          # pixels per mm
        if not width and dpi is None:
            dpi = px * 25.4
        w_px, h_px = w_mm * px, h_mm * px
        if max(w_px, h_px) > MAX_SIDE or w_px * h_px > MAX_AREA:
            raise OutputError(
                f"the PNG would be {w_px:.0f} x {h_px:.0f} pixels, more than {MAX_SIDE} a side "
                f"or {MAX_AREA // 1_000_000} megapixels; use a lower --dpi or --png-width")
        if style == "laser":
            # the laser style's 0.01 mm hairline is a fraction of a pixel: antialiased to
            # nearly white.  A raster draws it one pixel wide (the SVG and DXF keep 0.01 mm).
            svg = to_svg(output, show=show, style=style, margin=margin,
                         hairline=1.0 / px).encode()
        elif max(w_mm, h_mm) / 500.0 * px > STROKE_PX:
            # the preview's lines (the page's side / 500: 4 px at the default 2,000 px) stay
            # 4 px wide in a larger picture, not 10 px at 5,000 (runs eg, eh: zoomed to judge
            # a gap, a 750 mm board's 1.5 mm lines drew a 1 mm gap shut, and 3 mm as 1.5)
            svg = to_svg(output, show=show, style=style, margin=margin,
                         stroke=STROKE_PX / px).encode()
    kw = {"output_width": int(width)} if width else {"dpi": float(dpi or DEFAULT_DPI)}
    return cairosvg.svg2png(bytestring=svg, background_color="white", **kw)


# ------------------------------------------------------------------ the assembled product
VIEW = (-35.0, 25.0)        # degrees: the picture's azimuth (about z) and elevation
# the views side by side: from above the front-left corner and from above the back-right one
# (runs bp, bq, br, bs: which face an engraving or a countersink landed on, or whether a shelf
# stood into the wall, could not be told from one side)
VIEWS = (("front left", VIEW), ("back right", (VIEW[0] + 180.0, VIEW[1])))


def to_assembled_png(output: Output, thickness: float | None = None, width: int = 800,
                     highlight=None, views=VIEWS) -> bytes:
    """A PNG of the assembled product, ``width`` pixels wide (16 to 4096), seen from each of
    ``views`` (``(caption, (azimuth, elevation))``, degrees; side by side, each captioned):
    each part's triangles in its colour, shaded by how squarely they face the viewer, cut to
    a 24th of the largest part's size and drawn back to front (painter's order) with Pillow,
    at twice the size and scaled down (antialiasing), the engraving on the faces that look
    towards the viewer.  ``highlight``: :class:`Collision` s drawn over it as red boxes, a
    box per connected piece (None: those the fit check finds,
    :func:`~..fabrication.assembly.fit`, that W0517 says).  Raises
    :class:`~.part.MissingDependency` without Pillow (the ``png`` extra)."""
    if not 16 <= width <= 4096:
        raise OutputError(f"an assembled PNG is 16 to 4096 pixels wide, not {width}")
    from ..fabrication.assembly import _box, _rgba, colours, fit, normals_of, placements, solids
    colour_of = colours(output)
    bodies = solids(output, thickness)
    if highlight is None:
        highlight = fit(bodies, normals=normals_of(placements(output)))[0]
        said = getattr(output.drawing, "fit", None) if output.drawing is not None else None
        if said and said.get("checked"):
            # only what W0517 says: a bent skin resting on its profiles, an AllowOverlap's
            # press fit are no collision (runs cv, cx: red boxes the check never named)
            pairs = {frozenset((c["a"], c["b"])) for c in said.get("collisions", ())}
            highlight = [c for c in highlight if frozenset((c.a, c.b)) in pairs]
    from trimesh.remesh import subdivide_to_size
    size = max((max(np.subtract(_box(m)[3:], _box(m)[:3])) for _, m in bodies), default=1.0)
    parts = []
    for name, m in bodies:
        mesh = m.to_mesh()
        v = np.asarray(mesh.vert_properties, dtype=float)[:, :3]
        f = np.asarray(mesh.tri_verts, dtype=np.int64)
        if not len(f):
            continue
        # small triangles, so that sorting them by their centres draws them in depth order
        v, f = subdivide_to_size(v, f, max_edge=size / 24, max_iter=12)
        P = v[f]                                         # (n, 3, 3)
        nrm = np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0])
        ln = np.linalg.norm(nrm, axis=1)
        keep = ln > 1e-12
        parts.append((P[keep], nrm[keep] / ln[keep, None],
                      np.array(_rgba(colour_of.get(name, "#607d8b"))[:3], dtype=float)))
    boxes = []
    for c in highlight:
        for x0, y0, z0, x1, y1, z1 in (getattr(c, "places", ()) or (c.box,)):   # each piece
            boxes.append(np.array([[x, y, z] for x in (x0, x1) for y in (y0, y1)
                                   for z in (z0, z1)]))
    Image, _ = _pil()
    w = max(16, width // len(views))
    imgs = [_view(output, thickness, parts, boxes, size, az, el, w, caption)
            for caption, (az, el) in views]
    out = Image.new("RGB", (width, max(i.height for i in imgs)), "white")
    for k, im in enumerate(imgs):
        out.paste(im, (k * w, 0))
    import io
    buf = io.BytesIO()
    out.save(buf, format="PNG")
    return buf.getvalue()


def _view(output, thickness, parts, boxes, size, az_deg, el_deg, width, caption):
    """One view of :func:`to_assembled_png` (a Pillow image ``width`` pixels wide): the parts'
    triangles ``parts`` (``(triangles, normals, colour)``), the engraving
    (:func:`_assembled_marks`) and the red ``boxes``, from azimuth ``az_deg`` and elevation
    ``el_deg``, ``caption`` written in its top left corner."""
    import math

    az, el = math.radians(az_deg), math.radians(el_deg)
    # camera axes: right, up, towards the viewer
    fwd = np.array([math.cos(el) * math.sin(az), -math.cos(el) * math.cos(az), math.sin(el)])
    right = np.array([math.cos(az), math.sin(az), 0.0])
    up = np.cross(fwd, right)
    light = fwd * 0.6 + up * 0.6 + right * 0.2
    light /= np.linalg.norm(light)
    tris = []
    for P, nrm, base in parts:
        facing = nrm @ fwd > 0                           # back faces are hidden by the front
        Pf, nf = P[facing], nrm[facing]
        shade = 0.45 + 0.55 * np.clip(nf @ light, 0.0, 1.0)
        tris.append((Pf.mean(axis=1) @ fwd, Pf, shade[:, None] * base[None, :]))
    marks = _assembled_marks(output, thickness, fwd, size)
    Image, ImageDraw = _pil()
    pts = [t[1] for t in tris if len(t[1])] + boxes
    if not pts:
        return Image.new("RGB", (width, max(1, width // 2)), "white")
    allp = np.concatenate([p.reshape(-1, 3) for p in pts])
    X, Y = allp @ right, allp @ up
    x0, x1, y0, y1 = X.min(), X.max(), Y.min(), Y.max()
    span = max(x1 - x0, y1 - y0, 1e-9)
    margin = 0.05 * span
    scale = (width - 2) / (x1 - x0 + 2 * margin or 1.0)
    height = max(1, int(round((y1 - y0 + 2 * margin) * scale)))
    k = 2                                           # drawn twice as large, then scaled down
    img = Image.new("RGB", (width * k, height * k), "white")
    draw = ImageDraw.Draw(img)

    def xy(P):
        P = np.atleast_2d(P)
        u = ((P @ right) - x0 + margin) * scale * k
        v = (y1 + margin - (P @ up)) * scale * k
        return [(float(a), float(b)) for a, b in zip(u, v)]
    depth = np.concatenate([t[0] for t in tris]) if tris else np.zeros(0)
    if len(depth) or len(marks):
        P = np.concatenate([t[1] for t in tris]) if tris else np.zeros((0, 3, 3))
        rgb = np.clip(np.concatenate([t[2] for t in tris]), 0, 255).astype(np.uint8) \
            if tris else np.zeros((0, 3), dtype=np.uint8)
        # the triangles in painter's order, farthest first; then the engraving's segments
        # that no face in front of them covers (tested where each is, against the
        # triangles' depths there: run dq's base disc's lines showed through the top disc)
        order = np.argsort(depth, kind="stable")
        uv = np.stack([((P @ right) - x0 + margin) * scale * k,
                       (y1 + margin - (P @ up)) * scale * k], axis=-1)
        L = marks
        luv = np.stack([((L @ right) - x0 + margin) * scale * k,
                        (y1 + margin - (L @ up)) * scale * k], axis=-1)
        flat_t, fill_t = uv.reshape(len(uv), 6).tolist(), [tuple(c) for c in rgb.tolist()]
        for i in order.tolist():
            draw.polygon(flat_t[i], fill=fill_t[i], outline=fill_t[i])
        seen = _uncovered(uv, P @ fwd, luv.mean(axis=1), L.mean(axis=1) @ fwd, size / 500)
        for seg in luv[seen].reshape(-1, 4).tolist():
            draw.line(seg, fill=MARK_RGB, width=k)
    edges = ((0, 1), (0, 2), (0, 4), (1, 3), (1, 5), (2, 3), (2, 6), (3, 7), (4, 5), (4, 6),
             (5, 7), (6, 7))
    for B in boxes:
        for i, j in edges:
            draw.line(xy(np.array([B[i], B[j]])), fill=(255, 0, 0), width=3 * k)
    img = img.resize((width, height), Image.LANCZOS)
    if caption and width >= 120:
        ImageDraw.Draw(img).text((4, 2), f"from the {caption}", fill=CAPTION_RGB)
    return img


def _uncovered(uv: np.ndarray, depth: np.ndarray, at: np.ndarray, mark_depth: np.ndarray,
               tol: float) -> np.ndarray:
    """Per engraved segment (its middle ``at``, n x 2 pixels; its depth towards the viewer
    ``mark_depth``, mm): True when no front-facing triangle (``uv``: m x 3 x 2 pixels, its
    corners' depths ``depth``: m x 3, mm) covers that point at a depth more than ``tol``
    nearer the viewer (its own face, coplanar, is not nearer).  The triangles each point
    may lie in come from a grid of cells as large as a typical triangle's box (each
    triangle listed in the cells its box spans, each point looked up in its own cell:
    sorting, linear in the triangles and points for triangles of about one size, which the
    picture's subdivision makes them); each pair is tested by its barycentric coordinates."""
    n = len(at)
    if not n or not len(uv):
        return np.ones(n, dtype=bool)
    lo, hi = uv.min(axis=1), uv.max(axis=1)
    cell = max(float(np.median(np.max(hi - lo, axis=1))), 1.0)
    c0 = np.floor(lo / cell).astype(np.int64)
    c1 = np.floor(hi / cell).astype(np.int64)
    span = c1 - c0 + 1
    count = span[:, 0] * span[:, 1]
    tri = np.repeat(np.arange(len(uv)), count)
    k = np.arange(len(tri)) - np.repeat(np.cumsum(count) - count, count)
    w = np.repeat(span[:, 0], count)
    cx, cy = np.repeat(c0[:, 0], count) + k % w, np.repeat(c0[:, 1], count) + k // w
    key = cx * 1_000_003 + cy
    order = np.argsort(key, kind="stable")
    key, tri = key[order], tri[order]
    pc = np.floor(at / cell).astype(np.int64)
    pkey = pc[:, 0] * 1_000_003 + pc[:, 1]
    first, last = np.searchsorted(key, pkey, "left"), np.searchsorted(key, pkey, "right")
    many = last - first
    i = np.repeat(np.arange(n), many)
    j = tri[np.repeat(first, many) + (np.arange(len(i)) - np.repeat(np.cumsum(many) - many,
                                                                     many))]
    if not len(i):
        return np.ones(n, dtype=bool)
    a, b, c = uv[j, 0], uv[j, 1], uv[j, 2]
    v0, v1, v2 = b - a, c - a, at[i] - a
    den = v0[:, 0] * v1[:, 1] - v1[:, 0] * v0[:, 1]
    ok = np.abs(den) > 1e-12
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(ok, (v2[:, 0] * v1[:, 1] - v1[:, 0] * v2[:, 1]) / den, -1.0)
        r = np.where(ok, (v0[:, 0] * v2[:, 1] - v2[:, 0] * v0[:, 1]) / den, -1.0)
    inside = (s >= 0) & (r >= 0) & (s + r <= 1)
    d = depth[j, 0] + s * (depth[j, 1] - depth[j, 0]) + r * (depth[j, 2] - depth[j, 0])
    covered = inside & (d > mark_depth[i] + tol)
    out = np.ones(n, dtype=bool)
    out[i[covered]] = False
    return out


CAPTION_RGB = (110, 110, 110)   # a view's caption: grey, not the engraving's near-black


MARK_RGB = (30, 30, 30)      # the engraving's lines in the assembled picture


def _assembled_marks(output: Output, thickness, fwd, size: float) -> np.ndarray:
    """The engraving of ``output`` (strokes, fills, through-cuts) as it lies on the
    assembled parts: its segments (n x 2 x 3, mm), each on its part's top face (the face the
    laser works, z = the thickness) moved by the part's placement; only where that face looks
    towards the viewer (runs av, aw, bd, bf could not see which face a label landed on; the
    faces in front of a mark hide it, :func:`_uncovered`).  A bent part's marks are bent
    with it (:func:`~..part.build.placement.bend_points`, their lines cut to pieces of at
    most ``size / 400`` first; run ee's card wallet lost its engraving and living-hinge cuts
    from the picture, and nothing said so); which of them face the viewer is then left to
    the faces in front (:func:`_uncovered`)."""
    from ..fabrication.assembly import bends_of, placements
    from ..part.build.placement import bend_points
    from ...geometry.shapes.curves import sample_xy
    from ..part.build.sunk import DEFAULT_THICKNESS
    where, bends = placements(output), bends_of(output)
    thick = {p.name: float(thickness or p.thickness or DEFAULT_THICKNESS)
             for p in output.parts if p.kind == "solid"}
    segs: list = []
    for st in output.engrave:
        if st.part not in thick or not st.segments:
            continue
        M = where.get(st.part)
        R = np.eye(3) if M is None else np.asarray(M, dtype=float)[:3, :3]
        bend = bends.get(st.part)
        if not bend and (R @ np.array([0.0, 0.0, 1.0])) @ fwd <= 1e-9:
            continue                    # the engraved face looks away: hidden by its part
        xs: list = []
        ys: list = []
        sample_xy(st.segments, xs, ys, size / 400)
        end = st.segments[-1].end if hasattr(st.segments[-1], "end") else None
        if st.closed or end is None:
            xs.append(xs[0])
            ys.append(ys[0])
        else:
            xs.append(end[0])
            ys.append(end[1])
        P = np.column_stack([xs, ys, np.full(len(xs), thick[st.part])])
        if bend:                        # round the bend with its part, in short pieces
            step = size / 400
            n = np.maximum(1, np.ceil(np.hypot(*(P[1:, :2] - P[:-1, :2]).T) / step)).astype(int)
            k = np.repeat(np.arange(len(P) - 1), n)
            f = (np.arange(len(k)) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n, n)
            P = np.vstack([P[k] + (P[k + 1] - P[k]) * f[:, None], P[-1:]])
            P = bend_points(P, bend, thick[st.part])
        if M is not None:
            P = P @ R.T + np.asarray(M, dtype=float)[:3, 3]
        segs.append(np.stack([P[:-1], P[1:]], axis=1))
    if not segs:
        return np.zeros((0, 2, 3))
    return np.concatenate(segs)


def _pil():
    """Pillow (installed with the ``png`` extra, which cairosvg needs), or
    :class:`~.part.MissingDependency` naming the install line."""
    try:
        from PIL import Image, ImageDraw
    except ImportError:
        raise MissingDependency("an assembled PNG needs Pillow: pip install 'aidl-lang[png]'"
                                ) from None
    return Image, ImageDraw


def write(output: Output, options) -> bytes:
    """The registry's entry (:data:`~.FORMATS`): the assembled product's picture when
    ``options.assembled`` (``width`` or 800 pixels), else :func:`to_png` with the
    :class:`~.Options` ``dpi``, ``width``, ``show``, ``style`` and ``margin``."""
    if options.assembled:
        return to_assembled_png(output, options.thickness, width=options.width or 800)
    return to_png(output, dpi=options.dpi, width=options.width, show=options.show,
                  style=options.style, margin=options.margin)
