"""PNG preview: the SVG (:mod:`.svg`) rasterised with ``cairosvg`` (the ``png`` extra:
``pip install 'aidl-lang[png]'``), on a white background.

``dpi`` sets the resolution: the SVG is sized in millimetres, so 96 dpi draws 1 mm as 3.78
pixels; ``width`` (pixels) overrides it.
"""
from __future__ import annotations

import re

from .part import MissingDependency, Output, OutputError
from .svg import to_svg


MAX_SIDE = 32_767            # cairo's largest image side (pixels)
MAX_AREA = 100_000_000       # 400 MB of RGBA at most


def to_png(output: Output, dpi: float = 96.0, width: int | None = None, show=(),
           style: str = "preview", margin: float | None = None) -> bytes:
    """PNG bytes of ``output`` (the page of :func:`~.svg.to_svg` with ``show``, ``style`` and
    ``margin``, mm).  Raises :class:`MissingDependency` without ``cairosvg`` and
    :class:`OutputError` for a non-positive size or an image over :data:`MAX_SIDE` a side or
    :data:`MAX_AREA` pixels."""
    try:
        import cairosvg
    except (ImportError, OSError) as e:      # OSError: the cairo C library is missing
        raise MissingDependency(
            "PNG output needs cairosvg and the cairo library: pip install 'aidl-lang[png]' "
            f"(and apt-get install libcairo2 on Debian/Ubuntu) ({e})") from None
    svg = to_svg(output, show=show, style=style, margin=margin).encode()
    if width is not None and width < 1 or width is None and not dpi > 0:
        raise OutputError(f"a PNG needs a positive {'--png-width' if width is not None else '--dpi'}")
    w_mm = re.search(rb' width="([0-9.]+)mm"', svg)
    h_mm = re.search(rb' height="([0-9.]+)mm"', svg)
    if w_mm and h_mm:
        w_mm, h_mm = float(w_mm[1]), float(h_mm[1])
        px = width / w_mm if width else dpi / 25.4          # pixels per mm
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
    kw = {"output_width": int(width)} if width else {"dpi": float(dpi)}
    return cairosvg.svg2png(bytestring=svg, background_color="white", **kw)
