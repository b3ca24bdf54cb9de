"""The ``aidl`` command line's arguments: one ``argparse`` parser with a subparser per
subcommand (docs/language.md section 10.1 lists them; :mod:`aidl_lang.cli.main` runs them).

In: the subcommand given (or None); out: :func:`_parser`, the ``ArgumentParser`` that reads
``argv`` into the ``Namespace`` a ``cmd_*`` function of :mod:`aidl_lang.cli.main` takes.  Only
the given subcommand's parser is built (:class:`_Unused` stands in for the others: cold
start), and every message reads the same as with all of them.  Usage errors exit 2 with a
short message (:class:`_Parser`); the argument types (:func:`_port`, :func:`_budget_factor`,
:func:`_memory_size`, :func:`~aidl_lang.base.limits.min_wall_argument`) word a bad value as one.  ``prompt``, ``generate`` and ``eval`` add
theirs from :mod:`aidl_lang.cli.llm`, ``batch`` from :mod:`aidl_lang.batch.command`.
"""
from __future__ import annotations

import argparse
import os
import sys

from ..base.limits import min_wall_argument


_COLUMNS: int | None = None


def _columns() -> int:
    """The terminal's width as ``shutil.get_terminal_size`` finds it (``$COLUMNS``, else the
    terminal of stdout, else 80), without importing :mod:`shutil`."""
    global _COLUMNS
    if _COLUMNS is None:
        try:
            _COLUMNS = int(os.environ.get("COLUMNS", "0"))
        except ValueError:
            _COLUMNS = 0
        if _COLUMNS <= 0:
            try:
                _COLUMNS = os.get_terminal_size(sys.__stdout__.fileno()).columns
            except (AttributeError, ValueError, OSError):
                _COLUMNS = 0
        if _COLUMNS <= 0:
            _COLUMNS = 80
    return _COLUMNS


class _Formatter(argparse.HelpFormatter):
    """argparse's help layout at the terminal's width.  argparse makes a formatter for every
    ``add_argument`` and each one imported :mod:`shutil` (which imports ``bz2`` and ``lzma``)
    and asked the terminal: ~4 ms of every ``aidl`` command."""

    def __init__(self, prog, indent_increment=2, max_help_position=24, width=None):
        super().__init__(prog, indent_increment, max_help_position,
                         _columns() - 2 if width is None else width)


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        kwargs.setdefault("formatter_class", _Formatter)
        super().__init__(*args, **kwargs)

    def error(self, message):      # usage errors: exit 2 with a short message
        self.print_usage(sys.stderr)
        print(f"aidl: error: {message}", file=sys.stderr)
        raise SystemExit(2)


SUBCOMMANDS = ("render", "check", "parts", "explain", "docs", "import", "fmt", "set", "lsp", "serve",
               "studio", "mcp", "batch", "prompt", "generate", "eval")


class _Unused:
    """Stands in for the parser of a subcommand that was not asked for: it is not built and
    its arguments are not added (each ``ArgumentParser`` translates its headings through
    ``gettext``, which searches the locale folders every time, and makes a help formatter
    for every ``add_argument``: the eight other subcommands cost ~9 M instructions, ~3 ms,
    of every command)."""

    def add_argument(self, *args, **kwargs) -> None:
        pass


class _Version(argparse.Action):
    """``aidl --version``: prints ``aidl X.Y.Z`` (the installed distribution's version) and
    exits 0.  The version is read only when asked (``importlib.metadata`` costs ~10 ms)."""

    def __init__(self, option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS,
                 help="print the version of aidl and exit"):
        super().__init__(option_strings=option_strings, dest=dest, default=default, nargs=0,
                         help=help)

    def __call__(self, parser, namespace, values, option_string=None):
        from importlib.metadata import PackageNotFoundError, version
        try:
            v = version("aidl-lang")
        except PackageNotFoundError:       # run from a source tree that was never installed
            v = "unknown (not installed)"
        print(f"aidl {v}")
        parser.exit(0)


