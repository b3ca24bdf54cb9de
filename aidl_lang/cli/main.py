"""The ``aidl`` command line: ``render``, ``check``, ``parts``, ``explain``, ``fmt``, ``lsp``,
``serve``, ``mcp`` (and
``prompt``, ``generate``, ``eval`` from :mod:`aidl_lang.cli.llm`).

Exit status: 0 success, 1 a user error in the program (diagnostics printed) or an output the
writer cannot make (an impossible PNG size), 2 a usage error or a format whose optional library
is not installed (the message gives the ``pip install`` line), 3 an internal error (a bug).
An output file is written only when the whole pipeline succeeded and every requested format was
produced (each written to a temporary file beside it, then renamed), so a good drawing is never
replaced by a broken one.  ``render`` never writes over the program it reads, refuses a
directory as output, refuses a symlink as output unless ``--follow-symlinks`` (then it writes
through it; the link stays) and a read-only file unless ``--force``, never replaces a FIFO, a
device, a socket or a directory (:mod:`aidl_lang.output.writers.write`; ``-o -`` writes to standard
output, ``--format``), and creates files with the user's umask (an existing file keeps its
mode); docs/outputs.md has the details.
"""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path

from ..base.diagnostics import DiagnosticSink, render_texts
from ..base.limits import now
from .arguments import SUBCOMMANDS, _parser


def _cap_memory(args) -> None:
    """``aidl check/render/parts/import``: cap the address space (``--memory``; by default
    :func:`aidl_lang.base.memory.default_cap`), so running out is a located E0304."""
    from ..base.memory import default_cap, limit_memory
    size = args.memory
    if size is None:
        size = default_cap()
    limit_memory(size, raise_with="--memory SIZE")


def _budget(args):
    from ..base.limits import DEFAULT_BUDGET
    return DEFAULT_BUDGET.scaled(args.budget)


def _overrides(items: list[str]) -> dict[str, str]:
    out = {}
    for it in items:
        if "=" not in it:
            print(f"aidl: error: --set expects NAME=VALUE, got `{it}`", file=sys.stderr)
            raise SystemExit(2)
        k, v = it.split("=", 1)
        out[k.strip()] = v.strip()
    return out


PRINTED_PER_CODE = 10      # diagnostics of one code printed in full; the rest are counted


def _work_of(res) -> dict:
    """``{"work": ...}``: the work units a compile's stages spent (``--json``), or ``{}``."""
    return {"work": res.work.to_json()} if getattr(res, "work", None) is not None else {}


def _emit(sink: DiagnosticSink, as_json: bool, ok: bool, extra: dict | None = None) -> None:
    if as_json:
        doc = {"ok": ok, "diagnostics": [d.to_json(sink.sources) for d in sink.items]}
        doc.update(extra or {})
        print(json.dumps(doc, indent=2))
        return
    color = sys.stderr.isatty() and not os.environ.get("NO_COLOR")
    shown: dict[str, int] = {}
    printed = []
    for d in sink.items:            # a flood: the first PRINTED_PER_CODE of each code in full
        shown[d.code] = shown.get(d.code, 0) + 1
        if shown[d.code] <= PRINTED_PER_CODE:
            printed.append(d)
    for text in render_texts(printed, sink.sources, color=color):   # repeats in one line
        print(text, file=sys.stderr)
        print(file=sys.stderr)
    for code, n in shown.items():
        if n > PRINTED_PER_CODE:
            print(f"aidl: and {n - PRINTED_PER_CODE:,} more of {code} (`--json` lists them all)",
                  file=sys.stderr)
    n_err = sum(d.is_error for d in sink.items)
    n_warn = sum(d.severity == "warning" for d in sink.items)
    if n_err:
        print(f"aidl: {n_err} error{'s' if n_err != 1 else ''}"
              + (f", {n_warn} warning{'s' if n_warn != 1 else ''}" if n_warn else ""), file=sys.stderr)


def _read(path: str, as_json: bool) -> str | None:
    from ..library.sources import SourceRefused, read_program
    try:
        return read_program(path)          # a regular file, size-limited, never blocking
    except SourceRefused as e:
        sink = DiagnosticSink()
        sink.add(e.diagnostic(path))
        _emit(sink, as_json, False)
        return None


# plain `aidl check` looks for redundant constraints (W0401) within these bounds, as the
# language server does; `--dof` looks without them (docs/solver.md, section 6)
from ..api import REDUNDANCY_ROWS, REDUNDANCY_SECONDS  # noqa: E402


def _check_file(args, parser) -> None:
    """``aidl check --values FILE``: ``--values`` (any number of names) swallowed the
    program's name; the last name that is an existing file or ends in ``.aidl`` (or ``-``) is
    the program, the others stay names.  No program at all is argparse's usual usage error."""
    if args.file is not None:
        return
    names = args.values or []
    for k in range(len(names) - 1, -1, -1):
        v = names[k]
        if v == "-" or v.endswith(".aidl") or os.path.isfile(v):
            args.file = v
            args.values = names[:k] + names[k + 1:]
            return
    print("usage: aidl check [options] FILE\n"
          "aidl check: error: the following arguments are required: file", file=sys.stderr)
    raise SystemExit(2)


