"""``aidl mcp``: the Model Context Protocol server over stdio, on the official ``mcp`` SDK
(``MCPServer``).  The tools are thin wrappers of :mod:`.tools`; docs/mcp.md lists them.

Tools: ``check``, ``render`` (a file written inside the root and its figures; a PNG image
block with ``picture``),
``values``, ``describe`` (the final part in words), ``import_drawing`` (``aidl import
[--infer]`` of a DXF or SVG in the root, with the check of the program), ``write_program``,
``set_params`` (params rewritten in a file), ``measure`` (distance, angle, clearance between
named entities), ``explain``, ``docs``.  The compiling four
run side by side in a pool of worker processes (:mod:`.worker`) and return structured content
of the output schemas of :mod:`.schemas`; their input schemas take exactly one of ``source``
and ``path`` and nothing they do not list (:class:`_Server` refuses the rest).  ``tools/list``
is kept short (:func:`slim`, :func:`outline_schema`, :func:`_share`; the full output schemas
are the resources ``aidl://schemas/NAME.json``).  Resources:
``aidl://docs/language`` (the language reference), ``aidl://docs/api``, ``aidl://docs/topics``
and ``aidl://docs/topic/NAME`` (the topics of ``aidl docs``), ``aidl://prompt`` (the ``aidl
prompt`` text, when the caller provides it), ``aidl://stdlib/NAME.aidl`` and
``aidl://examples/NAME.aidl``.  Prompt: ``aidl`` (the system prompt, when the caller provides
it).
"""
from __future__ import annotations

import json
from collections.abc import Callable
from contextvars import ContextVar
from pathlib import Path
from typing import Annotated, Literal

from mcp.server.mcpserver import Image, MCPServer
from mcp.server.mcpserver.exceptions import ToolError
from mcp.server.mcpserver.tools import Tool
from mcp.shared.exceptions import MCPError
from mcp_types import INVALID_PARAMS, CallToolResult, TextContent, ToolAnnotations
from pydantic import Field

from ..base.limits import DEFAULT_BUDGET, MAX_ITER, MAX_TEMPLATE_DEPTH
from ..parser import MAX_NESTING
from ..library.sources import EXAMPLES as _EXAMPLES    # inside the package: shipped in the wheel
from ..library.sources import MAX_DRAWING_BYTES
from . import compact as C
from . import stdio
from . import tools as T
from .schemas import (CheckResult, DescribeResult, ImportResult, MeasureResult, RenderResult,
                      SetParamsResult, ValuesResult, WriteResult)
from .order import Call, Calls
from .wording import for_agents

# the call being answered, in the task that answers it (:class:`_Server` numbers each call
# as it comes in: :mod:`.order`)
CALL: ContextVar[Call | None] = ContextVar("aidl_mcp_call", default=None)

# the formats `render` writes, by extension (aidl_lang/output/writers' FORMATS but `.stp`,
# said here so that the server starts without the writers and what they import: numpy,
# Manifold; tests/test_mcp_text.py holds the two the same)
OUTPUT_FORMATS = (".svg", ".dxf", ".pdf", ".png", ".stl", ".3mf", ".step", ".glb", ".gcode",
                  ".nc", ".lbrn2", ".plt", ".hpgl")

# what one program may build (aidl_lang/base/limits.py, the parser's and the importer's limits),
# said once, in `check`'s description (the first tool: an agent reads it first)
LIMITS = (f"Limits: {T.MAX_SOURCE:,} characters, brackets {MAX_NESTING} deep, "
          f"{MAX_ITER:,} items in one loop, templates {MAX_TEMPLATE_DEPTH} deep, "
          f"{DEFAULT_BUDGET.steps:,} loop steps, {DEFAULT_BUDGET.objects:,} objects, "
          f"{DEFAULT_BUDGET.work:,} work units (x `budget`); drawings "
          f"{MAX_DRAWING_BYTES // 1_000_000} MB. Past one: a located E0304 (E0003, E0301), "
          f"not a hang.")

# The tools' arguments: the SDK turns each description, allowed value and range into the
# JSON Schema of `tools/list`, and checks calls against it before a tool runs.  An argument
# several tools take is described in full in the first of them only (:func:`_share`).
Source = Annotated[str | None, Field(
    description="The program text; or give `path`.", max_length=T.MAX_SOURCE)]
ProgramPath = Annotated[str | None, Field(
    description="A .aidl file in the allowed folder; or give `source`.")]
