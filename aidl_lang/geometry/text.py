"""Single-stroke text from the Hershey fonts (PyPI ``Hershey-Fonts``; font ``futural``).

Sizes are cap heights in mm.  :func:`text_strokes` gives polylines relative to the anchor point.
"""
from __future__ import annotations

import math
from functools import lru_cache

CAP = 21.0   # Hershey "futural" cap height in font units (normalize_rendering(1) maps ~1 em)


FONT = "futural"


@lru_cache(maxsize=1)
def _font():
    """The font, normalized.  Its glyph table (3.5 KB of text) is kept in the user's cache
    folder (:mod:`aidl_lang.cache`): ``load_default_font`` unpacks a bz2 archive of every
    Hershey font each time, the slowest step of a cold ``aidl check`` of a part with text."""
    from HersheyFonts import HersheyFonts
    from ..cache import cache_dir, read_owned, write_atomic
    f = HersheyFonts()
    d = cache_dir()
    path = d / f"hershey-{FONT}.jhf" if d is not None else None
    lines = read_owned(path) if path is not None else None
    if lines:
        f.read_from_string_lines(lines.splitlines())
    else:
        f.load_default_font(FONT)
        if path is not None:
            write_atomic(path, _font_text(f))
    f.normalize_rendering(1.0)
    return f


def _font_text(f) -> str:
    """The ``.jhf`` text of the default font ``FONT`` as the package ships it."""
    import io
    import tarfile
    raw = f._HersheyFonts__get_compressed_font_bytes()
    with tarfile.open(fileobj=io.BytesIO(raw), mode="r") as tar:
        return tar.extractfile(FONT).read().decode("utf-8")


@lru_cache(maxsize=512)
def _raw(text: str) -> tuple:
    f = _font()
    segs = tuple(((a[0], a[1]), (b[0], b[1])) for a, b in f.lines_for_text(text))
    return segs


def _cap_height() -> float:
    segs = _raw("H")
    ys = [p[1] for s in segs for p in s]
    return (max(ys) - min(ys)) if ys else 1.0


VALIGNS = ("baseline", "middle", "top", "bottom")


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
    base = _baseline()
    k = size / _cap_height()
    xs = [p[0] for s in segs for p in s]
    lo, hi = min(xs), max(xs)
    dx = {"start": -lo, "middle": -(lo + hi) / 2, "end": -hi}[anchor]
    low = min(p[1] for s in segs for p in s)
    dy = {"baseline": 0.0, "middle": -size / 2, "top": -size,
          "bottom": -(low - base) * k}[valign]
    cs, sn = math.cos(rotation), math.sin(rotation)

    def f(p):
        x, y = (p[0] + dx) * k, (p[1] - base) * k + dy
        return (x * cs - y * sn, x * sn + y * cs)
    return [(f(a), f(b)) for a, b in segs]


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


def missing_glyphs(text: str) -> list[str]:
    """Characters of ``text`` the single-stroke font cannot draw (it covers printable ASCII;
    spaces and newlines are layout, not glyphs), each once, in order."""
    out: list[str] = []
    for ch in text:
        if ch in " \n" or ch in out:
            continue
        if not (32 < ord(ch) < 127) or not _raw(ch):
            out.append(ch)
    return out
