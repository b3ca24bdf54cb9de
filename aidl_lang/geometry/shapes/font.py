"""Text as the closed outlines of a real font (issue 112): ``Text(..., font=...)``.

The font is read by fontTools (the glyphs' outlines, at the variable font's axis values for a
style such as ``Bold``) and the text is shaped by HarfBuzz (uharfbuzz: kerning, ligatures,
right-to-left runs and combining marks as the font says).  Each glyph contour becomes an
exact :class:`~.curves.Loop`: its straight pieces :class:`~.curves.Line`, each run of curves
one :class:`~.spline.CubicSpline` (a TrueType quadratic is raised to the cubic that is the same
curve, exactly; a CFF cubic is kept), so the outputs write the font's curves, not chords.

Families: ``"sans"`` (Noto Sans) and ``"serif"`` (Noto Serif) install with the package from
PyPI (``fontpkg-noto-sans``, ``fontpkg-noto-serif``, OFL-1.1; variable fonts, weights 100 to
900 and italics); any other family installed as a ``fontpkg`` package is found by its name;
else, where fontconfig's ``fc-match`` is present, the families it knows.  A style follows a
colon: ``"sans:Bold"``, ``"Noto Serif:Light Italic"``, ``"sans:650"``.  A file is read by
the interpreter (the import sandbox) and handed here as bytes.

Sizes: ``size`` is the cap height in mm (the height of ``H`` in the font, else the font's
``OS/2`` cap height), as for the single-stroke font; the outlines are in mm relative to the
text's position point, before its rotation (:func:`outlines`).
"""
from __future__ import annotations

import hashlib
import shutil
import subprocess
from functools import lru_cache

from .curves import Line, Loop, Spline
from .spline import CubicSpline

DEFAULT_FAMILIES = {"sans": "Noto Sans", "sans-serif": "Noto Sans", "serif": "Noto Serif"}
FONT_EXTS = (".ttf", ".otf", ".ttc")
WEIGHTS = {"thin": 100, "hairline": 100, "extralight": 200, "ultralight": 200, "light": 300,
           "normal": 400, "regular": 400, "book": 400, "medium": 500, "semibold": 600,
           "demibold": 600, "bold": 700, "extrabold": 800, "ultrabold": 800, "black": 900,
           "heavy": 900}
MAX_GLYPHS = 2000           # glyphs of one Text (each a few loops of tens of curves)


class FontError(ValueError):
    """A font that cannot be found or read, or a text it cannot draw; ``hint``: the fix."""

    def __init__(self, message: str, hint: str | None = None):
        super().__init__(message)
        self.hint = hint


# ------------------------------------------------------------------ finding the font
def is_path(spec: str) -> bool:
    """True when ``font=`` names a file (``.ttf``, ``.otf``, ``.ttc``, maybe ``:style``)."""
    head = spec.split(":", 1)[0] if ":" in spec else spec
    return head.strip().lower().endswith(FONT_EXTS)


def split_spec(spec: str) -> tuple[str, str]:
    """``(family or path, style)`` of ``font=``: ``"sans:Bold"`` -> ``("sans", "Bold")``."""
    name, _, style = spec.partition(":")
    return name.strip(), style.strip()


def parse_style(style: str) -> tuple[int | None, bool]:
    """``(weight 1-1000 or None, italic)`` of a style such as ``"Bold Italic"`` or ``"650"``;
    raises :class:`FontError` naming a word it does not know."""
    weight, italic = None, False
    said = style.replace("-", " ").replace("_", " ").split()
    joined = "".join(said).lower()
    if joined in WEIGHTS:
        return WEIGHTS[joined], False
    for w0 in said:
        w = w0.lower()
        if w in ("italic", "oblique"):
            italic = True
        elif w in WEIGHTS:
            weight = WEIGHTS[w]
        elif w.isdigit() and 1 <= int(w) <= 1000:
            weight = int(w)
        else:
            raise FontError(f"font style `{style}`: `{w0}` is no weight or slant",
                            hint="a style is weight words (Thin, Light, Regular, Medium, "
                                 "SemiBold, Bold, Black or a number 100-900) and Italic, "
                                 "e.g. `font=\"sans:Bold Italic\"`")
    return weight, italic


