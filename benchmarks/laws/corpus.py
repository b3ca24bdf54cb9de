"""The corpus of the laws (issue 109): every program the project has, each once.

:func:`iter_corpus` yields one :class:`Entry` per program, in a stable order and under a
stable, unique name, by kind:

* ``examples``: every ``examples/**/*.aidl`` (the top-level examples, ``generators/``,
  ``parts/``), as the files are (``examples/gear.aidl``);
* ``gallery``: every design of the studio's gallery (:mod:`aidl_lang.studio.gallery`: the
  examples and the standard-library generators, as the page shows them, self-contained) at
  its defaults (``gallery/example/telephone``), at each numeric param's slider ends, one
  param at a time, the others at their defaults (``gallery/generator/washer@outer=2.5mm``;
  the ends as ``benchmarks/checks/slider_extremes.py`` takes them: the ``min`` and the last
  step from it below the ``max``), and with each bool param flipped
  (``gallery/generator/tool_holder@outside=false``);
* ``stdlib``: every template (``def``) of ``stdlib/*.aidl`` at its defaults, in the small
  program ``aidl docs NAME`` shows (a solid, a plate it cuts into, an assembly:
  ``aidl_lang.library.reference``), named ``stdlib/boxes.aidl#finger_box``;
* ``docs``: the example program of every other ``aidl docs`` topic (shapes, constraints,
  operations, statements), named ``docs/topic/Circle``, and every ```aidl block of
  README.md, docs/*.md and docs/dev/*.md as tests/test_docs.py compiles it (blank lines in
  front, so lines are the file's), named by file and line (``docs/language.md:120``);
* ``model_runs``, ``maker_runs``: every ``data/model_runs/**/*.aidl`` and
  ``data/maker_runs/**/*.aidl`` (first valid and final programs, attempts, edits), named
  by their path under ``data/`` (``model_runs/issue105/run/02_jar_lid.aidl``);
* ``tests``: every ``tests/**/*.aidl`` fixture (``tests/programs/hostile/nan_radius.aidl``).

Some programs are kept *because* they give an error (a model's attempts, the hostile test
fixtures, a docs block marked with the error it shows): :func:`meant_to_fail` says which and
why; a law that needs a compiling program treats them as not applicable.

A law adds its own generated programs (kind ``generated``) through its module's
``generated(n)``; the runner (:mod:`benchmarks.laws.run`) asks for them, not this module.

Identical programs are counted once: an entry whose source, overrides and (when the program
reads a file beside it) folder equal an earlier one's is left out, the earlier (in the order
above) kept.  Building the list reads every file and the gallery (about 3 s of CPU; cached
per process).
"""
from __future__ import annotations

import functools
import math
import re
import textwrap
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Iterator

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "data"
KINDS = ("examples", "gallery", "stdlib", "docs", "model_runs", "maker_runs", "tests",
         "generated")
NUMERIC = ("length", "angle", "number", "integer")     # the gallery's slider kinds
# a program that reads a file beside it: a relative import (not std/) or a drawing
_READS_BESIDE = re.compile(r'import\s+"(?!std/)|Drawing2D\s*\(')


@dataclass(frozen=True)
class Entry:
    """One program of the corpus.

    ``name``: stable and unique (``examples/gear.aidl``,
    ``gallery/example/telephone@base_w=320mm``); ``source``: the program text; ``path``: a
    real file for it (give it as ``path=`` to :func:`aidl_lang.compile`: imports and drawings
    are read beside it; never write there); ``overrides``: param values as ``aidl --set``
    takes them (``{"base_w": "320 mm"}``, maybe empty); ``kind``: one of :data:`KINDS`."""

    name: str
    source: str
    path: str
    overrides: dict[str, str] = field(default_factory=dict)
    kind: str = "examples"

    def __hash__(self) -> int:                    # the dict field is not hashable
        return hash((self.name, self.source))


