"""PDF writer: a 1:1 printed template (scroll saw, coping saw, hand cutting) of the exact
output model (:class:`~.part.Output`), written with ReportLab (the ``pdf`` extra: ``pip
install 'aidl-lang[pdf]'``).

Pages.  By default one page the size of the drawing (its exact extent, or a cutting layout's
sheet) plus :data:`MARGIN` mm on every side and a footer :data:`FOOTER` mm high under it.
With ``page`` (``Options.page``, ``aidl render --page``) the drawing is tiled over pages of a
paper size of :data:`PAGES` (``A4``, ``A3``, ``Letter``, ``Legal``, each also
``-landscape``, e.g. ``A4-landscape``): each page shows a window of the drawing
``page width - 2 margin`` by ``page height - 2 margin - footer`` mm (clipped to it, its edge a
thin grey trim line), and neighbouring windows overlap by :data:`OVERLAP` mm.  Windows are
counted from the drawing's top-left corner: rows ``A``, ``B``, ... downwards, columns ``1``,
``2``, ... to the right, so the page of row ``r`` (0 for ``A``) and column ``c`` (0 for ``1``)
shows the drawing from ``x = x0 + c (window width - OVERLAP)`` and down from ``y = y1 - r
(window height - OVERLAP)`` (x0, y1: the drawing's left and top).  Each page carries its
label large (``B2``), its neighbours' labels beside its edges, crop marks at the window's
corners and registration marks (a circle and a cross) on the middle lines of the overlaps:
the same mark is on both pages, so one page laid over the other with the marks on each other
is in place.  A tile whose window holds no part and no engraving is left out (the footer
says how many).  Every page prints at 100 % ("actual size", never "fit to page").

Geometry.  Every part's outline loops (the cuts) are black, :data:`CUT_WIDTH` pt, and exact:
lines are ``m``/``l`` with their end points; spline spans are their own cubic Béziers; PDF has
no arcs, so every arc, circle and elliptical arc is cut into equal pieces of at most a
quarter turn, each a cubic Bézier through the piece's exact end points with the tangent
handles ``4/3 tan(sweep / 4)`` (the Bézier's middle is on the circle), and into more pieces
when needed so that the Bézier leaves the circle (or ellipse) by at most :data:`ARC_TOL` =
1e-3 mm (:mod:`.beziers`, shared with the LightBurn writer: the bound of a piece of sweep
``t`` is ``r 4/27 sin^6(t/4) / cos^2(t/4)``; an ellipse by its larger semi-axis).  Through-cuts
(a ``cut`` structure's curves, open paths too) are cuts: black, :data:`CUT_WIDTH` pt.
Engraving strokes are blue, :data:`ENGRAVE_WIDTH` pt; an area engraved filled
(``Text(..., font=, fill=true)``, issue 112) is one blue path filled by the non-zero rule
(``f``), its loops the letters and their counters.  Each solid part's name is
printed small inside it, at the point of its material farthest from every cut line found on a
grid (:func:`label_point`).  Coordinates are written to 1e-6 pt (3.5e-7 mm; :data:`DIGITS`)
— ReportLab's own drawing keeps 7 significant digits (2834.123 pt: 3.5e-4 mm off), so the
cut and engrave paths and the scale bar are written as literal path operators
(``Canvas.addLiteral``) and ReportLab does the rest (pages, fonts, text, compression).

Footer, on every page: a 100 mm scale bar with ticks every 10 mm (butt ends: the bar is
100 mm from end to end) and the words "100 mm — check this is 100 mm before cutting", the
program's title, and on a tiled page its label and the grid.

Units: 1 mm = 72 / 25.4 pt (:data:`PT_PER_MM`); y points up in both (PDF's origin is the
page's bottom-left corner), so a point (x, y) mm of the drawing is at ((x - ox) * 72 / 25.4,
(y - oy) * 72 / 25.4) pt on a page whose bottom-left corner is the drawing's (ox, oy).  Raises
:class:`~.part.OutputError` for an unknown page name (naming the choices), a margin that
leaves no window, a page over :data:`MAX_PAGE_PT` (the largest page PDF readers take) or more
than :data:`MAX_PAGES` tiles; :class:`~.part.MissingDependency` without ReportLab.
Reference: ISO 32000-1 (PDF 1.7), 8.5 "Path construction and painting".
"""
from __future__ import annotations

import io
import math

import numpy as np

