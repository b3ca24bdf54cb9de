# Request (crafts): an extension table for my sewing machine, so quilts lie flat round the
# free arm. 6 mm birch ply, glued tab-and-slot joints (0.2 mm clearance), four parts.
# - top: 500 wide x 400 deep, front corners R25, back corners R5; its surface 95 mm above
#   the desk (level with the machine's bed); a notch 330 wide x 160 deep from the back edge
#   for the machine (its centre 20 mm right of the table's centre, inner corners R20, mouth
#   corners rounded R4); a ruler engraved along the front edge: 0 to 400 mm, a tick every
#   5 mm (3 long), every 10 mm (5 long), every 50 mm (8 long) with the cm number (0 ... 40,
#   4 mm single-stroke) above it.
# - two legs 340 long x 89 tall under the top's sides (their mid-planes 225 from the centre),
#   each with two 40 mm tenons into the top and a 240 x 50 R20 arch cut from the foot.
# - a stretcher 60 tall between the legs, its mid-plane 50 mm in from the front edge, under
#   the top: two 40 mm tenons into the top and one 30 mm tenon through each leg.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
top_w = 500 mm
top_d = 400 mm
surface = 95 mm
leg_h = surface - t            # 89
leg_x = 225 mm                 # legs' mid-planes from the centre
leg_len = 340 mm
leg_mid_y = -10 mm             # legs run from y -180 to 160
str_y = -150 mm                # the stretcher's mid-plane
str_h = 60 mm
str_len = 2 * leg_x + t        # 456: tenon tip to tenon tip
notch_w = 330 mm
notch_d = 160 mm
notch_x = 20 mm

def leg() -> solid {
    body = Rectangle(center=(-10, 95 / 2), width=340, height=95)
    tenons = tab_and_slot(part="tab", length=340 mm, thickness=6 mm, tabs=2, tab=40 mm,
                          screw=0, cx=-10 mm, cy=95 mm)
    hole arch {
        a = RoundedRectangle(center=(-10, 50 / 2 - 10), width=240, height=70, corner_radius=20)
    }
    mortise = tab_and_slot(part="slot", length=60 mm, thickness=6 mm, tabs=1, tab=30 mm,
                           screw=0, clearance=0.2 mm, rotation=90 deg, cx=-150 mm,
                           cy=89 mm - 60 mm / 2)
}

assembly sewing_table {
    solid top {
        board = RoundedRectangle(center=(0, 0), width=500, height=400,
                                 corner_radii=[5, 5, 25, 25])
        hole cutout {
            n = RoundedRectangle(center=(notch_x, 200 - 160 + 90), width=330, height=180,
                                 corner_radius=20)
        }
        Fillet([board.top, cutout.n], 4 mm)
        left_mortise = tab_and_slot(part="slot", length=340 mm, thickness=6 mm, tabs=2,
                                    tab=40 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                    cx=-leg_x, cy=leg_mid_y)
        right_mortise = tab_and_slot(part="slot", length=340 mm, thickness=6 mm, tabs=2,
                                     tab=40 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                     cx=leg_x, cy=leg_mid_y)
        stretcher_mortise = tab_and_slot(part="slot", length=str_len, thickness=6 mm, tabs=2,
                                         tab=40 mm, screw=0, clearance=0.2 mm, cx=0 mm,
                                         cy=str_y)
        drawing ruler {
            for i in range(81) {
                tick = Line((-200 + i * 5, -199),
                            (-200 + i * 5, -199 + (8 if i % 10 == 0 else
                                                   (5 if i % 2 == 0 else 3))))
            }
            for k in range(9) {
                cm = Text(str(k * 5), position=(-200 + k * 50, -188), size=4,
                          valign="bottom")
            }
        }
    }

    left_leg = leg()
    right_leg = leg()

    solid stretcher {
        body = Rectangle(center=(0, 29 + 66 / 2), width=456, height=66)
        tenons = tab_and_slot(part="tab", length=456 mm, thickness=6 mm, tabs=2, tab=40 mm,
                              screw=0, cx=0 mm, cy=95 mm)
        left_tenon = tab_and_slot(part="tab", length=60 mm, thickness=6 mm, tabs=1,
                                  tab=30 mm, screw=0, rotation=90 deg, cx=-228 mm,
                                  cy=59 mm)
        right_tenon = tab_and_slot(part="tab", length=60 mm, thickness=6 mm, tabs=1,
                                   tab=30 mm, screw=0, rotation=-90 deg, cx=228 mm,
                                   cy=59 mm)
    }

    # 3D: legs standing at x = -225 and 225 (local x along +y), the stretcher across,
    # the top on the legs
    Place(top, position=(0, 0, leg_h))
    Place(left_leg, position=(-leg_x - t / 2, 0, 0), face="right", up="up")
    Place(right_leg, position=(leg_x - t / 2, 0, 0), face="right", up="up")
    Place(stretcher, position=(0, str_y + t / 2, 0), face="front", up="up")

    # the sheet
    Below(left_leg, top, gap=8)
    AlignLeft(left_leg, top)
    RightOf(right_leg, left_leg, gap=8)
    AlignTop(right_leg, left_leg)
    Below(stretcher, left_leg, gap=8)
    AlignLeft(stretcher, top)

    # the request's numbers
    assert top.board.bb.width == 500 mm and top.board.bb.height == 400 mm, "500 x 400"
    assert leg_h + t == 95 mm, "surface 95 above the desk"
    assert left_leg.body.bb.height - t == leg_h, "legs 89 under the top"
    assert left_leg.body.bb.width == 340 mm, "legs 340 long"
    assert top.cutout.n.width == 330 mm, "notch 330 wide"
    assert top.board.bb.top - top.cutout.n.bb.bottom == 160 mm, "notch 160 deep"
    assert top.cutout.n.bb.top > top.board.bb.top, "notch open at the back"
    assert top.cutout.n.center.x - top.board.center.x == 20 mm, "notch 20 right of centre"
    assert leg_x - t / 2 - 2 mm > notch_x + notch_w / 2, "legs clear of the notch"
    assert top.board.bb.top - notch_d > str_y + t, "stretcher clear of the notch"
    assert str_y - top.board.bb.bottom == 50 mm, "stretcher 50 in from the front edge"
    assert stretcher.body.bb.width == 2 * leg_x + t, "stretcher reaches through the legs"
    assert stretcher.body.bb.height - t == str_h, "stretcher 60 tall"
    assert len(top.ruler.tick) == 81 and len(top.ruler.cm) == 9, "0 to 400 mm, 0 to 40 cm"
    assert top.ruler.tick[80].start.x - top.ruler.tick[0].start.x == 400 mm, "400 mm ruler"
    assert left_leg.arch.a.width == 240 mm and
        left_leg.arch.a.bb.top - left_leg.body.bb.bottom == 50 mm, "arch 240 x 50"
    assert distance(left_leg.mortise.slot[0], left_leg.arch.a) >= 10 mm, "web by the mortise"
}
