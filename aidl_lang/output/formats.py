"""Output formats by file extension: :data:`FORMATS` maps ``.svg``, ``.dxf``, ``.png``,
``.stl``, ``.3mf``, ``.step`` / ``.stp`` to a writer that turns an :class:`~.part.Output` into bytes."""
from __future__ import annotations

from dataclasses import dataclass

from .part import Output


@dataclass
class Options:
    """Writer options: ``show`` debug layers (SVG/PNG), SVG ``style`` (preview | laser), PNG
    ``dpi`` / ``width`` (pixels), ``thickness`` (mm, STL/3MF/STEP; overrides the program's),
    ``margin`` (mm around the drawing on the SVG/PNG page; None: 5 % of the larger side, at
    least 1 mm; 0: the page is exactly the drawing's bounding box)."""
    show: tuple = ()
    style: str = "preview"
    dpi: float = 96.0
    width: int | None = None
    thickness: float | None = None
    margin: float | None = None


def _svg(o: Output, opt: Options) -> bytes:
    from .svg import to_svg
    return to_svg(o, show=opt.show, style=opt.style, margin=opt.margin).encode()


def _dxf(o: Output, opt: Options) -> bytes:
    from .dxf import to_dxf
    return to_dxf(o).encode()


def _png(o: Output, opt: Options) -> bytes:
    from .png import to_png
    return to_png(o, dpi=opt.dpi, width=opt.width, show=opt.show, style=opt.style,
                  margin=opt.margin)


def _stl(o: Output, opt: Options) -> bytes:
    from .mesh import to_stl
    return to_stl(o, opt.thickness)


def _3mf(o: Output, opt: Options) -> bytes:
    from .mesh import to_3mf
    return to_3mf(o, opt.thickness)


def _step(o: Output, opt: Options) -> bytes:
    from .step import to_step
    return to_step(o, opt.thickness)


# The formats a cutter reads (and their preview): written with the kerf offset applied.  STL,
# 3MF and STEP are the designed solid and never offset.
CUT_FORMATS = (".svg", ".dxf", ".png")


def for_cutting(output: Output, kerf: float | dict | None = None) -> Output:
    """``output`` as a cutter reads it: every cut of a solid part offset by half the kerf
    (:func:`~.layout.compensate`).  ``kerf``: mm, or a dict part name -> mm; ``None`` takes
    the program's ``kerf`` statements (``output.drawing.kerf``); 0 or no kerf anywhere returns
    ``output`` itself.  Raises :class:`~.layout.LayoutError` (an :class:`~.part.OutputError`)
    naming the part where a feature is smaller than the offset."""
    if kerf is None and output.drawing is not None:
        kerf = output.drawing.kerf
    if not kerf:
        return output
    from .layout import compensate
    return compensate(output, kerf)


FORMATS = {".svg": _svg, ".dxf": _dxf, ".png": _png, ".stl": _stl, ".3mf": _3mf,
           ".step": _step, ".stp": _step}


def encode(output: Output, suffix: str, options: Options | None = None) -> bytes:
    """The bytes of ``output`` in the format named by ``suffix`` (``.svg``, ...).  Raises
    ``KeyError`` for an unknown suffix and :class:`~.part.MissingDependency` when the format's
    library is not installed."""
    return FORMATS[suffix.lower()](output, options or Options())
