"""The writers: the exact output model (and the fabrication stage's layout, cut order,
machine profile, assembly) in, bytes and files out.  The top stage of ``aidl_lang.output``:
nothing below imports it.  :mod:`.write` holds the output-file rules (staged, never over a
good file, a FIFO or the program) every front end writes through.

One module per format, behind one registry: :data:`FORMATS` maps each file
extension to its :class:`Format` (the module and function that turn an
:class:`~..part.part.Output` into bytes, its media type, whether a cutter reads it, whether
``--assembled`` writes it, its cost), and :func:`encode` writes one.  Every front end (the CLI's
``-o``, ``aidl serve``'s downloads, the MCP render tool, ``aidl batch``, the Python API) takes
its list of formats from here, so adding a format is one module here and one :class:`Format`
line below.  A writer's library is imported only when its format is written."""
from __future__ import annotations

from dataclasses import dataclass

from ...base.records import Compared
from ..part.part import Output, OutputError


class Options(Compared):
    """Writer options: ``show`` debug layers (SVG/PNG), SVG ``style`` (preview | laser), PNG
    ``dpi`` / ``width`` (pixels; neither: 96 dpi, the longer side at most 2000 pixels), ``thickness`` (mm, STL/3MF/STEP; overrides the program's),
    ``margin`` (mm around the drawing on the SVG/PNG page; None: 5 % of the larger side, at
    least 1 mm; 0: the page is exactly the drawing's bounding box), ``assembled`` (STL, 3MF,
    STEP, GLB with every part placed by its ``Place``; PNG: a picture of the assembled
    product), ``machine`` (G-code: a :class:`~..fabrication.machine.Machine`, a kind's name, a TOML
    profile's path or a dict of its keys; None: the built-in laser profile), ``page`` (PDF: a
    paper size such as ``A4`` or ``A4-landscape`` the drawing is tiled over,
    :data:`.pdf.PAGES`; None: one page the size of the drawing; the PDF's ``margin`` defaults
    to 10 mm)."""
    __slots__ = ("show", "style", "dpi", "width", "thickness", "margin", "assembled", "machine",
                 "page")

    def __init__(self, show: tuple = (), style: str = "preview", dpi: float | None = None,
                 width: int | None = None, thickness: float | None = None,
                 margin: float | None = None, assembled: bool = False, machine: object = None,
                 page: str | None = None):
        self.show = show
        self.style = style
        self.dpi = dpi  # None: 96 dpi, the longer side at most 2000 pixels
        self.width = width
        self.thickness = thickness
        self.margin = margin
        self.assembled = assembled
        self.machine = machine
        self.page = page


@dataclass(frozen=True)
class Format:
    """One output format: ``module`` (in this package) and its ``function(output, options)
    -> bytes``; ``media`` (MIME type); ``text`` (readable on a terminal, ``-o -``); ``cut``
    (what a cutter reads: written with the kerf offset); ``assembled`` (``--assembled``
    writes the product in 3D, or its picture); ``empty``: a drawing with nothing in it is
    still a file of this format (a blank page); the cost :func:`writer_seconds` estimates:
    ``per_item`` s per part, loop and segment, or ``per_vertex`` s per vertex of the parts'
    shapes; ``about``: what it is for, in a few words (help texts, docs)."""
    module: str
    function: str
    media: str
    about: str
    text: bool = False
    cut: bool = False
    assembled: bool = False
    empty: bool = False
    per_item: float = 0.0
    per_vertex: float = 0.0

    def write(self, output: Output, options: "Options") -> bytes:
        """The bytes of ``output`` in this format (imports the writer module on first use)."""
        import importlib
        module = importlib.import_module(f"{__name__}.{self.module}")
        return getattr(module, self.function)(output, options)