class Face:
    """A resolved font: its bytes' key, where it comes from (``label``: the family and style,
    or the file as written), the face index in a collection and the variable axes' values."""
    __slots__ = ("key", "label", "path", "data", "index", "variations")

    def __init__(self, label: str, path: str | None = None, data: bytes | None = None,
                 index: int = 0, variations: tuple = ()):
        self.label, self.path, self.data = label, path, data
        self.index, self.variations = index, tuple(variations)
        digest = hashlib.sha256(data).hexdigest() if data is not None else path
        self.key = (digest, index, self.variations)

    def __reduce__(self):          # kept in a model that is pickled
        return (Face, (self.label, self.path, self.data, self.index, self.variations))

    def __eq__(self, other) -> bool:
        return isinstance(other, Face) and other.key == self.key

    def __hash__(self) -> int:
        return hash(self.key)


def installed_families() -> dict[str, object]:
    """The ``fontpkg`` families installed (slug -> family), none when ``fontpkg`` is not."""
    try:
        import fontpkg
    except ImportError:                                     # pragma: no cover
        return {}
    try:
        return fontpkg.families()
    except Exception:                                       # a broken third-party package
        return {}


def family_names() -> list[str]:
    """The family names ``font=`` finds without fontconfig, for hints."""
    return ["sans", "serif"] + sorted(f.name for f in installed_families().values()
                                      if f.name not in DEFAULT_FAMILIES.values())


def _slug(name: str) -> str:
    return "-".join(name.strip().lower().replace("_", " ").split())


@lru_cache(maxsize=64)
def resolve(spec: str) -> Face:
    """The :class:`Face` of a family ``font=`` (not a path: the interpreter reads those):
    the built-in ``sans``/``serif``, an installed ``fontpkg`` family, else fontconfig's
    (``fc-match``) when it knows the family by that name (kept per process: a family
    installed while it runs is found by the next).  Raises :class:`FontError`."""
    name, style = split_spec(spec)
    weight, italic = parse_style(style) if style else (None, False)
    fam_name = DEFAULT_FAMILIES.get(name.lower(), name)
    fams = installed_families()
    fam = fams.get(_slug(fam_name))
    if fam is not None:
        return _from_fontpkg(fam, spec, weight, italic)
    found = _fontconfig(fam_name, style)
    if found is not None:
        path, index = found
        face = Face(spec, path=path, index=index)
        return Face(spec, path=path, index=index, variations=weight_axis(face, weight))
    if fam_name != name:
        raise FontError(f"the font family `{name}` ({fam_name}) is not installed",
                        hint="reinstall aidl-lang: `pip install aidl-lang` brings "
                             "fontpkg-noto-sans and fontpkg-noto-serif")
    raise FontError(f"no font family `{name}` is installed",
                    hint="families: " + ", ".join(f"\"{n}\"" for n in family_names())
                    + " (more: `pip install fontpkg-FAMILY`, or fontconfig's), or a .ttf, "
                      ".otf or .ttc file beside the program: `font=\"fonts/MyFont.ttf\"`")


def _from_fontpkg(fam, spec: str, weight: int | None, italic: bool) -> Face:
    style = "italic" if italic else "normal"
    files = [f for f in fam.files if f.style == style]
    if not files:
        raise FontError(f"the font family `{fam.name}` has no {style} style",
                        hint=f"styles: {', '.join(sorted({f.style for f in fam.files}))}")
    w = 400 if weight is None else weight
    for f in files:
        if f.variable and f.wght_min is not None and f.wght_max is not None:
            if f.wght_min <= w <= f.wght_max:
                return Face(spec, path=str(f.path), variations=(("wght", float(w)),))
    static = [f for f in files if f.weight is not None]
    exact = [f for f in static if f.weight == w]
    if exact:
        return Face(spec, path=str(exact[0].path))
    have = sorted({f.weight for f in static}) or [
        f"{f.wght_min}-{f.wght_max}" for f in files if f.wght_min is not None]
    raise FontError(f"the font family `{fam.name}` has no weight {w} ({style})",
                    hint=f"weights: {', '.join(str(h) for h in have)}")


