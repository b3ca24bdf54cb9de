# Request: an espresso tamping station for my coffee corner, in 6 mm birch ply.
# A top deck 200 x 130 with R8 corners stands 60 mm clear above a base of the same size,
# on two sides 110 deep whose centre lines are 12 mm in from the ends; each side has two
# 20 mm tenons into mortises in the top and two into the base (glued). In the top: a 60 mm
# well for my 58 mm tamper (its centre 45 mm left of the middle) and a U-slot 36 mm wide
# running 70 mm in from the front edge for the portafilter's spouts (its centre 35 mm right
# of the middle, the mouth's corners eased R3), so the basket sits flat on the deck while I
# tamp. Engraved on the top: "58" under the well and "ESPRESSO" (sans bold, filled, 8 mm)
# along the back edge.

units mm
thickness 6 mm

import "std/joints.aidl"

T = 6 mm
W = 200 mm
D = 130 mm
CLEAR = 60 mm
SIDE_D = 110 mm
SIDE_X = W / 2 - 12 mm
TAB = 20 mm

def side_panel() -> solid {
    body = Rectangle(center=(0, 0), width=SIDE_D, height=CLEAR + 2 * T)
    top_t = tab_and_slot(part="tab", length=SIDE_D, thickness=T, tabs=2, tab=TAB, screw=0,
                         cx=0, cy=CLEAR / 2 + T)
    bot_t = tab_and_slot(part="tab", length=SIDE_D, thickness=T, tabs=2, tab=TAB, screw=0,
                         rotation=180 deg, cx=0, cy=-(CLEAR / 2 + T))
}

assembly tamping_station {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=W, height=D, corner_radius=8)
        hole well { c = Circle(center=(-45, 0), diameter=60) }
        hole spout { s = Slot(center=(35, -D / 2 + 30), length=80, width=36, rotation=90) }
        ml = tab_and_slot(part="slot", length=SIDE_D, thickness=T, tabs=2, tab=TAB, screw=0,
                          rotation=90 deg, cx=-SIDE_X, cy=0)
        mr = tab_and_slot(part="slot", length=SIDE_D, thickness=T, tabs=2, tab=TAB, screw=0,
                          rotation=90 deg, cx=SIDE_X, cy=0)
        Fillet([body.bottom, spout.s], 3)
        drawing marks {
            size_t = Text("58", position=(-45, -48), size=6, valign="middle")
            word = Text("ESPRESSO", position=(0, 52), size=8, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }

    solid base {
        body = RoundedRectangle(center=(0, 0), width=W, height=D, corner_radius=8)
        ml = tab_and_slot(part="slot", length=SIDE_D, thickness=T, tabs=2, tab=TAB, screw=0,
                          rotation=90 deg, cx=-SIDE_X, cy=0)
        mr = tab_and_slot(part="slot", length=SIDE_D, thickness=T, tabs=2, tab=TAB, screw=0,
                          rotation=90 deg, cx=SIDE_X, cy=0)
    }

    side_l = side_panel()
    side_r = side_panel()

    # flat on the sheet: base right of the top, the sides under them
    RightOf(base, top, gap=10)
    AlignTop(base, top)
    Below(side_l, top, gap=10)
    AlignLeft(side_l, top)
    RightOf(side_r, side_l, gap=10)
    AlignTop(side_r, side_l)

    # in 3D
    Place(base, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, T + CLEAR), face="up")
    Place(side_r, position=(SIDE_X - T / 2, 0, T + CLEAR / 2), face="right", up="up")
    Place(side_l, position=(-SIDE_X + T / 2, 0, T + CLEAR / 2), face="left", up="up")

    # the request's numbers
    assert top.body.bb.width == 200 mm and top.body.bb.height == 130 mm, "deck 200 x 130"
    assert base.body.bb.width == 200 mm and base.body.bb.height == 130 mm, "base 200 x 130"
    assert side_l.body.bb.height - 2 * 6 mm == 60 mm, "60 mm clear between base and deck"
    assert side_l.body.bb.width == 110 mm, "sides 110 deep"
    assert top.well.c.diameter == 60 mm, "60 mm tamper well"
    assert top.body.bb.center_x - top.well.c.center.x == 45 mm, "well 45 left of the middle"
    assert top.spout.s.center.x - top.body.bb.center_x == 35 mm, "spout slot 35 right of the middle"
    assert top.spout.s.width == 36 mm, "spout slot 36 wide"
    assert top.spout.s.bb.top - top.body.bb.bottom == 70 mm, "spout slot 70 deep"
    assert top.body.bb.right - top.mr.slot[0].bb.center_x == 12 mm, "sides 12 in from the ends"
    assert len(top.mr.slot) == 2 and len(base.ml.slot) == 2, "two tenons each edge"
}