# What one writer costs (per_item, per_vertex), measured by benchmarks/outputs/writer_cost.py on the
# reference machine (2 cores, busy) and rounded up about twice: seconds per item of the output,
# an item being a part, a loop or a segment (engraving strokes' segments included); STL, 3MF
# and GLB per vertex of the drawing's shapes (their triangles follow the tessellation); PNG adds
# its pixels (SECONDS_PER_PIXEL), every writer its start (WRITER_START: its library's import).
# SVG and DXF, the formats of the largest sheets, are the CPU a writer takes on a quiet machine
# (the larger of the parts and holes programs, not rounded up), so that a writer is refused
# only when it is sure to end past the deadline: the estimate twice over refused the DXF of a
# perforated sheet of 50,000 holes (15.5 s for a writer of 2.4 s) that fits the 15 s budget; on
# a busy machine a writer may end past the deadline by about its own time (issue 74).  The
# machine formats (G-code, LightBurn, HP-GL) likewise: the largest of the parts and holes
# programs' figures at N = 500 and 2,000 (50-116 us), rounded up to 120-150 us; 300-600 us
# (4 to 23 times the measure, 17 to 37 on a grid of slits: 61,000 lines) refused the G-code
# of a 100 x 100 grid of slits, a writer of 1.0 s, as 18.9 s past the budget (issue 83).
FORMATS: dict[str, Format] = {
    ".svg": Format("svg", "write", "image/svg+xml", "vector drawing: laser software, browsers",
                   text=True, cut=True, empty=True, per_item=15e-6),
    ".dxf": Format("dxf", "write", "application/dxf", "CAD exchange: laser and CNC software",
                   text=True, cut=True, empty=True, per_item=40e-6),
    ".pdf": Format("pdf", "write", "application/pdf",
                   "1:1 printed template (scroll saw, hand cutting)", cut=True, empty=True,
                   per_item=300e-6),
    ".png": Format("png", "write", "image/png", "picture of the drawing (or the product)",
                   cut=True, assembled=True, empty=True, per_item=100e-6),
    ".stl": Format("mesh", "write_stl", "model/stl", "3D mesh of the parts (printers)",
                   assembled=True, per_vertex=50e-6),
    ".3mf": Format("mesh", "write_3mf", "model/3mf", "3D parts, one object each (printers)",
                   assembled=True, per_vertex=60e-6),
    ".step": Format("step", "write", "model/step", "exact 3D solids for CAD",
                    text=True, assembled=True, per_item=5e-3),
    ".stp": Format("step", "write", "model/step", "exact 3D solids for CAD (.step)",
                   text=True, assembled=True, per_item=5e-3),
    ".glb": Format("glb", "write", "model/gltf-binary", "the assembled product for 3D viewers",
                   assembled=True, per_vertex=60e-6),
    ".gcode": Format("gcode", "write", "text/x.gcode",
                     "G-code (GRBL) for a laser, router or plotter (--machine)",
                     text=True, cut=True, per_item=150e-6),
    ".nc": Format("gcode", "write", "text/x.gcode", "G-code (GRBL), as .gcode",
                  text=True, cut=True, per_item=150e-6),
    ".lbrn2": Format("lightburn", "write", "application/x-lightburn",
                     "LightBurn project: a layer per operation", text=True, cut=True,
                     per_item=120e-6),
    ".plt": Format("hpgl", "write", "application/vnd.hp-hpgl",
                   "HPGL for vinyl cutters and pen plotters", text=True, cut=True,
                   per_item=150e-6),
    ".hpgl": Format("hpgl", "write", "application/vnd.hp-hpgl",
                    "HPGL for vinyl cutters and pen plotters (.plt)", text=True, cut=True,
                    per_item=150e-6),
}
# the formats a cutter reads (and their preview): written with the kerf offset applied; STL,
# 3MF, STEP and GLB are the designed solid and never offset
CUT_FORMATS = tuple(k for k, f in FORMATS.items() if f.cut)
# the formats `--assembled` writes (the product in 3D, or its picture)
ASSEMBLED_FORMATS = tuple(k for k, f in FORMATS.items() if f.assembled)
# what `-o -` writes to a terminal too; the other formats are binary
TEXT_FORMATS = tuple(k for k, f in FORMATS.items() if f.text)

WRITER_START = 0.5
SECONDS_PER_PIXEL = 1e-7