def weight_axis(face: Face, weight: int | None) -> tuple:
    """``(("wght", weight),)`` for a variable font with that axis, else ``()`` (a static
    font is drawn in its own weight)."""
    if weight is None:
        return ()
    tt = font_of(face).tt
    if "fvar" in tt and any(a.axisTag == "wght" for a in tt["fvar"].axes):
        return (("wght", float(weight)),)
    return ()


def _fontconfig(family: str, style: str) -> tuple[str, int] | None:
    """``(file, face index)`` fontconfig gives for ``family`` (and ``style``), when its
    family is that name (fc-match always answers with some font: a fallback is not the
    family asked for); None without fontconfig."""
    exe = shutil.which("fc-match")
    if exe is None or not family or any(c in family + style for c in ":\n\0"):
        return None
    pattern = family + (f":style={style}" if style else "")
    try:
        out = subprocess.run([exe, "-f", "%{family}\t%{file}\t%{index}", pattern],
                             capture_output=True, text=True, timeout=10).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    parts = out.split("\t")
    if len(parts) != 3:
        return None
    fams = [f.strip().lower() for f in parts[0].split(",")]
    if family.strip().lower() not in fams or not parts[1].lower().endswith(FONT_EXTS):
        return None
    try:
        return parts[1], int(parts[2] or 0)
    except ValueError:
        return None


@lru_cache(maxsize=64)
def covering(chars: str) -> str | None:
    """The first (by name) installed family that fontconfig says has every character of
    ``chars`` (a hint for a text a font cannot draw: run ec's 福 needed `fc-list :lang=zh`
    outside AIDL); None without fontconfig or when none has them all.  Asked once per set of
    characters (a loop's hundred labels with one accent: one `fc-list`)."""
    exe = shutil.which("fc-list")
    wanted = sorted({c for c in chars if not c.isspace()})
    if exe is None or not wanted or len(wanted) > 64:
        return None
    pattern = ":charset=" + " ".join(f"{ord(c):x}" for c in wanted)
    try:
        out = subprocess.run([exe, pattern, "family"], capture_output=True, text=True,
                             timeout=10).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    fams = sorted({line.split(",")[0].strip() for line in out.splitlines() if line.strip()})
    return fams[0] if fams else None


# ------------------------------------------------------------------ reading the font
@lru_cache(maxsize=8)
def _ttfont(key: tuple, index: int, data: bytes | None = None):
    from fontTools.ttLib import TTFont, TTLibError
    import io
    try:
        src = io.BytesIO(data) if data is not None else key[1]
        return TTFont(src, fontNumber=index, lazy=True)
    except (TTLibError, OSError, ValueError, AssertionError, KeyError, IndexError) as ex:
        raise FontError(f"the font file cannot be read: {ex}"[:300],
                        hint="give a TrueType or OpenType font (.ttf, .otf, .ttc)") from None


class _Font:
    """A face read once: fontTools' glyph set at the face's axis values, HarfBuzz's font,
    the units per em and the cap height in font units."""

    def __init__(self, face: Face):
        import uharfbuzz as hb
        key = ("data", face.key[0]) if face.data is not None else ("path", face.path)
        self.tt = tt = _ttfont(key, face.index, face.data)
        try:
            loc = dict(face.variations)
            self.glyphs = tt.getGlyphSet(location=loc) if loc and "fvar" in tt else \
                tt.getGlyphSet()
            self.order = tt.getGlyphOrder()
            self.upem = float(tt["head"].unitsPerEm)
        except Exception as ex:     # fontTools raises many kinds on a damaged table
            raise FontError(f"the font `{face.label}` cannot be read: {ex}"[:300],
                            hint="give a TrueType or OpenType font (.ttf, .otf, .ttc)") from None
        blob = hb.Blob(face.data) if face.data is not None else \
            hb.Blob.from_file_path(face.path)
        self.hb = hb.Font(hb.Face(blob, face.index))
        if loc:
            self.hb.set_variations(loc)
        self.cap = self._cap_height()

    def _cap_height(self) -> float:
        cmap = self.tt.getBestCmap() or {}
        name = cmap.get(ord("H"))
        if name is not None:
            box = _contours_box(self.contours(name))
            if box is not None and box[3] > box[1]:
                return box[3] - min(box[1], 0.0)
        os2 = self.tt.get("OS/2")
        cap = getattr(os2, "sCapHeight", 0) if os2 is not None else 0
        return float(cap) if cap and cap > 0 else 0.7 * self.upem

    def contours(self, name: str) -> list[list[tuple]]:
        """The closed contours of glyph ``name`` in font units, each a list of pieces
        ``("L", p0, p1)`` or ``("C", p0, c1, c2, p1)`` (a quadratic raised to its cubic)."""
        pen = _Pen(self.glyphs)
        self.glyphs[name].draw(pen)
        pen.endPath()
        return pen.contours


