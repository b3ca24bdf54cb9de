"""Every standard-library template says which point ``(cx, cy)`` is and which way its
``rotation=0`` points, in one ``# Anchor:`` line above its ``def`` (issue 111: `aidl docs
cross_halving` said "the mouth at (cx, cy)" in its text and "the center's starting position"
in its parameters; two models put the slot's middle there and missed by 10 and 20 mm).

For each template (enumerated from ``stdlib/*.aidl``, so a new one joins the test; one without
the line fails) one program, through the real parser and solver, holds it at (0, 0) and at
(7, -5) (and turned by 90 deg, and as its other ``part``): the point the line names is measured
on what the compiler reports (the instance's or a member's box and points, or the parts as
cut) and must sit at (cx, cy) within 1e-6 mm, so it moved by exactly (7, -5); the direction
the line gives for rotation 0 is read off the box around that point, and rotation 90 deg must
give the same box turned counter-clockwise about (cx, cy).
"""
from __future__ import annotations

import math
from pathlib import Path
import re

import pytest

import aidl_lang
from aidl_lang.library.reference import ANCHOR_LINE, _in_stdlib, stdlib_templates

TOL = 1e-6
AT = (7.0, -5.0)
TEMPLATES = stdlib_templates()
# fewer teeth than the defaults where they cost the most (the anchor holds for any)
CHEAP = {"planetary": ["sun=12", "planet=12", "ring=36", "planets=2"],
         "gear_train": ["teeth=[10, 12]"], "spur_gear": ["teeth=10"],
         "ring_gear": ["teeth=24"], "gear_pair": ["teeth1=10", "teeth2=12"],
         "rack_and_pinion": ["teeth=10", "rack_teeth=4"]}
HOLDERS = {"hole": "solid", "cut": "solid", "drawing": "solid", "solid": "solid",
           "assembly": "assembly"}


class Measured:
    """One compiled instance ``w.NAME``: its values (mm) and its parts as cut."""

    def __init__(self, result, name: str, part: str | None):
        self.vals = {v.name: v.mm for v in result.values}
        self.parts = result.parts
        self.path = f"w.{name}"
        self.part = part

    def box(self, member: str = "") -> tuple[float, float, float, float]:
        return self.vals[f"{self.path}{'.' + member if member else ''}.bbox"]

    def cut_box(self, member: str) -> tuple[float, float, float, float]:
        """The union of the boxes of the parts ``member`` or ``member[i]`` as cut."""
        pre = f"{self.path}.{member}"
        boxes = [p.bbox for p in self.parts if p.name == pre or p.name.startswith(pre + "[")]
        assert boxes, f"no part named {pre}"
        return (min(b[0] for b in boxes), min(b[1] for b in boxes),
                max(b[2] for b in boxes), max(b[3] for b in boxes))


def _centre(b):
    return ((b[0] + b[2]) / 2, (b[1] + b[3]) / 2)


def _member_centre(m: Measured, member: str):
    p = m.vals.get(f"{m.path}.{member}.center")
    return tuple(p) if p is not None else _centre(m.box(member))


def _circumcentre(a, b, c):
    d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
    ux = ((a[0] ** 2 + a[1] ** 2) * (b[1] - c[1]) + (b[0] ** 2 + b[1] ** 2) * (c[1] - a[1])
          + (c[0] ** 2 + c[1] ** 2) * (a[1] - b[1])) / d
    uy = ((a[0] ** 2 + a[1] ** 2) * (c[0] - b[0]) + (b[0] ** 2 + b[1] ** 2) * (a[0] - c[0])
          + (c[0] ** 2 + c[1] ** 2) * (b[0] - a[0])) / d
    return ux, uy


def _edge_middle(m: Measured):
    b = m.box()
    return ((b[0] + b[2]) / 2, b[3])


