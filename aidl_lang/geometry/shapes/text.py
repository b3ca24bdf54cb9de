"""Single-stroke text from the Hershey fonts (PyPI ``Hershey-Fonts``; font ``futural``).

The font draws printable ASCII and the symbols of dimensions that DXF text codes decode to
(:data:`SYMBOLS`): ``°`` ``±`` ``×`` from the package's Hershey simplex math font
(``mathlow``), ``µ`` from its simplex Greek (``greek``), and ``Ø`` ``ø`` ``⌀`` composed of
futural's ``O`` (``o``) and a slash corner to corner of its box; all in futural's units.

Sizes are cap heights in mm.  :func:`text_strokes` gives polylines relative to the anchor point.
"""
from __future__ import annotations

import math
from functools import lru_cache

CAP = 21.0   # Hershey "futural" cap height in font units (normalize_rendering(1) maps ~1 em)


FONT = "futural"


_GLYPHS_FORMAT = 2                 # 2: the symbols of SYMBOLS added (issue 71)

# character -> (Hershey font of the package, its character there): the same simplex strokes in
# the same units as futural (their digits and `+` are futural's, point for point)
_BORROWED = {"°": ("mathlow", "`"), "±": ("mathlow", "!"), "×": ("mathlow", "#"),
             "µ": ("greek", "m"), "μ": ("greek", "m")}
# character -> (futural's glyph, the slash added, from its lower left to its upper right, in
# the font's raw units: y down, baseline 9, cap line -12)
_SLASHED = {"Ø": ("O", ((-8, 9), (8, -12))), "⌀": ("O", ((-8, 9), (8, -12))),
            "ø": ("o", ((-6, 9), (7, -5)))}
SYMBOLS = "°±×µμØø⌀"


@lru_cache(maxsize=1)
def _glyphs() -> dict:
    """Every glyph of the font, normalized (``normalize_rendering(1.0)``): character ->
    ``(strokes, advance)``, each stroke a tuple of ``(x, y)`` points at pen position 0 and
    ``advance`` the pen's move to the next character, exactly as the package's render iterator
    computes them.  Kept as JSON in the user's cache folder (:mod:`aidl_lang.host.cache`), so a
    cold run neither imports the package (~10 ms: it imports ``tarfile``) nor unpacks its bz2
    archive of every Hershey font."""
    import json

    from ...host.cache import cache_dir, read_checked, write_checked
    d = cache_dir()
    key = f"hershey {FONT} {_GLYPHS_FORMAT}"
    path = d / f"hershey-{FONT}.json" if d is not None else None
    text = read_checked(path, key) if path is not None else None
    if text:
        try:
            data = json.loads(text)
            out = {c: (tuple(tuple((float(x), float(y)) for x, y in stroke) for stroke in strokes),
                       float(adv)) for c, (strokes, adv) in data.items()}
            if all(type(c) is str and len(c) == 1 for c in out):
                return out
        except (ValueError, TypeError, KeyError, AttributeError):
            pass                          # damaged: made again below
    glyphs = _glyphs_from_package()
    if path is not None:
        write_checked(path, key, json.dumps(glyphs))
    return glyphs


def _glyphs_from_package() -> dict:
    """:func:`_glyphs` from the ``Hershey-Fonts`` package (its ``_HersheyRenderIterator``:
    point ``(xofs + (x - left_offset) * scalex, yofs + y * scaley)``, then
    ``xofs += spacing + scalex * char_width``)."""
    from HersheyFonts import HersheyFonts
    f = HersheyFonts()
    f.load_default_font(FONT)
    f.normalize_rendering(1.0)
    o = f.render_options

    def norm(strokes, left_offset, char_width):
        return (tuple(tuple(((x - left_offset) * o["scalex"], o["yofs"] + y * o["scaley"])
                            for x, y in stroke) for stroke in strokes),
                o["spacing"] + o["scalex"] * char_width)
    out = {ch: norm(g.strokes, g.left_offset, g.char_width) for ch, g in f.all_glyphs.items()}
    fonts: dict = {}
    for ch, (font, src) in _BORROWED.items():
        if font not in fonts:
            fonts[font] = HersheyFonts()
            fonts[font].load_default_font(font)
        g = fonts[font].all_glyphs[src]
        out[ch] = norm(g.strokes, g.left_offset, g.char_width)
    for ch, (src, slash) in _SLASHED.items():
        g = f.all_glyphs[src]
        out[ch] = norm([*g.strokes, list(slash)], g.left_offset, g.char_width)
    return out


