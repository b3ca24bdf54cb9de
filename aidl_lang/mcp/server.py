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

from ..output.writers import FORMATS
from ..sources import EXAMPLES as _EXAMPLES    # inside the package: shipped in the wheel
from . import tools as T
from .schemas import CheckResult, DescribeResult, ImportResult, RenderResult, ValuesResult
from .wording import for_agents

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
                f"wall time), above 0 and at most {T.MAX_BUDGET:g}; default: the server's "
                f"(`aidl mcp --budget`).",
    gt=0, le=T.MAX_BUDGET)]
Dof = Annotated[bool, Field(
    description="Also count the degrees of freedom left per structure, with the entities "
                "still free to move.")]
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
Names = Annotated[list[str] | None, Field(
    description="Dotted name prefixes to keep, e.g. [\"plate.bore\", \"body.width\"] (the "
                "root structure's name may be left out); default: every value.")]
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
                raise ToolError(str(e)) from None
        return await super().call_tool(name, arguments, context)

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


def build_server(root: str, budget: float = 1.0,
                 prompt: Callable[[], str] | None = None) -> MCPServer:
    """The server for the allowed folder ``root`` with ``budget`` (a factor of the default
    evaluation budget) as each call's default; ``prompt``: a function that returns the
    ``aidl prompt`` text (given by the command line, which may import the LLM tools)."""
    ws = T.Workspace(root, budget)
    # the compiling tools run side by side in a pool of warm worker processes, each call
    # killed past twice the budget's wall time (aidl_lang/mcp/worker.py): a call always ends,
    # and a slow one delays only itself
    from .worker import Pool
    work = Pool(str(ws.root), budget)
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

    def refused(e: Exception) -> ToolError:
        return ToolError(for_agents(str(e)))

    # hints for hosts: check, values and explain only read; render writes only when given
    # `output` (never outside the root); nothing reaches the network
    reads = ToolAnnotations(read_only_hint=True, idempotent_hint=True, open_world_hint=False)
    writes = ToolAnnotations(read_only_hint=False, destructive_hint=True, idempotent_hint=True,
                             open_world_hint=False)

    @tool(reads)
    def check(source: Source = None, path: ProgramPath = None, overrides: Overrides = None,
              dof: Dof = False, budget: Budget = None) -> CheckResult:
        """Parse, check and solve an AIDL program; write nothing.

        Give `source` (program text) or `path` (a .aidl file, relative to the allowed folder);
        a Drawing2D("x.dxf") reads a drawing beside the program (source: in the folder).
        `overrides` sets params like `aidl --set` ({"width": "40 mm"}); `dof` adds degrees of
        freedom per structure; `budget` multiplies the evaluation budget (at most 4).
        Returns (structured content, and the same JSON as text): ok, diagnostics (code,
        severity, message, span with 1-based line and column, labels, hint, suggestions, fix),
        solve statistics, freedom (degrees of freedom left) and parts (name, kind, bbox [x0,
        y0, x1, y1] mm, area mm2, holes)."""
        try:
            return work.call("check", source, path, overrides, dof, budget, budget=budget)
        except T.Refused as e:
            raise refused(e) from None

    @tool(writes)
    def render(source: Source = None, path: ProgramPath = None, output: Output = None,
               width: Width = 800, overrides: Overrides = None, style: Style = "preview",
               budget: Budget = None, assembled: Assembled = False, layout: LayoutKind = None,
               sheet: Sheet = None, gap: Gap = None, rotate: Rotate = None, kerf: Kerf = None,
               thickness: Thickness = None, machine: Machine = None,
               page: Page = None) -> Annotated[CallToolResult, RenderResult]:
        """Compile an AIDL program and return a PNG picture of it (`width` pixels wide) and a
        JSON summary (ok, diagnostics, parts).  `output`: also write the drawing to this file
        inside the allowed folder, the format by extension (.svg, .dxf for laser cutters,
        .gcode for a GRBL laser, router or plotter per `machine`, .pdf a 1:1 printed template,
        tiled over `page` paper, .png, .stl, .3mf, .step, .glb).
        `style`: preview (filled) or laser (hairlines).
        `assembled`: the picture is the product in 3D, its parts placed (`Place`), collisions
        boxed in red.  `layout`: "sheet" lays the parts out on cutting sheets (`sheet`
        size, `gap`, `rotate`), a picture and a file per sheet; `kerf` offsets the cuts,
        `thickness` sets the extrusion of 3D outputs (as `aidl render`'s options).  When the
        program has errors there is no picture, only the diagnostics.  The summary is
        structured content (and the same JSON as text)."""
        try:
            doc, pngs = work.call("render", source, path, output, width, overrides, budget,
                                  style, assembled, layout, sheet, gap, rotate, kerf,
                                  thickness, machine, page, budget=budget)
        except T.Refused as e:
            raise refused(e) from None
        pictures = [Image(data=png, format="png").to_image_content() for png in pngs]
        return CallToolResult(content=pictures + [TextContent(type="text", text=_json(doc))],
                              structured_content=doc)

    @tool(reads)
    def values(source: Source = None, path: ProgramPath = None, names: Names = None,
               overrides: Overrides = None, budget: Budget = None) -> ValuesResult:
        """The solved values of named entities, in the file's units: each structure's frame
        origin and bounding box, each named geometry's points (center, start, end, corners)
        and sizes (radius, width, height), every copy of a pattern too, from the original
        (corners[0], corners[1].c.center, each at its real origin).  `names` filters by
        dotted prefix (e.g. ["plate.bore", "plate.body.width"]); the root structure's name
        may be left out.
        Returns (structured content, and the same JSON as text): ok, units, values [{name,
        kind, value, unit, mm}] and text (one `name = value unit` line each)."""
        try:
            return work.call("values", source, path, names, overrides, budget, budget=budget)
        except T.Refused as e:
            raise refused(e) from None

    @tool(reads)
    def describe(source: Source = None, path: ProgramPath = None, overrides: Overrides = None,
                 budget: Budget = None) -> DescribeResult:
        """What the final part is, for checking it without a picture: for each part its
        outline (kind, size, box), each opening with its kind (circle d=..., slot l long, w
        wide, rectangle, star, arc slot, n-gon), centre and size, engravings (text, height and
        place), copies (parts of the same shape, listed once under the first with their
        places) and symmetries (mirror, n-fold rotation); mm. Returns (structured content, and
        the same JSON as text): ok, diagnostics, text (one line per feature) and describe (the
        same as data)."""
        try:
            return work.call("describe", source, path, overrides, budget, budget=budget)
        except T.Refused as e:
            raise refused(e) from None

    @tool(writes)
    def import_drawing(path: DrawingPath, infer: Infer = True, parts: Parts = False,
                       units: Units = None, output: ProgramOutput = None,
                       budget: Budget = None) -> ImportResult:
        """Turn a DXF or SVG drawing into an AIDL program to edit (`aidl import`).  With
        `infer` (the default) the program is the design a person would write: the outline as
        RoundedRectangle, Slot, RegularPolygon..., holes named by what they are
        (corner_holes, bolt_circle, motor_holes, bore, slots, notches) with loops for
        patterns, one param per repeated size, pitch and count, features placed from the
        body's nearest edge or centre, every shape held where the drawing has it; exact to
        1e-6 mm.  Returns
        (structured content, and the same JSON as text): ok, program (the text), notes (what
        was skipped), output (the file written); or ok false and diagnostics."""
        try:
            return work.call("import_drawing", path, infer, parts, units, output, budget,
                             budget=budget)
        except T.Refused as e:
            raise refused(e) from None

    @tool(reads, structured=False)
    def explain(code: Code) -> str:
        """What a diagnostic code (E0103, W0402, ...) means, with an example."""
        try:
            return T.explain(code)
        except T.Refused as e:
            raise refused(e) from None

    @tool(reads, structured=False)
    def docs(name: TopicName = None) -> str:
        """The reference of a shape, constraint, statement or standard-library template (as
        `aidl docs NAME`): signature, the unit of every parameter, members and an example
        program that compiles.  Any case or style finds a name (SpurGear, spur-gear); no
        name: the list of topics."""
        try:
            return T.docs(name)
        except T.Refused as e:
            raise refused(e) from None

    server = _Server("aidl", instructions=INSTRUCTIONS, version=ver, tools=tools)
    from ..reference import index_text, topics
    server.resource("aidl://docs/topics", name="aidl docs topics", mime_type="text/plain",
                    description="`aidl docs`: every topic (statements, shapes, constraints, "
                                "relations, operations, stdlib templates)")(index_text)
    for name, topic in topics().items():
        server.resource(f"aidl://docs/topic/{name}", name=f"aidl docs {name}",
                        mime_type="text/plain",
                        description=f"{topic.kind}: {topic.summary}")(topic.render)
    server.resource("aidl://docs/language", name="language reference", mime_type="text/markdown",
                    description="The AIDL language reference (docs/language.md)")(
        _text_of(_DOCS / "language.md", "docs/language.md"))
    server.resource("aidl://docs/api", name="Python API", mime_type="text/markdown",
                    description="The Python API and the solved values (docs/api.md)")(
        _text_of(_DOCS / "api.md", "docs/api.md"))
    if prompt is not None:
        server.resource("aidl://prompt", name="system prompt", mime_type="text/plain",
                        description="`aidl prompt`: the vocabulary with signatures, and "
                                    "example programs")(lambda: prompt())

        @server.prompt(name="aidl", title="Write AIDL",
                       description="The AIDL system prompt (`aidl prompt`): the language, its "
                                   "vocabulary with signatures, the standard library and example "
                                   "programs; `request`: a part to design, appended")
        def aidl_prompt(request: Request = None) -> str:
            text = prompt()
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
    return server


def main(root: str, budget: float = 1.0, prompt: Callable[[], str] | None = None) -> int:
    """Serve over stdin/stdout until the client closes them."""
    build_server(root, budget, prompt).run("stdio")
    return 0
