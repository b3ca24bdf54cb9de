"""``aidl mcp``: the Model Context Protocol server over stdio, on the official ``mcp`` SDK
(``MCPServer``).  The tools are thin wrappers of :mod:`.tools`; docs/mcp.md lists them.

Tools: ``check``, ``render`` (a PNG image block, optionally a file written inside the root),
``values``, ``describe`` (the final part in words), ``import_drawing`` (``aidl import
[--infer]`` of a DXF or SVG in the root), ``explain``, ``docs``.  The compiling four
run side by side in a pool of worker processes (:mod:`.worker`) and return structured content
of the output schemas of :mod:`.schemas`; their input schemas take exactly one of ``source``
and ``path`` and nothing they do not list (:class:`_Server` refuses the rest).  Resources:
``aidl://docs/language`` (the language reference), ``aidl://docs/api``, ``aidl://docs/topics``
and ``aidl://docs/topic/NAME`` (the topics of ``aidl docs``), ``aidl://prompt`` (the ``aidl
prompt`` text, when the caller provides it), ``aidl://stdlib/NAME.aidl`` and
``aidl://examples/NAME.aidl``.  Prompt: ``aidl`` (the system prompt, when the caller provides
it).
"""
from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Annotated, Literal

from mcp.server.mcpserver import Image, MCPServer
from mcp.server.mcpserver.exceptions import ToolError
from mcp.server.mcpserver.tools import Tool
from mcp.shared.exceptions import MCPError
from mcp_types import INVALID_PARAMS, CallToolResult, TextContent, ToolAnnotations
from pydantic import Field

from ..limits import DEFAULT_BUDGET, MAX_ITER, MAX_TEMPLATE_DEPTH
from ..output.writers import FORMATS
from ..parser import MAX_NESTING
from ..sources import EXAMPLES as _EXAMPLES    # inside the package: shipped in the wheel
from ..sources import MAX_DRAWING_BYTES
from . import compact as C
from . import stdio
from . import tools as T
from .schemas import (CheckResult, DescribeResult, ImportResult, RenderResult, ValuesResult,
                      WriteResult)
from .wording import for_agents

# what one program may build (aidl_lang/limits.py, the parser's and the importer's limits),
# said in the descriptions of the tools that compile
LIMITS = (f"Limits: a program of at most {T.MAX_SOURCE:,} characters, brackets nested at "
          f"most {MAX_NESTING} deep, at most {MAX_ITER:,} items in one loop, templates "
          f"nested {MAX_TEMPLATE_DEPTH} deep, {DEFAULT_BUDGET.steps:,} loop steps and "
          f"{DEFAULT_BUDGET.objects:,} objects per compile, {DEFAULT_BUDGET.seconds:g} s "
          f"(x `budget`); a DXF or SVG drawing of at most "
          f"{MAX_DRAWING_BYTES // 1_000_000} MB. Past one: a located E0304 (or E0003, "
          f"E0301), not a hang.")

# The tools' arguments: the SDK turns each description, allowed value and range into the
# JSON Schema of `tools/list`, and checks calls against it before a tool runs.
Source = Annotated[str | None, Field(
    description="The AIDL program text. Give this or `path`, not both.",
    max_length=T.MAX_SOURCE)]
ProgramPath = Annotated[str | None, Field(
    description="A .aidl file, relative to the server's allowed folder (nothing outside it "
                "is read; another kind of file is refused: a program imports a DXF or SVG "
                "drawing with Drawing2D). Give this or `source`, not both.")]
Overrides = Annotated[dict[str, str | int | float | bool] | None, Field(
    description="Param values: param name -> value, e.g. {\"width\": \"40 mm\"} (a string, "
                "read as the program reads a value), {\"width\": 40} (a bare number, in the "
                "file's units, as the string \"40\") or {\"holes\": true}.")]
Budget = Annotated[float | None, Field(
    description=f"A factor of the default evaluation budget (steps, objects, sizes, 15 s of "
                f"CPU time), above 0 and at most {T.MAX_BUDGET:g}; default: the server's "
                f"(`aidl mcp --budget`).",
    gt=0, le=T.MAX_BUDGET)]
Dof = Annotated[bool, Field(
    description="Also count the degrees of freedom left per structure, with the entities "
                "still free to move.")]
Sweep = Annotated[bool, Field(
    description="Also check the design across its params' declared min/max ranges.")]
