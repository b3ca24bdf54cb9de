"""The reference of every name a program may use: ``aidl docs NAME``, the MCP ``docs`` tool and
resources, the stdlib lines of ``aidl prompt``, and the parameter lists of diagnostics.

A *topic* is a shape, constraint, structural relation or operation (from the registry,
:mod:`aidl_lang.registry`), a statement or concept (``assert``, ``kerf``, ``bb``, ...), or a
standard-library template (``spur_gear``; from the comment block above its ``def`` in
``stdlib/*.aidl``, so the reference cannot drift from the library).  Each topic prints its
signature, the unit of every parameter, its members and a short example program that compiles
(``tests/test_reference.py`` compiles them all).

Lookups are lenient: case and word style (``SpurGear``, ``spur-gear``, ``SPUR_GEAR``), the
registry's synonyms (``Orthogonal``) and a few words (``bbox``, ``elif``) find the topic;
:func:`suggest` gives the nearest topics for anything else.  Sources: the registry, the stdlib
files (parsed once), the statement texts and examples below.  Nothing here compiles a program.
"""
from __future__ import annotations

import difflib
import functools
import re
from dataclasses import dataclass, field
from pathlib import Path

from .. import ast as A
from ..registry import (BBOX_MEMBERS, CONSTANTS, ENTRIES, FUNCTIONS, SWAPPED, SYNONYM_DOCS,
                       SYNONYMS, UNITS_ANGLE, UNITS_LENGTH, Entry, arg_synonyms)
from .details import DETAILS
from .topic_examples import EXAMPLES, TEMPLATE_ARGS, TEMPLATE_EXAMPLES
from .sources import STDLIB

# ---------------------------------------------------------------- units of parameters

# an argument or parameter type -> what to write for it (its unit)
KIND_TEXT = {
    "length": "length: a number in the file's unit (mm unless `units`), or with a unit "
              "(`5 mm`, `0.25 in`)",
    "angle": "angle: degrees (`30` or `30 deg`; `1 rad`), counter-clockwise from +x",
    "number": "number: a count or factor, no unit",
    "point": "point: `(x, y)` in lengths, or a point member (`rect.top_left`)",
    "points": "list of points: `[(x, y), ...]`",
    "bool": "`true` or `false`",
    "string": "text in double quotes",
    "line": "a line: a Line, or a line member (`rect.top`, `slot.spine`)",
    "circular": "a Circle or an Arc",
    "centered": "a shape with a center (Circle, Arc, ArcSlot, Ellipse, RegularPolygon, Star, "
                "Slot, Rectangle, ...), or a point",
    "curve": "a Line, Circle or Arc",
    "geometry": "a shape, or a point or line member",
    "boxed": "a structure or a shape (anything with a `.bb`)",
    "any": "see the forms",
}
KIND_WORDS = {"angle": "an angle", "point": "a point (x, y)", "bool": "true or false",  # docs
              "string": "text", "numbers": "a list of numbers", "any": "a value"}
# the short unit note of a kind, for one-line signatures and hints
KIND_UNIT = {"length": "length, mm", "angle": "angle, deg", "number": "number",
             "point": "point (x, y) mm", "points": "[(x, y), ...]", "bool": "true/false",
             "string": "text"}

# what the conventional parameter names of a template that is not the standard library's mean
# (a stdlib template says which point (cx, cy) is in its `Anchor:` line: StdTemplate.anchor)
PARAM_GLOSS = {"cx": "x of the center's starting position (constraints may move the instance)",
               "cy": "y of the center's starting position (constraints may move the instance)"}


def kind_of_default(node) -> str:
    """The kind of a template parameter from its default expression: ``2 mm`` a length,
    ``20 deg`` an angle, ``20`` a number, ``"x"`` a string, ``true`` a bool, ``(0, 0)`` a point,
    ``[12, 36]`` numbers (``lengths``, ``points``; else ``list``); else ``any``."""
    if isinstance(node, A.Neg):
        node = node.operand
    if isinstance(node, A.Num):
        return "length" if node.unit in UNITS_LENGTH else (
            "angle" if node.unit in UNITS_ANGLE else "number")
    if isinstance(node, (A.Str, A.FStr)):
        return "string"
    if isinstance(node, A.Name) and node.id in ("true", "false", "True", "False"):
        return "bool"
    if isinstance(node, A.ListLit):    # `[12, 36]` numbers, `[10 mm]` lengths, `[(0, 0)]` points
        kinds = {kind_of_default(i) for i in node.items}
        one = {"number": "numbers", "length": "lengths", "point": "points"}
        return one.get(*kinds, "list") if len(kinds) == 1 else "list"
    return "point" if isinstance(node, A.TupleLit) and len(node.items) == 2 else "any"


def default_text(node) -> str:
    """A default expression as source (numbers with their units, strings, names)."""
    if node is None:
        return ""
    if isinstance(node, A.Neg):
        return "-" + default_text(node.operand)
    if isinstance(node, A.Num):
        v = f"{node.value:g}"
        return f"{v} {node.unit}" if node.unit else v
    if isinstance(node, A.Str):
        return '"' + node.value.replace('"', '\\"') + '"'
    if isinstance(node, A.Name):
        return node.id
    inner = [default_text(i) for i in getattr(node, "items", ())[:9]]   # a list or tuple
    brackets = "[]" if isinstance(node, A.ListLit) else "()"
    return brackets[0] + ", ".join(inner) + brackets[1] if isinstance(node, (
        A.TupleLit, A.ListLit)) and len(inner) <= 8 and "..." not in inner else "..."


def template_signature(d: A.Def) -> str:
    """``name(p1=default, ...) -> kind`` of a template definition."""
    ps = [p.name if p.default is None else f"{p.name}={default_text(p.default)}"
          for p in d.params]
    return f"{d.name}({', '.join(ps)}) -> {d.kind}"


def units_line(pairs, anchor: str = "") -> str:
    """``lengths (mm, or with a unit): a, b; angles (deg): c; ...`` for (name, kind) pairs:
    the unit of every parameter, grouped by kind, in one line (``anchor``: what ``cx, cy``
    are, when known)."""
    groups: dict[str, list[str]] = {}
    for name, kind in pairs:
        groups.setdefault(kind, []).append(name)
    heads = {"length": "lengths (the file's unit, mm by default, or e.g. `5 mm`)",
             "angle": "angles (degrees, or e.g. `1 rad`)", "number": "plain numbers",
             "point": "points `(x, y)`", "points": "point lists", "bool": "true/false",
             "string": "text", "line": "lines", "circular": "circles or arcs",
             "centered": "shapes with a center, or points",
             "curve": "lines, circles or arcs", "geometry": "shapes or points",
             "boxed": "structures or shapes", "any": "values", "numbers": "lists of numbers"}
    out = [f"{heads.get(k, k)}: {', '.join(v)}" for k, v in groups.items()]
    gloss = [f"{n}: {PARAM_GLOSS[n]}" for n, _ in pairs if n in PARAM_GLOSS]
    if {"cx", "cy"} <= {n for n, _ in pairs}:
        gloss = [f"cx, cy: {anchor}" if anchor else "cx, cy: the x and y where its center "
                 "starts (constraints may move the instance)"]
    return "; ".join(out + gloss)