def compile_entry(entry: Entry, **kw):
    """``entry`` compiled by :func:`aidl_lang.compile` (source, path, overrides; ``kw`` as
    ``compile`` takes them): the :class:`aidl_lang.api.Result`."""
    from aidl_lang import api
    return api.compile(source=entry.source, path=entry.path,
                       overrides=dict(entry.overrides) or None, **kw)


@functools.lru_cache(maxsize=1)
def compiled(entry: Entry):
    """:func:`compile_entry` of ``entry`` with the default arguments, kept for the next call
    with the same entry (the runner checks each program's laws one after another: they share
    this compile).  Do not change the result."""
    return compile_entry(entry)


# ------------------------------------------------------------------------ the kinds
def _files(folder: Path, under: Path, prefix: str, kind: str) -> Iterator[Entry]:
    for p in sorted(folder.rglob("*.aidl")):
        if p.is_file():
            name = prefix + p.relative_to(under).as_posix()
            yield Entry(name, p.read_text(encoding="utf-8"), str(p), {}, kind)


def _examples() -> Iterator[Entry]:
    yield from _files(ROOT / "examples", ROOT, "", "examples")


def _value_text(p: dict, x) -> str:
    """A form value as ``aidl --set`` takes it: ``"27.5 mm"``, ``"30 deg"``, ``"4"``,
    ``"false"`` (the gallery's display units: lengths in mm, angles in degrees)."""
    if isinstance(x, bool):
        return "true" if x else "false"
    return f"{x:.12g} {p['unit']}".strip()


def slider_ends(p: dict) -> list[tuple[str, float]]:
    """``[("min", x), ("max", x)]`` of a numeric form row (:func:`gallery.param_rows`): its
    ``min`` and the last of its steps from the ``min`` not above its ``max`` (what the slider
    reaches); ``[]`` without a range."""
    lo, hi, step = p.get("min"), p.get("max"), p.get("step")
    if lo is None or hi is None:
        return []
    top = hi if not step else lo + math.floor((hi - lo) / step + 1e-9) * step
    if p["kind"] == "integer":
        lo, top = int(round(lo)), int(round(top))
    return [("min", lo), ("max", top)]


def _gallery() -> Iterator[Entry]:
    from aidl_lang.studio import gallery
    for e in gallery.entries():
        origin = e.origin
        path = (ROOT / "stdlib" / origin[4:]) if origin.startswith("std/") else ROOT / origin
        base = f"gallery/{e.id}"
        yield Entry(base, e.source, str(path), {}, "gallery")
        ruling = _ruling(e.source)
        for p in e.params:
            if p["kind"] in NUMERIC:
                ends = [x for _, x in slider_ends(p)]
            elif p["kind"] == "bool" and isinstance(p["default"], bool):
                ends = [not p["default"]]
            else:
                continue
            for x in dict.fromkeys(ends):
                if x == p["default"] and not isinstance(x, bool):
                    continue
                text = _value_text(p, x)
                name = f"{base}@{p['name']}={text.replace(' ', '')}"
                if p["name"] in ruling:
                    _TO_SETTLE[name] = p["name"]
                yield Entry(name, e.source, str(path), {p["name"]: text}, "gallery")


# gallery entries whose moved param bounds another's range: name -> the moved param
_TO_SETTLE: dict[str, str] = {}


def _ruling(source: str) -> set[str]:
    """The params of ``source`` named in another param's ``min=``/``max=``/``step=``."""
    from aidl_lang import ast as A
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.parser import parse
    decls = [st for st in parse(source, "main.aidl", DiagnosticSink()).stmts
             if isinstance(st, A.ParamDecl)]
    names = {st.name for st in decls}
    lines = source.splitlines()
    out = set()
    for st in decls:
        for o in st.options:
            text = lines[o.span.line - 1][o.span.col - 1:] if o.span else ""
            out |= {n for n in names - {st.name} if re.search(rf"\b{n}\b", text)}
    return out


@functools.lru_cache(maxsize=8)
def _checked(source: str, path: str):
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.parser import parse
    from aidl_lang.typecheck import check
    sink = DiagnosticSink()
    program = parse(source, path, sink)
    check(program, sink)
    return program, sink.has_errors