def writer_seconds(output: Output, suffix: str, options: Options | None = None) -> float:
    """An estimate of the wall time (s) of :func:`encode` of ``output`` as ``suffix``
    (:data:`WRITER_START`, each :class:`Format`'s ``per_item`` or ``per_vertex``,
    :data:`SECONDS_PER_PIXEL`; for SVG and DXF a quiet machine's time, for the others about
    twice a busy one's; STL, 3MF and GLB also their faces' triangulation and their
    countersinks' cones, :func:`~.mesh.solid_seconds`), so that a writer sure to end past the deadline is refused before it
    starts.  A PNG over :data:`~.png.MAX_SIDE` or :data:`~.png.MAX_AREA` costs only
    the start: :func:`~.png.to_png` refuses it before drawing."""
    suffix = suffix.lower()
    fmt = FORMATS.get(suffix)
    if fmt is not None and fmt.per_vertex:
        from .mesh import solid_seconds
        return WRITER_START + solid_seconds(output, fmt.per_vertex)
    items = sum(1 + len(p.loops) + sum(len(lp.segments) for lp in p.loops)
                for p in output.parts) + sum(len(st.segments) for st in output.engrave)
    seconds = WRITER_START + (fmt.per_item if fmt is not None else 0.0) * items
    if suffix == ".png" and (output.parts or output.engrave):
        from .png import MAX_AREA, MAX_SIDE, pixels_per_mm
        opt = options or Options()
        x0, y0, x1, y1 = output.bounds()
        w, h = x1 - x0, y1 - y0
        m = opt.margin if opt.margin is not None else max(1.0, 0.05 * max(w, h))
        w, h = w + 2 * m, h + 2 * m
        px = pixels_per_mm(w, h, opt.dpi, opt.width)                 # pixels per mm
        w_px, h_px = w * px, h * px
        if max(w_px, h_px) <= MAX_SIDE and w_px * h_px <= MAX_AREA:   # else refused at once
            seconds += SECONDS_PER_PIXEL * w_px * h_px
    return seconds


def encode(output: Output, suffix: str, options: Options | None = None,
           deadline=None) -> bytes:
    """The bytes of ``output`` in the format named by ``suffix`` (``.svg``, ...).  Raises
    ``KeyError`` for an unknown suffix and :class:`~.part.MissingDependency` when the format's
    library is not installed.  ``deadline``: the compile's
    :class:`~aidl_lang.base.limits.Deadline` (``aidl render``, ``aidl batch``), or None: a writer
    whose :func:`writer_seconds` would end past it is refused before it starts, with an
    :class:`~.part.OutputError` whose ``budget`` names the part with the most segments; a
    writer that runs out of memory raises the same, its ``budget`` an
    :class:`~aidl_lang.base.limits.OutOfMemory`."""
    fmt = FORMATS[suffix.lower()]
    if not fmt.empty:
        _refuse_empty(output, suffix, fmt)
    if fmt.cut and not fmt.empty:
        _refuse_stacked(output, suffix)
    _refuse_sunk_away(output, options)
    if deadline is not None:
        from ...base.limits import OutOfBudget, seconds_as_work
        try:
            deadline.check(f"the {suffix.lstrip('.').upper()} writer",
                           ahead=seconds_as_work(writer_seconds(output, suffix, options)))
        except OutOfBudget as ex:
            ex.where = _biggest_part(output)
            ex.what += "; nothing was written"
            if fmt.per_vertex and ex.hint:
                from .mesh import tool_seconds
                tools, seconds = tool_seconds(output)
                if tools:       # what the cones cost, and the formats that draw them for less
                    ex.hint += (f"; cutting the {tools:,} countersinks and counterbores "
                                f"into the solid needs {int(seconds_as_work(seconds)):,} of "
                                "those units (the SVG, DXF and G-code draw their heads "
                                "without cutting a solid)")
            raise OutputError(f"the {suffix.lstrip('.').upper()} writer would end past the "
                              f"budget ({ex.what}); build less or raise the budget "
                              "(`--budget 2`)", ex) from None
    from ...base.limits import OutOfMemory, is_out_of_memory
    from ...base.memory import gc_paused
    try:
        with gc_paused():           # its entities: many small objects, no cycles to collect
            return fmt.write(output, options or Options())
    except (MemoryError, SystemError) as ex:
        if not is_out_of_memory(ex):
            raise
    # out of memory: said once the writer's frames (and what they held) are gone
    name = suffix.lstrip(".").upper()
    ex = OutOfMemory(f"the {name} writer", _biggest_part(output))
    raise OutputError(f"the {name} writer ran out of memory ({ex.what}); nothing was written",
                      ex)


def _refuse_empty(output: Output, suffix: str, fmt: Format) -> None:
    """An :class:`~.part.OutputError` for a drawing with nothing a machine or a 3D format can
    take: no part outline (and, for the cutting formats, no engraving either)."""
    name = suffix.lstrip(".").upper()
    outlines = any(p.loops for p in output.parts)
    if fmt.cut and not outlines and not any(st.segments for st in output.engrave):
        raise OutputError(f"nothing to write to {name}: the drawing has no part outline and "
                          "no engraving; draw a shape first")
    if not fmt.cut and not outlines:
        raise OutputError(f"nothing to write to {name}: the drawing has no solid part to "
                          "extrude (engravings and holes alone have no body); draw a solid first")