from ..part.extent import extent
from ..part.part import (Arc, Circle, EllipticArc, Line, MissingDependency, Output, OutputError,
                         fill_regions)
from ..part.edges.shared import cut_once, loop_paths
from . import beziers

PT_PER_MM = 72.0 / 25.4
DIGITS = 6                 # decimals of a pt written for paths: 1e-6 pt = 3.5e-7 mm
ARC_TOL = 1e-3             # mm: the most a Bézier piece of an arc strays from the circle
MARGIN = 10.0              # mm: blank border of every page (printers do not print to the edge)
FOOTER = 22.0              # mm: the scale bar, its words, the title (and the page label)
OVERLAP = 10.0             # mm: what neighbouring tiles share
CHAIN_TOL = 1e-6           # mm: a segment starting this close to the pen continues the subpath
CUT_WIDTH = 0.2            # pt
ENGRAVE_WIDTH = 0.15       # pt
MARK_WIDTH = 0.1           # pt: trim lines, crop and registration marks, the sheet's edge
BAR_WIDTH = 0.5            # pt: the scale bar
TICK_WIDTH = 0.25          # pt: its ticks
BAR_LENGTH = 100.0         # mm
CHECK_TEXT = "100 mm \u2014 check this is 100 mm before cutting"
MAX_PAGE_PT = 14400.0      # pt (200 in, 5.08 m): the largest page side PDF readers show
MAX_PAGES = 400
# paper sizes (width, height) in mm, portrait; "-landscape" swaps them
PAGES = {"A4": (210.0, 297.0), "A3": (297.0, 420.0), "Letter": (215.9, 279.4),
         "Legal": (215.9, 355.6)}
CUT_RGB = (0.0, 0.0, 0.0)
ENGRAVE_RGB = (0.0, 0.0, 1.0)
MARK_RGB = (0.5, 0.5, 0.5)
SHEET_RGB = (0.6, 0.6, 0.6)


def page_names() -> list[str]:
    """Every page name :func:`page_size` knows: ``A4``, ``A4-landscape``, ..."""
    return [n + s for n in PAGES for s in ("", "-landscape")]


def page_size(name: str) -> tuple[float, float]:
    """(width, height) mm of a paper size of :data:`PAGES` (any case; ``-landscape`` turns
    it).  Raises :class:`~.part.OutputError` naming the choices for an unknown name."""
    key = name.strip().lower()
    land = key.endswith("-landscape")
    if land:
        key = key[:-len("-landscape")]
    for n, (w, h) in PAGES.items():
        if n.lower() == key:
            return (h, w) if land else (w, h)
    raise OutputError(f"unknown page `{name}`; use one of {', '.join(page_names())} (or no "
                      "page: one page the size of the drawing)")


# ------------------------------------------------------------------ path operators
def _n(v: float) -> str:
    s = f"{v:.{DIGITS}f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


class _Pen:
    """Writes path operators of mm geometry on a page whose bottom-left corner is the
    drawing's (ox, oy) mm."""

    def __init__(self, ox: float, oy: float):
        self.ox, self.oy = ox, oy

    def p(self, q) -> str:
        return f"{_n((q[0] - self.ox) * PT_PER_MM)} {_n((q[1] - self.oy) * PT_PER_MM)}"

    def path(self, segments, closed: bool) -> list[str]:
        """Operators of a chain of segments: one subpath per run each starting within
        :data:`CHAIN_TOL` of the previous end (a gap is a move, never a drawn line); a
        circle or a whole ellipse or spline is a closed subpath of its own."""
        out: list[str] = []
        here = None
        for s in segments:
            if isinstance(s, Circle):
                whole = Arc(s.center, s.radius, 0.0, 2 * math.pi if s.ccw else -2 * math.pi)
                out.append(f"{self.p(whole.start)} m")
                out += [f"{self.p(b[1])} {self.p(b[2])} {self.p(b[3])} c"
                        for b in beziers.arc_beziers(whole, ARC_TOL)]
                out.append("h")
                here = None
                continue
            if here is None or math.dist(here, s.start) > CHAIN_TOL:
                out.append(f"{self.p(s.start)} m")
            if isinstance(s, Line):
                out.append(f"{self.p(s.end)} l")
            else:
                bs = (beziers.arc_beziers(s, ARC_TOL) if isinstance(s, Arc) else
                      beziers.ellipse_beziers(s, ARC_TOL) if isinstance(s, EllipticArc) else
                      s.spans)
                out += [f"{self.p(b[1])} {self.p(b[2])} {self.p(b[3])} c" for b in bs]
            here = s.end
        if closed and segments and not isinstance(segments[-1], Circle):
            out.append("h")
        return out


