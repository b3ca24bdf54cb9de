"""The gallery of ``aidl studio``: every example program and every standard-library generator
as an :class:`Entry` the studio lists, opens (its source) and shows as a form (its params).

Where the entries come from (all read once, :func:`entries` is cached):

* ``example/NAME``: every top-level ``examples/*.aidl`` (kind ``"example"``);
* ``generator/NAME``: every ``examples/generators/*.aidl`` (kind ``"generator"``), and every
  renderable standard-library generator that has no example file of its own, for which a
  program is *synthesized* (``synthesized=True``): ``units mm``, the ``import`` of its
  module, one ``param`` per documented argument (with its default and a slider range,
  ``min=``/``max=``/``step=``) and ``NAME = generator(arg=arg, ...)`` in a structure of the
  generator's kind.  A generator is *renderable* when its ``def`` returns a ``solid``,
  ``assembly`` or ``drawing``; one that returns a ``hole`` only cuts into a solid and is left
  out (:func:`skipped` names them), as are names starting with ``_`` and undocumented ones.

Every entry's ``source`` is a single self-contained program: it compiles in an empty folder
(``compile_entry``).  To get there the gallery rewrites, in its copy only (the files are not
touched):

* ``import "parts/x.aidl"`` (a file beside the example) is replaced by that file's text;
* ``Drawing2D("parts/x.svg")`` reads the byte-identical sample that ships with the standard
  library, ``std/drawings/x.svg``;
* a top-level ``param`` of an example that counts things (a whole number of at least 1,
  no range declared) gets ``min = 1``: its slider does not offer 0 (:func:`counts_from_one`);
* an ``examples/generators`` file with a form of the same name in ``studio/forms/`` is
  shown as that form: the same call, its arguments as params whose ranges depend on each
  other (the planetary's ring is sun + 2 x planet; a tool holder is as deep as its rows of
  holes need), written by hand where the generator's checks tie several arguments together;
* an ``examples/generators`` file that declares no ``param`` and calls one stdlib generator
  has that call's literal arguments lifted into ``param`` declarations (the example's values
  as defaults, the generator's own defaults for the arguments it leaves out), so its form has
  sliders too; a top-level ``thickness`` equal to the lifted ``thickness`` follows the param.
  Files that call several generators (the joint demonstrations) are kept as they are.

Units: ``params`` are in display units, as :mod:`aidl_lang.serve.params` gives them: lengths
in mm, angles in degrees, numbers plain.  :func:`thumbnail` returns an SVG whose user units
are millimetres, sized in pixels.

The examples are read from ``aidl_lang/examples`` (:data:`aidl_lang.library.sources.EXAMPLES`: a
link to the repository's ``examples/`` folder in a checkout, a copy inside the wheel) and the generators from the
bundled standard library.  Not part of the stable API.
"""
from __future__ import annotations

import functools
import math
import os
import re
import tempfile
import textwrap
from dataclasses import asdict, dataclass, field
from pathlib import Path

from .. import ast as A
from ..library.sources import EXAMPLES     # aidl_lang/examples: shipped in the wheel
from .wording import page_program

KINDS = ("example", "generator")
# the gallery's own programs of some examples/generators files (same name): their arguments
# as params whose ranges follow each other (``min = rows * (hole + 4 mm) + ...``), where the
# generator's checks tie several arguments together and a lifted form would offer values
# that fail
FORMS = Path(__file__).resolve().parent / "forms"
RENDERABLE = ("solid", "assembly", "drawing")

# the tag of a generator's stdlib module
MODULE_TAGS = {"boxes": "box", "enclosures": "enclosure", "fasteners": "fastener",
               "gears": "gear", "joints": "joint", "plates": "plate", "shapes": "shape",
               "stands": "stand"}
# further tags, from the words of an entry's file (or generator) name
WORD_TAGS = {"box": r"\bbox\b|\btray\b|\bdrawer\b", "gear": r"\bgears?\b|\bpinion\b|\bplanetary\b",
             "stand": r"\bstand\b|\bshelf\b|\bholder\b", "enclosure": r"\benclosure\b",
             "plate": r"\bplate\b|\bwasher\b|\brounded tab\b",
             "joint": r"\bhalving\b|\bdovetail\b|\bfinger\b|\bslot\b",
             "tool": r"\bwrench\b|\bruler\b|\bprotractor\b|\bopener\b|\bkey\b"}
ACRONYMS = {"pcb": "PCB", "usb": "USB"}
PURPOSE_MAX = 120
# arguments that only place an instance, or that a template takes for another's use
# (spur_gear's `addendum`: ring_gear's deeper spaces; a whole module more comes to points):
# never params of a synthesized program
PLACEMENT_ARGS = ("cx", "cy", "addendum")


@dataclass
class Entry:
    """One program of the gallery.

    ``id``: ``"example/telephone"``, ``"generator/divider_tray"`` (unique, URL-safe:
    ``[a-z0-9_/-]``); ``title``: ``"Divider tray"``; ``purpose``: one sentence, at most 120
    characters, from the program's leading comment (plain text, no backticks); ``kind``:
    ``"example"`` or ``"generator"``; ``source``: the program text, self-contained (see the
    module's docstring); ``params``: one dict per top-level ``param`` (:func:`param_rows`);
    ``tags``: short words to filter by (``"box"``, ``"gear"``, ...); ``origin``: where it
    comes from (``"examples/telephone.aidl"``, ``"std/boxes.aidl"``); ``generator``: the
    stdlib generator it shows (``""`` for an example that shows none); ``synthesized``: the
    program was written by the gallery (no example file)."""

    id: str
    title: str
    purpose: str
    kind: str
    source: str
    params: list[dict] = field(default_factory=list)
    tags: list[str] = field(default_factory=list)
    origin: str = ""
    generator: str = ""
    synthesized: bool = False