Output = Annotated[str | None, Field(
    description="Also write the drawing to this file, relative to the allowed folder (never "
                "outside it, never over the program or through a symbolic link; a missing "
                "folder is made); the format by extension: "
                + ", ".join(f"{k} ({f.about})" for k, f in FORMATS.items() if k != ".stp")
                + ".")]
Width = Annotated[int, Field(
    description="The PNG's width in pixels (the returned image's and a written .png's).",
    ge=16, le=T.MAX_PNG_WIDTH)]
Style = Annotated[Literal["preview", "laser"], Field(
    description="`preview`: parts filled, holes cut out; `laser`: hairline cut paths, as a "
                "laser cutter reads them.")]
Assembled = Annotated[bool, Field(
    description="Picture the assembled product instead of the flat parts: every part "
                "extruded by its thickness and placed by its `Place`, collisions boxed in red "
                "(a written .stl/.3mf/.step/.glb/.png is assembled too).")]
LayoutKind = Annotated[Literal["sheet"] | None, Field(
    description="\"sheet\": lay every solid part out flat on cutting sheets, as `aidl render "
                "--layout sheet` (true-shape nesting; the `layout` extra): one picture and one "
                "output file per sheet (cut-1.svg, cut-2.svg, ... when there are several; one "
                "material thickness per sheet).")]
Sheet = Annotated[str | None, Field(
    description="With layout: the sheet size WIDTHxHEIGHT with a unit, e.g. \"600x400mm\" "
                "(the default) or \"24x12in\".", max_length=100)]
Gap = Annotated[str | float | None, Field(
    description="With layout: the space between parts and to the sheet's edge, a number of "
                "mm or a string with its unit (\"3mm\", the default).")]
Rotate = Annotated[Annotated[str, Field(max_length=200)] | float | None, Field(
    description="With layout: the angles in degrees parts may be turned by, e.g. \"0,90\" "
                "(the default), 0 or \"any\".")]
Kerf = Annotated[str | float | None, Field(
    description="Offset every cut of SVG, DXF and PNG by half this kerf so parts come out at "
                "their size: a number of mm or a string with its unit (\"0.15mm\"), above 0 "
                "and up to 10 mm; default: the program's `kerf`, else none. STL, 3MF, STEP and "
                "GLB keep the designed size.")]
Thickness = Annotated[str | float | None, Field(
    description="The extrusion thickness of STL, 3MF, STEP, GLB and the assembled picture: a "
                "number of mm or a string with its unit (\"3mm\"); default: the program's "
                "`thickness`, else 3 mm.")]
Machine = Annotated[str | None, Field(
    description="For a .gcode output: the machine profile, `laser`, `router` or `plotter` "
                "(built-in profiles) or a TOML profile file inside the allowed folder (`aidl "
                "docs machine`); default: the built-in laser.")]
Page = Annotated[str | None, Field(
    description="With a .pdf output: tile the 1:1 template over pages of this paper size "
                "(\"A4\", \"A3\", \"Letter\", \"Legal\", each also \"-landscape\"), 10 mm "
                "overlaps with alignment marks; default: one page the drawing's size.",
    max_length=40)]
DrawingPath = Annotated[str, Field(
    description="A .dxf or .svg drawing, relative to the server's allowed folder.")]
Infer = Annotated[bool, Field(
    description="Write the design (recognised shapes such as RoundedRectangle and Slot, loops "
                "for hole patterns, named params, held in place), not the drawing's pieces.")]
Parts = Annotated[bool, Field(
    description="A sheet of parts: one solid per outer outline, in an assembly.")]
Units = Annotated[Literal["mm", "cm", "m", "in", "ft", "pt", "px"] | None, Field(
    description="The drawing's unit, instead of the DXF's $INSUNITS or the SVG's size.")]
ProgramOutput = Annotated[str | None, Field(
    description="Also write the program to this .aidl file, relative to the allowed folder.")]
Names = Annotated[list[Annotated[str, Field(max_length=500)]] | None, Field(
    description="Dotted name prefixes to keep, e.g. [\"plate.bore\", \"body.width\"] (the "
                "root structure's name may be left out); default: every value. Names that "
                "match nothing are an error (no_match) with the nearest names.",
    max_length=200)]
Detail = Annotated[bool, Field(
    description="Every item in full: each copy of a pattern or loop, each alike opening or "
                "cut, and each diagnostic's `rendered` text. Default: lists of more than "
                f"{C.GROUP_AT} alike items said once with their count (`count`, `alike`, "
                "`within`; values: kind `group`).")]
