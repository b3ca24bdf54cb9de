"""`aidl check --describe`, `Result.describe()` (aidl_lang/output/describe.py): the final part
in words and numbers, read from the exact output model."""
import json
from pathlib import Path

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
    assert "circle d=6 at (10, 5)" in text and "slot 4 x 14 at (-10, -5)" in text
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
    a, b, c = r.description["parts"]
    assert a["symmetry"] == {"center": [0, 0], "mirror_x": True, "mirror_y": True,
                             "rotation": 2}
    assert len(a["openings"]) == 4 and all(o["d"] == 4 for o in a["openings"])
    assert b["symmetry"]["rotation"] == 6 and b["symmetry"]["center"] == [60, 0]
    assert b["outline"][0]["kind"] == "polygon" and b["outline"][0]["n"] == 6
    assert b["copies"] == ["kit.c"] and c["copies"] == ["kit.b"]
    assert "6-fold rotation about (60, 0)" in r.describe()


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