# ------------------------------------------------------------------------ public API
@functools.cache
def _all() -> tuple[Entry, ...]:
    out = [_example_entry(p) for p in sorted(EXAMPLES.glob("*.aidl"))]
    gens = [_generator_example_entry(p) for p in sorted((EXAMPLES / "generators").glob("*.aidl"))]
    covered = {e.generator for e in out + gens if e.generator}
    for t in renderable_generators().values():
        if t.name not in covered:
            gens.append(_synthesized_entry(t))
    out += sorted(gens, key=lambda e: e.id)
    ids = [e.id for e in out]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise RuntimeError(f"gallery ids are not unique: {sorted(dup)}")
    return tuple(out)


def entries() -> list[Entry]:
    """Every entry of the gallery: the examples (by file name), then the generators (by
    name).  Built once per process (about a second: each program is parsed and interpreted
    once for its params); the list is new on each call, the entries are shared (do not
    change them).  Raises :class:`RuntimeError` if two entries would get the same id."""
    return list(_all())


@functools.cache
def _index() -> dict[str, Entry]:
    return {e.id: e for e in _all()}


def entry(id: str) -> Entry | None:
    """The entry of ``id`` (``"generator/divider_tray"``), or ``None``."""
    return _index().get(id)


def to_json(entry: Entry, with_source: bool = True) -> dict:
    """The entry as a JSON-ready dict: every field of :class:`Entry`; ``source`` only when
    ``with_source`` (leave it out of a listing)."""
    d = asdict(entry)
    if not with_source:
        del d["source"]
    return d


def compile_entry(entry: Entry, overrides: dict | None = None):
    """Compile the entry's program as the studio does, in a fresh empty folder (it imports
    nothing but the standard library).  ``overrides``: param values as ``aidl render --set``
    takes them (``{"rows": "4"}``; bare numbers in the program's units).  Returns the
    :class:`aidl_lang.api.Result` (``ok`` False with diagnostics for an error; never
    raises for a mistake in the program)."""
    from .. import api
    with tempfile.TemporaryDirectory(prefix="aidl-gallery-") as d:
        return api.compile(source=entry.source, path=os.path.join(d, "main.aidl"),
                           overrides=overrides)


def thumbnail(entry: Entry, size: int = 240) -> str:
    """A small SVG of the entry's default render (the designed shape, no kerf): the page of
    :meth:`aidl_lang.api.Result.to_svg` (user units: mm) shown at most ``size`` x ``size``
    pixels (``width``/``height`` in px, aspect kept), coordinates rounded to 0.01 mm.
    Compiles the program each time (about 0.01 to 0.3 s): the caller keeps it
    (:func:`keep_thumbnail`, :func:`kept_thumbnail`).  Raises
    :class:`ValueError` naming the first error when the program does not compile."""
    r = compile_entry(entry)
    if not r.ok:
        first = r.errors[0] if r.errors else None
        why = f"{first.code} {first.message}" if first else "it did not solve"
        raise ValueError(f"{entry.id} does not compile: {why}")
    svg = r.to_svg(kerf=0)
    m = re.search(r'viewBox="([-\d.e]+),([-\d.e]+),([-\d.e]+),([-\d.e]+)"', svg)
    if m:
        w, h = float(m.group(3)), float(m.group(4))
        k = size / max(w, h, 1e-9)
        px_w, px_h = max(1, round(w * k)), max(1, round(h * k))
        svg = re.sub(r'(<svg\b[^>]*?)\bheight="[^"]*"', rf'\1height="{px_h}px"', svg, count=1)
        svg = re.sub(r'(<svg\b[^>]*?)\bwidth="[^"]*"', rf'\1width="{px_w}px"', svg, count=1)
    return re.sub(r"(\d\.\d\d)\d+", r"\1", svg)


THUMBS = "gallery"          # the thumbnails' folder in the user's cache (aidl_lang.host.cache)


@functools.cache
def code_fingerprint() -> str:
    """A digest of this installation of ``aidl_lang``: its version and the name, size and
    modification time of every file of the package (code, grammar, standard library,
    drawings), so a picture kept by one build is never shown by another (a checkout edited
    without a new version number included)."""
    import hashlib
    from importlib.metadata import PackageNotFoundError, version
    try:
        v = version("aidl-lang")
    except PackageNotFoundError:
        v = "unknown"
    root = Path(__file__).resolve().parent.parent
    h = hashlib.sha256(v.encode())
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d != "__pycache__")
        for f in sorted(files):
            try:
                st = os.stat(os.path.join(folder, f))
            except OSError:
                continue
            h.update(f"{os.path.relpath(os.path.join(folder, f), root)}\0{st.st_size}\0"
                     f"{st.st_mtime_ns}\n".encode())
    return h.hexdigest()