def _pen_base():
    from fontTools.pens.basePen import BasePen
    return BasePen


class _Pen:
    """A fontTools pen (its ``BasePen`` splits TrueType's implied on-curve points) that keeps
    each contour's pieces; built on first use so that fontTools is imported only for text in
    a font."""

    def __new__(cls, glyphset):
        base = _pen_base()

        class Pen(base):
            def __init__(self, gs):
                super().__init__(gs)
                self.contours: list = []
                self.cur: list | None = None
                self.start = None

            def _moveTo(self, p):
                self.endPath()
                self.cur, self.start = [], (float(p[0]), float(p[1]))

            def _lineTo(self, p):
                p0, p1 = self._getCurrentPoint(), (float(p[0]), float(p[1]))
                if self.cur is not None and p0 != p1:
                    self.cur.append(("L", tuple(map(float, p0)), p1))

            def _curveToOne(self, c1, c2, p):
                p0 = tuple(map(float, self._getCurrentPoint()))
                if self.cur is not None:
                    self.cur.append(("C", p0, tuple(map(float, c1)), tuple(map(float, c2)),
                                     (float(p[0]), float(p[1]))))

            def _qCurveToOne(self, q, p):
                p0 = tuple(map(float, self._getCurrentPoint()))
                q = (float(q[0]), float(q[1]))
                p1 = (float(p[0]), float(p[1]))
                c1 = (p0[0] + 2 / 3 * (q[0] - p0[0]), p0[1] + 2 / 3 * (q[1] - p0[1]))
                c2 = (p1[0] + 2 / 3 * (q[0] - p1[0]), p1[1] + 2 / 3 * (q[1] - p1[1]))
                if self.cur is not None:
                    self.cur.append(("C", p0, c1, c2, p1))

            def _closePath(self):
                if self.cur is not None and self.start is not None:
                    p0 = tuple(map(float, self._getCurrentPoint()))
                    if p0 != self.start:
                        self.cur.append(("L", p0, self.start))
                self.endPath()

            def _endPath(self):
                self.endPath()

            def endPath(self):
                if self.cur:
                    self.contours.append(self.cur)
                self.cur = None

        return Pen(glyphset)


def _contours_box(contours) -> tuple | None:
    pts = [p for c in contours for piece in c for p in piece[1:]]
    if not pts:
        return None
    return (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts),
            max(p[1] for p in pts))


def font_of(face: Face) -> _Font:
    """The face read (cached by its bytes' key, its index and its axis values)."""
    return _font_by_key(face.key, face)


_FONTS: dict = {}


def _font_by_key(key, face: Face) -> _Font:
    f = _FONTS.get(key)
    if f is None:
        if len(_FONTS) >= 8:
            _FONTS.pop(next(iter(_FONTS)))
        f = _FONTS[key] = _Font(face)
    return f


# ------------------------------------------------------------------ shaping and outlines
class Shaped:
    """A text shaped and drawn at one size: ``loops`` (mm, relative to the position point,
    before the rotation; filled where the winding is positive, glyphs may overlap), for each
    glyph its characters, its loops' indices and its advance; ``ink`` the loops' box
    ``(x0, y0, x1, y1)`` and ``advance`` the pen's run (mm), ``size`` the cap height (mm)."""
    __slots__ = ("loops", "glyphs", "ink", "advance", "size")

    def __init__(self, loops, glyphs, ink, advance, size):
        self.loops, self.glyphs, self.ink, self.advance, self.size = \
            loops, glyphs, ink, advance, size