def _rgb(c) -> str:
    return f"{c[0]:g} {c[1]:g} {c[2]:g} RG"


# ------------------------------------------------------------------ labels
def label_point(part, strokes=()) -> tuple[tuple[float, float], float]:
    """Where to print a part's name: ``(point, clearance)`` mm, the point of a 24 x 24 grid
    over the part's box inside its material (even-odd over its loops' chords) farthest
    from every loop and every engraving stroke of ``strokes`` (:class:`~.part.Stroke`), and
    that distance; the box's centre (clearance 0) when no grid point is inside."""
    from ..part.part import sample_xy
    pts = [lp.points() for lp in part.loops]
    pts = [p for p in pts if len(p) >= 3]
    if not pts:
        return (0.0, 0.0), 0.0
    allp = np.vstack(pts)
    x0, y0 = allp.min(axis=0)
    x1, y1 = allp.max(axis=0)
    gx, gy = np.meshgrid(np.linspace(x0, x1, 26)[1:-1], np.linspace(y0, y1, 26)[1:-1])
    q = np.column_stack([gx.ravel(), gy.ravel()])
    inside = np.zeros(len(q), dtype=bool)
    dist = np.full(len(q), np.inf)
    qx, qy = q[:, 0][:, None], q[:, 1][:, None]
    marks = []                                  # engraving: kept clear of, never "inside"
    for st in strokes:
        xs: list = []
        ys: list = []
        sample_xy(st.segments, xs, ys)
        if not isinstance(st.segments[-1], Circle):
            xs.append(st.segments[-1].end[0])
            ys.append(st.segments[-1].end[1])
        e = np.column_stack([xs, ys]) if xs else np.zeros((0, 2))
        if len(e) and e[:, 0].max() >= x0 and e[:, 0].min() <= x1 and \
                e[:, 1].max() >= y0 and e[:, 1].min() <= y1:
            marks.append(e)
    for p, loop in [(p, True) for p in pts] + [(e, False) for e in marks]:
        nxt = np.roll(p, -1, axis=0) if loop else np.vstack([p[1:], p[-1:]])
        for i in range(0, len(p), 512):        # edges in blocks: bounded memory
            a = p[i:i + 512]
            b = nxt[i:i + 512]
            # even-odd: edges crossing the horizontal ray to the right of each grid point
            ay, by = a[:, 1][None, :], b[:, 1][None, :]
            crosses = (ay > qy) != (by > qy)
            with np.errstate(divide="ignore", invalid="ignore"):
                xc = a[:, 0][None, :] + (qy - ay) * (b[:, 0] - a[:, 0])[None, :] / (by - ay)
            if loop:
                inside ^= (crosses & (xc > qx)).sum(axis=1) % 2 == 1
            d = b - a
            ll = np.maximum((d ** 2).sum(axis=1), 1e-30)
            t = np.clip(((qx - a[:, 0]) * d[:, 0] + (qy - a[:, 1]) * d[:, 1]) / ll, 0, 1)
            nx, ny = a[:, 0] + t * d[:, 0], a[:, 1] + t * d[:, 1]
            dist = np.minimum(dist, np.hypot(qx - nx, qy - ny).min(axis=1))
    if not inside.any():
        return (float((x0 + x1) / 2), float((y0 + y1) / 2)), 0.0
    dist[~inside] = -1
    i = int(np.argmax(dist))
    return (float(q[i, 0]), float(q[i, 1])), float(dist[i])


def _short(name: str) -> str:
    return name.rsplit(".", 1)[-1] if len(name) > 40 else name


# ------------------------------------------------------------------ the document
def _tiles(box, page, margin):
    """``(page_w, page_h, window_w, window_h, cols, rows)`` mm."""
    x0, y0, x1, y1 = box
    w, h = x1 - x0, y1 - y0
    if page is None:
        ww, wh = w, h
        return w + 2 * margin, h + 2 * margin + FOOTER, ww, wh, 1, 1
    pw, ph = page_size(page)
    ww, wh = pw - 2 * margin, ph - 2 * margin - FOOTER
    if ww <= 2 * OVERLAP or wh <= 2 * OVERLAP:
        raise OutputError(f"a margin of {margin:g} mm leaves no room to draw on a {page} page; "
                          "use a smaller --margin")

    def count(size, win):
        return 1 if size <= win + 1e-9 else 1 + math.ceil((size - win) / (win - OVERLAP) - 1e-9)
    return pw, ph, ww, wh, count(w, ww), count(h, wh)