def thumbnail_key(entry: Entry, size: int = 240) -> str:
    """What a kept thumbnail of ``entry`` is filed under: a digest of the program's text,
    the picture's ``size`` and :func:`code_fingerprint`."""
    import hashlib
    text = f"{code_fingerprint()}\0{size}\0{entry.source}"
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _thumb_path(key: str, suffix: str = ".svg") -> Path | None:
    """Where the user's cache keeps what is filed under ``key`` (a thumbnail; with ``suffix``,
    a gallery design's whole sweep: :mod:`.ahead`), or None without a cache."""
    from ..host.cache import cache_dir
    base = cache_dir()
    if base is None:
        return None
    folder = base / THUMBS
    try:
        folder.mkdir(mode=0o700, exist_ok=True)
    except OSError:
        return None
    return folder / f"{key[:32]}{suffix}"


def kept_thumbnail(entry: Entry, size: int = 240) -> str | None:
    """The thumbnail of ``entry`` made before (by this or another server, this build, the
    same program text: :func:`thumbnail_key`) and kept in the user's cache
    (``~/.cache/aidl/gallery``, :mod:`aidl_lang.host.cache`: checked, this user's own), or None."""
    from ..host.cache import read_checked
    key = thumbnail_key(entry, size)
    path = _thumb_path(key)
    return read_checked(path, key) if path is not None else None


def keep_thumbnail(entry: Entry, svg: str, size: int = 240) -> bool:
    """Keep ``svg`` as ``entry``'s thumbnail for :func:`kept_thumbnail`; False when the
    cache cannot be written (the picture is then only kept in memory)."""
    from ..host.cache import write_checked
    key = thumbnail_key(entry, size)
    path = _thumb_path(key)
    return path is not None and write_checked(path, key, svg)


@functools.cache
def renderable_generators() -> dict:
    """The standard library's generators the gallery shows, by name: documented ``def``\\ s
    whose name does not start with ``_`` and whose result is a solid, an assembly or a
    drawing (:class:`aidl_lang.library.reference.StdTemplate` values)."""
    from ..library.reference import stdlib_templates
    return {n: t for n, t in stdlib_templates().items()
            if not n.startswith("_") and t.doc and t.node.kind in RENDERABLE}


def skipped() -> dict[str, str]:
    """The stdlib ``def``\\ s the gallery leaves out, each with the reason."""
    from ..library.reference import stdlib_templates
    out = {}
    for n, t in stdlib_templates().items():
        if n.startswith("_"):
            out[n] = "private helper (name starts with `_`)"
        elif not t.doc:
            out[n] = "undocumented"
        elif t.node.kind not in RENDERABLE:
            out[n] = f"returns a {t.node.kind}: it cuts into a solid, it renders nothing alone"
    return out


# ------------------------------------------------------------------------ params
def param_rows(source: str, path: str = "main.aidl") -> list[dict]:
    """The form rows of a program: one dict per top-level ``param`` from
    :func:`aidl_lang.serve.params.declared_params` with ``name``, ``kind`` (``length`` (mm),
    ``angle`` (deg), ``integer`` (a number param whose default, range and step are whole:
    a count), ``number``, ``bool`` or ``string``), ``unit`` (``"mm"``, ``"deg"`` or ``""``),
    ``default``, ``min``, ``max``, ``step`` (``None`` for bool and string), ``declared``
    (the range is written in the program) and ``help`` (the comment at the end of the
    ``param`` line, or ``""``).  ``[]`` when the program does not parse or interpret."""
    from ..serve.params import declared_params
    from ..base.diagnostics import split_lines     # lines as the compiler counts them (not at U+2028)
    params = declared_params(source, path) or []
    lines = split_lines(source)
    rows = []
    for p in params:
        kind = p.kind
        vals = {"default": p.default, "min": p.min, "max": p.max, "step": p.step}
        if kind == "number" and all(isinstance(v, (int, float)) and float(v).is_integer()
                                    for v in vals.values()):
            kind = "integer"
            vals = {k: int(v) for k, v in vals.items()}
        line = lines[p.line - 1] if 0 < p.line <= len(lines) else ""
        rows.append({"name": p.name, "kind": kind, "unit": p.unit, **vals,
                     "declared": p.declared, "help": _trailing_comment(line)})
    return rows


def _trailing_comment(line: str) -> str:
    """The ``# comment`` at the end of a line, outside string literals."""
    quote = False
    for i, ch in enumerate(line):
        if ch == '"':
            quote = not quote
        elif ch == "#" and not quote:
            return line[i + 1:].strip()
    return ""


def _nice(x: float) -> float:
    """The 1-2-5 step not above ``x`` (0.05 at least)."""
    if x <= 0.05:
        return 0.05
    e = math.floor(math.log10(x))
    for m in (5, 2, 1):
        if m * 10 ** e <= x + 1e-12:
            return m * 10 ** e
    return 10 ** e


def assert_bounds(template) -> dict[str, tuple[float | None, float | None]]:
    """What a generator's own top-level ``assert``\\ s say about its arguments one at a
    time (``assert angle > 30 deg and angle < 85 deg``, ``width >= 60 mm``): ``{name: (lo,
    hi)}`` in display units (mm, deg), a strict bound moved in by a hair (1e-6)."""
    out: dict[str, list] = {}
    names = {p.name for p in template.node.params}

    def comparisons(e):
        if isinstance(e, A.BoolOp) and e.op == "and":
            yield from comparisons(e.left)
            yield from comparisons(e.right)
        elif isinstance(e, A.Compare) and len(e.ops) == 1:
            yield e

    flip = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}
    for st in template.node.body.stmts:
        if not isinstance(st, A.Assert):
            continue
        for c in comparisons(st.expr):
            a, b, op = c.operands[0], c.operands[1], c.ops[0]
            if isinstance(b, A.Name) and not isinstance(a, A.Name):
                a, b, op = b, a, flip.get(op, op)
            lit = _literal(b) if isinstance(a, A.Name) and a.id in names else None
            if lit is None or lit[1] is None or op not in flip:
                continue
            v = lit[1] + {"<": -1e-6, ">": 1e-6}.get(op, 0.0)
            lo, hi = out.setdefault(a.id, [None, None])
            if op in (">", ">="):
                out[a.id][0] = v if lo is None else max(lo, v)
            else:
                out[a.id][1] = v if hi is None else min(hi, v)
    return {k: (v[0], v[1]) for k, v in out.items()}


