# Request (kitchen): a stand that holds a piping bag open while it is filled, in 4 mm
# ply. A 130 x 130 base and a 130 x 130 top, both with R10 corners; the top has a 70 mm
# hole in its centre for the bag. Two side panels 100 wide and 200 tall overall (tenon
# tip to tenon tip) stand 110 apart (centre to centre) between them, each glued with two
# 20 mm tenons into mortises in the top and two in the base; each side has a 40 x 120
# slot window in its middle. Engraved around the bag hole, on a 42 mm radius: ICING over
# the top and STATION under it, 6 mm letters. Four parts.

import "std/joints.aidl"

thickness 4 mm

def side() -> solid {
    body = Rectangle(center=(0, 0), width=100, height=200)
    top_tenons = tab_and_slot(part="tab", length=100 mm, thickness=4 mm, tabs=2, tab=20 mm,
                              screw=0, rotation=0 deg, cx=0 mm, cy=100 mm)
    bottom_tenons = tab_and_slot(part="tab", length=100 mm, thickness=4 mm, tabs=2,
                                 tab=20 mm, screw=0, rotation=180 deg, cx=0 mm, cy=-100 mm)
    hole window {
        w = Slot(center=(0, 0), length=120, width=40, rotation=90)
    }
}

def plate_with_mortises() -> solid {
    body = RoundedRectangle(center=(0, 0), width=130, height=130, corner_radius=10)
    left_mortise = tab_and_slot(part="slot", length=100 mm, thickness=4 mm, tabs=2,
                                tab=20 mm, screw=0, rotation=90 deg, cx=-55 mm, cy=0 mm)
    right_mortise = tab_and_slot(part="slot", length=100 mm, thickness=4 mm, tabs=2,
                                 tab=20 mm, screw=0, rotation=90 deg, cx=55 mm, cy=0 mm)
}

assembly stand {
    base = plate_with_mortises()
    solid top {
        plate = plate_with_mortises()
        hole bag {
            c = Circle(center=(0, 0), diameter=70)
        }
        drawing words {
            ring = Circle(center=(0, 0), radius=42, construction=true)
            over = Text("ICING", along=ring, size=6)
            under = Text("STATION", along=ring, size=6, flip=true)
        }
    }
    left_side = side()
    right_side = side()

    # flat on the sheet: a row
    RightOf(top, base, gap=10)
    AlignTop(top, base)
    RightOf(left_side, top, gap=10)
    AlignTop(left_side, top)
    RightOf(right_side, left_side, gap=10)
    AlignTop(right_side, left_side)

    # in 3D: base on the table, sides through it, top over them
    Place(base, position=(0, 0, 0), face="up")
    Place(left_side, position=(-53, 0, 100), face="left", up="up")
    Place(right_side, position=(53, 0, 100), face="right", up="up")
    Place(top, position=(0, 0, 196), face="up")

    assert base.body.bb.width == 130 mm and base.body.bb.height == 130 mm, "base 130 x 130"
    assert top.plate.body.bb.width == 130 mm, "top 130 wide"
    assert top.bag.c.diameter == 70 mm, "bag hole 70"
    assert left_side.body.bb.height == 200 mm and left_side.body.bb.width == 100 mm,
        "sides 100 x 200"
    assert base.right_mortise.bb.center_x - base.left_mortise.bb.center_x == 110 mm,
        "sides 110 apart"
    assert left_side.window.w.length == 120 mm and left_side.window.w.width == 40 mm,
        "window 40 x 120"
    assert top.words.ring.radius == 42 mm, "words on a 42 radius"
}