def cmd_check(args) -> int:
    from ..api import compile as compile_program
    program = compile_program(path=args.file, overrides=_overrides(args.set),
                              budget=_budget(args), min_wall=args.min_wall)
    global _program
    _program = (args.file, program.source) if program.source is not None else None
    res = program.compiled
    extra = {}
    dofs = None
    # the whole run has one budget (15 s x --budget) from the start of the compile:
    # the freedom count and the redundancy search get what the parse, solve and checks left
    end = (res.deadline.at if res.deadline is not None
           else now() + _budget(args).backstop)
    if res.solve is not None:
        extra["solve"] = {"converged": res.solve.converged, "iterations": res.solve.iterations,
                          "unknowns": res.solve.n_unknowns, "equations": res.solve.n_equations,
                          "settled": res.solve.n_settled,
                          "max_residual": res.solve.max_residual}
        from ..solver.diagnosis.freedom import degrees_of_freedom, freedom_text
        if args.dof and res.ok:
            dofs = degrees_of_freedom(res.solve.solver, deadline=end)
            extra["dof"] = [{"structure": d.structure.path, "unknowns": d.unknowns,
                             "dof": d.dof if d.rank >= 0 else None,     # None: not counted
                             "floating": d.floating}
                            | ({"not_counted": d.why} if d.rank < 0 else {}) for d in dofs]
        if res.ok:
            if args.dof:
                # the whole search, in what is left of the budget (2 500 chained points took
                # 15 s more, on top of the compile, before their rows were peeled)
                program.find_redundant(None, None, deadline=end)
            else:
                program.find_redundant(REDUNDANCY_SECONDS, REDUNDANCY_ROWS, deadline=end)
            if args.dof or program.not_searched:
                extra["redundancy"] = {"not_searched": program.not_searched}
                if program.not_searched:
                    extra["redundancy"]["why"] = program.not_searched_why
            dofs_all = (dofs if dofs is not None
                        else degrees_of_freedom(res.solve.solver, floating=False, deadline=end))
            extra["freedom"] = freedom_text(dofs_all, program.sliding())
    values = None
    if args.values is not None and program.ok:
        values = program.values_matching(args.values)
        extra["units"] = program.units
        extra["values"] = [v.to_json() for v in values]
    if getattr(args, "describe", False) and program.ok:
        program.deadline = res.deadline     # what the compile left of the one budget
        extra["describe"] = program.description
    report = None
    if getattr(args, "sweep", False) and program.ok:
        report = program.sweep(budget=_budget(args))
        for d in report.diagnostics:
            res.sink.add(d)
        extra["sweep"] = report.to_json()
    if res.work is not None:
        extra["work"] = res.work.to_json()
    _emit(res.sink, args.json, res.ok, extra)
    if res.ok and not args.json:
        s = res.solve
        from ..solver import solve_text     # (numpy: not for `aidl mcp`'s start, issue 95)
        print(f"{args.file}: ok ({len(res.model.structures)} structures, {solve_text(s)}; "
              f"{extra.get('freedom', 'not solved')})")
        if dofs is not None:
            _print_dof(dofs)
            if "freedom" in extra and extra["freedom"] != "fully constrained":
                from ..solver.diagnosis.freedom import floating_legend
                print(floating_legend(extra["freedom"]))
        if program.not_searched:
            n = program.not_searched
            why = program.not_searched_why
            if why == "out of time":           # the CPU backstop
                why += (f": the backstop's {_budget(args).backstop:g} s of CPU time; "
                        "--budget K gives K times more")
            elif why == "out of budget":       # the search's own work (flops): plain check
                why += (f": the search's {REDUNDANCY_SECONDS:g} s of work; `--dof` searches "
                        "in the whole budget")
            elif why == "too large" and not args.dof:
                why += f": blocks past {REDUNDANCY_ROWS} rows; `--dof` ranks larger ones"
            print(f"redundant constraints (W0401): not counted: {n} constraint"
                  f"{'s' if n != 1 else ''} not searched ({why})")
        for v in values or ():
            print(v.text())
        if "describe" in extra:
            from ..output.checks.reports.describe import describe_text
            print(describe_text(extra["describe"]))
        if values is not None and not values:
            print(f"aidl: no value matches {' '.join(args.values)}", file=sys.stderr)
        if report is not None:
            print(report.text())
    return 0 if res.ok else 1


def _print_dof(dofs) -> None:
    """One line per structure: its own unknowns (geometry and children's positions), the
    degrees of freedom its constraints leave, and what still floats."""
    width = max(len(d.structure.path) for d in dofs)
    print(f"{'structure':{width}}  unknowns  dof  floating")
    for d in dofs:
        fl = ", ".join(d.floating[:6]) + (f", ... ({len(d.floating)})" if len(d.floating) > 6
                                           else "")
        if d.rank < 0:                  # too large for the dense count, or out of time
            print(f"{d.structure.path:{width}}  {d.unknowns:8d}    ?  not counted ({d.why})")
            continue
        print(f"{d.structure.path:{width}}  {d.unknowns:8d}  {d.dof:3d}  {fl or '-'}")


def _usage(msg: str) -> int:
    print(f"aidl: error: {msg}", file=sys.stderr)
    return 2


def _materials(sheets) -> str:
    """`` (3 mm: sheets 1-2; 6 mm: sheet 3)`` when the sheets hold more than one material
    thickness (each sheet holds one, :func:`aidl_lang.output.fabrication.layout.plan`), else ``""``."""
    by: dict = {}
    for j, s in enumerate(sheets, 1):
        t = {p.thickness for p in s.parts}
        by.setdefault(t.pop() if len(t) == 1 else None, []).append(j)
    if len(by) < 2:
        return ""
    said = []
    for t, js in by.items():
        which = f"sheet {js[0]}" if len(js) == 1 else f"sheets {js[0]}-{js[-1]}"
        said.append(f"{'no thickness' if t is None else f'{t:g} mm'}: {which}")
    return " (" + "; ".join(said) + ")"