def assert_relations(template) -> dict[str, dict[str, list[tuple[str, bool]]]]:
    """How a generator's top-level ``assert``\\ s tie one argument to others
    (``assert length > width / 2``, ``radius <= min(width, length) / 2``): ``{name: {"min":
    [(expression text, strict)], "max": [...]}}``, the expression as written in the
    generator's file, over its other arguments only (no locals, no calls but ``min``,
    ``max``, ``abs``, ``sqrt``, ``square`` and the trigonometric ones; ``pi``: a spur gear's
    backlash bound where its teeth come to a point).  :func:`synthesize` and :func:`lift_params` make them the
    params' ``min=``/``max=`` (a range that follows the other params), declared after the
    params they use."""
    from ..library.sources import STDLIB
    try:
        text = (Path(STDLIB) / f"{template.module}.aidl").read_text(encoding="utf-8")
    except OSError:
        return {}
    names = {p.name for p in template.node.params}
    calls = {"min", "max", "abs", "sqrt", "square", "sin", "cos", "tan", "atan", "pi"}
    out: dict[str, dict[str, list]] = {}

    def comparisons(e):
        if isinstance(e, A.BoolOp) and e.op == "and":
            yield from comparisons(e.left)
            yield from comparisons(e.right)
        elif isinstance(e, A.Compare) and len(e.ops) == 1:
            yield e

    def over_arguments(e, own: str) -> bool:
        used = False
        for n in A.walk(e):
            if isinstance(n, A.Call):
                if not (isinstance(n.func, A.Name) and n.func.id in calls):
                    return False
            elif isinstance(n, A.Name):
                if n.id == own or (n.id not in names and n.id not in calls):
                    return False
                used = used or n.id in names
            elif not isinstance(n, (A.Num, A.BinOp, A.Neg, A.Ternary, A.Compare, A.BoolOp,
                                    A.Keyword)):
                return False
        return used

    flip = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}
    for st in template.node.body.stmts:
        if not isinstance(st, A.Assert):
            continue
        for c in comparisons(st.expr):
            a, b, op = c.operands[0], c.operands[1], c.ops[0]
            if isinstance(b, A.Name) and b.id in names and not isinstance(a, A.Name):
                a, b, op = b, a, flip.get(op, op)
            if not (isinstance(a, A.Name) and a.id in names and op in flip
                    and over_arguments(b, a.id)):
                continue
            side = "min" if op in (">", ">=") else "max"
            out.setdefault(a.id, {"min": [], "max": []})[side].append(
                (text[b.span.start:b.span.end], op in ("<", ">")))
    return out


def slider_range(name: str, kind: str, value: float,
                 bounds: tuple[float | None, float | None] = (None, None)
                 ) -> tuple[float, float, float]:
    """``(min, max, step)`` for a synthesized or lifted param ``name`` of ``kind`` (length mm,
    angle deg, number) whose default is ``value``; always ``min <= value <= max``.
    Thicknesses 1..12 mm; clearances and backlash 0..4x (at least 1 mm); a gear module
    0.5..6 mm; other lengths 0.25x..4x (0..20 mm for a default of 0); a pressure angle
    14.5..30 deg, a turn -180..180 deg, a slope 0.25x..2x (under 90 deg); gear teeth 8..4x;
    metric screw sizes 2..6 (each whole one an ISO size); other counts 1..12; a text's
    ``spacing`` (in character heights) 0.6..4x; other numbers 0.25x..4x; then narrowed to
    ``bounds`` (``(lo, hi)``, either None), what the generator asserts
    (:func:`assert_bounds`)."""
    v = float(value)
    if kind == "length":
        if name == "thickness" or name.endswith("_thickness"):
            lo, hi, step = 1.0, 12.0, 0.5
        elif "clearance" in name or "backlash" in name or "kerf" in name:
            lo, hi, step = 0.0, max(1.0, 4 * v), 0.05
        elif name == "module":
            lo, hi, step = 0.5, max(6.0, 2 * v), 0.25
        elif v == 0:
            lo, hi, step = 0.0, 20.0, 0.5
        else:
            step = _nice(abs(v) / 100)
            lo, hi = sorted((v / 4, v * 4))
    elif kind == "angle":
        step = 1.0
        if "pressure" in name:
            lo, hi, step = 14.5, 30.0, 0.5
        elif 0 < v < 90:
            lo, hi = max(1.0, v / 4), min(89.0, v * 2)
        else:
            lo, hi = (-180.0, 180.0) if v <= 180 else (0.0, 360.0)
    else:
        if float(v).is_integer():
            step = 1.0
            if "teeth" in name or name in ("sun", "planet", "ring"):
                lo, hi = 8.0, max(4 * v, 40.0)
            elif name in ("screw", "size"):
                # metric sizes (std/fasteners.aidl): a slider of whole steps offers only the
                # values the table has, M2 to M6 (M2.5 and M8 need `--set`; 7 is no size)
                lo, hi = 2.0, 6.0
            else:
                lo, hi = (1.0, max(12.0, v)) if v > 0 else (min(v, 0.0), 12.0)
        elif name == "spacing" and v > 0:
            # a spacing in character heights: under 0.6 a letter's advance, the letters are
            # drawn over each other (W0513)
            step = _nice(abs(v) / 100)
            lo, hi = max(0.6, v / 4), v * 4
        else:
            step = _nice(abs(v) / 100)
            lo, hi = sorted((v / 4, v * 4))
    lo = math.floor(round(lo / step, 6)) * step
    hi = math.ceil(round(hi / step, 6)) * step
    blo, bhi = bounds
    if blo is not None and lo < blo:
        lo = math.ceil(round(blo / step, 6)) * step
    if bhi is not None and hi > bhi:
        hi = math.floor(round(bhi / step, 6)) * step
    return min(lo, v), max(hi, v), step