def _shape(font: _Font, text: str) -> list[tuple]:
    """HarfBuzz's glyphs of ``text``: ``(glyph id, cluster, x, y, x_advance)`` in font units,
    the pen running left to right (a right-to-left run is given in visual order)."""
    import uharfbuzz as hb
    if not text:
        return []
    buf = hb.Buffer()
    buf.add_str(text)
    buf.guess_segment_properties()
    hb.shape(font.hb, buf, {"kern": True, "liga": True})
    out, pen_x, pen_y = [], 0.0, 0.0
    for info, pos in zip(buf.glyph_infos or (), buf.glyph_positions or ()):
        out.append((info.codepoint, info.cluster, pen_x + pos.x_offset, pen_y + pos.y_offset,
                    pos.x_advance))
        pen_x += pos.x_advance
        pen_y += pos.y_advance
    return out


def missing(face: Face, text: str) -> list[str]:
    """The characters of ``text`` (not spaces) the font has no glyph for, each once."""
    cmap = font_of(face).tt.getBestCmap() or {}
    out: list[str] = []
    for ch in text:
        if ch.isspace() or ch in out or ord(ch) in cmap:
            continue
        if 0x300 <= ord(ch) < 0x370 or 0xFE00 <= ord(ch) <= 0xFE0F or ch in "\u200c\u200d":
            continue                # combining marks and joiners: shaped onto their base
        out.append(ch)
    return out


def _loop(contour, k: float, dx: float, dy: float) -> Loop | None:
    """The exact loop of one contour: font units scaled by ``k`` and moved by ``(dx, dy)``
    mm; its lines as :class:`Line`, each run of curves one :class:`Spline` of a Bézier
    chain (one closed chain when the whole contour is curves)."""
    def f(p):
        return ((p[0] + dx) * k, (p[1] + dy) * k)
    segs: list = []
    run: list = []

    def flush():
        if run:
            ctrl = [f(run[0][1])]
            for piece in run:
                ctrl += [f(piece[2]), f(piece[3]), f(piece[4])]
            segs.append(_chain(ctrl, False))
            run.clear()
    for piece in contour:
        if piece[0] == "L":
            flush()
            a, b = f(piece[1]), f(piece[2])
            if a != b:
                segs.append(Line(a, b))
        else:
            if piece[1] == piece[2] == piece[3] == piece[4]:
                continue
            run.append(piece)
    if run and not segs:                    # the whole contour is curves: one closed chain
        ctrl = [f(run[0][1])]
        for piece in run:
            ctrl += [f(piece[2]), f(piece[3]), f(piece[4])]
        ctrl[-1] = ctrl[0]
        return Loop([_chain(ctrl, True)]) if len(ctrl) >= 4 else None
    flush()
    if not segs or (len(segs) < 2 and isinstance(segs[0], Line)):
        return None
    # the pieces join end to start exactly (the same font points scaled the same way)
    return Loop(segs)


def _chain(ctrl, closed: bool) -> Spline:
    from .spline import bezier_chain
    c: CubicSpline = bezier_chain(ctrl, closed)
    return Spline(c, 0.0, float(c.n))