Overrides = Annotated[dict[str, str | int | float | bool] | None, Field(
    description="Param values: {\"width\": \"40 mm\"}, {\"width\": 40} (the param's own unit), "
                "{\"holes\": true}.")]
Budget = Annotated[float | None, Field(
    description="Times the budget (15 s CPU, steps, objects); "
                "default 1.", gt=0, le=T.MAX_BUDGET)]
Dof = Annotated[bool, Field(
    description="Count the degrees of freedom per structure, and what still moves.")]
Sweep = Annotated[bool, Field(
    description="Also check the design across its params' min..max ranges (W0110).")]
Output = Annotated[str | None, Field(
    description="Also write this file (in the allowed folder), by its extension: "
                + ", ".join(OUTPUT_FORMATS) + ".")]
Picture = Annotated[bool, Field(
    description="Also return a PNG picture, `width` pixels wide (default: none).")]
Width = Annotated[int, Field(
    description="Width in pixels of the picture and of a written .png.",
    ge=16, le=T.MAX_PNG_WIDTH)]
Style = Annotated[Literal["preview", "laser"], Field(
    description="preview: filled parts; laser: hairline cut paths.")]
Assembled = Annotated[bool, Field(
    description="The product in 3D (parts placed by `Place`, collisions red), not the flat "
                "parts: a picture, .png, .stl, .3mf, .step, .glb.")]
LayoutKind = Annotated[Literal["sheet"] | None, Field(
    description="\"sheet\": nest the solid parts on cutting sheets, one file (cut-1.dxf, "
                "...) and picture per sheet.")]
Sheet = Annotated[str | None, Field(
    description="With layout: sheet size, \"600x400mm\" (default) or \"24x12in\".",
    max_length=100)]
Gap = Annotated[str | float | None, Field(
    description="With layout: space between parts and to the edge, mm or \"3mm\" (default).")]
Rotate = Annotated[Annotated[str, Field(max_length=200)] | float | None, Field(
    description="With layout: allowed turns in degrees, \"0,90\" (default), 0 or \"any\".")]
Kerf = Annotated[str | float | None, Field(
    description="Offset the cuts by half this kerf (mm or \"0.15mm\", at most 10 mm); "
                "default: the program's.")]
Thickness = Annotated[str | float | None, Field(
    description="Extrusion of 3D outputs (mm or \"3mm\"); default: the program's, else 3 mm.")]
Machine = Annotated[str | dict | None, Field(
    description="G-code machine: laser (default), router, plotter, a profile .toml or its "
                "keys as an object (`docs` machine).")]
Page = Annotated[str | None, Field(
    description="A .pdf tiled over paper: \"A4\", \"A3\", \"Letter\", \"Legal\", "
                "\"-landscape\" after any.", max_length=40)]
DrawingPath = Annotated[str, Field(
    description="A .dxf or .svg drawing in the allowed folder.")]
Infer = Annotated[bool, Field(
    description="Write the design (shapes, loops, named params); false: the drawing's "
                "pieces.")]
Parts = Annotated[bool, Field(
    description="A sheet of parts: one solid per outer outline, in an assembly.")]
Units = Annotated[Literal["mm", "cm", "m", "in", "ft", "pt", "px"] | None, Field(
    description="The drawing's unit, instead of the file's own.")]
ProgramOutput = Annotated[str | None, Field(
    description="Also write the program to this .aidl file in the allowed folder.")]
Names = Annotated[list[Annotated[str, Field(max_length=500)]] | None, Field(
    description="Dotted name prefixes, e.g. [\"plate.bore\"] (the root's name optional); "
                "default: all.", max_length=200)]
Detail = Annotated[bool, Field(
    description=f"Every item in full (default: over {C.GROUP_AT} alike items said once, "
                "counted).")]
WritePath = Annotated[str, Field(
    description="The .aidl file to write in the allowed folder (folders made).")]
WriteText = Annotated[str | None, Field(
    description="The whole program text (instead of a patch).", max_length=T.MAX_SOURCE)]
Old = Annotated[str | None, Field(
    description="Patch: text found exactly once in the file, replaced by `new`.",
    max_length=T.MAX_SOURCE)]
New = Annotated[str | None, Field(
    description="Patch: the replacement of `old`, or of characters `start`..`end`.",
    max_length=T.MAX_SOURCE)]
Start = Annotated[int | None, Field(
    description="Patch: 0-based offset of the first character replaced.",
    ge=0)]