def _num(v: float) -> str:
    """A number as AIDL source: ``3``, ``0.25``, ``-180``."""
    s = f"{round(v, 6):.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


_UNIT = {"length": "mm", "angle": "deg"}


def _param_decl(name: str, kind: str, text: str, value, bounds=(None, None),
                relations=None) -> str:
    """``param NAME = TEXT, min=.., max=.., step=..`` (the range for lengths, angles and
    numbers; ``value``: the default's number in display units; ``bounds``: as for
    :func:`slider_range`; ``relations``: ``{"min": [(text, strict)], "max": [...]}`` of
    :func:`assert_relations`, each a bound over other params that the range follows,
    ``min=max(20 mm, width / 2 + 0.2 mm)``, a strict one a step inside)."""
    if kind not in ("length", "angle", "number") or value is None:
        return f"param {name} = {text}"
    lo, hi, step = slider_range(name, kind, value, bounds)
    u = f" {_UNIT[kind]}" if kind in _UNIT else ""
    lo_t, hi_t = f"{_num(lo)}{u}", f"{_num(hi)}{u}"
    rel = relations or {}
    if rel.get("min"):
        terms = [f"{t} + {_num(step)}{u}" if strict else t for t, strict in rel["min"]]
        lo_t = f"max({', '.join([lo_t] + terms)})"
    if rel.get("max"):
        terms = [f"{t} - {_num(step)}{u}" if strict else t for t, strict in rel["max"]]
        hi_t = f"min({', '.join([hi_t] + terms)})"
    return _wrapped(f"param {name} = {text}, min={lo_t}, max={hi_t}, step={_num(step)}{u}")


def _wrapped(line: str, width: int = 96) -> str:
    """``line`` broken at spaces inside brackets (where a newline is allowed) so that no
    line is longer than ``width``, the continuation lines indented by four spaces (a bound as
    long as a spur gear's backlash, where its teeth come to a point)."""
    out, cur, depth = [], "", 0
    for i, word in enumerate(line.split(" ")):
        if i and depth > 0 and len(cur) + 1 + len(word) > width:
            out.append(cur)
            cur = "    " + word
        else:
            cur = word if not i else f"{cur} {word}"
        depth += word.count("(") + word.count("[") - word.count(")") - word.count("]")
    return "\n".join(out + [cur])


def _in_dependency_order(decls: list[tuple[str, str, set]]) -> list[str]:
    """The ``(name, declaration, names it uses)`` in their order, each after the params its
    range uses (a param's range may use only those declared before it)."""
    done: set = set()
    out, rest = [], list(decls)
    known = {n for n, _, _ in decls}
    while rest:
        for i, (n, d, uses) in enumerate(rest):
            if not (uses & known) - done:
                out.append(d)
                done.add(n)
                del rest[i]
                break
        else:                           # a cycle: as written
            out += [d for _, d, _ in rest]
            break
    return out


# the words of a bound's text that are no argument: calls, units, a ternary's keywords
_NOT_NAMES = {"min", "max", "abs", "sqrt", "square", "sin", "cos", "tan", "atan", "pi", "mm",
              "deg", "cm", "m", "in", "rad", "if", "else", "and", "or", "not", "true", "false"}


def _relations_for(name: str, relations: dict, params: set) -> tuple[dict, set]:
    """``relations[name]`` without the bounds that use a name that is not a param here,
    and the params they use."""
    got, uses = {"min": [], "max": []}, set()
    for side in ("min", "max"):
        for t, strict in relations.get(name, {}).get(side, []):
            used = set(re.findall(r"[A-Za-z_]\w*", t)) - _NOT_NAMES
            if used <= params:
                got[side].append((t, strict))
                uses |= used
    return got, uses


def _literal(node) -> tuple[str, float | None] | None:
    """``(kind, number in display units)`` of a literal argument or default (``40 mm``,
    ``20 deg``, ``3``, ``"hex"``, ``true``); ``None`` for anything else (a list, an
    expression) or a unit the gallery does not convert."""
    from ..library.reference import kind_of_default
    kind = kind_of_default(node)
    if kind in ("string", "bool"):
        return kind, None
    if kind not in ("length", "angle", "number"):
        return None
    sign, n = (-1, node.operand) if isinstance(node, A.Neg) else (1, node)
    if not isinstance(n, A.Num):
        return None
    scale = {None: 1.0, "mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4, "deg": 1.0,
             "rad": 180 / math.pi}.get(n.unit)
    if scale is None:
        return None
    return kind, sign * n.value * scale


