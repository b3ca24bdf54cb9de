"""The ``aidl`` command line: ``render``, ``check``, ``explain``, ``fmt``, ``lsp``, ``serve`` (and
``prompt``, ``generate``, ``eval`` from :mod:`aidl_lang.cli.llm`).

Exit status: 0 success, 1 a user error in the program (diagnostics printed), 2 a usage error.
An output file is written only when the whole pipeline succeeded (written to a temporary file
beside it, then renamed), so a good drawing is never replaced by a broken one.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path

from ..diagnostics import Diagnostic, DiagnosticSink, render_text


class _Parser(argparse.ArgumentParser):
    def error(self, message):      # usage errors: exit 2 with a short message
        self.print_usage(sys.stderr)
        print(f"aidl: error: {message}", file=sys.stderr)
        raise SystemExit(2)


def _parser() -> argparse.ArgumentParser:
    p = _Parser(prog="aidl", description="AIDL: a solver-aided hierarchical language for 2D CAD.")
    sub = p.add_subparsers(dest="cmd", required=True, parser_class=_Parser)
    r = sub.add_parser("render", help="compile a .aidl file to SVG")
    r.add_argument("file")
    r.add_argument("-o", "--output", help="output .svg (default: FILE with .svg)")
    r.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="override a model param, e.g. --set width=40mm")
    r.add_argument("--json", action="store_true", help="machine-readable diagnostics on stdout")
    c = sub.add_parser("check", help="parse, check and solve; write nothing")
    c.add_argument("file")
    c.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    c.add_argument("--json", action="store_true", help="machine-readable diagnostics on stdout")
    c.add_argument("--dof", action="store_true",
                   help="report degrees of freedom per structure, floating entities and "
                        "redundant constraints")
    e = sub.add_parser("explain", help="explain a diagnostic code, e.g. aidl explain E0202")
    e.add_argument("code")
    f = sub.add_parser("fmt", help="format .aidl files in place (canonical layout)")
    f.add_argument("files", nargs="+", metavar="FILE", help="files to format; - for stdin")
    f.add_argument("--check", action="store_true", help="write nothing; exit 1 if any would change")
    lsp = sub.add_parser("lsp", help="run the language server on stdin/stdout (for editors)")
    # What LSP clients append (vscode-languageclient: `--stdio` for its stdio transport, and
    # `--clientProcessId=N`; `--node-ipc`, `--pipe=NAME`, `--socket=N` for its other transports).
    lsp.add_argument("--stdio", action="store_true", help="talk over stdin/stdout (the default)")
    lsp.add_argument("--clientProcessId", "--client-process-id", type=int, metavar="PID",
                     help="the editor's process id (accepted; the server exits when stdin closes)")
    lsp.add_argument("--node-ipc", action="store_true", help=argparse.SUPPRESS)
    lsp.add_argument("--pipe", metavar="NAME", help=argparse.SUPPRESS)
    lsp.add_argument("--socket", "--port", type=int, metavar="PORT", help=argparse.SUPPRESS)
    v = sub.add_parser("serve", help="live preview in the browser with parameter sliders "
                                     "(http://127.0.0.1:PORT/)")
    v.add_argument("file")
    v.add_argument("--port", type=int, default=8765, help="port on 127.0.0.1 (0: any free one)")
    from .llm import add_commands
    add_commands(sub)                  # prompt, generate, eval
    return p


def _overrides(items: list[str]) -> dict[str, str]:
    out = {}
    for it in items:
        if "=" not in it:
            print(f"aidl: error: --set expects NAME=VALUE, got `{it}`", file=sys.stderr)
            raise SystemExit(2)
        k, v = it.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def _emit(sink: DiagnosticSink, as_json: bool, ok: bool, extra: dict | None = None) -> None:
    if as_json:
        doc = {"ok": ok, "diagnostics": [d.to_json(sink.sources) for d in sink.items]}
        doc.update(extra or {})
        print(json.dumps(doc, indent=2))
        return
    color = sys.stderr.isatty() and not os.environ.get("NO_COLOR")
    for d in sink.items:
        print(render_text(d, sink.sources, color=color), file=sys.stderr)
        print(file=sys.stderr)
    n_err = sum(d.is_error for d in sink.items)
    n_warn = sum(d.severity == "warning" for d in sink.items)
    if n_err:
        print(f"aidl: {n_err} error{'s' if n_err != 1 else ''}"
              + (f", {n_warn} warning{'s' if n_warn != 1 else ''}" if n_warn else ""), file=sys.stderr)


def _read(path: str, as_json: bool) -> str | None:
    try:
        return Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        sink = DiagnosticSink()
        sink.add(Diagnostic("E0004", f"cannot read `{path}`: {getattr(e, 'strerror', None) or e}",
                            None, hint="check the file name"))
        _emit(sink, as_json, False)
        return None


def cmd_check(args) -> int:
    from ..pipeline import compile_source
    src = _read(args.file, args.json)
    if src is None:
        return 1
    res = compile_source(src, args.file, _overrides(args.set))
    extra = {}
    dofs = None
    if res.solve is not None:
        extra["solve"] = {"converged": res.solve.converged, "iterations": res.solve.iterations,
                          "unknowns": res.solve.n_unknowns, "equations": res.solve.n_equations,
                          "max_residual": res.solve.max_residual}
        if args.dof and res.ok:
            from ..pipeline import report_redundancies
            from ..solver.diagnose import degrees_of_freedom
            report_redundancies(res.sink, res.solve)
            dofs = degrees_of_freedom(res.solve.solver)
            extra["dof"] = [{"structure": d.structure.path, "unknowns": d.unknowns,
                             "dof": d.dof, "floating": d.floating} for d in dofs]
        if res.ok:
            from ..solver.diagnose import degrees_of_freedom, freedom_text
            dofs_all = (dofs if dofs is not None
                        else degrees_of_freedom(res.solve.solver, floating=False))
            extra["freedom"] = freedom_text(dofs_all)
    _emit(res.sink, args.json, res.ok, extra)
    if res.ok and not args.json:
        s = res.solve
        print(f"{args.file}: ok ({len(res.model.structures)} structures, {s.n_unknowns} unknowns, "
              f"{s.n_equations} equations, solved in {s.iterations} Newton steps; "
              f"{extra.get('freedom', 'not solved')})")
        if dofs is not None:
            _print_dof(dofs)
    return 0 if res.ok else 1


def _print_dof(dofs) -> None:
    """One line per structure: its own unknowns (geometry and children's positions), the
    degrees of freedom its constraints leave, and what still floats."""
    width = max(len(d.structure.path) for d in dofs)
    print(f"{'structure':{width}}  unknowns  dof  floating")
    for d in dofs:
        fl = ", ".join(d.floating[:6]) + (f", ... ({len(d.floating)})" if len(d.floating) > 6
                                           else "")
        print(f"{d.structure.path:{width}}  {d.unknowns:8d}  {d.dof:3d}  {fl or '-'}")


def cmd_render(args) -> int:
    from ..pipeline import compile_source
    from ..output import render_model, to_svg
    src = _read(args.file, args.json)
    if src is None:
        return 1
    res = compile_source(src, args.file, _overrides(args.set))
    out = Path(args.output) if args.output else Path(args.file).with_suffix(".svg")
    if not res.ok:
        _emit(res.sink, args.json, False)
        return 1
    drawing = render_model(res.model)
    for g in drawing.open_curves:
        res.sink.warning("W0402", f"`{g.label}` is not part of a closed outline, so it is drawn as a "
                         "line, not filled", g.span,
                         hint="share endpoints between lines and arcs so they form a loop, or put "
                              "the curve in a `drawing` structure")
    svg = to_svg(drawing, title=res.model.root.name)
    try:
        fd, tmp = tempfile.mkstemp(suffix=".svg", dir=str(out.parent.resolve()))
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(svg)
        os.replace(tmp, out)
    except OSError as e:
        print(f"aidl: error: cannot write `{out}`: {e.strerror or e}", file=sys.stderr)
        return 1
    _emit(res.sink, args.json, True, {"output": str(out)})
    if not args.json:
        print(f"wrote {out}")
    return 0


def cmd_explain(args) -> int:
    from ..codes import CODES
    code = args.code.upper()
    if code not in CODES:
        print(f"aidl: unknown code `{args.code}`; known codes: {', '.join(sorted(CODES))}",
              file=sys.stderr)
        return 2
    title, text = CODES[code]
    print(f"{code}: {title}\n\n{text.strip()}")
    return 0


def cmd_fmt(args) -> int:
    from ..editor.fmt import main as fmt_main
    return fmt_main(args.files, check=args.check)


def cmd_lsp(args) -> int:
    for flag, given in (("--node-ipc", args.node_ipc), ("--pipe", args.pipe),
                        ("--socket", args.socket)):
        if given:
            print(f"aidl: error: `aidl lsp {flag}` is not supported: the server talks over "
                  "stdin/stdout (use the client's stdio transport, `--stdio`)", file=sys.stderr)
            return 2
    from ..editor.lsp.worker import spawn
    worker = spawn()                   # the diagnostics worker warms up while the server loads
    from ..editor.lsp.server import main as lsp_main
    return lsp_main(worker)


def cmd_serve(args) -> int:
    from ..serve import serve
    return serve(args.file, args.port)


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        from .llm import COMMANDS
        return ({"check": cmd_check, "render": cmd_render, "explain": cmd_explain,
                 "fmt": cmd_fmt, "lsp": cmd_lsp, "serve": cmd_serve} | COMMANDS)[args.cmd](args)
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:          # `aidl check --json | head`
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:
            pass
        return 0
    except RecursionError:
        print("aidl: error[E0302]: the program is nested too deeply to compile", file=sys.stderr)
        return 1
    except Exception as e:  # an internal error: report it as such, never a raw traceback
        print(f"aidl: internal error: {type(e).__name__}: {e}\n"
              "This is a bug in aidl, not in your program. Please report it with the input file.",
              file=sys.stderr)
        if os.environ.get("AIDL_DEBUG"):
            raise
        return 3


if __name__ == "__main__":
    raise SystemExit(main())
