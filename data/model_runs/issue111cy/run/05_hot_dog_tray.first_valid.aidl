# Request (parties): a serving tray for 6 hot dogs at a kids' party, 4 mm birch ply.
# Base 360 x 180 mm, 10 mm corner radius, with a hand-hold slot at each end: 80 x 22 mm,
# running front to back, its centre 18 mm in from the short edge. Two ribs 280 mm long stand
# 40 mm tall on the base, 80 mm apart (centre to centre), parallel to the long edges and
# centred on the base, each glued in with 3 tabs 20 mm wide. Each rib has 6 round cradles
# across its top edge, 40 mm across, 16 mm deep, on a 46 mm pitch and centred, so the buns
# lie front to back across both ribs. The front rib has "HOT DOGS" engraved in 10 mm letters,
# centred, in the band below the cradles.

import "std/joints.aidl"

thickness 4 mm

T = 4 mm
rib_len = 280 mm
rib_h = 40 mm          # above the base
cradle_d = 40 mm
cradle_depth = 16 mm
pitch = 46 mm

# a rib: its tabs' tips (the base's underside) on y = 0, the base's top on y = T
def rib(label="") -> solid {
    body = Rectangle(bottom_left=(-rib_len / 2, 0), width=rib_len, height=T + rib_h)
    tabs = tab_and_slot(part="tab", length=rib_len, thickness=T, tabs=3, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole cradles {
        for i in range(6) {
            c = Circle(center=((i - 2.5) * pitch, T + rib_h + cradle_d / 2 - cradle_depth),
                       diameter=cradle_d)
        }
    }
    if label != "" {
        drawing words {
            t = Text(label, position=(0, T + (rib_h - cradle_depth) / 2), size=10 mm,
                     valign="middle")
        }
    }
}

assembly hot_dog_tray {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=360 mm, height=180 mm,
                                 corner_radius=10 mm)
        hole handles {
            left = Slot(center=(-180 mm + 18 mm, 0), length=80 mm, width=22 mm,
                        rotation=90 deg)
            right = Slot(center=(180 mm - 18 mm, 0), length=80 mm, width=22 mm,
                         rotation=90 deg)
        }
        front_mortise = tab_and_slot(part="slot", length=rib_len, thickness=T, tabs=3,
                                     tab=20 mm, screw=0, cx=0 mm, cy=-40 mm)
        back_mortise = tab_and_slot(part="slot", length=rib_len, thickness=T, tabs=3,
                                    tab=20 mm, screw=0, cx=0 mm, cy=40 mm)
    }
    front_rib = rib(label="HOT DOGS")
    back_rib = rib()

    # flat for cutting
    Below(front_rib, base, gap=10 mm)
    Below(back_rib, front_rib, gap=10 mm)
    AlignCenterX(front_rib, base)
    AlignCenterX(back_rib, base)

    # assembled: the base on z = 0, the ribs standing through it
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(front_rib, position=(0, -40 mm + T / 2, 0), face="front", up="up")
    Place(back_rib, position=(0, 40 mm + T / 2, 0), face="front", up="up")

    # the request's numbers
    assert base.plate.bb.width == 360 mm and base.plate.bb.height == 180 mm, "base 360 x 180"
    assert base.handles.left.length == 80 mm and base.handles.left.width == 22 mm,
        "hand-holds 80 x 22"
    assert base.handles.left.center.x - base.plate.bb.left == 18 mm and
        base.plate.bb.right - base.handles.right.center.x == 18 mm, "18 mm in from the ends"
    assert base.back_mortise.slot[0].bb.center_y - base.front_mortise.slot[0].bb.center_y ==
        80 mm, "ribs 80 apart"
    assert front_rib.body.bb.height - T == 40 mm, "ribs 40 mm tall above the base"
    assert front_rib.body.bb.width == 280 mm, "ribs 280 long"
    assert len(front_rib.cradles.c) == 6, "6 cradles"
    assert front_rib.cradles.c[1].center.x - front_rib.cradles.c[0].center.x == 46 mm,
        "46 mm pitch"
    assert front_rib.cradles.c[0].diameter == 40 mm, "cradles 40 mm across"
    assert front_rib.body.bb.top - front_rib.cradles.c[0].bottom.y == 16 mm, "16 mm deep"
    assert abs(front_rib.cradles.c[0].center.x + front_rib.cradles.c[5].center.x) < 0.01 mm,
        "cradles centred"
    assert front_rib.cradles.c[0].right.x < front_rib.cradles.c[1].left.x, "cradles apart"
    assert front_rib.words.t.size == 10 mm, "10 mm letters"
    assert front_rib.words.t.bb.top < front_rib.cradles.c[0].bottom.y, "below the cradles"
}