End = Annotated[int | None, Field(
    description="Patch: offset after the last character replaced.", ge=0)]
ParamValues = Annotated[dict[str, str | int | float | bool], Field(
    description="Param name -> new value: \"50 mm\", 50 (the param's own unit), true.",
    min_length=1, max_length=200)]
EntityName = Annotated[str, Field(
    description="A name as `values` gives it: a point, line, circle, shape, part "
                "(plate.bore.c, gear_a).", min_length=1, max_length=500)]
Code = Annotated[str, Field(
    description="A diagnostic code, e.g. E0103 or W0402.", min_length=1, max_length=16)]
TopicName = Annotated[str | None, Field(
    description="A shape, constraint, statement or stdlib template, any case (Circle, "
                "SpurGear, assert); none: the topics.", max_length=200)]

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
more), then `render` to write the file and read its figures (picture=true to see it), `describe` to read the final part in words (outline, openings \
with centres and sizes, texts, symmetries), `values` to read exact positions and sizes and \
`measure` for the distance, angle or clearance between two of them; `set_params` changes a \
file's params. Paths are relative to the server's allowed folder; nothing outside it can be read or written."""

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
    (:mod:`.compact`), the pictures, and the same as text: a first line (the figures) and a
    line per diagnostic, value, feature, ... (:func:`.compact.body`); a program with errors
    also carries ``error`` (its first error's code and the summary)."""
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
    # the first line, then the rest of what the structured content holds (issue 95: a host
    # may show the model the text only); before the repeats go: the line says the job's text
    said = "\n".join([C.line(tool, doc), *C.body(tool, doc)])
    return CallToolResult(content=pictures + [TextContent(type="text", text=said)],
                          structured_content=C.no_repeats(doc, detail))


def _commit(calls: Calls, doc: dict, files: list, key: str, argument: str = "output") -> None:
    """Write the files a call's worker made (:meth:`.order.Calls.write`, in the order the
    calls were made); a file a later call wrote is left, and ``doc`` says so in
    ``superseded`` (and no longer names it under ``key``).  Raises :class:`~.tools.Refused`
    (``output_failed``) for a write that fails."""
    call = CALL.get(None) or calls.arrive("render")
    try:
        kept = calls.write(call, files)
    except OSError as e:
        raise T.Refused(str(e), "output_failed", argument) from None
    if kept:
        if files and Path(files[0][0]) in {t for t, _, _ in kept}:
            doc.pop(key, None)
        later = max(seq for _, _, seq in kept)
        doc["superseded"] = (f"{', '.join(s for _, s, _ in kept)} not written: call #{later}, "
                             f"made after this one (#{call.seq}), wrote it; of two calls "
                             "writing one file the one made last wins")


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


def slim(schema):
    """A JSON Schema as ``tools/list`` sends it, without what says nothing to a client: no
    ``title`` (the property's name again), no ``default: null``, an ``anyOf`` of one typed
    schema and null as that schema with ``null`` among its types (``{"type": ["string",
    "null"], "maxLength": ...}``), an ``anyOf`` of bare types as one ``type`` list.  It
    accepts the same values."""
    if isinstance(schema, list):
        return [slim(x) for x in schema]
    if not isinstance(schema, dict):
        return schema
    out = {}
    for k, v in schema.items():
        if k == "title" and isinstance(v, str) or k == "default" and v is None:
            continue
        out[k] = v if k in ("default", "const", "enum", "required") else slim(v)
    any_of = out.get("anyOf")
    if not isinstance(any_of, list):
        return out
    null = {"type": "null"} in any_of
    kept = [x for x in any_of if x != {"type": "null"}]
    if len(kept) == 1 and "const" in kept[0] and set(kept[0]) <= {"const", "type"}:
        out.pop("anyOf")
        out["enum"] = [kept[0]["const"]] + ([None] if null else [])
        return out
    merged = _merge_types(kept)
    if merged is None:
        return out
    out.pop("anyOf")
    out = {**merged, **out}
    if null:
        t = out["type"]
        out["type"] = [*(t if isinstance(t, list) else [t]), "null"]
        if "enum" in out:
            out["enum"] = [*out["enum"], None]
    if isinstance(out["type"], list) and len(out["type"]) == 1:
        out["type"] = out["type"][0]
    return out


