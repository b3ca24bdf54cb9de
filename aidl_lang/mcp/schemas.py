"""The shapes of the compiling tools' results (``check``, ``render``, ``values``,
``describe``), as typed dicts: the SDK turns each into the tool's ``outputSchema`` and checks
every result against it before sending it as ``structuredContent`` (docs/mcp.md).  Lengths are
in mm unless a field says otherwise (``values``: the file's units)."""
from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field
from typing_extensions import NotRequired, TypedDict


class Span(TypedDict):
    """Where in a file: 1-based ``line``/``column`` (and their ends), 0-based character
    offsets ``start``/``end``."""
    file: str
    line: int
    column: int
    end_line: int
    end_column: int
    start: int
    end: int


class Label(TypedDict):
    span: Span
    message: str
    primary: bool


class Fix(TypedDict):
    """Replace the text at ``span`` with ``replacement``."""
    span: Span
    replacement: str


class Diagnostic(TypedDict):
    """One located problem of the program, as ``aidl check --json`` gives it."""
    code: Annotated[str, Field(description="E0103, W0401, ...: `explain` says more")]
    severity: Literal["error", "warning", "note"]
    message: str
    span: Span | None
    labels: list[Label]
    hint: str | None
    suggestions: list[str]
    fix: Fix | None
    rendered: NotRequired[Annotated[str, Field(
        description="the diagnostic as text, with the source line (with `detail: true`)")]]


class Solve(TypedDict):
    converged: bool
    iterations: int
    unknowns: Annotated[int, Field(description="what Newton solved for")]
    equations: int
    settled: Annotated[int, Field(description="unknowns settled directly by their constraints "
                                              "before Newton (a Fixed point, a held size)")]
    max_residual: float


class StructureFreedom(TypedDict):
    structure: str
    unknowns: int
    dof: int | None
    floating: Annotated[list[str], Field(description="entities still free to move")]
    not_counted: NotRequired[str]


class Freedom(TypedDict):
    dof: Annotated[int | None, Field(description="degrees of freedom left; null: not counted")]
    text: str
    structures: NotRequired[Annotated[list[StructureFreedom], Field(
        description="per structure, with `dof: true`")]]


class Part(TypedDict):
    """One part of the final shape, in mm."""
    name: str
    kind: str
    bbox: Annotated[list[float], Field(description="[x0, y0, x1, y1] mm")]
    area: Annotated[float, Field(description="mm², holes subtracted")]
    holes: int
    loops: int


class Error(TypedDict):
    """Why a call failed: ``code`` (a program's first error code, E0103, ...; or what kind
    of refusal: unknown_argument, bad_argument, program_choice, outside_root, symlink,
    not_found, wrong_kind, no_match, not_unique, output_failed, timed_out, worker_died,
    internal_error), ``message``, and the ``argument`` at fault when there is one."""
    code: str
    message: str
    argument: NotRequired[str]


class Collision(TypedDict):
    a: str
    b: str
    volume: Annotated[float, Field(description="mm³ the two parts share")]
    depth: Annotated[float, Field(description="mm one runs into the other")]
    box: Annotated[list[float], Field(description="[x0, y0, z0, x1, y1, z1] mm")]


class Floating(TypedDict):
    part: str
    nearest: str
    gap: Annotated[float, Field(description="mm to the nearest part")]


class Fit(TypedDict):
    """The fit check of the assembled product (parts placed with `Place`)."""
    checked: Annotated[bool, Field(description="false: nothing is placed, no check ran")]
    collisions: list[Collision]
    floating: list[Floating]


class Overlap(TypedDict):
    a: str
    b: str
    sheet: NotRequired[int]
    area: Annotated[float, Field(description="mm² the two share")]
    box: Annotated[list[float], Field(description="[x0, y0, x1, y1] mm of it")]


class _Compiled(TypedDict):
    """What every compiling tool returns: ``ok``, the diagnostics, the file's length unit,
    the solve's statistics and, with errors, a one-line summary of them and the ``error``."""
    ok: Annotated[bool, Field(description="no errors, and the program solved")]
    error: NotRequired[Error]
    diagnostics: NotRequired[list[Diagnostic]]
    units: Annotated[str, Field(description="the file's length unit (mm when it names none)")]
    solve: NotRequired[Solve]
    work: NotRequired[dict]
    summary: NotRequired[Annotated[str, Field(description="with errors: one line per error")]]


class CheckResult(_Compiled):
    freedom: NotRequired[Freedom]
    parts: NotRequired[list[Part]]
    fit: NotRequired[Fit]
    sweep: NotRequired[dict]


class WriteResult(CheckResult):
    """``write_program``: the file written, then checked."""
    written: NotRequired[Annotated[str, Field(description="the file, relative to the root")]]
    lines: NotRequired[int]


class SetParamsResult(CheckResult):
    """``set_params``: the file with its params set, then checked."""
    written: NotRequired[Annotated[str, Field(description="the file, relative to the root")]]


