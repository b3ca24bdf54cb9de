"""PNG preview: the SVG (:mod:`.svg`) rasterised with ``cairosvg`` (the ``png`` extra:
``pip install 'aidl-lang[png]'``), on a white background.

``dpi`` sets the resolution: the SVG is sized in millimetres, so 96 dpi draws 1 mm as 3.78
pixels; ``width`` (pixels) overrides it.
"""
from __future__ import annotations

from .part import MissingDependency, Output
from .svg import to_svg


def to_png(output: Output, dpi: float = 96.0, width: int | None = None, show=(),
           style: str = "preview") -> bytes:
    """PNG bytes of ``output``.  Raises :class:`MissingDependency` without ``cairosvg``."""
    try:
        import cairosvg
    except (ImportError, OSError) as e:      # OSError: the cairo C library is missing
        raise MissingDependency(
            "PNG output needs cairosvg and the cairo library: pip install 'aidl-lang[png]' "
            f"(and apt-get install libcairo2 on Debian/Ubuntu) ({e})") from None
    svg = to_svg(output, show=show, style=style).encode()
    kw = {"output_width": int(width)} if width else {"dpi": float(dpi)}
    return cairosvg.svg2png(bytestring=svg, background_color="white", **kw)