# the keywords that apply to one JSON type only: a schema of several types may hold them
_ONLY = {"string": {"maxLength", "minLength", "pattern", "enum"},
         "number": {"minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"},
         "object": {"additionalProperties", "properties"}, "boolean": set()}


def _merge_types(branches: list) -> dict | None:
    """One schema ``{"type": [...], ...}`` accepting what ``anyOf`` of ``branches`` accepts,
    when each branch is one type with only that type's keywords (a string's ``maxLength``
    binds no number) and no two branches share a type; ``integer`` goes into a bare
    ``number``; None when they cannot be merged."""
    types = [b.get("type") for b in branches]
    if not branches or not all(isinstance(t, str) for t in types):
        return None
    if "integer" in types and "number" in types and branches[types.index("number")] == \
            {"type": "number"} and branches[types.index("integer")] == {"type": "integer"}:
        branches = [b for b in branches if b.get("type") != "integer"]
        types.remove("integer")
    if len(set(types)) < len(types):
        return None
    merged: dict = {}
    for b, t in zip(branches, types):
        extra = set(b) - {"type"}
        if len(branches) > 1 and not extra <= _ONLY.get(t, set()):
            return None
        merged.update({k: b[k] for k in extra})
    if "enum" in merged and len(branches) > 1:
        return None
    merged["type"] = types[0] if len(types) == 1 else types
    return merged


def _outline(prop: dict, defs: dict) -> str:
    """The fields of an object (through ``$ref``, arrays and ``anyOf``) in one line:
    ``{code, severity, message, span, ...}``, ``[{name, kind, bbox, ...}]``; "" for a value
    with no fields."""
    if "$ref" in prop:
        prop = defs.get(prop["$ref"].rsplit("/", 1)[-1], {})
    for alt in prop.get("anyOf", []):
        said = _outline(alt, defs)
        if said:
            return said
    if prop.get("type") == "array" and isinstance(prop.get("items"), dict):
        said = _outline(prop["items"], defs)
        return f"[{said}]" if said else ""
    if prop.get("type") == "object" and prop.get("properties"):
        return "{" + ", ".join(prop["properties"]) + "}"
    return ""


def _kind(prop: dict, defs: dict) -> dict:
    """The JSON type of a property (``{"type": ...}``, through ``$ref`` and ``anyOf``), {}
    when it may be anything."""
    if "$ref" in prop:
        return _kind(defs.get(prop["$ref"].rsplit("/", 1)[-1], {}), defs)
    if "anyOf" in prop:
        kinds = [_kind(a, defs).get("type") for a in prop["anyOf"]]
        if None in kinds:
            return {}
        flat = sorted({k for x in kinds for k in ([x] if isinstance(x, str) else x)})
        return {"type": flat[0] if len(flat) == 1 else flat}
    if "const" in prop or "enum" in prop:
        return {k: prop[k] for k in ("const", "enum") if k in prop}
    return {"type": prop["type"]} if "type" in prop else {}


def outline_schema(full: dict, resource: str | None = None) -> dict:
    """The output schema ``tools/list`` gives for the full one ``full`` (a pydantic JSON
    Schema, ``$defs`` inlined by reference): every top-level property with its JSON type and
    its description, an object's or a list's fields named in one line (``[{name, kind, bbox,
    area, holes, loops}]``), nothing deeper.  Everything the full schema accepts it accepts
    (it lists the same properties and ``required``, with their types only); the server
    still checks each result against the full schema, which ``resource`` (a URI) serves."""
    defs = full.get("$defs", {})
    props = {}
    for name, p in full.get("properties", {}).items():
        desc = p.get("description") or ""
        fields = _outline(p, defs)
        said = " ".join(x for x in (desc, fields) if x)
        props[name] = {**_kind(p, defs), **({"description": said} if said else {})}
    out = {"type": "object", "properties": props}
    if full.get("required"):
        out["required"] = full["required"]
    if resource:
        out["description"] = f"full schema: {resource}"
    return out


