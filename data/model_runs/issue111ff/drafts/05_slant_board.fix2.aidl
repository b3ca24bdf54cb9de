# Request (sport): a calf-stretch slant board in 9 mm birch ply, fixed at 20 degrees.
# Footprint 350 mm long; the top's underside rises from 15 mm at the toe end to
# 15 + 350 tan 20 at the high end. Top board 330 mm wide (R5 corners), as long as the slope,
# with a 110 x 30 hand-hold slot centred 40 mm from its high end, anti-slip grooves engraved
# across it every 15 mm (240 mm long), and "CALF STRETCH 20°" in filled 12 mm letters across
# the low end. Two side walls, 20 mm in from the top's edges, each with three 40 mm tenons
# through the top (flush). A back panel 15 mm in from the high end, between the sides, with
# two 30 mm tenons through each side, its top 5 mm under the top board.

units mm
thickness 9 mm

import "std/joints.aidl"

T = 9 mm
B = 350 mm                      # floor length
h0 = 15 mm                      # underside height at the toe
slope = 20 deg
H = h0 + B * tan(slope)         # underside height at the high end
L = B / cos(slope)              # slope length = top board length
W = 330 mm
dT = T / cos(slope)             # the tenons' tips stand T above the underside
side_y = W / 2 - 20 mm          # a side's outer face, from the middle
back_x = B - 15 mm              # the back panel's outer face
Hb = h0 + (back_x - T) * tan(slope) - 5 mm

assembly slant_board {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=L, height=W, corner_radius=5)
        m_left = tab_and_slot(part="slot", length=L, thickness=T, tabs=3, tab=40 mm, screw=0,
                              cx=0 mm, cy=side_y - T / 2)
        m_right = tab_and_slot(part="slot", length=L, thickness=T, tabs=3, tab=40 mm, screw=0,
                               cx=0 mm, cy=-side_y + T / 2)
        hole grip { s = Slot(center=(L / 2 - 40 mm, 0), length=110, width=30, rotation=90 deg) }
        drawing marks {
            for i in range(16) {
                g = Line((-L / 2 + 45 mm + i * 15 mm, -120), (-L / 2 + 45 mm + i * 15 mm, 120))
            }
            word = Text("CALF STRETCH 20°", position=(-L / 2 + 22 mm, 0), size=12,
                        font="sans:Bold", valign="middle", rotation=-90 deg, fill=true)
            # FIX: reads for someone stepping on from the low end (was rotation 90: upside down)
        }
    }

    def side() -> solid {
        # FIX after the first valid program: the tenons' line was centred straight above the
        # slope's middle, not square to the slope from it, so every tenon sat T tan 20 = 3.3 mm
        # off its mortise (W0517). The line's middle is now square off the slope's middle, and
        # the ends of the side are cut square to the slope like the top's ends.
        body = Polygon([(0, 0), (B, 0), (B, H), (B - T * sin(slope), H + T * cos(slope)),
                        (-T * sin(slope), h0 + T * cos(slope)), (0, h0)])
        tenons = tab_and_slot(part="tab", length=L, thickness=T, tabs=3, tab=40 mm, screw=0,
                              rotation=slope, cx=B / 2 - T * sin(slope),
                              cy=(h0 + H) / 2 + T * cos(slope))
        back_mortise = tab_and_slot(part="slot", length=Hb, thickness=T, tabs=2, tab=30 mm,
                                    screw=0, rotation=90 deg, cx=back_x - T / 2, cy=Hb / 2)
    }
    side_a = side()
    side_b = side()

    solid back {
        body = Rectangle(bottom_left=(-side_y, 0), width=2 * side_y, height=Hb)
        t_left = tab_and_slot(part="tab", length=Hb, thickness=T, tabs=2, tab=30 mm, screw=0,
                              rotation=90 deg, cx=-side_y, cy=Hb / 2)
        t_right = tab_and_slot(part="tab", length=Hb, thickness=T, tabs=2, tab=30 mm, screw=0,
                               rotation=-90 deg, cx=side_y, cy=Hb / 2)
    }

    # flat on the sheet
    Below(side_a, top, gap=10)
    AlignLeft(side_a, top)
    Below(side_b, side_a, gap=10)
    AlignLeft(side_b, side_a)
    RightOf(back, top, gap=10)
    AlignTop(back, top)

    # assembled: floor x from 0 (toe) to B (high end), y across, z up
    Place(top, position=(B / 2, 0, (h0 + H) / 2), rotation=(0, -slope, 0))
    Place(side_a, position=(0, -side_y + T, 0), face="front", up="up")
    Place(side_b, position=(0, side_y, 0), face="front", up="up")
    Place(back, position=(back_x - T, 0, 0), face="right", up="up")

    # the request's numbers
    assert atan((H - h0) / B) == 20 deg, "20 degree slope"
    assert top.body.bb.width == B / cos(20 deg) and top.body.bb.height == 330 mm, "top as long as the slope, 330 wide"
    assert top.body.bb.top - (top.m_left.slot[0].bb.top) == 20 mm, "sides 20 in from the edge"
    assert (top.grip.s.center.x - top.body.bb.left) == top.body.bb.width - 40 mm, "grip 40 from the high end"
    assert top.grip.s.length == 110 mm and top.grip.s.width == 30 mm, "grip 110 x 30"
    assert len(top.marks.g) * 15 mm + top.marks.g[0].start.x - top.body.bb.left < top.grip.bb.left - top.body.bb.left,
        "grooves stop short of the grip"
    assert side_a.body.points[1].x - side_a.body.points[0].x == 350 mm, "350 mm footprint"
    assert B - back_x == 15 mm, "back panel 15 in from the high end"
    assert h0 + (back_x - T) * tan(20 deg) - back.body.bb.height == 5 mm, "back 5 under the top"
}
