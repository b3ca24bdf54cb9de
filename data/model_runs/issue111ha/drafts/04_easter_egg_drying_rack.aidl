# Request (holidays): "A drying rack for freshly dyed Easter eggs, so the paint doesn't smudge.
# Twelve eggs in 3 rows of 4, 55 mm apart each way. Each egg rests on the points of three
# cocktail sticks: three 2.2 mm holes on a 22 mm circle, 120 degrees apart, one pointing to the
# back. A 240 x 200 mm top plate and a same-size base plate, both 3 mm ply and both drilled,
# so the sticks pass through the top plate and stand on the table. Two legs hold the top plate
# 80 mm above the table (top face), glued with two 30 mm tabs into mortises in each plate,
# 10 mm in from the plate's short ends, the legs 180 mm wide. Engrave HAPPY EASTER (7 mm
# letters) along the top plate's front margin."

import "std/joints.aidl"

thickness 3 mm

param plate_w = 240 mm, min = 220 mm, max = 300 mm
param plate_d = 200 mm, min = 180 mm, max = 240 mm
param pitch = 55 mm, min = 50 mm, max = 65 mm
param pin_circle = 22 mm, min = 16 mm, max = 30 mm
param pin_d = 2.2 mm, min = 1.8 mm, max = 3 mm
param rack_h = 80 mm, min = 60 mm, max = 120 mm
param leg_w = 180 mm, min = 120 mm, max = 190 mm

rows = 3
cols = 4
leg_x = plate_w / 2 - 10 mm

def egg_plate(top=false) -> solid {
    body = Rectangle(center=(0, 0), width=plate_w, height=plate_d)
    hole spot {
        for k in range(3) {
            pin = Circle(center=polar((-(cols - 1) * pitch / 2, -(rows - 1) * pitch / 2),
                                      pin_circle / 2, 90 deg + k * 120 deg), diameter=pin_d)
        }
    }
    spots = GridPattern(spot, rows, cols, (pitch, pitch))
    left_mortise = tab_and_slot(part="slot", length=leg_w, thickness=3 mm, tabs=2, tab=30 mm,
                                screw=0, rotation=90 deg, cx=-leg_x, cy=0 mm)
    right_mortise = tab_and_slot(part="slot", length=leg_w, thickness=3 mm, tabs=2, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=leg_x, cy=0 mm)
    if top {
        drawing greeting {
            t = Text("HAPPY EASTER", position=(0, -plate_d / 2 + 10 mm), size=7,
                     valign="middle")
        }
    }
}

def leg() -> solid {
    body = Rectangle(center=(0, 0), width=leg_w, height=rack_h)
    top_tabs = tab_and_slot(part="tab", length=leg_w, thickness=3 mm, tabs=2, tab=30 mm,
                            screw=0, cx=0 mm, cy=rack_h / 2)
    bottom_tabs = tab_and_slot(part="tab", length=leg_w, thickness=3 mm, tabs=2, tab=30 mm,
                               screw=0, rotation=180 deg, cx=0 mm, cy=-rack_h / 2)
}

assembly egg_rack {
    top_plate = egg_plate(top=true)
    base_plate = egg_plate()
    left_leg = leg()
    right_leg = leg()

    # flat layout
    RightOf(base_plate, top_plate, gap=10 mm)
    AlignBottom(base_plate, top_plate)
    Below(left_leg, top_plate, gap=10 mm)
    AlignLeft(left_leg, top_plate)
    RightOf(right_leg, left_leg, gap=10 mm)
    AlignBottom(right_leg, left_leg)

    # assembled: base on the table, legs standing on it, the top plate on the legs
    Place(base_plate, position=(0, 0, 0), face="up")
    Place(top_plate, position=(0, 0, rack_h - 3 mm), face="up")
    Place(left_leg, position=(-leg_x - 1.5 mm, 0, rack_h / 2), face="right", up="up")
    Place(right_leg, position=(leg_x - 1.5 mm, 0, rack_h / 2), face="right", up="up")

    assert len(top_plate.spots) == 12, "twelve eggs"
    assert len(top_plate.spot.pin) == 3, "three sticks per egg"
    assert top_plate.spots[1].pin[0].center.x - top_plate.spots[0].pin[0].center.x == 55 mm, "55 mm across"
    assert top_plate.spots[4].pin[0].center.y - top_plate.spots[0].pin[0].center.y == 55 mm, "55 mm back"
    assert abs(distance(top_plate.spot.pin[0].center, top_plate.spot.pin[1].center) - 22 mm * sin(60 deg)) < 0.01 mm, "pins on a 22 mm circle"
    assert top_plate.body.bb.width == 240 mm and top_plate.body.bb.height == 200 mm, "240 x 200 plates"
    assert left_leg.body.bb.height == 80 mm, "top face 80 mm above the table"
    assert left_leg.body.bb.width == 180 mm, "legs 180 mm wide"
    assert top_plate.body.bb.right - top_plate.right_mortise.slot[0].bb.center_x == 10 mm, "mortises 10 mm in"
    assert distance(top_plate.greeting, top_plate.spots) >= 3 mm, "greeting clear of the pin holes"
}