def _tool(fn: Callable, annotations: ToolAnnotations, structured: bool) -> Tool:
    """``fn`` as a tool (the SDK makes its input schema from its signature and, when
    ``structured``, its output schema from its return type; else it returns text) whose input
    schema allows only its own arguments (``additionalProperties: false``) and, for a tool
    that compiles, exactly one of ``source`` and ``path`` (``oneOf``); both schemas made
    short for ``tools/list`` (:func:`slim`, :func:`outline_schema`: the full output schema
    is the resource ``aidl://schemas/NAME.json``, and each result is still checked against
    it before it is sent)."""
    tool = Tool.from_function(fn, annotations=annotations, structured_output=structured)
    tool.description = " ".join((tool.description or "").split())     # (no docstring indent)
    tool.parameters = slim(tool.parameters)
    tool.parameters["additionalProperties"] = False
    if "source" in tool.parameters["properties"]:
        tool.parameters["oneOf"] = PROGRAM_CHOICE
    if tool.name == "check":             # the limits, said once: in the first tool
        tool.description = (tool.description or "").rstrip() + "\n" + LIMITS
    meta = tool.fn_metadata
    if meta.output_schema is not None:
        FULL_SCHEMAS[tool.name] = meta.output_schema
        meta.output_schema = outline_schema(meta.output_schema, schema_uri(tool.name))
    return tool


FULL_SCHEMAS: dict[str, dict] = {}     # tool -> its full output schema (a resource)


def schema_uri(name: str) -> str:
    """The resource that serves the full output schema of the tool ``name``."""
    return f"aidl://schemas/{name}.json"


def _share(tools: list[Tool]) -> None:
    """Say what several tools share once, in the first of them (``tools/list`` is read in
    one go): an argument taken alike (the same schema and description) is described in full
    in the first tool only, in the others ``as in `FIRST```; an output field returned alike
    is listed in the first tool's output schema only, the others name it in their schema's
    description (``as `check`: ok, error, ...``; a schema without it still accepts it)."""
    first: dict[str, str] = {}
    for t in tools:
        own: dict[str, str] = {}            # an argument as an earlier one of the same tool
        for name, prop in t.parameters.get("properties", {}).items():
            key = json.dumps(["in", name, prop], sort_keys=True)
            alike = json.dumps(prop, sort_keys=True)
            if key in first:
                prop["description"] = f"as in `{first[key]}`"
            elif alike in own and "description" in prop:
                prop["description"] = f"as `{own[alike]}`"
            else:
                first.setdefault(key, t.name)
                own.setdefault(alike, name)
    fields = {t.name: list((t.fn_metadata.output_schema or {}).get("properties", {}))
              for t in tools}
    for t in tools:
        out = t.fn_metadata.output_schema
        if not out:
            continue
        shared: dict[str, list[str]] = {}
        for name, prop in list(out["properties"].items()):
            key = json.dumps(["out", name, prop], sort_keys=True)
            if first.setdefault(key, t.name) != t.name:
                shared.setdefault(first[key], []).append(name)
                del out["properties"][name]
        said = [f"as `{k}`: " + ("all its fields" if v == fields[k] else ", ".join(v))
                for k, v in shared.items()]
        out["description"] = "; ".join(said + [out.get("description", "")]).strip("; ")


class _Server(MCPServer):
    """The SDK's server, holding each tool call to its input schema's names, which the SDK
    leaves to the tools (it drops an unknown argument silently): an unknown argument, and both
    or neither of ``source`` and ``path``, are tool errors saying so
    (:func:`.tools.check_arguments`).  A prompt's arguments likewise: an unknown one, or one
    that is not text, is an invalid-params error saying so (the SDK's own failure there is a
    bare "Error rendering prompt" with a traceback on stderr)."""

    def __init__(self, *args, tools: list[Tool], calls: Calls, **kwargs) -> None:
        _share(tools)                     # every tool's, wherever it is defined
        super().__init__(*args, tools=tools, **kwargs)
        self.accepted = {t.name: list(t.parameters["properties"]) for t in tools}
        self.calls = calls
        self.topics_offered = False       # the docs' topics: offered on the first resources call

    async def call_tool(self, name: str, arguments: dict, context=None):
        if name not in self.accepted:     # JSON-RPC's invalid params (the MCP spec's words)
            from ..base.diagnostics import did_you_mean
            near = did_you_mean(str(name), list(self.accepted), 1)
            raise MCPError(INVALID_PARAMS, f"Unknown tool: `{name}`"
                           + (f"; did you mean `{near[0]}`?" if near else "")
                           + f"; the tools: {', '.join(self.accepted)}")
        try:
            T.check_arguments(name, arguments, self.accepted[name])
        except T.Refused as e:
            return refusal(e.code, str(e), e.argument)
        CALL.set(self.calls.arrive(name))     # numbered as it came in (.order)
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

    async def list_resources(self):
        self._topics()
        return await super().list_resources()

    async def read_resource(self, uri, context=None):
        self._topics()
        return await super().read_resource(uri, context)

    def _topics(self) -> None:
        if not self.topics_offered:
            self.topics_offered = True
            _topic_resources(self)

    async def run_stdio_async(self) -> None:
        """The SDK's stdio serving, with JSON-RPC's error replies to lines that are no
        message (the SDK drops them: :mod:`.stdio`)."""
        await stdio.serve(self._lowlevel_server,
                          self._lowlevel_server.create_initialization_options(),
                          getattr(self, "first", None))


