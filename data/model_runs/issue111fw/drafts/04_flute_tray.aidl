# REQUEST (parties): a serving tray that carries six champagne flutes upright, 6 mm ply,
# four parts glued. A base 330 x 200 mm, R10 corners, on which the flutes' feet stand. A
# stem plate 300 x 200 mm between the ends, its top face 56 mm above the base's top (its
# underside 50 mm up), with six keyhole slots, three from each long edge, at 90 mm centres
# (x = -90, 0, 90): each a 12 mm wide slot from the edge ending in a 16 mm round seat whose
# centre is 40 mm from the tray's centre line (the two rows of flutes 80 mm apart). Two end
# panels 200 wide and 130 tall (above the base's top) whose inner faces are 300 mm apart,
# each with a 90 x 28 mm hand hole centred 100 mm up and "CHEERS" engraved filled on its
# outside (serif, 12 mm, between the hand hole and the stem plate). Joints: each end
# panel stands in the base on two 40 mm tenons, the stem plate's ends sit in the end panels
# on two 40 mm tenons each. Shown assembled.
# FIX after the first valid program: on the flat drawing the two end panels (200 wide each)
# were aligned to the ends of the 330 mm base and overlapped (W0511); now side by side.

units mm
import "std/joints.aidl"

t = 6 mm
thickness t
lift = 50 mm          # the stem plate's underside above the base's top

def end_panel() -> solid {
    # drawn with its tenons' tips on y = 0 (the base's underside), its shoulder on y = t
    body = Rectangle(corner=(-100, 0), opposite=(100, t + 130))
    feet = tab_and_slot(part="tab", length=200 mm, thickness=t, tabs=2, tab=40 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    plate_mortise = tab_and_slot(part="slot", length=200 mm, thickness=t, tabs=2, tab=40 mm,
                                 screw=0, cx=0 mm, cy=t + lift + t / 2)
    hole hand {
        h = Slot(center=(0, t + 100), length=90, width=28)
    }
    drawing word {
        w = Text("CHEERS", position=(0, t + lift + t + 12), size=12, font="serif",
                 valign="middle", fill=true)
    }
}

assembly tray {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=330, height=200, corner_radius=10)
        left_mortise = tab_and_slot(part="slot", length=200 mm, thickness=t, tabs=2, tab=40 mm,
                                    screw=0, rotation=90 deg, cx=-153 mm, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=200 mm, thickness=t, tabs=2, tab=40 mm,
                                     screw=0, rotation=90 deg, cx=153 mm, cy=0 mm)
    }
    solid stems {
        plate = Rectangle(center=(0, 0), width=300 + 2 * t, height=200)
        left_tenons = tab_and_slot(part="tab", length=200 mm, thickness=t, tabs=2, tab=40 mm,
                                   screw=0, rotation=90 deg, cx=-150 mm - t, cy=0 mm)
        right_tenons = tab_and_slot(part="tab", length=200 mm, thickness=t, tabs=2, tab=40 mm,
                                    screw=0, rotation=-90 deg, cx=150 mm + t, cy=0 mm)
        hole keyholes {
            for i in range(3) {
                front = Slot(start=(-90 + 90 * i, -40), end=(-90 + 90 * i, -101), width=12)
                front_seat = Circle(center=(-90 + 90 * i, -40), diameter=16)
                back = Slot(start=(-90 + 90 * i, 40), end=(-90 + 90 * i, 101), width=12)
                back_seat = Circle(center=(-90 + 90 * i, 40), diameter=16)
            }
        }
    }
    left = end_panel()
    right = end_panel()

    # flat, for cutting
    Above(stems, base, gap=10)
    AlignCenterX(stems, base)
    Above(left, stems, gap=10)
    AlignLeft(left, base)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    # 3D
    Place(base, position=(0, 0, 0))
    Place(stems, position=(0, 0, t + lift))
    Place(left, position=(-150, 0, 0), face="left", up="up")
    Place(right, position=(150, 0, 0), face="right", up="up")
}

# the request's numbers
assert tray.base.board.width == 330 mm and tray.base.board.height == 200 mm, "base 330 x 200"
assert tray.stems.plate.width - 2 * t == 300 mm, "stem plate 300 between the ends"
assert len(tray.stems.keyholes.front) + len(tray.stems.keyholes.back) == 6, "six flutes"
assert tray.stems.keyholes.back_seat[0].center.y - tray.stems.keyholes.front_seat[0].center.y == 80 mm, "rows 80 apart"
assert tray.stems.keyholes.front_seat[1].center.x - tray.stems.keyholes.front_seat[0].center.x == 90 mm, "90 mm centres"
assert tray.stems.keyholes.front[0].width == 12 mm and tray.stems.keyholes.front_seat[0].diameter == 16 mm, "12 slot, 16 seat"
assert tray.left.body.height - t == 130 mm and tray.left.body.width == 200 mm, "end panels 200 x 130"
assert tray.left.hand.h.length == 90 mm and tray.left.hand.h.width == 28 mm, "hand hole 90 x 28"
assert tray.left.hand.h.center.y - t == 100 mm, "hand hole centred 100 mm up"
# the word fits between the stem plate's mortise and the hand hole
assert tray.left.word.bb.bottom > tray.left.plate_mortise.bb.top, "CHEERS clear of the mortise"
assert tray.left.word.bb.top < tray.left.hand.bb.bottom, "CHEERS clear of the hand hole"