# every point an Anchor line may name, and how it is measured (at rotation 0)
POINTS = [
    (r"the centre of its box|of the slots", lambda m, g: _centre(m.box())),
    (r"the centre of `([\w.\[\]]+)`", lambda m, g: _member_centre(m, g[1])),
    # the cut opens the edge: its box ends there (its 1 mm `overrun` past the edge counts in
    # no box, issue 111)
    (r"the middle of (?:its mouth on )?the edge", lambda m, g: _edge_middle(m)),
    (r"the middle of its bottom edge", lambda m, g: (_centre(m.box())[0], m.box()[1])),
    # both parts' cuts start on the line (the socket's 1 mm before it is its `overrun`)
    (r"the middle of the tails' roots \(the socket panel's edge\)",
     lambda m, g: (_centre(m.box())[0], m.box()[1])),
    (r"the middle of the `(\w+)`s' bottom edge",
     lambda m, g: (_centre(m.cut_box(g[1]))[0], m.cut_box(g[1])[1])),
    (r"the centre of the circle its baselines follow",
     lambda m, g: _circumcentre(*(m.vals[f"{m.path}.ch[{i}].position"] for i in range(3)))),
]


def _measure(phrase: str, m: Measured):
    for pattern, how in POINTS:
        g = re.fullmatch(pattern, phrase)
        if g:
            return how(m, g)
    raise AssertionError(f"no measurement for the anchor {phrase!r}: add it to POINTS")


def _points_by_part(point: str) -> dict[str | None, str]:
    """``the middle of the edge (part "slot": of the slots)``: {None: main, "slot": alt}."""
    out = {}
    for g in re.finditer(r' \(part "(\w+)": ([^)]*)\)', point):
        out[g[1]] = g[2]
    out[None] = re.sub(r' \(part "\w+": [^)]*\)', "", point)
    return out


def _parts_of(t) -> list[str]:
    """The values of a template's `part` parameter, from its own assert (`part == "tab"`)."""
    if "part" not in [p[0] for p in t.params]:
        return []
    src = (Path(t.node.span.file).read_text(encoding="utf-8")
           .splitlines()[t.node.span.line - 1:t.node.span.end_line])
    return list(dict.fromkeys(re.findall(r'part == "(\w+)"', "\n".join(src))))


def _turned(b, about):
    """Box ``b`` turned 90 deg counter-clockwise about ``about``."""
    (x0, y0, x1, y1), (cx, cy) = b, about
    return (cx - (y1 - cy), cy + (x0 - cx), cx - (y0 - cy), cy + (x1 - cx))


def _direction_checks(turn: str, b, about) -> list[str]:
    """What the rotation-0 direction says, read off the box ``b`` around ``about``: a list of
    failures; a phrase that gives nothing to check is one."""
    reach = {"+x": b[2] - about[0], "-x": about[0] - b[0], "+y": b[3] - about[1],
             "-y": about[1] - b[1]}
    bad, checked = [], 0
    for sign, axis in re.findall(r"toward ([+-])([xy])", turn):
        d, o = sign + axis, ("-" if sign == "+" else "+") + axis
        checked += 1
        if not reach[d] > reach[o] + 0.5:
            bad.append(f"{turn!r}: reaches {reach[d]:.3f} mm toward {d}, {reach[o]:.3f} toward {o}")
    if re.search(r"along x|flats at top and bottom", turn):
        checked += 1
        if not b[2] - b[0] > b[3] - b[1]:
            bad.append(f"{turn!r}: the box is {b[2] - b[0]:.3f} wide, {b[3] - b[1]:.3f} tall")
    return bad if checked else [f"no check for the direction {turn!r}"]


def test_every_template_has_one_anchor_line():
    assert len(TEMPLATES) >= 38
    for t in TEMPLATES.values():
        assert "cx" in [p[0] for p in t.params], t.name
        assert t.anchor, f"{t.name}: no `# Anchor: (cx, cy) is ...` line above its def"
        assert ("rotation" in [p[0] for p in t.params]) == bool(t.turn), \
            f"{t.name}: a rotation parameter and a `rotation 0:` clause go together"
        assert "Anchor:" not in t.doc, t.name           # said once, in its own line
        assert _in_stdlib(t.node, t)
        assert ANCHOR_LINE.fullmatch("Anchor: " + t.anchor_text + ".")