def _parser(only: str | None = None) -> argparse.ArgumentParser:
    """The ``aidl`` argument parser; ``only``: the subcommand given, the only one whose parser
    is built (``None``: all, for ``aidl --help`` and errors).  The subcommand list in the
    usage line is spelled out, so every message reads the same either way."""
    p = _Parser(prog="aidl", description="AIDL: a solver-aided hierarchical language for 2D CAD.")
    p.add_argument("--version", action=_Version)
    sub = p.add_subparsers(dest="cmd", required=True, parser_class=_Parser,
                           metavar=None if only is None else "{" + ",".join(SUBCOMMANDS) + "}")

    def add(name: str, **kwargs):
        return sub.add_parser(name, **kwargs) if only is None or only == name else _Unused()
    r = add("render", help="compile a .aidl file to SVG, DXF, PDF, PNG, STL, 3MF or STEP",
            description="Compile FILE and write each -o output; the format follows "
                        "the extension (.svg .dxf .pdf .png .stl .3mf .step .glb). Nothing is "
                        "written unless the whole pipeline succeeded.")
    _render_arguments(r)
    c = add("check", help="parse, check and solve; write nothing")
    _check_arguments(c)
    pl = add("parts", help="list the parts: path, size, area, thickness, holes, copies")
    pl.add_argument("file")
    pl.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    pl.add_argument("--json", action="store_true", help="the list as JSON on stdout")
    _budget_arg(pl)
    _memory_arg(pl)
    e = add("explain", help="explain a diagnostic code, e.g. aidl explain E0202")
    e.add_argument("code")
    dc = add("docs", help="the reference of a shape, constraint, statement or stdlib template, "
                          "e.g. aidl docs spur_gear; alone: the list of topics")
    dc.add_argument("name", nargs="?", default=None,
                    help="a topic (any case or style: SpurGear, spur-gear); none: list them")
    im = add("import", help="turn a DXF or SVG drawing into an editable .aidl program",
             description="Read FILE.dxf or FILE.svg as exact lines, arcs, circles, "
                         "elliptical arcs and splines and write a program of the language's "
                         "own shapes (Line, Arc, Circle, Ellipse, Spline, Bezier; DXF text as "
                         "Text) that renders back to the same geometry (docs/import.md).")
    _import_arguments(im)
    f = add("fmt", help="format .aidl files in place (canonical layout)")
    f.add_argument("files", nargs="+", metavar="FILE", help="files to format; - for stdin")
    f.add_argument("--check", action="store_true", help="write nothing; exit 1 if any would change")
    st = add("set", help="change param values in a .aidl file, then check it",
             description="Rewrite the value of each `param NAME = VALUE` line named (only the "
                         "value's text: comments and formatting stay), after checking it "
                         "against the param's kind and min/max (refused: the file is left "
                         "as it was), then check the file as `aidl check` does.")
    st.add_argument("file", metavar="FILE", help="the .aidl program")
    st.add_argument("values", nargs="+", metavar="NAME=VALUE",
                    help="e.g. width=\"50 mm\" holes=6 (a bare number in the param's own unit, written with it)")
    st.add_argument("--json", action="store_true", help="the check's result as JSON")
    _budget_arg(st)
    lsp = add("lsp", help="run the language server on stdin/stdout (for editors)")
    # What LSP clients append (vscode-languageclient: `--stdio` for its stdio transport, and
    # `--clientProcessId=N`; `--node-ipc`, `--pipe=NAME`, `--socket=N` for its other transports).
    lsp.add_argument("--stdio", action="store_true", help="talk over stdin/stdout (the default)")
    lsp.add_argument("--clientProcessId", "--client-process-id", type=int, metavar="PID",
                     help="the editor's process id (accepted; the server exits when stdin closes)")
    lsp.add_argument("--node-ipc", action="store_true", help=argparse.SUPPRESS)
    lsp.add_argument("--pipe", metavar="NAME", help=argparse.SUPPRESS)
    lsp.add_argument("--socket", "--port", type=int, metavar="PORT", help=argparse.SUPPRESS)
    v = add("serve", help="live preview in the browser with parameter sliders "
                          "(http://127.0.0.1:PORT/)")
    v.add_argument("file")
    v.add_argument("--port", type=_port, default=8765, help="port on 127.0.0.1 (0: any free one)")
    so = add("studio", help="the studio in the browser: gallery, forms, code, 3D, downloads, "
                            "for many users (http://HOST:PORT/)",
             description="Serve AIDL's studio: a gallery of every example and generator with its "
                         "parameters as a form, a code pane with diagnostics, the flat sheet and "
                         "the assembled 3D view, downloads for every machine format, share links "
                         "and embeds. Every compile runs in a memory- and time-limited worker; "
                         "no program reads a file of this machine. docs/studio.md")
    _studio_arguments(so)
    m = add("mcp", help="run the Model Context Protocol server on stdin/stdout (for agents)",
            description="Serve AIDL's tools (check, render, values, explain, docs) and resources "
                        "(language reference, prompt, stdlib, examples) to an MCP host over "
                        "stdio. Only files inside --root can be read or written.")
    m.add_argument("--root", default=".", metavar="DIR",
                   help="the folder the server may read and write (default: the current one)")
    _budget_arg(m)
    if only is None or only == "batch":
        from ..batch.command import add_arguments as add_batch
        add_batch(add("batch", help="compile many programs (files, folders, JSONL) into "
                                    "one row each, locally or on Dask (docs/batch.md)"))
    if only is None or only in ("prompt", "generate", "eval"):
        from .llm import add_commands
        add_commands(add)              # prompt, generate, eval
    return p


