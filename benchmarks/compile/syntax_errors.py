"""Where a deleted bracket is reported (issue 28): every bracket of the given files (default:
the examples) is deleted in turn and the file parsed; a report is *right* when the first error,
or one of its labels, is on the line of the deleted bracket or of its partner.  Prints the
count of right reports and how many errors each broken file got.

Run:  .venv/bin/python benchmarks/compile/syntax_errors.py [FILE.aidl ...]
      AIDL_SRC=/path/to/other/checkout .venv/bin/python benchmarks/compile/syntax_errors.py   # compare
"""
from __future__ import annotations

import collections
import os
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
if os.environ.get("AIDL_SRC"):
    sys.path.insert(0, os.environ["AIDL_SRC"])


def bracket_pairs(src: str) -> list[tuple[int, int, int]]:
    """Every bracket of ``src`` (a balanced, lexable program): ``(offset, its line, its
    partner's line)``, sorted; ``ValueError`` if it does not lex or is unbalanced."""
    from aidl_lang.parser import mask_comments
    from aidl_lang.parsing.lexing import _lex_lists
    types, spans, err = _lex_lists(mask_comments(src))
    if err is not None:
        raise ValueError(f"does not lex: {err}")
    stack, out = [], []
    for t, sp in zip(types, spans):
        if t in ("LPAR", "LSQB", "LBRACE"):
            stack.append(sp)
        elif t in ("RPAR", "RSQB", "RBRACE"):
            if not stack:
                raise ValueError(f"unbalanced: {t} on line {sp.line}")
            o = stack.pop()
            out += [(o.start, o.line, sp.line), (sp.start, sp.line, o.line)]
    if stack:
        raise ValueError(f"unbalanced: a bracket on line {stack[-1].line} is never closed")
    return sorted(out)


def main(paths: list[str]) -> None:
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.parser import parse
    files = paths or sorted(str(p) for p in (ROOT / "examples").glob("*.aidl"))
    right = total = 0
    counts: collections.Counter = collections.Counter()
    for p in files:
        src = pathlib.Path(p).read_text()
        for off, line, partner in bracket_pairs(src):
            sink = DiagnosticSink()
            parse(src[:off] + src[off + 1:], p, sink)
            errors = [d for d in sink.items if d.is_error]
            total += 1
            counts[len(errors)] += 1
            if errors and errors[0].span is not None:
                lines = {errors[0].span.line} | {lab.span.line for lab in errors[0].labels}
                right += bool(lines & {line, partner})
    print(f"{right} of {total} deletions reported on the bracket's line or its partner's")
    print("errors per broken file:", dict(sorted(counts.items())))


if __name__ == "__main__":
    main(sys.argv[1:])
