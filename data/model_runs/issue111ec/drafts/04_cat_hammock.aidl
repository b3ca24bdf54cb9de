# Request (pets): a freestanding cat hammock frame from 9 mm birch ply; the canvas (sewn
# with a sleeve at each side) slides onto the two rails.
# - Two end panels 360 mm wide, 300 mm tall (top corners R40), with two cat ears on top
#   (90 mm base, standing 60 mm above the top edge, 100 mm either side of the middle,
#   tips rounded R8) and a 140 mm round window centred 160 mm up.
# - Two rails 50 mm high standing on edge, 500 mm between the end panels, their centres 300 mm
#   apart and 250 mm above the floor; one 30 mm glued through tenon each end (0.1 mm
#   clearance in the mortise).
# - A floor stretcher 560 mm long, 80 mm high, cross-halved into the bottom middle of both
#   end panels (40 mm slot in each, 0.2 mm clearance); "MISO" engraved filled on it
#   (sans bold, 36 mm) in the middle.

import "std/joints.aidl"

thickness 9 mm

t = 9 mm
end_w = 360 mm
end_h = 300 mm
span = 500 mm
rail_h = 50 mm
rail_gap = 300 mm
rail_z = 250 mm
str_len = 560 mm
str_h = 80 mm

def end_panel() -> solid {
    body = RoundedRectangle(center=(0, end_h / 2), width=end_w, height=end_h,
                            corner_radii=[40, 40, 0, 0])
    ear_l = Triangle(center=(-100, end_h - 5 + 65 / 2), base=90, height=65)
    ear_r = Triangle(center=(100, end_h - 5 + 65 / 2), base=90, height=65)
    Fillet(ear_l.c, 8 mm)
    Fillet(ear_r.c, 8 mm)
    hole window {
        c = Circle(center=(0, 160), diameter=140)
    }
    m_front = tab_and_slot(part="slot", length=rail_h, thickness=t, tabs=1, tab=30 mm, screw=0,
                           clearance=0.1 mm, rotation=90 deg, cx=rail_gap / 2, cy=rail_z)
    m_back = tab_and_slot(part="slot", length=rail_h, thickness=t, tabs=1, tab=30 mm, screw=0,
                          clearance=0.1 mm, rotation=90 deg, cx=-rail_gap / 2, cy=rail_z)
    halving = cross_halving(depth=str_h / 2, thickness=t, clearance=0.2 mm, rotation=180 deg,
                            cx=0, cy=0)
    Fixed(body)
}

def rail() -> solid {
    board = Rectangle(center=(0, 0), width=span + 2 * t, height=rail_h)
    left_tenon = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=1, tab=30 mm,
                              screw=0, rotation=90 deg, cx=-(span / 2 + t), cy=0)
    right_tenon = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=1, tab=30 mm,
                               screw=0, rotation=-90 deg, cx=span / 2 + t, cy=0)
    Fixed(board)
}

assembly hammock {
    end_l = end_panel()
    end_r = end_panel()
    rail_f = rail()
    rail_b = rail()
    solid stretcher {
        board = Rectangle(bottom_left=(-str_len / 2, 0), width=str_len, height=str_h)
        slot_l = cross_halving(depth=str_h / 2, thickness=t, clearance=0.2 mm,
                               cx=-(span / 2 + t / 2), cy=str_h)
        slot_r = cross_halving(depth=str_h / 2, thickness=t, clearance=0.2 mm,
                               cx=span / 2 + t / 2, cy=str_h)
        drawing name {
            word = Text("MISO", position=(0, str_h / 2), size=36, font="sans:Bold",
                        valign="middle", fill=true)
        }
        Fixed(board)
    }

    # flat on the sheet
    RightOf(end_r, end_l, gap=10)
    AlignBottom(end_r, end_l)
    Below(rail_f, end_l, gap=10)
    AlignLeft(rail_f, end_l)
    Below(rail_b, rail_f, gap=10)
    AlignLeft(rail_b, end_l)
    Below(stretcher, rail_b, gap=10)
    AlignLeft(stretcher, end_l)

    # assembled: x along the hammock, -y to the front, z up
    Place(end_l, position=(-span / 2, 0, 0), face="left", up="up")
    Place(end_r, position=(span / 2, 0, 0), face="right", up="up")
    Place(rail_f, position=(0, -rail_gap / 2 + t / 2, rail_z), face="front", up="up")
    Place(rail_b, position=(0, rail_gap / 2 - t / 2, rail_z), face="back", up="up")
    Place(stretcher, position=(0, t / 2, 0), face="front", up="up")

    # the request's numbers
    assert end_l.body.bb.width == 360 mm and end_l.body.bb.height == 300 mm, "end 360 x 300"
    assert end_l.bb.top - end_l.body.bb.top == 60 mm, "ears 60 above the top edge"
    assert end_l.ear_r.c.x - end_l.body.bb.center_x == 100 mm, "ears 100 out"
    assert end_l.ear_r.base == 90 mm, "ear base 90"
    assert end_l.window.c.diameter == 140 mm, "140 window"
    assert end_l.window.c.center.y - end_l.body.bb.bottom == 160 mm, "window 160 up"
    assert rail_f.board.bb.width - 2 * t == 500 mm, "500 between the ends"
    assert rail_f.board.bb.height == 50 mm, "rail 50 high"
    assert end_l.m_front.slot[0].bb.center_x - end_l.m_back.slot[0].bb.center_x == 300 mm,
        "rails 300 apart"
    assert end_l.m_front.slot[0].bb.center_y - end_l.body.bb.bottom == 250 mm, "rails 250 up"
    assert end_l.m_front.slot[0].bb.height == 30 mm + 0.1 mm, "30 mm tenon, 0.1 clearance"
    assert stretcher.board.bb.width == 560 mm and stretcher.board.bb.height == 80 mm,
        "stretcher 560 x 80"
    assert end_l.halving.cut.bb.height + stretcher.slot_l.cut.bb.height == 80 mm,
        "halvings add up to the stretcher's height"
    assert stretcher.slot_r.cut.bb.center_x - stretcher.slot_l.cut.bb.center_x == span + t,
        "stretcher slots under the end panels"
    assert distance(end_l.window, end_l.halving) >= 20 mm, "window clear of the halving"
    assert distance(end_l.window, end_l.m_front) >= 10 mm, "window clear of the mortises"
    assert distance(stretcher.name, stretcher.slot_l) >= 50 mm, "name clear of the slots"
}
