"""The most basic promise, and the runner's own law: every program the project ships compiles
without an error (``aidl check`` exit 0; warnings allowed).

Applies to the examples, the gallery (defaults, slider ends, bools flipped), the standard
library's templates, the ``aidl docs`` examples and the docs' ```aidl blocks, the model
and maker runs' programs that were kept as compiling (final, first valid, a maker's edit), and
the test fixtures: every program but those the project keeps because they give an error
(:func:`benchmarks.laws.corpus.meant_to_fail`: a model's attempts, ``tests/programs/hostile/``
files whose first line expects an error, docs blocks marked ``<!-- expect: E.... -->``).
"""
from __future__ import annotations

from .corpus import Entry, compiled, gallery_combinations, meant_to_fail

NAME = "every program in the corpus that the project ships compiles without error"
TOLERANCE = ("none: no diagnostic of severity error (warnings and notes are other laws' "
             "business), no exception from the compiler")


def applies(entry: Entry) -> bool:
    """False for the programs the project keeps because they give an error
    (:func:`benchmarks.laws.corpus.meant_to_fail`)."""
    return not meant_to_fail(entry)


def generated(n: int):
    """``n`` of the gallery's designs with all their sliders at seeded random steps, settled
    as the studio's form settles them (:func:`benchmarks.laws.corpus.gallery_combinations`):
    what a visitor can reach, which compiles too (docs/studio.md, "Forms that cannot
    fail")."""
    return gallery_combinations(n)


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