def _sheet_names(outs: list[Path], n: int) -> list[list[Path]]:
    """The files of ``n`` sheets for each output: ``cut.svg`` for one sheet, else
    ``cut-1.svg``, ``cut-2.svg``, ..."""
    if n == 1:
        return [[o] for o in outs]
    return [[o.with_name(f"{o.stem}-{k + 1}{o.suffix}") for k in range(n)] for o in outs]


STDOUT = Path("-")           # `-o -`: standard output (no file name: it has no extension)
from .importing import NOT_REGULAR_HINT  # noqa: E402  (the outputs' hint; one place)


def _stdout_format(args, outs: list[Path]) -> int | None:
    """Check ``-o -`` and ``--format`` (usage errors exit 2) and set ``args.stdout_suffix``
    (``.svg``, ...; None without ``-o -``)."""
    from ..output import FORMATS, TEXT_FORMATS   # TEXT_FORMATS: `-o -` to a terminal too
    fmt = getattr(args, "format", None)
    args.stdout_suffix = None
    if STDOUT not in outs:
        if fmt is not None:
            return _usage("--format is the format of `-o -` (standard output); a file's format "
                          "follows its extension")
        return None
    suffix = "." + (fmt or "svg").lower().lstrip(".")
    if suffix not in FORMATS:
        return _usage(f"--format takes one of {', '.join(sorted(f[1:] for f in FORMATS))}; "
                      f"got `{fmt}`")
    if args.json:
        return _usage("--json prints to standard output, so -o - cannot: write the output to "
                      "a file (-o OUT.svg)")
    if suffix not in TEXT_FORMATS and sys.stdout.isatty():
        return _usage(f"refusing to write binary {suffix[1:].upper()} to a terminal: redirect "
                      f"standard output (`> out{suffix}`) or give a file name")
    args.stdout_suffix = suffix
    return None


def _suffix(o: Path, args) -> str:
    """The format of the output ``o``: its extension, or ``--format`` for ``-o -``."""
    return args.stdout_suffix if o == STDOUT else o.suffix.lower()


def _outputs(args) -> list[Path] | int:
    """The output paths, checked before compiling (usage errors exit 2): known extensions,
    not the program itself, not a directory, not a FIFO, device or socket (never replaced:
    :func:`aidl_lang.output.writers.write.not_regular`); ``-`` is standard output (``--format``); a
    default only for a regular input file."""
    from ..output import FORMATS
    if args.output:
        outs = [Path(o) for o in args.output]
    else:
        src = Path(args.file)
        special = os.path.abspath(args.file).startswith(("/dev/", "/proc/"))
        if args.file == "-" or special or not src.is_file():
            if args.file == "-" or special or src.exists():
                return _usage(f"`{args.file}` is not a regular file, so there is no default "
                              "output name: give one with -o OUT.svg")
            return []              # a missing file: reported as E0004 when read
        if src.suffix.lower() == ".svg":
            return _usage(f"the default output `{src.with_suffix('.svg')}` is the program "
                          "itself: give an output name with -o")
        outs = [src.with_suffix(".svg")]
    seen = set()
    for o in outs:
        if o == STDOUT:
            if "-" in seen:
                return _usage("`-o -` is given twice")
            seen.add("-")
            continue
        real = os.path.realpath(o)
        if args.file != "-" and os.path.exists(args.file) and os.path.exists(real) \
                and os.path.samefile(real, args.file):
            return _usage(f"`{o}` is the program being rendered; refusing to overwrite it")
        if o.is_dir():
            return _usage(f"`{o}` is a directory; give a file name, e.g. {o / 'part.svg'}")
        if o.suffix.lower() not in FORMATS:
            return _usage(f"cannot tell the format of `{o}` from its extension; use one of "
                          + ", ".join(sorted(FORMATS)))
        if real in seen:
            return _usage(f"`{o}` is given twice")
        seen.add(real)
        refused = _refused_output(o, getattr(args, "follow_symlinks", False),
                                  getattr(args, "force", False))
        if refused is not None:
            return refused
    bad = _stdout_format(args, outs)
    return outs if bad is None else bad


def _refused_output(o: Path, follow: bool, force: bool) -> int | None:
    """A symbolic link as output is refused (exit 2: someone may have planted it to make the
    render overwrite another file) unless ``--follow-symlinks``, and even then (exit 1) when
    another user made it in a sticky world-writable folder (:func:`aidl_lang.output.writers.write.planted_link`);
    a FIFO, device or socket (or, with ``--follow-symlinks``, a link to one) is refused (exit
    2: never replaced); an existing read-only file is refused (exit 1) unless ``--force``.
    None when ``o`` may be written."""
    if os.path.islink(o) and not follow:
        return _usage(f"`{o}` is a symbolic link (to `{os.readlink(o)}`); refusing to write "
                      "through it: give --follow-symlinks to write the file it points to, or "
                      "another output name")
    if os.path.islink(o):
        from ..output.writers.write import planted_link
        planted = planted_link(o)
        if planted:
            print(f"aidl: error: {planted.replace('when asked to follow links', 'with --follow-symlinks')}",
                  file=sys.stderr)
            return 1
    target = os.path.realpath(o) if follow else str(o)
    try:
        st = os.stat(target)
    except OSError:
        return None
    from ..output.writers.write import kind_of, refusal
    kind = kind_of(st.st_mode)
    if kind is not None:
        if os.path.islink(o):
            kind = f"a symbolic link to {kind} (`{target}`)"
        return _usage(refusal(o, kind, NOT_REGULAR_HINT))
    import stat as S

    from ..output.writers.write import read_only
    if read_only(st, target) and not force:
        print(f"aidl: error: `{o}` is read-only (mode {S.S_IMODE(st.st_mode):04o}); refusing "
              "to replace it: give --force to replace it anyway", file=sys.stderr)
        return 1
    return None