# ------------------------------------------------------------------------ texts
def title_of(name: str) -> str:
    """``divider_tray`` -> ``Divider tray``; ``pcb_enclosure`` -> ``PCB enclosure``."""
    words = [ACRONYMS.get(w, w) for w in name.split("_") if w]
    if not words:
        return name
    first = words[0] if words[0] in ACRONYMS.values() else words[0].capitalize()
    return " ".join([first] + words[1:])


def header_comment(source: str) -> str:
    """The program's leading comment block, joined by spaces, without its command lines
    (``#   aidl render ...``) and ``Try:`` lines."""
    out = []
    for line in source.splitlines():
        s = line.strip()
        if not s.startswith("#"):
            break
        body = s[1:].strip()
        if not body or body.startswith(("aidl ", "Try:")) or s.startswith("#   "):
            continue
        out.append(body)
    return " ".join(out)


def _depth0(text: str, sep: str) -> int:
    """The index of the first ``sep`` outside parentheses and quotes, or -1."""
    depth, quote = 0, False
    for i, ch in enumerate(text):
        if ch == '"':
            quote = not quote
        elif not quote and ch == "(":
            depth += 1
        elif not quote and ch == ")":
            depth = max(0, depth - 1)
        elif not quote and depth == 0 and text.startswith(sep, i):
            return i
    return -1


def _drop_asides(text: str, keep=lambda inner: False) -> str:
    """``text`` without its parenthesized asides (outermost), except those ``keep`` likes."""
    out, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        if ch == "(":
            if depth == 0:
                out.append(text[start:i])
                start = i
            depth += 1
        elif ch == ")" and depth:
            depth -= 1
            if depth == 0:
                inner = text[start:i + 1]
                out.append(inner if keep(inner) else "")
                start = i + 1
    out.append(text[start:])
    return re.sub(r"\s+([,.;:])", r"\1", re.sub(r"\s+", " ", "".join(out))).strip()


def purpose_of(text: str) -> str:
    """The first sentence of a doc comment as one plain line (backticks dropped, asides that
    name files or imports dropped), at most 120 characters.  A longer sentence loses its
    parenthesized asides; still too long, it keeps the items of its list after the colon
    that fit, then an ellipsis (``A flat bottle opener: a round head with the cap-lifting
    cut-out, a handle with grip slots made by a loop, …``), or with no colon it is cut after
    its last whole word that fits.  ``""`` for an empty text."""
    from ..library.reference import sentences
    parts = sentences(re.sub(r"\s+", " ", text))
    s = re.sub(r"\s+", " ", parts[0]).strip().replace("`", "") if parts else ""
    s = _drop_asides(s, keep=lambda a: not re.search(r'"|\.aidl|/|\bimport\b', a))
    if len(s) <= PURPOSE_MAX:
        return s
    short = _drop_asides(s)
    if len(short) <= PURPOSE_MAX:
        return short
    colon = _depth0(short, ": ")
    if 0 < colon < PURPOSE_MAX - 2:
        head, rest, items = short[:colon], short[colon + 2:].rstrip("."), []
        while rest:
            i = _depth0(rest, ", ")
            item, rest = (rest, "") if i < 0 else (rest[:i], rest[i + 2:])
            item = re.sub(r"^and ", "", item)
            if len(f"{head}: {', '.join(items + [item])}, …") > PURPOSE_MAX:
                break
            items.append(item)
        return f"{head}: {', '.join(items)}, …" if items else head.rstrip(".,;") + "."
    return short[:PURPOSE_MAX - 1].rsplit(" ", 1)[0].rstrip(",;:") + "…"


def _tags(stem: str, source: str, modules=()) -> list[str]:
    """Module tags (``boxes`` -> ``box``), tags from the words of the file name, and feature
    tags from the source: ``text`` (Text or text_on_arc), ``3d`` (placed with ``Place``:
    an assembled view), ``spline``, ``drawing`` (reads an SVG or DXF drawing)."""
    tags = [MODULE_TAGS.get(m, m) for m in modules]
    words = stem.lower().replace("_", " ")
    tags += [t for t, rx in WORD_TAGS.items() if re.search(rx, words)]
    for tag, rx in (("text", r"\bText\(|\btext_on_arc\("), ("3d", r"\bPlace\("),
                    ("spline", r"\bSpline\("), ("drawing", r"\bDrawing2D\(")):
        if re.search(rx, source):
            tags.append(tag)
    return list(dict.fromkeys(tags))


# ------------------------------------------------------------------------ rewriting
def _parse(source: str, path: str):
    from ..base.diagnostics import DiagnosticSink
    from ..parser import parse
    sink = DiagnosticSink()
    prog = parse(source, path, sink)
    if sink.has_errors:
        raise ValueError(f"{path} does not parse")
    return prog


def _parse_or_none(source: str, path: str):
    try:
        return _parse(source, path)
    except ValueError:
        return None


def _replace(source: str, edits: list[tuple[int, int, str]]) -> str:
    for start, end, text in sorted(edits, reverse=True):
        source = source[:start] + text + source[end:]
    return source


def _std_modules(prog) -> list[str]:
    return [m.group(1) for st in prog.stmts if isinstance(st, A.Import)
            for m in [re.match(r"std[/:]([A-Za-z_]\w*)(?:\.aidl)?$", st.path)] if m]