def _render_arguments(r) -> None:
    """``aidl render``: the program, its outputs and how they are made."""
    r.add_argument("file", help="the .aidl program (- for stdin, then -o is required)")
    r.add_argument("-o", "--output", action="append", default=[], metavar="OUT",
                   help="output file, format by extension; repeat for several "
                        "(default: FILE with .svg); - writes to standard output (--format)")
    r.add_argument("--format", default=None, metavar="FMT",
                   help="the format of -o - (standard output): svg (default), dxf, step; png, "
                        "stl, 3mf, glb only when standard output is not a terminal")
    r.add_argument("--show", default="", metavar="LAYERS",
                   help="debug layers in SVG/PNG, comma-separated: construction,holes,bboxes")
    r.add_argument("--svg-style", choices=["preview", "laser"], default="preview",
                   help="preview: filled solids (default); laser: stroke-only red cut and blue "
                        "engrave hairlines, one element per loop")
    r.add_argument("--margin", type=float, default=None, metavar="MM",
                   help="space around the drawing on the SVG/PNG page, in mm (default 5%% of "
                        "the larger side, at least 1 mm; 0: the page is the bounding box); "
                        "the PDF's margin (default 10 mm)")
    r.add_argument("--page", default=None, metavar="PAPER",
                   help="PDF: tile the 1:1 template over pages of this paper size, with 10 mm "
                        "overlaps and alignment marks: A4, A3, Letter, Legal, each also "
                        "-landscape (e.g. A4-landscape); default: one page the drawing's size")
    r.add_argument("--dpi", type=float, default=None,
                   help="PNG resolution (default 96, scaled down so that the longer side is "
                        "at most 2000 pixels; an explicit --dpi is kept as given)")
    r.add_argument("--png-width", type=int, default=None, metavar="PX",
                   help="PNG width in pixels (overrides --dpi)")
    r.add_argument("--thickness", default=None, metavar="LENGTH",
                   help="extrusion thickness for STL/3MF/STEP and a router's G-code depth, "
                        "e.g. 3mm (default: the program's `thickness`, else 3 mm)")
    r.add_argument("--kerf", default=None, metavar="LENGTH",
                   help="offset every cut by half this kerf so parts come out at their size, "
                        "e.g. 0.15mm (default: the program's `kerf`, else none); SVG, DXF, "
                        "PNG and G-code only: STL, 3MF and STEP keep the designed size")
    r.add_argument("--machine", default=None, metavar="FILE",
                   help="machine profile (TOML) for G-code: laser, router or plotter, power, "
                        "speeds, passes, tool, tabs (`aidl docs machine`); or laser, router, "
                        "plotter for a built-in profile (default: laser)")
    r.add_argument("--assembled", action="store_true",
                   help="write the assembled product: every part extruded by its thickness and "
                        "placed by its `Place` (STL, 3MF, STEP, GLB: one named object per part; "
                        "PNG: a picture of it)")
    r.add_argument("--layout", choices=["sheet"], default=None,
                   help="sheet: lay every solid part out flat on cutting sheets (true-shape "
                        "nesting; `layout` extra), one file per sheet when there are several")
    r.add_argument("--sheet", default="600x400mm", metavar="WxH",
                   help="sheet size for --layout, e.g. 600x400mm or 24x12in (default 600x400mm)")
    r.add_argument("--gap", default="3mm", metavar="LENGTH",
                   help="space between parts and to the sheet's edge for --layout (default 3mm)")
    r.add_argument("--rotate", default="0,90", metavar="ANGLES",
                   help="angles in degrees parts may be turned by for --layout, e.g. 0 or 0,90 "
                        "(default), or any")
    r.add_argument("--nest-time", type=int, default=0, metavar="S",
                   help="seconds the nesting may spend improving its first packing (default 0); "
                        "added to the --budget (its CPU seconds: S x the cores)")
    r.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="override a model param, e.g. --set width=40mm")
    r.add_argument("--json", action="store_true", help="machine-readable diagnostics on stdout")
    r.add_argument("--min-wall", type=min_wall_argument, default=None, metavar="MM",
                   help="warn (W0507, W0519, W0520) about walls and slits thinner than this, in mm; "
                        "overrides the program's `min_wall` statements (default: theirs, else 0.5; 0: off; "
                        "else 0.001 to 1e6)")
    _budget_arg(r)
    _memory_arg(r)
    r.add_argument("--follow-symlinks", action="store_true",
                   help="write through an output that is a symbolic link (default: refuse it)")
    r.add_argument("--force", action="store_true",
                   help="replace an output file that is read-only (default: refuse it)")