WritePath = Annotated[str, Field(
    description="The .aidl file to write, relative to the allowed folder (its folders are "
                "made; never through a symbolic link).")]
WriteText = Annotated[str | None, Field(
    description="The whole program: the file becomes this text.", max_length=T.MAX_SOURCE)]
Old = Annotated[str | None, Field(
    description="Patch: the text to replace, found exactly once in the file (with `new`).",
    max_length=T.MAX_SOURCE)]
New = Annotated[str | None, Field(
    description="Patch: the replacement of `old`, or of the characters `start` to `end`.",
    max_length=T.MAX_SOURCE)]
Start = Annotated[int | None, Field(
    description="Patch: the first character replaced, a 0-based offset (a diagnostic's "
                "`span.start`, a fix's span).", ge=0)]
End = Annotated[int | None, Field(
    description="Patch: the offset after the last character replaced (`span.end`).", ge=0)]
Code = Annotated[str, Field(
    description="A diagnostic code, e.g. E0103 or W0402 (any case).", min_length=1,
    max_length=16)]
TopicName = Annotated[str | None, Field(
    description="A shape, constraint, statement or standard-library template, in any case "
                "or style (Circle, SpurGear, spur-gear, assert); none: the list of topics.",
    max_length=200)]

Request = Annotated[str | None, Field(
    description="The part to design, in words (e.g. \"a 40 mm washer with a 10 mm hole\"); "
                "appended to the system prompt as `Design this part: ...`. Optional.")]
MAX_REQUEST = 10_000      # characters of a prompt's request

INSTRUCTIONS = """AIDL is a text language for 2D CAD parts (laser cutting, CNC): named \
structures (solid, hole, cut, drawing, assembly) hold geometry (Rectangle, Circle, Slot, ...) and \
constraints that a solver satisfies. Read aidl://prompt (also offered as the prompt `aidl`) \
for the vocabulary, standard library and examples; call `docs` with a name (Circle, \
spur_gear, assert, ...) for its units, members and an example, or read aidl://docs/language \
for the full reference. Write a program, call `check` until it reports \
ok (each diagnostic has a code, a located span, a hint and often a fix; `explain` a code for \
more), then `render` to see it, `describe` to read the final part in words (outline, openings \
with centres and sizes, texts, symmetries) and `values` to read exact positions and sizes. Paths are \
relative to the server's allowed folder; nothing outside it can be read or written."""

_PKG = Path(__file__).resolve().parent.parent
# the two references the server offers as resources, inside the package (links to docs/ in a
# checkout, the files themselves in the wheel)
_DOCS = _PKG / "docs"


def _text_of(path: Path, what: str) -> Callable[[], str]:
    def read() -> str:
        try:
            return path.read_text(encoding="utf-8")
        except OSError:
            return f"({what} is not installed with this copy of aidl: see docs in the source " \
                   "repository)"
    return read


def _json(doc: dict) -> str:
    return json.dumps(doc, indent=1)


def answer(tool: str, doc: dict, pngs: list[bytes] = (), detail: bool = False
           ) -> CallToolResult:
    """A compiling tool's result: ``doc`` as structured content, compact unless ``detail``
    (:mod:`.compact`), the pictures, and one line of text; a program with errors also
    carries ``error`` (its first error's code and the summary)."""
    if "diagnostics" in doc and isinstance(doc["diagnostics"], list) and tool != "import_drawing":
        doc["diagnostics"] = C.diagnostics(doc["diagnostics"], detail)
    if tool == "values" and "values" in doc:
        doc["values"] = C.values(doc["values"], doc.get("units", "mm"), detail)
        if not detail:
            doc.pop("text", None)
    if tool == "describe":
        doc = C.describe(doc, detail)
    if not doc.get("ok") and "error" not in doc:
        first = next((d for d in doc.get("diagnostics", [])
                      if d.get("severity", "error") == "error"), None)
        if first is not None:
            doc["error"] = {"code": first["code"],
                            "message": doc.get("summary") or first["message"]}
    pictures = [Image(data=png, format="png").to_image_content() for png in pngs]
    return CallToolResult(content=pictures + [TextContent(type="text", text=C.line(tool, doc))],
                          structured_content=doc)