def settled(entry: Entry, moved: str | None = None) -> Entry:
    """``entry`` (a gallery slider end of param ``moved``) with the other params whose ranges
    follow ``moved`` moved back into them, as the studio's form does ("Forms that cannot
    fail", docs/studio.md: :func:`aidl_lang.studio.compiler.settle` and ``into_range``, at
    most ``MAX_CLAMPS`` times), judged by interpreting the program (its params and ranges;
    no solve); ``moved`` itself stays.  The entry as it was when nothing needs moving or
    nothing helps.  ``moved=None``: any value may move."""
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.interp import Interpreter
    from aidl_lang.pipeline import run_deep
    from aidl_lang.serve.params import _param
    from aidl_lang.studio.compiler import MAX_CLAMPS, into_range
    from aidl_lang import ast as A
    program, bad = _checked(entry.source, entry.path)
    if bad:
        return entry
    decls = [st for st in program.stmts if isinstance(st, A.ParamDecl)]
    values = dict(entry.overrides)
    for _ in range(MAX_CLAMPS + 1):
        sink = DiagnosticSink()
        interp = Interpreter(sink, dict(values))
        try:
            run_deep(lambda: interp.run(program))
        except Exception:           # noqa: BLE001 - the laws will meet it in the compile
            return entry
        if not sink.has_errors:
            break
        fctx = interp.file
        if fctx is None:
            return entry
        ranges = getattr(fctx, "param_ranges", {})
        rows = [r.to_json() for r in (_param(st.name, fctx.params.get(st.name),
                                             ranges.get(st.name), st.span.line) for st in decls)
                if r is not None]
        fixed = into_range(rows) or into_range(rows, grid=True)
        fixed.pop(moved, None)
        if not fixed:
            return entry
        values.update({k: t for k, (t, _) in fixed.items()})
    else:
        return entry
    return Entry(entry.name, entry.source, entry.path, values, entry.kind)


def _stdlib() -> Iterator[Entry]:
    from aidl_lang.library.reference import stdlib_templates, topics
    tp = topics()
    for name, t in stdlib_templates().items():
        topic = tp.get(name)
        if topic is not None and topic.example:
            path = ROOT / "aidl_lang" / "library" / "reference.py"   # where it is written
            yield Entry(f"stdlib/{t.module}.aidl#{name}", topic.example, str(path), {},
                        "stdlib")


def _docs() -> Iterator[Entry]:
    from aidl_lang.library.reference import stdlib_templates, topics
    templates = stdlib_templates()
    path = ROOT / "aidl_lang" / "library" / "topic_examples.py"
    for name, topic in sorted(topics().items()):
        if name not in templates and topic.example:
            yield Entry(f"docs/topic/{name}", topic.example, str(path), {}, "docs")
    for md in [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")),
               *sorted((ROOT / "docs" / "dev").glob("*.md"))]:
        for line, source, _ in aidl_blocks(md):
            name = f"{md.relative_to(ROOT).as_posix()}:{line}"
            # blank lines in front: the diagnostics' lines are the Markdown file's
            yield Entry(name, "\n" * (line - 1) + source, str(md), {}, "docs")


_MARKER = re.compile(r"<!--\s*expect:\s*(.*?)\s*-->")
_CODE = re.compile(r"\b[EW]\d{4}\b")


@functools.lru_cache(maxsize=64)
def aidl_blocks(md: Path) -> list[tuple[int, str, frozenset[str]]]:
    """The ```aidl blocks of a Markdown file as tests/test_docs.py reads them: ``(line of the
    first code line, the dedented code, the codes of the <!-- expect: ... --> marker on the
    last non-blank line before the fence)``."""
    lines = md.read_text(encoding="utf-8").split("\n")
    out, i = [], 0
    while i < len(lines):
        if lines[i].strip() == "```aidl":
            j = next((j for j in range(i + 1, len(lines)) if lines[j].strip() == "```"),
                     len(lines))
            k = next((k for k in range(i - 1, -1, -1) if lines[k].strip()), -1)
            m = _MARKER.search(lines[k]) if k >= 0 else None
            out.append((i + 2, textwrap.dedent("\n".join(lines[i + 1:j])) + "\n",
                        frozenset(_CODE.findall(m[1])) if m else frozenset()))
            i = j
        i += 1
    return out


