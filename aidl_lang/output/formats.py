"""Output formats by file extension: :data:`FORMATS` maps ``.svg``, ``.dxf``, ``.png``,
``.stl``, ``.3mf``, ``.step`` / ``.stp``, ``.glb`` to a writer that turns an :class:`~.part.Output` into bytes."""
from __future__ import annotations

from dataclasses import dataclass

from .part import Output, OutputError


@dataclass
class Options:
    """Writer options: ``show`` debug layers (SVG/PNG), SVG ``style`` (preview | laser), PNG
    ``dpi`` / ``width`` (pixels), ``thickness`` (mm, STL/3MF/STEP; overrides the program's),
    ``margin`` (mm around the drawing on the SVG/PNG page; None: 5 % of the larger side, at
    least 1 mm; 0: the page is exactly the drawing's bounding box), ``assembled`` (STL, 3MF,
    STEP, GLB with every part placed by its ``Place``; PNG: a picture of the assembled
    product)."""
    show: tuple = ()
    style: str = "preview"
    dpi: float = 96.0
    width: int | None = None
    thickness: float | None = None
    margin: float | None = None
    assembled: bool = False


def _svg(o: Output, opt: Options) -> bytes:
    from .svg import to_svg
    return to_svg(o, show=opt.show, style=opt.style, margin=opt.margin).encode()


def _dxf(o: Output, opt: Options) -> bytes:
    from .dxf import to_dxf
    return to_dxf(o).encode()


def _png(o: Output, opt: Options) -> bytes:
    if opt.assembled:
        from .assembly import to_png as assembled_png
        return assembled_png(o, opt.thickness, width=opt.width or 800)
    from .png import to_png
    return to_png(o, dpi=opt.dpi, width=opt.width, show=opt.show, style=opt.style,
                  margin=opt.margin)


def _stl(o: Output, opt: Options) -> bytes:
    from .mesh import to_stl
    return to_stl(o, opt.thickness, opt.assembled)


def _3mf(o: Output, opt: Options) -> bytes:
    from .mesh import to_3mf
    return to_3mf(o, opt.thickness, opt.assembled)


def _step(o: Output, opt: Options) -> bytes:
    from .step import to_step
    return to_step(o, opt.thickness, opt.assembled)


def _glb(o: Output, opt: Options) -> bytes:
    from .assembly import to_glb
    return to_glb(o, opt.thickness, opt.assembled)


# The formats a cutter reads (and their preview): written with the kerf offset applied.  STL,
# 3MF and STEP are the designed solid and never offset.
CUT_FORMATS = (".svg", ".dxf", ".png")


def for_cutting(output: Output, kerf: float | dict | None = None, deadline=None) -> Output:
    """``output`` as a cutter reads it: every cut of a solid part offset by half the kerf
    (:func:`~.layout.compensate`).  ``kerf``: mm, or a dict part name -> mm; ``None`` takes
    the program's ``kerf`` statements (``output.drawing.kerf``); 0 or no kerf anywhere returns
    ``output`` itself.  Raises :class:`~.layout.LayoutError` (an :class:`~.part.OutputError`)
    naming the part where a feature is smaller than the offset, and an
    :class:`~.part.OutputError` with its ``budget`` when the compile's ``deadline`` (or None)
    passes before every part is offset."""
    if kerf is None and output.drawing is not None:
        kerf = output.drawing.kerf
    if not kerf:
        return output
    from ..limits import OutOfBudget
    from .layout import compensate
    try:
        return compensate(output, kerf, deadline)
    except OutOfBudget as ex:
        raise OutputError(f"the kerf offset ran past the budget ({ex.what}); build less or "
                          "raise the budget (`--budget 2`)", ex) from None


FORMATS = {".svg": _svg, ".dxf": _dxf, ".png": _png, ".stl": _stl, ".3mf": _3mf,
           ".step": _step, ".stp": _step, ".glb": _glb}
# the formats `--assembled` writes (the product in 3D, or its picture)
ASSEMBLED_FORMATS = (".stl", ".3mf", ".step", ".stp", ".glb", ".png")