@lru_cache(maxsize=512)
def _raw(text: str) -> tuple:
    """The line segments ``((x0, y0), (x1, y1))`` of ``text`` in normalized font units, the
    pen starting at 0: the package's ``lines_for_text``, bit for bit."""
    glyphs = _glyphs()
    segs = []
    pen = 0
    for ch in text:
        g = glyphs.get(ch)
        if g is None:
            continue
        strokes, advance = g
        for stroke in strokes:
            pts = [(pen + x, y) for x, y in stroke]
            segs.extend(zip(pts, pts[1:]))
        pen += advance
    return tuple(segs)


def _cap_height() -> float:
    segs = _raw("H")
    ys = [p[1] for s in segs for p in s]
    return (max(ys) - min(ys)) if ys else 1.0


VALIGNS = ("baseline", "middle", "top", "bottom")


def _placement(segs: list, size: float, anchor: str, valign: str) -> tuple:
    """``(base, k, dx, dy)`` of the font's strokes ``segs`` drawn ``size`` mm tall: the font's
    baseline, its scale to mm, and the shifts (dx in font units, dy in mm) that put the
    position point at ``anchor`` (start, middle, end) and ``valign`` (baseline, middle, top,
    bottom)."""
    base = _baseline()
    k = size / _cap_height()
    xs = [p[0] for s in segs for p in s]
    lo, hi = min(xs), max(xs)
    dx = {"start": -lo, "middle": -(lo + hi) / 2, "end": -hi}[anchor]
    low = min(p[1] for s in segs for p in s)
    dy = {"baseline": 0.0, "middle": -size / 2, "top": -size,
          "bottom": -(low - base) * k}[valign]
    return base, k, dx, dy


def text_strokes(text: str, size: float, anchor: str = "middle", valign: str = "baseline",
                 rotation: float = 0.0) -> list[tuple[tuple, tuple]]:
    """Line segments ((x0, y0), (x1, y1)) in mm, relative to the text's position point.

    ``anchor`` (start, middle, end) puts the position at the left end, middle or right end of
    the strokes; ``valign`` puts it on the baseline, at half the cap height (middle), at the cap
    height (top) or at the lowest stroke (bottom, below descenders); ``rotation`` (radians)
    then turns the text counter-clockwise about the position.
    """
    segs = _raw(text)
    if not segs:
        return []
    base, k, dx, dy = _placement(segs, size, anchor, valign)
    cs, sn = math.cos(rotation), math.sin(rotation)

    def f(p):
        x, y = (p[0] + dx) * k, (p[1] - base) * k + dy
        return (x * cs - y * sn, x * sn + y * cs)
    return [(f(a), f(b)) for a, b in segs]