def template_params_hint(d: A.Def) -> str:
    """The parameter list of a template with the unit of each, for E0105/E0103 hints (a
    standard-library template's ``cx, cy`` glossed by its ``Anchor:`` line)."""
    pairs = [(p.name, kind_of_default(p.default) if p.default is not None else "any")
             for p in d.params]
    t = stdlib_templates().get(d.name)
    anchor = t.anchor_text if t is not None and _in_stdlib(d, t) else ""
    return f"`{template_signature(d)}`" + (f"; {units_line(pairs, anchor)}" if pairs else "")


def _in_stdlib(d: A.Def, t: StdTemplate) -> bool:
    """Whether ``d`` is the definition of stdlib template ``t`` (read from its file)."""
    try:
        return Path(d.span.file).resolve() == (Path(STDLIB) / f"{t.module}.aidl").resolve()
    except (TypeError, OSError, AttributeError):
        return False


def entry_units_hint(entry: Entry) -> str:
    """The unit of every argument of a registry entry, for E0105/E0104 hints."""
    pairs, seen = [], set()
    for v in entry.variants:
        for a in v:
            if a.name not in seen and not a.kw_only:
                seen.add(a.name)
                pairs.append((a.name, a.type))
    return units_line(pairs)


# ---------------------------------------------------------------- the standard library

@dataclass(frozen=True)
class StdTemplate:
    """A template of the standard library: where it is, its definition and its doc comment."""
    name: str
    module: str                      # "gears" (import "std/gears.aidl")
    node: A.Def
    doc: str                         # the comment block above the `def`, joined
    members: tuple[str, ...]         # the backticked names of its "Members:" sentence
    anchor: str = ""                 # its `Anchor:` line: the point (cx, cy) is ...
    turn: str = ""                   # ... and where it points at rotation 0 ("" if no rotation)

    @property
    def anchor_text(self) -> str:
        """``(cx, cy) is POINT; rotation 0: DIRECTION`` from the ``Anchor:`` line."""
        if not self.anchor:
            return ""
        return f"(cx, cy) is {self.anchor}" + (f"; rotation 0: {self.turn}" if self.turn else "")

    @property
    def holds_itself(self) -> bool:
        """Whether the template fixes its own instance (``Fixed(self)``: joints on an edge)."""
        return any(isinstance(st, A.ExprStmt) and isinstance(st.expr, A.Call)
                   and getattr(st.expr.func, "id", None) == "Fixed"
                   and [getattr(a, "id", None) for a in st.expr.args] == ["self"]
                   for st in self.node.body.stmts)

    @property
    def signature(self) -> str:
        return template_signature(self.node)

    @property
    def summary(self) -> str:
        """The doc comment's first sentence."""
        return sentences(self.doc)[0] if self.doc else ""

    @property
    def params(self) -> list[tuple[str, str, str]]:
        """(name, kind, default text) of every parameter."""
        return [(p.name, kind_of_default(p.default) if p.default is not None else "any",
                 default_text(p.default)) for p in self.node.params]


def sentences(text: str) -> list[str]:
    """``text`` split after each full stop that ends a sentence (not inside parentheses or
    backticks, and followed by a capital letter or a backtick)."""
    out, depth, tick, start = [], 0, False, 0
    for i, ch in enumerate(text):
        if ch == "`":
            tick = not tick
        elif not tick and ch == "(":
            depth += 1
        elif not tick and ch == ")":
            depth = max(0, depth - 1)
        elif (ch == "." and depth == 0 and not tick and i + 2 < len(text)
              and text[i + 1] == " " and (text[i + 2].isupper() or text[i + 2] == "`")):
            out.append(text[start:i + 1].strip())
            start = i + 2
    rest = text[start:].strip()
    if rest:
        out.append(rest)
    return out


def _doc_above(lines: list[str], row: int) -> str:
    """The comment block that ends on the line above ``row`` (0-based), joined by spaces."""
    block = []
    r = row - 1
    while r >= 0 and lines[r].startswith("#"):
        block.append(lines[r][1:].strip())
        r -= 1
    return " ".join(reversed(block)).strip()


ANCHOR_LINE = re.compile(r"Anchor: \(cx, cy\) is (?P<point>.+?)"
                         r"(?:; rotation 0: (?P<turn>.+?))?\.$")


def _anchor(doc: str) -> tuple[str, str, str]:
    """(doc without its ``Anchor:`` line, the point, the direction at rotation 0): the line
    ``# Anchor: (cx, cy) is POINT[; rotation 0: DIRECTION].`` ends a template's comment."""
    i = doc.rfind("Anchor: ")
    m = ANCHOR_LINE.match(doc[i:]) if i == 0 or (i > 0 and doc[i - 1] == " ") else None
    if m is None:
        return doc, "", ""
    return doc[:i].strip(), m.group("point"), m.group("turn") or ""


def _members(doc: str) -> tuple[str, ...]:
    for s in sentences(doc):
        m = re.match(r"Members?:\s*(.*)", s)
        if m:
            names = re.findall(r"`([A-Za-z_]\w*)(?:\[[^\]]*\])?`", m.group(1))
            return tuple(dict.fromkeys(names))
    return ()


@functools.cache
def stdlib_templates() -> dict[str, StdTemplate]:
    """Every template of ``stdlib/*.aidl`` by name, in file order (modules alphabetically)."""
    from ..base.diagnostics import DiagnosticSink
    from ..parser import parse
    out: dict[str, StdTemplate] = {}
    for f in sorted(Path(STDLIB).glob("*.aidl")):
        text = f.read_text(encoding="utf-8")
        lines = text.splitlines()
        prog = parse(text, str(f), DiagnosticSink())
        for st in prog.stmts:
            if isinstance(st, A.Def):
                doc, point, turn = _anchor(_doc_above(lines, st.span.line - 1))
                out[st.name] = StdTemplate(st.name, f.stem, st, doc, _members(doc), point, turn)
    return out