def self_contained(source: str, path: Path, depth: int = 0) -> str:
    """``source`` (the file ``path``) with its relative imports inlined and its drawings read
    from ``std/drawings/`` (see the module's docstring).  Raises :class:`ValueError` when
    that cannot be done (an import with ``as``, an imported file with params or structures,
    a drawing with no identical copy in the standard library)."""
    from ..library.sources import STDLIB
    prog = _parse(source, str(path))
    edits = []
    for st in prog.stmts:
        if isinstance(st, A.Import) and not st.path.startswith(("std/", "std:")):
            if st.alias or depth > 4:
                raise ValueError(f"{path}: cannot inline `import \"{st.path}\"`")
            rel = st.path if st.path.endswith(".aidl") else st.path + ".aidl"
            f = (path.parent / rel).resolve()
            sub = _parse(f.read_text(encoding="utf-8"), str(f))
            if any(isinstance(s, (A.ParamDecl, A.StructDecl)) for s in sub.stmts):
                raise ValueError(f"{path}: `{st.path}` has params or structures")
            text = self_contained(sub.source, f, depth + 1).rstrip("\n")
            edits.append((st.span.start, st.span.end,
                          f"# ---- {st.path} (the file beside the example), inlined:\n{text}\n"
                          f"# ---- end of {st.path}"))
    for n in A.walk(prog):
        if (isinstance(n, A.Call) and isinstance(n.func, A.Name) and n.func.id == "Drawing2D"
                and n.args and isinstance(n.args[0], A.Str)
                and not n.args[0].value.startswith("std/")):
            raw = n.args[0].value
            mine = (path.parent / raw).resolve()
            std = Path(STDLIB) / "drawings" / os.path.basename(raw)
            if not (std.is_file() and mine.is_file() and std.read_bytes() == mine.read_bytes()):
                raise ValueError(f"{path}: the drawing `{raw}` has no copy in std/drawings")
            s = n.args[0].span
            edits.append((s.start, s.end, f'"std/drawings/{os.path.basename(raw)}"'))
    return _replace(source, edits)


def _calls(prog, names) -> list[A.Call]:
    return [n for n in A.walk(prog) if isinstance(n, A.Call) and isinstance(n.func, A.Name)
            and n.func.id in names]


def _call_text(name: str, args: list[str], indent: int, width: int = 96) -> str:
    """``name(a=a, b=b, ...)`` for a call starting at column ``indent`` (0-based), wrapped
    under its opening parenthesis where a line would pass ``width``."""
    pad = " " * (indent + len(name) + 1)
    lines, cur = [], f"{name}("
    for i, a in enumerate(args):
        last = i == len(args) - 1
        piece = a if last else a + ", "
        col = (0 if lines else indent) + len(cur) + len(piece.rstrip()) + (1 if last else 0)
        if col > width and cur.strip() != f"{name}(":
            lines.append(cur.rstrip())
            cur = pad
        cur += piece
    lines.append(cur + ")")
    return "\n".join(lines)


def lift_params(source: str, path: str, template) -> str | None:
    """``source`` with the literal arguments of its one call of ``template`` (a
    :class:`~aidl_lang.library.reference.StdTemplate`) made ``param``\\ s: the call's own value, else
    the template's default, with a slider range (:func:`slider_range`).  Arguments given as
    other expressions (lists, names) stay as written; ``cx``/``cy`` stay as written and are
    not added.  ``None`` when the program declares params already or does not call
    ``template`` exactly once."""
    prog = _parse(source, path)
    calls = _calls(prog, {template.name})
    if len(calls) != 1 or any(isinstance(s, A.ParamDecl) for s in prog.stmts):
        return None
    call = calls[0]
    given = {k.name: k for k in call.kwargs}
    if call.args:
        return None
    decls, args, lifted = [], [], {}
    bounds, relations = assert_bounds(template), assert_relations(template)
    found = []
    for p in template.node.params:
        kw = given.get(p.name)
        node = kw.value if kw is not None else p.default
        lit = _literal(node) if node is not None and p.name not in PLACEMENT_ARGS else None
        if lit is None:
            if kw is not None:
                args.append(f"{p.name}={source[kw.value.span.start:kw.value.span.end]}")
            continue
        kind, value = lit
        text = source[node.span.start:node.span.end] if kw is not None else \
            _default_source(node)
        found.append((p.name, kind, text, value))
        args.append(f"{p.name}={p.name}")
        lifted[p.name] = value
    params = {f[0] for f in found}
    for name, kind, text, value in found:
        rel, uses = _relations_for(name, relations, params)
        decls.append((name, _param_decl(name, kind, text, value, bounds.get(name, (None, None)),
                                        rel), uses))
    decls = _in_dependency_order(decls)
    edits = [(call.span.start, call.span.end, _call_text(template.name, args, call.span.col - 1))]
    # the material thickness of the 3D view follows a lifted `thickness` of the same value
    for st in prog.stmts:
        if type(st) is A.ThicknessDecl and "thickness" in lifted and \
                _literal(st.value) == ("length", lifted["thickness"]):
            edits.append((st.value.span.start, st.value.span.end, "thickness"))
    # the params go after the last import (or the header comment)
    imports = [s for s in prog.stmts if isinstance(s, (A.Import, A.UnitsDecl))]
    if imports:
        nl = source.find("\n", imports[-1].span.end - 1)
        at = len(source) if nl < 0 else nl + 1
    else:
        at = _after_header(source)
    block = (f"\n# the arguments of {template.name} (std/{template.module}.aidl), as params\n"
             + "\n".join(decls) + "\n")
    edits.append((at, at, block))
    return _replace(source, edits)


