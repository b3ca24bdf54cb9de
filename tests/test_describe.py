"""`aidl check --describe`, `Result.describe()` (aidl_lang/output/checks/reports/describe.py): the final part
in words and numbers, read from the exact output model."""
import json
from pathlib import Path

import pytest

import aidl_lang
from aidl_lang.cli.main import main

ROOT_EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

PLATE = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole bore { c = Circle(center=(10, 5), diameter=6) }
    hole slot { s = Slot(start=(-15, -5), end=(-5, -5), width=4) }
    drawing marks { label = Text(position=(5, -6), text="AB", size=4) }
}
"""


def test_a_plate_with_a_hole_and_a_slot_is_described_as_exactly_that():
    r = aidl_lang.compile(source=PLATE)
    doc = r.description
    (p,) = doc["parts"]
    assert p["name"] == "plate" and p["size"] == [40, 20] and p["box"] == [-20, -10, 20, 10]
    assert p["outline"][0]["kind"] == "rectangle" and (p["outline"][0]["w"],
                                                      p["outline"][0]["h"]) == (40, 20)
    circle, slot = p["openings"]              # from the top down
    assert circle["kind"] == "circle" and circle["d"] == 6 and circle["center"] == [10, 5]
    assert slot["kind"] == "slot" and (slot["w"], slot["l"]) == (4, 14)
    assert slot["center"] == [-10, -5] and slot["angle"] == 0
    (t,) = p["engravings"]
    assert t["kind"] == "text" and t["text"] == "AB" and t["size"][1] == 4
    assert not p["copies"]
    assert not p["symmetry"]["mirror_x"] and p["symmetry"]["rotation"] == 1
    text = r.describe()
    assert "circle d=6 at (10, 5)" in text and "slot 14 long, 4 wide at (-10, -5)" in text
    assert "part `plate`: 40 x 20 mm, from (-20, -10) to (20, 10)" in text
    assert 'text "AB"' in text


def test_symmetries_and_copies():
    r = aidl_lang.compile(source="""units mm