def stdlib_lines(defaults: bool = True) -> str:
    """One line per stdlib template, by module: signature (without ``cx, cy``; defaults
    unless ``defaults`` is false), the first sentence of its doc comment, its members and
    ``@ POINT``, the point ``(cx, cy)`` is by its ``Anchor:`` line (``aidl prompt``)."""
    rows, module = [], None
    for t in stdlib_templates().values():
        if t.module != module:
            module = t.module
            rows.append(f"`import \"std/{module}.aidl\"`:")
        ps = [f"{n}={d}" if defaults else n for n, _, d in t.params if n not in ("cx", "cy")]
        mem = f" Members: {', '.join(t.members)}." if t.members else ""
        at = (f" @ {_short(t.anchor)}" + (f"; rotation 0: {t.turn}" if t.turn else "")
              + ".") if t.anchor else ""
        rows.append(f"- {t.name}({', '.join(ps)}) -> {t.node.kind}: {t.summary}{mem}{at}")
    return "\n".join(rows)


def _short(point: str) -> str:
    """An anchor's point as the prompt says it after ``@``: ``the centre of X`` as ``X``."""
    return point.removeprefix("the centre of ").removeprefix("the ")


# ---------------------------------------------------------------- topics

@dataclass
class Topic:
    """One entry of ``aidl docs``: ``name`` (as written in programs), ``kind`` (shape,
    constraint, relation, operation, statement, template), a one-line ``summary`` and the
    full ``text``; ``example`` is a whole program (empty for none)."""
    name: str
    kind: str
    summary: str
    text: str
    example: str = ""
    aliases: tuple[str, ...] = field(default_factory=tuple)

    def render(self) -> str:
        out = [f"{self.name} ({self.kind})", "", self.text.rstrip()]
        if self.example:
            out += ["", "Example:", "", _indent(self.example.rstrip(), "    ")]
        return "\n".join(out) + "\n"


def _indent(text: str, pad: str) -> str:
    return "\n".join(pad + ln if ln.strip() else ln for ln in text.splitlines())


_KINDS = {"primitive": "shape", "constraint": "constraint", "structural": "structural relation",
          "operation": "operation", "placement": "3D placement"}
_MEMBER_KINDS = {"point": "points", "points": "point lists", "line": "lines",
                 "lines": "line lists", "shapes": "shape lists", "circles": "circle lists",
                 "curves": "curve lists"}


def _member_text(members: dict[str, str]) -> str:
    groups: dict[str, list[str]] = {}
    for m, kind in members.items():
        if m != "bb":
            groups.setdefault(_MEMBER_KINDS.get(kind, "numbers (lengths, coordinates, "
                                                      "angles)"), []).append(m)
    rows = [f"  {k}: {' '.join(v)}" for k, v in groups.items()]
    return "\n".join(rows + ["  bb: its bounding box (`aidl docs bb`)"])


def _units_block(kinds) -> list[str]:
    """``Units:`` and what to write for each kind of the given ones, once each."""
    ks = [k for k in dict.fromkeys(kinds) if k in KIND_TEXT and k != "any"]
    return ["", "Units:"] + [f"  {KIND_TEXT[k]}" for k in ks] if ks else []


def _entry_topic(e: Entry) -> Topic:
    lines = [_wrap(e.doc, "")]
    if e.name in DETAILS:
        lines += [""] + [_wrap(par, "") for par in DETAILS[e.name].split("\n\n")]
    lines += ["", "Forms:"]
    for v in e.variants:
        ps = []
        for a in v:
            if a.kw_only:
                continue
            ps.append(a.name if a.shown_required or e.varargs else f"{a.name}={a.default_text}")
        lines.append(f"  {e.name}({', '.join(ps + ['...'] * e.varargs)})")
    kw = [a for v in e.variants for a in v if a.kw_only]
    for a in dict((a.name, a) for a in kw).values():
        lines.append(f"  every form also takes `{a.name}={a.default_text}` (keyword only): "
                     f"{a.doc}")
    lines += ["", "Parameters:"]
    seen: dict[str, str] = {}
    for v in e.variants:
        for a in v:
            if a.name not in seen and not a.kw_only:
                seen[a.name] = a.type
                extra = f" ({a.doc})" if a.doc else ""
                lines.append(f"  {a.name}: {a.type}{extra}")
    lines += _units_block(seen.values())
    if e.members:
        lines += ["", "Members:", _member_text(e.members)]
    syn = sorted(s for s, c in SYNONYMS.items() if c == e.name)
    if syn:
        lines += ["", "Also written: " + ", ".join(
            f"{s} ({SYNONYM_DOCS[s]})" if s in SYNONYM_DOCS else s for s in syn) + "."]
    canon = set(seen)
    arg_syn = [f"{k}={c[0]}" for k, cs in arg_synonyms(e.name).items()
               for c in [tuple(x for x in cs if x in canon)] if c and k not in canon]
    if arg_syn:
        lines.append("Argument synonyms (written -> meant): " + ", ".join(arg_syn) + ".")
    return Topic(e.name, _KINDS.get(e.category, e.category), e.doc, "\n".join(lines),
                 EXAMPLES.get(e.name, ""), tuple(syn))


def _template_topic(t: StdTemplate) -> Topic:
    lines = [_wrap(t.doc, ""), "", f"Import: `import \"std/{t.module}.aidl\"` (or `import stdlib.{t.module}`)",
             "", "Signature:", f"  {t.signature}", "", "Parameters:"]
    glosses = _anchor_glosses(t)
    for n, kind, d in t.params:
        gloss = f"; {glosses[n]}" if n in glosses else ""
        said = KIND_WORDS.get(kind, f"a list of {kind}" if kind[-1] == "s" else f"a {kind}")
        lines.append(f"  {n}: {said}, required{gloss}" if not d else f"  {n} = {d}: {said}{gloss}")
    lines += _units_block(k for _, k, _ in t.params)
    if t.members:
        lines += ["", "Members (reach them by path: `g.NAME`, `g.NAME.center`): "
                  + ", ".join(t.members) + ("; its arguments too, as given or defaulted "
                                            f"(`g.{t.params[0][0]}`)" if t.params else "")]
    lines += ["", "Use it by assignment inside a structure: `NAME = "
              f"{t.name}(...)` (an instance of kind {t.node.kind}; " + (
                  "it holds itself where `cx`, `cy` put it in the structure it is written "
                  "in, and moves with that structure)." if t.holds_itself else
                  "place it with constraints).")]
    if t.node.kind == "assembly":
        part = "lid" if "lid" in t.members else (t.members[0] if t.members else "PART")
        lines += ["", _wrap("Cut into one of its parts (a hole in a panel): declare `hole h { "
                            "... }` beside the instance, place it with constraints (`CenterInside"
                            f"(h, NAME.{part})`) and write `CutInto(h, NAME.{part})` there; a hole "
                            "left in the assembly cuts nothing (W0109).", "")]
    return Topic(t.name, f"{t.node.kind} template, std/{t.module}.aidl", t.summary,
                 "\n".join(lines), _template_example(t))