# programs kept in data/ as a model first wrote them, with the error their README reports
KEPT_WITH_ERRORS = {
    "model_runs/issue73/programs/e04_cable_organiser.aidl":
        "its first result, E0108 fixed by its hint in issue73/fixed/ (issue73/README.md)",
    "model_runs/issue111ca/run/02_cookie_stamp.first_valid.aidl":
        "its first valid program flipped a drawing with Text, which came out upside down: "
        "E0108 since (a mirror image cannot hold Text); its draft writes the word as a stencil",
}
_ATTEMPT = re.compile(r"\.(attempt|check)\d+\.aidl$|/(tries|drafts|probes)/")
_HOSTILE_EXPECT = re.compile(r"#\s*expect:\s*(ok|[EW]\d{4})")


def meant_to_fail(entry: Entry) -> str:
    """Why the project keeps ``entry`` although it is expected to give an error, or ``""``:
    a model's attempts on its way to a valid program (``*.attemptN.aidl``,
    ``*.checkN.aidl``, ``tries/``, ``drafts/``, ``probes/`` of data/), a program kept with
    the error its run reports (:data:`KEPT_WITH_ERRORS`), a test fixture whose first line
    expects an error (``# expect: E0123``, tests/test_hostile.py), a docs block marked
    ``<!-- expect: E0123 -->`` (tests/test_docs.py)."""
    if entry.kind in ("model_runs", "maker_runs"):
        if _ATTEMPT.search(entry.name):
            return "a model's attempt, kept on its way to a valid program"
        return KEPT_WITH_ERRORS.get(entry.name, "")
    if entry.kind == "tests":
        m = _HOSTILE_EXPECT.match(entry.source.split("\n", 1)[0])
        if m and m[1].startswith("E"):
            return f"its first line expects {m[1]} (tests/test_hostile.py)"
    if entry.kind == "docs" and entry.path.endswith(".md"):
        line = int(entry.name.rsplit(":", 1)[1])
        expect = next((x for n, _, x in aidl_blocks(Path(entry.path)) if n == line), ())
        errors = sorted(c for c in expect if c.startswith("E"))
        if errors:
            return f"marked <!-- expect: {' '.join(errors)} --> (tests/test_docs.py)"
    return ""


def _data(kind: str) -> Iterator[Entry]:
    yield from _files(DATA / kind, DATA, "", kind)


def _tests() -> Iterator[Entry]:
    yield from _files(ROOT / "tests", ROOT, "", "tests")


_SOURCES = {"examples": _examples, "gallery": _gallery, "stdlib": _stdlib, "docs": _docs,
            "model_runs": lambda: _data("model_runs"),
            "maker_runs": lambda: _data("maker_runs"), "tests": _tests}


def gallery_combinations(n: int, seed: int = 109) -> Iterator[Entry]:
    """``n`` programs of kind ``generated``: the gallery's designs in turn, each with every
    numeric slider at a step of its range and every bool drawn by ``random.Random(seed)``
    (the same programs every run), settled as the studio's form settles them
    (:func:`settled`, any value may move), named
    ``generated/gallery/007:generator/washer``."""
    import random
    from aidl_lang.studio import gallery
    rng = random.Random(seed)
    designs = [e for e in gallery.entries() if any(
        p["kind"] in NUMERIC or p["kind"] == "bool" for p in e.params)]
    for i in range(n):
        e = designs[i % len(designs)]
        values = {}
        for p in e.params:
            if p["kind"] == "bool" and isinstance(p["default"], bool):
                values[p["name"]] = _value_text(p, rng.random() < 0.5)
            elif p["kind"] in NUMERIC and slider_ends(p):
                (_, lo), (_, hi) = slider_ends(p)
                step = p.get("step") or (hi - lo) / 100 or 1
                k = rng.randint(0, max(0, int(round((hi - lo) / step))))
                x = min(hi, lo + k * step)
                values[p["name"]] = _value_text(p, int(round(x)) if p["kind"] == "integer"
                                                else round(x, 9))
        origin = e.origin
        path = (ROOT / "stdlib" / origin[4:]) if origin.startswith("std/") else ROOT / origin
        yield settled(Entry(f"generated/gallery/{i:03d}:{e.id}", e.source, str(path), values,
                            "generated"))