def refusal(code: str, message: str, argument: str | None = None) -> CallToolResult:
    """A refused call: a tool error whose structured content is ``{"ok": false, "error":
    {"code", "message", "argument"?}}`` (:func:`.compact.error`), the same in one line."""
    doc = C.error(code, for_agents(message), argument)
    return CallToolResult(content=[TextContent(type="text", text=C.line("", doc))],
                          structured_content=doc, is_error=True)


def _validation(exc: BaseException) -> tuple[str, str | None]:
    """The message and argument of the SDK's argument check that failed (a pydantic
    ``ValidationError``), without pydantic's links: ``width: Input should be less than or
    equal to 4096 (got 5000)``."""
    errors = getattr(exc, "errors", None)
    if not callable(errors):
        return str(exc).split("\n")[0], None
    said, first = [], None
    for e in errors()[:5]:
        loc = [str(x) for x in e.get("loc", ()) if x != "arguments"]
        name = loc[0] if loc else None
        first = first or name
        got = repr(e.get("input"))
        got = got if len(got) <= 60 else got[:57] + "..."
        said.append(f"`{'.'.join(loc) or '?'}`: {e.get('msg', 'invalid')} (got {got})")
    return "; ".join(said) or "invalid arguments", first


# a tool that compiles takes its program as `source` or `path`, exactly one of them (a null
# one is not given)
PROGRAM_CHOICE = [{"required": ["source"], "properties": {"source": {"type": "string"}}},
                  {"required": ["path"], "properties": {"path": {"type": "string"}}}]


def _tool(fn: Callable, annotations: ToolAnnotations, structured: bool) -> Tool:
    """``fn`` as a tool (the SDK makes its input schema from its signature and, when
    ``structured``, its output schema from its return type; else it returns text) whose input
    schema allows only its own arguments (``additionalProperties: false``) and, for a tool
    that compiles, exactly one of ``source`` and ``path`` (``oneOf``)."""
    tool = Tool.from_function(fn, annotations=annotations, structured_output=structured)
    tool.parameters["additionalProperties"] = False
    if "source" in tool.parameters["properties"]:
        tool.parameters["oneOf"] = PROGRAM_CHOICE
    if tool.name in ("check", "render", "values", "describe", "write_program",
                     "import_drawing"):
        tool.description = (tool.description or "").rstrip() + "\n" + LIMITS
    return tool


class _Server(MCPServer):
    """The SDK's server, holding each tool call to its input schema's names, which the SDK
    leaves to the tools (it drops an unknown argument silently): an unknown argument, and both
    or neither of ``source`` and ``path``, are tool errors saying so
    (:func:`.tools.check_arguments`).  A prompt's arguments likewise: an unknown one, or one
    that is not text, is an invalid-params error saying so (the SDK's own failure there is a
    bare "Error rendering prompt" with a traceback on stderr)."""

    def __init__(self, *args, tools: list[Tool], **kwargs) -> None:
        super().__init__(*args, tools=tools, **kwargs)
        self.accepted = {t.name: list(t.parameters["properties"]) for t in tools}

    async def call_tool(self, name: str, arguments: dict, context=None):
        if name in self.accepted:
            try:
                T.check_arguments(name, arguments, self.accepted[name])
            except T.Refused as e:
                return refusal(e.code, str(e), e.argument)
        try:
            return await super().call_tool(name, arguments, context)
        except ToolError as e:
            from mcp.server.mcpserver.exceptions import UnexpectedToolError
            cause: BaseException | None = e
            while cause is not None and not isinstance(cause, T.Refused):
                cause = cause.__cause__
            if isinstance(cause, T.Refused):
                return refusal(cause.code, str(cause), cause.argument)
            if isinstance(e, UnexpectedToolError):
                return refusal("internal_error", f"`{name}` failed inside aidl (please "
                                                 "report it)")
            cause = e.__cause__
            if cause is not None and hasattr(cause, "errors"):
                message, argument = _validation(cause)
                return refusal("bad_argument", f"arguments of `{name}`: {message}", argument)
            text = str(e)
            prefix = f"Error executing tool {name}: "
            return refusal("bad_argument", text[len(prefix):] if text.startswith(prefix)
                           else text)

    async def get_prompt(self, name: str, arguments: dict | None = None, context=None):
        prompts = {p.name: p for p in await self.list_prompts()}
        if name in prompts:
            accepted = [a.name for a in prompts[name].arguments or []]
            try:
                T.check_arguments(name, arguments or {}, accepted)
            except T.Refused as e:
                raise MCPError(INVALID_PARAMS, str(e)) from None
            for k, v in (arguments or {}).items():
                if not isinstance(v, str) or len(v) > MAX_REQUEST:
                    raise MCPError(INVALID_PARAMS, f"`{k}` is text of at most {MAX_REQUEST} "
                                                   "characters")
        return await super().get_prompt(name, arguments, context)

    async def run_stdio_async(self) -> None:
        """The SDK's stdio serving, with JSON-RPC's error replies to lines that are no
        message (the SDK drops them: :mod:`.stdio`)."""
        await stdio.serve(self._lowlevel_server,
                          self._lowlevel_server.create_initialization_options())