def text_strokes_along(text: str, size: float, radius: float, angle: float,
                       anchor: str = "middle", valign: str = "baseline",
                       flip: bool = False) -> list[tuple[tuple, tuple]]:
    """Line segments in mm relative to the center of a circle of ``radius`` mm: the text laid
    along the circle clockwise (left to right over the top), each letter upright (its up
    pointing away from the center) and rigid, its middle on the circle at the arc length of
    its middle along the straight text.  ``angle`` (radians, counter-clockwise from +x) is
    where the straight text's position point lands: ``anchor`` and ``valign`` as in
    :func:`text_strokes` (baseline on the circle by default).  ``flip``: counter-clockwise
    instead, each letter's up toward the center (readable under a circle)."""
    glyphs = _glyphs()
    segs = _raw(text)
    if not segs or radius <= 0:
        return []
    base, k, dx, dy = _placement(segs, size, anchor, valign)
    out = []
    pen = 0.0
    for ch in text:
        g = glyphs.get(ch)
        if g is None:
            continue
        strokes, advance = g
        mid = (pen + advance / 2 + dx) * k           # the letter's middle along the text (mm)
        sg = -1.0 if flip else 1.0
        t = angle - sg * mid / radius                # clockwise (flip: counter-clockwise)
        er = (math.cos(t), math.sin(t))              # outward
        tg = (sg * math.sin(t), -sg * math.cos(t))   # along the reading direction
        for stroke in strokes:
            pts = []
            for x, y in stroke:
                u = (pen + x + dx) * k - mid
                v = radius + sg * ((y - base) * k + dy)   # up: away from (flip: toward) the center
                pts.append((v * er[0] + u * tg[0], v * er[1] + u * tg[1]))
            out.extend(zip(pts, pts[1:]))
        pen += advance
    return out


@lru_cache(maxsize=1)
def _baseline() -> float:
    segs = _raw("H")
    ys = [p[1] for s in segs for p in s]
    return min(ys) if ys else 0.0


def text_extent(text: str, size: float, anchor: str = "middle", valign: str = "baseline",
                rotation: float = 0.0) -> tuple[float, float, float, float]:
    """(x0, x1, y0, y1) of the strokes relative to the position point, in mm."""
    segs = text_strokes(text, size, anchor, valign, rotation)
    if not segs:
        return (0.0, 0.0, 0.0, 0.0)
    xs = [p[0] for s in segs for p in s]
    ys = [p[1] for s in segs for p in s]
    return min(xs), max(xs), min(ys), max(ys)


def fit_size(text: str, size: float, max_width: float, extra: float = 0.0,
             per_size: float = 0.0) -> tuple[float, float]:
    """``(the size, the width at size)``: ``size`` when ``text`` is at most ``max_width`` mm
    wide along its baseline, else the size (mm, cap height) at which it is exactly
    ``max_width`` wide.  The width is the strokes' extent plus ``extra`` mm and ``per_size``
    times the size (a stencil's stroke weight, given or a share of the size); the strokes
    scale with the size, so the size that fits is exact.  Raises ValueError for a
    ``max_width`` that ``extra`` alone fills."""
    x0, x1, _, _ = text_extent(text, size, "start")
    wide = (x1 - x0) + extra + per_size * size
    if wide <= max_width:
        return size, wide
    if max_width <= extra:
        raise ValueError(f"max_width {max_width:g} mm is not wider than {extra:g} mm")
    per = (x1 - x0) / size + per_size              # mm of width per mm of size
    return (max_width - extra) / per, wide


def wraps(text: str, size: float, r: float) -> tuple[str, str] | None:
    """(what, the fix) when ``text`` at ``size`` laid along a circle of radius ``r`` (mm) is
    longer than the whole circle, so that its last letters run round onto its first ones
    (W0111); else None."""
    x0, x1, _, _ = text_extent(text, size)
    w, around = x1 - x0, 2 * math.pi * r
    if not (r > 0 and w > around):
        return None
    fit = math.floor(size * around / w * 100) / 100
    return ((f"(\"{text[:40]}\") is {w:.4g} mm long along a circle only {around:.4g} mm "
             f"around (radius {r:.4g} mm): its last letters run round onto its first ones"),
            (f"use a size of at most {fit:g} mm, a circle of radius at least "
             f"{math.ceil(w / (2 * math.pi) * 100) / 100:g} mm, or a shorter text"))


def missing_glyphs(text: str) -> list[str]:
    """Characters of ``text`` the single-stroke font cannot draw (it covers printable ASCII and
    :data:`SYMBOLS`; spaces and newlines are layout, not glyphs), each once, in order."""
    out: list[str] = []
    for ch in text:
        if ch in " \n" or ch in out:
            continue
        if (not (32 < ord(ch) < 127) and ch not in SYMBOLS) or not _raw(ch):
            out.append(ch)
    return out