def _anchor_glosses(t: StdTemplate) -> dict[str, str]:
    """What ``cx``, ``cy`` and ``rotation`` of a stdlib template mean, from its ``Anchor:``
    line (tests/test_template_anchors.py measures each point and direction)."""
    if not t.anchor:
        return dict(PARAM_GLOSS)
    stays = ("the instance holds itself there in the structure it is written in "
             "(`Fixed(self)`), and moves with that structure" if t.holds_itself else
             "constraints on the instance may move it, this point with it")
    flat = ", as laid out flat" if t.node.kind == "assembly" else ""
    out = {"cx": f"the x of (cx, cy), {t.anchor}{flat}; {stays}",
           "cy": "the y of (cx, cy) (see `cx`)"}
    if t.turn:
        out["rotation"] = f"at 0: {t.turn}; more turns it counter-clockwise about (cx, cy)"
    return out


def _template_example(t: StdTemplate) -> str:
    call = f"{t.name}({TEMPLATE_ARGS.get(t.name, '')})"
    imp = f'import "std/{t.module}.aidl"\n\n'
    if t.name in TEMPLATE_EXAMPLES:
        return imp + TEMPLATE_EXAMPLES[t.name]
    if t.node.kind == "hole":
        return (imp + "solid plate {\n    body = Rectangle(center=(0, 0), width=120, "
                f"height=120)\n    h = {call}\n    Fixed(body)\n    CenterInside(h, body)\n}}\n")
    if t.node.kind == "cut":
        return (imp + "solid panel {\n    body = Rectangle(center=(0, 0), width=60, "
                f"height=60)\n    c = {call}\n    Fixed(body)\n}}\n")
    if t.node.kind == "drawing":    # (cx, cy) the disc's centre: the anchor, not the box
        return (imp + "solid disc {\n    body = Circle(center=(0, 0), radius=45)\n"
                f"    label = {call}    # about (cx, cy) = (0, 0): the disc's centre\n"
                "    Fixed(body)\n}\n")
    if t.node.kind == "assembly":
        return imp + f"assembly kit {{\n    k = {call}\n}}\n"
    return imp + f"solid part {{\n    p = {call}\n}}\n"


@functools.cache
def topics() -> dict[str, Topic]:
    """Every topic by its name: registry entries, statements and concepts, stdlib templates."""
    out: dict[str, Topic] = {}
    for e in ENTRIES.values():
        out[e.name] = _entry_topic(e)
    for name, (kind, summary, text, aliases) in STATEMENTS.items():
        out[name] = Topic(name, kind, summary, text.strip(), EXAMPLES.get(name, ""),
                          tuple(aliases))
    for t in stdlib_templates().values():
        out.setdefault(t.name, _template_topic(t))
    return out


def _key(name: str) -> str:
    """A name without case and word style: ``SpurGear``, ``spur-gear``, ``SPUR_GEAR`` ->
    ``spurgear``."""
    return re.sub(r"[^a-z0-9]", "", name.lower())


@functools.cache
def _index() -> dict[str, list[str]]:
    """Style-free key -> topic names (the exact name first)."""
    idx: dict[str, list[str]] = {}

    def add(alias: str, name: str) -> None:
        lst = idx.setdefault(_key(alias), [])
        if name not in lst:
            lst.append(name)
    for name, t in topics().items():
        add(name, name)
        for a in t.aliases:
            add(a, name)
    for s, c in SYNONYMS.items():
        add(s, c)
    for f in FUNCTIONS:
        add(f, "functions")
    for c in CONSTANTS:
        add(c, "functions")
    for u in list(UNITS_LENGTH) + list(UNITS_ANGLE):
        add(u, "units")
    for t in stdlib_templates().values():
        add(f"{t.module}.{t.name}", t.name)
        add(f"std/{t.module}.aidl.{t.name}", t.name)
    return idx


def find(name: str) -> Topic | None:
    """The topic ``name`` means: exact, then without case and word style, then a synonym;
    ``None`` when nothing fits (see :func:`suggest`)."""
    name = name.strip().strip("`")
    ts = topics()
    if name in ts:
        return ts[name]
    if name.endswith("()"):
        return find(name[:-2])
    hits = _index().get(_key(name))
    if hits:
        # a style-only match: prefer a name of the same style (`slot` the template, `SLOT`
        # and `Slot` the shape)
        lower = [h for h in hits if h.islower() == name.islower()]
        return ts[(lower or hits)[0]]
    if "." in name:                       # gears.spur_gear, g.bore_hole -> its last part
        return find(name.rsplit(".", 1)[1]) if name.rsplit(".", 1)[1] else None
    return None


def suggest(name: str, n: int = 5) -> list[str]:
    """Topic names nearest to ``name`` (for did-you-mean)."""
    k = _key(name)
    idx = _index()
    keys = difflib.get_close_matches(k, list(idx), n=n, cutoff=0.6)
    keys += [key for key in idx if k and len(k) >= 3 and k in key and key not in keys]
    out: list[str] = []
    for key in keys:
        for t in idx[key]:
            if t not in out:
                out.append(t)
    return out[:n]


def lookup_text(name: str) -> tuple[str, bool]:
    """(the text ``aidl docs NAME`` prints, found?)."""
    t = find(name)
    if t is not None:
        return t.render(), True
    near = suggest(name)
    msg = f"no topic `{name}`"
    if near:
        msg += "; did you mean " + ", ".join(f"`{s}`" for s in near) + "?"
    return msg + "\n`aidl docs` lists every topic.\n", False