def _version() -> str:
    """The installed package's version ("0+unknown" for a source tree not installed)."""
    from importlib.metadata import PackageNotFoundError, version
    try:
        return version("aidl-lang")
    except PackageNotFoundError:
        return "0+unknown"


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
    # the files are written here, in the order the calls were made; a cancelled call's
    # worker is stopped and it writes nothing (.order, issue 91)
    calls = Calls(lambda target, data, program, shown: T.write_inside(ws, target, data,
                                                                      program, shown))

    async def run(name: str, *args, budget: float | None = None):
        call = CALL.get(None) or calls.arrive(name)
        return await calls.work(call, work, name, *args, budget=budget)
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
    async def check(source: Source = None, path: ProgramPath = None, overrides: Overrides = None,
              dof: Dof = False, budget: Budget = None, sweep: Sweep = False,
              detail: Detail = False) -> Annotated[CallToolResult, CheckResult]:
        """Parse, check and solve an AIDL program; write nothing. Returns ok, located
        diagnostics (with hint, fix), parts (bbox mm), freedom, the assembled fit (3D).
        Every result: whole in text and in structured content; refused: isError, error
        {code, message, argument}."""
        return answer("check", await run("check", source, path, overrides, dof, budget,
                                         sweep, budget=budget), detail=detail)

    @tool(writes)
    async def write_program(path: WritePath, text: WriteText = None, old: Old = None,
                      new: New = None, start: Start = None, end: End = None,
                      dof: Dof = False, detail: Detail = False
                      ) -> Annotated[CallToolResult, WriteResult]:
        """Write a .aidl file (the whole `text`, or a patch: `old` -> `new`, or `start`..`end`
        -> `new`), then check it as `check` does; the other tools then take it by `path`."""
        async with calls.program(path):      # one edit of a file at a time, in call order
            doc, files = await run("write_program", path, text, old, new, start, end, dof)
            _commit(calls, doc, files, "written", "path")
        return answer("write_program", doc, detail=detail)

    @tool(writes)
    async def render(source: Source = None, path: ProgramPath = None, output: Output = None,
               picture: Picture = False, width: Width = 800, overrides: Overrides = None,
               style: Style = "preview", budget: Budget = None, assembled: Assembled = False,
               layout: LayoutKind = None, sheet: Sheet = None, gap: Gap = None,
               rotate: Rotate = None, kerf: Kerf = None, thickness: Thickness = None,
               machine: Machine = None, page: Page = None, detail: Detail = False
               ) -> Annotated[CallToolResult, RenderResult]:
        """Compile, write `output` and return its figures: size, parts, fit (3D), overlaps
        (2D), for a cutting file the job at the `machine`'s speeds."""
        (doc, pngs), files = await run("render", source, path, output, width, overrides,
                                       budget, style, assembled, layout, sheet, gap, rotate,
                                       kerf, thickness, machine, page, picture, budget=budget)
        _commit(calls, doc, files, "written")
        return answer("render", doc, pngs, detail)

    @tool(reads)
    async def values(source: Source = None, path: ProgramPath = None, names: Names = None,
               overrides: Overrides = None, budget: Budget = None,
               detail: Detail = False) -> Annotated[CallToolResult, ValuesResult]:
        """Solved values of named entities, in the file's units: points, sizes (radius,
        width, ...), frame origins, boxes, a template's params and members, each copy of a
        pattern (corners[0]: the original)."""
        return answer("values", await run("values", source, path, names, overrides, budget,
                                          budget=budget), detail=detail)

    @tool(reads)
    async def describe(source: Source = None, path: ProgramPath = None, overrides: Overrides = None,
                 budget: Budget = None,
                 detail: Detail = False) -> Annotated[CallToolResult, DescribeResult]:
        """The final part in words and data, to check it without a picture (openings:
        kind, centre, size)."""
        return answer("describe", await run("describe", source, path, overrides, budget,
                                            budget=budget), detail=detail)

    @tool(writes)
    async def import_drawing(path: DrawingPath, infer: Infer = True, parts: Parts = False,
                       units: Units = None, output: ProgramOutput = None,
                       budget: Budget = None) -> Annotated[CallToolResult, ImportResult]:
        """A DXF or SVG drawing as an AIDL program to edit, exact to 1e-6 mm; with `infer`,
        the design (RoundedRectangle, Slot, hole patterns as loops, a param per size)."""
        doc, files = await run("import_drawing", path, infer, parts, units, output, budget,
                               budget=budget)
        _commit(calls, doc, files, "output")
        if not doc.get("ok") and doc.get("diagnostics"):
            d = doc["diagnostics"][0]
            doc["error"] = {"code": d["code"], "message": d["message"]}
        return answer("import_drawing", doc)

    @tool(writes)
    async def set_params(path: WritePath, values: ParamValues, dof: Dof = False,
                   budget: Budget = None, detail: Detail = False
                   ) -> Annotated[CallToolResult, SetParamsResult]:
        """Change `param` values in a .aidl file, rewriting only each value's text; each is
        checked against its kind and min/max first (refused: file untouched), then the
        file as `check`. Unknown name: no_match."""
        async with calls.program(path):
            doc, files = await run("set_params", path, values, dof, budget, budget=budget)
            _commit(calls, doc, files, "written", "path")
        return answer("set_params", doc, detail=detail)

    @tool(reads)
    async def measure(a: EntityName, b: EntityName, source: Source = None,
                path: ProgramPath = None, overrides: Overrides = None,
                budget: Budget = None) -> Annotated[CallToolResult, MeasureResult]:
        """Two named entities of the solved program, exact, mm: distance and points,
        center_distance, angle (two lines), clearance and contact (shapes or parts: apart,
        touching, overlapping negative)."""
        return answer("measure", await run("measure", a, b, source, path, overrides, budget,
                                           budget=budget))

    @tool(reads, structured=False)
    def explain(code: Code) -> str:
        """What a diagnostic code means, with an example."""
        return T.explain(code)

    @tool(reads, structured=False)
    def docs(name: TopicName = None) -> str:
        """The reference of a name: signature, units of the parameters, members, an example
        that compiles."""
        return T.docs(name)

    server = _Server("aidl", instructions=INSTRUCTIONS, version=_version(), tools=tools,
                     calls=calls)
    _resources(server, prompt)
    return server