def _encode_all(jobs: list, opt, deadline):
    """Each ``(path, output, suffix)`` of ``jobs`` encoded in turn: the ``[(path, bytes)]`` to
    write.  A writer that would end past the compile's ``deadline`` is refused before it
    starts (:func:`aidl_lang.output.encode`: an :class:`~aidl_lang.output.OutputError` whose
    ``budget`` names the part), and nothing is written."""
    from ..output import encode
    return [(o, encode(output, suffix, opt, deadline)) for o, output, suffix in jobs]


def _write_all(items: list[tuple[Path, bytes]], follow: bool = False) -> str | None:
    """Write every output or none: each staged beside its target (:func:`aidl_lang.output.writers.write.stage`:
    symlinks, modes), then ``-`` written to standard output, then all renamed over their
    targets (:func:`aidl_lang.output.writers.write.replace`: never half-written, never over a FIFO,
    device, socket or directory).  Returns an error message, or None."""
    from ..output.writers.write import NotRegularFile, discard, replace, stage
    staged = []
    out = items[0][0] if items else ""
    try:
        for out, data in items:
            if out != STDOUT:
                staged.append((*stage(out, data, follow, NOT_REGULAR_HINT), out))
        for out, data in items:
            if out == STDOUT:
                sys.stdout.flush()
                sys.stdout.buffer.write(data)
                sys.stdout.buffer.flush()
        for tmp, target, out in staged:
            replace(tmp, target, out, hint=NOT_REGULAR_HINT)
        staged = []
        return None
    except NotRegularFile as e:
        return str(e)
    except BrokenPipeError:
        raise
    except OSError as e:
        return f"cannot write `{out}`: {e.strerror or e}"
    finally:
        for tmp, _, _ in staged:
            discard(tmp)