def to_pdf(output: Output, page: str | None = None, margin: float | None = None,
           title: str = "") -> bytes:
    """The PDF bytes of ``output`` (see the module docstring): one page the size of the
    drawing, or tiles of paper size ``page`` (:data:`PAGES`); ``margin`` mm (default
    :data:`MARGIN`)."""
    try:
        from reportlab.pdfgen.canvas import Canvas
    except ImportError as e:
        raise MissingDependency("PDF output needs ReportLab: pip install 'aidl-lang[pdf]' "
                                f"({e})") from None
    if margin is None:
        margin = MARGIN
    if not 0 <= margin < math.inf:
        raise OutputError(f"the PDF margin must be a length of 0 mm or more, got {margin}")
    title = title or output.title or "AIDL drawing"
    box = extent(output)
    x0, y0, x1, y1 = box
    pw, ph, ww, wh, cols, rows = _tiles(box, page, margin)
    if page is None:
        pw = max(pw, BAR_LENGTH + 2 * margin + 20.0)     # room for the footer
    if max(pw, ph) * PT_PER_MM > MAX_PAGE_PT:
        raise OutputError(f"the page would be {pw:.0f} x {ph:.0f} mm, larger than PDF readers "
                          f"show ({MAX_PAGE_PT / PT_PER_MM:.0f} mm a side); tile it on paper "
                          "with --page A4 (or A3, Letter)")
    if cols * rows > MAX_PAGES:
        raise OutputError(f"the template would be {cols * rows} pages of {page} "
                          f"({rows} rows x {cols} columns), more than {MAX_PAGES}; use a "
                          "larger --page or no --page")
    buf = io.BytesIO()
    c = Canvas(buf, pagesize=(pw * PT_PER_MM, ph * PT_PER_MM), invariant=1,
               pageCompression=1)
    c.setTitle(title)
    c.setAuthor("AIDL")
    c.setSubject("1:1 template: print at 100 % (actual size)")
    c.setCreator("aidl render")
    tiled = page is not None
    windows = {}
    for r in range(rows):
        for col in range(cols):
            # the window in drawing coordinates (a tile's: counted from the top-left corner)
            wx0 = x0 + col * (ww - OVERLAP) if tiled else x0
            wy1 = y1 - r * (wh - OVERLAP) if tiled else y1
            windows[r, col] = (wx0, wy1 - wh, wx0 + ww, wy1)
    if tiled:                        # a tile with nothing on it is left out
        boxes = _boxes(output)
        kept = {k: w for k, w in windows.items() if any(_overlaps(b, w) for b in boxes)}
        windows = kept or windows
    grid = (rows, cols, len(windows), rows * cols - len(windows))
    labels = {id(p): label_point(p, [st for st in output.engrave if st.segments])
              for p in output.parts if p.kind == "solid" and p.loops}
    for n, ((r, col), win) in enumerate(windows.items()):
        # the drawing point at the page's bottom-left corner
        pen = _Pen(win[0] - margin, win[1] - margin - FOOTER)
        _page(c, output, pen, win, tiled, labels)
        tile = (r, col, n, grid, set(windows)) if tiled else None
        _marks(c, pen, win, tile)
        _footer(c, title, pw, margin, tile, page)
        c.showPage()
    c.save()
    return buf.getvalue()


def _label(r: int, col: int) -> str:
    row = ""
    r += 1
    while r:
        r, k = divmod(r - 1, 26)
        row = chr(65 + k) + row
    return f"{row}{col + 1}"


def _boxes(output: Output) -> list:
    """The exact box of every part and engraving stroke."""
    out = []
    for segs in [[s for lp in p.loops for s in lp.segments] for p in output.parts] + \
            [st.segments for st in output.engrave]:
        bs = [s.box() for s in segs]
        if bs:
            out.append((min(b[0] for b in bs), min(b[1] for b in bs), max(b[2] for b in bs),
                        max(b[3] for b in bs)))
    return out


def _overlaps(bb, win) -> bool:
    return bb[0] <= win[2] and bb[2] >= win[0] and bb[1] <= win[3] and bb[3] >= win[1]