def build_server(root: str, budget: float = 1.0,
                 prompt: Callable[[], str] | None = None, warm: bool = True) -> MCPServer:
    """The server for the allowed folder ``root`` with ``budget`` (a factor of the default
    evaluation budget) as each call's default; ``prompt``: a function that returns the
    ``aidl prompt`` text (given by the command line, which may import the LLM tools);
    ``warm``: start a worker and compile a small program in it at once, in the background
    (:meth:`.worker.Pool.warm`), so the first call is as fast as the rest."""
    ws = T.Workspace(root, budget)
    # the compiling tools run side by side in a pool of warm worker processes, each call
    # killed past the budget's wall guard (aidl_lang/mcp/worker.py): a call always ends,
    # and a slow one delays only itself
    from .worker import Pool
    work = Pool(str(ws.root), budget)
    if warm:
        work.warm()
    from importlib.metadata import PackageNotFoundError, version
    try:
        ver = version("aidl-lang")
    except PackageNotFoundError:         # a source tree that is not installed
        ver = "0+unknown"
    tools: list[Tool] = []

    def tool(annotations: ToolAnnotations, structured: bool = True):
        def register(fn: Callable) -> Callable:
            tools.append(_tool(fn, annotations, structured))
            return fn
        return register

    # hints for hosts: check, values and explain only read; render writes only when given
    # `output` (never outside the root); nothing reaches the network
    reads = ToolAnnotations(read_only_hint=True, idempotent_hint=True, open_world_hint=False)
    writes = ToolAnnotations(read_only_hint=False, destructive_hint=True, idempotent_hint=True,
                             open_world_hint=False)

    @tool(reads)
    def check(source: Source = None, path: ProgramPath = None, overrides: Overrides = None,
              dof: Dof = False, budget: Budget = None, sweep: Sweep = False,
              detail: Detail = False) -> Annotated[CallToolResult, CheckResult]:
        """Parse, check and solve an AIDL program; write nothing.

        Give `source` (program text) or `path` (a .aidl file, relative to the allowed folder);
        a Drawing2D("x.dxf") reads a drawing beside the program (source: in the folder).
        `overrides` sets params ({"width": "40 mm"}); `dof` adds degrees of freedom per
        structure; `sweep` adds W0110 for each param value of a declared range where the
        design breaks (sweep: points, skipped, findings); `budget` multiplies the evaluation
        budget (at most 4).
        Returns structured content (and one line of text): ok, diagnostics (code, severity,
        message, span with 1-based line and column and 0-based start/end, labels, hint,
        suggestions, fix), solve statistics, freedom (degrees of freedom left), parts (name,
        kind, bbox [x0, y0, x1, y1] mm, area mm2, holes) and fit (the assembled product's
        fit check: {checked, collisions: [{a, b, volume, depth, box}], floating: [{part,
        nearest, gap}]}); with errors, error {code, message}. """
        return answer("check", work.call("check", source, path, overrides, dof, budget,
                                         sweep, budget=budget), detail=detail)

    @tool(writes)
    def write_program(path: WritePath, text: WriteText = None, old: Old = None,
                      new: New = None, start: Start = None, end: End = None,
                      dof: Dof = False, detail: Detail = False
                      ) -> Annotated[CallToolResult, WriteResult]:
        """Write a program file inside the allowed folder, then check it (as `check`):
        the whole `text`, or a patch of the file as it is: `old` -> `new` (`old` found
        exactly once), or the characters `start` to `end` (0-based, as a diagnostic's span
        and fix give them) -> `new`. Then `check`, `render`, `values` and `describe` take it
        by `path`. Returns check's result with written (the path) and lines."""
        return answer("write_program", work.call("write_program", path, text, old, new, start,
                                                 end, dof), detail=detail)

    @tool(writes)
    def render(source: Source = None, path: ProgramPath = None, output: Output = None,
               width: Width = 800, overrides: Overrides = None, style: Style = "preview",
               budget: Budget = None, assembled: Assembled = False, layout: LayoutKind = None,
               sheet: Sheet = None, gap: Gap = None, rotate: Rotate = None, kerf: Kerf = None,
               thickness: Thickness = None, machine: Machine = None,
               page: Page = None, detail: Detail = False
               ) -> Annotated[CallToolResult, RenderResult]:
        """Compile an AIDL program and return a PNG picture of it (`width` pixels wide) and a
        summary (ok, diagnostics, parts, fit).  `output`: also write the drawing to this file
        inside the allowed folder, the format by extension (.svg, .dxf for laser cutters,
        .gcode for a GRBL laser, router or plotter per `machine`, .pdf a 1:1 printed template,
        tiled over `page` paper, .png, .stl, .3mf, .step, .glb); a cutting output adds job
        {cut_mm, travel_mm, seconds (at the `machine` profile's speeds, the laser's by
        default), machine, text}.  `style`: preview (filled) or laser (hairlines).
        `assembled`: the picture is the product in 3D, its parts placed (`Place`), collisions
        boxed in red.  `layout`: "sheet" lays the parts out on cutting sheets (`sheet`
        size, `gap`, `rotate`), a picture and a file per sheet, with layout {sheets, size,
        files, use per sheet, placements [{part, sheet, rotation, bbox}]}; `kerf` offsets the
        cuts, `thickness` sets the extrusion of 3D outputs.  When the program has errors
        there is no picture, only the diagnostics and error.  Structured content, and one
        line of text."""
        doc, pngs = work.call("render", source, path, output, width, overrides, budget,
                              style, assembled, layout, sheet, gap, rotate, kerf,
                              thickness, machine, page, budget=budget)
        return answer("render", doc, pngs, detail)

    @tool(reads)
    def values(source: Source = None, path: ProgramPath = None, names: Names = None,
               overrides: Overrides = None, budget: Budget = None,
               detail: Detail = False) -> Annotated[CallToolResult, ValuesResult]:
        """The solved values of named entities, in the file's units: each structure's frame
        origin and bounding box, each named geometry's points (center, start, end, corners)
        and sizes (radius and diameter, width, height, a rounded rectangle's corner_radius),
        every copy of a pattern too, from the original (corners[0], corners[1].c.center, each
        at its real origin).  `names` filters by dotted prefix (e.g. ["plate.bore",
        "plate.body.width"]); the root structure's name may be left out.
        Returns structured content (and one line of text): ok, units, values [{name, kind,
        value, unit, mm (when not the same as value)}]; more than 12 copies of one name
        (cut_a[0].start, cut_a[1].start, ...) are one {name: "cut_a[*].start", kind: "group",
        count, value} unless `detail` (which also adds text, one `name = value unit` line
        each)."""
        return answer("values", work.call("values", source, path, names, overrides, budget,
                                          budget=budget), detail=detail)

    @tool(reads)
    def describe(source: Source = None, path: ProgramPath = None, overrides: Overrides = None,
                 budget: Budget = None,
                 detail: Detail = False) -> Annotated[CallToolResult, DescribeResult]:
        """What the final part is, for checking it without a picture: for each part its
        outline (kind, size, box), each opening with its kind (circle d=..., slot l long, w
        wide, rectangle, star, arc slot, n-gon), centre and size, engravings (text, height and
        place), copies (parts of the same shape, listed once under the first with their
        places) and symmetries (mirror, n-fold rotation); mm. More than 12 alike openings or
        cuts are said once with their count and the box of their places, unless `detail`.
        Returns structured content (and one line of text): ok, diagnostics, text (one line
        per feature) and describe (the same as data)."""
        return answer("describe", work.call("describe", source, path, overrides, budget,
                                            budget=budget), detail=detail)

    @tool(writes)
    def import_drawing(path: DrawingPath, infer: Infer = True, parts: Parts = False,
                       units: Units = None, output: ProgramOutput = None,
                       budget: Budget = None) -> Annotated[CallToolResult, ImportResult]:
        """Turn a DXF or SVG drawing into an AIDL program to edit (`aidl import`).  With
        `infer` (the default) the program is the design a person would write: the outline as
        RoundedRectangle, Slot, RegularPolygon..., holes named by what they are
        (corner_holes, bolt_circle, motor_holes, bore, slots, notches) with loops for
        patterns, one param per repeated size, pitch and count, features placed from the
        body's nearest edge or centre, every shape held where the drawing has it; exact to
        1e-6 mm.  Returns structured content (and one line of text): ok, program (the text),
        notes (what was skipped), output (the file written: then `write_program` patches it
        and the other tools take it by `path`); or ok false, diagnostics and error."""
        doc = work.call("import_drawing", path, infer, parts, units, output, budget,
                        budget=budget)
        if not doc.get("ok") and doc.get("diagnostics"):
            d = doc["diagnostics"][0]
            doc["error"] = {"code": d["code"], "message": d["message"]}
        return answer("import_drawing", doc)

    @tool(reads, structured=False)
    def explain(code: Code) -> str:
        """What a diagnostic code (E0103, W0402, ...) means, with an example."""
        return T.explain(code)

    @tool(reads, structured=False)
    def docs(name: TopicName = None) -> str:
        """The reference of a shape, constraint, statement or standard-library template (as
        `aidl docs NAME`): signature, the unit of every parameter, members and an example
        program that compiles.  Any case or style finds a name (SpurGear, spur-gear); no
        name: the list of topics."""
        return T.docs(name)

    server = _Server("aidl", instructions=INSTRUCTIONS, version=ver, tools=tools)
    _resources(server, prompt)
    return server