def cmd_render(args) -> int:
    from ..pipeline import compile_source, report_out_of_budget, report_stacked
    from ..output import MissingDependency, Options, OutputError, build
    from ..output.writers import StackedParts, SunkAway
    outs = _outputs(args)
    if isinstance(outs, int):
        return outs
    got = _render_settings(args, outs)
    if isinstance(got, int):
        return got
    show, thickness, kerf, sheet, gap, rotate, machine = got
    if args.file == "-":
        src = sys.stdin.read()
    else:
        src = _read(args.file, args.json)
        if src is None:
            return 1
    global _program
    _program = (args.file, src)
    res = compile_source(src, args.file, _overrides(args.set), min_wall=args.min_wall,
                         budget=_budget(args))
    if not res.ok:
        _emit(res.sink, args.json, False, _work_of(res))
        return 1
    if args.layout:
        # W0534 speaks of the default sheet: a layout speaks of its own, and refuses a part
        # too large for it (run ff: "does not fit the 600 x 400 mm sheet" above a layout on
        # the 800 x 600 mm sheet it was told)
        res.sink.items[:] = [d for d in res.sink.items if d.code != "W0534"]
    opt = Options(show=show, style=args.svg_style, dpi=args.dpi, width=args.png_width,
                  thickness=thickness, margin=args.margin, assembled=args.assembled,
                  machine=machine, page=args.page)
    notes = []
    try:
        output = build(res.drawing, res.model.root.name, deadline=res.deadline)
        from ..output import CUT_FORMATS, for_cutting
        # --kerf, else the program's `kerf`; laid out, the pieces of a cut lie apart and each
        # is offset whole, else an edge two pieces share is cut once along its line
        cut = for_cutting(output, kerf, res.deadline, apart=bool(args.layout))
        from ..output.fabrication.layout import through_cut_note
        from ..output.part.edges.shared import shared_note
        kept = through_cut_note(output, cut)       # --kerf leaves the through-cuts
        if kept:
            notes.append(kept)
        if cut is not output and not args.layout:
            notes += shared_note(output, kerf if kerf is not None else output.drawing.kerf)
        flat, solid = [cut], [output]
        if args.layout:
            flat, solid = _lay_out(args, res, output, cut, sheet, gap, rotate, notes)
        if len(flat) > 1 and STDOUT in outs:
            print(f"aidl: error: the layout has {len(flat)} sheets and standard output takes "
                  "one: write them to files (-o cut.svg writes cut-1.svg, cut-2.svg, ...)",
                  file=sys.stderr)
            return 1
        names = _sheet_names(outs, len(flat)) if len(flat) > 1 else [[o] for o in outs]
        outs = [n for per in names for n in per]
        cutting = () if args.assembled else CUT_FORMATS      # an assembled PNG: designed
        jobs = [(n, s, _suffix(o, args)) for o, per in zip([p[0] for p in names], names)
                for n, s in zip(per, flat if _suffix(o, args) in cutting else solid)]
        if args.assembled and not getattr(res.drawing, "placement", None):
            notes.append("note: no part is placed (`Place`): the assembled product is the "
                         "parts as on the sheet")
        if args.assembled and getattr(res.drawing, "bends", None) and any(
                j[2] in (".step", ".stp") for j in jobs):
            notes.append("note: STEP shows the bent parts (`Bend`) flat, as cut; .3mf, .glb "
                         "and .stl show them bent")
        routed = machine is not None and machine.kind == "router" and any(
            j[2] in (".gcode", ".nc") for j in jobs)
        notes += _sink_notes(res.drawing, jobs, routed)
        from ..output.checks.material.toolpath_walls import machine_warnings
        if routed:              # W0510 (cut apart) and W0507 (too little left), located
            machine_warnings(res.drawing, cut, output, machine.tool_diameter, True, res.sink,
                             args.min_wall, bool(args.layout), machine.relief)
            from ..output.checks.assembly import check_routed_fit
            check_routed_fit(res.drawing, output, machine.tool_diameter, machine.relief,
                             res.sink, res.deadline)
        elif cut is not output and not args.assembled and any(j[2] in CUT_FORMATS
                                                              for j in jobs):
            machine_warnings(res.drawing, output, output, kerf if kerf is not None else
                             output.drawing.kerf, False, res.sink, args.min_wall,
                             bool(args.layout))
        items = _encode_all(jobs, opt, res.deadline)
    except MissingDependency as e:           # not the program's fault: install the extra
        print(f"aidl: error: {e}", file=sys.stderr)
        return 2
    except OutputError as e:                 # an impossible size, or bounded work ran out
        if e.budget is not None:                 # located: which structure, which stage
            report_out_of_budget(res.sink, e.budget)
            _emit(res.sink, args.json, False, _work_of(res))
        elif isinstance(e, StackedParts):        # located at the first of the two parts
            report_stacked(res.sink, res.drawing, e)
            _emit(res.sink, args.json, False, _work_of(res))
        elif isinstance(e, SunkAway):            # located at the widest head's call
            from ..base.diagnostics import Diagnostic
            res.sink.add(Diagnostic("E0503", e.message, e.span, "error", hint=e.hint))
            _emit(res.sink, args.json, False, _work_of(res))
        elif hasattr(e, "kerf"):                 # a kerf a cut cannot be offset by: at the hole
            res.sink.add(e.diagnostic(res.drawing))
            _emit(res.sink, args.json, False, _work_of(res))
        elif hasattr(e, "holds"):                # a layout with no solid part: at the design
            from ..pipeline import report_nothing
            report_nothing(res.sink, res.model, e)
            _emit(res.sink, args.json, False, _work_of(res))
        else:
            print(f"aidl: error: {e}", file=sys.stderr)
        return 1
    err = _write_all(items, args.follow_symlinks)
    if err:
        print(f"aidl: error: {err}", file=sys.stderr)
        return 1
    _emit(res.sink, args.json, True, {"output": str(outs[0]), "outputs": [str(o) for o in outs]}
          | _work_of(res))
    _report_written(args, items, outs, notes)
    return 0


def _sink_notes(drawing, jobs, routed: bool) -> list[str]:
    """The note of a flat file holding countersink or counterbore heads (issue 102): their
    circles are marks on a layer of their own; the cone or the step is not cut by a laser."""
    from ..output import CUT_FORMATS
    sinks = getattr(drawing, "sinks", None) or ()
    flat = [j for j in jobs if j[2] in CUT_FORMATS and not (routed and j[2] in (".gcode", ".nc"))]
    if not sinks or not flat:
        return []
    out = []
    for kind in ("countersink", "counterbore"):
        these = [s for s in sinks if s.kind == kind]
        if these:
            sizes = ", ".join(f"{d:g}" for d in sorted({s.diameter for s in these}))
            out.append(f"note: {len(these)} {kind} head{'s' if len(these) != 1 else ''} "
                       f"({sizes} mm) drawn as circles on the engrave layer `{kind}`: the "
                       f"holes are cut through, the {'cones' if kind == 'countersink' else 'steps'}"
                       " are not (sink them by hand, or with `--machine router`)")
    return out