def _page(c, output: Output, pen: _Pen, win, tiled: bool, where: dict) -> None:
    """The drawing on one page: the window's clip (tiles), the sheet's edge, the cuts, the
    engraving, the part names."""
    ops = ["q", "1 j 1 J"]
    if tiled:          # draw only inside the window: the overlap is the only shared strip
        a, b = pen.p((win[0], win[1])), pen.p((win[2], win[3]))
        (ax, ay), (bx, by) = map(float, a.split()), map(float, b.split())
        ops.append(f"{_n(ax)} {_n(ay)} {_n(bx - ax)} {_n(by - ay)} re W n")
    if output.page is not None:
        sx0, sy0, sx1, sy1 = output.page
        ops += [_rgb(SHEET_RGB), f"{MARK_WIDTH:g} w", f"{pen.p((sx0, sy0))} m",
                f"{pen.p((sx1, sy0))} l", f"{pen.p((sx1, sy1))} l", f"{pen.p((sx0, sy1))} l",
                "h S"]
    ops += [_rgb(CUT_RGB), f"{CUT_WIDTH:g} w"]
    labels = []
    once = cut_once(output)         # pieces of one cut part: each shared edge once
    for i, p in enumerate(output.parts):
        boxes = [s.box() for lp in p.loops for s in lp.segments]
        if not boxes:
            continue
        bb = (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes),
              max(b[3] for b in boxes))
        if not _overlaps(bb, win):
            continue
        for k, lp in enumerate(p.loops):
            for segs, closed in loop_paths(once, i, k, lp):
                ops += pen.path(segs, closed)
        ops.append("S")
        if p.kind == "solid":
            labels.append(p)
    cuts = [st for st in output.cuts if st.segments]
    if cuts:                        # through-cuts: black, at the cut width, as they run
        for st in cuts:
            ops += pen.path(st.segments, st.closed)
        ops.append("S")
    for _, _, loops in fill_regions(output.engrave):   # areas engraved filled: blue, filled
        ops += [_rgb(ENGRAVE_RGB), _rgb(ENGRAVE_RGB).replace("RG", "rg")]   # blue, not a cut
        for segs in loops:
            ops += pen.path(segs, True)
        ops.append("f")
    strokes = [st for st in output.engrave if st.segments and st.style not in ("cut", "fill")]
    if strokes:
        ops += [_rgb(ENGRAVE_RGB), f"{ENGRAVE_WIDTH:g} w"]
        for st in strokes:
            ops += pen.path(st.segments, st.closed)
        ops.append("S")
    c.addLiteral("\n".join(ops))
    c.setFillColorRGB(0.25, 0.25, 0.25)
    for p in labels:
        (lx, ly), room = where[id(p)]
        if not (win[0] <= lx <= win[2] and win[1] <= ly <= win[3]):
            continue
        size = 6.0 if room <= 0 else max(3.0, min(6.0, room * PT_PER_MM * 0.9))
        name = _short(p.name)
        x, y = map(float, pen.p((lx, ly)).split())
        c.setFont("Helvetica", size)
        c.drawCentredString(x, y - size * 0.35, name)
    c.addLiteral("Q")