def _topic_resources(server: MCPServer) -> None:
    """Offer each topic of ``aidl docs`` as ``aidl://docs/topic/NAME`` (listing them parses the
    standard library: done on the first resources call, not before the first tools/list)."""
    from ..library.reference import topics
    for name, topic in topics().items():
        server.resource(f"aidl://docs/topic/{name}", name=f"aidl docs {name}",
                        mime_type="text/plain",
                        description=f"{topic.kind}: {topic.summary}")(_worded(topic.render))


def _worded(render: Callable[[], str]) -> Callable[[], str]:
    """``render``'s text worded for the tools (:func:`.wording.for_agents`)."""
    def read() -> str:
        return for_agents(render())
    return read


def _resources(server: MCPServer, prompt: Callable[[], str] | None) -> None:
    """Offer the docs, the prompt (worded for the tools), the standard library and the
    examples as resources of ``server`` (see the module text)."""
    from ..library.reference import index_text
    server.resource("aidl://docs/topics", name="aidl docs topics", mime_type="text/plain",
                    description="`aidl docs`: every topic (statements, shapes, constraints, "
                                "relations, operations, stdlib templates)")(index_text)
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
    for name, schema in FULL_SCHEMAS.items():
        server.resource(schema_uri(name), name=f"{name} output schema",
                        mime_type="application/schema+json",
                        description=f"the full JSON Schema of `{name}`'s structured content")(
            (lambda doc: lambda: json.dumps(doc, indent=1))(schema))
    from ..library.sources import STDLIB
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


def main(root: str, budget: float = 1.0, prompt: Callable[[], str] | None = None,
         first=None) -> int:
    """Serve over stdin/stdout until the client closes them (``first``: what :mod:`.fast`
    read and answered before the SDK was loaded)."""
    import os
    server = build_server(root, budget, prompt, warm=not os.environ.get("AIDL_MCP_COLD"))
    server.first = first
    server.run("stdio")
    return 0