# What one writer costs, measured by benchmarks/writer_cost.py on the reference machine (2
# cores, busy) and rounded up about twice: a start (its library's import) and seconds per item
# of the output, an item being a part, a loop or a segment (engraving strokes' segments
# included); STL and 3MF per vertex of the drawing's shapes (their triangles follow the
# tessellation); PNG adds its pixels.
WRITER_START = 0.5
SECONDS_PER_ITEM = {".svg": 100e-6, ".dxf": 150e-6, ".png": 100e-6, ".step": 5e-3,
                    ".stp": 5e-3}
SECONDS_PER_VERTEX = {".stl": 50e-6, ".3mf": 60e-6, ".glb": 60e-6}
SECONDS_PER_PIXEL = 1e-7


def writer_seconds(output: Output, suffix: str, options: Options | None = None) -> float:
    """An upper estimate of the wall time (s) of :func:`encode` of ``output`` as ``suffix``
    (:data:`WRITER_START` and :data:`SECONDS_PER_ITEM`, :data:`SECONDS_PER_VERTEX`,
    :data:`SECONDS_PER_PIXEL`), so that a writer sure to end past the deadline is refused
    before it starts.  A PNG over :data:`~.png.MAX_SIDE` or :data:`~.png.MAX_AREA` costs only
    the start: :func:`~.png.to_png` refuses it before drawing."""
    suffix = suffix.lower()
    if suffix in SECONDS_PER_VERTEX:
        d = output.drawing
        verts = sum(p.shape.num_vert() for p in d.parts) if d is not None else 0
        return WRITER_START + SECONDS_PER_VERTEX[suffix] * verts
    items = sum(1 + len(p.loops) + sum(len(lp.segments) for lp in p.loops)
                for p in output.parts) + sum(len(st.segments) for st in output.engrave)
    seconds = WRITER_START + SECONDS_PER_ITEM.get(suffix, 0.0) * items
    if suffix == ".png" and (output.parts or output.engrave):
        from .png import MAX_AREA, MAX_SIDE
        opt = options or Options()
        x0, y0, x1, y1 = output.bounds()
        w, h = x1 - x0, y1 - y0
        m = opt.margin if opt.margin is not None else max(1.0, 0.05 * max(w, h))
        w, h = w + 2 * m, h + 2 * m
        px = opt.width / w if opt.width else opt.dpi / 25.4          # pixels per mm
        w_px, h_px = w * px, h * px
        if max(w_px, h_px) <= MAX_SIDE and w_px * h_px <= MAX_AREA:   # else refused at once
            seconds += SECONDS_PER_PIXEL * w_px * h_px
    return seconds


def encode(output: Output, suffix: str, options: Options | None = None,
           deadline=None) -> bytes:
    """The bytes of ``output`` in the format named by ``suffix`` (``.svg``, ...).  Raises
    ``KeyError`` for an unknown suffix and :class:`~.part.MissingDependency` when the format's
    library is not installed.  ``deadline``: the compile's
    :class:`~aidl_lang.limits.Deadline` (``aidl render``, ``aidl batch``), or None: a writer
    whose :func:`writer_seconds` would end past it is refused before it starts, with an
    :class:`~.part.OutputError` whose ``budget`` names the part with the most segments."""
    writer = FORMATS[suffix.lower()]
    if deadline is not None:
        from ..limits import OutOfBudget
        try:
            deadline.check(f"the {suffix.lstrip('.').upper()} writer",
                           ahead=writer_seconds(output, suffix, options))
        except OutOfBudget as ex:
            ex.where = _biggest_part(output)
            ex.what += "; nothing was written"
            raise OutputError(f"the {suffix.lstrip('.').upper()} writer would end past the "
                              f"budget ({ex.what}); build less or raise the budget "
                              "(`--budget 2`)", ex) from None
    return writer(output, options or Options())


def _biggest_part(output: Output):
    """The structure of the part with the most segments (None without a drawing)."""
    if output.drawing is None or not output.parts:
        return None
    p = max(output.parts, key=lambda p: sum(len(lp.segments) for lp in p.loops))
    return output.drawing.part_of.get(p.name)