class SunkAway(OutputError):
    """``E0503``: every format refused because the countersinks or counterbores that go
    through a part at the thickness given for the output (``--thickness``, the studio's
    download) leave nothing of it, or cut it apart (:func:`~..part.build.sunk.sunk_away`);
    ``span``: the call of the widest head; ``message`` and ``hint`` as the compile's."""

    def __init__(self, message: str, hint: str, span):
        super().__init__(f"{message}; {hint}")
        self.message, self.hint, self.span = message, hint, span


def _refuse_sunk_away(output: Output, options: Options | None) -> None:
    """:class:`SunkAway` for an output whose sink heads (:func:`~..part.part.sink_heads`,
    where a layout moved them) leave nothing of a part at the thickness each format would
    give it (``options.thickness``, else the part's, else 3 mm): the same answer for every
    format, so an SVG is not written beside an STL of nothing."""
    from ..part.build.sunk import DEFAULT_THICKNESS, sunk_away, sunk_message
    from ..part.part import sink_heads
    heads = sink_heads(output)
    if not heads:
        return
    given = options.thickness if options is not None else None
    for p in output.parts:
        mine = [h for h in heads if h[1].part == p.name]
        if p.kind != "solid" or not mine:
            continue
        t = float(given or p.thickness or DEFAULT_THICKNESS)
        found = sunk_away(p.shape, mine, t)
        if found is not None:
            raise SunkAway(*sunk_message(p.name, found, t), found[2].span)


STACKED_AREA = 0.05      # mm^2 two parts may share before a machine would cut one over the other
MACHINE_NAMES = {".gcode": "G-code", ".nc": "G-code", ".lbrn2": "LightBurn", ".plt": "HP-GL",
                 ".hpgl": "HP-GL"}


class StackedParts(OutputError):
    """``E0501``: a machine file refused because two separate parts lie over each other
    where the program draws them; ``parts``: the two parts' names (structure paths), the pair
    with the largest common area; ``message`` and ``hint``: what is wrong and what to do
    instead (``str()`` says both, for a front end that shows one line)."""

    def __init__(self, message: str, parts: tuple, hint: str):
        super().__init__(f"{message}; {hint}")
        self.message, self.parts, self.hint = message, parts, hint


def _refuse_stacked(output: Output, suffix: str) -> None:
    """:class:`StackedParts` for a machine file (G-code, LightBurn, HP-GL) whose separate
    parts overlap where the program draws them by more than :data:`STACKED_AREA` mm^2: the
    machine would cut one part through the other.  An assembly may draw its parts over each
    other (a house's walls at the origin, placed in 3D by ``Place``; a clock's hands on its
    face, ``AllowOverlap``), which a picture shows and a cutter cannot make; the cutting layout
    (``--layout sheet``) lays them apart.  The pairs: :func:`..part.measure.gaps.stacked_parts`
    (true outlines, Manifold's CrossSection)."""
    from ..part.measure.gaps import stacked_parts
    over = [(area, a, b) for area, a, b, _ in stacked_parts(output.parts, STACKED_AREA)]
    if not over:
        return
    area, a, b = max(over)
    more = f"; {len(over) - 1} more pair{'s' if len(over) > 2 else ''} of parts overlap" \
        if len(over) > 1 else ""
    name = MACHINE_NAMES.get(suffix.lower(), suffix.lstrip(".").upper())
    raise StackedParts(
        f"parts `{a}` and `{b}` lie over each other where the program draws them ({area:.1f} "
        f"mm^2 in common{more}): a {name} file of this drawing would cut one part through the "
        "other, so nothing was written", (a, b),
        "write the cutting layout instead (`aidl render --layout sheet` lays the parts apart, "
        "one file per sheet), or place the parts apart in the program")


def _biggest_part(output: Output):
    """The structure of the part with the most segments (None without a drawing)."""
    if output.drawing is None or not output.parts:
        return None
    p = max(output.parts, key=lambda p: sum(len(lp.segments) for lp in p.loops))
    return output.drawing.part_of.get(p.name)
