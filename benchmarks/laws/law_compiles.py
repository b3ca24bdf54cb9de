"""The most basic promise, and the runner's own law: every program the project ships compiles
without an error (``aidl check`` exit 0; warnings allowed).

Applies to the examples, the gallery (defaults, slider ends, bools flipped), the standard
library's templates and the ``aidl docs`` examples, the model and maker runs' programs that
were kept as compiling (final, first valid, a maker's edit: not the attempts a model checked
on its way, ``*.attemptN.aidl``, ``*.checkN.aidl``, ``tries/``, ``drafts/``, ``probes/``,
which were kept because they failed), and the test fixtures but those a test expects an
error of (``tests/programs/hostile/``: the first line's ``# expect: CODE``).
"""
from __future__ import annotations

import re

from .corpus import Entry, compiled

NAME = "every program in the corpus that the project ships compiles without error"
TOLERANCE = ("none: no diagnostic of severity error (warnings and notes are other laws' "
             "business), no exception from the compiler")

_ATTEMPT = re.compile(r"\.(attempt|check)\d+\.aidl$|/(tries|drafts|probes)/")
_EXPECT = re.compile(r"#\s*expect:\s*(ok|[EW]\d{4})")
# test fixtures written to fail, by how their tests use them (see `applies`)
_MEANT_TO_FAIL: dict[str, str] = {}


def applies(entry: Entry) -> bool:
    """False for the programs kept because they did not compile (a model's attempts) and
    the fixtures a test expects an error of."""
    if entry.kind in ("model_runs", "maker_runs"):
        return not _ATTEMPT.search(entry.name)
    if entry.kind == "tests":
        if entry.name in _MEANT_TO_FAIL:
            return False
        first = entry.source.split("\n", 1)[0]
        m = _EXPECT.match(first)
        return m is None or m.group(1) == "ok" or m.group(1).startswith("W")
    return True


def check(entry: Entry) -> list[str]:
    """One line per error diagnostic of ``entry``'s compile: ``E0101 3:5 message``."""
    res = compiled(entry)
    out = []
    for d in res.diagnostics:
        if d.severity == "error":
            where = f"{d.span.line}:{d.span.col}" if d.span is not None else "-"
            out.append(f"{d.code} {where} {d.message}")
    if not out and not res.ok:
        out.append("not ok, with no error diagnostic")
    return out
