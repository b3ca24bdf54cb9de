# Request (home): a low two-tier shoe rack for the hallway, for the children's shoes, cut from
# 6 mm birch ply on a 600 x 400 mm bed. Two side panels 250 mm deep x 300 mm tall, the top
# front corner rounded R60, a 90 x 30 mm hand hole near the top and an arch 150 mm wide x 20 mm
# high cut out of the bottom edge between the feet. Two shelves spanning 480 mm between the
# sides and 230 mm deep, the lower one resting 40 mm above the floor, the upper one 180 mm
# above it; each shelf has five 150 x 12 mm drain slots and two 60 mm glued tabs at each end
# into mortises in the sides. A back rail 60 mm tall at the top back (5 mm in from the back
# edge) with one 30 mm tab each end, engraved "LITTLE FEET" in bold filled letters.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm          # ply
SPAN = 480 mm     # between the sides
DEPTH = 230 mm    # shelf depth
SHELF_X = -5 mm   # shelf centre along the side (front at -125)

def side_panel() -> solid {
    body = RoundedRectangle(center=(0, 150), width=250, height=300,
                            corner_radii=[60, 0, 0, 0])
    hole feet { arch = Ellipse(center=(0, 0), rx=75, ry=20) }
    hole hand { grip = Slot(center=(0, 255), length=90, width=30) }
    lower = tab_and_slot(part="slot", length=DEPTH, thickness=T, tabs=2, tab=60 mm,
                         screw=0, cx=SHELF_X, cy=40 mm + T / 2)
    upper = tab_and_slot(part="slot", length=DEPTH, thickness=T, tabs=2, tab=60 mm,
                         screw=0, cx=SHELF_X, cy=180 mm + T / 2)
    back = tab_and_slot(part="slot", length=60 mm, thickness=T, tabs=1, tab=30 mm,
                        screw=0, rotation=90 deg, cx=125 mm - 5 mm - T / 2, cy=260 mm)
}

def shelf() -> solid {
    body = Rectangle(center=(0, 0), width=SPAN + 2 * T, height=DEPTH)
    hole vents {
        for i in range(5) {
            s = Slot(center=(-160 + i * 80, 0), length=150, width=12, rotation=90 deg)
        }
    }
    lt = tab_and_slot(part="tab", length=DEPTH, thickness=T, tabs=2, tab=60 mm, screw=0,
                      rotation=90 deg, cx=-(SPAN / 2 + T), cy=0 mm)
    rt = tab_and_slot(part="tab", length=DEPTH, thickness=T, tabs=2, tab=60 mm, screw=0,
                      rotation=-90 deg, cx=SPAN / 2 + T, cy=0 mm)
}

assembly shoe_rack {
    left = side_panel()
    right = side_panel()
    low_shelf = shelf()
    high_shelf = shelf()
    solid rail {
        body = Rectangle(center=(0, 0), width=SPAN + 2 * T, height=60)
        lt = tab_and_slot(part="tab", length=60 mm, thickness=T, tabs=1, tab=30 mm, screw=0,
                          rotation=90 deg, cx=-(SPAN / 2 + T), cy=0 mm)
        rt = tab_and_slot(part="tab", length=60 mm, thickness=T, tabs=1, tab=30 mm, screw=0,
                          rotation=-90 deg, cx=SPAN / 2 + T, cy=0 mm)
        drawing label {
            t = Text("LITTLE FEET", position=(0, 0), size=24, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # flat on the sheet, apart
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    Above(low_shelf, left, gap=10)
    AlignLeft(low_shelf, left)
    Above(high_shelf, low_shelf, gap=10)
    AlignLeft(high_shelf, left)
    Above(rail, high_shelf, gap=10)
    AlignLeft(rail, left)

    # assembled: sides stand in the y-z plane (side x -> world y, side y -> world z)
    Place(left, position=(-(SPAN / 2 + T), 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(SPAN / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(low_shelf, position=(0, SHELF_X, 40))
    Place(high_shelf, position=(0, SHELF_X, 180))
    Place(rail, position=(0, 125 - 5, 260), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert left.body.bb.width == 250 mm, "sides 250 deep"
    assert left.body.bb.height == 300 mm, "sides 300 tall"
    assert low_shelf.body.bb.width - 2 * T == 480 mm, "480 between the sides"
    assert low_shelf.body.bb.height == 230 mm, "shelves 230 deep"
    assert left.lower.bb.bottom - left.body.bb.bottom == 40 mm, "lower shelf 40 above the floor"
    assert left.upper.bb.bottom - left.body.bb.bottom == 180 mm, "upper shelf 180 above the floor"
    assert len(low_shelf.vents.s) == 5, "five drain slots"
    assert left.body.bb.right - left.back.bb.right == 5 mm, "rail 5 in from the back"
    assert left.hand.bb.width == 90 mm and left.hand.bb.height == 30 mm, "hand hole 90 x 30"
    assert left.feet.arch.rx * 2 == 150 mm, "arch 150 wide"
    # the bed
    assert low_shelf.bb.width <= 600 mm and low_shelf.bb.height <= 400 mm, "shelf fits the bed"
    assert left.bb.width <= 600 mm and left.bb.height <= 400 mm, "side fits the bed"
}