def _render_settings(args, outs):
    """`aidl render`'s settings from its flags, checked before anything is compiled: the
    tuple (show, thickness, kerf, sheet, gap, rotate, machine), or the exit code of a usage
    error already printed (2)."""
    from ..output import OutputError
    from ..output.fabrication.layout import parse_length, parse_rotate, parse_sheet
    show = tuple(x.strip() for x in args.show.split(",") if x.strip())
    from ..output.writers.svg import SHOW
    if set(show) - set(SHOW):
        return _usage(f"--show takes {', '.join(SHOW)}; got `{args.show}`")
    thickness = None
    if args.thickness is not None:
        thickness = parse_length(args.thickness)
        if thickness is None:
            return _usage(f"--thickness expects a positive length up to 1 km, such as 3mm, got "
                          f"`{args.thickness}`")
    from ..base.limits import MAX_EXTENT
    if args.margin is not None and not 0 <= args.margin <= MAX_EXTENT:
        return _usage(f"--margin expects a length in mm from 0 to 1e6, got `{args.margin:g}`")
    if args.page is not None:
        from ..output.writers.pdf import page_names, page_size
        if not any(_suffix(o, args) == ".pdf" for o in outs):
            return _usage("--page is the paper size of a PDF template: add -o NAME.pdf")
        try:
            page_size(args.page)
        except OutputError:
            return _usage(f"--page takes {', '.join(page_names())}; got `{args.page}`")
    kerf = None
    if args.kerf is not None:
        kerf = parse_length(args.kerf, zero=True)
        if kerf is None or kerf > 10:
            return _usage(f"--kerf expects a length from 0 (no offset) up to 10 mm, such as "
                          f"0.15mm, got "
                          f"`{args.kerf}`")
    sheet = parse_sheet(args.sheet)
    if sheet is None:
        return _usage(f"--sheet expects WIDTHxHEIGHT with a unit, such as 600x400mm, got "
                      f"`{args.sheet}`")
    gap = parse_length(args.gap, zero=True)
    if gap is None:
        return _usage(f"--gap expects a length of 0 or more, such as 3mm, got `{args.gap}`")
    try:
        rotate = parse_rotate(args.rotate)
    except ValueError:
        return _usage(f"--rotate expects angles in degrees such as 0,90, or any; got "
                      f"`{args.rotate}`")
    if args.nest_time < 0 or args.nest_time > 3600:
        return _usage(f"--nest-time expects seconds from 0 to 3600, got `{args.nest_time}`")
    if args.assembled:
        from ..output import ASSEMBLED_FORMATS
        flat_only = [str(o) for o in outs if _suffix(o, args) not in ASSEMBLED_FORMATS]
        if flat_only:
            return _usage(f"--assembled writes STL, 3MF, STEP, GLB or PNG, not "
                          f"`{flat_only[0]}` (SVG and DXF are the flat parts)")
        if args.layout:
            return _usage("--assembled and --layout do not go together: the assembled product "
                          "is in 3D, a layout is flat")
    if args.layout is None and (args.sheet, args.gap, args.rotate) != ("600x400mm", "3mm", "0,90"):
        return _usage("--sheet, --gap and --rotate are for a cutting layout: add --layout sheet")
    machine = None
    if args.machine is not None:
        from ..output.fabrication.machine import KINDS, MachineError, default, load
        try:
            machine = default(args.machine) if args.machine in KINDS and \
                not os.path.exists(args.machine) else load(args.machine)
        except MachineError as e:
            return _usage(str(e))
    return show, thickness, kerf, sheet, gap, rotate, machine


def _lay_out(args, res, output, cut, sheet, gap, rotate, notes: list):
    """`--layout sheet`: the parts of ``cut`` (as cut) and ``output`` (as designed) nested on
    sheets of ``sheet`` mm (``gap`` apart, turned by ``rotate``); returns the two lists of
    sheets and adds what it did to ``notes``.  Raises the layout's :class:`OutputError`."""
    from ..output.fabrication.layout import place, plan
    if args.nest_time and res.deadline is not None:
        # the nesting's own time limit comes on top of the compile's budget (the CPU
        # seconds of its threads)
        from ..base.limits import Deadline, seconds_as_work
        from ..output.fabrication.layout import nest_cpu_seconds
        res.deadline = Deadline(res.deadline.at + nest_cpu_seconds(args.nest_time),
                                res.deadline.budget, work=res.deadline.work)
        res.deadline.work.limit += seconds_as_work(nest_cpu_seconds(args.nest_time))
    where = plan(cut, sheet, gap, rotate, args.nest_time, deadline=res.deadline)
    flat, dropped = place(cut, where, sheet)
    solid, _ = place(output, where, sheet)
    notes.append(f"laid out {sum(len(s.parts) for s in flat)} parts on "
                 f"{len(flat)} sheet{'s' if len(flat) != 1 else ''} of "
                 f"{sheet[0]:g} x {sheet[1]:g} mm" + _materials(flat))
    if dropped:
        placed = {name for moves in where for name in moves}
        sheet_level = sum(1 for st in cut.engrave
                          if st.style == "cut" and st.part not in placed)
        kinds = [f"{n} {what} stroke{'s' if n != 1 else ''}" for n, what in
                 ((dropped - sheet_level, "engraving"), (sheet_level, "sheet-level cut"))
                 if n]
        notes.append(f"note: {' and '.join(kinds)} outside every part left out of the "
                     "layout" + ("" if dropped == sheet_level else
                                 " (a drawing at assembly level is an illustration; one meant "
                                 "on a part is given to it: `CutInto(label, box.front)`)"))
    return flat, solid


def _report_written(args, items, outs, notes: list) -> None:
    """After the files are written: each G-code file's estimate and its profile's warnings
    not said located already, the notes and a `wrote` line per file (on stderr when the
    drawing went to standard output)."""
    from ..output.writers.gcode import GCODE_FORMATS, LOCATED_TAGS, read_summary
    said = set()
    for o, data in items:                    # G-code: the estimates, the profile's warnings
        if _suffix(o, args) in GCODE_FORMATS:
            estimate, warnings, said_notes = read_summary(data)
            for w in warnings:
                if w.endswith(LOCATED_TAGS):     # said located (machine_warnings)
                    continue
                if w not in said:
                    said.add(w)
                    print(f"aidl: warning: {w}", file=sys.stderr)
            notes += [f"note: {n}" for n in said_notes if f"note: {n}" not in notes]
            if estimate and not args.json:
                notes.append(f"{'standard output' if o == STDOUT else o}: {estimate}")
    if not args.json:
        info = sys.stderr if STDOUT in outs else sys.stdout    # stdout holds the drawing
        for line in notes:
            print(line, file=info)
        for o in outs:
            if o != STDOUT:
                print(f"wrote {o}", file=info)

