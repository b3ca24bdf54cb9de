# Request (parties): a carrier for six champagne flutes, in 6 mm ply. A round tray 300 mm
# across; six stem slots 9 mm wide run in from the rim to a 12 mm round seat 100 mm from
# the centre, one every 60 deg starting at 30 deg; each slot's mouth flares to 20 mm at the
# rim over its last 12 mm. In the middle a handle board 120 wide stands 200 mm above the
# tray (R30 top corners) with an 80 x 28 hand hole centred 165 mm up, CHEERS engraved in
# italic serif, 16 mm capitals, centred 95 mm up. The handle is glued into the tray with
# two 30 mm through tenons and braced front and back by two triangular gussets (50 out,
# 80 up), each with a 20 mm tenon into the tray and a 20 mm tenon 3 mm into the handle
# (the two meet in the middle of the board's single mortise). Four parts.

import "std/joints.aidl"

thickness 6 mm

seat_r = 100 mm

# a gusset seen from the side: x out from the handle's face (0), y up from the tray (0);
# its tenons' tips at y = -6 (through the tray) and x = -3 (half into the handle)
def gusset() -> solid {
    body = Polygon([(0, -6), (50, -6), (50, 0), (0, 80), (-3, 80), (-3, 0)])
    foot = tab_and_slot(part="tab", length=50 mm, thickness=6 mm, tabs=1, tab=20 mm,
                        screw=0, rotation=180 deg, cx=25 mm, cy=-6 mm)
    back = tab_and_slot(part="tab", length=80 mm, thickness=3 mm, tabs=1, tab=20 mm,
                        screw=0, rotation=90 deg, cx=-3 mm, cy=40 mm)
}

assembly carrier {
    solid tray {
        disc = Circle(center=(0, 0), diameter=300)
        hole flute {
            seat = Circle(center=(seat_r, 0), diameter=12)
            neck = Rectangle(start=(seat_r, 0), end=(160, 0), width=9)
            mouth = Polygon([(138, 4.5), (152, 10), (152, -10), (138, -4.5)])
        }
        flutes = CircularPattern(flute, 6, disc.center, start_angle=30 deg)
        handle_mortise = tab_and_slot(part="slot", length=120 mm, thickness=6 mm, tabs=2,
                                      tab=30 mm, screw=0, rotation=0 deg, cx=0 mm, cy=0 mm)
        back_gusset_mortise = tab_and_slot(part="slot", length=50 mm, thickness=6 mm,
                                           tabs=1, tab=20 mm, screw=0, rotation=90 deg,
                                           cx=0 mm, cy=28 mm)
        front_gusset_mortise = tab_and_slot(part="slot", length=50 mm, thickness=6 mm,
                                            tabs=1, tab=20 mm, screw=0, rotation=90 deg,
                                            cx=0 mm, cy=-28 mm)
    }

    # the handle: x along the board, y up from the tray (0), tenon tips at -6
    solid handle {
        board = RoundedRectangle(bottom_left=(-60, -6), width=120, height=206,
                                 corner_radii=[30, 30, 0, 0])
        tenons = tab_and_slot(part="tab", length=120 mm, thickness=6 mm, tabs=2, tab=30 mm,
                              screw=0, rotation=180 deg, cx=0 mm, cy=-6 mm)
        gusset_mortise = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=1,
                                      tab=20 mm, screw=0, rotation=90 deg, cx=0 mm, cy=40 mm)
        hole grip {
            s = Slot(center=(0, 165), length=80, width=28)
        }
        drawing words {
            t = Text("CHEERS", position=(0, 95), size=16, font="serif:Italic",
                     valign="middle", fill=true)
        }
    }
    back_gusset = gusset()
    front_gusset = gusset()

    # flat on the sheet
    RightOf(handle, tray, gap=10)
    AlignTop(handle, tray)
    RightOf(back_gusset, handle, gap=10)
    AlignTop(back_gusset, handle)
    RightOf(front_gusset, back_gusset, gap=10)
    AlignTop(front_gusset, back_gusset)

    # in 3D
    Place(tray, position=(0, 0, 0), face="up")
    Place(handle, position=(0, 3, 6), face="front", up="up")
    Place(back_gusset, position=(-3, 3, 6), face="right", up="up")
    Place(front_gusset, position=(3, -3, 6), face="left", up="up")

    assert tray.disc.diameter == 300 mm, "tray 300"
    assert len(tray.flutes) == 6, "six flutes"
    assert distance(tray.flute.seat.center, tray.disc.center) == 100 mm, "seats 100 out"
    assert tray.flute.seat.diameter == 12 mm and tray.flute.neck.height == 9 mm,
        "12 seat, 9 slot"
    # heights from the tray's top, which is 6 above the tenons' tips (the board's bottom)
    assert handle.board.bb.top - (handle.board.bb.bottom + 6 mm) == 200 mm,
        "handle 200 above the tray"
    assert handle.board.bb.width == 120 mm, "handle 120 wide"
    assert handle.grip.s.center.y - (handle.board.bb.bottom + 6 mm) == 165 mm, "grip 165 up"
    assert handle.words.t.position.y - (handle.board.bb.bottom + 6 mm) == 95 mm,
        "CHEERS 95 up"
    assert back_gusset.body.bb.right - (back_gusset.body.bb.left + 3 mm) == 50 mm,
        "gussets 50 out"
    assert back_gusset.body.bb.top - (back_gusset.body.bb.bottom + 6 mm) == 80 mm,
        "gussets 80 up"
}