def _marks(c, pen: _Pen, win, tile) -> None:
    """A tile's trim line, crop marks at its corners and registration marks on the middle
    lines of its overlaps with its neighbours (in drawing coordinates: the same mark on both
    pages)."""
    if tile is None:
        return
    ops = ["q", _rgb(MARK_RGB), f"{MARK_WIDTH:g} w", "0 J"]
    wx0, wy0, wx1, wy1 = win
    ops += [f"{pen.p((wx0, wy0))} m", f"{pen.p((wx1, wy0))} l", f"{pen.p((wx1, wy1))} l",
            f"{pen.p((wx0, wy1))} l", "h S"]
    gap, arm = 1.0, 5.0                                   # mm: crop marks outside the corners
    for x, sx in ((wx0, -1), (wx1, 1)):
        for y, sy in ((wy0, -1), (wy1, 1)):
            ops += [f"{pen.p((x + sx * gap, y))} m", f"{pen.p((x + sx * (gap + arm), y))} l",
                    f"{pen.p((x, y + sy * gap))} m", f"{pen.p((x, y + sy * (gap + arm)))} l"]
    ops.append("S")
    # registration marks: on the middle line of each overlap with a page printed, in the
    # middle of the window's side
    r, col, _, _, kept = tile
    mx, my = (wx0 + wx1) / 2, (wy0 + wy1) / 2
    spots = [xy for (dr, dc), xy in (((0, -1), (wx0 + OVERLAP / 2, my)),
                                     ((0, 1), (wx1 - OVERLAP / 2, my)),
                                     ((-1, 0), (mx, wy1 - OVERLAP / 2)),
                                     ((1, 0), (mx, wy0 + OVERLAP / 2)))
             if (r + dr, col + dc) in kept]
    for x, y in spots:
        ops += [f"{pen.p((x - 4, y))} m", f"{pen.p((x + 4, y))} l",
                f"{pen.p((x, y - 4))} m", f"{pen.p((x, y + 4))} l"]
        ops += pen.path([Circle((x, y), 2.5)], True)
    ops += ["S", "Q"]
    c.addLiteral("\n".join(ops))
    # the neighbours' labels, in the margin beside the edges they overlap
    c.setFillColorRGB(0.35, 0.35, 0.35)
    c.setFont("Helvetica", 7)
    for (dr, dc), (x, y), turn in (((0, -1), (wx0 - 2.5, (wy0 + wy1) / 2), 90),
                                   ((0, 1), (wx1 + 2.5, (wy0 + wy1) / 2), -90),
                                   ((-1, 0), ((wx0 + wx1) / 2, wy1 + 2.5), 0),
                                   ((1, 0), ((wx0 + wx1) / 2, wy0 - 4.5), 0)):
        if (r + dr, col + dc) in kept:
            px, py = map(float, pen.p((x, y)).split())
            c.saveState()
            c.translate(px, py)
            c.rotate(turn)
            c.drawCentredString(0, -2.5 if turn else 0, f"overlaps {_label(r + dr, col + dc)}")
            c.restoreState()


def _footer(c, title: str, pw: float, margin: float, tile, page) -> None:
    """The scale bar (exact, butt ends), its words, the title, and a tile's label and grid."""
    k = PT_PER_MM
    bx, by = margin, margin + 7.0                        # mm: the bar's left end
    ops = ["q", "0 0 0 RG", f"{BAR_WIDTH:g} w", "0 J",
           f"{_n(bx * k)} {_n(by * k)} m {_n((bx + BAR_LENGTH) * k)} {_n(by * k)} l S",
           f"{TICK_WIDTH:g} w"]
    for i in range(11):
        x = bx + 10.0 * i
        up = 3.5 if i in (0, 5, 10) else 2.0
        ops.append(f"{_n(x * k)} {_n(by * k)} m {_n(x * k)} {_n((by + up) * k)} l S")
    ops.append("Q")
    c.addLiteral("\n".join(ops))
    c.setFillColorRGB(0, 0, 0)
    c.setFont("Helvetica", 6)
    for i, t in ((0, "0"), (5, "50"), (10, "100 mm")):
        c.drawString((bx + 10.0 * i) * k + 1.5, (by + 2.2) * k, t)
    c.setFont("Helvetica", 7.5)
    c.drawString(bx * k, (margin + 1.5) * k, CHECK_TEXT)
    c.setFont("Helvetica-Bold", 9)
    c.drawString(bx * k, (margin + FOOTER - 6.0) * k, title)
    if tile is None:
        return
    r, col, n, (rows, cols, pages, empty), _ = tile
    right = (pw - margin) * k
    c.setFont("Helvetica-Bold", 22)
    c.drawRightString(right, (margin + 9.0) * k, _label(r, col))
    c.setFont("Helvetica", 6.5)
    c.drawRightString(right, (margin + 4.0) * k,
                      f"page {n + 1} of {pages}: {page}, "
                      + (f"rows A-{_label(rows - 1, 0)[:-1]}" if rows > 1 else "row A")
                      + (f" x columns 1-{cols}" if cols > 1 else " x column 1")
                      + (f" ({empty} empty left out)" if empty else ""))
    c.drawRightString(right, (margin + 1.5) * k,
                      f"overlap {OVERLAP:g} mm: lay the pages so the + marks meet")


def write(output: Output, options) -> bytes:
    """The registry's entry (:data:`~.FORMATS`): :func:`to_pdf` with the
    :class:`~.Options` ``page`` and ``margin``."""
    return to_pdf(output, page=getattr(options, "page", None), margin=options.margin)