def _worded(render: Callable[[], str]) -> Callable[[], str]:
    """``render``'s text worded for the tools (:func:`.wording.for_agents`)."""
    def read() -> str:
        return for_agents(render())
    return read


def _resources(server: MCPServer, prompt: Callable[[], str] | None) -> None:
    """Offer the docs, the prompt (worded for the tools), the standard library and the
    examples as resources of ``server`` (see the module text)."""
    from ..reference import index_text, topics
    server.resource("aidl://docs/topics", name="aidl docs topics", mime_type="text/plain",
                    description="`aidl docs`: every topic (statements, shapes, constraints, "
                                "relations, operations, stdlib templates)")(index_text)
    for name, topic in topics().items():
        server.resource(f"aidl://docs/topic/{name}", name=f"aidl docs {name}",
                        mime_type="text/plain",
                        description=f"{topic.kind}: {topic.summary}")(_worded(topic.render))
    server.resource("aidl://docs/language", name="language reference", mime_type="text/markdown",
                    description="The AIDL language reference (docs/language.md)")(
        _text_of(_DOCS / "language.md", "docs/language.md"))
    server.resource("aidl://docs/api", name="Python API", mime_type="text/markdown",
                    description="The Python API and the solved values (docs/api.md)")(
        _text_of(_DOCS / "api.md", "docs/api.md"))
    if prompt is not None:
        server.resource("aidl://prompt", name="system prompt", mime_type="text/plain",
                        description="`aidl prompt`: the vocabulary with signatures, and "
                                    "example programs, worded for the tools")(
            lambda: for_agents(prompt()))

        @server.prompt(name="aidl", title="Write AIDL",
                       description="The AIDL system prompt (`aidl prompt`): the language, its "
                                   "vocabulary with signatures, the standard library and example "
                                   "programs; `request`: a part to design, appended")
        def aidl_prompt(request: Request = None) -> str:
            text = for_agents(prompt())
            if request and request.strip():
                text += f"\nDesign this part: {request.strip()}\n"
            return text
    from ..sources import STDLIB
    for f in sorted(Path(STDLIB).glob("**/*.aidl")):
        rel = f.relative_to(STDLIB).as_posix()
        server.resource(f"aidl://stdlib/{rel}", name=f"std/{rel}", mime_type="text/plain",
                        description=f"standard library module: import \"std/{rel}\"")(
            _text_of(f, f"std/{rel}"))
    if _EXAMPLES.is_dir():
        for f in sorted(_EXAMPLES.glob("**/*.aidl")):
            rel = f.relative_to(_EXAMPLES).as_posix()
            server.resource(f"aidl://examples/{rel}", name=f"example {rel}",
                            mime_type="text/plain", description="an example program")(
                _text_of(f, f"examples/{rel}"))


def main(root: str, budget: float = 1.0, prompt: Callable[[], str] | None = None) -> int:
    """Serve over stdin/stdout until the client closes them."""
    import os
    build_server(root, budget, prompt, warm=not os.environ.get("AIDL_MCP_COLD")).run("stdio")
    return 0
