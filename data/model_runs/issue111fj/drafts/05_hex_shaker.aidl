# Request: a hexagonal percussion shaker (filled with rice or seeds), 3 mm ply.
# Six side slats 30 mm wide whose inner faces form a regular hexagon of 30 mm sides, 120 mm
# long between the end plates, each with one 14 mm tenon at both ends. Two hexagonal end
# plates 70 mm across the flats with a mortise for each slat (so a 6 mm rim stands past the
# slats); one end plate has a 10 mm filling hole in its centre (closed with a dowel plug).
# Each end plate has an engraved hexagon 44 mm across the flats; one slat carries "SHAKER"
# engraved filled along its length (sans bold, 12 mm).

units mm
thickness 3 mm

import "std/joints.aidl"

T = 3 mm
SIDE = 30 mm                       # inner hexagon's side = a slat's width
APO = SIDE * sqrt(3) / 2           # inner hexagon's apothem: the slats' inner faces
LEN = 120 mm                       # slat length between the end plates
END_AF = 70 mm
TENON = 14 mm

def normal(i) = 30 deg + i * 60 deg    # outward normal of side i (flats top and bottom)

def end_plate(fill=false) -> solid {
    body = RegularPolygon(center=(0, 0), across_flats=END_AF, sides=6)
    for i in range(6) {
        mortise = tab_and_slot(part="slot", length=SIDE, thickness=T, tabs=1, tab=TENON,
                               screw=0, rotation=normal(i) - 90 deg,
                               cx=(APO + T / 2) * cos(normal(i)), cy=(APO + T / 2) * sin(normal(i)))
    }
    if fill {
        hole filler { c = Circle(center=(0, 0), diameter=10 mm) }
    }
    drawing deco {
        hex = RegularPolygon(center=(0, 0), across_flats=44 mm, sides=6)
    }
}

# a slat drawn along y, its tenons at both ends
def slat(label=false) -> solid {
    body = Rectangle(center=(0, 0), width=SIDE, height=LEN + 2 * T)
    top_tenon = tab_and_slot(part="tab", length=SIDE, thickness=T, tabs=1, tab=TENON,
                             screw=0, cx=0, cy=LEN / 2 + T)
    bottom_tenon = tab_and_slot(part="tab", length=SIDE, thickness=T, tabs=1, tab=TENON,
                                screw=0, rotation=180 deg, cx=0, cy=-LEN / 2 - T)
    if label {
        drawing word {
            t = Text("SHAKER", position=(0, 0), size=12, font="sans:Bold", valign="middle",
                     rotation=90 deg, fill=true)
        }
    }
}

assembly hex_shaker {
    bottom = end_plate()
    top = end_plate(fill=true)
    for i in range(6) {
        side = slat(label=(i == 0))
    }

    # flat layout: the two plates side by side, the slats in a row under them
    RightOf(top, bottom, gap=5)
    AlignTop(top, bottom)
    Below(side[0], bottom, gap=5)
    AlignLeft(side[0], bottom)
    for i in range(1, 6) {
        RightOf(side[i], side[i - 1], gap=5)
        AlignTop(side[i], side[0])
    }

    # 3D: standing on its bottom plate, the axis along z
    Place(bottom, position=(0, 0, T), face="down")
    Place(top, position=(0, 0, T + LEN), face="up")
    for i in range(6) {
        Place(side[i], position=(APO * cos(normal(i)), APO * sin(normal(i)), T + LEN / 2),
              face=(cos(normal(i)), sin(normal(i)), 0), up="up")
    }

    assert len(side) == 6, "six slats"
    assert side[0].body.bb.width == 30 mm, "slats 30 wide"
    assert side[0].body.bb.height - 2 * T == 120 mm, "120 between the plates"
    assert bottom.body.across_flats == 70 mm, "end plates 70 across the flats"
    assert top.filler.c.diameter == 10 mm, "10 mm filling hole"
}