def cmd_parts(args) -> int:
    from ..pipeline import compile_source
    from ..output import build
    from ..output.checks.reports.inventory import parts_list, parts_text
    src = _read(args.file, args.json)
    if src is None:
        return 1
    global _program
    _program = (args.file, src)          # what a last-resort diagnostic is located in
    res = compile_source(src, args.file, _overrides(args.set), budget=_budget(args))
    if not res.ok:
        _emit(res.sink, args.json, False)
        return 1
    # the parts list gets what the compile left of its budget (E0304 past it)
    rows = parts_list(build(res.drawing, res.model.root.name, deadline=res.deadline),
                      res.deadline)
    if args.json:
        print(json.dumps({"ok": True, "unit": "mm", "parts": rows}, indent=2))
    else:
        print(parts_text(rows))
    return 0


def cmd_explain(args) -> int:
    from ..base.codes import CODES
    code = args.code.upper()
    if code not in CODES:
        print(f"aidl: unknown code `{args.code}`; known codes: {', '.join(sorted(CODES))}",
              file=sys.stderr)
        return 2
    title, text = CODES[code]
    print(f"{code}: {title}\n\n{text.strip()}")
    return 0


def cmd_docs(args) -> int:
    from ..library.reference import index_text, lookup_text
    if args.name is None:
        sys.stdout.write(index_text())
        return 0
    text, found = lookup_text(args.name)
    if not found:
        print(f"aidl: {text.rstrip()}", file=sys.stderr)
        return 2
    sys.stdout.write(text)
    return 0


def _cmd_import(args) -> int:
    from .importing import cmd_import
    return cmd_import(args, _budget(args))


def cmd_fmt(args) -> int:
    from ..editor.fmt import main as fmt_main
    return fmt_main(args.files, check=args.check)


def cmd_set(args) -> int:
    """``aidl set FILE NAME=VALUE ...``: the params' values rewritten in the file
    (:func:`aidl_lang.api.set_params`), then ``aidl check FILE``; a value refused (an unknown
    name, the wrong kind, outside its range) leaves the file as it was: exit 1."""
    from ..api import ParamsRefused, set_params
    from ..output.writers.write import WriteError, edit_program
    values = {}
    for it in args.values:
        if "=" not in it:
            return _usage(f"`aidl set` takes NAME=VALUE, got `{it}`")
        k, v = it.split("=", 1)
        values[k.strip()] = v.strip()
    source = _read(args.file, args.json)
    if source is None:
        return 1
    try:
        text, _ = set_params(source, values, args.file, _budget(args))
    except ParamsRefused as e:
        if e.diagnostics:
            sink = DiagnosticSink()
            sink.sources[args.file] = source
            for d in e.diagnostics:
                sink.add(d)
            _emit(sink, args.json, False)
        else:
            print(f"aidl: error: {e}", file=sys.stderr)
        return 1
    except ValueError as e:
        print(f"aidl: error: {e}", file=sys.stderr)
        return 1
    try:
        edit_program(Path(args.file), text.encode("utf-8"))
    except WriteError as e:
        print(f"aidl: error: {e}", file=sys.stderr)
        return 1
    return main(["check", args.file] + (["--json"] if args.json else [])
                + [f"--budget={args.budget:g}"])


def cmd_lsp(args) -> int:
    for flag, given in (("--node-ipc", args.node_ipc), ("--pipe", args.pipe),
                        ("--socket", args.socket)):
        if given:
            print(f"aidl: error: `aidl lsp {flag}` is not supported: the server talks over "
                  "stdin/stdout (use the client's stdio transport, `--stdio`)", file=sys.stderr)
            return 2
    from ..editor.lsp.worker import spawn
    worker = spawn()                   # the diagnostics worker warms up while the server loads
    from ..editor.lsp.boot import main as lsp_main      # answers before pygls is loaded
    return lsp_main(worker)


def cmd_serve(args) -> int:
    if _read(args.file, False) is None:     # E0004: missing, a FIFO, a device, too large
        return 1
    from ..serve import serve
    return serve(args.file, args.port)


def cmd_studio(args) -> int:
    from ..studio import studio
    if not 1 <= args.processes <= 64 or not 1 <= args.compilers <= 64:
        return _usage("--processes and --compilers take 1 to 64")
    if args.recycle is not None and not 0 <= args.recycle <= 1_000_000:
        return _usage(f"--recycle takes 0 (never) to 1000000 answers, got {args.recycle}")
    if args.rate is not None:
        from limits import parse
        try:
            parse(args.rate)
        except ValueError:
            return _usage(f"--rate expects a count per period such as 300/minute, got "
                          f"`{args.rate}`")
    if args.store is not None:
        from ..studio.store import check_url
        try:
            check_url(args.store)
        except ValueError as e:
            return _usage(str(e))
    import re
    if args.scheduler is not None and not re.fullmatch(r"(tcp|tls|inproc|ucx)://\S+",
                                                        args.scheduler):
        return _usage(f"--scheduler expects a Dask scheduler address such as "
                      f"tcp://HOST:8786, got `{args.scheduler}`")
    return studio(args.host, args.port, args.processes, args.compilers, rate=args.rate,
                  memory_mb=args.memory, budget=getattr(args, "budget", None),
                  store=args.store, scheduler=args.scheduler, recycle=args.recycle)