def _check_arguments(c) -> None:
    """``aidl check``: what to check and report."""
    # optional here only so that `aidl check --values FILE` parses (`--values` takes any
    # number of names and would swallow it): _check_file takes the file back from the names
    c.add_argument("file", nargs="?")
    c.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    c.add_argument("--json", action="store_true", help="machine-readable diagnostics on stdout")
    c.add_argument("--min-wall", type=min_wall_argument, default=None, metavar="MM",
                   help="warn (W0507, W0519, W0520) about walls and slits thinner than this, in mm; "
                        "overrides the program's `min_wall` statements (default: theirs, else 0.5; 0: off; "
                        "else 0.001 to 1e6)")
    c.add_argument("--dof", action="store_true",
                   help="report degrees of freedom per structure, floating entities and "
                        "redundant constraints")
    c.add_argument("--sweep", action="store_true",
                   help="also check the design across its params' min=/max= ranges (a param "
                        "without one: its slider's span; ends, middles, a Latin hypercube; "
                        "within a work budget, the same on any machine): W0110 at each param "
                        "value where it breaks, with the clean range to narrow to or declare")
    c.add_argument("--values", nargs="*", default=None, metavar="NAME",
                   help="print the solved values of named entities (points, sizes, frames, "
                        "boxes) in the file's units; NAMEs filter by dotted prefix")
    c.add_argument("--describe", action="store_true",
                   help="describe the final part: outline, openings (kind, centre, size), "
                        "engravings, copies, symmetries (JSON with --json)")
    _budget_arg(c)
    _memory_arg(c)


def _import_arguments(im) -> None:
    """``aidl import``: the drawing, its unit, layer, roles and how it is written."""
    im.add_argument("file", metavar="FILE", help="a .dxf or .svg drawing")
    im.add_argument("-o", "--output", metavar="PART.aidl", default=None,
                    help="the program to write (default: FILE with .aidl; - for stdout)")
    im.add_argument("--units", choices=["mm", "cm", "m", "in", "ft", "pt", "px"], default=None,
                    help="the drawing's unit, instead of $INSUNITS or the SVG's width/viewBox")
    im.add_argument("--layer", default=None,
                    help="only this DXF layer (or SVG group id / Inkscape layer)")
    im.add_argument("--parts", action="store_true",
                    help="a sheet of parts: one solid per outer loop (its holes and "
                         "engravings with it) in an assembly, to re-nest with --layout sheet")
    im.add_argument("--infer", action="store_true",
                    help="write the design, not the pieces: recognised shapes (Slot, "
                         "RoundedRectangle, ...), loops for patterns, named params")
    im.add_argument("--snap", type=_snap_tolerance, default=None, metavar="TOL",
                    help="take cubic Bezier curves that are circles or arcs within TOL (e.g. "
                         "0.01mm, 0.001in; a bare number is mm) as true circles and arcs, "
                         "near-equal radii as one; the program's header says what was snapped "
                         "and the largest deviation (off by default: exact curves only)")
    im.add_argument("--close-tolerance", type=float, default=None, metavar="MM",
                    help="close chains whose ends meet within MM (default 0.05; 0: only "
                         "ends that meet)")
    for role, what in (("cut", "cut (outlines and holes)"), ("engrave", "engraved"),
                       ("ignore", "left out")):
        im.add_argument(f"--{role}", action="append", default=None, metavar="LAYER|COLOUR",
                        help=f"what is {what}: a layer name, a colour (red, #0000ff) or a DXF "
                             "ACI number; repeat for more")
    im.add_argument("--roles", default=None, choices=["laser"],
                    help="a preset of roles by colour: laser = Boxes.py's colours (black and "
                         "blue cut, open paths too; green and cyan engraved, red annotations "
                         "left out)")
    im.add_argument("--json", action="store_true",
                    help="the import's result as JSON: ok, output, notes, diagnostics and the "
                         "work units it spent (`work`)")
    _budget_arg(im)
    _memory_arg(im)