class Measured(TypedDict):
    """What lies between two named entities, mm and degrees (exact to 1e-9)."""
    a: dict[str, str]
    b: dict[str, str]
    unit: str
    distance: Annotated[float, Field(description="smallest distance between them")]
    points: Annotated[list[list[float]], Field(description="where: [[x, y], [x, y]]")]
    center_distance: NotRequired[float]
    centers: NotRequired[list[list[float]]]
    angle: NotRequired[Annotated[float, Field(description="two lines: 0 to 180 degrees")]]
    clearance: NotRequired[Annotated[float, Field(
        description="two shapes or parts: the gap; 0 touching; negative overlapping")]]
    contact: NotRequired[Literal["apart", "touching", "overlapping"]]
    overlap_area: NotRequired[Annotated[float, Field(description="mm² shared")]]
    overlap_area_within: NotRequired[Annotated[float, Field(description="estimated: ± mm²")]]
    sinks: NotRequired[Annotated[list[dict], Field(
        description="countersinks/counterbores on the holes named: kind, hole, center, "
                    "hole_d, diameter, depth (mm), angle (deg)")]]


class MeasureResult(_Compiled):
    measure: NotRequired[Measured]


class Value(TypedDict):
    """One solved value of a named entity."""
    name: Annotated[str, Field(description="dotted path, e.g. plate.bore.c.center")]
    kind: Literal["point", "length", "angle", "number", "box", "group"]
    value: Annotated[float | list[float], Field(
        description="in the file's units (angles in degrees); a point [x, y], a box "
                    "[left, bottom, right, top]; a group: the value all its members share, "
                    "else the box their points span or [least, greatest]")]
    unit: str
    mm: NotRequired[Annotated[float | list[float], Field(
        description="the same in mm (angles: radians); left out where it equals `value`")]]
    count: NotRequired[Annotated[int, Field(description="a group: how many values")]]
    of: NotRequired[Annotated[str, Field(description="a group: its members' kind")]]


class ValuesResult(_Compiled):
    values: NotRequired[list[Value]]
    unmatched: NotRequired[list[str]]
    text: NotRequired[Annotated[str, Field(description="one `name = value unit` line each")]]


class DescribeResult(_Compiled):
    text: NotRequired[Annotated[str, Field(description="one line per feature")]]
    describe: NotRequired[Annotated[dict[str, Any], Field(
        description="per part: outline, openings, engravings, copies, symmetries (mm)")]]


class ImageInfo(TypedDict):
    format: Literal["png"]
    width: Annotated[int, Field(description="pixels")]
    view: Literal["flat", "assembled"]


class LayoutInfo(TypedDict):
    """The cutting layout (``layout: "sheet"``)."""
    sheets: Annotated[int, Field(description="the number of sheets (one picture each)")]
    size: Annotated[list[float], Field(description="[width, height] of a sheet, mm")]
    files: Annotated[list[str], Field(description="the files written, one per sheet")]
    text: Annotated[str, Field(description="e.g. laid out 6 parts on 2 sheets of 600 x 400 mm")]
    use: Annotated[list[float], Field(description="per sheet: the parts' area over the "
                                                  "sheet's, 0 to 1")]
    placements: Annotated[list[dict[str, Any]], Field(
        description="per part: {part, sheet (1-based), rotation (degrees), bbox [x0, y0, "
                    "x1, y1] mm on the sheet}")]


class Job(TypedDict):
    """What cutting the written drawing takes, as the G-code writer plans it."""
    path_mm: Annotated[float, Field(description="mm of path, one pass of every cut")]
    passes: NotRequired[Annotated[int, Field(description="times the path is run")]]
    cut_mm: Annotated[float, Field(description="mm cut, every pass")]
    travel_mm: Annotated[float, Field(description="mm moved with the tool off")]
    seconds: Annotated[float, Field(description="the job's time at the machine profile's "
                                                "speeds (acceleration ignored)")]
    machine: Annotated[str, Field(description="the profile's kind: laser, router, plotter")]
    text: NotRequired[Annotated[str, Field(description="the same in words (with `detail`; "
                                                       "else in the line of text)")]]


class RenderResult(_Compiled):
    size: NotRequired[Annotated[list[float], Field(description="[width, height] mm of the "
                                                               "drawing")]]
    parts: NotRequired[list[Part]]
    image: NotRequired[Annotated[ImageInfo, Field(description="with `picture`")]]
    written: NotRequired[Annotated[str, Field(
        description="the file (a layout's first sheet), relative to the root")]]
    superseded: NotRequired[str]
    layout: NotRequired[LayoutInfo]
    job: NotRequired[Job]
    fit: NotRequired[Fit]
    overlaps: NotRequired[Annotated[list[Overlap], Field(
        description="parts over each other as cut (2D)")]]


class ImportNote(TypedDict):
    code: str
    message: str
    hint: str


class ImportProblem(TypedDict):
    code: Annotated[str, Field(description="E0130, E0131, E0132, E0304: `explain` says more")]
    message: str
    hint: str
    line: Annotated[int | None, Field(description="the DXF line of the entity, when known")]


class ImportCheck(TypedDict):
    """The check of the program written, in short."""
    ok: bool
    summary: NotRequired[Annotated[str, Field(description="with errors: one line each")]]
    warnings: NotRequired[Annotated[list[str], Field(description="`W0502 line 4: ...`")]]
    dof: NotRequired[Annotated[int | None, Field(description="degrees of freedom left")]]
    parts: NotRequired[list[Part]]


class ImportResult(TypedDict):
    """``import_drawing``: the program written from a drawing (docs/import.md)."""
    ok: bool
    program: NotRequired[Annotated[str, Field(description="the AIDL program's text")]]
    notes: NotRequired[list[ImportNote]]
    output: NotRequired[Annotated[str, Field(description="the .aidl file written")]]
    superseded: NotRequired[str]
    work: NotRequired[dict]
    check: NotRequired[ImportCheck]
    diagnostics: NotRequired[list[ImportProblem]]
    error: NotRequired[Error]