@pytest.mark.parametrize("name", list(TEMPLATES))
def test_the_anchor_is_where_its_line_says(name, tmp_path):
    t = TEMPLATES[name]
    kind = t.node.kind
    rotates = bool(t.turn)
    parts = _parts_of(t) or [None]
    calls = []      # (instance, part, (cx, cy), rotation)
    for i, part in enumerate(parts):
        for j, (at, rot) in enumerate([((0.0, 0.0), 0), (AT, 0)] + ([(AT, 90)] if rotates else [])):
            calls.append((f"p{i}r{j}", part, at, rot))
    lines = [f'import "std/{t.module}.aidl"', f"{HOLDERS[kind]} w {{"]
    if kind in ("hole", "cut", "drawing"):
        lines.append("    body = Rectangle(center=(0, 0), width=600, height=600)")
    for inst, part, (x, y), rot in calls:
        args = (CHEAP.get(name, []) + ([f'part="{part}"'] if part else [])
                + ([f"rotation={rot} deg"] if rotates else []))
        lines.append(f"    {inst} = {name}({', '.join(args + [f'cx={x:g} mm', f'cy={y:g} mm'])})")
    lines.append("}")
    r = aidl_lang.compile(source="\n".join(lines) + "\n", path=str(tmp_path / "a.aidl"))
    assert r.ok, [d.message for d in r.errors]
    by_part = _points_by_part(t.anchor)
    for inst, part, at, rot in calls:
        if rot:
            continue
        m = Measured(r, inst, part)
        p = _measure(by_part.get(part, by_part[None]), m)
        assert math.dist(p, at) < TOL, (name, part, t.anchor, p, at)
    if not rotates:
        return
    for i, part in enumerate(parts):
        b0 = Measured(r, f"p{i}r1", part).box()
        b90 = Measured(r, f"p{i}r2", part).box()
        if i == 0:      # the direction as said, of the default part
            assert not _direction_checks(t.turn, b0, AT), _direction_checks(t.turn, b0, AT)
        want = _turned(b0, AT)
        assert max(abs(a - b) for a, b in zip(b90, want)) < TOL, (name, part, b90, want)


def test_docs_and_prompt_say_the_anchor_not_a_centre(tmp_path):
    """`aidl docs` glosses cx, cy and rotation by the Anchor line (no "center's starting
    position" for a template whose point is not a centre), the prompt carries it as `@ ...`,
    and an E0105 hint on a stdlib template says it too."""
    from aidl_lang.library.reference import lookup_text
    from aidl_lang.llm.prompt import system_prompt
    text, found = lookup_text("cross_halving")
    assert found
    params = text.split("Parameters:")[1].split("Units:")[0]
    assert "starting position" not in params and "center" not in params
    assert "cx = 0 mm: a length; the x of (cx, cy), the middle of its mouth on the edge" in text
    assert "rotation = 0 deg: an angle; at 0: the slot runs toward -y; more turns it " \
        "counter-clockwise about (cx, cy)" in text
    prompt = system_prompt(examples=False)
    line = next(ln for ln in prompt.splitlines() if ln.startswith("- cross_halving("))
    assert line.endswith("@ middle of its mouth on the edge; rotation 0: the slot runs toward -y.")
    line = next(ln for ln in prompt.splitlines() if ln.startswith("- spur_gear("))
    assert line.endswith("@ `hub`.")
    src = ('import "std/shapes.aidl"\nsolid part {\n    t = rounded_tab(width=20 mm, lenght=30 mm)\n}\n')
    r = aidl_lang.compile(source=src, path=str(tmp_path / "a.aidl"))
    hint = next(d.hint for d in r.diagnostics if d.code == "E0105")
    assert "cx, cy: (cx, cy) is the middle of its bottom edge" in hint


def test_the_stdlib_page_tables_every_anchor_as_its_line_says():
    """docs/stdlib.md's table of anchors is the Anchor lines, row for row."""
    page = (Path(__file__).resolve().parents[1] / "docs" / "stdlib.md").read_text(encoding="utf-8")
    for t in TEMPLATES.values():
        assert f"| `{t.name}` | {t.anchor} | {t.turn} |" in page, t.name