@lru_cache(maxsize=256)
def shaped(face: Face, text: str, size: float) -> Shaped:
    """``text`` shaped in ``face`` with its cap height ``size`` mm, the pen starting at
    (0, 0) on the baseline: its loops oriented so that the filled area winds positively
    (TrueType draws outer contours clockwise, CFF counter-clockwise)."""
    font = font_of(face)
    k = size / font.cap
    glyphs = _shape(font, text)
    if len(glyphs) > MAX_GLYPHS:
        raise FontError(f"a Text in a font takes at most {MAX_GLYPHS} glyphs, got "
                        f"{len(glyphs)}")
    loops: list[Loop] = []
    info: list[tuple] = []
    area = 0.0
    cache: dict = {}
    for i, (gid, cluster, x, y, adv) in enumerate(glyphs):
        if gid == 0 or gid >= len(font.order):      # no glyph (W0105): left out, its
            info.append((text[cluster:cluster + 1], (), adv * k))   # advance kept
            continue
        name = font.order[gid]
        if name not in cache:
            cache[name] = font.contours(name)
        chars = _cluster_chars(text, cluster, glyphs, i)
        idx = []
        for contour in cache[name]:
            lp = _loop(contour, k, x, y)
            if lp is None:
                continue
            idx.append(len(loops))
            loops.append(lp)
            area += lp.area
        info.append((chars, tuple(idx), adv * k))
    if area < 0:                 # outer contours clockwise (TrueType): all turned round
        loops = [lp.reversed() for lp in loops]
    boxes = [s.box() for lp in loops for s in lp.segments]
    ink = ((min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes),
            max(b[3] for b in boxes)) if boxes else (0.0, 0.0, 0.0, 0.0))
    run = sum(g[4] for g in glyphs) * k
    return Shaped(tuple(loops), tuple(info), ink, run, size)


def _cluster_chars(text: str, cluster: int, glyphs, i: int) -> str:
    """The characters of ``text`` that glyph ``i`` (of cluster ``cluster``) stands for: from
    its cluster to the next greater cluster of any glyph."""
    later = [g[1] for g in glyphs if g[1] > cluster]
    end = min(later) if later else len(text)
    return text[cluster:end]


def width(sh: Shaped) -> float:
    """The text's width along its baseline (mm): its advances' run or its ink, the wider."""
    return max(sh.advance, sh.ink[2] - sh.ink[0])


def placement(sh: Shaped, anchor: str, valign: str) -> tuple[float, float]:
    """``(dx, dy)`` mm that put the position point at ``anchor`` (start, middle, end of the
    ink) and ``valign`` (baseline, middle: half the cap height, top: the cap height, bottom:
    the lowest ink)."""
    x0, y0, x1, _ = sh.ink
    dx = {"start": -x0, "middle": -(x0 + x1) / 2, "end": -x1}[anchor]
    dy = {"baseline": 0.0, "middle": -sh.size / 2, "top": -sh.size, "bottom": -y0}[valign]
    return dx, dy


def outlines(face: Face, text: str, size: float, anchor: str, valign: str) -> list[Loop]:
    """The loops of ``text`` relative to its position point, before its rotation (mm)."""
    sh = shaped(face, text, size)
    dx, dy = placement(sh, anchor, valign)
    return _moved_loops(sh.loops, dx, dy)


def _moved_loops(loops: tuple, dx: float, dy: float) -> list[Loop]:
    from .drawing2d import moved
    return [Loop(moved(lp.segments, dx, dy)) for lp in loops]


def extent(face: Face, text: str, size: float, anchor: str, valign: str,
           rotation: float) -> tuple[float, float, float, float]:
    """``(x0, x1, y0, y1)`` of the glyphs' true box relative to the position point, turned
    by ``rotation`` (radians), mm: each segment's exact box."""
    loops = outlines(face, text, size, anchor, valign)
    if rotation:
        from .drawing2d import copied
        loops = copied(loops, [], rotation)[0]
    bs = [s.box() for lp in loops for s in lp.segments]
    if not bs:
        return (0.0, 0.0, 0.0, 0.0)
    return (min(b[0] for b in bs), max(b[2] for b in bs), min(b[1] for b in bs),
            max(b[3] for b in bs))


def fit_size(face: Face, text: str, size: float, max_width: float) -> tuple[float, float]:
    """``(the size, the width at size)``: ``size`` when the text is at most ``max_width``
    mm wide (:func:`width`), else the size at which it is exactly that wide (the outlines
    scale with the size)."""
    wide = width(shaped(face, text, size))
    if wide <= max_width or wide <= 0:
        return size, wide
    return size * max_width / wide, wide


def glyph_of_loops(face: Face, text: str, size: float) -> list[str]:
    """For each loop of :func:`outlines`, the characters of the glyph it belongs to."""
    sh = shaped(face, text, size)
    out = [""] * len(sh.loops)
    for chars, idx, _ in sh.glyphs:
        for i in idx:
            out[i] = chars
    return out