def _key(e: Entry) -> tuple:
    beside = str(Path(e.path).parent) if _READS_BESIDE.search(e.source) else ""
    return (e.source, tuple(sorted(e.overrides.items())), beside)


@functools.cache
def _all(kinds: tuple[str, ...]) -> tuple[Entry, ...]:
    out, seen, names = [], set(), set()
    for k in kinds:
        for e in _SOURCES[k]():
            key = _key(e)
            if key in seen:
                continue
            if e.name in names:
                raise RuntimeError(f"corpus name twice: {e.name}")
            seen.add(key)
            names.add(e.name)
            out.append(e)
    return tuple(out)


def spread(entries: list, k: int, kind=lambda e: e.kind) -> list:
    """``k`` of ``entries`` spread over them, deterministically: each kind gets a share in
    proportion to its count (at least one while ``k`` allows), taken evenly spaced through
    it (every n-th); the chosen keep their order.  ``k`` at least ``len(entries)``: all."""
    if k >= len(entries):
        return list(entries)
    if k <= 0:
        return []
    groups: dict[str, list[int]] = {}
    for i, e in enumerate(entries):
        groups.setdefault(kind(e), []).append(i)
    quota = {g: 0 for g in groups}
    for g in sorted(groups, key=lambda g: -len(groups[g]))[:k]:
        quota[g] = 1                                  # one of each kind, the largest first
    left = k - sum(quota.values())
    if left > 0:
        n = len(entries)
        share = {g: left * len(ix) / n for g, ix in groups.items()}
        for g in groups:
            quota[g] += int(share[g])
        rest = k - sum(quota.values())
        for g in sorted(groups, key=lambda g: (-(share[g] - int(share[g])), g))[:rest]:
            quota[g] += 1
    chosen = []
    for g, ix in groups.items():
        q = min(quota[g], len(ix))
        chosen += [ix[(j * len(ix)) // q] for j in range(q)]
    return [entries[i] for i in sorted(chosen)]


def iter_corpus(sample: int | None = None,
                kinds: Iterable[str] | None = None) -> Iterator[Entry]:
    """Every program of the corpus (the kinds of :data:`KINDS` but ``generated``, or those of
    ``kinds``), each once, in a stable order.  ``sample=k``: ``k`` of them spread over the
    kinds (:func:`spread`), the same ``k`` every run.  Raises ``ValueError`` for an unknown
    kind."""
    wanted = tuple(k for k in KINDS if k != "generated" and (kinds is None or k in set(kinds)))
    unknown = set(kinds or ()) - set(KINDS)
    if unknown:
        raise ValueError(f"unknown corpus kinds: {sorted(unknown)} (known: {', '.join(KINDS)})")
    entries = list(_all(wanted))
    for e in (entries if sample is None else spread(entries, sample)):
        moved = _TO_SETTLE.get(e.name)
        yield e if moved is None else settled(e, moved)


def names(kinds: Iterable[str] | None = None) -> list[str]:
    """The names of :func:`iter_corpus`'s entries, in its order, without settling any (cheap:
    the list is built once per process)."""
    wanted = tuple(k for k in KINDS if k != "generated" and (kinds is None or k in set(kinds)))
    return [e.name for e in _all(wanted)]


def counts(entries: Iterable[Entry]) -> dict[str, int]:
    """How many entries of each kind, in :data:`KINDS` order."""
    n: dict[str, int] = {}
    for e in entries:
        n[e.kind] = n.get(e.kind, 0) + 1
    return {k: n[k] for k in KINDS if k in n}