def cmd_batch(args) -> int:
    from ..batch.command import main as batch_main
    return batch_main(args)


def cmd_mcp(args) -> int:
    if not os.path.isdir(args.root):
        return _usage(f"--root `{args.root}` is not a folder")
    import importlib.util               # (the `mcp` extra; found, not loaded: .mcp.fast)
    if importlib.util.find_spec("mcp") is None:
        print("aidl: error: `aidl mcp` needs the MCP SDK: pip install 'aidl-lang[mcp]'",
              file=sys.stderr)
        return 2
    from ..llm.prompt import agent_prompt
    from ..mcp.fast import serve        # the first answers while the SDK loads (issue 95)
    return serve(args.root, min(args.budget, 4.0), agent_prompt)


def main(argv: list[str] | None = None, cap_memory: bool = False) -> int:
    """Run one ``aidl`` command; returns the exit status (see the module text).
    ``cap_memory``: cap this process's address space for ``check``, ``render``, ``parts``
    and ``import`` (``--memory``; the ``aidl`` command does, :func:`entry`): a cap cannot be
    lifted again, so a caller that goes on in the same process (tests, a script) is left
    without one unless it asks."""
    global _command
    argv = sys.argv[1:] if argv is None else list(argv)
    first = argv[0] if argv else None
    parser = _parser(first if first in SUBCOMMANDS else None)
    args = parser.parse_args(argv)
    _command = args.cmd
    if args.cmd == "check":
        _check_file(args, parser)
    if cap_memory and args.cmd in ("check", "render", "parts", "import"):
        _cap_memory(args)
    oom = False
    try:
        run = {"check": cmd_check, "render": cmd_render, "parts": cmd_parts,
               "explain": cmd_explain, "docs": cmd_docs,
               "fmt": cmd_fmt, "set": cmd_set, "lsp": cmd_lsp, "serve": cmd_serve, "studio": cmd_studio, "mcp": cmd_mcp,
               "batch": cmd_batch, "import": _cmd_import}.get(args.cmd)
        if run is None:
            from .llm import COMMANDS
            run = COMMANDS[args.cmd]
        return run(args)
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
    except (MemoryError, SystemError) as e:
        from ..base.limits import is_out_of_memory
        if not is_out_of_memory(e):
            return _internal(e)
        oom = True                 # said below, once the failed frames are freed
    except Exception as e:  # an internal error: report it as such, never a raw traceback
        from ..output.part.part import OutputError
        if isinstance(e, OutputError):      # bounded work ran out after the compile
            return _output_error(args, e)
        return _internal(e)
    if oom:
        return _out_of_memory(args)
    return 3


def _internal(e: BaseException) -> int:
    """An internal error (a bug): one line, exit 3 (the traceback with ``AIDL_DEBUG=1``)."""
    print(f"aidl: internal error: {type(e).__name__}: {e}\n"
          "This is a bug in aidl, not in your program. Please report it with the input file.",
          file=sys.stderr)
    if os.environ.get("AIDL_DEBUG"):
        raise e
    return 3


_program: tuple[str, str] | None = None   # (path, source) of the program being compiled


def _program_text(args) -> tuple[str, str | None]:
    """``(path, source)`` of the program the failed command compiled (what it read, kept in
    :data:`_program`), to locate a last-resort diagnostic; the source None when unknown."""
    if _program is not None:
        return _program
    return getattr(args, "file", "-"), None


def _out_of_memory(args) -> int:
    """A ``MemoryError`` outside the compile's own handler (the freedom count, the redundancy
    search, the exact outlines, a writer, an import): one located ``E0304``, exit 1, nothing
    written."""
    from ..pipeline import out_of_memory_sink
    from ..base.limits import memory_text
    if args.cmd == "import":
        print(f"{args.file}: error[E0304]: importing `{args.file}` ran out of memory: "
              f"{memory_text()}\n  = help: import a smaller drawing, or one layer at a time "
              "(--layer)", file=sys.stderr)
        return 1
    sink = out_of_memory_sink(*_program_text(args))
    _emit(sink, getattr(args, "json", False), False)
    return 1


def _output_error(args, e) -> int:
    """An :class:`~aidl_lang.output.part.part.OutputError` after the compile (``aidl parts``,
    ``check --describe``): one located ``E0304``, exit 1, nothing written."""
    from ..pipeline import output_error_sink
    _emit(output_error_sink(*_program_text(args), e), getattr(args, "json", False), False)
    return 1


_command: str | None = None
# Commands that leave nothing behind when main() returns: outputs are written and renamed,
# cache files written, no threads or atexit work.
_QUICK_EXIT = frozenset({"check", "render", "parts", "explain", "docs", "fmt"})


def entry() -> None:
    """The ``aidl`` command (and ``python -m aidl_lang.cli``): :func:`main`, then exit with its
    status.  After the short commands (``check``, ``render``, ``explain``, ``fmt``) the
    process ends with ``os._exit`` once stdout and stderr are flushed, as mypy does: tearing
    the interpreter down (freeing every object of NumPy, Manifold, the model and the modules)
    cost 20-35 ms of a ~0.25 s cold ``aidl check`` and has no effect a user could see."""
    rc = main(cap_memory=True)
    if _command in _QUICK_EXIT:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):      # a closed pipe: nothing more can be shown
                pass
        os._exit(rc)
    sys.exit(rc)


if __name__ == "__main__":
    entry()