def index_text() -> str:
    """The list of topics by kind (``aidl docs`` alone)."""
    groups: dict[str, list[Topic]] = {}
    for t in topics().values():
        k = t.kind.split(",")[0]
        k = "template" if k.endswith("template") else k
        groups.setdefault(k, []).append(t)
    order = ["statement", "shape", "constraint", "structural relation", "operation",
             "3D placement", "template"]
    heads = {"statement": "Statements and concepts", "shape": "Shapes",
             "constraint": "Geometric constraints", "structural relation":
             "Structural relations (by bounding box)", "operation": "Operations",
             "template": "Standard-library templates (import \"std/MODULE.aidl\")"}
    out = ["`aidl docs NAME` prints a topic: signature, units of every parameter, members and "
           "an example. Names are found whatever their case or style (`SpurGear`, "
           "`spur-gear`).", ""]
    for k in order + [k for k in groups if k not in order]:
        if k in groups:
            out.append(f"{heads.get(k, k)}:")
            if k == "template":
                for t in groups[k]:
                    out.append(f"  {t.name:<17} {t.summary}")
            else:
                out.append(_wrap(", ".join(t.name for t in groups[k]), "  "))
            out.append("")
    return "\n".join(out).rstrip() + "\n"


def _wrap(text: str, pad: str, width: int = 92) -> str:
    import textwrap
    return textwrap.fill(text, width, initial_indent=pad, subsequent_indent=pad)


def topic_names() -> list[str]:
    return list(topics())


# ---------------------------------------------------------------- statements and concepts

