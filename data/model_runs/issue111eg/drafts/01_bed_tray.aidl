# Request: a breakfast-in-bed tray in 6 mm birch ply. Top 500 x 320 mm with R12 corners,
# two hand holes 110 x 30 mm (slots running front to back) 30 mm in from each short end,
# "GOOD MORNING" engraved filled (serif, 24 mm capitals) in the middle of the top.
# Two fixed legs 300 mm wide (front to back) and 230 mm tall to the top's underside,
# standing 170 mm either side of the centre, each with an arched opening 200 wide x 130
# tall between two 50 mm feet, and two 40 mm tenons glued into mortises in the top.
# A stretcher 50 mm tall between the legs, its top 30 mm below the top's underside,
# through-tenoned (one 30 mm tenon each end) into the legs.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
top_w = 500 mm
top_d = 320 mm
leg_x = 170 mm          # each leg's middle plane from the tray's centre
leg_w = 300 mm
leg_h = 230 mm          # floor to the top's underside
rail_h = 50 mm
rail_y = leg_h - 30 mm - rail_h / 2   # the stretcher's middle, from the floor
rail_len = 2 * (leg_x - T / 2) + 2 * T   # between the legs' inner faces, plus a tenon each end

def leg() -> solid {
    body = Rectangle(bottom_left=(-leg_w / 2, 0), width=leg_w, height=leg_h + T)
    tenons = tab_and_slot(part="tab", length=leg_w, thickness=T, tabs=2, tab=40 mm, screw=0,
                          cx=0 mm, cy=leg_h + T)
    hole arch {
        opening = Rectangle(bottom_left=(-100, -1), width=200, height=31, overrun=true)
        crown = Sector(center=(0, 30), radius=100, start_angle=0 deg, end_angle=180 deg)
    }
    mortise = tab_and_slot(part="slot", length=rail_h, thickness=T, tabs=1, tab=30 mm, screw=0,
                           rotation=90 deg, cx=0 mm, cy=rail_y)
}

assembly bed_tray {
    solid top {
        board = RoundedRectangle(center=(0, 0), width=top_w, height=top_d, corner_radius=12)
        hole handles {
            left_grip = Slot(center=(-(top_w / 2 - 30 - 15), 0), length=110, width=30, rotation=90)
            right_grip = Slot(center=(top_w / 2 - 30 - 15, 0), length=110, width=30, rotation=90)
        }
        left_mortise = tab_and_slot(part="slot", length=leg_w, thickness=T, tabs=2, tab=40 mm,
                                    screw=0, rotation=90 deg, cx=-leg_x, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=leg_w, thickness=T, tabs=2, tab=40 mm,
                                     screw=0, rotation=90 deg, cx=leg_x, cy=0 mm)
        drawing words {
            greeting = Text("GOOD MORNING", position=(0, 0), size=24, font="serif",
                            valign="middle", fill=true)
        }
    }
    left_leg = leg()
    right_leg = leg()
    solid stretcher {
        rail = Rectangle(center=(0, 0), width=rail_len, height=rail_h)
        right_tenon = tab_and_slot(part="tab", length=rail_h, thickness=T, tabs=1, tab=30 mm,
                                   screw=0, rotation=-90 deg, cx=rail_len / 2, cy=0 mm)
        left_tenon = tab_and_slot(part="tab", length=rail_h, thickness=T, tabs=1, tab=30 mm,
                                  screw=0, rotation=90 deg, cx=-rail_len / 2, cy=0 mm)
    }

    # flat on the sheet: legs under the top, the stretcher under the legs
    Below(left_leg, top, gap=10)
    AlignLeft(left_leg, top)
    RightOf(right_leg, left_leg, gap=10)
    AlignTop(right_leg, left_leg)
    Below(stretcher, left_leg, gap=10)
    AlignLeft(stretcher, top)

    # in 3D
    Place(top, position=(0, 0, leg_h), face="up")
    Place(left_leg, position=(-(leg_x - T / 2), 0, 0), face="left", up="up")
    Place(right_leg, position=(leg_x - T / 2, 0, 0), face="right", up="up")
    Place(stretcher, position=(0, T / 2, rail_y), face="front", up="up")

    # the request's numbers
    assert top.board.bb.width == 500 mm, "top 500 long"
    assert top.board.bb.height == 320 mm, "top 320 deep"
    assert top.handles.left_grip.bb.left - top.board.bb.left == 30 mm, "hand hole 30 in"
    assert top.board.bb.right - top.handles.right_grip.bb.right == 30 mm, "hand hole 30 in"
    assert top.handles.left_grip.bb.height == 110 mm and top.handles.left_grip.bb.width == 30 mm,
        "hand hole 110 x 30"
    assert left_leg.body.bb.width == 300 mm, "legs 300 wide"
    assert left_leg.arch.crown.bb.top - left_leg.body.bb.bottom == 130 mm, "arch 130 tall"
    assert left_leg.arch.crown.bb.width == 200 mm, "arch 200 wide"
    assert (left_leg.body.bb.width - left_leg.arch.crown.bb.width) / 2 == 50 mm, "feet 50 wide"
    assert distance(top.handles, top.right_mortise) >= 10 mm, "hand hole clear of the mortises"
    assert distance(top.words, top.right_mortise) >= 10 mm, "words clear of the mortises"
    assert leg_h - (rail_y + rail_h / 2) == 30 mm, "stretcher 30 below the top"
}
