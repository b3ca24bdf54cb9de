"""``aidl import``: a drawing (DXF or SVG) into an editable program (docs/import.md), with
``--json`` its result and the work units it spent (issue 101)."""
from __future__ import annotations

import json
import os
import sys

# the hint when an output path is not a regular file (a link, a FIFO, a device): every
# command that writes a file says it
NOT_REGULAR_HINT = "choose another path, or `-o -` to write to standard output"


def cmd_import(args, budget) -> int:
    """``aidl import FILE -o PART.aidl``: exit 0 written, 1 refused (a located message on
    stderr, nothing written)."""
    from ..drawing.infer import import_drawing
    from ..drawing.model import DrawingError
    from ..host.files import FileRefused, read_file
    from ..library.sources import MAX_DRAWING_BYTES
    from ..base.limits import Work
    src = args.file
    work = Work(budget.work)
    as_json = getattr(args, "json", False)

    def said(ok: bool, diagnostics=(), notes=(), output=None) -> None:
        if as_json:          # one JSON document on stdout (the program goes to the file)
            print(json.dumps({"ok": ok, "output": output, "diagnostics": list(diagnostics),
                              "notes": [{"code": n.code, "message": n.message, "hint": n.hint}
                                        for n in notes], "work": work.to_json()}, indent=2))
    try:
        data = read_file(src, MAX_DRAWING_BYTES)
        def sel(v):
            return None if v is None else [int(x) if x.strip().isdigit() else x for x in v]
        text, notes = import_drawing(data, src, unit=args.units, layer=args.layer,
                                     parts=args.parts, close_tolerance=args.close_tolerance,
                                     cut=sel(args.cut), engrave=sel(args.engrave),
                                     ignore=sel(args.ignore), roles=args.roles,
                                     budget=budget, infer=args.infer,
                                     snap=args.snap, work=work)
    except (OSError, FileRefused) as ex:
        msg = f"cannot read `{src}`: {getattr(ex, 'message', None) or ex.strerror or ex}"
        print(f"{src}: error[E0130]: {msg}", file=sys.stderr)
        said(False, [{"code": "E0130", "message": msg, "hint": None, "line": None}])
        return 1
    except DrawingError as ex:
        at = f"{src}:{ex.line}" if ex.line else src        # a DXF entity's line
        print(f"{at}: error[{ex.code}]: {ex.message}" + (f"\n  = help: {ex.hint}" if ex.hint else ""),
              file=sys.stderr)
        said(False, [{"code": ex.code, "message": ex.message, "hint": ex.hint,
                      "line": ex.line}])
        return 1
    for n in notes:
        print(f"{src}: warning[{n.code}]: {n.message}" + (f"\n  = help: {n.hint}" if n.hint else ""),
              file=sys.stderr)
    out = args.output or os.path.splitext(src)[0] + ".aidl"
    if out == "-":
        if as_json:
            said(True, notes=notes, output="-")
        else:
            sys.stdout.write(text)
        return 0
    from ..output.writers.write import write_in_dir
    folder, base = os.path.split(os.path.abspath(out))
    try:
        dfd = os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
        try:
            # never over a link, a FIFO or a device such as /dev/null (NotRegularFile)
            write_in_dir(dfd, base, text.encode("utf-8"), out, NOT_REGULAR_HINT)
        finally:
            os.close(dfd)
    except OSError as ex:            # FileRefused, NotRegularFile: their message says it all
        why = str(ex) if isinstance(ex, FileRefused) or not ex.strerror else \
            f"cannot write `{out}`: {ex.strerror}"
        print(f"aidl: error: {why}", file=sys.stderr)
        said(False, [{"code": None, "message": why, "hint": None, "line": None}], notes)
        return 1
    print(f"wrote {out}", file=sys.stderr)
    said(True, notes=notes, output=out)
    return 0
