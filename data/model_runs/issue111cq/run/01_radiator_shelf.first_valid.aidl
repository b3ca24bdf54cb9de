# Request: a shelf that sits on top of a panel radiator, no screws in the wall. 6 mm birch ply.
# Shelf board 700 x 140 mm, front corners rounded R15 (back corners square, against the wall),
# a row of 14 vent slots 12 x 60 mm at 30 mm pitch, centred, so the heat still rises through.
# Two brackets hang the shelf on the radiator: each an upside-down U whose opening is
# 104 mm (radiator 100 mm deep front to back + 4 mm clearance), legs 15 mm thick, the beam
# 25 mm tall under the shelf, front leg drops 30 mm below the beam, back leg 70 mm (between
# radiator and wall), inside corners rounded R5. Each bracket glued into the shelf with
# 2 tabs 20 mm wide in mortises; brackets centred 120 mm in from each shelf end.

import "std/joints.aidl"

units mm
thickness 6 mm

param shelf_len = 700 mm, min = 400 mm, max = 1200 mm
param shelf_depth = 140 mm, min = 134 mm, max = 200 mm
param radiator_depth = 100 mm, min = 60 mm, max = 130 mm

clearance = 4 mm
leg = 15 mm
beam = 25 mm
front_drop = 30 mm
back_drop = 70 mm
inset = 120 mm
t = 6 mm

def bracket() -> solid {
    gapw = radiator_depth + clearance
    outer = gapw + 2 * leg
    # frame: x along the shelf depth (front at -x), y up; y = 0 is the tab tips (shelf top)
    top_beam = Rectangle(bottom_left=(-outer / 2, -(beam + t)), width=outer, height=beam + t)
    front_leg = Rectangle(bottom_left=(-outer / 2, -(beam + t) - front_drop), width=leg,
                          height=front_drop + 1)
    back_leg = Rectangle(bottom_left=(outer / 2 - leg, -(beam + t) - back_drop), width=leg,
                         height=back_drop + 1)
    tabs = tab_and_slot(part="tab", length=outer, thickness=t, tabs=2, tab=20 mm, screw=0)
    Fillet([front_leg.right, top_beam.bottom], 5)
    Fillet([back_leg.left, top_beam.bottom], 5)
}

assembly radiator_shelf {
    solid shelf {
        board = RoundedRectangle(center=(0, 0), width=shelf_len, height=shelf_depth,
                                 corner_radii=[0, 0, 15, 15])
        hole vent {
            s = Slot(center=(-195, 0), length=60, width=12, rotation=90)
        }
        vents = LinearPattern(vent, 14, (30, 0))
        left_mortise = tab_and_slot(part="slot", length=radiator_depth + clearance + 2 * leg,
                                    thickness=t, tabs=2, tab=20 mm, screw=0, rotation=90 deg,
                                    cx=-(shelf_len / 2 - inset), cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=radiator_depth + clearance + 2 * leg,
                                     thickness=t, tabs=2, tab=20 mm, screw=0, rotation=90 deg,
                                     cx=shelf_len / 2 - inset, cy=0 mm)
    }
    left_bracket = bracket()
    right_bracket = bracket()
    Below(left_bracket, shelf, gap=10)
    Below(right_bracket, shelf, gap=10)
    AlignLeft(left_bracket, shelf)
    AlignRight(right_bracket, shelf)

    Place(shelf, position=(0, 0, 0), face="up")
    Place(left_bracket, position=(-(shelf_len / 2 - inset) - t / 2, 0, t), face="right", up="up")
    Place(right_bracket, position=(shelf_len / 2 - inset - t / 2, 0, t), face="right", up="up")

    # the request's numbers
    assert shelf.board.bb.width == 700 mm, "shelf 700 long"
    assert shelf.board.bb.height == 140 mm, "shelf 140 deep"
    assert len(shelf.vents) == 14, "14 vent slots"
    assert left_bracket.back_leg.bb.left - left_bracket.front_leg.bb.right == 104 mm,
        "opening = radiator 100 + 4 clearance"
    assert left_bracket.top_beam.bb.bottom - left_bracket.front_leg.bb.bottom == 30 mm + 1 mm - 1 mm,
        "front leg drops 30 below the beam"
    assert left_bracket.top_beam.bb.bottom - left_bracket.back_leg.bb.bottom == 70 mm,
        "back leg drops 70 below the beam"
    assert left_bracket.top_beam.bb.height - 6 mm == 25 mm, "beam 25 under the shelf"
    assert abs(shelf.left_mortise.slot[0].bb.center_x - shelf.board.bb.left) == 120 mm,
        "bracket 120 in from the end"
}