assembly kit {
    solid a {
        body = Rectangle(center=(0, 0), width=40, height=20)
        for i in range(4) {
            hole h { c = Circle(center=((i % 2) * 30 - 15, (i // 2) * 10 - 5), radius=2) }
        }
    }
    solid b {
        body = RegularPolygon(center=(60, 0), radius=10, sides=6)
    }
    solid c {
        body = RegularPolygon(center=(90, 0), radius=10, sides=6)
    }
}
""")
    a, b = r.description["parts"]             # c is a copy of b: listed under it, by place
    assert a["symmetry"] == {"center": [0, 0], "mirror_x": True, "mirror_y": True,
                             "rotation": 2}
    assert len(a["openings"]) == 4 and all(o["d"] == 4 for o in a["openings"])
    assert b["symmetry"]["rotation"] == 6 and b["symmetry"]["center"] == [60, 0]
    assert b["outline"][0]["kind"] == "polygon" and b["outline"][0]["n"] == 6
    assert a["copies"] == [] and a["same_shape"] == 1 and (a["shape"], b["shape"]) == (1, 2)
    assert b["same_shape"] == 2 and b["copies"] == [{"name": "kit.c",
                                                     "box": [80, -8.66, 100, 8.66]}]
    assert r.description["count"] == {"parts": 3, "shapes": 2}
    text = r.describe()
    assert "6-fold rotation about (60, 0)" in text
    assert "  1 more part of this shape (copies, not described again), at:\n" \
           "    `kit.c` from (80, -8.66) to (100, 8.66)" in text
    assert text.endswith("3 parts, 2 shapes")


# n equal circles, each a part of its own, 3 mm apart
CIRCLES = """assembly sheet {{
    for i in range({n}) {{
        solid p {{
            c = Circle(center=(i * 3, 0), radius=1)
        }}
    }}
}}
"""


@pytest.mark.timing
@pytest.mark.usefixtures("cpu_clock")    # 1,500 parts under the default budget
def test_copies_are_described_once_with_their_places(tmp_path, capsys):
    """6,000 equal circles: every part listed its 5,999 copies (`--describe --json` wrote
    970 MB in 89 s and 4.4 GB); now the first is described and the others are its copies,
    each once with its place, so the description grows with the parts, not their square:
    1,500 circles write less than 400 bytes a part (the old list: 1,499 names a part)."""
    n = 1500
    f = tmp_path / "sheet.aidl"
    f.write_text(CIRCLES.format(n=n))
    assert main(["check", str(f), "--describe", "--json"]) == 0
    out = capsys.readouterr().out
    assert len(out) < 400 * n, len(out)
    doc = json.loads(out)["describe"]
    (p,) = doc["parts"]
    assert p["name"] == "sheet.p[0]" and p["same_shape"] == n and len(p["copies"]) == n - 1
    assert p["outline"][0]["kind"] == "circle" and p["outline"][0]["d"] == 2
    assert [c["name"] for c in p["copies"]] == [f"sheet.p[{k}]" for k in range(1, n)]
    assert all(c["box"] == [3 * k - 1, -1, 3 * k + 1, 1]
               for k, c in enumerate(p["copies"], start=1))
    assert doc["count"] == {"parts": n, "shapes": 1}
    assert main(["check", str(f), "--describe"]) == 0
    text = capsys.readouterr().out
    assert text.count("\n    `sheet.p[") == n - 1 and text.count("part `") == 1
    assert f"{n - 1} more parts of this shape" in text and "`sheet.p[1499]` from (4496, -1) " \
        "to (4498, 1)" in text


def test_a_copy_with_its_own_engraving_is_described_in_full():
    """A copy is folded into the first part of its shape only when it has nothing of its own:
    a tag with its own text is described again (its engraving kept), naming the first."""
    r = aidl_lang.compile(source="""units mm
assembly kit {
    solid a { body = Rectangle(center=(0, 0), width=20, height=10) }
    solid b {
        body = Rectangle(center=(30, 0), width=20, height=10)
        drawing m { t = Text(position=(30, 0), text="B", size=4) }
    }
    solid c { body = Rectangle(center=(60, 0), width=20, height=10) }
    solid d {
        thickness 6 mm
        body = Rectangle(center=(90, 0), width=20, height=10)
    }
}
""")
    assert r.ok, [d.message for d in r.diagnostics]
    parts = {p["name"]: p for p in r.description["parts"]}
    assert set(parts) == {"kit.a", "kit.b", "kit.d"}
    assert [c["name"] for c in parts["kit.a"]["copies"]] == ["kit.c"]
    assert parts["kit.b"]["copy_of"] == "kit.a" and parts["kit.b"]["engravings"][0]["text"] == "B"
    assert parts["kit.d"]["copy_of"] == "kit.a" and parts["kit.d"]["thickness"] == 6
    assert all(p["shape"] == 1 and p["same_shape"] == 4 for p in parts.values())
    assert "the same shape as `kit.a` (described again" in r.describe()


def test_a_36_tooth_gear_has_36_fold_symmetry():
    r = aidl_lang.compile(source="""import "std/gears.aidl"
g = spur_gear(teeth=36, module=1.5 mm, bore=8 mm)
""", path="examples/x.aidl")
    (g,) = r.description["parts"]
    assert g["symmetry"]["rotation"] == 36 and g["size"] == [1.5 * 38] * 2
    assert g["openings"] == [{"kind": "circle", "center": [0, 0], "size": [8, 8], "d": 8}]


def test_check_describe_text_and_json(tmp_path, capsys):
    f = tmp_path / "plate.aidl"
    f.write_text(PLATE)
    assert main(["check", str(f), "--describe"]) == 0
    out = capsys.readouterr().out
    assert "circle d=6 at (10, 5)" in out and "symmetry: none found" in out
    assert main(["check", str(f), "--describe", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["describe"]["parts"][0]["openings"][0]["d"] == 6


def test_the_openings_are_counted_in_plural_words():
    """`12 openings (10 circles, 2 slots)`, not `10 circle, 2 slot`; one of a kind singular."""
    r = aidl_lang.compile(path=str(ROOT_EXAMPLES / "mounting_plate.aidl"))
    assert "12 openings (10 circles, 2 slots):" in r.describe()
    r = aidl_lang.compile(source="""import "std/gears.aidl"
g = spur_gear(teeth=12, module=2 mm, bore=6 mm)
""", path="examples/x.aidl")
    assert "1 opening (1 circle):" in r.describe()


KINDS = """units mm
assembly kit {
    solid star { s = Star(center=(0, 0), points=6, outer_radius=30, inner_radius=15) }
    solid turned { s = Star(center=(0, -80), points=5, outer_radius=20, inner_radius=8,
                            rotation=10 deg) }
    solid slot { s = Slot(start=(50, 0), end=(80, 0), width=8) }
    solid rr { r = RoundedRectangle(center=(0, 50), width=40, height=20, corner_radius=3) }
    solid el { e = Ellipse(center=(60, 50), rx=15, ry=8) }
    solid ci { c = Circle(center=(100, 50), diameter=12) }
    solid arc { a = ArcSlot(center=(0, 100), radius=20, width=6, start_angle=0 deg,
                            end_angle=90 deg) }
    solid tag {
        b = Rectangle(center=(100, 100), width=60, height=40)
        hole cut { s = Star(center=(110, 105), points=5, outer_radius=8, inner_radius=3) }
        drawing d { t = Text("OK", position=(85, 90), size=5) }
    }
}
"""


def test_shapes_are_named_after_the_primitive_that_drew_them():
    """A star is its points and radii, not a "12-gon 51.962 x 60"; a slot its length and
    width; a rounded rectangle its corner radius; an ellipse its axes; an arc slot its
    centre line; a text its string and height (issue 51)."""
    r = aidl_lang.compile(source=KINDS)
    parts = {p["name"]: p for p in r.description["parts"]}
    (star,) = parts["kit.star"]["outline"]
    assert {k: star[k] for k in ("kind", "points", "outer_radius", "inner_radius", "angle",
                                 "center")} == {"kind": "star", "points": 6, "outer_radius": 30,
                                                "inner_radius": 15, "angle": 0,
                                                "center": [0, 0]}
    (arc,) = parts["kit.arc"]["outline"]
    assert {k: arc[k] for k in ("kind", "radius", "width", "start_angle", "sweep", "center")} \
        == {"kind": "arc slot", "radius": 20, "width": 6, "start_angle": 0, "sweep": 90,
            "center": [0, 100]}
    (hole,) = parts["kit.tag"]["openings"]
    assert hole["kind"] == "star" and hole["points"] == 5 and hole["center"] == [110, 105]
    (t,) = parts["kit.tag"]["engravings"]
    assert t["text"] == "OK" and t["height"] == 5
    text = r.describe()
    for line in ("outline: 6-point star, outer radius 30, inner 15 at (0, 0)",
                 "outline: 5-point star, outer radius 20, inner 8, turned 10 deg at (0, -80)",
                 "outline: slot 38 long, 8 wide at (65, 0)",
                 "outline: rounded rectangle 40 x 20, corner radius 3 at (0, 50)",
                 "outline: ellipse with axes 30 x 16 at (60, 50)",
                 "outline: circle d=12 at (100, 50)",
                 "outline: arc slot radius 20, 6 wide, from 0 to 90 deg about (0, 100)",
                 "1 opening (1 star):",
                 "    5-point star, outer radius 8, inner 3 at (110, 105)",
                 'engraving: text "OK" 5 high at '):
        assert line in text, (line, text)
    assert "-gon" not in text


def _plain(x, where="describe"):
    """``x`` holds only JSON's own Python types (a NumPy scalar is not one: json refuses it)."""
    if isinstance(x, dict):
        for k, v in x.items():
            assert isinstance(k, str), where
            _plain(v, f"{where}.{k}")
    elif isinstance(x, list):
        for i, v in enumerate(x):
            _plain(v, f"{where}[{i}]")
    else:
        assert x is None or type(x) in (bool, int, float, str), (where, type(x))


def test_every_example_describes_itself_as_json(capsys):
    """`aidl check --describe --json` of every example: plain JSON.  The guitar body and the
    violin answered `internal error: TypeError: Object of type bool is not JSON serializable`
    (their symmetry test compared with a NumPy float: a NumPy bool)."""
    for f in sorted(ROOT_EXAMPLES.glob("*.aidl")):
        r = aidl_lang.compile(path=str(f))
        if not r.ok or not r.parts:
            continue
        _plain(r.description, f.name)
    for name in ("guitar_body.aidl", "violin.aidl"):
        assert main(["check", str(ROOT_EXAMPLES / name), "--describe", "--json"]) == 0
        doc = json.loads(capsys.readouterr().out)
        assert doc["describe"]["parts"][0]["symmetry"]["mirror_y"] is True, name


@pytest.mark.timing
@pytest.mark.usefixtures("cpu_clock")    # a 4,000-hole plate under the default budget
def test_turns_and_mirrors_the_moments_rule_out_are_not_tried(monkeypatch):
    """A turn changes the second moments of area by 2 d |sin t| and a mirror by 2 |Ixy|; an
    image within the tolerance can change them by at most tol r^2, so the others are not
    tried: a plate of 4,000 holes 4 m long spent 22 s in one uninterruptible boolean (its
    turn by 120 degrees) past every deadline; now 4 comparisons (the mirrors, a half turn and
    a turn too small to tell).  The symmetries of every example are those of trying all."""
    from aidl_lang.output.checks.reports import describe as D
    r = aidl_lang.compile(source="""solid plate {
    base = Rectangle(center=(0, 0), width=100, height=4000)
    for i in range(4000) {
        hole h { c = Circle(center=(0, i - 1999.5), radius=0.2 + i * 0.00005) }
    }
}
""")
    (p,) = r.output.parts
    tried = []
    got = D.symmetries(p, lambda: tried.append(1))
    assert got == {"center": [0.0, -1.246], "mirror_x": False, "mirror_y": True, "rotation": 1}
    assert len(tried) <= 4, len(tried)
    parts = []
    for f in sorted(ROOT_EXAMPLES.glob("*.aidl")):
        ex = aidl_lang.compile(path=str(f))
        if ex.ok:
            parts += [(f.name, q) for q in ex.output.parts]
    found = [D.symmetries(q) for _, q in parts]
    monkeypatch.setattr(D, "_moments", lambda shape: (0.0, 0.0, 0.0, 0.0))
    for (name, q), want in zip(parts, found):
        assert D.symmetries(q) == want, name
    assert sum(s["rotation"] != 1 or s["mirror_x"] or s["mirror_y"] for s in found) > 10