def _after_header(source: str) -> int:
    """The offset just after the leading comment lines."""
    at = 0
    for line in source.splitlines(keepends=True):
        if not line.lstrip().startswith("#"):
            break
        at += len(line)
    return at


def _default_source(node) -> str:
    from ..library.reference import default_text
    return default_text(node)


# ------------------------------------------------------------------------ entries
def _rel(p: Path) -> str:
    return "examples/" + p.relative_to(EXAMPLES).as_posix()


def _own_source(p: Path) -> tuple[str, str]:
    """``(file text, self-contained program)``; the file text itself when it cannot be made
    self-contained (the gallery still lists it; the compile test names it)."""
    raw = p.read_text(encoding="utf-8")
    try:
        return raw, self_contained(raw, p)
    except (ValueError, OSError):
        return raw, raw


def counts_from_one(source: str, path: str = "main.aidl") -> str:
    """``source`` with ``, min = 1`` after each top-level ``param`` whose value is a whole
    number of at least 1 and that declares no range: a count (bolts, grips), whose slider
    would otherwise start at 0 (:func:`aidl_lang.serve.params.default_span`), a value the
    program was never written for (a LinearPattern of 0, a loop of no grips)."""
    prog = _parse_or_none(source, path)
    if prog is None:
        return source
    edits = []
    for st in prog.stmts:
        if isinstance(st, A.ParamDecl) and not st.options and isinstance(st.value, A.Num) \
                and not st.value.unit and float(st.value.value).is_integer() \
                and st.value.value >= 1:
            edits.append((st.value.span.end, st.value.span.end, ", min = 1"))
    return _replace(source, edits)


def _example_entry(p: Path) -> Entry:
    """``example/NAME`` of a top-level example file (its own params; counts from 1,
    :func:`counts_from_one`)."""
    raw, src = _own_source(p)
    src = page_program(counts_from_one(src, str(p)))
    prog = _parse_or_none(src, str(p))
    gens = renderable_generators()
    shown = p.stem if p.stem in gens and prog and _calls(prog, {p.stem}) else ""
    purpose = purpose_of(header_comment(raw))
    modules = _std_modules(prog) if prog else []
    return Entry(f"example/{_slug(p.stem)}", title_of(p.stem), purpose, "example", src,
                 param_rows(src), _tags(p.stem, src, modules=modules), _rel(p), shown)


def _generator_example_entry(p: Path) -> Entry:
    """``generator/NAME`` of an ``examples/generators`` file (params lifted when it calls
    one generator and declares none)."""
    from ..library.reference import stdlib_templates
    raw, src = _own_source(p)
    gens = renderable_generators()
    t = stdlib_templates().get(p.stem)
    form = FORMS / p.name
    if form.is_file():              # a form that states how the arguments depend on each other
        src = form.read_text(encoding="utf-8")
    elif t is not None:
        try:
            src = lift_params(src, str(p), t) or src
        except ValueError:
            pass
    src = page_program(src)
    prog = _parse_or_none(src, str(p))
    shown = p.stem if p.stem in gens and prog and _calls(prog, {p.stem}) else ""
    purpose = purpose_of(header_comment(raw))
    modules = [t.module] if t is not None else _std_modules(prog) if prog else []
    return Entry(f"generator/{_slug(p.stem)}", title_of(p.stem), purpose, "generator", src,
                 param_rows(src), _tags(p.stem, src, modules=modules), _rel(p), shown)


def synthesize(t) -> str:
    """The program of a generator without an example (a
    :class:`~aidl_lang.library.reference.StdTemplate`): its doc comment, ``units mm``, the import, a
    ``param`` with a range for each argument with a literal default (not ``cx``/``cy``),
    ``thickness`` following a ``thickness`` param, and ``NAME = generator(arg=arg, ...)``
    in a structure of the generator's kind named after it."""
    doc = textwrap.wrap(t.doc, 94) or [t.name]
    lines = [f"# {ln}" for ln in doc]
    lines.append(f"# (the studio's program for `{t.name}` of std/{t.module}.aidl: its arguments "
                 "are the params)")
    lines += ["units mm", f'import "std/{t.module}.aidl"', ""]
    args, bounds, relations, found = [], assert_bounds(t), assert_relations(t), []
    for p in t.node.params:
        if p.default is None or p.name in PLACEMENT_ARGS:
            continue
        lit = _literal(p.default)
        if lit is None:
            continue
        kind, value = lit
        found.append((p.name, kind, _default_source(p.default), value))
        args.append(f"{p.name}={p.name}")
    params, decls = {f[0] for f in found}, []
    for name, kind, text, value in found:
        rel, uses = _relations_for(name, relations, params)
        decls.append((name, _param_decl(name, kind, text, value, bounds.get(name, (None, None)),
                                        rel), uses))
    lines += _in_dependency_order(decls)
    if any(a.startswith("thickness=") for a in args):
        lines += ["", "thickness thickness"]
    lines += ["", f"{t.node.kind} {t.name} {{",
              "    part = " + _call_text(t.name, args, 11), "}", ""]
    return "\n".join(lines)


def _synthesized_entry(t) -> Entry:
    src = page_program(synthesize(t))
    purpose = purpose_of(t.doc)
    return Entry(f"generator/{_slug(t.name)}", title_of(t.name), purpose, "generator", src,
                 param_rows(src), _tags(t.name, src, modules=[t.module]),
                 f"std/{t.module}.aidl", t.name, True)


def _slug(name: str) -> str:
    return re.sub(r"[^a-z0-9_-]+", "-", name.lower()).strip("-") or "entry"