# name -> (kind, summary, text, aliases)
STATEMENTS: dict[str, tuple[str, str, str, list[str]]] = {
    "units": ("statement", "`units mm`: the unit of bare lengths in the file.", """
`units mm` (default), `cm`, `m`, `in` (also `inch`), `ft`, at the top level: the unit of
bare lengths in the whole file and its templates. A number may always carry its own unit:
`5 mm`, `2 in`, `30 deg`, `1 rad`. A bare number is a length in the file unit where a length
is expected and an angle in degrees where an angle is expected (in arithmetic, and passed to
a `def`, it stays a plain number: `norm(p) * 2` is twice a length); `sin`, `cos`, `tan` of a
bare number take radians. Outputs are in millimetres.
""", ["unit", "mm", "inch", "deg", "degrees", "bare number"]),
    "import": ("statement", "`import \"std/gears.aidl\"`: templates and constants of another "
               "file.", """
`import "FILE.aidl"` or `import "FILE.aidl" as NAME` (top level). `import "std/NAME.aidl"`
(or `import stdlib.NAME`) reads the standard library: shapes, gears, joints, fasteners,
plates (`aidl docs` lists its templates). An import brings the file's templates, constants
and params (without `as`: as plain names; with `as shapes`: `shapes.washer(...)`), never its
structures. Paths are relative to the importing file and stay inside its folder tree.
""", ["as", "stdlib", "std", "include", "library"]),
    "param": ("statement", "`param width = 40 mm`: a value `--set` and the sliders can change.",
              """
`param NAME = VALUE [, min=A] [, max=B] [, step=S]` (top level): a number, length, angle,
string or bool that `aidl render --set NAME=VALUE` (and the live preview's slider) overrides.
Use it like a constant.
""", ["parameter", "set", "--set"]),
    "def": ("statement", "`def NAME(p=default) -> solid { ... }`: a template.", """
`def NAME(p1, p2=default, ...) -> KIND { body }` (or `KIND NAME(p1, ...) { body }`), at the top
level or inside a structure (there it is the same as written just above the structure: defined
for the whole file, its body reading the file's names and its parameters; two `def`s of one
name are E0107); KIND is solid, hole, cut, drawing or assembly. Instantiate it by assignment
inside a structure: `part = NAME(p1=...)` makes a child structure named `part` (reach
inside: `part.rim.center`); `hole cut = NAME(...)` changes the instance's kind. Arguments are values (numbers, lengths,
angles, strings, lists), not geometry; place the instance with constraints in the parent.
Bare numbers in the body are in the defining file's unit. A parameter without a default is
required. Keywords accept synonyms: `r` for `radius`, `num_teeth` for `teeth`.

`def NAME(p1, p2=default) = EXPR` (one line, where a template may stand) is a function: a
call gives the expression's value with the parameters bound (`def angle_of(v) = 225 deg - v * 27 deg`, then
`angle_of(3)`); numbers, points, lists and shapes in and out (`def cheek(w) = Polygon([(0, 0),
(w, 0), (w, 10)])`, then `c = cheek(20)`), used anywhere an expression goes. A bare
number passed in stays a plain number until it lands where a length is expected: in
`def toward(a, b, d) = b + (a - b) * (d / norm(a - b))`, `toward(p, q, 10)` scales by 10 per
mm (E0109, a 1/length): pass `10 mm`.
""", ["template", "templates", "function", "define", "instance", "lambda"]),
    "mirror": ("statement", "`mirror(points, about=\"y\")`: a point list and its mirror image, "
               "for a symmetric outline written once.", """
`mirror(points, about="y")` gives the points, then their mirror images in reverse order, so
that `Polygon(mirror(half, about="y"))` or `Spline(mirror(half, about="y"), closed=true)` is
symmetric and is written once. `about`: `"y"` (the y axis: x -> -x, exact), `"x"` (y ->
-y), or a Line (reflected across the line through its start and end as they are before
solving: exact for lines at multiples of 45 degrees). A first or last point that lies on the
axis is not repeated, so a half from the axis to the axis gives 2n - 2 points: with Spline
corners, point i and its mirror 2n - 2 - i. A list that is not points, or another `about`,
is E0108; `about=` is the one keyword argument a function takes.
""", ["mirror points", "symmetric outline", "symmetric"]),
    "assert": ("statement", "`assert cond, \"why\"`: a requirement checked after solving, never "
               "solved for.", """
`assert CONDITION` or `assert CONDITION, "reason"`, in a structure or at the top level: the
condition (comparisons joined by `and` and `or`, `!=` too, on any solved value: sizes,
positions, boxes) is checked at the solution; it adds no equation and no degree of freedom.
A false one is the error E0405 with the values found. Use it for requirements ("fits the
laser bed", "wall at least 2 mm") and for the request's own numbers and counts (`assert
len(feet) == 2`: a slip then fails the check), and constraints (`==`, `<=` statements) for
what the solver should make true.
""", ["requirement", "check", "require", "E0405"]),
    "kerf": ("statement", "`kerf 0.15 mm`: the laser's cut width; cuts are offset by half of "
             "it.", """
`kerf LENGTH` (top level: every part; inside a structure: that structure and its children,
the nearest one wins). `aidl render` offsets every cut by half the kerf so parts come out at
their drawn size: outlines outward, holes inward, arcs stay arcs; engravings are not offset.
Only the cutting formats (SVG, DXF, PDF, PNG, G-code, LightBurn `.lbrn2`, HPGL `.plt`) are
offset: STL, 3MF and STEP keep the designed size.
`aidl render --kerf 0.2mm` overrides it. A positive length known before solving, or 0 (not
offset). A Spline, an Ellipse and a font's letters are offset as circular arcs within 1e-4 mm. A
statement, with no `=`: `kerf = 0.2 mm` is an ordinary constant (warning W0108).
""", ["kerf_width", "laser kerf", "cut width"]),
    "min_wall": ("statement", "`min_wall 0.3 mm`: the thinnest wall the checks accept (W0507, "
                 "W0519, W0520); `min_wall 0`: off.", """
`min_wall LENGTH` (top level: every part; inside a structure: that structure and its
children, the nearest one wins) is the thinnest wall of material, and the narrowest slit, that
the final-part checks accept: W0507 (thin wall), W0519 (thin slit), W0520 (thin ledge). Without
it the minimum is 0.5 mm, what a laser or router holds. State it when a thin wall or a sharp
tip is what the request asks for (a 0.34 mm leg, an 18-degree corner): the checks then hold the
part to it, and no requested size has to change. `min_wall 0` turns those checks off (a part
not cut by a laser or router). A length known before solving, 0 or from 0.001 mm to 1e6 mm
(else E0109); `aidl check --min-wall MM` overrides it (the same range). A statement, with no `=`: `min_wall = 0.3 mm` is an
ordinary constant (warning W0108).
""", ["minimum wall", "min wall", "thin wall", "W0507", "minimum_wall", "wall_min"]),
    "lbrn2": ("statement", "`aidl render FILE -o x.lbrn2`: a LightBurn project, a layer per "
              "operation.", """
`aidl render FILE -o x.lbrn2` writes a LightBurn project: one layer (CutSetting) per operation
(engrave, score, cut inner, cut outer) with the machine profile's power, speed (mm/s in the
file) and passes; a group per part; shapes in the cut order (engraving first, holes before
outlines). Circles are exact Ellipse shapes, lines and spline pieces exact, arcs cubic Béziers
within 1e-4 mm. Cuts are offset by half the kerf.
""", ["lightburn", "LightBurn", ".lbrn2", "lbrn"]),
    "hpgl": ("statement", "`aidl render FILE -o x.plt`: HPGL for vinyl cutters and pen "
             "plotters.", """
`aidl render FILE -o x.plt` (or `.hpgl`) writes HPGL: `IN;SP1;`, PU/PD moves and AA arcs in
plotter units (40 a mm, whole numbers, origin at the drawing's lower-left so nothing is
negative, y up), one pen or knife, engraving first and holes before outlines; every drawn point
within 0.025 mm of the design.
""", ["plt", ".plt", ".hpgl", "vinyl cutter", "plotter", "pen plotter", "HPGL"]),
    "thickness": ("statement", "`thickness 3 mm`: the material thickness for STL, 3MF, STEP "
                  "and the parts list.", """
`thickness LENGTH` (top level: every part; inside a structure: that structure and its
children, the nearest one wins): the extrusion of the 3D outputs (STL, 3MF, STEP; default
3 mm), the thickness of `aidl parts` and the depth a router's G-code cuts to (see
`machine`). No other effect on 2D outputs. `aidl render --thickness` overrides it. A
positive length known before solving. A statement, with no `=`: `thickness = 4 mm` is an
ordinary constant (warning W0108, whose fix writes the statement); `param t = 4 mm` then
`thickness t` gives it a slider. `thickness` is no name an expression can read (E0101 says so):
to use the material's thickness in a slot or a `Place`, name it once, `t = 6 mm` then
`thickness t`, and write `t`.
""", ["material thickness", "extrude", "extrusion", "depth"]),
    "fonts": ("statement", "`Text(..., font=\"sans\")`: letters as filled outlines; which "
              "characters each font draws.", """
Without `font=`, a Text is engraved in a single-stroke font that draws printable ASCII and
`° ± × µ Ø ø ⌀`. With `font=`, its letters are the font's filled outlines: material in a
`solid`, openings in a `hole` (`stencil=true` keeps the counters), an engraved area in a
`drawing` (`fill=true`). `font=` takes `"sans"` or `"serif"` (installed with AIDL: Latin, Greek
and Cyrillic), a family installed on the machine (`"Droid Sans Fallback"`; fontconfig's
`fc-list :lang=zh family` lists those for Chinese, `:lang=ja` Japanese, `:lang=ar` Arabic), a
style after a colon (`"sans:Bold"`, `"serif:Light Italic"`, `"sans:650"`) or a `.ttf`, `.otf`
or `.ttc` file beside the program. A character the font has no glyph for is left out (W0105,
whose hint names an installed family that has it); a Text left with none is an error
(E0134). `size=` is the capital height: a capital is about `size` wide, a small letter about
0.7 x `size`, a CJK character about 1.4 x `size`; `max_width=` shrinks a text to fit.
""", ["font", "typeface", "glyph", "glyphs", "letters", "cjk", "script", "unicode"]),
    "machine": ("statement", "`aidl render FILE -o x.gcode --machine m.toml`: G-code (GRBL) "
                "for a laser, router or plotter.", """
`aidl render FILE -o part.gcode` (or .nc) writes GRBL G-code in mm: engraving first, then
each part's holes before its outline, parts in a short travel order; lines G1, arcs and
circles G2/G3 with I/J (exact), ellipses and splines as arcs within 0.001 mm. It prints the
cut and travel length and the job time. `--machine FILE` takes a TOML profile (every key
optional; `--machine router` or `plotter`: the built-in ones; default the built-in laser):
`kind` (laser | router | plotter), `max_power` (S of 100 %), `laser_mode` (M4 | M3),
`travel_speed`, `tool_diameter`, `safe_height`, `tabs`, `tab_width`, `tab_height`,
`lead_in`, `units`, and tables `[engrave]`, `[score]`, `[cut_inner]`, `[cut_outer]`, `[fill]`
with `power` (%), `speed` (mm/min), `passes`, `depth_per_pass`, `plunge`, `spindle`, and
`interval` (mm between a fill's lines: `Text(..., font=, fill=true)` is scanned in parallel
lines, letter by letter, after the engraving; a router refuses a fill). A router's
path is offset by the tool radius, down `depth_per_pass` at a time to the program's
`thickness`. The program's `kerf` and `thickness` are used; a profile stating others is
warned about. `--layout sheet -o cut.gcode` writes one program per sheet; parts drawn over each
other (an assembly placed in 3D) are refused (E0501): use `--layout sheet`. Each number has a
range (`passes` 1-100, `depth_per_pass` 0.01-100 mm, speeds 1-100000 mm/min, `tabs` 0-16,
`lead_in` 0 or 0.01-100 mm); past it the profile is refused naming the key and the range. A
lead-in keeps 0.5 mm from every other cut; a router's bit that cuts a part apart is W0510.
A through-cut is cut as wide as the tool (the bit's diameter; a laser's kerf) while outlines and
holes are offset: a bridge, rim or strip beside it that the tool leaves thinner than the
minimum wall, or cuts away, is W0507 at the cut (a slit 1.6 mm from the edge: 0.0125 mm left
with a 3.175 mm bit); keep cuts the tool's radius plus `min_wall` from edges and holes.
A router's round bit cannot cut a square inside corner: `relief = "dogbone"` (the built-in
router's default: along the bisector) or `"tbone"` (along the longer side) runs it in until
its edge touches every inside corner of the joints; `relief = "none"` warns W0527 naming the
corners (and the assembled fit of the routed parts, W0517). A relief is cut only where it takes
at most a disc of the bit's radius beside its corner and keeps the part whole: not at a corner
sharper than 60 deg, nor where it would cut through or thin a wall below `min_wall` (a T-bone
there becomes a dogbone if that fits); W0527 at the hole names each such corner and why. `Countersink` / `Counterbore`
holes: a router sinks them after the through-cuts with a V-bit (`v_bit_angle`, 90 deg) or
pockets them (`pocket_tool` mm; 0: `tool_diameter`); a laser engraves the head's circle on a
layer of its own (`countersink`, `counterbore`).
""", ["gcode", "g-code", "grbl", "--machine", "machine profile", "cnc", "router", "toolpath",
      "nc", "dogbone", "t-bone", "tbone", "relief", "inside corner"]),
    "assembled": ("statement", "The assembled product: parts placed in 3D with `Place`, "
                  "written by `aidl render --assembled`, checked for fit.", """
`Place(part, position=(x, y, z), rotation=(rx, ry, rz))` in the assembly that holds the part
(or an assembly) places it in 3D: its point (x, y) of the sheet, relative to its frame, with z
up through its `thickness`, is turned about x, then y, then z and moved by `position`
(lengths and angles known before solving; a part is placed once). `Place(vane, on=top,
position=(20, -27), face="front", up="up")` gives the position and turn in part `top`'s own
frame (x, y as drawn in it, z up from its bottom face; two numbers: on its top face), so the
vane follows the top wherever it is placed. Unplaced parts stay as on the sheet. `aidl render FILE --assembled -o box.3mf` (or .step, .glb, .stl; .png for a
picture) writes every part extruded and placed, one named object per part. The fit check
warns W0517 when two placed parts collide (a slot narrower than its partner's thickness, with
the figure) and W0518 when a part touches no other (a tab short of its slot, with the gap).
`finger_box` in std/joints.aidl places its panels; examples/phone_stand.aidl is a
cross-halving joint. `Bend(part, at=x, angle=a, radius=r)` bends a part (a living hinge) in
the assembled product only (`flex_box` in std/boxes.aidl bends its wall round the corners).
""", ["assembly 3d", "3d", "place", "placement", "assemble", "fit check", "collision", "W0517",
      "W0518"]),
    "outputs": ("statement", "`aidl render FILE -o x.svg` (.dxf, .pdf, .png, .stl, .3mf, "
                ".step, .glb): the format follows the extension.", """
`aidl render FILE -o OUT` writes each output, the format by its extension: `.svg` and `.dxf`
(exact outlines for laser cutters and CNC), `.pdf` (a 1:1 printed template for a scroll saw or
hand cutting: exact lines, arcs as Béziers within 0.001 mm, part names, a 100 mm scale bar to
check before cutting), `.png` (a picture), `.stl`, `.3mf`, `.step`, `.glb` (3D). A PDF is one
page the drawing's size; `--page A4` (A3, Letter, Legal, each also `-landscape`, e.g.
`--page A4-landscape`) tiles it over paper with 10 mm overlaps, alignment marks and page
labels (A1, A2 / B1); print at 100 %. `--layout sheet` writes one file per cutting sheet.
""", ["output", "formats", "format", "pdf", "page", "print", "printed template", "scroll saw",
      "render"]),
    "solid": ("statement", "`solid NAME { ... }`: filled material, minus its hole children.", """
`solid NAME { ... }`: the union of its own shapes and its solid children (touching or
overlapping shapes merge into one outline), minus its `hole` children. A hole cuts the solid
it is declared in: that solid's own shapes and its solid children. The cut solid is then
united with its own siblings in the parent, which are not cut (they can cover the opening).
Material the model wants to keep in an opening goes outside the solid that holds the hole.
""", ["structure", "part", "body"]),
    "hole": ("statement", "`hole NAME { ... }`: a cut-out of the enclosing solid.", """
`hole NAME { ... }` inside a solid: the union of its shapes and children is cut from the
enclosing solid (its own shapes and its solid children). A sibling of the enclosing solid is
not cut: it can cover the opening (warning W0501; `AllowOverlap` when meant). A hole at the
top level or directly in an assembly is drawn as a dashed outline. The hole's shapes count
in the enclosing structure's `.bb`, but for a shape written `overrun=true`: the part of a cut
drawn past the part's edge so that it opens cleanly (a slot run 1 mm out through the edge),
cut as drawn and left out of the boxes, so `AlignTop(slot, body)` still puts the slot's
mouth on the edge.
""", ["cutout", "cut-out", "opening", "pocket", "overrun"]),
    "cut": ("statement", "`cut NAME { ... }`: through-cuts along curves, open or closed.", """
`cut NAME { ... }` inside a solid: the laser cuts along each of its curves exactly as written
(Line, Arc, Bezier, Spline, Polyline; open or closed), through the part. An open curve takes
no area (zero width: a slit, a living hinge's cut, a relief cut), so the part's outline and
its 3D view are unchanged, unless the cut separates material: one that runs from edge to edge,
or closes a loop with the outline, itself or another cut, frees the piece, which becomes a
part of its own (or falls out as a hole when enclosed). A closed curve cuts a hole. Outputs
cut it on the part's cut layer, before the part's holes and outline, once along the line;
`--kerf` leaves it where it is (a line has no side). A cut belongs in a solid (E0125), or
directly in an assembly, beside the parts: a sheet-level cut, cut where it is drawn in no part
(scrap lines, the rest of a slot drawn across a plate's edge; `aidl import` writes cut paths
that lie in no part so; `--layout` leaves it out, with a note); across a part's material it is
W0525 (move it into that solid). `cut` stays usable as an ordinary name. W0522: a cut off the
material; W0507: a web thinner than the minimum wall between cuts. Templates may return it: `def f(...) -> cut`,
`cut c = f(...)`.
""", ["slit", "through-cut", "through cut", "cut line", "kerf cut", "relief cut",
      "sheet-level cut", "sheet cut"]),
    "drawing": ("statement", "`drawing NAME { ... }`: engraved lines and text (`fill=true`: "
                "a closed shape's or a font's area).", """
`drawing NAME { ... }`: its shapes are drawn as lines (closed shapes as outlines) and Text as
single strokes (with `font=`: the letters' outlines; with `font=` and `fill=true`: the letters'
area, on a fill layer), on the `engrave` layer; a closed shape with `fill=true` (a Circle, a
Polygon, a closed Spline, a Stroke, ...) is its area engraved filled, on the fill layer
(domino pips, a sign's solid border: a `Shell`); nothing else is filled, nothing is cut. Text
is only allowed in a drawing (a Text with `font=` also in a solid, as material,
and a hole, as openings). Put it inside the solid it marks. A `hole` in a drawing hides the drawing's lines
(its own and its children's) where it covers them, and draws no line of its own: a shape in front of
another is the hole in the back's drawing and its own drawing beside that one (`drawing back {
p = Polygon(...) hole cover { q = Polygon(...) } }` then `drawing front { q = Polygon(...) }`);
one that hides nothing is W0526. The solid's
holes hide none: its lines run across them (W0505) unless the drawing has its own `hole` there.
""", ["engraving", "engrave", "label", "mark", "engraving minus engraving", "hide lines"]),
    "assembly": ("statement", "`assembly NAME { ... }`: separate parts.", """
`assembly NAME { ... }`: each child is a separate part, drawn where the solver puts it
(parts may overlap); `aidl render --layout sheet` lays them out flat for cutting. Its own
shapes form one part.
""", ["parts", "kit"]),
    "for": ("statement", "`for i in range(n) { ... }`: repetition.", """
`for NAME in LIST { ... }` (`range(n)`, `range(a, b)`, a list): runs the body once per item;
names defined in the loop become lists (`knob[0]`), structures too (`bolt[2].c`). Also list
comprehensions: `[f(i) for i in range(n) if c]`, several `for`s one flat list as in Python
(`[(x, y) for x in xs for y in ys]`). For copies of a shape see LinearPattern,
CircularPattern, GridPattern.
""", ["loop", "range", "in", "repeat"]),
    "if": ("statement", "`if c { } else { }`: choice on values known before solving.", """
`if CONDITION { ... } elif CONDITION { ... } else { ... }` on values known before solving
(params, constants, template parameters). In expressions: `a if c else b`.
""", ["elif", "else", "conditional"]),
    "equations": ("statement", "`a.width == 20`, `x <= 60`: equations and inequalities as "
                  "constraints.", """
A comparison written as a statement in a structure is a constraint the solver makes true:
`==`, `<=`, `>=` (`<`, `>` mean `<=`, `>=`) between numbers, lengths, angles, or points
(`p == q`, `p == (0, 0)`, `c.center == r.bottom_right + (0, 4)`); chains (`0 <= x <= 10`) and
`and` join several. `or` and `!=` cannot be constraints. To check without solving, write
`assert`.
""", ["equation", "==", "<=", ">=", "inequality", "constraint"]),
    "bb": ("statement", "`x.bb`: the bounding box of a shape or structure.", """
Every shape and structure has `.bb`, its axis-aligned bounding box: `left`, `right`, `top`,
`bottom` (coordinates), `width`, `height` (lengths), `center_x`, `center_y`, `center`,
`top_left`, `top_right`, `bottom_left`, `bottom_right` (points). A structure also answers
`s.width`, `s.left`, `s.center`, ... with its box. A shape's box is the box of the shape as
drawn, within 1e-6 mm: a RoundedRectangle's arcs, a stencil's openings, an `Inset`'s, a
`Shell`'s, an `Intersect`'s outline (not its shape's box grown). A structure's box covers all
its geometry and descendants, holes included: a hole that pokes out past the outline widens it
(construction geometry is left out, and so is a shape drawn with `overrun=true`, a cut's run
past the edge: a joint template's box is its cut within the panel). For the material only, use
a shape's box
(`plate.body.bb`). Structural relations (Above, Inside, ...) work on boxes. `self` is the
current structure: `CenterInside(bore, self)`, `self.bb.width <= 60`.
""", ["bbox", "bounding box", "boundingbox", "self", "box", "members"]),
    "comments": ("statement", "`# a comment`; `//` after an operand is floor division.", """
`# text` and `/* text */` are comments. `//` is floor division when the code before it on
the line ends an operand (a name, number, string, `)` or `]`) and the rest of the line does not
read as prose (`7 // 2` is 3; `80 mm // 3` is 26 mm, warning W0106 when it becomes a length);
otherwise it starts a comment (`// note` on its own line, `x = f(a) // half of it`). Write
`#` for comments and `/` for division.
""", ["comment", "#", "//", "floor division"]),
    "functions": ("statement", "sin, cos, sqrt, min, max, range, ...: functions and "
                  "constants.", "\n".join(
        [f"`{n}`: {doc}" for n, (_lo, _hi, doc) in FUNCTIONS.items()]
        + ["Constants: pi, tau (radians: `aidl docs pi`), true, false. Functions take no "
           "keyword arguments, but `mirror(points, about=...)`."]),
        ["function list", "math"]),
    "pi": ("statement", "`pi`, `tau`: numbers that count radians; next to an angle `pi` is "
           "180 deg.", """
`pi` (also `PI`) is 3.14159..., `tau` is 2 pi: plain numbers in arithmetic (`2 * pi * r` is a
circumference, `sin(pi / 6)` is 0.5), not angles. They count radians: where `pi`, `tau` or a
number made from them (`2 * pi / n`, `pi * module / pitch_r`, `tau - 0.1`) meets an angle (in
`+`, `-`, a comparison, `min`/`max`, or given for an angle: `rotation=pi / 4`), it is that many
radians, where any other bare number is degrees: `theta + pi / 2` is `theta + 90 deg`, and
`theta + k * (tau - 2 * theta) / n` steps from `theta` to a whole turn less `theta`. `pi / pi`
is a plain number again. `180 deg`, `360 deg` or `tau * 1 rad` say the same explicitly.
Conversions: a number of radians as an angle is `x * 1 rad` (`0.5 rad` for a literal); a
number of degrees `radians(x)` (or `x * 1 deg`); an angle as a number of degrees `degrees(a)`;
an angle from a ratio `atan(y / x)` or `atan2(y, x)`. There is no `rad()` or `deg()`.
""", ["PI", "tau", "constants", "rad", "radians", "degrees", "conversion"]),
}
