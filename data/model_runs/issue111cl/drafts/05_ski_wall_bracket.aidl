# Request: a wall bracket for storing skis on edge, from 6 mm birch ply (I cut two, one for
# each end of the skis). A back plate 80 mm wide and 180 mm tall, screwed to the wall with
# four countersunk 4.5 mm holes (9 mm heads, 90 deg) 50 mm apart across and 150 mm apart up.
# A bracket 220 mm deep from the wall, 180 mm tall at the wall and 40 mm at the tip (a sloping
# underside), with two round-bottomed notches 32 mm wide and 30 mm deep in its top edge for
# two pairs of skis, a 10 mm high lip at the tip, and a rounded triangular lightening cut-out.
# The bracket's back edge goes through the back plate with two 30 mm tabs and an M3 screw with
# a captive nut between them.

import "std/joints.aidl"

units mm
thickness 6 mm

param ply = 6 mm, min = 4 mm, max = 9 mm
param reach = 220 mm, min = 160 mm, max = 300 mm
param notch_w = 32 mm, min = 20 mm, max = 45 mm
param notch_d = 30 mm, min = 20 mm, max = 40 mm

plate_w = 80 mm
plate_h = 180 mm
tip_h = 40 mm
lip_h = 10 mm

assembly ski_bracket {
    solid back {
        body = Rectangle(center=(0, 0), width=plate_w, height=plate_h)
        hole screw {
            c = Circle(center=(-25, -75), diameter=4.5)
        }
        screws = GridPattern(screw, 2, 2, (50, 150))
        Countersink(screws, diameter=9 mm)
        mortise = tab_and_slot(part="slot", length=plate_h, thickness=ply, tabs=2, tab=30 mm,
                               screw=3, clearance=0.1 mm, rotation=90 deg, cx=0 mm, cy=0 mm)
    }

    solid bracket {
        # the back edge at x = 0 (the plate's face), the tab tips at x = -ply
        profile = Polygon([(-ply, 0), (reach, plate_h - tip_h), (reach, plate_h),
                           (-ply, plate_h)])
        lip = RoundedRectangle(bottom_left=(reach - 15, plate_h - 2), width=15, height=lip_h + 2,
                               corner_radii=[4, 4, 0, 0])
        tabs = tab_and_slot(part="tab", length=plate_h, thickness=ply, tabs=2, tab=30 mm,
                            screw=3, rotation=90 deg, cx=-ply, cy=plate_h / 2)
        hole notch_a {
            round = Circle(center=(70, plate_h - notch_d + notch_w / 2), diameter=notch_w)
            mouth = Rectangle(bottom_left=(70 - notch_w / 2, plate_h - notch_d + notch_w / 2),
                              width=notch_w, height=notch_d - notch_w / 2 + 1)
        }
        hole notch_b {
            round = Circle(center=(150, plate_h - notch_d + notch_w / 2), diameter=notch_w)
            mouth = Rectangle(bottom_left=(150 - notch_w / 2, plate_h - notch_d + notch_w / 2),
                              width=notch_w, height=notch_d - notch_w / 2 + 1)
        }
        hole lightening {
            tri = Polygon([(25, 45), (25, 130), (160, 130)])
            Fillet(10)
        }
    }

    # on the sheet: the bracket beside the back plate
    RightOf(bracket, back, gap=10)
    AlignBottom(bracket, back)

    # on the wall (plane y = 0), x along the wall, z up, the bracket sticking out along +y
    # FIX after the first valid program: the --assembled view showed the plate's top face (the
    # one the countersinks are marked on) against the wall; turned the other way round
    # (frame z -> world y, frame y -> world -z), the marked face faces out.
    Place(back, position=(0, 0, plate_h / 2), rotation=(-90 deg, 0, 0))
    Place(bracket, position=(-ply / 2, ply, 0), rotation=(90 deg, 0, 90 deg))

    assert back.body.width == 80 mm and back.body.height == 180 mm, "80 x 180 back plate"
    assert len(back.screws) == 4, "four wall screws"
    assert back.screws[1].c.center.x - back.screws[0].c.center.x == 50 mm, "50 mm across"
    assert back.screws[2].c.center.y - back.screws[0].c.center.y == 150 mm, "150 mm up"
    assert bracket.profile.bb.right - (bracket.profile.bb.left + ply) == 220 mm, "220 mm from the wall"
    assert bracket.notch_a.bb.width == 32 mm, "32 mm notches"
    assert bracket.profile.bb.top - bracket.notch_a.round.bottom.y == 30 mm, "30 mm deep notches"
    assert bracket.lip.bb.top - bracket.profile.bb.top == 10 mm, "10 mm lip"
}