def _snap_tolerance(text: str) -> float:
    """``--snap``'s tolerance in mm: a number with an optional unit (mm, cm, in)."""
    import argparse
    import re
    from ..drawing.chains.snap import MAX_SNAP
    m = re.fullmatch(r"\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*(mm|cm|in)?\s*", text)
    if not m:
        raise argparse.ArgumentTypeError(f"`{text}` is no length: write it as 0.01mm, "
                                         f"0.001in or 0.01 (mm)")
    v = float(m.group(1)) * {"mm": 1.0, "cm": 10.0, "in": 25.4}[m.group(2) or "mm"]
    if not 0 < v <= MAX_SNAP:
        raise argparse.ArgumentTypeError(f"`{text}` is {v:g} mm: the tolerance must be more "
                                         f"than 0 and at most {MAX_SNAP:g} mm (0.01mm suits "
                                         f"Boxes.py's 3-decimal Béziers)")
    return v


def _studio_arguments(so) -> None:
    """``aidl studio``: where it listens, its processes, limits and stores."""
    so.add_argument("--host", default="127.0.0.1",
                    help="address to listen on (0.0.0.0: every interface, to serve others)")
    so.add_argument("--port", type=_port, default=8780, help="port (0: any free one)")
    so.add_argument("--processes", type=int, default=1, metavar="N",
                    help="server processes behind the one port (uvicorn workers)")
    so.add_argument("--compilers", type=int, default=2, metavar="N",
                    help="compile worker processes per server process")
    so.add_argument("--rate", default=None, metavar="N/PERIOD",
                    help="requests per client, such as 300/minute (the default)")
    so.add_argument("--memory", type=int, default=None, metavar="MB",
                    help="memory cap of one compile worker (default 1500)")
    so.add_argument("--recycle", type=int, default=None, metavar="N",
                    help="replace a compile worker's process after N answers, so its memory "
                         "stays flat (default 200; 0: never)")
    so.add_argument("--store", default=None, metavar="redis://HOST:PORT/DB",
                    help="keep uploads and rate counters in this Redis: any process of any "
                         "machine answers any request (default: a local folder)")
    so.add_argument("--scheduler", default=None, metavar="tcp://HOST:PORT",
                    help="compile on this Dask cluster instead of local workers")
    _budget_arg(so)


def _port(text: str) -> int:
    if not (text.isdigit() and int(text) <= 65535):
        raise argparse.ArgumentTypeError(f"--port expects a number from 0 to 65535, got `{text}`")
    return int(text)


def _budget_factor(text: str) -> float:
    try:
        k = float(text)
    except ValueError:
        k = -1.0
    if not 0 < k <= 1000:
        raise argparse.ArgumentTypeError(f"--budget expects a factor between 0 and 1000, got `{text}`")
    return k


def _budget_arg(p) -> None:
    p.add_argument("--budget", type=_budget_factor, default=1.0, metavar="K",
                   help="multiply the evaluation budget (steps, objects, sizes, CPU seconds; "
                        "docs/language.md §8.1) by K, e.g. --budget 4")


def _memory_size(text: str):
    from ..base.memory import parse_size
    try:
        size = parse_size(text)
    except ValueError as e:
        raise argparse.ArgumentTypeError(str(e)) from None
    if size is not None and size < 256 << 20:
        raise argparse.ArgumentTypeError(f"`{text}` is less than 256M, too little "
                                         "for the compiler itself")
    return 0 if size is None else size          # 0: no cap


def _memory_arg(p) -> None:
    p.add_argument("--memory", type=_memory_size, default=None, metavar="SIZE",
                   help="cap this command's memory (address space) at SIZE, e.g. 4G or 1500M; "
                        "none: no cap (default: half the machine's memory, at least 3G); "
                        "a program past it is E0304")
